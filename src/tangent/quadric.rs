//! S of degree ≤ 2: the exact and complete λ-parametrisation (contract §3).
//!
//! `∇S = λ∇E` is linear in the point: `(B − λA) p = λb − β`.  Where
//! `δ(λ) = det(B − λA) ≠ 0` the unique solution is `p(λ) = N(λ)/δ(λ)` with
//! `N = adj(B − λA)(λb − β)`, and `p(λ) ∈ E` iff `P(λ) = E(p(λ))·δ(λ)² = 0`
//! (the *secular polynomial*, degree exactly 6: `E(p(λ)) → E(centre) < 0`
//! as λ → ∞).  A real critical point forces a real λ (∇E ≠ 0 on E), so the
//! real critical points off the singular λ are exactly `p(λᵢ)` for the real
//! roots λᵢ of P that are not roots of δ.
//!
//! At a root λ₀ of δ (all real: generalised eigenvalues of (B, A), A > 0)
//! the solutions form an affine subspace `L` (or nothing); `S − λ₀E` has
//! zero gradient along `L`, so S is constant on `L ∩ E`: one critical value
//! `u₀ = (S − λ₀E)(p₀)`, attained by real points iff `min_L E ≤ 0`.  λ₀ may
//! be irrational (a root of an irreducible quadratic or cubic factor of δ):
//! the linear algebra then runs in the number field Q(λ₀).

use super::ellipsoid::Ellipsoid;
use super::pencil::{CentreApprox, pencil_polys};
use super::witness::{WitnessPoint, find_witness};
use crate::geom::{Mat4, QuadricForm, common_denominator};
use crate::number::{Q, QSqrt};
use crate::poly::extension::{NfElem, NumberField};
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::{
    RealAlg, eval_q, isolate_squarefree, split_cubic, value_at, value_polynomial, values_with,
};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Where a critical value comes from.
#[derive(Clone, Debug)]
pub enum Branch {
    /// `p(λ) = N(λ)/δ(λ)` at a simple-branch multiplier.
    Generic,
    /// A singular multiplier: the solutions of `(B − λ₀A)p = λ₀b − β` form
    /// an affine subspace of dimension `dim` meeting E.
    Singular {
        /// Dimension of the solution subspace (1 line, 2 plane, 3 space).
        dim: usize,
        /// True when the subspace touches E in a single point.
        single_point: bool,
    },
}

/// A critical value of S on E with its Lagrange multiplier.
#[derive(Clone, Debug)]
pub struct LambdaCritical {
    /// The multiplier λ (real).
    pub lambda: RealAlg,
    /// The value of S there.
    pub value: RealAlg,
    /// True when real points of E attain it.
    pub real: bool,
    /// Which branch.
    pub branch: Branch,
}

/// Everything the λ-parametrisation computes.
#[derive(Clone, Debug)]
pub struct LambdaAnalysis {
    /// `δ(λ) = det(B − λA)`.
    pub delta: QPoly,
    /// The secular polynomial `P(λ)`.
    pub secular: QPoly,
    /// P with the roots of δ removed.
    pub secular_generic: QPoly,
    /// Critical values (real and non-real points), by branch.
    pub critical: Vec<LambdaCritical>,
    /// The judging polynomial D(u): square-free, primitive, integer.
    pub judging: ZPoly,
    /// Witness approximations for each entry of `critical`.
    approximants: Vec<Approximant>,
    /// The integer matrices of `L·S` and `L·E`.
    s_mat: Mat4,
    e_mat: Mat4,
}

#[derive(Clone, Debug)]
enum Approximant {
    /// `p(λ)`: the centre of `S − λE` (integer matrices below).
    Generic,
    Singular {
        xp: [NfElem; 3],
        kernel: Vec<[NfElem; 3]>,
    },
}

fn lin(c0: &Q, c1: &Q) -> QPoly {
    QPoly::new(vec![c0.clone(), c1.clone()])
}

fn form_eval_k(k: &NumberField, f: &QuadricForm, p: &[NfElem; 3]) -> NfElem {
    let two = Q::from_integer(2.into());
    let mut acc = k.constant(f.c.clone());
    for i in 0..3 {
        acc = k.add(&acc, &p[i].map(|c| c * &f.b[i] * &two));
        for j in 0..3 {
            if !f.a[i][j].is_zero() {
                acc = k.add(&acc, &k.mul(&p[i], &p[j]).map(|c| c * &f.a[i][j]));
            }
        }
    }
    k.reduce(&acc)
}

