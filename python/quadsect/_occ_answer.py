"""Open CASCADE's answer for a pair of natural quadrics as class and
counts: `IntPatch_ImpImpIntersection`'s lines, conics and points tallied,
equal pieces counted once (within 10⁻⁶ of the scene's scale).

Pure Python over OCP objects, without the engine: `quadsect.occ` uses it,
and `scripts/bench_occ.py` loads this file by its path (it runs in a venv
without quadsect)."""

import math

from OCP.IntPatch import IntPatch_ImpImpIntersection, IntPatch_IType

CONIC_ITYPES = {IntPatch_IType.IntPatch_Circle: "circle", IntPatch_IType.IntPatch_Ellipse: "ellipse",
                IntPatch_IType.IntPatch_Parabola: "parabola", IntPatch_IType.IntPatch_Hyperbola: "hyperbola"}


def xyz(p):
    return (p.X(), p.Y(), p.Z())


def scale_of(*pts):
    return max([1.0] + [abs(c) for p in pts for c in p])


def dist(p, q):
    return math.sqrt(sum((a - b) ** 2 for a, b in zip(p, q)))


class Tally:
    """Lines, conics and points of one answer, equal ones counted once."""

    def __init__(self, scale):
        self.lines, self.conics, self.points = [], [], []
        self.tol = 1e-6 * scale
        self.types = []

    def line(self, lin):
        p, d = xyz(lin.Location()), xyz(lin.Direction())
        for q, e in self.lines:
            cr = (d[1] * e[2] - d[2] * e[1], d[2] * e[0] - d[0] * e[2], d[0] * e[1] - d[1] * e[0])
            w = [a - b for a, b in zip(p, q)]
            off = (w[1] * e[2] - w[2] * e[1], w[2] * e[0] - w[0] * e[2], w[0] * e[1] - w[1] * e[0])
            if math.sqrt(sum(c * c for c in cr)) < 1e-7 and math.sqrt(sum(c * c for c in off)) < self.tol:
                return
        self.lines.append((p, d))
        self.types.append("line")

    def conic(self, kind, c):
        centre = xyz(c.Location())
        normal = xyz(c.Axis().Direction())
        if kind == "circle":
            radii = (c.Radius(), c.Radius())
        elif kind == "parabola":
            radii = (c.Focal(), 0.0)
        else:
            radii = (c.MajorRadius(), c.MinorRadius())
        for k, q, n, r in self.conics:
            same_plane = abs(abs(sum(a * b for a, b in zip(normal, n))) - 1) < 1e-9
            if k == kind and same_plane and dist(centre, q) < self.tol and all(
                    abs(a - b) < self.tol for a, b in zip(radii, r)):
                if kind != "parabola" or dist(xyz(c.Location()), q) < self.tol:
                    return
        self.conics.append((kind, centre, normal, radii))
        self.types.append(kind)

    def point(self, p):
        p = xyz(p)
        if all(dist(p, q) > self.tol for q in self.points):
            self.points.append(p)

    def answer(self, curve=False):
        nl, nc, npt = len(self.lines), len(self.conics), len(self.points)
        if curve:
            cls = "curve"
        elif nc and nl:
            cls = "conic-and-line"
        elif nc:
            cls = "conics"
        elif nl:
            cls = "lines"
        elif npt:
            cls = "points"
        else:
            cls = "empty"
        return {"class": cls, "conics": nc, "lines": nl, "points": npt, "pieces": self.types}


def answer_intpatch(ii, scale):
    if not ii.IsDone():
        return {"no_answer": "IsDone() false"}
    st = ii.GetStatus()
    if st != IntPatch_ImpImpIntersection.IntStatus_e.IntStatus_OK:
        return {"no_answer": f"status {st}"}
    if ii.IsEmpty():
        return {"class": "empty", "conics": 0, "lines": 0, "points": 0, "pieces": []}
    if ii.TangentFaces():
        return {"class": "same-surface", "conics": 0, "lines": 0, "points": 0, "pieces": ["tangent-faces"]}
    t = Tally(scale)
    curve = False
    for i in range(1, ii.NbLines() + 1):
        line = ii.Line(i)
        at = line.ArcType()
        if at == IntPatch_IType.IntPatch_Lin:
            t.line(line.Line())
        elif at in CONIC_ITYPES:
            kind = CONIC_ITYPES[at]
            c = {"circle": line.Circle, "ellipse": line.Ellipse, "parabola": line.Parabola,
                 "hyperbola": line.Hyperbola}[kind]()
            t.conic(kind, c)
        else:
            curve = True
            t.types.append(str(at).split(".")[-1])
    for i in range(1, ii.NbPnts() + 1):
        t.point(ii.Point(i).Value())
    if curve or t.lines or t.conics:
        # the points of a line-type answer are its vertices, not isolated points
        t.points = []
    return t.answer(curve)
