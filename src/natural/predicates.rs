//! The fast exact route to the class and the counts (conics, lines,
//! points) of two natural quadrics, without constructing components
//! (docs/maths.md, "The fast route").
//!
//! The decisions are signs of integer polynomials in the quadrics'
//! parameters (denominators cleared once, [`super::prepared`]), written once
//! against `number::filter::SignRing` and run in tiers: ball arithmetic
//! (an `f64` filter with proven rounding) on the real inputs, then on the
//! integers, checked `i128`, big integers.  The branching follows
//! [`super::classify::classify`] exactly (same surface; two spheres; a
//! sphere centred on an axis; a common axis; coplanar axes whose projection
//! conic factors; everything else), and so do the planar counts; the
//! non-planar cases, where the present route computes the curve's
//! topology, are decided from the pencil `F(λ) = det(A − λB)`:
//!
//! * **four distinct roots** (a nonsingular quartic): empty iff a member of
//!   the pencil is definite (Finsler–Calabi), else a curve without acnodes;
//! * **exactly one multiple root λ₀** (rational) with `A − λ₀B` of rank 3:
//!   its vertex p is the only singular point; the tangent cone at p, the
//!   form of the member on `R⁴/p` and whether p is affine give the class
//!   and the acnode count (a nodal or cuspidal quartic, or the point alone);
//! * the same with rank 2 and complex-conjugate planes: the real points are
//!   those of the real line where the planes meet (isolated tangency
//!   points);
//! * anything else (several multiple roots, a line in the intersection,
//!   real plane pairs, `F ≡ 0`): the common rulings are looked for, and if
//!   none exists the present route answers.  Nothing is guessed.

use super::classify::classify_complete;
use super::prepared::{
    Axes, FromPrep, Kind, Prep, Prepared, QIn, axes_of, axes_relation_of, point_difference,
};
use super::result::{Class, Counts, NaturalReport, Route};
use super::types::Natural;
use crate::budget::Budget;
use crate::error::Error;
use crate::number::filter::{Ball, BallR, Ck, SignRing, all_of, all_zero, cross, dot, tiered};
use num_bigint::BigInt;

impl Counts {
    /// The class of components counted this way (the order of
    /// [`super::result::class_of`]; no curve).
    fn of(conics: usize, lines: usize, points: usize) -> Counts {
        let class = if conics > 0 && lines > 0 {
            Class::ConicAndLine
        } else if conics > 0 {
            Class::Conics
        } else if lines > 0 {
            Class::Lines
        } else if points > 0 {
            Class::Points
        } else {
            Class::Empty
        };
        Counts::new(class, conics, lines, points)
    }

    fn empty() -> Counts {
        Counts::new(Class::Empty, 0, 0, 0)
    }

    fn curve(points: usize) -> Counts {
        Counts::new(Class::Curve, 0, 0, points)
    }
}

/// What the integer program concluded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Outcome {
    /// Decided: the class and counts, how (in words), and the case the
    /// constructions build from.
    Counts(Counts, &'static str, Case),
    /// Decided on the projection conic of coplanar axes, in a tier that
    /// knows the conics exactly: the construction starts from them
    /// (predicates decide, constructions build — nothing computed twice).
    Planar(Counts, &'static str, Case, Box<PlanarConics>),
    /// The intersection may contain a line: look for common rulings.
    Rulings,
    /// Not a case of the fast route.
    Fallback(&'static str),
}

/// The integer conics of a planar decision ([`planar`]): the projection
/// conic `F` (divided by its content) and the squared heights `H` of the
/// first quadric, in the frame of [`super::build_planar`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct PlanarConics {
    pub f: [[BigInt; 3]; 3],
    pub h1: [[BigInt; 3]; 3],
}

/// Which multiple root of `F(λ) = det(A − λB)` a decision used, so that a
/// construction recomputes it exactly (the formulas of [`pencil_route`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RootKind {
    /// λ = 0 (the member A).
    Zero,
    /// λ = ∞ (the member B).
    Infinity,
    /// The double root `−c₁/(2c₂)` of the quadratic core.
    Quadratic,
    /// The triple root `−b/(3a)` of the cubic core.
    CubicTriple,
    /// The double root `(9ad − bc)/(2(b² − 3ac))` of the cubic core.
    CubicDouble,
}

/// The case a decision falls in: what the constructions need to know so
/// that they build the components without classifying again (CGAL's
/// predicates then constructions).  The matrices `A`, `B` of the pencil
/// cases are those of [`program`]'s call of [`pencil_route`] (a sphere
/// first when there is one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Case {
    /// Proportional equations: no components.
    SameSurface,
    /// Two spheres: a circle, a point or nothing in the radical plane.
    TwoSpheres,
    /// A sphere centred on the axis of the other quadric: circles.
    SphereOnAxis,
    /// Two axial quadrics on one axis: circles or the common vertex.
    SameAxis,
    /// Coplanar distinct axes whose projection conic factors.
    Planar {
        /// The axes are parallel.
        parallel: bool,
    },
    /// No real point (a definite member of a nonsingular pencil, or an
    /// isolated point at infinity).
    Empty,
    /// A nonsingular quartic with real points.
    Smooth,
    /// One singular point: the vertex of the rank-3 member at the multiple
    /// root, found in cofactor column `k`; a real curve through it.
    Nodal { root: RootKind, k: usize },
    /// The same vertex as an isolated point (the cone member's generators
    /// are imaginary): the only real point.
    ConePoint { root: RootKind, k: usize },
    /// A complex-conjugate plane pair at the multiple root: the real points
    /// lie on the real line where the planes meet.
    PlanePair { root: RootKind },
    /// A common ruling: lines and a twisted cubic.
    Rulings,
}

/// A 4×4 symmetric integer matrix.
pub(crate) type M4<R> = [[R; 4]; 4];

/// The matrix of a quadric (a positive multiple of that of its SPEC §2
/// equation): `[[q²K, −qKc], [−q(Kc)ᵀ, cᵀKc − q²ρ]]` with the quadratic
/// block K and the constant ρ of the scaled equation
/// (sphere `pd·I`, `pn`; cylinder `pd(|a|²I − aaᵀ)`, `pn|a|²`; cone
/// `pd|a|²I − (pn + pd)aaᵀ`, 0).
pub(crate) fn matrix<R: SignRing>(x: &QIn<R>) -> M4<R> {
    let a2 = dot(&x.a, &x.a);
    let (diag, outer, rho) = match x.kind {
        Kind::Sphere => (x.pd.clone(), R::int(0), x.pn.clone()),
        Kind::Cylinder => (x.pd.mul(&a2), x.pd.clone(), x.pn.mul(&a2)),
        Kind::Cone => (x.pd.mul(&a2), x.pn.add(&x.pd), R::int(0)),
    };
    let k: [[R; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let o = outer.mul(&x.a[i].mul(&x.a[j]));
            if i == j { diag.sub(&o) } else { o.neg() }
        })
    });
    let kc: [R; 3] = std::array::from_fn(|i| dot(&k[i], &x.c));
    let q2 = x.q.mul(&x.q);
    let mut m: M4<R> = std::array::from_fn(|_| std::array::from_fn(|_| R::int(0)));
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = q2.mul(&k[i][j]);
        }
        m[i][3] = x.q.mul(&kc[i]).neg();
        m[3][i] = m[i][3].clone();
    }
    m[3][3] = dot(&x.c, &kc).sub(&q2.mul(&rho));
    m
}

pub(crate) fn det2<R: SignRing>(a: &R, b: &R, c: &R, d: &R) -> R {
    a.mul(d).sub(&b.mul(c))
}

pub(crate) fn det3<R: SignRing>(m: &[[R; 3]; 3]) -> R {
    m[0][0]
        .mul(&det2(&m[1][1], &m[1][2], &m[2][1], &m[2][2]))
        .sub(&m[0][1].mul(&det2(&m[1][0], &m[1][2], &m[2][0], &m[2][2])))
        .add(&m[0][2].mul(&det2(&m[1][0], &m[1][1], &m[2][0], &m[2][1])))
}

/// The 3×3 minor of a 4×4 matrix without row `r` and column `c`.
pub(crate) fn minor3<R: SignRing>(m: &M4<R>, r: usize, c: usize) -> R {
    let rows: Vec<usize> = (0..4).filter(|&i| i != r).collect();
    let cols: Vec<usize> = (0..4).filter(|&j| j != c).collect();
    let s: [[R; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| m[rows[i]][cols[j]].clone()));
    det3(&s)
}

