//! Sturm sequences: exact counts of distinct real roots in any interval.
//!
//! For a square-free `p`, the sequence `p0 = p, p1 = p', p_{i+1} =
//! -rem(p_{i-1}, p_i)` (each term may be scaled by a positive constant, so
//! it is computed with primitive pseudo-remainders over Z) satisfies
//! `#{roots in (a, b]} = V(a) - V(b)` where `V` counts sign variations
//! (zeros dropped).  The half-open form holds at roots too because a
//! square-free `p` changes sign at each root.

use crate::number::Q;
use crate::poly::ZPoly;
use num_bigint::BigInt;
use num_traits::Signed;
#[cfg(test)]
use num_traits::Zero;

/// The Sturm sequence of the square-free part of a polynomial.
#[derive(Clone, Debug)]
pub struct SturmSequence {
    seq: Vec<ZPoly>,
}

/// A point of the extended real line where a Sturm sequence is evaluated.
#[derive(Clone, Debug)]
pub enum Point {
    /// −∞.
    NegInf,
    /// A rational number (only the tests count roots in bounded intervals).
    #[cfg_attr(not(test), allow(dead_code))]
    At(Q),
    /// +∞.
    PosInf,
}

impl SturmSequence {
    /// Builds the sequence for the square-free part of `p` (non-constant or
    /// constant; the zero polynomial gives an empty sequence).
    pub fn new(p: &ZPoly) -> SturmSequence {
        if p.is_zero() {
            return SturmSequence { seq: vec![] };
        }
        let p0 = p.squarefree_part();
        let p1 = p0.derivative();
        if p1.is_zero() {
            return SturmSequence { seq: vec![p0] };
        }
        // Subresultant PRS (exact divisions, no contents) with the signs
        // tracked so that each stored term is a positive multiple of the
        // Sturm remainder −rem(T_{i−1}, T_i):
        //   raw_{i+1} = prem(raw_{i−1}, raw_i)/d,  prem = lc(raw_i)^(δ+1)·rem,
        //   so −rem = −raw_{i+1}·d/lc(raw_i)^(δ+1) and the sign of T_{i+1}
        //   is −s_{i−1}·sign(d)·sign(lc raw_i)^(δ+1).
        let mut seq = vec![p0.clone(), p1.clone()];
        let (mut a, mut b) = (p0, p1);
        let (mut s_prev, mut s_cur) = (1i32, 1i32);
        let mut g = BigInt::from(1);
        let mut h = BigInt::from(1);
        while b.degree().unwrap_or(0) > 0 {
            let delta = a.degree().unwrap_or(0) - b.degree().unwrap_or(0);
            let r = a.pseudo_rem(&b);
            if r.is_zero() {
                break;
            }
            let divisor = &g * num_traits::pow(h.clone(), delta);
            let raw = r.div_exact_scalar(&divisor).unwrap_or(r);
            let lb_neg = b.lc().is_negative() && (delta + 1) % 2 == 1;
            let mut s_next = -s_prev;
            if divisor.is_negative() {
                s_next = -s_next;
            }
            if lb_neg {
                s_next = -s_next;
            }
            seq.push(if s_next > 0 { raw.clone() } else { -&raw });
            g = b.lc();
            h = match delta {
                0 => h,
                1 => g.clone(),
                _ => num_traits::pow(g.clone(), delta) / num_traits::pow(h, delta - 1),
            };
            a = b;
            b = raw;
            s_prev = s_cur;
            s_cur = s_next;
        }
        SturmSequence { seq }
    }

    /// Number of sign variations at a point.
    pub fn variations(&self, x: &Point) -> usize {
        let mut last = 0i32;
        let mut v = 0;
        for p in &self.seq {
            let s = match x {
                Point::At(q) => p.sign_at(q),
                Point::PosInf => sign_lc(p, false),
                Point::NegInf => sign_lc(p, true),
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

    /// Number of distinct real roots in `(a, b]` (`a < b`).
    pub fn count_in(&self, a: &Point, b: &Point) -> usize {
        self.variations(a).saturating_sub(self.variations(b))
    }

    /// Number of distinct real roots.
    pub fn count_all(&self) -> usize {
        self.count_in(&Point::NegInf, &Point::PosInf)
    }

    /// Number of distinct positive roots (in `(0, ∞)`).
    #[cfg(test)]
    pub fn count_positive(&self) -> usize {
        self.count_in(&Point::At(Q::zero()), &Point::PosInf)
    }

    /// Number of distinct negative roots (in `(−∞, 0)`).
    #[cfg(test)]
    pub fn count_negative(&self) -> usize {
        let c = self.count_in(&Point::NegInf, &Point::At(Q::zero()));
        if self.has_root_at_zero() { c - 1 } else { c }
    }

    /// True when 0 is a root.
    #[cfg(test)]
    pub fn has_root_at_zero(&self) -> bool {
        self.seq
            .first()
            .is_some_and(|p| p.coeffs().first().is_some_and(|c| c.is_zero()))
    }
}

fn sign_lc(p: &ZPoly, at_neg_inf: bool) -> i32 {
    let lc: BigInt = p.lc();
    let s = if lc.is_positive() {
        1
    } else if lc.is_negative() {
        -1
    } else {
        0
    };
    if at_neg_inf && p.degree().unwrap_or(0) % 2 == 1 {
        -s
    } else {
        s
    }
}

/// Number of distinct real roots of `p` in `(a, b]`, by a Sturm sequence.
#[cfg(test)]
pub fn count_real_roots_in(p: &ZPoly, a: &Q, b: &Q) -> usize {
    SturmSequence::new(p).count_in(&Point::At(a.clone()), &Point::At(b.clone()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    #[test]
    fn counts() {
        // (x-1)(x-2)(x+3)(x^2+1)
        let p = &(&ZPoly::from_i64s(&[-1, 1]) * &ZPoly::from_i64s(&[-2, 1]))
            * &(&ZPoly::from_i64s(&[3, 1]) * &ZPoly::from_i64s(&[1, 0, 1]));
        let s = SturmSequence::new(&p);
        assert_eq!(s.count_all(), 3);
        assert_eq!(s.count_positive(), 2);
        assert_eq!(s.count_negative(), 1);
        assert_eq!(s.count_in(&Point::At(q(1, 1)), &Point::At(q(2, 1))), 1);
        assert_eq!(s.count_in(&Point::At(q(0, 1)), &Point::At(q(1, 1))), 1);
        let z = SturmSequence::new(&ZPoly::from_i64s(&[0, -2, 0, 1]));
        assert_eq!(
            (z.count_positive(), z.count_negative(), z.has_root_at_zero()),
            (1, 1, true)
        );
        // negative leading coefficients and a multiple root
        let m = ZPoly::from_i64s(&[0, 0, 1, -1]).scale(&BigInt::from(-3)); // -3x^2(1-x)... 
        let sm = SturmSequence::new(&m);
        assert_eq!(sm.count_all(), 2);
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_count_real_roots_in() {
        use crate::number::q;
        use crate::poly::ZPoly;
        use crate::roots::count_real_roots_in;
        let p = ZPoly::from_i64s(&[0, -2, 0, 1]); // x^3 - 2x
        assert_eq!(count_real_roots_in(&p, &q(-2, 1), &q(0, 1)), 2); // -√2 and 0
    }
}
