"""The four jobs from Python: results, their agreement with the JSON of
the CLI, the typed natural quadrics, and bad input."""

import json
import math
import pickle
import threading
import time
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

import quadsect
from quadsect import BudgetError, Cone, Cylinder, InputError, RealAlgebraic, Sphere

E1 = "x^2 + y^2 + z^2 - 25"
S1 = "(x-9)^2/9 + y^2/4 + z^2/16 - 1"  # paper 004, Example 1: separated


# ------------------------------------------------------------------ tangent


def test_tangent_result_mirrors_its_json():
    r = quadsect.tangent(E1, S1)
    j = r.to_json()
    assert (r.verdict, r.intersect, r.touching, r.side, r.containment) == (
        j["verdict"], j["intersect"], j["touching"], j["side"], j["containment"])
    assert r.judging_poly == j["judging_poly"]
    assert isinstance(r.min, RealAlgebraic) and isinstance(r.max, RealAlgebraic)
    for value, alg in ((r.min, j["min"]), (r.max, j["max"])):
        assert value == RealAlgebraic(alg["poly"], tuple(alg["interval"]))
    # the certificate: exact strings decoded to Fractions, approximations kept
    c = r.certificate
    assert c["method"] == j["certificate"]["method"]
    for decoded, raw in zip(c["critical_values"], j["certificate"]["critical_values"]):
        assert decoded["interval"] == [Fraction(x) for x in raw["interval"]]
        assert decoded["approx"] == raw["approx"] and isinstance(decoded["approx"], str)
    assert r.critical_values == sorted(r.critical_values)
    assert r.min == r.critical_values[0] and r.max == r.critical_values[-1]
    assert r.undecided_kind is None and r.reason is None
    assert "separated" in str(r)
    # to_json is a fresh copy each time
    j["verdict"] = "changed"
    assert r.to_json()["verdict"] == "separated"


def test_tangent_verdicts_agree_with_min_and_max():
    cases = [S1, "(x-6)^2/9 + y^2/4 + z^2/16 - 1", "x - 5", "x^2 + y^2 + z^2 - 100", "z"]
    for s in cases:
        r = quadsect.tangent(E1, s)
        lo, hi = r.min, r.max
        assert r.intersect == (lo <= 0 <= hi)
        assert r.touching == (lo == 0 or hi == 0)
        if r.verdict == "separated":
            assert r.side == ("+" if lo > 0 else "-")
        else:
            assert r.verdict == ("touching" if r.touching else "intersecting")


def test_tangent_touching_plane():
    r = quadsect.tangent(E1, "x - 5")
    assert r.verdict == "touching" and r.max == 0 and r.min == -10


def test_tangent_pickles():
    r = quadsect.tangent(E1, S1)
    s = pickle.loads(pickle.dumps(r))
    assert s == r and s.min == r.min and str(s) == str(r)


def test_time_limit_validation():
    for bad in (-1.0, math.nan):
        with pytest.raises(InputError) as e:
            quadsect.tangent(E1, S1, time_limit=bad)
        assert e.value.kind == "input"
    assert quadsect.tangent(E1, S1, time_limit=math.inf).verdict == "separated"
    assert quadsect.tangent(E1, S1, time_limit=30).verdict == "separated"


def test_exhausted_time_limit_is_an_undecided_answer_for_tangent():
    r = quadsect.tangent("x^2 + 2y^2 + 3z^2 - 6", "x^3 - y*z + x*y^2 - 1/3", time_limit=0)
    assert r.verdict == "undecided" and r.intersect is None and r.touching is None
    assert r.undecided_kind == "budget" and "time" in r.reason
    assert r.to_json()["reason"]["limit"] == "time"


@pytest.mark.parametrize("components", [True, False])
def test_exhausted_time_limit_is_an_undecided_answer_for_natural(components):
    a = Cone((0, 0, 0), (0, 0, 1), tan2=1)
    b = Cylinder((1, 0, 0), (1, 1, 0), "1/3")
    r = quadsect.natural(a, b, time_limit=0, components=components)
    assert r.classification == "undecided"
    assert (r.conics, r.lines, r.points, r.components) == (None, None, None, [])
    assert r.undecided_kind == "budget" and "time" in r.reason
    assert r.to_json()["reason"]["limit"] == "time"
    # with time, the same pair is decided
    decided = quadsect.natural(a, b, components=components)
    assert decided.classification != "undecided" and decided.reason is None


