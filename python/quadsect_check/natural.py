"""Claims of ``natural`` answers (two natural quadrics).

The quadrics are rebuilt from the request's own text (JSON object or short
syntax) with their contract equations, negative inside:

* sphere   |P − O|² − r2
* cylinder |(P − Q) × a|² − r2·|a|²
* cone     |a|²·|P − V|² − (1 + t2)·((P − V)·a)²
"""


from fractions import Fraction

from . import poly as P
from .exact import QS, CheckError, NotChecked, cross, dot, json_number, parse_point, parse_value, sqrt_rational

FIELDS = {
    "sphere": ("center", "radius2"),
    "cylinder": ("point", "axis", "radius2"),
    "cone": ("vertex", "axis", "tan2", "tan", "cos2", "sin2"),
}


def _vec(v, float_mode, what):
    if isinstance(v, str):
        v = v.split(",")
    if not isinstance(v, list) or len(v) != 3:
        raise CheckError(f"{what}: expected three numbers")
    return [json_number(c.strip() if isinstance(c, str) else c, float_mode) for c in v]


def _fields(spec):
    """The kind and the fields of a quadric given as in the request (a JSON
    object or the short syntax ``cone vertex=0,0,0 axis=1,0,0 tan2=1/3``)."""
    if isinstance(spec, str) and spec.strip().startswith("{"):
        import json

        spec = json.loads(spec)
    if isinstance(spec, str):
        words = spec.split()
        if not words:
            raise CheckError("empty quadric")
        fields = {}
        for w in words[1:]:
            if "=" not in w:
                raise CheckError(f"expected name=value, got {w!r}")
            k, v = w.split("=", 1)
            if k in fields:
                raise CheckError(f"field {k} given twice")
            fields[k] = v
        kind = words[0]
    elif isinstance(spec, dict):
        fields = dict(spec)
        kind = fields.pop("kind", None)
    else:
        raise CheckError(f"a quadric must be a JSON object or the short syntax, got {spec!r}")
    if kind not in FIELDS:
        raise CheckError(f"unknown quadric kind {kind!r}")
    extra = set(fields) - set(FIELDS[kind])
    if extra:
        raise CheckError(f"unknown field(s) {sorted(extra)} for a {kind}")
    return kind, fields


def quadric(spec, float_mode=False):
    """The equation (a polynomial) of a natural quadric given as in the
    request, and its data ``(kind, point, axis, r2 or t2)`` (``None`` for a
    sphere)."""
    kind, fields = _fields(spec)
    x = [P.var(i) for i in range(3)]

    def num(name):
        if name not in fields:
            raise CheckError(f"a {kind} needs {name}")
        return json_number(fields[name], float_mode)

    def vec(name):
        if name not in fields:
            raise CheckError(f"a {kind} needs {name}")
        return _vec(fields[name], float_mode, name)

    def diff(c):  # P − c, three linear polynomials
        return [P.add(x[i], P.const(c[i]), -1) for i in range(3)]

    def dot(u, v):  # u polynomials, v numbers
        r = {}
        for i in range(3):
            r = P.add(r, P.scale(u[i], v[i]))
        return r

    def norm2p(u):
        r = {}
        for i in range(3):
            r = P.add(r, P.mul(u[i], u[i]))
        return r

    if kind == "sphere":
        r2 = num("radius2")
        if r2 <= 0:
            raise CheckError("radius2 must be positive")
        return P.add(norm2p(diff(vec("center"))), P.const(r2), -1), None
    axis = vec("axis")
    a2 = sum(c * c for c in axis)
    if a2 == 0:
        raise CheckError("the axis must be non-zero")
    if kind == "cylinder":
        r2 = num("radius2")
        if r2 <= 0:
            raise CheckError("radius2 must be positive")
        base = vec("point")
        d = diff(base)
        cr = [
            P.add(P.scale(d[1], axis[2]), P.scale(d[2], axis[1]), -1),
            P.add(P.scale(d[2], axis[0]), P.scale(d[0], axis[2]), -1),
            P.add(P.scale(d[0], axis[1]), P.scale(d[1], axis[0]), -1),
        ]
        return P.add(norm2p(cr), P.const(r2 * a2), -1), ("cylinder", base, axis, r2)
    angles = [k for k in ("tan2", "tan", "cos2", "sin2") if k in fields]
    if len(angles) != 1:
        raise CheckError("a cone needs exactly one of tan2, tan, cos2, sin2")
    v = num(angles[0])
    if angles[0] in ("tan2", "tan"):
        if v <= 0:
            raise CheckError(f"{angles[0]} must be positive")
        t2 = v if angles[0] == "tan2" else v * v
    else:
        if not 0 < v < 1:
            raise CheckError(f"{angles[0]} must lie in (0, 1)")
        t2 = (1 - v) / v if angles[0] == "cos2" else v / (1 - v)
    base = vec("vertex")
    d = diff(base)
    ax = dot(d, axis)
    return P.add(P.scale(norm2p(d), a2), P.scale(P.mul(ax, ax), 1 + t2), -1), ("cone", base, axis, t2)


