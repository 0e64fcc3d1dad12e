//! The zeros of a square system `f₁ = f₂ = f₃ = 0` in x, y, z with no
//! zeros at infinity, exactly, from computations modulo word primes that
//! need no verification: every object lifted by the CRT is a *resultant*
//! (an integer polynomial in the input coefficients), its image modulo p is
//! what is computed modulo p, and Sombra's bound on its size says how many
//! primes determine it ([`crate::system::square_resultant`]).
//!
//! * The **RUR** with respect to a linear form ℓ ([`solve_square`]):
//!   `w(u) = Res(u − ℓ, f) = ± R̄ · ∏_ξ (u − ℓ(ξ))` over the
//!   `d₁d₂d₃` zeros ξ, and the Kronecker numerators
//!   `V_v = −∂_ε Res(u − ℓ − εv, f)|_{ε=0} = ± R̄ · Σ_ξ v(ξ) ∏_{η≠ξ} (u − ℓ(η))`
//!   of v = x, y, z.  When `w` is square-free (checked modulo one prime) the
//!   zeros are exactly `ξ(τ) = (V_x, V_y, V_z)(τ) / w′(τ)` over the roots τ
//!   of w, a zero is real iff its τ is.
//! * The **values** of a polynomial h at the zeros selected by a factor
//!   `f | w` ([`value_polynomial`]): `R̄^e · ∏_{f(τ)=0} (u − h(ξ(τ)))` is an
//!   integer polynomial (a factor of `Res(u − h, f)` scaled by Gauss's
//!   lemma) whose image modulo p is the characteristic polynomial of
//!   `h(ξ(T))` in `F_p[T]/(f)`; its size is bounded through Landau's
//!   inequality by Sombra's bound on `Res(u − h, f)`.

use super::rur_modular::Declined;
use crate::number::Q;
use crate::number::modkernel::{mat_vec, mulmod, solve_columns};
use crate::number::prime31::{BlockResidues, CrtVec, Fp, prime31};
use crate::poly::modp::{ModAlgebra, berlekamp_massey, rem_mod};
use crate::poly::{ZMPoly, ZPoly};
use crate::system::groebner_modp::{
    ModGb, ModPoly, ModQuotient, Mono, SparseMult, exps, mono, rank, zmpoly_mod,
};
use crate::system::square_resultant::{PrimeFail, SquareSystem, max_coeff, resultant_bound_bits};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The exact RUR of a square system (see the module documentation).
#[derive(Clone, Debug)]
pub struct PoissonRur {
    /// The separating linear form ℓ = `form[0]·x + form[1]·y + form[2]·z`.
    pub form: [i64; 3],
    /// `w(u) = ± R̄ · charpoly(ℓ)`: degree `d₁d₂d₃`, square-free.
    pub w: ZPoly,
    /// The Kronecker numerators of x, y, z.
    pub v: [ZPoly; 3],
    /// `w′`, the common denominator of the coordinates.
    pub wd: ZPoly,
    /// The number of primes of the CRT.
    pub primes: usize,
    /// The bound on the coefficients the CRT passed, in bits: the smaller
    /// of Sombra's a-priori bound and the census's a-posteriori one.
    pub bound_bits: u64,
    /// Sombra's a-priori bound, in bits.
    pub sombra_bits: u64,
    /// A prime modulo which `w` keeps its degree and is square-free (so `w`
    /// is square-free over Q).
    pub squarefree_prime: u64,
    /// The census of all complex zeros behind the a-posteriori bound, when
    /// the early stop was certified.
    pub census: Option<RurCensus>,
}

/// The certified early stop of the RUR's CRT (docs/maths.md, "An
/// a-posteriori bound for the RUR"): every zero of F enclosed, and the
/// sizes it bounds.
#[derive(Clone, Debug)]
pub struct RurCensus {
    /// One certified box per zero of F.
    pub zeros: crate::system::census::ZeroCensus,
    /// `±R̄` exactly (its own CRT beyond Sombra's bound on it).
    pub rbar: BigInt,
    /// The primes of R̄'s CRT.
    pub rbar_primes: usize,
    /// Per coordinate v, a `b` with `∏_ξ (1 + |v(ξ)|) < 2^b`.
    pub coordinate_bits: [u64; 3],
    /// The a-posteriori bound on the RUR's coefficients, in bits.
    pub bits: u64,
}

impl PoissonRur {
    /// A bound (bits) on the coefficients of the coordinate eliminants
    /// `Res(u − v, F)`: Sombra's bound for ℓ covers them (its `|ℓᵢ| + 1 ≥
    /// 2`); with a census, `|R̄|·∏(1 + |v(ξ)|)` for the worst v.
    pub fn eliminant_bound_bits(&self) -> u64 {
        match &self.census {
            Some(c) => c.rbar.bits() + c.coordinate_bits.iter().max().copied().unwrap_or(0),
            None => self.sombra_bits,
        }
    }

    /// `± R̄`, the resultant of the leading forms (the leading coefficient
    /// of w).
    pub fn leading_resultant(&self) -> BigInt {
        self.w.lc()
    }

