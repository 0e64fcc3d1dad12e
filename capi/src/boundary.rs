//! The boundary between C and Rust: the error object, the return codes,
//! strings handed to and from the host, and the one wrapper every entry
//! point runs its body in (a panic becomes an internal error, never an
//! unwind into C).

use engine::{Error, ErrorKind};
use std::ffi::{CStr, CString, c_char, c_int};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::ptr;

/// Success.
pub const QS_OK: c_int = 0;
/// An internal failure inside quadsect (a bug: please report it).  No
/// answer, and never a wrong one.
pub const QS_ERR_INTERNAL: c_int = 1;
/// Bad input: a malformed expression, an invalid quadric, a NULL pointer,
/// a NaN or infinite double, invalid UTF-8, …
pub const QS_ERR_INPUT: c_int = 2;
/// A compute budget ran out (time limit, size limit or cancellation; see
/// `qs_options`).
pub const QS_ERR_BUDGET: c_int = 3;

/// An error: a kind (a short machine-readable tag such as `parse`,
/// `not-an-ellipsoid`, `bad-quadric`, `input`, `budget`, `internal`: the
/// batch protocol's kinds), a message for people, and the return code.
/// Opaque; read it with `qs_error_kind`, `qs_error_message` and
/// `qs_error_code`, free it with `qs_error_free`.
pub struct qs_error {
    kind: CString,
    message: CString,
    code: c_int,
}

impl qs_error {
    fn from_error(e: &Error) -> qs_error {
        qs_error {
            kind: c_string(e.kind().as_str()),
            message: c_string(e.message()),
            code: e.exit_code(),
        }
    }
}

/// A C string of `s`; an interior NUL (possible in a message that quotes
/// JSON input) becomes U+FFFD.
pub(crate) fn c_string(s: &str) -> CString {
    CString::new(s).unwrap_or_else(|_| {
        CString::new(s.replace('\0', "\u{FFFD}")).expect("no NUL left after replacing them")
    })
}

/// A newly allocated C string for the host, freed by `qs_string_free`.
pub(crate) fn host_string(s: &str) -> *mut c_char {
    c_string(s).into_raw()
}

/// An input error (kind `input`, code 2).
pub(crate) fn input_error(message: impl Into<String>) -> Error {
    Error::new(ErrorKind::Input, message)
}

/// The text behind a `const char *` argument named `what`: NULL and
/// invalid UTF-8 are input errors.
///
/// # Safety
/// `p` is NULL or points to a NUL-terminated string that stays valid and
/// unchanged for `'a`.
pub(crate) unsafe fn read_str<'a>(p: *const c_char, what: &str) -> Result<&'a str, Error> {
    if p.is_null() {
        return Err(input_error(format!("{what} is NULL")));
    }
    // SAFETY: non-NULL and NUL-terminated by the caller's contract
    let bytes = unsafe { CStr::from_ptr(p) };
    bytes.to_str().map_err(|e| {
        input_error(format!(
            "{what} is not valid UTF-8 (invalid byte at offset {})",
            e.valid_up_to()
        ))
    })
}

/// The value behind a `const T *` argument named `what` (NULL is an input
/// error).
///
/// # Safety
/// `p` is NULL or points to a valid, initialised `T` that stays unchanged
/// for `'a`.
pub(crate) unsafe fn read_ref<'a, T>(p: *const T, what: &str) -> Result<&'a T, Error> {
    // SAFETY: the caller's contract
    unsafe { p.as_ref() }.ok_or_else(|| input_error(format!("{what} is NULL")))
}

/// Checks that an output pointer named `what` is not NULL.
pub(crate) fn check_out<T>(p: *mut T, what: &str) -> Result<(), Error> {
    if p.is_null() {
        Err(input_error(format!(
            "{what} is NULL (nowhere to write the answer)"
        )))
    } else {
        Ok(())
    }
}

