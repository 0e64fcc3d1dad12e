//! `quadsect._quadsect`: the compiled half of the Python package `quadsect`.
//!
//! Everything that touches the engine is here: the four jobs (tangent,
//! natural, roots, resultant), the batch protocol (`answer_line`, the
//! streaming `Batch` iterator), exact number input and the exact real
//! algebraic numbers `RealAlgebraic`, the quadratic irrationals
//! `QuadraticIrrational`, and the engine forms of natural quadrics and of
//! their answers (`NativeNatural`, `NativeReport`, read on demand).  The pure-Python half
//! (`quadsect/__init__.py`) wraps the answers into result classes.
//!
//! Two rules hold at every entry point (see [`guard::run`]):
//! * the GIL is released while the engine computes (`Python::detach`), so
//!   Python threads run in parallel with it;
//! * nothing panics into Python: a panic is caught and becomes
//!   `quadsect.InternalError`, an engine error becomes `InputError`
//!   (`ValueError`), `BudgetError` or `InternalError`, with the engine's
//!   kind string in `.kind`.

use pyo3::prelude::*;

mod batch;
mod contact;
mod guard;
mod jobs;
mod natural;
mod numbers;

/// The module object: functions and classes of the compiled half.
#[pymodule]
fn _quadsect(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add(
        "DEFAULT_TIME_LIMIT",
        quadsect::budget::DEFAULT_TIME_LIMIT.as_secs_f64(),
    )?;
    m.add_class::<numbers::RealAlgebraic>()?;
    m.add_class::<numbers::QuadraticIrrational>()?;
    m.add_class::<natural::NativeNatural>()?;
    m.add_class::<natural::NativeReport>()?;
    m.add_class::<batch::Batch>()?;
    m.add_function(wrap_pyfunction!(numbers::exact, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::tangent, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::tangent_svg, m)?)?;
    m.add_function(wrap_pyfunction!(natural::natural, m)?)?;
    m.add_function(wrap_pyfunction!(natural::natural_native, m)?)?;
    m.add_function(wrap_pyfunction!(natural::natural_from_parts, m)?)?;
    m.add_function(wrap_pyfunction!(natural::_engine_time, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::roots, m)?)?;
    m.add_function(wrap_pyfunction!(jobs::resultant, m)?)?;
    m.add_function(wrap_pyfunction!(batch::answer_line, m)?)?;
    m.add_function(wrap_pyfunction!(contact::ellipsoid_contact_bytes, m)?)?;
    Ok(())
}
