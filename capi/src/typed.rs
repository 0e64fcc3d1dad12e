//! The typed double level: surfaces given as doubles, each taken as its
//! exact binary value (never rounded, never snapped to a decimal), and
//! answers as small C structs.

use crate::boundary::{Answer, answer_into, input_error, qs_error, read_ref};
use crate::float::{Enclosure, enclose, exact};
use crate::options::{budget_of, qs_options};
use engine::natural::AxesRelation;
use engine::tangent::{Containment, Side, Undecided};
use engine::{Class, ClassifyOptions, NaturalReport};
use engine::{
    Cone, Cylinder, Ellipsoid, Error, Natural, Polynomial, Rational, RealAlg, Sphere, Var,
};
use engine::{TangentOptions, Verdict};
use std::ffi::c_int;
use std::ptr;

/// The kind of a natural quadric (`QS_SPHERE`, `QS_CYLINDER`, `QS_CONE`).
pub type qs_natural_kind = i32;
/// A sphere: `point` is the centre, `param` the squared radius.
pub const QS_SPHERE: qs_natural_kind = 0;
/// A circular cylinder: `point` is any point of the axis, `axis` a
/// non-zero direction of any length, `param` the squared radius.
pub const QS_CYLINDER: qs_natural_kind = 1;
/// A right circular double cone: `point` is the vertex, `axis` a non-zero
/// direction, `param` tan² of the half-angle.
pub const QS_CONE: qs_natural_kind = 2;

/// A natural quadric in doubles.  Every double is taken as its exact
/// binary value (0.1 is 3602879701896397/2^55); NaN and ±infinity are bad
/// input.  For a sphere `axis` is not read.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct qs_natural_f64 {
    /// `QS_SPHERE`, `QS_CYLINDER` or `QS_CONE`.
    pub kind: qs_natural_kind,
    /// Sphere: the centre; cylinder: a point of the axis; cone: the vertex.
    pub point: [f64; 3],
    /// Cylinder and cone: the axis direction (non-zero, any length).
    pub axis: [f64; 3],
    /// Sphere and cylinder: radius² (> 0); cone: tan² of the half-angle (> 0).
    pub param: f64,
}

/// The class of the intersection of two natural quadrics (the JSON
/// `class`).
pub type qs_class = i32;
/// The two equations are proportional.
pub const QS_CLASS_SAME_SURFACE: qs_class = 0;
/// Real conics and no line.
pub const QS_CLASS_CONICS: qs_class = 1;
/// Conic(s) and line(s).
pub const QS_CLASS_CONIC_AND_LINE: qs_class = 2;
/// Lines only.
pub const QS_CLASS_LINES: qs_class = 3;
/// Isolated points only (tangency points, a lone common vertex).
pub const QS_CLASS_POINTS: qs_class = 4;
/// Nothing real.
pub const QS_CLASS_EMPTY: qs_class = 5;
/// A space curve not made of lines and conics.
pub const QS_CLASS_CURVE: qs_class = 6;
/// Not decided: the compute budget ran out (the call returns
/// `QS_ERR_BUDGET`; the counts are 0).
pub const QS_CLASS_UNDECIDED: qs_class = 7;

/// How the two axes lie (the JSON `axes`).
pub type qs_axes = i32;
/// No axes to compare (a sphere is involved).
pub const QS_AXES_NONE: qs_axes = 0;
/// The same line.
pub const QS_AXES_COINCIDENT: qs_axes = 1;
/// Parallel and distinct.
pub const QS_AXES_PARALLEL: qs_axes = 2;
/// Coplanar and meeting in one point.
pub const QS_AXES_COPLANAR_INTERSECTING: qs_axes = 3;
/// Not coplanar.
pub const QS_AXES_SKEW: qs_axes = 4;

/// The classification of two natural quadrics.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct qs_natural_result {
    /// The class (`QS_CLASS_…`).
    pub cls: qs_class,
    /// Real affine conics (a double conic counts once).
    pub conics: u32,
    /// Real lines (a double line counts once).
    pub lines: u32,
    /// Isolated real points on no other component.
    pub points: u32,
    /// How the axes lie (`QS_AXES_…`).
    pub axes: qs_axes,
    /// The closed-form test of Theorems 8.1/8.2 where it applies: 1 true,
    /// 0 false, -1 not applicable (skew or coincident axes, a sphere).
    pub thm8: i32,
}

