"""Open CASCADE in: natural faces of OCP shapes as exact quadrics, the
referee of a pair, and the audit of a shape against Open CASCADE's own
intersector.

Needs Open CASCADE's Python bindings (``pip install './python[occ]'``, the
package ``cadquery-ocp-novtk``).

* :func:`from_occ` takes a ``gp_Sphere``, ``gp_Cylinder``, ``gp_Cone``, a
  ``Geom_SphericalSurface``/``CylindricalSurface``/``ConicalSurface``, an
  adaptor surface (``BRepAdaptor_Surface``, ``GeomAdaptor_Surface``) or a
  ``TopoDS_Face`` (its location applied, as ``BRepAdaptor_Surface`` does)
  and returns the :class:`~quadsect.Sphere`, :class:`~quadsect.Cylinder`
  or :class:`~quadsect.Cone` of those doubles, each at its exact binary
  value: centre, axis point (``Location()``), vertex (``Apex()``, as Open
  CASCADE computes it), the axis direction, ``radius2`` the square of the
  double radius, and a cone's ``tan2`` the square of the double
  ``tan(SemiAngle())`` — that is the cone those doubles describe.
* :func:`referee` classifies a pair exactly with the stability interval
  (:class:`~quadsect.Referee`).
* :func:`audit` takes every pair of sphere/cylinder/cone faces of a shape:
  the exact class and counts, the stability interval, and
  ``IntPatch_ImpImpIntersection``'s answer for the same pair (in a worker
  process, so that a call that does not return costs that pair only),
  with agree / disagree.

>>> from OCP.gp import gp_Ax3, gp_Cylinder, gp_Dir, gp_Pnt, gp_Sphere
>>> s = gp_Sphere(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0)
>>> c = gp_Cylinder(gp_Ax3(gp_Pnt(1, 0, 0), gp_Dir(0, 0, 1)), 1.0)
>>> from_occ(c)
Cylinder(point=(Fraction(1, 1), Fraction(0, 1), Fraction(0, 1)), axis=(Fraction(0, 1), Fraction(0, 1), Fraction(1, 1)), radius2=Fraction(1, 1))
>>> r = referee(s, c)
>>> r.classification, r.referee.lo   # Viviani's curve: a tangency, so lo = 0
('curve', Fraction(0, 1))
"""

from __future__ import annotations

import json as _json
import math
import multiprocessing as _mp
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Dict, List, Optional, Tuple, Union

try:
    from OCP.Adaptor3d import Adaptor3d_Surface, Adaptor3d_TopolTool
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.Geom import Geom_ConicalSurface, Geom_CylindricalSurface, Geom_SphericalSurface
    from OCP.GeomAbs import GeomAbs_SurfaceType
    from OCP.GeomAdaptor import GeomAdaptor_Surface
    from OCP.gp import gp_Ax3, gp_Cone, gp_Cylinder, gp_Dir, gp_Pnt, gp_Sphere
    from OCP.IntPatch import IntPatch_ImpImpIntersection
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS, TopoDS_Shape
except ImportError as _err:  # pragma: no cover - the extra is not installed
    raise ImportError(
        "quadsect.occ needs Open CASCADE's Python bindings: pip install './python[occ]' "
        f"(the package cadquery-ocp-novtk): {_err}"
    ) from _err

from . import Cone, Cylinder, NaturalResult, Sphere, batch, natural
from ._occ_answer import answer_intpatch, scale_of

__all__ = ["from_occ", "referee", "audit", "Audit", "AuditRecord"]

#: The tolerance given to ``IntPatch_ImpImpIntersection`` (its ``TolArc``
#: and ``TolTang``), as in ``scripts/bench_occ.py``.
TOLERANCE = 1e-7

_Quadric = Union[gp_Sphere, gp_Cylinder, gp_Cone]

_ADAPTED = {
    GeomAbs_SurfaceType.GeomAbs_Sphere: "Sphere",
    GeomAbs_SurfaceType.GeomAbs_Cylinder: "Cylinder",
    GeomAbs_SurfaceType.GeomAbs_Cone: "Cone",
}


