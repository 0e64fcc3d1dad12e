//! # quadsect
//!
//! An exact-arithmetic engine that decides how two surfaces meet.
pub mod batch;
pub mod bench;
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
