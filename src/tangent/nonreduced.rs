//! S with a repeated factor (issue 35): `S = c·∏ Tᵢ^kᵢ` with the `Tᵢ`
//! square-free and pairwise coprime ([`crate::poly::sqfree`]), some
//! `kᵢ ≥ 2`.  Then every point of E on `Tᵢ = 0` (`kᵢ ≥ 2`) is a critical
//! point of S: the system `E = 0, ∇S × ∇E = 0` is not finite, and the
//! general routes would fall back on level sets.  S is decided from its
//! factors instead.
//!
//! * **One factor**, `S = c·T^k`: the critical points of S are the points of
//!   E on T = 0 (value 0) and the critical points of T (value `c·v^k` where
//!   T = v).  T is decided on its own (any route, its own certificate); E is
//!   connected, so T takes on E exactly the values of `[ν_T, μ_T]` and S
//!   those of `φ([ν_T, μ_T])`, `φ(v) = c·v^k`.  The critical values of S are
//!   `φ(v)` over T's and 0 when `ν_T ≤ 0 ≤ μ_T`; D(u) is the square-free
//!   part of `Res_v(D_T(v), u − c·v^k)`, times u when 0 is attained.
//! * **Several factors**: off `P = ∏ Tᵢ = 0`, `∇S = c·∏ Tᵢ^(kᵢ−1)·G` with
//!   `G = Σᵢ kᵢ (∏_{j≠i} Tⱼ) ∇Tᵢ` (the gradient of `log|S|` times P), so the
//!   critical points of S on E are the points of E on `Tᵢ = 0` with
//!   `kᵢ ≥ 2` (value 0) and the zeros of `E = 0, G × ∇E = 0` (a system of
//!   the size of a square-free surface of degree deg P, finite in general:
//!   G has degree deg P − 1).  The second set is solved by the general
//!   routes with S's values ([`super::critical_routes`]); whether E meets a
//!   repeated factor is decided by the tangent point method on that factor.
//!
//! The witnesses are points of E where S has the stated sign, exactly: near
//! a real zero of the G-system (several factors), or T's own witnesses,
//! where S = c·T^k has the sign of c·(sign T)^k (one factor).  A value 0
//! comes with a proven real point of E on a repeated factor (the factor's
//! own certificate: a critical point of value 0, or points of E on both
//! sides of it, which E, being connected, joins through it), and every such
//! point is a critical point of S.

use super::critical::CriticalSystem;
use super::ellipsoid::Ellipsoid;
use super::witness::WitnessPoint;
use super::witness::WitnessSearch;
use super::{
    Analysis, Routed, TangentReport, Verdict, WitnessFinder, classify, critical_routes,
    decide_validated, finish, undecided, witness_for,
};
use crate::error::Error;
use crate::number::Q;
use crate::poly::sqfree::SquareFree;
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::{RealAlg, value_polynomial, values_with_unsimplified};
use num_traits::{One, Zero};

/// How S with repeated factors was decided.
#[derive(Clone, Debug)]
pub struct NonReducedAnalysis {
    /// The constant c of `S = c·∏ Tᵢ^kᵢ`.
    pub constant: Q,
    /// The factors `(Tᵢ, kᵢ)` (primitive, square-free, pairwise coprime).
    pub factors: Vec<(QMPoly, u32)>,
    /// E against factors decided on their own (index into `factors`, the
    /// report): the single factor T of `S = c·T^k`; with several factors,
    /// each factor of multiplicity ≥ 2 (does E meet it?), or a factor that
    /// is a multiple of E (then S = 0 on all of E).
    pub factor_reports: Vec<(usize, TangentReport)>,
    /// With several factors (and none a multiple of E): G and the
    /// analysis of `E = 0, G × ∇E = 0`.
    pub field: Option<FieldAnalysis>,
}

/// The critical points of S off its zero set, from `E = 0, G × ∇E = 0`.
#[derive(Clone, Debug)]
pub struct FieldAnalysis {
    /// `G = Σᵢ kᵢ (∏_{j≠i} Tⱼ) ∇Tᵢ`.
    pub field: [QMPoly; 3],
    /// The route that solved the system (its values are those of S).
    pub analysis: Analysis,
    pub(crate) finder: WitnessFinder,
}

impl NonReducedAnalysis {
    /// `c·(T₁)^k₁·…` as printed.
    pub fn product(&self) -> String {
        product_string(&self.constant, &self.factors)
    }

    /// The analysis that found the critical points: the G-system's, or the
    /// single factor's.
    pub(crate) fn inner(&self) -> Option<&Analysis> {
        match &self.field {
            Some(f) => Some(&f.analysis),
            None if self.factors.len() == 1 => self
                .factor_reports
                .first()
                .map(|(_, r)| &r.certificate.method),
            None => None,
        }
    }
}