def _gp_of(obj: Any) -> Optional[_Quadric]:
    """The ``gp_`` quadric of an OCP object, or ``None`` for another
    surface type."""
    if isinstance(obj, (gp_Sphere, gp_Cylinder, gp_Cone)):
        return obj
    if isinstance(obj, Geom_SphericalSurface):
        return obj.Sphere()
    if isinstance(obj, Geom_CylindricalSurface):
        return obj.Cylinder()
    if isinstance(obj, Geom_ConicalSurface):
        return obj.Cone()
    if isinstance(obj, TopoDS_Shape):
        if obj.ShapeType() != TopAbs_FACE:
            raise TypeError(f"from_occ takes a face, not a {obj.ShapeType()}")
        obj = BRepAdaptor_Surface(TopoDS.Face(obj))
    if isinstance(obj, Adaptor3d_Surface):
        name = _ADAPTED.get(obj.GetType())
        return None if name is None else getattr(obj, name)()
    raise TypeError(
        "from_occ takes gp_Sphere/gp_Cylinder/gp_Cone, a Geom_ spherical, cylindrical or "
        f"conical surface, an adaptor surface or a TopoDS_Face, not {type(obj).__name__}"
    )


def _xyz(p: Any) -> Tuple[Fraction, Fraction, Fraction]:
    return (Fraction(p.X()), Fraction(p.Y()), Fraction(p.Z()))


def _exact(g: _Quadric) -> Union[Sphere, Cylinder, Cone]:
    if isinstance(g, gp_Sphere):
        return Sphere(_xyz(g.Location()), Fraction(g.Radius()) ** 2)
    axis = _xyz(g.Axis().Direction())
    if isinstance(g, gp_Cylinder):
        return Cylinder(_xyz(g.Location()), axis, Fraction(g.Radius()) ** 2)
    return Cone(_xyz(g.Apex()), axis, tan2=Fraction(math.tan(g.SemiAngle())) ** 2)


def from_occ(obj: Any) -> Union[Sphere, Cylinder, Cone]:
    """The exact natural quadric of an Open CASCADE sphere, cylinder or cone
    (module docs: which objects, and which doubles are taken).  Another
    surface type is a ``TypeError``."""
    g = _gp_of(obj)
    if g is None:
        raise TypeError(f"not a sphere, cylinder or cone: {obj.GetType() if hasattr(obj, 'GetType') else obj}")
    return _exact(g)


def referee(a: Any, b: Any, *, time_limit: Optional[float] = None) -> NaturalResult:
    """Class and counts of two Open CASCADE natural surfaces, exactly for
    their doubles, with the stability interval (:attr:`NaturalResult.referee`)."""
    return natural(from_occ(a), from_occ(b), components=False, referee=True, time_limit=time_limit)


# ---------------------------------------------------------------- IntPatch in a worker


def _params(g: _Quadric) -> tuple:
    """Picklable parameters rebuilding the same ``gp_`` quadric (the
    placement's X direction aside, which the intersection ignores)."""
    loc, d = g.Location(), g.Position().Direction()
    base = ((loc.X(), loc.Y(), loc.Z()), (d.X(), d.Y(), d.Z()))
    if isinstance(g, gp_Sphere):
        return ("sphere", *base, g.Radius())
    if isinstance(g, gp_Cylinder):
        return ("cylinder", *base, g.Radius())
    return ("cone", *base, g.SemiAngle(), g.RefRadius())


def _rebuild(p: tuple) -> Tuple[Any, Tuple[float, float, float]]:
    kind, loc, d, *rest = p
    ax = gp_Ax3(gp_Pnt(*loc), gp_Dir(*d))
    if kind == "sphere":
        g = Geom_SphericalSurface(gp_Sphere(ax, rest[0]))
    elif kind == "cylinder":
        g = Geom_CylindricalSurface(gp_Cylinder(ax, rest[0]))
    else:
        g = Geom_ConicalSurface(gp_Cone(ax, rest[0], rest[1]))
    return g, loc


