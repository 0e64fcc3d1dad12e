#!/usr/bin/env python3
"""The natural-quadric benchmark pair set: benches/data/natural_pairs.json.

Writes the pairs that `quadsect bench natural --pairs` and
scripts/bench_occ.py time (format: the "pair set" note of issue 15, repeated
in the file's "description").  Every number is exact: the script works in
fractions.Fraction and writes integers, "p/q" or exact finite decimals (a
double is written as its exact binary value, e.g. 0.7071067811865476 as
0.70710678118654757273731092936941422522068023681640625).  The random choices
come from random.Random(SEED), so the file is reproducible.

Groups
  class-same-surface, class-conics, class-conic-and-line, class-lines,
  class-points, class-empty, class-curve
      small-integer pairs of each class, built in a canonical frame from the
      paper's constructions and moved by rational rigid motions (Cayley
      rotations R = (I - K)^-1 (I + K) for a rational skew matrix K, which are
      exact rational rotations, plus integer translations);
  random-int      random generic small-integer pairs of all kinds (skew axes);
  double          53-bit double input: random rotations, positions and radii
                  rounded to doubles, and pairs as a CAD kernel writes them;
  near-degenerate within 1e-9 .. 1e-15 of tangency, a common vertex, equal
                  radii, parallel or intersecting axes (rationals and doubles);
  occ-regression  pairs from Open CASCADE's own Draw test scripts (tests/ of
                  OCCT 8.0.1); `source` names the test and says how the numbers
                  were converted;
  decimal500      500-significant-digit decimal input.

`expect` is the answer of quadsect's present exact route: each pair is sent
to `quadsect batch` as {"op":"natural"} in its own process (with a time
limit); the wall time of that call (and, for fast pairs, the time per call
of a batch of repeated lines on one thread, start-up subtracted) is recorded
in docs/natural_pairs_before.json: the "before" timings of issue 15.  Pairs
whose answer is already in that file (same a and b) are not recomputed.  A
pair that does not finish within --timeout seconds is dropped from the pair
file and listed under "dropped" in the timings file.

Usage (from the repository root, after `cargo build --release`):
    python3 scripts/gen_natural_pairs.py [--quadsect target/release/quadsect]
        [--timeout 600] [--only GROUP,...] [--no-expect] [--recompute]
"""
import argparse
import decimal
import hashlib
import json
import math
import os
import random
import subprocess
import sys
import time
from fractions import Fraction as F

SEED = 20240515
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAIRS_PATH = os.path.join(ROOT, "benches", "data", "natural_pairs.json")
BEFORE_PATH = os.path.join(ROOT, "docs", "natural_pairs_before.json")

# ---------------------------------------------------------------- numbers


def fmt(x):
    """Exact string of a rational: integer, finite decimal, or p/q."""
    x = F(x)
    p, q = x.numerator, x.denominator
    if q == 1:
        return str(p)
    a = b = 0
    r = q
    while r % 2 == 0:
        r //= 2
        a += 1
    while r % 5 == 0:
        r //= 5
        b += 1
    if r != 1:
        return f"{p}/{q}"
    k = max(a, b)
    n = abs(p) * 10**k // q
    s = str(n).rjust(k + 1, "0")
    s = s[:-k] + "." + s[-k:]
    return ("-" if p < 0 else "") + s


def dbl(x):
    """The exact value of the double nearest to x."""
    return F(float(x))


def dec(s):
    """An exact decimal literal (as written in a test script)."""
    return F(s.strip().rstrip(","))


# ---------------------------------------------------------------- geometry


def vadd(u, v):
    return [a + b for a, b in zip(u, v)]


def vsub(u, v):
    return [a - b for a, b in zip(u, v)]


def vmul(k, v):
    return [k * a for a in v]


def dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def matvec(m, v):
    return [sum(m[i][j] * v[j] for j in range(3)) for i in range(3)]


def cayley(a, b, c):
    """(I - K)^-1 (I + K) for K = [[0,-c,b],[c,0,-a],[-b,a,0]]: a rational rotation."""
    a, b, c = F(a), F(b), F(c)
    n = a * a + b * b + c * c
    d = 1 + n
    m = [
        [1 + a * a - b * b - c * c, 2 * (a * b - c), 2 * (a * c + b)],
        [2 * (a * b + c), 1 - a * a + b * b - c * c, 2 * (b * c - a)],
        [2 * (a * c - b), 2 * (b * c + a), 1 - a * a - b * b + c * c],
    ]
    return [[x / d for x in row] for row in m]


def sphere(c, r2):
    return {"kind": "sphere", "center": [F(x) for x in c], "radius2": F(r2)}


def cylinder(p, a, r2):
    return {"kind": "cylinder", "point": [F(x) for x in p], "axis": [F(x) for x in a], "radius2": F(r2)}


