//! The validation of the ellipsoid E (SPEC §2): degree 2, definite
//! quadratic part, non-empty and not a single point.

use crate::error::{Error, ErrorKind};
use crate::geom::{Mat4, QuadricForm, adj3_int, common_denominator};
use crate::number::Q;
use crate::poly::QMPoly;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// A validated ellipsoid `E(p) = pᵀ A p + 2 bᵀ p + c` with `A` positive
/// definite and `E(centre) < 0` (the input is negated when its quadratic
/// part is negative definite; the zero set is the same).
#[derive(Clone, Debug)]
pub struct Ellipsoid {
    /// The equation, oriented so that E < 0 inside.
    pub poly: QMPoly,
    /// Its matrices.
    pub form: QuadricForm,
    /// Centre `-A⁻¹ b`.
    pub center: [Q; 3],
    /// `E(centre) < 0`.
    pub center_value: Q,
    /// True when the input was negated.
    pub negated: bool,
}

impl Ellipsoid {
    /// Validates `p` as an ellipsoid, with a clear error otherwise.
    ///
    /// ```
    /// use quadsect::poly::parse_poly;
    /// use quadsect::tangent::Ellipsoid;
    /// assert!(Ellipsoid::new(&parse_poly("x^2 + y^2 + z^2 - 25").unwrap()).is_ok());
    /// let e = Ellipsoid::new(&parse_poly("x^2 + y^2 - z^2 - 1").unwrap()).unwrap_err();
    /// assert!(e.to_string().contains("not definite"));
    /// ```
    pub fn new(p: &QMPoly) -> Result<Ellipsoid, Error> {
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
