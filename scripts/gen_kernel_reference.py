#!/usr/bin/env python3
"""Generate exact reference data for quadsect's root and resultant kernels.

This script writes ``tests/data/kernel_reference.json``, which is read by the
Rust integration test ``tests/kernel_reference.rs`` (that test needs no
Python; the JSON file is committed as data).

Run it from the crate root (``/work/main``)::

    python3 scripts/gen_kernel_reference.py

It only needs sympy (and mpmath, which sympy depends on).  The output is
deterministic: all random polynomials come from ``random.Random`` with fixed
seeds, and the JSON is written with a stable key order.

The file contains two lists:

``roots``
    Univariate polynomials with, for each one, the counts of its real roots
    (distinct real roots, distinct positive / negative roots, multiplicity of
    the root 0, real roots counted with multiplicity) and every distinct real
    root in increasing order: a 60-significant-digit decimal approximation
    (correctly rounded from an exact isolating interval of relative width
    < 1e-80), the exact value ``p/q`` when the root is rational (else null),
    and its multiplicity.  Roots are computed exactly: the polynomial is
    factored over Z, the real roots of each irreducible factor are isolated
    and refined with sympy's exact real root isolation, and the result is
    cross-checked against ``Poly.intervals`` / ``Poly.count_roots`` on the
    whole polynomial and against ``mpmath.polyroots`` on each factor.

``resultants``
    Pairs (f, g) with a variable and ``sympy.resultant(f, g, var)`` (the
    determinant of the Sylvester matrix with f's rows first), cross-checked
    against the determinant of the Sylvester matrix (small cases) or against
    univariate resultants at integer specialisations of the other variables.

Every polynomial string uses the syntax of quadsect's parser: variables
x, y, z, u; operators + - * / ^; integers and p/q rationals; no ``**``.
"""

import json
import os
import random
import sys
import time
from decimal import Decimal, localcontext

import mpmath
import sympy
from sympy import (
    Integer,
    Matrix,
    Poly,
    QQ,
    Rational,
    ZZ,
    chebyshevt,
    expand,
    legendre,
    resultant,
    symbols,
)

x, y, z, u = symbols("x y z u")
VARS = {"x": x, "y": y, "z": z, "u": u}
ORDER = [x, y, z, u]

SIG_DIGITS = 60
NUM_DPS = 160  # working precision of the mpmath cross-check


# --------------------------------------------------------------------------
# formatting


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def fmt_rat(c):
    """A sympy Rational / int as "p" or "p/q" (sign included)."""
    c = Rational(c)
    if c.q == 1:
        return str(c.p)
    return "%d/%d" % (c.p, c.q)


def poly_to_str(expr, gens=None):
    """Expanded polynomial in quadsect syntax (x, y, z, u; ^; p/q)."""
    expr = sympy.sympify(expr)
    if gens is None:
        gens = [g for g in ORDER if g in expr.free_symbols]
    extra = expr.free_symbols - set(ORDER)
    if extra:
        raise ValueError("unsupported symbols %s" % extra)
    if not gens:
        c = Rational(expr)
        return fmt_rat(c)
    p = Poly(expr, *gens, domain=QQ)
    if p.is_zero:
        return "0"
    parts = []
    for monom, coeff in p.terms():  # lex order, highest first
        coeff = Rational(coeff)
        factors = []
        for g, e in zip(gens, monom):
            if e == 1:
                factors.append(str(g))
            elif e > 1:
                factors.append("%s^%d" % (g, e))
        mono = "*".join(factors)
        a = abs(coeff)
        if not mono:
            body = fmt_rat(a)
        elif a == 1:
            body = mono
        else:
            body = fmt_rat(a) + "*" + mono
        if not parts:
            parts.append(("-" if coeff < 0 else "") + body)
        else:
            parts.append(("- " if coeff < 0 else "+ ") + body)
    s = " ".join(parts)
    assert "**" not in s and "." not in s
    return s


