//! The text/JSON level: expressions in, the JSON of the CLI's `--json`
//! out, through the engine's one dispatch table (`batch::run_op_within`), so
//! the answers are exactly those of `quadsect batch`.

use crate::boundary::{Answer, answer_into, host_string, input_error, qs_error, read_str};
use crate::options::{budget_of, qs_options, referee_of, values_of};
use engine::{Error, ErrorKind};
use serde_json::{Map, Value};
use std::ffi::{CStr, c_char, c_int};
use std::ptr;

/// The options' flags that become fields of the request.
#[derive(Clone, Copy)]
struct Flags {
    /// Tangent: the exact critical values.
    values: bool,
    /// Natural: the referee.
    referee: bool,
}

/// The flags of `opts` (NULL: the defaults).
///
/// # Safety
/// `opts` is NULL or a live `qs_options`.
unsafe fn flags_of(opts: *const qs_options) -> Flags {
    // SAFETY: the caller's contract
    unsafe {
        Flags {
            values: values_of(opts),
            referee: referee_of(opts),
        }
    }
}

/// Runs the operation `op` with string fields: its JSON, and the budget
/// error when the answer is `undecided` because a budget ran out (the
/// answer's `reason` says so, as in the CLI, which then exits with 3).
fn run_json(
    op: &str,
    fields: &[(&str, &str)],
    budget: &engine::Budget,
    flags: Flags,
) -> Result<Answer<String>, Error> {
    let (answer, exhausted) = run_answer(op, fields, budget, flags, false)?;
    Ok((answer.to_string(), exhausted))
}

/// [`run_json`]'s answer as a JSON value (with `"svg"` when `svg`).
fn run_answer(
    op: &str,
    fields: &[(&str, &str)],
    budget: &engine::Budget,
    flags: Flags,
    svg: bool,
) -> Result<Answer<Value>, Error> {
    let mut obj = Map::new();
    obj.insert("op".into(), Value::from(op));
    for (name, text) in fields {
        obj.insert((*name).into(), Value::from(*text));
    }
    if op == "tangent" && !flags.values {
        obj.insert("values".into(), Value::from(false));
    }
    if op == "natural" && flags.referee {
        obj.insert("referee".into(), Value::from(true));
    }
    if svg {
        obj.insert("svg".into(), Value::from(true));
    }
    let answer = engine::batch::run_op_within(&obj, budget)?;
    let reason = &answer["reason"];
    let exhausted = (reason["kind"] == "budget").then(|| {
        let message = reason["message"].as_str().unwrap_or("budget exhausted");
        Error::new(ErrorKind::Budget, message)
    });
    Ok((answer, exhausted))
}

/// The body shared by the JSON entry points: reads the string arguments,
/// runs `op`, stores the JSON in `*out_json` (also when a budget ran out:
/// then the answer is `undecided` and the code 3).
///
/// # Safety
/// As for the entry points: every `args` pointer is NULL or a
/// NUL-terminated string; `out_json` and `err` are NULL or writable;
/// `opts` is NULL or live.
unsafe fn json_entry(
    op: &str,
    args: [(&str, *const c_char); 2],
    opts: *const qs_options,
    out_json: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        answer_into(out_json, "out_json", ptr::null_mut(), err, || {
            let a = read_str(args[0].1, args[0].0)?;
            let b = read_str(args[1].1, args[1].0)?;
            let (json, exhausted) = run_json(
                op,
                &[(args[0].0, a), (args[1].0, b)],
                &budget_of(opts),
                flags_of(opts),
            )?;
            Ok((host_string(&json), exhausted))
        })
    }
}

/// Ellipsoid vs surface (the tangent point method), both in the input
/// syntax (`x^2 + y^2/4 + z^2 - 1`, exact numbers), under the default
/// budget (10 s).  On success (0) `*out_json` is the JSON object of
/// `quadsect tangent --json` (`intersect`, `touching`, `side`,
/// `containment`, `min`, `max`, `judging_poly`, `certificate`,
/// `verdict`), to be freed with `qs_string_free`.  When the budget runs
/// out the code is 3 (`QS_ERR_BUDGET`, as the CLI's exit status), `*err`
/// says which limit, and `*out_json` is still set: the `undecided` answer
/// with its `reason` (free it too).  On bad input (2) or an internal
/// failure (1) `*out_json` is NULL and `*err` (when `err` is not NULL)
/// says why (for bad input the message names the argument and the
/// column).
///
/// # Safety
/// `ellipsoid` and `surface` are NULL or NUL-terminated strings;
/// `out_json` and `err` are NULL or point to writable pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_tangent_json(
    ellipsoid: *const c_char,
    surface: *const c_char,
    out_json: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe { qs_tangent_json_opts(ellipsoid, surface, ptr::null(), out_json, err) }
}

