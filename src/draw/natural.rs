//! The picture of a natural-quadric answer: a 3D view of both surfaces
//! with the components drawn thick and coloured by kind, and — when the
//! axes are coplanar — the axial plane of Shene and Johnstone's figures
//! (the sections of both surfaces, the axes, X with its heights, the
//! conics' planes as lines).

use super::{
    Camera, P3, Svg, add, cross, dot, inside_pieces, line_in_ball, norm, perpendicular, q3, qf,
    scale, short, short_q, sub, unit,
};
use crate::natural::numbers::{EPoint, Exact};
use crate::natural::result::{Component, ConicKind, NaturalReport};
use crate::natural::types::Natural;

const W: f64 = 1000.0;
const H: f64 = 620.0;
const PANEL: f64 = 480.0;
const COLOR_A: &str = "#4c72b0";
const COLOR_B: &str = "#dd8452";
const CONIC: &str = "#c0392b";
const LINE: &str = "#2e8b57";
const POINT: &str = "#7b3fa0";
const CURVE: &str = "#1f4e9e";

/// A natural quadric in doubles (unit axis).
#[derive(Clone, Copy, Debug)]
enum Shape {
    Sphere { c: P3, r: f64 },
    Cylinder { q: P3, a: P3, r: f64 },
    Cone { v: P3, a: P3, t2: f64 },
}

fn shape(n: &Natural) -> Shape {
    match n {
        Natural::Sphere(s) => Shape::Sphere {
            c: q3(&s.center),
            r: qf(&s.r2).sqrt(),
        },
        Natural::Cylinder(c) => Shape::Cylinder {
            q: q3(&c.point),
            a: unit(q3(&c.axis)),
            r: qf(&c.r2).sqrt(),
        },
        Natural::Cone(c) => Shape::Cone {
            v: q3(&c.vertex),
            a: unit(q3(&c.axis)),
            t2: qf(&c.t2),
        },
    }
}

impl Shape {
    /// The equation in doubles, normalised so that its gradient has about
    /// unit size near the surface.
    fn eval(&self, p: P3) -> f64 {
        match *self {
            Shape::Sphere { c, r } => (dot(sub(p, c), sub(p, c)) - r * r) / (2.0 * r),
            Shape::Cylinder { q, a, r } => {
                let w = cross(sub(p, q), a);
                (dot(w, w) - r * r) / (2.0 * r)
            }
            Shape::Cone { v, a, t2 } => {
                let d = sub(p, v);
                let h = dot(d, a);
                (dot(d, d) - (1.0 + t2) * h * h) / (1.0 + t2)
            }
        }
    }

    /// A reference point (centre, axis point, vertex).
    fn anchor(&self) -> P3 {
        match *self {
            Shape::Sphere { c, .. } => c,
            Shape::Cylinder { q, .. } => q,
            Shape::Cone { v, .. } => v,
        }
    }
}

fn e3(p: &EPoint) -> P3 {
    [ef(&p[0]), ef(&p[1]), ef(&p[2])]
}

fn ef(x: &Exact) -> f64 {
    x.to_f64_bounded().0.clamp(-1e300, 1e300)
}

/// The sampled 3D polylines of one component (before clipping) and the
/// points to mark.
struct Drawn {
    /// The paths are the whole component (an ellipse, a circle, a curve
    /// with bounded branches only), not a part clipped to the scene.
    bounded: bool,
    paths: Vec<Vec<P3>>,
    marks: Vec<(P3, String)>,
    color: &'static str,
    width: f64,
}

