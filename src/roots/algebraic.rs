//! Real algebraic numbers: a square-free integer defining polynomial and an
//! isolating interval, with exact comparison and exact sign of another
//! polynomial at the number (zero detected by a gcd, never by a tolerance).

use super::isolate::{RootInterval, bisect_once, isolate_squarefree, refine, sign_variations};
use crate::number::xball::XBall;
use crate::number::{Q, approx_decimal, floor_log2_q, fmt_q};
use crate::poly::ZPoly;
use crate::poly::mpoly::{MPoly, U};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// An exact real algebraic number: a rational, or the unique root of a
/// square-free integer polynomial in an isolating interval with rational
/// ends.
///
/// Comparison (`==`, `<`, [`Ord`]) is exact: equality is decided by a gcd
/// of the defining polynomials, order by refining the intervals.  Equal
/// numbers hash equally whatever their defining polynomials, so real
/// algebraic numbers can be sorted and used as keys.
///
/// ```
/// use quadsect::{IntPoly, RealAlg, Rational};
/// let r = "u^2 - 2".parse::<IntPoly>().unwrap().real_roots();
/// let sqrt2 = &r[1];
/// assert!(*sqrt2 > RealAlg::from(Rational::new(7.into(), 5.into())));
/// assert_eq!(sqrt2.approx(10), "1.414213562");
/// // the same number from another polynomial and interval
/// let p: IntPoly = "u^4 - 4".parse().unwrap();
/// let other = RealAlg::new(&p, &Rational::from_integer(1.into()), &Rational::from_integer(2.into())).unwrap();
/// assert_eq!(sqrt2, &other);
/// ```
#[derive(Clone)]
pub struct RealAlg {
    repr: Repr,
}

/// The representation: the invariant of `Root` is that `poly` is
/// square-free, primitive, with a positive leading coefficient, and has
/// exactly one root in the open interval `(lo, hi)`, with neither end a
/// root.  (The crate-internal roots of [`RealAlg::roots_narrow`] keep the
/// content of the caller's polynomial — its gcd on numbers of thousands of
/// bits costs more than everything else done with them; every operation
/// but the printing of the polynomial is indifferent to a constant factor,
/// and those numbers are never printed.)
#[derive(Clone, Debug)]
enum Repr {
    Rational(Q),
    Root { poly: ZPoly, lo: Q, hi: Q },
}

impl RealAlg {
    /// A rational value.
    pub fn rational(q: Q) -> RealAlg {
        RealAlg {
            repr: Repr::Rational(q),
        }
    }

    /// The root of the square-free `poly` isolated by `iv`.  An exact
    /// interval gives a rational.
    pub(crate) fn from_interval(poly: &ZPoly, iv: &RootInterval) -> RealAlg {
        Self::from_primitive(&poly.primitive_part(), iv)
    }

    /// [`RealAlg::from_interval`] for a `poly` already primitive with a
    /// positive leading coefficient (e.g. from
    /// [`ZPoly::squarefree_part`]): no content computed again.
    pub(crate) fn from_primitive(poly: &ZPoly, iv: &RootInterval) -> RealAlg {
        debug_assert!(poly.content().is_one() && poly.lc().is_positive());
        if iv.is_exact() {
            RealAlg::rational(iv.lo.clone())
        } else {
            RealAlg {
                repr: Repr::Root {
                    poly: poly.clone(),
                    lo: iv.lo.clone(),
                    hi: iv.hi.clone(),
                },
            }
        }
    }

    /// All real roots of `p` (any non-zero polynomial), increasing.
    pub(crate) fn roots_of(p: &ZPoly) -> Vec<RealAlg> {
        if p.degree().unwrap_or(0) == 0 {
            return vec![];
        }
        let sq = p.squarefree_part();
        isolate_squarefree(&sq)
            .iter()
            .map(|iv| RealAlg::from_primitive(&sq, iv))
            .collect()
    }

