//! # quadsect
//!
//! An exact-arithmetic engine that decides how two surfaces meet.
// Matrix and vector code indexes several arrays with one loop variable.
#![allow(clippy::needless_range_loop)]
// Report types carry their data inline on purpose (built once, read once).
#![allow(clippy::large_enum_variant)]

#[cfg(feature = "serde")]
pub mod batch;
pub mod budget;
#[cfg(feature = "cli")]
pub mod cli;
pub mod elim;
pub mod error;
pub mod geom;
pub mod natural;
pub mod number;
pub mod ops;
pub mod poly;
pub mod report;
pub mod roots;
pub mod tangent;

#[cfg(test)]
mod tests;

pub use error::{Error, ErrorKind};
