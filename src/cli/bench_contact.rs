//! `quadsect bench contact`: the ellipsoid-contact predicate per pair on
//! sets of pairs (random, near contact, exactly touching), beside a
//! plain-`f64` Wang–Wang–Kim test, with each one's wrong answers against
//! the exact labels.  Pairs come from a JSON-lines file (`--pairs`, as
//! written by `scripts/bench_contact.py`: `{"id", "set", "expect", "a",
//! "b"}` with poses of JSON numbers) or, without one, from a built-in
//! generator (labels from the exact route).

use super::bench::Row;
use crate::contact::{self, Contact, Pose, PoseArrays};
use crate::{Error, ErrorKind};
use serde_json::{Value, json};
use std::time::Instant;

struct Pair {
    set: String,
    a: Pose,
    b: Pose,
    expect: Option<Contact>,
}

fn pose_of(v: &Value, what: &str) -> Result<Pose, Error> {
    let bad = || {
        Error::new(
            ErrorKind::BadField,
            format!("{what}: expected center, semi_axes, rotation of JSON numbers"),
        )
    };
    let num = |x: &Value| x.as_f64().ok_or_else(bad);
    let v3 = |key: &str| -> Result<[f64; 3], Error> {
        let a = v
            .get(key)
            .and_then(Value::as_array)
            .filter(|a| a.len() == 3)
            .ok_or_else(bad)?;
        Ok([num(&a[0])?, num(&a[1])?, num(&a[2])?])
    };
    let rows = v
        .get("rotation")
        .and_then(Value::as_array)
        .filter(|a| a.len() == 3)
        .ok_or_else(bad)?;
    let mut m = [[0.0; 3]; 3];
    for (i, row) in rows.iter().enumerate() {
        let r = row.as_array().filter(|a| a.len() == 3).ok_or_else(bad)?;
        for j in 0..3 {
            m[i][j] = num(&r[j])?;
        }
    }
    Pose::new(v3("center")?, v3("semi_axes")?, m).map_err(|e| e.context(what))
}

fn contact_of(s: &str) -> Option<Contact> {
    match s {
        "separated" => Some(Contact::Separated),
        "touching" => Some(Contact::Touching),
        "overlapping" => Some(Contact::Overlapping),
        _ => None,
    }
}

fn read_pairs(path: &str) -> Result<Vec<Pair>, Error> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::new(ErrorKind::Io, format!("cannot read {path}: {e}")))?;
    let mut out = vec![];
    for (n, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
    {
        let at = format!("{path}:{}", n + 1);
        let v: Value = serde_json::from_str(line)
            .map_err(|e| Error::new(ErrorKind::Json, format!("{at}: {e}")))?;
        out.push(Pair {
            set: v
                .get("set")
                .and_then(Value::as_str)
                .unwrap_or("pairs")
                .to_string(),
            a: pose_of(&v["a"], &format!("{at}: a"))?,
            b: pose_of(&v["b"], &format!("{at}: b"))?,
            expect: v.get("expect").and_then(Value::as_str).and_then(contact_of),
        });
    }
    Ok(out)
}

/// A rotation-matrix maker from a stream of uniform numbers.
type RotFn<'a> = dyn FnMut(&mut dyn FnMut() -> f64) -> [[f64; 3]; 3] + 'a;

/// A deterministic generator (xorshift) of the three sets.
fn generated() -> Vec<Pair> {
    let mut s: u64 = 0x2545F4914F6CDD1D;
    let mut u = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut rot = |u: &mut dyn FnMut() -> f64| {
        let q = [u() - 0.5, u() - 0.5, u() - 0.5, u() - 0.5];
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        let [w, x, y, z] = q.map(|v| v / n);
        [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ]
    };
    let mut out = vec![];
    let random_pose = |u: &mut dyn FnMut() -> f64, rot: &mut RotFn| {
        let c = [4.0 * u() - 2.0, 4.0 * u() - 2.0, 4.0 * u() - 2.0];
        let r = [0.2 + u(), 0.2 + u(), 0.2 + u()];
        Pose::new(c, r, rot(u)).unwrap()
    };
    for _ in 0..5000 {
        let a = random_pose(&mut u, &mut rot);
        let b = random_pose(&mut u, &mut rot);
        out.push(Pair {
            set: "random".into(),
            a,
            b,
            expect: None,
        });
    }
    for k in 3..=12 {
        for i in 0..100 {
            let a = random_pose(&mut u, &mut rot);
            // B: A reflected through a boundary point p, moved by ±10^-k (p − c)
            let d = [u() - 0.5, u() - 0.5, u() - 0.5];
            let n = d.iter().map(|x| x * x).sum::<f64>().sqrt();
            let w: [f64; 3] = std::array::from_fn(|i| d[i] / n * a.semi_axes()[i]);
            let m = a.matrix();
            let p: [f64; 3] = std::array::from_fn(|i| {
                a.center()[i] + (0..3).map(|j| m[i][j] * w[j]).sum::<f64>()
            });
            let s = if i % 2 == 0 { 1.0 } else { -1.0 } * 10f64.powi(-k);
            let cb: [f64; 3] =
                std::array::from_fn(|i| 2.0 * p[i] - a.center()[i] + s * (p[i] - a.center()[i]));
            let b = Pose::new(cb, a.semi_axes(), m.map(|r| r.map(|x| -x))).unwrap();
            out.push(Pair {
                set: "near".into(),
                a,
                b,
                expect: None,
            });
        }
    }
    for _ in 0..200 {
        // exactly touching, in the convention |D⁻¹Rᵀ(x − c)| ≤ 1: R the
        // integer matrix of a quaternion (a, b, c, d) with RRᵀ = N²I,
        // N = a² + b² + c² + d² (so A is rotated by the rational rotation
        // R/N, with semi-axes r/N), r₀ = N²·2^j, hence the point
        // p = c + 2^j·R e₁ of A's surface is exact in doubles, and B = A
        // reflected through p = (2p − c, r, −R) touches A at p only
        let q = [0; 4].map(|_| (u() * 9.0) as i64 - 4);
        let n = q.iter().map(|x| x * x).sum::<i64>();
        if n == 0 {
            continue;
        }
        let m = contact::quaternion_matrix(q);
        let j = [0.25, 0.5, 1.0][(u() * 3.0) as usize % 3];
        let nf = n as f64;
        let c = [0; 3].map(|_| ((4.0 * u() - 2.0) * 1024.0).round() / 1024.0);
        let r = [nf * nf * j, nf * (0.2 + u()), nf * (0.2 + u())];
        let p: [f64; 3] = std::array::from_fn(|i| c[i] + j * m[i][0]);
        let cb: [f64; 3] = std::array::from_fn(|i| 2.0 * p[i] - c[i]);
        let a = Pose::new(c, r, m).unwrap();
        let b = Pose::new(cb, r, m.map(|row| row.map(|x| -x))).unwrap();
        out.push(Pair {
            set: "touching".into(),
            a,
            b,
            expect: Some(Contact::Touching),
        });
    }
    out
}

