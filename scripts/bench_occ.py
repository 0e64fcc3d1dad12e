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
    one markdown table per group and a summary table;
  * then the whole answer (issue 41): quadsect's `whole_s` (class, counts
    AND exact components, in-process) beside IntPatch_ImpImpIntersection and
    IntAna_QuadQuadGeo per group, per input kind and per exact class (the
    pair's `expect` class), class-and-counts on the doubles, and
    `quadsect batch FILE --threads 2|1` over a batch built from the same
    pairs (with and without `"components": false`), timed on the wall clock
    over the whole file repeated until it lasts >= --batch-seconds; the
    pairs/s figure excludes decimal500, which is timed apart; and the goals
    with their measured values (section "Whole answer" of the Markdown,
    keys `whole_answer`, `batch`, `goals` of the JSON).

Hangs and crashes: the OCC calls run in a worker subprocess that reports
after each call and each timing sample; when it is silent for --timeout
seconds (a hanging call) or dies (a crash), the parent kills it, records the
method as "no answer" (hang / crash) for that pair, starts a new worker and
goes on with the pair's remaining methods.

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
        [--timeout 60] [--no-batch] [--batch-seconds 2.5] [--batch-runs 3]
    .venv-occ/bin/python scripts/bench_occ.py --report   # the tables of --out again

The whole-answer report needs neither GeomInt_IntSS nor its minutes:
    nice -n 10 .venv-occ/bin/python scripts/bench_occ.py --no-intss --quadsect PATH
"""
import argparse
import decimal
import importlib.util
import resource
import select
import signal
import tempfile
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


def measure(f, beat=None):
    """Median seconds per call of f: quadsect's protocol (src/bench.rs `measure`).
    beat(), when given, is called after every sample (the worker's heartbeat)."""
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
        if beat is not None:
            beat()
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

# the tally of IntPatch's pieces (class and counts) is the package's own,
# python/quadsect/_occ_answer.py, loaded by path (no quadsect install here)
_spec = importlib.util.spec_from_file_location(
    "_occ_answer", os.path.join(ROOT, "python", "quadsect", "_occ_answer.py"))
_occ_answer = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_occ_answer)
CONIC_ITYPES, Tally, answer_intpatch = _occ_answer.CONIC_ITYPES, _occ_answer.Tally, _occ_answer.answer_intpatch
xyz, scale_of, dist = _occ_answer.xyz, _occ_answer.scale_of, _occ_answer.dist


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


METHODS = ("intpatch", "intana", "intss")


def run_pair(pair, do_intss, skip=(), emit=None):
    """One pair's OCC record; methods in skip are left out; emit(event), when
    given, is told when a method starts, its answer, each timing sample and
    its result (the worker's progress, see OccWorker)."""
    emit = emit or (lambda ev: None)
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
        if name in skip:
            continue
        emit({"ev": "start", "method": name})
        m = {}
        try:
            res = call()
            ans = answer(res, scale)
            m["answer"] = ans
            emit({"ev": "answer", "method": name, "answer": ans})
            m["median_s"], m["samples"] = measure(call, lambda: emit({"ev": "beat"}))
        except Exception as err:  # OCC raises Standard_Failure as a Python exception
            m["answer"] = {"no_answer": f"exception: {type(err).__name__}: {err}"}
            m.setdefault("median_s", None)
        m["verdict"] = judge(m["answer"], pair["expect"])
        rec[name] = m
        emit({"ev": "method", "method": name, "data": m})
    return rec


# ---------------------------------------------------------------- hang guard


class OccWorker:
    """The OCC calls in a subprocess (this script with --worker-fd), so that a
    hanging or crashing OCC call costs one method of one pair, not the run.

    The parent sends one JSON line per pair on the worker's stdin
    ({"pair", "skip", "intss"}); the worker answers on a pipe of its own (its
    stdout goes to our stderr: OCC may print there) with events: start of a
    method, its answer, a beat after each timing sample, the method's result,
    and "done" with the record.  No event for `timeout` seconds, or the
    worker's death, ends the method in progress as "no answer"; the worker is
    killed (by its pid) and a new one finishes the pair."""

    def __init__(self, timeout):
        self.timeout = timeout
        self.proc = None
        self.buf = b""
        self.restarts = 0

    def start(self):
        r, w = os.pipe()
        self.proc = subprocess.Popen([sys.executable, os.path.abspath(__file__), "--worker-fd", str(w)],
                                     stdin=subprocess.PIPE, stdout=sys.stderr.fileno(), pass_fds=(w,))
        os.close(w)
        self.fd = r
        self.buf = b""
        # start-up (importing OCP) is not an OCC call: a generous wait of its own
        kind, ev = self.event(max(self.timeout, 300))
        if kind != "event" or ev.get("ev") != "ready":
            self.stop()
            raise RuntimeError(f"the OCC worker did not start: {ev}")

    def stop(self):
        if self.proc is None:
            return
        try:
            if self.proc.poll() is None:
                self.proc.kill()
            self.proc.wait()
        finally:
            try:
                self.proc.stdin.close()
            except OSError:
                pass
            os.close(self.fd)
            self.proc = None

    def event(self, timeout=None):
        """The next event, or ("timeout" | "died", detail)."""
        timeout = timeout or self.timeout
        deadline = time.monotonic() + timeout
        while b"\n" not in self.buf:
            left = deadline - time.monotonic()
            if left <= 0:
                return "timeout", f"hang: no progress for {timeout:g} s (worker killed)"
            ready, _, _ = select.select([self.fd], [], [], left)
            if not ready:
                continue
            chunk = os.read(self.fd, 1 << 16)
            if not chunk:
                code = self.proc.wait()
                what = (f"signal {signal.Signals(-code).name}" if code < 0 else f"exit {code}")
                return "died", f"crash: the worker died ({what})"
            self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        return "event", json.loads(line)

    def run_pair(self, pair, do_intss):
        rec = {"name": pair["name"], "group": pair["group"], "expect": pair["expect"]}
        done, failures = {}, []
        while True:
            if self.proc is None:
                self.start()
            try:
                self.proc.stdin.write((json.dumps({"pair": pair, "skip": sorted(done), "intss": do_intss})
                                       + "\n").encode())
                self.proc.stdin.flush()
            except BrokenPipeError:
                pass  # the event loop sees the death
            current, answer = None, None
            while True:
                kind, ev = self.event()
                if kind != "event":
                    self.stop()
                    self.restarts += 1
                    failures.append(ev)
                    if current is None:  # outside the methods: building the surfaces
                        rec["error"] = ev
                        rec.update({m: done[m] for m in METHODS if m in done})
                        rec["failures"] = failures
                        return rec
                    m = {"answer": answer or {"no_answer": ev}, "median_s": None, "failure": ev}
                    if answer is not None:
                        m["failure"] = ev + ", while timing"
                    m["verdict"] = judge(m["answer"], pair["expect"])
                    done[current] = m
                    break
                if ev["ev"] == "start":
                    current, answer = ev["method"], None
                elif ev["ev"] == "answer":
                    answer = ev["answer"]
                elif ev["ev"] == "method":
                    done[ev["method"]] = ev["data"]
                    current = None
                elif ev["ev"] == "done":
                    r = ev["rec"]
                    for m in METHODS:
                        if m in done:
                            r[m] = done[m]
                    ordered = {k: v for k, v in r.items() if k not in METHODS}
                    ordered.update({m: r[m] for m in METHODS if m in r})
                    if failures:
                        ordered["failures"] = failures
                    return ordered


def worker(fd):
    """The worker's loop (see OccWorker)."""
    out = os.fdopen(fd, "w")

    def emit(ev):
        out.write(json.dumps(ev) + "\n")
        out.flush()

    emit({"ev": "ready"})
    for line in sys.stdin:
        job = json.loads(line)
        rec = run_pair(job["pair"], job["intss"], set(job["skip"]), emit)
        emit({"ev": "done", "rec": rec})


# ---------------------------------------------------------------- quadsect


def shown(cmd):
    """A command line with the paths inside the repository made relative."""
    return " ".join(os.path.relpath(w, ROOT) if w.startswith(ROOT + os.sep) else w for w in cmd)


def input_kind(group):
    """The input kind of a group, as quadsect's bench rows name it (src/cli/bench.rs `input_kind`)."""
    if group.startswith("class-") or group == "random-int":
        return "small-integers"
    return {"double": "doubles", "near-degenerate": "near-degenerate", "occ-regression": "occ-regression",
            "decimal500": "decimal500"}.get(group, "other")


KINDS = ("small-integers", "doubles", "near-degenerate", "occ-regression", "decimal500")
CLASSES = ("conics", "conic-and-line", "lines", "points", "empty", "curve", "same-surface")


def run_quadsect(qs, pairs_path, timeout=3600):
    """quadsect's natural-pair rows {name: row}, or (None, reason)."""
    if not os.path.exists(qs):
        return None, f"{qs} not found (cargo build --release, or --quadsect PATH)"
    cmd = [qs, "bench", "natural", "--pairs", pairs_path, "--json"]
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, f"`{shown(cmd)}` did not finish in {timeout} s (killed)"
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



# ---------------------------------------------------------------- batch


def batch_lines(pairs, components, repeat):
    """The batch file's text: one natural line per pair, the pair list repeated."""
    out = []
    for r in range(repeat):
        for p in pairs:
            line = {"id": p["name"] if r == 0 else f"{p['name']}#{r}", "op": "natural", "a": p["a"], "b": p["b"]}
            if not components:
                line["components"] = False
            out.append(json.dumps(line, separators=(",", ":")))
    return "\n".join(out) + "\n"


def batch_once(qs, path, threads, out_path, timeout, cpu=None):
    """Wall seconds of `quadsect batch path --threads N` (its output to out_path);
    its CPU seconds (user + system) appended to cpu when given."""
    cmd = [qs, "batch", path, "--threads", str(threads)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(out_path, "w") as out:
        t = time.perf_counter()
        p = subprocess.run(cmd, stdout=out, stderr=subprocess.PIPE, text=True, timeout=timeout)
        wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise RuntimeError(f"`{shown(cmd)}` exit {p.returncode}: {p.stderr.strip()[:300]}")
    if cpu is not None:
        cpu.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return wall


def check_batch(out_path, pairs):
    """(lines, ok lines, answers whose class and counts agree with expect)."""
    expect = {p["name"]: p["expect"] for p in pairs}
    n = ok = agree = 0
    with open(out_path) as f:
        for line in f:
            n += 1
            r = json.loads(line)
            if not r.get("ok"):
                continue
            ok += 1
            e, a = expect[r["id"].split("#")[0]], r["result"]
            agree += all(a.get(k) == e.get(k) for k in ("class", "conics", "lines", "points"))
    return n, ok, agree


def run_batch(qs, pairs, label, components, threads, seconds, runs, repeat, tmp, timeout):
    """pairs/s of quadsect batch on these pairs: a calibration pass over the
    file once (also checked against expect), then `runs` timed passes over
    the file repeated until one pass lasts >= seconds; the median wall."""
    once = os.path.join(tmp, "once.jsonl")
    with open(once, "w") as f:
        f.write(batch_lines(pairs, components, 1))
    out = os.path.join(tmp, "out.jsonl")
    t1 = batch_once(qs, once, threads, out, timeout)
    n, ok, agree = check_batch(out, pairs)
    path = os.path.join(tmp, "batch.jsonl")
    fixed = repeat is not None
    if not fixed:  # grow the repeat count until one pass lasts >= seconds (a short pass is mostly start-up)
        repeat, wall = 1, t1
        while wall < seconds:
            repeat = max(repeat + 1, math.ceil(repeat * min(1.2 * seconds / max(wall, 1e-3), 50)))
            with open(path, "w") as f:
                f.write(batch_lines(pairs, components, repeat))
            wall = batch_once(qs, path, threads, out, timeout)
    with open(path, "w") as f:
        f.write(batch_lines(pairs, components, repeat))
    for _ in range(3):  # a busy machine can make the calibration pass slow: grow and time again
        walls, cpus = [], []
        for _ in range(runs):
            walls.append(batch_once(qs, path, threads, out, timeout, cpus))
            print(f"  batch {label} components={components} threads={threads}: {repeat} x {len(pairs)} lines "
                  f"in {walls[-1]:.3f} s", file=sys.stderr)
        wall = statistics.median(walls)
        if fixed or wall >= 0.8 * seconds:
            break
        repeat = math.ceil(repeat * 1.2 * seconds / wall)
        with open(path, "w") as f:
            f.write(batch_lines(pairs, components, repeat))
    lines_total = repeat * len(pairs)
    return {"set": label, "components": components, "threads": threads, "pairs": len(pairs), "repeat": repeat,
            "lines": lines_total, "wall_s": walls, "median_wall_s": wall, "pairs_per_s": lines_total / wall,
            "cpu_s": cpus, "pairs_per_cpu_s": lines_total / statistics.median(cpus),
            "load_average": os.getloadavg(),
            "once_wall_s": t1, "once_ok": ok, "once_agree": agree, "once_lines": n,
            "command": f"{shown([qs])} batch FILE --threads {threads}"}


def batch_suite(qs, pairs, seconds, runs, repeat, timeout):
    """quadsect batch over the pairs without decimal500 and, apart, decimal500."""
    sets = [("without decimal500", [p for p in pairs if p["group"] != "decimal500"]),
            ("decimal500", [p for p in pairs if p["group"] == "decimal500"])]
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench_occ_batch") as tmp:
        for label, ps in sets:
            if not ps:
                continue
            for components in (True, False):
                for threads in (2, 1):
                    try:
                        rows.append(run_batch(qs, ps, label, components, threads, seconds, runs, repeat, tmp,
                                              timeout))
                    except (RuntimeError, subprocess.TimeoutExpired) as err:
                        rows.append({"set": label, "components": components, "threads": threads,
                                     "pairs": len(ps), "error": str(err)})
                        print(f"  batch {label} components={components} threads={threads}: {err}",
                              file=sys.stderr)
    return {"line_format": '{"id": NAME, "op": "natural", "a": A, "b": B} (+ "components": false), '
                           "the pairs' JSON quadrics as in the pair file",
            "protocol": (f"wall clock of the whole process over the file repeated {repeat} times" if repeat else
                         f"wall clock of the whole process over the file repeated until one pass lasts "
                         f">= {seconds:g} s") + f" (after a pass once through, checked), median of {runs} passes; "
                        "decimal500 apart",
            "load_average": os.getloadavg(), "runs": rows}


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


# ---------------------------------------------------------------- whole answer


def _stats(xs):
    """{median_s, max_s, n} of (seconds, name) pairs, with the slowest's name; None when empty."""
    if not xs:
        return None
    xs = sorted(xs)
    return {"median_s": statistics.median([x for x, _ in xs]), "max_s": xs[-1][0], "slowest": xs[-1][1],
            "n": len(xs)}


def _timing(r, m, key="median_s"):
    x = r.get(m)
    return x.get(key) if x else None


def whole_table(records, label_of, labels):
    """One row per label: quadsect's whole answer, its class and counts, IntPatch
    and IntAna (median and max over the pairs of each pair's median), the ratio
    of medians and the pairs where the whole answer is slower than IntPatch."""
    out = {}
    for lab in labels:
        rs = [r for r in records if label_of(r) == lab]
        if not rs:
            continue
        row = {"pairs": len(rs)}
        for key, m, field in (("quadsect_whole", "quadsect", "whole_s"), ("quadsect_counts", "quadsect", "median_s"),
                              ("intpatch", "intpatch", "median_s"), ("intana", "intana", "median_s")):
            st = _stats([(_timing(r, m, field), r["name"]) for r in rs if _timing(r, m, field) is not None])
            if st:
                row[key] = st
        w, ip, ia = row.get("quadsect_whole"), row.get("intpatch"), row.get("intana")
        if w and ip:
            row["whole/intpatch"] = w["median_s"] / ip["median_s"]
        if w and ia:
            row["whole/intana"] = w["median_s"] / ia["median_s"]
        if row.get("quadsect_counts") and ip:
            row["counts/intpatch"] = row["quadsect_counts"]["median_s"] / ip["median_s"]
        both = [(r["quadsect"]["whole_s"], r["intpatch"]["median_s"], r["name"]) for r in rs
                if _timing(r, "quadsect", "whole_s") is not None and _timing(r, "intpatch") is not None]
        slower = [n for q, i, n in both if q > i]
        row["compared_with_intpatch"] = len(both)
        row["whole_slower_than_intpatch"] = len(slower)
        row["slower_pairs"] = slower
        out[lab] = row
    return out


def whole_answer(records):
    """The whole-answer tables (per input kind, exact class, group) and the
    class-and-counts comparison on the doubles."""
    groups = list(dict.fromkeys(r["group"] for r in records))
    res = {"by_kind": whole_table(records, lambda r: r.get("kind") or input_kind(r["group"]), KINDS),
           "by_class": whole_table(records, lambda r: r["expect"]["class"], CLASSES),
           "by_group": whole_table(records, lambda r: r["group"], groups)}
    rest = [r for r in records if r["group"] != "decimal500" and _timing(r, "quadsect", "whole_s") is not None]
    if rest:
        res["batch_bound"] = {
            "pairs": len(rest),
            "mean_whole_s": statistics.mean(r["quadsect"]["whole_s"] for r in rest),
            "mean_counts_s": statistics.mean(r["quadsect"]["median_s"] for r in rest)}
    d = res["by_kind"].get("doubles")
    if d and d.get("quadsect_counts") and d.get("intpatch"):
        res["counts_doubles"] = {"quadsect_counts_median_s": d["quadsect_counts"]["median_s"],
                                 "intpatch_median_s": d["intpatch"]["median_s"],
                                 "intpatch/counts": d["intpatch"]["median_s"] / d["quadsect_counts"]["median_s"]}
    return res


def goals(whole, batch, records):
    """The issue's goals with the measured values: [{goal, measured, met}]."""
    out = []
    kinds = whole["by_kind"]
    per = [(k, row["quadsect_whole"]["median_s"], row["intpatch"]["median_s"]) for k, row in kinds.items()
           if "quadsect_whole" in row and "intpatch" in row]
    if per:
        out.append({"goal": "whole answer median <= IntPatch median on every input kind",
                    "measured": "; ".join(f"{k} {fmt_t(q)} vs {fmt_t(i)}" for k, q, i in per),
                    "met": all(q <= i for _, q, i in per)})
    over, worst = [], {}
    for k, row in kinds.items():
        limit = 20e-3 if k == "decimal500" else 1e-3
        w = row.get("quadsect_whole")
        if not w:
            continue
        worst[k] = (w["max_s"], w["slowest"], limit)
    for r in records:
        t = _timing(r, "quadsect", "whole_s")
        if t is None:
            continue
        limit = 20e-3 if (r.get("kind") or input_kind(r["group"])) == "decimal500" else 1e-3
        if t > limit:
            over.append(r["name"])
    if worst:
        out.append({"goal": "every pair's whole answer <= 1 ms, decimal500 <= 20 ms",
                    "measured": "; ".join(f"{k} slowest {fmt_t(m)} ({n})" for k, (m, n, _) in worst.items())
                                + f"; {len(over)} pairs over their limit",
                    "met": all(m <= lim for m, _, lim in worst.values()), "over": over})
    cd = whole.get("counts_doubles")
    if cd:
        out.append({"goal": "class and counts on doubles: median <= 5 µs",
                    "measured": fmt_t(cd["quadsect_counts_median_s"]),
                    "met": cd["quadsect_counts_median_s"] <= 5e-6})
        out.append({"goal": "class and counts on doubles: >= 4x faster than IntPatch (ratio of medians)",
                    "measured": f"{cd['intpatch/counts']:.1f}x (IntPatch {fmt_t(cd['intpatch_median_s'])})",
                    "met": cd["intpatch/counts"] >= 4})
    if batch:
        row = next((r for r in batch["runs"] if r["set"] == "without decimal500" and r["components"]
                    and r["threads"] == 2 and "pairs_per_s" in r), None)
        if row:
            out.append({"goal": "quadsect batch, components, 2 threads (without decimal500): >= 20 000 pairs/s",
                        "measured": f"{row['pairs_per_s']:,.0f} pairs/s", "met": row["pairs_per_s"] >= 20000})
    return out


def whole_markdown(result):
    """The section "Whole answer" of the report."""
    whole, batch = result["whole_answer"], result.get("batch")

    def mm(x):
        return f"{fmt_t(x['median_s'])} / {fmt_t(x['max_s'])}" if x else "–"

    def table(rows, first):
        t = [f"| {first} | pairs | quadsect whole median / max | IntPatch median / max | whole / IntPatch | "
             "whole slower than IntPatch | IntAna median / max | whole / IntAna | class & counts median / max | "
             "slowest whole |",
             "|---|---|---|---|---|---|---|---|---|---|"]
        for lab, row in rows.items():
            w = row.get("quadsect_whole")
            r1, r2 = row.get("whole/intpatch"), row.get("whole/intana")
            t.append(f"| {lab} | {row['pairs']} | {mm(w)} | {mm(row.get('intpatch'))} | "
                     f"{'%.2f' % r1 if r1 else '–'} | {row['whole_slower_than_intpatch']} of "
                     f"{row['compared_with_intpatch']} | {mm(row.get('intana'))} | {'%.2f' % r2 if r2 else '–'} | "
                     f"{mm(row.get('quadsect_counts'))} | {w['slowest'] if w else '–'} |")
        return "\n".join(t)

    text = ["", "## Whole answer", "",
            "quadsect's whole answer (`whole_s` of `quadsect bench natural`: class, counts and exact components, "
            "in-process, no JSON) beside IntPatch_ImpImpIntersection (which computes the curves) and "
            "IntAna_QuadQuadGeo, same pairs, same run. Medians and maxima over the pairs of each pair's median; "
            "IntPatch / IntAna over the pairs where they returned (a wrong or no answer is still timed); "
            "\"whole slower than IntPatch\": pairs where quadsect's whole answer takes longer than IntPatch's "
            "call. Ratios < 1: quadsect faster.", "",
            "### By input kind", "", table(whole["by_kind"], "input kind"), "",
            "### By exact class (the pair's expected class)", "", table(whole["by_class"], "exact class"), "",
            "### By group", "", table(whole["by_group"], "group"), ""]
    cd = whole.get("counts_doubles")
    if cd:
        text += [f"Class and counts only (`median_s`, no components) on the doubles: median "
                 f"{fmt_t(cd['quadsect_counts_median_s'])} against IntPatch {fmt_t(cd['intpatch_median_s'])}: "
                 f"{cd['intpatch/counts']:.1f}x faster.", ""]
    if batch:
        text += ["### Through `quadsect batch`", "",
                 f"One line per pair: `{batch['line_format']}`; {batch['protocol']}. Load average at the "
                 f"start: {' '.join('%.2f' % x for x in batch['load_average'])}.", "",
                 "pairs/s is on the wall clock (what the goal counts); pairs per CPU-second (user + system "
                 "time of the batch process, all threads) shows what a busy machine hides."]
        bb = whole.get("batch_bound")
        if bb:
            text[-1] += (f" In-process bound per thread, 1 / mean over the {bb['pairs']} pairs without decimal500 "
                         f"of each pair's median: {1 / bb['mean_whole_s']:,.0f} pairs/s with components (mean "
                         f"{fmt_t(bb['mean_whole_s'])}), {1 / bb['mean_counts_s']:,.0f} without (mean "
                         f"{fmt_t(bb['mean_counts_s'])}).")
        text += ["",
                 "| pairs | components | threads | lines per pass | wall (median) | pairs/s | pairs per CPU-s | "
                 "load average after | once through: ok / agree with expect |",
                 "|---|---|---|---|---|---|---|---|---|"]
        for r in batch["runs"]:
            comp = "yes" if r["components"] else "no (`\"components\": false`)"
            if "error" in r:
                text.append(f"| {r['set']} ({r['pairs']}) | {comp} | {r['threads']} | – | – | – | – | – | "
                            f"{r['error']} |")
                continue
            text.append(f"| {r['set']} ({r['pairs']}) | {comp} | {r['threads']} | {r['lines']} "
                        f"({r['repeat']} × {r['pairs']}) | {r['median_wall_s']:.3f} s | {r['pairs_per_s']:,.0f} | "
                        f"{r['pairs_per_cpu_s']:,.0f} | {r['load_average'][0]:.2f} | "
                        f"{r['once_ok']} / {r['once_agree']} of {r['once_lines']} |")
        text.append("")
    gl = result.get("goals") or []
    if gl:
        text += ["### Goals", "", "| goal | measured | met |", "|---|---|---|"]
        for g in gl:
            text.append(f"| {g['goal']} | {g['measured']} | {'yes' if g['met'] else '**no**'} |")
        over = next((g.get("over") for g in gl if g.get("over")), None)
        if over:
            text += ["", "Pairs over their limit (1 ms; decimal500 20 ms): " + ", ".join(over) + "."]
        text.append("")
    text.append(f"Command: `{result['command']}`; quadsect: `{(result.get('quadsect') or {}).get('command', '–')}`"
                + (f", then `{batch['runs'][0].get('command', 'quadsect batch FILE --threads N')}` and --threads 1"
                   if batch and batch["runs"] else "") + ".")
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pairs", default=os.path.join(ROOT, "benches", "data", "natural_pairs.json"))
    ap.add_argument("--quadsect", default=os.path.join(ROOT, "target", "release", "quadsect"))
    ap.add_argument("--no-quadsect", action="store_true", help="measure the OCC side only")
    ap.add_argument("--no-intss", action="store_true", help="skip GeomInt_IntSS (the whole-answer report does not "
                    "need it; it takes up to 12 s on some pairs)")
    ap.add_argument("--groups", default="", help="comma-separated groups (default all)")
    ap.add_argument("--only", default="", help="comma-separated pair names")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "occ_results.json"))
    ap.add_argument("--md-out", default=os.path.join(ROOT, "docs", "occ_results.md"),
                    help="the printed tables, also written here ('' for none)")
    ap.add_argument("--report", action="store_true", help="only print (and write) the tables of --out")
    ap.add_argument("--timeout", type=float, default=60.0,
                    help="hang guard: seconds without progress (one OCC call or timing sample) after which the "
                         "OCC worker is killed and the method recorded as no answer (default 60; 0: no worker, "
                         "OCC in this process, unguarded)")
    ap.add_argument("--no-batch", action="store_true", help="skip the `quadsect batch` throughput runs")
    ap.add_argument("--batch-seconds", type=float, default=2.5,
                    help="repeat the batch file until one pass lasts at least this long (default 2.5)")
    ap.add_argument("--batch-repeat", type=int, default=None, help="fixed repeat count of the batch file")
    ap.add_argument("--batch-runs", type=int, default=3, help="timed passes per batch configuration (median)")
    ap.add_argument("--worker-fd", type=int, default=None, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.worker_fd is not None:
        worker(args.worker_fd)
        return
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
    if not pairs:
        sys.exit("no pair selected")
    groups = list(dict.fromkeys(p["group"] for p in pairs))

    # the cost of one Python -> OCC call that does nothing (an empty IntAna_QuadQuadGeo)
    overhead, _ = measure(lambda: IntAna_QuadQuadGeo())
    print(f"Python/pybind11 overhead of one call (empty IntAna_QuadQuadGeo()): {fmt_t(overhead)}", file=sys.stderr)
    records = []
    t0 = time.time()
    guard = OccWorker(args.timeout) if args.timeout > 0 else None
    try:
        for k, pair in enumerate(pairs, 1):
            rec = guard.run_pair(pair, not args.no_intss) if guard else run_pair(pair, not args.no_intss)
            records.append(rec)
            brief = "  ".join(f"{m} {fmt_t(rec[m].get('median_s'))} {rec[m]['verdict']}"
                              for m in METHODS if m in rec)
            if rec.get("failures"):
                brief += "  [" + "; ".join(rec["failures"]) + "]"
            print(f"[{k}/{len(pairs)}] {pair['name']}: {brief}", file=sys.stderr)
    finally:
        if guard:
            guard.stop()
    occ_wall = time.time() - t0

    qs_info, batch = None, None
    if not args.no_quadsect:
        # a subset is benchmarked from a pair file of its own (quadsect's bench times every pair of its file)
        subset = len(pairs) != len(doc["pairs"])
        tmp = None
        pairs_path = args.pairs
        if subset:
            tmp = tempfile.NamedTemporaryFile("w", prefix="bench_occ_pairs", suffix=".json", delete=False)
            json.dump(dict(doc, pairs=pairs), tmp)
            tmp.close()
            pairs_path = tmp.name
        try:
            qs, why = run_quadsect(args.quadsect, pairs_path)
        finally:
            if tmp:
                os.unlink(tmp.name)
        if qs is None:
            print(f"quadsect: {why}", file=sys.stderr)
            qs_info = {"skipped": why}
        else:
            qs_info = {"command": qs["command"], "groups": qs["groups"]}
            if subset:
                qs_info["note"] = "the selected pairs, written to a temporary pair file"
            for rec in records:
                row = qs["pairs"].get(rec["name"])
                if row:
                    rec["quadsect"] = {"median_s": row["median_s"], "samples": row.get("samples")}
                    for k in ("whole_s", "answer", "agrees", "method"):
                        if k in row:
                            rec["quadsect"][k] = row[k]
                    rec["kind"] = row.get("kind") or input_kind(rec["group"])
            if not args.no_batch:
                print("quadsect batch:", file=sys.stderr)
                batch = batch_suite(args.quadsect, pairs, args.batch_seconds, args.batch_runs, args.batch_repeat,
                                    timeout=3600)
    summary = summarise(records, groups)
    import OCP
    result = {
        "description": "Open CASCADE (IntPatch_ImpImpIntersection, IntAna_QuadQuadGeo, GeomInt_IntSS) and quadsect "
                       "on the natural-quadric pairs, same run; written by scripts/bench_occ.py",
        "command": " ".join([os.path.relpath(sys.executable, ROOT) if sys.executable.startswith(ROOT) else sys.executable,
                             "scripts/bench_occ.py"] + sys.argv[1:]),
        "pairs_file": os.path.relpath(args.pairs, ROOT),
        "occ": {"module": "OCP (cadquery-ocp-novtk)", "version": getattr(OCP, "__version__", None),
                "tolerance": TOL, "hang_timeout_s": args.timeout or None,
                "worker_restarts": guard.restarts if guard else None, "wall_s": occ_wall},
        "machine": {"python": sys.version.split()[0], "platform": platform.platform(), "cpus": os.cpu_count()},
        "python_call_overhead_s": overhead,
        "started": time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(t0)),
        "quadsect": qs_info,
        "summary": summary,
    }
    if any(_timing(r, "quadsect", "whole_s") is not None for r in records):
        result["whole_answer"] = whole_answer(records)
        result["batch"] = batch
        result["goals"] = goals(result["whole_answer"], batch, records)
    result["pairs"] = records
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
    failed = [(r["name"], f) for r in records for f in r.get("failures", [])]
    text = [f"Open CASCADE {result['occ']['version']} beside quadsect, {result['started']}, "
            f"`{result['command']}`", "", markdown(summary, records), "",
            f"All {len(records)} pairs: " + "; ".join(
                f"{m} {v['right']} right / {v['wrong']} wrong / {v['no answer']} no answer" for m, v in tot.items()),
            f"Median over all pairs of each pair's median: {medians}.",
            "", f"Python call overhead included in OCC's times: {fmt_t(result['python_call_overhead_s'])} per call "
            "(an empty IntAna_QuadQuadGeo()).",
            (f"OCC hangs and crashes (worker killed after {result['occ'].get('hang_timeout_s')} s without progress): "
             + ("; ".join(f"{n}: {f}" for n, f in failed) if failed else "none") + "."
             if result["occ"].get("hang_timeout_s") else "OCC ran in-process, without the hang guard."),
            "quadsect: " + (f"`{qs_info['command']}`" if "command" in qs_info
                            else qs_info.get("skipped", "not run (--no-quadsect)")),
            f"Raw results: {os.path.relpath(out_path, ROOT)}."]
    if result.get("whole_answer"):
        result = dict(result, whole_answer=whole_answer(records))  # recomputed: --report follows the script
        result["goals"] = goals(result["whole_answer"], result.get("batch"), records)
        text += whole_markdown(result)
    print("\n".join(text))
    if md_path:
        with open(md_path, "w") as f:
            f.write("\n".join(text) + "\n")


if __name__ == "__main__":
    main()