    /// All real roots of `p`, increasing, each in an isolating interval
    /// that excludes 0 and is at most `2^-bits` of the root's magnitude
    /// wide (as after [`RealAlg::refine_relative`]).  The inclusion discs
    /// ([`super::inclusion`]) first, which give such intervals directly
    /// (narrow dyadic ones around numerical roots) when they prove the
    /// roots; the exact isolation and refinement otherwise.  The roots are
    /// those of [`RealAlg::roots_of`]; the intervals may differ, and the
    /// defining polynomial may keep `p`'s content (for comparisons and
    /// signs inside the crate, not for printing: [`Repr`]).
    pub(crate) fn roots_narrow(p: &ZPoly, bits: u32) -> Vec<RealAlg> {
        // square-free (n simple roots) with the content kept (type docs)
        let positive = |p: &ZPoly| if p.lc().is_negative() { -p } else { p.clone() };
        let build = |poly: ZPoly, ivs: Vec<RootInterval>| -> Vec<RealAlg> {
            ivs.into_iter()
                .map(|iv| RealAlg {
                    repr: Repr::Root {
                        poly: poly.clone(),
                        lo: iv.lo,
                        hi: iv.hi,
                    },
                })
                .collect()
        };
        if let Some(ivs) = super::inclusion::isolate_by_inclusion(p, bits) {
            return build(positive(p), ivs);
        }
        if p.degree().unwrap_or(0) == 0 {
            return vec![];
        }
        // a multiple root (a tangency): the discs again on the square-free
        // part, else the exact isolation of it
        let sq = p.squarefree_part();
        if sq.degree() < p.degree()
            && let Some(ivs) = super::inclusion::isolate_by_inclusion(&sq, bits)
        {
            return build(sq, ivs);
        }
        let mut roots: Vec<RealAlg> = isolate_squarefree(&sq)
            .iter()
            .map(|iv| RealAlg::from_primitive(&sq, iv))
            .collect();
        for x in roots.iter_mut() {
            x.refine_relative(bits);
        }
        roots
    }

    /// The same number, as a `Rational` when it is a rational of moderate
    /// height (a representation change only: the value is exact either way).
    ///
    /// The simplest rational in a narrow isolating interval is the only
    /// candidate of small height, and one exact evaluation tests it.  The
    /// widths tried are 2^-16, 2^-64 and finally `1/(2 lc²)` (capped at
    /// 2^-2048) — at that width the test is complete, since a rational root
    /// `a/b` has `b | lc` and two such rationals are `1/lc²` apart.  None
    /// of this when a sieve modulo small primes proves that the polynomial,
    /// divided by its power of `u` (the root 0 is told apart by the
    /// interval), has no rational root.
    pub fn simplify(&self) -> RealAlg {
        let Repr::Root { poly, lo, hi } = &self.repr else {
            return self.clone();
        };
        // 0 as a root of `poly` (a factor u^k: the value 0 of a surface on
        // its own zeros) says nothing of the other roots; they are the
        // roots of poly / u^k, sieved on their own
        let k = poly.coeffs().iter().take_while(|c| c.is_zero()).count();
        if k > 0 && lo.is_negative() && hi.is_positive() {
            // the open interval holds exactly one root, and 0 is one
            return RealAlg::rational(Q::zero());
        }
        let rest = ZPoly::new(poly.coeffs()[k..].to_vec());
        if super::rational::no_rational_root_sieve(&rest) {
            return self.clone();
        }
        let l = num_traits::Signed::abs(&poly.lc());
        let complete = 2 * l.bits() + 1;
        let mut c = self.clone();
        for bits in [16u64, 64, complete.min(2048)] {
            c.refine_to(&Q::new(BigInt::one(), BigInt::one() << bits as usize));
            if c.as_rational().is_some() {
                return c;
            }
            if let Repr::Root { poly, lo, hi } = &c.repr {
                let cand = super::rational::simplest_rational_in(lo, hi);
                if poly.sign_at(&cand) == 0 {
                    return RealAlg::rational(cand);
                }
            }
            if bits >= complete {
                break;
            }
        }
        // keep the original (coarser, shorter) interval
        self.clone()
    }

    /// The isolating interval `(lo, hi)` (equal ends for a rational).
    pub fn interval(&self) -> (Q, Q) {
        match &self.repr {
            Repr::Rational(q) => (q.clone(), q.clone()),
            Repr::Root { lo, hi, .. } => (lo.clone(), hi.clone()),
        }
    }

    /// The defining polynomial (`d·u - n` for a rational `n/d`).
    pub fn poly(&self) -> ZPoly {
        match &self.repr {
            Repr::Rational(q) => ZPoly::new(vec![-q.numer().clone(), q.denom().clone()]),
            Repr::Root { poly, .. } => poly.clone(),
        }
    }

    /// The defining polynomial printed in the variable `u`.
    pub fn poly_string(&self) -> String {
        MPoly::from_univariate(&self.poly(), U).to_string_canonical()
    }

    /// True when the value is rational (known exactly).
    pub fn as_rational(&self) -> Option<&Q> {
        match &self.repr {
            Repr::Rational(q) => Some(q),
            _ => None,
        }
    }

    /// Bisects the isolating interval once (a rational stays as it is; a
    /// midpoint that is the root turns the number into a rational).
    pub fn bisect(&mut self) {
        if let Repr::Root { poly, lo, hi } = &mut self.repr {
            let mut iv = RootInterval {
                lo: lo.clone(),
                hi: hi.clone(),
            };
            bisect_once(poly, &mut iv);
            if iv.is_exact() {
                self.repr = Repr::Rational(iv.lo);
            } else {
                *lo = iv.lo;
                *hi = iv.hi;
            }
        }
    }

