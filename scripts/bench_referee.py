#!/usr/bin/env python3
"""The referee of natural quadrics on the benchmark pairs: its cost against
the fast classification (class and counts) through `quadsect batch` on one
thread, and how tight it is (hi/lo) by input group.

    python3 scripts/bench_referee.py [--quadsect ./target/release/quadsect]
        [--pairs benches/data/natural_pairs.json] [--repeat 5]

Prints markdown (docs/BENCHMARKS.md, "The referee").  Needs only the
quadsect binary; with `--occ` (run with a Python that has quadsect and its
`occ` extra, e.g. `.venv-pytest/bin/python`) also Open CASCADE's
IntPatch_ImpImpIntersection on every pair (quadsect.occ's worker, 10 s per
call) and, on the pairs where its answer is wrong, the stability interval
and whether its answer is the witness's.
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
    ap.add_argument("--occ", action="store_true")
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
    if args.occ:
        occ_table(pairs, out)


def gp_params(s):
    """quadsect.occ's picklable parameters of a pair's surface, as
    scripts/bench_occ.py builds it (doubles nearest to the exact data)."""
    import math

    def vec(v):
        return tuple(float(Fraction(x)) for x in v)

    def fsqrt(q):
        import decimal
        with decimal.localcontext() as ctx:
            ctx.prec = 40
            return float((decimal.Decimal(q.numerator) / decimal.Decimal(q.denominator)).sqrt())

    if s["kind"] == "sphere":
        return ("sphere", vec(s["center"]), (0.0, 0.0, 1.0), fsqrt(Fraction(s["radius2"])))
    if s["kind"] == "cylinder":
        return ("cylinder", vec(s["point"]), vec(s["axis"]), fsqrt(Fraction(s["radius2"])))
    return ("cone", vec(s["vertex"]), vec(s["axis"]), math.atan(fsqrt(Fraction(s["tan2"]))), 0.0)


def occ_table(pairs, out):
    from quadsect import occ

    answers = {json.loads(line)["id"]: json.loads(line)["result"] for line in out.splitlines()[: len(pairs)]}
    worker = occ._IntPatchWorker(10.0)
    wrong = []
    try:
        for p in pairs:
            try:
                theirs = worker(gp_params(p["a"]), gp_params(p["b"]))
            except Exception as err:  # a null direction: gp_ refuses it
                theirs = {"no_answer": str(err)}
            mine = answers[p["name"]]
            exact = {k: mine[k] for k in ("class", "conics", "lines", "points")}
            if not occ._same(exact, theirs):
                wrong.append((p["name"], exact, theirs, mine["referee"]))
    finally:
        worker.close()
    small = [w for w in wrong if w[3]["hi_exact"] is not None and Fraction(w[3]["hi_exact"]) <= Fraction(1, 10**6)]
    explained = [w for w in small if "no_answer" not in w[2] and occ._same(w[3]["nearby"]["answer"], w[2])]
    print(f"\nIntPatch_ImpImpIntersection wrong (or no answer) on {len(wrong)} of {len(pairs)} pairs; "
          f"hi ≤ 1e-6 on {len(small)} of them ({100 * len(small) / max(1, len(wrong)):.0f}%), "
          f"and IntPatch's answer is the witness's on {len(explained)}.\n")
    print("| pair | exact | IntPatch | lo | hi | witness's answer |")
    print("|---|---|---|---|---|---|")

    def ans(a):
        return a.get("no_answer", "no answer") if "no_answer" in a else f"{a['class']} {a['conics']}/{a['lines']}/{a['points']}"

    for name, exact, theirs, f in wrong:
        near = ans(f["nearby"]["answer"]) if f["nearby"] else "–"
        print(f"| {name} | {ans(exact)} | {ans(theirs)} | {f['lo']} | {f['hi'] or '–'} | {near} |")


if __name__ == "__main__":
    main()
