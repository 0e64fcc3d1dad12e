//! The public face of the tangent point method: the verdict and its
//! vocabulary ([`Verdict`], [`Side`], [`Containment`], [`Method`],
//! [`Undecided`]), the options, the report with its certificate, and the
//! entry points ([`decide`], [`decide_with`], [`decide_str`]).  The
//! decision itself is in the parent module.

use super::{
    Ellipsoid, critical, decide_validated, modular, nonreduced, pencil, quadric, separable,
    square_subsystem, undecided_report,
};
use super::{WitnessPoint, decide_poly};
use crate::budget::{Budget, Exhausted};
use crate::error::Error;
use crate::poly::{IntPoly, Polynomial, QMPoly, ZPoly};
use crate::roots::RealAlg;
use std::fmt;

/// The overall answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
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
    /// `intersecting`, `touching`, `separated` or `undecided`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Verdict::Intersecting => "intersecting",
            Verdict::Touching => "touching",
            Verdict::Separated => "separated",
            Verdict::Undecided => "undecided",
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The side of S on which E lies, when S does not change sign on E.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// S ≥ 0 on E (printed `+`).
    Positive,
    /// S ≤ 0 on E (printed `-`).
    Negative,
}

impl Side {
    pub(crate) fn from_i32(s: i32) -> Option<Side> {
        match s {
            1 => Some(Side::Positive),
            -1 => Some(Side::Negative),
            _ => None,
        }
    }

    /// `+` or `-`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Side::Positive => "+",
            Side::Negative => "-",
        }
    }
}

impl fmt::Display for Side {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Where E lies relative to a closed surface S (an ellipsoid).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Containment {
    /// E is inside the solid bounded by S.
    EInsideS,
    /// S is inside the solid bounded by E.
    SInsideE,
    /// The two solids are disjoint.
    Apart,
    /// S = c·E: the same surface (the verdict is `touching`: S vanishes on
    /// all of E, ν = μ = 0).
    Coincident,
}

impl Containment {
    /// `E-inside-S`, `S-inside-E`, `apart` or `coincident`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Containment::EInsideS => "E-inside-S",
            Containment::SInsideE => "S-inside-E",
            Containment::Apart => "apart",
            Containment::Coincident => "coincident",
        }
    }
}

impl fmt::Display for Containment {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Which computation produced the critical values (the certificate's
/// `method`; the details are in the JSON certificate).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Method {
    /// deg S ≤ 2, generic pair: the pencil discriminant.
    PencilDiscriminant,
    /// deg S ≤ 2: the complete λ-parametrisation (singular multipliers
    /// solved exactly).
    LambdaParametrisation,
    /// Separable S against an axis-parallel E: univariate branches.
    SeparableBranches,
    /// deg S ≥ 3, finitely many critical points: Gröbner basis and RUR.
    CriticalIdeal,
    /// deg S ≥ 3 in general position: a Gröbner basis and RUR modulo word-size
    /// primes, lifted by CRT and rational reconstruction, verified exactly.
    ModularRur,
    /// deg S ≥ 3 in general position: the RUR of a square subsystem and the
    /// critical values as resultants (Poisson formula), computed modulo
    /// word-size primes and lifted by the CRT beyond an a-priori bound.
    PoissonRur,
    /// deg S ≥ 3 with curves of critical points: exact level-set tests.
    LevelSets,
    /// S with a repeated factor: decided from its square-free
    /// decomposition `S = c·∏ Tᵢ^kᵢ` (the factors' own analyses and the
    /// critical points of S off S = 0).
    SquareFreePart,
    /// S is a constant.
    Constant,
    /// No computation finished (undecided).
    None,
}

impl Method {
    /// The JSON spelling (`pencil-discriminant`, `lambda-parametrisation`, …).
    pub fn as_str(&self) -> &'static str {
        match self {
            Method::PencilDiscriminant => "pencil-discriminant",
            Method::LambdaParametrisation => "lambda-parametrisation",
            Method::SeparableBranches => "separable-branches",
            Method::CriticalIdeal => "critical-ideal-rur",
            Method::ModularRur => "critical-ideal-modular-rur",
            Method::PoissonRur => "critical-ideal-poisson-rur",
            Method::LevelSets => "level-sets",
            Method::SquareFreePart => "square-free-part",
            Method::Constant => "constant",
            Method::None => "none",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Why no verdict was given.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Undecided {
    /// The computation finished but no certificate could be produced.
    NoCertificate(String),
    /// A budget ran out (time, memory, size or cancellation).
    Budget(Exhausted),
}

impl fmt::Display for Undecided {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Undecided::NoCertificate(why) => f.write_str(why),
            Undecided::Budget(e) => write!(f, "{e}"),
        }
    }
}

/// Options of [`decide_with`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct TangentOptions {
    /// The compute budget (default: [`Budget::default`]).  When it runs out
    /// the answer is [`Verdict::Undecided`] with [`Undecided::Budget`].
    pub budget: Budget,
    /// Compute the exact critical values: D(u), ν and μ as real algebraic
    /// numbers (default `true`).  With `false` (see
    /// [`TangentOptions::without_values`]) a surface of degree ≥ 3 in
    /// general position is decided from the signs of S at its exactly
    /// known real critical points, and D(u) — the largest object of the
    /// computation — is skipped; `min`, `max` are then `None`.
    pub values: bool,
}

