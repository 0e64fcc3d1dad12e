"""Claims of the kernel operations: ``roots`` and ``resultant``."""

from fractions import Fraction
from itertools import product

from . import poly as P
from .exact import CheckError, parse_rational

# above this many Sylvester determinants the resultant is not recomputed
# (``partial``, "resultant" trusted): a documented size limit
MAX_RESULTANT_POINTS = 2000
MAX_SYLVESTER = 24


def _yun(a):
    """Square-free factors ``[(f, k), …]`` of ``a`` (monic, over Q), Yun's
    algorithm: ``a = lc · ∏ f^k``."""
    out, k = [], 1
    d = P.u_deriv(a)
    g = P.u_gcd(a, d)
    b = P.u_divmod(a, g)[0]
    c = P.u_divmod(d, g)[0]
    dd = P.u_trim([x - y for x, y in _pad(c, P.u_deriv(b))])
    while len(b) > 1:
        g = P.u_gcd(b, dd)
        b_next = P.u_divmod(b, g)[0]
        if len(g) > 1:
            out.append((g, k))
        c = P.u_divmod(dd, g)[0]
        b = b_next
        dd = P.u_trim([x - y for x, y in _pad(c, P.u_deriv(b))])
        k += 1
    return out


def _pad(a, b):
    n = max(len(a), len(b))
    return zip(a + [Fraction(0)] * (n - len(a)), b + [Fraction(0)] * (n - len(b)))


def _roots_in(seq, sqf, lo, hi):
    """Distinct roots of the square-free ``sqf`` in [lo, hi]."""
    return P.sturm_count(seq, lo, hi) + (P.u_eval(sqf, lo) == 0)


def check_roots(req, res):
    """``roots``: every claim is re-proved.

    * the square-free part q = p / gcd(p, p′) has, by Sturm's theorem on q,
      ``distinct_real`` real roots, ``positive`` of them in (0, ∞) and
      ``negative`` in (−∞, 0); 0 is a root of multiplicity
      ``zero_multiplicity`` (p's lowest non-zero coefficient);
    * each interval [lo, hi] (sorted; neighbours share at most an end that is
      not a root) holds exactly one root of q
      (Sturm count on (lo, hi] plus q(lo) = 0), so the intervals, as many as
      ``distinct_real``, isolate all of them;
    * each multiplicity is the k of the factor f_k of Yun's square-free
      decomposition p = c·∏ f_k^k that has a root in the interval; their sum
      is ``real_with_multiplicity``;
    * the Descartes bounds are the sign changes of p's coefficients and of
      p(−x)'s."""
    p = P.univariate(P.parse(req.get("poly")))
    if p == [0]:
        raise CheckError("the zero polynomial has no root list")
    checked = []
    sqf = P.u_divmod(p, P.u_gcd(p, P.u_deriv(p)))[0]
    seq = P.sturm_sequence(sqf)
    total = P.sturm_count(seq, "-inf", "+inf")
    pos = P.sturm_count(seq, Fraction(0), "+inf")
    neg = P.sturm_count(seq, "-inf", Fraction(0)) - (P.u_eval(sqf, 0) == 0)
    _expect(res, "distinct_real", total)
    _expect(res, "positive", pos)
    _expect(res, "negative", neg)
    z = next(i for i, c in enumerate(p) if c != 0)
    _expect(res, "zero_multiplicity", z)
    checked.append("root counts (Sturm)")
    intervals = res.get("intervals")
    if not isinstance(intervals, list) or len(intervals) != total:
        raise CheckError(f"{total} real roots but {len(intervals or [])} intervals")
    prev = None
    factors = _yun(p)
    seqs = [(P.sturm_sequence(f), f, k) for f, k in factors]
    mults = []
    for j, iv in enumerate(intervals):
        if not isinstance(iv, list) or len(iv) != 2:
            raise CheckError(f"interval {j} is not [lo, hi]")
        lo, hi = parse_rational(iv[0]), parse_rational(iv[1])
        # neighbours may share an end that is not a root
        if lo > hi or (prev is not None and (lo < prev or lo == prev and P.u_eval(sqf, lo) == 0)):
            raise CheckError(f"interval {j} is empty, unsorted or overlaps the previous one")
        prev = hi
        if _roots_in(seq, sqf, lo, hi) != 1:
            raise CheckError(f"interval {j} [{iv[0]}, {iv[1]}] does not hold exactly one root")
        ks = [k for s, f, k in seqs if _roots_in(s, f, lo, hi) == 1]
        if len(ks) != 1:
            raise CheckError(f"interval {j}: no single square-free factor has its root")
        mults.append(ks[0])
    checked.append("isolating intervals (Sturm)")
    if res.get("multiplicities") != mults:
        raise CheckError(f"multiplicities {res.get('multiplicities')} but Yun gives {mults}")
    _expect(res, "real_with_multiplicity", sum(mults))
    checked.append("multiplicities (Yun)")
    changes = lambda cs: P._sign_changes([c for c in cs if c != 0])  # noqa: E731
    _expect(res, "descartes_positive_bound", changes(p))
    _expect(res, "descartes_negative_bound", changes([c * (-1) ** i for i, c in enumerate(p)]))
    checked.append("Descartes bounds")
    return checked, []


