//! Tangency and disjointness for skew axes, the paper's way (§7): the
//! cylinder–cylinder rule, Theorem 7.1 (cone–cone) and Corollary 7.1
//! (cone–cylinder), with the bounding planes computed exactly in Q(√d) and
//! every distance compared through its square.
//!
//! With the errata of docs/errata.md: the cones are double cones, so the contact
//! point `t_i ∩ V2S_i` is taken on the whole line `V2S_i`; when `t_i ∥ V2S_i`
//! the contact is at infinity and the surfaces are disjoint.
//!
//! This is an independent decider: the classification itself uses the
//! topology of the intersection curve ([`super::topology`]), and the tests
//! check that both agree wherever the theorem's hypotheses hold.

use super::deciders::{AxesRelation, axes_relation};
use super::types::{Cone, Cylinder, Natural, dist2_point_line};
use crate::geom::vec3::{V3, cross, dot, norm2, orthogonal, sub};
use crate::number::{Q, QSqrt, qi};
use num_traits::{One, Signed, Zero};

/// The verdict of the paper's §7 tangency decider (skew axes).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Section7 {
    /// The hypotheses do not hold (or the pair is not covered): the reason.
    NotApplicable(String),
    /// Case 1: the surfaces are disjoint.
    Disjoint,
    /// Cases 2–4: tangent at these isolated points.
    Tangent(Vec<[QSqrt; 3]>),
    /// Case 5 (or Lemma 7.1/7.2): they cross.
    Transversal,
}

type SV = [QSqrt; 3];

fn sv(v: &V3) -> SV {
    std::array::from_fn(|i| QSqrt::rational(v[i].clone()))
}

fn sdot(a: &SV, b: &SV) -> QSqrt {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}

fn ssub(a: &SV, b: &SV) -> SV {
    std::array::from_fn(|i| a[i].sub(&b[i]))
}

fn sadd_scaled(a: &SV, b: &SV, k: &QSqrt) -> SV {
    std::array::from_fn(|i| a[i].add(&b[i].mul(k)))
}

fn scross(a: &SV, b: &SV) -> SV {
    [
        a[1].mul(&b[2]).sub(&a[2].mul(&b[1])),
        a[2].mul(&b[0]).sub(&a[0].mul(&b[2])),
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0])),
    ]
}

/// Cylinder–cylinder with skew axes: tangent iff the common perpendicular
/// has length `r1 + r2` (compared as `d² − r1² − r2² = 2 r1 r2`).
pub fn cylinder_cylinder(c1: &Cylinder, c2: &Cylinder) -> Section7 {
    let n = cross(&c1.axis, &c2.axis);
    if n.iter().all(|x| x.is_zero()) {
        return Section7::NotApplicable("parallel axes".into());
    }
    let w = sub(&c2.point, &c1.point);
    let dn = dot(&w, &n);
    let d2 = &dn * &dn / norm2(&n);
    // sign of d − (r1 + r2)  =  sign of (d² − r1² − r2²) − 2√(r1² r2²)
    let s = QSqrt::new(&d2 - &c1.r2 - &c2.r2, qi(-2), &c1.r2 * &c2.r2).signum();
    let far = (&d2 - &c1.r2 - &c2.r2).is_positive();
    match (far, s) {
        (true, 1) => Section7::Disjoint,
        (true, 0) => {
            // feet of the common perpendicular, then r1/d of the way
            let (f1, f2) = feet(&c1.point, &c1.axis, &c2.point, &c2.axis);
            let k = QSqrt::sqrt(&c1.r2 / &d2);
            let p = sadd_scaled(&sv(&f1), &sv(&sub(&f2, &f1)), &k);
            Section7::Tangent(vec![p])
        }
        _ => Section7::Transversal,
    }
}

/// Feet of the common perpendicular of two skew lines (rational).
fn feet(p1: &V3, a1: &V3, p2: &V3, a2: &V3) -> (V3, V3) {
    let w = sub(p1, p2);
    let (a, b, c) = (dot(a1, a1), dot(a1, a2), dot(a2, a2));
    let (d, e) = (dot(a1, &w), dot(a2, &w));
    let den = &a * &c - &b * &b;
    let s = (&b * &e - &c * &d) / &den;
    let t = (&a * &e - &b * &d) / &den;
    (
        std::array::from_fn(|i| &p1[i] + &a1[i] * &s),
        std::array::from_fn(|i| &p2[i] + &a2[i] * &t),
    )
}

/// Where a point lies relative to a cone: -1 inside the solid double cone,
/// 0 on it, 1 outside.
fn cone_side(c: &Cone, p: &V3) -> i32 {
    let d = sub(p, &c.vertex);
    let da = dot(&d, &c.axis);
    let v = norm2(&c.axis) * norm2(&d) - (Q::one() + &c.t2) * &da * &da;
    crate::number::sign_q(&v)
}

