//! The one division-free program of the contact predicate, written once
//! against [`Ar`] and run in three number types: `f64` (the value), [`Mag`]
//! (a rigorous bound on its rounding error) and [`Q`] (exact).
//!
//! **An ellipsoid given by a pose.**  Centre `c`, semi-axes `r` and an
//! invertible matrix `R` define `E = { x : |D⁻¹Rᵀ(x − c)| ≤ 1 }`
//! (`D = diag(r)`; for a rotation, `E = { c + R·D·u : |u| ≤ 1 }`).  With
//! `D⁻¹ = diag(r₂r₃, r₁r₃, r₁r₂)/(r₁r₂r₃)`:
//!
//! ```text
//! K = diag(r₂r₃, r₁r₃, r₁r₂)·Rᵀ,   σ = r₁r₂r₃,
//! q(x) = |K(x − c)|² − σ²  ( = σ²·(|D⁻¹Rᵀ(x − c)|² − 1) ),
//! ```
//!
//! a polynomial in the inputs with the sign of the canonical form; its
//! matrix part is `M = KᵀK` and its constant `ρ = σ²`.
//!
//! **The characteristic quartic.**  Translated so that A's centre is the
//! origin (`t = c_B − c_A`), `A = diag(M_A, −ρ_A)` and
//! `B = [[M_B, −M_B t], [−tᵀM_B, tᵀM_B t − ρ_B]]`.  With
//! `h(λ) = det(λM_A + M_B) = h₃λ³ + h₂λ² + h₁λ + h₀` (`h₃ = det M_A`,
//! `h₂ = tr(adj M_A · M_B)`, `h₁ = tr(M_A · adj M_B)`, `h₀ = det M_B`) and
//! the mixed adjugate `X = adj(M_A + M_B) − adj M_A − adj M_B`,
//! `f(λ) = det(λA + B) = Σ cₖλᵏ` is
//!
//! ```text
//! c₄ = −ρ_A h₃
//! c₃ = h₃·tᵀM_B t − ρ_B h₃ − ρ_A h₂
//! c₂ = (M_B t)ᵀ X (M_A t) − ρ_B h₂ − ρ_A h₁
//! c₁ = h₀·tᵀM_A t − ρ_B h₁ − ρ_A h₀
//! c₀ = −ρ_B h₀
//! ```
//!
//! (expand `det = w·det H − uᵀ adj(H) u` with `H = λM_A + M_B`,
//! `u = M_B t`, `w = tᵀM_B t − ρ_B − ρ_Aλ`, and use the coefficients of
//! `adj(H)·H = det(H)·I` to cancel the terms in `t` that would cancel in
//! floating point: e.g. `tᵀM_B t·h₁ − uᵀXu = h₀·tᵀM_A t`).  Two unit
//! spheres at distance d give `−(λ + 1)²(λ² − (d² − 2)λ + 1)`.
//!
//! **Rounding.**  Every operation of the `f64` run rounds once; a node's
//! *depth* is the largest number of roundings on a path from the inputs to
//! it (the `Depth` type of the tests measures it: [`DEPTH`] bounds it for
//! every output).  [`Mag`] runs the same program on `|inputs|` with every
//! subtraction an addition and every product raised to at least
//! [`TINY`].  By induction on the program, `|fl(v) − v| ≤ γ₂ₖ·Mag(v)` at a
//! node of depth k, `γₙ = nu/(1 − nu)`, `u = 2⁻⁵³`: a sum adds `u|fl|`, a
//! product `|a|e_b + |b|e_a + e_a e_b + u|fl| + 2⁻¹⁰⁷⁵`, and the
//! underflow term is below `u·TINY ≤ u·Mag`.  The `Mag` run rounds too,
//! only downwards by at most `(1 − u)^k` on non-negative terms.  Hence the
//! bound used, `(4k + 4)·u·fl(Mag)`, which covers both for `k ≤ 10⁶`.  An
//! overflow gives an infinite bound, which decides nothing.

