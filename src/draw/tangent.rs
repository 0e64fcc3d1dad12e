//! The picture of a tangent-method answer: the ellipsoid E from two
//! opposite sides, its surface shaded by the sign and size of S (red where
//! S > 0, blue where S < 0, in doubles), the level curve S = 0 on E through
//! points each proven by a Krawczyk box ([`zero_curve`]), the witness
//! points of the certificate (exact points of E in Q(√d)) marked with the
//! sign of S there, and the places of the extremes (proven when
//! [`certified_extreme`] succeeds).

use super::{Camera, P3, Svg, add, dot, norm, scale, sub, symmetric_eigen, unit};
use crate::poly::QMPoly;
use crate::tangent::TangentReport;
use crate::tangent::ellipsoid::Ellipsoid;

const W: f64 = 1000.0;
const H: f64 = 640.0;
const PANEL: f64 = 480.0;

/// S in doubles, from its terms (coefficients and powers).
struct SurfaceF {
    terms: Vec<(f64, [i32; 3])>,
    /// The largest exponent of a variable.
    degree: usize,
}

impl SurfaceF {
    fn new(s: &QMPoly) -> SurfaceF {
        let terms: Vec<(f64, [i32; 3])> = s
            .terms()
            .iter()
            .map(|(e, c)| (super::qf(c), [e[0] as i32, e[1] as i32, e[2] as i32]))
            .collect();
        let degree = terms.iter().flat_map(|(_, e)| *e).max().unwrap_or(0) as usize;
        SurfaceF { terms, degree }
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
        const N: usize = 32;
        if self.degree >= N {
            return self
                .terms
                .iter()
                .map(|(c, e)| c * p[0].powi(e[0]) * p[1].powi(e[1]) * p[2].powi(e[2]))
                .sum();
        }
        // the powers of each coordinate once, then three products a term
        let mut pw = [[1.0f64; N]; 3];
        for (row, x) in pw.iter_mut().zip(p) {
            for k in 1..=self.degree {
                row[k] = row[k - 1] * x;
            }
        }
        self.terms
            .iter()
            .map(|(c, e)| c * pw[0][e[0] as usize] * pw[1][e[1] as usize] * pw[2][e[2] as usize])
            .sum()
    }

