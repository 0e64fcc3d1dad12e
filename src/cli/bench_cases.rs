//! The general-position inputs of the tangent benchmark (issue 17): a
//! quartic against random rotated small-integer ellipsoids, a rotated
//! `x⁴ + y⁴ + z⁴ − 1/2`, dense S of degree 5, 6 and 8 against a sphere and
//! a rotated ellipsoid, and a cubic with 300-bit coefficients beside the
//! same shape with small ones.  Fixed seeds, so that `quadsect bench`, the
//! tests and `scripts/bench_msolve.py` (through `--dump-systems`) see the
//! same systems.

use super::bench::{Rng, Row};
use crate::geom::{cayley_rotation, rotate};
use crate::number::{Q, q};
use crate::poly::{QMPoly, parse_poly};
use crate::tangent::Ellipsoid;
use num_bigint::BigInt;

/// One input: a name, E and S.
#[derive(Clone, Debug)]
pub struct Case {
    /// Case id.
    pub id: String,
    /// The ellipsoid.
    pub e: QMPoly,
    /// The surface.
    pub s: QMPoly,
}

fn poly(s: &str) -> QMPoly {
    parse_poly(s).expect("benchmark inputs parse")
}

/// A random ellipsoid with small integer coefficients and cross terms, like
/// the issue's `18x² − 12xy + 10xz + 23y² − 24yz + 14z² − 2x + 3y + 2z − 27`.
fn random_ellipsoid(rng: &mut Rng) -> QMPoly {
    loop {
        let d = [rng.int(8, 25), rng.int(8, 25), rng.int(8, 25)];
        let o = [rng.int(-6, 6), rng.int(-6, 6), rng.int(-6, 6)];
        let l = [rng.int(-3, 3), rng.int(-3, 3), rng.int(-3, 3)];
        let c = rng.int(15, 40);
        let text = format!(
            "{}x^2 + {}x*y + {}x*z + {}y^2 + {}y*z + {}z^2 + {}x + {}y + {}z - {c}",
            d[0],
            2 * o[0],
            2 * o[1],
            d[1],
            2 * o[2],
            d[2],
            l[0],
            l[1],
            l[2]
        );
        let p = poly(&text);
        if Ellipsoid::from_poly(&p).is_ok() {
            return p;
        }
    }
}

const LOW_MONOMIALS: [&str; 19] = [
    "x", "y", "z", "x^2", "y^2", "z^2", "x*y", "x*z", "y*z", "x^3", "y^3", "z^3", "x^2*y", "x^2*z",
    "y^2*x", "y^2*z", "z^2*x", "z^2*y", "x*y*z",
];

/// The 100 pairs "quartic against a general ellipsoid": E random
/// (rotated, small integers), `S = x⁴ + y⁴ + z⁴ + a·m₁ + b·m₂ + c` with
/// random monomials `mᵢ` of degree ≤ 3.
pub fn quartic_pairs() -> Vec<Case> {
    let mut rng = Rng(0x5851_f42d_4c95_7f2d);
    (0..100)
        .map(|i| {
            let e = random_ellipsoid(&mut rng);
            let m1 = LOW_MONOMIALS[rng.int(0, 18) as usize];
            let m2 = LOW_MONOMIALS[rng.int(0, 18) as usize];
            let (a, b) = (rng.int(1, 3), rng.int(-3, -1));
            let c = rng.int(-4, 4);
            let s = poly(&format!("x^4+y^4+z^4 + {a}*{m1} + {b}*{m2} + {c}"));
            Case {
                id: format!("quartic_pair_{i}"),
                e,
                s,
            }
        })
        .collect()
}

/// The issue's example pair.
pub fn issue_example() -> Case {
    Case {
        id: "issue_example".into(),
        e: poly("18*x*x+-12*x*y+10*x*z+23*y*y+-24*y*z+14*z*z+-2*x+3*y+2*z-27"),
        s: poly("x^4+y^4+z^4-1*x*y-2"),
    }
}

fn rotation() -> [[Q; 3]; 3] {
    cayley_rotation(&q(1, 3), &q(1, 4), &q(-1, 2))
}

