//! Exact parsing of numbers: integers, rationals, decimals, scientific
//! decimals and hexadecimal floats, all to exact rationals (never through
//! `f64`).
//!
//! Literal grammar (one literal, no sign, no whitespace inside):
//!
//! ```text
//! decimal := D+ ('.' D+)? exp? | '.' D+ exp?        exp  := ('e'|'E') ('+'|'-')? D+
//! hex     := '0' ('x'|'X') hexdigits bexp?          bexp := ('p'|'P') ('+'|'-')? D+
//! hexdigits := H+ ('.' H*)? | '.' H+                (H: 0-9 a-f A-F; D: 0-9)
//! ```
//!
//! A hexadecimal literal (C99 / IEEE-754 `%a` syntax, e.g. `0x1.6a09e667f3bcdp-1`)
//! is `hexdigits × 2^exponent`, exactly; the binary exponent is written in
//! decimal and may be omitted (`0x10` is 16).  It starts at `0x` only when a
//! hex digit or `.` follows, so `0x` alone stays "0 times x" in polynomials,
//! and `0x1p3x` is `8·x`.  An `e` after decimal digits is an exponent only
//! when digits follow it (`2e` is 2 followed by `e`); inside a hex literal
//! `e` is a digit.
//!
//! In [`NumberMode::Float`] every literal is replaced by its nearest double
//! (round to nearest, ties to even): the way a program reading the same text
//! into `f64` sees it.  Each literal is rounded on its own, so `1/3` stays
//! the exact quotient of the doubles 1 and 3.

use super::Q;
use num_bigint::BigInt;
use num_traits::{Num, Zero};
use std::fmt;

/// Longest run of digits accepted in one literal (a documented size limit:
/// longer literals are rejected instead of making the parser slow).
pub const MAX_DIGITS: usize = 100_000;
/// Largest decimal exponent accepted in scientific notation (`1e100000`).
pub const MAX_EXPONENT: i64 = 100_000;
/// Largest bit size of the numerator or denominator of a hexadecimal
/// literal (about 99 000 decimal digits, so it prints within [`MAX_DIGITS`]).
pub const MAX_HEX_BITS: i64 = 330_000;

/// How number literals are read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum NumberMode {
    /// Every literal is the exact number it denotes (the default).
    #[default]
    Exact,
    /// Every literal is replaced by the double nearest to it (ties to
    /// even), as a program reading the text into `f64` would see it.
    Float,
}

/// A number that could not be read: what went wrong and at which column
/// (1-based, counted in characters of the input).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NumberError {
    /// Human-readable description of the problem.
    pub message: String,
    /// 1-based column of the offending character.
    pub column: usize,
}

impl fmt::Display for NumberError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at column {}", self.message, self.column)
    }
}

impl std::error::Error for NumberError {}

fn err(message: impl Into<String>, pos: usize) -> NumberError {
    NumberError {
        message: message.into(),
        column: pos + 1,
    }
}

fn digits_to_int(d: &[u8]) -> BigInt {
    if d.is_empty() {
        return BigInt::zero();
    }
    if d.len() <= 19 {
        // fits in a u64 (the bytes are ASCII digits): no string conversion
        return BigInt::from(d.iter().fold(0u64, |v, &c| v * 10 + u64::from(c - b'0')));
    }
    // the bytes are ASCII digits, checked by the caller
    let s = std::str::from_utf8(d).unwrap_or("0");
    BigInt::from_str_radix(s, 10).unwrap_or_default()
}

/// Reads one unsigned number literal starting at byte `pos` of `s`
/// (grammar in the module docs: decimal, scientific or hexadecimal).
/// Returns the exact value and the byte position just after the literal.
///
/// An `e` is taken as an exponent only when digits follow it (with an
/// optional sign), so `2e` is the number 2 followed by `e`.
#[cfg(test)]
pub fn scan_number(s: &[u8], pos: usize) -> Result<(Q, usize), NumberError> {
    scan_number_with(s, pos, NumberMode::Exact)
}

