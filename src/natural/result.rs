//! The answer of the natural-quadric classification: class, counts and
//! exact components (contract §4 output).

use super::deciders::AxesRelation;
use super::numbers::{EPoint, Exact};
use super::types::Natural;
use crate::number::Q;
use num_traits::One;

/// The type of a conic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ConicKind {
    /// A circle.
    Circle,
    /// A non-circular ellipse.
    Ellipse,
    /// A hyperbola.
    Hyperbola,
    /// A parabola.
    Parabola,
}

impl ConicKind {
    /// The output spelling.
    pub fn as_str(&self) -> &'static str {
        match self {
            ConicKind::Circle => "circle",
            ConicKind::Ellipse => "ellipse",
            ConicKind::Hyperbola => "hyperbola",
            ConicKind::Parabola => "parabola",
        }
    }
}

/// A plane `normal · P = offset`.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Plane {
    /// Normal vector.
    pub normal: EPoint,
    /// Right-hand side.
    pub offset: Exact,
}

/// Kind of an isolated point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum PointKind {
    /// The surfaces touch there (an isolated tangency point).
    Tangency,
    /// A cone vertex that is an isolated point of the intersection.
    Vertex,
    /// An isolated singular point (acnode) of an intersection curve.
    Acnode,
}

impl PointKind {
    /// Output spelling.
    pub fn as_str(&self) -> &'static str {
        match self {
            PointKind::Tangency => "tangency",
            PointKind::Vertex => "vertex",
            PointKind::Acnode => "acnode",
        }
    }
}

/// A real component of the intersection, with exact data (coordinates in
/// Q(√d) or real algebraic numbers, see [`Exact`]).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Component {
    /// A conic.
    Conic {
        /// Its plane.
        plane: Plane,
        /// Its type.
        kind: ConicKind,
        /// Centre (circle, ellipse, hyperbola).
        center: Option<EPoint>,
        /// Vertex (parabola).
        vertex: Option<EPoint>,
        /// Squared semi-axes (transverse first for a hyperbola).
        axes2: Vec<Exact>,
        /// Directions of the semi-axes (same order), or the parabola's axis.
        axis_dirs: Vec<EPoint>,
        /// Squared focal length (parabola).
        focal2: Option<Exact>,
        /// The surfaces are tangent along it.
        double: bool,
    },
    /// A line.
    Line {
        /// A point of it.
        point: EPoint,
        /// Its direction.
        direction: EPoint,
        /// A double line (the surfaces are tangent along it).
        double: bool,
    },
    /// An isolated point.
    Point {
        /// Coordinates.
        point: EPoint,
        /// Why it is isolated.
        kind: PointKind,
    },
    /// A genuine space curve (quartic, or twisted cubic beside a common line).
    Curve {
        /// Its degree.
        degree: u32,
        /// Its real affine singular points with their type.
        singular: Vec<SingularPoint>,
        /// Its real affine connected components (branches), each with
        /// whether it is bounded and a point on it (where a marcher
        /// starts).  Empty only in the reference route's answers
        /// ([`super::ClassifyOptions::deciders`]), which do not trace
        /// branches, and for a cubic beside a common ruling met to second
        /// order by a cone on both sides (a note says so).
        branches: Vec<CurveBranch>,
    },
}

/// The type of a real singular point of an intersection curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum SingularKind {
    /// An isolated real point (the tangent cone is imaginary).
    Acnode,
    /// Two real branches cross (a node with real tangents).
    Crossing,
    /// A cusp (the tangent cone is a double line).
    Cusp,
    /// Two real branches touch (a common line meeting the rest of the
    /// curve tangentially).
    Tacnode,
}

impl SingularKind {
    /// Output spelling.
    pub fn as_str(&self) -> &'static str {
        match self {
            SingularKind::Acnode => "acnode",
            SingularKind::Crossing => "crossing",
            SingularKind::Cusp => "cusp",
            SingularKind::Tacnode => "tacnode",
        }
    }
}

/// A real singular point of an intersection curve.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SingularPoint {
    /// Its exact coordinates.
    pub point: EPoint,
    /// Its type.
    pub kind: SingularKind,
}

