//! The tangent point method (paper 004): does an ellipsoid E meet an
//! algebraic surface S, touch it, or stay on one side — decided exactly,
//! with a certificate.
//!
//! Key idea (SPEC §3): with ν = min and μ = max of S on E, E and S
//! intersect iff ν ≤ 0 ≤ μ, touch iff ν = 0 or μ = 0.  ν and μ are real
//! critical values of S on E, computed exactly as real algebraic numbers:
//!
//! * deg S ≤ 2: the λ-parametrisation ([`quadric`]), exact and complete,
//!   including the singular multipliers where `det(A_S − λA_E) = 0`;
//! * deg S ≥ 3, separable S (`f(x) + g(y) + h(z)` with one coordinate not
//!   proportional to E's square) against an axis-parallel E: the Lagrange
//!   system splits into univariate branches ([`separable`]);
//! * deg S ≥ 3 otherwise: the critical points as the zero set of
//!   `E = 0, ∇S × ∇E = 0` (no λ), solved by a Gröbner basis and a rational
//!   univariate representation ([`critical`]); real critical points are
//!   exactly the real roots of the RUR's univariate polynomial.
//!
//! The judging polynomial D(u) is reported too (the paper's object), and the
//! paper's trap is avoided by construction: a real root of D(u) counts only
//! when a real critical point attains it.  Verdicts come with witnesses:
//! exact points of E (Q(√d) coordinates) where S has the stated sign.

pub mod critical;
pub mod ellipsoid;
pub mod examples;
pub mod judging;
pub mod modular;
pub mod pencil;
pub mod quadric;
pub mod separable;
pub mod witness;

pub use ellipsoid::{Ellipsoid, QuadricForm};
pub use witness::WitnessPoint;

use crate::error::{Error, ErrorKind};
use crate::poly::{QMPoly, ZPoly, parse_poly};
use crate::roots::RealAlg;
use std::cmp::Ordering;

/// The overall answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// S takes both signs on E (ν < 0 < μ).
    Intersecting,
    /// They meet without crossing (ν = 0 or μ = 0).
    Touching,
    /// S has one strict sign on E.
    Separated,
    /// No certificate could be produced (never a guess).
    Undecided,
}

impl Verdict {
    /// The SPEC spelling.
    pub fn as_str(&self) -> &'static str {
        match self {
            Verdict::Intersecting => "intersecting",
            Verdict::Touching => "touching",
            Verdict::Separated => "separated",
            Verdict::Undecided => "undecided",
        }
    }
}

/// Where E lies relative to a closed surface S (an ellipsoid).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Containment {
    /// E is inside the solid bounded by S.
    EInsideS,
    /// S is inside the solid bounded by E.
    SInsideE,
    /// The two solids are disjoint.
    Apart,
}

impl Containment {
    /// The SPEC spelling.
    pub fn as_str(&self) -> &'static str {
        match self {
            Containment::EInsideS => "E-inside-S",
            Containment::SInsideE => "S-inside-E",
            Containment::Apart => "apart",
        }
    }
}

/// How the critical values were obtained.
#[derive(Clone, Debug)]
pub enum Method {
    /// deg S ≤ 2, generic case: the pencil discriminant.
    Pencil(pencil::PencilAnalysis),
    /// deg S ≤ 2: the complete λ-parametrisation.
    Lambda(quadric::LambdaAnalysis),
    /// deg S ≥ 3, S separable with one general coordinate against an
    /// axis-parallel E: branch-wise univariate elimination.
    Separable(separable::SeparableAnalysis),
    /// deg S ≥ 3 with a finite critical set.
    CriticalIdeal(critical::CriticalAnalysis),
    /// deg S ≥ 3 in general position: the verified multi-modular RUR with
    /// S as separating element (D(u) is its polynomial).
    ModularRur(modular::ModularAnalysis),
    /// deg S ≥ 3 with curves of critical points (symmetric inputs).
    LevelSets(critical::LevelSetAnalysis),
    /// S is a non-zero constant.
    Constant,
}

