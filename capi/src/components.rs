//! The typed components of two natural quadrics: the class and counts of
//! `qs_natural_classify_f64` and every real component (conics, lines,
//! isolated points, space curves) as doubles, each with a proven bound on
//! its error (`qs_ball`), in one owned result freed by
//! `qs_natural_components_free`.

use crate::boundary::{Answer, answer_into, qs_error, read_ref};
use crate::float::{exact, round_outward};
use crate::options::{budget_of, qs_options};
use crate::typed::{natural_of, natural_result, qs_natural_f64, qs_natural_result};
use engine::ClassifyOptions;
use engine::natural::{
    Component, ConicKind, CurveBranch, EPoint, Exact, PointKind, SingularKind, SingularPoint,
    normalize_axis_direction, normalize_plane,
};
use engine::{BigInt, Budget, Error, QSqrt, Rational};
use num_traits::Zero;
use std::ffi::c_int;
use std::ptr;

/// A real number as a double with a proven bound on its error: the exact
/// value `x` satisfies `|x − value| ≤ bound` (the double arithmetic of
/// the check is the caller's: `value − bound ≤ x ≤ value + bound` holds
/// for the real numbers these doubles denote).  A rational `x` is rounded
/// to the nearest double: `bound` is 0 when `x` is that double, otherwise
/// one unit in the last place; an irrational `x` (`a + b√d`, or a root of
/// a higher-degree polynomial) is within a few units in the last place
/// (the `[value, bound]` pairs of the JSON's `f64` blocks); a curve's
/// branch point within about 1e-10 relative.  Beyond the range of doubles
/// `value` is ±infinity and `bound` infinity (possible for coordinates
/// only: directions and planes are scaled into range).  A field that does
/// not apply (a parabola's semi-axes, an ellipse's focal length², an
/// unused array entry) is `{NaN, NaN}`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_ball {
    /// The double nearest to the exact value, or close to it.
    pub value: f64,
    /// A proven bound on `|exact − value|`.
    pub bound: f64,
}

impl qs_ball {
    /// A field that does not apply.
    const ABSENT: qs_ball = qs_ball {
        value: f64::NAN,
        bound: f64::NAN,
    };

    /// A rational as the nearest double, with bound 0 when it is that
    /// double and the spacing of the two doubles around it otherwise;
    /// other numbers (and rationals beyond the range of doubles) by
    /// `Exact::to_f64_bounded`, as in the JSON's `f64` blocks.
    fn of(x: &Exact) -> qs_ball {
        if let Exact::Quad(r) = x
            && r.is_rational()
        {
            // b = 0: the approximation is the rational itself
            let q = x.to_rational_approx(0);
            let (lo, hi) = round_outward(&q);
            if lo == hi {
                return qs_ball {
                    value: lo,
                    bound: 0.0,
                };
            }
            if let (Some(l), Some(h)) = (exact(lo), exact(hi)) {
                // neighbouring doubles: hi − lo is exact
                let value = if &q - &l <= &h - &q { lo } else { hi };
                return qs_ball {
                    value,
                    bound: hi - lo,
                };
            }
        }
        let (value, bound) = x.to_f64_bounded();
        qs_ball { value, bound }
    }

    fn of_point(p: &EPoint) -> [qs_ball; 3] {
        [qs_ball::of(&p[0]), qs_ball::of(&p[1]), qs_ball::of(&p[2])]
    }
}

/// About `log2 |x|` from above (`a + b√d` as `max(|a|, |b|·√d)`, each
/// within a few units), or `None` for 0 and for roots of higher-degree
/// polynomials.
fn log2_magnitude(x: &Exact) -> Option<i64> {
    let log2 = |q: &Rational| {
        (!q.is_zero()).then(|| {
            let bits = |n: &BigInt| i64::try_from(n.bits()).unwrap_or(i64::MAX / 4);
            bits(q.numer()) - bits(q.denom())
        })
    };
    match x {
        Exact::Quad(q) => {
            let root = log2(q.b()).zip(log2(q.d())).map(|(b, d)| b + d / 2);
            log2(q.a()).max(root)
        }
        _ => None,
    }
}

/// A scale-free tuple (a direction; a plane's normal and offset) whose
/// largest entry lies beyond the comfortable range of doubles (about
/// `2^±900`), scaled exactly by a power of two so that it is near 1; any
/// other tuple unchanged.  Entries in `a + b√d` only: a tuple with a root
/// of a higher-degree polynomial is left as it is.
fn fit_scale(v: &mut [Exact]) -> Result<(), Error> {
    let Some(e) = v.iter().filter_map(log2_magnitude).max() else {
        return Ok(());
    };
    if (-900..=900).contains(&e) || v.iter().any(|x| matches!(x, Exact::Alg(_))) {
        return Ok(());
    }
    let shift = usize::try_from(e.unsigned_abs())
        .map_err(|_| Error::internal("a direction beyond any scale"))?;
    let p = Rational::from_integer(BigInt::from(1) << shift);
    let s = if e > 0 { p.recip() } else { p };
    for x in v.iter_mut() {
        if let Exact::Quad(q) = x {
            *x = Exact::Quad(QSqrt::try_new(q.a() * &s, q.b() * &s, q.d().clone())?);
        }
    }
    Ok(())
}

/// A conic's axis direction as the JSON gives it (rational ones scaled to
/// primitive integers), then by [`fit_scale`].
fn axis_direction(d: &EPoint, kind: ConicKind) -> Result<EPoint, Error> {
    scaled(&normalize_axis_direction(d, kind))
}

/// A line's direction as the JSON gives it, then by [`fit_scale`].
fn scaled(d: &EPoint) -> Result<EPoint, Error> {
    let mut d = d.clone();
    fit_scale(&mut d)?;
    Ok(d)
}

/// A plane's normal and offset as the JSON gives them (rational planes
/// scaled to primitive integers), then by [`fit_scale`].
fn plane(p: &engine::natural::Plane) -> Result<(EPoint, Exact), Error> {
    let (n, o) = normalize_plane(p);
    let mut v = [n[0].clone(), n[1].clone(), n[2].clone(), o];
    fit_scale(&mut v)?;
    let [a, b, c, o] = v;
    Ok(([a, b, c], o))
}

