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
//!   are exactly `U(α)` over the real roots α of `f` — the trap of contract §3
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
use super::witness::WitnessSearch;
use super::witness::{WitnessPoint, find_witness, witness_at_value};
use crate::error::Error;
use crate::number::{Q, qi};
use crate::poly::mpoly::{MPoly, U, X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::{RealAlg, separate, simplest_rational_in, values_with};
use crate::system::groebner::{GPoly, MonoOrder, groebner};
use crate::system::{GENERIC_FORMS, Rur, solve_zero_dim};
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// The critical points of S on E (finite case).
#[derive(Clone, Debug)]
pub struct CriticalAnalysis {
    /// The generators `E, (∇S × ∇E)₁, ₂, ₃`.
    pub generators: Vec<QMPoly>,
    /// The rational univariate representation of the critical points.
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
    /// Conics of critical points split off before the RUR (their values
    /// are in `judging` and in [`CriticalAnalysis::real_values`]).
    pub conics: Vec<super::modular::CriticalConic>,
}

impl CriticalAnalysis {
    /// The values attained by real critical points.
    pub fn real_values(&self) -> Vec<RealAlg> {
        super::modular::with_conic_values(&self.values, &self.conics)
    }
}

impl WitnessSearch for CriticalAnalysis {
    /// A witness near a real critical point whose value is `v`.
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        if let Some(w) = super::modular::conic_witness(&self.conics, v, want) {
            return Some(w);
        }
        witness_at_value(&self.values, v, e, s, want, &|i, bits| {
            Some(self.rur.approx_point(i, bits))
        })
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
    /// The minors `F × ∇E` of the critical system (for the witnesses'
    /// level curves).
    pub minors: [QMPoly; 3],
}

/// The polynomial system the routes of degree ≥ 3 solve: the critical
/// points of S on E are the zeros of E and of the three minors `F × ∇E` of
/// a vector field F — `F = ∇S` for S as given, or, when S has repeated
/// factors, the field G of [`super::nonreduced`] (∇S divided by a product
/// of powers of the factors; its zeros on E are the critical points off
/// S = 0 and some on it).
#[derive(Clone, Debug)]
pub struct CriticalSystem {
    /// `F × ∇E`.
    pub minors: [QMPoly; 3],
    /// True when `F = ∇S`: the resultant elimination of S's own Lagrange
    /// system is then tried beside the RUR.
    pub gradient: bool,
    /// Critical values of S known without these minors (0 when E meets a
    /// repeated factor of S): D(u) of the level sets has them as roots, so
    /// that no level tested is one of them.
    pub known_values: Vec<Q>,
}

impl CriticalSystem {
    /// The system of S as given: `∇S × ∇E`.
    pub fn of(s: &QMPoly, e: &Ellipsoid) -> CriticalSystem {
        CriticalSystem {
            minors: cross_gradients(s, &e.poly),
            gradient: true,
            known_values: Vec::new(),
        }
    }
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
    crate::geom::vec3::cross(&crate::geom::gradient(s), &crate::geom::gradient(e))
}

/// Runs the critical-point analysis of S on E.
#[cfg(test)]
pub fn analyze(e: &Ellipsoid, s: &QMPoly) -> Result<Outcome, Error> {
    analyze_system(e, s, &CriticalSystem::of(s, e))
}

/// [`analyze`] on a given critical system (the values are those of S).
pub fn analyze_system(e: &Ellipsoid, s: &QMPoly, sys: &CriticalSystem) -> Result<Outcome, Error> {
    let started = std::time::Instant::now();
    let cross = sys.minors.clone();
    let mut all = vec![e.poly.clone()];
    all.extend(cross.iter().cloned());
    // conics of critical points (a monomial dividing the three minors) are
    // split off; the level sets, if needed, work on the whole system
    let (conics, minors) = super::modular::split_conics(&e.poly, s, &cross);
    let mut gens = vec![e.poly.clone()];
    gens.extend(minors);
    match solve_zero_dim(&gens, std::slice::from_ref(s))? {
        Some(rur) => {
            if rur.points == 0 {
                return Err(Error::internal(
                    "no critical point of S on E (impossible on a compact ellipsoid)",
                ));
            }
            let value_poly = rur.extra[0].clone();
            let one = QPoly::constant(Q::one());
            let judging = rur.extra_values[0].clone();
            let values = values_with(&rur.f, &rur.real_roots, &value_poly, &one, &judging)
                .into_iter()
                .map(|v| v.expect("denominator 1"))
                .collect();
            // optional: an elimination too large for the size limits is
            // skipped, like one beyond its own work budget or one taking
            // longer than the critical points took (plus 0.1 s)
            let cap = started.elapsed() + std::time::Duration::from_millis(100);
            let elimination = if sys.gradient {
                crate::budget::run_optional_for(cap, || super::judging::eliminate(e, s)).flatten()
            } else {
                None
            };
            Ok(Outcome::Finite(CriticalAnalysis {
                generators: gens,
                rur,
                value_poly,
                values,
                judging: super::modular::with_conics(judging, &conics),
                elimination,
                conics,
            }))
        }
        None => Ok(Outcome::Curves(level_sets(e, s, &all, sys)?)),
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
        let p = g
            .to_mpoly(&slots)
            .to_univariate(U)
            .unwrap_or_else(QPoly::zero);
        let (z, _) = ZPoly::from_q(&p);
        d = if d.is_zero() { z } else { d.gcd(&z) };
    }
    if d.degree().unwrap_or(0) == 0 {
        return Err(Error::internal(
            "the critical values are not finite (elimination ideal is zero)",
        ));
    }
    Ok(d.squarefree_part())
}

/// Does `E ∩ {S = q}` have a real point?  (q must not be a critical value;
/// `cross` are the minors of the critical system, which off S = 0 vanish
/// exactly where `∇S × ∇E` does.)
fn level_has_real_point(
    e: &Ellipsoid,
    s: &QMPoly,
    cross: &[QMPoly; 3],
    q: &Q,
) -> Result<Option<(Rur, [Q; 3])>, Error> {
    let sq = s - &MPoly::constant(q.clone());
    for l in GENERIC_FORMS {
        crate::budget::check_now();
        let det =
            &(&cross[0].scale(&qi(l[0])) + &cross[1].scale(&qi(l[1]))) + &cross[2].scale(&qi(l[2]));
        if let Some(rur) = solve_zero_dim(&[e.poly.clone(), sq.clone(), det], &[])? {
            return Ok(Some((rur, [qi(l[0]), qi(l[1]), qi(l[2])])));
        }
    }
    Ok(None)
}

fn level_sets(
    e: &Ellipsoid,
    s: &QMPoly,
    gens: &[QMPoly],
    sys: &CriticalSystem,
) -> Result<LevelSetAnalysis, Error> {
    let mut judging = elimination_ideal_values(gens, s)?;
    if !sys.known_values.is_empty() {
        let mut p = judging.to_q();
        for v in &sys.known_values {
            p = &p * &QPoly::new(vec![-v.clone(), Q::one()]);
        }
        judging = ZPoly::from_q(&p).0.squarefree_part();
    }
    let mut roots = RealAlg::roots_of(&judging);
    // separate the isolating intervals so that rationals fit between roots
    separate(&mut roots);
    // one rational test level in each gap
    let mut tests: Vec<Q> = Vec::new();
    let k = roots.len();
    for j in 0..=k {
        let lo = if j == 0 {
            None
        } else {
            Some(roots[j - 1].interval().1)
        };
        let hi = if j == k {
            None
        } else {
            Some(roots[j].interval().0)
        };
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
        crate::budget::check_now();
        match level_has_real_point(e, s, &sys.minors, q)? {
            Some((rur, f)) => {
                form = f;
                levels.push((q.clone(), !rur.real_roots.is_empty()));
            }
            None => {
                return Err(Error::internal(
                    "level curve analysis did not reach a finite system",
                ));
            }
        }
    }
    let nonempty: Vec<usize> = (0..levels.len()).filter(|&j| levels[j].1).collect();
    let attained = match (nonempty.first(), nonempty.last()) {
        (Some(&a), Some(&b)) if a >= 1 && b < k => vec![roots[a - 1].clone(), roots[b].clone()],
        (Some(_), Some(_)) => {
            return Err(Error::internal(
                "a level beyond all critical values has real points",
            ));
        }
        _ => {
            // S is constant on E: its value at any point of E
            let c = e.center.clone();
            let mut p = c.clone();
            p[0] += Q::one();
            let w = super::witness::witness_at(e, s, &p)
                .or_else(|| super::witness::witness_at(e, s, &c));
            match w.and_then(|w| {
                if w.value.is_rational() {
                    Some(w.value.a)
                } else {
                    None
                }
            }) {
                Some(v) => vec![RealAlg::rational(v)],
                None => {
                    return Err(Error::internal(
                        "S appears constant on E but its value is not rational",
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
        minors: sys.minors.clone(),
    })
}

impl WitnessSearch for LevelSetAnalysis {
    /// A witness with S of sign `want`, from a level curve at a rational
    /// level of that sign strictly between ν and μ.
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        let (nu, mu) = (self.attained.first()?, self.attained.last()?);
        let _ = v;
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
        if q.is_zero()
            || nu.cmp_rational(&q) != Ordering::Less
            || mu.cmp_rational(&q) != Ordering::Greater
        {
            return None;
        }
        let (rur, _) = level_has_real_point(e, s, &self.minors, &q).ok()??;
        if rur.real_roots.is_empty() {
            return None;
        }
        let approx = |bits: u32| Some(rur.approx_point(0, bits));
        find_witness(e, s, want, false, &approx)
    }
}
