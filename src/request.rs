//! The one dispatch table of quadsect's operations, shared by the command
//! line, the batch protocol and the bindings: a [`Request`] (an operation
//! with its inputs) runs to an [`Answer`] (a report), which prints as JSON
//! (feature `serde`) or as text.

use crate::budget::Budget;
use crate::error::Error;
use crate::kernel::{ResultantReport, RootsReport};
use crate::natural::{ClassifyOptions, Natural, NaturalReport};
use crate::number::NumberMode;
use crate::tangent::{Ellipsoid, TangentOptions, TangentReport};
use std::fmt;

/// An operation and its inputs.
#[derive(Clone, Debug)]
pub(crate) enum Request {
    /// Ellipsoid vs surface (both in the input syntax, numbers read in
    /// `mode`); `values: false` asks for the verdict only (no D(u), ν, μ
    /// when they cost extra).
    Tangent {
        ellipsoid: String,
        surface: String,
        mode: NumberMode,
        values: bool,
    },
    /// Two natural quadrics; `components: false` asks for the class and
    /// counts only (the fast route).
    Natural {
        a: Natural,
        b: Natural,
        components: bool,
    },
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
    ("tangent", &["ellipsoid", "surface", "values", "float"]),
    ("natural", &["a", "b", "components", "float"]),
    ("roots", &["poly"]),
    ("resultant", &["f", "g", "var"]),
];

impl Request {
    /// Runs the request under `budget` (parsing included).  When the budget
    /// runs out, tangent and natural answer `undecided` (with the limit),
    /// roots and resultant give an error of kind `budget`.
    pub(crate) fn execute(&self, budget: &Budget) -> Result<Answer, Error> {
        match crate::budget::run(budget, || self.execute_unbudgeted(budget)) {
            Ok(answer) => answer,
            Err(e) => match self {
                Request::Tangent { .. } => Ok(Answer::Tangent(
                    crate::tangent::TangentReport::budget_exhausted(e),
                )),
                Request::Natural { a, b, .. } => {
                    Ok(Answer::Natural(NaturalReport::budget_exhausted(a, b, e)))
                }
                _ => Err(e.into()),
            },
        }
    }

    fn execute_unbudgeted(&self, budget: &Budget) -> Result<Answer, Error> {
        Ok(match self {
            Request::Tangent {
                ellipsoid,
                surface,
                mode,
                values,
            } => {
                let parse = |t: &str, what: &str| {
                    crate::poly::parse_poly_in(t, &crate::poly::Limits::default(), *mode)
                        .map_err(|x| Error::from(x).context(what))
                };
                let e = Ellipsoid::from_poly(&parse(ellipsoid, "in the ellipsoid")?)
                    .map_err(|x| x.context("in the ellipsoid"))?;
                let s = parse(surface, "in the surface")?;
                let mut options = TangentOptions::with_budget(budget.clone());
                options.values = *values;
                Answer::Tangent(crate::tangent::decide_with(
                    &e,
                    &crate::poly::Polynomial::from_inner(s),
                    &options,
                )?)
            }
            Request::Natural { a, b, components } => {
                let mut options = ClassifyOptions::with_budget(budget.clone());
                options.components = *components;
                Answer::Natural(crate::natural::classify_with(a, b, &options)?)
            }
            Request::Roots { poly } => {
                let p = crate::poly::parse_poly(poly)?;
                Answer::Roots(crate::kernel::roots_of(&p)?)
            }
            Request::Resultant { f, g, var } => {
                let v = var.parse()?;
                let fp = crate::poly::parse_poly(f)
                    .map_err(|e| Error::from(e).context("in the first polynomial"))?;
                let gp = crate::poly::parse_poly(g)
                    .map_err(|e| Error::from(e).context("in the second polynomial"))?;
                Answer::Resultant(crate::kernel::resultant_of(&fp, &gp, v)?)
            }
        })
    }
}

impl Answer {
    /// The budget that ran out, when the answer is `undecided` because of it.
    pub(crate) fn exhausted(&self) -> Option<&crate::budget::Exhausted> {
        match self {
            Answer::Tangent(r) => match r.undecided() {
                Some(crate::tangent::Undecided::Budget(e)) => Some(e),
                _ => None,
            },
            Answer::Natural(r) => r.exhausted(),
            _ => None,
        }
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
    use super::{Answer, NumberMode, OPS, Request};
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

    /// An optional boolean field.
    fn flag(obj: &Map<String, Value>, name: &str, default: bool) -> Result<bool, Error> {
        match obj.get(name) {
            None => Ok(default),
            Some(Value::Bool(b)) => Ok(*b),
            Some(_) => Err(Error::new(
                ErrorKind::BadField,
                format!("field \"{name}\" must be true or false"),
            )),
        }
    }

    /// The number mode of a line: `"float": true` reads literals as doubles.
    fn mode(obj: &Map<String, Value>) -> Result<NumberMode, Error> {
        Ok(if flag(obj, "float", false)? {
            NumberMode::Float
        } else {
            NumberMode::Exact
        })
    }

    fn natural(
        obj: &Map<String, Value>,
        name: &str,
        mode: NumberMode,
    ) -> Result<crate::natural::Natural, Error> {
        match field(obj, name)? {
            Value::String(s) => crate::natural::types::parse_natural_in(s, mode),
            other => crate::natural::types::from_json_in(other, mode),
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
                    mode: mode(obj)?,
                    values: flag(obj, "values", true)?,
                },
                "natural" => Request::Natural {
                    a: natural(obj, "a", mode(obj)?)?,
                    b: natural(obj, "b", mode(obj)?)?,
                    components: flag(obj, "components", true)?,
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
