"""Completeness of a natural answer from a member of the pencil λA + μB.

If μ ≠ 0, A ∩ B = A ∩ {λA + μB = 0}.  Two kinds of member prove that the
listed components are all the real points:

* a **definite** member (a definite 4×4 form in (x, y, z, 1)) has no real
  zero: A ∩ B is empty.  This checker finds one itself when it exists: the
  forms of the pencil A − tB that are definite make an open interval between
  consecutive real roots of det(A − tB), so one rational point in each gap
  between those roots (isolated by Sturm sequences) is tested by LDLᵀ;
* a member that is a product of **planes**, λA + μB = κ·P₁·P₂ (P₂ = 1 for a
  member of degree 1, P₂ = P₁ for a double plane), with the planes taken
  from the answer's certificate or from its listed conics, and λ, μ, κ
  solved for exactly.  Then A ∩ B is the union of the plane sections A ∩ Pᵢ,
  each classified exactly (the 3×3 form of A restricted to the plane: its
  eigenvalue signs by Descartes' rule on the characteristic polynomial, a
  symmetric matrix having only real eigenvalues), and compared with the
  components listed in that plane.
"""

from fractions import Fraction

from . import poly as P
from .exact import QS, CheckError, cross, dot, sqrt_rational


def _qs(x):
    return x if isinstance(x, QS) else QS(x)


def kernel(rows, n):
    """A basis of {v : rows·v = 0} over Q(√d) (reduced row echelon form)."""
    m = [[_qs(x) for x in r] for r in rows]
    pivots, r = [], 0
    for c in range(n):
        piv = next((i for i in range(r, len(m)) if not m[i][c].is_zero()), None)
        if piv is None:
            continue
        m[r], m[piv] = m[piv], m[r]
        inv = m[r][c].inv()
        m[r] = [x * inv for x in m[r]]
        for i in range(len(m)):
            if i != r and not m[i][c].is_zero():
                f = m[i][c]
                m[i] = [x - f * y for x, y in zip(m[i], m[r])]
        pivots.append(c)
        r += 1
    basis = []
    for f in (c for c in range(n) if c not in pivots):
        v = [QS(0)] * n
        v[f] = QS(1)
        for i, c in enumerate(pivots):
            v[c] = -m[i][f]
        basis.append(v)
    return basis


def nullspace(rows, n):
    """A non-zero vector v (over Q(√d)) with rows·v = 0, or None."""
    basis = kernel(rows, n)
    return basis[0] if basis else None


MONOS = [e for e in ((i, j, k, 0) for i in range(3) for j in range(3) for k in range(3)) if sum(e) <= 2]


def _coef(p, e):
    return _qs(p.get(e, 0))


def plane_poly(n, off):
    """n·P − off as a dict polynomial over Q(√d) (coefficients QS)."""
    out = {(0, 0, 0, 0): -off}
    for i in range(3):
        e = [0, 0, 0, 0]
        e[i] = 1
        out[tuple(e)] = n[i]
    return out


def _mul_qs(p, q):
    out = {}
    for e1, c1 in p.items():
        for e2, c2 in q.items():
            e = tuple(a + b for a, b in zip(e1, e2))
            out[e] = out.get(e, QS(0)) + _qs(c1) * _qs(c2)
    return out


def solve_member(a, b, planes):
    """(λ, μ) with λA + μB = κ·∏ planes for some κ (exact), or None."""
    prod = {(0, 0, 0, 0): QS(1)}
    for n, off in planes:
        prod = _mul_qs(prod, plane_poly(n, off))
    rows = [[_coef(a, e), _coef(b, e), -_coef(prod, e)] for e in MONOS]
    v = nullspace(rows, 3)
    if v is None or (v[0].is_zero() and v[1].is_zero()) or v[2].is_zero():
        return None
    return v[0], v[1]


