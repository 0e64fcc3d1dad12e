//! Construction of a planar intersection (coplanar axes, the projection
//! conic factors: paper §4–§6, Lemma 8.1) over Z, from the integer conics
//! of the fast route ([`super::predicates`]): the projection conic `F` and the
//! squared heights `H` of the first quadric, both in the homogeneous frame
//! coordinates `(s, t, w)` of the axial plane, `U = P1 + (s·a1 + t·e2)/w`
//! (`P1` the first quadric's point, `a1` its axis, `e2` the second axis or,
//! for parallel axes, `q1q2(P2 − P1)`), with `H = κ(q1q2·w)²·h1²(U)`,
//! `κ = |a1|²·pd1`.
//!
//! Each real line `L` of `F` gives the plane through `L` perpendicular to
//! the axial plane (Lemma 4.4), where the intersection is `z² = h1²(U)`,
//! `U ∈ L`.  With `L: p + σ·pw·w` (`p` homogeneous with `pw ∈ Z`, `w` a
//! direction, entries in `Z[√d]` when `F`'s lines need a square root),
//! `a′ = wᵀHw`, `b′ = pᵀHw`, `c′ = pᵀHp` and `K = κ(q1q2)²`:
//! `h1²(B + σD) = Aσ² + Bσ + C` with `A = a′/K`, `B = 2b′/(K·pw)`,
//! `C = c′/(K·pw²)`, where `B` is the 3D base point and `D = ws·a1 + wt·e2`.
//! The conic's type and data follow from the signs of `a′`, `b′`, `c′` and
//! `a′c′ − b′²` (all exact in `Z[√d]`); only the output values are divided,
//! once each (STYLE: denominators cleared once).  The same formulas as the
//! reference construction ([`super::planar`]), in another frame: the tests
//! compare the two.

use super::numbers::{EPoint, Exact, epoint};
use super::planar::{drop_points_on_lines, offset_point, push_unique};
use super::predicates::{PlanarConics, Sq, det2, projection_conics};
use super::prepared::{QIn, point_difference};
use super::result::{Component, ConicKind, Plane, PointKind};
use super::zsqrt::{Zf, radicand};
use crate::geom::vec3::V3;
use crate::number::filter::{all_zero, cross, dot};
use crate::number::{Q, QSqrt};
use num_bigint::BigInt as Z;
use num_traits::{One, Signed, Zero};

type S = Sq<Z>;

fn sq(u: Z) -> S {
    Sq::rat(u)
}

#[cfg(test)]
fn is_zero(a: &S) -> bool {
    a.u.is_zero() && a.v.is_zero()
}

/// `xᵀ M y` for a symmetric integer matrix and vectors over `Z[√d]`.
fn form3(m: &[[Z; 3]; 3], x: &[S; 3], y: &[S; 3], d: &Z) -> S {
    let mut acc = sq(Z::zero());
    for i in 0..3 {
        for j in 0..3 {
            if m[i][j].is_zero() {
                continue;
            }
            acc = acc.add(&x[i].mul(&y[j], d).scale(&m[i][j]));
        }
    }
    acc
}

/// A real line of the projection conic in frame coordinates: the
/// homogeneous point `p` (`p[2]` rational and non-zero) and the direction
/// `(w0, w1, 0)`.
#[derive(Clone, Debug)]
struct ZLine {
    p: [S; 3],
    w: [S; 2],
    double: bool,
}

/// The real factors of a degenerate conic `F` (rank ≤ 2) over `Z[√d]`.
enum Factors {
    /// Real lines, with the radicand `d` of their coefficients.
    Lines(Vec<ZLine>, Z),
    /// Two complex-conjugate lines meeting at the real point `x`
    /// (homogeneous, `x[2] ≠ 0`).
    Point([Z; 3]),
    /// No real affine point (conjugate parallel lines, the line at
    /// infinity, the zero conic).
    Nothing,
}