/// The rows of the suite.
pub fn contact_suite(pairs: Option<&str>, rows: &mut Vec<Row>) -> Result<(), Error> {
    let mut all = match pairs {
        Some(p) => read_pairs(p)?,
        None => generated(),
    };
    // exact labels where the file gave none
    for p in all.iter_mut().filter(|p| p.expect.is_none()) {
        p.expect = Some(contact::contact_exact(&p.a, &p.b)?);
    }
    let mut sets: Vec<String> = vec![];
    for p in &all {
        if !sets.contains(&p.set) {
            sets.push(p.set.clone());
        }
    }
    for set in sets {
        let ps: Vec<&Pair> = all.iter().filter(|p| p.set == set).collect();
        let n = ps.len();
        let arrays_a = PoseArrays::new(ps.iter().map(|p| &p.a));
        let arrays_b = PoseArrays::new(ps.iter().map(|p| &p.b));
        let mut out = vec![Contact::Separated; n];
        let (pa, pb) = (arrays_a.view(), arrays_b.view());
        // per pair: the whole set through the bulk API, one thread, 5 runs
        let mut times = vec![];
        for _ in 0..5 {
            let t = Instant::now();
            contact::contact_many(pa, pb, &mut out, 1)?;
            times.push(t.elapsed().as_secs_f64() / n as f64);
        }
        times.sort_by(f64::total_cmp);
        // each pair timed alone (3 passes, the fastest of each pair): the
        // median over the pairs (includes ≈ 20 ns of clock reading)
        let mut each = vec![f64::INFINITY; n];
        for _ in 0..3 {
            for (i, p) in ps.iter().enumerate() {
                let t = Instant::now();
                std::hint::black_box(contact::contact(&p.a, &p.b)?);
                each[i] = each[i].min(t.elapsed().as_secs_f64());
            }
        }
        each.sort_by(f64::total_cmp);
        let (median_pair, max_pair) = (each[n / 2], each[n - 1]);
        let wrong = ps
            .iter()
            .zip(&out)
            .filter(|(p, o)| p.expect != Some(**o))
            .count();
        let mut wwk = vec![Contact::Separated; n];
        let mut wtimes = vec![];
        for _ in 0..5 {
            let t = Instant::now();
            for (i, p) in ps.iter().enumerate() {
                wwk[i] = contact::wwk_f64(&p.a, &p.b, 1e-10);
            }
            wtimes.push(t.elapsed().as_secs_f64() / n as f64);
        }
        wtimes.sort_by(f64::total_cmp);
        std::hint::black_box(&wwk);
        let wwk_wrong = ps
            .iter()
            .zip(&wwk)
            .filter(|(p, o)| p.expect != Some(**o))
            .count();
        let decided = ps
            .iter()
            .filter(|p| contact::filter_decides(&p.a, &p.b))
            .count();
        let mut extra = serde_json::Map::new();
        extra.insert("pairs".into(), json!(n));
        extra.insert("median_pair_s".into(), json!(median_pair));
        extra.insert("max_pair_s".into(), json!(max_pair));
        extra.insert("wwk_s".into(), json!(wtimes[2]));
        extra.insert("wwk_wrong".into(), json!(wwk_wrong));
        extra.insert("quadsect_wrong".into(), json!(wrong));
        extra.insert("filter_decided".into(), json!(decided));
        rows.push(Row {
            suite: "contact",
            id: set.clone(),
            desc: format!(
                "{n} pairs: exact contact, mean per pair (bulk, 1 thread); each pair alone: median {:.3} µs, max {:.1} µs; f64 WWK {:.3} µs/pair, {wwk_wrong} wrong; quadsect {wrong} wrong; filter decided {decided}",
                median_pair * 1e6,
                max_pair * 1e6,
                wtimes[2] * 1e6
            ),
            median: times[2],
            samples: 5,
            extra,
        });
    }
    Ok(())
}
