//! `quadsect batch`: JSON lines in, JSON lines out, one answer per input
//! line, in order.  Lines are processed in parallel (rayon) in chunks; a bad
//! line (or even an internal failure) yields an error line and the batch
//! goes on.

use crate::error::{Error, ErrorKind};
use serde_json::{Map, Value, json};
use std::io::{BufRead, Write};

/// Lines processed together (in parallel) before their answers are written.
pub const CHUNK: usize = 2048;

fn field<'a>(obj: &'a Map<String, Value>, name: &str) -> Result<&'a Value, Error> {
    obj.get(name)
        .ok_or_else(|| Error::new(ErrorKind::MissingField, format!("missing field \"{name}\"")))
}

fn str_field<'a>(obj: &'a Map<String, Value>, name: &str) -> Result<&'a str, Error> {
    field(obj, name)?.as_str().ok_or_else(|| {
        Error::new(
            ErrorKind::BadField,
            format!("field \"{name}\" must be a string"),
        )
    })
}

/// An optional boolean field.
fn bool_field(obj: &Map<String, Value>, name: &str, default: bool) -> Result<bool, Error> {
    match obj.get(name) {
        None => Ok(default),
        Some(Value::Bool(b)) => Ok(*b),
        Some(_) => Err(Error::new(
            ErrorKind::BadField,
            format!("field \"{name}\" must be true or false"),
        )),
    }
}

/// The number mode of an op: `"float": true` reads literals as doubles.
fn number_mode(obj: &Map<String, Value>) -> Result<crate::number::NumberMode, Error> {
    Ok(if bool_field(obj, "float", false)? {
        crate::number::NumberMode::Float
    } else {
        crate::number::NumberMode::Exact
    })
}

/// Runs one operation given as a JSON object (`op` and its arguments) and
/// returns the same JSON as the CLI's `--json`.
pub fn run_op(obj: &Map<String, Value>) -> Result<Value, Error> {
    let op = str_field(obj, "op")?;
    match op {
        "roots" => {
            let r = crate::ops::roots(str_field(obj, "poly")?)?;
            Ok(crate::report::roots_json(&r))
        }
        "resultant" => {
            let r = crate::ops::resultant(
                str_field(obj, "f")?,
                str_field(obj, "g")?,
                str_field(obj, "var")?,
            )?;
            Ok(crate::report::resultant_json(&r))
        }
        "tangent" => {
            let r = crate::tangent::decide_str_in(
                str_field(obj, "ellipsoid")?,
                str_field(obj, "surface")?,
                number_mode(obj)?,
            )?;
            Ok(crate::report::tangent_json(&r))
        }
        "natural" => {
            let mode = number_mode(obj)?;
            let q = |name: &str| -> Result<crate::natural::Natural, Error> {
                let v = field(obj, name)?;
                match v {
                    Value::String(s) => crate::natural::types::parse_natural_in(s, mode),
                    other => crate::natural::types::from_json_in(other, mode),
                }
                .map_err(|e| e.context(&format!("in \"{name}\"")))
            };
            if !bool_field(obj, "components", true)? {
                let opts = crate::natural::ClassifyOptions { components: false };
                let r = crate::natural::classify_with(&q("a")?, &q("b")?, &opts)?;
                return Ok(crate::report::natural_counts_json(&r));
            }
            let r = crate::natural::classify(&q("a")?, &q("b")?)?;
            Ok(crate::report::natural_json(&r))
        }
        other => Err(Error::new(
            ErrorKind::UnknownOp,
            format!("unknown op \"{other}\" (expected tangent, natural, roots or resultant)"),
        )),
    }
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