def _intpatch(p1: tuple, p2: tuple) -> Dict[str, Any]:
    """``IntPatch_ImpImpIntersection``'s answer as class and counts."""
    (g1, l1), (g2, l2) = _rebuild(p1), _rebuild(p2)
    s1, s2 = GeomAdaptor_Surface(g1), GeomAdaptor_Surface(g2)
    try:
        ii = IntPatch_ImpImpIntersection(s1, Adaptor3d_TopolTool(s1), s2, Adaptor3d_TopolTool(s2), TOLERANCE, TOLERANCE)
        ans = answer_intpatch(ii, scale_of(l1, l2))
    except Exception as err:  # Standard_Failure arrives as a Python exception
        return {"no_answer": f"exception: {type(err).__name__}: {err}"}
    ans.pop("pieces", None)
    return ans


def _worker(conn: Any) -> None:
    while True:
        job = conn.recv()
        if job is None:
            return
        conn.send(_intpatch(*job))


class _IntPatchWorker:
    """IntPatch calls in a forked process: a call that does not return
    within ``timeout`` seconds is ``no answer`` and the worker is replaced."""

    def __init__(self, timeout: float) -> None:
        self.timeout = timeout
        self.proc = None
        ctx = _mp.get_context("fork")
        self._ctx = ctx

    def _start(self) -> None:
        self.conn, child = self._ctx.Pipe()
        self.proc = self._ctx.Process(target=_worker, args=(child,), daemon=True)
        self.proc.start()

    def __call__(self, p1: tuple, p2: tuple) -> Dict[str, Any]:
        if self.proc is None or not self.proc.is_alive():
            self._start()
        self.conn.send((p1, p2))
        if self.conn.poll(self.timeout):
            return self.conn.recv()
        self.proc.kill()
        self.proc.join()
        self.proc = None
        return {"no_answer": f"no answer within {self.timeout:g} s"}

    def close(self) -> None:
        if self.proc is not None and self.proc.is_alive():
            self.conn.send(None)
            self.proc.join(1.0)
            if self.proc.is_alive():
                self.proc.kill()


# ---------------------------------------------------------------- the audit


@dataclass(frozen=True)
class AuditRecord:
    """One pair of natural faces of an audited shape: the faces' indices
    among the shape's faces (``TopExp_Explorer`` order) and kinds, the exact
    answer (``exact``: class, conics, lines, points), the referee's ``lo``
    and ``hi`` (``hi`` ``None`` without a witness) and the witness's answer
    (``nearby``), Open CASCADE's answer (``occ``: the same keys, or
    ``{"no_answer": why}``; ``None`` when not asked for), whether the two
    agree (class, and the counts the class has), and ``explained``: they
    disagree, ``hi ≤ 1e-6`` and Open CASCADE's answer is the witness's —
    the disagreement is a change of answer within rounding distance."""

    i: int
    j: int
    kinds: Tuple[str, str]
    exact: Dict[str, Any]
    lo: Fraction
    hi: Optional[Fraction]
    nearby: Optional[Dict[str, Any]]
    occ: Optional[Dict[str, Any]]
    agree: Optional[bool]
    explained: Optional[bool]


def _same(x: Dict[str, Any], y: Dict[str, Any]) -> bool:
    """Same class and the counts that class has (as scripts/bench_occ.py
    judges)."""
    if "no_answer" in x or "no_answer" in y or x["class"] != y["class"]:
        return False
    cls = x["class"]
    if cls in ("conics", "conic-and-line", "lines"):
        return (x["conics"], x["lines"]) == (y["conics"], y["lines"])
    if cls == "points":
        return x["points"] == y["points"]
    return True


