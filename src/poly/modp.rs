//! Polynomials over a word prime field `F_p` (dense, ascending `u64`
//! coefficients): remainders, gcds and resultants by Euclid's algorithm
//! with lazy reduction, Berlekamp–Massey, and the algebra `F_p[T]/(f)`
//! (products, inverses, characteristic polynomials by Krylov sequences).
//!
//! Key idea: the image modulo p of an integer computation is computed here
//! in word arithmetic (rows kept below p² and reduced once per pass, the
//! vector kernels of [`crate::number::modkernel`]); the callers lift the
//! images by the Chinese remainder theorem with a size bound, so nothing
//! here needs to be exact over Q.

use crate::number::modkernel::mulmod;
use crate::number::prime31::Fp;
use crate::poly::ZPoly;

/// The minimal polynomial (ascending, monic) of a linearly recurrent
/// sequence over F_p by Berlekamp–Massey: the monic `m` of least degree L
/// with `Σ_i m_i a_{k+i} = 0` for all `k + L < a.len()`.
pub(crate) fn berlekamp_massey(fp: &Fp, a: &[u64]) -> Vec<u64> {
    // connection polynomial C(x) = 1 + c₁x + … with a_k + Σ c_i a_{k−i} = 0
    let mut c: Vec<u64> = vec![1];
    let mut b: Vec<u64> = vec![1];
    let (mut l, mut m, mut bd) = (0usize, 1usize, 1u64);
    for k in 0..a.len() {
        crate::budget::check();
        let mut d = a[k];
        for i in 1..=l.min(c.len() - 1) {
            d = fp.add(d, fp.mul(c[i], a[k - i]));
        }
        if d == 0 {
            m += 1;
            continue;
        }
        let coef = fp.mul(d, fp.inv(bd).expect("non-zero discrepancy"));
        let old = c.clone();
        if c.len() < b.len() + m {
            c.resize(b.len() + m, 0);
        }
        for (i, &bi) in b.iter().enumerate() {
            c[i + m] = fp.sub(c[i + m], fp.mul(coef, bi));
        }
        if 2 * l <= k {
            l = k + 1 - l;
            b = old;
            bd = d;
            m = 1;
        } else {
            m += 1;
        }
    }
    c.resize(l + 1, 0);
    // m(T) = T^L·C(1/T): ascending coefficients are C reversed
    c.reverse();
    c
}

/// Arithmetic in `F_p[T]/(f)` for a monic `f` of degree n ≥ 1.
pub(crate) struct ModAlgebra {
    pub(crate) fp: Fp,
    /// `T^n = Σ c_j T^j` (length n).
    pub(crate) c: Vec<u64>,
    /// Shoup's quotients of c, for [`ModAlgebra::times_t`].
    cw: Vec<u64>,
}

impl ModAlgebra {
    /// From `c` with `T^n = Σ c_j T^j`.
    pub(crate) fn from_c(fp: Fp, c: Vec<u64>) -> ModAlgebra {
        let cw = crate::number::modkernel::shoup_quotients(fp.p, &c);
        ModAlgebra { fp, c, cw }
    }

    /// From a polynomial with ascending residues and a non-zero leading
    /// coefficient (made monic).
    pub(crate) fn from_poly(fp: Fp, f: &[u64]) -> Option<ModAlgebra> {
        let (&lc, low) = f.split_last()?;
        if low.is_empty() {
            return None;
        }
        let inv = fp.inv(lc)?;
        let c = low.iter().map(|&a| fp.neg(fp.mul(a, inv))).collect();
        Some(ModAlgebra::from_c(fp, c))
    }

    pub(crate) fn n(&self) -> usize {
        self.c.len()
    }

    /// The low coefficients of the monic `f`.
    pub(crate) fn low(&self) -> Vec<u64> {
        self.c.iter().map(|&x| self.fp.neg(x)).collect()
    }

    /// `f` ascending, monic.
    fn full(&self) -> Vec<u64> {
        let mut f = self.low();
        f.push(1);
        f
    }

    /// `f′ mod f` (degree < n: f′ itself).
    pub(crate) fn derivative(&self) -> Vec<u64> {
        let fp = &self.fp;
        let n = self.n();
        let low = self.low();
        let mut fd = vec![0u64; n];
        for j in 1..n {
            fd[j - 1] = fp.mul(j as u64 % fp.p, low[j]);
        }
        fd[n - 1] = n as u64 % fp.p;
        fd
    }

