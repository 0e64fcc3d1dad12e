//! The picture of a tangent-method answer: the ellipsoid E from two
//! opposite sides, its surface shaded by the sign and size of S (red where
//! S > 0, blue where S < 0, in doubles), the level curve S = 0 on E traced
//! through the mesh, and the witness points of the certificate (exact
//! points of E in Q(√d)) marked with the sign of S there.

use super::{Camera, P3, Svg, add, dot, norm, scale, sub, symmetric_eigen, unit};
use crate::poly::QMPoly;
use crate::tangent::TangentReport;
use crate::tangent::ellipsoid::Ellipsoid;

const W: f64 = 1000.0;
const H: f64 = 620.0;
const PANEL: f64 = 480.0;

/// S in doubles, from its terms (coefficients and powers).
struct SurfaceF {
    terms: Vec<(f64, [i32; 3])>,
}

impl SurfaceF {
    fn new(s: &QMPoly) -> SurfaceF {
        SurfaceF {
            terms: s
                .terms()
                .iter()
                .map(|(e, c)| (super::qf(c), [e[0] as i32, e[1] as i32, e[2] as i32]))
                .collect(),
        }
    }
    /// Mesh divisions `(n, 2n)` for about `evals` evaluations of S at
    /// most: the drawing's cost stays bounded whatever S's size (the
    /// finest mesh `(cap, 2·cap)` for small S, never below 8).
    fn divisions(&self, cap: usize) -> usize {
        const EVALS: usize = 20_000_000;
        let per = self.terms.len().max(1);
        let n = ((EVALS / per / 2) as f64).sqrt() as usize;
        n.clamp(8, cap)
    }

    fn eval(&self, p: P3) -> f64 {
        self.terms
            .iter()
            .map(|(c, e)| c * p[0].powi(e[0]) * p[1].powi(e[1]) * p[2].powi(e[2]))
            .sum()
    }
}

/// E as `centre + M·y` for unit `y` (doubles): `M = V·diag(√(−E(c)/λᵢ))`.
struct EllipsoidF {
    c: P3,
    m: [[f64; 3]; 3],
    /// The inverse-transpose, for normals: `n = M⁻ᵀ·y`.
    mit: [[f64; 3]; 3],
}

impl EllipsoidF {
    fn new(e: &Ellipsoid) -> EllipsoidF {
        let a: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| super::qf(&e.form.a[i][j])));
        let (l, v) = symmetric_eigen(a);
        let k = -super::qf(&e.center_value);
        let s: [f64; 3] = std::array::from_fn(|i| (k / l[i]).abs().sqrt());
        let m = std::array::from_fn(|i| std::array::from_fn(|j| v[i][j] * s[j]));
        let mit = std::array::from_fn(|i| std::array::from_fn(|j| v[i][j] / s[j]));
        EllipsoidF {
            c: super::q3(&e.center),
            m,
            mit,
        }
    }
    fn point(&self, y: P3) -> P3 {
        add(self.c, std::array::from_fn(|i| dot(self.m[i], y)))
    }
    fn normal(&self, y: P3) -> P3 {
        unit(std::array::from_fn(|i| dot(self.mit[i], y)))
    }
    fn radius(&self) -> f64 {
        (0..3)
            .map(|j| norm([self.m[0][j], self.m[1][j], self.m[2][j]]))
            .fold(0.0, f64::max)
    }
}

fn sphere(theta: f64, phi: f64) -> P3 {
    [
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    ]
}

