"""The components of two natural quadrics' intersection, typed.

:attr:`quadsect.NaturalResult.components` is a list of :class:`Conic`,
:class:`Line`, :class:`Point` and :class:`Curve` (with
:class:`SingularPoint` and :class:`CurveBranch`).  Every number is exact:
a ``Fraction`` when rational, a :class:`~quadsect.QuadraticIrrational`
``a + b√d`` where one square root is taken, a
:class:`~quadsect.RealAlgebraic` where square roots nest.  Points and
vectors are tuples of three.

**Certified doubles.**  Every numeric field ``x`` has a twin ``x_f64`` of
the same shape in which each number is a pair ``(value, bound)``: a double
and a proven bound on its error, ``|exact − value| ≤ bound`` (a few units in
the last place, at most ``2**-46 * abs(value)``; 0 when the exact number is
itself a double).  A :class:`CurveBranch`'s point is given this way only
(``point_f64``): its exact coordinates nest square roots.  The same pairs
are the ``"f64"`` blocks of the CLI's ``--json``.

All classes are frozen dataclasses: comparable, hashable, picklable.

**The dict form.**  Before these classes, components were dicts of the
CLI's ``--json`` (exact rationals as ``Fraction``, ``a + b√d`` as ``{"a",
"b", "d", "approx"}``, lists for vectors).  That form stays available:
``component.to_dict()`` returns it, and ``component["semi_axes2"]``,
``component.get(key)``, ``component.keys()`` and ``key in component`` read
it, so code written for the dicts keeps working.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any, ClassVar, Dict, Iterator, List, Literal, Optional, Tuple, Union

from ._quadsect import QuadraticIrrational, RealAlgebraic

__all__ = [
    "Plane",
    "Conic",
    "Line",
    "Point",
    "SingularPoint",
    "CurveBranch",
    "Curve",
    "Component",
    "ExactNumber",
    "Certified",
]

ExactNumber = Union[Fraction, QuadraticIrrational, RealAlgebraic]
"""An exact real number of a component: ``Fraction``,
:class:`~quadsect.QuadraticIrrational` (``a + b√d``) or
:class:`~quadsect.RealAlgebraic`."""

Certified = Tuple[float, float]
"""``(value, bound)``: a double and a proven bound on its error,
``|exact − value| ≤ bound``."""

Vector = Tuple[ExactNumber, ExactNumber, ExactNumber]
Vector64 = Tuple[Certified, Certified, Certified]


def _num(x: Any) -> str:
    """A short exact spelling of a number (``1/3``, ``1 + 4·√(2)``, ``≈0.7071``)."""
    if isinstance(x, RealAlgebraic):
        return "≈" + x.approx(6)
    return str(x)


def _vec(v: Any) -> str:
    return "(" + ", ".join(_num(x) for x in v) + ")"


def _approx(v: Vector64) -> str:
    return "(" + ", ".join(f"{x:.6g}" for x, _ in v) + ")"


def _exact_dict(x: Any) -> Any:
    """A number as the dict form spells it (the CLI's JSON, rationals as
    ``Fraction``)."""
    if isinstance(x, Fraction):
        return x
    if isinstance(x, QuadraticIrrational):
        return {"a": x.a, "b": x.b, "d": x.d, "approx": x.approx(20)}
    if isinstance(x, RealAlgebraic):
        j = x.to_json()
        return {"poly": j["poly"], "interval": [Fraction(c) for c in j["interval"]], "approx": j["approx"]}
    if x is None:
        return None
    if isinstance(x, tuple):
        return [_exact_dict(c) for c in x]
    return x


def _f64_dict(x: Any) -> Any:
    """Certified doubles as the dict form spells them (lists)."""
    if x is None:
        return None
    if isinstance(x, tuple):
        return [_f64_dict(c) for c in x]
    return x


class _DictForm:
    """Read access to the dict form (:meth:`to_dict`) by key, as the
    components were before they were typed."""

    __slots__ = ()

    def to_dict(self) -> Dict[str, Any]:  # pragma: no cover - overridden
        raise NotImplementedError

    def __getitem__(self, key: str) -> Any:
        return self.to_dict()[key]

    def get(self, key: str, default: Any = None) -> Any:
        """``to_dict().get(key, default)``."""
        return self.to_dict().get(key, default)

    def keys(self) -> List[str]:
        """The keys of the dict form."""
        return list(self.to_dict())

    def __contains__(self, key: object) -> bool:
        return key in self.to_dict()

    def __iter__(self) -> Iterator[str]:
        return iter(self.to_dict())


@dataclass(frozen=True, repr=False)
class Plane:
    """The plane ``normal · P = offset`` of a conic.

    A plane with rational coefficients is scaled to a primitive integer
    ``normal`` whose first non-zero component is positive (``offset``
    scaled alike).

    >>> Plane((0, 1, -1), 0, ((0.0, 0.0), (1.0, 0.0), (-1.0, 0.0)), (0.0, 0.0))
    Plane(normal=(0, 1, -1), offset=0)
    """

    normal: Vector
    offset: ExactNumber
    normal_f64: Vector64
    offset_f64: Certified

    def __repr__(self) -> str:
        return f"Plane(normal={_vec(self.normal)}, offset={_num(self.offset)})"

    def to_dict(self) -> Dict[str, Any]:
        """``{"normal", "offset"}`` as in the CLI's JSON."""
        return {"normal": _exact_dict(self.normal), "offset": _exact_dict(self.offset)}


