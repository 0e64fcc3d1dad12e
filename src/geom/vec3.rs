//! Exact 3-vectors: generic dot and cross products over any ring whose
//! borrowed operands multiply (Q, Q(√d), polynomials), the rational helpers,
//! and checked machine-word versions for the i128 fast paths.

use crate::number::{Q, QSqrt};
use crate::poly::QMPoly;
use num_traits::Zero;

/// The ring operations the generic products need: `self · r` for `r` in
/// the ring `R` (the same ring or a subring), and `±` within the ring.
pub trait Scalar<R = Self>: Sized {
    /// `self · r`.
    fn times(&self, r: &R) -> Self;
    /// `self + o`.
    fn plus(&self, o: &Self) -> Self;
    /// `self − o`.
    fn minus(&self, o: &Self) -> Self;
}

// (rationals reduced with Lehmer's gcd: `number::q_mul`, `q_add` give
// num-rational's canonical values, without its binary gcd)
impl Scalar for Q {
    fn times(&self, r: &Q) -> Q {
        crate::number::q_mul(self, r)
    }
    fn plus(&self, o: &Q) -> Q {
        crate::number::q_add(self, o)
    }
    fn minus(&self, o: &Q) -> Q {
        crate::number::q_sub(self, o)
    }
}

impl Scalar for QMPoly {
    fn times(&self, r: &QMPoly) -> QMPoly {
        self * r
    }
    fn plus(&self, o: &QMPoly) -> QMPoly {
        self + o
    }
    fn minus(&self, o: &QMPoly) -> QMPoly {
        self - o
    }
}

impl Scalar for QSqrt {
    fn times(&self, r: &QSqrt) -> QSqrt {
        self.mul(r)
    }
    fn plus(&self, o: &QSqrt) -> QSqrt {
        self.add(o)
    }
    fn minus(&self, o: &QSqrt) -> QSqrt {
        self.sub(o)
    }
}

impl Scalar<Q> for QSqrt {
    fn times(&self, r: &Q) -> QSqrt {
        self.scale(r)
    }
    fn plus(&self, o: &QSqrt) -> QSqrt {
        self.add(o)
    }
    fn minus(&self, o: &QSqrt) -> QSqrt {
        self.sub(o)
    }
}

/// A rational 3-vector.
pub type V3 = [Q; 3];
/// A 3-vector over Q(√d).
pub type SV3 = [QSqrt; 3];

/// `u + v`.
pub fn add(u: &V3, v: &V3) -> V3 {
    std::array::from_fn(|i| u[i].plus(&v[i]))
}

/// `u − v`.
pub fn sub(u: &V3, v: &V3) -> V3 {
    std::array::from_fn(|i| u[i].minus(&v[i]))
}

/// `k u`.
pub fn scale(u: &V3, k: &Q) -> V3 {
    std::array::from_fn(|i| u[i].times(k))
}

/// `u · v` over any ring (the second factor may be of a subring, e.g. a
/// Q(√d) vector dotted with a rational one).
pub fn dot<T: Scalar<S>, S>(u: &[T; 3], v: &[S; 3]) -> T {
    u[0].times(&v[0])
        .plus(&u[1].times(&v[1]))
        .plus(&u[2].times(&v[2]))
}

/// `u × v` over any ring (the second factor may be of a subring).
pub fn cross<T: Scalar<S>, S>(u: &[T; 3], v: &[S; 3]) -> [T; 3] {
    [
        u[1].times(&v[2]).minus(&u[2].times(&v[1])),
        u[2].times(&v[0]).minus(&u[0].times(&v[2])),
        u[0].times(&v[1]).minus(&u[1].times(&v[0])),
    ]
}

/// `|u|²`.
pub fn norm2(u: &V3) -> Q {
    dot(u, u)
}

/// True for the zero vector.
pub fn is_zero(u: &V3) -> bool {
    u.iter().all(|c| c.is_zero())
}

/// True when `u` and `v` are parallel (or one is zero).
pub fn parallel(u: &V3, v: &V3) -> bool {
    is_zero(&cross(u, v))
}

/// A rational vector as a Q(√d) vector.
pub fn lift(u: &V3) -> SV3 {
    std::array::from_fn(|i| QSqrt::rational(u[i].clone()))
}

/// A non-zero rational vector orthogonal to `a` (not normalised).
pub fn orthogonal(a: &V3) -> V3 {
    let e = if a[0].is_zero() && a[1].is_zero() {
        [Q::from_integer(1.into()), Q::zero(), Q::zero()]
    } else {
        [Q::zero(), Q::zero(), Q::from_integer(1.into())]
    };
    cross(a, &e)
}

/// `u × v` in i128, `None` on overflow.
pub fn cross_i128(u: &[i128; 3], v: &[i128; 3]) -> Option<[i128; 3]> {
    Some([
        u[1].checked_mul(v[2])?
            .checked_sub(u[2].checked_mul(v[1])?)?,
        u[2].checked_mul(v[0])?
            .checked_sub(u[0].checked_mul(v[2])?)?,
        u[0].checked_mul(v[1])?
            .checked_sub(u[1].checked_mul(v[0])?)?,
    ])
}

/// `u · v` in i128, `None` on overflow.
pub fn dot_i128(u: &[i128; 3], v: &[i128; 3]) -> Option<i128> {
    u[0].checked_mul(v[0])?
        .checked_add(u[1].checked_mul(v[1])?)?
        .checked_add(u[2].checked_mul(v[2])?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::qi;

    #[test]
    fn generic_products_agree_across_rings() {
        let u = [qi(1), qi(-2), qi(3)];
        let v = [qi(4), qi(5), qi(-6)];
        assert_eq!(cross(&u, &v), [qi(-3), qi(18), qi(13)]);
        assert_eq!(dot(&u, &v), qi(-24));
        let su = lift(&u);
        let c = cross(&su, &v);
        assert!((0..3).all(|i| c[i] == QSqrt::rational(cross(&u, &v)[i].clone())));
        let ui = [1i128, -2, 3];
        let vi = [4i128, 5, -6];
        assert_eq!(cross_i128(&ui, &vi), Some([-3, 18, 13]));
        assert_eq!(dot_i128(&ui, &vi), Some(-24));
        assert_eq!(cross_i128(&[i128::MAX, 0, 0], &[0, 2, 0]), None);
    }
}