impl SingularPoint {
    /// True for an isolated point (an acnode).
    pub fn is_isolated(&self) -> bool {
        self.kind == SingularKind::Acnode
    }
}

/// One real affine connected component of an intersection curve.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct CurveBranch {
    /// The component is bounded (a closed loop); otherwise both its ends go
    /// to infinity.
    pub bounded: bool,
    /// A point on it.
    pub start: super::curve::CurvePoint,
}

/// The class of the intersection, decided in this order: `same-surface`
/// (proportional equations); `curve` (a one-dimensional real part not made
/// of lines and conics); `conics`; `conic-and-line`; `lines`; `points`
/// (isolated real points only); `empty`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Class {
    /// Proportional equations.
    SameSurface,
    /// Real conics, no line.
    Conics,
    /// Conic(s) and line(s).
    ConicAndLine,
    /// Lines only.
    Lines,
    /// Isolated points only.
    Points,
    /// Nothing real.
    Empty,
    /// A space curve that is not made of lines and conics.
    Curve,
    /// Not decided: the compute budget ran out (see
    /// [`NaturalReport::exhausted`]).
    Undecided,
}

impl std::fmt::Display for Class {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl Class {
    /// `same-surface`, `conics`, `conic-and-line`, `lines`, `points`,
    /// `empty` or `curve`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Class::SameSurface => "same-surface",
            Class::Conics => "conics",
            Class::ConicAndLine => "conic-and-line",
            Class::Lines => "lines",
            Class::Points => "points",
            Class::Empty => "empty",
            Class::Curve => "curve",
            Class::Undecided => "undecided",
        }
    }
}

/// The decider values of part 1 (when the axes are coplanar and distinct).
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct PlanarDeciders {
    /// Theorem 8.1 / 8.2.
    pub thm8: Option<bool>,
    /// Lemma 8.1: discriminant of the projection conic is zero.
    pub lemma81: bool,
    /// The discriminant itself.
    pub discriminant: Q,
    /// The pencil has a member of rank ≤ 2.
    pub pencil: bool,
    /// X (where ∇F = 0), as a 3D point.
    pub x_point: Option<[Q; 3]>,
    /// Squared heights at X.
    pub heights_at_x: Option<(Q, Q)>,
    /// The projection conic F as a polynomial in the frame coordinates.
    pub projection: String,
    /// The frame: origin, e1, e2.
    pub frame: [[Q; 3]; 3],
    /// Skeletal lines of each surface (point, direction).
    pub skeletal: Vec<Vec<(EPoint, EPoint)>>,
    /// Common vertex (§6): the squared heights at the parallelogram vertices
    /// A (on L1) and D (on L2); positive: two real lines through V, zero: a
    /// double line, negative: imaginary lines.
    pub parallelogram: Option<Vec<Exact>>,
}

/// The answer of the classification of two natural quadrics: the class,
/// the counts of real affine conics, lines and points, the components with
/// exact data, the relation of the axes, Theorem 8.1/8.2's value and the
/// part-1 deciders.  `Display` prints the human summary; with the feature
/// `serde` it serializes to the JSON of `quadsect natural --json`.
#[derive(Clone, Debug)]
pub struct NaturalReport {
    pub(crate) a: Natural,
    pub(crate) b: Natural,
    pub(crate) class: Class,
    pub(crate) axes: Option<AxesRelation>,
    pub(crate) thm8: Option<bool>,
    pub(crate) components: Vec<Component>,
    pub(crate) deciders: Option<PlanarDeciders>,
    pub(crate) section7: Option<super::tangency::Section7>,
    pub(crate) method: &'static str,
    pub(crate) notes: Vec<String>,
    /// Class and counts (the same whichever route answered).
    pub(crate) counts: Counts,
    /// False when only the class and counts were asked for (fast route).
    pub(crate) components_computed: bool,
    /// For a request without components: which route answered.
    pub(crate) route: Option<Route>,
    /// The compute budget that ran out (class `Undecided`).
    pub(crate) exhausted: Option<crate::budget::Exhausted>,
    /// Real planes P₁, P₂ with a pencil member λA + μB = κ·P₁·P₂ (the
    /// planar construction's planes, those without a component included):
    /// the intersection is the union of the plane sections, which a checker
    /// re-derives (contract §7).  Empty when the route has none.
    pub(crate) member_planes: Vec<Plane>,
    /// The referee, when asked for ([`super::ClassifyOptions::referee`]).
    pub(crate) referee: Option<super::referee::Referee>,
}

