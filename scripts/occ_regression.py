"""Natural-quadric pairs from Open CASCADE's own regression test scripts.

The Draw (Tcl) lines of OCCT 8.0.1's tests/ that define spheres, cylinders
and cones, move them, and intersect them are kept as data in
occ_regression_data.json (extracted from the OCCT sources with
`python3 scripts/occ_regression.py --extract GIT_DIR`, which reads the mirror
with `git --git-dir=GIT_DIR show`).  This module interprets that small part
of Draw and returns the pairs of natural quadrics the test intersects:

  * surfaces: `cylinder|sphere name [x y z [dx dy dz [xdx xdy xdz]]] R` and
    `cone name [...] semi-angle-in-degrees R` (Geom_ConicalSurface: R is the
    radius at the placement origin, so the vertex is origin - R/tan(angle)*dir),
    and the primitives `pcylinder name [plane] R H`, `pcone name [plane] R1 R2 H`
    (vertex where the radius is 0, tan = (R2 - R1)/H), `psphere name [plane] R`;
  * moves: ttranslate/translate, trotate/rotate (degrees), tmirror, tscale,
    copy/tcopy, mkface, trim*, and `-copy`;
  * intersections: `intersect r s1 s2`, `bopcurves f1 f2`, `bop a b`,
    `bcut|bfuse|bcommon|bsection r a b`, `baddobjects/baddtools ... bfillds|bbuild
    |bcbuild|bapibop`, `mkvolume r f1 f2 ...`: every pair of natural quadrics
    from two different arguments.

Exact where the script's numbers allow it: decimal literals are exact
rationals; rotations by multiples of 90 degrees about an axis of rational
length and by 180 degrees about any axis are rational; cone angles of 30, 45
and 60 degrees have tan^2 1/3, 1, 3 (the angle the test means; OCC itself
holds the double nearest to angle*pi/180).  Everything else (other angles,
sqrt() in an expression, a cone vertex R/tan(angle) away from the placement
origin with irrational tan) is computed in doubles the way OCC does it
(gp_Mat::SetRotation's Rodrigues formula, gp_Cone::Apex, gp_Dir
normalisation) and written as the exact values of those doubles; `source`
then says "doubles".  Python's double arithmetic may differ from OCC's by an
ulp where the operation order differs.
"""
import json
import math
import os
import re
import subprocess
import sys
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "occ_regression_data.json")

GEOM = {"cylinder", "cone", "sphere", "plane", "pcylinder", "pcone", "psphere", "ttranslate", "trotate",
        "tmirror", "tscale", "translate", "rotate", "copy", "tcopy", "mkface", "trim", "trimu", "trimv",
        "set", "dset", "intersect", "bopcurves", "bop", "bcut", "bfuse", "bcommon", "bsection", "baddobjects",
        "baddtools", "bclearobjects", "bcleartools", "bfillds", "bbuild", "bcbuild", "bapibop", "mkvolume",
        "box", "baddcompound", "compound", "bopcommon", "bopfuse", "bopcut", "boptuc", "bopsection",
        "add", "shape"}


# ---------------------------------------------------------------- values


class Num:
    """A value of the script: exact (Fraction) unless a double was needed."""

    __slots__ = ("v", "exact")

    def __init__(self, v, exact):
        self.v, self.exact = v, exact

    def f(self):
        return float(self.v)


def num_of(x):
    if isinstance(x, Num):
        return x
    if isinstance(x, F) or isinstance(x, int):
        return Num(F(x), True)
    return Num(float(x), False)


_lit = re.compile(r"(?<![A-Za-z_0-9.])(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)")


class Inexact(Exception):
    pass


def evaluate(expr, variables):
    """A Draw/Tcl arithmetic expression: exact Fraction if only + - * / of literals."""
    e = expr.strip().rstrip(",").strip('"').replace("{", "").replace("}", "")
    if re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", e):
        return Num(F(e), True)
    names = {"pi": math.pi, "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan,
             "atan": math.atan, "atan2": math.atan2, "abs": abs, "F": F}
    for k, v in variables.items():
        names[k] = v.v
    py = _lit.sub(lambda m: f"F('{m.group(1)}')", e)
    try:
        v = eval(py, {"__builtins__": {}}, names)  # noqa: S307  (arithmetic of a test script)
    except Exception as err:  # pragma: no cover - reported to the caller
        raise ValueError(f"cannot evaluate {expr!r}: {err}") from err
    return num_of(v)


