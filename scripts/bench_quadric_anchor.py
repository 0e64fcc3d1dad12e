#!/usr/bin/env python3
"""FLINT / sympy anchor for the `quadric_rotated_pairs` benchmark.

For each of the 16 ellipsoid pairs of docs/quadric_pairs.json (E axis-aligned,
S a rotated ellipsoid; the same pairs `quadsect bench` decides) this times the
reference elimination methods of ../shared/bench/bench_elimination.py on the
tangent-point Lagrange system
    E = 0,  S - u = 0,  S_x - lam E_x = 0,  S_y - lam E_y = 0,  S_z - lam E_z = 0
and records, per pair and method, the median time, the D(u) found, its degree
in u, and whether it is a nonzero polynomial in u.

Nothing of bench_elimination.py is copied. It is imported from the shared
folder (default <repo root>/../shared, override with --shared) and used as is:

  * child side: bench_elimination.child(name, method) builds the system with
    lagrange_system(), runs the method and its repetitions (its own policy:
    up to 11 runs if a run takes < 50 ms, else up to 5, within a 60 s budget)
    and prints one JSON line. It looks the example up in
    bench_elimination.EXAMPLES, so the adapter registers the pair there under
    the name "pairNN" (with `^` turned into `**`) before calling it.
  * parent side: bench_elimination.run_child(name, method, cap, ground) starts
    the child with a wall-clock cap. It launches `sys.executable <its own
    __file__> --child name method`; the adapter points the module's __file__
    at this script, so the child that starts is this script's --child mode
    (which registers the pair, then calls bench_elimination.child). The pairs
    file and the shared folder reach the child through the environment.

Methods (names as in bench_elimination.py, same default set as there): flint.chain,
flint.branch, sympy.chain, sympy.branch, sympy.groebner (choose with
--methods). Every run is its own subprocess. The quick methods (all but
sympy.groebner) run one at a time. sympy.groebner, which times out on most
pairs, runs --jobs at a time (default 2) to find the timeouts in reasonable
time; each groebner run that finished in that parallel pass is then timed
again alone, and that serial timing is the one reported (the parallel one is
kept as parallel_pass_median_s; --no-retime skips the second pass). Note that a
timeout in the parallel pass means > cap seconds of wall time while sharing
the cores.

What each method computes is only the eliminant D(u) (or fails to): no root
isolation, no min/max of S on E, no certificate, i.e. less than quadsect's
"full verdict".

Usage (from the repo root):
    .venv-bench/bin/python scripts/bench_quadric_anchor.py
        [--shared PATH] [--pairs docs/quadric_pairs.json]
        [--out docs/quadric_anchor_results.json] [--cap 60] [--jobs 2]
        [--methods flint.chain,flint.branch,sympy.groebner] [--only 0,4,14]
"""
import argparse
import concurrent.futures
import importlib.util
import json
import os
import platform
import shlex
import statistics
import sys
import time

SCRIPT = os.path.abspath(__file__)
REPO = os.path.dirname(os.path.dirname(SCRIPT))
DEFAULT_SHARED = os.path.normpath(os.path.join(REPO, "..", "shared"))
ENV_SHARED = "QUADRIC_ANCHOR_SHARED"
ENV_PAIRS = "QUADRIC_ANCHOR_PAIRS"
DEFAULT_METHODS = ["flint.chain", "flint.branch", "sympy.chain", "sympy.branch", "sympy.groebner"]
PARALLEL_METHODS = {"sympy.groebner"}   # slow, mostly timeouts: found in a parallel pass


