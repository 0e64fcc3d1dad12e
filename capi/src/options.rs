//! `qs_options`: the compute budget of a call (time limit, size limits,
//! cancellation), an opaque object so that fields can be added without
//! breaking the ABI.

use crate::boundary::{guard, input_error, qs_error};
use engine::Budget;
use std::ffi::c_int;
use std::ptr;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

/// Options of the `_opts` functions: the compute budget.  Opaque; made by
/// `qs_options_new` (the library's defaults: 10 s, 2 000 000 terms,
/// 4 000 000 coefficient bits), changed by the setters, freed by
/// `qs_options_free`.  A NULL `const qs_options *` means the defaults.
///
/// One object may serve many calls, also concurrently on several threads,
/// once it is set up: the setters must not run while a call uses it;
/// `qs_options_cancel` may run at any time, from any thread.
pub struct qs_options {
    budget: Budget,
    cancel: Arc<AtomicBool>,
    values: bool,
    referee: bool,
}

impl qs_options {
    fn new() -> qs_options {
        let cancel = Arc::new(AtomicBool::new(false));
        qs_options {
            budget: Budget::default().with_cancel_flag(cancel.clone()),
            cancel,
            values: true,
            referee: false,
        }
    }
}

/// Whether the tangent point method computes the exact critical values
/// (NULL: the default, yes).
///
/// # Safety
/// `opts` is NULL or a live `qs_options`.
pub(crate) unsafe fn values_of(opts: *const qs_options) -> bool {
    // SAFETY: the caller's contract
    unsafe { opts.as_ref() }.is_none_or(|o| o.values)
}

/// Whether the natural-quadric calls referee their answer (NULL: the
/// default, no).
///
/// # Safety
/// `opts` is NULL or a live `qs_options`.
pub(crate) unsafe fn referee_of(opts: *const qs_options) -> bool {
    // SAFETY: the caller's contract
    unsafe { opts.as_ref() }.is_some_and(|o| o.referee)
}

/// The budget of `opts` (NULL: the defaults).
///
/// # Safety
/// `opts` is NULL or a live `qs_options`.
pub(crate) unsafe fn budget_of(opts: *const qs_options) -> Budget {
    // SAFETY: the caller's contract
    match unsafe { opts.as_ref() } {
        Some(o) => o.budget.clone(),
        None => Budget::default(),
    }
}

/// A new options object with the defaults (NULL only if the allocation
/// failed).  Free it with `qs_options_free`.
#[unsafe(no_mangle)]
pub extern "C" fn qs_options_new() -> *mut qs_options {
    std::panic::catch_unwind(|| Box::into_raw(Box::new(qs_options::new())))
        .unwrap_or(ptr::null_mut())
}

/// Frees an options object (NULL is allowed).  No call may still be using
/// it.
///
/// # Safety
/// `opts` is NULL or made by `qs_options_new`, freed only once.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_free(opts: *mut qs_options) {
    if !opts.is_null() {
        // SAFETY: made by Box::into_raw in qs_options_new, freed once
        drop(unsafe { Box::from_raw(opts) });
    }
}

/// Sets the wall-time limit of each call, in seconds: `INFINITY` for none,
/// `0` for a budget that is exhausted at once.  NaN or a negative value is
/// bad input (code 2).  When the limit is hit, the call returns
/// `QS_ERR_BUDGET` (3) with an undecided answer (`QS_VERDICT_UNDECIDED`
/// with `QS_UNDECIDED_BUDGET`, `QS_CLASS_UNDECIDED`, or JSON with
/// `"verdict"`/`"class"` `"undecided"` and its `reason`).
///
/// # Safety
/// `opts` is NULL or a live `qs_options` that no call is using; `err` is
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_set_time_limit(
    opts: *mut qs_options,
    seconds: f64,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: `err` by the caller's contract
    unsafe {
        guard(err, || {
            // SAFETY: the caller's contract
            let o = opts_mut(opts)?;
            if seconds.is_nan() || seconds < 0.0 {
                return Err(input_error(format!(
                    "the time limit must be >= 0 seconds (INFINITY for none), got {seconds}"
                )));
            }
            // beyond Duration's range (about 5.8e11 years) is no limit
            let limit = Duration::try_from_secs_f64(seconds).ok();
            o.budget = o.budget.clone().with_time_limit(limit);
            Ok(())
        })
    }
}

/// Sets the size limits: the most terms of an intermediate polynomial,
/// matrix or basis, and the most bits of an intermediate coefficient; `0`
/// means no limit.
///
/// # Safety
/// `opts` is NULL or a live `qs_options` that no call is using; `err` is
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_set_size_limits(
    opts: *mut qs_options,
    max_terms: u64,
    max_bits: u64,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: `err` by the caller's contract
    unsafe {
        guard(err, || {
            let o = opts_mut(opts)?;
            let terms = (max_terms != 0).then(|| usize::try_from(max_terms).unwrap_or(usize::MAX));
            let bits = (max_bits != 0).then_some(max_bits);
            o.budget = o.budget.clone().with_size_limits(terms, bits);
            Ok(())
        })
    }
}

