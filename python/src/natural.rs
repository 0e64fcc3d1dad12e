//! Natural quadrics across the boundary without text: the typed quadrics
//! of the Python half keep their parsed engine form (`NativeNatural`), the
//! answer stays the engine's report (`NativeReport`) until the Python half
//! asks for a part of it, and the components come out as tuples of exact
//! numbers (`Fraction`, `QuadraticIrrational`, `RealAlgebraic`) and
//! certified doubles, which `quadsect/_components.py` wraps into classes.

use crate::guard;
use crate::numbers::{Frac, QuadraticIrrational, RealAlgebraic, fraction, to_rational};
use pyo3::prelude::*;
use pyo3::types::{PyString, PyTuple};
use quadsect::ClassifyOptions;
use quadsect::natural::{
    Component, CurveBranch, EPoint, Exact, SingularPoint, normalize_axis_direction, normalize_plane,
};
use quadsect::{
    Class, Cone, Cylinder, Error, ErrorKind, Natural, NaturalReport, QSqrt, Rational, Sphere,
};
use std::time::Instant;

fn json_text<T: serde::Serialize>(report: &T) -> Result<String, Error> {
    serde_json::to_string(report).map_err(|e| Error::internal(format!("JSON output: {e}")))
}

/// A checked natural quadric in the engine's form: what the typed
/// `Sphere`, `Cylinder` and `Cone` of the Python half hold, so that
/// `natural()` reads no text.
#[pyclass(frozen, module = "quadsect._quadsect", name = "NativeNatural")]
pub(crate) struct NativeNatural {
    q: Natural,
}

#[pymethods]
impl NativeNatural {
    /// The short syntax (`sphere center=0,0,0 radius2=1`).
    fn __str__(&self) -> String {
        self.q.to_string()
    }

    fn __repr__(&self) -> String {
        format!("NativeNatural('{}')", self.q)
    }

    /// The JSON object form (numbers as exact strings), as text.
    fn json(&self, py: Python<'_>) -> PyResult<String> {
        guard::run(py, || json_text(&self.q))
    }

    /// Pickling: rebuilt from the JSON form.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let f = py.import("quadsect._quadsect")?.getattr("natural_native")?;
        (f, (self.json(py)?,)).into_pyobject(py)
    }
}

/// natural_native(text) -> NativeNatural
///
/// A natural quadric in the short syntax or the JSON object form, checked.
#[pyfunction]
pub(crate) fn natural_native(py: Python<'_>, text: &str) -> PyResult<NativeNatural> {
    let q = guard::run(py, || text.parse::<Natural>())?;
    Ok(NativeNatural { q })
}

/// Three Python numbers.
type Triple<'py> = (Bound<'py, PyAny>, Bound<'py, PyAny>, Bound<'py, PyAny>);

fn triple(v: &Triple<'_>) -> PyResult<[Rational; 3]> {
    Ok([to_rational(&v.0)?, to_rational(&v.1)?, to_rational(&v.2)?])
}

fn frac3(v: &[Rational; 3]) -> (Frac, Frac, Frac) {
    (Frac(v[0].clone()), Frac(v[1].clone()), Frac(v[2].clone()))
}

/// The checked quadric and its fields as the typed class stores them:
/// `(center, radius2)`, `(point, axis, radius2)` or `(vertex, axis, tan2)`.
type Parts = (
    NativeNatural,
    (Frac, Frac, Frac),
    Option<(Frac, Frac, Frac)>,
    Frac,
);

