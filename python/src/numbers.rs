//! Exact numbers across the boundary: Python numbers in (`int`,
//! `Fraction`, `str` in the engine's syntax, `float` and `Decimal` by their
//! exact value), `fractions.Fraction` out, and the exact real algebraic
//! numbers `RealAlgebraic`.

use crate::guard::{self, input_error};
use num_bigint::BigInt;
use num_traits::{One, ToPrimitive, Zero};
use pyo3::basic::CompareOp;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyFloat, PyInt, PyString, PyTuple, PyType};
use quadsect::{ErrorKind, IntPoly, QSqrt, Rational, RealAlg};
use std::cmp::Ordering;
use std::hash::{Hash, Hasher};
use std::sync::OnceLock;

/// The exact value of a Python number: a `str` is read by the engine's
/// number syntax (`-12`, `7/9`, `1.5`, `1e-12`); a `bool` is refused; an
/// `int` is itself; anything with `as_integer_ratio()` (`float`, `Fraction`,
/// `Decimal`, NumPy scalars) or with `numerator`/`denominator` is taken
/// exactly (a float as its binary value).
pub(crate) fn to_rational(x: &Bound<'_, PyAny>) -> PyResult<Rational> {
    let py = x.py();
    if let Ok(s) = x.cast::<PyString>() {
        let text = s.to_cow()?;
        return quadsect::parse_rational(&text).map_err(|e| guard::py_error(py, &e));
    }
    if x.is_instance_of::<PyBool>() {
        return Err(input_error(
            py,
            ErrorKind::Number,
            "a bool is not a number here (write 0 or 1)",
        ));
    }
    if x.is_instance_of::<PyInt>() {
        return Ok(Rational::from_integer(big_int(x)?));
    }
    let (n, d) = if x.hasattr("as_integer_ratio")? {
        match x.call_method0(pyo3::intern!(py, "as_integer_ratio")) {
            Ok(pair) => {
                let (n, d) = pair.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>()?;
                (big_int(&n)?, big_int(&d)?)
            }
            // nan and infinities have no exact value (ValueError / OverflowError)
            Err(_) => {
                return Err(input_error(
                    py,
                    ErrorKind::Number,
                    format!("{} has no exact value", x.repr()?),
                ));
            }
        }
    } else if x.hasattr("numerator")? && x.hasattr("denominator")? {
        (
            big_int(&x.getattr("numerator")?)?,
            big_int(&x.getattr("denominator")?)?,
        )
    } else {
        return Err(PyTypeError::new_err(format!(
            "expected a number (int, Fraction, float, Decimal or str), got {}",
            x.get_type().name()?
        )));
    };
    if d.is_zero() {
        return Err(input_error(py, ErrorKind::Number, "zero denominator"));
    }
    Ok(Rational::new(n, d))
}

/// A Python int as a `BigInt`: through a machine integer when it fits (the
/// limited API's conversion of big integers goes through `int.to_bytes`).
fn big_int(x: &Bound<'_, PyAny>) -> PyResult<BigInt> {
    match x.extract::<i64>() {
        Ok(v) => Ok(BigInt::from(v)),
        Err(_) => x.extract::<BigInt>(),
    }
}

/// An exact rational on its way to Python as a `fractions.Fraction`.
///
/// PyO3's own conversion builds the numerator and denominator through
/// `int.from_bytes` under the limited API (abi3), several microseconds
/// each; machine-size ones go through `PyLong_FromLongLong` here.
pub(crate) struct Frac(pub(crate) Rational);

static FRACTION: PyOnceLock<Py<PyType>> = PyOnceLock::new();

impl<'py> IntoPyObject<'py> for Frac {
    type Target = PyAny;
    type Output = Bound<'py, PyAny>;
    type Error = PyErr;

    fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        fraction(py, &self.0)
    }
}

/// The small integers as `Fraction`s, made once (a `Fraction` is
/// immutable; components hold many zeros and ones).
static SMALL: PyOnceLock<Vec<Py<PyAny>>> = PyOnceLock::new();
const SMALL_MAX: i64 = 16;

