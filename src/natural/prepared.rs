//! Natural quadrics prepared for fast exact predicates: the parameters with
//! denominators cleared once (integers), their `f64` and `i128` images
//! cached, and the Theorem 8.1/8.2 decider behind a floating-point filter.
//!
//! A quadric is stored as integers `c` (a point: centre, point of the axis
//! or vertex `= c/q`, `q > 0`), `a` (the axis, a primitive integer vector;
//! zero for a sphere) and `pn/pd` (`r2` or `tan²α`, `pd > 0`).  Dyadic input
//! (doubles) has power-of-two denominators, so clearing them is a shift and
//! the integers keep the doubles' 53-bit mantissas: their `f64` images are
//! exact.
//!
//! **Theorem 8.1/8.2, division-free.**  With `D = q1·c2 − q2·c1`
//! (`= q1q2(P2 − P1)`), `e1 = D·a1`, `e2 = D·a2`, `g = a1·a2`, `Aᵢ = |aᵢ|²`:
//! the axes are parallel iff `|a1 × a2|² = A1A2 − g² = 0`; coincident iff
//! moreover `|D|²A1 − e1² = 0`; skew iff `det(D, a1, a2) ≠ 0`.  For
//! meeting axes, `O = P1 + s1 a1 = P2 + s2 a2` with
//! `s1 = s1n/N`, `s2 = s2n/N`, `N = q1q2(A1A2 − g²)` and, by the
//! Binet–Cauchy identity, `s1n = e1A2 − e2g`, `s2n = e1g − e2A1`.  The
//! inscribed sphere at O of a cone has radius² `sᵢ²Aᵢ·tn/(tn + td)`, of a
//! cylinder `rn/rd`; Theorem 8.1 compares them by cross-multiplication
//! (the factor `N²` cancels between two cones).  Parallel axes: equal
//! angles (Theorem 8.2).

use super::deciders::AxesRelation;
use super::types::Natural;
use crate::number::Q;
use crate::number::filter::{
    Ball, BallR, Ck, SignRing, all_zero, cross, dot, sign_with_bound, z_to_f64,
};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The kind of a natural quadric.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    Sphere,
    Cylinder,
    Cone,
}

/// Indices of the stored integers.
pub(crate) const C: usize = 0; // c0, c1, c2
pub(crate) const QD: usize = 3; // q
pub(crate) const AX: usize = 4; // a0, a1, a2
pub(crate) const PN: usize = 7;
pub(crate) const PD: usize = 8;
const NZ: usize = 9;

/// The integer form of one quadric with its cached images.
#[derive(Clone, Debug)]
pub(crate) struct Prep {
    pub kind: Kind,
    pub z: [BigInt; NZ],
    f: [(f64, u32); NZ],
    /// The real values (point, 1, axis, parameter, 1) as doubles, for the
    /// real-valued filter; `None` when one is out of `[2^-64, 2^64]`.
    r: Option<[(f64, u32); NZ]>,
    i: [Option<i128>; NZ],
    thm: ThmF,
}

/// The `f64` data of the Theorem 8 filter (see [`thm8_f64`]).
#[derive(Clone, Copy, Debug, Default)]
struct ThmF {
    c: [f64; 3],
    q: f64,
    a: [f64; 3],
    a2: f64,
    /// `A·tn` (cone) — the numerator factor of the inscribed radius².
    x: f64,
    /// `tn + td` (cone).
    y: f64,
    pn: f64,
    pd: f64,
    /// `max |cᵢ|`, `max |aᵢ|`.
    mc: f64,
    ma: f64,
    /// Precomputed bound factors: `k = |a|² + 3·max|aᵢ|²` (so that
    /// `3·md·max|a₁|·k₂` bounds the permanent of `s1n`), `α = max|aᵢ|²·x`,
    /// `β = k²·y`.
    k: f64,
    alpha: f64,
    beta: f64,
}

