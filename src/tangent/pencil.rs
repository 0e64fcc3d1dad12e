//! S of degree ≤ 2, the generic case, by the pencil `S − λE − u`: all
//! critical values of S on E from one quartic discriminant, in integer
//! arithmetic (the fast path in front of [`super::quadric`]).
//!
//! With `Ŝ`, `Ê` the 4×4 symmetric matrices of S and E (E oriented, E < 0
//! inside) and `S₃`, `E₃` their 3×3 blocks, let
//!
//! * `F(λ) = det(Ŝ − λÊ)` (degree 4) and `δ(λ) = det(S₃ − λE₃)` (degree 3);
//! * `g(λ) = F(λ)/δ(λ)`: where `δ(λ) ≠ 0`, the quadric `S − λE` has one
//!   centre `x(λ)`, and `g(λ) = (S − λE)(x(λ))` (Schur complement);
//! * `P(λ) = F'δ − Fδ' = δ²·g'`, and `g'(λ) = −E(x(λ))` (envelope theorem),
//!   so `P(λ) = 0` exactly when `x(λ)` lies on E: then `x(λ)` is a critical
//!   point of S on E with multiplier λ and value `g(λ)`;
//! * `D(u) = disc_λ(F(λ) − u·δ(λ))`, a polynomial of degree ≤ 6 computed
//!   from the invariants of the quartic: `27·disc = 4I³ − J²`.
//!
//! **The test.** If `gcd(P, δ) = 1` and D has degree 6 and is square-free,
//! then the real roots of D are exactly the critical values of S on E at
//! real points, so ν = the smallest and μ = the largest real root of D.
//! Proof: a common root of F and δ, or a double root of δ, is a root of P,
//! so `gcd(P, δ) = 1` gives `gcd(F, δ) = 1` and δ square-free.  At a
//! singular multiplier λ₀ with a critical point, `S − λ₀E` has a centre, so
//! `F(λ₀) = 0 = δ(λ₀)` — excluded; hence every real critical point is
//! `x(λ)` for a real root λ of P, and `F − g(λ)δ` has the double root λ,
//! so `D(g(λ)) = 0`.  Conversely a root u of D makes `F − uδ` have a double
//! root λ₀; then `P(λ₀) = 0`, `δ(λ₀) ≠ 0` and `u = g(λ₀)`.  So the roots of
//! D lie in `{g(λᵢ) : P(λᵢ) = 0}`, a set of at most 6 values; six distinct
//! roots make g injective on the six roots of P, and a non-real λᵢ would
//! share its real value with its conjugate.  Hence every real root of D
//! comes from a real λᵢ, i.e. from the real critical point `x(λᵢ)` of E.
//!
//! When the test fails (symmetric inputs: concentric or coaxial surfaces,
//! singular multipliers, degenerate critical points) the complete
//! λ-parametrisation of [`super::quadric`] answers instead.

use super::ellipsoid::Ellipsoid;
use super::witness::{WitnessPoint, find_witness};
use crate::geom::{Mat4, QuadricForm, adj3_int, common_denominator};
use crate::number::Q;
use crate::poly::{QMPoly, ZPoly};
use crate::roots::{RealAlg, isolate_squarefree};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// The pencil analysis of a quadric S against E (generic case).
#[derive(Clone, Debug)]
pub struct PencilAnalysis {
    /// The positive integer `L` making `L·E` and `L·S` integral; the
    /// polynomials in λ below belong to `Ŝ = L·S` and `Ê = L·E` (the
    /// multipliers are those of S and E themselves).
    pub scale: BigInt,
    /// `F(λ) = det(Ŝ − λÊ)`.
    pub char_poly: ZPoly,
    /// `δ(λ) = det(S₃ − λE₃)` (of the scaled blocks).
    pub delta: ZPoly,
    /// `P(λ) = F'δ − Fδ'`: its real roots are the multipliers of the real
    /// critical points.
    pub secular: ZPoly,
    /// D(u) for the values of S: degree 6, square-free, primitive.
    pub judging: ZPoly,
    /// The real roots of D, increasing: every critical value of S on E.
    pub values: Vec<RealAlg>,
    /// The multipliers of the minimum and the maximum (the smallest and
    /// largest real roots of P, by the theory of the trust-region problem;
    /// used for witnesses only, which are checked exactly).
    pub extreme_multipliers: Option<(RealAlg, RealAlg)>,
    s_mat: Mat4,
    e_mat: Mat4,
}