/// Gauss–Jordan over a number field: returns (particular solution, kernel
/// basis) of `M p = r`, or `None` if inconsistent.
#[allow(clippy::type_complexity)]
fn solve_k(
    k: &NumberField,
    m: [[NfElem; 3]; 3],
    r: [NfElem; 3],
) -> Option<([NfElem; 3], Vec<[NfElem; 3]>)> {
    let mut a: Vec<Vec<NfElem>> = (0..3)
        .map(|i| {
            let mut row: Vec<NfElem> = m[i].to_vec();
            row.push(r[i].clone());
            row
        })
        .collect();
    let mut pivots = Vec::new();
    let mut row = 0;
    for col in 0..3 {
        let Some(p) = (row..3).find(|&i| !k.is_zero(&a[i][col])) else {
            continue;
        };
        a.swap(row, p);
        let inv = k.inv(&a[row][col])?;
        for j in 0..4 {
            a[row][j] = k.mul(&a[row][j], &inv);
        }
        for i in 0..3 {
            if i != row && !k.is_zero(&a[i][col]) {
                let f = a[i][col].clone();
                for j in 0..4 {
                    let t = k.mul(&f, &a[row][j]);
                    a[i][j] = k.sub(&a[i][j], &t);
                }
            }
        }
        pivots.push(col);
        row += 1;
    }
    for a_i in a.iter().skip(row) {
        if !k.is_zero(&a_i[3]) {
            return None;
        }
    }
    let mut xp: [NfElem; 3] = std::array::from_fn(|_| k.zero());
    for (i, &c) in pivots.iter().enumerate() {
        xp[c] = a[i][3].clone();
    }
    let free: Vec<usize> = (0..3).filter(|c| !pivots.contains(c)).collect();
    let kernel = free
        .iter()
        .map(|&f| {
            let mut v: [NfElem; 3] = std::array::from_fn(|_| k.zero());
            v[f] = k.one();
            for (i, &c) in pivots.iter().enumerate() {
                v[c] = k.sub(&k.zero(), &a[i][f]);
            }
            v
        })
        .collect();
    Some((xp, kernel))
}

/// Solves `H y = g` over a number field for a small symmetric positive
/// definite `H` (at every real embedding); returns `y`.
fn solve_small_k(k: &NumberField, h: Vec<Vec<NfElem>>, g: Vec<NfElem>) -> Option<Vec<NfElem>> {
    let n = g.len();
    let mut a: Vec<Vec<NfElem>> = h
        .into_iter()
        .zip(g)
        .map(|(mut row, gi)| {
            row.push(gi);
            row
        })
        .collect();
    for col in 0..n {
        let p = (col..n).find(|&i| !k.is_zero(&a[i][col]))?;
        a.swap(col, p);
        let inv = k.inv(&a[col][col])?;
        for j in 0..=n {
            a[col][j] = k.mul(&a[col][j], &inv);
        }
        for i in 0..n {
            if i != col && !k.is_zero(&a[i][col]) {
                let f = a[i][col].clone();
                for j in 0..=n {
                    let t = k.mul(&f, &a[col][j]);
                    a[i][j] = k.sub(&a[i][j], &t);
                }
            }
        }
    }
    Some(a.into_iter().map(|row| row[n].clone()).collect())
}

