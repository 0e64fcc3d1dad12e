//! Linear algebra in the quotient `A = Q[x]/I` of a zero-dimensional ideal:
//! normal forms as coordinate vectors, multiplication matrices, minimal
//! polynomials (Krylov), and the *shape* (rational univariate
//! representation) of a radical ideal with a separating element.
//!
//! Key facts used:
//! * the minimal polynomial of the multiplication by `h` on `A` vanishes
//!   exactly at the values `h(ξ)` over the zeros ξ of `I`; it is the
//!   generator of `I ∩ Q[h]`, found from the Krylov sequence `hⁱ mod I`;
//! * `I` is radical iff the minimal polynomials of the coordinates are
//!   square-free (Seidenberg), and `√I = I + (sqfree(m_x), sqfree(m_y), …)`;
//! * for a radical `I` with `D = dim A` zeros, `t` separates them iff its
//!   minimal polynomial has degree `D`; then `1, t, …, t^(D−1)` is a basis of
//!   `A` and every coordinate is a polynomial in `t` (shape lemma).

use super::groebner::{GPoly, GV, GroebnerBasis, Mono};
use crate::number::Q;
use crate::poly::{QPoly, Ring, ZPoly};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};
use std::collections::HashMap;

/// A zero-dimensional quotient algebra with its monomial basis.
#[derive(Clone, Debug)]
pub struct Quotient {
    /// The Gröbner basis.
    pub gb: GroebnerBasis,
    /// Standard monomials, the basis of `A`.
    pub basis: Vec<Mono>,
    index: HashMap<Mono, usize>,
}

/// A square matrix over Q stored by columns.
pub type QMatrix = Vec<Vec<Q>>;

impl Quotient {
    /// The quotient of a zero-dimensional Gröbner basis (`None` otherwise).
    pub fn new(gb: GroebnerBasis) -> Option<Quotient> {
        let basis = gb.standard_monomials()?;
        // the multiplication matrices by x, y, z have dim² entries each
        let n = basis.len();
        let bits = gb
            .polys
            .iter()
            .flat_map(|g| g.terms.iter().map(|(_, c)| c.bits()))
            .max()
            .unwrap_or(0);
        crate::budget::check_size(
            "the multiplication matrices of the quotient algebra",
            n.saturating_mul(n).saturating_mul(3),
            bits,
        );
        let index = basis.iter().enumerate().map(|(i, m)| (*m, i)).collect();
        Some(Quotient { gb, basis, index })
    }

    /// Dimension of `A` (number of zeros counted with multiplicity).
    pub fn dim(&self) -> usize {
        self.basis.len()
    }

    /// Coordinates of the normal form of `f` in the monomial basis.
    pub fn nf(&self, f: &GPoly) -> Vec<Q> {
        let mut v = vec![Q::zero(); self.dim()];
        if f.is_zero() {
            return v;
        }
        let (r, s) = self.gb.reduce(f);
        for (m, c) in &r.terms {
            let i = self.index[m];
            v[i] = Q::from_integer(c.clone()) / &s;
        }
        v
    }

    /// The multiplication matrix of `f` (columns: `NF(f · b_j)`).
    pub fn mult_matrix(&self, f: &GPoly) -> QMatrix {
        self.basis
            .iter()
            .map(|b| {
                crate::budget::check();
                let terms: Vec<(Mono, BigInt)> = f
                    .terms
                    .iter()
                    .map(|(m, c)| (std::array::from_fn(|i| m[i] + b[i]), c.clone()))
                    .collect();
                let p = GPoly { terms };
                // a product of a monomial with a standard monomial may be standard
                if p.terms.len() == 1
                    && p.terms[0].1.is_one()
                    && let Some(&i) = self.index.get(&p.terms[0].0)
                {
                    let mut v = vec![Q::zero(); self.dim()];
                    v[i] = Q::one();
                    return v;
                }
                self.nf(&p)
            })
            .collect()
    }

    /// The multiplication matrix of the variable in `slot`.
    pub fn var_matrix(&self, slot: usize) -> QMatrix {
        let mut m = [0u16; GV];
        m[slot] = 1;
        self.mult_matrix(&GPoly {
            terms: vec![(m, BigInt::one())],
        })
    }

    /// The coordinate vector of 1.
    pub fn one(&self) -> Vec<Q> {
        let mut v = vec![Q::zero(); self.dim()];
        v[self.index[&[0; GV]]] = Q::one();
        v
    }
}

/// `M v` for a column-stored matrix.
pub fn mat_vec(m: &QMatrix, v: &[Q]) -> Vec<Q> {
    let n = v.len();
    let mut out = vec![Q::zero(); m.first().map(|c| c.len()).unwrap_or(0)];
    for j in 0..n {
        if v[j].is_zero() {
            continue;
        }
        crate::budget::check_for(v[j].bit_size().saturating_mul(out.len() as u64));
        for (o, mij) in out.iter_mut().zip(m[j].iter()) {
            if !mij.is_zero() {
                *o += mij * &v[j];
            }
        }
    }
    out
}

