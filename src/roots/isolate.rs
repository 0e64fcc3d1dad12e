//! Real root isolation by Descartes' rule of signs with bisection
//! (Vincent–Collins–Akritas, Taylor-shift form), and refinement.
//!
//! Key idea: the roots of `q` in `(0, 1)` correspond to the positive roots
//! of `(x+1)^n q(1/(x+1))`, whose number is bounded by (and has the parity
//! of) the sign variations of its coefficients.  0 variations: no root; 1:
//! exactly one.  Otherwise split `(0, 1)` at 1/2 with the exact maps
//! `q_L(x) = 2^n q(x/2)` and `q_R(x) = q_L(x+1)`.  All arithmetic is over Z;
//! the interval ends are dyadic rationals, and an exact rational root met at
//! a midpoint is reported exactly (`lo = hi`).

use crate::number::Q;
use crate::poly::ZPoly;
use crate::poly::zpoly::taylor_shift_one;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// An isolating interval: `lo == hi` for an exact rational root; otherwise
/// the open interval `(lo, hi)` contains exactly one root and neither end is
/// a root.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RootInterval {
    /// Lower end.
    pub lo: Q,
    /// Upper end.
    pub hi: Q,
}

impl RootInterval {
    /// True for an exact rational root.
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }
}

/// Number of sign variations of a coefficient sequence (zeros skipped).
pub fn sign_variations(c: &[BigInt]) -> usize {
    let mut last = 0i8;
    let mut v = 0;
    for x in c {
        let s = if x.is_positive() {
            1
        } else if x.is_negative() {
            -1
        } else {
            0
        };
        if s != 0 {
            if last != 0 && s != last {
                v += 1;
            }
            last = s;
        }
    }
    v
}

/// Descartes' bounds: `(var p(x), var p(-x))` after removing the root 0;
/// upper bounds on the numbers of positive and negative roots (counted with
/// multiplicity) with the same parity.
pub fn descartes_bounds(p: &ZPoly) -> (usize, usize) {
    let q = p.strip_zero_roots();
    (
        sign_variations(q.coeffs()),
        sign_variations(q.neg_x().coeffs()),
    )
}

/// Sign variations of `(x+1)^n q(1/(x+1))`, stopping early at 2: returns
/// 0, 1 or 2 (meaning "two or more").  The shift finalises the
/// coefficients from the constant term up, so the count can stop as soon as
/// it reaches two.
fn descartes_unit(q: &[BigInt]) -> usize {
    let mut c: Vec<BigInt> = q.iter().rev().cloned().collect();
    let n = c.len();
    let mut v = 0;
    let mut last = 0i8;
    let mut push = |x: &BigInt, v: &mut usize| {
        let s = if x.is_positive() {
            1
        } else if x.is_negative() {
            -1
        } else {
            0
        };
        if s != 0 {
            if last != 0 && s != last {
                *v += 1;
            }
            last = s;
        }
    };
    for i in 0..n.saturating_sub(1) {
        for j in (i..n - 1).rev() {
            let (lo, hi) = c.split_at_mut(j + 1);
            lo[j] += &hi[0];
        }
        push(&c[i], &mut v);
        if v >= 2 {
            return 2;
        }
    }
    if let Some(x) = c.last() {
        push(x, &mut v);
    }
    v.min(2)
}

/// Divides out the largest common power of two of the coefficients.
fn remove_pow2(c: &mut [BigInt]) {
    let k = c
        .iter()
        .filter(|x| !x.is_zero())
        .map(|x| x.trailing_zeros().unwrap_or(0))
        .min()
        .unwrap_or(0);
    if k > 0 {
        for x in c.iter_mut() {
            *x >>= k as usize;
        }
    }
}

enum Found {
    /// Root in the open interval (c/2^j, (c+1)/2^j); the flags say whether
    /// an end is an exact root found at a midpoint (and needs fixing).
    Open(BigInt, u64, bool),
    /// Exact root c/2^j.
    Exact(BigInt, u64),
}

