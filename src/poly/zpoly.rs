//! Univariate polynomials over Z ([`ZPoly`]) and Q ([`QPoly`]): content and
//! primitive part, gcd, square-free part and factorisation (Yun), exact
//! evaluation and signs at rationals, Taylor shifts, reversal and root
//! bounds.
//!
//! Key idea (STYLE, "performance habits"): computations run over Z on
//! primitive polynomials; a polynomial over Q is a rational constant times a
//! primitive integer polynomial, and rationals appear only at the edges.

use super::modp::{poly_gcd_mod, zpoly_mod};
use super::ring::Ring;
use super::upoly::UPoly;
use crate::number::fixed::{AtWidth, Fixed, MAX_LIMBS, at_width, push_limbs};
use crate::number::prime31::{CrtVec, Fp, prime31};
use crate::number::{Q, sign_z};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::borrow::Cow;
use std::ops::AddAssign;

/// Polynomials with integer coefficients.
pub type ZPoly = UPoly<BigInt>;
/// Polynomials with rational coefficients.
pub type QPoly = UPoly<Q>;

impl UPoly<BigInt> {
    /// The content: the non-negative gcd of the coefficients (0 for zero).
    pub fn content(&self) -> BigInt {
        // from the shortest non-zero coefficient: every later gcd is then
        // unbalanced or small (one division, then word-size steps), where
        // starting from the leading one pays a full gcd of two long ones
        let cs = self.coeffs();
        let Some(start) = cs.iter().filter(|c| !c.is_zero()).min_by_key(|c| c.bits()) else {
            return BigInt::zero();
        };
        let mut g = num_traits::Signed::abs(start);
        for c in cs.iter().rev() {
            if g.is_one() {
                break;
            }
            g = crate::number::gcd_z(&g, c);
        }
        g
    }

    /// The primitive part, normalised to a positive leading coefficient.
    pub fn primitive_part(&self) -> ZPoly {
        if self.is_zero() {
            return ZPoly::zero();
        }
        let mut g = self.content();
        if self.lc().is_negative() {
            g = -g;
        }
        if g.is_one() {
            return self.clone();
        }
        ZPoly::new(self.coeffs().iter().map(|c| c / &g).collect())
    }

    /// Converts to a polynomial over Q.
    pub fn to_q(&self) -> QPoly {
        self.map(|c| Q::from_integer(c.clone()))
    }

    /// Writes a rational polynomial as `k · P` with `P` primitive in Z[x] and
    /// positive leading coefficient; returns `(P, k)`.  Zero gives `(0, 0)`.
    pub fn from_q(p: &QPoly) -> (ZPoly, Q) {
        if p.is_zero() {
            return (ZPoly::zero(), Q::zero());
        }
        let l = crate::number::denom_lcm(p.coeffs());
        let z = ZPoly::new(
            p.coeffs()
                .iter()
                .map(|c| c.numer() * (&l / c.denom()))
                .collect(),
        );
        let pp = z.primitive_part();
        let k = Q::new(z.lc(), l) / Q::from_integer(pp.lc());
        (pp, k)
    }

    /// Exact value at a rational point.
    pub fn eval_q(&self, x: &Q) -> Q {
        let (num, den) = self.eval_homogeneous(x.numer(), x.denom());
        Q::new(num, den)
    }

    /// `(Σ c_i n^i d^(N-i), d^N)` for `x = n/d`: the value times `d^N`, exact
    /// in integers.
    pub fn eval_homogeneous(&self, n: &BigInt, d: &BigInt) -> (BigInt, BigInt) {
        let c = self.coeffs();
        if c.is_empty() {
            return (BigInt::zero(), BigInt::one());
        }
        crate::budget::check();
        let long = c.len() > SHORT;
        let mut acc = c[c.len() - 1].clone();
        let mut dpow = BigInt::one();
        for ci in c.iter().rev().skip(1) {
            if long {
                crate::budget::check();
            }
            dpow *= d;
            acc *= n;
            if !ci.is_zero() {
                acc += ci * &dpow;
            }
        }
        (acc, dpow)
    }

    /// Exact sign (-1, 0, 1) of the value at a rational point.
    pub fn sign_at(&self, x: &Q) -> i32 {
        // the denominator of a BigRational is positive, so d^N > 0
        sign_z(&self.eval_homogeneous(x.numer(), x.denom()).0)
    }

