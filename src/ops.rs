//! The operations behind the CLI, as library functions: text in, exact
//! result out.  The CLI (`main.rs`) only parses arguments and prints what
//! these return through [`crate::report`].

use crate::budget::Budget;
use crate::elim::resultant_mpoly;
use crate::error::{Error, ErrorKind};
use crate::poly::mpoly::{QMPoly, VAR_NAMES, var_index};
use crate::poly::{ZPoly, parse_poly};
use crate::roots::{RootReport, analyze_roots};

/// The result of `quadsect roots`.
#[derive(Clone, Debug)]
pub struct RootsResult {
    /// The polynomial as parsed.
    pub poly: QMPoly,
    /// Its variable (`None` for a constant).
    pub variable: Option<&'static str>,
    /// The primitive integer polynomial with the same roots.
    pub integer_poly: ZPoly,
    /// The root summary.
    pub report: RootReport,
}

/// Parses a univariate expression and analyses its real roots.
///
/// ```
/// let r = quadsect::ops::roots("x^3 - 2x").unwrap();
/// assert_eq!(r.report.distinct_real, 3);
/// assert!(quadsect::ops::roots("x*y").is_err());
/// ```
pub fn roots(expr: &str) -> Result<RootsResult, Error> {
    let p = parse_poly(expr)?;
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
    Ok(RootsResult {
        variable: vars.first().map(|&v| VAR_NAMES[v]),
        poly: p,
        integer_poly: z,
        report,
    })
}

/// [`roots`] within a compute budget: an error of kind
/// [`ErrorKind::Budget`] when a limit runs out.
///
/// ```
/// use quadsect::budget::Budget;
/// use quadsect::ErrorKind;
/// let r = quadsect::ops::roots_within("x^3 - 2x", &Budget::default()).unwrap();
/// assert_eq!(r.report.distinct_real, 3);
/// let none = Budget::unlimited().with_time_limit(Some(std::time::Duration::ZERO));
/// let e = quadsect::ops::roots_within("x^3000 - 3x^1001 + 1", &none).unwrap_err();
/// assert_eq!(e.kind(), ErrorKind::Budget);
/// ```
pub fn roots_within(expr: &str, budget: &Budget) -> Result<RootsResult, Error> {
    crate::budget::run(budget, || roots(expr)).unwrap_or_else(|e| Err(e.into()))
}

/// [`resultant`] within a compute budget: an error of kind
/// [`ErrorKind::Budget`] when a limit runs out.
pub fn resultant_within(
    f: &str,
    g: &str,
    var: &str,
    budget: &Budget,
) -> Result<ResultantResult, Error> {
    crate::budget::run(budget, || resultant(f, g, var)).unwrap_or_else(|e| Err(e.into()))
}

/// The result of `quadsect resultant`.
#[derive(Clone, Debug)]
pub struct ResultantResult {
    /// `Res_var(f, g)`.
    pub resultant: QMPoly,
    /// Its total degree (-1 for the zero polynomial).
    pub degree: i64,
}

/// `Res_var(f, g)` of two parsed expressions.
///
/// ```
/// let r = quadsect::ops::resultant("x^2 + y^2 - 1", "x - y", "x").unwrap();
/// assert_eq!(r.resultant.to_string_canonical(), "2*y^2 - 1");
/// assert_eq!(r.degree, 2);
/// ```
pub fn resultant(f: &str, g: &str, var: &str) -> Result<ResultantResult, Error> {
    let v = match var_index(var.trim()) {
        Some(v) if v <= 3 => v,
        _ => {
            return Err(Error::new(
                ErrorKind::Input,
                format!("unknown variable '{var}' for --var (use x, y, z or u)"),
            ));
        }
    };
    let fp = parse_poly(f).map_err(|e| Error::from(e).context("in F"))?;
    let gp = parse_poly(g).map_err(|e| Error::from(e).context("in G"))?;
    let r = resultant_mpoly(&fp, &gp, v);
    let degree = r.total_degree().map(|d| d as i64).unwrap_or(-1);
    Ok(ResultantResult {
        resultant: r,
        degree,
    })
}