/// `fractions.Fraction(q)`.
pub(crate) fn fraction<'py>(py: Python<'py>, q: &Rational) -> PyResult<Bound<'py, PyAny>> {
    let cls = FRACTION.import(py, "fractions", "Fraction")?;
    if q.denom().is_one()
        && let Some(n) = q.numer().to_i64()
        && (-SMALL_MAX..=SMALL_MAX).contains(&n)
    {
        let small = SMALL.get_or_try_init(py, || {
            (-SMALL_MAX..=SMALL_MAX)
                .map(|k| cls.call1((k,)).map(Bound::unbind))
                .collect::<PyResult<Vec<_>>>()
        })?;
        return Ok(small[(n + SMALL_MAX) as usize].bind(py).clone());
    }
    match (q.numer().to_i64(), q.denom().to_i64()) {
        (Some(n), Some(1)) => cls.call1((n,)),
        (Some(n), Some(d)) => cls.call1((n, d)),
        _ => cls.call1((q.numer().clone(), q.denom().clone())),
    }
}

/// exact(x) -> Fraction
///
/// The exact value quadsect takes for the number ``x``: an ``int``, a
/// ``Fraction``, a ``str`` in the engine's syntax (``"-12"``, ``"7/9"``,
/// ``"1.5"``, ``"1e-12"``), or a ``float`` / ``Decimal`` by its exact
/// value (``0.1`` is 3602879701896397/36028797018963968).
///
/// >>> quadsect.exact("2.5E-1")
/// Fraction(1, 4)
/// >>> quadsect.exact(0.1) == Fraction(0.1)
/// True
#[pyfunction]
pub(crate) fn exact(x: &Bound<'_, PyAny>) -> PyResult<Frac> {
    to_rational(x).map(Frac)
}

/// An exact real algebraic number: the unique root of a square-free
/// integer polynomial ``poly`` (in ``u``) in the isolating interval
/// ``interval`` (two ``Fraction`` s; equal ends for a rational value).
///
/// Comparisons (``==``, ``<``, …) with other ``RealAlgebraic`` numbers,
/// ``int``, ``Fraction`` and ``float`` (its exact value) are exact, and
/// equal numbers hash equally (a rational value hashes like the equal
/// ``Fraction`` / ``int``), so they can be sorted and used as keys.
///
/// >>> r = RealAlgebraic("u^2 - 2", (1, 2))   # √2
/// >>> r > Fraction(7, 5), r < 1.4142135623730951, float(r)
/// (True, True, 1.4142135623730951)
/// >>> RealAlgebraic("u^4 - 4", (0, 3)) == r
/// True
#[pyclass(frozen, module = "quadsect", name = "RealAlgebraic")]
pub(crate) struct RealAlgebraic {
    value: RealAlg,
    /// The exact rational value, when the number is rational (computed once).
    rational: OnceLock<Option<Rational>>,
}

impl RealAlgebraic {
    pub(crate) fn new(value: RealAlg) -> RealAlgebraic {
        RealAlgebraic {
            value,
            rational: OnceLock::new(),
        }
    }

    /// The value as a rational, when it is one (decided by
    /// `RealAlg::simplify`: complete for leading coefficients below 2^1023).
    fn rational_value(&self) -> &Option<Rational> {
        self.rational.get_or_init(|| {
            let (lo, hi) = self.value.simplify().interval();
            (lo == hi).then_some(lo)
        })
    }

