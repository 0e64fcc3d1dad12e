//! The real topology of a non-planar intersection curve `X = P ∩ Q` of two
//! natural quadrics, one of them (`P`) a cylinder or a cone: the number of
//! real affine connected components, whether each is bounded, and a point
//! on each — by the rulings of `P` (docs/maths.md, "Curve topology by
//! rulings").
//!
//! **Rulings.**  `P`'s rulings are the lines `s·S + r·R(z)` (homogeneous
//! points) through `P`'s vertex `S` — the point at infinity of the axis for
//! a cylinder, the apex for a cone — with `z = (x, y)` on the conic
//! `Γ: g1·x² + g2·y² = g0` (a cylinder: `R(z) = C + x·u + y·v`, the
//! cross-section circle; a cone: `R(z) = a + x·u + y·v` at infinity, the
//! generators' directions; `u ⊥ a`, `v = a × u`).  `Q` restricted to the
//! ruling over `z` is the binary form `σs² + 2β(z)sr + ρ(z)r²` with `σ`
//! constant, `β` affine and `ρ` quadratic in `z`; `Δ = β² − σρ`.
//!
//! * `σ ≠ 0` (`S ∉ Q`): over `z`, two real points when `Δ(z) > 0`, one when
//!   `Δ(z) = 0`, none when `Δ(z) < 0`: `X` is a double cover of the arcs of
//!   `Γ` where `Δ > 0`, the two sheets `ε = ±` (`s/r = (−β + ε√Δ)/σ`)
//!   joining where `Δ` vanishes.  For a cone, the point of sheet
//!   `ε = sign β(z)` is at infinity where `ρ(z) = 0` (`s = 0`): the sheet is
//!   cut there.
//! * `σ = 0` (`S ∈ Q`, then `S` is the singular point of `X`): one point
//!   `[s : r] = [−ρ(z) : 2β(z)]` per ruling besides `S`; at infinity where
//!   `β = 0` (cylinder) or `ρ = 0` (cone); through the apex where `β = 0`
//!   (cone: every such arc end meets at the apex).
//!
//! The special points of `Γ` (zeros of `Δ`, `ρ`, `β` as needed) are exact
//! real algebraic points, given by their `x` (a root of an integer
//! polynomial of degree ≤ 4) and the sign of `y`, sorted around `Γ`; the
//! sign of `Δ` on each arc between them is evaluated exactly at a rational
//! sample `x`.  The pieces (arc, sheet) are joined where the curve passes
//! through an affine point, and the connected components counted by
//! union–find; a component touching a cut is unbounded.

use super::numbers::{EPoint, Exact};
use super::predicates::{M4, matrix};
use super::prepared::{Kind, QIn};
use super::zsqrt::{Zf, radicand};
use crate::error::Error;
use crate::number::filter::dot as dot4;
use crate::number::xball::XBall;
use crate::number::{Q, QSqrt};
use crate::poly::ZPoly;
use crate::roots::{RealAlg, simplest_rational_in};
use num_bigint::BigInt as Z;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// A quadratic function on the plane of `Γ`:
/// `c[0] + c[1]x + c[2]y + c[3]x² + c[4]xy + c[5]y²`.
#[derive(Clone, Debug)]
pub(crate) struct Quad2 {
    pub c: [Z; 6],
}

impl Quad2 {
    fn is_zero(&self) -> bool {
        self.c.iter().all(Zero::is_zero)
    }

    /// The value at `(x, y)` over `Z[√d]`:
    /// `c0 + x(c1 + c3x) + y(c2 + c4x) + c5y²`.
    fn eval(&self, x: &Zf, y: &Zf, d: &Z) -> Zf {
        let c = |i: usize| Zf::int(self.c[i].clone());
        let xpart = x.mul(&c(1).add(&x.scale(&self.c[3])), d);
        let ypart = y.mul(&c(2).add(&x.scale(&self.c[4])).add(&y.scale(&self.c[5])), d);
        c(0).add(&xpart).add(&ypart)
    }
}

/// The conic `Γ: g1·x² + g2·y² = g0` (`g0, g1, g2 > 0`).
#[derive(Clone, Debug)]
pub(crate) struct Gamma {
    pub g0: Z,
    pub g1: Z,
    pub g2: Z,
}

/// `Ã(x)`, `B(x)` with `g2·F ≡ Ã(x) + g2·y·B(x)` on `Γ`, and
/// `W = Ã² − g2(g0 − g1x²)B²`, whose real roots are the `x` of the zeros of
/// `F` on `Γ` (over C; the real points are those with `|x| ≤ xm`).
#[derive(Clone, Debug)]
struct Reduced {
    a: ZPoly,
    b: ZPoly,
    w: ZPoly,
}

impl Gamma {
    fn reduce(&self, f: &Quad2) -> Reduced {
        let c = &f.c;
        let (g0, g1, g2) = (&self.g0, &self.g1, &self.g2);
        let a = ZPoly::new(vec![
            g2 * &c[0] + g0 * &c[5],
            g2 * &c[1],
            g2 * &c[3] - g1 * &c[5],
        ]);
        let b = ZPoly::new(vec![c[2].clone(), c[4].clone()]);
        // g2(g0 − g1x²)
        let e = ZPoly::new(vec![g2 * g0, Z::zero(), -(g2 * g1)]);
        let w = &(&a * &a) - &(&e * &(&b * &b));
        Reduced { a, b, w }
    }

    /// The derivative of `f` along `Γ`, `∇f · (−g2·y, g1·x)` (the tangent
    /// of `g1x² + g2y² = g0`, non-zero on it): a quadratic function again.
    fn tangential(&self, f: &Quad2) -> Quad2 {
        let (c, g1, g2) = (&f.c, &self.g1, &self.g2);
        Quad2 {
            c: [
                Z::zero(),
                g1 * &c[2],
                -(g2 * &c[1]),
                g1 * &c[4],
                (g1 * &c[5] - g2 * &c[3]) * 2,
                -(g2 * &c[4]),
            ],
        }
    }

    /// `g1·x² − g0` (negative inside `Γ`'s range of `x`).
    fn edge(&self) -> ZPoly {
        ZPoly::new(vec![-self.g0.clone(), Z::zero(), self.g1.clone()])
    }

    /// `(g0 − g1x²)/g2 = y²` at a rational `x`.
    fn y2(&self, x: &Q) -> Q {
        // (g0·q² − g1·p²)/(g2·q²) for x = p/q, reduced once (Lehmer's gcd)
        let (p, q) = (x.numer(), x.denom());
        let q2 = q * q;
        crate::number::q_new(&self.g0 * &q2 - &self.g1 * p * p, &self.g2 * q2)
    }

    /// `xm = √(g0/g1)` and `−xm` as real algebraic numbers.
    fn ends(&self) -> [RealAlg; 2] {
        let r = RealAlg::roots_narrow(&self.edge(), 40);
        [r[0].clone(), r[r.len() - 1].clone()]
    }
}

/// A point of `Γ`: its `x` and the sign of its `y` (0 at `x = ±xm`).
#[derive(Clone, Debug)]
pub(crate) struct GPoint {
    pub x: RealAlg,
    pub ys: i32,
}