/// `Σ kᵢ Mᵢ` for column-stored matrices of the same size.
pub fn mat_comb(terms: &[(Q, &QMatrix)]) -> QMatrix {
    let n = terms[0].1.len();
    let rows = terms[0].1.first().map(|c| c.len()).unwrap_or(0);
    let mut out = vec![vec![Q::zero(); rows]; n];
    for (k, m) in terms {
        if k.is_zero() {
            continue;
        }
        for j in 0..n {
            crate::budget::check_for(k.bit_size().saturating_mul(rows as u64));
            for i in 0..rows {
                if !m[j][i].is_zero() {
                    out[j][i] += &m[j][i] * k;
                }
            }
        }
    }
    out
}

/// Scales a rational vector to integers: `(v·l, l)` with `l` the lcm of the
/// denominators.
fn to_integers(v: &[Q]) -> (Vec<BigInt>, BigInt) {
    let l = crate::number::denom_lcm(v);
    let z = v.iter().map(|c| c.numer() * (&l / c.denom())).collect();
    (z, l)
}

/// The most primes [`modular_dependency`] tries before the fraction-free
/// elimination takes over.
const MAX_KRYLOV_PRIMES: usize = 3000;

/// The Krylov vectors `v, M v, …, Mⁿ v` modulo p (`M` by columns, n its
/// size), in a vector with room for `cap` columns.
fn krylov_mod(
    fp: &crate::number::prime31::Fp,
    mp: &[Vec<u64>],
    v: Vec<u64>,
    cap: usize,
) -> Vec<Vec<u64>> {
    let n = v.len();
    let mut cols: Vec<Vec<u64>> = Vec::with_capacity(cap);
    cols.push(v);
    // a step is n² products: the clock is read every step when that is
    // much work (amortised over 64 steps, a tangent line found by fuzzing
    // ran 75 ms natively, 1.7 s under the sanitizer, past its deadline)
    let step = (n as u64).saturating_mul(n as u64);
    for _ in 0..n {
        crate::budget::check_for(step);
        let cur = cols.last().expect("non-empty");
        let mut out = vec![0u64; n];
        for (cj, col) in cur.iter().zip(mp) {
            if *cj == 0 {
                continue;
            }
            for (o, &mij) in out.iter_mut().zip(col) {
                *o = fp.add(*o, fp.mul(mij, *cj));
            }
        }
        cols.push(out);
    }
    cols
}

/// The integer Krylov data of [`modular_dependency`]: `M = L·m` by columns
/// (`mi`), the vectors `w_i = Mⁱ·(lv·v)` (`ws`, `i = 0 … n`), and the
/// right-hand sides `rhs_j = r_j / l_j` with `r_j` integral (`rhs`).
struct KrylovData<'a> {
    mi: &'a [Vec<BigInt>],
    l: &'a BigInt,
    lv: &'a BigInt,
    ws: &'a [Vec<BigInt>],
    rhs: &'a [(Vec<BigInt>, BigInt)],
}