/// Where S is smallest or largest on E (`sign` −1 or +1): the best mesh
/// vertex, improved by a pattern search in the angles (doubles; the value
/// printed beside it is the exact one of the answer).
fn extreme(e: &EllipsoidF, s: &SurfaceF, sign: f64) -> P3 {
    let f = |t: f64, p: f64| sign * s.eval(e.point(sphere(t, p)));
    let (mut bt, mut bp, mut bv) = (0.0, 0.0, f64::NEG_INFINITY);
    let n = s.divisions(60);
    for i in 0..=n {
        for j in 0..2 * n {
            let (t, p) = (
                std::f64::consts::PI * i as f64 / n as f64,
                std::f64::consts::TAU * j as f64 / (2 * n) as f64,
            );
            let v = f(t, p);
            if v > bv {
                (bt, bp, bv) = (t, p, v);
            }
        }
    }
    let mut h = 0.05;
    for _ in 0..200 {
        let mut moved = false;
        for (dt, dp) in [(h, 0.0), (-h, 0.0), (0.0, h), (0.0, -h)] {
            let v = f(bt + dt, bp + dp);
            if v > bv {
                (bt, bp, bv) = (bt + dt, bp + dp, v);
                moved = true;
            }
        }
        if !moved {
            h *= 0.5;
            if h < 1e-9 {
                break;
            }
        }
    }
    e.point(sphere(bt, bp))
}

/// A proof that the critical point near `p` attains `value`: a Krawczyk
/// box (exact interval arithmetic) holding exactly one zero of `E` and of
/// the components `m·a′`, `m·b′` of `m = ∇S × ∇E` along two rational
/// vectors across the normal near `p` — with `(a′ × b′)·∇E ≠ 0` on the box,
/// `a′`, `b′`, `∇E` span R³ there and `m` (always ⟂ `∇E`) vanishes, so the
/// zero is a critical point of S on E — and S's enclosure on the box holds
/// `value` and no other critical value.
/// `None` when a step does not prove it (the mark is then drawn hollow:
/// located in doubles).
fn certified_extreme(
    report: &TangentReport,
    e: &Ellipsoid,
    p: P3,
    value: &crate::roots::RealAlg,
) -> Option<()> {
    use crate::number::Q;
    use crate::poly::{QMPoly, ZMPoly};
    use crate::system::krawczyk::{Dyadic3, System, eval_box};
    use num_traits::FromPrimitive;
    use std::cmp::Ordering;
    let grad_e = crate::geom::gradient(&e.poly);
    let grad_s = crate::geom::gradient(&report.surface);
    // n₀ = ∇E at a dyadic point near p, and two short rational vectors
    // across it
    let at: [Q; 6] =
        std::array::from_fn(|i| p.get(i).and_then(|v| Q::from_f64(*v)).unwrap_or_default());
    let n0: [Q; 3] = std::array::from_fn(|i| grad_e[i].eval(&at));
    let n = unit(std::array::from_fn(|i| super::qf(&n0[i])));
    let a = super::perpendicular(n);
    let b = super::cross(n, a);
    let short = |v: P3| -> [Q; 3] {
        std::array::from_fn(|i| Q::from_f64((v[i] * 1024.0).round() / 1024.0).unwrap_or_default())
    };
    // Σ vᵢ·psᵢ = k·P with P integer (k's sign kept: the sign of ∇E·n₀ counts)
    let combine = |ps: &[QMPoly; 3], v: &[Q; 3]| -> (ZMPoly, Q) {
        let mut acc = QMPoly::zero();
        for i in 0..3 {
            acc = &acc + &ps[i].scale(&v[i]);
        }
        acc.to_primitive_z()
    };
    let m = crate::geom::vec3::cross(&grad_s, &grad_e);
    let (sa, sb) = (short(a), short(b));
    let (fa, fb) = (combine(&m, &sa).0, combine(&m, &sb).0);
    if fa.is_zero() || fb.is_zero() {
        return None;
    }
    let sys = System::new([e.poly.to_primitive_z().0, fa, fb]);
    let k0 = 48usize;
    let x = Dyadic3 {
        m: std::array::from_fn(|i| {
            num_bigint::BigInt::from_f64((p[i] * (1u64 << k0) as f64).round()).unwrap_or_default()
        }),
        k: k0,
    };
    let zb = sys.certify(&x, 40)?;
    // (a′ × b′)·∇E ≠ 0 on the box: a′, b′ and ∇E span R³ there, so the
    // cross product m (⟂ ∇E, with m·a′ = m·b′ = 0 at the zero) is 0
    let across = crate::geom::vec3::cross(&sa, &sb);
    if eval_box(&combine(&grad_e, &across).0, &zb.enclosure, zb.k).sign() == 0 {
        return None;
    }
    let (sz, ks) = report.surface.to_primitive_z();
    let (lo, hi) = eval_box(&sz, &zb.enclosure, zb.k).to_q(zb.k);
    let (lo, hi) = if num_traits::Signed::is_negative(&ks) {
        (&hi * &ks, &lo * &ks)
    } else {
        (&lo * &ks, &hi * &ks)
    };
    let inside = |v: &crate::roots::RealAlg| {
        v.cmp_rational(&lo) != Ordering::Less && v.cmp_rational(&hi) != Ordering::Greater
    };
    let others = report
        .certificate()
        .critical_values()
        .iter()
        .filter(|v| v.cmp_exact(value) != Ordering::Equal)
        .any(inside);
    (inside(value) && !others).then_some(())
}

