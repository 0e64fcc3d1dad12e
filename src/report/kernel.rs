//! Formatting of the kernel operations (`roots`, `resultant`) and of real
//! algebraic numbers.

use crate::number::{approx_decimal, fmt_q};
use crate::ops::{ResultantResult, RootsResult};
use crate::roots::RealAlg;
use serde_json::{Value, json};

/// A real algebraic number as SPEC's ALG object:
/// `{"poly", "interval": [lo, hi], "approx"}`.
pub fn alg_json(a: &RealAlg) -> Value {
    let (poly, interval, approx) = a.describe();
    json!({"poly": poly, "interval": interval, "approx": approx})
}

/// `quadsect roots --json`.
pub fn roots_json(r: &RootsResult) -> Value {
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

/// Left-aligned text table with a header row.
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let n = header.len();
    let mut w: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in rows {
        for (i, c) in r.iter().enumerate().take(n) {
            w[i] = w[i].max(c.chars().count());
        }
    }
    let line = |cells: Vec<String>| -> String {
        let mut s = String::from("  ");
        for (i, c) in cells.iter().enumerate() {
            s.push_str(c);
            if i + 1 < cells.len() {
                s.push_str(&" ".repeat(w[i] - c.chars().count() + 2));
            }
        }
        s.trim_end().to_string()
    };
    let mut out = vec![line(header.iter().map(|h| h.to_string()).collect())];
    for r in rows {
        out.push(line(r.clone()));
    }
    out.join("\n")
}

/// `quadsect roots` for people: counts, then one aligned row per root with
/// its exact interval, multiplicity and a decimal approximation.
pub fn roots_human(r: &RootsResult) -> String {
    let rep = &r.report;
    let v = r.variable.unwrap_or("x");
    let mut s = format!(
        "polynomial        {}\ndegree            {}\n",
        r.poly.to_string_canonical(),
        r.integer_poly.degree().unwrap_or(0)
    );
    s.push_str(&format!(
        "real roots        {} distinct ({} counted with multiplicity): {} positive, {} negative, {}\n",
        rep.distinct_real,
        rep.real_with_multiplicity,
        rep.positive,
        rep.negative,
        if rep.zero_multiplicity > 0 {
            format!("{v} = 0 with multiplicity {}", rep.zero_multiplicity)
        } else {
            "0 is not a root".to_string()
        }
    ));
    s.push_str(&format!(
        "Descartes bounds  at most {} positive, at most {} negative (with multiplicity)\n",
        rep.descartes_positive_bound, rep.descartes_negative_bound
    ));
    if rep.roots.is_empty() {
        s.push_str("no real roots\n");
        return s;
    }
    let rows: Vec<Vec<String>> = rep
        .roots
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let iv = if x.interval.is_exact() {
                format!("{} (exact)", fmt_q(&x.interval.lo))
            } else {
                format!("({}, {})", fmt_q(&x.interval.lo), fmt_q(&x.interval.hi))
            };
            let approx = match x.value() {
                RealAlg::Rational(q) => approx_decimal(&q, 20),
                a => a.approx(20),
            };
            vec![
                format!("{}", i + 1),
                format!("{}", x.multiplicity),
                iv,
                format!("≈ {approx}"),
            ]
        })
        .collect();
    s.push('\n');
    s.push_str(&table(&["#", "mult", "isolating interval", "value"], &rows));
    s.push('\n');
    s
}

/// `quadsect resultant --json`.
pub fn resultant_json(r: &ResultantResult) -> Value {
    json!({"resultant": r.resultant.to_string_canonical(), "degree": r.degree})
}

/// `quadsect resultant` for people.
pub fn resultant_human(r: &ResultantResult) -> String {
    format!(
        "resultant  {}\ndegree     {}\n",
        r.resultant.to_string_canonical(),
        r.degree
    )
}