/// The two planes through the vertex of `cone` containing the direction `u`
/// and tangent to the cone: normals in Q(√D) (Definition 7.1).  `None` when
/// `u` points into the cone.
fn bounding_normals(cone: &Cone, u: &V3) -> Option<[SV; 2]> {
    let w1 = orthogonal(u);
    let w2 = cross(u, &w1);
    let a = &cone.axis;
    let a2 = norm2(a);
    // n = x w1 + y w2,  (1 + t2)(n·a)² = t2 |n|²|a|²
    let (p, q) = (dot(&w1, a), dot(&w2, a));
    let (g11, g12, g22) = (norm2(&w1), dot(&w1, &w2), norm2(&w2));
    let k1 = Q::one() + &cone.t2;
    let k2 = &cone.t2 * &a2;
    let cxx = &k1 * &p * &p - &k2 * &g11;
    let cxy = qi(2) * (&k1 * &p * &q - &k2 * &g12);
    let cyy = &k1 * &q * &q - &k2 * &g22;
    // cxx x² + cxy x y + cyy y² = 0
    let disc = &cxy * &cxy - qi(4) * &cxx * &cyy;
    if !disc.is_positive() {
        return None;
    }
    let mk = |x: QSqrt, y: QSqrt| -> SV {
        std::array::from_fn(|i| x.scale(&w1[i]).add(&y.scale(&w2[i])))
    };
    if !cxx.is_zero() {
        let n: Vec<SV> = [1, -1]
            .iter()
            .map(|&s| {
                mk(
                    QSqrt::new(-cxy.clone(), qi(s), disc.clone()),
                    QSqrt::rational(qi(2) * &cxx),
                )
            })
            .collect();
        Some([n[0].clone(), n[1].clone()])
    } else {
        // x (cxy y) + cyy y² = 0 with cxx = 0: y = 0 or cxy x + cyy y = 0
        Some([
            mk(QSqrt::rational(qi(1)), QSqrt::rational(qi(0))),
            mk(QSqrt::rational(-cyy.clone()), QSqrt::rational(cxy.clone())),
        ])
    }
}

/// Meeting point of the lines `p + λ r` and `q + μ s` (coplanar); `None`
/// when parallel.
fn meet(p: &SV, r: &SV, q: &SV, s: &SV) -> Option<SV> {
    let rs = scross(r, s);
    let rs2 = sdot(&rs, &rs);
    if rs2.is_zero() {
        return None;
    }
    let lam = sdot(&scross(&ssub(q, p), s), &rs).div(&rs2)?;
    Some(sadd_scaled(p, r, &lam))
}

/// The common part of Theorem 7.1 and Corollary 7.1: `cone` is C (C1), the
/// second surface is represented by its axis point `s` (S), the apex of its
/// lines (`v_point`, V2, or `None` for a cylinder), the line direction `u`
/// of v, and the inscribed-sphere radius² `rho2` at S.
fn bounding_test(cone: &Cone, u: &V3, axis2: &V3, s: &V3, rho2: &Q, v2: Option<&V3>) -> Section7 {
    let Some(normals) = bounding_normals(cone, u) else {
        return Section7::NotApplicable("the line v lies inside the cone".into());
    };
    let v1 = sv(&cone.vertex);
    // ℓ2 outside B(C, v): the cone occupies the quadrants of sign ±(σ1, σ2).
    // For two cones ℓ2 leaves v at V2 along a2, so its side is that of a2;
    // for a cylinder ℓ2 is parallel to v, so its side is that of S − V.
    let sig: Vec<i32> = normals
        .iter()
        .map(|n| sdot(n, &sv(&cone.axis)).signum())
        .collect();
    let probe = match v2 {
        Some(_) => axis2.clone(),
        None => sub(s, &cone.vertex),
    };
    let dir: Vec<i32> = normals
        .iter()
        .map(|n| sdot(n, &sv(&probe)).signum())
        .collect();
    if dir.contains(&0) {
        return Section7::NotApplicable("the axis lies in a bounding plane".into());
    }
    let inside = (dir[0] == sig[0] && dir[1] == sig[1]) || (dir[0] == -sig[0] && dir[1] == -sig[1]);
    if inside {
        return Section7::Transversal; // Lemma 7.2
    }
    // distances² from S to the bounding planes
    let ssv = sv(s);
    let d2: Vec<QSqrt> = normals
        .iter()
        .map(|n| {
            let h = sdot(n, &ssub(&ssv, &v1));
            h.mul(&h)
                .div(&sdot(n, n))
                .unwrap_or_else(|| QSqrt::rational(Q::zero()))
        })
        .collect();
    let rho = QSqrt::rational(rho2.clone());
    let cmp: Vec<i32> = d2.iter().map(|x| x.sub(&rho).signum()).collect();
    if cmp.iter().any(|&c| c < 0) {
        return Section7::Transversal; // case 5
    }
    if cmp.iter().all(|&c| c > 0) {
        return Section7::Disjoint; // case 1
    }
    let mut pts = Vec::new();
    for (i, n) in normals.iter().enumerate() {
        if cmp[i] != 0 {
            continue;
        }
        // tangent line t_i: the ruling of C in T_i
        let a = sv(&cone.axis);
        let k = sdot(&a, n)
            .div(&sdot(n, n))
            .unwrap_or_else(|| QSqrt::rational(Q::zero()));
        let r = ssub(&a, &std::array::from_fn(|j| n[j].mul(&k)));
        // S_i: the foot of S on T_i
        let h = sdot(n, &ssub(&ssv, &v1))
            .div(&sdot(n, n))
            .unwrap_or_else(|| QSqrt::rational(Q::zero()));
        let si: SV = std::array::from_fn(|j| ssv[j].sub(&n[j].mul(&h)));
        // the other surface touches T_i along V2S_i (cone) or the line
        // through S_i parallel to its axis (cylinder)
        let (q, sdir) = match v2 {
            Some(v) => (sv(v), ssub(&si, &sv(v))),
            None => (si.clone(), sv(axis2)),
        };
        if let Some(p) = meet(&v1, &r, &q, &sdir) {
            pts.push(p);
        }
    }
    if pts.is_empty() {
        Section7::Disjoint
    } else {
        Section7::Tangent(pts)
    }
}