def test_exhausted_time_limit_raises_budget_error_for_the_kernel():
    with pytest.raises(BudgetError) as e:
        quadsect.resultant("(x+y+z)^6+x^3*y-7", "(x-2y+3z)^5+y^5*z-1", "x", time_limit=0)
    assert e.value.kind == "budget" and isinstance(e.value, RuntimeError)
    assert "time" in str(e.value)
    with pytest.raises(BudgetError):
        quadsect.roots("x^300 - 3x^77 + 5x - 1", time_limit=0)


def test_the_gil_is_released_while_the_engine_computes():
    """A Python thread keeps running while another one is inside the engine:
    with the GIL held, the main loop would stall for the whole call."""
    f, g = "(x+y+z)^6+x^3*y-7", "(x-2y+3z)^5+y^5*z-1"  # ~0.2 s each
    start = time.perf_counter()
    quadsect.resultant(f, g, "x")
    one_call = time.perf_counter() - start
    worker = threading.Thread(target=lambda: [quadsect.resultant(f, g, "x") for _ in range(3)])
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    gaps = [b - a for a, b in zip(stamps, stamps[1:])]
    assert len(stamps) > 20
    assert max(gaps) < max(0.1, one_call / 2), (max(gaps), one_call)


# ------------------------------------------------------------------ natural

PERPENDICULAR = (
    Cylinder((0, 0, 0), (1, 0, 0), 1),
    "cylinder point=0,0,0 axis=0,1,0 radius2=1",
)


def test_natural_accepts_every_input_form():
    a_forms = [
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        '{"kind":"cylinder","point":["0","0","0"],"axis":["1","0","0"],"radius2":"1"}',
        {"kind": "cylinder", "point": [0, 0, 0], "axis": [1, 0, 0], "radius2": 1},
        {"kind": "cylinder", "point": [0.0, 0, Fraction(0)], "axis": ["1", 0, 0], "radius2": 1.0},
        Cylinder((0, 0, 0), (1, 0, 0), 1),
    ]
    results = [quadsect.natural(a, PERPENDICULAR[1]) for a in a_forms]
    assert all(r == results[0] for r in results)
    r = results[0]
    assert (r.classification, r.conics, r.lines, r.points) == ("conics", 2, 0, 0)
    assert r.axes == "coplanar-intersecting" and r.thm8 is True
    j = r.to_json()
    assert r.classification == j["class"] and len(r.components) == len(j["components"]) == 2
    for c, raw in zip(r.components, j["components"]):
        assert c["conic"] == raw["conic"] == "ellipse"
        assert c["semi_axes2"] == [Fraction(x) for x in raw["semi_axes2"]]
        assert c["center"] == [0, 0, 0]


NATURAL_PAIRS = [
    ("cylinder point=0,0,0 axis=1,0,0 radius2=1", "cylinder point=0,0,0 axis=0,1,0 radius2=1"),
    ("cone vertex=0,0,0 axis=0,0,1 tan2=1", "sphere center=0,0,2 radius2=2"),
    ("sphere center=0,0,0 radius2=1", "sphere center=3,0,0 radius2=1"),
    ("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=1,0,0 axis=0,0,1 radius2=1"),
    ("cone vertex=0,0,0 axis=0,0,1 tan2=1", "cylinder point=1,0,0 axis=1,1,0 radius2=1/3"),
]


@pytest.mark.parametrize("a,b", NATURAL_PAIRS)
def test_natural_without_components_gives_the_same_class_and_counts(a, b):
    full = quadsect.natural(a, b)
    fast = quadsect.natural(a, b, components=False)
    assert (fast.classification, fast.conics, fast.lines, fast.points, fast.thm8) == (
        full.classification, full.conics, full.lines, full.points, full.thm8)
    assert full.route is None and fast.route in ("fast", "complete")
    if fast.route == "fast":
        assert fast.components == [] and "components" not in fast.to_json()
    line = json.dumps({"id": 0, "op": "natural", "a": a, "b": b, "components": False})
    assert json.loads(quadsect.answer_line(line))["result"] == fast.to_json()


def test_typed_quadrics_validate_and_normalise():
    s = Sphere(("1/2", 0.5, 2), Fraction(9, 4))
    assert s.center == (Fraction(1, 2), Fraction(1, 2), 2) and s.radius2 == Fraction(9, 4)
    assert str(s) == "sphere center=1/2,1/2,2 radius2=9/4"
    assert s == Sphere((Fraction(1, 2), "0.5", 2), "2.25") and hash(s) == hash(Sphere(("1/2", "1/2", 2), "9/4"))
    assert Cone((0, 0, 0), (0, 0, 1), tan="1/2").tan2 == Fraction(1, 4)
    assert Cone((0, 0, 0), (0, 0, 1), sin2="1/4").tan2 == Fraction(1, 3)
    assert Cone((0, 0, 0), (0, 0, 1), cos2="3/4") == Cone((0, 0, 0), (0, 0, 1), tan2="1/3")
    assert Cylinder((0, 0, 0), (1, 2, 3), 2).to_dict() == {
        "kind": "cylinder", "point": ["0", "0", "0"], "axis": ["1", "2", "3"], "radius2": "2"}
    # the typed form is the same quadric as its short syntax and dict
    c = Cone((1, 2, 3), (0, 1, 1), tan2="1/3")
    assert quadsect.natural(c, s) == quadsect.natural(str(c), s.to_dict())