    /// `gcd(f, f′) = 1`.
    pub(crate) fn is_squarefree(&self) -> bool {
        poly_gcd_mod(&self.fp, &self.full(), &self.derivative()).len() == 1
    }

    /// Product.
    pub(crate) fn mul(&self, a: &[u64], b: &[u64]) -> Vec<u64> {
        mulmod(&self.fp, a, b, &self.c)
    }

    /// The inverse of `a` (`None` when `gcd(a, f) ≠ 1`), by extended Euclid.
    pub(crate) fn inv(&self, a: &[u64]) -> Option<Vec<u64>> {
        let fp = &self.fp;
        let n = self.n();
        let (g, s) = euclid(fp, self.full(), a.to_vec(), Some(n));
        // g = gcd(f, a) (not normalised), s·a ≡ g (mod f)
        if g.len() != 1 {
            return None;
        }
        let k = fp.inv(g[0])?;
        let s = s.expect("cofactor requested");
        Some(s.iter().map(|&x| fp.mul(x, k)).collect())
    }

    /// `Tr(T^m)` for `m < count` (power sums of the roots of f, Newton).
    fn traces(&self, count: usize) -> Vec<u64> {
        let fp = &self.fp;
        let n = self.n();
        let a = self.low(); // f = T^n + Σ a_k T^k
        let mut p = vec![0u64; count];
        if count == 0 {
            return p;
        }
        p[0] = n as u64 % fp.p;
        // p_1 … p_{m−1}, for the dot product with a_{n−k} … a_{n−1}
        let mut rev: Vec<u64> = Vec::with_capacity(count);
        for m in 1..count {
            // p_m = −(m·a_{n−m} [m ≤ n] + Σ_{i=1}^{min(m−1, n)} a_{n−i} p_{m−i})
            let mut acc = if m <= n {
                fp.mul(m as u64 % fp.p, a[n - m])
            } else {
                0
            };
            let k = (m - 1).min(n);
            if k > 0 {
                // p_{m−1}, p_{m−2}, …, p_{m−k} against a_{n−1}, …, a_{n−k}
                let ps = &rev[rev.len() - k..];
                acc = fp.add(acc, crate::number::modkernel::dot(fp, ps, &a[n - k..n]));
            }
            p[m] = fp.neg(acc);
            rev.push(p[m]);
        }
        p
    }

    /// `T·v mod f`: a shift and one fold (n products).
    pub(crate) fn times_t(&self, v: &[u64]) -> Vec<u64> {
        let mut out = Vec::with_capacity(self.n());
        out.push(0);
        out.extend_from_slice(&v[..self.n() - 1]);
        self.fold_top(&mut out, v[self.n() - 1]);
        out
    }

    /// `out ← out + top·T^n mod f` (the fold of [`Self::times_t`]).
    fn fold_top(&self, out: &mut [u64], top: u64) {
        if top != 0 {
            crate::number::modkernel::axpy_shoup(self.fp.p, out, top, &self.c, &self.cw);
        }
    }

    /// The columns `s·T^j mod f` (`j < n`) of the multiplication by `s`,
    /// one after the other, each from the one before by a shift and a fold
    /// (`n²` products).
    fn mult_columns(&self, s: &[u64]) -> Vec<u64> {
        let n = self.n();
        let mut m = Vec::with_capacity(n * n);
        m.extend_from_slice(&s[..s.len().min(n)]);
        m.resize(n, 0);
        for j in 1..n {
            let prev = (j - 1) * n;
            let top = m[prev + n - 1];
            m.push(0);
            m.extend_from_within(prev..prev + n - 1);
            self.fold_top(&mut m[j * n..], top);
        }
        m
    }

    /// [`Self::mult_columns`] as 32-bit entries, for
    /// [`mat_vec`](crate::number::modkernel::mat_vec).
    pub(crate) fn mult_matrix(&self, s: &[u64]) -> Vec<u32> {
        self.mult_columns(s).into_iter().map(|x| x as u32).collect()
    }

