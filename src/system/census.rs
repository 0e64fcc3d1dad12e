//! A census of *all* complex zeros of a square system: one certified box
//! per zero, found from a candidate RUR, and the size bounds it gives.
//!
//! Key facts (docs/maths.md, "An a-posteriori bound for the RUR"):
//!
//! * A square system `F = (f₁, f₂, f₃)` whose leading forms have no common
//!   zero at infinity (`R̄ ≠ 0`) has exactly `N = d₁d₂d₃` zeros in `C³`
//!   counted with multiplicity (Bézout).  So `N` pairwise disjoint boxes,
//!   each proved to hold exactly one zero, hold *all* the zeros, and every
//!   zero is simple.
//! * A box is proved by the Krawczyk test in complex ball arithmetic
//!   ([`CBall`]: real and imaginary parts are [`BallR`]s, so each operation
//!   encloses every exact result).  Read as a map of `R⁶`, the complex
//!   Jacobian enclosure on the box is an interval enclosure of the real
//!   Jacobian (a complex product `(p + iq)(x + iy)` is computed with `p`,
//!   `q` once in each part, exactly as the realified matrix would be), so
//!   `K(X) ⊂ int(X)` proves one and only one zero in `X` (Krawczyk, Rump).
//! * The starting points come from a candidate RUR `(w, V)` — the CRT image
//!   before it is known to be exact: the roots τ of w by the Aberth–Ehrlich
//!   iteration in doubles, `ξ ≈ V(τ)/w′(τ)`, then Newton's iteration on F.
//!   The candidate only supplies approximations: a wrong candidate makes
//!   the census fail (boxes missing or overlapping), never makes it wrong.
//! * With every zero enclosed, any polynomial `h` is bounded at every zero,
//!   and `∏_ξ (1 + |h(ξ)|)` is bounded from above by an exact product of
//!   doubles ([`ZeroCensus::product_bits`]).  Those products bound the
//!   coefficients of `R̄·∏(u − h(ξ))` and of the Kronecker numerators
//!   without any a-priori height estimate.
//!
//! Everything here is a filter in the sense of STYLE: doubles only choose
//! where to look, every accepted statement is proved by ball arithmetic,
//! and a failure (`None`) leaves the caller on its a-priori route.

use super::krawczyk::System;
use super::krawczyk_filter::{BallArith, BallSystem, monomial, powers};
use crate::number::filter::{BallR, SignRing};
use crate::poly::{ZMPoly, ZPoly};
use num_bigint::BigUint;
use num_traits::{One, ToPrimitive, Zero};

/// `1 + 2^-48`: a sum of at most four non-negative doubles rounded to
/// nearest, times this (rounded), bounds the exact sum.
const INFL: f64 = 1.0 + 1.0 / 281_474_976_710_656.0;

/// A complex double (approximations only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct C64 {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl C64 {
    const ZERO: C64 = C64 { re: 0.0, im: 0.0 };
    const ONE: C64 = C64 { re: 1.0, im: 0.0 };

    fn new(re: f64, im: f64) -> C64 {
        C64 { re, im }
    }
    fn add(self, o: C64) -> C64 {
        C64::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: C64) -> C64 {
        C64::new(self.re - o.re, self.im - o.im)
    }
    fn mul(self, o: C64) -> C64 {
        C64::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn scale(self, s: f64) -> C64 {
        C64::new(self.re * s, self.im * s)
    }
    fn div(self, o: C64) -> C64 {
        // scaled by the larger part of o (no overflow for moderate values)
        let s = o.re.abs().max(o.im.abs());
        if s == 0.0 {
            return C64::new(f64::NAN, f64::NAN);
        }
        let (a, b) = (o.re / s, o.im / s);
        let d = a * a + b * b;
        let n = C64::new(self.re / s, self.im / s).mul(C64::new(a, -b));
        C64::new(n.re / d, n.im / d)
    }
    /// `|z|`.
    pub fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }
    fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
}

impl BallArith for C64 {
    fn of_real(b: BallR) -> Self {
        C64::new(b.m, 0.0)
    }
    fn plus(&self, o: &Self) -> Self {
        self.add(*o)
    }
    fn times(&self, o: &Self) -> Self {
        self.mul(*o)
    }
}