@pytest.mark.parametrize(
    "make",
    [lambda: Sphere((0, 0, 0), -1), lambda: Sphere((0, 0), 1), lambda: Sphere("000", 1),
     lambda: Cylinder((0, 0, 0), (0, 0, 0), 1), lambda: Cone((0, 0, 0), (1, 0, 0), tan2=0),
     lambda: Cone((0, 0, 0), (1, 0, 0)), lambda: Cone((0, 0, 0), (1, 0, 0), tan2=1, cos2="1/2"),
     lambda: Cone((0, 0, 0), (1, 0, 0), cos2=2)],
)
def test_bad_typed_quadrics_raise_bad_quadric(make):
    with pytest.raises(InputError) as e:
        make()
    assert e.value.kind == "bad-quadric"


def test_natural_result_pickles():
    r = quadsect.natural(*PERPENDICULAR)
    assert pickle.loads(pickle.dumps(r)) == r


# ------------------------------------------------------------ roots, resultant


def test_roots_result():
    r = quadsect.roots("(x^2-2)^3 (x-1/3)")
    j = r.to_json()
    assert (len(r), r.distinct_real, r.positive, r.negative) == (3, 3, 2, 1)
    assert r.real_with_multiplicity == 7 and r.multiplicities == [3, 1, 3]
    assert r.zero_multiplicity == 0 and r.descartes_bounds == (j["descartes_positive_bound"], j["descartes_negative_bound"])
    assert r.intervals == [(Fraction(a), Fraction(b)) for a, b in j["intervals"]]
    assert r[1] == Fraction(1, 3) and r[1].is_rational
    assert abs(r[0].approx_fraction(200) + r[2].approx_fraction(200)) <= Fraction(1, 2**199)
    assert [float(x) for x in r] == [-math.sqrt(2), 1 / 3, math.sqrt(2)]
    assert r[0] < r[1] < r[2] and r[::2] == [r[0], r[2]]
    assert pickle.loads(pickle.dumps(r)) == r


def test_resultant_result():
    r = quadsect.resultant("x^2 + y^2 - 1", "x - y", "x")
    assert (str(r), r.resultant, r.degree) == ("2*y^2 - 1", "2*y^2 - 1", 2)
    assert r.to_json() == {"resultant": "2*y^2 - 1", "degree": 2}
    zero = quadsect.resultant("x*y", "x*z", "x")
    assert zero.resultant == "0" and zero.degree is None


@given(st.lists(st.integers(-5, 5), min_size=1, max_size=4), st.lists(st.integers(-5, 5), min_size=1, max_size=4))
def test_resultant_of_products_of_linear_factors(a, b):
    """Property: Res_x(∏(x - aᵢ), ∏(x - bⱼ)) = ∏(aᵢ - bⱼ)."""
    f = "*".join(f"(x - ({v}))" for v in a)
    g = "*".join(f"(x - ({v}))" for v in b)
    expected = 1
    for u in a:
        for v in b:
            expected *= u - v
    assert quadsect.exact(quadsect.resultant(f, g, "x").resultant) == expected


# ---------------------------------------------------------------- bad input

