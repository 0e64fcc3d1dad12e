//! Lehmer's gcd on 64-bit limb vectors, two words at a time.
//!
//! Key idea (Knuth, TAOCP vol. 2, §4.5.2, Algorithm L): Euclid's quotients
//! depend mostly on the leading bits.  Run Euclid on the leading 125 bits
//! `û ≥ v̂` of `x ≥ y`, tracking the cofactor matrix `(a, b; c, d)`, and
//! accept a quotient only when the two extreme ratios the truncation allows,
//! `(û + a)/(v̂ + c)` and `(û + b)/(v̂ + d)`, give the same one: then it is
//! the full numbers' quotient.  One pass over the limbs then applies the
//! whole block, `(x, y) ← (a·x + b·y, c·x + d·y)`, two consecutive
//! remainders of Euclid's sequence.  With 125-bit leading parts a block
//! holds about 62 bits of quotients (cofactors are kept below 2^62, so each
//! limb product fits an `i128`), twice what one-word leading parts give, and
//! the two combinations are written into reused buffers: no allocation per
//! block.  A block that certifies nothing (a large quotient, unbalanced
//! sizes) takes one Euclidean remainder instead.

use num_bigint::BigUint;
use std::cmp::Ordering;

type Limbs = Vec<u64>;

/// Cofactors stay below this, so `cofactor · limb` fits 126 bits.
const LIMIT: i128 = 1 << 62;

fn trim(v: &mut Limbs) {
    while v.last() == Some(&0) {
        v.pop();
    }
}

/// Significant bits of a trimmed limb vector.
fn bits(v: &[u64]) -> u64 {
    match v.last() {
        None => 0,
        Some(w) => 64 * v.len() as u64 - u64::from(w.leading_zeros()),
    }
}

/// Order of trimmed limb vectors.
fn cmp(x: &[u64], y: &[u64]) -> Ordering {
    x.len()
        .cmp(&y.len())
        .then_with(|| x.iter().rev().cmp(y.iter().rev()))
}

/// `⌊z / 2^shift⌋ mod 2^64`.
fn word_at(z: &[u64], shift: u64) -> u64 {
    let (w, off) = ((shift / 64) as usize, (shift % 64) as u32);
    let lo = z.get(w).copied().unwrap_or(0);
    if off == 0 {
        return lo;
    }
    (lo >> off) | (z.get(w + 1).copied().unwrap_or(0) << (64 - off))
}

/// `⌊z / 2^shift⌋ mod 2^128`.
fn top(z: &[u64], shift: u64) -> i128 {
    let v = (u128::from(word_at(z, shift + 64)) << 64) | u128::from(word_at(z, shift));
    (v & (u128::MAX >> 3)) as i128
}

/// `⌊n/m⌋` for `0 ≤ n < 2^125`, `0 < m`.  Most of Euclid's quotients are
/// small (about 3 in 4 are at most 4, Gauss–Kuzmin) and a 128-bit division
/// is a slow library call: small quotients by subtraction, others from the
/// leading 64 bits' word division, corrected upwards (at most twice when
/// the divisor keeps 32 leading bits; a smaller one means a quotient above
/// 2^31, divided in full).
fn quotient(n: i128, m: i128) -> i128 {
    // written out: LLVM turns a counted subtraction loop back into the
    // division it avoids
    let mut r = n;
    for q in 0..4 {
        if r < m {
            return q;
        }
        r -= m;
    }
    if r < m {
        return 4;
    }
    let s = (128 - n.leading_zeros()).saturating_sub(64);
    let (n1, m1) = ((n >> s) as u64, (m >> s) as u64);
    if m1 >> 32 == 0 {
        return n / m;
    }
    // n1/(m1 + 1) ≤ n/m (m1 < 2^62 here, as n ≥ 5m)
    let mut q = i128::from(n1 / (m1 + 1));
    let mut r = n - q * m;
    while r >= m {
        r -= m;
        q += 1;
    }
    q
}

/// The cofactors of one block from the leading parts `u ≥ v` (same shift,
/// both below 2^125): `None` when not even the first quotient is certified.
pub(crate) fn cofactors_of_tops(mut u: i128, mut v: i128) -> Option<(i128, i128, i128, i128)> {
    let (mut a, mut b, mut c, mut d) = (1i128, 0i128, 0i128, 1i128);
    loop {
        let (den1, den2) = (v + c, v + d);
        if den1 <= 0 || den2 <= 0 || u + a < 0 || u + b < 0 {
            break;
        }
        let q = quotient(u + a, den1);
        if q == 0 || q >= LIMIT || q != quotient(u + b, den2) {
            break;
        }
        // |q|, |c|, |d| < 2^62: the products fit
        let (nc, nd) = (a - q * c, b - q * d);
        if nc.abs() >= LIMIT || nd.abs() >= LIMIT {
            break;
        }
        (a, c) = (c, nc);
        (b, d) = (d, nd);
        (u, v) = (v, u - q * v);
    }
    (b != 0).then_some((a, b, c, d))
}