/// The type of a component (`qs_component.tag`).
pub type qs_component_type = i32;
/// A conic: `data.conic`.
pub const QS_COMPONENT_CONIC: qs_component_type = 0;
/// A line: `data.line`.
pub const QS_COMPONENT_LINE: qs_component_type = 1;
/// An isolated point: `data.point`.
pub const QS_COMPONENT_POINT: qs_component_type = 2;
/// A space curve (a quartic, or a twisted cubic beside a common line):
/// `data.curve`.
pub const QS_COMPONENT_CURVE: qs_component_type = 3;

/// The type of a conic.
pub type qs_conic_kind = i32;
/// A circle.
pub const QS_CONIC_CIRCLE: qs_conic_kind = 0;
/// A non-circular ellipse.
pub const QS_CONIC_ELLIPSE: qs_conic_kind = 1;
/// A hyperbola.
pub const QS_CONIC_HYPERBOLA: qs_conic_kind = 2;
/// A parabola.
pub const QS_CONIC_PARABOLA: qs_conic_kind = 3;

/// Why an isolated point is isolated.
pub type qs_point_kind = i32;
/// The surfaces touch there (an isolated tangency point).
pub const QS_POINT_TANGENCY: qs_point_kind = 0;
/// A cone vertex that is an isolated point of the intersection.
pub const QS_POINT_VERTEX: qs_point_kind = 1;
/// An isolated singular point (acnode) of an intersection curve.
pub const QS_POINT_ACNODE: qs_point_kind = 2;

/// The type of a real singular point of a space curve.
pub type qs_singular_kind = i32;
/// An isolated real point (the tangent cone is imaginary); counted in
/// `qs_natural_result.points`.
pub const QS_SINGULAR_ACNODE: qs_singular_kind = 0;
/// Two real branches cross (a node with real tangents).
pub const QS_SINGULAR_CROSSING: qs_singular_kind = 1;
/// A cusp (the tangent cone is a double line).
pub const QS_SINGULAR_CUSP: qs_singular_kind = 2;
/// Two real branches touch.
pub const QS_SINGULAR_TACNODE: qs_singular_kind = 3;

/// A conic in its plane `normal · P = offset`.  The plane is the JSON's
/// (rational coefficients scaled to primitive integers), except that a
/// plane or direction whose numbers would lie beyond the range of doubles
/// is multiplied by a power of two (exactly) so that its largest entry is
/// near 1.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_conic {
    /// `QS_CONIC_…`.
    pub kind: qs_conic_kind,
    /// 1 when the surfaces are tangent along the conic (a double conic).
    pub is_double: i32,
    /// The plane's normal (not of unit length).
    pub normal: [qs_ball; 3],
    /// The plane's right-hand side.
    pub offset: qs_ball,
    /// 0: `center` is the centre (circle, ellipse, hyperbola); 1: it is
    /// the vertex (parabola).
    pub is_vertex: i32,
    /// How many entries of `semi_axes2` are set: 2, or 0 for a parabola.
    pub n_semi_axes2: u32,
    /// The centre, or the vertex of a parabola (see `is_vertex`).
    pub center: [qs_ball; 3],
    /// The squared semi-axes (a circle's radius² twice; a hyperbola's
    /// transverse one first); `{NaN, NaN}` for a parabola.
    pub semi_axes2: [qs_ball; 2],
    /// How many entries of `axis_dirs` are set: 2, or 1 for a parabola.
    pub n_axis_dirs: u32,
    /// The directions of the semi-axes in the same order (any length;
    /// rational ones scaled to primitive integers, as in the JSON), or
    /// `axis_dirs[0]` the axis of a parabola; unset entries are
    /// `{NaN, NaN}`.
    pub axis_dirs: [[qs_ball; 3]; 2],
    /// A parabola's squared focal length; `{NaN, NaN}` otherwise.
    pub focal2: qs_ball,
}

impl qs_conic {
    const ABSENT: qs_conic = qs_conic {
        kind: QS_CONIC_CIRCLE,
        is_double: 0,
        normal: [qs_ball::ABSENT; 3],
        offset: qs_ball::ABSENT,
        is_vertex: 0,
        n_semi_axes2: 0,
        center: [qs_ball::ABSENT; 3],
        semi_axes2: [qs_ball::ABSENT; 2],
        n_axis_dirs: 0,
        axis_dirs: [[qs_ball::ABSENT; 3]; 2],
        focal2: qs_ball::ABSENT,
    };
}

/// A line `point + t·direction`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_line {
    /// A point of the line.
    pub point: [qs_ball; 3],
    /// Its direction (non-zero, any length: the JSON's, multiplied by a
    /// power of two when its numbers would lie beyond the range of
    /// doubles).
    pub direction: [qs_ball; 3],
    /// 1 when the surfaces are tangent along it (a double line).
    pub is_double: i32,
}

/// An isolated point of the intersection.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_point {
    /// Its coordinates.
    pub point: [qs_ball; 3],
    /// `QS_POINT_…`.
    pub kind: qs_point_kind,
}

/// A real singular point of a space curve.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_singular_point {
    /// Its coordinates.
    pub point: [qs_ball; 3],
    /// `QS_SINGULAR_…`.
    pub kind: qs_singular_kind,
}

/// A real affine connected component (branch) of a space curve.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_curve_branch {
    /// 1: a closed loop; 0: both its ends go to infinity.
    pub bounded: i32,
    /// A point on it (where a marcher can start).
    pub point: [qs_ball; 3],
}

/// A space curve that is not made of lines and conics.  The arrays belong
/// to the `qs_natural_components` result and live until
/// `qs_natural_components_free`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct qs_curve {
    /// Its degree (4, or 3 for a twisted cubic beside a common line).
    pub degree: u32,
    /// The number of its real affine singular points.
    pub n_singular: usize,
    /// Its singular points (NULL when `n_singular` is 0).
    pub singular: *const qs_singular_point,
    /// The number of its real affine connected components (at least 1
    /// for a real curve); 0 only when they were not traced (a rare shape of
    /// the twisted cubic beside a common line, with a note in the JSON).
    pub n_branches: usize,
    /// Its connected components (NULL when `n_branches` is 0).
    pub branches: *const qs_curve_branch,
}

/// The data of a component: the member named by `qs_component.tag`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union qs_component_data {
    /// `QS_COMPONENT_CONIC`.
    pub conic: qs_conic,
    /// `QS_COMPONENT_LINE`.
    pub line: qs_line,
    /// `QS_COMPONENT_POINT`.
    pub point: qs_point,
    /// `QS_COMPONENT_CURVE`.
    pub curve: qs_curve,
}

