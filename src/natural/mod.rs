//! Natural quadrics (paper 000, Shene & Johnstone): how two spheres,
//! circular cylinders or right cones meet, decided and computed exactly.

pub mod classify;
pub mod coaxial;
pub mod deciders;
pub mod exact;
pub mod planar;
pub mod result;
pub mod tangency;
pub mod topology;
pub mod types;

pub use crate::geom::cayley_rotation;
pub use classify::{classify, classify_str};
pub use types::{Cone, Cylinder, Natural, Sphere, parse_natural};