/// The first dependency `mᵏv = Σ_(i<k) a_i mⁱv` among the rational Krylov
/// vectors `u_i = mⁱv` and, when `k = n`, the coordinates `β_ji` of each
/// right-hand side (`rhs_j = Σ β_ji u_i`), by Gauss–Jordan elimination
/// modulo word primes on `u_i ≡ w_i / (Lⁱ·lv)`, the CRT and rational
/// reconstruction with a common denominator, tried on a geometric schedule
/// of modulus sizes.  The unscaled `a_i`, `β_ji` are reconstructed, not the
/// coefficients of the integer relation among the `w_i` (which carry a
/// factor `L^(k−i)`: with an 800-bit L and k = 46 they have 38 000 bits
/// where the `a_i` have 400).  Nothing modular is trusted: a reconstruction
/// (`a_i = α_i / δ`, `β_ji = b_ji / δ`) is returned only when the
/// relations hold exactly over Z, `δ·w_k = Σ α_i·L^(k−i)·w_i` and
/// `δ·lv·L^(n−1)·r_j = Σ b_ji·l_j·L^(n−1−i)·w_i`, and `u_0 … u_(k−1)` are
/// independent over Q because they are modulo p.  The cost follows the
/// size of the answer instead of the fraction-free elimination's minors.
/// Returns the `a_i` (k of them) and the `β_j`; `None` when no verified
/// answer came within the prime limit (the caller eliminates
/// fraction-free).
#[allow(clippy::type_complexity)]
fn modular_dependency(kd: &KrylovData) -> Option<(Vec<Q>, Option<Vec<Vec<Q>>>)> {
    use crate::number::prime31::{CrtVec, Fp, prime31};
    let ws = kd.ws;
    let n = ws.len() - 1;
    let mut best: Option<usize> = None;
    let mut crt = CrtVec::new(0);
    let mut next_bits = 62u64;
    // L^0 … L^n, for the exact checks
    let lpow: Vec<BigInt> = std::iter::successors(Some(BigInt::one()), |x| Some(x * kd.l))
        .take(n + 1)
        .collect();
    for j in 0..MAX_KRYLOV_PRIMES {
        crate::budget::check_now();
        let fp = Fp::new(prime31(j));
        // the scales L, lv and l_j must be units modulo p
        let Some(linv) = fp.inv(fp.reduce_big(kd.l)) else {
            continue;
        };
        let Some(lvinv) = fp.inv(fp.reduce_big(kd.lv)) else {
            continue;
        };
        let Some(ljinv) = kd
            .rhs
            .iter()
            .map(|(_, lj)| fp.inv(fp.reduce_big(lj)))
            .collect::<Option<Vec<u64>>>()
        else {
            continue;
        };
        let mp: Vec<Vec<u64>> = kd
            .mi
            .iter()
            .map(|col| col.iter().map(|c| fp.reduce_big(c)).collect())
            .collect();
        // the Krylov vectors modulo p, by columns of the row-major matrix
        let v0 = ws[0].iter().map(|c| fp.reduce_big(c)).collect();
        let mut cols = krylov_mod(&fp, &mp, v0, n + 1 + kd.rhs.len());
        // u_i = w_i / (Lⁱ·lv), rhs_j = r_j / l_j
        let mut scale = lvinv;
        for c in cols.iter_mut() {
            for x in c.iter_mut() {
                *x = fp.mul(*x, scale);
            }
            scale = fp.mul(scale, linv);
        }
        for ((r, _), &inv) in kd.rhs.iter().zip(&ljinv) {
            cols.push(r.iter().map(|c| fp.mul(fp.reduce_big(c), inv)).collect());
        }
        let mut a: Vec<Vec<u64>> = (0..n)
            .map(|i| cols.iter().map(|c| c[i]).collect())
            .collect();
        let (pivots, k) = gauss_jordan_mod(&fp, &mut a, n + 1);
        match best {
            Some(b) if k < b => continue,
            Some(b) if k == b => {}
            _ => {
                best = Some(k);
                let len = k + if k == n { n * kd.rhs.len() } else { 0 };
                crt = CrtVec::new(len);
                next_bits = 62;
            }
        }
        let mut res: Vec<u64> = (0..k).map(|i| a[pivots[i]][k]).collect();
        if k == n {
            for jr in 0..kd.rhs.len() {
                res.extend((0..n).map(|i| a[pivots[i]][n + 1 + jr]));
            }
        }
        crt.push(&fp, &res);
        if crt.modulus_bits() < next_bits {
            continue;
        }
        next_bits = crt.modulus_bits() + (crt.modulus_bits() / 4).max(62);
        crt.flush();
        let Some((nums, den)) =
            crate::number::reconstruct::reconstruct_common(crt.values(), crt.modulus())
        else {
            continue;
        };
        // exact check over Z: Σ_i coef_i·w_i = target, coef_i = c_i·scale_i
        let holds = |coef: &[BigInt], scales: &dyn Fn(usize) -> BigInt, target: &[BigInt]| {
            let coef: Vec<BigInt> = coef
                .iter()
                .enumerate()
                .map(|(i, c)| c * scales(i))
                .collect();
            (0..n).all(|r| {
                let mut acc = -&target[r];
                for (c, w) in coef.iter().zip(ws) {
                    crate::budget::check_for(c.bits() + w[r].bits());
                    if !c.is_zero() && !w[r].is_zero() {
                        acc += c * &w[r];
                    }
                }
                acc.is_zero()
            })
        };
        // δ·w_k = Σ α_i·L^(k−i)·w_i
        let wk: Vec<BigInt> = ws[k].iter().map(|x| x * &den).collect();
        if !holds(&nums[..k], &|i| lpow[k - i].clone(), &wk) {
            continue;
        }
        let to_q = |xs: &[BigInt]| -> Vec<Q> {
            xs.iter().map(|c| Q::new(c.clone(), den.clone())).collect()
        };
        let b = if k == n {
            let mut out = Vec::with_capacity(kd.rhs.len());
            for (jr, (r, lj)) in kd.rhs.iter().enumerate() {
                let coef = &nums[k + jr * n..k + (jr + 1) * n];
                // δ·lv·L^(n−1)·r_j = Σ b_ji·l_j·L^(n−1−i)·w_i
                let f = &den * kd.lv * &lpow[n - 1];
                let target: Vec<BigInt> = r.iter().map(|x| x * &f).collect();
                if !holds(coef, &|i| lj * &lpow[n - 1 - i], &target) {
                    return None;
                }
                out.push(to_q(coef));
            }
            Some(out)
        } else {
            None
        };
        return Some((to_q(&nums[..k]), b));
    }
    None
}

