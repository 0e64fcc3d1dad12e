//! Real roots of an integer polynomial of small degree isolated from
//! numerical roots, certified by inclusion discs: a filter in front of the
//! exact isolation (square-free part, Descartes, refinement), which it
//! replaces whenever the roots are simple and not clustered.
//!
//! **Key idea** (Weierstrass corrections, Gerschgorin's theorem; Braess and
//! Hadeler 1973, Carstensen 1991).  Let `p` have degree `n`, leading
//! coefficient `c`, and let `x_1, …, x_n` be distinct complex numbers.  With
//! `W_i = p(x_i) / (c ∏_{j≠i} (x_i − x_j))`, Lagrange interpolation gives
//! `p(λ)/c = ∏(λ − x_j) + Σ_i W_i ∏_{j≠i}(λ − x_j)`, the characteristic
//! polynomial of the matrix `diag(x) − W·1ᵀ`.  Gerschgorin's discs of its
//! rows, `D(x_i − W_i, (n−1)|W_i|)`, lie in `D(x_i, n|W_i|)`: every root of
//! `p` lies in the union of the discs `D_i = D(x_i, ρ_i)` for any
//! `ρ_i ≥ n|W_i|`, and a disc disjoint from the others holds exactly one
//! root (the continuity argument of Gerschgorin's theorem, unchanged by
//! enlarging the discs).  When the discs are pairwise disjoint:
//!
//! * `p` has `n` distinct roots (it is square-free);
//! * a disc with a real centre holds a real root: its one root `ζ` has its
//!   conjugate `ζ̄` (a root of the real `p`) in the same disc;
//! * a disc that misses the real axis holds a non-real root.
//!
//! So the real roots are isolated, exactly counted and ordered by the real
//! centres.  With `ρ_i ≥ 2n|W_i|` the root lies in the inner half of its
//! disc, so the ends `x_i ± ρ_i` of the isolating interval are not roots.
//!
//! The `x_i` come from Aberth's iteration in doubles on the polynomial
//! scaled to roots of magnitude near 1 (no proof needed there); the proof
//! is in [`XBall`] arithmetic (extended exponents, every rounding in the
//! radius) on the integer coefficients at the exact dyadic `x_i`, and
//! every comparison is a certified sign.  Anything uncertain (a multiple
//! or clustered root, a near-real pair, a range beyond the doubles) gives
//! `None`, and the caller isolates exactly.

use super::isolate::RootInterval;
use crate::number::xball::{XBall, floor_log2, top};
use crate::number::{Q, Z};
use crate::poly::ZPoly;
use num_traits::{Signed, Zero};

/// The highest degree the filter takes (Aberth's iteration and the `n²`
/// pairwise checks stay cheap; the curve topology needs 4).
const MAX_DEGREE: usize = 8;

/// A complex double.
#[derive(Clone, Copy, Debug)]
struct C {
    re: f64,
    im: f64,
}

impl C {
    fn add(self, o: C) -> C {
        C {
            re: self.re + o.re,
            im: self.im + o.im,
        }
    }
    fn sub(self, o: C) -> C {
        C {
            re: self.re - o.re,
            im: self.im - o.im,
        }
    }
    fn mul(self, o: C) -> C {
        C {
            re: self.re * o.re - self.im * o.im,
            im: self.re * o.im + self.im * o.re,
        }
    }
    fn div(self, o: C) -> C {
        let d = o.re * o.re + o.im * o.im;
        C {
            re: (self.re * o.re + self.im * o.im) / d,
            im: (self.im * o.re - self.re * o.im) / d,
        }
    }
    /// `max(|re|, |im|)`: a norm within √2 of the modulus, enough for
    /// the iteration's stopping test and the near-real test
    fn abs(self) -> f64 {
        self.re.abs().max(self.im.abs())
    }
}

