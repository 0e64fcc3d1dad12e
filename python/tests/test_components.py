"""The typed components of natural(): Conic, Line, Point, Curve.

Every component equals the CLI's JSON of the same answer (its dict form is
the decoded JSON component, exactly), and every certified double
``(value, bound)`` encloses the exact number: ``|exact − value| ≤ bound``,
checked in exact arithmetic (Fraction against QuadraticIrrational and
RealAlgebraic), on hand-picked pairs (conics with √d values, lines, points,
curves with singular points) and on random pairs (hypothesis)."""

import json
import math
import pathlib
import pickle
from decimal import Decimal, localcontext
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

import quadsect
from quadsect import (
    Cone,
    Conic,
    Curve,
    CurveBranch,
    Cylinder,
    Line,
    Plane,
    Point,
    QuadraticIrrational,
    RealAlgebraic,
    SingularPoint,
    Sphere,
)

ROOT = pathlib.Path(__file__).resolve().parents[2]
BENCH_PAIRS = {p["name"]: p for p in json.loads((ROOT / "benches" / "data" / "natural_pairs.json").read_text())["pairs"]}


def bench(name):
    """A pair of benches/data/natural_pairs.json as JSON texts."""
    p = BENCH_PAIRS[name]
    return json.dumps(p["a"]), json.dumps(p["b"])


PAIRS = {
    # circles at the heights z = (3 ± √3)/2: irrational planes, centres, radii
    "cone-sphere-sqrt3": ("cone vertex=0,0,0 axis=0,0,1 tan2=1", "sphere center=0,0,3 radius2=6"),
    # two ellipses through the axes' crossing, rational
    "perpendicular-cylinders": ("cylinder point=0,0,0 axis=1,0,0 radius2=1",
                                "cylinder point=0,0,0 axis=0,1,0 radius2=1"),
    # two lines x = 1/2, y = ±√3/2
    "parallel-cylinders": ("cylinder point=0,0,0 axis=0,0,1 radius2=1",
                           "cylinder point=1,0,0 axis=0,0,1 radius2=1"),
    # one tangency point
    "touching-spheres": ("sphere center=0,0,0 radius2=1", "sphere center=2,0,0 radius2=1"),
    # Viviani's curve: a quartic with a crossing at (2, 0, 0)
    "viviani": ("sphere center=0,0,0 radius2=4", "cylinder point=1,0,0 axis=0,0,1 radius2=1"),
    # a quartic with two bounded branches
    "two-loops": ("sphere center=0,0,0 radius2=4", "cylinder point=1,0,0 axis=1,1,0 radius2=1"),
    # a quartic with two unbounded branches
    "cone-cylinder": ("cone vertex=0,0,0 axis=0,0,1 tan2=1", "cylinder point=0,0,0 axis=1,0,1 radius2=1"),
    # a parabola and a line
    "parabola": bench("class-conic-and-line-001"),
    # hyperbolas
    "hyperbola": bench("class-conics-006"),
    # a quartic with an acnode
    "acnode": bench("class-curve-001"),
    # a cubic beside a line, with a crossing
    "cubic": bench("class-curve-003"),
    # a cone's vertex as an isolated point beside conics
    "vertex": bench("class-conics-011"),
    # a nearly degenerate curve: branches on rulings with tiny coefficients
    # of huge radicands (once a crash of the certified doubles)
    "near-degenerate": bench("near-degenerate-007"),
}
# every pair of the class-* groups of the benchmark
CLASS_PAIRS = sorted(n for n in BENCH_PAIRS if n.startswith("class-"))


