//! Fixed-width signed integers: `64·N` bits in two's complement, held inline
//! (no heap allocation, no length or sign field).
//!
//! Key idea: "small numbers deserve small types".  Where an algorithm can
//! prove *before* a batch of operations that every intermediate result stays
//! below a known number of bits, it can run the batch on [`Fixed<N>`] and
//! fall back to `BigInt` only when the proof fails.  The arithmetic wraps
//! modulo `2^(64·N)`, so it is exact precisely when every true result lies in
//! `[-2^(64·N-1), 2^(64·N-1))`; the caller owns that proof (see the headroom
//! bound of VCA isolation in `roots::isolate`).  Conversions to and from
//! `BigInt` are exact and belong at the edges.
//!
//! Storage of many values of one runtime width `w` is a plain `&[u64]` of
//! `w` limbs each; [`signed_bits`], [`push_limbs`] and [`bigint_from_limbs`]
//! work on such slices.

use num_bigint::{BigInt, BigUint, Sign};
use std::ops::AddAssign;

/// A signed integer of `64·N` bits in two's complement, limbs little-endian.
///
/// Addition and left shifts wrap modulo `2^(64·N)`: exact whenever the true
/// result fits, which the caller must prove.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fixed<const N: usize>([u64; N]);

impl<const N: usize> Fixed<N> {
    /// The width in bits, `64·N`.
    pub const BITS: u32 = 64 * N as u32;

    /// The value of `w` two's-complement limbs (little-endian), sign-extended
    /// when `w < N` and reduced modulo `2^(64·N)` when `w > N` (exact when
    /// the value fits, e.g. when [`signed_bits`] `< 64·N`).  `O(N)`.
    #[inline]
    pub fn from_limbs(limbs: &[u64]) -> Self {
        let fill = match limbs.last() {
            Some(&top) if (top as i64) < 0 => u64::MAX,
            _ => 0,
        };
        let mut out = [fill; N];
        let k = limbs.len().min(N);
        out[..k].copy_from_slice(&limbs[..k]);
        Fixed(out)
    }

    /// The limbs, little-endian, two's complement.
    #[inline]
    pub fn limbs(&self) -> &[u64; N] {
        &self.0
    }

    /// `x` if it fits in `64·N` bits, else `None`.  `O(N)`, no allocation.
    #[cfg(test)]
    pub fn from_bigint(x: &BigInt) -> Option<Self> {
        if !fits(x, N) {
            return None;
        }
        let mut out = [0u64; N];
        for (o, d) in out.iter_mut().zip(x.iter_u64_digits()) {
            *o = d;
        }
        if x.sign() == Sign::Minus {
            negate(&mut out);
        }
        Some(Fixed(out))
    }

    /// The exact value as a `BigInt`.  `O(N)`.
    #[cfg(test)]
    #[allow(clippy::wrong_self_convention)] // Fixed<N> is large: no copy
    pub fn to_bigint(&self) -> BigInt {
        bigint_from_limbs(&self.0)
    }

    /// True for zero.
    #[inline]
    pub fn is_zero(&self) -> bool {
        self.0.iter().all(|&l| l == 0)
    }

    /// The sign: -1, 0 or 1.
    #[inline]
    pub fn signum(&self) -> i8 {
        if (self.0[N - 1] as i64) < 0 {
            -1
        } else if self.is_zero() {
            0
        } else {
            1
        }
    }

    /// The least `β >= 0` with `-2^β <= self < 2^β` (so `|self| <= 2^β`);
    /// see [`signed_bits`].
    #[inline]
    #[cfg(test)]
    pub fn signed_bits(&self) -> u32 {
        signed_bits(&self.0)
    }

    /// Number of trailing zero bits, `None` for zero.
    #[inline]
    pub fn trailing_zeros(&self) -> Option<u32> {
        let i = self.0.iter().position(|&l| l != 0)?;
        Some(64 * i as u32 + self.0[i].trailing_zeros())
    }

    /// `-self` modulo `2^(64·N)`.
    #[inline]
    pub fn neg(&self) -> Self {
        let mut out = self.0;
        negate(&mut out);
        Fixed(out)
    }

