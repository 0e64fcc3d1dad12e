//! The fast route (`classify_with` without components) against the
//! complete route (`classify`): the same class and counts on random pairs,
//! on pairs built to be degenerate (conics, lines, tangency, common vertex,
//! a vertex on the other surface, parallel axes, equal radii, common axis,
//! a sphere centred on an axis), and on all of them moved by rational rigid
//! motions.

use crate::cli::examples::natural::NATURAL_EXAMPLES;
use crate::geom::cayley_rotation;
use crate::natural::{ClassifyOptions, Natural, classify, classify_with, parse_natural};
use crate::number::{Q, q, qi};
use proptest::prelude::*;

fn nat(s: &str) -> Natural {
    parse_natural(s).unwrap_or_else(|e| panic!("{s}: {e}"))
}

/// The fast and the complete route give the same class and counts.
fn same_answer(a: &Natural, b: &Natural) -> Result<bool, TestCaseError> {
    let full = classify(a, b).map_err(|e| TestCaseError::fail(format!("complete route: {e}")))?;
    let fast = classify_with(a, b, &ClassifyOptions::default().without_components())
        .map_err(|e| TestCaseError::fail(format!("fast route: {e}")))?;
    prop_assert_eq!(
        fast.counts,
        full.counts,
        "A = {}, B = {} (fast method: {})",
        a.to_short(),
        b.to_short(),
        fast.method
    );
    prop_assert_eq!(fast.thm8, full.thm8);
    prop_assert_eq!(
        fast.axes.as_ref().map(|x| x.as_str()),
        full.axes.as_ref().map(|x| x.as_str())
    );
    if let (
        Some(crate::natural::deciders::AxesRelation::Intersecting(o1)),
        Some(crate::natural::deciders::AxesRelation::Intersecting(o2)),
    ) = (&fast.axes, &full.axes)
    {
        prop_assert_eq!(o1, o2);
    }
    Ok(fast.answered_fast())
}

fn moved(n: &Natural, rot: (i64, i64, i64, i64), t: (i64, i64, i64)) -> Natural {
    let r = cayley_rotation(&q(rot.0, rot.3), &q(rot.1, rot.3), &q(rot.2, rot.3));
    n.moved(&r, &[qi(t.0), qi(t.1), qi(t.2)])
}

fn v(p: (i64, i64, i64)) -> String {
    format!("{},{},{}", p.0, p.1, p.2)
}

#[test]
fn examples_and_classics_agree_and_mostly_take_the_fast_route() {
    let mut pairs: Vec<(Natural, Natural)> = NATURAL_EXAMPLES
        .iter()
        .map(|e| (nat(e.a), nat(e.b)))
        .collect();
    for (a, b) in [
        // §7 tangency at two points (complex-conjugate plane pair)
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cone vertex=0,0,2 axis=0,1,0 tan2=3",
        ),
        // §5.1 isolated vertex and crossing vertex
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cone vertex=0,1,0 axis=0,1,0 tan2=1",
        ),
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cone vertex=0,1,0 axis=1,1,0 tan2=3",
        ),
        // tangent cylinders (one point) and crossing ones
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,2 axis=0,1,0 radius2=1",
        ),
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,1 axis=0,1,0 radius2=1",
        ),
        // common ruling: a line and a twisted cubic
        (
            "cylinder point=0,0,0 axis=0,0,1 radius2=1",
            "cone vertex=1,0,0 axis=1,1,1 tan2=2",
        ),
        (
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cone vertex=2,2,0 axis=1,2,1 tan2=1/3",
        ),
        // sphere tangent to a cylinder, off the axis
        (
            "sphere center=3,0,0 radius2=4",
            "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        ),
        (
            "sphere center=2,0,0 radius2=4",
            "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        ),
        (
            "sphere center=0,4,0 radius2=8",
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        ),
        (
            "sphere center=9,0,0 radius2=1",
            "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        ),
        (
            "sphere center=1,1,0 radius2=1/2",
            "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        ),
        // empty skew
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,3 axis=0,1,0 radius2=1",
        ),
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cone vertex=0,0,3 axis=0,1,0 tan2=1",
        ),
        // generic skew curves
        (
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cone vertex=1,5,2 axis=1,2,3 tan2=1/2",
        ),
    ] {
        pairs.push((nat(a), nat(b)));
    }
    let mut fast = 0;
    for (a, b) in &pairs {
        for (x, y) in [(a, b), (b, a)] {
            if same_answer(x, y).unwrap_or_else(|e| panic!("{e}")) {
                fast += 1;
            }
        }
    }
    // every example but the few Segre types the fast route leaves to the
    // complete one takes the fast route
    assert!(
        fast * 10 >= pairs.len() * 2 * 9,
        "only {fast} of {} fast",
        2 * pairs.len()
    );
}