/// The scene's centre and radius: centred on the components' points (the
/// surfaces' anchors when there are none), wide enough for them, the
/// conics' sizes, the spheres, the cylinders' sections and the cones'
/// vertices.
fn scene(report: &NaturalReport, a: &Shape, b: &Shape, bounded: &[P3]) -> (P3, f64) {
    let mut pts: Vec<P3> = bounded.to_vec();
    let mut sizes = vec![0.0f64];
    for c in &report.components {
        match c {
            Component::Conic {
                center,
                vertex,
                axes2,
                focal2,
                ..
            } => {
                if let Some(p) = center.as_ref().or(vertex.as_ref()) {
                    pts.push(e3(p));
                }
                for a2 in axes2 {
                    sizes.push(ef(a2).abs().sqrt());
                }
                if let Some(f2) = focal2 {
                    sizes.push(4.0 * ef(f2).abs().sqrt());
                }
            }
            Component::Line { point, .. } => pts.push(e3(point)),
            Component::Point { point, .. } => pts.push(e3(point)),
            Component::Curve {
                singular, branches, ..
            } => {
                pts.extend(singular.iter().map(|s| e3(&s.point)));
                pts.extend(
                    branches
                        .iter()
                        .map(|b| b.start.approx().map(|(v, _)| v.clamp(-1e300, 1e300))),
                );
            }
        }
    }
    if pts.is_empty() {
        pts.push(a.anchor());
        pts.push(b.anchor());
    }
    // the middle of the points' bounding box
    let lo = pts.iter().fold([f64::INFINITY; 3], |m, p| {
        [m[0].min(p[0]), m[1].min(p[1]), m[2].min(p[2])]
    });
    let hi = pts.iter().fold([f64::NEG_INFINITY; 3], |m, p| {
        [m[0].max(p[0]), m[1].max(p[1]), m[2].max(p[2])]
    });
    let c = scale(add(lo, hi), 0.5);
    let mut extent = pts.iter().map(|&p| norm(sub(p, c))).fold(0.0, f64::max);
    extent = extent.max(sizes.iter().cloned().fold(0.0, f64::max));
    for s in [a, b] {
        let reach = match *s {
            Shape::Sphere { c: o, r } => norm(sub(o, c)) + r,
            Shape::Cylinder { q, a, r } => {
                let w = sub(c, q);
                norm(sub(w, scale(a, dot(w, a)))) + r
            }
            Shape::Cone { v, .. } => norm(sub(v, c)),
        };
        extent = extent.max(reach);
    }
    let r = if extent > 0.0 && extent.is_finite() {
        extent * 1.15
    } else {
        1.0
    };
    (c, r)
}

/// The chord of the line `p + t·d` (unit `d`) inside the ball, projected
/// (nothing when the line misses the ball).
fn chord(svg: &mut Svg, cam: &Camera, p: P3, d: P3, ball: (P3, f64), color: &str, width: f64) {
    if let Some((t0, t1)) = line_in_ball(p, d, ball.0, ball.1) {
        svg.polyline(
            &[
                cam.project(add(p, scale(d, t0))),
                cam.project(add(p, scale(d, t1))),
            ],
            color,
            width,
            None,
        );
    }
}

/// Samples of each component (doubles from the exact data).
/// The certified points of each space curve of the answer, in order (they
/// do not depend on the scene: traced once per figure).
fn curve_traces(report: &NaturalReport) -> Vec<Vec<Vec<P3>>> {
    report
        .components
        .iter()
        .filter_map(|c| match c {
            // an answer without branches (the reference route) has no curve
            // to draw (the legend says so)
            Component::Curve { branches, .. } => Some(
                branches
                    .first()
                    .map(|first| first.start.trace(2000))
                    .unwrap_or_default(),
            ),
            _ => None,
        })
        .collect()
}

