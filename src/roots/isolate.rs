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
//!
//! Speed: the Taylor shifts are `O(n²)` additions per node, so the integer
//! type decides the cost.  Each node's step runs on inline fixed-width
//! integers ([`Fixed`]) of the fewest limbs that a headroom bound proves
//! sufficient ([`limbs_for_node`]); only nodes beyond 1024 bits use
//! `BigInt`.  The interval ends that sit on roots are fixed by bisection with
//! signs at dyadic points, also in fixed width when a bound allows
//! ([`DyadicSigner`]).  The results are the same as with `BigInt` alone.

use crate::number::Q;
use crate::number::fixed::{AtWidth, Fixed, at_width, bigint_from_limbs, push_limbs, signed_bits};
use crate::poly::ZPoly;
use crate::poly::zpoly::DyadicSigner;
use crate::poly::zpoly::{taylor_shift_one, taylor_shift_stage};
use num_bigint::{BigInt, Sign};
use num_traits::{One, Zero};
use std::cell::OnceCell;
use std::ops::AddAssign;

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

/// Counts the sign changes of a sequence of signs (-1, 0, 1), zeros skipped.
#[derive(Default)]
struct SignChanges {
    last: i8,
    count: usize,
}

impl SignChanges {
    #[inline]
    fn push(&mut self, s: i8) {
        if s != 0 {
            if self.last != 0 && s != self.last {
                self.count += 1;
            }
            self.last = s;
        }
    }
}

/// Number of sign variations of a coefficient sequence (zeros skipped).
pub fn sign_variations(c: &[BigInt]) -> usize {
    let mut v = SignChanges::default();
    for x in c {
        v.push(x.sign_i8());
    }
    v.count
}

/// Descartes' rule on an open interval `(lo, hi)`: the sign variations of
/// `(be(1+t))ⁿ·p((ae + bc·t)/(be(1+t)))` for `lo = a/b`, `hi = c/e` — an
/// upper bound on the number of roots of `p` in `(lo, hi)` with the same
/// parity, so 0 and 1 are exact counts.
pub(crate) fn descartes_in(p: &ZPoly, lo: &Q, hi: &Q) -> usize {
    let Some(n) = p.degree() else {
        return usize::MAX;
    };
    let (a, b) = (lo.numer(), lo.denom());
    let (c, e) = (hi.numer(), hi.denom());
    // x = (u0 + u1 t)/(w0 + w1 t)
    let num = ZPoly::new(vec![a * e, b * c]);
    let den = ZPoly::new(vec![b * e, b * e]);
    let mut pows_num = vec![ZPoly::constant(BigInt::one())];
    let mut pows_den = vec![ZPoly::constant(BigInt::one())];
    for i in 1..=n {
        pows_num.push(&pows_num[i - 1] * &num);
        pows_den.push(&pows_den[i - 1] * &den);
    }
    let mut acc = ZPoly::zero();
    for (i, ci) in p.coeffs().iter().enumerate() {
        if ci.is_zero() {
            continue;
        }
        acc = &acc + &(&pows_num[i] * &pows_den[n - i]).scale(ci);
    }
    sign_variations(acc.coeffs())
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

/// The integer operations of the subdivision tree: on `BigInt` (always
/// exact) or on [`Fixed<N>`] (exact for a node that passes the headroom
/// bound [`limbs_for_node`]).
trait TreeInt: Clone + for<'a> AddAssign<&'a Self> {
    /// -1, 0 or 1.
    fn sign_i8(&self) -> i8;
    /// `self · 2^k`.
    fn mul_pow2(&self, k: usize) -> Self;
    /// `self / 2^k`, for `2^k` dividing `self`.
    fn div_pow2(&mut self, k: usize);
    /// The exponent of 2 in `self`, `None` for zero.
    fn pow2_valuation(&self) -> Option<u64>;
}

impl TreeInt for BigInt {
    #[inline]
    fn sign_i8(&self) -> i8 {
        match self.sign() {
            Sign::Minus => -1,
            Sign::NoSign => 0,
            Sign::Plus => 1,
        }
    }
    fn mul_pow2(&self, k: usize) -> Self {
        self << k
    }
    fn div_pow2(&mut self, k: usize) {
        *self >>= k;
    }
    fn pow2_valuation(&self) -> Option<u64> {
        self.trailing_zeros()
    }
}

impl<const N: usize> TreeInt for Fixed<N> {
    #[inline]
    fn sign_i8(&self) -> i8 {
        self.signum()
    }
    #[inline]
    fn mul_pow2(&self, k: usize) -> Self {
        self.shl(k as u32)
    }
    #[inline]
    fn div_pow2(&mut self, k: usize) {
        *self = self.shr(k as u32);
    }
    #[inline]
    fn pow2_valuation(&self) -> Option<u64> {
        self.trailing_zeros().map(u64::from)
    }
}

/// Sign variations of `(x+1)^n q(1/(x+1))`, stopping early at 2: returns
/// 0, 1 or 2 (meaning "two or more").  The shift finalises the
/// coefficients from the constant term up, so the count can stop as soon as
/// it reaches two.
fn descartes_unit<T: TreeInt>(q: &[T]) -> usize {
    let mut c: Vec<T> = q.iter().rev().cloned().collect();
    let n = c.len();
    let mut v = SignChanges::default();
    let long = n > crate::poly::zpoly::SHORT;
    for i in 0..n.saturating_sub(1) {
        if long {
            crate::budget::check();
        }
        taylor_shift_stage(&mut c[i..]);
        v.push(c[i].sign_i8());
        if v.count >= 2 {
            return 2;
        }
    }
    if let Some(x) = c.last() {
        v.push(x.sign_i8());
    }
    v.count.min(2)
}

/// Divides out the largest common power of two of the coefficients.
fn remove_pow2<T: TreeInt>(c: &mut [T]) {
    let k = c.iter().filter_map(T::pow2_valuation).min().unwrap_or(0);
    if k > 0 {
        for x in c.iter_mut() {
            x.div_pow2(k as usize);
        }
    }
}

#[derive(Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Found {
    /// Root in the open interval (c/2^j, (c+1)/2^j); the flags say whether
    /// the lower and the upper end are exact roots found at midpoints (and
    /// need fixing).
    Open(BigInt, u64, bool, bool),
    /// Exact root c/2^j.
    Exact(BigInt, u64),
}