/// Roots of `q` in `(0, 1)` for a square-free `q` with `q(0) != 0`,
/// `q(1) != 0`, as dyadic intervals.
fn isolate_unit(q: Vec<BigInt>) -> Vec<Found> {
    let mut out = Vec::new();
    // (polynomial, c, j, an end of the interval is a root found earlier)
    let mut stack: Vec<(Vec<BigInt>, BigInt, u64, bool, bool)> =
        vec![(q, BigInt::zero(), 0, false, false)];
    while let Some((poly, c, j, lo_root, hi_root)) = stack.pop() {
        match descartes_unit(&poly) {
            0 => {}
            1 => out.push(Found::Open(c, j, lo_root || hi_root)),
            _ => {
                let n = poly.len() - 1;
                let mut left: Vec<BigInt> =
                    poly.iter().enumerate().map(|(i, x)| x << (n - i)).collect();
                remove_pow2(&mut left);
                let mut right = left.clone();
                taylor_shift_one(&mut right);
                let c2 = &c << 1usize;
                let mid: BigInt = &c2 + 1u32;
                let mid_root = right[0].is_zero();
                if mid_root {
                    out.push(Found::Exact(mid.clone(), j + 1));
                    right.remove(0);
                }
                stack.push((right, mid, j + 1, mid_root, hi_root));
                stack.push((left, c2, j + 1, lo_root, mid_root));
            }
        }
    }
    out
}

fn dyadic(c: &BigInt, j: i64) -> Q {
    // c · 2^j
    if j >= 0 {
        Q::from_integer(c << (j as usize))
    } else {
        crate::number::dyadic(c.clone(), (-j) as usize)
    }
}

/// Isolating intervals of the positive roots of a square-free `p` with
/// `p(0) != 0`, sorted increasingly.
fn isolate_positive(p: &ZPoly) -> Vec<RootInterval> {
    let Some(k) = p.root_bound_log2() else {
        return vec![];
    };
    if sign_variations(p.coeffs()) == 0 {
        return vec![];
    }
    // q(t) ∝ p(2^k t): roots in (0, 1)
    let q = p.scale_roots_pow2(-k);
    let mut c = q.coeffs().to_vec();
    remove_pow2(&mut c);
    let mut found: Vec<(Q, Q, bool)> = isolate_unit(c)
        .into_iter()
        .map(|f| match f {
            Found::Open(c, j, fix) => (
                dyadic(&c, k - j as i64),
                dyadic(&(c + 1), k - j as i64),
                fix,
            ),
            Found::Exact(c, j) => {
                let v = dyadic(&c, k - j as i64);
                (v.clone(), v, false)
            }
        })
        .collect();
    found.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)));
    found
        .into_iter()
        .map(|(lo, hi, fix)| {
            let mut iv = RootInterval { lo, hi };
            if fix && !iv.is_exact() {
                fix_endpoints(p, &mut iv);
            }
            iv
        })
        .collect()
}

/// Makes sure neither end of an isolating interval of the square-free `p`
/// is a root (an end can sit on an exact root found at a midpoint), by
/// bisection; may turn the interval into an exact root.
///
/// Inside `(lo, hi)` there is exactly one simple root `r`; `p` has one sign
/// σ on `(lo, r)` and `-σ` on `(r, hi)`.  σ is read off a non-root end, or
/// off `p'(lo)` when both ends are roots.
fn fix_endpoints(p: &ZPoly, iv: &mut RootInterval) {
    // the ends are dyadic (VCA): bisect in integers, lo = a/2^k, hi = b/2^k
    let (Some(kl), Some(kh)) = (pow2_exponent(iv.lo.denom()), pow2_exponent(iv.hi.denom())) else {
        return fix_endpoints_rational(p, iv);
    };
    let mut k = kl.max(kh);
    let scale = |q: &Q, k: u64| -> BigInt {
        q.numer() << (k - pow2_exponent(q.denom()).unwrap_or(0)) as usize
    };
    let mut a = scale(&iv.lo, k);
    let mut b = scale(&iv.hi, k);
    let mut s_lo = p.sign_at_dyadic(&a, k);
    let mut s_hi = p.sign_at_dyadic(&b, k);
    let mut deriv: Option<i32> = None;
    while s_lo == 0 || s_hi == 0 {
        let sigma = if s_lo != 0 {
            s_lo
        } else if s_hi != 0 {
            -s_hi
        } else {
            *deriv.get_or_insert_with(|| p.derivative().sign_at_dyadic(&a, k))
        };
        let m: BigInt = &a + &b;
        k += 1;
        let s = p.sign_at_dyadic(&m, k);
        if s == 0 {
            let v = crate::number::dyadic(m, k as usize);
            iv.lo = v.clone();
            iv.hi = v;
            return;
        }
        if s == sigma {
            a = m;
            b <<= 1usize;
            s_lo = s;
            if s_hi == 0 {
                deriv = None;
            }
        } else {
            b = m;
            a <<= 1usize;
            s_hi = s;
        }
    }
    let den = BigInt::one() << k as usize;
    iv.lo = Q::new(a, den.clone());
    iv.hi = Q::new(b, den);
}