def numbers(component):
    """(exact, certified) for every numeric field of a component."""
    out = []

    def pair(x, f):
        if x is None:
            assert f is None
            return
        if isinstance(x, tuple):
            assert isinstance(f, tuple) and len(f) == len(x)
            for xi, fi in zip(x, f):
                pair(xi, fi)
            return
        out.append((x, f))

    c = component
    if isinstance(c, Conic):
        pair(c.plane.normal, c.plane.normal_f64)
        pair(c.plane.offset, c.plane.offset_f64)
        pair(c.center, c.center_f64)
        pair(c.vertex, c.vertex_f64)
        pair(c.semi_axes2, c.semi_axes2_f64)
        pair(c.axis_directions, c.axis_directions_f64)
        pair(c.focal_length2, c.focal_length2_f64)
    elif isinstance(c, Line):
        pair(c.point, c.point_f64)
        pair(c.direction, c.direction_f64)
    elif isinstance(c, Point):
        pair(c.point, c.point_f64)
    else:
        assert isinstance(c, Curve)
        for s in c.singular_points:
            pair(s.point, s.point_f64)
        for b in c.branches:
            pair(b.ruling_point, b.ruling_point_f64)
            pair(b.ruling_direction, b.ruling_direction_f64)
            pair(b.quadratic, b.quadratic_f64)
            pair(b.t, b.t_f64)
    return out


def check_enclosure(x, certified):
    """|x − value| ≤ bound, exactly; float(x) within bound + ½ ulp."""
    value, bound = certified
    assert isinstance(value, float) and isinstance(bound, float)
    assert bound >= 0 and math.isfinite(value)
    assert isinstance(x, (Fraction, QuadraticIrrational, RealAlgebraic)), type(x)
    lo, hi = Fraction(value) - Fraction(bound), Fraction(value) + Fraction(bound)
    assert lo <= x <= hi, (x, certified)
    # the bound is tight: at most 2^-46·|value| (64 units in the last place),
    # 0 for an exact double
    assert bound <= abs(value) * 2.0 ** -46, (x, certified)
    if isinstance(x, Fraction) and Fraction(value) == x:
        assert bound == 0
    assert abs(float(x) - value) <= bound + math.ulp(value) / 2


def sqrt_dec(x):
    return x.sqrt() if x > 0 else Decimal(0)


def dec(x):
    """A number as a Decimal (60 digits)."""
    if isinstance(x, Fraction):
        return Decimal(x.numerator) / Decimal(x.denominator)
    q = x.approx_fraction(220)
    return Decimal(q.numerator) / Decimal(q.denominator)


def branch_point(b):
    """The exact point of a branch from its ruling data, to 60 digits."""
    with localcontext() as ctx:
        ctx.prec = 60
        if b.root == 0:
            t = dec(b.t)
        else:
            a, bb, c = (dec(x) for x in b.quadratic)
            t = (-bb + b.root * sqrt_dec(bb * bb - a * c)) / a
        return [dec(p) + t * dec(d) for p, d in zip(b.ruling_point, b.ruling_direction)]


def check_component(c):
    for x, f in numbers(c):
        check_enclosure(x, f)
    if isinstance(c, Curve):
        assert c.real_components == len(c.branches)
        for b in c.branches:
            assert b.root in (-1, 0, 1) and (b.t is None) == (b.root != 0)
            for exact, (value, bound) in zip(branch_point(b), b.point_f64):
                assert abs(exact - Decimal(value)) <= Decimal(bound) + Decimal(2) ** -150


def check_answer(r):
    """The typed components against the JSON of the same answer."""
    j = r.to_json()
    raw = quadsect._decode(j.get("components", []))
    assert len(r.components) == len(raw)
    for c, d in zip(r.components, raw):
        assert c.to_dict() == d
        assert c["type"] == d["type"] == c.type
        check_component(c)
    assert pickle.loads(pickle.dumps(r.components)) == r.components


@pytest.mark.parametrize("name", list(PAIRS) + CLASS_PAIRS)
def test_components_equal_the_json_and_doubles_enclose_the_exact_values(name):
    a, b = PAIRS[name] if name in PAIRS else bench(name)
    r = quadsect.natural(a, b)
    assert r.classification != "undecided"
    check_answer(r)
    # the counts agree with the component types
    types = [c.type for c in r.components]
    assert types.count("conic") == r.conics and types.count("line") == r.lines
    isolated = sum(isinstance(c, Point) for c in r.components) + sum(
        s.isolated for c in r.components if isinstance(c, Curve) for s in c.singular_points)
    assert isolated == r.points