def sylvester(a, b):
    """The Sylvester matrix of a and b (ascending coefficients, formal
    degrees len − 1): deg b rows of a's coefficients, deg a rows of b's."""
    n, m = len(a) - 1, len(b) - 1
    rows = []
    for p, count in ((a, m), (b, n)):
        for k in range(count):
            row = [Fraction(0)] * (n + m)
            for j, c in enumerate(reversed(p)):
                row[k + j] = c
            rows.append(row)
    return rows


def _expect(res, key, value):
    if res.get(key) != value or isinstance(res.get(key), bool):
        raise CheckError(f"{key} is {res.get(key)!r}, recomputed {value}")


def _det(m):
    """Determinant over Q (Gaussian elimination with fractions)."""
    m = [row[:] for row in m]
    n, det = len(m), Fraction(1)
    for c in range(n):
        piv = next((r for r in range(c, n) if m[r][c] != 0), None)
        if piv is None:
            return Fraction(0)
        if piv != c:
            m[c], m[piv] = m[piv], m[c]
            det = -det
        det *= m[c][c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            if f:
                for k in range(c, n):
                    m[r][k] -= f * m[c][k]
    return det


def _coeffs_in(p, i):
    """p as a polynomial in variable i: list (ascending) of polynomials in
    the other variables."""
    n = P.deg_in(p, i)
    out = [dict() for _ in range(n + 1)]
    for e, c in p.items():
        rest = list(e)
        rest[i] = 0
        out[e[i]][tuple(rest)] = c
    return out


def _eval_rat(p, pt):
    return sum(c * pt[0] ** e[0] * pt[1] ** e[1] * pt[2] ** e[2] * pt[3] ** e[3] for e, c in p.items())


def check_resultant(req, res):
    """``resultant``: Res_v(f, g) is the determinant of the Sylvester matrix
    of f and g as polynomials in v (formal degrees: their degrees in v).  The
    claimed R and that determinant are both polynomials whose degree in each
    other variable w is at most deg_v(g)·deg_w(f) + deg_v(f)·deg_w(g); two
    such polynomials that agree on the whole grid {0, …, bound_w} in every
    variable are equal (a polynomial of degree ≤ b in a variable vanishing
    at b + 1 values of it is zero, variable by variable).  So R is checked
    by that many exact Sylvester determinants over Q (``partial`` above
    MAX_RESULTANT_POINTS of them); ``degree`` is R's total degree."""
    f, g = P.parse(req.get("f")), P.parse(req.get("g"))
    v = req.get("var")
    if v not in ("x", "y", "z", "u"):
        raise CheckError(f"var must be x, y, z or u, got {v!r}")
    i = P.VARS.index(v)
    r = P.parse(res.get("resultant"))
    if P.deg_in(r, i) > 0:
        raise CheckError(f"the resultant still contains {v}")
    _expect(res, "degree", P.degree(r))
    n, m = P.deg_in(f, i), P.deg_in(g, i)
    if n < 1 and m < 1 or not f or not g:
        return ["degree"], ["resultant (constant or zero input)"]
    others = [w for w in range(4) if w != i]
    bounds = {w: m * max(P.deg_in(f, w), 0) + n * max(P.deg_in(g, w), 0) for w in others}
    for w in others:
        if P.deg_in(r, w) > bounds[w]:
            raise CheckError(f"the resultant has degree {P.deg_in(r, w)} in {P.VARS[w]}, above {bounds[w]}")
    points = 1
    for w in others:
        points *= bounds[w] + 1
    if points > MAX_RESULTANT_POINTS or n + m > MAX_SYLVESTER:
        return ["degree"], ["resultant (beyond the checker's size limit)"]
    fc, gc = _coeffs_in(f, i), _coeffs_in(g, i)
    for values in product(*(range(bounds[w] + 1) for w in others)):
        pt = [Fraction(0)] * 4
        for w, val in zip(others, values):
            pt[w] = Fraction(val)
        a = [_eval_rat(c, pt) for c in fc]
        b = [_eval_rat(c, pt) for c in gc]
        rows = sylvester(a, b)
        if _det(rows) != _eval_rat(r, pt):
            raise CheckError(f"the resultant differs from the Sylvester determinant at {values}")
    return ["resultant (Sylvester determinants on a grid)", "degree"], []