/// `uᵀ M v`.
pub(crate) fn form<R: SignRing>(m: &M4<R>, u: &[R; 4], v: &[R; 4]) -> R {
    let mv: [R; 4] = std::array::from_fn(|i| dot(&m[i], v));
    dot(u, &mv)
}

/// `d·A − n·B`.
pub(crate) fn member<R: SignRing>(a: &M4<R>, b: &M4<R>, n: &R, d: &R) -> M4<R> {
    std::array::from_fn(|i| std::array::from_fn(|j| d.mul(&a[i][j]).sub(&n.mul(&b[i][j]))))
}

/// Laplace expansion of a 4×4 determinant along rows {0, 1}: the sign and
/// the column pairs.
const LAPLACE: [([usize; 2], [usize; 2], bool); 6] = [
    ([0, 1], [2, 3], true),
    ([0, 2], [1, 3], false),
    ([0, 3], [1, 2], true),
    ([1, 2], [0, 3], true),
    ([1, 3], [0, 2], false),
    ([2, 3], [0, 1], true),
];

/// The coefficients `f₀..f₄` of `F(λ) = det(A − λB)`.
pub(crate) fn pencil_coefficients<R: SignRing>(a: &M4<R>, b: &M4<R>) -> [R; 5] {
    // entries as linear polynomials (a, −b)
    let e = |i: usize, j: usize| (&a[i][j], b[i][j].neg());
    let minor = |r: [usize; 2], c: [usize; 2]| -> [R; 3] {
        let (p0, p1) = e(r[0], c[0]);
        let (q0, q1) = e(r[1], c[1]);
        let (s0, s1) = e(r[0], c[1]);
        let (t0, t1) = e(r[1], c[0]);
        [
            p0.mul(q0).sub(&s0.mul(t0)),
            p0.mul(&q1)
                .add(&p1.mul(q0))
                .sub(&s0.mul(&t1))
                .sub(&s1.mul(t0)),
            p1.mul(&q1).sub(&s1.mul(&t1)),
        ]
    };
    let mut f: [R; 5] = std::array::from_fn(|_| R::int(0));
    for (top, bottom, plus) in LAPLACE {
        let u = minor([0, 1], top);
        let v = minor([2, 3], bottom);
        for i in 0..3 {
            for j in 0..3 {
                let t = u[i].mul(&v[j]);
                f[i + j] = if plus {
                    f[i + j].add(&t)
                } else {
                    f[i + j].sub(&t)
                };
            }
        }
    }
    f
}

/// `det M` of a numeric 4×4 matrix (Laplace along rows {0, 1}).
pub(crate) fn det4<R: SignRing>(m: &M4<R>) -> R {
    let mut acc = R::int(0);
    for (top, bottom, plus) in LAPLACE {
        let u = det2(&m[0][top[0]], &m[0][top[1]], &m[1][top[0]], &m[1][top[1]]);
        let v = det2(
            &m[2][bottom[0]],
            &m[2][bottom[1]],
            &m[3][bottom[0]],
            &m[3][bottom[1]],
        );
        let t = u.mul(&v);
        acc = if plus { acc.add(&t) } else { acc.sub(&t) };
    }
    acc
}

/// Is the symmetric matrix definite?  Sylvester's criterion on the leading
/// principal minors (definite iff `D₁, D₂, …` are all positive, or
/// alternate starting negative; a zero minor rules definiteness out).
/// Also returns the sign of the last minor.
pub(crate) fn definite4<R: SignRing>(m: &M4<R>) -> Option<(bool, i32)> {
    let d4 = det4(m).sign()?;
    let s1 = m[0][0].sign()?;
    if s1 == 0 || d4 <= 0 {
        return Some((false, d4));
    }
    let d2 = det2(&m[0][0], &m[0][1], &m[1][0], &m[1][1]).sign()?;
    if d2 <= 0 {
        return Some((false, d4));
    }
    let top: [[R; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].clone()));
    let d3 = det3(&top).sign()?;
    Some((d3 == s1, d4))
}

fn definite3<R: SignRing>(m: &[[R; 3]; 3]) -> Option<bool> {
    let s1 = m[0][0].sign()?;
    if s1 == 0 || det2(&m[0][0], &m[0][1], &m[1][0], &m[1][1]).sign()? <= 0 {
        return Some(false);
    }
    Some(det3(m).sign()? == s1)
}

/// A multiple root of F on the projective line.
#[derive(Clone, Debug)]
enum Root<R> {
    Zero,
    Infinity,
    /// `n/d`, by the formula of the kind.
    Ratio(R, R, RootKind),
}

/// The multiple root `n/d` of the core `F/λ^lo` of the pencil's
/// determinant (coefficients ascending) by the formula of `kind` (not for
/// 0 and ∞).
pub(crate) fn root_ratio<R: SignRing>(core: &[R], kind: RootKind) -> (R, R) {
    match kind {
        RootKind::Quadratic => (core[1].neg(), R::int(2).mul(&core[2])),
        RootKind::CubicTriple => (core[2].neg(), R::int(3).mul(&core[3])),
        RootKind::CubicDouble => {
            let (d, c, bb, aa) = (&core[0], &core[1], &core[2], &core[3]);
            let e = bb.mul(bb).sub(&R::int(3).mul(&aa.mul(c)));
            (R::int(9).mul(&aa.mul(d)).sub(&bb.mul(c)), R::int(2).mul(&e))
        }
        RootKind::Zero | RootKind::Infinity => (R::int(0), R::int(1)),
    }
}

/// `F`'s coefficients and the range `lo..=hi` of its non-zero ones.
pub(crate) type PencilCore<R> = ([R; 5], Option<(usize, usize)>);

/// The pencil's determinant `F(λ) = det(A − λB)` with its known zero
/// coefficients set (B axial: `f₄ = 0`; both axial: `f₀ = 0` too), and the
/// core `f[lo..=hi]` between the first and last non-zero coefficients
/// (`None` inside when `F ≡ 0`; `None` outside when this tier cannot tell).
pub(crate) fn pencil_core<R: SignRing>(
    a: &M4<R>,
    b: &M4<R>,
    both_axial: bool,
) -> Option<PencilCore<R>> {
    let mut f = pencil_coefficients(a, b);
    // det B = 0 (B axial: its vertex, or the point at infinity of its
    // axis, is in the kernel), and det A = 0 when A is axial too: exact
    // zeros the real-valued filter could not certify
    f[4] = R::int(0);
    if both_axial {
        f[0] = R::int(0);
    }
    let mut nz = [false; 5];
    for k in 0..5 {
        nz[k] = f[k].sign()? != 0;
    }
    let Some(lo) = (0..5).find(|&k| nz[k]) else {
        return Some((f, None));
    };
    let hi = (0..5).rev().find(|&k| nz[k]).unwrap_or(lo);
    Some((f, Some((lo, hi))))
}

/// The non-planar cases, from the pencil of `A` and `B`: B is axial, A is
/// axial too (`both_axial`) or a sphere.
fn pencil_route<R: SignRing>(a: &M4<R>, b: &M4<R>, both_axial: bool) -> Option<Outcome> {
    let (f, range) = pencil_core(a, b, both_axial)?;
    let Some((lo, hi)) = range else {
        return Some(Outcome::Fallback("singular pencil (F ≡ 0)"));
    };
    let core: Vec<R> = f[lo..=hi].to_vec();
    let mut multiple: Vec<Root<R>> = Vec::new();
    if lo >= 2 {
        multiple.push(Root::Zero);
    }
    if hi <= 2 {
        multiple.push(Root::Infinity);
    }
    let mut disc2 = None;
    match core.len() - 1 {
        0 | 1 => {}
        2 => {
            let (c0, c1, c2) = (&core[0], &core[1], &core[2]);
            let disc = c1.mul(c1).sub(&R::int(4).mul(&c0.mul(c2)));
            let s = disc.sign()?;
            if s == 0 {
                let (n, d) = root_ratio(&core, RootKind::Quadratic);
                multiple.push(Root::Ratio(n, d, RootKind::Quadratic));
            }
            disc2 = Some(s);
        }
        3 => {
            // three sign changes of F certify three distinct real roots
            // (no discriminant needed: it suffers from the cancellation of
            // the coefficients)
            if !both_axial
                && lo == 0
                && let Some(samples) = float_samples(a, b, &f)
            {
                return definite_at(a, b, &samples);
            }
            let (d, c, bb, aa) = (&core[0], &core[1], &core[2], &core[3]);
            let disc = R::int(18)
                .mul(&aa.mul(bb))
                .mul(&c.mul(d))
                .sub(&R::int(4).mul(&bb.mul(bb).mul(bb)).mul(d))
                .add(&bb.mul(bb).mul(&c.mul(c)))
                .sub(&R::int(4).mul(aa).mul(&c.mul(c).mul(c)))
                .sub(&R::int(27).mul(&aa.mul(aa)).mul(&d.mul(d)));
            let s = disc.sign()?;
            if s == 0 {
                let e = bb.mul(bb).sub(&R::int(3).mul(&aa.mul(c)));
                let kind = if e.sign()? == 0 {
                    RootKind::CubicTriple
                } else {
                    RootKind::CubicDouble
                };
                let (n, d) = root_ratio(&core, kind);
                multiple.push(Root::Ratio(n, d, kind));
            }
            disc2 = Some(s);
        }
        _ => return Some(Outcome::Fallback("pencil of degree 4")),
    }
    match multiple.len() {
        0 => nonsingular(a, b, &f, lo, hi, disc2, both_axial),
        1 => {
            let (m0, n, kind) = match &multiple[0] {
                Root::Zero => (a.clone(), b, RootKind::Zero),
                Root::Infinity => (b.clone(), a, RootKind::Infinity),
                Root::Ratio(num, den, kind) => (member(a, b, num, den), b, *kind),
            };
            one_multiple_root(&m0, n, kind)
        }
        _ => Some(Outcome::Rulings),
    }
}

