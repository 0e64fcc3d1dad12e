//! Three of the four jobs (`natural` is in `natural.rs`).  Each runs the engine with the GIL released and returns
//! the CLI's `--json` text (the Python half decodes it into a result
//! class), the human text, and the exact numbers as `RealAlgebraic`.

use crate::guard;
use crate::numbers::RealAlgebraic;
use pyo3::prelude::*;
use quadsect::TangentOptions;
use quadsect::tangent::Undecided;
use quadsect::{Ellipsoid, Error, Polynomial, RealAlg, Var};

fn json_text<T: serde::Serialize>(report: &T) -> Result<String, Error> {
    serde_json::to_string(report).map_err(|e| Error::internal(format!("JSON output: {e}")))
}

/// Parses an input, naming it in the error (`in the ellipsoid: …`).
fn parse<T: std::str::FromStr<Err = Error>>(text: &str, what: &str) -> Result<T, Error> {
    text.parse().map_err(|e: Error| e.context(what))
}

fn algebraic(values: &[RealAlg]) -> Vec<RealAlgebraic> {
    values.iter().cloned().map(RealAlgebraic::new).collect()
}

/// The tangent method's options: the budget, and the values or not.
fn options(py: Python<'_>, time_limit: Option<f64>, values: bool) -> PyResult<TangentOptions> {
    let options = TangentOptions::with_budget(guard::budget(py, time_limit)?);
    Ok(if values {
        options
    } else {
        options.without_values()
    })
}

/// The tangent method on the inputs' text.
fn decide(
    ellipsoid: &str,
    surface: &str,
    options: &TangentOptions,
) -> Result<quadsect::TangentReport, Error> {
    let e: Ellipsoid = parse(ellipsoid, "in the ellipsoid")?;
    let s: Polynomial = parse(surface, "in the surface")?;
    quadsect::decide_with(&e, &s, options)
}

/// What `tangent` hands to the Python half.
type TangentParts = (
    String,
    String,
    Option<RealAlgebraic>,
    Option<RealAlgebraic>,
    Vec<RealAlgebraic>,
    Vec<RealAlgebraic>,
    Option<(String, String)>,
);

/// tangent(ellipsoid, surface, time_limit, values) -> (json, text, min,
/// max, critical_values, nonreal_point_values, undecided)
///
/// `undecided` is `None` or `(kind, reason)` with kind `budget` or
/// `no-certificate`; `values = False` asks for the verdict only (no D(u),
/// min, max when they cost extra).
#[pyfunction]
#[pyo3(signature = (ellipsoid, surface, time_limit = None, values = true))]
pub(crate) fn tangent(
    py: Python<'_>,
    ellipsoid: &str,
    surface: &str,
    time_limit: Option<f64>,
    values: bool,
) -> PyResult<TangentParts> {
    let options = options(py, time_limit, values)?;
    guard::run(py, || {
        let r = decide(ellipsoid, surface, &options)?;
        let c = r.certificate();
        let undecided = r.undecided().map(|u| {
            let kind = match u {
                Undecided::Budget(_) => "budget",
                _ => "no-certificate",
            };
            (kind.to_string(), u.to_string())
        });
        Ok((
            json_text(&r)?,
            r.to_string(),
            r.min().cloned().map(RealAlgebraic::new),
            r.max().cloned().map(RealAlgebraic::new),
            algebraic(c.critical_values()),
            algebraic(c.nonreal_point_values()),
            undecided,
        ))
    })
}

/// tangent_svg(ellipsoid, surface, time_limit, values) -> str: the
/// picture of the answer (`TangentReport::svg`), computed again from the
/// inputs.
#[pyfunction]
#[pyo3(signature = (ellipsoid, surface, time_limit = None, values = true))]
pub(crate) fn tangent_svg(
    py: Python<'_>,
    ellipsoid: &str,
    surface: &str,
    time_limit: Option<f64>,
    values: bool,
) -> PyResult<String> {
    let options = options(py, time_limit, values)?;
    guard::run(py, || Ok(decide(ellipsoid, surface, &options)?.svg()))
}

/// What `roots` hands to the Python half: JSON, text, (root, multiplicity).
type RootsParts = (String, String, Vec<(RealAlgebraic, u32)>);

/// roots(poly, time_limit) -> (json, text, roots)
///
/// `roots` are the distinct real roots, increasing, with multiplicities.
#[pyfunction]
#[pyo3(signature = (poly, time_limit = None))]
pub(crate) fn roots(py: Python<'_>, poly: &str, time_limit: Option<f64>) -> PyResult<RootsParts> {
    let budget = guard::budget(py, time_limit)?;
    guard::run(py, || {
        let p: Polynomial = poly.parse()?;
        let r = quadsect::roots_with(&p, &budget)?;
        let values = r
            .roots()
            .map(|x| (RealAlgebraic::new(x.value()), x.multiplicity()))
            .collect();
        Ok((json_text(&r)?, r.to_string(), values))
    })
}

/// resultant(f, g, var, time_limit) -> (json, text)
#[pyfunction]
#[pyo3(signature = (f, g, var, time_limit = None))]
pub(crate) fn resultant(
    py: Python<'_>,
    f: &str,
    g: &str,
    var: &str,
    time_limit: Option<f64>,
) -> PyResult<(String, String)> {
    let budget = guard::budget(py, time_limit)?;
    guard::run(py, || {
        let v: Var = var.parse()?;
        let fp: Polynomial = parse(f, "in the first polynomial")?;
        let gp: Polynomial = parse(g, "in the second polynomial")?;
        let r = quadsect::resultant_with(&fp, &gp, v, &budget)?;
        Ok((json_text(&r)?, r.to_string()))
    })
}
