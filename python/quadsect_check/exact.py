"""Exact numbers: the literals of the request (contract §1) and the field
Q(√d) of the answers' irrational values.

Literals are read exactly as ``Fraction``: integers, decimals (``1.5`` is
3/2), scientific decimals (``2.5e-3``) and hexadecimal literals with a
binary exponent (``0x1.8p3`` is 12).  In float mode (``"float": true`` on a
request) each literal is replaced by the double nearest to it (ties to
even), as a program reading the text into a ``double`` would see it.
"""

from fractions import Fraction
from math import isqrt

_HEX = "0123456789abcdefABCDEF"


class CheckError(Exception):
    """Something in the request or the answer is not what it must be."""


class NotChecked(Exception):
    """A value beyond this checker (a real algebraic number of degree > 2):
    the claim that needs it is reported as trusted, by name."""


def _digits(s, i, alphabet):
    j = i
    while j < len(s) and s[j] in alphabet:
        j += 1
    return j


def scan_number(s, i):
    """The unsigned literal starting at index ``i`` of ``s``: ``(value, end)``.

    A decimal ``d+[.d*]`` or ``.d+``, then an exponent ``e[+-]d+`` only when
    digits follow the ``e``; or ``0x`` followed by hex digits with an optional
    ``.`` fraction and an optional ``p[+-]d+`` binary exponent."""
    if s.startswith(("0x", "0X"), i) and i + 2 < len(s) and (s[i + 2] in _HEX or s[i + 2] == "."):
        j = _digits(s, i + 2, _HEX)
        mant, digits = s[i + 2 : j], 0
        if j < len(s) and s[j] == ".":
            k = _digits(s, j + 1, _HEX)
            digits = k - j - 1
            mant += s[j + 1 : k]
            j = k
        if not mant:
            raise CheckError(f"hexadecimal literal without digits at column {i + 1}")
        value = Fraction(int(mant, 16), 16**digits)
        if j < len(s) and s[j] in "pP":
            k = j + 1
            if k < len(s) and s[k] in "+-":
                k += 1
            e = _digits(s, k, "0123456789")
            if e == k:
                raise CheckError(f"binary exponent without digits at column {j + 1}")
            value *= Fraction(2) ** int(s[j + 1 : e])
            j = e
        return value, j
    j = _digits(s, i, "0123456789")
    whole, frac = s[i:j], ""
    if j < len(s) and s[j] == ".":
        k = _digits(s, j + 1, "0123456789")
        frac = s[j + 1 : k]
        j = k
    if not whole and not frac:
        raise CheckError(f"expected a number at column {i + 1}")
    value = Fraction(int(whole + frac or "0"), 10 ** len(frac))
    if j < len(s) and s[j] in "eE":
        k = j + 1
        if k < len(s) and s[k] in "+-":
            k += 1
        e = _digits(s, k, "0123456789")
        if e > k:
            value *= Fraction(10) ** int(s[j + 1 : e])
            j = e
    return value, j


def nearest_double(q):
    """The double nearest to ``q`` (ties to even), exactly, as a Fraction.
    (``int / int`` true division is correctly rounded in CPython.)"""
    try:
        return Fraction(q.numerator / q.denominator)
    except OverflowError:
        raise CheckError(f"number out of the double range: {q}") from None


def parse_rational(text, float_mode=False):
    """An exact number written as the engine writes and reads them:
    an optional sign, a literal, optionally ``/`` and a second literal."""
    if not isinstance(text, str) or not text.strip():
        raise CheckError(f"not a number: {text!r}")
    t = text.strip()
    sign = 1
    if t[:1] in "+-":
        sign = -1 if t[0] == "-" else 1
        t = t[1:].strip()
    if "/" in t:
        n, d = t.split("/", 1)
        a, b = _literal(n, float_mode), _literal(d, float_mode)
        if b == 0:
            raise CheckError(f"division by zero in {text!r}")
        return sign * a / b
    return sign * _literal(t, float_mode)


def _literal(t, float_mode):
    t = t.strip()
    try:
        v, end = scan_number(t, 0)
    except CheckError:
        raise CheckError(f"not a number: {t!r}") from None
    if end != len(t):
        raise CheckError(f"not a number: {t!r}")
    return nearest_double(v) if float_mode else v


def json_number(v, float_mode=False):
    """A number of a JSON request field: an exact string, or a JSON integer."""
    if isinstance(v, bool) or not isinstance(v, (str, int)):
        raise CheckError(f"expected an exact number (string or integer), got {v!r}")
    if isinstance(v, int):
        return nearest_double(Fraction(v)) if float_mode else Fraction(v)
    return parse_rational(v, float_mode)


