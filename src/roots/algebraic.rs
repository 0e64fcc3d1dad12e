//! Real algebraic numbers: a square-free integer defining polynomial and an
//! isolating interval, with exact comparison and exact sign of another
//! polynomial at the number (zero detected by a gcd, never by a tolerance).

use super::isolate::{RootInterval, bisect_once, isolate_squarefree, refine, sign_variations};
use crate::number::{Q, approx_decimal, fmt_q};
use crate::poly::ZPoly;
use crate::poly::mpoly::{MPoly, U};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// An exact real algebraic number.
#[derive(Clone, Debug)]
pub enum RealAlg {
    /// A rational number.
    Rational(Q),
    /// The unique root of `poly` (square-free, primitive, positive leading
    /// coefficient) in the open interval `(lo, hi)`; neither end is a root.
    Root {
        /// Defining polynomial.
        poly: ZPoly,
        /// Lower end of the isolating interval.
        lo: Q,
        /// Upper end.
        hi: Q,
    },
}

impl RealAlg {
    /// A rational value.
    pub fn rational(q: Q) -> RealAlg {
        RealAlg::Rational(q)
    }

    /// The root of the square-free `poly` isolated by `iv`.  An exact
    /// interval gives a rational.
    pub fn from_interval(poly: &ZPoly, iv: &RootInterval) -> RealAlg {
        Self::from_primitive(&poly.primitive_part(), iv)
    }

    /// [`RealAlg::from_interval`] for a `poly` already primitive with a
    /// positive leading coefficient (e.g. from
    /// [`ZPoly::squarefree_part`]): no content computed again.
    pub fn from_primitive(poly: &ZPoly, iv: &RootInterval) -> RealAlg {
        debug_assert!(poly.content().is_one() && poly.lc().is_positive());
        if iv.is_exact() {
            RealAlg::Rational(iv.lo.clone())
        } else {
            RealAlg::Root {
                poly: poly.clone(),
                lo: iv.lo.clone(),
                hi: iv.hi.clone(),
            }
        }
    }

    /// All real roots of `p` (any non-zero polynomial), increasing.
    ///
    /// ```
    /// use quadsect::roots::RealAlg;
    /// use quadsect::poly::ZPoly;
    /// let r = RealAlg::roots_of(&ZPoly::from_i64s(&[-2, 0, 1]));
    /// assert_eq!(r.len(), 2);
    /// assert_eq!(r[0].approx(6), "-1.41421");
    /// ```
    pub fn roots_of(p: &ZPoly) -> Vec<RealAlg> {
        if p.degree().unwrap_or(0) == 0 {
            return vec![];
        }
        let sq = p.squarefree_part();
        isolate_squarefree(&sq)
            .iter()
            .map(|iv| RealAlg::from_primitive(&sq, iv))
            .collect()
    }

    /// The same number, as a `Rational` when it is a rational of moderate
    /// height (a representation change only: the value is exact either way).
    ///
    /// The simplest rational in a narrow isolating interval is the only
    /// candidate of small height, and one exact evaluation tests it.  The
    /// widths tried are 2^-16, 2^-64 and finally `1/(2 lc²)` (capped at
    /// 2^-2048) — at that width the test is complete, since a rational root
    /// `a/b` has `b | lc` and two such rationals are `1/lc²` apart.
    pub fn simplify(&self) -> RealAlg {
        let RealAlg::Root { poly, .. } = self else {
            return self.clone();
        };
        if super::rational::no_rational_root_sieve(poly) {
            return self.clone();
        }
        let l = num_traits::Signed::abs(&poly.lc());
        let complete = 2 * l.bits() + 1;
        let mut c = self.clone();
        for bits in [16u64, 64, complete.min(2048)] {
            c.refine_to(&Q::new(BigInt::one(), BigInt::one() << bits as usize));
            if c.as_rational().is_some() {
                return c;
            }
            if let RealAlg::Root { poly, lo, hi } = &c {
                let cand = super::rational::simplest_rational_in(lo, hi);
                if poly.sign_at(&cand) == 0 {
                    return RealAlg::Rational(cand);
                }
            }
            if bits >= complete {
                break;
            }
        }
        // keep the original (coarser, shorter) interval
        self.clone()
    }

    /// The isolating interval `(lo, hi)` (equal ends for a rational).
    pub fn interval(&self) -> (Q, Q) {
        match self {
            RealAlg::Rational(q) => (q.clone(), q.clone()),
            RealAlg::Root { lo, hi, .. } => (lo.clone(), hi.clone()),
        }
    }

    /// The defining polynomial (`d·u - n` for a rational `n/d`).
    pub fn poly(&self) -> ZPoly {
        match self {
            RealAlg::Rational(q) => ZPoly::new(vec![-q.numer().clone(), q.denom().clone()]),
            RealAlg::Root { poly, .. } => poly.clone(),
        }
    }

    /// The defining polynomial printed in the variable `u`.
    pub fn poly_string(&self) -> String {
        MPoly::from_univariate(&self.poly(), U).to_string_canonical()
    }