/// The factorisation of [`super::planar::factor_conic`], over Z.
fn factor(f: &[[Z; 3]; 3]) -> Factors {
    let minors_zero = (0..3).all(|i| {
        (0..3).all(|j| {
            (i + 1..3)
                .all(|k| (j + 1..3).all(|l| det2(&f[i][j], &f[i][l], &f[k][j], &f[k][l]).is_zero()))
        })
    });
    let one = Z::one();
    if minors_zero {
        // rank ≤ 1: a double line (or nothing)
        let Some(row) = (0..3).find(|&i| f[i].iter().any(|x| !x.is_zero())) else {
            return Factors::Nothing;
        };
        let v = &f[row];
        if v[0].is_zero() && v[1].is_zero() {
            return Factors::Nothing;
        }
        let p = if !v[0].is_zero() {
            [sq(-&v[2]), sq(Z::zero()), sq(v[0].clone())]
        } else {
            [sq(Z::zero()), sq(-&v[2]), sq(v[1].clone())]
        };
        return Factors::Lines(
            vec![ZLine {
                p,
                w: [sq(-&v[1]), sq(v[0].clone())],
                double: true,
            }],
            one,
        );
    }
    // rank 2: the kernel from two independent rows
    let mut k = None;
    'k: for i in 0..3 {
        for j in i + 1..3 {
            let c = cross(&f[i], &f[j]);
            if !all_zero(&c).expect("exact") {
                k = Some(c);
                break 'k;
            }
        }
    }
    let mut k = k.expect("rank 2 has two independent rows");
    crate::number::divide_content_z(&mut k); // as in the decision
    let (f00, f01, f11) = (&f[0][0], &f[0][1], &f[1][1]);
    if !k[2].is_zero() {
        let dd = f01 * f01 - f00 * f11;
        if dd.is_negative() {
            return Factors::Point([k[0].clone(), k[1].clone(), k[2].clone()]);
        }
        let p = [sq(k[0].clone()), sq(k[1].clone()), sq(k[2].clone())];
        let dirs: Vec<[S; 2]> = if !f00.is_zero() {
            [1, -1]
                .iter()
                .map(|&s| {
                    [
                        Sq {
                            u: -f01,
                            v: Z::from(s),
                        },
                        sq(f00.clone()),
                    ]
                })
                .collect()
        } else if !f11.is_zero() {
            [1, -1]
                .iter()
                .map(|&s| {
                    [
                        sq(f11.clone()),
                        Sq {
                            u: -f01,
                            v: Z::from(s),
                        },
                    ]
                })
                .collect()
        } else {
            vec![[sq(one.clone()), sq(Z::zero())], [sq(Z::zero()), sq(one)]]
        };
        return folded(
            dirs.into_iter()
                .map(|w| ZLine {
                    p: p.clone(),
                    w,
                    double: false,
                })
                .collect(),
            dd,
        );
    }
    // parallel lines with direction (k0, k1): the points σ·pv, σ a root of
    // a σ² + 2b σ + c
    let pv = [-&k[1], k[0].clone()];
    let a = f00 * &pv[0] * &pv[0] + Z::from(2) * f01 * &pv[0] * &pv[1] + f11 * &pv[1] * &pv[1];
    let b = &pv[0] * &f[0][2] + &pv[1] * &f[1][2];
    let mut abc = [a, b, f[2][2].clone()];
    crate::number::divide_content_z(&mut abc);
    let [a, b, c] = abc;
    let w = [sq(k[0].clone()), sq(k[1].clone())];
    let line = |num: S, den: Z, double: bool| ZLine {
        p: [num.scale(&pv[0]), num.scale(&pv[1]), sq(den)],
        w: w.clone(),
        double,
    };
    if a.is_zero() {
        if b.is_zero() {
            return Factors::Nothing;
        }
        return Factors::Lines(vec![line(sq(-c), Z::from(2) * b, false)], one);
    }
    let disc = &b * &b - &a * &c;
    if disc.is_negative() {
        return Factors::Nothing;
    }
    if disc.is_zero() {
        return Factors::Lines(vec![line(sq(-b), a, true)], one);
    }
    let lines = [1, -1]
        .iter()
        .map(|&s| {
            line(
                Sq {
                    u: -&b,
                    v: Z::from(s),
                },
                a.clone(),
                false,
            )
        })
        .collect();
    folded(lines, disc)
}

/// Real lines over `Z[√d]`, with `√d` folded into the integers when `d` is
/// a square (then the radicand is 1).
fn folded(lines: Vec<ZLine>, d: Z) -> Factors {
    let (d, root) = radicand(d);
    let Some(r) = root else {
        return Factors::Lines(lines, d);
    };
    let fold = |x: &S| sq(&x.u + &x.v * &r);
    let lines = lines
        .into_iter()
        .map(|l| ZLine {
            p: [fold(&l.p[0]), fold(&l.p[1]), fold(&l.p[2])],
            w: [fold(&l.w[0]), fold(&l.w[1])],
            double: l.double,
        })
        .collect();
    Factors::Lines(lines, d)
}