/// The half of `Γ` a point starts: 0 for the upper half from `(xm, 0)`
/// (where `x` decreases), 1 for the lower half from `(−xm, 0)`.
fn half(p: &GPoint) -> u8 {
    match p.ys {
        1 => 0,
        -1 => 1,
        _ => {
            if p.x.signum() > 0 {
                0
            } else {
                1
            }
        }
    }
}

/// The counter-clockwise order of points of `Γ` from `(xm, 0)`.
fn cyclic_cmp(p: &GPoint, q: &GPoint) -> Ordering {
    let (hp, hq) = (half(p), half(q));
    if hp != hq {
        return hp.cmp(&hq);
    }
    let c = p.x.cmp_exact(&q.x);
    if hp == 0 { c.reverse() } else { c }
}

/// The sign of `F` at a point of `Γ` (exact): `g2F = Ã + g2·y·B` with
/// `y = ys·√((g0 − g1x²)/g2)`; when `Ã` and `yB` have opposite signs the
/// sign is `sign(Ã)·sign(W)`.
fn sign_at_point(r: &Reduced, p: &GPoint) -> i32 {
    let sa = p.x.sign_of(&r.a);
    let sb = if p.ys == 0 {
        0
    } else {
        p.ys * p.x.sign_of(&r.b)
    };
    if sb == 0 || sa == sb {
        return if sa == 0 { sb } else { sa };
    }
    if sa == 0 {
        return sb;
    }
    sa * p.x.sign_of(&r.w)
}

/// The sign of `F` at `(x, ys·√y²)` for a rational `x` inside `Γ`'s range.
fn sign_at_rational(g: &Gamma, r: &Reduced, x: &Q, ys: i32) -> i32 {
    // in integers: x = p/q, a = Ha/Da, b = Hb·g2·ys/Db (Da, Db > 0)
    let (p, q) = (x.numer(), x.denom());
    let (ha, da) = r.a.eval_homogeneous(p, q);
    let (hb, db) = r.b.eval_homogeneous(p, q);
    let sz = crate::number::sign_z;
    let (sa, sb) = (sz(&ha), sz(&hb) * sz(&g.g2) * ys);
    if sb == 0 || sa == sb {
        return if sa == 0 { sb } else { sa };
    }
    if sa == 0 {
        return sb;
    }
    // a + b√E with opposite signs: compare a² with b²E, E = (g0q² − g1p²)/(g2q²),
    // times Da²·Db²·q² > 0
    let q2 = q * q;
    let e = &g.g0 * &q2 - &g.g1 * p * p;
    sa * sz(&(&ha * &ha * &db * &db * &q2 - &hb * &hb * &g.g2 * e * &da * &da))
}

/// The zeros of `F` on `Γ` (distinct points; `Err` when `F` vanishes on
/// all of `Γ`).
fn zeros(g: &Gamma, r: &Reduced) -> Result<Vec<GPoint>, Error> {
    if r.w.is_zero() {
        return Err(Error::internal(
            "a quadratic function vanishing on the whole ruling conic",
        ));
    }
    let edge = g.edge();
    let mut out = Vec::new();
    // narrow, so that the signs at x below are decided by balls
    for x in RealAlg::roots_narrow(&r.w, 40) {
        crate::budget::check();
        match x.sign_of(&edge) {
            1 => continue, // no real point of Γ there
            0 => out.push(GPoint { x, ys: 0 }),
            _ => {
                let sb = x.sign_of(&r.b);
                if sb != 0 {
                    let sa = x.sign_of(&r.a);
                    out.push(GPoint { x, ys: -sa * sb });
                } else {
                    // Ã = B = 0 there: both points of Γ over x
                    out.push(GPoint {
                        x: x.clone(),
                        ys: 1,
                    });
                    out.push(GPoint { x, ys: -1 });
                }
            }
        }
    }
    Ok(out)
}

/// A rational strictly between two real algebraic numbers `lo < hi`.
fn between(lo: &RealAlg, hi: &RealAlg) -> Q {
    let gap = |a: &RealAlg, b: &RealAlg| {
        let (x, y) = (a.interval().1, b.interval().0);
        crate::number::q_cmp(&x, &y)
            .is_lt()
            .then(|| simplest_rational_in(&x, &y))
    };
    if let Some(q) = gap(lo, hi) {
        return q;
    }
    // narrowed by Newton steps (the ends ±xm come wide; close values need
    // many bits: doubled each round), then bisected
    let mut v = [lo.clone(), hi.clone()];
    let mut bits = 40;
    while bits <= 4096 {
        for x in v.iter_mut() {
            x.refine_relative(bits);
        }
        if let Some(q) = gap(&v[0], &v[1]) {
            return q;
        }
        bits *= 2;
    }
    crate::roots::separate(&mut v);
    simplest_rational_in(&v[0].interval().1, &v[1].interval().0)
}

/// A rational `x` and a sign of `y` strictly inside the arc of `Γ` from
/// `p` counter-clockwise to `q` (`q = None`: the whole of `Γ` but `p`;
/// both `None`: anywhere).
fn arc_sample(ends: &[RealAlg; 2], p: Option<&GPoint>, q: Option<&GPoint>) -> (Q, i32) {
    let [xm_neg, xm] = ends;
    let Some(p) = p else {
        return (Q::zero(), 1);
    };
    // q when the arc reaches it without leaving p's half: in the upper half
    // x decreases counter-clockwise, in the lower half it increases
    let ahead = |want: i32, dir: Ordering| q.filter(|q| q.ys == want && q.x.cmp_exact(&p.x) == dir);
    let same_half_next = |want: i32| q.filter(|q| q.ys == want);
    match (p.ys, half(p)) {
        (1, _) => match ahead(1, Ordering::Less) {
            Some(q) => (between(&q.x, &p.x), 1),
            None => (between(xm_neg, &p.x), 1),
        },
        (-1, _) => match ahead(-1, Ordering::Greater) {
            Some(q) => (between(&p.x, &q.x), -1),
            None => (between(&p.x, xm), -1),
        },
        (_, 0) => match same_half_next(1) {
            // from (xm, 0) into the upper half
            Some(q) => (between(&q.x, xm), 1),
            None => (Q::zero(), 1),
        },
        _ => match same_half_next(-1) {
            // from (−xm, 0) into the lower half
            Some(q) => (between(xm_neg, &q.x), -1),
            None => (Q::zero(), -1),
        },
    }
}

/// Union–find.
struct Dsu(Vec<usize>);

impl Dsu {
    fn find(&mut self, i: usize) -> usize {
        let mut r = i;
        while self.0[r] != r {
            r = self.0[r];
        }
        let mut j = i;
        while self.0[j] != r {
            let n = self.0[j];
            self.0[j] = r;
            j = n;
        }
        r
    }
    fn join(&mut self, i: usize, j: usize) {
        let (a, b) = (self.find(i), self.find(j));
        if a != b {
            self.0[a] = b;
        }
    }
}

/// Where the curve goes at a special point of `Γ` when `σ = 0`.
enum End {
    /// Through an affine point off `P`'s vertex: the arcs on both sides join.
    Affine,
    /// To infinity: both arcs are cut there.
    Infinity,
    /// Through the cone's apex, where all such arc ends meet.
    Apex,
}

/// The parameterisation of `X` by the rulings of `P` (module docs).
#[derive(Clone, Debug)]
pub(crate) struct Rulings {
    /// `P` is a cone (else a cylinder).
    pub cone: bool,
    pub gamma: Gamma,
    pub sigma: Z,
    pub beta: Quad2,
    pub rho: Quad2,
    pub delta: Quad2,
}

