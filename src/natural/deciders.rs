//! The relation of the axes and the three independent exact deciders of
//! conic (planar) intersection for two axial natural quadrics:
//!
//! 1. the closed forms of Theorem 8.1 / Corollary 8.1 (intersecting axes:
//!    equal inscribed spheres centred at the meeting point O) and Theorem
//!    8.2 (parallel axes: equal cone angles) — [`thm8`];
//! 2. Lemma 8.1 — the projection conic `F = h1² − h2²` in a rational frame
//!    of the axial plane and its 3×3 discriminant — [`AxialPlane`];
//! 3. the pencil `A1 − λA2`: a member of rank ≤ 2 exists iff the gcd of its
//!    3×3 minors is non-constant (or `A2` itself has rank ≤ 2) —
//!    [`pencil_has_planar_member`].

use super::types::Natural;
use crate::geom::det3;
use crate::geom::vec3::{
    V3, add, cross, cross_i128, dot, dot_i128, is_zero, norm2, parallel, scale, sub,
};
use crate::number::Q;
use crate::poly::{QPoly, ZPoly};
use num_traits::{One, Zero};

/// How two axes lie.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum AxesRelation {
    /// The same line.
    Coincident,
    /// Parallel, distinct.
    Parallel,
    /// Coplanar, meeting at the rational point O.
    Intersecting(V3),
    /// Not coplanar.
    Skew,
}

impl AxesRelation {
    /// The output spelling (`coplanar-intersecting`, `parallel`, `coincident`,
    /// `skew`).
    pub fn as_str(&self) -> &'static str {
        match self {
            AxesRelation::Coincident => "coincident",
            AxesRelation::Parallel => "parallel",
            AxesRelation::Intersecting(_) => "coplanar-intersecting",
            AxesRelation::Skew => "skew",
        }
    }
}

/// The relation of the lines `p1 + s a1` and `p2 + t a2`, exactly; the
/// meeting point is rational.
pub fn axes_relation(p1: &V3, a1: &V3, p2: &V3, a2: &V3) -> AxesRelation {
    let d = sub(p2, p1);
    let n = cross(a1, a2);
    if is_zero(&n) {
        return if parallel(&d, a1) {
            AxesRelation::Coincident
        } else {
            AxesRelation::Parallel
        };
    }
    if !dot(&d, &n).is_zero() {
        return AxesRelation::Skew;
    }
    // p1 + s a1 = p2 + t a2  ⇒  s = ((p2 − p1) × a2)·n / |n|²
    let s = dot(&cross(&d, a2), &n) / norm2(&n);
    AxesRelation::Intersecting(add(p1, &scale(a1, &s)))
}

/// The axes relation of two quadrics (`None` when a sphere is involved).
pub fn relation(a: &Natural, b: &Natural) -> Option<AxesRelation> {
    let (p1, a1) = a.axis_line()?;
    let (p2, a2) = b.axis_line()?;
    Some(axes_relation(&p1, &a1, &p2, &a2))
}

/// Squared radius of the sphere centred at `o` (a point of the axis)
/// inscribed in an axial quadric: `r2` for a cylinder, `|O − V|²·sin²α` for
/// a cone (Corollary 8.1: `d sin α`).
pub fn inscribed_radius2(q: &Natural, o: &V3) -> Q {
    match q {
        Natural::Cylinder(c) => c.r2.clone(),
        Natural::Cone(c) => norm2(&sub(o, &c.vertex)) * c.sin2(),
        Natural::Sphere(s) => s.r2.clone(),
    }
}

/// Theorem 8.1 / Corollary 8.1 (intersecting axes: equal inscribed spheres
/// at O) and Theorem 8.2 (parallel axes: equal angles, a cylinder having
/// angle 0).  `None` for skew or coincident axes and for spheres.
pub fn thm8(a: &Natural, b: &Natural, rel: &AxesRelation) -> Option<bool> {
    match rel {
        AxesRelation::Intersecting(o) => Some(inscribed_radius2(a, o) == inscribed_radius2(b, o)),
        AxesRelation::Parallel => Some(match (a, b) {
            (Natural::Cylinder(_), Natural::Cylinder(_)) => true,
            (Natural::Cone(x), Natural::Cone(y)) => x.t2 == y.t2,
            _ => false,
        }),
        _ => None,
    }
}

