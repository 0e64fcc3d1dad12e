//! The kernel jobs: real roots of a univariate polynomial and resultants,
//! as library functions (exact results, no formatting; see
//! the report layer for the JSON and the text).

use crate::budget::Budget;
use crate::elim::resultant_mpoly;
use crate::error::{Error, ErrorKind};
use crate::number::Q;
use crate::poly::mpoly::VAR_NAMES;
use crate::poly::{IntPoly, Polynomial, QMPoly, Var, ZPoly, parse_poly};
use crate::roots::{RealAlg, RootReport, analyze_roots};

/// The real roots of a univariate polynomial: counts by sign, the
/// multiplicity of 0, Descartes' bounds, and one exact isolating interval
/// per distinct real root (sorted, disjoint, `lo = hi` for a rational root).
#[derive(Clone, Debug)]
pub struct RootsReport {
    pub(crate) poly: QMPoly,
    pub(crate) variable: Option<&'static str>,
    pub(crate) integer_poly: ZPoly,
    pub(crate) report: RootReport,
}

/// One distinct real root of [`RootsReport`].
#[derive(Clone, Debug)]
pub struct Root<'a> {
    root: &'a crate::roots::RealRoot,
}

impl Root<'_> {
    /// The isolating interval `[lo, hi]` (rational ends; `lo = hi` for an
    /// exact rational root, otherwise the root lies strictly inside).
    pub fn interval(&self) -> (&Q, &Q) {
        (&self.root.interval.lo, &self.root.interval.hi)
    }

    /// Its multiplicity as a root of the input.
    pub fn multiplicity(&self) -> u32 {
        self.root.multiplicity
    }

    /// The root as an exact real algebraic number.
    pub fn value(&self) -> RealAlg {
        self.root.value()
    }
}

impl RootsReport {
    /// The polynomial as given.
    pub fn polynomial(&self) -> Polynomial {
        Polynomial::from_inner(self.poly.clone())
    }

    /// Its variable (`None` for a constant).
    pub fn variable(&self) -> Option<Var> {
        self.variable.and_then(|v| v.parse().ok())
    }

    /// The primitive integer polynomial with the same roots.
    pub fn integer_poly(&self) -> IntPoly {
        IntPoly::from_inner(self.integer_poly.clone())
    }

    /// Number of distinct real roots.
    pub fn distinct_real(&self) -> usize {
        self.report.distinct_real
    }

    /// Distinct positive roots.
    pub fn positive(&self) -> usize {
        self.report.positive
    }

    /// Distinct negative roots.
    pub fn negative(&self) -> usize {
        self.report.negative
    }

    /// Multiplicity of the root 0 (0 when 0 is not a root).
    pub fn zero_multiplicity(&self) -> u32 {
        self.report.zero_multiplicity
    }

    /// Real roots counted with multiplicity.
    pub fn real_with_multiplicity(&self) -> u32 {
        self.report.real_with_multiplicity
    }

    /// Descartes' bounds on the positive and negative roots (sign
    /// variations, counted with multiplicity, 0 removed).
    pub fn descartes_bounds(&self) -> (usize, usize) {
        (
            self.report.descartes_positive_bound,
            self.report.descartes_negative_bound,
        )
    }

    /// The distinct real roots, increasing.
    pub fn roots(&self) -> impl Iterator<Item = Root<'_>> + '_ {
        self.report.roots.iter().map(|root| Root { root })
    }
}

/// Analyses the real roots of a univariate polynomial exactly (square-free
/// factorisation for the multiplicities, Descartes/VCA isolation; for degree
/// n and τ-bit coefficients O(n⁴τ²) bit operations in the worst case, far
/// less in practice), under the default budget.
///
/// ```
/// let p: quadsect::Polynomial = "(x^2-2)^3 (x-1/3)".parse().unwrap();
/// let r = quadsect::roots(&p).unwrap();
/// assert_eq!((r.distinct_real(), r.positive(), r.negative()), (3, 2, 1));
/// assert_eq!(r.real_with_multiplicity(), 7);
/// let third = r.roots().nth(1).unwrap();
/// assert_eq!(third.value().to_string(), "1/3");
/// assert!(quadsect::roots(&"x*y".parse().unwrap()).is_err());
/// ```
pub fn roots(p: &Polynomial) -> Result<RootsReport, Error> {
    roots_with(p, &Budget::default())
}

