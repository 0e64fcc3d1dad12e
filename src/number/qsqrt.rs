//! Numbers `a + b√d` with rational `a`, `b` and a rational radicand `d >= 0`:
//! the quadratic field Q(√d), with exact sign and comparison.
//!
//! These are the numbers the natural-quadric classification needs where a
//! construction takes one square root (the two lines of a degenerate conic,
//! the tangent planes through a line) and the witness points of the tangent
//! point method (`z = ±√c`).  Signs are decided by squaring, never by floats:
//! `sign(a + b√d)` is the sign of `a` and `b` when they agree, otherwise the
//! sign of whichever of `a²` and `b²d` is larger.

use super::{Q, approx_decimal, exact_sqrt_q, fmt_q, q_add, q_mul, q_sub, sign_q};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;

/// An exact real number `a + b√d` (rational `a`, `b`, and `d ≥ 0`).
///
/// Comparison is exact, also between numbers of different fields Q(√d)
/// (by squaring once); equal values hash equally.
///
/// ```
/// use quadsect::{QSqrt, Rational};
/// let r = |n: i64| Rational::from_integer(n.into());
/// let x = QSqrt::try_new(r(1), r(2), r(2)).unwrap(); // 1 + 2√2
/// let y = QSqrt::try_new(r(1), r(1), r(8)).unwrap(); // 1 + √8
/// assert_eq!(x, y);
/// assert_eq!(x.to_string(), "1 + 2·√(2)");
/// assert!(x > QSqrt::rational(r(3)));
/// assert!(QSqrt::try_new(r(0), r(1), r(-1)).is_err()); // √-1 is not real
/// ```
#[derive(Clone, Debug)]
pub struct QSqrt {
    /// Rational part.
    pub(crate) a: Q,
    /// Coefficient of √d.
    pub(crate) b: Q,
    /// Radicand, `d >= 0`.  When `d` is a rational square the value is folded
    /// into `a` and `b` is zero.
    pub(crate) d: Q,
}

impl QSqrt {
    /// The rational `a` (with `b = 0`, `d = 0`).
    pub fn rational(a: Q) -> Self {
        QSqrt {
            a,
            b: Q::zero(),
            d: Q::zero(),
        }
    }

    /// `a + b√d` for `d ≥ 0` (an error of kind `input` otherwise), folding
    /// `√d` into the rational part when `d` is a square.
    pub fn try_new(a: Q, b: Q, d: Q) -> Result<QSqrt, crate::Error> {
        if d.is_negative() && !b.is_zero() {
            return Err(crate::Error::new(
                crate::ErrorKind::Input,
                format!("√({}) is not real: the radicand must be ≥ 0", fmt_q(&d)),
            ));
        }
        Ok(QSqrt::new(
            a,
            b,
            if d.is_negative() { Q::zero() } else { d },
        ))
    }

    /// The rational part `a`.
    pub fn a(&self) -> &Q {
        &self.a
    }

    /// The coefficient `b` of `√d`.
    pub fn b(&self) -> &Q {
        &self.b
    }

    /// The radicand `d` (0 for a rational).
    pub fn d(&self) -> &Q {
        &self.d
    }

    /// The exact sign.
    pub fn sign(&self) -> super::Sign {
        super::Sign::from_i32(self.signum())
    }

    /// Exact comparison of any two, in one field or not.  Across fields,
    /// `x − y = u + v` with `u = (a₁ − a₂) + b₁√d₁ ∈ Q(√d₁)` and
    /// `v = −b₂√d₂`: when the signs of `u` and `v` differ, the larger of
    /// `u² ∈ Q(√d₁)` and `v² = b₂²d₂` decides (one sign in Q(√d₁)).
    fn cmp_any(&self, o: &QSqrt) -> Ordering {
        if self.b.is_zero() || o.b.is_zero() || self.d == o.d {
            return self.cmp_exact(o);
        }
        let u = QSqrt::from_parts(&self.a - &o.a, self.b.clone(), self.d.clone());
        let (su, sv) = (u.signum(), -sign_q(&o.b));
        let s = if su == 0 || su == sv {
            if su == 0 { sv } else { su }
        } else {
            let v2 = QSqrt::rational(&o.b * &o.b * &o.d);
            match u.mul(&u).sub(&v2).signum() {
                1 => su,
                -1 => sv,
                _ => 0,
            }
        };
        s.cmp(&0)
    }