/// Theorem 8.1/8.2 decided directly from the two quadrics (`None` where
/// it does not apply): an exact fast path in checked `i128` arithmetic for
/// integer points and axes (division-free: the meeting point is kept as
/// `p1 + (sn/sd) a1` and the inscribed radii are compared by
/// cross-multiplication), falling back to rationals on overflow.
///
/// Cost: O(1) — a few dozen machine-word operations on small integer
/// input (≈ 0.1 µs), rational arithmetic otherwise.
///
/// ```
/// use quadsect::Natural;
/// let a: Natural = "cone vertex=2,0,0 axis=1,0,0 sin2=1/4".parse().unwrap();
/// let b: Natural = "cylinder point=0,0,0 axis=0,1,0 radius2=1".parse().unwrap();
/// assert_eq!(quadsect::natural::thm8(&a, &b), Some(true));
/// ```
pub fn conic_intersection_thm8(a: &Natural, b: &Natural) -> Option<bool> {
    if let Some(r) = thm8_small(a, b) {
        return r;
    }
    let rel = relation(a, b)?;
    thm8(a, b, &rel)
}

struct Small {
    p: [i128; 3],
    a: [i128; 3],
    cone: bool,
    num: i128,
    den: i128,
}

fn small(q: &Natural) -> Option<Small> {
    let int = |x: &Q| -> Option<i128> {
        if !x.denom().is_one() {
            return None;
        }
        num_traits::ToPrimitive::to_i64(x.numer()).map(|v| v as i128)
    };
    let frac = |x: &Q| -> Option<(i128, i128)> {
        Some((
            num_traits::ToPrimitive::to_i64(x.numer())? as i128,
            num_traits::ToPrimitive::to_i64(x.denom())? as i128,
        ))
    };
    let v3 = |v: &V3| -> Option<[i128; 3]> { Some([int(&v[0])?, int(&v[1])?, int(&v[2])?]) };
    match q {
        Natural::Cone(c) => {
            let (n, d) = frac(&c.t2)?;
            Some(Small {
                p: v3(&c.vertex)?,
                a: v3(&c.axis)?,
                cone: true,
                num: n,
                den: d,
            })
        }
        Natural::Cylinder(c) => {
            let (n, d) = frac(&c.r2)?;
            Some(Small {
                p: v3(&c.point)?,
                a: v3(&c.axis)?,
                cone: false,
                num: n,
                den: d,
            })
        }
        Natural::Sphere(_) => None,
    }
}

/// `Some(answer)` when the fast path decided, `None` to fall back.
fn thm8_small(a: &Natural, b: &Natural) -> Option<Option<bool>> {
    let (x, y) = (small(a)?, small(b)?);
    let d = [y.p[0] - x.p[0], y.p[1] - x.p[1], y.p[2] - x.p[2]];
    let n = cross_i128(&x.a, &y.a)?;
    if n == [0, 0, 0] {
        if cross_i128(&d, &x.a)? == [0, 0, 0] {
            return Some(None); // coincident
        }
        return Some(Some(match (x.cone, y.cone) {
            (false, false) => true,
            (true, true) => x.num.checked_mul(y.den)? == y.num.checked_mul(x.den)?,
            _ => false,
        }));
    }
    if dot_i128(&d, &n)? != 0 {
        return Some(None); // skew
    }
    let sn = dot_i128(&cross_i128(&d, &y.a)?, &n)?;
    let sd = dot_i128(&n, &n)?;
    // ρ² as num/den for each quadric, O = p1 + (sn/sd) a1
    let rho = |q: &Small| -> Option<(i128, i128)> {
        if !q.cone {
            return Some((q.num, q.den));
        }
        let w: [i128; 3] = [
            (x.p[0] - q.p[0])
                .checked_mul(sd)?
                .checked_add(sn.checked_mul(x.a[0])?)?,
            (x.p[1] - q.p[1])
                .checked_mul(sd)?
                .checked_add(sn.checked_mul(x.a[1])?)?,
            (x.p[2] - q.p[2])
                .checked_mul(sd)?
                .checked_add(sn.checked_mul(x.a[2])?)?,
        ];
        Some((
            dot_i128(&w, &w)?.checked_mul(q.num)?,
            sd.checked_mul(sd)?.checked_mul(q.num + q.den)?,
        ))
    };
    let (n1, d1) = rho(&x)?;
    let (n2, d2) = rho(&y)?;
    Some(Some(n1.checked_mul(d2)? == n2.checked_mul(d1)?))
}

