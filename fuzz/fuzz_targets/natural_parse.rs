//! Fuzz the natural-quadric parser (short syntax and JSON, through the
//! public `str::parse::<Natural>` and `Natural::parse_in`) and, when two
//! quadrics parse, their classification under a compute budget of 0.5 s
//! (`quadsect::classify_with`): never a panic, never a run past the budget
//! by more than 1 s, and a quadric that parses prints (`to_short`) to text
//! that parses back to the same quadric.
//!
//! Input: the two quadrics' texts separated by the first newline.
#![no_main]
use libfuzzer_sys::fuzz_target;
use quadsect::{Budget, ClassifyOptions, Natural, NumberMode};
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_millis(500);
const SLACK: Duration = Duration::from_millis(1000);

/// The CPU time of this process so far.  An input overshoots its budget
/// only when both the wall time and the CPU time it took are past
/// `LIMIT + SLACK`: on a loaded machine the fuzzer (run at `nice 19`) may
/// wait seconds for a core, which is no finding.
fn cpu_time() -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec to write to
    unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

/// Parses one quadric (both number modes) and checks its round trip.
fn parse(text: &str) -> Option<Natural> {
    let _ = Natural::parse_in(text, NumberMode::Float);
    let q: Natural = text.parse().ok()?;
    let short = q.to_short();
    let back: Natural = short
        .parse()
        .unwrap_or_else(|e| panic!("printed quadric {short:?} does not parse: {e}"));
    assert_eq!(back, q, "{short:?}");
    Some(q)
}

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let (a, b) = s.split_once('\n').unwrap_or((s, ""));
        if let (Some(x), Some(y)) = (parse(a), parse(b)) {
            let budget = Budget::default().with_time_limit(Some(LIMIT));
            let mut options = ClassifyOptions::with_budget(budget);
            // the last byte picks the route: full components or the fast counts
            options.components = data.last().is_none_or(|b| b & 1 == 0);
            let (t0, c0) = (Instant::now(), cpu_time());
            let _ = quadsect::classify_with(&x, &y, &options);
            let (took, cpu) = (t0.elapsed(), cpu_time() - c0);
            assert!(
                took.min(cpu) <= LIMIT + SLACK,
                "took {took:?} ({cpu:?} of CPU time) with a budget of {LIMIT:?}"
            );
        }
    }
});