class Audit(List[AuditRecord]):
    """The records of :func:`audit` (a list), with :meth:`table`."""

    def table(self) -> str:
        """A plain-text table: one row per pair."""
        rows = [("faces", "kinds", "exact", "lo", "hi", "nearby", "Open CASCADE", "")]

        def ans(a: Optional[Dict[str, Any]]) -> str:
            if a is None:
                return "-"
            if "no_answer" in a:
                return "no answer"
            return f"{a['class']} {a['conics']}/{a['lines']}/{a['points']}"

        for r in self:
            verdict = "" if r.agree is None else ("agree" if r.agree else ("DISAGREE (explained)" if r.explained else "DISAGREE"))
            rows.append((
                f"{r.i}-{r.j}", "/".join(r.kinds), ans(r.exact), f"{float(r.lo):.2e}",
                "-" if r.hi is None else f"{float(r.hi):.2e}", ans(r.nearby), ans(r.occ), verdict,
            ))
        widths = [max(len(row[k]) for row in rows) for k in range(len(rows[0]))]
        lines = ["  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() for row in rows]
        agree = sum(1 for r in self if r.agree)
        dis = sum(1 for r in self if r.agree is False)
        lines.append(f"{len(self)} pairs: {agree} agree, {dis} disagree "
                     f"({sum(1 for r in self if r.explained)} explained by an answer within 1e-6)")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.table()


def natural_faces(shape: TopoDS_Shape) -> List[Tuple[int, Any]]:
    """The sphere, cylinder and cone faces of a shape as ``(index, gp_
    quadric)``, the index counting every face in ``TopExp_Explorer``
    order."""
    out = []
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    k = 0
    while ex.More():
        g = _gp_of(BRepAdaptor_Surface(TopoDS.Face(ex.Current())))
        if g is not None:
            out.append((k, g))
        k += 1
        ex.Next()
    return out


def audit(shape: TopoDS_Shape, *, occ: bool = True, timeout: float = 5.0,
          time_limit: Optional[float] = None, threads: Optional[int] = None) -> Audit:
    """Every pair of sphere/cylinder/cone faces of ``shape``: the exact
    class and counts, the stability interval, and (``occ``) Open
    CASCADE's ``IntPatch_ImpImpIntersection`` answer with agree /
    disagree; ``timeout`` seconds per IntPatch call (it may not return),
    ``time_limit`` per exact classification (running out: class
    ``undecided``).  The exact side runs on ``threads`` engine threads
    (:func:`quadsect.batch`) while Open CASCADE's calls run in their
    worker process.  ``print(audit(shape))`` prints the table."""
    faces = natural_faces(shape)
    exact = [_exact(g) for _, g in faces]
    params = [_params(g) for _, g in faces]
    pairs = [(x, y) for x in range(len(faces)) for y in range(x + 1, len(faces))]
    lines = (
        _json.dumps({"op": "natural", "a": exact[x].to_dict(), "b": exact[y].to_dict(),
                     "components": False, "referee": True})
        for x, y in pairs
    )
    worker = _IntPatchWorker(timeout) if occ else None
    out = Audit()
    try:
        for (x, y), line in zip(pairs, batch(lines, threads, time_limit=time_limit)):
            res = _json.loads(line)
            if not res.get("ok"):
                raise RuntimeError(f"faces {faces[x][0]} and {faces[y][0]}: {res.get('error')}")
            r = res["result"]
            mine = {k: r[k] for k in ("class", "conics", "lines", "points")}
            f = r.get("referee")
            near = f["nearby"] if f else None
            hi = Fraction(f["hi_exact"]) if f and f["hi_exact"] is not None else None
            theirs = worker(params[x], params[y]) if worker else None
            agree = None if theirs is None else _same(mine, theirs)
            explained = None
            if agree is False:
                explained = bool(hi is not None and hi <= Fraction(1, 10**6) and near is not None
                                 and _same(near["answer"], theirs))
            out.append(AuditRecord(
                i=faces[x][0], j=faces[y][0], kinds=(exact[x].kind, exact[y].kind), exact=mine,
                lo=Fraction(f["lo_exact"]) if f else Fraction(0), hi=hi,
                nearby=near["answer"] if near else None, occ=theirs, agree=agree, explained=explained,
            ))
    finally:
        if worker is not None:
            worker.close()
    return out
