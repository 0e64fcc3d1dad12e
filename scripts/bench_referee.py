#!/usr/bin/env python3
"""The referee of natural quadrics on the benchmark pairs: its cost against
the fast classification (class and counts) through `quadsect batch` on one
thread, and how tight it is (hi/lo) by input group.

    python3 scripts/bench_referee.py [--quadsect ./target/release/quadsect]
        [--pairs benches/data/natural_pairs.json] [--repeat 5]

Prints markdown (docs/BENCHMARKS.md, "The referee").  Needs only the
quadsect binary.
"""
import argparse
import collections
import json
import os
import subprocess
import tempfile
import time
from fractions import Fraction


def run(qs, path):
    t = time.perf_counter()
    out = subprocess.run([qs, "batch", "--threads", "1", path], capture_output=True, text=True, check=True).stdout
    return time.perf_counter() - t, out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quadsect", default="./target/release/quadsect")
    ap.add_argument("--pairs", default="benches/data/natural_pairs.json")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    pairs = json.load(open(args.pairs))["pairs"]
    tmp = tempfile.mkdtemp()
    files = {}
    for ref in (False, True):
        lines = [json.dumps({"id": p["name"], "op": "natural", "a": p["a"], "b": p["b"],
                             "components": False, "referee": ref}) for p in pairs]
        files[ref] = os.path.join(tmp, f"ref{int(ref)}.jsonl")
        with open(files[ref], "w") as f:
            f.write("\n".join(lines * args.repeat) + "\n")
    times = {False: [], True: []}
    for _ in range(3):  # alternate, median of three
        for ref in (False, True):
            dt, out = run(args.quadsect, files[ref])
            times[ref].append(dt)
    n = len(pairs) * args.repeat
    t0, t1 = sorted(times[False])[1] / n, sorted(times[True])[1] / n
    print(f"Command: `python3 scripts/bench_referee.py --repeat {args.repeat}` ({len(pairs)} pairs × {args.repeat}, "
          "`quadsect batch --threads 1`, components off, median of three alternating runs)\n")
    print("| per pair (batch, JSON included) | class and counts | with the referee | ratio |")
    print("|---|---|---|---|")
    print(f"| mean | {t0 * 1e6:.1f} µs | {t1 * 1e6:.1f} µs | {t1 / t0:.1f}× |\n")
    groups = collections.defaultdict(lambda: collections.Counter())
    ratios = collections.defaultdict(list)
    for line in out.splitlines()[: len(pairs)]:
        r = json.loads(line)
        g = r["id"].rsplit("-", 1)[0]
        f = r["result"]["referee"] if "result" in r else r["referee"]
        lo = Fraction(f["lo_exact"])
        hi = None if f["hi_exact"] is None else Fraction(f["hi_exact"])
        c = groups[g]
        c["pairs"] += 1
        c["lo = 0"] += lo == 0
        c["witness"] += hi is not None
        if lo > 0 and hi is not None:
            ratios[g].append(float(hi / lo))
    print("| group | pairs | lo = 0 | with a witness | lo > 0 and a witness | hi/lo ≤ 10 | median hi/lo |")
    print("|---|---|---|---|---|---|---|")
    tot = collections.Counter()
    allr = []
    for g in sorted(groups):
        c, q = groups[g], sorted(ratios[g])
        tot.update(c)
        allr += q
        med = f"{q[len(q) // 2]:.3g}" if q else "–"
        print(f"| {g} | {c['pairs']} | {c['lo = 0']} | {c['witness']} | {len(q)} | {sum(x <= 10 for x in q)} | {med} |")
    allr.sort()
    med = f"{allr[len(allr) // 2]:.3g}" if allr else "–"
    print(f"| all | {tot['pairs']} | {tot['lo = 0']} | {tot['witness']} | {len(allr)} | {sum(x <= 10 for x in allr)} | {med} |")


if __name__ == "__main__":
    main()
