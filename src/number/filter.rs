//! Filtered exact sign computations: one division-free program, run in
//! three number types in turn (STYLE: filters first).
//!
//! A predicate written once against [`SignRing`] is evaluated first with
//! [`Ball`] (an `f64` midpoint with a rigorous radius), then, if some sign
//! was too close to zero to be decided, with [`Ck`] (checked `i128`), and
//! finally with [`BigInt`], which always decides.  The first two answer
//! `None` from [`SignRing::sign`] when they cannot certify a sign (near
//! zero for a ball, overflow for `Ck`); the program then returns `None` and
//! the caller moves to the next tier.  So no sign is ever guessed: a tier
//! either proves the sign or declines.
//!
//! **Ball arithmetic** (docs/maths.md, "Floating-point filters").  A value
//! is a pair `(m, r)` with the invariant that the exact value y satisfies
//! `|y − m| ≤ r`.  With `u = 2^-53`, round-to-nearest gives
//! `|fl(s) − s| ≤ u·|fl(s)|` for a sum or product s whose result is normal;
//! a sum with a subnormal result is exact, a product with a subnormal
//! result is within `2^-1075`.  Hence
//!
//! * `x + y`: `m = fl(mx + my)`, exact radius `rx + ry + u|m|`;
//! * `x · y`: `m = fl(mx·my)`, exact radius
//!   `|mx|ry + rx|my| + rx·ry + u|m| + 2^-1075`;
//!
//! the radius formulas are themselves evaluated in round-to-nearest on
//! non-negative terms (at most 8 roundings, each by a factor ≥ `1 − u`), so
//! adding `2^-1070` (which also covers products of radii that underflow)
//! and multiplying by `1 + 2^-48 > (1 − u)^-9` makes the computed radius an
//! upper bound.  Overflow gives infinite or NaN radii, and no comparison
//! accepts them.
//!
//! **Deciding a sign.**  `m > r` ⇒ `y > 0`, `m < −r` ⇒ `y < 0`; `r = 0` and
//! `m = 0` ⇒ `y = 0`.  In an *integer-valued* program ([`Ball`] with
//! `INT = true`: every quantity an integer polynomial in integer inputs, the
//! callers clear denominators once) also `|m| + r < 1` ⇒ `y = 0`.  Programs
//! on the real inputs themselves ([`BallR`]: the doubles of the input, no
//! denominators cleared, so the magnitudes stay small) certify zero only
//! exactly.  Otherwise undecided.
//!
//! An input integer or rational is converted to the nearest double or
//! within two roundings (`r = 0` when exact, else `r = 4u|m|` — at most
//! five roundings for a quotient of converted integers take `r = 8u|m|`).

use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};

/// A commutative ring of integers in which the sign of a value can be
/// asked; [`Ball`] and [`Ck`] may decline (`None`).
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
    /// Divides the entries of a vector known up to a positive factor by
    /// their content, where that is cheap and exact (big integers: the
    /// degenerate conics of near-degenerate inputs carry contents of
    /// thousands of bits, which every later product would drag along).
    /// Signs and ratios are kept; the other tiers leave `xs` as it is.
    fn divide_content(_xs: &mut [Self]) {}
}

/// `u = 2^-53`, the unit roundoff of `f64`.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;
/// The inflation of computed radii: `1 + 2^-48`.
const INFL: f64 = 1.0 + 1.0 / 281_474_976_710_656.0;
/// The absolute term covering subnormal products: `2^-1070`.
const ETA: f64 = 1.0e-322;

/// The sign of an integer-valued quantity computed as `v` with error at
/// most `b`, or `None` (the integer rule of the module docs).
#[inline]
pub(crate) fn sign_with_bound(v: f64, b: f64) -> Option<i32> {
    if v > b {
        Some(1)
    } else if v < -b {
        Some(-1)
    } else if (v.abs() + b) * INFL < 1.0 {
        Some(0)
    } else {
        None
    }
}