    /// Sign of the value at the dyadic point `m / 2^k` (see
    /// [`DyadicSigner`], which also serves repeated evaluations).
    pub fn sign_at_dyadic(&self, m: &BigInt, k: u64) -> i32 {
        DyadicSigner::new(self).sign_at(m, k)
    }

    /// `x^n p(1/x)`: the coefficients reversed.
    pub fn reversed(&self) -> ZPoly {
        let mut c = self.coeffs().to_vec();
        c.reverse();
        ZPoly::new(c)
    }

    /// `p(-x)`.
    pub fn neg_x(&self) -> ZPoly {
        ZPoly::new(
            self.coeffs()
                .iter()
                .enumerate()
                .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
                .collect(),
        )
    }

    /// `p(x + a)` (Taylor shift), `O(n²)` additions and multiplications.
    pub fn taylor_shift(&self, a: &BigInt) -> ZPoly {
        let mut c = self.coeffs().to_vec();
        if a.is_one() {
            taylor_shift_one(&mut c);
        } else if !a.is_zero() {
            let n = c.len();
            for i in 0..n.saturating_sub(1) {
                crate::budget::check();
                for j in (i..n - 1).rev() {
                    let (lo, hi) = c.split_at_mut(j + 1);
                    lo[j] += &hi[0] * a;
                }
            }
        }
        ZPoly::new(c)
    }

    /// `2^(k·n) p(x / 2^k)` for `k >= 0` or `p(2^(-k) x)` for `k < 0`,
    /// always an integer polynomial with the same roots scaled by `2^k`.
    pub fn scale_roots_pow2(&self, k: i64) -> ZPoly {
        let c = self.coeffs();
        let n = c.len();
        if n == 0 {
            return ZPoly::zero();
        }
        let top = self.bit_size() + k.unsigned_abs() * (n as u64 - 1);
        crate::budget::check_size("a polynomial with scaled roots", n, top);
        let out = c
            .iter()
            .enumerate()
            .map(|(i, ci)| {
                if k >= 0 {
                    ci << ((k as usize) * (n - 1 - i))
                } else {
                    ci << (((-k) as usize) * i)
                }
            })
            .collect();
        ZPoly::new(out)
    }

    /// An integer `k` with every complex root `|z| < 2^k` (Fujiwara's bound
    /// in powers of two).  `None` for constants.
    pub fn root_bound_log2(&self) -> Option<i64> {
        let n = self.degree().filter(|&d| d > 0)?;
        let c = self.coeffs();
        let bn = c[n].bits() as i64;
        let mut best = i64::MIN;
        for i in 1..=n {
            let a = &c[n - i];
            if a.is_zero() {
                continue;
            }
            // |a/c_n| < 2^(bits(a) - bits(c_n) + 1); the last term has a /2
            let mut t = a.bits() as i64 - bn + 1;
            if i == n {
                t -= 1;
            }
            let e = t.div_euclid(i as i64) + if t.rem_euclid(i as i64) != 0 { 1 } else { 0 };
            best = best.max(e);
        }
        if best == i64::MIN {
            // p = c x^n: all roots are 0
            return Some(-1);
        }
        Some(best + 1)
    }

    /// Multiplicity of the root 0 (the number of trailing zero coefficients).
    pub fn zero_root_multiplicity(&self) -> usize {
        self.coeffs().iter().take_while(|c| c.is_zero()).count()
    }

    /// Divides out `x^k` for the multiplicity `k` of the root 0.
    pub fn strip_zero_roots(&self) -> ZPoly {
        let k = self.zero_root_multiplicity();
        ZPoly::new(self.coeffs()[k..].to_vec())
    }

    /// Greatest common divisor, primitive with positive leading coefficient
    /// (`gcd(0, 0) = 0`).  A modular test first detects the frequent coprime
    /// case; otherwise the primitive PRS is used.
    pub fn gcd(&self, o: &ZPoly) -> ZPoly {
        if self.is_zero() {
            return o.primitive_part();
        }
        if o.is_zero() {
            return self.primitive_part();
        }
        // the common case first, before any content is computed: a constant
        // modular gcd proves coprimality whatever the contents
        if self.degree() == Some(0) || o.degree() == Some(0) || coprime_mod_p(self, o) {
            return ZPoly::constant(BigInt::one());
        }
        let (mut a, mut b) = (self.primitive_part(), o.primitive_part());
        if a.degree() < b.degree() {
            std::mem::swap(&mut a, &mut b);
        }
        modular_gcd(&a, &b)
    }

