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
mod inclusion;
mod isolate;
mod newton;
mod rational;
mod sturm;
mod summary;

pub use algebraic::{RealAlg, separate};
pub use enclose::{
    eval_q, value_at, value_polynomial, values_at, values_with, values_with_unsimplified,
};
pub(crate) use enclose::{meets, ratio_enclosure};
pub(crate) use isolate::descartes_in;
pub use isolate::{RootInterval, bisect_once, isolate_real_roots, isolate_squarefree};
pub(crate) use rational::no_rational_root_sieve;
pub use rational::{simplest_rational_in, split_cubic};
pub use sturm::SturmSequence;
pub use summary::{RealRoot, RootReport, analyze_roots};

// Used by the property tests (independent deciders checked against each
// other: Sturm counts, Descartes bounds, interval enclosures).
#[cfg(test)]
pub use enclose::enclose_mean_value;
#[cfg(test)]
pub use isolate::refine;
#[cfg(test)]
pub use rational::rational_roots;
#[cfg(test)]
pub use sturm::count_real_roots_in;
