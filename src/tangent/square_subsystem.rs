//! S of degree ≥ 3 in general position: the critical points of S on E from
//! the exact RUR of a *square* subsystem, computed modulo primes and lifted
//! by the CRT with an a-priori bound ([`crate::system::rur_square`]) — no
//! reconstruction is guessed and no verification is needed.
//!
//! The critical points are the zeros of `E = 0, m = ∇S × ∇E = 0`
//! ([`super::critical`]).  For a direction `n` and a basis `a, b` of `n^⊥`
//! the square system `F = (E, a·m, b·m)` has as zeros the critical points
//! and the *extra* points of `E = n·∇E = n·∇S = 0` (where `m ∥ n`): a zero
//! of F with `m ≠ 0` has `m ∥ a × b = n`, and `m ⊥ ∇E, ∇S` then gives
//! `n·∇E = n·∇S = 0`; conversely there `∇E, ∇S ⊥ n` so `m ∥ n`.  The extras
//! are the roots of `g = gcd(w, (n·∇E)(ξ)·w′)` in the RUR `(w, V)` of F;
//! none of them is a critical point when `n·m` is non-zero at all of them
//! (checked modulo a prime: a common zero over Q̄ would stay one modulo p).
//! The critical points are then exactly the roots of `w / g`, all simple,
//! and a critical point is real iff its root is.
//!
//! The critical values: `D(u)`, the primitive part of
//! `R̄^d · ∏ (u − S(ξ))` over the critical points, again by the CRT with a
//! bound ([`crate::system::rur_square::value_polynomial`]); the value at each
//! real critical point is identified among the real roots of D by interval
//! evaluation of S on an enclosure of the point.

use super::ellipsoid::Ellipsoid;
use super::witness::WitnessSearch;
use super::witness::{WitnessPoint, find_witness, witness_at_value};
use crate::number::prime31::{Fp, prime31};
use crate::number::{Q, dyadic, dyadic_floor, qi};
use crate::poly::modp::{ModAlgebra, poly_gcd_mod, zpoly_mod};
use crate::poly::mpoly::{X, Y, Z};
use crate::poly::zpoly::DyadicSigner;
use crate::poly::{QMPoly, ZMPoly, ZPoly};
use crate::roots::{RealAlg, RootInterval, isolate_squarefree};
use crate::system::groebner_modp::zmpoly_mod;
use crate::system::krawczyk::{Dyadic3, Fix, System, ZeroBox, eval_box};
use crate::system::krawczyk_filter::{BallSystem, enclose_on};
use crate::system::rur_modular::Declined;
use crate::system::rur_square::{
    PoissonRur, ValueMap, coordinate_eliminants, solve_square, value_bound_bits, value_polynomial,
};
use crate::system::square_resultant::SquareSystem;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The directions `n` tried in turn (the first gives the sparsest system).
pub const DIRECTIONS: [[i64; 3]; 4] = [[0, 0, 1], [1, 2, 3], [3, -1, 2], [-2, 5, 1]];

/// The separating linear forms tried in turn: single variables first
/// (their multiplication matrices are sparse), z first (the smallest in
/// grevlex: the fewest dense columns).
pub const FORMS: [[i64; 3]; 4] = [[0, 0, 1], [0, 1, 0], [1, 0, 0], [1, 3, -2]];

/// The largest number of primes of one lifting.
pub const MAX_PRIMES: usize = 20_000;

/// The critical points of S on E by the Poisson route.
#[derive(Clone, Debug)]
pub struct PoissonAnalysis {
    /// The direction n.
    pub direction: [i64; 3],
    /// The square system `E, a·m, b·m` (integer, primitive).
    pub generators: [ZMPoly; 3],
    /// Its exact RUR.
    pub rur: PoissonRur,
    /// `g`: the factor of `w` at the extra points (1 when there are none).
    pub extras: ZPoly,
    /// The prime at which no extra point was shown to be critical.
    pub extras_prime: Option<u64>,
    /// `w / g`: its roots are the critical points.
    pub critical: ZPoly,
    /// The real roots of `critical` (one per real critical point).
    pub real_points: Vec<RealAlg>,
    /// S at each real critical point (same order), when D(u) has fewer
    /// distinct roots than there are critical points (S takes a value
    /// twice); empty otherwise, when the real critical values are exactly
    /// the real roots of D(u), one per real critical point.
    pub values: Vec<RealAlg>,
    /// D(u): the critical values (complex points included), square-free;
    /// `None` when only the verdict was asked for and every sign was decided
    /// without it.
    pub judging: Option<ZPoly>,
    /// Without D(u): per real critical point (order of `real_points`) the
    /// sign of S there and an enclosure of its value.
    pub enclosures: Vec<(i32, (Q, Q))>,
    /// Sombra's bound (bits) on `Res(u − S′, F)` behind D(u).
    pub value_bound_bits: u64,
    /// The number of primes of D(u).
    pub value_primes: usize,
    /// Per coordinate v = x, y, z, an upper bound (bits) on
    /// `log₂ ∏ max(1, |v(ξ)|)` over all zeros ξ of F, from the Mahler
    /// measure of the exact eliminant `Res(u − v, F)` (when it was worth
    /// computing: see [`coordinate_mahler_bits`]).
    pub coordinate_mahler_bits: Option<[u64; 3]>,
    /// The direct bound (bits) on the coefficients of `R̄^d·∏(u − S′(ξ))`
    /// that follows from them ([`direct_value_bits`]); D(u)'s CRT stops
    /// beyond the smaller of it and the Landau–Sombra bound.
    pub value_direct_bits: Option<u64>,
    /// S at a 2^-96 approximation of each real critical point, with the S
    /// it was made for (see [`PoissonAnalysis::approx_values`]).
    approx_values: std::sync::OnceLock<(QMPoly, Vec<Option<Q>>)>,
    /// w′ and the RUR's numerators prepared for floating Horner passes
    /// ([`PoissonAnalysis::approx_point`]), made on first use.
    rur_float: std::sync::OnceLock<Vec<crate::poly::horner::FloatCoeffs>>,
    /// With [`PoissonAnalysis::separates`]: the real roots of D(u),
    /// increasing (isolated once, in [`analyze`]).
    judging_roots: Vec<RealAlg>,
}

impl PoissonAnalysis {
    /// True when S takes distinct values at the critical points: D(u) has
    /// one root per critical point, and a root is real iff its point is
    /// (a non-real point and its conjugate would share a real value).
    pub fn separates(&self) -> bool {
        self.values.is_empty()
    }

    /// The values attained by real critical points (with
    /// [`PoissonAnalysis::separates`]: all real roots of D(u), increasing).
    pub fn real_values(&self) -> Vec<RealAlg> {
        match &self.judging {
            Some(_) if self.separates() => self.judging_roots.clone(),
            _ => self.values.clone(),
        }
    }

