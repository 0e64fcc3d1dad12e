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
//! the quartic `det(S − τE)` (definiteness can change only where the
//! determinant vanishes), so one test point in each gap between the roots
//! (and beyond them) finds one: the simplest rational of the gap.

use super::pencil::pencil_polys;
use crate::geom::matrix::Mat4;
use crate::geom::{QuadricForm, common_denominator};
use crate::number::Q;
use crate::poly::QMPoly;
use crate::roots::{isolate_real_roots, simplest_rational_in};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

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

/// A rational τ with `side·(S − τE)` positive definite (E given as its
/// form), when S has degree
/// ≤ 2 and `side·S > 0` on E (`None` otherwise, or when S is not a form of
/// degree ≤ 2).
pub(crate) fn s_lemma_tau(fe: &QuadricForm, s: &QMPoly, side: i32) -> Option<Q> {
    let fs = QuadricForm::from_poly(s)?;
    let l = common_denominator(&[fe, &fs]);
    let (me, ms) = (fe.int_matrix(&l), fs.int_matrix(&l));
    // det(side·(S − τE)) = det(S − τE) (a 4×4 determinant): definiteness
    // changes only at its real roots
    let (det, _) = pencil_polys(&ms, &me);
    let roots = if det.degree().unwrap_or(0) == 0 {
        vec![]
    } else {
        isolate_real_roots(&det)
    };
    let mut candidates = Vec::with_capacity(roots.len() + 1);
    match (roots.first(), roots.last()) {
        (Some(first), Some(last)) => {
            candidates.push(&first.lo - Q::one());
            for w in roots.windows(2) {
                let (a, b) = (&w[0].hi, &w[1].lo);
                candidates.push(if a < b {
                    simplest_rational_in(a, b)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn check(e: &str, s: &str, side: i32) -> Option<Q> {
        let (e, s) = (parse_poly(e).unwrap(), parse_poly(s).unwrap());
        let tau = s_lemma_tau(&QuadricForm::from_poly(&e).unwrap(), &s, side)?;
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

    /// The certificate's τ refers to E as the user wrote it, also when the
    /// engine oriented E the other way (negative inside): side·(S − τE) is
    /// positive definite for the input polynomial.
    #[test]
    fn the_reported_tau_is_for_the_ellipsoid_as_given() {
        for (e, s) in [
            ("1 - x^2 - 2y^2 - z^2", "(x-3)^2+y^2+z^2-1"),
            ("-x^2-y^2-z^2+4", "x+y+z-10"),
            ("x^2+y^2+z^2-4", "x+y+z-10"),
        ] {
            let r = crate::tangent::decide_str(e, s).unwrap();
            let tau = r
                .certificate()
                .s_lemma_tau()
                .expect("a separated quadric pair");
            let side = r.side.unwrap();
            let (fe, fs) = (
                QuadricForm::from_poly(&parse_poly(e).unwrap()).unwrap(),
                QuadricForm::from_poly(&parse_poly(s).unwrap()).unwrap(),
            );
            let l = common_denominator(&[&fe, &fs]);
            let m = member(&fs.int_matrix(&l), &fe.int_matrix(&l), side, tau);
            assert!(positive_definite(&m), "{e} / {s}: τ = {tau}");
        }
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
}