/// Theorem 7.1 (two cones with skew axes).
pub fn cone_cone(c1: &Cone, c2: &Cone) -> Section7 {
    if cone_side(c2, &c1.vertex) <= 0 || cone_side(c1, &c2.vertex) <= 0 {
        return if cone_side(c2, &c1.vertex) < 0 || cone_side(c1, &c2.vertex) < 0 {
            Section7::Transversal // Lemma 7.1: a vertex inside the other cone
        } else {
            Section7::NotApplicable("a vertex lies on the other cone".into())
        };
    }
    let u = sub(&c2.vertex, &c1.vertex);
    // S = V2 + a2, d = |a2|, inscribed radius² d² sin²α2
    let s: V3 = std::array::from_fn(|i| &c2.vertex[i] + &c2.axis[i]);
    let rho2 = norm2(&c2.axis) * c2.sin2();
    bounding_test(c1, &u, &c2.axis, &s, &rho2, Some(&c2.vertex))
}

/// Corollary 7.1 (a cone and a cylinder with skew axes).
pub fn cone_cylinder(c: &Cone, z: &Cylinder) -> Section7 {
    let dv = dist2_point_line(&c.vertex, &z.point, &z.axis);
    if dv < z.r2 {
        return Section7::Transversal; // the vertex is inside the cylinder
    }
    if dv == z.r2 {
        return Section7::NotApplicable("the vertex lies on the cylinder".into());
    }
    bounding_test(c, &z.axis, &z.axis, &z.point, &z.r2, None)
}

/// The §7 decider for two axial quadrics with skew axes.
pub fn section7(a: &Natural, b: &Natural) -> Section7 {
    let (Some((p1, a1)), Some((p2, a2))) = (a.axis_line(), b.axis_line()) else {
        return Section7::NotApplicable("a sphere is involved".into());
    };
    if axes_relation(&p1, &a1, &p2, &a2) != AxesRelation::Skew {
        return Section7::NotApplicable("the axes are not skew".into());
    }
    match (a, b) {
        (Natural::Cylinder(x), Natural::Cylinder(y)) => cylinder_cylinder(x, y),
        (Natural::Cone(x), Natural::Cone(y)) => cone_cone(x, y),
        (Natural::Cone(x), Natural::Cylinder(y)) | (Natural::Cylinder(y), Natural::Cone(x)) => {
            cone_cylinder(x, y)
        }
        _ => Section7::NotApplicable("a sphere is involved".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::natural::parse_natural;

    fn run(a: &str, b: &str) -> Section7 {
        section7(&parse_natural(a).unwrap(), &parse_natural(b).unwrap())
    }

    #[test]
    fn cylinder_rule() {
        let a = "cylinder point=0,0,0 axis=1,0,0 radius2=1";
        assert!(matches!(
            run(a, "cylinder point=0,0,3 axis=0,1,0 radius2=1"),
            Section7::Disjoint
        ));
        assert!(matches!(
            run(a, "cylinder point=0,0,1 axis=0,1,0 radius2=1"),
            Section7::Transversal
        ));
        match run(a, "cylinder point=0,0,2 axis=0,1,0 radius2=1") {
            Section7::Tangent(p) => assert_eq!(p[0][2], QSqrt::rational(qi(1))),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn corollary_7_1() {
        let z = "cylinder point=0,0,0 axis=1,0,0 radius2=1";
        match run(z, "cone vertex=0,0,2 axis=0,1,0 tan2=3") {
            Section7::Tangent(p) => assert_eq!(p.len(), 2),
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            run(z, "cone vertex=0,0,3 axis=0,1,0 tan2=1"),
            Section7::Disjoint
        ));
    }
}
