//! The JSON of `--json` and of the batch protocol (contract field names, keys in
//! the documented order).

mod contact;
mod kernel;
mod natural;
mod tangent;
pub(crate) mod write;

pub use contact::contact_json;
pub use kernel::{alg_json, resultant_json, roots_json};
pub use natural::{natural_input_json, natural_json, natural_json_text};
pub use tangent::tangent_json;
