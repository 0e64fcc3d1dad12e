//! Fuzzing of the text inputs with proptest (the libFuzzer targets in
//! `fuzz/` need nightly): parsers and batch lines never panic, what parses
//! prints back to itself, and every input ends within a small compute
//! budget (an exhausted budget is an answer; a run past the budget by more
//! than a small constant is a finding).

use crate::budget::Budget;
use crate::number::parse_rational;
use crate::poly::parse_poly;
use proptest::prelude::*;
use serde_json::Value;
use std::time::{Duration, Instant};

/// The budget of each fuzzed input, and what it may overshoot.
const LIMIT: Duration = Duration::from_millis(500);
/// (Unoptimised builds are much slower between two checks.)
const SLACK: Duration = Duration::from_millis(if cfg!(debug_assertions) {
    15_000
} else {
    2_000
});

/// One batch line under the fuzzing budget; fails when it runs past it.
fn answer_line(line: &str) -> Value {
    let budget = Budget::default().with_time_limit(Some(LIMIT));
    let t0 = Instant::now();
    let v = crate::batch::answer_line_within(line, &budget);
    let took = t0.elapsed();
    assert!(
        took <= LIMIT + SLACK,
        "{line:?} took {took:?} with a budget of {LIMIT:?}"
    );
    v
}

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
            let budget = Budget::default().with_time_limit(Some(LIMIT));
            let t0 = Instant::now();
            let _ = crate::natural::classify_with(&q, &other, &crate::natural::ClassifyOptions::with_budget(budget));
            prop_assert!(t0.elapsed() <= LIMIT + SLACK, "{} took {:?}", text, t0.elapsed());
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

/// Inputs found by libFuzzer (`fuzz/`) that ran for seconds to minutes
/// before the budgets: each now answers within the fuzzing budget.
#[test]
fn fuzzer_slow_inputs_end_within_the_budget() {
    for line in [
        r#"{"op":"tangent","ellipsoid":"(x--2)^2/6+(y--5)^2/6+(z-0)^2/4-1","surface":"-9/4*4*y*y+5*yz+6/3*z*z+-12/2*xx+3*yz^126+8/5*z+6/3"}"#,
        r#"{"op":"tangent","ellipsoid":"x^2+y^2+z^2-1","surface":"x-5e-98709-90e-5083"}"#,
        r#"{"op":"roots","poly":"x^6667-3x^5000+7x^4000-x^3333+5x^2000-2x^1000+x^500-9x^100+x^50-3x^10+x-1"}"#,
    ] {
        let v = answer_line(line);
        assert!(v.get("ok").is_some(), "{v}");
    }
}

/// Found by libFuzzer (`fuzz/`, parse_poly: the first input ran 1.5 s
/// under a 0.5 s budget): a product of polynomials with large coefficients
/// read the clock every 64 rows, and ran up to 64 rows past its deadline
/// (`poly::mpoly` now reads it every row when rows are large).  The second
/// input needs minutes without a budget.
#[test]
fn fuzzer_slow_parses_end_within_the_budget() {
    for s in ["(9 + y/7/ 9)^416 -/8 \u{f}16 -^1", "(9 + y/7/9)^2000"] {
        let budget = Budget::default().with_time_limit(Some(LIMIT));
        let t0 = Instant::now();
        let r = crate::budget::run(&budget, || parse_poly(s).map(|p| p.len()));
        let took = t0.elapsed();
        assert!(took <= LIMIT + SLACK, "{s:?} took {took:?}");
        assert!(r.is_err() || !s.ends_with("2000"), "{s:?}: {r:?}");
    }
}

/// Found by libFuzzer (`fuzz/`, parse_poly: `(2^3)^77773 -0-1_…` ran
/// 1.2–1.6 s under a 0.5 s budget in the sanitizer build): one step of a
/// sum of huge integers is a gcd (num-bigint's binary gcd, quadratic in the
/// bits even against 1: about 0.15 s natively for 233 000 bits, five times
/// that under AddressSanitizer).  That is the budget's documented
/// granularity, one arithmetic operation, and not a missed check: the sum
/// reads the clock before each large step (`poly::ring`), so a run stops
/// after the step running at its deadline, not several steps later.
#[test]
fn a_sum_of_huge_integers_stops_a_step_after_its_deadline() {
    let one = "8^77773 - 1";
    let t0 = Instant::now();
    let _ = parse_poly(one).unwrap();
    let step = t0.elapsed();
    let six = [one; 6].join(" + ");
    let limit = Duration::from_millis(1);
    let t0 = Instant::now();
    let r = crate::budget::run(&Budget::default().with_time_limit(Some(limit)), || {
        parse_poly(&six).map(|p| p.len())
    });
    let took = t0.elapsed();
    assert!(r.is_err(), "six steps end after the deadline: {r:?}");
    assert!(
        took <= limit + 3 * step + Duration::from_millis(20),
        "{took:?} with a limit of {limit:?} and steps of {step:?}"
    );
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