    /// `self · m` modulo `2^(64·N)` (exact when the product fits: reduction
    /// modulo `2^(64·N)` commutes with products, two's complement or not).
    #[inline]
    pub fn mul_u64(&self, m: u64) -> Self {
        let mut out = [0u64; N];
        let mut carry = 0u64;
        for (o, &l) in out.iter_mut().zip(self.0.iter()) {
            let t = u128::from(l) * u128::from(m) + u128::from(carry);
            *o = t as u64;
            carry = (t >> 64) as u64;
        }
        Fixed(out)
    }

    /// `self · 2^k` modulo `2^(64·N)`, for `k < 64·N`.
    #[inline]
    pub fn shl(&self, k: u32) -> Self {
        debug_assert!(k < Self::BITS);
        let (q, r) = ((k / 64) as usize, k % 64);
        let mut out = [0u64; N];
        for i in q..N {
            let lo = self.0[i - q];
            out[i] = if r == 0 {
                lo
            } else {
                let below = if i > q {
                    self.0[i - q - 1] >> (64 - r)
                } else {
                    0
                };
                (lo << r) | below
            };
        }
        Fixed(out)
    }

    /// `floor(self / 2^k)` (arithmetic shift), for `k < 64·N`.
    #[inline]
    pub fn shr(&self, k: u32) -> Self {
        debug_assert!(k < Self::BITS);
        let (q, r) = ((k / 64) as usize, k % 64);
        let fill = if (self.0[N - 1] as i64) < 0 {
            u64::MAX
        } else {
            0
        };
        let mut out = [fill; N];
        for i in 0..N - q {
            let hi = self.0[i + q];
            out[i] = if r == 0 {
                hi
            } else {
                let above = if i + q + 1 < N {
                    self.0[i + q + 1]
                } else {
                    fill
                };
                (hi >> r) | (above << (64 - r))
            };
        }
        Fixed(out)
    }
}

impl<const N: usize> AddAssign<&Fixed<N>> for Fixed<N> {
    /// Addition modulo `2^(64·N)`: one carry chain, exact when the sum fits.
    // `c1 | c2` (the carry out of a limb) compiles to an `adc` chain; the
    // short-circuit `||` that the lint suggests doubles the instructions.
    #[allow(clippy::suspicious_op_assign_impl)]
    #[inline]
    fn add_assign(&mut self, rhs: &Fixed<N>) {
        let mut carry = false;
        for (a, &b) in self.0.iter_mut().zip(rhs.0.iter()) {
            let (s, c1) = a.overflowing_add(b);
            let (s, c2) = s.overflowing_add(carry as u64);
            *a = s;
            carry = c1 | c2;
        }
    }
}

/// The least `β >= 0` with `-2^β <= x < 2^β` for the two's-complement value
/// `x` of `limbs` (little-endian; empty means 0): the bit length of `x` for
/// `x >= 0` and of `-x - 1` for `x < 0`.  So `|x| <= 2^β`, and `x` fits in
/// `β + 1` bits of two's complement.
#[inline]
pub fn signed_bits(limbs: &[u64]) -> u32 {
    let mask = match limbs.last() {
        Some(&top) if (top as i64) < 0 => u64::MAX,
        _ => 0,
    };
    for (i, &l) in limbs.iter().enumerate().rev() {
        let m = l ^ mask;
        if m != 0 {
            return 64 * i as u32 + 64 - m.leading_zeros();
        }
    }
    0
}

/// Widest [`Fixed`] that [`at_width`] dispatches to (1024 bits).
pub const MAX_LIMBS: usize = 16;

/// A computation generic over the width of [`Fixed`], for [`at_width`].
pub trait AtWidth: Sized {
    /// The result.
    type Output;
    /// Runs the computation on `Fixed<N>`.
    fn run<const N: usize>(self) -> Self::Output;
}

