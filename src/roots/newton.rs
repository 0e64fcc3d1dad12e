//! Refinement of an isolating interval with dyadic ends: bisection with
//! verified Newton steps, in integer arithmetic.
//!
//! Each round evaluates p and p' at the midpoint `m/2^k` (one Horner pass
//! over the integers `2^{kn} p(m/2^k)` and `2^{k(n−1)} p'(m/2^k)`).  The
//! sign of p there halves the interval, as plain bisection would.  The
//! Newton point `x_N = m/2^k − p/p'`, rounded to a grid `t·2^e` finer than
//! the interval by `g` bits (g doubling on success: quadratic convergence,
//! whatever the root's magnitude), is then
//! *verified*: when p has the sign of the left end at `(t − 1)·2^e` and the
//! opposite sign at `(t + 1)·2^e`, both inside the interval, the unique root
//! lies between them and the interval shrinks to width `2^{e+1}` at once.
//! A failed check costs two sign evaluations and changes nothing, so the
//! result is an isolating interval as bisection's, only reached in far
//! fewer rounds (about log₂(bits) instead of bits).
//!
//! Before the first round, a safeguarded Newton iteration in doubles (on
//! the coefficients scaled by a common power of two) proposes the root to
//! about 2^-48 of its magnitude; the proposal is checked the same way (two
//! exact signs, both points inside the bracket) and skipped when the check
//! fails, so it only saves rounds.

use super::isolate::{DyadicBracket, Halved};
use crate::number::{Q, sign_z};
use crate::poly::ZPoly;
use crate::poly::zpoly::DyadicSigner;
use crate::roots::RootInterval;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Zero;

/// `(2^{kn} p(m/2^k), 2^{k(n−1)} p'(m/2^k))` for `n = deg p`: the
/// homogenised `P(m, h) = Σ cᵢ mⁱ h^{n−i}` (h = 2^k) and `∂P/∂m`, by one
/// Horner pass (`d ← d·m + v`, then `v ← v·m + c_j h^{n−j}`).
fn eval_with_derivative(p: &ZPoly, m: &BigInt, k: u64) -> (BigInt, BigInt) {
    let c = p.coeffs();
    let n = c.len() - 1;
    let mut v = c[n].clone();
    let mut dv = BigInt::zero();
    crate::budget::check();
    for j in (0..n).rev() {
        if n > crate::poly::zpoly::SHORT {
            crate::budget::check();
        }
        dv = &dv * m + &v;
        v *= m;
        if !c[j].is_zero() {
            v += &c[j] << (k as usize * (n - j));
        }
    }
    (v, dv)
}

/// The exact sign of p at `m/2^km` and a pair `(v, dv)` with
/// `v/(dv·2^km) ≈ p/p′` there, as [`eval_with_derivative`]'s exact
/// `(2^{km·n} p, 2^{km(n−1)} p′)` would give.  When those exact numbers
/// would be long, the pair comes from a floating Horner pass
/// ([`DyadicSigner::float_value`]) keeping enough bits for a Newton point on the grid
/// `2^e`: the Newton point is only a proposal, which the caller verifies
/// by exact signs.  That pass's value decides the sign when it exceeds its
/// error bound; otherwise the signer does, exactly.
fn newton_values(
    p: &ZPoly,
    signs: &DyadicSigner,
    m: &BigInt,
    km: u64,
    e: i64,
) -> (i32, BigInt, BigInt) {
    let n = p.degree().unwrap_or(0) as u64;
    let prec = km.max((-e).max(0) as u64) + 128 + u64::from(64 - n.leading_zeros());
    let fv = (n >= crate::poly::horner::FLOAT_MIN_DEGREE
        && prec.saturating_mul(2) <= n.saturating_mul(m.bits().max(km)))
    .then(|| signs.float_value(m, km, prec, true))
    .flatten();
    let Some(fv) = fv else {
        let (v, dv) = eval_with_derivative(p, m, km);
        return (sign_z(&v), v, dv);
    };
    let sign = fv.sign().unwrap_or_else(|| signs.sign_at_past(m, km, prec));
    // v/dv = 2^km·(a·2^f)/(d·2^fd)
    let sh = fv.f - fv.fd + km as i64;
    let (v, dv) = if sh >= 0 {
        (fv.a << sh as usize, fv.d)
    } else {
        (fv.a, fv.d << (-sh) as usize)
    };
    (sign, v, dv)
}

