//! Horner's rule at a dyadic point in big floating point, with a rigorous
//! error bound: a filter in front of the exact integer evaluation.
//!
//! The exact value `2^{kn}·p(m/2^k)` has `B + n·max(bits(m), k)` bits for
//! coefficients of `B` bits — about 10⁴ bits for a degree-128 polynomial
//! at a 2^-80 point.  Its sign (and Newton's step) rarely needs them: here
//! each Horner step keeps `prec` bits below the larger of its two terms,
//!
//! `A' = trunc(A·m·2^{F−k−F'}) + trunc(c·2^{−F'})` (truncations toward 0), `F' = max(bits(A·m) + F − k, bits(c)) − prec`,
//!
//! so the value is `A·2^F` with `A` of about `prec` bits.  Each step adds an
//! error below `3·2^{F'}` (two truncations, and one more when the
//! coefficient is read from its top bits, [`FloatCoeffs`]) and multiplies the error so far
//! by `|x|`; the bound `ε' = ε·x̄ + 2^{F'+2}` is carried in [`Up`], numbers
//! rounded upwards, with `x̄ ≥ |x|` from the top 62 bits of `|m|`.  The sign
//! of `A` is that of `p(x)` when `|A|·2^F > ε`; otherwise the caller falls
//! back to exact arithmetic (more bits rarely help: what is lost is
//! cancellation near a root, which more precision only postpones).

use crate::number::sign_z;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// Below this degree the exact pass is used directly: its numbers stay
/// short, and a floating pass costs about as much per step.
pub(crate) const FLOAT_MIN_DEGREE: u64 = 24;

/// A non-negative upper bound `mant·2^exp` (`mant < 2^62`), rounded up
/// by every operation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Up {
    mant: u64,
    exp: i64,
}

impl Up {
    const ZERO: Up = Up { mant: 0, exp: 0 };

    /// `⌈v⌉` normalised to a mantissa below 2^62 (rounding up).
    fn from_u128(v: u128, exp: i64) -> Up {
        let bits = 128 - v.leading_zeros() as i64;
        if bits <= 62 {
            return Up {
                mant: v as u64,
                exp,
            };
        }
        let sh = bits - 62;
        // ⌊v / 2^sh⌋ + 1 < 2^62 + 1; one more shift keeps it below 2^62
        let q = (v >> sh) + 1;
        if q >> 62 != 0 {
            Up {
                mant: ((q >> 1) + 1) as u64,
                exp: exp + sh + 1,
            }
        } else {
            Up {
                mant: q as u64,
                exp: exp + sh,
            }
        }
    }

    /// An upper bound of `|m|·2^-k`.
    pub(crate) fn of_dyadic(m: &BigInt, k: u64) -> Up {
        let bits = m.bits() as i64;
        let sh = (bits - 62).max(0);
        let top: u64 = (m.magnitude() >> sh as usize)
            .iter_u64_digits()
            .next()
            .unwrap_or(0);
        // |m| < (top + 1)·2^sh when bits were dropped
        let top = if sh > 0 {
            u128::from(top) + 1
        } else {
            u128::from(top)
        };
        Up::from_u128(top, sh - k as i64)
    }

    /// `2^e`.
    fn pow2(e: i64) -> Up {
        Up { mant: 1, exp: e }
    }

    fn mul(self, o: Up) -> Up {
        Up::from_u128(u128::from(self.mant) * u128::from(o.mant), self.exp + o.exp)
    }

    fn add(self, o: Up) -> Up {
        if self.mant == 0 {
            return o;
        }
        if o.mant == 0 {
            return self;
        }
        let (hi, lo) = if self.exp >= o.exp {
            (self, o)
        } else {
            (o, self)
        };
        let d = hi.exp - lo.exp;
        if d >= 64 {
            // lo < 2^62·2^lo.exp ≤ 2^hi.exp: one unit of hi's mantissa
            return Up::from_u128(u128::from(hi.mant) + 1, hi.exp);
        }
        // exact in 128 bits at lo's exponent
        Up::from_u128((u128::from(hi.mant) << d) + u128::from(lo.mant), lo.exp)
    }

