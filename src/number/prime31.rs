//! Arithmetic modulo 31-bit primes, the one prime field of every
//! multi-modular algorithm (resultants, gcds and square-free tests over Z,
//! the modular Gröbner/RUR routes): [`Fp`] (Barrett reduction, products
//! delayed in `u64`), the primes below 2^31 ([`prime31`]), residues of many
//! integers at once ([`BlockResidues`]) and Chinese remaindering of whole
//! vectors ([`CrtVec`]).
//!
//! Key idea: an object over Q is computed modulo many word-size primes and
//! lifted by the CRT.  Primes below 2^31 keep a product of two residues
//! below 2^62, so the vector kernels ([`super::modkernel`]) accumulate
//! several products in a `u64` before one reduction.

use super::reconstruct::symmetric_mod;
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Zero};
use std::sync::Mutex;

/// `a + b mod p` for residues `a, b < p < 2^63`.
#[inline(always)]
pub(crate) fn add_mod(a: u64, b: u64, p: u64) -> u64 {
    let s = a + b;
    if s >= p { s - p } else { s }
}

/// `a − b mod p` for residues `a, b < p < 2^63`.
#[inline(always)]
pub(crate) fn sub_mod(a: u64, b: u64, p: u64) -> u64 {
    if a >= b { a - b } else { a + p - b }
}

/// `−a mod p` for a residue `a < p`.
#[inline(always)]
pub(crate) fn neg_mod(a: u64, p: u64) -> u64 {
    if a == 0 { 0 } else { p - a }
}

/// Arithmetic modulo a prime `p < 2^31`: elements are `u64` in `[0, p)`.
///
/// Products of two elements are below `2^62`, so sums of a few products can
/// be accumulated in a `u64` and reduced once ([`Fp::reduce`], Barrett).
#[derive(Clone, Copy, Debug)]
pub struct Fp {
    /// The prime.
    pub p: u64,
    /// `p²` (for delayed reduction: accumulators are kept below it).
    pub p2: u64,
    /// `⌊(2^64 − 1)/p⌋`.
    barrett: u64,
    /// `2^32 mod p` and `2^64 mod p` (for [`Fp::fold_digit`] and the dot
    /// products of `modkernel`).
    pub(crate) c32: u64,
    c64: u64,
}

impl Fp {
    /// The field of the prime `p` (`3 ≤ p < 2^31`; primality is the
    /// caller's promise).
    pub fn new(p: u64) -> Fp {
        assert!((3..1u64 << 31).contains(&p));
        Fp {
            p,
            p2: p * p,
            barrett: u64::MAX / p,
            c32: (1u64 << 32) % p,
            c64: ((1u128 << 64) % p as u128) as u64,
        }
    }

    /// `x mod p` for any `x < 2^64`.
    #[inline(always)]
    pub fn reduce(&self, x: u64) -> u64 {
        let q = ((x as u128 * self.barrett as u128) >> 64) as u64;
        let mut r = x - q * self.p;
        // the estimate is at most 2 too small
        while r >= self.p {
            r -= self.p;
        }
        r
    }

    /// Product.
    #[inline(always)]
    pub fn mul(&self, a: u64, b: u64) -> u64 {
        self.reduce(a * b)
    }

    /// Sum.
    #[inline(always)]
    pub fn add(&self, a: u64, b: u64) -> u64 {
        add_mod(a, b, self.p)
    }

    /// Difference.
    #[inline(always)]
    pub fn sub(&self, a: u64, b: u64) -> u64 {
        sub_mod(a, b, self.p)
    }

    /// Negation.
    #[inline(always)]
    pub fn neg(&self, a: u64) -> u64 {
        neg_mod(a, self.p)
    }

    /// `a^e`, by squaring and multiplying.
    pub fn pow(&self, mut a: u64, mut e: u64) -> u64 {
        let mut r = 1u64;
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        r
    }