    /// True when the value is rational (known exactly).
    pub fn as_rational(&self) -> Option<&Q> {
        match self {
            RealAlg::Rational(q) => Some(q),
            _ => None,
        }
    }

    /// Bisects the isolating interval once (a rational stays as it is; a
    /// midpoint that is the root turns the number into a rational).
    pub fn bisect(&mut self) {
        if let RealAlg::Root { poly, lo, hi } = self {
            let mut iv = RootInterval {
                lo: lo.clone(),
                hi: hi.clone(),
            };
            bisect_once(poly, &mut iv);
            if iv.is_exact() {
                *self = RealAlg::Rational(iv.lo);
            } else {
                *lo = iv.lo;
                *hi = iv.hi;
            }
        }
    }

    /// Refines until the interval is at most `width` wide.
    pub fn refine_to(&mut self, width: &Q) {
        if let RealAlg::Root { poly, lo, hi } = self {
            let mut iv = RootInterval {
                lo: lo.clone(),
                hi: hi.clone(),
            };
            refine(poly, &mut iv, width);
            if iv.is_exact() {
                *self = RealAlg::Rational(iv.lo);
            } else {
                *lo = iv.lo;
                *hi = iv.hi;
            }
        }
    }

    /// A rational approximation within `2^-bits`.
    pub fn to_rational_approx(&self, bits: u32) -> Q {
        let mut c = self.clone();
        let w = Q::new(BigInt::one(), BigInt::one() << bits as usize);
        c.refine_to(&w);
        let (lo, hi) = c.interval();
        (lo + hi) / Q::from_integer(BigInt::from(2))
    }

    /// Decimal approximation with `digits` significant digits.
    pub fn approx(&self, digits: usize) -> String {
        match self {
            RealAlg::Rational(q) => approx_decimal(q, digits),
            RealAlg::Root { lo, hi, .. } => {
                // enough bits for the requested relative precision
                let mag = lo.numer().bits().max(hi.numer().bits()) as i64
                    - lo.denom().bits().min(hi.denom().bits()) as i64;
                let bits = (digits as f64 * 3.33) as i64 + 16 + (-mag).max(0);
                approx_decimal(&self.to_rational_approx(bits.max(8) as u32), digits)
            }
        }
    }

    /// Exact sign of the number: -1, 0 or 1.
    pub fn sign(&self) -> i32 {
        self.cmp_rational(&Q::zero()) as i32
    }

    /// Exact comparison with a rational.
    pub fn cmp_rational(&self, r: &Q) -> Ordering {
        match self {
            RealAlg::Rational(q) => q.cmp(r),
            RealAlg::Root { poly, lo, hi } => {
                if r <= lo {
                    return Ordering::Greater;
                }
                if r >= hi {
                    return Ordering::Less;
                }
                let s = poly.sign_at(r);
                if s == 0 {
                    return Ordering::Equal;
                }
                if s == poly.sign_at(lo) {
                    // r lies between lo and the root
                    Ordering::Greater
                } else {
                    Ordering::Less
                }
            }
        }
    }

    /// Exact comparison of two real algebraic numbers.  Equality is decided
    /// by the gcd of the defining polynomials; otherwise the intervals are
    /// refined until they separate.
    pub fn cmp_exact(&self, other: &RealAlg) -> Ordering {
        match (self, other) {
            (RealAlg::Rational(a), RealAlg::Rational(b)) => a.cmp(b),
            (_, RealAlg::Rational(b)) => self.cmp_rational(b),
            (RealAlg::Rational(a), _) => other.cmp_rational(a).reverse(),
            (RealAlg::Root { poly: pa, .. }, RealAlg::Root { poly: pb, .. }) => {
                let mut a = self.clone();
                let mut b = other.clone();
                let g = if pa == pb { pa.clone() } else { pa.gcd(pb) };
                let mut equal_checked = false;
                loop {
                    if let Some(x) = a.as_rational() {
                        return b.cmp_rational(x).reverse();
                    }
                    if let Some(x) = b.as_rational() {
                        return a.cmp_rational(x);
                    }
                    let (alo, ahi) = a.interval();
                    let (blo, bhi) = b.interval();
                    // open intervals: a < ahi <= blo < b
                    if ahi <= blo {
                        return Ordering::Less;
                    }
                    if bhi <= alo {
                        return Ordering::Greater;
                    }
                    if !equal_checked && g.degree().unwrap_or(0) > 0 {
                        equal_checked = true;
                        // intersection J of the two intervals; g has at most one
                        // root there, and it is then both numbers
                        let jlo = if alo > blo { alo.clone() } else { blo.clone() };
                        let jhi = if ahi < bhi { ahi.clone() } else { bhi.clone() };
                        if jlo < jhi && g.sign_at(&jlo) * g.sign_at(&jhi) < 0 {
                            return Ordering::Equal;
                        }
                    }
                    a.bisect();
                    b.bisect();
                }
            }
        }
    }