/// The numbers of an integer vector over one common positive denominator.
fn common_denominator(v: &[Q; 3]) -> ([BigInt; 3], BigInt) {
    let l = crate::number::denom_lcm(v.iter());
    let c = std::array::from_fn(|i| {
        if v[i].denom() == &l {
            v[i].numer().clone()
        } else {
            v[i].numer() * (&l / v[i].denom())
        }
    });
    (c, l)
}

/// A rational as a double with its rounding count for the real-valued
/// filter: exact (`k = 0`) for a dyadic with a 53-bit numerator, else the
/// quotient of the two converted integers (`k = 5`: two conversions of two
/// roundings each and a division); `None` outside `[2^-64, 2^64]`.
fn real_of(x: &Q) -> Option<(f64, u32)> {
    if x.is_zero() {
        return Some((0.0, 0));
    }
    let (n, d) = (x.numer(), x.denom());
    let dz = d.trailing_zeros().unwrap_or(0);
    let (v, k) = if n.bits() <= 53 && d.bits() == dz + 1 && dz < 1000 {
        (z_to_f64(n).0 * 2f64.powi(-(dz as i32)), 0)
    } else {
        (z_to_f64(n).0 / z_to_f64(d).0, 5)
    };
    let m = v.abs();
    (m.is_finite() && (5.4e-20..=1.8e19).contains(&m)).then_some((v, k))
}

/// A primitive integer vector with the direction of `v`.
fn primitive_direction(v: &[Q; 3]) -> [BigInt; 3] {
    let (c, _) = common_denominator(v);
    let mut g = BigInt::zero();
    for x in &c {
        g = crate::number::gcd_z(&g, x);
    }
    if g.is_zero() || g.is_one() {
        return c;
    }
    std::array::from_fn(|i| &c[i] / &g)
}

impl Prep {
    pub fn new(q: &Natural) -> Prep {
        let zero = || [BigInt::zero(), BigInt::zero(), BigInt::zero()];
        let (kind, (c, qd), a, p) = match q {
            Natural::Sphere(s) => (Kind::Sphere, common_denominator(&s.center), zero(), &s.r2),
            Natural::Cylinder(k) => (
                Kind::Cylinder,
                common_denominator(&k.point),
                primitive_direction(&k.axis),
                &k.r2,
            ),
            Natural::Cone(k) => (
                Kind::Cone,
                common_denominator(&k.vertex),
                primitive_direction(&k.axis),
                &k.t2,
            ),
        };
        let [c0, c1, c2] = c;
        let [a0, a1, a2] = a;
        let z = [
            c0,
            c1,
            c2,
            qd,
            a0,
            a1,
            a2,
            p.numer().clone(),
            p.denom().clone(),
        ];
        let f = std::array::from_fn(|k| z_to_f64(&z[k]));
        let (pt, ax): (&[Q; 3], Option<&[Q; 3]>) = match q {
            Natural::Sphere(s) => (&s.center, None),
            Natural::Cylinder(k) => (&k.point, Some(&k.axis)),
            Natural::Cone(k) => (&k.vertex, Some(&k.axis)),
        };
        let one = (1.0, 0);
        let zero = (0.0, 0);
        let r = (|| -> Option<[(f64, u32); NZ]> {
            let axis = |k: usize| ax.map_or(Some(zero), |a| real_of(&a[k]));
            Some([
                real_of(&pt[0])?,
                real_of(&pt[1])?,
                real_of(&pt[2])?,
                one,
                axis(0)?,
                axis(1)?,
                axis(2)?,
                real_of(p)?,
                one,
            ])
        })();
        let i = std::array::from_fn(|k| z[k].to_i128());
        let exact = |x: BigInt| z_to_f64(&x).0;
        let thm = if kind == Kind::Sphere {
            ThmF::default()
        } else {
            let a2: BigInt = (0..3).map(|k| &z[AX + k] * &z[AX + k]).sum();
            let (x, y) = if kind == Kind::Cone {
                (&a2 * &z[PN], &z[PN] + &z[PD])
            } else {
                (BigInt::zero(), BigInt::zero())
            };
            let fv = |k: usize| f[k].0;
            let max = |off: usize| (0..3).map(|k| z[off + k].abs()).max().map_or(0.0, &exact);
            ThmF {
                c: [fv(C), fv(C + 1), fv(C + 2)],
                q: fv(QD),
                a: [fv(AX), fv(AX + 1), fv(AX + 2)],
                a2: exact(a2),
                x: exact(x),
                y: exact(y),
                pn: fv(PN),
                pd: fv(PD),
                mc: max(C),
                ma: max(AX),
                k: 0.0,
                alpha: 0.0,
                beta: 0.0,
            }
        };
        let mut thm = thm;
        thm.k = thm.a2 + 3.0 * thm.ma * thm.ma;
        thm.alpha = thm.ma * thm.ma * thm.x;
        thm.beta = thm.k * thm.k * thm.y;
        Prep {
            kind,
            z,
            f,
            r,
            i,
            thm,
        }
    }

