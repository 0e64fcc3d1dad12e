"""The independent checker `quadsect_check` on the answers of the CLI.

The corpus of scripts/check_corpus.py is answered once per session by
`quadsect batch --echo`; every answer must be verified or partial, and every
answer corrupted by one of the mutators below (a wrong class, count, conic,
line, point, branch, witness, interval, coefficient, contact or kind, a λ or
μ, an interior point, a and b exchanged, or the certificate of another
input) must be rejected.  Section 4: ellipsoid-contact on a larger random
sample of poses and on hand-made inputs."""

import copy
import json
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]

try:
    import quadsect_check
except ImportError:  # a local run without the package installed
    sys.path.insert(0, str(REPO / "python"))
    import quadsect_check

from quadsect_check import exact, natural, poly

# mutated answers per mutator at most (a deterministic, stratified sample)
SAMPLE = 25

CLASSES = ["same-surface", "curve", "conics", "conic-and-line", "lines", "points", "empty"]
GEOMETRY = {"natural": ("a", "b"), "tangent": ("ellipsoid", "surface"), "roots": ("poly",), "resultant": ("f", "g", "var"),
            "ellipsoid-contact": ("a", "b")}


def quadsect_binary():
    env = os.environ.get("QUADSECT_BIN")
    for p in ([Path(env)] if env else []) + [REPO / "target" / "release" / "quadsect"]:
        if p.is_file() and os.access(p, os.X_OK):
            return p
    return None