/// `qs_tangent_json` with options (`opts` NULL: the defaults): the budget,
/// and with `qs_options_set_values(opts, 0, …)` the verdict only (`min`,
/// `max` and `judging_poly` null when skipping them saves time).
///
/// # Safety
/// As `qs_tangent_json`; `opts` is NULL or a live `qs_options`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_tangent_json_opts(
    ellipsoid: *const c_char,
    surface: *const c_char,
    opts: *const qs_options,
    out_json: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        json_entry(
            "tangent",
            [("ellipsoid", ellipsoid), ("surface", surface)],
            opts,
            out_json,
            err,
        )
    }
}

/// Two natural quadrics, each in the short syntax
/// (`cone vertex=0,0,0 axis=1,0,0 tan2=1/3`) or as the JSON object text
/// (`{"kind":"sphere","center":["0","0","0"],"radius2":"1"}`), under the
/// default budget (10 s).  On success (0) `*out_json` is the JSON object
/// of `quadsect natural --json` (`class`, `conics`, `lines`, `points`,
/// `axes`, `thm8`, `components`, …), to be freed with `qs_string_free`.
/// When the budget runs out the code is 3, `*err` says which limit and
/// `*out_json` is the `undecided` answer (free it too).  On bad input (2)
/// or an internal failure (1) `*out_json` is NULL and `*err` says why.
///
/// # Safety
/// `a` and `b` are NULL or NUL-terminated strings; `out_json` and `err`
/// are NULL or point to writable pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_json(
    a: *const c_char,
    b: *const c_char,
    out_json: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe { qs_natural_json_opts(a, b, ptr::null(), out_json, err) }
}

/// `qs_natural_json` with options (`opts` NULL: the defaults).
///
/// # Safety
/// As `qs_natural_json`; `opts` is NULL or a live `qs_options`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_json_opts(
    a: *const c_char,
    b: *const c_char,
    opts: *const qs_options,
    out_json: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe { json_entry("natural", [("a", a), ("b", b)], opts, out_json, err) }
}

/// The picture of an answer: runs `op` with `"svg": true` and returns the
/// answer's `svg` member, with the budget error when the answer is
/// `undecided` because a budget ran out (its picture is still drawn).
///
/// # Safety
/// As [`json_entry`].
unsafe fn svg_entry(
    op: &str,
    args: [(&str, *const c_char); 2],
    opts: *const qs_options,
    out_svg: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        answer_into(out_svg, "out_svg", ptr::null_mut(), err, || {
            let a = read_str(args[0].1, args[0].0)?;
            let b = read_str(args[1].1, args[1].0)?;
            let fields = [(args[0].0, a), (args[1].0, b)];
            let (answer, exhausted) =
                run_answer(op, &fields, &budget_of(opts), flags_of(opts), true)?;
            let svg = answer["svg"]
                .as_str()
                .ok_or_else(|| Error::internal("the answer has no picture"))?;
            Ok((host_string(svg), exhausted))
        })
    }
}

/// The picture of the tangent method's answer for `ellipsoid` and
/// `surface` (as for `qs_tangent_json_opts`) as SVG text in `*out_svg`
/// (free it with `qs_string_free`): E from two sides shaded by the sign of
/// S, the curve S = 0 on E, the certificate's witness points, the verdict.
/// Codes as `qs_tangent_json_opts` (3: the budget ran out, `*out_svg` is
/// the picture of the `undecided` answer).
///
/// # Safety
/// As `qs_tangent_json_opts`, with `out_svg` for `out_json`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_tangent_svg(
    ellipsoid: *const c_char,
    surface: *const c_char,
    opts: *const qs_options,
    out_svg: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        svg_entry(
            "tangent",
            [("ellipsoid", ellipsoid), ("surface", surface)],
            opts,
            out_svg,
            err,
        )
    }
}

