//! `quadsect bench`: median timings of the kernel on the shared benchmark
//! inputs (`../shared/bench/inputs.json`), of the tangent point method, and
//! of the natural-quadric deciders and classification — each beside a
//! reference measured in the same run where one exists in-process (a plain
//! `f64` formula for the predicates).  FLINT, PARI and sympy are timed by
//! `../shared/bench/bench_anchors.py` in the same session; the ratios are in
//! `docs/BENCHMARKS.md`.

use crate::error::{Error, ErrorKind};
use serde_json::{Value, json};
use std::hint::black_box;
use std::time::Instant;

/// One measurement.
#[derive(Clone, Debug)]
pub struct Row {
    /// Suite (`kernel`, `tangent`, `natural`).
    pub suite: &'static str,
    /// Case id.
    pub id: String,
    /// What is timed.
    pub desc: String,
    /// Median seconds per call.
    pub median: f64,
    /// Number of samples.
    pub samples: usize,
    /// Extra JSON fields of the row (`group`, `max_s`, `agrees`, … of the
    /// natural-pair rows).
    pub extra: serde_json::Map<String, Value>,
}

/// Median seconds per call of `f`: calls are repeated inside a sample until
/// it lasts about 25 ms, and at least 5 samples (11 for fast calls) are
/// taken (the same protocol as `bench_anchors.py`).
pub fn measure(f: impl FnMut()) -> (f64, usize) {
    sample(f, 0.025, None, 30.0)
}

/// [`measure`] with a chosen sample length (seconds) and number of samples.
pub fn measure_with(f: impl FnMut(), target: f64, want: usize) -> (f64, usize) {
    sample(f, target, Some(want), 10.0)
}

/// The sampling loop: `want` samples (default 5 for slow calls, 11 for
/// fast ones) of about `target` seconds each, stopping after `limit`
/// seconds once three are taken.
fn sample(mut f: impl FnMut(), target: f64, want: Option<usize>, limit: f64) -> (f64, usize) {
    let t0 = Instant::now();
    f();
    let first = t0.elapsed().as_secs_f64();
    let inner = if first >= target {
        1
    } else {
        ((target / first.max(1e-8)) as usize).max(1)
    };
    let want = want.unwrap_or(if first >= 0.2 { 5 } else { 11 });
    let mut samples = Vec::with_capacity(want);
    if first >= 1.0 {
        samples.push(first);
    }
    let start = Instant::now();
    while samples.len() < want {
        let t = Instant::now();
        for _ in 0..inner {
            f();
        }
        samples.push(t.elapsed().as_secs_f64() / inner as f64);
        if start.elapsed().as_secs_f64() > limit && samples.len() >= 3 {
            break;
        }
    }
    samples.sort_by(|a, b| a.total_cmp(b));
    (samples[samples.len() / 2], samples.len())
}

/// [`measure`] of `f` applied to the items in turn (one item per call).
fn measure_cycled<T>(items: &[T], mut f: impl FnMut(&T)) -> (f64, usize) {
    let mut k = 0;
    measure(|| {
        f(&items[k % items.len()]);
        k += 1;
    })
}

fn zpoly_of(v: &Value) -> Option<crate::poly::ZPoly> {
    let cs: Option<Vec<num_bigint::BigInt>> = v
        .as_array()?
        .iter()
        .map(|c| c.as_str().and_then(|s| s.parse().ok()))
        .collect();
    Some(crate::poly::ZPoly::new(cs?))
}

