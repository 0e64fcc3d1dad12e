"""Claims of ``tangent`` answers (an ellipsoid E against a surface S)."""

from fractions import Fraction

from . import poly as P
from .exact import QS, CheckError, NotChecked, parse_point, parse_rational, parse_value
from .natural import proportional


def _ldl_signs(m):
    """The signs of the pivots of a symmetric matrix (exact LDLᵀ without
    pivoting; None when a zero pivot comes before the end)."""
    m = [list(map(Fraction, row)) for row in m]
    n, signs = len(m), []
    for k in range(n):
        piv = m[k][k]
        if piv == 0:
            return None if k < n - 1 else signs + [0]
        signs.append(1 if piv > 0 else -1)
        for i in range(k + 1, n):
            f = m[i][k] / piv
            for j in range(k, n):
                m[i][j] -= f * m[k][j]
    return signs


def check_s_lemma(e, s, side, tau):
    """side·(S − τE) positive definite as a form in (x, y, z, 1) (every
    LDLᵀ pivot positive): on E = 0 it is side·S, so side·S > 0 on all of E."""
    me, ms = P.form_matrix(e), P.form_matrix(s)
    m = [[side * (ms[i][j] - tau * me[i][j]) for j in range(4)] for i in range(4)]
    signs = _ldl_signs(m)
    if signs is None or signs != [1, 1, 1, 1]:
        raise CheckError(f"side·(S − τE) is not positive definite for τ = {tau}")


def check_ellipsoid(e):
    """E is a real ellipsoid: total degree 2, its quadratic part M definite
    (LDLᵀ pivots of one sign), and E below zero (for M positive) at its
    centre, so that E = 0 is a real ellipsoid, not empty nor a point."""
    if P.degree(e) != 2 or any(k[3] for k in e):
        raise CheckError("E is not a quadric in x, y, z")
    m = P.form_matrix(e)
    signs = _ldl_signs([row[:3] for row in m[:3]])
    if not signs or 0 in signs or len(set(signs)) != 1:
        raise CheckError("E's quadratic part is not definite: not an ellipsoid")
    # the full 4×4 pivots: the last one is E at the centre (Schur complement)
    full = _ldl_signs(m)
    if full is None or full[-1] != -signs[0]:
        raise CheckError("E is empty or a single point: not a real ellipsoid")


def _witness(w, e, s, want, what):
    if not isinstance(w, dict):
        raise CheckError(f"{what}: missing witness")
    p = parse_point(w.get("point"), what)
    if not P.evaluate(e, p).is_zero():
        raise CheckError(f"{what}: the point is not on E")
    v = P.evaluate(s, p)
    if v.sign() != want or w.get("sign") != want:
        raise CheckError(f"{what}: S has not the sign {want} there")
    if "value" in w and w["value"] is not None:
        claimed = parse_value(w["value"], f"{what} value")
        if not (claimed - v).is_zero():
            raise CheckError(f"{what}: the value printed is not S there")


def _alg_equals(alg, v, what):
    """Whether the exact value v (Q(√d)) is the real algebraic number
    {poly, interval}: a root of poly inside [lo, hi] (which holds one root)."""
    if not isinstance(alg, dict):
        raise CheckError(f"{what}: expected {{poly, interval}}")
    poly = P.univariate(P.parse(alg.get("poly")))
    lo, hi = (parse_rational(x) for x in alg.get("interval") or [])
    acc = QS(0)
    for c in reversed(poly):
        acc = acc * v + QS(c)
    return acc.is_zero() and (v - QS(lo)).sign() >= 0 and (QS(hi) - v).sign() >= 0


def extreme_at(e, s, w):
    """For S of degree ≤ 2 and a witness point p on E: with v = S(p) and
    ∇S(p) = λ·∇E(p), the form S − v − λE in (x, y, z, 1) vanishes with its
    gradient at p.  If it is positive semidefinite (no negative eigenvalue,
    by Descartes on its characteristic polynomial), S ≥ v on E = 0: v is the
    minimum, attained at p; negative semidefinite: the maximum.  Returns
    ("min" | "max", v), or None when p proves neither."""
    from .pencil import charpoly_signs

    p = parse_point(w.get("point"), "witness")
    v = P.evaluate(s, p)
    ge = [P.evaluate(g, p) for g in P.gradient(e)]
    gs = [P.evaluate(g, p) for g in P.gradient(s)]
    i = next((k for k in range(3) if not ge[k].is_zero()), None)
    if i is None:
        return None
    lam = gs[i] / ge[i]
    if any(not (gs[k] - lam * ge[k]).is_zero() for k in range(3)):
        return None
    me, ms = P.form_matrix(e), P.form_matrix(s)
    m = [[QS(ms[a][b]) - lam * QS(me[a][b]) for b in range(4)] for a in range(4)]
    m[3][3] = m[3][3] - v
    pos, neg, _ = charpoly_signs(m)
    if not neg:
        return "min", v
    if not pos:
        return "max", v
    return None


