//! # quadsect
//!
//! An exact-arithmetic engine that decides how two surfaces meet.
// Matrix and vector code indexes several arrays with one loop variable.
#![allow(clippy::needless_range_loop)]
// Report types carry their data inline on purpose (built once, read once).
#![allow(clippy::large_enum_variant)]

pub mod batch;
pub mod bench;
pub mod bench_cases;
pub mod budget;
pub mod elim;
pub mod error;
pub mod examples;
pub mod natural;
pub mod number;
pub mod ops;
pub mod poly;
pub mod report;
pub mod roots;
pub mod tangent;

pub use error::{Error, ErrorKind};
