//! Fuzzing of the text inputs with proptest: the properties of the three
//! libFuzzer targets in `fuzz/` (which need nightly), run by `cargo test`.
//!
//! * `parse_poly`: the expression and number parsers never panic, what
//!   parses prints back to itself, and parsing ends within its budget.
//! * `natural_parse`: the natural-quadric parsers (short syntax and JSON)
//!   never panic, what parses prints back (`to_short`) to itself, and two
//!   parsed quadrics classify (both routes) within the budget.
//! * `batch_line`: any bytes on a batch line give exactly one JSON answer
//!   object within the budget; the line's own limits and unknown fields
//!   give the documented answers.
//!
//! Every input runs under a compute budget: an exhausted budget is an
//! answer; a run past the budget by more than a small constant is a
//! finding.

use crate::budget::Budget;
use crate::natural::{ClassifyOptions, Natural};
use crate::number::{NumberMode, Q, parse_rational};
use crate::poly::parse_poly;
use crate::{IntPoly, Polynomial};
use num_bigint::BigInt;
use proptest::prelude::*;
use serde_json::{Value, json};
use std::time::{Duration, Instant};

/// The budget of each fuzzed input, and what it may overshoot.
const LIMIT: Duration = Duration::from_millis(500);
/// (Unoptimised builds are much slower between two checks.)
const SLACK: Duration = Duration::from_millis(if cfg!(debug_assertions) {
    15_000
} else {
    2_000
});

/// One batch line under the fuzzing budget; fails when it runs past it or
/// when the answer is not exactly one answer object (`batch_line`).
fn answer_line(line: &str) -> Value {
    let budget = Budget::default().with_time_limit(Some(LIMIT));
    let t0 = Instant::now();
    let v = crate::batch::answer_line_within(line, &budget);
    let took = t0.elapsed();
    assert!(
        took <= LIMIT + SLACK,
        "{line:?} took {took:?} with a budget of {LIMIT:?}"
    );
    // the text path (what the CLI, Python and C write) gives the same bytes,
    // unless one of the two runs ran out of its budget and the other not
    let text = crate::batch::answer_line_text_within(line, &budget);
    let printed = v.to_string();
    if !printed.contains(r#""kind":"budget""#) && !text.contains(r#""kind":"budget""#) {
        assert_eq!(text, printed, "{line:?}: text and Value answers differ");
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
    assert!(!v.to_string().contains('\n'), "{v}");
    v
}

/// Every parser of `parse_poly` on `s` under the fuzzing budget: no panic,
/// no run past the budget, and a polynomial that parses prints to text
/// that parses back to it.
fn parse_everything(s: &str) {
    let budget = Budget::default().with_time_limit(Some(LIMIT));
    let t0 = Instant::now();
    let r = crate::budget::run(&budget, || {
        let _ = parse_rational(s);
        let _ = crate::parse_rational_in(s, NumberMode::Float);
        let _ = Polynomial::parse_in(s, NumberMode::Float);
        let _ = s.parse::<IntPoly>();
        s.parse::<Polynomial>().map(|p| (p.to_string(), p))
    });
    let took = t0.elapsed();
    assert!(took <= LIMIT + SLACK, "{s:?} took {took:?}");
    if let Ok(Ok((printed, p))) = r {
        let back: Polynomial = printed
            .parse()
            .unwrap_or_else(|e| panic!("{s:?} printed as {printed:?}, which does not parse: {e}"));
        assert_eq!(back, p, "{s:?} printed as {printed:?}");
    }
}

/// A natural quadric's text parsed as `natural_parse` does (both number
/// modes); one that parses prints (`to_short`) to text that parses back.
fn parse_natural(text: &str) -> Option<Natural> {
    let _ = Natural::parse_in(text, NumberMode::Float);
    let q: Natural = text.parse().ok()?;
    let short = q.to_short();
    let back: Natural = short
        .parse()
        .unwrap_or_else(|e| panic!("{text:?} printed as {short:?}, which does not parse: {e}"));
    assert_eq!(back, q, "{text:?} printed as {short:?}");
    Some(q)
}

/// Two quadrics classified under the fuzzing budget, by the full or the
/// fast route: never past the budget.
fn classify_within_budget(a: &Natural, b: &Natural, components: bool) {
    let mut options = ClassifyOptions::with_budget(Budget::default().with_time_limit(Some(LIMIT)));
    options.components = components;
    let t0 = Instant::now();
    let _ = crate::natural::classify_with(a, b, &options);
    let took = t0.elapsed();
    assert!(took <= LIMIT + SLACK, "{a:?} and {b:?} took {took:?}");
}

/// A number as the inputs write them: integers, fractions, decimals,
/// scientific and hexadecimal floats, and now and then nonsense.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => (-4i32..5).prop_map(|n| n.to_string()),
        6 => (-9i32..10, 1u32..5).prop_map(|(n, d)| format!("{n}/{d}")),
        4 => "-?[0-9]\\.[0-9]{1,3}(e-?[0-9])?",
        1 => Just("0x1.8p-1".to_string()),
        1 => "[-0-9/.e]{0,6}",
    ]
}