    /// `a + b√d`, folding `√d` into the rational part when `d` is a square.
    /// Panics (debug) on negative `d`; callers check the sign first.
    pub(crate) fn new(a: Q, b: Q, d: Q) -> Self {
        debug_assert!(!d.is_negative(), "negative radicand");
        if b.is_zero() || d.is_zero() {
            return QSqrt::rational(a);
        }
        if let Some(r) = exact_sqrt_q(&d) {
            return QSqrt::rational(a + b * r);
        }
        QSqrt { a, b, d }
    }

    /// The result of an operation on values of one field Q(√d): `d` is
    /// already known not to be a square (it comes from an operand with
    /// `b ≠ 0`), so only the rational case needs folding.
    fn from_parts(a: Q, b: Q, d: Q) -> Self {
        if b.is_zero() || d.is_zero() {
            QSqrt::rational(a)
        } else {
            QSqrt { a, b, d }
        }
    }

    /// `a + b√d` for a `d` known not to be a square (no square test).
    pub(crate) fn from_parts_nonsquare(a: Q, b: Q, d: Q) -> Self {
        debug_assert!(exact_sqrt_q(&d).is_none() || b.is_zero());
        QSqrt::from_parts(a, b, d)
    }

    /// `√d` itself.
    pub(crate) fn sqrt(d: Q) -> Self {
        QSqrt::new(Q::zero(), Q::one(), d)
    }

    /// True when the value is rational (`b = 0`).
    pub fn is_rational(&self) -> bool {
        self.b.is_zero()
    }

    /// True when the value is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }

    /// The exact sign: -1, 0 or 1.
    pub(crate) fn signum(&self) -> i32 {
        let sa = sign_q(&self.a);
        let sb = sign_q(&self.b);
        if sb == 0 {
            return sa;
        }
        if sa == 0 || sa == sb {
            return sb;
        }
        // opposite signs: compare a^2 with b^2 d
        let a2 = &self.a * &self.a;
        let b2d = &self.b * &self.b * &self.d;
        match a2.cmp(&b2d) {
            Ordering::Greater => sa,
            Ordering::Less => sb,
            Ordering::Equal => 0,
        }
    }

    fn radicand_with(&self, other: &QSqrt) -> Q {
        if self.b.is_zero() {
            other.d.clone()
        } else {
            debug_assert!(
                other.b.is_zero() || other.d == self.d,
                "mixing different radicands"
            );
            self.d.clone()
        }
    }

    /// Sum (both operands must live in the same field Q(√d)).
    // (the field operations reduce with Lehmer's gcd — `super::q_add`,
    // `super::q_mul` — not num-rational's binary one: the same values)
    pub(crate) fn add(&self, o: &QSqrt) -> QSqrt {
        let d = self.radicand_with(o);
        QSqrt::from_parts(q_add(&self.a, &o.a), q_add(&self.b, &o.b), d)
    }

    /// Difference.
    pub(crate) fn sub(&self, o: &QSqrt) -> QSqrt {
        let d = self.radicand_with(o);
        QSqrt::from_parts(q_sub(&self.a, &o.a), q_sub(&self.b, &o.b), d)
    }

    /// Product.
    pub(crate) fn mul(&self, o: &QSqrt) -> QSqrt {
        let d = self.radicand_with(o);
        let a = q_add(&q_mul(&self.a, &o.a), &q_mul(&q_mul(&self.b, &o.b), &d));
        let b = q_add(&q_mul(&self.a, &o.b), &q_mul(&self.b, &o.a));
        QSqrt::from_parts(a, b, d)
    }

    /// Product with a rational.
    pub(crate) fn scale(&self, k: &Q) -> QSqrt {
        QSqrt::from_parts(q_mul(&self.a, k), q_mul(&self.b, k), self.d.clone())
    }