    /// Exact division over Q of primitive integer polynomials whose quotient
    /// is known to be integral (Gauss' lemma), e.g. `p / gcd(p, q)`.
    /// Panics if the division is not exact.
    pub fn div_exact_z(&self, b: &ZPoly) -> ZPoly {
        self.div_exact(b)
            .expect("division by a factor must be exact over Z")
    }

    /// The square-free part `p / gcd(p, p')`, primitive.
    pub fn squarefree_part(&self) -> ZPoly {
        if self.degree().unwrap_or(0) == 0 {
            return self.primitive_part();
        }
        let p = self.primitive_part();
        let g = p.gcd(&p.derivative());
        if g.degree() == Some(0) {
            p
        } else {
            p.div_exact_z(&g).primitive_part()
        }
    }

    /// Square-free factorisation (Yun): `pp(p) = ∏ f_i^i` with the `f_i`
    /// square-free, pairwise coprime and primitive; returns the non-constant
    /// `(f_i, i)`.
    pub fn squarefree_decomposition(&self) -> Vec<(ZPoly, u32)> {
        let a = self.primitive_part();
        if a.degree().unwrap_or(0) == 0 {
            return vec![];
        }
        let b = a.derivative();
        let c = a.gcd(&b);
        let mut w = a.div_exact_z(&c);
        let mut y = b.div_exact_z(&c);
        let mut z = &y - &w.derivative();
        let mut out = Vec::new();
        let mut i = 1;
        while w.degree().unwrap_or(0) > 0 {
            let g = w.gcd(&z);
            if g.degree().unwrap_or(0) > 0 {
                out.push((g.clone(), i));
            }
            w = w.div_exact_z(&g);
            y = z.div_exact_z(&g);
            z = &y - &w.derivative();
            i += 1;
        }
        out
    }

    /// Division with remainder over Q: `(q, r)` with `self = q·b + r`.
    pub fn divrem_q(&self, b: &ZPoly) -> (QPoly, QPoly) {
        let (q, r) = self.pseudo_divrem(b);
        let k = match (self.degree(), b.degree()) {
            (Some(da), Some(db)) if da >= db => b.lc().pow((da - db + 1) as u32),
            _ => BigInt::one(),
        };
        let kq = Q::from_integer(k);
        (q.to_q().map(|c| c / &kq), r.to_q().map(|c| c / &kq))
    }
}

/// An integer polynomial prepared for exact signs at many dyadic points
/// `m / 2^k` (bisection): the sign of `2^(k·n) p(m/2^k) = Σ c_i m^i 2^(k(n-i))`
/// by Horner's rule, in [`Fixed`] arithmetic when `|m| < 2^64` and the
/// headroom bound below allows, else in `BigInt`.  The coefficients are
/// converted to two's-complement limbs once, in [`DyadicSigner::new`].
///
/// Headroom: let `|c_i| < 2^B` and `L = max(bits(|m|), k)`, so `|m| < 2^L`
/// and `2^k <= 2^L`.  After the step for `c_i` the accumulator is
/// `Σ_{l>=i} c_l m^(l-i) 2^(k(n-l))`, and before adding `c_i 2^(k(n-i))` it
/// is the same sum without that term; each term is below `2^(B+nL)` in
/// absolute value, so every number met is below
/// `(n+1) 2^(B+nL) <= 2^(B + nL + bits(n))`.  Hence
/// `B + nL + bits(n) + 1 <= 64·N` bits of two's complement hold them all
/// exactly (products and sums modulo `2^(64N)` are exact when the true
/// value fits).  `m < 0` is `|m|` with the odd coefficients negated.
pub struct DyadicSigner<'a> {
    p: Cow<'a, ZPoly>,
    /// The coefficients, `width` limbs each.
    limbs: Vec<u64>,
    width: usize,
    /// `B`: every `|c_i| < 2^B`.
    coeff_bits: u64,
    /// The coefficients' top bits for [`DyadicSigner::float_value`], made
    /// on first use.
    tops: std::sync::OnceLock<super::horner::FloatCoeffs>,
}