    /// S at a 2^-96 approximation of each real critical point (`None`
    /// where w′ vanished there): made once for the analysed S and shared
    /// (by the isolation of D(u)'s roots, which brackets them to about
    /// 2^-86, and the witnesses of min and max); for another S computed
    /// afresh.
    fn approx_values(&self, s: &QMPoly) -> std::borrow::Cow<'_, [Option<Q>]> {
        let values_of = || -> Vec<Option<Q>> {
            (0..self.real_points.len())
                .map(|i| Some(approx_value(s, &self.approx_point(i, VALUE_BITS)?)))
                .collect()
        };
        let cached = self.approx_values.get_or_init(|| (s.clone(), values_of()));
        if &cached.0 == s {
            std::borrow::Cow::Borrowed(&cached.1)
        } else {
            std::borrow::Cow::Owned(values_of())
        }
    }

    /// A witness with S of sign `want` near real critical point `i`.
    pub fn witness_at(
        &self,
        i: usize,
        e: &Ellipsoid,
        s: &QMPoly,
        want: i32,
    ) -> Option<WitnessPoint> {
        find_witness(e, s, want, false, &|bits| self.approx_point(i, bits))
    }

    /// The number of complex critical points.
    pub fn points(&self) -> usize {
        self.critical.degree().unwrap_or(0)
    }

    /// A rational approximation of real critical point `i` (dyadic, within
    /// about `2^-(bits+16)` of the point at a `2^-bits` approximation of
    /// its τ).  An approximation only: every use checks what it finds
    /// exactly (witnesses, the isolation of D(u)'s roots).
    pub fn approx_point(&self, i: usize, bits: u32) -> Option<[Q; 3]> {
        let t = self.real_points[i].to_rational_approx(bits);
        if let Some(p) = self.approx_point_float(&t, bits) {
            return p;
        }
        let (dn, dd) = self.rur.wd.eval_homogeneous(t.numer(), t.denom());
        if dn.is_zero() {
            return None;
        }
        Some(std::array::from_fn(|k| {
            let (n, d) = self.rur.v[k].eval_homogeneous(t.numer(), t.denom());
            let (mut num, mut den) = (n * &dd, d * &dn);
            if den.is_negative() {
                num = -num;
                den = -den;
            }
            dyadic_floor(&num, &den, bits as usize + 16)
        }))
    }

    /// [`Self::approx_point`] at a dyadic τ from floating Horner passes
    /// ([`horner_float`](crate::poly::horner::horner_float), `bits + 160`
    /// bits per step), when their error bounds leave `bits + 24` right
    /// bits in `w′(τ)` and the `Vᵢ(τ)`: the exact pass's numbers grow to
    /// `deg·bits(τ)` bits.  `None` to fall back to the exact pass.
    fn approx_point_float(&self, t: &Q, bits: u32) -> Option<Option<[Q; 3]>> {
        use crate::poly::horner::{FloatCoeffs, FloatValue, horner_float};
        let d = t.denom();
        let k = d.trailing_zeros()?;
        if d.bits() != k + 1 {
            return None;
        }
        let prec = u64::from(bits) + 160;
        let need = i64::from(bits) + 24;
        let polys = [&self.rur.wd, &self.rur.v[0], &self.rur.v[1], &self.rur.v[2]];
        let prepared = self
            .rur_float
            .get_or_init(|| polys.iter().map(|p| FloatCoeffs::new(p.coeffs())).collect());
        let at = |i: usize| -> Option<FloatValue> {
            let p = polys[i];
            if p.is_zero() {
                return None;
            }
            let v = horner_float(p.coeffs(), &prepared[i], t.numer(), k, prec, false)?;
            (v.correct_bits()? >= need).then_some(v)
        };
        let dw = at(0)?;
        let mut out: [Q; 3] = Default::default();
        for (i, (o, v)) in out.iter_mut().zip(&self.rur.v).enumerate() {
            if !v.is_zero() {
                *o = at(i + 1)?.quotient_floor(&dw, bits as usize + 16)?;
            }
        }
        Some(Some(out))
    }
}

impl WitnessSearch for PoissonAnalysis {
    /// A witness near the real critical point whose value is `v`.
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        if !self.separates() {
            return witness_at_value(&self.values, v, e, s, want, &|i, bits| {
                self.approx_point(i, bits)
            });
        }
        // the points in the order of their approximate values' distance to
        // the isolating interval of `v` (0 inside): the nearest is the
        // one (a witness is checked exactly, so an imprecise choice can
        // only cost a retry, never a wrong answer).  No refinement of
        // `v`: a root of D(u) of high degree is costly to refine.
        let (lo, hi) = v.interval();
        let approx = self.approx_values(s);
        let mut order: Vec<(Q, usize)> = approx
            .iter()
            .enumerate()
            .filter_map(|(i, v)| {
                let v = v.as_ref()?;
                let d = if v < &lo {
                    &lo - v
                } else if v > &hi {
                    v - &hi
                } else {
                    Q::zero()
                };
                Some((d, i))
            })
            .collect();
        order.sort();
        order
            .into_iter()
            .take(3)
            .find_map(|(_, i)| find_witness(e, s, want, false, &|bits| self.approx_point(i, bits)))
    }
}

/// `p` at a point with dyadic coordinates, exactly, in integers: with
/// `m_k / 2^K` the coordinates, `Σ c_α m^α 2^{K(d − |α|)}` over the common
/// denominator `2^{Kd}` (one reduction at the end).
fn approx_value(p: &QMPoly, pt: &[Q; 3]) -> Q {
    let (pz, k) = p.to_primitive_z();
    let kk = pt.iter().map(|x| x.denom().bits() - 1).max().unwrap_or(0) as usize;
    let m: Vec<BigInt> = pt
        .iter()
        .map(|x| x.numer() * (BigInt::one() << (kk - (x.denom().bits() as usize - 1))))
        .collect();
    let d = pz.total_degree().unwrap_or(0) as usize;
    // the powers m_v^e, e ≤ d, once
    let pw: Vec<Vec<BigInt>> = m
        .iter()
        .map(|mv| {
            std::iter::successors(Some(BigInt::one()), |x| Some(x * mv))
                .take(d + 1)
                .collect()
        })
        .collect();
    let mut acc = BigInt::zero();
    for (ex, c) in pz.terms() {
        let deg = (ex[X] + ex[Y] + ex[Z]) as usize;
        let mut t = c.clone();
        for (v, &e) in [ex[X], ex[Y], ex[Z]].iter().enumerate() {
            if e > 0 {
                t *= &pw[v][e as usize];
            }
        }
        acc += t << (kk * (d - deg));
    }
    // over a power of two: no gcd (nor a product when S is S′)
    let v = dyadic(acc, kk * d);
    if k.is_one() { v } else { v * k }
}