/// A node of the subdivision tree: the interval `(c/2^j, (c+1)/2^j)` of
/// `(0, 1)`, and whether its ends are roots met earlier at midpoints.
struct Node {
    c: BigInt,
    j: u64,
    lo_root: bool,
    hi_root: bool,
}

impl Node {
    fn root() -> Node {
        Node {
            c: BigInt::zero(),
            j: 0,
            lo_root: false,
            hi_root: false,
        }
    }
}

/// The two halves of a node, `[right, left]` (pushed in this order, the
/// left half is worked on first).
type Halves<T> = [(Vec<T>, Node); 2];

/// One VCA step on `node`, whose interval is mapped to `(0, 1)` with the
/// polynomial `poly`: no root, one root (recorded in `out`), or the two
/// halves `q_L(x) = 2^n poly(x/2)` (a common power of two removed) and
/// `q_R(x) = q_L(x+1)`.  An exact root at the midpoint is recorded and
/// divided out of `q_R`.
fn vca_step<T: TreeInt>(poly: &[T], node: Node, out: &mut Vec<Found>) -> Option<Halves<T>> {
    match descartes_unit(poly) {
        0 => None,
        1 => {
            out.push(Found::Open(node.c, node.j, node.lo_root, node.hi_root));
            None
        }
        _ => {
            let n = poly.len() - 1;
            let mut left: Vec<T> = poly
                .iter()
                .enumerate()
                .map(|(i, x)| x.mul_pow2(n - i))
                .collect();
            remove_pow2(&mut left);
            let mut right = left.clone();
            taylor_shift_one(&mut right);
            let j = node.j + 1;
            let c2 = &node.c << 1usize;
            let mid: BigInt = &c2 + 1u32;
            let mid_root = right[0].sign_i8() == 0;
            if mid_root {
                out.push(Found::Exact(mid.clone(), j));
                right.remove(0);
            }
            let right_node = Node {
                c: mid,
                j,
                lo_root: mid_root,
                hi_root: node.hi_root,
            };
            let left_node = Node {
                c: c2,
                j,
                lo_root: node.lo_root,
                hi_root: mid_root,
            };
            Some([(right, right_node), (left, left_node)])
        }
    }
}