/// A point of `X` over a rational point of `Γ`: `z = (x, ys·√y²)`, on
/// sheet `sheet` (`s/r = (−β + sheet·√Δ)/σ`; 0 when `σ = 0`, the one point
/// `[−ρ : 2β]`).
#[derive(Clone, Debug)]
pub(crate) struct RulingPoint {
    pub x: Q,
    pub ys: i32,
    pub sheet: i32,
}

/// One real connected component of the affine curve.
#[derive(Clone, Debug)]
pub(crate) struct Branch {
    pub bounded: bool,
    pub at: RulingPoint,
}

/// The topology found: the branches and the isolated points of `Γ`'s
/// special points (acnodes), as points of `Γ` with their affine 3D point
/// left to the caller (it is the pencil's singular point).
#[derive(Clone, Debug)]
pub(crate) struct Topology {
    pub branches: Vec<Branch>,
    pub isolated: usize,
}

impl Rulings {
    /// The rulings of `p` (a cylinder or a cone) and `q`'s restriction.
    pub fn new(p: &QIn<Z>, q: &QIn<Z>) -> Rulings {
        let a = &p.a;
        let (u, v) = frame(a);
        let nu: Z = dot(&u, &u);
        let na: Z = dot(a, a);
        let cone = p.kind == Kind::Cone;
        // Γ: pd·nu·x² + pd·nu·na·y² = pn (cylinder) or pn·na (cone)
        let gamma = Gamma {
            g1: &p.pd * &nu,
            g2: &p.pd * &nu * &na,
            g0: if cone { &p.pn * &na } else { p.pn.clone() },
        };
        let z = Z::zero;
        let (s, r) = if cone {
            (
                [p.c[0].clone(), p.c[1].clone(), p.c[2].clone(), p.q.clone()],
                [
                    [a[0].clone(), a[1].clone(), a[2].clone(), z()],
                    [u[0].clone(), u[1].clone(), u[2].clone(), z()],
                    [v[0].clone(), v[1].clone(), v[2].clone(), z()],
                ],
            )
        } else {
            let qu = |w: &[Z; 3]| [&p.q * &w[0], &p.q * &w[1], &p.q * &w[2], z()];
            (
                [a[0].clone(), a[1].clone(), a[2].clone(), z()],
                [
                    [p.c[0].clone(), p.c[1].clone(), p.c[2].clone(), p.q.clone()],
                    qu(&u),
                    qu(&v),
                ],
            )
        };
        let m: M4<Z> = matrix(q);
        // M·s and M·r_j once, then dot products (the forms share them; ρ's
        // matrix is symmetric)
        let mv = |v: &[Z; 4]| -> [Z; 4] { std::array::from_fn(|i| dot4(&m[i], v)) };
        let ms = mv(&s);
        let mr: [[Z; 4]; 3] = std::array::from_fn(|j| mv(&r[j]));
        let sigma = dot4(&s, &ms);
        let bs: [Z; 3] = std::array::from_fn(|i| dot4(&r[i], &ms));
        let mut rr: [[Z; 3]; 3] = Default::default();
        for i in 0..3 {
            for j in i..3 {
                rr[i][j] = dot4(&r[i], &mr[j]);
                rr[j][i] = rr[i][j].clone();
            }
        }
        let beta = Quad2 {
            c: [bs[0].clone(), bs[1].clone(), bs[2].clone(), z(), z(), z()],
        };
        let two = Z::from(2);
        let rho = Quad2 {
            c: [
                rr[0][0].clone(),
                &two * &rr[0][1],
                &two * &rr[0][2],
                rr[1][1].clone(),
                &two * &rr[1][2],
                rr[2][2].clone(),
            ],
        };
        // Δ = β² − σρ
        let b = &bs;
        let delta = Quad2 {
            c: [
                &b[0] * &b[0] - &sigma * &rho.c[0],
                &two * &b[0] * &b[1] - &sigma * &rho.c[1],
                &two * &b[0] * &b[2] - &sigma * &rho.c[2],
                &b[1] * &b[1] - &sigma * &rho.c[3],
                &two * &b[1] * &b[2] - &sigma * &rho.c[4],
                &b[2] * &b[2] - &sigma * &rho.c[5],
            ],
        };
        Rulings {
            cone,
            gamma,
            sigma,
            beta,
            rho,
            delta,
        }
    }

    /// Where the rest of the curve meets a common ruling (`σ = 0`, `β` and
    /// `ρ` both zero at `p`).  Along `Γ` near `p`, `β` and `ρ` vanish to
    /// orders `mβ ∈ {1, 2}` and `mρ ≥ 1` (order ≥ 2 iff the derivative
    /// along `Γ` vanishes too: [`Gamma::tangential`]).  The point is
    /// `−ρ·S + 2β·R(z)`, whose affine weight is `∝ β` for a cylinder and
    /// `∝ ρ` for a cone: a cylinder's curve stays affine iff `mρ ≥ mβ`; a
    /// cone's iff `mρ ≤ mβ`, through the apex iff `mρ < mβ`.  (A cone with
    /// `mβ = mρ = 2` would need the next order: not traced.)
    fn common_ruling_end(&self, p: &GPoint) -> Result<End, Error> {
        let g = &self.gamma;
        let double = |f: &Quad2| sign_at_point(&g.reduce(&g.tangential(f)), p) == 0;
        let (mb2, mr2) = (double(&self.beta), double(&self.rho));
        Ok(match (self.cone, mb2, mr2) {
            (false, true, false) => End::Infinity,
            (false, _, _) | (true, false, false) => End::Affine,
            (true, false, true) => End::Infinity,
            (true, true, false) => End::Apex,
            (true, true, true) => {
                return Err(Error::internal(
                    "a common ruling met to second order on both sides",
                ));
            }
        })
    }