    /// Narrows the isolating interval to `(a, b)` when `lo < a < b < hi`
    /// and the defining polynomial has non-zero values of opposite signs at
    /// a and b (then `(a, b)` holds the one root of `(lo, hi)`); returns
    /// whether it did.  The caller's guess of where the root is only
    /// decides whether the narrowing happens.
    pub(crate) fn narrow_within(&mut self, a: &Q, b: &Q) -> bool {
        let Repr::Root { poly, lo, hi } = &mut self.repr else {
            return false;
        };
        if !(&*lo < a && a < b && b < &*hi) {
            return false;
        }
        let sa = poly.sign_at(a);
        if sa == 0 || poly.sign_at(b) != -sa {
            return false;
        }
        *lo = a.clone();
        *hi = b.clone();
        true
    }

    /// Refines until the interval is at most `width` wide.
    pub fn refine_to(&mut self, width: &Q) {
        if let Repr::Root { poly, lo, hi } = &mut self.repr {
            let mut iv = RootInterval {
                lo: lo.clone(),
                hi: hi.clone(),
            };
            refine(poly, &mut iv, width);
            if iv.is_exact() {
                self.repr = Repr::Rational(iv.lo);
            } else {
                *lo = iv.lo;
                *hi = iv.hi;
            }
        }
    }

    /// A rational approximation within `2^-bits`.
    pub fn to_rational_approx(&self, bits: u32) -> Q {
        let w = Q::new(BigInt::one(), BigInt::one() << bits as usize);
        let (lo, hi) = self.interval();
        if &hi - &lo <= w {
            // narrow enough already: no copy of the polynomial
            return (lo + hi) / Q::from_integer(BigInt::from(2));
        }
        let mut c = self.clone();
        c.refine_to(&w);
        let (lo, hi) = c.interval();
        (lo + hi) / Q::from_integer(BigInt::from(2))
    }

    /// Decimal approximation with `digits` significant digits, correctly
    /// rounded (to nearest) whenever the isolating interval can be refined
    /// until both its ends round to the same digits — always, except for a
    /// value within 2^-40 of the last digit's unit of a rounding boundary,
    /// where the midpoint of an interval of relative width
    /// 2^-(3.33·digits + 56) is rounded (then the printed digits are within
    /// one unit of the last place).  The precision is relative however close
    /// to 0 the value is: the interval is first moved off 0
    /// (by a lower bound on its nonzero roots).
    pub fn approx(&self, digits: usize) -> String {
        match &self.repr {
            Repr::Rational(q) => approx_decimal(q, digits),
            Repr::Root { .. } => {
                let mut c = self.clone();
                c.approx_in_place(digits)
            }
        }
    }

    /// [`RealAlg::approx`], keeping the refined interval.
    pub(crate) fn approx_in_place(&mut self, digits: usize) -> String {
        self.refine_for_approx(digits);
        for extra in [0u32, 24] {
            if extra > 0 {
                self.refine_relative_to(digits, extra);
            }
            let Repr::Root { lo, hi, .. } = &self.repr else {
                break;
            };
            let (a, b) = (approx_decimal(lo, digits), approx_decimal(hi, digits));
            if a == b {
                return a;
            }
        }
        match &self.repr {
            Repr::Rational(q) => approx_decimal(q, digits),
            Repr::Root { lo, hi, .. } => {
                approx_decimal(&((lo + hi) / Q::from_integer(BigInt::from(2))), digits)
            }
        }
    }

    /// `2^e` as a rational (any sign of `e`).
    fn pow2(e: i64) -> Q {
        if e >= 0 {
            Q::from_integer(BigInt::one() << e as usize)
        } else {
            // 1/2^k is in lowest terms
            Q::new_raw(BigInt::one(), BigInt::one() << (-e) as usize)
        }
    }

