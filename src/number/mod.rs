//! Exact scalars: parsing of exact numbers, rational helpers, the quadratic
//! field elements `a + b√d` ([`QSqrt`]), word-size modular arithmetic for the
//! multi-modular algorithms, fixed-width integers for inner loops whose
//! operands a headroom bound keeps small ([`fixed::Fixed`]), and decimal
//! approximations for printing.
//!
//! Key idea: every number that enters quadsect is an exact rational.  A
//! decimal such as `1.77777777777` is `177777777777/10^11`, never a float.
//! Floats appear only in printed approximations, and those are computed from
//! the exact value by integer arithmetic ([`approx_decimal`]).

pub(crate) mod filter;
pub mod fixed;
pub(crate) mod float;
pub(crate) mod lehmer;
pub(crate) mod modkernel;
mod parse;
pub(crate) mod prime31;
pub mod qsqrt;
pub(crate) mod reconstruct;
mod sign;
pub(crate) mod xball;

pub use float::{double_parts, double_value};
pub use parse::{NumberError, NumberMode, parse_rational, parse_rational_with, scan_number_with};
pub use qsqrt::QSqrt;
pub use sign::Sign;

use num_bigint::{BigInt, Sign as BigSign};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Exact rational numbers (the coefficient field of every input).
pub type Q = BigRational;
/// Arbitrary-precision integers.
pub type Z = BigInt;

