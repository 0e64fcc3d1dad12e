//! Fuzz the expression and number parsers through the public API
//! (`str::parse::<Polynomial>`, `Polynomial::parse_in`, `parse_rational`,
//! `parse_rational_in`, `str::parse::<IntPoly>`): they must never panic,
//! a polynomial that parses must print (`Display`, the canonical form) to
//! text that parses back to the same polynomial, and parsing must end
//! within a compute budget of 0.5 s (plus 1 s of slack).
#![no_main]
use libfuzzer_sys::fuzz_target;
use quadsect::{Budget, IntPoly, NumberMode, Polynomial, budget};
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

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let budget = Budget::default().with_time_limit(Some(LIMIT));
        let (t0, c0) = (Instant::now(), cpu_time());
        let r = budget::run(&budget, || {
            let _ = quadsect::parse_rational(s);
            let _ = quadsect::parse_rational_in(s, NumberMode::Float);
            let _ = Polynomial::parse_in(s, NumberMode::Float);
            let _ = s.parse::<IntPoly>();
            s.parse::<Polynomial>().map(|p| (p.to_string(), p))
        });
        let (took, cpu) = (t0.elapsed(), cpu_time() - c0);
        assert!(
            took.min(cpu) <= LIMIT + SLACK,
            "took {took:?} ({cpu:?} of CPU time) with a budget of {LIMIT:?}"
        );
        if let Ok(Ok((printed, p))) = r {
            let back: Polynomial = printed
                .parse()
                .unwrap_or_else(|e| panic!("printed polynomial {printed:?} does not parse: {e}"));
            assert_eq!(back, p, "{printed:?}");
        }
    }
});
