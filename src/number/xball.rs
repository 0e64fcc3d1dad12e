//! Balls of doubles with an extended exponent: `[(m − r)·2^e, (m + r)·2^e]`
//! with `f64` midpoint and radius and an `i64` exponent, so that numbers of
//! thousands of bits (the integers of cleared 53-bit doubles) keep a
//! relative precision near 2^-50 where an `f64` would overflow.  The
//! arithmetic is rigorous in the sense of [`super::filter`]'s balls: every
//! rounding is covered by the radius (inflated by `1 + 2^-48`, plus the
//! smallest normal for underflow), and scaling by a power of two is exact.
//! Used for certified enclosures (square roots of quadratic irrationals,
//! certified doubles of exact values); never for a sign decision by itself.

use super::{Q, Z};
use num_bigint::BigInt;
use num_traits::Zero;

const U: f64 = 1.0 / 9_007_199_254_740_992.0; // 2^-53
const INFL: f64 = 1.0 + 1.0 / 281_474_976_710_656.0; // 1 + 2^-48
const TINY: f64 = f64::MIN_POSITIVE;

/// A ball `(m ± r)·2^e` (`r ≥ 0`).
#[derive(Clone, Copy, Debug)]
pub struct XBall {
    /// Midpoint (scaled).
    pub m: f64,
    /// Radius (scaled).
    pub r: f64,
    /// The exponent.
    pub e: i64,
}

/// `⌊log2 |x|⌋` of a finite non-zero double, exactly, from its bits.
pub(crate) fn floor_log2(x: f64) -> i64 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    if biased == 0 {
        // subnormal: m·2^-1074
        let m = bits & ((1u64 << 52) - 1);
        63 - i64::from(m.leading_zeros()) - 1074
    } else {
        biased - 1023
    }
}

/// `⌊z / 2^shift⌋ mod 2^64`, from the two words it spans (no shifted copy
/// of `z`).
pub(crate) fn word_at(z: &num_bigint::BigUint, shift: u64) -> u64 {
    let (w, off) = ((shift / 64) as usize, (shift % 64) as u32);
    let mut words = z.iter_u64_digits().skip(w);
    let lo = words.next().unwrap_or(0);
    if off == 0 {
        return lo;
    }
    (lo >> off) | (words.next().unwrap_or(0) << (64 - off))
}

/// `2^k` for `|k| ≤ 1000` (exact).
pub(crate) fn pow2(k: i64) -> f64 {
    debug_assert!(k.abs() <= 1000);
    f64::from_bits(((1023 + k) as u64) << 52)
}

/// The leading 64 bits of `|z|` as a double (truncated, then rounded:
/// relative error below `2^-52`), the exponent of the scaling, and whether
/// it is exact (`z` has at most 53 significant bits).
pub(crate) fn top(z: &Z) -> (f64, i64, bool) {
    let bits = z.bits() as i64;
    let shift = (bits - 64).max(0);
    let t = word_at(z.magnitude(), shift as u64);
    let exact = bits - z.trailing_zeros().unwrap_or(0) as i64 <= 53;
    (t as f64, shift, exact)
}

impl XBall {
    /// The exact integer or rational zero.
    pub fn zero() -> XBall {
        XBall {
            m: 0.0,
            r: 0.0,
            e: 0,
        }
    }

    /// A ball holding the integer `x`.
    pub fn from_z(x: &Z) -> XBall {
        if x.is_zero() {
            return XBall::zero();
        }
        let (t, e, exact) = top(x);
        let m = if x.sign() == num_bigint::Sign::Minus {
            -t
        } else {
            t
        };
        // a truncation and a rounding when inexact (2u)
        XBall {
            m,
            r: if exact { 0.0 } else { 2.0 * U * t * INFL },
            e,
        }
        .normalized()
    }

    /// A ball holding the rational `x`.
    pub fn from_q(x: &Q) -> XBall {
        if x.is_zero() {
            return XBall::zero();
        }
        let (n, en, xn) = top(x.numer());
        let (d, ed, xd) = top(x.denom());
        let m = n / d;
        let m = if x.numer().sign() == num_bigint::Sign::Minus {
            -m
        } else {
            m
        };
        // a truncation and a rounding per inexact part (2u each), a division
        // (u; none by a power of two)
        let pow2_den = x.denom().bits() - 1 == x.denom().trailing_zeros().unwrap_or(0);
        let units = 2 * u32::from(!xn) + 2 * u32::from(!xd) + u32::from(!pow2_den);
        XBall {
            m,
            r: f64::from(units) * U * m.abs() * INFL,
            e: en - ed,
        }
        .normalized()
    }

    /// A ball holding the closed interval `[lo, hi]` (the hull of the
    /// balls of its ends: no rational arithmetic).
    pub fn from_interval(lo: &Q, hi: &Q) -> XBall {
        XBall::from_q(lo).hull(&XBall::from_q(hi))
    }