/// The kernel suite on the shared inputs.
pub fn kernel_suite(inputs: &Value, rows: &mut Vec<Row>) -> Result<(), Error> {
    let bad = || Error::new(ErrorKind::Input, "unexpected format of inputs.json");
    for case in inputs["resultant"].as_array().ok_or_else(bad)? {
        let f = zpoly_of(&case["f"]).ok_or_else(bad)?;
        let g = zpoly_of(&case["g"]).ok_or_else(bad)?;
        let (m, n) = measure(|| {
            black_box(crate::elim::resultant_modular(&f, &g));
        });
        rows.push(Row {
            suite: "kernel",
            id: case["id"].as_str().unwrap_or("?").to_string(),
            desc: "resultant (multi-modular)".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
    }
    for case in inputs["roots"].as_array().ok_or_else(bad)? {
        let p = zpoly_of(&case["p"]).ok_or_else(bad)?;
        let (m, n) = measure(|| {
            black_box(crate::roots::isolate_real_roots(&p));
        });
        rows.push(Row {
            suite: "kernel",
            id: case["id"].as_str().unwrap_or("?").to_string(),
            desc: "exact real-root isolation (VCA)".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
        let (m, n) = measure(|| {
            black_box(crate::roots::SturmSequence::new(&p).count_all());
        });
        rows.push(Row {
            suite: "kernel",
            id: case["id"].as_str().unwrap_or("?").to_string(),
            desc: "Sturm count of real roots".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
    }
    for case in inputs["bivariate"].as_array().ok_or_else(bad)? {
        let mk = |v: &Value| -> Option<crate::poly::ZMPoly> {
            let terms: Option<Vec<_>> = v
                .as_array()?
                .iter()
                .map(|t| {
                    let t = t.as_array()?;
                    let mut e = [0u32; crate::poly::mpoly::NVARS];
                    e[0] = t.first()?.as_u64()? as u32;
                    e[1] = t.get(1)?.as_u64()? as u32;
                    let c: num_bigint::BigInt = match t.get(2)? {
                        Value::String(s) => s.parse().ok()?,
                        Value::Number(n) => n.as_i64()?.into(),
                        _ => return None,
                    };
                    Some((e, c))
                })
                .collect();
            Some(crate::poly::MPoly::from_terms(terms?))
        };
        let f = mk(&case["f"]).ok_or_else(bad)?;
        let g = mk(&case["g"]).ok_or_else(bad)?;
        let (m, n) = measure(|| {
            black_box(crate::elim::resultant_zmpoly(&f, &g, 0));
        });
        rows.push(Row {
            suite: "kernel",
            id: case["id"].as_str().unwrap_or("?").to_string(),
            desc: "bivariate resultant (evaluation/interpolation mod p)".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
    }
    gcd_cases(rows);
    Ok(())
}

/// Integer gcds (the reductions to lowest terms of the exact outputs):
/// Lehmer's gcd on limbs beside num-bigint's binary gcd, on fixed
/// pseudo-random operands — coprime, and with a common factor of three
/// quarters of their bits (a construction's unreduced value).
fn gcd_cases(rows: &mut Vec<Row>) {
    use num_integer::Integer;
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut big = |bits: usize| {
        (0..bits.div_ceil(64)).fold(num_bigint::BigInt::from(1), |acc, _| {
            (acc << 64usize) + num_bigint::BigInt::from(rng.next())
        })
    };
    for bits in [1_000usize, 13_000] {
        let g = big(bits * 3 / 4);
        let cases = [
            ("coprime", big(bits), big(bits)),
            ("common-factor", &g * big(bits / 4), &g * big(bits / 4)),
        ];
        for (what, a, b) in cases {
            for (who, lehmer) in [("Lehmer on limbs", true), ("num-bigint (binary)", false)] {
                let (m, n) = measure(|| {
                    black_box(if lehmer {
                        crate::number::gcd_z(&a, &b)
                    } else {
                        a.gcd(&b)
                    });
                });
                rows.push(Row {
                    suite: "kernel",
                    id: format!("gcd-{bits}-{what}"),
                    desc: format!("integer gcd, {who}"),
                    median: m,
                    samples: n,
                    extra: Default::default(),
                });
            }
        }
    }
}

/// A pseudo-random generator (xorshift) so the benchmark inputs are fixed.
pub(crate) struct Rng(pub(crate) u64);
impl Rng {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    pub(crate) fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % ((hi - lo + 1) as u64)) as i64
    }
}

/// The 16 random rotated ellipsoid pairs (E, S) of the quadric-S
/// benchmark (fixed seed, so runs and profiles compare).
pub fn quadric_pairs() -> Result<Vec<(crate::poly::QMPoly, crate::poly::QMPoly)>, Error> {
    use crate::poly::parse_poly;
    let mut rng = Rng(0x9e3779b97f4a7c15);
    let mut pairs = Vec::new();
    for _ in 0..16 {
        let r = crate::geom::cayley_rotation(
            &crate::number::q(rng.int(-3, 3), rng.int(1, 3)),
            &crate::number::q(rng.int(-3, 3), rng.int(1, 3)),
            &crate::number::q(rng.int(-3, 3), rng.int(1, 3)),
        );
        let e = parse_poly(&format!(
            "{}x^2+{}y^2+{}z^2-{}",
            rng.int(1, 5),
            rng.int(1, 5),
            rng.int(1, 5),
            rng.int(5, 40)
        ))?;
        let s0 = parse_poly(&format!(
            "{}(x-{})^2+{}(y-{})^2+{}(z-{})^2-{}",
            rng.int(1, 5),
            rng.int(-4, 4),
            rng.int(1, 5),
            rng.int(-4, 4),
            rng.int(1, 5),
            rng.int(-4, 4),
            rng.int(1, 20)
        ))?;
        let s = crate::geom::rotate(&s0, &r);
        pairs.push((e, s));
    }
    Ok(pairs)
}

/// The tangent point suite.
pub fn tangent_suite(rows: &mut Vec<Row>) -> Result<(), Error> {
    use crate::poly::parse_poly;
    use crate::tangent::decide_poly;
    let pairs = quadric_pairs()?;
    let (m, n) = measure_cycled(&pairs, |(e, s)| {
        black_box(decide_poly(e, s).ok());
    });
    rows.push(Row {
        suite: "tangent",
        id: "quadric_rotated_pairs".into(),
        desc: "full verdict, quadric S (16 random rotated ellipsoid pairs, cycled)".into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    // each pair on its own: the median over the pairs of their medians is
    // the typical verdict; the slowest pair is reported beside it
    let mut per_pair: Vec<(f64, usize)> = pairs
        .iter()
        .enumerate()
        .map(|(i, (e, s))| {
            let (t, _) = measure(|| {
                black_box(decide_poly(e, s).ok());
            });
            (t, i)
        })
        .collect();
    per_pair.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (slow, which) = per_pair[per_pair.len() - 1];
    rows.push(Row {
        suite: "tangent",
        id: "quadric_pairs_median".into(),
        desc: "full verdict, quadric S: median over the 16 pairs of each pair's median".into(),
        median: per_pair[per_pair.len() / 2].0,
        samples: per_pair.len(),
        extra: Default::default(),
    });
    rows.push(Row {
        suite: "tangent",
        id: "quadric_pairs_slowest".into(),
        desc: format!("full verdict, quadric S: the slowest of the 16 pairs (pair {which})"),
        median: slow,
        samples: per_pair.len(),
        extra: Default::default(),
    });
    for (id, e, s) in [
        ("paper_ex1", "x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1"),
        (
            "paper_ex4",
            "2x^2+3y^2+4z^2-25",
            "(x-1)^4/9+y^2/4+4z^2/23-1",
        ),
    ] {
        let (e, s) = (parse_poly(e)?, parse_poly(s)?);
        let (m, n) = measure(|| {
            black_box(decide_poly(&e, &s).ok());
        });
        rows.push(Row {
            suite: "tangent",
            id: id.into(),
            desc: "full verdict (D(u), exact min/max, certificate)".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
    }
    // Examples 1 and 4 moved by the exact rigid motion of
    // shared/bench/bench_elimination.py (R = Cayley(1/3, 1/4, -1/2),
    // t = (1/2, -1/3, 1)): nothing splits by symmetry any more
    for (id, e, s) in [
        ("paper_ex1_rotated", EX1ROT_E, EX1ROT_S),
        ("paper_ex4_rotated", EX4ROT_E, EX4ROT_S),
    ] {
        let (e, s) = (parse_poly(e)?, parse_poly(s)?);
        let (m, n) = measure(|| {
            black_box(decide_poly(&e, &s).ok());
        });
        rows.push(Row {
            suite: "tangent",
            id: id.into(),
            desc: "full verdict after a rational rigid motion (not separable)".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
    }
    super::bench_cases::general_position_suite(rows);
    Ok(())
}

/// Example 1 moved rigidly (`ex1rot` of shared/bench/bench_elimination.py).
pub const EX1ROT_E: &str = "x^2 - x + y^2 + 2*y/3 + z^2 - 2*z - 851/36";
/// S of `ex1rot`.
pub const EX1ROT_S: &str = "77053*x^2/378225 + 15064*x*y/126075 + 1463*x*z/25215 - 56476*x/42025 + 20957*y^2/168100 + 1469*y*z/16810 + 139529*y/126075 + 2561*z^2/26896 + 65923*z/67240 + 47931433/6051600";
/// Example 4 moved rigidly (`ex4rot`).
pub const EX4ROT_E: &str = "113426*x^2/42025 + 21264*x*y/42025 + 7008*x*z/8405 - 141378*x/42025 + 129099*y^2/42025 - 13944*y*z/8405 + 145154*y/42025 + 5428*z^2/1681 - 62432*z/8405 - 5010049/252150";
/// S of `ex4rot`.
pub const EX4ROT_S: &str = "279841*x^4/25431849 - 389344*x^3*y/8477283 - 389344*x^3*z/8477283 - 1776382*x^3/25431849 + 203136*x^2*y^2/2825761 + 406272*x^2*y*z/2825761 + 617872*x^2*y/2825761 + 203136*x^2*z^2/2825761 + 617872*x^2*z/2825761 + 3281023487*x^2/9748875450 - 141312*x*y^3/2825761 - 423936*x*y^2*z/2825761 - 644736*x*y^2/2825761 - 423936*x*y*z^2/2825761 - 1289472*x*y*z/2825761 - 278394572*x*y/1624812575 - 141312*x*z^3/2825761 - 644736*x*z^2/2825761 - 63784024*x*z/324962515 - 12820478233*x/29246626350 + 36864*y^4/2825761 + 147456*y^3*z/2825761 + 224256*y^3/2825761 + 221184*y^2*z^2/2825761 + 672768*y^2*z/2825761 + 2039680367*y^2/6499250300 + 147456*y*z^3/2825761 + 672768*y*z^2/2825761 + 86064882*y*z/324962515 + 914752541*y/3249625150 + 36864*z^4/2825761 + 224256*z^3/2825761 + 19620064*z^2/64992503 - 161727002*z/974887545 - 157592469077/233973010800";

/// The natural-quadric suite: the Theorem 8.1/8.2 decider against a plain
/// f64 formula on the same random rational pairs, and the full
/// classification per family.
pub fn natural_suite(rows: &mut Vec<Row>) -> Result<(), Error> {
    use crate::natural::deciders::{conic_intersection_thm8, relation, thm8};
    use crate::natural::{Prepared, classify, parse_natural};
    let mut rng = Rng(0x2545f4914f6cdd1d);
    let mut pairs = Vec::new();
    for _ in 0..64 {
        let cone = |rng: &mut Rng| {
            format!(
                "cone vertex={},{},{} axis={},{},0 tan2={}/{}",
                rng.int(-9, 9),
                rng.int(-9, 9),
                0,
                rng.int(1, 9),
                rng.int(-9, 9),
                rng.int(1, 50),
                rng.int(1, 50)
            )
        };
        let a = parse_natural(&cone(&mut rng))?;
        let b = parse_natural(&cone(&mut rng))?;
        pairs.push((a, b));
    }
    let prepared: Vec<(Prepared, Prepared)> = pairs
        .iter()
        .map(|(a, b)| (Prepared::new(a), Prepared::new(b)))
        .collect();
    let (m, n) = measure_cycled(&prepared, |(a, b)| {
        black_box(black_box(a).conic_intersection_thm8(black_box(b)));
    });
    rows.push(Row {
        suite: "natural",
        id: "thm8_decider".into(),
        desc: "Theorem 8.1/8.2 decider, filtered: f64 with a static error bound, exact fallback (prepared quadrics), 64 random cone pairs".into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    let (m, n) = measure_cycled(&prepared, |(a, b)| {
        black_box(black_box(a).conic_intersection_thm8_exact(black_box(b)));
    });
    rows.push(Row {
        suite: "natural",
        id: "thm8_exact_fallback".into(),
        desc: "the filter's exact fallback alone (checked i128, big integers on overflow; prepared quadrics)".into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    let (m, n) = measure_cycled(&pairs, |(a, b)| {
        black_box(conic_intersection_thm8(a, b));
    });
    rows.push(Row {
        suite: "natural",
        id: "thm8_decider_unprepared".into(),
        desc: "conic_intersection_thm8 on unprepared quadrics (i128 fast path, rational fallback)"
            .into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    let mut k = 0;
    let (m, n) = measure(|| {
        let (a, b) = &pairs[k % pairs.len()];
        k += 1;
        if let Some(rel) = relation(a, b) {
            black_box(thm8(a, b, &rel));
        }
    });
    rows.push(Row {
        suite: "natural",
        id: "thm8_decider_rational".into(),
        desc: "the same decider in BigRational only (axes relation + inscribed radii)".into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    // the same predicate as a plain f64 formula (reference; may be wrong)
    let fpairs: Vec<[f64; 12]> = pairs
        .iter()
        .map(|(a, b)| {
            let f = |x: &crate::number::Q| num_traits::ToPrimitive::to_f64(x).unwrap_or(0.0);
            let g = |n: &crate::natural::Natural| -> [f64; 6] {
                match n {
                    crate::natural::Natural::Cone(c) => [
                        f(&c.vertex[0]),
                        f(&c.vertex[1]),
                        f(&c.axis[0]),
                        f(&c.axis[1]),
                        f(&c.t2),
                        0.0,
                    ],
                    _ => [0.0; 6],
                }
            };
            let (x, y) = (g(a), g(b));
            [
                x[0], x[1], x[2], x[3], x[4], 0.0, y[0], y[1], y[2], y[3], y[4], 0.0,
            ]
        })
        .collect();
    let mut k = 0;
    let (mf, nf) = measure(|| {
        let p = &fpairs[k % fpairs.len()];
        k += 1;
        black_box(f64_thm8(black_box(p)));
    });
    rows.push(Row {
        suite: "natural",
        id: "thm8_f64_reference".into(),
        desc: "the same test as a plain f64 formula (reference only: not exact)".into(),
        median: mf,
        samples: nf,
        extra: Default::default(),
    });
    // the same predicate in 3D (cross products, coplanarity test): the
    // formula the exact decider generalises
    let f3: Vec<[[f64; 7]; 2]> = pairs
        .iter()
        .map(|(a, b)| {
            let f = |x: &crate::number::Q| num_traits::ToPrimitive::to_f64(x).unwrap_or(0.0);
            let g = |n: &crate::natural::Natural| -> [f64; 7] {
                match n {
                    crate::natural::Natural::Cone(c) => [
                        f(&c.vertex[0]),
                        f(&c.vertex[1]),
                        f(&c.vertex[2]),
                        f(&c.axis[0]),
                        f(&c.axis[1]),
                        f(&c.axis[2]),
                        f(&c.t2),
                    ],
                    _ => [0.0; 7],
                }
            };
            [g(a), g(b)]
        })
        .collect();
    let (m, n) = measure_cycled(&f3, |p| {
        black_box(f64_thm8_3d(black_box(p)));
    });
    rows.push(Row {
        suite: "natural",
        id: "thm8_f64_reference_3d".into(),
        desc: "the same test as a plain f64 formula in 3D (cross products, coplanarity; reference only: not exact)".into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    let families: [(&str, &str, &str); 8] = [
        (
            "conics",
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,0 axis=0,1,0 radius2=1",
        ),
        (
            "conic_and_line",
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cone vertex=2,2,0 axis=0,1,0 tan2=1",
        ),
        (
            "lines_common_vertex",
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cone vertex=0,0,0 axis=0,1,0 tan2=3",
        ),
        (
            "points_section7",
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cone vertex=0,0,2 axis=0,1,0 tan2=3",
        ),
        (
            "empty_skew",
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,3 axis=0,1,0 radius2=1",
        ),
        (
            "curve_skew",
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cone vertex=1,5,2 axis=1,2,3 tan2=1/2",
        ),
        (
            "curve_5_1_isolated_vertex",
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cone vertex=0,1,0 axis=0,1,0 tan2=1",
        ),
        (
            "spheres_circle",
            "sphere center=0,0,0 radius2=4",
            "sphere center=3,0,0 radius2=4",
        ),
    ];
    let no_components = crate::natural::ClassifyOptions::default().without_components();
    let refereed = no_components.clone().with_referee();
    for (id, a, b) in families {
        let (a, b) = (parse_natural(a)?, parse_natural(b)?);
        let (m, n) = measure(|| {
            black_box(crate::natural::classify_with(&a, &b, &no_components).ok());
        });
        rows.push(Row {
            suite: "natural",
            id: format!("classify_fast_{id}"),
            desc: "fast route: class and counts, no components".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
        let (m, n) = measure(|| {
            black_box(crate::natural::classify_with(&a, &b, &refereed).ok());
        });
        rows.push(Row {
            suite: "natural",
            id: format!("referee_{id}"),
            desc: "class and counts with the referee (lo proved, hi witnessed)".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
        let (m, n) = measure(|| {
            black_box(classify(&a, &b).ok());
        });
        rows.push(Row {
            suite: "natural",
            id: format!("classify_{id}"),
            desc: "full classification with exact components".into(),
            median: m,
            samples: n,
            extra: Default::default(),
        });
    }
    // generic random pairs (skew axes, cones)
    let generic: Vec<(crate::natural::Natural, crate::natural::Natural)> = (0..16)
        .map(|_| {
            let a = parse_natural(&format!(
                "cone vertex={},{},{} axis={},{},{} tan2={}/{}",
                rng.int(-5, 5),
                rng.int(-5, 5),
                rng.int(-5, 5),
                rng.int(1, 5),
                rng.int(-5, 5),
                rng.int(-5, 5),
                rng.int(1, 9),
                rng.int(1, 9)
            ));
            let b = parse_natural(&format!(
                "cylinder point={},{},{} axis={},{},{} radius2={}",
                rng.int(-5, 5),
                rng.int(-5, 5),
                rng.int(-5, 5),
                rng.int(-5, 5),
                rng.int(1, 5),
                rng.int(-5, 5),
                rng.int(1, 9)
            ));
            (a, b)
        })
        .filter_map(|(a, b)| Some((a.ok()?, b.ok()?)))
        .collect();
    let (m, n) = measure_cycled(&generic, |(a, b)| {
        black_box(classify(a, b).ok());
    });
    let (mf, nf) = measure_cycled(&generic, |(a, b)| {
        black_box(crate::natural::classify_with(a, b, &no_components).ok());
    });
    rows.push(Row {
        suite: "natural",
        id: "classify_fast_generic_random".into(),
        desc: "fast route, the same 16 random cone–cylinder pairs (cycled)".into(),
        median: mf,
        samples: nf,
        extra: Default::default(),
    });
    rows.push(Row {
        suite: "natural",
        id: "classify_generic_random".into(),
        desc: "full classification, 16 random cone–cylinder pairs (skew axes, cycled)".into(),
        median: m,
        samples: n,
        extra: Default::default(),
    });
    Ok(())
}

/// The Theorem 8.1 test in f64 for two cones in the plane z = 0 (vertex,
/// axis, tan²): equal inscribed radii at the axes' meeting point.
fn f64_thm8(p: &[f64; 12]) -> bool {
    let (v1, a1, t1) = ([p[0], p[1]], [p[2], p[3]], p[4]);
    let (v2, a2, t2) = ([p[6], p[7]], [p[8], p[9]], p[10]);
    let den = a1[0] * a2[1] - a1[1] * a2[0];
    if den == 0.0 {
        return t1 == t2;
    }
    let s = ((v2[0] - v1[0]) * a2[1] - (v2[1] - v1[1]) * a2[0]) / den;
    let o = [v1[0] + s * a1[0], v1[1] + s * a1[1]];
    let d1 = (o[0] - v1[0]).powi(2) + (o[1] - v1[1]).powi(2);
    let d2 = (o[0] - v2[0]).powi(2) + (o[1] - v2[1]).powi(2);
    d1 * t1 / (1.0 + t1) == d2 * t2 / (1.0 + t2)
}

/// The Theorem 8.1 test in f64 for two cones in space (vertex, axis, tan²).
fn f64_thm8_3d(p: &[[f64; 7]; 2]) -> bool {
    let [x, y] = p;
    let cr = |u: [f64; 3], v: [f64; 3]| {
        [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ]
    };
    let dt = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let (v1, a1, v2, a2) = (
        [x[0], x[1], x[2]],
        [x[3], x[4], x[5]],
        [y[0], y[1], y[2]],
        [y[3], y[4], y[5]],
    );
    let n = cr(a1, a2);
    let nn = dt(n, n);
    if nn == 0.0 {
        return x[6] == y[6];
    }
    let d = [v2[0] - v1[0], v2[1] - v1[1], v2[2] - v1[2]];
    if dt(d, n) != 0.0 {
        return false;
    }
    let s = dt(cr(d, a2), n) / nn;
    let o = [v1[0] + s * a1[0], v1[1] + s * a1[1], v1[2] + s * a1[2]];
    let w1 = [o[0] - v1[0], o[1] - v1[1], o[2] - v1[2]];
    let w2 = [o[0] - v2[0], o[1] - v2[1], o[2] - v2[2]];
    dt(w1, w1) * x[6] / (1.0 + x[6]) == dt(w2, w2) * y[6] / (1.0 + y[6])
}

/// One pair of a pair file (format of `benches/data/natural_pairs.json`).
#[derive(Clone, Debug)]
pub struct BenchPair {
    /// Its name.
    pub name: String,
    /// Its group.
    pub group: String,
    /// First quadric.
    pub a: crate::natural::Natural,
    /// Second quadric.
    pub b: crate::natural::Natural,
    /// The expected class and counts (`{"class", "conics", "lines", "points"}`).
    pub expect: Value,
}

/// The natural-quadric pairs of a pair file.
pub fn read_pairs(path: Option<&str>) -> Result<Vec<BenchPair>, Error> {
    let text = match path {
        None => NATURAL_PAIRS.to_string(),
        Some(p) => std::fs::read_to_string(p)
            .map_err(|e| Error::new(ErrorKind::Io, format!("cannot read {p}: {e}")))?,
    };
    let path = path.unwrap_or("benches/data/natural_pairs.json (built in)");
    let v: Value = serde_json::from_str(&text)
        .map_err(|e| Error::new(ErrorKind::Json, format!("{path}: {e}")))?;
    let bad = |what: &str| Error::new(ErrorKind::Input, format!("{path}: {what}"));
    let mut out = Vec::new();
    for p in v["pairs"]
        .as_array()
        .ok_or_else(|| bad("no \"pairs\" array"))?
    {
        let name = p["name"]
            .as_str()
            .ok_or_else(|| bad("a pair without a name"))?;
        let q = |k: &str| {
            crate::natural::types::from_json(&p[k])
                .map_err(|e| e.context(&format!("{path}: {name}.{k}")))
        };
        out.push(BenchPair {
            name: name.to_string(),
            group: p["group"].as_str().unwrap_or("").to_string(),
            a: q("a")?,
            b: q("b")?,
            expect: p["expect"].clone(),
        });
    }
    Ok(out)
}

/// The per-group tally of [`pairs_suite`].
struct GroupTally {
    name: String,
    times: Vec<(f64, String)>,
    /// The whole answer's times (class, counts and components).
    whole: Vec<(f64, String)>,
    agree: usize,
    fast: usize,
}

/// The input kind of a benchmark group (the table rows): small
/// integers, 53-bit doubles, near-degenerate, Open CASCADE regression pairs,
/// 500-digit decimals.
pub fn input_kind(group: &str) -> &'static str {
    match group {
        g if g.starts_with("class-") || g == "random-int" => "small-integers",
        "double" => "doubles",
        "near-degenerate" => "near-degenerate",
        "occ-regression" => "occ-regression",
        "decimal500" => "decimal500",
        _ => "other",
    }
}

/// The pair suite: the fast classification (no components) timed per
/// pair, its answer checked against the pair's `expect`, one row per pair
/// (`natural-pair`) and one per group (`natural-group`: median over the
/// group's pairs of each pair's median, and the slowest pair).
pub fn pairs_suite(path: Option<&str>, rows: &mut Vec<Row>) -> Result<(), Error> {
    use crate::natural::{ClassifyOptions, classify_with};
    let opts = ClassifyOptions::default().without_components();
    let pairs = read_pairs(path)?;
    let mut groups: Vec<GroupTally> = Vec::new();
    let mut kinds: std::collections::BTreeMap<&'static str, Vec<(f64, f64, String)>> =
        std::collections::BTreeMap::new();
    for BenchPair {
        name,
        group,
        a,
        b,
        expect,
    } in &pairs
    {
        let r = classify_with(a, b, &opts)?;
        let c = &r.counts;
        let agrees = expect["class"].as_str() == Some(c.class.as_str())
            && expect["conics"].as_u64() == Some(c.conics as u64)
            && expect["lines"].as_u64() == Some(c.lines as u64)
            && expect["points"].as_u64() == Some(c.points as u64);
        let (m, n) = measure_with(
            || {
                black_box(classify_with(a, b, &opts).ok());
            },
            0.005,
            7,
        );
        let whole_opts = ClassifyOptions::default();
        let (mw, _) = measure_with(
            || {
                black_box(classify_with(a, b, &whole_opts).ok());
            },
            0.005,
            7,
        );
        let mut extra = serde_json::Map::new();
        extra.insert("group".into(), json!(group));
        extra.insert("agrees".into(), json!(agrees));
        extra.insert("fast".into(), json!(r.answered_fast()));
        extra.insert("method".into(), json!(r.method));
        extra.insert("whole_s".into(), json!(mw));
        extra.insert("kind".into(), json!(input_kind(group)));
        extra.insert(
            "answer".into(),
            json!({"class": c.class.as_str(), "conics": c.conics, "lines": c.lines, "points": c.points}),
        );
        rows.push(Row {
            suite: "natural-pair",
            id: name.clone(),
            desc: format!(
                "fast classification, no components ({}{})",
                c.class.as_str(),
                if agrees {
                    ""
                } else {
                    ", DISAGREES with expect"
                }
            ),
            median: m,
            samples: n,
            extra,
        });
        let g = match groups.iter().position(|g| &g.name == group) {
            Some(k) => &mut groups[k],
            None => {
                groups.push(GroupTally {
                    name: group.clone(),
                    times: Vec::new(),
                    whole: Vec::new(),
                    agree: 0,
                    fast: 0,
                });
                groups.last_mut().expect("just pushed")
            }
        };
        g.times.push((m, name.clone()));
        g.whole.push((mw, name.clone()));
        kinds
            .entry(input_kind(group))
            .or_default()
            .push((mw, m, name.clone()));
        g.agree += usize::from(agrees);
        g.fast += usize::from(r.answered_fast());
    }
    for GroupTally {
        name: group,
        mut times,
        mut whole,
        agree,
        fast,
    } in groups
    {
        times.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (max, slowest) = times[times.len() - 1].clone();
        let mut extra = serde_json::Map::new();
        extra.insert("max_s".into(), json!(max));
        extra.insert("slowest".into(), json!(slowest));
        extra.insert("pairs".into(), json!(times.len()));
        extra.insert("agree".into(), json!(agree));
        extra.insert("fast_route".into(), json!(fast));
        rows.push(Row {
            suite: "natural-group",
            id: group.clone(),
            desc: format!(
                "fast classification: median over {} pairs (slowest {slowest} {}); {agree} agree with expect, {fast} by the fast route",
                times.len(),
                fmt_time(max)
            ),
            median: times[times.len() / 2].0,
            samples: times.len(),
            extra,
        });
        whole.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (wmax, wslowest) = whole[whole.len() - 1].clone();
        let mut extra = serde_json::Map::new();
        extra.insert("max_s".into(), json!(wmax));
        extra.insert("slowest".into(), json!(wslowest));
        extra.insert("pairs".into(), json!(whole.len()));
        rows.push(Row {
            suite: "natural-whole-group",
            id: group,
            desc: format!(
                "whole answer (class, counts, components): median over {} pairs (slowest {wslowest} {})",
                whole.len(),
                fmt_time(wmax)
            ),
            median: whole[whole.len() / 2].0,
            samples: whole.len(),
            extra,
        });
    }
    for (kind, mut v) in kinds {
        v.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (wmax, _, wslowest) = v[v.len() - 1].clone();
        let mut counts: Vec<f64> = v.iter().map(|x| x.1).collect();
        counts.sort_by(f64::total_cmp);
        let mut extra = serde_json::Map::new();
        extra.insert("max_s".into(), json!(wmax));
        extra.insert("slowest".into(), json!(wslowest));
        extra.insert("pairs".into(), json!(v.len()));
        extra.insert("counts_median_s".into(), json!(counts[counts.len() / 2]));
        rows.push(Row {
            suite: "natural-whole-kind",
            id: kind.to_string(),
            desc: format!(
                "whole answer by input kind: median over {} pairs (slowest {wslowest} {}); class and counts only {}",
                v.len(),
                fmt_time(wmax),
                fmt_time(counts[counts.len() / 2])
            ),
            median: v[v.len() / 2].0,
            samples: v.len(),
            extra,
        });
    }
    Ok(())
}

/// The kernel benchmark inputs shipped with the crate (a copy of the team's
/// shared inputs, `benches/data/kernel_inputs.json`), used when no
/// `--inputs` path is given.
pub const KERNEL_INPUTS: &str = include_str!("../../benches/data/kernel_inputs.json");

/// The natural-quadric pair set shipped with the crate
/// (`benches/data/natural_pairs.json`), used when no `--pairs` path is given.
pub const NATURAL_PAIRS: &str = include_str!("../../benches/data/natural_pairs.json");

/// Runs the suites (`kernel`, `tangent`, `nonreduced`, `natural` or `all`); the kernel
/// suite reads `inputs_path` and the natural suite's pair rows `pairs_path`,
/// or the shipped files when they are `None`.
pub fn run(
    suite: &str,
    inputs_path: Option<&str>,
    pairs_path: Option<&str>,
) -> Result<Vec<Row>, Error> {
    let mut rows = Vec::new();
    let all = suite == "all";
    if ![
        "all",
        "kernel",
        "tangent",
        "nonreduced",
        "natural",
        "figures",
        "contact",
    ]
    .contains(&suite)
    {
        return Err(Error::new(
            ErrorKind::Input,
            format!(
                "unknown benchmark suite \"{suite}\" (kernel, tangent, nonreduced, natural, figures, contact or all)"
            ),
        ));
    }
    if all || suite == "kernel" {
        let inputs_path = inputs_path.unwrap_or("benches/data/kernel_inputs.json (built in)");
        let text = match inputs_path {
            p if p.ends_with("(built in)") => KERNEL_INPUTS.to_string(),
            p => std::fs::read_to_string(p).map_err(|e| {
                Error::new(
                    ErrorKind::Io,
                    format!("cannot read {p}: {e} (use --inputs PATH)"),
                )
            })?,
        };
        let v: Value = serde_json::from_str(&text)
            .map_err(|e| Error::new(ErrorKind::Json, format!("{inputs_path}: {e}")))?;
        kernel_suite(&v, &mut rows)?;
    }
    if all || suite == "tangent" {
        tangent_suite(&mut rows)?;
    }
    if all || suite == "nonreduced" {
        super::bench_cases::nonreduced_suite(&mut rows);
    }
    if all || suite == "natural" {
        natural_suite(&mut rows)?;
        pairs_suite(pairs_path, &mut rows)?;
    }
    if all || suite == "figures" {
        figures_suite(&mut rows)?;
    }
    if suite == "contact" {
        super::bench_contact::contact_suite(pairs_path, &mut rows)?;
    }
    Ok(rows)
}

/// The pictures of the papers' examples (issue 38): the SVG text from an
/// answer already computed, and the PNG rendered from it (fonts loaded
/// before timing: once per process).
fn figures_suite(rows: &mut Vec<Row>) -> Result<(), Error> {
    use super::examples::{natural::NATURAL_EXAMPLES, tangent::PAPER_004};
    let mut pictures: Vec<(String, Box<dyn Fn() -> String>)> = Vec::new();
    for (i, ex) in NATURAL_EXAMPLES.iter().enumerate() {
        let r = crate::natural::classify(&ex.a.parse()?, &ex.b.parse()?)?;
        pictures.push((format!("natural_{:02}", i + 1), Box::new(move || r.svg())));
    }
    for (i, ex) in PAPER_004.iter().enumerate() {
        let r = crate::tangent::decide_str(ex.ellipsoid, ex.surface)?;
        pictures.push((format!("tangent_{:02}", i + 1), Box::new(move || r.svg())));
    }
    let _ = crate::svg_to_png(&pictures[0].1())?;
    for (id, draw) in &pictures {
        let (t, n) = measure(|| {
            std::hint::black_box(draw());
        });
        rows.push(Row {
            suite: "figures",
            id: format!("{id}_svg"),
            desc: "the answer's picture as SVG text".into(),
            median: t,
            samples: n,
            extra: Default::default(),
        });
        let svg = draw();
        let (t, n) = measure_with(
            || {
                std::hint::black_box(crate::svg_to_png(&svg).ok());
            },
            0.05,
            5,
        );
        rows.push(Row {
            suite: "figures",
            id: format!("{id}_png"),
            desc: "the SVG rendered to PNG (resvg)".into(),
            median: t,
            samples: n,
            extra: Default::default(),
        });
    }
    Ok(())
}

/// Human-readable seconds.
pub fn fmt_time(s: f64) -> String {
    if s < 1e-6 {
        format!("{:.1} ns", s * 1e9)
    } else if s < 1e-3 {
        format!("{:.2} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// The rows as JSON.
pub fn to_json(rows: &[Row]) -> Value {
    Value::Array(
        rows.iter()
            .map(|r| {
                let mut o = json!({"suite": r.suite, "id": r.id, "desc": r.desc, "median_s": r.median, "samples": r.samples});
                if let Value::Object(m) = &mut o {
                    m.extend(r.extra.clone());
                }
                o
            })
            .collect(),
    )
}

/// The rows as a Markdown table.
pub fn to_markdown(rows: &[Row]) -> String {
    let mut s = String::from("| suite | case | what | median | samples |\n|---|---|---|---|---|\n");
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} |\n",
            r.suite,
            r.id,
            r.desc,
            fmt_time(r.median),
            r.samples
        ));
    }
    s
}