/// A complex ball: a rectangle `re × im` of real balls.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CBall {
    /// The real part.
    pub re: BallR,
    /// The imaginary part.
    pub im: BallR,
}

impl BallArith for CBall {
    fn of_real(b: BallR) -> Self {
        CBall {
            re: b,
            im: BallR::input(0.0, 0),
        }
    }
    fn plus(&self, o: &Self) -> Self {
        CBall {
            re: self.re.add(&o.re),
            im: self.im.add(&o.im),
        }
    }
    fn times(&self, o: &Self) -> Self {
        CBall {
            re: self.re.mul(&o.re).sub(&self.im.mul(&o.im)),
            im: self.re.mul(&o.im).add(&self.im.mul(&o.re)),
        }
    }
}

impl CBall {
    /// The exact complex double `z`.
    fn point(z: C64) -> CBall {
        CBall {
            re: BallR::input(z.re, 0),
            im: BallR::input(z.im, 0),
        }
    }
    /// The square `z ± r` (real and imaginary half-width r).
    fn square(z: C64, r: f64) -> CBall {
        CBall {
            re: BallR { m: z.re, r },
            im: BallR { m: z.im, r },
        }
    }
    fn neg(&self) -> CBall {
        CBall {
            re: BallR {
                m: -self.re.m,
                r: self.re.r,
            },
            im: BallR {
                m: -self.im.m,
                r: self.im.r,
            },
        }
    }
    fn mid(&self) -> C64 {
        C64::new(self.re.m, self.im.m)
    }
    /// An upper bound of `|z|` over the ball (`|re| + |im|`, rounded up;
    /// infinite or NaN when the ball is).
    pub fn abs_upper(&self) -> f64 {
        (self.re.m.abs() + self.re.r + self.im.m.abs() + self.im.r) * INFL
    }
}

/// One certified zero: the box `centre ± half` (in the real and the
/// imaginary part of each coordinate) holds exactly one zero of the
/// system.
#[derive(Clone, Debug)]
pub struct CensusBox {
    /// The centre.
    pub centre: [C64; 3],
    /// The half-width.
    pub half: f64,
}

impl CensusBox {
    /// The box as complex balls.
    pub(crate) fn balls(&self) -> [CBall; 3] {
        self.centre.map(|z| CBall::square(z, self.half))
    }

    /// True when the centre is real: the box is then its own complex
    /// conjugate, so its unique zero (F has real coefficients, so the
    /// conjugate of a zero is a zero) is real.
    pub fn is_real(&self) -> bool {
        self.centre.iter().all(|z| z.im == 0.0)
    }

    /// True when the box misses the real space (some coordinate's
    /// imaginary part is further from 0 than the half-width; doubles
    /// compared exactly), so its zero is not real.
    pub fn misses_real_space(&self) -> bool {
        self.centre.iter().any(|z| z.im.abs() > self.half)
    }

    /// True when the two boxes are proved disjoint (some coordinate's real
    /// or imaginary parts are further apart than the half-widths allow).
    fn disjoint(&self, o: &CensusBox) -> bool {
        let gap = (self.half + o.half) * INFL;
        // |a − b| rounded is at least (1 − 2^-53)·|a − b|
        let far = |a: f64, b: f64| (a - b).abs() * (1.0 - 1.0 / 4_503_599_627_370_496.0) > gap;
        self.centre
            .iter()
            .zip(&o.centre)
            .any(|(a, b)| far(a.re, b.re) || far(a.im, b.im))
    }
}

/// Certified boxes around all `N` zeros of a square system.
#[derive(Clone, Debug)]
pub struct ZeroCensus {
    /// One box per zero, pairwise disjoint.
    pub boxes: Vec<CensusBox>,
}

impl ZeroCensus {
    /// A `b` with `∏_ξ (1 + |h(ξ)|) < 2^b` over all zeros, `h` enclosed on
    /// each box by `f` (`None` when an enclosure is not finite).  The
    /// factors are upper bounds rounded to doubles and multiplied exactly.
    pub(crate) fn product_bits(&self, f: impl Fn(&[CBall; 3]) -> CBall) -> Option<u64> {
        let mut mant = BigUint::one();
        let mut exp: i64 = 0;
        for b in &self.boxes {
            let a = (1.0 + f(&b.balls()).abs_upper()) * INFL;
            let (m, e) = split_double(a)?;
            mant *= m;
            exp += e;
        }
        Some((mant.bits() as i64 + exp).max(0) as u64)
    }