/// A number for a squared radius or an angle: mostly positive (and in
/// (0, 1), as cos2 and sin2 need), at times anything (zero, negative,
/// nonsense).
fn positive() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => "1/[2-9]",
        3 => (1u32..10, 1u32..5).prop_map(|(n, d)| format!("{n}/{d}")),
        1 => "0\\.[0-9]{1,3}",
        1 => number(),
    ]
}

fn triple() -> impl Strategy<Value = [String; 3]> {
    [number(), number(), number()]
}

/// A natural quadric in the short syntax or as JSON text, mostly valid
/// (every kind and angle parameter), sometimes with a bad value.
fn quadric_text() -> impl Strategy<Value = String> {
    let short = |v: &[String; 3]| v.join(",");
    let json = |v: &[String; 3]| json!(v).to_string();
    prop_oneof![
        (triple(), positive(), any::<bool>()).prop_map(move |(c, r, j)| if j {
            format!(
                r#"{{"kind":"sphere","center":{},"radius2":"{r}"}}"#,
                json(&c)
            )
        } else {
            format!("sphere center={} radius2={r}", short(&c))
        }),
        (triple(), triple(), positive(), any::<bool>()).prop_map(move |(p, a, r, j)| if j {
            format!(
                r#"{{"kind":"cylinder","point":{},"axis":{},"radius2":"{r}"}}"#,
                json(&p),
                json(&a)
            )
        } else {
            format!(
                "cylinder point={} axis={} radius2={r}",
                short(&p),
                short(&a)
            )
        }),
        (
            triple(),
            triple(),
            "(tan2|tan|cos2|sin2)",
            positive(),
            any::<bool>()
        )
            .prop_map(move |(v, a, k, t, j)| if j {
                format!(
                    r#"{{"kind":"cone","vertex":{},"axis":{},"{k}":"{t}"}}"#,
                    json(&v),
                    json(&a)
                )
            } else {
                format!("cone vertex={} axis={} {k}={t}", short(&v), short(&a))
            }),
    ]
}

/// The generator of [`natural_pairs_classify_within_the_budget`] reaches
/// the classification: most pairs parse (else the property tests little).
#[test]
fn most_generated_quadric_pairs_parse() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let pair = (quadric_text(), quadric_text());
    let parsed = (0..400)
        .filter(|_| {
            let (a, b) = pair.new_tree(&mut runner).unwrap().current();
            a.parse::<Natural>().is_ok() && b.parse::<Natural>().is_ok()
        })
        .count();
    assert!(parsed >= 160, "{parsed} of 400 pairs parse");
}

/// A value of a batch line's `time_limit` or `memory_limit`, valid or not.
fn limit_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(Value::Null),
        Just(json!("none")),
        Just(json!("NONE")),
        (0.0f64..2.0).prop_map(Value::from),
        (0u32..3).prop_map(Value::from),
        (-2.0f64..-1e-9).prop_map(Value::from),
        Just(json!(-1)),
        Just(json!("NaN")),
        Just(json!("0.5")),
        Just(json!(true)),
        Just(json!([1])),
        Just(json!({"s": 1})),
        "[a-z0-9.]{0,4}".prop_map(Value::from),
    ]
}

/// Whether a batch line may have this limit value (contract §5).
fn valid_limit(v: &Value) -> bool {
    match v {
        Value::Null => true,
        Value::String(s) => s.trim().eq_ignore_ascii_case("none"),
        Value::Number(n) => n.as_f64().is_some_and(|x| x >= 0.0),
        _ => false,
    }
}

