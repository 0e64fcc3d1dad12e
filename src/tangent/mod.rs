//! The tangent point method (paper 004): does an ellipsoid E meet an
//! algebraic surface S, touch it, or stay on one side — decided exactly,
//! with a certificate.
//!
//! Key idea (contract §3): with ν = min and μ = max of S on E, E and S
//! intersect iff ν ≤ 0 ≤ μ, touch iff ν = 0 or μ = 0.  ν and μ are real
//! critical values of S on E, computed exactly as real algebraic numbers:
//!
//! * deg S ≤ 2: the λ-parametrisation (`quadric.rs`), exact and complete,
//!   including the singular multipliers where `det(A_S − λA_E) = 0`;
//! * deg S ≥ 3, separable S (`f(x) + g(y) + h(z)` with one coordinate not
//!   proportional to E's square) against an axis-parallel E: the Lagrange
//!   system splits into univariate branches (`separable.rs`);
//! * deg S ≥ 3 otherwise: the critical points as the zero set of
//!   `E = 0, ∇S × ∇E = 0` (no λ), solved by a Gröbner basis and a rational
//!   univariate representation (`critical.rs`); real critical points are
//!   exactly the real roots of the RUR's univariate polynomial;
//! * deg S ≥ 3 with a repeated factor (`S = c·∏ Tᵢ^kᵢ`, some kᵢ ≥ 2, which
//!   makes that system positive-dimensional): decided from the square-free
//!   part (`nonreduced.rs`) — a square-free S is recognised first by one
//!   modular image per variable and goes on unchanged.
//!
//! The judging polynomial D(u) is reported too (the paper's object), and the
//! paper's trap is avoided by construction: a real root of D(u) counts only
//! when a real critical point attains it.  Verdicts come with witnesses:
//! exact points of E (Q(√d) coordinates) where S has the stated sign.

pub(crate) mod api;
pub(crate) mod critical;
pub(crate) mod ellipsoid;
pub(crate) mod judging;
pub(crate) mod modular;
pub(crate) mod nonreduced;
pub(crate) mod pencil;
pub(crate) mod quadric;
pub(crate) mod separable;
pub(crate) mod slemma;
pub(crate) mod square_subsystem;
pub(crate) mod witness;

pub(crate) use ellipsoid::Ellipsoid;
pub use witness::WitnessPoint;

pub(crate) use crate::geom::QuadricForm;

use crate::budget::Exhausted;
use crate::error::{Error, ErrorKind};
use crate::poly::{QMPoly, ZPoly};
use crate::roots::RealAlg;
use std::cmp::Ordering;
use witness::WitnessSearch;

pub(crate) use api::{Analysis, TangentOptions, TangentReport, Verdict, decide_with};
pub use api::{Certificate, Containment, Method, Side, Undecided, decide_str, decide_str_in};

/// Decides E against S given as internal polynomials (E is validated).
pub(crate) fn decide_poly(ellipsoid: &QMPoly, surface: &QMPoly) -> Result<TangentReport, Error> {
    let e = Ellipsoid::from_poly(ellipsoid).map_err(|x| x.context("in the ellipsoid"))?;
    decide_validated(&e, surface, true)
}

