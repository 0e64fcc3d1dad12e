#!/usr/bin/env python3
"""Instruction counts (callgrind) of the budget checks, the counting
allocator and the streaming batch, against a build without them.

Each case is a batch file of one benchmark input repeated; every binary
answers it with one worker thread.  Two counts per run:

* `compute`: instructions inside `quadsect::batch::answer_line` (base) or
  `answer_line_within` (new), with `--toggle-collect`: the parsing, the
  computation and the formatting of each answer, budget checks included;
* `total`: the whole process (start-up, reading, the allocator, writing).

Usage:
    scripts/bench_budget_overhead.py BASE_BIN NEW_BIN [NOALLOC_BIN] > docs/budget_overhead.json

BASE_BIN is a build of the commit before the budgets (rayon batch, no
allocator: run with RAYON_NUM_THREADS=1); NEW_BIN the current build (run
with its default limits, and with `--time-limit none --memory-limit none`);
NOALLOC_BIN the current sources without `#[global_allocator]`.
"""

import json
import os
import re
import subprocess
import sys
import tempfile

EX1ROT_E = "x^2 - x + y^2 + 2*y/3 + z^2 - 2*z - 851/36"
EX1ROT_S = ("77053*x^2/378225 + 15064*x*y/126075 + 1463*x*z/25215 - 56476*x/42025"
            " + 20957*y^2/168100 + 1469*y*z/16810 + 139529*y/126075 + 2561*z^2/26896"
            " + 65923*z/67240 + 47931433/6051600")

CASES = [
    ("tangent_paper_ex1", 200, {"op": "tangent", "ellipsoid": "x^2+y^2+z^2-25",
                                "surface": "(x-9)^2/9+y^2/4+z^2/16-1"}),
    ("tangent_paper_ex4", 100, {"op": "tangent", "ellipsoid": "2x^2+3y^2+4z^2-25",
                                "surface": "(x-1)^4/9+y^2/4+4z^2/23-1"}),
    ("tangent_ex1_rotated", 50, {"op": "tangent", "ellipsoid": EX1ROT_E, "surface": EX1ROT_S}),
    ("tangent_quadric_generic", 200, {"op": "tangent", "ellipsoid": "x^2+2y^2+3z^2-10",
                                      "surface": "(x-1)^2+y^2/2+z^2/3+x*y/5-y*z/7-2"}),
    ("tangent_cubic", 20, {"op": "tangent", "ellipsoid": "x^2+2y^2+3z^2-6",
                           "surface": "x*y*z+x^2-y+1/3"}),
    ("natural_skew_cones", 200, {"op": "natural",
                                 "a": "cone vertex=0,0,0 axis=1,0,0 tan2=1/3",
                                 "b": "cone vertex=0,1,1 axis=0,1,0 tan2=1"}),
    ("natural_conics", 500, {"op": "natural",
                             "a": "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
                             "b": "cylinder point=0,0,0 axis=0,1,0 radius2=1"}),
    ("roots_wilkinson20", 200, {"op": "roots",
                                "poly": "*".join(f"(x-{k})" for k in range(1, 21)) + "+1"}),
    ("roots_dense30", 100, {"op": "roots",
                            "poly": "+".join(f"{(7 * k * k + 3) % 19 - 9}*x^{k}" for k in range(31))}),
    ("resultant_bivariate", 100, {"op": "resultant", "f": "x^5*y^2-3x^3*y+2x*y^4-7+y",
                                  "g": "2x^4-x^2*y^3+5x*y-1", "var": "x"}),
]


def callgrind(cmd, env, toggle):
    with tempfile.NamedTemporaryFile(suffix=".cg") as out:
        args = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out.name}"]
        if toggle:
            args.append(f"--toggle-collect={toggle}")
        subprocess.run(args + cmd, env=env, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        text = open(out.name).read()
    m = re.search(r"^summary:\s*(\d+)", text, re.M) or re.search(r"^totals:\s*(\d+)", text, re.M)
    return int(m.group(1))


def main():
    base, new = sys.argv[1], sys.argv[2]
    noalloc = sys.argv[3] if len(sys.argv) > 3 else None
    env1 = dict(os.environ, RAYON_NUM_THREADS="1")
    runs = [("base", [base, "batch"], env1)]
    runs.append(("new_default_limits", [new, "batch", "--threads", "1"], os.environ))
    runs.append(("new_no_limits", [new, "batch", "--threads", "1", "--time-limit", "none",
                                   "--memory-limit", "none"], os.environ))
    if noalloc:
        runs.append(("new_without_allocator", [noalloc, "batch", "--threads", "1"], os.environ))
    results = []
    for name, reps, line in CASES:
        with tempfile.NamedTemporaryFile("w", suffix=".jsonl", delete=False) as f:
            for i in range(reps):
                f.write(json.dumps(dict(line, id=i)) + "\n")
            path = f.name
        row = {"case": name, "lines": reps}
        for rname, cmd, env in runs:
            row[rname] = {
                "compute": callgrind(cmd + [path], env, "quadsect::batch::answer_line*"),
                "total": callgrind(cmd + [path], env, None),
            }
        for rname, _, _ in runs[1:]:
            for k in ("compute", "total"):
                row[rname][k + "_ratio"] = round(row[rname][k] / row["base"][k], 4)
        os.unlink(path)
        results.append(row)
        print(json.dumps(row), file=sys.stderr)
    json.dump(results, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