impl Default for TangentOptions {
    fn default() -> TangentOptions {
        TangentOptions {
            budget: Budget::default(),
            values: true,
        }
    }
}

impl TangentOptions {
    /// Options with the given budget.
    pub fn with_budget(budget: Budget) -> TangentOptions {
        TangentOptions {
            budget,
            ..TangentOptions::default()
        }
    }

    /// The verdict and its certificate only (no exact critical values when
    /// they cost extra): see [`TangentOptions::values`].
    ///
    /// ```
    /// use quadsect::{TangentOptions, Verdict};
    /// let e = "x^2 + 2y^2 + 3z^2 - 6".parse().unwrap();
    /// let s = "x^3 - 2x*y + z^2 + y*z - 1".parse().unwrap();
    /// let r = quadsect::decide_with(&e, &s, &TangentOptions::default().without_values()).unwrap();
    /// assert_eq!(r.verdict(), Verdict::Intersecting);
    /// assert!(r.certificate().negative_witness().is_some());
    /// ```
    pub fn without_values(mut self) -> TangentOptions {
        self.values = false;
        self
    }
}

/// How the critical values were obtained (the data behind [`Method`]).
#[derive(Clone, Debug)]
pub(crate) enum Analysis {
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
    /// deg S ≥ 3 in general position: the Poisson route (square subsystem,
    /// resultants lifted beyond an a-priori bound).
    Poisson(Box<square_subsystem::PoissonAnalysis>),
    /// deg S ≥ 3 with curves of critical points (symmetric inputs).
    LevelSets(critical::LevelSetAnalysis),
    /// S with a repeated factor, from its square-free decomposition.
    NonReduced(Box<nonreduced::NonReducedAnalysis>),
    /// S is a non-zero constant.
    Constant,
    /// No computation finished.
    Undecided,
}

/// The certificate of a verdict: everything needed to re-check it.
#[derive(Clone, Debug)]
pub struct Certificate {
    pub(crate) critical_values: Vec<RealAlg>,
    pub(crate) nonreal_point_values: Vec<RealAlg>,
    pub(crate) negative_witness: Option<WitnessPoint>,
    pub(crate) positive_witness: Option<WitnessPoint>,
    pub(crate) method: Analysis,
    pub(crate) notes: Vec<String>,
    /// `separated` with S of degree ≤ 2: τ with `side·(S − τE)` positive
    /// definite in (x, y, z, 1) (the S-lemma certificate).
    pub(crate) s_lemma: Option<crate::number::Q>,
}

impl Certificate {
    /// The distinct critical values of S on E attained by real critical
    /// points, increasing (ν is the first, μ the last; with curves of
    /// critical points only ν and μ are listed).
    pub fn critical_values(&self) -> &[RealAlg] {
        &self.critical_values
    }

    /// Real roots of D(u) that no real critical point attains: values of S
    /// at non-real critical points (the paper's trap), never counted.
    pub fn nonreal_point_values(&self) -> &[RealAlg] {
        &self.nonreal_point_values
    }