fn decide_validated(e: &Ellipsoid, surface: &QMPoly, values: bool) -> Result<TangentReport, Error> {
    crate::budget::check_now();
    if surface.vars().iter().any(|&v| v > 2) {
        return Err(Error::new(
            ErrorKind::Input,
            "the surface must be a polynomial in x, y, z only",
        ));
    }
    if surface.is_zero() {
        return Err(Error::new(
            ErrorKind::Input,
            "the zero polynomial is not a surface (every point satisfies S = 0)",
        ));
    }
    let e = e.clone();
    let deg = surface.total_degree().unwrap_or(0);
    // a repeated factor makes the critical set of S positive-dimensional:
    // S is decided from its square-free decomposition (a square-free S,
    // the usual case, is recognised by one modular specialisation per
    // variable and goes on unchanged)
    if deg >= 3
        && let Some(sf) = crate::poly::sqfree::repeated_factors(surface)
    {
        return nonreduced::decide(&e, surface, &sf);
    }
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
            Analysis::Pencil(pa),
            WitnessFinder::Pencil,
        ));
    }
    let (values, nonreal, judging, method, witness_fn): (
        Vec<RealAlg>,
        Vec<RealAlg>,
        ZPoly,
        Analysis,
        WitnessFinder,
    ) = if deg == 0 {
        let c = surface.constant_term();
        (
            vec![RealAlg::rational(c.clone())],
            vec![],
            RealAlg::rational(c).poly(),
            Analysis::Constant,
            WitnessFinder::None,
        )
    } else if let Some(sa) = separable::analyze(&e, surface) {
        let (vals, nonreal) = split_values(&sa.real_values(), &sa.judging);
        let j = sa.judging.clone();
        (
            vals,
            nonreal,
            j,
            Analysis::Separable(sa),
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
        (
            vals,
            nonreal,
            j,
            Analysis::Lambda(an),
            WitnessFinder::Lambda,
        )
    } else {
        match critical_routes(
            &e,
            surface,
            &critical::CriticalSystem::of(surface, &e),
            values,
        )? {
            Routed::Values(f) => (f.values, f.nonreal, f.judging, f.method, f.finder),
            Routed::Signs(an) => return Ok(finish_signs(&e, surface, *an)),
            Routed::Undecided(why) => return Ok(undecided(&e, surface, why)),
        }
    };
    Ok(finish(
        &e, surface, values, nonreal, judging, method, witness_fn,
    ))
}

/// What the routes of degree ≥ 3 found: the attained values, the roots of
/// D(u) that are not attained (see [`classify`]), D(u), the analysis.
pub(crate) struct Found {
    pub(crate) values: Vec<RealAlg>,
    pub(crate) nonreal: Vec<RealAlg>,
    pub(crate) judging: ZPoly,
    pub(crate) method: Analysis,
    pub(crate) finder: WitnessFinder,
}

/// The outcome of [`critical_routes`].
pub(crate) enum Routed {
    /// The critical values.
    Values(Found),
    /// The signs of S at the real critical points only (verdict only).
    Signs(Box<square_subsystem::PoissonAnalysis>),
    /// No certificate (the reason).
    Undecided(String),
}

/// The critical values of S on E from the zeros of E and the minors of
/// `sys` (degree ≥ 3, no special structure): the Poisson route, the
/// multi-modular RUR, then the exact Gröbner route (finite critical set or
/// level sets).
pub(crate) fn critical_routes(
    e: &Ellipsoid,
    surface: &QMPoly,
    sys: &critical::CriticalSystem,
    values: bool,
) -> Result<Routed, Error> {
    if let Ok(an) = square_subsystem::analyze_minors(e, surface, &sys.minors, values) {
        let Some(j) = an.judging.clone() else {
            return Ok(Routed::Signs(Box::new(an)));
        };
        let (vals, nonreal) = if an.separates() {
            (an.real_values(), vec![])
        } else {
            split_values(&an.real_values(), &j)
        };
        return Ok(Routed::Values(Found {
            values: vals,
            nonreal,
            judging: j,
            method: Analysis::Poisson(Box::new(an)),
            finder: WitnessFinder::Poisson,
        }));
    }
    if let Ok(an) = modular::analyze(e, surface, &sys.minors) {
        let (vals, nonreal) = split_values(&an.real_values(), &an.judging);
        let j = an.judging.clone();
        return Ok(Routed::Values(Found {
            values: vals,
            nonreal,
            judging: j,
            method: Analysis::ModularRur(an),
            finder: WitnessFinder::Modular,
        }));
    }
    let outcome = match critical::analyze_system(e, surface, sys) {
        Ok(o) => o,
        Err(err) if err.kind() == ErrorKind::Internal => {
            return Ok(Routed::Undecided(err.message().to_string()));
        }
        Err(other) => return Err(other),
    };
    Ok(Routed::Values(match outcome {
        critical::Outcome::Finite(an) => {
            let real: Vec<RealAlg> = an.real_values();
            let (vals, nonreal) = split_values(&real, &an.judging);
            let j = an.judging.clone();
            Found {
                values: vals,
                nonreal,
                judging: j,
                method: Analysis::CriticalIdeal(an),
                finder: WitnessFinder::Critical,
            }
        }
        critical::Outcome::Curves(ls) => {
            let j = ls.judging.clone();
            let (vals, nonreal) = classify(&ls.attained, &j, true);
            Found {
                values: vals,
                nonreal,
                judging: j,
                method: Analysis::LevelSets(ls),
                finder: WitnessFinder::Level,
            }
        }
    }))
}

