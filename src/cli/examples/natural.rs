//! Natural-quadric examples mirroring the figures of paper 000, near misses
//! that a floating-point implementation gets wrong, and one example per
//! class of contract §4.

use super::ExampleResult;
use crate::natural::{ClassifyOptions, classify_with, parse_natural};
use crate::report::{natural_human, natural_json};

/// An example pair with the answer the paper (or elementary geometry)
/// predicts.
pub struct NaturalExample {
    /// Title.
    pub title: &'static str,
    /// First quadric (short syntax).
    pub a: &'static str,
    /// Second quadric.
    pub b: &'static str,
    /// What the paper says (or the expected class).
    pub expected: &'static str,
    /// The class the example must get.
    pub class: &'static str,
    /// Counts (conics, lines, points).
    pub counts: (usize, usize, usize),
    /// A float computation that gets it wrong (near misses).
    pub float_note: Option<&'static str>,
    /// Where the paper is wrong on this example.
    pub paper_error: Option<&'static str>,
}

/// The examples.
pub const NATURAL_EXAMPLES: &[NaturalExample] = &[
    NaturalExample {
        title: "Two equal cylinders with perpendicular axes (Theorem 8.1: two ellipses)",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cylinder point=0,0,0 axis=0,1,0 radius2=1",
        expected: "Corollary 8.1: r1 = r2, conic intersection; the ellipses lie in the planes x = y and x = -y",
        class: "conics",
        counts: (2, 0, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "A cone and a cylinder with a common inscribed sphere (Figure 1, Theorem 8.1)",
        a: "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
        b: "cylinder point=0,0,0 axis=0,1,0 radius2=1",
        expected: "Corollary 8.1: d sin α = 2·(1/2) = 1 = r: two conics",
        class: "conics",
        counts: (2, 0, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Two cones with parallel axes and equal angles (Theorem 8.2)",
        a: "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        b: "cone vertex=3,0,1 axis=0,0,1 tan2=1",
        expected: "Theorem 8.2: equal angles give conic intersection; one affine conic, the other at infinity (docs/errata.md)",
        class: "conics",
        counts: (1, 0, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Near miss of Theorem 8.1: radius² off by 10^-20",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cylinder point=0,0,0 axis=0,1,0 radius2=1.00000000000000000001",
        expected: "r1² ≠ r2²: no conic; a space quartic",
        class: "curve",
        counts: (0, 0, 0),
        float_note: Some(
            "in f64, 1.00000000000000000001 == 1.0, so a float test of r1² = r2² reports two ellipses",
        ),
        paper_error: None,
    },
    NaturalExample {
        title: "Near miss of Corollary 8.1 (cone–cylinder): radius² off by 10^-20",
        a: "cone vertex=2,0,0 axis=1,0,0 sin2=1/4",
        b: "cylinder point=0,0,0 axis=0,1,0 radius2=0.99999999999999999999",
        expected: "d² sin²α = 1 ≠ r²: no conic",
        class: "curve",
        counts: (0, 0, 0),
        float_note: Some(
            "in f64, 0.99999999999999999999 rounds to 1.0 = d² sin²α: a float test reports two conics",
        ),
        paper_error: None,
    },
    NaturalExample {
        title: "Near miss of Theorem 8.2: cone angles tan² 1 and 1 + 10^-20",
        a: "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        b: "cone vertex=3,0,1 axis=0,0,1 tan2=1.00000000000000000001",
        expected: "different angles: no conic",
        class: "curve",
        counts: (0, 0, 0),
        float_note: Some("in f64 both tan² are 1.0: a float test reports a conic"),
        paper_error: None,
    },
    NaturalExample {
        title: "Theorem 5.1: a double line V1V2 and a parabola (P at infinity)",
        a: "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        b: "cone vertex=2,2,0 axis=0,1,0 tan2=1",
        expected: "§5.2: both vertices on the other's skeletal lines: the double line V1V2 and a residual conic, a parabola because the other two skeletal lines are parallel",
        class: "conic-and-line",
        counts: (1, 1, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Theorem 6.1: two cones with a common vertex, four lines",
        a: "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        b: "cone vertex=0,0,0 axis=0,1,0 tan2=3",
        expected: "§6: the planes through L1, L2 cut four real lines through V",
        class: "lines",
        counts: (0, 4, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Theorem 6.1: common vertex with only the vertex real",
        a: "cone vertex=0,0,0 axis=1,0,0 tan2=1/10",
        b: "cone vertex=0,0,0 axis=0,1,0 tan2=1/10",
        expected: "§6 case (c): both squared heights negative, the lines are imaginary: only the vertex",
        class: "points",
        counts: (0, 0, 1),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Two parallel cylinders: two lines",
        a: "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        b: "cylinder point=1,0,0 axis=0,0,1 radius2=1",
        expected: "§6: all rulings parallel: two lines",
        class: "lines",
        counts: (0, 2, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "§5.1: a cone vertex on the cylinder, an isolated point on a quartic",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cone vertex=0,1,0 axis=0,1,0 tan2=1",
        expected: "Lemma 5.1: no conic or line; the skeletal line through V lies outside the solid cone, so V is isolated (docs/errata.md)",
        class: "curve",
        counts: (0, 0, 1),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "§5.1 with the skeletal line inside the cone: branches cross at the vertex",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cone vertex=0,1,0 axis=1,1,0 tan2=3",
        expected: "the paper's 'isolated point' claim fails here (docs/errata.md): real branches cross at V",
        class: "curve",
        counts: (0, 0, 0),
        float_note: None,
        paper_error: Some(
            "§5.1 says the intersection is 'a space quartic with one isolated point'; with the skeletal line through V inside the solid cone, real branches cross at V and there is no isolated point",
        ),
    },
    NaturalExample {
        title: "Skew cylinders at distance r1 + r2: one tangency point",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cylinder point=0,0,2 axis=0,1,0 radius2=1",
        expected: "§7, cylinder rule: tangent at one point of the common perpendicular",
        class: "points",
        counts: (0, 0, 1),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Corollary 7.1: a cone tangent to a cylinder at two points",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cone vertex=0,0,2 axis=0,1,0 tan2=3",
        expected: "§7, case 4: d1 = d2 = r, two tangency points",
        class: "points",
        counts: (0, 0, 2),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "Skew cylinders apart",
        a: "cylinder point=0,0,0 axis=1,0,0 radius2=1",
        b: "cylinder point=0,0,3 axis=0,1,0 radius2=1",
        expected: "§7, case 1: disjoint",
        class: "empty",
        counts: (0, 0, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "A cone vertex on a cylinder with a common ruling: a line and a twisted cubic",
        a: "cylinder point=0,0,0 axis=0,0,1 radius2=1",
        b: "cone vertex=1,0,0 axis=1,1,1 tan2=2",
        expected: "missing from Table 1 (docs/errata.md): the common ruling plus a twisted cubic",
        class: "curve",
        counts: (0, 1, 0),
        float_note: None,
        paper_error: Some("Table 1 has no row for a line plus a twisted cubic"),
    },
    NaturalExample {
        title: "Two spheres meeting in a circle",
        a: "sphere center=0,0,0 radius2=4",
        b: "sphere center=3,0,0 radius2=4",
        expected: "a circle in the radical plane x = 3/2",
        class: "conics",
        counts: (1, 0, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "A sphere inscribed in a cylinder: a double circle",
        a: "sphere center=1,2,3 radius2=2",
        b: "cylinder point=0,2,3 axis=1,0,0 radius2=2",
        expected: "centre on the axis, equal radii: the surfaces touch along a circle",
        class: "conics",
        counts: (1, 0, 0),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "A sphere through a cone's vertex, centred on its axis: a circle and the vertex",
        a: "sphere center=0,0,2 radius2=4",
        b: "cone vertex=0,0,0 axis=0,0,1 tan2=1",
        expected: "a circle at z = 2 and the isolated vertex",
        class: "conics",
        counts: (1, 0, 1),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "A sphere touching both nappes of a cone",
        a: "sphere center=0,4,0 radius2=8",
        b: "cone vertex=0,0,0 axis=1,0,0 tan2=1",
        expected: "distance 2√2 to both skeletal lines: two tangency points",
        class: "points",
        counts: (0, 0, 2),
        float_note: None,
        paper_error: None,
    },
    NaturalExample {
        title: "The same cylinder written twice",
        a: "cylinder point=0,0,0 axis=1,1,0 radius2=2",
        b: "cylinder point=3,3,0 axis=-2,-2,0 radius2=2",
        expected: "proportional equations",
        class: "same-surface",
        counts: (0, 0, 0),
        float_note: None,
        paper_error: None,
    },
];

/// Runs the natural-quadric examples.
pub fn natural_examples() -> Vec<ExampleResult> {
    NATURAL_EXAMPLES
        .iter()
        .map(|ex| {
            let command = format!("quadsect natural '{}' '{}'", ex.a, ex.b);
            // with the papers' deciders by the reference route (checked
            // against the answer)
            let run = || -> Result<crate::natural::NaturalReport, crate::Error> {
                let (a, b) = (parse_natural(ex.a)?, parse_natural(ex.b)?);
                classify_with(&a, &b, &ClassifyOptions::default().with_deciders())
            };
            match run() {
                Ok(r) => {
                    let mut disc: Vec<String> =
                        ex.paper_error.iter().map(|e| e.to_string()).collect();
                    let got = (r.conics(), r.lines(), r.points());
                    if r.class.as_str() != ex.class || got != ex.counts {
                        disc.push(format!(
                            "quadsect computed {} {:?}, the expectation is {} {:?} — please report",
                            r.class.as_str(),
                            got,
                            ex.class,
                            ex.counts
                        ));
                    }
                    let mut ours = natural_human(&r);
                    if let Some(f) = ex.float_note {
                        ours.push_str(&format!("floating point: {f}\n"));
                    }
                    ExampleResult {
                        source: "paper 000".into(),
                        title: ex.title.into(),
                        command,
                        ours,
                        ours_json: natural_json(&r),
                        paper: ex.expected.into(),
                        discrepancies: disc,
                        figure: Some(r.svg()),
                    }
                }
                Err(e) => ExampleResult {
                    source: "paper 000".into(),
                    title: ex.title.into(),
                    command,
                    ours: format!("error: {e}\n"),
                    ours_json: serde_json::Value::Null,
                    paper: ex.expected.into(),
                    discrepancies: vec![format!("error: {e}")],
                    figure: None,
                },
            }
        })
        .collect()
}