def cone(v, a, t2):
    return {"kind": "cone", "vertex": [F(x) for x in v], "axis": [F(x) for x in a], "tan2": F(t2)}


def move(s, rot, t):
    """The quadric s moved by P -> rot P + t."""
    s = dict(s)
    for key in ("center", "point", "vertex"):
        if key in s:
            s[key] = vadd(matvec(rot, s[key]), t)
    if "axis" in s:
        s["axis"] = matvec(rot, s["axis"])
    return s


def scale(s, k):
    """The quadric s scaled by k about the origin."""
    s = dict(s)
    k = F(k)
    for key in ("center", "point", "vertex"):
        if key in s:
            s[key] = vmul(k, s[key])
    if "radius2" in s:
        s["radius2"] = s["radius2"] * k * k
    return s


def to_json(s):
    out = {"kind": s["kind"]}
    for key in ("center", "point", "vertex", "axis"):
        if key in s:
            out[key] = [fmt(x) for x in s[key]]
    for key in ("radius2", "tan2"):
        if key in s:
            out[key] = fmt(s[key])
    return out


class Gen:
    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.pairs = []

    def add(self, group, a, b, source=None):
        n = sum(1 for p in self.pairs if p["group"] == group) + 1
        pair = {"name": f"{group}-{n:03d}", "group": group}
        if source:
            pair["source"] = source
        pair["a"], pair["b"] = to_json(a), to_json(b)
        self.pairs.append(pair)

    # random helpers
    def i(self, lo, hi):
        return self.rng.randint(lo, hi)

    def ivec(self, lo=-5, hi=5, nonzero=False):
        while True:
            v = [self.i(lo, hi) for _ in range(3)]
            if not nonzero or any(v):
                return v

    def q(self, lo=1, hi=9):
        return F(self.i(lo, hi), self.i(1, hi))

    def motion(self, small=True):
        """A rational rigid motion (Cayley rotation with small parameters, integer shift)."""
        h = 3 if small else 9
        par = [F(self.i(-h, h), self.i(1, h)) for _ in range(3)]
        return cayley(*par), self.ivec(-5, 5)

    def moved(self, a, b, small=True):
        rot, t = self.motion(small)
        return move(a, rot, t), move(b, rot, t)


X, Y, Z, O = [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]

# ---------------------------------------------------------------- class groups