    /// A ball holding both balls.
    pub fn hull(&self, o: &XBall) -> XBall {
        let e = self.e.max(o.e);
        let (m1, r1) = self.at_exponent(e);
        let (m2, r2) = o.at_exponent(e);
        // the ends, widened by their roundings
        let lo = (m1 - r1).min(m2 - r2);
        let hi = (m1 + r1).max(m2 + r2);
        let m = 0.5 * (lo + hi);
        let r = ((hi - m).max(m - lo) + U * (lo.abs() + hi.abs())) * INFL + TINY;
        XBall { m, r, e }.normalized()
    }

    /// The same ball with the midpoint's magnitude brought near 1 (an exact
    /// rescaling by a power of two).
    fn normalized(self) -> XBall {
        if self.m == 0.0 {
            // keep a zero midpoint; scale the radius instead
            if self.r == 0.0 {
                return XBall::zero();
            }
            let k = floor_log2(self.r).clamp(-1000, 1000);
            return XBall {
                m: 0.0,
                r: self.r * pow2(-k) * INFL,
                e: self.e + k,
            };
        }
        let k = floor_log2(self.m).clamp(-1000, 1000);
        if k == 0 {
            return self;
        }
        XBall {
            m: self.m * pow2(-k),
            r: self.r * pow2(-k) + if self.r > 0.0 { TINY } else { 0.0 },
            e: self.e + k,
        }
    }

    /// `self · 2^(self.e − e)`: the ball rescaled to exponent `e ≥ self.e`
    /// (an underflowed part goes into the radius).
    fn at_exponent(&self, e: i64) -> (f64, f64) {
        let k = self.e - e;
        if k < -1000 {
            // negligible: the whole value into the radius
            return (0.0, TINY);
        }
        let s = pow2(k.max(-1000));
        (self.m * s, self.r * s + TINY)
    }

    pub fn add(&self, o: &XBall) -> XBall {
        if self.m == 0.0 && self.r == 0.0 {
            return *o;
        }
        if o.m == 0.0 && o.r == 0.0 {
            return *self;
        }
        let e = self.e.max(o.e);
        let (m1, r1) = self.at_exponent(e);
        let (m2, r2) = o.at_exponent(e);
        let m = m1 + m2;
        XBall {
            m,
            r: (r1 + r2 + U * m.abs()) * INFL,
            e,
        }
        .normalized()
    }

    pub fn neg(&self) -> XBall {
        XBall {
            m: -self.m,
            r: self.r,
            e: self.e,
        }
    }

    pub fn sub(&self, o: &XBall) -> XBall {
        self.add(&o.neg())
    }

    pub fn mul(&self, o: &XBall) -> XBall {
        if (self.m == 0.0 && self.r == 0.0) || (o.m == 0.0 && o.r == 0.0) {
            return XBall::zero();
        }
        let m = self.m * o.m;
        XBall {
            m,
            r: (self.m.abs() * o.r + self.r * o.m.abs() + self.r * o.r + U * m.abs() + TINY) * INFL,
            e: self.e + o.e,
        }
        .normalized()
    }

    /// `1/self`, `None` when the ball reaches 0:
    /// `|1/x − 1/m| ≤ r/(|m|(|m| − r))`.
    pub fn recip(&self) -> Option<XBall> {
        let am = self.m.abs();
        let lo = (am - self.r) * (1.0 - 4.0 * U);
        if !(lo > 0.0 && am.is_finite()) {
            return None;
        }
        let m = 1.0 / self.m;
        Some(
            XBall {
                m,
                r: (self.r / (am * lo) + U * m.abs()) * INFL * INFL + TINY,
                e: -self.e,
            }
            .normalized(),
        )
    }

    /// `√self`, `None` when the ball reaches below 0 (or is not finite).
    pub fn sqrt(&self) -> Option<XBall> {
        const W: f64 = 1.0 / 1_125_899_906_842_624.0; // 2^-50
        let (mut m, mut r, mut e) = (self.m, self.r, self.e);
        if e % 2 != 0 {
            m *= 2.0;
            r *= 2.0;
            e -= 1;
        }
        let lo2 = (m - r) * (1.0 - W);
        let hi2 = (m + r) * (1.0 + W);
        if !(lo2 >= 0.0 && hi2.is_finite()) {
            return None;
        }
        let (lo, hi) = (lo2.sqrt() * (1.0 - W), hi2.sqrt() * (1.0 + W));
        let mid = 0.5 * (lo + hi);
        Some(
            XBall {
                m: mid,
                r: (mid - lo).max(hi - mid) * (1.0 + W) + TINY,
                e: e / 2,
            }
            .normalized(),
        )
    }

    /// The sign of every point of the ball, when it is one (`None` when
    /// the ball holds 0 or is not finite; an exact zero ball is 0).
    pub fn sign(&self) -> Option<i32> {
        if self.m == 0.0 && self.r == 0.0 {
            return Some(0);
        }
        if !(self.m.is_finite() && self.r.is_finite()) {
            return None;
        }
        if self.m > self.r {
            Some(1)
        } else if self.m < -self.r {
            Some(-1)
        } else {
            None
        }
    }