/// A random natural quadric with small integer data.
fn quadric() -> impl Strategy<Value = Natural> {
    let pt = (-3i64..4, -3i64..4, -3i64..4);
    let ax = (-2i64..3, -2i64..3, -2i64..3).prop_filter("axis", |a| *a != (0, 0, 0));
    (0u8..3, pt, ax, 1i64..7, 1i64..4).prop_map(|(k, p, a, n, d)| {
        nat(&match k {
            0 => format!("sphere center={} radius2={n}/{d}", v(p)),
            1 => format!("cylinder point={} axis={} radius2={n}/{d}", v(p), v(a)),
            _ => format!("cone vertex={} axis={} tan2={n}/{d}", v(p), v(a)),
        })
    })
}

/// Pairs built to be degenerate, by family.
fn degenerate() -> impl Strategy<Value = (Natural, Natural)> {
    let small = -2i64..3;
    let ax = (-2i64..3, -2i64..3, -2i64..3).prop_filter("axis", |a| *a != (0, 0, 0));
    (
        0u8..13,
        (small.clone(), small.clone(), small),
        ax.clone(),
        ax,
        1i64..5,
        1i64..4,
        1i64..4,
        0u8..2,
    )
        .prop_map(|(fam, p, a1, a2, r, s, t, c)| {
            let kind2 = |pt: String, ax: String, par: String| {
                if c == 0 {
                    format!("cylinder point={pt} axis={ax} radius2={par}")
                } else {
                    format!("cone vertex={pt} axis={ax} tan2={par}")
                }
            };
            let (x, y) = match fam {
                // common vertex
                0 => (
                    format!("cone vertex={} axis={} tan2={r}/{s}", v(p), v(a1)),
                    format!("cone vertex={} axis={} tan2={t}/{s}", v(p), v(a2)),
                ),
                // parallel axes, equal or different parameters
                1 => (
                    kind2(v(p), v(a1), format!("{r}")),
                    kind2(
                        v((p.0 + s, p.1 - t, p.2)),
                        v((2 * a1.0, 2 * a1.1, 2 * a1.2)),
                        format!("{}", if t == 1 { r } else { t }),
                    ),
                ),
                // equal radii, axes meeting at p: two cylinders (conics)
                2 => (
                    format!("cylinder point={} axis={} radius2={r}", v(p), v(a1)),
                    format!("cylinder point={} axis={} radius2={r}", v(p), v(a2)),
                ),
                // a common inscribed sphere (radius² 1 at p): cone with
                // vertex p + s·a1, |V − O|² = s²|a1|², t2 = 1/(s²|a1|² − 1)
                3 => {
                    let n2 = s * s * (a1.0 * a1.0 + a1.1 * a1.1 + a1.2 * a1.2);
                    let vtx = (p.0 + s * a1.0, p.1 + s * a1.1, p.2 + s * a1.2);
                    let other = if c == 0 {
                        format!("cylinder point={} axis={} radius2=1", v(p), v(a2))
                    } else {
                        format!(
                            "cone vertex={} axis={} tan2=1/{}",
                            v((p.0 + a2.0 * 2, p.1 + a2.1 * 2, p.2 + a2.2 * 2)),
                            v(a2),
                            4 * (a2.0 * a2.0 + a2.1 * a2.1 + a2.2 * a2.2) - 1
                        )
                    };
                    if n2 > 1 {
                        (
                            format!("cone vertex={} axis={} tan2=1/{}", v(vtx), v(a1), n2 - 1),
                            other,
                        )
                    } else {
                        (
                            format!("cylinder point={} axis={} radius2=1", v(p), v(a1)),
                            other,
                        )
                    }
                }
                // a cone vertex on a cylinder: V = p + u with u ⊥ axis, r² = |u|²
                4 => {
                    let ax = (0, 0, 1);
                    let u = (r, s - 2, 0);
                    let rr = u.0 * u.0 + u.1 * u.1;
                    (
                        format!("cylinder point={} axis={} radius2={rr}", v(p), v(ax)),
                        format!(
                            "cone vertex={} axis={} tan2={t}/{s}",
                            v((p.0 + u.0, p.1 + u.1, p.2 + u.2)),
                            v(a2)
                        ),
                    )
                }
                // a cone vertex on a sphere
                5 => {
                    let u = (r, s - 2, t - 2);
                    let rr = u.0 * u.0 + u.1 * u.1 + u.2 * u.2;
                    (
                        format!("sphere center={} radius2={rr}", v(p)),
                        format!(
                            "cone vertex={} axis={} tan2={t}/{s}",
                            v((p.0 + u.0, p.1 + u.1, p.2 + u.2)),
                            v(a2)
                        ),
                    )
                }
                // tangent cylinders: perpendicular axes at distance r1 + r2
                6 => (
                    format!("cylinder point={} axis=1,0,0 radius2={}", v(p), r * r),
                    format!(
                        "cylinder point={} axis=0,1,0 radius2={}",
                        v((p.0, p.1, p.2 + r + s)),
                        s * s
                    ),
                ),
                // a sphere touching a cylinder (outside or inside) off the axis
                7 => (
                    format!(
                        "sphere center={} radius2={}",
                        v((p.0 + r + s * (t - 2), p.1, p.2)),
                        s * s
                    ),
                    format!("cylinder point={} axis=0,0,1 radius2={}", v(p), r * r),
                ),
                // common axis
                8 => (
                    kind2(v(p), v(a1), format!("{r}/{s}")),
                    format!(
                        "cone vertex={} axis={} tan2={t}",
                        v((p.0 + a1.0 * s, p.1 + a1.1 * s, p.2 + a1.2 * s)),
                        v(a1)
                    ),
                ),
                // §7: a cylinder and a cone touching at two points (the
                // complex-conjugate plane pair), scaled by r
                10 => (
                    format!("cylinder point={} axis=1,0,0 radius2={}", v(p), r * r),
                    format!(
                        "cone vertex={} axis=0,1,0 tan2=3",
                        v((p.0, p.1, p.2 + 2 * r))
                    ),
                ),
                // a common ruling: a cone with its vertex on a cylinder and a
                // generator parallel to the cylinder's axis (tan²α from the
                // angle between the cone's axis and the z-axis)
                11 => {
                    let u = (r, s - 2, 0);
                    let ax = (
                        if a2.0 == 0 && a2.1 == 0 { 1 } else { a2.0 },
                        a2.1,
                        if a2.2 == 0 { 1 } else { a2.2 },
                    );
                    (
                        format!(
                            "cylinder point={} axis=0,0,1 radius2={}",
                            v(p),
                            u.0 * u.0 + u.1 * u.1
                        ),
                        format!(
                            "cone vertex={} axis={} tan2={}/{}",
                            v((p.0 + u.0, p.1 + u.1, p.2)),
                            v(ax),
                            ax.0 * ax.0 + ax.1 * ax.1,
                            ax.2 * ax.2
                        ),
                    )
                }
                // two cones sharing a generator: the second vertex on a line
                // d of the first cone through its vertex
                12 => {
                    // first cone: axis z, tan² = (d0² + d1²)/d2² for d = (a1.0, a1.1, 1)
                    let d = (a1.0, a1.1, 1);
                    let t1 = d.0 * d.0 + d.1 * d.1;
                    let v2 = (p.0 + s * d.0, p.1 + s * d.1, p.2 + s * d.2);
                    let dot = d.0 * a2.0 + d.1 * a2.1 + d.2 * a2.2;
                    let cr = (
                        d.1 * a2.2 - d.2 * a2.1,
                        d.2 * a2.0 - d.0 * a2.2,
                        d.0 * a2.1 - d.1 * a2.0,
                    );
                    let num = cr.0 * cr.0 + cr.1 * cr.1 + cr.2 * cr.2;
                    if t1 == 0 || dot == 0 || num == 0 {
                        (
                            format!("cone vertex={} axis=0,0,1 tan2=1", v(p)),
                            format!(
                                "cone vertex={} axis=1,0,1 tan2=1",
                                v((p.0 + 1, p.1, p.2 + 1))
                            ),
                        )
                    } else {
                        (
                            format!("cone vertex={} axis=0,0,1 tan2={t1}", v(p)),
                            format!(
                                "cone vertex={} axis={} tan2={num}/{}",
                                v(v2),
                                v(a2),
                                dot * dot
                            ),
                        )
                    }
                }
                // a sphere centred on an axis (through the vertex or not)
                _ => {
                    let n2 = a1.0 * a1.0 + a1.1 * a1.1 + a1.2 * a1.2;
                    (
                        format!(
                            "sphere center={} radius2={}",
                            v((p.0 + a1.0, p.1 + a1.1, p.2 + a1.2)),
                            if t == 1 { n2 } else { r }
                        ),
                        kind2(v(p), v(a1), format!("{s}")),
                    )
                }
            };
            (nat(&x), nat(&y))
        })
}