    /// The zero at a rational τ rounded down to dyadics of scale `2^-k`
    /// (integer arithmetic only; `None` where `w′(τ) = 0`).
    pub fn point_dyadic(&self, t: &Q, k: usize) -> Option<crate::system::krawczyk::Dyadic3> {
        let (dn, dd) = self.wd.eval_homogeneous(t.numer(), t.denom());
        if dn.is_zero() {
            return None;
        }
        let mut num: [BigInt; 3] = std::array::from_fn(|_| BigInt::zero());
        let mut den: [BigInt; 3] = std::array::from_fn(|_| BigInt::zero());
        for i in 0..3 {
            let (n, d) = self.v[i].eval_homogeneous(t.numer(), t.denom());
            num[i] = n * &dd;
            den[i] = d * &dn;
        }
        Some(crate::system::krawczyk::Dyadic3::floor_ratio(&num, &den, k))
    }

    /// The zero at a rational τ (exact; `None` where `w′(τ) = 0`).
    pub fn point_at(&self, t: &Q) -> Option<[Q; 3]> {
        let (dn, dd) = self.wd.eval_homogeneous(t.numer(), t.denom());
        if dn.is_zero() {
            return None;
        }
        Some(std::array::from_fn(|k| {
            let (n, d) = self.v[k].eval_homogeneous(t.numer(), t.denom());
            Q::new(n * &dd, d * &dn)
        }))
    }
}

/// The charpoly of ℓ on the quotient modulo p (monic, low coefficients
/// `f_0 … f_(n−1)`) and the Kronecker numerators `G_v = v·f′(ℓ) mod f` of
/// x, y, z — when ℓ generates the quotient and `f` is square-free.
pub(crate) fn kronecker_mod(
    fp: &Fp,
    quo: &ModQuotient,
    ell: [u64; 3],
) -> Option<(Vec<u64>, [Vec<u64>; 3])> {
    let n = quo.dim();
    let cols = quo.combined_columns(fp, ell);
    let mut e1 = vec![0u64; n];
    e1[0] = 1;
    let mut kry = Vec::with_capacity(n + 1);
    kry.push(e1);
    for _ in 0..n {
        crate::budget::check();
        let next = mat_vec(fp, &cols, n, kry.last().expect("non-empty"));
        kry.push(next);
    }
    let top = kry.pop().expect("n + 1 vectors");
    let xs: Vec<Vec<u64>> = (0..3)
        .map(|v| quo.mult[v][0].iter().map(|&c| c as u64).collect())
        .collect();
    let rhs = vec![top, xs[0].clone(), xs[1].clone(), xs[2].clone()];
    let sol = solve_columns(fp, &kry, &rhs)?;
    // T^n = Σ c_j T^j: f = T^n − Σ c_j T^j
    let c = &sol[0];
    let alg = ModAlgebra::from_c(*fp, c.clone());
    if !alg.is_squarefree() {
        return None;
    }
    let fd = alg.derivative();
    let g: [Vec<u64>; 3] = std::array::from_fn(|k| mulmod(fp, &sol[1 + k], &fd, c));
    Some((alg.low(), g))
}

/// The coordinates of the normal forms of x, y, z on `basis`.
fn variable_coords(gb: &ModGb, basis: &[Mono]) -> Option<[Vec<u64>; 3]> {
    let targets: Vec<ModPoly> = [mono(1, 0, 0), mono(0, 1, 0), mono(0, 0, 1)]
        .iter()
        .map(|&m| vec![(m, 1)])
        .collect();
    let nfs = gb.normal_forms(&targets);
    let n = basis.len();
    let mut out: [Vec<u64>; 3] = std::array::from_fn(|_| vec![0u64; n]);
    for (v, nf) in nfs.iter().enumerate() {
        for &(m, c) in nf {
            let i = basis.binary_search_by_key(&rank(m), |&b| rank(b)).ok()?;
            out[v][i] = c as u64;
        }
    }
    Some(out)
}

