//! The public polynomial types: [`Polynomial`] (multivariate over Q in
//! x, y, z, u — what every input is) and [`IntPoly`] (univariate over Z —
//! judging polynomials, defining polynomials of real algebraic numbers).
//! They wrap the internal representations and keep their invariants
//! (canonical sparse terms; no leading zero coefficients).

use super::mpoly::{Exps, MPoly, NVARS, QMPoly, VAR_NAMES};
use super::parse::parse_poly;
use super::zpoly::ZPoly;
use crate::error::{Error, ErrorKind};
use crate::number::{Q, Sign, fmt_q};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::str::FromStr;

/// A variable of the input syntax.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Var {
    /// `x`.
    X,
    /// `y`.
    Y,
    /// `z`.
    Z,
    /// `u` (the critical-value variable of judging polynomials).
    U,
}

impl Var {
    /// All four, in order.
    pub const ALL: [Var; 4] = [Var::X, Var::Y, Var::Z, Var::U];

    pub(crate) fn index(self) -> usize {
        self as usize
    }

    pub(crate) fn from_index(i: usize) -> Option<Var> {
        Var::ALL.get(i).copied()
    }

    /// The variable's name (`x`, `y`, `z`, `u`).
    pub fn name(self) -> &'static str {
        VAR_NAMES[self.index()]
    }
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Var {
    type Err = Error;
    /// `x`, `y`, `z` or `u`.
    fn from_str(s: &str) -> Result<Var, Error> {
        Var::ALL
            .iter()
            .copied()
            .find(|v| v.name() == s.trim())
            .ok_or_else(|| {
                Error::new(
                    ErrorKind::Input,
                    format!("unknown variable '{s}' (use x, y, z or u)"),
                )
            })
    }
}

/// A polynomial in x, y, z, u with exact rational coefficients.
///
/// Parsed from the input syntax (`"2x^2 - 3(x-1) + y/4"`; numbers are
/// exact: `1.5` is 3/2, `1e-12` is 10⁻¹²), printed canonically (graded,
/// then lexicographic), and combined with `+ - *` on owned or borrowed
/// operands, with rationals and integers on either side.
///
/// ```
/// use quadsect::{Polynomial, Var};
/// let p: Polynomial = "(x + 1)(x - 1)".parse().unwrap();
/// assert_eq!(p.to_string(), "x^2 - 1");
/// let q = 3 * &p - Polynomial::var(Var::Y);
/// assert_eq!(q.to_string(), "3*x^2 - y - 3");
/// assert_eq!(q.total_degree(), Some(2));
/// assert!("x^1.5".parse::<Polynomial>().is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Polynomial(pub(crate) QMPoly);

impl Polynomial {
    /// The zero polynomial.
    pub fn zero() -> Polynomial {
        Polynomial(MPoly::zero())
    }

    /// A constant.
    pub fn constant(c: Q) -> Polynomial {
        Polynomial(MPoly::constant(c))
    }

    /// A variable.
    pub fn var(v: Var) -> Polynomial {
        Polynomial(MPoly::var(v.index()))
    }

    pub(crate) fn from_inner(p: QMPoly) -> Polynomial {
        Polynomial(p)
    }

    pub(crate) fn inner(&self) -> &QMPoly {
        &self.0
    }

    /// Parses the input syntax with the numbers read in `mode` (see
    /// [`crate::NumberMode`]).
    pub fn parse_in(text: &str, mode: crate::NumberMode) -> Result<Polynomial, Error> {
        Ok(Polynomial(super::parse::parse_poly_in(
            text,
            &super::parse::Limits::default(),
            mode,
        )?))
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    /// The total degree (`None` for the zero polynomial).
    pub fn total_degree(&self) -> Option<u32> {
        self.0.total_degree()
    }

    /// The degree in one variable (`None` for the zero polynomial).
    pub fn degree_in(&self, v: Var) -> Option<u32> {
        self.0.degree_in(v.index())
    }

    /// The variables that occur, in order.
    pub fn vars(&self) -> Vec<Var> {
        self.0
            .vars()
            .into_iter()
            .filter_map(Var::from_index)
            .collect()
    }

    /// The terms as (exponents of x, y, z, u; coefficient), in the internal
    /// (lexicographic) order.
    pub fn terms(&self) -> impl Iterator<Item = ([u32; 4], &Q)> + '_ {
        self.0
            .terms()
            .iter()
            .map(|(e, c)| ([e[0], e[1], e[2], e[3]], c))
    }

    /// The coefficient of `x^a y^b z^c u^d`.
    pub fn coefficient(&self, exps: [u32; 4]) -> Q {
        let mut e: Exps = [0; NVARS];
        e[..4].copy_from_slice(&exps);
        self.0
            .terms()
            .iter()
            .find(|(f, _)| *f == e)
            .map(|(_, c)| c.clone())
            .unwrap_or_else(Q::zero)
    }