/// A quadratic polynomial in the frame coordinates (s, t) of the axial
/// plane, as the symmetric matrix of `(s, t, 1)`.
pub type Conic2 = [[Q; 3]; 3];

/// The axial plane H with a rational, non-orthonormal frame: points
/// `O + s e1 + t e2`, normal `n = e1 × e2`, Gram matrix of `e1, e2`.
#[derive(Clone, Debug)]
pub struct AxialPlane {
    /// Origin (the meeting point of the axes, or a point of the first axis).
    pub o: V3,
    /// First spanning vector (the first axis direction).
    pub e1: V3,
    /// Second spanning vector.
    pub e2: V3,
    /// Normal `e1 × e2`.
    pub n: V3,
    /// Squared heights `h1²`, `h2²` as conics in (s, t).
    pub heights: [Conic2; 2],
    /// The projection conic `F = h1² − h2²` (Lemma 8.1).
    pub projection: Conic2,
    /// Its discriminant `det F` (zero iff F factors).
    pub discriminant: Q,
    /// The point X where `∇F = 0` (the paper's meeting point of the
    /// diagonals), in frame coordinates, when it is unique and affine.
    pub x_point: Option<(Q, Q)>,
}

/// Squared height of an axial quadric over the point `O + s e1 + t e2` of
/// the axial plane (contract §4): cylinder `r2 − |(U − Q) × a|²/|a|²`, cone
/// `(1 + t2)((U − V)·a)²/|a|² − |U − V|²`.
pub fn squared_height(q: &Natural, o: &V3, e1: &V3, e2: &V3) -> Conic2 {
    let (p0, a, cyl_r2, coef) = match q {
        Natural::Cylinder(c) => (
            c.point.clone(),
            c.axis.clone(),
            Some(c.r2.clone()),
            Q::one(),
        ),
        Natural::Cone(c) => (c.vertex.clone(), c.axis.clone(), None, Q::one() + &c.t2),
        Natural::Sphere(_) => unreachable!("spheres have no axial plane"),
    };
    let c0 = sub(o, &p0);
    let vecs = [e1.clone(), e2.clone(), c0];
    let a2 = norm2(&a);
    let mut m: Conic2 = std::array::from_fn(|_| std::array::from_fn(|_| Q::zero()));
    let va: [Q; 3] = std::array::from_fn(|i| dot(&vecs[i], &a));
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = &coef * &va[i] * &va[j] / &a2 - dot(&vecs[i], &vecs[j]);
        }
    }
    if let Some(r2) = cyl_r2 {
        m[2][2] += r2;
    }
    m
}

/// Evaluates a conic at frame coordinates.
pub fn eval_conic(c: &Conic2, s: &Q, t: &Q) -> Q {
    let v = [s.clone(), t.clone(), Q::one()];
    let mut acc = Q::zero();
    for i in 0..3 {
        for j in 0..3 {
            acc += &c[i][j] * &v[i] * &v[j];
        }
    }
    acc
}

