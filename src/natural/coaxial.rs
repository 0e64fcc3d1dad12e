//! Intersections made of circles: two spheres, a sphere centred on the axis
//! of a cylinder or cone, and two axial quadrics on the same axis (paper
//! §4, footnote 3, Algorithm Conic-Intersection step 2).  Every point of
//! such an intersection lies on a circle about the common axis, so the
//! computation is one quadratic equation in the position along the axis.

use super::numbers::{EPoint, Exact, epoint};
use super::result::{Component, ConicKind, Plane, PointKind};
use super::types::{Cone, Natural, Sphere, axial_param};
use crate::geom::vec3::{V3, add, cross, lift, norm2, orthogonal, scale, sub};
use crate::number::{Q, QSqrt, qi};
use num_traits::{One, Signed, Zero};

fn circle(center: [QSqrt; 3], axis: &V3, r2: QSqrt, double: bool) -> Component {
    let u = orthogonal(axis);
    let v = cross(axis, &u);
    let offset = (0..3).fold(QSqrt::rational(Q::zero()), |acc, i| {
        acc.add(&center[i].scale(&axis[i]))
    });
    Component::Conic {
        plane: Plane {
            normal: std::array::from_fn(|i| Exact::rational(axis[i].clone())),
            offset: Exact::Quad(offset),
        },
        kind: ConicKind::Circle,
        center: Some(epoint(&center)),
        vertex: None,
        axes2: vec![Exact::Quad(r2.clone()), Exact::Quad(r2)],
        axis_dirs: vec![rat(&u), rat(&v)],
        focal2: None,
        double,
    }
}

fn rat(v: &V3) -> EPoint {
    std::array::from_fn(|i| Exact::rational(v[i].clone()))
}

/// `p + τ a` with `τ ∈ Q(√d)`.
fn along(p: &V3, a: &V3, tau: &QSqrt) -> [QSqrt; 3] {
    std::array::from_fn(|i| QSqrt::rational(p[i].clone()).add(&tau.scale(&a[i])))
}

/// Two spheres: a circle in the radical plane, a tangency point, or nothing
/// (all rational: the circle's centre is `O1 + k (O2 − O1)` with
/// `k = (d² + r1² − r2²)/(2d²)` and radius² `r1² − k² d²`).
pub fn sphere_sphere(s1: &Sphere, s2: &Sphere) -> Vec<Component> {
    let dv = sub(&s2.center, &s1.center);
    let d2 = norm2(&dv);
    if d2.is_zero() {
        return vec![]; // concentric, different radii (same radii: same surface)
    }
    let k = (&d2 + &s1.r2 - &s2.r2) / (qi(2) * &d2);
    let c = add(&s1.center, &scale(&dv, &k));
    let rho2 = &s1.r2 - &k * &k * &d2;
    if rho2.is_positive() {
        vec![circle(lift(&c), &dv, QSqrt::rational(rho2), false)]
    } else if rho2.is_zero() {
        vec![Component::Point {
            point: epoint(&lift(&c)),
            kind: PointKind::Tangency,
        }]
    } else {
        vec![]
    }
}

/// A sphere whose centre lies on the axis of a cylinder or cone: circles
/// perpendicular to the axis (a double circle where the sphere is
/// inscribed), and the vertex when the sphere passes through it.
pub fn sphere_on_axis(s: &Sphere, q: &Natural) -> Vec<Component> {
    match q {
        Natural::Cylinder(c) => {
            let a = &c.axis;
            // |τ a|² + r_c² = r_s²
            let t2 = (&s.r2 - &c.r2) / norm2(a);
            if t2.is_negative() {
                return vec![];
            }
            if t2.is_zero() {
                return vec![circle(
                    lift(&s.center),
                    a,
                    QSqrt::rational(c.r2.clone()),
                    true,
                )];
            }
            [1, -1]
                .iter()
                .map(|&sg| {
                    let tau = QSqrt::new(Q::zero(), qi(sg), t2.clone());
                    circle(
                        along(&s.center, a, &tau),
                        a,
                        QSqrt::rational(c.r2.clone()),
                        false,
                    )
                })
                .collect()
        }
        Natural::Cone(c) => sphere_cone_on_axis(s, c),
        Natural::Sphere(_) => vec![],
    }
}