/// The rational `n/d` from small integers.
pub fn q(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// The integer `n` as a rational.
pub fn qi(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

/// Prints a rational as `a` or `a/b` (lowest terms, sign on the numerator).
pub fn fmt_q(x: &Q) -> String {
    // printing is quadratic in the size of the number
    crate::budget::check_for(x.numer().bits() + x.denom().bits());
    use num_traits::ToPrimitive;
    // word-size parts print without num-bigint's general conversion
    let part = |z: &Z| match z.to_i64() {
        Some(v) => v.to_string(),
        None => z.to_str_radix(10),
    };
    if x.denom().is_one() {
        part(x.numer())
    } else {
        let mut s = part(x.numer());
        s.push('/');
        s.push_str(&part(x.denom()));
        s
    }
}

/// The exact sign of a rational: -1, 0 or 1.
pub fn sign_q(x: &Q) -> i32 {
    sign_z(x.numer())
}

/// The exact sign of an integer: -1, 0 or 1.
pub fn sign_z(x: &Z) -> i32 {
    match x.sign() {
        BigSign::Minus => -1,
        BigSign::NoSign => 0,
        BigSign::Plus => 1,
    }
}

/// `floor(log2 |x|)` for a non-zero rational, computed exactly.
pub fn floor_log2_q(x: &Q) -> i64 {
    debug_assert!(!x.is_zero());
    let n = x.numer().abs();
    let d = x.denom().clone();
    let mut e = n.bits() as i64 - d.bits() as i64;
    // 2^e <= n/d < 2^(e+1) after at most one correction in each direction
    loop {
        let lhs_ge = if e >= 0 {
            n >= (&d << (e as usize))
        } else {
            (&n << ((-e) as usize)) >= d
        };
        if !lhs_ge {
            e -= 1;
            continue;
        }
        let next_ge = if e + 1 >= 0 {
            n >= (&d << ((e + 1) as usize))
        } else {
            (&n << ((-(e + 1)) as usize)) >= d
        };
        if next_ge {
            e += 1;
            continue;
        }
        return e;
    }
}

/// A decimal approximation of `x` with `digits` significant digits, rounded
/// to nearest, computed exactly with integers (no floating point).
///
/// Plain notation is used for moderate exponents, scientific otherwise.
pub fn approx_decimal(x: &Q, digits: usize) -> String {
    approx_decimal_ratio(x.numer(), x.denom(), digits)
}

/// `x > 0` as a decimal of three significant digits rounded down
/// (`up = false`) or up: a printed bound stays a bound.
pub(crate) fn decimal_bound(x: &Q, up: bool) -> String {
    if !x.is_positive() {
        return "0".into();
    }
    let e10 = (x.to_f64().unwrap_or(1.0).log10().floor()) as i32;
    let sh = 2 - e10;
    let ten =
        |k: i32| Q::from_integer(num_traits::pow(BigInt::from(10), k.unsigned_abs() as usize));
    let scaled = if sh >= 0 { x * ten(sh) } else { x / ten(sh) };
    let n = if up { scaled.ceil() } else { scaled.floor() }.to_integer();
    let s = n.to_string();
    let exp = -sh + s.len() as i32 - 1;
    let mant = if s.len() > 1 {
        format!("{}.{}", &s[..1], s[1..].trim_end_matches('0'))
    } else {
        s.clone()
    };
    let mant = mant.trim_end_matches('.').to_string();
    format!("{mant}e{exp}")
}

/// [`approx_decimal`] of `n/d` (`d > 0`, not necessarily in lowest terms),
/// in integers only: no reduction of the fraction.
pub(crate) fn approx_decimal_ratio(n: &BigInt, d: &BigInt, digits: usize) -> String {
    debug_assert!(d.is_positive());
    let digits = digits.max(1);
    if n.is_zero() {
        return "0".to_string();
    }
    crate::budget::check_for(n.bits() + d.bits());
    let neg = n.is_negative();
    let an = n.magnitude();
    let dm = d.magnitude();
    // 2^(l2−1) < |x| < 2^(l2+1): with sh = digits − ⌊(l2−1)·log10 2⌋,
    // q = ⌊|x|·10^sh⌋ has digits + 1 or digits + 2 decimal digits (one
    // more step if the estimate was off); one product, one division and
    // one conversion to decimal, then the rounding on the digits
    let l2 = an.bits() as i64 - dm.bits() as i64;
    let mut sh = digits as i64 - (((l2 - 1) as f64) * std::f64::consts::LOG10_2).floor() as i64;
    // a power of two in d is shifted out of the dividend instead
    // (⌊⌊a/2^t⌋/b⌋ = ⌊a/(2^t·b)⌋): a shorter division (QSqrt::approx
    // divides by D·2^k)
    let t = dm.trailing_zeros().unwrap_or(0) as usize;
    let odd = dm >> t;
    let q = loop {
        // 10^k and the quotient's digits in u128 when they fit (k ≤ 38;
        // the quotient has digits + 1 or + 2 digits): num-bigint's pow and
        // to_str_radix were half of this function
        let k = sh.unsigned_abs() as u32;
        let p = match 10u128.checked_pow(k) {
            Some(p) => num_bigint::BigUint::from(p),
            None => num_traits::pow(num_bigint::BigUint::from(10u32), k as usize),
        };
        let q = if sh >= 0 {
            ((an * p) >> t) / &odd
        } else {
            (an >> t) / (&odd * p)
        };
        let q = match q.to_u128() {
            Some(v) => v.to_string(),
            None => q.to_str_radix(10),
        };
        if q.len() > digits {
            break q;
        }
        sh += 1;
    };
    // |x| = (q + f)·10^-sh with 0 ≤ f < 1; rounding half up to `digits`
    // digits adds 5 at the first dropped digit: the fraction f cannot
    // carry across (⌊(N + f)/M⌋ = ⌊N/M⌋ for integers N, M), so the first
    // dropped digit decides
    let mut e10 = q.len() as i64 - 1 - sh;
    let mut s: Vec<u8> = q.as_bytes()[..digits].to_vec();
    if q.as_bytes()[digits] >= b'5' {
        let mut i = digits;
        loop {
            if i == 0 {
                // 9.99… → 10.0…: one more digit, shifted out again
                s.insert(0, b'1');
                s.truncate(digits);
                e10 += 1;
                break;
            }
            i -= 1;
            if s[i] == b'9' {
                s[i] = b'0';
            } else {
                s[i] += 1;
                break;
            }
        }
    }
    let s = String::from_utf8(s).expect("decimal digits");

    let sign = if neg { "-" } else { "" };
    if (-6..=20).contains(&e10) {
        if e10 >= 0 {
            let int_len = (e10 + 1) as usize;
            if int_len >= s.len() {
                let mut t = s.clone();
                t.push_str(&"0".repeat(int_len - s.len()));
                format!("{sign}{t}")
            } else {
                let frac = s[int_len..].trim_end_matches('0');
                if frac.is_empty() {
                    format!("{sign}{}", &s[..int_len])
                } else {
                    format!("{sign}{}.{}", &s[..int_len], frac)
                }
            }
        } else {
            let zeros = "0".repeat((-e10 - 1) as usize);
            let frac = s.trim_end_matches('0');
            format!("{sign}0.{zeros}{frac}")
        }
    } else {
        let frac = s[1..].trim_end_matches('0');
        if frac.is_empty() {
            format!("{sign}{}e{}", &s[..1], e10)
        } else {
            format!("{sign}{}.{}e{}", &s[..1], frac, e10)
        }
    }
}

/// `n / 2^k` in lowest terms (only powers of two can cancel, so no gcd).
pub fn dyadic(n: Z, k: usize) -> Q {
    let tz = n.trailing_zeros().map_or(k, |t| (t as usize).min(k));
    Q::new_raw(n >> tz, Z::from(1) << (k - tz))
}

/// `⌊n / d · 2^k⌋ / 2^k` (`d > 0`): a dyadic rational within `2^-k` below
/// `n / d`, found with one division and no gcd.
pub fn dyadic_floor(n: &Z, d: &Z, k: usize) -> Q {
    use num_integer::Integer;
    dyadic((n << k).div_floor(d), k)
}

/// `n/d` in lowest terms (`d ≠ 0`): `Ratio::new` with [`gcd_z`] (Lehmer)
/// instead of num-bigint's binary gcd, which dominates the reduction of
/// the constructions' large integers.
pub fn q_new(n: Z, d: Z) -> Q {
    debug_assert!(!d.is_zero());
    // long operands where one divides the other (an integer, or 1/k: a
    // construction's value with its denominator cancelled): one division
    // instead of Euclid over all the bits
    if d.bits() >= 512 && !n.is_zero() {
        let n_big = n.bits() >= d.bits();
        let (big, small) = if n_big { (&n, &d) } else { (&d, &n) };
        if big.bits() - small.bits() < 64 {
            // q = big/small exactly (signs included): n/d = q, or 1/q
            let (q, r) = num_integer::Integer::div_rem(big, small);
            if r.is_zero() {
                return if n_big {
                    Q::new_raw(q, Z::one())
                } else if q.is_negative() {
                    Q::new_raw(-Z::one(), -q)
                } else {
                    Q::new_raw(Z::one(), q)
                };
            }
        }
    }
    let g = gcd_z(&n, &d);
    let (mut n, mut d) = if g.is_one() { (n, d) } else { (n / &g, d / &g) };
    if d.is_negative() {
        n = -n;
        d = -d;
    }
    Q::new_raw(n, d)
}

/// `a = b` by one cross product each way: num-rational's `==` goes
/// through its `cmp`, a continued-fraction recursion of divisions (most of
/// the cost of printing a component's doubles).  Reduced or not.
pub(crate) fn q_eq(a: &Q, b: &Q) -> bool {
    if a.denom() == b.denom() {
        return a.numer() == b.numer();
    }
    a.numer() * b.denom() == b.numer() * a.denom()
}

/// `a` against `b` by one cross product each way (positive denominators;
/// else num-rational's order): num-rational's `cmp` is a continued-fraction
/// recursion of divisions, several times dearer on the dyadic ends of
/// isolating intervals.
pub(crate) fn q_cmp(a: &Q, b: &Q) -> std::cmp::Ordering {
    if !(a.denom().is_positive() && b.denom().is_positive()) {
        return a.cmp(b);
    }
    if a.denom() == b.denom() {
        return a.numer().cmp(b.numer());
    }
    let (sa, sb) = (a.numer().sign(), b.numer().sign());
    if sa != sb {
        return sa.cmp(&sb);
    }
    (a.numer() * b.denom()).cmp(&(b.numer() * a.denom()))
}

/// `a·b` in lowest terms, cross-reducing with [`gcd_z`] (as `Ratio`'s
/// product does with num-bigint's gcd).
pub fn q_mul(a: &Q, b: &Q) -> Q {
    if a.is_zero() || b.is_zero() {
        return Q::zero();
    }
    if a.denom().is_one() && b.denom().is_one() {
        return Q::from_integer(a.numer() * b.numer());
    }
    let g1 = gcd_z(a.numer(), b.denom());
    let g2 = gcd_z(b.numer(), a.denom());
    let div = |x: &Z, g: &Z| if g.is_one() { x.clone() } else { x / g };
    Q::new_raw(
        div(a.numer(), &g1) * div(b.numer(), &g2),
        div(a.denom(), &g2) * div(b.denom(), &g1),
    )
}

/// `a + b` in lowest terms (Knuth, TAOCP vol. 2, §4.5.1 — Henrici's sum:
/// with `g = gcd(da, db)` the sum is `(na·(db/g) + nb·(da/g)) / (da·(db/g))`
/// and only `gcd(numerator, g)` can remain), with [`gcd_z`]; integers add
/// without any gcd.  num-rational reduces every result with num-bigint's
/// binary gcd, quadratic in the bits even against 1.
pub fn q_add(a: &Q, b: &Q) -> Q {
    add_signed(a, b, false)
}

/// `a − b` in lowest terms (as [`q_add`]).
pub fn q_sub(a: &Q, b: &Q) -> Q {
    add_signed(a, b, true)
}

fn add_signed(a: &Q, b: &Q, negate: bool) -> Q {
    let c = if negate {
        -b.numer()
    } else {
        b.numer().clone()
    };
    let (an, ad, bd) = (a.numer(), a.denom(), b.denom());
    if ad.is_one() && bd.is_one() {
        return Q::from_integer(an + c);
    }
    let g = gcd_z(ad, bd);
    let (ad_g, bd_g) = (ad / &g, bd / &g);
    let t = an * &bd_g + c * &ad_g;
    if t.is_zero() {
        return Q::zero();
    }
    if g.is_one() {
        // gcd(t, ad·bd) = 1 when gcd(ad, bd) = 1
        return Q::new_raw(t, ad * bd);
    }
    let g2 = gcd_z(&t, &g);
    Q::new_raw(t / &g2, ad_g * (bd / g2))
}

/// Divides the integers `xs` by their content (the gcd of all, positive);
/// nothing when they are all zero or the content is 1.
pub(crate) fn divide_content_z(xs: &mut [Z]) {
    let mut g = Z::zero();
    for x in xs.iter() {
        if g.is_one() {
            return;
        }
        g = gcd_z(&g, x);
    }
    if g.is_zero() || g.is_one() {
        return;
    }
    for x in xs.iter_mut() {
        if !x.is_zero() {
            *x = &*x / &g;
        }
    }
}

/// `gcd(|a|, |b|)`, fast when the sizes differ or a value fits a word.
///
/// num-bigint's gcd is binary (Stein): every step shifts the whole
/// operands, so `gcd(huge, small)` costs as much as `gcd(huge, huge)`.
/// Here word-size operands finish in native arithmetic, the twos come out
/// by shifts, and the rest is Lehmer's gcd on limbs ([`lehmer`]: blocks of
/// about 62 bits of quotients applied in one pass, a Euclidean remainder
/// when the sizes differ).  Content computations (`gcd(g, cᵢ)` with a small
/// running g) become one short division per coefficient.
pub fn gcd_z(a: &Z, b: &Z) -> Z {
    use num_bigint::BigUint;
    use num_traits::ToPrimitive;
    if a.is_zero() {
        return Z::from(b.magnitude().clone());
    }
    if b.is_zero() {
        return Z::from(a.magnitude().clone());
    }
    if let (Some(u), Some(v)) = (a.magnitude().to_u64(), b.magnitude().to_u64()) {
        return Z::from(gcd_u64(u, v));
    }
    // the twos apart (gcd(2^i·x, 2^j·y) = 2^min(i,j)·gcd(x, y) for odd x,
    // y): the copies are shifted instead of cloned, so this is free, and
    // the denominators of cleared doubles (powers of two times a small
    // factor) shrink to words
    let (ta, tb) = (
        a.trailing_zeros().unwrap_or(0),
        b.trailing_zeros().unwrap_or(0),
    );
    let (x, y): (BigUint, BigUint) = (a.magnitude() >> ta, b.magnitude() >> tb);
    let t = ta.min(tb);
    let g = lehmer::gcd(&x, &y);
    Z::from(if t == 0 { g } else { g << t })
}

/// Binary gcd of machine words.
pub(crate) fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    let k = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << k;
        }
    }
}

