//! Elimination: Sylvester matrices, fraction-free (Bareiss) determinants,
//! and resultants by three independent routes — the Sylvester determinant,
//! the subresultant PRS, and (over Z) a multi-modular algorithm.
//!
//! Key idea: everything generic runs over any [`Ring`] with exact division,
//! so the same code computes `Res_x(f, g)` for `f, g ∈ Z[x]`, `Q[x]` and
//! `Z[y, z, …][x]`.  The subresultant PRS (Brown–Collins, as in Cohen,
//! Algorithm 3.3.7) divides each pseudo-remainder by a known factor, which
//! keeps coefficients at the size of the subresultants instead of growing
//! exponentially as naive Euclid over Q would.

mod value_resultant;
pub(crate) use value_resultant::value_resultant;

use crate::number::prime31::{CrtVec, Fp, prime31};
use crate::poly::modp::resultant_mod;
use crate::poly::mpoly::{MPoly, NVARS, QMPoly, ZMPoly};
use crate::poly::{Ring, UPoly, ZPoly};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// The Sylvester matrix of `f` (degree m) and `g` (degree n): `n` shifted
/// rows of the coefficients of `f` followed by `m` rows of `g`, highest
/// powers first.  Its determinant is `Res(f, g)`.
#[cfg(test)]
pub fn sylvester_matrix<R: Ring>(f: &UPoly<R>, g: &UPoly<R>) -> Vec<Vec<R>> {
    let m = f.degree().unwrap_or(0);
    let n = g.degree().unwrap_or(0);
    let size = m + n;
    let mut rows = Vec::with_capacity(size);
    for (p, count, deg) in [(f, n, m), (g, m, n)] {
        for i in 0..count {
            let mut row = vec![R::rzero(); size];
            for k in 0..=deg {
                row[i + k] = p.coeff(deg - k);
            }
            rows.push(row);
        }
    }
    rows
}

/// Determinant by Bareiss' fraction-free elimination (exact divisions by the
/// previous pivot only), with row pivoting.  `O(n³)` ring operations.
#[cfg(test)]
pub fn bareiss_determinant<R: Ring>(mut m: Vec<Vec<R>>) -> R {
    let n = m.len();
    if n == 0 {
        return R::rone();
    }
    let mut sign = false;
    let mut prev = R::rone();
    for k in 0..n - 1 {
        if m[k][k].ris_zero() {
            match (k + 1..n).find(|&i| !m[i][k].ris_zero()) {
                Some(p) => {
                    m.swap(k, p);
                    sign = !sign;
                }
                None => return R::rzero(),
            }
        }
        // a row costs about n − k products of entries of the pivot's size
        let row_work = m[k][k].bit_size().saturating_mul((n - k) as u64);
        for i in k + 1..n {
            crate::budget::check_for(row_work);
            for j in k + 1..n {
                let t = m[i][j].rmul(&m[k][k]).rsub(&m[i][k].rmul(&m[k][j]));
                m[i][j] = t
                    .div_exact(&prev)
                    .expect("Bareiss division is exact in an integral domain");
            }
            m[i][k] = R::rzero();
        }
        prev = m[k][k].clone();
    }
    let d = m[n - 1][n - 1].clone();
    if sign { d.rneg() } else { d }
}

/// `Res(f, g)` as the Bareiss determinant of the Sylvester matrix.
/// The resultant with a zero polynomial is 0.
#[cfg(test)]
pub fn resultant_sylvester<R: Ring>(f: &UPoly<R>, g: &UPoly<R>) -> R {
    if f.is_zero() || g.is_zero() {
        return R::rzero();
    }
    bareiss_determinant(sylvester_matrix(f, g))
}

