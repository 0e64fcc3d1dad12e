//! Fuzz one line of `quadsect batch`: any bytes must give exactly one JSON
//! answer object, never a panic, and never a run past its compute budget
//! (an exhausted budget is fine; overshooting it by more than a small
//! constant is a finding).
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_millis(500);
const SLACK: Duration = Duration::from_millis(1000);

fuzz_target!(|data: &[u8]| {
    let line = String::from_utf8_lossy(data);
    let budget = quadsect::budget::Budget::default().with_time_limit(Some(LIMIT));
    let t0 = Instant::now();
    let v = quadsect::batch::answer_line_within(&line, &budget);
    let took = t0.elapsed();
    assert!(v.get("ok").is_some());
    assert!(took <= LIMIT + SLACK, "took {took:?} with a budget of {LIMIT:?}");
});