    /// The real affine topology of `X` (module docs).
    pub fn topology(&self) -> Result<Topology, Error> {
        let g = &self.gamma;
        let ends = g.ends();
        let rd = g.reduce(&self.delta);
        let rr = g.reduce(&self.rho);
        let rb = g.reduce(&self.beta);
        let sigma0 = self.sigma.is_zero();
        // the special points, with what vanishes there: (Δ, ρ, β)
        let mut pts: Vec<(GPoint, [bool; 3])> = Vec::new();
        let mut add = |p: GPoint, k: usize| {
            for (q, f) in pts.iter_mut() {
                if q.ys == p.ys && q.x.cmp_exact(&p.x) == Ordering::Equal {
                    f[k] = true;
                    return;
                }
            }
            let mut f = [false; 3];
            f[k] = true;
            pts.push((p, f));
        };
        if !sigma0 {
            if self.delta.is_zero() {
                return Err(Error::internal("Δ ≡ 0 on a non-planar curve"));
            }
            for p in zeros(g, &rd)? {
                add(p, 0);
            }
            if self.cone {
                for p in zeros(g, &rr)? {
                    add(p, 1);
                }
            }
        } else {
            if !self.beta.is_zero() {
                for p in zeros(g, &rb)? {
                    add(p, 2);
                }
            }
            if self.cone {
                for p in zeros(g, &rr)? {
                    add(p, 1);
                }
            }
        }
        pts.sort_by(|a, b| cyclic_cmp(&a.0, &b.0));
        let n = pts.len();
        // the arcs: arc i from point i to point i + 1 (cyclically)
        let arcs: Vec<(Q, i32)> = if n == 0 {
            vec![arc_sample(&ends, None, None)]
        } else {
            (0..n)
                .map(|i| {
                    let q = if n == 1 {
                        None
                    } else {
                        Some(&pts[(i + 1) % n].0)
                    };
                    arc_sample(&ends, Some(&pts[i].0), q)
                })
                .collect()
        };
        let na = arcs.len();
        let sheets: Vec<i32> = if sigma0 { vec![0] } else { vec![1, -1] };
        let ns = sheets.len();
        // piece (arc i, sheet k) ↦ i·ns + k; present when Δ > 0 on the arc
        let present: Vec<bool> = (0..na)
            .flat_map(|i| {
                let (x, ys) = &arcs[i];
                let on = sigma0 || sign_at_rational(g, &rd, x, *ys) > 0;
                std::iter::repeat_n(on, ns)
            })
            .collect();
        let mut dsu = Dsu((0..na * ns).collect());
        let mut unbounded = vec![false; na * ns];
        let mut isolated = 0;
        let mut apex: Option<usize> = None;
        let mut common = false;
        for i in 0..n {
            let (p, f) = &pts[i];
            let left = (i + na - 1) % na;
            let right = i;
            let piece = |arc: usize, k: usize| arc * ns + k;
            if !sigma0 {
                let dz = if f[0] { 0 } else { sign_at_point(&rd, p) };
                match dz {
                    1 => {
                        // a zero of ρ (cone): the sheet sign β is cut
                        let cut = if self.cone && f[1] {
                            sign_at_point(&rb, p)
                        } else {
                            0
                        };
                        for (k, &e) in sheets.iter().enumerate() {
                            if e == cut {
                                unbounded[piece(left, k)] = true;
                                unbounded[piece(right, k)] = true;
                            } else {
                                dsu.join(piece(left, k), piece(right, k));
                            }
                        }
                    }
                    0 => {
                        let at_infinity = self.cone && f[1];
                        let incident: Vec<usize> = [left, right]
                            .iter()
                            .flat_map(|&a| (0..ns).map(move |k| piece(a, k)))
                            .filter(|&j| present[j])
                            .collect();
                        if at_infinity {
                            for &j in &incident {
                                unbounded[j] = true;
                            }
                        } else if incident.is_empty() {
                            isolated += 1;
                        } else {
                            for w in incident.windows(2) {
                                dsu.join(w[0], w[1]);
                            }
                        }
                    }
                    _ => {}
                }
            } else {
                // σ = 0: one sheet, the point [−ρ : 2β] on the ruling over
                // z: where only β vanishes it is at infinity (cylinder) or
                // the apex (cone), where only ρ vanishes (cone) at infinity;
                // where both vanish the ruling is a common line, reached
                // at the limit of [−ρ : 2β] ([`Self::common_ruling_end`])
                let both = f[2] && (f[1] || sign_at_point(&rr, p) == 0);
                let end = if both {
                    common = true;
                    self.common_ruling_end(p)?
                } else if self.cone && f[1] {
                    End::Infinity
                } else if f[2] {
                    if self.cone { End::Apex } else { End::Infinity }
                } else {
                    End::Affine
                };
                match end {
                    End::Infinity => {
                        unbounded[piece(left, 0)] = true;
                        unbounded[piece(right, 0)] = true;
                    }
                    End::Affine => dsu.join(piece(left, 0), piece(right, 0)),
                    End::Apex => {
                        dsu.join(piece(left, 0), piece(right, 0));
                        match apex {
                            Some(j) => dsu.join(j, piece(right, 0)),
                            None => apex = Some(piece(right, 0)),
                        }
                    }
                }
            }
        }
        if sigma0 && self.cone && apex.is_none() && !common {
            // no real ruling of the apex's tangent cone (and no common
            // line through it): an isolated apex
            isolated += 1;
        }
        // the components
        let mut roots: Vec<(usize, bool, usize)> = Vec::new(); // (root, unbounded, piece)
        for j in 0..na * ns {
            if !present[j] {
                continue;
            }
            let r = dsu.find(j);
            match roots.iter_mut().find(|c| c.0 == r) {
                Some(c) => c.1 |= unbounded[j],
                None => roots.push((r, unbounded[j], j)),
            }
        }
        let branches = roots
            .into_iter()
            .map(|(_, unb, j)| {
                let (x, ys) = arcs[j / ns].clone();
                Branch {
                    bounded: !unb,
                    at: RulingPoint {
                        x,
                        ys,
                        sheet: sheets[j % ns],
                    },
                }
            })
            .collect();
        Ok(Topology { branches, isolated })
    }
}

/// The integer frame of the rulings' cross-section: `u ⊥ a`, `v = a × u`.
fn frame(a: &[Z; 3]) -> ([Z; 3], [Z; 3]) {
    let e: [Z; 3] = if a[0].is_zero() && a[1].is_zero() {
        [Z::one(), Z::zero(), Z::zero()]
    } else {
        [Z::zero(), Z::zero(), Z::one()]
    };
    let u = cross(a, &e);
    let v = cross(a, &u);
    (u, v)
}