    /// The order against a Python operand, or `None` when the operand is
    /// not a number this class compares with.
    fn compare(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Option<Ordering>> {
        if let Ok(o) = other.cast::<RealAlgebraic>() {
            let b = o.get();
            return guard::run(py, || Ok(Some(self.value.cmp(&b.value))));
        }
        if let Ok(o) = other.cast::<QuadraticIrrational>() {
            let b = o.get();
            return guard::run(py, || Ok(Some(self.value.cmp(b.algebraic()))));
        }
        if other.is_instance_of::<PyString>() || other.is_instance_of::<PyBool>() {
            return Ok(None);
        }
        if let Some(ord) = against_infinity(other) {
            return Ok(ord);
        }
        let Ok(q) = to_rational(other) else {
            return Ok(None);
        };
        guard::run(py, || Ok(self.value.partial_cmp(&q)))
    }

    /// The exact double nearest to the value.
    fn nearest_f64(&self, py: Python<'_>) -> PyResult<f64> {
        nearest_f64(py, self.rational_value().clone(), |bits| {
            guard::run(py, || Ok(self.value.to_rational_approx(bits)))
        })
    }
}

/// The double nearest to a real number given exactly when rational, or by
/// rational approximations within `2^-bits` (ties cannot occur for an
/// irrational number): refine until both ends of an enclosure round to the
/// same double.
fn nearest_f64(
    py: Python<'_>,
    rational: Option<Rational>,
    approx: impl Fn(u32) -> PyResult<Rational>,
) -> PyResult<f64> {
    let to_f64 = |q: Rational| -> PyResult<f64> {
        // Python's Fraction -> float is correctly rounded
        fraction(py, &q)?.call_method0("__float__")?.extract()
    };
    if let Some(q) = rational {
        return to_f64(q);
    }
    let mut bits = 64u32;
    loop {
        let m = approx(bits)?;
        let eps = Rational::new(BigInt::one(), BigInt::one() << bits as usize);
        let (lo, hi) = (to_f64(&m - &eps)?, to_f64(&m + &eps)?);
        if lo == hi || bits >= 1 << 13 {
            return Ok(lo);
        }
        bits *= 2;
    }
}

/// -1, 0 or 1.
fn sign_int(s: quadsect::Sign) -> i32 {
    match s {
        quadsect::Sign::Negative => -1,
        quadsect::Sign::Zero => 0,
        quadsect::Sign::Positive => 1,
    }
}

/// The order of an exact number against ±infinity (a float), or `None`
/// for nan; `Some(None)` when `other` is no infinite float.
fn against_infinity(other: &Bound<'_, PyAny>) -> Option<Option<Ordering>> {
    let f = other.cast::<PyFloat>().ok()?;
    let v = f.value();
    if v.is_nan() {
        return Some(None);
    }
    if v.is_infinite() {
        return Some(Some(if v > 0.0 {
            Ordering::Less
        } else {
            Ordering::Greater
        }));
    }
    None
}

/// A comparison result as Python sees it: the order, or `NotImplemented`
/// for an operand of another type (nan compares unequal to everything).
fn rich_result(
    py: Python<'_>,
    ord: Option<Ordering>,
    other: &Bound<'_, PyAny>,
    op: CompareOp,
) -> Py<PyAny> {
    let Some(ord) = ord else {
        if other.cast::<PyFloat>().is_ok() {
            return PyBool::new(py, matches!(op, CompareOp::Ne))
                .to_owned()
                .into_any()
                .unbind();
        }
        return py.NotImplemented();
    };
    PyBool::new(py, op.matches(ord))
        .to_owned()
        .into_any()
        .unbind()
}

/// The hash Python sees for an irrational real algebraic number (the
/// engine's exact hash, `floor(2^32 x)`); `-1` is reserved by CPython.
fn algebraic_hash(value: &RealAlg) -> isize {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    value.hash(&mut h);
    let v = h.finish() as i64 as isize;
    if v == -1 { -2 } else { v }
}

#[pymethods]
impl RealAlgebraic {
    /// RealAlgebraic(poly: str, interval: tuple[Number, Number])
    ///
    /// The root of ``poly`` (one variable, integer coefficients) in the
    /// closed interval ``[lo, hi]``, checked: ``poly`` must have exactly
    /// one distinct real root there (``lo == hi`` asks for the rational
    /// ``lo``, which must be a root).  Raises ``InputError`` otherwise.
    #[new]
    fn py_new(
        py: Python<'_>,
        poly: &str,
        interval: (Bound<'_, PyAny>, Bound<'_, PyAny>),
    ) -> PyResult<Self> {
        let lo = to_rational(&interval.0)?;
        let hi = to_rational(&interval.1)?;
        let value = guard::run(py, || {
            let p: IntPoly = poly.parse()?;
            RealAlg::new(&p, &lo, &hi)
        })?;
        Ok(RealAlgebraic::new(value))
    }

