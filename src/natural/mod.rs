//! Natural quadrics (paper 000, Shene & Johnstone): how two spheres,
//! circular cylinders or right cones meet, decided and computed exactly.

pub mod classify;
pub mod coaxial;
pub mod deciders;
pub mod exact;
pub mod examples;
pub mod planar;
pub mod result;
pub mod tangency;
pub mod topology;
pub mod types;
pub mod vec3;

pub use classify::{classify, classify_str, classify_str_within, classify_within};
pub use types::{Cone, Cylinder, Natural, Sphere, cayley_rotation, parse_natural};