/// A real component of the intersection: a tag and its data.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct qs_component {
    /// `QS_COMPONENT_CONIC`, `_LINE`, `_POINT` or `_CURVE`: which member
    /// of `data` is set.
    pub tag: qs_component_type,
    /// The component.
    pub data: qs_component_data,
}

/// The answer of `qs_natural_components_f64`: the class and counts (as
/// `qs_natural_classify_f64` gives them) and the real affine components.
/// Made by the library, read-only for the caller, freed (with every array
/// in it) by `qs_natural_components_free`.
#[repr(C)]
#[derive(Debug)]
pub struct qs_natural_components {
    /// The class, counts, axes and Theorem 8.
    pub result: qs_natural_result,
    /// The number of components (0 for the classes empty, same surface
    /// and undecided).
    pub count: usize,
    /// The components (NULL when `count` is 0).
    pub components: *const qs_component,
}

/// The allocation behind a `qs_natural_components *`: the header first
/// (the pointer the host holds), then the arrays it points into.
#[repr(C)]
struct Owned {
    head: qs_natural_components,
    components: Vec<qs_component>,
    singular: Vec<Vec<qs_singular_point>>,
    branches: Vec<Vec<qs_curve_branch>>,
}

/// The start of `v`, or NULL when it is empty.
fn start<T>(v: &[T]) -> *const T {
    if v.is_empty() {
        ptr::null()
    } else {
        v.as_ptr()
    }
}

fn conic_kind(k: ConicKind) -> Result<qs_conic_kind, Error> {
    Ok(match k {
        ConicKind::Circle => QS_CONIC_CIRCLE,
        ConicKind::Ellipse => QS_CONIC_ELLIPSE,
        ConicKind::Hyperbola => QS_CONIC_HYPERBOLA,
        ConicKind::Parabola => QS_CONIC_PARABOLA,
        other => {
            return Err(Error::internal(format!(
                "conic {} has no C code",
                other.as_str()
            )));
        }
    })
}

fn point_kind(k: PointKind) -> Result<qs_point_kind, Error> {
    Ok(match k {
        PointKind::Tangency => QS_POINT_TANGENCY,
        PointKind::Vertex => QS_POINT_VERTEX,
        PointKind::Acnode => QS_POINT_ACNODE,
        other => {
            return Err(Error::internal(format!(
                "point kind {} has no C code",
                other.as_str()
            )));
        }
    })
}

fn singular_kind(k: SingularKind) -> Result<qs_singular_kind, Error> {
    Ok(match k {
        SingularKind::Acnode => QS_SINGULAR_ACNODE,
        SingularKind::Crossing => QS_SINGULAR_CROSSING,
        SingularKind::Cusp => QS_SINGULAR_CUSP,
        SingularKind::Tacnode => QS_SINGULAR_TACNODE,
        other => {
            return Err(Error::internal(format!(
                "singular point {} has no C code",
                other.as_str()
            )));
        }
    })
}

/// At most two entries of `v` into `out` (the rest stay absent); more is
/// an internal error.
fn fill<T, U>(out: &mut [U; 2], v: &[T], f: impl Fn(&T) -> U, what: &str) -> Result<u32, Error> {
    if v.len() > 2 {
        return Err(Error::internal(format!("a conic with {} {what}", v.len())));
    }
    for (o, x) in out.iter_mut().zip(v) {
        *o = f(x);
    }
    Ok(v.len() as u32)
}

/// The C form of `c`; a curve's arrays are pushed to `owned`.
fn component(c: &Component, owned: &mut Owned) -> Result<qs_component, Error> {
    // the largest member first, so every byte of the union is written
    let mut data = qs_component_data {
        conic: qs_conic::ABSENT,
    };
    let tag = match c {
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
            let (normal, offset) = self::plane(plane)?;
            let mut k = qs_conic {
                kind: conic_kind(*kind)?,
                is_double: i32::from(*double),
                normal: qs_ball::of_point(&normal),
                offset: qs_ball::of(&offset),
                is_vertex: i32::from(center.is_none() && vertex.is_some()),
                ..qs_conic::ABSENT
            };
            if let Some(p) = center.as_ref().or(vertex.as_ref()) {
                k.center = qs_ball::of_point(p);
            }
            k.n_semi_axes2 = fill(&mut k.semi_axes2, axes2, qs_ball::of, "semi-axes")?;
            let dirs = axis_dirs
                .iter()
                .map(|d| axis_direction(d, *kind))
                .collect::<Result<Vec<_>, _>>()?;
            k.n_axis_dirs = fill(
                &mut k.axis_dirs,
                &dirs,
                qs_ball::of_point,
                "axis directions",
            )?;
            if let Some(f) = focal2 {
                k.focal2 = qs_ball::of(f);
            }
            data.conic = k;
            QS_COMPONENT_CONIC
        }
        Component::Line {
            point,
            direction,
            double,
        } => {
            data.line = qs_line {
                point: qs_ball::of_point(point),
                direction: qs_ball::of_point(&scaled(direction)?),
                is_double: i32::from(*double),
            };
            QS_COMPONENT_LINE
        }
        Component::Point { point, kind } => {
            data.point = qs_point {
                point: qs_ball::of_point(point),
                kind: point_kind(*kind)?,
            };
            QS_COMPONENT_POINT
        }
        Component::Curve {
            degree,
            singular,
            branches,
        } => {
            let s = singular
                .iter()
                .map(|p: &SingularPoint| {
                    Ok(qs_singular_point {
                        point: qs_ball::of_point(&p.point),
                        kind: singular_kind(p.kind)?,
                    })
                })
                .collect::<Result<Vec<_>, Error>>()?;
            let b: Vec<qs_curve_branch> = branches
                .iter()
                .map(|b: &CurveBranch| {
                    let a = b.start.approx();
                    qs_curve_branch {
                        bounded: i32::from(b.bounded),
                        point: a.map(|(value, bound)| qs_ball { value, bound }),
                    }
                })
                .collect();
            // the vectors' buffers stay where they are when the vectors move
            data.curve = qs_curve {
                degree: *degree,
                n_singular: s.len(),
                singular: start(&s),
                n_branches: b.len(),
                branches: start(&b),
            };
            owned.singular.push(s);
            owned.branches.push(b);
            QS_COMPONENT_CURVE
        }
        _ => return Err(Error::internal("a component with no C form")),
    };
    Ok(qs_component { tag, data })
}