/// [`fix_endpoints`] for non-dyadic ends.
fn fix_endpoints_rational(p: &ZPoly, iv: &mut RootInterval) {
    let two = Q::from_integer(BigInt::from(2));
    let mut s_lo = p.sign_at(&iv.lo);
    let mut s_hi = p.sign_at(&iv.hi);
    loop {
        if s_lo != 0 && s_hi != 0 {
            return;
        }
        let sigma = if s_lo != 0 {
            s_lo
        } else if s_hi != 0 {
            -s_hi
        } else {
            p.derivative().sign_at(&iv.lo)
        };
        let m = (&iv.lo + &iv.hi) / &two;
        let s = p.sign_at(&m);
        if s == 0 {
            iv.lo = m.clone();
            iv.hi = m;
            return;
        }
        if s == sigma {
            iv.lo = m;
            s_lo = s;
        } else {
            iv.hi = m;
            s_hi = s;
        }
    }
}

/// Isolating intervals of all distinct real roots of `p` (any non-zero
/// integer polynomial; its square-free part is used), sorted and disjoint.
///
/// ```
/// use quadsect::roots::isolate_real_roots;
/// use quadsect::poly::ZPoly;
/// let p = ZPoly::from_i64s(&[0, -2, 0, 1]); // x^3 - 2x
/// let iv = isolate_real_roots(&p);
/// assert_eq!(iv.len(), 3);
/// assert!(iv[1].is_exact()); // the root 0
/// ```
pub fn isolate_real_roots(p: &ZPoly) -> Vec<RootInterval> {
    if p.degree().unwrap_or(0) == 0 {
        return vec![];
    }
    let sq = p.squarefree_part();
    isolate_squarefree(&sq)
}

/// As [`isolate_real_roots`] for a polynomial already known square-free.
pub fn isolate_squarefree(sq: &ZPoly) -> Vec<RootInterval> {
    if sq.degree().unwrap_or(0) == 0 {
        return vec![];
    }
    let has_zero = sq.coeffs()[0].is_zero();
    let core = if has_zero {
        sq.strip_zero_roots()
    } else {
        sq.clone()
    };
    let mut neg: Vec<RootInterval> = isolate_positive(&core.neg_x())
        .into_iter()
        .map(|iv| RootInterval {
            lo: -iv.hi,
            hi: -iv.lo,
        })
        .collect();
    neg.reverse();
    let mut out = neg;
    if has_zero {
        out.push(RootInterval {
            lo: Q::zero(),
            hi: Q::zero(),
        });
    }
    out.extend(isolate_positive(&core));
    if has_zero {
        // intervals of the core may end at 0, a root of `sq`
        for iv in out.iter_mut() {
            if !iv.is_exact() && (iv.lo.is_zero() || iv.hi.is_zero()) {
                fix_endpoints(sq, iv);
            }
        }
    }
    out
}

/// Bisects an isolating interval of the square-free `p` until its width is
/// at most `width` (or the root is found exactly).  Dyadic ends (the usual
/// case: VCA produces them) are bisected in integer arithmetic, without the
/// gcd of every rational operation.
pub fn refine(p: &ZPoly, iv: &mut RootInterval, width: &Q) {
    if iv.is_exact() {
        return;
    }
    if let (Some(kl), Some(kh)) = (pow2_exponent(iv.lo.denom()), pow2_exponent(iv.hi.denom())) {
        refine_dyadic(p, iv, width, kl.max(kh));
        return;
    }
    let two = Q::from_integer(BigInt::from(2));
    let s_lo = p.sign_at(&iv.lo);
    while &(&iv.hi - &iv.lo) > width {
        let m = (&iv.lo + &iv.hi) / &two;
        let s = p.sign_at(&m);
        if s == 0 {
            iv.lo = m.clone();
            iv.hi = m;
            return;
        }
        if s == s_lo {
            iv.lo = m;
        } else {
            iv.hi = m;
        }
    }
}