# ---------------------------------------------------------------- geometry

# A surface: {"kind", "o" (point/centre/vertex), "d" (axis), "r2" | "t2", "exact"}
# with Fractions (exact) or floats.


def fl(s):
    """The same surface in doubles."""
    out = dict(s)
    out["exact"] = False
    out["o"] = [float(x) for x in s["o"]]
    if "d" in s:
        out["d"] = [float(x) for x in s["d"]]
    return out


def rational_sqrt(q):
    q = F(q)
    if q < 0:
        return None
    a, b = math.isqrt(q.numerator), math.isqrt(q.denominator)
    if a * a == q.numerator and b * b == q.denominator:
        return F(a, b)
    return None


def unit_f(d):
    n = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
    return [d[0] / n, d[1] / n, d[2] / n]


def rot_matrix_f(axis, ang):
    """gp_Mat::SetRotation (Rodrigues) in doubles."""
    a, b, c = unit_f(axis)
    cs, sn = math.cos(ang), math.sin(ang)
    om = 1.0 - cs
    return [
        [1.0 + om * (-(b * b + c * c)), om * a * b - sn * c, om * a * c + sn * b],
        [om * a * b + sn * c, 1.0 + om * (-(a * a + c * c)), om * b * c - sn * a],
        [om * a * c - sn * b, om * b * c + sn * a, 1.0 + om * (-(a * a + b * b))],
    ]


def rot_matrix_exact(axis, deg):
    """The rotation by deg degrees about axis if it is rational, else None."""
    deg = F(deg) % 360
    axis = [F(x) for x in axis]
    n2 = sum(x * x for x in axis)
    if deg == 0:
        return [[F(int(i == j)) for j in range(3)] for i in range(3)]
    if deg == 180:
        return [[2 * axis[i] * axis[j] / n2 - int(i == j) for j in range(3)] for i in range(3)]
    if deg in (90, 270):
        n = rational_sqrt(n2)
        if n is None:
            return None
        a, b, c = (x / n for x in axis)
        s = 1 if deg == 90 else -1
        # cos = 0: R = s [n]x + n n^T
        return [
            [a * a, a * b - s * c, a * c + s * b],
            [a * b + s * c, b * b, b * c - s * a],
            [a * c - s * b, b * c + s * a, c * c],
        ]
    return None


def apply(s, m, t):
    """P -> m P + t on the surface (exact or double)."""
    out = dict(s)
    out["o"] = [sum(m[i][j] * s["o"][j] for j in range(3)) + t[i] for i in range(3)]
    if "d" in s:
        out["d"] = [sum(m[i][j] * s["d"][j] for j in range(3)) for i in range(3)]
    return out


def transform(s, kind, args):
    """ttranslate / trotate / tmirror / tscale with Num arguments."""
    exact = s["exact"] and all(a.exact for a in args)
    if kind == "translate":
        if exact:
            return apply(s, [[F(int(i == j)) for j in range(3)] for i in range(3)], [a.v for a in args])
        s = fl(s)
        return apply(s, [[float(i == j) for j in range(3)] for i in range(3)], [a.f() for a in args])
    if kind == "rotate":
        p, d, ang = args[0:3], args[3:6], args[6]
        m = rot_matrix_exact([a.v for a in d], ang.v) if exact else None
        if m is not None:
            pv = [a.v for a in p]
            loc = [pv[i] - sum(m[i][j] * pv[j] for j in range(3)) for i in range(3)]
            return apply(s, m, loc)
        s = fl(s)
        m = rot_matrix_f([a.f() for a in d], ang.f() * (math.pi / 180.0))
        pv = [a.f() for a in p]
        loc = [pv[i] - sum(m[i][j] * pv[j] for j in range(3)) for i in range(3)]
        return apply(s, m, loc)
    if kind == "mirror":
        p, n = [a.v for a in args[0:3]], [a.v for a in args[3:6]]
        if exact:
            n2 = sum(x * x for x in n)
            m = [[int(i == j) - 2 * n[i] * n[j] / n2 for j in range(3)] for i in range(3)]
        else:
            s = fl(s)
            p, n = [float(x) for x in p], unit_f([float(x) for x in n])
            m = [[float(i == j) - 2 * n[i] * n[j] for j in range(3)] for i in range(3)]
        loc = [p[i] - sum(m[i][j] * p[j] for j in range(3)) for i in range(3)]
        return apply(s, m, loc)
    if kind == "scale":
        p, k = args[0:3], args[3]
        if not exact:
            s = fl(s)
        kv = k.v if exact else k.f()
        pv = [a.v if exact else a.f() for a in p]
        out = dict(s)
        out["o"] = [pv[i] + kv * (s["o"][i] - pv[i]) for i in range(3)]
        if "r2" in s:
            out["r2"] = s["r2"] * kv * kv
        return out
    raise ValueError(kind)


