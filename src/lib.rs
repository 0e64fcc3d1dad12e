//! # quadsect — exact decisions on how two surfaces meet
//!
//! quadsect answers, without a single rounding error and with a
//! certificate for every answer:
//!
//! 1. **Ellipsoid vs algebraic surface** (the *tangent point method*): do an
//!    ellipsoid `E = 0` and a surface `S = 0` intersect, touch, or stay
//!    apart — and on which side of `S` does `E` lie?  [`decide`]
//!    returns the exact minimum ν and maximum μ of S on E (they intersect
//!    iff ν ≤ 0 ≤ μ, touch iff ν = 0 or μ = 0), the judging polynomial
//!    D(u), and exact witness points.
//! 2. **Two natural quadrics** (spheres, circular cylinders, right circular
//!    cones): [`classify`] says whether the intersection is two
//!    conics, a conic and a double line, lines, isolated points, empty or a
//!    genuine space curve, and gives every conic, line and point exactly.
//! 3. **The algebra kernel**: real roots of univariate polynomials
//!    ([`roots`]) and resultants ([`resultant`]), exactly.
//!
//! Every number is exact: inputs are rationals (`1.5` is 3/2, `1e-12` is
//! 10⁻¹²), irrational outputs are `a + b√d` ([`QSqrt`]) or real algebraic
//! numbers ([`RealAlg`]: a square-free integer polynomial and an isolating
//! interval).  Floats appear only in printed approximations.
//!
//! ## One example per job
//!
//! ```
//! use quadsect::{Class, Ellipsoid, Natural, Polynomial, Var, Verdict};
//!
//! // 1. the paper's Example 1: separated, min 7/9 and max 187/9 exactly
//! let e: Ellipsoid = "x^2 + y^2 + z^2 - 25".parse()?;
//! let s: Polynomial = "(x-9)^2/9 + y^2/4 + z^2/16 - 1".parse()?;
//! let r = quadsect::decide(&e, &s)?;
//! assert_eq!(r.verdict(), Verdict::Separated);
//! assert_eq!((r.min().unwrap().to_string(), r.max().unwrap().to_string()),
//!            ("7/9".to_string(), "187/9".to_string()));
//!
//! // 2. two perpendicular unit cylinders meet in two ellipses
//! let a: Natural = "cylinder point=0,0,0 axis=1,0,0 radius2=1".parse()?;
//! let b: Natural = "cylinder point=0,0,0 axis=0,1,0 radius2=1".parse()?;
//! let n = quadsect::classify(&a, &b)?;
//! assert_eq!(n.class(), Class::Conics);
//! assert_eq!(n.conics(), 2);
//!
//! // 3. the kernel
//! let p: Polynomial = "x^3 - 2x".parse()?;
//! assert_eq!(quadsect::roots(&p)?.distinct_real(), 3);
//! let res = quadsect::resultant(&"x^2+y^2-1".parse()?, &"x-y".parse()?, Var::X)?;
//! assert_eq!(res.resultant().to_string(), "2*y^2 - 1");
//! # Ok::<(), quadsect::Error>(())
//! ```
//!
//! ## Module map
//!
//! The data flows one way — text → surfaces → polynomials → elimination →
//! root counting → verdict → report; each floor imports only the floors
//! below it (no circle between folders):
//!
//! | layer | what it holds |
//! |---|---|
//! | `number` | exact scalars: rationals, Q(√d) ([`QSqrt`]), [`Sign`], one word prime field (31-bit primes) with one CRT, rational reconstruction, Lehmer's gcd |
//! | `poly` | [`Polynomial`] (sparse, over Q), [`IntPoly`] (dense, over Z), the parser, square-free parts, polynomials over `F_p` |
//! | `elim` | resultants: Sylvester, subresultants, multi-modular, the values of a rational function at the roots of a polynomial |
//! | `roots` | real roots of univariate integer polynomials: Sturm sequences, Descartes/VCA isolation, [`RealAlg`], enclosures |
//! | `system` | zero-dimensional systems in x, y, z: Gröbner bases over Q and F_p, the quotient algebra, the RUR by three routes and its exact check, certified boxes (Krawczyk, the census) |
//! | `geom` | the shared geometry floor: vectors, matrices, quadric forms, rigid motions |
//! | [`tangent`], [`natural`] | the two domains (siblings on `geom`, never importing each other) |
//! | `report` | all formatting: JSON (feature `serde`) and human text |
//! | `draw` | the answers' pictures: SVG text ([`NaturalReport::svg`], [`TangentReport::svg`]), PNG with feature `png` |
//! | [`batch`] | the JSON-lines protocol of `quadsect batch` (feature `serde`) |
//! | `cli` | the command-line program (feature `cli`) |
//!
//! ## What the types forbid
//!
//! Invalid values cannot be built: every input type has private fields and
//! checked constructors, so a zero axis, a negative radius², an "isolating"
//! interval without a root or a non-square-free defining polynomial is an
//! error at construction, never a panic or a wrong answer later.
//!
//! ```compile_fail
//! // a cylinder's fields are private: only Cylinder::new (which checks) builds one
//! use quadsect::{Cylinder, Natural, Rational};
//! let z = Rational::from_integer(0.into());
//! let c = Natural::Cylinder(Cylinder { point: [z.clone(), z.clone(), z.clone()],
//!     axis: [z.clone(), z.clone(), z.clone()], r2: -Rational::from_integer(1.into()) });
//! ```
//!
//! ```compile_fail
//! // a real algebraic number has no public representation: RealAlg::new checks it
//! use quadsect::RealAlg;
//! let r = RealAlg::Root { poly: "u^2-2".parse().unwrap(), lo: 0.into(), hi: 1.into() };
//! ```
//!
//! ```compile_fail
//! // QSqrt's parts are read through accessors only (d ≥ 0 is an invariant)
//! let mut x = quadsect::QSqrt::rational(1.into());
//! x.d = (-1).into();
//! ```
//!
//! ```compile_fail
//! // result enums are #[non_exhaustive]: matches need a wildcard arm
//! fn name(v: quadsect::Verdict) -> &'static str {
//!     match v {
//!         quadsect::Verdict::Intersecting => "i",
//!         quadsect::Verdict::Touching => "t",
//!         quadsect::Verdict::Separated => "s",
//!         quadsect::Verdict::Undecided => "u",
//!     }
//! }
//! ```
//!
//! The checked errors, for comparison:
//!
//! ```
//! use quadsect::{Cylinder, ErrorKind, IntPoly, RealAlg, Rational};
//! let r = |n: i64| Rational::from_integer(n.into());
//! let e = Cylinder::new([r(0), r(0), r(0)], [r(0), r(0), r(0)], r(-1)).unwrap_err();
//! assert_eq!(e.kind(), ErrorKind::BadQuadric);
//! let p: IntPoly = "u^2 - 2".parse().unwrap();
//! assert!(RealAlg::new(&p, &r(0), &r(1)).is_err()); // no root in [0, 1]
//! let sq: IntPoly = "(u^2 - 2)^2".parse().unwrap();
//! let s = RealAlg::new(&sq, &r(1), &r(2)).unwrap(); // √2, not a wrong value
//! assert_eq!(s.approx(6), "1.41421");
//! ```
//!
//! ## Budgets
//!
//! Every operation runs under a [`Budget`] (time, memory, sizes,
//! cancellation; [`Budget::default`] unless the `_with` variant is given
//! one).  Running out is an answer — [`Verdict::Undecided`] with
//! [`tangent::Undecided::Budget`] — or an error of kind
//! [`ErrorKind::Budget`], never a hang.
//!
//! ## Features
//!
//! * `cli` (default): the `quadsect` program (clap, indicatif; batch threads are std threads).
//!   Library users: `default-features = false`.
//! * `serde`: `Serialize` for the reports (the JSON of `--json`, keys in the
//!   documented order), the JSON input form of natural quadrics, and
//!   [`batch::answer_line`].
//! * `png` (with `cli`): `svg_to_png`, PNG images of the pictures
//!   (`NaturalReport::svg`, `TangentReport::svg`, which need no feature)
//!   by resvg, pure Rust.
//!
//! See `docs/contract.md` in the repository for the full input/output
//! contract.

