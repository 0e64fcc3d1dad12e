//! Doubles as exact numbers: the exact rational value of an IEEE-754
//! binary64 number, and the nearest double of a rational (round to nearest,
//! ties to even), both computed with integers — the platform's float
//! parser is never used for a decision.
//!
//! A double is a dyadic rational `m·2^e` (`|m| < 2^53`, `−1074 ≤ e ≤ 971`),
//! so a user checking a floating-point kernel can hand quadsect exactly the
//! numbers that kernel used: as hexadecimal floats (`0x1.8p-3`, exact by
//! definition) or as decimals read in *float mode* (each literal replaced
//! by its nearest double, [`round_to_double`]).

use super::{Q, Z, floor_log2_q};
use num_bigint::BigInt;
use num_integer::Integer;
#[cfg(test)]
use num_traits::One;
use num_traits::{Signed, ToPrimitive, Zero};

/// The exact value of a finite double (`None` for infinities and NaN).
pub fn double_value(x: f64) -> Option<Q> {
    if !x.is_finite() {
        return None;
    }
    let (neg, m, e) = double_parts(x);
    let m = if neg {
        -BigInt::from(m)
    } else {
        BigInt::from(m)
    };
    Some(if e >= 0 {
        Q::from_integer(m << (e as usize))
    } else {
        super::dyadic(m, (-e) as usize)
    })
}

/// A finite double as `(negative, m, e)` with `|x| = m·2^e` exactly.
pub fn double_parts(x: f64) -> (bool, u64, i64) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    (bits >> 63 == 1, m, e)
}

/// The double nearest to `x`, ties to even (IEEE-754 round to nearest);
/// `None` when the rounded magnitude is `2^1024` or more (out of range).
/// Values below half the smallest subnormal round to zero.
pub fn nearest_double(x: &Q) -> Option<f64> {
    if x.is_zero() {
        return Some(0.0);
    }
    let neg = x.is_negative();
    let n = x.numer().abs();
    let d = x.denom();
    // the quantum 2^q of the doubles in the binade of |x| (subnormals: 2^-1074)
    let e = floor_log2_q(&Q::new_raw(n.clone(), d.clone()));
    if e > 1100 {
        return None;
    }
    let q = (e - 52).max(-1074);
    // M = round(|x| / 2^q), ties to even
    let (num, den): (Z, Z) = if q >= 0 {
        (n, d << (q as usize))
    } else {
        (n << ((-q) as usize), d.clone())
    };
    let (mut m, r) = num.div_rem(&den);
    let twice = &r << 1usize;
    if twice > den || (twice == den && m.is_odd()) {
        m += 1;
    }
    let mut m = m.to_u64()?;
    let mut q = q;
    if m == 1 << 53 {
        m >>= 1;
        q += 1;
    }
    let bits = if m >= 1 << 52 {
        let biased = q + 52 + 1023;
        if biased >= 0x7ff {
            return None;
        }
        ((biased as u64) << 52) | (m - (1 << 52))
    } else {
        // subnormal (or zero): q = −1074
        m
    };
    let v = f64::from_bits(bits);
    Some(if neg { -v } else { v })
}

/// The exact value of the double nearest to `x` (see [`nearest_double`]).
pub fn round_to_double(x: &Q) -> Option<Q> {
    double_value(nearest_double(x)?)
}