    /// Moves the isolating interval off 0: afterwards a non-zero value has
    /// an interval of one sign (`lo > 0` or `hi < 0`), so that its sign and
    /// magnitude show, and a zero value is the rational 0.
    ///
    /// Key idea: every non-zero root of `p = Σ aᵢuⁱ` with `a₀ = p(0) ≠ 0`
    /// satisfies `|u| > |a₀| / (|a₀| + maxᵢ|aᵢ|)` (Cauchy's bound for the
    /// reversed polynomial), so the end at 0 moves to a power of two below
    /// that bound at once; then the exponent is bisected (signs at powers
    /// of two) until the ends are within a factor 4.  Cost: O(log of the
    /// bound's exponent) exact signs.
    pub(crate) fn separate_from_zero(&mut self) {
        let Repr::Root { poly, lo, hi } = &mut self.repr else {
            return;
        };
        if lo.is_positive() || hi.is_negative() {
            return;
        }
        let a0 = poly.coeffs()[0].clone();
        if a0.is_zero() {
            // 0 is a root; an end is never a root, so it is this one
            self.repr = Repr::Rational(Q::zero());
            return;
        }
        // which side of 0 the root lies on
        let positive = if lo.is_zero() {
            true
        } else if hi.is_zero() {
            false
        } else {
            // the root lies between lo and 0 iff the signs at lo and 0 differ
            poly.sign_at(lo) == crate::number::sign_z(&a0)
        };
        let m = poly
            .coeffs()
            .iter()
            .skip(1)
            .map(|c| c.abs())
            .max()
            .unwrap_or_else(BigInt::zero);
        let a0 = a0.abs();
        // |root| > |a0|/(|a0| + m) > 2^-k
        let k = (&a0 + &m).bits() as i64 - a0.bits() as i64 + 1;
        let bound = Self::pow2(-k);
        if positive {
            *lo = bound;
        } else {
            *hi = -bound;
        }
        // bisect the exponent: |root| in (2^e_lo, 2^e_hi)
        let sign = if positive { 1 } else { -1 };
        let s_near = poly.sign_at(if positive { &*lo } else { &*hi });
        loop {
            let (near, far) = if positive {
                (lo.clone(), hi.clone())
            } else {
                (-hi.clone(), -lo.clone())
            };
            let (e_near, e_far) = (floor_log2_q(&near), floor_log2_q(&far) + 1);
            if e_far - e_near <= 2 {
                return;
            }
            let c = Self::pow2((e_near + e_far).div_euclid(2));
            if c <= near || c >= far {
                return;
            }
            let at = if positive { c.clone() } else { -c.clone() };
            let s = poly.sign_at(&at);
            if s == 0 {
                self.repr = Repr::Rational(at);
                return;
            }
            // the root lies between the near end and c iff the signs differ
            let root_near = s != s_near;
            match (root_near, sign) {
                (true, 1) => *hi = at,
                (false, 1) => *lo = at,
                (true, _) => *lo = at,
                (false, _) => *hi = at,
            }
        }
    }

    /// The floor of log₂ of the smaller end's magnitude (the interval must
    /// not contain 0).
    fn low_magnitude(lo: &Q, hi: &Q) -> i64 {
        floor_log2_q(&lo.abs()).min(floor_log2_q(&hi.abs()))
    }

    /// Refines (off 0 first) to a width of `2^-(3.33·digits + 16 + extra)`
    /// relative to the value.
    fn refine_relative_to(&mut self, digits: usize, extra: u32) {
        self.separate_from_zero();
        if let Repr::Root { lo, hi, .. } = &self.repr {
            let e = Self::low_magnitude(lo, hi) - (digits as f64 * 3.33) as i64 - 16 - extra as i64;
            let w = Self::pow2(e);
            if hi.clone() - lo.clone() > w {
                self.refine_to(&w);
            }
        }
    }

    /// Refines the isolating interval in place to a width of about
    /// `2^-bits` relative to the value (off 0 first).
    pub(crate) fn refine_relative(&mut self, bits: u32) {
        self.separate_from_zero();
        if let Repr::Root { lo, hi, .. } = &self.repr {
            let w = Self::pow2(Self::low_magnitude(lo, hi) - bits as i64);
            if hi.clone() - lo.clone() > w {
                self.refine_to(&w);
            }
        }
    }

    /// Refines the isolating interval in place so that later
    /// [`RealAlg::approx`] calls with `digits` digits (on this number or its
    /// clones) need no further refinement, usually: the interval excludes 0
    /// (a non-zero value) and its width is at most `2^-(3.33·digits + 16)`
    /// of the value's magnitude.
    pub(crate) fn refine_for_approx(&mut self, digits: usize) {
        self.refine_relative_to(digits, 0);
    }

    /// Exact sign of the number: -1, 0 or 1.
    pub fn signum(&self) -> i32 {
        self.cmp_rational(&Q::zero()) as i32
    }

    /// Exact comparison with a rational.
    pub fn cmp_rational(&self, r: &Q) -> Ordering {
        match &self.repr {
            Repr::Rational(q) => q.cmp(r),
            Repr::Root { poly, lo, hi } => {
                if r <= lo {
                    return Ordering::Greater;
                }
                if r >= hi {
                    return Ordering::Less;
                }
                let s = poly.sign_at(r);
                if s == 0 {
                    return Ordering::Equal;
                }
                if s == poly.sign_at(lo) {
                    // r lies between lo and the root
                    Ordering::Greater
                } else {
                    Ordering::Less
                }
            }
        }
    }