/// Gauss–Jordan elimination modulo p on a row-major matrix, pivots made 1,
/// on the columns `0, 1, …` in order up to `stop`, stopping at the first
/// column with no pivot: the pivot rows and that column (`stop` when every
/// column has one).  Later columns then hold the coordinates of each
/// column in the pivot columns.
fn gauss_jordan_mod(
    fp: &crate::number::prime31::Fp,
    a: &mut [Vec<u64>],
    stop: usize,
) -> (Vec<usize>, usize) {
    let rows = a.len();
    let mut used = vec![false; rows];
    let mut pivots = Vec::new();
    // a column is up to rows × width products (see `krylov_mod`)
    let step = (rows as u64).saturating_mul(a.first().map_or(0, |r| r.len()) as u64);
    for c in 0..stop {
        crate::budget::check_for(step);
        let Some(r) = (0..rows).find(|&i| !used[i] && a[i][c] != 0) else {
            return (pivots, c);
        };
        used[r] = true;
        pivots.push(r);
        let inv = fp.inv(a[r][c]).expect("non-zero pivot");
        for x in a[r][c..].iter_mut() {
            *x = fp.mul(*x, inv);
        }
        let prow = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            let f = row[c];
            if i == r || f == 0 {
                continue;
            }
            let t = fp.neg(f);
            for (x, &y) in row[c..].iter_mut().zip(&prow[c..]) {
                *x = fp.add(*x, fp.mul(t, y));
            }
        }
    }
    (pivots, stop)
}

/// Fraction-free Gauss–Jordan elimination (Bareiss' rule applied to every
/// row) on a row-major integer matrix, pivoting on the columns
/// `0, 1, …` in order and stopping at the first column with no pivot.
///
/// After the steps on the pivot columns `c_0 < … < c_(k-1)` (pivot rows
/// `r_i`), every entry is a `k × k` minor of the input, so each division by
/// the previous pivot is exact, and each later column `j` satisfies
/// `column_j = Σ (A[r_i][j] / D) · column_(c_i)` restricted to the pivot
/// rows, with `D` the last pivot (the determinant of the pivot block).
/// Returns the pivot rows, `D`, and the index of the first column without
/// a pivot (`None` when every column in `0..stop` has one).
fn gauss_jordan_ff(
    a: &mut [Vec<BigInt>],
    stop: usize,
) -> Result<(Vec<usize>, BigInt, Option<usize>), crate::error::Error> {
    let rows = a.len();
    let width = a.first().map(|r| r.len()).unwrap_or(0);
    let mut used = vec![false; rows];
    let mut pivots = Vec::new();
    let mut prev = BigInt::one();
    for c in 0..stop {
        let Some(r) = (0..rows).find(|&i| !used[i] && !a[i][c].is_zero()) else {
            return Ok((pivots, prev, Some(c)));
        };
        used[r] = true;
        pivots.push(r);
        let prow = a[r].clone();
        let p = &prow[c];
        // a row costs about (width − c) products of numbers of this size:
        // with large numbers the clock is read for each row, with huge
        // ones for each entry
        let (row_work, huge) = (
            p.bits().saturating_mul((width - c) as u64),
            p.bits() > crate::budget::LARGE_BITS,
        );
        for (i, row) in a.iter_mut().enumerate() {
            if i == r {
                continue;
            }
            crate::budget::check_for(row_work);
            let f = std::mem::take(&mut row[c]);
            for j in c + 1..width {
                if huge {
                    crate::budget::check_now();
                }
                let mut t = p * &row[j];
                if !f.is_zero() && !prow[j].is_zero() {
                    t -= &f * &prow[j];
                }
                if !prev.is_one() && !t.is_zero() {
                    let (q, rem) = t.div_rem(&prev);
                    if !rem.is_zero() {
                        return Err(crate::error::Error::internal(
                            "fraction-free elimination: inexact division",
                        ));
                    }
                    t = q;
                }
                row[j] = t;
            }
        }
        prev = p.clone();
    }
    Ok((pivots, prev, None))
}

/// A minimal polynomial and, when the Krylov basis is complete, the
/// coordinates of the right-hand sides in it (see [`krylov_shape`]).
pub type KrylovShape = (QPoly, Option<Vec<Vec<Q>>>);