impl AxialPlane {
    /// The axial plane of two axial quadrics with coplanar distinct axes
    /// (`None` otherwise).
    pub fn new(a: &Natural, b: &Natural) -> Option<AxialPlane> {
        let (p1, a1) = a.axis_line()?;
        let (p2, a2) = b.axis_line()?;
        let (o, e2) = match axes_relation(&p1, &a1, &p2, &a2) {
            AxesRelation::Intersecting(o) => (o, a2.clone()),
            AxesRelation::Parallel => (p1.clone(), sub(&p2, &p1)),
            _ => return None,
        };
        let e1 = a1.clone();
        let n = cross(&e1, &e2);
        let h1 = squared_height(a, &o, &e1, &e2);
        let h2 = squared_height(b, &o, &e1, &e2);
        let f: Conic2 = std::array::from_fn(|i| std::array::from_fn(|j| &h1[i][j] - &h2[i][j]));
        let disc = det3(&f);
        // ∇F = 0:  [f00 f01; f01 f11] (s, t) = −(f02, f12)
        let det2 = &f[0][0] * &f[1][1] - &f[0][1] * &f[1][0];
        let x_point = if det2.is_zero() {
            None
        } else {
            let s = (-&f[0][2] * &f[1][1] + &f[1][2] * &f[0][1]) / &det2;
            let t = (-&f[1][2] * &f[0][0] + &f[0][2] * &f[1][0]) / &det2;
            Some((s, t))
        };
        Some(AxialPlane {
            o,
            e1,
            e2,
            n,
            heights: [h1, h2],
            projection: f,
            discriminant: disc,
            x_point,
        })
    }

    /// The 3D point of frame coordinates (s, t).
    pub fn point(&self, s: &Q, t: &Q) -> V3 {
        add(&self.o, &add(&scale(&self.e1, s), &scale(&self.e2, t)))
    }

    /// Lemma 8.1: conic or linear intersection iff the discriminant is 0.
    pub fn lemma81_planar(&self) -> bool {
        self.discriminant.is_zero()
    }

    /// Squared heights `(h1², h2²)` at X.
    pub fn heights_at_x(&self) -> Option<(Q, Q)> {
        let (s, t) = self.x_point.as_ref()?;
        Some((
            eval_conic(&self.heights[0], s, t),
            eval_conic(&self.heights[1], s, t),
        ))
    }
}

/// A 4×4 matrix with polynomial entries (in λ).
type PMat4 = [[QPoly; 4]; 4];

fn pencil(a1: &[[Q; 4]; 4], a2: &[[Q; 4]; 4]) -> PMat4 {
    std::array::from_fn(|i| std::array::from_fn(|j| QPoly::new(vec![a1[i][j].clone(), -&a2[i][j]])))
}

fn minor3(m: &PMat4, rows: [usize; 3], cols: [usize; 3]) -> QPoly {
    let e = |i: usize, j: usize| &m[rows[i]][cols[j]];
    let t = |a: &QPoly, b: &QPoly, c: &QPoly, d: &QPoly| &(a * b) - &(c * d);
    &(&(e(0, 0) * &t(e(1, 1), e(2, 2), e(1, 2), e(2, 1)))
        - &(e(0, 1) * &t(e(1, 0), e(2, 2), e(1, 2), e(2, 0))))
        + &(e(0, 2) * &t(e(1, 0), e(2, 1), e(1, 1), e(2, 0)))
}

const TRIPLES: [[usize; 3]; 4] = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];

/// `det(A1 − λA2)`, the characteristic polynomial of the pencil.
#[cfg(test)]
pub fn pencil_determinant(a1: &[[Q; 4]; 4], a2: &[[Q; 4]; 4]) -> QPoly {
    let m = pencil(a1, a2);
    let mut acc = QPoly::zero();
    for (j, cols) in TRIPLES.iter().enumerate() {
        let minor = minor3(&m, [1, 2, 3], *cols);
        let term = &m[0][j] * &minor;
        acc = if j % 2 == 0 {
            &acc + &term
        } else {
            &acc - &term
        };
    }
    acc
}