    /// The largest bit size of the stored integers.
    pub fn max_bits(&self) -> u64 {
        self.z.iter().map(|x| x.bits()).max().unwrap_or(0)
    }

    /// True when the real-valued filter can run on this quadric.
    pub fn has_reals(&self) -> bool {
        self.r.is_some()
    }

    /// The quadric's integers in a tier.
    pub fn tier<R: SignRing + FromPrep>(&self) -> QIn<R> {
        let v = |k: usize| R::from_prep(self, k);
        QIn {
            kind: self.kind,
            c: [v(C), v(C + 1), v(C + 2)],
            q: v(QD),
            a: [v(AX), v(AX + 1), v(AX + 2)],
            pn: v(PN),
            pd: v(PD),
        }
    }
}

/// Building a tier's value from the cached images.
pub(crate) trait FromPrep: Sized {
    fn from_prep(p: &Prep, k: usize) -> Self;
}

impl FromPrep for Ball {
    #[inline]
    fn from_prep(p: &Prep, k: usize) -> Self {
        Ball::input(p.f[k].0, p.f[k].1)
    }
}

impl FromPrep for BallR {
    /// The real values (callers check [`Prep::has_reals`]; NaN otherwise,
    /// which no sign test accepts).
    #[inline]
    fn from_prep(p: &Prep, k: usize) -> Self {
        match &p.r {
            Some(r) => BallR::input(r[k].0, r[k].1),
            None => BallR::input(f64::NAN, 0),
        }
    }
}

impl FromPrep for Ck {
    #[inline]
    fn from_prep(p: &Prep, k: usize) -> Self {
        Ck(p.i[k])
    }
}

impl FromPrep for BigInt {
    fn from_prep(p: &Prep, k: usize) -> Self {
        p.z[k].clone()
    }
}

/// One quadric's integers in a tier R: point `c/q`, axis `a`, parameter
/// `pn/pd` (`r2` or `tan²α`).
#[derive(Clone, Debug)]
pub(crate) struct QIn<R> {
    pub kind: Kind,
    pub c: [R; 3],
    pub q: R,
    pub a: [R; 3],
    pub pn: R,
    pub pd: R,
}

/// How two axes lie (the meeting point is left out: it is built only
/// when a report needs it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Axes {
    /// A sphere is involved.
    None,
    Coincident,
    Parallel,
    Intersecting,
    Skew,
}

/// `D = q1·c2 − q2·c1 = q1q2(P2 − P1)`.
pub(crate) fn point_difference<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> [R; 3] {
    std::array::from_fn(|i| x.q.mul(&y.c[i]).sub(&y.q.mul(&x.c[i])))
}

/// The relation of the axes of two axial quadrics (`None`: undecided in
/// this tier).
pub(crate) fn axes_of<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<Axes> {
    if x.kind == Kind::Sphere || y.kind == Kind::Sphere {
        return Some(Axes::None);
    }
    let d = point_difference(x, y);
    let n = cross(&x.a, &y.a);
    if all_zero(&n)? {
        return Some(if all_zero(&cross(&d, &x.a))? {
            Axes::Coincident
        } else {
            Axes::Parallel
        });
    }
    Some(if dot(&d, &n).sign()? == 0 {
        Axes::Intersecting
    } else {
        Axes::Skew
    })
}