/// [`kronecker_mod`] for ℓ = the variable `var`, from the sparse
/// multiplication matrix (Wiedemann / sparse FGLM): with φ the coefficient
/// of 1, the sequence `φ(ℓᵏ)` (k < 2n) gives the minimal polynomial f by
/// Berlekamp–Massey, and `φ(v·ℓᵏ)` (k < n) the numerators
/// `N_v = [f(T)·Σ φ(v ℓᵏ) T^{−k−1}]₊ = Σ_ξ c_ξ v(ξ) f(T)/(T − ℓ(ξ))`, so
/// that `G_v = v·f′ = N_v·f′/N_1 mod f` (φ = Σ c_ξ ev_ξ with every c_ξ ≠ 0
/// exactly when the sequence has degree n).
pub(crate) fn kronecker_sparse(
    fp: &Fp,
    gb: &ModGb,
    basis: &[Mono],
    var: usize,
) -> Option<(Vec<u64>, [Vec<u64>; 3])> {
    let n = basis.len();
    let mult = SparseMult::new(gb, basis, var)?;
    let coords = variable_coords(gb, basis)?;
    // forward vectors v_j = Mʲ·1 and transposed rows r_j = (Mᵀ)ʲ·e₀
    // (j < n): φ(ℓᵏ) = r_⌈k/2⌉ · v_⌊k/2⌋ for k < 2n, and
    // φ(u·ℓᵏ) = r_k · (coordinates of u) for k < n
    let mut fwd: Vec<Vec<u64>> = Vec::with_capacity(n);
    let mut rows: Vec<Vec<u64>> = Vec::with_capacity(n);
    let mut v = vec![0u64; n];
    v[0] = 1;
    let mut r = v.clone();
    for j in 0..n {
        crate::budget::check();
        let (nv, nr) = if j + 1 < n {
            (mult.apply(fp, &v), mult.apply_transposed(fp, &r))
        } else {
            (Vec::new(), Vec::new())
        };
        fwd.push(std::mem::replace(&mut v, nv));
        rows.push(std::mem::replace(&mut r, nr));
    }
    let dot = crate::number::modkernel::dot;
    let a: Vec<u64> = (0..2 * n)
        .map(|k| {
            let (i, j) = (k.div_ceil(2), k / 2);
            if i < n {
                dot(fp, &rows[i], &fwd[j])
            } else {
                // k = 2n − 1: r_n is not kept; use r_(n−1)·(M·v_(n−1))
                dot(fp, &rows[n - 1], &mult.apply(fp, &fwd[j]))
            }
        })
        .collect();
    let f = berlekamp_massey(fp, &a);
    if f.len() != n + 1 {
        return None;
    }
    let c: Vec<u64> = f[..n].iter().map(|&x| fp.neg(x)).collect();
    let alg = ModAlgebra::from_c(*fp, c);
    if !alg.is_squarefree() {
        return None;
    }
    // N[i] = Σ_{j=i+1}^{n} f_j s_{j−i−1}
    let numer = |s: &[u64]| -> Vec<u64> {
        (0..n)
            .map(|i| dot(fp, &f[i + 1..=n], &s[..n - i]))
            .collect()
    };
    let n1 = numer(&a[..n]);
    let inv1 = alg.inv(&n1)?;
    let fd = alg.derivative();
    let scale = alg.mul(&fd, &inv1);
    let g: [Vec<u64>; 3] = std::array::from_fn(|u| {
        let s: Vec<u64> = if u == var {
            a[1..=n].to_vec()
        } else {
            rows.iter().map(|rk| dot(fp, rk, &coords[u])).collect()
        };
        alg.mul(&numer(&s), &scale)
    });
    Some((alg.low(), g))
}

/// coprime to f, as the polynomial of degree < deg f: computed modulo word
/// primes (`num · den⁻¹` in `F_p[T]/(f)`), lifted by the CRT and rational
/// reconstruction with a common denominator on a geometric schedule, and
/// returned only when `q·den ≡ num (mod f)` holds exactly (f, primitive,
/// divides `d·(q·den − num)` over Z, d the common denominator).  Exact
/// extended Euclid over Q would build the same answer through remainders
/// whose coefficients are far longer.  `None` when no verified answer came
/// within `max_primes`.
pub(crate) fn quotient_mod_f(
    num: &ZPoly,
    den: &ZPoly,
    f: &ZPoly,
    max_primes: usize,
) -> Option<crate::poly::QPoly> {
    let n = f.degree().filter(|&n| n >= 1)?;
    let mut crt = CrtVec::new(n);
    let mut next_bits = 62u64;
    for j in 0..max_primes {
        crate::budget::check_now();
        let fp = Fp::new(prime31(j));
        let red = |p: &ZPoly| -> Vec<u64> { p.coeffs().iter().map(|c| fp.reduce_big(c)).collect() };
        let fm = red(f);
        if fm.last() == Some(&0) {
            continue;
        }
        let Some(alg) = ModAlgebra::from_poly(fp, &fm) else {
            continue;
        };
        let reduce = |a: &[u64]| -> Vec<u64> {
            let mut r = rem_mod(&fp, a, &fm);
            r.resize(n, 0);
            r
        };
        let Some(dinv) = alg.inv(&reduce(&red(den))) else {
            continue;
        };
        crt.push(&fp, &alg.mul(&reduce(&red(num)), &dinv));
        if crt.modulus_bits() < next_bits {
            continue;
        }
        next_bits = crt.modulus_bits() + (crt.modulus_bits() / 4).max(62);
        crt.flush();
        let Some((nums, d)) =
            crate::number::reconstruct::reconstruct_common(crt.values(), crt.modulus())
        else {
            continue;
        };
        // q = Σ nums_i T^i / d: f divides nums·den − d·num over Z (f is
        // primitive: exact division over Z, no fractions)
        let qz = ZPoly::new(nums);
        let h = &(&qz * den) - &num.scale(&d);
        if h.is_zero() || h.div_exact(f).is_some() {
            return Some(qz.to_q().scale(&Q::new(BigInt::one(), d)));
        }
    }
    None
}