impl<'a> DyadicSigner<'a> {
    /// Prepares `p`: `O(n)` conversions.
    pub fn new(p: &'a ZPoly) -> Self {
        Self::prepare(Cow::Borrowed(p))
    }

    /// As [`DyadicSigner::new`], owning `p`.
    pub fn owned(p: ZPoly) -> DyadicSigner<'static> {
        DyadicSigner::prepare(Cow::Owned(p))
    }

    fn prepare(p: Cow<'a, ZPoly>) -> Self {
        let coeff_bits = p.coeffs().iter().map(|x| x.bits()).max().unwrap_or(0);
        let width = usize::try_from((coeff_bits + 1).div_ceil(64)).unwrap_or(usize::MAX);
        let mut limbs = Vec::new();
        if width <= MAX_LIMBS {
            limbs.reserve_exact(width * p.coeffs().len());
            for c in p.coeffs() {
                let fits = push_limbs(c, width, &mut limbs);
                debug_assert!(fits);
            }
        }
        DyadicSigner {
            p,
            limbs,
            width,
            coeff_bits,
            tops: std::sync::OnceLock::new(),
        }
    }

    /// `p(m/2^k)` in floating point with `prec` bits per step and a
    /// rigorous error bound ([`horner_float`](super::horner::horner_float)),
    /// with `p′` when `derivative`.
    pub(crate) fn float_value(
        &self,
        m: &BigInt,
        k: u64,
        prec: u64,
        derivative: bool,
    ) -> Option<super::horner::FloatValue> {
        let c = self.p.coeffs();
        let tops = self.tops.get_or_init(|| super::horner::FloatCoeffs::new(c));
        super::horner::horner_float(c, tops, m, k, prec, derivative)
    }

    /// Exact sign (-1, 0, 1) of `p(m / 2^k)`.  `O(n)` operations on numbers
    /// of `B + n·max(bits(m), k)` bits.
    pub fn sign_at(&self, m: &BigInt, k: u64) -> i32 {
        self.sign_at_past(m, k, 0)
    }

    /// [`DyadicSigner::sign_at`] for a caller whose own floating pass with
    /// `tried` bits per step did not decide: floating passes with no more
    /// bits than that are not run again.
    pub(crate) fn sign_at_past(&self, m: &BigInt, k: u64, tried: u64) -> i32 {
        let c = self.p.coeffs();
        if c.is_empty() {
            return 0;
        }
        crate::budget::check();
        if let Some(s) = self.sign_at_fixed(m, k) {
            return s;
        }
        if let Some(s) = self.sign_at_truncated(m, k, tried) {
            return s;
        }
        let long = c.len() > SHORT;
        let mut acc = c[c.len() - 1].clone();
        let mut sh = 0u64;
        for ci in c.iter().rev().skip(1) {
            if long {
                crate::budget::check();
            }
            sh += k;
            acc *= m;
            if !ci.is_zero() {
                acc += ci << (sh as usize);
            }
        }
        sign_z(&acc)
    }

    /// The sign from [`horner_float`](super::horner::horner_float) passes
    /// keeping `k + 128` and then `2k + 384` bits per step (plus
    /// `bits(n)`), when one decides and the exact pass's numbers (`n·max(bits(m),
    /// k)` bits beyond the coefficients) would be more than twice as long:
    /// away from clusters of roots, a few hundred bits instead of `n·k`.
    fn sign_at_truncated(&self, m: &BigInt, k: u64, tried: u64) -> Option<i32> {
        let n = (self.p.coeffs().len() - 1) as u64;
        if n < super::horner::FLOAT_MIN_DEGREE {
            return None;
        }
        let exact = n.checked_mul(m.bits().max(k))?;
        let log_n = 64 - u64::from(n.leading_zeros());
        for prec in [k + 128 + log_n, 2 * k + 384 + log_n] {
            if prec.checked_mul(2)? > exact {
                return None;
            }
            if prec <= tried {
                continue;
            }
            if let Some(s) = self.float_value(m, k, prec, false)?.sign() {
                return Some(s);
            }
        }
        None
    }

    /// The [`Fixed`] path, when the headroom bound allows it.
    fn sign_at_fixed(&self, m: &BigInt, k: u64) -> Option<i32> {
        if self.limbs.is_empty() {
            return None;
        }
        let mag = m.magnitude().to_u64()?;
        let n = (self.p.coeffs().len() - 1) as u64;
        let l = k.max(64 - u64::from(mag.leading_zeros()));
        let bits = l
            .checked_mul(n)?
            .checked_add(self.coeff_bits + (64 - u64::from(n.leading_zeros())) + 1)?;
        let job = Horner {
            signer: self,
            m: mag,
            m_negative: m.is_negative(),
            k,
        };
        at_width(usize::try_from(bits.div_ceil(64)).ok()?, job).ok()
    }
}

