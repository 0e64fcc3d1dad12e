//! The referee (natural quadrics): `lo` is proved — random inputs inside
//! the ball of relative size `lo` keep the class and counts — and `hi` is
//! witnessed — the nearby input is exactly `hi` away and its exact answer
//! differs.

use super::natural_whole::surface;
use crate::natural::referee::{distance, within};
use crate::natural::{ClassifyOptions, Natural, classify_with, parse_natural};
use crate::number::Q;
use num_bigint::BigInt;
use proptest::prelude::*;

/// Checks one pair's referee; `fracs` picks points inside the `lo` ball
/// (eighths of the allowed move, per number).
fn check(a: &Natural, b: &Natural, fracs: &[[i8; 14]]) -> Result<(), String> {
    let r = classify_with(
        a,
        b,
        &ClassifyOptions::default()
            .without_components()
            .with_referee(),
    )
    .map_err(|e| e.to_string())?;
    let f = r.referee().ok_or("no referee")?;
    let counts = (r.class(), r.conics(), r.lines(), r.points());
    if let Some(hi) = f.hi() {
        if f.lo() >= hi {
            return Err(format!("lo {} >= hi {}", f.lo(), hi));
        }
        let n = f.nearby().ok_or("hi without a witness")?;
        if distance(a, b, n.a(), n.b()).as_ref() != Some(hi) {
            return Err(format!("the witness is not at distance hi {hi}"));
        }
        let w =
            classify_with(n.a(), n.b(), &ClassifyOptions::default()).map_err(|e| e.to_string())?;
        let wc = (w.class(), w.conics(), w.lines(), w.points());
        if wc == counts || (n.class(), n.conics(), n.lines(), n.points()) != wc {
            return Err(format!(
                "witness answer {wc:?}, claimed {:?}, input {counts:?}",
                n.class()
            ));
        }
    } else if f.nearby().is_some() || f.hi_reason().is_none() {
        return Err("no hi but a witness, or no reason".into());
    }
    if f.lo() > &Q::from_integer(0.into()) {
        for fr in fracs {
            let frac: [Q; 14] =
                std::array::from_fn(|i| Q::new(BigInt::from(fr[i]), BigInt::from(8)));
            let (c, d) = within(a, b, f.lo(), &frac).ok_or("a point of the lo ball is no pair")?;
            let x = classify_with(&c, &d, &ClassifyOptions::default().without_components())
                .map_err(|e| e.to_string())?;
            let xc = (x.class(), x.conics(), x.lines(), x.points());
            if xc != counts {
                return Err(format!(
                    "inside the lo ball ({fr:?}): {xc:?}, not {counts:?}"
                ));
            }
        }
    } else if f.lo_reason().is_none() {
        return Err("lo = 0 without a reason".into());
    }
    Ok(())
}

/// The corners and a few inner points of the lo ball.
fn some_fracs(seed: u64) -> Vec<[i8; 14]> {
    let mut s = seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % 17) as i8 - 8
    };
    let mut v = vec![[8; 14], [-8; 14]];
    for _ in 0..3 {
        v.push(std::array::from_fn(|_| next()));
    }
    v
}

#[test]
fn the_referee_holds_on_the_benchmark_pairs() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/benches/data/natural_pairs.json"
    ))
    .unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut failures = Vec::new();
    let mut witnessed = 0;
    for (k, p) in v["pairs"].as_array().unwrap().iter().enumerate() {
        let a = crate::natural::types::from_json(&p["a"]).unwrap();
        let b = crate::natural::types::from_json(&p["b"]).unwrap();
        if let Err(e) = check(&a, &b, &some_fracs(k as u64)) {
            failures.push(format!("{}: {e}", p["name"]));
        }
        let r = classify_with(
            &a,
            &b,
            &ClassifyOptions::default()
                .without_components()
                .with_referee(),
        )
        .unwrap();
        witnessed += usize::from(r.referee().unwrap().hi().is_some());
    }
    assert!(failures.is_empty(), "{failures:#?}");
    // most pairs have a witness (every degenerate one, most of the rest)
    assert!(witnessed > 250, "{witnessed} witnesses");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, .. ProptestConfig::default() })]

    /// Random pairs (degenerate ones frequent, and generic ones with wider
    /// ranges): lo is proved on points of its ball, the witness is exact.
    #[test]
    fn the_referee_holds_on_random_pairs(
        k1 in 0u8..4, p1 in (-3i64..4, -3i64..4, -3i64..4), a1 in (-2i64..3, -2i64..3, 0i64..3), r1 in 1i64..9,
        k2 in 0u8..4, p2 in (-3i64..4, -3i64..4, -3i64..4), a2 in (-2i64..3, -2i64..3, 0i64..3), r2 in 1i64..9,
        seed in 0u64..1000,
    ) {
        let (sa, sb) = (surface(k1, p1, a1, r1), surface(k2, p2, a2, r2));
        let (a, b) = (parse_natural(&sa).unwrap(), parse_natural(&sb).unwrap());
        if let Err(e) = check(&a, &b, &some_fracs(seed)) {
            return Err(TestCaseError::fail(format!("{sa} | {sb}: {e}")));
        }
    }
}