/// [`scan_number`] in the given [`NumberMode`]: in float mode the literal's
/// value is rounded to the nearest double (an error if it is out of the
/// double range).
pub fn scan_number_with(s: &[u8], pos: usize, mode: NumberMode) -> Result<(Q, usize), NumberError> {
    let (v, end) = if starts_hex(s, pos) {
        scan_hex(s, pos)?
    } else {
        scan_decimal(s, pos)?
    };
    match mode {
        NumberMode::Exact => Ok((v, end)),
        NumberMode::Float => match super::float::round_to_double(&v) {
            Some(d) => Ok((d, end)),
            None => Err(err(
                "number is out of the double range (magnitude 2^1024 or more)",
                pos,
            )),
        },
    }
}

/// `0x` or `0X` followed by a hex digit or `.`.
fn starts_hex(s: &[u8], pos: usize) -> bool {
    s.len() > pos + 2
        && s[pos] == b'0'
        && (s[pos + 1] == b'x' || s[pos + 1] == b'X')
        && (s[pos + 2].is_ascii_hexdigit() || s[pos + 2] == b'.')
}

/// The end of the run of digits (by `is_digit`) starting at `i`.
fn digit_run(s: &[u8], mut i: usize, is_digit: fn(&u8) -> bool) -> usize {
    while i < s.len() && is_digit(&s[i]) {
        i += 1;
    }
    i
}

/// The integer digits, the point's position with the fraction digits
/// (when there is a point), and the end of a mantissa.
type Mantissa<'a> = (&'a [u8], Option<(usize, &'a [u8])>, usize);

/// `digits [. digits]` from `i`.
fn mantissa(s: &[u8], i: usize, is_digit: fn(&u8) -> bool) -> Mantissa<'_> {
    let e = digit_run(s, i, is_digit);
    if e < s.len() && s[e] == b'.' {
        let f = digit_run(s, e + 1, is_digit);
        return (&s[i..e], Some((e, &s[e + 1..f])), f);
    }
    (&s[i..e], None, e)
}

/// After an exponent letter at `i`: the sign, and the decimal digits'
/// start and end.
fn exponent_digits(s: &[u8], i: usize) -> (bool, usize, usize) {
    let mut j = i + 1;
    let neg = j < s.len() && s[j] == b'-';
    if j < s.len() && (s[j] == b'+' || s[j] == b'-') {
        j += 1;
    }
    (neg, j, digit_run(s, j, u8::is_ascii_digit))
}

/// The value of a run of decimal digits, `None` beyond `limit`.
fn small_value(d: &[u8], limit: i64) -> Option<i64> {
    if d.len() > 9 {
        return None;
    }
    std::str::from_utf8(d)
        .ok()
        .and_then(|t| t.parse().ok())
        .filter(|v| *v <= limit)
}

