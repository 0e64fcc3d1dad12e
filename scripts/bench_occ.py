#!/usr/bin/env python3
"""Open CASCADE beside quadsect on the natural-quadric pair set (issue 15).

For every pair of benches/data/natural_pairs.json this script

  * builds the two surfaces in Open CASCADE (pip package cadquery-ocp-novtk,
    module OCP) from the exact numbers rounded to doubles: gp_Sphere (centre,
    radius = the double nearest to sqrt(radius2)), gp_Cylinder (a point of the
    axis, the axis direction, radius), gp_Cone built at the vertex with
    semi-angle atan(sqrt(tan2)) and reference radius 0;
  * times, with quadsect's protocol (calls repeated inside a sample until it
    lasts >= 25 ms, median of >= 5 samples, 11 for fast calls):
      - IntPatch_ImpImpIntersection(S1, D1, S2, D2, TolArc, TolTang): OCC's
        complete analytic quadric/quadric intersector, on GeomAdaptor_Surface
        handles of the Geom surfaces with Adaptor3d_TopolTool domains (as
        IntPatch_Intersection::GeomGeomPerfom calls it), TolArc = TolTang =
        1e-7 (the default tolerance of GeomInt_IntSS / Draw `intersect`);
      - IntAna_QuadQuadGeo(Q1, Q2, 1e-7): the closed forms (gp_ quadrics);
      - GeomInt_IntSS(S1, S2, 1e-7, Approx=True): what Draw `intersect` and
        the Boolean operations call (unless --no-intss);
    the surfaces and adaptors are built once per pair, outside the timing;
  * maps each answer to quadsect's class and counts and judges it against
    the pair's `expect` (right / wrong / no answer);
  * runs `quadsect bench natural --pairs PAIRS --json` in the same run (after
    the OCC measurements, so that the two never share the cores) and takes
    its natural-pair rows;
  * writes docs/occ_results.json (raw: every pair, every method) and prints
    one markdown table per group and a summary table.

Mapping OCC's output to quadsect's classes: TangentFaces / IntAna_Same ->
same-surface; IsEmpty / IntAna_Empty -> empty; an analytic (IntPatch_ALine),
walking (IntPatch_WLine) or restriction line, or a B-spline curve of
GeomInt_IntSS -> curve; otherwise lines (IntPatch_Lin, Geom_Line) and conics
(circles, ellipses, parabolas, hyperbolas) are counted, collinear lines and
equal conics (the two branches of one hyperbola, one conic cut in pieces)
counted once, and the class is conic-and-line / conics / lines, or points
when only single points were returned.  An answer is right when the class is
quadsect's and, for conics / conic-and-line / lines, the numbers of conics
and lines, for points the number of points, agree.  IsDone() false, a status
other than IntStatus_OK, an exception, or IntAna_NoGeometricSolution is "no
answer" (for IntAna the latter is listed apart on pairs whose exact class is
curve, where a closed form cannot exist).

Usage (from the repository root):
    python3 -m venv .venv-occ --system-site-packages
    .venv-occ/bin/pip install cadquery-ocp-novtk
    cargo build --release
    .venv-occ/bin/python scripts/bench_occ.py [--pairs benches/data/natural_pairs.json]
        [--quadsect target/release/quadsect | --no-quadsect] [--groups g1,g2]
        [--only NAME,...] [--no-intss] [--out docs/occ_results.json]
"""
import argparse
import decimal
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from fractions import Fraction

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

try:
    from OCP.Adaptor3d import Adaptor3d_TopolTool
    from OCP.Geom import (Geom_Circle, Geom_ConicalSurface, Geom_CylindricalSurface, Geom_Ellipse,
                          Geom_Hyperbola, Geom_Line, Geom_Parabola, Geom_SphericalSurface,
                          Geom_TrimmedCurve)
    from OCP.GeomAdaptor import GeomAdaptor_Surface
    from OCP.GeomInt import GeomInt_IntSS
    from OCP.gp import gp_Ax3, gp_Cone, gp_Cylinder, gp_Dir, gp_Pnt, gp_Sphere
    from OCP.IntAna import IntAna_QuadQuadGeo, IntAna_ResultType
    from OCP.IntPatch import IntPatch_ImpImpIntersection, IntPatch_IType
