//! Fuzz one line of `quadsect batch` (`batch::answer_line_within`, the
//! function the CLI, Python and C run on each line): any bytes must give
//! exactly one JSON answer object — `{"id", "ok": true, "result"}` or
//! `{"id", "ok": false, "error": {"kind", "message"}}` — never a panic,
//! and never a run past its compute budget of 0.5 s by more than 1 s (an
//! exhausted budget is an answer; a line's own `time_limit` can only make
//! it shorter).
#![no_main]
use libfuzzer_sys::fuzz_target;
use quadsect::Budget;
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_millis(500);
const SLACK: Duration = Duration::from_millis(1000);

fuzz_target!(|data: &[u8]| {
    // as the CLI reads a line: invalid UTF-8 becomes U+FFFD
    let line = String::from_utf8_lossy(data);
    let budget = Budget::default().with_time_limit(Some(LIMIT));
    let t0 = Instant::now();
    let v = quadsect::batch::answer_line_within(&line, &budget);
    let took = t0.elapsed();
    assert!(
        took <= LIMIT + SLACK,
        "took {took:?} with a budget of {LIMIT:?}"
    );
    let obj = v.as_object().expect("the answer is a JSON object");
    assert!(obj.contains_key("id"), "{v}");
    match obj.get("ok").and_then(|b| b.as_bool()) {
        Some(true) => assert!(obj.len() == 3 && obj.contains_key("result"), "{v}"),
        Some(false) => {
            assert!(obj.len() == 3, "{v}");
            assert!(
                v["error"]["kind"].is_string() && v["error"]["message"].is_string(),
                "{v}"
            );
        }
        None => panic!("no boolean \"ok\": {v}"),
    }
    // one line in, one line out: the answer prints without a newline
    assert!(!v.to_string().contains('\n'), "{v}");
});
