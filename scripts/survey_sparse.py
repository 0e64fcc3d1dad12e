#!/usr/bin/env python3
"""Random *sparse* surfaces against a few ellipsoids: which route answers, how fast, and how
often the answer is `undecided` (issue 17's "surfaces users actually have").

    python3 scripts/survey_sparse.py --quadsect target/release/quadsect
        [--seed 1] [--count 30] [--time-limit 10] [--out docs/sparse_survey.tsv]

Each case: S of degree d in 5..8 with one term of degree d and 2..5 more terms of random
degree 0..d, monomials and coefficients (from -3, -2, -1, 1, 2, 3, 5, 7) drawn at random; E
one of four ellipsoids (a sphere, two axis-tilted ones, the rotated ellipsoid of the issue).
The same seed gives the same cases. One line per case (tab-separated): index, degree of S,
wall time (s), verdict, the certificate's method, the budget message (if any), E, S. A
summary goes to stderr.

Why sparse: random monomials often share a power of a variable (S = c + x^k·T: a plane of
singular points, so curves of critical points), or vanish to second order along a
coordinate axis (singular points of S on E: multiple critical points), and their top forms
are singular at infinity (zeros at infinity of the critical system in every direction).
Dense random surfaces have none of these.
"""
import argparse
import json
import random
import subprocess
import sys
import time

ELLIPSOIDS = [
    "3x^2+y^2+2z^2+x*y-4",
    "x^2+y^2+z^2-4",
    "18*x*x-12*x*y+10*x*z+23*y*y-24*y*z+14*z*z-2*x+3*y+2*z-27",
    "2x^2+3y^2+z^2-y*z+x-5",
]
COEFFS = [-3, -2, -1, 1, 2, 3, 5, 7]


def monomial(rng, d):
    a = rng.randint(0, d)
    b = rng.randint(0, d - a)
    c = d - a - b
    parts = []
    for v, e in zip("xyz", (a, b, c)):
        if e == 1:
            parts.append(v)
        elif e > 1:
            parts.append(f"{v}^{e}")
    return "*".join(parts) if parts else "1"


def cases(seed, count):
    rng = random.Random(seed)
    for i in range(count):
        d = rng.randint(5, 8)
        terms = [(rng.choice(COEFFS), monomial(rng, d))]
        for _ in range(rng.randint(2, 5)):
            terms.append((rng.choice(COEFFS), monomial(rng, rng.randint(0, d))))
        s = " + ".join(f"({c})*{m}" for c, m in terms)
        yield i, d, rng.choice(ELLIPSOIDS), s


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quadsect", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=30)
    ap.add_argument("--time-limit", default="10")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    out = open(a.out, "w") if a.out else sys.stdout
    tally = {}
    for i, d, e, s in cases(a.seed, a.count):
        t0 = time.time()
        r = subprocess.run(
            [a.quadsect, "tangent", "--ellipsoid", e, "--surface", s, "--json",
             "--time-limit", a.time_limit],
            capture_output=True, text=True)
        dt = time.time() - t0
        try:
            j = json.loads(r.stdout)
            verdict, method = j["verdict"], j["certificate"]["method"]
            reason = (j.get("reason") or {}).get("message", "")
        except (ValueError, KeyError, TypeError):
            verdict, method, reason = "ERROR", "", r.stderr.strip()[-200:]
        key = "undecided" if verdict == "undecided" else ("error" if verdict == "ERROR" else method)
        tally[key] = tally.get(key, 0) + 1
        print(f"{i}\t{d}\t{dt:.2f}\t{verdict}\t{method}\t{reason}\t{e}\t{s}", file=out, flush=True)
    print(f"seed {a.seed}, {a.count} cases: " +
          ", ".join(f"{k} {v}" for k, v in sorted(tally.items())), file=sys.stderr)


if __name__ == "__main__":
    main()