def surface_from_draw(cmd, nums):
    """Geometric `cylinder|sphere|cone name ...` (nums without the name)."""
    npar = 2 if cmd == "cone" else 1
    frame, par = nums[:-npar], nums[-npar:]
    o = frame[0:3] if len(frame) >= 3 else [Num(F(0), True)] * 3
    d = frame[3:6] if len(frame) >= 6 else [Num(F(0), True), Num(F(0), True), Num(F(1), True)]
    if len(frame) not in (0, 3, 6, 9):
        raise ValueError(f"{cmd}: {len(nums)} numbers")
    exact = all(x.exact for x in o + d + par)
    if cmd in ("cylinder", "sphere"):
        r = par[0]
        s = {"kind": cmd, "o": [x.v for x in o], "r2": (r.v * r.v) if exact else F(r.f()) ** 2, "exact": exact}
        if cmd == "cylinder":
            s["d"] = [x.v for x in d]
        return s if exact else fl(s)
    ang, r = par
    tan_exact = {F(45): (F(1), F(1)), F(30): (None, F(1, 3)), F(60): (None, F(3))}
    if ang.exact and ang.v in tan_exact and exact:
        tan, t2 = tan_exact[ang.v]
        dv = [x.v for x in d]
        if r.v == 0:
            return {"kind": "cone", "o": [x.v for x in o], "d": dv, "t2": t2, "exact": True}
        n = rational_sqrt(sum(x * x for x in dv))
        if tan is not None and n is not None:
            v = [o[i].v - r.v / tan * dv[i] / n for i in range(3)]
            return {"kind": "cone", "o": v, "d": dv, "t2": t2, "exact": True}
    # doubles, as Geom_ConicalSurface / gp_Cone::Apex compute them
    rad = ang.f() * (math.pi / 180.0)
    dn = unit_f([x.f() for x in d])
    k = -r.f() / math.tan(rad)
    v = [dn[i] * k + o[i].f() for i in range(3)]
    if r.f() == 0:
        v = [x.f() for x in o]
    return {"kind": "cone", "o": v, "d": [x.f() for x in d], "t2": F(math.tan(rad)) ** 2, "exact": False,
            "note": "cone angle in doubles" + ("" if r.f() == 0 else ", vertex = gp_Cone::Apex in doubles")}


def primitive(cmd, nums, frame):
    """pcylinder / pcone / psphere in the placement frame (o, z)."""
    o, z = frame
    exact_frame = all(isinstance(x, F) for x in o + z)
    if cmd == "pcylinder":
        r = nums[0]
        return {"kind": "cylinder", "o": list(o), "d": list(z), "r2": r.v * r.v, "exact": r.exact and exact_frame}
    if cmd == "psphere":
        r = nums[0]
        return {"kind": "sphere", "o": list(o), "r2": r.v * r.v, "exact": r.exact and exact_frame}
    r1, r2, h = nums[0:3]
    if r1.v == r2.v:
        return None
    if all(x.exact for x in (r1, r2, h)) and exact_frame:
        n = rational_sqrt(sum(x * x for x in z))
        if n is not None:
            h0 = -r1.v * h.v / (r2.v - r1.v)
            v = [o[i] + h0 * z[i] / n for i in range(3)]
            return {"kind": "cone", "o": v, "d": list(z), "t2": ((r2.v - r1.v) / h.v) ** 2, "exact": True}
    zn = unit_f([float(x) for x in z])
    ang = math.atan((r2.f() - r1.f()) / h.f())
    k = -r1.f() / math.tan(ang)
    v = [zn[i] * k + float(o[i]) for i in range(3)]
    return {"kind": "cone", "o": v, "d": [float(x) for x in z], "t2": F(math.tan(ang)) ** 2, "exact": False}