/// Whether `v, m v, …, m^(n−1) v` can span `Qⁿ` (`n = v.len()`), judged
/// modulo up to two word primes before any exact Krylov vector is built.
/// Their rank modulo p is at most their rank over Q, so a full rank modulo
/// one prime proves the span; `false` means both primes found a dependency
/// earlier (over Q too, unless both primes are unlucky).  Callers only use
/// `false` to skip a candidate they may do without (a form that would not
/// make A cyclic, or would not separate): a wrong `false` costs a
/// candidate, never a wrong answer.
pub fn krylov_full_likely(m: &QMatrix, v: &[Q]) -> bool {
    use crate::number::prime31::{Fp, prime31};
    let n = v.len();
    let mut tried = 0;
    for j in 0..8 {
        crate::budget::check_now();
        let fp = Fp::new(prime31(j));
        let red = |c: &Q| -> Option<u64> {
            let d = fp.inv(fp.reduce_big(c.denom()))?;
            Some(fp.mul(fp.reduce_big(c.numer()), d))
        };
        let Some(mp) = m
            .iter()
            .map(|col| col.iter().map(red).collect::<Option<Vec<u64>>>())
            .collect::<Option<Vec<Vec<u64>>>>()
        else {
            continue;
        };
        let Some(v0) = v.iter().map(red).collect::<Option<Vec<u64>>>() else {
            continue;
        };
        let cols = krylov_mod(&fp, &mp, v0, n + 1);
        let mut a: Vec<Vec<u64>> = (0..n)
            .map(|i| cols.iter().map(|c| c[i]).collect())
            .collect();
        if gauss_jordan_mod(&fp, &mut a, n + 1).1 == n {
            return true;
        }
        tried += 1;
        if tried == 2 {
            return false;
        }
    }
    // no usable prime: let the exact computation judge
    true
}

/// The integral Krylov data of `m` (by columns) and `v`: `L` (the common
/// denominator of m), `M = L·m`, `v = v₀/lv` and `w_i = Mⁱ v₀` for
/// `i = 0 … n`, after a size check sized for `extra` more columns.
struct IntKrylov {
    l: BigInt,
    mi: Vec<Vec<BigInt>>,
    lv: BigInt,
    ws: Vec<Vec<BigInt>>,
}

fn int_krylov(m: &QMatrix, v: &[Q], extra: usize) -> IntKrylov {
    let n = v.len();
    let l = crate::number::denom_lcm(m.iter().flatten());
    // the Krylov vectors w_0 … w_n have entries of up to about
    // n·bits(M) + bits(V) bits (M = L·m integral); the elimination works on
    // minors of them.  Estimated before anything is built.
    let lbits = l.bits();
    let mbits = m
        .iter()
        .flatten()
        .filter(|c| !c.is_zero())
        .map(|c| (c.numer().bits() + lbits + 1).saturating_sub(c.denom().bits()))
        .max()
        .unwrap_or(0);
    let vbits = v
        .iter()
        .map(|c| c.numer().bits() + c.denom().bits())
        .max()
        .unwrap_or(0);
    crate::budget::check_size(
        "the Krylov matrix of a minimal polynomial",
        n.saturating_mul(n + 1 + extra),
        (n as u64).saturating_mul(mbits + crate::poly::upoly::log2_ceil(n)) + vbits,
    );
    let mi: Vec<Vec<BigInt>> = m
        .iter()
        .map(|col| col.iter().map(|c| c.numer() * (&l / c.denom())).collect())
        .collect();
    let (v0, lv) = to_integers(v);
    // Krylov vectors w_0 … w_n (integral)
    let mut ws: Vec<Vec<BigInt>> = Vec::with_capacity(n + 1);
    ws.push(v0);
    for _ in 0..n {
        let cur = ws.last().expect("non-empty");
        let mut out = vec![BigInt::zero(); n];
        for (j, cj) in cur.iter().enumerate() {
            if cj.is_zero() {
                continue;
            }
            crate::budget::check_for(cj.bits().saturating_mul(n as u64));
            for (o, mij) in out.iter_mut().zip(mi[j].iter()) {
                if !mij.is_zero() {
                    *o += mij * cj;
                }
            }
        }
        ws.push(out);
    }
    IntKrylov { l, mi, lv, ws }
}

/// The square-free part `sq` of a minimal polynomial and `sq(m)·v`.
pub type SquarefreeImage = (ZPoly, Vec<Q>);

/// The minimal polynomial `μ` of `m` relative to `v` (as
/// [`krylov_shape`]) and, when `μ` is not square-free, its square-free
/// part `sq` (primitive, integral) with `sq(m)·v` exactly.  With
/// `m` the multiplication by a coordinate on `Q[x]/I` and `v = 1`, that
/// vector is the normal form of `sq(x)`, an element of `√I` of the degree
/// of the standard monomials.  It is read off the integral Krylov vectors
/// the minimal polynomial was found from: `Σ sq_i·w_i·L^(s−i) / (L^s·lv)`.
pub fn minpoly_and_squarefree_image(
    m: &QMatrix,
    v: &[Q],
) -> Result<(QPoly, Option<SquarefreeImage>), crate::error::Error> {
    let ik = int_krylov(m, v, 0);
    let (mp, _) = krylov_from(&ik, &[], KrylovRoute::Modular)?;
    let (mz, _) = ZPoly::from_q(&mp);
    let sq = mz.squarefree_part();
    if sq.degree() == mz.degree() {
        return Ok((mp, None));
    }
    let s = sq.degree().unwrap_or(0);
    let lpow: Vec<BigInt> = std::iter::successors(Some(BigInt::one()), |x| Some(x * &ik.l))
        .take(s + 1)
        .collect();
    let den = &lpow[s] * &ik.lv;
    let image = (0..v.len())
        .map(|r| {
            let mut acc = BigInt::zero();
            for (i, c) in sq.coeffs().iter().enumerate() {
                crate::budget::check_for(ik.ws[i][r].bits());
                if !c.is_zero() && !ik.ws[i][r].is_zero() {
                    acc += c * &ik.ws[i][r] * &lpow[s - i];
                }
            }
            Q::new(acc, den.clone())
        })
        .collect();
    Ok((mp, Some((sq, image))))
}