    /// ∇S at `p` (doubles: it only chooses the planes that cut S = 0).
    fn grad(&self, p: P3) -> P3 {
        std::array::from_fn(|v| {
            self.terms
                .iter()
                .filter(|(_, e)| e[v] > 0)
                .map(|(c, e)| {
                    let mut d = *e;
                    d[v] -= 1;
                    c * e[v] as f64 * p[0].powi(d[0]) * p[1].powi(d[1]) * p[2].powi(d[2])
                })
                .sum()
        })
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

/// S on a mesh of E: the unit-sphere points of [`grid`] (`n × 2n`
/// cells) and S at their images on E (doubles).
struct Mesh {
    ys: Vec<Vec<P3>>,
    vals: Vec<Vec<f64>>,
}

impl Mesh {
    fn new(e: &EllipsoidF, s: &SurfaceF, n: usize) -> Mesh {
        let ys = grid(n, 2 * n);
        let vals = ys
            .iter()
            .map(|row| row.iter().map(|&y| s.eval(e.point(y))).collect())
            .collect();
        Mesh { ys, vals }
    }
}

/// Where S is smallest and largest on E: the best vertices of one mesh,
/// each improved by a pattern search in the angles (doubles; the values
/// printed beside them are the exact ones of the answer).
fn extremes(e: &EllipsoidF, s: &SurfaceF) -> [P3; 2] {
    let n = s.divisions(60);
    let mesh = Mesh::new(e, s, n);
    [-1.0, 1.0].map(|sign| {
        let (mut bi, mut bj, mut bv) = (0, 0, f64::NEG_INFINITY);
        for (i, row) in mesh.vals.iter().enumerate() {
            // the last column repeats the first
            for (j, v) in row[..2 * n].iter().enumerate() {
                if sign * v > bv {
                    (bi, bj, bv) = (i, j, sign * v);
                }
            }
        }
        let (t, p) = (
            std::f64::consts::PI * bi as f64 / n as f64,
            std::f64::consts::TAU * bj as f64 / (2 * n) as f64,
        );
        polish(e, s, sign, (t, p), bv)
    })
}

/// The pattern search of [`extremes`] from the angles `at` where
/// `sign·S = v`.
fn polish(e: &EllipsoidF, s: &SurfaceF, sign: f64, at: (f64, f64), v: f64) -> P3 {
    let f = |t: f64, p: f64| sign * s.eval(e.point(sphere(t, p)));
    let ((mut bt, mut bp), mut bv) = (at, v);
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
/// `None` when a step does not prove it (the mark is then not drawn).
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

/// The level curve S = 0 on E as drawn: chords between certified points.
struct ZeroCurve {
    /// Chords (two certified points) with the mesh cell's centre on the
    /// unit sphere (which side of E it is on).
    chords: Vec<([P3; 2], P3)>,
    /// Crossings of the mesh's edges proven near a point of the curve.
    certified: usize,
    /// Crossings the proof declined (their chords are not drawn).
    declined: usize,
}

/// The curve S = 0 on E, when the verdict says they intersect (touching,
/// S = 0 on E is where an extreme 0 is attained, marked apart): a mesh of
/// E in the angles locates where S changes sign along an edge (doubles);
/// at each such crossing `p`, the plane through `p` across the curve
/// (normal `∇E × ∇S`, exact doubles) cuts it, and the ball-arithmetic
/// Krawczyk test proves a box of relative width `2^-40` (at most `2^-24`)
/// holding exactly one zero of `{E, S, plane}` — a point of E ∩ {S = 0} —
/// within `reach` of `p`.  The box's centre is drawn; chords join the
/// proven crossings of a cell (their straightness is the drawing's, not
/// the proof's); a declined crossing (near a singular point of the curve,
/// or beyond doubles) leaves a gap rather than a guess.
fn zero_curve(report: &TangentReport, e: &Ellipsoid, ef: &EllipsoidF, s: &SurfaceF) -> ZeroCurve {
    use crate::poly::ZMPoly;
    use crate::poly::mpoly::X;
    use crate::system::krawczyk::System;
    use crate::system::krawczyk_filter::BallSystem;
    let mut out = ZeroCurve {
        chords: Vec::new(),
        certified: 0,
        declined: 0,
    };
    if report.verdict() != crate::Verdict::Intersecting {
        return out;
    }
    let sys = System::new([
        e.poly.to_primitive_z().0,
        report.surface.to_primitive_z().0,
        ZMPoly::var(X),
    ]);
    let mut balls = BallSystem::new(&sys);
    // the mesh: as fine as 90 × 180 cells, coarser when its crossings
    // would need more than 200 000 / (terms of the system and its
    // Jacobian) proofs (a proof is ≈ 8 evaluations of them: ≈ 10 ms in
    // all whatever S's size)
    let terms: usize = sys_terms(&sys);
    // the crossings of a 24 × 48 mesh, times n / 24, estimate those of
    // the n × 2n one
    let cap = (200_000 / terms.max(1)).max(24);
    let n = s.divisions(90);
    let rough = crossings(&Mesh::new(ef, s, 24).vals) * n / 24;
    let n = if rough > cap {
        (n * cap / rough).max(8)
    } else {
        n
    };
    let Mesh { ys, vals } = Mesh::new(ef, s, n);
    let (nt, np) = (n, 2 * n);
    let reach = 3.0 * ef.radius() * std::f64::consts::PI / nt as f64;
    let mut proven = |y: P3| prove_on_curve(balls.as_mut()?, ef, s, y, reach);
    // the crossing on the edge from (i, j) down or right, once
    let mut edges: std::collections::HashMap<(usize, usize, bool), Option<P3>> =
        std::collections::HashMap::new();
    let mut crossing = |i: usize, j: usize, down: bool| -> Option<P3> {
        *edges.entry((i, j, down)).or_insert_with(|| {
            let (i2, j2) = if down { (i + 1, j) } else { (i, j + 1) };
            let (a, b) = (vals[i][j], vals[i2][j2]);
            let t = a / (a - b);
            let y = unit(add(scale(ys[i][j], 1.0 - t), scale(ys[i2][j2], t)));
            proven(y)
        })
    };
    for i in 0..nt {
        for j in 0..np {
            let vs = [
                vals[i][j],
                vals[i][j + 1],
                vals[i + 1][j + 1],
                vals[i + 1][j],
            ];
            if vs.iter().any(|v| !v.is_finite())
                || vs.iter().all(|v| *v < 0.0)
                || vs.iter().all(|v| *v >= 0.0)
            {
                continue;
            }
            // the cell's edges in order, as (start corner, direction)
            let sides = [
                (i, j, false),
                (i, j + 1, true),
                (i + 1, j, false),
                (i, j, true),
            ];
            let mut cut = Vec::with_capacity(4);
            for (k, &(a, b, down)) in sides.iter().enumerate() {
                if (vs[k] < 0.0) != (vs[(k + 1) % 4] < 0.0) {
                    let q = crossing(a, b, down);
                    cut.push(q);
                }
            }
            let mid = unit(add(
                add(ys[i][j], ys[i][j + 1]),
                add(ys[i + 1][j + 1], ys[i + 1][j]),
            ));
            for pair in cut.chunks_exact(2) {
                if let [Some(p), Some(q)] = pair {
                    out.chords.push(([*p, *q], mid));
                }
            }
        }
    }
    for q in edges.values() {
        if q.is_some() {
            out.certified += 1;
        } else {
            out.declined += 1;
        }
    }
    out
}

/// A point of E ∩ {S = 0} near `ef.point(y)`: the plane through that
/// point across the curve (normal `∇E × ∇S` in doubles, exact as a
/// plane) replaces the third equation of `balls` (E, S, ·), and the
/// Krawczyk test proves a box holding exactly one zero; its centre is
/// returned when it lies within `reach` of the start (`None` otherwise, or
/// when the test declines).
fn prove_on_curve(
    balls: &mut crate::system::krawczyk_filter::BallSystem,
    ef: &EllipsoidF,
    s: &SurfaceF,
    y: P3,
    reach: f64,
) -> Option<P3> {
    let p = ef.point(y);
    let t = unit(super::cross(ef.normal(y), s.grad(p)));
    if !t.iter().all(|v| v.is_finite()) {
        return None;
    }
    balls.set_plane(t, dot(t, p));
    let (k, _) = balls.certify_near(p)?;
    let q: P3 = k.map(|b| b.m);
    (norm(sub(q, p)) <= reach).then_some(q)
}

/// The unit sphere at `nt + 1` polar by `np + 1` azimuthal angles (the
/// last column repeats the first).
fn grid(nt: usize, np: usize) -> Vec<Vec<P3>> {
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
}

/// How many mesh edges S changes sign along.
fn crossings(vals: &[Vec<f64>]) -> usize {
    let mut count = 0;
    for (i, row) in vals.iter().enumerate() {
        for (j, &a) in row.iter().enumerate() {
            let right = row.get(j + 1);
            let down = vals.get(i + 1).map(|r| &r[j]);
            count += [right, down]
                .into_iter()
                .flatten()
                .filter(|&&b| (a < 0.0) != (b < 0.0))
                .count();
        }
    }
    count
}

/// The terms of a square system and its Jacobian (the cost of one
/// evaluation).
fn sys_terms(sys: &crate::system::krawczyk::System) -> usize {
    let (f, jac) = sys.parts();
    f.iter()
        .chain(jac.iter().flatten())
        .map(|p| p.terms().len())
        .sum()
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
    extremes: &[(Option<P3>, String); 2],
    curve: &ZeroCurve,
    (shade, shade_max): (&Mesh, f64),
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
    let front = |ys: &[P3]| {
        let mid = unit(ys.iter().fold([0.0; 3], |a, &y| add(a, y)));
        dot(e.normal(mid), cam.eye) > 0.0
    };
    let (coarse, cvals) = (&shade.ys, &shade.vals);
    let vmax = shade_max;
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
            let vs = [
                cvals[i][j],
                cvals[i][j + 1],
                cvals[i + 1][j + 1],
                cvals[i + 1][j],
            ];
            let mid = unit(ys.iter().fold([0.0; 3], |a, &y| add(a, y)));
            let vm = s.eval(e.point(mid));
            if !vs.iter().all(|v| v.is_finite()) || vs.iter().all(|v| (*v < 0.0) == (vs[0] < 0.0)) {
                let c = color(vm, vmax);
                svg.polygon(&pts, &c, &c);
                continue;
            }
            // a cell S = 0 crosses: each side in its colour (split along the
            // chords of the edges' crossings; the shading is the doubles')
            for negative in [true, false] {
                let mut part = Vec::with_capacity(6);
                for k in 0..4 {
                    let (a, b) = (vs[k], vs[(k + 1) % 4]);
                    if (a < 0.0) == negative {
                        part.push(pts[k]);
                    }
                    if (a < 0.0) != (b < 0.0) {
                        let t = a / (a - b);
                        let (p, q) = (pts[k], pts[(k + 1) % 4]);
                        part.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
                    }
                }
                let v = if negative { -vm.abs() } else { vm.abs() };
                let c = color(v, vmax);
                svg.polygon(&part, &c, &c);
            }
        }
    }
    let zero_segments: Vec<[(f64, f64); 2]> = curve
        .chords
        .iter()
        .filter(|(_, mid)| dot(e.normal(*mid), cam.eye) > 0.0)
        .map(|(c, _)| [cam.project(c[0]), cam.project(c[1])])
        .collect();
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
            let end = at.0 > x0 + 0.6 * PANEL;
            svg.text_anchored(
                (at.0 + if end { -9.0 } else { 9.0 }, at.1 - 7.0),
                12.0,
                "#111111",
                &format!("witness {name}"),
                end,
            );
        } else {
            svg.circle(at, 5.0, "none", fill, 1.5);
        }
    }
    // where the extremes are attained: found in doubles, drawn only when
    // proven (a certified box)
    for (mark, v) in extremes {
        let Some(p) = *mark else { continue };
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
            "#ffd23f",
            "#111111",
        );
        let end = at.0 > x0 + 0.6 * PANEL;
        let dx = if end { -10.0 } else { 10.0 };
        svg.text_anchored((at.0 + dx, at.1 + 14.0), 12.0, "#111111", v, end);
    }
    svg.text((x0 + 8.0, y0 + 18.0), 13.0, "#333333", label);
}