    /// `e` with `self < 2^e` (for `self = 0`, any: `i64::MIN`).
    fn log2_above(self) -> i64 {
        if self.mant == 0 {
            i64::MIN
        } else {
            self.exp + 64 - i64::from(self.mant.leading_zeros())
        }
    }
}

/// The result of [`horner_float`]: `p(x) ≈ a·2^f` within `err`, and with
/// the derivative asked for, `p′(x) ≈ d·2^fd` (no bound claimed).
pub(crate) struct FloatValue {
    pub a: BigInt,
    pub f: i64,
    err: Up,
    pub d: BigInt,
    pub fd: i64,
}

impl FloatValue {
    /// How many leading bits of `a·2^f` are right: `g` with
    /// `err ≤ 2^-g·|a|·2^f` (`None` when the bound does not separate the
    /// value from 0).
    pub(crate) fn correct_bits(&self) -> Option<i64> {
        if self.a.is_zero() || self.err.mant == 0 {
            return (!self.a.is_zero()).then_some(i64::MAX);
        }
        let g = self.a.bits() as i64 - 1 + self.f - self.err.log2_above();
        (g >= 0).then_some(g)
    }

    /// The value as a rational (exactly `a·2^f`).
    #[cfg(test)]
    pub(crate) fn to_q(&self) -> crate::number::Q {
        crate::number::dyadic(
            self.a.clone() << self.f.max(0) as usize,
            (-self.f).max(0) as usize,
        )
    }

    /// `⌊(self / by)·2^k⌋ / 2^k` of the two values' centres, by one
    /// integer division (no gcd); `None` when `by`'s centre is 0.
    pub(crate) fn quotient_floor(&self, by: &FloatValue, k: usize) -> Option<crate::number::Q> {
        use num_integer::Integer;
        if by.a.is_zero() {
            return None;
        }
        // a·2^f / (b·2^g) · 2^k = a·2^(f − g + k) / b
        let sh = self.f - by.f + k as i64;
        let q = if sh >= 0 {
            (&self.a << sh as usize).div_floor(&by.a)
        } else {
            self.a.div_floor(&(&by.a << (-sh) as usize))
        };
        Some(crate::number::dyadic(q, k))
    }

    /// The sign of `p(x)` when `|a|·2^f` exceeds the error bound.
    pub(crate) fn sign(&self) -> Option<i32> {
        if self.a.is_zero() {
            return None;
        }
        // |a|·2^f ≥ 2^(bits(a) − 1 + f) and err < 2^log2_above
        (self.a.bits() as i64 - 1 + self.f >= self.err.log2_above()).then(|| sign_z(&self.a))
    }
}

/// Integer coefficients for [`horner_float`]: each `c` as sign and
/// magnitude limbs of its top `TOP_BITS` bits `⌊|c| / 2^e⌋`, and `e`, so a
/// step reads a short number: `⌊⌊|c|/2^e⌋·2^{e−f}⌋` is within 2 of
/// `|c|/2^f` (one truncation more than the whole coefficient's).
#[derive(Clone, Debug)]
pub(crate) struct FloatCoeffs {
    tops: Vec<(bool, Vec<u64>, i64)>,
}

/// The bits kept of each coefficient by [`FloatCoeffs`].
const TOP_BITS: u64 = 640;

impl FloatCoeffs {
    /// Prepares `c` (ascending, not empty).
    pub(crate) fn new(c: &[BigInt]) -> FloatCoeffs {
        let tops = c
            .iter()
            .map(|x| {
                let e = x.bits().saturating_sub(TOP_BITS);
                let top = x.magnitude() >> e as usize;
                (x.is_negative(), top.to_u64_digits(), e as i64)
            })
            .collect();
        FloatCoeffs { tops }
    }
}

/// A signed mantissa: sign and little-endian magnitude limbs (no leading
/// zero limb; empty for 0).
#[derive(Clone, Default)]
struct Mant {
    neg: bool,
    mag: Vec<u64>,
}

impl Mant {
    fn to_bigint(&self) -> BigInt {
        let m = BigInt::from(crate::number::fixed::biguint_from_limbs(&self.mag));
        if self.neg { -m } else { m }
    }
}

fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// Bits of a trimmed magnitude (`i64::MIN` for 0, so it loses every max).
fn mag_bits(x: &[u64]) -> i64 {
    match x.last() {
        None => i64::MIN,
        Some(&t) => 64 * x.len() as i64 - i64::from(t.leading_zeros()),
    }
}

/// `out = a·b` (magnitudes).
fn mul_into(a: &[u64], b: &[u64], out: &mut Vec<u64>) {
    out.clear();
    out.resize(a.len() + b.len(), 0);
    for (i, &x) in a.iter().enumerate() {
        let mut carry = 0u128;
        for (j, &y) in b.iter().enumerate() {
            let t = u128::from(x) * u128::from(y) + u128::from(out[i + j]) + carry;
            out[i + j] = t as u64;
            carry = t >> 64;
        }
        out[i + b.len()] = carry as u64;
    }
    trim(out);
}

/// `out = ⌊x·2^s⌋` for a magnitude (a right shift truncates).
fn shift_into(x: &[u64], s: i64, out: &mut Vec<u64>) {
    out.clear();
    if x.is_empty() {
        return;
    }
    if s >= 0 {
        let (limbs, bits) = ((s / 64) as usize, (s % 64) as u32);
        out.reserve(limbs + x.len() + 1);
        out.resize(limbs, 0);
        if bits == 0 {
            out.extend_from_slice(x);
        } else {
            let mut carry = 0u64;
            for &l in x {
                out.push((l << bits) | carry);
                carry = l >> (64 - bits);
            }
            out.push(carry);
        }
    } else {
        let (limbs, bits) = (((-s) / 64) as usize, ((-s) % 64) as u32);
        if limbs >= x.len() {
            return;
        }
        let x = &x[limbs..];
        out.reserve(x.len());
        if bits == 0 {
            out.extend_from_slice(x);
        } else {
            for i in 0..x.len() {
                let hi = x.get(i + 1).map_or(0, |&h| h << (64 - bits));
                out.push((x[i] >> bits) | hi);
            }
        }
    }
    trim(out);
}

/// `a += (neg, b)` on signed mantissas.
fn add_signed(a: &mut Mant, neg: bool, b: &[u64]) {
    if b.is_empty() {
        return;
    }
    if a.mag.is_empty() {
        a.neg = neg;
        a.mag.extend_from_slice(b);
        return;
    }
    if a.neg == neg {
        let mut carry = false;
        if a.mag.len() < b.len() {
            a.mag.resize(b.len(), 0);
        }
        for i in 0..a.mag.len() {
            let (s1, c1) = a.mag[i].overflowing_add(b.get(i).copied().unwrap_or(0));
            let (s2, c2) = s1.overflowing_add(u64::from(carry));
            a.mag[i] = s2;
            carry = c1 || c2;
            if !carry && i >= b.len() {
                break;
            }
        }
        if carry {
            a.mag.push(1);
        }
        return;
    }
    // opposite signs: subtract the smaller magnitude from the larger
    let a_ge = a.mag.len() > b.len()
        || (a.mag.len() == b.len()
            && a.mag.iter().rev().cmp(b.iter().rev()) != std::cmp::Ordering::Less);
    let (big, small): (Vec<u64>, &[u64]) = if a_ge {
        (std::mem::take(&mut a.mag), b)
    } else {
        a.neg = neg;
        let old = std::mem::take(&mut a.mag);
        let mut r = b.to_vec();
        sub_in_place(&mut r, &old);
        a.mag = r;
        trim(&mut a.mag);
        return;
    };
    a.mag = big;
    sub_in_place(&mut a.mag, small);
    trim(&mut a.mag);
}

/// `x −= y` for magnitudes with `x ≥ y`.
fn sub_in_place(x: &mut [u64], y: &[u64]) {
    let mut borrow = false;
    for i in 0..x.len() {
        let (d1, b1) = x[i].overflowing_sub(y.get(i).copied().unwrap_or(0));
        let (d2, b2) = d1.overflowing_sub(u64::from(borrow));
        x[i] = d2;
        borrow = b1 || b2;
        if !borrow && i >= y.len() {
            break;
        }
    }
}

/// Scratch buffers of one evaluation.
#[derive(Default)]
struct Scratch {
    prod: Vec<u64>,
    add: Vec<u64>,
}

