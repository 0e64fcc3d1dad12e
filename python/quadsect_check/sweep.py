"""The topology of a ``curve`` answer, re-derived by a sweep over the
rulings of one quadric (a cylinder or a cone, R) against the other (Q).

**Rulings.**  With the axis k of R and e₁ = k × m, e₂ = k × e₁ (m a small
integer vector), every ruling of R is met once as (u, v) runs over the
ellipse Γ: α·u² + β·v² = γ, and t over the whole line:

* cylinder (point P, r2): X = P + u·e₁ + v·e₂ + t·k, (α, β, γ) = (|e₁|², |e₂|², r2);
* cone (vertex V, t2):    X = V + t·(k + u·e₁ + v·e₂), (α, β, γ) = (|e₁|², |e₂|², |k|²·t2)
  (w·k = |k|² ≠ 0 for every ruling direction w, as the half-angle is below 90°).

Q along a ruling is a·t² + 2b·t + c with a, b, c polynomials in (u, v);
the curve's points on the ruling are its real roots.  With D = b² − ac:

* a ≢ 0 on Γ: two points where D > 0, none where D < 0.  At a zero of D of
  multiplicity m along Γ the two points meet: a fold (m = 1), a crossing
  (m = 2, D ≥ 0 around), an isolated point (m even, D ≤ 0 around), a cusp
  (m = 3), a tacnode (m ≥ 4 even, D ≥ 0) — the curve Q(X(s, t)) = 0 is
  singular exactly where D and its derivative along Γ vanish.  At a zero
  of a (there D = b² > 0 is required) the root (−b ± √D)/a with ± = sign b
  stays finite (→ −c/2b) and continues; the other escapes to infinity: an
  end of an unbounded component.
* a ≡ 0 on Γ: one point t = −c/2b where b ≠ 0, escaping at the zeros of b
  (c ≠ 0 there is required).
* the cone's vertex V on Q (c = 0): besides V, one point t = −2b/a per
  ruling, escaping at the zeros of a and passing through V at the zeros of
  b (``_through_vertex``).

Each branch of the answer (a ruling of R and a root on it) is located on
the sweep — its ruling is a point of Γ, exact in Q(√d), placed among the
events, and its root is the upper or lower one — so that the branches can
be shown to lie on different components.

The events (zeros on Γ) are found exactly: f = f₀(u) + f₁(u)·v modulo Γ
vanishes on Γ at the real roots of N(u) = f₀² − f₁²·(γ − αu²)/β with
v = −f₀/f₁ (real, so the point is on Γ) — once the frame is such that f₁
and N share no root and no root sits at u = ±√(γ/α), which is checked (a
few frames are tried).  Multiplicities come from Yun's square-free
decomposition of N, the order along Γ from isolating intervals, and the
signs of D and a on each arc from a rational sample point of the arc (exact
in Q(√w)).  The pieces are joined with union–find.

Anything outside these cases (a ruling on both quadrics, D ≡ 0 on Γ, a
zero of a where b = 0, a branch on an event's ruling) raises
``NotChecked``; ``common_vertex_lines`` counts the lines of two cones
sharing their vertex.
"""

from fractions import Fraction
from functools import cmp_to_key

from . import poly as P
from .exact import QS, CheckError, NotChecked, cross, dot
from .kernel import _yun
from .pencil import _interpolate, _isolate, det_poly

FRAMES = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 2, 3), (2, -3, 1), (3, 1, -2), (1, -5, 2), (4, 1, 3)]


# ---- bivariate polynomials in (u, v): dicts {(i, j): Fraction} ------------


def _bmul(p, q):
    r = {}
    for (i1, j1), c1 in p.items():
        for (i2, j2), c2 in q.items():
            k = (i1 + i2, j1 + j2)
            r[k] = r.get(k, 0) + c1 * c2
    return {k: c for k, c in r.items() if c}


def _badd(p, q, s=1):
    r = dict(p)
    for k, c in q.items():
        r[k] = r.get(k, 0) + s * c
    return {k: c for k, c in r.items() if c}


def _uadd(a, b):
    n = max(len(a), len(b))
    return P.u_trim([(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)])


def _umul(a, b):
    r = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return P.u_trim(r)