    /// For a `separated` verdict with S of degree ≤ 2: a rational τ for
    /// which `side·(S − τ·E)` is positive definite as a quadratic form in
    /// `(x, y, z, 1)` (so `side·S = side·(S − τE) > 0` on E = 0): the
    /// S-lemma certificate, checked by one exact LDLᵀ of a 4×4 matrix.
    pub fn s_lemma_tau(&self) -> Option<&crate::number::Q> {
        self.s_lemma.as_ref()
    }

    /// An exact point of E where S < 0.
    pub fn negative_witness(&self) -> Option<&WitnessPoint> {
        self.negative_witness.as_ref()
    }

    /// An exact point of E where S > 0.
    pub fn positive_witness(&self) -> Option<&WitnessPoint> {
        self.positive_witness.as_ref()
    }

    /// The computation behind the critical values (its data is in the JSON
    /// certificate, feature `serde`).
    pub fn method(&self) -> Method {
        match &self.method {
            Analysis::Pencil(_) => Method::PencilDiscriminant,
            Analysis::Lambda(_) => Method::LambdaParametrisation,
            Analysis::Separable(_) => Method::SeparableBranches,
            Analysis::CriticalIdeal(_) => Method::CriticalIdeal,
            Analysis::ModularRur(_) => Method::ModularRur,
            Analysis::Poisson(_) => Method::PoissonRur,
            Analysis::LevelSets(_) => Method::LevelSets,
            Analysis::NonReduced(_) => Method::SquareFreePart,
            Analysis::Constant => Method::Constant,
            Analysis::Undecided => Method::None,
        }
    }

    /// Remarks (e.g. "S vanishes on all of E").
    pub fn notes(&self) -> &[String] {
        &self.notes
    }
}

/// The answer of the tangent point method for an ellipsoid E and a
/// surface S: the verdict, the exact minimum ν and maximum μ of S on E, the
/// judging polynomial D(u) and a certificate.  `Display` prints the human
/// summary; with the feature `serde` it serializes to the JSON of
/// `quadsect tangent --json`.
#[derive(Clone, Debug)]
pub struct TangentReport {
    pub(crate) ellipsoid: QMPoly,
    pub(crate) surface: QMPoly,
    pub(crate) verdict: Verdict,
    pub(crate) intersect: Option<bool>,
    pub(crate) touching: Option<bool>,
    pub(crate) side: Option<i32>,
    pub(crate) containment: Option<Containment>,
    pub(crate) min: Option<RealAlg>,
    pub(crate) max: Option<RealAlg>,
    pub(crate) judging_poly: ZPoly,
    pub(crate) certificate: Certificate,
    pub(crate) reason: Option<Undecided>,
}

impl TangentReport {
    /// The verdict.
    pub fn verdict(&self) -> Verdict {
        self.verdict
    }

    /// E and S meet: ν ≤ 0 ≤ μ (`None` when undecided).
    pub fn intersect(&self) -> Option<bool> {
        self.intersect
    }

    /// E and S touch: ν = 0 or μ = 0 (`None` when undecided).
    pub fn touching(&self) -> Option<bool> {
        self.touching
    }

    /// The side of S on which E lies, when S does not change sign on E.
    pub fn side(&self) -> Option<Side> {
        self.side.and_then(Side::from_i32)
    }

    /// Containment, when S is an ellipsoid and they do not intersect
    /// (`Coincident` when S = c·E).
    pub fn containment(&self) -> Option<Containment> {
        self.containment
    }

    /// ν = min of S on E, exactly.
    pub fn min(&self) -> Option<&RealAlg> {
        self.min.as_ref()
    }

    /// μ = max of S on E, exactly.
    pub fn max(&self) -> Option<&RealAlg> {
        self.max.as_ref()
    }

    /// The judging polynomial D(u): square-free, primitive; its real roots
    /// include every critical value (and possibly values at non-real
    /// critical points, listed in the certificate).  The constant 1 when
    /// undecided or when the values were skipped
    /// ([`TangentReport::values_skipped`]).
    pub fn judging_poly(&self) -> IntPoly {
        IntPoly::from_inner(self.judging_poly.clone())
    }