/// A nonsingular quartic with real points.
const NONSINGULAR: Outcome = Outcome::Counts(
    Counts {
        class: Class::Curve,
        conics: 0,
        lines: 0,
        points: 0,
    },
    "pencil: nonsingular quartic",
    Case::Smooth,
);

/// A nonsingular intersection without real points.
const DEFINITE: Outcome = Outcome::Counts(
    Counts {
        class: Class::Empty,
        conics: 0,
        lines: 0,
        points: 0,
    },
    "pencil: definite member (nonsingular, no real point)",
    Case::Empty,
);

/// A nonsingular intersection (F has four distinct roots on the projective
/// line): empty iff some member is definite.  A member next to the member
/// of a natural quadric (λ = 0 or ∞; such a matrix has eigenvalues of both
/// signs) is indefinite, and the inertia is constant between consecutive
/// roots, so only the arcs away from λ = 0 and λ = ∞ need a sample.
fn nonsingular<R: SignRing>(
    a: &M4<R>,
    b: &M4<R>,
    f: &[R; 5],
    lo: usize,
    hi: usize,
    disc: Option<i32>,
    both_axial: bool,
) -> Option<Outcome> {
    let (curve, empty) = (Some(NONSINGULAR), Some(DEFINITE));
    let disc = disc?;
    if both_axial && lo == 1 && hi == 3 {
        // roots 0, ∞ and those of f1 + f2λ + f3λ²
        if disc < 0 || f[1].sign()? * f[3].sign()? < 0 {
            return curve; // a complex pair, or roots on both sides of 0
        }
        // the arc between the two roots r1, r2 of G = f1 + f2λ + f3λ²: a
        // double near their midpoint, verified (F = λG, and G has the sign
        // of −f3 only between its roots), else the midpoint −f2/(2f3)
        let lead = f[3].sign()?;
        let approx = -f[2].approx() / (2.0 * f[3].approx());
        if let Some((n, d)) = dyadic_of(approx).filter(|_| approx != 0.0) {
            let want = if approx > 0.0 { -lead } else { lead };
            let m = member(a, b, &R::from_z(&n), &R::from_z(&d));
            if let Some((def, d4)) = definite4(&m)
                && d4 == want
            {
                return if def { empty } else { curve };
            }
        }
        let m = member(a, b, &f[2].neg(), &R::int(2).mul(&f[3]));
        return if definite4(&m)?.0 { empty } else { curve };
    }
    if !both_axial && lo == 0 && hi == 3 {
        // A a sphere, B axial: roots ∞ and those of the cubic
        if disc < 0 {
            return curve;
        }
        let samples = match float_samples(a, b, f) {
            Some(s) => s,
            None => exact_samples(f)?,
        };
        return definite_at(a, b, &samples);
    }
    Some(Outcome::Fallback("unexpected pencil degrees"))
}

/// The nonsingular answer from samples of the two candidate arcs.
fn definite_at<R: SignRing>(a: &M4<R>, b: &M4<R>, samples: &[(R, R)]) -> Option<Outcome> {
    for (n, d) in samples {
        if definite4(&member(a, b, n, d))?.0 {
            return Some(DEFINITE);
        }
    }
    Some(NONSINGULAR)
}

/// Two samples `n/d` of a cubic F, one in `(r1, r2)` and one in
/// `(r2, r3)` where `r1 < r2 < r3` are its roots: doubles near the critical
/// points of F, *verified* exactly — F has the sign of its leading
/// coefficient on `(r1, r2)` and the other sign on `(r2, r3)`, so with
/// `s1 < s2` and these two signs F changes sign three times: three
/// distinct real roots, one on each side of each sample.  `None` when the
/// floating-point guess or its verification fails.
fn float_samples<R: SignRing>(a: &M4<R>, b: &M4<R>, f: &[R; 5]) -> Option<Vec<(R, R)>> {
    let lead = f[3].sign()?;
    let [c1, c2, c3] = [f[1].approx(), f[2].approx(), f[3].approx()];
    // critical points: 3c3λ² + 2c2λ + c1 = 0
    let dd = c2 * c2 - 3.0 * c1 * c3;
    if !(dd.is_finite() && dd > 0.0 && c3 != 0.0) {
        return None;
    }
    let q = -(c2 + c2.signum() * dd.sqrt());
    let (m1, m2) = (q / (3.0 * c3), c1 / q);
    let (lo, hi) = if m1 < m2 { (m1, m2) } else { (m2, m1) };
    if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
        return None;
    }
    let mut out = Vec::new();
    for (x, want) in [(lo, lead), (hi, -lead)] {
        let (n, d) = dyadic_of(x)?;
        let (n, d) = (R::from_z(&n), R::from_z(&d));
        // det(dA − nB) = d⁴F(n/d)
        if det4(&member(a, b, &n, &d)).sign()? != want {
            return None;
        }
        out.push((n, d));
    }
    Some(out)
}

/// The same samples from an exact isolation of the roots of F (exact
/// tiers only): rationals between consecutive isolating intervals.
fn exact_samples<R: SignRing>(f: &[R; 5]) -> Option<Vec<(R, R)>> {
    let coeffs: Option<Vec<BigInt>> = f[..4].iter().map(|c| c.exact()).collect();
    let p = crate::poly::ZPoly::new(coeffs?);
    let ivs = crate::roots::isolate_squarefree(&p);
    if ivs.len() != 3 {
        return None;
    }
    let mut out = Vec::new();
    for w in ivs.windows(2) {
        let s = if w[0].hi < w[1].lo {
            (&w[0].hi + &w[1].lo) / crate::number::qi(2)
        } else {
            w[0].hi.clone()
        };
        out.push((R::from_z(s.numer()), R::from_z(s.denom())));
    }
    Some(out)
}

/// A finite double as `(n, d)` with `n/d` its exact value.
fn dyadic_of(x: f64) -> Option<(BigInt, BigInt)> {
    let q = crate::number::double_value(x)?;
    Some((q.numer().clone(), q.denom().clone()))
}

/// Exactly one multiple root λ₀; `m0 = A − λ₀B` (scaled), `n` another
/// member of the pencil.
fn one_multiple_root<R: SignRing>(m0: &M4<R>, n: &M4<R>, root: RootKind) -> Option<Outcome> {
    // rank 3 iff a diagonal cofactor is non-zero (adj = c·ppᵀ)
    let mut vertex = None;
    for k in 0..4 {
        if minor3(m0, k, k).sign()? != 0 {
            vertex = Some(k);
            break;
        }
    }
    match vertex {
        Some(k) => {
            let p: [R; 4] = std::array::from_fn(|i| {
                let c = minor3(m0, i, k);
                if (i + k) % 2 == 0 { c } else { c.neg() }
            });
            nodal(m0, n, &p, root, k)
        }
        None => plane_pair(m0, n, root),
    }
}

