//! The polynomial expression parser (contract §1).
//!
//! Grammar (whitespace is free):
//!
//! ```text
//! expr    := term (('+' | '-') term)*
//! term    := unary (('*' | '/') unary | implicit)*
//! implicit:= a variable or '(' directly after a factor: 2x, 3(x-1), (x+1)(x-1), x y
//! unary   := ('+' | '-') unary | power
//! power   := primary ('^' integer-literal)?
//! primary := number | 'x' | 'y' | 'z' | 'u' | '(' expr ')'
//! ```
//!
//! Numbers are exact (integers, decimals, scientific).  `/` divides only by
//! a non-zero constant; `^` takes a non-negative integer literal.  Every
//! error names the problem and the 1-based column.  Documented size limits
//! keep hostile inputs from hanging: see [`Limits`].

use super::mpoly::{MPoly, NVARS, QMPoly};
use crate::number::{NumberMode, Q, scan_number_with};
use num_traits::{One, Zero};
use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::fmt;

/// Size limits of the parser.  Inputs beyond them are rejected with a clear
/// error instead of exhausting time or memory.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Longest accepted expression, in bytes.
    pub max_input_bytes: usize,
    /// Deepest bracket / unary-sign nesting.
    pub max_depth: usize,
    /// Largest total degree of any intermediate polynomial.
    pub max_degree: u32,
    /// Most terms in any intermediate polynomial.
    pub max_terms: usize,
    /// Largest number of term products in one multiplication.
    pub max_work: usize,
    /// Largest bit size of a coefficient produced by `^` on a constant.
    pub max_coeff_bits: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_input_bytes: 1 << 20,
            max_depth: 100,
            max_degree: 10_000,
            max_terms: 200_000,
            max_work: 20_000_000,
            // below the 100 000-digit literal limit, so that every printed
            // polynomial parses back
            max_coeff_bits: 330_000,
        }
    }
}

/// A parse error: the problem and the 1-based column where it was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// What is wrong.
    pub message: String,
    /// 1-based column (in characters).
    pub column: usize,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at column {}", self.message, self.column)
    }
}

impl std::error::Error for ParseError {}

/// Parses a polynomial expression with the default [`Limits`].
pub fn parse_poly(text: &str) -> Result<QMPoly, ParseError> {
    parse_poly_with(text, &Limits::default())
}

/// Parses a polynomial expression with explicit limits.
pub fn parse_poly_with(text: &str, limits: &Limits) -> Result<QMPoly, ParseError> {
    parse_poly_in(text, limits, NumberMode::Exact)
}

/// Parses a polynomial expression with explicit limits, reading every
/// number literal in the given [`NumberMode`] (float mode: each literal
/// becomes its nearest double).
pub fn parse_poly_in(text: &str, limits: &Limits, mode: NumberMode) -> Result<QMPoly, ParseError> {
    if text.len() > limits.max_input_bytes {
        return Err(ParseError {
            message: format!(
                "expression is {} bytes long; the limit is {} bytes",
                text.len(),
                limits.max_input_bytes
            ),
            column: 1,
        });
    }
    let mut p = Parser {
        text,
        s: text.as_bytes(),
        pos: 0,
        depth: 0,
        limits,
        mode,
    };
    p.skip_ws();
    if p.pos == p.s.len() {
        return Err(p.err_at("empty expression", 0));
    }
    let v = p.expr()?;
    p.check_size(&v, 0)?;
    p.skip_ws();
    if p.pos < p.s.len() {
        let c = p.current_char();
        return Err(p.err_at(&format!("unexpected '{c}'"), p.pos));
    }
    Ok(v)
}

struct Parser<'a> {
    text: &'a str,
    s: &'a [u8],
    pos: usize,
    depth: usize,
    limits: &'a Limits,
    mode: NumberMode,
}

fn variable(c: u8) -> Option<usize> {
    match c {
        b'x' => Some(0),
        b'y' => Some(1),
        b'z' => Some(2),
        b'u' => Some(3),
        _ => None,
    }
}