/// Polynomials in x, y, z (modulo p) evaluated in the algebra.
impl ModAlgebra {
    /// [`ModAlgebra::eval`] when coordinate `sep` is T itself (the
    /// separating coordinate of a RUR; `xyz[sep]` is not read): a term
    /// `c·u1^a·u2^b·T^e` adds `c·T^e·u2^b` (powers of u2 by its matrix,
    /// then shifts by T) to the coefficient of `u1^a`, and Horner's rule in
    /// u1 runs by the matrix of u1: `(deg u1 + deg u2 + 2)·n²` products
    /// and `n` per term, no product modulo f.
    pub(crate) fn eval_sep(&self, p: &ModPoly, xyz: [&[u64]; 3], sep: usize) -> Vec<u64> {
        use crate::number::modkernel::{axpy_lazy, mat_vec};
        let fp = &self.fp;
        let n = self.n();
        let terms: Vec<([u32; 3], u64)> = p.iter().map(|&(m, c)| (exps(m), c as u64)).collect();
        let deg = |v: usize| terms.iter().map(|t| t.0[v]).max().unwrap_or(0) as usize;
        if deg(sep) >= n {
            return self.eval(p, xyz);
        }
        let others: Vec<usize> = (0..3).filter(|&v| v != sep).collect();
        // Horner in u1 (the lower degree), powers of u2
        let (u1, u2) = if deg(others[0]) <= deg(others[1]) {
            (others[0], others[1])
        } else {
            (others[1], others[0])
        };
        let (d1, d2, ds) = (deg(u1), deg(u2), deg(sep));
        // T^e·u2^b for b ≤ d2, e ≤ ds: powers by the matrix of u2, then shifts
        let mut one = vec![0u64; n];
        one[0] = 1;
        let mut pw: Vec<Vec<u64>> = vec![one];
        if d2 >= 1 {
            let mut u = xyz[u2].to_vec();
            u.resize(n, 0);
            pw.push(u);
        }
        if d2 >= 2 {
            let m2 = self.mult_matrix(xyz[u2]);
            for k in 2..=d2 {
                crate::budget::check();
                let next = mat_vec(fp, &m2, n, &pw[k - 1]);
                pw.push(next);
            }
        }
        let shifted: Vec<Vec<Vec<u64>>> = pw
            .into_iter()
            .map(|p| {
                let mut row = Vec::with_capacity(ds + 1);
                row.push(p);
                for e in 1..=ds {
                    let next = self.times_t(&row[e - 1]);
                    row.push(next);
                }
                row
            })
            .collect();
        // C_a = Σ c·T^e·u2^b over the terms of exponent a in u1
        let mut coeffs = vec![vec![0u64; n]; d1 + 1];
        for (e, c) in &terms {
            let v = &shifted[e[u2] as usize][e[sep] as usize];
            axpy_lazy(fp, &mut coeffs[e[u1] as usize], *c, v);
        }
        for c in coeffs.iter_mut() {
            c.iter_mut().for_each(|x| *x = fp.reduce(*x));
        }
        // Horner in u1 by its matrix
        let mut acc = coeffs.pop().expect("d1 + 1 coefficients");
        if d1 == 0 {
            return acc;
        }
        let m1 = self.mult_matrix(xyz[u1]);
        for c in coeffs.iter().rev() {
            crate::budget::check();
            acc = mat_vec(fp, &m1, n, &acc);
            for (x, &y) in acc.iter_mut().zip(c) {
                *x = fp.add(*x, y);
            }
        }
        acc
    }

    /// The value of a polynomial in x, y, z (modulo p) at algebra elements.
    pub(crate) fn eval(&self, p: &ModPoly, xyz: [&[u64]; 3]) -> Vec<u64> {
        let fp = &self.fp;
        let n = self.n();
        // terms by exponent of x, then y; inner sums are combinations of
        // the powers of z (no products)
        let mut terms: Vec<([u32; 3], u64)> = p.iter().map(|&(m, c)| (exps(m), c as u64)).collect();
        terms.sort_by_key(|t| std::cmp::Reverse(t.0));
        let dz = terms.iter().map(|t| t.0[2]).max().unwrap_or(0) as usize;
        let mut zp: Vec<Vec<u64>> = Vec::with_capacity(dz + 1);
        let mut one = vec![0u64; n];
        one[0] = 1;
        zp.push(one);
        for k in 1..=dz {
            let next = self.mul(&zp[k - 1], xyz[2]);
            zp.push(next);
        }
        let inner = |ts: &[([u32; 3], u64)]| -> Vec<u64> {
            let mut acc = vec![0u64; n];
            for (e, c) in ts {
                crate::number::modkernel::axpy_lazy(fp, &mut acc, *c, &zp[e[2] as usize]);
            }
            acc.iter().map(|&x| fp.reduce(x)).collect()
        };
        // Horner in x over a, each coefficient a Horner in y over b
        let horner = |groups: Vec<(u32, Vec<u64>)>, var: &[u64]| -> Vec<u64> {
            let mut acc: Option<Vec<u64>> = None;
            let mut prev = 0u32;
            for (k, poly) in groups {
                // groups by decreasing exponent
                acc = Some(match acc {
                    None => {
                        prev = k;
                        poly
                    }
                    Some(mut a) => {
                        for _ in k..prev {
                            a = self.mul(&a, var);
                        }
                        prev = k;
                        a.iter().zip(&poly).map(|(&x, &y)| fp.add(x, y)).collect()
                    }
                });
            }
            let mut a = acc.unwrap_or_else(|| vec![0u64; n]);
            for _ in 0..prev {
                a = self.mul(&a, var);
            }
            a
        };
        let mut by_x: Vec<(u32, Vec<u64>)> = Vec::new();
        let mut i = 0;
        while i < terms.len() {
            let a = terms[i].0[0];
            let mut by_y: Vec<(u32, Vec<u64>)> = Vec::new();
            while i < terms.len() && terms[i].0[0] == a {
                let b = terms[i].0[1];
                let start = i;
                while i < terms.len() && terms[i].0[0] == a && terms[i].0[1] == b {
                    i += 1;
                }
                by_y.push((b, inner(&terms[start..i])));
            }
            by_x.push((a, horner(by_y, xyz[1])));
        }
        horner(by_x, xyz[0])
    }
}

