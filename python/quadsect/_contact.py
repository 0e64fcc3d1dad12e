"""Ellipsoid–ellipsoid contact: exact, in bulk over NumPy arrays.

An ellipsoid is given as a physics code holds it — a centre ``c``, semi-axes
``r`` (all > 0) and an invertible 3×3 matrix ``R`` (a rotation, or any
invertible matrix) — and denotes ``{c + R·diag(r)·u : |u| ≤ 1}`` with every
double taken at its exact binary value (``R⁻¹`` is the exact inverse of the
given doubles: a rotation rounded to doubles is not exactly orthogonal, and
the ellipsoid is the one those numbers define).  The answer is exact.
"""

from __future__ import annotations

import enum
import json
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Any, Mapping, Optional, Sequence, Union

from . import _quadsect
from ._errors import BudgetError, InputError, InternalError


class Contact(enum.IntEnum):
    """The codes of :func:`ellipsoid_contact`."""

    SEPARATED = 0
    TOUCHING = 1
    OVERLAPPING = 2


@dataclass(frozen=True)
class ContactReport:
    """The answer for one pair: ``contact``, the ``kind`` of an overlap
    (``surfaces-cross``, ``A-inside-B``, ``B-inside-A``,
    ``internally-touching``, ``identical``; ``separated`` or
    ``externally-touching`` otherwise), the ``route`` (``filter``: doubles
    decided, ``exact``) and the ``certificate`` (docs/contract.md,
    "Ellipsoid contact"; exact numbers as strings ``p/q``), which
    ``python3 -m quadsect_check`` re-checks."""

    contact: Contact
    kind: str
    route: str
    certificate: Mapping[str, Any]
    json: Mapping[str, Any]


def _number(x: Any) -> Any:
    """A JSON value for a number: floats as JSON numbers (the double they
    are), every exact number as a string of its exact value."""
    if isinstance(x, bool):
        raise InputError(f"{x!r} is not a number", "bad-field")
    if isinstance(x, float):
        return x
    if isinstance(x, (int, Fraction)):
        return str(x)
    if isinstance(x, Decimal):
        return str(Fraction(x))
    if isinstance(x, str):
        return x
    try:  # NumPy scalars
        import numpy as np

        if isinstance(x, np.floating):
            return float(x)
        if isinstance(x, np.integer):
            return str(int(x))
    except ImportError:  # pragma: no cover
        pass
    raise InputError(f"{x!r} is not a number", "bad-field")


EllipsoidLike = Union[str, Mapping[str, Any], Sequence[Any]]


def _ellipsoid(e: EllipsoidLike, name: str) -> Any:
    if isinstance(e, str):
        return e
    if isinstance(e, Mapping):
        c, r, m = e.get("center"), e.get("semi_axes"), e.get("rotation")
    else:
        try:
            c, r, m = e
        except (TypeError, ValueError):
            raise InputError(
                f"{name}: expected (center, semi_axes, rotation), a dict with those keys, "
                "or a quadric polynomial string",
                "bad-field",
            ) from None
    try:
        return {
            "center": [_number(v) for v in c],
            "semi_axes": [_number(v) for v in r],
            "rotation": [[_number(v) for v in row] for row in m],
        }
    except TypeError:
        raise InputError(f"{name}: center, semi_axes and rotation must be arrays", "bad-field") from None


def ellipsoid_contact_pair(
    a: EllipsoidLike, b: EllipsoidLike, time_limit: Optional[float] = None
) -> ContactReport:
    """Separated, touching or overlapping — exactly, with the overlap's kind
    and a certificate.  ``a`` and ``b``: ``(center, semi_axes, rotation)``
    (floats are the doubles they are; ints, ``Fraction``, ``Decimal`` and
    strings such as ``"1/3"`` are exact), a dict with those keys, or a
    quadric polynomial string such as ``"x^2 + y^2/4 + z^2 - 1"``.

    >>> import quadsect
    >>> I = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> r = quadsect.ellipsoid_contact_pair(([0, 0, 0], [1, 1, 1], I), ([2, 0, 0], [1, 1, 1], I))
    >>> r.contact, r.kind
    (<Contact.TOUCHING: 1>, 'externally-touching')
    """
    line = json.dumps(
        {"op": "ellipsoid-contact", "a": _ellipsoid(a, "a"), "b": _ellipsoid(b, "b")}
    )
    out = json.loads(_quadsect.answer_line(line, time_limit=time_limit, echo=False))
    if not out.get("ok"):
        err = out["error"]
        cls = {"budget": BudgetError, "internal": InternalError}.get(err["kind"], InputError)
        raise cls(err["message"], err["kind"])
    res = out["result"]
    return ContactReport(
        contact=Contact[res["contact"].upper()],
        kind=res["kind"],
        route=res["route"],
        certificate=res["certificate"],
        json=res,
    )


def ellipsoid_contact(ca, ra, Ra, cb, rb, Rb, threads: Optional[int] = None):
    """The contact of n pairs of ellipsoids given as arrays: centres (n, 3),
    semi-axes (n, 3) and matrices (n, 3, 3) of each side.  Returns an
    ``int8`` array of n codes: 0 separated, 1 touching, 2 overlapping
    (:class:`Contact`).  float64 arrays (or anything NumPy converts to
    float64) run in the engine's bulk API with the GIL released on
    ``threads`` threads (default: all cores); object arrays of exact numbers
    (``Fraction``, ``int``, strings) are decided exactly pair by pair.

    >>> import numpy as np, quadsect
    >>> c = np.zeros((2, 3)); r = np.ones((2, 3)); R = np.tile(np.eye(3), (2, 1, 1))
    >>> quadsect.ellipsoid_contact(c, r, R, c + [[2, 0, 0], [3, 0, 0]], r, R)
    array([1, 0], dtype=int8)
    """
    import numpy as np

    raw = [np.asarray(x) for x in (ca, ra, Ra, cb, rb, Rb)]
    names = ("ca", "ra", "Ra", "cb", "rb", "Rb")
    n = raw[0].shape[0] if raw[0].ndim >= 1 else -1
    for x, name, tail in zip(raw, names, [(3,), (3,), (3, 3)] * 2):
        if x.shape != (n,) + tail:
            raise InputError(
                f"{name} has shape {x.shape}, expected {(n,) + tail} (n = {n}, from ca)", "input"
            )
    if any(x.dtype == object for x in raw):
        out = np.empty(n, dtype=np.int8)
        for i in range(n):
            a = (raw[0][i], raw[1][i], raw[2][i])
            b = (raw[3][i], raw[4][i], raw[5][i])
            try:
                out[i] = int(ellipsoid_contact_pair(a, b).contact)
            except InputError as e:
                raise InputError(f"in row {i}: {e.message}", e.kind) from None
        return out
    arrs = [np.ascontiguousarray(x, dtype=np.float64) for x in raw]
    codes = _quadsect.ellipsoid_contact_bytes(*(x.tobytes() for x in arrs), threads or 0)
    return np.frombuffer(codes, dtype=np.int8).copy()