/// A hexadecimal literal at `pos` (which starts with `0x` and a hex digit
/// or `.`): exactly `hexdigits × 2^exponent`.
fn scan_hex(s: &[u8], pos: usize) -> Result<(Q, usize), NumberError> {
    let (int_part, frac, mut i) = mantissa(s, pos + 2, u8::is_ascii_hexdigit);
    let frac_part = frac.map_or(&[][..], |f| f.1);
    if let Some((dot, _)) = frac
        && int_part.is_empty()
        && frac_part.is_empty()
    {
        return Err(err(
            "a hexadecimal number needs at least one hex digit",
            dot,
        ));
    }
    let ndig = (int_part.len() + frac_part.len()) as i64;
    let mut exp: i64 = 0;
    if i < s.len() && (s[i] == b'p' || s[i] == b'P') {
        let (neg, es, j) = exponent_digits(s, i);
        if j == es {
            return Err(err(
                "the binary exponent 'p' of a hexadecimal number must be followed by decimal digits",
                j,
            ));
        }
        let v = small_value(&s[es..j], MAX_HEX_BITS).ok_or_else(|| {
            err(
                format!("binary exponent too large (limit {MAX_HEX_BITS})"),
                es,
            )
        })?;
        exp = if neg { -v } else { v };
        i = j;
    }
    if i < s.len() && (s[i] == b'.' || s[i].is_ascii_alphanumeric() && s[i] != b'x') {
        // e.g. "0x1.8.5", "0x1g": a hex literal cannot run into more
        // digits or letters (a variable after it must be x, y, z or u:
        // those are not hex digits, and x is allowed for "0x1p3x")
        if !matches!(s[i], b'y' | b'z' | b'u') {
            let c = s[i] as char;
            return Err(err(format!("unexpected '{c}' in a hexadecimal number"), i));
        }
    }
    // value = digits · 2^(exp − 4·frac_len); the exact value must print
    // within the digit limit
    let e_total = exp - 4 * frac_part.len() as i64;
    if 4 * ndig + e_total.max(0) > MAX_HEX_BITS || -e_total > MAX_HEX_BITS {
        return Err(err(
            format!("hexadecimal number has more than {MAX_HEX_BITS} bits (size limit)"),
            pos,
        ));
    }
    let mut all = Vec::with_capacity(ndig as usize);
    all.extend_from_slice(int_part);
    all.extend_from_slice(frac_part);
    let mantissa = if all.is_empty() {
        BigInt::zero()
    } else {
        BigInt::from_str_radix(std::str::from_utf8(&all).unwrap_or("0"), 16).unwrap_or_default()
    };
    let value = if e_total >= 0 {
        Q::from_integer(mantissa << (e_total as usize))
    } else {
        super::dyadic(mantissa, (-e_total) as usize)
    };
    Ok((value, i))
}

/// A decimal literal at `pos`.
fn scan_decimal(s: &[u8], pos: usize) -> Result<(Q, usize), NumberError> {
    let (int_part, frac, i) = mantissa(s, pos, u8::is_ascii_digit);
    let frac_part = frac.map_or(&[][..], |f| f.1);
    if let Some((dot, _)) = frac {
        if int_part.is_empty() && frac_part.is_empty() {
            return Err(err("a lone '.' is not a number", dot));
        }
        if frac_part.is_empty() {
            return Err(err("a decimal point must be followed by digits", dot));
        }
    }
    let mut i = i;
    if int_part.is_empty() && frac_part.is_empty() {
        return Err(err("expected a number", pos));
    }
    if int_part.len() + frac_part.len() > MAX_DIGITS {
        return Err(err(
            format!("number literal has more than {MAX_DIGITS} digits (size limit)"),
            pos,
        ));
    }
    let mut exp: i64 = 0;
    if i < s.len() && (s[i] == b'e' || s[i] == b'E') {
        let (neg, es, j) = exponent_digits(s, i);
        if j > es {
            let v = small_value(&s[es..j], MAX_EXPONENT)
                .ok_or_else(|| err(format!("exponent too large (limit {MAX_EXPONENT})"), es))?;
            exp = if neg { -v } else { v };
            i = j;
        } else if es > i + 1 {
            // "1e+" or "1e-" without digits
            return Err(err("exponent sign must be followed by digits", j));
        }
    }
    // the exact value must print within MAX_DIGITS digits (numerator and
    // denominator), so that every printed number parses back
    let e_total = exp - frac_part.len() as i64;
    let mant_digits = int_part.len() + frac_part.len();
    if (e_total >= 0 && mant_digits as i64 + e_total > MAX_DIGITS as i64)
        || (e_total < 0 && -e_total > MAX_DIGITS as i64)
    {
        return Err(err(
            format!("number has more than {MAX_DIGITS} digits (size limit)"),
            pos,
        ));
    }
    let mut all = Vec::with_capacity(int_part.len() + frac_part.len());
    all.extend_from_slice(int_part);
    all.extend_from_slice(frac_part);
    let mantissa = digits_to_int(&all);
    let e = exp - frac_part.len() as i64;
    let ten = BigInt::from(10);
    let value = if e == 0 {
        Q::from_integer(mantissa)
    } else if e > 0 {
        Q::from_integer(mantissa * num_traits::pow(ten, e as usize))
    } else {
        reduce_by_power_of_ten(mantissa, (-e) as usize)
    };
    Ok((value, i))
}