impl Parser<'_> {
    fn err_at(&self, msg: &str, byte: usize) -> ParseError {
        let byte = byte.min(self.text.len());
        let mut b = byte;
        while !self.text.is_char_boundary(b) {
            b -= 1;
        }
        ParseError {
            message: msg.to_string(),
            column: self.text[..b].chars().count() + 1,
        }
    }

    fn current_char(&self) -> char {
        let mut b = self.pos;
        while !self.text.is_char_boundary(b) {
            b -= 1;
        }
        self.text[b..].chars().next().unwrap_or('?')
    }

    fn skip_ws(&mut self) {
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_ws();
        self.s.get(self.pos).copied()
    }

    fn enter(&mut self) -> Result<(), ParseError> {
        self.depth += 1;
        if self.depth > self.limits.max_depth {
            return Err(self.err_at(
                &format!(
                    "expression nested too deeply (limit {} levels)",
                    self.limits.max_depth
                ),
                self.pos,
            ));
        }
        Ok(())
    }

    fn check_size(&self, p: &QMPoly, at: usize) -> Result<(), ParseError> {
        let bits = p
            .terms()
            .iter()
            .map(|(_, c)| c.numer().bits().max(c.denom().bits()))
            .max()
            .unwrap_or(0);
        self.check_counts(p.len(), bits, at)
    }

    /// The size limits on a polynomial of `terms` terms whose largest
    /// numerator or denominator has `bits` bits.
    fn check_counts(&self, terms: usize, bits: u64, at: usize) -> Result<(), ParseError> {
        if terms > self.limits.max_terms {
            return Err(self.err_at(
                &format!(
                    "expression too large: more than {} terms",
                    self.limits.max_terms
                ),
                at,
            ));
        }
        if bits > self.limits.max_coeff_bits {
            return Err(self.err_at(
                &format!(
                    "a coefficient has more than {} bits (size limit)",
                    self.limits.max_coeff_bits
                ),
                at,
            ));
        }
        Ok(())
    }

    fn multiply(&self, a: &QMPoly, b: &QMPoly, at: usize) -> Result<QMPoly, ParseError> {
        if a.len().saturating_mul(b.len()) > self.limits.max_work {
            return Err(self.err_at(
                &format!(
                    "expression too large: a product of {} by {} terms (limit {} term products)",
                    a.len(),
                    b.len(),
                    self.limits.max_work
                ),
                at,
            ));
        }
        let da = a.total_degree().unwrap_or(0);
        let db = b.total_degree().unwrap_or(0);
        if da + db > self.limits.max_degree {
            return Err(self.err_at(
                &format!(
                    "degree {} exceeds the limit {}",
                    da + db,
                    self.limits.max_degree
                ),
                at,
            ));
        }
        let r = a * b;
        self.check_size(&r, at)?;
        Ok(r)
    }

    fn expr(&mut self) -> Result<QMPoly, ParseError> {
        let mut acc = self.term()?;
        // a long sum is accumulated by monomial, so that its cost is linear
        // in the input (repeated merges would be quadratic); a short one
        // by merging, which is cheaper for a few terms
        let mut long: Option<Sum> = None;
        loop {
            let negate = match self.peek() {
                Some(b'+') => false,
                Some(b'-') => true,
                _ => break,
            };
            self.pos += 1;
            let t = self.term()?;
            let Some(sum) = long.as_mut() else {
                acc = if negate { &acc - &t } else { &acc + &t };
                self.check_size(&acc, self.pos)?;
                if acc.len() > SHORT_SUM {
                    let mut sum = Sum::default();
                    sum.add(&std::mem::replace(&mut acc, MPoly::zero()), false);
                    long = Some(sum);
                }
                continue;
            };
            crate::budget::check_for(sum.bits);
            sum.add(&t, negate);
            self.check_counts(sum.terms.len(), sum.bits, self.pos)?;
        }
        Ok(match long {
            Some(sum) => MPoly::from_terms(sum.terms),
            None => acc,
        })
    }

    fn term(&mut self) -> Result<QMPoly, ParseError> {
        let mut acc = self.unary()?;
        loop {
            crate::budget::check();
            match self.peek() {
                Some(b'*') => {
                    let at = self.pos;
                    self.pos += 1;
                    let f = self.unary()?;
                    acc = self.multiply(&acc, &f, at)?;
                }
                Some(b'/') => {
                    let at = self.pos;
                    self.pos += 1;
                    let f = self.unary()?;
                    if !f.is_constant() {
                        return Err(self.err_at(
                            "division by a non-constant expression ('/' divides only by a number)",
                            at,
                        ));
                    }
                    let c = f.constant_term();
                    if c.is_zero() {
                        return Err(self.err_at("division by zero", at));
                    }
                    // the reciprocal of a fraction in lowest terms needs no gcd
                    let inv = c.recip();
                    acc = acc.scale(&inv);
                    self.check_size(&acc, at)?;
                }
                Some(c) if variable(c).is_some() || c == b'(' => {
                    let at = self.pos;
                    let f = self.power()?;
                    acc = self.multiply(&acc, &f, at)?;
                }
                Some(c) if c.is_ascii_digit() || c == b'.' => {
                    return Err(self.err_at(
                        "a number cannot follow a factor without an operator (write '*')",
                        self.pos,
                    ));
                }
                Some(c) if c.is_ascii_alphabetic() => {
                    let ch = self.current_char();
                    return Err(self.err_at(
                        &format!("unknown variable '{ch}' (variables are x, y, z, u)"),
                        self.pos,
                    ));
                }
                _ => return Ok(acc),
            }
        }
    }

    fn unary(&mut self) -> Result<QMPoly, ParseError> {
        match self.peek() {
            Some(b'-') => {
                self.pos += 1;
                self.enter()?;
                let v = self.unary()?;
                self.depth -= 1;
                Ok(-v)
            }
            Some(b'+') => {
                self.pos += 1;
                self.enter()?;
                let v = self.unary()?;
                self.depth -= 1;
                Ok(v)
            }
            _ => self.power(),
        }
    }

    fn power(&mut self) -> Result<QMPoly, ParseError> {
        let base = self.primary()?;
        if self.peek() != Some(b'^') {
            return Ok(base);
        }
        let caret = self.pos;
        self.pos += 1;
        self.skip_ws();
        let start = self.pos;
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_digit() {
            self.pos += 1;
        }
        if start == self.pos {
            let what = if self.pos < self.s.len() {
                format!("'{}'", self.current_char())
            } else {
                "the end of the expression".to_string()
            };
            return Err(self.err_at(
                &format!("exponent must be a non-negative integer literal, found {what}"),
                start,
            ));
        }
        if self.pos < self.s.len()
            && (self.s[self.pos] == b'.' || self.s[self.pos] == b'e' || self.s[self.pos] == b'E')
            && self.s.get(self.pos + 1).is_some_and(|c| c.is_ascii_digit())
        {
            return Err(self.err_at("exponent must be a non-negative integer literal", start));
        }
        let digits = &self.text[start..self.pos];
        let e: u64 = if digits.len() > 12 {
            u64::MAX
        } else {
            digits.parse().unwrap_or(u64::MAX)
        };
        if base.is_constant() {
            let c = base.constant_term();
            if c.is_zero() || c.is_one() || c == -Q::one() {
                let v = if e == 0 {
                    Q::one()
                } else if c.is_zero() {
                    Q::zero()
                } else if c.is_one() || e.is_multiple_of(2) {
                    Q::one()
                } else {
                    -Q::one()
                };
                return Ok(MPoly::constant(v));
            }
            let bits = c.numer().bits().max(c.denom().bits());
            if (bits as u128) * (e as u128) > self.limits.max_coeff_bits as u128 {
                return Err(self.err_at(
                    &format!(
                        "exponent {digits} makes a number of more than {} bits (size limit)",
                        self.limits.max_coeff_bits
                    ),
                    caret,
                ));
            }
            // numerator and denominator separately: they stay coprime, so
            // no gcd (num-rational's `pow` reduces every square with
            // num-bigint's binary gcd, quadratic in the bits even against 1:
            // `(2-488)^22384` took 2.7 s under the fuzzer's sanitizer)
            let (n, d) = (c.numer().pow(e as u32), c.denom().pow(e as u32));
            return Ok(MPoly::constant(Q::new_raw(n, d)));
        }
        let d = base.total_degree().unwrap_or(0) as u128;
        if d * (e as u128) > self.limits.max_degree as u128 {
            return Err(self.err_at(
                &format!(
                    "exponent {digits} gives degree {} above the limit {}",
                    d * e as u128,
                    self.limits.max_degree
                ),
                caret,
            ));
        }
        // repeated squaring with the size checks of `multiply`
        let mut r = MPoly::constant(Q::one());
        let mut b = base;
        let mut k = e;
        while k > 0 {
            if k & 1 == 1 {
                r = self.multiply(&r, &b, caret)?;
            }
            k >>= 1;
            if k > 0 {
                b = self.multiply(&b, &b, caret)?;
            }
        }
        Ok(r)
    }

    fn primary(&mut self) -> Result<QMPoly, ParseError> {
        let Some(c) = self.peek() else {
            return Err(self.err_at("unexpected end of expression", self.pos));
        };
        if c.is_ascii_digit() || c == b'.' {
            let (v, end) =
                scan_number_with(self.s, self.pos, self.mode).map_err(|e| ParseError {
                    message: e.message,
                    column: self.err_at("", e.column - 1).column,
                })?;
            self.pos = end;
            return Ok(MPoly::constant(v));
        }
        if let Some(v) = variable(c) {
            self.pos += 1;
            return Ok(MPoly::var(v));
        }
        if c == b'(' {
            let open = self.pos;
            self.pos += 1;
            self.enter()?;
            let v = self.expr()?;
            self.depth -= 1;
            if self.peek() != Some(b')') {
                if self.pos >= self.s.len() {
                    return Err(self.err_at("unclosed '(' (opened here)", open));
                }
                let ch = self.current_char();
                return Err(self.err_at(&format!("expected ')' but found '{ch}'"), self.pos));
            }
            self.pos += 1;
            return Ok(v);
        }
        if c.is_ascii_alphabetic() {
            let ch = self.current_char();
            return Err(self.err_at(
                &format!("unknown variable '{ch}' (variables are x, y, z, u)"),
                self.pos,
            ));
        }
        let ch = self.current_char();
        Err(self.err_at(&format!("unexpected '{ch}'"), self.pos))
    }
}

