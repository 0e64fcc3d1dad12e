//! Output: JSON values (SPEC field names) and human-readable text.  This is
//! the only layer that formats results; the computations return plain data.

mod kernel;
mod natural;
mod tangent;

pub use kernel::{alg_json, resultant_human, resultant_json, roots_human, roots_json, table};
pub use natural::{natural_human, natural_json};
pub use tangent::{alg_json_in, qsqrt_json, tangent_human, tangent_json, upoly_string};

use serde_json::{Value, json};

/// Why an answer is `undecided` because a compute budget ran out:
/// `{"kind": "budget", "limit": "time"|"memory"|"size"|"cancelled",
/// "message": "…"}` (the `reason` of the tangent and natural JSON).
pub fn budget_reason_json(e: &crate::budget::Exhausted) -> Value {
    json!({"kind": "budget", "limit": e.limit().as_str(), "message": e.to_string()})
}