def test_planar_conics_with_square_roots():
    r = quadsect.natural(*PAIRS["cone-sphere-sqrt3"])
    assert (r.classification, r.conics) == ("conics", 2)
    heights = sorted(c.plane.offset for c in r.components)
    assert all(isinstance(h, QuadraticIrrational) for h in heights)
    assert heights == [QuadraticIrrational("3/2", "-1/2", 3), QuadraticIrrational("3/2", "1/2", 3)]
    for c in r.components:
        assert c.kind == "circle" and c.plane.normal == (0, 0, 1)
        z = c.plane.offset
        assert c.center[:2] == (0, 0) and c.center[2] == z
        # on the cone x² + y² = z²: the radius² is z² = (3 ± √3)²/4 = (12 ± 6√3)/4
        r2 = c.semi_axes2[0]
        assert c.semi_axes2[0] == c.semi_axes2[1]
        assert r2 == QuadraticIrrational(3, 3 * z.b, 3)
        assert isinstance(r2, QuadraticIrrational) and r2.d == 3


def test_lines_points_and_curves():
    lines = quadsect.natural(*PAIRS["parallel-cylinders"]).components
    assert [type(c) for c in lines] == [Line, Line]
    ys = sorted(c.point[1] for c in lines)
    assert ys == [QuadraticIrrational(0, "-1/2", 3), QuadraticIrrational(0, "1/2", 3)]
    assert all(c.point[0] == Fraction(1, 2) and c.direction in ((0, 0, 1), (0, 0, -1)) for c in lines)

    (p,) = quadsect.natural(*PAIRS["touching-spheres"]).components
    assert isinstance(p, Point) and p.kind == "tangency" and p.point == (1, 0, 0)
    assert p.point_f64 == ((1.0, 0.0), (0.0, 0.0), (0.0, 0.0))

    r = quadsect.natural(*PAIRS["viviani"])
    (c,) = r.components
    assert isinstance(c, Curve) and c.degree == 4
    assert [(s.kind, s.point, s.isolated) for s in c.singular_points] == [("crossing", (2, 0, 0), False)]
    assert isinstance(c.singular_points[0], SingularPoint)
    assert c.real_components == len(c.branches) >= 1
    assert all(isinstance(b, CurveBranch) and b.bounded for b in c.branches)

    r = quadsect.natural(*PAIRS["two-loops"])
    (c,) = r.components
    assert isinstance(c, Curve) and c.real_components == 2 and all(b.bounded for b in c.branches)
    (c,) = quadsect.natural(*PAIRS["cone-cylinder"]).components
    assert isinstance(c, Curve) and c.real_components == 2 and not any(b.bounded for b in c.branches)

    r = quadsect.natural(*PAIRS["acnode"])
    curve = [c for c in r.components if isinstance(c, Curve)]
    assert any(s.kind == "acnode" and s.isolated for c in curve for s in c.singular_points)
    r = quadsect.natural(*PAIRS["cubic"])
    assert any(isinstance(c, Curve) and c.degree == 3 for c in r.components)
    assert any(isinstance(c, Line) for c in r.components)
    r = quadsect.natural(*PAIRS["parabola"])
    (par,) = [c for c in r.components if isinstance(c, Conic)]
    assert par.kind == "parabola" and par.center is None and par.semi_axes2 == ()
    assert par.vertex is not None and par.focal_length2 > 0 and len(par.axis_directions) == 1
    r = quadsect.natural(*PAIRS["vertex"])
    assert any(isinstance(c, Point) and c.kind == "vertex" for c in r.components)