def proportional(p, q):
    """Whether p = c·q for a non-zero rational c."""
    if set(p) != set(q) or not p:
        return False
    e0 = next(iter(p))
    c = p[e0] / q[e0]
    return all(p[e] == c * q[e] for e in p)


def _on_surface_along(eq, origin, dirs, what):
    """eq (degree ≤ 2) restricted to origin + Σ t_k·dirs[k]: a dict of
    monomials in the t_k with Q(√d) coefficients, from the restricted form
    Tᵀ·M·T (M the 4×4 matrix of eq, T the columns (dirs[k], 0) and
    (origin, 1))."""
    m = [[QS(x) for x in row] for row in P.form_matrix(eq)]
    cols = [list(d) + [QS(0)] for d in dirs] + [list(origin) + [QS(1)]]
    mc = [[sum((m[i][j] * c[j] for j in range(4) if not c[j].is_zero()), QS(0)) for i in range(4)] for c in cols]
    k = len(dirs)
    r = [[sum((cols[a][i] * mc[b][i] for i in range(4) if not cols[a][i].is_zero()), QS(0)) for b in range(k + 1)] for a in range(k + 1)]
    out = {}

    def put(e, v):
        if not v.is_zero():
            out[tuple(e)] = v

    for a in range(k):
        e = [0] * k
        e[a] = 2
        put(e, r[a][a])
        for b in range(a + 1, k):
            e = [0] * k
            e[a] = e[b] = 1
            put(e, r[a][b] * QS(2))
        e = [0] * k
        e[a] = 1
        put(e, r[a][k] * QS(2))
    put([0] * k, r[k][k])
    return out


def _multiple_of(restricted, model, what):
    """``restricted`` = κ·``model`` (both dicts over Q(√d)) with κ ≠ 0; κ."""
    keys = set(restricted) | set(model)
    k0 = next((k for k in model if not model[k].is_zero()), None)
    if k0 is None or k0 not in restricted:
        raise CheckError(f"{what}: the surface is not a multiple of the component's equation")
    # κ = restricted[k0] / model[k0]: compare cross products instead
    for k in keys:
        lhs = restricted.get(k, QS(0)) * model[k0]
        rhs = model.get(k, QS(0)) * restricted[k0]
        if not (lhs - rhs).is_zero():
            raise CheckError(f"{what}: the surface is not a multiple of the component's equation")


def _conic_model(c, n):
    """The conic in its plane: origin, in-plane directions and the equation
    (dict over (s, t)) it satisfies, from the listed exact data."""
    kind = c.get("conic")
    dirs = c.get("axis_directions") or []
    if kind in ("ellipse", "circle", "hyperbola"):
        ctr = parse_point(c.get("center"), "center")
        if len(dirs) != 2 or len(c.get("semi_axes2") or []) != 2:
            raise CheckError(f"a {kind} needs two axis directions and two squared semi-axes")
        d1, d2 = (parse_point(d, "axis direction") for d in dirs)
        a2, b2 = (parse_value(v, "semi_axes2") for v in c["semi_axes2"])
        if a2.sign() <= 0 or b2.sign() <= 0:
            raise CheckError("squared semi-axes must be positive (a real conic)")
        if kind == "circle" and not (a2 - b2).is_zero():
            raise CheckError("a circle with unequal semi-axes")
        # s, t along d1, d2: s²|d1|²/a2 ± t²|d2|²/b2 = 1, scaled by a2·b2
        sgn = -1 if kind == "hyperbola" else 1
        model = {(2, 0): dot(d1, d1) * b2, (0, 2): dot(d2, d2) * a2 * sgn, (0, 0): -(a2 * b2)}
        return ctr, [d1, d2], model
    if kind == "parabola":
        v = parse_point(c.get("vertex"), "vertex")
        if len(dirs) != 1:
            raise CheckError("a parabola needs one axis direction")
        d1 = parse_point(dirs[0], "axis direction")
        d2 = cross(n, d1)
        f2 = parse_value(c.get("focal_length2"), "focal_length2")
        return v, [d1, d2], ("parabola", f2)
    raise CheckError(f"unknown conic type {kind!r}")


