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
use super::witness::{WitnessPoint, witness_at_value};
use crate::number::{Q, q};
use crate::poly::mpoly::{MPoly, X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::RealAlg;
use crate::roots::modrur::{Declined, ModularRur, solve_modular_implied};
use crate::roots::{value_polynomial, values_with};
use num_traits::{One, Zero};

/// When S alone does not separate the critical points (symmetric inputs),
/// `S + c·ℓ` for these `(ℓ, c)` is tried in turn.
pub const SHIFTS: [([i64; 3], (i64, i64)); 2] = [([1, 2, 3], (1, 3)), ([3, -1, 2], (1, 5))];

/// The largest number of primes tried before the route gives up.
pub const MAX_PRIMES: usize = 4000;

/// The verified critical points of S on E with S as separating element.
#[derive(Clone, Debug)]
pub struct ModularAnalysis {
    /// The generators `E, (∇S × ∇E)₁, ₂, ₃`.
    pub generators: Vec<QMPoly>,
    /// The verified RUR with respect to `h = S + c·ℓ` (`shift = (ℓ, c)`, or
    /// `None` for `h = S`, when `rur.f` is D(u) itself).
    pub rur: ModularRur,
    /// The shift of the separating element.
    pub shift: Option<([Q; 3], Q)>,
    /// `S = value_num(u)/value_den(u)` at the critical point of RUR root u.
    pub value_num: QPoly,
    /// See `value_num`.
    pub value_den: QPoly,
    /// The value of S at each real critical point (order of
    /// `rur.real_roots`).
    pub values: Vec<RealAlg>,
    /// D(u): all critical values (complex points included), square-free.
    pub judging: ZPoly,
}

impl ModularAnalysis {
    /// The values attained by real critical points (with `h = S`: the real
    /// roots of D(u), increasing).
    pub fn real_values(&self) -> Vec<RealAlg> {
        self.values.clone()
    }

    /// A witness near the real critical point whose value is `value`.
    pub fn witness(
        &self,
        value: &RealAlg,
        e: &Ellipsoid,
        s: &QMPoly,
        want: i32,
    ) -> Option<WitnessPoint> {
        witness_at_value(&self.values, value, e, s, want, &|i, bits| {
            self.rur.approx_point(i, bits)
        })
    }
}

/// The modular analysis, or why it does not apply (the caller then uses the
/// exact route of [`super::critical`]).
pub fn analyze(e: &Ellipsoid, s: &QMPoly) -> Result<ModularAnalysis, Declined> {
    let cross = cross_gradients(s, &e.poly);
    let mut gens = vec![e.poly.clone()];
    gens.extend(cross.iter().cloned());
    let form = |l: &[i64; 3]| -> QMPoly {
        &(&MPoly::var(X).scale(&q(l[0], 1)) + &MPoly::var(Y).scale(&q(l[1], 1)))
            + &MPoly::var(Z).scale(&q(l[2], 1))
    };
    let mut hs = vec![s.clone()];
    for (l, (cn, cd)) in SHIFTS {
        hs.push(s + &form(&l).scale(&q(cn, cd)));
    }
    // ∇E · (∇S × ∇E) = 0: where E_x ≠ 0 (resp. E_y, E_z) the first (second,
    // third) minor follows from the other two
    let implied: Vec<(usize, QMPoly)> = [X, Y, Z]
        .iter()
        .enumerate()
        .map(|(j, &v)| (j + 1, e.poly.derivative(v)))
        .collect();
    let rur = solve_modular_implied(&gens, &hs, MAX_PRIMES, &implied)?;
    if rur.points() == 0 {
        return Err(Declined("no critical point".into()));
    }
    let den = rur.denom.to_q();
    if rur.separating == 0 {
        let values = rur.real_roots.clone();
        let judging = rur.f.clone();
        return Ok(ModularAnalysis {
            generators: gens,
            rur,
            shift: None,
            value_num: QPoly::new(vec![Q::zero(), Q::one()]) * &den,
            value_den: den,
            values,
            judging,
        });
    }
    // S(ξ(u)) = u − c·ℓ(ξ(u)) = (u·Φ(u) − c·Σ ℓᵢ Gᵢ(u)) / Φ(u)
    let (l, (cn, cd)) = SHIFTS[rur.separating - 1];
    let c = q(cn, cd);
    let mut lin = QPoly::zero();
    for (k, &lk) in l.iter().enumerate() {
        lin = &lin + &rur.coords[k].to_q().scale(&(&c * q(lk, 1)));
    }
    let num = &(QPoly::new(vec![Q::zero(), Q::one()]) * &den) - &lin;
    let judging = value_polynomial(&rur.f, &num, &den);
    let values = values_with(&rur.f, &rur.real_roots, &num, &den, &judging)
        .into_iter()
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| Declined("the denominator vanishes at a real root".into()))?;
    Ok(ModularAnalysis {
        generators: gens,
        rur,
        shift: Some((l.map(|x| q(x, 1)), c)),
        value_num: num,
        value_den: den,
        values,
        judging,
    })
}
