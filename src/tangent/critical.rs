//! S of degree ≥ 3: the critical points of S on E, exactly.
//!
//! On E the gradient ∇E never vanishes, so the critical points of S on E
//! are the zeros of `E = 0, ∇S × ∇E = 0` — three minors, no multiplier λ.
//!
//! * **Finite critical set** ([`CriticalAnalysis`]): a Gröbner basis makes
//!   the quotient algebra explicit; after making the ideal radical
//!   (Seidenberg) a separating linear form `t = x + a·y + b·z` gives the
//!   rational univariate representation `f(t) = 0, x = X(t), y = Y(t),
//!   z = Z(t), S = U(t)`.  A critical point is real iff its `t` is a real
//!   root of `f` (t separates conjugate points), so the real critical values
//!   are exactly `U(α)` over the real roots α of `f` — the trap of SPEC §3
//!   cannot occur.
//! * **Curves of critical points** ([`LevelSetAnalysis`], symmetric inputs):
//!   the critical values are the roots of the generator of
//!   `(I + (S − u)) ∩ Q[u]`.  For a rational `q` that is not a critical
//!   value, the level curve `E ∩ {S = q}` is smooth and compact, and it has
//!   real points iff a generic linear form `ℓ` has a real critical point on
//!   it (zeros of `E, S − q, ∇ℓ·(∇E × ∇S)`, a finite system).  That decides
//!   `ν < q < μ` for one rational in each gap between consecutive critical
//!   values, which pins down ν and μ exactly.

use super::ellipsoid::Ellipsoid;
use super::witness::{WitnessPoint, find_witness};
use crate::elim::groebner::{GPoly, MonoOrder, groebner};
use crate::elim::quotient::{Quotient, krylov_minpoly, mat_comb, solve_columns};
use crate::error::Error;
use crate::number::{Q, qi};
use crate::poly::mpoly::{MPoly, U, X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::{RealAlg, eval_q, simplest_rational_in, value_at, value_polynomial};
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// A rational univariate representation of the zeros of a radical
/// zero-dimensional system in x, y, z.
#[derive(Clone, Debug)]
pub struct Rur {
    /// Dimension of the quotient of the original ideal (zeros with
    /// multiplicity).
    pub multiplicity_dim: usize,
    /// Number of distinct zeros.
    pub points: usize,
    /// The separating form `t = c0·x + c1·y + c2·z`.
    pub form: [Q; 3],
    /// `f(t)`: square-free, its roots are the values of `t` at the zeros.
    pub f: ZPoly,
    /// `x, y, z` as polynomials in `t` (degree < deg f).
    pub coords: [QPoly; 3],
    /// Extra polynomials (e.g. S) as polynomials in `t`.
    pub extra: Vec<QPoly>,
    /// The real roots of `f`, increasing: one per real zero.
    pub real_roots: Vec<RealAlg>,
    /// True when the ideal had to be made radical.
    pub made_radical: bool,
}

const SLOTS: [usize; 3] = [X, Y, Z];

fn to_g(p: &QMPoly) -> GPoly {
    GPoly::from_mpoly(p, &SLOTS, MonoOrder::GrevLex)
}

/// Solves a zero-dimensional system in x, y, z exactly: `Ok(None)` when the
/// system has infinitely many complex zeros.
pub fn solve_zero_dim(gens: &[QMPoly], extra: &[QMPoly]) -> Result<Option<Rur>, Error> {
    let ord = MonoOrder::GrevLex;
    let input: Vec<GPoly> = gens.iter().filter(|g| !g.is_zero()).map(to_g).collect();
    let gb = groebner(input.clone(), 3, ord);
    if gb.is_unit() {
        return Ok(Some(Rur {
            multiplicity_dim: 0,
            points: 0,
            form: [qi(1), qi(0), qi(0)],
            f: ZPoly::constant(1.into()),
            coords: [QPoly::zero(), QPoly::zero(), QPoly::zero()],
            extra: extra.iter().map(|_| QPoly::zero()).collect(),
            real_roots: vec![],
            made_radical: false,
        }));
    }
    let Some(mut quo) = Quotient::new(gb) else {
        return Ok(None);
    };
    let multiplicity_dim = quo.dim();
    // radical: the minimal polynomials of x, y, z must be square-free
    let mut made_radical = false;
    let mut mats = [quo.var_matrix(0), quo.var_matrix(1), quo.var_matrix(2)];
    let mut sq_add = Vec::new();
    for (v, m) in mats.iter().enumerate() {
        let (mp, _) = krylov_minpoly(m, &quo.one());
        let (mz, _) = ZPoly::from_q(&mp);
        let sq = mz.squarefree_part();
        if sq.degree() != mz.degree() {
            sq_add.push(MPoly::from_univariate(&sq.to_q(), SLOTS[v]));
        }
    }
    if !sq_add.is_empty() {
        made_radical = true;
        let mut all = input;
        all.extend(sq_add.iter().map(to_g));
        let gb2 = groebner(all, 3, ord);
        quo = Quotient::new(gb2)
            .ok_or_else(|| Error::Internal("radical of a zero-dimensional ideal is not zero-dimensional".into()))?;
        mats = [quo.var_matrix(0), quo.var_matrix(1), quo.var_matrix(2)];
    }
    let d = quo.dim();
    // a separating linear form
    let candidates: [(i64, i64); 12] = [
        (0, 0),
        (1, 0),
        (0, 1),
        (1, 1),
        (1, -1),
        (2, 1),
        (1, 2),
        (2, -1),
        (-1, 3),
        (3, 5),
        (5, -7),
        (7, 11),
    ];
    let one = quo.one();
    let mut chosen = None;
    for (a, b) in candidates {
        let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
        let (mp, vecs) = krylov_minpoly(&mt, &one);
        if mp.degree() == Some(d) {
            chosen = Some(([qi(1), qi(a), qi(b)], mp, vecs));
            break;
        }
    }
    let (form, mp, vecs) = match chosen {
        Some(c) => c,
        None => {
            // deterministic wider search
            let mut found = None;
            'outer: for a in -20i64..=20 {
                for b in -20i64..=20 {
                    let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
                    let (mp, vecs) = krylov_minpoly(&mt, &one);
                    if mp.degree() == Some(d) {
                        found = Some(([qi(1), qi(a), qi(b)], mp, vecs));
                        break 'outer;
                    }
                }
            }
            found.ok_or_else(|| Error::Internal("no separating linear form found".into()))?
        }
    };
    // shape: coordinates of x, y, z, extras in the basis 1, t, …, t^(d-1)
    let mut rhs: Vec<Vec<Q>> = (0..3)
        .map(|v| crate::elim::quotient::mat_vec(&mats[v], &one))
        .collect();
    for p in extra {
        rhs.push(nf_rational(&quo, p));
    }
    let sol = solve_columns(&vecs, &rhs)
        .ok_or_else(|| Error::Internal("Krylov basis of a separating element is singular".into()))?;
    let polys: Vec<QPoly> = sol.into_iter().map(QPoly::new).collect();
    let (f, _) = ZPoly::from_q(&mp);
    let real_roots = RealAlg::roots_of(&f);
    Ok(Some(Rur {
        multiplicity_dim,
        points: d,
        form,
        f,
        coords: [polys[0].clone(), polys[1].clone(), polys[2].clone()],
        extra: polys[3..].to_vec(),
        real_roots,
        made_radical,
    }))
}