/// How [`krylov_shape_with`] eliminates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum KrylovRoute {
    /// Modulo primes (verified over Z), else fraction-free.
    Modular,
    /// Fraction-free only.
    FractionFree,
    /// Modulo primes only (an error when no verified answer comes), for
    /// the tests.
    #[cfg(test)]
    ModularOnly,
}

/// The minimal polynomial of `m` relative to `v` (the monic generator of
/// the polynomials `p` with `p(m) v = 0`) and, when its degree is the full
/// dimension `n` (so `v, m v, …, m^(n−1) v` is a basis), the coordinates of
/// each `rhs` vector in that basis (`rhs_j = Σ_i sol_j[i] · mⁱ v`).
///
/// Everything runs over the integers: with `m = M / L` (`M` integral) the
/// Krylov vectors `Mᵏ V` are integral, one fraction-free Gauss–Jordan pass
/// finds the first dependency and solves the right-hand sides, and the
/// powers of `L` are put back at the end.
pub fn krylov_shape(
    m: &QMatrix,
    v: &[Q],
    rhs: &[Vec<Q>],
) -> Result<KrylovShape, crate::error::Error> {
    krylov_shape_with(m, v, rhs, KrylovRoute::Modular)
}

/// [`krylov_shape`], with the modular elimination first (`modular`) or
/// fraction-free only.
fn krylov_shape_with(
    m: &QMatrix,
    v: &[Q],
    rhs: &[Vec<Q>],
    route: KrylovRoute,
) -> Result<KrylovShape, crate::error::Error> {
    krylov_from(&int_krylov(m, v, rhs.len()), rhs, route)
}

