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
use num_traits::{Signed, Zero};

/// The smallest and largest of four rationals (interval products).
fn min_max(c: [Q; 4]) -> (Q, Q) {
    let mut mn = c[0].clone();
    let mut mx = c[0].clone();
    for v in &c[1..] {
        if *v < mn {
            mn = v.clone();
        }
        if *v > mx {
            mx = v.clone();
        }
    }
    (mn, mx)
}

/// An enclosure `[lo, hi]` of `p(x)` for all `x ∈ [a, b]` (rational interval
/// Horner scheme; exact rational arithmetic, so it is a true enclosure).
pub fn eval_interval(p: &QPoly, a: &Q, b: &Q) -> (Q, Q) {
    let mut lo = Q::zero();
    let mut hi = Q::zero();
    for c in p.coeffs().iter().rev() {
        // [lo, hi] * [a, b]
        let (mn, mx) = min_max([&lo * a, &lo * b, &hi * a, &hi * b]);
        lo = mn + c;
        hi = mx + c;
    }
    (lo, hi)
}

/// An enclosure of `p(x)` for all `x ∈ [a, b]` by the mean-value form
/// around the midpoint `m`: `p(x) ∈ p(m) ± r·Σ i|pᵢ|Rⁱ⁻¹` with `r = (b − a)/2`
/// and `R = 2^e ≥ max(|a|, |b|)`.  One exact evaluation and one integer sum:
/// much cheaper than interval Horner, and as tight as the interval shrinks.
pub fn enclose_mean_value(p: &ZPoly, a: &Q, b: &Q) -> (Q, Q) {
    let two = Q::from_integer(2.into());
    let m = (a + b) / &two;
    let r = (b - a) / &two;
    let c = p.eval_q(&m);
    let big = if a.abs() > b.abs() { a.abs() } else { b.abs() };
    let e = if big.is_zero() {
        0
    } else {
        crate::number::floor_log2_q(&big) + 1
    };
    // Σ i|p_i| 2^(e(i−1))
    let mut bound = Q::zero();
    for (i, pi) in p.coeffs().iter().enumerate().skip(1) {
        if pi.is_zero() {
            continue;
        }
        let k = e * (i as i64 - 1);
        let pow = if k >= 0 {
            Q::from_integer(num_bigint::BigInt::from(1) << (k as usize))
        } else {
            Q::new(1.into(), num_bigint::BigInt::from(1) << ((-k) as usize))
        };
        bound += Q::from_integer(pi.abs() * num_bigint::BigInt::from(i)) * pow;
    }
    let w = bound * r;
    (&c - &w, c + w)
}

/// Enclosure of `num(x)/den(x)` on `[a, b]`, or `None` when the enclosure of
/// `den` contains 0.
pub fn eval_ratio_interval(num: &QPoly, den: &QPoly, a: &Q, b: &Q) -> Option<(Q, Q)> {
    let n = ZPoly::from_q(num);
    let d = ZPoly::from_q(den);
    ratio_enclosure(&n, &d, a, b)
}

/// [`eval_ratio_interval`] with numerator and denominator already written
/// as `k·P` with `P` integer (see [`ZPoly::from_q`]).
pub fn ratio_enclosure(num: &(ZPoly, Q), den: &(ZPoly, Q), a: &Q, b: &Q) -> Option<(Q, Q)> {
    let (nl, nh) = scale_iv(enclose_mean_value(&num.0, a, b), &num.1);
    let (dl, dh) = scale_iv(enclose_mean_value(&den.0, a, b), &den.1);
    if dl <= Q::zero() && dh >= Q::zero() {
        return None;
    }
    Some(min_max([&nl / &dl, &nl / &dh, &nh / &dl, &nh / &dh]))
}

fn scale_iv((l, h): (Q, Q), k: &Q) -> (Q, Q) {
    if k.is_negative() {
        (&h * k, &l * k)
    } else {
        (&l * k, &h * k)
    }
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
    values_at(&alpha.poly(), std::slice::from_ref(alpha), num, den).pop()?
}

/// [`value_at`] for several roots of the same square-free polynomial `phi`:
/// the value polynomial is computed and isolated once.
pub fn values_at(
    phi: &ZPoly,
    alphas: &[RealAlg],
    num: &QPoly,
    den: &QPoly,
) -> Vec<Option<RealAlg>> {
    values_inner(phi, alphas, num, den, None)
}

/// [`values_at`] when a square-free polynomial `values` vanishing at every
/// `num(α)/den(α)` (α a root of `phi`) is already known, e.g. a minimal
/// polynomial from a quotient algebra.  The values are identified by
/// interval evaluation against its isolated roots, as in [`values_at`].
pub fn values_with(
    phi: &ZPoly,
    alphas: &[RealAlg],
    num: &QPoly,
    den: &QPoly,
    values: &ZPoly,
) -> Vec<Option<RealAlg>> {
    values_inner(phi, alphas, num, den, Some(values))
}

fn values_inner(
    phi: &ZPoly,
    alphas: &[RealAlg],
    num: &QPoly,
    den: &QPoly,
    known: Option<&ZPoly>,
) -> Vec<Option<RealAlg>> {
    let mut r: Option<(ZPoly, Vec<RootInterval>)> = None;
    let mut zs: Option<((ZPoly, Q), (ZPoly, Q))> = None;
    alphas
        .iter()
        .map(|alpha| {
            if alpha.sign_of_q(den) == 0 {
                return None;
            }
            if let Some(a) = alpha.as_rational() {
                return Some(RealAlg::Rational(eval_q(num, a) / eval_q(den, a)));
            }
            let (rp, ivs) = r.get_or_insert_with(|| {
                let rp = match known {
                    Some(v) => v.clone(),
                    None => value_polynomial(phi, num, den),
                };
                let ivs = isolate_squarefree(&rp);
                (rp, ivs)
            });
            let mut a = alpha.clone();
            let (nzq, dzq) = zs.get_or_insert_with(|| (ZPoly::from_q(num), ZPoly::from_q(den)));
            loop {
                if let Some(x) = a.as_rational() {
                    let x = x.clone();
                    return Some(RealAlg::Rational(eval_q(num, &x) / eval_q(den, &x)));
                }
                let (lo, hi) = a.interval();
                if let Some((vl, vh)) = ratio_enclosure(nzq, dzq, &lo, &hi) {
                    let hits: Vec<usize> = (0..ivs.len())
                        .filter(|&j| meets(&ivs[j], &vl, &vh))
                        .collect();
                    if hits.len() == 1 {
                        return Some(RealAlg::from_interval(rp, &ivs[hits[0]]).simplify());
                    }
                    for j in hits {
                        bisect_once(rp, &mut ivs[j]);
                    }
                }
                // shrink α geometrically (16 bits per round)
                let w = (&hi - &lo) / Q::from_integer(num_bigint::BigInt::from(1u32 << 16));
                a.refine_to(&w);
            }
        })
        .collect()
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