/// Sums of more terms than this are accumulated by monomial ([`Sum`]).
const SHORT_SUM: usize = 64;

/// The running value of a long sum in [`Parser::expr`]: its non-zero terms by
/// monomial, and the largest coefficient size (bits of the numerator or
/// the denominator) among the coefficients changed so far.
#[derive(Default)]
struct Sum {
    terms: HashMap<[u32; NVARS], Q>,
    bits: u64,
}

impl Sum {
    fn add(&mut self, p: &QMPoly, negate: bool) {
        for (e, c) in p.terms() {
            let c = if negate { -c } else { c.clone() };
            let v = match self.terms.entry(*e) {
                Entry::Occupied(mut o) => {
                    *o.get_mut() += c;
                    if o.get().is_zero() {
                        o.remove();
                        continue;
                    }
                    o.into_mut()
                }
                Entry::Vacant(v) => v.insert(c),
            };
            self.bits = self.bits.max(v.numer().bits().max(v.denom().bits()));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(t: &str) -> String {
        parse_poly(t).unwrap().to_string_canonical()
    }

    #[test]
    fn accepts_the_spec_syntax() {
        assert_eq!(s("2x^2"), "2*x^2");
        assert_eq!(s("3(x-1)"), "3*x - 3");
        assert_eq!(s("-x^2"), "-x^2");
        assert_eq!(
            s("(x^2-2)^3 (x-1/3)"),
            "x^7 - 1/3*x^6 - 6*x^5 + 2*x^4 + 12*x^3 - 4*x^2 - 8*x + 8/3"
        );
        assert_eq!(s("1.5x + 1e-2"), "3/2*x + 1/100");
        assert_eq!(s("x y z"), "x*y*z");
        assert_eq!(
            s("(x-9)^2/9 + y^2/4 + z^2/16 - 1"),
            "1/9*x^2 + 1/4*y^2 + 1/16*z^2 - 2*x + 8"
        );
        assert_eq!(s("x - x"), "0");
        assert_eq!(s("2^10"), "1024");
        assert_eq!(s("u^2 - 2u"), "u^2 - 2*u");
    }

    #[test]
    fn hex_literals_and_implicit_multiplication() {
        // the grammar of number::parse: a hex literal starts at 0x only
        // when a hex digit or '.' follows; a variable may follow it
        assert_eq!(s("0x1p3x"), "8*x");
        assert_eq!(s("0x1.8p1x^2 - 0x.8y"), "3*x^2 - 1/2*y");
        assert_eq!(s("0x^2 + 1"), "1");
        assert_eq!(s("2x + 0xy"), "2*x");
        assert_eq!(s("0xap-1(x+1)"), "5*x + 5");
        assert_eq!(s("-0x1p-3"), "-1/8");
        let e = parse_poly("x + 0x1p").unwrap_err();
        assert_eq!(e.column, 9);
        assert!(e.message.contains("binary exponent"), "{e}");
        // inside a hex literal 'e' is a digit: 0x1.8e = 1 + 8/16 + 14/256
        assert_eq!(
            parse_poly("0x1.8e").unwrap().to_string_canonical(),
            "199/128"
        );
        let e = parse_poly("0x1g + x").unwrap_err();
        assert_eq!(
            (e.message.as_str(), e.column),
            ("unexpected 'g' in a hexadecimal number", 4)
        );
    }

    #[test]
    fn float_mode_reads_literals_as_doubles() {
        let f = |t: &str| {
            parse_poly_in(t, &Limits::default(), NumberMode::Float)
                .unwrap()
                .to_string_canonical()
        };
        assert_eq!(f("0.5x + 0.25"), "1/2*x + 1/4");
        assert_eq!(f("0.1x"), "3602879701896397/36028797018963968*x");
        assert_eq!(f("x/10"), "1/10*x"); // 10 is a double: the quotient stays exact
        assert_eq!(s("0.1x"), "1/10*x");
    }

    #[test]
    fn errors_name_problem_and_column() {
        let cases = [
            ("x + ", "unexpected end of expression", 5),
            ("(x + 1", "unclosed '(' (opened here)", 1),
            (
                "x^-1",
                "exponent must be a non-negative integer literal, found '-'",
                3,
            ),
            (
                "x^1.5",
                "exponent must be a non-negative integer literal",
                3,
            ),
            (
                "1/(x-1)",
                "division by a non-constant expression ('/' divides only by a number)",
                2,
            ),
            ("x/0", "division by zero", 2),
            (
                "x + w",
                "unknown variable 'w' (variables are x, y, z, u)",
                5,
            ),
            (
                "x 2",
                "a number cannot follow a factor without an operator (write '*')",
                3,
            ),
            ("", "empty expression", 1),
        ];
        for (t, msg, col) in cases {
            let e = parse_poly(t).unwrap_err();
            assert_eq!((e.message.as_str(), e.column), (msg, col), "input {t:?}");
        }
        assert!(parse_poly("x^100000000").is_err());
        assert!(parse_poly("(x+y+z+u+1)^400").is_err());
        assert!(parse_poly("10^100000000").is_err());
        let deep = "(".repeat(100_000) + "x" + &")".repeat(100_000);
        assert!(parse_poly(&deep).is_err());
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_parse_poly() {
        use crate::poly::parse_poly;
        let p = parse_poly("2x^2 - 3(x-1) + y/4").unwrap();
        assert_eq!(p.to_string_canonical(), "2*x^2 - 3*x + 1/4*y + 3");
        let e = parse_poly("(x + 1))").unwrap_err();
        assert_eq!(e.to_string(), "unexpected ')' at column 8");
    }
}

#[cfg(test)]
mod doc_examples_more {
    //! Examples that were doc comments of crate-private items.

    #[test]
    fn doc_parse_poly_in() {
        use crate::number::NumberMode;
        use crate::poly::{Limits, parse_poly_in};
        let p = parse_poly_in("0x1p3x + 0.5", &Limits::default(), NumberMode::Float).unwrap();
        assert_eq!(p.to_string_canonical(), "8*x + 1/2");
    }
}