/// An ellipsoid in doubles: `Σᵢ ((Rᵀ (p − center))ᵢ / semi_axes[i])² = 1`.
/// Every double is taken as its exact value; `rotation` is used exactly as
/// given (it need not be orthogonal to the last bit: any invertible matrix
/// defines an ellipsoid, the one those exact numbers describe).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct qs_ellipsoid_f64 {
    /// The centre.
    pub center: [f64; 3],
    /// The three semi-axis lengths (> 0).
    pub semi_axes: [f64; 3],
    /// Row-major 3×3 matrix `R` (`rotation[row][col]`) whose column `i` is
    /// the direction of semi-axis `i` (world = R · local + center).
    pub rotation: [[f64; 3]; 3],
}

/// The verdict of the tangent point method.
pub type qs_verdict = i32;
/// No certificate could be produced, or the budget ran out (see `reason`).
pub const QS_VERDICT_UNDECIDED: qs_verdict = 0;
/// S takes both signs on E (ν < 0 < μ).
pub const QS_VERDICT_INTERSECTING: qs_verdict = 1;
/// They meet without crossing (ν = 0 or μ = 0).
pub const QS_VERDICT_TOUCHING: qs_verdict = 2;
/// S has one strict sign on E.
pub const QS_VERDICT_SEPARATED: qs_verdict = 3;

/// The side of S on which E lies (when S does not change sign on E).
pub type qs_side = i32;
/// S takes both signs on E, or undecided.
pub const QS_SIDE_NONE: qs_side = 0;
/// S ≥ 0 on E.
pub const QS_SIDE_POSITIVE: qs_side = 1;
/// S ≤ 0 on E.
pub const QS_SIDE_NEGATIVE: qs_side = -1;

/// Containment, when S is an ellipsoid and they do not intersect, or
/// coincident when S = c·E.
pub type qs_containment = i32;
/// Not applicable.
pub const QS_CONTAINMENT_NONE: qs_containment = 0;
/// E is inside the solid bounded by S.
pub const QS_CONTAINMENT_E_INSIDE_S: qs_containment = 1;
/// S is inside the solid bounded by E.
pub const QS_CONTAINMENT_S_INSIDE_E: qs_containment = 2;
/// The two solids are disjoint.
pub const QS_CONTAINMENT_APART: qs_containment = 3;
/// S = c·E, the same surface (the verdict is touching).
pub const QS_CONTAINMENT_COINCIDENT: qs_containment = 4;

/// Why the verdict is undecided.
pub type qs_undecided = i32;
/// Decided.
pub const QS_UNDECIDED_NONE: qs_undecided = 0;
/// The computation finished without a certificate.
pub const QS_UNDECIDED_NO_CERTIFICATE: qs_undecided = 1;
/// A budget ran out (time, size, cancellation).
pub const QS_UNDECIDED_BUDGET: qs_undecided = 2;

/// An exact real number as doubles rounded outward: `lo ≤ value ≤ hi`,
/// computed from the exact value (refining its isolating interval and
/// rounding the rational ends down and up exactly), never by converting
/// an approximation.  `lo` and `hi` are the same double when the value is
/// that double (`exact` = 1), otherwise neighbouring doubles
/// (`f64::MAX` / `DBL_MAX` and infinity beyond the range).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_interval {
    /// A double ≤ the value.
    pub lo: f64,
    /// A double ≥ the value.
    pub hi: f64,
    /// 1 when `lo == hi` is the exact value.
    pub exact: i32,
    /// 0 when there is no value (undecided): then `lo` and `hi` are NaN.
    pub known: i32,
}

impl qs_interval {
    const UNKNOWN: qs_interval = qs_interval {
        lo: f64::NAN,
        hi: f64::NAN,
        exact: 0,
        known: 0,
    };

    fn of(x: Option<&RealAlg>) -> qs_interval {
        match x.map(enclose) {
            Some(Enclosure { lo, hi, exact }) => qs_interval {
                lo,
                hi,
                exact: exact as i32,
                known: 1,
            },
            None => qs_interval::UNKNOWN,
        }
    }
}

