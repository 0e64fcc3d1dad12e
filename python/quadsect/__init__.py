"""quadsect — exact decisions on how two surfaces meet.

Every number is exact: inputs are ``int``, ``fractions.Fraction``, ``str``
in the engine's syntax (``"7/9"``, ``"1.5"``, ``"1e-12"``) or ``float`` /
``Decimal`` taken at their exact binary/decimal value; rationals come back
as ``Fraction``, numbers of one square root as :class:`QuadraticIrrational`
(``a + b√d``) and other irrational values as :class:`RealAlgebraic` (a
square-free integer polynomial and an isolating interval).  Polynomials are
strings in the input syntax (``"x^2 + y^2 + z^2 - 25"``, ``"2x^2 - 3(y-1)"``).

The four jobs:

* :func:`tangent` — an ellipsoid against an algebraic surface (the tangent
  point method): intersecting, touching, separated, with the exact min and
  max of S on E and a certificate;
* :func:`natural` — two natural quadrics (spheres, circular cylinders, right
  cones): the class of their intersection and every component, typed
  (:class:`Conic`, :class:`Line`, :class:`Point`, :class:`Curve`) with exact
  numbers and certified doubles;
* :func:`roots`, :func:`resultant` — the algebra kernel;

and the batch protocol of ``quadsect batch``: :func:`answer_line`,
:func:`batch` (streaming, in order, on Rust threads), and
:mod:`quadsect.dask` for bags of lines on a Dask cluster.

>>> r = quadsect.tangent("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1")
>>> r.verdict, r.min, r.max
('separated', RealAlgebraic('9*u - 7', ('7/9', '7/9')), RealAlgebraic('9*u - 187', ('187/9', '187/9')))
>>> r.min == Fraction(7, 9)
True

The engine computes with the GIL released, so Python threads run in
parallel with it; it never panics into Python: bad input raises
:class:`InputError` (a ``ValueError``) with ``.kind``, an exhausted budget
:class:`BudgetError` from :func:`roots` and :func:`resultant` (:func:`tangent`
and :func:`natural` answer ``"undecided"`` instead), a failure inside
quadsect :class:`InternalError`.
"""

from __future__ import annotations

import json as _json
import re as _re
from collections.abc import Mapping as _Mapping
from dataclasses import dataclass as _dataclass
from fractions import Fraction as _Fraction
from typing import TYPE_CHECKING as _TYPE_CHECKING
from typing import Sequence as _Sequence
from typing import overload as _overload

from . import _quadsect
from ._components import (
    Conic,
    Curve,
    CurveBranch,
    Line,
    Plane,
    Point,
    SingularPoint,
    _component,
)
from ._contact import Contact, ContactReport, ellipsoid_contact, ellipsoid_contact_pair
from ._errors import BudgetError, InputError, InternalError, QuadsectError
from ._quadsect import QuadraticIrrational, RealAlgebraic, answer_line, exact

if _TYPE_CHECKING:  # names of the annotations only: not attributes of the package
    from fractions import Fraction
    from typing import (
        Any,
        Dict,
        Iterable,
        Iterator,
        List,
        Mapping,
        Optional,
        Sequence,
        Tuple,
        Union,
    )

    from ._components import Component

    #: A number input: int, Fraction, str (engine syntax), float or Decimal (exact value).
    Number = Union[int, Fraction, float, str, Any]
    Vector = Tuple[Fraction, Fraction, Fraction]
    #: A natural quadric: short syntax, JSON text, a dict, or Sphere/Cylinder/Cone.
    NaturalLike = Union[str, Mapping[str, Any], "Sphere", "Cylinder", "Cone"]

# the __future__ import binds a name: not part of the package
del annotations

__version__: str = _quadsect.__version__

#: The time limit (seconds) of one call when ``time_limit`` is ``None``.
DEFAULT_TIME_LIMIT: float = _quadsect.DEFAULT_TIME_LIMIT