/// The frame of the axial plane in exact 3D terms.
struct Frame {
    /// `P1 = c1/q1`.
    c1: [Z; 3],
    q1: Z,
    a1: [Z; 3],
    e2: [Z; 3],
    /// `n = a1 × e2`.
    n: [Z; 3],
    /// `K = κ(q1q2)²`.
    kk: Z,
}

fn zf(x: &S) -> Zf {
    Zf::uv(x.u.clone(), x.v.clone())
}

impl Frame {
    /// The 3D point of homogeneous frame coordinates `p` (entries in
    /// `Z[√d]`, `p[2] = pw` rational): `(c1·pw + q1(p0·a1 + p1·e2))/(q1·pw)`.
    fn point(&self, p: &[S; 3]) -> [Zf; 3] {
        let pw = &p[2].u;
        let den = &self.q1 * pw;
        std::array::from_fn(|i| {
            let num = sq(&self.c1[i] * pw).add(
                &p[0]
                    .scale(&self.a1[i])
                    .add(&p[1].scale(&self.e2[i]))
                    .scale(&self.q1),
            );
            zf(&num).div_z(&den)
        })
    }

    /// The 3D direction `w0·a1 + w1·e2`.
    fn direction(&self, w: &[S; 2]) -> [Zf; 3] {
        std::array::from_fn(|i| zf(&w[0].scale(&self.a1[i]).add(&w[1].scale(&self.e2[i]))))
    }

    fn n_q(&self) -> V3 {
        std::array::from_fn(|i| Q::from_integer(self.n[i].clone()))
    }
}

fn cross_z(a: &[Zf; 3], b: &[Z; 3]) -> [Zf; 3] {
    [
        a[1].scale(&b[2]).sub(&a[2].scale(&b[1])),
        a[2].scale(&b[0]).sub(&a[0].scale(&b[2])),
        a[0].scale(&b[1]).sub(&a[1].scale(&b[0])),
    ]
}

fn out3(v: &[Zf; 3], d: &Z) -> [QSqrt; 3] {
    std::array::from_fn(|i| v[i].to_qsqrt(d))
}

fn rat_point(v: &V3) -> EPoint {
    std::array::from_fn(|i| Exact::rational(v[i].clone()))
}