/// natural_from_parts(kind, first, second, name, value) -> (NativeNatural,
/// first, second, value)
///
/// A natural quadric from Python numbers (as `exact()` takes them):
/// `("sphere", center, None, "radius2", r2)`, `("cylinder", point, axis,
/// "radius2", r2)`, `("cone", vertex, axis, "tan2" | "tan" | "cos2" |
/// "sin2", value)`; checked as its JSON form is, and returned with its
/// canonical fields (a cone's angle as `tan2`).
#[pyfunction]
pub(crate) fn natural_from_parts(
    py: Python<'_>,
    kind: &str,
    first: Triple<'_>,
    second: Option<Triple<'_>>,
    name: &str,
    value: &Bound<'_, PyAny>,
) -> PyResult<Parts> {
    let p = triple(&first)?;
    let v = second.as_ref().map(triple).transpose()?;
    let x = to_rational(value)?;
    let q = guard::run(py, || {
        let bad = || Error::new(ErrorKind::BadQuadric, format!("bad fields for a {kind}"));
        Ok(match (kind, v, name) {
            ("sphere", None, "radius2") => Natural::Sphere(Sphere::new(p, x)?),
            ("cylinder", Some(v), "radius2") => Natural::Cylinder(Cylinder::new(p, v, x)?),
            ("cone", Some(v), "tan2") => Natural::Cone(Cone::new(p, v, x)?),
            ("cone", Some(v), _) => {
                // the other angle parameters, converted by the engine
                let f = |c: &[Rational; 3]| c.iter().map(|x| x.to_string()).collect::<Vec<_>>();
                let json = serde_json::json!({
                    "kind": "cone", "vertex": f(&p), "axis": f(&v), name: x.to_string(),
                });
                json.to_string().parse::<Natural>()?
            }
            _ => return Err(bad()),
        })
    })?;
    let (first, second, value) = match &q {
        Natural::Sphere(s) => (frac3(s.center()), None, s.radius2()),
        Natural::Cylinder(c) => (frac3(c.point()), Some(frac3(c.axis())), c.radius2()),
        Natural::Cone(c) => (frac3(c.vertex()), Some(frac3(c.axis())), c.tan2()),
    };
    let value = Frac(value.clone());
    Ok((NativeNatural { q }, first, second, value))
}

/// A quadric argument: the engine form of a typed quadric, or text.
#[derive(FromPyObject)]
pub(crate) enum NaturalArg<'py> {
    Native(Bound<'py, NativeNatural>),
    Text(String),
}

/// A quadric argument resolved to something that crosses into the engine
/// with the GIL released.
enum Input<'a> {
    Parsed(&'a Natural),
    Text(&'a str),
}

impl<'a> Input<'a> {
    fn of(arg: &'a NaturalArg<'_>) -> Input<'a> {
        match arg {
            NaturalArg::Native(n) => Input::Parsed(&n.get().q),
            NaturalArg::Text(t) => Input::Text(t),
        }
    }

    fn natural(&self, what: &str) -> Result<std::borrow::Cow<'a, Natural>, Error> {
        match self {
            Input::Parsed(q) => Ok(std::borrow::Cow::Borrowed(*q)),
            Input::Text(t) => t
                .parse()
                .map(std::borrow::Cow::Owned)
                .map_err(|e: Error| e.context(what)),
        }
    }
}

fn options(
    py: Python<'_>,
    time_limit: Option<f64>,
    components: bool,
    referee: bool,
) -> PyResult<ClassifyOptions> {
    let mut options = ClassifyOptions::with_budget(guard::budget(py, time_limit)?);
    options.components = components;
    options.referee = referee;
    Ok(options)
}