    /// RealAlgebraic.from_number(x) -> RealAlgebraic
    ///
    /// The number ``x`` (int, Fraction, str, float, Decimal) as a
    /// ``RealAlgebraic``.
    #[staticmethod]
    fn from_number(x: &Bound<'_, PyAny>) -> PyResult<RealAlgebraic> {
        Ok(RealAlgebraic::new(RealAlg::from(to_rational(x)?)))
    }

    /// The defining polynomial in ``u``: square-free, primitive, positive
    /// leading coefficient (``d*u - n`` for a rational ``n/d``).
    #[getter]
    fn poly(&self) -> String {
        self.value.defining_poly().to_string()
    }

    /// The isolating interval ``(lo, hi)`` as two ``Fraction`` s (equal
    /// ends for a rational value; otherwise the root lies strictly inside).
    #[getter]
    fn interval(&self) -> (Frac, Frac) {
        let (lo, hi) = self.value.interval();
        (Frac(lo), Frac(hi))
    }

    /// True when the value is rational.
    #[getter]
    fn is_rational(&self) -> bool {
        self.rational_value().is_some()
    }

    /// The exact sign: -1, 0 or 1.
    #[getter]
    fn sign(&self) -> i32 {
        sign_int(self.value.sign())
    }

    /// exact_fraction() -> Fraction | None
    ///
    /// The exact value as a ``Fraction`` when it is rational, else ``None``.
    fn exact_fraction(&self) -> Option<Frac> {
        self.rational_value().clone().map(Frac)
    }

    /// approx_fraction(bits=64) -> Fraction
    ///
    /// A ``Fraction`` within ``2**-bits`` of the value (the value itself
    /// when it is rational).
    #[pyo3(signature = (bits = 64))]
    fn approx_fraction(&self, py: Python<'_>, bits: u32) -> PyResult<Frac> {
        if let Some(q) = self.rational_value() {
            return Ok(Frac(q.clone()));
        }
        guard::run(py, || Ok(Frac(self.value.to_rational_approx(bits))))
    }

    /// approx(digits=20) -> str
    ///
    /// A decimal approximation with ``digits`` significant digits.
    #[pyo3(signature = (digits = 20))]
    fn approx(&self, py: Python<'_>, digits: usize) -> PyResult<String> {
        guard::run(py, || Ok(self.value.approx(digits.max(1))))
    }

    /// to_json() -> dict
    ///
    /// The JSON form of the CLI: ``{"poly": …, "interval": [lo, hi],
    /// "approx": …}`` with exact strings.
    fn to_json<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = guard::run(py, || {
            serde_json::to_string(&self.value).map_err(|e| quadsect::Error::internal(e.to_string()))
        })?;
        py.import("json")?.call_method1("loads", (text,))
    }

    fn __float__(&self, py: Python<'_>) -> PyResult<f64> {
        self.nearest_f64(py)
    }

    fn __bool__(&self) -> bool {
        self.sign() != 0
    }

    fn __richcmp__(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        op: CompareOp,
    ) -> PyResult<Py<PyAny>> {
        let ord = self.compare(py, other)?;
        Ok(rich_result(py, ord, other, op))
    }

    /// A rational value hashes like the equal `Fraction` (and `int`);
    /// an irrational one by `floor(2^32 x)` (the engine's exact hash).
    fn __hash__(&self, py: Python<'_>) -> PyResult<isize> {
        if let Some(q) = self.rational_value() {
            return fraction(py, q)?.hash();
        }
        Ok(algebraic_hash(&self.value))
    }

