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
#[inline]
fn check_pair(a: &BigRational, b: &BigRational) {
    let bits = a.numer().bits().max(a.denom().bits());
    let bits = bits.max(b.numer().bits()).max(b.denom().bits());
    if bits > crate::budget::LARGE_BITS {
        crate::budget::check_now();
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
        check_pair(self, o);
        self + o
    }
    fn rsub(&self, o: &Self) -> Self {
        check_pair(self, o);
        self - o
    }
    fn rmul(&self, o: &Self) -> Self {
        check_pair(self, o);
        self * o
    }
    fn rneg(&self) -> Self {
        -self
    }
    fn radd_assign(&mut self, o: &Self) {
        check_pair(self, o);
        *self += o;
    }
    fn rsub_assign(&mut self, o: &Self) {
        check_pair(self, o);
        *self -= o;
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