_ZERO = Fraction(0)


class QS:
    """``a + b√d`` with rational a, b and an integer d ≥ 0 (d = 0 or b = 0: a
    rational).  Values of different radicands d do not mix (an error)."""

    __slots__ = ("a", "b", "d")

    def __init__(self, a, b=Fraction(0), d=0):
        self.a = a if type(a) is Fraction else Fraction(a)
        self.b = b if type(b) is Fraction else Fraction(b)
        self.d = d if type(d) is int else int(d)
        if not self.d:
            self.b = _ZERO
            return
        if self.d < 0:
            raise CheckError(f"negative radicand {d}")
        if self.d:
            r = isqrt(self.d)
            if r * r == self.d:  # a square radicand: a rational value
                self.a, self.b, self.d = self.a + self.b * r, Fraction(0), 0
        if self.b == 0 or self.d == 0:
            self.b, self.d = Fraction(0), 0

    def _join(self, o):
        if not isinstance(o, QS):
            o = QS(o)
        if self.d and o.d and self.d != o.d:
            # the same field when d₁·d₂ = r²: √d₂ = (r/d₁)·√d₁
            r = isqrt(self.d * o.d)
            if r * r != self.d * o.d:
                raise NotChecked("a point with coordinates in two quadratic fields Q(√d₁, √d₂)")
            o = QS(o.a, o.b * Fraction(r, self.d), self.d)
        return o, self.d or o.d

    def __add__(self, o):
        if type(o) is QS and not self.d and not o.d:
            return QS(self.a + o.a)
        o, d = self._join(o)
        return QS(self.a + o.a, self.b + o.b, d)

    __radd__ = __add__

    def __neg__(self):
        return QS(-self.a, -self.b, self.d)

    def __sub__(self, o):
        return self + (-(o if isinstance(o, QS) else QS(o)))

    def __rsub__(self, o):
        return QS(o) - self

    def __mul__(self, o):
        if type(o) is QS and not self.d and not o.d:
            return QS(self.a * o.a)
        o, d = self._join(o)
        return QS(self.a * o.a + self.b * o.b * d, self.a * o.b + self.b * o.a, d)

    __rmul__ = __mul__

    def inv(self):
        """1/(a + b√d) = (a − b√d)/(a² − b²d) (d not a square, or b = 0)."""
        n = self.a * self.a - self.b * self.b * self.d
        if n == 0:
            raise CheckError("division by zero in Q(√d)")
        return QS(self.a / n, -self.b / n, self.d)

    def __truediv__(self, o):
        return self * (o if isinstance(o, QS) else QS(o)).inv()

    def sign(self):
        """The exact sign of a + b√d: compare a² with b²d when the terms'
        signs differ."""
        sa = (self.a > 0) - (self.a < 0)
        sb = (self.b > 0) - (self.b < 0)
        if sb == 0 or sa == sb:
            return sa or sb
        if sa == 0:
            return sb
        t = self.a * self.a - self.b * self.b * self.d
        st = (t > 0) - (t < 0)
        return sa * st

    def is_zero(self):
        return self.a == 0 and self.b == 0

    def __repr__(self):
        return f"{self.a} + {self.b}√{self.d}" if self.d else str(self.a)


def parse_value(v, what):
    """A number of an answer: an exact string (a rational) or
    ``{"a", "b", "d"}`` meaning a + b√d."""
    if isinstance(v, str):
        return QS(parse_rational(v))
    if isinstance(v, dict) and {"a", "b", "d"} <= set(v):
        d = parse_rational(v["d"])
        if d.denominator != 1 or d < 0:
            raise CheckError(f"{what}: radicand {v['d']} is not a non-negative integer")
        return QS(parse_rational(v["a"]), parse_rational(v["b"]), int(d))
    if isinstance(v, dict) and {"poly", "interval"} <= set(v):
        raise NotChecked(f"{what} is a real algebraic number of higher degree")
    raise CheckError(f"{what}: expected an exact number or {{a, b, d}}, got {str(v)[:80]}")


def parse_point(v, what):
    if not isinstance(v, list) or len(v) != 3:
        raise CheckError(f"{what}: expected three coordinates")
    return [parse_value(c, f"{what}[{i}]") for i, c in enumerate(v)]


def sqrt_rational(r):
    """√r for a rational r ≥ 0, in Q(√d): √(n/m) = √(n·m)/m."""
    r = Fraction(r)
    return QS(0, Fraction(1, r.denominator), r.numerator * r.denominator)


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