/// The subtree of `node` (polynomial `poly`) in `BigInt` arithmetic.
fn isolate_unit_bigint(poly: Vec<BigInt>, node: Node, out: &mut Vec<Found>) {
    let mut stack = vec![(poly, node)];
    while let Some((poly, node)) = stack.pop() {
        let bits = poly.iter().map(|c| c.bits()).max().unwrap_or(0);
        crate::budget::check_size(
            "a polynomial of the root-isolation tree",
            poly.len() * (stack.len() + 1),
            bits,
        );
        if let Some(halves) = vca_step(&poly, node, out) {
            stack.extend(halves);
        }
    }
}

/// The headroom bound: the number of 64-bit limbs that make one VCA step
/// ([`vca_step`]) on a node of degree `n` with coefficients `|a_i| <= 2^β`
/// exact in [`Fixed`] arithmetic.
///
/// The step computes nothing but
/// 1. the Descartes test: the Taylor shift by one of the reversed
///    coefficients (degree `n`, inputs `|·| <= 2^β`);
/// 2. the left half `a_i · 2^(n-i)`, so `|·| <= 2^(β+n)`, then divided by a
///    common power of two (which only shrinks it);
/// 3. the right half: the Taylor shift by one of the left half (inputs
///    `|·| <= 2^(β+n)`).
///
/// The in-place Taylor shift only ever does `c_j += c_{j+1}`.  Write each
/// value as `c_j = Σ_k w_jk a_k`: the weights start at 0 or 1 and only have
/// non-negative weights added to them, so every intermediate weight is at
/// most its final value, the binomial `C(k, j)`.  With inputs `|a_k| <= 2^b`
/// every intermediate value is thus at most
/// `2^b Σ_{k=j..n} C(k, j) = 2^b C(n+1, j+1) < 2^(b+n+1)` in absolute value.
/// With `b = β + n` (step 3) every number the step meets is below
/// `2^(β+2n+1)` in absolute value.  `64·N`-bit two's complement holds every
/// `|v| < 2^(64N-1)` exactly (wrapping addition of representable values is
/// exact when the true sum is representable), so `β + 2n + 2 <= 64·N`
/// suffices.  The halves are stored at the width of their parent (they fit
/// by the same bound) and each checks its own bound before its step.
fn limbs_for_node(beta: u32, n: usize) -> usize {
    (beta as usize + 2 * n + 2).div_ceil(64)
}

/// A node waiting for its step; its polynomial is `len` coefficients of
/// `width` two's-complement limbs at `FixedTree::limbs[at..]`.
struct Pending {
    node: Node,
    at: usize,
    len: usize,
    width: usize,
}

/// The subdivision tree on [`Fixed`] coefficients: each node's step runs at
/// the smallest width its headroom bound allows ([`limbs_for_node`]), or in
/// `BigInt` (the whole subtree) beyond
/// [`MAX_LIMBS`](crate::number::fixed::MAX_LIMBS) limbs.  The polynomials of
/// the pending nodes sit contiguously in one buffer, in stack order: a node
/// is always popped from the end, so the buffer is truncated, not searched.
#[derive(Default)]
struct FixedTree {
    limbs: Vec<u64>,
    pending: Vec<Pending>,
    out: Vec<Found>,
    /// Steps done in [`Fixed`] arithmetic.
    fixed_steps: usize,
    /// Subtrees handed to `BigInt` (the headroom bound failed at their root).
    bigint_subtrees: usize,
}