/// `k` when `d = 2^k`.
fn pow2_exponent(d: &BigInt) -> Option<u64> {
    let k = d.trailing_zeros()?;
    if d.bits() == k + 1 { Some(k) } else { None }
}

fn refine_dyadic(p: &ZPoly, iv: &mut RootInterval, width: &Q, k0: u64) {
    // lo = a/2^k, hi = b/2^k
    let mut k = k0;
    let scale = |q: &Q, k: u64| -> BigInt {
        q.numer() << (k - pow2_exponent(q.denom()).unwrap_or(0)) as usize
    };
    let mut a = scale(&iv.lo, k);
    let mut b = scale(&iv.hi, k);
    let (wn, wd) = (width.numer().clone(), width.denom().clone());
    let s_lo = p.sign_at_dyadic(&a, k);
    // many bits to gain: bisection with verified Newton steps
    let need = ((&b - &a) * &wd).bits() as i64 - (&wn << k as usize).bits() as i64;
    if need > 8 && s_lo != 0 {
        super::newton::refine_dyadic_newton(p, iv, a, b, k, s_lo, width);
        return;
    }
    // (b − a)/2^k > wn/wd  ⇔  (b − a)·wd > wn·2^k
    while (&b - &a) * &wd > (&wn << k as usize) {
        let m: BigInt = &a + &b;
        k += 1;
        let s = p.sign_at_dyadic(&m, k);
        if s == 0 {
            let v = crate::number::dyadic(m, k as usize);
            iv.lo = v.clone();
            iv.hi = v;
            return;
        }
        if s == s_lo {
            a = m;
            b <<= 1usize;
        } else {
            b = m;
            a <<= 1usize;
        }
    }
    let den = BigInt::one() << k as usize;
    iv.lo = Q::new(a, den.clone());
    iv.hi = Q::new(b, den);
}

/// One bisection step of an isolating interval (no-op on exact roots).
pub fn bisect_once(p: &ZPoly, iv: &mut RootInterval) {
    let w = (&iv.hi - &iv.lo) / Q::from_integer(BigInt::from(2));
    refine(p, iv, &w);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    fn check(p: &ZPoly, expect: usize) {
        let iv = isolate_real_roots(p);
        assert_eq!(iv.len(), expect, "{p:?}");
        let sq = p.squarefree_part();
        for w in iv.windows(2) {
            assert!(w[0].hi <= w[1].lo);
        }
        for r in &iv {
            if r.is_exact() {
                assert_eq!(sq.sign_at(&r.lo), 0);
            } else {
                let (a, b) = (sq.sign_at(&r.lo), sq.sign_at(&r.hi));
                assert!(a * b < 0, "no sign change on {r:?}");
            }
        }
    }

    #[test]
    fn isolates() {
        check(&ZPoly::from_i64s(&[0, -2, 0, 1]), 3);
        check(&ZPoly::from_i64s(&[-1, 0, 0, 0, 1]), 2);
        check(&ZPoly::from_i64s(&[1, 0, 1]), 0);
        // roots at dyadic midpoints: (2x-1)(4x-1)(4x-3)(x-1)(x+1/2)
        let p = [[-1, 2], [-1, 4], [-3, 4], [-1, 1], [1, 2]]
            .iter()
            .fold(ZPoly::from_i64s(&[1]), |acc, f| &acc * &ZPoly::from_i64s(f));
        check(&p, 5);
        // ∏ (x - k), k = 1..20
        let w = (1..=20).fold(ZPoly::from_i64s(&[1]), |acc, k| {
            &acc * &ZPoly::from_i64s(&[-k, 1])
        });
        check(&w, 20);
        // close roots: (x - 1/3)(x - 1/3 - 10^-30)
        let big = num_traits::pow(BigInt::from(10), 30);
        let a = ZPoly::new(vec![BigInt::from(-1), BigInt::from(3)]);
        let b = ZPoly::new(vec![-(&big + 3u32), &big * 3u32]);
        check(&(&a * &b), 2);
    }

    #[test]
    fn refinement_narrows() {
        let p = ZPoly::from_i64s(&[-2, 0, 1]);
        let mut iv = isolate_real_roots(&p)[1].clone();
        refine(&p, &mut iv, &q(1, 1_000_000));
        assert!(&iv.hi - &iv.lo <= q(1, 1_000_000));
        assert!(iv.lo < q(1414214, 1000000) && iv.hi > q(1414213, 1000000));
    }
}