/// Runs the λ-parametrisation of S (degree ≤ 2) on the ellipsoid E.
pub fn analyze(e: &Ellipsoid, s: &QuadricForm) -> LambdaAnalysis {
    let a = &e.form.a;
    let m: [[QPoly; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| lin(&s.a[i][j], &-&a[i][j])));
    let r: [QPoly; 3] = std::array::from_fn(|i| lin(&-&s.b[i], &e.form.b[i]));
    // δ and P from the integer pencil of Ŝ = L·S, Ê = L·E (see `pencil`):
    // δ̂ = L³δ, and P̂ = F̂'δ̂ − F̂δ̂' = δ̂²·ĝ' with ĝ' = −Ê(p(λ)) = −L·E(p(λ)),
    // so P = E(p(λ))·δ² = −P̂ / L⁷
    let l = common_denominator(&[&e.form, s]);
    let (s_mat, e_mat) = (s.int_matrix(&l), e.form.int_matrix(&l));
    let (f, fd) = pencil_polys(&s_mat, &e_mat);
    let p_hat = &(&f.derivative() * &fd) - &(&f * &fd.derivative());
    let delta = fd.to_q().scale(&Q::new(BigInt::one(), l.pow(3)));
    let secular = p_hat.to_q().scale(&Q::new(-BigInt::one(), l.pow(7)));

    // remove from P every root it shares with δ
    let dz = fd.primitive_part();
    let mut pz = p_hat.primitive_part();
    loop {
        let g = pz.gcd(&dz);
        if g.degree().unwrap_or(0) == 0 {
            break;
        }
        pz = pz.div_exact_z(&g);
    }
    let secular_generic = pz.to_q();

    let mut critical = Vec::new();
    let mut approximants = Vec::new();
    let mut judging = ZPoly::constant(1.into());
    if pz.degree().unwrap_or(0) > 0 {
        // at a root of P off the roots of δ the value is
        // S(p(λ)) = (S − λE)(p(λ)) = F̂(λ) / (L·δ̂(λ)) (Schur complement)
        let (num, den) = (f.to_q(), fd.scale(&l).to_q());
        let sq = pz.squarefree_part();
        let vp = value_polynomial(&sq, &num, &den);
        judging = &judging * &vp;
        let roots: Vec<RealAlg> = isolate_squarefree(&sq)
            .iter()
            .map(|iv| RealAlg::from_primitive(&sq, iv))
            .collect();
        let values = values_with(&sq, &roots, &num, &den, &vp);
        for (lam, v) in roots.into_iter().zip(values) {
            if let Some(v) = v {
                critical.push(LambdaCritical {
                    lambda: lam,
                    value: v,
                    real: true,
                    branch: Branch::Generic,
                });
                approximants.push(Approximant::Generic);
            }
        }
    }

    // singular multipliers: the irreducible factors of δ
    let (rat, rest) = split_cubic(&dz);
    let mut factors: Vec<QPoly> = rat
        .iter()
        .map(|q| QPoly::new(vec![-q.clone(), Q::one()]))
        .collect();
    if rest.degree().unwrap_or(0) > 0 {
        factors.push(rest.to_q());
    }
    for phi in factors {
        let k = NumberField::new(&phi);
        let lam = k.gen_elem();
        let mk: [[NfElem; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| k.reduce(&m[i][j])));
        let rk: [NfElem; 3] = std::array::from_fn(|i| k.reduce(&r[i]));
        let Some((xp, kernel)) = solve_k(&k, mk, rk) else {
            continue; // no solutions for this multiplier
        };
        // u0 = (S − λ E)(xp)
        let sv = form_eval_k(&k, s, &xp);
        let ev = form_eval_k(&k, &e.form, &xp);
        let u0 = k.sub(&sv, &k.mul(&lam, &ev));
        // min of E over xp + span(kernel): e0 − gᵀ H⁻¹ g
        let hx: [NfElem; 3] = std::array::from_fn(|i| {
            let mut acc = k.constant(e.form.b[i].clone());
            for j in 0..3 {
                acc = k.add(&acc, &xp[j].map(|c| c * &a[i][j]));
            }
            acc
        });
        let av = |v: &[NfElem; 3], w: &[NfElem; 3]| -> NfElem {
            let mut acc = k.zero();
            for i in 0..3 {
                for j in 0..3 {
                    if !a[i][j].is_zero() {
                        acc = k.add(&acc, &k.mul(&v[i], &w[j]).map(|c| c * &a[i][j]));
                    }
                }
            }
            acc
        };
        let dot = |v: &[NfElem; 3], w: &[NfElem; 3]| -> NfElem {
            let mut acc = k.zero();
            for i in 0..3 {
                acc = k.add(&acc, &k.mul(&v[i], &w[i]));
            }
            acc
        };
        let h: Vec<Vec<NfElem>> = kernel
            .iter()
            .map(|v| kernel.iter().map(|w| av(v, w)).collect())
            .collect();
        let g: Vec<NfElem> = kernel.iter().map(|v| dot(v, &hx)).collect();
        let Some(y) = solve_small_k(&k, h, g.clone()) else {
            continue;
        };
        let mut gy = k.zero();
        for (gi, yi) in g.iter().zip(y.iter()) {
            gy = k.add(&gy, &k.mul(gi, yi));
        }
        let min_e = k.sub(&ev, &gy);
        let (phi_z, _) = ZPoly::from_q(&phi);
        judging = &judging * &value_polynomial(&phi_z, &u0, &QPoly::constant(Q::one()));
        for lam0 in RealAlg::roots_of(&phi_z) {
            let sgn = lam0.sign_of_q(&min_e);
            let value = value_at(&lam0, &u0, &QPoly::constant(Q::one()))
                .expect("denominator 1 never vanishes");
            critical.push(LambdaCritical {
                lambda: lam0,
                value,
                real: sgn <= 0,
                branch: Branch::Singular {
                    dim: kernel.len(),
                    single_point: sgn == 0,
                },
            });
            approximants.push(Approximant::Singular {
                xp: xp.clone(),
                kernel: kernel.clone(),
            });
        }
    }
    let judging = judging.squarefree_part();
    LambdaAnalysis {
        delta,
        secular,
        secular_generic,
        critical,
        judging,
        approximants,
        s_mat,
        e_mat,
    }
}