def class_groups(g):
    # same surface: the same quadric written twice (other axis point, scaled axis)
    base = [
        (cylinder([1, 2, 0], [1, 1, 0], 2), cylinder([4, 5, 0], [-2, -2, 0], 2)),
        (cylinder([0, 0, 0], [1, 2, 3], 5), cylinder([2, 4, 6], [3, 6, 9], 5)),
        (sphere([1, -2, 3], 7), sphere([1, -2, 3], 7)),
        (cone([1, 1, 1], [1, 0, 2], F(1, 3)), cone([1, 1, 1], [-3, 0, -6], F(1, 3))),
        (cone([0, 2, -1], [2, -1, 2], 3), cone([0, 2, -1], [4, -2, 4], 3)),
    ]
    for a, b in base:
        g.add("class-same-surface", a, b)
    for a, b in base[:4]:
        g.add("class-same-surface", *g.moved(a, b))

    # conics
    base = [
        # Corollary 8.1: equal cylinders with intersecting axes (two ellipses)
        (cylinder(O, X, 1), cylinder(O, Y, 1)),
        (cylinder([1, 1, 1], [1, 2, 0], 3), cylinder([1, 1, 1], [2, -1, 1], 3)),
        # cone and cylinder with a common inscribed sphere: d^2 sin^2 = r^2
        (cone([2, 0, 0], X, F(1, 3)), cylinder(O, Y, 1)),
        (cone([3, 0, 0], X, F(4, 5)), cylinder(O, [1, 2, 0], 4)),
        # two cones with a common inscribed sphere (radius^2 2): V = O + a, tan2 = r2/(|a|^2 - r2)
        (cone([1, 2, 2], [1, 2, 2], F(2, 7)), cone([3, 0, 0], [3, 0, 0], F(2, 7))),
        # Theorem 8.2: parallel axes, equal angles
        (cone(O, Z, 1), cone([3, 0, 1], Z, 1)),
        (cone([1, 2, 0], [1, 1, 1], F(1, 4)), cone([2, -1, 3], [2, 2, 2], F(1, 4))),
        # spheres meeting in a circle; coaxial sphere/cylinder and sphere/cone
        (sphere(O, 4), sphere([3, 0, 0], 4)),
        (sphere([1, 2, 3], 9), cylinder([0, 2, 3], X, 4)),
        (sphere([1, 2, 3], 2), cylinder([0, 2, 3], X, 2)),
        (sphere([0, 0, 2], 4), cone(O, Z, 1)),
        (sphere([0, 0, 5], 10), cone([0, 0, 1], [0, 0, 2], F(1, 2))),
    ]
    for a, b in base:
        g.add("class-conics", a, b)
    for a, b in base[1:8:2]:
        g.add("class-conics", *g.moved(a, b))

    # a conic and a double line: a common ruling in a common symmetry plane
    base = []
    for p, q, s, sign in [(1, 1, 2, 1), (2, F(1, 2), 1, -1), (F(1, 2), 3, 2, 1), (3, F(1, 3), -1, 1)]:
        # cone A: vertex 0, axis x, tan = p; its skeletal line y = p x carries V2;
        # cone B's axis makes the angle atan(q) with the line V2 O
        v2 = [s, s * F(p), 0]
        w = [1 - sign * q * F(p), sign * q + F(p), 0]
        base.append((cone(O, X, F(p) ** 2), cone(v2, w, F(q) ** 2)))
    for r, q, s in [(1, 1, 3), (2, F(1, 2), -1)]:
        # cylinder axis x radius r; cone vertex on the skeletal line y = r, axis at atan(q) to it
        base.append((cylinder(O, X, r * r), cone([s, r, 0], [1, q, 0], F(q) ** 2)))
    for a, b in base:
        g.add("class-conic-and-line", a, b)
    for a, b in base[:4]:
        g.add("class-conic-and-line", *g.moved(a, b))

    # lines
    base = [
        (cone(O, X, 1), cone(O, Y, 3)),  # Theorem 6.1: four lines
        (cone([1, 1, 1], [1, 2, 0], 2), cone([1, 1, 1], [0, 1, 2], 3)),
        (cylinder(O, Z, 1), cylinder([1, 0, 0], Z, 1)),  # parallel cylinders: two lines
        (cylinder([1, 2, 0], [1, 1, 1], 4), cylinder([2, 1, 0], [2, 2, 2], 1)),
        (cylinder(O, Z, 1), cylinder([3, 0, 0], Z, 4)),  # parallel, tangent: a double line
        (cone(O, X, 1), cone(O, [1, 1, 0], 1)),  # common vertex, tangent along a ruling
    ]
    for a, b in base:
        g.add("class-lines", a, b)
    for a, b in base[:4]:
        g.add("class-lines", *g.moved(a, b))

    # isolated points
    base = [
        (cylinder(O, X, 1), cylinder([0, 0, 2], Y, 1)),  # skew cylinders at r1 + r2
        (cylinder(O, X, 4), cylinder([0, 0, 3], [1, 2, 0], 1)),
        (cylinder(O, X, 1), cone([0, 0, 2], Y, 3)),  # Corollary 7.1
        (scale(cylinder(O, X, 1), 3), scale(cone([0, 0, 2], Y, 3), 3)),
        (cone(O, X, F(1, 10)), cone(O, Y, F(1, 10))),  # common vertex, only the vertex real
        (sphere(O, 1), sphere([1, 2, 2], 4)),  # spheres touching from outside (3 = 1 + 2)
        (sphere(O, 25), sphere([1, 2, 2], 4)),  # touching from inside (3 = 5 - 2)
        (sphere([0, 4, 0], 8), cone(O, X, 1)),  # touching both nappes
        (sphere([0, 6, 0], 12), cone(O, X, 2)),  # d^2 = c^2/(1 + t2)
        (sphere([0, 5, 0], 4), cylinder(O, X, 9)),  # sphere touching a cylinder from outside
    ]
    for a, b in base:
        g.add("class-points", a, b)
    for a, b in base[:4]:
        g.add("class-points", *g.moved(a, b))

    # empty
    base = [
        (cylinder(O, X, 1), cylinder([0, 0, 3], Y, 1)),
        (cylinder(O, X, 4), cylinder([0, 1, 5], [1, 3, 0], 1)),
        (sphere(O, 1), sphere([3, 3, 3], 4)),
        (sphere(O, 100), sphere([1, 1, 1], 4)),
        (cylinder(O, Z, 1), cylinder([5, 0, 0], Z, 4)),
        (cylinder(O, Z, 1), cylinder(O, Z, F(1, 4))),  # coaxial, other radius
        (sphere([1, 1, 1], 1), cylinder([0, 1, 1], X, 4)),  # sphere inside a cylinder
        (sphere([0, 5, 0], 4), cone(O, X, 1)),  # sphere between the nappes
        (cylinder([0, 0, 5], Y, 1), cone(O, X, 1)),  # cylinder outside the double cone
    ]
    for a, b in base:
        g.add("class-empty", a, b)
    for a, b in base[:4]:
        g.add("class-empty", *g.moved(a, b))

    # a genuine space curve
    base = [
        (cylinder(O, X, 1), cone([0, 1, 0], Y, 1)),  # §5.1, isolated vertex
        (cylinder(O, X, 1), cone([0, 1, 0], [1, 1, 0], 3)),  # branches cross at the vertex
        (cylinder(O, Z, 1), cone([1, 0, 0], [1, 1, 1], 2)),  # a line and a twisted cubic
        (cone(O, X, 1), cone([1, 5, 2], [1, 2, 3], F(1, 2))),
        (cylinder(O, X, 1), cylinder(O, Y, F(5, 4))),  # crossing, unequal radii
        (cylinder(O, X, 1), cylinder([0, 0, 1], Y, 1)),  # skew, overlapping
        (sphere([0, 0, 1], 4), cylinder(O, X, 1)),  # sphere off the axis
        (cone(O, Z, 1), cone([3, 0, 1], Z, 2)),  # parallel axes, other angles
    ]
    for a, b in base:
        g.add("class-curve", a, b)
    for a, b in base[:4]:
        g.add("class-curve", *g.moved(a, b))


