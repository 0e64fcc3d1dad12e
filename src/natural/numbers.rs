//! Exact output numbers for the natural-quadric constructions: rationals,
//! quadratic irrationals `a + b√d` ([`QSqrt`]) and, where a construction
//! nests square roots, general real algebraic numbers ([`RealAlg`]).
//!
//! A real algebraic number found by an algebraic method (a coordinate of a
//! RUR point) is turned into `a + b√d` when it has degree ≤ 2: an integer
//! relation `c2 x² + c1 x + c0 ≈ 0` is found by lattice reduction on a
//! high-precision approximation and then *verified exactly* (the relation
//! must vanish at the number, decided by a gcd), so nothing is guessed.

use super::result::Plane;
use crate::number::xball::XBall;
use crate::number::{Q, QSqrt};
use crate::poly::{QPoly, ZPoly};
use crate::roots::{RealAlg, isolate_squarefree};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// An exact real number of the output: an element `a + b√d` of a
/// quadratic field (rationals included), or a real algebraic number of
/// higher degree.  `Display` prints it exactly (`1/2 + 3/4·√(5)`) or, for
/// higher degree, as its defining polynomial and interval.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Exact {
    /// In Q(√d) (rationals included).
    Quad(QSqrt),
    /// A real algebraic number of higher degree.
    Alg(RealAlg),
}

impl Exact {
    /// A rational.
    pub fn rational(q: Q) -> Exact {
        Exact::Quad(QSqrt::rational(q))
    }

    /// Decimal approximation.
    pub fn approx(&self, digits: usize) -> String {
        match self {
            Exact::Quad(x) => x.approx(digits),
            Exact::Alg(a) => a.approx(digits),
        }
    }

    /// Exact text (`a + b·√(d)` or an approximation with its polynomial).
    pub fn text(&self) -> String {
        match self {
            Exact::Quad(x) => x.normalized().to_string(),
            Exact::Alg(a) => format!("≈{}", a.approx(12)),
        }
    }

    /// The value as a double with a proven bound on its error:
    /// `|self − v| ≤ b` for `(v, b)`, with `b` a few units in the last place
    /// of `v` (at most `2^-46·|v|`; 0 for a rational that is a double;
    /// `(±∞, ∞)` beyond the range of doubles).
    ///
    /// ```
    /// use quadsect::natural::{classify_str, Component};
    /// let r = classify_str("sphere center=0,0,0 radius2=2", "sphere center=1,0,0 radius2=2").unwrap();
    /// let Component::Conic { axes2, .. } = &r.components()[0] else { panic!() };
    /// let (v, b) = axes2[0].to_f64_bounded(); // the circle's radius², 7/4
    /// assert!((v - 1.75).abs() <= b && b < 1e-15);
    /// ```
    pub fn to_f64_bounded(&self) -> (f64, f64) {
        match self {
            Exact::Quad(x) => x.to_f64_bounded(),
            Exact::Alg(a) => {
                let mut c = a.clone();
                c.refine_relative(64);
                let (lo, hi) = c.interval();
                crate::number::xball::XBall::from_interval(&lo, &hi)
                    .to_f64()
                    .unwrap_or_else(|| {
                        (
                            if a.signum() < 0 {
                                f64::NEG_INFINITY
                            } else {
                                f64::INFINITY
                            },
                            f64::INFINITY,
                        )
                    })
            }
        }
    }

    /// Exact sign.
    pub fn signum(&self) -> i32 {
        match self {
            Exact::Quad(x) => x.signum(),
            Exact::Alg(a) => a.signum(),
        }
    }

    /// A rational approximation within `2^-bits`.
    pub fn to_rational_approx(&self, bits: u32) -> Q {
        match self {
            Exact::Quad(x) => x.to_rational_approx(bits),
            Exact::Alg(a) => a.to_rational_approx(bits),
        }
    }

    /// Exact equality (same field or via algebraic comparison).
    pub fn equals(&self, other: &Exact) -> bool {
        match (self, other) {
            (Exact::Quad(a), Exact::Quad(b))
                if a.is_rational() || b.is_rational() || a.d == b.d =>
            {
                a.cmp_exact(b) == std::cmp::Ordering::Equal
            }
            _ => self.to_alg().cmp_exact(&other.to_alg()) == std::cmp::Ordering::Equal,
        }
    }