/// One Horner evaluation of a [`DyadicSigner`] at a width the headroom
/// bound allows.
struct Horner<'s, 'a> {
    signer: &'s DyadicSigner<'a>,
    m: u64,
    m_negative: bool,
    k: u64,
}

impl AtWidth for Horner<'_, '_> {
    type Output = i32;
    fn run<const N: usize>(self) -> i32 {
        let w = self.signer.width;
        let term = |i: usize| -> Fixed<N> {
            let t = Fixed::<N>::from_limbs(&self.signer.limbs[i * w..(i + 1) * w]);
            if self.m_negative && i % 2 == 1 {
                t.neg()
            } else {
                t
            }
        };
        let n = self.signer.limbs.len() / w - 1;
        let mut acc = term(n);
        for i in (0..n).rev() {
            acc = acc.mul_u64(self.m);
            let t = term(i);
            if !t.is_zero() {
                // k(n-i) <= nL < 64N by the bound
                acc += &t.shl((self.k * (n - i) as u64) as u32);
            }
        }
        i32::from(acc.signum())
    }
}

/// In-place Taylor shift by one, `p(x) -> p(x + 1)`, on ascending
/// coefficients: `n(n+1)/2` additions, no multiplications.  Generic over
/// the integer type (`BigInt`, or a fixed-width integer under a proven
/// headroom bound, as in VCA isolation).
pub fn taylor_shift_one<T>(c: &mut [T])
where
    T: for<'a> AddAssign<&'a T>,
{
    let long = c.len() > SHORT;
    for i in 0..c.len().saturating_sub(1) {
        if long {
            crate::budget::check();
        }
        taylor_shift_stage(&mut c[i..]);
    }
}

/// One stage of [`taylor_shift_one`]: `c_j += c_{j+1}` for `j` from the top
/// down (synthetic division by `x - 1`).  After stage `i` (on `c[i..]`) the
/// coefficient `c_i` of `p(x + 1)` is final.
#[inline]
pub fn taylor_shift_stage<T>(c: &mut [T])
where
    T: for<'a> AddAssign<&'a T>,
{
    for j in (0..c.len().saturating_sub(1)).rev() {
        let (lo, hi) = c.split_at_mut(j + 1);
        lo[j] += &hi[0];
    }
}

/// Polynomials up to this length are short: the budget checks sit in the
/// loops that repeat their (cheap) passes, not in each pass.
pub(crate) const SHORT: usize = 32;

/// True when `a` and `b` are certainly coprime over Q: their gcd modulo a
/// prime not dividing both leading coefficients is constant.  (`false` means
/// "unknown"; a modular gcd can only be too large, never too small, when the
/// degrees are preserved.)
fn coprime_mod_p(a: &ZPoly, b: &ZPoly) -> bool {
    for i in 0..2 {
        let m = Fp::new(prime31(i));
        let ra = zpoly_mod(&m, a);
        let rb = zpoly_mod(&m, b);
        if ra.last() == Some(&0) || rb.last() == Some(&0) {
            continue;
        }
        return poly_gcd_mod(&m, &ra, &rb).len() == 1;
    }
    false
}