/// A proposal for the root of `p` in the bracket `br` (`s_lo`: the sign
/// of p at its lower end): `(t, e)` with the root expected in
/// `[(t − 1)·2^e, (t + 1)·2^e]`, from Newton's iteration in doubles on the
/// coefficients scaled by a common power of two, kept inside the bracket
/// (a step leaving it, or not shrinking, bisects by the doubles' sign).
/// `e` is the finer of `e_min` and 2^-48 of the proposal's magnitude.
/// Only a proposal: the caller checks it by exact signs.  `None` where
/// doubles cannot represent the problem (roots or scaled values outside
/// ±2^200, a zero derivative) or the iteration does not settle.
fn float_proposal(p: &ZPoly, br: &DyadicBracket, s_lo: i32, e_min: i64) -> Option<(BigInt, i64)> {
    use crate::number::xball::{pow2, top};
    use num_traits::Signed;
    let c = p.coeffs();
    // the leading 64 bits of z as a double, and their power of two
    let lead = |z: &BigInt| {
        let (t, sh, _) = top(z);
        (if z.is_negative() { -t } else { t }, sh)
    };
    // coefficients scaled to at most 2^400 (tiny ones flush to 0: a
    // proposal need not be exact)
    let shift = c.iter().map(|x| x.bits()).max()? as i64 - 400;
    let cf: Vec<f64> = c
        .iter()
        .map(|x| {
            if x.is_zero() {
                return 0.0;
            }
            let (v, sh) = lead(x);
            if sh - shift < -1000 {
                0.0
            } else {
                v * pow2(sh - shift)
            }
        })
        .collect();
    let dy = |m: &BigInt| -> Option<f64> {
        if m.is_zero() {
            return Some(0.0);
        }
        if (m.bits() as i64 - br.k as i64).abs() > 200 {
            return None;
        }
        let (v, sh) = lead(m);
        Some(v * pow2(sh - br.k as i64))
    };
    let (mut lo, mut hi) = (dy(&br.a)?, dy(&br.b)?);
    let eval = |x: f64| -> (f64, f64) {
        let (mut v, mut d) = (0.0f64, 0.0f64);
        for &ci in cf.iter().rev() {
            d = d * x + v;
            v = v * x + ci;
        }
        (v, d)
    };
    let mut x = 0.5 * (lo + hi);
    let mut converged = false;
    for _ in 0..80 {
        let (v, d) = eval(x);
        if !v.is_finite() || !d.is_finite() {
            return None;
        }
        if v == 0.0 {
            converged = true;
            break;
        }
        // the doubles' sign narrows the bracket (a guess near the root)
        if (v > 0.0) == (s_lo > 0) {
            lo = x;
        } else {
            hi = x;
        }
        let mut nx = if d != 0.0 { x - v / d } else { f64::NAN };
        if !(nx > lo && nx < hi) {
            nx = 0.5 * (lo + hi);
        }
        if (nx - x).abs() <= 4.0 * f64::EPSILON * nx.abs().max(f64::MIN_POSITIVE) {
            x = nx;
            converged = true;
            break;
        }
        x = nx;
    }
    if !converged || x == 0.0 || !x.is_finite() {
        return None;
    }
    // the grid: 2^-48 of |x|, or the asked width's if that is coarser
    // (the binary exponent read from the bits: the same on every platform)
    let e = ((x.abs().to_bits() >> 52) as i64 - 1023 - 48).max(e_min);
    if !(-1000..=1000).contains(&e) {
        return None;
    }
    let t = (x * pow2(-e)).round();
    if !t.is_finite() || t.abs() > 2f64.powi(62) {
        return None;
    }
    Some((BigInt::from(t as i64), e))
}

/// What the exact signs say of a candidate bracket.
enum Candidate {
    /// An end of the candidate is the root.
    Root(Q),
    /// The root lies in this narrower bracket.
    Narrower(DyadicBracket),
    /// Not confirmed (or not inside the bracket): nothing learnt.
    Rejected,
}

