"""Invariance under rational rigid motions (Cayley rotations built in
Python Fractions, rational translations): moving both surfaces by the same
motion changes neither the class of two natural quadrics nor the verdict,
the exact min and max of a tangent problem."""

from fractions import Fraction

from hypothesis import given
from hypothesis import strategies as st

import quadsect
from quadsect import Cone, Cylinder, Sphere

from motions import apply, is_rotation, move_expression, move_point, rotation

small = st.integers(-3, 3)
quaternions = st.tuples(small, small, small, small).filter(lambda q: any(q))
rationals = st.fractions(min_value=-3, max_value=3, max_denominator=4)
translations = st.tuples(rationals, rationals, rationals)
scales = st.sampled_from([Fraction(1), Fraction(2), Fraction(-1, 3), Fraction(5, 2)])


def move_natural(q, r, t, k):
    """The natural quadric q moved by p ↦ R p + t (its axis also rescaled
    by k ≠ 0, which names the same surface)."""
    if isinstance(q, Sphere):
        return Sphere(move_point(r, t, q.center), q.radius2)
    axis = tuple(k * c for c in apply(r, q.axis))
    if isinstance(q, Cylinder):
        return Cylinder(move_point(r, t, q.point), axis, q.radius2)
    return Cone(move_point(r, t, q.vertex), axis, tan2=q.tan2)


ints = st.integers(-2, 2)
points = st.tuples(ints, ints, ints)
axes = st.sampled_from([(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1), (0, 1, 1), (1, -1, 1), (1, 2, 0)])
sizes = st.sampled_from([Fraction(1), Fraction(2), Fraction(1, 3), Fraction(1, 4), Fraction(3), Fraction(4)])
naturals = st.one_of(
    st.builds(Sphere, points, sizes),
    st.builds(Cylinder, points, axes, sizes),
    st.builds(lambda v, a, t2: Cone(v, a, tan2=t2), points, axes, sizes),
)


def summary(r):
    return (r.classification, r.conics, r.lines, r.points, r.axes, r.thm8,
            sorted(c["type"] for c in r.components))


def test_cayley_rotations_are_exact_rotations():
    for q in [(1, 0, 0, 0), (1, 1, 0, 0), (1, 2, 3, 4), (0, 1, -2, 2), (3, -1, 2, 1)]:
        assert is_rotation(rotation(*q))


@given(naturals, naturals, quaternions, translations, scales)
def test_natural_classification_is_invariant_under_rigid_motions(a, b, q, t, k):
    """Property: natural(M a, M b) has the class, counts, axes relation,
    Theorem 8 value and component types of natural(a, b) for a rational
    rigid motion M."""
    r = rotation(*q)
    before = quadsect.natural(a, b)
    after = quadsect.natural(move_natural(a, r, t, k), move_natural(b, r, t, Fraction(1)))
    assert summary(after) == summary(before)


@given(naturals, naturals)
def test_natural_is_symmetric_in_its_arguments(a, b):
    """Property: the class and counts do not depend on the order of a, b."""
    assert summary(quadsect.natural(a, b))[:4] == summary(quadsect.natural(b, a))[:4]


positive = st.fractions(min_value=Fraction(1, 4), max_value=4, max_denominator=4)
coef = st.fractions(min_value=-2, max_value=2, max_denominator=3)


@st.composite
def tangent_problems(draw):
    """An axis-parallel ellipsoid and a quadric surface (deg S ≤ 2: the
    exact complete route)."""
    a, b, c = (draw(positive) for _ in range(3))
    cx, cy, cz = (draw(coef) for _ in range(3))
    e = f"({a})*(x-({cx}))^2 + ({b})*(y-({cy}))^2 + ({c})*(z-({cz}))^2 - 1"
    kind = draw(st.sampled_from(["ellipsoid", "plane", "hyperboloid", "paraboloid", "touching"]))
    p, q, s, u, v, w = (draw(coef) for _ in range(6))
    if kind == "ellipsoid":
        surface = f"({draw(positive)})*(x-({p}))^2 + ({draw(positive)})*(y-({q}))^2 + ({draw(positive)})*(z-({s}))^2 - ({draw(positive)})"
    elif kind == "plane":
        surface = f"({p})*x + ({q})*y + ({s})*z - ({u})"
    elif kind == "hyperboloid":
        surface = f"(x-({p}))^2 + (y-({q}))^2 - ({draw(positive)})*(z-({s}))^2 - ({u})"
    elif kind == "touching":
        # the plane x = cx + m touches E when its semi-axis along x is m
        m = draw(st.sampled_from([Fraction(1), Fraction(2), Fraction(1, 2), Fraction(3, 2)]))
        e = f"(1/({m})^2)*(x-({cx}))^2 + ({b})*(y-({cy}))^2 + ({c})*(z-({cz}))^2 - 1"
        surface = f"x - ({cx}) - ({m})"
    else:
        surface = f"z - ({p})*x^2 - ({q})*y^2 - ({u})*x*y - ({v})*x - ({w})"
    if surface.startswith("(0)*x + (0)*y + (0)*z"):
        surface = "x - 1"
    return e, surface


@given(tangent_problems(), quaternions, translations)
def test_tangent_verdict_and_extremes_are_invariant_under_rigid_motions(problem, q, t):
    """Property: moving E and S by the same rational rigid motion keeps the
    verdict, side and the exact min and max of S on E."""
    e, s = problem
    r = rotation(*q)
    before = quadsect.tangent(e, s)
    after = quadsect.tangent(move_expression(r, t, e), move_expression(r, t, s))
    assert after.verdict == before.verdict
    assert (after.intersect, after.touching, after.side) == (before.intersect, before.touching, before.side)
    if before.verdict != "undecided":
        assert after.min == before.min and after.max == before.max