    /// A `b` with `Σ_ξ |h(ξ)| < 2^b` (`N · max`).
    pub(crate) fn sum_bits(&self, f: impl Fn(&[CBall; 3]) -> CBall) -> Option<u64> {
        let mut top = 0.0f64;
        for b in &self.boxes {
            let a = f(&b.balls()).abs_upper();
            if !a.is_finite() {
                return None;
            }
            top = top.max(a);
        }
        let n = self.boxes.len().max(1) as u64;
        let log_n = 64 - (n - 1).leading_zeros() as u64; // 2^log_n ≥ n
        let (m, e) = split_double(top.max(1.0))?;
        Some(((m.bits() as i64 + e).max(0) as u64) + log_n)
    }

    /// The bits of `∏ (1 + |v(ξ)|)` for v = x, y, z ([`Self::product_bits`]).
    pub fn coordinate_bits(&self) -> Option<[u64; 3]> {
        Some([
            self.product_bits(|x| x[0])?,
            self.product_bits(|x| x[1])?,
            self.product_bits(|x| x[2])?,
        ])
    }

    /// A `b` with `∏_ξ (1 + |p(ξ)|) < 2^b` for an integer polynomial p.
    pub fn polynomial_bits(&self, p: &ZMPoly) -> Option<u64> {
        let terms: Vec<([u32; 3], BallR)> = p
            .terms()
            .iter()
            .map(|(e, c)| ([e[0], e[1], e[2]], BallR::from_z(c)))
            .collect();
        let deg = terms
            .iter()
            .map(|(e, _)| e[0].max(e[1]).max(e[2]))
            .max()
            .unwrap_or(0);
        self.product_bits(|x| {
            let pw = powers(x, deg as usize);
            terms
                .iter()
                .fold(CBall::of_real(BallR::input(0.0, 0)), |acc, (e, c)| {
                    acc.plus(&CBall::of_real(*c).times(&monomial(&pw, e)))
                })
        })
    }

    /// The bits of the a-posteriori bound on the RUR `(w, V)` for the form
    /// `ℓ`, given `|R̄| < 2^rbar_bits`: every coefficient of
    /// `w = ±R̄·∏(u − ℓ(ξ))` and of `V_v = ±R̄·Σ_ξ v(ξ)·∏_{η≠ξ}(u − ℓ(η))`
    /// is below `2^b`.
    pub fn rur_bits(&self, form: [i64; 3], rbar_bits: u64) -> Option<u64> {
        let l: [BallR; 3] = form.map(|c| BallR::input(c as f64, 0));
        let ell = self.product_bits(|x| {
            (0..3).fold(CBall::of_real(BallR::input(0.0, 0)), |acc, i| {
                acc.plus(&CBall::of_real(l[i]).times(&x[i]))
            })
        })?;
        let mut sum = 0u64;
        for v in 0..3 {
            sum = sum.max(self.sum_bits(|x| x[v])?);
        }
        Some(rbar_bits + ell + sum)
    }
}

/// The positive finite double `a` as `m · 2^e` exactly (`None` otherwise).
fn split_double(a: f64) -> Option<(BigUint, i64)> {
    if !(a.is_finite() && a > 0.0) {
        return None;
    }
    let (_, m, e) = crate::number::float::double_parts(a);
    Some((BigUint::from(m), e))
}

