//! Natural quadrics: every row of the paper's Table 1 and every case of the
//! classification, each also after a rational rigid motion; the three
//! conic deciders agree; computed conics really lie on both surfaces; the
//! pencil is consistent with the class; §7 agrees with the curve topology.

use crate::cli::examples::natural::NATURAL_EXAMPLES;
use crate::geom::cayley_rotation;
use crate::geom::eval_qsqrt;
use crate::natural::classify::section7_agrees;
use crate::natural::deciders::{
    AxesRelation, AxialPlane, pencil_determinant, pencil_has_planar_member, relation, thm8,
};
use crate::natural::numbers::{EPoint, Exact};
use crate::natural::result::{Class, Component, NaturalReport};
use crate::natural::tangency::section7;
use crate::natural::{Natural, classify, parse_natural};
use crate::number::{Q, QSqrt, q, qi};
use crate::poly::ZPoly;
use num_traits::{One, Zero};
use proptest::prelude::*;

fn nat(s: &str) -> Natural {
    parse_natural(s).unwrap_or_else(|e| panic!("{s}: {e}"))
}

fn counts(r: &NaturalReport) -> (usize, usize, usize) {
    (r.conics(), r.lines(), r.points())
}

/// (A, B, class, (conics, lines, points)) — the expectations come from the
/// paper's constructions or elementary geometry (see each comment).
/// A pair, its class and its counts (conics, lines, points).
type Case = (
    &'static str,
    &'static str,
    &'static str,
    (usize, usize, usize),
);

