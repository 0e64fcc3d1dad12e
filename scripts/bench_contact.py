#!/usr/bin/env python3
"""coal.collide beside quadsect's exact ellipsoid contact, on the same ellipsoid pairs, in one run.

    python3 -m venv .venv-contact --system-site-packages && .venv-contact/bin/pip install coal numpy
    .venv-contact/bin/python scripts/bench_contact.py --quadsect ./target/release/quadsect
        [--seed 1] [--n 20000] [--near 3000] [--touching 300] [--tangent 200]
        [--pairs /tmp/contact_pairs.jsonl]
        [--out-json scripts/contact_results.json] [--out-md scripts/contact_results.md]

What it does
------------
1. Pair sets (numpy RandomState(seed); every number a double; rotations from random unit
   quaternions, computed in doubles, so only nearly orthogonal):
   - random:   centres uniform in [-2,2]^3, semi-axes uniform in [0.2,1.2];
   - near:     for k = 3..12, A random, p = c_A + R_A·diag(r_A)·u0 (u0 a random unit vector),
               B = the point reflection of A through p (centre 2p - c_A, matrix -R_A), moved by
               s·10^-k·(p - c_A), s = +1 (separates) / -1 (overlaps) alternating;
   - touching: exactly touching in doubles. quadsect's ellipsoid is
               { x : |diag(r)^-1 R^T (x - c)| <= 1 } with R exactly as given (for a rotation,
               c + R·diag(r)·ball), and no rotation rounded to doubles is exactly orthogonal;
               so R is the integer matrix of a quaternion q (R R^T = N^2 I, N = |q|^2: A is the
               rational rotation R/N applied to semi-axes r/N), r_0 = N^2·2^j, the point
               p = c + 2^j·R e1 of A's surface is exact, and B = A reflected through p =
               (2p - c, r, -R) touches A at p only (exactness checked with Fractions).
               coal gets the same ellipsoids as rotation R/N and semi-axes r/N (doubles).
2. Exact labels: `quadsect ellipsoids FILE` (the set is in the id, since quadsect rejects unknown
   fields).
3. Independent check: a subset is decided again by the tangent point method (`quadsect batch`,
   op "tangent", A's and B's polynomials as exact rational strings built with Fractions);
   intersecting -> overlapping, touching -> touching unless internal (side "-", or B's centre
   inside A), separated -> separated unless one lies inside the other (containment).
4. coal: coal.collide(Ellipsoid, Transform3s(R, c), ...) with a default CollisionRequest, each call
   timed alone with perf_counter_ns (Python call included, the shapes and transforms built
   beforehand), 3 repetitions over all pairs; wrong = (collision) != (exact label != separated).
5. quadsect: `quadsect bench contact --pairs FILE --json` on the same pairs (with "expect"), one
   row per set: per-pair time of the exact predicate and of a plain-f64 Wang-Wang-Kim test.
"""
import argparse, datetime, hashlib, json, os, platform, subprocess, sys, time
from fractions import Fraction as F
import numpy as np

def rotation(rs):
    w, x, y, z = (q := rs.normal(size=4)) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])

def ell(c, r, R):
    return {"center": [float(v) for v in c], "semi_axes": [float(v) for v in r],
            "rotation": [[float(v) for v in row] for row in R]}

def random_ell(rs):
    return rs.uniform(-2, 2, 3), rs.uniform(0.2, 1.2, 3), rotation(rs)