/// A JSON value where a pose expects a number: mostly numbers, sometimes
/// exact strings, garbage, zeros, negatives, huge and tiny values.
fn pose_number() -> impl Strategy<Value = Value> {
    prop_oneof![
        4 => (-3.0f64..3.0).prop_map(|x| json!(x)),
        1 => prop_oneof![Just(0.0), Just(-1.0), Just(1e300), Just(1e-300), Just(5e-324)].prop_map(|x| json!(x)),
        1 => "-?[0-9]{1,3}(/[0-9]{1,3})?".prop_map(|s| json!(s)),
        1 => "\\PC{0,6}".prop_map(|s| json!(s)),
        1 => Just(json!(null)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Ellipsoid-contact lines with poses of random (often bad) numbers:
    /// one answer each — a contact with a certificate, or an input error
    /// naming the field — never a panic or an internal error.
    #[test]
    fn contact_pose_lines_answer(nums in proptest::collection::vec(pose_number(), 30), short in any::<bool>()) {
        let pose = |k: usize| {
            let v = |i: usize| nums[k * 15 + i].clone();
            let rows: Vec<Value> = (0..3).map(|r| json!([v(6 + 3 * r), v(7 + 3 * r), v(8 + 3 * r)])).collect();
            let centre = if short { json!([v(0), v(1)]) } else { json!([v(0), v(1), v(2)]) };
            json!({"center": centre, "semi_axes": [v(3), v(4), v(5)], "rotation": rows})
        };
        let line = json!({"id": 1, "op": "ellipsoid-contact", "a": pose(0), "b": pose(1)});
        let v = answer_line(&line.to_string());
        let kind = v["error"]["kind"].as_str().unwrap_or("");
        prop_assert!(kind != "internal", "{}", v);
        if v["ok"] == json!(true) {
            let c = v["result"]["contact"].as_str().unwrap_or("");
            prop_assert!(["separated", "touching", "overlapping"].contains(&c), "{}", v);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, .. ProptestConfig::default() })]

    /// `parse_poly` on arbitrary Unicode text.
    #[test]
    fn parse_poly_never_panics(s in "\\PC{0,60}") {
        parse_everything(&s);
    }

    /// `parse_poly` on text built from the grammar's own alphabet, which
    /// reaches deep into the parser (powers, products, long numbers).
    #[test]
    fn parse_poly_grammar_alphabet(s in "[-+*/^() xyzu0-9.eE]{0,80}") {
        parse_everything(&s);
    }

    /// `batch_line` on arbitrary text and on arbitrary bytes (read as the
    /// CLI reads a line: invalid UTF-8 becomes U+FFFD).
    #[test]
    fn batch_line_always_answers(s in "\\PC{0,80}", bytes in proptest::collection::vec(any::<u8>(), 0..80)) {
        answer_line(&s);
        answer_line(&String::from_utf8_lossy(&bytes));
    }

    /// `natural_parse` on arbitrary text.
    #[test]
    fn natural_parser_never_panics(s in "\\PC{0,60}") {
        let _ = parse_natural(&s);
    }

    /// Text close to the short syntax reaches deep into the parser, and
    /// whatever parses can be classified (against a fixed partner).
    #[test]
    fn natural_syntax_alphabet(kind in "(sphere|cylinder|cone|torus)", k1 in "(center|point|vertex|axis|radius2|tan2|tan|cos2|sin2|foo)",
                               v1 in "[-0-9/.,e]{0,12}", k2 in "(axis|radius2|tan2|cos2)", v2 in "[-0-9/.,]{0,10}") {
        let text = format!("{kind} {k1}={v1} {k2}={v2}");
        if let Some(q) = parse_natural(&text) {
            let other = parse_natural("cylinder point=0,0,0 axis=1,0,0 radius2=1").unwrap();
            classify_within_budget(&q, &other, true);
        }
    }

    /// Well-formed lines of every op with random text in their fields,
    /// random limits and now and then a stray field: the documented answer
    /// (unknown op, unknown field, bad limit, or the op's own answer).
    #[test]
    fn batch_json_fields(op in "(roots|resultant|tangent|natural|ellipsoid-contact|bogus)",
                         text in proptest::collection::vec("[-+*/^() xyzu0-9]{0,20}", 3),
                         flag in any::<bool>(),
                         time in proptest::option::of(limit_value()),
                         memory in proptest::option::of(limit_value()),
                         stray in proptest::option::of("[a-z_]{1,10}")) {
        let mut line = serde_json::Map::new();
        line.insert("id".into(), json!(1));
        line.insert("op".into(), json!(op));
        let fields = crate::request::OPS.iter().find(|(n, _)| *n == op).map_or(&[][..], |(_, f)| *f);
        for (i, f) in fields.iter().enumerate() {
            let v = match *f {
                "values" | "components" | "float" | "svg" => json!(flag),
                "var" => json!(["x", "y", "w"][i % 3]),
                _ => json!(text[i % text.len()]),
            };
            line.insert((*f).into(), v);
        }
        if let Some(t) = &time {
            line.insert("time_limit".into(), t.clone());
        }
        if let Some(m) = &memory {
            line.insert("memory_limit".into(), m.clone());
        }
        let known = |k: &str| ["id", "op", "time_limit", "memory_limit"].contains(&k) || fields.contains(&k);
        let stray = stray.filter(|k| !known(k));
        if let Some(k) = &stray {
            line.insert(k.clone(), json!(1));
        }
        let v = answer_line(&Value::Object(line).to_string());
        prop_assert_eq!(&v["id"], &json!(1));
        let kind = v["error"]["kind"].as_str().unwrap_or("");
        let message = v["error"]["message"].as_str().unwrap_or("");
        let bad = |l: &Option<Value>| l.as_ref().is_some_and(|x| !valid_limit(x));
        if op == "bogus" {
            prop_assert_eq!(kind, "unknown-op");
        } else if let Some(k) = &stray {
            prop_assert_eq!(kind, "bad-field");
            prop_assert!(message.starts_with(&format!("unknown field \"{k}\"")), "{}", message);
        } else if bad(&time) || bad(&memory) {
            let name = if bad(&time) { "time_limit" } else { "memory_limit" };
            prop_assert_eq!(kind, "bad-field");
            prop_assert!(message.starts_with(&format!("field \"{name}\"")), "{}", message);
        } else {
            prop_assert!(kind != "bad-field" && kind != "unknown-op", "{}", v);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, .. ProptestConfig::default() })]

    /// `natural_parse` on pairs of mostly valid quadrics of every kind, in
    /// both syntaxes: they print back to themselves and classify within
    /// the budget by both routes.
    #[test]
    fn natural_pairs_classify_within_the_budget(a in quadric_text(), b in quadric_text(), components in any::<bool>()) {
        if let (Some(x), Some(y)) = (parse_natural(&a), parse_natural(&b)) {
            classify_within_budget(&x, &y, components);
        }
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

/// Found by libFuzzer (`fuzz/`, batch_line): a tangent surface of degree
/// 788 reached the Poisson route, whose F4 monomials pack exponents and
/// degree in bytes: `zmpoly_mod` built monomials that overflowed their
/// fields (an overflow panic in `f4::rank` with debug assertions; in a
/// release build, silently other monomials).  `SquareSystem::new` now
/// declines degrees beyond `f4::MAX_DEGREE`, and `zmpoly_mod` panics
/// instead of packing a degree of 128 or more.
#[test]
fn fuzzer_tangent_of_degree_beyond_f4_answers() {
    let line = r#"{"id":3,"op":"tangent","ellipsoid":"x^2+y^2+z^2-25","surface":"(x-9)^1/8+y^788+z^2/-16-1"}"#;
    let v = answer_line(line);
    assert_eq!(v["id"], json!(3), "{v}");
    let deg = |d: &str| crate::poly::parse_poly(d).unwrap().to_primitive_z().0;
    let sys = crate::system::square_resultant::SquareSystem::new([
        deg("x^121 - 1"),
        deg("y - 1"),
        deg("z - 1"),
    ]);
    assert!(sys.is_none(), "degree 121 is beyond F4");
    let sys = crate::system::square_resultant::SquareSystem::new([
        deg("x^120 - 1"),
        deg("y - 1"),
        deg("z - 1"),
    ]);
    assert!(sys.is_some(), "degree 120 is within F4");
}

/// Found by libFuzzer (`fuzz/`, natural_parse, on the merge of main at
/// 4b51eda: 1.7 s, 1.5 s of CPU, under a 0.5 s budget in the sanitizer
/// build): two cones, one of half-angle ~10^-415, took 0.1 s natively in
/// `curve::zf_ball`'s loop of rational bounds on √D (reduced with
/// num-bigint's binary gcd, no budget check inside).  Main's conjugate
/// route (a419730) replaced that loop; this pins the pair within the budget.
#[test]
fn fuzzer_thin_cone_pair_classifies_within_the_budget() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/src/tests/data/fuzz_thin_cones.txt"
    ))
    .unwrap();
    let (a, b) = text.split_once('\n').unwrap();
    let (x, y) = (parse_natural(a).unwrap(), parse_natural(b).unwrap());
    for components in [true, false] {
        classify_within_budget(&x, &y, components);
    }
    let mut options = ClassifyOptions::with_budget(Budget::default().with_time_limit(Some(LIMIT)));
    options.components = true;
    let t0 = Instant::now();
    assert!(crate::natural::classify_with(&x, &y, &options).is_ok());
    assert!(t0.elapsed() <= LIMIT, "{:?}", t0.elapsed());
}