except ImportError as err:  # pragma: no cover
    sys.exit(f"bench_occ.py needs Open CASCADE's Python module OCP (pip package cadquery-ocp-novtk): {err}")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_table import fmt as fmt_t  # noqa: E402  (seconds for people: ns, µs, ms, s)

TOL = 1e-7

# ---------------------------------------------------------------- timing


def measure(f):
    """Median seconds per call of f: quadsect's protocol (src/bench.rs `measure`)."""
    t0 = time.perf_counter()
    f()
    first = time.perf_counter() - t0
    target = 0.025
    inner = 1 if first >= target else max(1, int(target / max(first, 1e-8)))
    want = 5 if first >= 0.2 else 11
    samples = [first] if first >= 1.0 else []
    start = time.perf_counter()
    while len(samples) < want:
        t = time.perf_counter()
        for _ in range(inner):
            f()
        samples.append((time.perf_counter() - t) / inner)
        if time.perf_counter() - start > 30.0 and len(samples) >= 3:
            break
    samples.sort()
    return samples[len(samples) // 2], len(samples)


# ---------------------------------------------------------------- surfaces


def exact(s):
    return Fraction(s)


def fsqrt(q):
    """The double nearest to sqrt(q) (q an exact rational), via 40-digit decimals."""
    with decimal.localcontext() as ctx:
        ctx.prec = 40
        d = decimal.Decimal(q.numerator) / decimal.Decimal(q.denominator)
        return float(d.sqrt())


def vec(v):
    return [float(exact(x)) for x in v]


def occ_quadric(s):
    """(gp_ quadric, Geom surface) of a pair's surface."""
    if s["kind"] == "sphere":
        c = vec(s["center"])
        g = gp_Sphere(gp_Ax3(gp_Pnt(*c), gp_Dir(0, 0, 1)), fsqrt(exact(s["radius2"])))
        return g, Geom_SphericalSurface(g)
    if s["kind"] == "cylinder":
        g = gp_Cylinder(gp_Ax3(gp_Pnt(*vec(s["point"])), gp_Dir(*vec(s["axis"]))), fsqrt(exact(s["radius2"])))
        return g, Geom_CylindricalSurface(g)
    ang = math.atan(fsqrt(exact(s["tan2"])))
    g = gp_Cone(gp_Ax3(gp_Pnt(*vec(s["vertex"])), gp_Dir(*vec(s["axis"]))), ang, 0.0)
    return g, Geom_ConicalSurface(g)


# ---------------------------------------------------------------- answers

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


def answer_intana(q, scale):
    if not q.IsDone():
        return {"no_answer": "IsDone() false"}
    ty = q.TypeInter()
    n = q.NbSolutions()
    if ty == IntAna_ResultType.IntAna_NoGeometricSolution:
        return {"no_answer": "IntAna_NoGeometricSolution"}
    if ty == IntAna_ResultType.IntAna_Same:
        return {"class": "same-surface", "conics": 0, "lines": 0, "points": 0, "pieces": ["same"]}
    if ty == IntAna_ResultType.IntAna_Empty:
        return {"class": "empty", "conics": 0, "lines": 0, "points": 0, "pieces": []}
    t = Tally(scale)
    for i in range(1, n + 1):
        if ty == IntAna_ResultType.IntAna_Point:
            t.point(q.Point(i))
        elif ty == IntAna_ResultType.IntAna_Line:
            t.line(q.Line(i))
        elif ty in (IntAna_ResultType.IntAna_Circle, IntAna_ResultType.IntAna_PointAndCircle):
            if ty == IntAna_ResultType.IntAna_PointAndCircle and i == 1:
                t.point(q.Point(1))
                continue
            t.conic("circle", q.Circle(i))
        elif ty == IntAna_ResultType.IntAna_Ellipse:
            t.conic("ellipse", q.Ellipse(i))
        elif ty == IntAna_ResultType.IntAna_Parabola:
            t.conic("parabola", q.Parabola(i))
        elif ty == IntAna_ResultType.IntAna_Hyperbola:
            t.conic("hyperbola", q.Hyperbola(i))
    pts = list(t.points)
    a = t.answer()
    if ty == IntAna_ResultType.IntAna_PointAndCircle:
        a["points"] = len(pts)
    return a


def answer_intss(r, scale):
    if not r.IsDone():
        return {"no_answer": "IsDone() false"}
    t = Tally(scale)
    curve = False
    for i in range(1, r.NbLines() + 1):
        c = r.Line(i)
        while isinstance(c, Geom_TrimmedCurve):
            c = c.BasisCurve()
        if isinstance(c, Geom_Line):
            t.line(c.Lin())
        elif isinstance(c, Geom_Circle):
            t.conic("circle", c.Circ())
        elif isinstance(c, Geom_Ellipse):
            t.conic("ellipse", c.Elips())
        elif isinstance(c, Geom_Parabola):
            t.conic("parabola", c.Parab())
        elif isinstance(c, Geom_Hyperbola):
            t.conic("hyperbola", c.Hypr())
        else:
            curve = True
            t.types.append(type(c).__name__)
    if not (curve or t.lines or t.conics):
        for i in range(1, r.NbPoints() + 1):
            t.point(r.Point(i))
    return t.answer(curve)


def judge(ans, expect):
    if ans is None or "no_answer" in ans:
        return "no answer"
    if ans["class"] != expect["class"]:
        return "wrong"
    cls = expect["class"]
    if cls in ("conics", "conic-and-line", "lines"):
        ok = ans["conics"] == expect["conics"] and ans["lines"] == expect["lines"]
    elif cls == "points":
        ok = ans["points"] == expect["points"]
    else:
        ok = True
    return "right" if ok else "wrong"


# ---------------------------------------------------------------- per pair


def intana_of(q1, q2, k1, k2):
    """IntAna_QuadQuadGeo with the arguments in the order its constructors take."""
    order = {"cylinder": 0, "sphere": 1, "cone": 2}
    if (k1, k2) in (("cylinder", "cylinder"), ("cylinder", "sphere"), ("cylinder", "cone"), ("sphere", "sphere"),
                    ("sphere", "cone"), ("cone", "cone")):
        return lambda: IntAna_QuadQuadGeo(q1, q2, TOL)
    if order[k1] > order[k2]:
        return lambda: IntAna_QuadQuadGeo(q2, q1, TOL)
    return None


def run_pair(pair, do_intss):
    a, b = pair["a"], pair["b"]
    rec = {"name": pair["name"], "group": pair["group"], "expect": pair["expect"]}
    try:
        (q1, g1), (q2, g2) = occ_quadric(a), occ_quadric(b)
    except Exception as err:  # gp_ constructors refuse e.g. a null direction
        rec["error"] = f"cannot build the OCC surfaces: {err}"
        return rec
    pts = [vec(s.get("center") or s.get("point") or s.get("vertex")) for s in (a, b)]
    scale = scale_of(*pts)
    s1, s2 = GeomAdaptor_Surface(g1), GeomAdaptor_Surface(g2)
    d1, d2 = Adaptor3d_TopolTool(s1), Adaptor3d_TopolTool(s2)

    def intpatch():
        return IntPatch_ImpImpIntersection(s1, d1, s2, d2, TOL, TOL)

    methods = [("intpatch", intpatch, answer_intpatch)]
    f = intana_of(q1, q2, a["kind"], b["kind"])
    if f is not None:
        methods.append(("intana", f, answer_intana))
    if do_intss:
        def intss():
            r = GeomInt_IntSS()
            r.Perform(g1, g2, TOL, True, False, False)
            return r
        methods.append(("intss", intss, answer_intss))
    for name, call, answer in methods:
        m = {}
        try:
            res = call()
            ans = answer(res, scale)
            m["answer"] = ans
            m["median_s"], m["samples"] = measure(call)
        except Exception as err:  # OCC raises Standard_Failure as a Python exception
            m["answer"] = {"no_answer": f"exception: {type(err).__name__}: {err}"}
            m.setdefault("median_s", None)
        m["verdict"] = judge(m["answer"], pair["expect"])
        rec[name] = m
    return rec


# ---------------------------------------------------------------- quadsect


def shown(cmd):
    """A command line with the paths inside the repository made relative."""
    return " ".join(os.path.relpath(w, ROOT) if w.startswith(ROOT + os.sep) else w for w in cmd)


def run_quadsect(qs, pairs_path):
    """quadsect's natural-pair rows {name: median_s}, or (None, reason)."""
    if not os.path.exists(qs):
        return None, f"{qs} not found (cargo build --release, or --quadsect PATH)"
    cmd = [qs, "bench", "natural", "--pairs", pairs_path, "--json"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        first = (p.stderr.strip().splitlines() or [""])[0]
        return None, (f"`{shown(cmd)}` failed (exit {p.returncode}: {first}) — this quadsect "
                      "has no --pairs option yet (issue 15 adds it); the OCC side is measured alone")
    try:
        rows = json.loads(p.stdout)
    except json.JSONDecodeError:
        rows = [json.loads(line) for line in p.stdout.splitlines() if line.strip().startswith("{")]
    pair_rows = {r["id"]: r for r in rows if r.get("suite") == "natural-pair"}
    if not pair_rows:
        return None, "quadsect printed no natural-pair rows"
    group_rows = {r["id"]: r for r in rows if r.get("suite") == "natural-group"}
    return {"pairs": pair_rows, "groups": group_rows, "command": shown(cmd)}, None


# ---------------------------------------------------------------- report


def summarise(records, groups):
    out = {}
    for g in groups:
        rs = [r for r in records if r["group"] == g]
        row = {"pairs": len(rs)}
        for m in ("intpatch", "intana", "intss", "quadsect"):
            ts = [r[m]["median_s"] for r in rs if m in r and r[m].get("median_s") is not None]
            if ts:
                row[m] = {"median_s": statistics.median(ts), "max_s": max(ts), "timed": len(ts)}
            if m != "quadsect" and any(m in r for r in rs):
                v = [r[m]["verdict"] for r in rs if m in r]
                row.setdefault("verdicts", {})[m] = {k: v.count(k) for k in ("right", "wrong", "no answer")}
                if m == "intana":
                    row["verdicts"][m]["no answer on curve pairs"] = sum(
                        1 for r in rs if m in r and r[m]["verdict"] == "no answer" and r["expect"]["class"] == "curve")
        q = row.get("quadsect")
        if q:
            for m in ("intpatch", "intana", "intss"):
                if m in row:
                    row.setdefault("ratios", {})[f"quadsect/{m}"] = q["median_s"] / row[m]["median_s"]
        out[g] = row
    return out


def markdown(summary, records):
    lines = ["| group | pairs | IntPatch median / max | IntAna median / max | GeomInt_IntSS median / max | "
             "quadsect median / max | quadsect / IntPatch | IntPatch right / wrong / no answer | "
             "IntAna right / wrong / no answer (on curve pairs) | IntSS right / wrong / no answer |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for g, row in summary.items():
        def mm(m):
            x = row.get(m)
            return f"{fmt_t(x['median_s'])} / {fmt_t(x['max_s'])}" if x else "–"

        def vv(m, extra=False):
            v = row.get("verdicts", {}).get(m)
            if not v:
                return "–"
            s = f"{v['right']} / {v['wrong']} / {v['no answer']}"
            if extra:
                s += f" ({v['no answer on curve pairs']})"
            return s

        ratio = row.get("ratios", {}).get("quadsect/intpatch")
        lines.append(f"| {g} | {row['pairs']} | {mm('intpatch')} | {mm('intana')} | {mm('intss')} | {mm('quadsect')} | "
                     f"{'%.2f' % ratio if ratio else '–'} | {vv('intpatch')} | {vv('intana', True)} | {vv('intss')} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pairs", default=os.path.join(ROOT, "benches", "data", "natural_pairs.json"))
    ap.add_argument("--quadsect", default=os.path.join(ROOT, "target", "release", "quadsect"))
    ap.add_argument("--no-quadsect", action="store_true", help="measure the OCC side only")
    ap.add_argument("--no-intss", action="store_true", help="skip GeomInt_IntSS")
    ap.add_argument("--groups", default="", help="comma-separated groups (default all)")
    ap.add_argument("--only", default="", help="comma-separated pair names")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "occ_results.json"))
    ap.add_argument("--md-out", default=os.path.join(ROOT, "docs", "occ_results.md"),
                    help="the printed tables, also written here ('' for none)")
    ap.add_argument("--report", action="store_true", help="only print (and write) the tables of --out")
    args = ap.parse_args()
    if args.report:
        write_report(json.load(open(args.out)), args.out, args.md_out)
        return

    doc = json.load(open(args.pairs))
    pairs = doc["pairs"]
    if args.groups:
        keep = set(args.groups.split(","))
        pairs = [p for p in pairs if p["group"] in keep]
    if args.only:
        keep = set(args.only.split(","))
        pairs = [p for p in pairs if p["name"] in keep]
    groups = list(dict.fromkeys(p["group"] for p in pairs))

    # the cost of one Python -> OCC call that does nothing (an empty IntAna_QuadQuadGeo)
    overhead, _ = measure(lambda: IntAna_QuadQuadGeo())
    print(f"Python/pybind11 overhead of one call (empty IntAna_QuadQuadGeo()): {fmt_t(overhead)}", file=sys.stderr)
    records = []
    t0 = time.time()
    for k, pair in enumerate(pairs, 1):
        rec = run_pair(pair, not args.no_intss)
        records.append(rec)
        brief = "  ".join(f"{m} {fmt_t(rec[m].get('median_s'))} {rec[m]['verdict']}"
                          for m in ("intpatch", "intana", "intss") if m in rec)
        print(f"[{k}/{len(pairs)}] {pair['name']}: {brief}", file=sys.stderr)

    qs_info = None
    if not args.no_quadsect:
        qs, why = run_quadsect(args.quadsect, args.pairs)
        if qs is None:
            print(f"quadsect: {why}", file=sys.stderr)
            qs_info = {"skipped": why}
        else:
            qs_info = {"command": qs["command"], "groups": qs["groups"]}
            for rec in records:
                row = qs["pairs"].get(rec["name"])
                if row:
                    rec["quadsect"] = {"median_s": row["median_s"], "samples": row.get("samples")}
    summary = summarise(records, groups)
    import OCP
    result = {
        "description": "Open CASCADE (IntPatch_ImpImpIntersection, IntAna_QuadQuadGeo, GeomInt_IntSS) and quadsect "
                       "on the natural-quadric pairs, same run; written by scripts/bench_occ.py",
        "command": " ".join([os.path.relpath(sys.executable, ROOT) if sys.executable.startswith(ROOT) else sys.executable,
                             "scripts/bench_occ.py"] + sys.argv[1:]),
        "pairs_file": os.path.relpath(args.pairs, ROOT),
        "occ": {"module": "OCP (cadquery-ocp-novtk)", "version": getattr(OCP, "__version__", None),
                "tolerance": TOL},
        "machine": {"python": sys.version.split()[0], "platform": platform.platform(), "cpus": os.cpu_count()},
        "python_call_overhead_s": overhead,
        "started": time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(t0)),
        "quadsect": qs_info,
        "summary": summary,
        "pairs": records,
    }
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w") as f:
        json.dump(result, f, indent=1)
        f.write("\n")
    write_report(result, args.out, args.md_out)