fn components(
    report: &NaturalReport,
    a: &Shape,
    b: &Shape,
    c: P3,
    r: f64,
    traces: &[Vec<Vec<P3>>],
) -> Vec<Drawn> {
    let mut traces = traces.iter();
    let mut out = Vec::new();
    for comp in &report.components {
        match comp {
            Component::Conic {
                plane,
                kind,
                center,
                vertex,
                axes2,
                axis_dirs,
                focal2,
                double,
            } => {
                let n = unit(e3(&plane.normal));
                let dirs: Vec<P3> = axis_dirs.iter().map(|d| unit(e3(d))).collect();
                let d1 = dirs.first().copied().unwrap_or_else(|| perpendicular(n));
                let d2 = dirs.get(1).copied().unwrap_or_else(|| unit(cross(n, d1)));
                let ax: Vec<f64> = axes2.iter().map(|v| ef(v).abs().sqrt()).collect();
                let mut paths = Vec::new();
                match kind {
                    ConicKind::Circle | ConicKind::Ellipse => {
                        let o = center.as_ref().map(e3).unwrap_or(c);
                        let a1 = ax.first().copied().unwrap_or(0.0);
                        let a2 = ax.get(1).copied().unwrap_or(a1);
                        paths.push(
                            (0..=360)
                                .map(|i| {
                                    let t = (i as f64).to_radians();
                                    add(o, add(scale(d1, a1 * t.cos()), scale(d2, a2 * t.sin())))
                                })
                                .collect(),
                        );
                    }
                    ConicKind::Hyperbola => {
                        let o = center.as_ref().map(e3).unwrap_or(c);
                        let a1 = ax.first().copied().unwrap_or(1.0);
                        let a2 = ax.get(1).copied().unwrap_or(a1);
                        let reach = (r + norm(sub(o, c))) / a1.min(a2).max(1e-12);
                        let tmax = reach.max(2.0).acosh() + 0.5;
                        for side in [1.0, -1.0] {
                            paths.push(
                                (0..=400)
                                    .map(|i| {
                                        let t = -tmax + 2.0 * tmax * i as f64 / 400.0;
                                        add(
                                            o,
                                            add(
                                                scale(d1, side * a1 * t.cosh()),
                                                scale(d2, a2 * t.sinh()),
                                            ),
                                        )
                                    })
                                    .collect(),
                            );
                        }
                    }
                    ConicKind::Parabola => {
                        let v = vertex.as_ref().map(e3).unwrap_or(c);
                        let f = focal2.as_ref().map(|x| ef(x).abs().sqrt()).unwrap_or(1.0);
                        let w = unit(cross(n, d1));
                        let reach = 2.0 * (r + norm(sub(v, c)));
                        let ymax = (reach * 4.0 * f).sqrt().max(reach);
                        // the opening side: the one on both surfaces
                        let sample = |sign: f64| -> Vec<P3> {
                            (0..=400)
                                .map(|i| {
                                    let y = -ymax + 2.0 * ymax * i as f64 / 400.0;
                                    add(v, add(scale(d1, sign * y * y / (4.0 * f)), scale(w, y)))
                                })
                                .collect()
                        };
                        let miss = |pts: &[P3]| -> f64 {
                            let p = pts[250];
                            a.eval(p).abs() + b.eval(p).abs()
                        };
                        let (plus, minus) = (sample(1.0), sample(-1.0));
                        paths.push(if miss(&plus) <= miss(&minus) {
                            plus
                        } else {
                            minus
                        });
                    }
                }
                out.push(Drawn {
                    bounded: matches!(kind, ConicKind::Circle | ConicKind::Ellipse),
                    paths,
                    marks: vec![],
                    color: CONIC,
                    width: if *double { 4.5 } else { 3.0 },
                });
            }
            Component::Line {
                point,
                direction,
                double,
            } => {
                let p = e3(point);
                let d = unit(e3(direction));
                if let Some((t0, t1)) = line_in_ball(p, d, c, r) {
                    // a hair inside the ball: the ends survive the clipping
                    let (t0, t1) = (t0 * 0.999, t1 * 0.999);
                    out.push(Drawn {
                        bounded: false,
                        paths: vec![vec![add(p, scale(d, t0)), add(p, scale(d, t1))]],
                        marks: vec![],
                        color: LINE,
                        width: if *double { 4.5 } else { 3.0 },
                    });
                }
            }
            Component::Point { point, kind } => out.push(Drawn {
                bounded: false,
                paths: vec![],
                marks: vec![(e3(point), kind.as_str().to_string())],
                color: POINT,
                width: 0.0,
            }),
            Component::Curve {
                singular, branches, ..
            } => {
                // certified points along the rulings (the exact topology's
                // parameterisation)
                let paths = traces.next().cloned().unwrap_or_default();
                out.push(Drawn {
                    bounded: !branches.is_empty() && branches.iter().all(|b| b.bounded),
                    paths,
                    marks: singular
                        .iter()
                        .map(|s| (e3(&s.point), s.kind.as_str().to_string()))
                        .collect(),
                    color: CURVE,
                    width: 3.0,
                });
            }
        }
    }
    out
}