def charpoly_signs(m):
    """(positive, negative, zero) eigenvalue counts of a symmetric matrix
    over Q(√d): Descartes' rule is exact on a polynomial with only real
    roots (sign changes of p(λ) and p(−λ); zero roots from the trailing
    zero coefficients).  The characteristic polynomial by Faddeev–LeVerrier."""
    n = len(m)
    m = [[_qs(x) for x in r] for r in m]
    coeffs = [QS(1)]  # det(λI − M) = λⁿ + c1 λⁿ⁻¹ + … + cn
    mk = [[QS(0)] * n for _ in range(n)]
    for k in range(1, n + 1):
        # M_k = M·(M_{k−1} + c_{k−1} I), c_k = −tr(M·M_k')/k
        prev = [[mk[i][j] + (coeffs[-1] if i == j else QS(0)) for j in range(n)] for i in range(n)]
        mk = [[sum((m[i][l] * prev[l][j] for l in range(n)), QS(0)) for j in range(n)] for i in range(n)]
        tr = sum((mk[i][i] for i in range(n)), QS(0))
        coeffs.append(tr * QS(Fraction(-1, k)))
    # coeffs[k] multiplies λ^(n−k)
    signs = [c.sign() for c in coeffs]
    zeros = 0
    while zeros < n and signs[n - zeros] == 0:
        zeros += 1
    s = [x for x in signs[: n + 1 - zeros]]
    changes = lambda v: sum(1 for x, y in zip([t for t in v if t], [t for t in v if t][1:]) if x != y)  # noqa: E731
    pos = changes(s)
    neg = changes([x * (-1) ** (n - k) for k, x in enumerate(s)])
    return pos, neg, zeros


def _form3(q):
    """The symmetric 3×3 matrix of a quadratic q(s, t) as a form in (s, t, 1)."""
    m = [[QS(0)] * 3 for _ in range(3)]
    for (i, j), c in q.items():
        idx = [0] * i + [1] * j
        if len(idx) == 2:
            a, b = idx
            if a == b:
                m[a][a] = m[a][a] + c
            else:
                m[a][b] = m[a][b] + c * QS(Fraction(1, 2))
                m[b][a] = m[b][a] + c * QS(Fraction(1, 2))
        elif len(idx) == 1:
            m[idx[0]][2] = m[idx[0]][2] + c * QS(Fraction(1, 2))
            m[2][idx[0]] = m[2][idx[0]] + c * QS(Fraction(1, 2))
        else:
            m[2][2] = m[2][2] + c
    return m


def section(eq, n, off):
    """The real affine zero set of the quadric eq in the plane n·P = off:
    ("empty",), ("conic",), ("point", P), ("lines", k) (k real affine lines,
    a double line counting once)."""
    n = [_qs(x) for x in n]
    off = _qs(off)
    axes = [[QS(int(i == j)) for j in range(3)] for i in range(3)]
    u = next(w for w in (cross(n, a) for a in axes) if not all(x.is_zero() for x in w))
    v = cross(n, u)
    nn = dot(n, n)
    o = [x * off / nn for x in n]
    q = P.substitute_affine(eq, [[c] for c in o], [[u[i], v[i]] for i in range(3)])
    if not q:
        raise CheckError("a plane of the member lies on the quadric")
    m = _form3(q)
    pos, neg, zeros = charpoly_signs(m)
    quad = [r[:2] for r in m[:2]]
    quad_zero = all(x.is_zero() for r in quad for x in r)
    if zeros == 0:
        return ("empty",) if pos == 0 or neg == 0 else ("conic",)
    if zeros == 1:
        # kernel: the cross product of two independent rows
        ker = None
        for i, j in ((0, 1), (0, 2), (1, 2)):
            c = cross(m[i], m[j])
            if not all(x.is_zero() for x in c):
                ker = c
                break
        if pos == 0 or neg == 0:  # a real point (two conjugate lines)
            if ker[2].is_zero():
                return ("empty",)
            s, t = ker[0] / ker[2], ker[1] / ker[2]
            return ("point", [o[i] + s * u[i] + t * v[i] for i in range(3)])
        return ("lines", 1 if quad_zero else 2)
    if zeros == 2:  # a double line, or the line at infinity twice
        return ("empty",) if quad_zero else ("lines", 1)
    raise CheckError("a plane of the member lies on the quadric")


def in_plane(c, n, off, parse_point, parse_value):
    """Whether a listed component lies in the plane n·P = off."""
    t = c.get("type")
    if t == "conic":
        pl = c.get("plane") or {}
        cn = parse_point(pl.get("normal"), "normal")
        co = parse_value(pl.get("offset"), "offset")
        return all(x.is_zero() for x in cross(cn, n)) and all((co * n[i] - off * cn[i]).is_zero() for i in range(3))
    if t == "line":
        p, d = parse_point(c.get("point"), "point"), parse_point(c.get("direction"), "direction")
        return (dot(n, p) - off).is_zero() and dot(n, d).is_zero()
    if t == "point":
        p = parse_point(c.get("point"), "point")
        return (dot(n, p) - off).is_zero()
    return False


def _on_listed(p, comps, parse_point, parse_value):
    """Whether the point p lies on a listed line, or in a listed conic's
    plane (a conic listed is the whole section of its plane, checked)."""
    for c in comps:
        if c.get("type") == "line":
            q, d = parse_point(c.get("point"), "point"), parse_point(c.get("direction"), "direction")
            if all(x.is_zero() for x in cross([a - b for a, b in zip(p, q)], d)):
                return True
        elif c.get("type") == "conic":
            pl = c.get("plane") or {}
            n, off = parse_point(pl.get("normal"), "normal"), parse_value(pl.get("offset"), "offset")
            if (dot(n, p) - off).is_zero():
                return True
    return False