/// The isolating intervals of all real roots of `p`, increasing, each
/// holding exactly one root in its open interior and none at its ends,
/// excluding 0 and at most `2^-bits` of the root's magnitude wide — when
/// the inclusion discs prove them (module docs); `None` otherwise
/// (including a degree below 2 or above [`MAX_DEGREE`]).
pub(crate) fn isolate_by_inclusion(p: &ZPoly, bits: u32) -> Option<Vec<RootInterval>> {
    let n = p.degree()?;
    if !(2..=MAX_DEGREE).contains(&n) {
        return None;
    }
    let cs = p.coeffs();
    let (k, monic) = scaled_monic(cs)?;
    let z = aberth(&monic)?;
    // real approximations snapped to the axis (a true real root is then a
    // real centre; a near-real pair fails the disjointness below)
    let z: Vec<C> = z
        .into_iter()
        .map(|w| {
            if w.im.abs() <= 1e-9 * w.abs() {
                C { re: w.re, im: 0.0 }
            } else {
                w
            }
        })
        .collect();
    certify(cs, &z, k, bits)
}

/// `p(2^k y) / (c·2^{kn})` as a monic polynomial in doubles (ascending, the
/// leading 1 omitted), with `k` chosen so that its roots have magnitude
/// near 1 (Fujiwara's bound); `None` when the coefficients' range does not
/// fit the doubles or `p` is a monomial.
fn scaled_monic(cs: &[Z]) -> Option<(i64, Vec<f64>)> {
    let n = cs.len() - 1;
    // |c_j| ≈ t_j · 2^{s_j}
    let parts: Vec<Option<(f64, i64)>> = cs
        .iter()
        .map(|c| {
            (!c.is_zero()).then(|| {
                let (t, s, _) = top(c);
                (if c.is_negative() { -t } else { t }, s)
            })
        })
        .collect();
    let (tn, sn) = parts[n]?;
    let log2 = |t: f64, s: i64| t.abs().log2() + s as f64;
    let ln = log2(tn, sn);
    let k = (0..n)
        .filter_map(|j| parts[j].map(|(t, s)| (log2(t, s) - ln) / (n - j) as f64))
        .fold(f64::NEG_INFINITY, f64::max);
    if !k.is_finite() {
        return None; // c·x^n: a multiple root at 0
    }
    let k = k.ceil() as i64;
    let monic = (0..n)
        .map(|j| match parts[j] {
            None => Some(0.0),
            Some((t, s)) => {
                let e = s - sn + k * (j as i64 - n as i64);
                if e < -1000 {
                    Some(0.0) // negligible for the numerical roots
                } else if e > 1000 {
                    None
                } else {
                    Some(t / tn * 2f64.powi(e as i32))
                }
            }
        })
        .collect::<Option<Vec<f64>>>()?;
    Some((k, monic))
}

/// The roots of the monic `y^n + Σ b_j y^j` by Aberth's iteration (no
/// guarantee: the discs prove or reject them).
fn aberth(b: &[f64]) -> Option<Vec<C>> {
    let n = b.len();
    let eval = |y: C| -> (C, C) {
        // value and derivative by Horner
        let mut v = C { re: 1.0, im: 0.0 };
        let mut d = C { re: 0.0, im: 0.0 };
        for &c in b.iter().rev() {
            d = d.mul(y).add(v);
            v = v.mul(y).add(C { re: c, im: 0.0 });
        }
        (v, d)
    };
    let mut z: Vec<C> = (0..n)
        .map(|i| {
            let a = 0.4 + std::f64::consts::TAU * i as f64 / n as f64;
            C {
                re: a.cos(),
                im: a.sin(),
            }
        })
        .collect();
    // stopped when converged, or after three slow steps in a row (linear
    // convergence: a multiple root or a cluster, which the discs reject)
    let (mut prev, mut slow) = (f64::INFINITY, 0);
    for it in 0..80 {
        let mut moved = 0.0f64;
        for i in 0..n {
            let (v, d) = eval(z[i]);
            if v.re == 0.0 && v.im == 0.0 {
                continue;
            }
            let w = v.div(d);
            let mut s = C { re: 0.0, im: 0.0 };
            for (j, zj) in z.iter().enumerate() {
                if j != i {
                    s = s.add(C { re: 1.0, im: 0.0 }.div(z[i].sub(*zj)));
                }
            }
            let step = w.div(C { re: 1.0, im: 0.0 }.sub(w.mul(s)));
            if !(step.re.is_finite() && step.im.is_finite()) {
                return None;
            }
            z[i] = z[i].sub(step);
            moved = moved.max(step.abs() / z[i].abs().max(1e-300));
        }
        if moved < 1e-15 {
            break;
        }
        slow = if it >= 10 && moved > 0.5 * prev {
            slow + 1
        } else {
            0
        };
        if slow >= 3 {
            break;
        }
        prev = moved;
    }
    Some(z)
}