/// [`roots`] under a given budget (an exhausted budget is an error of kind
/// [`ErrorKind::Budget`]).
pub fn roots_with(p: &Polynomial, budget: &Budget) -> Result<RootsReport, Error> {
    crate::budget::run(budget, || roots_of(p.inner()))?
}

/// [`roots`] of an expression in the input syntax.
pub fn roots_str(expr: &str) -> Result<RootsReport, Error> {
    roots_of(&parse_poly(expr)?)
}

pub(crate) fn roots_of(p: &QMPoly) -> Result<RootsReport, Error> {
    crate::budget::check_now();
    let vars = p.vars();
    if vars.len() > 1 {
        let names: Vec<&str> = vars.iter().map(|&v| VAR_NAMES[v]).collect();
        return Err(Error::new(
            ErrorKind::NotUnivariate,
            format!(
                "roots needs a univariate polynomial, but the expression has the variables {}",
                names.join(", ")
            ),
        ));
    }
    if p.is_zero() {
        return Err(Error::new(
            ErrorKind::ZeroPolynomial,
            "the zero polynomial has every number as a root; roots needs a non-zero polynomial",
        ));
    }
    let v = vars.first().copied().unwrap_or(0);
    let uq = p
        .to_univariate(v)
        .ok_or_else(|| Error::internal("univariate conversion failed"))?;
    let (z, _) = ZPoly::from_q(&uq);
    let report = analyze_roots(&z);
    Ok(RootsReport {
        variable: vars.first().map(|&v| VAR_NAMES[v]),
        poly: p.clone(),
        integer_poly: z,
        report,
    })
}

/// The resultant of two polynomials with respect to a variable.
#[derive(Clone, Debug)]
pub struct ResultantReport {
    pub(crate) resultant: QMPoly,
    pub(crate) degree: i64,
}

impl ResultantReport {
    /// `Res_var(f, g)`.
    pub fn resultant(&self) -> Polynomial {
        Polynomial::from_inner(self.resultant.clone())
    }

    /// Its total degree (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<u32> {
        u32::try_from(self.degree).ok()
    }
}

/// `Res_var(f, g)`, exactly (subresultants over Z[other variables] or a
/// multi-modular determinant; cost polynomial in the degrees and bit sizes),
/// under the default budget.
///
/// ```
/// use quadsect::{Polynomial, Var};
/// let f: Polynomial = "x^2 + y^2 - 1".parse().unwrap();
/// let g: Polynomial = "x - y".parse().unwrap();
/// let r = quadsect::resultant(&f, &g, Var::X).unwrap();
/// assert_eq!(r.resultant().to_string(), "2*y^2 - 1");
/// assert_eq!(r.degree(), Some(2));
/// ```
pub fn resultant(f: &Polynomial, g: &Polynomial, var: Var) -> Result<ResultantReport, Error> {
    resultant_with(f, g, var, &Budget::default())
}

/// [`resultant`] under a given budget.
pub fn resultant_with(
    f: &Polynomial,
    g: &Polynomial,
    var: Var,
    budget: &Budget,
) -> Result<ResultantReport, Error> {
    crate::budget::run(budget, || resultant_of(f.inner(), g.inner(), var))?
}

/// [`resultant`] of expressions in the input syntax; `var` is `x`, `y`,
/// `z` or `u`.
pub fn resultant_str(f: &str, g: &str, var: &str) -> Result<ResultantReport, Error> {
    let v: Var = var.parse()?;
    let fp = parse_poly(f).map_err(|e| Error::from(e).context("in the first polynomial"))?;
    let gp = parse_poly(g).map_err(|e| Error::from(e).context("in the second polynomial"))?;
    resultant_of(&fp, &gp, v)
}

pub(crate) fn resultant_of(f: &QMPoly, g: &QMPoly, var: Var) -> Result<ResultantReport, Error> {
    crate::budget::check_now();
    let r = resultant_mpoly(f, g, var.index());
    let degree = r.total_degree().map(|d| d as i64).unwrap_or(-1);
    Ok(ResultantReport {
        resultant: r,
        degree,
    })
}
