//! Planar intersections of two axial quadrics with coplanar axes (paper
//! §4–§6): the projection conic `F = h1² − h2²` factors into lines of the
//! axial plane H (Lemma 8.1); each real line `L` gives the plane through `L`
//! perpendicular to H (Lemma 4.4), and there the intersection is the conic
//! `z² = h1²(U)`, `U ∈ L` (heights, §4.3).
//!
//! This single construction covers the paper's cases: two conics through
//! the diagonals of the complete quadrilateral (§4, Algorithm
//! Conic-Intersection: `X`, where `∇F = 0`, is the meeting point of the
//! diagonals), the double line `V1V2` plus the residual conic (§5.2,
//! Theorem 5.1: `h1² ≡ 0` on the common skeletal line), the line pairs of a
//! common vertex (§6, Theorem 6.1: the lines `L1, L2` of Lemma 6.1 are the
//! factors of F through V, and the sign of the squared height along them
//! decides 2, 1 or 0 real lines), parallel axes (Theorem 8.2: one line of F
//! at infinity), and complex-conjugate factors, whose real common point
//! carries isolated tangency points (docs/errata.md).  Lines of F may need one
//! square root: everything is computed in Q(√d).

use super::deciders::{AxialPlane, Conic2};
use super::numbers::{EPoint, Exact, epoint, epoint_equal, nested};
use super::result::{Component, ConicKind, Plane, PointKind};
use crate::geom::vec3::{V3, cross, dot, norm2};
use crate::number::{Q, QSqrt, qi};
use num_traits::{One, Signed, Zero};

/// A line of the axial plane in frame coordinates: point `p`, direction `w`.
#[derive(Clone, Debug)]
pub struct HLine {
    /// A point (s, t).
    pub p: [QSqrt; 2],
    /// A direction (u, v).
    pub w: [QSqrt; 2],
    /// True when it is a double factor.
    pub double: bool,
}

/// The factorisation of a degenerate conic of H.
#[derive(Clone, Debug)]
pub enum Factored {
    /// Real lines.
    Lines(Vec<HLine>),
    /// Two complex-conjugate lines meeting at a real point.
    Point([Q; 2]),
    /// No real point (conjugate parallel lines, or a non-zero constant).
    Nothing,
    /// The zero conic.
    Zero,
}

fn qs(q: &Q) -> QSqrt {
    QSqrt::rational(q.clone())
}

fn rank_of(f: &Conic2) -> usize {
    if !crate::geom::det3(f).is_zero() {
        return 3;
    }
    let any_minor = (0..3).any(|i| {
        (0..3).any(|j| {
            (i + 1..3)
                .any(|k| (j + 1..3).any(|l| !(&f[i][j] * &f[k][l] - &f[i][l] * &f[k][j]).is_zero()))
        })
    });
    if any_minor {
        2
    } else if f.iter().flatten().any(|x| !x.is_zero()) {
        1
    } else {
        0
    }
}