/// The colour of a value: red (S > 0) or blue (S < 0), deeper with |S|.
fn color(v: f64, vmax: f64) -> String {
    let t = if vmax > 0.0 {
        (v.abs() / vmax).sqrt().min(1.0)
    } else {
        0.0
    };
    let (r, g, b) = if v > 0.0 {
        (214.0, 96.0, 77.0)
    } else if v < 0.0 {
        (67.0, 147.0, 195.0)
    } else {
        (200.0, 200.0, 200.0)
    };
    let mix = |c: f64| (255.0 + (c - 255.0) * (0.25 + 0.75 * t)).round() as u8;
    format!("#{:02x}{:02x}{:02x}", mix(r), mix(g), mix(b))
}

#[allow(clippy::too_many_arguments)]
fn view(
    svg: &mut Svg,
    e: &EllipsoidF,
    s: &SurfaceF,
    report: &TangentReport,
    eye: P3,
    x0: f64,
    y0: f64,
    label: &str,
    extremes: &[(Option<(P3, bool)>, String); 2],
) {
    let r = e.radius();
    let cam = Camera::new(
        e.c,
        eye,
        0.42 * PANEL / r,
        (x0 + PANEL / 2.0, y0 + PANEL / 2.0),
    );
    svg.rect(x0, y0, PANEL, PANEL, "#fbfbfb", "#cccccc");
    // the shading on a coarse mesh, S = 0 through a fine one
    let grid = |nt: usize, np: usize| -> Vec<Vec<P3>> {
        (0..=nt)
            .map(|i| {
                (0..=np)
                    .map(|j| {
                        sphere(
                            std::f64::consts::PI * i as f64 / nt as f64,
                            std::f64::consts::TAU * j as f64 / np as f64,
                        )
                    })
                    .collect()
            })
            .collect()
    };
    let front = |ys: &[P3]| {
        let mid = unit(ys.iter().fold([0.0; 3], |a, &y| add(a, y)));
        dot(e.normal(mid), cam.eye) > 0.0
    };
    let nc = s.divisions(30);
    let coarse = grid(nc, 2 * nc);
    let vmax = coarse
        .iter()
        .flatten()
        .map(|&y| s.eval(e.point(y)))
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    for i in 0..coarse.len() - 1 {
        for j in 0..coarse[i].len() - 1 {
            let ys = [
                coarse[i][j],
                coarse[i][j + 1],
                coarse[i + 1][j + 1],
                coarse[i + 1][j],
            ];
            if !front(&ys) {
                continue; // the far side
            }
            let pts: Vec<(f64, f64)> = ys.iter().map(|&y| cam.project(e.point(y))).collect();
            let mid = unit(ys.iter().fold([0.0; 3], |a, &y| add(a, y)));
            let c = color(s.eval(e.point(mid)), vmax);
            svg.polygon(&pts, &c, &c);
        }
    }
    // S changes sign on E only when they intersect (the exact verdict):
    // touching, the zero set is where an extreme 0 is attained (marked
    // below), not a curve
    let crossing = report.verdict() == crate::Verdict::Intersecting;
    let nf = s.divisions(120);
    let fine = if crossing { grid(nf, 2 * nf) } else { vec![] };
    let vals: Vec<Vec<f64>> = fine
        .iter()
        .map(|row| row.iter().map(|&y| s.eval(e.point(y))).collect())
        .collect();
    let mut zero_segments: Vec<[(f64, f64); 2]> = Vec::new();
    for i in 0..fine.len().saturating_sub(1) {
        for j in 0..fine[i].len() - 1 {
            let vs = [
                vals[i][j],
                vals[i][j + 1],
                vals[i + 1][j + 1],
                vals[i + 1][j],
            ];
            if vs.iter().all(|v| *v < 0.0) || vs.iter().all(|v| *v >= 0.0) {
                continue;
            }
            let ys = [
                fine[i][j],
                fine[i][j + 1],
                fine[i + 1][j + 1],
                fine[i + 1][j],
            ];
            if !front(&ys) {
                continue;
            }
            let pts: Vec<(f64, f64)> = ys.iter().map(|&y| cam.project(e.point(y))).collect();
            let mut cut = Vec::new();
            for k in 0..4 {
                let (a, b) = (vs[k], vs[(k + 1) % 4]);
                if (a < 0.0) != (b < 0.0) && a.is_finite() && b.is_finite() {
                    let t = a / (a - b);
                    let (p, q) = (pts[k], pts[(k + 1) % 4]);
                    cut.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
                }
            }
            if cut.len() >= 2 {
                zero_segments.push([cut[0], cut[1]]);
            }
            if cut.len() == 4 {
                zero_segments.push([cut[2], cut[3]]);
            }
        }
    }
    svg.segments(&zero_segments, "#111111", 2.2);
    // the certificate's witness points
    let cert = report.certificate();
    for (w, name) in [
        (cert.negative_witness(), "S < 0"),
        (cert.positive_witness(), "S > 0"),
    ] {
        let Some(w) = w else { continue };
        let p: P3 = std::array::from_fn(|i| w.coords()[i].to_f64_bounded().0);
        let at = cam.project(p);
        let n = sub(p, e.c);
        let front = dot(n, cam.eye) >= 0.0;
        let fill = if name == "S < 0" {
            "#08519c"
        } else {
            "#a50f15"
        };
        if front {
            svg.circle(at, 6.0, fill, "white", 2.0);
            svg.text(
                (at.0 + 9.0, at.1 - 7.0),
                12.0,
                "#111111",
                &format!("witness {name}"),
            );
        } else {
            svg.circle(at, 5.0, "none", fill, 1.5);
        }
    }
    // where the extremes are attained: found in doubles, then proven
    // (a certified box) when the exact checks succeed
    for (mark, v) in extremes {
        let Some((p, proven)) = *mark else { continue };
        let at = cam.project(p);
        if dot(sub(p, e.c), cam.eye) < 0.0 {
            continue;
        }
        let d = 7.0;
        svg.polygon(
            &[
                (at.0, at.1 - d),
                (at.0 + d, at.1),
                (at.0, at.1 + d),
                (at.0 - d, at.1),
            ],
            if proven { "#ffd23f" } else { "none" },
            "#111111",
        );
        svg.text((at.0 + 10.0, at.1 + 14.0), 12.0, "#111111", v);
    }
    svg.text((x0 + 8.0, y0 + 18.0), 13.0, "#333333", label);
}