def alg_qs(alg):
    """A printed real algebraic number {poly, interval} of degree ≤ 2 as an
    exact value of Q(√d) (the root of poly in the interval), else None."""
    if not isinstance(alg, dict) or not isinstance(alg.get("poly"), str):
        return None
    poly = P.univariate(P.parse(alg["poly"].replace("l", "u")))
    lo, hi = (QS(parse_rational(x)) for x in alg.get("interval") or [])
    if len(poly) == 2:
        roots = [QS(-poly[0] / poly[1])]
    elif len(poly) == 3:
        c, b, a = poly
        disc = b * b - 4 * a * c
        if disc < 0:
            return None
        n, d = disc.numerator * disc.denominator, disc.denominator
        roots = [QS(-b / (2 * a), Fraction(sgn, 2 * a * d), n) for sgn in (1, -1)]
    else:
        return None
    inside = [r for r in roots if (r - lo).sign() >= 0 and (hi - r).sign() >= 0]
    return inside[0] if len(inside) == 1 else None


def extreme_by_multiplier(e, s, alg, kind, multipliers=()):
    """For S of degree ≤ 2 and a printed extreme v in Q or Q(√d): a
    multiplier λ — a rational root of det(S − v − λE) found here, or the
    certificate's λ for that value when it lies in Q(√d) — with S − v − λE
    positive (negative) semidefinite proves S ≥ v (≤ v) on E = 0 (E is 0
    there); a kernel vector of it that is a point of E proves v attained.
    True when proved."""
    from .pencil import charpoly_signs, det_poly, kernel, rational_roots

    v = alg_qs(alg)
    if v is None:
        return False
    me, ms = P.form_matrix(e), P.form_matrix(s)
    cands = []
    if not v.d:
        shifted = [row[:] for row in ms]
        shifted[3][3] -= v.a
        cands = [QS(x) for x in rational_roots(det_poly(shifted, me))]
    if P.degree(s) == 1:
        # a plane n·x + s₀: at a critical point n = λ·∇E = λ(2Mx + 2b), so
        # x = M⁻¹(n/2λ − b) and v = S(x) give λ = nᵀM⁻¹n / 2(v − s₀ + nᵀM⁻¹b)
        from .pencil import nullspace

        n = [2 * ms[i][3] for i in range(3)]
        b = [me[i][3] for i in range(3)]
        sol = [nullspace([me[i][:3] + [-rhs[i]] for i in range(3)], 4) for rhs in (n, b)]
        if all(x is not None and not x[3].is_zero() for x in sol):
            minv_n, minv_b = ([x[i] / x[3] for i in range(3)] for x in sol)
            nn = sum((QS(n[i]) * minv_n[i] for i in range(3)), QS(0))
            nb = sum((QS(n[i]) * minv_b[i] for i in range(3)), QS(0))
            den = (v - QS(ms[3][3]) + nb) * QS(2)
            if not den.is_zero():
                cands.append(nn / den)
    strip = lambda a: {k: a.get(k) for k in ("poly", "interval")} if isinstance(a, dict) else a  # noqa: E731
    for mlt in multipliers:
        if isinstance(mlt, dict) and strip(mlt.get("value")) == strip(alg):
            lam = alg_qs(mlt.get("lambda"))
            if lam is not None:
                cands.append(lam)
    for lam in cands:
        m = [[QS(ms[a][b]) - lam * QS(me[a][b]) for b in range(4)] for a in range(4)]
        m[3][3] = m[3][3] - v
        pos, neg, _ = charpoly_signs(m)
        if (kind == "min" and neg) or (kind == "max" and pos):
            continue
        if _kernel_meets(kernel(m, 4), e):
            return True
    return False


def _kernel_meets(ker, e):
    """Whether the kernel of S − v − λE (projective vectors in (x, y, z, w))
    holds a real affine point of E: for a single vector, that point; for a
    pencil k₁ + t·k₂ with an affine k₁ and k₂ at infinity, a real root of
    E(p + t·d) = α·t² + 2β·t + γ (β² − αγ ≥ 0, α ≠ 0)."""
    aff = [k for k in ker if not k[3].is_zero()]
    if len(ker) == 1:
        if not aff:
            return False
        p = [aff[0][i] / aff[0][3] for i in range(3)]
        return P.evaluate(e, p).is_zero()
    if len(ker) != 2 or not aff:
        return False
    k1 = aff[0]
    k2 = next(k for k in ker if k is not k1)
    p = [k1[i] / k1[3] for i in range(3)]
    d = [k2[i] - k2[3] * p[i] for i in range(3)]  # k₂ − k₂[w]·(p, 1): at infinity
    me = P.form_matrix(e)
    pe, de = p + [QS(1)], d + [QS(0)]
    form = lambda u, v: sum((QS(me[i][j]) * u[i] * v[j] for i in range(4) for j in range(4)), QS(0))  # noqa: E731
    al, be, ga = form(de, de), form(pe, de), form(pe, pe)
    return not al.is_zero() and (be * be - al * ga).sign() >= 0