impl LambdaAnalysis {
    /// A witness on E near the critical point `i` with S of sign `want`.
    pub fn witness(&self, i: usize, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        let crit = &self.critical[i];
        if !crit.real {
            return None;
        }
        if let Approximant::Generic = self.approximants[i] {
            let approx = CentreApprox::new(crit.lambda.clone(), &self.s_mat, &self.e_mat);
            return find_witness(e, s, want, true, &|bits| approx.at(bits));
        }
        let lam = crit.lambda.clone();
        let form = e.form.clone();
        let approx = |bits: u32| -> Option<[Q; 3]> {
            let l = lam.to_rational_approx(bits);
            match &self.approximants[i] {
                Approximant::Generic => None,
                Approximant::Singular { xp, kernel } => {
                    let x0: [Q; 3] = std::array::from_fn(|j| eval_q(&xp[j], &l));
                    let vs: Vec<[Q; 3]> = kernel
                        .iter()
                        .map(|v| std::array::from_fn(|j| eval_q(&v[j], &l)))
                        .collect();
                    // centre of L ∩ E: x0 + V y with (VᵀAV) y = −Vᵀ(A x0 + b)
                    let hx = form.half_gradient(&x0);
                    let mut centre = x0.clone();
                    if let Some(y) = solve_rational_spd(&form, &vs, &hx) {
                        for (v, yi) in vs.iter().zip(y.iter()) {
                            for j in 0..3 {
                                centre[j] -= &v[j] * yi;
                            }
                        }
                    }
                    // move along the first kernel direction to reach E
                    let m = form.eval(&centre);
                    let v = &vs[0];
                    let mut vav = Q::zero();
                    for p in 0..3 {
                        for q in 0..3 {
                            vav += &form.a[p][q] * &v[p] * &v[q];
                        }
                    }
                    let t2 = if m.is_negative() {
                        -&m / &vav
                    } else {
                        Q::zero()
                    };
                    let t = QSqrt::sqrt(t2).to_rational_approx(bits);
                    Some(std::array::from_fn(|j| &centre[j] + &v[j] * &t))
                }
            }
        };
        find_witness(e, s, want, false, &approx)
    }
}

/// Solves `(VᵀAV) y = Vᵀ h` for rational data (small, positive definite).
fn solve_rational_spd(f: &QuadricForm, vs: &[[Q; 3]], h: &[Q; 3]) -> Option<Vec<Q>> {
    let n = vs.len();
    let mut a: Vec<Vec<Q>> = vec![vec![Q::zero(); n + 1]; n];
    for i in 0..n {
        for j in 0..n {
            let mut acc = Q::zero();
            for p in 0..3 {
                for q in 0..3 {
                    acc += &f.a[p][q] * &vs[i][p] * &vs[j][q];
                }
            }
            a[i][j] = acc;
        }
        a[i][n] = (0..3)
            .map(|p| &vs[i][p] * &h[p])
            .fold(Q::zero(), |x, y| x + y);
    }
    for col in 0..n {
        let p = (col..n).find(|&i| !a[i][col].is_zero())?;
        a.swap(col, p);
        let inv = Q::one() / &a[col][col];
        for j in 0..=n {
            a[col][j] = &a[col][j] * &inv;
        }
        for i in 0..n {
            if i != col && !a[i][col].is_zero() {
                let fct = a[i][col].clone();
                for j in 0..=n {
                    let t = &fct * &a[col][j];
                    a[i][j] -= t;
                }
            }
        }
    }
    Some(a.into_iter().map(|r| r[n].clone()).collect())
}

#[cfg(test)]
mod tests {

    // the rational λ-parametrisation written out (the formulas of the
    // module doc), as an oracle for the integer pencil used by `analyze`
    fn det3p(m: &[[QPoly; 3]; 3]) -> QPoly {
        let t = |a: &QPoly, b: &QPoly, c: &QPoly, d: &QPoly| &(a * b) - &(c * d);
        &(&(&m[0][0] * &t(&m[1][1], &m[2][2], &m[1][2], &m[2][1]))
            - &(&m[0][1] * &t(&m[1][0], &m[2][2], &m[1][2], &m[2][0])))
            + &(&m[0][2] * &t(&m[1][0], &m[2][1], &m[1][1], &m[2][0]))
    }