/// The census of the zeros of `gens` from the candidate RUR `(w, v)` (w of
/// degree N = the Bézout number, `v` the Kronecker numerators): `None`
/// unless all N zeros are certified in pairwise disjoint boxes.
pub fn census(gens: &[ZMPoly; 3], w: &ZPoly, v: &[ZPoly; 3]) -> Option<ZeroCensus> {
    let n = w.degree()?;
    let sys = BallSystem::new(&System::new(gens.clone()))?;
    let taus = aberth(w)?;
    let wd = Scaled::new(&w.derivative());
    let vs: Vec<Scaled> = v.iter().map(Scaled::new).collect();
    let mut boxes: Vec<CensusBox> = Vec::with_capacity(n);
    for t in taus {
        crate::budget::check();
        let start: [C64; 3] = std::array::from_fn(|k| ratio_at(&vs[k], &wd, t, n - 1));
        if !start.iter().all(|z| z.is_finite()) {
            return None;
        }
        boxes.push(certify_complex(&sys, start)?);
    }
    for i in 0..boxes.len() {
        for j in 0..i {
            if !boxes[i].disjoint(&boxes[j]) {
                return None;
            }
        }
    }
    Some(ZeroCensus { boxes })
}

/// Newton's iteration on F from `start` in complex doubles, then the
/// Krawczyk test on squares of relative half-width `2^-40`, `2^-32`,
/// `2^-24` around the result (around its real part first when it looks
/// real, see [`CensusBox::is_real`]).
fn certify_complex(sys: &BallSystem, start: [C64; 3]) -> Option<CensusBox> {
    let mut c = start;
    let mut close = false;
    for _ in 0..40 {
        let (f, j) = approx(sys, &c);
        let inv = inverse3(&j)?;
        let step: [C64; 3] =
            std::array::from_fn(|i| (0..3).fold(C64::ZERO, |a, l| a.add(inv[i][l].mul(f[l]))));
        for (ci, s) in c.iter_mut().zip(&step) {
            *ci = ci.sub(*s);
        }
        if !c.iter().all(|z| z.is_finite()) {
            return None;
        }
        if close {
            break;
        }
        let size = c.iter().fold(1.0f64, |a, z| a.max(z.abs()));
        close = step.iter().all(|s| s.abs() <= size * 1e-12);
    }
    if !close {
        return None;
    }
    let size = c.iter().fold(1.0f64, |a, z| a.max(z.abs()));
    // a zero that looks real is tried first around its real part: a box
    // with a real centre is its own conjugate, so success proves the zero
    // real (a non-real one would bring its conjugate into the box, against
    // uniqueness); failure leaves the complex centre to try
    if c.iter().all(|z| z.im.abs() <= size * 1e-9) {
        let real = c.map(|z| C64::new(z.re, 0.0));
        if let Some(b) = krawczyk_squares(sys, real, size) {
            return Some(b);
        }
    }
    krawczyk_squares(sys, c, size)
}

/// The Krawczyk test on squares of half-width `size·2^-40`, `2^-32`,
/// `2^-24` around `c`: the first that succeeds.
fn krawczyk_squares(sys: &BallSystem, c: [C64; 3], size: f64) -> Option<CensusBox> {
    let v = sys.eval_in(&c.map(CBall::point));
    let j: [[C64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|l| v[3 + 3 * i + l].mid()));
    let y = inverse3(&j)?;
    for e in [40, 32, 24] {
        let r = size * 2f64.powi(-e);
        if krawczyk(sys, &c, r, &y, &v[..3]) {
            return Some(CensusBox { centre: c, half: r });
        }
    }
    None
}

/// F and its Jacobian at a point, approximately (coefficients and
/// arithmetic in plain complex doubles).
fn approx(sys: &BallSystem, c: &[C64; 3]) -> ([C64; 3], [[C64; 3]; 3]) {
    let v: Vec<C64> = sys.eval_in(c);
    (
        std::array::from_fn(|i| v[i]),
        std::array::from_fn(|i| std::array::from_fn(|l| v[3 + 3 * i + l])),
    )
}

