//! Hidden-variable resultants of a square system `f₁ = f₂ = f₃ = 0` in
//! x, y, z by the Poisson formula, modulo word primes, lifted by the CRT
//! with an a-priori height bound — exact results with no verification step.
//!
//! Key facts (docs/maths.md, "the Poisson route"):
//!
//! * **Poisson formula** (Cox–Little–O'Shea, *Using Algebraic Geometry*,
//!   ch. 3, Thm 3.4): when the leading forms `f̄ᵢ` have no common zero in
//!   `P²`, i.e. `R̄ = Res(f̄₁, f̄₂, f̄₃) ≠ 0`, the quotient
//!   `A = K[x, y, z]/(f₁, f₂, f₃)` has dimension `d₁d₂d₃` over any field K
//!   and for every `g` of degree `e`
//!   `Res(g, f₁, f₂, f₃) = ± R̄^e · det(multiplication by g on A)`.
//!   With `g = u − h` this is `± R̄^e · charpoly_A(h)(u)`.
//! * The resultant is a polynomial with integer coefficients in the
//!   coefficients of the `fᵢ` and `g`, so its value modulo p is the value
//!   computed modulo p — at *every* prime where `R̄ ≢ 0` (checked: the
//!   quotient modulo p has dimension `d₁d₂d₃`).  No prime is unlucky.
//! * **Height bound** (Sombra, *The height of the mixed sparse resultant*,
//!   Amer. J. Math. 126 (2004), Thm 1.1): the universal resultant of
//!   dense polynomials of degrees `d₀ … d₃` in three variables has
//!   coefficients below `∏ᵢ (#Aᵢ)^{Dᵢ}`, with `#Aᵢ = C(dᵢ + 3, 3)` monomials
//!   and `Dᵢ = ∏_{j≠i} dⱼ` its degree in the coefficients of `fᵢ`.  Each of
//!   its monomials has multidegree `(D₀, …, D₃)`, so it has at most
//!   `∏ᵢ C(#Aᵢ + Dᵢ − 1, Dᵢ)` of them, and at a point whose coefficients
//!   are bounded by `cᵢ` its value is below
//!   `∏ᵢ C(#Aᵢ + Dᵢ − 1, Dᵢ) · #Aᵢ^{Dᵢ} · cᵢ^{Dᵢ}`.  For a coefficient of
//!   `u^k ε^j` of a resultant depending polynomially on `u, ε` the same
//!   holds with `cᵢ` the bound on the unit torus (Cauchy's estimate).
//!
//! The leading-form resultant `R̄` itself is computed modulo p by the
//! Poisson formula one dimension down: for ternary forms,
//! `Res(F₁, F₂, F₃) = ± Res(F₁|_{z=0}, F₂|_{z=0})^{d₃} ·
//! det(F₃(x, y, 1) on K[x, y]/(F₁(x, y, 1), F₂(x, y, 1)))` when the binary
//! resultant is non-zero (else another variable plays z).

use super::groebner_modp::{
    ModGb, ModPoly, ModQuotient, Mono, exps, groebner_mod, mono, normalize, zmpoly_mod,
};
use crate::number::prime31::Fp;
use crate::poly::ZMPoly;
use crate::poly::mpoly::{X, Y, Z};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// A square system with its leading forms.
#[derive(Clone, Debug)]
pub struct SquareSystem {
    /// The three equations, integer and primitive.
    pub gens: [ZMPoly; 3],
    /// Their total degrees.
    pub degs: [u32; 3],
    /// The leading forms (homogeneous parts of top degree).
    forms: [ZMPoly; 3],
    /// The variable (0, 1, 2 for x, y, z) set to 1 for the leading-form
    /// resultant; fixed once for all primes.
    dehom: usize,
}

/// Why a prime gave no image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrimeFail {
    /// The quotient modulo p is not of dimension `d₁d₂d₃` (p divides `R̄`, or
    /// `R̄ = 0`).
    Dimension,
    /// The binary resultant of the leading-form computation vanishes
    /// modulo p.
    Binary,
    /// A degree beyond the F4 limit.
    TooLarge,
}

/// The homogeneous part of top degree.
pub fn leading_form(p: &ZMPoly) -> ZMPoly {
    let d = p.total_degree().unwrap_or(0);
    ZMPoly::from_terms(
        p.terms()
            .iter()
            .filter(|(e, _)| e[X] + e[Y] + e[Z] == d)
            .cloned(),
    )
}

