//! Fuzz one line of `quadsect batch`: any bytes must give exactly one JSON
//! answer object, never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let line = String::from_utf8_lossy(data);
    let v = quadsect::batch::answer_line(&line);
    assert!(v.get("ok").is_some());
});