/// The tangent cone of the intersection at the vertex `p` of the cone
/// member `m0` (on the other member `n`): the sign of the discriminant of
/// `m0`'s form on two vectors spanning `n`'s tangent plane at `p` modulo
/// `p` (negative: an acnode, zero: a cusp, positive: two real branches),
/// the sign of the resultant of that form and `n`'s (zero: a common line
/// through `p`), and the index `k` of a non-zero coordinate of `p`.
pub(crate) fn vertex_cone<R: SignRing>(
    m0: &M4<R>,
    n: &M4<R>,
    p: &[R; 4],
) -> Option<Result<(i32, i32, usize), &'static str>> {
    let g: [R; 4] = std::array::from_fn(|i| dot(&n[i], p));
    if dot(&g, p).sign()? != 0 {
        return Some(Err("vertex not on the intersection"));
    }
    let Some(j) = (0..4).find(|&i| g[i].sign() != Some(0)) else {
        return Some(Err("common singular point"));
    };
    g[j].sign()?;
    let mut k = None;
    for i in (0..4).filter(|&i| i != j) {
        if p[i].sign()? != 0 {
            k = Some(i);
            break;
        }
    }
    let Some(k) = k else {
        return Some(Err("degenerate vertex"));
    };
    // u, v: t_i = g_j e_i − g_i e_j for the two i ∉ {j, k}
    let t = |i: usize| -> [R; 4] {
        std::array::from_fn(|l| {
            if l == i {
                g[j].clone()
            } else if l == j {
                g[i].neg()
            } else {
                R::int(0)
            }
        })
    };
    let rest: Vec<usize> = (0..4).filter(|&i| i != j && i != k).collect();
    let (u, v) = (t(rest[0]), t(rest[1]));
    let m = [form(m0, &u, &u), form(m0, &u, &v), form(m0, &v, &v)];
    let bq = [form(n, &u, &u), form(n, &u, &v), form(n, &v, &v)];
    let disc_m = m[1].mul(&m[1]).sub(&m[0].mul(&m[2])).sign()?;
    let r1 = det2(&m[0], &m[2], &bq[0], &bq[2]);
    let res = r1.mul(&r1).sub(
        &R::int(4)
            .mul(&det2(&m[0], &m[1], &bq[0], &bq[1]).mul(&det2(&m[1], &m[2], &bq[1], &bq[2]))),
    );
    Some(Ok((disc_m, res.sign()?, k)))
}

/// A cone member `m0` (rank 3, vertex p) at the only multiple root: p is
/// the only singular point of the intersection; real points other than p
/// correspond to the real generators of the cone off the tangent plane of
/// `n` at p (each meets `n` once more), so there is a real curve iff the
/// cone is real (the form of `m0` on `R⁴/p` is indefinite); p is an acnode
/// iff the tangent cone (the cone's lines in `T_p n`) is a complex pair.  A
/// line of the intersection must pass through p and lie in the tangent
/// cone and on `n`: a common root of two binary forms.
fn nodal<R: SignRing>(
    m0: &M4<R>,
    n: &M4<R>,
    p: &[R; 4],
    root: RootKind,
    k0: usize,
) -> Option<Outcome> {
    let (disc_m, res, k) = match vertex_cone(m0, n, p)? {
        Ok(x) => x,
        Err(why) => return Some(Outcome::Fallback(why)),
    };
    if res == 0 {
        return Some(Outcome::Rulings);
    }
    let idx: Vec<usize> = (0..4).filter(|&i| i != k).collect();
    let sub: [[R; 3]; 3] =
        std::array::from_fn(|r| std::array::from_fn(|c| m0[idx[r]][idx[c]].clone()));
    let definite = definite3(&sub)?;
    let affine = p[3].sign()? != 0;
    if definite {
        if disc_m >= 0 {
            return Some(Outcome::Fallback("inconsistent tangent cone"));
        }
        return Some(Outcome::Counts(
            if affine {
                Counts::new(Class::Points, 0, 0, 1)
            } else {
                Counts::empty()
            },
            "pencil: a cone member with imaginary generators (isolated tangency point)",
            if affine {
                Case::ConePoint { root, k: k0 }
            } else {
                Case::Empty
            },
        ));
    }
    let acnode = disc_m < 0 && affine;
    Some(Outcome::Counts(
        Counts::curve(usize::from(acnode)),
        "pencil: one singular point (nodal or cuspidal quartic)",
        Case::Nodal { root, k: k0 },
    ))
}

/// A member of rank 2 at the only multiple root: two planes.  Complex
/// conjugate planes meet in a real line L, and every real point of the
/// intersection lies on L: the affine real points of `L ∩ n`.
fn plane_pair<R: SignRing>(m0: &M4<R>, n: &M4<R>, root: RootKind) -> Option<Outcome> {
    let mut pivot = None;
    'outer: for i in 0..4 {
        for j in i + 1..4 {
            let s = det2(&m0[i][i], &m0[i][j], &m0[j][i], &m0[j][j]).sign()?;
            if s != 0 {
                pivot = Some((i, j, s));
                break 'outer;
            }
        }
    }
    let Some((i, j, s)) = pivot else {
        return Some(Outcome::Fallback("member of rank ≤ 1"));
    };
    if s < 0 {
        return Some(Outcome::Fallback("real plane pair in a non-planar case"));
    }
    let d2 = det2(&m0[i][i], &m0[i][j], &m0[j][i], &m0[j][j]);
    let kernel = |k: usize| -> [R; 4] {
        let mut x: [R; 4] = std::array::from_fn(|_| R::int(0));
        x[k] = d2.clone();
        x[i] = det2(&m0[j][j], &m0[i][j], &m0[j][k], &m0[i][k]).neg();
        x[j] = det2(&m0[i][i], &m0[i][j], &m0[i][k], &m0[j][k]).neg();
        x
    };
    let ks: Vec<usize> = (0..4).filter(|&k| k != i && k != j).collect();
    let (x, y) = (kernel(ks[0]), kernel(ks[1]));
    for v in [&x, &y] {
        for r in 0..4 {
            if dot(&m0[r], v).sign()? != 0 {
                return Some(Outcome::Fallback("member of rank 3"));
            }
        }
    }
    let b = [form(n, &x, &x), form(n, &x, &y), form(n, &y, &y)];
    if all_zero(&b)? {
        return Some(Outcome::Rulings);
    }
    let disc = b[1].mul(&b[1]).sub(&b[0].mul(&b[2])).sign()?;
    let mut count: usize = match disc {
        1 => 2,
        0 => 1,
        _ => 0,
    };
    let (x3, y3) = (x[3].sign()?, y[3].sign()?);
    if x3 == 0 && y3 == 0 {
        count = 0;
    } else if count > 0 {
        let w: [R; 4] = std::array::from_fn(|l| y[3].mul(&x[l]).sub(&x[3].mul(&y[l])));
        if form(n, &w, &w).sign()? == 0 {
            count -= 1;
        }
    }
    Some(Outcome::Counts(
        Counts::of(0, 0, count),
        "pencil: complex-conjugate plane pair (isolated tangency points)",
        if count > 0 {
            Case::PlanePair { root }
        } else {
            Case::Empty
        },
    ))
}

// ------------------------------------------------------------ common rulings

/// The number of common real roots of two binary quadratic forms
/// `a0 s² + a1 st + a2 t²` (the first not identically zero), counted as
/// [`super::topology`] counts common rulings: all real roots of the first
/// when the second vanishes identically or is proportional to it, one when
/// their resultant vanishes otherwise (a single common root of real forms
/// is real), none else.
fn common_roots<R: SignRing>(p: &[R; 3], q: &[R; 3]) -> Option<usize> {
    let real_roots = || -> Option<usize> {
        Some(
            match p[1]
                .mul(&p[1])
                .sub(&R::int(4).mul(&p[0].mul(&p[2])))
                .sign()?
            {
                1 => 2,
                0 => 1,
                _ => 0,
            },
        )
    };
    if all_zero(q)? {
        return real_roots();
    }
    let (m02, m01, m12) = (
        det2(&p[0], &p[2], &q[0], &q[2]),
        det2(&p[0], &p[1], &q[0], &q[1]),
        det2(&p[1], &p[2], &q[1], &q[2]),
    );
    if m02.mul(&m02).sub(&m01.mul(&m12)).sign()? != 0 {
        return Some(0);
    }
    if all_zero(&[m02, m01, m12])? {
        return real_roots();
    }
    Some(1)
}