/// Brown's small-primes gcd of primitive polynomials: modular gcds scaled
/// by `gcd(lc a, lc b)`, combined by the CRT over the primes of minimal
/// degree, and accepted only when the primitive candidate divides both
/// inputs exactly (so the answer is proven, whatever primes were used).
/// A candidate is tried when the newest prime left every value as it was
/// (and not twice the same one).
fn modular_gcd(a: &ZPoly, b: &ZPoly) -> ZPoly {
    let g = a.lc().gcd(&b.lc());
    let mut best: Option<usize> = None;
    let mut crt = CrtVec::new(0);
    let mut last: Option<ZPoly> = None;
    let mut i = 0;
    loop {
        crate::budget::check();
        let m = Fp::new(prime31(i));
        i += 1;
        let ra = zpoly_mod(&m, a);
        let rb = zpoly_mod(&m, b);
        if ra.last() == Some(&0) || rb.last() == Some(&0) {
            continue;
        }
        let h = poly_gcd_mod(&m, &ra, &rb);
        let d = h.len() - 1;
        if d == 0 {
            return ZPoly::constant(BigInt::one());
        }
        match best {
            Some(bd) if d > bd => continue, // unlucky prime
            Some(bd) if d == bd => {}
            _ => {
                best = Some(d);
                crt = CrtVec::new(d + 1);
                last = None;
            }
        }
        // the monic gcd times g
        let lc = m.inv(h[d]).expect("non-zero leading coefficient");
        let gm = m.mul(m.reduce_big(&g), lc);
        let scaled: Vec<u64> = h.iter().map(|c| m.mul(*c, gm)).collect();
        crt.push(&m, &scaled);
        // a candidate only once the newest prime changed no value (the
        // division below is the proof)
        if !crt.newest_digits_stable() {
            continue;
        }
        let cand = ZPoly::new(crt.symmetric_values()).primitive_part();
        if last.as_ref() != Some(&cand)
            && a.div_exact(&cand).is_some()
            && b.div_exact(&cand).is_some()
        {
            return cand;
        }
        last = Some(cand);
    }
}

impl UPoly<Q> {
    /// Division with remainder over the field Q: `(q, r)` with
    /// `self = q·b + r`, `deg r < deg b`.  Panics if `b` is zero.
    pub fn divrem(&self, b: &QPoly) -> (QPoly, QPoly) {
        let db = b.degree().expect("division by the zero polynomial");
        let Some(da) = self.degree() else {
            return (QPoly::zero(), QPoly::zero());
        };
        if da < db {
            return (QPoly::zero(), self.clone());
        }
        let inv = Q::one() / b.lc();
        let mut r: Vec<Q> = self.coeffs().to_vec();
        let mut q = vec![Q::zero(); da - db + 1];
        let b_bits = b.coeffs().iter().map(Ring::bit_size).max().unwrap_or(0);
        for k in (0..=da - db).rev() {
            let t = r[k + db].rmul(&inv);
            // a row is db products of coefficients: the clock is read every
            // row when that is much work (amortised over 64 rows, fuzzing
            // found a tangent line's radical shape running 1.7 s past its
            // deadline under the sanitizer), and large coefficients take
            // the ring's operations (no binary gcd)
            crate::budget::check_for((t.bit_size() + b_bits).saturating_mul(db as u64));
            if !t.is_zero() {
                for (j, bj) in b.coeffs().iter().enumerate() {
                    r[k + j].rsub_assign(&t.rmul(bj));
                }
            }
            q[k] = t;
        }
        r.truncate(db);
        (QPoly::new(q), QPoly::new(r))
    }

    /// Remainder modulo `b`.
    pub fn rem(&self, b: &QPoly) -> QPoly {
        self.divrem(b).1
    }

    /// Monic version (zero stays zero).
    pub fn monic(&self) -> QPoly {
        if self.is_zero() {
            return QPoly::zero();
        }
        let inv = Q::one() / self.lc();
        self.map(|c| c * &inv)
    }

    /// Extended gcd over Q: `(g, s, t)` with `g = s·self + t·b`, `g` monic.
    pub fn gcdext(&self, b: &QPoly) -> (QPoly, QPoly, QPoly) {
        let (mut r0, mut r1) = (self.clone(), b.clone());
        let (mut s0, mut s1) = (QPoly::constant(Q::one()), QPoly::zero());
        let (mut t0, mut t1) = (QPoly::zero(), QPoly::constant(Q::one()));
        while !r1.is_zero() {
            crate::budget::check();
            let (q, r) = r0.divrem(&r1);
            r0 = std::mem::replace(&mut r1, r);
            let s2 = &s0 - &(&q * &s1);
            s0 = std::mem::replace(&mut s1, s2);
            let t2 = &t0 - &(&q * &t1);
            t0 = std::mem::replace(&mut t1, t2);
        }
        if r0.is_zero() {
            return (r0, s0, t0);
        }
        let inv = Q::one() / r0.lc();
        (
            r0.map(|c| c * &inv),
            s0.map(|c| c * &inv),
            t0.map(|c| c * &inv),
        )
    }