/// The view direction: among directions spread over a hemisphere, the one
/// that shows every drawn component widest — the sum over the components
/// of the smaller spread (standard deviation) of its projected samples,
/// so that a conic is seen open rather than edge-on and a curve's loop
/// rather than its shadow — with a slight preference for a view from
/// above.
fn choose_eye(drawn: &[Drawn]) -> P3 {
    let samples: Vec<Vec<P3>> = drawn
        .iter()
        .map(|d| {
            let all: Vec<P3> = d.paths.iter().flatten().copied().collect();
            let step = (all.len() / 200).max(1);
            all.into_iter().step_by(step).collect()
        })
        .filter(|v: &Vec<P3>| v.len() > 2)
        .collect();
    let mut best = ([1.0, -1.6, 0.9], f64::NEG_INFINITY);
    for i in 0..16 {
        for j in 1..7 {
            let phi = std::f64::consts::TAU * (i as f64 + 0.37) / 16.0;
            let th = std::f64::consts::PI * j as f64 / 7.0;
            let e = [th.sin() * phi.cos(), th.sin() * phi.sin(), th.cos()];
            let cam = Camera::new([0.0; 3], e, 1.0, (0.0, 0.0));
            let mut score = 0.0;
            for pts in &samples {
                let proj: Vec<(f64, f64)> = pts.iter().map(|&p| cam.project(p)).collect();
                let n = proj.len() as f64;
                let (mx, my) = proj
                    .iter()
                    .fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
                let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
                for p in &proj {
                    let (dx, dy) = (p.0 - mx, p.1 - my);
                    sxx += dx * dx / n;
                    syy += dy * dy / n;
                    sxy += dx * dy / n;
                }
                let tr = sxx + syy;
                let det = sxx * syy - sxy * sxy;
                let small = (tr / 2.0 - ((tr * tr / 4.0 - det).max(0.0)).sqrt()).max(0.0);
                // relative to the component's own size: every one counts
                score += (small / tr.max(1e-300)).sqrt();
            }
            score += 0.05 * e[2] + 0.02 * (e[0] * e[1]).abs();
            if score > best.1 {
                best = (e, score);
            }
        }
    }
    best.0
}

/// Light strokes of a surface inside the scene ball: silhouettes, rulings
/// and parallels.
fn surface_strokes(svg: &mut Svg, cam: &Camera, s: &Shape, c: P3, r: f64, color: &str) {
    let draw = |svg: &mut Svg, pts: Vec<P3>, w: f64| {
        for piece in inside_pieces(cam, &pts, c, r) {
            svg.polyline(&piece, color, w, None);
        }
    };
    match *s {
        Shape::Sphere { c: o, r: rr } => {
            // the outline, and parallels about z
            let centre = cam.project(o);
            svg.circle(centre, rr * cam.px, "none", color, 1.6);
            for k in 1..6 {
                let z = -rr + 2.0 * rr * k as f64 / 6.0;
                let rad = (rr * rr - z * z).max(0.0).sqrt();
                let pts = (0..=120)
                    .map(|i| {
                        let t = std::f64::consts::TAU * i as f64 / 120.0;
                        add(o, [rad * t.cos(), rad * t.sin(), z])
                    })
                    .collect();
                draw(svg, pts, 0.6);
            }
        }
        Shape::Cylinder { q, a, r: rr } => {
            let u = perpendicular(a);
            let w = cross(a, u);
            let base = add(q, scale(a, dot(sub(c, q), a)));
            let mut thetas: Vec<(f64, f64)> = (0..16)
                .map(|i| (std::f64::consts::TAU * i as f64 / 16.0, 0.6))
                .collect();
            // silhouettes: the surface normal across the view
            let phi = dot(w, cam.eye).atan2(dot(u, cam.eye));
            thetas.push((phi + std::f64::consts::FRAC_PI_2, 1.6));
            thetas.push((phi - std::f64::consts::FRAC_PI_2, 1.6));
            for (t, width) in thetas {
                let foot = add(base, add(scale(u, rr * t.cos()), scale(w, rr * t.sin())));
                chord(svg, cam, foot, a, (c, r), color, width);
            }
            for k in [-0.66, 0.0, 0.66] {
                let o = add(base, scale(a, k * r));
                let pts = (0..=120)
                    .map(|i| {
                        let t = std::f64::consts::TAU * i as f64 / 120.0;
                        add(o, add(scale(u, rr * t.cos()), scale(w, rr * t.sin())))
                    })
                    .collect();
                draw(svg, pts, 0.6);
            }
        }
        Shape::Cone { v, a, t2 } => {
            let u = perpendicular(a);
            let w = cross(a, u);
            let s = t2.sqrt();
            let reach = r + norm(sub(v, c));
            let generator =
                |t: f64| unit(add(a, add(scale(u, s * t.cos()), scale(w, s * t.sin()))));
            for i in 0..16 {
                let g = generator(std::f64::consts::TAU * i as f64 / 16.0);
                chord(svg, cam, v, g, (c, r), color, 0.6);
            }
            // silhouettes: generators whose tangent plane contains the view
            let n = 720;
            let f = |t: f64| {
                let g = generator(t);
                let tangent = add(scale(u, -t.sin()), scale(w, t.cos()));
                dot(unit(cross(g, tangent)), cam.eye)
            };
            for i in 0..n {
                let (t0, t1) = (
                    std::f64::consts::TAU * i as f64 / n as f64,
                    std::f64::consts::TAU * (i + 1) as f64 / n as f64,
                );
                if f(t0) * f(t1) < 0.0 {
                    let g = generator(0.5 * (t0 + t1));
                    chord(svg, cam, v, g, (c, r), color, 1.6);
                }
            }
            for k in [-0.66, -0.33, 0.33, 0.66] {
                let h = k * reach;
                let o = add(v, scale(a, h));
                let rad = (h * s).abs();
                let pts = (0..=120)
                    .map(|i| {
                        let t = std::f64::consts::TAU * i as f64 / 120.0;
                        add(o, add(scale(u, rad * t.cos()), scale(w, rad * t.sin())))
                    })
                    .collect();
                draw(svg, pts, 0.6);
            }
        }
    }
}

