"""The batch protocol from Python: `answer_line` gives the bytes of
`quadsect batch`, `batch` streams the same answers in order."""

import itertools
import json
import os
import pathlib
import subprocess

import pytest
from hypothesis import given
from hypothesis import strategies as st

import quadsect

REPO = pathlib.Path(__file__).resolve().parents[2]


def corpus():
    """Batch lines of every op, good and bad (ids of several JSON types)."""
    lines = [
        {"id": 1, "op": "tangent", "ellipsoid": "x^2+y^2+z^2-25", "surface": "(x-9)^2/9+y^2/4+z^2/16-1"},
        {"id": "two", "op": "tangent", "ellipsoid": "x^2+y^2+z^2-25", "surface": "(x-6)^2/9+y^2/4+z^2/16-1"},
        {"id": [3], "op": "natural", "a": "cylinder point=0,0,0 axis=1,0,0 radius2=1",
         "b": {"kind": "cylinder", "point": ["0", "0", "0"], "axis": ["0", "1", "0"], "radius2": "1"}},
        {"id": 4.5, "op": "natural", "a": "cone vertex=0,0,0 axis=0,0,1 tan2=1", "b": "sphere center=0,0,2 radius2=2"},
        {"id": None, "op": "roots", "poly": "(x^2-2)^3 (x-1/3)"},
        {"id": 6, "op": "resultant", "f": "x^2+y^2-1", "g": "x-y", "var": "x"},
        {"id": 7, "op": "roots", "poly": "x*y"},
        {"id": 8, "op": "tangent", "ellipsoid": "x^2+y^2-z^2-1", "surface": "x"},
        {"id": 9, "op": "frobnicate"},
        {"id": 10, "op": "roots"},
        {"id": 11, "op": "roots", "poly": 5},
    ]
    text = [json.dumps(line) for line in lines]
    return text + ["", "not json", "[1, 2]", '{"id": 12, "op": "roots", "poly": "x^2 - 3"}\r']


def quadsect_binary():
    """The CLI built from this repository (scripts/test_python.sh builds it)."""
    path = os.environ.get("QUADSECT_BIN") or str(REPO / "target" / "release" / "quadsect")
    if not os.path.exists(path):
        pytest.fail(f"the quadsect CLI is not built at {path} (scripts/test_python.sh builds it; "
                    "or set QUADSECT_BIN)")
    return path


def test_answer_line_is_byte_identical_to_the_cli(tmp_path):
    lines = corpus()
    src = tmp_path / "in.jsonl"
    src.write_text("\n".join(lines) + "\n")
    out = subprocess.run([quadsect_binary(), "batch", str(src)], check=True, capture_output=True)
    expected = out.stdout.decode().split("\n")[:-1]
    assert len(expected) == len(lines)
    assert [quadsect.answer_line(line) for line in lines] == expected
    assert list(quadsect.batch(lines)) == expected
    assert list(quadsect.batch(lines, threads=1)) == expected


def test_answer_line_protocol():
    ok = json.loads(quadsect.answer_line('{"id": 7, "op": "roots", "poly": "x^2 - 2"}\n'))
    assert ok["id"] == 7 and ok["ok"] is True and ok["result"] == quadsect.roots("x^2 - 2").to_json()
    bad = json.loads(quadsect.answer_line('{"id": "b", "op": "roots", "poly": "x*y"}'))
    assert bad == {"id": "b", "ok": False, "error": {"kind": "not-univariate", "message": bad["error"]["message"]}}
    assert json.loads(quadsect.answer_line("garbage"))["error"]["kind"] == "json"


@given(st.text(max_size=60))
def test_answer_line_never_raises(line):
    """Property: any text gets exactly one JSON answer object."""
    a = json.loads(quadsect.answer_line(line))
    assert set(a) == {"id", "ok", "result"} or set(a) == {"id", "ok", "error"}


@given(st.lists(st.sampled_from(corpus()), max_size=40), st.integers(1, 4))
def test_batch_streams_in_order(lines, threads):
    """Property: batch(lines) is [answer_line(l) for l in lines] for any
    thread count."""
    assert list(quadsect.batch(lines, threads=threads)) == [quadsect.answer_line(l) for l in lines]


def test_batch_reads_files_and_bytes(tmp_path):
    lines = corpus()
    path = tmp_path / "in.jsonl"
    path.write_text("\n".join(lines) + "\n")
    expected = [quadsect.answer_line(l) for l in lines]
    with open(path) as f:
        assert list(quadsect.batch(f)) == expected
    with open(path, "rb") as f:
        assert list(quadsect.batch(f)) == expected
    # invalid UTF-8 is an error answer, never lost
    (bad,) = quadsect.batch([b'{"id": 1, "op": "roots", "poly": "x\xff"}'])
    assert json.loads(bad)["ok"] is False


def test_batch_look_ahead_is_bounded():
    """An endless input streams: the first answers come back while the
    input is still being read, and only a bounded part is read ahead."""
    pulled = 0

    def endless():
        nonlocal pulled
        for i in itertools.count():
            pulled += 1
            yield json.dumps({"id": i, "op": "roots", "poly": f"x^2 - {i}"})

    answers = quadsect.batch(endless(), threads=2)
    first = [json.loads(next(answers))["id"] for _ in range(10)]
    assert first == list(range(10))
    assert pulled <= 10 + 2 * 32
    del answers


def test_batch_rejects_bad_arguments():
    with pytest.raises(TypeError):
        list(quadsect.batch([1, 2]))
    with pytest.raises(TypeError):
        quadsect.batch(5)
    with pytest.raises(quadsect.InputError):
        quadsect.batch([], threads=0)
    assert list(quadsect.batch([])) == []


def test_batch_propagates_errors_of_the_input_iterable():
    def broken():
        yield '{"id": 1, "op": "roots", "poly": "x"}'
        raise OSError("disk gone")

    it = quadsect.batch(broken(), threads=1)
    with pytest.raises(OSError):
        list(it)


def test_time_limit_is_per_line_as_in_the_cli(tmp_path):
    """`time_limit` of answer_line / batch is `quadsect batch --time-limit`:
    a limit of 1 ns stops every line that computes at its first budget
    check, identically in both."""
    lines = corpus()
    src = tmp_path / "in.jsonl"
    src.write_text("\n".join(lines) + "\n")
    out = subprocess.run([quadsect_binary(), "batch", "--time-limit", "1e-9", str(src)],
                         check=True, capture_output=True)
    expected = out.stdout.decode().split("\n")[:-1]
    assert [quadsect.answer_line(line, time_limit=1e-9) for line in lines] == expected
    assert list(quadsect.batch(lines, threads=2, time_limit=1e-9)) == expected
    budget = [json.loads(a) for a in expected]
    assert any(a["ok"] and a["result"].get("verdict") == "undecided" for a in budget)
    assert any(not a["ok"] and a["error"]["kind"] == "budget" for a in budget)
