#!/usr/bin/env python3
"""Writes the checker's corpus: batch request lines (JSONL) for
`quadsect batch --echo`, whose answers `python3 -m quadsect_check` must
accept (0 rejected).  Deterministic (fixed seed); no dependency.

    python3 scripts/check_corpus.py > corpus.jsonl
    ./target/release/quadsect batch --echo corpus.jsonl | PYTHONPATH=python python3 -m quadsect_check -
    python3 scripts/check_corpus.py --random-natural 3000 7 > sample.jsonl   # a larger property sample

The lines: every natural pair of benches/data/natural_pairs.json; the
papers' examples (the commands `quadsect examples` runs, given here as
batch lines); a seeded random sample of natural pairs with small integer
data (a property sample: whatever the engine answers must be accepted); tangent cases — spheres, ellipsoids rotated by rational
rotations, planes, quadrics (ellipsoid pairs), cubics and quartics,
intersecting, separated and touching, and surfaces with repeated factors —
a seeded random sample of ellipsoid pairs and of quadric/cubic surfaces;
roots and resultants from benches/data/kernel_inputs.json (those of
moderate size) and a few by hand; ellipsoid contacts of every kind by hand
and a seeded random sample of poses of doubles.
"""

import json
import math
import random
import sys
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def line(**kw):
    return json.dumps(kw, separators=(",", ":"))