/// True when `x` is a dyadic rational (its denominator is a power of two),
/// e.g. every double.
#[cfg(test)]
pub fn is_dyadic(x: &Q) -> bool {
    let d = x.denom();
    d.is_one() || d.trailing_zeros() == Some(d.bits() - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{parse_rational, q};

    #[test]
    fn halfway_cases_round_to_even() {
        // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: even is 1
        let half = Q::one() + super::super::dyadic(BigInt::one(), 53);
        assert_eq!(nearest_double(&half), Some(1.0));
        // 1 + 3·2^-53 is halfway between 1 + 2^-52 and 1 + 2^-51: even is 1 + 2^-51
        let h3 = Q::one() + super::super::dyadic(BigInt::from(3), 53);
        assert_eq!(nearest_double(&h3), Some(1.0 + 2f64.powi(-51)));
        // just above halfway rounds up
        let above = &half + super::super::dyadic(BigInt::one(), 200);
        assert_eq!(nearest_double(&above), Some(1.0 + f64::EPSILON));
        // 2^53 + 1 → 2^53 (even), 2^53 + 3 → 2^53 + 4
        assert_eq!(
            nearest_double(&q(9007199254740993, 1)),
            Some(9007199254740992.0)
        );
        assert_eq!(
            nearest_double(&q(9007199254740995, 1)),
            Some(9007199254740996.0)
        );
        // the decimal halfway case 9007199254740993 also through the parser
        let x = parse_rational("9007199254740993").unwrap();
        assert_eq!(nearest_double(&x), Some(9007199254740992.0));
        // negative ties are symmetric
        assert_eq!(nearest_double(&-&half), Some(-1.0));
    }

    #[test]
    fn subnormals_overflow_and_underflow() {
        let tiny = super::super::dyadic(BigInt::one(), 1074);
        assert_eq!(nearest_double(&tiny), Some(f64::from_bits(1)));
        // half the smallest subnormal ties to even: 0
        let half_tiny = super::super::dyadic(BigInt::one(), 1075);
        assert_eq!(nearest_double(&half_tiny), Some(0.0));
        let three_half = super::super::dyadic(BigInt::from(3), 1075);
        assert_eq!(nearest_double(&three_half), Some(f64::from_bits(2)));
        assert_eq!(
            nearest_double(&Q::from_integer(BigInt::one() << 1024usize)),
            None
        );
        let max = double_value(f64::MAX).unwrap();
        assert_eq!(nearest_double(&max), Some(f64::MAX));
        // f64::MAX + half an ulp rounds to even = 2^1024: out of range
        let half_ulp = Q::from_integer(BigInt::one() << 970usize);
        assert_eq!(nearest_double(&(&max + &half_ulp)), None);
        assert_eq!(
            nearest_double(&(&max + &half_ulp - Q::one())),
            Some(f64::MAX)
        );
    }

    proptest::proptest! {
        /// A double's exact value rounds back to the same double, and
        /// decimal strings round as Rust's (correctly rounded) parser does.
        #[test]
        fn round_trips(bits in proptest::num::u64::ANY, digits in 1u32..25, e10 in -330i32..310, mant in 1u64..u64::MAX) {
            let x = f64::from_bits(bits);
            if x.is_finite() {
                let v = double_value(x).unwrap();
                let back = nearest_double(&v).unwrap();
                proptest::prop_assert_eq!(back.to_bits(), if x == 0.0 { 0.0f64.to_bits() } else { x.to_bits() });
            }
            let m = mant % 10u64.pow(digits.min(19));
            let s = format!("{m}e{e10}");
            let exact = parse_rational(&s).unwrap();
            let std: f64 = s.parse().unwrap();
            if std.is_finite() {
                proptest::prop_assert_eq!(nearest_double(&exact), Some(std));
            } else {
                proptest::prop_assert_eq!(nearest_double(&exact), None);
            }
        }
    }

    #[test]
    fn dyadic_test() {
        assert!(is_dyadic(&q(3, 8)));
        assert!(is_dyadic(&q(5, 1)));
        assert!(!is_dyadic(&q(1, 10)));
    }
}

#[cfg(test)]
mod doc_examples_more {
    //! Examples that were doc comments of crate-private items.

    #[test]
    fn doc_double_value() {
        use crate::number::{double_value, q};
        assert_eq!(
            double_value(0.1).unwrap(),
            q(3602879701896397, 36028797018963968)
        );
        assert_eq!(double_value(-0.0).unwrap(), q(0, 1));
    }

    #[test]
    fn doc_nearest_double() {
        use crate::number::float::nearest_double;
        use crate::number::q;
        assert_eq!(nearest_double(&q(1, 10)), Some(0.1));
        assert_eq!(nearest_double(&q(1, 3)), Some(1.0 / 3.0));
    }
}