    /// Exact value at a rational point.
    pub fn eval_rational(&self, x: &Q) -> Q {
        let mut acc = Q::zero();
        for c in self.coeffs().iter().rev() {
            acc = acc * x + c;
        }
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    #[test]
    fn gcd_and_squarefree() {
        let a = ZPoly::from_i64s(&[-2, 0, 1]); // x^2 - 2
        let b = ZPoly::from_i64s(&[-1, 3]); // 3x - 1
        let p = &a.pow(3) * &b;
        assert_eq!(p.gcd(&p.derivative()), a.pow(2));
        assert_eq!(p.squarefree_part(), &a * &b);
        let d = p.squarefree_decomposition();
        assert_eq!(d, vec![(b.clone(), 1), (a.clone(), 3)]);
        assert_eq!(a.gcd(&b), ZPoly::from_i64s(&[1]));
    }

    #[test]
    fn evaluation_and_shifts() {
        let p = ZPoly::from_i64s(&[-2, 0, 1]);
        assert_eq!(p.eval_q(&q(3, 2)), q(1, 4));
        assert_eq!(p.sign_at(&q(7, 5)), -1);
        assert_eq!(p.sign_at(&q(3, 2)), 1);
        assert_eq!(p.sign_at_dyadic(&BigInt::from(3), 1), 1);
        assert_eq!(
            p.taylor_shift(&BigInt::from(1)),
            ZPoly::from_i64s(&[-1, 2, 1])
        );
        assert_eq!(
            p.taylor_shift(&BigInt::from(-2)),
            ZPoly::from_i64s(&[2, -4, 1])
        );
        assert_eq!(p.neg_x(), p);
        assert_eq!(p.reversed(), ZPoly::from_i64s(&[1, 0, -2]));
        // roots ±√2 < 2^k
        let k = p.root_bound_log2().unwrap();
        assert!(k >= 1);
        assert_eq!(p.scale_roots_pow2(1), ZPoly::from_i64s(&[-8, 0, 1]));
    }

    #[test]
    fn from_q_normalises() {
        let p = QPoly::new(vec![q(-1, 2), q(0, 1), q(-3, 4)]);
        let (z, k) = ZPoly::from_q(&p);
        assert_eq!(z, ZPoly::from_i64s(&[2, 0, 3]));
        assert_eq!(z.to_q().map(|c| c * &k), p);
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_primitive_part() {
        use crate::poly::ZPoly;
        let p = ZPoly::from_i64s(&[4, -6, -2]);
        assert_eq!(p.primitive_part(), ZPoly::from_i64s(&[-2, 3, 1]));
    }

    #[test]
    fn doc_gcd() {
        use crate::poly::ZPoly;
        let a = ZPoly::from_i64s(&[-1, 0, 1]); // x^2 - 1
        let b = ZPoly::from_i64s(&[1, 2, 1]); // (x + 1)^2
        assert_eq!(a.gcd(&b), ZPoly::from_i64s(&[1, 1]));
    }

    #[test]
    fn doc_squarefree_decomposition() {
        use crate::poly::ZPoly;
        // (x - 1)^2 (x + 2)
        let p = ZPoly::from_i64s(&[2, -3, 0, 1]);
        let f = p.squarefree_decomposition();
        assert_eq!(
            f,
            vec![
                (ZPoly::from_i64s(&[2, 1]), 1),
                (ZPoly::from_i64s(&[-1, 1]), 2)
            ]
        );
    }

    #[test]
    fn doc_dyadicsigner() {
        use crate::poly::ZPoly;
        use crate::poly::zpoly::DyadicSigner;
        use num_bigint::BigInt;
        let p = ZPoly::from_i64s(&[-2, 0, 1]); // x^2 - 2
        let s = DyadicSigner::new(&p);
        assert_eq!(s.sign_at(&BigInt::from(181), 7), -1); // 181/128 < √2
        assert_eq!(s.sign_at(&BigInt::from(-182), 7), 1); // -182/128 < -√2
        assert_eq!(s.sign_at(&BigInt::from(-4), 1), 1);
    }
}
