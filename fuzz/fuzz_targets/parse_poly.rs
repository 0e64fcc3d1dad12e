//! Fuzz the expression and number parsers: they must never panic, and a
//! successful parse must print to a string that parses back to the same
//! polynomial.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let _ = quadsect::number::parse_rational(s);
        if let Ok(p) = quadsect::poly::parse_poly(s) {
            let printed = p.to_string_canonical();
            let back = quadsect::poly::parse_poly(&printed).expect("printed polynomial must parse");
            assert_eq!(back, p);
        }
    }
});