/// Normal-form coordinates of a rational polynomial.
fn nf_rational(quo: &Quotient, p: &QMPoly) -> Vec<Q> {
    if p.is_zero() {
        return vec![Q::zero(); quo.dim()];
    }
    let (z, k) = p.to_primitive_z();
    let g = GPoly::from_zmpoly(&z, &SLOTS, MonoOrder::GrevLex);
    quo.nf(&g).into_iter().map(|c| c * &k).collect()
}

impl Rur {
    /// A rational approximation of the real zero number `i`.
    pub fn approx_point(&self, i: usize, bits: u32) -> [Q; 3] {
        let t = self.real_roots[i].to_rational_approx(bits);
        std::array::from_fn(|k| eval_q(&self.coords[k], &t))
    }
}

/// The critical points of S on E (finite case).
#[derive(Clone, Debug)]
pub struct CriticalAnalysis {
    /// The generators `E, (∇S × ∇E)₁, ₂, ₃`.
    pub generators: Vec<QMPoly>,
    /// Gröbner basis size of the critical ideal.
    pub rur: Rur,
    /// `S = U(t)` on the critical points.
    pub value_poly: QPoly,
    /// The value of S at each real critical point (same order as
    /// `rur.real_roots`).
    pub values: Vec<RealAlg>,
    /// D(u): all critical values (complex points included), square-free.
    pub judging: ZPoly,
    /// The judging polynomial by resultant elimination with branch
    /// splitting, when it finished within its size budget.
    pub elimination: Option<super::judging::Elimination>,
}

impl CriticalAnalysis {
    /// The values attained by real critical points.
    pub fn real_values(&self) -> Vec<RealAlg> {
        self.values.clone()
    }