/// Which route answered a request for the class and counts only.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Route {
    /// The fast exact route (no components computed).
    Fast,
    /// The complete route, because the fast one could not decide (the
    /// reason).
    Complete(&'static str),
}

/// Class and counts of an intersection (contract §4 conventions: real
/// affine components, a double line once, acnodes of a curve in `points`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Counts {
    /// The class.
    pub class: Class,
    /// Real affine conics.
    pub conics: usize,
    /// Real affine lines.
    pub lines: usize,
    /// Isolated real points (acnodes of a curve included).
    pub points: usize,
}

impl Counts {
    pub(crate) fn new(class: Class, conics: usize, lines: usize, points: usize) -> Counts {
        Counts {
            class,
            conics,
            lines,
            points,
        }
    }

    pub(crate) fn same_surface() -> Counts {
        Counts::new(Class::SameSurface, 0, 0, 0)
    }

    /// The counts of a list of components.
    pub(crate) fn of_components(components: &[Component]) -> Counts {
        let count = |f: fn(&Component) -> bool| components.iter().filter(|c| f(c)).count();
        let acnodes: usize = components
            .iter()
            .map(|c| match c {
                Component::Curve { singular, .. } => {
                    singular.iter().filter(|p| p.is_isolated()).count()
                }
                _ => 0,
            })
            .sum();
        Counts::new(
            class_of(components),
            count(|c| matches!(c, Component::Conic { .. })),
            count(|c| matches!(c, Component::Line { .. })),
            count(|c| matches!(c, Component::Point { .. })) + acnodes,
        )
    }
}

impl NaturalReport {
    /// The first quadric.
    pub fn a(&self) -> &Natural {
        &self.a
    }

    /// The second quadric.
    pub fn b(&self) -> &Natural {
        &self.b
    }

    /// How far the input is from a different answer: asked for with
    /// [`super::ClassifyOptions::with_referee`] (`None` otherwise, and for
    /// an undecided answer).
    pub fn referee(&self) -> Option<&super::referee::Referee> {
        self.referee.as_ref()
    }

    /// The class.
    pub fn class(&self) -> Class {
        self.class
    }

    /// How the axes lie (`None` when a sphere is involved).
    pub fn axes(&self) -> Option<&AxesRelation> {
        self.axes.as_ref()
    }

    /// Theorem 8.1/8.2's closed-form value where it applies (coplanar or
    /// parallel distinct axes), else `None`.  Not the class: see the crate
    /// docs.
    pub fn thm8(&self) -> Option<bool> {
        self.thm8
    }

    /// The real affine components.
    pub fn components(&self) -> &[Component] {
        &self.components
    }

    /// The part-1 deciders (coplanar distinct axes).
    pub fn deciders(&self) -> Option<&PlanarDeciders> {
        self.deciders.as_ref()
    }

    /// The paper's §7 tangency decider (skew axes).
    pub fn section7(&self) -> Option<&super::tangency::Section7> {
        self.section7.as_ref()
    }

    /// How the class was decided, in words.
    pub fn method_description(&self) -> &str {
        self.method
    }

    /// Remarks.
    pub fn notes(&self) -> &[String] {
        &self.notes
    }

    /// Number of real affine conics (0 when the class is `Undecided`).
    pub fn conics(&self) -> usize {
        self.counts.conics
    }

    /// Number of real affine lines (a double line counts once).
    pub fn lines(&self) -> usize {
        self.counts.lines
    }

    /// Number of isolated real points (acnodes of a curve included).
    pub fn points(&self) -> usize {
        self.counts.points
    }

    /// True when the fast route answered (no components computed).
    pub(crate) fn answered_fast(&self) -> bool {
        self.route == Some(Route::Fast)
    }

    /// The compute budget that ran out (then the class is
    /// [`Class::Undecided`] and nothing else is known).
    pub fn exhausted(&self) -> Option<&crate::budget::Exhausted> {
        self.exhausted.as_ref()
    }

