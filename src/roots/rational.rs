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
/// `(lo, hi)` (`lo < hi`), by the continued-fraction (Stern–Brocot) rule,
/// iteratively on integer pairs (no rational normalisation per step).
pub fn simplest_rational_in(lo: &Q, hi: &Q) -> Q {
    if !crate::number::q_cmp(lo, hi).is_lt() {
        debug_assert!(false, "an empty interval");
        return lo.clone();
    }
    if lo.is_negative() && hi.is_positive() {
        return Q::zero();
    }
    if !hi.is_positive() {
        return -simplest_rational_in(&-hi, &-lo);
    }
    let word = |x: &BigInt| u128::try_from(x).ok();
    if let (Some(a), Some(b), Some(c), Some(d)) = (
        word(lo.numer()),
        word(lo.denom()),
        word(hi.numer()),
        word(hi.denom()),
    ) && let Some((n, m)) = simplest_u128(a, b, c, d)
    {
        // a Stern–Brocot fraction is in lowest terms
        return Q::new_raw(n.into(), m.into());
    }
    simplest_big(
        lo.numer().clone(),
        lo.denom().clone(),
        hi.numer().clone(),
        hi.denom().clone(),
    )
}

/// [`simplest_rational_in`] on big integers: `0 ≤ a/b < c/d`.
fn simplest_big(mut a: BigInt, mut b: BigInt, mut c: BigInt, mut d: BigInt) -> Q {
    // convergent matrix [[p0, p1], [q0, q1]] maps the remaining interval
    // back: x = (p1 t + p0)/(q1 t + q0)
    let (mut p0, mut p1) = (BigInt::zero(), BigInt::one());
    let (mut q0, mut q1) = (BigInt::one(), BigInt::zero());
    loop {
        crate::budget::check();
        // floor of the lower end; the upper end may be ∞ (d = 0)
        let (fa, ra) = num_integer::Integer::div_rem(&a, &b);
        let candidate = &fa + 1u32;
        // is floor(a/b) + 1 < c/d (or the upper end infinite)?
        let below_hi = d.is_zero() || &candidate * &d < c;
        if below_hi {
            // the integer floor(a/b)+1 lies inside (a/b, c/d)
            let num = &p1 * &candidate + &p0;
            let den = &q1 * &candidate + &q0;
            return Q::new(num, den);
        }
        // both ends share the integer part fa: recurse on the reciprocals
        // of the fractional parts, reversed: (d/(c − fa d), b/ra)
        let (np0, nq0) = (p1.clone(), q1.clone());
        p1 = &p1 * &fa + &p0;
        q1 = &q1 * &fa + &q0;
        p0 = np0;
        q0 = nq0;
        if ra.is_zero() {
            // lower end is exactly fa: the interval (fa, c/d) with c/d < fa + 1
            // → fa + 1/k for the least k with 1/k < c/d − fa, i.e. t ∈ (k, ∞)
            let cr = &c - &fa * &d; // c/d − fa = cr/d
            let k = &d / &cr + 1u32;
            let num = &p1 * &k + &p0;
            let den = &q1 * &k + &q0;
            return Q::new(num, den);
        }
        let cr = &c - &fa * &d;
        // new interval (d/cr, b/ra): reciprocals of (cr/d, ra/b) reversed
        let (na, nb, nc, nd) = (d.clone(), cr, b.clone(), ra);
        a = na;
        b = nb;
        c = nc;
        d = nd;
    }
}

/// [`simplest_rational_in`] on machine words: `0 ≤ a/b < c/d`, `b, d > 0`;
/// `None` if an intermediate overflows (then the big-integer loop runs).
fn simplest_u128(mut a: u128, mut b: u128, mut c: u128, mut d: u128) -> Option<(u128, u128)> {
    let (mut p0, mut p1, mut q0, mut q1) = (0u128, 1u128, 1u128, 0u128);
    let conv = |p0: u128, p1: u128, k: u128| p1.checked_mul(k)?.checked_add(p0);
    loop {
        let (fa, ra) = (a / b, a % b);
        let candidate = fa.checked_add(1)?;
        if d == 0 || candidate.checked_mul(d)? < c {
            return Some((conv(p0, p1, candidate)?, conv(q0, q1, candidate)?));
        }
        (p0, p1) = (p1, conv(p0, p1, fa)?);
        (q0, q1) = (q1, conv(q0, q1, fa)?);
        let cr = c - fa * d; // fa·d ≤ c here
        if ra == 0 {
            let k = (d / cr).checked_add(1)?;
            return Some((conv(p0, p1, k)?, conv(q0, q1, k)?));
        }
        (a, b, c, d) = (d, cr, b, ra);
    }
}