/// A basis `a, b` of the plane orthogonal to `n ≠ 0` (integer vectors).
fn orthogonal_basis(n: [i64; 3]) -> ([i64; 3], [i64; 3]) {
    // e_i × n and e_j × n (i, j the coordinates other than k) are
    // independent exactly when n_k ≠ 0: take k with |n_k| largest
    let k = (0..3)
        .max_by_key(|&i| n[i].abs())
        .expect("three coordinates");
    let e = |i: usize| {
        let mut v = [0i64; 3];
        v[i] = 1;
        v
    };
    let cross = |u: [i64; 3], v: [i64; 3]| {
        [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ]
    };
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    (cross(e(i), n), cross(e(j), n))
}

fn combine(v: [i64; 3], m: &[QMPoly; 3]) -> QMPoly {
    let mut acc = QMPoly::zero();
    for (c, p) in v.iter().zip(m) {
        if *c != 0 {
            acc = &acc + &p.scale(&qi(*c));
        }
    }
    acc
}

/// The Poisson analysis, or why it does not apply (the caller then uses
/// another route).
#[cfg(test)]
pub fn analyze(e: &Ellipsoid, s: &QMPoly, values: bool) -> Result<PoissonAnalysis, Declined> {
    analyze_minors(e, s, &super::critical::cross_gradients(s, &e.poly), values)
}

/// [`analyze`] with the minors `m` of the critical system given (`∇S × ∇E`
/// for S as given; see [`super::critical::CriticalSystem`]): the argument
/// above holds for any m of the form `F × ∇E`, with `n·F` for `n·∇S`.
pub fn analyze_minors(
    e: &Ellipsoid,
    s: &QMPoly,
    m: &[QMPoly; 3],
    values: bool,
) -> Result<PoissonAnalysis, Declined> {
    let (ez, _) = e.poly.to_primitive_z();
    let grad_e = crate::geom::gradient(&e.poly);
    let mut last = Declined("no direction tried".into());
    for n in DIRECTIONS {
        crate::budget::check_now();
        let (a, b) = orthogonal_basis(n);
        let ma = combine(a, m);
        let mb = combine(b, m);
        if ma.is_zero() || mb.is_zero() {
            continue;
        }
        let gens = [ez.clone(), ma.to_primitive_z().0, mb.to_primitive_z().0];
        let Some(mut sys) = SquareSystem::new(gens.clone()) else {
            continue;
        };
        let rur = match solve_square(&mut sys, &FORMS, MAX_PRIMES) {
            Ok(r) => r,
            Err(d) => {
                last = d;
                continue;
            }
        };
        match finish(&e.poly, s, n, m, &grad_e, gens, &sys, rur, values) {
            Ok(an) => return Ok(an),
            Err(d) => last = d,
        }
    }
    Err(last)
}

/// The real roots of `critical` (a factor of the RUR's squarefree `w`)
/// read off the census, without an isolation: `None` unless every box is
/// either real ([`CensusBox::is_real`](crate::system::census::CensusBox::is_real))
/// or proved to hold a non-real zero with a non-real `ℓ`, and the real
/// boxes' ℓ-intervals `ℓ(centre) ± Σ|ℓᵢ|·half` are pairwise disjoint.
///
/// Then `w = c·∏(u − ℓ(ξ))` has as real roots exactly the `ℓ(ξ)` of the
/// real zeros, one in each of those intervals, each simple.  `critical`
/// divides w, so on each interval it either has that root, simple (its
/// sign changes, checked exactly at the ends), or no root (the root is
/// one of the extra factor's); an end where it vanishes declines.  The
/// intervals are those of the boxes, about 2^-40 relative.
pub(crate) fn census_real_roots(
    critical: &ZPoly,
    census: &crate::system::census::ZeroCensus,
    form: [i64; 3],
) -> Option<Vec<RealAlg>> {
    let mut spans: Vec<(Q, Q)> = Vec::new();
    // |Im ℓ| over a box, below: the three-term sums in doubles are within
    // 2^-50 of the exact ones relative to Σ|ℓᵢ|·|imᵢ| (with room to spare),
    // so `|Σ ℓᵢ imᵢ| − slack > Σ|ℓᵢ|·half` proves Im ℓ ≠ 0 on the box
    let lf = form.map(|l| l as f64);
    let im_excludes_zero = |b: &crate::system::census::CensusBox| {
        let (mut mid, mut size, mut rad) = (0.0f64, 0.0f64, 0.0f64);
        for (l, z) in lf.iter().zip(&b.centre) {
            mid += l * z.im;
            size += (l * z.im).abs();
            rad += l.abs() * b.half;
        }
        let slack = size * 2f64.powi(-48) + rad * 2f64.powi(-48);
        (mid.abs() - slack - rad).is_finite() && mid.abs() - slack > rad
    };
    for b in &census.boxes {
        if b.is_real() {
            spans.push(real_ell_span(b, form)?);
        } else if !(b.misses_real_space() && im_excludes_zero(b)) {
            return None;
        }
    }
    // ends rounded outward to a grid of an eighth of the span's width
    // (short dyadics: cheap exact signs), still disjoint
    let mut spans: Vec<_> = spans.iter().map(|(a, b)| round_out(a, b)).collect();
    spans.sort_by(|a, b| a.0.cmp(&b.0));
    if spans.windows(2).any(|w| w[0].1 >= w[1].0) {
        return None;
    }
    let sq = critical.squarefree_part();
    let signer = DyadicSigner::new(&sq);
    let mut roots = Vec::new();
    for (a, b, (ma, mb, k)) in spans {
        let (sa, sb) = (signer.sign_at(&ma, k), signer.sign_at(&mb, k));
        if sa == 0 || sb == 0 {
            return None;
        }
        if sa != sb {
            roots.push(RealAlg::from_primitive(&sq, &RootInterval { lo: a, hi: b }));
        }
    }
    Some(roots)
}

/// `[a, b]` (`a < b`) widened to the grid `2^g` with `2^(g+3) ≤ b − a`:
/// the ends as rationals and as numerators over `2^k` (`k = max(0, −g)`).
fn round_out(a: &Q, b: &Q) -> (Q, Q, (BigInt, BigInt, u64)) {
    let w = b - a;
    let g = w.numer().bits() as i64 - w.denom().bits() as i64 - 4;
    let (k, sh) = ((-g).max(0) as usize, g.max(0) as usize);
    let ma = grid_index(a, g, false) << sh;
    let mb = grid_index(b, g, true) << sh;
    (
        dyadic(ma.clone(), k),
        dyadic(mb.clone(), k),
        (ma, mb, k as u64),
    )
}

/// `⌊x / 2^g⌋`, or `⌈x / 2^g⌉` when `up`: x's place on the grid `2^g`.
fn grid_index(x: &Q, g: i64, up: bool) -> BigInt {
    let (n, d) = if g <= 0 {
        (x.numer() << (-g) as usize, x.denom().clone())
    } else {
        (x.numer().clone(), x.denom() << g as usize)
    };
    if up { n.div_ceil(&d) } else { n.div_floor(&d) }
}