    /// Inverse (`None` for zero), by extended Euclid on words.
    pub fn inv(&self, a: u64) -> Option<u64> {
        inv_mod(a % self.p, self.p)
    }

    /// A big integer as an element (two Barrett steps per 64-bit digit).
    pub fn reduce_big(&self, x: &BigInt) -> u64 {
        let m = self.reduce_biguint(x.magnitude());
        if x.sign() == Sign::Minus {
            self.neg(m)
        } else {
            m
        }
    }

    /// A natural number as an element (one [`Fp::fold_digit`] per 64-bit
    /// digit).
    pub fn reduce_biguint(&self, x: &BigUint) -> u64 {
        x.iter_u64_digits()
            .rev()
            .fold(0, |acc, d| self.fold_digit(acc, d))
    }

    /// `acc·2^64 + d mod p` for `acc < p`: as `acc·(2^64 mod p) + hi·(2^32
    /// mod p) + lo`, below 2^62 + 2^63 + 2^32 < 2^64, so one reduction.
    #[inline(always)]
    pub fn fold_digit(&self, acc: u64, d: u64) -> u64 {
        self.reduce(acc * self.c64 + (d >> 32) * self.c32 + (d & 0xffff_ffff))
    }
}

/// Primes per block of [`BlockResidues`].
const BLOCK: usize = 8;

/// Integers of more than this many 64-bit digits take the dot-product path
/// of [`BlockResidues`].
const LONG: usize = 8;

/// Whether `x` takes the dot-product path of [`BlockResidues`].
fn is_long(x: &BigInt) -> bool {
    x.magnitude().iter_u64_digits().len() > LONG
}

/// Residues of a fixed list of integers modulo the primes [`prime31`]`(k)`,
/// `k = 0, 1, …`.  Integers of at most [`LONG`] 64-bit digits are reduced a
/// block of [`BlockResidues::BLOCK`] consecutive primes at a time: each
/// integer's digits are read once, from the top, and folded into the eight
/// residues together (one Barrett step per 64-bit digit and prime,
/// independent across primes, so they overlap in the pipeline).  Longer
/// ones are cut once into 32-bit digits `hᵢ`, and their residue modulo p is
/// the dot product `Σ hᵢ·(2^(32i) mod p)` ([`super::modkernel::dot`]:
/// vectorised multiplies and adds, one reduction per integer and prime; on
/// the 2000-bit RUR of dense degree 8 against a rotated ellipsoid, with 501
/// primes of D(u), 87 instead of 148 million instructions).
pub struct BlockResidues<'a> {
    ints: Vec<&'a BigInt>,
    /// The index of the cached block (`usize::MAX`: none).
    block: usize,
    /// Per short integer, its residues modulo the block's primes (sign
    /// applied; zeros for the long ones).
    rems: Vec<[u64; BLOCK]>,
    /// The 32-bit digits of the long integers (ascending, one per word).
    digits: Vec<u64>,
    /// Per long integer: its index, where its digits start, how many.
    long: Vec<(usize, usize, usize)>,
    /// `2^(32i) mod p` for the current prime (a buffer).
    powers: Vec<u64>,
}

impl<'a> BlockResidues<'a> {
    /// Primes per block.
    pub const BLOCK: usize = BLOCK;

    /// The residues of `ints` will be asked for.
    pub fn new(ints: Vec<&'a BigInt>) -> Self {
        let mut digits = Vec::new();
        let mut long = Vec::new();
        for (i, x) in ints.iter().enumerate() {
            if is_long(x) {
                let start = digits.len();
                digits.extend(x.magnitude().iter_u32_digits().map(u64::from));
                long.push((i, start, digits.len() - start));
            }
        }
        BlockResidues {
            ints,
            block: usize::MAX,
            rems: Vec::new(),
            digits,
            long,
            powers: Vec::new(),
        }
    }