/// Found by libFuzzer (`fuzz/`, batch_line: 2.3 s, 2.2 s of CPU, under a
/// 0.5 s budget in the sanitizer build): the exact route of a tangent line
/// reduced its radical shape with `QPoly::divrem`, which read the clock
/// every 64 rows of large rational products (75 ms past a 20 ms deadline
/// natively); the modular Krylov steps likewise.  A division now reads it
/// every row when rows are large and stops within a row or so.
#[test]
fn fuzzer_tangent_line_and_large_divisions_stop_near_their_deadline() {
    let line = r#"{"id":3,"op":"tangent","ellipsoid":"x^2+y^2+z^2-25","surface":"(x-1)^2/91y^2/4+z^5/162-1"}"#;
    let v = answer_line(line);
    assert_eq!(v["id"], json!(3), "{v}");
    use crate::poly::zpoly::QPoly;
    // rows of 60 products of 20 000-bit rationals (> budget::LARGE_BITS)
    let big = |n: usize, base: u32| -> QPoly {
        QPoly::new(
            (0..n)
                .map(|i| {
                    Q::new(
                        num_traits::pow(BigInt::from(base), 8_000 + i),
                        num_traits::pow(BigInt::from(7), 7_000 + i),
                    )
                })
                .collect(),
        )
    };
    let b = big(60, 5);
    let t0 = Instant::now();
    let _ = big(62, 3).divrem(&b);
    let row = t0.elapsed() / 3;
    let a = big(400, 3);
    let limit = Duration::from_millis(5);
    let t0 = Instant::now();
    let r = crate::budget::run(&Budget::unlimited().with_time_limit(Some(limit)), || {
        a.divrem(&b)
    });
    let took = t0.elapsed();
    assert!(r.is_err(), "340 rows end after the deadline");
    assert!(
        took <= limit + 8 * row + Duration::from_millis(20),
        "{took:?} with a limit of {limit:?} and rows of {row:?}"
    );
}