def make_pairs(rs, n, n_near, n_touch):
    pairs = [("random", f"random-{i:05d}", ell(*random_ell(rs)), ell(*random_ell(rs))) for i in range(n)]
    for k in range(3, 13):
        for i in range(n_near // 10):
            c, r, R = random_ell(rs)
            u0 = rs.normal(size=3); u0 /= np.linalg.norm(u0)
            p = c + R @ (r * u0)
            s = 1.0 if i % 2 == 0 else -1.0
            cb = 2 * p - c + s * 10.0 ** -k * (p - c)
            pairs.append(("near", f"near-k{k:02d}-{i:05d}", ell(c, r, R), ell(cb, r, -R)))
    i = 0
    while i < n_touch:
        q = rs.randint(-4, 5, size=4)
        N = int(q @ q)
        if N == 0:
            continue
        w, x, y, z = (int(v) for v in q)
        R = np.array([[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
                      [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
                      [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]], dtype=float)
        j = rs.choice([0.25, 0.5, 1.0])
        c = np.round(rs.uniform(-2, 2, 3) * 1024) / 1024
        r = np.array([N * N * j, N * rs.uniform(0.2, 1.2), N * rs.uniform(0.2, 1.2)])
        p = c + j * R[:, 0]
        cb = 2 * p - c
        if any(F(p[k]) != F(c[k]) + F(j) * F(R[k, 0]) or F(cb[k]) != 2 * F(p[k]) - F(c[k])
               for k in range(3)):
            continue  # not exact in doubles: draw again
        pairs.append(("touching", f"touching-{i:05d}", ell(c, r, R), ell(cb, r, -R)))
        i += 1
    return pairs

def sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:16]

def run(cmd, stdin=None):
    return subprocess.run(cmd, input=stdin, capture_output=True, text=True)

def jsonl(out):
    return [json.loads(l) for l in out.splitlines() if l.strip()]

# ---- exact polynomials for the tangent route ----
def quadric(e):
    """W and c with q(x) = (x-c)^T W (x-c) - 1, W = G^T G, G = diag(r)^-1 R^T, all exact."""
    c = [F(v) for v in e["center"]]
    G = [[F(e["rotation"][j][i]) / F(e["semi_axes"][i]) for j in range(3)] for i in range(3)]
    return [[sum(G[k][i] * G[k][j] for k in range(3)) for j in range(3)] for i in range(3)], c

def poly_string(e):
    W, c = quadric(e)
    v, terms = "xyz", []
    for i in range(3):
        terms.append(f"{W[i][i]}*{v[i]}^2")
        terms += [f"{2 * W[i][j]}*{v[i]}*{v[j]}" for j in range(i + 1, 3)]
    Wc = [sum(W[i][j] * c[j] for j in range(3)) for i in range(3)]
    terms += [f"{-2 * Wc[i]}*{v[i]}" for i in range(3)]
    terms.append(str(sum(c[i] * Wc[i] for i in range(3)) - 1))
    return " + ".join(terms)

def inside(e, pt):
    W, c = quadric(e)
    d = [F(pt[i]) - c[i] for i in range(3)]
    return sum(d[i] * W[i][j] * d[j] for i in range(3) for j in range(3)) < 1

def tangent_label(res, a, b):
    v = res["verdict"]
    if v == "intersecting":
        return "overlapping"
    if v == "touching":  # external iff S >= 0 on E and B's centre is outside A
        return "touching" if res["side"] == "+" and not inside(a, b["center"]) else "overlapping"
    if v == "separated":
        return "separated" if res["containment"] in (None, "apart") else "overlapping"
    return v

# ---- coal ----
def bench_coal(pairs, reps):
    import coal
    req = coal.CollisionRequest()
    def shape(e):
        # a rotation for coal: R scaled by its first column's norm (N for the touching set's
        # integer quaternion matrices, ~1 otherwise), the semi-axes likewise
        R = np.array(e["rotation"]); n = np.linalg.norm(R[:, 0])
        return coal.Ellipsoid(*(np.array(e["semi_axes"]) / n)), coal.Transform3s(R / n, np.array(e["center"]))
    objs = [shape(e) for _, _, a, b in pairs for e in (a, b)]
    times = np.zeros((reps, len(pairs)), dtype=np.int64)
    hits = np.zeros(len(pairs), dtype=bool)
    res, collide, clock = coal.CollisionResult(), coal.collide, time.perf_counter_ns
    for rep in range(reps):
        for i in range(len(pairs)):
            (s1, t1), (s2, t2) = objs[2 * i], objs[2 * i + 1]
            res.clear()
            t0 = clock(); n = collide(s1, t1, s2, t2, req, res); t = clock() - t0
            times[rep, i] = t
            hits[i] = n > 0
    settings = {k: str(getattr(req, k)) for k in ("security_margin", "break_distance", "gjk_tolerance",
                "gjk_max_iterations", "enable_contact", "num_max_contacts", "epa_tolerance")}
    return times, hits, settings

def _timed(f):
    t0 = time.perf_counter(); f(); return time.perf_counter() - t0

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quadsect", default="./target/release/quadsect")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--n", type=int, default=20000)
    ap.add_argument("--near", type=int, default=3000)
    ap.add_argument("--touching", type=int, default=300)
    ap.add_argument("--tangent", type=int, default=200, help="pairs checked by the tangent route")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--pairs", default="/tmp/contact_pairs.jsonl")
    ap.add_argument("--out-json", default="scripts/contact_results.json")
    ap.add_argument("--out-md", default="scripts/contact_results.md")
    args = ap.parse_args()
    Q = args.quadsect
    rs = np.random.RandomState(args.seed)
    binary_sha = sha(Q)
    pairs = make_pairs(rs, args.n, args.near, args.touching)
    sets = ["random", "near", "touching"]
    print(f"{len(pairs)} pairs", file=sys.stderr)

    # exact labels
    lab_in = "".join(json.dumps({"id": pid, "a": a, "b": b}) + "\n" for _, pid, a, b in pairs)
    t0 = time.perf_counter()
    p = run([Q, "ellipsoids", "--time-limit", "60", "-"], lab_in)
    ans = {d["id"]: d for d in jsonl(p.stdout)}
    label_wall = time.perf_counter() - t0
    expect = {}
    for _, pid, _, _ in pairs:
        d = ans.get(pid)
        expect[pid] = d["result"]["contact"] if d and d.get("ok") else None
        if expect[pid] is None:
            print(f"!!! no exact label for {pid}: {d}", file=sys.stderr)
    bad_touch = [pid for s, pid, _, _ in pairs if s == "touching" and expect[pid] != "touching"]
    if bad_touch:
        print(f"!!!!!!!! {len(bad_touch)} exact-touching pairs not labelled touching: {bad_touch[:5]}", file=sys.stderr)
    with open(args.pairs, "w") as f:
        for s, pid, a, b in pairs:
            f.write(json.dumps({"id": pid, "set": s, "expect": expect[pid], "a": a, "b": b}) + "\n")

    # tangent route on a subset (a quarter touching, a quarter near, the rest random)
    sub, nt = [], args.tangent
    for s, m in (("touching", nt // 4), ("near", nt // 4), ("random", nt - 2 * (nt // 4))):
        idx = [i for i, x in enumerate(pairs) if x[0] == s]
        sub += [pairs[i] for i in sorted(rs.choice(idx, min(m, len(idx)), replace=False))]
    tan_in = "".join(json.dumps({"id": pid, "op": "tangent", "ellipsoid": poly_string(a),
                                 "surface": poly_string(b), "values": False}) + "\n" for _, pid, a, b in sub)
    t0 = time.perf_counter()
    tans = {d["id"]: d for d in jsonl(run([Q, "batch", "--time-limit", "120", "-"], tan_in).stdout)}
    tangent = {"checked": len(sub), "agree": 0, "disagree": [], "undecided": [], "labels": {},
               "wall_s": round(time.perf_counter() - t0, 2)}
    for _, pid, a, b in sub:
        d = tans.get(pid)
        lab = tangent_label(d["result"], a, b) if d and d.get("ok") else None
        tangent["labels"][lab] = tangent["labels"].get(lab, 0) + 1
        if lab == expect[pid]:
            tangent["agree"] += 1
        elif lab in ("separated", "touching", "overlapping"):
            tangent["disagree"].append({"id": pid, "ellipsoids": expect[pid], "tangent": lab})
        else:
            tangent["undecided"].append({"id": pid, "answer": d})
    if tangent["disagree"]:
        print("!!!!!!!! TANGENT ROUTE DISAGREES WITH quadsect ellipsoids:", tangent["disagree"], file=sys.stderr)
    print(f"tangent route: {tangent['agree']}/{len(sub)} agree", file=sys.stderr)

    # coal
    times, hits, coal_settings = bench_coal(pairs, args.reps)
    import coal
    # quadsect's own bench
    qcmd = [Q, "bench", "contact", "--pairs", args.pairs, "--json"]
    p = run(qcmd)
    try:
        qrows = {r["id"]: r for r in json.loads(p.stdout) if r.get("suite") == "contact"}
        qerr = None
    except (ValueError, TypeError, AttributeError):
        qrows, qerr = {}, (p.stderr.strip() or p.stdout.strip())[:400]
        print(f"!!! `{' '.join(qcmd)}` is not available (exit {p.returncode}): {qerr}\n"
              "    quadsect columns are left empty.", file=sys.stderr)

    # the Python bulk call (quadsect installed in this interpreter): the random set tiled to
    # 10^6 pairs, one call with 1 and with 2 threads (best of 3), codes checked on the set
    pybulk = None
    try:
        import quadsect
        rnd = [x for x in pairs if x[0] == "random"]
        arr = lambda side, key: np.array([e[key] for _, _, *ab in rnd for e in [ab[side]]], dtype=np.float64)
        A = [arr(0, "center"), arr(0, "semi_axes"), arr(0, "rotation"), arr(1, "center"), arr(1, "semi_axes"), arr(1, "rotation")]
        codes = quadsect.ellipsoid_contact(*A)
        want = np.array([{"separated": 0, "touching": 1, "overlapping": 2}[expect[pid]] for _, pid, _, _ in rnd])
        reps_n = max(1, 10**6 // len(rnd))
        big = [np.ascontiguousarray(np.tile(x, (reps_n,) + (1,) * (x.ndim - 1))) for x in A]
        pybulk = {"pairs": int(big[0].shape[0]), "wrong_on_set": int((codes != want).sum()), "quadsect": quadsect.__version__}
        for th in (1, 2):
            best = min(_timed(lambda: quadsect.ellipsoid_contact(*big, threads=th)) for _ in range(3))
            pybulk[f"pairs_per_s_threads{th}"] = big[0].shape[0] / best
        print(f"python bulk: {pybulk}", file=sys.stderr)
    except ImportError as e:
        print(f"!!! quadsect not importable here ({e}): no Python bulk measurement", file=sys.stderr)

    if sha(Q) != binary_sha:
        print(f"!!! {Q} CHANGED DURING THE RUN: labels and bench rows may come from different builds", file=sys.stderr)
    results = {}
    for s in sets:
        idx = [i for i, x in enumerate(pairs) if x[0] == s]
        if not idx:
            continue
        t = times[:, idx].ravel() * 1e-9
        exact_hit = np.array([expect[pairs[i][1]] != "separated" for i in idx])
        wrong = hits[idx] != exact_hit
        labels = [expect[pairs[i][1]] for i in idx]
        q = qrows.get(s)
        if q and q.get("quadsect_wrong"):
            print(f"!!!!!!!! quadsect bench contact: {q['quadsect_wrong']} WRONG on {s}", file=sys.stderr)
        med = float(np.median(t))
        results[s] = {
            "pairs": len(idx), "labels": {l: labels.count(l) for l in ("separated", "touching", "overlapping")},
            "coal_median_s": med, "coal_mean_s": float(t.mean()), "coal_wrong": int(wrong.sum()),
            "coal_wrong_by_label": {l: int(sum(w for w, x in zip(wrong, labels) if x == l))
                                    for l in ("separated", "touching", "overlapping")},
            "coal_median_by_label_s": {l: float(np.median(times[:, [i for i, x in zip(idx, labels) if x == l]]))
                                       * 1e-9 for l in set(labels)},
            "quadsect": q,
            **({"coal_wrong_by_k": {k: int(sum(w for w, i in zip(wrong, idx) if pairs[i][1][5:8] == f"k{k:02d}"))
                                    for k in range(3, 13)}} if s == "near" else {}),
            "ratio_quadsect_coal": q["median_pair_s"] / med if q and q.get("median_pair_s") else None,
            "ratio_quadsect_wwk": q["median_s"] / q["wwk_s"] if q and q.get("wwk_s") else None}
    exe = os.path.relpath(sys.executable) if sys.executable.startswith(os.getcwd()) else "python3"
    out = {"command": " ".join([exe] + sys.argv),
           "quadsect_bench_command": " ".join(qcmd), "quadsect_bench_error": qerr,
           "seed": args.seed, "reps": args.reps,
           "machine": {"uname": " ".join(platform.uname()), "cpus": os.cpu_count(),
                       "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
                       "python": platform.python_version(), "coal": coal.__version__,
                       "quadsect": run([Q, "--version"]).stdout.strip()},
           "quadsect_sha256_16": [binary_sha, sha(Q)], "coal_request": coal_settings, "label_wall_s": round(label_wall, 2),
           "tangent_check": tangent, "sets": results, "python_bulk": pybulk}
    with open(args.out_json, "w") as f:
        json.dump(out, f, indent=1)
    with open(args.out_md, "w") as f:
        f.write(markdown(out))
    print(markdown(out))

def markdown(o):
    us = lambda x: "–" if x is None else f"{x * 1e6:.3f}"
    fx = lambda x: "–" if x is None else f"{x:.2f}"
    L = ["# Ellipsoid contact: coal.collide beside quadsect", "",
         "| set | pairs | sep/touch/overl | coal µs/pair | coal wrong | f64 WWK µs/pair | WWK wrong "
         "| quadsect µs/pair: median (bulk mean) | quadsect wrong | filter decided | quadsect/coal (medians) | quadsect/WWK (means) |",
         "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for s, r in o["sets"].items():
        q, lb = r["quadsect"] or {}, r["labels"]
        L.append(f"| {s} | {r['pairs']} | {lb['separated']}/{lb['touching']}/{lb['overlapping']} "
                 f"| {us(r['coal_median_s'])} (mean {us(r['coal_mean_s'])}) | {r['coal_wrong']} "
                 f"| {us(q.get('wwk_s'))} | {q.get('wwk_wrong', '–')} | {us(q.get('median_pair_s'))} ({us(q.get('median_s'))}) "
                 f"| {q.get('quadsect_wrong', '–')} | {q.get('filter_decided', '–')} "
                 f"| {fx(r['ratio_quadsect_coal'])} | {fx(r['ratio_quadsect_wwk'])} |")
    L += ["", "Seconds per million pairs (medians):", "",
          "| set | coal | f64 WWK | quadsect |", "|---|---:|---:|---:|"]
    sm = lambda x: "–" if x is None else f"{x * 1e6:.2f}"
    for s, r in o["sets"].items():
        q = r["quadsect"] or {}
        L.append(f"| {s} | {sm(r['coal_median_s'])} | {sm(q.get('wwk_s'))} | {sm(q.get('median_s'))} |")
    L.append("")
    for s, r in o["sets"].items():
        w = r["coal_wrong_by_label"]
        L.append(f"- coal wrong on {s}, by exact label: separated {w['separated']}, "
                 f"touching {w['touching']}, overlapping {w['overlapping']}; coal median by label: "
                 + ", ".join(f"{l} {us(v)} µs" for l, v in sorted(r["coal_median_by_label_s"].items()))
                 + (f"; near, by k (offset 10^-k): {r['coal_wrong_by_k']}" if "coal_wrong_by_k" in r else ""))
    pb = o.get("python_bulk")
    if pb:
        L += ["", f"Python bulk call `quadsect.ellipsoid_contact` on {pb['pairs']} pairs (the random set tiled; "
              f"{pb['wrong_on_set']} wrong on the set): {pb['pairs_per_s_threads1'] / 1e6:.2f}·10⁶ pairs/s on 1 thread, "
              f"**{pb['pairs_per_s_threads2'] / 1e6:.2f}·10⁶ pairs/s on 2 threads** (one call, best of 3, array conversion included)."]
    t = o["tangent_check"]
    L += ["", f"Tangent point route (independent, `quadsect batch` op `tangent`, exact rational polynomials): "
          f"**{t['agree']}/{t['checked']} agree** with `quadsect ellipsoids`, {len(t['disagree'])} disagree, "
          f"{len(t['undecided'])} undecided ({t['wall_s']} s); tangent-route labels {t['labels']}."]
    L += [f"- DISAGREEMENT: {d}" for d in t["disagree"]]
    if o["quadsect_bench_error"]:
        L += ["", f"`{o['quadsect_bench_command']}` was not available: {o['quadsect_bench_error']}"]
    m = o["machine"]
    L += ["", "Notes: coal times each `coal.collide` call alone (perf_counter_ns, Python call included; "
          f"median and mean over {o['reps']} repetitions of all pairs), default `CollisionRequest` "
          f"({', '.join(f'{k}={v}' for k, v in o['coal_request'].items())}); coal's answer is a boolean, "
          "touching counts as colliding. The rotation matrices are doubles from unit quaternions, "
          "not exactly orthogonal: quadsect decides the ellipsoid "
          "{ x : |diag(r)^-1 Rᵀ(x - c)| <= 1 } with R exactly as given; coal treats R as a rotation "
          "(RᵀR - I is ~1e-16 for the random and near sets); the touching set's R are integer "
          "quaternion matrices (R Rᵀ = N²I), given to coal as R/N with semi-axes r/N. "
          "B of the near and touching sets has matrix -R_A (det -1; the same point set as R_A).",
          "", f"Machine: {m['uname']}, {m['cpus']} CPUs, {m['date']}; Python {m['python']}, "
          f"coal {m['coal']}, {m['quadsect']} (binary sha256 {o['quadsect_sha256_16'][0]}"
          + (")." if len(set(o["quadsect_sha256_16"])) == 1 else f", CHANGED during the run to {o['quadsect_sha256_16'][1]})."),
          "", f"Command: `{o['command']}`", ""]
    return "\n".join(L)

if __name__ == "__main__":
    main()