/// The components in the plane through the line `l` perpendicular to the
/// axial plane (the module docs' case analysis).
fn section(fr: &Frame, h: &[[Z; 3]; 3], l: &ZLine, d: &Z) -> (Vec<Component>, Option<Plane>) {
    let p = &l.p;
    let w3 = [l.w[0].clone(), l.w[1].clone(), sq(Z::zero())];
    let a1 = zf(&form3(h, &w3, &w3, d));
    let b1 = zf(&form3(h, p, &w3, d));
    let c1 = zf(&form3(h, p, p, d));
    let pw = p[2].u.clone();
    let base = fr.point(p);
    let dir = fr.direction(&l.w);
    // each value below only when the case needs it: on long inputs every
    // product in Z[√d] counts (an empty section needs its plane alone)
    let plane = || {
        let normal = cross_z(&dir, &fr.n);
        let offset = (0..3).fold(Zf::zero(), |acc, i| acc.add(&normal[i].mul(&base[i], d)));
        Plane {
            normal: epoint(&out3(&normal, d)),
            offset: Exact::Quad(offset.to_qsqrt(d)),
        }
    };
    // the certificate lists the plane only when no conic carries it (a
    // conic's plane is printed with it): computed only then
    let bare =
        |out: &[Component]| (!out.iter().any(|c| matches!(c, Component::Conic { .. }))).then(plane);
    let n = || fr.n_q();
    let n2 = || -> Z { dot(&fr.n, &fr.n) };
    let lam = || (0..3).fold(Zf::zero(), |acc, i| acc.add(&dir[i].mul(&dir[i], d)));
    let kk = &fr.kk;
    let at =
        |sigma: &Zf| -> [Zf; 3] { std::array::from_fn(|i| base[i].add(&sigma.mul(&dir[i], d))) };
    let mut out = Vec::new();
    let (sa, sb, sc) = (a1.sign(d), b1.sign(d), c1.sign(d));
    if sa == 0 && sb == 0 && sc == 0 {
        // L lies on the surface: a line of contact
        out.push(Component::Line {
            point: epoint(&out3(&base, d)),
            direction: epoint(&out3(&dir, d)),
            double: true,
        });
        let p = bare(&out);
        return (out, p);
    }
    if sa != 0 {
        // σ0 = −b′/(a′·pw), k = (a′c′ − b′²)/(K·pw²·a′)
        let disc = a1.mul(&c1, d).sub(&b1.mul(&b1, d));
        let sk = disc.sign(d) * sa;
        if sa < 0 && sk < 0 {
            let p = bare(&out);
            return (out, p);
        }
        let inv_a = a1.inv(d);
        let sigma0 = b1.neg().mul(&inv_a, d).div_z(&pw);
        let kq = || disc.mul(&inv_a, d).div_z(&(kk * &pw * &pw));
        let center = || epoint(&out3(&at(&sigma0), d));
        if sa < 0 {
            match sk {
                1 => {
                    let (kq, lam) = (kq(), lam());
                    // along L: k·|D|²·K/(−a′); along the normal: k
                    let k_out = kq.to_qsqrt(d);
                    let along_out = k_out.mul(&lam.mul(&inv_a, d).scale(&-kk.clone()).to_qsqrt(d));
                    let circle = a1.add(&lam.scale(kk)).is_zero();
                    out.push(Component::Conic {
                        plane: plane(),
                        kind: if circle {
                            ConicKind::Circle
                        } else {
                            ConicKind::Ellipse
                        },
                        center: Some(center()),
                        vertex: None,
                        axes2: vec![Exact::Quad(along_out), Exact::Quad(k_out)],
                        axis_dirs: vec![epoint(&out3(&dir, d)), rat_point(&n())],
                        focal2: None,
                        double: l.double,
                    });
                }
                0 => out.push(Component::Point {
                    point: center(),
                    kind: PointKind::Tangency,
                }),
                _ => {}
            }
        } else if sk != 0 {
            // along = −k·|D|²·K/a′
            let (kq, lam) = (kq(), lam());
            let k_out = kq.to_qsqrt(d);
            let along_out = k_out.mul(&lam.mul(&inv_a, d).scale(&-kk.clone()).to_qsqrt(d));
            let (axes2, dirs) = if sk > 0 {
                (
                    vec![Exact::Quad(k_out), Exact::Quad(along_out.neg())],
                    vec![rat_point(&n()), epoint(&out3(&dir, d))],
                )
            } else {
                (
                    vec![Exact::Quad(along_out), Exact::Quad(k_out.neg())],
                    vec![epoint(&out3(&dir, d)), rat_point(&n())],
                )
            };
            out.push(Component::Conic {
                plane: plane(),
                kind: ConicKind::Hyperbola,
                center: Some(center()),
                vertex: None,
                axes2,
                axis_dirs: dirs,
                focal2: None,
                double: l.double,
            });
        } else {
            // two lines through the centre: directions D ± μn, μ² = a′/(K|n|²)
            let mu2 = a1.div_z(&(kk * &n2())).to_qsqrt(d);
            let (dir_q, n) = (out3(&dir, d), n());
            for s in [1, -1] {
                out.push(Component::Line {
                    point: center(),
                    direction: offset_point(&dir_q, &n, &mu2, s),
                    double: l.double,
                });
            }
        }
    } else if sb != 0 {
        // parabola z² = Bσ + C: vertex σ = −c′/(2b′·pw), focal² b′²/(4K²pw²|D|²)
        let sv = c1.neg().div(&b1, d).div_z(&(Z::from(2) * &pw));
        let f2 = b1
            .mul(&b1, d)
            .div(&lam(), d)
            .div_z(&(Z::from(4) * kk * kk * &pw * &pw));
        let up = sb * if pw.is_negative() { -1 } else { 1 };
        let axis: [Zf; 3] = if up > 0 {
            dir.clone()
        } else {
            std::array::from_fn(|i| dir[i].neg())
        };
        out.push(Component::Conic {
            plane: plane(),
            kind: ConicKind::Parabola,
            center: None,
            vertex: Some(epoint(&out3(&at(&sv), d))),
            axes2: vec![],
            axis_dirs: vec![epoint(&out3(&axis, d))],
            focal2: Some(Exact::Quad(f2.to_qsqrt(d))),
            double: l.double,
        });
    } else {
        // z² = C = c′/(K·pw²): two parallel lines, a double line, or nothing
        match sc {
            1 => {
                let mu2 = c1.div_z(&(kk * &pw * &pw * &n2())).to_qsqrt(d);
                let (base_q, n) = (out3(&base, d), n());
                let dir_q = out3(&dir, d);
                for s in [1, -1] {
                    out.push(Component::Line {
                        point: offset_point(&base_q, &n, &mu2, s),
                        direction: epoint(&dir_q),
                        double: l.double,
                    });
                }
            }
            0 => out.push(Component::Line {
                point: epoint(&out3(&base, d)),
                direction: epoint(&out3(&dir, d)),
                double: true,
            }),
            _ => {}
        }
    }
    let p = bare(&out);
    (out, p)
}

