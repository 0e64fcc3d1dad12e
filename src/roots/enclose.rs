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
use crate::number::{Q, dyadic_floor};
use crate::poly::mpoly::{MPoly, T, U};
use crate::poly::{QPoly, ZPoly};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// An unreduced rational `n / d` with `d > 0`: enclosures are built from
/// products and sums only, and reduced (or rounded) once at the end.
#[derive(Clone, Debug)]
struct Frac(BigInt, BigInt);

impl Frac {
    fn of(q: &Q) -> Frac {
        Frac(q.numer().clone(), q.denom().clone())
    }
    fn add(&self, o: &Frac) -> Frac {
        if self.1 == o.1 {
            return Frac(&self.0 + &o.0, self.1.clone());
        }
        Frac(&self.0 * &o.1 + &o.0 * &self.1, &self.1 * &o.1)
    }
    fn neg(&self) -> Frac {
        Frac(-&self.0, self.1.clone())
    }
    fn mul(&self, o: &Frac) -> Frac {
        Frac(&self.0 * &o.0, &self.1 * &o.1)
    }
    /// `self / o` for `o != 0`.
    fn div(&self, o: &Frac) -> Frac {
        let (n, d) = (&self.0 * &o.1, &self.1 * &o.0);
        if d.is_negative() {
            Frac(-n, -d)
        } else {
            Frac(n, d)
        }
    }
    fn cmp(&self, o: &Frac) -> std::cmp::Ordering {
        (&self.0 * &o.1).cmp(&(&o.0 * &self.1))
    }
    fn sign(&self) -> i32 {
        crate::number::sign_z(&self.0)
    }
}

/// The mean-value enclosure of `p` on `[a, b]` as (centre, radius):
/// `p(x) ∈ p(m) ± r·Σ i|pᵢ|Rⁱ⁻¹` with `m` the midpoint, `r = (b − a)/2` and
/// `R = 2^e ≥ max(|a|, |b|)`.
fn mean_value_ball(p: &ZPoly, a: &Q, b: &Q) -> (Frac, Frac) {
    let (an, ad, bn, bd) = (a.numer(), a.denom(), b.numer(), b.denom());
    let md: BigInt = ad * bd * 2;
    let mn = an * bd + bn * ad;
    let rn = bn * ad - an * bd;
    let (cn, cd) = p.eval_homogeneous(&mn, &md);
    let big = if a.abs() > b.abs() { a.abs() } else { b.abs() };
    let e = if big.is_zero() {
        0
    } else {
        crate::number::floor_log2_q(&big) + 1
    };
    // Σ i|p_i| 2^(e(i−1)) = bound / 2^sh, in integers
    let deg = p.degree().unwrap_or(0) as i64;
    let sh = if e < 0 {
        (-e * (deg - 1).max(0)) as usize
    } else {
        0
    };
    let mut bound = BigInt::zero();
    for (i, pi) in p.coeffs().iter().enumerate().skip(1) {
        if !pi.is_zero() {
            let k = (e * (i as i64 - 1) + sh as i64) as usize;
            bound += (pi.abs() * BigInt::from(i)) << k;
        }
    }
    (Frac(cn, cd), Frac(bound * rn, md << sh))
}

/// Rounds `[lo, hi]` outward to dyadic rationals a little finer than its
/// width (2⁻²⁴ of it), so the endpoints stay small; exact when `lo = hi`.
fn round_outward(lo: &Frac, hi: &Frac) -> (Q, Q) {
    let w = hi.add(&lo.neg());
    if w.0.is_zero() {
        let v = Q::new(lo.0.clone(), lo.1.clone());
        return (v.clone(), v);
    }
    let prec = (24 + w.1.bits() as i64 - w.0.bits() as i64).max(0) as usize;
    let fl = dyadic_floor(&lo.0, &lo.1, prec);
    let ce = -dyadic_floor(&-&hi.0, &hi.1, prec);
    (fl, ce)
}

/// An enclosure of `p(x)` for all `x ∈ [a, b]` by the mean-value form
/// around the midpoint `m`: `p(x) ∈ p(m) ± r·Σ i|pᵢ|Rⁱ⁻¹` with `r = (b − a)/2`
/// and `R = 2^e ≥ max(|a|, |b|)`.  One exact evaluation and one integer sum
/// (no gcd: the endpoints are rounded outward to dyadic rationals), much
/// cheaper than interval Horner, and as tight as the interval shrinks.
#[cfg(test)]
pub fn enclose_mean_value(p: &ZPoly, a: &Q, b: &Q) -> (Q, Q) {
    let (c, r) = mean_value_ball(p, a, b);
    round_outward(&c.add(&r.neg()), &c.add(&r))
}

