//! Dense univariate polynomials over any [`Ring`], with the ring operations
//! as operator traits on references (`&a * &b`), evaluation, derivative and
//! pseudo-division.  Z- and Q-specific algorithms (content, gcd, square-free
//! factorisation, Taylor shifts, root bounds) are in [`crate::poly::zpoly`].

use super::ring::Ring;
use std::ops::{Add, Mul, Neg, Sub};

/// A dense univariate polynomial `c[0] + c[1] x + … + c[n] x^n`.
///
/// Invariant: the leading coefficient `c[n]` is non-zero; the zero
/// polynomial has no coefficients.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct UPoly<R> {
    c: Vec<R>,
}

impl<R: Ring> UPoly<R> {
    /// The polynomial with the given coefficients (ascending powers); trailing
    /// zeros are removed.
    pub fn new(mut c: Vec<R>) -> Self {
        while c.last().is_some_and(|x| x.ris_zero()) {
            c.pop();
        }
        UPoly { c }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        UPoly { c: Vec::new() }
    }

    /// The constant polynomial `a`.
    pub fn constant(a: R) -> Self {
        UPoly::new(vec![a])
    }

    /// The monomial `a x^k`.
    pub fn monomial(a: R, k: usize) -> Self {
        if a.ris_zero() {
            return UPoly::zero();
        }
        let mut c = vec![R::rzero(); k + 1];
        c[k] = a;
        UPoly { c }
    }

    /// The polynomial `x`.
    pub fn x() -> Self {
        UPoly::monomial(R::rone(), 1)
    }

    /// From small integer coefficients (ascending).
    pub fn from_i64s(cs: &[i64]) -> Self {
        UPoly::new(cs.iter().map(|&v| R::from_i64(v)).collect())
    }

    /// Coefficients in ascending order of powers.
    pub fn coeffs(&self) -> &[R] {
        &self.c
    }

    /// Consumes the polynomial, returning its coefficients.
    pub fn into_coeffs(self) -> Vec<R> {
        self.c
    }

    /// The coefficient of `x^i` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> R {
        self.c.get(i).cloned().unwrap_or_else(R::rzero)
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// Degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    /// Degree with the convention `deg 0 = -1`.
    pub fn deg(&self) -> i64 {
        self.c.len() as i64 - 1
    }

    /// Leading coefficient (zero for the zero polynomial).
    pub fn lc(&self) -> R {
        self.c.last().cloned().unwrap_or_else(R::rzero)
    }

    /// Reference to the leading coefficient.
    pub fn lc_ref(&self) -> Option<&R> {
        self.c.last()
    }

    /// Value at `a` (Horner's rule).
    pub fn eval(&self, a: &R) -> R {
        let mut acc = R::rzero();
        for c in self.c.iter().rev() {
            crate::budget::check();
            acc = acc.rmul(a);
            acc.radd_assign(c);
        }
        acc
    }

