//! Fuzz the natural-quadric parser (short syntax and JSON) and, when two
//! quadrics parse, the classification under a small compute budget: never
//! a panic, never a run past the budget (plus a small constant).
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_millis(500);
const SLACK: Duration = Duration::from_millis(1000);

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let mut parts = s.splitn(2, '\n');
        let a = parts.next().unwrap_or("");
        let b = parts.next().unwrap_or("");
        if let (Ok(x), Ok(y)) = (
            quadsect::natural::parse_natural(a),
            quadsect::natural::parse_natural(b),
        ) {
            let budget = quadsect::budget::Budget::default().with_time_limit(Some(LIMIT));
            let t0 = Instant::now();
            let _ = quadsect::natural::classify_within(&x, &y, &budget);
            let took = t0.elapsed();
            assert!(took <= LIMIT + SLACK, "took {took:?} with a budget of {LIMIT:?}");
        }
    }
});