__all__ = [
    # the jobs
    "tangent",
    "natural",
    "roots",
    "resultant",
    "answer_line",
    "batch",
    # exact numbers
    "exact",
    "RealAlgebraic",
    "QuadraticIrrational",
    # natural quadrics and the components of their intersection
    "Sphere",
    "Cylinder",
    "Cone",
    "Conic",
    "Plane",
    "Line",
    "Point",
    "Curve",
    "SingularPoint",
    "CurveBranch",
    # ellipsoid contact
    "ellipsoid_contact",
    "ellipsoid_contact_pair",
    "Contact",
    "ContactReport",
    # results
    "TangentResult",
    "NaturalResult",
    "Referee",
    "RootsResult",
    "ResultantResult",
    # errors
    "QuadsectError",
    "InputError",
    "BudgetError",
    "InternalError",
    "DEFAULT_TIME_LIMIT",
]

# ---------------------------------------------------------------- helpers

_RATIONAL = _re.compile(r"-?[0-9]+(?:/[0-9]+)?\Z")


def _decode(value: Any, key: Optional[str] = None) -> Any:
    """The JSON of a report with its exact rational strings as ``Fraction``.

    Approximations (``approx``) and polynomials (``poly``, ``*_poly``) stay
    strings; everything else that reads as an exact rational becomes one.
    """
    if isinstance(value, str):
        if key is not None and (key == "approx" or key.endswith("poly")):
            return value
        return _Fraction(value) if _RATIONAL.match(value) else value
    if isinstance(value, list):
        return [_decode(v, key) for v in value]
    if isinstance(value, dict):
        return {k: _decode(v, k) for k, v in value.items()}
    return value


def _text(q: Fraction) -> str:
    """The engine's spelling of an exact rational."""
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def _vector(v: Sequence[Number], name: str) -> Tuple[Number, Number, Number]:
    """Three numbers (converted by the compiled half)."""
    if isinstance(v, (str, bytes)) or len(v) != 3:
        raise InputError(f"{name} must be three numbers, got {v!r}", "bad-quadric")
    x, y, z = v
    return (x, y, z)


def _json_numbers(value: Any) -> Any:
    """A natural quadric's dict with every number as an exact string."""
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple)):
        return [_json_numbers(v) for v in value]
    if isinstance(value, _Mapping):
        return {k: (v if k == "kind" else _json_numbers(v)) for k, v in value.items()}
    return _text(exact(value))


# ------------------------------------------------------ natural quadrics


class _NaturalBase:
    """Shared behaviour of the typed natural quadrics: each holds its
    checked engine form (``_native``), so :func:`natural` reads no text."""

    kind: str = ""
    _native: _quadsect.NativeNatural

    def to_dict(self) -> Dict[str, Any]:
        """The JSON object form (numbers as exact strings), as the batch
        protocol and the CLI read it."""
        raise NotImplementedError

    def to_json(self) -> str:
        """The JSON object form as text."""
        return _json.dumps(self.to_dict(), separators=(",", ":"))

    def __str__(self) -> str:
        """The short syntax (``sphere center=0,0,0 radius2=1``)."""
        return str(self._native)


@_dataclass(frozen=True)
class Sphere(_NaturalBase):
    """A sphere ``|P - center|² = radius2`` (``radius2 > 0``).

    >>> Sphere((0, 0, 0), Fraction(9, 4))
    Sphere(center=(Fraction(0, 1), Fraction(0, 1), Fraction(0, 1)), radius2=Fraction(9, 4))
    >>> str(Sphere((1, 2, 3), "1/4"))
    'sphere center=1,2,3 radius2=1/4'
    """

    center: Vector
    radius2: Fraction
    kind = "sphere"

    def __post_init__(self) -> None:
        native, center, _, radius2 = _quadsect.natural_from_parts(
            "sphere", _vector(self.center, "center"), None, "radius2", self.radius2
        )
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "radius2", radius2)
        object.__setattr__(self, "_native", native)

    def to_dict(self) -> Dict[str, Any]:
        return {
            "kind": "sphere",
            "center": [_text(c) for c in self.center],
            "radius2": _text(self.radius2),
        }


@_dataclass(frozen=True)
class Cylinder(_NaturalBase):
    """A circular cylinder of squared radius ``radius2`` around the line
    through ``point`` with direction ``axis`` (non-zero, any length).

    >>> str(Cylinder((0, 0, 0), (1, 0, 0), 1))
    'cylinder point=0,0,0 axis=1,0,0 radius2=1'
    """

    point: Vector
    axis: Vector
    radius2: Fraction
    kind = "cylinder"

    def __post_init__(self) -> None:
        native, point, axis, radius2 = _quadsect.natural_from_parts(
            "cylinder",
            _vector(self.point, "point"),
            _vector(self.axis, "axis"),
            "radius2",
            self.radius2,
        )
        object.__setattr__(self, "point", point)
        object.__setattr__(self, "axis", axis)
        object.__setattr__(self, "radius2", radius2)
        object.__setattr__(self, "_native", native)

    def to_dict(self) -> Dict[str, Any]:
        return {
            "kind": "cylinder",
            "point": [_text(c) for c in self.point],
            "axis": [_text(c) for c in self.axis],
            "radius2": _text(self.radius2),
        }