/// The linear form of the variable `v`.
pub(crate) fn unit_form(v: usize) -> [i64; 3] {
    let mut e = [0i64; 3];
    e[v] = 1;
    e
}

/// The exact RUR of the square system with the first linear form of
/// `forms` that separates its zeros (see the module documentation).
/// Declines when the leading forms have a common zero at infinity, when no
/// form gives a square-free characteristic polynomial (multiple zeros, or
/// no separating form among those tried), or when the prime limit is
/// reached.
pub fn solve_square(
    sys: &mut SquareSystem,
    forms: &[[i64; 3]],
    max_primes: usize,
) -> Result<PoissonRur, Declined> {
    let decline = |s: &str| Err(Declined(s.into()));
    let probe: Vec<u64> = (0..3).map(prime31).collect();
    if !sys.choose_dehomogenisation(&probe) {
        return decline("the leading forms share a zero on every coordinate line at infinity");
    }
    let n = sys.bezout();
    crate::budget::check_size("the Poisson RUR", 4 * n + 1, 0);
    let mut chosen: Option<usize> = None;
    let mut crt = CrtVec::new(4 * n + 1);
    let mut bound_bits = 0u64;
    let mut sombra_bits = 0u64;
    let mut squarefree_prime = 0u64;
    let (mut fails, mut dim_fails) = (0usize, 0usize);
    // R̄ on its own (every prime where it is defined), for the census
    let mut rbar = CrtVec::new(1);
    let mut census: Option<RurCensus> = None;
    let mut census_tries = 0usize;
    let mut next = 0usize;
    while next < max_primes {
        crate::budget::check_now();
        let k = next;
        next += 1;
        let fp = Fp::new(prime31(k));
        // R̄ mod p first (a small computation): R̄ ≡ 0 means zeros at infinity
        // modulo p, and the Gröbner basis is not needed to see it
        let zeros_at_infinity = |dim_fails: &mut usize| -> Option<Result<PoissonRur, Declined>> {
            *dim_fails += 1;
            (chosen.is_none() && *dim_fails >= 3).then(|| {
                decline(
                    "zeros at infinity: the leading forms have a common zero modulo three primes",
                )
            })
        };
        let r = match sys.leading_resultant_mod(&fp) {
            Ok(0) => {
                rbar.push(&fp, &[0]);
                if let Some(d) = zeros_at_infinity(&mut dim_fails) {
                    return d;
                }
                continue;
            }
            Ok(r) => r,
            Err(PrimeFail::TooLarge) => return decline("degree too large for the modular route"),
            Err(_) => {
                fails += 1;
                continue;
            }
        };
        rbar.push(&fp, &[r]);
        let (gb, basis) = match sys.quotient_mod(&fp) {
            Ok(q) => q,
            Err(PrimeFail::TooLarge) => return decline("degree too large for the modular route"),
            Err(_) => {
                // R̄ ≢ 0 gives the Bézout dimension: only a bug gets here
                if let Some(d) = zeros_at_infinity(&mut dim_fails) {
                    return d;
                }
                continue;
            }
        };
        let candidates: Vec<usize> = match chosen {
            Some(i) => vec![i],
            None => (0..forms.len()).collect(),
        };
        // a single variable as ℓ: the sparse route; otherwise the dense
        // multiplication matrices (built once for this prime)
        let mut quo: Option<Option<ModQuotient>> = None;
        let got = candidates.into_iter().find_map(|i| {
            let ell = forms[i];
            if let Some(v) = (0..3).find(|&v| ell == unit_form(v)) {
                return kronecker_sparse(&fp, &gb, &basis, v).map(|img| (i, img));
            }
            let q = quo.get_or_insert_with(|| ModQuotient::new(&gb)).as_ref()?;
            let ellp = ell.map(|x| fp.reduce_big(&BigInt::from(x)));
            kronecker_mod(&fp, q, ellp).map(|img| (i, img))
        });
        let Some((i, (f_low, g))) = got else {
            fails += 1;
            if chosen.is_none() && fails >= 2 {
                return decline(
                    "no linear form tried separates the zeros (multiple zeros or a symmetric system)",
                );
            }
            continue;
        };
        if chosen.is_none() {
            chosen = Some(i);
            squarefree_prime = fp.p;
            // f₀ = u − ℓ − ε·v: coefficients at most max|ℓᵢ| + 1 on the torus
            let lmax = forms[i].iter().map(|x| x.unsigned_abs()).max().unwrap_or(0);
            let degs = [1, sys.degs[0], sys.degs[1], sys.degs[2]];
            let bounds = [
                BigInt::from(lmax + 1),
                max_coeff(&sys.gens[0]),
                max_coeff(&sys.gens[1]),
                max_coeff(&sys.gens[2]),
            ];
            bound_bits = resultant_bound_bits(&degs, &bounds);
            sombra_bits = bound_bits;
        }
        let mut res: Vec<u64> = f_low.iter().map(|&c| fp.mul(c, r)).collect();
        res.push(r);
        for gv in &g {
            res.extend(gv.iter().map(|&c| fp.mul(c, r)));
        }
        crt.push(&fp, &res);
        crate::budget::check_size("the Poisson RUR", 4 * n + 1, crt.modulus_bits());
        // the image looks stable: try to prove a smaller bound from it
        // (when at least three primes remain to the a-priori bound)
        if census.is_none()
            && census_tries < census_limit()
            && crt.modulus_bits() + 93 <= bound_bits + 1
            && crt.newest_digits_stable()
        {
            census_tries += 1;
            let form = forms[chosen.expect("chosen")];
            if let Some(c) = try_census(sys, &mut crt, &mut rbar, &mut next, form, n) {
                bound_bits = bound_bits.min(c.bits);
                census = Some(c);
            }
        }
        if crt.modulus_bits() > bound_bits + 1 {
            let (w, v) = rur_image(&mut crt, n);
            let wd = w.derivative();
            return Ok(PoissonRur {
                form: forms[chosen.expect("chosen")],
                w,
                v,
                wd,
                primes: crt.primes(),
                bound_bits,
                sombra_bits,
                squarefree_prime,
                census,
            });
        }
        if fails > 16 + k / 2 {
            return decline("too many primes without an image");
        }
    }
    decline("the prime limit was reached")
}