/// Classifies `a` and `b` with their components; the result, and the
/// budget error when the budget ran out (no components then).
fn components(
    a: &qs_natural_f64,
    b: &qs_natural_f64,
    budget: Budget,
) -> Result<Answer<Box<Owned>>, Error> {
    let (a, b) = (natural_of(a, "a")?, natural_of(b, "b")?);
    let r = engine::classify_with(&a, &b, &ClassifyOptions::with_budget(budget))?;
    let (result, exhausted) = natural_result(&r)?;
    let mut owned = Owned {
        head: qs_natural_components {
            result,
            count: 0,
            components: ptr::null(),
        },
        components: Vec::new(),
        singular: Vec::new(),
        branches: Vec::new(),
    };
    if exhausted.is_none() {
        let mut list = Vec::with_capacity(r.components().len());
        for c in r.components() {
            list.push(component(c, &mut owned)?);
        }
        owned.components = list;
    }
    owned.head.count = owned.components.len();
    owned.head.components = start(&owned.components);
    Ok((Box::new(owned), exhausted))
}

/// Classifies the intersection of two natural quadrics given in doubles
/// (exact values) and gives its real affine components: `*out` is a new
/// `qs_natural_components` with the class and counts (as
/// `qs_natural_classify_f64`) and `count` components, each a tagged
/// `qs_component` (`QS_COMPONENT_CONIC`, `_LINE`, `_POINT`, `_CURVE`)
/// whose numbers are doubles with proven error bounds (`qs_ball`), the
/// values of the JSON's `f64` blocks.  `opts` NULL means the default
/// budget (10 s).  Free `*out` with `qs_natural_components_free`.
///
/// Returns 0; 3 (`QS_ERR_BUDGET`) when the budget ran out: `*out` is then
/// a result with `QS_CLASS_UNDECIDED`, zero counts and no components (free
/// it too); 2 for bad input (NaN, infinity, radius² ≤ 0, a zero axis, an
/// unknown kind, a NULL pointer) or 1 internal: `*out` is then NULL.  On
/// every non-zero code `*err` (when `err` is not NULL) says why.  Slower
/// than `qs_natural_classify_f64`, which computes no components.
///
/// # Safety
/// `a` and `b` are NULL or valid `qs_natural_f64`; `opts` is NULL or a
/// live `qs_options`; `out` is NULL or writable; `err` is NULL or points
/// to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_components_f64(
    a: *const qs_natural_f64,
    b: *const qs_natural_f64,
    opts: *const qs_options,
    out: *mut *mut qs_natural_components,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        answer_into(out, "out", ptr::null_mut(), err, || {
            let (a, b) = (read_ref(a, "a")?, read_ref(b, "b")?);
            let (owned, exhausted) = components(a, b, budget_of(opts))?;
            // the header is the first field of the repr(C) Owned
            Ok((
                Box::into_raw(owned).cast::<qs_natural_components>(),
                exhausted,
            ))
        })
    }
}