    /// The residues of the integers modulo `prime31(k)` (`fp` its field).
    pub fn residues(&mut self, k: usize, fp: &Fp) -> Vec<u64> {
        debug_assert_eq!(fp.p, prime31(k));
        let b = k / Self::BLOCK;
        if b != self.block {
            let fields: [Fp; BLOCK] =
                std::array::from_fn(|j| Fp::new(prime31(b * Self::BLOCK + j)));
            self.rems = self
                .ints
                .iter()
                .map(|x| {
                    let mut acc = [0u64; BLOCK];
                    if is_long(x) {
                        return acc;
                    }
                    for d in x.magnitude().iter_u64_digits().rev() {
                        for (a, f) in acc.iter_mut().zip(&fields) {
                            *a = f.fold_digit(*a, d);
                        }
                    }
                    if x.sign() == Sign::Minus {
                        for (a, f) in acc.iter_mut().zip(&fields) {
                            *a = f.neg(*a);
                        }
                    }
                    acc
                })
                .collect();
            self.block = b;
        }
        let j = k % Self::BLOCK;
        let mut out: Vec<u64> = self.rems.iter().map(|r| r[j]).collect();
        if let Some(longest) = self.long.iter().map(|l| l.2).max() {
            self.powers.clear();
            let mut pw = 1 % fp.p;
            for _ in 0..longest {
                self.powers.push(pw);
                pw = fp.mul(pw, fp.c32);
            }
            for &(i, start, len) in &self.long {
                let r = super::modkernel::dot(
                    fp,
                    &self.digits[start..start + len],
                    &self.powers[..len],
                );
                out[i] = if self.ints[i].sign() == Sign::Minus {
                    fp.neg(r)
                } else {
                    r
                };
            }
        }
        out
    }
}

/// `a^-1 mod n` for `0 < a < n < 2^63`, `None` when not invertible.
pub fn inv_mod(a: u64, n: u64) -> Option<u64> {
    if a == 0 {
        return None;
    }
    if n < 1 << 62 {
        // in i64 (|s| ≤ n, remainders below n): word divisions, not the
        // 128-bit ones of the general case
        return inv_by_euclid(n as i64, (a % n) as i64).map(|x| x as u64);
    }
    inv_by_euclid(n as i128, a as i128).map(|x| x as u64)
}

/// The extended Euclidean algorithm on `(n, a)`: `a⁻¹ mod n` in `[0, n)`
/// when `gcd(n, a) = 1`.
fn inv_by_euclid<T: num_integer::Integer + Copy>(n: T, a: T) -> Option<T> {
    let (mut r0, mut r1) = (n, a);
    let (mut s0, mut s1) = (T::zero(), T::one());
    while !r1.is_zero() {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
    }
    r0.is_one().then(|| s0.mod_floor(&n))
}