def q(x):
    x = Fraction(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def cayley(a, b, c):
    """The rational rotation of the Cayley parameters (a, b, c)."""
    a, b, c = Fraction(a), Fraction(b), Fraction(c)
    n = 1 + a * a + b * b + c * c
    return [
        [(1 + a * a - b * b - c * c) / n, 2 * (a * b - c) / n, 2 * (a * c + b) / n],
        [2 * (a * b + c) / n, (1 - a * a + b * b - c * c) / n, 2 * (b * c - a) / n],
        [2 * (a * c - b) / n, 2 * (b * c + a) / n, (1 - a * a - b * b + c * c) / n],
    ]


def moved(expr, rot, shift=(0, 0, 0)):
    """expr at Rᵀ(P − shift): the surface rotated by R and moved by shift
    (as text; every variable replaced by a bracketed linear form)."""
    forms = []
    for i in range(3):
        terms = [f"({q(rot[j][i])})*(X{j} - ({q(shift[j])}))" for j in range(3)]
        forms.append("(" + " + ".join(terms) + ")")
    out = expr
    for i, v in enumerate("xyz"):
        out = out.replace(v, f"V{i}")
    for i in range(3):
        out = out.replace(f"V{i}", forms[i])
    for j, v in enumerate("xyz"):
        out = out.replace(f"X{j}", v)
    return out


def natural_lines():
    data = json.loads((ROOT / "benches/data/natural_pairs.json").read_text())
    for p in data["pairs"]:
        yield line(id=f"natural:{p['name']}", op="natural", a=p["a"], b=p["b"])
    # class and counts only (every third pair, all classes), and float mode
    for p in data["pairs"][::3]:
        yield line(id=f"natural-counts:{p['name']}", op="natural", a=p["a"], b=p["b"], components=False)
    yield line(id="natural-float", op="natural", a="cylinder point=0,0,0 axis=1,0,0 radius2=1",
               b="cylinder point=0,0,0 axis=0,1,0 radius2=1.0000000000000001", float=True)


def random_natural_lines(rng, n=120):
    """A seeded sample of natural pairs with small integer data, so that
    coincidences are frequent: half of the second quadrics placed at a
    point of {−1, 0, 1}³ (common vertices, vertices on the other surface,
    tangencies, shared rulings)."""
    def vec(r):
        return [str(rng.randint(-r, r)) for _ in range(3)]

    def axis():
        while True:
            a = vec(1)
            if any(x != "0" for x in a):
                return a

    def quadric(base):
        kind = rng.choice(["sphere", "cylinder", "cone", "cylinder", "cone"])
        num = rng.choice(["1", "2", "3", "1/2", "4", "5/4", "9", "1/3"])
        if kind == "sphere":
            return {"kind": kind, "center": base, "radius2": num}
        if kind == "cylinder":
            return {"kind": kind, "point": base, "axis": axis(), "radius2": num}
        return {"kind": kind, "vertex": base, "axis": axis(), "tan2": num}

    for i in range(n):
        a = quadric(vec(1))
        b = quadric(vec(1) if rng.random() < 0.5 else vec(3))
        yield line(id=f"natural-random:{i}", op="natural", a=a, b=b)


EXAMPLES_NATURAL = [
    ("cylinder point=0,0,0 axis=1,0,0 radius2=1", "cylinder point=0,0,0 axis=0,1,0 radius2=1"),
    ("cone vertex=2,0,0 axis=1,0,0 sin2=1/4", "cylinder point=0,0,0 axis=0,1,0 radius2=1"),
    ("cone vertex=0,0,0 axis=0,0,1 tan2=1", "cone vertex=3,0,1 axis=0,0,1 tan2=1"),
    ("cylinder point=0,0,0 axis=1,0,0 radius2=1", "cylinder point=0,0,0 axis=0,1,0 radius2=1.00000000000000000001"),
    ("cone vertex=2,0,0 axis=1,0,0 sin2=1/4", "cylinder point=0,0,0 axis=0,1,0 radius2=0.99999999999999999999"),
    ("cone vertex=0,0,0 axis=1,0,0 tan2=1", "cone vertex=2,2,0 axis=0,1,0 tan2=1"),
    ("cone vertex=0,0,0 axis=1,0,0 tan2=1", "cone vertex=0,0,0 axis=0,1,0 tan2=3"),
    ("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cylinder point=1,0,0 axis=0,0,1 radius2=1"),
    ("cylinder point=0,0,0 axis=1,0,0 radius2=1", "cone vertex=0,1,0 axis=1,1,0 tan2=3"),
    ("cylinder point=0,0,0 axis=1,0,0 radius2=1", "cylinder point=0,0,3 axis=0,1,0 radius2=1"),
    ("cylinder point=0,0,0 axis=0,0,1 radius2=1", "cone vertex=1,0,0 axis=1,1,1 tan2=2"),
    ("sphere center=0,0,0 radius2=4", "sphere center=3,0,0 radius2=4"),
    ("sphere center=1,2,3 radius2=2", "cylinder point=0,2,3 axis=1,0,0 radius2=2"),
    ("sphere center=0,4,0 radius2=8", "cone vertex=0,0,0 axis=1,0,0 tan=1"),
    ("cylinder point=0,0,0 axis=1,1,0 radius2=2", "cylinder point=3,3,0 axis=-2,-2,0 radius2=2"),
    ('{"kind":"cone","vertex":["0","0","0"],"axis":[1,0,0],"cos2":"1/2"}', "sphere center=0,0,0 radius2=1"),
]

TANGENT = [
    # the papers' examples
    ("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1"),
    ("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1.77777777777"),
    ("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-16/9"),
    ("x^2+y^2+z^2-25", "(x-6)^2/9+y^2/4+z^2/16-1"),
    ("x^2+y^2+z^2-25", "(x-1)^2/9+y^2/4+z^2/2-1"),
    ("2x^2+3y^2+4z^2-25", "(x-1)^4/9+y^2/4+4z^2/23-1"),
    # planes: crossing, tangent, apart
    ("x^2+y^2+z^2-1", "x+y-1/2"),
    ("x^2+y^2+z^2-1", "z-1"),
    ("x^2+2y^2+3z^2-6", "x+y+z-10"),
    # quadrics
    ("x^2+2y^2+z^2-1", "(x-3)^2+y^2+z^2-1"),
    ("x^2+y^2+z^2-1", "x^2+y^2+z^2-4"),
    ("x^2+y^2+z^2-4", "x^2+y^2+z^2-1"),
    ("x^2+y^2+z^2-1", "2x^2+2y^2+2z^2-2"),
    ("x^2+y^2+z^2-1", "(x-2)^2+y^2+z^2-1"),
    ("x^2+y^2+z^2-1", "x y - 1"),
    ("x^2+y^2+z^2-1", "x^2 - y^2 - z"),
    # cubics and quartics
    ("x^2+y^2+z^2-1", "x y z - 1"),
    ("x^2+y^2+z^2-1", "x^3 + y^3 + z^3 - 1/2"),
    ("x^2+4y^2+9z^2-1", "x^4+y^4+z^4-1/2"),
    ("18*x*x+-12*x*y+10*x*z+23*y*y+-24*y*z+14*z*z+-2*x+3*y+2*z-27", "x^4+y^4+z^4-1*x*y-2"),
    # an ellipsoid written negative inside (the engine orients it)
    ("1 - x^2 - 2y^2 - z^2", "(x-3)^2+y^2+z^2-1"),
    ("-x^2-y^2-z^2+4", "x+y+z-10"),
    # repeated factors
    ("x^2+y^2+z^2-4", "(x y - z)^2"),
    ("x^2+y^2+z^2-4", "(x + y + z - 1)^2 (x - y)^3"),
    ("x^2+y^2+z^2-1", "(z - 2)^2"),
]


def tangent_lines(rng):
    for i, (e, s) in enumerate(TANGENT):
        yield line(id=f"tangent:{i}", op="tangent", ellipsoid=e, surface=s)
    yield line(id="tangent:verdict-only", op="tangent", ellipsoid="x^2+y^2+z^2-1", surface="x y z - 1/10", values=False)
    yield line(id="tangent:float", op="tangent", ellipsoid="x^2+y^2+z^2-1", surface="x+y+z-1.7320508075688772", float=True)
    # rotated and moved: the same shapes, rational rigid motions
    rot = cayley(Fraction(1, 3), Fraction(1, 4), Fraction(-1, 2))
    for i, (e, s) in enumerate(TANGENT[:16]):
        yield line(id=f"tangent-moved:{i}", op="tangent", ellipsoid=moved(e, rot, (1, -2, Fraction(1, 2))),
                   surface=moved(s, rot, (1, -2, Fraction(1, 2))))
    # a seeded sample: ellipsoid pairs, planes, cubics
    for i in range(40):
        a = [rng.randint(1, 6) for _ in range(3)]
        c = [Fraction(rng.randint(-8, 8), rng.randint(1, 3)) for _ in range(3)]
        r = cayley(*(Fraction(rng.randint(-3, 3), rng.randint(1, 4)) for _ in range(3)))
        e = moved(f"{a[0]}x^2+{a[1]}y^2+{a[2]}z^2-{rng.randint(1, 9)}", r, (0, 0, 0))
        kind = i % 4
        if kind == 0:
            s = f"(x-({q(c[0])}))^2/{rng.randint(1, 5)} + (y-({q(c[1])}))^2/{rng.randint(1, 5)} + (z-({q(c[2])}))^2 - {rng.randint(1, 6)}"
        elif kind == 1:
            s = f"{rng.randint(-3, 3)}x + {rng.randint(-3, 3)}y + {rng.randint(1, 3)}z - ({q(c[0])})"
        elif kind == 2:
            s = f"x y - ({q(c[1])}) z + {rng.randint(-2, 2)}"
        else:
            s = f"x^3 - {rng.randint(1, 3)}y^2 z + z - ({q(c[2])})"
        yield line(id=f"tangent-random:{i}", op="tangent", ellipsoid=e, surface=s)


def poly_text(coeffs, var="x"):
    terms = [f"({c})*{var}^{i}" for i, c in enumerate(coeffs) if str(c) != "0"]
    return " + ".join(terms) or "0"


def kernel_lines():
    data = json.loads((ROOT / "benches/data/kernel_inputs.json").read_text())
    for r in data["roots"]:
        if len(r["p"]) <= 31:
            yield line(id=f"roots:{r['id']}", op="roots", poly=poly_text(r["p"]))
    for r in data["resultant"]:
        if len(r["f"]) + len(r["g"]) <= 24:
            yield line(id=f"resultant:{r['id']}", op="resultant", f=poly_text(r["f"]), g=poly_text(r["g"]), var="x")
    for r in data["bivariate"]:
        f = " + ".join(f"({c})*x^{i}*y^{j}" for i, j, c in r["f"])
        g = " + ".join(f"({c})*x^{i}*y^{j}" for i, j, c in r["g"])
        yield line(id=f"resultant:{r['id']}", op="resultant", f=f, g=g, var=r.get("eliminate", "x"))
    for i, p in enumerate(["x^3 - 2x", "(x^2-2)^3 (x-1/3)", "x^5", "(x-1)^2 (x+1)^3 (x^2+1)", "x^4 - 10x^2 + 1", "7"]):
        yield line(id=f"roots:hand-{i}", op="roots", poly=p)
    for i, (f, g, v) in enumerate([("x^2+y^2-1", "x-y z", "x"), ("x^2+y^2+z^2-1", "x y z - 1", "z"), ("x^3 - y", "x^2 + y^2 - 2", "y")]):
        yield line(id=f"resultant:hand-{i}", op="resultant", f=f, g=g, var=v)
    yield line(id="bad-input", op="roots", poly="x^")


ID3 = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]