/// One Horner step kept to `prec` bits: `t ← trunc(t·m·2^{ft−k−f}) +
/// trunc(c·2^{ec−f})`, `f = max(magnitudes) − prec`, for `t·2^{ft}`, the
/// point `m/2^k` (magnitude `m`, sign `m_neg`) and `c·2^{ec}` (`c_exact`
/// false when c stands for a longer number truncated to its top bits).
/// Returns the new exponent; the result is within `3·2^f` of the exact
/// step; `None` when c's truncation would be visible (`f < ec` for an
/// inexact c).
#[allow(clippy::too_many_arguments)]
fn step(
    t: &mut Mant,
    ft: i64,
    (m, m_neg, k): (&[u64], bool, i64),
    (c_neg, c, ec, c_exact): (bool, &[u64], i64, bool),
    prec: i64,
    sc: &mut Scratch,
) -> Option<i64> {
    mul_into(&t.mag, m, &mut sc.prod);
    let mag_t = mag_bits(&sc.prod).saturating_add(ft - k);
    let mag_c = mag_bits(c).saturating_add(ec);
    let top = mag_t.max(mag_c);
    if top < i64::MIN / 2 {
        t.mag.clear();
        return Some(0);
    }
    let f = top - prec;
    if f < ec && !c_exact && !c.is_empty() {
        return None;
    }
    t.neg ^= m_neg;
    shift_into(&sc.prod, ft - k - f, &mut t.mag);
    if t.mag.is_empty() {
        t.neg = false;
    }
    shift_into(c, ec - f, &mut sc.add);
    add_signed(t, c_neg, &sc.add);
    if t.mag.is_empty() {
        t.neg = false;
    }
    Some(f)
}