@_dataclass(frozen=True, init=False)
class Cone(_NaturalBase):
    """A right circular double cone with vertex ``vertex``, axis direction
    ``axis`` and half-angle α given by exactly one of ``tan2 = tan²α``,
    ``tan``, ``cos2 = cos²α`` or ``sin2 = sin²α`` (stored as ``tan2``).

    >>> Cone((0, 0, 0), (0, 0, 1), cos2=Fraction(3, 4)).tan2
    Fraction(1, 3)
    >>> str(Cone((0, 0, 0), (1, 0, 0), tan2="1/3"))
    'cone vertex=0,0,0 axis=1,0,0 tan2=1/3'
    """

    vertex: Vector
    axis: Vector
    tan2: Fraction
    kind = "cone"

    def __init__(
        self,
        vertex: Sequence[Number],
        axis: Sequence[Number],
        tan2: Optional[Number] = None,
        *,
        tan: Optional[Number] = None,
        cos2: Optional[Number] = None,
        sin2: Optional[Number] = None,
    ) -> None:
        given = {k: v for k, v in (("tan2", tan2), ("tan", tan), ("cos2", cos2), ("sin2", sin2)) if v is not None}
        if len(given) != 1:
            raise InputError(
                "a cone needs exactly one of tan2, tan, cos2, sin2", "bad-quadric"
            )
        ((name, value),) = given.items()
        native, v, a, tan2 = _quadsect.natural_from_parts(
            "cone", _vector(vertex, "vertex"), _vector(axis, "axis"), name, value
        )
        object.__setattr__(self, "vertex", v)
        object.__setattr__(self, "axis", a)
        object.__setattr__(self, "tan2", tan2)
        object.__setattr__(self, "_native", native)

    def to_dict(self) -> Dict[str, Any]:
        return {
            "kind": "cone",
            "vertex": [_text(c) for c in self.vertex],
            "axis": [_text(c) for c in self.axis],
            "tan2": _text(self.tan2),
        }


def _natural_arg(q: NaturalLike, which: str) -> Union[str, _quadsect.NativeNatural]:
    """What the compiled ``natural`` takes: a typed quadric's engine form,
    or text."""
    if isinstance(q, _NaturalBase):
        return q._native
    if isinstance(q, str):
        return q
    if isinstance(q, _Mapping):
        return _json.dumps(_json_numbers(q))
    raise TypeError(
        f"{which} must be a str (short syntax or JSON), a dict, or a "
        f"Sphere/Cylinder/Cone, got {type(q).__name__}"
    )


# ------------------------------------------------------------ results


class _Result:
    """Shared behaviour: the CLI's JSON and human text."""

    def __init__(self, json_text: str, text: str) -> None:
        self._json: Dict[str, Any] = _json.loads(json_text)
        self._text = text

    def to_json(self) -> Dict[str, Any]:
        """The CLI's ``--json`` object (exact numbers as strings), a fresh copy."""
        return _json.loads(_json.dumps(self._json))

    @property
    def summary(self) -> str:
        """The human summary, as the CLI prints it without ``--json``."""
        return self._text

    def __str__(self) -> str:
        """The human summary (:attr:`summary`)."""
        return self._text

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other._json == self._json  # type: ignore[attr-defined]

    __hash__ = None  # type: ignore[assignment]