/// `Res(f, g)` by the subresultant PRS (Cohen, Algorithm 3.3.7, without the
/// content step so that it runs over any ring with exact division).
pub fn resultant_subresultant<R: Ring>(f: &UPoly<R>, g: &UPoly<R>) -> R {
    if f.is_zero() || g.is_zero() {
        return R::rzero();
    }
    let (mut a, mut b) = (f.clone(), g.clone());
    let mut neg = false;
    if a.degree() < b.degree() {
        std::mem::swap(&mut a, &mut b);
        let (da, db) = (a.degree().unwrap_or(0), b.degree().unwrap_or(0));
        if da % 2 == 1 && db % 2 == 1 {
            neg = true;
        }
    }
    let signed = |x: R, neg: bool| if neg { x.rneg() } else { x };
    if b.degree() == Some(0) {
        return signed(b.lc().rpow(a.degree().unwrap_or(0) as u32), neg);
    }
    let mut gg = R::rone();
    let mut h = R::rone();
    loop {
        crate::budget::check_now();
        let da = a.degree().unwrap_or(0);
        let db = b.degree().unwrap_or(0);
        let delta = da - db;
        if da % 2 == 1 && db % 2 == 1 {
            neg = !neg;
        }
        let r = a.pseudo_rem(&b);
        a = b;
        if r.is_zero() {
            return R::rzero();
        }
        let divisor = gg.rmul(&h.rpow(delta as u32));
        b = r
            .div_exact_scalar(&divisor)
            .expect("subresultant division is exact");
        gg = a.lc();
        h = match delta {
            0 => h,
            1 => gg.clone(),
            _ => gg
                .rpow(delta as u32)
                .div_exact(&h.rpow(delta as u32 - 1))
                .expect("subresultant h update is exact"),
        };
        if b.degree() == Some(0) {
            let d_a = a.degree().unwrap_or(0) as u32;
            let lb = b.lc();
            let res = if d_a == 0 {
                R::rone()
            } else {
                lb.rpow(d_a)
                    .div_exact(&h.rpow(d_a - 1))
                    .expect("final subresultant division is exact")
            };
            return signed(res, neg);
        }
    }
}

/// log2 of the Euclidean norm of a vector of integers, rounded up (a safe
/// upper bound), from exact squares.
fn log2_norm2_ceil<'a>(xs: impl IntoIterator<Item = &'a BigInt>) -> u64 {
    let mut s = num_bigint::BigUint::zero();
    for x in xs {
        let m = x.magnitude();
        s += m * m;
    }
    // ceil(log2 sqrt(s)) <= ceil(bits(s)/2)
    s.bits().div_ceil(2)
}

/// `Res(f, g)` over Z by the multi-modular method: Hadamard's bound
/// `|Res| <= ‖f‖₂^n ‖g‖₂^m` fixes the number of 31-bit primes in advance;
/// each modular resultant is computed by Euclid's algorithm and the result
/// is reconstructed by the CRT.  Deterministic and exact.
pub fn resultant_modular(f: &ZPoly, g: &ZPoly) -> BigInt {
    let (Some(m), Some(n)) = (f.degree(), g.degree()) else {
        return BigInt::zero();
    };
    if m == 0 {
        return num_traits::pow(f.lc(), n);
    }
    if n == 0 {
        return num_traits::pow(g.lc(), m);
    }
    let bound = (n as u64) * log2_norm2_ceil(f.coeffs()) + (m as u64) * log2_norm2_ceil(g.coeffs());
    crate::budget::check_size("a resultant", 1, bound);
    let mut crt = CrtVec::new(1);
    let mut i = 0;
    while crt.modulus_bits() <= bound + 1 {
        crate::budget::check();
        let md = Fp::new(prime31(i));
        i += 1;
        let a: Vec<u64> = f.coeffs().iter().map(|c| md.reduce_big(c)).collect();
        let b: Vec<u64> = g.coeffs().iter().map(|c| md.reduce_big(c)).collect();
        if a[m] == 0 || b[n] == 0 {
            continue; // the degree would drop modulo this prime
        }
        crt.push(&md, &[resultant_mod(&md, &a, &b)]);
    }
    crt.symmetric_values().swap_remove(0)
}

/// The resultant of two univariate integer polynomials, by the fastest
/// exact route (multi-modular).
#[cfg(test)]
pub fn resultant_z(f: &ZPoly, g: &ZPoly) -> BigInt {
    resultant_modular(f, g)
}

