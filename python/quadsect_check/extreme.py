"""The minimum of a quadric S on the ellipsoid E when it is an algebraic
number of any degree (ellipsoid pairs: degree 6), re-proved without the
engine's critical set.

* Every critical value v of S on E is a root of Δ(v) = disc_λ det(S − v −
  λE) (forms in (x, y, z, 1)): at a critical point x (∇S = λ∇E, E(x) = 0)
  the vector (x, 1) is in the kernel of F = S − v − λE, so h(λ) = det(S −
  v − λE) vanishes at λ, and h′(λ) = −tr(adj F · E) is 0 — adj F is a
  multiple of (x, 1)(x, 1)ᵀ when F has rank 3, and 0 below, and E(x) = 0.
  Δ is a polynomial of degree ≤ 6 (h is affine in v, of degree 4 in λ with
  the constant leading coefficient det(−E)); it is interpolated from seven
  exact discriminants.  The minimum of S on the compact E is a critical
  value.
* The printed minimum ρ (the only root of its polynomial in its interval)
  must be a root of Δ; w < ρ < u are rationals with no other root of Δ in
  [w, u].
* S − w − τE positive definite for a rational τ (S-lemma) gives S > w on E;
  a point p of E (exact, in Q(√d)) with S(p) < u gives min < u.  So the
  minimum, a root of Δ in (w, u), is ρ.  (u = ∞ when ρ is the largest root.)

The maximum is the minimum of −S.  Where Δ ≡ 0 (det(S − v − λE) has a
multiple root for every v: S = κE + c, or a repeated eigenvalue of the
pencil's quadratic parts, as for S = xy on a sphere) the route only covers
S = κE + c, S ≡ c on E, checked directly.  The point p is one of the answer's
witnesses or found here by a search in floating point (a heuristic: only
its exact value counts).
"""

import math
import random
from fractions import Fraction

from . import poly as P
from .exact import QS, parse_rational
from .kernel import _det, _roots_in, sylvester
from .pencil import _interpolate, definite_member, det_poly


def _disc(h):
    """The resultant of h and h′ (a constant multiple of the discriminant)."""
    return _det(sylvester(h, P.u_deriv(h)))


def minimum(e, s, alg, witnesses, sign=1):
    """True when the printed extreme ``alg`` of ``sign``·S on E (the
    minimum for sign = 1, the maximum for −1) is re-proved as above."""
    from .sweep import _between, isolated_roots
    from .tangent import _ldl_signs

    sp = P.scale(s, Fraction(sign))
    me, ms = P.form_matrix(e), P.form_matrix(sp)
    vals = []
    for v in range(7):
        shifted = [row[:] for row in ms]
        shifted[3][3] -= v
        vals.append(_disc(P.u_trim(det_poly(shifted, me))))
    delta = _interpolate(vals)
    p = P.univariate(P.parse(alg.get("poly")))
    lo, hi = (parse_rational(x) for x in alg.get("interval"))
    if sign < 0:
        p = [c * (-1) ** i for i, c in enumerate(p)]
        lo, hi = -hi, -lo
    psq = P.u_divmod(p, P.u_gcd(p, P.u_deriv(p)))[0]
    if len(psq) < 2 or _roots_in(P.sturm_sequence(psq), psq, lo, hi) != 1:
        return False
    if len(delta) < 2:
        # Δ ≡ 0: re-proved only when S − κE is a constant c (S ≡ c on E)
        e0 = next(k for k in e if sum(k) > 0)
        rest = P.add(sp, P.scale(e, sp.get(e0, Fraction(0)) / e[e0]), -1)
        if any(sum(k) for k in rest):
            return False
        c = rest.get((0, 0, 0, 0), Fraction(0))
        return P.u_eval(psq, c) == 0 and lo <= c <= hi
    g = P.u_gcd(psq, delta)
    if len(g) < 2 or _roots_in(P.sturm_sequence(g), g, lo, hi) != 1:
        return False  # the printed value is not a root of Δ
    # ρ among the roots of Δ: the one that is a root of g inside [lo, hi]
    roots = isolated_roots(delta)
    gseq = P.sturm_sequence(g)
    j = None
    for i, r in enumerate(roots):
        for x in (lo, hi):  # a rational root at an end of [lo, hi]: exact
            if not r.exact and r.lo < x <= r.hi and P.u_eval(r.g, x) == 0:
                r.lo = r.hi = x
                r.exact = True
        while not r.exact and r.lo < lo < r.hi or not r.exact and r.lo < hi < r.hi:
            r.refine()  # each interval inside [lo, hi] or apart from it
        inside = lo <= r.lo and r.hi <= hi if not r.exact else lo <= r.hi <= hi
        if inside and (P.u_eval(g, r.hi) == 0 if r.exact else P.sturm_count(gseq, r.lo, r.hi) == 1):
            j = i
    if j is None:
        return False
    w = _between(roots[j - 1], roots[j]) if j > 0 else (roots[j].lo if not roots[j].exact else roots[j].hi) - 1
    u = _between(roots[j], roots[j + 1]) if j + 1 < len(roots) else None
    # S − w − τE positive definite: S > w on E
    t = definite_member(P.add(sp, P.const(w), -1), e)
    if t is None:
        return False
    mw = [[ms[a][b] - t * me[a][b] for b in range(4)] for a in range(4)]
    mw[3][3] -= w
    if _ldl_signs(mw) != [1, 1, 1, 1]:
        return False
    if u is None:
        return True
    for pt in list(witnesses) + [_search(e, sp, me)]:
        if pt is not None and P.evaluate(e, pt).is_zero() and (P.evaluate(sp, pt) - QS(u)).sign() < 0:
            return True
    return False