def write_report(result, out_path, md_path):
    """The Markdown tables of a results document: printed, and written to md_path."""
    summary, records = result["summary"], result["pairs"]
    tot = {m: {k: sum(r.get("verdicts", {}).get(m, {}).get(k, 0) for r in summary.values())
               for k in ("right", "wrong", "no answer")} for m in ("intpatch", "intana", "intss")
           if any(m in r.get("verdicts", {}) for r in summary.values())}
    qs_info = result.get("quadsect") or {}
    overall = summarise([dict(r, group="all") for r in records], ["all"])["all"]
    medians = "; ".join(f"{m} {fmt_t(overall[m]['median_s'])} (slowest {fmt_t(overall[m]['max_s'])})"
                        for m in ("intpatch", "intana", "intss", "quadsect") if m in overall)
    text = [f"Open CASCADE {result['occ']['version']} beside quadsect, {result['started']}, "
            f"`{result['command']}`", "", markdown(summary, records), "",
            f"All {len(records)} pairs: " + "; ".join(
                f"{m} {v['right']} right / {v['wrong']} wrong / {v['no answer']} no answer" for m, v in tot.items()),
            f"Median over all pairs of each pair's median: {medians}.",
            "", f"Python call overhead included in OCC's times: {fmt_t(result['python_call_overhead_s'])} per call "
            "(an empty IntAna_QuadQuadGeo()).",
            "quadsect: " + (f"`{qs_info['command']}`" if "command" in qs_info
                            else qs_info.get("skipped", "not run (--no-quadsect)")),
            f"Raw results: {os.path.relpath(out_path, ROOT)}."]
    print("\n".join(text))
    if md_path:
        with open(md_path, "w") as f:
            f.write("\n".join(text) + "\n")

if __name__ == "__main__":
    main()