    /// Negation.
    pub(crate) fn neg(&self) -> QSqrt {
        QSqrt::from_parts(-&self.a, -&self.b, self.d.clone())
    }

    /// Norm `a² - b²d` (a rational): over the common denominator
    /// `ad²·bd²·dd` in integers, then in lowest terms by one gcd (not a
    /// gcd per rational operation).
    pub(crate) fn norm(&self) -> Q {
        let (an, ad) = (self.a.numer(), self.a.denom());
        let (bn, bd) = (self.b.numer(), self.b.denom());
        let (dn, dd) = (self.d.numer(), self.d.denom());
        let (ad2, bd2) = (ad * ad, bd * bd);
        super::q_new(an * an * &bd2 * dd - bn * bn * dn * &ad2, ad2 * bd2 * dd)
    }

    /// Inverse; `None` for zero.
    pub(crate) fn inv(&self) -> Option<QSqrt> {
        if self.is_zero() {
            return None;
        }
        let n = self.norm();
        // n != 0 since √d is irrational when b != 0
        Some(QSqrt::new(&self.a / &n, -&self.b / &n, self.d.clone()))
    }

    /// Quotient; `None` when dividing by zero.
    pub(crate) fn div(&self, o: &QSqrt) -> Option<QSqrt> {
        Some(self.mul(&o.inv()?))
    }

    /// Exact comparison of two elements of the same field.
    pub(crate) fn cmp_exact(&self, o: &QSqrt) -> Ordering {
        match self.sub(o).signum() {
            -1 => Ordering::Less,
            0 => Ordering::Equal,
            _ => Ordering::Greater,
        }
    }

    /// A rational within `2^-bits` of the value (exact integer square root).
    pub fn to_rational_approx(&self, bits: u32) -> Q {
        if self.b.is_zero() {
            return self.a.clone();
        }
        // √d ≈ isqrt(num·den·4^k) / (den·2^k), error < 1/(den·2^k)
        let k = bits as usize + 8 + (self.b.numer().bits() as usize);
        let nd = self.d.numer() * self.d.denom();
        let s = (nd << (2 * k)).sqrt();
        let root = Q::new(s, self.d.denom() << k);
        &self.a + &self.b * root
    }

    /// The value as a double with a proven bound on its error:
    /// `|self − v| ≤ b` for `(v, b)`, the bound within a few units in the
    /// last place of `v` (at most `2^-46·|v|`) however close to 0 the value
    /// is (`(±∞, ∞)` beyond the range of doubles; bound 0 for a rational
    /// that is a double).  Cancellation in `a + b√d` is met by the
    /// conjugate: `(a² − b²d)/(a − b√d)`.
    pub fn to_f64_bounded(&self) -> (f64, f64) {
        use super::xball::XBall;
        let ball = if self.b.is_zero() {
            let ball = XBall::from_q(&self.a);
            // a double exactly: bound 0
            if let Some((v, _)) = ball.to_f64()
                && super::double_value(v).is_some_and(|x| super::q_eq(&x, &self.a))
            {
                return (v, 0.0);
            }
            ball
        } else {
            let a = XBall::from_q(&self.a);
            let rb = XBall::from_q(&self.d)
                .sqrt()
                .map(|r| XBall::from_q(&self.b).mul(&r));
            match rb {
                // tight when the radius is below 2^-47 of the midpoint:
                // a ball of √d is about 2^-50 wide (relative) and the
                // conversions of a, b add a few 2^-53, so the sum passes
                // unless it cancels more than a few bits; under
                // cancellation a + b√d = (a² − b²d)/(a − b√d)
                Some(rb) => a.add_by_conjugate(&rb, 47, || XBall::from_q(&self.norm())),
                // √d of a positive d always has a ball: not reached, and
                // an infinite bound is still true
                None => return (0.0, f64::INFINITY),
            }
        };
        // (lazily: the exact sign costs more than the ball)
        ball.to_f64().unwrap_or_else(|| {
            (
                if self.signum() < 0 {
                    f64::NEG_INFINITY
                } else {
                    f64::INFINITY
                },
                f64::INFINITY,
            )
        })
    }