/// A rational rotation (Cayley parameters over a common denominator) and
/// an integer translation.
type Motion = ((i64, i64, i64, i64), (i64, i64, i64));

fn motion() -> impl Strategy<Value = Motion> {
    (
        (-2i64..3, -2i64..3, -2i64..3, 1i64..4),
        (-3i64..4, -3i64..4, -3i64..4),
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    /// Random small-integer pairs: same class and counts.
    #[test]
    fn fast_route_agrees_on_random_pairs(a in quadric(), b in quadric()) {
        same_answer(&a, &b)?;
    }

    /// Degenerate pairs of every family: same class and counts.
    #[test]
    fn fast_route_agrees_on_degenerate_pairs(p in degenerate()) {
        same_answer(&p.0, &p.1)?;
        same_answer(&p.1, &p.0)?;
    }

    /// Degenerate pairs moved by a rational rigid motion: same class and counts.
    #[test]
    fn fast_route_agrees_after_rigid_motions(p in degenerate(), m in motion()) {
        let (a, b) = (moved(&p.0, m.0, m.1), moved(&p.1, m.0, m.1));
        same_answer(&a, &b)?;
    }

    /// Random pairs moved by a rational rigid motion.
    #[test]
    fn fast_route_agrees_on_moved_random_pairs(a in quadric(), b in quadric(), m in motion()) {
        same_answer(&moved(&a, m.0, m.1), &moved(&b, m.0, m.1))?;
    }
}

#[test]
fn dyadic_and_rational_inputs() {
    // the same pair scaled by a power of two and by 1/3: same answers
    let a = nat("cylinder point=0,0,0 axis=1,0,0 radius2=1");
    let b = nat("cone vertex=0,0,2 axis=0,1,0 tan2=3");
    for k in [q(1, 1024), q(1, 3), q(7, 5)] {
        same_answer(&a.scaled(&k), &b.scaled(&k)).unwrap();
    }
    let _ = Q::from(num_bigint::BigInt::from(1));
}

/// The degenerate families reach every branch of the fast route (so the
/// properties above test them all) and never need the complete route.
#[test]
fn degenerate_families_cover_every_branch_of_the_fast_route() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let mut methods = std::collections::BTreeSet::new();
    for i in 0..400 {
        let (a, b) = if i % 2 == 0 {
            degenerate().new_tree(&mut runner).unwrap().current()
        } else {
            let p = degenerate().new_tree(&mut runner).unwrap().current();
            let m = motion().new_tree(&mut runner).unwrap().current();
            (moved(&p.0, m.0, m.1), moved(&p.1, m.0, m.1))
        };
        let fast = classify_with(&a, &b, &ClassifyOptions::default().without_components()).unwrap();
        assert!(
            fast.answered_fast(),
            "{} / {}: {}",
            a.to_short(),
            b.to_short(),
            fast.method
        );
        methods.insert(fast.method);
    }
    for m in [
        "proportional equations",
        "common axis (circles)",
        "sphere centred on the axis (circles)",
        "axial plane: projection conic factors (Lemma 8.1)",
        "pencil: nonsingular quartic",
        "pencil: one singular point (nodal or cuspidal quartic)",
        "pencil: a cone member with imaginary generators (isolated tangency point)",
        "pencil: complex-conjugate plane pair (isolated tangency points)",
        "common ruling: a line and a twisted cubic",
    ] {
        assert!(methods.contains(m), "no degenerate pair reached \"{m}\"");
    }
}