#[cfg(test)]
fn is_prime_u32(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for p in [2u64, 3, 5, 7, 11, 13] {
        if n.is_multiple_of(p) {
            return n == p;
        }
    }
    // deterministic for n < 4 759 123 141 with bases 2, 7, 61
    let mut d = n - 1;
    let mut s = 0;
    while d.is_multiple_of(2) {
        d /= 2;
        s += 1;
    }
    let pow = |mut a: u64, mut e: u64| {
        let mut r = 1u64;
        while e > 0 {
            if e & 1 == 1 {
                r = r * a % n;
            }
            a = a * a % n;
            e >>= 1;
        }
        r
    };
    'bases: for a in [2u64, 7, 61] {
        if a % n == 0 {
            continue;
        }
        let mut x = pow(a, d);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = x * x % n;
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

static PRIMES31: Mutex<Vec<u64>> = Mutex::new(Vec::new());

/// The `i`-th prime below 2^31 (0-based, decreasing order; cached).  The
/// list grows by a sieve of Eratosthenes over windows of 2^15 numbers
/// below the last prime found (the odd primes up to √(2^31) cross out
/// their multiples; about 1500 primes per window), so a process that
/// needs a hundred primes spends well under a millisecond on them (a
/// Miller–Rabin test per candidate took about 2 ms).
pub fn prime31(i: usize) -> u64 {
    let mut list = PRIMES31.lock().unwrap_or_else(|e| e.into_inner());
    while list.len() <= i {
        let hi = list.last().copied().unwrap_or(1u64 << 31);
        sieve_window(hi, &mut list);
    }
    list[i]
}

/// Appends the primes of `[hi − 2^15, hi)` (`hi ≤ 2^31`, far above √hi)
/// in decreasing order.
fn sieve_window(hi: u64, out: &mut Vec<u64>) {
    const WIDTH: u64 = 1 << 15;
    let lo = hi - WIDTH;
    let mut composite = vec![false; WIDTH as usize];
    for &q in small_odd_primes() {
        let q = u64::from(q);
        if q * q >= hi {
            break;
        }
        // the first odd multiple of q at or above lo (q² < lo: q itself is
        // not in the window)
        let mut m = lo.div_ceil(q) * q;
        if m.is_multiple_of(2) {
            m += q;
        }
        while m < hi {
            composite[(m - lo) as usize] = true;
            m += 2 * q;
        }
    }
    out.extend(
        (lo..hi)
            .rev()
            .filter(|&n| n % 2 == 1 && !composite[(n - lo) as usize]),
    );
}

/// The odd primes below 46 341 (> √(2^31)), by a plain sieve, once.
fn small_odd_primes() -> &'static [u32] {
    static SMALL: std::sync::OnceLock<Vec<u32>> = std::sync::OnceLock::new();
    SMALL.get_or_init(|| {
        const N: usize = 46_341;
        let mut composite = vec![false; N];
        let mut primes = Vec::new();
        for n in 3..N {
            if composite[n] || n % 2 == 0 {
                continue;
            }
            primes.push(n as u32);
            let mut m = n * n;
            while m < N {
                composite[m] = true;
                m += 2 * n;
            }
        }
        primes
    })
}

/// Chinese remaindering of a vector of residues modulo 31-bit primes, by
/// Garner's mixed radix: `x = d₀ + p₀(d₁ + p₁(d₂ + …))` with digits
/// `0 ≤ d_j < p_j`.  A new prime's digits take word operations only: the
/// known digits are evaluated modulo it by Horner's rule, one product by a
/// constant per digit and value (Shoup's precomputed quotient, a vector
/// kernel).  Big integers appear only when [`CrtVec::flush`] converts the
/// digits pushed since the previous flush (Horner in machine words over the
/// new digits, two a step, then one multiply-add against the part already
/// converted).  A lifting over k primes thus costs about k²/2 vector
/// operations per value and no big-integer reduction; flushing on a
/// geometric schedule (the modular RUR) stays cheap.  Call
/// [`CrtVec::flush`] before reading the values.
#[derive(Clone, Debug)]
pub struct CrtVec {
    /// The product of all primes pushed.
    modulus: BigInt,
    /// The values for the primes before `converted`, in `[0, ∏ p)`.
    values: Vec<BigInt>,
    /// The product of the primes before `converted`.
    converted_modulus: BigInt,
    converted: usize,
    /// The primes, in the order pushed.
    primes: Vec<u64>,
    /// `digits[j][i]`: the mixed-radix digit of value i at prime j.
    digits: Vec<Vec<u32>>,
}

impl CrtVec {
    /// An empty accumulator for vectors of length `n`.
    pub fn new(n: usize) -> CrtVec {
        CrtVec {
            modulus: BigInt::one(),
            values: vec![BigInt::zero(); n],
            converted_modulus: BigInt::one(),
            converted: 0,
            primes: Vec::new(),
            digits: Vec::new(),
        }
    }

    /// The number of residue vectors pushed.
    pub fn primes(&self) -> usize {
        self.primes.len()
    }

    /// The bit size of the product of all primes pushed.
    pub fn modulus_bits(&self) -> u64 {
        self.modulus.bits()
    }

    /// The product of the primes pushed.
    pub fn modulus(&self) -> &BigInt {
        &self.modulus
    }

