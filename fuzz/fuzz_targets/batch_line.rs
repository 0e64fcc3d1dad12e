//! Fuzz one line of `quadsect batch` (`batch::answer_line_within`, the
//! function the CLI, Python and C run on each line): any bytes must give
//! exactly one JSON answer object — `{"id", "ok": true, "result"}` or
//! `{"id", "ok": false, "error": {"kind", "message"}}` — never a panic,
//! and never a run past its compute budget of 0.5 s by more than 1 s (an
//! exhausted budget is an answer; a line's own `time_limit` can only make
//! it shorter); and the text answer (`answer_line_text_within`, what the
//! CLI writes) is the `Value` answer's bytes.
#![no_main]
use libfuzzer_sys::fuzz_target;
use quadsect::Budget;
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
    // as the CLI reads a line: invalid UTF-8 becomes U+FFFD
    let line = String::from_utf8_lossy(data);
    let budget = Budget::default().with_time_limit(Some(LIMIT));
    let (t0, c0) = (Instant::now(), cpu_time());
    let v = quadsect::batch::answer_line_within(&line, &budget);
    let (took, cpu) = (t0.elapsed(), cpu_time() - c0);
    assert!(
        took.min(cpu) <= LIMIT + SLACK,
        "took {took:?} ({cpu:?} of CPU time) with a budget of {LIMIT:?}"
    );
    // the text path (what the CLI, Python and C write) gives the same bytes,
    // unless one of the two runs ran out of its budget and the other not
    let text = quadsect::batch::answer_line_text_within(&line, &budget);
    let printed = v.to_string();
    if !printed.contains(r#""kind":"budget""#) && !text.contains(r#""kind":"budget""#) {
        assert_eq!(text, printed, "text and Value answers differ");
    }
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