/// What the result class reads at once: class, conics, lines, points
/// (`None` when undecided), axes, thm8, method, and `(kind, message)` of an
/// undecided answer.
type Head = (
    &'static str,
    Option<usize>,
    Option<usize>,
    Option<usize>,
    Option<&'static str>,
    Option<bool>,
    String,
    Option<(&'static str, String)>,
);

/// natural(a, b, time_limit, components, referee) -> (NativeReport, head)
///
/// `a`, `b`: a `NativeNatural`, or text in the short syntax or the JSON
/// object form; `components = false` asks for the class and counts only
/// (the fast route); `referee = true` adds the stability interval (in the
/// JSON).  `head` is [`NativeReport::head`].
#[pyfunction]
#[pyo3(signature = (a, b, time_limit = None, components = true, referee = false))]
pub(crate) fn natural(
    py: Python<'_>,
    a: NaturalArg<'_>,
    b: NaturalArg<'_>,
    time_limit: Option<f64>,
    components: bool,
    referee: bool,
) -> PyResult<(NativeReport, Head)> {
    let options = options(py, time_limit, components, referee)?;
    let (ia, ib) = (Input::of(&a), Input::of(&b));
    let r = guard::run(py, || {
        let qa = ia.natural("in the first quadric")?;
        let qb = ib.natural("in the second quadric")?;
        // boxed at once: the report is large, and moves of it would cost
        // a noticeable part of a fast call
        Ok(Box::new(quadsect::classify_with(&qa, &qb, &options)?))
    })?;
    let report = NativeReport { r };
    let head = report.head();
    Ok((report, head))
}

/// _engine_time(a, b, components=True, number=1000) -> float
///
/// Seconds per call of the engine's classification alone (the quadrics
/// parsed beforehand, as `quadsect bench natural` times it), over `number`
/// calls: the reference for the binding's overhead (`scripts/bench_python.py`).
#[pyfunction]
#[pyo3(signature = (a, b, components = true, number = 1000))]
pub(crate) fn _engine_time(
    py: Python<'_>,
    a: NaturalArg<'_>,
    b: NaturalArg<'_>,
    components: bool,
    number: u32,
) -> PyResult<f64> {
    let options = options(py, None, components, false)?;
    let (ia, ib) = (Input::of(&a), Input::of(&b));
    guard::run(py, || {
        let qa = ia.natural("in the first quadric")?;
        let qb = ib.natural("in the second quadric")?;
        let t = Instant::now();
        for _ in 0..number.max(1) {
            std::hint::black_box(quadsect::classify_with(&qa, &qb, &options)?);
        }
        Ok(t.elapsed().as_secs_f64() / f64::from(number.max(1)))
    })
}

/// The engine's answer to `natural()`, read by the Python half
/// (`NaturalResult`) on demand.
#[pyclass(frozen, module = "quadsect._quadsect", name = "NativeReport")]
pub(crate) struct NativeReport {
    r: Box<NaturalReport>,
}

impl NativeReport {
    fn head(&self) -> Head {
        let r = &self.r;
        let decided = r.class() != Class::Undecided;
        let count = |n: usize| decided.then_some(n);
        (
            r.class().as_str(),
            count(r.conics()),
            count(r.lines()),
            count(r.points()),
            r.axes().map(|a| a.as_str()),
            r.thm8(),
            r.method_description().to_string(),
            r.exhausted().map(|e| ("budget", e.to_string())),
        )
    }
}

#[pymethods]
impl NativeReport {
    /// The CLI's `--json` text.
    fn json(&self, py: Python<'_>) -> PyResult<String> {
        guard::run(py, || Ok(self.r.to_json_string()))
    }

    /// The human summary, as the CLI prints it.
    fn text(&self, py: Python<'_>) -> PyResult<String> {
        guard::run(py, || Ok(self.r.to_string()))
    }

    /// Remarks.
    fn notes(&self) -> Vec<String> {
        self.r.notes().to_vec()
    }

    /// The picture of the answer (SVG text, `NaturalReport::svg`).
    fn svg(&self, py: Python<'_>) -> PyResult<String> {
        guard::run(py, || Ok(self.r.svg()))
    }

    /// The components as tuples (see `quadsect/_components.py`,
    /// `_component`): exact numbers and `(value, bound)` doubles.
    fn components<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        let parts = guard::run(py, || {
            self.r
                .components()
                .iter()
                .map(Part::of)
                .collect::<Result<Vec<_>, Error>>()
        })?;
        parts.iter().map(|p| p.to_python(py)).collect()
    }
}

/// A double and a proven bound on its error.
type F64 = (f64, f64);

/// An exact number with its certified double.
struct Num {
    x: Exact,
    f: F64,
}

impl Num {
    fn new(x: &Exact) -> Num {
        Num {
            x: x.clone(),
            f: x.to_f64_bounded(),
        }
    }

    fn quad(x: &QSqrt) -> Num {
        Num {
            x: Exact::Quad(x.clone()),
            f: x.to_f64_bounded(),
        }
    }
}

type Pt = [Num; 3];

fn pt(p: &EPoint) -> Pt {
    std::array::from_fn(|i| Num::new(&p[i]))
}

fn qpt(p: &[QSqrt; 3]) -> Pt {
    std::array::from_fn(|i| Num::quad(&p[i]))
}

/// A branch of a curve: bounded, its certified point, and its ruling data.
struct Branch {
    bounded: bool,
    point: [F64; 3],
    ruling_point: Pt,
    ruling_direction: Pt,
    quadratic: Pt,
    root: i32,
    t: Option<Num>,
}