const CASES: &[Case] = &[
    // Table 1, row 1: two conics
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cylinder point=0,0,0 axis=0,1,0 radius2=1",
        "conics",
        (2, 0, 0),
    ),
    (
        "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
        "cylinder point=0,0,0 axis=0,1,0 radius2=1",
        "conics",
        (2, 0, 0),
    ),
    // two cones with a common inscribed sphere (d1² sin²α1 = 4·1/2 = 2 = d2² sin²α2 = 16·1/8)
    (
        "cone vertex=2,0,0 axis=1,0,0 sin2=1/2",
        "cone vertex=0,4,0 axis=0,1,0 sin2=1/8",
        "conics",
        (2, 0, 0),
    ),
    (
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "cone vertex=0,0,3 axis=0,0,1 tan2=3",
        "conics",
        (2, 0, 0),
    ),
    (
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "cylinder point=0,0,0 axis=0,0,5 radius2=4",
        "conics",
        (2, 0, 0),
    ),
    // parallel axes, equal angles: one affine conic
    (
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "cone vertex=3,0,1 axis=0,0,1 tan2=1",
        "conics",
        (1, 0, 0),
    ),
    (
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "cone vertex=0,0,4 axis=0,0,1 tan2=1",
        "conics",
        (1, 0, 0),
    ),
    // Table 1, row 2: a conic and a (double) line — Theorem 5.1
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=2,2,0 axis=0,1,0 tan2=1",
        "conic-and-line",
        (1, 1, 0),
    ),
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cone vertex=0,1,0 axis=1,-1,0 tan2=1",
        "conic-and-line",
        (1, 1, 0),
    ),
    // Table 1, row 3: 1–4 lines
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=0,0,0 axis=0,1,0 tan2=3",
        "lines",
        (0, 4, 0),
    ),
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=0,0,0 axis=1,1,0 tan2=1/3",
        "lines",
        (0, 2, 0),
    ),
    (
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "cylinder point=1,0,0 axis=0,0,1 radius2=1",
        "lines",
        (0, 2, 0),
    ),
    (
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "cylinder point=2,0,0 axis=0,0,1 radius2=1",
        "lines",
        (0, 1, 0),
    ),
    // parallel equal cones with V1V2 a common skeletal line: only the double line
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=1,1,0 axis=1,0,0 tan2=1",
        "lines",
        (0, 1, 0),
    ),
    // Table 1, row 4: 1 or 2 points
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1/10",
        "cone vertex=0,0,0 axis=0,1,0 tan2=1/10",
        "points",
        (0, 0, 1),
    ),
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cylinder point=0,0,2 axis=0,1,0 radius2=1",
        "points",
        (0, 0, 1),
    ),
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cone vertex=0,0,2 axis=0,1,0 tan2=3",
        "points",
        (0, 0, 2),
    ),
    (
        "sphere center=3,0,0 radius2=4",
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "points",
        (0, 0, 1),
    ),
    (
        "sphere center=0,4,0 radius2=8",
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "points",
        (0, 0, 2),
    ),
    (
        "sphere center=0,0,0 radius2=1",
        "sphere center=3,0,0 radius2=4",
        "points",
        (0, 0, 1),
    ),
    (
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "cone vertex=0,0,0 axis=0,0,1 tan2=2",
        "points",
        (0, 0, 1),
    ),
    // empty
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cylinder point=0,0,3 axis=0,1,0 radius2=1",
        "empty",
        (0, 0, 0),
    ),
    (
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "cylinder point=3,0,0 axis=0,0,1 radius2=1",
        "empty",
        (0, 0, 0),
    ),
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cone vertex=0,0,3 axis=0,1,0 tan2=1",
        "empty",
        (0, 0, 0),
    ),
    (
        "sphere center=0,0,0 radius2=1",
        "sphere center=5,0,0 radius2=4",
        "empty",
        (0, 0, 0),
    ),
    (
        "sphere center=0,0,0 radius2=1",
        "sphere center=0,0,0 radius2=4",
        "empty",
        (0, 0, 0),
    ),
    (
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "cylinder point=0,0,5 axis=0,0,-2 radius2=4",
        "empty",
        (0, 0, 0),
    ),
    (
        "sphere center=0,0,0 radius2=1",
        "cylinder point=0,0,0 axis=0,0,1 radius2=4",
        "empty",
        (0, 0, 0),
    ),
    (
        "sphere center=9,0,0 radius2=1",
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "empty",
        (0, 0, 0),
    ),
    // curve
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cylinder point=0,0,0 axis=0,1,0 radius2=2",
        "curve",
        (0, 0, 0),
    ),
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cylinder point=0,0,1 axis=0,1,0 radius2=1",
        "curve",
        (0, 0, 0),
    ),
    (
        "sphere center=2,0,0 radius2=4",
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "curve",
        (0, 0, 0),
    ),
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=1,5,2 axis=1,2,3 tan2=1/2",
        "curve",
        (0, 0, 0),
    ),
    // §5.1: one vertex on the other surface; isolated or crossing
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cone vertex=0,1,0 axis=0,1,0 tan2=1",
        "curve",
        (0, 0, 1),
    ),
    (
        "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        "cone vertex=0,1,0 axis=1,1,0 tan2=3",
        "curve",
        (0, 0, 0),
    ),
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=2,2,0 axis=0,1,0 tan2=1/3",
        "curve",
        (0, 0, 1),
    ),
    // common ruling: line + twisted cubic (missing from Table 1)
    (
        "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        "cone vertex=1,0,0 axis=1,1,1 tan2=2",
        "curve",
        (0, 1, 0),
    ),
    (
        "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        "cone vertex=2,2,0 axis=1,2,1 tan2=1/3",
        "curve",
        (0, 1, 0),
    ),
    // spheres and circles
    (
        "sphere center=0,0,0 radius2=4",
        "sphere center=3,0,0 radius2=4",
        "conics",
        (1, 0, 0),
    ),
    (
        "sphere center=1,2,3 radius2=2",
        "cylinder point=0,2,3 axis=1,0,0 radius2=2",
        "conics",
        (1, 0, 0),
    ),
    (
        "sphere center=1,2,3 radius2=5",
        "cylinder point=0,2,3 axis=1,0,0 radius2=2",
        "conics",
        (2, 0, 0),
    ),
    (
        "sphere center=0,0,2 radius2=4",
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "conics",
        (1, 0, 1),
    ),
    // 2τ² − 6τ + 4 = 0: circles at heights 1 and 2
    (
        "sphere center=0,0,3 radius2=5",
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "conics",
        (2, 0, 0),
    ),
    // distance 3·sin 45° > 1: the sphere misses the cone
    (
        "sphere center=0,0,3 radius2=1",
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "empty",
        (0, 0, 0),
    ),
    (
        "sphere center=0,0,4 radius2=8",
        "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        "conics",
        (1, 0, 0),
    ),
    // same surface
    (
        "cylinder point=0,0,0 axis=1,1,0 radius2=2",
        "cylinder point=3,3,0 axis=-2,-2,0 radius2=2",
        "same-surface",
        (0, 0, 0),
    ),
    (
        "cone vertex=1,1,1 axis=0,0,1 tan2=3",
        "cone vertex=1,1,1 axis=0,0,-7 cos2=1/4",
        "same-surface",
        (0, 0, 0),
    ),
    (
        "sphere center=1,2,3 radius2=4/9",
        "sphere center=1,2,3 radius2=4/9",
        "same-surface",
        (0, 0, 0),
    ),
];