/// `k·P` enclosed on `[a, b]` as unreduced endpoints (low, high).
fn scaled_ends(p: &(ZPoly, Q), a: &Q, b: &Q) -> (Frac, Frac) {
    let (c, r) = if p.0.degree().unwrap_or(0) == 0 {
        (
            Frac(p.0.coeff(0), BigInt::one()),
            Frac(BigInt::zero(), BigInt::one()),
        )
    } else {
        mean_value_ball(&p.0, a, b)
    };
    let k = Frac::of(&p.1);
    let (l, h) = (c.add(&r.neg()).mul(&k), c.add(&r).mul(&k));
    if k.sign() < 0 { (h, l) } else { (l, h) }
}

/// [`eval_ratio_interval`] with numerator and denominator already written
/// as `k·P` with `P` integer (see [`ZPoly::from_q`]).
pub fn ratio_enclosure(num: &(ZPoly, Q), den: &(ZPoly, Q), a: &Q, b: &Q) -> Option<(Q, Q)> {
    let (nl, nh) = scaled_ends(num, a, b);
    let (dl, dh) = scaled_ends(den, a, b);
    if dl.sign() <= 0 && dh.sign() >= 0 {
        return None;
    }
    let c = [nl.div(&dl), nl.div(&dh), nh.div(&dl), nh.div(&dh)];
    let mut lo = &c[0];
    let mut hi = &c[0];
    for v in &c[1..] {
        if v.cmp(lo).is_lt() {
            lo = v;
        }
        if v.cmp(hi).is_gt() {
            hi = v;
        }
    }
    Some(round_outward(lo, hi))
}

pub(crate) fn meets(iv: &RootInterval, lo: &Q, hi: &Q) -> bool {
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
    if phi.degree() == Some(1) {
        // one rational root r: the value polynomial is den(r)·u − num(r)
        let r = Q::new(-phi.coeff(0), phi.coeff(1));
        let (d, n) = (eval_q(den, &r), eval_q(num, &r));
        if !d.is_zero() {
            return ZPoly::from_q(&QPoly::new(vec![-n, d])).0;
        }
    }
    if !num.is_zero() && !den.is_zero() {
        let (nz, kn) = ZPoly::from_q(num);
        let (dz, kd) = ZPoly::from_q(den);
        let sigma = kn / kd;
        if let Some(r) = crate::elim::value_resultant(phi, &nz, &dz, sigma.numer(), sigma.denom()) {
            return r.primitive_part().squarefree_part();
        }
    }
    value_polynomial_bivariate(phi, num, den)
}

/// [`value_polynomial`] by the general bivariate resultant.
fn value_polynomial_bivariate(phi: &ZPoly, num: &QPoly, den: &QPoly) -> ZPoly {
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
    values_inner(phi, alphas, num, den, None, true)
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
    values_inner(phi, alphas, num, den, Some(values), true)
}

/// [`values_with`] without [`RealAlg::simplify`]: an irrational α whose
/// value happens to be rational keeps the isolating interval of `values`
/// (exact either way; simplifying refines to up to 2048 bits when the
/// rational-root sieve of `values` fails, which costs more than the
/// identification on high-degree `values`).
pub fn values_with_unsimplified(
    phi: &ZPoly,
    alphas: &[RealAlg],
    num: &QPoly,
    den: &QPoly,
    values: &ZPoly,
) -> Vec<Option<RealAlg>> {
    values_inner(phi, alphas, num, den, Some(values), false)
}