/// True when the Krawczyk operator on the square `c ± r` lies in its
/// interior (then it holds exactly one zero).
fn krawczyk(sys: &BallSystem, c: &[C64; 3], r: f64, y: &[[C64; 3]; 3], fc: &[CBall]) -> bool {
    let v = sys.eval_in(&c.map(|z| CBall::square(z, r)));
    let jx = &v[3..];
    let dev = CBall::square(C64::ZERO, r);
    let yb = y.map(|row| row.map(CBall::point));
    for i in 0..3 {
        // c − Y·f(c) + (I − Y·J(X))·(X − c)
        let mut k = CBall::point(c[i]);
        for (yij, fj) in yb[i].iter().zip(fc) {
            k = k.plus(&yij.times(fj).neg());
        }
        for l in 0..3 {
            let mut m = CBall::point(if i == l { C64::ONE } else { C64::ZERO });
            for (j, yij) in yb[i].iter().enumerate() {
                m = m.plus(&yij.times(&jx[3 * j + l]).neg());
            }
            k = k.plus(&m.times(&dev));
        }
        // |K.m − c| + K.r < r in both parts, the left side bounded above
        for (kb, ci) in [(k.re, c[i].re), (k.im, c[i].im)] {
            let d = BallR::input(kb.m, 0).sub(&BallR::input(ci, 0));
            let left = (d.m.abs() + d.r + kb.r) * INFL;
            if !(left.is_finite() && left < r) {
                return false;
            }
        }
    }
    true
}

/// The inverse of a complex 3×3 matrix (an approximation; `None` when
/// singular or not finite).
fn inverse3(j: &[[C64; 3]; 3]) -> Option<[[C64; 3]; 3]> {
    let cof = |r: usize, c: usize| -> C64 {
        let (r0, r1) = ((r + 1) % 3, (r + 2) % 3);
        let (c0, c1) = ((c + 1) % 3, (c + 2) % 3);
        j[r0][c0].mul(j[r1][c1]).sub(j[r0][c1].mul(j[r1][c0]))
    };
    let det = (0..3).fold(C64::ZERO, |a, c| a.add(j[0][c].mul(cof(0, c))));
    if det.abs() == 0.0 || !det.is_finite() {
        return None;
    }
    let inv: [[C64; 3]; 3] = std::array::from_fn(|a| std::array::from_fn(|b| cof(b, a).div(det)));
    inv.iter().flatten().all(|z| z.is_finite()).then_some(inv)
}

/// A double-double `hi + lo` (`|lo| ≤ ulp(hi)/2`): about 106 bits, for
/// evaluations where doubles cancel (approximations only).
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
}

/// `a + b = s + e` exactly.
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Dekker's split: `x = h + l` with h, l of at most 26 bits each.
fn split(x: f64) -> (f64, f64) {
    let c = 134_217_729.0 * x;
    let h = c - (c - x);
    (h, x - h)
}

/// `a·b = p + e` exactly for `b = bh + bl` split: by one fused
/// multiply-add when `FMA` (only in code compiled for a processor that has
/// it), by Dekker's product otherwise.  Both give the exact error (no
/// overflow: the scaled coefficients and points are at most 1 in size;
/// barring underflow, below 2^-969), so the two agree bit for bit.
#[inline(always)]
fn two_prod<const FMA: bool>(a: f64, b: f64, (bh, bl): (f64, f64)) -> (f64, f64) {
    let p = a * b;
    if FMA {
        return (p, a.mul_add(b, -p));
    }
    let (ah, al) = split(a);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    #[inline(always)]
    fn norm(s: f64, e: f64) -> Dd {
        let hi = s + e;
        Dd {
            hi,
            lo: e - (hi - s),
        }
    }
    #[inline(always)]
    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        Dd::norm(s, e + self.lo + o.lo)
    }
    #[inline(always)]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
    /// `self · b` for a double b split as `bs`.
    #[inline(always)]
    fn mul_f64<const FMA: bool>(self, b: f64, bs: (f64, f64)) -> Dd {
        let (p, e) = two_prod::<FMA>(self.hi, b, bs);
        Dd::norm(p, e + self.lo * b)
    }
}

/// A complex double-double.
#[derive(Clone, Copy, Debug)]
struct CDd {
    re: Dd,
    im: Dd,
}