    /// Exact sign of `q(self)` for an integer polynomial `q`.
    ///
    /// Zero is decided by `gcd(poly, q)` having the root in the interval;
    /// otherwise the interval is refined until `q` has no root in it
    /// (Descartes' test on the interval), and `q` is evaluated at an end.
    pub fn sign_of(&self, q: &ZPoly) -> i32 {
        match self {
            RealAlg::Rational(r) => q.sign_at(r),
            RealAlg::Root { poly, lo, hi } => {
                if q.is_zero() {
                    return 0;
                }
                if q.degree() == Some(0) {
                    return crate::number::sign_z(&q.lc());
                }
                let g = poly.gcd(q);
                if g.degree().unwrap_or(0) > 0 && g.sign_at(lo) * g.sign_at(hi) < 0 {
                    return 0;
                }
                let mut iv = RootInterval {
                    lo: lo.clone(),
                    hi: hi.clone(),
                };
                loop {
                    if q.sign_at(&iv.lo) != 0 && !has_root_in_open(q, &iv.lo, &iv.hi) {
                        return q.sign_at(&iv.lo);
                    }
                    bisect_once(poly, &mut iv);
                    if iv.is_exact() {
                        return q.sign_at(&iv.lo);
                    }
                }
            }
        }
    }

    /// Exact sign of `q(self)` for a rational polynomial.
    pub fn sign_of_q(&self, q: &crate::poly::QPoly) -> i32 {
        let (z, k) = ZPoly::from_q(q);
        crate::number::sign_q(&k) * self.sign_of(&z)
    }

    /// Interval `[lo, hi]` strings and the defining polynomial, for output.
    pub fn describe(&self) -> (String, [String; 2], String) {
        let (lo, hi) = self.interval();
        (
            self.poly_string(),
            [fmt_q(&lo), fmt_q(&hi)],
            self.approx(20),
        )
    }
}

/// Refines the isolating intervals of increasing, distinct real algebraic
/// numbers until consecutive intervals are strictly separated
/// (`hi_i < lo_{i+1}`), so that a rational fits between any two.
pub fn separate(values: &mut [RealAlg]) {
    for i in 0..values.len().saturating_sub(1) {
        loop {
            let (_, hi) = values[i].interval();
            let (lo, _) = values[i + 1].interval();
            if hi < lo {
                break;
            }
            values[i].bisect();
            values[i + 1].bisect();
        }
    }
}

/// True when `q` may have a root in the open interval `(a, b)`: Descartes'
/// test of `q` transformed to `(0, ∞)`; `false` is a proof of no root.
pub fn has_root_in_open(q: &ZPoly, a: &Q, b: &Q) -> bool {
    let n = match q.degree() {
        Some(n) if n > 0 => n,
        _ => return false,
    };
    // x = (a + b t)/(1 + t) maps (0, ∞) to (a, b): with a = a1/d, b = b1/d,
    // (1+t)^n d^n q(x) = Σ c_i (a1 + b1 t)^i (d (1 + t))^(n-i)
    let d = num_integer::Integer::lcm(a.denom(), b.denom());
    let a1 = a.numer() * (&d / a.denom());
    let b1 = b.numer() * (&d / b.denom());
    let lin_ab = ZPoly::new(vec![a1, b1]);
    let lin_d = ZPoly::new(vec![d.clone(), d]);
    let mut pow_ab = vec![ZPoly::constant(BigInt::one())];
    let mut pow_d = vec![ZPoly::constant(BigInt::one())];
    for i in 1..=n {
        pow_ab.push(&pow_ab[i - 1] * &lin_ab);
        pow_d.push(&pow_d[i - 1] * &lin_d);
    }
    let mut acc = ZPoly::zero();
    for (i, c) in q.coeffs().iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        acc = &acc + &(&pow_ab[i] * &pow_d[n - i]).scale(c);
    }
    sign_variations(acc.coeffs()) > 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    #[test]
    fn compare_and_sign() {
        let s2 = RealAlg::roots_of(&ZPoly::from_i64s(&[-2, 0, 1]))[1].clone();
        let s8 = RealAlg::roots_of(&ZPoly::from_i64s(&[-8, 0, 1]))[1].clone();
        // √8 = 2√2 > √2, and √2·√2 - 2 = 0 as a sign query
        assert_eq!(s2.cmp_exact(&s8), Ordering::Less);
        assert_eq!(s2.sign_of(&ZPoly::from_i64s(&[-2, 0, 1])), 0);
        assert_eq!(s2.sign_of(&ZPoly::from_i64s(&[-3, 2])), -1); // 2√2 - 3 < 0
        assert_eq!(s2.cmp_rational(&q(7, 5)), Ordering::Greater);
        // equal numbers with different defining polynomials
        let a = RealAlg::roots_of(&(&ZPoly::from_i64s(&[-2, 0, 1]) * &ZPoly::from_i64s(&[-3, 1])))
            .into_iter()
            .nth(1)
            .unwrap();
        assert_eq!(a.cmp_exact(&s2), Ordering::Equal);
        assert_eq!(s2.approx(20), "1.4142135623730950488");
    }
}