/// Factors a degenerate conic (rank ≤ 2) of the axial plane into lines.
pub fn factor_conic(f: &Conic2) -> Factored {
    match rank_of(f) {
        0 => Factored::Zero,
        1 => {
            let row = (0..3)
                .find(|&i| f[i].iter().any(|x| !x.is_zero()))
                .unwrap_or(0);
            let v = &f[row];
            if v[0].is_zero() && v[1].is_zero() {
                return Factored::Nothing;
            }
            let p = if !v[0].is_zero() {
                [qs(&(-&v[2] / &v[0])), qs(&Q::zero())]
            } else {
                [qs(&Q::zero()), qs(&(-&v[2] / &v[1]))]
            };
            Factored::Lines(vec![HLine {
                p,
                w: [qs(&-&v[1]), qs(&v[0])],
                double: true,
            }])
        }
        2 => {
            // kernel vector from two independent rows
            let rows = [&f[0], &f[1], &f[2]];
            let mut k = [Q::zero(), Q::zero(), Q::zero()];
            'outer: for i in 0..3 {
                for j in i + 1..3 {
                    let c = cross(rows[i], rows[j]);
                    if c.iter().any(|x| !x.is_zero()) {
                        k = c;
                        break 'outer;
                    }
                }
            }
            let (f00, f01, f11) = (&f[0][0], &f[0][1], &f[1][1]);
            if !k[2].is_zero() {
                let x = [&k[0] / &k[2], &k[1] / &k[2]];
                let d = f01 * f01 - f00 * f11;
                if d.is_negative() {
                    return Factored::Point(x);
                }
                let p = [qs(&x[0]), qs(&x[1])];
                let dirs: Vec<[QSqrt; 2]> = if !f00.is_zero() {
                    [1, -1]
                        .iter()
                        .map(|&s| [QSqrt::new(-f01.clone(), qi(s), d.clone()), qs(f00)])
                        .collect()
                } else if !f11.is_zero() {
                    [1, -1]
                        .iter()
                        .map(|&s| [qs(f11), QSqrt::new(-f01.clone(), qi(s), d.clone())])
                        .collect()
                } else {
                    vec![[qs(&qi(1)), qs(&qi(0))], [qs(&qi(0)), qs(&qi(1))]]
                };
                Factored::Lines(
                    dirs.into_iter()
                        .map(|w| HLine {
                            p: p.clone(),
                            w,
                            double: false,
                        })
                        .collect(),
                )
            } else {
                // parallel lines with direction (k0, k1)
                let dir = [k[0].clone(), k[1].clone()];
                let pv = [-&k[1], k[0].clone()];
                let a = &f[0][0] * &pv[0] * &pv[0]
                    + Q::from_integer(2.into()) * &f[0][1] * &pv[0] * &pv[1]
                    + &f[1][1] * &pv[1] * &pv[1];
                let b = &pv[0] * &f[0][2] + &pv[1] * &f[1][2];
                let c = f[2][2].clone();
                let mk = |sigma: QSqrt, double: bool| HLine {
                    p: [sigma.scale(&pv[0]), sigma.scale(&pv[1])],
                    w: [qs(&dir[0]), qs(&dir[1])],
                    double,
                };
                if a.is_zero() {
                    if b.is_zero() {
                        return Factored::Nothing;
                    }
                    return Factored::Lines(vec![mk(
                        qs(&(-&c / (Q::from_integer(2.into()) * &b))),
                        false,
                    )]);
                }
                let disc = &b * &b - &a * &c;
                if disc.is_negative() {
                    return Factored::Nothing;
                }
                if disc.is_zero() {
                    return Factored::Lines(vec![mk(qs(&(-&b / &a)), true)]);
                }
                Factored::Lines(
                    [1, -1]
                        .iter()
                        .map(|&s| mk(QSqrt::new(-&b / &a, qi(s) / &a, disc.clone()), false))
                        .collect(),
                )
            }
        }
        _ => Factored::Nothing,
    }
}

/// `[s t 1] M [s t 1]ᵀ` over Q(√d).
fn eval2(m: &Conic2, s: &QSqrt, t: &QSqrt) -> QSqrt {
    let v = [s.clone(), t.clone(), qs(&qi(1))];
    let mut acc = qs(&Q::zero());
    for i in 0..3 {
        for j in 0..3 {
            if !m[i][j].is_zero() {
                acc = acc.add(&v[i].mul(&v[j]).scale(&m[i][j]));
            }
        }
    }
    acc
}

/// The 3D point of frame coordinates over Q(√d).
pub fn point3(h: &AxialPlane, s: &QSqrt, t: &QSqrt) -> [QSqrt; 3] {
    std::array::from_fn(|i| qs(&h.o[i]).add(&s.scale(&h.e1[i])).add(&t.scale(&h.e2[i])))
}

/// The 3D vector of frame components over Q(√d).
pub fn vec3(h: &AxialPlane, u: &QSqrt, v: &QSqrt) -> [QSqrt; 3] {
    std::array::from_fn(|i| u.scale(&h.e1[i]).add(&v.scale(&h.e2[i])))
}

fn rat_vec(v: &V3) -> EPoint {
    std::array::from_fn(|i| Exact::rational(v[i].clone()))
}

/// `base + s·μ·n` coordinate-wise, with `μ² = mu2 ∈ Q(√d)`.
pub(crate) fn offset_point(base: &[QSqrt; 3], n: &V3, mu2: &QSqrt, s: i32) -> EPoint {
    std::array::from_fn(|i| {
        nested(
            &base[i].a,
            &base[i].b,
            if base[i].b.is_zero() {
                &mu2.d
            } else {
                &base[i].d
            },
            &n[i],
            &mu2.a,
            &mu2.b,
            s,
        )
    })
}