/// Runs an entry point's body: catches every panic (an internal error),
/// stores the error in `*err` (when `err` is not NULL) or NULL on success,
/// and returns the code (0 success, 2 bad input, 3 budget, 1 internal).
///
/// # Safety
/// `err` is NULL or points to writable storage for one pointer.
pub(crate) unsafe fn guard(
    err: *mut *mut qs_error,
    body: impl FnOnce() -> Result<(), Error>,
) -> c_int {
    let result = catch_unwind(AssertUnwindSafe(body))
        .unwrap_or_else(|p| Err(Error::internal(engine::batch::panic_message(&p))));
    let (code, e) = match result {
        Ok(()) => (QS_OK, ptr::null_mut()),
        Err(e) => (
            e.exit_code(),
            // building the error object allocates: a panic there (out of
            // memory aborts anyway) must not escape either
            catch_unwind(|| Box::into_raw(Box::new(qs_error::from_error(&e))))
                .unwrap_or(ptr::null_mut()),
        ),
    };
    if !err.is_null() {
        // SAFETY: writable by the caller's contract
        unsafe { *err = e };
    } else if !e.is_null() {
        // SAFETY: just made by Box::into_raw and not shared
        drop(unsafe { Box::from_raw(e) });
    }
    code
}

/// An answer and, when a budget ran out, the budget error: the answer is
/// then the `undecided` one and is written all the same (code 3), as the
/// CLI prints it before exiting with 3.
pub(crate) type Answer<T> = (T, Option<Error>);

/// Runs an entry point that writes one answer to `*out` (named `what`):
/// checks `out`, sets it to `cleared` (what a failed call leaves), runs
/// `body` in [`guard`] and writes its answer, also when the budget ran out.
///
/// # Safety
/// `out` is NULL or writable; `err` as for [`guard`].
pub(crate) unsafe fn answer_into<T>(
    out: *mut T,
    what: &str,
    cleared: T,
    err: *mut *mut qs_error,
    body: impl FnOnce() -> Result<Answer<T>, Error>,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        guard(err, || {
            check_out(out, what)?;
            *out = cleared;
            let (answer, exhausted) = body()?;
            *out = answer;
            exhausted.map_or(Ok(()), Err)
        })
    }
}

/// The error's kind: a NUL-terminated tag (`parse`, `number`,
/// `not-an-ellipsoid`, `bad-quadric`, `input`, `json`, `missing-field`,
/// `bad-field`, `unknown-op`, `budget`, `internal`, …).  The string belongs
/// to the error and lives until `qs_error_free`.  NULL for a NULL `err`.
///
/// # Safety
/// `err` is NULL or an error returned by this library and not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_error_kind(err: *const qs_error) -> *const c_char {
    // SAFETY: the caller's contract
    match unsafe { err.as_ref() } {
        Some(e) => e.kind.as_ptr(),
        None => ptr::null(),
    }
}

/// The error's message for people (UTF-8, NUL-terminated; for expressions
/// it names the column).  The string belongs to the error and lives until
/// `qs_error_free`.  NULL for a NULL `err`.
///
/// # Safety
/// `err` is NULL or an error returned by this library and not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_error_message(err: *const qs_error) -> *const c_char {
    // SAFETY: the caller's contract
    match unsafe { err.as_ref() } {
        Some(e) => e.message.as_ptr(),
        None => ptr::null(),
    }
}

/// The return code the failing call gave (`QS_ERR_INPUT`,
/// `QS_ERR_BUDGET` or `QS_ERR_INTERNAL`); `QS_OK` for a NULL `err`.
///
/// # Safety
/// `err` is NULL or an error returned by this library and not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_error_code(err: *const qs_error) -> c_int {
    // SAFETY: the caller's contract
    match unsafe { err.as_ref() } {
        Some(e) => e.code,
        None => QS_OK,
    }
}

/// Frees an error (NULL is allowed and does nothing).
///
/// # Safety
/// `err` is NULL or an error returned by this library, freed only once.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_error_free(err: *mut qs_error) {
    if !err.is_null() {
        // SAFETY: made by Box::into_raw in `guard`, freed once
        drop(unsafe { Box::from_raw(err) });
    }
}

