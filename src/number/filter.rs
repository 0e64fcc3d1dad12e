//! Filtered exact sign computations: one division-free program, run in
//! three number types in turn (STYLE: filters first).
//!
//! A predicate written once against [`SignRing`] is evaluated first with
//! [`Fe`] (an `f64` with a running error bound), then, if some sign was too
//! close to zero to be decided, with [`Ck`] (checked `i128`), and finally with
//! [`BigInt`], which always decides.  The first two answer `None` from
//! [`SignRing::sign`] when they cannot certify a sign (near zero for `Fe`,
//! overflow for `Ck`); the program then returns `None` and the caller moves
//! to the next tier.  So no sign is ever guessed: a tier either proves the
//! sign or declines.
//!
//! **Integer-valued programs only.**  Every quantity must be a polynomial
//! with integer coefficients in integer inputs (the callers clear
//! denominators once).  This is what lets [`Fe`] certify zero: an integer
//! within distance `< 1/2` of 0 is 0.
//!
//! **The error bound of [`Fe`]** (docs/maths.md, "Floating-point filters").
//! Each value carries `v` (the computed value), `a` (the computed value of
//! the same program with every input replaced by its absolute value and
//! every subtraction by an addition — the *permanent*), and `k`, the
//! largest number of roundings on a path from the inputs: an input converted
//! with rounding has `k = 2` (exact conversions `k = 0`), `x ± y` has
//! `max(k_x, k_y) + 1` and `x·y` has `k_x + k_y + 1`.  With `u = 2^-53` and
//! round-to-nearest, each operation satisfies `fl(x∘y) = (x∘y)(1 + δ)`,
//! `|δ| ≤ u` (no underflow: every computed value is an integer-valued
//! float, so non-zero values have magnitude ≥ 1).  Expanding the program,
//! the computed value is `Σ t·(1 + θ_t)` over the terms t of its expansion
//! with `|θ_t| ≤ γ_k = ku/(1 − ku)` (Higham, *Accuracy and Stability of
//! Numerical Algorithms*, Lemma 3.1), so `|v − y| ≤ γ_k·Σ|t|`; the computed
//! permanent satisfies `a ≥ (1 − γ_k)·Σ|t|`.  Hence
//! `|v − y| ≤ γ_k/(1 − γ_k)·a = ku/(1 − 2ku)·a ≤ (k + 1)·u·a·(1 − u)`
//! for `k ≤ 2^20`, and the rounded product `fl((k + 1)u·a)` is an upper
//! bound `b` of the error.  The sign is then decided as
//!
//! * `v > b` ⇒ `y > 0`, `v < −b` ⇒ `y < 0`;
//! * otherwise, if `2b < 1`, then `|y| ≤ |v| + b ≤ 2b < 1` and `y` is an
//!   integer, so `y = 0`;
//! * otherwise undecided.
//!
//! Overflow makes `a` infinite or NaN (the permanent dominates every
//! intermediate by monotonicity of rounding), and every comparison with it
//! fails: undecided.

use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};

/// A commutative ring of integers in which the sign of a value can be
/// asked; [`Fe`] and [`Ck`] may decline (`None`).
pub(crate) trait SignRing: Clone {
    /// The integer `z` (rounded for [`Fe`], `None`-valued on overflow for [`Ck`]).
    fn from_z(z: &BigInt) -> Self;
    /// A small integer constant (exact in every tier).
    fn int(v: i64) -> Self;
    /// `self + o`.
    fn add(&self, o: &Self) -> Self;
    /// `self − o`.
    fn sub(&self, o: &Self) -> Self;
    /// `self · o`.
    fn mul(&self, o: &Self) -> Self;
    /// `−self`.
    fn neg(&self) -> Self;
    /// The sign (−1, 0, 1), or `None` when this tier cannot certify it.
    fn sign(&self) -> Option<i32>;
    /// A floating-point approximation (for choosing sample points only,
    /// never for a decision).
    fn approx(&self) -> f64;
    /// The exact value, when this tier knows it.
    fn exact(&self) -> Option<BigInt>;
}

/// `u = 2^-53`, the unit roundoff of `f64`.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;