// Matrix and vector code indexes several arrays with one loop variable.
#![allow(clippy::needless_range_loop)]
// Report types carry their data inline on purpose (built once, read once).
#![allow(clippy::large_enum_variant)]
#![warn(missing_docs)]
// Some internal helpers serve only the command line (examples, benchmarks):
// without the `cli` feature they are compiled but unused.
#![cfg_attr(not(feature = "cli"), allow(unused_imports, dead_code))]

#[cfg(feature = "serde")]
pub mod batch;
pub mod budget;
#[cfg(feature = "cli")]
#[doc(hidden)]
pub mod cli;
pub mod contact;
mod draw;
mod elim;
mod error;
mod geom;
mod kernel;
pub mod natural;
mod number;
mod poly;
mod report;
mod request;
mod roots;
#[cfg(feature = "serde")]
mod serde_impls;
mod system;
pub mod tangent;

#[cfg(test)]
mod tests;

pub use budget::limits::{Budget, Exhausted, Limit};
#[cfg(feature = "png")]
pub use draw::png::svg_to_png;
pub use error::{Error, ErrorKind};
pub use geom::{cayley_rotation, is_rotation};
pub use kernel::{
    ResultantReport, Root, RootsReport, resultant, resultant_str, resultant_with, roots, roots_str,
    roots_with,
};
pub use natural::classify::classify;
pub use natural::predicates::{ClassifyOptions, classify_with};
pub use natural::referee::{NearbyPair, Referee};
pub use natural::result::{Class, NaturalReport};
pub use natural::types::{Cone, Cylinder, Natural, Sphere};
pub use number::{NumberMode, QSqrt, Sign};
pub use poly::{IntPoly, Polynomial, Var};
pub use roots::RealAlg;
pub use tangent::api::{TangentOptions, TangentReport, Verdict, decide, decide_with};
pub use tangent::ellipsoid::Ellipsoid;