/// Theorem 8.1/8.2 as a division-free program (module docs): `Some(None)`
/// where it does not apply, `None` when this tier cannot decide.
pub(crate) fn thm8_prog<R: SignRing>(x: &QIn<R>, y: &QIn<R>) -> Option<Option<bool>> {
    if x.kind == Kind::Sphere || y.kind == Kind::Sphere {
        return Some(None);
    }
    let d = point_difference(x, y);
    let (e1, e2, g) = (dot(&d, &x.a), dot(&d, &y.a), dot(&x.a, &y.a));
    let (a1, a2) = (dot(&x.a, &x.a), dot(&y.a, &y.a));
    let nn = a1.mul(&a2).sub(&g.mul(&g));
    if nn.sign()? == 0 {
        if dot(&d, &d).mul(&a1).sub(&e1.mul(&e1)).sign()? == 0 {
            return Some(None);
        }
        return Some(Some(match (x.kind, y.kind) {
            (Kind::Cylinder, Kind::Cylinder) => true,
            (Kind::Cone, Kind::Cone) => x.pn.mul(&y.pd).sub(&y.pn.mul(&x.pd)).sign()? == 0,
            _ => false,
        }));
    }
    if dot(&d, &cross(&x.a, &y.a)).sign()? != 0 {
        return Some(None);
    }
    let s1 = e1.mul(&a2).sub(&e2.mul(&g));
    let s2 = e1.mul(&g).sub(&e2.mul(&a1));
    let n2 = || {
        let n = x.q.mul(&y.q).mul(&nn);
        n.mul(&n)
    };
    // inscribed radius² = num/den (cones: times 1/N²)
    let e = match (x.kind, y.kind) {
        (Kind::Cone, Kind::Cone) => s1
            .mul(&s1)
            .mul(&a1.mul(&x.pn))
            .mul(&y.pn.add(&y.pd))
            .sub(&s2.mul(&s2).mul(&a2.mul(&y.pn)).mul(&x.pn.add(&x.pd))),
        (Kind::Cone, _) => s1
            .mul(&s1)
            .mul(&a1.mul(&x.pn))
            .mul(&y.pd)
            .sub(&y.pn.mul(&x.pn.add(&x.pd)).mul(&n2())),
        (_, Kind::Cone) => {
            x.pn.mul(&y.pn.add(&y.pd))
                .mul(&n2())
                .sub(&s2.mul(&s2).mul(&a2.mul(&y.pn)).mul(&x.pd))
        }
        _ => x.pn.mul(&y.pd).sub(&y.pn.mul(&x.pd)),
    };
    Some(Some(e.sign()? == 0))
}

/// The error-bound constant of [`thm8_f64`]: `2^-46`.
const THM_BOUND: f64 = 1.0 / 70_368_744_177_664.0;

/// The sign of an integer-valued quantity computed as `v` whose permanent
/// is at most `m` (up to the rounding of m itself), or `None`.
#[inline]
fn sgn(v: f64, m: f64) -> Option<i32> {
    sign_with_bound(v, THM_BOUND * m)
}