@dataclass(frozen=True, repr=False)
class Conic(_DictForm):
    """A real conic of the intersection: ``kind`` is ``"circle"``,
    ``"ellipse"``, ``"hyperbola"`` or ``"parabola"``; it lies in
    :attr:`plane`.

    With ``u₁, u₂`` the unit vectors along :attr:`axis_directions` and
    ``a₁, a₂`` the squared semi-axes :attr:`semi_axes2`, the conic is the
    set of points ``center + x·u₁ + y·u₂`` with

    * ellipse (circle: ``a₁ = a₂``, and the directions are any two
      orthogonal ones in the plane): ``x²/a₁ + y²/a₂ = 1``;
    * hyperbola (transverse axis first): ``x²/a₁ − y²/a₂ = 1``;
    * parabola: ``center`` and ``semi_axes2`` are empty (``None``, ``()``),
      the one axis direction ``u`` points from the :attr:`vertex` ``V``
      into the parabola, and with ``f² =`` :attr:`focal_length2` (the
      squared distance from the vertex to the focus) and ``w`` the unit
      vector of the plane orthogonal to ``u``, the points are
      ``V + x·u + y·w`` with ``y² = 4·f·x``.

    Rational directions are scaled to primitive integer vectors.
    ``double`` is true when the surfaces are tangent along the conic.
    Each numeric field has its certified double in ``<field>_f64``.
    """

    type: ClassVar[str] = "conic"

    kind: Literal["circle", "ellipse", "hyperbola", "parabola"]
    plane: Plane
    center: Optional[Vector]
    vertex: Optional[Vector]
    semi_axes2: Tuple[ExactNumber, ...]
    axis_directions: Tuple[Vector, ...]
    focal_length2: Optional[ExactNumber]
    double: bool
    center_f64: Optional[Vector64]
    vertex_f64: Optional[Vector64]
    semi_axes2_f64: Tuple[Certified, ...]
    axis_directions_f64: Tuple[Vector64, ...]
    focal_length2_f64: Optional[Certified]

    def __repr__(self) -> str:
        if self.kind == "parabola":
            where = f"vertex={_vec(self.vertex)}, focal_length2={_num(self.focal_length2)}"
        else:
            axes = ", ".join(_num(a) for a in self.semi_axes2)
            where = f"center={_vec(self.center)}, semi_axes2=({axes})"
        double = ", double" if self.double else ""
        return f"Conic({self.kind!r}, {where}, plane={self.plane!r}{double})"

    def to_dict(self) -> Dict[str, Any]:
        """The dict form: the component as in the CLI's ``--json``, exact
        rationals as ``Fraction`` (see the module's documentation)."""
        return {
            "type": "conic",
            "conic": self.kind,
            "plane": self.plane.to_dict(),
            "center": _exact_dict(self.center),
            "vertex": _exact_dict(self.vertex),
            "semi_axes2": _exact_dict(self.semi_axes2),
            "axis_directions": _exact_dict(self.axis_directions),
            "focal_length2": _exact_dict(self.focal_length2),
            "double": self.double,
            "f64": {
                "plane": {
                    "normal": _f64_dict(self.plane.normal_f64),
                    "offset": _f64_dict(self.plane.offset_f64),
                },
                "center": _f64_dict(self.center_f64),
                "vertex": _f64_dict(self.vertex_f64),
                "semi_axes2": _f64_dict(self.semi_axes2_f64),
                "axis_directions": _f64_dict(self.axis_directions_f64),
                "focal_length2": _f64_dict(self.focal_length2_f64),
            },
        }


