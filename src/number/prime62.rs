//! Word-size modular arithmetic for multi-modular algorithms: Montgomery
//! multiplication modulo odd primes below 2^62, a lazily grown list of such
//! primes, reduction of big integers, and Chinese remaindering.
//!
//! Key idea: an integer result whose size is bounded in advance (Hadamard's
//! bound for a resultant) is computed modulo enough word-size primes and
//! reconstructed exactly by the CRT in the symmetric range.  Nothing is
//! guessed: the number of primes comes from the bound, not from stabilisation.

use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Zero};
use std::sync::Mutex;

/// Arithmetic modulo an odd modulus `n < 2^63` in Montgomery form
/// (R = 2^64).  Elements are `u64` in `[0, n)`, kept in Montgomery form by
/// the caller between [`Modulus::to_mont`] and [`Modulus::from_mont`].
#[derive(Clone, Copy, Debug)]
pub struct Modulus {
    /// The modulus.
    pub n: u64,
    ninv: u64,
    r2: u64,
    /// R mod n, i.e. 1 in Montgomery form.
    pub one: u64,
}

impl Modulus {
    /// Prepares Montgomery arithmetic modulo the odd number `n < 2^63`.
    pub fn new(n: u64) -> Modulus {
        assert!(n % 2 == 1 && n < (1u64 << 63));
        let mut inv: u64 = n; // correct to 3 bits
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(n.wrapping_mul(inv)));
        }
        let r = ((1u128 << 64) % n as u128) as u64;
        let r2 = ((r as u128 * r as u128) % n as u128) as u64;
        Modulus {
            n,
            ninv: inv.wrapping_neg(),
            r2,
            one: r,
        }
    }

    #[inline(always)]
    fn redc(&self, t: u128) -> u64 {
        let m = (t as u64).wrapping_mul(self.ninv);
        let u = ((t + (m as u128) * (self.n as u128)) >> 64) as u64;
        if u >= self.n { u - self.n } else { u }
    }

    /// Montgomery product.
    #[inline(always)]
    pub fn mul(&self, a: u64, b: u64) -> u64 {
        self.redc(a as u128 * b as u128)
    }

    /// Sum.
    #[inline(always)]
    pub fn add(&self, a: u64, b: u64) -> u64 {
        super::prime31::add_mod(a, b, self.n)
    }

    /// Difference.
    #[inline(always)]
    pub fn sub(&self, a: u64, b: u64) -> u64 {
        super::prime31::sub_mod(a, b, self.n)
    }

    /// Negation.
    #[inline(always)]
    pub fn neg(&self, a: u64) -> u64 {
        super::prime31::neg_mod(a, self.n)
    }

    /// Into Montgomery form.
    #[inline(always)]
    #[allow(clippy::wrong_self_convention)] // conversions need the modulus
    pub fn to_mont(&self, a: u64) -> u64 {
        self.mul(a % self.n, self.r2)
    }

    /// Out of Montgomery form.
    #[inline(always)]
    #[allow(clippy::wrong_self_convention)] // conversions need the modulus
    pub fn from_mont(&self, a: u64) -> u64 {
        self.redc(a as u128)
    }

    /// `a^e` (Montgomery form in and out).
    pub fn pow(&self, mut a: u64, mut e: u64) -> u64 {
        let mut r = self.one;
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        r
    }

    /// Inverse modulo a prime modulus (Montgomery form in and out); `None`
    /// for zero.  Extended Euclid on 64-bit words (no 128-bit division).
    pub fn inv(&self, a: u64) -> Option<u64> {
        if a == 0 {
            return None;
        }
        let x = self.from_mont(a);
        let (mut r0, mut r1) = (self.n, x);
        let (mut s0, mut s1) = (0i64, 1i64);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            // |s| < n < 2^63: the products stay in range
            (s0, s1) = (s1, s0.wrapping_sub((q as i64).wrapping_mul(s1)));
        }
        if r0 != 1 {
            return None;
        }
        let inv = if s0 < 0 {
            (s0 + self.n as i64) as u64
        } else {
            s0 as u64
        };
        Some(self.to_mont(inv))
    }

    /// A signed small integer into Montgomery form.
    #[cfg(test)]
    #[allow(clippy::wrong_self_convention)] // conversions need the modulus
    pub fn from_i64(&self, v: i64) -> u64 {
        let m = self.to_mont(v.unsigned_abs());
        if v < 0 { self.neg(m) } else { m }
    }

    /// A big integer, given by its little-endian 64-bit digits and sign,
    /// into Montgomery form.
    pub fn reduce_digits(&self, sign: Sign, digits: &[u64]) -> u64 {
        let mut acc = 0u64; // plain form
        for &d in digits.iter().rev() {
            // acc * 2^64 + d  (mod n):  acc*R mod n = to-Montgomery of acc
            acc = self.add(self.mul(acc, self.r2), d % self.n);
        }
        let m = self.to_mont(acc);
        if sign == Sign::Minus { self.neg(m) } else { m }
    }
}

/// A big integer prepared for fast reduction modulo many primes.
#[derive(Clone, Debug)]
pub struct Digits {
    sign: Sign,
    digits: Vec<u64>,
}