/// The isolated points over the real meeting point `x` of two conjugate
/// lines of `F`: `X ± √(h1²(X)/|n|²)·n`.
fn conjugate_points(fr: &Frame, h: &[[Z; 3]; 3], x: &[Z; 3]) -> Vec<Component> {
    let one = Z::one();
    let xs = [sq(x[0].clone()), sq(x[1].clone()), sq(x[2].clone())];
    let hx = form3(h, &xs, &xs, &one).u;
    let base = out3(&fr.point(&xs), &one);
    match hx.sign() {
        num_bigint::Sign::Minus => vec![],
        num_bigint::Sign::NoSign => vec![Component::Point {
            point: epoint(&base),
            kind: PointKind::Tangency,
        }],
        num_bigint::Sign::Plus => {
            let n2: Z = dot(&fr.n, &fr.n);
            let mu2 = QSqrt::rational(Q::new(hx, &fr.kk * &x[2] * &x[2] * n2));
            let n = fr.n_q();
            [1, -1]
                .iter()
                .map(|&s| Component::Point {
                    point: offset_point(&base, &n, &mu2, s),
                    kind: PointKind::Tangency,
                })
                .collect()
        }
    }
}

/// `F` (divided by its content: it matters up to a positive factor, and
/// near-degenerate inputs give contents of thousands of bits) and `H` of
/// the module docs, as [`super::predicates`]'s decision computes them.
fn conics(x: &QIn<Z>, y: &QIn<Z>, parallel: bool) -> PlanarConics {
    let (mut f, h1) = projection_conics(x, y, parallel);
    crate::number::divide_content_z(f.as_flattened_mut());
    PlanarConics { f, h1 }
}