/// `Res_v(f, g)` of multivariate rational polynomials with respect to the
/// variable `v`; the result does not contain `v`.
///
/// Rational coefficients are cleared first (`Res(c·F, d·G) = cⁿ dᵐ Res(F,
/// G)`); univariate inputs use the multi-modular algorithm, bivariate ones
/// evaluation/interpolation modulo primes, and others the subresultant PRS
/// over Z[other variables].
pub fn resultant_mpoly(f: &QMPoly, g: &QMPoly, v: usize) -> QMPoly {
    if f.is_zero() || g.is_zero() {
        return MPoly::zero();
    }
    let m = f.degree_in(v).unwrap_or(0);
    let n = g.degree_in(v).unwrap_or(0);
    let (fz, cf) = f.to_primitive_z();
    let (gz, cg) = g.to_primitive_z();
    let r = resultant_zmpoly(&fz, &gz, v);
    let k = num_traits::pow(cf, n as usize) * num_traits::pow(cg, m as usize);
    r.to_q().scale(&k)
}

/// `Res_v(f, g)` for integer multivariate polynomials.
pub fn resultant_zmpoly(f: &ZMPoly, g: &ZMPoly, v: usize) -> ZMPoly {
    if f.is_zero() || g.is_zero() {
        return MPoly::zero();
    }
    let mut others: Vec<usize> = f.vars();
    others.extend(g.vars());
    others.sort();
    others.dedup();
    others.retain(|&w| w != v);
    match others.len() {
        0 => {
            let fu = f.to_univariate(v).unwrap_or_else(ZPoly::zero);
            let gu = g.to_univariate(v).unwrap_or_else(ZPoly::zero);
            MPoly::constant(resultant_modular(&fu, &gu))
        }
        1 => resultant_bivariate_modular(f, g, v, others[0]),
        _ => {
            let (terms, bits) = resultant_size(f, g, v, &others);
            crate::budget::check_size("a resultant", terms, bits);
            let fu = f.to_upoly(v);
            let gu = g.to_upoly(v);
            resultant_subresultant(&fu, &gu)
        }
    }
}

/// Upper bounds on the size of `Res_v(f, g)` from the Sylvester matrix
/// (`m = deg_v f`, `n = deg_v g`): its degree in each other variable `w` is
/// at most `n·deg_w f + m·deg_w g` (so at most the product of those plus
/// one terms), its total degree at most `deg f · deg g`, and its coefficients have at most
/// `n·bits(‖f‖₁) + m·bits(‖g‖₁)` bits (Hadamard's bound with row sums).
fn resultant_size(f: &ZMPoly, g: &ZMPoly, v: usize, others: &[usize]) -> (usize, u64) {
    let m = f.degree_in(v).unwrap_or(0) as usize;
    let n = g.degree_in(v).unwrap_or(0) as usize;
    let dense = others.iter().fold(1usize, |acc, &w| {
        let dw =
            n * f.degree_in(w).unwrap_or(0) as usize + m * g.degree_in(w).unwrap_or(0) as usize;
        acc.saturating_mul(dw + 1)
    });
    // total degree at most deg f · deg g: at most C(D + k, k) monomials
    let d = (f.total_degree().unwrap_or(0) as usize)
        .saturating_mul(g.total_degree().unwrap_or(0) as usize);
    let by_degree = (1..=others.len()).fold(1usize, |acc, i| acc.saturating_mul(d + i) / i);
    let terms = dense.min(by_degree);
    let l1 = |p: &ZMPoly| -> u64 {
        let top = p.terms().iter().map(|(_, c)| c.bits()).max().unwrap_or(0);
        top + crate::poly::upoly::log2_ceil(p.len())
    };
    (terms, (n as u64) * l1(f) + (m as u64) * l1(g))
}

