//! Exact evaluation of polynomials at points of Q(√d)³ (witness points,
//! points of conics and lines in a quadratic field).

use crate::number::{Q, QSqrt};
use crate::poly::QMPoly;
use crate::poly::mpoly::NVARS;
use num_traits::{One, Zero};

/// Exact value of a polynomial in x, y, z at a point of Q(√d)³.
///
/// With at most one irrational coordinate `x_k` (the witnesses' shape) the
/// rational coordinates are substituted first and the univariate rest is
/// evaluated by Horner's rule in Q(√d): a handful of Q(√d) products instead
/// of one per monomial factor.
pub fn eval_qsqrt(p: &QMPoly, pt: &[QSqrt; 3]) -> QSqrt {
    let irrational: Vec<usize> = (0..3).filter(|&i| !pt[i].is_rational()).collect();
    let d = irrational
        .first()
        .map(|&i| pt[i].d.clone())
        .unwrap_or_else(Q::zero);
    if irrational.len() > 1 {
        return eval_qsqrt_terms(p, pt, &d);
    }
    let k = irrational.first().copied().unwrap_or(0);
    // coefficients of p restricted to the line, as a polynomial in x_k
    let deg = p
        .terms()
        .iter()
        .map(|(e, _)| e[k] as usize)
        .max()
        .unwrap_or(0);
    let mut coef = vec![Q::zero(); deg + 1];
    let mut powers: [Vec<Q>; 3] = Default::default();
    for (e, c) in p.terms() {
        crate::budget::check();
        let mut t = c.clone();
        for v in (0..3).filter(|&v| v != k) {
            let ev = e[v] as usize;
            if ev == 0 {
                continue;
            }
            let pw = &mut powers[v];
            if pw.is_empty() {
                pw.push(Q::one());
            }
            while pw.len() <= ev {
                let next = pw.last().expect("non-empty") * &pt[v].a;
                pw.push(next);
            }
            t *= &pw[ev];
        }
        coef[e[k] as usize] += t;
    }
    let x = &pt[k];
    let mut acc = QSqrt::new(Q::zero(), Q::zero(), d.clone());
    for c in coef.iter().rev() {
        acc = acc.mul(x).add(&QSqrt::new(c.clone(), Q::zero(), d.clone()));
    }
    acc
}

fn eval_qsqrt_terms(p: &QMPoly, pt: &[QSqrt; 3], d: &Q) -> QSqrt {
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

/// `∇p = (∂p/∂x, ∂p/∂y, ∂p/∂z)`.
pub fn gradient(p: &QMPoly) -> [QMPoly; 3] {
    use crate::poly::mpoly::{X, Y, Z};
    [p.derivative(X), p.derivative(Y), p.derivative(Z)]
}