@pytest.fixture(scope="module")
def answers():
    """The corpus answered by the CLI: [(answer dict, request dict)]."""
    binary = quadsect_binary()
    if binary is None:
        pytest.skip("no quadsect CLI: set QUADSECT_BIN or run `cargo build --release` (target/release/quadsect)")
    corpus = subprocess.run([sys.executable, str(REPO / "scripts" / "check_corpus.py")], cwd=REPO,
                            capture_output=True, text=True, check=True, timeout=120).stdout
    out = subprocess.run([str(binary), "batch", "--echo", "--threads", "2", "-"], input=corpus,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode in (0, 1), out.stderr
    lines = [l for l in out.stdout.splitlines() if l.strip()]
    assert len(lines) == len([l for l in corpus.splitlines() if l.strip()])
    result = []
    for l in lines:
        a = json.loads(l)
        result.append((a, json.loads(a["request"])))
    return result


@pytest.fixture(scope="module")
def verdicts(answers):
    return {a["id"]: quadsect_check.check_answer(a) for a, _ in answers}


def check(answer):
    """The verdict on an answer re-serialized as an answer line."""
    return quadsect_check.check_line(json.dumps(answer))


# ---- 1. the corpus ------------------------------------------------------


def test_corpus_has_no_rejection(answers, verdicts):
    rejected = [(v["id"], v["reason"]) for v in verdicts.values() if v["status"] == "rejected"]
    assert not rejected, "rejected answers:\n" + "\n".join(f"  {i}: {r}" for i, r in rejected)
    by_op = {}
    for a, req in answers:
        if a.get("ok"):
            by_op.setdefault(req["op"], []).append((a, verdicts[a["id"]]))
    for op in ("natural", "tangent", "roots", "resultant", "ellipsoid-contact"):
        assert by_op.get(op), f"no {op} answer in the corpus"
    not_verified = [(a["id"], v["status"], v["trusted"]) for op in ("roots", "resultant", "ellipsoid-contact")
                    for a, v in by_op[op] if v["status"] != "verified"]
    assert not not_verified, f"roots/resultant/ellipsoid-contact answers not verified: {not_verified}"
    inter = [(a, v) for a, v in by_op["tangent"] if a["result"].get("verdict") == "intersecting"]
    assert inter
    bad = [a["id"] for a, v in inter if not any(c.startswith("intersecting:") for c in v["checked"])]
    assert not bad, f"intersecting answers without the two witnesses re-proved: {bad}"
    empty_trust = [v["id"] for v in verdicts.values() if v["status"] == "partial" and not v["trusted"]]
    assert not empty_trust, f"partial answers without a trusted list: {empty_trust}"


# ---- 2. mutations -------------------------------------------------------


def _is_zero(v):
    if isinstance(v, dict):
        return Fraction(v["a"]) == 0 and Fraction(v["b"]) == 0
    return Fraction(v) == 0


def _shift(v, delta):
    """v + delta (on the "a" part of {a, b, d})."""
    if isinstance(v, dict):
        w = dict(v)
        w["a"] = str(Fraction(v["a"]) + delta)
        w.pop("approx", None)
        return w
    return str(Fraction(v) + delta)


def _scale(v, k):
    if isinstance(v, dict):
        w = dict(v)
        w["a"], w["b"] = str(Fraction(v["a"]) * k), str(Fraction(v["b"]) * k)
        w.pop("approx", None)
        return w
    return str(Fraction(v) * k)


def _exact(x):
    """Whether a value tree holds only numbers this checker re-proves
    (no real algebraic number of higher degree)."""
    if isinstance(x, dict):
        return "poly" not in x and all(_exact(v) for k, v in x.items() if k != "f64")
    if isinstance(x, list):
        return all(_exact(v) for v in x)
    return True


def _op(answer):
    return json.loads(answer["request"]).get("op")


def _res(answer, op):
    """The result to mutate: an ok answer of ``op`` with a decided claim."""
    if not answer.get("ok") or _op(answer) != op:
        return None
    r = answer["result"]
    if r.get("class") == "undecided" or r.get("verdict") == "undecided":
        return None
    return r


def _components_listed(answer):
    r = _res(answer, "natural")
    return r if r is not None and isinstance(r.get("components"), list) else None


def _variants(answer, edit, keys):
    """One deep copy per key, changed by ``edit(result_copy, key)`` (which
    returns False when the key does not apply)."""
    out = []
    for k in keys:
        m = copy.deepcopy(answer)
        if edit(m["result"], k) is not False:
            out.append(m)
    return out


def _each_component(answer, ctype, pred=lambda c: True):
    r = _components_listed(answer)
    if r is None:
        return []
    return [j for j, c in enumerate(r["components"])
            if isinstance(c, dict) and c.get("type") == ctype and _exact(c) and pred(c)]


# natural


def mut_natural_class(answer):
    r = _res(answer, "natural")
    if r is None or (r.get("components") is None and r["class"] != "same-surface"):
        return []  # class and counts only: nothing to check them against
    return _variants(answer, lambda res, c: res.__setitem__("class", c), [c for c in CLASSES if c != r["class"]])


def mut_natural_count(answer):
    if _components_listed(answer) is None:
        return []
    return _variants(answer, lambda res, k: res.__setitem__(k, res[k] + 1), ["conics", "lines", "points"])


def mut_conic_offset(answer):
    def edit(res, j):
        pl = res["components"][j]["plane"]
        pl["offset"] = _shift(pl["offset"], 1)
    return _variants(answer, edit, _each_component(answer, "conic"))


def mut_conic_center(answer):
    def edit(res, jk):
        j, k = jk
        c = res["components"][j]
        key = "vertex" if c["conic"] == "parabola" else "center"
        c[key][k] = _shift(c[key][k], 1)
    return _variants(answer, edit, [(j, k) for j in _each_component(answer, "conic") for k in range(3)])


def mut_conic_semi_axis(answer):
    def edit(res, jk):
        j, k = jk
        s = res["components"][j]["semi_axes2"]
        s[k] = _scale(s[k], 2)
    keys = [(j, k) for j in _each_component(answer, "conic", lambda c: c["conic"] != "parabola") for k in range(2)]
    return _variants(answer, edit, keys)


def mut_parabola_focal(answer):
    def edit(res, j):
        c = res["components"][j]
        c["focal_length2"] = _scale(c["focal_length2"], 2)
    return _variants(answer, edit, _each_component(answer, "conic", lambda c: c["conic"] == "parabola"))


def mut_parabola_axis(answer):
    def edit(res, j):
        c = res["components"][j]
        c["axis_directions"][0] = [_scale(v, -1) for v in c["axis_directions"][0]]
    return _variants(answer, edit, _each_component(answer, "conic", lambda c: c["conic"] == "parabola"))


def _off_direction(d):
    """The coordinates k for which d + e_k is not parallel to d (d not a
    multiple of e_k): moving a point by e_k leaves the line."""
    return [k for k in range(3) if any(not _is_zero(d[i]) for i in range(3) if i != k)]


def mut_line_point(answer):
    def edit(res, jk):
        j, k = jk
        c = res["components"][j]
        c["point"][k] = _shift(c["point"][k], 1)
    comps = (_components_listed(answer) or {}).get("components", [])
    keys = [(j, k) for j in _each_component(answer, "line") for k in _off_direction(comps[j]["direction"])]
    return _variants(answer, edit, keys)


def mut_line_direction(answer):
    def edit(res, jk):
        j, k = jk
        c = res["components"][j]
        c["direction"][k] = _shift(c["direction"][k], 1)
    comps = (_components_listed(answer) or {}).get("components", [])
    keys = [(j, k) for j in _each_component(answer, "line") for k in _off_direction(comps[j]["direction"])]
    return _variants(answer, edit, keys)


def mut_point(answer):
    def edit(res, jk):
        j, k = jk
        c = res["components"][j]
        c["point"][k] = _shift(c["point"][k], 1)
    return _variants(answer, edit, [(j, k) for j in _each_component(answer, "point") for k in range(3)])


def mut_branch_c(answer):
    def edit(res, jk):
        j, k = jk
        al = res["components"][j]["branches"][k]["along_ruling"]
        al["c"] = _shift(al["c"], 1)
    comps = (_components_listed(answer) or {}).get("components", [])
    keys = [(j, k) for j in _each_component(answer, "curve") for k in range(len(comps[j].get("branches") or []))]
    return _variants(answer, edit, keys)


def mut_singular_point(answer):
    def edit(res, jkl):
        j, k, l = jkl
        p = res["components"][j]["singular_points"][k]["point"]
        p[l] = _shift(p[l], 1)
    comps = (_components_listed(answer) or {}).get("components", [])
    keys = [(j, k, l) for j in _each_component(answer, "curve")
            for k in range(len(comps[j].get("singular_points") or [])) for l in range(3)]
    return _variants(answer, edit, keys)


def _curves(answer):
    """The curve components whose topology the checker re-derives (a curve
    beside a line, the twisted cubic, is documented as beyond it)."""
    comps = (_components_listed(answer) or {}).get("components", [])
    return [(j, comps[j]) for j in _each_component(answer, "curve") if len(comps) == 1]


def mut_curve_bounded(answer):
    """A branch said bounded when it is not (or the reverse)."""
    def edit(res, jk):
        b = res["components"][jk[0]]["branches"][jk[1]]
        b["bounded"] = not b["bounded"]
    return _variants(answer, edit, [(j, k) for j, c in _curves(answer) for k in range(len(c.get("branches") or []))])


def mut_curve_extra_branch(answer):
    """One more real component claimed: a branch listed twice."""
    def edit(res, j):
        c = res["components"][j]
        c["branches"].append(copy.deepcopy(c["branches"][0]))
        c["real_components"] += 1
    return _variants(answer, edit, [j for j, c in _curves(answer) if c.get("branches")])


def mut_curve_singular_kind(answer):
    """A singular point's kind renamed, the isolated flag and the point count
    kept consistent with the new kind."""
    other = {"acnode": "crossing", "crossing": "cusp", "cusp": "crossing", "tacnode": "crossing"}

    def edit(res, jk):
        s = res["components"][jk[0]]["singular_points"][jk[1]]
        s["kind"] = other[s["kind"]]
        iso = s["kind"] == "acnode"
        res["points"] += iso - bool(s["isolated"])
        s["isolated"] = iso
    return _variants(answer, edit, [(j, k) for j, c in _curves(answer) for k in range(len(c.get("singular_points") or []))])


def mut_drop_component(answer):
    r = _components_listed(answer)
    if r is None:
        return []
    return _variants(answer, lambda res, j: res["components"].pop(j), range(len(r["components"])))


# tangent

_FLAGS = {"intersecting": (True, False), "touching": (True, True), "separated": (False, False)}


def _set_verdict(res, verdict):
    res["verdict"] = verdict
    res["intersect"], res["touching"] = _FLAGS[verdict]


def mut_tangent_verdict(answer):
    r = _res(answer, "tangent")
    if r is None or r.get("verdict") not in ("intersecting", "separated"):
        return []
    if r["verdict"] == "separated":
        def edit(res, _):
            _set_verdict(res, "intersecting")
            res["side"] = None
        return _variants(answer, edit, [None])

    def edit(res, side):
        _set_verdict(res, "separated")
        res["side"] = side
    return _variants(answer, edit, [None, "+", "-"])


def _witnesses(answer):
    r = _res(answer, "tangent")
    cert = (r or {}).get("certificate") or {}
    return [k for k in ("witness_negative", "witness_positive") if isinstance(cert.get(k), dict) and _exact(cert[k])]


def mut_witness_point(answer):
    def edit(res, wk):
        w, k = wk
        p = res["certificate"][w]["point"]
        p[k] = _shift(p[k], Fraction(1, 7))
    return _variants(answer, edit, [(w, k) for w in _witnesses(answer) for k in range(3)])


def mut_witness_sign(answer):
    def edit(res, w):
        res["certificate"][w]["sign"] = -res["certificate"][w]["sign"]
    return _variants(answer, edit, _witnesses(answer))


def mut_witness_drop(answer):
    r = _res(answer, "tangent")
    if r is None or r.get("verdict") != "intersecting":
        return []
    return _variants(answer, lambda res, w: res["certificate"].__setitem__(w, None), _witnesses(answer))


def mut_tangent_side(answer):
    r = _res(answer, "tangent")
    if r is None or r.get("verdict") != "separated":
        return []
    return _variants(answer, lambda res, _: res.__setitem__("side", "-" if res["side"] == "+" else "+"), [None])


def mut_s_lemma(answer):
    """τ moved far out of the interval where side·(S − τE) is definite (for
    large |τ| it has the signature of −τE: indefinite), or the side flipped
    under it."""
    r = _res(answer, "tangent")
    lemma = ((r or {}).get("certificate") or {}).get("s_lemma")
    if not lemma:
        return []
    tau = Fraction(lemma["tau"])

    def edit(res, k):
        if k == "side":
            res["side"] = "-" if res["side"] == "+" else "+"
        else:
            res["certificate"]["s_lemma"]["tau"] = str(tau + k)
    return _variants(answer, edit, [10**9, -(10**9), "side"])


def mut_tangent_extreme(answer):
    """A printed minimum or maximum replaced by another rational, where the
    checker re-proves that extreme (a witness at it, the S-lemma form
    semidefinite)."""
    r = _res(answer, "tangent")
    if r is None:
        return []
    proved = [k for k in ("min", "max") if any(c.startswith(f"{k}: S − ") for c in check(answer)["checked"])]

    def edit(res, k):
        res[k] = {"poly": "u - 12345", "interval": ["12345", "12345"], "approx": "12345"}
    return _variants(answer, edit, proved)


def mut_member_plane(answer):
    """A plane of the natural certificate's pencil member moved."""
    r = _res(answer, "natural")
    planes = (((r or {}).get("certificate") or {}).get("planes")) or []

    def edit(res, j):
        res["certificate"]["planes"][j]["offset"] = _shift(res["certificate"]["planes"][j]["offset"], 1)
    return _variants(answer, edit, range(len(planes)))


# ellipsoid-contact

CONTACTS = [("separated", "separated"), ("touching", "externally-touching")] + [
    ("overlapping", k) for k in ("surfaces-cross", "A-inside-B", "B-inside-A", "internally-touching", "identical")]


def _contact_cert(answer):
    r = answer["result"] if answer.get("ok") and _op(answer) == "ellipsoid-contact" else None
    return (r, r["certificate"]) if r is not None else (None, None)


def _contact_edits(answer, edits):
    """One deep copy per edit, changed by ``edit(certificate_copy)``."""
    out = []
    for edit in edits:
        m = copy.deepcopy(answer)
        edit(m["result"]["certificate"])
        out.append(m)
    return out


def mut_contact_flip(answer):
    """Every other (contact, kind) pair."""
    r, _ = _contact_cert(answer)
    if r is None:
        return []
    out = []
    for c, k in CONTACTS:
        if (c, k) != (r["contact"], r["kind"]):
            m = copy.deepcopy(answer)
            m["result"].update(contact=c, kind=k)
            out.append(m)
    return out


def mut_contact_lambda(answer):
    """λ ≤ 0; λ so small (large) that det(λA + B) has the sign of det B
    (of λ⁴·det A), negative for an ellipsoid; a touching λ doubled."""
    r, cert = _contact_cert(answer)
    if r is None or r["contact"] == "overlapping":
        return []
    ks = [-1, 0, Fraction(1, 10**30), 10**30] if r["contact"] == "separated" else [-1, 2]
    return _contact_edits(answer, [lambda c, k=k: c.__setitem__("lambda", _scale(c["lambda"], k)) for k in ks])


def mut_contact_point(answer):
    """The touching point moved off the surfaces, the common interior point
    far outside, the evidence's surface point moved, a_only and b_only
    exchanged."""
    r, cert = _contact_cert(answer)
    if r is None or r["contact"] == "separated":
        return []
    nudge = lambda pt: pt.__setitem__(0, _shift(pt[0], Fraction(1, 1000)))  # noqa: E731
    if r["contact"] == "touching":
        return _contact_edits(answer, [lambda c: nudge(c["point"])])
    edits = [lambda c: c.__setitem__("point", ["100", "100", "100"])]
    ke = cert.get("kind_evidence") or {}
    if ke.get("type") == "semidefinite" and ke.get("point"):
        edits.append(lambda c: nudge(c["kind_evidence"]["point"]))
    if ke.get("type") == "cross" and ke.get("a_only") and ke.get("b_only"):
        edits.append(lambda c: c["kind_evidence"].update(a_only=ke["b_only"], b_only=ke["a_only"]))
    return _contact_edits(answer, edits)


def mut_contact_evidence(answer):
    """μ negated; the semidefinite sign flipped; B = 2μA claimed."""
    r, cert = _contact_cert(answer)
    ke = (cert or {}).get("kind_evidence") or {}
    if ke.get("type") not in ("definite", "semidefinite", "identical"):
        return []
    edits = [lambda c: c["kind_evidence"].__setitem__("mu", _scale(ke["mu"], -1))]
    if ke["type"] == "semidefinite":
        edits.append(lambda c: c["kind_evidence"].__setitem__("sign", {"negative": "positive"}.get(ke["sign"], "negative")))
    if ke["type"] == "identical":
        edits.append(lambda c: c["kind_evidence"].__setitem__("mu", _scale(ke["mu"], 2)))
    return _contact_edits(answer, edits)


def _is_one(v):
    return Fraction(v["a"]) == 1 and Fraction(v["b"]) == 0 if isinstance(v, dict) else Fraction(v) == 1


def contact_symmetric(answer):
    """Whether the certificate proves the claim for (b, a) as well: a
    separating λ may; a touching λ = 1, B = 1·A, a cross without both
    points do.  Every other claim is not symmetric: A-inside-B becomes
    B-inside-A; λ∇q_A + ∇q_B = 0 and λ∇q_B + ∇q_A = 0 need λ² = 1;
    B − μA ≤ 0 and A − μB ≤ 0 give (μ² − 1)B ≥ 0, so μ = 1 and A = B."""
    r, cert = _contact_cert(answer)
    ke = cert.get("kind_evidence") or {}
    return (r["contact"] == "separated" or (r["contact"] == "touching" and _is_one(cert["lambda"]))
            or (ke.get("type") == "identical" and _is_one(ke["mu"]))
            or (ke.get("type") == "cross" and not (ke.get("a_only") and ke.get("b_only"))))


def swap_ab(answer):
    m = copy.deepcopy(answer)
    req = json.loads(m["request"])
    req["a"], req["b"] = req["b"], req["a"]
    m["request"] = json.dumps(req)
    return m


def mut_contact_swap_ab(answer):
    """a and b exchanged in the request (where the claim is not symmetric)."""
    r, _ = _contact_cert(answer)
    return [] if r is None or contact_symmetric(answer) else [swap_ab(answer)]


# roots


def _intervals(answer):
    r = _res(answer, "roots")
    return (r or {}).get("intervals") or []


def mut_roots_shift(answer):
    ivs = _intervals(answer)
    if not ivs:
        return []

    def edit(res, _):
        hi = Fraction(res["intervals"][-1][1])
        res["intervals"][-1] = [str(hi + 1), str(hi + 2)]
    return _variants(answer, edit, [None])


def mut_roots_count(answer):
    if _res(answer, "roots") is None:
        return []
    keys = ["distinct_real", "positive", "negative", "zero_multiplicity", "real_with_multiplicity"]
    return _variants(answer, lambda res, k: res.__setitem__(k, res[k] + 1), keys)


def mut_roots_multiplicity(answer):
    def edit(res, j):
        res["multiplicities"][j] += 1
    return _variants(answer, edit, range(len(_intervals(answer))))


def mut_roots_descartes(answer):
    if _res(answer, "roots") is None:
        return []
    keys = ["descartes_positive_bound", "descartes_negative_bound"]
    return _variants(answer, lambda res, k: res.__setitem__(k, res[k] + 1), keys)


def mut_roots_drop(answer):
    def edit(res, j):
        res["intervals"].pop(j)
        res["multiplicities"].pop(j)
    return _variants(answer, edit, range(len(_intervals(answer))))


# resultant


def mut_resultant_value(answer):
    if _res(answer, "resultant") is None:
        return []
    return _variants(answer, lambda res, _: res.__setitem__("resultant", res["resultant"] + " + 1"), [None])


def mut_resultant_degree(answer):
    if _res(answer, "resultant") is None:
        return []
    return _variants(answer, lambda res, _: res.__setitem__("degree", res["degree"] + 1), [None])


# any op: the certificate of another input


def _normalized(p):
    """A polynomial up to a non-zero constant factor (as a frozenset)."""
    if not p:
        return frozenset()
    c = p[min(p)]
    return frozenset((e, v / c) for e, v in p.items())


def _input_key(req):
    """What an answer is about: the surfaces' equations (up to a constant,
    unordered for natural) or the polynomials, plus the other options."""
    op, fm = req["op"], req.get("float", False) is True
    try:
        if op == "natural":
            geo = frozenset(_normalized(natural.quadric(req[k], fm)[0]) for k in ("a", "b"))
        elif op == "tangent":
            geo = tuple(_normalized(poly.parse(req[k], fm)) for k in ("ellipsoid", "surface"))
        elif op == "roots":
            geo = _normalized(poly.parse(req["poly"]))
        else:
            geo = (frozenset(poly.parse(req["f"]).items()), frozenset(poly.parse(req["g"]).items()), req["var"])
    except Exception:
        geo = tuple(req.get(k) for k in GEOMETRY[op])
    return geo


def _has_claims(answer):
    r = answer["result"]
    op = _op(answer)
    if op == "natural":  # a component the checker can refute (exact data)
        return any(isinstance(c, dict) and _exact(c) for c in r.get("components") or [])
    if op == "tangent":
        cert = r.get("certificate") or {}
        return cert.get("witness_negative") is not None or cert.get("witness_positive") is not None
    if op == "roots":
        return bool(r.get("intervals"))
    if op == "ellipsoid-contact":  # a separating λ may separate another pair too
        return r.get("contact") != "separated"
    return True


def make_swap(corpus):
    """The mutator "request of another answer": the next answer of the same
    op (corpus order, cyclic) with the same options, another input and
    another result; its request with this answer's id."""
    ok = [a for a in corpus if a.get("ok")]
    reqs = {id(a): json.loads(a["request"]) for a in ok}
    keys = {id(a): _input_key(reqs[id(a)]) for a in ok}

    def options(req):
        return {k: v for k, v in req.items() if k != "id" and k not in GEOMETRY.get(req.get("op"), ())}

    def mut_swap_request(answer):
        if not answer.get("ok") or id(answer) not in reqs or not _has_claims(answer):
            return []
        if _res(answer, _op(answer)) is None:
            return []
        req = reqs[id(answer)]
        i = next(n for n, a in enumerate(ok) if a is answer)
        for donor in ok[i + 1:] + ok[:i]:
            dreq = reqs[id(donor)]
            if dreq.get("op") != req["op"] or options(dreq) != options(req):
                continue
            if keys[id(donor)] == keys[id(answer)] or donor["result"] == answer["result"]:
                continue
            m = copy.deepcopy(answer)
            m["request"] = json.dumps({**dreq, "id": answer["id"]}, separators=(",", ":"))
            return [m]
        return []

    return mut_swap_request


MUTATORS = [
    mut_natural_class, mut_natural_count, mut_conic_offset, mut_conic_center, mut_conic_semi_axis,
    mut_parabola_focal, mut_parabola_axis, mut_line_point, mut_line_direction, mut_point, mut_branch_c,
    mut_singular_point, mut_drop_component, mut_curve_bounded, mut_curve_extra_branch, mut_curve_singular_kind,
    mut_tangent_verdict, mut_witness_point, mut_witness_sign, mut_witness_drop, mut_tangent_side,
    mut_s_lemma, mut_member_plane, mut_tangent_extreme,
    mut_roots_shift, mut_roots_count, mut_roots_multiplicity, mut_roots_descartes, mut_roots_drop,
    mut_resultant_value, mut_resultant_degree,
    mut_contact_flip, mut_contact_lambda, mut_contact_point, mut_contact_evidence, mut_contact_swap_ab,
]


def _stratum(answer):
    """Answers of a kind (op, class or verdict, component types): the sample
    takes them in turn so that every kind is mutated."""
    r = answer.get("result") or {}
    comps = r.get("components") or []
    kinds = tuple(sorted({(c.get("type"), c.get("conic")) for c in comps if isinstance(c, dict)}, key=str))
    return (_op(answer), r.get("class") or r.get("verdict") or r.get("kind"), kinds)


def _sample(pairs, n):
    """At most n of the (answer, mutants) pairs, round-robin over strata
    (corpus order within each): deterministic."""
    strata = {}
    for p in pairs:
        strata.setdefault(_stratum(p[0]), []).append(p)
    queues = list(strata.values())
    out = []
    while len(out) < n and any(queues):
        for q in queues:
            if q and len(out) < n:
                out.append(q.pop(0))
    return out


def test_mutations_are_rejected(answers, verdicts):
    corpus = [a for a, _ in answers if verdicts[a["id"]]["status"] != "rejected"]
    mutators = MUTATORS + [make_swap(corpus)]
    applied, survivors = {}, []
    for mut in mutators:
        kind = mut.__name__
        pairs = [(a, ms) for a in corpus for ms in [mut(a)] if ms]
        applied[kind] = 0
        for a, ms in _sample(pairs, SAMPLE):
            for m in ms:
                assert m != a
                applied[kind] += 1
                v = check(m)
                if v["status"] != "rejected":
                    survivors.append((kind, a["id"], v["status"], v["trusted"] or v["reason"]))
    print("mutated answers checked:", applied)
    never = [k for k, n in applied.items() if n == 0]
    assert not never, f"mutators never applied: {never}"
    assert not survivors, f"{len(survivors)} mutated answers not rejected:\n" + "\n".join(
        f"  {k} on {i}: {s}, {t}" for k, i, s, t in survivors)


# ---- 3. the checker's pieces --------------------------------------------


def test_parse_rational():
    assert exact.parse_rational("0x1.8p3") == 12
    assert exact.parse_rational("-2.5e-3") == Fraction(-1, 400)
    assert exact.parse_rational("1/3") == Fraction(1, 3)
    # float mode: each literal rounded on its own, then divided exactly
    assert exact.parse_rational("1/3", float_mode=True) == Fraction(1, 3)
    assert exact.parse_rational("1.77777777777") == Fraction(177777777777, 10**11)
    assert exact.parse_rational("1.77777777777", float_mode=True) == Fraction(1.77777777777)
    assert exact.parse_rational("1.77777777777", float_mode=True) != Fraction(177777777777, 10**11)
    for bad in ("1/0", "0x", "1e", "x", "1/", "--1"):
        with pytest.raises(exact.CheckError):
            exact.parse_rational(bad)


def test_poly_parse():
    X = lambda ex, ey, ez: (ex, ey, ez, 0)  # noqa: E731
    want = {X(2, 0, 0): Fraction(2), X(1, 1, 0): Fraction(-3), X(1, 0, 0): Fraction(-2), X(0, 1, 0): Fraction(3),
            X(0, 0, 0): Fraction(3), X(1, 1, 1): Fraction(1, 2)}
    assert poly.parse("2x^2 - 3(x-1)(y+1) + x y z/2 - -x") == want
    assert poly.parse("x - x") == {}
    for bad in ("x^", "x/y", "(x", "x +"):
        with pytest.raises(exact.CheckError):
            poly.parse(bad)


def test_qs_sign():
    assert exact.QS(1, -1, 2).sign() == -1
    assert exact.QS(3, -2, 2).sign() == 1
    assert exact.QS(-3, 2, 2).sign() == -1
    assert exact.QS(0, -1, 2).sign() == -1
    assert exact.QS(2, -1, 4).sign() == 0


def test_sturm_counts():
    p = [Fraction(1, 3), Fraction(-2), Fraction(0), Fraction(1)]  # x^3 - 2x + 1/3
    seq = poly.sturm_sequence(p)
    assert poly.sturm_count(seq, "-inf", "+inf") == 3
    assert [poly.sturm_count(seq, Fraction(a), Fraction(b)) for a, b in ((-2, -1), (0, 1), (1, 2))] == [1, 1, 1]
    assert poly.sturm_count(seq, Fraction(2), "+inf") == 0


def _cli(text):
    pkg_root = str(Path(quadsect_check.__file__).resolve().parents[1])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([pkg_root] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    return subprocess.run([sys.executable, "-m", "quadsect_check", "-"], input=text, capture_output=True,
                          text=True, env=env, timeout=120)


def test_cli(answers, verdicts):
    good = next(a for a, req in answers if req["op"] == "roots" and verdicts[a["id"]]["status"] == "verified"
                and a["result"]["intervals"])
    out = _cli(json.dumps(good) + "\n")
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[-1] == "1 verified, 0 partial, 0 rejected"
    assert json.loads(lines[0])["status"] == "verified"
    bad = copy.deepcopy(good)
    bad["result"]["distinct_real"] += 1
    out = _cli(json.dumps(good) + "\n\n" + json.dumps(bad) + "\n")
    assert out.returncode == 1, out.stderr
    lines = out.stdout.splitlines()
    assert lines[-1] == "1 verified, 0 partial, 1 rejected"
    assert [json.loads(l)["status"] for l in lines[:-1]] == ["verified", "rejected"]


def _sweep(a, b):
    from quadsect_check import sweep

    (qa, da), (qb, db) = natural.quadric(a), natural.quadric(b)
    ruled, other = (da, qb) if da and (da[0] == "cylinder" or not db or db[0] != "cylinder") else (db, qa)
    return sweep.rank_two_free(poly.form_matrix(qa), poly.form_matrix(qb)), sweep.curve_topology(*ruled, other)[:3]


def test_sweep_topologies_worked_by_hand():
    # a thin cylinder through a thick one: it enters and leaves — two closed loops
    assert _sweep("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=0,0,0 axis=1,0,0 radius2=1/4") == (
        True, (2, [True, True], []))
    # the same offset so that it only grazes a side: one loop (y + 1/2 over a radius 1/2 … 3/2 band)
    assert _sweep("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=0,1,0 axis=1,0,0 radius2=1/4")[1][:2] == (1, [True])
    # Viviani's curve: one component, crossing itself at (2, 0, 0)
    assert _sweep("cylinder point=1,0,0 axis=0,0,1 radius2=1", "sphere center=0,0,0 radius2=4") == (
        True, (1, [True], [("crossing", False)]))
    # z² = x² + y² against y² + z² = 1: x² = 1 − 2y², z = ±√(1 − y²) ≠ 0 — two loops, one per nappe
    assert _sweep("cone vertex=0,0,0 axis=0,0,1 tan2=1", "cylinder point=0,0,0 axis=1,0,0 radius2=1") == (
        True, (2, [True, True], []))
    # a sphere inside a cylinder: no real point on any ruling
    assert _sweep("cylinder point=0,0,0 axis=0,0,1 radius2=1", "sphere center=0,0,0 radius2=1/4")[1] == (0, [], [])
    # equal perpendicular cylinders meet in two ellipses: a member of rank 2
    assert _sweep("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=0,0,0 axis=1,0,0 radius2=1")[0] is False


def test_extremes_by_multiplier():
    from quadsect_check import tangent

    e = poly.parse("x^2+y^2+z^2-1")
    # z − 1 ≤ 0 on the sphere, 0 at (0, 0, 1): λ = 1/2 is the second rational root of
    # det(S − λE) = −λ²(λ − 1/2)² (the root 0 sits at the end of its isolating interval)
    assert tangent.extreme_by_multiplier(e, poly.parse("z-1"), {"poly": "u", "interval": ["0", "0"]}, "max")
    assert not tangent.extreme_by_multiplier(e, poly.parse("z-1"), {"poly": "u", "interval": ["0", "0"]}, "min")
    # x + y on the sphere: max √2, λ = √2/2 from the certificate's multipliers (Q(√2))
    mult = [{"lambda": {"poly": "2*l^2 - 1", "interval": ["7/10", "71/100"]},
             "value": {"poly": "u^2 - 2", "interval": ["141/100", "142/100"]}}]
    assert tangent.extreme_by_multiplier(e, poly.parse("x+y"), mult[0]["value"], "max", mult)
    assert not tangent.extreme_by_multiplier(e, poly.parse("x+y"), {"poly": "u^2 - 3", "interval": ["17/10", "18/10"]}, "max", mult)
    # … and without the certificate: for a plane λ = nᵀM⁻¹n / 2(v − s₀ + nᵀM⁻¹b), in Q(√2)
    assert tangent.extreme_by_multiplier(e, poly.parse("x+y"), mult[0]["value"], "max")
    assert tangent.extreme_by_multiplier(e, poly.parse("x+y"), {"poly": "u^2 - 2", "interval": ["-142/100", "-141/100"]}, "min")
    # x y on the sphere: min −1/2 on the kernel line x + y = 0, z = 0 (irrational points)
    assert tangent.extreme_by_multiplier(e, poly.parse("x y"), {"poly": "2*u + 1", "interval": ["-1/2", "-1/2"]}, "min")


def test_counts_without_components():
    def counts(a, b, cls, c, l, p):
        (qa, da), (qb, db) = natural.quadric(a), natural.quadric(b)
        return natural._counts_only(qa, qb, (da, db), {"class": cls, "conics": c, "lines": l, "points": p})

    # equal perpendicular cylinders: the member x² − z² = (x − z)(x + z), two ellipses
    assert "rank-2" in counts("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=0,0,0 axis=1,0,0 radius2=1", "conics", 2, 0, 0)
    with pytest.raises(exact.CheckError):
        counts("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=0,0,0 axis=1,0,0 radius2=1", "conics", 1, 0, 0)
    # a sphere in a cylinder of its radius: the double plane z² = 0, one circle
    assert counts("sphere center=0,0,0 radius2=1", "cylinder point=0,0,0 axis=0,0,1 radius2=1", "conics", 1, 0, 0)
    # two spheres touching: A − B is a plane (the other factor at infinity), one point
    assert counts("sphere center=0,0,0 radius2=1", "sphere center=2,0,0 radius2=1", "points", 0, 0, 1)
    with pytest.raises(exact.CheckError):
        counts("sphere center=0,0,0 radius2=1", "sphere center=2,0,0 radius2=1", "empty", 0, 0, 0)
    # parallel cylinders (a singular pencil): A − B = 2x − 1, the lines x = 1/2, y = ±√3/2
    assert counts("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=1,0,0 axis=0,0,1 radius2=1", "lines", 0, 2, 0)
    # cones z² = x² + y² and x² = y² + z² with a common vertex: y = 0, z = ±x — two lines
    assert counts("cone vertex=0,0,0 axis=0,0,1 tan2=1", "cone vertex=0,0,0 axis=1,0,0 tan2=1", "lines", 0, 2, 0)
    with pytest.raises(exact.CheckError):
        counts("cone vertex=0,0,0 axis=0,0,1 tan2=1", "cone vertex=0,0,0 axis=1,0,0 tan2=1", "lines", 0, 4, 0)
    # Viviani's curve: no conic, no isolated point
    assert counts("cylinder point=1,0,0 axis=0,0,1 radius2=1", "sphere center=0,0,0 radius2=4", "curve", 0, 0, 0)


def test_extremes_by_the_discriminant():
    """A sphere's distance² to an ellipsoid: min and max are roots of a sextic;
    only the true extremes are re-proved — another root of the same sextic,
    a root of a polynomial not vanishing there, or the max as min, is not."""
    from quadsect_check import extreme

    e = poly.parse("(x-(1))^2/5 + (y-(2))^2/9 + (z-(3))^2/1 - 4")
    s = poly.parse("(x-(2))^2 + (y-(-3))^2 + (z-(-2))^2 - 1")
    sextic = "256*u^6 - 69120*u^5 + 6193168*u^4 - 273061440*u^3 + 6525006731*u^2 - 81528052740*u + 402598940220"
    lo = {"poly": sextic, "interval": ["30548609957894610947018693/2417851639229258349412352",
                                       "30548609957894610947018695/2417851639229258349412352"]}
    hi = {"poly": sextic, "interval": ["22370909677618451069537897/151115727451828646838272",
                                       "22370909677618451069537899/151115727451828646838272"]}
    assert extreme.minimum(e, s, lo, [], 1)
    assert extreme.minimum(e, s, hi, [], -1)
    assert not extreme.minimum(e, s, hi, [], 1)  # the max is not the min
    assert not extreme.minimum(e, s, lo, [], -1)
    # the sextic's other real roots, if any, are not extremes either
    from quadsect_check.pencil import real_roots

    for a, b in real_roots(poly.univariate(poly.parse(sextic)))[2]:
        other = {"poly": sextic, "interval": [str(a), str(b)]}
        if not (a <= Fraction(126346, 10000) <= b or a <= Fraction(1480382, 10000) <= b):
            assert not extreme.minimum(e, s, other, [], 1) and not extreme.minimum(e, s, other, [], -1)
    # a sphere centred inside an ellipsoid: Δ(v) has saddle values among its
    # real roots; exactly one root is re-proved the min and one the max, and
    # they bracket a float sample of S on E
    from quadsect_check.pencil import _interpolate, det_poly

    e2, s2 = poly.parse("x^2/9 + y^2/4 + z^2 - 1"), poly.parse("(x - 1/2)^2 + (y - 1/3)^2 + z^2")
    me, ms = poly.form_matrix(e2), poly.form_matrix(s2)
    vals = []
    for v in range(7):
        m = [row[:] for row in ms]
        m[3][3] -= v
        vals.append(extreme._disc(poly.u_trim(det_poly(m, me))))
    delta = _interpolate(vals)
    text = " + ".join(f"({c})*u^{i}" for i, c in enumerate(delta))
    ivs = real_roots(delta)[2]
    assert len(ivs) >= 3
    mins = [iv for iv in ivs if extreme.minimum(e2, s2, {"poly": text, "interval": [str(iv[0]), str(iv[1])]}, [], 1)]
    maxs = [iv for iv in ivs if extreme.minimum(e2, s2, {"poly": text, "interval": [str(iv[0]), str(iv[1])]}, [], -1)]
    assert len(mins) == 1 and len(maxs) == 1
    import math
    sample = [float(poly.evaluate(s2, [exact.QS(Fraction(3 * math.cos(a) * math.cos(b))), exact.QS(Fraction(2 * math.sin(a) * math.cos(b))),
                                         exact.QS(Fraction(math.sin(b)))]).a) for a in [k / 7 for k in range(44)] for b in [k / 7 - 1.5 for k in range(22)]]
    assert float(mins[0][0]) - 1e-9 <= min(sample) and max(sample) <= float(maxs[0][1]) + 1e-9
    # S = E − 3 on the unit sphere: Δ ≡ 0, S ≡ −3 on E is both extremes; −2 is neither
    e3, s3 = poly.parse("x^2+y^2+z^2-1"), poly.parse("x^2+y^2+z^2-4")
    for sign in (1, -1):
        assert extreme.minimum(e3, s3, {"poly": "u + 3", "interval": ["-3", "-3"]}, [], sign)
        assert not extreme.minimum(e3, s3, {"poly": "u + 2", "interval": ["-2", "-2"]}, [], sign)
    # a value near the min that is not a root of Δ
    assert not extreme.minimum(e, s, {"poly": "u^2 - 160", "interval": ["12", "13"]}, [], 1)


# ---- 4. ellipsoid-contact ------------------------------------------------

CONTACT_MUTATORS = [mut_contact_flip, mut_contact_lambda, mut_contact_point, mut_contact_evidence, mut_contact_swap_ab]

CONTACT_EXAMPLES = [
    {"a": {"center": [0, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
     "b": {"center": [2, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}},
    {"a": {"center": [0, 0, 0], "semi_axes": [1, 2, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
     "b": {"center": [2.5, 0.3, 0], "semi_axes": [1, 1, 1], "rotation": [[0.36, 0.48, -0.8], [-0.8, 0.6, 0], [0.48, 0.64, 0.6]]}},
    {"a": "x^2+y^2+z^2-1", "b": {"center": ["1/3", 0, 0], "semi_axes": ["1/2", 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}},
    {"a": "x^2+y^2+z^2-1", "b": "(x-1)^2+y^2+z^2-4"},
    # exactly touching at (1.1, 0, 0) with exact decimals; as JSON numbers (doubles) the
    # centres are 2 + 8.3e-17 apart: separated, the touching certificate rejected (below)
    {"a": {"center": ["0.1", 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
     "b": {"center": ["2.1", 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}},
    {"a": {"center": [0.1, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
     "b": {"center": [2.1, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}},
    # a non-orthogonal matrix, exact decimal strings and an exponent
    {"a": {"center": ["1e-3", "-0.25", 0], "semi_axes": ["0.5", 1, "3/4"], "rotation": [[2, 1, 0], [0, 1, 0], [0, "1/3", 1]]},
     "b": "x^2 + 2y^2 + 3z^2 - 1"},
]


def _corpus_script():
    import importlib.util

    spec = importlib.util.spec_from_file_location("check_corpus", REPO / "scripts" / "check_corpus.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def contact_answers():
    """The contacts by hand of scripts/check_corpus.py, 100 random pairs of
    poses of doubles (another seed than the corpus's) and the examples
    above, answered by the CLI: [(answer, verdict)]."""
    import random

    binary = quadsect_binary()
    if binary is None:
        pytest.skip("no quadsect CLI: set QUADSECT_BIN or run `cargo build --release` (target/release/quadsect)")
    lines = list(_corpus_script().contact_lines(random.Random(7), 100))
    lines += [json.dumps({"id": f"contact-example:{i}", "op": "ellipsoid-contact", **ex}) for i, ex in enumerate(CONTACT_EXAMPLES)]
    out = subprocess.run([str(binary), "batch", "--echo", "-"], input="\n".join(lines) + "\n",
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    answers = [json.loads(l) for l in out.stdout.splitlines() if l.strip()]
    assert len(answers) == len(lines) and all(a.get("ok") for a in answers), [a for a in answers if not a.get("ok")][:3]
    return [(a, quadsect_check.check_answer(a)) for a in answers]


def test_contact_answers_verified(contact_answers):
    rejected = [(a["id"], v["reason"]) for a, v in contact_answers if v["status"] == "rejected"]
    assert not rejected, f"engine answers rejected: {rejected}"
    # partial only for a kind whose evidence lacks a point (named)
    partial = [(a["id"], v["trusted"]) for a, v in contact_answers if v["status"] == "partial"]
    assert all(t and all(x.startswith(("surfaces-cross: ", "internally-touching: ")) for x in t) for _, t in partial), partial
    assert len(partial) <= len(contact_answers) // 20, partial
    kinds = {a["result"]["kind"] for a, _ in contact_answers}
    assert kinds == {k for _, k in CONTACTS}, kinds
    assert {a["result"]["route"] for a, _ in contact_answers} == {"filter", "exact"}
    # touching from inside without a point in the evidence (the osculating sphere of a tip,
    # two points, a circle): the checker finds one in the kernel of B − μA
    found = [a["id"] for a, v in contact_answers if any("found in the kernel" in c for c in v["checked"])]
    assert {"contact:7", "contact:8", "contact:9"} <= set(found), found
    by_id = {a["id"]: a["result"] for a, _ in contact_answers}
    assert by_id["contact-example:0"]["contact"] == "touching"
    assert by_id["contact-example:1"]["contact"] == "separated"
    assert by_id["contact-example:3"]["kind"] == "internally-touching"
    assert by_id["contact-example:4"]["contact"] == "touching" and by_id["contact-example:5"]["contact"] == "separated"


def test_contact_mutations_rejected(contact_answers):
    applied, survivors = {}, []
    for mut in CONTACT_MUTATORS:
        applied[mut.__name__] = 0
        for a, v in contact_answers:
            if v["status"] == "rejected":
                continue
            for m in mut(a):
                applied[mut.__name__] += 1
                w = check(m)
                if w["status"] != "rejected":
                    survivors.append((mut.__name__, a["id"], w["status"], w["trusted"]))
    print("mutated contact answers checked:", applied)
    assert all(n >= 5 for n in applied.values()), applied
    assert not survivors, survivors
    # a symmetric certificate stays valid for (b, a): touching spheres (λ = 1), B = 1·A
    sym = [a for a, v in contact_answers if v["status"] == "verified" and a["result"]["contact"] != "separated" and contact_symmetric(a)]
    assert len(sym) >= 3 and all(check(swap_ab(a))["status"] == "verified" for a in sym)
    # a strict containment passed off as touching from inside: B − μA is
    # semidefinite, but no common surface point exists (partial without
    # one, rejected with one)
    inside = [a for a, v in contact_answers if v["status"] == "verified" and a["result"]["kind"] in ("A-inside-B", "B-inside-A")]
    assert inside
    for a in inside:
        m = copy.deepcopy(a)
        ke = m["result"]["certificate"]["kind_evidence"]
        sign = "negative" if a["result"]["kind"] == "A-inside-B" else "positive"
        m["result"]["kind"] = "internally-touching"
        m["result"]["certificate"]["kind_evidence"] = {"type": "semidefinite", "mu": ke["mu"], "sign": sign, "point": None}
        v = check(m)
        assert v["status"] == "partial" and v["trusted"] == ["internally-touching: the surfaces meet (no common point given)"], v
        m["result"]["certificate"]["kind_evidence"]["point"] = m["result"]["certificate"]["point"]
        assert check(m)["status"] == "rejected"
    # the exact-decimal touching certificate is not one for the doubles 0.1, 2.1
    by_id = {a["id"]: a for a, _ in contact_answers}
    m = copy.deepcopy(by_id["contact-example:4"])
    m["request"] = json.dumps({**json.loads(by_id["contact-example:5"]["request"]), "id": m["id"]})
    assert check(m)["status"] == "rejected"


def test_contact_canonical_forms():
    from quadsect_check import contact

    form = lambda e: contact.ellipsoid_form(e, "a")  # noqa: E731
    P = poly.parse
    # R's columns are the axes: the long semi-axis 2 along R·e₁ = (0, −1, 0)
    assert form({"center": [1, 2, 3], "semi_axes": [2, 1, 1], "rotation": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]}) == P(
        "(x-1)^2 + (y-2)^2/4 + (z-3)^2 - 1")
    # any invertible matrix, used as Rᵀ: R = diag(2, 1, 1) gives (2x)² + y² + z² ≤ 1
    assert form({"center": [0, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[2, 0, 0], [0, 1, 0], [0, 0, 1]]}) == P("4*x^2+y^2+z^2-1")
    # JSON numbers are doubles, strings exact
    assert form({"center": [0.1, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}) != P("(x-0.1)^2+y^2+z^2-1")
    assert form({"center": ["0.1", 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}) == P("(x-0.1)^2+y^2+z^2-1")
    assert form("1 - x^2 - y^2/4 - z^2") == P("x^2 + y^2/4 + z^2 - 1")  # negative inside
    bad = [{"center": [0, 0, 0], "semi_axes": [1, 0, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
           {"center": [0, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [1, 1, 0]]},
           {"center": [0, 0, 0], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0]]},
           {"center": [0, 0, True], "semi_axes": [1, 1, 1], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
           "x^2 + y^2 - z^2 - 1", "x^2 + y^2 + z^2 + 1", "x^2 + y^2 + z^2", "x^2 + y^2 - 1", "x^3 + y^2 + z^2 - 1", 5]
    for e in bad:
        with pytest.raises(exact.CheckError):
            form(e)