class TangentResult(_Result):
    """The answer of :func:`tangent`.

    ``verdict`` is ``"intersecting"``, ``"touching"``, ``"separated"`` or
    ``"undecided"``; ``min`` and ``max`` are the exact minimum ν and maximum
    μ of S on E (E and S intersect iff ν ≤ 0 ≤ μ, touch iff ν = 0 or μ = 0).
    """

    def __init__(
        self,
        json_text: str,
        text: str,
        min: Optional[RealAlgebraic],
        max: Optional[RealAlgebraic],
        critical_values: List[RealAlgebraic],
        nonreal_point_values: List[RealAlgebraic],
        undecided: Optional[Tuple[str, str]],
        inputs: Optional[Tuple[str, str, Optional[float], bool]] = None,
    ) -> None:
        super().__init__(json_text, text)
        # (ellipsoid, surface, time_limit, values): what svg() draws again
        self._inputs = inputs
        self.min = min
        self.max = max
        #: The real critical values of S on E (increasing), exactly.
        self.critical_values = critical_values
        #: Real values of S at non-real critical points (roots of D(u) that are no critical value).
        self.nonreal_point_values = nonreal_point_values
        #: For an undecided verdict, why: ``"budget"`` or ``"no-certificate"``.
        self.undecided_kind: Optional[str] = undecided[0] if undecided else None
        #: For an undecided verdict, the reason in words.
        self.reason: Optional[str] = undecided[1] if undecided else None

    @property
    def verdict(self) -> str:
        """``"intersecting"``, ``"touching"``, ``"separated"`` or ``"undecided"``."""
        return self._json["verdict"]

    @property
    def intersect(self) -> Optional[bool]:
        """E and S meet (ν ≤ 0 ≤ μ); ``None`` when undecided."""
        return self._json["intersect"]

    @property
    def touching(self) -> Optional[bool]:
        """They meet without crossing (ν = 0 or μ = 0); ``None`` when undecided."""
        return self._json["touching"]

    @property
    def side(self) -> Optional[str]:
        """``"+"`` or ``"-"``: the sign of S on E when it does not change."""
        return self._json["side"]

    @property
    def containment(self) -> Optional[str]:
        """``"E-inside-S"``, ``"S-inside-E"`` or ``"apart"`` when S is an
        ellipsoid and they do not intersect, ``"coincident"`` when S = c·E
        (verdict ``"touching"``), else ``None``."""
        return self._json["containment"]

    @property
    def judging_poly(self) -> Optional[str]:
        """The judging polynomial D(u) (square-free, integer coefficients);
        ``None`` when the values were skipped (``values=False``)."""
        return self._json["judging_poly"]

    @property
    def values_skipped(self) -> bool:
        """True when the verdict was decided without the exact critical
        values (``tangent(..., values=False)``): ``min``, ``max`` and
        ``judging_poly`` are then ``None``."""
        return self._json["judging_poly"] is None

    @property
    def certificate(self) -> Dict[str, Any]:
        """The certificate (the JSON ``certificate`` object with exact
        rationals as ``Fraction``; approximations and polynomials as str)."""
        return _decode(self._json["certificate"])

    def svg(self) -> str:
        """The picture of the answer as SVG text: E from two opposite sides,
        shaded by the sign of S (red S > 0, blue S < 0), the curve S = 0 on
        E, the certificate's witness points, and a legend with the verdict
        and the extreme values (the CLI's ``tangent --svg``).  The answer is
        computed again from the inputs (a few milliseconds for quadrics).

        >>> svg = quadsect.tangent("x^2+y^2+z^2-25", "(x-6)^2/9+y^2/4+z^2/16-1").svg()
        >>> svg.startswith("<svg"), "verdict: intersecting" in svg
        (True, True)
        """
        if self._inputs is None:
            raise ValueError("this result does not know its inputs (built by hand)")
        return _quadsect.tangent_svg(*self._inputs)

    def _repr_svg_(self) -> str:
        """The picture, for Jupyter."""
        return self.svg()

    def __repr__(self) -> str:
        return f"TangentResult(verdict={self.verdict!r}, min={self.min!r}, max={self.max!r})"

    def __reduce__(self):
        return (_rebuild_tangent, (_json.dumps(self._json), self._text, self.min, self.max,
                                   self.critical_values, self.nonreal_point_values,
                                   (self.undecided_kind, self.reason) if self.reason else None,
                                   self._inputs))


def _rebuild_tangent(*args: Any) -> TangentResult:
    return TangentResult(*args)