impl FixedTree {
    /// Runs the whole tree of `q` on `(0, 1)`.
    fn run(q: &[BigInt]) -> FixedTree {
        let bits = q.iter().map(|x| x.bits()).max().unwrap_or(0);
        let width = (bits as usize + 1).div_ceil(64).max(1);
        let mut tree = FixedTree::default();
        for x in q {
            let fits = push_limbs(x, width, &mut tree.limbs);
            debug_assert!(fits);
        }
        tree.pending.push(Pending {
            node: Node::root(),
            at: 0,
            len: q.len(),
            width,
        });
        while let Some(p) = tree.pending.pop() {
            crate::budget::check();
            tree.step(p);
        }
        tree
    }

    /// Dispatches one node to the width its headroom bound asks for.
    fn step(&mut self, p: Pending) {
        debug_assert_eq!(p.at + p.len * p.width, self.limbs.len());
        let beta = self.limbs[p.at..]
            .chunks_exact(p.width)
            .map(signed_bits)
            .max()
            .unwrap_or(0);
        let limbs = limbs_for_node(beta, p.len - 1);
        if let Err(StepAt { tree, p }) = at_width(limbs, StepAt { tree: self, p }) {
            let poly = tree.limbs[p.at..]
                .chunks_exact(p.width)
                .map(bigint_from_limbs)
                .collect();
            tree.limbs.truncate(p.at);
            tree.bigint_subtrees += 1;
            isolate_unit_bigint(poly, p.node, &mut tree.out);
        }
    }

    /// The step of `p` in `Fixed<N>`, which its headroom bound allows; the
    /// halves are stored at width `N`.
    fn step_fixed<const N: usize>(&mut self, p: Pending) {
        let poly: Vec<Fixed<N>> = self.limbs[p.at..]
            .chunks_exact(p.width)
            .map(Fixed::from_limbs)
            .collect();
        self.limbs.truncate(p.at);
        self.fixed_steps += 1;
        if let Some(halves) = vca_step(&poly, p.node, &mut self.out) {
            for (half, node) in halves {
                let at = self.limbs.len();
                for x in &half {
                    self.limbs.extend_from_slice(x.limbs());
                }
                self.pending.push(Pending {
                    node,
                    at,
                    len: half.len(),
                    width: N,
                });
            }
        }
    }
}

/// One node's step at the width its headroom bound asks for.
struct StepAt<'a> {
    tree: &'a mut FixedTree,
    p: Pending,
}

impl AtWidth for StepAt<'_> {
    type Output = ();
    fn run<const N: usize>(self) {
        self.tree.step_fixed::<N>(self.p);
    }
}

/// Roots of `q` in `(0, 1)` for a square-free `q` with `q(0) != 0`,
/// `q(1) != 0`, as dyadic intervals (in no particular order).
fn isolate_unit(q: &[BigInt]) -> Vec<Found> {
    FixedTree::run(q).out
}

fn dyadic(c: &BigInt, j: i64) -> Q {
    // c · 2^j
    if j >= 0 {
        Q::from_integer(c << (j as usize))
    } else {
        crate::number::dyadic(c.clone(), (-j) as usize)
    }
}

/// `(k, q)` with all positive roots of `p` below `2^k` and
/// `q(t) ∝ p(2^k t)` (a common power of two removed), so that the roots of
/// `q` in `(0, 1)` are those of `p` in `(0, 2^k)`; `None` when `p` has no
/// positive root by Descartes' rule or is constant.
fn unit_form(p: &ZPoly) -> Option<(i64, Vec<BigInt>)> {
    let k = p.root_bound_log2()?;
    if sign_variations(p.coeffs()) == 0 {
        return None;
    }
    let mut c = p.scale_roots_pow2(-k).coeffs().to_vec();
    remove_pow2(&mut c);
    Some((k, c))
}