fn cross(a: &[Z; 3], b: &[Z; 3]) -> [Z; 3] {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &[Z; 3], b: &[Z; 3]) -> Z {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// A point of an intersection curve on a ruling of the cylinder or cone
/// `P`: `X = P0 + t·d`, with the ruling (`P0`, `d`, exact in Q(√E)) and
/// `t` a root of `A·t² + 2B·t + C`, `Q`'s equation along the ruling (a
/// positive multiple of it): `t = (−B + root·√(B² − AC))/A`, or given
/// exactly (`t`, in Q(√E)) when `P`'s vertex lies on `Q`.  The coordinates
/// also as doubles, each with a proven bound on its error.
#[derive(Clone, Debug)]
pub struct CurvePoint {
    /// What the exact values are computed from: the ruling point and the
    /// parameterisation (shared by the branches of a curve).
    src: std::sync::Arc<RulingSource>,
    at: RulingPoint,
    /// `P0`, `d` and `A, B, C` over `Z[√D]/den`, unreduced: computed when
    /// the certified doubles needed them or when asked for, and reduced to
    /// lowest terms only when asked for (the gcds of 300-digit integers
    /// cost more than the rest of the construction).
    raw: std::sync::OnceLock<RawPoint>,
    exact: std::sync::OnceLock<[[QSqrt; 3]; 3]>,
    pub(crate) root: i32,
    pub(crate) t: Option<QSqrt>,
    pub(crate) approx: [(f64, f64); 3],
}

/// What [`Rulings::realize`]'s exact values are computed from: the
/// parameterisation of `X` by the rulings of `P`, and `P`'s axis, point
/// and denominator.
#[derive(Debug)]
pub(crate) struct RulingSource {
    rulings: Rulings,
    a: [Z; 3],
    c: [Z; 3],
    q: Z,
}

#[derive(Clone, Debug)]
struct RawPoint {
    p0: [Zf; 3],
    dir: [Zf; 3],
    quadratic: [Zf; 3],
    d: Z,
}

impl CurvePoint {
    fn raw(&self) -> &RawPoint {
        self.raw.get_or_init(|| self.src.raw_point(&self.at).0)
    }

    fn reduced(&self) -> &[[QSqrt; 3]; 3] {
        self.exact.get_or_init(|| {
            let r = self.raw();
            let out = |v: &[Zf; 3]| -> [QSqrt; 3] { std::array::from_fn(|i| v[i].to_qsqrt(&r.d)) };
            [out(&r.p0), out(&r.dir), out(&r.quadratic)]
        })
    }

    /// The ruling it lies on: a point and a direction (exact).
    pub fn ruling(&self) -> (&[QSqrt; 3], &[QSqrt; 3]) {
        let r = self.reduced();
        (&r[0], &r[1])
    }

    /// `[A, B, C]`: the other quadric's equation along the ruling is a
    /// positive multiple of `A·t² + 2B·t + C`.
    pub fn quadratic(&self) -> &[QSqrt; 3] {
        &self.reduced()[2]
    }

    /// Which root `t` of the quadratic the point is: `t = (−B + r·√(B² −
    /// AC))/A` for `r = ±1`; 0 when `t` is given exactly ([`Self::parameter`]).
    pub fn root(&self) -> i32 {
        self.root
    }

    /// Certified points of the whole curve for drawing, along `n` rulings
    /// ([`RulingSource::trace`]): the paths of every branch of the curve
    /// this point is on (the parameterisation is shared by the branches).
    pub(crate) fn trace(&self, n: usize) -> Vec<Vec<[f64; 3]>> {
        self.src.trace(n)
    }

    /// `t` when it lies in the field of the ruling (the cone's apex or the
    /// cylinder's point at infinity lies on the other quadric).
    pub fn parameter(&self) -> Option<&QSqrt> {
        self.t.as_ref()
    }

    /// The coordinates as doubles, each with a proven bound on its error:
    /// `|xᵢ − approx[i].0| ≤ approx[i].1`.
    pub fn approx(&self) -> [(f64, f64); 3] {
        self.approx
    }

    /// The exact coordinates (in Q(√E), or real algebraic numbers of
    /// degree ≤ 4 when the root nests a square root: computed on demand,
    /// tens of microseconds to milliseconds).
    pub fn exact(&self) -> EPoint {
        let (ruling_point, ruling_direction) = self.ruling();
        if let Some(t) = &self.t {
            return std::array::from_fn(|i| {
                Exact::Quad(ruling_point[i].add(&t.mul(&ruling_direction[i])))
            });
        }
        let [a, b, c] = self.quadratic();
        let disc = b.mul(b).sub(&a.mul(c));
        let inv_a = a.inv().expect("a quadratic along a ruling");
        let e = ruling_point
            .iter()
            .chain(ruling_direction.iter())
            .chain(self.quadratic().iter())
            .find(|x| !x.is_rational())
            .map(|x| x.d.clone())
            .unwrap_or_else(Q::one);
        std::array::from_fn(|i| {
            // X = (P0 − B·k) + root·k·√disc with k = dᵢ/A
            let k = ruling_direction[i].mul(&inv_a);
            let base = ruling_point[i].sub(&b.mul(&k));
            let inner = disc.mul(&k).mul(&k);
            let s = self.root * k.signum();
            super::numbers::nested(&base.a, &base.b, &e, &Q::one(), &inner.a, &inner.b, s)
        })
    }
}

/// `(u + v√D)/den` as an extended-exponent ball, with a relative radius
/// below 2^-40 (so its sign shows) unless it is 0: from the double ball of
/// `√D` when `u` and `v√D` have the same sign, else (cancellation) as
/// `(u² − v²D)/(den·(u − v√D))`, whose numerator is an exact integer and
/// whose denominator adds two terms of one sign.
fn zf_ball(x: &Zf, sqrt_d: &XBall, d: &Z) -> XBall {
    let q = |n: &Z| XBall::from_q(&Q::new_raw(n.clone(), x.den.clone()));
    let (a, b) = (q(&x.u), q(&x.v).mul(sqrt_d));
    if x.v.is_zero() || x.is_zero() {
        return a.add(&b);
    }
    // (u/den)² − (v√D/den)² = (u² − v²D)/den²
    a.add_by_conjugate(&b, 40, || {
        XBall::from_q(&Q::new_raw(&x.u * &x.u - &x.v * &x.v * d, &x.den * &x.den))
    })
}

/// A ball away from 0 with a relative radius below 2^-40.
fn tight(b: &XBall) -> bool {
    b.r * 1_099_511_627_776.0 < b.m.abs()
}

impl Rulings {
    /// What [`Self::realize`] needs of `P` (the cylinder or cone) beside
    /// the rulings, shared by the points of one curve.
    pub fn source(&self, p: &QIn<Z>) -> std::sync::Arc<RulingSource> {
        std::sync::Arc::new(RulingSource {
            rulings: self.clone(),
            a: p.a.clone(),
            c: p.c.clone(),
            q: p.q.clone(),
        })
    }

    /// The point of `X` at a ruling point of a branch (module docs; the
    /// rational `x`, the sign of `y`, the sheet), with `src` from
    /// [`Self::source`].  The certified doubles come from balls on the
    /// integer data when those are tight (no arithmetic in `Z[√D]`), else
    /// from the exact values; the exact values are computed when asked for
    /// (or when the doubles needed them).
    pub fn realize(
        src: &std::sync::Arc<RulingSource>,
        at: &RulingPoint,
    ) -> Result<CurvePoint, Error> {
        let r = &src.rulings;
        let root = if r.sigma.is_zero() {
            0
        } else if r.cone {
            -at.sheet
        } else {
            at.sheet
        };
        let raw = std::sync::OnceLock::new();
        let by_balls = (!r.sigma.is_zero())
            .then(|| src.approx_by_balls(at, root))
            .flatten();
        let (approx, t) = match by_balls {
            Some(approx) => (approx, None),
            None => {
                let (point, t) = src.raw_point(at);
                let approx = exact_doubles(&point, t.as_ref(), root)?;
                let t = t.map(|t| t.to_qsqrt(&point.d));
                let _ = raw.set(point);
                (approx, t)
            }
        };
        Ok(CurvePoint {
            src: src.clone(),
            at: at.clone(),
            raw,
            exact: std::sync::OnceLock::new(),
            root,
            t,
            approx,
        })
    }
}

impl Quad2 {
    /// [`Self::eval`] on balls.
    fn eval_ball(&self, x: &XBall, y: &XBall) -> XBall {
        let c = |i: usize| XBall::from_z(&self.c[i]);
        let xpart = x.mul(&c(1).add(&x.mul(&c(3))));
        let ypart = y.mul(&c(2).add(&x.mul(&c(4))).add(&y.mul(&c(5))));
        c(0).add(&xpart).add(&ypart)
    }
}

/// A certified double of a ball: `±∞` with an infinite bound beyond the
/// range of doubles, the sign that of the ball (relative radius < 2^-40),
/// as for every other certified double (contract §4).
fn double_of(b: XBall) -> (f64, f64) {
    let m = b.m;
    b.to_f64().unwrap_or((
        if m < 0.0 {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        },
        f64::INFINITY,
    ))
}

impl RulingSource {
    /// The certified doubles of the point from balls on the integer data
    /// (`σ ≠ 0`; the formulas of [`Self::raw_point`] and [`exact_doubles`],
    /// each ball a proven enclosure): `None` when a sign is not certain or
    /// a coordinate is not tight (a cancellation), then the exact values
    /// decide.
    fn approx_by_balls(&self, at: &RulingPoint, root: i32) -> Option<[(f64, f64); 3]> {
        let balls = self.point_balls(at, root)?;
        let mut approx = [(0.0, 0.0); 3];
        for i in 0..3 {
            let x = balls[i];
            if !(x.m == 0.0 && x.r == 0.0 || tight(&x)) {
                return None;
            }
            approx[i] = double_of(x);
        }
        Some(approx)
    }

    /// The balls of the point's coordinates ([`Self::approx_by_balls`]
    /// without the tightness test); `None` when a sign is not certain.
    fn point_balls(&self, at: &RulingPoint, root: i32) -> Option<[XBall; 3]> {
        let r = &self.rulings;
        let g = &r.gamma;
        let xb = XBall::from_q(&at.x);
        // y = ys·√((g0·q² − g1·p²)/(g2·q²)) for x = p/q
        let (xn, xd) = (at.x.numer(), at.x.denom());
        let q2 = xd * xd;
        let en = &g.g0 * &q2 - &g.g1 * xn * xn;
        let yb = if en.is_zero() {
            XBall::zero()
        } else {
            let y = XBall::from_q(&Q::new_raw(en, &g.g2 * q2)).sqrt()?;
            if at.ys < 0 { y.neg() } else { y }
        };
        let (u, v) = frame(&self.a);
        let zb = |w: &[Z; 3]| -> [XBall; 3] { std::array::from_fn(|i| XBall::from_z(&w[i])) };
        let (ub, vb, ab) = (zb(&u), zb(&v), zb(&self.a));
        let xy: [XBall; 3] = std::array::from_fn(|i| xb.mul(&ub[i]).add(&yb.mul(&vb[i])));
        let c3: [XBall; 3] =
            std::array::from_fn(|i| XBall::from_q(&Q::new_raw(self.c[i].clone(), self.q.clone())));
        let (p0, dir): ([XBall; 3], [XBall; 3]) = if r.cone {
            (c3, std::array::from_fn(|i| ab[i].add(&xy[i])))
        } else {
            (std::array::from_fn(|i| c3[i].add(&xy[i])), ab)
        };
        let (bz, rz) = (r.beta.eval_ball(&xb, &yb), r.rho.eval_ball(&xb, &yb));
        let sig = XBall::from_z(&r.sigma);
        let qi = XBall::from_z(&self.q).recip()?;
        let qb = bz.mul(&qi);
        let (qa, qc) = if r.cone {
            (rz, sig.mul(&qi).mul(&qi))
        } else {
            (sig, rz.mul(&qi).mul(&qi))
        };
        let sq = qb.mul(&qb).sub(&qa.mul(&qc)).sqrt()?;
        let sq = if root > 0 { sq } else { sq.neg() };
        let sb = qb.sign()?;
        let t = if sb == 0 || -sb == root {
            qb.neg().add(&sq).mul(&qa.recip()?)
        } else {
            qc.mul(&qb.neg().sub(&sq).recip()?)
        };
        Some(std::array::from_fn(|i| p0[i].add(&t.mul(&dir[i]))))
    }

    /// Points of `X` for drawing: over `n` rulings of `P` around `Γ` (the
    /// rational `x = ⌊xm·cos θ⌉` on a 2^-40 grid, `y`'s sign that of
    /// `sin θ`), each root of the ruling's quadratic as certified doubles
    /// ([`Self::point_balls`]: every point is on the curve within its
    /// proven bounds, below 2^-30 of the point's size).  Runs of
    /// consecutive rulings with a point make the paths; where the two roots
    /// meet (`Δ = 0` between two rulings) their last points are joined.
    /// No point where the ball evaluation is not certain (near `Δ = 0`, a
    /// point at infinity): a gap there.
    fn trace(&self, n: usize) -> Vec<Vec<[f64; 3]>> {
        let g = &self.rulings.gamma;
        // xm = √(g0/g1), a hair inside Γ's range of x
        let Some(ratio) = XBall::from_z(&g.g1)
            .recip()
            .map(|r| XBall::from_z(&g.g0).mul(&r))
            .and_then(|b| b.to_f64())
            .map(|(v, _)| v)
            .filter(|v| v.is_finite() && *v > 0.0)
        else {
            return vec![];
        };
        let xm = ratio.sqrt() * (1.0 - 1e-9);
        let scale = (1u64 << 40) as f64;
        let points: Vec<[Option<[f64; 3]>; 2]> = (0..n)
            .map(|k| {
                let theta = std::f64::consts::TAU * (k as f64 + 0.5) / n as f64;
                let xr = (xm * theta.cos() * scale).round();
                let Some(xz) = <Z as num_traits::FromPrimitive>::from_f64(xr) else {
                    return [None, None];
                };
                let at = RulingPoint {
                    x: Q::new(xz, Z::from(1u64 << 40)),
                    ys: if theta.sin() >= 0.0 { 1 } else { -1 },
                    sheet: 1,
                };
                // a point within 2^-30 of its size (absolute, not per
                // coordinate: a coordinate near 0 is drawn as well)
                let one = |root: i32| -> Option<[f64; 3]> {
                    let b = self.point_balls(&at, root)?;
                    let d: Vec<(f64, f64)> = b.iter().map(|x| x.to_f64()).collect::<Option<_>>()?;
                    let size = d.iter().fold(1.0f64, |m, (v, _)| m.max(v.abs()));
                    let ok = d.iter().all(|(v, e)| v.is_finite() && *e <= size * 9.3e-10);
                    ok.then(|| [d[0].0, d[1].0, d[2].0])
                };
                [one(-1), one(1)]
            })
            .collect();
        // start at a ruling without a point of either root, if any (a run
        // is then never cut by the wrap-around)
        let start = points
            .iter()
            .position(|p| p[0].is_none() && p[1].is_none())
            .unwrap_or(0);
        let mut paths = Vec::new();
        for root in 0..2 {
            let mut cur: Vec<[f64; 3]> = Vec::new();
            for k in 0..=n {
                match points[(start + k) % n][root] {
                    Some(p) if k < n => cur.push(p),
                    _ => {
                        if cur.len() > 1 {
                            paths.push(std::mem::take(&mut cur));
                        }
                        cur.clear();
                    }
                }
            }
            // a root on every ruling: a closed loop, closed
            if points.iter().all(|p| p[root].is_some())
                && let (Some(first), Some(path)) = (points[start][root], paths.last_mut())
            {
                path.push(first);
            }
        }
        // where the roots meet: both present at a ruling, both absent at the
        // next (or the previous)
        for k in 0..n {
            let (here, next) = (&points[k], &points[(k + 1) % n]);
            let both = |p: &[Option<[f64; 3]>; 2]| p[0].zip(p[1]);
            let none = |p: &[Option<[f64; 3]>; 2]| p[0].is_none() && p[1].is_none();
            if let Some((a, b)) = both(here)
                && none(next)
            {
                paths.push(vec![a, b]);
            }
            if let Some((a, b)) = both(next)
                && none(here)
            {
                paths.push(vec![a, b]);
            }
        }
        paths
    }

    /// The exact data of the point over `Z[√D]/den`, unreduced, and `t`
    /// when it is exact (`σ = 0`).
    fn raw_point(&self, at: &RulingPoint) -> (RawPoint, Option<Zf>) {
        let r = &self.rulings;
        // y = ys·√E, E = En/Ed: y = ys·√D/Ed with D = En·Ed
        let e = r.gamma.y2(&at.x);
        let (d, root_d) = radicand(e.numer() * e.denom());
        let ed = e.denom().clone();
        let (xn, xd) = (at.x.numer().clone(), at.x.denom().clone());
        let ys = Z::from(at.ys);
        // y as a Zf: ys·√D/Ed (or ys·r/Ed when D = r²)
        let y = match &root_d {
            Some(r) => Zf::int(&ys * r).div_z(&ed),
            None => Zf::uv(Z::zero(), ys.clone()).div_z(&ed),
        };
        let xq = Zf::int(xn).div_z(&xd);
        let a3 = |w: &[Z; 3]| -> [Zf; 3] { std::array::from_fn(|i| Zf::int(w[i].clone())) };
        let (u, v) = frame(&self.a);
        let (uz, vz, az) = (a3(&u), a3(&v), a3(&self.a));
        let c3: [Zf; 3] = std::array::from_fn(|i| Zf::int(self.c[i].clone()).div_z(&self.q));
        // x·u + y·v
        let xy: [Zf; 3] = std::array::from_fn(|i| xq.mul(&uz[i], &d).add(&y.mul(&vz[i], &d)));
        let (p0, dir): ([Zf; 3], [Zf; 3]) = if r.cone {
            (c3, std::array::from_fn(|i| az[i].add(&xy[i])))
        } else {
            (std::array::from_fn(|i| c3[i].add(&xy[i])), az)
        };
        // Q along the ruling, from the restrictions already computed
        // (module docs): for a cylinder the ruling is s·(a, 0) + r·q·(P0, 1),
        // so A = σ, B = β(z)/q, C = ρ(z)/q²; for a cone it is
        // s·q·(P0, 1) + r·(d, 0), so A = ρ(z), B = β(z)/q, C = σ/q² —
        // the values of xᵀMy on the homogeneous (P0, 1) and (d, 0)
        let (bz, rz) = (r.beta.eval(&xq, &y, &d), r.rho.eval(&xq, &y, &d));
        let sig = Zf::int(r.sigma.clone());
        let q2 = &self.q * &self.q;
        let qb = bz.div_z(&self.q);
        let (qa, qc) = if r.cone {
            (rz, sig.div_z(&q2))
        } else {
            (sig, rz.div_z(&q2))
        };
        // P's vertex on Q: the one other point of the ruling, rational in Q(√E)
        let t = r.sigma.is_zero().then(|| {
            if r.cone {
                // C = 0: t = −2B/A
                qb.scale(&Z::from(-2)).div(&qa, &d)
            } else {
                // A = 0: t = −C/(2B)
                qc.neg().div(&qb.scale(&Z::from(2)), &d)
            }
        });
        let point = RawPoint {
            p0,
            dir,
            quadratic: [qa, qb, qc],
            d,
        };
        (point, t)
    }
}

/// The certified doubles of a point from its exact data (`t_exact` when
/// `σ = 0`).  A coordinate that cancels (near 0 against its terms) is
/// recomputed without cancellation, so that every bound is relative: with
/// t exact, Xᵢ is exact in Z[√D]/den; otherwise A·Xᵢ = N + σ√M
/// (N = A·P₀ᵢ − B·dᵢ, M = dᵢ²(B² − AC), σ = root·sign dᵢ), and when N and
/// σ√M have opposite signs A·Xᵢ = (N² − M)/(N − σ√M), an exact numerator
/// over a sum of two terms of one sign.
fn exact_doubles(
    raw: &RawPoint,
    t_exact: Option<&Zf>,
    root: i32,
) -> Result<[(f64, f64); 3], Error> {
    let RawPoint {
        p0,
        dir,
        quadratic: [qa, qb, qc],
        d,
    } = raw;
    let sd = if d.is_one() {
        XBall::from_q(&Q::one())
    } else {
        XBall::from_z(d)
            .sqrt()
            .ok_or_else(|| Error::internal("√D of a ruling point"))?
    };
    let ball = |x: &Zf| zf_ball(x, &sd, d);
    let t_ball = match t_exact {
        Some(t) => ball(t),
        None => {
            // B² − AC exactly (positive inside the arc), then its root
            let disc = ball(&qb.mul(qb, d).sub(&qa.mul(qc, d)));
            let sq = disc
                .sqrt()
                .ok_or_else(|| Error::internal("a branch point off its arc"))?;
            let sq = if root > 0 { sq } else { sq.neg() };
            // t = (−B + root·√disc)/A, or C/(−B − root·√disc) when −B and
            // root·√disc have opposite signs (no cancellation either way)
            let sb = qb.sign(d);
            if sb == 0 || -sb == root {
                let inv = ball(qa)
                    .recip()
                    .ok_or_else(|| Error::internal("A = 0 at a branch point"))?;
                ball(qb).neg().add(&sq).mul(&inv)
            } else {
                let den = ball(qb).neg().sub(&sq);
                let inv = den
                    .recip()
                    .ok_or_else(|| Error::internal("a branch point at infinity"))?;
                ball(qc).mul(&inv)
            }
        }
    };
    let mut approx = [(0.0, 0.0); 3];
    for i in 0..3 {
        let b = ball(&p0[i]).add(&t_ball.mul(&ball(&dir[i])));
        let b = if tight(&b) {
            b
        } else if let Some(t) = t_exact {
            ball(&p0[i].add(&t.mul(&dir[i], d)))
        } else {
            let n = qa.mul(&p0[i], d).sub(&qb.mul(&dir[i], d));
            let m = dir[i]
                .mul(&dir[i], d)
                .mul(&qb.mul(qb, d).sub(&qa.mul(qc, d)), d);
            let sqrt_m = ball(&m)
                .sqrt()
                .ok_or_else(|| Error::internal("a branch point off its arc"))?;
            let sigma = root * dir[i].sign(d);
            let inv_a = ball(qa)
                .recip()
                .ok_or_else(|| Error::internal("A = 0 at a branch point"))?;
            let sn = n.sign(d);
            if sigma == 0 || sn == 0 || sn == sigma {
                // N and σ√M of one sign: no cancellation
                let s = if sigma < 0 { sqrt_m.neg() } else { sqrt_m };
                ball(&n).add(&s).mul(&inv_a)
            } else {
                let norm = n.mul(&n, d).sub(&m);
                if norm.is_zero() {
                    XBall::from_q(&Q::zero())
                } else {
                    let conj = if sigma > 0 {
                        ball(&n).sub(&sqrt_m)
                    } else {
                        ball(&n).add(&sqrt_m)
                    };
                    let inv = conj
                        .recip()
                        .ok_or_else(|| Error::internal("a branch point at infinity"))?;
                    ball(&norm).mul(&inv).mul(&inv_a)
                }
            }
        };
        approx[i] = double_of(b);
    }
    Ok(approx)
}

// ------------------------------------------------- a common ruling (σ = 0)

/// The lines of `X` that are rulings of `P` (the common rulings: `β` and
/// `ρ` both zero over `z0`) and the points where the rest of the curve
/// crosses them, exactly; `None` when this case is not the simple one (σ ≠
/// 0, no or several common rulings, `β` constant, or `X` singular along a
/// whole line), which the caller leaves to the reference route.
///
/// `z0` lies on the line `β = 0`, so it is one of the two points of that
/// line on `Γ`, in one Q(√e); it is the one where `ρ` vanishes too.  A
/// point of the line `L: X0 + λ·d` is singular on `P ∩ Q` iff the normals
/// there are parallel; both are perpendicular to `d`, so iff
/// `f(λ) = (∇P × ∇Q)·d = 0`, a quadratic in `λ` (the apex of a cone,
/// where `∇P = 0`, among its roots).
pub(crate) fn common_ruling(
    p: &QIn<Z>,
    q: &QIn<Z>,
    r: &Rulings,
) -> Option<(EPoint, EPoint, Vec<EPoint>)> {
    if !r.sigma.is_zero() {
        return None;
    }
    let g = &r.gamma;
    let [b0, b1, b2] = [&r.beta.c[0], &r.beta.c[1], &r.beta.c[2]];
    let qz = |z: &Z| Q::from_integer(z.clone());
    let rat = |x: Q| QSqrt::rational(x);
    // the points of β = 0 on Γ: (x, y) over Q(√e)
    let cands: Vec<(QSqrt, QSqrt)> = if b2.is_zero() {
        if b1.is_zero() {
            return None;
        }
        let x = -qz(b0) / qz(b1);
        let y2 = (qz(&g.g0) - qz(&g.g1) * &x * &x) / qz(&g.g2);
        if y2 < Q::zero() {
            return None;
        }
        [1, -1]
            .iter()
            .map(|&s| {
                (
                    rat(x.clone()),
                    QSqrt::new(Q::zero(), Q::from_integer(s.into()), y2.clone()),
                )
            })
            .collect()
    } else {
        // (g1·b2² + g2·b1²)x² + 2·g2·b0·b1·x + g2·b0² − g0·b2² = 0
        let a = qz(&(&g.g1 * b2 * b2 + &g.g2 * b1 * b1));
        let b = qz(&(&g.g2 * b0 * b1 * 2));
        let c = qz(&(&g.g2 * b0 * b0 - &g.g0 * b2 * b2));
        let disc = &b * &b - Q::from_integer(4.into()) * &a * &c;
        if disc < Q::zero() {
            return None;
        }
        let two_a = Q::from_integer(2.into()) * &a;
        [1, -1]
            .iter()
            .map(|&s| {
                let x = QSqrt::new(
                    -&b / &two_a,
                    Q::from_integer(s.into()) / &two_a,
                    disc.clone(),
                );
                // y = −(b0 + b1·x)/b2
                let y = x
                    .scale(&qz(b1))
                    .add(&rat(qz(b0)))
                    .scale(&(-Q::one() / qz(b2)));
                (x, y)
            })
            .collect()
    };
    let quad_at = |f: &Quad2, x: &QSqrt, y: &QSqrt| -> QSqrt {
        let c = |i: usize| rat(qz(&f.c[i]));
        c(0).add(&x.mul(&c(1).add(&x.mul(&c(3))).add(&y.mul(&c(4)))))
            .add(&y.mul(&c(2).add(&y.mul(&c(5)))))
    };
    let common: Vec<&(QSqrt, QSqrt)> = cands
        .iter()
        .filter(|(x, y)| quad_at(&r.rho, x, y).is_zero())
        .collect();
    // (β = 0 tangent to Γ gives two equal candidates: both or neither
    // pass, and the case is left to the caller)
    let [(x0, y0)] = common[..] else {
        return None;
    };
    // the line: the ruling of P over z0 (as in `realize`)
    let (u, v) = frame(&p.a);
    let c3: [QSqrt; 3] = std::array::from_fn(|i| rat(Q::new(p.c[i].clone(), p.q.clone())));
    let xy: [QSqrt; 3] = std::array::from_fn(|i| x0.scale(&qz(&u[i])).add(&y0.scale(&qz(&v[i]))));
    let a3: [QSqrt; 3] = std::array::from_fn(|i| rat(qz(&p.a[i])));
    let (x_0, d): ([QSqrt; 3], [QSqrt; 3]) = if r.cone {
        (c3, std::array::from_fn(|i| a3[i].add(&xy[i])))
    } else {
        (std::array::from_fn(|i| c3[i].add(&xy[i])), a3)
    };
    // f(λ) = ((nP0 + λ nP1) × (nQ0 + λ nQ1))·d, with nF = M_F·(X, 1)
    let grad = |f: &QIn<Z>, h: &[QSqrt; 3], w: i64| -> [QSqrt; 3] {
        let m: M4<Z> = matrix(f);
        std::array::from_fn(|i| {
            (0..3).fold(rat(Q::from_integer(&m[i][3] * w)), |acc, j| {
                acc.add(&h[j].scale(&qz(&m[i][j])))
            })
        })
    };
    let (np0, np1) = (grad(p, &x_0, 1), grad(p, &d, 0));
    let (nq0, nq1) = (grad(q, &x_0, 1), grad(q, &d, 0));
    let cr = |a: &[QSqrt; 3], b: &[QSqrt; 3]| -> [QSqrt; 3] {
        std::array::from_fn(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            a[j].mul(&b[k]).sub(&a[k].mul(&b[j]))
        })
    };
    let dotq = |a: &[QSqrt; 3]| a[0].mul(&d[0]).add(&a[1].mul(&d[1])).add(&a[2].mul(&d[2]));
    let f0 = dotq(&cr(&np0, &nq0));
    let f1 = dotq(&cr(&np0, &nq1)).add(&dotq(&cr(&np1, &nq0)));
    let f2 = dotq(&cr(&np1, &nq1));
    let e = [x0, y0]
        .iter()
        .find(|t| !t.is_rational())
        .map(|t| t.d.clone())
        .unwrap_or_else(Q::one);
    let at = |lam: &QSqrt| -> EPoint {
        std::array::from_fn(|i| Exact::Quad(x_0[i].add(&lam.mul(&d[i]))))
    };
    let mut points = Vec::new();
    if f2.is_zero() {
        if f1.is_zero() {
            return None; // singular along the whole line
        }
        points.push(at(&f0.neg().div(&f1)?));
    } else {
        // λ = (−f1 ± √Δ)/(2 f2), Δ = f1² − 4 f0 f2 in Q(√e)
        let delta = f1
            .mul(&f1)
            .sub(&f0.mul(&f2).scale(&Q::from_integer(4.into())));
        match delta.signum() {
            -1 => {}
            0 => points.push(at(&f1.neg().div(&f2.scale(&Q::from_integer(2.into())))?)),
            _ => {
                let inv = f2.scale(&Q::from_integer(2.into())).inv()?;
                let mid = f1.neg().mul(&inv);
                for sign in [1, -1] {
                    // Xᵢ = (X0ᵢ + mid·dᵢ) + sign·kᵢ·√Δ with kᵢ = dᵢ/(2 f2)
                    points.push(std::array::from_fn(|i| {
                        let base = x_0[i].add(&mid.mul(&d[i]));
                        let k = d[i].mul(&inv);
                        let inner = delta.mul(&k).mul(&k);
                        let s = sign * k.signum();
                        super::numbers::nested(
                            &base.a,
                            &base.b,
                            &e,
                            &Q::one(),
                            &inner.a,
                            &inner.b,
                            s,
                        )
                    }));
                }
            }
        }
    }
    Some((
        super::numbers::epoint(&x_0),
        super::numbers::epoint(&d),
        points,
    ))
}