/// `Res_v(f, g)` for `f, g ∈ Z[v, w]` by evaluation at `w = 0, 1, 2, …`
/// and Newton interpolation modulo primes, then the CRT.  The bound on the
/// coefficients is `‖f‖₁ⁿ ‖g‖₁ᵐ` (row sums of the Sylvester matrix), and
/// the degree in `w` is at most `n·deg_w f + m·deg_w g`.
pub fn resultant_bivariate_modular(f: &ZMPoly, g: &ZMPoly, v: usize, w: usize) -> ZMPoly {
    let m = f.degree_in(v).unwrap_or(0) as usize;
    let n = g.degree_in(v).unwrap_or(0) as usize;
    if m == 0 && n == 0 {
        return MPoly::constant(BigInt::one());
    }
    let dw = n * f.degree_in(w).unwrap_or(0) as usize + m * g.degree_in(w).unwrap_or(0) as usize;
    let l1 = |p: &ZMPoly| -> u64 {
        let s: BigInt = p.terms().iter().map(|(_, c)| c.abs()).sum();
        s.bits()
    };
    let bound = (n as u64) * l1(f) + (m as u64) * l1(g);
    crate::budget::check_size("a resultant", dw + 1, bound);
    // coefficient grids: fc[i][j] = coefficient of v^i w^j
    let grid = |p: &ZMPoly, dv: usize| -> Vec<Vec<(usize, BigInt)>> {
        let mut rows: Vec<Vec<(usize, BigInt)>> = vec![Vec::new(); dv + 1];
        for (e, c) in p.terms() {
            rows[e[v] as usize].push((e[w] as usize, c.clone()));
        }
        rows
    };
    let fg = grid(f, m);
    let gg = grid(g, n);
    let mut crt = CrtVec::new(dw + 1);
    let mut pi = 0;
    loop {
        if crt.modulus_bits() > bound + 1 {
            break;
        }
        crate::budget::check_now();
        let md = Fp::new(prime31(pi));
        pi += 1;
        let red = |rows: &Vec<Vec<(usize, BigInt)>>| -> Vec<Vec<u64>> {
            rows.iter()
                .map(|r| {
                    let mut c = vec![0u64; r.iter().map(|(j, _)| j + 1).max().unwrap_or(0)];
                    for (j, d) in r {
                        c[*j] = md.reduce_big(d);
                    }
                    c
                })
                .collect()
        };
        let fr = red(&fg);
        let gr = red(&gg);
        if fr[m].iter().all(|&c| c == 0) || gr[n].iter().all(|&c| c == 0) {
            continue;
        }
        let eval = |c: &Vec<u64>, x: u64| -> u64 {
            let mut acc = 0;
            for &ci in c.iter().rev() {
                acc = md.add(md.mul(acc, x), ci);
            }
            acc
        };
        let mut xs = Vec::with_capacity(dw + 1);
        let mut ks = Vec::with_capacity(dw + 1);
        let mut ys = Vec::with_capacity(dw + 1);
        let mut k = 0u64;
        while xs.len() <= dw {
            crate::budget::check();
            let x = md.reduce(k);
            let kk = k;
            k += 1;
            let a: Vec<u64> = fr.iter().map(|c| eval(c, x)).collect();
            let b: Vec<u64> = gr.iter().map(|c| eval(c, x)).collect();
            if a[m] == 0 || b[n] == 0 {
                continue;
            }
            let r = if m == 0 {
                md.pow(a[0], n as u64)
            } else if n == 0 {
                md.pow(b[0], m as u64)
            } else {
                resultant_mod(&md, &a, &b)
            };
            xs.push(x);
            ks.push(kk);
            ys.push(r);
        }
        let mut coeffs = interpolate_mod(&xs, &ks, &ys, &md);
        coeffs.resize(dw + 1, 0);
        crt.push(&md, &coeffs);
    }
    MPoly::from_terms(
        crt.symmetric_values()
            .into_iter()
            .enumerate()
            .map(|(i, c)| {
                let mut e = [0u32; NVARS];
                e[w] = i as u32;
                (e, c)
            }),
    )
}