    /// The characteristic polynomial of the multiplication by `s`
    /// (ascending, monic, degree n): power sums `Tr(s^k)` by baby steps
    /// and giant steps, then Newton's identities (p > n).  With r = ⌈√(n+1)⌉
    /// and `G = s^r`, `Tr(s^(jr+i)) = λ_j(s^i)` for the linear forms
    /// `λ_j = Tr(G^j ·)`: the baby steps `s^i` are products by the matrix
    /// of s, the forms `λ_(j+1)(x) = λ_j(G·x)` products by the transpose
    /// of G's matrix (`λ_0` = the traces of the powers of T), so about
    /// `(2√n + 4)·n²` products in all, no product modulo f.
    pub(crate) fn charpoly(&self, s: &[u64]) -> Vec<u64> {
        use crate::number::modkernel::{dot, mat_vec};
        let fp = &self.fp;
        let n = self.n();
        let r = (1..)
            .find(|&r: &usize| r * r > n)
            .expect("r² > n for some r");
        let ms = self.mult_matrix(s);
        // baby steps s^0 … s^(r−1), then G = s^r
        let mut one = vec![0u64; n];
        one[0] = 1;
        let mut baby: Vec<Vec<u64>> = vec![one];
        for i in 1..=r {
            crate::budget::check();
            let next = mat_vec(fp, &ms, n, &baby[i - 1]);
            baby.push(next);
        }
        let giant = baby.pop().expect("r + 1 powers");
        let mg = self.mult_columns(&giant);
        // power sums P_k = Tr(s^k) for k = 1 … n
        let mut ps = vec![0u64; n + 1];
        let mut lam = self.traces(n);
        let mut k0 = 0;
        while k0 <= n {
            crate::budget::check();
            for (i, b) in baby.iter().enumerate() {
                let k = k0 + i;
                if k > n {
                    break;
                }
                ps[k] = dot(fp, &lam, b);
            }
            k0 += r;
            if k0 <= n {
                lam = mg.chunks_exact(n).map(|col| dot(fp, &lam, col)).collect();
            }
        }
        // Newton: χ = Σ e_k u^(n−k), k·e_k = −Σ_{i=1}^k P_i e_{k−i}
        let mut e = vec![0u64; n + 1];
        e[0] = 1;
        // prev = P_n, …, P_1: Σ P_i e_{k−i} = e_0 … e_{k−1} against P_k … P_1
        let prev: Vec<u64> = ps[1..].iter().rev().copied().collect();
        for k in 1..=n {
            let acc = dot(fp, &e[..k], &prev[n - k..]);
            let inv = fp.inv(k as u64 % fp.p).expect("p > n");
            e[k] = fp.neg(fp.mul(acc, inv));
        }
        e.reverse();
        e
    }
}

pub(crate) fn trimmed(a: &[u64]) -> Vec<u64> {
    let mut v = a.to_vec();
    while v.last() == Some(&0) {
        v.pop();
    }
    v
}

/// `a rem b` modulo p (ascending, trimmed; `b` non-zero).
pub(crate) fn rem_mod(fp: &Fp, a: &[u64], b: &[u64]) -> Vec<u64> {
    let mut r = a.to_vec();
    let b: Vec<u32> = trimmed(b).iter().map(|&x| x as u32).collect();
    let il = fp
        .inv(*b.last().expect("non-zero divisor") as u64)
        .expect("non-zero");
    divide_lazy(fp, &mut r, &b, il, None);
    reduced_trimmed(fp, &r)
}

/// `num / den` in `Q[T]/(f)` for a square-free `f` (degree ≥ 1) and `den`
/// `Res(a, b)` modulo p by Euclid's algorithm, for `a`, `b` with non-zero
/// leading coefficients modulo p (ascending): `Res(a, b) = (−1)^(mn)
/// lc(b)^(m − deg r)·Res(b, r)` with `r = a rem b`, down to a constant.
pub(crate) fn resultant_mod(fp: &Fp, a: &[u64], b: &[u64]) -> u64 {
    let (mut a, mut b) = (trimmed(a), trimmed(b));
    let mut acc = 1u64;
    loop {
        let (Some(m), Some(n)) = (a.len().checked_sub(1), b.len().checked_sub(1)) else {
            return 0;
        };
        if n == 0 {
            return fp.mul(acc, fp.pow(b[0], m as u64));
        }
        let r = if b.len() <= SHORT_DIVISOR {
            rem_short(fp, a, &b)
        } else {
            rem_mod(fp, &a, &b)
        };
        if r.is_empty() {
            return 0;
        }
        if m * n % 2 == 1 {
            acc = fp.neg(acc);
        }
        acc = fp.mul(acc, fp.pow(b[n], (m - (r.len() - 1)) as u64));
        (a, b) = (b, r);
    }
}

/// The gcd modulo p (not normalised; ascending, trimmed).
pub(crate) fn poly_gcd_mod(fp: &Fp, a: &[u64], b: &[u64]) -> Vec<u64> {
    if a.len().max(b.len()) > SHORT_DIVISOR {
        return euclid(fp, a.to_vec(), b.to_vec(), None).0;
    }
    let (mut a, mut b) = (trimmed(a), trimmed(b));
    while !b.is_empty() {
        a = rem_short(fp, a, &b);
        std::mem::swap(&mut a, &mut b);
    }
    a
}

