//! The S-lemma certificate of a *separated* verdict when S has degree ≤ 2
//! (ellipsoid pairs among them): a rational τ for which `side·(S − τE)` is
//! positive definite as a quadratic form in `(x, y, z, 1)`.  On E = 0 it
//! equals `side·S`, so S keeps the sign `side` on all of E — checkable by
//! anyone with one exact LDLᵀ (or the leading minors) of a 4×4 matrix.
//!
//! Such a τ exists whenever `side·S > 0` on E: E has no points at infinity
//! (its quadratic part is definite), so `side·S_h > 0` on the whole
//! projective zero set of the homogenised `E_h` in R⁴ ∖ 0, and Finsler's
//! lemma (n = 4 ≥ 3) gives τ with `side·S_h − τ·E_h` positive definite.
//! The τ that work form an open interval between consecutive real roots of
//! the quartic `det(side·(S − τE))` (definiteness can change only where the
//! determinant vanishes), so one test point in each gap between the roots
//! (and beyond them) finds one: the simplest rational of the gap.

use crate::geom::matrix::Mat4;
use crate::geom::{QuadricForm, common_denominator};
use crate::number::Q;
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::isolate_real_roots;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// `det m` (Laplace along the first two rows).
fn det4(m: &Mat4) -> BigInt {
    let d2 = |r: usize, a: usize, b: usize| &m[r][a] * &m[r + 1][b] - &m[r][b] * &m[r + 1][a];
    // column pairs of the top rows and their complements, with signs
    type Minors = ((usize, usize), (usize, usize), bool);
    const PAIRS: [Minors; 6] = [
        ((0, 1), (2, 3), true),
        ((0, 2), (1, 3), false),
        ((0, 3), (1, 2), true),
        ((1, 2), (0, 3), true),
        ((1, 3), (0, 2), false),
        ((2, 3), (0, 1), true),
    ];
    let mut acc = BigInt::zero();
    for ((a, b), (c, d), plus) in PAIRS {
        let t = d2(0, a, b) * d2(2, c, d);
        if plus {
            acc += t;
        } else {
            acc -= t;
        }
    }
    acc
}

/// Whether a symmetric integer matrix is positive definite: all leading
/// principal minors positive (the pivots of fraction-free elimination
/// without exchanges are those minors).
pub(crate) fn positive_definite(m: &Mat4) -> bool {
    let mut a = m.clone();
    let mut prev = BigInt::one();
    for k in 0..4 {
        if !a[k][k].is_positive() {
            return false;
        }
        for i in k + 1..4 {
            for j in k + 1..4 {
                let v = &a[k][k] * &a[i][j] - &a[i][k] * &a[k][j];
                a[i][j] = v / &prev;
            }
        }
        prev = a[k][k].clone();
    }
    true
}

/// `side·(den(τ)·S − num(τ)·E)` on the integer matrices.
fn member(s: &Mat4, e: &Mat4, side: i32, tau: &Q) -> Mat4 {
    let (k, t) = (
        BigInt::from(side) * tau.denom(),
        BigInt::from(side) * tau.numer(),
    );
    std::array::from_fn(|i| std::array::from_fn(|j| &k * &s[i][j] - &t * &e[i][j]))
}

/// The simplest rational strictly between `a < b` (fewest digits: the
/// continued-fraction rule).
fn simplest_between(a: &Q, b: &Q) -> Q {
    let fl = a.floor();
    if &(&fl + Q::one()) < b {
        // an integer strictly inside: the one nearest 0
        let lo = &fl + Q::one();
        let hi = b.ceil() - Q::one();
        return if lo.is_positive() {
            lo
        } else if hi.is_negative() {
            hi
        } else {
            Q::zero()
        };
    }
    // a and b in [n, n + 1]: n + 1/simplest(1/(b − n), 1/(a − n))
    let n = fl;
    let (x, y) = (a - &n, b - &n);
    if x.is_zero() {
        // (n, n + y) with y ≤ 1: n + 1/k for the least k with 1/k < y
        let k = (Q::one() / &y).floor() + Q::one();
        return n + Q::one() / k;
    }
    n + Q::one() / simplest_between(&(Q::one() / &y), &(Q::one() / &x))
}