def check_conic(c, eqs, what):
    """A listed conic lies on both quadrics and is real: its plane holds its
    centre (vertex) and directions, the directions are orthogonal, and each
    quadric restricted to the plane P = C + s·d1 + t·d2 is a non-zero
    multiple of the conic's equation in (s, t) — s²|d1|²·b2 + t²|d2|²·a2 =
    a2·b2 for an ellipse (−t² for a hyperbola); for a parabola t²|d2|² = k·s
    with k > 0 (it opens along d1) and k² = 16·f²·|d1|² (f² the squared
    focal length).  A quadric whose restriction to a plane is a multiple of
    a real conic's equation meets the plane exactly in that conic."""
    pl = c.get("plane") or {}
    n = parse_point(pl.get("normal"), f"{what} plane normal")
    off = parse_value(pl.get("offset"), f"{what} plane offset")
    if all(x.is_zero() for x in n):
        raise CheckError(f"{what}: zero plane normal")
    origin, dirs, model = _conic_model(c, n)
    if not (dot(n, origin) - off).is_zero():
        raise CheckError(f"{what}: the centre or vertex is not on the plane")
    for d in dirs:
        if not dot(n, d).is_zero() or all(x.is_zero() for x in d):
            raise CheckError(f"{what}: an axis direction is zero or not in the plane")
    if not dot(dirs[0], dirs[1]).is_zero():
        raise CheckError(f"{what}: the axis directions are not orthogonal")
    for name, eq in eqs:
        r = _on_surface_along(eq, origin, dirs, what)
        if isinstance(model, tuple):  # parabola: r = κ(t²|d2|² − k s)
            f2 = model[1]
            bad = [k for k in r if k not in ((0, 2), (1, 0))]
            if bad or (0, 2) not in r or (1, 0) not in r:
                raise CheckError(f"{what}: {name} restricted to the plane is not a parabola with this vertex and axis")
            # k = −r_s·|d2|²/r_tt  (r_tt ≠ 0); k > 0 and k² = 16 f² |d1|²
            num, den = -(r[(1, 0)] * dot(dirs[1], dirs[1])), r[(0, 2)]
            if (num * den).sign() <= 0:
                raise CheckError(f"{what}: the parabola does not open along its axis direction")
            if not (num * num - den * den * f2 * dot(dirs[0], dirs[0]) * 16).is_zero():
                raise CheckError(f"{what}: wrong focal length")
        else:
            _multiple_of(r, model, f"{what} on {name}")


def check_line(c, eqs, what):
    """A listed line P + t·D (D ≠ 0) lies on both quadrics: each equation
    restricted to it is the zero polynomial in t."""
    p = parse_point(c.get("point"), f"{what} point")
    d = parse_point(c.get("direction"), f"{what} direction")
    if all(x.is_zero() for x in d):
        raise CheckError(f"{what}: zero direction")
    for name, eq in eqs:
        if _on_surface_along(eq, p, [d], what):
            raise CheckError(f"{what}: not on {name}")


def check_point(pt, eqs, what, singular):
    """A listed point lies on both quadrics; where it is a tangency, a
    singular point of the curve or a common vertex, the gradients there are
    parallel (∇A × ∇B = 0)."""
    p = parse_point(pt, what)
    for name, eq in eqs:
        if not P.evaluate(eq, p).is_zero():
            raise CheckError(f"{what}: not on {name}")
    if singular:
        ga, gb = ([P.evaluate(g, p) for g in P.gradient(eq)] for _, eq in eqs)
        if any(not x.is_zero() for x in cross(ga, gb)):
            raise CheckError(f"{what}: the surfaces are transversal there (not a singular point)")


def check_branch(b, eqs, what):
    """A curve branch's point: the ruling (point R, direction D, exact)
    lies on one quadric, the other restricted to it is a positive multiple
    of a·t² + 2b·t + c, and b² − ac ≥ 0 with a ≠ 0 (or the exact t given is a
    root): so the curve has a real point on that ruling."""
    ru = b.get("ruling") or {}
    r = parse_point(ru.get("point"), f"{what} ruling point")
    d = parse_point(ru.get("direction"), f"{what} ruling direction")
    if all(x.is_zero() for x in d):
        raise CheckError(f"{what}: zero ruling direction")
    along = b.get("along_ruling") or {}
    restricted = [(name, _on_surface_along(eq, r, [d], what)) for name, eq in eqs]
    on = [name for name, rr in restricted if not rr]
    if not on:
        raise CheckError(f"{what}: the ruling lies on neither quadric")
    other = next((rr for name, rr in restricted if rr), {})
    qa, qb, qc = (parse_value(along.get(k), f"{what} along_ruling.{k}") for k in ("a", "b", "c"))
    model = {(2,): qa, (1,): qb * 2, (0,): qc}
    model = {k: v for k, v in model.items() if not v.is_zero()}
    if other:
        _multiple_of(other, model, f"{what} along the ruling")
        k0 = next(iter(model))
        if (other[k0] * model[k0]).sign() <= 0:
            raise CheckError(f"{what}: not a positive multiple along the ruling")
    t = along.get("t")
    if t is not None:
        tv = parse_value(t, f"{what} t")
        if not (qa * tv * tv + qb * tv * 2 + qc).is_zero():
            raise CheckError(f"{what}: t is not a root along the ruling")
    else:
        if qa.is_zero() or (qb * qb - qa * qc).sign() < 0:
            raise CheckError(f"{what}: no real root along the ruling")