def to_natural(s):
    """The surface as the generator's quadric dict (Fractions; doubles exactly)."""
    o = [F(x) for x in s["o"]]
    if s["kind"] == "sphere":
        return {"kind": "sphere", "center": o, "radius2": F(s["r2"])}
    d = [F(x) for x in s["d"]]
    if s["kind"] == "cylinder":
        return {"kind": "cylinder", "point": o, "axis": d, "radius2": F(s["r2"])}
    return {"kind": "cone", "vertex": o, "axis": d, "tan2": F(s["t2"])}


# ---------------------------------------------------------------- interpreter


def tcl_expr(expr):
    """A Tcl [expr ...] in Tcl's arithmetic (doubles, or integers), as the string Tcl substitutes."""
    e = expr.strip().strip("{}").replace(",", " ")
    names = {"pi": math.pi, "sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan,
             "atan": math.atan, "abs": abs, "double": float}
    try:
        if re.fullmatch(r"[0-9+\-* ()]*", e):
            return str(eval(e, {"__builtins__": {}}, {}))  # noqa: S307  integer arithmetic
        v = eval(e, {"__builtins__": {}}, names)  # noqa: S307  double arithmetic, as Tcl
    except Exception as err:
        raise ValueError(f"cannot evaluate [expr {expr}]: {err}") from err
    return repr(float(v))


def tcl_words(line, tclvars):
    """Split a Draw line into words after $var / ${var} / [expr ...] substitution."""
    def sub_vars(text):
        return re.sub(r"\$\{([^}]+)\}|\$([A-Za-z_][A-Za-z_0-9-]*)",
                      lambda m: tclvars[m.group(1) or m.group(2)], text)

    line = sub_vars(line)
    while True:
        m = re.search(r"\[(?:expr|dval)\s+([^\[\]]*)\]", line)
        if not m:
            break
        line = line[: m.start()] + tcl_expr(m.group(1)) + line[m.end():]
    if "[" in line or "$" in line:
        raise ValueError(f"unsupported Tcl in {line!r}")
    line = line.split(";#")[0].split(";")[0]
    return line.split()