/// An exact ball of the dyadic `v·2^k`.
fn exact(v: f64, k: i64) -> XBall {
    XBall { m: v, r: 0.0, e: k }
}

/// The smallest `t` with `2^t ≥` every point of the ball (`None` when it
/// is not finite).
fn log2_ceil_upper(b: &XBall) -> Option<i64> {
    let v = (b.m.abs() + b.r) * (1.0 + 1.0 / 281_474_976_710_656.0);
    if !v.is_finite() || v <= 0.0 {
        return None;
    }
    // v = f·2^x with f in [0.5, 1): v ≤ 2^x
    let bits = v.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let x = if biased == 0 {
        -1021 // subnormal: below 2^-1022
    } else {
        biased - 1022
    };
    Some(x + b.e)
}

/// `2^t` as an exact ball.
fn pow2_ball(t: i64) -> XBall {
    XBall {
        m: 1.0,
        r: 0.0,
        e: t,
    }
}

/// `|a − b|²` for complex balls given by their parts.
fn dist2(a: (&XBall, &XBall), b: (&XBall, &XBall)) -> XBall {
    let (dr, di) = (a.0.sub(b.0), a.1.sub(b.1));
    dr.mul(&dr).add(&di.mul(&di))
}

/// The proof (module docs) for the numerical roots `z` of the scaled
/// polynomial (`x = z·2^k`): the isolating intervals of the real roots
/// (each `2^-bits` of its root narrow), or `None`.
fn certify(cs: &[Z], z: &[C], k: i64, bits: u32) -> Option<Vec<RootInterval>> {
    let n = z.len();
    let coef: Vec<XBall> = cs.iter().map(XBall::from_z).collect();
    let xs: Vec<(XBall, XBall)> = z.iter().map(|w| (exact(w.re, k), exact(w.im, k))).collect();
    let lc2 = coef[n].mul(&coef[n]);
    // |x_i − x_j|², once per pair
    let mut gaps = vec![XBall::zero(); n * n];
    for i in 0..n {
        for j in i + 1..n {
            let g = dist2((&xs[i].0, &xs[i].1), (&xs[j].0, &xs[j].1));
            gaps[i * n + j] = g;
            gaps[j * n + i] = g;
        }
    }
    // t_i with 2^{t_i} ≥ 2n|W_i|
    let mut t = Vec::with_capacity(n);
    for i in 0..n {
        let (xr, xi) = &xs[i];
        // |p(x_i)|² by Horner (real or complex)
        let p2 = if z[i].im == 0.0 {
            let mut acc = coef[n];
            for c in coef[..n].iter().rev() {
                acc = acc.mul(xr).add(c);
            }
            acc.mul(&acc)
        } else {
            let (mut ar, mut ai) = (coef[n], XBall::zero());
            for c in coef[..n].iter().rev() {
                let nr = ar.mul(xr).sub(&ai.mul(xi)).add(c);
                ai = ar.mul(xi).add(&ai.mul(xr));
                ar = nr;
            }
            ar.mul(&ar).add(&ai.mul(&ai))
        };
        // |c ∏_{j≠i}(x_i − x_j)|², bounded away from 0
        let mut d2 = lc2;
        for j in (0..n).filter(|&j| j != i) {
            d2 = d2.mul(&gaps[i * n + j]);
        }
        let inv = d2.recip()?;
        // (2n)²|W_i|² ≤ 2^{2t}
        let w2 = p2.mul(&inv).mul(&exact((4 * n * n) as f64, 0));
        let e = log2_ceil_upper(&w2)?;
        let mut ti = (e + 1).div_euclid(2);
        if z[i].im == 0.0 && z[i].re != 0.0 {
            // a real disc enlarged to 2^-(bits+4) of its centre when the
            // bound is smaller (an exact dyadic root, a tiny correction):
            // shorter interval ends, the same proof
            ti = ti.max(floor_log2(z[i].re) + k - i64::from(bits) - 4);
        }
        t.push(ti);
    }
    // pairwise disjoint discs: |x_i − x_j|² > (2^{t_i} + 2^{t_j})²
    for i in 0..n {
        for j in i + 1..n {
            let s = pow2_ball(t[i]).add(&pow2_ball(t[j]));
            if gaps[i * n + j].sub(&s.mul(&s)).sign() != Some(1) {
                return None;
            }
        }
    }
    let mut out = Vec::new();
    for i in 0..n {
        if z[i].im == 0.0 {
            // the root ζ is within 2^{t_i − 1} of x_i; with
            // |x_i| ≥ 2^{t_i + bits + 2} the interval x_i ± 2^{t_i} excludes
            // 0 and its width 2^{t_i + 1} is at most 2^-bits·|ζ|
            if z[i].re == 0.0 || floor_log2(z[i].re) + k < t[i] + i64::from(bits) + 2 {
                return None;
            }
            out.push(i);
        } else if xs[i].1.mul(&xs[i].1).sub(&pow2_ball(2 * t[i])).sign() != Some(1) {
            // a non-real centre whose disc reaches the real axis
            return None;
        }
    }
    out.sort_by(|&a, &b| z[a].re.total_cmp(&z[b].re));
    Some(
        out.into_iter()
            .map(|i| RootInterval {
                lo: dyadic_sum(z[i].re, k, -1, t[i]),
                hi: dyadic_sum(z[i].re, k, 1, t[i]),
            })
            .collect(),
    )
}

