//! Fuzz the expression and number parsers: they must never panic, a
//! successful parse must print to a string that parses back to the same
//! polynomial, and parsing must end within a small compute budget (plus a
//! small constant).
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_millis(500);
const SLACK: Duration = Duration::from_millis(1000);

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let budget = quadsect::budget::Budget::default().with_time_limit(Some(LIMIT));
        let t0 = Instant::now();
        let r = quadsect::budget::run(&budget, || {
            let _ = quadsect::number::parse_rational(s);
            quadsect::poly::parse_poly(s).map(|p| (p.to_string_canonical(), p))
        });
        let took = t0.elapsed();
        assert!(took <= LIMIT + SLACK, "took {took:?} with a budget of {LIMIT:?}");
        if let Ok(Ok((printed, p))) = r {
            let back = quadsect::poly::parse_poly(&printed).expect("printed polynomial must parse");
            assert_eq!(back, p);
        }
    }
});