def _numbers(spec, float_mode):
    """A quadric's point, axis (zero for a sphere) and parameter (r2 or
    tan²α), as the referee's metric moves them."""
    _, data = quadric(spec, float_mode)
    if data is not None:
        return data
    _, fields = _fields(spec)
    return "sphere", _vec(fields["center"], float_mode, "center"), [0, 0, 0], json_number(fields["radius2"], float_mode)


def _radius_bound(r2):
    """The least power of two at or above √r2."""
    k = (r2.numerator.bit_length() - r2.denominator.bit_length()) // 2 - 1
    while Fraction(2) ** (2 * k) < r2:
        k += 1
    return Fraction(2) ** k


def _referee(req, ref, float_mode):
    """The referee's witness is exactly ``hi`` away (each quadric's point,
    axis and parameter moved by at most hi·L, hi·max|aᵢ|, hi·|s|, kinds
    kept; L the larger of the points' max|pᵢ| and the spheres' and
    cylinders' radii rounded up to powers of two) and ``lo < hi``; ``lo``
    and the witness's answer are the engine's (trusted)."""
    trusted = ["referee: lo (the ball evaluation of the predicates)"]
    near = ref.get("nearby")
    if near is None:
        return [], trusted
    lo, hi = Fraction(ref["lo_exact"]), Fraction(ref["hi_exact"])
    given = {name: _numbers(req.get(name), float_mode) for name in ("a", "b")}
    length = max(max(map(abs, q[1])) for q in given.values())
    for k, _, _, s in given.values():
        if k != "cone":
            length = max(length, _radius_bound(s))
    worst = Fraction(0)
    for name in ("a", "b"):
        k0, p0, a0, s0 = given[name]
        k1, p1, a1, s1 = _numbers(near[name], False)
        if k0 != k1:
            raise CheckError(f"referee: the nearby {name} is a {k1}, not a {k0}")
        for old, new, scale in ((p0, p1, length), (a0, a1, max(map(abs, a0))), ([s0], [s1], abs(s0))):
            for u, v in zip(old, new):
                if u != v:
                    if scale == 0:
                        raise CheckError(f"referee: the nearby {name} moves a number that may not move")
                    worst = max(worst, abs(Fraction(v) - Fraction(u)) / scale)
    if worst != hi or not lo < hi:
        raise CheckError(f"referee: the witness is {worst} away, not hi = {hi} (lo {lo})")
    return ["referee: the nearby input is exactly hi away, lo < hi"], trusted + ["referee: the nearby input's answer"]


