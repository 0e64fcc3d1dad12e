//! Output of the fast classification (`quadsect natural --no-components`):
//! class, counts, axes and Theorem 8 — the SPEC §4 fields without
//! `components` — or the full report when the fast route fell back to the
//! complete one.

use super::natural::{axes_thm8_method, natural_human, natural_json};
use crate::natural::Classification;
use serde_json::{Value, json};

/// `quadsect natural --no-components --json`: `class`, `conics`, `lines`,
/// `points`, `axes`, `thm8`, `method` and `route` (`fast` or `complete`);
/// when the complete route answered, its whole report follows (with
/// `components`).
pub fn natural_counts_json(r: &Classification) -> Value {
    if let Some(full) = &r.report {
        let mut v = natural_json(full);
        if let Value::Object(m) = &mut v {
            m.insert("route".into(), json!("complete"));
            m.insert("fallback".into(), json!(r.method));
        }
        return v;
    }
    let c = &r.counts;
    json!({
        "class": c.class.as_str(),
        "conics": c.conics,
        "lines": c.lines,
        "points": c.points,
        "axes": r.axes.as_ref().map(|a| a.as_str()),
        "thm8": r.thm8,
        "method": r.method,
        "route": "fast",
    })
}

/// `quadsect natural --no-components` for people.
pub fn natural_counts_human(r: &Classification) -> String {
    if let Some(full) = &r.report {
        return format!("{}route     complete ({})\n", natural_human(full), r.method);
    }
    let c = &r.counts;
    format!(
        "class     {}  ({} conics, {} lines, {} points)\n{}route     fast (no components computed)\n",
        c.class.as_str(),
        c.conics,
        c.lines,
        c.points,
        axes_thm8_method(r.axes.as_ref(), r.thm8, r.method)
    )
}