/// `m / 10^k` in lowest terms (`m ≥ 0`).  The common factor is
/// `2^a·5^b`: the twos from the trailing zero bits, the fives by word-size
/// divisions (5^13, then 5), at most k of each — no gcd (num-rational's
/// `Q::new` would use num-bigint's binary gcd, quadratic in the bits of
/// `10^k` even for a small `m`).
fn reduce_by_power_of_ten(m: BigInt, k: usize) -> Q {
    if m.is_zero() {
        return Q::zero();
    }
    let twos = (m.trailing_zeros().unwrap_or(0) as usize).min(k);
    let mut m = m >> twos;
    let mut fives = 0;
    const P13: u32 = 1_220_703_125; // 5^13
    while fives + 13 <= k && (&m % P13).is_zero() {
        m /= P13;
        fives += 13;
    }
    while fives < k && (&m % 5u32).is_zero() {
        m /= 5u32;
        fives += 1;
    }
    // what is left of 2^k (5^k) is coprime to m: all twos (fives) of m
    // were removed unless 2^k (5^k) was used up
    Q::new_raw(m, num_traits::pow(BigInt::from(5), k - fives) << (k - twos))
}

/// Parses a complete exact number: an optional sign, a literal (integer,
/// decimal or scientific) and optionally `/` and a second literal.
pub fn parse_rational(text: &str) -> Result<Q, NumberError> {
    parse_rational_with(text, NumberMode::Exact)
}

/// [`parse_rational`] in the given [`NumberMode`] (in float mode each
/// literal — numerator and denominator — is first rounded to its nearest
/// double).
pub fn parse_rational_with(text: &str, mode: NumberMode) -> Result<Q, NumberError> {
    let s = text.as_bytes();
    let mut i = 0;
    while i < s.len() && s[i].is_ascii_whitespace() {
        i += 1;
    }
    if i == s.len() {
        return Err(err("expected a number, found nothing", i));
    }
    let mut neg = false;
    if s[i] == b'+' || s[i] == b'-' {
        neg = s[i] == b'-';
        i += 1;
    }
    if i < s.len() && !(s[i].is_ascii_digit() || s[i] == b'.') {
        return Err(err(
            format!("unexpected '{}' in a number", char_at(text, i)),
            i,
        ));
    }
    let (mut v, mut j) = scan_number_with(s, i, mode)?;
    while j < s.len() && s[j].is_ascii_whitespace() {
        j += 1;
    }
    if j < s.len() && s[j] == b'/' {
        let mut k = j + 1;
        while k < s.len() && s[k].is_ascii_whitespace() {
            k += 1;
        }
        if k < s.len() && !(s[k].is_ascii_digit() || s[k] == b'.') {
            return Err(err("expected a denominator after '/'", k));
        }
        let (d, k2) = scan_number_with(s, k, mode)?;
        if d.is_zero() {
            return Err(err("division by zero", k));
        }
        v /= d;
        j = k2;
        while j < s.len() && s[j].is_ascii_whitespace() {
            j += 1;
        }
    }
    if j < s.len() {
        return Err(err(
            format!("unexpected '{}' after the number", char_at(text, j)),
            j,
        ));
    }
    Ok(if neg { -v } else { v })
}

