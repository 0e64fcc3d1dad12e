//! Exact rational interval enclosures of polynomial values, and the exact
//! identification of `num(α)/den(α)` at a real algebraic `α` as a real
//! algebraic number.
//!
//! Key idea: `u = num(α)/den(α)` is a root of
//! `R(u) = Res_λ(φ(λ), u·den(λ) − num(λ))` (φ the defining polynomial of
//! α).  Isolate the real roots of `R`, then shrink α's interval until the
//! interval enclosure of `num/den` meets exactly one of them: that root *is*
//! `u` (it lies in the enclosure and in exactly one isolating interval).

use super::algebraic::RealAlg;
use super::isolate::{RootInterval, bisect_once, isolate_squarefree};
use crate::elim::resultant_mpoly;
use crate::number::Q;
use crate::poly::mpoly::{MPoly, NVARS, T, U};
use crate::poly::{QPoly, ZPoly};
use num_traits::Zero;

/// An enclosure `[lo, hi]` of `p(x)` for all `x ∈ [a, b]` (rational interval
/// Horner scheme; exact rational arithmetic, so it is a true enclosure).
pub fn eval_interval(p: &QPoly, a: &Q, b: &Q) -> (Q, Q) {
    let mut lo = Q::zero();
    let mut hi = Q::zero();
    for c in p.coeffs().iter().rev() {
        // [lo, hi] * [a, b]
        let cands = [&lo * a, &lo * b, &hi * a, &hi * b];
        let mut mn = cands[0].clone();
        let mut mx = cands[0].clone();
        for v in &cands[1..] {
            if *v < mn {
                mn = v.clone();
            }
            if *v > mx {
                mx = v.clone();
            }
        }
        lo = mn + c;
        hi = mx + c;
    }
    (lo, hi)
}

/// Enclosure of `num(x)/den(x)` on `[a, b]`, or `None` when the enclosure of
/// `den` contains 0.
pub fn eval_ratio_interval(num: &QPoly, den: &QPoly, a: &Q, b: &Q) -> Option<(Q, Q)> {
    let (nl, nh) = eval_interval(num, a, b);
    let (dl, dh) = eval_interval(den, a, b);
    if dl <= Q::zero() && dh >= Q::zero() {
        return None;
    }
    let cands = [&nl / &dl, &nl / &dh, &nh / &dl, &nh / &dh];
    let mut mn = cands[0].clone();
    let mut mx = cands[0].clone();
    for v in &cands[1..] {
        if *v < mn {
            mn = v.clone();
        }
        if *v > mx {
            mx = v.clone();
        }
    }
    Some((mn, mx))
}

fn meets(iv: &RootInterval, lo: &Q, hi: &Q) -> bool {
    if iv.is_exact() {
        lo <= &iv.lo && &iv.lo <= hi
    } else {
        &iv.lo < hi && lo < &iv.hi
    }
}

/// `Res_λ(φ(λ), u·den(λ) − num(λ))`, square-free and primitive, as a
/// polynomial in `u`: its roots include `num(α)/den(α)` for every root α of
/// φ with `den(α) != 0`.
pub fn value_polynomial(phi: &ZPoly, num: &QPoly, den: &QPoly) -> ZPoly {
    let phi_m = MPoly::from_univariate(&phi.to_q(), T);
    let u = MPoly::<Q>::var(U);
    let den_m = MPoly::from_univariate(den, T);
    let num_m = MPoly::from_univariate(num, T);
    let g = &(&u * &den_m) - &num_m;
    let r = resultant_mpoly(&phi_m, &g, T);
    let ru = r.to_univariate(U).unwrap_or_else(QPoly::zero);
    let (z, _) = ZPoly::from_q(&ru);
    z.squarefree_part()
}

/// The exact value `num(α)/den(α)` as a real algebraic number, for a real
/// algebraic `α` with `den(α) != 0`.  Returns `None` only if `den(α) = 0`.
///
/// ```
/// use quadsect::roots::{RealAlg, value_at};
/// use quadsect::poly::{QPoly, ZPoly};
/// use quadsect::number::qi;
/// // α = √2, value α² + 1 = 3
/// let a = RealAlg::roots_of(&ZPoly::from_i64s(&[-2, 0, 1]))[1].clone();
/// let num = QPoly::new(vec![qi(1), qi(0), qi(1)]);
/// let v = value_at(&a, &num, &QPoly::constant(qi(1))).unwrap();
/// assert_eq!(v.as_rational(), Some(&qi(3)));
/// ```
pub fn value_at(alpha: &RealAlg, num: &QPoly, den: &QPoly) -> Option<RealAlg> {
    if alpha.sign_of_q(den) == 0 {
        return None;
    }
    if let Some(a) = alpha.as_rational() {
        let d = eval_q(den, a);
        return Some(RealAlg::Rational(eval_q(num, a) / d));
    }
    let phi = alpha.poly();
    let r = value_polynomial(&phi, num, den);
    let mut ivs = isolate_squarefree(&r);
    let mut a = alpha.clone();
    loop {
        if let Some(x) = a.as_rational() {
            let x = x.clone();
            return Some(RealAlg::Rational(eval_q(num, &x) / eval_q(den, &x)));
        }
        let (lo, hi) = a.interval();
        if let Some((vl, vh)) = eval_ratio_interval(num, den, &lo, &hi) {
            let hits: Vec<usize> = (0..ivs.len())
                .filter(|&j| meets(&ivs[j], &vl, &vh))
                .collect();
            if hits.len() == 1 {
                return Some(RealAlg::from_interval(&r, &ivs[hits[0]]).simplify());
            }
            for j in hits {
                bisect_once(&r, &mut ivs[j]);
            }
        }
        a.bisect();
    }
}

/// Exact value of a rational polynomial at a rational point.
pub fn eval_q(p: &QPoly, x: &Q) -> Q {
    let mut acc = Q::zero();
    for c in p.coeffs().iter().rev() {
        acc = acc * x + c;
    }
    acc
}

/// Exact value of a multivariate polynomial with `x`, `y`, `z` given.
pub fn eval_xyz(p: &crate::poly::QMPoly, x: &Q, y: &Q, z: &Q) -> Q {
    let mut pt: [Q; NVARS] = std::array::from_fn(|_| Q::zero());
    pt[0] = x.clone();
    pt[1] = y.clone();
    pt[2] = z.clone();
    p.eval(&pt)
}