    fn adj3p(m: &[[QPoly; 3]; 3]) -> [[QPoly; 3]; 3] {
        let cof = |i: usize, j: usize| -> QPoly {
            let r: Vec<usize> = (0..3).filter(|&k| k != i).collect();
            let c: Vec<usize> = (0..3).filter(|&k| k != j).collect();
            let v = &(&m[r[0]][c[0]] * &m[r[1]][c[1]]) - &(&m[r[0]][c[1]] * &m[r[1]][c[0]]);
            if (i + j).is_multiple_of(2) { v } else { -v }
        };
        std::array::from_fn(|i| std::array::from_fn(|j| cof(j, i)))
    }

    /// `pᵀ F p·… `: the value `q(N/δ)·δ²` of a quadric form at `N/δ`.
    fn form_at_rational_point(f: &QuadricForm, n: &[QPoly; 3], d: &QPoly) -> QPoly {
        let two = Q::from_integer(2.into());
        let mut acc = QPoly::zero();
        for i in 0..3 {
            for j in 0..3 {
                if !f.a[i][j].is_zero() {
                    acc = &acc + &(&n[i] * &n[j]).map(|c| c * &f.a[i][j]);
                }
            }
            if !f.b[i].is_zero() {
                acc = &acc + &(d * &n[i]).map(|c| c * &f.b[i] * &two);
            }
        }
        &acc + &(d * d).map(|c| c * &f.c)
    }

    #[test]
    fn integer_pencil_gives_the_secular_polynomial() {
        for (e, s) in [
            ("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1"),
            (
                "3x^2+2xy+4y^2-2yz+5z^2+x-7z-30",
                "x^2/3-4xz+2y^2+yz/5-z^2+6x-y+2z-11/7",
            ),
            ("2x^2+3y^2+4z^2-25", "x+2y-z/3-1"),
        ] {
            let e = Ellipsoid::from_poly(&parse_poly(e).unwrap()).unwrap();
            let s = QuadricForm::from_poly(&parse_poly(s).unwrap()).unwrap();
            let a = &e.form.a;
            let m: [[QPoly; 3]; 3] =
                std::array::from_fn(|i| std::array::from_fn(|j| lin(&s.a[i][j], &-&a[i][j])));
            let r: [QPoly; 3] = std::array::from_fn(|i| lin(&-&s.b[i], &e.form.b[i]));
            let delta = det3p(&m);
            let adj = adj3p(&m);
            let numer: [QPoly; 3] = std::array::from_fn(|i| {
                let mut acc = QPoly::zero();
                for j in 0..3 {
                    acc = &acc + &(&adj[i][j] * &r[j]);
                }
                acc
            });
            let an = analyze(&e, &s);
            assert_eq!(an.delta, delta);
            assert_eq!(an.secular, form_at_rational_point(&e.form, &numer, &delta));
        }
    }
    use super::*;
    use crate::number::q;
    use crate::poly::parse_poly;

    fn run(e: &str, s: &str) -> LambdaAnalysis {
        let e = Ellipsoid::from_poly(&parse_poly(e).unwrap()).unwrap();
        let s = QuadricForm::from_poly(&parse_poly(s).unwrap()).unwrap();
        analyze(&e, &s)
    }

    #[test]
    fn paper_example_1_range() {
        let a = run("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1");
        assert_eq!(a.secular.degree(), Some(6));
        let real: Vec<&LambdaCritical> = a.critical.iter().filter(|c| c.real).collect();
        let mut vals: Vec<Q> = real
            .iter()
            .filter_map(|c| c.value.as_rational().cloned())
            .collect();
        vals.sort();
        assert_eq!(vals.first(), Some(&q(7, 9)));
        assert_eq!(vals.last(), Some(&q(187, 9)));
        // the non-real critical value -1233/112 is a root of D(u)
        assert_eq!(a.judging.sign_at(&q(-1233, 112)), 0);
        assert_eq!(a.judging.sign_at(&q(429, 20)), 0);
    }

    #[test]
    fn paper_example_2_max_from_singular_branch() {
        let a = run("x^2+y^2+z^2-25", "(x-6)^2/9+y^2/4+z^2/16-1");
        let best = a
            .critical
            .iter()
            .filter(|c| c.real)
            .max_by(|x, y| x.value.cmp_exact(&y.value))
            .unwrap();
        assert_eq!(best.value.as_rational(), Some(&q(249, 20)));
        assert!(matches!(best.branch, Branch::Singular { dim: 1, .. }));
    }
}