impl Digits {
    /// Splits `x` into 64-bit digits once.
    pub fn new(x: &BigInt) -> Digits {
        Digits {
            sign: x.sign(),
            digits: x.magnitude().to_u64_digits(),
        }
    }
    /// `x mod n` in Montgomery form.
    pub fn reduce(&self, m: &Modulus) -> u64 {
        m.reduce_digits(self.sign, &self.digits)
    }
}

fn is_prime_u64(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for p in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        if n.is_multiple_of(p) {
            return n == p;
        }
    }
    let m = Modulus::new(n);
    let mut d = n - 1;
    let mut s = 0;
    while d.is_multiple_of(2) {
        d /= 2;
        s += 1;
    }
    let minus_one = m.neg(m.one);
    'bases: for a in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        let mut x = m.pow(m.to_mont(a), d);
        if x == m.one || x == minus_one {
            continue;
        }
        for _ in 1..s {
            x = m.mul(x, x);
            if x == minus_one {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

static PRIMES: Mutex<Vec<u64>> = Mutex::new(Vec::new());

/// The first `k` primes below 2^62, in decreasing order (computed once and
/// cached; deterministic Miller–Rabin).
pub fn primes(k: usize) -> Vec<u64> {
    let mut list = PRIMES.lock().unwrap_or_else(|e| e.into_inner());
    let mut c = list.last().copied().unwrap_or((1u64 << 62) + 1);
    while list.len() < k {
        c -= 2;
        if is_prime_u64(c) {
            list.push(c);
        }
    }
    list[..k].to_vec()
}

/// The `i`-th prime below 2^62 (0-based, decreasing order).
pub fn nth_prime(i: usize) -> u64 {
    {
        let list = PRIMES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(&p) = list.get(i) {
            return p;
        }
    }
    primes(i + 1)[i]
}

/// Incremental Chinese remaindering in the symmetric range.
#[derive(Clone, Debug)]
pub struct Crt {
    value: BigInt,
    modulus: BigInt,
}

impl Default for Crt {
    fn default() -> Self {
        Crt::new()
    }
}

impl Crt {
    /// Empty (value 0 modulo 1).
    pub fn new() -> Crt {
        Crt {
            value: BigInt::zero(),
            modulus: BigInt::one(),
        }
    }

    /// Adds the residue `r` (Montgomery form) modulo the prime `m.n`.
    pub fn push(&mut self, m: &Modulus, r: u64) {
        let cur = Digits::new(&self.value).reduce(m);
        let mm = Digits::new(&self.modulus).reduce(m);
        let t = m.mul(m.sub(r, cur), m.inv(mm).expect("moduli are coprime"));
        let t = m.from_mont(t);
        self.value += &self.modulus * BigInt::from(t);
        self.modulus *= BigInt::from(m.n);
    }

    /// The reconstructed value in `(-M/2, M/2]`.
    pub fn symmetric(&self) -> BigInt {
        let half: BigInt = &self.modulus >> 1usize;
        if self.value > half {
            &self.value - &self.modulus
        } else {
            self.value.clone()
        }
    }

    /// Bit length of the product of the moduli so far.
    pub fn modulus_bits(&self) -> u64 {
        self.modulus.bits()
    }
}

/// log2 of the Euclidean norm of a vector of integers, rounded up (a safe
/// upper bound), from exact squares.
pub fn log2_norm2_ceil<'a>(xs: impl IntoIterator<Item = &'a BigInt>) -> u64 {
    let mut s = BigUint::zero();
    for x in xs {
        let m = x.magnitude();
        s += m * m;
    }
    // ceil(log2 sqrt(s)) <= ceil(bits(s)/2)
    s.bits().div_ceil(2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn montgomery_roundtrip_and_inverse() {
        let ps = primes(3);
        assert!(ps[0] < (1u64 << 62) && ps[0] > (1u64 << 61));
        assert!(ps[0] > ps[1] && ps[1] > ps[2]);
        let m = Modulus::new(ps[0]);
        let a = m.to_mont(123456789);
        assert_eq!(m.from_mont(a), 123456789);
        let ai = m.inv(a).unwrap();
        assert_eq!(m.from_mont(m.mul(a, ai)), 1);
        assert_eq!(m.from_mont(m.from_i64(-1)), ps[0] - 1);
    }

    #[test]
    fn crt_reconstructs_negative_big_values() {
        let x: BigInt = -(BigInt::from(7u32) << 300usize) + 12345;
        let d = Digits::new(&x);
        let mut c = Crt::new();
        for p in primes(6) {
            let m = Modulus::new(p);
            c.push(&m, d.reduce(&m));
        }
        assert_eq!(c.symmetric(), x);
    }

    #[test]
    fn miller_rabin_small() {
        let ps: Vec<u64> = (1..60).filter(|&n| is_prime_u64(n)).collect();
        assert_eq!(
            ps,
            vec![
                2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59
            ]
        );
        assert!(!is_prime_u64(3215031751)); // strong pseudoprime to bases 2,3,5,7
    }
}