def interpret(text):
    """The pairs (surface, surface) a test script intersects; raises on unsupported input."""
    tclvars, dvars = {}, {}
    geoms = {}  # name -> list of surfaces (a face/shape may carry several)
    planes = {}
    objects, tools = [], []
    pairs = []

    def val(w):
        if w in dvars:
            return dvars[w]
        return evaluate(w, dvars)

    def gen_pairs(args):
        lists = [geoms.get(a, []) for a in args]
        for i in range(len(lists)):
            for j in range(i + 1, len(lists)):
                for s in lists[i]:
                    for t in lists[j]:
                        pairs.append((s, t))

    for raw in text.splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        w0 = line.split()[0]
        if w0 not in GEOM:
            continue
        if w0 == "set":
            parts = line.split(None, 2)
            if len(parts) == 3:
                try:
                    tclvars[parts[1]] = tcl_words("x " + parts[2], tclvars)[1]
                except (ValueError, KeyError, IndexError):
                    tclvars.pop(parts[1], None)  # not a number (a command's output): unused here
            continue
        w = tcl_words(line, tclvars)
        cmd, rest = w[0], w[1:]
        if rest and rest[-1] in ("-copy", "-copymesh"):
            rest = rest[:-1]
        if cmd == "dset":
            for k in range(0, len(rest) - 1, 2):
                dvars[rest[k]] = val(rest[k + 1])
        elif cmd in ("cylinder", "sphere", "cone"):
            geoms[rest[0]] = [surface_from_draw(cmd, [val(x) for x in rest[1:]])]
        elif cmd == "plane":
            nums = [val(x) for x in rest[1:]]
            o = [x.v for x in nums[0:3]] if len(nums) >= 3 else [F(0)] * 3
            z = [x.v for x in nums[3:6]] if len(nums) >= 6 else [F(0), F(0), F(1)]
            if not all(x.exact for x in nums):
                o, z = [float(x) for x in o], [float(x) for x in z]
            planes[rest[0]] = (o, z)
            geoms[rest[0]] = []
        elif cmd in ("pcylinder", "pcone", "psphere"):
            frame = ([F(0)] * 3, [F(0), F(0), F(1)])
            args = rest[1:]
            if args and args[0] in planes:
                frame = planes[args[0]]
                args = args[1:]
            s = primitive(cmd, [val(x) for x in args], frame)
            geoms[rest[0]] = [s] if s else []
        elif cmd in ("ttranslate", "translate"):
            d = [val(x) for x in rest[-3:]]
            for name in rest[:-3]:
                geoms[name] = [transform(s, "translate", d) for s in geoms.get(name, [])]
        elif cmd in ("trotate", "rotate"):
            a = [val(x) for x in rest[-7:]]
            for name in rest[:-7]:
                geoms[name] = [transform(s, "rotate", a) for s in geoms.get(name, [])]
        elif cmd == "tmirror":
            a = [val(x) for x in rest[-6:]]
            for name in rest[:-6]:
                geoms[name] = [transform(s, "mirror", a) for s in geoms.get(name, [])]
        elif cmd == "tscale":
            a = [val(x) for x in rest[-4:]]
            for name in rest[:-4]:
                geoms[name] = [transform(s, "scale", a) for s in geoms.get(name, [])]
        elif cmd in ("copy", "tcopy"):
            names = [x for x in rest if not x.startswith("-")]
            for k in range(0, len(names) - 1, 2):
                geoms[names[k + 1]] = list(geoms.get(names[k], []))
        elif cmd in ("mkface", "trim", "trimu", "trimv"):
            geoms[rest[0]] = list(geoms.get(rest[1], []))
        elif cmd in ("compound", "shape"):
            if cmd == "compound":
                geoms[rest[-1]] = [s for n in rest[:-1] for s in geoms.get(n, [])]
            else:
                geoms[rest[0]] = []
        elif cmd == "add":
            geoms[rest[1]] = geoms.get(rest[1], []) + geoms.get(rest[0], [])
        elif cmd == "box":
            geoms[rest[0]] = []
        elif cmd in ("intersect", "bcut", "bfuse", "bcommon", "bsection"):
            args = rest[1:3]
            gen_pairs(args)
            geoms[rest[0]] = [s for n in args for s in geoms.get(n, [])]
        elif cmd in ("bopcurves", "bop"):
            gen_pairs(rest[0:2])
        elif cmd == "mkvolume":
            gen_pairs([x for x in rest[1:] if not x.startswith("-")])
        elif cmd == "bclearobjects":
            objects = []
        elif cmd == "bcleartools":
            tools = []
        elif cmd in ("baddobjects", "baddcompound"):
            objects += rest
        elif cmd == "baddtools":
            tools += rest
        elif cmd in ("bfillds", "bbuild", "bcbuild", "bapibop"):
            gen_pairs(objects + tools)
    return pairs


def canon(nat):
    """A canonical key of a quadric (for removing repeated pairs)."""
    n = dict(nat)
    if "axis" in n:
        a = n["axis"]
        k = next(x for x in a if x != 0)
        a = [x / k for x in a]
        n["axis"] = a
        if n["kind"] == "cylinder":
            p = n["point"]
            t = sum(pi * ai for pi, ai in zip(p, a)) / sum(ai * ai for ai in a)
            n["point"] = [pi - t * ai for pi, ai in zip(p, a)]
    return json.dumps({k: [str(x) for x in v] if isinstance(v, list) else str(v) for k, v in n.items()}, sort_keys=True)


PER_TEST = 4


