#!/usr/bin/env python3
"""Throughput of the Python package on a batch of JSON lines: the CLI's
`quadsect batch` (reference), `quadsect.batch` on 1 and 2 Rust threads,
a plain loop of `answer_line`, and `quadsect.dask.decide_bag` on a
distributed LocalCluster (2 worker processes x 1 thread).

    scripts/test_python.sh            # builds the CLI and a venv with the package
    .venv-pytest/bin/python scripts/bench_python.py [--repeat 5] [--copies 4]

The lines: the natural-quadric pairs of benches/data/natural_pairs.json in
the groups class-*, random-int and near-degenerate (the groups whose pairs
take at most a few ms; `double`, `occ-regression` and `decimal500` hold
pairs of seconds to minutes), plus deterministic tangent problems (an
axis-parallel ellipsoid against a quadric, random.Random(SEED)), each set
repeated `--copies` times with fresh ids.  Every measurement is the median
of `--repeat` runs in this process; the answers of every method are checked
identical to the CLI's.  The methods are timed round-robin (each round
times every method once; the median of `--repeat` rounds is reported), so
a change of the machine's load touches all of them alike; the load average
before and after is recorded.  Writes docs/python_bench.json and prints the
Markdown table of docs/BENCHMARKS.md ("Python and Dask").
"""

from __future__ import annotations

import argparse
import json
import os
import pathlib
import platform
import random
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import quadsect
import quadsect.dask

ROOT = pathlib.Path(__file__).resolve().parents[1]
SEED = 20240519
NATURAL_GROUPS = ("class-", "random-int", "near-degenerate")
REFERENCE = "CLI `quadsect batch` (2 threads)"


def natural_lines():
    data = json.loads((ROOT / "benches" / "data" / "natural_pairs.json").read_text())
    return [
        {"op": "natural", "a": p["a"], "b": p["b"], "name": p["name"]}
        for p in data["pairs"]
        if p["group"].startswith(NATURAL_GROUPS)
    ]


def tangent_lines(n, rng):
    def q(lo, hi, den=4):
        return Fraction(rng.randint(lo * den, hi * den), den)

    def pos():
        return Fraction(rng.randint(1, 16), 4)

    out = []
    for i in range(n):
        cx, cy, cz = q(-2, 2), q(-2, 2), q(-2, 2)
        e = f"({pos()})*(x-({cx}))^2 + ({pos()})*(y-({cy}))^2 + ({pos()})*(z-({cz}))^2 - 1"
        kind = i % 4
        if kind == 0:
            s = f"({pos()})*(x-({q(-2, 2)}))^2 + ({pos()})*(y-({q(-2, 2)}))^2 + ({pos()})*(z-({q(-2, 2)}))^2 - ({pos()})"
        elif kind == 1:
            s = f"({q(-2, 2)})*x + ({q(-2, 2)})*y + ({q(1, 2)})*z - ({q(-2, 2)})"
        elif kind == 2:
            s = f"(x-({q(-2, 2)}))^2 + (y-({q(-2, 2)}))^2 - ({pos()})*(z-({q(-2, 2)}))^2 - ({q(-2, 2)})"
        else:
            s = f"z - ({q(-1, 1)})*x^2 - ({q(-1, 1)})*y^2 - ({q(-1, 1)})*x*y - ({q(-2, 2)})"
        out.append({"op": "tangent", "ellipsoid": e, "surface": s, "name": f"tangent-{i}"})
    return out


def workload(copies):
    rng = random.Random(SEED)
    base = natural_lines() + tangent_lines(400, rng)
    lines = []
    for c in range(copies):
        for item in base:
            lines.append(json.dumps({"id": len(lines), **{k: v for k, v in item.items() if k != "name"}}))
    return lines