/// `det` of a square matrix of integer polynomials of size ≤ 4 (cofactor
/// expansion along the first row).
fn det_poly(m: &[Vec<ZPoly>]) -> ZPoly {
    let n = m.len();
    if n == 1 {
        return m[0][0].clone();
    }
    if n == 2 {
        return &(&m[0][0] * &m[1][1]) - &(&m[0][1] * &m[1][0]);
    }
    let mut acc = ZPoly::zero();
    for c in 0..n {
        if m[0][c].is_zero() {
            continue;
        }
        let minor: Vec<Vec<ZPoly>> = m[1..]
            .iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .filter(|&(j, _)| j != c)
                    .map(|(_, p)| p.clone())
                    .collect()
            })
            .collect();
        let t = &m[0][c] * &det_poly(&minor);
        acc = if c % 2 == 0 { &acc + &t } else { &acc - &t };
    }
    acc
}

/// `det(S − λE)` of the leading `n × n` blocks.
fn pencil_det(s: &Mat4, e: &Mat4, n: usize) -> ZPoly {
    let m: Vec<Vec<ZPoly>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| ZPoly::new(vec![s[i][j].clone(), -&e[i][j]]))
                .collect()
        })
        .collect();
    det_poly(&m)
}

/// `a·b` added into `out` (ascending coefficients), `None` on overflow.
fn mul_add_i128(a: &[i128], b: &[i128], sign: i128, out: &mut [i128]) -> Option<()> {
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            let t = x.checked_mul(*y)?.checked_mul(sign)?;
            out[i + j] = out[i + j].checked_add(t)?;
        }
    }
    Some(())
}

/// `(F, δ) = (det(S − λE), det(S₃ − λE₃))` in machine integers: Laplace
/// expansion of the 4×4 determinant along its first two rows (six products
/// of 2×2 minors), δ along its third row.  `None` when an entry or an
/// intermediate does not fit in an `i128` (then [`pencil_det`] answers).
fn pencil_dets_i128(s: &Mat4, e: &Mat4) -> Option<(ZPoly, ZPoly)> {
    let mut p = [[[0i128; 2]; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            p[i][j] = [
                i128::try_from(&s[i][j]).ok()?,
                -i128::try_from(&e[i][j]).ok()?,
            ];
        }
    }
    // 2×2 minor of rows r, columns c
    let minor = |r: [usize; 2], c: [usize; 2]| -> Option<[i128; 3]> {
        let mut m = [0i128; 3];
        mul_add_i128(&p[r[0]][c[0]], &p[r[1]][c[1]], 1, &mut m)?;
        mul_add_i128(&p[r[0]][c[1]], &p[r[1]][c[0]], -1, &mut m)?;
        Some(m)
    };
    // columns of rows 0,1, the complementary columns of rows 2,3, and the
    // Laplace sign (−1)^(1 + c0 + c1)
    const PAIRS: [([usize; 2], [usize; 2], i128); 6] = [
        ([0, 1], [2, 3], 1),
        ([0, 2], [1, 3], -1),
        ([0, 3], [1, 2], 1),
        ([1, 2], [0, 3], 1),
        ([1, 3], [0, 2], -1),
        ([2, 3], [0, 1], 1),
    ];
    let mut f = [0i128; 5];
    for (top, bottom, sign) in PAIRS {
        mul_add_i128(&minor([0, 1], top)?, &minor([2, 3], bottom)?, sign, &mut f)?;
    }
    let mut delta = [0i128; 4];
    for (c, rest, sign) in [(0, [1, 2], 1), (1, [0, 2], -1), (2, [0, 1], 1)] {
        mul_add_i128(&p[2][c], &minor([0, 1], rest)?, sign, &mut delta)?;
    }
    let z = |c: &[i128]| ZPoly::new(c.iter().map(|&x| BigInt::from(x)).collect());
    Some((z(&f), z(&delta)))
}