    /// E as validated, oriented so that E < 0 inside.
    pub fn ellipsoid(&self) -> Polynomial {
        Polynomial::from_inner(self.ellipsoid.clone())
    }

    /// S as given.
    pub fn surface(&self) -> Polynomial {
        Polynomial::from_inner(self.surface.clone())
    }

    /// The certificate.
    pub fn certificate(&self) -> &Certificate {
        &self.certificate
    }

    /// Why no verdict was given (only for [`Verdict::Undecided`]).
    pub fn undecided(&self) -> Option<&Undecided> {
        self.reason.as_ref()
    }

    /// True when the verdict was decided without the exact critical values
    /// ([`TangentOptions::without_values`]): `min`, `max` are `None` and
    /// [`TangentReport::judging_poly`] is the constant 1; the certificate
    /// holds the real critical points with the sign of S at each.
    pub fn values_skipped(&self) -> bool {
        matches!(&self.certificate.method, Analysis::Poisson(an) if an.judging.is_none())
    }
}

/// Decides E against S given in the input syntax (a convenience for
/// [`Ellipsoid::from_str`](std::str::FromStr) and [`decide`]).
///
/// ```
/// use quadsect::tangent::{decide_str};
/// use quadsect::{Verdict};
/// let r = decide_str("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1").unwrap();
/// assert_eq!(r.verdict(), Verdict::Separated);
/// assert_eq!(r.min().unwrap().to_string(), "7/9");
/// assert_eq!(r.max().unwrap().to_string(), "187/9");
/// ```
pub fn decide_str(ellipsoid: &str, surface: &str) -> Result<TangentReport, Error> {
    decide_str_in(ellipsoid, surface, crate::number::NumberMode::Exact)
}

/// [`decide_str`] with the number literals read in the given mode
/// ([`NumberMode::Float`](crate::NumberMode::Float): each decimal literal
/// becomes its nearest double, as a program reading it would see it).
pub fn decide_str_in(
    ellipsoid: &str,
    surface: &str,
    mode: crate::number::NumberMode,
) -> Result<TangentReport, Error> {
    let parse = |t: &str| crate::poly::parse_poly_in(t, &crate::poly::Limits::default(), mode);
    let e = parse(ellipsoid).map_err(|x| Error::from(x).context("in the ellipsoid"))?;
    let s = parse(surface).map_err(|x| Error::from(x).context("in the surface"))?;
    decide_poly(&e, &s)
}

/// Decides how the ellipsoid `e` and the surface `s` meet, under the
/// default budget ([`Budget::default`]).
///
/// Cost: for deg S ≤ 2 a handful of exact operations on degree-6
/// polynomials (tens of µs); for higher degrees a Gröbner basis of the
/// critical system `E = 0, ∇S × ∇E = 0` (up to `2(d² − d + 1)` points for
/// degree d), whose cost grows steeply with d and the coefficient size —
/// bounded by the budget.
///
/// ```
/// use quadsect::{Ellipsoid, Polynomial};
/// use quadsect::{decide, Verdict};
/// let e: Ellipsoid = "x^2+y^2+z^2-25".parse().unwrap();
/// let s: Polynomial = "(x-6)^2/9+y^2/4+z^2/16-1".parse().unwrap();
/// let r = decide(&e, &s).unwrap();
/// assert_eq!(r.verdict(), Verdict::Intersecting);
/// assert!(r.certificate().negative_witness().is_some());
/// ```
pub fn decide(e: &Ellipsoid, s: &Polynomial) -> Result<TangentReport, Error> {
    decide_with(e, s, &TangentOptions::default())
}

/// [`decide`] with options (the budget).  An exhausted budget is an answer:
/// [`Verdict::Undecided`] with [`Undecided::Budget`].
pub fn decide_with(
    e: &Ellipsoid,
    s: &Polynomial,
    options: &TangentOptions,
) -> Result<TangentReport, Error> {
    match crate::budget::run(&options.budget, || {
        decide_validated(e, s.inner(), options.values)
    }) {
        Ok(r) => r,
        Err(exhausted) => Ok(undecided_report(
            e.poly.clone(),
            s.inner().clone(),
            Undecided::Budget(exhausted),
        )),
    }
}