#[cfg(test)]
thread_local! {
    /// Tests: the RUR from Sombra's bound alone (no census).
    pub(crate) static NO_CENSUS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// How many times the census is tried (three; none in tests that ask
/// for the a-priori route).
fn census_limit() -> usize {
    #[cfg(test)]
    if NO_CENSUS.with(|c| c.get()) {
        return 0;
    }
    3
}

/// The RUR `(w, V)` the CRT's values stand for (symmetric images): w's
/// `n + 1` coefficients, then the `n` of each numerator.
fn rur_image(crt: &mut CrtVec, n: usize) -> (ZPoly, [ZPoly; 3]) {
    let vals = crt.symmetric_values();
    let w = ZPoly::new(vals[..=n].to_vec());
    let v = std::array::from_fn(|j| ZPoly::new(vals[n + 1 + j * n..n + 1 + (j + 1) * n].to_vec()));
    (w, v)
}

/// The candidate `(w, V)` from the current image, its census, and R̄
/// exactly (more primes for R̄ alone, from `next` on, until its CRT passes
/// Sombra's bound on it); `None` when the census does not certify all `n`
/// zeros.
fn try_census(
    sys: &SquareSystem,
    crt: &mut CrtVec,
    rbar: &mut CrtVec,
    next: &mut usize,
    form: [i64; 3],
    n: usize,
) -> Option<RurCensus> {
    let (w, v) = rur_image(crt, n);
    if w.degree() != Some(n) {
        return None;
    }
    let zeros = crate::system::census::census(&sys.gens, &w, &v)?;
    // the census proves n distinct zeros: exactly the Bézout number
    if zeros.boxes.len() != n {
        return None;
    }
    let target = sys.leading_resultant_bound_bits();
    let mut misses = 0usize;
    while rbar.modulus_bits() <= target + 1 {
        crate::budget::check_now();
        let fp = Fp::new(prime31(*next));
        *next += 1;
        match sys.leading_resultant_mod(&fp) {
            Ok(r) => rbar.push(&fp, &[r]),
            Err(_) => {
                misses += 1;
                if misses > 16 {
                    return None;
                }
            }
        }
    }
    let r = rbar.symmetric_values().pop().expect("one value");
    let coordinate_bits = zeros.coordinate_bits()?;
    let bits = zeros.rur_bits(form, r.bits())?;
    Some(RurCensus {
        zeros,
        rbar_primes: rbar.primes(),
        rbar: r,
        coordinate_bits,
        bits,
    })
}

/// The residues of a block of polynomials' coefficients (in order, as
/// given to [`BlockResidues`]) cut into one slice per polynomial, and the
/// position after the last.
fn split_residues<'a>(all: &'a [u64], polys: &[&ZPoly]) -> (Vec<&'a [u64]>, usize) {
    let mut parts = Vec::with_capacity(polys.len());
    let mut at = 0;
    for p in polys {
        parts.push(&all[at..at + p.coeffs().len()]);
        at += p.coeffs().len();
    }
    (parts, at)
}

/// `⌈bits(m)/2⌉`: `√m < 2^sqrt_bits(m)`.
pub(crate) fn sqrt_bits(m: usize) -> u64 {
    (usize::BITS - m.leading_zeros()).div_ceil(2) as u64
}