    /// As a real algebraic number.
    pub fn to_alg(&self) -> RealAlg {
        match self {
            Exact::Alg(a) => a.clone(),
            Exact::Quad(x) if x.is_rational() => RealAlg::rational(x.a.clone()),
            Exact::Quad(x) => {
                // root of (u − a)² − b² d
                let p = QPoly::new(vec![
                    &x.a * &x.a - &x.b * &x.b * &x.d,
                    -(&x.a * Q::from_integer(2.into())),
                    Q::one(),
                ]);
                let (z, _) = ZPoly::from_q(&p);
                let enclose = |bits: u32| {
                    let c = x.to_rational_approx(bits + 2);
                    let e = Q::new(BigInt::one(), BigInt::one() << (bits as usize));
                    (&c - &e, &c + &e)
                };
                identify_root(&z, &enclose)
            }
        }
    }
}

/// A point with exact coordinates.
pub type EPoint = [Exact; 3];

impl std::fmt::Display for Exact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Exact::Quad(x) => write!(f, "{}", x.normalized()),
            Exact::Alg(a) => write!(f, "{a}"),
        }
    }
}

impl PartialEq for Exact {
    /// Exact equality.
    fn eq(&self, other: &Exact) -> bool {
        self.equals(other)
    }
}

/// Lifts a Q(√d) vector.
pub fn epoint(v: &[QSqrt; 3]) -> EPoint {
    std::array::from_fn(|i| Exact::Quad(v[i].clone()))
}

/// A direction with rational components scaled to a primitive integer
/// vector (first non-zero component positive); other directions unchanged.
pub fn normalize_direction(d: &EPoint) -> EPoint {
    if !d
        .iter()
        .all(|c| matches!(c, Exact::Quad(x) if x.is_rational()))
    {
        return d.clone();
    }
    let p = primitive_direction(d);
    if p.iter()
        .find(|c| c.signum() != 0)
        .is_some_and(|c| c.signum() < 0)
    {
        std::array::from_fn(|i| match &p[i] {
            Exact::Quad(x) => Exact::Quad(x.neg()),
            other => other.clone(),
        })
    } else {
        p
    }
}

/// A conic's axis direction as printed: as [`normalize_direction`], except
/// that a parabola's axis keeps its orientation (it points into the
/// parabola: scaled by a positive rational only).
pub fn normalize_axis_direction(d: &EPoint, kind: super::result::ConicKind) -> EPoint {
    let rational = d
        .iter()
        .all(|c| matches!(c, Exact::Quad(x) if x.is_rational()));
    match kind {
        super::result::ConicKind::Parabola if rational => primitive_direction(d),
        super::result::ConicKind::Parabola => d.clone(),
        _ => normalize_direction(d),
    }
}

/// A direction scaled by a positive rational so that its coordinates,
/// all in one field Q(√d), have coprime integer parts `a`, `b` (the
/// orientation kept: a parabola's axis points into it); directions with
/// a coordinate outside a common Q(√d) unchanged.  Constructions over Z
/// leave directions with products of the inputs' denominators in them
/// (10³⁰⁰ for 53-bit inputs); this keeps them the size of the inputs.
pub(crate) fn primitive_direction(v: &EPoint) -> EPoint {
    let mut field: Option<&Q> = None;
    let mut parts: Vec<&Q> = Vec::with_capacity(6);
    for c in v {
        let Exact::Quad(x) = c else { return v.clone() };
        if !x.is_rational() {
            match field {
                Some(d) if d != &x.d => return v.clone(),
                _ => field = Some(&x.d),
            }
        }
        parts.push(&x.a);
        parts.push(&x.b);
    }
    let l = crate::number::denom_lcm(parts.iter().copied());
    // (Lehmer's gcd and cross-reduced products: num-bigint's binary gcd
    // was most of this on long decimals)
    let mut g = BigInt::zero();
    for q in &parts {
        if g.is_one() {
            break;
        }
        g = crate::number::gcd_z(&g, &(q.numer() * (&l / q.denom())));
    }
    if g.is_zero() {
        return v.clone();
    }
    let k = crate::number::q_new(l, g);
    let mul = crate::number::q_mul;
    std::array::from_fn(|i| match &v[i] {
        Exact::Quad(x) if x.is_rational() => Exact::Quad(QSqrt::rational(mul(&x.a, &k))),
        Exact::Quad(x) => Exact::Quad(QSqrt::from_parts_nonsquare(
            mul(&x.a, &k),
            mul(&x.b, &k),
            x.d.clone(),
        )),
        other => other.clone(),
    })
}

