//! Witness points: exact points of E with two rational coordinates and the
//! third in Q(√d), on which the sign of S is decided exactly.
//!
//! Lemma 1 of the paper: two points of E with S of opposite signs prove that
//! E and S intersect (E is connected).  A witness is built from a rational
//! approximation of a point of E by solving E = 0 for the coordinate along
//! which E's gradient is largest (so the discriminant stays positive).

use super::ellipsoid::Ellipsoid;
use crate::geom::{Mat4, common_denominator};
use crate::number::{Q, QSqrt};
use crate::poly::QMPoly;
use crate::roots::RealAlg;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// A point of E: coordinates in Q(√d) (at most one irrational coordinate).
#[derive(Clone, Debug)]
pub struct WitnessPoint {
    /// The coordinates x, y, z.
    pub(crate) coords: [QSqrt; 3],
    /// S at the point, exactly.
    pub(crate) value: QSqrt,
    /// Its sign (-1, 0, 1).
    pub(crate) sign: i32,
}

impl WitnessPoint {
    /// The coordinates x, y, z (exact, in Q(√d)); E vanishes there exactly.
    pub fn coords(&self) -> &[QSqrt; 3] {
        &self.coords
    }

    /// The value of S at the point, exactly.
    pub fn value(&self) -> &QSqrt {
        &self.value
    }

    /// The sign of S at the point.
    pub fn sign(&self) -> crate::number::Sign {
        crate::number::Sign::from_i32(self.sign)
    }
}

/// Projects a rational point near E onto E along the coordinate axis of the
/// largest gradient component; `None` if that line misses E.
#[cfg(test)]
pub fn snap_to_ellipsoid(e: &Ellipsoid, p: &[Q; 3]) -> Option<[QSqrt; 3]> {
    let g = e.form.half_gradient(p);
    let mut k = 0;
    for i in 1..3 {
        if g[i].abs() > g[k].abs() {
            k = i;
        }
    }
    let a = &e.form.a;
    // E restricted to the line p + s·e_k:  a_kk s² + 2 h s + c0 (in the coordinate x_k = s)
    let mut h = e.form.b[k].clone();
    for j in 0..3 {
        if j != k {
            h += &a[k][j] * &p[j];
        }
    }
    let mut c0 = e.form.c.clone();
    for i in 0..3 {
        if i == k {
            continue;
        }
        c0 += &e.form.b[i] * &p[i] * Q::from_integer(2.into());
        for j in 0..3 {
            if j != k {
                c0 += &a[i][j] * &p[i] * &p[j];
            }
        }
    }
    let akk = &a[k][k];
    let disc = &h * &h - akk * &c0;
    if disc.is_negative() {
        return None;
    }
    // root closer to p_k: sign of (akk p_k + h)
    let s = if (akk * &p[k] + &h).is_negative() {
        -1
    } else {
        1
    };
    let root = QSqrt::new(-&h / akk, Q::from_integer(s.into()) / akk, disc);
    let mut out: [QSqrt; 3] = std::array::from_fn(|i| QSqrt::rational(p[i].clone()));
    out[k] = root.normalized();
    Some(out)
}

/// The witness search shared by the analyses of critical values: a point
/// of E with S of sign `want` near a real critical point whose value is
/// `v` (exactly on E, its sign checked exactly).  `None` when the
/// analysis has no such point to start from.
pub(crate) trait WitnessSearch {
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint>;
}

/// A witness near the real critical point whose exact value is `value`,
/// given the values of the real critical points in order and, for the i-th
/// one, an approximation of the point to `bits` bits (`approx(i, bits)`).
pub fn witness_at_value(
    values: &[RealAlg],
    value: &RealAlg,
    e: &Ellipsoid,
    s: &QMPoly,
    want: i32,
    approx: &dyn Fn(usize, u32) -> Option<[Q; 3]>,
) -> Option<WitnessPoint> {
    let i = values
        .iter()
        .position(|v| v.cmp_exact(value) == std::cmp::Ordering::Equal)?;
    find_witness(e, s, want, false, &|bits| approx(i, bits))
}