def _search(e, sp, me):
    """A point of E (exact, in Q(√d)) near the minimum of sp, found by a
    seeded random search and shrinking steps in floating point; its
    direction from the centre c is rounded to a rational d and the point
    taken exactly as c + d·√(r / dᵀMd)."""
    m = [[me[i][j] for j in range(3)] for i in range(3)]
    b = [me[i][3] for i in range(3)]
    from .pencil import nullspace

    sol = nullspace([m[i] + [b[i]] for i in range(3)], 4)  # M c + b = 0
    if sol is None or sol[3].is_zero():
        return None
    c = [(sol[i] / sol[3]).a for i in range(3)]
    # E = 0 is (x − c)ᵀM(x − c) = r (M and r of one sign: E may be written negative inside)
    r = sum(c[i] * m[i][j] * c[j] for i in range(3) for j in range(3)) - me[3][3]
    cf, mf, rf = [float(x) for x in c], [[float(x) for x in row] for row in m], float(r)
    terms = [(float(coef), ex) for ex, coef in sp.items()]

    def val(d):
        q = sum(d[i] * mf[i][j] * d[j] for i in range(3) for j in range(3))
        if q * rf <= 0:
            return math.inf
        k = math.sqrt(rf / q)
        x = [cf[i] + k * d[i] for i in range(3)]
        return sum(cf_ * x[0] ** ex[0] * x[1] ** ex[1] * x[2] ** ex[2] for cf_, ex in terms)

    rng = random.Random(1)
    best = min(([rng.gauss(0, 1) for _ in range(3)] for _ in range(200)), key=val)
    fb, step = val(best), 0.5
    while step > 1e-13:
        moved = False
        for i in range(3):
            for sgn in (1, -1):
                cand = best[:]
                cand[i] += sgn * step * max(1.0, abs(best[i]))
                fc = val(cand)
                if fc < fb:
                    best, fb, moved = cand, fc, True
        if not moved:
            step /= 2
    d = [Fraction(x).limit_denominator(10**15) for x in best]
    q = sum(d[i] * m[i][j] * d[j] for i in range(3) for j in range(3))
    if q == 0 or r / q <= 0:
        return None
    k2 = r / q  # the point c + d·√k2
    num, den = k2.numerator * k2.denominator, k2.denominator
    return [QS(c[i], d[i] / den, num) for i in range(3)]