use crate::number::Q;

/// Unit roundoff of `f64`.
pub(crate) const U: f64 = 1.1102230246251565e-16; // 2^-53
/// The floor of every product's magnitude in [`Mag`] (see the module doc).
pub(crate) const TINY: f64 = 2.409919865102884e-181; // 2^-600
/// A bound on the depth of every output of the programs below (checked by
/// the `Depth` test).
pub(crate) const DEPTH: u32 = 32;

/// The rigorous error bound of an `f64` node from its [`Mag`] value.
#[inline]
pub(crate) fn err(mag: f64) -> f64 {
    mag * ((4 * DEPTH + 4) as f64 * U)
}

/// The ring operations the program needs.
pub(crate) trait Ar: Clone {
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
}

impl Ar for f64 {
    #[inline(always)]
    fn add(&self, o: &f64) -> f64 {
        self + o
    }
    #[inline(always)]
    fn sub(&self, o: &f64) -> f64 {
        self - o
    }
    #[inline(always)]
    fn mul(&self, o: &f64) -> f64 {
        self * o
    }
}

/// The magnitude run: `|x|` for an input, `a + b` for both sum and
/// difference, `max(a·b, TINY)` for a product.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Mag(pub f64);

impl Ar for Mag {
    #[inline(always)]
    fn add(&self, o: &Mag) -> Mag {
        Mag(self.0 + o.0)
    }
    #[inline(always)]
    fn sub(&self, o: &Mag) -> Mag {
        Mag(self.0 + o.0)
    }
    #[inline(always)]
    fn mul(&self, o: &Mag) -> Mag {
        Mag((self.0 * o.0).max(TINY))
    }
}

impl Ar for Q {
    fn add(&self, o: &Q) -> Q {
        crate::number::q_add(self, o)
    }
    fn sub(&self, o: &Q) -> Q {
        crate::number::q_sub(self, o)
    }
    fn mul(&self, o: &Q) -> Q {
        crate::number::q_mul(self, o)
    }
}

/// A symmetric 3×3 matrix by its upper triangle: `[m00, m01, m02, m11, m12, m22]`.
pub(crate) type Sym<T> = [T; 6];

#[inline(always)]
fn sym_at(i: usize, j: usize) -> usize {
    const IDX: [[usize; 3]; 3] = [[0, 1, 2], [1, 3, 4], [2, 4, 5]];
    IDX[i][j]
}

/// `s[i][j]` of a symmetric matrix.
#[inline(always)]
pub(crate) fn at<T>(s: &Sym<T>, i: usize, j: usize) -> &T {
    &s[sym_at(i, j)]
}

/// The matrix part `M = KᵀK`, the constant `ρ = σ²` and `K` of a pose
/// (module doc).  `r` the semi-axes, `m` the matrix (rows).
#[inline(always)]
pub(crate) fn pose_form<T: Ar>(r: &[T; 3], m: &[[T; 3]; 3]) -> (Sym<T>, T, [[T; 3]; 3]) {
    let s = [r[1].mul(&r[2]), r[0].mul(&r[2]), r[0].mul(&r[1])];
    // K = diag(s)·Rᵀ
    let k: [[T; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| s[i].mul(&m[j][i])));
    let mm = |i: usize, j: usize| {
        k[0][i]
            .mul(&k[0][j])
            .add(&k[1][i].mul(&k[1][j]))
            .add(&k[2][i].mul(&k[2][j]))
    };
    let msym = [mm(0, 0), mm(0, 1), mm(0, 2), mm(1, 1), mm(1, 2), mm(2, 2)];
    let sigma = r[0].mul(&r[1]).mul(&r[2]);
    let rho = sigma.mul(&sigma);
    (msym, rho, k)
}