    fn __repr__(&self) -> String {
        let (lo, hi) = self.value.interval();
        format!("RealAlgebraic('{}', ('{}', '{}'))", self.poly(), lo, hi)
    }

    fn __str__(&self) -> String {
        self.value.to_string()
    }

    /// Pickling (Dask, multiprocessing): rebuilt from poly and interval.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let (lo, hi) = self.value.interval();
        let args = (self.poly(), (lo.to_string(), hi.to_string()));
        (py.get_type::<RealAlgebraic>(), args).into_pyobject(py)
    }
}

/// An exact quadratic irrational ``a + b·√d``: rational ``a`` and ``b``
/// (``Fraction``) and a square-free integer radicand ``d > 1`` — the
/// numbers of one square root that the natural-quadric components hold
/// (centres, semi-axes, lines of a degenerate conic).  ``d`` is made
/// square-free on construction (``√8 = 2√2``); a square ``d`` folds into
/// ``a`` (then ``b == d == 0`` and :attr:`is_rational` is true).
///
/// Comparisons with ``QuadraticIrrational`` (of any field Q(√d)),
/// ``RealAlgebraic``, ``int``, ``Fraction`` and ``float`` are exact, and
/// equal numbers hash equally (also across the two classes).
///
/// >>> x = QuadraticIrrational(1, 2, 8)   # 1 + 2√8 = 1 + 4√2
/// >>> x.a, x.b, x.d
/// (Fraction(1, 1), Fraction(4, 1), Fraction(2, 1))
/// >>> str(x), x > 6, float(x)
/// ('1 + 4·√(2)', True, 6.656854249492381)
/// >>> x == RealAlgebraic("u^2 - 2*u - 31", (6, 7))
/// True
#[pyclass(frozen, module = "quadsect", name = "QuadraticIrrational")]
pub(crate) struct QuadraticIrrational {
    /// Normalized (square-free integer radicand).
    value: QSqrt,
    /// The value as a real algebraic number (computed once, for comparisons
    /// across fields and the hash).
    alg: OnceLock<RealAlg>,
}

impl QuadraticIrrational {
    /// `x` with its radicand made square-free.
    pub(crate) fn new(x: &QSqrt) -> QuadraticIrrational {
        QuadraticIrrational {
            value: x.normalized(),
            alg: OnceLock::new(),
        }
    }

    fn algebraic(&self) -> &RealAlg {
        self.alg.get_or_init(|| self.value.to_real_alg())
    }

    fn compare(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Option<Ordering>> {
        if let Ok(o) = other.cast::<QuadraticIrrational>() {
            let b = o.get();
            return guard::run(py, || Ok(Some(self.value.cmp(&b.value))));
        }
        if let Ok(o) = other.cast::<RealAlgebraic>() {
            let b = o.get();
            return guard::run(py, || Ok(Some(self.algebraic().cmp(&b.value))));
        }
        if other.is_instance_of::<PyString>() || other.is_instance_of::<PyBool>() {
            return Ok(None);
        }
        if let Some(ord) = against_infinity(other) {
            return Ok(ord);
        }
        let Ok(q) = to_rational(other) else {
            return Ok(None);
        };
        guard::run(py, || Ok(Some(self.value.cmp(&QSqrt::rational(q)))))
    }
}

#[pymethods]
impl QuadraticIrrational {
    /// QuadraticIrrational(a, b, d)
    ///
    /// The number ``a + b·√d`` for numbers ``a``, ``b`` and ``d ≥ 0`` (int,
    /// Fraction, str, float, Decimal: exact values); ``InputError`` for a
    /// negative ``d`` with ``b ≠ 0``.
    #[new]
    fn py_new(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>, d: &Bound<'_, PyAny>) -> PyResult<Self> {
        let py = a.py();
        let (a, b, d) = (to_rational(a)?, to_rational(b)?, to_rational(d)?);
        let x = guard::run(py, || QSqrt::try_new(a, b, d))?;
        Ok(QuadraticIrrational::new(&x))
    }

