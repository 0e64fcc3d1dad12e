"""quadsect.dask on a distributed LocalCluster with 2 worker processes:
the answers are those of `batch`, one per line, in order."""

import json

import pytest

import quadsect

# the `dask` extra is part of the suite (scripts/test_python.sh installs
# './python[dask,test]'): a missing Dask is a failure, not a skip
import dask.bag as dask_bag
import distributed

from quadsect.dask import decide_bag, decide_files

OPS = [
    {"op": "tangent", "ellipsoid": "x^2+y^2+z^2-25", "surface": "(x-{k})^2/9+y^2/4+z^2/16-1"},
    {"op": "natural", "a": "sphere center=0,0,0 radius2={k}", "b": "cylinder point=1,0,0 axis=0,0,1 radius2=1"},
    {"op": "roots", "poly": "x^3 - {k}x + 1"},
    {"op": "resultant", "f": "x^2+y^2-{k}", "g": "x-y+1", "var": "x"},
    {"op": "roots", "poly": "x*y + {k}"},  # an error answer
]


def lines(n):
    out = []
    for i in range(n):
        op = {k: (v.format(k=i % 11 + 1) if isinstance(v, str) else v) for k, v in OPS[i % len(OPS)].items()}
        out.append(json.dumps({"id": i, **op}))
    return out


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_decide_bag_on_two_workers_keeps_order_and_ids(client):
    src = lines(300)
    bag = dask_bag.from_sequence(src, npartitions=8)
    answers = decide_bag(bag).compute()
    assert [json.loads(a)["id"] for a in answers] == list(range(300))
    assert answers == list(quadsect.batch(src))
    # both workers took part
    assert len(client.scheduler_info()["workers"]) == 2


def test_recipe_for_files(client, tmp_path):
    src = lines(120)
    for part in range(3):
        (tmp_path / f"pairs-{part}.jsonl").write_text("\n".join(src[part * 40:(part + 1) * 40]) + "\n")
    # the documented recipe, unchanged
    dask_bag.read_text(str(tmp_path / "pairs-*.jsonl")).map(quadsect.answer_line).to_textfiles(
        str(tmp_path / "out-*.jsonl"))
    got = []
    for part in range(3):
        got += (tmp_path / f"out-{part}.jsonl").read_text().splitlines()
    assert got == list(quadsect.batch(src))
    # the convenience does the same, with a final newline
    written = decide_files(str(tmp_path / "pairs-*.jsonl"), str(tmp_path / "again-*.jsonl"))
    assert len(written) == 3
    again = []
    for part in range(3):
        text = (tmp_path / f"again-{part}.jsonl").read_text()
        assert text.endswith("\n")
        again += text.splitlines()
    assert again == got


def test_results_and_numbers_travel_between_processes(client):
    """Result objects, RealAlgebraic numbers and errors pickle: mapping the
    typed API over a bag works on worker processes too."""
    polys = [f"x^2 - {k}" for k in range(2, 8)]
    roots = dask_bag.from_sequence(polys, npartitions=2).map(quadsect.roots).compute()
    assert [list(r) for r in roots] == [list(quadsect.roots(p)) for p in polys]

    def kind(p):
        try:
            quadsect.roots(p)
            return None
        except quadsect.InputError as e:
            return e.kind

    assert dask_bag.from_sequence(["x*y", "x"], npartitions=2).map(kind).compute() == ["not-univariate", None]