/// The SVG picture of a tangent-method answer.
pub(crate) fn svg(report: &TangentReport) -> String {
    let title = format!(
        "E: {} · S: {} — {}",
        report.ellipsoid.to_string_canonical(),
        report.surface.to_string_canonical(),
        report.verdict().as_str()
    );
    let mut svg = Svg::new(W, H, &title);
    let Ok(e) = Ellipsoid::from_poly(&report.ellipsoid) else {
        svg.text((20.0, 40.0), 14.0, "#111111", "E is not an ellipsoid");
        return svg.finish();
    };
    let ef = EllipsoidF::new(&e);
    let s = SurfaceF::new(&report.surface);
    let mut proofs = 0;
    let extremes: [(Option<(P3, bool)>, String); 2] =
        [(-1.0, "min", report.min()), (1.0, "max", report.max())].map(|(sign, name, v)| {
            let Some(v) = v else {
                return (None, String::new());
            };
            let p = extreme(&ef, &s, sign);
            // the proof in exact arithmetic only for an S of moderate size
            // (it is an extra: a hollow mark otherwise)
            let small = report.surface.terms().len() <= 120
                && report.surface.total_degree().unwrap_or(0) <= 10;
            let proven = small && certified_extreme(report, &e, p, v).is_some();
            proofs += usize::from(proven);
            (Some((p, proven)), format!("{name} S = {}", v.approx(8)))
        });
    let eye = [1.0, -1.4, 0.8];
    view(
        &mut svg,
        &ef,
        &s,
        report,
        eye,
        12.0,
        12.0,
        "E seen from (1, −1.4, 0.8)",
        &extremes,
    );
    view(
        &mut svg,
        &ef,
        &s,
        report,
        scale(eye, -1.0),
        24.0 + PANEL,
        12.0,
        "E seen from the opposite side",
        &extremes,
    );
    let y = PANEL + 36.0;
    svg.text(
        (14.0, y),
        16.0,
        "#111111",
        &format!("verdict: {}", report.verdict().as_str()),
    );
    let val = |v: Option<&crate::roots::RealAlg>| match v {
        Some(v) => v.approx(12),
        None => "not computed".to_string(),
    };
    svg.text(
        (14.0, y + 20.0),
        12.0,
        "#333333",
        &format!(
            "min S on E ≈ {} · max S on E ≈ {} (exact values in the answer)",
            val(report.min()),
            val(report.max())
        ),
    );
    let clip = |t: String| -> String {
        if t.chars().count() > 110 {
            format!("{}…", t.chars().take(110).collect::<String>())
        } else {
            t
        }
    };
    svg.text(
        (14.0, y + 38.0),
        12.0,
        "#333333",
        &clip(format!("E: {}", report.ellipsoid.to_string_canonical())),
    );
    svg.text(
        (14.0, y + 54.0),
        12.0,
        "#333333",
        &clip(format!("S: {}", report.surface.to_string_canonical())),
    );
    svg.text(
        (14.0, y + 72.0),
        12.0,
        "#333333",
        "red S > 0, blue S < 0 (deeper: larger |S|); black: S = 0 on E; dots: the certificate's witness points",
    );
    let marks = match proofs {
        2 => {
            "diamonds: the critical points where min and max are attained (each proven by a Krawczyk box)"
        }
        1 => {
            "diamonds: where min and max are attained (filled: proven by a Krawczyk box; hollow: located in doubles)"
        }
        _ => "diamonds: where min and max are attained (located in doubles, not proven)",
    };
    svg.text((14.0, y + 88.0), 12.0, "#333333", marks);
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The proof of an extreme's place accepts the true pairing of point
    /// and value and refuses a wrong one.
    #[test]
    fn extremes_are_proven_where_they_are() {
        let r = crate::tangent::decide_str("x^2+2y^2+3z^2-6", "x^3-2x*y+z^2+y*z-1").unwrap();
        let e = Ellipsoid::from_poly(&r.ellipsoid).unwrap();
        let (ef, s) = (EllipsoidF::new(&e), SurfaceF::new(&r.surface));
        let (lo, hi) = (r.min().unwrap(), r.max().unwrap());
        let (pmin, pmax) = (extreme(&ef, &s, -1.0), extreme(&ef, &s, 1.0));
        assert!(certified_extreme(&r, &e, pmin, lo).is_some());
        assert!(certified_extreme(&r, &e, pmax, hi).is_some());
        assert!(certified_extreme(&r, &e, pmin, hi).is_none());
        assert!(certified_extreme(&r, &e, pmax, lo).is_none());
        // a point that is no critical point: no box
        let off = ef.point(unit([1.0, 1.0, 1.0]));
        assert!(certified_extreme(&r, &e, off, lo).is_none());
    }
}