    /// Decimal approximation with `digits` significant digits, correctly
    /// rounded, however close to 0 the value is (a + b√d may cancel to far
    /// below 2^-1000): approximations within `2^-bits` are taken with
    /// doubling `bits` until both ends of `[m − 2^-bits, m + 2^-bits]` have
    /// one sign and round to the same digits.  An irrational value is never
    /// a rounding boundary, so this ends; a rational one (`d` a square) is
    /// rounded exactly.
    pub fn approx(&self, digits: usize) -> String {
        if self.b.is_zero() {
            return approx_decimal(&self.a, digits);
        }
        if let Some(r) = super::exact_sqrt_q(&self.d) {
            return approx_decimal(&(&self.a + &self.b * r), digits);
        }
        self.approx_irrational(digits)
    }

    /// [`QSqrt::approx`] of a number known irrational (`b ≠ 0`, `d` not a
    /// rational square: a [`QSqrt::normalized`] one with `b ≠ 0`).
    pub(crate) fn approx_irrational(&self, digits: usize) -> String {
        debug_assert!(!self.b.is_zero());
        // in integers: x = (N1 + N2·√R)/D with a = an/ad, b = bn/bd,
        // d = dn/dd: N1 = an·bd·dd, N2 = bn·ad, R = dn·dd, D = ad·bd·dd;
        // m = N1·2^k + sgn(N2)·r with r within e of √T, T = N2²·R·4^k, so
        // that m is within e of x·D·2^k.  The square root of the leading
        // bits only: M = ⌊N2²R/4^t⌋ with ≥ 2k + 16 bits, r = ⌊√M·2^k⌋·2^t;
        // √T − r ∈ [0, 2^t·(2^k(√(M+1) − √M) + 1)) and
        // 2^k(√(M+1) − √M) ≤ 2^k/(2√M) < 1, so e = 2^(t+1) + 1 (1 when
        // t = 0: the whole root, as before)
        let (an, ad) = (self.a.numer(), self.a.denom());
        let (bn, bd) = (self.b.numer(), self.b.denom());
        let (dn, dd) = (self.d.numer(), self.d.denom());
        let n1 = an * bd * dd;
        let r = dn * dd;
        let n2sq_r = bn * bn * ad * ad * &r;
        let den = ad * bd * dd;
        // the first k for a relative precision of 2^-p, p ≈ 3.33·digits +
        // 16, when nothing cancels: with |x·D| ≈ 2^b (b: the larger of the
        // two terms' bits) m is ≈ 2^(b+k) and e ≤ 2^(max(t,0)+1) + 1 with
        // t ≈ b − k − 8, so the relative error is below 2^-(2k+6) when
        // t > 0 and below 2^-(b+k−1) when t = 0; cancellation (or a value
        // near a rounding boundary) fails the test below and doubles k
        let p = (digits * 10 / 3 + 16) as i64;
        let b = (n1.bits() as i64).max(n2sq_r.bits() as i64 / 2);
        let mut k = ((p - 6 + 1) / 2).max(p - b + 1).max(8) as usize;
        loop {
            let t = ((n2sq_r.bits() as i64 - 2 * k as i64 - 16) / 2).max(0) as usize;
            let root = if t == 0 {
                (&n2sq_r << (2 * k)).sqrt()
            } else {
                ((&n2sq_r >> (2 * t)) << (2 * k)).sqrt() << t
            };
            let e = if t == 0 {
                BigInt::one()
            } else {
                (BigInt::one() << (t + 1)) + 1
            };
            let m = if bn.is_negative() {
                (&n1 << k) - root
            } else {
                (&n1 << k) + root
            };
            let d2 = &den << k;
            let (lo, hi): (BigInt, BigInt) = (&m - &e, &m + &e);
            if lo.is_positive() || hi.is_negative() {
                let a = super::approx_decimal_ratio(&lo, &d2, digits);
                if a == super::approx_decimal_ratio(&hi, &d2, digits) {
                    return a;
                }
            }
            k *= 2;
        }
    }

