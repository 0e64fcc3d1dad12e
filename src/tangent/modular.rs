//! S of degree ≥ 3, general position: the critical points of S on E by the
//! multi-modular route ([`crate::roots::modrur`]) with S itself as the
//! separating element.
//!
//! The critical points are the zeros of `E = 0, ∇S × ∇E = 0`
//! ([`super::critical`]).  When S takes distinct values at distinct
//! critical points (general position), the rational univariate
//! representation with respect to S has `f = D(u)`: its roots are exactly
//! the critical values, each from one critical point, and a critical point
//! is real iff its value is real (a non-real point and its conjugate would
//! share a real value).  So the real critical values are the real roots of
//! D(u), and no root of D(u) comes from a non-real point.  The RUR is
//! verified exactly (soundness) and proven complete by the counting
//! certificate; symmetric inputs (equal values, curves, multiple points)
//! are declined and go to the exact route.

use super::critical::cross_gradients;
use super::ellipsoid::Ellipsoid;
use super::witness::{WitnessPoint, find_witness};
use crate::poly::QMPoly;
use crate::roots::RealAlg;
use crate::roots::modrur::{Declined, ModularRur, solve_modular};
use std::cmp::Ordering;

/// The largest number of primes tried before the route gives up.
pub const MAX_PRIMES: usize = 4000;

/// The verified critical points of S on E with S as separating element.
#[derive(Clone, Debug)]
pub struct ModularAnalysis {
    /// The generators `E, (∇S × ∇E)₁, ₂, ₃`.
    pub generators: Vec<QMPoly>,
    /// The verified RUR: `rur.f` is D(u).
    pub rur: ModularRur,
}

impl ModularAnalysis {
    /// The real critical values, increasing: the real roots of D(u).
    pub fn real_values(&self) -> Vec<RealAlg> {
        self.rur.real_roots.clone()
    }

    /// A witness near the real critical point whose value is `value`.
    pub fn witness(
        &self,
        value: &RealAlg,
        e: &Ellipsoid,
        s: &QMPoly,
        want: i32,
    ) -> Option<WitnessPoint> {
        let i = self
            .rur
            .real_roots
            .iter()
            .position(|v| v.cmp_exact(value) == Ordering::Equal)?;
        let approx = |bits: u32| self.rur.approx_point(i, bits);
        find_witness(e, s, want, false, &approx)
    }
}

/// The modular analysis, or why it does not apply (the caller then uses the
/// exact route of [`super::critical`]).
pub fn analyze(e: &Ellipsoid, s: &QMPoly) -> Result<ModularAnalysis, Declined> {
    let cross = cross_gradients(s, &e.poly);
    let mut gens = vec![e.poly.clone()];
    gens.extend(cross.iter().cloned());
    let rur = solve_modular(&gens, s, MAX_PRIMES)?;
    if rur.points() == 0 {
        return Err(Declined("no critical point".into()));
    }
    Ok(ModularAnalysis {
        generators: gens,
        rur,
    })
}