/// The intersection in the plane through the line `l` of H perpendicular to
/// H, using the squared heights `h2` (either surface's; they agree on F = 0).
pub fn section(h: &AxialPlane, heights: &Conic2, l: &HLine) -> Vec<Component> {
    let (p, w) = (&l.p, &l.w);
    let mq = |i: usize, j: usize| &heights[i][j];
    // q(σ) = A σ² + B σ + C along p + σ w
    let mut a = qs(&Q::zero());
    let mut b = qs(&Q::zero());
    for i in 0..2 {
        for j in 0..2 {
            a = a.add(&w[i].mul(&w[j]).scale(mq(i, j)));
            b = b.add(&w[i].mul(&p[j]).scale(&(mq(i, j) * qi(2))));
        }
        b = b.add(&w[i].scale(&(mq(i, 2) * qi(2))));
    }
    let c = eval2(heights, &p[0], &p[1]);
    let base = point3(h, &p[0], &p[1]);
    let w3 = vec3(h, &w[0], &w[1]);
    let n = h.n.clone();
    let n2 = norm2(&n);
    let lam = dot(&w3, &w3);
    let normal = cross(&w3, &n);
    let plane = Plane {
        offset: Exact::Quad(dot(&normal, &base)),
        normal: epoint(&normal),
    };
    let at =
        |sigma: &QSqrt| -> [QSqrt; 3] { std::array::from_fn(|i| base[i].add(&sigma.mul(&w3[i]))) };
    let two = qi(2);
    let four = qi(4);
    let mut out = Vec::new();
    if a.is_zero() && b.is_zero() && c.is_zero() {
        // L lies on the surface: a line of contact (the plane is tangent)
        out.push(Component::Line {
            point: epoint(&base),
            direction: epoint(&w3),
            double: true,
        });
        return out;
    }
    if a.signum() != 0 {
        let sigma0 = b
            .neg()
            .div(&a.scale(&two))
            .unwrap_or_else(|| qs(&Q::zero()));
        let k = c.sub(
            &b.mul(&b)
                .div(&a.scale(&four))
                .unwrap_or_else(|| qs(&Q::zero())),
        );
        let center = at(&sigma0);
        if a.signum() < 0 {
            match k.signum() {
                1 => {
                    // ellipse: along L  k·λ/(−A), along the normal  k
                    let along = k.mul(&lam).div(&a.neg()).unwrap_or_else(|| qs(&Q::zero()));
                    let circle = a.neg().cmp_exact(&lam) == std::cmp::Ordering::Equal;
                    out.push(Component::Conic {
                        plane,
                        kind: if circle {
                            ConicKind::Circle
                        } else {
                            ConicKind::Ellipse
                        },
                        center: Some(epoint(&center)),
                        vertex: None,
                        axes2: vec![Exact::Quad(along), Exact::Quad(k)],
                        axis_dirs: vec![epoint(&w3), rat_vec(&n)],
                        focal2: None,
                        double: l.double,
                    });
                }
                0 => out.push(Component::Point {
                    point: epoint(&center),
                    kind: PointKind::Tangency,
                }),
                _ => {}
            }
        } else if k.signum() != 0 {
            let along = k.mul(&lam).div(&a).unwrap_or_else(|| qs(&Q::zero())).neg();
            let (axes2, dirs) = if k.signum() > 0 {
                (
                    vec![Exact::Quad(k.clone()), Exact::Quad(along.neg())],
                    vec![rat_vec(&n), epoint(&w3)],
                )
            } else {
                (
                    vec![Exact::Quad(along), Exact::Quad(k.neg())],
                    vec![epoint(&w3), rat_vec(&n)],
                )
            };
            out.push(Component::Conic {
                plane,
                kind: ConicKind::Hyperbola,
                center: Some(epoint(&center)),
                vertex: None,
                axes2,
                axis_dirs: dirs,
                focal2: None,
                double: l.double,
            });
        } else {
            // two lines through the centre: directions w3 ± μ n, μ² = A/|n|²
            let mu2 = a.scale(&(Q::one() / &n2));
            for s in [1, -1] {
                out.push(Component::Line {
                    point: epoint(&center),
                    direction: offset_point(&w3, &n, &mu2, s),
                    double: l.double,
                });
            }
        }
    } else if b.signum() != 0 {
        // parabola z² = Bσ + C: vertex at σ = −C/B, focal length² B²/(16 λ)
        let sv = c.neg().div(&b).unwrap_or_else(|| qs(&Q::zero()));
        let f2 = b
            .mul(&b)
            .div(&lam.scale(&qi(16)))
            .unwrap_or_else(|| qs(&Q::zero()));
        let dir: [QSqrt; 3] = if b.signum() > 0 {
            w3.clone()
        } else {
            std::array::from_fn(|i| w3[i].neg())
        };
        out.push(Component::Conic {
            plane,
            kind: ConicKind::Parabola,
            center: None,
            vertex: Some(epoint(&at(&sv))),
            axes2: vec![],
            axis_dirs: vec![epoint(&dir)],
            focal2: Some(Exact::Quad(f2)),
            double: l.double,
        });
    } else {
        // z² = C: two parallel lines, one double line, or nothing
        match c.signum() {
            1 => {
                let mu2 = c.scale(&(Q::one() / &n2));
                for s in [1, -1] {
                    out.push(Component::Line {
                        point: offset_point(&base, &n, &mu2, s),
                        direction: epoint(&w3),
                        double: l.double,
                    });
                }
            }
            0 => out.push(Component::Line {
                point: epoint(&base),
                direction: epoint(&w3),
                double: true,
            }),
            _ => {}
        }
    }
    out
}