    /// The ends as exact rationals, `None` when not finite.
    pub fn bounds(&self) -> Option<(Q, Q)> {
        let (lo, hi) = (self.m - self.r, self.m + self.r);
        if !(lo.is_finite() && hi.is_finite()) {
            return None;
        }
        let scale = |x: f64| -> Option<Q> {
            let q = super::double_value(x)?;
            Some(if self.e >= 0 {
                q * Q::from_integer(BigInt::from(1) << self.e as usize)
            } else {
                q / Q::from_integer(BigInt::from(1) << (-self.e) as usize)
            })
        };
        Some((scale(lo)?, scale(hi)?))
    }

    /// `self + y` for balls whose `self² − y²` is known exactly (`norm`,
    /// computed only when needed): the sum when it is tight (radius below
    /// `2^-bits` of the midpoint), else — the two cancel, so `self` and
    /// `−y` have one sign — `norm/(self − y)`, whose denominator adds
    /// without cancellation (`a + b√d = (a² − b²d)/(a − b√d)`).
    pub fn add_by_conjugate(&self, y: &XBall, bits: i32, norm: impl FnOnce() -> XBall) -> XBall {
        let fast = self.add(y);
        if fast.r * 2f64.powi(bits) < fast.m.abs() {
            return fast;
        }
        match self.sub(y).recip() {
            Some(inv) => norm().mul(&inv),
            // self − y contains 0 only when both are near 0: keep the sum
            None => fast,
        }
    }

    /// A double approximation of the midpoint and a bound on the distance
    /// from it to any point of the ball (`None` outside the range of
    /// doubles).
    pub fn to_f64(self) -> Option<(f64, f64)> {
        if self.e > 1000 || self.e < -1000 {
            if self.e < -1000 {
                // tiny: 0 with the whole ball as the bound
                return Some((0.0, TINY));
            }
            return None;
        }
        let s = pow2(self.e);
        let v = self.m * s;
        if self.r == 0.0 && (self.m == 0.0 || v.is_normal()) {
            // an exact ball (a dyadic rational of at most 53 bits): scaling
            // by a power of two into the normal range is exact
            return v.is_finite().then_some((v, 0.0));
        }
        // rounding of the product (subnormal results: absolute 2^-1074)
        let b = (self.r * s + U * v.abs() + 5e-324) * INFL;
        (v.is_finite() && b.is_finite()).then_some((v, b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{q, qi};

    fn holds(b: &XBall, x: &Q) -> bool {
        let (lo, hi) = b.bounds().unwrap();
        lo <= *x && *x <= hi
    }

    #[test]
    fn huge_and_tiny_rationals_stay_enclosed() {
        let big = Q::from_integer(BigInt::from(3) << 3000usize);
        let small = Q::new(BigInt::from(7), BigInt::from(1) << 2500usize);
        for x in [big.clone(), small.clone(), q(-22, 7), qi(0), &big * &small] {
            assert!(holds(&XBall::from_q(&x), &x), "{x}");
        }
        let p = XBall::from_q(&big).mul(&XBall::from_q(&small));
        assert!(holds(&p, &(&big * &small)));
        let s = XBall::from_q(&big).add(&XBall::from_q(&small));
        assert!(holds(&s, &(&big + &small)));
    }

    #[test]
    fn exact_doubles_have_bound_zero() {
        for (x, v) in [
            (qi(0), 0.0),
            (qi(1), 1.0),
            (q(-3, 4), -0.75),
            (q(5, 1024), 5.0 / 1024.0),
        ] {
            assert_eq!(XBall::from_q(&x).to_f64(), Some((v, 0.0)), "{x}");
        }
        let third = q(1, 3);
        let (v, b) = XBall::from_q(&third).to_f64().unwrap();
        assert!(b > 0.0 && b < 1e-15);
        let (vq, bq) = (Q::from_float(v).unwrap(), Q::from_float(b).unwrap());
        assert!(&vq - &bq <= third && third <= &vq + &bq);
    }

    #[test]
    fn square_roots_are_enclosed() {
        // √(2^2001) = 2^1000·√2
        let x = Q::from_integer(BigInt::from(1) << 2001usize);
        let r = XBall::from_q(&x).sqrt().unwrap();
        let (lo, hi) = r.bounds().unwrap();
        assert!(&lo * &lo <= x && x <= &hi * &hi);
        assert!((&hi - &lo) / &lo < q(1, 1 << 40));
    }
}

#[cfg(test)]
mod top_tests {
    use super::*;

    #[test]
    fn top_is_the_leading_bits() {
        for bits in [
            1u32, 52, 53, 63, 64, 65, 100, 127, 128, 129, 191, 192, 193, 1000,
        ] {
            for low in [0u64, 1, 12345] {
                let z = (Z::from(1) << (bits - 1) as usize) + Z::from(low) * 3 + Z::from(5);
                let (t, s, _) = top(&z);
                let want = (&z >> s as usize).to_string().parse::<f64>().unwrap();
                assert_eq!(t, want, "bits {bits} low {low}");
                assert_eq!(s, (z.bits() as i64 - 64).max(0));
            }
        }
    }
}