@_dataclass(frozen=True)
class Referee:
    """The stability of a natural answer (:attr:`NaturalResult.referee`),
    in relative perturbation sizes: each quadric's point ``p``, axis ``a``
    and parameter ``s`` (``radius2`` or ``tan2``) moving by at most
    ``size·L``, ``size·max|aᵢ|`` and ``size·|s|`` per coordinate, ``L`` the
    scene's length (the points' ``max|pᵢ|``, the spheres' and cylinders'
    radii rounded up to powers of two).

    ``lo`` is proved: every input within it has the same class and counts
    (``0`` when nothing is proved, with :attr:`lo_reason`).  ``hi`` is
    witnessed: :attr:`nearby` (two quadrics in the JSON object form, exact,
    accepted by :func:`natural`) is exactly that far and its exact answer
    is :attr:`nearby_answer` (``class``, ``conics``, ``lines``, ``points``),
    which differs; ``None`` when no witness was found (:attr:`reason`)."""

    lo: Fraction
    hi: Optional[Fraction]
    nearby: Optional[Tuple[Dict[str, Any], Dict[str, Any]]]
    nearby_answer: Optional[Dict[str, Any]]
    lo_reason: Optional[str]
    reason: Optional[str]


class NaturalResult:
    """The answer of :func:`natural`: the class of the intersection, the
    counts of real affine conics, lines and isolated points, and each
    component, typed, with exact data (:attr:`components`).

    Running out of budget is an answer, not an error: ``classification ==
    "undecided"``, the counts are ``None``, :attr:`undecided_kind` is
    ``"budget"`` and :attr:`reason` says which limit ran out.

    The parts are read from the engine's answer when first asked for: the
    components, the JSON (:meth:`to_json`) and the :attr:`summary` cost
    nothing until then."""

    __slots__ = ("_report", "_head", "_json_text", "_text", "_components")

    def __init__(
        self,
        report: Optional[_quadsect.NativeReport],
        head: tuple,
        json_text: Optional[str] = None,
        text: Optional[str] = None,
        components: Optional[Tuple[Component, ...]] = None,
    ) -> None:
        # the engine's report, or None for a result rebuilt by pickle (then
        # json_text, text and components are given)
        self._report = report
        # (class, conics, lines, points, axes, thm8, method, reason)
        self._head = head
        self._json_text = json_text
        self._text = text
        self._components = components

    def _json_str(self) -> str:
        if self._json_text is None:
            self._json_text = self._report.json()  # type: ignore[union-attr]
        return self._json_text

    def _components_tuple(self) -> Tuple[Component, ...]:
        if self._components is None:
            self._components = tuple(_component(t) for t in self._report.components())  # type: ignore[union-attr]
        return self._components

    def to_json(self) -> Dict[str, Any]:
        """The CLI's ``--json`` object (exact numbers as strings), a fresh copy."""
        return _json.loads(self._json_str())

    @property
    def summary(self) -> str:
        """The human summary, as the CLI prints it without ``--json``."""
        if self._text is None:
            self._text = self._report.text()  # type: ignore[union-attr]
        return self._text

    def __str__(self) -> str:
        """The human summary (:attr:`summary`)."""
        return self.summary

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.to_json() == self.to_json()  # type: ignore[attr-defined]

    __hash__ = None  # type: ignore[assignment]

    @property
    def classification(self) -> str:
        """``"same-surface"``, ``"conics"``, ``"conic-and-line"``, ``"lines"``,
        ``"points"``, ``"empty"``, ``"curve"``, or ``"undecided"`` (the
        budget ran out)."""
        return self._head[0]

    @property
    def undecided_kind(self) -> Optional[str]:
        """For an undecided answer, why: ``"budget"``; else ``None``."""
        r = self._head[7]
        return r[0] if r is not None else None

    @property
    def reason(self) -> Optional[str]:
        """For an undecided answer, the reason in words (which limit ran
        out); else ``None``."""
        r = self._head[7]
        return r[1] if r is not None else None

    @property
    def conics(self) -> Optional[int]:
        """Real affine conics (a double conic counts once); ``None`` when undecided."""
        return self._head[1]

    @property
    def lines(self) -> Optional[int]:
        """Real affine lines (a double line counts once); ``None`` when undecided."""
        return self._head[2]

    @property
    def points(self) -> Optional[int]:
        """Isolated real points on no other component (acnodes of a curve
        included); ``None`` when undecided."""
        return self._head[3]

    @property
    def axes(self) -> Optional[str]:
        """``"coplanar-intersecting"``, ``"parallel"``, ``"coincident"``,
        ``"skew"``, or ``None`` when a sphere is involved."""
        return self._head[4]

    @property
    def thm8(self) -> Optional[bool]:
        """The closed-form test of Theorems 8.1/8.2 where it applies."""
        return self._head[5]

    @property
    def components(self) -> List[Component]:
        """The components: :class:`Conic`, :class:`Line`, :class:`Point` and
        :class:`Curve` objects with exact numbers (``Fraction``,
        :class:`QuadraticIrrational`, :class:`RealAlgebraic`) and, beside
        each numeric field ``x``, its certified doubles ``x_f64`` (pairs
        ``(value, bound)`` with ``|exact − value| ≤ bound``).  Built when
        first asked for.  Empty when undecided or asked for without
        components (``natural(a, b, components=False)``)."""
        return list(self._components_tuple())

    @property
    def route(self) -> Optional[str]:
        """``"fast"`` or ``"complete"`` for an answer without components
        (the complete route answers where the fast one cannot decide),
        else ``None``."""
        return self.to_json().get("route")

    @property
    def method(self) -> str:
        """How the class was decided, in words."""
        return self._head[6]

    @property
    def referee(self) -> Optional["Referee"]:
        """How far the input is from a different answer (asked for with
        ``natural(a, b, referee=True)``; else ``None``): a :class:`Referee`.

        >>> r = quadsect.natural("sphere center=0,0,0 radius2=1",
        ...                      "sphere center=3/2,0,0 radius2=1", referee=True)
        >>> f = r.referee
        >>> 0 < f.lo < f.hi, f.nearby_answer["class"] != r.classification
        (True, True)
        >>> quadsect.natural(*f.nearby).classification == f.nearby_answer["class"]
        True
        """
        j = self.to_json().get("referee")
        if j is None:
            return None
        near = j["nearby"]
        return Referee(
            lo=_Fraction(j["lo_exact"]),
            hi=None if j["hi_exact"] is None else _Fraction(j["hi_exact"]),
            nearby=None if near is None else (near["a"], near["b"]),
            nearby_answer=None if near is None else near["answer"],
            lo_reason=j["lo_reason"],
            reason=j["reason"],
        )

    @property
    def notes(self) -> List[str]:
        """Remarks."""
        return list(self.to_json().get("notes", []))

    def svg(self) -> str:
        """The picture of the answer as SVG text: a 3D view of both surfaces
        with the components drawn thick and coloured by kind, the axial
        plane of the paper's figures when the axes are coplanar, and a
        legend with the class, the counts and the route (the CLI's
        ``natural --svg``).

        >>> r = quadsect.natural("sphere center=0,0,0 radius2=4", "sphere center=3,0,0 radius2=4")
        >>> "class conics" in r.svg()
        True
        """
        if self._report is None:
            # rebuilt by pickle: the quadrics are in the JSON
            j = self.to_json()
            return natural(_json.dumps(j["a"]), _json.dumps(j["b"])).svg()
        return self._report.svg()

    def _repr_svg_(self) -> str:
        """The picture, for Jupyter."""
        return self.svg()

    def __repr__(self) -> str:
        return (
            f"NaturalResult(classification={self.classification!r}, conics={self.conics}, "
            f"lines={self.lines}, points={self.points})"
        )

    def __reduce__(self):
        return (
            _rebuild_natural,
            (self._head, self._json_str(), self.summary, self._components_tuple()),
        )