/// The certificate of a verdict.
#[derive(Clone, Debug)]
pub struct Certificate {
    /// The distinct critical values attained by real points, increasing.
    pub critical_values: Vec<RealAlg>,
    /// Real roots of D(u) that no real critical point attains (values at
    /// non-real critical points: the paper's trap).
    pub nonreal_point_values: Vec<RealAlg>,
    /// A point of E with S < 0.
    pub negative_witness: Option<WitnessPoint>,
    /// A point of E with S > 0.
    pub positive_witness: Option<WitnessPoint>,
    /// The computation behind the values.
    pub method: Method,
    /// Remarks (e.g. "S vanishes on all of E").
    pub notes: Vec<String>,
}

/// The full answer of `quadsect tangent`.
#[derive(Clone, Debug)]
pub struct TangentReport {
    /// E as validated (oriented with E < 0 inside).
    pub ellipsoid: QMPoly,
    /// S as given.
    pub surface: QMPoly,
    /// The verdict.
    pub verdict: Verdict,
    /// ν ≤ 0 ≤ μ.
    pub intersect: Option<bool>,
    /// ν = 0 or μ = 0.
    pub touching: Option<bool>,
    /// The sign of S on E when it does not change sign (+1 / -1).
    pub side: Option<i32>,
    /// Filled when S is an ellipsoid and they do not intersect.
    pub containment: Option<Containment>,
    /// ν, exactly.
    pub min: Option<RealAlg>,
    /// μ, exactly.
    pub max: Option<RealAlg>,
    /// The judging polynomial D(u) (square-free, primitive).
    pub judging_poly: ZPoly,
    /// Why the verdict holds.
    pub certificate: Certificate,
    /// Why no verdict could be given (only for `Undecided`).
    pub reason: Option<String>,
}

/// Decides E against S given as text.
///
/// ```
/// let r = quadsect::tangent::decide_str(
///     "x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1").unwrap();
/// assert_eq!(r.verdict, quadsect::tangent::Verdict::Separated);
/// assert_eq!(quadsect::number::fmt_q(r.min.unwrap().as_rational().unwrap()), "7/9");
/// ```
pub fn decide_str(ellipsoid: &str, surface: &str) -> Result<TangentReport, Error> {
    let e = parse_poly(ellipsoid).map_err(|x| Error::from(x).context("in --ellipsoid"))?;
    let s = parse_poly(surface).map_err(|x| Error::from(x).context("in --surface"))?;
    decide(&e, &s)
}

/// Decides E against S.
pub fn decide(ellipsoid: &QMPoly, surface: &QMPoly) -> Result<TangentReport, Error> {
    let e = Ellipsoid::new(ellipsoid).map_err(|x| x.context("in --ellipsoid"))?;
    if surface.vars().iter().any(|&v| v > 2) {
        return Err(Error::new(
            ErrorKind::Input,
            "in --surface: the surface must be a polynomial in x, y, z only",
        ));
    }
    if surface.is_zero() {
        return Err(Error::new(
            ErrorKind::Input,
            "in --surface: the zero polynomial is not a surface (every point satisfies S = 0)",
        ));
    }
    let deg = surface.total_degree().unwrap_or(0);
    // deg S ≤ 2: the pencil discriminant decides generic pairs; the others
    // go to the separable route when it applies, else the λ-parametrisation
    let quadric_form = if deg == 1 || deg == 2 {
        Some(
            QuadricForm::from_poly(surface)
                .ok_or_else(|| Error::internal("quadric form of a degree-2 surface"))?,
        )
    } else {
        None
    };
    if let Some(form) = &quadric_form
        && let Some(pa) = pencil::analyze(&e, form).map(|p| p.with_extremes())
    {
        let (vals, j) = (pa.values.clone(), pa.judging.clone());
        return Ok(finish(
            &e,
            surface,
            vals,
            vec![],
            j,
            Method::Pencil(pa),
            WitnessFinder::Pencil,
        ));
    }
    let (values, nonreal, judging, method, witness_fn): (
        Vec<RealAlg>,
        Vec<RealAlg>,
        ZPoly,
        Method,
        WitnessFinder,
    ) = if deg == 0 {
        let c = surface.constant_term();
        (
            vec![RealAlg::Rational(c.clone())],
            vec![],
            RealAlg::Rational(c).poly(),
            Method::Constant,
            WitnessFinder::None,
        )
    } else if let Some(sa) = separable::analyze(&e, surface) {
        let (vals, nonreal) = split_values(&sa.real_values(), &sa.judging);
        let j = sa.judging.clone();
        (
            vals,
            nonreal,
            j,
            Method::Separable(sa),
            WitnessFinder::Separable,
        )
    } else if let Some(form) = &quadric_form {
        let an = quadric::analyze(&e, form);
        let real: Vec<RealAlg> = an
            .critical
            .iter()
            .filter(|c| c.real)
            .map(|c| c.value.clone())
            .collect();
        let (vals, nonreal) = split_values(&real, &an.judging);
        let j = an.judging.clone();
        (vals, nonreal, j, Method::Lambda(an), WitnessFinder::Lambda)
    } else if let Ok(an) = modular::analyze(&e, surface) {
        let (vals, nonreal) = split_values(&an.real_values(), &an.judging);
        let j = an.judging.clone();
        (
            vals,
            nonreal,
            j,
            Method::ModularRur(an),
            WitnessFinder::Modular,
        )
    } else {
        let outcome = match critical::analyze(&e, surface) {
            Ok(o) => o,
            Err(err) if err.kind() == ErrorKind::Internal => {
                return Ok(undecided(&e, surface, err.message().to_string()));
            }
            Err(other) => return Err(other),
        };
        match outcome {
            critical::Outcome::Finite(an) => {
                let real: Vec<RealAlg> = an.real_values();
                let (vals, nonreal) = split_values(&real, &an.judging);
                let j = an.judging.clone();
                (
                    vals,
                    nonreal,
                    j,
                    Method::CriticalIdeal(an),
                    WitnessFinder::Critical,
                )
            }
            critical::Outcome::Curves(ls) => {
                let j = ls.judging.clone();
                let vals = ls.attained.clone();
                let (_, nonreal) = split_values(&vals, &j);
                (
                    vals,
                    nonreal,
                    j,
                    Method::LevelSets(ls),
                    WitnessFinder::Level,
                )
            }
        }
    };
    Ok(finish(
        &e, surface, values, nonreal, judging, method, witness_fn,
    ))
}

