//! The answer of the natural-quadric classification: class, counts and
//! exact components (contract §4 output).

use super::deciders::AxesRelation;
use super::exact::{EPoint, Exact};
use super::types::Natural;
use crate::number::Q;

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
        /// Its real singular points, with `true` for an isolated one (acnode).
        singular: Vec<(EPoint, bool)>,
    },
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
                    singular.iter().filter(|(_, iso)| *iso).count()
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
