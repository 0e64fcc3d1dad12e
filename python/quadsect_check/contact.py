"""Claims of ``ellipsoid-contact`` answers (two solid ellipsoids A, B).

Each ellipsoid is rebuilt from the request in its canonical form q,
negative inside: a pose {center c, semi_axes r, rotation R} is
q(x) = |D⁻¹Rᵀ(x − c)|² − 1 with D = diag(r), R as given (a JSON number is
the double it denotes, a string an exact number); a polynomial is itself,
negated when its quadratic part is negative definite.  A and B are the 4×4
matrices of q_A, q_B as forms in (x, y, z, 1), W_A, W_B their quadratic
parts.  The certificates:

* ``separating-pencil``: λ > 0 with det(λA + B) > 0.  The convex
  λq_A + q_B has the minimum det(λA + B)/det(λW_A + W_B) > 0, so no point
  has q_A ≤ 0 and q_B ≤ 0;
* ``touching-point``: λ > 0 and p on both surfaces with λ∇q_A + ∇q_B = 0
  (in Q(√d)).  The strictly convex λq_A + q_B ≥ 0 is 0 only at p, so the
  solids share p and nothing else;
* ``common-interior-point``: q_A(p) < 0 and q_B(p) < 0, and the kind's
  evidence (``definite``, ``semidefinite``, ``cross``, ``identical``).
"""

import math
from fractions import Fraction

from . import poly as P
from .exact import QS, CheckError, NotChecked, nearest_double, parse_point, parse_rational, parse_value, sqrt_rational
from .kernel import _det
from .natural import proportional
from .pencil import charpoly_signs, kernel, nullspace
from .tangent import _ldl_signs, check_ellipsoid

_OVERLAP = ("surfaces-cross", "A-inside-B", "B-inside-A", "internally-touching", "identical", "unclassified")
_KINDS = {"separated": ("separating-pencil", ("separated",)), "touching": ("touching-point", ("externally-touching",)),
          "overlapping": ("common-interior-point", _OVERLAP)}


def _number(x, what):
    """A request number: a JSON number is the double it denotes (its exact
    binary value), a string an exact rational."""
    if isinstance(x, str):
        return parse_rational(x)
    if isinstance(x, int) and not isinstance(x, bool):
        return nearest_double(Fraction(x))
    if isinstance(x, float) and math.isfinite(x):
        return Fraction(x)
    raise CheckError(f"{what}: expected a number, got {str(x)[:40]}")


def _three(v, what, each=_number):
    if not isinstance(v, list) or len(v) != 3:
        raise CheckError(f"{what}: expected three entries")
    return [each(x, what) for x in v]


def pose_form(e, name):
    """q = |G(x − c)|² − 1 with G = D⁻¹Rᵀ (R exactly as given, any
    invertible matrix); semi-axes > 0 and det R ≠ 0 first."""
    c, r = _three(e.get("center"), f"{name}.center"), _three(e.get("semi_axes"), f"{name}.semi_axes")
    m = _three(e.get("rotation"), f"{name}.rotation", _three)
    if set(e) != {"center", "semi_axes", "rotation"}:
        raise CheckError(f"{name}: expected the keys center, semi_axes, rotation")
    if any(x <= 0 for x in r):
        raise CheckError(f"{name}: a semi-axis is not > 0")
    det = _det(m)
    if det == 0:
        raise CheckError(f"{name}: the rotation matrix is singular")
    g = [[m[j][i] / r[i] for j in range(3)] for i in range(3)]
    q = P.const(-1)
    for i in range(3):
        lin = P.add({k: g[i][j] for j in range(3) if g[i][j] for k in P.var(j)}, P.const(-sum(g[i][j] * c[j] for j in range(3))))
        q = P.add(q, P.mul(lin, lin))
    return q


def ellipsoid_form(e, name):
    """The canonical form of ``a`` or ``b``: a pose, or a polynomial that is
    a real ellipsoid (tangent's check: definite quadratic part, det of the
    4×4 matrix < 0), negated when its quadratic part is negative."""
    if isinstance(e, dict):
        return pose_form(e, name)
    q = P.parse(e)
    try:
        check_ellipsoid(q)
    except CheckError as err:
        raise CheckError(f"{name} (as E): {err}") from None
    return P.scale(q, Fraction(-1)) if _ldl_signs([row[:3] for row in P.form_matrix(q)[:3]])[0] < 0 else q


