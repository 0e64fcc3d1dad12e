//! The shared geometry floor under both domains (the tangent point method
//! and the natural quadrics, which never import each other): exact
//! 3-vectors, small matrices over Q and Z, quadrics as matrices, rigid
//! motions, and evaluation at points with coordinates in Q(√d).

pub mod eval;
pub mod matrix;
pub mod motion;
pub mod quadric;
pub mod vec3;

pub use eval::{eval_qsqrt, gradient};
pub use matrix::{Mat4, adj3_int, det3};
#[cfg(any(test, feature = "cli"))]
pub use motion::rotate;
pub use motion::{cayley_rotation, is_rotation};
pub use quadric::{QuadricForm, common_denominator};
