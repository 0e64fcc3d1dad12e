//! # quadsect's C and C++ interface
//!
//! `libquadsect.so` / `libquadsect.a` and `include/quadsect.h` (made by
//! cbindgen from this crate; the test in `header.rs` checks it is fresh).  Two
//! levels, both exact and both never aborting the host:
//!
//! * text/JSON ([`json`]): expressions in the input syntax in, the JSON of
//!   the CLI's `--json` out, and one line of the batch protocol;
//! * typed doubles ([`typed`]): natural quadrics, ellipsoids and quadrics
//!   given as doubles, each taken as its exact binary value; answers in
//!   small structs, extremes as doubles rounded outward ([`float`]), and
//!   the components of two natural quadrics as doubles with proven error
//!   bounds ([`components`]: one owned result, freed by its `_free`).
//!
//! Every entry point runs inside [`boundary::guard`]: a panic becomes an
//! internal error (code 1), bad input code 2, an exhausted budget code 3
//! (with the `undecided` answer still written, as the CLI prints it), with
//! the kind and message in a `qs_error`.  No global state: calls on
//! different threads share nothing (the engine's budget is thread-local).
//! See the README's "C and C++" section for the ownership rules.

// The C names (qs_error, qs_natural_f64, …) are the interface.
#![allow(non_camel_case_types)]

pub mod boundary;
mod float;
#[cfg(test)]
mod header;
pub mod json;
pub mod options;
pub mod typed;
// after typed: its section of the header follows qs_natural_classify_f64
pub mod components;
// after components: the ellipsoid pairs
pub mod contact;

use std::ffi::c_char;

/// The major version of the library (`QS_VERSION_MAJOR`).
pub const QS_VERSION_MAJOR: u32 = 0;
/// The minor version.
pub const QS_VERSION_MINOR: u32 = 1;
/// The patch version.
pub const QS_VERSION_PATCH: u32 = 0;
/// `MAJOR * 10000 + MINOR * 100 + PATCH`, for `#if QS_VERSION_NUMBER >= …`.
pub const QS_VERSION_NUMBER: u32 =
    QS_VERSION_MAJOR * 10000 + QS_VERSION_MINOR * 100 + QS_VERSION_PATCH;
/// The version of the library that is linked, `"MAJOR.MINOR.PATCH"`
/// (compare it with the header's `QS_VERSION`, made from
/// `QS_VERSION_MAJOR`, `QS_VERSION_MINOR` and `QS_VERSION_PATCH`).  A static string: never free it.
#[unsafe(no_mangle)]
pub extern "C" fn qs_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_version_macros_match_the_package_version() {
        // the header's constants are literals (cbindgen exports only
        // those): they must follow Cargo.toml's version
        let parts = [QS_VERSION_MAJOR, QS_VERSION_MINOR, QS_VERSION_PATCH];
        let cargo: Vec<u32> = env!("CARGO_PKG_VERSION")
            .split('.')
            .map(|p| p.parse().unwrap())
            .collect();
        assert_eq!(cargo, parts);
        assert_eq!(
            QS_VERSION_NUMBER,
            parts[0] * 10000 + parts[1] * 100 + parts[2]
        );
        let v = unsafe { std::ffi::CStr::from_ptr(qs_version()) };
        let dotted = format!("{}.{}.{}", parts[0], parts[1], parts[2]);
        assert_eq!(v.to_str().unwrap(), dotted);
    }
}