def _values(e, s, res, witnesses):
    """The claims on min and max: re-proved for S of degree ≤ 2 at a
    witness sitting at that extreme, else trusted."""
    crit = (res.get("certificate") or {}).get("critical_values") or []
    strip = lambda a: {k: a.get(k) for k in ("poly", "interval")} if isinstance(a, dict) else a  # noqa: E731
    if crit and res.get("min") is not None and (strip(res["min"]) != strip(crit[0]) or strip(res["max"]) != strip(crit[-1])):
        raise CheckError("min and max are not the first and last of the critical values")
    proved = []
    for w in witnesses:
        if w is None:
            continue
        v = P.evaluate(s, parse_point(w.get("point"), "witness"))
        # a point of E: min ≤ S(p) ≤ max whatever S is
        lo = parse_rational((res.get("min") or {}).get("interval", [None])[0] or "")
        hi = parse_rational((res.get("max") or {}).get("interval", [None, None])[1] or "")
        if (v - QS(lo)).sign() < 0 or (QS(hi) - v).sign() < 0:
            raise CheckError("S at a witness point of E lies outside [min, max]")
        found = extreme_at(e, s, w) if P.degree(s) <= 2 else None
        if found:
            kind, v = found
            if not _alg_equals(res.get(kind), v, kind):
                raise CheckError(f"the witness proves the {kind} is {v}, not the printed one")
            proved.append(kind)
    if P.degree(s) <= 2:
        for kind in ("min", "max"):
            mults = (res.get("certificate") or {}).get("multipliers") or []
            try:
                if kind not in proved and res.get(kind) and extreme_by_multiplier(e, s, res[kind], kind, mults):
                    proved.append(kind)
            except NotChecked:
                pass  # λ and v in two different fields: the extreme stays trusted
        from . import extreme

        points = [parse_point(w.get("point"), "witness") for w in witnesses if w is not None]
        for kind, sign in (("min", 1), ("max", -1)):
            if kind not in proved and res.get(kind) and extreme.minimum(e, s, res[kind], points, sign):
                proved.append(kind)
    proved = sorted(set(proved), key=["min", "max"].index)
    trusted = [k for k in ("min", "max") if k not in proved]
    checked = [f"{k}: S − {k} − λE semidefinite with a zero on E, or a root of Δ(v) = disc_λ det(S − v − λE) bracketed by an S-lemma bound and a point of E" for k in proved]
    return checked, ([f"{' and '.join(trusted)} (the critical values)"] if trusted else [])


def check_tangent(req, res):
    float_mode = req.get("float", False) is True
    e = P.parse(req.get("ellipsoid"), float_mode)
    s = P.parse(req.get("surface"), float_mode)
    check_ellipsoid(e)
    checked, trusted = ["E is a real ellipsoid (LDLᵀ)"], []
    verdict = res.get("verdict")
    cert = res.get("certificate") or {}
    if verdict == "undecided":
        return checked, ["undecided: no claim"]
    if verdict not in ("intersecting", "touching", "separated"):
        raise CheckError(f"unknown verdict {verdict!r}")
    flags = {"intersecting": (True, False), "touching": (True, True), "separated": (False, False)}
    if (res.get("intersect"), res.get("touching")) != flags[verdict]:
        raise CheckError("intersect/touching do not match the verdict")
    neg, pos = cert.get("witness_negative"), cert.get("witness_positive")
    if neg is not None:
        _witness(neg, e, s, -1, "witness_negative")
    if pos is not None:
        _witness(pos, e, s, 1, "witness_positive")
    if verdict == "intersecting":
        if neg is None or pos is None:
            raise CheckError("intersecting without two witnesses")
        checked.append("intersecting: two exact points of E with S of opposite signs")
        c2, t2 = _values(e, s, res, [neg, pos])
        return checked + c2, trusted + t2
    if res.get("containment") == "coincident":
        if not proportional(e, s):
            raise CheckError("coincident, but S is not a multiple of E")
        checked.append("coincident: S = c·E")
        return checked, trusted
    side = res.get("side")
    if verdict == "separated":
        if side not in ("+", "-"):
            raise CheckError("separated without a side")
        w = pos if side == "+" else neg
        if w is None or (neg if side == "+" else pos) is not None:
            raise CheckError("separated: the witness of its side is missing or one of the other side is given")
        checked.append(f"a point of E where S has the sign {side}")
        lemma = cert.get("s_lemma")
        if lemma is not None:
            check_s_lemma(e, s, 1 if side == "+" else -1, parse_rational(lemma.get("tau")))
            checked.append("separated: side·(S − τE) is positive definite (S-lemma), so S ≠ 0 on E")
        else:
            trusted.append("separated: S has no zero on E (the critical set is complete)")
    c2, t2 = _values(e, s, res, [neg, pos])
    if verdict == "touching":
        # the extreme on the side S keeps, re-proved by a multiplier, is 0
        kind = {"+": "min", "-": "max"}.get(side)
        v = alg_qs(res.get(kind)) if kind and not any(kind in t for t in t2) else None
        if v is not None and v.is_zero():
            checked.append(f"touching: the {kind} of S on E is 0 (re-proved above): S keeps its sign {side} and vanishes on E")
        else:
            trusted.append("touching: S has a zero on E and keeps its sign (the critical set is complete)")
    return checked + c2, trusted + t2
