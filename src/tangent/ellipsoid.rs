//! Quadrics as matrices, and the validation of the ellipsoid E (SPEC §2):
//! degree 2, definite quadratic part, non-empty and not a single point.

use crate::error::{Error, ErrorKind};
use crate::number::Q;
use crate::poly::QMPoly;
use crate::poly::mpoly::{MPoly, NVARS};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// A polynomial of degree ≤ 2 in x, y, z written as
/// `q(p) = pᵀ A p + 2 bᵀ p + c` with `A` symmetric.
#[derive(Clone, Debug, PartialEq)]
pub struct QuadricForm {
    /// Symmetric matrix of the quadratic part.
    pub a: [[Q; 3]; 3],
    /// Half the linear part.
    pub b: [Q; 3],
    /// Constant term.
    pub c: Q,
}

/// `k/2` of a reduced rational, without a gcd.
fn half(k: &Q) -> Q {
    let n = k.numer();
    if n.is_even() {
        Q::new_raw(n >> 1usize, k.denom().clone())
    } else {
        Q::new_raw(n.clone(), k.denom() << 1usize)
    }
}

fn zero3() -> [Q; 3] {
    std::array::from_fn(|_| Q::zero())
}

impl QuadricForm {
    /// Reads a polynomial of total degree ≤ 2 in x, y, z; `None` otherwise.
    pub fn from_poly(p: &QMPoly) -> Option<QuadricForm> {
        if p.total_degree().unwrap_or(0) > 2 || p.vars().iter().any(|&v| v > 2) {
            return None;
        }
        let mut a: [[Q; 3]; 3] = std::array::from_fn(|_| zero3());
        let mut b = zero3();
        let mut c = Q::zero();
        for (e, k) in p.terms() {
            // the variables of the monomial, with multiplicity (at most two)
            let mut idx = [0usize; 2];
            let mut n = 0;
            for v in 0..3 {
                for _ in 0..e[v] {
                    if n == 2 {
                        return None;
                    }
                    idx[n] = v;
                    n += 1;
                }
            }
            match (n, idx[0], idx[1]) {
                (0, _, _) => c = k.clone(),
                (1, i, _) => b[i] = half(k),
                (_, i, j) if i == j => a[i][i] = k.clone(),
                (_, i, j) => {
                    a[i][j] = half(k);
                    a[j][i] = a[i][j].clone();
                }
            }
        }
        Some(QuadricForm { a, b, c })
    }

    /// Back to a polynomial.
    pub fn to_poly(&self) -> QMPoly {
        let mut terms = Vec::new();
        let two = Q::from_integer(2.into());
        for i in 0..3 {
            for j in i..3 {
                let mut e = [0u32; NVARS];
                e[i] += 1;
                e[j] += 1;
                let k = if i == j {
                    self.a[i][i].clone()
                } else {
                    &self.a[i][j] * &two
                };
                terms.push((e, k));
            }
            let mut e = [0u32; NVARS];
            e[i] = 1;
            terms.push((e, &self.b[i] * &two));
        }
        terms.push(([0; NVARS], self.c.clone()));
        MPoly::from_terms(terms)
    }

    /// Exact value at a rational point.
    pub fn eval(&self, p: &[Q; 3]) -> Q {
        let mut s = self.c.clone();
        for i in 0..3 {
            s += &self.b[i] * &p[i] * Q::from_integer(2.into());
            for j in 0..3 {
                s += &self.a[i][j] * &p[i] * &p[j];
            }
        }
        s
    }

    /// `A p + b` (half the gradient).
    pub fn half_gradient(&self, p: &[Q; 3]) -> [Q; 3] {
        std::array::from_fn(|i| {
            let mut s = self.b[i].clone();
            for j in 0..3 {
                s += &self.a[i][j] * &p[j];
            }
            s
        })
    }