/// Theorem 8.1 for two axial quadrics with meeting axes, in `f64` with a
/// static error bound from per-quadric magnitudes (docs/maths.md,
/// "Floating-point filters"): `Some(None)` for skew axes, `Some(Some(b))`
/// for meeting axes, `None` when undecided (near zero, parallel axes,
/// overflow).
///
/// Each quantity of [`thm8_prog`] is computed in `f64` beside an upper
/// bound `m` of its permanent built from `max|cᵢ|`, `max|aᵢ|` and the
/// stored `|a|²`, `A·tn`, `tn + td` (a dot product of vectors bounded by
/// `M`, `M'` has permanent ≤ `3MM'`).  The program has at most 52
/// roundings on a path (inputs count two), so its error is at most
/// `γ₅₂·permanent`; the bounds are computed in `f64` with at most 60 more
/// roundings from inputs that may be `2u` below the exact magnitudes, so
/// `2^-46·m` bounds the error with room to spare (`γ₅₂/(1 − 60u) < 53u <
/// 2^-46(1 − u)`).
#[inline]
fn thm8_f64(p: &ThmF, r: &ThmF, pk: Kind, rk: Kind) -> Option<Option<bool>> {
    // integer points (q = 1, the usual case) need no scaling
    let (d, md) = if p.q == 1.0 && r.q == 1.0 {
        (
            [r.c[0] - p.c[0], r.c[1] - p.c[1], r.c[2] - p.c[2]],
            r.mc + p.mc,
        )
    } else {
        (
            [
                p.q * r.c[0] - r.q * p.c[0],
                p.q * r.c[1] - r.q * p.c[1],
                p.q * r.c[2] - r.q * p.c[2],
            ],
            p.q * r.mc + r.q * p.mc,
        )
    };
    let dt = |u: &[f64; 3], v: &[f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let (e1, e2, g) = (dt(&d, &p.a), dt(&d, &r.a), dt(&p.a, &r.a));
    let (me1, mg) = (3.0 * md * p.ma, 3.0 * p.ma * r.ma);
    let nn = p.a2 * r.a2 - g * g;
    let mnn = p.a2 * r.a2 + mg * mg;
    if sgn(nn, mnn)? == 0 {
        // parallel: coincident iff |D|²A1 − e1² = 0, else Theorem 8.2
        let dd = dt(&d, &d);
        if sgn(dd * p.a2 - e1 * e1, 3.0 * md * md * p.a2 + me1 * me1)? == 0 {
            return Some(None);
        }
        return Some(Some(match (pk, rk) {
            (Kind::Cylinder, Kind::Cylinder) => true,
            (Kind::Cone, Kind::Cone) => {
                sgn(p.pn * r.pd - r.pn * p.pd, p.pn * r.pd + r.pn * p.pd)? == 0
            }
            _ => false,
        }));
    }
    let n = [
        p.a[1] * r.a[2] - p.a[2] * r.a[1],
        p.a[2] * r.a[0] - p.a[0] * r.a[2],
        p.a[0] * r.a[1] - p.a[1] * r.a[0],
    ];
    if sgn(dt(&d, &n), 6.0 * md * p.ma * r.ma)? != 0 {
        return Some(None);
    }
    let s1 = e1 * r.a2 - e2 * g;
    let s2 = e1 * g - e2 * p.a2;
    // permanents: s1n ≤ me1·A2 + me2·mg = 3·md·ma1·k2, s2n ≤ 3·md·ma2·k1
    let ms1 = 3.0 * md * p.ma * r.k;
    let ms2 = 3.0 * md * r.ma * p.k;
    let qq = p.q * r.q;
    let (e, m) = match (pk, rk) {
        (Kind::Cone, Kind::Cone) => (
            s1 * s1 * (p.x * r.y) - s2 * s2 * (r.x * p.y),
            // ms1²·x1·y2 + ms2²·x2·y1 = 9md²(α1β2 + α2β1)
            9.0 * md * md * (p.alpha * r.beta + r.alpha * p.beta),
        ),
        (Kind::Cone, _) => {
            let (nf, mn) = (qq * nn, qq * mnn);
            (
                s1 * s1 * p.x * r.pd - r.pn * p.y * (nf * nf),
                ms1 * ms1 * p.x * r.pd + r.pn * p.y * (mn * mn),
            )
        }
        (_, Kind::Cone) => {
            let (nf, mn) = (qq * nn, qq * mnn);
            (
                p.pn * r.y * (nf * nf) - s2 * s2 * r.x * p.pd,
                p.pn * r.y * (mn * mn) + ms2 * ms2 * r.x * p.pd,
            )
        }
        _ => (p.pn * r.pd - r.pn * p.pd, p.pn * r.pd + r.pn * p.pd),
    };
    Some(Some(sgn(e, m)? == 0))
}

/// A natural quadric prepared once for fast exact predicates and for the
/// fast classification: denominators cleared, `f64` and `i128` images of
/// its integers cached.
///
/// ```
/// use quadsect::{Natural, natural::Prepared};
/// let a = Prepared::new(&"cone vertex=2,0,0 axis=1,0,0 sin2=1/4".parse::<Natural>().unwrap());
/// let b = Prepared::new(&"cylinder point=0,0,0 axis=0,1,0 radius2=1".parse::<Natural>().unwrap());
/// assert_eq!(a.conic_intersection_thm8(&b), Some(true));
/// ```
#[derive(Clone, Debug)]
pub struct Prepared {
    natural: Natural,
    pub(crate) prep: Prep,
}

impl Prepared {
    /// Prepares a quadric (clears its denominators once).
    pub fn new(q: &Natural) -> Prepared {
        Prepared {
            natural: q.clone(),
            prep: Prep::new(q),
        }
    }

    /// The quadric.
    pub fn natural(&self) -> &Natural {
        &self.natural
    }

    /// Theorem 8.1/8.2 ([`super::deciders::conic_intersection_thm8`]):
    /// `None` for skew or coincident axes and for spheres.  A
    /// floating-point filter with a proven error bound answers first; near
    /// zero (or for parallel axes) the exact tiers ([`Self::conic_intersection_thm8_exact`]) decide.
    /// Cost: a few nanoseconds when the filter decides.
    #[inline]
    pub fn conic_intersection_thm8(&self, other: &Prepared) -> Option<bool> {
        let (p, r) = (&self.prep, &other.prep);
        if p.kind != Kind::Sphere
            && r.kind != Kind::Sphere
            && let Some(v) = thm8_f64(&p.thm, &r.thm, p.kind, r.kind)
        {
            return v;
        }
        self.conic_intersection_thm8_exact(other)
    }

    /// Theorem 8.1/8.2 decided in exact integer arithmetic only (checked
    /// `i128`, big integers on overflow): the filter's fallback.
    pub fn conic_intersection_thm8_exact(&self, other: &Prepared) -> Option<bool> {
        let (p, r) = (&self.prep, &other.prep);
        if let Some(v) = thm8_prog(&p.tier::<Ck>(), &r.tier::<Ck>()) {
            return v;
        }
        thm8_prog(&p.tier::<BigInt>(), &r.tier::<BigInt>()).flatten()
    }
}

/// The axes relation with its exact meeting point, from the integer data
/// (`None` when a sphere is involved).
pub(crate) fn axes_relation_of(x: &Prep, y: &Prep, axes: Axes) -> Option<AxesRelation> {
    Some(match axes {
        Axes::None => return None,
        Axes::Coincident => AxesRelation::Coincident,
        Axes::Parallel => AxesRelation::Parallel,
        Axes::Skew => AxesRelation::Skew,
        Axes::Intersecting => {
            let (u, v) = (x.tier::<BigInt>(), y.tier::<BigInt>());
            let d = point_difference(&u, &v);
            let (e1, e2, g) = (dot(&d, &u.a), dot(&d, &v.a), dot(&u.a, &v.a));
            let (a1, a2) = (dot(&u.a, &u.a), dot(&v.a, &v.a));
            let s1 = &e1 * &a2 - &e2 * &g;
            let n = &u.q * &v.q * (&a1 * &a2 - &g * &g);
            // O = c1/q1 + (s1/N)·a1
            let o = std::array::from_fn(|i| {
                Q::new(u.c[i].clone(), u.q.clone()) + Q::new(&s1 * &u.a[i], n.clone())
            });
            AxesRelation::Intersecting(o)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::natural::deciders::{relation, thm8};
    use crate::natural::parse_natural;

    fn both(a: &str, b: &str) -> (Option<bool>, Option<bool>, Option<bool>) {
        let (x, y) = (parse_natural(a).unwrap(), parse_natural(b).unwrap());
        let reference = relation(&x, &y).and_then(|r| thm8(&x, &y, &r));
        let (px, py) = (Prepared::new(&x), Prepared::new(&y));
        (
            reference,
            px.conic_intersection_thm8(&py),
            px.conic_intersection_thm8_exact(&py),
        )
    }

    #[test]
    fn agrees_with_the_rational_decider_on_classics() {
        for (a, b) in [
            (
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                "cylinder point=0,0,0 axis=0,1,0 radius2=1",
            ),
            (
                "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
                "cylinder point=0,0,0 axis=0,1,0 radius2=1",
            ),
            (
                "cylinder point=0,0,0 axis=0,1,0 radius2=1",
                "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
            ),
            (
                "cone vertex=2,0,0 axis=1,0,0 sin2=1/2",
                "cone vertex=0,4,0 axis=0,1,0 sin2=1/8",
            ),
            (
                "cone vertex=0,0,0 axis=0,0,1 tan2=1",
                "cone vertex=3,0,1 axis=0,0,2 tan2=1",
            ),
            (
                "cone vertex=0,0,0 axis=0,0,1 tan2=1",
                "cone vertex=0,0,5 axis=0,0,2 tan2=1",
            ),
            (
                "cone vertex=1/3,0,0 axis=1,1,0 tan2=2/7",
                "cylinder point=0,1/5,0 axis=1,-1,0 radius2=3/11",
            ),
            (
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                "cylinder point=0,0,3 axis=0,1,0 radius2=1",
            ),
            (
                "sphere center=0,0,0 radius2=1",
                "cylinder point=0,0,0 axis=0,1,0 radius2=1",
            ),
        ] {
            let (r, f, e) = both(a, b);
            assert_eq!(f, r, "{a} / {b}");
            assert_eq!(e, r, "{a} / {b}");
        }
    }

    #[test]
    fn filter_declines_near_equal_radii_with_large_numbers() {
        // cylinders meeting at O with radii² 1 and 1 + 2^-60: the f64
        // program cannot separate them, the exact tiers must answer false
        let a = parse_natural("cylinder point=0,0,0 axis=1,0,0 radius2=1").unwrap();
        let b = parse_natural("cylinder point=0,0,0 axis=0,1,0 radius2=1.000000000000000000867361737988403547205962240695953369140625").unwrap();
        let (pa, pb) = (Prepared::new(&a), Prepared::new(&b));
        assert_eq!(
            thm8_f64(&pa.prep.thm, &pb.prep.thm, pa.prep.kind, pb.prep.kind),
            None
        );
        assert_eq!(pa.conic_intersection_thm8(&pb), Some(false));
    }

    proptest::proptest! {
        /// The filtered decider, its exact fallback and the BigRational
        /// decider agree on random rational pairs (coplanar by
        /// construction half of the time, so that Theorem 8.1 applies),
        /// including pairs built to have equal inscribed radii.
        #[test]
        fn filtered_thm8_agrees(v1 in (-9i64..10, -9i64..10), v2 in (-9i64..10, -9i64..10),
                                a1 in (-9i64..10, -9i64..10), a2 in (-9i64..10, -9i64..10),
                                t1 in (1i64..50, 1i64..50), t2 in (1i64..50, 1i64..50),
                                z in -2i64..3, den in 1i64..4, cyl in 0u8..4) {
            if a1 == (0, 0) || a2 == (0, 0) { return Ok(()); }
            let q1 = if cyl & 1 == 1 {
                format!("cylinder point={}/{den},{},0 axis={},{},0 radius2={}/{}", v1.0, v1.1, a1.0, a1.1, t1.0, t1.1)
            } else {
                format!("cone vertex={}/{den},{},0 axis={},{},0 tan2={}/{}", v1.0, v1.1, a1.0, a1.1, t1.0, t1.1)
            };
            let q2 = if cyl & 2 == 2 {
                format!("cylinder point={},{},{z} axis={},{},0 radius2={}/{}", v2.0, v2.1, a2.0, a2.1, t2.0, t2.1)
            } else {
                format!("cone vertex={},{},{z} axis={},{},0 tan2={}/{}", v2.0, v2.1, a2.0, a2.1, t2.0, t2.1)
            };
            let (r, f, e) = both(&q1, &q2);
            proptest::prop_assert_eq!(f, r);
            proptest::prop_assert_eq!(e, r);
        }
    }
}