    /// Square root of a non-negative rational in the field Q(√d), if it lies
    /// there: `√x` for rational `x`, either rational or `b·√d` with `x/d` a
    /// rational square.
    pub(crate) fn sqrt_of_rational_in(x: &Q, d: &Q) -> Option<QSqrt> {
        if x.is_negative() {
            return None;
        }
        if let Some(r) = exact_sqrt_q(x) {
            return Some(QSqrt::rational(r));
        }
        if d.is_zero() {
            return None;
        }
        // Lehmer's gcd for the reduction (num-rational's division reduces
        // with the binary gcd: most of a long answer's time)
        let ratio = q_mul(x, &d.recip());
        exact_sqrt_q(&ratio).map(|r| QSqrt::new(Q::zero(), r, d.clone()))
    }

    /// Canonical radicand: a square-free integer `d'` with `√d = c·√d'`.
    /// Only the square part found by trial division of small primes and an
    /// exact square test is removed; the result is still exact.
    pub fn normalized(&self) -> QSqrt {
        if self.b.is_zero() {
            return self.clone();
        }
        // the radicands of one answer repeat (a curve point's ruling and
        // quadratic share one): its split is kept for the next call
        thread_local! {
            static LAST: std::cell::RefCell<Option<(Q, Split)>> =
                const { std::cell::RefCell::new(None) };
        }
        let cached = LAST.with(|l| {
            l.borrow()
                .as_ref()
                .filter(|(d, _)| d == &self.d)
                .map(|(_, s)| s.clone())
        });
        let split = match cached {
            Some(s) => s,
            None => {
                let s = self.split_radicand();
                LAST.with(|l| *l.borrow_mut() = Some((self.d.clone(), s.clone())));
                s
            }
        };
        let coef = super::q_new(split.out, self.d.denom().clone());
        match split.root {
            Some(r) => {
                QSqrt::rational(&self.a + super::q_mul(&self.b, &(coef * Q::from_integer(r))))
            }
            None => QSqrt {
                a: self.a.clone(),
                b: super::q_mul(&self.b, &coef),
                d: Q::from_integer(split.rad),
            },
        }
    }

    /// `√d = (out/den)·√rad` with the small square factors of `rad` taken
    /// out, and `√rad` when `rad` is a square.
    fn split_radicand(&self) -> Split {
        // √(n/m) = √(n·m)/m
        let mut rad = self.d.numer() * self.d.denom();
        let mut out = BigInt::one();
        // the primes below 200 (composite squares are products of these):
        // one pass over the words of rad per group of primes whose squares
        // multiply to less than 2^64, then word-size remainders
        let mut group: Vec<u64> = Vec::with_capacity(4);
        let mut i = 0;
        while i < PRIMES_BELOW_200.len() {
            let p = PRIMES_BELOW_200[i];
            if rad.bits() < 2 * (64 - p.leading_zeros() as u64) - 1 {
                break; // p² > rad
            }
            group.clear();
            let mut modulus: u64 = 1;
            while i < PRIMES_BELOW_200.len() {
                let p2 = PRIMES_BELOW_200[i] * PRIMES_BELOW_200[i];
                match modulus.checked_mul(p2) {
                    Some(m) => {
                        modulus = m;
                        group.push(PRIMES_BELOW_200[i]);
                        i += 1;
                    }
                    None => break,
                }
            }
            let r = rem_u64(&rad, modulus);
            for &p in &group {
                if !r.is_multiple_of(p * p) {
                    continue;
                }
                while rem_u64(&rad, p * p) == 0 {
                    rad /= p * p;
                    out *= p;
                }
            }
        }
        let root = {
            let r = rad.sqrt();
            (&r * &r == rad).then_some(r)
        };
        Split { out, rad, root }
    }
}

/// A radicand split by [`QSqrt::normalized`].
#[derive(Clone)]
struct Split {
    out: BigInt,
    rad: BigInt,
    root: Option<BigInt>,
}

