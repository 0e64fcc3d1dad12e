//! Real roots of univariate integer polynomials: Sturm sequences
//! ([`SturmSequence`]), Descartes' rule of signs and VCA isolation
//! ([`isolate_real_roots`]), refinement, real algebraic numbers
//! ([`RealAlg`]) with exact comparison and sign queries, and the root
//! summary behind `quadsect roots` ([`analyze_roots`]).
//!
//! Key idea: two independent exact counters — Sturm's theorem and Descartes
//! bisection — must agree (the property tests check it), and zero is always
//! decided exactly (gcds and exact evaluation at rationals).

mod algebraic;
mod enclose;
mod isolate;
pub mod modrur;
mod newton;
mod rational;
mod report;
pub mod rurcheck;
mod sturm;
mod zerodim;

pub use algebraic::{RealAlg, has_root_in_open, separate};
pub use enclose::{
    enclose_mean_value, eval_interval, eval_q, eval_ratio_interval, eval_xyz, ratio_enclosure,
    value_at, value_polynomial, values_at, values_with,
};
pub use isolate::{
    RootInterval, bisect_once, descartes_bounds, isolate_real_roots, isolate_squarefree, refine,
    sign_variations,
};
pub use rational::{no_rational_root_sieve, rational_roots, simplest_rational_in, split_cubic};
pub use report::{RealRoot, RootReport, analyze_roots};
pub use sturm::{Point, SturmSequence, count_real_roots_in};
pub use zerodim::{GENERIC_FORMS, Rur, solve_zero_dim};