def _rebuild_natural(
    head: tuple, json_text: str, text: str, components: Tuple[Component, ...]
) -> NaturalResult:
    return NaturalResult(None, head, json_text, text, components)


class RootsResult(_Result, _Sequence[RealAlgebraic]):
    """The answer of :func:`roots`: a sequence of the distinct real roots
    (increasing, as :class:`RealAlgebraic`), with counts and multiplicities."""

    def __init__(self, json_text: str, text: str, roots: List[Tuple[RealAlgebraic, int]]) -> None:
        super().__init__(json_text, text)
        self._roots = [r for r, _ in roots]
        #: The multiplicity of each root, in order.
        self.multiplicities: List[int] = [m for _, m in roots]

    @_overload
    def __getitem__(self, i: int) -> RealAlgebraic: ...
    @_overload
    def __getitem__(self, i: slice) -> List[RealAlgebraic]: ...
    def __getitem__(self, i):  # type: ignore[no-untyped-def]
        return self._roots[i]

    def __len__(self) -> int:
        return len(self._roots)

    def __iter__(self) -> Iterator[RealAlgebraic]:
        return iter(self._roots)

    @property
    def roots(self) -> List[RealAlgebraic]:
        """The distinct real roots, increasing."""
        return list(self._roots)

    @property
    def distinct_real(self) -> int:
        """Number of distinct real roots."""
        return self._json["distinct_real"]

    @property
    def positive(self) -> int:
        """Distinct positive roots."""
        return self._json["positive"]

    @property
    def negative(self) -> int:
        """Distinct negative roots."""
        return self._json["negative"]

    @property
    def zero_multiplicity(self) -> int:
        """Multiplicity of the root 0 (0 when 0 is no root)."""
        return self._json["zero_multiplicity"]

    @property
    def real_with_multiplicity(self) -> int:
        """Real roots counted with multiplicity."""
        return self._json["real_with_multiplicity"]

    @property
    def descartes_bounds(self) -> Tuple[int, int]:
        """Descartes' bounds on the positive and negative roots."""
        return (self._json["descartes_positive_bound"], self._json["descartes_negative_bound"])

    @property
    def intervals(self) -> List[Tuple[Fraction, Fraction]]:
        """One isolating interval per distinct real root (``lo == hi`` for
        an exact rational root)."""
        return [(_Fraction(lo), _Fraction(hi)) for lo, hi in self._json["intervals"]]

    def __repr__(self) -> str:
        return f"RootsResult({self._roots!r})"

    def __reduce__(self):
        return (RootsResult, (_json.dumps(self._json), self._text,
                              list(zip(self._roots, self.multiplicities))))