/// `ℓ(re centre) ± Σ|ℓᵢ|·half`, exactly: the values of ℓ on the real
/// points of the box.
fn real_ell_span(b: &crate::system::census::CensusBox, form: [i64; 3]) -> Option<(Q, Q)> {
    let q = |x: f64| crate::number::float::double_value(x);
    let h = q(b.half)?;
    let mut mid = Q::zero();
    let mut rad = Q::zero();
    for (l, z) in form.iter().zip(&b.centre) {
        let l = Q::from_integer(BigInt::from(*l));
        mid = &mid + &(&l * &q(z.re)?);
        rad = &rad + &(&l.abs() * &h);
    }
    Some((&mid - &rad, &mid + &rad))
}

/// Narrows the isolating intervals of the real roots from the census:
/// a box that meets the real space (every imaginary part within its
/// half-width) gives the interval `ℓ(re centre) ± Σ|ℓᵢ|·half`, which holds
/// ℓ at the box's zero if that zero is real; each root's interval is
/// narrowed to the first such interval inside it where the defining
/// polynomial changes sign ([`RealAlg::narrow_within`]: exact signs decide,
/// the boxes only propose).  The 2^-64 refinement then starts from about
/// 2^-40 instead of from the isolation's widths.
fn narrow_from_census(
    points: &mut [RealAlg],
    census: &crate::system::census::ZeroCensus,
    form: [i64; 3],
) {
    let spans: Vec<(Q, Q)> = census
        .boxes
        .iter()
        .filter(|b| b.centre.iter().all(|z| z.im.abs() <= b.half))
        .filter_map(|b| real_ell_span(b, form))
        .collect();
    for p in points.iter_mut() {
        for (a, b) in &spans {
            if p.narrow_within(a, b) {
                break;
            }
        }
    }
}

/// `K(ξ)·w′` for a polynomial K of degree ≤ 1 at the RUR (the numerator of
/// K at the zero of root τ).
fn linear_at_rur(k: &QMPoly, rur: &PoissonRur) -> ZPoly {
    let (kz, _) = k.to_primitive_z();
    let mut acc = ZPoly::zero();
    for (ex, c) in kz.terms() {
        let part = match (ex[X], ex[Y], ex[Z]) {
            (1, 0, 0) => &rur.v[0],
            (0, 1, 0) => &rur.v[1],
            (0, 0, 1) => &rur.v[2],
            _ => &rur.wd,
        };
        acc = &acc + &part.scale(c);
    }
    acc
}

/// True when `h` vanishes at no root of `g` (`g` a factor of `rur.w`):
/// `gcd(g_p, h(ξ(T))) = 1` in `F_p[T]/(g_p)` at a prime keeping the degree
/// of g with `w′` invertible.  Returns that prime.
fn nonzero_at_roots(rur: &PoissonRur, g: &ZPoly, h: &ZMPoly) -> Option<u64> {
    let ng = g.degree()?;
    // h is evaluated in its packed form modulo p
    if h.total_degree().unwrap_or(0) > crate::system::groebner_modp::MAX_DEGREE {
        return None;
    }
    for k in 0..8 {
        let fp = Fp::new(prime31(1000 + k));
        let gm = zpoly_mod(&fp, g);
        if gm.last() == Some(&0) {
            continue;
        }
        let alg = ModAlgebra::from_poly(fp, &gm)?;
        let reduce = |p: &ZPoly| -> Vec<u64> {
            let a = zpoly_mod(&fp, p);
            let mut r = poly_rem(&fp, &a, &gm);
            r.resize(ng, 0);
            r
        };
        let Some(dinv) = alg.inv(&reduce(&rur.wd)) else {
            continue;
        };
        let xs: Vec<Vec<u64>> = rur.v.iter().map(|v| alg.mul(&reduce(v), &dinv)).collect();
        let val = alg.eval(&zmpoly_mod(&fp, h), [&xs[0], &xs[1], &xs[2]]);
        // a common root over Q̄ stays one modulo every such prime; a common
        // factor modulo p alone only makes this prime unlucky
        if poly_gcd_mod(&fp, &gm, &val).len() == 1 {
            return Some(fp.p);
        }
    }
    None
}

fn poly_rem(fp: &Fp, a: &[u64], b: &[u64]) -> Vec<u64> {
    let mut r = a.to_vec();
    while r.last() == Some(&0) {
        r.pop();
    }
    let db = b.len() - 1;
    let inv = fp.inv(b[db]).expect("non-zero leading coefficient");
    while r.len() > db {
        let k = r.len() - 1 - db;
        let t = fp.mul(*r.last().expect("non-empty"), inv);
        for j in 0..db {
            r[k + j] = fp.sub(r[k + j], fp.mul(t, b[j]));
        }
        r.pop();
        while r.last() == Some(&0) {
            r.pop();
        }
    }
    r
}