    /// The exact value at `(x, y, z, u)`.
    pub fn eval(&self, point: &[Q; 4]) -> Q {
        let mut p: [Q; NVARS] = std::array::from_fn(|_| Q::zero());
        p[..4].clone_from_slice(point);
        self.0.eval(&p)
    }

    /// The partial derivative in `v`.
    pub fn derivative(&self, v: Var) -> Polynomial {
        Polynomial(self.0.derivative(v.index()))
    }

    /// `self^e`.
    pub fn pow(&self, e: u32) -> Polynomial {
        Polynomial(self.0.pow(e))
    }
}

impl FromStr for Polynomial {
    type Err = Error;
    /// Parses the input syntax; the error names the problem and the column.
    fn from_str(s: &str) -> Result<Polynomial, Error> {
        Ok(Polynomial(parse_poly(s)?))
    }
}

impl fmt::Display for Polynomial {
    /// The canonical form, which parses back to the same polynomial.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.to_string_canonical())
    }
}

impl From<Q> for Polynomial {
    fn from(c: Q) -> Polynomial {
        Polynomial::constant(c)
    }
}

impl From<i64> for Polynomial {
    fn from(c: i64) -> Polynomial {
        Polynomial::constant(Q::from_integer(c.into()))
    }
}

impl From<Var> for Polynomial {
    fn from(v: Var) -> Polynomial {
        Polynomial::var(v)
    }
}

/// Implements a binary operator for all owned/borrowed combinations of
/// polynomials, and of a polynomial with a rational or an integer on either
/// side.
macro_rules! poly_binop {
    ($trait:ident, $method:ident, $op:tt) => {
        impl $trait<&Polynomial> for &Polynomial {
            type Output = Polynomial;
            fn $method(self, o: &Polynomial) -> Polynomial {
                Polynomial(&self.0 $op &o.0)
            }
        }
        impl $trait<Polynomial> for Polynomial {
            type Output = Polynomial;
            fn $method(self, o: Polynomial) -> Polynomial {
                &self $op &o
            }
        }
        impl $trait<&Polynomial> for Polynomial {
            type Output = Polynomial;
            fn $method(self, o: &Polynomial) -> Polynomial {
                &self $op o
            }
        }
        impl $trait<Polynomial> for &Polynomial {
            type Output = Polynomial;
            fn $method(self, o: Polynomial) -> Polynomial {
                self $op &o
            }
        }
        poly_binop!(@scalar $trait, $method, $op, Q, |k: &Q| k.clone());
        poly_binop!(@scalar $trait, $method, $op, i64, |k: &i64| Q::from_integer((*k).into()));
        poly_binop!(@scalar $trait, $method, $op, BigInt, |k: &BigInt| Q::from_integer(k.clone()));
    };
    (@scalar $trait:ident, $method:ident, $op:tt, $t:ty, $conv:expr) => {
        impl $trait<$t> for &Polynomial {
            type Output = Polynomial;
            fn $method(self, k: $t) -> Polynomial {
                self $op &Polynomial::constant($conv(&k))
            }
        }
        impl $trait<$t> for Polynomial {
            type Output = Polynomial;
            fn $method(self, k: $t) -> Polynomial {
                &self $op &Polynomial::constant($conv(&k))
            }
        }
        impl $trait<&Polynomial> for $t {
            type Output = Polynomial;
            fn $method(self, p: &Polynomial) -> Polynomial {
                &Polynomial::constant($conv(&self)) $op p
            }
        }
        impl $trait<Polynomial> for $t {
            type Output = Polynomial;
            fn $method(self, p: Polynomial) -> Polynomial {
                &Polynomial::constant($conv(&self)) $op &p
            }
        }
    };
}

poly_binop!(Add, add, +);
poly_binop!(Sub, sub, -);
poly_binop!(Mul, mul, *);

impl Neg for &Polynomial {
    type Output = Polynomial;
    fn neg(self) -> Polynomial {
        Polynomial(-&self.0)
    }
}

impl Neg for Polynomial {
    type Output = Polynomial;
    fn neg(self) -> Polynomial {
        -&self
    }
}

/// A univariate polynomial with integer coefficients (no variable of its
/// own: it is printed in `u` unless asked otherwise).
///
/// ```
/// use quadsect::{IntPoly, Rational, Sign};
/// let p: IntPoly = "2u^3 - 4u".parse().unwrap();
/// assert_eq!(p.degree(), Some(3));
/// assert_eq!(p.to_string(), "2*u^3 - 4*u");
/// assert_eq!(p.sign_at(&Rational::from_integer(1.into())), Sign::Negative);
/// assert_eq!(p.real_roots().len(), 3);
/// assert!("u/2 + 1".parse::<IntPoly>().is_err()); // not integral
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct IntPoly(pub(crate) ZPoly);

impl IntPoly {
    /// From coefficients, constant term first (trailing zeros dropped).
    pub fn from_coeffs(coeffs: Vec<BigInt>) -> IntPoly {
        IntPoly(ZPoly::new(coeffs))
    }