impl WitnessSearch for NonReducedAnalysis {
    /// A witness with S of sign `want`, near the real critical point of
    /// value `v` (G-system), or among the single factor's witnesses.
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        if let Some(f) = &self.field {
            return witness_for(&f.analysis, f.finder, e, s, v, want);
        }
        self.factor_reports
            .iter()
            .flat_map(|(_, r)| {
                [
                    r.certificate.negative_witness.as_ref(),
                    r.certificate.positive_witness.as_ref(),
                ]
            })
            .flatten()
            .find_map(|w| {
                let v = crate::geom::eval_qsqrt(s, &w.coords);
                let sign = v.signum();
                (sign == want).then(|| WitnessPoint {
                    coords: w.coords.clone(),
                    value: v,
                    sign,
                })
            })
    }
}

/// `c·(T₁)^k₁·…` as printed (`c·` left out when c = 1, `-` for c = −1,
/// `^1` left out).
pub(crate) fn product_string(c: &Q, factors: &[(QMPoly, u32)]) -> String {
    let parts: Vec<String> = factors
        .iter()
        .map(|(t, k)| {
            let t = format!("({})", t.to_string_canonical());
            if *k == 1 { t } else { format!("{t}^{k}") }
        })
        .collect();
    let head = if c.is_one() {
        String::new()
    } else if (-c).is_one() {
        "-".to_string()
    } else {
        format!("{}·", crate::number::fmt_q(c))
    };
    format!("{head}{}", parts.join("·"))
}

/// `p·(u − v)`, square-free.
fn with_root(p: &ZPoly, v: &Q) -> ZPoly {
    if p.to_q().eval_rational(v).is_zero() {
        return p.clone();
    }
    let lin = QPoly::new(vec![-v.clone(), Q::one()]);
    ZPoly::from_q(&(&p.to_q() * &lin)).0.squarefree_part()
}

/// True when `t` is a rational multiple of E's polynomial.
fn is_multiple_of(t: &QMPoly, e: &QMPoly) -> bool {
    match (t.leading(), e.leading()) {
        (Some((et, ct)), Some((ee, ce))) => et == ee && t.scale(ce) == e.scale(ct),
        _ => false,
    }
}

/// Decides E against S from its square-free decomposition (`sf` has a
/// repeated factor).
pub(crate) fn decide(e: &Ellipsoid, s: &QMPoly, sf: &SquareFree) -> Result<TangentReport, Error> {
    let factors: Vec<(QMPoly, u32)> = sf.factors.iter().map(|(t, k)| (t.to_q(), *k)).collect();
    let c = sf.constant.clone();
    let printed = product_string(&c, &factors);
    let (mut report, note) = if factors.len() == 1 {
        let note = format!(
            "S = {printed}: decided from its square-free part T = {} (S = 0 where T = 0, and S = {}·v^{} where T = v: the extremes of S on E follow from those of T)",
            factors[0].0.to_string_canonical(),
            crate::number::fmt_q(&c),
            factors[0].1
        );
        (power(e, s, c, factors)?, note)
    } else {
        let note = format!(
            "S = {printed}: decided from its square-free part, the product of the factors Tᵢ (square-free, pairwise coprime; S = 0 where a factor vanishes, and elsewhere the critical points of S on E are the zeros of E = 0, G × ∇E = 0 with G = Σ kᵢ·(∏_(j≠i) Tⱼ)·∇Tᵢ)"
        );
        (several(e, s, c, factors)?, note)
    };
    if report.verdict != Verdict::Undecided {
        report.certificate.notes.insert(0, note);
    }
    Ok(report)
}

/// The reason of an undecided factor, or `None` when it was decided.
fn undecided_factor(t: &QMPoly, r: &TangentReport) -> Option<String> {
    (r.verdict == Verdict::Undecided).then(|| {
        let why = r.reason.as_ref().map(|u| u.to_string()).unwrap_or_default();
        format!("the factor {} of S: {why}", t.to_string_canonical())
    })
}