impl CDd {
    const ZERO: CDd = CDd {
        re: Dd::ZERO,
        im: Dd::ZERO,
    };
    #[inline(always)]
    fn add(self, o: CDd) -> CDd {
        CDd {
            re: self.re.add(o.re),
            im: self.im.add(o.im),
        }
    }
    /// `self · x` for the complex double x with its parts split as `xs`.
    #[inline(always)]
    fn mul_c64<const FMA: bool>(self, x: C64, xs: ((f64, f64), (f64, f64))) -> CDd {
        CDd {
            re: self
                .re
                .mul_f64::<FMA>(x.re, xs.0)
                .add(self.im.mul_f64::<FMA>(x.im, xs.1).neg()),
            im: self
                .re
                .mul_f64::<FMA>(x.im, xs.1)
                .add(self.im.mul_f64::<FMA>(x.re, xs.0)),
        }
    }
    fn hi(self) -> C64 {
        C64::new(self.re.hi + self.re.lo, self.im.hi + self.im.lo)
    }
}

/// An integer polynomial's coefficients times `2^-top` (`top` the bits of
/// the largest), ascending, as doubles and as double-doubles.
struct Scaled {
    f: Vec<f64>,
    dd: Vec<Dd>,
    top: i64,
}

impl Scaled {
    fn new(p: &ZPoly) -> Scaled {
        let top = p.coeffs().iter().map(|c| c.bits()).max().unwrap_or(0) as i64;
        let mut f = Vec::with_capacity(p.coeffs().len());
        let mut dd = Vec::with_capacity(p.coeffs().len());
        for c in p.coeffs() {
            let b = c.bits() as i64;
            let shift = (b - 106).max(0);
            let x = c.magnitude() >> shift as usize;
            let high = (&x >> 53usize).to_u64().unwrap_or(0) as f64 * 9_007_199_254_740_992.0;
            let low = (x & BigUint::from((1u64 << 53) - 1)).to_u64().unwrap_or(0) as f64;
            let scale = 2f64.powi((shift - top).clamp(-1100, 1100) as i32);
            let sign = if c.sign() == num_bigint::Sign::Minus {
                -1.0
            } else {
                1.0
            };
            let v = Dd::norm(high * scale * sign, low * scale * sign);
            f.push(v.hi);
            dd.push(v);
        }
        Scaled { f, dd, top }
    }

    /// `(p(z), p′(z))` when `|z| ≤ 1`; otherwise `(q(y), q′(y))` at
    /// `y = 1/z` for `q(y) = y^deg·p(1/y)` (formal degree `deg`).  In
    /// doubles with a running error bound, redone in double-doubles when
    /// the value has fewer than about 20 correct bits.
    fn eval(&self, deg: usize, z: C64) -> (C64, C64) {
        let rev = z.abs() > 1.0;
        let x = if rev { C64::ONE.div(z) } else { z };
        let coef = |i: usize| coef_index(deg, rev, i);
        let get = |k: usize| self.f.get(k).copied().unwrap_or(0.0);
        let (mut p, mut d, mut bound) = (C64::ZERO, C64::ZERO, 0.0f64);
        let ax = x.abs();
        for i in 0..=deg {
            let c = get(coef(i));
            d = d.mul(x).add(p);
            p = p.mul(x).add(C64::new(c, 0.0));
            bound = bound * ax + c.abs();
        }
        let err = bound * (8.0 * (deg as f64 + 2.0)) * f64::EPSILON;
        if p.abs() > err * 1_048_576.0 {
            return (p, d);
        }
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("fma") {
            // SAFETY: the processor has FMA (checked above); the function
            // only enables code generation for it.
            return unsafe { self.eval_dd_fma(deg, x, rev) };
        }
        self.eval_dd::<false>(deg, x, rev)
    }

    /// [`Self::eval`]'s double-double pass, compiled with fused
    /// multiply-adds.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "fma")]
    unsafe fn eval_dd_fma(&self, deg: usize, x: C64, rev: bool) -> (C64, C64) {
        self.eval_dd::<true>(deg, x, rev)
    }

    /// `(p(x), p′(x))` (or the reversed polynomial's, when `rev`) in
    /// double-doubles.
    #[inline(always)]
    fn eval_dd<const FMA: bool>(&self, deg: usize, x: C64, rev: bool) -> (C64, C64) {
        let xs = (split(x.re), split(x.im));
        let (mut p, mut d) = (CDd::ZERO, CDd::ZERO);
        for i in 0..=deg {
            let k = coef_index(deg, rev, i);
            let c = self.dd.get(k).copied().unwrap_or(Dd::ZERO);
            d = d.mul_c64::<FMA>(x, xs).add(p);
            p = p.mul_c64::<FMA>(x, xs).add(CDd {
                re: c,
                im: Dd::ZERO,
            });
        }
        (p.hi(), d.hi())
    }
}