/// The picture of two natural quadrics' answer (inputs as for
/// `qs_natural_json_opts`) as SVG text in `*out_svg` (free it with
/// `qs_string_free`): a 3D view with the components coloured by kind, the
/// axial plane when the axes are coplanar, the class and counts.  Codes as
/// `qs_natural_json_opts`.
///
/// # Safety
/// As `qs_natural_json_opts`, with `out_svg` for `out_json`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_svg(
    a: *const c_char,
    b: *const c_char,
    opts: *const qs_options,
    out_svg: *mut *mut c_char,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe { svg_entry("natural", [("a", a), ("b", b)], opts, out_svg, err) }
}

/// One line of the `quadsect batch` protocol: `line` is one JSON object
/// (`{"id":7,"op":"roots","poly":"x^2-2"}`; ops `tangent`, `natural`,
/// `roots`, `resultant`), `*out` becomes its answer line, without a
/// trailing newline: `{"id":7,"ok":true,"result":{…}}` or
/// `{"id":7,"ok":false,"error":{"kind":…,"message":…}}`.  Free it with
/// `qs_string_free`.  Returns 0 whenever an answer line was written (read
/// `"ok"` in it: a bad request is an error line, as in the batch);
/// invalid UTF-8 is read with U+FFFD replacements (then answered with a
/// JSON error line, as the CLI does).  Returns 2 when `line` or `out` is
/// NULL (`*out` NULL), 1 on an internal failure.
///
/// # Safety
/// `line` is NULL or a NUL-terminated string; `out` is NULL or points to
/// a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_batch_line(line: *const c_char, out: *mut *mut c_char) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        // a budget that runs out is an error line of the answer, not a code
        answer_into(out, "out", ptr::null_mut(), ptr::null_mut(), || {
            if line.is_null() {
                return Err(input_error("line is NULL"));
            }
            let text = CStr::from_ptr(line).to_string_lossy();
            let answer = engine::batch::answer_line_text_within(&text, &engine::Budget::default());
            Ok((host_string(&answer), None))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::boundary::{qs_error_free, qs_error_kind, qs_error_message, qs_string_free};
    use std::ffi::CString;

    fn owned(p: *mut c_char) -> String {
        let s = unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_string();
        unsafe { qs_string_free(p) };
        s
    }

    fn call(
        f: unsafe extern "C" fn(
            *const c_char,
            *const c_char,
            *mut *mut c_char,
            *mut *mut qs_error,
        ) -> c_int,
        a: &str,
        b: &str,
    ) -> (c_int, Result<Value, (String, String)>) {
        let (a, b) = (CString::new(a).unwrap(), CString::new(b).unwrap());
        let mut out = ptr::null_mut();
        let mut err = ptr::null_mut();
        let code = unsafe { f(a.as_ptr(), b.as_ptr(), &mut out, &mut err) };
        if code == 0 {
            assert!(err.is_null());
            (code, Ok(serde_json::from_str(&owned(out)).unwrap()))
        } else {
            assert!(out.is_null());
            let kind = unsafe { CStr::from_ptr(qs_error_kind(err)) }
                .to_str()
                .unwrap()
                .to_string();
            let msg = unsafe { CStr::from_ptr(qs_error_message(err)) }
                .to_str()
                .unwrap()
                .to_string();
            unsafe { qs_error_free(err) };
            (code, Err((kind, msg)))
        }
    }

    #[test]
    fn tangent_json_equals_the_batch_answer() {
        let (e, s) = ("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1");
        let (code, v) = call(qs_tangent_json, e, s);
        assert_eq!(code, 0);
        let v = v.unwrap();
        let line = serde_json::json!({"id": 1, "op": "tangent", "ellipsoid": e, "surface": s});
        let batch = engine::batch::answer_line(&line.to_string());
        assert_eq!(batch["result"], v);
        assert_eq!(v["verdict"], "separated");
    }

    #[test]
    fn natural_json_accepts_both_syntaxes_and_equals_the_engine() {
        let a = "cylinder point=0,0,0 axis=1,0,0 radius2=1";
        let b = r#"{"kind":"cylinder","point":["0","0","0"],"axis":["0","1","0"],"radius2":"1"}"#;
        let (code, v) = call(qs_natural_json, a, b);
        assert_eq!(code, 0);
        let v = v.unwrap();
        let r = engine::classify(&a.parse().unwrap(), &b.parse().unwrap()).unwrap();
        assert_eq!(v, serde_json::to_value(&r).unwrap());
        assert_eq!(v["conics"], 2);
    }

    #[test]
    fn bad_input_gives_code_2_and_a_message_naming_the_argument() {
        let (code, r) = call(qs_tangent_json, "x^2+y^2+z^2-1", "x^2 + )");
        assert_eq!(code, 2);
        let (kind, msg) = r.unwrap_err();
        assert_eq!(kind, "parse");
        assert!(msg.starts_with("in the surface"), "{msg}");
        assert!(msg.contains("column"), "{msg}");
        let (code, r) = call(
            qs_natural_json,
            "sphere center=0,0,0 radius2=-1",
            "sphere center=0,0,0 radius2=1",
        );
        assert_eq!(code, 2);
        assert_eq!(r.unwrap_err().0, "bad-quadric");
        let (code, r) = call(qs_tangent_json, "x^2+y^2-z^2-1", "x");
        assert_eq!(code, 2);
        assert_eq!(r.unwrap_err().0, "not-an-ellipsoid");
    }

    #[test]
    fn pictures_are_the_engines_svg() {
        let svg = |f: unsafe extern "C" fn(
            *const c_char,
            *const c_char,
            *const qs_options,
            *mut *mut c_char,
            *mut *mut qs_error,
        ) -> c_int,
                   a: &str,
                   b: &str|
         -> (c_int, String) {
            let (a, b) = (CString::new(a).unwrap(), CString::new(b).unwrap());
            let mut out = ptr::null_mut();
            let code = unsafe {
                f(
                    a.as_ptr(),
                    b.as_ptr(),
                    ptr::null(),
                    &mut out,
                    ptr::null_mut(),
                )
            };
            let text = if out.is_null() {
                String::new()
            } else {
                owned(out)
            };
            (code, text)
        };
        let (a, b) = (
            "sphere center=0,0,0 radius2=4",
            "cylinder point=1,0,0 axis=0,0,1 radius2=1",
        );
        let (code, text) = svg(qs_natural_svg, a, b);
        assert_eq!(code, 0);
        let r = engine::classify(&a.parse().unwrap(), &b.parse().unwrap()).unwrap();
        assert_eq!(text, r.svg());
        let (code, text) = svg(qs_tangent_svg, "x^2+y^2+z^2-25", "x-6");
        assert_eq!(code, 0);
        assert!(text.contains("verdict: separated"));
        let (code, text) = svg(qs_tangent_svg, "x^2+y^2+z^2-25", "x-)");
        assert_eq!((code, text.as_str()), (2, ""));
    }

    #[test]
    fn null_arguments_give_code_2() {
        let mut out = ptr::null_mut();
        let mut err = ptr::null_mut();
        let s = CString::new("x").unwrap();
        let code = unsafe { qs_tangent_json(ptr::null(), s.as_ptr(), &mut out, &mut err) };
        assert_eq!(code, 2);
        assert!(out.is_null());
        let msg = unsafe { CStr::from_ptr(qs_error_message(err)) }
            .to_str()
            .unwrap()
            .to_string();
        assert_eq!(msg, "ellipsoid is NULL");
        unsafe { qs_error_free(err) };
        let code =
            unsafe { qs_natural_json(s.as_ptr(), s.as_ptr(), ptr::null_mut(), ptr::null_mut()) };
        assert_eq!(code, 2);
    }

    #[test]
    fn batch_line_answers_every_line_and_rejects_null() {
        let line = CString::new(r#"{"id":7,"op":"roots","poly":"x^2-2"}"#).unwrap();
        let mut out = ptr::null_mut();
        assert_eq!(unsafe { qs_batch_line(line.as_ptr(), &mut out) }, 0);
        let v: Value = serde_json::from_str(&owned(out)).unwrap();
        assert_eq!(
            (v["id"].clone(), v["ok"].clone()),
            (Value::from(7), Value::from(true))
        );
        assert_eq!(v["result"]["distinct_real"], 2);
        let bad = b"{\"op\":\"roots\",\"poly\":\"\xff\"}\0";
        assert_eq!(unsafe { qs_batch_line(bad.as_ptr().cast(), &mut out) }, 0);
        let text = owned(out);
        assert!(!text.contains('\n'));
        let v: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(v["ok"], false);
        assert_eq!(unsafe { qs_batch_line(ptr::null(), &mut out) }, 2);
        assert!(out.is_null());
        assert_eq!(unsafe { qs_batch_line(line.as_ptr(), ptr::null_mut()) }, 2);
    }

    #[test]
    fn the_values_option_gives_the_verdict_only() {
        let opts = crate::options::qs_options_new();
        let (e, s) = (
            CString::new("x^2 + 2y^2 + 3z^2 - 6").unwrap(),
            CString::new("x^3 - 2x*y + z^2 + y*z - 1").unwrap(),
        );
        let run = |o: *const qs_options| -> Value {
            let mut out = ptr::null_mut();
            let code = unsafe {
                qs_tangent_json_opts(e.as_ptr(), s.as_ptr(), o, &mut out, ptr::null_mut())
            };
            assert_eq!(code, 0);
            serde_json::from_str(&owned(out)).unwrap()
        };
        let full = run(opts);
        assert!(full["judging_poly"].is_string() && full["min"].is_object());
        unsafe { crate::options::qs_options_set_values(opts, 0, ptr::null_mut()) };
        let vo = run(opts);
        assert_eq!(vo["verdict"], full["verdict"]);
        assert!(vo["judging_poly"].is_null() && vo["min"].is_null());
        assert!(
            !vo["certificate"]["value_enclosures"]
                .as_array()
                .unwrap()
                .is_empty()
        );
        unsafe { crate::options::qs_options_free(opts) };
    }

    #[test]
    fn the_referee_option_adds_the_stability_interval() {
        let opts = crate::options::qs_options_new();
        let (a, b) = (
            CString::new("sphere center=0,0,0 radius2=1").unwrap(),
            CString::new("sphere center=3/2,0,0 radius2=1").unwrap(),
        );
        let run = |o: *const qs_options| -> Value {
            let mut out = ptr::null_mut();
            let code = unsafe {
                qs_natural_json_opts(a.as_ptr(), b.as_ptr(), o, &mut out, ptr::null_mut())
            };
            assert_eq!(code, 0);
            serde_json::from_str(&owned(out)).unwrap()
        };
        assert!(run(opts).get("referee").is_none());
        unsafe { crate::options::qs_options_set_referee(opts, 1, ptr::null_mut()) };
        let r = run(opts);
        assert_eq!(r["class"], "conics");
        assert!(r["referee"]["lo_exact"].is_string());
        assert_eq!(r["referee"]["nearby"]["answer"]["class"], "empty");
        unsafe { crate::options::qs_options_free(opts) };
    }

    #[test]
    fn an_exhausted_budget_gives_code_3_an_error_and_the_undecided_answer() {
        let opts = crate::options::qs_options_new();
        unsafe { crate::options::qs_options_set_time_limit(opts, 0.0, ptr::null_mut()) };
        let cases = [
            (
                qs_tangent_json_opts as unsafe extern "C" fn(_, _, _, _, _) -> _,
                "x^2+y^2+z^2-1",
                "x-3",
                "verdict",
            ),
            (
                qs_natural_json_opts,
                "sphere center=0,0,0 radius2=1",
                "cone vertex=0,0,0 axis=1,0,0 tan2=1/3",
                "class",
            ),
        ];
        for (f, a, b, key) in cases {
            let (a, b) = (CString::new(a).unwrap(), CString::new(b).unwrap());
            let mut out = ptr::null_mut();
            let mut err = ptr::null_mut();
            let code = unsafe { f(a.as_ptr(), b.as_ptr(), opts, &mut out, &mut err) };
            assert_eq!(code, crate::boundary::QS_ERR_BUDGET);
            let kind = unsafe { CStr::from_ptr(qs_error_kind(err)) };
            assert_eq!(kind.to_str().unwrap(), "budget");
            let msg = unsafe { CStr::from_ptr(qs_error_message(err)) };
            assert!(msg.to_str().unwrap().contains("time"), "{msg:?}");
            unsafe { qs_error_free(err) };
            let v: Value = serde_json::from_str(&owned(out)).unwrap();
            assert_eq!(v[key], "undecided");
            assert_eq!(v["reason"]["limit"], "time");
        }
        unsafe { crate::options::qs_options_free(opts) };
    }
}