/// The isolated points over the real meeting point X of two conjugate
/// lines of F: `X ± √(h²(X)/|n|²)·n`.
pub fn conjugate_points(h: &AxialPlane, heights: &Conic2, x: &[Q; 2]) -> Vec<Component> {
    let hx = super::deciders::eval_conic(heights, &x[0], &x[1]);
    let base = point3(h, &qs(&x[0]), &qs(&x[1]));
    match hx.cmp(&Q::zero()) {
        std::cmp::Ordering::Less => vec![],
        std::cmp::Ordering::Equal => vec![Component::Point {
            point: epoint(&base),
            kind: PointKind::Tangency,
        }],
        std::cmp::Ordering::Greater => {
            let mu2 = qs(&(hx / norm2(&h.n)));
            [1, -1]
                .iter()
                .map(|&s| Component::Point {
                    point: offset_point(&base, &h.n, &mu2, s),
                    kind: PointKind::Tangency,
                })
                .collect()
        }
    }
}

/// All real components of a planar intersection (F degenerate).
pub fn planar_components(h: &AxialPlane) -> Vec<Component> {
    let mut out: Vec<Component> = Vec::new();
    match factor_conic(&h.projection) {
        Factored::Lines(lines) => {
            for l in &lines {
                for c in section(h, &h.heights[0], l) {
                    push_unique(&mut out, c);
                }
            }
        }
        Factored::Point(x) => out = conjugate_points(h, &h.heights[0], &x),
        Factored::Nothing | Factored::Zero => {}
    }
    drop_points_on_lines(out)
}

/// Removes isolated points that lie on a reported line (a common vertex
/// where one plane gives lines and the other only the vertex).
pub fn drop_points_on_lines(comps: Vec<Component>) -> Vec<Component> {
    let lines: Vec<(EPoint, EPoint)> = comps
        .iter()
        .filter_map(|c| match c {
            Component::Line {
                point, direction, ..
            } => Some((point.clone(), direction.clone())),
            _ => None,
        })
        .collect();
    comps
        .into_iter()
        .filter(|c| match c {
            Component::Point { point, .. } => !lines
                .iter()
                .any(|(q, d)| epoint_equal(point, q) || on_line(point, q, d)),
            _ => true,
        })
        .collect()
}

/// Adds a component unless an equal point is already there (several planes
/// through a common vertex all degenerate to that vertex).
pub fn push_unique(out: &mut Vec<Component>, c: Component) {
    if let Component::Point { point, .. } = &c {
        for o in out.iter() {
            match o {
                Component::Point { point: q, .. } if epoint_equal(point, q) => return,
                Component::Line {
                    point: q,
                    direction,
                    ..
                } if on_line(point, q, direction) => return,
                _ => {}
            }
        }
    }
    out.push(c);
}