    /// The answer when the compute budget ran out: class `Undecided`, no
    /// components, and the limit that was hit.
    pub(crate) fn budget_exhausted(
        a: &Natural,
        b: &Natural,
        e: crate::budget::Exhausted,
    ) -> NaturalReport {
        NaturalReport {
            a: a.clone(),
            b: b.clone(),
            class: Class::Undecided,
            axes: None,
            thm8: None,
            components: vec![],
            deciders: None,
            section7: None,
            method: "none (the compute budget ran out)",
            notes: vec![],
            counts: Counts::new(Class::Undecided, 0, 0, 0),
            components_computed: false,
            route: None,
            exhausted: Some(e),
            member_planes: Vec::new(),
            referee: None,
        }
    }

    /// False when only the class and counts were asked for
    /// ([`super::ClassifyOptions::without_components`]): then
    /// [`NaturalReport::components`] and the deciders are empty.
    pub fn has_components(&self) -> bool {
        self.components_computed
    }
}

/// The class implied by a list of components (contract §4 order).
pub(crate) fn class_of(components: &[Component]) -> Class {
    let has = |f: fn(&Component) -> bool| components.iter().any(f);
    if has(|c| matches!(c, Component::Curve { .. })) {
        Class::Curve
    } else if has(|c| matches!(c, Component::Conic { .. })) {
        if has(|c| matches!(c, Component::Line { .. })) {
            Class::ConicAndLine
        } else {
            Class::Conics
        }
    } else if has(|c| matches!(c, Component::Line { .. })) {
        Class::Lines
    } else if has(|c| matches!(c, Component::Point { .. })) {
        Class::Points
    } else {
        Class::Empty
    }
}

/// Two exact numbers equal: exactly when both lie in one quadratic field
/// (or one is rational), else through their real algebraic forms.
fn same_number(a: &Exact, b: &Exact) -> bool {
    a.equals(b)
}

/// The exact values of a vector when all lie in one field Q(√d).
fn one_field(v: &[&Exact]) -> Option<Vec<crate::number::QSqrt>> {
    let mut d: Option<Q> = None;
    let mut out = Vec::new();
    for x in v {
        match x {
            Exact::Quad(q) => {
                let q = q.normalized();
                if !q.is_rational() {
                    match &d {
                        Some(e) if *e != q.d => return None,
                        _ => d = Some(q.d.clone()),
                    }
                }
                out.push(q);
            }
            Exact::Alg(_) => return None,
        }
    }
    Some(out)
}

/// Are two vectors (of any length) parallel?  Exact in one field;
/// otherwise the 2×2 minors are compared at 2^-200 of the product of the
/// largest entries (a test-and-report helper, never a decision of the
/// engine's answers).
fn parallel(u: &[Exact], v: &[Exact]) -> bool {
    let all: Vec<&Exact> = u.iter().chain(v.iter()).collect();
    let n = u.len();
    if let Some(q) = one_field(&all) {
        for i in 0..n {
            for j in i + 1..n {
                if !q[i].mul(&q[n + j]).sub(&q[j].mul(&q[n + i])).is_zero() {
                    return false;
                }
            }
        }
        return true;
    }
    let ap: Vec<Q> = all.iter().map(|x| x.to_rational_approx(256)).collect();
    let big = ap
        .iter()
        .map(num_traits::Signed::abs)
        .max()
        .unwrap_or_else(Q::one);
    let tol = &big * &big / Q::from_integer(num_bigint::BigInt::from(1) << 200usize);
    for i in 0..n {
        for j in i + 1..n {
            let m = &ap[i] * &ap[n + j] - &ap[j] * &ap[n + i];
            if num_traits::Signed::abs(&m) > tol {
                return false;
            }
        }
    }
    true
}

fn same_point(p: &EPoint, q: &EPoint) -> bool {
    (0..3).all(|i| same_number(&p[i], &q[i]))
}

fn diff(p: &EPoint, q: &EPoint) -> Option<EPoint> {
    let v = one_field(&[&p[0], &p[1], &p[2], &q[0], &q[1], &q[2]])?;
    Some(std::array::from_fn(|i| Exact::Quad(v[i].sub(&v[i + 3]))))
}

