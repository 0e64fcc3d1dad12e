//! The real intersection curve `X = Q1 ∩ Q2` of two natural quadrics when
//! it is *not* planar: a genuine space curve, isolated points, or nothing —
//! decided exactly by algebra (no floating point, no tolerance).
//!
//! * **Singular points** of X: the zeros of `Q1 = Q2 = 0, ∇Q1 × ∇Q2 = 0`
//!   (a cone vertex on the other surface is one of them); every isolated
//!   real point of X is singular.
//! * **Common rulings** (skew axes, docs/errata.md): a ruling of one surface lying
//!   on the other, found by exact linear algebra and one square root; X is
//!   then that line plus a twisted cubic (class `curve`, `lines` 1).
//! * **One-dimensional real part** (sweep): for a generic linear form ℓ, the
//!   values of ℓ at the critical points of ℓ on X (zeros of `Q1, Q2,
//!   det(∇Q1, ∇Q2, ∇ℓ)`) cut the line into gaps; the real part of X has
//!   dimension one iff a level `ℓ = q` in some gap meets X in a real point.
//! * **Isolated or crossing** (tangent cone, docs/errata.md on §5.1): at a singular
//!   point with `∇Q1 = λ∇Q2 ≠ 0`, the quadratic form `Hess Q1 − λ Hess Q2`
//!   on the common tangent plane is definite (isolated point) or indefinite
//!   (two real branches cross); at a cone vertex V on the other surface, the
//!   cone's form on the other surface's tangent plane at V decides the same.

use super::numbers::{EPoint, Exact, epoint, exact_of};
use super::result::{Component, PointKind, SingularKind, SingularPoint};
use super::types::Natural;
use crate::error::Error;
use crate::geom::QuadricForm;
use crate::geom::eval_qsqrt;
use crate::geom::vec3::{V3, cross, dot, lift, norm2, orthogonal};
use crate::number::{Q, QSqrt, qi};
use crate::poly::mpoly::MPoly;
use crate::poly::{QMPoly, QPoly};
use crate::roots::{RealAlg, separate, simplest_rational_in, values_at, values_with};
use crate::system::{GENERIC_FORMS, Rur, solve_zero_dim};
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// A real zero of a system, with exact coordinates.
#[derive(Clone, Debug)]
pub struct RealZero {
    /// Index in the RUR's real roots.
    pub index: usize,
    /// Coordinates as real algebraic numbers.
    pub coords: [RealAlg; 3],
}

fn real_zeros(rur: &Rur) -> Vec<RealZero> {
    let one = QPoly::constant(Q::one());
    let per: Vec<Vec<RealAlg>> = (0..3)
        .map(|k| {
            values_at(&rur.f, &rur.real_roots, &rur.coords[k], &one)
                .into_iter()
                .map(|v| v.expect("denominator 1"))
                .collect()
        })
        .collect();
    (0..rur.real_roots.len())
        .map(|i| RealZero {
            index: i,
            coords: std::array::from_fn(|k| per[k][i].clone()),
        })
        .collect()
}

/// Sign of a polynomial in x, y, z at a real zero of a RUR.
fn sign_at_zero(rur: &Rur, i: usize, p: &QMPoly) -> i32 {
    if p.is_zero() {
        return 0;
    }
    // substitute x = X(t), y = Y(t), z = Z(t), reduce mod f
    let f = rur.f.to_q();
    let mut subs: [Option<QMPoly>; crate::poly::mpoly::NVARS] = Default::default();
    for k in 0..3 {
        subs[k] = Some(MPoly::from_univariate(
            &rur.coords[k],
            crate::poly::mpoly::T,
        ));
    }
    let pt = p.substitute_all(&subs);
    let up = pt
        .to_univariate(crate::poly::mpoly::T)
        .unwrap_or_else(QPoly::zero);
    let r = up.rem(&f);
    rur.real_roots[i].sign_of_q(&r)
}

/// The singular points of X, or `None` when X is singular along a curve.
pub fn singular_points(f1: &QMPoly, f2: &QMPoly) -> Result<Option<Rur>, Error> {
    let c = cross(&crate::geom::gradient(f1), &crate::geom::gradient(f2));
    let mut gens = vec![f1.clone(), f2.clone()];
    gens.extend(c);
    solve_zero_dim(&gens, &[])
}

