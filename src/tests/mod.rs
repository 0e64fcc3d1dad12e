//! Behaviour tests that need the crate's internals (the deciders, the
//! witness machinery, the kernel), run with `cargo test`.  Tests of the
//! public API alone are in `tests/`.
//!
//! * `tangent`: every example of paper 004 with the paper's printed numbers
//!   beside ours, constructed tangencies, property tests (rigid motions,
//!   scaling, sampling, agreement of routes);
//! * `natural`: paper 000's examples, the three conic deciders, the
//!   classification of every class, property tests;
//! * `kernel_props`, `kernel_reference`: the algebra kernel against
//!   properties and against committed sympy reference data;
//! * `fuzz_props`: proptest versions of the fuzz targets;
//! * `figures`: the pictures (well-formed, inked, one per class and
//!   verdict, the committed ones up to date);
//! * `layout`: the folders' imports (no circle, the ground floors import
//!   nothing above them) and the files' names.

/// One step of Marsaglia's xorshift (shifts 13, 7, 17): the fixed
/// pseudo-random sequences of the unit tests.
pub(crate) fn xorshift(state: &mut u64) -> u64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    *state
}

mod fast_route;
#[cfg(all(feature = "cli", feature = "png"))]
mod figures;
mod fuzz_props;
mod kernel_props;
mod kernel_reference;
mod layout;
mod natural;
mod natural_whole;
mod nonreduced;
mod printing;
mod referee;
mod square_subsystem;
mod tangent;
