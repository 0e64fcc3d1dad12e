//! Output: JSON values (SPEC field names) and human-readable text.  This is
//! the only layer that formats results; the computations return plain data.

mod counts;
mod kernel;
mod natural;
mod tangent;

pub use counts::{natural_counts_human, natural_counts_json};
pub use kernel::{alg_json, resultant_human, resultant_json, roots_human, roots_json, table};
pub use natural::{natural_human, natural_json};
pub use tangent::{alg_json_in, qsqrt_json, tangent_human, tangent_json, upoly_string};
