//! Constructions of the non-planar cases decided from the pencil
//! `det(A − λB)` ([`super::predicates`]): the singular point of a nodal quartic
//! (the vertex of the rank-3 member at the multiple root) with its type, an
//! isolated tangency point (the same vertex when the member's generators
//! are imaginary), the isolated points on the real line of a
//! complex-conjugate plane pair, and the curve's real components by the
//! rulings of a cylinder or cone ([`super::curve`]).  Exact integers
//! throughout; the multiple root is recomputed exactly by the formula the
//! predicate used (no classification again).

use super::curve::{CurvePoint, Rulings};
use super::numbers::{EPoint, Exact, epoint};
use super::predicates::{
    Case, M4, RootKind, det2, form, matrix, member, minor3, pencil_core, root_ratio, vertex_cone,
};
use super::prepared::{Kind, QIn};
use super::result::{Component, CurveBranch, PointKind, SingularKind, SingularPoint};
use super::zsqrt::{Zf, radicand};
use crate::error::Error;
use crate::number::Q;
use num_bigint::BigInt as Z;
use num_traits::{One, Zero};

/// The pencil's two matrices as the predicates took them: a sphere first
/// when there is one; whether both quadrics are axial.
fn pencil_pair(x: &QIn<Z>, y: &QIn<Z>) -> (M4<Z>, M4<Z>, bool) {
    if y.kind == Kind::Sphere {
        (matrix(y), matrix(x), false)
    } else if x.kind == Kind::Sphere {
        (matrix(x), matrix(y), false)
    } else {
        (matrix(x), matrix(y), true)
    }
}

/// The member at the multiple root and another member of the pencil.
fn multiple_member(x: &QIn<Z>, y: &QIn<Z>, root: RootKind) -> Result<(M4<Z>, M4<Z>), Error> {
    let (a, b, both) = pencil_pair(x, y);
    Ok(match root {
        RootKind::Zero => (a, b),
        RootKind::Infinity => (b, a),
        kind => {
            let (f, range) =
                pencil_core(&a, &b, both).ok_or_else(|| Error::internal("exact signs"))?;
            let (lo, hi) = range.ok_or_else(|| Error::internal("a singular pencil"))?;
            let (n, d) = root_ratio(&f[lo..=hi], kind);
            if d.is_zero() {
                return Err(Error::internal("a multiple root at infinity"));
            }
            (member(&a, &b, &n, &d), b)
        }
    })
}

/// The vertex of a rank-3 member: its cofactor column `k`.
fn vertex(m0: &M4<Z>, k: usize) -> [Z; 4] {
    std::array::from_fn(|i| {
        let c = minor3(m0, i, k);
        if (i + k).is_multiple_of(2) { c } else { -c }
    })
}

/// An affine homogeneous point with integer coordinates, exactly.
fn affine(p: &[Z; 4]) -> EPoint {
    std::array::from_fn(|i| Exact::rational(Q::new(p[i].clone(), p[3].clone())))
}

/// Is `p` (affine) a cone's apex?
fn is_apex(q: &QIn<Z>, p: &[Z; 4]) -> bool {
    q.kind == Kind::Cone && (0..3).all(|i| &q.c[i] * &p[3] == &p[i] * &q.q)
}

/// The vertex `p` of the multiple member as an isolated point.
fn cone_point(x: &QIn<Z>, y: &QIn<Z>, root: RootKind, k: usize) -> Result<Component, Error> {
    let (m0, _) = multiple_member(x, y, root)?;
    let p = vertex(&m0, k);
    if p[3].is_zero() {
        return Err(Error::internal("an isolated point at infinity"));
    }
    Ok(Component::Point {
        point: affine(&p),
        kind: if is_apex(x, &p) || is_apex(y, &p) {
            PointKind::Vertex
        } else {
            PointKind::Tangency
        },
    })
}