    /// The values in `[0, M)` (after [`CrtVec::flush`]).
    pub fn values(&self) -> &[BigInt] {
        debug_assert_eq!(
            self.converted,
            self.primes.len(),
            "CrtVec read before flush"
        );
        &self.values
    }

    /// Adds the residues `r` (in `[0, p)`) modulo a new prime `p`, distinct
    /// from those pushed before.
    pub fn push(&mut self, fp: &Fp, r: &[u64]) {
        assert_eq!(r.len(), self.values.len());
        let p = fp.p;
        // y = d₀ + p₀(d₁ + … + p_{j−2} d_{j−1}) mod p, by Horner from the
        // last digit (kept below 2^32, congruent)
        let mut y = vec![0u32; r.len()];
        let mut prefix = 1u64; // p₀⋯p_{j−1} mod p
        for (t, d) in self.digits.iter().enumerate().rev() {
            crate::budget::check();
            let a = self.primes[t] % p;
            crate::number::modkernel::shoup_horner(&mut y, d, a, (a << 32) / p, p);
            prefix = fp.mul(prefix, a);
        }
        // d_j = (r − y)·(p₀⋯p_{j−1})⁻¹ mod p
        let inv = fp.inv(prefix).expect("distinct primes");
        let digits: Vec<u32> = y
            .iter()
            .zip(r)
            .map(|(&yi, &ri)| fp.mul(fp.sub(ri, fp.reduce(u64::from(yi))), inv) as u32)
            .collect();
        self.digits.push(digits);
        self.primes.push(p);
        self.modulus *= BigInt::from(p);
    }

    /// The values in the symmetric range `(−M/2, M/2]` (flushes first).
    pub fn symmetric_values(&mut self) -> Vec<BigInt> {
        self.flush();
        let m = &self.modulus;
        self.values.iter().map(|x| symmetric_mod(x, m)).collect()
    }

    /// True when the newest prime left every value's symmetric
    /// representative as it was: each newest mixed-radix digit is 0 (a
    /// value in `[0, M/2)`) or `p − 1` (a negative value).  A heuristic for
    /// "the image has stabilised", never a proof.
    pub fn newest_digits_stable(&self) -> bool {
        match (self.digits.last(), self.primes.last()) {
            (Some(d), Some(&p)) if self.primes.len() >= 2 => {
                let top = (p - 1) as u32;
                d.iter().all(|&x| x == 0 || x == top)
            }
            _ => false,
        }
    }

    /// Converts the digits pushed since the last flush into the values.
    pub fn flush(&mut self) {
        let (from, to) = (self.converted, self.primes.len());
        if from == to {
            return;
        }
        let primes = &self.primes[from..to];
        let mut limbs: Vec<u64> = Vec::with_capacity((to - from).div_ceil(2) + 1);
        for (i, v) in self.values.iter_mut().enumerate() {
            crate::budget::check();
            // z = d_from + p_from(d_{from+1} + …) by Horner from the top, in
            // machine words, two digits a step
            limbs.clear();
            let digit = |j: usize| u64::from(self.digits[from + j][i]);
            let mut j = primes.len();
            if j % 2 == 1 {
                j -= 1;
                limbs.push(digit(j));
            }
            while j >= 2 {
                j -= 2;
                // z ← z·p_j p_{j+1} + (d_j + p_j d_{j+1})  (both < 2^62)
                let m = primes[j] * primes[j + 1];
                mul_add_limbs(&mut limbs, m, digit(j) + primes[j] * digit(j + 1));
            }
            if limbs.iter().any(|&l| l != 0) {
                let z = BigInt::from_biguint(Sign::Plus, super::fixed::biguint_from_limbs(&limbs));
                *v += &self.converted_modulus * z;
            }
        }
        for &q in primes {
            self.converted_modulus *= BigInt::from(q);
        }
        self.converted = to;
    }
}

