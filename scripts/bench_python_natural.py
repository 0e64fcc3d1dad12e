#!/usr/bin/env python3
"""Per-call cost of `quadsect.natural` from Python against the engine's own
time (issue 41: typed quadrics should cost at most 2x the engine).

    scripts/test_python.sh        # a venv .venv-pytest with the package installed
    .venv-pytest/bin/python scripts/bench_python_natural.py [--repeat 7] [--out docs/python_natural_bench.json]

The pairs: benches/data/natural_pairs.json in the groups class-*,
random-int and near-degenerate (the fast groups; `double`,
`occ-regression` and `decimal500` hold the slow and huge pairs), as typed
`Sphere`/`Cylinder`/`Cone` objects built once.  For each pair and each
mode, in alternation (so a change of the machine's load touches both):

* engine: `quadsect._quadsect._engine_time(a, b, components, n)`, the
  engine's `classify_with` on the parsed quadrics in a Rust loop (what
  `quadsect bench natural` times), seconds per call;
* python: `quadsect.natural(a, b, components=...)` called n times from a
  Python loop, reading `classification` and the counts (and, with
  components, building the typed `components` list), seconds per call.

n is chosen so that one sample takes about 2 ms; each number is the
median of --repeat samples.  Modes: `counts` (components=False, the fast
route) and `components` (components=True, the typed components read).
Prints per-group medians and the overall median of the per-pair ratios
python/engine, and writes every row to --out.
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import platform
import statistics
import sys
import time

import quadsect
from quadsect import Cone, Cylinder, Sphere, _quadsect

ROOT = pathlib.Path(__file__).resolve().parents[1]
GROUPS = ("class-", "random-int", "near-degenerate")


def typed(d):
    if d["kind"] == "sphere":
        return Sphere(d["center"], d["radius2"])
    if d["kind"] == "cylinder":
        return Cylinder(d["point"], d["axis"], d["radius2"])
    (name,) = [k for k in ("tan2", "tan", "cos2", "sin2") if k in d]
    return Cone(d["vertex"], d["axis"], **{name: d[name]})


def python_time(a, b, components, n):
    natural = quadsect.natural
    t = time.perf_counter()
    if components:
        for _ in range(n):
            r = natural(a, b)
            r.classification, r.conics, r.lines, r.points, r.components
    else:
        for _ in range(n):
            r = natural(a, b, components=False)
            r.classification, r.conics, r.lines, r.points
    return (time.perf_counter() - t) / n


def measure(a, b, components, repeat):
    one = _quadsect._engine_time(a._native, b._native, components, 20)
    n = max(1, min(20000, int(0.002 / max(one, 1e-7))))
    python_time(a, b, components, max(1, n // 10))  # warm
    eng, py = [], []
    for _ in range(repeat):
        eng.append(_quadsect._engine_time(a._native, b._native, components, n))
        py.append(python_time(a, b, components, n))
    return statistics.median(eng), statistics.median(py), n


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--modes", default="counts,components")
    ap.add_argument("--out", default=str(ROOT / "docs" / "python_natural_bench.json"))
    args = ap.parse_args()

    data = json.loads((ROOT / "benches" / "data" / "natural_pairs.json").read_text())
    pairs = [p for p in data["pairs"] if p["group"].startswith(GROUPS)]
    load_before = os.getloadavg()
    rows = []
    for mode in args.modes.split(","):
        components = mode == "components"
        for p in pairs:
            a, b = typed(p["a"]), typed(p["b"])
            eng, py, n = measure(a, b, components, args.repeat)
            rows.append({"mode": mode, "name": p["name"], "group": p["group"], "calls_per_sample": n,
                         "engine_us": round(eng * 1e6, 3), "python_us": round(py * 1e6, 3),
                         "ratio": round(py / eng, 3), "overhead_us": round((py - eng) * 1e6, 3)})
    load_after = os.getloadavg()

    def group_of(name):
        return "class-*" if name.startswith("class-") else name

    summary = []
    for mode in args.modes.split(","):
        mrows = [r for r in rows if r["mode"] == mode]
        groups = sorted({group_of(r["group"]) for r in mrows}) + ["all"]
        for g in groups:
            rs = [r for r in mrows if g == "all" or group_of(r["group"]) == g]
            summary.append({
                "mode": mode, "group": g, "pairs": len(rs),
                "engine_us": round(statistics.median(r["engine_us"] for r in rs), 2),
                "python_us": round(statistics.median(r["python_us"] for r in rs), 2),
                "overhead_us": round(statistics.median(r["overhead_us"] for r in rs), 2),
                "ratio_median": round(statistics.median(r["ratio"] for r in rs), 2),
                "ratio_max": round(max(r["ratio"] for r in rs), 2),
                "pairs_within_2x": sum(r["ratio"] <= 2 for r in rs),
            })
    result = {
        "command": "scripts/bench_python_natural.py " + " ".join(sys.argv[1:]),
        "python": sys.version.split()[0],
        "machine": f"{platform.machine()}, {os.cpu_count()} cores",
        "load_average_1min_before_after": [round(load_before[0], 2), round(load_after[0], 2)],
        "quadsect": quadsect.__version__,
        "repeat": args.repeat,
        "summary": summary,
        "rows": rows,
    }
    pathlib.Path(args.out).write_text(json.dumps(result, indent=2) + "\n")
    print(f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after; medians over pairs of "
          f"per-pair medians of {args.repeat} samples\n")
    print("| mode | group | pairs | engine (µs) | Python `natural` (µs) | overhead (µs) "
          "| Python/engine median | max | pairs ≤ 2× |")
    print("|---|---|---|---|---|---|---|---|---|")
    for s in summary:
        print(f"| {s['mode']} | {s['group']} | {s['pairs']} | {s['engine_us']:.2f} | {s['python_us']:.2f} | "
              f"{s['overhead_us']:.2f} | {s['ratio_median']:.2f} | {s['ratio_max']:.2f} | "
              f"{s['pairs_within_2x']}/{s['pairs']} |")


if __name__ == "__main__":
    main()