def check_sections(eq, planes, comps, parse_point, parse_value):
    """Every plane's section of eq is exactly the components listed in it,
    and every component lies in one of the planes."""
    used = [False] * len(comps)
    for n, off in planes:
        sec = section(eq, n, off)
        inside = [j for j, c in enumerate(comps) if in_plane(c, n, off, parse_point, parse_value)]
        for j in inside:
            used[j] = True
        kinds = [comps[j].get("type") for j in inside]
        what = f"the section by the plane {[str(x) for x in n]}·P = {off}"
        if sec[0] == "empty" and inside:
            raise CheckError(f"{what} is empty but components are listed in it")
        if sec[0] == "conic" and kinds != ["conic"]:
            raise CheckError(f"{what} is a real conic, listed as {kinds}")
        if sec[0] == "point" and not kinds and _on_listed(sec[1], comps, parse_point, parse_value):
            continue  # a common vertex, on lines (or a conic) of another plane
        if sec[0] == "point":
            if kinds != ["point"]:
                raise CheckError(f"{what} is one real point, listed as {kinds}")
            p = parse_point(comps[inside[0]].get("point"), "point")
            if not all((x - y).is_zero() for x, y in zip(p, sec[1])):
                raise CheckError(f"{what}: the listed point is not its real point")
        if sec[0] == "lines":
            if kinds != ["line"] * sec[1]:
                raise CheckError(f"{what} is {sec[1]} real line(s), listed as {kinds}")
            if sec[1] == 2:
                l1, l2 = (comps[j] for j in inside)
                p1, d1 = parse_point(l1["point"], "point"), parse_point(l1["direction"], "direction")
                p2, d2 = parse_point(l2["point"], "point"), parse_point(l2["direction"], "direction")
                diff = [x - y for x, y in zip(p2, p1)]
                if all(x.is_zero() for x in cross(d1, d2)) and all(x.is_zero() for x in cross(d1, diff)):
                    raise CheckError(f"{what}: the same line listed twice")
    if not all(used):
        raise CheckError("a listed component lies in none of the member's planes")


def det_poly(ma, mb, n=4):
    """Ascending coefficients of det(ma − t·mb) on the leading n×n blocks (a
    polynomial of degree ≤ n), interpolated from its values at t = 0, …, n."""
    from .kernel import _det

    return _interpolate([_det([[ma[i][j] - t * mb[i][j] for j in range(n)] for i in range(n)]) for t in range(n + 1)])


def real_roots(f):
    """(q, its Sturm sequence, intervals (lo, hi] each holding exactly one
    root of q) for the square-free part q of f (no intervals for a
    constant), inside a Cauchy bound."""
    if len(f) < 2:
        return f, [], []
    sqf = P.u_divmod(f, P.u_gcd(f, P.u_deriv(f)))[0]
    seq = P.sturm_sequence(sqf)
    bound = 1 + max(abs(c / sqf[-1]) for c in sqf[:-1])
    return sqf, seq, _isolate(seq, -bound, bound)


def rational_roots(f):
    """The rational roots of f (ascending Fractions) among its real roots:
    each real root is isolated (Sturm), narrowed by bisection, and its
    simplest nearby fraction kept if it is an exact root."""
    sqf, seq, intervals = real_roots(f)
    out = []
    for lo, hi in intervals:  # one root in (lo, hi]; lo may be the root below
        for _ in range(200):
            if P.u_eval(sqf, hi) == 0:
                break
            mid = (lo + hi) / 2
            if P.sturm_count(seq, lo, mid) == 1:
                hi = mid
            else:
                lo = mid
        for cand in (hi, ((lo + hi) / 2).limit_denominator(10**40)):
            if P.u_eval(sqf, cand) == 0 and cand not in out:
                out.append(cand)
                break
    return out


def definite_member(a, b):
    """A rational t with A − tB definite (as a form in (x, y, z, 1)), or
    None when no member of the pencil is definite: one candidate strictly
    inside each gap between the real roots of det(A − tB) and beyond them
    (complete: definiteness can only change at a root)."""
    from .sweep import _between, isolated_roots
    from .tangent import _ldl_signs

    ma, mb = P.form_matrix(a), P.form_matrix(b)
    roots = isolated_roots(det_poly(ma, mb))
    # the inertia of A − tB is constant between consecutive roots: one
    # rational strictly inside each gap, and one beyond each end
    cands = [roots[0].lo - 1, roots[-1].hi + 1] + [_between(r, s) for r, s in zip(roots, roots[1:])] if roots else [Fraction(0)]
    for t in cands:
        s = _ldl_signs([[ma[i][j] - t * mb[i][j] for j in range(4)] for i in range(4)])
        if s is not None and 0 not in s and len(set(s)) == 1:
            return t
    return None


