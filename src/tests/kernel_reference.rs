//! Checks the real-root and resultant kernels against reference data made
//! by sympy (`scripts/gen_kernel_reference.py`, output committed as
//! `tests/data/kernel_reference.json`).  No Python is needed to run this.
//!
//! Every case is checked (a panic inside the crate counts as a failure of
//! that case) and all failing ids are reported together.

use crate::number::parse_rational;
use crate::poly::parse_poly;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use serde_json::Value;
use std::panic::{AssertUnwindSafe, catch_unwind};

const DATA: &str = include_str!("data/kernel_reference.json");

fn data() -> Value {
    serde_json::from_str(DATA).expect("kernel_reference.json is valid JSON")
}

fn field<'a>(case: &'a Value, key: &str) -> &'a Value {
    case.get(key)
        .unwrap_or_else(|| panic!("missing field {key} in {case}"))
}

fn str_field<'a>(case: &'a Value, key: &str) -> &'a str {
    field(case, key)
        .as_str()
        .unwrap_or_else(|| panic!("field {key} is not a string in {case}"))
}

fn u64_field(case: &Value, key: &str) -> u64 {
    field(case, key)
        .as_u64()
        .unwrap_or_else(|| panic!("field {key} is not an unsigned integer in {case}"))
}

/// `10^-k` as an exact rational.
fn ten_pow_neg(k: usize) -> BigRational {
    BigRational::new(BigInt::one(), num_traits::pow(BigInt::from(10), k))
}

fn fmt_q(q: &BigRational) -> String {
    if q.is_integer() {
        q.numer().to_string()
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

/// Runs `f`, turning a panic into an error message.
fn guarded<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(e) => {
            let msg = e
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown panic".into());
            Err(format!("panicked: {msg}"))
        }
    }
}

/// All problems found for one roots case (empty when it passes).
fn check_roots_case(case: &Value) -> Vec<String> {
    let poly = str_field(case, "poly");
    let result = match guarded(|| crate::kernel::roots_str(poly).map_err(|e| format!("{e:?}"))) {
        Ok(r) => r,
        Err(e) => return vec![format!("roots({poly:?}) failed: {e}")],
    };
    let rep = &result.report;
    let mut problems = Vec::new();

    let counts: [(&str, u64, u64); 5] = [
        (
            "distinct_real",
            u64_field(case, "distinct_real"),
            rep.distinct_real as u64,
        ),
        ("positive", u64_field(case, "positive"), rep.positive as u64),
        ("negative", u64_field(case, "negative"), rep.negative as u64),
        (
            "zero_multiplicity",
            u64_field(case, "zero_multiplicity"),
            rep.zero_multiplicity as u64,
        ),
        (
            "real_with_multiplicity",
            u64_field(case, "real_with_multiplicity"),
            rep.real_with_multiplicity as u64,
        ),
    ];
    for (name, want, got) in counts {
        if want != got {
            problems.push(format!("{name}: expected {want}, got {got}"));
        }
    }

    let want_roots = field(case, "roots").as_array().expect("roots is an array");
    if want_roots.len() != rep.roots.len() {
        problems.push(format!(
            "number of roots: expected {}, got {}",
            want_roots.len(),
            rep.roots.len()
        ));
    }
    if rep.roots.len() != rep.distinct_real {
        problems.push(format!(
            "report.roots has {} entries but distinct_real = {}",
            rep.roots.len(),
            rep.distinct_real
        ));
    }

    // intervals well formed, increasing and pairwise disjoint
    for (i, r) in rep.roots.iter().enumerate() {
        if r.interval.lo > r.interval.hi {
            problems.push(format!(
                "root {i}: interval lo {} > hi {}",
                fmt_q(&r.interval.lo),
                fmt_q(&r.interval.hi)
            ));
        }
    }
    for (i, w) in rep.roots.windows(2).enumerate() {
        if w[0].interval.hi > w[1].interval.lo {
            problems.push(format!(
                "roots {i} and {}: intervals not sorted/disjoint: [{}, {}] and [{}, {}]",
                i + 1,
                fmt_q(&w[0].interval.lo),
                fmt_q(&w[0].interval.hi),
                fmt_q(&w[1].interval.lo),
                fmt_q(&w[1].interval.hi)
            ));
        }
    }

    for (i, (want, got)) in want_roots.iter().zip(rep.roots.iter()).enumerate() {
        let want_mult = u64_field(want, "multiplicity");
        if want_mult != got.multiplicity as u64 {
            problems.push(format!(
                "root {i}: multiplicity expected {want_mult}, got {}",
                got.multiplicity
            ));
        }
        let (lo, hi) = (&got.interval.lo, &got.interval.hi);
        let iv = if got.interval.is_exact() {
            format!("exact {}", fmt_q(lo))
        } else {
            format!("({}, {})", fmt_q(lo), fmt_q(hi))
        };
        match field(want, "exact") {
            Value::String(e) => {
                let e = parse_rational(e).expect("reference exact root parses");
                let ok = if got.interval.is_exact() {
                    *lo == e
                } else {
                    *lo < e && e < *hi
                };
                if !ok {
                    problems.push(format!(
                        "root {i}: expected the rational root {}, got {iv}",
                        fmt_q(&e)
                    ));
                }
            }
            Value::Null => {
                let approx = str_field(want, "approx");
                let a = parse_rational(approx).expect("reference approximation parses");
                if got.interval.is_exact() {
                    problems.push(format!(
                        "root {i}: irrational root ~{approx} reported as the exact rational {}",
                        fmt_q(lo)
                    ));
                    continue;
                }
                // `a` has 60 significant digits: its error is below
                // |a|·5e-60.  Only a very narrow interval may miss it.
                let scale = if a.abs() > BigRational::one() {
                    a.abs()
                } else {
                    BigRational::one()
                };
                let width = hi - lo;
                let ok = if width < ten_pow_neg(50) * &scale {
                    let tol = ten_pow_neg(55) * &scale;
                    lo - &tol < a && a < hi + &tol
                } else {
                    *lo < a && a < *hi
                };
                if !ok {
                    problems.push(format!(
                        "root {i}: reference root ~{approx} not in our interval {iv}"
                    ));
                }
            }
            other => panic!("bad 'exact' field {other}"),
        }
    }
    problems
}