/// The bits the CRT modulus of [`value_polynomial`] must pass (it passes
/// `target + 1`): the smaller of Landau's bound on the factor `R̄^e·A` of
/// `Res(u − h, F)` (`‖R̄^e·A‖∞ ≤ 2^deg A·√(bezout + 1)·2^resultant_bits`,
/// `√(bezout + 1) < 2^⌈bits(bezout + 1)/2⌉`) and a direct bound on it
/// ([`ValueMap::direct_bits`]).
pub fn value_target_bits(
    resultant_bits: u64,
    nf: usize,
    bezout: usize,
    direct_bits: Option<u64>,
) -> u64 {
    let landau = resultant_bits + nf as u64 + sqrt_bits(bezout + 1);
    direct_bits.map_or(landau, |d| d.min(landau))
}

/// `Res(u − v, F) = ± R̄ · charpoly(v)` exactly for the coordinates
/// v = x, y, z, from the exact RUR: modulo p it is `lc(w)·χ(v_v/w′)` in
/// `F_p[T]/(w)` (Poisson's formula; the coordinate that is ℓ gives w
/// itself), at every prime where `lc(w) ≢ 0` and w is square-free (w′
/// invertible modulo w).  They are resultants of the same degrees as
/// `w = Res(u − ℓ, F)` with `f₀ = u − v` of coefficients at most those of
/// `u − ℓ`, so the RUR's bound (`rur.bound_bits`) bounds them, and the CRT
/// stops beyond it.  Their Mahler measures bound the coordinates of all
/// zeros at once (see `tangent::poisson`, the judging polynomial's direct
/// bound).
pub fn coordinate_eliminants(rur: &PoissonRur, max_primes: usize) -> Result<[ZPoly; 3], Declined> {
    let n = rur.w.degree().unwrap_or(0);
    let own = (0..3).find(|&v| rur.form == unit_form(v));
    let polys = [&rur.w, &rur.wd, &rur.v[0], &rur.v[1], &rur.v[2]];
    let ints: Vec<&BigInt> = polys.iter().flat_map(|p| p.coeffs()).collect();
    let mut blocks = BlockResidues::new(ints);
    let mut crt = CrtVec::new(3 * (n + 1));
    for k in 0..max_primes {
        crate::budget::check_now();
        let fp = Fp::new(prime31(k));
        let all = blocks.residues(k, &fp);
        let (parts, _) = split_residues(&all, &polys);
        let wm = parts[0];
        let r = *wm.last().expect("w has degree ≥ 1");
        if r == 0 {
            continue;
        }
        let Some(alg) = ModAlgebra::from_poly(fp, wm) else {
            continue;
        };
        let mut wd = rem_mod(&fp, parts[1], wm);
        wd.resize(n, 0);
        let Some(dinv) = alg.inv(&wd) else {
            continue;
        };
        let mut res = Vec::with_capacity(3 * (n + 1));
        for v in 0..3 {
            let chi = if own == Some(v) {
                let mut f = alg.low();
                f.push(1);
                f
            } else {
                let mut num = rem_mod(&fp, parts[2 + v], wm);
                num.resize(n, 0);
                alg.charpoly(&alg.mul(&num, &dinv))
            };
            res.extend(chi.iter().map(|&c| fp.mul(c, r)));
        }
        crt.push(&fp, &res);
        if crt.modulus_bits() > rur.eliminant_bound_bits() + 1 {
            let vals = crt.symmetric_values();
            return Ok(std::array::from_fn(|v| {
                ZPoly::new(vals[v * (n + 1)..(v + 1) * (n + 1)].to_vec())
            }));
        }
    }
    Err(Declined(
        "the prime limit was reached (coordinate eliminants)".into(),
    ))
}

/// What [`value_polynomial`] computes: the values of `h` (an integer
/// polynomial of degree `degree`) at the zeros, read from a polynomial
/// `eval` with `h(ξ) = scale · eval(ξ)` at every zero ξ of the factor (e.g.
/// `eval` = h reduced modulo an equation of the system, which is cheaper
/// to evaluate).
pub struct ValueMap<'a> {
    /// The degree of h (the power of `R̄` in the result).
    pub degree: u32,
    /// The polynomial evaluated modulo p.
    pub eval: &'a ZMPoly,
    /// `h / eval` at the zeros.
    pub scale: &'a Q,
    /// A bound (bits) on the coefficients of the result itself, used when
    /// it is below the general one (see [`value_target_bits`]).
    pub direct_bits: Option<u64>,
}