/// The coefficient read at Horner step `i` (from the top) of a polynomial
/// of formal degree `deg`, or of its reverse when `rev`.
fn coef_index(deg: usize, rev: bool, i: usize) -> usize {
    if rev { i } else { deg - i }
}

/// `p(τ)/q(τ)` for two polynomials of formal degree `deg` (the powers of
/// τ cancel when they are evaluated in `1/τ`).
fn ratio_at(p: &Scaled, q: &Scaled, t: C64, deg: usize) -> C64 {
    let (a, _) = p.eval(deg, t);
    let (b, _) = q.eval(deg, t);
    a.div(b)
        .scale(2f64.powi((p.top - q.top).clamp(-2000, 2000) as i32))
}

/// `p(z)/p′(z)` (the Newton correction) for p of degree n.
fn newton_ratio(p: &Scaled, n: usize, z: C64) -> C64 {
    let (v, d) = p.eval(n, z);
    if z.abs() <= 1.0 {
        v.div(d)
    } else {
        // p(z) = z^n q(y), y = 1/z: p/p′ = z·q / (n·q − y·q′)
        let y = C64::ONE.div(z);
        z.mul(v).div(v.scale(n as f64).sub(y.mul(d)))
    }
}

/// Approximations of all complex roots of `w` (square-free, degree n ≥ 1)
/// by the Aberth–Ehrlich iteration, started on circles whose radii come
/// from the upper convex hull of `(k, log₂|w_k|)` (Bini); evaluations in
/// doubles, or double-doubles where doubles cancel.  `None` when a
/// correction is not finite.
fn aberth(w: &ZPoly) -> Option<Vec<C64>> {
    let n = w.degree()?;
    if n == 0 {
        return Some(Vec::new());
    }
    let sp = Scaled::new(w);
    if sp.f[n] == 0.0 || sp.f.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let logs: Vec<Option<f64>> = w
        .coeffs()
        .iter()
        .map(|c| {
            (!c.is_zero()).then(|| {
                let b = c.bits() as i64;
                let shift = (b - 64).max(0);
                let t = (c.magnitude() >> shift as usize)
                    .to_u64()
                    .unwrap_or(u64::MAX) as f64;
                t.log2() + shift as f64
            })
        })
        .collect();
    let mut z = initial_points(&logs, n);
    let mut done = vec![false; n];
    for _ in 0..150 {
        crate::budget::check();
        let mut moved = false;
        for i in 0..n {
            if done[i] {
                continue;
            }
            let r = newton_ratio(&sp, n, z[i]);
            if !r.is_finite() {
                return None;
            }
            let s = (0..n).filter(|&j| j != i).fold(C64::ZERO, |acc, j| {
                let d = z[i].sub(z[j]);
                let q = d.re * d.re + d.im * d.im;
                acc.add(C64::new(d.re / q, -d.im / q))
            });
            let step = r.div(C64::ONE.sub(r.mul(s)));
            if !step.is_finite() {
                return None;
            }
            z[i] = z[i].sub(step);
            if step.abs() <= 1e-10 * z[i].abs() {
                done[i] = true;
            } else {
                moved = true;
            }
        }
        if !moved {
            break;
        }
    }
    // roots that did not settle to full precision are left to Newton's
    // iteration on F and the Krawczyk test
    Some(z)
}

