//! The boundary between Python and the engine: run engine code with the GIL
//! released and panics caught, and turn engine errors into the package's
//! Python exceptions.

use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::PyType;
use quadsect::{Budget, Error, ErrorKind};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Duration;

/// The exception classes, defined in Python (`quadsect/_errors.py`) so that
/// they carry `.kind`, docstrings and plain Python subclassing.
static INPUT_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static BUDGET_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();
static INTERNAL_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();

/// The Python exception of an engine error: `InputError` (a `ValueError`)
/// for bad input, `BudgetError` for an exhausted budget, `InternalError`
/// otherwise; constructed as `Class(message, kind)`.
pub(crate) fn py_error(py: Python<'_>, e: &Error) -> PyErr {
    let (cell, name) = match e.kind() {
        ErrorKind::Budget => (&BUDGET_ERROR, "BudgetError"),
        ErrorKind::Internal | ErrorKind::Io => (&INTERNAL_ERROR, "InternalError"),
        _ => (&INPUT_ERROR, "InputError"),
    };
    let built = cell
        .import(py, "quadsect._errors", name)
        .and_then(|cls| cls.call1((e.message(), e.kind().as_str())));
    match built {
        Ok(instance) => PyErr::from_value(instance),
        // the package half is missing (the module imported on its own):
        // the builtin base classes still tell bad input from failures
        Err(_) if e.is_input() => {
            pyo3::exceptions::PyValueError::new_err(format!("{}: {}", e.kind(), e.message()))
        }
        Err(_) => {
            pyo3::exceptions::PyRuntimeError::new_err(format!("{}: {}", e.kind(), e.message()))
        }
    }
}

/// An `InputError` of the given kind.
pub(crate) fn input_error(py: Python<'_>, kind: ErrorKind, message: impl Into<String>) -> PyErr {
    py_error(py, &Error::new(kind, message))
}

/// Runs `f` with the GIL released and panics caught: `Ok` passes through,
/// an engine error or a panic becomes the matching Python exception.
pub(crate) fn run<T: Send>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, Error> + Send,
) -> PyResult<T> {
    match py.detach(|| catch_unwind(AssertUnwindSafe(f))) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(py_error(py, &e)),
        Err(panic) => Err(py_error(
            py,
            &Error::internal(quadsect::batch::panic_message(&panic)),
        )),
    }
}

/// The budget of a call: `time_limit` in seconds (`None`: the library
/// default, [`quadsect::budget::DEFAULT_TIME_LIMIT`]; `inf`: no time
/// limit); the other limits are the library defaults.
pub(crate) fn budget(py: Python<'_>, time_limit: Option<f64>) -> PyResult<Budget> {
    let Some(t) = time_limit else {
        return Ok(Budget::default());
    };
    if t == f64::INFINITY {
        return Ok(Budget::default().with_time_limit(None));
    }
    match Duration::try_from_secs_f64(t) {
        Ok(d) => Ok(Budget::default().with_time_limit(Some(d))),
        Err(_) => Err(input_error(
            py,
            ErrorKind::Input,
            format!("time_limit must be a number of seconds >= 0 (or None), got {t}"),
        )),
    }
}