/// `det` of a symmetric matrix.
#[inline(always)]
pub(crate) fn det_sym<T: Ar>(s: &Sym<T>) -> T {
    let (a, b, c, d, e, f) = (&s[0], &s[1], &s[2], &s[3], &s[4], &s[5]);
    // a(df − e²) − b(bf − ce) + c(be − cd)
    a.mul(&d.mul(f).sub(&e.mul(e)))
        .sub(&b.mul(&b.mul(f).sub(&c.mul(e))))
        .add(&c.mul(&b.mul(e).sub(&c.mul(d))))
}

/// The adjugate of a symmetric matrix (symmetric).
#[inline(always)]
pub(crate) fn adj_sym<T: Ar>(s: &Sym<T>) -> Sym<T> {
    let (a, b, c, d, e, f) = (&s[0], &s[1], &s[2], &s[3], &s[4], &s[5]);
    [
        d.mul(f).sub(&e.mul(e)),
        c.mul(e).sub(&b.mul(f)),
        b.mul(e).sub(&c.mul(d)),
        a.mul(f).sub(&c.mul(c)),
        b.mul(c).sub(&a.mul(e)),
        a.mul(d).sub(&b.mul(b)),
    ]
}

/// The mixed adjugate `adj(A + B) − adj A − adj B` of two symmetric matrices.
#[inline(always)]
pub(crate) fn mix_sym<T: Ar>(p: &Sym<T>, q: &Sym<T>) -> Sym<T> {
    // for each entry of adj, x·y − z·w becomes x_p y_q + x_q y_p − z_p w_q − z_q w_p
    let m = |x: usize, y: usize, z: usize, w: usize| {
        p[x].mul(&q[y])
            .add(&q[x].mul(&p[y]))
            .sub(&p[z].mul(&q[w]).add(&q[z].mul(&p[w])))
    };
    // indices: a0 b1 c2 d3 e4 f5, as in adj_sym
    [
        m(3, 5, 4, 4),
        m(2, 4, 1, 5),
        m(1, 4, 2, 3),
        m(0, 5, 2, 2),
        m(1, 2, 0, 4),
        m(0, 3, 1, 1),
    ]
}

/// `tr(P·Q)` of two symmetric matrices.
#[inline(always)]
pub(crate) fn tr_prod<T: Ar>(p: &Sym<T>, q: &Sym<T>) -> T {
    let d = p[0].mul(&q[0]).add(&p[3].mul(&q[3])).add(&p[5].mul(&q[5]));
    let o = p[1].mul(&q[1]).add(&p[2].mul(&q[2])).add(&p[4].mul(&q[4]));
    d.add(&o.add(&o))
}

/// `S·v`.
#[inline(always)]
pub(crate) fn sym_vec<T: Ar>(s: &Sym<T>, v: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|i| {
        at(s, i, 0)
            .mul(&v[0])
            .add(&at(s, i, 1).mul(&v[1]))
            .add(&at(s, i, 2).mul(&v[2]))
    })
}

#[inline(always)]
pub(crate) fn dot3<T: Ar>(x: &[T; 3], y: &[T; 3]) -> T {
    x[0].mul(&y[0]).add(&x[1].mul(&y[1])).add(&x[2].mul(&y[2]))
}

/// The pencil of two ellipsoids in the translated frame: the quartic
/// `f(λ) = det(λA + B)` (coefficients from the constant up) and the cubic
/// `h(λ) = det(λM_A + M_B)`, with the matrices the numeric search needs.
#[derive(Clone, Debug)]
pub(crate) struct Pencil<T> {
    pub f: [T; 5],
    pub h: [T; 4],
    pub ma: Sym<T>,
    pub mb: Sym<T>,
    pub rho: [T; 2],
}