def load_bench(shared):
    path = os.path.join(shared, "bench", "bench_elimination.py")
    if not os.path.exists(path):
        sys.exit(f"bench_elimination.py not found at {path} (use --shared PATH)")
    spec = importlib.util.spec_from_file_location("bench_elimination", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod, path


def load_pairs(path):
    with open(path) as fh:
        return json.load(fh)


def pair_name(i):
    return f"pair{i:02d}"


def register(be, pairs, i):
    """Make pair i an example of bench_elimination (sympy syntax)."""
    p = pairs[i]
    be.EXAMPLES[pair_name(i)] = {"E": p["E"].replace("^", "**"),
                                 "S": p["S"].replace("^", "**")}


# --------------------------------------------------------------------------- child mode
def child_main(name, method):
    be, _ = load_bench(os.environ[ENV_SHARED])
    pairs = load_pairs(os.environ[ENV_PAIRS])
    register(be, pairs, int(name[len("pair"):]))
    be.child(name, method)


# --------------------------------------------------------------------------- D(u) analysis
def analyse_D(D):
    """(nonzero, degree in u, sorted primitive irreducible factors) from a D string."""
    import sympy as sp
    u = sp.Symbol("u")
    if D is None:
        return None, None, None
    if not isinstance(D, str) or D.startswith("0") or D == "continuum":
        return False, None, None
    e = sp.sympify(D.replace("^", "**"))
    if e.free_symbols - {u}:
        return None, None, None
    P = sp.Poly(e, u)
    if P.is_zero:
        return False, None, None
    facs = []
    for f, _m in P.factor_list()[1]:
        f = f.primitive()[1]
        if f.LC() < 0:
            f = -f
        if f.degree() > 0:
            facs.append(str(f.as_expr()).replace("**", "^"))
    return True, int(P.degree()), sorted(facs, key=lambda s: (len(s), s))


def classify(r):
    """status: ok (nonzero D(u) found) | no_D (finished without one) | timeout | error."""
    if r.get("timeout"):
        return "timeout"
    if "error" in r:
        return "error"
    if "median_s" not in r:
        return "error"
    nonzero, deg, _ = analyse_D(r.get("D"))
    return "ok" if nonzero else "no_D"


def run_one(be, name, method, cap, ground):
    t0 = time.perf_counter()
    r = be.run_child(name, method, cap, ground)
    wall = time.perf_counter() - t0
    status = classify(r)
    nonzero, deg, facs = analyse_D(r.get("D")) if status in ("ok", "no_D") else (None, None, None)
    out = {"status": status,
           "median_s": r.get("median_s") if status in ("ok", "no_D") else None,
           "n": r.get("n"), "min_s": r.get("min_s"), "max_s": r.get("max_s"),
           "deg_u": deg, "D_nonzero": nonzero, "D": r.get("D"), "D_factors": facs,
           "wall_s_incl_startup": wall}
    if status == "timeout":
        out["cap_s"] = r.get("cap_s", cap)
    if status == "error":
        tb = (r.get("error") or "no result").strip()
        out["error"] = tb.splitlines()[-1] if tb else "no result"
        out["error_tail"] = tb[-800:]
    if status == "no_D":
        out["why"] = ("branch pipeline ended in a positive-dimensional branch (no D(u))"
                      if r.get("D") == "continuum" else
                      "D(u) identically zero (equations shared a factor)" if str(r.get("D", "")).startswith("0")
                      else "no univariate element")
    for k in ("stats", "log", "basis_len", "note", "ground_types"):
        if k in r:
            out[k] = r[k]
    return out


# --------------------------------------------------------------------------- summary
def stats_block(values):
    if not values:
        return {"count": 0, "median_s": None, "mean_s": None, "min_s": None, "max_s": None}
    return {"count": len(values), "median_s": statistics.median(values),
            "mean_s": statistics.fmean(values), "min_s": min(values), "max_s": max(values)}


def censored_median(recs, cap):
    """Median over all pairs, a timeout/error counted as slower than everything.
    Returns seconds, or a string '> cap' / 'undefined' when the middle lands on a failure."""
    keys = sorted(((0, r["median_s"]) if r["status"] in ("ok", "no_D") else (1, float("inf"))) for r in recs)
    n = len(keys)
    if n == 0:
        return None
    mid = [keys[(n - 1) // 2], keys[n // 2]]
    if any(k[0] == 1 for k in mid):
        return f"> {cap} s (half or more of the pairs did not finish)"
    return (mid[0][1] + mid[1][1]) / 2


def summarise(per_pair, methods, cap):
    out = {}
    for m in methods:
        recs = [p["methods"][m] for p in per_pair if m in p["methods"]]
        fin = [r["median_s"] for r in recs if r["status"] in ("ok", "no_D")]
        withD = [r["median_s"] for r in recs if r["status"] == "ok"]
        out[m] = {
            "pairs": len(recs),
            "finished": len(fin),
            "with_nonzero_D": len(withD),
            "no_D": sum(r["status"] == "no_D" for r in recs),
            "timeout": sum(r["status"] == "timeout" for r in recs),
            "error": sum(r["status"] == "error" for r in recs),
            "over_finished_pairs": stats_block(fin),
            "over_pairs_with_nonzero_D": stats_block(withD),
            "median_all_pairs_failures_as_slowest": censored_median(recs, cap),
        }
    return out


def consistency(per_pair, methods):
    """Per pair: do the methods that found a nonzero D(u) agree on its irreducible factors?"""
    for p in per_pair:
        found = {m: set(r["D_factors"]) for m, r in p["methods"].items() if r["status"] == "ok"}
        if len(found) < 2:
            p["factor_agreement"] = None
            continue
        ref_m = "sympy.groebner" if "sympy.groebner" in found else sorted(found)[0]
        ref = found[ref_m]
        p["factor_agreement"] = {
            "reference": ref_m,
            **{m: {"same": s == ref, "extra": sorted(s - ref), "missing": sorted(ref - s)}
               for m, s in found.items() if m != ref_m}}


def fmt(s):
    if s is None:
        return "—"
    if isinstance(s, str):
        return s
    if s < 1e-3:
        return f"{s * 1e6:.0f} µs"
    if s < 1:
        return f"{s * 1e3:.2f} ms"
    return f"{s:.2f} s"


def cell(r):
    st = r["status"]
    if st == "ok":
        return f"{fmt(r['median_s'])} (deg {r['deg_u']})"
    if st == "no_D":
        tag = "continuum" if r.get("D") == "continuum" else "D≡0" if str(r.get("D", "")).startswith("0") else "no D"
        return f"{fmt(r['median_s'])}, {tag}"
    if st == "timeout":
        return f"timeout (>{r.get('cap_s')} s)"
    return "error"


def versions():
    v = {"python": platform.python_version(), "implementation": platform.python_implementation()}
    try:
        import flint
        v["python-flint"] = flint.__version__
    except Exception as e:  # noqa: BLE001
        v["python-flint"] = f"unavailable: {e}"
    import sympy
    v["sympy"] = sympy.__version__
    try:
        import gmpy2
        v["gmpy2"] = gmpy2.version()
    except Exception:  # noqa: BLE001
        v["gmpy2"] = None
    v["platform"] = platform.platform()
    v["cpu_count"] = os.cpu_count()
    return v


# --------------------------------------------------------------------------- main
def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child_main(sys.argv[2], sys.argv[3])
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--shared", default=DEFAULT_SHARED, help="the shared folder (holds bench/bench_elimination.py)")
    ap.add_argument("--pairs", default=os.path.join(REPO, "docs", "quadric_pairs.json"))
    ap.add_argument("--out", default=os.path.join(REPO, "docs", "quadric_anchor_results.json"))
    ap.add_argument("--cap", type=float, default=60.0, help="wall-clock cap in s for the first run of one method on one pair")
    ap.add_argument("--jobs", type=int, default=2, help="parallel subprocesses for sympy.groebner's first pass")
    ap.add_argument("--no-retime", action="store_true",
                    help="keep the timings of the parallel pass (default: re-time its finished runs serially)")
    ap.add_argument("--methods", default=",".join(DEFAULT_METHODS))
    ap.add_argument("--only", default=None, help="comma-separated pair indices")
    args = ap.parse_args()

    shared = os.path.abspath(args.shared)
    be, be_path = load_bench(shared)
    pairs = load_pairs(args.pairs)
    idx = [int(s) for s in args.only.split(",")] if args.only else list(range(len(pairs)))
    methods = [m.strip() for m in args.methods.split(",") if m.strip()]
    ground = os.environ.get("SYMPY_GROUND_TYPES", "python")   # as bench_elimination.main
    os.environ[ENV_SHARED] = shared
    os.environ[ENV_PAIRS] = os.path.abspath(args.pairs)
    # the adapter: run_child starts `sys.executable <module __file__> --child ...`
    be.__file__ = SCRIPT
    for i in idx:
        register(be, pairs, i)

    per_pair = [{"index": i, "name": pair_name(i), "E": pairs[i]["E"], "S": pairs[i]["S"], "methods": {}}
                for i in idx]
    by_name = {p["name"]: p for p in per_pair}
    t_start = time.perf_counter()

    def task(name, m):
        r = run_one(be, name, m, args.cap, ground)
        by_name[name]["methods"][m] = r
        print(f"{name} {m:15s} {cell(r)}", flush=True)

    fast = [m for m in methods if m not in PARALLEL_METHODS]
    slow = [m for m in methods if m in PARALLEL_METHODS]
    for m in fast:                      # quick: one at a time, nothing else running
        for p in per_pair:
            task(p["name"], m)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        futs = [ex.submit(task, p["name"], m) for m in slow for p in per_pair]
        for f in futs:
            f.result()
    if args.jobs > 1 and not args.no_retime:
        # the parallel pass mainly finds the timeouts; whatever finished is timed again
        # one at a time, so that no two measured runs share the 2 cores
        print("re-timing the finished parallel-pass runs one at a time", flush=True)
        for m in slow:
            for p in per_pair:
                first = p["methods"][m]
                if first["status"] not in ("ok", "no_D"):
                    continue
                task(p["name"], m)
                again = p["methods"][m]
                if again["status"] in ("ok", "no_D"):
                    again["parallel_pass_median_s"] = first["median_s"]
                else:           # failed when alone (noise near the cap): keep the parallel timing
                    first["note_retime"] = f"serial re-timing gave {again['status']}; parallel-pass timing kept"
                    p["methods"][m] = first
    total = time.perf_counter() - t_start

    for p in per_pair:                  # fixed method order in the file
        p["methods"] = {m: p["methods"][m] for m in methods if m in p["methods"]}
    consistency(per_pair, methods)
    summary = summarise(per_pair, methods, args.cap)
    result = {
        "description": ("FLINT/sympy anchor for quadsect's quadric_rotated_pairs: time to compute the "
                        "judging polynomial D(u) of the tangent-point Lagrange system with the methods of "
                        "bench_elimination.py, per pair (median of that script's repetitions), "
                        "then median/mean/min/max over the pairs. Only D(u) is computed (no roots, min/max, "
                        "certificate)."),
        "command": " ".join(shlex.quote(a) for a in [sys.executable] + sys.argv),
        "cwd": os.getcwd(),
        "bench_elimination": be_path,
        "pairs_file": os.path.abspath(args.pairs),
        "cap_s_first_run": args.cap,
        "jobs_parallel_pass": args.jobs,
        "parallel_pass_methods": sorted(PARALLEL_METHODS & set(methods)),
        "retimed_serially": args.jobs > 1 and not args.no_retime,
        "sympy_ground_types": ground,
        "repetitions": "bench_elimination.child: up to 11 runs if the first takes < 50 ms, else up to 5, "
                       "while the 60 s repetition budget lasts; median reported",
        "versions": versions(),
        "load_average_at_end": os.getloadavg(),
        "total_wall_s": total,
        "summary": summary,
        "pairs": per_pair,
    }
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w") as fh:
        json.dump(result, fh, indent=1)
        fh.write("\n")

    # markdown
    print()
    print(f"Wrote {args.out} in {total:.0f} s (cap {args.cap:g} s, sympy ground types {ground}).")
    print()
    print("| pair | " + " | ".join(methods) + " |")
    print("|---|" + "---|" * len(methods))
    for p in per_pair:
        print(f"| {p['index']} | " + " | ".join(cell(p["methods"][m]) for m in methods) + " |")
    print()
    print("| method | finished | nonzero D | no D | timeout | error | median (finished) | mean | min | max | median (all, failures slowest) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for m in methods:
        s = summary[m]
        f = s["over_finished_pairs"]
        print(f"| {m} | {s['finished']}/{s['pairs']} | {s['with_nonzero_D']} | {s['no_D']} | {s['timeout']} | "
              f"{s['error']} | {fmt(f['median_s'])} | {fmt(f['mean_s'])} | {fmt(f['min_s'])} | {fmt(f['max_s'])} | "
              f"{fmt(s['median_all_pairs_failures_as_slowest'])} |")


if __name__ == "__main__":
    main()