/// A plane with rational coefficients scaled to primitive integers (the
/// normal as by [`normalize_direction`], the offset by the same factor);
/// other planes unchanged.  The JSON and the C interface print planes so.
pub fn normalize_plane(p: &Plane) -> (EPoint, Exact) {
    let rat: Option<Vec<&Q>> = p
        .normal
        .iter()
        .chain(std::iter::once(&p.offset))
        .map(|c| match c {
            Exact::Quad(x) if x.is_rational() => Some(&x.a),
            _ => None,
        })
        .collect();
    let Some(rat) = rat else {
        return (p.normal.clone(), p.offset.clone());
    };
    // in integers: the normal times the lcm l of its denominators, divided
    // by the gcd g of those integers, the sign making the first non-zero
    // coordinate positive; the offset times the same k = ±l/g
    let l = crate::number::denom_lcm(rat[..3].iter().copied());
    let ints: [BigInt; 3] = std::array::from_fn(|i| rat[i].numer() * (&l / rat[i].denom()));
    let mut g = BigInt::zero();
    for v in &ints {
        if g.is_one() {
            break;
        }
        g = crate::number::gcd_z(&g, v);
    }
    if g.is_zero() {
        return (p.normal.clone(), p.offset.clone());
    }
    if ints
        .iter()
        .find(|v| !v.is_zero())
        .is_some_and(|v| v.is_negative())
    {
        g = -g;
    }
    let n: EPoint = std::array::from_fn(|i| Exact::rational(Q::from_integer(&ints[i] / &g)));
    let offset = crate::number::q_new(rat[3].numer() * &l, rat[3].denom() * &g);
    (n, Exact::rational(offset))
}

/// Text of a point.
pub fn epoint_text(p: &EPoint) -> String {
    format!(
        "({})",
        p.iter().map(|c| c.text()).collect::<Vec<_>>().join(", ")
    )
}

/// Exact equality of points.
pub fn epoint_equal(p: &EPoint, q: &EPoint) -> bool {
    (0..3).all(|i| p[i].equals(&q[i]))
}

/// The root of the square-free `r` that lies in the enclosures
/// `enclose(bits)` (which must shrink to it as `bits` grows).
pub fn identify_root(r: &ZPoly, enclose: &dyn Fn(u32) -> (Q, Q)) -> RealAlg {
    let sq = r.squarefree_part();
    let mut ivs = isolate_squarefree(&sq);
    let mut bits = 16;
    loop {
        let (lo, hi) = enclose(bits);
        let hits: Vec<usize> = (0..ivs.len())
            .filter(|&j| {
                let iv = &ivs[j];
                if iv.is_exact() {
                    lo <= iv.lo && iv.lo <= hi
                } else {
                    iv.lo < hi && lo < iv.hi
                }
            })
            .collect();
        if hits.len() == 1 {
            return RealAlg::from_interval(&sq, &ivs[hits[0]]).simplify();
        }
        for j in hits {
            crate::roots::bisect_once(&sq, &mut ivs[j]);
        }
        bits += 16;
    }
}

pub use crate::number::sqrt_bounds;

