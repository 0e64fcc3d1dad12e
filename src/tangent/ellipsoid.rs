//! The validation of the ellipsoid E (contract §2): degree 2, definite
//! quadratic part, non-empty and not a single point.

use crate::error::{Error, ErrorKind};
use crate::geom::{Mat4, QuadricForm, adj3_int, common_denominator};
use crate::number::Q;
use crate::poly::mpoly::MPoly;
use crate::poly::{Polynomial, QMPoly};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// A validated ellipsoid `E(p) = pᵀ A p + 2 bᵀ p + c` with `A` positive
/// definite and `E(centre) < 0` (the input is negated when its quadratic
/// part is negative definite; the zero set is the same).  It cannot hold a
/// hyperboloid, an empty "imaginary ellipsoid" or a single point: every
/// constructor checks.
///
/// ```
/// use quadsect::{Ellipsoid, Polynomial, ErrorKind};
/// let e: Ellipsoid = "x^2 + y^2 + z^2 - 25".parse().unwrap();
/// assert!(e.center().iter().all(|c| *c == quadsect::Rational::from_integer(0.into())));
/// let bad = "x^2 + y^2 - z^2 - 1".parse::<Ellipsoid>().unwrap_err();
/// assert_eq!(bad.kind(), ErrorKind::NotAnEllipsoid);
/// assert!(bad.to_string().contains("not definite"));
/// assert!("x^2 + y^2 + z^2 + 1".parse::<Ellipsoid>().is_err()); // empty
/// ```
#[derive(Clone, Debug)]
pub struct Ellipsoid {
    /// The equation, oriented so that E < 0 inside.
    pub(crate) poly: QMPoly,
    /// Its matrices.
    pub(crate) form: QuadricForm,
    /// Centre `-A⁻¹ b`.
    pub(crate) center: [Q; 3],
    /// `E(centre) < 0`.
    pub(crate) center_value: Q,
    /// True when the input was negated.
    pub(crate) negated: bool,
}

impl Ellipsoid {
    /// Validates a polynomial as an ellipsoid (degree 2 in x, y, z, definite
    /// quadratic part, a real ellipsoid: not empty, not a point), with a
    /// clear error otherwise.
    pub fn new(p: &Polynomial) -> Result<Ellipsoid, Error> {
        Ellipsoid::from_poly(p.inner())
    }

    /// The ellipsoid with centre `center`, semi-axes `semi_axes` (> 0) along
    /// the columns of the rotation `rotation` (an exact rational rotation,
    /// e.g. a Cayley rotation; checked: `R Rᵀ = I`, `det R = 1`):
    /// `Σᵢ ((Rᵀ (p − center))ᵢ / aᵢ)² − 1`.
    ///
    /// ```
    /// use quadsect::{Ellipsoid, Rational};
    /// let r = |n: i64| Rational::from_integer(n.into());
    /// let id = [[r(1), r(0), r(0)], [r(0), r(1), r(0)], [r(0), r(0), r(1)]];
    /// let e = Ellipsoid::from_axes([r(1), r(0), r(0)], [r(2), r(3), r(4)], id).unwrap();
    /// assert_eq!(e.polynomial().to_string(), "1/4*x^2 + 1/9*y^2 + 1/16*z^2 - 1/2*x - 3/4");
    /// ```
    pub fn from_axes(
        center: [Q; 3],
        semi_axes: [Q; 3],
        rotation: [[Q; 3]; 3],
    ) -> Result<Ellipsoid, Error> {
        if !crate::geom::is_rotation(&rotation) {
            return Err(Error::new(
                ErrorKind::NotAnEllipsoid,
                "the rotation must be an exact rotation matrix (R Rᵀ = I, det R = 1); use Ellipsoid::from_frame for any invertible matrix",
            ));
        }
        Ellipsoid::from_frame(center, semi_axes, rotation)
    }