/// Frees a result of `qs_natural_components_f64` with all its arrays
/// (NULL is allowed and does nothing).  Pointers into it (components,
/// singular points, branches) are invalid afterwards.
///
/// # Safety
/// `c` is NULL or a result of `qs_natural_components_f64`, unmodified and
/// freed only once.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_natural_components_free(c: *mut qs_natural_components) {
    if !c.is_null() {
        // SAFETY: made by Box::into_raw of an Owned (whose first field is
        // the header) in qs_natural_components_f64, freed once
        drop(unsafe { Box::from_raw(c.cast::<Owned>()) });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::boundary::tests::take_message;
    use crate::boundary::{QS_ERR_BUDGET, QS_ERR_INPUT};
    use crate::typed::{
        QS_CLASS_CONIC_AND_LINE, QS_CLASS_CONICS, QS_CLASS_CURVE, QS_CLASS_EMPTY, QS_CLASS_LINES,
        QS_CLASS_POINTS, QS_CLASS_SAME_SURFACE, QS_CLASS_UNDECIDED, QS_CONE, QS_CYLINDER,
        QS_SPHERE, qs_natural_classify_f64,
    };
    use engine::NaturalReport;
    use engine::{Rational, RealAlg};
    use proptest::prelude::*;
    use serde_json::Value;
    use std::cmp::Ordering;

    fn q(kind: i32, point: [f64; 3], axis: [f64; 3], param: f64) -> qs_natural_f64 {
        qs_natural_f64 {
            kind,
            point,
            axis,
            param,
        }
    }

    fn sphere(c: [f64; 3], r2: f64) -> qs_natural_f64 {
        q(QS_SPHERE, c, [0.0; 3], r2)
    }

    fn cyl(p: [f64; 3], a: [f64; 3], r2: f64) -> qs_natural_f64 {
        q(QS_CYLINDER, p, a, r2)
    }

    fn cone(v: [f64; 3], a: [f64; 3], t2: f64) -> qs_natural_f64 {
        q(QS_CONE, v, a, t2)
    }

    /// The C answer: code, the result (NULL on failure) and the message.
    fn run(
        a: &qs_natural_f64,
        b: &qs_natural_f64,
        opts: *const qs_options,
    ) -> (c_int, *mut qs_natural_components, String) {
        let mut out = ptr::dangling_mut(); // garbage the caller left there
        let mut err = ptr::null_mut();
        let code = unsafe { qs_natural_components_f64(a, b, opts, &mut out, &mut err) };
        (code, out, take_message(err))
    }

    /// The engine's exact answer for the same doubles.
    fn exact_report(a: &qs_natural_f64, b: &qs_natural_f64) -> NaturalReport {
        let (a, b) = (natural_of(a, "a").unwrap(), natural_of(b, "b").unwrap());
        engine::classify_with(&a, &b, &ClassifyOptions::default()).unwrap()
    }

    /// `|x − value| ≤ bound`, decided exactly, and the bound tight: a few
    /// ulps (a curve's branch points, from double balls: `1e-10` relative).
    /// `j` is the same number's `[value, bound]` in the JSON's `f64`
    /// blocks: both enclose `x`, and they are the same doubles when `x` is
    /// irrational (a rational is rounded to the nearest double here).
    fn encloses(ball: qs_ball, x: &Exact, j: &Value, what: &str) {
        let tol = if what.starts_with("branch") {
            1e-10
        } else {
            1e-14
        };
        assert!(
            ball.value.is_finite() && ball.bound.is_finite() && ball.bound >= 0.0,
            "{what}: {ball:?}"
        );
        assert!(
            ball.bound <= tol * ball.value.abs().max(1.0),
            "{what}: loose bound {ball:?}"
        );
        let x_alg = x.to_alg();
        let inside = |value: f64, bound: f64| {
            let v = Rational::from_float(value).unwrap();
            let e = Rational::from_float(bound).unwrap();
            let (lo, hi) = (RealAlg::rational(&v - &e), RealAlg::rational(&v + &e));
            lo.cmp_exact(&x_alg) != Ordering::Greater && x_alg.cmp_exact(&hi) != Ordering::Greater
        };
        assert!(
            inside(ball.value, ball.bound),
            "{what}: {ball:?} does not enclose {x_alg}"
        );
        let pair = |k: usize| {
            j[k].as_f64()
                .unwrap_or_else(|| panic!("{what}: JSON {j} is not [value, bound]"))
        };
        if j.is_null() {
            return; // scaled here, not in the JSON
        }
        let (jv, jb) = (pair(0), pair(1));
        assert!(inside(jv, jb), "{what}: JSON {j} does not enclose {x_alg}");
        let rational = matches!(x, Exact::Quad(r) if r.is_rational());
        if !rational {
            assert_eq!((ball.value, ball.bound), (jv, jb), "{what}: JSON {j}");
        }
    }

    fn encloses3(balls: &[qs_ball; 3], p: &EPoint, j: &Value, what: &str) {
        for i in 0..3 {
            encloses(balls[i], &p[i], &j[i], &format!("{what}[{i}]"));
        }
    }

    /// The JSON's numbers of `json` when `ours` (what the C side reports)
    /// equals `theirs` (what the JSON reports), else `Null`: no comparison.
    fn same_or_null<'a>(ours: &[Exact], theirs: &[Exact], json: &'a Value) -> &'a Value {
        if ours.iter().zip(theirs).all(|(x, y)| x.equals(y)) {
            json
        } else {
            &Value::Null
        }
    }

    fn absent(b: &qs_ball) -> bool {
        b.value.is_nan() && b.bound.is_nan()
    }

    /// Every number of `c` against the exact component `e` and its JSON
    /// `j` (an element of the JSON's `components`).
    fn check_component(c: &qs_component, e: &Component, j: &Value) {
        let f = &j["f64"];
        match e {
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
                assert_eq!(c.tag, QS_COMPONENT_CONIC);
                let k = unsafe { c.data.conic };
                assert_eq!(k.kind, conic_kind(*kind).unwrap());
                assert_eq!(k.is_double, i32::from(*double));
                let (n, o) = super::plane(plane).unwrap();
                let (jn, jo) = normalize_plane(plane);
                let fits = n.iter().zip(&jn).all(|(x, y)| x.equals(y)) && o.equals(&jo);
                let jp = if fits { &f["plane"] } else { &Value::Null };
                encloses3(&k.normal, &n, &jp["normal"], "normal");
                encloses(k.offset, &o, &jp["offset"], "offset");
                match (center, vertex) {
                    (Some(p), _) => {
                        assert_eq!(k.is_vertex, 0);
                        encloses3(&k.center, p, &f["center"], "center");
                    }
                    (None, Some(p)) => {
                        assert_eq!(k.is_vertex, 1);
                        encloses3(&k.center, p, &f["vertex"], "vertex");
                    }
                    (None, None) => assert!(k.center.iter().all(absent)),
                }
                assert_eq!(k.n_semi_axes2 as usize, axes2.len());
                for (i, s) in k.semi_axes2.iter().enumerate() {
                    match axes2.get(i) {
                        Some(x) => encloses(*s, x, &f["semi_axes2"][i], "semi_axes2"),
                        None => assert!(absent(s)),
                    }
                }
                assert_eq!(k.n_axis_dirs as usize, axis_dirs.len());
                for (i, d) in k.axis_dirs.iter().enumerate() {
                    match axis_dirs.get(i) {
                        Some(x) => {
                            let ours = axis_direction(x, *kind).unwrap();
                            let theirs = normalize_axis_direction(x, *kind);
                            let j = same_or_null(&ours, &theirs, &f["axis_directions"][i]);
                            encloses3(d, &ours, j, "axis_dirs");
                        }
                        None => assert!(d.iter().all(absent)),
                    }
                }
                match focal2 {
                    Some(x) => encloses(k.focal2, x, &f["focal_length2"], "focal2"),
                    None => assert!(absent(&k.focal2)),
                }
            }
            Component::Line {
                point,
                direction,
                double,
            } => {
                assert_eq!(c.tag, QS_COMPONENT_LINE);
                let l = unsafe { c.data.line };
                encloses3(&l.point, point, &f["point"], "line point");
                let ours = scaled(direction).unwrap();
                let j = same_or_null(&ours, direction, &f["direction"]);
                encloses3(&l.direction, &ours, j, "line direction");
                assert_eq!(l.is_double, i32::from(*double));
            }
            Component::Point { point, kind } => {
                assert_eq!(c.tag, QS_COMPONENT_POINT);
                let p = unsafe { c.data.point };
                encloses3(&p.point, point, &f["point"], "point");
                assert_eq!(p.kind, point_kind(*kind).unwrap());
            }
            Component::Curve {
                degree,
                singular,
                branches,
            } => {
                assert_eq!(c.tag, QS_COMPONENT_CURVE);
                let k = unsafe { c.data.curve };
                assert_eq!(k.degree, *degree);
                assert_eq!(k.n_singular, singular.len());
                assert_eq!(k.singular.is_null(), singular.is_empty());
                for (i, s) in singular.iter().enumerate() {
                    let cs = unsafe { *k.singular.add(i) };
                    let js = &f["singular_points"][i];
                    encloses3(&cs.point, &s.point, js, "singular point");
                    assert_eq!(cs.kind, singular_kind(s.kind).unwrap());
                }
                assert_eq!(k.n_branches, branches.len());
                assert_eq!(k.branches.is_null(), branches.is_empty());
                for (i, b) in branches.iter().enumerate() {
                    let cb = unsafe { *k.branches.add(i) };
                    assert_eq!(cb.bounded, i32::from(b.bounded));
                    let jb = &j["branches"][i];
                    assert_eq!(jb["bounded"], b.bounded);
                    encloses3(&cb.point, &b.start.exact(), &jb["point"], "branch point");
                }
            }
            _ => panic!("a new kind of component"),
        }
    }

    /// Every component of `o` against the engine's exact answer for the
    /// same pair and its JSON.
    fn check_components(o: &Owner, a: &qs_natural_f64, b: &qs_natural_f64) {
        let exact = exact_report(a, b);
        let json = serde_json::to_value(&exact).unwrap();
        let list = o.list();
        assert_eq!(list.len(), exact.components().len());
        assert_eq!(o.get().components.is_null(), list.is_empty());
        let js = json["components"].as_array().unwrap();
        assert_eq!(js.len(), list.len());
        for ((c, e), j) in list.iter().zip(exact.components()).zip(js) {
            check_component(c, e, j);
        }
    }

    /// A result of the C call, freed on drop.
    struct Owner(*mut qs_natural_components);

    impl Owner {
        fn get(&self) -> &qs_natural_components {
            unsafe { &*self.0 }
        }

        fn list(&self) -> &[qs_component] {
            let r = self.get();
            if r.count == 0 {
                &[]
            } else {
                unsafe { std::slice::from_raw_parts(r.components, r.count) }
            }
        }
    }

    impl Drop for Owner {
        fn drop(&mut self) {
            unsafe { qs_natural_components_free(self.0) };
        }
    }

    fn singular(c: &qs_curve) -> &[qs_singular_point] {
        unsafe { std::slice::from_raw_parts(c.singular, c.n_singular) }
    }

    /// Runs one pair through the C call and checks it against the engine:
    /// the class and counts of `qs_natural_classify_f64`, and every
    /// component's numbers enclosing the exact ones.
    fn check_pair(
        a: qs_natural_f64,
        b: qs_natural_f64,
        class: i32,
        counts: (u32, u32, u32),
    ) -> Owner {
        let (code, out, msg) = run(&a, &b, ptr::null());
        assert_eq!(code, 0, "{msg}");
        let owner = Owner(out);
        let r = owner.get();
        let mut plain = qs_natural_result::default();
        let c = unsafe { qs_natural_classify_f64(&a, &b, &mut plain, ptr::null_mut()) };
        assert_eq!(c, 0);
        assert_eq!(r.result, plain);
        assert_eq!(
            (
                r.result.cls,
                (r.result.conics, r.result.lines, r.result.points)
            ),
            (class, counts)
        );
        check_components(&owner, &a, &b);
        owner
    }

    fn tags(list: &[qs_component]) -> Vec<i32> {
        list.iter().map(|c| c.tag).collect()
    }

    #[test]
    fn conics_ellipses_and_circles() {
        // perpendicular unit cylinders: two ellipses in the planes x = ±y
        let o = check_pair(
            cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cyl([0.0; 3], [0.0, 1.0, 0.0], 1.0),
            QS_CLASS_CONICS,
            (2, 0, 0),
        );
        let l = o.list();
        assert_eq!(tags(l), [QS_COMPONENT_CONIC; 2]);
        for c in l {
            let k = unsafe { c.data.conic };
            assert_eq!((k.kind, k.is_vertex, k.is_double), (QS_CONIC_ELLIPSE, 0, 0));
            // semi-axes² 2 and 1, normals (1, ±1, 0) as primitive integers
            let s: Vec<f64> = k.semi_axes2.iter().map(|b| b.value).collect();
            assert_eq!(s, [2.0, 1.0]);
            assert_eq!((k.normal[0].value, k.normal[2].value), (1.0, 0.0));
            assert_eq!(k.normal[1].value.abs(), 1.0);
            assert!(absent(&k.focal2));
        }
        // a sphere inscribed in a cylinder: a double circle of radius² 2
        let o = check_pair(
            sphere([1.0, 2.0, 3.0], 2.0),
            cyl([0.0, 2.0, 3.0], [1.0, 0.0, 0.0], 2.0),
            QS_CLASS_CONICS,
            (1, 0, 0),
        );
        let l = o.list();
        let k = unsafe { l[0].data.conic };
        assert_eq!((k.kind, k.is_double), (QS_CONIC_CIRCLE, 1));
        let center: Vec<f64> = k.center.iter().map(|b| b.value).collect();
        assert_eq!(center, [1.0, 2.0, 3.0]);
        assert_eq!((k.semi_axes2[0].value, k.semi_axes2[0].bound), (2.0, 0.0));
        // two spheres through an irrational circle: 0.1 is taken exactly
        check_pair(
            sphere([0.0; 3], 2.0),
            sphere([0.5, 0.3, 0.0], 3.0),
            QS_CLASS_CONICS,
            (1, 0, 0),
        );
    }

    #[test]
    fn conic_and_line_a_parabola_and_a_double_line() {
        let o = check_pair(
            cone([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cone([2.0, 2.0, 0.0], [0.0, 1.0, 0.0], 1.0),
            QS_CLASS_CONIC_AND_LINE,
            (1, 1, 0),
        );
        let l = o.list();
        let conic = l.iter().find(|c| c.tag == QS_COMPONENT_CONIC).unwrap();
        let k = unsafe { conic.data.conic };
        assert_eq!((k.kind, k.is_vertex), (QS_CONIC_PARABOLA, 1));
        assert_eq!((k.n_semi_axes2, k.n_axis_dirs), (0, 1));
        assert!(k.semi_axes2.iter().all(absent) && k.axis_dirs[1].iter().all(absent));
        assert!(!absent(&k.focal2) && k.focal2.value > 0.0);
        let line = l.iter().find(|c| c.tag == QS_COMPONENT_LINE).unwrap();
        assert_eq!(unsafe { line.data.line }.is_double, 1);
    }

    #[test]
    fn lines_through_a_common_vertex() {
        let o = check_pair(
            cone([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cone([0.0; 3], [0.0, 1.0, 0.0], 3.0),
            QS_CLASS_LINES,
            (0, 4, 0),
        );
        let l = o.list();
        assert_eq!(tags(l), [QS_COMPONENT_LINE; 4]);
        // irrational directions: bounds of a few ulps, not 0
        assert!(l.iter().any(|c| {
            unsafe { c.data.line }
                .direction
                .iter()
                .any(|b| b.bound > 0.0)
        }));
        check_pair(
            cyl([0.0; 3], [0.0, 0.0, 1.0], 1.0),
            cyl([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0),
            QS_CLASS_LINES,
            (0, 2, 0),
        );
    }

    #[test]
    fn points_tangency_and_vertex() {
        let o = check_pair(
            cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cone([0.0, 0.0, 2.0], [0.0, 1.0, 0.0], 3.0),
            QS_CLASS_POINTS,
            (0, 0, 2),
        );
        let l = o.list();
        assert_eq!(tags(l), [QS_COMPONENT_POINT; 2]);
        assert!(
            l.iter()
                .all(|c| unsafe { c.data.point }.kind == QS_POINT_TANGENCY)
        );
        // a sphere through a cone's vertex, centred on its axis: a circle
        // and the vertex, exactly 0
        let o = check_pair(
            sphere([0.0, 0.0, 2.0], 4.0),
            cone([0.0; 3], [0.0, 0.0, 1.0], 1.0),
            QS_CLASS_CONICS,
            (1, 0, 1),
        );
        let l = o.list();
        let p = l.iter().find(|c| c.tag == QS_COMPONENT_POINT).unwrap();
        let p = unsafe { p.data.point };
        assert_eq!(p.kind, QS_POINT_VERTEX);
        assert!(p.point.iter().all(|b| (b.value, b.bound) == (0.0, 0.0)));
    }

    #[test]
    fn curves_with_singular_points_and_branches() {
        // the skeletal line inside the cone: two branches cross at the vertex (0, 1, 0)
        let o = check_pair(
            cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cone([0.0, 1.0, 0.0], [1.0, 1.0, 0.0], 3.0),
            QS_CLASS_CURVE,
            (0, 0, 0),
        );
        let l = o.list();
        let k = unsafe { l[0].data.curve };
        assert_eq!((k.degree, k.n_singular), (4, 1));
        let s = singular(&k)[0];
        assert_eq!(s.kind, QS_SINGULAR_CROSSING);
        let p: Vec<f64> = s.point.iter().map(|b| b.value).collect();
        assert_eq!(p, [0.0, 1.0, 0.0]);
        assert!(k.n_branches >= 1);
        // a cone vertex on the cylinder with the cone outside: an acnode,
        // counted as a point
        let o = check_pair(
            cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cone([0.0, 1.0, 0.0], [0.0, 1.0, 0.0], 1.0),
            QS_CLASS_CURVE,
            (0, 0, 1),
        );
        let l = o.list();
        let k = unsafe { l[0].data.curve };
        assert!(singular(&k).iter().any(|s| s.kind == QS_SINGULAR_ACNODE));
        // a common ruling: a line and a twisted cubic
        let o = check_pair(
            cyl([0.0; 3], [0.0, 0.0, 1.0], 1.0),
            cone([1.0, 0.0, 0.0], [1.0, 1.0, 1.0], 2.0),
            QS_CLASS_CURVE,
            (0, 1, 0),
        );
        let l = o.list();
        let curve = l.iter().find(|c| c.tag == QS_COMPONENT_CURVE).unwrap();
        let k = unsafe { curve.data.curve };
        // traced by the rulings: one unbounded branch
        assert_eq!((k.degree, k.n_branches), (3, 1));
        let b = unsafe { std::slice::from_raw_parts(k.branches, k.n_branches) };
        assert_eq!(b[0].bounded, 0);
    }

    #[test]
    fn empty_and_same_surface_have_no_components() {
        let o = check_pair(
            cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            cyl([0.0, 0.0, 3.0], [0.0, 1.0, 0.0], 1.0),
            QS_CLASS_EMPTY,
            (0, 0, 0),
        );
        let l = o.list();
        assert!(l.is_empty());
        let o = check_pair(
            cyl([0.0; 3], [1.0, 1.0, 0.0], 2.0),
            cyl([3.0, 3.0, 0.0], [-2.0, -2.0, 0.0], 2.0),
            QS_CLASS_SAME_SURFACE,
            (0, 0, 0),
        );
        let l = o.list();
        assert!(l.is_empty());
    }

    #[test]
    fn directions_beyond_the_range_of_doubles_are_scaled_by_a_power_of_two() {
        // parallel cylinders with an axis in random doubles: the engine's
        // line directions have 300-digit integers (beyond 1e308)
        let axis = [0.0, 0.1899470196761869, 0.8847639398954555];
        let o = check_pair(
            cyl([0.0; 3], axis, 0.45890223345139264),
            cyl([0.0, 0.49273575971289313, -0.8087490237081977], axis, 0.1),
            QS_CLASS_LINES,
            (0, 2, 0),
        );
        for c in o.list() {
            let d = unsafe { c.data.line }.direction;
            assert!(d.iter().all(|b| b.value.is_finite() && b.bound.is_finite()));
            // parallel to the axis: d × axis ≈ 0 relative to |d|
            let v: Vec<f64> = d.iter().map(|b| b.value).collect();
            let cross = v[1] * axis[2] - v[2] * axis[1];
            assert!(v[0] == 0.0 && cross.abs() <= 1e-12 * v[1].abs().max(v[2].abs()));
        }
        // doubles at the ends of the range: nothing infinite where a
        // scale-free number (direction, plane) is reported
        for (a, b) in [
            (
                cyl([0.0; 3], [0.0, 1e-300, 3e-300], 1.0),
                cyl([1.0, 0.0, 0.0], [0.0, 1e-300, 3e-300], 1.0),
            ),
            (
                cone([0.0; 3], [1e300, 0.0, 0.0], 1.0),
                cone([0.0; 3], [0.0, 5e-324, 0.0], 3.0),
            ),
            (sphere([0.0; 3], 1e-300), sphere([1e-151, 0.0, 0.0], 1e-300)),
        ] {
            let (code, out, msg) = run(&a, &b, ptr::null());
            assert_eq!(code, 0, "{msg}");
            let o = Owner(out);
            check_components(&o, &a, &b);
            assert!(!o.list().is_empty());
            for c in o.list() {
                let scale_free: Vec<qs_ball> = match c.tag {
                    QS_COMPONENT_LINE => unsafe { c.data.line }.direction.to_vec(),
                    QS_COMPONENT_CONIC => {
                        let k = unsafe { c.data.conic };
                        let dirs = k.axis_dirs[..k.n_axis_dirs as usize].concat();
                        [&k.normal[..], &[k.offset], &dirs].concat()
                    }
                    _ => vec![],
                };
                assert!(
                    scale_free.iter().all(|b| b.value.is_finite()),
                    "{scale_free:?}"
                );
            }
        }
    }

    #[test]
    fn fit_scale_keeps_ordinary_tuples_and_scales_huge_ones_exactly() {
        let r = |n: i64, shift: usize| {
            let q = Rational::from_integer(BigInt::from(n) << shift);
            Exact::rational(q)
        };
        let mut small = [r(3, 0), r(-5, 0), r(0, 0)];
        fit_scale(&mut small).unwrap();
        assert!(small[0].equals(&r(3, 0)) && small[1].equals(&r(-5, 0)));
        let mut huge = [r(3, 2000), r(-5, 2000), r(0, 0)];
        fit_scale(&mut huge).unwrap();
        let d: Vec<f64> = huge.iter().map(|x| x.to_f64_bounded().0).collect();
        assert!(d.iter().all(|x| x.is_finite()) && d[0] > 0.0 && d[1] < 0.0 && d[2] == 0.0);
        assert_eq!(d[0] / d[1], -0.6); // the same ratio: a power of two
        let tiny = Rational::new(BigInt::from(7), BigInt::from(1) << 3000);
        let mut t = [Exact::rational(tiny), r(0, 0), r(0, 0)];
        fit_scale(&mut t).unwrap();
        let v = t[0].to_f64_bounded().0;
        assert!(v > 0.5 && v < 16.0, "{v}");
    }

    #[test]
    fn bad_input_gives_code_2_and_null() {
        let ok = sphere([0.0; 3], 1.0);
        let (code, out, msg) = run(&sphere([f64::NAN, 0.0, 0.0], 1.0), &ok, ptr::null());
        assert_eq!((code, out), (QS_ERR_INPUT, ptr::null_mut()));
        assert!(msg.contains("a.point[0] is NaN"), "{msg}");
        let (code, out, msg) = run(&ok, &cone([0.0; 3], [0.0; 3], 1.0), ptr::null());
        assert_eq!((code, out), (QS_ERR_INPUT, ptr::null_mut()));
        assert!(msg.contains("in b"), "{msg}");
        let mut out = ptr::dangling_mut();
        let code = unsafe {
            qs_natural_components_f64(ptr::null(), &ok, ptr::null(), &mut out, ptr::null_mut())
        };
        assert_eq!((code, out), (QS_ERR_INPUT, ptr::null_mut()));
        let code = unsafe {
            qs_natural_components_f64(&ok, &ok, ptr::null(), ptr::null_mut(), ptr::null_mut())
        };
        assert_eq!(code, QS_ERR_INPUT);
        unsafe { qs_natural_components_free(ptr::null_mut()) };
    }

    #[test]
    fn an_exhausted_budget_gives_code_3_and_an_undecided_result() {
        let opts = crate::options::qs_options_new();
        unsafe { crate::options::qs_options_set_time_limit(opts, 0.0, ptr::null_mut()) };
        let (code, out, msg) = run(
            &sphere([0.0; 3], 1.0),
            &cyl([0.0; 3], [1.0, 0.0, 0.0], 1.0),
            opts,
        );
        assert_eq!(code, QS_ERR_BUDGET, "{msg}");
        let r = unsafe { &*out };
        assert_eq!(
            (r.result.cls, r.result.conics, r.count, r.components),
            (QS_CLASS_UNDECIDED, 0, 0, ptr::null())
        );
        unsafe {
            qs_natural_components_free(out);
            crate::options::qs_options_free(opts);
        }
    }

    /// A natural quadric of any kind: random doubles (general position),
    /// or numbers from a small grid (special positions: common vertices,
    /// tangencies, parallel or meeting axes).
    fn natural() -> impl Strategy<Value = qs_natural_f64> {
        let nonzero = |a: &[f64; 3]| a.iter().any(|x| x.abs() > 0.1);
        let random = (
            0..3i32,
            prop::array::uniform3(-2.0f64..2.0),
            prop::array::uniform3(-1.0f64..1.0).prop_filter("a non-zero axis", nonzero),
            0.1f64..3.0,
        );
        let half = |k: i32| f64::from(k) / 2.0;
        let grid = (
            0..3i32,
            prop::array::uniform3((-2i32..=2).prop_map(half)),
            prop::array::uniform3((-1i32..=1).prop_map(f64::from))
                .prop_filter("a non-zero axis", nonzero),
            prop::sample::select(vec![0.5, 1.0, 2.0, 3.0, 4.0]),
        );
        prop_oneof![random, grid].prop_map(|(kind, point, axis, param)| q(kind, point, axis, param))
    }

    /// The C answer for a pair against the engine: code 0 (or 3 when the
    /// budget ran out, then undecided and empty), the class and counts of
    /// `qs_natural_classify_f64`, every number enclosing the exact one.
    fn check_random(a: &qs_natural_f64, b: &qs_natural_f64) -> Result<(), TestCaseError> {
        let opts = crate::options::qs_options_new();
        unsafe { crate::options::qs_options_set_time_limit(opts, 20.0, ptr::null_mut()) };
        let (code, out, msg) = run(a, b, opts);
        unsafe { crate::options::qs_options_free(opts) };
        let o = Owner(out);
        if code == QS_ERR_BUDGET {
            let r = o.get();
            prop_assert_eq!((r.result.cls, r.count), (QS_CLASS_UNDECIDED, 0));
            return Ok(());
        }
        prop_assert_eq!(code, 0, "{}", msg);
        let mut plain = qs_natural_result::default();
        unsafe { qs_natural_classify_f64(a, b, &mut plain, ptr::null_mut()) };
        prop_assert_eq!(o.get().result, plain);
        check_components(&o, a, b);
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// Property: for a sphere and a cylinder or cone in general
        /// position (random doubles), every number of every component
        /// encloses the exact value, and the class is the one of
        /// `qs_natural_classify_f64`.
        #[test]
        fn random_pairs_are_enclosed(
            c in prop::array::uniform3(-3.0f64..3.0),
            r2 in 0.1f64..4.0,
            p in prop::array::uniform3(-2.0f64..2.0),
            axis in prop::array::uniform3(-1.0f64..1.0),
            param in 0.1f64..3.0,
            is_cone in any::<bool>(),
        ) {
            prop_assume!(axis.iter().any(|x| x.abs() > 0.1));
            let a = sphere(c, r2);
            let b = if is_cone { cone(p, axis, param) } else { cyl(p, axis, param) };
            check_random(&a, &b)?;
        }

        /// Property: the same for any two natural quadrics, in general or
        /// special position (grid numbers, and `b` sharing `a`'s point or
        /// axis: lines, points, double conics, singular curves).
        #[test]
        fn random_natural_pairs_are_enclosed(
            a in natural(),
            b in natural(),
            same_point in any::<bool>(),
            same_axis in any::<bool>(),
        ) {
            let mut b = b;
            if same_point {
                b.point = a.point;
            }
            if same_axis && a.kind != QS_SPHERE {
                b.axis = a.axis;
            }
            check_random(&a, &b)?;
        }
    }
}