#[allow(clippy::too_many_arguments)]
fn finish(
    e: &QMPoly,
    s: &QMPoly,
    n: [i64; 3],
    m: &[QMPoly; 3],
    grad_e: &[QMPoly; 3],
    generators: [ZMPoly; 3],
    sys: &SquareSystem,
    rur: PoissonRur,
    values: bool,
) -> Result<PoissonAnalysis, Declined> {
    let decline = |s: &str| Err(Declined(s.into()));
    // the extra points: roots of w where n·∇E vanishes
    let l = combine(n, grad_e);
    let lv = linear_at_rur(&l, &rur);
    let g = rur.w.gcd(&lv);
    let (extras, extras_prime) = if g.degree().unwrap_or(0) == 0 {
        (ZPoly::constant(BigInt::one()), None)
    } else {
        let nm = combine(n, m).to_primitive_z().0;
        match nonzero_at_roots(&rur, &g, &nm) {
            Some(p) => (g, Some(p)),
            None => return decline("a critical point lies on the silhouette of the direction"),
        }
    };
    let critical = rur
        .w
        .div_exact(&extras)
        .ok_or_else(|| Declined("the extra factor does not divide w".into()))?;
    if critical.degree().unwrap_or(0) == 0 {
        return decline("no critical point");
    }
    let from_census = rur
        .census
        .as_ref()
        .and_then(|c| census_real_roots(&critical, &c.zeros, rur.form));
    let mut real_points = match from_census {
        Some(r) => r,
        None => {
            let mut r = RealAlg::roots_of(&critical);
            if let Some(c) = &rur.census {
                narrow_from_census(&mut r, &c.zeros, rur.form);
            }
            r
        }
    };
    // refined once, in place, to 2^-96: the boxes (from 2^-64), the values'
    // approximations (2^-96), the witnesses and the printed 20 digits then
    // refine no copies
    let w96 = Q::new(BigInt::one(), BigInt::one() << 96usize);
    for p in real_points.iter_mut() {
        p.refine_to(&w96);
        p.refine_for_approx(20);
    }
    if real_points.is_empty() {
        // S attains its extremes on the compact E at real critical points
        return decline("no real critical point (inconsistent)");
    }
    let mut an = PoissonAnalysis {
        direction: n,
        generators,
        rur,
        extras,
        extras_prime,
        critical,
        real_points,
        values: Vec::new(),
        judging: None,
        enclosures: Vec::new(),
        value_bound_bits: 0,
        value_primes: 0,
        coordinate_mahler_bits: None,
        value_direct_bits: None,
        approx_values: std::sync::OnceLock::new(),
        rur_float: std::sync::OnceLock::new(),
        judging_roots: Vec::new(),
    };
    if !values {
        // the verdict from the signs of S at the real critical points; D(u)
        // only when a sign is not decided (a critical value 0, or nearly)
        let l_int = l.to_primitive_z().0;
        let boxed = box_signs(&an.generators, &l_int, &an.rur, s, &an.real_points);
        if let Some(enclosures) = boxed.or_else(|| point_signs(&an.rur, s, &an.real_points)) {
            an.enclosures = enclosures;
            return Ok(an);
        }
    }
    // D(u) for the integer S′ (S = k·S′), then scaled to S
    let (sz, k) = s.to_primitive_z();
    let bits = value_bound_bits(sys, &sz);
    // S is evaluated reduced modulo E (degree ≤ 1 in x: fewer products),
    // which it equals at every critical point
    let (sr, kr) = reduce_mod_ellipsoid(s, e).to_primitive_z();
    let degree = sz.total_degree().unwrap_or(0);
    let nf = an.critical.degree().unwrap_or(0);
    an.value_direct_bits = match census_value_bits(&an.rur, &sz) {
        Some(b) => Some(b),
        None => {
            an.coordinate_mahler_bits =
                coordinate_mahler_bits(&an.rur, &sz, bits, nf, sys.bezout())?;
            an.coordinate_mahler_bits
                .map(|m| direct_value_bits(&an.rur, &sz, nf, &m))
        }
    };
    let map = ValueMap {
        degree,
        eval: &sr,
        scale: &(&kr / &k),
        direct_bits: an.value_direct_bits,
    };
    let (t, value_primes) =
        value_polynomial(&an.rur, &an.critical, &map, bits, sys.bezout(), MAX_PRIMES)?;
    let d_prime = t.primitive_part();
    let judging = scale_roots(&d_prime, &k).squarefree_part();
    if judging.degree() != an.critical.degree() {
        an.values = identify_values(&an.rur, &an.real_points, s, &judging)?;
    }
    if an.separates() {
        an.judging_roots = isolate_by_values(&judging, &an.approx_values(s))
            .unwrap_or_else(|| RealAlg::roots_of(&judging));
    }
    an.judging = Some(judging);
    an.value_bound_bits = bits;
    an.value_primes = value_primes;
    Ok(an)
}