/// `(f(u,u), 2f(u,v), f(v,v))`: the binary form of `f` on `span(u, v)`.
pub(crate) fn binary<R: SignRing, const N: usize>(
    f: &[[R; N]; N],
    u: &[R; N],
    v: &[R; N],
) -> [R; 3] {
    let fu: [R; N] = std::array::from_fn(|i| dot(&f[i], u));
    let fv: [R; N] = std::array::from_fn(|i| dot(&f[i], v));
    [dot(u, &fu), R::int(2).mul(&dot(u, &fv)), dot(v, &fv)]
}

/// The number of real lines of `x` (a ruling: through the vertex of a
/// cone, parallel to the axis of a cylinder) lying on `y`, the count of
/// [`super::topology::common_rulings`]; `None` inside: not decided here.
fn ruling_count<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<Option<usize>> {
    let my = matrix(y);
    let mx = matrix(x);
    let block = |m: &M4<R>| -> [[R; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].clone()))
    };
    let zero = R::int(0);
    match x.kind {
        Kind::Sphere => Some(Some(0)),
        Kind::Cone => {
            let v4 = [x.c[0].clone(), x.c[1].clone(), x.c[2].clone(), x.q.clone()];
            let w: [R; 4] = std::array::from_fn(|i| dot(&my[i], &v4));
            if dot(&w, &v4).sign()? != 0 {
                return Some(Some(0)); // the vertex is not on y
            }
            let g = [w[0].clone(), w[1].clone(), w[2].clone()];
            if all_zero(&g)? {
                return Some(None); // a common vertex
            }
            let mut u1 = None;
            for j in 0..3 {
                let mut e: [R; 3] = std::array::from_fn(|_| zero.clone());
                e[j] = R::int(1);
                let c = cross(&g, &e);
                if !all_zero(&c)? {
                    u1 = Some(c);
                    break;
                }
            }
            let u1 = u1?;
            let u2 = cross(&g, &u1);
            let p = binary(&block(&mx), &u1, &u2);
            if all_zero(&p)? {
                return Some(None);
            }
            Some(Some(common_roots(&p, &binary(&block(&my), &u1, &u2))?))
        }
        Kind::Cylinder => {
            let a4 = [x.a[0].clone(), x.a[1].clone(), x.a[2].clone(), zero.clone()];
            let ha: [R; 4] = std::array::from_fn(|i| dot(&my[i], &a4));
            if dot(&ha, &a4).sign()? != 0 {
                return Some(Some(0)); // the axis direction is not on y's asymptotic cone
            }
            // the cross-section plane through the point: P = (c + C u + S v)/q
            let e = if all_zero(&x.a[..2])? {
                [R::int(1), zero.clone(), zero.clone()]
            } else {
                [zero.clone(), zero.clone(), R::int(1)]
            };
            let u = cross(&x.a, &e);
            let v = cross(&x.a, &u);
            let c4 = [x.c[0].clone(), x.c[1].clone(), x.c[2].clone(), x.q.clone()];
            let ha3 = [ha[0].clone(), ha[1].clone(), ha[2].clone()];
            let (lu, lv, l0) = (dot(&ha3, &u), dot(&ha3, &v), dot(&ha, &c4));
            if lu.sign()? == 0 && lv.sign()? == 0 {
                return Some(Some(0));
            }
            // the line lu·C + lv·S + l0·W = 0 in (C, S, W)
            let base = if lu.sign()? != 0 {
                [l0.neg(), zero.clone(), lu.clone()]
            } else {
                [zero.clone(), l0.neg(), lv.clone()]
            };
            let dir = [lv.neg(), lu.clone(), zero.clone()];
            // the circle pd(C²|u|² + S²|v|²) − q²pn W² and y, as forms in (C, S, W)
            let circle: [[R; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|j| match (i, j) {
                    (0, 0) => x.pd.mul(&dot(&u, &u)),
                    (1, 1) => x.pd.mul(&dot(&v, &v)),
                    (2, 2) => x.q.mul(&x.q).mul(&x.pn).neg(),
                    _ => zero.clone(),
                })
            });
            let emb: [[R; 4]; 3] = [
                [u[0].clone(), u[1].clone(), u[2].clone(), zero.clone()],
                [v[0].clone(), v[1].clone(), v[2].clone(), zero.clone()],
                c4,
            ];
            let yform: [[R; 3]; 3] =
                std::array::from_fn(|i| std::array::from_fn(|j| form(&my, &emb[i], &emb[j])));
            // along base + σ·dir: (σ², σ, 1) coefficients, as (s², st, t²) with t = 1
            let along = |f: &[[R; 3]; 3]| binary(f, &dir, &base);
            Some(Some(common_roots(&along(&circle), &along(&yform))?))
        }
    }
}

/// A possible common ruling: the rulings of each quadric lying on the
/// other, counted both ways; a line and a twisted cubic when there are some
/// (the complete route's answer), else not a case of the fast route.
fn rulings<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<Outcome> {
    let (Some(n1), Some(n2)) = (ruling_count(x, y)?, ruling_count(y, x)?) else {
        return Some(Outcome::Fallback("common vertex in a non-planar case"));
    };
    if x.kind != Kind::Sphere && y.kind != Kind::Sphere && n1 != n2 {
        return Some(Outcome::Fallback("ruling counts differ"));
    }
    let n = n1.max(n2);
    if n == 0 {
        return Some(Outcome::Fallback(
            "several multiple roots and no common ruling",
        ));
    }
    Some(Outcome::Counts(
        Counts::new(Class::Curve, 0, n, 0),
        "common ruling: a line and a twisted cubic",
        Case::Rulings,
    ))
}

// ------------------------------------------------------------ planar cases

/// `u + v√d`.
#[derive(Clone, Debug)]
pub(crate) struct Sq<R> {
    pub(crate) u: R,
    pub(crate) v: R,
}

impl<R: SignRing> Sq<R> {
    pub(crate) fn rat(u: R) -> Sq<R> {
        Sq { u, v: R::int(0) }
    }
    pub(crate) fn add(&self, o: &Sq<R>) -> Sq<R> {
        Sq {
            u: self.u.add(&o.u),
            v: self.v.add(&o.v),
        }
    }
    pub(crate) fn mul(&self, o: &Sq<R>, d: &R) -> Sq<R> {
        Sq {
            u: self.u.mul(&o.u).add(&self.v.mul(&o.v).mul(d)),
            v: self.u.mul(&o.v).add(&self.v.mul(&o.u)),
        }
    }
    pub(crate) fn scale(&self, k: &R) -> Sq<R> {
        Sq {
            u: self.u.mul(k),
            v: self.v.mul(k),
        }
    }
    /// The exact sign (`d > 0`).
    pub(crate) fn sign(&self, d: &R) -> Option<i32> {
        let (su, sv) = (self.u.sign()?, self.v.sign()?);
        if sv == 0 || su == sv {
            return Some(su);
        }
        if su == 0 {
            return Some(sv);
        }
        Some(
            su * self
                .u
                .mul(&self.u)
                .sub(&self.v.mul(&self.v).mul(d))
                .sign()?,
        )
    }
}

/// The section of the plane through a line of the axial plane,
/// perpendicular to it (Lemma 4.4): `z² = h²(p + σw)` (the case analysis
/// of [`super::planar::section`], counts only).
#[derive(Clone, Copy, Debug, Default)]
struct Section {
    conics: usize,
    lines: usize,
    /// An isolated point, at the line's base point (when `at_base`).
    point: bool,
    at_base: bool,
    /// Lines of the section pass through the base point.
    lines_through_base: bool,
}

fn section<R: SignRing>(h: &[[R; 3]; 3], p: &[Sq<R>; 3], w: &[Sq<R>; 2], d: &R) -> Option<Section> {
    let mut a = Sq::rat(R::int(0));
    let mut b = Sq::rat(R::int(0));
    let mut c = Sq::rat(R::int(0));
    for i in 0..2 {
        for j in 0..2 {
            a = a.add(&w[i].mul(&w[j], d).scale(&h[i][j]));
        }
        for j in 0..3 {
            b = b.add(&w[i].mul(&p[j], d).scale(&h[i][j]));
        }
    }
    for i in 0..3 {
        for j in 0..3 {
            c = c.add(&p[i].mul(&p[j], d).scale(&h[i][j]));
        }
    }
    // (b here is half of the linear coefficient: irrelevant to the signs,
    // k = C − B²/4A has the sign of (AC − b²)·A)
    let (sa, sb, sc) = (a.sign(d)?, b.sign(d)?, c.sign(d)?);
    let mut s = Section::default();
    if sa == 0 && sb == 0 && sc == 0 {
        s.lines = 1;
        s.lines_through_base = true;
        return Some(s);
    }
    if sa != 0 {
        let k = sa * a.mul(&c, d).add(&b.mul(&b, d).scale(&R::int(-1))).sign(d)?;
        if sa < 0 {
            match k {
                1 => s.conics = 1,
                0 => {
                    s.point = true;
                    s.at_base = sb == 0;
                }
                _ => {}
            }
        } else if k != 0 {
            s.conics = 1;
        } else {
            s.lines = 2;
            s.lines_through_base = sb == 0;
        }
    } else if sb != 0 {
        s.conics = 1;
    } else if sc > 0 {
        s.lines = 2;
    }
    Some(s)
}