/// Checks the candidate `[(t − 1)·2^e, (t + 1)·2^e]` against the bracket
/// `br` (whose lower end has the sign `s_lo`) by the exact signs of p at
/// the candidate's ends, both over the common power of two `2^kc`.  With
/// `clamp`, an end outside `br` is replaced by `br`'s own (its sign is
/// known), so one end inside suffices; without, both must lie inside.
fn check_candidate(
    signs: &DyadicSigner,
    br: &DyadicBracket,
    s_lo: i32,
    t: &BigInt,
    e: i64,
    clamp: bool,
) -> Candidate {
    let kk = (-e).max(0) as u64;
    let kc = br.k.max(kk);
    let up = e.max(0) as usize + (kc - kk) as usize;
    let (tl, th) = ((t - 1) << up, (t + 1) << up);
    let (a, b) = (&br.a << (kc - br.k) as usize, &br.b << (kc - br.k) as usize);
    let (lo_in, hi_in) = (tl > a, th < b);
    let inside = if clamp {
        (lo_in || hi_in) && tl < b && th > a
    } else {
        lo_in && hi_in
    };
    if !inside {
        return Candidate::Rejected;
    }
    let sl = if lo_in { signs.sign_at(&tl, kc) } else { s_lo };
    let sr = if hi_in { signs.sign_at(&th, kc) } else { -s_lo };
    if sl == 0 || sr == 0 {
        let root = if sl == 0 { tl } else { th };
        return Candidate::Root(crate::number::dyadic(root, kc as usize));
    }
    if sl == s_lo && sr == -s_lo {
        Candidate::Narrower(DyadicBracket {
            a: if lo_in { tl } else { a },
            b: if hi_in { th } else { b },
            k: kc,
        })
    } else {
        Candidate::Rejected
    }
}

/// Refines the bracket `br` around a simple root of `p` (`s_lo` = sign of p
/// at its lower end, non-zero) until its width is at most `width`; sets
/// `iv` to the result (an exact root if one is hit).
///
/// The Newton bracket is sized relative to the current width, not to an
/// absolute grid: with the width about `2^L`, the Newton point is rounded
/// to multiples of `2^e`, `e = L − g`, and bracketed by its neighbours.  The
/// gain `g` doubles on success (quadratic convergence) and halves on
/// failure (Abbott's quadratic interval refinement), so roots of any
/// magnitude (e.g. 2^300 for the values of a big-coefficient S) converge in
/// about log₂(bits) rounds.
pub(crate) fn refine_dyadic_newton(
    p: &ZPoly,
    signs: &DyadicSigner,
    iv: &mut RootInterval,
    mut br: DyadicBracket,
    s_lo: i32,
    width: &Q,
) {
    let (wn, wd) = (width.numer(), width.denom());
    // the finest grid needed: 2^(e_min + 1) ≤ wn/wd
    let e_min = wn.bits() as i64 - wd.bits() as i64 - 2;
    // `gain`: bits asked of the next Newton step; `wait`: rounds of plain
    // bisection before the next attempt (doubles on failure), so a failing
    // Newton costs a bounded fraction of the work
    // a bracket already narrow against its ends' magnitude (`known` bits,
    // e.g. a root isolated earlier to 2^-64 and now printed) starts from a
    // gain of that many bits, which Newton's quadratic step gives near a
    // simple root; a wide one from 4
    let known = br.a.bits().max(br.b.bits()) as i64 - (&br.b - &br.a).bits() as i64;
    let (mut gain, mut wait, mut backoff) = (known.clamp(4, 1 << 20), 0u32, 1u32);
    let exact = |iv: &mut RootInterval, x: Q| {
        *iv = RootInterval {
            lo: x.clone(),
            hi: x,
        };
    };
    // a first proposal from a safeguarded Newton iteration in doubles: a
    // well-conditioned root is then known to ≈ 2^-48 of its magnitude after
    // two exact signs instead of a round of exact evaluations per doubling
    // of the bits; a proposal that fails its check costs those two signs
    if let Some((t, e)) = float_proposal(p, &br, s_lo, e_min) {
        match check_candidate(signs, &br, s_lo, &t, e, false) {
            Candidate::Root(r) => return exact(iv, r),
            Candidate::Narrower(nb) => {
                br = nb;
                gain = gain.max(48);
            }
            Candidate::Rejected => {}
        }
    }
    while (&br.b - &br.a) * wd > (wn << br.k as usize) {
        if wait > 0 {
            wait -= 1;
            if let Halved::Root(r) = br.halve(signs, s_lo) {
                return exact(iv, r);
            }
            continue;
        }
        // one Horner pass gives the midpoint's sign (bisection) and p'
        let m: BigInt = &br.a + &br.b;
        let km = br.k + 1;
        // the grid the Newton point will be rounded to, from the width
        // before halving (at most one bit coarser than after)
        let l0 = (&br.b - &br.a).bits() as i64 - br.k as i64;
        let (sign, v, dv) = newton_values(p, signs, &m, km, (l0 - 1 - gain).max(e_min));
        if let Halved::Root(r) = br.halve_at(m.clone(), sign, s_lo) {
            return exact(iv, r);
        }
        if dv.is_zero() {
            continue;
        }
        // the width is in (2^(l−1), 2^l]; Newton's point rounded to the
        // grid 2^e, bracketed by its two neighbours on that grid
        let l = (&br.b - &br.a).bits() as i64 - br.k as i64;
        let e = (l - gain).max(e_min);
        if e >= l - 1 {
            continue;
        }
        // x_N = (m·dv − v) / (dv·2^km); t = ⌊x_N / 2^e⌋
        let num = &m * &dv - &v;
        let sh = km as i64 + e;
        let t = if sh >= 0 {
            num.div_floor(&(&dv << sh as usize))
        } else {
            (num << (-sh) as usize).div_floor(&dv)
        };
        match check_candidate(signs, &br, s_lo, &t, e, true) {
            Candidate::Root(r) => return exact(iv, r),
            Candidate::Narrower(nb) => {
                br = nb;
                gain = (gain * 2).min(1 << 20);
                backoff = 1;
            }
            Candidate::Rejected => {
                gain = (gain / 2).max(2);
                wait = backoff;
                backoff = (backoff * 2).min(8);
            }
        }
    }
    *iv = br.interval();
}

