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

use super::ellipsoid::{Ellipsoid, Mat4, QuadricForm, adj3_int, common_denominator};
use super::witness::{WitnessPoint, find_witness};
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

/// The discriminant of `F(λ) − u·δ(λ)` in λ, as a polynomial in u, up to a
/// positive constant: `4I³ − J²` with the invariants of the quartic.
fn quartic_discriminant(f: &ZPoly, delta: &ZPoly) -> ZPoly {
    // coefficient of λ^k as a polynomial in u
    let c = |k: usize| ZPoly::new(vec![f.coeff(k), -delta.coeff(k)]);
    let (a, b, c2, d, e) = (c(4), c(3), c(2), c(1), c(0));
    let k = |n: i64| ZPoly::constant(BigInt::from(n));
    let i = &(&(&k(12) * &(&a * &e)) - &(&k(3) * &(&b * &d))) + &(&c2 * &c2);
    let ace = &(&a * &c2) * &e;
    let bcd = &(&b * &c2) * &d;
    let add = &(&a * &d) * &d;
    let bbe = &(&b * &b) * &e;
    let ccc = &(&c2 * &c2) * &c2;
    let j = &(&(&(&k(72) * &ace) + &(&k(9) * &bcd)) - &(&k(27) * &(&add + &bbe))) - &(&k(2) * &ccc);
    &(&k(4) * &(&(&i * &i) * &i)) - &(&j * &j)
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
    let f = pencil_det(&sm, &em, 4);
    let delta = pencil_det(&sm, &em, 3);
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
        .map(|iv| RealAlg::from_interval(&judging, iv))
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
            RealAlg::from_interval(&sq, first),
            RealAlg::from_interval(&sq, last),
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
        let lam = if want < 0 { lo } else { hi };
        let approx = |bits: u32| -> Option<[Q; 3]> {
            let l = lam.to_rational_approx(bits);
            centre_at(&self.s_mat, &self.e_mat, l.numer(), l.denom())
        };
        find_witness(e, s, want, &approx)
    }
}

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
    Some(std::array::from_fn(|i| {
        let num: BigInt = (0..3).map(|j| &adj[i][j] * &w[j]).sum();
        Q::new(-num, det.clone())
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn run(e: &str, s: &str) -> Option<PencilAnalysis> {
        let e = Ellipsoid::new(&parse_poly(e).unwrap()).unwrap();
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
    fn centre_by_cramer() {
        // S − λE = (x−1)² + 2(y+2)² + 3z² − λ(x² + y² + z² − 4) at λ = 1/2
        let e = Ellipsoid::new(&parse_poly("x^2+y^2+z^2-4").unwrap()).unwrap();
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
