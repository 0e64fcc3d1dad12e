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
    /// counts only (the fast route); `referee` adds the stability interval.
    Natural {
        a: Natural,
        b: Natural,
        components: bool,
        referee: bool,
    },
    /// Two solid ellipsoids: separated, touching or overlapping.
    EllipsoidContact {
        a: crate::contact::ExactEllipsoid,
        b: crate::contact::ExactEllipsoid,
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
    Contact(crate::contact::ContactReport),
    Roots(RootsReport),
    Resultant(ResultantReport),
}

/// The operations by name, with the fields of their batch lines (besides
/// [`LINE_FIELDS`]).
pub(crate) const OPS: [(&str, &[&str]); 5] = [
    (
        "tangent",
        &["ellipsoid", "surface", "values", "float", "svg"],
    ),
    (
        "natural",
        &["a", "b", "components", "referee", "float", "svg"],
    ),
    ("ellipsoid-contact", &["a", "b"]),
    ("roots", &["poly"]),
    ("resultant", &["f", "g", "var"]),
];

/// The fields every batch line may have, whatever its op: before the op's
/// own fields (`id`, `op`) and after them (the line's limits).
pub(crate) const LINE_FIELDS: ([&str; 2], [&str; 2]) =
    (["id", "op"], ["time_limit", "memory_limit"]);

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
            Request::Natural {
                a,
                b,
                components,
                referee,
            } => {
                let mut options = ClassifyOptions::with_budget(budget.clone());
                options.components = *components;
                options.referee = *referee;
                Answer::Natural(crate::natural::classify_with(a, b, &options)?)
            }
            Request::EllipsoidContact { a, b } => {
                Answer::Contact(crate::contact::contact_report(a, b)?)
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
            Answer::Contact(r) => fmt::Display::fmt(r, f),
            Answer::Roots(r) => fmt::Display::fmt(r, f),
            Answer::Resultant(r) => fmt::Display::fmt(r, f),
        }
    }
}

#[cfg(feature = "serde")]
mod json {
    use super::{Answer, LINE_FIELDS, NumberMode, OPS, Request};
    use crate::budget::Budget;
    use crate::error::{Error, ErrorKind};
    use serde_json::{Map, Value};
    use std::time::Duration;

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