/// All real components of a planar intersection of `x` and `y` (coplanar
/// distinct axes, parallel or meeting; the projection conic degenerate).
/// Also returns the planes through the real lines of the projection conic
/// perpendicular to the axial plane that carry no conic (a member of the
/// pencil is the product of these and the conics' planes: the checker's
/// completeness certificate, contract §7).
pub(crate) fn planar_components(
    x: &QIn<Z>,
    y: &QIn<Z>,
    parallel: bool,
    decided: Option<&PlanarConics>,
) -> (Vec<Component>, Vec<Plane>) {
    let dv = point_difference(x, y);
    let qq = &x.q * &y.q;
    let e2 = if parallel { dv } else { y.a.clone() };
    let k1 = dot(&x.a, &x.a) * &x.pd;
    // F and H as the decision computed them, else (a decision in balls)
    // the same formulas here
    let computed;
    let PlanarConics { f, h1 } = match decided {
        Some(c) => c,
        None => {
            computed = conics(x, y, parallel);
            &computed
        }
    };
    let fr = Frame {
        c1: x.c.clone(),
        q1: x.q.clone(),
        a1: x.a.clone(),
        n: cross(&x.a, &e2),
        e2,
        kk: &k1 * &qq * &qq,
    };
    let mut out = Vec::new();
    let mut planes = Vec::new();
    match factor(f) {
        Factors::Lines(lines, d) => {
            for l in &lines {
                let (comps, plane) = section(&fr, h1, l, &d);
                planes.extend(plane);
                for c in comps {
                    push_unique(&mut out, c);
                }
            }
        }
        Factors::Point(xp) => out = conjugate_points(&fr, h1, &xp),
        Factors::Nothing => {}
    }
    (drop_points_on_lines(out), planes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_factors_of_a_line_pair_expand_back() {
        // F = (s − t)(s + 2t − w) as a symmetric matrix (times 2)
        let f: [[Z; 3]; 3] = [
            [Z::from(2), Z::from(1), Z::from(-1)],
            [Z::from(1), Z::from(-4), Z::from(1)],
            [Z::from(-1), Z::from(1), Z::from(0)],
        ];
        let Factors::Lines(ls, d) = factor(&f) else {
            panic!("two real lines expected");
        };
        assert_eq!(ls.len(), 2);
        for l in &ls {
            // the point and the direction lie on F
            let w = [l.w[0].clone(), l.w[1].clone(), sq(Z::zero())];
            assert!(is_zero(&form3(&f, &l.p, &l.p, &d)));
            assert!(is_zero(&form3(&f, &l.p, &w, &d)));
            assert!(is_zero(&form3(&f, &w, &w, &d)));
        }
    }

    /// The construction from the decision's conics (big-integer and
    /// `i128` tiers) and from its own (a decision in balls) agree, and
    /// the conics are the decision's, `F` primitive.
    #[test]
    fn the_decisions_conics_and_the_constructions_agree() {
        use super::super::prepared::Prepared;
        use crate::Natural;
        let pairs = [
            // parallel cylinders: two lines; touching: a double line
            (
                "cylinder point=0,0,0 axis=0,0,1 radius2=1",
                "cylinder point=1,0,0 axis=0,0,1 radius2=1",
            ),
            (
                "cylinder point=0,0,0 axis=0,0,1 radius2=1",
                "cylinder point=2,0,0 axis=0,0,1 radius2=1",
            ),
            // intersecting axes of equal radii: two ellipses
            (
                "cylinder point=0,0,0 axis=0,0,1 radius2=1",
                "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            ),
            // long decimals: F carries a content of hundreds of bits
            (
                "cylinder point=1.2,0,-0.4000000000000003 axis=-0.000000000000000068996496966039912,-1,-0.00000000000000044408920985006262 radius2=0.0400000000000000040000000000000001",
                "cylinder point=1.1999999999999997,0.00000000000000011102230246251565,-1.2000808300000003 axis=-0.000000000000000068996496966039912,-1,-0.00000000000000044408920985006262 radius2=0.0400000000000000040000000000000001",
            ),
        ];
        for (sa, sb) in pairs {
            let (na, nb): (Natural, Natural) = (sa.parse().unwrap(), sb.parse().unwrap());
            let (a, b) = (Prepared::new(&na), Prepared::new(&nb));
            let (x, y) = (a.prep.tier::<Z>(), b.prep.tier::<Z>());
            // the big-integer decision hands over its conics
            let (out, _) = super::super::predicates::program(&x, &y).unwrap();
            let super::super::predicates::Outcome::Planar(_, _, case, got) = out else {
                panic!("{sa} / {sb}: a planar decision expected, got {out:?}");
            };
            let super::super::predicates::Case::Planar { parallel } = case else {
                panic!("{sa} / {sb}: {case:?}");
            };
            let c = conics(&x, &y, parallel);
            assert_eq!(*got, c, "{sa} / {sb}");
            let g =
                c.f.iter()
                    .flatten()
                    .fold(Z::zero(), |g, v| crate::number::gcd_z(&g, v));
            assert!(g.is_one(), "{sa} / {sb}: F not primitive");
            let own = planar_components(&x, &y, parallel, None);
            let given = planar_components(&x, &y, parallel, Some(&c));
            assert_eq!(format!("{own:?}"), format!("{given:?}"), "{sa} / {sb}");
        }
    }

    #[test]
    fn conjugate_lines_meet_in_a_real_point() {
        // s² + t² (complex lines through the origin)
        let f: [[Z; 3]; 3] = [
            [Z::from(1), Z::from(0), Z::from(0)],
            [Z::from(0), Z::from(1), Z::from(0)],
            [Z::from(0), Z::from(0), Z::from(0)],
        ];
        assert!(matches!(factor(&f), Factors::Point(p) if p[0].is_zero() && p[1].is_zero()));
    }
}