    /// A witness near a real critical point whose value is `value`.
    pub fn witness(&self, value: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        let i = self
            .values
            .iter()
            .position(|v| v.cmp_exact(value) == Ordering::Equal)?;
        let approx = |bits: u32| Some(self.rur.approx_point(i, bits));
        find_witness(e, s, want, &approx)
    }
}

/// Level-set analysis for curves of critical points.
#[derive(Clone, Debug)]
pub struct LevelSetAnalysis {
    /// D(u), the generator of the elimination ideal, square-free.
    pub judging: ZPoly,
    /// The rational levels tested and whether `E ∩ {S = q}` has real points.
    pub levels: Vec<(Q, bool)>,
    /// ν and μ (the values attained), as found.
    pub attained: Vec<RealAlg>,
    /// The linear form used for the level curves.
    pub form: [Q; 3],
}

/// What the critical-point analysis found.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// Finitely many critical points.
    Finite(CriticalAnalysis),
    /// Curves of critical points.
    Curves(LevelSetAnalysis),
}

/// `∇S × ∇E`.
pub fn cross_gradients(s: &QMPoly, e: &QMPoly) -> [QMPoly; 3] {
    let gs = [s.derivative(X), s.derivative(Y), s.derivative(Z)];
    let ge = [e.derivative(X), e.derivative(Y), e.derivative(Z)];
    [
        &(&gs[1] * &ge[2]) - &(&gs[2] * &ge[1]),
        &(&gs[2] * &ge[0]) - &(&gs[0] * &ge[2]),
        &(&gs[0] * &ge[1]) - &(&gs[1] * &ge[0]),
    ]
}

/// Runs the critical-point analysis of S on E.
pub fn analyze(e: &Ellipsoid, s: &QMPoly) -> Result<Outcome, Error> {
    let cross = cross_gradients(s, &e.poly);
    let mut gens = vec![e.poly.clone()];
    gens.extend(cross.iter().cloned());
    match solve_zero_dim(&gens, std::slice::from_ref(s))? {
        Some(rur) => {
            if rur.points == 0 {
                return Err(Error::Internal(
                    "no critical point of S on E (impossible on a compact ellipsoid)".into(),
                ));
            }
            let value_poly = rur.extra[0].clone();
            let one = QPoly::constant(Q::one());
            let judging = value_polynomial(&rur.f, &value_poly, &one);
            let values = rur
                .real_roots
                .iter()
                .map(|a| value_at(a, &value_poly, &one).expect("denominator 1"))
                .collect();
            let elimination = super::judging::eliminate(e, s);
            Ok(Outcome::Finite(CriticalAnalysis {
                generators: gens,
                rur,
                value_poly,
                values,
                judging,
                elimination,
            }))
        }
        None => Ok(Outcome::Curves(level_sets(e, s, &gens)?)),
    }
}

/// D(u) as the generator of `(I + (S − u)) ∩ Q[u]`.
fn elimination_ideal_values(gens: &[QMPoly], s: &QMPoly) -> Result<ZPoly, Error> {
    let slots = [X, Y, Z, U];
    let ord = MonoOrder::Elim(3);
    let mut input: Vec<GPoly> = gens
        .iter()
        .filter(|g| !g.is_zero())
        .map(|g| GPoly::from_mpoly(g, &slots, ord))
        .collect();
    let su = s - &MPoly::var(U);
    input.push(GPoly::from_mpoly(&su, &slots, ord));
    let gb = groebner(input, 4, ord);
    let mut d = ZPoly::zero();
    for g in gb.eliminated(3) {
        let p = g.to_mpoly(&slots).to_univariate(U).unwrap_or_else(QPoly::zero);
        let (z, _) = ZPoly::from_q(&p);
        d = if d.is_zero() { z } else { d.gcd(&z) };
    }
    if d.degree().unwrap_or(0) == 0 {
        return Err(Error::Internal(
            "the critical values are not finite (elimination ideal is zero)".into(),
        ));
    }
    Ok(d.squarefree_part())
}

/// Does `E ∩ {S = q}` have a real point?  (q must not be a critical value.)
fn level_has_real_point(e: &Ellipsoid, s: &QMPoly, q: &Q) -> Result<Option<(Rur, [Q; 3])>, Error> {
    let cross = cross_gradients(s, &e.poly);
    let sq = s - &MPoly::constant(q.clone());
    for l in [[1i64, 2, 3], [3, -1, 2], [2, 5, -3], [7, 3, 11], [-5, 13, 4]] {
        let det = &(&cross[0].scale(&qi(l[0])) + &cross[1].scale(&qi(l[1]))) + &cross[2].scale(&qi(l[2]));
        if let Some(rur) = solve_zero_dim(&[e.poly.clone(), sq.clone(), det], &[])? {
            return Ok(Some((rur, [qi(l[0]), qi(l[1]), qi(l[2])])));
        }
    }
    Ok(None)
}