/// The affine real points of the real line of a complex-conjugate plane
/// pair (the multiple member) on another member: the roots of the binary
/// form of `n` on two points spanning the line.
fn plane_pair_points(x: &QIn<Z>, y: &QIn<Z>, root: RootKind) -> Result<Vec<Component>, Error> {
    let (m0, n) = multiple_member(x, y, root)?;
    let mut pivot = None;
    'outer: for i in 0..4 {
        for j in i + 1..4 {
            if !det2(&m0[i][i], &m0[i][j], &m0[j][i], &m0[j][j]).is_zero() {
                pivot = Some((i, j));
                break 'outer;
            }
        }
    }
    let (i, j) = pivot.ok_or_else(|| Error::internal("a member of rank ≤ 1"))?;
    let d2 = det2(&m0[i][i], &m0[i][j], &m0[j][i], &m0[j][j]);
    let kernel = |k: usize| -> [Z; 4] {
        let mut x: [Z; 4] = std::array::from_fn(|_| Z::zero());
        x[k] = d2.clone();
        x[i] = -det2(&m0[j][j], &m0[i][j], &m0[j][k], &m0[i][k]);
        x[j] = -det2(&m0[i][i], &m0[i][j], &m0[i][k], &m0[j][k]);
        x
    };
    let ks: Vec<usize> = (0..4).filter(|&k| k != i && k != j).collect();
    let (xv, yv) = (kernel(ks[0]), kernel(ks[1]));
    let b = [form(&n, &xv, &xv), form(&n, &xv, &yv), form(&n, &yv, &yv)];
    // the roots (s : t) of b0 s² + 2 b1 st + b2 t², as points s·x + t·y
    let disc = &b[1] * &b[1] - &b[0] * &b[2];
    let (d, root_d) = radicand(disc.clone());
    let mut pts: Vec<[Zf; 4]> = Vec::new();
    let comb = |s: &Zf, t: &Zf| -> [Zf; 4] {
        std::array::from_fn(|l| s.scale(&xv[l]).add(&t.scale(&yv[l])))
    };
    let sq = |sign: i64| -> Zf {
        match &root_d {
            Some(r) => Zf::int(r * Z::from(sign)),
            None => Zf::uv(Z::zero(), Z::from(sign)),
        }
    };
    if disc.sign() == num_bigint::Sign::Minus {
        return Ok(vec![]);
    }
    if !b[0].is_zero() {
        // s/t = (−b1 ± √disc)/b0
        let signs: &[i64] = if disc.is_zero() { &[1] } else { &[1, -1] };
        for &sg in signs {
            let s = Zf::int(-b[1].clone()).add(&sq(sg));
            pts.push(comb(&s, &Zf::int(b[0].clone())));
        }
    } else {
        // t = 0 (the point x) and s/t = −b2/(2b1)
        pts.push(comb(&Zf::int(Z::one()), &Zf::zero()));
        if !b[1].is_zero() {
            pts.push(comb(&Zf::int(-b[2].clone()), &Zf::int(&b[1] * 2)));
        }
    }
    let mut out = Vec::new();
    for p in pts {
        if p[3].is_zero() {
            continue; // at infinity
        }
        let inv = p[3].inv(&d);
        let pt: [crate::number::QSqrt; 3] =
            std::array::from_fn(|l| p[l].mul(&inv, &d).to_qsqrt(&d));
        out.push(Component::Point {
            point: epoint(&pt),
            kind: PointKind::Tangency,
        });
    }
    Ok(out)
}

/// The singular point of a nodal quartic with its type, when affine.
fn nodal_point(
    x: &QIn<Z>,
    y: &QIn<Z>,
    root: RootKind,
    k: usize,
) -> Result<Option<SingularPoint>, Error> {
    let (m0, n) = multiple_member(x, y, root)?;
    let p = vertex(&m0, k);
    let (disc_m, _, _) = vertex_cone(&m0, &n, &p)
        .ok_or_else(|| Error::internal("exact signs"))?
        .map_err(Error::internal)?;
    if p[3].is_zero() {
        return Ok(None);
    }
    Ok(Some(SingularPoint {
        point: affine(&p),
        kind: match disc_m {
            d if d < 0 => SingularKind::Acnode,
            0 => SingularKind::Cusp,
            _ => SingularKind::Crossing,
        },
    }))
}

/// The quadric whose rulings parameterise the curve: a cylinder first, a
/// cone otherwise; and the other.
pub(crate) fn ruling_choice<'a>(x: &'a QIn<Z>, y: &'a QIn<Z>) -> (&'a QIn<Z>, &'a QIn<Z>) {
    match (x.kind, y.kind) {
        (Kind::Cylinder, _) => (x, y),
        (_, Kind::Cylinder) => (y, x),
        (Kind::Cone, _) => (x, y),
        _ => (y, x),
    }
}

/// The real components of a curve by the rulings of `p`, with their
/// points, and the number of isolated points found.
pub(crate) fn branches_by(p: &QIn<Z>, q: &QIn<Z>) -> Result<(Vec<CurveBranch>, usize), Error> {
    branches_on(&Rulings::new(p, q), p)
}

/// [`branches_by`] on rulings already built (`r` of `p`).
pub(crate) fn branches_on(r: &Rulings, p: &QIn<Z>) -> Result<(Vec<CurveBranch>, usize), Error> {
    let t = r.topology()?;
    let src = r.source(p);
    let branches = t
        .branches
        .iter()
        .map(|b| {
            let start: CurvePoint = Rulings::realize(&src, &b.at)?;
            Ok(CurveBranch {
                bounded: b.bounded,
                start,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok((branches, t.isolated))
}

/// The components of the non-planar cases decided from the pencil.
pub(crate) fn pencil_components(
    x: &QIn<Z>,
    y: &QIn<Z>,
    case: Case,
) -> Result<Vec<Component>, Error> {
    match case {
        Case::ConePoint { root, k } => Ok(vec![cone_point(x, y, root, k)?]),
        Case::PlanePair { root } => plane_pair_points(x, y, root),
        Case::Smooth | Case::Nodal { .. } => {
            let singular = match case {
                Case::Nodal { root, k } => nodal_point(x, y, root, k)?.into_iter().collect(),
                _ => vec![],
            };
            let (p, q) = ruling_choice(x, y);
            let (branches, isolated) = branches_by(p, q)?;
            let acnodes = singular
                .iter()
                .filter(|s: &&SingularPoint| s.is_isolated())
                .count();
            if isolated != acnodes {
                return Err(Error::internal(format!(
                    "the rulings found {isolated} isolated points, the pencil {acnodes}"
                )));
            }
            if branches.is_empty() {
                return Err(Error::internal("a real curve without a branch"));
            }
            Ok(vec![Component::Curve {
                degree: 4,
                singular,
                branches,
            }])
        }
        _ => Err(Error::internal("not a pencil case")),
    }
}