fn sphere_cone_on_axis(s: &Sphere, c: &Cone) -> Vec<Component> {
    let a = &c.axis;
    let a2 = norm2(a);
    let to = axial_param(&s.center, &c.vertex, a);
    // (1 + t2)|a|² τ² − 2 τ_O |a|² τ + τ_O²|a|² − r² = 0
    let qa = (Q::one() + &c.t2) * &a2;
    let qb = -(qi(2) * &to * &a2);
    let qc = &to * &to * &a2 - &s.r2;
    let disc = &qb * &qb - qi(4) * &qa * &qc;
    let radius2 = |tau: &QSqrt| tau.mul(tau).scale(&(&c.t2 * &a2));
    let mut out = Vec::new();
    if disc.is_negative() {
        return out;
    }
    if disc.is_zero() {
        let tau = QSqrt::rational(-&qb / (qi(2) * &qa));
        out.push(circle(along(&c.vertex, a, &tau), a, radius2(&tau), true));
        return out;
    }
    for sg in [1, -1] {
        let tau = QSqrt::new(-&qb / (qi(2) * &qa), qi(sg) / (qi(2) * &qa), disc.clone());
        if tau.is_zero() {
            out.push(Component::Point {
                point: epoint(&lift(&c.vertex)),
                kind: PointKind::Vertex,
            });
        } else {
            out.push(circle(along(&c.vertex, a, &tau), a, radius2(&tau), false));
        }
    }
    out
}

/// Two axial quadrics on the same axis (not the same surface): two circles,
/// one circle, the common vertex only, or nothing.
pub fn same_axis(x: &Natural, y: &Natural) -> Vec<Component> {
    match (x, y) {
        (Natural::Cylinder(_), Natural::Cylinder(_)) => vec![],
        (Natural::Cone(k), Natural::Cylinder(c)) | (Natural::Cylinder(c), Natural::Cone(k)) => {
            let a = &k.axis;
            // t2 τ² |a|² = r2
            let t = &c.r2 / (&k.t2 * norm2(a));
            [1, -1]
                .iter()
                .map(|&sg| {
                    let tau = QSqrt::new(Q::zero(), qi(sg), t.clone());
                    circle(
                        along(&k.vertex, a, &tau),
                        a,
                        QSqrt::rational(c.r2.clone()),
                        false,
                    )
                })
                .collect()
        }
        (Natural::Cone(k1), Natural::Cone(k2)) => {
            let a = &k1.axis;
            let a2 = norm2(a);
            let delta = axial_param(&k2.vertex, &k1.vertex, a);
            if delta.is_zero() {
                // common vertex, different angles: only the vertex
                return vec![Component::Point {
                    point: epoint(&lift(&k1.vertex)),
                    kind: PointKind::Vertex,
                }];
            }
            let (t1, t2) = (&k1.t2, &k2.t2);
            if t1 == t2 {
                let tau = QSqrt::rational(&delta / qi(2));
                let r2 = tau.mul(&tau).scale(&(t1 * &a2));
                return vec![circle(along(&k1.vertex, a, &tau), a, r2, false)];
            }
            // (t1 − t2) τ² + 2 t2 δ τ − t2 δ² = 0, disc/4 = t1 t2 δ²
            let den = t1 - t2;
            [1, -1]
                .iter()
                .map(|&sg| {
                    let tau = QSqrt::new(-(t2 * &delta) / &den, qi(sg) * &delta / &den, t1 * t2);
                    let r2 = tau.mul(&tau).scale(&(t1 * &a2));
                    circle(along(&k1.vertex, a, &tau), a, r2, false)
                })
                .collect()
        }
        _ => vec![],
    }
}

/// True when the sphere's centre lies on the quadric's axis.
pub fn center_on_axis(s: &Sphere, q: &Natural) -> bool {
    match q.axis_line() {
        Some((p, a)) => cross(&sub(&s.center, &p), &a).iter().all(|x| x.is_zero()),
        None => false,
    }
}