    /// An ellipsoid of `ellipsoid-contact`: `{"center", "semi_axes",
    /// "rotation"}` (JSON numbers are the doubles they denote, strings exact
    /// numbers) or a quadric polynomial as a string.
    fn contact_ellipsoid(
        obj: &Map<String, Value>,
        name: &str,
    ) -> Result<crate::contact::ExactEllipsoid, Error> {
        use crate::contact::{ExactEllipsoid, Pose};
        let ctx = |e: Error| e.context(&format!("in \"{name}\""));
        let v = field(obj, name)?;
        let o = match v {
            Value::String(s) => return s.parse::<ExactEllipsoid>().map_err(ctx),
            Value::Object(o) => o,
            _ => {
                return Err(Error::new(
                    ErrorKind::BadField,
                    format!(
                        "field \"{name}\" must be an object {{\"center\", \"semi_axes\", \"rotation\"}} or a quadric polynomial string"
                    ),
                ));
            }
        };
        const KEYS: [&str; 3] = ["center", "semi_axes", "rotation"];
        if let Some(k) = o.keys().find(|k| !KEYS.contains(&k.as_str())) {
            return Err(Error::new(
                ErrorKind::BadField,
                format!(
                    "unknown key {} in \"{name}\" (expected center, semi_axes, rotation)",
                    shown(&Value::from(k.as_str()))
                ),
            ));
        }
        // numbers: (exact value, the double when given as a JSON number)
        let num = |v: &Value, at: &str| -> Result<(crate::number::Q, Option<f64>), Error> {
            match v {
                Value::Number(n) => {
                    let x = n.as_f64().filter(|x| x.is_finite()).ok_or_else(|| {
                        Error::new(
                            ErrorKind::Number,
                            format!("{at}: {n} is not a finite double"),
                        )
                    })?;
                    Ok((crate::number::Q::from_float(x).unwrap(), Some(x)))
                }
                Value::String(s) => {
                    Ok((crate::parse_rational(s).map_err(|e| e.context(at))?, None))
                }
                _ => Err(Error::new(
                    ErrorKind::BadField,
                    format!("{at} must be a number or a string holding one"),
                )),
            }
        };
        let vec3 = |key: &str| -> Result<Vec<(crate::number::Q, Option<f64>)>, Error> {
            let at = format!("\"{name}\".{key}");
            match o.get(key) {
                None => Err(Error::new(
                    ErrorKind::MissingField,
                    format!("missing key {at}"),
                )),
                Some(Value::Array(xs)) if xs.len() == 3 => xs
                    .iter()
                    .enumerate()
                    .map(|(i, x)| num(x, &format!("{at}[{i}]")))
                    .collect(),
                Some(_) => Err(Error::new(
                    ErrorKind::BadField,
                    format!("{at} must be an array of 3 numbers"),
                )),
            }
        };
        let c = vec3("center")?;
        let r = vec3("semi_axes")?;
        let rows = match o.get("rotation") {
            None => {
                return Err(Error::new(
                    ErrorKind::MissingField,
                    format!("missing key \"{name}\".rotation"),
                ));
            }
            Some(Value::Array(rows)) if rows.len() == 3 => rows
                .iter()
                .enumerate()
                .map(|(i, row)| match row {
                    Value::Array(xs) if xs.len() == 3 => xs
                        .iter()
                        .enumerate()
                        .map(|(j, x)| num(x, &format!("\"{name}\".rotation[{i}][{j}]")))
                        .collect::<Result<Vec<_>, Error>>(),
                    _ => Err(Error::new(
                        ErrorKind::BadField,
                        format!("\"{name}\".rotation[{i}] must be an array of 3 numbers"),
                    )),
                })
                .collect::<Result<Vec<_>, Error>>()?,
            Some(_) => {
                return Err(Error::new(
                    ErrorKind::BadField,
                    format!("\"{name}\".rotation must be a 3×3 array (rows)"),
                ));
            }
        };
        // every number exactly a double (a JSON number, or an exact string
        // such as "0.5" or "3"): the pose of doubles, whose filter applies
        let as_double = |x: &(crate::number::Q, Option<f64>)| {
            x.1.or_else(|| {
                use num_traits::ToPrimitive;
                let d = x.0.to_f64()?;
                (d.is_finite() && crate::number::Q::from_float(d).as_ref() == Some(&x.0))
                    .then_some(d)
            })
        };
        let all: Vec<&(crate::number::Q, Option<f64>)> =
            c.iter().chain(&r).chain(rows.iter().flatten()).collect();
        if let Some(ds) = all
            .iter()
            .map(|x| as_double(x))
            .collect::<Option<Vec<f64>>>()
        {
            let p = Pose::new(
                [ds[0], ds[1], ds[2]],
                [ds[3], ds[4], ds[5]],
                std::array::from_fn(|i| std::array::from_fn(|j| ds[6 + 3 * i + j])),
            )
            .map_err(ctx)?;
            return Ok(ExactEllipsoid::from_pose(&p));
        }
        let q = |x: &(crate::number::Q, Option<f64>)| x.0.clone();
        ExactEllipsoid::from_pose_exact(
            std::array::from_fn(|i| q(&c[i])),
            std::array::from_fn(|i| q(&r[i])),
            std::array::from_fn(|i| std::array::from_fn(|j| q(&rows[i][j]))),
        )
        .map_err(ctx)
    }

    /// A field name or value as shown in a message: quoted and escaped
    /// (JSON), and cut short when long.
    fn shown(v: &Value) -> String {
        let s = v.to_string();
        match s.char_indices().nth(60) {
            Some((i, _)) => format!("{}…", &s[..i]),
            None => s,
        }
    }

    /// The error of an op that is not in [`OPS`].
    fn unknown_op(op: &str) -> Error {
        let names: Vec<&str> = OPS.iter().map(|(n, _)| *n).collect();
        Error::new(
            ErrorKind::UnknownOp,
            format!(
                "unknown op {} (expected {})",
                shown(&Value::from(op)),
                names.join(", ")
            ),
        )
    }

    /// Every field of the line is one of `op`'s or of [`LINE_FIELDS`]: a
    /// misspelt field is an error, never silently ignored.
    fn known_fields(obj: &Map<String, Value>, op: &str, fields: &[&str]) -> Result<(), Error> {
        let (head, tail) = LINE_FIELDS;
        let known =
            |name: &str| head.contains(&name) || fields.contains(&name) || tail.contains(&name);
        match obj.keys().find(|k| !known(k)) {
            None => Ok(()),
            Some(name) => {
                let expected: Vec<&str> = head.iter().chain(fields).chain(&tail).copied().collect();
                Err(Error::new(
                    ErrorKind::BadField,
                    format!(
                        "unknown field {} for op \"{op}\" (expected: {})",
                        shown(&Value::from(name.as_str())),
                        expected.join(", ")
                    ),
                ))
            }
        }
    }

