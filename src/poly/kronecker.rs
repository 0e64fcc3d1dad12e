//! Products of integer polynomials by Kronecker substitution: `a(2^w)` and
//! `b(2^w)` are multiplied as big integers (num-bigint's Karatsuba/Toom-3)
//! and the product is read back in balanced base `2^w`.
//!
//! Key idea: if every coefficient `c` of `a·b` satisfies `|c| < 2^(w−1)`,
//! the balanced base-`2^w` digits of `(a·b)(2^w)` are exactly those
//! coefficients.  `w` is taken from the exact bound
//! `|c| ≤ min(len a, len b)·‖a‖∞·‖b‖∞`.

use super::ZPoly;
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{Signed, Zero};

/// Below this many coefficients in the shorter factor the schoolbook
/// product is used.
const SCHOOLBOOK_BELOW: usize = 6;

fn max_bits(p: &ZPoly) -> u64 {
    p.coeffs().iter().map(|c| c.bits()).max().unwrap_or(0)
}

/// The big integer `Σ cᵢ 2^(w·i)` (coefficients of either sign).
fn pack(c: &[BigInt], w: u64) -> BigInt {
    let total = (w as usize * c.len()).div_ceil(64) + 1;
    let mut pos = vec![0u64; total];
    let mut neg = vec![0u64; total];
    let mut any_neg = false;
    for (i, x) in c.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        let target = if x.is_negative() {
            any_neg = true;
            &mut neg
        } else {
            &mut pos
        };
        let off = w as usize * i;
        let (word, shift) = (off / 64, off % 64);
        for (k, d) in x.magnitude().iter_u64_digits().enumerate() {
            target[word + k] |= d << shift;
            if shift > 0 {
                target[word + k + 1] |= d >> (64 - shift);
            }
        }
    }
    let p = BigInt::from_biguint(Sign::Plus, BigUint::from_slice(&to_u32(&pos)));
    if any_neg {
        p - BigInt::from_biguint(Sign::Plus, BigUint::from_slice(&to_u32(&neg)))
    } else {
        p
    }
}

fn to_u32(d: &[u64]) -> Vec<u32> {
    d.iter()
        .flat_map(|&x| [x as u32, (x >> 32) as u32])
        .collect()
}

/// Bits `[off, off + w)` of a little-endian digit array.
fn bits_at(d: &[u64], off: usize, w: usize) -> BigUint {
    let nw = w.div_ceil(64);
    let (word, shift) = (off / 64, off % 64);
    let mut out = vec![0u64; nw];
    for (k, o) in out.iter_mut().enumerate() {
        let lo = d.get(word + k).copied().unwrap_or(0);
        let hi = d.get(word + k + 1).copied().unwrap_or(0);
        *o = if shift == 0 {
            lo
        } else {
            (lo >> shift) | (hi << (64 - shift))
        };
    }
    if !w.is_multiple_of(64) {
        out[nw - 1] &= (1u64 << (w % 64)) - 1;
    }
    BigUint::from_slice(&to_u32(&out))
}

/// The balanced base-`2^w` digits of `v` (`n` of them), given that each is
/// below `2^(w−1)` in absolute value.
fn unpack(v: &BigInt, w: u64, n: usize) -> Vec<BigInt> {
    let negative = v.is_negative();
    let d: Vec<u64> = v.magnitude().iter_u64_digits().collect();
    let half = BigUint::from(1u8) << (w as usize - 1);
    let full = BigInt::from(1u8) << w as usize;
    let mut carry = false;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut c = BigInt::from_biguint(Sign::Plus, bits_at(&d, w as usize * i, w as usize));
        if carry {
            c += 1;
        }
        carry = c.magnitude() >= &half;
        if carry {
            c -= &full;
        }
        out.push(if negative { -c } else { c });
    }
    out
}

/// `a · b` (Kronecker substitution for long operands, schoolbook for short
/// ones).
///
/// ```
/// use quadsect::poly::{ZPoly, kronecker::mul};
/// let a = ZPoly::from_i64s(&[-3, 0, 7, -1, 2, 5, 1]);
/// let b = ZPoly::from_i64s(&[1, -1, 4, 0, 0, -9, 3]);
/// assert_eq!(mul(&a, &b), &a * &b);
/// ```
pub fn mul(a: &ZPoly, b: &ZPoly) -> ZPoly {
    if a.is_zero() || b.is_zero() {
        return ZPoly::zero();
    }
    let (la, lb) = (a.coeffs().len(), b.coeffs().len());
    if la.min(lb) < SCHOOLBOOK_BELOW {
        return a * b;
    }
    let (ba, bb) = (max_bits(a), max_bits(b));
    let bound = ba + bb + (la.min(lb) as u64).ilog2() as u64 + 1;
    let w = bound + 2;
    // schoolbook: la·lb word products of the operand sizes; Kronecker: one
    // product of the packed sizes (Karatsuba above 32 words, ~n^1.6)
    let school = (la * lb) as f64 * (ba / 64 + 1) as f64 * (bb / 64 + 1) as f64;
    let (na, nb) = (
        (la as u64 * w / 64 + 1) as f64,
        (lb as u64 * w / 64 + 1) as f64,
    );
    let (small, big) = (na.min(nb), na.max(nb));
    let kron = if small < 32.0 {
        small * big
    } else {
        big / small * small.powf(1.6)
    };
    if school <= kron {
        return a * b;
    }
    crate::budget::check_size(
        "Kronecker product",
        la + lb,
        (w as usize * (la + lb)) as u64,
    );
    let v = pack(a.coeffs(), w) * pack(b.coeffs(), w);
    ZPoly::new(unpack(&v, w, la + lb - 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kronecker_product_equals_schoolbook() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for trial in 0..40 {
            let la = 6 + (next() % 40) as usize;
            let lb = 6 + (next() % 40) as usize;
            let bits = [1u32, 30, 64, 65, 200][trial % 5];
            let mut rnd = |len: usize| {
                ZPoly::new(
                    (0..len)
                        .map(|_| {
                            let mut x = BigInt::from(next() >> 1);
                            for _ in 0..bits / 64 {
                                x = (x << 64usize) + BigInt::from(next());
                            }
                            x >>= (64 - bits % 64) as usize % 64;
                            if next() % 3 == 0 { -x } else { x }
                        })
                        .collect(),
                )
            };
            let (a, b) = (rnd(la), rnd(lb));
            assert_eq!(mul(&a, &b), &a * &b, "trial {trial}");
        }
    }
}