fn view_3d(svg: &mut Svg, report: &NaturalReport, a: &Shape, b: &Shape, x0: f64, y0: f64) {
    // the scene from the components' points, then widened to hold the
    // bounded components whole
    let (c0, r0) = scene(report, a, b, &[]);
    let traces = curve_traces(report);
    let first = components(report, a, b, c0, 4.0 * r0, &traces);
    let whole: Vec<P3> = first
        .iter()
        .filter(|d| d.bounded)
        .flat_map(|d| d.paths.iter().flatten().copied())
        .filter(|p| p.iter().all(|v| v.is_finite()))
        .collect();
    let (c, r) = if whole.is_empty() {
        (c0, r0)
    } else {
        scene(report, a, b, &whole)
    };
    let drawn = components(report, a, b, c, r, &traces);
    let cam = Camera::new(
        c,
        choose_eye(&drawn),
        0.5 * PANEL / r,
        (x0 + PANEL / 2.0, y0 + PANEL / 2.0),
    );
    svg.rect(x0, y0, PANEL, PANEL, "#fbfbfb", "#cccccc");
    svg.clipped(x0, y0, PANEL, PANEL);
    surface_strokes(svg, &cam, a, c, r, COLOR_A);
    surface_strokes(svg, &cam, b, c, r, COLOR_B);
    for d in drawn {
        for path in &d.paths {
            for piece in inside_pieces(&cam, path, c, r * 1.02) {
                svg.polyline(&piece, d.color, d.width, None);
            }
        }
        for (p, label) in &d.marks {
            let at = cam.project(*p);
            svg.circle(at, 5.5, d.color, "white", 1.5);
            svg.text((at.0 + 8.0, at.1 - 6.0), 12.0, d.color, label);
        }
    }
    svg.end_group();
    svg.text(
        (x0 + 8.0, y0 + 18.0),
        13.0,
        "#333333",
        "3D view (orthographic)",
    );
}

/// Coordinates in the axial plane's frame (origin, unit e1, unit e2).
struct Frame {
    o: P3,
    e1: P3,
    e2: P3,
}

impl Frame {
    fn to2(&self, p: P3) -> (f64, f64) {
        let d = sub(p, self.o);
        (dot(d, self.e1), dot(d, self.e2))
    }
    fn dir2(&self, d: P3) -> (f64, f64) {
        (dot(d, self.e1), dot(d, self.e2))
    }
}

/// The axial plane's frame: the part-1 deciders' when the answer has
/// them, else the plane through both axes (coplanar axes; a sphere's
/// centre stands for an axis through it); `None` for skew axes.
fn axial_frame(report: &NaturalReport, a: &Shape, b: &Shape) -> Option<Frame> {
    let frame = |o: P3, e1: P3, toward: P3| -> Option<Frame> {
        let e1 = unit(e1);
        let mut e2 = sub(toward, scale(e1, dot(toward, e1)));
        if norm(e2) < 1e-9 * (1.0 + norm(toward)) {
            e2 = perpendicular(e1);
        }
        let e2 = unit(e2);
        (norm(e1) > 0.0).then_some(Frame { o, e1, e2 })
    };
    if let Some(dec) = report.deciders.as_ref() {
        return frame(q3(&dec.frame[0]), q3(&dec.frame[1]), q3(&dec.frame[2]));
    }
    if matches!(report.axes(), Some(crate::natural::AxesRelation::Skew)) {
        return None;
    }
    let axis = |s: &Shape| match *s {
        Shape::Cylinder { a, .. } | Shape::Cone { a, .. } => Some(a),
        Shape::Sphere { .. } => None,
    };
    match (axis(a), axis(b)) {
        (Some(da), Some(db)) => {
            // B's axis, or (parallel) the way from A's axis to B's
            let toward = if norm(cross(da, db)) > 1e-12 {
                db
            } else {
                sub(b.anchor(), a.anchor())
            };
            frame(a.anchor(), da, toward)
        }
        (Some(da), None) => frame(a.anchor(), da, sub(b.anchor(), a.anchor())),
        (None, Some(db)) => frame(b.anchor(), db, sub(a.anchor(), b.anchor())),
        (None, None) => {
            let d = sub(b.anchor(), a.anchor());
            let e1 = if norm(d) > 0.0 { d } else { [1.0, 0.0, 0.0] };
            frame(a.anchor(), e1, perpendicular(unit(e1)))
        }
    }
}