/// Isolating intervals of the positive roots of a square-free `p` with
/// `p(0) != 0`, sorted increasingly.
fn isolate_positive(p: &ZPoly) -> Vec<RootInterval> {
    let Some((k, c)) = unit_form(p) else {
        return vec![];
    };
    let mut found: Vec<(Q, Q, [bool; 2])> = isolate_unit(&c)
        .into_iter()
        .map(|f| match f {
            Found::Open(c, j, lo_root, hi_root) => (
                dyadic(&c, k - j as i64),
                dyadic(&(c + 1), k - j as i64),
                [lo_root, hi_root],
            ),
            Found::Exact(c, j) => {
                let v = dyadic(&c, k - j as i64);
                (v.clone(), v, [false; 2])
            }
        })
        .collect();
    found.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)));
    let fixer = EndFixer::new(p);
    found
        .into_iter()
        .map(|(lo, hi, roots)| {
            let mut iv = RootInterval { lo, hi };
            if roots.contains(&true) && !iv.is_exact() {
                fixer.fix(&mut iv, roots);
            }
            iv
        })
        .collect()
}

/// A square-free polynomial prepared for [`EndFixer::fix`] on many
/// intervals: exact signs at dyadic points without per-call conversions,
/// and the derivative computed at most once.
struct EndFixer<'a> {
    p: &'a ZPoly,
    signs: DyadicSigner<'a>,
    deriv: OnceCell<DyadicSigner<'static>>,
}

impl<'a> EndFixer<'a> {
    fn new(p: &'a ZPoly) -> Self {
        EndFixer {
            p,
            signs: DyadicSigner::new(p),
            deriv: OnceCell::new(),
        }
    }

    /// Makes sure neither end of an isolating interval of the square-free
    /// `p` is a root (an end can sit on an exact root found at a midpoint),
    /// by bisection; may turn the interval into an exact root.  `roots`
    /// says which ends are known to be roots (`false`: unknown).
    ///
    /// Inside `(lo, hi)` there is exactly one simple root `r`; `p` has one
    /// sign σ on `(lo, r)` and `-σ` on `(r, hi)`.  σ is read off a non-root
    /// end, or off `p'(lo)` when both ends are roots.
    fn fix(&self, iv: &mut RootInterval, roots: [bool; 2]) {
        // the ends are dyadic (VCA): bisect in integers
        let Some(mut br) = DyadicBracket::of(iv) else {
            return fix_endpoints_rational(self.p, iv);
        };
        let sign = |known_root: bool, x: &BigInt, k: u64| {
            if known_root {
                0
            } else {
                self.signs.sign_at(x, k)
            }
        };
        let mut s_lo = sign(roots[0], &br.a, br.k);
        let mut s_hi = sign(roots[1], &br.b, br.k);
        while s_lo == 0 || s_hi == 0 {
            let sigma = if s_lo != 0 {
                s_lo
            } else if s_hi != 0 {
                -s_hi
            } else {
                let dp = self
                    .deriv
                    .get_or_init(|| DyadicSigner::owned(self.p.derivative()));
                dp.sign_at(&br.a, br.k)
            };
            match br.halve(&self.signs, sigma) {
                Halved::Root(r) => {
                    *iv = RootInterval {
                        lo: r.clone(),
                        hi: r,
                    };
                    return;
                }
                Halved::Lower(s) => s_hi = s,
                Halved::Upper(s) => s_lo = s,
            }
        }
        *iv = br.interval();
    }
}

/// A dyadic interval `(a/2^k, b/2^k)` around one simple root of a
/// square-free polynomial, bisected in integer arithmetic (no gcds).
pub(crate) struct DyadicBracket {
    pub(crate) a: BigInt,
    pub(crate) b: BigInt,
    pub(crate) k: u64,
}

/// The result of [`DyadicBracket::halve`].
pub(crate) enum Halved {
    /// The midpoint is the root.
    Root(Q),
    /// The root is in the lower half; the new upper end has this sign.
    Lower(i32),
    /// The root is in the upper half; the new lower end has this sign.
    Upper(i32),
}

impl DyadicBracket {
    /// The ends of `iv` over their common power of two; `None` unless both
    /// are dyadic.
    fn of(iv: &RootInterval) -> Option<DyadicBracket> {
        let (kl, kh) = (pow2_exponent(iv.lo.denom())?, pow2_exponent(iv.hi.denom())?);
        let k = kl.max(kh);
        Some(DyadicBracket {
            a: iv.lo.numer() << (k - kl) as usize,
            b: iv.hi.numer() << (k - kh) as usize,
            k,
        })
    }

