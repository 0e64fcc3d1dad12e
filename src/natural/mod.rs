//! Natural quadrics (paper 000, Shene & Johnstone): how two spheres,
//! circular cylinders or right circular cones meet, decided and computed
//! exactly.
//!
//! [`classify`] returns the class of the intersection (two conics, a conic
//! and a double line, lines, isolated points, empty, or a genuine space
//! curve), the counts of real affine conics, lines and points, and each
//! component with exact data (planes, centres, squared semi-axes in Q(√d)
//! or as real algebraic numbers).  For coplanar axes the three conic
//! deciders of part 1 — Theorem 8.1/8.2's closed forms, Lemma 8.1's
//! projection-conic discriminant and the pencil rank — are reported and
//! checked against each other; [`thm8`] is the closed form alone.

pub(crate) mod build_pencil;
pub(crate) mod build_planar;
pub(crate) mod classify;
pub(crate) mod coaxial;
pub(crate) mod construct;
pub(crate) mod curve;
pub(crate) mod deciders;
pub(crate) mod numbers;
pub(crate) mod planar;
pub(crate) mod predicates;
pub(crate) mod prepared;
pub(crate) mod referee;
pub(crate) mod result;
pub(crate) mod tangency;
pub(crate) mod topology;
pub(crate) mod types;
pub(crate) mod zsqrt;

pub(crate) use classify::classify;
pub use classify::classify_str;
pub use curve::CurvePoint;
pub use deciders::{AxesRelation, conic_intersection_thm8 as thm8};
pub use numbers::{EPoint, Exact, normalize_axis_direction, normalize_direction, normalize_plane};
pub(crate) use predicates::{ClassifyOptions, classify_with};
pub use predicates::{classify_counts, classify_prepared};
pub use prepared::Prepared;
pub use referee::{NearbyPair, Referee};
pub(crate) use result::NaturalReport;
pub use result::{
    Component, ConicKind, CurveBranch, PlanarDeciders, Plane, PointKind, SingularKind,
    SingularPoint,
};
pub use tangency::Section7;
pub(crate) use types::Natural;
pub(crate) use types::parse_natural;
