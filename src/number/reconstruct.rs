//! Rational reconstruction: from a residue `a mod M` back to the rational
//! `n/d` with `|n|, d ≤ √(M/2)` it stands for (Wang's algorithm, with
//! Lehmer blocks while far above the bound), the symmetric representative,
//! and vectors reconstructed over one common denominator.
//!
//! Key idea: a residue has at most one such preimage, so what is
//! reconstructed is a *candidate*; the callers verify it exactly before
//! using it.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The rational `n/d` (`d > 0`, `gcd(n, d) = 1`) with `n ≡ a·d (mod m)` and
/// `|n|, d ≤ √(m/2)`, if there is one (it is then unique): Wang's algorithm,
/// the extended Euclidean algorithm on `(m, a)` stopped at the first
/// remainder below the bound.
pub fn rational_reconstruction(a: &BigInt, m: &BigInt) -> Option<(BigInt, BigInt)> {
    let a = a.mod_floor(m);
    // bound = ⌊√(m/2)⌋
    let bound: BigInt = (m >> 1usize).sqrt();
    if a <= bound {
        return Some((a, BigInt::one()));
    }
    if (m - &a) <= bound {
        return Some((-(m - &a), BigInt::one()));
    }
    let (mut r0, mut r1) = (m.clone(), a);
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
    let bound_bits = bound.bits();
    while r1 > bound {
        crate::budget::check();
        // Lehmer blocks while far above the bound: the block's last
        // remainder is the smallest, so no stopping point is skipped when
        // it is still above the bound
        if r1.bits() > bound_bits + 128
            && r0.bits() - r1.bits() < 16
            && let Some((a, b, c, d)) =
                crate::number::lehmer::cofactors(r0.magnitude(), r1.magnitude())
        {
            let lin = |p: i128, q: i128, x: &BigInt, y: &BigInt| -> BigInt {
                x * BigInt::from(p) + y * BigInt::from(q)
            };
            let n1 = lin(c, d, &r0, &r1);
            if n1 > bound {
                let n0 = lin(a, b, &r0, &r1);
                let (s0, s1) = (lin(a, b, &t0, &t1), lin(c, d, &t0, &t1));
                (r0, r1, t0, t1) = (n0, n1, s0, s1);
                continue;
            }
        }
        let (q, r) = r0.div_rem(&r1);
        r0 = std::mem::replace(&mut r1, r);
        let t = &t0 - &q * &t1;
        t0 = std::mem::replace(&mut t1, t);
    }
    if t1.abs() > bound || t1.is_zero() {
        return None;
    }
    if !r1.gcd(&t1).is_one() {
        return None;
    }
    if t1.is_negative() {
        Some((-r1, -t1))
    } else {
        Some((r1, t1))
    }
}

/// The bit size of the symmetric representative of `v ∈ [0, m)` (no
/// division).
pub fn symmetric_bits(v: &BigInt, m: &BigInt) -> u64 {
    if v + v > *m { (m - v).bits() } else { v.bits() }
}

/// The symmetric representative of `a mod m` in `(−m/2, m/2]`.
pub fn symmetric_mod(a: &BigInt, m: &BigInt) -> BigInt {
    let r = a.mod_floor(m);
    if &r + &r > *m { r - m } else { r }
}

/// Rational reconstruction of all values with a running common denominator
/// (after the first few coefficients most are integers times it): the
/// numerators over the final common denominator.
pub(crate) fn reconstruct_common(values: &[BigInt], m: &BigInt) -> Option<(Vec<BigInt>, BigInt)> {
    let bound_bits = (m.bits() - 1) / 2;
    let mut den = BigInt::one();
    // (numerator, denominator at the time) per value
    let mut out: Vec<(BigInt, BigInt)> = Vec::with_capacity(values.len());
    for v in values {
        crate::budget::check();
        let a = (v * &den).mod_floor(m);
        let s = symmetric_mod(&a, m);
        if s.bits() <= bound_bits {
            out.push((s, den.clone()));
            continue;
        }
        let (n, d) = rational_reconstruction(&a, m)?;
        den *= &d;
        if den.bits() > bound_bits {
            return None;
        }
        out.push((n, den.clone()));
    }
    let nums = out.into_iter().map(|(n, d)| n * (&den / d)).collect();
    Some((nums, den))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::prime31::prime31;

    /// Wang's algorithm with plain Euclidean steps (the reference for the
    /// Lehmer-accelerated version).
    fn plain_reconstruction(a: &BigInt, m: &BigInt) -> Option<(BigInt, BigInt)> {
        let bound: BigInt = (m >> 1usize).sqrt();
        let (mut r0, mut r1) = (m.clone(), a.mod_floor(m));
        let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
        while r1 > bound {
            let (q, r) = r0.div_rem(&r1);
            r0 = std::mem::replace(&mut r1, r);
            let t = &t0 - &q * &t1;
            t0 = std::mem::replace(&mut t1, t);
        }
        if t1.abs() > bound || t1.is_zero() || !r1.gcd(&t1).is_one() {
            return None;
        }
        if t1.is_negative() {
            Some((-r1, -t1))
        } else {
            Some((r1, t1))
        }
    }

    #[test]
    fn lehmer_reconstruction_agrees_with_plain_euclid() {
        let m: BigInt = (0..70).map(|i| BigInt::from(prime31(i))).product();
        let mut seed = 0x1234_5678_9abc_def1u64;
        let mut big = |bits: u32| {
            let mut x = BigInt::one();
            for _ in 0..bits / 32 {
                x = (x << 32usize) + BigInt::from(crate::tests::xorshift(&mut seed) >> 32);
            }
            x
        };
        for bits in [64u32, 500, 1000, 1080, 1200] {
            let (n, d) = (big(bits), big(bits / 2 + 32));
            let a = (&n * d.modinv(&m).unwrap()).mod_floor(&m);
            let want = plain_reconstruction(&a, &m);
            assert_eq!(rational_reconstruction(&a, &m), want, "{bits} bits");
            if bits <= 1000 {
                let g = n.gcd(&d);
                assert_eq!(want, Some((&n / &g, &d / &g)));
            }
            // a random residue: both agree on failure too
            let r = big(2100).mod_floor(&m);
            assert_eq!(
                rational_reconstruction(&r, &m),
                plain_reconstruction(&r, &m)
            );
        }
    }

    #[test]
    fn rational_reconstruction_inverts_reduction() {
        let m: BigInt = (0..6).map(|i| BigInt::from(prime31(i))).product();
        for (n, d) in [
            (-355i64, 113i64),
            (1, 1),
            (0, 1),
            (123456789, 987654323),
            (-7, 3),
        ] {
            let (n, d) = (BigInt::from(n), BigInt::from(d));
            let dinv = d.modinv(&m).unwrap();
            let a = (&n * dinv).mod_floor(&m);
            assert_eq!(rational_reconstruction(&a, &m), Some((n, d)));
        }
        // a residue with no small preimage: numerator and denominator both
        // near √m are out of reach for a modulus of 2^62
        let m2 = BigInt::from(prime31(0)) * BigInt::from(prime31(1));
        let (n, d) = (
            BigInt::from(3_000_000_017i64),
            BigInt::from(2_999_999_929i64),
        );
        let a = (&n * d.modinv(&m2).unwrap()).mod_floor(&m2);
        assert_ne!(rational_reconstruction(&a, &m2), Some((n, d)));
    }
}