/// [`krylov_shape_with`] on the integral Krylov data.
fn krylov_from(
    ik: &IntKrylov,
    rhs: &[Vec<Q>],
    route: KrylovRoute,
) -> Result<KrylovShape, crate::error::Error> {
    let IntKrylov { l, mi, lv, ws } = ik;
    let n = ws.len() - 1;
    let scaled: Vec<(Vec<BigInt>, BigInt)> = rhs.iter().map(|r| to_integers(r)).collect();
    let kd = KrylovData {
        mi,
        l,
        lv,
        ws,
        rhs: &scaled,
    };
    if route != KrylovRoute::FractionFree
        && let Some((a, b)) = modular_dependency(&kd)
    {
        // mᵏ v = Σ a_i mⁱ v: the minimal polynomial T^k − Σ a_i T^i
        let mut low: Vec<Q> = a.into_iter().map(|x| -x).collect();
        low.push(Q::one());
        return Ok((QPoly::new(low), b));
    }
    #[cfg(test)]
    if route == KrylovRoute::ModularOnly {
        return Err(crate::error::Error::internal("no verified modular answer"));
    }
    // the fraction-free fallback works on the row-major matrix
    // [w_0 … w_n | rhs], built only now
    let mut a: Vec<Vec<BigInt>> = (0..n)
        .map(|i| {
            ws.iter()
                .map(|w| w[i].clone())
                .chain(scaled.iter().map(|(r, _)| r[i].clone()))
                .collect()
        })
        .collect();
    let (pivots, d, dep) = gauss_jordan_ff(&mut a, n + 1)?;
    let k = dep.ok_or_else(|| {
        crate::error::Error::internal("n + 1 Krylov vectors in dimension n are independent")
    })?;
    // w_k = Σ c_i w_i with c_i = A[r_i][k] / D;  mᵏ v = Σ c_i L^(i−k) mⁱ v
    let lq = Q::from_integer(l.clone());
    let mut coeffs = Vec::with_capacity(k + 1);
    let mut lpow = Q::one(); // L^(i−k), built from i = k − 1 down
    let mut low: Vec<Q> = Vec::with_capacity(k);
    for i in (0..k).rev() {
        lpow = &lpow / &lq;
        low.push(-Q::new(a[pivots[i]][k].clone(), d.clone()) * &lpow);
    }
    low.reverse();
    coeffs.extend(low);
    coeffs.push(Q::one());
    let minpoly = QPoly::new(coeffs);
    if k < n {
        return Ok((minpoly, None));
    }
    // rhs_j · l_j = Σ b_i w_i with b_i = A[r_i][n+1+j] / D;  w_i = Lⁱ mⁱ (lv·v)
    let sol = scaled
        .iter()
        .enumerate()
        .map(|(j, (_, lj))| {
            let dl = &d * lj;
            let mut lp = lv.clone();
            (0..n)
                .map(|i| {
                    let c = Q::new(&a[pivots[i]][n + 1 + j] * &lp, dl.clone());
                    lp *= l;
                    c
                })
                .collect()
        })
        .collect();
    Ok((minpoly, Some(sol)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{q, qi};
    use crate::poly::parse_poly;
    use crate::system::groebner::{MonoOrder, groebner};

    #[test]
    fn minpoly_of_coordinates() {
        let ord = MonoOrder::GrevLex;
        let gp = |s: &str| GPoly::from_mpoly(&parse_poly(s).unwrap(), &[0, 1, 2, 3], ord);
        let g = groebner(vec![gp("x^2+y^2-5"), gp("x*y-2")], 2, ord);
        let q = Quotient::new(g).unwrap();
        assert_eq!(q.dim(), 4); // (±1, ±2), (±2, ±1)
        let mx = q.var_matrix(0);
        let (mp, _) = krylov_shape(&mx, &q.one(), &[]).unwrap();
        // x ∈ {1, 2, -1, -2}: (x²-1)(x²-4) = x⁴ - 5x² + 4
        assert_eq!(mp, QPoly::new(vec![qi(4), qi(0), qi(-5), qi(0), qi(1)]));
    }

    /// `Σ cᵢ mⁱ v` for a column-stored rational matrix.
    fn krylov_combination(m: &QMatrix, v: &[Q], c: &[Q]) -> Vec<Q> {
        let mut acc = vec![Q::zero(); v.len()];
        let mut cur = v.to_vec();
        for ci in c {
            for (a, x) in acc.iter_mut().zip(cur.iter()) {
                *a += ci * x;
            }
            cur = mat_vec(m, &cur);
        }
        acc
    }

    #[test]
    fn krylov_shape_solves_rational_systems() {
        // a deterministic rational 5×5 matrix, a start vector with
        // denominators, and two right-hand sides
        let mut seed = 12345u64;
        let mut next = |lo: i64, hi: i64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            lo + ((seed >> 33) % ((hi - lo + 1) as u64)) as i64
        };
        let n = 5;
        let m: QMatrix = (0..n)
            .map(|_| {
                (0..n)
                    .map(|_| Q::new(next(-9, 9).into(), next(1, 4).into()))
                    .collect()
            })
            .collect();
        let v: Vec<Q> = (0..n)
            .map(|_| Q::new(next(-5, 5).into(), next(1, 3).into()))
            .collect();
        let rhs: Vec<Vec<Q>> = (0..2)
            .map(|_| {
                (0..n)
                    .map(|_| Q::new(next(-7, 7).into(), next(1, 6).into()))
                    .collect()
            })
            .collect();
        let (mp, sol) = krylov_shape(&m, &v, &rhs).unwrap();
        // mp(m) v = 0
        assert!(
            krylov_combination(&m, &v, mp.coeffs())
                .iter()
                .all(|x| x.is_zero())
        );
        let sol = sol.expect("a random start vector is cyclic");
        assert_eq!(mp.degree(), Some(n));
        for (r, c) in rhs.iter().zip(sol.iter()) {
            assert_eq!(&krylov_combination(&m, &v, c), r);
        }
    }

    /// A matrix conjugated by a diagonal of ~100-bit integers has the same
    /// small minimal polynomial but a ~600-bit common denominator L: the
    /// modular elimination reconstructs the unscaled relation (not one with
    /// factors L^(k−i)), verifies it over Z, and agrees with the
    /// fraction-free one and with the unconjugated matrix.
    #[test]
    fn a_big_common_denominator_leaves_the_minimal_polynomial_small() {
        let n = 6usize;
        let base: QMatrix = (0..n)
            .map(|j| {
                (0..n)
                    .map(|i| q(((3 * i + 5 * j) % 7) as i64 - 3, 1))
                    .collect()
            })
            .collect();
        let d: Vec<BigInt> = (0..n)
            .map(|i| (BigInt::one() << (90 + 3 * i)) + BigInt::from(2 * i + 1))
            .collect();
        // (D m D⁻¹)_ij = d_i m_ij / d_j; column j of the matrix is `m[j]`
        let conj: QMatrix = (0..n)
            .map(|j| {
                (0..n)
                    .map(|i| &base[j][i] * Q::new(d[i].clone(), d[j].clone()))
                    .collect()
            })
            .collect();
        let v: Vec<Q> = (0..n).map(|i| q(i as i64 + 1, 1)).collect();
        let dv: Vec<Q> = (0..n)
            .map(|i| &v[i] * Q::from_integer(d[i].clone()))
            .collect();
        let rhs: Vec<Vec<Q>> = vec![dv.iter().map(|x| x * q(3, 7)).collect()];
        let plain = krylov_shape_with(&base, &v, &[], KrylovRoute::FractionFree).unwrap();
        let a = krylov_shape_with(&conj, &dv, &rhs, KrylovRoute::ModularOnly).unwrap();
        let b = krylov_shape_with(&conj, &dv, &rhs, KrylovRoute::FractionFree).unwrap();
        assert_eq!(a, b);
        assert_eq!(a.0, plain.0);
        assert!(crate::number::denom_lcm(conj.iter().flatten()).bits() > 500);
        if a.0.degree() == Some(n) {
            // rhs = (3/7)·v: coordinates (3/7, 0, …, 0)
            let sol = a.1.expect("cyclic");
            assert_eq!(sol[0][0], q(3, 7));
            assert!(sol[0][1..].iter().all(|c| c.is_zero()));
        }
    }

    /// `krylov_full_likely`: true for a companion matrix (cyclic), false
    /// when the Krylov space of v is smaller (a repeated eigenvalue).
    #[test]
    fn the_modular_cyclicity_check() {
        // companion matrix of T³ − 2T² + 5T − 7, v = e₀: cyclic
        let comp: QMatrix = vec![
            vec![q(0, 1), q(1, 1), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(1, 1)],
            vec![q(7, 1), q(-5, 1), q(2, 1)],
        ];
        let e0 = vec![q(1, 1), q(0, 1), q(0, 1)];
        assert!(krylov_full_likely(&comp, &e0));
        // diag(1/3, 1/3, 2): minimal polynomial of degree 2
        let diag: QMatrix = vec![
            vec![q(1, 3), q(0, 1), q(0, 1)],
            vec![q(0, 1), q(1, 3), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(2, 1)],
        ];
        let ones = vec![q(1, 1), q(1, 1), q(1, 1)];
        assert!(!krylov_full_likely(&diag, &ones));
        assert!(
            krylov_shape_with(&diag, &ones, &[], KrylovRoute::ModularOnly)
                .unwrap()
                .1
                .is_none()
        );
    }

    /// The modular elimination (verified over Z) and the fraction-free one
    /// give the same minimal polynomials and coordinates: pseudo-random
    /// rational matrices with full and early dependencies (a repeated
    /// block), and right-hand sides.
    #[test]
    fn modular_and_fraction_free_krylov_agree() {
        let mut seed = 12345u64;
        let mut next = |m: i64| -> i64 {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 33) % (2 * m as u64 + 1)) as i64 - m
        };
        for n in [2usize, 4, 6, 8, 12] {
            for early in [false, true] {
                let mut m: QMatrix = (0..n)
                    .map(|_| {
                        (0..n)
                            .map(|_| q(next(40), 1 + next(6).unsigned_abs() as i64))
                            .collect()
                    })
                    .collect();
                if early {
                    // m = diag(B, B): the minimal polynomial has degree ≤ n/2
                    for (j, col) in m.iter_mut().enumerate() {
                        for (i, c) in col.iter_mut().enumerate() {
                            if (i < n / 2) != (j < n / 2) {
                                *c = Q::zero();
                            }
                        }
                    }
                    for j in 0..n / 2 {
                        for i in 0..n / 2 {
                            m[j + n / 2][i + n / 2] = m[j][i].clone();
                        }
                    }
                }
                let v: Vec<Q> = (0..n)
                    .map(|_| q(next(9), 1 + next(3).unsigned_abs() as i64))
                    .collect();
                let rhs: Vec<Vec<Q>> = (0..2)
                    .map(|_| {
                        (0..n)
                            .map(|_| q(next(99), 1 + next(5).unsigned_abs() as i64))
                            .collect()
                    })
                    .collect();
                let a = krylov_shape_with(&m, &v, &rhs, KrylovRoute::ModularOnly).unwrap();
                let b = krylov_shape_with(&m, &v, &rhs, KrylovRoute::FractionFree).unwrap();
                assert_eq!(a, b, "n = {n}, early = {early}");
                assert_eq!(a.1.is_none(), early || a.0.degree() < Some(n));
            }
        }
    }

    #[test]
    fn krylov_shape_finds_early_dependencies() {
        // diag(2, 2, 3): the minimal polynomial relative to (1, 1, 1) is
        // (T − 2)(T − 3), of degree 2 < 3, so no shape
        let d = |i: usize, x: i64| -> Vec<Q> {
            let mut c = vec![Q::zero(); 3];
            c[i] = qi(x);
            c
        };
        let m: QMatrix = vec![d(0, 2), d(1, 2), d(2, 3)];
        let (mp, sol) = krylov_shape(&m, &[qi(1), qi(1), qi(1)], &[vec![qi(1); 3]]).unwrap();
        assert_eq!(mp, QPoly::new(vec![qi(6), qi(-5), qi(1)]));
        assert!(sol.is_none());
    }
}
