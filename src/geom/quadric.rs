//! Quadrics as matrices: a polynomial of degree ≤ 2 in x, y, z as
//! `pᵀ A p + 2 bᵀ p + c`, and its 4×4 integer matrix after clearing
//! denominators once.  Shared by the tangent point method (the ellipsoid,
//! quadric S) and the natural quadrics (their matrices and pencils).

use super::matrix::Mat4;
use crate::number::Q;
use crate::poly::QMPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

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

    /// The negated form.
    pub fn neg(&self) -> QuadricForm {
        QuadricForm {
            a: std::array::from_fn(|i| std::array::from_fn(|j| -&self.a[i][j])),
            b: std::array::from_fn(|i| -&self.b[i]),
            c: -&self.c,
        }
    }
}

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