/// Is the real singular point `i` an isolated point of the real curve?
/// `Some(true)` isolated, `Some(false)` real branches pass through it,
/// `None` when the tangent cone is degenerate.
pub fn isolated_by_tangent_cone(f1: &QMPoly, f2: &QMPoly, rur: &Rur, i: usize) -> Option<bool> {
    let g1 = crate::geom::gradient(f1);
    let g2 = crate::geom::gradient(f2);
    let zero1 = g1.iter().all(|g| sign_at_zero(rur, i, g) == 0);
    let zero2 = g2.iter().all(|g| sign_at_zero(rur, i, g) == 0);
    let h1 = QuadricForm::from_poly(f1)?;
    let h2 = QuadricForm::from_poly(f2)?;
    let hess = |f: &QuadricForm| -> [[QMPoly; 3]; 3] {
        std::array::from_fn(|r| std::array::from_fn(|c| MPoly::constant(&f.a[r][c] * qi(2))))
    };
    let (h, normal): ([[QMPoly; 3]; 3], [QMPoly; 3]) = match (zero1, zero2) {
        (true, true) => return None,
        (true, false) => (hess(&h1), g2.clone()),
        (false, true) => (hess(&h2), g1.clone()),
        (false, false) => {
            // |g2|² H1 − (g1·g2) H2
            let n2 = dot(&g2, &g2);
            let l = dot(&g1, &g2);
            let a = hess(&h1);
            let b = hess(&h2);
            (
                std::array::from_fn(|r| {
                    std::array::from_fn(|c| &(&a[r][c] * &n2) - &(&b[r][c] * &l))
                }),
                g2.clone(),
            )
        }
    };
    // a basis of the tangent plane normal^⊥: u1 = normal × e_k, u2 = normal × u1
    for k in 0..3 {
        let mut e: [QMPoly; 3] = [MPoly::zero(), MPoly::zero(), MPoly::zero()];
        e[k] = MPoly::constant(Q::one());
        let u1 = cross(&normal, &e);
        if u1.iter().all(|c| sign_at_zero(rur, i, c) == 0) {
            continue;
        }
        let u2 = cross(&normal, &u1);
        let form = |u: &[QMPoly; 3], v: &[QMPoly; 3]| -> QMPoly {
            let mut acc = MPoly::zero();
            for r in 0..3 {
                for c in 0..3 {
                    acc = &acc + &(&(&u[r] * &h[r][c]) * &v[c]);
                }
            }
            acc
        };
        let (a11, a12, a22) = (form(&u1, &u1), form(&u1, &u2), form(&u2, &u2));
        let det = &(&a11 * &a22) - &(&a12 * &a12);
        return match sign_at_zero(rur, i, &det) {
            1 => Some(true),
            -1 => Some(false),
            _ => None,
        };
    }
    None
}