/// The heights of an axial quadric as a conic on the axial plane, in the
/// homogeneous frame coordinates `(s, t, w)` of `U = P1 + (s e1 + t e2)/w`:
/// `κ(Qw)²h²(U)` with `κ = |a|²pd` (docs/maths.md), from the vectors
/// `E1 = Q e1`, `E2 = Q e2`, `E0 = Q(P1 − P)`.
pub(crate) fn height_conic<R: SignRing>(x: &QIn<R>, e: &[[R; 3]; 3], qq: &R) -> [[R; 3]; 3] {
    let a2 = dot(&x.a, &x.a);
    let ea: [R; 3] = std::array::from_fn(|i| dot(&e[i], &x.a));
    let mut h: [[R; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let ee = dot(&e[i], &e[j]);
            let aa = ea[i].mul(&ea[j]);
            match x.kind {
                Kind::Cone => x.pn.add(&x.pd).mul(&aa).sub(&x.pd.mul(&a2).mul(&ee)),
                _ => x.pd.mul(&aa.sub(&a2.mul(&ee))),
            }
        })
    });
    if x.kind == Kind::Cylinder {
        h[2][2] = h[2][2].add(&x.pn.mul(&a2).mul(&qq.mul(qq)));
    }
    h
}

/// Coplanar distinct axes: `None` inside when the projection conic does not
/// factor (then the pencil decides), else the planar counts of
/// [`super::planar::planar_components`].
/// The projection conic `F` of two quadrics with coplanar axes and the
/// squared heights `H` of the first, in the frame of
/// [`super::build_planar`] (`e2` the second axis, or `P2 − P1` for
/// parallel axes): `F = κ2·H1 − κ1·H2`.
pub(crate) fn projection_conics<R: SignRing>(
    x: &QIn<R>,
    y: &QIn<R>,
    parallel: bool,
) -> ([[R; 3]; 3], [[R; 3]; 3]) {
    let d = point_difference(x, y);
    let qq = x.q.mul(&y.q);
    let e2 = if parallel { d.clone() } else { y.a.clone() };
    let e1s: [R; 3] = std::array::from_fn(|i| qq.mul(&x.a[i]));
    let e2s: [R; 3] = std::array::from_fn(|i| qq.mul(&e2[i]));
    let zero: [R; 3] = std::array::from_fn(|_| R::int(0));
    let negd: [R; 3] = std::array::from_fn(|i| d[i].neg());
    let h1 = height_conic(x, &[e1s.clone(), e2s.clone(), zero], &qq);
    let h2 = height_conic(y, &[e1s, e2s, negd], &qq);
    let k1 = dot(&x.a, &x.a).mul(&x.pd);
    let k2 = dot(&y.a, &y.a).mul(&y.pd);
    let f: [[R; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| k2.mul(&h1[i][j]).sub(&k1.mul(&h2[i][j]))));
    (f, h1)
}

fn planar<R: SignRing>(x: &QIn<R>, y: &QIn<R>, parallel: bool) -> Option<Option<Outcome>> {
    let (f, h1) = projection_conics(x, y, parallel);
    if det3(&f).sign()? != 0 {
        return Some(None);
    }
    let mut f = f; // F matters up to a positive factor
    R::divide_content(f.as_flattened_mut());
    let out = planar_counts(&f, &h1, Case::Planar { parallel })?;
    // the exact conics for the construction, when this tier has them
    let exact = |m: &[[R; 3]; 3]| -> Option<[[BigInt; 3]; 3]> {
        let mut out: [[BigInt; 3]; 3] = Default::default();
        for i in 0..3 {
            for j in 0..3 {
                out[i][j] = m[i][j].exact()?;
            }
        }
        Some(out)
    };
    Some(Some(match out {
        Outcome::Counts(c, m, case) => match exact(&f).zip(exact(&h1)) {
            Some((f, h1)) => Outcome::Planar(c, m, case, Box::new(PlanarConics { f, h1 })),
            None => Outcome::Counts(c, m, case),
        },
        o => o,
    }))
}

fn planar_counts<R: SignRing>(f: &[[R; 3]; 3], h: &[[R; 3]; 3], case: Case) -> Option<Outcome> {
    const WHY: &str = "axial plane: projection conic factors (Lemma 8.1)";
    let r = |x: &R| Sq::rat(x.clone());
    let zero = R::int(0);
    // rank
    let mut rank2 = false;
    'm: for i in 0..3 {
        for j in 0..3 {
            for k in i + 1..3 {
                for l in j + 1..3 {
                    if det2(&f[i][j], &f[i][l], &f[k][j], &f[k][l]).sign()? != 0 {
                        rank2 = true;
                        break 'm;
                    }
                }
            }
        }
    }
    let count = |secs: &[Section], crossing: bool| -> Outcome {
        let conics = secs.iter().map(|s| s.conics).sum();
        let lines = secs.iter().map(|s| s.lines).sum();
        let mut points = 0;
        for (i, s) in secs.iter().enumerate() {
            if !s.point {
                continue;
            }
            if crossing && s.at_base {
                // the point is X: dropped on a line through X, merged with
                // another point at X
                let others = secs.iter().enumerate().filter(|&(j, _)| j != i);
                if others.clone().any(|(_, o)| o.lines_through_base)
                    || others.clone().any(|(j, o)| j < i && o.point && o.at_base)
                {
                    continue;
                }
            }
            points += 1;
        }
        Outcome::Counts(Counts::of(conics, lines, points), WHY, case)
    };
    if !rank2 {
        let Some(row) = (0..3).find(|&i| f[i].iter().any(|x| x.sign() != Some(0))) else {
            return Some(Outcome::Counts(Counts::empty(), WHY, case)); // F ≡ 0
        };
        for x in &f[row] {
            x.sign()?;
        }
        let v = &f[row];
        if v[0].sign()? == 0 && v[1].sign()? == 0 {
            return Some(Outcome::Counts(Counts::empty(), WHY, case));
        }
        let p = if v[0].sign()? != 0 {
            [r(&v[2].neg()), r(&zero), r(&v[0])]
        } else {
            [r(&zero), r(&v[2].neg()), r(&v[1])]
        };
        let s = section(h, &p, &[r(&v[1].neg()), r(&v[0])], &zero)?;
        return Some(count(&[s], false));
    }
    // kernel of a rank-2 conic: cross product of two independent rows
    let mut k = None;
    'k: for i in 0..3 {
        for j in i + 1..3 {
            let c = cross(&f[i], &f[j]);
            if !all_zero(&c)? {
                k = Some(c);
                break 'k;
            }
        }
    }
    let mut k = k?; // a point or direction: up to a positive factor
    R::divide_content(&mut k);
    if k[2].sign()? != 0 {
        let dd = f[0][1].mul(&f[0][1]).sub(&f[0][0].mul(&f[1][1]));
        let x = [r(&k[0]), r(&k[1]), r(&k[2])];
        match dd.sign()? {
            -1 => {
                // conjugate lines: points over X
                let hx = x
                    .iter()
                    .enumerate()
                    .fold(r(&zero), |acc, (i, xi)| {
                        (0..3).fold(acc, |a2, j| a2.add(&xi.mul(&x[j], &zero).scale(&h[i][j])))
                    })
                    .sign(&zero)?;
                let n = match hx {
                    1 => 2,
                    0 => 1,
                    _ => 0,
                };
                return Some(Outcome::Counts(Counts::of(0, 0, n), WHY, case));
            }
            0 => return Some(Outcome::Fallback("degenerate factorisation")),
            _ => {}
        }
        let one = R::int(1);
        let dirs: [[Sq<R>; 2]; 2] = if f[0][0].sign()? != 0 {
            let m = f[0][1].neg();
            [
                [
                    Sq {
                        u: m.clone(),
                        v: one.clone(),
                    },
                    r(&f[0][0]),
                ],
                [Sq { u: m, v: one.neg() }, r(&f[0][0])],
            ]
        } else if f[1][1].sign()? != 0 {
            let m = f[0][1].neg();
            [
                [
                    r(&f[1][1]),
                    Sq {
                        u: m.clone(),
                        v: one.clone(),
                    },
                ],
                [r(&f[1][1]), Sq { u: m, v: one.neg() }],
            ]
        } else {
            [[r(&one), r(&zero)], [r(&zero), r(&one)]]
        };
        let secs = [
            section(h, &x, &dirs[0], &dd)?,
            section(h, &x, &dirs[1], &dd)?,
        ];
        return Some(count(&secs, true));
    }
    // parallel lines with direction (k0, k1)
    let pv = [k[1].neg(), k[0].clone()];
    let a = f[0][0]
        .mul(&pv[0].mul(&pv[0]))
        .add(&R::int(2).mul(&f[0][1]).mul(&pv[0].mul(&pv[1])))
        .add(&f[1][1].mul(&pv[1].mul(&pv[1])));
    let b = pv[0].mul(&f[0][2]).add(&pv[1].mul(&f[1][2]));
    let mut abc = [a, b, f[2][2].clone()]; // the roots σ alone matter
    R::divide_content(&mut abc);
    let [a, b, c] = abc;
    let w = [r(&k[0]), r(&k[1])];
    if a.sign()? == 0 {
        if b.sign()? == 0 {
            return Some(Outcome::Counts(Counts::empty(), WHY, case));
        }
        let p = [
            r(&c.neg().mul(&pv[0])),
            r(&c.neg().mul(&pv[1])),
            r(&R::int(2).mul(&b)),
        ];
        return Some(count(&[section(h, &p, &w, &zero)?], false));
    }
    let disc = b.mul(&b).sub(&a.mul(&c));
    match disc.sign()? {
        -1 => Some(Outcome::Counts(Counts::empty(), WHY, case)),
        0 => {
            let p = [r(&b.neg().mul(&pv[0])), r(&b.neg().mul(&pv[1])), r(&a)];
            Some(count(&[section(h, &p, &w, &zero)?], false))
        }
        _ => {
            let mut secs = Vec::new();
            for sg in [1, -1] {
                let sigma = Sq {
                    u: b.neg(),
                    v: R::int(sg),
                };
                let p = [sigma.scale(&pv[0]), sigma.scale(&pv[1]), r(&a)];
                secs.push(section(h, &p, &w, &disc)?);
            }
            Some(count(&secs, false))
        }
    }
}