/// `z ← z·m + c` on little-endian 64-bit limbs.
fn mul_add_limbs(z: &mut Vec<u64>, m: u64, c: u64) {
    let mut carry = u128::from(c);
    for l in z.iter_mut() {
        let t = u128::from(*l) * u128::from(m) + carry;
        *l = t as u64;
        carry = t >> 64;
    }
    if carry != 0 {
        z.push(carry as u64);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use num_traits::Signed;

    /// `Fp::pow` equals repeated multiplication and BigInt's modpow, and
    /// satisfies Fermat's little theorem.
    #[test]
    fn powers_by_squaring() {
        let fp = Fp::new(prime31(5));
        for a in [0u64, 1, 2, 12345, fp.p - 1] {
            let mut slow = 1u64;
            for e in 0..70u64 {
                assert_eq!(fp.pow(a, e), slow, "{a}^{e}");
                slow = fp.mul(slow, a);
            }
            let e = 987_654_321u64;
            let want = BigInt::from(a).modpow(&BigInt::from(e), &BigInt::from(fp.p));
            assert_eq!(BigInt::from(fp.pow(a, e)), want);
            if a != 0 {
                assert_eq!(fp.pow(a, fp.p - 1), 1);
            }
        }
    }

    /// Block residues equal the residues one prime at a time, for big and
    /// small, positive and negative integers, across block boundaries.
    #[test]
    fn block_residues_match_direct_reduction() {
        let big = (BigInt::from(3) << 4000usize) - BigInt::from(12345);
        let ints = [
            big.clone(),
            -big.clone(),
            BigInt::zero(),
            BigInt::from(-5),
            BigInt::from(prime31(3)) * BigInt::from(prime31(9)),
            -(big << 64usize) + BigInt::one(),
            // every digit 2^64 − 1: the largest terms of the fold
            (BigInt::one() << 4096usize) - BigInt::one(),
            // the longest folded integer, the shortest dotted one, and an
            // odd number of 32-bit digits
            (BigInt::one() << 512usize) - BigInt::one(),
            BigInt::one() << 512usize,
            -((BigInt::one() << 544usize) + BigInt::from(7)),
        ];
        let mut blocks = BlockResidues::new(ints.iter().collect());
        for k in [0usize, 1, 7, 8, 9, 3, 17, 40] {
            let fp = Fp::new(prime31(k));
            let want: Vec<u64> = ints.iter().map(|x| fp.reduce_big(x)).collect();
            assert_eq!(blocks.residues(k, &fp), want, "prime index {k}");
            for x in &ints {
                let r = x.mod_floor(&BigInt::from(fp.p));
                assert_eq!(BigInt::from(fp.reduce_big(x)), r);
            }
        }
    }

    #[test]
    fn barrett_reduction_matches_remainder() {
        for i in [0usize, 1, 7] {
            let p = prime31(i);
            let fp = Fp::new(p);
            let mut state = 0x9e37_79b9_7f4a_7c15u64;
            for _ in 0..1000 {
                let x = crate::tests::xorshift(&mut state);
                assert_eq!(fp.reduce(x), x % p);
                let (a, b) = (x % p, (x >> 20) % p);
                assert_eq!(fp.mul(a, b), ((a as u128 * b as u128) % p as u128) as u64);
                if a != 0 {
                    assert_eq!(fp.mul(a, fp.inv(a).unwrap()), 1);
                }
            }
        }
    }

    /// The sieve finds exactly the numbers Miller–Rabin calls prime, over
    /// more than one window (none skipped, none repeated).
    #[test]
    fn the_sieve_agrees_with_miller_rabin() {
        let ps: Vec<u64> = (0..3200).map(prime31).collect();
        let mut c = 1u64 << 31;
        for (i, &p) in ps.iter().enumerate() {
            c -= 1;
            while !is_prime_u32(c) {
                c -= 1;
            }
            assert_eq!(p, c, "prime {i}");
        }
    }

    #[test]
    fn primes_below_2_31_are_prime_and_decreasing() {
        let ps: Vec<u64> = (0..50).map(prime31).collect();
        assert_eq!(ps[0], 2147483647); // 2^31 − 1
        assert!(ps.windows(2).all(|w| w[0] > w[1]));
        for &p in &ps {
            assert!(
                (2..50_000u64)
                    .take_while(|d| d * d <= p)
                    .all(|d| p % d != 0)
            );
        }
        // composite numbers are rejected (a strong pseudoprime to base 2)
        for c in [2047u64, 561, 1373653, 25326001, 2147483645] {
            assert!(!is_prime_u32(c), "{c} is composite");
        }
    }

    #[test]
    fn crt_of_vectors_recovers_big_signed_values() {
        let xs: Vec<BigInt> = vec![
            -(BigInt::from(7u32) << 200usize) + 12345,
            BigInt::from(3u32).pow(150u32),
            BigInt::zero(),
            BigInt::from(-1),
        ];
        let mut c = CrtVec::new(xs.len());
        let mut k = 0;
        while c.modulus().bits() < 260 {
            let fp = Fp::new(prime31(k));
            let r: Vec<u64> = xs.iter().map(|x| fp.reduce_big(x)).collect();
            c.push(&fp, &r);
            k += 1;
        }
        c.flush();
        let back: Vec<BigInt> = c
            .values()
            .iter()
            .map(|v| symmetric_mod(v, c.modulus()))
            .collect();
        assert_eq!(back, xs);
        assert_eq!(c.primes(), k);
    }

    /// Garner's digits converted in several flushes (the modular RUR's
    /// geometric schedule) give the values of one flush at the end, which
    /// are the residues' unique preimages in [0, M): checked against the
    /// residues directly, for 1 to 60 primes.
    #[test]
    fn crt_flushed_in_steps_agrees_with_one_flush() {
        let xs: Vec<BigInt> = vec![
            (BigInt::one() << 1800usize) - BigInt::from(977),
            -(BigInt::from(5u32).pow(700u32)),
            BigInt::from(prime31(0)) * BigInt::from(prime31(1)),
            BigInt::from(-1),
            BigInt::zero(),
        ];
        let mut stepped = CrtVec::new(xs.len());
        let mut once = CrtVec::new(xs.len());
        for k in 0..60 {
            let fp = Fp::new(prime31(k));
            let r: Vec<u64> = xs.iter().map(|x| fp.reduce_big(x)).collect();
            stepped.push(&fp, &r);
            once.push(&fp, &r);
            if k % 7 == 3 || k == 59 {
                stepped.flush();
                let m = stepped.modulus().clone();
                assert_eq!(stepped.primes(), k + 1);
                for (v, x) in stepped.values().iter().zip(&xs) {
                    assert!(!v.is_negative() && v < &m);
                    assert_eq!(v, &x.mod_floor(&m), "after {} primes", k + 1);
                }
            }
        }
        once.flush();
        assert_eq!(once.values(), stepped.values());
        assert_eq!(once.modulus(), stepped.modulus());
    }

    /// Inverses modulo word primes, composite moduli and moduli past 2^62
    /// (the 128-bit path): `a·a⁻¹ ≡ 1`, and `None` exactly when
    /// `gcd(a, n) ≠ 1`.
    #[test]
    fn inverses_modulo_n() {
        use num_integer::Integer;
        for n in [
            7u64,
            12,
            2147483647,
            (1 << 62) - 57,
            (1 << 62) + 135,
            (1 << 63) - 25,
        ] {
            for a in [1u64, 2, 3, 6, 1234567, n - 1, n + 5] {
                match inv_mod(a, n) {
                    Some(b) => {
                        assert!(b < n);
                        assert_eq!(
                            (a as u128 % n as u128) * b as u128 % n as u128,
                            1 % n as u128,
                            "{a} mod {n}"
                        );
                    }
                    None => assert_ne!(a.gcd(&n), 1, "{a} mod {n}"),
                }
            }
        }
    }
}