@dataclass(frozen=True, repr=False)
class Line(_DictForm):
    """A real line of the intersection: the points ``point + t·direction``
    (``t`` real).  A rational direction is scaled to a primitive integer
    vector.  ``double`` is true when the surfaces are tangent along it (a
    double line counts once).  Certified doubles: ``point_f64``,
    ``direction_f64``.
    """

    type: ClassVar[str] = "line"

    point: Vector
    direction: Vector
    double: bool
    point_f64: Vector64
    direction_f64: Vector64

    def __repr__(self) -> str:
        double = ", double" if self.double else ""
        return f"Line(point={_vec(self.point)}, direction={_vec(self.direction)}{double})"

    def to_dict(self) -> Dict[str, Any]:
        """The dict form (as in the CLI's ``--json``)."""
        return {
            "type": "line",
            "point": _exact_dict(self.point),
            "direction": _exact_dict(self.direction),
            "double": self.double,
            "f64": {"point": _f64_dict(self.point_f64), "direction": _f64_dict(self.direction_f64)},
        }


@dataclass(frozen=True, repr=False)
class Point(_DictForm):
    """An isolated real point of the intersection: ``kind`` is
    ``"tangency"`` (the surfaces touch there), ``"vertex"`` (a cone's vertex
    alone on the other surface) or ``"acnode"`` (an isolated singular point
    of the intersection curve).  Certified double: ``point_f64``.
    """

    type: ClassVar[str] = "point"

    point: Vector
    kind: Literal["tangency", "vertex", "acnode"]
    point_f64: Vector64

    def __repr__(self) -> str:
        return f"Point({self.kind!r}, {_vec(self.point)})"

    def to_dict(self) -> Dict[str, Any]:
        """The dict form (as in the CLI's ``--json``)."""
        return {
            "type": "point",
            "point": _exact_dict(self.point),
            "kind": self.kind,
            "f64": {"point": _f64_dict(self.point_f64)},
        }


@dataclass(frozen=True, repr=False)
class SingularPoint:
    """A real singular point of an intersection :class:`Curve`: ``kind``
    is ``"acnode"`` (an isolated real point: the tangent cone is
    imaginary; ``isolated`` is true, and it counts in
    :attr:`NaturalResult.points <quadsect.NaturalResult.points>`),
    ``"crossing"`` (two real branches cross), ``"cusp"`` (the tangent cone
    is a double line) or ``"tacnode"`` (two real branches touch).
    Certified double: ``point_f64``.
    """

    point: Vector
    kind: Literal["acnode", "crossing", "cusp", "tacnode"]
    isolated: bool
    point_f64: Vector64

    def __repr__(self) -> str:
        return f"SingularPoint({self.kind!r}, {_vec(self.point)})"

    def to_dict(self) -> Dict[str, Any]:
        """``{"point", "kind", "isolated"}`` as in the CLI's JSON."""
        return {"point": _exact_dict(self.point), "kind": self.kind, "isolated": self.isolated}