/// [`Pencil`] of `(M_A, ρ_A)`, `(M_B, ρ_B)` and `t = c_B − c_A` (module doc).
#[inline(always)]
pub(crate) fn pencil<T: Ar>(ma: Sym<T>, rho_a: T, mb: Sym<T>, rho_b: T, t: [T; 3]) -> Pencil<T> {
    let (adj_a, adj_b) = (adj_sym(&ma), adj_sym(&mb));
    let h3 = det_sym(&ma);
    let h0 = det_sym(&mb);
    let h2 = tr_prod(&adj_a, &mb);
    let h1 = tr_prod(&ma, &adj_b);
    let x = mix_sym(&ma, &mb);
    let u = sym_vec(&mb, &t);
    let v = sym_vec(&ma, &t);
    let tbt = dot3(&t, &u);
    let tat = dot3(&t, &v);
    let uxv = dot3(&u, &sym_vec(&x, &v));
    let c4 = rho_a.mul(&h3);
    let c4 = c4.sub(&c4).sub(&c4); // −ρ_A h₃ (0 − x would need a zero of T)
    let c3 = h3.mul(&tbt).sub(&rho_b.mul(&h3)).sub(&rho_a.mul(&h2));
    let c2 = uxv.sub(&rho_b.mul(&h2)).sub(&rho_a.mul(&h1));
    let c1 = h0.mul(&tat).sub(&rho_b.mul(&h1)).sub(&rho_a.mul(&h0));
    let c0 = rho_b.mul(&h0);
    let c0 = c0.sub(&c0).sub(&c0);
    Pencil {
        f: [c0, c1, c2, c3, c4],
        h: [h0, h1, h2, h3],
        ma,
        mb,
        rho: [rho_a, rho_b],
    }
}

/// `q(x) = |K(x − c)|² − ρ` of a pose at the point x.
#[inline(always)]
pub(crate) fn pose_value<T: Ar>(k: &[[T; 3]; 3], rho: &T, c: &[T; 3], x: &[T; 3]) -> T {
    let d: [T; 3] = std::array::from_fn(|i| x[i].sub(&c[i]));
    let w: [T; 3] = std::array::from_fn(|i| dot3(&k[i], &d));
    dot3(&w, &w).sub(rho)
}

/// Negation in a ring without a zero: `0 − x` as `x − x − x`, exact in
/// every type here (in `f64` too: `x − x = 0` exactly).
pub(crate) fn neg<T: Ar>(x: &T) -> T {
    x.sub(x).sub(x)
}

/// `Σ cₖ λᵏ` by Horner.
#[cfg(test)]
pub(crate) fn horner<T: Ar>(c: &[T], x: &T) -> T {
    let mut v = c[c.len() - 1].clone();
    for ck in c[..c.len() - 1].iter().rev() {
        v = v.mul(x).add(ck);
    }
    v
}

impl Ar for num_bigint::BigInt {
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
}