/// Parses an exact number: an integer (`-12`), a rational (`7/9`), a
/// decimal (`1.77777777777` is exactly 177777777777/10¹¹) or a scientific
/// decimal (`1e-12`, `2.5E3`).
///
/// ```
/// let q = quadsect::parse_rational("2.5E-1").unwrap();
/// assert_eq!(q, quadsect::Rational::new(1.into(), 4.into()));
/// assert!(quadsect::parse_rational("1/0").is_err());
/// ```
pub fn parse_rational(s: &str) -> Result<Rational, Error> {
    number::parse_rational(s).map_err(Error::from)
}

/// [`parse_rational`] in a [`NumberMode`]: with [`NumberMode::Float`] a
/// decimal literal becomes its nearest double (round to nearest, ties to
/// even) — the number a program reading the text would hold.  Hexadecimal
/// floats (`0x1.8p-1`) are exact in both modes.
///
/// ```
/// use quadsect::{NumberMode, Rational};
/// let x = quadsect::parse_rational_in("0.1", NumberMode::Float).unwrap();
/// assert_eq!(Some(x), Rational::from_float(0.1_f64));
/// assert_eq!(quadsect::parse_rational("0x1.8p-1").unwrap(), Rational::new(3.into(), 4.into()));
/// ```
pub fn parse_rational_in(s: &str, mode: NumberMode) -> Result<Rational, Error> {
    number::parse_rational_with(s, mode).map_err(Error::from)
}

/// Arbitrary-precision integers (re-exported from `num-bigint`).
pub use num_bigint::BigInt;
/// Exact rationals (re-exported from `num-rational`): every input number.
pub use num_rational::BigRational as Rational;

/// The README's Rust examples, compiled and run as doctests so they stay true.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