def check_natural(req, res):
    float_mode = req.get("float", False) is True
    A, data_a = quadric(req.get("a"), float_mode)
    B, data_b = quadric(req.get("b"), float_mode)
    eqs = [("a", A), ("b", B)]
    cls = res.get("class")
    checked, trusted = [], []
    if isinstance(res.get("referee"), dict):
        checked, trusted = _referee(req, res["referee"], float_mode)
    same = proportional(A, B)
    if cls == "undecided":
        return [], ["undecided: no claim"]
    if same != (cls == "same-surface"):
        raise CheckError(f"class {cls} but the equations are {'' if same else 'not '}proportional")
    checked.append("same-surface: the equations are proportional" if same else "not the same surface: the equations are not proportional")
    if same:
        if (res.get("conics"), res.get("lines"), res.get("points")) != (0, 0, 0) or res.get("components") not in ([], None):
            raise CheckError("a same-surface answer lists components or counts")
        return checked, trusted
    if res.get("certificate") is not None:
        if _member_planes(A, B, res, res.get("components") or []) is None:
            raise CheckError("the certificate's planes and the conics' planes are not a member of the pencil")
        checked.append("the certificate's planes: λA + μB = κ·P₁·P₂")
    want_components = req.get("components", True) is not False
    comps = res.get("components")
    if not want_components and comps is None:
        try:
            checked.append(_counts_only(A, B, (data_a, data_b), res))
            return checked, trusted
        except NotChecked as e:
            return checked, [f"class {cls} and counts (components not requested: {e})"]
    if not isinstance(comps, list):
        raise CheckError("components must be a list")
    counts = {"conic": 0, "line": 0, "point": 0}
    curve_points, unchecked = 0, []
    for j, c in enumerate(comps):
        what = f"component {j}"
        t = c.get("type") if isinstance(c, dict) else None
        try:
            if t == "conic":
                check_conic(c, eqs, what)
            elif t == "line":
                check_line(c, eqs, what)
            elif t == "point":
                check_point(c.get("point"), eqs, what, c.get("kind") in ("tangency", "vertex"))
        except NotChecked as e:
            unchecked.append(f"{what} on both quadrics ({e})")
        if t in ("conic", "line", "point"):
            pass
        elif t == "curve":
            if cls != "curve":
                raise CheckError(f"a curve component in a {cls} answer")
            for k, s in enumerate(c.get("singular_points") or []):
                check_point(s.get("point"), eqs, f"{what} singular point {k}", True)
                curve_points += bool(s.get("isolated"))
            branches = c.get("branches") or []
            for k, b in enumerate(branches):
                check_branch(b, eqs, f"{what} branch {k}")
            if c.get("real_components") != len(branches):
                raise CheckError(f"{what}: real_components is not the number of branches")
            continue
        else:
            raise CheckError(f"{what}: unknown type {t!r}")
        counts[t] += 1
    if want_components:
        if (res.get("conics"), res.get("lines")) != (counts["conic"], counts["line"]):
            raise CheckError("the counts do not match the components listed")
        if res.get("points") != counts["point"] + curve_points:
            raise CheckError("the point count does not match the components listed")
        expect = {
            "conics": counts["conic"] > 0 and counts["line"] == 0,
            "conic-and-line": counts["conic"] > 0 and counts["line"] > 0,
            "lines": counts["conic"] == 0 and counts["line"] > 0,
            "points": counts["point"] > 0 and not counts["conic"] and not counts["line"],
            "empty": not comps,
            "curve": any(isinstance(c, dict) and c.get("type") == "curve" for c in comps),
        }
        if cls == "curve" and counts["conic"]:
            raise CheckError("a curve answer listing conics")
        if cls not in expect or not expect[cls]:
            raise CheckError(f"class {cls} does not fit the components listed")
        trusted.extend(unchecked)
        if comps and len(unchecked) < len(comps):
            checked.append("every listed component lies on both quadrics (exact substitution)")
            checked.append("counts and class agree with the components")
        if cls == "curve":
            checked.append("each branch has a real point on both quadrics")
            try:
                checked.extend(_check_curve(A, B, (data_a, data_b), comps))
            except NotChecked as e:
                trusted.append(f"curve: no other real component; singular point kinds ({e})")
        elif unchecked:
            try:  # two cones with a common vertex: at least the number of lines
                from . import sweep

                if not (data_a and data_a[0] == "cone" and cls == "lines"):
                    raise NotChecked("not two cones")
                n = sweep.common_vertex_lines(*data_a, B)
                if n != counts["line"] or counts["conic"] or counts["point"]:
                    raise CheckError(f"{counts['line']} lines listed, the common vertex's rulings give {n}")
                checked.append("lines: as many as the rulings of one cone on which the other vanishes (common vertex)")
            except NotChecked:
                trusted.append(f"{cls}: no real point besides the listed components")
        else:
            why = _complete(A, B, res, comps)
            if why:
                checked.append(why)
            else:
                trusted.append(f"{cls}: no real point besides the listed components")
    else:
        trusted.append(f"class {cls} and counts (components not requested)")
    return checked, trusted


def _plane_of(c):
    pl = c.get("plane") or {}
    return parse_point(pl.get("normal"), "normal"), parse_value(pl.get("offset"), "offset")


def _same_plane(p, q):
    (n1, o1), (n2, o2) = p, q
    return all(x.is_zero() for x in cross(n1, n2)) and all((o1 * n2[i] - o2 * n1[i]).is_zero() for i in range(3))


def _complete(A, B, res, comps):
    """Why the listed components are all of A ∩ B (see pencil.py), or None
    when no member proving it is found."""
    from . import pencil

    if not comps and not (res.get("certificate") or {}).get("planes"):
        t = pencil.definite_member(A, B)
        if t is not None:
            return f"empty: A − ({t})·B is a definite form (no real zero)"
    # a member of degree ≤ 1: quadratic parts proportional (spheres)
    q2 = lambda p: {e: c for e, c in p.items() if sum(e) == 2}  # noqa: E731
    if proportional(q2(A), q2(B)) and not (res.get("certificate") or {}).get("planes"):
        e0 = next(iter(q2(A)))
        m = P.add(A, P.scale(B, q2(A)[e0] / q2(B)[e0]), -1)
        if not m:
            return None
        if P.degree(m) == 0:
            return "empty: A − cB is a non-zero constant" if not comps else None
        n = [QS(m.get(tuple(int(i == j) for j in range(3)) + (0,), 0)) for i in range(3)]
        off = QS(-m.get((0, 0, 0, 0), 0))
        pencil.check_sections(A, [(n, off)], comps, parse_point, parse_value)
        return "complete: A − cB is a plane, and A's section by it is exactly the listed components"
    if comps and all(c.get("type") == "point" for c in comps):
        pts = pencil.singular_member_points(A, B)
        if pts is not None:
            listed = [parse_point(c.get("point"), "point") for c in comps]
            same = lambda p, q: all((x - y).is_zero() for x, y in zip(p, q))  # noqa: E731
            if len(pts) == len(listed) and all(any(same(p, q) for q in listed) for p in pts):
                return "complete: a semidefinite singular member A − t₀B has exactly the listed points as its real zeros on A"
            raise CheckError("the real points of A ∩ B are not the listed points")
    found = _member_planes(A, B, res, comps)
    if found is None:
        found = _coaxial_member(A, B)
        if found == "empty":
            if comps:
                raise CheckError("a member A − tB = c·ℓ² + b·ℓ + e has no real zero, but components are listed")
            return "empty: a member A − tB is c·ℓ² + b·ℓ + e in one linear form ℓ, with no real root"
    if found is None:
        return None
    (lam, mu), distinct = found
    eq = A if not mu.is_zero() else B
    pencil.check_sections(eq, distinct, comps, parse_point, parse_value)
    return "complete: a member λA + μB is κ·P₁·P₂, and the plane sections are exactly the listed components"


