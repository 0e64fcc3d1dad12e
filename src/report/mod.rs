//! Output: the JSON of `--json` (feature `serde`) and the human-readable
//! text.  This is the only layer that formats results; the computations
//! return plain data.

#[cfg(feature = "serde")]
mod json;
mod text;

#[cfg(feature = "serde")]
pub use json::{
    alg_json, contact_json, natural_input_json, natural_json, natural_json_text, resultant_json,
    roots_json, tangent_json,
};
pub use text::{natural_human, roots_human, tangent_human, upoly_string};

/// The separating element of a modular RUR: `S`, or `S + c·(l·(x, y, z))`
/// when S alone does not separate the critical points.
pub(crate) fn separating_element(an: &crate::tangent::modular::ModularAnalysis) -> String {
    match &an.shift {
        None => "S".into(),
        Some((l, c)) => format!(
            "S + {}*({}*x + {}*y + {}*z)",
            crate::number::fmt_q(c),
            crate::number::fmt_q(&l[0]),
            crate::number::fmt_q(&l[1]),
            crate::number::fmt_q(&l[2])
        ),
    }
}