    /// Leading principal minors `(a00, a00 a11 - a01², det A)`.
    pub fn principal_minors(&self) -> (Q, Q, Q) {
        let a = &self.a;
        let m1 = a[0][0].clone();
        let m2 = &a[0][0] * &a[1][1] - &a[0][1] * &a[1][0];
        (m1, m2, det3(a))
    }

    /// The negated form.
    pub fn neg(&self) -> QuadricForm {
        QuadricForm {
            a: std::array::from_fn(|i| std::array::from_fn(|j| -&self.a[i][j])),
            b: std::array::from_fn(|i| -&self.b[i]),
            c: -&self.c,
        }
    }

    /// The quadratic part is positive definite.
    pub fn is_positive_definite(&self) -> bool {
        let (m1, m2, m3) = self.principal_minors();
        m1.is_positive() && m2.is_positive() && m3.is_positive()
    }
}

/// A 4×4 integer matrix `[[A, b], [bᵀ, c]]`.
pub type Mat4 = [[BigInt; 4]; 4];

/// lcm of the denominators of every matrix entry of the forms: the
/// smallest positive integer `L` with `L·q` integral for each form `q`.
pub fn common_denominator(forms: &[&QuadricForm]) -> BigInt {
    let mut l = BigInt::one();
    for f in forms {
        let entries = f.a.iter().flatten().chain(f.b.iter()).chain([&f.c]);
        for q in entries {
            crate::number::lcm_assign(&mut l, q.denom());
        }
    }
    l
}

impl QuadricForm {
    /// The 4×4 matrix of `l·q`; `l` must clear every denominator (see
    /// [`common_denominator`]).
    pub fn int_matrix(&self, l: &BigInt) -> Mat4 {
        let z = |q: &Q| -> BigInt {
            if q.denom().is_one() {
                q.numer() * l
            } else {
                q.numer() * (l / q.denom())
            }
        };
        std::array::from_fn(|i| {
            std::array::from_fn(|j| match (i, j) {
                (3, 3) => z(&self.c),
                (3, k) | (k, 3) => z(&self.b[k]),
                (i, j) => z(&self.a[i][j]),
            })
        })
    }
}

/// Adjugate and determinant of the leading 3×3 block of an integer matrix.
pub fn adj3_int(m: &Mat4) -> ([[BigInt; 3]; 3], BigInt) {
    let cof = |i: usize, j: usize| -> BigInt {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        &m[r0][c0] * &m[r1][c1] - &m[r0][c1] * &m[r1][c0]
    };
    // adj[i][j] = cofactor(j, i); the cyclic index choice carries the sign
    let adj: [[BigInt; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| cof(j, i)));
    let det: BigInt = (0..3).map(|j| &m[0][j] * &adj[j][0]).sum();
    (adj, det)
}

/// Determinant of a 3×3 rational matrix.
pub fn det3(a: &[[Q; 3]; 3]) -> Q {
    &a[0][0] * (&a[1][1] * &a[2][2] - &a[1][2] * &a[2][1])
        - &a[0][1] * (&a[1][0] * &a[2][2] - &a[1][2] * &a[2][0])
        + &a[0][2] * (&a[1][0] * &a[2][1] - &a[1][1] * &a[2][0])
}

/// Inverse of an invertible 3×3 rational matrix.
pub fn inv3(a: &[[Q; 3]; 3]) -> Option<[[Q; 3]; 3]> {
    let d = det3(a);
    if d.is_zero() {
        return None;
    }
    let cof = |i: usize, j: usize| -> Q {
        let r: Vec<usize> = (0..3).filter(|&k| k != i).collect();
        let c: Vec<usize> = (0..3).filter(|&k| k != j).collect();
        let m = &a[r[0]][c[0]] * &a[r[1]][c[1]] - &a[r[0]][c[1]] * &a[r[1]][c[0]];
        if (i + j).is_multiple_of(2) { m } else { -m }
    };
    // inverse = adj / det, adj[i][j] = cof(j, i)
    Some(std::array::from_fn(|i| {
        std::array::from_fn(|j| cof(j, i) / &d)
    }))
}

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