/// Rulings of `q` that lie on the surface `other` (exactly computed lines).
pub fn common_rulings(q: &Natural, other: &Natural) -> Vec<(EPoint, EPoint)> {
    let fo = other.equation();
    let form = match QuadricForm::from_poly(&fo) {
        Some(f) => f,
        None => return vec![],
    };
    let mut out = Vec::new();
    match q {
        Natural::Cone(k) => {
            if !form.eval(&k.vertex).is_zero() {
                return out;
            }
            let g = form.half_gradient(&k.vertex);
            if g.iter().all(|c| c.is_zero()) {
                return out; // common vertex: a planar case
            }
            let u1 = orthogonal(&g);
            let u2 = cross(&g, &u1);
            // directions d = y u1 + x u2 on the cone and with Aᵀ-form zero
            let a2 = norm2(&k.axis);
            let cone_form = |d: &V3| -> Q {
                let da = dot(d, &k.axis);
                &a2 * norm2(d) - (Q::one() + &k.t2) * &da * &da
            };
            let oth = |d: &V3| -> Q { form_quad(&form, d) };
            // binary quadratic forms in (y, x): coefficients from values
            let bin = |f: &dyn Fn(&V3) -> Q| -> [Q; 3] {
                let p = |y: i64, x: i64| {
                    f(&[
                        &u1[0] * qi(y) + &u2[0] * qi(x),
                        &u1[1] * qi(y) + &u2[1] * qi(x),
                        &u1[2] * qi(y) + &u2[2] * qi(x),
                    ])
                };
                let (yy, xx, s) = (p(1, 0), p(0, 1), p(1, 1));
                [yy.clone(), &s - &yy - &xx, xx]
            };
            let c1 = bin(&cone_form);
            let c2 = bin(&oth);
            for d in common_binary_roots(&c1, &c2) {
                let dir: [QSqrt; 3] =
                    std::array::from_fn(|i| d[0].scale(&u1[i]).add(&d[1].scale(&u2[i])));
                out.push((epoint(&lift(&k.vertex)), epoint(&dir)));
            }
        }
        Natural::Cylinder(c) => {
            let a = &c.axis;
            if !form_quad(&form, a).is_zero() {
                return out;
            }
            // linear condition (A a)·P0 = −b·a on the cross-section circle
            let aa: V3 = std::array::from_fn(|r| {
                (0..3)
                    .map(|s| &form.a[r][s] * &a[s])
                    .fold(Q::zero(), |x, y| x + y)
            });
            let rhs = -dot(&form.b, a);
            let u = orthogonal(a);
            let v = cross(a, &u);
            // P0 = P + c u + s v,  c²|u|² + s²|v|² = r2 |a|²/|a|² ... radius: |c u + s v|² = r2
            let (lu, lv, l0) = (dot(&aa, &u), dot(&aa, &v), &rhs - dot(&aa, &c.point));
            if lu.is_zero() && lv.is_zero() {
                return out;
            }
            // param the line lu c + lv s = l0: (c, s) = base + σ (−lv, lu)
            let (bc, bs) = if !lu.is_zero() {
                (&l0 / &lu, Q::zero())
            } else {
                (Q::zero(), &l0 / &lv)
            };
            let (dc, ds) = (-&lv, lu.clone());
            let (nu, nv) = (norm2(&u), norm2(&v));
            // (bc + σ dc)² nu + (bs + σ ds)² nv = r2
            let qa = &dc * &dc * &nu + &ds * &ds * &nv;
            let qb = qi(2) * (&bc * &dc * &nu + &bs * &ds * &nv);
            let qc = &bc * &bc * &nu + &bs * &bs * &nv - &c.r2;
            let disc = &qb * &qb - qi(4) * &qa * &qc;
            if disc.is_negative() {
                return out;
            }
            let sigmas: Vec<QSqrt> = if disc.is_zero() {
                vec![QSqrt::rational(-&qb / (qi(2) * &qa))]
            } else {
                [1, -1]
                    .iter()
                    .map(|&s| QSqrt::new(-&qb / (qi(2) * &qa), qi(s) / (qi(2) * &qa), disc.clone()))
                    .collect()
            };
            for sg in sigmas {
                let cc = sg.scale(&dc).add(&QSqrt::rational(bc.clone()));
                let ss = sg.scale(&ds).add(&QSqrt::rational(bs.clone()));
                let p0: [QSqrt; 3] = std::array::from_fn(|i| {
                    QSqrt::rational(c.point[i].clone())
                        .add(&cc.scale(&u[i]))
                        .add(&ss.scale(&v[i]))
                });
                if eval_qsqrt(&fo, &p0).is_zero() {
                    out.push((epoint(&p0), epoint(&lift(a))));
                }
            }
        }
        Natural::Sphere(_) => {}
    }
    out
}

fn form_quad(f: &QuadricForm, d: &V3) -> Q {
    let mut acc = Q::zero();
    for r in 0..3 {
        for c in 0..3 {
            acc += &f.a[r][c] * &d[r] * &d[c];
        }
    }
    acc
}