def pose(c, r, rot=ID3):
    return {"center": c, "semi_axes": r, "rotation": rot}


def _rational_pose():
    """An ellipsoid (2, 1, 1) rotated by a rational rotation R and a unit
    sphere at c + R·(3, 0, 0): touching at c + R·(2, 0, 0) (exact strings)."""
    rot, c = cayley(Fraction(1, 3), Fraction(1, 4), Fraction(-1, 2)), [Fraction(1), Fraction(-2), Fraction(1, 2)]
    far = [c[i] + 3 * rot[i][0] for i in range(3)]
    return (pose([q(x) for x in c], ["2", "1", "1"], [[q(x) for x in row] for row in rot]),
            pose([q(x) for x in far], ["1", "1", "1"]))


CONTACT = [
    # touching from outside: spheres, an ellipsoid's tip, a rational rotation
    (pose([0, 0, 0], [1, 1, 1]), pose([2, 0, 0], [1, 1, 1])),
    (pose([0, 0, 0], [2, 1, 1]), "(x-3)^2+y^2+z^2-1"),
    _rational_pose(),
    # one inside the other
    ("x^2+y^2+z^2-1", pose([0.1, 0, 0], [0.5, 0.3, 0.4])),
    (pose([0, 0.2, 0], ["1/2", "1/3", "1/4"], [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]), "1 - x^2/4 - y^2/4 - z^2/9"),
    # touching from inside: at a point, the osculating sphere of a tip, two points, a circle
    ("x^2+y^2+z^2-1", "(x-1)^2+y^2+z^2-4"),
    (pose([0, 0, 0], [2, 1, 1]), pose(["7/4", 0, 0], ["1/4", "1/4", "1/4"])),
    (pose([0, 0, 0], [2, 1, 1]), pose(["3/2", 0, 0], ["1/2", "1/2", "1/2"])),
    (pose([0, 0, 0], [2, 1.5, 1]), "x^2+y^2+z^2-1"),
    ("x^2+y^2+z^2-1", pose([0, 0, 0], [1, 1, 2])),
    # the same ellipsoid
    (pose([0, 0, 0], [2, 1, 1]), "x^2/4+y^2+z^2-1"),
    ("1-x^2-y^2-z^2", "2x^2+2y^2+2z^2-2"),
    # the surfaces cross; apart
    ("x^2+y^2+z^2-1", pose(["1/3", 0, 0], ["1/2", 1, 1])),
    ("x^2+y^2+z^2-1", pose([0, 0, 0], [2, 0.5, 0.5])),
    (pose([0, 0, 0], [1, 2, 1]), pose([2.5, 0.3, 0], [1, 1, 1], [[0.36, 0.48, -0.8], [-0.8, 0.6, 0], [0.48, 0.64, 0.6]])),
]


