#!/usr/bin/env python3
"""Combine `quadsect bench all --json` with the FLINT/PARI/sympy anchors of
../shared/bench/bench_anchors.py (results.json) and bench_elimination.py
(elimination_results.json), measured in the same session, into the ratio
tables of docs/BENCHMARKS.md.

    python3 scripts/bench_table.py docs/quadsect_bench.json docs/anchors_results.json docs/elimination_results.json
"""
import json
import sys


def fmt(s):
    if s is None:
        return "—"
    if s < 1e-6:
        return f"{s * 1e9:.0f} ns"
    if s < 1e-3:
        return f"{s * 1e6:.1f} µs"
    if s < 1:
        return f"{s * 1e3:.2f} ms"
    return f"{s:.2f} s"


def ratio(a, b):
    if a is None or b is None:
        return "—"
    r = a / b
    return f"{r:.2g}×" if r < 10 else f"{r:.0f}×"


def main():
    ours_rows = json.load(open(sys.argv[1]))
    anchors = json.load(open(sys.argv[2]))
    elim = json.load(open(sys.argv[3])) if len(sys.argv) > 3 else {}
    ours = {}
    for r in ours_rows:
        ours.setdefault(r["id"], {})[r["desc"]] = r["median_s"]

    def med(entry, key):
        v = entry.get(key)
        return v.get("median_s") if isinstance(v, dict) else None

    print("### Resultants (univariate, 64-bit coefficients)\n")
    print("| case | quadsect | FLINT | PARI | sympy (python) | quadsect/FLINT | quadsect/PARI |")
    print("|---|---|---|---|---|---|---|")
    for e in anchors["resultant"]:
        q = ours.get(e["id"], {}).get("resultant (multi-modular)")
        f, p, s = med(e, "flint.res"), med(e, "pari.res"), med(e, "sympy[python].res")
        print(f"| {e['id']} | {fmt(q)} | {fmt(f)} | {fmt(p)} | {fmt(s)} | {ratio(q, f)} | {ratio(q, p)} |")
    print("\n### Exact real-root isolation\n")
    print("| case | quadsect (VCA) | FLINT isolate (VCA) | PARI polrootsreal | sympy intervals | quadsect/FLINT | quadsect/PARI |")
    print("|---|---|---|---|---|---|---|")
    for e in anchors["roots"]:
        q = ours.get(e["id"], {}).get("exact real-root isolation (VCA)")
        f, p, s = med(e, "flint.isolate"), med(e, "pari.rootsreal"), med(e, "sympy[python].intervals")
        print(f"| {e['id']} | {fmt(q)} | {fmt(f)} | {fmt(p)} | {fmt(s)} | {ratio(q, f)} | {ratio(q, p)} |")
    print("\n### Counting real roots (Sturm)\n")
    print("| case | quadsect Sturm | FLINT Sturm | PARI polsturm | sympy count_roots | quadsect/FLINT | quadsect/PARI |")
    print("|---|---|---|---|---|---|---|")
    for e in anchors["roots"]:
        q = ours.get(e["id"], {}).get("Sturm count of real roots")
        f, p, s = med(e, "flint.sturm"), med(e, "pari.polsturm"), med(e, "sympy[python].count")
        print(f"| {e['id']} | {fmt(q)} | {fmt(f)} | {fmt(p)} | {fmt(s)} | {ratio(q, f)} | {ratio(q, p)} |")
    print("\n### Bivariate resultant\n")
    print("| case | quadsect | FLINT | PARI | sympy (python) | quadsect/FLINT | quadsect/PARI |")
    print("|---|---|---|---|---|---|---|")
    for e in anchors["bivariate"]:
        q = ours.get(e["id"], {}).get("bivariate resultant (evaluation/interpolation mod p)")
        f, p, s = med(e, "flint.mres"), med(e, "pari.res"), med(e, "sympy[python].res")
        print(f"| {e['id']} | {fmt(q)} | {fmt(f)} | {fmt(p)} | {fmt(s)} | {ratio(q, f)} | {ratio(q, p)} |")
    if elim:
        print("\n### Tangent point method: quadsect's full verdict vs D(u) alone elsewhere\n")
        print("| example | quadsect (D(u), exact min/max, witnesses) | FLINT branch-split resultants (D(u) only) | sympy Gröbner (D(u) only) | quadsect/FLINT | quadsect/sympy |")
        print("|---|---|---|---|---|---|")
        for ex, key in [("ex1", "paper_ex1"), ("ex4", "paper_ex4")]:
            q = list(ours.get(key, {}).values())
            q = q[0] if q else None
            f = (elim.get(f"{ex}/flint.branch") or {}).get("median_s")
            s = (elim.get(f"{ex}/sympy.groebner[python]") or {}).get("median_s")
            print(f"| {ex} | {fmt(q)} | {fmt(f)} | {fmt(s)} | {ratio(q, f)} | {ratio(q, s)} |")


if __name__ == "__main__":
    main()