/// Horner's rule for `p` (ascending coefficients `exact`, not empty, and
/// the same prepared by [`FloatCoeffs`]) at `x = m/2^k` keeping `prec`
/// bits per step (see the module documentation); with `derivative`,
/// `p′(x)` too, by `D ← D·x + A` before each step.  `None` when `prec`
/// asks for more bits of a coefficient than [`FloatCoeffs`] keeps.
pub(crate) fn horner_float(
    exact: &[BigInt],
    c: &FloatCoeffs,
    m: &BigInt,
    k: u64,
    prec: u64,
    derivative: bool,
) -> Option<FloatValue> {
    let n = c.tops.len() - 1;
    let (k, prec) = (k as i64, prec as i64);
    let xbar = Up::of_dyadic(m, k as u64);
    let mm = m.magnitude().to_u64_digits();
    let point = (&mm[..], m.is_negative(), k);
    let mut a = Mant {
        neg: exact[n].is_negative(),
        mag: exact[n].magnitude().to_u64_digits(),
    };
    let mut f = 0i64;
    let mut err = Up::ZERO;
    let (mut d, mut fd) = (Mant::default(), 0i64);
    let mut sc = Scratch::default();
    let long = n > super::zpoly::SHORT;
    for j in (0..n).rev() {
        if long {
            crate::budget::check();
        }
        if derivative {
            fd = step(&mut d, fd, point, (a.neg, &a.mag, f, true), prec, &mut sc)?;
        }
        let (neg, top, e) = &c.tops[j];
        f = step(&mut a, f, point, (*neg, top, *e, *e == 0), prec, &mut sc)?;
        // three truncations' worth, each below 2^f
        err = err.mul(xbar).add(Up::pow2(f + 2));
    }
    Some(FloatValue {
        a: a.to_bigint(),
        f,
        err,
        d: d.to_bigint(),
        fd,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::Q;
    use crate::poly::ZPoly;
    use num_traits::One;
    use proptest::prelude::*;

    /// The bound holds: `|p(x) − a·2^f| ≤ err` exactly, for points of every
    /// size, and a decided sign is the exact one.
    fn check(p: &ZPoly, m: &BigInt, k: u64, prec: u64) -> Result<(), TestCaseError> {
        let Some(v) = horner_float(p.coeffs(), &FloatCoeffs::new(p.coeffs()), m, k, prec, true)
        else {
            return Ok(());
        };
        let x = Q::new(m.clone(), BigInt::one() << k as usize);
        let (num, den) = p.eval_homogeneous(x.numer(), x.denom());
        let exact = Q::new(num, den);
        let approx = if v.f >= 0 {
            Q::from_integer(&v.a << v.f as usize)
        } else {
            Q::new(v.a.clone(), BigInt::one() << (-v.f) as usize)
        };
        let err = if v.err.exp >= 0 {
            Q::from_integer(BigInt::from(v.err.mant) << v.err.exp as usize)
        } else {
            Q::new(
                BigInt::from(v.err.mant),
                BigInt::one() << (-v.err.exp) as usize,
            )
        };
        prop_assert!((&exact - &approx).abs() <= err, "{p:?} at {m}/2^{k}");
        if let Some(s) = v.sign() {
            prop_assert_eq!(s, p.sign_at(&x));
        }
        Ok(())
    }

    proptest! {
        #[test]
        fn the_error_bound_holds(c in prop::collection::vec(-1i64 << 40..1i64 << 40, 1..40),
                                 big in 0usize..300,
                                 m in any::<i64>(), extra in 0usize..100,
                                 k in 0u64..140, prec in 8u64..200) {
            let coeffs: Vec<BigInt> = c.iter().enumerate()
                .map(|(i, &x)| BigInt::from(x) << (if i % 3 == 0 { big } else { 0 }))
                .collect();
            let p = ZPoly::new(coeffs);
            prop_assume!(p.degree().is_some());
            check(&p, &(BigInt::from(m) << extra), k, prec)?;
        }
    }

    /// Near a root the sign is decided once the precision covers the
    /// distance, and never wrongly; at the root it is not decided.
    #[test]
    fn near_a_root() {
        // (x − 3/8)(x² − 2)(x − 3/8 − 2^-60)
        let r = ZPoly::new(vec![BigInt::from(-3), BigInt::from(8)]);
        let s = ZPoly::new(vec![
            -((BigInt::from(3) << 57usize) + BigInt::one()),
            BigInt::one() << 60usize,
        ]);
        let p = &(&r * &ZPoly::from_i64s(&[-2, 0, 1])) * &s;
        let at_root = BigInt::from(3) << 77usize;
        assert!(
            horner_float(
                p.coeffs(),
                &FloatCoeffs::new(p.coeffs()),
                &at_root,
                80,
                200,
                false
            )
            .unwrap()
            .sign()
            .is_none()
        );
        for (m, k) in [
            (at_root.clone() + 1, 80u64),
            (at_root - 1, 80),
            (BigInt::from(7), 4),
        ] {
            let v =
                horner_float(p.coeffs(), &FloatCoeffs::new(p.coeffs()), &m, k, 200, false).unwrap();
            let x = Q::new(m.clone(), BigInt::one() << k as usize);
            assert_eq!(v.sign(), Some(p.sign_at(&x)), "{m}/2^{k}");
        }
    }

    /// The quotient of two centres, floored on the grid 2^-k, equals the
    /// floor of the exact quotient of their rationals (signs mixed, at
    /// positive and negative exponents).
    #[test]
    fn quotient_floor_is_the_floor_of_the_quotient() {
        let p = ZPoly::from_i64s(&[-7, 3, 0, 5, -1]);
        let q = ZPoly::from_i64s(&[2, -9, 4, 1, 3]);
        for (m, k) in [
            (BigInt::from(5), 3u64),
            (BigInt::from(-1234567), 10),
            (BigInt::from(3) << 70usize, 2),
        ] {
            let at = |r: &ZPoly| {
                horner_float(r.coeffs(), &FloatCoeffs::new(r.coeffs()), &m, k, 200, false).unwrap()
            };
            let (a, b) = (at(&p), at(&q));
            for bits in [0usize, 5, 64, 130] {
                let x = a.to_q() / b.to_q();
                let want = crate::number::dyadic_floor(x.numer(), x.denom(), bits);
                assert_eq!(
                    a.quotient_floor(&b, bits),
                    Some(want),
                    "{m}/2^{k}, {bits} bits"
                );
                let y = b.to_q() / a.to_q();
                let want = crate::number::dyadic_floor(y.numer(), y.denom(), bits);
                assert_eq!(b.quotient_floor(&a, bits), Some(want));
            }
        }
    }
}