def quaternion_rotation(rng):
    """The rotation of a random unit quaternion, in doubles (not exactly
    orthogonal: the ellipsoid is the one these doubles define)."""
    w, x, y, z = (rng.gauss(0, 1) for _ in range(4))
    n = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def contact_lines(rng, n=15):
    """The contacts by hand, then n random pairs of poses of doubles
    (centres in [−2, 2]³, semi-axes in [0.2, 1.2])."""
    for i, (a, b) in enumerate(CONTACT):
        yield line(id=f"contact:{i}", op="ellipsoid-contact", a=a, b=b)
    for i in range(n):
        a, b = (pose([rng.uniform(-2, 2) for _ in range(3)], [rng.uniform(0.2, 1.2) for _ in range(3)],
                     quaternion_rotation(rng)) for _ in range(2))
        yield line(id=f"contact-random:{i}", op="ellipsoid-contact", a=a, b=b)


def main():
    rng = random.Random(20261204)
    out = sys.stdout
    if sys.argv[1:2] == ["--random-natural"]:  # N [SEED]: only a random natural sample
        n, seed = int(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) > 3 else 20261205
        for l in random_natural_lines(random.Random(seed), n):
            out.write(l + "\n")
        return
    for l in natural_lines():
        out.write(l + "\n")
    for i, (a, b) in enumerate(EXAMPLES_NATURAL):
        out.write(line(id=f"natural-example:{i}", op="natural", a=a, b=b) + "\n")
    for l in random_natural_lines(random.Random(20261205)):
        out.write(l + "\n")
    for l in tangent_lines(rng):
        out.write(l + "\n")
    for l in kernel_lines():
        out.write(l + "\n")
    for l in contact_lines(random.Random(20261206)):
        out.write(l + "\n")


if __name__ == "__main__":
    main()