    /// Exact comparison of two real algebraic numbers.  Equality is decided
    /// by the gcd of the defining polynomials; otherwise the intervals are
    /// refined until they separate.
    pub fn cmp_exact(&self, other: &RealAlg) -> Ordering {
        match (&self.repr, &other.repr) {
            (Repr::Rational(a), Repr::Rational(b)) => a.cmp(b),
            (_, Repr::Rational(b)) => self.cmp_rational(b),
            (Repr::Rational(a), _) => other.cmp_rational(a).reverse(),
            (Repr::Root { poly: pa, .. }, Repr::Root { poly: pb, .. }) => {
                let mut a = self.clone();
                let mut b = other.clone();
                let g = if pa == pb { pa.clone() } else { pa.gcd(pb) };
                let mut equal_checked = false;
                loop {
                    if let Some(x) = a.as_rational() {
                        return b.cmp_rational(x).reverse();
                    }
                    if let Some(x) = b.as_rational() {
                        return a.cmp_rational(x);
                    }
                    let (alo, ahi) = a.interval();
                    let (blo, bhi) = b.interval();
                    // open intervals: a < ahi <= blo < b
                    let le = |x: &Q, y: &Q| crate::number::q_cmp(x, y) != Ordering::Greater;
                    if le(&ahi, &blo) {
                        return Ordering::Less;
                    }
                    if le(&bhi, &alo) {
                        return Ordering::Greater;
                    }
                    if !equal_checked && g.degree().unwrap_or(0) > 0 {
                        equal_checked = true;
                        // intersection J of the two intervals; g has at most one
                        // root there, and it is then both numbers
                        let jlo = if alo > blo { alo.clone() } else { blo.clone() };
                        let jhi = if ahi < bhi { ahi.clone() } else { bhi.clone() };
                        if jlo < jhi && g.sign_at(&jlo) * g.sign_at(&jhi) < 0 {
                            return Ordering::Equal;
                        }
                    }
                    a.bisect();
                    b.bisect();
                }
            }
        }
    }

    /// Exact sign of `q(self)` for an integer polynomial `q`.
    ///
    /// Zero is decided by `gcd(poly, q)` having the root in the interval;
    /// otherwise the interval is refined until `q` has no root in it
    /// (Descartes' test on the interval), and `q` is evaluated at an end.
    pub fn sign_of(&self, q: &ZPoly) -> i32 {
        match &self.repr {
            Repr::Rational(r) => q.sign_at(r),
            Repr::Root { poly, lo, hi } => {
                if q.is_zero() {
                    return 0;
                }
                if q.degree() == Some(0) {
                    return crate::number::sign_z(&q.lc());
                }
                // a filter first: q over the isolating interval in
                // extended-exponent balls, on a few bisections of it (a
                // non-zero sign only; zero is left to the gcd)
                if let Some(s) = Self::sign_by_balls(poly, lo, hi, q) {
                    return s;
                }
                let g = poly.gcd(q);
                if g.degree().unwrap_or(0) > 0 && g.sign_at(lo) * g.sign_at(hi) < 0 {
                    return 0;
                }
                let mut iv = RootInterval {
                    lo: lo.clone(),
                    hi: hi.clone(),
                };
                // narrowed by 1, 2, 4, … 64 bits per round (the Newton
                // steps of `refine` make the long rounds cheap): a root of q
                // near this one is passed in O(log) Descartes tests, not one
                // per bit
                let mut step = 1usize;
                loop {
                    if q.sign_at(&iv.lo) != 0 && !has_root_in_open(q, &iv.lo, &iv.hi) {
                        return q.sign_at(&iv.lo);
                    }
                    if step == 1 {
                        bisect_once(poly, &mut iv);
                    } else {
                        let w = (&iv.hi - &iv.lo) / Q::from_integer(BigInt::one() << step);
                        refine(poly, &mut iv, &w);
                    }
                    step = (step * 2).min(64);
                    if iv.is_exact() {
                        return q.sign_at(&iv.lo);
                    }
                }
            }
        }
    }

    /// The sign of `q` at the root of `poly` in `(lo, hi)` when interval
    /// evaluation proves it non-zero on the interval or on one of up to six
    /// successive halvings of it (each halving decided by an exact sign of
    /// `poly`); `None` otherwise.  Rigorous: [`XBall`] arithmetic.
    fn sign_by_balls(poly: &ZPoly, lo: &Q, hi: &Q, q: &ZPoly) -> Option<i32> {
        let coeffs: Vec<XBall> = q.coeffs().iter().map(XBall::from_z).collect();
        let eval = |lo: &Q, hi: &Q| -> Option<i32> {
            let x = XBall::from_interval(lo, hi);
            let mut acc = *coeffs.last()?;
            for c in coeffs.iter().rev().skip(1) {
                acc = acc.mul(&x).add(c);
            }
            acc.sign().filter(|&s| s != 0)
        };
        if let Some(s) = eval(lo, hi) {
            return Some(s);
        }
        let (mut lo, mut hi) = (lo.clone(), hi.clone());
        let s_lo = poly.sign_at(&lo);
        for _ in 0..6 {
            // the midpoint unreduced (no gcd)
            let mid = Q::new_raw(
                lo.numer() * hi.denom() + hi.numer() * lo.denom(),
                lo.denom() * hi.denom() * 2,
            );
            let sm = poly.sign_at(&mid);
            if sm == 0 {
                return None; // a rational root: the exact path decides
            }
            if sm == s_lo {
                lo = mid;
            } else {
                hi = mid;
            }
            if let Some(s) = eval(&lo, &hi) {
                return Some(s);
            }
        }
        None
    }