/// The answer of the tangent point method for an ellipsoid E and a
/// quadric S: verdict, side, and the exact minimum ν and maximum μ of S on
/// E as outward-rounded doubles.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_tangent_result {
    /// `QS_VERDICT_…`.
    pub verdict: qs_verdict,
    /// `QS_SIDE_…`.
    pub side: qs_side,
    /// `QS_CONTAINMENT_…`.
    pub containment: qs_containment,
    /// `QS_UNDECIDED_…` (why the verdict is undecided).
    pub reason: qs_undecided,
    /// ν, the minimum of S on E (not named `min`: windows.h defines it).
    pub minimum: qs_interval,
    /// μ, the maximum of S on E.
    pub maximum: qs_interval,
}

impl qs_tangent_result {
    const CLEAR: qs_tangent_result = qs_tangent_result {
        verdict: QS_VERDICT_UNDECIDED,
        side: QS_SIDE_NONE,
        containment: QS_CONTAINMENT_NONE,
        reason: QS_UNDECIDED_NONE,
        minimum: qs_interval::UNKNOWN,
        maximum: qs_interval::UNKNOWN,
    };
}

/// A double's exact value; `what` names it in the error.
fn exact_double(x: f64, what: impl FnOnce() -> String) -> Result<Rational, Error> {
    exact(x).ok_or_else(|| {
        input_error(format!(
            "{} is {x}: only finite doubles are accepted",
            what()
        ))
    })
}

fn exact3(v: &[f64; 3], what: &str) -> Result<[Rational; 3], Error> {
    let c = |i: usize| exact_double(v[i], || format!("{what}[{i}]"));
    Ok([c(0)?, c(1)?, c(2)?])
}

/// The natural quadric `q`, checked; `name` (`a`, `b`) prefixes errors.
pub(crate) fn natural_of(q: &qs_natural_f64, name: &str) -> Result<Natural, Error> {
    let point = exact3(&q.point, &format!("{name}.point"))?;
    let param = exact_double(q.param, || format!("{name}.param"))?;
    let axis = || exact3(&q.axis, &format!("{name}.axis"));
    let n = match q.kind {
        QS_SPHERE => Sphere::new(point, param).map(Natural::Sphere),
        QS_CYLINDER => Cylinder::new(point, axis()?, param).map(Natural::Cylinder),
        QS_CONE => Cone::new(point, axis()?, param).map(Natural::Cone),
        k => {
            return Err(input_error(format!(
                "{name}.kind is {k}: expected QS_SPHERE (0), QS_CYLINDER (1) or QS_CONE (2)"
            )));
        }
    };
    n.map_err(|e| e.context(&format!("in {name}")))
}

fn class_code(c: Class) -> Result<qs_class, Error> {
    Ok(match c {
        Class::SameSurface => QS_CLASS_SAME_SURFACE,
        Class::Conics => QS_CLASS_CONICS,
        Class::ConicAndLine => QS_CLASS_CONIC_AND_LINE,
        Class::Lines => QS_CLASS_LINES,
        Class::Points => QS_CLASS_POINTS,
        Class::Empty => QS_CLASS_EMPTY,
        Class::Curve => QS_CLASS_CURVE,
        Class::Undecided => QS_CLASS_UNDECIDED,
        other => return Err(Error::internal(format!("class {other} has no C code"))),
    })
}

fn axes_code(a: Option<&AxesRelation>) -> Result<qs_axes, Error> {
    Ok(match a {
        None => QS_AXES_NONE,
        Some(AxesRelation::Coincident) => QS_AXES_COINCIDENT,
        Some(AxesRelation::Parallel) => QS_AXES_PARALLEL,
        Some(AxesRelation::Intersecting(_)) => QS_AXES_COPLANAR_INTERSECTING,
        Some(AxesRelation::Skew) => QS_AXES_SKEW,
        Some(other) => {
            return Err(Error::internal(format!(
                "axes {} have no C code",
                other.as_str()
            )));
        }
    })
}