/// A surface's section by the axial plane as lines (point, direction) in
/// 3D: a cylinder's two rulings, a cone's two generators (a sphere's
/// circle is drawn apart).
fn section_lines(s: &Shape, fr: &Frame) -> Vec<(P3, P3)> {
    let normal = cross(fr.e1, fr.e2);
    let across = |a: P3| unit(cross(normal, a));
    match *s {
        Shape::Sphere { .. } => vec![],
        Shape::Cylinder { q, a, r } => {
            let w = across(a);
            vec![(add(q, scale(w, r)), a), (sub(q, scale(w, r)), a)]
        }
        Shape::Cone { v, a, t2 } => {
            let w = across(a);
            let t = t2.sqrt();
            vec![(v, add(a, scale(w, t))), (v, sub(a, scale(w, t)))]
        }
    }
}

fn axial_plane(svg: &mut Svg, report: &NaturalReport, a: &Shape, b: &Shape, x0: f64, y0: f64) {
    let Some(fr) = axial_frame(report, a, b) else {
        return;
    };
    let (o, e1, e2) = (fr.o, fr.e1, fr.e2);
    let dec = report.deciders.as_ref();
    // the extent: anchors, X, conic centres, radii
    let mut pts = vec![fr.to2(a.anchor()), fr.to2(b.anchor())];
    if let Some(x) = dec.and_then(|d| d.x_point.as_ref()) {
        pts.push(fr.to2(q3(x)));
    }
    let mut size: f64 = 0.0;
    for s in [a, b] {
        if let Shape::Sphere { r, .. } | Shape::Cylinder { r, .. } = *s {
            size = size.max(r);
        }
    }
    let n = pts.len() as f64;
    let c2 = pts
        .iter()
        .fold((0.0, 0.0), |s, p| (s.0 + p.0 / n, s.1 + p.1 / n));
    let spread = pts
        .iter()
        .map(|p| ((p.0 - c2.0).powi(2) + (p.1 - c2.1).powi(2)).sqrt())
        .fold(0.0, f64::max);
    let r = ((spread + size) * 1.4).max(1e-9);
    let px = 0.5 * PANEL / r;
    let to_px = |p: (f64, f64)| {
        (
            x0 + PANEL / 2.0 + px * (p.0 - c2.0),
            y0 + PANEL / 2.0 - px * (p.1 - c2.1),
        )
    };
    svg.rect(x0, y0, PANEL, PANEL, "#fbfbfb", "#cccccc");
    svg.clipped(x0, y0, PANEL, PANEL);
    let line2 =
        |svg: &mut Svg, p: (f64, f64), d: (f64, f64), color: &str, w: f64, dash: Option<&str>| {
            let l = (d.0 * d.0 + d.1 * d.1).sqrt();
            if l == 0.0 {
                return;
            }
            let (dx, dy) = (d.0 / l, d.1 / l);
            let reach = 3.0 * r + ((p.0 - c2.0).powi(2) + (p.1 - c2.1).powi(2)).sqrt();
            svg.polyline(
                &[
                    to_px((p.0 - reach * dx, p.1 - reach * dy)),
                    to_px((p.0 + reach * dx, p.1 + reach * dy)),
                ],
                color,
                w,
                dash,
            );
        };
    // the axes, and each surface's section (its skeletal lines)
    for (s, color) in [(a, COLOR_A), (b, COLOR_B)] {
        match *s {
            Shape::Sphere { c, r: rr } => {
                let d = dot(sub(c, o), cross(e1, e2));
                let rad = (rr * rr - d * d).max(0.0).sqrt();
                svg.circle(to_px(fr.to2(c)), rad * px, "none", color, 2.0);
            }
            Shape::Cylinder { q, a: ax, .. } | Shape::Cone { v: q, a: ax, .. } => {
                line2(svg, fr.to2(q), fr.dir2(ax), color, 1.0, Some("8 4 2 4"));
            }
        }
    }
    // the skeletal lines: the deciders' exact ones, else the sections
    // from the surfaces' data
    let skeletal: Vec<Vec<(P3, P3)>> = match dec {
        Some(d) => d
            .skeletal
            .iter()
            .map(|ls| ls.iter().map(|(p, q)| (e3(p), e3(q))).collect())
            .collect(),
        None => vec![section_lines(a, &fr), section_lines(b, &fr)],
    };
    for (i, lines) in skeletal.iter().enumerate() {
        let color = if i == 0 { COLOR_A } else { COLOR_B };
        for (p, d) in lines {
            line2(svg, fr.to2(*p), fr.dir2(*d), color, 2.0, None);
        }
    }
    // the conics' planes, seen edge-on
    let normal = cross(e1, e2);
    for comp in &report.components {
        if let Component::Conic { plane, .. } = comp {
            let n = e3(&plane.normal);
            let dir = cross(n, normal);
            if norm(dir) < 1e-9 * norm(n) {
                continue;
            }
            // a point of the plane in the axial plane: o + s·m with m the
            // in-plane direction across `dir`
            let m = unit(cross(normal, dir));
            let denom = dot(n, m);
            if denom == 0.0 {
                continue;
            }
            let s = (ef(&plane.offset) - dot(n, o)) / denom;
            let p = add(o, scale(m, s));
            line2(svg, fr.to2(p), fr.dir2(dir), CONIC, 1.5, Some("6 4"));
        }
    }
    if let Some((dec, x)) = dec.and_then(|d| d.x_point.as_ref().map(|x| (d, x))) {
        let at = to_px(fr.to2(q3(x)));
        svg.circle(at, 5.0, "#111111", "white", 1.5);
        let label = format!(
            "X = ({}, {}, {})",
            short_q(&x[0]),
            short_q(&x[1]),
            short_q(&x[2])
        );
        svg.text((at.0 + 8.0, at.1 - 8.0), 12.0, "#111111", &label);
        if let Some((h1, h2)) = &dec.heights_at_x {
            let hl = format!("heights² at X: {}, {}", short_q(h1), short_q(h2));
            svg.text((at.0 + 8.0, at.1 + 16.0), 12.0, "#111111", &hl);
        }
    }
    svg.end_group();
    svg.text(
        (x0 + 8.0, y0 + 18.0),
        13.0,
        "#333333",
        "axial plane: sections, axes, X, conic planes",
    );
}