def occ_pairs(data_path=DATA, per_test=PER_TEST):
    """[(source, a, b)]: the distinct natural-quadric pairs of the tests, in test order.

    A test that intersects many surfaces (a model of many faces) gives at most
    per_test pairs (evenly spaced in the order the test meets them), so that
    no single test dominates the group."""
    data = json.load(open(data_path))
    seen = {}
    out = []
    for test in data["tests"]:
        try:
            pairs = interpret(test["draw"])
        except (ValueError, KeyError, IndexError, ZeroDivisionError) as err:
            print(f"occ_regression: skipped {test['path']}: {err}", file=sys.stderr)
            continue
        fresh = []
        for s, t in pairs:
            a, b = to_natural(s), to_natural(t)
            key = tuple(sorted([canon(a), canon(b)]))
            if key in seen:
                seen[key].append(test["path"])
            elif key not in [k for _, _, k in fresh]:
                fresh.append((s, t, key))
        if len(fresh) > per_test:
            fresh = [fresh[(i * (len(fresh) - 1)) // (per_test - 1)] for i in range(per_test)]
        for s, t, _ in fresh:
            a, b = to_natural(s), to_natural(t)
            key = tuple(sorted([canon(a), canon(b)]))
            if key in seen:
                seen[key].append(test["path"])
                continue
            seen[key] = [test["path"]]
            how = test.get("note", "") + ("; " if "note" in test else "")
            how += "exact" if s["exact"] and t["exact"] else "doubles (" + "; ".join(
                sorted({x.get("note", "computed in doubles as OCC does") for x in (s, t) if not x["exact"]})) + ")"
            out.append([test["path"], how, a, b, key])
    result = []
    for path, how, a, b, key in out:
        also = [p for p in seen[key] if p != path]
        src = f"OCCT 8.0.1 {path}; {how}"
        if also:
            src += "; same pair in " + ", ".join(sorted(set(also))[:6]) + (" …" if len(set(also)) > 6 else "")
        result.append((src, a, b))
    return result


# ---------------------------------------------------------------- extraction

DIRS = ["tests/lowalgos/intss", "tests/bugs", "tests/boolean", "tests/cr/base", "tests/perf/modalg"]

# Tests whose intersections sit in a Tcl loop: the loop unrolled by hand (data of
# the test, the loop variable's values written out).
UNROLLED = [
    {"path": "tests/bugs/modalg_7/bug29182_1",
     "note": "the loop `copy fc f1; trotate f1 0 0 0 1 0 0 $i*5` for i = 1, 6, 10",
     "draw": "cylinder c 0 10 0 1 0 0 10\nmkface fc c\n"
             "copy fc f1\ntrotate f1 0 0 0 1 0 0 5\ncopy fc f6\ntrotate f6 0 0 0 1 0 0 30\n"
             "copy fc f10\ntrotate f10 0 0 0 1 0 0 50\nbaddobjects fc f1 f6 f10\nbfillds"},
]


def extract(git_dir):
    """The geometric Draw lines of the OCCT tests that define and intersect natural quadrics."""
    def git(*args):
        return subprocess.run(["git", "--git-dir", git_dir, *args], capture_output=True, check=True).stdout.decode("utf-8", "replace")

    pat = r"^\s*(cylinder|cone|sphere|pcylinder|pcone|psphere)\s"
    files = [f.split(":", 1)[1] for f in git("grep", "-l", "-E", pat, "HEAD", "--", *DIRS).split()]
    tests = []
    for path in files:
        text = git("show", f"HEAD:{path}")
        if not re.search(r"^\s*(cylinder|cone|sphere|pcylinder|pcone|psphere)\s", text, re.M):
            continue
        keep = []
        for line in text.splitlines():
            s = line.strip()
            m = re.search(r"\[\s*((?:intersect|bopcurves)\s+[^\[\]]*)\]", s)
            if m:
                s = m.group(1)
            if s and s.split()[0] in GEOM:
                keep.append(s)
        draw = "\n".join(keep)
        try:
            pairs = interpret(draw)
        except (ValueError, KeyError, IndexError, ZeroDivisionError) as err:
            print(f"skip {path}: {err}", file=sys.stderr)
            continue
        if pairs:
            tests.append({"path": path, "draw": draw})
    for t in UNROLLED:
        tests = [x for x in tests if x["path"] != t["path"]] + [t]
    head = git("rev-parse", "HEAD").strip()
    return {"description": "Draw lines (data) of Open CASCADE tests that intersect natural quadrics, "
                           f"OCCT commit {head} (8.0.1); interpreted by scripts/occ_regression.py",
            "commit": head, "tests": tests}


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--extract":
        doc = extract(sys.argv[2])
        with open(DATA, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
        print(f"{len(doc['tests'])} tests -> {DATA}; {len(occ_pairs())} distinct pairs", file=sys.stderr)
    else:
        for src, a, b in occ_pairs():
            print(src)