def _process_cpu_seconds():
    """CPU seconds of the calling process (run on each Dask worker)."""
    import resource

    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--copies", type=int, default=4)
    ap.add_argument("--partitions", type=int, default=16)
    ap.add_argument("--cli", default=os.environ.get("QUADSECT_BIN", str(ROOT / "target" / "release" / "quadsect")))
    ap.add_argument("--out", default=str(ROOT / "docs" / "python_bench.json"))
    args = ap.parse_args()

    import dask
    import dask.bag
    import distributed

    lines = workload(args.copies)
    n = len(lines)
    load_before = os.getloadavg()
    with tempfile.TemporaryDirectory() as tmp:
        src = pathlib.Path(tmp) / "lines.jsonl"
        src.write_text("\n".join(lines) + "\n")
        parts = 4
        for i in range(parts):
            (pathlib.Path(tmp) / f"pairs-{i}.jsonl").write_text("\n".join(lines[i::parts]) + "\n")

        def cli(threads):
            def run():
                out = subprocess.run([args.cli, "batch", "--threads", str(threads), str(src)],
                                     check=True, capture_output=True)
                return out.stdout.decode().split("\n")[:-1]
            return run

        t0 = time.perf_counter()
        cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
        client = distributed.Client(cluster)
        startup = time.perf_counter() - t0
        try:
            # warm the workers (import of quadsect) before timing
            dask.bag.from_sequence(lines[:4], npartitions=2).map(quadsect.answer_line).compute()
            bag = dask.bag.from_sequence(lines, npartitions=args.partitions)

            def recipe():
                dask.bag.read_text(f"{tmp}/pairs-*.jsonl").map(quadsect.answer_line).to_textfiles(
                    f"{tmp}/out-*.jsonl")
                got = [(pathlib.Path(tmp) / f"out-{i}.jsonl").read_text().split("\n") for i in range(parts)]
                # the recipe's files in line order again, for the check below
                return [got[i % parts][i // parts] for i in range(n)]

            methods = [
                (REFERENCE, cli(2)),
                ("CLI `quadsect batch --threads 1`", cli(1)),
                ("`[answer_line(l) for l in lines]` (1 thread)", lambda: [quadsect.answer_line(l) for l in lines]),
                ("`quadsect.batch(lines, threads=1)`", lambda: list(quadsect.batch(lines, threads=1))),
                ("`quadsect.batch(lines, threads=2)`", lambda: list(quadsect.batch(lines, threads=2))),
                (f"`decide_bag` on LocalCluster (2 processes x 1 thread, {args.partitions} partitions)",
                 lambda: quadsect.dask.decide_bag(bag).compute()),
                (f"files recipe `read_text(...).map(answer_line).to_textfiles(...)` ({parts} files)", recipe),
            ]
            def cpu_seconds():
                """CPU time used so far by this process, its finished
                children (the CLI) and the Dask workers: a cost that other
                programs on the machine barely change, unlike wall time."""
                own = resource.getrusage(resource.RUSAGE_SELF)
                kids = resource.getrusage(resource.RUSAGE_CHILDREN)
                workers = client.run(_process_cpu_seconds)
                return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime + sum(workers.values())

            # round-robin: every round times every method once, so a change
            # of the machine's load touches all of them alike
            samples = {name: [] for name, _ in methods}
            cpu = {name: [] for name, _ in methods}
            reference = None
            for _ in range(args.repeat):
                for name, fn in methods:
                    c = cpu_seconds()
                    t = time.perf_counter()
                    got = fn()
                    samples[name].append(time.perf_counter() - t)
                    cpu[name].append(cpu_seconds() - c)
                    if reference is None:
                        reference = got
                    assert got == reference, name
        finally:
            client.close()
            cluster.close()
    load_after = os.getloadavg()

    rows = {name: statistics.median(ts) for name, ts in samples.items()}
    cpu_rows = {name: statistics.median(ts) for name, ts in cpu.items()}
    ref = rows[REFERENCE]
    cpu_ref = cpu_rows[REFERENCE]
    result = {
        "command": "scripts/bench_python.py " + " ".join(sys.argv[1:]),
        "lines": n,
        "copies": args.copies,
        "repeat": args.repeat,
        "python": sys.version.split()[0],
        "machine": f"{platform.machine()}, {os.cpu_count()} cores",
        "load_average_1min_before_after": [round(load_before[0], 2), round(load_after[0], 2)],
        "quadsect": quadsect.__version__,
        "dask": dask.__version__,
        "distributed": distributed.__version__,
        "cluster_startup_s": round(startup, 3),
        "median_seconds": {k: round(v, 4) for k, v in rows.items()},
        "samples_seconds": {k: [round(x, 4) for x in v] for k, v in samples.items()},
        "median_cpu_seconds": {k: round(v, 4) for k, v in cpu_rows.items()},
        "samples_cpu_seconds": {k: [round(x, 4) for x in v] for k, v in cpu.items()},
    }
    pathlib.Path(args.out).write_text(json.dumps(result, indent=2) + "\n")
    print(f"{n} lines; LocalCluster start-up {startup:.2f} s (not included below); "
          f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after\n")
    print("| method | median wall time (s) | lines/s | wall / CLI | CPU time (s) | CPU / CLI |")
    print("|---|---|---|---|---|---|")
    for name, t in rows.items():
        c = cpu_rows[name]
        print(f"| {name} | {t:.3f} | {n / t:,.0f} | {t / ref:.2f} | {c:.2f} | {c / cpu_ref:.2f} |")


if __name__ == "__main__":
    main()