/// Least common multiple of the denominators of a list of rationals.
pub fn denom_lcm<'a>(xs: impl IntoIterator<Item = &'a Q>) -> Z {
    let mut l = Z::one();
    for x in xs {
        lcm_assign(&mut l, x.denom());
    }
    l
}

/// `l ← lcm(l, d)` for positive `l` and `d`, with no gcd when `d` already
/// divides `l` (the usual case when clearing the denominators of a matrix
/// or a polynomial: a handful of distinct denominators, many repeats).
pub fn lcm_assign(l: &mut Z, d: &Z) {
    if d.is_one() || (&*l % d).is_zero() {
        return;
    }
    let g = gcd_z(l, d);
    *l = &*l / g * d;
}

/// Rational bounds `(l, h)` with `l <= √x <= h` and `h − l` about `2^-bits`
/// (`x >= 0`).
pub fn sqrt_bounds(x: &Q, bits: u32) -> (Q, Q) {
    if !x.is_positive() {
        return (Q::zero(), Q::zero());
    }
    let k = bits as usize + 4;
    let nd = x.numer() * x.denom();
    let s = (nd << (2 * k)).sqrt();
    let den = x.denom() << k;
    (Q::new(s.clone(), den.clone()), Q::new(s + 1u32, den))
}

/// The squares modulo `m ≤ 128`, as a bit mask.
const fn square_mask(m: u64) -> u128 {
    let (mut mask, mut k) = (0u128, 0u64);
    while k < m {
        mask |= 1 << ((k * k) % m);
        k += 1;
    }
    mask
}