fn count(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// The classification of `a` and `b` (class and counts only: the fast
/// route), and the budget error when the budget ran out (the class is then
/// `QS_CLASS_UNDECIDED`).
fn classify(
    a: &qs_natural_f64,
    b: &qs_natural_f64,
    budget: engine::Budget,
) -> Result<Answer<qs_natural_result>, Error> {
    let (a, b) = (natural_of(a, "a")?, natural_of(b, "b")?);
    let options = ClassifyOptions::with_budget(budget).without_components();
    let r = engine::classify_with(&a, &b, &options)?;
    natural_result(&r)
}

/// The class, counts, axes and Theorem 8 of a report, and the budget
/// error when the budget ran out (the class is then `QS_CLASS_UNDECIDED`
/// and the counts 0).
pub(crate) fn natural_result(r: &NaturalReport) -> Result<Answer<qs_natural_result>, Error> {
    let exhausted = r.exhausted().map(|e| Error::from(e.clone()));
    let undecided = exhausted.is_some();
    let counted = |n: usize| if undecided { 0 } else { count(n) };
    let out = qs_natural_result {
        cls: class_code(r.class())?,
        conics: counted(r.conics()),
        lines: counted(r.lines()),
        points: counted(r.points()),
        axes: axes_code(r.axes())?,
        thm8: r.thm8().map_or(-1, i32::from),
    };
    Ok((out, exhausted))
}

/// Classifies the intersection of two natural quadrics given in doubles
/// (exact values), under the default budget: fills `*out` with the class
/// and the counts of conics, lines and points (by the fast route: no
/// components are computed).  Returns 0; 3 (`QS_ERR_BUDGET`) when the
/// budget ran out: `*out` is then `QS_CLASS_UNDECIDED` with zero counts;
/// 2 for bad input (NaN, infinity, radius² ≤ 0, a zero axis, an unknown
/// kind) or 1 internal: `*out` is then zeroed.  On every non-zero code
/// `*err` (when `err` is not NULL) says why.
///
/// # Safety
/// `a` and `b` are NULL or valid `qs_natural_f64`; `out` is NULL or
/// writable; `err` is NULL or points to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_classify_f64(
    a: *const qs_natural_f64,
    b: *const qs_natural_f64,
    out: *mut qs_natural_result,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe { qs_natural_classify_f64_opts(a, b, ptr::null(), out, err) }
}

/// `qs_natural_classify_f64` with options (`opts` NULL: the defaults).
///
/// # Safety
/// As `qs_natural_classify_f64`; `opts` is NULL or a live `qs_options`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_classify_f64_opts(
    a: *const qs_natural_f64,
    b: *const qs_natural_f64,
    opts: *const qs_options,
    out: *mut qs_natural_result,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        answer_into(out, "out", qs_natural_result::default(), err, || {
            classify(read_ref(a, "a")?, read_ref(b, "b")?, budget_of(opts))
        })
    }
}

/// The ellipsoid `e`, checked (finite doubles, semi-axes > 0, invertible
/// matrix).
fn ellipsoid_of(e: &qs_ellipsoid_f64) -> Result<Ellipsoid, Error> {
    let center = exact3(&e.center, "e.center")?;
    let semi = exact3(&e.semi_axes, "e.semi_axes")?;
    let row = |r: usize| exact3(&e.rotation[r], &format!("e.rotation[{r}]"));
    let m = [row(0)?, row(1)?, row(2)?];
    Ellipsoid::from_frame(center, semi, m).map_err(|x| x.context("in the ellipsoid"))
}

/// The quadric `Σ c_k m_k` with the monomials x², y², z², xy, xz, yz, x,
/// y, z, 1.
fn quadric_of(c: &[f64; 10]) -> Result<Polynomial, Error> {
    let (x, y, z) = (
        Polynomial::var(Var::X),
        Polynomial::var(Var::Y),
        Polynomial::var(Var::Z),
    );
    let one = Polynomial::from(1);
    let monomials = [
        &x * &x,
        &y * &y,
        &z * &z,
        &x * &y,
        &x * &z,
        &y * &z,
        x,
        y,
        z,
        one,
    ];
    let mut s = Polynomial::zero();
    for (k, m) in monomials.iter().enumerate() {
        let ck = exact_double(c[k], || format!("quadric[{k}]"))?;
        s = s + m * ck;
    }
    Ok(s)
}

