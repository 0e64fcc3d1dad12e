//! The JSON of `--json` and of the batch protocol (contract field names, keys in
//! the documented order).

/// A JSON object from `"key" => value` pairs in order, each value moved in
/// with `Value::from`.  (`serde_json::json!` serializes every interpolated
/// expression again: each nested `Value` is deep-copied once per level,
/// which cost the batch output of curve answers a third of its time.)
macro_rules! obj {
    ($($k:literal => $v:expr),* $(,)?) => {{
        let mut m = serde_json::Map::new();
        $( m.insert(String::from($k), serde_json::Value::from($v)); )*
        serde_json::Value::Object(m)
    }};
}

mod kernel;
mod natural;
mod tangent;

pub use kernel::{alg_json, resultant_json, roots_json};
pub use natural::{natural_input_json, natural_json};
pub use tangent::tangent_json;