/// Divisors up to this length are divided by [`rem_short`] (in place, one
/// reduction per product): the lazy kernel's set-up costs more than it
/// saves on them.
const SHORT_DIVISOR: usize = 24;

/// `a rem b` modulo p for residues (`b` trimmed, non-zero), in place.
fn rem_short(fp: &Fp, mut a: Vec<u64>, b: &[u64]) -> Vec<u64> {
    let db = b.len() - 1;
    let inv = fp.inv(b[db]).expect("non-zero leading coefficient");
    while a.len() > db {
        let k = a.len() - 1 - db;
        let t = fp.mul(a[a.len() - 1], inv);
        if t != 0 {
            for j in 0..db {
                a[k + j] = fp.sub(a[k + j], fp.mul(t, b[j]));
            }
        }
        a.pop();
        while a.last() == Some(&0) {
            a.pop();
        }
    }
    a
}

/// Euclid's algorithm modulo p on `(a, b)`: the gcd (reduced, trimmed, not
/// normalised) and, when `cofactor = Some(len)`, an `s` of length `len`
/// with `s·b ≡ gcd (mod a)` (cofactors truncated to `len` terms, which
/// is exact when `len > deg a`).
///
/// Rows are kept lazily below p² and updated by the vector kernel of the
/// modular product (`row ← row + t·d` with the divisor `d` made monic and
/// stored on 32 bits); only leading coefficients are reduced on the way,
/// and a remainder once, when it becomes the next divisor.
pub(crate) fn euclid(
    fp: &Fp,
    a: Vec<u64>,
    b: Vec<u64>,
    cofactor: Option<usize>,
) -> (Vec<u64>, Option<Vec<u64>>) {
    let len = cofactor.unwrap_or(0);
    let (mut r0, mut r1) = (a, b);
    let mut s0 = vec![0u64; len];
    let mut s1 = vec![0u64; len];
    if len > 0 {
        s1[0] = 1;
    }
    loop {
        trim_lazy(fp, &mut r1);
        if r1.is_empty() {
            break;
        }
        // the divisor and its cofactor reduced once, on 32 bits; the
        // quotient's terms are top·lc⁻¹
        let d = crate::number::modkernel::reduce_to_u32(fp, &r1);
        let il = fp
            .inv(*d.last().expect("non-empty") as u64)
            .expect("non-zero");
        let e = (len > 0).then(|| {
            // entries past the cofactor's degree were never touched
            let sl = s1.iter().rposition(|&x| x != 0).map_or(0, |i| i + 1);
            let mut e = crate::number::modkernel::reduce_to_u32(fp, &s1[..sl]);
            while e.last() == Some(&0) {
                e.pop();
            }
            e
        });
        divide_lazy(fp, &mut r0, &d, il, e.as_deref().map(|e| (&mut s0[..], e)));
        std::mem::swap(&mut r0, &mut r1);
        std::mem::swap(&mut s0, &mut s1);
    }
    let g = reduced_trimmed(fp, &r0);
    let s = (len > 0).then(|| s0.iter().map(|&x| fp.reduce(x)).collect());
    (g, s)
}

/// `r ← r rem d` for `d` with 32-bit entries below p and leading
/// coefficient inverse `il`, `r` with entries below p² (left so, trimmed of
/// leading zeros modulo p); with `cof = Some((s, e))` also `s ← s − q·e`
/// for the quotient q (terms past `s.len()` dropped).
pub(crate) fn divide_lazy(
    fp: &Fp,
    r: &mut Vec<u64>,
    d: &[u32],
    il: u64,
    mut cof: Option<(&mut [u64], &[u32])>,
) {
    let fold = crate::number::modkernel::fold_row_kernel();
    let p2 = fp.p2;
    let low = &d[..d.len() - 1];
    trim_lazy(fp, r);
    while r.len() >= d.len() {
        let top = fp.reduce(*r.last().expect("non-empty"));
        let k = r.len() - d.len();
        let t = fp.neg(fp.mul(top, il));
        let end = r.len() - 1;
        fold(&mut r[k..end], t, low, p2);
        if let Some((s, e)) = cof.as_mut()
            && k < s.len()
        {
            let m = e.len().min(s.len() - k);
            fold(&mut s[k..k + m], t, &e[..m], p2);
        }
        r.pop();
        trim_lazy(fp, r);
    }
}