/// `x⁴ + y⁴ + z⁴ − 1/2` rotated by a rational rotation, on the unit sphere
/// and on an axis-parallel ellipsoid.
pub fn rotated_quartic() -> Vec<Case> {
    let s = rotate(&poly("x^4+y^4+z^4-1/2"), &rotation());
    vec![
        Case {
            id: "rotated_quartic_sphere".into(),
            e: poly("x^2+y^2+z^2-1"),
            s: s.clone(),
        },
        Case {
            id: "rotated_quartic_ellipsoid".into(),
            e: poly("x^2+2y^2+3z^2-2"),
            s,
        },
    ]
}

/// All monomials of degree ≤ d with random coefficients in `[-5, 5]`.
fn dense(rng: &mut Rng, d: u32) -> QMPoly {
    let mut terms = Vec::new();
    for a in 0..=d {
        for b in 0..=d - a {
            for c in 0..=d - a - b {
                let mut k = rng.int(-5, 5);
                if a + b + c == d && k == 0 {
                    k = 1;
                }
                terms.push(format!("{k}*x^{a}*y^{b}*z^{c}"));
            }
        }
    }
    poly(&terms.join(" + "))
}

/// The rotated ellipsoid of the dense rows.
pub fn rotated_ellipsoid() -> QMPoly {
    rotate(&poly("2x^2+3y^2+5z^2-7"), &rotation())
}

/// Dense S of degree `d` against the sphere `x² + y² + z² − 4` and against
/// a rotated ellipsoid.
pub fn dense_cases(d: u32) -> Vec<Case> {
    let mut rng = Rng(0x2f69_7c5b_1d37_9e11 ^ d as u64);
    let s = dense(&mut rng, d);
    vec![
        Case {
            id: format!("dense{d}_sphere"),
            e: poly("x^2+y^2+z^2-4"),
            s: s.clone(),
        },
        Case {
            id: format!("dense{d}_rotated_ellipsoid"),
            e: rotated_ellipsoid(),
            s,
        },
    ]
}

/// A dense cubic with random signed `bits`-bit integer coefficients (and
/// the same monomials) against the rotated ellipsoid.
pub fn big_cubic(bits: u32) -> Case {
    let mut rng = Rng(0x7c15_9e37_79b9_4a7f);
    let mut terms = Vec::new();
    for a in 0..=3u32 {
        for b in 0..=3 - a {
            for c in 0..=3 - a - b {
                let k = if bits <= 4 {
                    let k = rng.int(-9, 8);
                    BigInt::from(if k >= 0 { k + 1 } else { k })
                } else {
                    let mut k = BigInt::from(1u8);
                    for _ in 0..bits.div_ceil(32) {
                        k = (k << 32usize) + BigInt::from(rng.next() >> 32);
                    }
                    let k = k >> ((bits.div_ceil(32) * 32 + 1 - bits) as usize);
                    if rng.int(0, 1) == 0 { -k } else { k }
                };
                terms.push(format!("({k})*x^{a}*y^{b}*z^{c}"));
            }
        }
    }
    Case {
        id: format!("cubic_{bits}bit"),
        e: rotated_ellipsoid(),
        s: poly(&terms.join(" + ")),
    }
}

/// The route a report took (for the benchmark table).
pub fn method_name(r: &crate::tangent::TangentReport) -> &'static str {
    analysis_name(&r.certificate.method)
}

/// The name of a route (a non-reduced S: the route inside).
fn analysis_name(a: &crate::tangent::Analysis) -> &'static str {
    use crate::tangent::Analysis;
    match a {
        Analysis::NonReduced(an) => match an.inner() {
            Some(Analysis::Pencil(_)) => "square-free part: pencil",
            Some(Analysis::Lambda(_)) => "square-free part: lambda",
            Some(Analysis::Separable(_)) => "square-free part: separable",
            Some(Analysis::CriticalIdeal(_)) => "square-free part: exact-groebner",
            Some(Analysis::ModularRur(_)) => "square-free part: modular",
            Some(Analysis::Poisson(_)) => "square-free part: poisson",
            Some(Analysis::LevelSets(_)) => "square-free part: level-sets",
            _ => "square-free part",
        },
        Analysis::Constant => "constant",
        Analysis::Pencil(_) => "pencil",
        Analysis::Lambda(_) => "lambda",
        Analysis::Separable(_) => "separable",
        Analysis::CriticalIdeal(_) => "exact-groebner",
        Analysis::ModularRur(an) if an.shift.is_none() => "modular",
        Analysis::ModularRur(_) => "modular-shifted",
        Analysis::Poisson(_) => "poisson",
        Analysis::LevelSets(_) => "level-sets",
        Analysis::Undecided => "none",
    }
}