/// `a + b√d + m·s·√(α + β√d)` (s = ±1) exactly, as a real algebraic number
/// (or in Q(√·) when no nesting happens).  Requires `α + β√d > 0`.
pub fn nested(a: &Q, b: &Q, d: &Q, m: &Q, alpha: &Q, beta: &Q, s: i32) -> Exact {
    let inner = QSqrt::new(alpha.clone(), beta.clone(), d.clone());
    if m.is_zero() || inner.is_zero() {
        return Exact::Quad(QSqrt::new(a.clone(), b.clone(), d.clone()));
    }
    if inner.is_rational() && (b.is_zero() || d.is_zero()) {
        // a + m s √alpha'
        let ms = if s < 0 { -m } else { m.clone() };
        return Exact::Quad(QSqrt::new(a.clone(), ms, inner.a.clone()));
    }
    if let Some(r) = QSqrt::sqrt_of_rational_in(&inner.a, d).filter(|_| inner.b.is_zero()) {
        // √alpha lies in Q(√d)
        let t = r.scale(&(if s < 0 { -m } else { m.clone() }));
        return Exact::Quad(QSqrt::new(a.clone(), b.clone(), d.clone()).add(&t));
    }
    // c = a + b·y + m·s·μ with y² = d, μ² = α + β·y: (c − a − b y)² =
    // m²(α + β y) is P(c) + y·Q(c) = 0 with P = c² − 2ac + a² + b²d − m²α,
    // Q = −2bc + 2ab − m²β, so c is a root of the quartic P² − d·Q²
    // (computed over Z with the products of the denominators: no gcd until
    // the primitive part)
    let (na, da) = (a.numer(), a.denom());
    let (nb, db) = (b.numer(), b.denom());
    let (nm, dm) = (m.numer(), m.denom());
    let (nd, dd) = (d.numer(), d.denom());
    let (nal, dal) = (alpha.numer(), alpha.denom());
    let (nbe, dbe) = (beta.numer(), beta.denom());
    let (da2, db2, dm2) = (da * da, db * db, dm * dm);
    // P·D0 with D0 = da²·db²·dd·dm²·dal
    let d0 = &da2 * &db2 * dd * &dm2 * dal;
    let p0 = na * na * (&db2 * dd * &dm2 * dal) + nb * nb * nd * (&da2 * &dm2 * dal)
        - nm * nm * nal * (&da2 * &db2 * dd);
    let p1 = -(na * (&d0 / da)) * 2;
    let zp = ZPoly::new(vec![p0, p1, d0.clone()]);
    // Q·D1 with D1 = da·db·dm²·dbe
    let d1 = da * db * &dm2 * dbe;
    let q0 = na * nb * (&dm2 * dbe) * 2 - nm * nm * nbe * (da * db);
    let q1 = -(nb * (&d1 / db)) * 2;
    let zq = ZPoly::new(vec![q0, q1]);
    // (P² − d·Q²)·D0²·D1²·dd = dd·D1²·(P·D0)² − nd·D0²·(Q·D1)²
    let rz = &(&zp * &zp).scale(&(dd * &d1 * &d1)) - &(&zq * &zq).scale(&(nd * &d0 * &d0));
    let sq = rz.squarefree_part();
    // an enclosure of c holding exactly one root of the square-free quartic
    // (Descartes' rule on the interval: one sign variation): from double
    // balls first, then from rational bounds as they narrow; an isolation of
    // all roots only as the fallback
    let holds_one = |lo: &Q, hi: &Q| {
        lo < hi
            && sq.sign_at(lo) != 0
            && sq.sign_at(hi) != 0
            && crate::roots::descartes_in(&sq, lo, hi) == 1
    };
    // (a rational root is looked for only when a cheap sieve allows one)
    let irrational = crate::roots::no_rational_root_sieve(&sq);
    let done = |lo: Q, hi: Q| {
        let x = RealAlg::from_interval(&sq, &crate::roots::RootInterval { lo, hi });
        Exact::Alg(if irrational { x } else { x.simplify() })
    };
    let nb = nested_ball(a, b, d, m, alpha, beta, s);
    if let Some((lo, hi)) = nb
        && holds_one(&lo, &hi)
    {
        return done(lo, hi);
    }
    let enclose = |bits: u32| -> (Q, Q) {
        let (yl, yh) = sqrt_bounds(d, bits + 8);
        let (il, ih) = {
            let (p, q) = (alpha + beta * &yl, alpha + beta * &yh);
            if p < q { (p, q) } else { (q, p) }
        };
        let (ml, _) = sqrt_bounds(&il.clone().max(Q::zero()), bits + 8);
        let (_, mh) = sqrt_bounds(&ih.clone().max(Q::zero()), bits + 8);
        let ms = if s < 0 { -m } else { m.clone() };
        let cands = [
            a + b * &yl + &ms * &ml,
            a + b * &yl + &ms * &mh,
            a + b * &yh + &ms * &ml,
            a + b * &yh + &ms * &mh,
        ];
        let lo = cands.iter().min().cloned().unwrap_or_default();
        let hi = cands.iter().max().cloned().unwrap_or_default();
        (lo, hi)
    };
    for bits in [64u32, 128, 256, 512] {
        let (lo, hi) = enclose(bits);
        if holds_one(&lo, &hi) {
            return done(lo, hi);
        }
    }
    Exact::Alg(identify_root(&rz, &enclose))
}