def parse_back(s):
    """Parse our own syntax with sympy (to check the round trip)."""
    return sympy.sympify(s.replace("^", "**"), locals=VARS, rational=True)


def decimal_of(r, digits=SIG_DIGITS):
    """Correctly rounded positional decimal with `digits` significant digits."""
    r = Rational(r)
    with localcontext() as ctx:
        ctx.prec = digits
        d = Decimal(int(r.p)) / Decimal(int(r.q))
    s = format(d, "f")
    return s


# --------------------------------------------------------------------------
# roots


def sign_at(coeffs, r):
    """Sign of the integer polynomial (coefficients highest first) at the
    rational r, computed exactly with integers."""
    a, b = int(r.p), int(r.q)
    acc = coeffs[0]
    bp = 1
    for c in coeffs[1:]:
        bp *= b
        acc = acc * a + c * bp
    return (acc > 0) - (acc < 0)


def refine_to(f, lo, hi, rel):
    """Refine, by exact bisection, the isolating interval [lo, hi] of a real
    root of the square-free integer Poly f (degree >= 2, irreducible, so no
    rational root and the root is not 0) until hi - lo < rel * min(|lo|, |hi|)
    and 0 is outside [lo, hi]."""
    coeffs = [int(c) for c in f.all_coeffs()]
    lo, hi = Rational(lo), Rational(hi)
    slo, shi = sign_at(coeffs, lo), sign_at(coeffs, hi)
    assert slo * shi < 0, "not an isolating interval with a sign change"
    while not (lo * hi > 0 and hi - lo < rel * min(abs(lo), abs(hi))):
        mid = (lo + hi) / 2
        sm = sign_at(coeffs, mid)
        assert sm != 0
        if sm == slo:
            lo = mid
        else:
            hi = mid
    return lo, hi


