//! Fuzz the natural-quadric parser (short syntax and JSON) and, when two
//! quadrics parse, the classification: never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let mut parts = s.splitn(2, '\n');
        let a = parts.next().unwrap_or("");
        let b = parts.next().unwrap_or("");
        if let (Ok(x), Ok(y)) = (
            quadsect::natural::parse_natural(a),
            quadsect::natural::parse_natural(b),
        ) {
            // keep the fuzzer fast: only small inputs are classified
            if a.len() < 80 && b.len() < 80 {
                let _ = quadsect::natural::classify(&x, &y);
            }
        }
    }
});