    /// A limit field of a line (`time_limit` in seconds, `memory_limit` in
    /// MiB): a number ≥ 0, or absent, `null` or `"none"` (any case) for no
    /// limit of the line's own.
    fn limit(obj: &Map<String, Value>, name: &str, unit: &str) -> Result<Option<f64>, Error> {
        let bad = |v: &Value, why: &str| {
            Error::new(
                ErrorKind::BadField,
                format!(
                    "field \"{name}\" must be a number of {unit} ≥ 0, or null or \"none\" for the \
                     batch's limit; got {} ({why})",
                    shown(v)
                ),
            )
        };
        match obj.get(name) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::String(s)) if s.trim().eq_ignore_ascii_case("none") => Ok(None),
            Some(v @ Value::Number(n)) => match n.as_f64() {
                Some(x) if x >= 0.0 && x.is_finite() => Ok(Some(x)),
                _ => Err(bad(v, "negative")),
            },
            Some(v @ Value::String(_)) => Err(bad(v, "a string, not a number")),
            Some(v) => Err(bad(v, "wrong type")),
        }
    }

    /// The budget of a batch line: `budget` tightened by the line's own
    /// `time_limit` (seconds) and `memory_limit` (MiB), which can lower the
    /// limits but never raise them (see [`Budget::tightened`]).
    fn line_budget(obj: &Map<String, Value>, budget: &Budget) -> Result<Budget, Error> {
        // beyond 10⁹ s or 10¹² MiB a limit is no limit (as on the command line)
        let time =
            limit(obj, "time_limit", "seconds")?.map(|s| Duration::from_secs_f64(s.min(1e9)));
        let memory = limit(obj, "memory_limit", "MiB")?.map(|m| (m.min(1e12) * 1048576.0) as usize);
        Ok(budget.clone().tightened(time, memory))
    }

    impl Request {
        /// The request of a batch line's JSON object and its budget:
        /// `budget` tightened by the line's own limits.  The line is read
        /// in this order, and the first problem is the error: `op` (missing
        /// or unknown), a field the op does not take ([`LINE_FIELDS`] are
        /// always allowed), the limits, the op's fields.
        pub(crate) fn from_line(
            obj: &Map<String, Value>,
            budget: &Budget,
        ) -> Result<(Request, Budget), Error> {
            let op = text(obj, "op")?;
            let Some((_, fields)) = OPS.iter().find(|(name, _)| *name == op) else {
                return Err(unknown_op(&op));
            };
            known_fields(obj, &op, fields)?;
            let budget = line_budget(obj, budget)?;
            Ok((Request::from_fields(obj, &op)?, budget))
        }

        /// The line's `"svg": true` (tangent and natural): the answer then
        /// carries its picture as `"svg"`.
        pub(crate) fn svg_wanted(obj: &Map<String, Value>) -> Result<bool, Error> {
            flag(obj, "svg", false)
        }

        /// The request of a known op's fields.
        fn from_fields(obj: &Map<String, Value>, op: &str) -> Result<Request, Error> {
            Ok(match op {
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
                    referee: flag(obj, "referee", false)?,
                },
                "ellipsoid-contact" => Request::EllipsoidContact {
                    a: contact_ellipsoid(obj, "a")?,
                    b: contact_ellipsoid(obj, "b")?,
                },
                "roots" => Request::Roots {
                    poly: text(obj, "poly")?,
                },
                "resultant" => Request::Resultant {
                    f: text(obj, "f")?,
                    g: text(obj, "g")?,
                    var: text(obj, "var")?,
                },
                other => return Err(unknown_op(other)),
            })
        }
    }

    impl serde::Serialize for Answer {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            match self {
                Answer::Tangent(r) => r.serialize(s),
                Answer::Natural(r) => r.serialize(s),
                Answer::Contact(r) => crate::report::contact_json(r).serialize(s),
                Answer::Roots(r) => r.serialize(s),
                Answer::Resultant(r) => r.serialize(s),
            }
        }
    }

    impl Answer {
        /// The picture of a tangent or natural answer (SVG text).
        pub(crate) fn svg(&self) -> Option<String> {
            match self {
                Answer::Tangent(r) => Some(r.svg()),
                Answer::Natural(r) => Some(r.svg()),
                _ => None,
            }
        }

        /// The JSON of `--json`.
        pub(crate) fn to_json(&self) -> Value {
            match self {
                Answer::Tangent(r) => crate::report::tangent_json(r),
                Answer::Natural(r) => crate::report::natural_json(r),
                Answer::Contact(r) => crate::report::contact_json(r),
                Answer::Roots(r) => crate::report::roots_json(r),
                Answer::Resultant(r) => crate::report::resultant_json(r),
            }
        }

        /// [`Answer::to_json`] as compact text (a natural pair's written
        /// without a `Value` tree).
        pub(crate) fn to_json_text(&self) -> String {
            match self {
                Answer::Natural(r) => crate::report::natural_json_text(r),
                other => other.to_json().to_string(),
            }
        }
    }
}
