//! Human-readable text: aligned summaries with decimal approximations
//! beside the exact values.

mod contact;
mod kernel;
mod natural;
mod tangent;

pub use kernel::roots_human;
pub use natural::natural_human;
pub use tangent::{tangent_human, upoly_string};
