//! `quadsect batch`: JSON lines in, JSON lines out, one answer per input
//! line, in order.  Lines are processed in parallel (rayon) in chunks; a bad
//! line (or even an internal failure) yields an error line and the batch
//! goes on.

use crate::error::{Error, ErrorKind};
use serde_json::{Map, Value, json};
#[cfg(feature = "cli")]
use std::io::{BufRead, Write};

/// Lines processed together (in parallel) before their answers are written.
pub const CHUNK: usize = 2048;

/// Runs one operation given as a JSON object (`op` and its arguments) and
/// returns the same JSON as the CLI's `--json`, under the default budget.
pub fn run_op(obj: &Map<String, Value>) -> Result<Value, Error> {
    let request = crate::request::Request::from_json(obj)?;
    Ok(request
        .execute(&crate::budget::Budget::default())?
        .to_json())
}

/// Answers one input line (never panics: an internal failure becomes an
/// error line).
pub fn answer_line(line: &str) -> Value {
    let parsed: Result<Value, _> = serde_json::from_str(line);
    let (id, result) = match parsed {
        Err(e) => (
            Value::Null,
            Err(Error::new(
                ErrorKind::Json,
                if line.trim().is_empty() {
                    "empty line (expected a JSON object)".to_string()
                } else {
                    format!("invalid JSON: {e}")
                },
            )),
        ),
        Ok(Value::Object(obj)) => {
            let id = obj.get("id").cloned().unwrap_or(Value::Null);
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_op(&obj)))
                .unwrap_or_else(|p| Err(Error::internal(panic_message(&p))));
            (id, r)
        }
        Ok(_) => (
            Value::Null,
            Err(Error::new(
                ErrorKind::Json,
                "each line must be a JSON object",
            )),
        ),
    };
    match result {
        Ok(v) => json!({"id": id, "ok": true, "result": v}),
        Err(e) => {
            json!({"id": id, "ok": false, "error": {"kind": e.kind().as_str(), "message": e.message()}})
        }
    }
}

/// Best-effort text of a panic payload.
pub fn panic_message(p: &Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

#[cfg(feature = "cli")]
/// Reads JSON lines from `input` and writes one answer line per input line
/// to `out`, in order, processing chunks in parallel.  `progress` shows a
/// spinner with the count of lines on stderr.  Returns the number of lines.
pub fn run_batch(
    input: impl BufRead,
    mut out: impl Write,
    progress: bool,
) -> std::io::Result<usize> {
    use rayon::prelude::*;
    let bar = if progress {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {pos} lines  {per_sec}  {elapsed}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
        );
        Some(b)
    } else {
        None
    };
    let mut input = input;
    let mut total = 0;
    let mut buf = Vec::new();
    loop {
        let mut chunk = Vec::with_capacity(CHUNK);
        while chunk.len() < CHUNK {
            buf.clear();
            if input.read_until(b'\n', &mut buf)? == 0 {
                break;
            }
            if buf.last() == Some(&b'\n') {
                buf.pop();
                if buf.last() == Some(&b'\r') {
                    buf.pop();
                }
            }
            // invalid UTF-8 becomes U+FFFD and then a JSON error line: never lost
            chunk.push(String::from_utf8_lossy(&buf).into_owned());
        }
        if chunk.is_empty() {
            break;
        }
        let answers: Vec<String> = chunk
            .par_iter()
            .map(|l| answer_line(l).to_string())
            .collect();
        for a in &answers {
            writeln!(out, "{a}")?;
        }
        out.flush()?;
        total += chunk.len();
        if let Some(b) = &bar {
            b.set_position(total as u64);
        }
        if chunk.len() < CHUNK {
            break;
        }
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    Ok(total)
}
