//! The answer of the natural-quadric classification: class, counts and
//! exact components (SPEC §4 output).

use super::deciders::AxesRelation;
use super::exact::{EPoint, Exact};
use super::types::Natural;
use crate::number::Q;

/// The type of a conic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    /// SPEC spelling.
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
pub struct Plane {
    /// Normal vector.
    pub normal: EPoint,
    /// Right-hand side.
    pub offset: Exact,
}

/// Kind of an isolated point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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

/// A real component of the intersection.
#[derive(Clone, Debug)]
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

/// The class of the intersection (SPEC §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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

impl Class {
    /// SPEC spelling.
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

/// The full answer of `quadsect natural`.
#[derive(Clone, Debug)]
pub struct NaturalReport {
    /// First quadric.
    pub a: Natural,
    /// Second quadric.
    pub b: Natural,
    /// The class.
    pub class: Class,
    /// Relation of the axes (`None` when a sphere is involved).
    pub axes: Option<AxesRelation>,
    /// Theorem 8.1/8.2 value where it applies.
    pub thm8: Option<bool>,
    /// Real components.
    pub components: Vec<Component>,
    /// Part-1 deciders (coplanar distinct axes).
    pub deciders: Option<PlanarDeciders>,
    /// The paper's §7 decider (skew axes).
    pub section7: Option<super::tangency::Section7>,
    /// How the class was decided.
    pub method: &'static str,
    /// Remarks.
    pub notes: Vec<String>,
    /// The compute budget that ran out (class `Undecided`).
    pub exhausted: Option<crate::budget::Exhausted>,
}

impl NaturalReport {
    /// The answer when the compute budget ran out: class `Undecided`, no
    /// components, and the limit that was hit.
    pub fn budget_exhausted(
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
            exhausted: Some(e),
        }
    }

    /// Number of real affine conics.
    pub fn conics(&self) -> usize {
        self.components
            .iter()
            .filter(|c| matches!(c, Component::Conic { .. }))
            .count()
    }

    /// Number of real affine lines (a double line counts once).
    pub fn lines(&self) -> usize {
        self.components
            .iter()
            .filter(|c| matches!(c, Component::Line { .. }))
            .count()
    }

    /// Number of isolated real points (acnodes of a curve included).
    pub fn points(&self) -> usize {
        let own = self
            .components
            .iter()
            .filter(|c| matches!(c, Component::Point { .. }))
            .count();
        let acn: usize = self
            .components
            .iter()
            .map(|c| match c {
                Component::Curve { singular, .. } => {
                    singular.iter().filter(|(_, iso)| *iso).count()
                }
                _ => 0,
            })
            .sum();
        own + acn
    }
}

/// The class implied by a list of components (SPEC §4 order).
pub fn class_of(components: &[Component]) -> Class {
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
