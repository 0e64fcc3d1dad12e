#!/usr/bin/env python3
"""How far past its time limit each hostile input runs (wall clock).

Runs `quadsect` on a list of inputs that are slow, huge or both (the
issue-16 findings and variations), each with `--time-limit LIMIT`, and
prints one JSON line per input: wall time, overshoot, exit status and the
answer's kind.  Usage:  scripts/budget_overshoot.py BIN [LIMIT]
"""

import json
import random
import subprocess
import sys
import time


def dense(d, seed=7):
    terms = []
    m = (1 << 64) - 1
    for i in range(d + 1):
        for j in range(d + 1 - i):
            for k in range(d + 1 - i - j):
                seed = (seed * 6364136223846793005 + 1442695040888963407) & m
                terms.append(f"{(seed >> 33) % 19 - 9}*x^{i}*y^{j}*z^{k}")
    return "+".join(terms)


def cases():
    e264 = "(x--2)^2/6+(y--5)^2/6+(z-0)^2/4-1"
    s264 = "-9/4*4*y*y+5*yz+6/3*z*z+-12/2*xx+3*yz^126+8/5*z+6/3"
    yield "tangent_264_bytes", ["tangent", "--ellipsoid", e264, "--surface", s264]
    yield "tangent_huge_literal", ["tangent", "--ellipsoid", "x^2+y^2+z^2-1",
                                   "--surface", "x-5e-98709-90e-5083"]
    for d in (3, 4, 5, 6, 8, 10):
        yield f"tangent_dense_degree_{d}", ["tangent", "--ellipsoid", "x^2+2y^2+3z^2-5",
                                            "--surface", dense(d)]
    yield "tangent_huge_quadric", ["tangent", "--ellipsoid", "x^2+y^2+z^2-" + "7" * 90000,
                                   "--surface", "(x-" + "3" * 90000 + ")^2+y^2/" + "9" * 50000 + "+z^2-1"]
    yield "roots_sparse_6667", ["roots", "x^6667-3x^5000+7x^4000-x^3333+5x^2000-2x^1000"
                                "+x^500-9x^100+x^50-3x^10+x-1"]
    rnd = random.Random(3)
    yield "roots_dense_2000", ["roots", "+".join(f"{rnd.randint(-99, 99)}*x^{k}" for k in range(2001))]
    yield "roots_big_coefficients", ["roots", "+".join(f"{rnd.randint(1, 9)}{'7' * 3000}*x^{k}"
                                                       for k in range(0, 300, 3)) + "-1"]
    yield "roots_mignotte_like", ["roots", "x^1000-2*(" + "9" * 5000 + "*x-1)^2"]
    yield "resultant_bivariate_200", ["resultant", "+".join(f"{rnd.randint(-9, 9)}*x^{i}*y^{j}"
                                                            for i in range(60) for j in range(0, 60, 7)),
                                      "+".join(f"{rnd.randint(-9, 9)}*x^{i}*y^{j}"
                                               for i in range(0, 60, 5) for j in range(60)), "--var", "x"]
    yield "resultant_trivariate", ["resultant", "(x+y+z+1)^12-3", "(x-2y+z^2-1)^9+x", "--var", "x"]
    yield "parse_sum_of_fractions", ["roots", "+".join(f"x/{k}" for k in range(1, 60000))]
    yield "natural_huge_numbers", ["natural", f"cone vertex=0,0,0 axis=1,{'3' * 20000},0 tan2=1/{'7' * 20000}",
                                   f"cylinder point=0,{'1' * 20000},1 axis=0,0,{'9' * 20000} radius2=2"]


def main():
    binary = sys.argv[1]
    limit = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
    for name, args in cases():
        argv = [binary] + args + ["--time-limit", str(limit), "--json"]
        if sum(len(a) for a in argv) > 120_000:
            # too long for one argument list: a batch line instead
            line = {"id": name, "op": args[0]}
            if args[0] == "tangent":
                line.update(ellipsoid=args[2], surface=args[4])
            elif args[0] == "roots":
                line.update(poly=args[1])
            elif args[0] == "natural":
                line.update(a=args[1], b=args[2])
            argv = [binary, "batch", "--time-limit", str(limit)]
            t0 = time.time()
            r = subprocess.run(argv, input=json.dumps(line) + "\n", capture_output=True, text=True)
        else:
            t0 = time.time()
            r = subprocess.run(argv, capture_output=True, text=True)
        wall = time.time() - t0
        out = r.stdout.strip()
        answer = out[:160]
        print(json.dumps({"case": name, "limit": limit, "wall": round(wall, 3),
                          "overshoot": round(wall - limit, 3), "status": r.returncode,
                          "stderr": r.stderr.strip()[:160], "answer": answer}), flush=True)


if __name__ == "__main__":
    main()