/// False when `x ≥ 0` is certainly not a square: a square is a quadratic
/// residue modulo 64, 63, 65 and 11 (as in GMP's `mpz_perfect_square_p`);
/// together the four reject all but about 1 in 100 non-squares, for one
/// short division instead of an integer square root.
fn may_be_square(x: &Z) -> bool {
    const M64: u128 = square_mask(64);
    const M63: u128 = square_mask(63);
    const M65: u128 = square_mask(65);
    const M11: u128 = square_mask(11);
    let low = x.magnitude().iter_u64_digits().next().unwrap_or(0);
    if (M64 >> (low & 63)) & 1 == 0 {
        return false;
    }
    // 45045 = 63·65·11
    let r = (x.magnitude() % 45045u32)
        .iter_u64_digits()
        .next()
        .unwrap_or(0);
    (M63 >> (r % 63)) & 1 == 1 && (M65 >> (r % 65)) & 1 == 1 && (M11 >> (r % 11)) & 1 == 1
}

/// Integer square root test: `Some(r)` with `r*r == x` when `x >= 0` is a
/// perfect square.
pub fn exact_sqrt_z(x: &Z) -> Option<Z> {
    if x.is_negative() || !may_be_square(x) {
        return None;
    }
    let r = x.sqrt();
    if &(&r * &r) == x { Some(r) } else { None }
}

