"""The exceptions of quadsect (raised by the compiled module too)."""

from __future__ import annotations

__all__ = ["QuadsectError", "InputError", "BudgetError", "InternalError"]


class QuadsectError(Exception):
    """Base class of quadsect's errors.

    ``.kind`` is the engine's machine-readable kind (the ``kind`` of the
    batch protocol's error answers: ``"parse"``, ``"number"``,
    ``"not-an-ellipsoid"``, ``"bad-quadric"``, ``"input"``,
    ``"not-univariate"``, ``"zero-polynomial"``, ``"json"``,
    ``"missing-field"``, ``"bad-field"``, ``"unknown-op"``, ``"budget"``,
    ``"internal"``) and ``.message`` the text for people.
    """

    kind: str
    message: str

    def __init__(self, message: str, kind: str) -> None:
        super().__init__(message)
        self.message = message
        self.kind = kind

    def __reduce__(self):  # picklable across processes (Dask workers)
        return (type(self), (self.message, self.kind))

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.message!r}, kind={self.kind!r})"


class InputError(QuadsectError, ValueError):
    """Bad input: a syntax error, a bad number, a surface that is not what
    was asked for (``.kind`` says which).

    >>> try:
    ...     quadsect.roots("x*y")
    ... except quadsect.InputError as e:
    ...     print(e.kind)
    not-univariate
    """


class BudgetError(QuadsectError, RuntimeError):
    """A compute budget ran out (``.kind == "budget"``; the message says which
    limit).  Raised by ``roots`` and ``resultant``; ``tangent`` and
    ``natural`` answer ``"undecided"`` instead (with the reason)."""


class InternalError(QuadsectError, RuntimeError):
    """A failure inside quadsect (``.kind == "internal"``): never a wrong
    answer, but no answer either.  Please report it."""