/// The error bound of a value with permanent `a` and `k` roundings, or
/// infinity when `k` is too large for the derivation (`k ≤ 2^20`).
#[inline]
pub(crate) fn fe_bound(a: f64, k: u32) -> f64 {
    if k > 1 << 20 {
        return f64::INFINITY;
    }
    ((k + 1) as f64 * U) * a
}

/// The sign of an integer-valued quantity computed as `v` with error at
/// most `b` (see the module docs), or `None`.
#[inline]
pub(crate) fn sign_with_bound(v: f64, b: f64) -> Option<i32> {
    if v > b {
        Some(1)
    } else if v < -b {
        Some(-1)
    } else if 2.0 * b < 1.0 && !v.is_nan() {
        Some(0)
    } else {
        None
    }
}

/// An `f64` with its permanent and rounding count (the filter tier).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fe {
    /// Computed value.
    pub v: f64,
    /// Computed permanent (≥ 0).
    pub a: f64,
    /// Roundings on the longest path.
    pub k: u32,
}

impl Fe {
    /// An input integer given as an `f64` that is exact (`k = 0`) or the
    /// nearest double of it (`k = 1`); conversions that may be off by more
    /// than half an ulp must use `k = 2`.
    #[inline]
    pub fn input(v: f64, k: u32) -> Fe {
        Fe { v, a: v.abs(), k }
    }
}

/// `z` as an `f64` within a relative error `2u` (exact when `|z| < 2^53`),
/// with the rounding count to use (`0` exact, `2` otherwise).
pub(crate) fn z_to_f64(z: &BigInt) -> (f64, u32) {
    if let Some(v) = z.to_i64()
        && v.unsigned_abs() < (1u64 << 53)
    {
        return (v as f64, 0);
    }
    // the leading 64 bits (truncated: relative error < 2^-63) rounded once
    // to 53 bits, then scaled exactly by a power of two
    let bits = z.bits();
    if bits > 1100 {
        return (
            if z.is_negative() {
                -f64::INFINITY
            } else {
                f64::INFINITY
            },
            2,
        );
    }
    let shift = bits.saturating_sub(64);
    let top = (z.magnitude() >> shift).to_u64().unwrap_or(u64::MAX) as f64;
    let v = top * 2f64.powi(shift as i32);
    (if z.is_negative() { -v } else { v }, 2)
}

impl SignRing for Fe {
    fn from_z(z: &BigInt) -> Self {
        let (v, k) = z_to_f64(z);
        Fe::input(v, k)
    }
    #[inline]
    fn int(v: i64) -> Self {
        debug_assert!(v.unsigned_abs() < 1 << 53);
        Fe::input(v as f64, 0)
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        Fe {
            v: self.v + o.v,
            a: self.a + o.a,
            k: self.k.max(o.k) + 1,
        }
    }
    #[inline]
    fn sub(&self, o: &Self) -> Self {
        Fe {
            v: self.v - o.v,
            a: self.a + o.a,
            k: self.k.max(o.k) + 1,
        }
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        Fe {
            v: self.v * o.v,
            a: self.a * o.a,
            k: self.k + o.k + 1,
        }
    }
    #[inline]
    fn neg(&self) -> Self {
        Fe {
            v: -self.v,
            a: self.a,
            k: self.k,
        }
    }
    #[inline]
    fn sign(&self) -> Option<i32> {
        sign_with_bound(self.v, fe_bound(self.a, self.k))
    }
    fn approx(&self) -> f64 {
        self.v
    }
    fn exact(&self) -> Option<BigInt> {
        None
    }
}

/// A checked `i128`: `None` once an operation overflowed (sticky).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ck(pub Option<i128>);