def check_separated(ma, mb, cert):
    """λ > 0 and det(λA + B) > 0."""
    lam = parse_rational(cert.get("lambda"))
    if lam <= 0 or _det([[lam * ma[i][j] + mb[i][j] for j in range(4)] for i in range(4)]) <= 0:
        raise CheckError(f"separated: λ = {lam} is not > 0 with det(λA + B) > 0")
    return "separated: λ > 0 and det(λA + B) > 0, so λq_A + q_B > 0 everywhere"


def check_touching(qa, qb, cert):
    """λ > 0, q_A(p) = q_B(p) = 0 and λ∇q_A(p) + ∇q_B(p) = 0 in Q(√d)."""
    lam, p = parse_value(cert.get("lambda"), "lambda"), parse_point(cert.get("point"), "point")
    try:
        if lam.sign() <= 0:
            raise CheckError(f"touching: λ = {lam} is not > 0")
        if not (P.evaluate(qa, p).is_zero() and P.evaluate(qb, p).is_zero()):
            raise CheckError("touching: the point is not on both surfaces")
        ga, gb = P.gradient(qa), P.gradient(qb)
        if any(not (lam * P.evaluate(ga[i], p) + P.evaluate(gb[i], p)).is_zero() for i in range(3)):
            raise CheckError("touching: λ∇q_A + ∇q_B ≠ 0 at the point")
    except NotChecked:
        raise CheckError("touching: λ and the point do not lie in one field Q(√d)") from None
    return "touching: λ > 0, the point on both surfaces, λ∇q_A + ∇q_B = 0 there (λq_A + q_B ≥ 0, zero only there)"


def _signs(qa, qb, v, what):
    p = parse_point(v, what)
    return P.evaluate(qa, p).sign(), P.evaluate(qb, p).sign()


def _definite(qa, qb, ma, mb, ke):
    """μ > 0 and B − μA definite (LDLᵀ pivots of one sign): negative ⇒
    q_B < μq_A ≤ 0 on A, A inside B; positive ⇒ B inside A."""
    mu = parse_rational(ke.get("mu"))
    s = _ldl_signs([[mb[i][j] - mu * ma[i][j] for j in range(4)] for i in range(4)])
    if mu <= 0 or not s or 0 in s or len(set(s)) != 1:
        raise CheckError(f"B − μA is not definite for μ = {mu} > 0")
    return ("A-inside-B" if s[0] < 0 else "B-inside-A"), "B − μA definite (μ > 0): one solid in the other's interior", None


def _semidefinite(qa, qb, ma, mb, ke):
    """μ > 0 and B − μA negative (positive) semidefinite — no positive
    (negative) eigenvalue, Descartes on its characteristic polynomial — so
    q_B ≤ μq_A: A ⊆ B (B ⊆ A); B not a multiple of A (not identical); a
    point on both surfaces (the evidence's, else :func:`_surface_point`'s):
    they touch."""
    mu = parse_value(ke.get("mu"), "mu")
    sign = {"negative": 0, "positive": 1}.get(ke.get("sign"))
    m = [[mb[i][j] - mu * ma[i][j] for j in range(4)] for i in range(4)]
    if mu.sign() <= 0 or sign is None or charpoly_signs(m)[sign]:
        raise CheckError(f"B − μA is not {ke.get('sign')} semidefinite for μ = {mu} > 0")
    if proportional(qb, qa):
        raise CheckError("B is a multiple of A: identical, not internally touching")
    claim = "B − μA semidefinite (μ > 0), B ≠ cA, a point on both surfaces"
    if ke.get("point") is not None:
        if _signs(qa, qb, ke["point"], "kind_evidence.point") != (0, 0):
            raise CheckError("kind_evidence.point is not on both surfaces")
        return "internally-touching", claim, None
    x = _surface_point(qa, ma, m)
    if x is not None and P.evaluate(qa, x).is_zero() and P.evaluate(qb, x).is_zero():
        return "internally-touching", claim + " (found in the kernel of B − μA)", None
    return "internally-touching", "B − μA semidefinite (μ > 0): one solid contains the other", "internally-touching: the surfaces meet (no common point given)"