/// The answer when no certificate could be produced (never a guess).
fn undecided(e: &Ellipsoid, surface: &QMPoly, why: String) -> TangentReport {
    TangentReport {
        ellipsoid: e.poly.clone(),
        surface: surface.clone(),
        verdict: Verdict::Undecided,
        intersect: None,
        touching: None,
        side: None,
        containment: None,
        min: None,
        max: None,
        judging_poly: ZPoly::constant(1.into()),
        certificate: Certificate {
            critical_values: vec![],
            nonreal_point_values: vec![],
            negative_witness: None,
            positive_witness: None,
            method: Method::Constant,
            notes: vec![],
        },
        reason: Some(why),
    }
}

#[derive(Clone, Copy, Debug)]
enum WitnessFinder {
    None,
    Pencil,
    Lambda,
    Separable,
    Critical,
    Modular,
    Level,
}

/// Sorts and deduplicates the attained values, and lists the real roots of
/// D(u) that are not attained.
fn split_values(real: &[RealAlg], judging: &ZPoly) -> (Vec<RealAlg>, Vec<RealAlg>) {
    let mut vals: Vec<RealAlg> = Vec::new();
    for v in real {
        if !vals.iter().any(|w| w.cmp_exact(v) == Ordering::Equal) {
            vals.push(v.clone());
        }
    }
    vals.sort_by(|a, b| a.cmp_exact(b));
    let nonreal = RealAlg::roots_of(judging)
        .into_iter()
        .filter(|r| !vals.iter().any(|v| v.cmp_exact(r) == Ordering::Equal))
        .map(|r| r.simplify())
        .collect();
    (vals, nonreal)
}