/// The tangent point method on `e` and `quadric`, and the budget error
/// when the budget ran out (the verdict is then undecided).
fn tangent(
    e: &qs_ellipsoid_f64,
    quadric: &[f64; 10],
    budget: engine::Budget,
) -> Result<Answer<qs_tangent_result>, Error> {
    let e = ellipsoid_of(e)?;
    let s = quadric_of(quadric)?;
    let r = engine::decide_with(&e, &s, &TangentOptions::with_budget(budget))?;
    let verdict = match r.verdict() {
        Verdict::Intersecting => QS_VERDICT_INTERSECTING,
        Verdict::Touching => QS_VERDICT_TOUCHING,
        Verdict::Separated => QS_VERDICT_SEPARATED,
        _ => QS_VERDICT_UNDECIDED,
    };
    let (reason, exhausted) = match r.undecided() {
        None => (QS_UNDECIDED_NONE, None),
        Some(Undecided::Budget(e)) => (QS_UNDECIDED_BUDGET, Some(Error::from(e.clone()))),
        Some(_) => (QS_UNDECIDED_NO_CERTIFICATE, None),
    };
    let out = qs_tangent_result {
        verdict,
        side: match r.side() {
            Some(Side::Positive) => QS_SIDE_POSITIVE,
            Some(Side::Negative) => QS_SIDE_NEGATIVE,
            None => QS_SIDE_NONE,
        },
        containment: match r.containment() {
            Some(Containment::EInsideS) => QS_CONTAINMENT_E_INSIDE_S,
            Some(Containment::SInsideE) => QS_CONTAINMENT_S_INSIDE_E,
            Some(Containment::Apart) => QS_CONTAINMENT_APART,
            Some(Containment::Coincident) => QS_CONTAINMENT_COINCIDENT,
            _ => QS_CONTAINMENT_NONE,
        },
        reason,
        minimum: qs_interval::of(r.min()),
        maximum: qs_interval::of(r.max()),
    };
    Ok((out, exhausted))
}

/// Decides an ellipsoid against a quadric surface given in doubles (exact
/// values), under the default budget.  `quadric` points to 10 doubles, the
/// coefficients of S in this order:
/// `x², y², z², xy, xz, yz, x, y, z, 1`
/// (S = q[0]x² + q[1]y² + q[2]z² + q[3]xy + q[4]xz + q[5]yz + q[6]x +
/// q[7]y + q[8]z + q[9]; a plane when the first six are 0).  Fills `*out`
/// with the verdict, the side, and ν = min and μ = max of S on E rounded
/// outward to doubles.  Returns 0; 3 (`QS_ERR_BUDGET`) when the budget
/// ran out: `*out` is then `QS_VERDICT_UNDECIDED` with `reason`
/// `QS_UNDECIDED_BUDGET`; 2 for bad input (NaN, infinity, a semi-axis
/// ≤ 0, a singular matrix, S = 0) or 1 internal: `*out` is then cleared
/// (undecided, unknown bounds).  On every non-zero code `*err` (when `err`
/// is not NULL) says why.  An undecided verdict without a certificate
/// (`QS_UNDECIDED_NO_CERTIFICATE`) is an answer, code 0.
///
/// # Safety
/// `e` is NULL or a valid `qs_ellipsoid_f64`; `quadric` is NULL or points
/// to 10 readable doubles; `out` is NULL or writable; `err` is NULL or
/// points to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_tangent_quadric_f64(
    e: *const qs_ellipsoid_f64,
    quadric: *const f64,
    out: *mut qs_tangent_result,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe { qs_tangent_quadric_f64_opts(e, quadric, ptr::null(), out, err) }
}