#[cfg(test)]
thread_local! {
    /// Tests: D(u) from the Landau–Sombra bound alone (no direct bound).
    pub(crate) static GENERAL_BOUND_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// `⌈log₂ ‖h‖₁⌉` (the sum of the absolute values of the coefficients).
fn l1_bits(h: &ZMPoly) -> u64 {
    let l1: BigInt = h.terms().iter().map(|(_, c)| c.abs()).sum();
    l1.bits()
}

/// The direct bound (bits) on the coefficients of `A = R̄^d·∏(u − S′(ξ))`
/// over the `nf` critical points, from the coordinate bounds `m`
/// (`m_v ≥ log₂ ∏_ξ max(1, |v(ξ)|)` over all zeros of F):
/// `|S′(ξ)| ≤ ‖S′‖₁·∏_v max(1, |v(ξ)|)^d` (every monomial has degree ≤ d),
/// so `∏ max(1, |S′(ξ)|) ≤ ‖S′‖₁^nf·2^(d·Σ m_v)`, and a coefficient of A
/// is at most `|R̄|^d·C(nf, i)·∏ max(1, |S′(ξ)|)` with `C(nf, i) ≤ 2^nf`.
pub(crate) fn direct_value_bits(rur: &PoissonRur, h: &ZMPoly, nf: usize, m: &[u64; 3]) -> u64 {
    let d = h.total_degree().unwrap_or(0) as u64;
    let nf = nf as u64;
    d * rur.leading_resultant().bits() + nf + nf * l1_bits(h) + d * m.iter().sum::<u64>()
}

/// With the RUR's census of all zeros of F: the bound (bits) on the
/// coefficients of `A = R̄^d·∏(u − S′(ξ))` over the critical points,
/// `d·bits(R̄) + b` with `∏_ξ (1 + |S′(ξ)|) < 2^b` over all zeros (S′
/// enclosed on every box): a coefficient of `∏(u − a_ξ)` is at most
/// `∏(1 + |a_ξ|)`, and the factors of the zeros left out are ≥ 1.
fn census_value_bits(rur: &PoissonRur, h: &ZMPoly) -> Option<u64> {
    #[cfg(test)]
    if GENERAL_BOUND_ONLY.with(|c| c.get()) {
        return None;
    }
    let c = rur.census.as_ref()?;
    let d = h.total_degree().unwrap_or(0) as u64;
    Some(d * c.rbar.bits() + c.zeros.polynomial_bits(h)?)
}

/// The coordinate bounds of [`direct_value_bits`], when they promise to
/// save work: `None` unless the estimate from w alone (w is the
/// eliminant of ℓ, exact already) saves D(u) at least two thirds as many
/// bits of primes as the eliminants cost (a prime of D(u) costs about 1.5
/// characteristic polynomials, one of an eliminant one; the eliminants
/// need the RUR's bound, once per coordinate other than ℓ); otherwise the
/// three exact eliminants `P_v = Res(u − v, F)` ([`coordinate_eliminants`]) give
/// `∏_ξ max(1, |v(ξ)|) = M(P_v)/|R̄| ≤ ‖P_v‖₂/|R̄|` (Landau's inequality),
/// i.e. at most `bits(‖P_v‖∞) + ⌈bits(n + 1)/2⌉ − (bits(R̄) − 1)` bits.
fn coordinate_mahler_bits(
    rur: &PoissonRur,
    h: &ZMPoly,
    resultant_bits: u64,
    nf: usize,
    bezout: usize,
) -> Result<Option<[u64; 3]>, Declined> {
    let sqrt_bits = crate::system::rur_square::sqrt_bits(rur.w.degree().unwrap_or(0) + 1);
    let rb = rur.leading_resultant().bits();
    let mahler = |p: &ZPoly| -> u64 {
        let top = p.coeffs().iter().map(|c| c.bits()).max().unwrap_or(0);
        (top + sqrt_bits).saturating_sub(rb - 1)
    };
    let guess = mahler(&rur.w);
    let estimate = direct_value_bits(rur, h, nf, &[guess; 3]);
    let target = crate::system::rur_square::value_target_bits(resultant_bits, nf, bezout, None);
    #[cfg(test)]
    if GENERAL_BOUND_ONLY.with(|c| c.get()) {
        return Ok(None);
    }
    let others = (0..3)
        .filter(|&v| rur.form != crate::system::rur_square::unit_form(v))
        .count() as u64;
    if 3 * target.saturating_sub(estimate) <= 2 * others * rur.bound_bits {
        return Ok(None);
    }
    // without them (the prime limit) the general bound serves
    Ok(coordinate_eliminants(rur, MAX_PRIMES)
        .ok()
        .map(|elims| [0, 1, 2].map(|v| mahler(&elims[v]))))
}

/// The real roots of D(u) (square-free, primitive, positive leading
/// coefficient) when S separates the critical points, isolated from
/// approximations of S at the R real critical points instead of by
/// Descartes' rule: D then has exactly R real roots (a real value at a
/// non-real point would be shared by its conjugate), so separators
/// `t₁ < … < t_{R−1}` between the sorted approximations at which D's sign
/// alternates (starting from its sign at −∞) cut the line into R intervals
/// with an odd number of roots each, hence exactly one.  Each root is then
/// narrowed, when two more signs confirm it, to about 2^-24 relative around
/// its approximation, which the printed 20 digits refine from.  The
/// approximations only choose where D is evaluated: every conclusion rests on
/// exact signs of D.  `None` (and Descartes' rule instead) when an
/// approximation is missing, two coincide, or a sign does not alternate.
pub(crate) fn isolate_by_values(d: &ZPoly, approx: &[Option<Q>]) -> Option<Vec<RealAlg>> {
    let mut v: Vec<Q> = approx.iter().cloned().collect::<Option<_>>()?;
    v.sort();
    if v.is_empty() || v.windows(2).any(|w| w[0] == w[1]) {
        return None;
    }
    let n = d.degree()?;
    let lead = d.lc().sign() == num_bigint::Sign::Plus;
    let at_minus_inf = if lead == (n % 2 == 0) { 1 } else { -1 };
    // ends beyond every complex root: D has its signs at ±∞ there
    let k = d.root_bound_log2()?.max(0) as usize;
    let big = Q::from_integer(BigInt::one() << k);
    let mut ends = vec![-big.clone()];
    let mut separators = Vec::new();
    for w in v.windows(2) {
        // the shortest dyadic in the middle half between neighbours (its
        // sign is then a short floating Horner pass, usually)
        let q = (&w[1] - &w[0]) / Q::from_integer(BigInt::from(4));
        let (m, k) = short_dyadic_in(&(&w[0] + &q), &(&w[1] - &q));
        ends.push(dyadic(m.clone(), k as usize));
        separators.push((m, k));
    }
    ends.push(big);
    if ends.windows(2).any(|w| w[0] >= w[1]) {
        return None;
    }
    // D's signs at −2^k, t₁, …, t_{R−1}, 2^k must alternate
    let signer = DyadicSigner::new(d);
    let mut sign = at_minus_inf;
    for (m, k) in &separators {
        let st = signer.sign_at(m, *k);
        if st != -sign {
            return None;
        }
        sign = st;
    }
    let at_plus_inf = if lead { 1 } else { -1 };
    if at_plus_inf != -sign {
        return None;
    }
    // every interval (ends[i], ends[i+1]) holds exactly one root; narrow it
    // around v[i] where D's signs confirm
    let mut s_lo = at_minus_inf;
    let roots = (0..v.len())
        .map(|i| {
            let (a, b) = (&ends[i], &ends[i + 1]);
            let iv = narrow_around(&signer, &v[i], s_lo, a, b).unwrap_or_else(|| RootInterval {
                lo: a.clone(),
                hi: b.clone(),
            });
            s_lo = -s_lo;
            RealAlg::from_primitive(d, &iv)
        })
        .collect();
    Some(roots)
}

/// The dyadic `m/2^k` in `[lo, hi]` (`lo < hi`) with the least `k ≥ 0`.
pub(crate) fn short_dyadic_in(lo: &Q, hi: &Q) -> (BigInt, u64) {
    let w = hi - lo;
    // a step 2^-k ≤ w always has a multiple in [lo, hi]
    let enough = (w.denom().bits() as i64 - w.numer().bits() as i64 + 1).max(0) as u64;
    for k in 0..enough {
        let m = (lo.numer() << k as usize).div_ceil(lo.denom());
        if dyadic(m.clone(), k as usize) <= *hi {
            return (m, k);
        }
    }
    ((lo.numer() << enough as usize).div_ceil(lo.denom()), enough)
}

/// A bracket of about 2^-86 (failing that, 2^-22) relative width around
/// `v` inside `(a, b)`, on which D (of sign `s_lo` just above `a`, one root
/// in `(a, b)`) changes sign: dyadic ends 2^8 steps of a grid of about
/// 2^-95·|v| (2^-31·|v|) from `v`.
fn narrow_around(signer: &DyadicSigner, v: &Q, s_lo: i32, a: &Q, b: &Q) -> Option<RootInterval> {
    // first as fine as the value allows (about 2^-86 of |v|: the printed
    // 20 digits need no refinement), then at 2^-22
    [i64::from(VALUE_BITS) - 1, 31]
        .into_iter()
        .find_map(|digits| narrow_on_grid(signer, v, s_lo, a, b, digits))
}

/// The values of S at real critical points are computed from `2^-VALUE_BITS`
/// approximations of their τ ([`PoissonAnalysis::approx_values`]).
const VALUE_BITS: u32 = 96;

/// [`narrow_around`] on the grid `2^g`, `g = log₂|v| − digits`: the
/// bracket `[(t − 256)·2^g, (t + 257)·2^g]`, `t = ⌊v / 2^g⌋`.
fn narrow_on_grid(
    signer: &DyadicSigner,
    v: &Q,
    s_lo: i32,
    a: &Q,
    b: &Q,
    digits: i64,
) -> Option<RootInterval> {
    let g = v.numer().bits() as i64 - v.denom().bits() as i64 - digits;
    let t = grid_index(v, g, false);
    // the ends (t − 256)·2^g and (t + 257)·2^g as numerators over 2^k
    let (k, sh) = ((-g).max(0) as usize, g.max(0) as usize);
    let (ml, mh): (BigInt, BigInt) = ((&t - 256) << sh, (&t + 257) << sh);
    let (lo, hi) = (dyadic(ml.clone(), k), dyadic(mh.clone(), k));
    if &lo <= a || &hi >= b {
        return None;
    }
    (signer.sign_at(&ml, k as u64) == s_lo && signer.sign_at(&mh, k as u64) == -s_lo)
        .then_some(RootInterval { lo, hi })
}

/// The remainder of `s` by `e` as polynomials in x (`e` of degree 2 in x
/// with a constant leading coefficient, as an ellipsoid's): degree ≤ 1 in
/// x, total degree ≤ deg s, equal to `s` wherever `e = 0`.
fn reduce_mod_ellipsoid(s: &QMPoly, e: &QMPoly) -> QMPoly {
    let e2 = e
        .terms()
        .iter()
        .find(|(ex, _)| ex[X] == 2)
        .map(|(_, c)| c.clone())
        .expect("an ellipsoid has an x² term");
    // e = e2·x² + rest: x² ≡ −rest/e2
    let rest = &(e - &QMPoly::monomial(e2.clone(), {
        let mut x2 = [0u32; crate::poly::mpoly::NVARS];
        x2[X] = 2;
        x2
    }))
        .scale(&(-Q::one() / &e2));
    let mut r = s.clone();
    loop {
        let Some(top) = r
            .terms()
            .iter()
            .filter(|(ex, _)| ex[X] >= 2)
            .max_by_key(|(ex, _)| ex[X])
            .cloned()
        else {
            return r;
        };
        // replace every term with x^a, a ≥ 2, of the highest a at once
        let a = top.0[X];
        let (hi, lo): (Vec<_>, Vec<_>) = r.terms().iter().cloned().partition(|(ex, _)| ex[X] == a);
        let mut hi_poly = QMPoly::from_terms(hi.into_iter().map(|(mut ex, c)| {
            ex[X] -= 2;
            (ex, c)
        }));
        hi_poly = &hi_poly * rest;
        r = &QMPoly::from_terms(lo) + &hi_poly;
    }
}

/// The polynomial whose roots are `k·r` for the roots r of `p` (primitive).
fn scale_roots(p: &ZPoly, k: &Q) -> ZPoly {
    // p(u/k) = Σ c_i u^i k^{-i}; times a^N (k = a/b): c_i b^i a^{N−i}
    let (a, b) = (k.numer().clone(), k.denom().clone());
    let nn = p.degree().unwrap_or(0);
    let c: Vec<BigInt> = p
        .coeffs()
        .iter()
        .enumerate()
        .map(|(i, ci)| ci * num_traits::pow(b.clone(), i) * num_traits::pow(a.clone(), nn - i))
        .collect();
    ZPoly::new(c).primitive_part()
}

/// An enclosure of `p` on a box with dyadic ends, in fixed-point interval
/// arithmetic at the finest scale `2^-k` of the ends (exact conversion,
/// outward rounding of each product: [`eval_box`]).
fn box_eval(p: &QMPoly, bx: &[(Q, Q); 3]) -> (Q, Q) {
    let (pz, scale) = p.to_primitive_z();
    let k = bx
        .iter()
        .flat_map(|(a, b)| [a.denom().bits(), b.denom().bits()])
        .max()
        .unwrap_or(1) as usize;
    // ⌊q·2^k⌋ and ⌈q·2^k⌉ (exact for the dyadic ends this is used with)
    let fix_lo =
        |q: &Q| -> BigInt { num_integer::Integer::div_floor(&(q.numer() << k), q.denom()) };
    let fix_hi =
        |q: &Q| -> BigInt { -num_integer::Integer::div_floor(&(-q.numer() << k), q.denom()) };
    let fbox: [Fix; 3] = std::array::from_fn(|i| Fix {
        lo: fix_lo(&bx[i].0),
        hi: fix_hi(&bx[i].1),
    });
    let (a, b) = eval_box(&pz, &fbox, k).to_q(k);
    let (a, b) = (a * &scale, b * &scale);
    if scale.is_negative() { (b, a) } else { (a, b) }
}

/// `[lo, hi]` widened to the grid `2^-g`: `[⌊lo·2^g⌋, ⌈hi·2^g⌉]/2^g` (the
/// same interval when its ends are on the grid already).
fn outward((lo, hi): (Q, Q), g: u32) -> (Q, Q) {
    let down = grid_index(&lo, -i64::from(g), false);
    let up = grid_index(&hi, -i64::from(g), true);
    (dyadic(down, g as usize), dyadic(up, g as usize))
}

/// An enclosure of S at the zero of the RUR whose τ lies in `[lo, hi]`.
fn enclose_value(rur: &PoissonRur, s: &QMPoly, lo: &Q, hi: &Q) -> Option<(Q, Q)> {
    let den = (rur.wd.clone(), Q::one());
    let mut bx: [(Q, Q); 3] = std::array::from_fn(|_| (Q::zero(), Q::zero()));
    for (k, b) in bx.iter_mut().enumerate() {
        *b = crate::roots::ratio_enclosure(&(rur.v[k].clone(), Q::one()), &den, lo, hi)?;
    }
    Some(box_eval(s, &bx))
}

/// The signs of S at the real critical points from certified boxes of
/// the points in the original system (Krawczyk: [`System::certify`]),
/// started from the RUR at a 64-bit approximation of each root: one box
/// per real root of `critical`, pairwise disjoint, each holding exactly one
/// zero of the square system on which `n·∇E ≠ 0` (so a critical point, not
/// an extra) — as many distinct real critical points as there are, hence
/// all of them.  S is enclosed on each box; a sign the verdict needs is
/// sharpened on finer boxes (to 4096 bits).  `None` when a step fails (the
/// caller then encloses S through the RUR, or computes D(u)).
fn box_signs(
    gens: &[ZMPoly; 3],
    l: &ZMPoly,
    rur: &PoissonRur,
    s: &QMPoly,
    points: &[RealAlg],
) -> Option<Vec<(i32, (Q, Q))>> {
    let sys = System::new(gens.clone());
    // the float filter first (a success is a proof), the integer test when
    // it declines
    let filter = BallSystem::new(&sys);
    let (sz, scale) = s.to_primitive_z();
    let sgn = if scale.is_negative() { -1 } else { 1 };
    let mut boxes: Vec<ZeroBox> = Vec::with_capacity(points.len());
    for a in points {
        crate::budget::check_now();
        let t = a.to_rational_approx(64);
        let not_extra = |b: &ZeroBox| eval_box(l, &b.enclosure, b.k).sign() != 0;
        // the filter from the point at τ rounded to 24 bits (a shorter
        // evaluation of the RUR; Newton does the rest), then at 64 bits
        let by_filter = |start: &Dyadic3| -> Option<ZeroBox> {
            filter.as_ref()?.certify(start).filter(not_extra)
        };
        let b = rur
            .point_dyadic(&round_relative(&t, 24), 64)
            .and_then(|start| by_filter(&start))
            .or_else(|| {
                let start = rur.point_dyadic(&t, 64)?;
                by_filter(&start).or_else(|| {
                    [64usize, 128, 256].iter().find_map(|&bits| {
                        let b = sys.certify(&start, bits)?;
                        not_extra(&b).then_some(b)
                    })
                })
            })?;
        if boxes.iter().any(|o| !o.disjoint(&b)) {
            return None;
        }
        boxes.push(b);
    }
    let sign_on = |b: &ZeroBox| -> (i32, (Q, Q)) {
        // the ball enclosure when it decides the sign, else the integer one
        let (sign, (lo, hi)) = match enclose_on(&sz, b) {
            Some(e) if e.0 != 0 => e,
            _ => {
                let v = eval_box(&sz, &b.enclosure, b.k);
                (v.sign(), v.to_q(b.k))
            }
        };
        let (lo, hi) = (lo * &scale, hi * &scale);
        let iv = if sgn < 0 { (hi, lo) } else { (lo, hi) };
        (sign * sgn, iv)
    };
    let mut out: Vec<(i32, (Q, Q))> = boxes.iter().map(sign_on).collect();
    let both = out.iter().any(|o| o.0 < 0) && out.iter().any(|o| o.0 > 0);
    if !both {
        for (o, b) in out.iter_mut().zip(&boxes) {
            let mut bits = 128;
            while o.0 == 0 && bits <= 4096 {
                crate::budget::check_now();
                let finer = sys.certify(&b.center(), bits)?;
                *o = sign_on(&finer);
                bits *= 2;
            }
            if o.0 == 0 {
                return None;
            }
        }
    }
    Some(out)
}

/// `t` rounded down to `bits` significant bits (a dyadic; `t` itself when
/// it is 0 or has no more than that).
fn round_relative(t: &Q, bits: u32) -> Q {
    if t.is_zero() {
        return t.clone();
    }
    let e = bits as i64 - 1 - crate::number::floor_log2_q(&t.abs());
    if e < 0 {
        return t.clone();
    }
    let m = (t.numer() << e as usize).div_floor(t.denom());
    crate::number::dyadic(m, e as usize)
}

/// The sign of S at every real critical point with an enclosure of the
/// value, as far as the verdict needs it: all points up to 64 bits; once
/// both signs occur the verdict is `intersecting` and the others may stay
/// undecided (sign 0, an enclosure containing 0); otherwise each undecided
/// point is refined up to 4096 bits.  `None` when a sign the verdict needs
/// stays undecided (a critical value 0, or within about 2^-4096 of it): the
/// exact values are needed.
fn point_signs(rur: &PoissonRur, s: &QMPoly, points: &[RealAlg]) -> Option<Vec<(i32, (Q, Q))>> {
    let mut out: Vec<(i32, Option<(Q, Q)>)> = points
        .iter()
        .map(|a| sign_at_point(rur, s, a, 64, false))
        .collect();
    let both = out.iter().any(|o| o.0 < 0) && out.iter().any(|o| o.0 > 0);
    for (o, a) in out.iter_mut().zip(points) {
        if o.0 == 0 && !(both && o.1.is_some()) {
            // with both signs, any enclosure will do for the certificate
            *o = sign_at_point(rur, s, a, 4096, both);
            if !both && o.0 == 0 {
                return None;
            }
        }
    }
    out.into_iter()
        .map(|(sign, iv)| Some((sign, iv?)))
        .collect()
}

/// The sign of S at the real critical point of RUR root `alpha`, with an
/// enclosure of the value: S is enclosed on a shrinking interval of α
/// (32, 64, … up to `max_bits` bits) until the enclosure excludes 0.  Sign 0
/// when it never does (with the last enclosure, which contains 0, if any)
/// and at a rational root where S is exactly 0.  With `any`, the first
/// enclosure found is returned, whatever its sign.
fn sign_at_point(
    rur: &PoissonRur,
    s: &QMPoly,
    alpha: &RealAlg,
    max_bits: u32,
    any: bool,
) -> (i32, Option<(Q, Q)>) {
    let mut a = alpha.clone();
    let mut bits = 32u32;
    let mut last = None;
    while bits <= max_bits {
        crate::budget::check_now();
        if let Some(x) = a.as_rational() {
            let Some(pt) = rur.point_at(x) else {
                return (0, None);
            };
            let mut full: [Q; 6] = std::array::from_fn(|_| Q::zero());
            full[..3].clone_from_slice(&pt);
            let v = s.eval(&full);
            return (crate::number::sign_q(&v), Some((v.clone(), v)));
        }
        // the interval rounded outwards to the stage's grid: a point
        // refined further (to 2^-96, for printing) gives no longer numbers
        let (lo, hi) = outward(a.interval(), bits.max(64));
        if let Some((vl, vh)) = enclose_value(rur, s, &lo, &hi) {
            if vl.is_positive() {
                return (1, Some((vl, vh)));
            }
            if vh.is_negative() {
                return (-1, Some((vl, vh)));
            }
            if any {
                return (0, Some((vl, vh)));
            }
            last = Some((vl, vh));
        }
        a.refine_relative(bits);
        bits *= 2;
    }
    (0, last)
}

/// S at each real critical point as a root of `judging`: the enclosure of
/// S on a shrinking interval of τ meets exactly one isolating interval.
fn identify_values(
    rur: &PoissonRur,
    points: &[RealAlg],
    s: &QMPoly,
    judging: &ZPoly,
) -> Result<Vec<RealAlg>, Declined> {
    let mut ivs = isolate_squarefree(judging);
    let mut out = Vec::with_capacity(points.len());
    for p in points {
        let mut a = p.clone();
        let mut found = None;
        for round in 0..200 {
            crate::budget::check_now();
            if let Some(x) = a.as_rational() {
                let pt = rur
                    .point_at(x)
                    .ok_or_else(|| Declined("w′ vanishes at a rational root".into()))?;
                let mut full = [
                    Q::zero(),
                    Q::zero(),
                    Q::zero(),
                    Q::zero(),
                    Q::zero(),
                    Q::zero(),
                ];
                full[..3].clone_from_slice(&pt);
                found = Some(RealAlg::rational(s.eval(&full)));
                break;
            }
            let (lo, hi) = a.interval();
            // first on the 2^-64 grid (shorter numbers), then as refined
            let (el, eh) = if round == 0 {
                outward((lo.clone(), hi.clone()), 64)
            } else {
                (lo.clone(), hi.clone())
            };
            if let Some((vl, vh)) = enclose_value(rur, s, &el, &eh) {
                let hits: Vec<usize> = (0..ivs.len())
                    .filter(|&j| crate::roots::meets(&ivs[j], &vl, &vh))
                    .collect();
                if hits.len() == 1 {
                    found = Some(RealAlg::from_interval(judging, &ivs[hits[0]]).simplify());
                    break;
                }
                for j in hits {
                    crate::roots::bisect_once(judging, &mut ivs[j]);
                }
            }
            let w = (&hi - &lo) / Q::from_integer(BigInt::from(1u32 << 16));
            a.refine_to(&w);
        }
        out.push(found.ok_or_else(|| {
            Declined("the value at a real critical point was not identified".into())
        })?);
    }
    Ok(out)
}