/// `S = c·T^k`: from T's report.
fn power(
    e: &Ellipsoid,
    s: &QMPoly,
    c: Q,
    factors: Vec<(QMPoly, u32)>,
) -> Result<TangentReport, Error> {
    let (t, k) = &factors[0];
    let rt = decide_validated(e, t, true)?;
    if let Some(why) = undecided_factor(t, &rt) {
        return Ok(undecided(e, s, why));
    }
    // φ(v) = c·v^k on T's critical values; 0 where T = 0 meets E
    let num = QPoly::monomial(c.clone(), *k as usize);
    let one = QPoly::constant(Q::one());
    let mut judging = value_polynomial(&rt.judging_poly, &num, &one);
    // (not simplified: finish simplifies ν and μ, the values it prints)
    let mut values: Vec<RealAlg> = values_with_unsimplified(
        &rt.judging_poly,
        &rt.certificate.critical_values,
        &num,
        &one,
        &judging,
    )
    .into_iter()
    .map(|v| v.expect("the denominator is 1"))
    .collect();
    if rt.intersect == Some(true) {
        values.push(RealAlg::rational(Q::zero()));
        judging = with_root(&judging, &Q::zero());
    }
    let curves = matches!(rt.certificate.method, Analysis::LevelSets(_));
    let (values, nonreal) = classify(&values, &judging, curves);
    let an = NonReducedAnalysis {
        constant: c,
        factors,
        factor_reports: vec![(0, rt)],
        field: None,
    };
    Ok(finish(
        e,
        s,
        values,
        nonreal,
        judging,
        Analysis::NonReduced(Box::new(an)),
        WitnessFinder::NonReduced,
    ))
}

/// `G = Σᵢ kᵢ (∏_{j≠i} Tⱼ) ∇Tᵢ`.
pub fn field_of(factors: &[(QMPoly, u32)]) -> [QMPoly; 3] {
    let mut g: [QMPoly; 3] = std::array::from_fn(|_| QMPoly::zero());
    for (i, (t, k)) in factors.iter().enumerate() {
        crate::budget::check();
        let others = factors.iter().enumerate().filter(|(j, _)| *j != i).fold(
            QMPoly::constant(Q::from_integer((*k).into())),
            |acc, (_, (f, _))| &acc * f,
        );
        let grad = crate::geom::gradient(t);
        for (gi, di) in g.iter_mut().zip(grad.iter()) {
            *gi = &*gi + &(di * &others);
        }
    }
    g
}

/// Several factors: the zeros of `E = 0, G × ∇E = 0`, and 0 when E meets a
/// repeated factor.
fn several(
    e: &Ellipsoid,
    s: &QMPoly,
    c: Q,
    factors: Vec<(QMPoly, u32)>,
) -> Result<TangentReport, Error> {
    // the factors decided on their own: a multiple of E alone (S = 0 on
    // all of E), else each repeated factor (does E meet it?)
    let vanishing = factors.iter().position(|(t, _)| is_multiple_of(t, &e.poly));
    let mut reports = Vec::new();
    for (i, (t, k)) in factors.iter().enumerate() {
        if vanishing.map_or(*k < 2, |j| j != i) {
            continue;
        }
        let r = decide_validated(e, t, true)?;
        if let Some(why) = undecided_factor(t, &r) {
            return Ok(undecided(e, s, why));
        }
        reports.push((i, r));
    }
    if vanishing.is_some() {
        let an = NonReducedAnalysis {
            constant: c,
            factors,
            factor_reports: reports,
            field: None,
        };
        let zero = RealAlg::rational(Q::zero());
        let judging = zero.poly();
        return Ok(finish(
            e,
            s,
            vec![zero],
            vec![],
            judging,
            Analysis::NonReduced(Box::new(an)),
            WitnessFinder::NonReduced,
        ));
    }
    let meets = reports.iter().any(|(_, r)| r.intersect == Some(true));
    let field = field_of(&factors);
    let sys = CriticalSystem {
        minors: crate::geom::vec3::cross(&field, &crate::geom::gradient(&e.poly)),
        gradient: false,
        known_values: if meets { vec![Q::zero()] } else { vec![] },
    };
    let found = match critical_routes(e, s, &sys, true)? {
        Routed::Values(f) => f,
        Routed::Signs(_) => {
            return Err(Error::internal(
                "the critical routes skipped the values they were asked for",
            ));
        }
        Routed::Undecided(why) => return Ok(undecided(e, s, why)),
    };
    let mut values = found.values;
    let mut judging = found.judging;
    if meets {
        values.push(RealAlg::rational(Q::zero()));
        judging = with_root(&judging, &Q::zero());
    }
    let curves = matches!(found.method, Analysis::LevelSets(_));
    let (values, nonreal) = if meets || curves {
        classify(&values, &judging, curves)
    } else {
        (values, found.nonreal)
    };
    let an = NonReducedAnalysis {
        constant: c,
        factors,
        factor_reports: reports,
        field: Some(FieldAnalysis {
            field,
            analysis: found.method,
            finder: found.finder,
        }),
    };
    Ok(finish(
        e,
        s,
        values,
        nonreal,
        judging,
        Analysis::NonReduced(Box::new(an)),
        WitnessFinder::NonReduced,
    ))
}