    /// The ellipsoid `Σᵢ ((Mᵀ (p − center))ᵢ / aᵢ)² − 1` for any invertible
    /// matrix `M` taken exactly as given (e.g. a rotation stored in doubles,
    /// which is orthogonal only up to rounding: the ellipsoid is then the
    /// one those exact numbers define).  Checked: `aᵢ > 0` and `M`
    /// invertible.
    pub fn from_frame(
        center: [Q; 3],
        semi_axes: [Q; 3],
        m: [[Q; 3]; 3],
    ) -> Result<Ellipsoid, Error> {
        if let Some(a) = semi_axes.iter().find(|a| !a.is_positive()) {
            return Err(Error::new(
                ErrorKind::NotAnEllipsoid,
                format!("semi-axes must be > 0, got {}", crate::number::fmt_q(a)),
            ));
        }
        if crate::geom::det3(&m).is_zero() {
            return Err(Error::new(
                ErrorKind::NotAnEllipsoid,
                "the axis matrix is singular (its columns must be independent)",
            ));
        }
        // local coordinate i: (column i of M) · (p − center)
        let mut e = QMPoly::constant(-Q::one());
        for i in 0..3 {
            let mut w = QMPoly::zero();
            for (j, c) in center.iter().enumerate() {
                let xj = &MPoly::var(j) - &MPoly::constant(c.clone());
                w = &w + &xj.scale(&m[j][i]);
            }
            let a2 = &semi_axes[i] * &semi_axes[i];
            e = &e + &(&w * &w).scale(&(Q::one() / a2));
        }
        Ellipsoid::from_poly(&e)
    }

    /// The equation, oriented so that E < 0 inside.
    pub fn polynomial(&self) -> Polynomial {
        Polynomial::from_inner(self.poly.clone())
    }

    /// The centre.
    pub fn center(&self) -> &[Q; 3] {
        &self.center
    }

    /// True when the given polynomial was negated to orient E < 0 inside
    /// (its quadratic part was negative definite).
    pub fn is_negated(&self) -> bool {
        self.negated
    }

    /// Validates an internal polynomial (see [`Ellipsoid::new`]).
    pub(crate) fn from_poly(p: &QMPoly) -> Result<Ellipsoid, Error> {
        if p.vars().iter().any(|&v| v > 2) {
            return Err(Error::new(
                ErrorKind::NotAnEllipsoid,
                "the ellipsoid must be a polynomial in x, y, z only",
            ));
        }
        let deg = p.total_degree().unwrap_or(0);
        if deg != 2 {
            return Err(Error::new(
                ErrorKind::NotAnEllipsoid,
                format!("an ellipsoid has total degree 2, this polynomial has degree {deg}"),
            ));
        }
        let mut form = QuadricForm::from_poly(p)
            .ok_or_else(|| Error::internal("degree-2 polynomial without a quadric form"))?;
        // integer arithmetic on L·E (L > 0 clears the denominators)
        let l = common_denominator(&[&form]);
        let shape = IntEllipsoid::of(&form.int_matrix(&l));
        let c = match shape {
            Ok(c) => c,
            Err(Shape::Singular) => {
                return Err(Error::new(
                    ErrorKind::NotAnEllipsoid,
                    "the quadratic part is singular (det = 0): a paraboloid, cylinder or plane pair, not an ellipsoid",
                ));
            }
            Err(Shape::Indefinite) => {
                return Err(Error::new(
                    ErrorKind::NotAnEllipsoid,
                    "the quadratic part is not definite: a hyperboloid or cone, not an ellipsoid",
                ));
            }
            Err(Shape::Point(c)) => {
                let center = c.center();
                return Err(Error::new(
                    ErrorKind::NotAnEllipsoid,
                    format!(
                        "the zero set is a single point ({}, {}, {}), not an ellipsoid",
                        crate::number::fmt_q(&center[0]),
                        crate::number::fmt_q(&center[1]),
                        crate::number::fmt_q(&center[2])
                    ),
                ));
            }
            Err(Shape::Empty) => {
                return Err(Error::new(
                    ErrorKind::NotAnEllipsoid,
                    "the zero set is empty (an imaginary ellipsoid: the polynomial never vanishes on real points)",
                ));
            }
        };
        let negated = c.negated;
        if negated {
            form = form.neg();
        }
        let center = c.center();
        // E(centre) = value / (L·det), oriented
        let center_value = Q::new(c.value, &l * &c.det);
        let poly = if negated { -p } else { p.clone() };
        Ok(Ellipsoid {
            poly,
            form,
            center,
            center_value,
            negated,
        })
    }
}