    /// Formal derivative.
    pub fn derivative(&self) -> Self {
        if self.c.len() <= 1 {
            return UPoly::zero();
        }
        UPoly::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c.rmul(&R::from_i64(i as i64)))
                .collect(),
        )
    }

    /// Multiplication by a scalar.
    pub fn scale(&self, k: &R) -> Self {
        if k.ris_zero() {
            return UPoly::zero();
        }
        UPoly::new(self.c.iter().map(|c| c.rmul(k)).collect())
    }

    /// Exact division of every coefficient by `k`; `None` if some division
    /// is not exact.
    pub fn div_exact_scalar(&self, k: &R) -> Option<Self> {
        let mut out = Vec::with_capacity(self.c.len());
        for c in &self.c {
            out.push(c.div_exact(k)?);
        }
        Some(UPoly::new(out))
    }

    /// Multiplication by `x^k`.
    pub fn shift_up(&self, k: usize) -> Self {
        if self.ris_zero() {
            return UPoly::zero();
        }
        let mut c = vec![R::rzero(); k];
        c.extend(self.c.iter().cloned());
        UPoly { c }
    }

    /// Applies `f` to every coefficient.
    pub fn map<S: Ring>(&self, f: impl Fn(&R) -> S) -> UPoly<S> {
        UPoly::new(self.c.iter().map(f).collect())
    }

    /// Pseudo-division: returns `(q, r)` with
    /// `lc(b)^(deg a - deg b + 1) · a = q·b + r` and `deg r < deg b`.
    /// When `deg a < deg b` the result is `(0, a)` (no scaling).
    /// Panics if `b` is zero.
    pub fn pseudo_divrem(&self, b: &Self) -> (Self, Self) {
        let db = b.degree().expect("pseudo-division by the zero polynomial");
        let da = match self.degree() {
            Some(d) if d >= db => d,
            _ => return (UPoly::zero(), self.clone()),
        };
        let lb = b.lc();
        let mut r = self.c.clone();
        let mut q = vec![R::rzero(); da - db + 1];
        for k in (0..=da - db).rev() {
            crate::budget::check();
            // r := lb·r − r[k+db]·x^k·b, q := lb·q + r[k+db]·x^k
            let t = r[k + db].clone();
            for qi in q.iter_mut() {
                *qi = qi.rmul(&lb);
            }
            q[k].radd_assign(&t);
            for ri in r.iter_mut().take(k + db + 1) {
                *ri = ri.rmul(&lb);
            }
            if !t.ris_zero() {
                for (j, bj) in b.c.iter().enumerate() {
                    r[k + j].rsub_assign(&t.rmul(bj));
                }
            }
            r.truncate(k + db);
        }
        (UPoly::new(q), UPoly::new(r))
    }

    /// Pseudo-remainder `prem(a, b)`: `lc(b)^(deg a - deg b + 1)·a mod b`.
    pub fn pseudo_rem(&self, b: &Self) -> Self {
        let db = b.degree().expect("pseudo-division by the zero polynomial");
        let da = match self.degree() {
            Some(d) if d >= db => d,
            _ => return self.clone(),
        };
        let lb = b.lc();
        let mut r = self.c.clone();
        for k in (0..=da - db).rev() {
            crate::budget::check();
            let t = r[k + db].clone();
            for ri in r.iter_mut().take(k + db) {
                *ri = ri.rmul(&lb);
            }
            if !t.ris_zero() {
                for (j, bj) in b.c.iter().enumerate().take(db) {
                    r[k + j].rsub_assign(&t.rmul(bj));
                }
            }
            r.truncate(k + db);
        }
        UPoly::new(r)
    }

    /// Exact polynomial division `self / b` over a ring with exact division:
    /// `Some(q)` with `q·b = self`, `None` if `b` does not divide `self`.
    pub fn div_exact(&self, b: &Self) -> Option<Self> {
        let db = b.degree()?;
        let Some(da) = self.degree() else {
            return Some(UPoly::zero());
        };
        if da < db {
            return None;
        }
        let lb = b.lc();
        let mut r = self.c.clone();
        let mut q = vec![R::rzero(); da - db + 1];
        for k in (0..=da - db).rev() {
            crate::budget::check();
            let t = r[k + db].div_exact(&lb)?;
            if !t.ris_zero() {
                for (j, bj) in b.c.iter().enumerate() {
                    r[k + j].rsub_assign(&t.rmul(bj));
                }
            }
            q[k] = t;
        }
        if r.iter().all(|x| x.ris_zero()) {
            Some(UPoly::new(q))
        } else {
            None
        }
    }

    /// `self^e`.
    pub fn pow(&self, e: u32) -> Self {
        let mut r = UPoly::constant(R::rone());
        let mut b = self.clone();
        let mut e = e;
        while e > 0 {
            if e & 1 == 1 {
                r = &r * &b;
            }
            e >>= 1;
            if e > 0 {
                b = &b * &b;
            }
        }
        r
    }

    /// Composition `self(g(x))` (Horner).
    pub fn compose(&self, g: &Self) -> Self {
        let mut acc = UPoly::zero();
        for c in self.c.iter().rev() {
            crate::budget::check();
            acc = &(&acc * g) + &UPoly::constant(c.clone());
        }
        acc
    }
}

impl<R: Ring> Add for &UPoly<R> {
    type Output = UPoly<R>;
    fn add(self, o: &UPoly<R>) -> UPoly<R> {
        let (long, short) = if self.c.len() >= o.c.len() {
            (self, o)
        } else {
            (o, self)
        };
        let mut c = long.c.clone();
        for (ci, si) in c.iter_mut().zip(short.c.iter()) {
            ci.radd_assign(si);
        }
        UPoly::new(c)
    }
}