fn on_line(p: &EPoint, q: &EPoint, d: &EPoint) -> bool {
    // only exact-quadratic data is compared; other points are kept
    let get = |e: &Exact| match e {
        Exact::Quad(x) => Some(x.clone()),
        Exact::Alg(_) => None,
    };
    let (Some(p0), Some(p1), Some(p2)) = (get(&p[0]), get(&p[1]), get(&p[2])) else {
        return false;
    };
    let (Some(q0), Some(q1), Some(q2)) = (get(&q[0]), get(&q[1]), get(&q[2])) else {
        return false;
    };
    let (Some(d0), Some(d1), Some(d2)) = (get(&d[0]), get(&d[1]), get(&d[2])) else {
        return false;
    };
    let same_field = [&p0, &p1, &p2, &q0, &q1, &q2, &d0, &d1, &d2]
        .iter()
        .filter(|x| !x.is_rational())
        .map(|x| x.d.clone())
        .collect::<Vec<_>>();
    if same_field.windows(2).any(|w| w[0] != w[1]) {
        return false;
    }
    let r = [p0.sub(&q0), p1.sub(&q1), p2.sub(&q2)];
    let dd = [d0, d1, d2];
    // r × d = 0
    let c = [
        r[1].mul(&dd[2]).sub(&r[2].mul(&dd[1])),
        r[2].mul(&dd[0]).sub(&r[0].mul(&dd[2])),
        r[0].mul(&dd[1]).sub(&r[1].mul(&dd[0])),
    ];
    c.iter().all(|x| x.is_zero())
}

/// §6 (common vertex V of two cones): the squared heights at the
/// parallelogram vertices A ∈ L1 and D ∈ L2 — the points of the diagonals
/// (the lines of F through V) whose projection on ℓ1 is at distance cos α1
/// from V: with A − V = μ w, `μ² = |a1|²/((1 + t2)(w·a1)²)` and
/// `h²(A) = μ² h²(w)` (h² is homogeneous around V).
pub fn parallelogram_heights(h: &AxialPlane, a1: &V3, t2: &Q) -> Option<Vec<Exact>> {
    let Factored::Lines(lines) = factor_conic(&h.projection) else {
        return None;
    };
    let mut out = Vec::new();
    for l in &lines {
        let w3 = vec3(h, &l.w[0], &l.w[1]);
        let wa = (0..3).fold(qs(&Q::zero()), |acc, i| acc.add(&w3[i].scale(&a1[i])));
        // squared height along the direction w (the quadratic coefficient A)
        let mut qw = qs(&Q::zero());
        for i in 0..2 {
            for j in 0..2 {
                qw = qw.add(&l.w[i].mul(&l.w[j]).scale(&h.heights[0][i][j]));
            }
        }
        let den = wa.mul(&wa).scale(&(Q::one() + t2));
        let v = qw.scale(&norm2(a1)).div(&den)?;
        out.push(Exact::Quad(v));
    }
    Some(out)
}

/// The skeletal lines of an axial quadric in H (factors of `h² = 0`), as 3D
/// point and direction.
pub fn skeletal_lines(h: &AxialPlane, heights: &Conic2) -> Vec<(EPoint, EPoint)> {
    match factor_conic(heights) {
        Factored::Lines(ls) => ls
            .iter()
            .map(|l| {
                (
                    epoint(&point3(h, &l.p[0], &l.p[1])),
                    epoint(&vec3(h, &l.w[0], &l.w[1])),
                )
            })
            .collect(),
        _ => vec![],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::natural::parse_natural;

    #[test]
    fn equal_perpendicular_cylinders_give_two_ellipses() {
        let a = parse_natural("cylinder point=0,0,0 axis=1,0,0 radius2=1").unwrap();
        let b = parse_natural("cylinder point=0,0,0 axis=0,1,0 radius2=1").unwrap();
        let h = AxialPlane::new(&a, &b).unwrap();
        let comps = planar_components(&h);
        assert_eq!(comps.len(), 2);
        for c in &comps {
            match c {
                Component::Conic {
                    kind, plane, axes2, ..
                } => {
                    assert_eq!(*kind, ConicKind::Ellipse);
                    // planes x = ±y: normal (±1, 1, 0) up to scale, through 0
                    assert!(plane.offset.signum() == 0);
                    let n = &plane.normal;
                    assert_eq!(n[2].signum(), 0);
                    assert!(
                        n[0].equals(&n[1])
                            || n[0].equals(&Exact::Quad(match &n[1] {
                                Exact::Quad(x) => x.neg(),
                                _ => unreachable!(),
                            }))
                    );
                    // semi-axes² 2 (along the diagonal) and 1
                    assert!(axes2[0].equals(&Exact::rational(qi(2))));
                    assert!(axes2[1].equals(&Exact::rational(qi(1))));
                }
                other => panic!("unexpected {other:?}"),
            }
        }
    }
}