impl TangentReport {
    /// The picture of the answer as SVG text (`quadsect tangent --svg`): E
    /// from two opposite sides, shaded by the sign of S (red S > 0, blue
    /// S < 0, in doubles), the curve S = 0 on E through points each proven
    /// by a Krawczyk box to lie on it, the certificate's witness points
    /// (exact points of E) and the places of the extremes marked, and a
    /// legend with the verdict and the extreme values.
    ///
    /// ```
    /// let r = quadsect::tangent::decide_str("x^2+y^2+z^2-25", "(x-6)^2/9+y^2/4+z^2/16-1").unwrap();
    /// let svg = r.svg();
    /// assert!(svg.starts_with("<svg") && svg.contains("verdict: intersecting"));
    /// ```
    pub fn svg(&self) -> String {
        svg(self)
    }
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
    let (mut values, mut proofs) = (0, 0);
    // the proof in exact arithmetic only for an S of moderate size
    let small =
        report.surface.terms().len() <= 120 && report.surface.total_degree().unwrap_or(0) <= 10;
    let places = (report.min().is_some() || report.max().is_some()).then(|| extremes(&ef, &s));
    let extremes: [(Option<P3>, String); 2] = [(0, "min", report.min()), (1, "max", report.max())]
        .map(|(k, name, v)| {
            let (Some(v), Some(places)) = (v, places) else {
                return (None, String::new());
            };
            let p = places[k];
            // a place not proven is not drawn (the legend says so)
            let proven = small && certified_extreme(report, &e, p, v).is_some();
            values += 1;
            proofs += usize::from(proven);
            (proven.then_some(p), format!("{name} S = {}", v.approx(8)))
        });
    let curve = zero_curve(report, &e, &ef, &s);
    // the shading's mesh, shared by both views
    let shade = Mesh::new(&ef, &s, s.divisions(30));
    let shade_max = shade
        .vals
        .iter()
        .flatten()
        .filter(|v| v.is_finite())
        .fold(0.0f64, |m, v| m.max(v.abs()));
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
        &curve,
        (&shade, shade_max),
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
        &curve,
        (&shade, shade_max),
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
        "red S > 0, blue S < 0 (deeper: larger |S|, doubles); dots: the certificate's witness points",
    );
    let traced = if curve.certified + curve.declined == 0 {
        String::new()
    } else if curve.declined == 0 {
        format!(
            "black: S = 0 on E, chords through {} points each proven (a Krawczyk box, ≤ 2^-24 relative) to lie on it",
            curve.certified
        )
    } else {
        format!(
            "black: S = 0 on E, chords through {} points proven by Krawczyk boxes; {} not proven (gaps)",
            curve.certified, curve.declined
        )
    };
    let marks = if values == 0 {
        "no diamonds: the exact min and max were not computed".to_string()
    } else if proofs == values {
        "diamonds: the critical points where min and max are attained (each proven by a Krawczyk box)"
            .to_string()
    } else if !small {
        "no diamonds: their places are proven only for S of degree ≤ 10 and ≤ 120 terms".to_string()
    } else {
        format!(
            "diamonds: where min and max are attained, each proven by a Krawczyk box ({} not proven: not drawn)",
            values - proofs
        )
    };
    svg.text((14.0, y + 88.0), 12.0, "#333333", &marks);
    if !traced.is_empty() {
        svg.text((14.0, y + 104.0), 12.0, "#333333", &clip(traced));
    }
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
        let [pmin, pmax] = extremes(&ef, &s);
        assert!(certified_extreme(&r, &e, pmin, lo).is_some());
        assert!(certified_extreme(&r, &e, pmax, hi).is_some());
        assert!(certified_extreme(&r, &e, pmin, hi).is_none());
        assert!(certified_extreme(&r, &e, pmax, lo).is_none());
        // a point that is no critical point: no box
        let off = ef.point(unit([1.0, 1.0, 1.0]));
        assert!(certified_extreme(&r, &e, off, lo).is_none());
    }

    /// A place of an extreme that is not proven is not drawn (here the
    /// proof is not attempted: S of degree 11), and the legend says why.
    #[test]
    fn unproven_extremes_are_not_drawn() {
        let r = crate::tangent::decide_str("x^2+y^2+z^2-1", "x^11+y-1/2").unwrap();
        let svg = r.svg();
        assert!(!svg.contains("#ffd23f"), "a diamond was drawn");
        assert!(svg.contains("no diamonds: their places are proven only for S of degree ≤ 10"));
        let small = crate::tangent::decide_str("x^2+y^2+z^2-1", "x^3+y-1/2").unwrap();
        assert_eq!(
            small.svg().matches("#ffd23f").count(),
            2,
            "both places, each in the view facing it"
        );
    }

    /// The level curve is drawn through proven points only: on a sphere cut
    /// by the plane z = 1/2 every drawn point is on the circle, the chords
    /// close up, and a start away from the curve is refused.
    #[test]
    fn the_level_curve_is_drawn_through_proven_points() {
        let r = crate::tangent::decide_str("x^2+y^2+z^2-1", "2z-1").unwrap();
        let e = Ellipsoid::from_poly(&r.ellipsoid).unwrap();
        let (ef, s) = (EllipsoidF::new(&e), SurfaceF::new(&r.surface));
        let curve = zero_curve(&r, &e, &ef, &s);
        assert!(curve.certified >= 100 && curve.declined == 0);
        assert!(curve.chords.len() >= curve.certified / 2);
        for ([p, q], _) in &curve.chords {
            for v in [p, q] {
                assert!((v[2] - 0.5).abs() < 1e-12, "{v:?}");
                assert!((v[0] * v[0] + v[1] * v[1] - 0.75).abs() < 1e-12, "{v:?}");
            }
        }
        let mut balls = crate::system::krawczyk_filter::BallSystem::new(
            &crate::system::krawczyk::System::new([
                e.poly.to_primitive_z().0,
                r.surface.to_primitive_z().0,
                crate::poly::ZMPoly::var(crate::poly::mpoly::X),
            ]),
        )
        .unwrap();
        let near = unit([1.0, 0.0, 0.55]);
        assert!(prove_on_curve(&mut balls, &ef, &s, near, 0.1).is_some());
        // the pole: the curve is 0.5 away, beyond reach
        assert!(prove_on_curve(&mut balls, &ef, &s, [0.0, 0.0, 1.0], 0.1).is_none());
        // touching: no curve (the zero set is a point, marked apart)
        let t = crate::tangent::decide_str("x^2+y^2+z^2-1", "z-1").unwrap();
        let et = Ellipsoid::from_poly(&t.ellipsoid).unwrap();
        let (eft, st) = (EllipsoidF::new(&et), SurfaceF::new(&t.surface));
        assert_eq!(zero_curve(&t, &et, &eft, &st).certified, 0);
    }
}