/// Frees a string returned by this library (`out_json`, `out` of every
/// function that returns text).  NULL is allowed and does nothing.  Never
/// pass it a string from anywhere else, nor `free()` a string of ours.
///
/// # Safety
/// `s` is NULL or a string returned by this library, freed only once.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_string_free(s: *mut c_char) {
    if !s.is_null() {
        // SAFETY: made by CString::into_raw in `host_string`, freed once
        drop(unsafe { CString::from_raw(s) });
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    fn text(p: *const c_char) -> String {
        unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_string()
    }

    #[test]
    fn answer_into_writes_the_answer_also_with_a_budget_error() {
        let mut out = 7;
        let mut err = ptr::null_mut();
        let budget = || Ok((42, Some(Error::new(ErrorKind::Budget, "time"))));
        let code = unsafe { answer_into(&mut out, "out", 0, &mut err, budget) };
        assert_eq!((code, out), (QS_ERR_BUDGET, 42));
        assert_eq!(text(unsafe { qs_error_kind(err) }), "budget");
        unsafe { qs_error_free(err) };
        let code = unsafe { answer_into(&mut out, "out", 0, &mut err, || Err(input_error("no"))) };
        assert_eq!((code, out), (QS_ERR_INPUT, 0));
        unsafe { qs_error_free(err) };
        let code = unsafe { answer_into(ptr::null_mut(), "out", 0, &mut err, || Ok((1, None))) };
        assert_eq!(code, QS_ERR_INPUT);
        assert!(text(unsafe { qs_error_message(err) }).contains("out is NULL"));
        unsafe { qs_error_free(err) };
    }

    /// The message of `err` (empty for NULL), and frees it.
    pub(crate) fn take_message(err: *mut qs_error) -> String {
        if err.is_null() {
            return String::new();
        }
        let m = text(unsafe { qs_error_message(err) });
        unsafe { qs_error_free(err) };
        m
    }

    #[test]
    fn guard_turns_a_panic_into_an_internal_error() {
        let mut err = ptr::null_mut();
        let code = unsafe { guard(&mut err, || panic!("boom at the boundary")) };
        assert_eq!(code, QS_ERR_INTERNAL);
        assert!(!err.is_null());
        assert_eq!(text(unsafe { qs_error_kind(err) }), "internal");
        assert!(text(unsafe { qs_error_message(err) }).contains("boom at the boundary"));
        assert_eq!(unsafe { qs_error_code(err) }, QS_ERR_INTERNAL);
        unsafe { qs_error_free(err) };
    }

    #[test]
    fn guard_clears_err_on_success_and_accepts_a_null_err() {
        let mut err = ptr::dangling_mut::<qs_error>(); // garbage the caller left there
        assert_eq!(unsafe { guard(&mut err, || Ok(())) }, QS_OK);
        assert!(err.is_null());
        let code = unsafe { guard(ptr::null_mut(), || Err(input_error("x"))) };
        assert_eq!(code, QS_ERR_INPUT);
    }

    #[test]
    fn codes_follow_the_error_kind() {
        for (kind, code) in [
            (ErrorKind::Parse, QS_ERR_INPUT),
            (ErrorKind::Budget, QS_ERR_BUDGET),
            (ErrorKind::Internal, QS_ERR_INTERNAL),
        ] {
            let mut err = ptr::null_mut();
            let c = unsafe { guard(&mut err, || Err(Error::new(kind, "m"))) };
            assert_eq!(c, code);
            assert_eq!(text(unsafe { qs_error_kind(err) }), kind.as_str());
            unsafe { qs_error_free(err) };
        }
    }

    #[test]
    fn interior_nul_in_a_message_is_replaced() {
        let s = c_string("a\0b");
        assert_eq!(s.to_str().unwrap(), "a\u{FFFD}b");
    }

    #[test]
    fn read_str_rejects_null_and_invalid_utf8() {
        let e = unsafe { read_str(ptr::null(), "surface") }.unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Input);
        assert_eq!(e.message(), "surface is NULL");
        let bad = b"x^2\xff\0";
        let e = unsafe { read_str(bad.as_ptr().cast(), "surface") }.unwrap_err();
        assert!(e.message().contains("not valid UTF-8"), "{}", e.message());
        assert!(e.message().contains("offset 3"), "{}", e.message());
    }

    #[test]
    fn null_accessors_and_frees_are_harmless() {
        unsafe {
            assert!(qs_error_kind(ptr::null()).is_null());
            assert!(qs_error_message(ptr::null()).is_null());
            assert_eq!(qs_error_code(ptr::null()), QS_OK);
            qs_error_free(ptr::null_mut());
            qs_string_free(ptr::null_mut());
        }
    }
}