#[test]
fn every_case_gets_its_class_and_counts() {
    let mut failures = Vec::new();
    for (a, b, class, cnt) in CASES {
        let r = classify(&nat(a), &nat(b)).unwrap();
        if r.class.as_str() != *class || counts(&r) != *cnt {
            failures.push(format!(
                "{a} | {b}: got {} {:?}, expected {class} {cnt:?}",
                r.class.as_str(),
                counts(&r)
            ));
        }
        assert!(
            !r.notes.iter().any(|n| n.contains("please report")),
            "{a} | {b}: {:?}",
            r.notes
        );
        // symmetric in the order of the arguments
        let s = classify(&nat(b), &nat(a)).unwrap();
        if s.class != r.class || counts(&s) != counts(&r) {
            failures.push(format!(
                "{b} | {a} (swapped): got {} {:?}",
                s.class.as_str(),
                counts(&s)
            ));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn examples_match_their_expectations() {
    for ex in NATURAL_EXAMPLES {
        let r = classify(&nat(ex.a), &nat(ex.b)).unwrap();
        assert_eq!(
            (r.class.as_str(), counts(&r)),
            (ex.class, ex.counts),
            "{}",
            ex.title
        );
    }
}

#[test]
fn done_when_two_ellipses_in_the_planes_x_eq_pm_y() {
    let r = classify(
        &nat("cylinder point=0,0,0 axis=1,0,0 radius2=1"),
        &nat("cylinder point=0,0,0 axis=0,1,0 radius2=1"),
    )
    .unwrap();
    assert_eq!(r.class, Class::Conics);
    let mut planes = Vec::new();
    for c in &r.components {
        let Component::Conic { plane, kind, .. } = c else {
            panic!("{c:?}")
        };
        assert_eq!(kind.as_str(), "ellipse");
        let n: Vec<Q> = plane.normal.iter().map(rational).collect();
        assert!(n[2].is_zero() && rational(&plane.offset).is_zero());
        planes.push(&n[0] / &n[1]);
    }
    planes.sort();
    assert_eq!(planes, vec![qi(-1), qi(1)]); // x − y = 0 and x + y = 0
}

fn rational(e: &Exact) -> Q {
    match e {
        Exact::Quad(x) if x.is_rational() => x.a.clone(),
        other => panic!("not rational: {other:?}"),
    }
}

fn quad(e: &Exact) -> Option<QSqrt> {
    match e {
        Exact::Quad(x) => Some(x.clone()),
        Exact::Alg(_) => None,
    }
}

fn qpoint(p: &EPoint) -> Option<[QSqrt; 3]> {
    Some([quad(&p[0])?, quad(&p[1])?, quad(&p[2])?])
}

/// Every exactly representable point, vertex, centre-plane combination
/// lies on both surfaces.
fn check_components(a: &Natural, b: &Natural, r: &NaturalReport) {
    let (fa, fb) = (a.equation(), b.equation());
    for c in &r.components {
        match c {
            Component::Point { point, .. } => {
                if let Some(p) = qpoint(point) {
                    assert!(
                        eval_qsqrt(&fa, &p).is_zero() && eval_qsqrt(&fb, &p).is_zero(),
                        "point {point:?} not on both"
                    );
                }
            }
            Component::Line {
                point, direction, ..
            } => {
                if let (Some(p), Some(d)) = (qpoint(point), qpoint(direction)) {
                    for t in [0i64, 1, -2, 3] {
                        let x: [QSqrt; 3] = std::array::from_fn(|i| p[i].add(&d[i].scale(&qi(t))));
                        assert!(
                            eval_qsqrt(&fa, &x).is_zero() && eval_qsqrt(&fb, &x).is_zero(),
                            "line point not on both"
                        );
                    }
                }
            }
            Component::Conic {
                plane,
                center,
                vertex,
                axes2,
                axis_dirs,
                kind,
                ..
            } => {
                // a vertex of the conic (centre + semi-axis) lies on both surfaces
                if let (Some(n), Some(off)) = (qpoint(&plane.normal), quad(&plane.offset)) {
                    let base = center.as_ref().or(vertex.as_ref()).and_then(qpoint);
                    if let Some(b0) = &base {
                        let on_plane = (0..3).fold(QSqrt::rational(Q::zero()), |acc, i| {
                            acc.add(&n[i].mul(&b0[i]))
                        });
                        assert_eq!(
                            on_plane.cmp_exact(&off),
                            std::cmp::Ordering::Equal,
                            "centre/vertex off the plane"
                        );
                    }
                    if *kind != crate::natural::result::ConicKind::Parabola
                        && let (Some(c0), Some(a2)) = (base, axes2.first().and_then(quad))
                        && let Some(dir) = axis_dirs.first().and_then(qpoint)
                    {
                        // point c0 + s·dir with s² |dir|² = a² (when a² > 0)
                        let dd = (0..3).fold(QSqrt::rational(Q::zero()), |acc, i| {
                            acc.add(&dir[i].mul(&dir[i]))
                        });
                        if a2.signum() > 0 && a2.is_rational() && dd.is_rational() {
                            let s2 = &a2.a / &dd.a;
                            let s = QSqrt::sqrt(s2);
                            if s.is_rational()
                                || c0.iter().chain(dir.iter()).all(|x| x.is_rational())
                            {
                                let x: [QSqrt; 3] =
                                    std::array::from_fn(|i| c0[i].add(&dir[i].mul(&s)));
                                let (va, vb) = (eval_qsqrt(&fa, &x), eval_qsqrt(&fb, &x));
                                // the transverse vertex of a hyperbola or an ellipse's vertex is on both
                                assert!(
                                    va.is_zero()
                                        || vb.is_zero()
                                        || *kind == crate::natural::result::ConicKind::Hyperbola,
                                    "conic vertex off the surfaces"
                                );
                            }
                        }
                    }
                }
            }
            Component::Curve { .. } => {}
        }
    }
}

#[test]
fn components_lie_on_both_surfaces() {
    for (a, b, _, _) in CASES {
        let (qa, qb) = (nat(a), nat(b));
        let r = classify(&qa, &qb).unwrap();
        check_components(&qa, &qb, &r);
    }
}

/// Conic planes contain the intersection: both quadrics restricted to the
/// plane give proportional conics (checked on rational-plane cases by
/// sampling the plane exactly).
#[test]
fn conic_planes_cut_proportional_conics() {
    for (a, b, _, _) in CASES {
        let (qa, qb) = (nat(a), nat(b));
        let r = classify(&qa, &qb).unwrap();
        for c in &r.components {
            let Component::Conic { plane, .. } = c else {
                continue;
            };
            let (Some(n), Some(off)) = (qpoint(&plane.normal), quad(&plane.offset)) else {
                continue;
            };
            if !n.iter().all(|x| x.is_rational()) || !off.is_rational() {
                continue;
            }
            let n: [Q; 3] = std::array::from_fn(|i| n[i].a.clone());
            // a rational parametrisation of the plane: P = p0 + s u + t v
            let k = (0..3).find(|&i| !n[i].is_zero()).unwrap();
            let mut p0 = [Q::zero(), Q::zero(), Q::zero()];
            p0[k] = &off.a / &n[k];
            let others: Vec<usize> = (0..3).filter(|&i| i != k).collect();
            let mk = |j: usize| -> [Q; 3] {
                let mut v = [Q::zero(), Q::zero(), Q::zero()];
                v[j] = Q::one();
                v[k] = -&n[j] / &n[k];
                v
            };
            let (u, v) = (mk(others[0]), mk(others[1]));
            let eval = |f: &crate::poly::QMPoly, s: i64, t: i64| -> Q {
                let mut pt: [Q; crate::poly::mpoly::NVARS] = std::array::from_fn(|_| Q::zero());
                for i in 0..3 {
                    pt[i] = &p0[i] + &u[i] * qi(s) + &v[i] * qi(t);
                }
                f.eval(&pt)
            };
            let (fa, fb) = (qa.equation(), qb.equation());
            // proportional restrictions: fa = λ fb on six points of a conic's worth
            let samples: Vec<(Q, Q)> = [(0, 0), (1, 0), (0, 1), (1, 1), (2, -1), (-1, 3), (3, 2)]
                .iter()
                .map(|&(s, t)| (eval(&fa, s, t), eval(&fb, s, t)))
                .collect();
            let (ra, rb) = samples.iter().find(|(_, y)| !y.is_zero()).cloned().unwrap();
            let lam = ra / rb;
            for (x, y) in &samples {
                assert_eq!(
                    x,
                    &(&lam * y),
                    "{a} | {b}: restrictions to the conic plane are not proportional"
                );
            }
        }
    }
}

/// The pencil is consistent with every class: a planar class iff a member
/// of rank ≤ 2; a tangency (isolated points, double components, singular
/// curve points) forces a multiple root of det(A1 − λA2) (or det ≡ 0).
#[test]
fn pencil_consistent_with_classes() {
    for (a, b, class, _) in CASES {
        let (qa, qb) = (nat(a), nat(b));
        let r = classify(&qa, &qb).unwrap();
        let planar_member = pencil_has_planar_member(&qa, &qb);
        let planar_class = matches!(
            r.class,
            Class::Conics | Class::ConicAndLine | Class::Lines | Class::SameSurface
        ) || (r.class == Class::Points
            && r.axes
                .as_ref()
                .is_some_and(|x| !matches!(x, AxesRelation::Skew))
            && r.deciders.as_ref().is_some_and(|d| d.lemma81));
        if *class != "points" && *class != "empty" {
            assert_eq!(planar_member, planar_class, "{a} | {b}");
        }
        let tangency = r.class == Class::Points
            || r.components.iter().any(|c| match c {
                Component::Conic { double, .. } | Component::Line { double, .. } => *double,
                Component::Curve { singular, .. } => !singular.is_empty(),
                _ => false,
            });
        if tangency && r.class != Class::SameSurface {
            // det(μA1 − λA2) as a binary quartic: a multiple root is a finite
            // multiple root or a root of multiplicity ≥ 2 at infinity
            let d = pencil_determinant(&qa.matrix(), &qb.matrix());
            let (dz, _) = ZPoly::from_q(&d);
            let multiple = dz.is_zero()
                || dz.degree().unwrap_or(0) <= 2
                || dz.gcd(&dz.derivative()).degree().unwrap_or(0) > 0;
            assert!(
                multiple,
                "{a} | {b}: tangency without a multiple root of the pencil"
            );
        }
    }
}

#[test]
fn section7_agrees_with_topology() {
    for (a, b, _, _) in CASES {
        let (qa, qb) = (nat(a), nat(b));
        if relation(&qa, &qb) != Some(AxesRelation::Skew) {
            continue;
        }
        let r = classify(&qa, &qb).unwrap();
        assert!(
            section7_agrees(&section7(&qa, &qb), &r.components),
            "{a} | {b}"
        );
    }
}

#[test]
fn bad_quadrics_are_rejected() {
    for bad in [
        "cone vertex=0,0,0 axis=1,0,0 tan2=0",
        "cylinder point=0,0,0 axis=0,0,0 radius2=1",
        "sphere center=0,0,0 radius2=-1",
        "cone vertex=0,0,0 axis=1,0,0 tan=-1",
        "cone vertex=0,0,0 axis=1,0,0 sin2=1",
        "plane point=0,0,0",
        "cylinder point=0,0,0 axis=1,0,0 radius2=1/0",
        "{\"kind\":\"cone\",\"vertex\":[\"0\",\"0\",\"0\"],\"axis\":[\"1\",\"0\",\"0\"]}",
    ] {
        let e = parse_natural(bad).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{bad}");
    }
}

// ----------------------------------------------------------------- properties

fn moved(n: &Natural, rot: (i64, i64, i64, i64), t: (i64, i64, i64)) -> Natural {
    let r = cayley_rotation(&q(rot.0, rot.3), &q(rot.1, rot.3), &q(rot.2, rot.3));
    n.moved(&r, &[qi(t.0), qi(t.1), qi(t.2)])
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, .. ProptestConfig::default() })]

    /// Class and counts are invariant under a rational rigid motion applied
    /// to both surfaces (every case of the table).
    #[test]
    fn rigid_motion_invariance(idx in 0usize..CASES.len(), rot in (-3i64..4, -3i64..4, -3i64..4, 1i64..4), t in (-4i64..5, -4i64..5, -4i64..5)) {
        let (a, b, class, cnt) = CASES[idx];
        let (qa, qb) = (moved(&nat(a), rot, t), moved(&nat(b), rot, t));
        let r = classify(&qa, &qb).unwrap();
        prop_assert_eq!(r.class.as_str(), class, "{} | {}", a, b);
        prop_assert_eq!(counts(&r), cnt);
        check_components(&qa, &qb, &r);
    }

    /// Scaling space by a positive rational keeps class and counts.
    #[test]
    fn scaling_invariance(idx in 0usize..CASES.len(), k in 1i64..9, d in 1i64..5) {
        let (a, b, class, cnt) = CASES[idx];
        let kq = q(k, d);
        let r = classify(&nat(a).scaled(&kq), &nat(b).scaled(&kq)).unwrap();
        prop_assert_eq!(r.class.as_str(), class);
        prop_assert_eq!(counts(&r), cnt);
    }

    /// The three deciders agree on random coplanar pairs (intersecting axes).
    #[test]
    fn deciders_agree_random(v1 in (-4i64..5, -4i64..5), v2 in (-4i64..5, -4i64..5), a1 in (-3i64..4, -3i64..4), a2 in (-3i64..4, -3i64..4),
                             t1 in 1i64..6, t2 in 1i64..6, r1 in 1i64..6, kinds in 0u8..3) {
        prop_assume!(a1 != (0, 0) && a2 != (0, 0));
        let qa = if kinds == 2 { format!("cylinder point={},{},0 axis={},{},0 radius2={}", v1.0, v1.1, a1.0, a1.1, r1) }
                 else { format!("cone vertex={},{},0 axis={},{},0 tan2={}/3", v1.0, v1.1, a1.0, a1.1, t1) };
        let qb = if kinds == 1 { format!("cylinder point={},{},0 axis={},{},0 radius2={}", v2.0, v2.1, a2.0, a2.1, r1 + 1) }
                 else { format!("cone vertex={},{},0 axis={},{},0 tan2={}/2", v2.0, v2.1, a2.0, a2.1, t2) };
        let (x, y) = (nat(&qa), nat(&qb));
        let rel = relation(&x, &y).unwrap();
        prop_assume!(matches!(rel, AxesRelation::Intersecting(_) | AxesRelation::Parallel));
        let h = AxialPlane::new(&x, &y).unwrap();
        let t8 = thm8(&x, &y, &rel).unwrap();
        // the i128 fast path agrees with the rational closed form
        prop_assert_eq!(crate::natural::deciders::conic_intersection_thm8(&x, &y), Some(t8));
        prop_assert_eq!(t8, h.lemma81_planar(), "{} | {}", qa, qb);
        prop_assert_eq!(t8, pencil_has_planar_member(&x, &y), "{} | {}", qa, qb);
    }

    /// The three deciders agree on pairs built to satisfy Theorem 8.1
    /// exactly: pick O and a radius², then a cone and a cylinder/cone
    /// tangent to that sphere, and move everything rigidly.
    #[test]
    fn deciders_agree_on_common_inscribed_spheres(o in (-3i64..4, -3i64..4), rho2 in 1i64..5, d1 in 2i64..6, d2 in 2i64..6,
                                                  dirs in (0usize..4, 0usize..4), cyl in any::<bool>(),
                                                  rot in (-2i64..3, -2i64..3, -2i64..3, 1i64..3)) {
        // axis directions with rational lengths: (3,4,0)/5, (0,1,0), (1,0,0), (4,-3,0)/5
        let dirs_tab = [[q(3,5), q(4,5)], [qi(0), qi(1)], [qi(1), qi(0)], [q(4,5), q(-3,5)]];
        prop_assume!(dirs.0 != dirs.1);
        let (u1, u2) = (&dirs_tab[dirs.0], &dirs_tab[dirs.1]);
        prop_assume!(&u1[0] * &u2[1] - &u1[1] * &u2[0] != qi(0));
        let o3 = [qi(o.0), qi(o.1), qi(0)];
        let rho2q = qi(rho2);
        // cone with vertex at distance d from O: sin²α = ρ²/d²
        let cone = |u: &[Q; 2], d: i64| -> Option<Natural> {
            let s2 = &rho2q / qi(d * d);
            if s2 >= Q::one() { return None; }
            let v = [&o3[0] + &u[0] * qi(d), &o3[1] + &u[1] * qi(d), qi(0)];
            Some(Natural::Cone(crate::Cone::new(v, [u[0].clone(), u[1].clone(), qi(0)], &s2 / (Q::one() - &s2)).ok()?))
        };
        let Some(a) = cone(u1, d1) else { return Ok(()); };
        let b = if cyl {
            Natural::Cylinder(crate::Cylinder::new(o3.clone(), [u2[0].clone(), u2[1].clone(), qi(0)], rho2q.clone()).unwrap())
        } else {
            match cone(u2, d2) { Some(c) => c, None => return Ok(()) }
        };
        let (a, b) = (moved(&a, rot, (1, -2, 3)), moved(&b, rot, (1, -2, 3)));
        let rel = relation(&a, &b).unwrap();
        let t8 = thm8(&a, &b, &rel).unwrap();
        prop_assert!(t8);
        prop_assert_eq!(crate::natural::deciders::conic_intersection_thm8(&a, &b), Some(true));
        prop_assert!(AxialPlane::new(&a, &b).unwrap().lemma81_planar());
        prop_assert!(pencil_has_planar_member(&a, &b));
        let r = classify(&a, &b).unwrap();
        prop_assert!(matches!(r.class, Class::Conics | Class::ConicAndLine | Class::Lines | Class::Points));
        check_components(&a, &b, &r);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    /// Two independent algorithms agree: a sphere is an ellipsoid, so the
    /// tangent point method on (sphere, axial quadric's equation) must say
    /// separated / touching / intersecting exactly when the natural-quadric
    /// classification says empty / isolated points or a double conic /
    /// a curve or crossing conics.
    #[test]
    fn sphere_classes_agree_with_the_tangent_method(c in (-3i64..4, -3i64..4, -3i64..4), r2 in 1i64..12,
                                                    p in (-2i64..3, -2i64..3, -2i64..3), a in (-2i64..3, -2i64..3, 1i64..3),
                                                    k in 1i64..5, cone in any::<bool>()) {
        let s = format!("sphere center={},{},{} radius2={}", c.0, c.1, c.2, r2);
        let q = if cone {
            format!("cone vertex={},{},{} axis={},{},{} tan2={}/2", p.0, p.1, p.2, a.0, a.1, a.2, k)
        } else {
            format!("cylinder point={},{},{} axis={},{},{} radius2={}", p.0, p.1, p.2, a.0, a.1, a.2, k)
        };
        let (qs, qq) = (nat(&s), nat(&q));
        let r = classify(&qs, &qq).unwrap();
        let t = crate::tangent::decide_poly(&qs.equation(), &qq.equation()).unwrap();
        use crate::tangent::Verdict;
        let double = r.components.iter().any(|c| matches!(c, Component::Conic { double: true, .. }));
        let expected = match r.class {
            Class::Empty => Verdict::Separated,
            Class::Points => Verdict::Touching,
            Class::Curve => Verdict::Intersecting,
            Class::Conics if double => Verdict::Touching,
            Class::Conics => Verdict::Intersecting,
            other => panic!("unexpected class {other:?} for {s} | {q}"),
        };
        prop_assert_eq!(t.verdict, expected, "{} | {}: class {}", s, q, r.class.as_str());
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, .. ProptestConfig::default() })]

    /// Random axial pairs: the class and counts do not depend on the order
    /// of the arguments or on a rigid motion, and the paper's §7 decider
    /// agrees with the curve topology wherever it applies.
    #[test]
    fn random_axial_pairs_are_consistent(p1 in (-3i64..4, -3i64..4, -3i64..4), a1 in (-2i64..3, -2i64..3, 1i64..3), k1 in 1i64..6,
                                         p2 in (-3i64..4, -3i64..4, -3i64..4), a2 in (1i64..3, -2i64..3, -2i64..3), k2 in 1i64..6,
                                         kinds in 0u8..3, rot in (-2i64..3, -2i64..3, -2i64..3, 1i64..3)) {
        let mk = |cone: bool, p: (i64, i64, i64), a: (i64, i64, i64), k: i64| if cone {
            format!("cone vertex={},{},{} axis={},{},{} tan2={}/3", p.0, p.1, p.2, a.0, a.1, a.2, k)
        } else {
            format!("cylinder point={},{},{} axis={},{},{} radius2={}", p.0, p.1, p.2, a.0, a.1, a.2, k)
        };
        let (x, y) = (nat(&mk(kinds != 1, p1, a1, k1)), nat(&mk(kinds != 2, p2, a2, k2)));
        let r = classify(&x, &y).unwrap();
        prop_assert!(!r.notes.iter().any(|n| n.contains("please report")), "{:?}", r.notes);
        let s = classify(&y, &x).unwrap();
        prop_assert_eq!((s.class, counts(&s)), (r.class, counts(&r)));
        let m = classify(&moved(&x, rot, (1, -1, 2)), &moved(&y, rot, (1, -1, 2))).unwrap();
        prop_assert_eq!((m.class, counts(&m)), (r.class, counts(&r)));
        prop_assert!(section7_agrees(&section7(&x, &y), &r.components));
        check_components(&x, &y, &r);
    }
}