impl SignRing for Ck {
    fn from_z(z: &BigInt) -> Self {
        Ck(z.to_i128())
    }
    #[inline]
    fn int(v: i64) -> Self {
        Ck(Some(v as i128))
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        Ck(self.0.zip(o.0).and_then(|(x, y)| x.checked_add(y)))
    }
    #[inline]
    fn sub(&self, o: &Self) -> Self {
        Ck(self.0.zip(o.0).and_then(|(x, y)| x.checked_sub(y)))
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        Ck(self.0.zip(o.0).and_then(|(x, y)| x.checked_mul(y)))
    }
    #[inline]
    fn neg(&self) -> Self {
        Ck(self.0.and_then(|x| x.checked_neg()))
    }
    #[inline]
    fn sign(&self) -> Option<i32> {
        self.0.map(|x| x.signum() as i32)
    }
    fn approx(&self) -> f64 {
        self.0.map_or(f64::NAN, |x| x as f64)
    }
    fn exact(&self) -> Option<BigInt> {
        self.0.map(BigInt::from)
    }
}

impl SignRing for BigInt {
    fn from_z(z: &BigInt) -> Self {
        z.clone()
    }
    fn int(v: i64) -> Self {
        BigInt::from(v)
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        if self.is_zero() || o.is_zero() {
            return BigInt::zero();
        }
        self * o
    }
    fn neg(&self) -> Self {
        -self
    }
    fn sign(&self) -> Option<i32> {
        Some(super::sign_z(self))
    }
    fn approx(&self) -> f64 {
        z_to_f64(self).0
    }
    fn exact(&self) -> Option<BigInt> {
        Some(self.clone())
    }
}

/// `Σ xᵢ·yᵢ`.
pub(crate) fn dot<R: SignRing>(x: &[R], y: &[R]) -> R {
    let mut acc = x[0].mul(&y[0]);
    for i in 1..x.len() {
        acc = acc.add(&x[i].mul(&y[i]));
    }
    acc
}

/// `x × y` in three dimensions.
pub(crate) fn cross<R: SignRing>(x: &[R; 3], y: &[R; 3]) -> [R; 3] {
    [
        x[1].mul(&y[2]).sub(&x[2].mul(&y[1])),
        x[2].mul(&y[0]).sub(&x[0].mul(&y[2])),
        x[0].mul(&y[1]).sub(&x[1].mul(&y[0])),
    ]
}

/// True when every component is zero (`None`: undecided).
pub(crate) fn all_zero<R: SignRing>(x: &[R]) -> Option<bool> {
    for c in x {
        if c.sign()? != 0 {
            return Some(false);
        }
    }
    Some(true)
}