#[cfg(test)]
mod tests {
    use crate::number::Q;
    use crate::poly::ZPoly;
    use crate::roots::{isolate_real_roots, refine};
    use num_bigint::BigInt;

    /// Refines each isolating interval of `p` to width `w` and checks that
    /// the result still holds its root (a sign change, or the exact root).
    fn refine_all_and_check(p: &ZPoly, roots: Vec<crate::roots::RootInterval>, w: &Q) {
        for mut iv in roots {
            refine(p, &mut iv, w);
            if iv.is_exact() {
                assert_eq!(p.sign_at(&iv.lo), 0);
                continue;
            }
            assert!(&(&iv.hi - &iv.lo) <= w);
            assert!(p.sign_at(&iv.lo) * p.sign_at(&iv.hi) < 0);
        }
    }

    /// Roots of magnitude 2^300 (the values of a big-coefficient S) are
    /// refined to relative precision in a few Newton rounds: a sign change
    /// remains, and the width is as asked.
    #[test]
    fn huge_roots_refine_relative() {
        // (x − 3·2^300)(x − (3·2^300 + 2^280))(x + 5·2^299)(x² + 2^600)
        let a = BigInt::from(3) << 300usize;
        let b = &a + (BigInt::from(1) << 280usize);
        let c = -(BigInt::from(5) << 299usize);
        let lin = |r: &BigInt| ZPoly::new(vec![-r.clone(), BigInt::from(1)]);
        let quad = ZPoly::new(vec![
            BigInt::from(1) << 600usize,
            BigInt::from(0),
            BigInt::from(1),
        ]);
        let p = &(&(&lin(&a) * &lin(&b)) * &lin(&c)) * &quad;
        let roots = isolate_real_roots(&p);
        assert_eq!(roots.len(), 3);
        // 2^-100 relative to 2^300: width 2^200
        let w = Q::from_integer(BigInt::from(1) << 200usize);
        refine_all_and_check(&p, roots, &w);
    }

    /// A bracket already refined to 2^-40 (or 2^-64) and refined again
    /// starts Newton with a gain of as many bits as it holds: the sign change
    /// and the asked width survive, also where that first step must fail
    /// (a cluster of roots 2^-40 apart, which a 40-bit gain overshoots).
    #[test]
    fn narrow_brackets_refine_again() {
        // (x − 1/3)(x² − 2)(x − (1 + 2^-40))(x − 1)(x − (1 − 2^-40))
        let cluster = |c: i64| {
            let one = BigInt::from(1) << 40usize;
            ZPoly::new(vec![-(&one + c), one])
        };
        let p = &(&(&(&ZPoly::from_i64s(&[-1, 3]) * &ZPoly::from_i64s(&[-2, 0, 1])) * &cluster(1))
            * &ZPoly::from_i64s(&[-1, 1]))
            * &cluster(-1);
        let width = |bits: usize| Q::new(BigInt::from(1), BigInt::from(1) << bits);
        let roots = isolate_real_roots(&p);
        assert_eq!(roots.len(), 6);
        for first in [40usize, 64] {
            for mut iv in roots.clone() {
                for bits in [first, 100, 200] {
                    refine(&p, &mut iv, &width(bits));
                    if iv.is_exact() {
                        assert_eq!(p.sign_at(&iv.lo), 0);
                        break;
                    }
                    assert!(&iv.hi - &iv.lo <= width(bits));
                    assert!(p.sign_at(&iv.lo) * p.sign_at(&iv.hi) < 0);
                }
            }
        }
    }