/// `v·2^k + sign·2^t` exactly, in integers (no gcd: only powers of two
/// can cancel).
fn dyadic_sum(v: f64, k: i64, sign: i32, t: i64) -> Q {
    let (neg, m, e) = crate::number::double_parts(v);
    let ex = e + k;
    let s = ex.min(t);
    let mut x = Z::from(m) << (ex - s) as usize;
    if neg {
        x = -x;
    }
    let r = Z::from(1) << (t - s) as usize;
    let n = if sign < 0 { x - r } else { x + r };
    if s >= 0 {
        Q::from_integer(n << s as usize)
    } else {
        crate::number::dyadic(n, (-s) as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::roots::isolate_squarefree;

    fn check(p: &ZPoly) -> Option<Vec<RootInterval>> {
        let got = isolate_by_inclusion(p, 40)?;
        let exact = isolate_squarefree(&p.squarefree_part());
        assert_eq!(got.len(), exact.len(), "{p:?}");
        for (g, e) in got.iter().zip(&exact) {
            // each interval holds exactly that root: the exact one's
            // interval meets it, and p changes sign across it
            assert!(g.lo < g.hi);
            assert!(p.sign_at(&g.lo) * p.sign_at(&g.hi) < 0, "{p:?}");
            assert!(g.lo < e.hi && e.lo < g.hi, "{p:?}");
        }
        Some(got)
    }

    #[test]
    fn simple_roots_are_isolated() {
        // (x − 1)(x + 2)(x² + 1): two real roots, a complex pair
        let p = &(&ZPoly::from_i64s(&[-1, 1]) * &ZPoly::from_i64s(&[2, 1]))
            * &ZPoly::from_i64s(&[1, 0, 1]);
        assert_eq!(check(&p).unwrap().len(), 2);
        // four real roots, huge coefficients
        let big = Z::from(10).pow(300u32);
        let p = ZPoly::new(vec![
            big.clone() * -6,
            big.clone() * 11,
            big.clone() * -6,
            big.clone(),
        ]);
        assert_eq!(check(&p).unwrap().len(), 3);
        // no real root
        let p = ZPoly::from_i64s(&[5, 0, 3, 0, 1]);
        assert_eq!(check(&p).unwrap().len(), 0);
        // roots of very different sizes: 10^-40 and 10^40
        let s = Z::from(10).pow(40u32);
        let p = ZPoly::new(vec![Z::from(1), -(&s * &s + Z::from(1)), s.clone()]);
        assert_eq!(check(&p).unwrap().len(), 2);
    }

    #[test]
    fn multiple_and_clustered_roots_are_declined() {
        // (x − 1)²(x + 3)
        let p = &(&ZPoly::from_i64s(&[-1, 1]) * &ZPoly::from_i64s(&[-1, 1]))
            * &ZPoly::from_i64s(&[3, 1]);
        assert!(isolate_by_inclusion(&p, 40).is_none());
        // x⁴: one root of multiplicity 4
        assert!(isolate_by_inclusion(&ZPoly::from_i64s(&[0, 0, 0, 0, 1]), 40).is_none());
        // a pair 2^-200 apart is declined or isolated correctly
        let e = Z::from(1) << 200usize;
        let p =
            &ZPoly::new(vec![-(&e), e.clone()]) * &ZPoly::new(vec![-(&e + Z::from(1)), e.clone()]);
        let _ = check(&p);
    }
}

#[cfg(test)]
mod props {
    use super::*;
    use crate::roots::isolate_squarefree;
    use proptest::prelude::*;

    /// A product of linear factors `a·x − b` and quadratic factors
    /// `x² + c·x + e` with integer coefficients scaled by `2^shift`.
    fn product(lin: &[(i64, i64)], quad: &[(i64, i64)], shift: usize) -> ZPoly {
        let mut p = ZPoly::new(vec![Z::from(1) << shift]);
        for &(a, b) in lin {
            p = &p * &ZPoly::from_i64s(&[-b, a]);
        }
        for &(c, e) in quad {
            p = &p * &ZPoly::from_i64s(&[e, c, 1]);
        }
        p
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]
        /// Whatever the filter returns is right: as many intervals as real
        /// roots, each with a sign change of `p`, meeting the exact
        /// isolating interval of the same root, narrow and away from 0.
        #[test]
        fn certified_intervals_hold_the_roots(
            lin in proptest::collection::vec((1i64..40, -60i64..60), 0..4),
            quad in proptest::collection::vec((-20i64..20, -30i64..30), 0..2),
            shift in 0usize..400,
        ) {
            let p = product(&lin, &quad, shift);
            prop_assume!(p.degree().unwrap_or(0) >= 2);
            if let Some(got) = isolate_by_inclusion(&p, 40) {
                let exact = isolate_squarefree(&p.squarefree_part());
                prop_assert_eq!(got.len(), exact.len());
                for (g, e) in got.iter().zip(&exact) {
                    prop_assert!(p.sign_at(&g.lo) * p.sign_at(&g.hi) < 0);
                    prop_assert!(g.lo < e.hi && e.lo < g.hi);
                    prop_assert!(g.lo.is_positive() || g.hi.is_negative());
                    let w = &g.hi - &g.lo;
                    let m = if g.lo.is_positive() { g.lo.clone() } else { -g.hi.clone() };
                    prop_assert!(w * Q::from_integer(Z::from(1) << 40usize) <= m);
                }
            }
        }
    }
}