/// `|x| mod m` (`m > 0`) by one pass over the 64-bit words, most
/// significant first, with no big temporary.
fn rem_u64(x: &BigInt, m: u64) -> u64 {
    x.magnitude().iter_u64_digits().rev().fold(0u64, |r, w| {
        ((((r as u128) << 64) | w as u128) % m as u128) as u64
    })
}

/// The primes below 200 (trial division in [`QSqrt::normalized`]).
const PRIMES_BELOW_200: [u64; 46] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
    101, 103, 107, 109, 113, 127, 131, 137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193,
    197, 199,
];

impl fmt::Display for QSqrt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.b.is_zero() {
            return write!(f, "{}", fmt_q(&self.a));
        }
        let rad = format!("√({})", fmt_q(&self.d));
        let bpart = if self.b.is_one() {
            rad
        } else if self.b == -Q::one() {
            format!("-{rad}")
        } else {
            format!("{}·{rad}", fmt_q(&self.b))
        };
        if self.a.is_zero() {
            write!(f, "{bpart}")
        } else if let Some(rest) = bpart.strip_prefix('-') {
            write!(f, "{} - {}", fmt_q(&self.a), rest)
        } else {
            write!(f, "{} + {}", fmt_q(&self.a), bpart)
        }
    }
}

impl PartialEq for QSqrt {
    /// Exact equality of the values.
    fn eq(&self, o: &QSqrt) -> bool {
        self.cmp_any(o) == Ordering::Equal
    }
}

impl Eq for QSqrt {}