#[test]
fn roots_match_sympy_reference() {
    let d = data();
    let cases = d["roots"].as_array().expect("roots list");
    assert!(cases.len() >= 30, "too few roots cases: {}", cases.len());
    let mut failures = Vec::new();
    for case in cases {
        let id = str_field(case, "id");
        let problems = check_roots_case(case);
        if !problems.is_empty() {
            failures.push(format!(
                "[{id}] poly = {}\n    {}",
                str_field(case, "poly"),
                problems.join("\n    ")
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} roots cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

fn check_resultant_case(case: &Value) -> Result<(), String> {
    let (f, g, var) = (
        str_field(case, "f"),
        str_field(case, "g"),
        str_field(case, "var"),
    );
    let want_text = str_field(case, "resultant");
    let want = parse_poly(want_text).map_err(|e| format!("reference does not parse: {e}"))?;
    let got = guarded(|| crate::kernel::resultant_str(f, g, var).map_err(|e| format!("{e:?}")))?;
    if got.resultant == want {
        Ok(())
    } else {
        let shown = |s: String| {
            if s.len() > 400 {
                format!("{}... ({} chars)", &s[..400], s.len())
            } else {
                s
            }
        };
        Err(format!(
            "expected {}\n    got      {}",
            shown(want.to_string_canonical()),
            shown(got.resultant.to_string_canonical())
        ))
    }
}

#[test]
fn resultants_match_sympy_reference() {
    let d = data();
    let cases = d["resultants"].as_array().expect("resultants list");
    assert!(
        cases.len() >= 20,
        "too few resultant cases: {}",
        cases.len()
    );
    let mut failures = Vec::new();
    for case in cases {
        let id = str_field(case, "id");
        if let Err(e) = check_resultant_case(case) {
            failures.push(format!(
                "[{id}] Res_{}({}, {})\n    {e}",
                str_field(case, "var"),
                str_field(case, "f"),
                str_field(case, "g")
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} resultant cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// The reference file itself is sane: counts agree with the root list.
#[test]
fn reference_data_is_consistent() {
    let d = data();
    for case in d["roots"].as_array().unwrap() {
        let id = str_field(case, "id");
        let roots = case["roots"].as_array().unwrap();
        let vals: Vec<BigRational> = roots
            .iter()
            .map(|r| parse_rational(str_field(r, "approx")).unwrap())
            .collect();
        assert_eq!(
            u64_field(case, "distinct_real") as usize,
            roots.len(),
            "{id}"
        );
        let pos = vals.iter().filter(|v| v.is_positive()).count();
        let neg = vals.iter().filter(|v| v.is_negative()).count();
        assert_eq!(u64_field(case, "positive") as usize, pos, "{id}");
        assert_eq!(u64_field(case, "negative") as usize, neg, "{id}");
        let zero = roots
            .iter()
            .zip(&vals)
            .find(|(_, v)| v.is_zero())
            .map(|(r, _)| u64_field(r, "multiplicity"))
            .unwrap_or(0);
        assert_eq!(u64_field(case, "zero_multiplicity"), zero, "{id}");
        let total: u64 = roots.iter().map(|r| u64_field(r, "multiplicity")).sum();
        assert_eq!(u64_field(case, "real_with_multiplicity"), total, "{id}");
        assert!(vals.windows(2).all(|w| w[0] < w[1]), "{id}: not increasing");
        for r in roots {
            if let Some(e) = r["exact"].as_str() {
                // the 60-digit approximation of an exact root is within 1e-59 relative
                let e = parse_rational(e).unwrap();
                let a = parse_rational(str_field(r, "approx")).unwrap();
                let scale = if e.abs() > BigRational::one() {
                    e.abs()
                } else {
                    BigRational::one()
                };
                assert!((a - &e).abs() < ten_pow_neg(59) * scale, "{id}");
            }
        }
    }
}