impl SquareSystem {
    /// The system, or `None` when a polynomial is zero or constant, or of
    /// a degree beyond the F4 limit [`MAX_DEGREE`](super::groebner_modp::MAX_DEGREE)
    /// (its monomials do not fit [`Mono`]).
    pub fn new(gens: [ZMPoly; 3]) -> Option<SquareSystem> {
        let mut degs = [0u32; 3];
        for (d, g) in degs.iter_mut().zip(&gens) {
            *d = g
                .total_degree()
                .filter(|&d| d > 0 && d <= super::groebner_modp::MAX_DEGREE)?;
        }
        let forms = std::array::from_fn(|i| leading_form(&gens[i]));
        Some(SquareSystem {
            gens,
            degs,
            forms,
            dehom: 2,
        })
    }

    /// The Bézout number `d₁d₂d₃`: the dimension of the quotient when there
    /// is no zero at infinity.
    pub fn bezout(&self) -> usize {
        self.degs.iter().map(|&d| d as usize).product()
    }

    /// Chooses the variable set to 1 in the leading-form resultant: the
    /// first whose binary resultant is non-zero modulo one of a few primes
    /// (hence over Z).  `false` when none is found.
    pub fn choose_dehomogenisation(&mut self, primes: &[u64]) -> bool {
        for v in [2usize, 0, 1] {
            for &p in primes {
                let fp = Fp::new(p);
                let f: Vec<ModPoly> = self.forms.iter().map(|g| zmpoly_mod(&fp, g)).collect();
                if binary_resultant_mod(&fp, &f[0], &f[1], self.degs[0], self.degs[1], v) != 0 {
                    self.dehom = v;
                    return true;
                }
            }
        }
        false
    }

    /// The reduced Gröbner basis modulo p and its standard monomials, when
    /// the quotient has dimension `d₁d₂d₃` (no zeros at infinity modulo p).
    pub fn quotient_mod(&self, fp: &Fp) -> Result<(ModGb, Vec<Mono>), PrimeFail> {
        let gens: Vec<ModPoly> = self.gens.iter().map(|g| zmpoly_mod(fp, g)).collect();
        let gb = groebner_mod(fp, &gens).ok_or(PrimeFail::TooLarge)?;
        let basis = gb.standard_monomials().ok_or(PrimeFail::Dimension)?;
        if basis.len() != self.bezout() {
            return Err(PrimeFail::Dimension);
        }
        Ok((gb, basis))
    }

    /// Sombra's bound (bits) on `|R̄|`, the resultant of the three leading
    /// forms (ternary forms of degrees `dᵢ` with `C(dᵢ + 2, 2)` monomials).
    pub fn leading_resultant_bound_bits(&self) -> u64 {
        let bounds: Vec<BigInt> = self.forms.iter().map(max_coeff).collect();
        sombra_bits(&self.degs, &bounds, |a| (a + 1) * (a + 2) / 2)
    }

    /// `± R̄ mod p` (the same sign at every prime), by the Poisson formula
    /// in two variables.
    pub fn leading_resultant_mod(&self, fp: &Fp) -> Result<u64, PrimeFail> {
        let f: Vec<ModPoly> = self.forms.iter().map(|g| zmpoly_mod(fp, g)).collect();
        let v = self.dehom;
        let rb = binary_resultant_mod(fp, &f[0], &f[1], self.degs[0], self.degs[1], v);
        if rb == 0 {
            return Err(PrimeFail::Binary);
        }
        // the affine system F₁ = F₂ = 0 in the plane x_v = 1, with x_v = 1
        // imposed as a third generator
        let one = |p: &ModPoly| dehomogenise(fp, p, v);
        let mut var = [0u32; 3];
        var[v] = 1;
        let xv = mono(var[0], var[1], var[2]);
        let gens = vec![one(&f[0]), one(&f[1]), vec![(xv, 1), (0, fp.p as u32 - 1)]];
        let gb = groebner_mod(fp, &gens).ok_or(PrimeFail::TooLarge)?;
        let quo = ModQuotient::new(&gb).ok_or(PrimeFail::Binary)?;
        if quo.dim() != (self.degs[0] * self.degs[1]) as usize {
            return Err(PrimeFail::Binary);
        }
        let g3 = one(&f[2]);
        let targets: Vec<ModPoly> = quo
            .basis
            .iter()
            .map(|&b| {
                let mut t: ModPoly = g3.iter().map(|&(m, c)| (m + b, c)).collect();
                normalize(&mut t);
                t
            })
            .collect();
        let nfs = gb.normal_forms(&targets);
        let n = quo.dim();
        let mut mat: Vec<Vec<u64>> = vec![vec![0; n]; n];
        for (j, nf) in nfs.iter().enumerate() {
            let col = quo.coords(nf).ok_or(PrimeFail::Binary)?;
            for i in 0..n {
                mat[i][j] = col[i];
            }
        }
        let det = det_mod(fp, mat);
        Ok(fp.mul(det, fp.pow(rb, self.degs[2] as u64)))
    }
}

