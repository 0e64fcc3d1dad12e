"""quadsect_check — an independent checker of quadsect's answers.

It reads the answer lines of ``quadsect batch --echo`` (each carries its
request line as ``"request"``), rebuilds every surface from the request's
text with its own parser (never from the answer), and re-proves the claims
of the answer from its certificate with exact rational arithmetic (Python's
``fractions``; nothing else, no import of the engine).  Each answer gets

    {"id", "status": "verified" | "partial" | "rejected",
     "checked": [claims re-proved], "trusted": [claims not re-proved], "reason"}

``verified``: every claim re-proved.  ``partial``: what is re-proved is
right and the claims listed in ``trusted`` are beyond this checker (named;
see docs/contract.md §7).  ``rejected``: a claim is wrong, or its
certificate is missing, malformed or not for this input (``reason`` says
which).

The ops checked: ``natural`` (module natural), ``tangent`` (tangent),
``ellipsoid-contact`` (contact), ``roots`` and ``resultant`` (kernel).

Usage: ``python3 -m quadsect_check FILE`` (``-``: standard input), or
:func:`check_answer` on one parsed answer line.
"""

import json
import sys

from .contact import check_contact
from .exact import CheckError, NotChecked
from .kernel import check_resultant, check_roots
from .natural import check_natural
from .tangent import check_tangent

__all__ = ["check_answer", "check_line", "CheckError"]

# exact numbers of thousands of digits (500-digit inputs) are ordinary here
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)

_OPS = {
    "natural": check_natural,
    "tangent": check_tangent,
    "ellipsoid-contact": check_contact,
    "roots": check_roots,
    "resultant": check_resultant,
}


def check_answer(answer):
    """The verdict on one answer (a dict parsed from a ``--echo`` line)."""
    out = {"id": answer.get("id") if isinstance(answer, dict) else None}
    try:
        if not isinstance(answer, dict):
            raise CheckError("an answer must be a JSON object")
        text = answer.get("request")
        if not isinstance(text, str):
            raise CheckError('no "request" in the answer: run quadsect batch --echo')
        try:
            req = json.loads(text)
        except ValueError:
            req = None
        if answer.get("ok") is not True:
            err = answer.get("error") or {}
            kind = err.get("kind") if isinstance(err, dict) else None
            if not kind:
                raise CheckError("an answer that is neither ok nor an error")
            return {**out, "status": "partial", "checked": [], "trusted": [f"no answer to check (error of kind {kind})"], "reason": None}
        if not isinstance(req, dict) or req.get("id") != answer.get("id"):
            raise CheckError("the request is not a JSON object with this answer's id")
        op = req.get("op")
        if op not in _OPS:
            raise CheckError(f"an answer to an unknown op {op!r}")
        res = answer.get("result")
        if not isinstance(res, dict):
            raise CheckError("no result object")
        checked, trusted = _OPS[op](req, res)
        status = "partial" if trusted else "verified"
        return {**out, "status": status, "checked": checked, "trusted": trusted, "reason": None}
    except NotChecked as e:
        return {**out, "status": "partial", "checked": [], "trusted": [str(e)], "reason": None}
    except (CheckError, ValueError, KeyError, TypeError, AttributeError, ZeroDivisionError, IndexError) as e:
        return {**out, "status": "rejected", "checked": [], "trusted": [], "reason": f"{type(e).__name__}: {e}" if not isinstance(e, CheckError) else str(e)}


def check_line(line):
    """:func:`check_answer` of one answer line (text)."""
    try:
        answer = json.loads(line)
    except ValueError as e:
        return {"id": None, "status": "rejected", "checked": [], "trusted": [], "reason": f"not JSON: {e}"}
    return check_answer(answer)