fn char_at(text: &str, byte: usize) -> char {
    text.get(byte..)
        .and_then(|t| t.chars().next())
        .unwrap_or('?')
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;
    use num_traits::One;

    #[test]
    fn literals() {
        assert_eq!(parse_rational("12").unwrap(), q(12, 1));
        assert_eq!(parse_rational(" -12 ").unwrap(), q(-12, 1));
        assert_eq!(parse_rational(".5").unwrap(), q(1, 2));
        assert_eq!(parse_rational("1e3").unwrap(), q(1000, 1));
        assert_eq!(parse_rational("1.5e-1").unwrap(), q(3, 20));
        assert_eq!(parse_rational("3/6").unwrap(), q(1, 2));
        assert_eq!(parse_rational("0.1/0.3").unwrap(), q(1, 3));
    }

    /// `x` in the C99 `%a` form (`0x1.<13 hex digits>p<exp>`, subnormals
    /// `0x0.<…>p-1022`).
    fn hex_of(x: f64) -> String {
        let bits = x.to_bits();
        let sign = if bits >> 63 == 1 { "-" } else { "" };
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        if exp == 0 {
            format!("{sign}0x0.{frac:013x}p-1022")
        } else {
            format!("{sign}0x1.{frac:013x}p{}", exp - 1023)
        }
    }

    #[test]
    fn hex_floats() {
        assert_eq!(parse_rational("0x1p-3").unwrap(), q(1, 8));
        assert_eq!(parse_rational("-0x1p-3").unwrap(), q(-1, 8));
        assert_eq!(parse_rational("0X1.8P1").unwrap(), q(3, 1));
        assert_eq!(parse_rational("0x.8").unwrap(), q(1, 2));
        assert_eq!(parse_rational("0x10").unwrap(), q(16, 1));
        assert_eq!(parse_rational("0x1.").unwrap(), q(1, 1));
        assert_eq!(parse_rational("0xa.8p+2").unwrap(), q(42, 1));
        assert_eq!(parse_rational("0x1p3/0x1p1").unwrap(), q(4, 1));
        assert_eq!(
            parse_rational("0x1.6a09e667f3bcdp-1").unwrap(),
            crate::number::double_value(std::f64::consts::FRAC_1_SQRT_2).unwrap()
        );
        // scan_number leaves what follows a hex literal to the caller
        assert_eq!(scan_number(b"0x1p3x", 0).unwrap(), (q(8, 1), 5));
        assert_eq!(scan_number(b"0xay", 0).unwrap(), (q(10, 1), 3));
        // "0x" without a hex digit or '.' after it is the number 0
        assert_eq!(scan_number(b"0x^2", 0).unwrap(), (q(0, 1), 1));
        assert_eq!(scan_number(b"0xy", 0).unwrap(), (q(0, 1), 1));
    }

    #[test]
    fn malformed_hex_floats_name_the_problem_and_column() {
        for (text, msg, col) in [
            (
                "0x.p1",
                "a hexadecimal number needs at least one hex digit",
                3,
            ),
            (
                "0x1p",
                "the binary exponent 'p' of a hexadecimal number must be followed by decimal digits",
                5,
            ),
            (
                "0x1p+",
                "the binary exponent 'p' of a hexadecimal number must be followed by decimal digits",
                6,
            ),
            ("0x1.8.5", "unexpected '.' in a hexadecimal number", 6),
            ("0x1g", "unexpected 'g' in a hexadecimal number", 4),
            ("0x1p3e4", "unexpected 'e' in a hexadecimal number", 6),
            (
                "0x1p999999999",
                "binary exponent too large (limit 330000)",
                5,
            ),
            (
                "  -0x1p",
                "the binary exponent 'p' of a hexadecimal number must be followed by decimal digits",
                8,
            ),
        ] {
            let e = parse_rational(text).unwrap_err();
            assert_eq!((e.message.as_str(), e.column), (msg, col), "{text:?}");
        }
    }

    #[test]
    fn float_mode_rounds_each_literal_to_the_nearest_double() {
        let f = |t: &str| parse_rational_with(t, NumberMode::Float).unwrap();
        let d = |x: f64| crate::number::double_value(x).unwrap();
        assert_eq!(f("0.1"), d(0.1));
        assert_eq!(f("0.7071067811865476"), d(std::f64::consts::FRAC_1_SQRT_2));
        // halfway between 1 and 1 + 2^-52: ties to even (1)
        assert_eq!(
            f("1.00000000000000011102230246251565404236316680908203125"),
            q(1, 1)
        );
        // halfway between 1 + 2^-52 and 1 + 2^-51: ties to even (1 + 2^-51)
        assert_eq!(
            f("1.00000000000000033306690738754696212708950042724609375"),
            d(1.0 + 2f64.powi(-51))
        );
        // each literal on its own: 1/3 is the quotient of the doubles 1 and 3
        assert_eq!(f("1/3"), q(1, 3));
        assert_eq!(f("0.1/0.3"), d(0.1) / d(0.3));
        // hex literals with more than 53 bits are rounded too
        assert_eq!(f("0x1.00000000000008p0"), q(1, 1));
        let e = parse_rational_with("1e400", NumberMode::Float).unwrap_err();
        assert_eq!(e.column, 1);
        assert!(e.message.contains("out of the double range"));
        assert_eq!(f("1e-400"), q(0, 1));
    }

    proptest::proptest! {
        /// A random double written as a hex float parses to its exact value.
        #[test]
        fn hex_round_trips(bits in proptest::num::u64::ANY) {
            let x = f64::from_bits(bits);
            if x.is_finite() {
                let t = hex_of(x);
                proptest::prop_assert_eq!(parse_rational(&t).unwrap(), crate::number::double_value(x).unwrap(), "{}", t);
                proptest::prop_assert_eq!(parse_rational_with(&t, NumberMode::Float).unwrap(), crate::number::double_value(x).unwrap());
            }
        }

        /// `m/10^k` reduced through its twos and fives is num-rational's
        /// canonical value: mantissas with and without the factor 5^k
        /// (every double's full decimal expansion has it), zeros, and
        /// finite doubles written out in full decimal.
        #[test]
        fn powers_of_ten_reduce_canonically(
            w in proptest::collection::vec(proptest::num::u64::ANY, 0..4),
            k in 0usize..60,
            a in 0usize..70,
            b in 0usize..70,
            bits in proptest::num::u64::ANY,
        ) {
            let m = w.iter().fold(BigInt::zero(), |acc, &x| (acc << 64usize) + x);
            let m = (m << a) * num_traits::pow(BigInt::from(5), b);
            let want = Q::new(m.clone(), num_traits::pow(BigInt::from(10), k));
            let got = reduce_by_power_of_ten(m, k);
            proptest::prop_assert!(got.numer() == want.numer() && got.denom() == want.denom(), "{} vs {}", got, want);
            // a dyadic n/2^j (a double's kind of value) in full decimal:
            // the digits of n·5^j with the point j places from the right
            let (n, j) = (BigInt::from(bits >> 11), a);
            let digits = format!("{:0>width$}", (&n * num_traits::pow(BigInt::from(5), j)).to_string(), width = j + 1);
            let text = format!("{}.{}", &digits[..digits.len() - j], &digits[digits.len() - j..]);
            let text = text.trim_end_matches('.');
            let exact = Q::new(n, BigInt::one() << j);
            proptest::prop_assert_eq!(parse_rational(text).unwrap(), exact, "{}", text);
        }
    }

    #[test]
    fn bad_literals() {
        for bad in [
            "", "-", "1.", "abc", "1/", "1/x", "1e", "1e-", "2 3", "1/0.0", "--1",
        ] {
            assert!(parse_rational(bad).is_err(), "{bad:?} should fail");
        }
        assert_eq!(parse_rational("1e").unwrap_err().column, 2);
        assert!(parse_rational("1e9999999").is_err());
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_parse_rational() {
        use crate::number::{parse_rational, q};
        assert_eq!(parse_rational("-7/9").unwrap(), q(-7, 9));
        assert_eq!(
            parse_rational("1.77777777777").unwrap(),
            q(177777777777, 100000000000)
        );
        assert_eq!(parse_rational("2.5E3").unwrap(), q(2500, 1));
        assert_eq!(parse_rational("1e-2").unwrap(), q(1, 100));
        assert!(parse_rational("1/0").is_err());
    }
}

#[cfg(test)]
mod doc_examples_more {
    //! Examples that were doc comments of crate-private items.

    #[test]
    fn doc_parse_rational_with() {
        use crate::number::{NumberMode, double_value, parse_rational_with};
        let x = parse_rational_with("0.1", NumberMode::Float).unwrap();
        assert_eq!(x, double_value(0.1).unwrap());
        let h = parse_rational_with("-0x1.8p-3", NumberMode::Exact).unwrap();
        assert_eq!(h, crate::number::q(-3, 16));
    }
}