/// A component in the form the answers print (planes and rational
/// directions normalized, as in the JSON), every number with its certified
/// double: computed by the engine with the GIL released, then converted.
// a few per answer, each converted to Python at once: the size of a conic
// beside a line costs nothing worth a box
#[allow(clippy::large_enum_variant)]
enum Part {
    Conic {
        kind: &'static str,
        normal: Pt,
        offset: Num,
        center: Option<Pt>,
        vertex: Option<Pt>,
        axes2: Vec<Num>,
        dirs: Vec<Pt>,
        focal2: Option<Num>,
        double: bool,
    },
    Line {
        point: Pt,
        direction: Pt,
        double: bool,
    },
    Point {
        point: Pt,
        kind: &'static str,
    },
    Curve {
        degree: u32,
        singular: Vec<(Pt, &'static str, bool)>,
        branches: Vec<Branch>,
    },
}

impl Part {
    fn of(c: &Component) -> Result<Part, Error> {
        Ok(match c {
            Component::Conic {
                plane,
                kind,
                center,
                vertex,
                axes2,
                axis_dirs,
                focal2,
                double,
            } => {
                let (normal, offset) = normalize_plane(plane);
                Part::Conic {
                    kind: kind.as_str(),
                    normal: pt(&normal),
                    offset: Num::new(&offset),
                    center: center.as_ref().map(pt),
                    vertex: vertex.as_ref().map(pt),
                    axes2: axes2.iter().map(Num::new).collect(),
                    dirs: axis_dirs
                        .iter()
                        .map(|d| pt(&normalize_axis_direction(d, *kind)))
                        .collect(),
                    focal2: focal2.as_ref().map(Num::new),
                    double: *double,
                }
            }
            Component::Line {
                point,
                direction,
                double,
            } => Part::Line {
                point: pt(point),
                direction: pt(direction),
                double: *double,
            },
            Component::Point { point, kind } => Part::Point {
                point: pt(point),
                kind: kind.as_str(),
            },
            Component::Curve {
                degree,
                singular,
                branches,
            } => Part::Curve {
                degree: *degree,
                singular: singular.iter().map(singular_part).collect(),
                branches: branches.iter().map(branch_part).collect(),
            },
            _ => return Err(Error::internal("a component of an unknown type")),
        })
    }

    /// The tuple `quadsect._components._component` reads: the type, then
    /// the exact fields, then their certified doubles in the same order.
    fn to_python<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let tag = |s: &'static str| PyString::intern(py, s).into_any();
        let none = || py.None().into_bound(py);
        let flag = |b: bool| -> PyResult<Bound<'py, PyAny>> {
            Ok(b.into_pyobject(py)?.to_owned().into_any())
        };
        let items: Vec<Bound<'py, PyAny>> = match self {
            Part::Conic {
                kind,
                normal,
                offset,
                center,
                vertex,
                axes2,
                dirs,
                focal2,
                double,
            } => {
                let plane = tuple_of(
                    py,
                    [
                        exact_pt(py, normal),
                        exact_py(py, &offset.x),
                        f64_pt(py, normal),
                        f64_py(py, offset.f),
                    ]
                    .into_iter(),
                )?;
                let opt =
                    |p: &Option<Pt>, f: fn(Python<'py>, &Pt) -> PyResult<Bound<'py, PyAny>>| {
                        p.as_ref().map_or_else(|| Ok(none()), |p| f(py, p))
                    };
                vec![
                    tag("conic"),
                    tag(kind),
                    plane,
                    opt(center, exact_pt)?,
                    opt(vertex, exact_pt)?,
                    tuple_of(py, axes2.iter().map(|x| exact_py(py, &x.x)))?,
                    tuple_of(py, dirs.iter().map(|d| exact_pt(py, d)))?,
                    focal2
                        .as_ref()
                        .map_or_else(|| Ok(none()), |x| exact_py(py, &x.x))?,
                    flag(*double)?,
                    opt(center, f64_pt)?,
                    opt(vertex, f64_pt)?,
                    tuple_of(py, axes2.iter().map(|x| f64_py(py, x.f)))?,
                    tuple_of(py, dirs.iter().map(|d| f64_pt(py, d)))?,
                    focal2
                        .as_ref()
                        .map_or_else(|| Ok(none()), |x| f64_py(py, x.f))?,
                ]
            }
            Part::Line {
                point,
                direction,
                double,
            } => vec![
                tag("line"),
                exact_pt(py, point)?,
                exact_pt(py, direction)?,
                flag(*double)?,
                f64_pt(py, point)?,
                f64_pt(py, direction)?,
            ],
            Part::Point { point, kind } => vec![
                tag("point"),
                exact_pt(py, point)?,
                tag(kind),
                f64_pt(py, point)?,
            ],
            Part::Curve {
                degree,
                singular,
                branches,
            } => vec![
                tag("curve"),
                degree.into_pyobject(py)?.into_any(),
                tuple_of(
                    py,
                    singular.iter().map(|(p, kind, isolated)| {
                        tuple_of(
                            py,
                            [
                                exact_pt(py, p),
                                Ok(tag(kind)),
                                flag(*isolated),
                                f64_pt(py, p),
                            ]
                            .into_iter(),
                        )
                    }),
                )?,
                tuple_of(py, branches.iter().map(|b| branch_py(py, b)))?,
            ],
        };
        PyTuple::new(py, items)
    }
}