/// Common real roots `(y, x)` (up to scale) of two binary quadratic forms
/// `a y² + b yx + c x²`.
fn common_binary_roots(p: &[Q; 3], q: &[Q; 3]) -> Vec<[QSqrt; 2]> {
    let roots = |f: &[Q; 3]| -> Option<Vec<[QSqrt; 2]>> {
        let (a, b, c) = (&f[0], &f[1], &f[2]);
        if a.is_zero() && b.is_zero() && c.is_zero() {
            return None; // every direction
        }
        let mut out = Vec::new();
        if a.is_zero() {
            out.push([QSqrt::rational(qi(1)), QSqrt::rational(Q::zero())]); // x = 0 direction y:1
            if !b.is_zero() {
                out.push([QSqrt::rational(-c.clone()), QSqrt::rational(b.clone())]);
            }
            return Some(out);
        }
        // y/x = (−b ± √(b² − 4ac)) / 2a
        let d = b * b - qi(4) * a * c;
        if d.is_negative() {
            return Some(out);
        }
        if d.is_zero() {
            out.push([QSqrt::rational(-b.clone()), QSqrt::rational(qi(2) * a)]);
        } else {
            for s in [1, -1] {
                out.push([
                    QSqrt::new(-b.clone(), qi(s), d.clone()),
                    QSqrt::rational(qi(2) * a),
                ]);
            }
        }
        Some(out)
    };
    let eval = |f: &[Q; 3], r: &[QSqrt; 2]| -> QSqrt {
        r[0].mul(&r[0])
            .scale(&f[0])
            .add(&r[0].mul(&r[1]).scale(&f[1]))
            .add(&r[1].mul(&r[1]).scale(&f[2]))
    };
    match (roots(p), roots(q)) {
        (None, None) => vec![],
        (None, Some(r)) => r,
        (Some(r), None) => r,
        (Some(r), Some(_)) => r.into_iter().filter(|x| eval(q, x).is_zero()).collect(),
    }
}

/// Does the real curve X have a one-dimensional part?  (ℓ-sweep; X must
/// contain no line and no planar component.)
pub fn has_real_curve(f1: &QMPoly, f2: &QMPoly) -> Result<bool, Error> {
    let g1 = crate::geom::gradient(f1);
    let g2 = crate::geom::gradient(f2);
    for l in GENERIC_FORMS {
        crate::budget::check_now();
        let lin = crate::system::linear_form(&l.map(qi));
        let gl: [QMPoly; 3] = std::array::from_fn(|k| MPoly::constant(qi(l[k])));
        let det = dot(&cross(&g1, &g2), &gl);
        let Some(rur) = solve_zero_dim(&[f1.clone(), f2.clone(), det], std::slice::from_ref(&lin))?
        else {
            continue;
        };
        let one = QPoly::constant(Q::one());
        let mut vals: Vec<RealAlg> = values_with(
            &rur.f,
            &rur.real_roots,
            &rur.extra[0],
            &one,
            &rur.extra_values[0],
        )
        .into_iter()
        .map(|v| v.expect("denominator 1"))
        .collect();
        vals.sort_by(|a, b| a.cmp_exact(b));
        vals.dedup_by(|a, b| a.cmp_exact(b) == Ordering::Equal);
        separate(&mut vals);
        let mut levels = Vec::new();
        let k = vals.len();
        if k == 0 {
            levels.push(Q::zero());
        }
        for j in 0..=k {
            if k == 0 {
                break;
            }
            let q = if j == 0 {
                vals[0].interval().0 - Q::one()
            } else if j == k {
                vals[k - 1].interval().1 + Q::one()
            } else {
                let (l, h) = (vals[j - 1].interval().1, vals[j].interval().0);
                simplest_rational_in(&l, &h)
            };
            levels.push(q);
        }
        let mut decided = true;
        for q in &levels {
            crate::budget::check_now();
            let plane = &lin - &MPoly::constant(q.clone());
            match solve_zero_dim(&[f1.clone(), f2.clone(), plane], &[])? {
                Some(r) => {
                    if !r.real_roots.is_empty() {
                        return Ok(true);
                    }
                }
                None => {
                    decided = false;
                    break;
                }
            }
        }
        if decided {
            return Ok(false);
        }
    }
    Err(Error::internal("the sweep found no generic linear form"))
}