/// A ball `(m, r)`: the exact value lies in `[m − r, m + r]` (the filter
/// tier).  `INT`: the program is integer-valued (zero is certified inside
/// `(−1, 1)`), else real-valued ([`BallR`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ball<const INT: bool = true> {
    /// Midpoint.
    pub m: f64,
    /// Radius (≥ 0).
    pub r: f64,
}

/// The filter on real-valued inputs (see the module docs).
pub(crate) type BallR = Ball<false>;

impl<const INT: bool> Ball<INT> {
    /// An input within `k` roundings of `m` (`k = 0`: exact).
    #[inline]
    pub fn input(m: f64, k: u32) -> Self {
        let r = if k == 0 {
            0.0
        } else {
            (2 * k) as f64 * U * m.abs() * INFL
        };
        Ball { m, r }
    }
}

/// `z` as an `f64` within a relative error `2u` (exact when it fits 53
/// bits), with the rounding count to use (`0` exact, `2` otherwise).
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
    let exact = bits - z.trailing_zeros().unwrap_or(0) <= 53;
    let top = (z.magnitude() >> shift).to_u64().unwrap_or(u64::MAX) as f64;
    let v = top * 2f64.powi(shift as i32);
    (
        if z.is_negative() { -v } else { v },
        if exact { 0 } else { 2 },
    )
}

impl<const INT: bool> SignRing for Ball<INT> {
    fn from_z(z: &BigInt) -> Self {
        let (v, k) = z_to_f64(z);
        Self::input(v, k)
    }
    #[inline]
    fn int(v: i64) -> Self {
        debug_assert!(v.unsigned_abs() < 1 << 53);
        Self::input(v as f64, 0)
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        let m = self.m + o.m;
        Ball {
            m,
            r: (self.r + o.r + U * m.abs()) * INFL,
        }
    }
    #[inline]
    fn sub(&self, o: &Self) -> Self {
        let m = self.m - o.m;
        Ball {
            m,
            r: (self.r + o.r + U * m.abs()) * INFL,
        }
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        if (self.m == 0.0 && self.r == 0.0) || (o.m == 0.0 && o.r == 0.0) {
            return Ball { m: 0.0, r: 0.0 }; // an exact zero factor
        }
        let m = self.m * o.m;
        Ball {
            m,
            r: (self.m.abs() * o.r + self.r * o.m.abs() + self.r * o.r + U * m.abs() + ETA) * INFL,
        }
    }
    #[inline]
    fn neg(&self) -> Self {
        Ball {
            m: -self.m,
            r: self.r,
        }
    }
    #[inline]
    fn sign(&self) -> Option<i32> {
        let (m, r) = (self.m, self.r);
        if m > r {
            Some(1)
        } else if m < -r {
            Some(-1)
        } else if (r == 0.0 && m == 0.0) || (INT && (m.abs() + r) * INFL < 1.0) {
            Some(0)
        } else {
            None
        }
    }
    fn approx(&self) -> f64 {
        self.m
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
    fn divide_content(xs: &mut [Self]) {
        super::divide_content_z(xs);
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

/// True when every component is zero (`None`: undecided).  One component
/// certainly non-zero answers `false` even when another is undecided (the
/// referee's balls need that: a conjunction is as decided as its
/// decided-false part).
pub(crate) fn all_zero<R: SignRing>(x: &[R]) -> Option<bool> {
    let mut unknown = false;
    for c in x {
        match c.sign() {
            Some(0) => {}
            Some(_) => return Some(false),
            None => unknown = true,
        }
    }
    (!unknown).then_some(true)
}

/// The conjunction of lazily evaluated, possibly undecided terms: `false`
/// as soon as one term is certainly false, `true` when all are certainly
/// true, else undecided.
pub(crate) fn all_of(terms: &[&dyn Fn() -> Option<bool>]) -> Option<bool> {
    let mut unknown = false;
    for t in terms {
        match t() {
            Some(true) => {}
            Some(false) => return Some(false),
            None => unknown = true,
        }
    }
    (!unknown).then_some(true)
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

    /// The integer-valued filter.
    type BallI = Ball<true>;

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
            det2(
                &BallI::int(a),
                &BallI::int(b),
                &BallI::int(c),
                &BallI::int(d),
            )
            .sign()
        };
        assert_eq!(s(3, 4, 2, 5), Some(1));
        assert_eq!(s(2, 5, 3, 4), Some(-1));
        // exactly zero with small operands: the ball lies inside (−1, 1)
        assert_eq!(s(6, 4, 3, 8), Some(0));
        // the real-valued filter does not certify that zero (a rounding
        // radius remains), only an exactly computed one
        let r = |a: i64, b: i64, c: i64, d: i64| {
            det2(
                &BallR::int(a),
                &BallR::int(b),
                &BallR::int(c),
                &BallR::int(d),
            )
            .sign()
        };
        assert_eq!(r(6, 4, 3, 8), None);
        assert_eq!(r(0, 4, 3, 0), Some(0));
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
            &BallI::from_z(&p),
            &BallI::from_z(&m),
            &BallI::from_z(&t),
            &BallI::from_z(&t),
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
            &BallI::from_z(&p),
            &BallI::from_z(&m),
            &BallI::from_z(&p),
            &BallI::from_z(&m),
        );
        assert_eq!(f0.sign(), None);
    }