/// Bini's starting points: for each edge `[k₀, k₁]` of the upper convex
/// hull of `(k, log₂|w_k|)`, `k₁ − k₀` points on the circle of radius
/// `2^((l₀ − l₁)/(k₁ − k₀))`, spread in angle.
fn initial_points(logs: &[Option<f64>], n: usize) -> Vec<C64> {
    let pts: Vec<(usize, f64)> = logs
        .iter()
        .enumerate()
        .filter_map(|(k, l)| l.map(|l| (k, l)))
        .collect();
    let mut hull: Vec<(usize, f64)> = Vec::new();
    for p in pts {
        while hull.len() >= 2 {
            let (a, b) = (hull[hull.len() - 2], hull[hull.len() - 1]);
            // drop b when it lies on or below the segment a–p
            let cross =
                (b.0 as f64 - a.0 as f64) * (p.1 - a.1) - (b.1 - a.1) * (p.0 as f64 - a.0 as f64);
            if cross >= 0.0 {
                hull.pop();
            } else {
                break;
            }
        }
        hull.push(p);
    }
    let mut z = Vec::with_capacity(n);
    let tau = std::f64::consts::TAU;
    for e in hull.windows(2) {
        let ((k0, l0), (k1, l1)) = (e[0], e[1]);
        let m = k1 - k0;
        let radius = 2f64.powf(((l0 - l1) / m as f64).clamp(-1000.0, 1000.0));
        for j in 0..m {
            let ang = tau * j as f64 / m as f64 + tau * z.len() as f64 / n as f64 + 0.4;
            z.push(C64::new(radius * ang.cos(), radius * ang.sin()));
        }
    }
    // a zero constant term leaves no hull edge for the root 0
    while z.len() < n {
        let ang = 0.3 + z.len() as f64;
        z.push(C64::new(1e-3 * ang.cos(), 1e-3 * ang.sin()));
    }
    z
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn zp(v: &[i64]) -> ZPoly {
        ZPoly::new(v.iter().map(|&c| BigInt::from(c)).collect())
    }

    /// The fused and Dekker's products give the same bits (both exact), so
    /// the census does not depend on the processor: the products alone, and
    /// whole double-double evaluations (also through the FMA-compiled copy
    /// when the processor has it).
    #[test]
    fn fused_and_dekker_products_agree() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            let x = crate::tests::xorshift(&mut state);
            // in (-1, 1), of varied sizes
            let m = (x >> 11) as f64 / (1u64 << 53) as f64;
            let e = (x % 40) as i32;
            if x & 1 == 0 {
                m * 2f64.powi(-e)
            } else {
                -m * 2f64.powi(-e)
            }
        };
        for _ in 0..10_000 {
            let (a, b) = (next(), next());
            let (p, e) = two_prod::<true>(a, b, split(b));
            assert_eq!((p, e), two_prod::<false>(a, b, split(b)), "{a} · {b}");
            assert!(e.abs() <= p.abs() * f64::EPSILON);
        }
        // (u − 3)(u² + 4)(u + 1)(7u − 1) and a degree-40 polynomial of
        // 200-bit coefficients
        let big: Vec<BigInt> = (0..41)
            .map(|i| (BigInt::from(3 + i) << (200 - i)) - BigInt::from(i * i))
            .collect();
        for w in [
            &(&zp(&[-12, 4, -3, 1]) * &zp(&[1, 1])) * &zp(&[-1, 7]),
            ZPoly::new(big),
        ] {
            let sp = Scaled::new(&w);
            let n = w.degree().expect("not zero");
            for _ in 0..50 {
                let z = C64::new(next(), next());
                let rev = z.abs() > 1.0;
                let want = sp.eval_dd::<false>(n, z, rev);
                assert_eq!(sp.eval_dd::<true>(n, z, rev), want);
                #[cfg(target_arch = "x86_64")]
                if std::is_x86_feature_detected!("fma") {
                    // SAFETY: the processor has FMA
                    assert_eq!(unsafe { sp.eval_dd_fma(n, z, rev) }, want);
                }
            }
        }
    }

    #[test]
    fn aberth_finds_the_roots_of_a_product() {
        // (u − 3)(u² + 4)(u + 1)(7u − 1)
        let w = &(&zp(&[-12, 4, -3, 1]) * &zp(&[1, 1])) * &zp(&[-1, 7]);
        let r = aberth(&w).expect("roots");
        assert_eq!(r.len(), 5);
        for e in [
            C64::new(3.0, 0.0),
            C64::new(0.0, 2.0),
            C64::new(0.0, -2.0),
            C64::new(-1.0, 0.0),
            C64::new(1.0 / 7.0, 0.0),
        ] {
            assert!(r.iter().any(|z| z.sub(e).abs() < 1e-9), "{e:?} in {r:?}");
        }
    }
}
