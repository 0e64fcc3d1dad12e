"""Ellipsoid contact from Python: the bulk API on NumPy arrays, the single
pair with its certificate, exact object arrays, errors."""

import json
import os
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import quadsect
from quadsect import Contact

I = np.eye(3)


def rot(q):
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def test_spheres_codes():
    n = 5
    c = np.zeros((n, 3))
    r = np.ones((n, 3))
    R = np.tile(I, (n, 1, 1))
    cb = np.array([[3, 0, 0], [2, 0, 0], [1, 0, 0], [0, 0, 0], [2 + 1e-15, 0, 0]], dtype=float)
    out = quadsect.ellipsoid_contact(c, r, R, cb, r, R)
    assert out.dtype == np.int8
    assert list(out) == [0, 1, 2, 2, 0]
    assert Contact(out[1]) is Contact.TOUCHING


def test_bulk_agrees_with_pairs_and_threads():
    rng = np.random.RandomState(3)
    n = 600
    ca, cb = rng.uniform(-2, 2, (n, 3)), rng.uniform(-2, 2, (n, 3))
    ra, rb = rng.uniform(0.2, 1.2, (n, 3)), rng.uniform(0.2, 1.2, (n, 3))
    Ra = np.array([rot(q) for q in rng.uniform(-1, 1, (n, 4))])
    Rb = np.array([rot(q) for q in rng.uniform(-1, 1, (n, 4))])
    one = quadsect.ellipsoid_contact(ca, ra, Ra, cb, rb, Rb, threads=1)
    two = quadsect.ellipsoid_contact(ca, ra, Ra, cb, rb, Rb, threads=2)
    assert (one == two).all()
    for i in range(0, n, 37):
        rep = quadsect.ellipsoid_contact_pair((ca[i], ra[i], Ra[i]), (cb[i], rb[i], Rb[i]))
        assert int(rep.contact) == one[i]
    # the three answers all occur
    assert set(one.tolist()) >= {0, 2}


def test_exact_object_arrays():
    c = np.array([[0, 0, 0], [0, 0, 0]], dtype=object)
    r = np.array([[1, 1, 1], [1, 1, 1]], dtype=object)
    R = np.array([np.eye(3, dtype=int).astype(object)] * 2)
    cb = np.array([[2, 0, 0], [Fraction(2) + Fraction(1, 10**30), 0, 0]], dtype=object)
    out = quadsect.ellipsoid_contact(c, r, R, cb, r, R)
    assert list(out) == [1, 0]


def test_pair_report_and_kinds():
    rep = quadsect.ellipsoid_contact_pair(([0, 0, 0], [1, 1, 1], I), ([2, 0, 0], [1, 1, 1], I))
    assert rep.contact is Contact.TOUCHING and rep.kind == "externally-touching"
    assert rep.certificate["type"] == "touching-point"
    inside = quadsect.ellipsoid_contact_pair("x^2+y^2+z^2-1", "x^2+y^2+z^2-4")
    assert inside.kind == "A-inside-B"
    sep = quadsect.ellipsoid_contact_pair(
        {"center": [3, 0.5, 0], "semi_axes": [1, 2, 0.5], "rotation": rot([1, 2, 3, 4])},
        ([0, 0, 0], [1, 1, 1], I),
    )
    assert sep.contact is Contact.SEPARATED
    assert Fraction(sep.certificate["lambda"]) > 0


def test_bad_input_names_the_row():
    c = np.zeros((3, 3))
    r = np.ones((3, 3))
    r[1, 2] = -1.0
    R = np.tile(I, (3, 1, 1))
    with pytest.raises(quadsect.InputError) as e:
        quadsect.ellipsoid_contact(c, r, R, c, np.ones((3, 3)), R)
    assert "row 1" in str(e.value)
    with pytest.raises(quadsect.InputError):
        quadsect.ellipsoid_contact(c, r[:2], R, c, r, R)
    singular = np.tile(np.array([[1.0, 2, 3], [2, 4, 6], [0, 0, 1]]), (3, 1, 1))
    with pytest.raises(quadsect.InputError) as e:
        quadsect.ellipsoid_contact(c, np.ones((3, 3)), singular, c, np.ones((3, 3)), R)
    assert e.value.kind == "not-an-ellipsoid"


def test_cli_batch_answers_equal_the_binding():
    exe = os.environ.get("QUADSECT_BIN")
    if not exe:
        pytest.skip("QUADSECT_BIN not set")
    line = {
        "id": 1,
        "a": {"center": [0, 0, 0], "semi_axes": [1, 2, 1], "rotation": I.tolist()},
        "b": {"center": [2.5, 0.3, 0], "semi_axes": [1, 1, 1], "rotation": rot([1, 2, 3, 4]).tolist()},
    }
    out = subprocess.run([exe, "ellipsoids", "-"], input=json.dumps(line), capture_output=True, text=True, check=True)
    res = json.loads(out.stdout)["result"]
    rep = quadsect.ellipsoid_contact_pair(line["a"], line["b"])
    assert res == rep.json
