//! Witness points: exact points of E with two rational coordinates and the
//! third in Q(√d), on which the sign of S is decided exactly.
//!
//! Lemma 1 of the paper: two points of E with S of opposite signs prove that
//! E and S intersect (E is connected).  A witness is built from a rational
//! approximation of a point of E by solving E = 0 for the coordinate along
//! which E's gradient is largest (so the discriminant stays positive).

use super::ellipsoid::Ellipsoid;
use crate::number::{Q, QSqrt};
use crate::poly::QMPoly;
use crate::poly::mpoly::NVARS;
use num_traits::{Signed, Zero};

/// A point of E: coordinates in Q(√d) (at most one irrational coordinate).
#[derive(Clone, Debug)]
pub struct WitnessPoint {
    /// The coordinates x, y, z.
    pub coords: [QSqrt; 3],
    /// S at the point, exactly.
    pub value: QSqrt,
    /// Its sign (-1, 0, 1).
    pub sign: i32,
}

/// Exact value of a polynomial in x, y, z at a point of Q(√d)³.
pub fn eval_qsqrt(p: &QMPoly, pt: &[QSqrt; 3]) -> QSqrt {
    let d = pt
        .iter()
        .find(|c| !c.is_rational())
        .map(|c| c.d.clone())
        .unwrap_or_else(Q::zero);
    let mut acc = QSqrt::new(Q::zero(), Q::zero(), d.clone());
    for (e, c) in p.terms() {
        let mut t = QSqrt::new(c.clone(), Q::zero(), d.clone());
        for v in 0..3.min(NVARS) {
            for _ in 0..e[v] {
                t = t.mul(&pt[v]);
            }
        }
        acc = acc.add(&t);
    }
    acc
}

/// Projects a rational point near E onto E along the coordinate axis of the
/// largest gradient component; `None` if that line misses E.
pub fn snap_to_ellipsoid(e: &Ellipsoid, p: &[Q; 3]) -> Option<[QSqrt; 3]> {
    let g = e.form.half_gradient(p);
    let mut k = 0;
    for i in 1..3 {
        if g[i].abs() > g[k].abs() {
            k = i;
        }
    }
    let a = &e.form.a;
    // E restricted to the line p + s·e_k:  a_kk s² + 2 h s + c0 (in the coordinate x_k = s)
    let mut h = e.form.b[k].clone();
    for j in 0..3 {
        if j != k {
            h += &a[k][j] * &p[j];
        }
    }
    let mut c0 = e.form.c.clone();
    for i in 0..3 {
        if i == k {
            continue;
        }
        c0 += &e.form.b[i] * &p[i] * Q::from_integer(2.into());
        for j in 0..3 {
            if j != k {
                c0 += &a[i][j] * &p[i] * &p[j];
            }
        }
    }
    let akk = &a[k][k];
    let disc = &h * &h - akk * &c0;
    if disc.is_negative() {
        return None;
    }
    // root closer to p_k: sign of (akk p_k + h)
    let s = if (akk * &p[k] + &h).is_negative() {
        -1
    } else {
        1
    };
    let root = QSqrt::new(-&h / akk, Q::from_integer(s.into()) / akk, disc);
    let mut out: [QSqrt; 3] = std::array::from_fn(|i| QSqrt::rational(p[i].clone()));
    out[k] = root.normalized();
    Some(out)
}

/// Tries to turn approximations of a point of E (given for increasing
/// precision by `approx(bits)`) into a witness on which S has the sign
/// `want`.  Gives up after 2^12 bits.
pub fn find_witness(
    e: &Ellipsoid,
    s: &QMPoly,
    want: i32,
    approx: &dyn Fn(u32) -> Option<[Q; 3]>,
) -> Option<WitnessPoint> {
    let mut bits = 8;
    while bits <= 1024 {
        if let Some(p) = approx(bits + 16)
            && let Some(pt) = snap_to_ellipsoid(e, &round_point(&p, bits))
        {
            let v = eval_qsqrt(s, &pt);
            let sg = v.sign();
            if sg == want {
                return Some(WitnessPoint {
                    coords: pt,
                    value: v,
                    sign: sg,
                });
            }
        }
        bits *= 2;
    }
    None
}

/// Replaces each coordinate by the simplest rational within `2^-bits`, so
/// that witnesses have short coordinates.
fn round_point(p: &[Q; 3], bits: u32) -> [Q; 3] {
    let eps = Q::new(1.into(), num_bigint::BigInt::from(1) << bits as usize);
    std::array::from_fn(|i| crate::roots::simplest_rational_in(&(&p[i] - &eps), &(&p[i] + &eps)))
}

/// An exact point of E with S evaluated there (for the sampling checks and
/// the side of S when no critical point is needed).
pub fn witness_at(e: &Ellipsoid, s: &QMPoly, p: &[Q; 3]) -> Option<WitnessPoint> {
    let pt = snap_to_ellipsoid(e, p)?;
    let v = eval_qsqrt(s, &pt);
    let sign = v.sign();
    Some(WitnessPoint {
        coords: pt,
        value: v,
        sign,
    })
}