/// Runs `job` on `Fixed<N>` for the smallest `N` in 1, 2, 3, 4, 5, 6, 8,
/// 10, 12, 16 with `N >= limbs`; gives `job` back when `limbs >`
/// [`MAX_LIMBS`] (the caller's `BigInt` fallback).
pub fn at_width<J: AtWidth>(limbs: usize, job: J) -> Result<J::Output, J> {
    Ok(match limbs {
        0 | 1 => job.run::<1>(),
        2 => job.run::<2>(),
        3 => job.run::<3>(),
        4 => job.run::<4>(),
        5 => job.run::<5>(),
        6 => job.run::<6>(),
        7 | 8 => job.run::<8>(),
        9 | 10 => job.run::<10>(),
        11 | 12 => job.run::<12>(),
        13..=MAX_LIMBS => job.run::<MAX_LIMBS>(),
        _ => return Err(job),
    })
}

/// Whether `x` fits in `w` limbs of two's complement:
/// `-2^(64w-1) <= x < 2^(64w-1)`.
fn fits(x: &BigInt, w: usize) -> bool {
    let b = x.bits();
    b < 64 * w as u64
        || (b == 64 * w as u64 && x.sign() == Sign::Minus && x.trailing_zeros() == Some(b - 1))
}

/// Appends `x` as `w` two's-complement limbs (little-endian) to `out`;
/// returns false, appending nothing, when `x` does not fit in `64·w` bits.
pub fn push_limbs(x: &BigInt, w: usize, out: &mut Vec<u64>) -> bool {
    if !fits(x, w) {
        return false;
    }
    let at = out.len();
    out.extend(x.iter_u64_digits());
    out.resize(at + w, 0);
    if x.sign() == Sign::Minus {
        negate(&mut out[at..]);
    }
    true
}

/// The value of two's-complement limbs (little-endian) as a `BigInt`.
pub fn bigint_from_limbs(limbs: &[u64]) -> BigInt {
    let negative = matches!(limbs.last(), Some(&top) if (top as i64) < 0);
    let mut mag = limbs.to_vec();
    if negative {
        negate(&mut mag);
    }
    let sign = if negative { Sign::Minus } else { Sign::Plus };
    BigInt::from_biguint(sign, biguint_from_limbs(&mag))
}

/// The value of little-endian magnitude limbs as a `BigUint`.
pub fn biguint_from_limbs(limbs: &[u64]) -> BigUint {
    BigUint::new(
        limbs
            .iter()
            .flat_map(|&l| [l as u32, (l >> 32) as u32])
            .collect(),
    )
}

