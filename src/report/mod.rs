//! Output: the JSON of `--json` (feature `serde`) and the human-readable
//! text.  This is the only layer that formats results; the computations
//! return plain data.

#[cfg(feature = "serde")]
mod json;
mod text;

#[cfg(feature = "serde")]
pub use json::{
    alg_json, natural_input_json, natural_json, resultant_json, roots_json, tangent_json,
};
pub use text::{natural_human, roots_human, tangent_human, upoly_string};