BAD_CALLS = [
    (lambda: quadsect.tangent("x^2+y^2+z^2-", "x"), "parse"),
    (lambda: quadsect.tangent("x^2+y^2-z^2-1", "x"), "not-an-ellipsoid"),
    (lambda: quadsect.tangent("x^2+y^2+z^2+1", "x"), "not-an-ellipsoid"),
    (lambda: quadsect.tangent("x^2+y^2+z^2", "x"), "not-an-ellipsoid"),
    (lambda: quadsect.tangent("x^2+y^2+z^2-1", "u"), "input"),
    (lambda: quadsect.tangent("x^2+y^2+z^2-1", "0"), "input"),
    (lambda: quadsect.tangent("x^2+y^2+z^2-1", "x/0"), "parse"),
    (lambda: quadsect.natural("sphere center=0,0,0 radius2=-1", "sphere center=0,0,0 radius2=1"), "bad-quadric"),
    (lambda: quadsect.natural('{"kind":"sphere"}', "sphere center=0,0,0 radius2=1"), "bad-quadric"),
    (lambda: quadsect.natural("blob", "sphere center=0,0,0 radius2=1"), "bad-quadric"),
    (lambda: quadsect.natural({"kind": "sphere", "center": [0, 0, 0], "radius2": 1.0 / 3.0 - 1}, "x"), "bad-quadric"),
    (lambda: quadsect.natural({"kind": "sphere", "center": [0, 0, 0], "radius2": math.nan}, "x"), "number"),
    (lambda: quadsect.roots("x*y"), "not-univariate"),
    (lambda: quadsect.roots("0"), "zero-polynomial"),
    (lambda: quadsect.roots("x^"), "parse"),
    (lambda: quadsect.roots("(x"), "parse"),
    (lambda: quadsect.resultant("x", "y", "w"), "input"),
    (lambda: quadsect.resultant("x+", "y", "x"), "parse"),
]


@pytest.mark.parametrize("call, kind", BAD_CALLS)
def test_bad_input_raises_input_error_with_its_kind(call, kind):
    with pytest.raises(InputError) as e:
        call()
    assert e.value.kind == kind
    assert isinstance(e.value, ValueError) and e.value.message and str(e.value) == e.value.message


def test_wrong_python_types_raise_type_error():
    with pytest.raises(TypeError):
        quadsect.tangent(E1, 5)
    with pytest.raises(TypeError):
        quadsect.natural(3, "sphere center=0,0,0 radius2=1")
    with pytest.raises(TypeError):
        quadsect.roots(None)


def test_errors_pickle_with_their_kind():
    try:
        quadsect.roots("x*y")
    except InputError as e:
        f = pickle.loads(pickle.dumps(e))
        assert type(f) is InputError and f.kind == e.kind and str(f) == str(e)


EXPRESSION_CHARS = "xyzu0123456789+-*/^(). e"


@given(st.text(alphabet=EXPRESSION_CHARS, max_size=14))
def test_any_text_is_an_answer_or_an_input_error(text):
    """Property: arbitrary expression text never crashes: each job answers
    or raises InputError (never another exception)."""
    calls = [
        lambda: quadsect.roots(text),
        lambda: quadsect.resultant(text, "x^2 - y", "x"),
        lambda: quadsect.tangent("x^2 + 2y^2 + 3z^2 - 6", text),
        lambda: quadsect.tangent(text, "x"),
        lambda: quadsect.exact(text),
    ]
    for call in calls:
        try:
            call()
        except InputError as e:
            assert e.kind in {"parse", "number", "input", "not-an-ellipsoid", "not-univariate", "zero-polynomial"}


@given(st.text(max_size=40))
def test_any_natural_text_is_an_answer_or_an_input_error(text):
    try:
        quadsect.natural(text, "sphere center=0,0,0 radius2=1")
    except InputError as e:
        assert e.kind == "bad-quadric" or e.kind == "number" or e.kind == "parse"


def test_answers_serialise_like_the_cli_json():
    r = quadsect.natural(*PERPENDICULAR)
    line = quadsect.answer_line(json.dumps({"id": 1, "op": "natural", "a": str(PERPENDICULAR[0]), "b": PERPENDICULAR[1]}))
    assert json.loads(line)["result"] == r.to_json()


# ------------------------------------------------------------------ pictures


def test_pictures_of_both_jobs_and_their_jupyter_display():
    t = quadsect.tangent(E1, S1)
    svg = t.svg()
    assert svg.startswith("<svg") and "verdict: separated" in svg
    assert t._repr_svg_() == svg
    # a pickled result draws the same picture (it keeps its inputs)
    assert pickle.loads(pickle.dumps(t)).svg() == svg
    n = quadsect.natural(Cylinder((0, 0, 0), (1, 0, 0), 1),
                         "cylinder point=0,0,0 axis=0,1,0 radius2=1")
    nsvg = n.svg()
    assert "class conics" in nsvg and "axial plane" in nsvg
    assert n._repr_svg_() == nsvg
    # rebuilt by pickle: drawn again from the quadrics in its JSON
    assert pickle.loads(pickle.dumps(n)).svg() == nsvg
    # the batch protocol's "svg" field gives the same text
    line = json.dumps({"id": 1, "op": "natural", "a": "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                       "b": "cylinder point=0,0,0 axis=0,1,0 radius2=1", "svg": True})
    assert json.loads(quadsect.answer_line(line))["result"]["svg"] == nsvg