/// Median seconds of `decide(e, s)` under a time limit (at least three
/// runs and 50 ms), with the last report; `None` when the budget ran out.
pub fn time_case(
    c: &Case,
    limit: std::time::Duration,
) -> (f64, Option<crate::tangent::TangentReport>) {
    time_case_with(c, limit, true)
}

/// [`time_case`] with or without the exact values (`values = false`: the
/// verdict only, [`crate::tangent::TangentOptions::without_values`]).
pub fn time_case_with(
    c: &Case,
    limit: std::time::Duration,
    values: bool,
) -> (f64, Option<crate::tangent::TangentReport>) {
    use crate::budget::Budget;
    let e = match Ellipsoid::from_poly(&c.e) {
        Ok(e) => e,
        Err(_) => return (0.0, None),
    };
    let s = crate::poly::Polynomial::from_inner(c.s.clone());
    let mut opts = crate::tangent::TangentOptions::with_budget(
        Budget::unlimited().with_time_limit(Some(limit)),
    );
    opts.values = values;
    let mut times = Vec::new();
    let mut last = None;
    let start = std::time::Instant::now();
    while times.len() < 3 || (start.elapsed().as_secs_f64() < 0.05 && times.len() < 101) {
        let t = std::time::Instant::now();
        let r = crate::tangent::decide_with(&e, &s, &opts);
        times.push(t.elapsed().as_secs_f64());
        match r {
            Ok(rep) if rep.undecided().is_none() => last = Some(rep),
            _ => return (t.elapsed().as_secs_f64(), None),
        }
        if start.elapsed().as_secs_f64() > 30.0 {
            break;
        }
    }
    times.sort_by(|a, b| a.total_cmp(b));
    (times[times.len() / 2], last)
}

/// Every case of the general-position suite, in table order (the 100
/// quartic pairs first).
pub fn all_cases() -> Vec<Case> {
    let mut all = quartic_pairs();
    all.push(issue_example());
    all.extend(rotated_quartic());
    for d in [5, 6, 8] {
        all.extend(dense_cases(d));
    }
    all.push(big_cubic(300));
    all.push(big_cubic(3));
    all
}

/// The surfaces with a repeated factor of the `nonreduced` suite (issue 35):
/// (id, S).
pub const NONREDUCED_SURFACES: [(&str, &str); 7] = [
    ("square", "(x*y - z)^2"),
    ("cube", "(x*y - z)^3"),
    ("cylinder_sq_plane", "(x^2 + y^2 - 1)^2*(z - 1)"),
    ("plane_sq_plane_cube", "(x + y + z - 1)^2*(x - y)^3"),
    (
        "two_quadrics_squared",
        "(x^2 + 2y^2 - z - 1)^2*(x*y + z^2 - 2)^2",
    ),
    (
        "quadric_sq_quadric_cube",
        "(x^2 + 2y^2 - z - 1)^2*(x*y + z^2 - 2)^3",
    ),
    (
        "sextic_part",
        "(x^3 + y^3 + z^3 + x*y - 2z - 1)^2*(x^2 + y*z - 2)*(x + 2y - z)",
    ),
];

/// The three rotated ellipsoids of the `nonreduced` suite: the dense rows'
/// ellipsoid, and two moved off the origin.
pub fn nonreduced_ellipsoids() -> Vec<(&'static str, QMPoly)> {
    vec![
        ("e1", rotated_ellipsoid()),
        (
            "e2",
            rotate(
                &poly("(x - 1/2)^2/4 + (y + 1)^2 + (z - 1/3)^2/9 - 1"),
                &cayley_rotation(&q(2, 3), &q(-1, 5), &q(1, 2)),
            ),
        ),
        (
            "e3",
            rotate(
                &poly("x^2 + 4y^2 + 2z^2 - 3"),
                &cayley_rotation(&q(1, 1), &q(1, 2), &q(1, 3)),
            ),
        ),
    ]
}