class ResultantResult(_Result):
    """The answer of :func:`resultant`; ``str()`` is the resultant."""

    @property
    def resultant(self) -> str:
        """``Res_var(f, g)`` in canonical form."""
        return self._json["resultant"]

    @property
    def degree(self) -> Optional[int]:
        """Its total degree (``None`` for the zero polynomial)."""
        d = self._json["degree"]
        return d if d is not None and d >= 0 else None

    def __str__(self) -> str:
        """The resultant (the human summary is :attr:`summary`)."""
        return self.resultant

    def __repr__(self) -> str:
        return f"ResultantResult({self.resultant!r})"

    def __reduce__(self):
        return (ResultantResult, (_json.dumps(self._json), self._text))


# --------------------------------------------------------------- jobs


def tangent(
    ellipsoid: str,
    surface: str,
    *,
    time_limit: Optional[float] = None,
    values: bool = True,
) -> TangentResult:
    """How the ellipsoid ``E = 0`` and the surface ``S = 0`` meet (the tangent
    point method), exactly.

    ``time_limit`` is in seconds (``None``: :data:`DEFAULT_TIME_LIMIT`;
    ``math.inf``: none).  Running out of time is an answer, not an error:
    ``verdict == "undecided"`` with ``undecided_kind == "budget"`` and the
    ``reason``.  Bad input raises :class:`InputError`.

    ``values=False`` asks for the verdict and its certificate only: for a
    surface of degree ≥ 3 in general position the judging polynomial D(u)
    and the exact ``min``/``max`` are then skipped (``None``;
    ``values_skipped`` is true) and the sign of S at each real critical
    point is proven by an interval enclosure — about twice as fast.

    >>> r = quadsect.tangent("x^2+y^2+z^2-25", "(x-6)^2/9+y^2/4+z^2/16-1")
    >>> r.verdict, r.intersect, r.side
    ('intersecting', True, None)
    >>> r.min < 0 < r.max
    True
    >>> v = quadsect.tangent("x^2+2y^2+3z^2-6", "x^3-2x*y+z^2+y*z-1", values=False)
    >>> v.verdict, v.values_skipped, v.min
    ('intersecting', True, None)
    """
    return TangentResult(*_quadsect.tangent(ellipsoid, surface, time_limit, values),
                         inputs=(ellipsoid, surface, time_limit, values))