impl NaturalReport {
    /// The picture of the answer as SVG text (`quadsect natural --svg`):
    /// a 3D view of both surfaces with the components drawn thick and
    /// coloured by kind (conics, lines, points, curve branches; singular
    /// points marked), and, when the axes are coplanar, the axial plane of
    /// the paper's figures (the surfaces' sections, the axes, X and its
    /// heights, the conics' planes as lines); a legend with the class, the
    /// counts and the route.  Decisions and labels come from the exact
    /// answer; the strokes are doubles computed from its exact data.
    ///
    /// ```
    /// let a: quadsect::Natural = "sphere center=0,0,0 radius2=4".parse().unwrap();
    /// let b: quadsect::Natural = "cylinder point=1,0,0 axis=0,0,1 radius2=1".parse().unwrap();
    /// let svg = quadsect::classify(&a, &b).unwrap().svg();
    /// assert!(svg.starts_with("<svg") && svg.contains("class curve"));
    /// ```
    pub fn svg(&self) -> String {
        svg(self)
    }
}

/// The SVG picture of a natural-quadric answer.
pub(crate) fn svg(report: &NaturalReport) -> String {
    let a = shape(&report.a);
    let b = shape(&report.b);
    let title = format!(
        "{} ∩ {}: {}",
        report.a,
        report.b,
        report.counts.class.as_str()
    );
    let mut svg = Svg::new(W, H, &title);
    view_3d(&mut svg, report, &a, &b, 12.0, 12.0);
    let axial = axial_frame(report, &a, &b).is_some();
    if axial {
        axial_plane(&mut svg, report, &a, &b, 2.0 * 12.0 + PANEL, 12.0);
    }
    // the legend: below the panels, or beside the 3D view alone
    let (lx, y) = if axial {
        (14.0, PANEL + 36.0)
    } else {
        (2.0 * 12.0 + PANEL + 4.0, 60.0)
    };
    let counts = format!(
        "class {} — {} conic(s), {} line(s), {} point(s)",
        report.counts.class.as_str(),
        report.conics(),
        report.lines(),
        report.points()
    );
    svg.text((lx, y), 16.0, "#111111", &counts);
    svg.text((lx, y + 20.0), 12.0, COLOR_A, &format!("A: {}", report.a));
    svg.text((lx, y + 36.0), 12.0, COLOR_B, &format!("B: {}", report.b));
    let mut key = format!("route: {}", report.method);
    if let Some(t) = report.thm8 {
        key.push_str(&format!(" · Theorem 8.1/8.2: {t}"));
    }
    if let Some(d) = &report.deciders {
        key.push_str(&format!(
            " · discriminant {}",
            short(crate::number::fmt_q(&d.discriminant), || format!(
                "{:.6e}",
                qf(&d.discriminant)
            ))
        ));
    }
    svg.text((lx, y + 54.0), 12.0, "#333333", &key);
    let mut x = lx;
    for (color, name) in [
        (CONIC, "conic"),
        (LINE, "line"),
        (POINT, "point"),
        (CURVE, "curve branch"),
    ] {
        svg.polyline(&[(x, y + 70.0), (x + 24.0, y + 70.0)], color, 3.0, None);
        svg.text((x + 30.0, y + 74.0), 12.0, "#333333", name);
        x += 112.0;
    }
    let untraced = report
        .components
        .iter()
        .any(|c| matches!(c, Component::Curve { branches, .. } if branches.is_empty()));
    let mut notes: Vec<String> = Vec::new();
    if untraced {
        notes.push("the curve is not drawn: this answer has no branch data".into());
    }
    notes.extend(report.notes.iter().cloned());
    for (i, note) in notes.iter().take(4).enumerate() {
        let note: String = note.chars().take(80).collect();
        svg.text((lx, y + 96.0 + 16.0 * i as f64), 11.0, "#555555", &note);
    }
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The traced points of a space curve lie on both surfaces (to the
    /// doubles' accuracy), and every bounded branch closes.
    #[test]
    fn traced_curves_lie_on_both_surfaces() {
        for (a, b) in [
            (
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                "cone vertex=0,1,0 axis=1,1,0 tan2=3",
            ),
            (
                "cone vertex=0,0,0 axis=1,0,0 tan2=1",
                "cylinder point=0,0,0 axis=0,0,1 radius2=1",
            ),
            (
                "sphere center=0,0,0 radius2=4",
                "cylinder point=1,0,0 axis=0,0,1 radius2=1",
            ),
            (
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                "cylinder point=0,1/2,0 axis=1,1,1 radius2=2",
            ),
        ] {
            let (na, nb): (Natural, Natural) = (a.parse().unwrap(), b.parse().unwrap());
            let r = crate::natural::classify(&na, &nb).unwrap();
            let (sa, sb) = (shape(&na), shape(&nb));
            let mut traced = 0;
            for c in r.components() {
                let Component::Curve { branches, .. } = c else {
                    continue;
                };
                let paths = branches[0].start.trace(500);
                assert!(!paths.is_empty(), "{a} / {b}");
                for p in paths.iter().flatten() {
                    let size = 1.0 + norm(*p);
                    for s in [&sa, &sb] {
                        assert!(s.eval(*p).abs() < 1e-9 * size * size, "{a} / {b}: {p:?}");
                    }
                    traced += 1;
                }
                if branches.iter().all(|b| b.bounded) {
                    // closed: every path's ends meet another path's ends
                    let ends = |q: &Vec<P3>| [q[0], q[q.len() - 1]];
                    for (i, path) in paths.iter().enumerate() {
                        let [first, last] = ends(path);
                        let closed = norm(sub(first, last)) < 0.05;
                        for e in [first, last] {
                            let joined = paths.iter().enumerate().any(|(j, q)| {
                                j != i && ends(q).iter().any(|f| norm(sub(*f, e)) < 0.05)
                            });
                            assert!(closed || joined, "{a} / {b}: an open end {e:?}");
                        }
                    }
                }
            }
            assert!(traced > 100, "{a} / {b}: {traced} points");
        }
    }
}