/// The rows of the `nonreduced` suite: full verdict (exact ν, μ, D(u) and
/// certificate) of each surface with a repeated factor against each
/// rotated ellipsoid.
pub fn nonreduced_suite(rows: &mut Vec<Row>) {
    let limit = std::time::Duration::from_secs(10);
    for (sid, s) in NONREDUCED_SURFACES {
        for (eid, e) in nonreduced_ellipsoids() {
            let c = Case {
                id: format!("{sid}_{eid}"),
                e,
                s: poly(s),
            };
            let (t, r) = time_case(&c, limit);
            rows.push(Row {
                suite: "nonreduced",
                id: c.id,
                desc: format!("S = {s}: {}", describe(&r)),
                median: t,
                samples: 3,
                extra: Default::default(),
            });
        }
    }
}

/// A polynomial with its denominators cleared (an integer multiple).
fn integer_multiple(p: &QMPoly) -> QMPoly {
    let l = p.terms().iter().fold(BigInt::from(1), |l, (_, c)| {
        num_integer::Integer::lcm(&l, c.denom())
    });
    p.scale(&Q::from_integer(l))
}

/// Writes the critical system `E, (∇S × ∇E)₁, ₂, ₃` of every case for an
/// outside solver: `DIR/<id>.ms` in msolve's input format (variables,
/// characteristic 0, integer generators), and `DIR/cases.jsonl` with the
/// id, E and S of each case, so that a script can time quadsect and the
/// solver on the same systems.  Returns the number of cases.
pub fn dump_systems(dir: &std::path::Path) -> std::io::Result<usize> {
    use std::io::Write;
    std::fs::create_dir_all(dir)?;
    let cases = all_cases();
    let mut index = std::fs::File::create(dir.join("cases.jsonl"))?;
    for c in &cases {
        let cross = crate::tangent::critical::cross_gradients(&c.s, &c.e);
        let gens: Vec<String> = std::iter::once(&c.e)
            .chain(cross.iter())
            .filter(|g| !g.is_zero())
            .map(|g| integer_multiple(g).to_string_canonical().replace(' ', ""))
            .collect();
        std::fs::write(
            dir.join(format!("{}.ms", c.id)),
            format!("x,y,z\n0\n{}\n", gens.join(",\n")),
        )?;
        let line = serde_json::json!({
            "id": c.id,
            "ellipsoid": c.e.to_string_canonical(),
            "surface": c.s.to_string_canonical(),
        });
        writeln!(index, "{line}")?;
    }
    Ok(cases.len())
}

/// The rows of the general-position benchmark (issue 17).
pub fn general_position_suite(rows: &mut Vec<Row>) {
    let limit = std::time::Duration::from_secs(10);
    let pairs = quartic_pairs();
    let mut per: Vec<(f64, usize, String)> = pairs
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let (t, r) = time_case(c, limit);
            (t, i, describe(&r))
        })
        .collect();
    let modular = per
        .iter()
        .filter(|p| p.2.contains("modular") || p.2.contains("poisson"))
        .count();
    per.sort_by(|a, b| a.0.total_cmp(&b.0));
    rows.push(Row {
        suite: "tangent",
        id: "quartic_pairs_median".into(),
        desc: format!(
            "full verdict, quartic S vs general ellipsoid: median over 100 random pairs ({modular} by a modular route)"
        ),
        median: per[per.len() / 2].0,
        samples: per.len(),
        extra: Default::default(),
    });
    let (t, i, d) = per.last().cloned().expect("100 pairs");
    rows.push(Row {
        suite: "tangent",
        id: "quartic_pairs_max".into(),
        desc: format!("the slowest of the 100 pairs (pair {i}: {d})"),
        median: t,
        samples: per.len(),
        extra: Default::default(),
    });
    let mut vo: Vec<f64> = pairs
        .iter()
        .map(|c| time_case_with(c, limit, false).0)
        .collect();
    vo.sort_by(|a, b| a.total_cmp(b));
    rows.push(Row {
        suite: "tangent",
        id: "quartic_pairs_verdict_only_median".into(),
        desc: "verdict only (no exact values), the same 100 pairs: median".into(),
        median: vo[vo.len() / 2],
        samples: vo.len(),
        extra: Default::default(),
    });
    rows.push(Row {
        suite: "tangent",
        id: "quartic_pairs_verdict_only_max".into(),
        desc: "verdict only, the same 100 pairs: the slowest".into(),
        median: *vo.last().expect("100 pairs"),
        samples: vo.len(),
        extra: Default::default(),
    });
    let mut singles = vec![issue_example()];
    singles.extend(rotated_quartic());
    for d in [5, 6, 8] {
        singles.extend(dense_cases(d));
    }
    for c in singles {
        for values in [true, false] {
            let (t, r) = time_case_with(&c, limit, values);
            let (what, suffix) = mode(values);
            rows.push(tangent_row(
                format!("{}{suffix}", c.id),
                format!("{what} ({})", describe(&r)),
                t,
                3,
            ));
        }
    }
    cubic_rows(rows, limit);
}