    #[test]
    fn filter_boundary_cases() {
        // a value exactly on the error bound is not decided by the
        // inequality; |v| + b < 1 decides zero for an integer
        let b = 1.0e-10;
        assert_eq!(sign_with_bound(b, b), Some(0)); // |y| < 1 ⇒ y = 0
        assert_eq!(sign_with_bound(0.5, 0.5), None); // |y| ≤ 1 could be ±1
        let ball = |m: f64, r: f64| Ball::<true> { m, r }.sign();
        let real = |m: f64, r: f64| BallR { m, r }.sign();
        assert_eq!(ball(1.0, 1.0), None); // y ∈ [0, 2]
        assert_eq!(ball(0.5, 0.4999), Some(1));
        assert_eq!(ball(0.5, 0.5), None);
        assert_eq!(real(0.0, 0.0), Some(0));
        assert_eq!(real(0.0, 1e-300), None);
        assert_eq!(real(-1e-300, 1e-300), None);
        assert_eq!(sign_with_bound(0.50000001, 0.5), Some(1));
        assert_eq!(sign_with_bound(-0.5, 0.25), Some(-1));
        assert_eq!(sign_with_bound(0.25, 0.25), Some(0)); // |y| ≤ 0.5: y = 0
        assert_eq!(sign_with_bound(f64::NAN, 0.0), None);
        assert_eq!(sign_with_bound(1.0, f64::INFINITY), None);
        assert_eq!(sign_with_bound(1.0, f64::NAN), None);
    }

    #[test]
    fn real_mode_certifies_only_structural_zeros() {
        let x = BallR::input(0.1, 1);
        let y = BallR::input(0.3, 1);
        // 0.1·3 − 0.3: undecided (near zero)
        assert_eq!(x.mul(&BallR::int(3)).sub(&y).sign(), None);
        // 0·x: exactly zero
        assert_eq!(BallR::int(0).mul(&x).sign(), Some(0));
        assert_eq!(x.mul(&y).sign(), Some(1));
        // a product that underflows keeps a radius covering it
        let t = BallR::input(1e-200, 0);
        let tt = t.mul(&t);
        assert!(tt.r >= 1e-322);
        assert_eq!(tt.sub(&tt).sign(), None);
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
            // and a ball from it contains the exact value
            let b = Ball::<true>::from_z(&x);
            let lo = num_rational::BigRational::from_float(b.m - b.r).unwrap();
            let hi = num_rational::BigRational::from_float(b.m + b.r).unwrap();
            let ex = num_rational::BigRational::from_integer(x.clone());
            assert!(lo <= ex && ex <= hi, "{s}");
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
                let f: Vec<BallI> = v.iter().map(BallI::from_z).collect();
                let e = |r: &[BallI]| r[0].mul(&r[1]).mul(&r[2]).sub(&r[3].mul(&r[4]).mul(&r[5]));
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