class _Ruled:
    """The sweep for one frame: the restriction of Q to R's rulings."""

    def __init__(self, kind, base, k, param, q, m):
        e1 = cross(k, m)
        e2 = cross(k, e1)
        n1, n2, kk = (sum(c * c for c in v) for v in (e1, e2, k))
        self.al, self.be = n1, n2
        self.kind, self.base, self.k, self.e1, self.e2 = kind, base, k, e1, e2
        self.ga = param if kind == "cylinder" else kk * param
        # Q at base + t·k + s₁·e₁ + s₂·e₂; for the cone s_i = t·u, t·v
        sub = P.substitute_affine(q, [[QS(c)] for c in base], [[QS(k[i]), QS(e1[i]), QS(e2[i])] for i in range(3)])
        coef = [{}, {}, {}]
        for (et, i, j), c in sub.items():
            deg = et if kind == "cylinder" else et + i + j
            if deg > 2:
                raise CheckError("not a quadric")
            coef[deg][(i, j)] = coef[deg].get((i, j), 0) + c.a
        self.a, self.c = coef[2], coef[0]
        self.b = {key: c / 2 for key, c in coef[1].items()}
        self.w = [self.ga / self.be, Fraction(0), -self.al / self.be]  # v² on Γ

    def reduce(self, f):
        """f = f₀(u) + f₁(u)·v on Γ."""
        parts = [[Fraction(0)], [Fraction(0)]]
        for (i, j), c in f.items():
            t = [Fraction(0)] * i + [c]
            for _ in range(j // 2):
                t = _umul(t, self.w)
            parts[j % 2] = _uadd(parts[j % 2], t)
        return parts

    def norm(self, f0, f1):
        return _uadd(_umul(f0, f0), [-x for x in _umul(_umul(f1, f1), self.w)])


class _Root:
    """A real root of the square-free G, in (lo, hi] or exact."""

    def __init__(self, g, seq, lo, hi):
        self.g, self.seq, self.lo, self.hi = g, seq, lo, hi
        self.exact = P.u_eval(g, hi) == 0
        if self.exact:
            self.lo = hi

    def refine(self):
        if self.exact:
            return
        mid = (self.lo + self.hi) / 2
        if P.u_eval(self.g, mid) == 0:
            self.lo = self.hi = mid
            self.exact = True
        elif P.sturm_count(self.seq, self.lo, mid) == 1:
            self.hi = mid
        else:
            self.lo = mid

    def sign_of(self, h):
        """The sign of the polynomial h at this root."""
        h = P.u_trim(h)
        if self.exact:
            v = P.u_eval(h, self.hi)
            return (v > 0) - (v < 0)
        if h == [0]:
            return 0
        g = P.u_gcd(self.g, h)
        if len(g) > 1 and P.sturm_count(P.sturm_sequence(g), self.lo, self.hi) == 1:
            return 0
        sq = P.u_divmod(h, P.u_gcd(h, P.u_deriv(h)))[0]
        seq = P.sturm_sequence(sq) if len(sq) > 1 else None
        while seq and P.sturm_count(seq, self.lo, self.hi) and not self.exact:
            self.refine()
        v = P.u_eval(h, self.hi)
        return (v > 0) - (v < 0)


def isolated_roots(f):
    """The distinct real roots of f as ``_Root``s, ascending."""
    from .pencil import real_roots

    sqf, seq, intervals = real_roots(f)
    return [_Root(sqf, seq, lo, hi) for lo, hi in intervals]


def _compare(r, s):
    """−1, 0, 1 as the root r is below, equal to or above the root s."""
    if r.exact or s.exact:
        return -_cmp_root(s, QS(r.hi)) if r.exact else _cmp_root(r, QS(s.hi))
    if r.g is s.g:
        return (r.hi > s.hi) - (r.hi < s.hi)
    h = P.u_gcd(r.g, s.g)
    both = len(h) > 1 and r.sign_of(h) == 0 and s.sign_of(h) == 0
    hseq = P.sturm_sequence(h) if both else None
    while not (r.hi < s.lo or s.hi < r.lo):
        # both roots of h, in one interval holding a single root of h: equal
        if both and P.sturm_count(hseq, min(r.lo, s.lo), max(r.hi, s.hi)) == 1:
            return 0
        r.refine()
        s.refine()
        if r.exact or s.exact:
            return _compare(r, s)
    return -1 if r.hi < s.lo else 1


def _between(r, s):
    """A rational strictly between the roots r < s."""
    while not r.hi < s.lo:
        r.refine()
        s.refine()
    return (r.hi + s.lo) / 2


def _toward_turn(r, side, al, ga):
    """A rational strictly between the root r and the turn side·√(γ/α)."""

    def inside(x):
        return side * x <= 0 or al * x * x < ga

    while not inside(r.hi if side > 0 else r.lo):
        r.refine()
    near, far = (r.hi if side > 0 else r.lo), side * max(Fraction(1), ga / al)
    while True:
        mid = (near + far) / 2
        if inside(mid):
            return mid
        far = mid


def _frame(kind, base, k, param, q, vertex):
    for m in FRAMES:
        if all(x == 0 for x in cross(k, m)):
            continue
        sw = _Ruled(kind, base, k, param, q, m)
        a0, a1 = sw.reduce(sw.a)
        linear = a0 == [0] and a1 == [0]
        mode = "vertex" if vertex else "linear" if linear else "quadratic"
        if vertex and linear:
            raise NotChecked("the vertex on the other quadric and a ≡ 0 on Γ")
        if vertex:
            fs = {"a": sw.a, "b": sw.b}
        elif linear:
            fs = {"b": sw.b}
        else:
            fs = {"a": sw.a, "D": _badd(_bmul(sw.b, sw.b), _bmul(sw.a, sw.c), -1)}
        red = {n: sw.reduce(f) for n, f in fs.items()}
        norms = {n: sw.norm(*red[n]) for n in fs}
        if norms.get("D") == [0]:
            raise NotChecked("the rulings are tangent to the other quadric all along (D ≡ 0 on Γ)")
        if norms.get("b") == [0]:
            raise NotChecked("a ruling family with no curve point (b ≡ 0 on Γ)")
        turn = [-sw.ga, Fraction(0), sw.al]
        ok = all(len(P.u_gcd(norms[n], red[n][1])) == 1 and len(P.u_gcd(norms[n], turn)) == 1 for n in fs if len(norms[n]) > 1)
        if ok:
            return sw, mode, red, norms
    raise NotChecked("no frame separates the events of the sweep")


def curve_topology(kind, base, k, param, q, branches=()):
    """The curve R ∩ Q by the sweep: (number of one-dimensional real
    components, sorted list of their ``bounded`` flags, sorted list of the
    singular points' (kind, isolated), and for each of the answer's
    ``branches`` (its ruling on R) the component its point lies on, as
    (component key, bounded))."""
    vertex = kind == "cone" and P.evaluate(q, [QS(c) for c in base]).is_zero()
    sw, mode, red, norms = _frame(kind, base, k, param, q, vertex)
    linear = mode == "linear"
    # the roots of each square-free factor, isolated in (−B, B] ∋ ±√(γ/α)
    bound = max(Fraction(1), sw.ga / sw.al)
    found = []
    for n in red:
        if len(norms[n]) > 1:
            for g, mult in _yun(norms[n]):
                seq = P.sturm_sequence(g)
                found += [(_Root(g, seq, lo, hi), n, mult) for lo, hi in _isolate(seq, -bound, bound)]
    found.sort(key=cmp_to_key(lambda x, y: _compare(x[0], y[0])))
    # events: (position, sheet) → {name: multiplicity}; roots[position]
    roots, events = [], {}
    for r, n, mult in found:
        if not roots or _compare(roots[-1], r):
            roots.append(r)
        f0, f1 = red[n]
        sheet = -r.sign_of(f0) * r.sign_of(f1)
        if sheet == 0:
            raise NotChecked("an event at the turn of the ruling ellipse")
        events.setdefault((len(roots) - 1, sheet), {})[n] = mult
    order = sorted((key for key in events if key[1] > 0), key=lambda e: e[0])
    order += sorted((key for key in events if key[1] < 0), key=lambda e: -e[0])

    def value_sign(f, u, sheet):
        f0, f1 = red[f] if f in red else sw.reduce(getattr(sw, f))
        w = P.u_eval(sw.w, u)
        return QS(P.u_eval(f0, u), sheet * P.u_eval(f1, u) / w.denominator, w.numerator * w.denominator).sign()

    def sample(i):
        """A rational point (u, sheet) just after event i on its sheet."""
        idx, sheet = order[i]
        if sheet > 0:
            return (_between(roots[idx], roots[idx + 1]) if idx + 1 < len(roots) else _toward_turn(roots[idx], 1, sw.al, sw.ga)), 1
        return (_between(roots[idx - 1], roots[idx]) if idx > 0 else _toward_turn(roots[idx], -1, sw.al, sw.ga)), -1

    n_ev = len(order)
    samples = [sample(i) for i in range(n_ev)] or [(Fraction(0), 1)]
    if mode == "vertex":
        n, bounded, singular, find, unbounded = _through_vertex(order, events, len(samples))
        located = [_locate(b, sw, mode, roots, order, events, None) for b in branches]
        return n, bounded, singular, [(find(x), find(x) not in unbounded) for x in located]
    key = "b" if linear else "D"
    s_main = [value_sign(key, u, sh) for u, sh in samples]
    s_a = [0] * len(samples) if linear else [value_sign("a", u, sh) for u, sh in samples]
    parent = {}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    def union(x, y):
        parent[find(x)] = find(y)

    nodes = [(i, h) for i in range(len(samples)) for h in ((0,) if linear else (0, 1)) if linear or s_main[i] > 0]
    for x in nodes:
        parent[x] = x
    ends, singular = set(), []
    for i, ev in enumerate(order):
        prev, nxt = (i - 1) % n_ev, i
        kinds = events[ev]
        if len(kinds) > 1:
            raise NotChecked("a zero of a where D = 0 (b = 0): a ruling asymptotic to the other quadric")
        (name, mult), = kinds.items()
        if linear:
            r = roots[ev[0]]
            c0, c1 = sw.reduce(sw.c)
            f0, f1 = red["b"]
            if r.sign_of(_uadd(_umul(c0, f1), [-x for x in _umul(c1, f0)])) == 0:
                raise NotChecked("a ruling on both quadrics")
            ends.update({(prev, 0), (nxt, 0)})
        elif name == "D":
            sp, sn = s_main[prev], s_main[nxt]
            if sp > 0 and sn > 0:
                for x in ((prev, 1), (nxt, 0), (nxt, 1)):
                    union((prev, 0), x)
                singular.append(("crossing" if mult == 2 else "tacnode", False))
            elif sp < 0 and sn < 0:
                singular.append(("acnode", True))
            else:
                side = prev if sp > 0 else nxt
                union((side, 0), (side, 1))
                if mult >= 3:
                    singular.append(("cusp", False))
        else:
            if s_main[prev] <= 0 or s_main[nxt] <= 0:
                raise NotChecked("D ≤ 0 beside a zero of a")
            r = roots[ev[0]]
            f0, f1 = red["a"]
            b0, b1 = sw.reduce(sw.b)
            sb = r.sign_of(_uadd(_umul(b0, f1), [-x for x in _umul(b1, f0)])) * r.sign_of(f1)
            if sb == 0:
                raise NotChecked("a ruling asymptotic to the other quadric")
            fin = [1 if sb * s_a[j] > 0 else 0 for j in (prev, nxt)]
            union((prev, fin[0]), (nxt, fin[1]))
            ends.update({(prev, 1 - fin[0]), (nxt, 1 - fin[1])})
    comps = {find(x) for x in nodes}
    unbounded = {find(x) for x in ends if x in parent}
    bounded = sorted(c not in unbounded for c in comps)
    located = [_locate(b, sw, mode, roots, order, events, s_main) for b in branches]
    if any(x not in parent for x in located):
        raise CheckError("a branch point on an arc of the sweep without real points")
    return len(comps), bounded, sorted(singular), [(find(x), find(x) not in unbounded) for x in located]


def _cmp_root(r, x):
    """The sign of (root r) − x for x in Q(√d)."""
    while True:
        if r.exact:
            return (QS(r.hi) - x).sign()
        if (x - r.lo).sign() <= 0:
            return 1
        if (x - r.hi).sign() >= 0:
            return -1
        if P.u_eval(r.g, x).is_zero():
            return 0
        r.refine()


def _bval(f, u, v):
    return sum((QS(c) * _qpow(u, i) * _qpow(v, j) for (i, j), c in f.items()), QS(0))


def _qpow(x, n):
    out = QS(1)
    for _ in range(n):
        out = out * x
    return out


def _locate(branch, sw, mode, roots, order, events, s_main):
    """The sweep's node (arc, sheet) — or ``"V"`` — holding a branch's
    point: its ruling (point r, direction d, on R) is the ruling (u, v) of
    Γ, and the engine's parameter t on it is t₀ + s·t in the sweep's."""
    from .exact import parse_point, parse_value

    ru, al = branch.get("ruling") or {}, branch.get("along_ruling") or {}
    r, d = parse_point(ru.get("point"), "ruling point"), parse_point(ru.get("direction"), "ruling direction")
    k, kk = [QS(c) for c in sw.k], QS(sum(c * c for c in sw.k))
    base = [QS(c) for c in sw.base]
    rel = [x - y for x, y in zip(r, base)]
    s = dot(d, k) / kk
    if s.is_zero():
        raise NotChecked("a branch's ruling is not a ruling of the swept quadric")
    if sw.kind == "cylinder":
        w = k
        u, v = dot(rel, [QS(c) for c in sw.e1]) / QS(sw.al), dot(rel, [QS(c) for c in sw.e2]) / QS(sw.be)
    else:
        w = [x / s for x in d]
        u, v = dot(w, [QS(c) for c in sw.e1]) / QS(sw.al), dot(w, [QS(c) for c in sw.e2]) / QS(sw.be)
    t0 = dot(rel, k) / kk
    x0 = [base[i] + (u * sw.e1[i] + v * sw.e2[i] if sw.kind == "cylinder" else QS(0)) for i in range(3)]
    if any(not (a - b * s).is_zero() for a, b in zip(d, w)) or any(
        not (a - b - t0 * c).is_zero() for a, b, c in zip(r, x0, w)
    ) or not (u * u * sw.al + v * v * sw.be - sw.ga).is_zero():
        raise NotChecked("a branch's ruling is not a ruling of the swept quadric")
    sheet, turn = v.sign(), u.sign()
    # the arc: after the last event before (u, sheet) in the cyclic order
    def place(ev):  # −1: the event comes before the point, 0: at it, 1: after
        idx, sh = ev
        if sheet == 0:  # at the turn (±√(γ/α), 0): after the upper sheet's events for +, before all for −
            return -1 if turn > 0 and sh > 0 else 1
        if sh != sheet:
            return -1 if sh > 0 else 1
        c = _cmp_root(roots[idx], u)
        return c * sheet

    arc, at = max(len(order) - 1, 0), None
    for i, ev in enumerate(order):
        p = place(ev)
        if p == 0:
            at = i
        if p >= 0:
            break
        arc = i
    te = al.get("t")
    tm = None if te is None else t0 + s * parse_value(te, "t")
    if at is not None:
        (name, _), = events[order[at]].items()
        prev = (at - 1) % len(order)
        if mode == "vertex" and name == "b" and tm is not None and tm.is_zero():
            return "V"
        if mode == "quadratic" and name == "D":
            return (prev if s_main[prev] > 0 else at, 0)
        raise NotChecked("a branch point on an event's ruling")
    if mode == "linear":
        return (arc, 0)
    if mode == "vertex":
        return "V" if tm is not None and tm.is_zero() else arc
    if tm is not None:
        a, b = _bval(sw.a, u, v), _bval(sw.b, u, v)
        hi = (tm * a + b).sign() * a.sign()
    else:
        hi = int(al.get("root", 0)) * parse_value(al.get("a"), "a").sign() * s.sign()
    if hi == 0:
        raise NotChecked("a branch point at a double root")
    return (arc, 1 if hi > 0 else 0)


def _through_vertex(order, events, n_arcs):
    """The vertex V of the cone on Q (c = 0): on each ruling t = 0 (the
    point V) and t = −2b/a, one point per arc, escaping at the zeros of a
    and passing through V at the zeros of b.  V is a singular point of the
    curve: isolated (no zero of b), a crossing (two simple zeros: two
    branches through V) or a cusp (one double zero: the tangent plane of Q
    at V touches the cone along a ruling)."""
    parent = {x: x for x in list(range(n_arcs)) + ["V"]}

    def find(x):
        while parent[x] != x:
            x = parent[x]
        return x

    ends, through = set(), []
    for i, ev in enumerate(order):
        prev, nxt = (i - 1) % len(order), i
        if len(events[ev]) > 1:
            raise NotChecked("a ruling on both quadrics")
        (name, mult), = events[ev].items()
        if name == "a":
            ends.update({prev, nxt})
        else:
            for x in (prev, nxt):
                parent[find(x)] = find("V")
            through.append(mult)
    kind = {(): ("acnode", True), (1, 1): ("crossing", False), (2,): ("cusp", False)}.get(tuple(sorted(through)))
    if kind is None:
        raise NotChecked(f"the curve passes through the vertex with multiplicities {through}")
    comps = {find(x) for x in range(n_arcs)}
    unbounded = {find(x) for x in ends}
    return len(comps), sorted(c not in unbounded for c in comps), [kind], find, unbounded


def rank_two_free(ma, mb):
    """No member λA + μB of the pencil has rank ≤ 2 (over C): gcd of
    det(A − tB) and all 3×3 minors of A − tB is 1, and B has rank ≥ 3.  A
    conic on both quadrics would make one (the member vanishing on its
    plane: A and B restricted to the plane are proportional)."""
    f = det_poly(ma, mb)
    if f == [0]:
        raise NotChecked("a singular pencil (det(A − tB) ≡ 0)")
    from .kernel import _det

    # rank ≤ 2 at t₀ makes t₀ a multiple root of det(A − tB) (and rank B ≤ 2
    # lowers its degree by two): only the multiple roots need the minors
    g = P.u_gcd(f, P.u_deriv(f)) if len(f) > 1 else [Fraction(1)]
    if len(g) > 1 and len(minors_gcd(ma, mb, g)) > 1:
        return False
    return any(_det([[mb[i][j] for j in cols] for i in rows]) != 0 for rows in _triples() for cols in _triples())


def minors_gcd(ma, mb, g=(0,)):
    """gcd of g and all 3×3 minors of A − tB (polynomials of degree ≤ 3 in
    t, interpolated): its roots are the t where A − tB has rank ≤ 2."""
    from .kernel import _det

    g = list(g)
    for rows in _triples():
        for cols in _triples():
            g = P.u_gcd(g, _interpolate([_det([[ma[i][j] - t * mb[i][j] for j in cols] for i in rows]) for t in range(4)]))
            if g == [1]:
                return g
    return g


def _triples():
    return [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]


def common_vertex_lines(kind, base, k, param, q):
    """Two cones with a common vertex V (Q singular at V): on the ruling
    V + t·w of R, Q is a(w)·t², so A ∩ B is V and the rulings where a = 0 —
    as many real lines as distinct zeros of a on Γ (a ≢ 0 on Γ, else the
    cones coincide).  Returns that number."""
    base_q = [QS(c) for c in base]
    if kind != "cone" or not P.evaluate(q, base_q).is_zero() or any(
        not P.evaluate(g, base_q).is_zero() for g in P.gradient(q)
    ):
        raise NotChecked("not two cones with a common vertex")
    for m in FRAMES:
        if all(x == 0 for x in cross(k, m)):
            continue
        sw = _Ruled(kind, base, k, param, q, m)
        a0, a1 = sw.reduce(sw.a)
        norm = sw.norm(a0, a1)
        if norm == [0]:
            raise NotChecked("a ≡ 0 on Γ")
        if len(norm) == 1:
            return 0
        if len(P.u_gcd(norm, a1)) == 1 and len(P.u_gcd(norm, [-sw.ga, Fraction(0), sw.al])) == 1:
            # each real root of the norm is one point of Γ (v = −a₀/a₁)
            sqf = P.u_divmod(norm, P.u_gcd(norm, P.u_deriv(norm)))[0]
            bound = max(Fraction(1), sw.ga / sw.al)
            return len(_isolate(P.sturm_sequence(sqf), -bound, bound))
    raise NotChecked("no frame separates the zeros of a")