# ---------------------------------------------------------------- random-int


def random_int(g, n=100):
    kinds = ["cyl-cyl"] * 3 + ["cyl-cone"] * 4 + ["cone-cone"] * 3 + ["sph-cyl", "sph-cone", "sph-sph"]
    for _ in range(n):
        k = g.rng.choice(kinds)

        def one(kind):
            if kind == "sph":
                return sphere(g.ivec(), g.i(1, 16))
            if kind == "cyl":
                return cylinder(g.ivec(), g.ivec(nonzero=True), g.q(1, 9))
            return cone(g.ivec(), g.ivec(nonzero=True), g.q(1, 9))

        ka, kb = k.split("-")
        g.add("random-int", one(ka), one(kb))


# ---------------------------------------------------------------- double


def frot(rng):
    """A random rotation in floating point (unit quaternion), as float entries."""
    while True:
        q = [rng.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(x * x for x in q))
        if n > 1e-3:
            break
    w, x, y, z = (c / n for c in q)
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def fmove(s, rot, t):
    """s moved in floating point (the coordinates of a CAD model), then written exactly."""
    out = dict(s)

    def mv(v):
        return [float(sum(rot[i][j] * float(v[j]) for j in range(3))) for i in range(3)]

    for key in ("center", "point", "vertex"):
        if key in s:
            out[key] = [F(c + float(tt)) for c, tt in zip(mv(s[key]), t)]
    if "axis" in s:
        out["axis"] = [F(c) for c in mv(s["axis"])]
    for key in ("radius2", "tan2"):
        if key in s:
            out[key] = dbl(s[key])
    return out


def fcyl(p, a, r):
    """A cylinder as a kernel holds it: doubles for point, unit axis and radius (radius2 = r*r exactly)."""
    n = math.sqrt(sum(x * x for x in a))
    return {"kind": "cylinder", "point": [dbl(x) for x in p], "axis": [dbl(x / n) for x in a], "radius2": dbl(r) ** 2}


def fsph(c, r):
    return {"kind": "sphere", "center": [dbl(x) for x in c], "radius2": dbl(r) ** 2}


def fcone(v, a, ang):
    """A cone at its vertex with semi-angle ang (radians, a double): tan2 = tan(ang)^2 exactly."""
    n = math.sqrt(sum(x * x for x in a))
    return {"kind": "cone", "vertex": [dbl(x) for x in v], "axis": [dbl(x / n) for x in a], "tan2": F(math.tan(ang)) ** 2}