def _member_planes(A, B, res, comps):
    """((λ, μ), distinct planes) of a member λA + μB = κ·P₁·P₂ whose planes
    are the certificate's (planes that carry no listed conic) and the listed
    conics' planes (a single plane: P₁², or P₁ alone for a member of degree
    one), or None."""
    from . import pencil

    cert = res.get("certificate") if isinstance(res.get("certificate"), dict) else {}
    planes = []
    given = cert.get("planes") or []
    if not isinstance(given, list):
        raise CheckError("certificate.planes must be a list")
    for p in [(parse_point(p.get("normal"), "normal"), parse_value(p.get("offset"), "offset")) for p in given] + [
        _plane_of(c) for c in comps if c.get("type") == "conic"
    ]:
        if not any(_same_plane(p, q) for q in planes):
            planes.append(p)
    tries = {2: [planes], 1: [planes * 2, planes]}.get(len(planes), [])
    for pl in tries:
        lm = pencil.solve_member(A, B, pl)
        if lm is not None:
            return lm, planes
    return None


def _multiple_root_members(A, B, n):
    """(t₀, A − t₀B) for each rational multiple root t₀ of det(A − tB) on
    the leading n×n blocks (n = 3: the quadratic parts); for a singular
    pencil (det ≡ 0, n = 4) each rational root of the 3×3 minors' gcd."""
    from .kernel import _yun
    from .pencil import det_poly

    ma, mb = P.form_matrix(A), P.form_matrix(B)
    f = det_poly(ma, mb, n)
    if n == 4 and f == [0]:  # a singular pencil: the roots of the 3×3 minors' gcd
        from .sweep import minors_gcd

        from .pencil import rational_roots

        f = minors_gcd(ma, mb)
        found = [([-r, 1], 2) for r in rational_roots(f)] if len(f) > 1 else []  # each root once
    else:
        found = _yun(f) if len(f) >= 3 else []
    for g, k in found:
        if k >= 2 and len(g) == 2:
            t0 = -g[0] / g[1]
            yield t0, [[ma[i][j] - t0 * mb[i][j] for j in range(4)] for i in range(4)]


def _coaxial_member(A, B):
    """A member A − t₀B that depends on one linear form ℓ = n·P only (two
    quadrics on one axis): its quadratic part has rank 1 at a double root t₀
    of det(A₂ − tB₂) (the 3×3 quadratic parts), and then A − t₀B =
    c·ℓ² + b·ℓ + e, a product of the planes ℓ = r for the real roots r of
    c·r² + b·r + e.  Returns ((1, −t₀), planes), "empty" when there is no
    real root, or None."""
    for t0, m in _multiple_root_members(A, B, 3):
        q = [row[:3] for row in m[:3]]
        i0 = next((i for i in range(3) if q[i][i] != 0), None)
        if i0 is None:
            continue
        n = q[i0]  # rank 1: q = n nᵀ / n[i0]
        c = 1 / n[i0]
        if any(q[i][j] != c * n[i] * n[j] for i in range(3) for j in range(3)):
            continue
        lin = [2 * m[i][3] for i in range(3)]  # must be b·n
        b = lin[i0] / n[i0]
        if any(lin[i] != b * n[i] for i in range(3)):
            continue
        e = m[3][3]
        # c·ℓ² + b·ℓ + e with ℓ = n·P (the form is c(n·P)² since q = c·n nᵀ)
        disc = b * b - 4 * c * e
        if disc < 0:
            return "empty"
        nq = [QS(x) for x in n]
        if disc == 0:
            planes = [(nq, QS(-b / (2 * c)))]
        else:
            sq = sqrt_rational(disc)
            planes = [(nq, (QS(-b) + sq * s) / QS(2 * c)) for s in (1, -1)]
        return (QS(1), QS(-t0)), planes
    return None