/// An enclosure `[lo, hi]` (dyadic ends) of `a + b√d + m·s·√(α + β√d)`
/// from extended-exponent double balls, or `None` when a square root
/// cannot be certified.
fn nested_ball(a: &Q, b: &Q, d: &Q, m: &Q, alpha: &Q, beta: &Q, s: i32) -> Option<(Q, Q)> {
    let y = XBall::from_q(d).sqrt()?;
    let mu = XBall::from_q(alpha)
        .add(&XBall::from_q(beta).mul(&y))
        .sqrt()?;
    let ms = if s < 0 {
        XBall::from_q(m).neg()
    } else {
        XBall::from_q(m)
    };
    XBall::from_q(a)
        .add(&XBall::from_q(b).mul(&y))
        .add(&ms.mul(&mu))
        .bounds()
}

// ------------------------------------------------------ quadratic recognition

fn round_q(x: &Q) -> BigInt {
    (x + Q::new(BigInt::one(), BigInt::from(2)))
        .floor()
        .to_integer()
}

/// LLL reduction (δ = 3/4) of integer row vectors, with exact rational
/// Gram–Schmidt recomputed at each step (small dimensions only).
fn lll(mut b: Vec<Vec<BigInt>>) -> Vec<Vec<BigInt>> {
    let n = b.len();
    let delta = Q::new(BigInt::from(3), BigInt::from(4));
    let gs = |b: &Vec<Vec<BigInt>>| -> (Vec<Vec<Q>>, Vec<Q>) {
        let mut bs: Vec<Vec<Q>> = Vec::new();
        let mut mu = vec![vec![Q::zero(); n]; n];
        let mut bn: Vec<Q> = Vec::new();
        for i in 0..n {
            let mut v: Vec<Q> = b[i].iter().map(|x| Q::from_integer(x.clone())).collect();
            for j in 0..i {
                let num: Q = b[i]
                    .iter()
                    .zip(&bs[j])
                    .map(|(x, y)| Q::from_integer(x.clone()) * y)
                    .fold(Q::zero(), |a, c| a + c);
                mu[i][j] = if bn[j].is_zero() {
                    Q::zero()
                } else {
                    num / &bn[j]
                };
                for (vk, bsk) in v.iter_mut().zip(&bs[j]) {
                    *vk -= &mu[i][j] * bsk;
                }
            }
            bn.push(v.iter().map(|x| x * x).fold(Q::zero(), |a, c| a + c));
            bs.push(v);
        }
        (mu, bn)
    };
    let mut k = 1;
    let mut guard = 0;
    while k < n && guard < 100_000 {
        crate::budget::check();
        guard += 1;
        let (mut mu, bn) = gs(&b);
        for j in (0..k).rev() {
            let q = round_q(&mu[k][j]);
            if !q.is_zero() {
                let bj = b[j].clone();
                for (x, y) in b[k].iter_mut().zip(bj.iter()) {
                    *x -= &q * y;
                }
                let qq = Q::from_integer(q);
                for i in 0..j {
                    let t = &qq * &mu[j][i];
                    mu[k][i] -= t;
                }
                mu[k][j] -= &qq;
            }
        }
        if bn[k] >= (&delta - &mu[k][k - 1] * &mu[k][k - 1]) * &bn[k - 1] {
            k += 1;
        } else {
            b.swap(k, k - 1);
            k = (k - 1).max(1);
        }
    }
    b
}