def double_group(g):
    rng = g.rng
    # random rotations and positions of random configurations, rounded to doubles
    for k in range(30):
        rot = frot(rng)
        t = [round(rng.uniform(-50, 50), rng.choice([2, 3, 6, 17])) for _ in range(3)]
        kind = k % 5
        if kind == 0:
            a = fcyl([0, 0, 0], [1, 0, 0], rng.uniform(0.5, 10))
            b = fcyl([rng.uniform(-3, 3) for _ in range(3)], [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.5, 10))
        elif kind == 1:
            a = fcyl([0, 0, 0], [0, 0, 1], rng.uniform(1, 10))
            b = fcone([rng.uniform(-5, 5) for _ in range(3)], [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.1, 1.4))
        elif kind == 2:
            a = fcone([0, 0, 0], [0, 0, 1], rng.uniform(0.1, 1.4))
            b = fcone([rng.uniform(-5, 5) for _ in range(3)], [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.1, 1.4))
        elif kind == 3:
            a = fsph([rng.uniform(-3, 3) for _ in range(3)], rng.uniform(1, 5))
            b = fcyl([0, 0, 0], [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.5, 4))
        else:
            a = fsph([rng.uniform(-3, 3) for _ in range(3)], rng.uniform(1, 5))
            b = fcone([0, 0, 0], [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.1, 1.4))
        g.add("double", fmove(a, rot, t), fmove(b, rot, t))
    # degenerate configurations (the exact ones of the class groups) after a
    # floating-point rotation: what a modeler holds after moving a part
    degenerate = [
        (cylinder(O, X, 1), cylinder(O, Y, 1)),
        (cone([2, 0, 0], X, F(1, 3)), cylinder(O, Y, 1)),
        (cylinder(O, Z, 1), cylinder([1, 0, 0], Z, 1)),
        (cylinder(O, X, 1), cylinder([0, 0, 2], Y, 1)),
        (cone(O, X, 1), cone(O, Y, 3)),
        (sphere(O, 4), sphere([3, 0, 0], 4)),
        (sphere([1, 2, 3], 9), cylinder([0, 2, 3], X, 4)),
        (cone(O, X, 1), cone([2, 2, 0], Y, 1)),
        (cylinder(O, X, 1), cone([0, 1, 0], Y, 1)),
        (cylinder(O, X, 1), cone([0, 0, 2], Y, 3)),
    ]
    for a, b in degenerate:
        rot = frot(rng)
        t = [round(rng.uniform(-100, 100), 3) for _ in range(3)]
        src = "exact degenerate configuration rotated in floating point"
        g.add("double", fmove(a, rot, t), fmove(b, rot, t), src)
    # pairs as a CAD kernel writes them: unit axes, 45/30/60 degree angles in doubles
    s2 = 0.7071067811865476
    c30, s30 = math.cos(math.pi / 6), math.sin(math.pi / 6)
    cad = [
        ({"kind": "cylinder", "point": [F(0)] * 3, "axis": [dbl(s2), dbl(0.7071067811865475), F(0)], "radius2": F(1)},
         fcyl([0, 0, 0], [0, 0, 1], 1.0), "axis=0.7071067811865476,0.7071067811865475,0"),
        (fcyl([0, 0, 0], [1, 0, 0], 1.0), fcyl([0, 0, 0], [s2, s2, 0], 1.0), "equal cylinders at 45 degrees"),
        (fcyl([0, 0, 0], [1, 0, 0], 5.0), fcyl([0, 0, 0], [c30, s30, 0], 5.0), "equal cylinders at 30 degrees"),
        (fcone([0, 0, 0], [0, 0, 1], math.pi / 4), fcone([0, 0, 0], [1, 0, 0], math.pi / 4), "45-degree cones, common vertex"),
        (fcone([0, 0, 0], [0, 0, 1], math.pi / 6), fcyl([0, 0, 0], [1, 0, 0], 1.0), "30-degree cone, unit cylinder"),
        (fcone([0, 0, 2], [0, 0, 1], math.pi / 6), fcyl([0, 0, 0], [1, 0, 0], 1.0), "30-degree cone d sin = r"),
        (fcone([0, 0, 0], [0, s2, s2], math.pi / 4), fcone([0, 0, 1.5], [s2, 0, s2], math.pi / 4), "45-degree cones, 45-degree axes"),
        (fsph([0.1, 0.2, 0.3], 1.0), fsph([0.4, 0.5, 0.6], 0.7), "decimal centres"),
        (fsph([0, 0, 0], 0.3), fcyl([0.1, 0, 0], [0, 0.6, 0.8], 0.2), "decimal radii"),
        (fcyl([10.1, 20.2, 30.3], [0.6, 0.8, 0], 2.5), fcyl([10.1, 20.2, 30.3], [0, 0.6, 0.8], 2.5), "decimal points, Pythagorean axes"),
        (fcyl([0, 0, 0], [1, 1, 1], 0.1), fcone([0.3, 0, 0], [1, -1, 0], 0.5235987755982988), "normalised (1,1,1), 30 degrees"),
        (fcone([1e-3, 0, 0], [1, 0, 0], 0.7853981633974483), fcone([0, 1e-3, 0], [0, 1, 0], 0.7853981633974483), "millimetre offsets"),
    ]
    for a, b, src in cad:
        g.add("double", a, b, src)
    for _ in range(8):
        rot = frot(rng)
        a = fcyl([0, 0, 0], rot[0], rng.choice([1.0, 2.5, 0.1, 7.5]))
        b = fcyl([rng.choice([0.0, 0.5, 1.25]), 0, 0], rot[1], rng.choice([1.0, 2.5, 0.1, 7.5]))
        g.add("double", a, b, "cylinders along the columns of a float rotation")


# ---------------------------------------------------------------- near-degenerate


