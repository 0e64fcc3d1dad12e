"""quadsect on Dask: answer bags of batch lines on a cluster.

Install with ``pip install 'quadsect[dask]'``.  Every worker needs only the
quadsect wheel; the answers are exactly those of ``quadsect batch`` (and
:func:`quadsect.answer_line`), one per input line, in order.

The recipe for files (one partition per input file, one output file per
partition, lines in order)::

    import dask.bag, quadsect
    dask.bag.read_text("pairs-*.jsonl").map(quadsect.answer_line).to_textfiles("out-*.jsonl")

or, the same, :func:`decide_files`.  The engine releases the GIL, so a
worker with several threads answers several lines at once.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, List, Sequence, Union

from . import answer_line

if TYPE_CHECKING:  # pragma: no cover
    import dask.bag

__all__ = ["decide_bag", "decide_files"]


def decide_bag(lines: "dask.bag.Bag") -> "dask.bag.Bag":
    """The bag of answers to a bag of batch lines (``str``, trailing newline
    allowed), element by element and in order: ``lines.map(answer_line)``.

    >>> import dask.bag
    >>> b = dask.bag.from_sequence(['{"id": 1, "op": "roots", "poly": "x^2 - 2"}'])
    >>> import json; [json.loads(a)["ok"] for a in decide_bag(b).compute()]
    [True]
    """
    return lines.map(answer_line)


def decide_files(
    inputs: Union[str, Sequence[str]],
    outputs: Union[str, Sequence[str]],
    *,
    blocksize: Union[None, int, str] = None,
    compute: bool = True,
) -> List[str]:
    """Answers JSON-lines files: ``inputs`` (a glob such as
    ``"pairs-*.jsonl"`` or a list of paths) to ``outputs`` (a glob with one
    ``*``, e.g. ``"out-*.jsonl"``, or a list of paths, one per partition).
    With ``blocksize=None`` each input file is one partition and gives one
    output file, in the order of the sorted input paths.  Returns the paths
    written (or the delayed writes when ``compute=False``)."""
    import dask.bag

    bag = dask.bag.read_text(inputs, blocksize=blocksize)
    return decide_bag(bag).to_textfiles(outputs, compute=compute, last_endline=True)
