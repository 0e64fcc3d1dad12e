//! Fuzzing of the text inputs with proptest (the libFuzzer targets in
//! `fuzz/` need nightly): parsers and batch lines never panic, and what
//! parses prints back to itself.

use crate::batch::answer_line;
use crate::number::parse_rational;
use crate::poly::parse_poly;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, .. ProptestConfig::default() })]

    /// Arbitrary Unicode text: no panic; a successful parse round-trips.
    #[test]
    fn parse_poly_never_panics(s in "\\PC{0,60}") {
        let _ = parse_rational(&s);
        if let Ok(p) = parse_poly(&s) {
            prop_assert_eq!(parse_poly(&p.to_string_canonical()).unwrap(), p);
        }
    }

    /// Text built from the grammar's own alphabet reaches deep into the parser.
    #[test]
    fn parse_poly_grammar_alphabet(s in "[-+*/^() xyzu0-9.eE]{0,80}") {
        if let Ok(p) = parse_poly(&s) {
            prop_assert_eq!(parse_poly(&p.to_string_canonical()).unwrap(), p);
        }
    }

    /// Any batch line gives exactly one answer object with `ok`.
    #[test]
    fn batch_line_always_answers(s in "\\PC{0,80}") {
        let v = answer_line(&s);
        prop_assert!(v.get("ok").and_then(|b| b.as_bool()).is_some());
    }

    /// The natural-quadric parser never panics on arbitrary text.
    #[test]
    fn natural_parser_never_panics(s in "\\PC{0,60}") {
        let _ = crate::natural::parse_natural(&s);
    }

    /// Text close to the short syntax reaches deep into the parser, and
    /// whatever parses can be classified (against a fixed partner).
    #[test]
    fn natural_syntax_alphabet(kind in "(sphere|cylinder|cone|torus)", k1 in "(center|point|vertex|axis|radius2|tan2|tan|cos2|sin2|foo)",
                               v1 in "[-0-9/.,e]{0,12}", k2 in "(axis|radius2|tan2|cos2)", v2 in "[-0-9/.,]{0,10}") {
        let text = format!("{kind} {k1}={v1} {k2}={v2}");
        if let Ok(q) = crate::natural::parse_natural(&text) {
            let other = crate::natural::parse_natural("cylinder point=0,0,0 axis=1,0,0 radius2=1").unwrap();
            let _ = crate::natural::classify(&q, &other);
        }
    }

    /// Well-formed JSON with random fields still answers.
    #[test]
    fn batch_json_fields(op in "(roots|resultant|tangent|natural|bogus)", a in "[-+*/^() xyzu0-9]{0,20}", b in "[-+*/^() xyzu0-9]{0,20}") {
        let line = serde_json::json!({"id": 1, "op": op, "poly": a, "f": a, "g": b, "var": "x",
            "ellipsoid": a, "surface": b, "a": a, "b": b}).to_string();
        let v = answer_line(&line);
        prop_assert_eq!(v.get("id").cloned(), Some(serde_json::json!(1)));
    }
}

/// Inputs found by libFuzzer (`fuzz/`): huge constants must either be
/// rejected with a size-limit error or print to text that parses back.
#[test]
fn fuzzer_regressions_round_trip() {
    for s in [
        "558^85887",
        "85^54820",
        "1e100000",
        "9e99999",
        "(10^99000)*(10^99000)",
        "1/10^99999",
    ] {
        if let Ok(p) = parse_poly(s) {
            assert_eq!(parse_poly(&p.to_string_canonical()).unwrap(), p, "{s}");
        }
    }
}