/// Exact coordinates of a real zero, in Q(√d) when possible.
pub fn zero_point(z: &RealZero) -> EPoint {
    std::array::from_fn(|k| exact_of(&z.coords[k]))
}

/// Classifies a non-planar intersection: the components (curve with its
/// singular points, common lines, isolated points).
pub fn classify_nonplanar(
    a: &Natural,
    b: &Natural,
) -> Result<(Vec<Component>, Vec<String>), Error> {
    let f1 = a.equation();
    let f2 = b.equation();
    let mut notes = Vec::new();
    let mut lines: Vec<(EPoint, EPoint)> = common_rulings(a, b);
    for l in common_rulings(b, a) {
        if !lines.iter().any(|m| same_line(m, &l)) {
            lines.push(l);
        }
    }
    let sing = singular_points(&f1, &f2)?.ok_or_else(|| {
        Error::internal("the intersection is singular along a curve in a non-planar case")
    })?;
    let zeros = real_zeros(&sing);
    let vertices: Vec<V3> = [a, b]
        .iter()
        .filter_map(|q| match q {
            Natural::Cone(c) => Some(c.vertex.clone()),
            _ => None,
        })
        .collect();
    let is_vertex = |z: &RealZero| -> bool {
        vertices
            .iter()
            .any(|v| (0..3).all(|k| z.coords[k].cmp_rational(&v[k]) == Ordering::Equal))
    };
    let mut comps = Vec::new();
    if !lines.is_empty() {
        for (p, d) in &lines {
            comps.push(Component::Line {
                point: p.clone(),
                direction: d.clone(),
                double: false,
            });
        }
        let singular = zeros
            .iter()
            .map(|z| SingularPoint {
                point: zero_point(z),
                kind: SingularKind::Crossing,
            })
            .collect();
        comps.push(Component::Curve {
            degree: 4 - lines.len() as u32,
            singular,
            branches: vec![],
        });
        notes.push(super::construct::TWISTED_CUBIC_NOTE.into());
        return Ok((comps, notes));
    }
    if has_real_curve(&f1, &f2)? {
        let mut singular = Vec::new();
        for z in &zeros {
            let iso = match isolated_by_tangent_cone(&f1, &f2, &sing, z.index) {
                Some(x) => x,
                None => {
                    notes.push(format!(
                        "the tangent cone at the singular point {} is degenerate; it is reported as not isolated",
                        super::numbers::epoint_text(&zero_point(z))
                    ));
                    false
                }
            };
            singular.push(SingularPoint {
                point: zero_point(z),
                kind: if iso {
                    SingularKind::Acnode
                } else {
                    SingularKind::Crossing
                },
            });
        }
        comps.push(Component::Curve {
            degree: 4,
            singular,
            branches: vec![],
        });
    } else {
        for z in &zeros {
            comps.push(Component::Point {
                point: zero_point(z),
                kind: if is_vertex(z) {
                    PointKind::Vertex
                } else {
                    PointKind::Tangency
                },
            });
        }
    }
    Ok((comps, notes))
}

fn same_line(a: &(EPoint, EPoint), b: &(EPoint, EPoint)) -> bool {
    // both lines exact in Q(√d): same if b's point is on a and directions parallel
    let q = |e: &Exact| match e {
        Exact::Quad(x) => Some(x.clone()),
        Exact::Alg(_) => None,
    };
    let get = |p: &EPoint| -> Option<[QSqrt; 3]> { Some([q(&p[0])?, q(&p[1])?, q(&p[2])?]) };
    let (Some(pa), Some(da), Some(pb), Some(db)) = (get(&a.0), get(&a.1), get(&b.0), get(&b.1))
    else {
        return false;
    };
    let r: [QSqrt; 3] = std::array::from_fn(|i| pb[i].sub(&pa[i]));
    let cr = |u: &[QSqrt; 3], v: &[QSqrt; 3]| -> bool {
        u[1].mul(&v[2]).sub(&u[2].mul(&v[1])).is_zero()
            && u[2].mul(&v[0]).sub(&u[0].mul(&v[2])).is_zero()
            && u[0].mul(&v[1]).sub(&u[1].mul(&v[0])).is_zero()
    };
    cr(&r, &da) && cr(&da, &db)
}
