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

/// The real components of a curve counted by the rulings of either
/// quadric (when both are cylinders or cones): the same number of
/// components, of which the same number bounded — two independent
/// parameterisations of the same curve.
pub(crate) fn rulings_agree(a: &Natural, b: &Natural) -> Result<Option<(usize, usize)>, String> {
    use crate::natural::Prepared;
    use crate::natural::build_pencil::branches_by;
    use crate::natural::prepared::Kind;
    let (pa, pb) = (Prepared::new(a), Prepared::new(b));
    let (x, y) = (
        pa.prep.tier::<num_bigint::BigInt>(),
        pb.prep.tier::<num_bigint::BigInt>(),
    );
    if x.kind == Kind::Sphere || y.kind == Kind::Sphere {
        return Ok(None);
    }
    let r = classify_with(a, b, &ClassifyOptions::default()).map_err(|e| e.to_string())?;
    let is_quartic = r
        .components()
        .iter()
        .any(|c| matches!(c, crate::natural::Component::Curve { degree: 4, .. }));
    if !is_quartic {
        return Ok(None);
    }
    let (b1, i1) = branches_by(&x, &y).map_err(|e| e.to_string())?;
    let (b2, i2) = branches_by(&y, &x).map_err(|e| e.to_string())?;
    let count =
        |b: &[crate::natural::CurveBranch]| (b.len(), b.iter().filter(|c| c.bounded).count());
    if count(&b1) != count(&b2) || i1 != i2 {
        return Err(format!(
            "by the first: {:?} and {i1} isolated, by the second: {:?} and {i2}",
            count(&b1),
            count(&b2)
        ));
    }
    Ok(Some(count(&b1)))
}

#[test]
fn both_rulings_count_the_same_components_on_the_benchmark_pairs() {
    let pairs = read_pairs(None).unwrap();
    let mut bad = Vec::new();
    let mut checked = 0;
    for p in pairs.iter().filter(|p| p.group != "decimal500") {
        match rulings_agree(&p.a, &p.b) {
            Ok(Some(_)) => checked += 1,
            Ok(None) => {}
            Err(e) => bad.push(format!("{}: {e}", p.name)),
        }
    }
    assert!(
        bad.is_empty(),
        "{} pairs differ:\n{}",
        bad.len(),
        bad.join("\n")
    );
    assert!(checked > 100, "only {checked} curves checked");
}
