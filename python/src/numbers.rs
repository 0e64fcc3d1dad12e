//! Exact numbers across the boundary: Python numbers in (`int`,
//! `Fraction`, `str` in the engine's syntax, `float` and `Decimal` by their
//! exact value), `fractions.Fraction` out, and the exact real algebraic
//! numbers `RealAlgebraic`.

use crate::guard::{self, input_error};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use pyo3::basic::CompareOp;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyString, PyTuple};
use quadsect::{ErrorKind, IntPoly, Rational, RealAlg};
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
        return Ok(Rational::from_integer(x.extract::<BigInt>()?));
    }
    let (n, d) = if x.hasattr("as_integer_ratio")? {
        match x.call_method0("as_integer_ratio") {
            Ok(pair) => pair.extract::<(BigInt, BigInt)>()?,
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
            x.getattr("numerator")?.extract::<BigInt>()?,
            x.getattr("denominator")?.extract::<BigInt>()?,
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
pub(crate) fn exact(x: &Bound<'_, PyAny>) -> PyResult<Rational> {
    to_rational(x)
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
        if other.is_instance_of::<PyString>() || other.is_instance_of::<PyBool>() {
            return Ok(None);
        }
        if let Ok(f) = other.cast::<PyFloat>() {
            let v = f.value();
            if v.is_nan() {
                return Ok(None);
            }
            if v.is_infinite() {
                return Ok(Some(if v > 0.0 {
                    Ordering::Less
                } else {
                    Ordering::Greater
                }));
            }
        }
        let Ok(q) = to_rational(other) else {
            return Ok(None);
        };
        guard::run(py, || Ok(self.value.partial_cmp(&q)))
    }

    /// The exact double nearest to the value (ties cannot occur for an
    /// irrational number): refine until both ends of an enclosure round to
    /// the same double.
    fn nearest_f64(&self, py: Python<'_>) -> PyResult<f64> {
        let to_f64 = |q: Rational| -> PyResult<f64> {
            // Python's Fraction -> float is correctly rounded
            q.into_pyobject(py)?.call_method0("__float__")?.extract()
        };
        if let Some(q) = self.rational_value() {
            return to_f64(q.clone());
        }
        let mut bits = 64u32;
        loop {
            let m = guard::run(py, || Ok(self.value.to_rational_approx(bits)))?;
            let eps = Rational::new(BigInt::one(), BigInt::one() << bits as usize);
            let (lo, hi) = (to_f64(&m - &eps)?, to_f64(&m + &eps)?);
            if lo == hi || bits >= 1 << 13 {
                return Ok(lo);
            }
            bits *= 2;
        }
    }
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
    fn interval(&self) -> (Rational, Rational) {
        self.value.interval()
    }

    /// True when the value is rational.
    #[getter]
    fn is_rational(&self) -> bool {
        self.rational_value().is_some()
    }

    /// The exact sign: -1, 0 or 1.
    #[getter]
    fn sign(&self) -> i32 {
        match self.value.sign() {
            quadsect::Sign::Negative => -1,
            quadsect::Sign::Zero => 0,
            quadsect::Sign::Positive => 1,
        }
    }

    /// exact_fraction() -> Fraction | None
    ///
    /// The exact value as a ``Fraction`` when it is rational, else ``None``.
    fn exact_fraction(&self) -> Option<Rational> {
        self.rational_value().clone()
    }

    /// approx_fraction(bits=64) -> Fraction
    ///
    /// A ``Fraction`` within ``2**-bits`` of the value (the value itself
    /// when it is rational).
    #[pyo3(signature = (bits = 64))]
    fn approx_fraction(&self, py: Python<'_>, bits: u32) -> PyResult<Rational> {
        if let Some(q) = self.rational_value() {
            return Ok(q.clone());
        }
        guard::run(py, || Ok(self.value.to_rational_approx(bits)))
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
        let Some(ord) = self.compare(py, other)? else {
            // nan compares unequal to everything; other types defer
            if other.cast::<PyFloat>().is_ok() {
                return Ok(PyBool::new(py, matches!(op, CompareOp::Ne))
                    .to_owned()
                    .into_any()
                    .unbind());
            }
            return Ok(py.NotImplemented());
        };
        Ok(PyBool::new(py, op.matches(ord))
            .to_owned()
            .into_any()
            .unbind())
    }

    /// A rational value hashes like the equal `Fraction` (and `int`);
    /// an irrational one by `floor(2^32 x)` (the engine's exact hash).
    fn __hash__(&self, py: Python<'_>) -> PyResult<isize> {
        if let Some(q) = self.rational_value() {
            return q.clone().into_pyobject(py)?.hash();
        }
        let mut h = std::collections::hash_map::DefaultHasher::new();
        self.value.hash(&mut h);
        let v = h.finish() as i64 as isize;
        Ok(if v == -1 { -2 } else { v })
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
