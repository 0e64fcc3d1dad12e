//! Exact numbers to doubles with outward rounding: a rational rounded
//! down and up exactly (integer division, no floating-point arithmetic),
//! and a real algebraic number enclosed in the tightest interval of
//! doubles its refined isolating interval allows.
//!
//! Why it is right: for `m = |q| > 0` with `2^e ≤ m < 2^(e+1)` the double
//! of the same binade with the largest mantissa not above `m` is
//! `floor(m · 2^(52−e)) · 2^(e−52)` (a 53-bit integer times a power of
//! two), and below the normal range the subnormal grid `2^-1074` replaces
//! `2^(e−52)`.  The remainder of the integer division says whether the
//! truncation was exact; if not, the next double away from zero is the
//! other bound.  A real algebraic number `x` lies in its isolating
//! interval `(a, b)`, so `down(a) ≤ a < x < b ≤ up(b)`; refining the
//! interval brings `down(a)` and `up(b)` to the two doubles around `x`.

use engine::{BigInt, Rational, RealAlg};
use num_traits::{Signed, ToPrimitive, Zero};

/// An exact value as doubles: `lo ≤ value ≤ hi`, rounded outward.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Enclosure {
    pub lo: f64,
    pub hi: f64,
    /// `lo == hi` is the exact value.
    pub exact: bool,
}

/// `|n/d|` (for `n ≠ 0`, `d > 0`) truncated toward zero to a double, and
/// whether the truncation was exact.  Above `f64::MAX` it is `f64::MAX`,
/// inexact.
fn truncate_magnitude(n: &BigInt, d: &BigInt) -> (f64, bool) {
    let n = n.abs();
    // 2^(e0−1) < n/d < 2^(e0+1); the exact binade exponent e is e0 or e0 − 1
    let e0 = n.bits() as i64 - d.bits() as i64;
    let at_least_2_to = |e: i64| {
        if e >= 0 {
            n >= (d << e as usize)
        } else {
            (&n << (-e) as usize) >= *d
        }
    };
    let e = if at_least_2_to(e0) { e0 } else { e0 - 1 };
    if e > 1023 {
        return (f64::MAX, false);
    }
    // the scale 2^k that puts the 53 significant bits (or the subnormal
    // grid) in the integer part
    let k = if e >= -1022 { 52 - e } else { 1074 };
    let (num, den) = if k >= 0 {
        (&n << k as usize, d.clone())
    } else {
        (n.clone(), d << (-k) as usize)
    };
    let mantissa = &num / &den;
    let exact = (&num % &den).is_zero();
    let m = mantissa.to_u64().expect("the mantissa has at most 53 bits");
    let bits = if e >= -1022 {
        // m ∈ [2^52, 2^53): the implicit bit is dropped
        (((e + 1023) as u64) << 52) | (m & ((1u64 << 52) - 1))
    } else {
        // m < 2^52: a subnormal (or zero) with exponent field 0
        m
    };
    (f64::from_bits(bits), exact)
}

/// The largest double `≤ q` and the smallest double `≥ q` (±infinity
/// beyond `±f64::MAX`).  Equal exactly when `q` is a double.
pub(crate) fn round_outward(q: &Rational) -> (f64, f64) {
    if q.is_zero() {
        return (0.0, 0.0);
    }
    let (t, exact) = truncate_magnitude(q.numer(), q.denom());
    let away = if exact { t } else { t.next_up() };
    // adding 0.0 turns −0.0 into +0.0
    if q.is_positive() {
        (t, away)
    } else {
        (-away, -t + 0.0)
    }
}

/// The exact rational value of a finite double (`None` for NaN and ±∞).
pub(crate) fn exact(x: f64) -> Option<Rational> {
    Rational::from_float(x)
}

/// Most refinement rounds of [`enclose`]; each shrinks the interval at
/// least fourfold and below a quarter of the local spacing of doubles, so
/// a few rounds suffice in practice and the cap only bounds pathological
/// inputs (the enclosure is valid at every round, only possibly wider).
const MAX_ROUNDS: usize = 64;

/// The tightest outward enclosure of `x` by doubles: `[d, d]` when `x` is
/// the double `d`, otherwise two neighbouring doubles (or `f64::MAX` and
/// infinity beyond the range).
pub(crate) fn enclose(x: &RealAlg) -> Enclosure {
    let mut x = x.clone();
    let mut best = None;
    for _ in 0..MAX_ROUNDS {
        if let Some(q) = x.as_rational() {
            let (lo, hi) = round_outward(q);
            return Enclosure {
                lo,
                hi,
                exact: lo == hi,
            };
        }
        let (a, b) = x.interval();
        let (lo, _) = round_outward(&a);
        let (_, hi) = round_outward(&b);
        best = Some(Enclosure {
            lo,
            hi,
            exact: false,
        });
        let between = lo.next_up();
        if hi <= between {
            break;
        }
        // exactly one double strictly inside: x may be that double (a
        // rational root kept in algebraic form), which no refinement of an
        // open interval around x would ever exclude
        if hi == between.next_up() && exact(between).is_some_and(|m| x == m) {
            let m = between + 0.0;
            return Enclosure {
                lo: m,
                hi: m,
                exact: true,
            };
        }
        x.refine_to(&target_width(lo, hi, &a, &b));
    }
    best.expect("at least one round")
}