@dataclass(frozen=True, repr=False)
class CurveBranch:
    """One real affine connected component of an intersection
    :class:`Curve`: ``bounded`` (a closed loop) or not (both ends go to
    infinity), and a point on it.

    The point is given as certified doubles, ``point_f64``, and exactly as
    a root of the other quadric along a ruling of the cylinder or cone:
    ``P = ruling_point + t·ruling_direction`` (both exact, in one field
    Q(√d)), where ``t`` is the root of ``A·t² + 2B·t + C`` (``quadratic
    = (A, B, C)``, a positive multiple of the other quadric's equation
    along the ruling) given by ``t = (−B + root·√(B² − A·C))/A`` with
    ``root`` = ±1, or, when ``root`` is 0, by ``t`` itself (exact, in the
    ruling's field: the cone's apex or the cylinder's point at infinity
    lies on the other quadric).  Certified doubles: ``ruling_point_f64``,
    ``ruling_direction_f64``, ``quadratic_f64``, ``t_f64``.
    """

    bounded: bool
    point_f64: Vector64
    ruling_point: Vector
    ruling_direction: Vector
    quadratic: Tuple[ExactNumber, ExactNumber, ExactNumber]
    root: int
    t: Optional[ExactNumber]
    ruling_point_f64: Vector64
    ruling_direction_f64: Vector64
    quadratic_f64: Vector64
    t_f64: Optional[Certified]

    def __repr__(self) -> str:
        return f"CurveBranch(bounded={self.bounded}, point≈{_approx(self.point_f64)})"

    def to_dict(self) -> Dict[str, Any]:
        """The branch as in the CLI's JSON: ``bounded``, ``point`` (the
        certified doubles), ``ruling`` and ``along_ruling``."""
        a, b, c = self.quadratic
        return {
            "bounded": self.bounded,
            "point": _f64_dict(self.point_f64),
            "ruling": {"point": _exact_dict(self.ruling_point), "direction": _exact_dict(self.ruling_direction)},
            "along_ruling": {
                "a": _exact_dict(a),
                "b": _exact_dict(b),
                "c": _exact_dict(c),
                "root": self.root,
                "t": _exact_dict(self.t),
            },
        }


@dataclass(frozen=True, repr=False)
class Curve(_DictForm):
    """A genuine space curve of the intersection (not made of lines and
    conics): a quartic, or a twisted cubic beside a common line
    (``degree`` 4 or 3), with its real affine singular points
    (:class:`SingularPoint`) and its real connected components
    (:class:`CurveBranch`, one per branch; :attr:`real_components` counts
    them).
    """

    type: ClassVar[str] = "curve"

    degree: int
    singular_points: Tuple[SingularPoint, ...]
    branches: Tuple[CurveBranch, ...]

    @property
    def real_components(self) -> int:
        """The number of real affine connected components (branches)."""
        return len(self.branches)

    def __repr__(self) -> str:
        bounded = sum(b.bounded for b in self.branches)
        sing = ", ".join(repr(s) for s in self.singular_points)
        return (
            f"Curve(degree={self.degree}, singular_points=[{sing}], "
            f"branches={len(self.branches)} ({bounded} bounded))"
        )

    def to_dict(self) -> Dict[str, Any]:
        """The dict form (as in the CLI's ``--json``)."""
        return {
            "type": "curve",
            "degree": self.degree,
            "singular_points": [s.to_dict() for s in self.singular_points],
            "real_components": self.real_components,
            "branches": [b.to_dict() for b in self.branches],
            "f64": {"singular_points": [_f64_dict(s.point_f64) for s in self.singular_points]},
        }


Component = Union[Conic, Line, Point, Curve]
"""A component of the intersection of two natural quadrics."""


def _component(t: tuple) -> Component:
    """A component from the compiled half's tuple (``NativeReport.components``)."""
    tag = t[0]
    if tag == "conic":
        return Conic(t[1], Plane(*t[2]), *t[3:])
    if tag == "line":
        return Line(*t[1:])
    if tag == "point":
        return Point(*t[1:])
    if tag == "curve":
        return Curve(
            t[1],
            tuple(SingularPoint(*s) for s in t[2]),
            tuple(CurveBranch(*b) for b in t[3]),
        )
    raise ValueError(f"unknown component type {tag!r}")