/// The gcd of all 3×3 minors of `A1 − λA2` (primitive, over Z; the zero
/// polynomial when every minor vanishes identically).  Its roots are the λ
/// with `rank(A1 − λA2) ≤ 2`.
pub fn pencil_rank2_gcd(a1: &[[Q; 4]; 4], a2: &[[Q; 4]; 4]) -> ZPoly {
    let m = pencil(a1, a2);
    let mut g = ZPoly::zero();
    for rows in TRIPLES {
        for cols in TRIPLES {
            let (z, _) = ZPoly::from_q(&minor3(&m, rows, cols));
            g = if g.is_zero() { z } else { g.gcd(&z) };
            if g.degree() == Some(0) {
                return g;
            }
        }
    }
    g
}

fn rank_le2(a: &[[Q; 4]; 4]) -> bool {
    let z: [[QPoly; 4]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|j| QPoly::constant(a[i][j].clone())));
    TRIPLES
        .iter()
        .all(|r| TRIPLES.iter().all(|c| minor3(&z, *r, *c).is_zero()))
}

/// The pencil decider: some member `A1 − λA2` (λ ∈ C ∪ {∞}) has rank ≤ 2,
/// i.e. the intersection lies in a pair of (possibly complex) planes.
pub fn pencil_has_planar_member(a: &Natural, b: &Natural) -> bool {
    let (a1, a2) = (a.matrix(), b.matrix());
    if rank_le2(&a2) {
        return true;
    }
    let g = pencil_rank2_gcd(&a1, &a2);
    g.is_zero() || g.degree().unwrap_or(0) >= 1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::natural::parse_natural;

    fn deciders(a: &str, b: &str) -> (Option<bool>, bool, bool) {
        let a = parse_natural(a).unwrap();
        let b = parse_natural(b).unwrap();
        let rel = relation(&a, &b).unwrap();
        let h = AxialPlane::new(&a, &b).unwrap();
        (
            thm8(&a, &b, &rel),
            h.lemma81_planar(),
            pencil_has_planar_member(&a, &b),
        )
    }

    #[test]
    fn three_deciders_agree_on_classics() {
        // equal perpendicular cylinders: two ellipses
        assert_eq!(
            deciders(
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                "cylinder point=0,0,0 axis=0,1,0 radius2=1"
            ),
            (Some(true), true, true)
        );
        // unequal: quartic
        assert_eq!(
            deciders(
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                "cylinder point=0,0,0 axis=0,1,0 radius2=2"
            ),
            (Some(false), false, false)
        );
        // cone and cylinder with a common inscribed sphere: cone vertex at
        // distance 2 from O with sin²α = 1/4 → radius² 1
        assert_eq!(
            deciders(
                "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
                "cylinder point=0,0,0 axis=0,1,0 radius2=1"
            ),
            (Some(true), true, true)
        );
        // parallel cones with equal angles
        assert_eq!(
            deciders(
                "cone vertex=0,0,0 axis=0,0,1 tan2=1",
                "cone vertex=3,0,1 axis=0,0,2 tan2=1"
            ),
            (Some(true), true, true)
        );
        assert_eq!(
            deciders(
                "cone vertex=0,0,0 axis=0,0,1 tan2=1",
                "cone vertex=3,0,1 axis=0,0,2 tan2=2"
            ),
            (Some(false), false, false)
        );
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_thm8() {
        use crate::natural::{
            deciders::{relation, thm8},
            parse_natural,
        };
        let a = parse_natural("cylinder point=0,0,0 axis=1,0,0 radius2=1").unwrap();
        let b = parse_natural("cylinder point=0,0,0 axis=0,1,0 radius2=1").unwrap();
        assert_eq!(thm8(&a, &b, &relation(&a, &b).unwrap()), Some(true));
    }
}