/// `qs_tangent_quadric_f64` with options (`opts` NULL: the defaults).
///
/// # Safety
/// As `qs_tangent_quadric_f64`; `opts` is NULL or a live `qs_options`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_tangent_quadric_f64_opts(
    e: *const qs_ellipsoid_f64,
    quadric: *const f64,
    opts: *const qs_options,
    out: *mut qs_tangent_result,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        answer_into(out, "out", qs_tangent_result::CLEAR, err, || {
            let q = read_ref(quadric.cast::<[f64; 10]>(), "quadric")?;
            tangent(read_ref(e, "e")?, q, budget_of(opts))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::boundary::qs_error_free;
    use crate::boundary::tests::take_message;
    use proptest::prelude::*;

    const ID: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

    fn sphere(c: [f64; 3], r2: f64) -> qs_natural_f64 {
        qs_natural_f64 {
            kind: QS_SPHERE,
            point: c,
            axis: [f64::NAN; 3],
            param: r2,
        }
    }

    fn cyl(p: [f64; 3], a: [f64; 3], r2: f64) -> qs_natural_f64 {
        qs_natural_f64 {
            kind: QS_CYLINDER,
            point: p,
            axis: a,
            param: r2,
        }
    }

    fn classify_c(a: &qs_natural_f64, b: &qs_natural_f64) -> (c_int, qs_natural_result, String) {
        let mut out = qs_natural_result {
            cls: 99,
            ..Default::default()
        };
        let mut err = ptr::null_mut();
        let code = unsafe { qs_natural_classify_f64(a, b, &mut out, &mut err) };
        (code, out, take_message(err))
    }

    fn tangent_c(e: &qs_ellipsoid_f64, q: &[f64; 10]) -> (c_int, qs_tangent_result, String) {
        let mut out = qs_tangent_result::CLEAR;
        let mut err = ptr::null_mut();
        let code = unsafe { qs_tangent_quadric_f64(e, q.as_ptr(), &mut out, &mut err) };
        (code, out, take_message(err))
    }

    #[test]
    fn perpendicular_cylinders_meet_in_two_conics() {
        let a = cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0);
        let b = cyl([0.0; 3], [0.0, 1.0, 0.0], 1.0);
        let (code, r, _) = classify_c(&a, &b);
        assert_eq!(code, 0);
        assert_eq!(
            (r.cls, r.conics, r.lines, r.points),
            (QS_CLASS_CONICS, 2, 0, 0)
        );
        assert_eq!((r.axes, r.thm8), (QS_AXES_COPLANAR_INTERSECTING, 1));
        // a sphere: no axes, thm8 not applicable (the sphere's NaN axis is not read)
        let (code, r, _) = classify_c(&sphere([0.0; 3], 4.0), &sphere([1.0, 0.0, 0.0], 1.0));
        assert_eq!(code, 0);
        assert_eq!((r.cls, r.axes, r.thm8), (QS_CLASS_POINTS, QS_AXES_NONE, -1));
    }

    #[test]
    fn doubles_are_taken_exactly_one_ulp_decides() {
        // two unit spheres whose centres are 2 apart touch; one ulp closer
        // they meet in a circle, one ulp farther they miss
        let a = sphere([0.0; 3], 1.0);
        let at = |x: f64| classify_c(&a, &sphere([x, 0.0, 0.0], 1.0)).1;
        let touch = at(2.0);
        assert_eq!((touch.cls, touch.points), (QS_CLASS_POINTS, 1));
        let closer = at(2.0f64.next_down());
        assert_eq!((closer.cls, closer.conics), (QS_CLASS_CONICS, 1));
        assert_eq!(at(2.0f64.next_up()).cls, QS_CLASS_EMPTY);
    }

    #[test]
    fn hostile_natural_input_gives_code_2_and_a_message() {
        let ok = sphere([0.0; 3], 1.0);
        let cases = [
            (sphere([f64::NAN, 0.0, 0.0], 1.0), "a.point[0] is NaN"),
            (sphere([0.0; 3], f64::INFINITY), "a.param is inf"),
            (sphere([0.0; 3], -1.0), "radius2 must be > 0"),
            (
                cyl([0.0; 3], [0.0; 3], 1.0),
                "axis direction must be non-zero",
            ),
            (
                cyl([0.0; 3], [1.0, f64::NEG_INFINITY, 0.0], 1.0),
                "a.axis[1] is -inf",
            ),
            (qs_natural_f64 { kind: 7, ..ok }, "a.kind is 7"),
        ];
        for (bad, want) in cases {
            let (code, out, msg) = classify_c(&bad, &ok);
            assert_eq!(code, 2, "{want}");
            assert!(msg.contains(want), "{msg} lacks {want}");
            assert_eq!(out, qs_natural_result::default());
        }
        let mut out = qs_natural_result::default();
        assert_eq!(
            unsafe { qs_natural_classify_f64(ptr::null(), &ok, &mut out, ptr::null_mut()) },
            2
        );
        assert_eq!(
            unsafe { qs_natural_classify_f64(&ok, &ok, ptr::null_mut(), ptr::null_mut()) },
            2
        );
    }

    #[test]
    fn the_same_ellipsoid_is_coincident() {
        // E: sphere of radius 5; S = 2·(x² + y² + z² − 25)
        let e = qs_ellipsoid_f64 {
            center: [0.0; 3],
            semi_axes: [5.0; 3],
            rotation: ID,
        };
        let q = [2.0, 2.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -50.0];
        let (code, r, msg) = tangent_c(&e, &q);
        assert_eq!(code, 0, "{msg}");
        assert_eq!(r.verdict, QS_VERDICT_TOUCHING);
        assert_eq!(r.containment, QS_CONTAINMENT_COINCIDENT);
    }

    #[test]
    fn paper_example_1_in_doubles_gives_exact_bounds() {
        // E: sphere of radius 5; S = (x−9)²/9 + y²/4 + z²/16 − 1 (scaled by
        // 144 to integer coefficients): min 7/9·144 = 112, max 187/9·144 = 2992
        let e = qs_ellipsoid_f64 {
            center: [0.0; 3],
            semi_axes: [5.0; 3],
            rotation: ID,
        };
        let q = [
            16.0,
            36.0,
            9.0,
            0.0,
            0.0,
            0.0,
            -288.0,
            0.0,
            0.0,
            1296.0 - 144.0,
        ];
        let (code, r, msg) = tangent_c(&e, &q);
        assert_eq!(code, 0, "{msg}");
        assert_eq!(
            (r.verdict, r.side, r.reason),
            (QS_VERDICT_SEPARATED, QS_SIDE_POSITIVE, QS_UNDECIDED_NONE)
        );
        assert_eq!(
            r.minimum,
            qs_interval {
                lo: 112.0,
                hi: 112.0,
                exact: 1,
                known: 1
            }
        );
        assert_eq!(
            r.maximum,
            qs_interval {
                lo: 2992.0,
                hi: 2992.0,
                exact: 1,
                known: 1
            }
        );
    }

    #[test]
    fn irrational_extremes_are_enclosed_by_neighbouring_doubles() {
        // S = x + y on the unit sphere: min −√2, max √2
        let e = qs_ellipsoid_f64 {
            center: [0.0; 3],
            semi_axes: [1.0; 3],
            rotation: ID,
        };
        let q = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0];
        let (code, r, _) = tangent_c(&e, &q);
        assert_eq!(code, 0);
        assert_eq!(r.verdict, QS_VERDICT_INTERSECTING);
        let s2 = std::f64::consts::SQRT_2;
        assert_eq!(r.maximum.exact, 0);
        assert!(r.maximum.lo < r.maximum.hi && r.maximum.hi == r.maximum.lo.next_up());
        assert!(r.maximum.lo <= s2 && s2 <= r.maximum.hi);
        assert_eq!((r.minimum.lo, r.minimum.hi), (-r.maximum.hi, -r.maximum.lo));
    }

    #[test]
    fn hostile_tangent_input_gives_code_2_and_a_cleared_answer() {
        let e = qs_ellipsoid_f64 {
            center: [0.0; 3],
            semi_axes: [1.0; 3],
            rotation: ID,
        };
        let q = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0];
        let mut bad_e = e;
        bad_e.rotation[1][2] = f64::NAN;
        let (code, r, msg) = tangent_c(&bad_e, &q);
        assert_eq!(code, 2);
        assert!(msg.contains("e.rotation[1][2] is NaN"), "{msg}");
        assert!(r.minimum.lo.is_nan() && r.minimum.known == 0);
        let singular = qs_ellipsoid_f64 {
            rotation: [[1.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            ..e
        };
        let (code, _, msg) = tangent_c(&singular, &q);
        assert_eq!(code, 2);
        assert!(msg.contains("singular"), "{msg}");
        let flat = qs_ellipsoid_f64 {
            semi_axes: [1.0, 0.0, 1.0],
            ..e
        };
        assert_eq!(tangent_c(&flat, &q).0, 2);
        assert!(tangent_c(&e, &[0.0; 10]).2.contains("zero polynomial"));
        let mut nan_q = q;
        nan_q[9] = f64::NAN;
        assert!(tangent_c(&e, &nan_q).2.contains("quadric[9] is NaN"));
        let mut out = qs_tangent_result::CLEAR;
        assert_eq!(
            unsafe { qs_tangent_quadric_f64(&e, ptr::null(), &mut out, ptr::null_mut()) },
            2
        );
        assert_eq!(
            unsafe { qs_tangent_quadric_f64(ptr::null(), q.as_ptr(), &mut out, ptr::null_mut()) },
            2
        );
    }

    #[test]
    fn a_double_rotation_is_used_as_given() {
        // a rotation by 30° about z in doubles is orthogonal only up to
        // rounding; the answer is the one for those exact numbers
        let (s, c) = (0.5f64, 3f64.sqrt() / 2.0);
        let rot = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
        let e = qs_ellipsoid_f64 {
            center: [1.0, 2.0, 3.0],
            semi_axes: [3.0, 2.0, 1.0],
            rotation: rot,
        };
        let plane_far = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -10.0];
        let (code, r, _) = tangent_c(&e, &plane_far);
        assert_eq!(code, 0);
        assert_eq!(
            (r.verdict, r.side),
            (QS_VERDICT_SEPARATED, QS_SIDE_NEGATIVE)
        );
        // z ranges over [2, 4]: S = z − 10 over [−8, −6], exactly
        assert_eq!((r.minimum.lo, r.minimum.exact), (-8.0, 1));
        assert_eq!((r.maximum.lo, r.maximum.exact), (-6.0, 1));
    }

    #[test]
    fn an_exhausted_budget_gives_code_3_and_an_undecided_answer() {
        let opts = crate::options::qs_options_new();
        unsafe { crate::options::qs_options_set_time_limit(opts, 0.0, ptr::null_mut()) };
        let a = sphere([0.0; 3], 1.0);
        let b = cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0);
        let mut n = qs_natural_result::default();
        let mut err = ptr::null_mut();
        let code = unsafe { qs_natural_classify_f64_opts(&a, &b, opts, &mut n, &mut err) };
        assert_eq!(code, crate::boundary::QS_ERR_BUDGET);
        assert_eq!(
            (n.cls, n.conics, n.lines, n.points),
            (QS_CLASS_UNDECIDED, 0, 0, 0)
        );
        assert!(!err.is_null());
        unsafe { qs_error_free(err) };
        let e = qs_ellipsoid_f64 {
            center: [0.0; 3],
            semi_axes: [1.0; 3],
            rotation: ID,
        };
        let q = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -3.0];
        let mut t = qs_tangent_result::CLEAR;
        t.verdict = 99;
        let code =
            unsafe { qs_tangent_quadric_f64_opts(&e, q.as_ptr(), opts, &mut t, ptr::null_mut()) };
        assert_eq!(code, crate::boundary::QS_ERR_BUDGET);
        assert_eq!(
            (t.verdict, t.reason, t.minimum.known),
            (QS_VERDICT_UNDECIDED, QS_UNDECIDED_BUDGET, 0)
        );
        unsafe { crate::options::qs_options_free(opts) };
    }

    #[test]
    fn threads_share_nothing() {
        let handles: Vec<_> = (0..4)
            .map(|i| {
                std::thread::spawn(move || {
                    let e = qs_ellipsoid_f64 {
                        center: [0.0; 3],
                        semi_axes: [1.0; 3],
                        rotation: ID,
                    };
                    let q = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -(i as f64)];
                    (0..20)
                        .map(|_| tangent_c(&e, &q).1.maximum.lo)
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        for (i, h) in handles.into_iter().enumerate() {
            // S = x − i on the unit sphere: max 1 − i, exactly
            assert!(h.join().unwrap().iter().all(|&m| m == 1.0 - i as f64));
        }
    }

    proptest! {
        /// Property: for an axis-parallel ellipsoid and a plane S = x − t,
        /// the returned bounds contain the exact extremes c ± a − t.
        #[test]
        fn plane_extremes_are_enclosed(c in -1e3f64..1e3, a in 1e-3f64..1e3, t in -1e3f64..1e3) {
            let e = qs_ellipsoid_f64 { center: [c, 0.0, 0.0], semi_axes: [a, 1.0, 1.0], rotation: ID };
            let q = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -t];
            let (code, r, _) = tangent_c(&e, &q);
            prop_assert_eq!(code, 0);
            let (c, a, t) = (exact(c).unwrap(), exact(a).unwrap(), exact(t).unwrap());
            for (iv, v) in [(r.minimum, &c - &a - &t), (r.maximum, &c + &a - &t)] {
                prop_assert!(exact(iv.lo).unwrap() <= v && v <= exact(iv.hi).unwrap());
                prop_assert_eq!(iv.exact == 1, iv.lo == iv.hi);
            }
        }
    }
}