// ------------------------------------------------------- circles (common axis)

/// Two spheres (the circle of [`super::coaxial::sphere_sphere`]).
fn two_spheres<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<Outcome> {
    const WHY: &str = "sphere-sphere (radical plane)";
    let d = point_difference(x, y);
    let dd = dot(&d, &d);
    if dd.sign()? == 0 {
        return Some(Outcome::Counts(Counts::empty(), WHY, Case::TwoSpheres));
    }
    // d² = Δ/s with s = (q1q2)²; ρ² has the sign of 4Δ·r1·s·pd1·pd2² − T²
    let s = x.q.mul(&y.q);
    let s = s.mul(&s);
    let t = dd
        .mul(&x.pd.mul(&y.pd))
        .add(&x.pn.mul(&s).mul(&y.pd))
        .sub(&y.pn.mul(&s).mul(&x.pd));
    let e = R::int(4)
        .mul(&dd)
        .mul(&x.pn)
        .mul(&s)
        .mul(&x.pd)
        .mul(&y.pd.mul(&y.pd))
        .sub(&t.mul(&t));
    let c = match e.sign()? {
        1 => Counts::of(1, 0, 0),
        0 => Counts::of(0, 0, 1),
        _ => Counts::empty(),
    };
    Some(Outcome::Counts(c, WHY, Case::TwoSpheres))
}

/// A sphere whose centre lies on the axis of `w` ([`super::coaxial::sphere_on_axis`]).
fn sphere_on_axis<R: SignRing>(s: &QIn<R>, w: &QIn<R>) -> Option<Outcome> {
    const WHY: &str = "sphere centred on the axis (circles)";
    let a2 = dot(&w.a, &w.a);
    let c = match w.kind {
        Kind::Cylinder => match s.pn.mul(&w.pd).sub(&w.pn.mul(&s.pd)).sign()? {
            1 => Counts::of(2, 0, 0),
            0 => Counts::of(1, 0, 0),
            _ => Counts::empty(),
        },
        _ => {
            // (O − V)·a = wv/(q_s q_v), disc ∝ (tn+td) rn qq² |a|² − tn rd wv²
            let u = point_difference(w, s);
            let wv = dot(&u, &w.a);
            let qq = s.q.mul(&w.q);
            let qq2a = qq.mul(&qq).mul(&a2);
            let disc =
                w.pn.add(&w.pd)
                    .mul(&s.pn)
                    .mul(&qq2a)
                    .sub(&w.pn.mul(&s.pd).mul(&wv.mul(&wv)));
            match disc.sign()? {
                -1 => Counts::empty(),
                0 => Counts::of(1, 0, 0),
                _ => {
                    let through_vertex = wv.mul(&wv).mul(&s.pd).sub(&s.pn.mul(&qq2a)).sign()? == 0;
                    if through_vertex {
                        Counts::of(1, 0, 1)
                    } else {
                        Counts::of(2, 0, 0)
                    }
                }
            }
        }
    };
    Some(Outcome::Counts(c, WHY, Case::SphereOnAxis))
}

/// Two axial quadrics on one axis ([`super::coaxial::same_axis`]).
fn same_axis<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<Outcome> {
    const WHY: &str = "common axis (circles)";
    let c = match (x.kind, y.kind) {
        (Kind::Cylinder, Kind::Cylinder) => Counts::empty(),
        (Kind::Cone, Kind::Cone) => {
            if dot(&point_difference(x, y), &x.a).sign()? == 0 {
                Counts::of(0, 0, 1)
            } else if x.pn.mul(&y.pd).sub(&y.pn.mul(&x.pd)).sign()? == 0 {
                Counts::of(1, 0, 0)
            } else {
                Counts::of(2, 0, 0)
            }
        }
        _ => Counts::of(2, 0, 0),
    };
    Some(Outcome::Counts(c, WHY, Case::SameAxis))
}

/// Are the two quadrics the same surface (equal parameters)?
fn same_surface<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<bool> {
    if x.kind != y.kind {
        return Some(false);
    }
    let d = point_difference(x, y);
    let same_param = || Some(x.pn.mul(&y.pd).sub(&y.pn.mul(&x.pd)).sign()? == 0);
    let same_point = || all_zero(&d);
    let parallel = || all_zero(&cross(&x.a, &y.a));
    let on_axis = || all_zero(&cross(&d, &x.a));
    match x.kind {
        Kind::Sphere => all_of(&[&same_param, &same_point]),
        Kind::Cylinder => all_of(&[&same_param, &parallel, &on_axis]),
        Kind::Cone => all_of(&[&same_param, &same_point, &parallel]),
    }
}

/// The whole fast program in one tier.
pub(crate) fn program<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<(Outcome, Axes)> {
    let axes = axes_of(x, y)?;
    if same_surface(x, y)? {
        return Some((
            Outcome::Counts(
                Counts::new(Class::SameSurface, 0, 0, 0),
                "proportional equations",
                Case::SameSurface,
            ),
            axes,
        ));
    }
    let out = match (x.kind, y.kind) {
        (Kind::Sphere, Kind::Sphere) => two_spheres(x, y)?,
        (Kind::Sphere, _) | (_, Kind::Sphere) => {
            let (s, w) = if x.kind == Kind::Sphere {
                (x, y)
            } else {
                (y, x)
            };
            let u = point_difference(w, s);
            if all_zero(&cross(&u, &w.a))? {
                sphere_on_axis(s, w)?
            } else {
                pencil_route(&matrix(s), &matrix(w), false)?
            }
        }
        _ => match axes {
            Axes::Coincident => same_axis(x, y)?,
            Axes::Parallel | Axes::Intersecting => match planar(x, y, axes == Axes::Parallel)? {
                Some(o) => o,
                None => pencil_route(&matrix(x), &matrix(y), true)?,
            },
            _ => pencil_route(&matrix(x), &matrix(y), true)?,
        },
    };
    let out = match out {
        Outcome::Rulings => rulings(x, y)?,
        o => o,
    };
    Some((out, axes))
}