    pub(crate) fn from_inner(p: ZPoly) -> IntPoly {
        IntPoly(p)
    }

    pub(crate) fn inner(&self) -> &ZPoly {
        &self.0
    }

    /// The coefficients, constant term first (empty for zero).
    pub fn coeffs(&self) -> &[BigInt] {
        self.0.coeffs()
    }

    /// The degree (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.0.degree()
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    /// The exact sign at a rational point.
    pub fn sign_at(&self, x: &Q) -> Sign {
        Sign::from_i32(self.0.sign_at(x))
    }

    /// The exact value at a rational point.
    pub fn eval(&self, x: &Q) -> Q {
        let mut acc = Q::zero();
        for c in self.0.coeffs().iter().rev() {
            acc = acc * x + Q::from_integer(c.clone());
        }
        acc
    }

    /// The square-free part, primitive with a positive leading coefficient
    /// (same roots, each simple).
    pub fn squarefree_part(&self) -> IntPoly {
        IntPoly(self.0.squarefree_part())
    }

    /// Printed in the variable `v`.
    pub fn to_string_in(&self, v: Var) -> String {
        MPoly::from_univariate(&self.0.to_q(), v.index()).to_string_canonical()
    }

    /// The same polynomial as a [`Polynomial`] in the variable `v`.
    pub fn to_polynomial(&self, v: Var) -> Polynomial {
        Polynomial(MPoly::from_univariate(&self.0.to_q(), v.index()))
    }
}

impl fmt::Display for IntPoly {
    /// The polynomial in `u`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_string_in(Var::U))
    }
}

impl FromStr for IntPoly {
    type Err = Error;
    /// A univariate expression (in any one variable) with integer
    /// coefficients after expansion.
    fn from_str(s: &str) -> Result<IntPoly, Error> {
        let p = parse_poly(s)?;
        let vars = p.vars();
        if vars.len() > 1 {
            return Err(Error::new(
                ErrorKind::NotUnivariate,
                format!(
                    "an integer polynomial has one variable, but the expression has {}",
                    vars.iter()
                        .map(|&v| VAR_NAMES[v])
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            ));
        }
        let v = vars.first().copied().unwrap_or(0);
        let mut coeffs: Vec<BigInt> = Vec::new();
        for (e, c) in p.terms() {
            if !c.denom().is_one() {
                return Err(Error::new(
                    ErrorKind::Input,
                    format!(
                        "the coefficient {} is not an integer (an IntPoly has integer coefficients)",
                        fmt_q(c)
                    ),
                ));
            }
            let d = e[v] as usize;
            if coeffs.len() <= d {
                coeffs.resize(d + 1, BigInt::zero());
            }
            coeffs[d] = c.numer().clone();
        }
        Ok(IntPoly(ZPoly::new(coeffs)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{q, qi};

    #[test]
    fn operators_on_every_operand_shape() {
        let x = Polynomial::var(Var::X);
        let y: Polynomial = "y".parse().unwrap();
        let p = &x * &x - 2 * &y + q(1, 2);
        assert_eq!(p.to_string(), "x^2 - 2*y + 1/2");
        let r = p.clone() * 2i64 - BigInt::from(1) + (-&x);
        assert_eq!(r.to_string(), "2*x^2 - x - 4*y");
        assert_eq!(qi(3) * x.clone(), "3x".parse().unwrap());
        assert_eq!(p.eval(&[qi(2), qi(1), qi(0), qi(0)]), q(5, 2));
        assert_eq!(p.coefficient([0, 1, 0, 0]), qi(-2));
        assert_eq!(p.vars(), vec![Var::X, Var::Y]);
        assert_eq!(p.derivative(Var::X).to_string(), "2*x");
    }

    #[test]
    fn display_parses_back() {
        for s in ["x^3 - 2/3*x*y + z^2 - 7", "u^5 - 1", "0", "-x - 1/9"] {
            let p: Polynomial = s.parse().unwrap();
            assert_eq!(p.to_string().parse::<Polynomial>().unwrap(), p);
        }
        let z: IntPoly = "x^2 - 2".parse().unwrap();
        assert_eq!(z.to_string(), "u^2 - 2");
        assert_eq!(z.to_string_in(Var::X), "x^2 - 2");
        assert_eq!(z.to_string().parse::<IntPoly>().unwrap(), z);
    }

    #[test]
    fn intpoly_refuses_what_it_cannot_hold() {
        assert_eq!(
            "x*y".parse::<IntPoly>().unwrap_err().kind(),
            ErrorKind::NotUnivariate
        );
        assert_eq!(
            "x/3".parse::<IntPoly>().unwrap_err().kind(),
            ErrorKind::Input
        );
        assert_eq!(
            "(x".parse::<IntPoly>().unwrap_err().kind(),
            ErrorKind::Parse
        );
        assert_eq!("q".parse::<Var>().unwrap_err().kind(), ErrorKind::Input);
    }
}