/// Tries to turn approximations of a point of E (given for increasing
/// precision by `approx(bits)`) into a witness on which S has the sign
/// `want`.  With `coarse_first`, `approx(0)` is tried first: the caller's
/// cheapest approximation, whatever its precision.  Gives up after 2^10
/// bits.
pub fn find_witness(
    e: &Ellipsoid,
    s: &QMPoly,
    want: i32,
    coarse_first: bool,
    approx: &dyn Fn(u32) -> Option<[Q; 3]>,
) -> Option<WitnessPoint> {
    let fast = IntegerData::new(e, s);
    if coarse_first
        && let Some(p) = approx(0)
        && let Some(w) = fast.witness(&round_point(&p, 8), Some(want))
    {
        return Some(w);
    }
    let mut bits = 8;
    while bits <= 1024 {
        crate::budget::check_now();
        if let Some(p) = approx(bits + 16)
            && let Some(w) = fast.witness(&round_point(&p, bits), Some(want))
        {
            return Some(w);
        }
        bits *= 2;
    }
    None
}

/// Replaces each coordinate by a simplest rational within `2^-bits`, so
/// that witnesses have short coordinates.
fn round_point(p: &[Q; 3], bits: u32) -> [Q; 3] {
    std::array::from_fn(|i| {
        // X = ⌊x·2^k⌋ with k = bits + 2 (one division): x ∈ [X, X+1)/2^k,
        // so [(X − 3)/2^k, (X + 3)/2^k] lies within 2^-bits of x, and its
        // continued fraction runs on integers of about k + log|x| bits
        let k = bits as usize + 2;
        let x = num_integer::Integer::div_floor(&(p[i].numer() << k), p[i].denom());
        let den = BigInt::one() << k;
        crate::roots::simplest_rational_in(
            &Q::new_raw(&x - 3, den.clone()),
            &Q::new_raw(x + 3, den),
        )
    })
}

/// An exact point of E with S evaluated there (for the sampling checks and
/// the side of S when no critical point is needed).
pub fn witness_at(e: &Ellipsoid, s: &QMPoly, p: &[Q; 3]) -> Option<WitnessPoint> {
    IntegerData::new(e, s).witness(p, None)
}

/// E and S in integers, for the inner loop of the witness search: the
/// snapping of a rational point onto E and the exact sign of S there use
/// integer arithmetic in Z[√Δ] only (no rational normalisation), and the
/// exact Q(√d) coordinates and value are built once, for the answer.
struct IntegerData {
    /// The 4×4 matrix of L·E (E oriented, so `m[k][k] > 0`).
    m: Mat4,
    /// S times the lcm of its denominators: (exponents, integer coefficient).
    s_terms: Vec<([u32; 3], BigInt)>,
    /// That lcm (> 0).
    s_den: BigInt,
    /// Total degree of S.
    s_deg: u32,
}

impl IntegerData {
    fn new(e: &Ellipsoid, s: &QMPoly) -> IntegerData {
        let l = common_denominator(&[&e.form]);
        let m = e.form.int_matrix(&l);
        let mut s_den = BigInt::one();
        for (_, c) in s.terms() {
            crate::number::lcm_assign(&mut s_den, c.denom());
        }
        let s_terms = s
            .terms()
            .iter()
            .map(|(ex, c)| ([ex[0], ex[1], ex[2]], c.numer() * (&s_den / c.denom())))
            .collect();
        let s_deg = s.total_degree().unwrap_or(0);
        IntegerData {
            m,
            s_terms,
            s_den,
            s_deg,
        }
    }