/// `x` as `a + b√d` when it is a quadratic irrational (or rational),
/// verified exactly; `None` otherwise.
pub fn recognize_quadratic(x: &RealAlg) -> Option<QSqrt> {
    if let Some(q) = x.as_rational() {
        return Some(QSqrt::rational(q.clone()));
    }
    let p = x.poly();
    if p.degree() == Some(2) {
        return quad_root(&p, x);
    }
    let hb = p.coeffs().iter().map(|c| c.bits()).max().unwrap_or(1);
    for bits in [hb as u32 * 2 + 64, hb as u32 * 4 + 160] {
        let v = x.to_rational_approx(bits + 32);
        let scale = BigInt::one() << (bits as usize);
        let sc = |q: &Q| round_q(&(q * Q::from_integer(scale.clone())));
        let basis = vec![
            vec![BigInt::one(), BigInt::zero(), BigInt::zero(), sc(&Q::one())],
            vec![BigInt::zero(), BigInt::one(), BigInt::zero(), sc(&v)],
            vec![
                BigInt::zero(),
                BigInt::zero(),
                BigInt::one(),
                sc(&(&v * &v)),
            ],
        ];
        let red = lll(basis);
        for row in red.iter().take(2) {
            let q = ZPoly::new(vec![row[0].clone(), row[1].clone(), row[2].clone()]);
            if q.degree() == Some(2) && x.sign_of(&q) == 0 {
                return quad_root(&q.primitive_part(), x);
            }
            if q.degree() == Some(1) && x.sign_of(&q) == 0 {
                return Some(QSqrt::rational(Q::new(-q.coeff(0), q.coeff(1))));
            }
        }
    }
    None
}

fn quad_root(q: &ZPoly, x: &RealAlg) -> Option<QSqrt> {
    let (c0, c1, c2) = (q.coeff(0), q.coeff(1), q.coeff(2));
    let disc = &c1 * &c1 - BigInt::from(4) * &c2 * &c0;
    let a = Q::new(-c1, BigInt::from(2) * &c2);
    let b = Q::new(BigInt::one(), BigInt::from(2) * &c2);
    let (lo, hi) = x.interval();
    // exactly one root of q lies in x's isolating interval (q divides the
    // minimal polynomial of x)
    for s in [1i64, -1] {
        let cand = QSqrt::new(
            a.clone(),
            &b * Q::from_integer(s.into()),
            Q::from_integer(disc.clone()),
        );
        let inside = cand.cmp_exact(&QSqrt::rational(lo.clone())) == std::cmp::Ordering::Greater
            && cand.cmp_exact(&QSqrt::rational(hi.clone())) == std::cmp::Ordering::Less;
        if inside {
            return Some(cand.normalized());
        }
    }
    None
}

/// A real algebraic coordinate as an [`Exact`], in Q(√d) when possible.
pub fn exact_of(x: &RealAlg) -> Exact {
    match recognize_quadratic(x) {
        Some(q) => Exact::Quad(q),
        None => Exact::Alg(x.clone()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{q, qi};
    use num_traits::Signed;

    #[test]
    fn recognizes_quadratics_inside_larger_polynomials() {
        // root (1 + √2)/3 of (9x² − 6x − 1)(x³ − 2)
        let p = &ZPoly::from_i64s(&[-1, -6, 9]) * &ZPoly::from_i64s(&[-2, 0, 0, 1]);
        let roots = RealAlg::roots_of(&p);
        let target = roots
            .iter()
            .find(|r| {
                r.cmp_rational(&q(8, 10)) == std::cmp::Ordering::Equal
                    || (r.to_rational_approx(30) - q(8047, 10000)).abs() < q(1, 1000)
            })
            .unwrap();
        let got = recognize_quadratic(target).unwrap();
        assert_eq!(
            got.cmp_exact(&QSqrt::new(q(1, 3), q(1, 3), qi(2))),
            std::cmp::Ordering::Equal
        );
        // 2^(1/3) is not quadratic
        let cbrt = roots
            .iter()
            .find(|r| (r.to_rational_approx(30) - q(126, 100)).abs() < q(1, 100))
            .unwrap();
        assert!(recognize_quadratic(cbrt).is_none());
    }

    #[test]
    fn nested_radicals() {
        // 1 + √(3 + √2) ≈ 3.1010
        let e = nested(&qi(1), &qi(0), &qi(2), &qi(1), &qi(3), &qi(1), 1);
        assert!(matches!(e, Exact::Alg(_)));
        assert_eq!(e.approx(5), "3.101");
    }
}
