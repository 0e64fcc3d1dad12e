"""Polynomials in x, y, z (and u) with rational coefficients: the
request's expressions, parsed by this package's own reader, and the few
operations the checks need.

A polynomial is a dict ``{(ex, ey, ez, eu): Fraction}`` without zero
coefficients.  Grammar of expressions (contract §1)::

    expr    := term (('+' | '-') term)*
    term    := unary (('*' | '/') unary | implicit)*      implicit: 2x, 3(x-1), x y
    unary   := ('+' | '-') unary | power
    power   := primary ('^' integer)?
    primary := number | x | y | z | u | '(' expr ')'
"""

from fractions import Fraction

from .exact import CheckError, QS, nearest_double, scan_number

VARS = "xyzu"
ZERO_EXP = (0, 0, 0, 0)


def const(c):
    c = Fraction(c)
    return {ZERO_EXP: c} if c else {}


def var(i):
    e = [0, 0, 0, 0]
    e[i] = 1
    return {tuple(e): Fraction(1)}


def add(p, q, s=1):
    r = dict(p)
    for e, c in q.items():
        v = r.get(e, 0) + s * c
        if v:
            r[e] = v
        else:
            r.pop(e, None)
    return r


def mul(p, q):
    r = {}
    for e1, c1 in p.items():
        for e2, c2 in q.items():
            e = (e1[0] + e2[0], e1[1] + e2[1], e1[2] + e2[2], e1[3] + e2[3])
            v = r.get(e, 0) + c1 * c2
            if v:
                r[e] = v
            else:
                r.pop(e, None)
    return r


def scale(p, c):
    return {e: c * v for e, v in p.items()} if c else {}


def power(p, n):
    r, b = const(1), p
    while n:
        if n & 1:
            r = mul(r, b)
        n >>= 1
        if n:
            b = mul(b, b)
    return r


def gradient(p):
    """The three partial derivatives of p in x, y, z."""
    out = []
    for i in range(3):
        g = {}
        for e, c in p.items():
            if e[i]:
                f = list(e)
                f[i] -= 1
                g[tuple(f)] = c * e[i]
        out.append(g)
    return out


def degree(p):
    return max((sum(e) for e in p), default=-1)


def deg_in(p, i):
    return max((e[i] for e in p), default=-1)


class _Parser:
    MAX_DEGREE = 10_000

    def __init__(self, text, float_mode):
        self.s, self.i, self.float_mode, self.depth = text, 0, float_mode, 0

    def error(self, msg):
        raise CheckError(f"{msg} at column {self.i + 1} of {self.s[:60]!r}")

    def peek(self):
        while self.i < len(self.s) and self.s[self.i].isspace():
            self.i += 1
        return self.s[self.i] if self.i < len(self.s) else ""

    def parse(self):
        p = self.expr()
        if self.peek():
            self.error(f"unexpected {self.peek()!r}")
        return p

    def expr(self):
        p = self.term()
        while self.peek() in ("+", "-") and self.peek():
            s = 1 if self.s[self.i] == "+" else -1
            self.i += 1
            p = add(p, self.term(), s)
        return p

    def term(self):
        p = self.unary()
        while True:
            c = self.peek()
            if c == "*":
                self.i += 1
                p = mul(p, self.unary())
            elif c == "/":
                self.i += 1
                q = self.unary()
                if degree(q) > 0 or not q:
                    self.error("'/' divides only by a non-zero constant")
                p = scale(p, 1 / q[ZERO_EXP])
            elif c and (c in VARS or c == "("):
                p = mul(p, self.power())
            else:
                return p

    def unary(self):
        c = self.peek()
        if c in ("+", "-") and c:
            self.i += 1
            self.depth += 1
            if self.depth > 100:
                self.error("nesting deeper than 100")
            p = self.unary()
            self.depth -= 1
            return p if c == "+" else scale(p, -1)
        return self.power()

    def power(self):
        p = self.primary()
        if self.peek() == "^":
            self.i += 1
            self.peek()
            j = self.i
            while j < len(self.s) and self.s[j].isdigit():
                j += 1
            if j == self.i:
                self.error("'^' needs a non-negative integer")
            n = int(self.s[self.i : j])
            if n * max(degree(p), 0) > self.MAX_DEGREE:
                self.error("degree too large")
            self.i = j
            p = power(p, n)
        return p

    def primary(self):
        c = self.peek()
        if c == "(":
            self.i += 1
            self.depth += 1
            if self.depth > 100:
                self.error("nesting deeper than 100")
            p = self.expr()
            self.depth -= 1
            if self.peek() != ")":
                self.error("expected ')'")
            self.i += 1
            return p
        if c and c in VARS:
            self.i += 1
            return var(VARS.index(c))
        if c and (c.isdigit() or c == "."):
            v, self.i = scan_number(self.s, self.i)
            return const(nearest_double(v) if self.float_mode else v)
        self.error(f"unexpected {c!r}" if c else "unexpected end of input")