/// The description and the id suffix of a timed mode (full or verdict only).
fn mode(values: bool) -> (&'static str, &'static str) {
    if values {
        ("full verdict", "")
    } else {
        ("verdict only, no exact values", "_verdict_only")
    }
}

/// A row of the tangent suite.
fn tangent_row(id: String, desc: String, median: f64, samples: usize) -> Row {
    Row {
        suite: "tangent",
        id,
        desc,
        median,
        samples,
        extra: Default::default(),
    }
}

/// The verdict and the route of a timed case's report.
fn describe(r: &Option<crate::tangent::TangentReport>) -> String {
    match r {
        Some(r) => format!("{}, {}", r.verdict().as_str(), method_name(r)),
        None => "undecided: budget (10 s)".into(),
    }
}

/// The 300-bit and the 3-bit cubic, timed alternately (7 rounds of each),
/// so that their ratio — what coefficient size costs — is measured under
/// the same machine conditions; the ratio is in the description and in
/// the row's `ratio_to_3bit`.
fn cubic_rows(rows: &mut Vec<Row>, limit: std::time::Duration) {
    let (big, small) = (big_cubic(300), big_cubic(3));
    for values in [true, false] {
        let (mut tb, mut ts) = (Vec::new(), Vec::new());
        let (mut rb, mut rs) = (None, None);
        for _ in 0..7 {
            let (t, r) = time_case_with(&big, limit, values);
            tb.push(t);
            rb = r;
            let (t, r) = time_case_with(&small, limit, values);
            ts.push(t);
            rs = r;
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(|a, b| a.total_cmp(b));
            v[v.len() / 2]
        };
        let (mb, ms) = (median(&mut tb), median(&mut ts));
        let ratio = if ms > 0.0 { mb / ms } else { f64::NAN };
        let (what, suffix) = mode(values);
        let mut row = tangent_row(
            format!("{}{suffix}", big.id),
            format!(
                "{what} ({}; {ratio:.1}x the 3-bit cubic, timed alternately)",
                describe(&rb)
            ),
            mb,
            7,
        );
        row.extra
            .insert("ratio_to_3bit".into(), serde_json::json!(ratio));
        rows.push(row);
        rows.push(tangent_row(
            format!("{}{suffix}", small.id),
            format!("{what} ({})", describe(&rs)),
            ms,
            7,
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_are_valid_and_reproducible() {
        let a = quartic_pairs();
        assert_eq!(a.len(), 100);
        for c in &a {
            assert!(Ellipsoid::from_poly(&c.e).is_ok(), "{}", c.id);
            assert_eq!(c.s.total_degree(), Some(4));
        }
        assert_eq!(quartic_pairs()[17].e, a[17].e);
        let big = big_cubic(300);
        let coeff_bits: Vec<u64> = big
            .s
            .terms()
            .iter()
            .map(|(_, c)| c.numer().bits())
            .collect();
        assert!(coeff_bits.iter().all(|&b| b == 300), "{coeff_bits:?}");
        assert_eq!(big_cubic(3).s.len(), big.s.len());
        for d in [5, 6, 8] {
            let cs = dense_cases(d);
            // every monomial of degree d is present
            let top = cs[0]
                .s
                .terms()
                .iter()
                .filter(|(e, _)| e.iter().sum::<u32>() == d)
                .count();
            assert_eq!(top as u32, (d + 1) * (d + 2) / 2);
            assert_eq!(cs[1].s, cs[0].s);
        }
    }
}
