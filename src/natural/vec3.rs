//! Exact 3-vectors over Q and over Q(√d).

use crate::number::{Q, QSqrt};
use num_traits::Zero;

/// A rational 3-vector.
pub type V3 = [Q; 3];
/// A 3-vector over Q(√d).
pub type SV3 = [QSqrt; 3];

/// `u + v`.
pub fn add(u: &V3, v: &V3) -> V3 {
    std::array::from_fn(|i| &u[i] + &v[i])
}

/// `u − v`.
pub fn sub(u: &V3, v: &V3) -> V3 {
    std::array::from_fn(|i| &u[i] - &v[i])
}

/// `k u`.
pub fn scale(u: &V3, k: &Q) -> V3 {
    std::array::from_fn(|i| &u[i] * k)
}

/// `u · v`.
pub fn dot(u: &V3, v: &V3) -> Q {
    &u[0] * &v[0] + &u[1] * &v[1] + &u[2] * &v[2]
}

/// `u × v`.
pub fn cross(u: &V3, v: &V3) -> V3 {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
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

/// `u + k v` with `k ∈ Q(√d)`.
pub fn add_scaled(u: &SV3, v: &V3, k: &QSqrt) -> SV3 {
    std::array::from_fn(|i| u[i].add(&k.scale(&v[i])))
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