#[allow(clippy::too_many_arguments)]
fn finish(
    e: &Ellipsoid,
    surface: &QMPoly,
    values: Vec<RealAlg>,
    nonreal: Vec<RealAlg>,
    judging: ZPoly,
    method: Method,
    wf: WitnessFinder,
) -> TangentReport {
    let mut notes = Vec::new();
    if matches!(method, Method::LevelSets(_)) {
        notes.push("curves of critical points: ν and μ are exact; critical values strictly between them are not classified".into());
    }
    if let Method::Separable(sa) = &method
        && sa.has_curves()
    {
        notes.push("curves of critical points on a branch with two free coordinates; every critical value is exact".into());
    }
    let (min, max) = match (values.first(), values.last()) {
        (Some(a), Some(b)) => (a.simplify(), b.simplify()),
        _ => {
            return undecided(
                e,
                surface,
                "no real critical value was found (internal inconsistency)".into(),
            );
        }
    };
    let sn = min.sign();
    let sm = max.sign();
    let (verdict, intersect, touching, side) = if sn > 0 {
        (Verdict::Separated, false, false, Some(1))
    } else if sm < 0 {
        (Verdict::Separated, false, false, Some(-1))
    } else if sn == 0 && sm == 0 {
        notes.push("S vanishes on all of E: E lies on the surface S".into());
        (Verdict::Touching, true, true, None)
    } else if sn == 0 {
        (Verdict::Touching, true, true, Some(1))
    } else if sm == 0 {
        (Verdict::Touching, true, true, Some(-1))
    } else {
        (Verdict::Intersecting, true, false, None)
    };
    // witnesses at the extreme critical points
    let (mut negw, mut posw) = (None, None);
    if sn < 0 {
        negw = witness_for(&method, wf, e, surface, &min, -1);
    }
    if sm > 0 {
        posw = witness_for(&method, wf, e, surface, &max, 1);
    }
    if verdict == Verdict::Separated && negw.is_none() && posw.is_none() {
        // one point showing the side
        let target = if side == Some(1) { &min } else { &max };
        let w = witness_for(&method, wf, e, surface, target, side.unwrap_or(1));
        if side == Some(1) {
            posw = w;
        } else {
            negw = w;
        }
    }
    let containment = if !intersect {
        containment_of(e, surface, side.unwrap_or(0))
    } else {
        None
    };
    TangentReport {
        ellipsoid: e.poly.clone(),
        surface: surface.clone(),
        verdict,
        intersect: Some(intersect),
        touching: Some(touching),
        side,
        containment,
        min: Some(min),
        max: Some(max),
        judging_poly: judging,
        certificate: Certificate {
            critical_values: values,
            nonreal_point_values: nonreal,
            negative_witness: negw,
            positive_witness: posw,
            method,
            notes,
        },
        reason: None,
    }
}

fn witness_for(
    method: &Method,
    wf: WitnessFinder,
    e: &Ellipsoid,
    s: &QMPoly,
    value: &RealAlg,
    want: i32,
) -> Option<WitnessPoint> {
    match (method, wf) {
        (Method::Lambda(an), WitnessFinder::Lambda) => {
            let i = an
                .critical
                .iter()
                .position(|c| c.real && c.value.cmp_exact(value) == Ordering::Equal)?;
            an.witness(i, e, s, want)
        }
        (Method::Pencil(an), WitnessFinder::Pencil) => an.witness(e, s, want),
        (Method::Separable(an), WitnessFinder::Separable) => an.witness(value, e, s, want),
        (Method::CriticalIdeal(an), WitnessFinder::Critical) => an.witness(value, e, s, want),
        (Method::ModularRur(an), WitnessFinder::Modular) => an.witness(value, e, s, want),
        (Method::LevelSets(ls), WitnessFinder::Level) => ls.witness(value, e, s, want),
        (Method::Constant, _) => {
            let c = e.center.clone();
            let mut p = c.clone();
            p[0] += crate::number::qi(1);
            witness::witness_at(e, s, &p).or_else(|| witness::witness_at(e, s, &c))
        }
        _ => None,
    }
}

/// Containment when S is an ellipsoid and does not meet E.
fn containment_of(e: &Ellipsoid, s: &QMPoly, side: i32) -> Option<Containment> {
    use ellipsoid::{IntEllipsoid, common_denominator, sign_at_int};
    let form = QuadricForm::from_poly(s)?;
    let se = IntEllipsoid::of(&form.int_matrix(&common_denominator(&[&form]))).ok()?;
    // S oriented negative inside: the sign of the oriented S on E
    let oriented = if se.negated { -side } else { side };
    if oriented < 0 {
        return Some(Containment::EInsideS);
    }
    // S's centre inside E (in integers: no rational normalisation)
    let em = e.form.int_matrix(&common_denominator(&[&e.form]));
    if sign_at_int(&em, &se.numer, &se.det) < 0 {
        Some(Containment::SInsideE)
    } else {
        Some(Containment::Apart)
    }
}