/// The width to refine `(a, b)` to: a quarter of the spacing of doubles
/// near `[lo, hi]` or of `b − a`, whichever is smaller, or a 2^-32
/// fraction of `b − a` when the spacing is not known yet (the interval
/// straddles zero or infinity).
fn target_width(lo: f64, hi: f64, a: &Rational, b: &Rational) -> Rational {
    let near = if lo > 0.0 {
        lo
    } else if hi < 0.0 {
        -hi
    } else {
        0.0
    };
    let spacing = near.next_up() - near;
    let quarter = |w: Rational| w / Rational::from_integer(4.into());
    match exact(spacing) {
        // also below a quarter of the current width: an interval already
        // narrower than the spacing may still hold a double (not x) inside
        Some(s) if near > 0.0 && s.is_positive() => quarter(s).min(quarter(b - a)),
        _ => (b - a) / Rational::from_integer(BigInt::from(1u64 << 32)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::IntPoly;
    use proptest::prelude::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    fn encloses(e: &Enclosure, x: &RealAlg) -> bool {
        let lo_ok = !e.lo.is_finite() || *x >= exact(e.lo).unwrap();
        let hi_ok = !e.hi.is_finite() || *x <= exact(e.hi).unwrap();
        lo_ok && hi_ok && e.lo <= e.hi
    }

    #[test]
    fn doubles_round_to_themselves() {
        for d in [
            1.0,
            -0.1,
            1e-310,
            f64::MIN_POSITIVE,
            f64::MAX,
            -f64::MAX,
            5e-324,
            3.0,
        ] {
            assert_eq!(round_outward(&exact(d).unwrap()), (d, d), "{d}");
        }
    }

    #[test]
    fn thirds_and_extremes_round_outward() {
        let (lo, hi) = round_outward(&q(1, 3));
        assert_eq!(hi, lo.next_up());
        assert!(exact(lo).unwrap() < q(1, 3) && q(1, 3) < exact(hi).unwrap());
        let (lo, hi) = round_outward(&q(-1, 3));
        assert_eq!(
            (lo, hi),
            (-round_outward(&q(1, 3)).1, -round_outward(&q(1, 3)).0)
        );
        // beyond the range: MAX and infinity
        let huge = Rational::from_integer(BigInt::from(1) << 1100usize);
        assert_eq!(round_outward(&huge), (f64::MAX, f64::INFINITY));
        assert_eq!(round_outward(&-huge), (f64::NEG_INFINITY, -f64::MAX));
        // below the smallest subnormal: 0 and 2^-1074, and −0 never appears
        let tiny = Rational::new(1.into(), BigInt::from(1) << 1100usize);
        assert_eq!(round_outward(&tiny), (0.0, 5e-324));
        let (lo, hi) = round_outward(&-tiny);
        assert_eq!(lo, -5e-324);
        assert!(hi == 0.0 && hi.is_sign_positive());
    }

    #[test]
    fn sqrt2_is_enclosed_by_its_two_neighbouring_doubles() {
        let p: IntPoly = "u^2 - 2".parse().unwrap();
        let r = &p.real_roots()[1];
        let e = enclose(r);
        assert!(!e.exact);
        assert_eq!(e.hi, e.lo.next_up());
        assert!(encloses(&e, r));
        assert!(e.lo <= std::f64::consts::SQRT_2 && std::f64::consts::SQRT_2 <= e.hi);
    }

    #[test]
    fn a_rational_root_in_algebraic_form_is_found_exact() {
        // (2u − 1)(u² − 2): the root 1/2 given by an interval, not as a rational
        let p: IntPoly = "(2u - 1)*(u^2 - 2)".parse().unwrap();
        let r = RealAlg::new(&p, &q(1, 3), &q(2, 3)).unwrap();
        let e = enclose(&r);
        assert_eq!((e.lo, e.hi, e.exact), (0.5, 0.5, true));
    }

    proptest! {
        /// Property: a double's exact value rounds to that double both ways.
        #[test]
        fn every_finite_double_is_its_own_enclosure(bits in any::<u64>()) {
            let d = f64::from_bits(bits);
            prop_assume!(d.is_finite());
            let (lo, hi) = round_outward(&exact(d).unwrap());
            prop_assert_eq!(lo, d + 0.0);
            prop_assert_eq!(hi, d + 0.0);
        }

        /// Property: a rational lies in [lo, hi], and lo, hi are equal or
        /// neighbours (the rounding is the tightest).
        #[test]
        fn rationals_lie_between_neighbouring_doubles(n in any::<i64>(), d in 1i64.., shift in -1200i32..1200) {
            let mut x = q(n, d);
            let two = Rational::from_integer(2.into());
            x *= two.pow(shift);
            let (lo, hi) = round_outward(&x);
            prop_assert!(lo <= hi);
            prop_assert!(hi == lo || hi == lo.next_up());
            if lo.is_finite() { prop_assert!(exact(lo).unwrap() <= x); }
            if hi.is_finite() { prop_assert!(x <= exact(hi).unwrap()); }
        }

        /// Property: the enclosure of a root of a random quadratic contains
        /// it and is exact only on a double.
        #[test]
        fn roots_of_quadratics_are_enclosed(a in 1i64..1000, b in -10_000i64..10_000, c in -10_000i64..10_000) {
            let p = IntPoly::from_coeffs(vec![c.into(), b.into(), a.into()]);
            for r in p.real_roots() {
                let e = enclose(&r);
                prop_assert!(encloses(&e, &r));
                prop_assert!(e.hi == e.lo || e.hi == e.lo.next_up());
                if e.exact { prop_assert!(r == exact(e.lo).unwrap()); }
            }
        }
    }
}
