//! JSON of the kernel operations (`roots`, `resultant`) and of real
//! algebraic numbers.

use super::write::{Json, W, wobj};
use crate::kernel::{ResultantReport, RootsReport};
use crate::number::fmt_q;
use crate::roots::RealAlg;
use serde_json::{Value, json};

/// A real algebraic number as the contract's ALG object:
/// `{"poly", "interval": [lo, hi], "approx"}`.
pub fn alg_json(a: &RealAlg) -> Value {
    let mut out = Vec::new();
    alg_w(a).write(&mut out);
    super::write::to_value(&out)
}

/// [`alg_json`] written into JSON text (the one place the ALG object's
/// fields are spelled).
pub(crate) fn alg_w(a: &RealAlg) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        let (poly, interval, approx) = a.describe();
        wobj!(out; "poly" => poly, "interval" => interval, "approx" => approx)
    })
}

/// `quadsect roots --json`.
pub fn roots_json(r: &RootsReport) -> Value {
    let rep = &r.report;
    let intervals: Vec<Value> = rep
        .roots
        .iter()
        .map(|x| json!([fmt_q(&x.interval.lo), fmt_q(&x.interval.hi)]))
        .collect();
    let mult: Vec<u32> = rep.roots.iter().map(|x| x.multiplicity).collect();
    json!({
        "distinct_real": rep.distinct_real,
        "positive": rep.positive,
        "negative": rep.negative,
        "zero_multiplicity": rep.zero_multiplicity,
        "real_with_multiplicity": rep.real_with_multiplicity,
        "descartes_positive_bound": rep.descartes_positive_bound,
        "descartes_negative_bound": rep.descartes_negative_bound,
        "intervals": intervals,
        "multiplicities": mult,
    })
}

/// `quadsect resultant --json`.
pub fn resultant_json(r: &ResultantReport) -> Value {
    json!({"resultant": r.resultant.to_string_canonical(), "degree": r.degree})
}