/// `Σ a_i b_j u^{i+j}` (ascending coefficient slices).
fn pmul(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let mut out = vec![BigInt::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// `acc += k·p` (coefficient slices, `acc` at least as long).
fn add_scaled(acc: &mut [BigInt], k: i64, p: &[BigInt]) {
    for (a, x) in acc.iter_mut().zip(p) {
        *a += x * k;
    }
}

/// `(F, δ) = (det(S − λE), det(S₃ − λE₃))` of integer matrices: in
/// machine integers when they fit, else by cofactor expansion.
pub(crate) fn pencil_polys(s: &Mat4, e: &Mat4) -> (ZPoly, ZPoly) {
    pencil_dets_i128(s, e).unwrap_or_else(|| (pencil_det(s, e, 4), pencil_det(s, e, 3)))
}

/// The discriminant of `F(λ) − u·δ(λ)` in λ, as a polynomial in u, up to a
/// positive constant: `4I³ − J²` with the invariants of the quartic
/// `a λ⁴ + b λ³ + c λ² + d λ + e` whose coefficients are linear in u
/// (`a` constant: δ is cubic), each product formed once.
fn quartic_discriminant(f: &ZPoly, delta: &ZPoly) -> ZPoly {
    let lin = |k: usize| [f.coeff(k), -delta.coeff(k)];
    let a = f.coeff(4);
    let (b, c, d, e) = (lin(3), lin(2), lin(1), lin(0));
    let (bd, cc) = (pmul(&b, &d), pmul(&c, &c));
    let ae: Vec<BigInt> = e.iter().map(|x| &a * x).collect();
    // I = 12ae − 3bd + c²
    let mut i = cc.clone();
    add_scaled(&mut i, 12, &ae);
    add_scaled(&mut i, -3, &bd);
    // J = 72ace + 9bcd − 27ad² − 27eb² − 2c³
    let mut j = vec![BigInt::zero(); 4];
    add_scaled(&mut j, 72, &pmul(&ae, &c));
    add_scaled(&mut j, 9, &pmul(&bd, &c));
    let ad: Vec<BigInt> = d.iter().map(|x| &a * x).collect();
    add_scaled(&mut j, -27, &pmul(&ad, &d));
    add_scaled(&mut j, -27, &pmul(&e, &pmul(&b, &b)));
    add_scaled(&mut j, -2, &pmul(&cc, &c));
    // 4I³ − J²
    let mut out = pmul(&pmul(&i, &i), &i);
    for x in out.iter_mut() {
        *x <<= 2usize;
    }
    for (o, x) in out.iter_mut().zip(pmul(&j, &j)) {
        *o -= x;
    }
    ZPoly::new(out)
}

/// `p(l·u)` made primitive with a positive leading coefficient.
fn rescale_variable(p: &ZPoly, l: &BigInt) -> ZPoly {
    let mut pw = BigInt::one();
    let mut out = Vec::with_capacity(p.coeffs().len());
    for c in p.coeffs() {
        out.push(c * &pw);
        pw *= l;
    }
    let q = ZPoly::new(out).primitive_part();
    if q.lc().is_negative() { -q } else { q }
}

/// The pencil analysis, or `None` when the generic test fails (then the
/// complete λ-parametrisation must be used).
pub fn analyze(e: &Ellipsoid, s: &QuadricForm) -> Option<PencilAnalysis> {
    let l = common_denominator(&[&e.form, s]);
    let (sm, em) = (s.int_matrix(&l), e.form.int_matrix(&l));
    let (f, delta) = pencil_polys(&sm, &em);
    if f.degree() != Some(4) || delta.degree() != Some(3) {
        return None; // cannot happen for an ellipsoid E; be safe
    }
    let secular = &(&f.derivative() * &delta) - &(&f * &delta.derivative());
    if secular.gcd(&delta).degree() != Some(0) {
        return None;
    }
    let d = quartic_discriminant(&f, &delta);
    if d.degree() != Some(6) || d.gcd(&d.derivative()).degree() != Some(0) {
        return None;
    }
    let judging = rescale_variable(&d, &l);
    let values: Vec<RealAlg> = isolate_squarefree(&judging)
        .iter()
        .map(|iv| RealAlg::from_primitive(&judging, iv))
        .collect();
    if values.is_empty() {
        return None; // impossible (E is compact); never guess
    }
    Some(PencilAnalysis {
        scale: l,
        char_poly: f,
        delta,
        secular,
        judging,
        values,
        extreme_multipliers: None,
        s_mat: sm,
        e_mat: em,
    })
}

impl PencilAnalysis {
    /// The multipliers of the extreme critical points (computed on demand).
    fn extremes(&self) -> Option<(RealAlg, RealAlg)> {
        let sq = self.secular.squarefree_part();
        let roots = isolate_squarefree(&sq);
        let (first, last) = (roots.first()?, roots.last()?);
        Some((
            RealAlg::from_primitive(&sq, first),
            RealAlg::from_primitive(&sq, last),
        ))
    }

    /// Fills [`PencilAnalysis::extreme_multipliers`].
    pub fn with_extremes(mut self) -> Self {
        self.extreme_multipliers = self.extremes();
        self
    }

    /// A point of E near the minimum (`want < 0`) or the maximum
    /// (`want > 0`) of S on which S has the sign `want`, checked exactly.
    pub fn witness(&self, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        let (lo, hi) = match &self.extreme_multipliers {
            Some(x) => x.clone(),
            None => self.extremes()?,
        };
        let approx = CentreApprox::new(if want < 0 { lo } else { hi }, &self.s_mat, &self.e_mat);
        find_witness(e, s, want, true, &|bits| approx.at(bits))
    }
}

/// Approximations of the critical point `x(λ)` (the centre of `S − λE`)
/// of a simple-branch multiplier λ, for [`find_witness`]: λ's isolating
/// interval is refined in place from one attempt to the next (never from
/// scratch); `at(0)` is the cheap first try, at width 2^-[`COARSE_BITS`].
pub(crate) struct CentreApprox<'a> {
    lam: std::cell::RefCell<RealAlg>,
    s_mat: &'a Mat4,
    e_mat: &'a Mat4,
}

impl<'a> CentreApprox<'a> {
    /// For the multiplier `lam` of the integer matrices of `L·S`, `L·E`.
    pub(crate) fn new(lam: RealAlg, s_mat: &'a Mat4, e_mat: &'a Mat4) -> Self {
        CentreApprox {
            lam: std::cell::RefCell::new(lam),
            s_mat,
            e_mat,
        }
    }

    /// `x(λ̃)` for λ̃ the midpoint of λ's interval refined to `2^-bits`.
    pub(crate) fn at(&self, bits: u32) -> Option<[Q; 3]> {
        let mut l = self.lam.borrow_mut();
        let bits = if bits > 0 { bits } else { COARSE_BITS };
        l.refine_to(&Q::new(BigInt::one(), BigInt::one() << bits as usize));
        // the midpoint, unreduced (centre_at takes any fraction)
        let (a, b) = l.interval();
        let num = a.numer() * b.denom() + b.numer() * a.denom();
        centre_at(
            self.s_mat,
            self.e_mat,
            &num,
            &((a.denom() * b.denom()) << 1usize),
        )
    }
}

/// The width `2^-COARSE_BITS` of the first attempt: the extreme
/// multipliers come from isolation with intervals as wide as the root
/// bound; a quarter is enough for most witnesses (measured on the
/// benchmark pairs: finer costs more refinement than it saves attempts).
const COARSE_BITS: u32 = 2;

/// The centre `x(λ)` of `S − λE` at `λ = n/d`, by Cramer's rule on the
/// integer matrices (`None` where `δ(λ) = 0`).
fn centre_at(s: &Mat4, e: &Mat4, n: &BigInt, d: &BigInt) -> Option<[Q; 3]> {
    let m: [[BigInt; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| d * &s[i][j] - n * &e[i][j]));
    let w: [BigInt; 3] = std::array::from_fn(|i| d * &s[i][3] - n * &e[i][3]);
    let mut m4: Mat4 = Default::default();
    for i in 0..3 {
        for j in 0..3 {
            m4[i][j] = m[i][j].clone();
        }
    }
    let (adj, det) = adj3_int(&m4);
    if det.is_zero() {
        return None;
    }
    // unreduced (positive denominator): only rounded afterwards
    let (sg, det) = if det.is_negative() {
        (1, -det)
    } else {
        (-1, det)
    };
    Some(std::array::from_fn(|i| {
        let num: BigInt = (0..3).map(|j| &adj[i][j] * &w[j]).sum();
        Q::new_raw(num * sg, det.clone())
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn run(e: &str, s: &str) -> Option<PencilAnalysis> {
        let e = Ellipsoid::from_poly(&parse_poly(e).unwrap()).unwrap();
        let s = QuadricForm::from_poly(&parse_poly(s).unwrap()).unwrap();
        analyze(&e, &s)
    }

    #[test]
    fn generic_pair_gives_all_critical_values() {
        // E a sphere, S an ellipsoid off every axis: six real critical points
        let an = run("x^2+y^2+z^2-25", "(x-1)^2/9+(y-2)^2/4+(z-3)^2/16-1").unwrap();
        assert_eq!(an.judging.degree(), Some(6));
        assert!(!an.values.is_empty());
        // the range is brute-force bracketed by points of E
        let s = parse_poly("(x-1)^2/9+(y-2)^2/4+(z-3)^2/16-1").unwrap();
        let at = |p: [i64; 3]| {
            let mut pt: [Q; crate::poly::mpoly::NVARS] = Default::default();
            for i in 0..3 {
                pt[i] = Q::from_integer(p[i].into());
            }
            s.eval(&pt)
        };
        for p in [
            [5, 0, 0],
            [-5, 0, 0],
            [0, 5, 0],
            [0, -5, 0],
            [0, 0, 5],
            [0, 0, -5],
            [3, 4, 0],
            [0, 3, -4],
        ] {
            let v = at(p);
            assert!(an.values[0].cmp_rational(&v).is_le());
            assert!(an.values.last().unwrap().cmp_rational(&v).is_ge());
        }
    }

    #[test]
    fn machine_determinants_match_the_cofactor_expansion() {
        let e =
            Ellipsoid::from_poly(&parse_poly("3x^2+2xy+4y^2-2yz+5z^2+x-7z-30").unwrap()).unwrap();
        let s =
            QuadricForm::from_poly(&parse_poly("x^2/3-4xz+2y^2+yz/5-z^2+6x-y+2z-11/7").unwrap())
                .unwrap();
        let l = common_denominator(&[&e.form, &s]);
        let (sm, em) = (s.int_matrix(&l), e.form.int_matrix(&l));
        let (f, delta) = pencil_dets_i128(&sm, &em).unwrap();
        assert_eq!(f, pencil_det(&sm, &em, 4));
        assert_eq!(delta, pencil_det(&sm, &em, 3));
        assert_eq!(f.degree(), Some(4));
        // entries past i128 take the cofactor path
        let mut big = sm.clone();
        big[0][3] = BigInt::one() << 130usize;
        assert!(pencil_dets_i128(&big, &em).is_none());
    }

    #[test]
    fn discriminant_from_invariants_matches_the_resultant() {
        // 27·disc(G) = 4I³ − J² and a·disc(G) = Res(G, G') for the quartic
        // G = F − u₀δ (leading coefficient a): check at several u₀
        let e =
            Ellipsoid::from_poly(&parse_poly("3x^2+2xy+4y^2-2yz+5z^2+x-7z-30").unwrap()).unwrap();
        let s =
            QuadricForm::from_poly(&parse_poly("x^2-4xz+2y^2+yz-z^2+6x-y+2z-11").unwrap()).unwrap();
        let l = common_denominator(&[&e.form, &s]);
        let (sm, em) = (s.int_matrix(&l), e.form.int_matrix(&l));
        let (f, delta) = pencil_dets_i128(&sm, &em).unwrap();
        let d = quartic_discriminant(&f, &delta);
        assert_eq!(d.degree(), Some(6));
        for u0 in [-7i64, -1, 0, 2, 5, 40] {
            let u0 = BigInt::from(u0);
            let g = &f - &delta.scale(&u0);
            let res = crate::elim::resultant_z(&g, &g.derivative());
            assert_eq!(&f.coeff(4) * d.eval(&u0), res * 27, "u0 = {u0}");
        }
    }

    #[test]
    fn centre_by_cramer() {
        // S − λE = (x−1)² + 2(y+2)² + 3z² − λ(x² + y² + z² − 4) at λ = 1/2
        let e = Ellipsoid::from_poly(&parse_poly("x^2+y^2+z^2-4").unwrap()).unwrap();
        let s = QuadricForm::from_poly(&parse_poly("(x-1)^2+2(y+2)^2+3z^2").unwrap()).unwrap();
        let l = common_denominator(&[&e.form, &s]);
        let c = centre_at(
            &s.int_matrix(&l),
            &e.form.int_matrix(&l),
            &1.into(),
            &2.into(),
        )
        .unwrap();
        // gradient: (1−λ)·2x − 2 = 0, (2−λ)·2y + 8 = 0, (3−λ)·2z = 0
        assert_eq!(
            c,
            [
                Q::from_integer(2.into()),
                Q::new((-8).into(), 3.into()),
                Q::zero()
            ]
        );
    }

    #[test]
    fn symmetric_pair_falls_back() {
        // paper Example 1: the singular multipliers 1/4 and 1/16 share roots with F
        assert!(run("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1").is_none());
        // concentric spheres
        assert!(run("x^2+y^2+z^2-25", "x^2+y^2+z^2-4").is_none());
    }
}