    /// Halves the bracket given the sign `sigma` of the polynomial between
    /// the lower end and the root (its sign above the root is `-sigma`).
    pub(crate) fn halve(&mut self, signs: &DyadicSigner, sigma: i32) -> Halved {
        let m: BigInt = &self.a + &self.b;
        let s = signs.sign_at(&m, self.k + 1);
        self.halve_at(m, s, sigma)
    }

    /// [`DyadicBracket::halve`] when the sign `s` of the polynomial at the
    /// midpoint `m/2^(k+1)` (`m = a + b`) is already known.
    pub(crate) fn halve_at(&mut self, m: BigInt, s: i32, sigma: i32) -> Halved {
        self.k += 1;
        if s == 0 {
            return Halved::Root(crate::number::dyadic(m, self.k as usize));
        }
        if s == sigma {
            self.a = m;
            self.b <<= 1usize;
            Halved::Upper(s)
        } else {
            self.b = m;
            self.a <<= 1usize;
            Halved::Lower(s)
        }
    }

    pub(crate) fn interval(self) -> RootInterval {
        // a/2^k in lowest terms by a shift (Q::new would run a gcd)
        RootInterval {
            lo: crate::number::dyadic(self.a, self.k as usize),
            hi: crate::number::dyadic(self.b, self.k as usize),
        }
    }
}

