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
    // the quartics, and the cubics beside a common ruling
    let is_curve = r
        .components()
        .iter()
        .any(|c| matches!(c, crate::natural::Component::Curve { .. }));
    if !is_curve {
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

// ----------------------------------------------------------------- properties

use crate::geom::cayley_rotation;
use crate::natural::numbers::Exact;
use crate::natural::{Component, parse_natural};
use crate::number::{Q, q, qi};
use crate::roots::RealAlg;
use proptest::prelude::*;

/// `x` lies in `[v − b, v + b]`, decided exactly (the double and its
/// bound at their exact binary values).
fn holds(x: &Exact, (v, b): (f64, f64)) -> bool {
    if v.is_infinite() && b == f64::INFINITY {
        // beyond the range of doubles, with its sign (documented)
        let max = Q::from_float(f64::MAX).unwrap();
        let a = x.to_alg();
        return if v > 0.0 {
            a.cmp_exact(&RealAlg::rational(max)).is_gt()
        } else {
            a.cmp_exact(&RealAlg::rational(-max)).is_lt()
        };
    }
    if !v.is_finite() || !b.is_finite() {
        return false;
    }
    let (lo, hi) = (
        Q::from_float(v).unwrap() - Q::from_float(b).unwrap(),
        Q::from_float(v).unwrap() + Q::from_float(b).unwrap(),
    );
    let a = x.to_alg();
    a.cmp_exact(&RealAlg::rational(lo)).is_ge() && a.cmp_exact(&RealAlg::rational(hi)).is_le()
}

/// Every numeric field of every component: its certified double holds the
/// exact value, and the bound is small (relative 2⁻⁴⁰, or absolute 2⁻⁶⁰
/// for 0); curve branch points hold their exact coordinates.
fn bounds_hold(components: &[Component]) -> Result<usize, String> {
    let mut n = 0;
    let mut check = |what: &str, x: &Exact, vb: (f64, f64)| -> Result<(), String> {
        n += 1;
        let small =
            vb.1 <= vb.0.abs() * 2f64.powi(-40) || vb.1 <= 2f64.powi(-60) || vb.1 == f64::INFINITY;
        if holds(x, vb) && small {
            Ok(())
        } else {
            Err(format!("{what}: {} not within {vb:?}", x.approx(30)))
        }
    };
    for c in components {
        match c {
            Component::Conic {
                plane,
                center,
                vertex,
                axes2,
                focal2,
                ..
            } => {
                for x in plane.normal.iter().chain([&plane.offset]) {
                    check("plane", x, x.to_f64_bounded())?;
                }
                for x in center.iter().chain(vertex.iter()).flatten() {
                    check("centre or vertex", x, x.to_f64_bounded())?;
                }
                for x in axes2.iter().chain(focal2.iter()) {
                    check("semi-axis² or focal length²", x, x.to_f64_bounded())?;
                }
            }
            Component::Line {
                point, direction, ..
            } => {
                for x in point.iter().chain(direction.iter()) {
                    check("line", x, x.to_f64_bounded())?;
                }
            }
            Component::Point { point, .. } => {
                for x in point {
                    check("point", x, x.to_f64_bounded())?;
                }
            }
            Component::Curve {
                singular, branches, ..
            } => {
                for p in singular {
                    for x in &p.point {
                        check("singular point", x, x.to_f64_bounded())?;
                    }
                }
                for br in branches {
                    let exact = br.start.exact();
                    for (x, vb) in exact.iter().zip(br.start.approx()) {
                        check("branch point", x, vb)?;
                    }
                }
            }
        }
    }
    Ok(n)
}

/// One surface from a small code: kinds and parameters drawn from small
/// ranges so that coincidences (common vertices, tangencies, parallel or
/// intersecting axes, equal radii) are frequent.
pub(crate) fn surface(kind: u8, p: (i64, i64, i64), a: (i64, i64, i64), k: i64) -> String {
    let a = if a == (0, 0, 0) { (0, 0, 1) } else { a };
    match kind {
        0 => format!("sphere center={},{},{} radius2={}", p.0, p.1, p.2, k),
        1 => format!(
            "cylinder point={},{},{} axis={},{},{} radius2={}",
            p.0, p.1, p.2, a.0, a.1, a.2, k
        ),
        2 => format!(
            "cone vertex={},{},{} axis={},{},{} tan2={}",
            p.0, p.1, p.2, a.0, a.1, a.2, k
        ),
        _ => format!(
            "cone vertex={},{},{} axis={},{},{} tan2=1/{}",
            p.0, p.1, p.2, a.0, a.1, a.2, k
        ),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    /// Random pairs, degenerate ones frequent by construction, moved by a
    /// rational rigid motion: the one pipeline's whole answer equals the
    /// reference route's (class, counts and exact components), and every
    /// certified double holds its exact value.
    #[test]
    fn whole_answers_agree_and_bounds_hold_on_random_pairs(
        k1 in 0u8..4, p1 in (-1i64..2, -1i64..2, -1i64..2), a1 in (-1i64..2, -1i64..2, 0i64..2), r1 in 1i64..4,
        k2 in 0u8..4, p2 in (-1i64..2, -1i64..2, -1i64..2), a2 in (-1i64..2, -1i64..2, 0i64..2), r2 in 1i64..4,
        rot in (-2i64..3, -2i64..3, -2i64..3, 1i64..3), t in (-2i64..3, -2i64..3, -2i64..3),
    ) {
        let (sa, sb) = (surface(k1, p1, a1, r1), surface(k2, p2, a2, r2));
        let r = cayley_rotation(&q(rot.0, rot.3), &q(rot.1, rot.3), &q(rot.2, rot.3));
        let m = |s: &str| parse_natural(s).unwrap().moved(&r, &[qi(t.0), qi(t.1), qi(t.2)]);
        let (a, b) = (m(&sa), m(&sb));
        if let Err(e) = compare(&a, &b) {
            return Err(TestCaseError::fail(format!("{sa} | {sb} moved by {rot:?} {t:?}: {e}")));
        }
        let rep = crate::natural::classify(&a, &b).unwrap();
        if let Err(e) = bounds_hold(rep.components()) {
            return Err(TestCaseError::fail(format!("{sa} | {sb}: {e}")));
        }
        if let Err(e) = rulings_agree(&a, &b) {
            return Err(TestCaseError::fail(format!("{sa} | {sb}: {e}")));
        }
    }
}

/// The certified doubles hold on every benchmark pair (decimal500
/// included: its values are the far ones from doubles).
#[test]
fn certified_doubles_hold_on_the_benchmark_pairs() {
    let pairs = read_pairs(None).unwrap();
    let mut bad = Vec::new();
    let mut n = 0;
    for p in &pairs {
        let rep = crate::natural::classify(&p.a, &p.b).unwrap();
        match bounds_hold(rep.components()) {
            Ok(k) => n += k,
            Err(e) => bad.push(format!("{}: {e}", p.name)),
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert!(n > 1000, "only {n} values checked");
}

/// The value of `f` at a point with coordinates in one Q(√E).
fn eval_quad(f: &crate::poly::QMPoly, x: &[crate::number::QSqrt; 3]) -> crate::number::QSqrt {
    use crate::number::QSqrt;
    let mut acc = QSqrt::rational(qi(0));
    for (e, c) in f.terms() {
        let mut t = QSqrt::rational(c.clone());
        for (k, xk) in x.iter().enumerate() {
            for _ in 0..e[k] {
                t = t.mul(xk);
            }
        }
        acc = acc.add(&t);
    }
    acc
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, .. ProptestConfig::default() })]

    /// Pairs sharing a ruling by construction — a cone whose apex lies on a
    /// cylinder with one generator along the cylinder's ruling there, or
    /// two cones with a common generator through both apices — moved by a
    /// rational rigid motion: a line and a cubic whose branches are traced
    /// (the same components by the rulings of either quadric), each branch
    /// point exactly on both surfaces, the certified doubles holding.
    #[test]
    fn twisted_cubics_beside_a_common_ruling_are_traced(
        two_cones in any::<bool>(),
        w in (-3i64..4, -3i64..4, 1i64..4), w2 in (-3i64..4, -3i64..4, 1i64..4),
        h in -2i64..3, k in 1i64..4,
        rot in (-2i64..3, -2i64..3, -2i64..3, 1i64..3), t in (-2i64..3, -2i64..3, -2i64..3),
    ) {
        prop_assume!(w.0 != 0 || w.1 != 0);
        prop_assume!(w2.0 != 0 || w2.1 != 0);
        // the common line: x = k, y = 0 (parallel to z)
        let tan2 = |w: (i64, i64, i64)| format!("{}/{}", w.0 * w.0 + w.1 * w.1, w.2 * w.2);
        let cone = |apex: i64, w: (i64, i64, i64)| format!(
            "cone vertex={k},0,{apex} axis={},{},{} tan2={}", w.0, w.1, w.2, tan2(w)
        );
        let sa = if two_cones {
            prop_assume!(w != w2);
            cone(h + 3, w2)
        } else {
            format!("cylinder point=0,0,0 axis=0,0,1 radius2={}", k * k)
        };
        let sb = cone(h, w);
        let r = cayley_rotation(&q(rot.0, rot.3), &q(rot.1, rot.3), &q(rot.2, rot.3));
        let m = |s: &str| parse_natural(s).unwrap().moved(&r, &[qi(t.0), qi(t.1), qi(t.2)]);
        let (a, b) = (m(&sa), m(&sb));
        let rep = crate::natural::classify(&a, &b).unwrap();
        prop_assume!(rep.lines() == 1 && rep.class() == crate::natural::result::Class::Curve);
        let fail = |e: String| TestCaseError::fail(format!("{sa} | {sb} moved by {rot:?} {t:?}: {e}"));
        let mut traced = 0;
        for c in rep.components() {
            if let Component::Curve { degree, branches, .. } = c {
                prop_assert_eq!(*degree, 3);
                prop_assert!(!branches.is_empty(), "no branch traced: {:?}", rep.notes());
                for br in branches {
                    let x: Vec<_> = br.start.exact().iter().map(|e| match e {
                        Exact::Quad(v) => Ok(v.clone()),
                        Exact::Alg(_) => Err(fail("a nested branch point with σ = 0".into())),
                    }).collect::<Result<_, _>>()?;
                    let x: [crate::number::QSqrt; 3] = [x[0].clone(), x[1].clone(), x[2].clone()];
                    for f in [a.equation(), b.equation()] {
                        prop_assert!(eval_quad(&f, &x).is_zero(), "a branch point off a surface");
                    }
                    traced += 1;
                }
            }
        }
        prop_assert!(traced > 0);
        bounds_hold(rep.components()).map_err(fail)?;
        rulings_agree(&a, &b).map_err(fail)?;
        // the line and its crossing points built by the rulings (not the
        // reference route), equal to the reference route's
        let (pa, pb) = (crate::natural::Prepared::new(&a), crate::natural::Prepared::new(&b));
        let (x, y) = (pa.prep.tier::<num_bigint::BigInt>(), pb.prep.tier::<num_bigint::BigInt>());
        let (p, qq) = crate::natural::build_pencil::ruling_choice(&x, &y);
        let r = crate::natural::curve::Rulings::new(p, qq);
        prop_assert!(crate::natural::curve::common_ruling(p, qq, &r).is_some(), "{} | {}: not built by the rulings", sa, sb);
        compare(&a, &b).map_err(fail)?;
    }
}

/// Curve points beyond the range of doubles (a 1 500-digit radius, a
/// 600-digit apex on a common ruling): the branches are traced and their
/// certified doubles are ±∞ with an infinite bound, holding the exact
/// values (contract §4), not an internal error.
#[test]
fn branch_points_beyond_the_range_of_doubles() {
    let big = "7".repeat(1500);
    let far = format!("1{}7", "0".repeat(599));
    for (sa, sb) in [
        (
            format!("cylinder point=0,0,0 axis=0,0,1 radius2={big}"),
            format!("cone vertex=0,0,0 axis=1,2,3 tan2=1/{big}"),
        ),
        (
            "cylinder point=0,0,0 axis=0,0,1 radius2=1".to_string(),
            format!("cone vertex=1,0,{far} axis=0,1,1 tan2=1"),
        ),
    ] {
        let (a, b) = (parse_natural(&sa).unwrap(), parse_natural(&sb).unwrap());
        let rep = crate::natural::classify(&a, &b).unwrap();
        let branches: Vec<_> = rep
            .components()
            .iter()
            .filter_map(|c| match c {
                Component::Curve { branches, .. } => Some(branches),
                _ => None,
            })
            .flatten()
            .collect();
        assert!(!branches.is_empty(), "{sa} | {sb}: {:?}", rep.notes());
        assert!(
            branches
                .iter()
                .any(|b| b.start.approx().iter().any(|v| v.0.is_infinite())),
            "{sa} | {sb}: no coordinate beyond doubles"
        );
        bounds_hold(rep.components()).unwrap();
    }
}

/// A printed parabola's axis points into it (contract §4), on every
/// benchmark pair with a rational parabola: with V its vertex, d1 the
/// printed axis direction and d2 = n × d1 in its plane, the first quadric
/// along V + s·d1 + t·d2 is κ(t²|d2|² − k·s) with k > 0 exactly when
/// A(V + d1) and A(V + d2) − A(V) have opposite signs (A(V) = 0).  The
/// printing once flipped such axes to a first positive coordinate.
#[test]
fn printed_parabola_axes_point_into_the_parabola() {
    use crate::natural::{Component, ConicKind, Exact, normalize_axis_direction};
    let rational = |p: &[Exact; 3]| -> Option<[crate::number::Q; 3]> {
        let mut out: [crate::number::Q; 3] = Default::default();
        for (o, c) in out.iter_mut().zip(p) {
            match c {
                Exact::Quad(x) if x.is_rational() => *o = x.a().clone(),
                _ => return None,
            }
        }
        Some(out)
    };
    let pairs = read_pairs(None).unwrap();
    let mut seen = 0;
    for p in pairs.iter().filter(|p| p.group != "decimal500") {
        let r = classify_with(&p.a, &p.b, &ClassifyOptions::default()).unwrap();
        for c in r.components() {
            let Component::Conic {
                kind: ConicKind::Parabola,
                plane,
                vertex: Some(v),
                axis_dirs,
                ..
            } = c
            else {
                continue;
            };
            let printed = normalize_axis_direction(&axis_dirs[0], ConicKind::Parabola);
            let (Some(v), Some(d1), Some(n)) =
                (rational(v), rational(&printed), rational(&plane.normal))
            else {
                continue;
            };
            let d2 = crate::geom::vec3::cross(&n, &d1);
            let eq = p.a.equation();
            let at = |s: i64, t: i64| {
                let pt: [crate::number::Q; crate::poly::mpoly::NVARS] = std::array::from_fn(|i| {
                    if i < 3 {
                        &v[i] + &d1[i] * crate::number::qi(s) + &d2[i] * crate::number::qi(t)
                    } else {
                        crate::number::Q::zero()
                    }
                });
                eq.eval(&pt)
            };
            use num_traits::{Signed, Zero};
            assert!(at(0, 0).is_zero(), "{}: vertex off the quadric", p.name);
            let (along, across) = (at(1, 0), at(0, 1));
            assert!(
                along.is_positive() != across.is_positive() && !along.is_zero(),
                "{}: the axis {:?} points out of the parabola",
                p.name,
                printed
            );
            seen += 1;
        }
    }
    assert!(seen >= 4, "only {seen} parabolas checked");
}