/// `p` with the variable `v` set to 1 (the result does not involve it).
fn dehomogenise(fp: &Fp, p: &ModPoly, v: usize) -> ModPoly {
    let mut out: ModPoly = p
        .iter()
        .map(|&(m, c)| {
            let mut e = exps(m);
            e[v] = 0;
            (mono(e[0], e[1], e[2]), c)
        })
        .collect();
    normalize(&mut out);
    // merge equal monomials
    let mut merged: ModPoly = Vec::with_capacity(out.len());
    for (m, c) in out {
        match merged.last_mut() {
            Some(last) if last.0 == m => last.1 = fp.add(last.1 as u64, c as u64) as u32,
            _ => merged.push((m, c)),
        }
    }
    merged.retain(|t| t.1 != 0);
    merged
}

/// The resultant of the binary forms `F(x_a, x_b) = F|_{x_v = 0}` and
/// `G|_{x_v = 0}` of formal degrees `m`, `n` (a, b the other two
/// variables), by the Sylvester determinant modulo p.
fn binary_resultant_mod(fp: &Fp, f: &ModPoly, g: &ModPoly, m: u32, n: u32, v: usize) -> u64 {
    let a = if v == 0 { 1 } else { 0 };
    // coefficient of x_a^i x_b^(deg−i), i = deg … 0
    let coeffs = |p: &ModPoly, deg: u32| -> Vec<u64> {
        let mut c = vec![0u64; deg as usize + 1];
        for &(mo, k) in p {
            let e = exps(mo);
            if e[v] == 0 {
                c[(deg - e[a]) as usize] = k as u64;
            }
        }
        c
    };
    let (cf, cg) = (coeffs(f, m), coeffs(g, n));
    let size = (m + n) as usize;
    let mut mat = vec![vec![0u64; size]; size];
    for i in 0..n as usize {
        for (k, &c) in cf.iter().enumerate() {
            mat[i][i + k] = c;
        }
    }
    for i in 0..m as usize {
        for (k, &c) in cg.iter().enumerate() {
            mat[n as usize + i][i + k] = c;
        }
    }
    det_mod(fp, mat)
}

/// Determinant modulo p by Gaussian elimination.
pub fn det_mod(fp: &Fp, mut a: Vec<Vec<u64>>) -> u64 {
    let n = a.len();
    let mut det = 1u64;
    for c in 0..n {
        let Some(piv) = (c..n).find(|&i| a[i][c] != 0) else {
            return 0;
        };
        if piv != c {
            a.swap(c, piv);
            det = fp.neg(det);
        }
        det = fp.mul(det, a[c][c]);
        let inv = fp.inv(a[c][c]).expect("non-zero pivot");
        for i in c + 1..n {
            if a[i][c] == 0 {
                continue;
            }
            let f = fp.mul(a[i][c], inv);
            let f = fp.neg(f);
            let (top, bot) = a.split_at_mut(i);
            let prow = &top[c];
            for (x, &y) in bot[0][c..].iter_mut().zip(&prow[c..]) {
                *x = fp.reduce(*x + f * y);
            }
        }
    }
    det
}

/// `C(n, k)` exactly.
fn binomial(n: u64, k: u64) -> BigInt {
    let mut r = BigInt::one();
    for i in 0..k {
        r = r * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    r
}

/// An upper bound (in bits) on `|Res(f₀, f₁, f₂, f₃)|` for polynomials in
/// three variables of total degrees `degs[i]` whose coefficients are
/// bounded in absolute value by `bounds[i]` (Sombra's height bound, see
/// the module documentation).
pub fn resultant_bound_bits(degs: &[u32; 4], bounds: &[BigInt; 4]) -> u64 {
    sombra_bits(degs, bounds, |a| (a + 1) * (a + 2) * (a + 3) / 6)
}

/// Sombra's bound for dense polynomials with `count(d)` monomials of
/// degree ≤ d: `∏ᵢ C(#Aᵢ + Dᵢ − 1, Dᵢ) · #Aᵢ^{Dᵢ} · cᵢ^{Dᵢ}`, in bits.
fn sombra_bits(degs: &[u32], bounds: &[BigInt], count: impl Fn(u64) -> u64) -> u64 {
    let mut total = BigInt::one();
    for i in 0..degs.len() {
        let di: u64 = (0..degs.len())
            .filter(|&j| j != i)
            .map(|j| degs[j] as u64)
            .product();
        let count = count(degs[i] as u64);
        total *= binomial(count + di - 1, di);
        total *= num_traits::pow(BigInt::from(count), di as usize);
        total *= num_traits::pow(bounds[i].abs().max(BigInt::one()), di as usize);
    }
    total.bits()
}

/// The largest absolute value of a coefficient.
pub fn max_coeff(p: &ZMPoly) -> BigInt {
    p.terms()
        .iter()
        .map(|(_, c)| c.abs())
        .max()
        .unwrap_or_else(BigInt::zero)
}