def near_degenerate(g):
    eps = [F(1, 10**9), F(1, 10**12), F(1, 10**15)]
    add = lambda a, b, src: g.add("near-degenerate", a, b, src)
    for e in eps:
        add(cylinder(O, X, 1), cylinder([0, 0, 2 + e], Y, 1), f"skew cylinders at r1 + r2 + {fmt(e)}")
        add(cylinder(O, X, 1), cylinder([0, 0, 2 - e], Y, 1), f"skew cylinders at r1 + r2 - {fmt(e)}")
        add(cylinder(O, X, 1), cylinder(O, Y, 1 + e), f"Corollary 8.1 near miss, radius2 off by {fmt(e)}")
        add(cone(O, X, 1), cone([e, e, e], Y, 3), f"nearly common vertex ({fmt(e)})")
        add(cylinder(O, X, 1), cylinder([0, 0, e], Y, 1), f"nearly intersecting axes ({fmt(e)})")
        add(cylinder(O, Z, 1), cylinder([1, 0, 0], [e, 0, 1], 1), f"nearly parallel axes ({fmt(e)})")
        add(cylinder(O, X, 1), cone([0, 1 + e, 0], Y, 1), f"cone vertex nearly on the cylinder ({fmt(e)})")
    for e in [1e-9, 1e-12, 1e-15]:
        add(fsph([0, 0, 0], 1.0), fsph([2.0 + e, 0, 0], 1.0), f"spheres {e:g} apart, as doubles")
        add(fcyl([0, 0, 0], [1, 0, 0], 1.0), fcyl([0, 0, 0], [e, 1, 0], 1.0), f"axes {e:g} off perpendicular, as doubles")
        add(fcone([0, 0, 0], [1, 0, 0], math.pi / 4), fcone([0, 0, 0], [0, 1, 0], math.pi / 4 + e), f"equal angles off by {e:g}, as doubles")
    add(cone([2, 0, 0], X, F(1, 3)), cylinder(O, Y, 1 + F(1, 10**13)), "cone-cylinder common inscribed sphere off by 1e-13")
    add(cone(O, Z, 1), cone([3, 0, 1], [F(1, 10**12), 0, 1], 1), "Theorem 8.2 with axes 1e-12 off parallel")
    add(sphere(O, 1), sphere([1, 2, 2], 4 + F(1, 10**14)), "spheres touching, radius2 off by 1e-14")


# ---------------------------------------------------------------- decimal500