def _surface_point(qa, ma, m):
    """A candidate common point when the evidence gives none: (x, 1) in the
    kernel of the semidefinite B − μA has q_B(x) = μq_A(x), so a point of
    A's surface there is one.  The minimum c of q_A on the affine kernel
    p + span(dᵢ) (Σⱼ dᵢᵀWdⱼ·tⱼ = −dᵢᵀ(Wp + b)), then c itself or, when
    q_A(c) < 0, c + √(−q_A(c)/d₀ᵀWd₀)·d₀; None beyond Q(√d).  The caller
    evaluates it."""
    ker = kernel(m, 4)
    aff = next((k for k in ker if not k[3].is_zero()), None)
    if aff is None:
        return None
    p = [aff[i] / aff[3] for i in range(3)]
    dirs = [[k[i] - k[3] * p[i] for i in range(3)] for k in ker if k is not aff]
    w = lambda u, v: sum((u[i] * ma[i][j] * v[j] for i in range(3) for j in range(3)), QS(0))  # noqa: E731
    grad = [sum((ma[i][j] * p[j] for j in range(3)), QS(ma[i][3])) for i in range(3)]
    t = nullspace([[w(d, e) for e in dirs] + [sum((d[i] * grad[i] for i in range(3)), QS(0))] for d in dirs], len(dirs) + 1)
    c = [p[i] + sum((t[j] / t[-1] * dirs[j][i] for j in range(len(dirs))), QS(0)) for i in range(3)] if dirs else p
    r = -P.evaluate(qa, c) / w(dirs[0], dirs[0]) if dirs else QS(0)
    try:
        return c if r.sign() <= 0 else None if r.d else [c[i] + sqrt_rational(r.a) * dirs[0][i] for i in range(3)]
    except NotChecked:
        return None


def _cross(qa, qb, ma, mb, ke):
    """q_A(a_only) < 0 < q_B(a_only): A ⊄ B; q_B(b_only) < 0 < q_A(b_only):
    B ⊄ A; with the common interior point the surfaces cross."""
    missing = []
    for key, want, what in (("a_only", (-1, 1), "A ⊄ B"), ("b_only", (1, -1), "B ⊄ A")):
        if ke.get(key) is None:
            missing.append(f"{what} (no {key} point)")
        elif _signs(qa, qb, ke[key], key) != want:
            raise CheckError(f"{key} is not inside {key[0].upper()} and outside the other")
    return "surfaces-cross", "a point of each solid's interior outside the other", ("surfaces-cross: " + ", ".join(missing)) if missing else None


def _identical(qa, qb, ma, mb, ke):
    """B = μA exactly with μ > 0."""
    mu = parse_rational(ke.get("mu"))
    if mu <= 0 or any(mb[i][j] != mu * ma[i][j] for i in range(4) for j in range(4)):
        raise CheckError(f"B ≠ μA for μ = {mu} > 0")
    return "identical", "B = μA, μ > 0", None


_EVIDENCE = {"definite": _definite, "semidefinite": _semidefinite, "cross": _cross, "identical": _identical}


def check_contact(req, res):
    qa, qb = ellipsoid_form(req.get("a"), "a"), ellipsoid_form(req.get("b"), "b")
    ma, mb = P.form_matrix(qa), P.form_matrix(qb)
    checked, trusted = ["A and B are real solid ellipsoids (canonical forms, negative inside)"], []
    contact, kind, cert = res.get("contact"), res.get("kind"), res.get("certificate")
    if contact not in _KINDS or kind not in _KINDS[contact][1]:
        raise CheckError(f"contact {contact!r} with kind {kind!r}")
    if not isinstance(cert, dict) or cert.get("type") != _KINDS[contact][0]:
        raise CheckError(f"{contact} needs a {_KINDS[contact][0]} certificate")
    if contact == "separated":
        return checked + [check_separated(ma, mb, cert)], trusted
    if contact == "touching":
        return checked + [check_touching(qa, qb, cert)], trusted
    if _signs(qa, qb, cert.get("point"), "point") != (-1, -1):
        raise CheckError("overlapping: the point is not inside both")
    checked.append("overlapping: a point with q_A < 0 and q_B < 0")
    ke = cert.get("kind_evidence")
    if ke is None:  # the kind is trusted (an unclassified overlap claims none)
        return checked, trusted + ([f"the kind {kind} (no evidence)"] if kind != "unclassified" else [])
    if not isinstance(ke, dict) or ke.get("type") not in _EVIDENCE:
        raise CheckError(f"unknown kind evidence {str(ke)[:60]}")
    proved, claim, trust = _EVIDENCE[ke["type"]](qa, qb, ma, mb, ke)
    if proved != kind:
        raise CheckError(f"the evidence proves {proved}, not {kind}")
    return checked + [f"{kind}: {claim}"], trusted + ([trust] if trust else [])