/// Runs an integer-valued program in the three tiers in turn: the filter,
/// checked `i128`, and big integers (which always decide).
pub(crate) fn tiered<T>(
    fe: impl FnOnce() -> Option<T>,
    ck: impl FnOnce() -> Option<T>,
    big: impl FnOnce() -> T,
) -> T {
    if let Some(t) = fe() {
        return t;
    }
    if let Some(t) = ck() {
        return t;
    }
    big()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn z(s: &str) -> BigInt {
        s.parse().unwrap()
    }

    /// A program evaluated in all three tiers: `x·y − w·t`.
    fn det2<R: SignRing>(x: &R, y: &R, w: &R, t: &R) -> R {
        x.mul(y).sub(&w.mul(t))
    }

    #[test]
    fn filter_decides_far_from_zero_and_exact_small_zeros() {
        let s = |a: i64, b: i64, c: i64, d: i64| {
            det2(&Fe::int(a), &Fe::int(b), &Fe::int(c), &Fe::int(d)).sign()
        };
        assert_eq!(s(3, 4, 2, 5), Some(1));
        assert_eq!(s(2, 5, 3, 4), Some(-1));
        // exactly zero with small operands: the bound is < 1/2
        assert_eq!(s(6, 4, 3, 8), Some(0));
    }

    #[test]
    fn filter_refuses_near_zero_with_large_operands() {
        // (2^40 + 1)(2^40 − 1) − 2^80 = −1: the computed products round
        // (2^80 − 1 is not a double), the filter must not decide, and the
        // exact tiers give −1
        let p = z("1099511627777");
        let m = z("1099511627775");
        let t = z("1099511627776");
        let f = det2(
            &Fe::from_z(&p),
            &Fe::from_z(&m),
            &Fe::from_z(&t),
            &Fe::from_z(&t),
        );
        assert_eq!(f.sign(), None);
        let c = det2(
            &Ck::from_z(&p),
            &Ck::from_z(&m),
            &Ck::from_z(&t),
            &Ck::from_z(&t),
        );
        assert_eq!(c.sign(), Some(-1));
        assert_eq!(SignRing::sign(&det2(&p, &m, &t, &t)), Some(-1));
        // exactly zero with large operands: undecided by the filter
        let f0 = det2(
            &Fe::from_z(&p),
            &Fe::from_z(&m),
            &Fe::from_z(&p),
            &Fe::from_z(&m),
        );
        assert_eq!(f0.sign(), None);
    }

    #[test]
    fn filter_boundary_cases() {
        // a value exactly at the error bound is not decided by the
        // inequality; 2b < 1 decides zero only for an exactly computed 0
        let b = fe_bound(1.0, 0);
        assert_eq!(sign_with_bound(b, b), Some(0)); // 2b < 1: |y| < 1 ⇒ y = 0
        assert_eq!(sign_with_bound(0.5, 0.5), None); // |y| ≤ 1 could be ±1
        assert_eq!(sign_with_bound(0.50000001, 0.5), Some(1));
        assert_eq!(sign_with_bound(-0.5, 0.25), Some(-1));
        assert_eq!(sign_with_bound(0.25, 0.25), Some(0)); // |y| ≤ 0.5: y = 0
        assert_eq!(sign_with_bound(f64::NAN, 0.0), None);
        assert_eq!(sign_with_bound(1.0, f64::INFINITY), None);
        assert_eq!(sign_with_bound(1.0, f64::NAN), None);
    }

    #[test]
    fn checked_tier_declines_on_overflow() {
        let big = Ck::from_z(&(BigInt::from(1u8) << 100usize));
        assert_eq!(big.mul(&big).sign(), None);
        assert_eq!(big.sign(), Some(1));
        assert_eq!(Ck::from_z(&(BigInt::from(1u8) << 200usize)).sign(), None);
    }

    #[test]
    fn conversion_error_is_within_two_ulps() {
        for s in [
            "123456789012345678901234567890",
            "-98765432109876543210987654321098765",
            "9007199254740993",
            "18446744073709551615",
        ] {
            let x = z(s);
            let (v, k) = z_to_f64(&x);
            assert_eq!(k, 2);
            let exact = num_rational::BigRational::from_integer(x.clone());
            let back = num_rational::BigRational::from_float(v).unwrap();
            let err = (exact.clone() - back).abs();
            let rel = err / exact.abs();
            let two_u = num_rational::BigRational::new(1.into(), BigInt::from(1u8) << 52usize);
            assert!(rel <= two_u, "{s}");
        }
    }

    proptest::proptest! {
        /// Whenever the filter decides the sign of a random integer
        /// polynomial program, it is the exact sign.
        #[test]
        fn filter_never_lies(xs in proptest::collection::vec(-(1i64 << 40)..(1i64 << 40), 6),
                             shift in 0u32..30) {
            let big: Vec<BigInt> = xs.iter().map(|&x| BigInt::from(x) << shift as usize).collect();
            let prog = |v: &[BigInt]| -> (Option<i32>, i32) {
                let f: Vec<Fe> = v.iter().map(Fe::from_z).collect();
                let e = |r: &[Fe]| r[0].mul(&r[1]).mul(&r[2]).sub(&r[3].mul(&r[4]).mul(&r[5]));
                let ex = |r: &[BigInt]| &r[0] * &r[1] * &r[2] - &r[3] * &r[4] * &r[5];
                (e(&f).sign(), crate::number::sign_z(&ex(v)))
            };
            let (fs, es) = prog(&big);
            if let Some(s) = fs { proptest::prop_assert_eq!(s, es); }
            // a near-cancelling instance: x0 x1 x2 − x0 x1 x2 ± small
            let mut w = big.clone();
            w[3] = w[0].clone(); w[4] = w[1].clone(); w[5] = &w[2] + BigInt::from(xs[5].signum());
            let (fs, es) = prog(&w);
            if let Some(s) = fs { proptest::prop_assert_eq!(s, es); }
        }
    }
}