/// [`EndFixer::fix`] for non-dyadic ends.
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
        let fixer = EndFixer::new(sq);
        for iv in out.iter_mut() {
            let roots = [iv.lo.is_zero(), iv.hi.is_zero()];
            if !iv.is_exact() && roots.contains(&true) {
                fixer.fix(iv, roots);
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
    let wider = |iv: &RootInterval| crate::number::q_cmp(&(&iv.hi - &iv.lo), width).is_gt();
    if iv.is_exact() || !wider(iv) {
        return;
    }
    if let Some(br) = DyadicBracket::of(iv) {
        refine_dyadic(p, iv, width, br);
        return;
    }
    let two = Q::from_integer(BigInt::from(2));
    let s_lo = p.sign_at(&iv.lo);
    while wider(iv) {
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

fn refine_dyadic(p: &ZPoly, iv: &mut RootInterval, width: &Q, mut br: DyadicBracket) {
    let signs = DyadicSigner::new(p);
    let (wn, wd) = (width.numer(), width.denom());
    let s_lo = signs.sign_at(&br.a, br.k);
    // many bits to gain: bisection with verified Newton steps
    let need = ((&br.b - &br.a) * wd).bits() as i64 - (wn << br.k as usize).bits() as i64;
    if need > 8 && s_lo != 0 {
        super::newton::refine_dyadic_newton(p, &signs, iv, br, s_lo, width);
        return;
    }
    // (b − a)/2^k > wn/wd  ⇔  (b − a)·wd > wn·2^k
    while (&br.b - &br.a) * wd > (wn << br.k as usize) {
        if let Halved::Root(r) = br.halve(&signs, s_lo) {
            *iv = RootInterval {
                lo: r.clone(),
                hi: r,
            };
            return;
        }
    }
    *iv = br.interval();
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
    use proptest::prelude::*;

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

    fn fixed<const N: usize>(c: &[BigInt]) -> Vec<Fixed<N>> {
        c.iter()
            .map(|x| Fixed::from_bigint(x).expect("fits"))
            .collect()
    }

    fn unfixed<const N: usize>(c: &[Fixed<N>]) -> Vec<BigInt> {
        c.iter().map(Fixed::to_bigint).collect()
    }

    /// The roots found in `(0, 1)` by the `BigInt` tree alone (the
    /// reference) and by the fixed-width tree, sorted.
    fn both_trees(q: &[BigInt]) -> (Vec<Found>, FixedTree) {
        let mut reference = Vec::new();
        isolate_unit_bigint(q.to_vec(), Node::root(), &mut reference);
        reference.sort();
        let mut tree = FixedTree::run(q);
        tree.out.sort();
        (reference, tree)
    }

    /// One VCA step in `Fixed<N>` and in `BigInt` on the same node: the same
    /// Descartes count, the same roots recorded, the same halves.
    fn same_step<const N: usize>(c: &[BigInt]) -> Result<(), String> {
        let fx = fixed::<N>(c);
        let (d_fixed, d_big) = (descartes_unit(&fx), descartes_unit(c));
        if d_fixed != d_big {
            return Err(format!("Descartes {d_fixed} != {d_big}"));
        }
        let (mut out_f, mut out_b) = (Vec::new(), Vec::new());
        let halves_f = vca_step(&fx, Node::root(), &mut out_f);
        let halves_b = vca_step(c, Node::root(), &mut out_b);
        if out_f != out_b {
            return Err(format!("found {out_f:?} != {out_b:?}"));
        }
        match (halves_f, halves_b) {
            (None, None) => Ok(()),
            (Some(hf), Some(hb)) => {
                for ((pf, _), (pb, _)) in hf.iter().zip(hb.iter()) {
                    if unfixed(pf) != *pb {
                        return Err(format!("halves differ: {:?} != {pb:?}", unfixed(pf)));
                    }
                }
                Ok(())
            }
            _ => Err("one step split, the other did not".into()),
        }
    }

    /// Coefficients at the headroom limit of `Fixed<N>` for degree `n`:
    /// `β = 64N - 2n - 2`, the largest `β` that [`limbs_for_node`] accepts.
    fn at_the_limit(n: usize, limbs: usize, picks: &[(u8, i64)]) -> Vec<BigInt> {
        let beta = 64 * limbs - 2 * n - 2;
        assert_eq!(limbs_for_node(beta as u32, n), limbs);
        let top = BigInt::one() << beta;
        picks
            .iter()
            .take(n + 1)
            .map(|&(kind, r)| match kind % 5 {
                0 => -top.clone(),
                1 => &top - 1u32,
                2 => BigInt::zero(),
                // a random value of about β bits, either sign
                _ => (BigInt::from(r) << (beta.saturating_sub(63))) % &top,
            })
            .collect()
    }

    #[test]
    fn fixed_taylor_shift_matches_bigint() {
        // (x + 1)^5 - 2^100 x^2, and its shift by one
        let mut c: Vec<BigInt> = [1, 5, 10, 10, 5, 1]
            .iter()
            .map(|&x| BigInt::from(x))
            .collect();
        c[2] -= BigInt::one() << 100usize;
        let mut f = fixed::<2>(&c);
        taylor_shift_one(&mut f);
        taylor_shift_one(&mut c);
        assert_eq!(unfixed(&f), c);
        assert_eq!(c[0], BigInt::from(32) - (BigInt::one() << 100usize));
    }

    #[test]
    fn headroom_bound_is_needed() {
        // all coefficients -2^β, degree 20: the shift's middle coefficients
        // are -2^β C(21, 11) ≈ -2^(β+18.4)
        let n = 20;
        let wrapped = |beta: usize| {
            let c = vec![-(BigInt::one() << beta); n + 1];
            let mut f = fixed::<2>(&c);
            let mut b = c.clone();
            taylor_shift_one(&mut f);
            taylor_shift_one(&mut b);
            unfixed(&f) != b
        };
        // at the bound of one shift (β + n + 1 <= 127) the result is exact
        assert!(!wrapped(127 - n - 1));
        // a few bits beyond it, Fixed<2> wraps: the bound is not vacuous
        assert!(wrapped(127 - 8));
        assert_eq!(limbs_for_node(127 - 8, n), 3);
        // the bound itself: β + 2n + 2 <= 64N, and not one bit more
        for n in [1usize, 5, 20, 50] {
            for limbs in [2usize, 3, 16] {
                let beta = (64 * limbs - 2 * n - 2) as u32;
                assert_eq!(limbs_for_node(beta, n), limbs);
                assert_eq!(limbs_for_node(beta + 1, n), limbs + 1);
            }
        }
    }

    #[test]
    fn wide_coefficients_fall_back_to_bigint() {
        // (3x - 1)(5x - 3) times an odd 1100-bit constant: beyond 16 limbs
        let m: BigInt = (BigInt::one() << 1100usize) + 1u32;
        let q: Vec<BigInt> = [3, -14, 15].iter().map(|&x| &m * x).collect();
        let (reference, tree) = both_trees(&q);
        assert_eq!(tree.bigint_subtrees, 1);
        assert_eq!(tree.fixed_steps, 0);
        assert_eq!(tree.out, reference);
        assert_eq!(reference.len(), 2);
    }

    #[test]
    fn subtrees_past_the_bound_fall_back_to_bigint() {
        // ∏ (7x - k), k = 1..6, times an odd 989-bit constant: the root fits
        // 16 limbs, some halves grow past the headroom bound
        let m: BigInt = (BigInt::one() << 989usize) + 1u32;
        let q = (1..=6).fold(ZPoly::new(vec![m]), |acc, k| {
            &acc * &ZPoly::from_i64s(&[-k, 7])
        });
        let (reference, tree) = both_trees(q.coeffs());
        assert!(tree.fixed_steps > 0);
        assert!(tree.bigint_subtrees > 0);
        assert_eq!(tree.out, reference);
        assert_eq!(reference.len(), 6);
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, .. ProptestConfig::default() })]

        /// At the headroom limit of `Fixed<N>` (coefficients ±2^β, 0 or
        /// random, β = 64N - 2n - 2) one VCA step — Descartes test, halves,
        /// midpoint root — gives exactly what `BigInt` gives.
        #[test]
        fn fixed_step_equals_bigint_step_at_the_limit(
            n in 1usize..=30,
            picks in prop::collection::vec((any::<u8>(), any::<i64>()), 31),
        ) {
            if 2 * n + 2 < 64 {
                same_step::<1>(&at_the_limit(n, 1, &picks)).map_err(TestCaseError::fail)?;
            }
            same_step::<2>(&at_the_limit(n, 2, &picks)).map_err(TestCaseError::fail)?;
            same_step::<3>(&at_the_limit(n, 3, &picks)).map_err(TestCaseError::fail)?;
            same_step::<5>(&at_the_limit(n, 5, &picks)).map_err(TestCaseError::fail)?;
        }

        /// The fixed-width subdivision tree finds exactly the roots and
        /// intervals of the `BigInt` tree (the algorithm before fixed-width
        /// arithmetic), on both sides of 0, for random square-free
        /// polynomials: dense random ones, products of rational linear
        /// factors (roots met at midpoints), and wide coefficients.
        #[test]
        fn fixed_tree_equals_bigint_tree(
            dense in prop::collection::vec(-(1i64 << 40)..(1i64 << 40), 2..24),
            roots in prop::collection::vec((-40i64..40, 0u32..5), 0..10),
            scale_bits in 0usize..1200,
        ) {
            let linear = roots.iter().fold(ZPoly::from_i64s(&[1]), |acc, &(a, e)| {
                &acc * &ZPoly::from_i64s(&[-a, 1 << e])
            });
            let wide = &ZPoly::from_i64s(&dense) * &ZPoly::new(vec![(BigInt::one() << scale_bits) + 1u32]);
            for p in [ZPoly::from_i64s(&dense), &linear * &ZPoly::from_i64s(&dense[..2]), wide] {
                if p.degree().unwrap_or(0) == 0 {
                    continue;
                }
                let sq = p.squarefree_part().strip_zero_roots();
                for side in [sq.clone(), sq.neg_x()] {
                    if let Some((_, q)) = unit_form(&side) {
                        let (reference, tree) = both_trees(&q);
                        prop_assert_eq!(tree.out, reference);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_isolate_real_roots() {
        use crate::poly::ZPoly;
        use crate::roots::isolate_real_roots;
        let p = ZPoly::from_i64s(&[0, -2, 0, 1]); // x^3 - 2x
        let iv = isolate_real_roots(&p);
        assert_eq!(iv.len(), 3);
        assert!(iv[1].is_exact()); // the root 0
    }
}