def test_dict_form_reads_like_the_old_dicts():
    r = quadsect.natural(*PAIRS["perpendicular-cylinders"])
    e = r.components[0]
    assert e["conic"] == "ellipse" and e["semi_axes2"] == [2, 1] and e["center"] == [0, 0, 0]
    assert e.get("focal_length2") is None and e.get("nope", 7) == 7 and "plane" in e
    assert set(e.keys()) == set(r.to_json()["components"][0]) == set(e)
    assert isinstance(e.plane, Plane) and e.plane.normal in ((1, -1, 0), (1, 1, 0))
    (c,) = quadsect.natural(*PAIRS["cone-sphere-sqrt3"]).components[:1]
    assert set(c["plane"]["offset"]) == {"a", "b", "d", "approx"}
    with pytest.raises(KeyError):
        e["nope"]


def test_components_are_hashable_and_compare_by_value():
    a = quadsect.natural(*PAIRS["cone-sphere-sqrt3"]).components
    b = quadsect.natural(Cone((0, 0, 0), (0, 0, 1), tan2=1), Sphere((0, 0, 3), 6)).components
    assert a == b and hash(tuple(a)) == hash(tuple(b)) and len(set(a)) == 2


ints = st.integers(-2, 2)
points = st.tuples(ints, ints, ints)
axes = st.sampled_from([(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1), (0, 1, 1), (1, -1, 1), (1, 2, 0)])
sizes = st.sampled_from([Fraction(1), Fraction(2), Fraction(1, 3), Fraction(3), Fraction(4), Fraction(6)])
naturals = st.one_of(
    st.builds(Sphere, points, sizes),
    st.builds(Cylinder, points, axes, sizes),
    st.builds(lambda v, a, t2: Cone(v, a, tan2=t2), points, axes, sizes),
)


@given(naturals, naturals)
def test_property_components_match_json_and_bounds_hold(a, b):
    """Property: for random pairs, every typed component is its JSON
    component and every certified double encloses its exact number."""
    r = quadsect.natural(a, b, time_limit=20)
    if r.classification != "undecided":
        check_answer(r)


def test_the_package_namespace_is_its_public_api():
    public = {n for n in dir(quadsect) if not n.startswith("_")}
    # submodules imported by the tests (quadsect.dask, quadsect.occ) are attributes too
    public -= {"dask", "occ"}
    assert public == set(quadsect.__all__), public ^ set(quadsect.__all__)
    assert len(quadsect.__all__) == len(set(quadsect.__all__))
    for leak in ("Any", "Dict", "List", "Optional", "Union", "json", "re", "dataclass", "Fraction",
                 "Mapping", "Sequence", "overload", "annotations", "Number", "Vector"):
        assert not hasattr(quadsect, leak), leak
    for name in ("Conic", "Line", "Point", "Curve", "Plane", "SingularPoint", "CurveBranch",
                 "QuadraticIrrational", "natural", "Sphere", "NaturalResult"):
        assert name in quadsect.__all__
    # `from quadsect import *` gives exactly __all__
    ns: dict = {}
    exec("from quadsect import *", ns)
    assert set(ns) - {"__builtins__"} == set(quadsect.__all__)


def test_the_referee_witness_is_exact_and_differs():
    r = quadsect.natural("sphere center=0,0,0 radius2=1", "sphere center=3/2,0,0 radius2=1",
                         components=False, referee=True)
    f = r.referee
    assert isinstance(f, quadsect.Referee)
    assert 0 < f.lo < f.hi and isinstance(f.lo, Fraction)
    near = quadsect.natural(*f.nearby)
    assert near.classification == f.nearby_answer["class"] != r.classification
    # without the option there is none; a degenerate pair has lo = 0
    assert quadsect.natural("sphere center=0,0,0 radius2=1", "sphere center=2,0,0 radius2=1").referee is None
    t = quadsect.natural("sphere center=0,0,0 radius2=1", "sphere center=2,0,0 radius2=1", referee=True).referee
    assert t.lo == 0 and t.lo_reason and t.hi < Fraction(1, 2**30)
