//! Rational roots without factoring integers: a rational root `a/b` (lowest
//! terms) of a primitive `p ∈ Z[x]` has `b | lc(p)`; two rationals with
//! denominators `<= L` differ by at least `1/L²`, so once an isolating
//! interval is narrower than that, the simplest rational inside it (by
//! continued fractions) is the only candidate, and one exact evaluation
//! decides.

use super::isolate::{isolate_squarefree, refine};
use crate::number::Q;
use crate::poly::ZPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The rational with the smallest denominator in the open interval
/// `(lo, hi)` (`lo < hi`), by the continued-fraction (Stern–Brocot) rule.
pub fn simplest_rational_in(lo: &Q, hi: &Q) -> Q {
    debug_assert!(lo < hi);
    if lo.is_negative() && hi.is_positive() {
        return Q::zero();
    }
    if !hi.is_positive() {
        return -simplest_rational_in(&-hi, &-lo);
    }
    // 0 <= lo < hi
    let fl = lo.floor();
    if &(&fl + Q::one()) < hi {
        // the integer floor(lo) + 1 lies strictly inside
        return fl + Q::one();
    }
    // lo and hi share the integer part n (or hi = n + 1 exactly)
    let n = fl;
    let a = lo - &n;
    let b = hi - &n;
    if a.is_zero() {
        // (n, n + b): the simplest is n + 1/k with k = floor(1/b) + 1
        let k = (Q::one() / &b).floor() + Q::one();
        return n + Q::one() / k;
    }
    // n + 1 / simplest in (1/b, 1/a)
    let inner = simplest_rational_in(&(Q::one() / &b), &(Q::one() / &a));
    n + Q::one() / inner
}

/// All rational roots of a non-zero integer polynomial, increasing.
///
/// ```
/// use quadsect::roots::rational_roots;
/// use quadsect::poly::ZPoly;
/// use quadsect::number::q;
/// // (3x - 1)(x^2 - 2)
/// let p = ZPoly::from_i64s(&[2, -6, -1, 3]);
/// assert_eq!(rational_roots(&p), vec![q(1, 3)]);
/// ```
pub fn rational_roots(p: &ZPoly) -> Vec<Q> {
    if p.degree().unwrap_or(0) == 0 {
        return vec![];
    }
    let sq = p.squarefree_part();
    let l = sq.lc().abs();
    let width = Q::new(BigInt::one(), &l * &l * BigInt::from(2));
    let mut out = Vec::new();
    for mut iv in isolate_squarefree(&sq) {
        if iv.is_exact() {
            out.push(iv.lo);
            continue;
        }
        refine(&sq, &mut iv, &width);
        if iv.is_exact() {
            out.push(iv.lo);
            continue;
        }
        let c = simplest_rational_in(&iv.lo, &iv.hi);
        if l.is_multiple_of(c.denom()) && sq.sign_at(&c) == 0 {
            out.push(c);
        }
    }
    out
}

/// Factorisation over Q of a polynomial of degree at most 3 into its
/// rational linear factors (as roots) and one remaining factor with no
/// rational root, which is irreducible because its degree is at most 3.
/// Returns `(rational roots, remaining primitive factor)`.
pub fn split_cubic(p: &ZPoly) -> (Vec<Q>, ZPoly) {
    debug_assert!(p.degree().unwrap_or(0) <= 3);
    let roots = rational_roots(p);
    let mut rest = p.primitive_part();
    for r in &roots {
        let lin = ZPoly::new(vec![-r.numer().clone(), r.denom().clone()]);
        while let Some(q) = rest.div_exact(&lin) {
            rest = q;
        }
    }
    (roots, rest.primitive_part())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    #[test]
    fn simplest() {
        assert_eq!(simplest_rational_in(&q(1, 3), &q(1, 2)), q(2, 5));
        assert_eq!(simplest_rational_in(&q(-1, 3), &q(1, 2)), q(0, 1));
        assert_eq!(simplest_rational_in(&q(3, 1), &q(7, 2)), q(10, 3));
        assert_eq!(simplest_rational_in(&q(-7, 2), &q(-3, 1)), -q(10, 3));
        assert_eq!(simplest_rational_in(&q(2, 1), &q(4, 1)), q(3, 1));
        let r = simplest_rational_in(&q(333, 1000), &q(334, 1000));
        assert_eq!(r, q(1, 3));
    }

    #[test]
    fn rational_roots_found() {
        // (7x + 3)(x - 5)(x^2 + x - 1)
        let p = &(&ZPoly::from_i64s(&[3, 7]) * &ZPoly::from_i64s(&[-5, 1]))
            * &ZPoly::from_i64s(&[-1, 1, 1]);
        assert_eq!(rational_roots(&p), vec![q(-3, 7), q(5, 1)]);
        let (r, rest) = split_cubic(&(&ZPoly::from_i64s(&[3, 7]) * &ZPoly::from_i64s(&[-1, 1, 1])));
        assert_eq!(r, vec![q(-3, 7)]);
        assert_eq!(rest, ZPoly::from_i64s(&[-1, 1, 1]));
    }
}
