//! Human-readable text of the kernel operations (`roots`, `resultant`) and of real
//! algebraic numbers.

use crate::kernel::{ResultantReport, RootsReport};
use crate::number::fmt_q;

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
pub fn roots_human(r: &RootsReport) -> String {
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
            let approx = x.value().approx(20);
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

/// `quadsect resultant` for people.
pub fn resultant_human(r: &ResultantReport) -> String {
    format!(
        "resultant  {}\ndegree     {}\n",
        r.resultant.to_string_canonical(),
        r.degree
    )
}

impl std::fmt::Display for RootsReport {
    /// The human summary (as `quadsect roots` prints it).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&roots_human(self))
    }
}

impl std::fmt::Display for ResultantReport {
    /// The human form (as `quadsect resultant` prints it).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&resultant_human(self))
    }
}