/// Whether `qs_tangent_json_opts` computes the exact critical values
/// (`values` non-zero, the default) or gives the verdict and its
/// certificate only (`values` = 0): for a surface of degree ≥ 3 in general
/// position the judging polynomial D(u) and the exact `min`/`max` are then
/// skipped (`null` in the JSON) and the sign of S at each real critical
/// point is proven by an interval enclosure — about twice as fast.
///
/// # Safety
/// `opts` is NULL or a live `qs_options` that no call is using; `err` is
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_set_values(
    opts: *mut qs_options,
    values: c_int,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: `err` by the caller's contract
    unsafe {
        guard(err, || {
            opts_mut(opts)?.values = values != 0;
            Ok(())
        })
    }
}

/// Whether `qs_natural_json_opts` also referees its answer (`referee`
/// non-zero; default 0): the JSON then has a `"referee"` object — `lo`,
/// the relative perturbation size within which every input provably has
/// the same class and counts, `hi` and `nearby`, an exact input that far
/// whose answer differs (README, "Refereeing a floating-point kernel").
///
/// # Safety
/// `opts` is NULL or a live `qs_options` that no call is using; `err` is
/// NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_set_referee(
    opts: *mut qs_options,
    referee: c_int,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: `err` by the caller's contract
    unsafe {
        guard(err, || {
            opts_mut(opts)?.referee = referee != 0;
            Ok(())
        })
    }
}

/// Cancels every call running (or started later) with these options: they
/// stop at their next budget check, as if a limit had run out.  Safe to
/// call from any thread while calls run.  `qs_options_reset_cancel` clears
/// it.  A NULL `opts` does nothing.
///
/// # Safety
/// `opts` is NULL or a live `qs_options`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_cancel(opts: *const qs_options) {
    // SAFETY: the caller's contract; only the atomic flag is touched
    if let Some(o) = unsafe { opts.as_ref() } {
        o.cancel.store(true, Ordering::Relaxed);
    }
}

/// Clears the cancellation of `qs_options_cancel` (for the next calls).
///
/// # Safety
/// `opts` is NULL or a live `qs_options`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_options_reset_cancel(opts: *const qs_options) {
    // SAFETY: the caller's contract; only the atomic flag is touched
    if let Some(o) = unsafe { opts.as_ref() } {
        o.cancel.store(false, Ordering::Relaxed);
    }
}

/// # Safety
/// `opts` is NULL or a live `qs_options` that nothing else uses now.
unsafe fn opts_mut<'a>(opts: *mut qs_options) -> Result<&'a mut qs_options, engine::Error> {
    // SAFETY: the caller's contract
    unsafe { opts.as_mut() }.ok_or_else(|| input_error("opts is NULL"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_and_setters() {
        let o = qs_options_new();
        assert!(!o.is_null());
        let b = unsafe { budget_of(o) };
        assert_eq!(b.time_limit(), Budget::default().time_limit());
        unsafe {
            assert_eq!(qs_options_set_time_limit(o, 0.5, ptr::null_mut()), 0);
            assert_eq!(budget_of(o).time_limit(), Some(Duration::from_millis(500)));
            assert_eq!(
                qs_options_set_time_limit(o, f64::INFINITY, ptr::null_mut()),
                0
            );
            assert_eq!(budget_of(o).time_limit(), None);
            assert_eq!(qs_options_set_time_limit(o, f64::NAN, ptr::null_mut()), 2);
            assert_eq!(qs_options_set_time_limit(o, -1.0, ptr::null_mut()), 2);
            assert_eq!(qs_options_set_size_limits(o, 0, 99, ptr::null_mut()), 0);
            assert_eq!(budget_of(o).size_limits(), (None, Some(99)));
            assert!(values_of(o) && values_of(ptr::null()));
            assert_eq!(qs_options_set_values(o, 0, ptr::null_mut()), 0);
            assert!(!values_of(o));
            assert_eq!(
                qs_options_set_values(ptr::null_mut(), 0, ptr::null_mut()),
                2
            );
            assert_eq!(
                qs_options_set_time_limit(ptr::null_mut(), 1.0, ptr::null_mut()),
                2
            );
            qs_options_free(o);
        }
        assert_eq!(
            unsafe { budget_of(ptr::null()) }.size_limits(),
            Budget::default().size_limits()
        );
    }

    #[test]
    fn cancel_reaches_the_budget_flag() {
        // a decision under the options' budget: cancelled, it stops at its
        // first budget check with the limit `cancelled`
        let decide = |o: *mut qs_options| {
            let s: engine::Polynomial = "x^3 + y^2*z - 1".parse().unwrap();
            let e = engine::Ellipsoid::new(&"x^2 + 2y^2 + 3z^2 - 1".parse().unwrap()).unwrap();
            let opts = engine::TangentOptions::with_budget(unsafe { budget_of(o) });
            engine::decide_with(&e, &s, &opts).unwrap()
        };
        let o = qs_options_new();
        unsafe {
            qs_options_cancel(o);
            let r = decide(o);
            assert_eq!(r.verdict(), engine::Verdict::Undecided);
            match r.undecided() {
                Some(engine::tangent::Undecided::Budget(e)) => {
                    assert_eq!(e.limit(), engine::Limit::Cancelled)
                }
                other => panic!("not cancelled: {other:?}"),
            }
            qs_options_reset_cancel(o);
            assert_ne!(decide(o).verdict(), engine::Verdict::Undecided);
            qs_options_cancel(ptr::null());
            qs_options_free(o);
        }
    }
}