/// [`split_values`], and with `curves` (only ν and μ are known among the
/// attained values) only the roots of D(u) outside [ν, μ] count as known
/// not to be attained at real points; those between are unclassified
/// (named in a note by `finish`).
pub(crate) fn classify(
    attained: &[RealAlg],
    judging: &ZPoly,
    curves: bool,
) -> (Vec<RealAlg>, Vec<RealAlg>) {
    let (vals, roots) = split_values(attained, judging);
    if !curves {
        return (vals, roots);
    }
    let nonreal = match (vals.first(), vals.last()) {
        (Some(lo), Some(hi)) => roots
            .into_iter()
            .filter(|r| r.cmp_exact(lo) == Ordering::Less || r.cmp_exact(hi) == Ordering::Greater)
            .collect(),
        _ => roots,
    };
    (vals, nonreal)
}

/// The answer when no certificate could be produced (never a guess).
fn undecided(e: &Ellipsoid, surface: &QMPoly, why: String) -> TangentReport {
    undecided_report(
        e.poly.clone(),
        surface.clone(),
        Undecided::NoCertificate(why),
    )
}

fn undecided_report(ellipsoid: QMPoly, surface: QMPoly, why: Undecided) -> TangentReport {
    TangentReport {
        ellipsoid,
        surface,
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
            method: Analysis::Undecided,
            notes: vec![],
            s_lemma: None,
        },
        reason: Some(why),
    }
}

impl TangentReport {
    /// The answer when the budget ran out before E and S were even read
    /// (their polynomials are then zero).
    pub(crate) fn budget_exhausted(e: Exhausted) -> TangentReport {
        undecided_report(QMPoly::zero(), QMPoly::zero(), Undecided::Budget(e))
    }
}