fn singular_part(s: &SingularPoint) -> (Pt, &'static str, bool) {
    (pt(&s.point), s.kind.as_str(), s.is_isolated())
}

fn branch_part(b: &CurveBranch) -> Branch {
    let p = &b.start;
    let (rp, rd) = p.ruling();
    Branch {
        bounded: b.bounded,
        point: p.approx(),
        ruling_point: qpt(rp),
        ruling_direction: qpt(rd),
        quadratic: qpt(p.quadratic()),
        root: p.root(),
        t: p.parameter().map(Num::quad),
    }
}

/// `(bounded, point_f64, ruling_point, ruling_direction, quadratic, root,
/// t, ruling_point_f64, ruling_direction_f64, quadratic_f64, t_f64)`.
fn branch_py<'py>(py: Python<'py>, b: &Branch) -> PyResult<Bound<'py, PyAny>> {
    let none = || Ok(py.None().into_bound(py));
    let items = [
        Ok(b.bounded.into_pyobject(py)?.to_owned().into_any()),
        tuple_of(py, b.point.iter().map(|f| f64_py(py, *f))),
        exact_pt(py, &b.ruling_point),
        exact_pt(py, &b.ruling_direction),
        exact_pt(py, &b.quadratic),
        Ok(b.root.into_pyobject(py)?.into_any()),
        b.t.as_ref().map_or_else(none, |t| exact_py(py, &t.x)),
        f64_pt(py, &b.ruling_point),
        f64_pt(py, &b.ruling_direction),
        f64_pt(py, &b.quadratic),
        b.t.as_ref().map_or_else(none, |t| f64_py(py, t.f)),
    ];
    tuple_of(py, items.into_iter())
}

fn tuple_of<'py>(
    py: Python<'py>,
    items: impl Iterator<Item = PyResult<Bound<'py, PyAny>>>,
) -> PyResult<Bound<'py, PyAny>> {
    let v = items.collect::<PyResult<Vec<_>>>()?;
    Ok(PyTuple::new(py, v)?.into_any())
}

/// An exact number: a `Fraction` for a rational, a `QuadraticIrrational`
/// for `a + b√d`, a `RealAlgebraic` otherwise (as the JSON spells them:
/// a string, `{a, b, d}`, `{poly, interval}`).
fn exact_py<'py>(py: Python<'py>, x: &Exact) -> PyResult<Bound<'py, PyAny>> {
    match x {
        Exact::Quad(q) if q.is_rational() => fraction(py, q.a()),
        Exact::Quad(q) => Ok(Bound::new(py, QuadraticIrrational::new(q))?.into_any()),
        Exact::Alg(a) => Ok(Bound::new(py, RealAlgebraic::new(a.clone()))?.into_any()),
        other => Ok(Bound::new(py, RealAlgebraic::new(other.to_alg()))?.into_any()),
    }
}

fn exact_pt<'py>(py: Python<'py>, p: &Pt) -> PyResult<Bound<'py, PyAny>> {
    tuple_of(py, p.iter().map(|n| exact_py(py, &n.x)))
}

fn f64_py<'py>(py: Python<'py>, f: F64) -> PyResult<Bound<'py, PyAny>> {
    Ok(f.into_pyobject(py)?.into_any())
}

fn f64_pt<'py>(py: Python<'py>, p: &Pt) -> PyResult<Bound<'py, PyAny>> {
    tuple_of(py, p.iter().map(|n| f64_py(py, n.f)))
}
