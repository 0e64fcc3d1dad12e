//! `quadsect examples`: the papers' examples recomputed exactly, side by
//! side with what the papers printed, with every discrepancy flagged.

use serde_json::{Value, json};

pub mod natural;
pub mod tangent;

/// One reproduced example.
#[derive(Clone, Debug)]
pub struct ExampleResult {
    /// Where it comes from (`paper 004, Example 1`, `kernel`, …).
    pub source: String,
    /// Short title.
    pub title: String,
    /// The equivalent command line.
    pub command: String,
    /// Our exact answer, for people.
    pub ours: String,
    /// Our answer as JSON (the `--json` output of the command).
    pub ours_json: Value,
    /// What the paper printed (empty when the example is ours).
    pub paper: String,
    /// Discrepancies between the paper and the exact answer.
    pub discrepancies: Vec<String>,
    /// The answer's picture (SVG), for the examples of the papers.
    pub figure: Option<String>,
}

/// The figures of the examples that have one, each with a file name made
/// of its source and title (`paper-004-example-1`, …).
pub fn figures(r: &[ExampleResult]) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for e in r {
        let Some(svg) = &e.figure else { continue };
        let mut name = String::new();
        for c in format!("{} {}", e.source, e.title).chars() {
            if c.is_ascii_alphanumeric() {
                name.push(c.to_ascii_lowercase());
            } else if !name.ends_with('-') {
                name.push('-');
            }
        }
        let mut name = name.trim_matches('-').chars().take(60).collect::<String>();
        name = name.trim_end_matches('-').to_string();
        // distinct names
        let base = name.clone();
        let mut k = 2;
        while out.iter().any(|(n, _)| *n == name) {
            name = format!("{base}-{k}");
            k += 1;
        }
        out.push((name, svg.clone()));
    }
    out
}

fn kernel_examples() -> Vec<ExampleResult> {
    let mut out = Vec::new();
    for (expr, title) in [
        (
            "x^3 - 2x",
            "three simple roots: one negative, one positive, one at 0",
        ),
        (
            "(x^2-2)^3 (x-1/3)",
            "multiple roots: ±√2 with multiplicity 3 and 1/3",
        ),
    ] {
        if let Ok(r) = crate::kernel::roots_str(expr) {
            out.push(ExampleResult {
                source: "kernel".into(),
                title: title.into(),
                command: format!("quadsect roots \"{expr}\""),
                ours: crate::report::roots_human(&r),
                ours_json: crate::report::roots_json(&r),
                paper: String::new(),
                discrepancies: vec![],
                figure: None,
            });
        }
    }
    out
}

/// Runs every example.
pub fn run_all() -> Vec<ExampleResult> {
    let mut out = kernel_examples();
    out.extend(tangent::paper_examples());
    out.extend(natural::natural_examples());
    out
}

/// All examples as one JSON array.
pub fn to_json(r: &[ExampleResult]) -> Value {
    Value::Array(
        r.iter()
            .map(|e| {
                json!({
                    "source": e.source,
                    "title": e.title,
                    "command": e.command,
                    "ours": e.ours_json,
                    "paper": e.paper,
                    "discrepancies": e.discrepancies,
                })
            })
            .collect(),
    )
}

/// All examples for people.
pub fn to_human(r: &[ExampleResult]) -> String {
    let mut s = String::new();
    for e in r {
        s.push_str(&format!(
            "=== {} — {}\n$ {}\n",
            e.source, e.title, e.command
        ));
        s.push_str(&indent(&e.ours));
        if !e.paper.is_empty() {
            s.push_str("  paper printed:\n");
            s.push_str(&indent(&indent(&e.paper)));
        }
        if e.discrepancies.is_empty() {
            if !e.paper.is_empty() {
                s.push_str("  agrees with the paper\n");
            }
        } else {
            for d in &e.discrepancies {
                s.push_str(&format!("  !! {d}\n"));
            }
        }
        s.push('\n');
    }
    s
}

fn indent(t: &str) -> String {
    t.lines().map(|l| format!("  {l}\n")).collect()
}
