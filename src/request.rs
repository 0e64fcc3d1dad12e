//! The one dispatch table of quadsect's operations, shared by the command
//! line, the batch protocol and the bindings: a [`Request`] (an operation
//! with its inputs) runs to an [`Answer`] (a report), which prints as JSON
//! (feature `serde`) or as text.

use crate::budget::Budget;
use crate::error::Error;
use crate::kernel::{ResultantReport, RootsReport};
use crate::natural::{ClassifyOptions, Natural, NaturalReport};
use crate::tangent::{Ellipsoid, TangentOptions, TangentReport};
use std::fmt;

/// An operation and its inputs.
#[derive(Clone, Debug)]
pub(crate) enum Request {
    /// Ellipsoid vs surface (both in the input syntax).
    Tangent { ellipsoid: String, surface: String },
    /// Two natural quadrics.
    Natural { a: Natural, b: Natural },
    /// Real roots of a univariate polynomial.
    Roots { poly: String },
    /// A resultant.
    Resultant { f: String, g: String, var: String },
}

/// The report of a [`Request`].
#[derive(Clone, Debug)]
pub(crate) enum Answer {
    Tangent(TangentReport),
    Natural(NaturalReport),
    Roots(RootsReport),
    Resultant(ResultantReport),
}

/// The operations by name, with the fields of their batch lines.
pub(crate) const OPS: [(&str, &[&str]); 4] = [
    ("tangent", &["ellipsoid", "surface"]),
    ("natural", &["a", "b"]),
    ("roots", &["poly"]),
    ("resultant", &["f", "g", "var"]),
];

impl Request {
    /// Runs the request under `budget`.
    pub(crate) fn execute(&self, budget: &Budget) -> Result<Answer, Error> {
        Ok(match self {
            Request::Tangent { ellipsoid, surface } => {
                let e: Ellipsoid = ellipsoid
                    .parse()
                    .map_err(|x: Error| x.context("in the ellipsoid"))?;
                let s = crate::poly::parse_poly(surface)
                    .map_err(|x| Error::from(x).context("in the surface"))?;
                let options = TangentOptions::with_budget(budget.clone());
                Answer::Tangent(crate::tangent::decide_with(
                    &e,
                    &crate::poly::Polynomial::from_inner(s),
                    &options,
                )?)
            }
            Request::Natural { a, b } => Answer::Natural(crate::natural::classify_with(
                a,
                b,
                &ClassifyOptions::with_budget(budget.clone()),
            )?),
            Request::Roots { poly } => {
                let p = crate::poly::parse_poly(poly)?;
                Answer::Roots(crate::budget::run(budget, || crate::kernel::roots_of(&p))??)
            }
            Request::Resultant { f, g, var } => {
                let v = var.parse()?;
                let fp = crate::poly::parse_poly(f)
                    .map_err(|e| Error::from(e).context("in the first polynomial"))?;
                let gp = crate::poly::parse_poly(g)
                    .map_err(|e| Error::from(e).context("in the second polynomial"))?;
                Answer::Resultant(crate::budget::run(budget, || {
                    crate::kernel::resultant_of(&fp, &gp, v)
                })??)
            }
        })
    }
}

impl fmt::Display for Answer {
    /// The human-readable text.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Answer::Tangent(r) => fmt::Display::fmt(r, f),
            Answer::Natural(r) => fmt::Display::fmt(r, f),
            Answer::Roots(r) => fmt::Display::fmt(r, f),
            Answer::Resultant(r) => fmt::Display::fmt(r, f),
        }
    }
}

#[cfg(feature = "serde")]
mod json {
    use super::{Answer, OPS, Request};
    use crate::error::{Error, ErrorKind};
    use serde_json::{Map, Value};

    fn field<'a>(obj: &'a Map<String, Value>, name: &str) -> Result<&'a Value, Error> {
        obj.get(name)
            .ok_or_else(|| Error::new(ErrorKind::MissingField, format!("missing field \"{name}\"")))
    }

    fn text(obj: &Map<String, Value>, name: &str) -> Result<String, Error> {
        field(obj, name)?
            .as_str()
            .map(str::to_string)
            .ok_or_else(|| {
                Error::new(
                    ErrorKind::BadField,
                    format!("field \"{name}\" must be a string"),
                )
            })
    }

    fn natural(obj: &Map<String, Value>, name: &str) -> Result<crate::natural::Natural, Error> {
        match field(obj, name)? {
            Value::String(s) => crate::natural::parse_natural(s),
            other => crate::natural::types::from_json(other),
        }
        .map_err(|e| e.context(&format!("in \"{name}\"")))
    }

    impl Request {
        /// The request of a batch line's JSON object (`op` and its fields).
        pub(crate) fn from_json(obj: &Map<String, Value>) -> Result<Request, Error> {
            let op = text(obj, "op")?;
            Ok(match op.as_str() {
                "tangent" => Request::Tangent {
                    ellipsoid: text(obj, "ellipsoid")?,
                    surface: text(obj, "surface")?,
                },
                "natural" => Request::Natural {
                    a: natural(obj, "a")?,
                    b: natural(obj, "b")?,
                },
                "roots" => Request::Roots {
                    poly: text(obj, "poly")?,
                },
                "resultant" => Request::Resultant {
                    f: text(obj, "f")?,
                    g: text(obj, "g")?,
                    var: text(obj, "var")?,
                },
                other => {
                    let names: Vec<&str> = OPS.iter().map(|(n, _)| *n).collect();
                    return Err(Error::new(
                        ErrorKind::UnknownOp,
                        format!("unknown op \"{other}\" (expected {})", names.join(", ")),
                    ));
                }
            })
        }
    }

    impl serde::Serialize for Answer {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            match self {
                Answer::Tangent(r) => r.serialize(s),
                Answer::Natural(r) => r.serialize(s),
                Answer::Roots(r) => r.serialize(s),
                Answer::Resultant(r) => r.serialize(s),
            }
        }
    }

    impl Answer {
        /// The JSON of `--json`.
        pub(crate) fn to_json(&self) -> Value {
            match self {
                Answer::Tangent(r) => crate::report::tangent_json(r),
                Answer::Natural(r) => crate::report::natural_json(r),
                Answer::Roots(r) => crate::report::roots_json(r),
                Answer::Resultant(r) => crate::report::resultant_json(r),
            }
        }
    }
}