def sympy_root_data(expr):
    """Exact real-root analysis of a univariate polynomial expression."""
    expr = sympy.sympify(expr)
    p = Poly(expr, x, domain=QQ)
    assert not p.is_zero
    _, pz = p.clear_denoms(convert=True)  # integer polynomial, same roots
    pz = Poly(pz, x, domain=ZZ)

    # method 1: factor over Z, isolate and refine each irreducible factor
    _, factors = pz.factor_list()
    items = []  # (lo, hi, exact_or_None, multiplicity, factor)
    zero_mult = 0
    rel = Rational(1, 10**80)
    for f, m in factors:
        f = Poly(f, x, domain=ZZ)
        d = f.degree()
        if d == 0:
            continue
        if d == 1:
            a, b = f.all_coeffs()
            r = Rational(-b, a)
            if r == 0:
                zero_mult = m
            items.append([r, r, r, m, f])
            continue
        for (s, t), mm in f.intervals():
            assert mm == 1
            s, t = Rational(s), Rational(t)
            if s == t:
                raise AssertionError("rational root of an irreducible factor")
            lo, hi = refine_to(f, s, t, rel)
            items.append([lo, hi, None, m, f])
    # sort; make sure the (closed) intervals are pairwise disjoint
    items.sort(key=lambda it: it[0])
    for _ in range(50):
        bad = False
        for i in range(len(items) - 1):
            a, b = items[i], items[i + 1]
            if not a[1] < b[0]:
                bad = True
                for it in (a, b):
                    if it[2] is None:
                        it[0], it[1] = refine_to(it[4], it[0], it[1], (it[1] - it[0]) / 2**64 / max(abs(it[0]), abs(it[1])))
        items.sort(key=lambda it: it[0])
        if not bad:
            break
    else:
        raise AssertionError("could not separate roots")

    roots = []
    for lo, hi, ex, m, f in items:
        if ex is not None:
            approx = decimal_of(ex)
        else:
            a1 = decimal_of(lo)
            a2 = decimal_of(hi)
            # the interval is far narrower than the 60-digit rounding step, so
            # both ends round alike except in the (unseen) tie case
            if a1 != a2:
                lo2, hi2 = refine_to(f, lo, hi, Rational(1, 10**120))
                a1, a2 = decimal_of(lo2), decimal_of(hi2)
                assert a1 == a2, (a1, a2)
            approx = a1
        roots.append(
            {
                "approx": approx,
                "exact": fmt_rat(ex) if ex is not None else None,
                "multiplicity": int(m),
            }
        )

    distinct = len(roots)
    positive = sum(1 for it in items if it[0] > 0)
    negative = sum(1 for it in items if it[1] < 0)
    with_mult = sum(r["multiplicity"] for r in roots)

    # method 2: sympy's isolation on the whole (non square-free) polynomial
    ivs = pz.intervals() if pz.degree() > 0 else []
    assert len(ivs) == distinct, (len(ivs), distinct)
    for ((s, t), m), it, r in zip(ivs, items, roots):
        assert m == r["multiplicity"], (m, r)
        s, t = Rational(s), Rational(t)
        assert s <= it[0] and it[1] <= t, ((s, t), it[:2])
    npos = sum(1 for (s, t), _ in ivs if Rational(s) >= 0 and Rational(t) > 0)
    nneg = sum(1 for (s, t), _ in ivs if Rational(s) < 0 and Rational(t) <= 0)
    assert (npos, nneg) == (positive, negative), ((npos, nneg), (positive, negative))
    if 0 < pz.degree() <= 24:
        # Sturm sequences over QQ (slow for big inputs, hence the bound)
        assert pz.count_roots() == distinct
        assert pz.count_roots(inf=0) - (1 if zero_mult else 0) == positive
        assert pz.count_roots(sup=0) - (1 if zero_mult else 0) == negative
    assert positive + negative + (1 if zero_mult else 0) == distinct

    # method 3: independent numerics, mpmath.polyroots (Durand-Kerner) on
    # each irreducible factor at high precision; the real roots it finds
    # must be exactly ours, with the same multiplicities
    for f, m in factors:
        f = Poly(f, x, domain=ZZ)
        if f.degree() < 2:
            continue
        mine = [r for r, it in zip(roots, items) if it[2] is None and it[4] == f]
        with mpmath.workdps(NUM_DPS):
            found = mpmath.polyroots([int(c) for c in f.all_coeffs()], maxsteps=2000, extraprec=4 * NUM_DPS)
            real = sorted(r.real for r in found
                          if abs(mpmath.im(r)) <= mpmath.mpf(10) ** (-NUM_DPS // 2) * max(1, abs(r)))
            assert len(real) == len(mine), (len(real), len(mine))
            for v, r in zip(real, mine):
                a = mpmath.mpf(r["approx"])
                assert abs(v - a) <= abs(a) * mpmath.mpf(10) ** (1 - SIG_DIGITS), (v, a)
                assert r["multiplicity"] == m

    return {
        "distinct_real": distinct,
        "positive": positive,
        "negative": negative,
        "zero_multiplicity": int(zero_mult),
        "real_with_multiplicity": int(with_mult),
        "roots": roots,
    }


def rand_poly(rng, deg, bits=None, lo=-9, hi=9):
    coeffs = []
    for i in range(deg + 1):
        if bits is None:
            c = rng.randint(lo, hi)
        else:
            c = rng.randrange(-(2**bits) + 1, 2**bits)
        if i == 0:
            while c == 0:
                c = rng.randint(1, hi) if bits is None else rng.randrange(1, 2**bits)
        coeffs.append(c)
    return sum(c * x ** (deg - i) for i, c in enumerate(coeffs))


def root_cases():
    cases = []

    def add(cid, expr, poly_str=None):
        if poly_str is None:
            poly_str = poly_to_str(expand(expr), [x] if expand(expr).free_symbols else [])
        # round trip through the string
        assert expand(parse_back(poly_str) - expr) == 0, cid
        t0 = time.time()
        data = sympy_root_data(expr)
        log("roots %-36s %6.2fs" % (cid, time.time() - t0))
        case = {"id": cid, "poly": poly_str}
        case.update(data)
        cases.append(case)

    rng = random.Random(20240611)
    # random dense, small coefficients
    for d in (5, 8, 12, 17, 23, 30):
        add("rand_small_deg%d" % d, rand_poly(rng, d))
    # random dense, small coefficients, wider range
    for d in (7, 20):
        add("rand_mid_deg%d" % d, rand_poly(rng, d, lo=-1000, hi=1000))
    # random dense, 200-bit coefficients
    for d in (5, 9, 14, 20, 30):
        add("rand_big200_deg%d" % d, rand_poly(rng, d, bits=200))
    # random products with many real roots: rational and irrational roots
    rats = [Rational(rng.randint(-50, 50), rng.randint(1, 30)) for _ in range(6)]
    e = 1
    for r in rats:
        e *= (r.q * x - r.p)
    e *= (x**2 - 5) * (7 * x**3 - 3 * x + 1)
    add("rand_product_rational_irrational", e)
    # 200-bit quadratic with real roots, squared, times a random cubic
    while True:
        q = rand_poly(rng, 2, bits=200)
        if Poly(q, x).count_roots() == 2:
            break
    add("big200_quadratic_squared", q**2 * rand_poly(rng, 3, bits=64))

    # multiple roots
    add("mult_x2m2_cubed_3xm1", (x**2 - 2) ** 3 * (3 * x - 1))
    add("mult_xm1_5_xp2_2", (x - 1) ** 5 * (x + 2) ** 2)
    add("zero_mult4_x2m3", x**4 * (x**2 - 3))
    add("mult_golden2_third3", (x**2 - x - 1) ** 2 * (3 * x + 1) ** 3)
    add("mult_cbrt2_sq_xm1_4_x2", (x**3 - 2) ** 2 * (x - 1) ** 4 * x**2)
    add("mult_x2p1_2_x2m7_3", (x**2 + 1) ** 2 * (x**2 - 7) ** 3 * (x + Rational(5, 3)))
    # Wilkinson
    w = 1
    for k in range(1, 21):
        w *= x - k
    add("wilkinson20", w)
    add("wilkinson20_perturbed", expand(w) - Rational(1, 2**23) * x**19)
    # Mignotte-like
    add("mignotte12_2pow20", x**12 - 2 * (2**20 * x - 1) ** 2)
    add("mignotte20_100", x**20 - 2 * (100 * x - 1) ** 2)
    # very close roots
    add("close_rational_1e31", (3 * x - 1) * ((3 * 10**31) * x - (10**31 + 1)))
    a = Rational(1, 7)
    c = Rational(1, 2 * 10**70)  # roots a +- sqrt(c), ~1.41e-35 apart
    qq = expand((x**2 - 2 * a * x + a**2 - c) * 98 * 10**70)
    assert Poly(qq, x).is_irreducible and Poly(qq, x).count_roots() == 2
    add("close_irrational_quadratic_1e35", qq)
    add("close_irrational_quartic_1e40", expand((x**2 - 2) ** 2 * 10**80 - 1))
    # no real roots
    add("no_real_x4p1", x**4 + 1)
    add("no_real_x6_x2_1", x**6 + x**2 + 1)
    add("no_real_x2p1_cubed", (x**2 + 1) ** 3)
    # orthogonal polynomials
    add("chebyshev_t15", chebyshevt(15, x))
    add("legendre_p12", legendre(12, x))
    # rational coefficients
    add("rational_x3_7_9x_1_81", x**3 - Rational(7, 9) * x + Rational(1, 81), "x^3 - 7/9*x + 1/81")
    add("rational_quintic", Rational(1, 2) * x**5 - Rational(3, 7) * x**2 - Rational(5, 11) * x + Rational(1, 13))
    # extreme magnitudes
    add("large_root_x3m1e40", x**3 - 10**40)
    add("tiny_roots_1e30x2m2", 10**30 * x**2 - 2)
    # small / degenerate
    add("constant_7", Integer(7), "7")
    add("constant_neg_3_4", Rational(-3, 4), "-3/4")
    add("linear_x", x)
    add("linear_5xm3", 5 * x - 3)
    add("x_pow_7", x**7)
    return cases


# --------------------------------------------------------------------------
# resultants


def sylvester_det(f, g, v):
    fp, gp = Poly(f, v), Poly(g, v)
    m, n = fp.degree(), gp.degree()
    if m <= 0 or n <= 0:
        return None
    fc, gc = fp.all_coeffs(), gp.all_coeffs()
    rows = []
    for i in range(n):
        rows.append([0] * i + fc + [0] * (n - 1 - i))
    for i in range(m):
        rows.append([0] * i + gc + [0] * (m - 1 - i))
    return expand(Matrix(rows).det(method="bareiss"))


def check_resultant(f, g, v, r):
    others = sorted((f.free_symbols | g.free_symbols) - {v}, key=str)
    fp, gp = Poly(f, v), Poly(g, v)
    size = max(fp.degree(), 0) + max(gp.degree(), 0)
    if not others and size <= 30 or size <= 8:
        s = sylvester_det(f, g, v)
        if s is not None:
            assert expand(s - r) == 0
            return "sylvester"
    # specialise the other variables at integer points where the leading
    # coefficients in v do not vanish, compare with univariate resultants
    rng = random.Random(7)
    done = 0
    tries = 0
    while done < 4 and tries < 100:
        tries += 1
        pt = {w: rng.randint(-5, 5) for w in others}
        lf = fp.LC().subs(pt) if fp.degree() > 0 else 1
        lg = gp.LC().subs(pt) if gp.degree() > 0 else 1
        if lf == 0 or lg == 0:
            continue
        rs = resultant(f.subs(pt), g.subs(pt), v)
        assert rs == r.subs(pt), (pt, rs, r.subs(pt))
        done += 1
    assert done == 4
    return "specialised"


def resultant_cases():
    cases = []

    def add(cid, f, g, var, f_str=None, g_str=None):
        v = VARS[var]
        f, g = expand(f), expand(g)
        if f_str is None:
            f_str = poly_to_str(f)
        if g_str is None:
            g_str = poly_to_str(g)
        assert expand(parse_back(f_str) - f) == 0, cid
        assert expand(parse_back(g_str) - g) == 0, cid
        t0 = time.time()
        r = expand(resultant(f, g, v))
        assert v not in r.free_symbols
        how = check_resultant(f, g, v, r)
        log("resultant %-32s %6.2fs (%s)" % (cid, time.time() - t0, how))
        r_str = poly_to_str(r)
        assert expand(parse_back(r_str) - r) == 0
        cases.append({"id": cid, "f": f_str, "g": g_str, "var": var, "resultant": r_str})

    rng = random.Random(987654321)
    # univariate, small coefficients
    for (m, n) in ((2, 2), (3, 2), (5, 4), (7, 7), (12, 10)):
        add("uni_small_%d_%d" % (m, n), rand_poly(rng, m), rand_poly(rng, n), "x")
    # univariate, 64-bit coefficients
    for (m, n) in ((4, 3), (8, 6), (11, 12)):
        add("uni_64bit_%d_%d" % (m, n), rand_poly(rng, m, bits=64), rand_poly(rng, n, bits=64), "x")
    # univariate, 200-bit coefficients
    for (m, n) in ((3, 2), (6, 5), (12, 12)):
        add("uni_200bit_%d_%d" % (m, n), rand_poly(rng, m, bits=200), rand_poly(rng, n, bits=200), "x")
    # odd x odd degrees: Res(g, f) = -Res(f, g)
    f1, g1 = 2 * x**3 + x + 1, x**3 - x - 5
    add("uni_sign_fg", f1, g1, "x")
    add("uni_sign_gf", g1, f1, "x")
    # common roots
    add("common_root_rational", (x - 2) * (x**2 + 1), (x - 2) * (x + 5), "x")
    add("common_root_irrational", (x**2 - 2) * (3 * x + 1), (x**2 - 2) * (x - 3) * (x**2 + x + 1), "x")
    add("common_root_200bit", (x - 2**199 - 3) * rand_poly(rng, 3, bits=200), (x - 2**199 - 3) * rand_poly(rng, 4, bits=200), "x")
    # rational coefficients
    add("rational_uni", x**3 - Rational(1, 2) * x + Rational(1, 3), Rational(2, 5) * x**2 - 7, "x")
    add("rational_bivariate", Rational(1, 2) * x**2 + Rational(2, 3) * y * x - Rational(5, 7), x * y - Rational(3, 4) * y**2 + 1, "x")
    # bivariate in x, y
    add("circle_line_elim_x", x**2 + y**2 - 1, x - y, "x")
    add("circle_parabola_elim_x", x**2 + y**2 - 4, y - x**2 + 1, "x")
    add("circle_parabola_elim_y", x**2 + y**2 - 4, y - x**2 + 1, "y")

    def rand_multi(gens, deg, cmax=9):
        e = 0
        mons = [()]
        for _ in gens:
            mons = [mm + (k,) for mm in mons for k in range(deg + 1)]
        for mm in mons:
            if sum(mm) <= deg:
                c = rng.randint(-cmax, cmax)
                t = c
                for g, k in zip(gens, mm):
                    t *= g**k
                e += t
        return e

    fb, gb = rand_multi([x, y], 3), rand_multi([x, y], 4)
    add("rand_bivariate_3_4_elim_x", fb, gb, "x")
    add("rand_bivariate_3_4_elim_y", fb, gb, "y")
    fb2, gb2 = rand_multi([x, y], 4, 2**40), rand_multi([x, y], 3, 2**40)
    add("rand_bivariate_big_elim_y", fb2, gb2, "y")
    # trivariate: eliminate z
    add("sphere_saddle_elim_z", x**2 + y**2 + z**2 - 1, z - x * y, "z")
    add("two_quadrics_elim_z", x**2 + 2 * y**2 - z**2 + 3 * x * z - 1, x * y + y * z + z**2 - 2 * x + 5, "z")
    ft, gt = rand_multi([x, y, z], 2), rand_multi([x, y, z], 3)
    add("rand_trivariate_elim_z", ft, gt, "z")
    add("rand_trivariate_elim_x", ft, gt, "x")
    # one polynomial free of the variable
    add("const_in_var_f", y**2 + 1, x**3 - y, "x")
    add("const_in_var_g", x**3 - y, y**2 + 1, "x")
    add("const_in_var_number", Integer(3), x**2 + y, "x", "3", None)
    add("both_const_in_var", y**2 + 1, y - 2, "x")
    # variable u
    add("u_univariate", u**3 - 2 * u + 1, u**2 + u - 5, "u")
    add("u_bivariate_elim_u", u**2 + x * u - 3, x * u**3 - u + x**2, "u")
    add("u_bivariate_elim_x", u**2 + x * u - 3, x * u**3 - u + x**2, "x")
    add("uxyz_elim_u", u**2 - x * y, u * z - x - y, "u")
    return cases


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    out = os.path.join(root, "tests", "data", "kernel_reference.json")
    data = {
        "generator": "scripts/gen_kernel_reference.py",
        "sympy_version": sympy.__version__,
        "roots": root_cases(),
        "resultants": resultant_cases(),
    }
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as fh:
        json.dump(data, fh, indent=1)
        fh.write("\n")
    print(
        "wrote %s: %d root cases, %d resultant cases"
        % (os.path.relpath(out, os.getcwd()), len(data["roots"]), len(data["resultants"])),
        file=sys.stderr,
    )


if __name__ == "__main__":
    main()