/// The cofactors of one block on `x ≥ y` (big integers' magnitudes).
pub(crate) fn cofactors(x: &BigUint, y: &BigUint) -> Option<(i128, i128, i128, i128)> {
    let shift = x.bits().saturating_sub(125);
    let t = |z: &BigUint| {
        let w = |s| super::xball::word_at(z, s);
        (((u128::from(w(shift + 64)) << 64) | u128::from(w(shift))) & (u128::MAX >> 3)) as i128
    };
    cofactors_of_tops(t(x), t(y))
}

/// `out ← p·x + q·y`, known to be non-negative and at most `x` (`x` at
/// least as long as `y`; `|p|, |q| < 2^62`).
fn combine(x: &[u64], y: &[u64], p: i128, q: i128, out: &mut Limbs) {
    out.clear();
    let mut carry: i128 = 0;
    for (i, &xi) in x.iter().enumerate() {
        let yi = y.get(i).copied().unwrap_or(0);
        let acc = p * i128::from(xi) + q * i128::from(yi) + carry;
        out.push(acc as u64);
        carry = acc >> 64;
    }
    debug_assert_eq!(carry, 0, "a Lehmer block left Euclid's sequence");
    trim(out);
}

fn to_big(v: &[u64]) -> BigUint {
    BigUint::new(
        v.iter()
            .flat_map(|&w| [w as u32, (w >> 32) as u32])
            .collect(),
    )
}

/// `x mod w` for a non-zero word `w`.
fn rem_word(x: &[u64], w: u64) -> u64 {
    let w = u128::from(w);
    x.iter()
        .rev()
        .fold(0u128, |r, &l| ((r << 64) | u128::from(l)) % w) as u64
}

/// `gcd(x, y)` of two magnitudes.
pub(crate) fn gcd(x: &BigUint, y: &BigUint) -> BigUint {
    let (mut x, mut y) = (x.to_u64_digits(), y.to_u64_digits());
    let (mut nx, mut ny) = (Vec::with_capacity(x.len()), Vec::with_capacity(x.len()));
    loop {
        if y.is_empty() {
            return to_big(&x);
        }
        if x.is_empty() {
            return to_big(&y);
        }
        if cmp(&x, &y) == Ordering::Less {
            std::mem::swap(&mut x, &mut y);
        }
        if y.len() == 1 {
            let w = y[0];
            return BigUint::from(super::gcd_u64(rem_word(&x, w), w));
        }
        let block = if bits(&x) - bits(&y) < 16 {
            let shift = bits(&x).saturating_sub(125);
            cofactors_of_tops(top(&x, shift), top(&y, shift))
        } else {
            None
        };
        match block {
            Some((a, b, c, d)) => {
                combine(&x, &y, a, b, &mut nx);
                combine(&x, &y, c, d, &mut ny);
                std::mem::swap(&mut x, &mut nx);
                std::mem::swap(&mut y, &mut ny);
            }
            None => {
                let r = to_big(&x) % to_big(&y);
                x = std::mem::replace(&mut y, r.to_u64_digits());
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;

    proptest::proptest! {
        /// The quotient shortcut is the division, small and large quotients
        /// (a divisor of any size below the dividend).
        #[test]
        fn quotient_is_the_division(n in 1i128..(1i128 << 125), shift in 0u32..124) {
            let m = (n >> shift).max(1);
            proptest::prop_assert_eq!(quotient(n, m), n / m);
            proptest::prop_assert_eq!(quotient(n, m + 1), n / (m + 1));
            proptest::prop_assert_eq!(quotient(m, n), m / n);
        }

        /// Lehmer blocks on long operands (up to 40 limbs) with a common
        /// factor give num-bigint's gcd; likewise the cofactor blocks map
        /// `(x, y)` to two consecutive remainders (non-negative, ordered).
        #[test]
        fn long_gcd_agrees(
            a in proptest::collection::vec(proptest::num::u64::ANY, 1..40),
            b in proptest::collection::vec(proptest::num::u64::ANY, 1..40),
            g in proptest::collection::vec(proptest::num::u64::ANY, 0..20),
        ) {
            let g = to_big(&g) + 1u32;
            let (x, y) = (to_big(&a) * &g, to_big(&b) * &g);
            proptest::prop_assert_eq!(gcd(&x, &y), x.gcd(&y));
            let (x, y) = if x >= y { (x, y) } else { (y, x) };
            if let Some((p, q, r, s)) = cofactors(&x, &y) {
                let lin = |p: i128, q: i128| {
                    num_bigint::BigInt::from(x.clone()) * p + num_bigint::BigInt::from(y.clone()) * q
                };
                let (nx, ny) = (lin(p, q), lin(r, s));
                proptest::prop_assert!(nx >= ny && ny.sign() != num_bigint::Sign::Minus);
                proptest::prop_assert_eq!(nx.magnitude().gcd(ny.magnitude()), x.gcd(&y));
            }
        }
    }
}