fn same_line(p: &EPoint, d: &EPoint, q: &EPoint, e: &EPoint) -> bool {
    if !parallel(d, e) {
        return false;
    }
    if same_point(p, q) {
        return true;
    }
    match diff(q, p) {
        Some(r) => parallel(&r, d),
        None => {
            // approximately: (q − p) × d small
            let r: Vec<Exact> = (0..3)
                .map(|i| {
                    Exact::rational(q[i].to_rational_approx(256) - p[i].to_rational_approx(256))
                })
                .collect();
            parallel(&r, d)
        }
    }
}

fn same_plane(a: &Plane, b: &Plane) -> bool {
    let u = [
        a.normal[0].clone(),
        a.normal[1].clone(),
        a.normal[2].clone(),
        a.offset.clone(),
    ];
    let v = [
        b.normal[0].clone(),
        b.normal[1].clone(),
        b.normal[2].clone(),
        b.offset.clone(),
    ];
    parallel(&u, &v)
}

/// Two components describe the same geometric object (planes, directions
/// and lines compared up to scale and choice of point).
pub(crate) fn same_component(a: &Component, b: &Component) -> bool {
    let opt_point = |p: &Option<EPoint>, q: &Option<EPoint>| match (p, q) {
        (None, None) => true,
        (Some(p), Some(q)) => same_point(p, q),
        _ => false,
    };
    match (a, b) {
        (
            Component::Conic {
                plane: p1,
                kind: k1,
                center: c1,
                vertex: v1,
                axes2: x1,
                axis_dirs: d1,
                focal2: f1,
                double: o1,
            },
            Component::Conic {
                plane: p2,
                kind: k2,
                center: c2,
                vertex: v2,
                axes2: x2,
                axis_dirs: d2,
                focal2: f2,
                double: o2,
            },
        ) => {
            k1 == k2
                && o1 == o2
                && same_plane(p1, p2)
                && opt_point(c1, c2)
                && opt_point(v1, v2)
                && x1.len() == x2.len()
                && x1.iter().zip(x2).all(|(x, y)| same_number(x, y))
                && d1.len() == d2.len()
                && (*k1 == ConicKind::Circle || d1.iter().zip(d2).all(|(x, y)| parallel(x, y)))
                && match (f1, f2) {
                    (None, None) => true,
                    (Some(x), Some(y)) => same_number(x, y),
                    _ => false,
                }
        }
        (
            Component::Line {
                point: p1,
                direction: d1,
                double: o1,
            },
            Component::Line {
                point: p2,
                direction: d2,
                double: o2,
            },
        ) => o1 == o2 && same_line(p1, d1, p2, d2),
        (
            Component::Point {
                point: p1,
                kind: k1,
            },
            Component::Point {
                point: p2,
                kind: k2,
            },
        ) => k1 == k2 && same_point(p1, p2),
        (
            Component::Curve {
                degree: g1,
                singular: s1,
                branches: b1,
            },
            Component::Curve {
                degree: g2,
                singular: s2,
                branches: b2,
            },
        ) => {
            // the reference route does not trace branches nor tell cusps
            // from crossings: compare what both computed
            let kinds_agree = |a: &SingularPoint, b: &SingularPoint| {
                if b1.is_empty() || b2.is_empty() {
                    a.is_isolated() == b.is_isolated()
                } else {
                    a.kind == b.kind
                }
            };
            g1 == g2
                && s1.len() == s2.len()
                && s1.iter().all(|p| {
                    s2.iter()
                        .any(|q| kinds_agree(p, q) && same_point(&p.point, &q.point))
                })
                && (b1.is_empty()
                    || b2.is_empty()
                    || (b1.len() == b2.len()
                        && b1.iter().filter(|b| b.bounded).count()
                            == b2.iter().filter(|b| b.bounded).count()))
        }
        _ => false,
    }
}

/// Two lists of components hold the same objects (in any order).
pub(crate) fn same_components(a: &[Component], b: &[Component]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    let mut used = vec![false; b.len()];
    for x in a {
        match (0..b.len()).find(|&j| !used[j] && same_component(x, &b[j])) {
            Some(j) => used[j] = true,
            None => return false,
        }
    }
    true
}
