"""Rational rigid motions for the invariance tests, in Python Fractions.

A rotation comes from an integer quaternion (a, b, c, d) ≠ 0 by the
Euler–Rodrigues / Cayley formula R = M / (a² + b² + c² + d²), which is
exactly orthogonal with determinant 1 for every such quaternion.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import List, Sequence, Tuple

Matrix = List[List[Fraction]]
Vec = Tuple[Fraction, Fraction, Fraction]


def rotation(a: int, b: int, c: int, d: int) -> Matrix:
    n = a * a + b * b + c * c + d * d
    assert n != 0
    m = [
        [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
        [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
        [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
    ]
    return [[Fraction(x, n) for x in row] for row in m]


def is_rotation(r: Matrix) -> bool:
    """RᵀR = I and det R = 1, exactly."""
    ident = all(
        sum(r[k][i] * r[k][j] for k in range(3)) == (1 if i == j else 0)
        for i in range(3)
        for j in range(3)
    )
    det = (
        r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1])
        - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
        + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0])
    )
    return ident and det == 1


def apply(r: Matrix, v: Sequence[Fraction]) -> Vec:
    x, y, z = (sum(r[i][j] * v[j] for j in range(3)) for i in range(3))
    return (x, y, z)


def move_point(r: Matrix, t: Sequence[Fraction], p: Sequence[Fraction]) -> Vec:
    """R p + t."""
    q = apply(r, p)
    return (q[0] + t[0], q[1] + t[1], q[2] + t[2])


def _frac(q: Fraction) -> str:
    return f"({q.numerator}/{q.denominator})"


def move_expression(r: Matrix, t: Sequence[Fraction], expr: str) -> str:
    """The polynomial F∘M⁻¹ (its zero set moved by p ↦ R p + t): every
    variable of ``expr`` is replaced by the coordinate of Rᵀ(p − t)."""
    inverse = {}
    for i, name in enumerate("xyz"):
        terms = [f"{_frac(r[j][i])}*({v} - {_frac(t[j])})" for j, v in enumerate("xyz")]
        inverse[name] = "(" + " + ".join(terms) + ")"
    return re.sub(r"[xyz]", lambda m: inverse[m.group(0)], expr)