def parse(text, float_mode=False):
    """The polynomial an expression denotes (exact; float mode: each literal
    rounded to its nearest double)."""
    if not isinstance(text, str):
        raise CheckError(f"expected an expression (string), got {text!r}")
    return _Parser(text, float_mode).parse()


def evaluate(p, point):
    """``p`` at a point of Q(√d)³ (values ``QS``; u, if present, must not
    occur)."""
    total = QS(0)
    powers = [[QS(1)] for _ in range(3)]
    for e, c in p.items():
        if e[3]:
            raise CheckError("u in a surface equation")
        t = QS(c)
        for i in range(3):
            while len(powers[i]) <= e[i]:
                powers[i].append(powers[i][-1] * point[i])
            t = t * powers[i][e[i]]
        total = total + t
    return total


def substitute_affine(p, const_part, lin_parts):
    """``p`` at the affine point ``c + Σ_k t_k·v_k`` (``const_part[i]`` is
    ``[c_i]``, ``lin_parts[i][k]`` is ``v_k[i]``) as a dict ``{exponent
    tuple of the t_k: QS}``."""
    nt = len(lin_parts[0])
    coords = []
    for i in range(3):
        lin = {(0,) * nt: const_part[i][0]}
        for k in range(nt):
            e = [0] * nt
            e[k] = 1
            lin[tuple(e)] = lin_parts[i][k]
        coords.append(lin)

    def pmul(a, b):
        r = {}
        for e1, c1 in a.items():
            for e2, c2 in b.items():
                e = tuple(x + y for x, y in zip(e1, e2))
                r[e] = r.get(e, QS(0)) + c1 * c2
        return r

    total = {}
    powers = [[{(0,) * nt: QS(1)}] for _ in range(3)]
    for e, c in p.items():
        if e[3]:
            raise CheckError("u in a surface equation")
        t = {(0,) * nt: QS(c)}
        for i in range(3):
            while len(powers[i]) <= e[i]:
                powers[i].append(pmul(powers[i][-1], coords[i]))
            t = pmul(t, powers[i][e[i]])
        for k, v in t.items():
            total[k] = total.get(k, QS(0)) + v
    return {k: v for k, v in total.items() if not v.is_zero()}


def form_matrix(p):
    """The symmetric 4×4 matrix of a polynomial of degree ≤ 2 as a form in
    (x, y, z, 1)."""
    if degree(p) > 2 or any(k[3] for k in p):
        raise CheckError("not a polynomial of degree ≤ 2 in x, y, z")
    m = [[Fraction(0)] * 4 for _ in range(4)]
    for k, c in p.items():
        idx = [i for i in range(3) for _ in range(k[i])] or [3, 3]
        if len(idx) == 1:
            idx = [idx[0], 3]
        i, j = idx
        if i == j:
            m[i][i] += c
        else:
            m[i][j] += c / 2
            m[j][i] += c / 2
    return m


# ---- univariate polynomials: lists of Fractions, ascending -------------


def univariate(p):
    """``p`` as a univariate polynomial (ascending coefficients) in its only
    variable (any of x, y, z, u)."""
    used = {i for e in p for i in range(4) if e[i]}
    if len(used) > 1:
        raise CheckError("expected a univariate polynomial")
    i = used.pop() if used else 0
    out = [Fraction(0)] * (deg_in(p, i) + 1 if p else 1)
    for e, c in p.items():
        out[e[i]] = c
    return u_trim(out)


def u_trim(a):
    a = list(a)
    while len(a) > 1 and a[-1] == 0:
        a.pop()
    return a


def u_eval(a, x):
    r = Fraction(0)
    for c in reversed(a):
        r = r * x + c
    return r


def u_deriv(a):
    return u_trim([i * a[i] for i in range(1, len(a))] or [Fraction(0)])