/// Why an integer quadric matrix is not an ellipsoid.
pub(crate) enum Shape {
    /// `det A = 0`.
    Singular,
    /// `A` is not definite.
    Indefinite,
    /// The zero set is the centre alone.
    Point(Box<IntEllipsoid>),
    /// The zero set is empty.
    Empty,
}

/// The centre of a quadric with a definite quadratic part, from its
/// integer matrix `M` (of `L·q`, `L > 0`), oriented so that `A` is
/// positive definite: centre `= −adj(A)·b / det A` with `det A > 0`.
pub(crate) struct IntEllipsoid {
    /// True when `q` was negated to make `A` positive definite.
    pub negated: bool,
    /// `−adj(A)·b` (oriented).
    pub numer: [BigInt; 3],
    /// `det A > 0` (oriented).
    pub det: BigInt,
    /// `det A · (L·q)(centre)` (oriented): negative for an ellipsoid.
    pub value: BigInt,
}

impl IntEllipsoid {
    /// Classifies the quadric of the integer matrix `m` (no rational
    /// arithmetic: leading principal minors, adjugate, one value).
    pub(crate) fn of(m: &Mat4) -> Result<IntEllipsoid, Shape> {
        let m1 = &m[0][0];
        let m2 = &m[0][0] * &m[1][1] - &m[0][1] * &m[1][0];
        let (adj, m3) = adj3_int(m);
        let negated = if m1.is_positive() && m2.is_positive() && m3.is_positive() {
            false
        } else if m1.is_negative() && m2.is_positive() && m3.is_negative() {
            true
        } else if m3.is_zero() {
            return Err(Shape::Singular);
        } else {
            return Err(Shape::Indefinite);
        };
        // adj(−A) = adj(A) (3×3), det(−A) = −det A; b and c change sign
        let sg = if negated { -1 } else { 1 };
        let ab: [BigInt; 3] =
            std::array::from_fn(|i| (0..3).map(|j| &adj[i][j] * &m[j][3]).sum::<BigInt>());
        let bab: BigInt = (0..3).map(|i| &m[i][3] * &ab[i]).sum();
        // det·q(centre) = c·det − bᵀ adj b, the same for −q:
        // (−c)(−det) − (−b)ᵀ adj (−b)
        let value = &m[3][3] * &m3 - bab;
        let c = IntEllipsoid {
            negated,
            numer: std::array::from_fn(|i| -&ab[i] * sg),
            det: m3 * sg,
            value,
        };
        if c.value.is_zero() {
            Err(Shape::Point(Box::new(c)))
        } else if c.value.is_positive() {
            Err(Shape::Empty)
        } else {
            Ok(c)
        }
    }

    /// The centre as rationals.
    pub(crate) fn center(&self) -> [Q; 3] {
        std::array::from_fn(|i| Q::new(self.numer[i].clone(), self.det.clone()))
    }
}

/// The sign of the quadric of the integer matrix `m` at the rational point
/// `n/d` (`d > 0`): the sign of `nᵀAn + 2d·bᵀn + c·d²`.
pub(crate) fn sign_at_int(m: &Mat4, n: &[BigInt; 3], d: &BigInt) -> i32 {
    let mut acc = &m[3][3] * d * d;
    for i in 0..3 {
        let mut row = (&m[i][3] * d) << 1usize;
        row += &m[i][i] * &n[i];
        for j in (i + 1)..3 {
            row += (&m[i][j] * &n[j]) << 1usize;
        }
        acc += row * &n[i];
    }
    crate::number::sign_z(&acc)
}

impl std::str::FromStr for Ellipsoid {
    type Err = Error;
    /// Parses and validates (see [`Ellipsoid::new`]).
    fn from_str(s: &str) -> Result<Ellipsoid, Error> {
        Ellipsoid::new(&s.parse()?)
    }
}

impl std::fmt::Display for Ellipsoid {
    /// The equation (oriented, E < 0 inside).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.poly.to_string_canonical())
    }
}