    /// Exact sign of `q(self)` for a rational polynomial.
    pub fn sign_of_q(&self, q: &crate::poly::QPoly) -> i32 {
        let (z, k) = ZPoly::from_q(q);
        crate::number::sign_q(&k) * self.sign_of(&z)
    }

    /// The defining polynomial, the interval `[lo, hi]` and 20 digits, as
    /// strings for output: the interval is the one the digits were read
    /// from (it excludes 0 for a non-zero value).
    pub fn describe(&self) -> (String, [String; 2], String) {
        let mut c = self.clone();
        let approx = c.approx_in_place(20);
        let (lo, hi) = c.interval();
        (self.poly_string(), [fmt_q(&lo), fmt_q(&hi)], approx)
    }
}

impl RealAlg {
    /// The root of `poly` in the closed interval `[lo, hi]`, checked: `poly`
    /// must be non-zero and have exactly one distinct real root there
    /// (`lo = hi` asks for the rational `lo`, which must be a root).  The
    /// polynomial need not be square-free: its square-free part is used.
    ///
    /// ```
    /// use quadsect::{IntPoly, RealAlg, Rational, ErrorKind};
    /// let p: IntPoly = "u^2 - 2".parse().unwrap();
    /// let r = |n: i64| Rational::from_integer(n.into());
    /// assert!(RealAlg::new(&p, &r(1), &r(2)).is_ok());
    /// assert_eq!(RealAlg::new(&p, &r(0), &r(1)).unwrap_err().kind(), ErrorKind::Input); // no root
    /// assert!(RealAlg::new(&p, &r(-2), &r(2)).is_err()); // two roots
    /// let sq: IntPoly = "(u^2 - 2)^2".parse().unwrap(); // repeated roots are fine
    /// assert_eq!(RealAlg::new(&sq, &r(1), &r(2)).unwrap().approx(5), "1.4142");
    /// ```
    pub fn new(poly: &crate::poly::IntPoly, lo: &Q, hi: &Q) -> Result<RealAlg, crate::Error> {
        use crate::error::{Error, ErrorKind};
        let p = poly.inner();
        if p.is_zero() {
            return Err(Error::new(
                ErrorKind::ZeroPolynomial,
                "the zero polynomial defines no number",
            ));
        }
        if lo > hi {
            return Err(Error::new(
                ErrorKind::Input,
                format!("the interval [{}, {}] is empty", fmt_q(lo), fmt_q(hi)),
            ));
        }
        if lo == hi {
            return if p.sign_at(lo) == 0 {
                Ok(RealAlg::rational(lo.clone()))
            } else {
                Err(Error::new(
                    ErrorKind::Input,
                    format!("{} is not a root of the polynomial", fmt_q(lo)),
                ))
            };
        }
        let inside: Vec<RealAlg> = RealAlg::roots_of(p)
            .into_iter()
            .filter(|r| {
                r.cmp_rational(lo) != Ordering::Less && r.cmp_rational(hi) != Ordering::Greater
            })
            .collect();
        match inside.len() {
            1 => Ok(inside.into_iter().next().expect("one root")),
            n => Err(Error::new(
                ErrorKind::Input,
                format!(
                    "the polynomial has {n} distinct real roots in [{}, {}]; an isolating interval holds exactly one",
                    fmt_q(lo),
                    fmt_q(hi)
                ),
            )),
        }
    }

    /// The exact sign.
    pub fn sign(&self) -> crate::number::Sign {
        crate::number::Sign::from_i32(self.signum())
    }

    /// The defining polynomial as a public [`crate::IntPoly`] (square-free,
    /// primitive, positive leading coefficient; `d·u − n` for a rational).
    pub fn defining_poly(&self) -> crate::poly::IntPoly {
        crate::poly::IntPoly::from_inner(self.poly())
    }

    /// `floor(2^k · self)`, exactly (used for hashing: equal numbers give
    /// equal values whatever their representation).
    fn floor_scaled(&self, k: usize) -> BigInt {
        let scale = Q::from_integer(BigInt::one() << k);
        let floor = |x: &Q| (x * &scale).floor().to_integer();
        let mut c = self.clone();
        loop {
            let (poly, lo, hi) = match &c.repr {
                Repr::Rational(q) => return floor(q),
                Repr::Root { poly, lo, hi } => (poly, lo, hi),
            };
            let (a, b) = (floor(lo), floor(hi));
            if a == b {
                // k/2^s <= lo < x < hi < (k+1)/2^s
                return a;
            }
            // the grid point just above lo lies in (lo, hi]
            let g = crate::number::dyadic(&a + BigInt::one(), k);
            if &g < hi && poly.sign_at(&g) == 0 {
                return a + BigInt::one();
            }
            c.bisect();
        }
    }
}