impl<R: Ring> Sub for &UPoly<R> {
    type Output = UPoly<R>;
    fn sub(self, o: &UPoly<R>) -> UPoly<R> {
        let n = self.c.len().max(o.c.len());
        let mut c = Vec::with_capacity(n);
        for i in 0..n {
            match (self.c.get(i), o.c.get(i)) {
                (Some(a), Some(b)) => c.push(a.rsub(b)),
                (Some(a), None) => c.push(a.clone()),
                (None, Some(b)) => c.push(b.rneg()),
                (None, None) => unreachable!(),
            }
        }
        UPoly::new(c)
    }
}

/// `⌈log₂ n⌉` (the bits a sum of `n` terms can add), 0 for `n <= 1`.
pub(crate) fn log2_ceil(n: usize) -> u64 {
    (usize::BITS - n.saturating_sub(1).leading_zeros()) as u64
}

impl<R: Ring> Mul for &UPoly<R> {
    type Output = UPoly<R>;
    fn mul(self, o: &UPoly<R>) -> UPoly<R> {
        if self.ris_zero() || o.ris_zero() {
            return UPoly::zero();
        }
        let len = self.c.len() + o.c.len() - 1;
        // the size of the product from the operands: all coefficients for
        // long polynomials, the leading ones (O(1)) for short ones
        let bits = if len > crate::poly::zpoly::SHORT {
            self.bit_size() + o.bit_size() + log2_ceil(self.c.len().min(o.c.len()))
        } else {
            let lead = |p: &UPoly<R>| p.c.last().map_or(0, R::bit_size);
            lead(self) + lead(o) + log2_ceil(self.c.len().min(o.c.len()))
        };
        crate::budget::check_size("a product of polynomials", len, bits);
        let mut c = vec![R::rzero(); len];
        for (i, a) in self.c.iter().enumerate() {
            if a.ris_zero() {
                continue;
            }
            crate::budget::check();
            for (j, b) in o.c.iter().enumerate() {
                c[i + j].radd_assign(&a.rmul(b));
            }
        }
        UPoly::new(c)
    }
}

impl<R: Ring> Neg for &UPoly<R> {
    type Output = UPoly<R>;
    fn neg(self) -> UPoly<R> {
        UPoly {
            c: self.c.iter().map(|x| x.rneg()).collect(),
        }
    }
}

super::macros::forward_owned_ops!(UPoly, R);

/// Polynomials over a ring form a ring (used for the recursive
/// representation R[y][x] in elimination).
impl<R: Ring> Ring for UPoly<R> {
    fn rzero() -> Self {
        UPoly::zero()
    }
    fn rone() -> Self {
        UPoly::constant(R::rone())
    }
    fn from_i64(n: i64) -> Self {
        UPoly::constant(R::from_i64(n))
    }
    fn ris_zero(&self) -> bool {
        self.c.is_empty()
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
    fn div_exact(&self, o: &Self) -> Option<Self> {
        UPoly::div_exact(self, o)
    }
    fn bit_size(&self) -> u64 {
        self.c.iter().map(R::bit_size).max().unwrap_or(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    type P = UPoly<BigInt>;

    #[test]
    fn ring_ops() {
        let a = P::from_i64s(&[1, 1]); // x + 1
        let b = P::from_i64s(&[-1, 1]); // x - 1
        assert_eq!(&a * &b, P::from_i64s(&[-1, 0, 1]));
        assert_eq!(&a - &a, P::zero());
        assert_eq!(&a + &b, P::from_i64s(&[0, 2]));
        assert_eq!(a.pow(3), P::from_i64s(&[1, 3, 3, 1]));
        assert_eq!(a.eval(&BigInt::from(4)), BigInt::from(5));
        assert_eq!(a.pow(3).derivative(), P::from_i64s(&[3, 6, 3]));
    }

    #[test]
    fn pseudo_division_identity() {
        let a = P::from_i64s(&[3, -2, 0, 5, 7]);
        let b = P::from_i64s(&[1, 0, 3]);
        let (q, r) = a.pseudo_divrem(&b);
        let k = b.lc().pow(3);
        assert_eq!(a.scale(&k), &(&q * &b) + &r);
        assert_eq!(r, a.pseudo_rem(&b));
        assert!(r.deg() < 2);
        let prod = &a * &b;
        assert_eq!(prod.div_exact(&b), Some(a.clone()));
        assert_eq!(a.div_exact(&b), None);
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_new() {
        use crate::poly::ZPoly;
        use num_bigint::BigInt;
        let p = ZPoly::new(vec![BigInt::from(1), BigInt::from(0), BigInt::from(0)]);
        assert_eq!(p.degree(), Some(0));
    }
}