impl PartialOrd for QSqrt {
    fn partial_cmp(&self, o: &QSqrt) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for QSqrt {
    /// Exact order of the values.
    fn cmp(&self, o: &QSqrt) -> Ordering {
        self.cmp_any(o)
    }
}

impl std::hash::Hash for QSqrt {
    /// Consistent with the exact equality (hashes the value, not the form).
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        // a + b√d: the rational part a, b²d and the sign of b are the
        // value's (√d is irrational), whatever the form of the radicand
        self.a.hash(state);
        if !self.b.is_zero() {
            (&self.b * &self.b * &self.d).hash(state);
            self.b.is_positive().hash(state);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{q, qi};

    /// The unit of the last digit of a printed decimal (`d.ddd…e±x` or
    /// plain), as a rational.
    fn last_digit_unit(printed: &str) -> Q {
        let (mant, exp) = match printed.split_once('e') {
            Some((m, e)) => (m, e.parse::<i64>().unwrap()),
            None => (printed, 0),
        };
        let frac = mant.split_once('.').map_or(0, |(_, f)| f.len()) as i64;
        let e = exp - frac;
        let ten = BigInt::from(10);
        if e >= 0 {
            Q::from_integer(num_traits::pow(ten, e as usize))
        } else {
            Q::new(BigInt::one(), num_traits::pow(ten, (-e) as usize))
        }
    }

    proptest::proptest! {
        /// `approx(20)` of an irrational a + b√d is its correct rounding:
        /// within half a unit of the last printed digit of the exact value
        /// (decided exactly, in Q(√d)), with 20 significant digits at most (trailing zeros dropped); also under
        /// heavy cancellation (a = −b·⌊√d·10^s⌋/10^s + ε).
        #[test]
        fn approx_of_quadratic_irrationals_is_correctly_rounded(
            bn in -10_000i64..10_000,
            bd in 1i64..1000,
            d in 2i64..100_000,
            s in 0u32..40,
            eps in -5i64..5,
            big in 0u32..3,
        ) {
            let b = Q::new(BigInt::from(bn), BigInt::from(bd)) * Q::from_integer(num_traits::pow(BigInt::from(1_000_003), big as usize));
            let dq = Q::from_integer(BigInt::from(d));
            proptest::prop_assume!(!b.is_zero() && super::super::exact_sqrt_q(&dq).is_none());
            // a ≈ −b√d to s digits, off by eps units of 10^-s
            let scale = num_traits::pow(BigInt::from(10), s as usize);
            let root = (BigInt::from(d) * &scale * &scale).sqrt();
            let a = -(&b * Q::new(root + eps, scale.clone()));
            let x = QSqrt::new(a.clone(), b.clone(), dq.clone());
            let printed = x.approx(20);
            let p = super::super::parse::parse_rational(&printed).unwrap();
            let half = last_digit_unit(&printed) / Q::from_integer(BigInt::from(2));
            // x − (p − half) > 0 and x − (p + half) < 0
            let lo = QSqrt::new(&a - (&p - &half), b.clone(), dq.clone());
            let hi = QSqrt::new(&a - (&p + &half), b.clone(), dq.clone());
            proptest::prop_assert!(lo.signum() > 0 && hi.signum() < 0, "{printed} for {a} + {b}√{d}");
            let digits = printed
                .split('e')
                .next()
                .unwrap()
                .trim_start_matches('-')
                .replace('.', "");
            // (trailing zeros are not printed)
            proptest::prop_assert!(digits.trim_start_matches('0').len() <= 20, "{}", printed);
        }
    }

    #[test]
    fn sign_and_compare() {
        // 1 - √2 < 0, 3 - √2·2 > 0 (9 > 8), 3 - 2√(9/4) = 0
        assert_eq!(QSqrt::new(qi(1), qi(-1), qi(2)).signum(), -1);
        assert_eq!(QSqrt::new(qi(3), qi(-2), qi(2)).signum(), 1);
        assert_eq!(QSqrt::new(qi(3), qi(-2), q(9, 4)).signum(), 0);
        let s2 = QSqrt::sqrt(qi(2));
        let x = s2.mul(&s2);
        assert_eq!(x, QSqrt::rational(qi(2)));
        assert_eq!(
            s2.cmp_exact(&QSqrt::rational(q(141421, 100000))),
            Ordering::Greater
        );
        assert_eq!(
            s2.cmp_exact(&QSqrt::rational(q(141422, 100000))),
            Ordering::Less
        );
        let inv = s2.inv().unwrap();
        assert_eq!(inv.mul(&s2), QSqrt::rational(qi(1)));
        assert_eq!(s2.approx(10), "1.414213562");
    }

    #[test]
    fn f64_bounded_encloses_and_is_tight_under_cancellation() {
        // (a, b, d): no cancellation, mild (3 − 1.5·√3 ≈ 0.40), strong
        // (99/70 − √2 ≈ −7.2e-5, 665857/470832 − √2 ≈ 1.6e-12)
        let cases = [
            (qi(1), qi(1), qi(2)),
            (qi(3), q(-3, 2), qi(3)),
            (qi(-3), q(3, 2), qi(3)),
            (q(99, 70), qi(-1), qi(2)),
            (q(665857, 470832), qi(-1), qi(2)),
            (q(1, 3), q(-7, 5), qi(11)),
            // a tiny coefficient of a huge radicand (a curve branch's ruling)
            (
                qi(0),
                Q::new(
                    BigInt::from(-1),
                    "1772303994379887832075638086516255403".parse().unwrap(),
                ),
                Q::from_integer(
                    "2724436517094913528924234705567029378355482133044366905"
                        .parse()
                        .unwrap(),
                ),
            ),
        ];
        for (a, b, d) in cases {
            let x = QSqrt::new(a, b, d);
            let (v, bound) = x.to_f64_bounded();
            let (vq, bq) = (Q::from_float(v).unwrap(), Q::from_float(bound).unwrap());
            assert!(
                QSqrt::rational(&vq - &bq).cmp_exact(&x) != Ordering::Greater,
                "{x:?}"
            );
            assert!(
                QSqrt::rational(&vq + &bq).cmp_exact(&x) != Ordering::Less,
                "{x:?}"
            );
            // at most 2^-46·|v| (64 units in the last place at worst)
            assert!(
                bound <= v.abs() / 70_368_744_177_664.0,
                "{x:?}: {v} ± {bound}"
            );
        }
    }

    #[test]
    fn normalize_radicand() {
        let x = QSqrt::new(qi(0), qi(1), q(8, 9)).normalized();
        assert_eq!(x.d, qi(2));
        assert_eq!(x.b, q(2, 3));
    }
}