/// A quick proof that `p` has no rational root: a root `a/b` (lowest terms)
/// has `b | lc(p)`, so for a prime `q ∤ lc(p)` it gives the root `a·b⁻¹` of
/// `p mod q`; if `p mod q` has no root in `F_q` for one such prime, `p` has
/// no rational root.  `false` means "unknown" (then a complete test is
/// needed).  Cost: at most a few thousand word operations.
pub fn no_rational_root_sieve(p: &ZPoly) -> bool {
    const PRIMES: [u64; 16] = [3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59];
    if p.degree().unwrap_or(0) == 0 {
        return true;
    }
    if p.coeffs()[0].is_zero() {
        return false; // 0 is a root
    }
    for q in PRIMES {
        let c: Vec<u64> = p.coeffs().iter().map(|a| small_mod(a, q)).collect();
        if c.last() == Some(&0) {
            continue;
        }
        let has_root = (0..q).any(|x| c.iter().rev().fold(0, |acc, &a| (acc * x + a) % q) == 0);
        if !has_root {
            return true;
        }
    }
    false
}

/// `a mod q` in `[0, q)` for a small prime `q`.
fn small_mod(a: &BigInt, q: u64) -> u64 {
    let r = a
        .magnitude()
        .iter_u32_digits()
        .rev()
        .fold(0u64, |acc, d| ((acc << 32) | d as u64) % q);
    if a.is_negative() && r != 0 { q - r } else { r }
}

/// All rational roots of a non-zero integer polynomial, increasing.
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
    proptest::proptest! {
        /// The machine-word continued fraction gives the big-integer one.
        #[test]
        fn word_and_big_simplest_agree(a in 0u64..1 << 40, b in 1u64..1 << 40,
                                       w in 1u64..1 << 30, d in 1u64..1 << 40) {
            // a/b < c/d with c/d = a/b + w/(b·d)
            let (a, b, d) = (a as u128, b as u128, d as u128);
            let c = a * d + w as u128;
            let d2 = b * d;
            let big = simplest_big(a.into(), b.into(), c.into(), d2.into());
            let (n, m) = simplest_u128(a, b, c, d2).unwrap();
            proptest::prop_assert_eq!(big.clone(), Q::new(n.into(), m.into()));
            proptest::prop_assert!(Q::new(a.into(), b.into()) < big);
            proptest::prop_assert!(big < Q::new(c.into(), d2.into()));
        }
    }

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

#[cfg(test)]
mod brute {
    use super::*;
    use crate::number::q;

    #[test]
    fn simplest_matches_brute_force() {
        let mut seed = 12345u64;
        let mut next = || crate::tests::xorshift(&mut seed);
        for _ in 0..3000 {
            let a = (next() % 2000) as i64 - 1000;
            let b = (next() % 60) as i64 + 1;
            let c = (next() % 2000) as i64 - 1000;
            let d = (next() % 60) as i64 + 1;
            let (lo, hi) = (q(a, b), q(c, d));
            if lo >= hi {
                continue;
            }
            let s = simplest_rational_in(&lo, &hi);
            assert!(lo < s && s < hi, "({lo}, {hi}) -> {s}");
            // no smaller denominator fits
            for den in 1..*s.denom().to_u64_digits().1.first().unwrap_or(&1) {
                let den = den as i64;
                let k = (&lo * Q::from_integer(den.into())).floor() + Q::one();
                let cand = k / Q::from_integer(den.into());
                assert!(
                    cand >= hi,
                    "({lo}, {hi}): {cand} has a smaller denominator than {s}"
                );
            }
        }
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_no_rational_root_sieve() {
        use crate::poly::ZPoly;
        use crate::roots::no_rational_root_sieve;
        assert!(no_rational_root_sieve(&ZPoly::from_i64s(&[-2, 0, 1]))); // x^2 - 2
        assert!(!no_rational_root_sieve(&ZPoly::from_i64s(&[-1, 3, -1, 3]))); // (3x - 1)(x^2 + 1)
    }

    #[test]
    fn doc_rational_roots() {
        use crate::number::q;
        use crate::poly::ZPoly;
        use crate::roots::rational_roots;
        // (3x - 1)(x^2 - 2)
        let p = ZPoly::from_i64s(&[2, -6, -1, 3]);
        assert_eq!(rational_roots(&p), vec![q(1, 3)]);
    }
}