/// Runs [`program`] in the tiers (real balls, integer balls, checked
/// `i128`, big integers).
fn run_tiers(x: &Prep, y: &Prep) -> (Outcome, Axes) {
    fn go<R: SignRing + FromPrep>(x: &Prep, y: &Prep) -> Option<(Outcome, Axes)> {
        program(&x.tier::<R>(), &y.tier::<R>())
    }
    tiered(
        || {
            let real = (x.has_reals() && y.has_reals())
                .then(|| go::<BallR>(x, y))
                .flatten();
            real.or_else(|| go::<Ball>(x, y))
        },
        || go::<Ck>(x, y),
        || {
            // big integers: the pencil's coefficients have about 20 times
            // the inputs' bits (degree 4 in entries of degree ≤ 5)
            crate::budget::check_size(
                "the pencil of two natural quadrics",
                25,
                20 * x.max_bits().max(y.max_bits()),
            );
            go::<BigInt>(x, y)
                .unwrap_or((Outcome::Fallback("undecided in big integers"), Axes::None))
        },
    )
}

/// Options of [`classify_with`]: whether to compute the exact components,
/// and the compute budget.
///
/// ```
/// use quadsect::{Natural, ClassifyOptions, Class};
/// let a: Natural = "cylinder point=0,0,0 axis=1,0,0 radius2=1".parse().unwrap();
/// let b: Natural = "cone vertex=0,0,2 axis=0,1,0 tan2=3".parse().unwrap();
/// let r = quadsect::classify_with(&a, &b, &ClassifyOptions::default().without_components()).unwrap();
/// assert_eq!((r.class(), r.points()), (Class::Points, 2));
/// assert!(!r.has_components());
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ClassifyOptions {
    /// Compute the exact components (conics, lines, points, curve data)
    /// and the deciders' details (the default).  Without them only the
    /// class, the counts, the axes and Theorem 8 are given, by the fast
    /// route (same class and counts).
    pub components: bool,
    /// The compute budget (default: [`Budget::default`]); when it runs out
    /// the class is [`Class::Undecided`] and [`NaturalReport::exhausted`]
    /// says which limit.
    pub budget: Budget,
    /// Also run the papers' deciders by the reference route (Theorem
    /// 8.1/8.2, Lemma 8.1, the pencil, and §7 for skew axes), report them
    /// ([`NaturalReport::deciders`], [`NaturalReport::section7`]) and check
    /// them and the reference route's components against the answer (a
    /// disagreement is a note).  Off by default: it costs the reference
    /// route (milliseconds); `quadsect examples` uses it (the command line and
    /// batch do not offer it yet: their `deciders` and `section7` are null).
    pub deciders: bool,
    /// Also referee the answer ([`NaturalReport::referee`]): the proved
    /// relative size within which every input has the same class and
    /// counts, and an exact nearby input with a different answer.  Off by
    /// default (module `natural::referee`; tens of µs to a few ms).
    pub referee: bool,
}

impl Default for ClassifyOptions {
    fn default() -> Self {
        ClassifyOptions {
            components: true,
            budget: Budget::default(),
            deciders: false,
            referee: false,
        }
    }
}

impl ClassifyOptions {
    /// The default options with the given budget.
    pub fn with_budget(budget: Budget) -> ClassifyOptions {
        ClassifyOptions {
            budget,
            ..ClassifyOptions::default()
        }
    }

    /// The same options, class and counts only (the fast route).
    pub fn without_components(mut self) -> ClassifyOptions {
        self.components = false;
        self
    }

    /// The same options with the referee ([`ClassifyOptions::referee`]).
    pub fn with_referee(mut self) -> ClassifyOptions {
        self.referee = true;
        self
    }

    /// The same options with the papers' deciders by the reference route
    /// ([`ClassifyOptions::deciders`]).
    pub fn with_deciders(mut self) -> ClassifyOptions {
        self.deciders = true;
        self
    }
}

/// The fast route on prepared quadrics (see [`Prepared`]): class and
/// counts, no components; where the fast route cannot decide with
/// certainty, the complete route answers (and its components are kept).
/// No budget of its own (see [`classify_with`]).
pub fn classify_counts(a: &Prepared, b: &Prepared) -> Result<NaturalReport, Error> {
    let (x, y) = (&a.prep, &b.prep);
    let (out, axes) = run_tiers(x, y);
    let fallback = |why: &'static str| -> Result<NaturalReport, Error> {
        let mut r = classify_complete(a.natural(), b.natural())?;
        r.route = Some(Route::Complete(why));
        Ok(r)
    };
    let (counts, method) = match out {
        Outcome::Counts(c, m, _) | Outcome::Planar(c, m, _, _) => (c, m),
        Outcome::Fallback(why) => return fallback(why),
        Outcome::Rulings => return fallback("possible common ruling"),
    };
    Ok(NaturalReport {
        a: a.natural().clone(),
        b: b.natural().clone(),
        class: counts.class,
        axes: axes_relation_of(x, y, axes),
        thm8: a.conic_intersection_thm8(b),
        components: Vec::new(),
        deciders: None,
        section7: None,
        method,
        notes: Vec::new(),
        counts,
        components_computed: false,
        route: Some(Route::Fast),
        exhausted: None,
        member_planes: Vec::new(),
        referee: None,
    })
}

/// The whole answer on prepared quadrics: the fast route's predicates
/// decide the class and counts and the case, then the case's construction
/// builds the exact components (module `natural::construct`) — one pipeline, no
/// second classification.  No budget of its own (see [`classify_with`]).
pub fn classify_prepared(a: &Prepared, b: &Prepared) -> Result<NaturalReport, Error> {
    let (x, y) = (&a.prep, &b.prep);
    let (out, axes) = run_tiers(x, y);
    let (counts, method, case, conics) = match out {
        Outcome::Counts(c, m, case) => (c, m, case, None),
        Outcome::Planar(c, m, case, conics) => (c, m, case, Some(conics)),
        Outcome::Fallback(why) => {
            let mut r = classify_complete(a.natural(), b.natural())?;
            r.notes.push(format!(
                "decided by the reference route (the predicates: {why})"
            ));
            return Ok(r);
        }
        Outcome::Rulings => {
            let mut r = classify_complete(a.natural(), b.natural())?;
            r.notes
                .push("decided by the reference route (a possible common ruling)".into());
            return Ok(r);
        }
    };
    // nothing to build for an empty intersection, except the planes that
    // certify a planar one (on 500-digit spheres the radical plane alone
    // cost 40 times the decision)
    let (components, notes, member_planes) =
        if counts.class == Class::Empty && !matches!(case, Case::Planar { .. }) {
            (Vec::new(), Vec::new(), Vec::new())
        } else {
            super::construct::components(a, b, case, conics.as_deref())?
        };
    let built = Counts::of_components(&components);
    if case != Case::SameSurface && built != counts {
        return Err(Error::internal(format!(
            "the construction for {case:?} built {built:?}, the predicates decided {counts:?}"
        )));
    }
    Ok(NaturalReport {
        a: a.natural().clone(),
        b: b.natural().clone(),
        class: counts.class,
        axes: axes_relation_of(x, y, axes),
        thm8: a.conic_intersection_thm8(b),
        components,
        deciders: None,
        section7: None,
        method,
        notes,
        counts,
        components_computed: true,
        route: None,
        exhausted: None,
        member_planes,
        referee: None,
    })
}

/// Classifies two natural quadrics under a budget: the class and counts
/// from the fast route's predicates (pencil signatures and filtered integer
/// sign tests, a few µs), and with `components` the exact components built
/// from the decision ([`classify_prepared`]).  The class and counts are the
/// same either way.
pub fn classify_with(
    a: &Natural,
    b: &Natural,
    options: &ClassifyOptions,
) -> Result<NaturalReport, Error> {
    crate::budget::run(&options.budget, || {
        crate::budget::check_now();
        let (pa, pb) = (Prepared::new(a), Prepared::new(b));
        let mut r = if options.components {
            classify_prepared(&pa, &pb)?
        } else {
            classify_counts(&pa, &pb)?
        };
        if options.deciders {
            super::classify::add_reference_deciders(&mut r)?;
        }
        if options.referee && r.class != Class::Undecided {
            r.referee = Some(super::referee::referee_within(a, b, &r.counts));
        }
        Ok(r)
    })
    .unwrap_or_else(|e| Ok(NaturalReport::budget_exhausted(a, b, e)))
}