def _swept_quartic(A, B, data, branches=()):
    """No member of rank ≤ 2 (else ``CheckError``), then the sweep over the
    rulings of the cylinder (preferred) or the cone: ``sweep.curve_topology``'s
    answer, or ``NotChecked`` with the first reason."""
    from . import sweep

    if not sweep.rank_two_free(P.form_matrix(A), P.form_matrix(B)):
        raise CheckError("a member of the pencil has rank ≤ 2: the quadrics share a conic, not a quartic curve")
    why = None
    for i in sorted((i for i in (0, 1) if data[i]), key=lambda i: data[i][0] != "cylinder"):
        try:
            return sweep.curve_topology(*data[i], (A, B)[1 - i], branches)
        except NotChecked as e:
            why = why or e
    raise why or NotChecked("no cylinder or cone")


def _check_curve(A, B, data, comps):
    """A ``curve`` answer's topology: no member of the pencil has rank ≤ 2
    (so no conic, real or complex, lies on both quadrics; with no ruling on
    both — the sweep's precondition — the curve is an irreducible quartic),
    and the sweep over the rulings of a cylinder or cone (module ``sweep``)
    gives the same number of real components, the same ``bounded`` flags
    and the same singular points (kind, isolated) as the answer."""
    curves = [c for c in comps if c.get("type") == "curve"]
    if len(curves) != 1 or len(comps) != 1:
        raise NotChecked("a curve beside other components")
    c = curves[0]
    branches = c.get("branches") or []
    n, bounded, singular, located = _swept_quartic(A, B, data, branches)
    if c.get("degree") != 4:
        raise CheckError(f"degree {c.get('degree')!r} for an irreducible quartic")
    if c.get("real_components") != n:
        raise CheckError(f"real_components is {c.get('real_components')!r}, the sweep finds {n}")
    if len({key for key, _ in located}) != len(located):
        raise CheckError("two branches' points lie on the same real component")
    for k, (b, (_, bd)) in enumerate(zip(branches, located)):
        if bool(b.get("bounded")) != bd:
            raise CheckError(f"branch {k} is said {'' if b.get('bounded') else 'un'}bounded, its component is {'' if bd else 'un'}bounded")
    if sorted(bd for _, bd in located) != bounded:
        raise CheckError(f"bounded flags {sorted(bd for _, bd in located)}, the sweep finds {bounded}")
    sing = sorted((s.get("kind"), bool(s.get("isolated"))) for s in c.get("singular_points") or [])
    if sing != singular:
        raise CheckError(f"singular points {sing}, the sweep finds {singular}")
    return [
        "curve: irreducible quartic (no member of rank ≤ 2)",
        "curve: real components, bounded flags and singular points (sweep over the rulings)",
        "curve: one branch point on each real component",
    ]


def _plane_pair(A, B):
    """A member A − t₀B of rank 2 (t₀ a rational multiple root of
    det(A − tB)) split into its planes.  With two rows r₁, r₂ of the member
    M whose principal 2×2 minor K is invertible (a symmetric matrix of rank
    2 has one), M = Rᵀ·K⁻¹·R (R = [r₁; r₂]), i.e. the member is the binary
    form α·y₁² + 2β·y₁y₂ + γ·y₂² in y_k = r_k·(x, y, z, 1), which factors over
    Q(√(β² − αγ)).  Returns ("planes", [(normal, offset), …]) — the affine
    planes (one for a double plane or when the other is the plane at
    infinity) —, ("line", (r₁, r₂)) for two complex conjugate planes meeting
    in a real line, or None when no such member exists."""
    from .pencil import kernel

    for _, m in _multiple_root_members(A, B, 4):
        rank = 4 - len(kernel(m, 4))
        if rank == 1:  # c·ℓ²: a double plane (its row ℓ)
            row = next(r for r in m if any(r))
            return "planes", [([QS(x) for x in row[:3]], QS(-row[3]))] if any(row[:3]) else []
        if rank != 2:
            continue
        i, j = next((i, j) for i in range(4) for j in range(i + 1, 4) if m[i][i] * m[j][j] != m[i][j] ** 2)
        dk = m[i][i] * m[j][j] - m[i][j] ** 2
        al, be, ga = m[j][j] / dk, -m[i][j] / dk, m[i][i] / dk
        r1, r2 = [QS(x) for x in m[i]], [QS(x) for x in m[j]]
        disc = be * be - al * ga
        if disc < 0:
            return "line", (r1, r2)
        if al == 0:  # y₂·(2β·y₁ + γ·y₂)
            forms = [r2] + ([[QS(2 * be) * a + QS(ga) * b for a, b in zip(r1, r2)]] if be else [])
        else:
            sq = sqrt_rational(disc)
            rhos = [(QS(-be) + sq * s) / QS(al) for s in ((1, -1) if disc else (1,))]
            forms = [[a - rho * b for a, b in zip(r1, r2)] for rho in rhos]
        planes = [(fm[:3], -fm[3]) for fm in forms if not all(x.is_zero() for x in fm[:3])]
        return "planes", planes
    return None