/// Drops the leading entries that are zero modulo p.
pub(crate) fn trim_lazy(fp: &Fp, r: &mut Vec<u64>) {
    while let Some(&x) = r.last() {
        if fp.reduce(x) != 0 {
            break;
        }
        r.pop();
    }
}

/// Entries reduced modulo p, leading zeros dropped.
pub(crate) fn reduced_trimmed(fp: &Fp, a: &[u64]) -> Vec<u64> {
    let r: Vec<u64> = a.iter().map(|&x| fp.reduce(x)).collect();
    trimmed(&r)
}

/// Residues of an integer polynomial (ascending).
pub(crate) fn zpoly_mod(fp: &Fp, p: &ZPoly) -> Vec<u64> {
    p.coeffs().iter().map(|c| fp.reduce_big(c)).collect()
}

/// `len` pseudo-random residues modulo p (a linear congruential
/// generator on `seed`), for the tests of the arithmetic modulo p.
#[cfg(test)]
pub(crate) fn residues_for_tests(fp: &Fp, seed: &mut u64, len: usize) -> Vec<u64> {
    (0..len)
        .map(|_| {
            *seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (*seed >> 33) % fp.p
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::prime31::prime31;

    /// Berlekamp–Massey finds the recurrence of a sequence built from one:
    /// `a_{k+3} = 5a_{k+2} − 2a_{k+1} + 7a_k` (minimal polynomial
    /// `T³ − 5T² + 2T − 7`).
    #[test]
    fn berlekamp_massey_finds_the_recurrence() {
        let fp = Fp::new(prime31(4));
        let mut a = vec![1u64, 2, 3];
        for k in 0..20 {
            let next = fp.add(
                fp.sub(fp.mul(5, a[k + 2]), fp.mul(2, a[k + 1])),
                fp.mul(7, a[k]),
            );
            a.push(next);
        }
        let m = berlekamp_massey(&fp, &a);
        assert_eq!(m, vec![fp.neg(7), 2, fp.neg(5), 1]);
    }

    /// Naive product modulo p (ascending), for the checks below.
    fn mul_naive(fp: &Fp, a: &[u64], b: &[u64]) -> Vec<u64> {
        let mut r = vec![0u64; a.len() + b.len() - 1];
        for (i, &x) in a.iter().enumerate() {
            for (j, &y) in b.iter().enumerate() {
                r[i + j] = fp.add(r[i + j], fp.mul(x, y));
            }
        }
        r
    }

    /// The lazy Euclid (rows below p², vector row updates): inverses are
    /// inverses, a common factor is found by the gcd and blocks the
    /// inverse, and the remainder is that of the schoolbook division.
    #[test]
    fn lazy_euclid_inverse_gcd_and_remainder() {
        let fp = Fp::new(prime31(3));
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut rnd = |len: usize| residues_for_tests(&fp, &mut seed, len);
        for n in [1usize, 2, 7, 40, 129] {
            let mut f = rnd(n);
            f.push(1);
            let alg = ModAlgebra::from_poly(fp, &f).expect("monic");
            let a = rnd(n);
            let inv = alg.inv(&a).expect("a random element is invertible");
            let mut one = vec![0u64; n];
            one[0] = 1;
            assert_eq!(alg.mul(&a, &inv), one, "degree {n}");
            // a common factor g of degree 3: no inverse, gcd = c·g
            let mut g = rnd(3);
            g.push(1);
            let mut h = rnd(n);
            h.push(1);
            let fg = mul_naive(&fp, &g, &h);
            let ag = mul_naive(&fp, &g, &rnd(n.max(2) - 1));
            let alg = ModAlgebra::from_poly(fp, &fg).expect("monic");
            let mut ar = rem_mod(&fp, &ag, &fg);
            ar.resize(fg.len() - 1, 0);
            assert!(alg.inv(&ar).is_none(), "a common factor blocks the inverse");
            let d = poly_gcd_mod(&fp, &fg, &ag);
            assert!(d.len() >= g.len(), "the gcd contains the common factor");
            assert!(rem_mod(&fp, &d, &g).is_empty(), "g divides the gcd");
            // remainder: a = q·b + r with deg r < deg b
            let b = h.clone();
            let q = rnd(5);
            let r = rnd(n.min(b.len() - 1));
            let mut a2 = mul_naive(&fp, &q, &b);
            for (x, &y) in a2.iter_mut().zip(&r) {
                *x = fp.add(*x, y);
            }
            assert_eq!(rem_mod(&fp, &a2, &b), trimmed(&r));
        }
    }
}