/// `R̄^e · ∏_{f(τ)=0} (u − h(ξ(τ)))` exactly, for a square-free factor `f`
/// of `rur.w` and `h` of degree `e` (given by `map`), where
/// `resultant_bits` bounds the coefficients of `Res(u − h, system)` (see
/// [`value_bound_bits`]).  Its primitive part is the polynomial of the
/// values of h at the zeros of f.  Also returns the number of primes.
pub fn value_polynomial(
    rur: &PoissonRur,
    f: &ZPoly,
    map: &ValueMap,
    resultant_bits: u64,
    bezout: usize,
    max_primes: usize,
) -> Result<(ZPoly, usize), Declined> {
    let nf = f.degree().unwrap_or(0);
    if nf == 0 {
        return Ok((ZPoly::constant(BigInt::one()), 0));
    }
    // the polynomial is evaluated in its packed form modulo p
    if map.eval.total_degree().unwrap_or(0) > crate::system::groebner_modp::MAX_DEGREE {
        return Err(Declined(
            "the polynomial whose values are asked for is of too high a degree for the modular evaluation".into(),
        ));
    }
    let target = value_target_bits(resultant_bits, nf, bezout, map.direct_bits);
    let rbar = rur.leading_resultant();
    let mut crt = CrtVec::new(nf + 1);
    // every big integer of a prime's step, reduced a block of primes at a
    // time: f, w′, the numerators v, then R̄ and the scale
    let polys = [f, &rur.wd, &rur.v[0], &rur.v[1], &rur.v[2]];
    let ints: Vec<&BigInt> = polys
        .iter()
        .flat_map(|p| p.coeffs())
        .chain([&rbar, map.scale.numer(), map.scale.denom()])
        .collect();
    let mut blocks = BlockResidues::new(ints);
    let sep = (0..3).find(|&v| rur.form == unit_form(v));
    for k in 0..max_primes {
        crate::budget::check_now();
        let fp = Fp::new(prime31(k));
        let all = blocks.residues(k, &fp);
        let (parts, at) = split_residues(&all, &polys);
        let (r, sn, sd) = (all[at], all[at + 1], all[at + 2]);
        let fm = parts[0];
        if fm.last() == Some(&0) || r == 0 || sn == 0 || sd == 0 {
            continue;
        }
        let Some(alg) = ModAlgebra::from_poly(fp, fm) else {
            continue;
        };
        let reduce = |a: &[u64]| -> Vec<u64> {
            let mut rem = rem_mod(&fp, a, fm);
            rem.resize(nf, 0);
            rem
        };
        let Some(dinv) = alg.inv(&reduce(parts[1])) else {
            continue;
        };
        // the separating coordinate (when ℓ is one) is T itself
        let xs: Vec<Vec<u64>> = parts[2..]
            .iter()
            .enumerate()
            .map(|(i, v)| {
                if sep == Some(i) {
                    Vec::new()
                } else {
                    alg.mul(&reduce(v), &dinv)
                }
            })
            .collect();
        let pm = zmpoly_mod(&fp, map.eval);
        let s = match sep {
            Some(v) => alg.eval_sep(&pm, [&xs[0], &xs[1], &xs[2]], v),
            None => alg.eval(&pm, [&xs[0], &xs[1], &xs[2]]),
        };
        let chi = alg.charpoly(&s);
        // ∏(u − σ·s_j) = Σ σ^(N−i) χ_i u^i, times R̄^e
        let sigma = fp.mul(sn, fp.inv(sd).expect("non-zero"));
        let re = fp.pow(r, map.degree as u64);
        let mut res = vec![0u64; nf + 1];
        let mut pw = re;
        for i in (0..=nf).rev() {
            res[i] = fp.mul(chi[i], pw);
            pw = fp.mul(pw, sigma);
        }
        crt.push(&fp, &res);
        crate::budget::check_size("the value polynomial", nf + 1, crt.modulus_bits());
        if crt.modulus_bits() > target + 1 {
            return Ok((ZPoly::new(crt.symmetric_values()), crt.primes()));
        }
    }
    Err(Declined(
        "the prime limit was reached (value polynomial)".into(),
    ))
}

/// Sombra's bound (bits) on the coefficients of `Res(u − h, system)`.
pub fn value_bound_bits(sys: &SquareSystem, h: &ZMPoly) -> u64 {
    let e = h.total_degree().unwrap_or(0).max(1);
    let degs = [e, sys.degs[0], sys.degs[1], sys.degs[2]];
    let bounds = [
        max_coeff(h) + BigInt::one(),
        max_coeff(&sys.gens[0]),
        max_coeff(&sys.gens[1]),
        max_coeff(&sys.gens[2]),
    ];
    resultant_bound_bits(&degs, &bounds)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;
    use crate::system::square_resultant::SquareSystem;

    /// The sparse Kronecker images (ℓ = z, Berlekamp–Massey on the sparse
    /// multiplication matrix) equal the dense ones (Krylov and a solve).
    #[test]
    fn sparse_and_dense_kronecker_agree() {
        let gens = [
            "x^2 + 2y^2 + 3z^2 - 6",
            "x^3 - 2x*y + z - 1",
            "y^3 + x*z - 2",
        ]
        .map(|g| parse_poly(g).unwrap().to_primitive_z().0);
        let sys = SquareSystem::new(gens).unwrap();
        for k in 0..3 {
            let fp = Fp::new(prime31(k));
            let (gb, basis) = sys.quotient_mod(&fp).unwrap();
            let sparse = kronecker_sparse(&fp, &gb, &basis, 2).unwrap();
            let quo = ModQuotient::new(&gb).unwrap();
            let dense = kronecker_mod(&fp, &quo, [0, 0, 1]).unwrap();
            assert_eq!(sparse, dense);
        }
    }
}