def decimal500(g):
    ctx = decimal.Context(prec=500)  # products of 500-digit numbers stay 500 digits
    rng = g.rng

    def d500(lo, hi):
        """A decimal with 500 significant digits in [lo, hi)."""
        whole = rng.randint(lo, hi - 1)
        frac = "".join(str(rng.randint(0, 9)) for _ in range(500 - len(str(abs(whole)))))
        return F(f"{whole}.{frac}")

    def unit500(ang):
        """cos and sin of the double ang to 500 significant digits (Taylor series)."""
        with decimal.localcontext(ctx):
            x = decimal.Decimal(F(ang).numerator) / decimal.Decimal(F(ang).denominator)
            term, cs, sn, k = decimal.Decimal(1), decimal.Decimal(0), decimal.Decimal(0), 0
            while abs(term) > decimal.Decimal(10) ** -520:
                sign = 1 if (k // 2) % 2 == 0 else -1
                if k % 2 == 0:
                    cs += sign * term
                else:
                    sn += sign * term
                k += 1
                term = term * x / k
            return F(str(+cs)), F(str(+sn))

    for _ in range(5):
        a = cylinder([d500(-5, 5) for _ in range(3)], [d500(-3, 3) for _ in range(3)], d500(1, 9))
        b = cone([d500(-5, 5) for _ in range(3)], [d500(-3, 3) for _ in range(3)], d500(1, 3))
        g.add("decimal500", a, b, "random 500-digit decimals")
    a = cylinder([d500(-5, 5) for _ in range(3)], [d500(-3, 3) for _ in range(3)], d500(1, 9))
    b = cylinder([d500(-5, 5) for _ in range(3)], [d500(-3, 3) for _ in range(3)], d500(1, 9))
    g.add("decimal500", a, b, "random 500-digit decimals")
    # 500-digit positions and radii, small-integer axes
    a = cone([d500(-5, 5) for _ in range(3)], [1, 2, 2], d500(1, 3))
    b = cylinder([d500(-5, 5) for _ in range(3)], [2, -1, 0], d500(1, 9))
    g.add("decimal500", a, b, "500-digit positions, radius2 and tan2; integer axes")
    a = cylinder([d500(-5, 5) for _ in range(3)], [0, 0, 1], d500(1, 9))
    b = cylinder([d500(-5, 5) for _ in range(3)], [1, 1, 0], d500(1, 9))
    g.add("decimal500", a, b, "500-digit positions and radius2; integer axes")
    # exact degeneracies written with 500-digit cos/sin (they stay degenerate)
    for ang in [math.pi / 4, math.pi / 6]:
        c, s = unit500(ang)
        g.add("decimal500", cylinder(O, X, 1), cylinder(O, [c, s, 0], 1),
              f"equal cylinders, axis (cos, sin) of {ang!r} to 500 digits")
    c, s = unit500(math.pi / 3)
    g.add("decimal500", cone(O, X, 1), cone(O, [c, s, 0], 3), "common vertex, axis (cos, sin) of pi/3 to 500 digits")
    # tangency rotated by 500-digit cos/sin: c^2 + s^2 != 1, so the axes are 2 sqrt(c^2 + s^2) apart
    c, s = unit500(0.5)
    g.add("decimal500", cylinder(O, X, 1), cylinder([0, -2 * s, 2 * c], [0, c, s], 1),
          "skew cylinders at r1 + r2 rotated about x by 0.5 with 500-digit cos/sin (off tangency by ~1e-500)")
    # a few numbers with 500 digits each
    g.add("decimal500", sphere([d500(-5, 5) for _ in range(3)], d500(1, 9)),
          sphere([d500(-5, 5) for _ in range(3)], d500(1, 9)), "spheres, 500-digit centres and radius2")
    g.add("decimal500", sphere([d500(-3, 3) for _ in range(3)], d500(1, 9)),
          cylinder([0, 0, 0], [1, 2, 3], d500(1, 4)), "sphere and cylinder, 500-digit centre and radius2")
    g.add("decimal500", cone([d500(-5, 5) for _ in range(3)], [1, 0, 1], 1),
          cone([d500(-5, 5) for _ in range(3)], [0, 1, 2], 3), "cones, 500-digit vertices, integer axes and tan2")
    g.add("decimal500", cylinder([0, 0, 0], [1, 0, 0], d500(1, 4)),
          cylinder([0, 1, 2], [1, 3, 2], d500(1, 4)), "skew cylinders, 500-digit radius2 only")


# ---------------------------------------------------------------- occ-regression

from occ_regression import occ_pairs  # noqa: E402  (the Draw data of OCCT's tests)


def occ_group(g):
    for source, a, b in occ_pairs():
        g.add("occ-regression", a, b, source)


# ---------------------------------------------------------------- expect

GROUPS = ["class-same-surface", "class-conics", "class-conic-and-line", "class-lines", "class-points",
          "class-empty", "class-curve", "random-int", "double", "near-degenerate", "occ-regression",
          "decimal500"]


def key(pair):
    return hashlib.sha256(json.dumps([pair["a"], pair["b"]], sort_keys=True).encode()).hexdigest()[:16]


def run_batch(qs, lines, timeout, threads=None):
    env = dict(os.environ)
    if threads:
        env["RAYON_NUM_THREADS"] = str(threads)
    t0 = time.perf_counter()
    p = subprocess.run([qs, "batch"], input="".join(lines), capture_output=True, text=True, timeout=timeout, env=env)
    return time.perf_counter() - t0, p.stdout


def compute_expect(qs, pair, timeout):
    line = json.dumps({"id": pair["name"], "op": "natural", "a": pair["a"], "b": pair["b"]}) + "\n"
    try:
        wall, out = run_batch(qs, [line], timeout, threads=1)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "timeout_s": timeout}
    r = json.loads(out.splitlines()[0])
    if not r.get("ok"):
        return {"status": "error", "error": r.get("error")}
    res = r["result"]
    expect = {"class": res["class"], "conics": res["conics"], "lines": res["lines"], "points": res["points"]}
    rec = {"status": "ok", "expect": expect, "wall_s": wall}
    if wall < 0.3:
        # per-call time: a batch of k copies on one thread minus the one-line run
        k = max(2, min(200, int(0.5 / max(wall, 1e-3))))
        walls = []
        for _ in range(3):
            w1, _ = run_batch(qs, [line], timeout, threads=1)
            wk, _ = run_batch(qs, [line] * k, timeout, threads=1)
            walls.append(max(wk - w1, 0.0) / (k - 1))
        rec["per_call_s"] = sorted(walls)[1]
        rec["per_call_method"] = f"(batch of {k} lines - batch of 1) / {k - 1}, one thread, median of 3"
    else:
        rec["per_call_s"] = wall
        rec["per_call_method"] = "wall time of one batch call (start-up included)"
    return rec


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quadsect", default=os.path.join(ROOT, "target", "release", "quadsect"))
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--only", default="", help="comma-separated groups to (re)compute")
    ap.add_argument("--no-expect", action="store_true", help="write the pairs without running quadsect")
    ap.add_argument("--recompute", action="store_true", help="ignore the answers already recorded")
    ap.add_argument("--summary", action="store_true", help="print the 'before' timings per group and exit")
    args = ap.parse_args()
    if args.summary:
        print(summary_table(json.load(open(BEFORE_PATH))))
        return

    g = Gen(SEED)
    class_groups(g)
    random_int(g)
    double_group(g)
    near_degenerate(g)
    occ_group(g)
    decimal500(g)

    before = {"pairs": {}, "dropped": {}}
    if os.path.exists(BEFORE_PATH) and not args.recompute:
        before = json.load(open(BEFORE_PATH))
    only = set(filter(None, args.only.split(",")))
    pairs_out = []
    names = {}
    for pair in g.pairs:
        k = key(pair)
        rec = before["pairs"].get(k) or before["dropped"].get(k)
        if not args.no_expect and (rec is None or (only and pair["group"] in only)):
            if rec is not None and rec.get("status") == "timeout" and rec.get("timeout_s", 0) >= args.timeout:
                pass
            else:
                print(f"{pair['name']} ...", end="", file=sys.stderr, flush=True)
                rec = compute_expect(args.quadsect, pair, args.timeout)
                rec.update({"name": pair["name"], "group": pair["group"]})
                print(f" {rec['status']} {rec.get('wall_s', 0):.3f}s {rec.get('expect', '')}", file=sys.stderr)
                before["pairs"].pop(k, None)
                before["dropped"].pop(k, None)
                (before["pairs"] if rec["status"] == "ok" else before["dropped"])[k] = rec
                save_before(before)
        if rec is not None:
            names.setdefault(k, []).append(pair["name"])
        if rec is not None and rec.get("status") == "ok":
            pair["expect"] = rec["expect"]
            pairs_out.append(pair)
        elif rec is None and args.no_expect:
            pairs_out.append(pair)
    for part in ("pairs", "dropped"):
        for k in [k for k in before[part] if k not in names]:
            del before[part][k]  # a pair no longer generated
    for k, rec in list(before["pairs"].items()) + list(before["dropped"].items()):
        if k in names:
            rec["name"] = names[k][0]
            rec["names"] = names[k]
    if not args.no_expect:
        save_before(before)
    counts = {gr: sum(1 for p in pairs_out if p["group"] == gr) for gr in GROUPS}
    doc = {
        "description": (
            "Natural-quadric benchmark pairs of issue 15, written by scripts/gen_natural_pairs.py "
            f"(random.Random({SEED}); exact numbers: integers, p/q or exact decimals, doubles as their "
            "exact binary value). expect = class and counts of quadsect's exact route at generation "
            "time. Groups and counts: " + ", ".join(f"{k} {v}" for k, v in counts.items()) + "."
        ),
        "seed": SEED,
        "counts": counts,
        "pairs": pairs_out,
    }
    os.makedirs(os.path.dirname(PAIRS_PATH), exist_ok=True)
    with open(PAIRS_PATH, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    print(f"wrote {len(pairs_out)} pairs to {PAIRS_PATH}: {counts}", file=sys.stderr)


def group_summary(before):
    """Per group: pairs, median and max of per_call_s and of wall_s, dropped pairs."""
    out = {}
    def groups_of(r):
        return {n.rsplit("-", 1)[0] for n in r.get("names", [r["name"]])}

    for gr in GROUPS:
        recs = [r for r in before["pairs"].values() if gr in groups_of(r)]
        n = sum(1 for r in recs for x in r.get("names", [r["name"]]) if x.rsplit("-", 1)[0] == gr)
        if not recs:
            continue
        pc = sorted(r["per_call_s"] for r in recs)
        wall = sorted(r["wall_s"] for r in recs)
        slowest = max(recs, key=lambda r: r["per_call_s"])
        out[gr] = {"pairs": n, "distinct": len(recs), "median_per_call_s": pc[(len(pc) - 1) // 2] if len(pc) % 2
                   else (pc[len(pc) // 2 - 1] + pc[len(pc) // 2]) / 2, "max_per_call_s": pc[-1],
                   "slowest": slowest["name"], "median_wall_s": wall[len(wall) // 2],
                   "dropped": sorted(r["name"] for r in before["dropped"].values() if gr in groups_of(r))}
    return out


def summary_table(before):
    def t(x):
        return f"{x * 1e3:.2f} ms" if x < 1 else f"{x:.2f} s"

    lines = ["| group | pairs | median per pair | slowest pair | dropped (no answer within the limit) |",
             "|---|---|---|---|---|"]
    for gr, s in group_summary(before).items():
        lines.append(f"| {gr} | {s['pairs']} | {t(s['median_per_call_s'])} | {t(s['max_per_call_s'])} "
                     f"({s['slowest']}) | {', '.join(s['dropped']) or '–'} |")
    return "\n".join(lines)


def save_before(before):
    before["description"] = (
        "Timings of quadsect's present exact route ('before' of issue 15) per pair of "
        "benches/data/natural_pairs.json, keyed by a hash of (a, b): wall_s = one `quadsect batch` "
        "process with one line (start-up included); per_call_s = time per call (see per_call_method). "
        "'dropped' lists pairs that did not finish within the time limit or failed."
    )
    before["groups"] = group_summary(before)
    tmp = BEFORE_PATH + ".tmp"
    with open(tmp, "w") as f:
        json.dump(before, f, indent=1, sort_keys=True)
    os.replace(tmp, BEFORE_PATH)


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