/// Found by libFuzzer (`fuzz/`, batch_line: 3.85 s, 3.8 s of CPU, under
/// a 0.5 s budget in the sanitizer build): a tangent surface of degree 2391
/// spent its time in `roots::enclose::eval_q`, Horner's rule over Q with
/// no budget check (0.15 s natively under a 0.02 s limit).  It now reads
/// the clock at every large step.
#[test]
fn fuzzer_high_degree_evaluation_stops_at_its_deadline() {
    let line = r#"{"id":3,"op":"tangent","ellipsoid":"x^2+y^2+z^2-25","surface":"(x-0)^2391+z^2/16^2/16-1"}"#;
    let v = answer_line(line);
    assert_eq!(v["id"], json!(3), "{v}");
    use crate::poly::zpoly::QPoly;
    let mut c = vec![Q::from_integer(BigInt::from(1)); 2392];
    c[7] = Q::new(BigInt::from(3), BigInt::from(5));
    let p = QPoly::new(c);
    let x = Q::new(
        BigInt::from(1_234_567_891_011u64),
        BigInt::from(998_877_665_544u64),
    );
    let limit = Duration::from_millis(1);
    let t0 = Instant::now();
    let r = crate::budget::run(&Budget::unlimited().with_time_limit(Some(limit)), || {
        crate::roots::eval_q(&p, &x)
    });
    let took = t0.elapsed();
    assert!(
        r.is_err(),
        "2391 steps on 100 000-bit numbers end after 1 ms"
    );
    assert!(took <= Duration::from_millis(200), "{took:?}");
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
/// sum of huge integers was a gcd (num-bigint's binary gcd, quadratic in
/// the bits even against 1).  Sums and products of large rationals now
/// reduce with `number::gcd_z` and integers with no gcd at all
/// (`poly::ring`), so a step is cheap; and the sum still reads the clock
/// before each large step, so a run stops a step or so after its deadline.
#[test]
fn a_sum_of_huge_integers_stops_a_step_after_its_deadline() {
    let one = "8^77773 - 1";
    let t0 = Instant::now();
    let _ = parse_poly(one).unwrap();
    let step = t0.elapsed();
    let many = [one; 200].join(" + ");
    let limit = Duration::from_millis(1);
    let t0 = Instant::now();
    let r = crate::budget::run(&Budget::default().with_time_limit(Some(limit)), || {
        parse_poly(&many).map(|p| p.len())
    });
    let took = t0.elapsed();
    assert!(r.is_err(), "200 steps end after the deadline: {r:?}");
    assert!(
        took <= limit + 3 * step + Duration::from_millis(20),
        "{took:?} with a limit of {limit:?} and steps of {step:?}"
    );
}

/// Found by libFuzzer (`fuzz/`, parse_poly: 2.3–3.3 s under a 0.5 s
/// budget in the sanitizer build): a power of a constant was
/// num-rational's `pow`, which reduces every square with num-bigint's
/// binary gcd (quadratic in the bits even against 1), and a scientific
/// literal with a large negative exponent was reduced the same way.  A
/// constant power is now `numer^e / denom^e` (coprime, no gcd) and a
/// literal is reduced with `number::gcd_z`: each input parses, exactly,
/// in a fraction of the budget.
#[test]
fn fuzzer_constant_powers_take_no_binary_gcd() {
    for s in [
        "(2-488)^22384",
        "3-8888188^8888(6x^629/366",
        "(x-9(x-1e-4298^22I1)^22.1",
        "1388881e-88881e1e-24",
    ] {
        parse_everything(s);
    }
    let ten = || BigInt::from(10);
    for (s, value) in [
        (
            "(2-488)^22384",
            Q::from_integer(num_traits::pow(BigInt::from(-486), 22_384)),
        ),
        (
            "8888188^8888",
            Q::from_integer(num_traits::pow(BigInt::from(8_888_188), 8_888)),
        ),
        (
            "(1e-4298)^22",
            Q::new(BigInt::from(1), num_traits::pow(ten(), 94_556)),
        ),
        (
            "(-6/35)^9001",
            Q::new(BigInt::from(-6), BigInt::from(35)).pow(9001),
        ),
        (
            "1388881e-88881",
            Q::new(BigInt::from(1_388_881), num_traits::pow(ten(), 88_881)),
        ),
        ("25e-3", Q::new(BigInt::from(1), BigInt::from(40))),
        ("0e-5", Q::from_integer(BigInt::from(0))),
        ("1/(-7/3)", Q::new(BigInt::from(-3), BigInt::from(7))),
    ] {
        let budget = Budget::default().with_time_limit(Some(LIMIT));
        let t0 = Instant::now();
        let r = crate::budget::run(&budget, || parse_poly(s));
        let took = t0.elapsed();
        let p = r
            .unwrap_or_else(|e| panic!("{s:?} ran out of its budget after {took:?}: {e}"))
            .unwrap_or_else(|e| panic!("{s:?}: {e}"));
        assert!(p.is_constant(), "{s:?}");
        let c = p.constant_term();
        assert_eq!(c, value, "{s:?}");
        // in lowest terms with a positive denominator
        let fresh = Q::new(c.numer().clone(), c.denom().clone());
        assert_eq!(
            (c.numer(), c.denom()),
            (fresh.numer(), fresh.denom()),
            "{s:?}"
        );
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