    /// Snaps `p` onto E along the axis of the largest gradient component
    /// (the root nearer to p) and evaluates S there; with `want`, only a
    /// point where S has that sign is returned.
    fn witness(&self, p: &[Q; 3], want: Option<i32>) -> Option<WitnessPoint> {
        let m = &self.m;
        // p = P / D with a common denominator D
        let mut dd = BigInt::one();
        for c in p {
            crate::number::lcm_assign(&mut dd, c.denom());
        }
        let pp: [BigInt; 3] = std::array::from_fn(|i| p[i].numer() * (&dd / p[i].denom()));
        // D·L·(A p + b): pick the axis of the largest |component|
        let grad: [BigInt; 3] = std::array::from_fn(|i| {
            (0..3).map(|j| &m[i][j] * &pp[j]).sum::<BigInt>() + &m[i][3] * &dd
        });
        let mut k = 0;
        for i in 1..3 {
            if grad[i].abs() > grad[k].abs() {
                k = i;
            }
        }
        let others: Vec<usize> = (0..3).filter(|&j| j != k).collect();
        // D²·L·E on the line x_k = T/D:  α T² + 2β T + γ
        let alpha = m[k][k].clone();
        let beta = &m[k][3] * &dd + others.iter().map(|&j| &m[k][j] * &pp[j]).sum::<BigInt>();
        let mut gamma = &m[3][3] * &dd * &dd;
        for &i in &others {
            gamma += BigInt::from(2) * &dd * &m[i][3] * &pp[i];
            for &j in &others {
                gamma += &m[i][j] * &pp[i] * &pp[j];
            }
        }
        let disc = &beta * &beta - &alpha * &gamma;
        if disc.is_negative() {
            return None;
        }
        // the root nearer to P_k: T = (−β + s√Δ)/α
        let s: i64 = if (&alpha * &pp[k] + &beta).is_negative() {
            -1
        } else {
            1
        };
        // D^deg·S'(x) = Σ C_j T^j  (S' = s_den·S)
        let n = self.s_terms.iter().map(|(ex, _)| ex[k]).max().unwrap_or(0) as usize;
        let mut cs = vec![BigInt::zero(); n + 1];
        for (ex, c) in &self.s_terms {
            crate::budget::check();
            let mut t = c.clone();
            for &j in &others {
                if ex[j] > 0 {
                    t *= num_traits::pow(pp[j].clone(), ex[j] as usize);
                }
            }
            let rest = self.s_deg - ex.iter().sum::<u32>();
            if rest > 0 {
                t *= num_traits::pow(dd.clone(), rest as usize);
            }
            cs[ex[k] as usize] += t;
        }
        // α^n · Σ C_j T^j = Σ C_j N^j α^(n−j), N = −β + s√Δ, in Z[√Δ]
        let (nr, ni) = (-&beta, BigInt::from(s));
        let (mut hr, mut hi) = (cs[n].clone(), BigInt::zero());
        let mut apow = BigInt::one();
        for j in (0..n).rev() {
            crate::budget::check();
            apow *= &alpha;
            let r = &hr * &nr + &hi * &ni * &disc;
            let i = &hr * &ni + &hi * &nr;
            hr = r + &cs[j] * &apow;
            hi = i;
        }
        let sign = sign_sqrt(&hr, &hi, &disc);
        if want.is_some_and(|w| w != sign) {
            return None;
        }
        // the exact answer, built once
        let ad = &alpha * &dd;
        let mut coords: [QSqrt; 3] = std::array::from_fn(|i| QSqrt::rational(p[i].clone()));
        coords[k] = QSqrt::new(
            Q::new(-&beta, ad.clone()),
            Q::new(BigInt::from(s), ad),
            Q::from_integer(disc.clone()),
        )
        .normalized();
        // S = h / (s_den · D^deg · α^n)
        let den = &self.s_den * num_traits::pow(dd.clone(), self.s_deg as usize) * &apow;
        let value = QSqrt::new(
            Q::new(hr, den.clone()),
            Q::new(hi, den),
            Q::from_integer(disc),
        )
        .normalized();
        debug_assert_eq!(value.signum(), sign);
        Some(WitnessPoint {
            coords,
            value,
            sign,
        })
    }
}

/// The sign of `a + b√d` (`d ≥ 0`), exactly.
fn sign_sqrt(a: &BigInt, b: &BigInt, d: &BigInt) -> i32 {
    let sg = |x: &BigInt| -> i32 {
        if x.is_positive() {
            1
        } else if x.is_negative() {
            -1
        } else {
            0
        }
    };
    let (sa, sb) = (sg(a), if d.is_zero() { 0 } else { sg(b) });
    if sb == 0 {
        return sa;
    }
    if sa == 0 || sa == sb {
        return sb;
    }
    match (a * a).cmp(&(b * b * d)) {
        std::cmp::Ordering::Greater => sa,
        std::cmp::Ordering::Less => sb,
        std::cmp::Ordering::Equal => 0,
    }
}