/// Newton interpolation modulo a prime at the small integer points `ks`
/// (their residues `xs`): the coefficients (ascending, residues)
/// of the polynomial of degree `< xs.len()` through the points.  The
/// inverses of the point differences come from one table of `1/k`.
fn interpolate_mod(xs: &[u64], ks: &[u64], ys: &[u64], m: &Fp) -> Vec<u64> {
    let n = xs.len();
    let kmax = ks.iter().copied().max().unwrap_or(0) as usize;
    // inverses of 1..=kmax by the batch trick: one modular inversion
    let mut pref = vec![1u64; kmax + 1];
    for d in 1..=kmax {
        pref[d] = m.mul(pref[d - 1], m.reduce(d as u64));
    }
    let mut inv_tab = vec![0u64; kmax + 1];
    if kmax > 0 {
        let mut acc = m.inv(pref[kmax]).expect("small integers are invertible");
        for d in (1..=kmax).rev() {
            inv_tab[d] = m.mul(acc, pref[d - 1]);
            acc = m.mul(acc, m.reduce(d as u64));
        }
    }
    // divided differences
    let mut dd = ys.to_vec();
    for j in 1..n {
        crate::budget::check();
        for i in (j..n).rev() {
            let num = m.sub(dd[i], dd[i - 1]);
            let diff = (ks[i] - ks[i - j]) as usize;
            dd[i] = m.mul(num, inv_tab[diff]);
        }
    }
    // expand Newton form from the top
    let mut c = vec![0u64; n];
    for i in (0..n).rev() {
        crate::budget::check();
        // c := c·(x - xs[i]) + dd[i]
        for k in (1..n).rev() {
            c[k] = m.sub(c[k - 1], m.mul(c[k], xs[i]));
        }
        c[0] = m.sub(dd[i], m.mul(c[0], xs[i]));
        // (the loop above computed c·x - c·xs[i] with the old c shifted)
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::mpoly::{X, Y};
    use crate::poly::parse_poly;

    #[test]
    fn three_routes_agree_on_small_cases() {
        let f = ZPoly::from_i64s(&[3, -2, 0, 5, 7]);
        let g = ZPoly::from_i64s(&[1, 0, 3, -1]);
        let a = resultant_sylvester(&f, &g);
        let b = resultant_subresultant(&f, &g);
        let c = resultant_modular(&f, &g);
        assert_eq!(a, b);
        assert_eq!(a, c);
        // antisymmetry: Res(g, f) = (-1)^(4·3) Res(f, g)
        assert_eq!(resultant_modular(&g, &f), c);
        let h = ZPoly::from_i64s(&[1, 1]);
        assert_eq!(
            resultant_subresultant(&(&f * &h), &(&g * &h)),
            BigInt::zero()
        );
        assert_eq!(resultant_modular(&(&f * &h), &(&g * &h)), BigInt::zero());
    }

    #[test]
    fn bivariate_matches_generic() {
        let f = parse_poly("x^3*y - 2*x*y^2 + 3*x - y^3 + 7").unwrap();
        let g = parse_poly("2*x^2*y^2 - x + 5*y - 1").unwrap();
        let (fz, _) = f.to_primitive_z();
        let (gz, _) = g.to_primitive_z();
        let a = resultant_bivariate_modular(&fz, &gz, X, Y);
        let b = resultant_subresultant(&fz.to_upoly(X), &gz.to_upoly(X));
        let c = resultant_sylvester(&fz.to_upoly(X), &gz.to_upoly(X));
        assert_eq!(a, b);
        assert_eq!(a, c);
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_bareiss_determinant() {
        use crate::elim::bareiss_determinant;
        use num_bigint::BigInt;
        let m = vec![
            vec![BigInt::from(2), BigInt::from(1)],
            vec![BigInt::from(7), BigInt::from(4)],
        ];
        assert_eq!(bareiss_determinant(m), BigInt::from(1));
    }

    #[test]
    fn doc_resultant_subresultant() {
        use crate::elim::resultant_subresultant;
        use crate::poly::ZPoly;
        use num_bigint::BigInt;
        // Res(x^2 - 1, x - 2) = f(2) = 3
        let f = ZPoly::from_i64s(&[-1, 0, 1]);
        let g = ZPoly::from_i64s(&[-2, 1]);
        assert_eq!(resultant_subresultant(&f, &g), BigInt::from(3));
    }

    #[test]
    fn doc_resultant_mpoly() {
        use crate::elim::resultant_mpoly;
        use crate::poly::mpoly::X;
        use crate::poly::parse_poly;
        let f = parse_poly("x^2 + y^2 - 1").unwrap();
        let g = parse_poly("x - y").unwrap();
        assert_eq!(
            resultant_mpoly(&f, &g, X).to_string_canonical(),
            "2*y^2 - 1"
        );
    }
}