fn values_inner(
    phi: &ZPoly,
    alphas: &[RealAlg],
    num: &QPoly,
    den: &QPoly,
    known: Option<&ZPoly>,
    simplify: bool,
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
                return Some(RealAlg::rational(eval_q(num, a) / eval_q(den, a)));
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
                    return Some(RealAlg::rational(eval_q(num, &x) / eval_q(den, &x)));
                }
                let (lo, hi) = a.interval();
                if let Some((vl, vh)) = ratio_enclosure(nzq, dzq, &lo, &hi) {
                    let hits: Vec<usize> = (0..ivs.len())
                        .filter(|&j| meets(&ivs[j], &vl, &vh))
                        .collect();
                    if hits.len() == 1 {
                        let v = RealAlg::from_interval(rp, &ivs[hits[0]]);
                        return Some(if simplify { v.simplify() } else { v });
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
    use crate::poly::ring::Ring;
    let mut acc = Q::zero();
    for c in p.coeffs().iter().rev() {
        // acc grows to deg·bits(x) bits: a step on large numbers reads the
        // clock and takes the ring's operations (no binary gcd); fuzzing
        // found a degree-2391 surface spending 0.13 s natively (3.3 s under
        // the sanitizer) here past its deadline
        crate::budget::check_for(acc.bit_size());
        acc = acc.rmul(x).radd(c);
    }
    acc
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_value_at() {
        use crate::number::qi;
        use crate::poly::{QPoly, ZPoly};
        use crate::roots::{RealAlg, value_at};
        // α = √2, value α² + 1 = 3
        let a = RealAlg::roots_of(&ZPoly::from_i64s(&[-2, 0, 1]))[1].clone();
        let num = QPoly::new(vec![qi(1), qi(0), qi(1)]);
        let v = value_at(&a, &num, &QPoly::constant(qi(1))).unwrap();
        assert_eq!(v.as_rational(), Some(&qi(3)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    fn zp(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    fn qp(c: &[(i64, i64)]) -> QPoly {
        QPoly::new(c.iter().map(|&(n, d)| q(n, d)).collect())
    }

    /// The Poisson formula modulo primes and the general bivariate
    /// resultant give the same value polynomial, including repeated values
    /// (a smaller square-free part), big coefficients, a constant
    /// denominator and numerators of every degree up to deg φ − 1.
    #[test]
    fn poisson_value_polynomial_agrees_with_the_bivariate_resultant() {
        let big: BigInt = num_traits::pow(BigInt::from(3u8), 90) + 7;
        let mut phi_big = zp(&[-5, 0, 3, 1, 0, 2]);
        phi_big = &phi_big + &ZPoly::new(vec![big.clone()]);
        let cases: Vec<(ZPoly, QPoly, QPoly)> = vec![
            (zp(&[-2, 0, 1]), qp(&[(1, 1), (0, 1)]), qp(&[(1, 1)])),
            (
                zp(&[-2, 0, 1]),
                qp(&[(0, 1), (0, 1), (1, 1)]),
                qp(&[(1, 1)]),
            ),
            (
                zp(&[1, -3, 0, 1]),
                qp(&[(1, 2), (-2, 3), (5, 7)]),
                qp(&[(3, 1), (1, 1)]),
            ),
            (
                zp(&[-1, 0, 0, 0, 1]),
                qp(&[(0, 1), (0, 1), (1, 1)]),
                qp(&[(1, 1)]),
            ),
            (
                zp(&[7, 1, -4, 0, 9, 2, 1]),
                qp(&[(-1, 5), (2, 1), (0, 1), (3, 4)]),
                qp(&[(2, 3), (0, 1), (1, 1)]),
            ),
            (
                phi_big,
                qp(&[(1, 1), (-1, 1), (1, 3), (0, 1), (2, 1)]),
                qp(&[(-3, 2), (1, 1)]),
            ),
        ];
        for (phi, num, den) in cases {
            let (nz, kn) = ZPoly::from_q(&num);
            let (dz, kd) = ZPoly::from_q(&den);
            let s = kn / kd;
            let fast = crate::elim::value_resultant(&phi, &nz, &dz, s.numer(), s.denom())
                .expect("den is invertible modulo φ");
            let general = value_polynomial_bivariate(&phi, &num, &den);
            assert_eq!(fast.primitive_part().squarefree_part(), general, "{phi:?}");
            assert_eq!(value_polynomial(&phi, &num, &den), general);
        }
    }

    /// A denominator vanishing at a root of φ: Res(φ, den) = 0 modulo
    /// every prime, so the general resultant answers.
    #[test]
    fn a_denominator_vanishing_at_a_root_declines_the_poisson_formula() {
        let phi = zp(&[-2, -1, 1]); // roots 2 and −1
        let num = qp(&[(1, 1), (1, 1)]);
        let den = qp(&[(-2, 1), (1, 1)]); // zero at 2
        let (nz, _) = ZPoly::from_q(&num);
        let (dz, _) = ZPoly::from_q(&den);
        let one = BigInt::one();
        assert!(crate::elim::value_resultant(&phi, &nz, &dz, &one, &one).is_none());
        assert_eq!(
            value_polynomial(&phi, &num, &den),
            value_polynomial_bivariate(&phi, &num, &den)
        );
    }
}
