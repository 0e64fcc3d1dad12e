//! The coefficient rings of quadsect's polynomials.
//!
//! Elimination works over integral domains with *exact division*: the
//! subresultant PRS and Bareiss' determinant divide only by quantities known
//! to divide exactly.  The same generic code therefore runs over Z, Q, and
//! multivariate polynomial rings Z[y, z, …] (which is how the tangent point
//! method eliminates one variable after another).

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::fmt::Debug;

/// An integral domain with exact division.
pub trait Ring: Clone + PartialEq + Debug {
    /// Additive identity.
    fn rzero() -> Self;
    /// Multiplicative identity.
    fn rone() -> Self;
    /// The image of a machine integer.
    fn from_i64(n: i64) -> Self;
    /// True for the additive identity.
    fn ris_zero(&self) -> bool;
    /// True for the multiplicative identity.
    fn ris_one(&self) -> bool {
        *self == Self::rone()
    }
    /// `self + o`.
    fn radd(&self, o: &Self) -> Self;
    /// `self - o`.
    fn rsub(&self, o: &Self) -> Self;
    /// `self * o`.
    fn rmul(&self, o: &Self) -> Self;
    /// `-self`.
    fn rneg(&self) -> Self;
    /// `self += o` (in place where the type allows it).
    fn radd_assign(&mut self, o: &Self) {
        *self = self.radd(o);
    }
    /// `self -= o`.
    fn rsub_assign(&mut self, o: &Self) {
        *self = self.rsub(o);
    }
    /// `self / o` when `o` divides `self` exactly, otherwise `None`.
    fn div_exact(&self, o: &Self) -> Option<Self>;
    /// The bit size of the largest integer stored (numerator plus
    /// denominator for a rational, the largest coefficient for a
    /// polynomial): what the size budget ([`crate::budget::check_size`])
    /// measures.
    fn bit_size(&self) -> u64 {
        0
    }
    /// `self^e` by repeated squaring.
    fn rpow(&self, mut e: u32) -> Self {
        let mut base = self.clone();
        let mut r = Self::rone();
        while e > 0 {
            if e & 1 == 1 {
                r = r.rmul(&base);
            }
            e >>= 1;
            if e > 0 {
                base = base.rmul(&base);
            }
        }
        r
    }
}

impl Ring for BigInt {
    fn rzero() -> Self {
        Zero::zero()
    }
    fn rone() -> Self {
        One::one()
    }
    fn from_i64(n: i64) -> Self {
        BigInt::from(n)
    }
    fn ris_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn ris_one(&self) -> bool {
        One::is_one(self)
    }
    fn radd(&self, o: &Self) -> Self {
        self + o
    }
    fn rsub(&self, o: &Self) -> Self {
        self - o
    }
    fn rmul(&self, o: &Self) -> Self {
        self * o
    }
    fn rneg(&self) -> Self {
        -self
    }
    fn radd_assign(&mut self, o: &Self) {
        *self += o;
    }
    fn rsub_assign(&mut self, o: &Self) {
        *self -= o;
    }
    fn bit_size(&self) -> u64 {
        self.bits()
    }
    fn div_exact(&self, o: &Self) -> Option<Self> {
        if Zero::is_zero(o) {
            return None;
        }
        let (q, r) = self.div_rem(o);
        if Zero::is_zero(&r) { Some(q) } else { None }
    }
}

/// The budget check before a rational operation on large numbers (each
/// one computes a gcd, whose cost grows quadratically with their size);
/// operations on small numbers leave the checks to the loops around them.
/// `true` when the operands are large: the caller then reduces with
/// [`crate::number::q_add`] / [`crate::number::q_mul`] (Lehmer's gcd)
/// instead of num-rational's operators.
#[inline]
fn check_pair(a: &BigRational, b: &BigRational) -> bool {
    let bits = a.numer().bits().max(a.denom().bits());
    let bits = bits.max(b.numer().bits()).max(b.denom().bits());
    if bits > crate::budget::LARGE_BITS {
        crate::budget::check_now();
        true
    } else {
        false
    }
}

impl Ring for BigRational {
    fn rzero() -> Self {
        Zero::zero()
    }
    fn rone() -> Self {
        One::one()
    }
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }
    fn ris_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn radd(&self, o: &Self) -> Self {
        if check_pair(self, o) {
            crate::number::q_add(self, o)
        } else {
            self + o
        }
    }
    fn rsub(&self, o: &Self) -> Self {
        if check_pair(self, o) {
            crate::number::q_sub(self, o)
        } else {
            self - o
        }
    }
    fn rmul(&self, o: &Self) -> Self {
        if check_pair(self, o) {
            crate::number::q_mul(self, o)
        } else {
            self * o
        }
    }
    fn rneg(&self) -> Self {
        -self
    }
    fn radd_assign(&mut self, o: &Self) {
        if check_pair(self, o) {
            *self = crate::number::q_add(self, o);
        } else {
            *self += o;
        }
    }
    fn rsub_assign(&mut self, o: &Self) {
        if check_pair(self, o) {
            *self = crate::number::q_sub(self, o);
        } else {
            *self -= o;
        }
    }
    fn bit_size(&self) -> u64 {
        self.numer().bits() + self.denom().bits()
    }
    fn div_exact(&self, o: &Self) -> Option<Self> {
        if Zero::is_zero(o) {
            None
        } else {
            Some(self / o)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Large rationals with shared prime factors (so that the gcds have
    /// work to do), integers, both signs and zero.
    fn samples() -> Vec<BigRational> {
        let p = |b: u32, e: usize| num_traits::pow(BigInt::from(b), e);
        let mut out = vec![BigRational::zero(), BigRational::one()];
        for (i, (n, d)) in [
            (p(3, 12_000), BigInt::one()),
            (p(2, 20_000) * p(7, 3), BigInt::one()),
            (p(3, 11_000) * 5, p(2, 17_000)),
            (BigInt::one(), p(2, 17_000) * p(3, 500)),
            (p(5, 9_000) + 1, p(6, 7_000)),
            (BigInt::from(7), p(10, 5_000)),
            (p(6, 7_000) - 1, p(35, 4_000)),
        ]
        .into_iter()
        .enumerate()
        {
            let q = BigRational::new(n, d);
            out.push(if i % 2 == 0 { -q.clone() } else { q.clone() });
            out.push(q.recip());
        }
        out
    }

    /// The gcd-free / fast-gcd operations on large operands give exactly
    /// num-rational's results (lowest terms, positive denominator).
    #[test]
    fn large_rational_operations_agree_with_num_rational() {
        let v = samples();
        for a in &v {
            for b in &v {
                let (sum, diff, prod) = (a.radd(b), a.rsub(b), a.rmul(b));
                assert_eq!(sum, a + b);
                assert_eq!(diff, a - b);
                assert_eq!(prod, a * b);
                for r in [&sum, &diff, &prod] {
                    // in lowest terms: the fields equal a fresh reduction
                    let fresh = BigRational::new(r.numer().clone(), r.denom().clone());
                    assert_eq!((r.numer(), r.denom()), (fresh.numer(), fresh.denom()));
                }
                let mut s = a.clone();
                s.radd_assign(b);
                assert_eq!(s, sum);
                let mut d = a.clone();
                d.rsub_assign(b);
                assert_eq!(d, diff);
            }
        }
    }
}