def _count_sections(A, found):
    """(conics, lines, points) of A ∩ B from a rank-2 member (``_plane_pair``)."""
    from .pencil import section

    kind, data = found
    if kind == "line":  # the real line r₁ = r₂ = 0, on which A is a quadratic
        r1, r2 = data
        d = cross(r1[:3], r2[:3])
        if all(x.is_zero() for x in d):
            return 0, 0, 0  # the line at infinity
        # a point of the line: solve r1·p = −r1[3], r2·p = −r2[3], d·p = 0
        from .pencil import nullspace

        v = nullspace([r1, r2, list(d) + [QS(0)]], 4)
        if v is None or v[3].is_zero():
            raise NotChecked("the member's real line")
        p = [v[i] / v[3] for i in range(3)]
        q = _on_surface_along(A, p, [d], "the member's real line")
        if not q:
            return 0, 1, 0
        a2, a1, a0 = (q.get((e,), QS(0)) for e in (2, 1, 0))
        if a2.is_zero():
            return 0, 0, int(not a1.is_zero())
        disc = (a1 * a1 - a2 * a0 * QS(4)).sign()
        return 0, 0, 0 if disc < 0 else 1 if disc == 0 else 2
    planes = data
    secs = [section(A, n, off) for n, off in planes]
    conics = sum(s[0] == "conic" for s in secs)
    lines = sum(s[1] for s in secs if s[0] == "lines")
    points = 0
    if len(planes) == 2:
        (n1, o1), (n2, o2) = planes
        d = cross(n1, n2)
        if lines and not all(x.is_zero() for x in d) and all(s[0] == "lines" for s in secs):
            from .pencil import nullspace

            v = nullspace([list(n1) + [-o1], list(n2) + [-o2], list(d) + [QS(0)]], 4)
            p = [v[i] / v[3] for i in range(3)]
            if not _on_surface_along(A, p, [d], "the planes' common line"):
                lines -= 1  # the planes' common line, counted in both
        for k, s in enumerate(secs):
            if s[0] == "point":
                n, off = planes[1 - k]
                other = secs[1 - k]
                if (dot(n, s[1]) - off).is_zero() and (other[0] != "point" or k == 1):
                    continue  # on the other plane's section, counted there
                points += 1
    else:
        points = sum(s[0] == "point" for s in secs)
    return conics, lines, points


def _counts_only(A, B, data, res):
    """Class and counts of an answer without components, re-derived: empty
    (a definite or one-axis member), curve (the sweep), points (a
    semidefinite singular member), the planar classes (the sections of a
    rank-2 member's planes)."""
    cls = res.get("class")
    want = (res.get("conics"), res.get("lines"), res.get("points"))
    if cls == "empty":
        why = _complete(A, B, {}, [])
        if why and want == (0, 0, 0):
            return why
        raise NotChecked("no member proves the intersection empty")
    if cls == "curve":
        try:
            _, _, singular, _ = _swept_quartic(A, B, data)
        except NotChecked:
            raise NotChecked("the sweep's preconditions") from None
        got = (0, 0, sum(iso for _, iso in singular))
        if got != want:
            raise CheckError(f"counts {want}, the sweep finds {got}")
        return "curve: irreducible quartic and its isolated points (sweep over the rulings)"
    if cls in ("lines", "points") and data[0] and data[1] and data[0][0] == data[1][0] == "cone":
        from . import sweep

        try:
            n = sweep.common_vertex_lines(*data[0], B)
            got = (0, n, 0 if n else 1)
            if got != want:
                raise CheckError(f"counts {want}, the common vertex's rulings give {got}")
            return "lines: the rulings of one cone on which the other vanishes (common vertex)"
        except NotChecked:
            pass
    found = _plane_pair(A, B)
    if found is None:
        if cls == "points":
            from .pencil import singular_member_points

            pts = singular_member_points(A, B)
            if pts is not None and want == (0, 0, len(pts)):
                return "points: a semidefinite singular member's real zeros on A"
        raise NotChecked("no rational member of rank 2")
    got = _count_sections(A, found)
    if got != want:
        raise CheckError(f"counts {want}, the rank-2 member's plane sections give {got}")
    c, l, p = got
    expect = "conic-and-line" if c and l else "conics" if c else "lines" if l else "points" if p else "empty"
    if cls != expect:
        raise CheckError(f"class {cls}, the counts make it {expect}")
    return "class and counts: the plane sections of a rank-2 member A − t₀B"