/// Rational square root test: `Some(r)` with `r >= 0`, `r*r == x`.
pub fn exact_sqrt_q(x: &Q) -> Option<Q> {
    let n = exact_sqrt_z(x.numer())?;
    let d = exact_sqrt_z(x.denom())?;
    Some(Q::new(n, d))
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;

    #[test]
    fn printed_bounds_round_the_right_way() {
        let third = Q::new(1.into(), 3.into());
        assert_eq!(decimal_bound(&third, false), "3.33e-1");
        assert_eq!(decimal_bound(&third, true), "3.34e-1");
        let x = Q::new(1.into(), BigInt::from(1u64 << 40));
        assert_eq!(decimal_bound(&x, false), "9.09e-13");
        assert_eq!(decimal_bound(&Q::from_integer(1.into()), true), "1e0");
        assert_eq!(decimal_bound(&Q::zero(), true), "0");
    }

    #[test]
    fn approx_rounds_and_carries() {
        assert_eq!(approx_decimal(&q(2, 3), 3), "0.667");
        assert_eq!(approx_decimal(&q(999, 1000), 2), "1");
        assert_eq!(approx_decimal(&q(187, 9), 20), "20.777777777777777778");
        assert_eq!(approx_decimal(&q(1, 3_000_000_000), 3), "3.33e-10");
        assert_eq!(approx_decimal(&qi(-5), 4), "-5");
        assert_eq!(approx_decimal(&q(1, 8), 20), "0.125");
        assert_eq!(
            approx_decimal(&Q::from_integer(num_traits::pow(BigInt::from(10), 30)), 3),
            "1e30"
        );
    }

    proptest::proptest! {
        /// The cross-product order and equality agree with num-rational's,
        /// reduced or not (one denominator shared, signs mixed).
        #[test]
        fn q_cmp_and_q_eq_agree_with_ratio(
            a in -10_000i64..10_000, b in 1i64..10_000,
            c in -10_000i64..10_000, d in 1i64..10_000,
            k in 1i64..50, shift in 0usize..200,
        ) {
            let big = |v: i64| BigInt::from(v) << shift;
            let (x, y) = (Q::new(big(a), big(b)), Q::new(big(c), big(d)));
            let xr = Q::new_raw(big(a) * k, big(b) * k); // unreduced
            proptest::prop_assert_eq!(q_cmp(&x, &y), x.cmp(&y));
            proptest::prop_assert_eq!(q_cmp(&xr, &y), x.cmp(&y));
            proptest::prop_assert_eq!(q_eq(&xr, &x), true);
            proptest::prop_assert_eq!(q_eq(&x, &y), x == y);
            let z = Q::new_raw(big(c), big(b)); // the same denominator
            proptest::prop_assert_eq!(q_cmp(&Q::new_raw(big(a), big(b)), &z), x.cmp(&z));
        }

        /// Dividing by the content leaves a primitive vector, the same up
        /// to a positive factor.
        #[test]
        fn divide_content_leaves_a_primitive_multiple(
            v in proptest::collection::vec(-1_000i64..1_000, 1..8),
            g in 1i64..1_000, shift in 0usize..300,
        ) {
            let orig: Vec<BigInt> = v.iter().map(|&x| (BigInt::from(x) * g) << shift).collect();
            let mut w = orig.clone();
            divide_content_z(&mut w);
            let c = w.iter().fold(BigInt::zero(), |acc, x| acc.gcd(x));
            proptest::prop_assert!(c.is_zero() || c.is_one());
            if let Some(i) = orig.iter().position(|x| !x.is_zero()) {
                // w = orig / m for one positive m
                let m = Q::new(orig[i].clone(), w[i].clone());
                proptest::prop_assert!(m.is_positive());
                for (o, x) in orig.iter().zip(&w) {
                    proptest::prop_assert_eq!(Q::from_integer(o.clone()), &m * Q::from_integer(x.clone()));
                }
            }
        }
    }

    #[test]
    fn gcd_z_agrees_with_num_bigint() {
        let big = BigInt::from(3u32).pow(200) * BigInt::from(14u32);
        let cases = [
            (BigInt::from(0), BigInt::from(0)),
            (BigInt::from(0), BigInt::from(-12)),
            (BigInt::from(-18), BigInt::from(12)),
            (big.clone(), BigInt::from(21)),
            (BigInt::from(-21), big.clone()),
            (big.clone(), BigInt::from(2u32).pow(90) * 7),
            (big.clone() * 5, big.clone() * 10 + &big),
            (BigInt::from(u64::MAX), BigInt::from(u64::MAX - 1)),
            (BigInt::from(1u128 << 100), BigInt::from(1u128 << 40)),
        ];
        for (a, b) in cases {
            assert_eq!(gcd_z(&a, &b), a.gcd(&b), "gcd({a}, {b})");
        }
    }

    proptest::proptest! {
        /// Lehmer steps on balanced multi-word operands (with a large
        /// common factor, so the answer is not 1) give num-bigint's gcd.
        #[test]
        fn lehmer_gcd_agrees(
            a in proptest::collection::vec(proptest::num::u64::ANY, 1..6),
            b in proptest::collection::vec(proptest::num::u64::ANY, 1..6),
            g in proptest::collection::vec(proptest::num::u64::ANY, 0..3),
            s1 in 0usize..200,
            s2 in 0usize..200,
        ) {
            let make = |v: &[u64]| -> BigInt {
                v.iter().fold(BigInt::zero(), |acc, &w| (acc << 64usize) + w)
            };
            let g = make(&g) + 1;
            let (x, y) = (make(&a) * &g, -make(&b) * &g);
            proptest::prop_assert_eq!(gcd_z(&x, &y), x.gcd(&y));
            // near-equal operands: long runs of quotient 1
            let z = &x + &g;
            proptest::prop_assert_eq!(gcd_z(&x, &z), x.gcd(&z));
            // powers of two on either side (the twos are taken apart)
            let (xs, ys) = (&x << s1, &y << s2);
            proptest::prop_assert_eq!(gcd_z(&xs, &ys), xs.gcd(&ys));
            proptest::prop_assert_eq!(gcd_z(&xs, &(&g << s2)), xs.gcd(&(&g << s2)));
        }

        /// `q_new`, `q_mul`, `q_add` give num-rational's canonical values
        /// (lowest terms, positive denominator, 0 as 0/1) on multi-word
        /// operands with common factors, zeros and signs.
        #[test]
        fn lehmer_rationals_agree(
            a in proptest::collection::vec(proptest::num::u64::ANY, 0..4),
            b in proptest::collection::vec(proptest::num::u64::ANY, 1..4),
            c in proptest::collection::vec(proptest::num::u64::ANY, 0..4),
            d in proptest::collection::vec(proptest::num::u64::ANY, 1..4),
            g in proptest::collection::vec(proptest::num::u64::ANY, 0..2),
            signs in (proptest::bool::ANY, proptest::bool::ANY, proptest::bool::ANY),
        ) {
            let make = |v: &[u64]| -> BigInt {
                v.iter().fold(BigInt::zero(), |acc, &w| (acc << 64usize) + w)
            };
            let g = make(&g) + 1;
            let sg = |s: bool, x: BigInt| if s { -x } else { x };
            let (an, ad): (BigInt, BigInt) = (sg(signs.0, make(&a) * &g), sg(signs.1, (make(&b) + 1u32) * &g));
            let (cn, cd): (BigInt, BigInt) = (sg(signs.2, make(&c) * &g), (make(&d) + 1u32) * &g);
            let x = q_new(an.clone(), ad.clone());
            let y = q_new(cn.clone(), cd.clone());
            let (rx, ry) = (Q::new(an, ad), Q::new(cn, cd));
            let canon = |v: &Q, r: &Q| v.numer() == r.numer() && v.denom() == r.denom();
            proptest::prop_assert!(canon(&x, &rx) && canon(&y, &ry));
            proptest::prop_assert!(canon(&q_mul(&x, &y), &(&rx * &ry)));
            proptest::prop_assert!(canon(&q_add(&x, &y), &(&rx + &ry)));
            proptest::prop_assert!(canon(&q_add(&x, &-&x), &Q::zero()));
            proptest::prop_assert!(canon(&q_sub(&x, &y), &(&rx - &ry)));
        }

        /// The residue filter never rejects a square (of any size) and
        /// `exact_sqrt_z` agrees with the integer square root on
        /// non-squares next to squares.
        #[test]
        fn square_filter_keeps_squares(
            v in proptest::collection::vec(proptest::num::u64::ANY, 1..12),
            k in 0u64..1000,
        ) {
            let r = v.iter().fold(BigInt::zero(), |acc, &w| (acc << 64usize) + w) + k;
            let sq = &r * &r;
            proptest::prop_assert_eq!(exact_sqrt_z(&sq), Some(r.clone()));
            for x in [&sq + 1u32, &sq + &r + &r + 2u32, &sq + 3u32] {
                let root = x.sqrt();
                let want = (&root * &root == x).then_some(root);
                proptest::prop_assert_eq!(exact_sqrt_z(&x), want);
            }
        }

        /// `q_new`'s division shortcut on long operands (≥ 512 bits) where
        /// one divides the other, with every sign, and its miss (a common
        /// factor that is not the whole of either): num-rational's
        /// canonical values.
        #[test]
        fn long_divisible_rationals_agree(
            g in proptest::collection::vec(proptest::num::u64::ANY, 8..14),
            k in proptest::collection::vec(proptest::num::u64::ANY, 0..2),
            m in 2u64..1000,
            signs in (proptest::bool::ANY, proptest::bool::ANY),
        ) {
            let make = |v: &[u64]| -> BigInt {
                v.iter().fold(BigInt::zero(), |acc, &w| (acc << 64usize) + w)
            };
            let g: BigInt = make(&g) + 1;
            let k: BigInt = make(&k) + 1;
            let sg = |s: bool, x: BigInt| if s { -x } else { x };
            for (n, d) in [
                (&g * &k, g.clone()),
                (g.clone(), &g * &k),
                (g.clone(), g.clone()),
                (&g * m, &g * (m + 1)),
            ] {
                let (n, d) = (sg(signs.0, n), sg(signs.1, d));
                let (x, r) = (q_new(n.clone(), d.clone()), Q::new(n, d));
                proptest::prop_assert!(x.numer() == r.numer() && x.denom() == r.denom(), "{} vs {}", x, r);
            }
        }
    }

    /// The exact value of a printed decimal (`-1.25e-7`, `0.001`, `120`).
    fn parse_decimal(s: &str) -> Q {
        let (m, e) = s
            .split_once('e')
            .map_or((s, 0), |(m, e)| (m, e.parse::<i64>().unwrap()));
        let (neg, m) = m.strip_prefix('-').map_or((false, m), |m| (true, m));
        let (int, frac) = m.split_once('.').unwrap_or((m, ""));
        let digits: BigInt = format!("{int}{frac}").parse().unwrap();
        let e = e - frac.len() as i64;
        let p = num_traits::pow(BigInt::from(10), e.unsigned_abs() as usize);
        let v = if e >= 0 {
            Q::from_integer(digits * p)
        } else {
            Q::new(digits, p)
        };
        if neg { -v } else { v }
    }

    /// `⌊log10 |x|⌋` by comparison with powers of ten (the slow way).
    fn floor_log10(x: &Q) -> i64 {
        let ax = x.abs();
        let p = |e: i64| {
            let t = Q::from_integer(num_traits::pow(BigInt::from(10), e.unsigned_abs() as usize));
            if e >= 0 { t } else { t.recip() }
        };
        let mut e = 0;
        while p(e) > ax {
            e -= 1;
        }
        while p(e + 1) <= ax {
            e += 1;
        }
        e
    }

    proptest::proptest! {
        /// `approx_decimal_ratio` is |x| rounded half up to `digits`
        /// significant digits, with x's sign: the printed value r has at
        /// most `digits` significant digits and |x| ∈ [|r| − u/2, |r| + u/2)
        /// with u the unit of the last digit at |x|'s own magnitude (also
        /// near powers of ten, where rounding carries into a new digit).
        #[test]
        fn approx_decimal_is_rounded_half_up(
            a in proptest::collection::vec(proptest::num::u64::ANY, 0..4),
            b in proptest::collection::vec(proptest::num::u64::ANY, 0..4),
            near in 0usize..4,
            k in 0usize..40,
            neg in proptest::bool::ANY,
            digits in 1usize..26,
        ) {
            let make = |v: &[u64]| -> BigInt {
                v.iter().fold(BigInt::zero(), |acc, &w| (acc << 64usize) + w)
            };
            let ten_k = num_traits::pow(BigInt::from(10), k);
            let (n, d) = match near {
                // random
                0 => (make(&a) + 1u32, make(&b) + 1u32),
                // just below a power of ten: 0.999… and 9.99…·10^k
                1 => (&ten_k - 1u32, BigInt::from(10u32).pow(1 + k as u32 / 2)),
                // a power of ten times d, ± 1
                2 => { let d = make(&b) + 1u32; (&ten_k * &d - 1u32, d) }
                // an exact half at the rounding position
                _ => (&ten_k * 10u32 + 5u32, BigInt::from(10u32).pow(k as u32 % 7)),
            };
            proptest::prop_assume!(!n.is_zero());
            let n = if neg { -n } else { n };
            let s = approx_decimal_ratio(&n, &d, digits);
            let x = Q::new(n.clone(), d.clone());
            let r = parse_decimal(&s);
            proptest::prop_assert_eq!(r.is_negative(), x.is_negative(), "{}", s);
            let mant = s.trim_start_matches('-').split('e').next().unwrap().replace('.', "");
            let sig = mant.trim_start_matches('0').trim_end_matches('0').len();
            proptest::prop_assert!(sig <= digits, "{} has more than {} digits", s, digits);
            let e10 = floor_log10(&x);
            let e = e10 - digits as i64 + 1;
            let u = {
                let t = Q::from_integer(num_traits::pow(BigInt::from(10), e.unsigned_abs() as usize));
                if e >= 0 { t } else { t.recip() }
            };
            let half = &u / Q::from_integer(BigInt::from(2));
            let (ax, ar) = (x.abs(), r.abs());
            proptest::prop_assert!(&ar - &half <= ax && ax < &ar + &half, "{}/{} printed {}", n, d, s);
        }
    }

    #[test]
    fn floor_log2_is_exact() {
        assert_eq!(floor_log2_q(&q(1, 1)), 0);
        assert_eq!(floor_log2_q(&q(3, 1)), 1);
        assert_eq!(floor_log2_q(&q(4, 1)), 2);
        assert_eq!(floor_log2_q(&q(1, 3)), -2);
        assert_eq!(floor_log2_q(&q(1, 4)), -2);
        assert_eq!(floor_log2_q(&q(-7, 2)), 1);
    }

    #[test]
    fn sqrt_tests() {
        assert_eq!(exact_sqrt_q(&q(9, 4)), Some(q(3, 2)));
        assert_eq!(exact_sqrt_q(&q(2, 1)), None);
        assert_eq!(exact_sqrt_q(&q(-4, 1)), None);
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_q() {
        let q = crate::number::q(6, 4);
        assert_eq!(crate::number::fmt_q(&q), "3/2");
    }

    #[test]
    fn doc_approx_decimal() {
        use crate::number::{approx_decimal, q};
        assert_eq!(approx_decimal(&q(7, 9), 5), "0.77778");
        assert_eq!(approx_decimal(&q(-1233, 112), 6), "-11.0089");
    }
}