impl From<Q> for RealAlg {
    fn from(q: Q) -> RealAlg {
        RealAlg::rational(q)
    }
}

impl From<i64> for RealAlg {
    fn from(n: i64) -> RealAlg {
        RealAlg::rational(Q::from_integer(n.into()))
    }
}

impl PartialEq for RealAlg {
    fn eq(&self, other: &RealAlg) -> bool {
        self.cmp_exact(other) == Ordering::Equal
    }
}

impl Eq for RealAlg {}

impl PartialOrd for RealAlg {
    fn partial_cmp(&self, other: &RealAlg) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for RealAlg {
    /// Exact order (see [`RealAlg::cmp_exact`]).
    fn cmp(&self, other: &RealAlg) -> Ordering {
        self.cmp_exact(other)
    }
}

impl PartialEq<Q> for RealAlg {
    fn eq(&self, other: &Q) -> bool {
        self.cmp_rational(other) == Ordering::Equal
    }
}

impl PartialOrd<Q> for RealAlg {
    fn partial_cmp(&self, other: &Q) -> Option<Ordering> {
        Some(self.cmp_rational(other))
    }
}

impl std::hash::Hash for RealAlg {
    /// Hashes `floor(2^32 · x)`: consistent with the exact equality.
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.floor_scaled(32).hash(state);
    }
}

impl std::fmt::Debug for RealAlg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.repr {
            Repr::Rational(q) => write!(f, "RealAlg({})", fmt_q(q)),
            Repr::Root { poly, lo, hi } => write!(
                f,
                "RealAlg(root of {} in ({}, {}) ≈ {})",
                MPoly::from_univariate(&poly.to_q(), U).to_string_canonical(),
                fmt_q(lo),
                fmt_q(hi),
                self.approx(12)
            ),
        }
    }
}

impl std::fmt::Display for RealAlg {
    /// A rational as `p/q`; otherwise `root of P(u) in (lo, hi) ≈ 1.41421356237`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.repr {
            Repr::Rational(q) => f.write_str(&fmt_q(q)),
            Repr::Root { .. } => {
                let (lo, hi) = self.interval();
                write!(
                    f,
                    "root of {} in ({}, {}) ≈ {}",
                    self.poly_string(),
                    fmt_q(&lo),
                    fmt_q(&hi),
                    self.approx(12)
                )
            }
        }
    }
}

/// Refines the isolating intervals of increasing, distinct real algebraic
/// numbers until consecutive intervals are strictly separated
/// (`hi_i < lo_{i+1}`), so that a rational fits between any two.
pub fn separate(values: &mut [RealAlg]) {
    for i in 0..values.len().saturating_sub(1) {
        loop {
            let (_, hi) = values[i].interval();
            let (lo, _) = values[i + 1].interval();
            if hi < lo {
                break;
            }
            values[i].bisect();
            values[i + 1].bisect();
        }
    }
}

/// True when `q` may have a root in the open interval `(a, b)`: Descartes'
/// test of `q` transformed to `(0, ∞)`; `false` is a proof of no root.
pub fn has_root_in_open(q: &ZPoly, a: &Q, b: &Q) -> bool {
    let n = match q.degree() {
        Some(n) if n > 0 => n,
        _ => return false,
    };
    // x = (a + b t)/(1 + t) maps (0, ∞) to (a, b): with a = a1/d, b = b1/d,
    // (1+t)^n d^n q(x) = Σ c_i (a1 + b1 t)^i (d (1 + t))^(n-i)
    let d = num_integer::Integer::lcm(a.denom(), b.denom());
    let a1 = a.numer() * (&d / a.denom());
    let b1 = b.numer() * (&d / b.denom());
    let lin_ab = ZPoly::new(vec![a1, b1]);
    let lin_d = ZPoly::new(vec![d.clone(), d]);
    let mut pow_ab = vec![ZPoly::constant(BigInt::one())];
    let mut pow_d = vec![ZPoly::constant(BigInt::one())];
    for i in 1..=n {
        pow_ab.push(&pow_ab[i - 1] * &lin_ab);
        pow_d.push(&pow_d[i - 1] * &lin_d);
    }
    let mut acc = ZPoly::zero();
    for (i, c) in q.coeffs().iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        acc = &acc + &(&pow_ab[i] * &pow_d[n - i]).scale(c);
    }
    sign_variations(acc.coeffs()) > 0
}