impl Ar for i64 {
    fn add(&self, o: &i64) -> i64 {
        self + o
    }
    fn sub(&self, o: &i64) -> i64 {
        self - o
    }
    fn mul(&self, o: &i64) -> i64 {
        self * o
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The depth of a node: the most roundings on a path from an input.
    #[derive(Clone, Copy, Debug)]
    struct Depth(u32);
    impl Ar for Depth {
        fn add(&self, o: &Depth) -> Depth {
            Depth(self.0.max(o.0) + 1)
        }
        fn sub(&self, o: &Depth) -> Depth {
            Depth(self.0.max(o.0) + 1)
        }
        fn mul(&self, o: &Depth) -> Depth {
            Depth(self.0.max(o.0) + 1)
        }
    }

    #[test]
    fn depth_of_every_output_is_within_the_bound() {
        let z = Depth(0);
        let r = [z; 3];
        let m = [[z; 3]; 3];
        let (ma, rho_a, ka) = pose_form(&r, &m);
        let (mb, rho_b, _) = pose_form(&r, &m);
        let t = [z.sub(&z); 3]; // c_B − c_A: one rounding
        let p = pencil(ma, rho_a, mb, rho_b, t);
        let mut worst = 0;
        for d in p.f.iter().chain(p.h.iter()) {
            worst = worst.max(d.0);
        }
        let q = pose_value(&ka, &rho_a, &[z; 3], &[z; 3]);
        worst = worst.max(q.0);
        assert!(worst <= DEPTH, "depth {worst} > {DEPTH}");
        assert!(
            worst >= 10,
            "the program is deeper than {worst}: the test is miswired"
        );
    }

    #[test]
    fn unit_spheres_give_the_closed_form() {
        // spheres of radius 1 at distance d: −(λ+1)²(λ² − (d²−2)λ + 1)
        let one = [[1i64, 0, 0], [0, 1, 0], [0, 0, 1]];
        let (ma, ra, _) = pose_form(&[1i64, 1, 1], &one);
        let (mb, rb, _) = pose_form(&[1i64, 1, 1], &one);
        for d in [0i64, 1, 2, 3, 7] {
            let p = pencil(ma, ra, mb, rb, [d, 0, 0]);
            let dd = d * d - 2;
            // expand −(λ² + 2λ + 1)(λ² − Dλ + 1)
            let want = [-1, -(2 - dd), -(2 - 2 * dd), -(2 - dd), -1];
            assert_eq!(p.f, want, "d = {d}");
            assert_eq!(p.h, [1, 3, 3, 1]);
        }
    }

    #[test]
    fn quartic_is_the_determinant_of_the_pencil() {
        // an arbitrary pair with integer data: the coefficients equal a
        // direct 4×4 determinant of λA + B at five values of λ
        let ra = [2i64, 3, 1];
        let rmat = [[1i64, 2, 0], [0, 1, -1], [1, 0, 3]];
        let rb = [1i64, 1, 2];
        let smat = [[2i64, 0, 1], [1, 1, 0], [0, -1, 1]];
        let t = [3i64, -1, 2];
        let (ma, pa, _) = pose_form(&ra, &rmat);
        let (mb, pb, _) = pose_form(&rb, &smat);
        let p = pencil(ma, pa, mb, pb, t);
        let full = |s: &Sym<i64>, rho: i64, c: &[i64; 3]| -> [[i128; 4]; 4] {
            let sc = sym_vec(s, c);
            let mut a = [[0i128; 4]; 4];
            for i in 0..3 {
                for j in 0..3 {
                    a[i][j] = *at(s, i, j) as i128;
                }
                a[i][3] = -(sc[i] as i128);
                a[3][i] = -(sc[i] as i128);
            }
            a[3][3] = dot3(c, &sc) as i128 - rho as i128;
            a
        };
        let a = full(&ma, pa, &[0, 0, 0]);
        let b = full(&mb, pb, &t);
        fn det4(m: [[i128; 4]; 4]) -> i128 {
            let mut s = 0;
            for j in 0..4 {
                let minor: Vec<Vec<i128>> = (1..4)
                    .map(|i| (0..4).filter(|&k| k != j).map(|k| m[i][k]).collect())
                    .collect();
                let d3 = minor[0][0] * (minor[1][1] * minor[2][2] - minor[1][2] * minor[2][1])
                    - minor[0][1] * (minor[1][0] * minor[2][2] - minor[1][2] * minor[2][0])
                    + minor[0][2] * (minor[1][0] * minor[2][1] - minor[1][1] * minor[2][0]);
                s += if j % 2 == 0 {
                    m[0][j] * d3
                } else {
                    -m[0][j] * d3
                };
            }
            s
        }
        for lam in -2i128..3 {
            let m: [[i128; 4]; 4] =
                std::array::from_fn(|i| std::array::from_fn(|j| lam * a[i][j] + b[i][j]));
            let f: i128 = (0..5).map(|k| p.f[k] as i128 * lam.pow(k as u32)).sum();
            assert_eq!(det4(m), f, "λ = {lam}");
        }
    }
}
