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
use crate::poly::QPoly;
use num_bigint::BigInt;
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
            for i in 0..rows {
                if !m[j][i].is_zero() {
                    out[j][i] += &m[j][i] * k;
                }
            }
        }
    }
    out
}

/// Incremental row-echelon form used to detect the first linear dependency
/// in a sequence of vectors and to express it.
struct Echelon {
    /// Reduced vectors with their pivot index and the combination of the
    /// original vectors they equal.
    rows: Vec<(usize, Vec<Q>, Vec<Q>)>,
}

impl Echelon {
    fn new() -> Echelon {
        Echelon { rows: Vec::new() }
    }

    /// Reduces `v` (the k-th input); returns `Some(coeffs)` with
    /// `v = Σ coeffs[i] · input_i` when dependent, else records it.
    fn push(&mut self, v: Vec<Q>, k: usize) -> Option<Vec<Q>> {
        let mut w = v;
        // comb: w = input_k − Σ c_i input_i
        let mut comb = vec![Q::zero(); k + 1];
        comb[k] = Q::one();
        for (p, row, rc) in &self.rows {
            if w[*p].is_zero() {
                continue;
            }
            let f = w[*p].clone() / &row[*p];
            for (wi, ri) in w.iter_mut().zip(row.iter()) {
                if !ri.is_zero() {
                    *wi -= &f * ri;
                }
            }
            for (ci, rci) in comb.iter_mut().zip(rc.iter()) {
                if !rci.is_zero() {
                    *ci -= &f * rci;
                }
            }
        }
        match w.iter().position(|x| !x.is_zero()) {
            Some(p) => {
                self.rows.push((p, w, comb));
                None
            }
            None => {
                // 0 = input_k + Σ comb_i input_i  (comb[k] = 1)
                Some(comb[..k].iter().map(|c| -c).collect())
            }
        }
    }
}

/// The minimal polynomial of `m` relative to `v` (the monic generator of
/// the polynomials `p` with `p(m) v = 0`), and the Krylov vectors
/// `v, m v, …, m^(d−1) v`.
pub fn krylov_minpoly(m: &QMatrix, v: &[Q]) -> (QPoly, Vec<Vec<Q>>) {
    let mut ech = Echelon::new();
    let mut vecs: Vec<Vec<Q>> = Vec::new();
    let mut cur = v.to_vec();
    for k in 0..=v.len() {
        if let Some(coeffs) = ech.push(cur.clone(), k) {
            // m^k v = Σ coeffs_i m^i v  →  T^k − Σ coeffs_i T^i
            let mut c: Vec<Q> = coeffs.iter().map(|x| -x).collect();
            c.push(Q::one());
            return (QPoly::new(c), vecs);
        }
        vecs.push(cur.clone());
        cur = mat_vec(m, &cur);
    }
    unreachable!("a Krylov sequence in dimension n is dependent after n steps")
}

/// Solves `[cols] c = rhs` for an invertible square system given by
/// columns; `None` if singular.
pub fn solve_columns(cols: &[Vec<Q>], rhs: &[Vec<Q>]) -> Option<Vec<Vec<Q>>> {
    let n = cols.len();
    // augmented row-major matrix
    let mut a: Vec<Vec<Q>> = (0..n)
        .map(|i| {
            let mut row: Vec<Q> = cols.iter().map(|c| c[i].clone()).collect();
            row.extend(rhs.iter().map(|r| r[i].clone()));
            row
        })
        .collect();
    let w = n + rhs.len();
    for col in 0..n {
        let p = (col..n).find(|&i| !a[i][col].is_zero())?;
        a.swap(col, p);
        let inv = Q::one() / &a[col][col];
        for j in col..w {
            if !a[col][j].is_zero() {
                a[col][j] = &a[col][j] * &inv;
            }
        }
        let prow = a[col].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != col && !row[col].is_zero() {
                let f = row[col].clone();
                for j in col..w {
                    if !prow[j].is_zero() {
                        row[j] -= &f * &prow[j];
                    }
                }
            }
        }
    }
    Some(
        (0..rhs.len())
            .map(|k| (0..n).map(|i| a[i][n + k].clone()).collect())
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::elim::groebner::{MonoOrder, groebner};
    use crate::number::qi;
    use crate::poly::parse_poly;

    #[test]
    fn minpoly_of_coordinates() {
        let ord = MonoOrder::GrevLex;
        let gp = |s: &str| GPoly::from_mpoly(&parse_poly(s).unwrap(), &[0, 1, 2, 3], ord);
        let g = groebner(vec![gp("x^2+y^2-5"), gp("x*y-2")], 2, ord);
        let q = Quotient::new(g).unwrap();
        assert_eq!(q.dim(), 4); // (±1, ±2), (±2, ±1)
        let mx = q.var_matrix(0);
        let (mp, _) = krylov_minpoly(&mx, &q.one());
        // x ∈ {1, 2, -1, -2}: (x²-1)(x²-4) = x⁴ - 5x² + 4
        assert_eq!(mp, QPoly::new(vec![qi(4), qi(0), qi(-5), qi(0), qi(1)]));
    }
}