/// A rational τ with `side·(S − τE)` positive definite, when S has degree
/// ≤ 2 and `side·S > 0` on E (`None` otherwise, or when S is not a form of
/// degree ≤ 2).
pub(crate) fn s_lemma_tau(e: &QMPoly, s: &QMPoly, side: i32) -> Option<Q> {
    let (fe, fs) = (QuadricForm::from_poly(e)?, QuadricForm::from_poly(s)?);
    let l = common_denominator(&[&fe, &fs]);
    let (me, ms) = (fe.int_matrix(&l), fs.int_matrix(&l));
    // det(side·(S − τE)), degree ≤ 4, from its values at τ = 0, …, 4
    let values: Vec<Q> = (0..5)
        .map(|t| Q::from_integer(det4(&member(&ms, &me, side, &Q::from_integer(t.into())))))
        .collect();
    let det = newton_interpolate(&values);
    let (z, _) = ZPoly::from_q(&det);
    let roots = if z.degree().unwrap_or(0) == 0 {
        vec![]
    } else {
        isolate_real_roots(&z)
    };
    let mut candidates = Vec::with_capacity(roots.len() + 1);
    match (roots.first(), roots.last()) {
        (Some(first), Some(last)) => {
            candidates.push(&first.lo - Q::one());
            for w in roots.windows(2) {
                let (a, b) = (&w[0].hi, &w[1].lo);
                candidates.push(if a < b {
                    simplest_between(a, b)
                } else {
                    a.clone()
                });
            }
            candidates.push(&last.hi + Q::one());
        }
        _ => candidates.push(Q::zero()),
    }
    candidates
        .into_iter()
        .find(|t| positive_definite(&member(&ms, &me, side, t)))
}

/// The polynomial of degree < n through `(k, values[k])`, k = 0…n−1
/// (Newton's forward differences).
fn newton_interpolate(values: &[Q]) -> QPoly {
    let n = values.len();
    let mut diffs = values.to_vec();
    let mut coef = Vec::with_capacity(n);
    for k in 0..n {
        coef.push(diffs[0].clone());
        for i in 0..n - 1 - k {
            diffs[i] = (&diffs[i + 1] - &diffs[i]) / Q::from_integer(BigInt::from(k + 1));
        }
    }
    // Σ coef_k · t(t−1)…(t−k+1)
    let mut out = QPoly::new(vec![Q::zero()]);
    let mut basis = QPoly::new(vec![Q::one()]);
    for (k, c) in coef.iter().enumerate() {
        out = &out + &basis.scale(c);
        basis = &basis * &QPoly::new(vec![Q::from_integer(-BigInt::from(k)), Q::one()]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn check(e: &str, s: &str, side: i32) -> Option<Q> {
        let (e, s) = (parse_poly(e).unwrap(), parse_poly(s).unwrap());
        let tau = s_lemma_tau(&e, &s, side)?;
        // independent check: side·(S − τE) > 0 at many rational points and
        // the matrix test again
        let fe = QuadricForm::from_poly(&e).unwrap();
        let fs = QuadricForm::from_poly(&s).unwrap();
        for p in [[0, 0, 0], [1, 2, 3], [-3, 1, 0], [7, -5, 2]] {
            let p: [Q; 3] = std::array::from_fn(|i| Q::from_integer(p[i].into()));
            let v = (fs.eval(&p) - &tau * fe.eval(&p)) * Q::from_integer(side.into());
            assert!(v.is_positive(), "{p:?}");
        }
        Some(tau)
    }

    #[test]
    fn separated_quadrics_have_a_tau_and_touching_ones_none() {
        // apart, nested both ways, a plane, an ellipsoid in a hyperboloid's gap
        assert!(check("x^2+2y^2+z^2-1", "(x-3)^2+y^2+z^2-1", 1).is_some());
        assert!(check("x^2+y^2+z^2-1", "x^2+y^2+z^2-4", -1).is_some());
        assert!(check("x^2+y^2+z^2-4", "x^2+y^2+z^2-1", 1).is_some());
        assert!(check("x^2+2y^2+3z^2-6", "x+y+z-10", -1).is_some());
        assert!(check("x^2+y^2+z^2-1", "x y - 1", -1).is_some());
        // the wrong side, touching, crossing: no τ
        assert!(check("x^2+y^2+z^2-1", "(x-3)^2+y^2+z^2-1", -1).is_none());
        assert!(check("x^2+y^2+z^2-1", "(x-2)^2+y^2+z^2-1", 1).is_none());
        assert!(check("x^2+y^2+z^2-1", "x+y-1/2", 1).is_none());
        // S of degree 3: not this certificate
        assert!(check("x^2+y^2+z^2-1", "x y z - 1", -1).is_none());
    }

    #[test]
    fn simplest_rationals() {
        let q = |a: i64, b: i64| Q::new(a.into(), b.into());
        assert_eq!(simplest_between(&q(1, 3), &q(1, 2)), q(2, 5));
        assert_eq!(simplest_between(&q(-7, 2), &q(5, 1)), q(0, 1));
        assert_eq!(simplest_between(&q(3, 1), &q(31, 10)), q(34, 11));
        assert_eq!(simplest_between(&q(-31, 10), &q(-3, 1)), q(-34, 11));
        assert_eq!(simplest_between(&q(2, 1), &q(7, 2)), q(3, 1));
    }
}