impl crate::poly::IntPoly {
    /// All distinct real roots, increasing, exactly (Descartes/VCA
    /// isolation of the square-free part: O(n⁴ τ²) bit operations in the
    /// worst case for degree n and τ-bit coefficients, far less in practice).
    pub fn real_roots(&self) -> Vec<RealAlg> {
        RealAlg::roots_of(self.inner())
    }
}

impl crate::number::QSqrt {
    /// The same number as a real algebraic number (a rational, or the root
    /// of `(t − a)² − b²d` on the side of `a` given by the sign of `b`).
    pub fn to_real_alg(&self) -> RealAlg {
        let (a, b, d) = (self.a(), self.b(), self.d());
        if b.is_zero() {
            return RealAlg::rational(a.clone());
        }
        // t² − 2a t + (a² − b²d), cleared of denominators
        let c = [a * a - b * b * d, -(a + a), Q::one()];
        let l = crate::number::denom_lcm(c.iter());
        let z: Vec<BigInt> = c.iter().map(|q| q.numer() * (&l / q.denom())).collect();
        let roots = RealAlg::roots_of(&ZPoly::new(z));
        roots[usize::from(b.is_positive())].clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    /// Narrowing needs both ends inside and a sign change between them.
    #[test]
    fn narrowing_keeps_the_root() {
        let mut s2 = RealAlg::roots_of(&ZPoly::from_i64s(&[-2, 0, 1]))[1].clone();
        let (lo, hi) = s2.interval();
        assert!(lo < q(7, 5) && q(3, 2) < hi, "{lo} {hi}");
        // no sign change on (3/2, 8/5), and (0, 3/2) leaves the interval
        assert!(!s2.narrow_within(&q(3, 2), &q(8, 5)));
        assert!(!s2.narrow_within(&(&lo - &q(1, 8)), &q(3, 2)));
        assert!(s2.narrow_within(&q(7, 5), &q(3, 2)));
        assert_eq!(s2.interval(), (q(7, 5), q(3, 2)));
        assert_eq!(s2.cmp_rational(&q(141, 100)), Ordering::Greater);
        assert_eq!(s2.cmp_rational(&q(142, 100)), Ordering::Less);
    }

    /// A factor u (the value 0) neither hides the other rational roots nor
    /// makes the irrational ones look rational; the root 0 is told apart
    /// by its interval.
    #[test]
    fn simplify_beside_the_root_zero() {
        let u = ZPoly::from_i64s(&[0, 1]);
        let sq2 = ZPoly::from_i64s(&[-2, 0, 1]);
        let sq3 = ZPoly::from_i64s(&[-3, 0, 1]);
        let half = ZPoly::from_i64s(&[-1, 2]);
        // u(u² − 2)(u² − 3): the sieve modulo 5 proves the rest irrational
        let p = &(&u * &sq2) * &sq3;
        let roots = RealAlg::roots_of(&p);
        assert_eq!(roots.len(), 5);
        for r in &roots {
            let s = r.simplify();
            assert_eq!(s.cmp_exact(r), Ordering::Equal);
            let zero = r.sign_of(&u) == 0;
            assert_eq!(s.as_rational().is_some(), zero, "{r:?}");
        }
        // u(2u − 1)(u² − 2): 1/2 is still found rational
        let p = &(&u * &half) * &sq2;
        let rational: Vec<Q> = RealAlg::roots_of(&p)
            .iter()
            .filter_map(|r| r.simplify().as_rational().cloned())
            .collect();
        assert_eq!(rational, vec![Q::zero(), q(1, 2)]);
    }

    #[test]
    fn compare_and_sign() {
        let s2 = RealAlg::roots_of(&ZPoly::from_i64s(&[-2, 0, 1]))[1].clone();
        let s8 = RealAlg::roots_of(&ZPoly::from_i64s(&[-8, 0, 1]))[1].clone();
        // √8 = 2√2 > √2, and √2·√2 - 2 = 0 as a sign query
        assert_eq!(s2.cmp_exact(&s8), Ordering::Less);
        assert_eq!(s2.sign_of(&ZPoly::from_i64s(&[-2, 0, 1])), 0);
        assert_eq!(s2.sign_of(&ZPoly::from_i64s(&[-3, 2])), -1); // 2√2 - 3 < 0
        assert_eq!(s2.cmp_rational(&q(7, 5)), Ordering::Greater);
        // equal numbers with different defining polynomials
        let a = RealAlg::roots_of(&(&ZPoly::from_i64s(&[-2, 0, 1]) * &ZPoly::from_i64s(&[-3, 1])))
            .into_iter()
            .nth(1)
            .unwrap();
        assert_eq!(a.cmp_exact(&s2), Ordering::Equal);
        assert_eq!(s2.approx(20), "1.4142135623730950488");
    }
}