def natural(
    a: NaturalLike,
    b: NaturalLike,
    *,
    time_limit: Optional[float] = None,
    components: bool = True,
    referee: bool = False,
) -> NaturalResult:
    """How two natural quadrics meet, exactly.

    ``a`` and ``b`` are each a :class:`Sphere`, :class:`Cylinder` or
    :class:`Cone` (the fastest: their checked form is passed as is), the
    short syntax (``"cone vertex=0,0,0 axis=1,0,0 tan2=1/3"``), JSON text,
    or a dict of the JSON object form (numbers may be
    int/Fraction/float/str).  ``components=False`` asks for the class and
    counts only (the fast route: same class and counts, much quicker).
    ``time_limit`` is in seconds as for :func:`tangent`; running out is an
    answer: ``classification == "undecided"`` with the
    :attr:`~NaturalResult.reason`.  ``referee=True`` adds
    :attr:`~NaturalResult.referee`: how far the input is from a different
    answer (a :class:`Referee`).

    >>> r = quadsect.natural(Cylinder((0, 0, 0), (1, 0, 0), 1),
    ...                      "cylinder point=0,0,0 axis=0,1,0 radius2=1")
    >>> r.classification, r.conics
    ('conics', 2)
    >>> e = r.components[0]
    >>> e
    Conic('ellipse', center=(0, 0, 0), semi_axes2=(2, 1), plane=Plane(normal=(1, -1, 0), offset=0))
    >>> e.semi_axes2, e.axis_directions
    ((Fraction(2, 1), Fraction(1, 1)), ((Fraction(1, 1), Fraction(1, 1), Fraction(0, 1)), (Fraction(0, 1), Fraction(0, 1), Fraction(1, 1))))
    >>> value, bound = e.semi_axes2_f64[0]   # a double and a proven error bound
    >>> value, abs(value - e.semi_axes2[0]) <= bound
    (2.0, True)
    """
    report, head = _quadsect.natural(
        _natural_arg(a, "a"), _natural_arg(b, "b"), time_limit, components, referee
    )
    return NaturalResult(report, head)


def roots(poly: str, *, time_limit: Optional[float] = None) -> RootsResult:
    """The real roots of a univariate polynomial, exactly: a sequence of
    :class:`RealAlgebraic` (distinct, increasing) with counts.  An exhausted
    budget raises :class:`BudgetError`.

    >>> r = quadsect.roots("x^3 - 2x")
    >>> len(r), r.positive, [float(x) for x in r]
    (3, 1, [-1.4142135623730951, 0.0, 1.4142135623730951])
    >>> r[1] == 0, r.intervals[1]
    (True, (Fraction(0, 1), Fraction(0, 1)))
    """
    return RootsResult(*_quadsect.roots(poly, time_limit))


def resultant(f: str, g: str, var: str, *, time_limit: Optional[float] = None) -> ResultantResult:
    """The resultant ``Res_var(f, g)``, exactly (``var`` is ``"x"``, ``"y"``,
    ``"z"`` or ``"u"``).  An exhausted budget raises :class:`BudgetError`.

    >>> r = quadsect.resultant("x^2 + y^2 - 1", "x - y", "x")
    >>> str(r), r.degree
    ('2*y^2 - 1', 2)
    """
    return ResultantResult(*_quadsect.resultant(f, g, var, time_limit))


def batch(
    lines: Iterable[Union[str, bytes]],
    threads: Optional[int] = None,
    *,
    time_limit: Optional[float] = None,
    echo: bool = False,
) -> Iterator[str]:
    """The answers to batch lines (the protocol of ``quadsect batch``), one
    per line, in order, streamed: each answer is :func:`answer_line` of its
    line.  The lines are answered on ``threads`` Rust worker threads
    (default: the number of CPUs) with the GIL released, reading at most
    ``32 * threads`` lines ahead of the answer returned, so an endless or
    huge input streams in bounded memory.  ``lines`` may be a file object.
    Each line runs under its own budget: ``time_limit`` seconds (``None``:
    :data:`DEFAULT_TIME_LIMIT`), as ``quadsect batch --time-limit``.
    ``echo=True`` puts each line, verbatim, into its answer as
    ``"request"`` (``quadsect batch --echo``), the input of the independent
    checker ``quadsect_check``.

    >>> lines = ['{"id": 1, "op": "roots", "poly": "x^2 - 2"}',
    ...          '{"id": 2, "op": "resultant", "f": "x^2+y^2-1", "g": "x-y", "var": "x"}']
    >>> [json.loads(a)["id"] for a in quadsect.batch(lines, threads=2)]
    [1, 2]
    """
    return _quadsect.Batch(lines, threads, time_limit, echo)