    /// The doubles' proposal: for a well-conditioned root it lands on the
    /// root (the bracket it proposes holds √2 and is 2^-47 wide); on a
    /// cluster closer than doubles resolve it may propose anything, and the
    /// refinement still ends with one sign change (the exact check decides).
    #[test]
    fn float_proposal_is_checked() {
        use super::{DyadicBracket, float_proposal};
        let p = ZPoly::from_i64s(&[-2, 0, 1]);
        let br = DyadicBracket {
            a: BigInt::from(1),
            b: BigInt::from(2),
            k: 0,
        };
        let (t, e) = float_proposal(&p, &br, -1, -200).expect("a proposal");
        assert_eq!(e, -48);
        let lo = Q::new(&t - 1, BigInt::from(1) << 48usize);
        let hi = Q::new(&t + 1, BigInt::from(1) << 48usize);
        assert!(p.sign_at(&lo) < 0 && p.sign_at(&hi) > 0);
        // x(x − 1)(x − (1 + 2^-60)): roots 2^-60 apart
        let one: BigInt = BigInt::from(1) << 60usize;
        let p = &(&ZPoly::from_i64s(&[0, 1]) * &ZPoly::from_i64s(&[-1, 1]))
            * &ZPoly::new(vec![-(&one + 1u32), one]);
        let w = Q::new(BigInt::from(1), BigInt::from(1) << 100usize);
        let roots = isolate_real_roots(&p);
        assert_eq!(roots.len(), 3);
        refine_all_and_check(&p, roots, &w);
    }

    proptest::proptest! {
        /// Products of linear factors with random integer roots (some
        /// repeated as near-clusters `r` and `r + 1/2^s`) and an irreducible
        /// quadratic: every isolating interval refined to 2^-bits keeps its
        /// root, whichever way (doubles' proposal, exact Newton, bisection).
        #[test]
        fn refinement_keeps_the_root_property(
            roots in proptest::collection::vec(-1000i64..1000, 1..5),
            s in 1usize..80,
            c in 2i64..50,
            bits in 8usize..150,
        ) {
            let scale = BigInt::from(1) << s;
            let mut p = ZPoly::from_i64s(&[-c, 0, 1]);
            for &r in &roots {
                p = &p * &ZPoly::new(vec![-(BigInt::from(r) * &scale) - 1, scale.clone()]);
                p = &p * &ZPoly::from_i64s(&[-r, 1]);
            }
            let p = p.squarefree_part();
            let w = Q::new(BigInt::from(1), BigInt::from(1) << bits);
            for mut iv in isolate_real_roots(&p) {
                refine(&p, &mut iv, &w);
                if iv.is_exact() {
                    proptest::prop_assert_eq!(p.sign_at(&iv.lo), 0);
                    continue;
                }
                proptest::prop_assert!(&iv.hi - &iv.lo <= w);
                proptest::prop_assert!(p.sign_at(&iv.lo) * p.sign_at(&iv.hi) < 0);
            }
        }
    }

    /// Refining every isolating interval to 2^-bits keeps exactly one sign
    /// change (or finds the rational root), for clustered and spread roots.
    #[test]
    fn newton_refinement_keeps_the_root() {
        let polys = [
            ZPoly::from_i64s(&[-2, 0, 1]),
            // (x² − 2)(x − 1/3)(100x² − 1)(x² − 10⁶ x + 1)
            &(&(&ZPoly::from_i64s(&[-2, 0, 1]) * &ZPoly::from_i64s(&[-1, 3]))
                * &ZPoly::from_i64s(&[-1, 0, 100]))
                * &ZPoly::from_i64s(&[1, -1_000_000, 1]),
            // Mignotte-like cluster: x⁶ − 2(1000x − 1)²
            ZPoly::from_i64s(&[-2, 4000, -2_000_000, 0, 0, 0, 1]),
        ];
        for p in &polys {
            for bits in [10usize, 40, 130] {
                let w = Q::new(BigInt::from(1), BigInt::from(1) << bits);
                for mut iv in isolate_real_roots(p) {
                    refine(p, &mut iv, &w);
                    if iv.is_exact() {
                        assert_eq!(p.sign_at(&iv.lo), 0);
                        continue;
                    }
                    assert!(&iv.hi - &iv.lo <= w, "{p:?} at {bits} bits");
                    let (sl, sh) = (p.sign_at(&iv.lo), p.sign_at(&iv.hi));
                    assert!(
                        sl * sh < 0,
                        "{p:?}: no sign change in ({}, {})",
                        iv.lo,
                        iv.hi
                    );
                }
            }
        }
    }
}