fn level_sets(e: &Ellipsoid, s: &QMPoly, gens: &[QMPoly]) -> Result<LevelSetAnalysis, Error> {
    let judging = elimination_ideal_values(gens, s)?;
    let mut roots = RealAlg::roots_of(&judging);
    // separate the isolating intervals so that rationals fit between roots
    for i in 0..roots.len().saturating_sub(1) {
        loop {
            let (_, hi) = roots[i].interval();
            let (lo, _) = roots[i + 1].interval();
            if hi < lo || roots[i].as_rational().is_some() || roots[i + 1].as_rational().is_some() {
                break;
            }
            roots[i].bisect();
            roots[i + 1].bisect();
        }
    }
    // one rational test level in each gap
    let mut tests: Vec<Q> = Vec::new();
    let k = roots.len();
    for j in 0..=k {
        let lo = if j == 0 { None } else { Some(roots[j - 1].interval().1) };
        let hi = if j == k { None } else { Some(roots[j].interval().0) };
        let q = match (lo, hi) {
            (None, None) => Q::zero(),
            (None, Some(h)) => h - Q::one(),
            (Some(l), None) => l + Q::one(),
            (Some(l), Some(h)) => {
                if l < h {
                    simplest_rational_in(&l, &h)
                } else {
                    l
                }
            }
        };
        tests.push(q);
    }
    let mut levels = Vec::new();
    let mut form = [qi(1), qi(2), qi(3)];
    for q in &tests {
        match level_has_real_point(e, s, q)? {
            Some((rur, f)) => {
                form = f;
                levels.push((q.clone(), !rur.real_roots.is_empty()));
            }
            None => {
                return Err(Error::Internal(
                    "level curve analysis did not reach a finite system".into(),
                ));
            }
        }
    }
    let nonempty: Vec<usize> = (0..levels.len()).filter(|&j| levels[j].1).collect();
    let attained = match (nonempty.first(), nonempty.last()) {
        (Some(&a), Some(&b)) if a >= 1 && b < k => vec![roots[a - 1].clone(), roots[b].clone()],
        (Some(_), Some(_)) => {
            return Err(Error::Internal(
                "a level beyond all critical values has real points".into(),
            ));
        }
        _ => {
            // S is constant on E: its value at any point of E
            let c = e.center.clone();
            let mut p = c.clone();
            p[0] += Q::one();
            let w = super::witness::witness_at(e, s, &p).or_else(|| super::witness::witness_at(e, s, &c));
            match w.and_then(|w| if w.value.is_rational() { Some(w.value.a) } else { None }) {
                Some(v) => vec![RealAlg::Rational(v)],
                None => {
                    return Err(Error::Internal(
                        "S appears constant on E but its value is not rational".into(),
                    ));
                }
            }
        }
    };
    Ok(LevelSetAnalysis {
        judging,
        levels,
        attained,
        form,
    })
}

impl LevelSetAnalysis {
    /// A witness with S of sign `want`, from a level curve at a rational
    /// level of that sign strictly between ν and μ.
    pub fn witness(&self, value: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        let (nu, mu) = (self.attained.first()?, self.attained.last()?);
        let _ = value;
        // a rational level q with sign(q) = want and ν < q < μ
        let mut lo = nu.to_rational_approx(64);
        let mut hi = mu.to_rational_approx(64);
        if want < 0 {
            hi = hi.min(Q::zero());
        } else {
            lo = lo.max(Q::zero());
        }
        for _ in 0..64 {
            if lo < hi {
                break;
            }
            lo = nu.to_rational_approx(128);
            hi = mu.to_rational_approx(128);
        }
        if lo >= hi {
            return None;
        }
        let q = simplest_rational_in(&lo, &hi);
        if q.is_zero() || nu.cmp_rational(&q) != Ordering::Less || mu.cmp_rational(&q) != Ordering::Greater {
            return None;
        }
        let (rur, _) = level_has_real_point(e, s, &q).ok()??;
        if rur.real_roots.is_empty() {
            return None;
        }
        let approx = |bits: u32| Some(rur.approx_point(0, bits));
        find_witness(e, s, want, &approx)
    }
}