/// Two's-complement negation in place (`!x + 1`).
fn negate(limbs: &mut [u64]) {
    let mut carry = true;
    for l in limbs.iter_mut() {
        let (s, c) = (!*l).overflowing_add(carry as u64);
        *l = s;
        carry = c;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::One;

    fn fx<const N: usize>(x: &BigInt) -> Fixed<N> {
        Fixed::from_bigint(x).expect("fits")
    }

    fn pow2(k: usize) -> BigInt {
        BigInt::one() << k
    }

    #[test]
    fn round_trips_through_bigint() {
        let samples = [
            BigInt::from(0),
            BigInt::from(1),
            BigInt::from(-1),
            BigInt::from(u64::MAX),
            -BigInt::from(u64::MAX),
            pow2(64),
            -pow2(64),
            pow2(127) - 1,
            -pow2(127),
            pow2(100) + 12345u32,
            -(pow2(100) + 12345u32),
        ];
        for x in &samples {
            assert_eq!(fx::<2>(x).to_bigint(), *x, "{x}");
            assert_eq!(fx::<3>(x).to_bigint(), *x, "{x}");
        }
        // the range of Fixed<2> is [-2^127, 2^127)
        assert!(Fixed::<2>::from_bigint(&pow2(127)).is_none());
        assert!(Fixed::<2>::from_bigint(&(-pow2(127) - 1)).is_none());
        assert!(Fixed::<1>::from_bigint(&BigInt::from(i64::MIN)).is_some());
        assert!(Fixed::<1>::from_bigint(&BigInt::from(u64::MAX)).is_none());
    }

    #[test]
    fn addition_carries_and_borrows_across_limbs() {
        // carry out of limb 0 and limb 1
        let mut a = fx::<3>(&(pow2(128) - 1));
        a += &fx::<3>(&BigInt::from(1));
        assert_eq!(a.to_bigint(), pow2(128));
        // borrow through two limbs: 2^128 + (-1)
        a += &fx::<3>(&BigInt::from(-1));
        assert_eq!(a.to_bigint(), pow2(128) - 1);
        // sign change: 5 + (-2^130) and back
        let mut b = fx::<3>(&BigInt::from(5));
        b += &fx::<3>(&-pow2(130));
        assert_eq!(b.to_bigint(), 5 - pow2(130));
        assert_eq!(b.signum(), -1);
        b += &fx::<3>(&pow2(130));
        assert_eq!(b.to_bigint(), BigInt::from(5));
        // negative + negative
        let mut c = fx::<2>(&-(pow2(64) + 7u32));
        c += &fx::<2>(&-(pow2(63) + 9u32));
        assert_eq!(c.to_bigint(), -(pow2(64) + 7u32) - (pow2(63) + 9u32));
        let mut z = fx::<2>(&-pow2(70));
        z += &fx::<2>(&pow2(70));
        assert!(z.is_zero());
        assert_eq!(z.signum(), 0);
    }

    #[test]
    fn shifts_are_exact_multiplications_and_floor_divisions() {
        let xs = [
            BigInt::from(3),
            BigInt::from(-3),
            pow2(63) + 1u32,
            -(pow2(63) + 1u32),
            BigInt::from(-1),
        ];
        for x in &xs {
            for k in [0u32, 1, 5, 63, 64, 65, 100, 127] {
                let s = fx::<4>(x).shl(k);
                assert_eq!(s.to_bigint(), x << (k as usize), "{x} << {k}");
                assert_eq!(s.shr(k).to_bigint(), *x, "{x} << {k} >> {k}");
                // floor division, as BigInt's >>
                assert_eq!(fx::<4>(x).shr(k).to_bigint(), x >> (k as usize));
            }
        }
    }

    #[test]
    fn bit_counts() {
        for (x, beta, tz) in [
            (BigInt::from(0), 0, None),
            (BigInt::from(1), 1, Some(0)),
            (BigInt::from(-1), 0, Some(0)),
            (BigInt::from(-2), 1, Some(1)),
            (BigInt::from(-3), 2, Some(0)),
            (pow2(64), 65, Some(64)),
            (-pow2(64), 64, Some(64)),
            (-pow2(64) - 1u32, 65, Some(0)),
        ] {
            let f = fx::<3>(&x);
            assert_eq!(f.signed_bits(), beta, "{x}");
            assert_eq!(f.trailing_zeros(), tz, "{x}");
            // -2^β <= x < 2^β
            assert!(-pow2(beta as usize) <= x && x < pow2(beta as usize));
        }
    }

    #[test]
    fn runtime_width_limbs_sign_extend() {
        let mut v = Vec::new();
        assert!(push_limbs(&BigInt::from(-5), 1, &mut v));
        assert!(push_limbs(&(pow2(70) + 1), 2, &mut v));
        assert!(!push_limbs(&pow2(127), 2, &mut v));
        assert_eq!(v.len(), 3);
        assert_eq!(
            Fixed::<3>::from_limbs(&v[..1]).to_bigint(),
            BigInt::from(-5)
        );
        assert_eq!(bigint_from_limbs(&v[1..]), pow2(70) + 1);
        // narrowing is exact when the value fits
        let wide = fx::<4>(&BigInt::from(-9));
        assert_eq!(
            Fixed::<2>::from_limbs(wide.limbs()).to_bigint(),
            BigInt::from(-9)
        );
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_fixed() {
        use crate::number::fixed::Fixed;
        use num_bigint::BigInt;
        let a = Fixed::<2>::from_bigint(&BigInt::from(u64::MAX)).unwrap();
        let mut b = Fixed::<2>::from_bigint(&BigInt::from(-3)).unwrap();
        b += &a; // the borrow crosses a limb
        assert_eq!(b.to_bigint(), BigInt::from(u64::MAX) - 3);
        assert_eq!(
            b.shl(60).to_bigint(),
            (BigInt::from(u64::MAX) - 3) << 60usize
        );
    }
}