#[derive(Clone, Copy, Debug)]
pub(crate) enum WitnessFinder {
    None,
    Pencil,
    Lambda,
    Separable,
    Critical,
    Modular,
    Poisson,
    Level,
    NonReduced,
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
    method: Analysis,
    wf: WitnessFinder,
) -> TangentReport {
    let mut notes = Vec::new();
    // the analysis that found the critical points (a non-reduced S: its
    // factor's or its G-system's)
    let inner = match &method {
        Analysis::NonReduced(an) => an.inner().unwrap_or(&method),
        m => m,
    };
    if matches!(inner, Analysis::LevelSets(_)) {
        let between: Vec<String> = match (values.first(), values.last()) {
            (Some(lo), Some(hi)) => RealAlg::roots_of(&judging)
                .iter()
                .filter(|r| {
                    r.cmp_exact(lo) == Ordering::Greater
                        && r.cmp_exact(hi) == Ordering::Less
                        && !values.iter().any(|v| v.cmp_exact(r) == Ordering::Equal)
                })
                .map(|r| r.approx(12))
                .collect(),
            _ => vec![],
        };
        let listed = if between.is_empty() {
            String::new()
        } else {
            format!(" (roots of D(u) there: {})", between.join(", "))
        };
        notes.push(format!("curves of critical points: ν and μ are exact; critical values strictly between them are not classified{listed}"));
    }
    if let Analysis::Separable(sa) = inner
        && sa.has_curves()
    {
        notes.push("curves of critical points on a branch with two free coordinates; every critical value is exact".into());
    }
    // every value's interval off 0 and narrow enough for its 20 digits (a
    // value of 1e-40 must not sit in [0, 256])
    let mut values = values;
    let mut nonreal = nonreal;
    for v in values.iter_mut().chain(nonreal.iter_mut()) {
        v.refine_for_approx(20);
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
    let sn = min.signum();
    let sm = max.signum();
    let (verdict, intersect, touching, side) = if sn > 0 {
        (Verdict::Separated, false, false, Some(1))
    } else if sm < 0 {
        (Verdict::Separated, false, false, Some(-1))
    } else if sn == 0 && sm == 0 {
        if surface.total_degree() == Some(2) {
            // a quadric vanishing on the irreducible quadric E is c·E
            notes.push(
                "S vanishes on all of E and has degree 2: S = c·E, so E lies on the surface S (they coincide)".into(),
            );
        } else {
            notes.push("S vanishes on all of E: E lies on the surface S".into());
        }
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
    let s_lemma = match (verdict, side) {
        (Verdict::Separated, Some(sd)) if surface.total_degree().unwrap_or(0) <= 2 => {
            slemma::s_lemma_tau(&e.form, surface, sd)
                // τ of the oriented E; the certificate speaks of E as given
                .map(|t| if e.negated { -t } else { t })
        }
        _ => None,
    };
    let containment = if !intersect {
        containment_of(e, surface, side.unwrap_or(0))
    } else if sn == 0 && sm == 0 && surface.total_degree() == Some(2) {
        Some(Containment::Coincident)
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
            s_lemma,
        },
        reason: None,
    }
}

/// The verdict from the signs of S at the real critical points (no exact
/// values: [`TangentOptions::without_values`]).  Every sign is decided
/// (the analysis computes the values when one is not), and zero is never
/// one of them, so the verdict is `separated` or `intersecting`.
fn finish_signs(
    e: &Ellipsoid,
    surface: &QMPoly,
    an: square_subsystem::PoissonAnalysis,
) -> TangentReport {
    let signs: Vec<i32> = an.enclosures.iter().map(|(s, _)| *s).collect();
    let (neg, pos) = (signs.contains(&-1), signs.contains(&1));
    let (verdict, intersect, side) = match (neg, pos) {
        (true, true) => (Verdict::Intersecting, true, None),
        (false, _) => (Verdict::Separated, false, Some(1)),
        (true, false) => (Verdict::Separated, false, Some(-1)),
    };
    // witnesses at the extreme real critical points (by their enclosures)
    let extreme = |want: i32| -> Option<WitnessPoint> {
        let i = (0..signs.len())
            .filter(|&i| signs[i] == want)
            .max_by(|&i, &j| {
                let (a, b) = (&an.enclosures[i].1, &an.enclosures[j].1);
                if want < 0 {
                    b.0.cmp(&a.0)
                } else {
                    a.1.cmp(&b.1)
                }
            })?;
        an.witness_at(i, e, surface, want)
    };
    let negw = if neg { extreme(-1) } else { None };
    let posw = if pos { extreme(1) } else { None };
    let notes = vec![
        "verdict only: D(u) and the exact critical values were not computed; S has the sign of its enclosure at every real critical point".to_string(),
    ];
    TangentReport {
        ellipsoid: e.poly.clone(),
        surface: surface.clone(),
        verdict,
        intersect: Some(intersect),
        touching: Some(false),
        side,
        containment: if intersect {
            None
        } else {
            containment_of(e, surface, side.unwrap_or(0))
        },
        min: None,
        max: None,
        judging_poly: ZPoly::constant(num_bigint::BigInt::from(1)),
        certificate: Certificate {
            critical_values: vec![],
            nonreal_point_values: vec![],
            negative_witness: negw,
            positive_witness: posw,
            method: Analysis::Poisson(Box::new(an)),
            notes,
            s_lemma: None,
        },
        reason: None,
    }
}

fn witness_for(
    method: &Analysis,
    wf: WitnessFinder,
    e: &Ellipsoid,
    s: &QMPoly,
    value: &RealAlg,
    want: i32,
) -> Option<WitnessPoint> {
    match (method, wf) {
        (Analysis::Lambda(an), WitnessFinder::Lambda) => {
            let i = an
                .critical
                .iter()
                .position(|c| c.real && c.value.cmp_exact(value) == Ordering::Equal)?;
            an.witness(i, e, s, want)
        }
        (Analysis::Pencil(an), WitnessFinder::Pencil) => an.witness(e, s, want),
        (Analysis::Separable(an), WitnessFinder::Separable) => an.witness(value, e, s, want),
        (Analysis::CriticalIdeal(an), WitnessFinder::Critical) => an.witness(value, e, s, want),
        (Analysis::ModularRur(an), WitnessFinder::Modular) => an.witness(value, e, s, want),
        (Analysis::Poisson(an), WitnessFinder::Poisson) => an.witness(value, e, s, want),
        (Analysis::LevelSets(ls), WitnessFinder::Level) => ls.witness(value, e, s, want),
        (Analysis::NonReduced(an), WitnessFinder::NonReduced) => an.witness(value, e, s, want),
        (Analysis::Constant, _) => {
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
    use crate::geom::common_denominator;
    use ellipsoid::{IntEllipsoid, sign_at_int};
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