def _isolate(seq, lo, hi):
    """Intervals [l, h] each holding exactly one root, by bisection."""
    n = P.sturm_count(seq, lo, hi)
    if n == 0:
        return []
    if n == 1:
        return [(lo, hi)]
    mid = (lo + hi) / 2
    return _isolate(seq, lo, mid) + _isolate(seq, mid, hi)


def _interpolate(values):
    """Ascending coefficients of the polynomial through (k, values[k])."""
    n = len(values)
    diffs, coef = list(values), []
    for k in range(n):
        coef.append(diffs[0])
        diffs = [(diffs[i + 1] - diffs[i]) / (k + 1) for i in range(len(diffs) - 1)]
    out = [Fraction(0)] * n
    basis = [Fraction(1)]
    for k, c in enumerate(coef):
        for i, x in enumerate(basis):
            out[i] += c * x
        basis = [Fraction(0)] + basis
        for i in range(len(basis) - 1):
            basis[i] -= k * basis[i + 1]
    return P.u_trim(out)


def _form_eval(m, u, v):
    return sum((m[i][j] * u[i] * v[j] for i in range(4) for j in range(4)), QS(0))


def singular_member_points(a, b):
    """The real points of A ∩ B from a semidefinite singular member A − t₀B
    (t₀ a multiple root of det(A − tB), rational or in Q(√d)).  A ∩ B lies
    in the real zeros of every member; a semidefinite form vanishes exactly
    on its kernel: rank 3 — one projective point; rank 2 — a projective
    line, on which A is a quadratic in one parameter (its real roots, then
    kept if B vanishes there too).  Returns the real affine points (exact),
    or None when there is no such member."""
    from .kernel import _yun

    ma, mb = P.form_matrix(a), P.form_matrix(b)
    f = det_poly(ma, mb)
    if len(f) < 3:
        return None
    roots = []
    for g, k in _yun(f):
        if k < 2:
            continue
        if len(g) == 2:
            roots.append(QS(-g[0] / g[1]))
        elif len(g) == 3:
            c, bb, aa = g
            disc = bb * bb - 4 * aa * c
            if disc >= 0:
                num, den = disc.numerator * disc.denominator, disc.denominator
                for sgn in (1, -1):
                    roots.append(QS(-bb / (2 * aa), Fraction(sgn, 2 * aa * den), num))
    for t0 in roots:
        m = [[ma[i][j] - t0 * mb[i][j] for j in range(4)] for i in range(4)]
        pos, neg, zeros = charpoly_signs(m)
        if pos and neg or zeros not in (1, 2):
            continue
        ker = kernel(m, 4)
        if len(ker) != zeros:
            continue
        affine = lambda v: [v[i] / v[3] for i in range(3)]  # noqa: E731
        on_both = lambda v: _form_eval(ma, v, v).is_zero() and _form_eval(mb, v, v).is_zero()  # noqa: E731
        if zeros == 1:
            k = ker[0]
            return [affine(k)] if not k[3].is_zero() and on_both(k) else []
        # the kernel line k1 + s·k2 (and k2): A there is α + 2βs + γs²
        k1, k2 = ker
        al, be, ga = _form_eval(ma, k1, k1), _form_eval(ma, k1, k2), _form_eval(ma, k2, k2)
        if al.is_zero() and be.is_zero() and ga.is_zero():
            return None  # the line lies on A: not a points certificate
        cand = [k2] if ga.is_zero() else []  # the point at s = ∞
        if ga.is_zero() and not be.is_zero():
            cand.append([k1[i] + (-al / (be * QS(2))) * k2[i] for i in range(4)])
        elif not ga.is_zero():
            disc = be * be - al * ga
            if disc.is_zero():
                cand.append([k1[i] + (-be / ga) * k2[i] for i in range(4)])
            elif disc.sign() > 0:
                if disc.b:
                    return None  # nested radicals: beyond this checker
                sq = sqrt_rational(disc.a)
                cand += [[k1[i] + ((-be + sq * sgn) / ga) * k2[i] for i in range(4)] for sgn in (1, -1)]
        pts = []
        for c in cand:
            if not c[3].is_zero() and on_both(c):
                pts.append(affine(c))
        return pts
    return None
