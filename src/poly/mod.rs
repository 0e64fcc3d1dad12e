//! Polynomials: dense univariate over any ring ([`UPoly`], with the Z/Q
//! algorithms in [`zpoly`]), sparse multivariate ([`MPoly`]), the expression
//! parser ([`parse_poly`]) and the canonical printer
//! ([`MPoly::to_string_canonical`]).
//!
//! Key idea: one generic dense type serves Z[x], Q[x] and the recursive
//! representation R[y][x] used in elimination; the [`Ring`] trait supplies
//! exact division, which is all the fraction-free algorithms need.

pub mod extension;
pub(crate) mod horner;
mod macros;
pub(crate) mod modp;
pub mod mpoly;
pub mod parse;
mod polynomial;
pub mod ring;
pub(crate) mod sqfree;
pub mod upoly;
pub mod zpoly;

#[cfg(any(test, feature = "cli"))]
pub use mpoly::MPoly;
pub use mpoly::{QMPoly, ZMPoly};
pub use parse::{Limits, ParseError, parse_poly, parse_poly_in};
pub use polynomial::{IntPoly, Polynomial, Var};
pub use ring::Ring;
pub use upoly::UPoly;
pub use zpoly::{QPoly, ZPoly};