    /// The rational part ``a`` (a ``Fraction``).
    #[getter]
    fn a(&self) -> Frac {
        Frac(self.value.a().clone())
    }

    /// The coefficient ``b`` of ``√d`` (a ``Fraction``; 0 for a rational value).
    #[getter]
    fn b(&self) -> Frac {
        Frac(self.value.b().clone())
    }

    /// The radicand ``d``: a square-free integer > 1 (a ``Fraction``; 0 for
    /// a rational value).
    #[getter]
    fn d(&self) -> Frac {
        Frac(self.value.d().clone())
    }

    /// True when the value is rational (``b == 0``).
    #[getter]
    fn is_rational(&self) -> bool {
        self.value.is_rational()
    }

    /// The exact sign: -1, 0 or 1.
    #[getter]
    fn sign(&self) -> i32 {
        sign_int(self.value.sign())
    }

    /// to_real_algebraic() -> RealAlgebraic
    ///
    /// The same number as a ``RealAlgebraic`` (a root of
    /// ``(u − a)² − b²d`` cleared of denominators).
    fn to_real_algebraic(&self, py: Python<'_>) -> PyResult<RealAlgebraic> {
        let a = guard::run(py, || Ok(self.algebraic().clone()))?;
        Ok(RealAlgebraic::new(a))
    }

    /// approx_fraction(bits=64) -> Fraction
    ///
    /// A ``Fraction`` within ``2**-bits`` of the value.
    #[pyo3(signature = (bits = 64))]
    fn approx_fraction(&self, py: Python<'_>, bits: u32) -> PyResult<Frac> {
        guard::run(py, || Ok(Frac(self.value.to_rational_approx(bits))))
    }

    /// approx(digits=20) -> str
    ///
    /// A decimal approximation with ``digits`` significant digits, correctly
    /// rounded.
    #[pyo3(signature = (digits = 20))]
    fn approx(&self, py: Python<'_>, digits: usize) -> PyResult<String> {
        guard::run(py, || Ok(self.value.approx(digits.max(1))))
    }

    /// to_f64_bounded() -> tuple[float, float]
    ///
    /// ``(value, bound)``: a double and a proven bound on its error,
    /// ``|x − value| ≤ bound`` (a few units in the last place of ``value``,
    /// at most ``2**-46 * abs(value)``).
    fn to_f64_bounded(&self, py: Python<'_>) -> PyResult<(f64, f64)> {
        guard::run(py, || Ok(self.value.to_f64_bounded()))
    }

    fn __float__(&self, py: Python<'_>) -> PyResult<f64> {
        let rational = self.value.is_rational().then(|| self.value.a().clone());
        nearest_f64(py, rational, |bits| Ok(self.value.to_rational_approx(bits)))
    }

    fn __bool__(&self) -> bool {
        !self.value.is_zero()
    }

    fn __richcmp__(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
        op: CompareOp,
    ) -> PyResult<Py<PyAny>> {
        let ord = self.compare(py, other)?;
        Ok(rich_result(py, ord, other, op))
    }

    /// Consistent with ``RealAlgebraic`` and ``Fraction``: equal values
    /// hash equally.
    fn __hash__(&self, py: Python<'_>) -> PyResult<isize> {
        if self.value.is_rational() {
            return fraction(py, self.value.a())?.hash();
        }
        guard::run(py, || Ok(algebraic_hash(self.algebraic())))
    }

    fn __repr__(&self) -> String {
        let v = &self.value;
        format!("QuadraticIrrational('{}', '{}', '{}')", v.a(), v.b(), v.d())
    }

    fn __str__(&self) -> String {
        self.value.to_string()
    }

    /// Pickling (Dask, multiprocessing): rebuilt from ``a``, ``b``, ``d``.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let v = &self.value;
        let args = (v.a().to_string(), v.b().to_string(), v.d().to_string());
        (py.get_type::<QuadraticIrrational>(), args).into_pyobject(py)
    }
}