def u_divmod(a, b):
    a, b = u_trim(a), u_trim(b)
    if b == [0]:
        raise ZeroDivisionError
    q = [Fraction(0)] * max(len(a) - len(b) + 1, 1)
    r = list(a)
    while len(r) >= len(b) and r != [0]:
        k = len(r) - len(b)
        f = r[-1] / b[-1]
        q[k] = f
        for i, c in enumerate(b):
            r[i + k] -= f * c
        r = u_trim(r[:-1]) if len(r) > 1 else [Fraction(0)]
    return u_trim(q), u_trim(r)


def u_gcd(a, b):
    """The monic gcd over Q (Euclid on primitive integer pseudo-remainders:
    the same gcd up to a constant, without the fractions' growth)."""
    a, b = u_trim(a), u_trim(b)
    if b == [0]:
        return [c / a[-1] for c in a] if a != [0] else a
    if a == [0]:
        return [c / b[-1] for c in b]
    x, y = _primitive_int(a), _primitive_int(b)
    if len(x) < len(y):
        x, y = y, x
    while not (len(y) == 1 and y[0] == 0):
        if len(y) == 1:
            return [Fraction(1)]
        r = _prem(x, y)
        x, y = y, (_primitive_int([Fraction(c) for c in r]) if any(r) else [0])
    return [Fraction(c, x[-1]) for c in x]


def _primitive_int(a):
    """a scaled by a positive rational to coprime integers."""
    from math import gcd

    den = 1
    for c in a:
        den = den * c.denominator // gcd(den, c.denominator)
    ints = [int(c * den) for c in a]
    g = 0
    for c in ints:
        g = gcd(g, c)
    return [c // g for c in ints] if g else ints


def _prem(a, b):
    """The pseudo-remainder lc(b)^(deg a − deg b + 1)·a mod b, in integers."""
    r = list(a)
    lb, db = b[-1], len(b) - 1
    for _ in range(len(a) - len(b) + 1):
        if len(r) - 1 < db:
            r = [lb * c for c in r]
            continue
        lr = r[-1]
        r = [lb * c for c in r]
        k = len(r) - 1 - db
        for i, c in enumerate(b):
            r[i + k] -= lr * c
        r.pop()
        while len(r) > 1 and r[-1] == 0:
            r.pop()
    return r


def sturm_sequence(a):
    """A Sturm sequence of a (positive rational multiples of the classical
    one −rem(p_{i−1}, p_i): the signs, hence the counts, are the same),
    computed by pseudo-remainders over Z with the content removed: lists
    of integers."""
    seq = [_primitive_int(u_trim(a)), _primitive_int(u_deriv(a))]
    while len(seq[-1]) > 1 or seq[-1] != [0]:
        a_, b_ = seq[-2], seq[-1]
        if len(b_) == 1 and b_[0] == 0:
            break
        r = _prem(a_, b_)
        if all(c == 0 for c in r):
            break
        # prem = lc(b)^(δ+1)·a − q·b: −rem has the sign of −prem·lc(b)^(δ+1)
        s = -1 if (b_[-1] < 0 and (len(a_) - len(b_) + 1) % 2) else 1
        seq.append([-s * c for c in _primitive_int([Fraction(c) for c in r])])
        if len(seq[-1]) == 1:
            break
    return seq


def _sign_changes(values):
    s = [v for v in values if v != 0]
    return sum(1 for x, y in zip(s, s[1:]) if (x > 0) != (y > 0))


def _signs_at(seq, x):
    if x == "-inf":
        return [c[-1] * (-1) ** (len(c) - 1) for c in seq]
    if x == "+inf":
        return [c[-1] for c in seq]
    x = Fraction(x)
    p, q = x.numerator, x.denominator
    out = []
    for c in seq:  # q^n·c(p/q) in integers (the same sign, q > 0)
        acc, qq = c[-1], 1
        for k in range(len(c) - 2, -1, -1):
            qq *= q
            acc = acc * p + c[k] * qq
        out.append(acc)
    return out


def sturm_count(seq, lo, hi):
    """Distinct real roots of the square-free first member in (lo, hi]
    (Sturm's theorem; ``lo``/``hi`` may be "-inf"/"+inf")."""
    return _sign_changes(_signs_at(seq, lo)) - _sign_changes(_signs_at(seq, hi))
