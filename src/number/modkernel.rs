//! Vector kernels modulo a word prime `p < 2^31` (see [`Fp`]): the
//! product in `F_p[T]/(m)`, the matrix–vector product and the
//! Gauss–Jordan solve of the multi-modular routes.
//!
//! Key idea: every inner loop has the shape `x ← x + a·b` with `a, b < p`
//! (so `a·b < 2^62`) and `x` kept below `p²` by one conditional
//! subtraction, the reduction modulo p done once per output.  Written on
//! 32-bit factors, such loops vectorise (`vpmuludq` multiplies four 32-bit
//! pairs into 64-bit lanes); each kernel is compiled twice, for the base
//! target and for AVX2, and the AVX2 copy is chosen at run time when the
//! processor has it.  The results are identical (exact arithmetic).

use super::reconstruct::Fp;

/// Defines `pub fn $name` that runs an AVX2-compiled copy of `$generic`
/// when the processor supports it, the generic code otherwise.
macro_rules! dispatch {
    ($(#[$m:meta])* pub fn $name:ident / $avx:ident / $generic:ident ($($arg:ident : $ty:ty),*) -> $ret:ty) => {
        $(#[$m])*
        pub fn $name($($arg: $ty),*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            {
                if std::is_x86_feature_detected!("avx2") {
                    // SAFETY: the processor supports AVX2 (checked above);
                    // the function only enables code generation for it.
                    return unsafe { $avx($($arg),*) };
                }
            }
            $generic($($arg),*)
        }

        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2")]
        unsafe fn $avx($($arg: $ty),*) -> $ret {
            $generic($($arg),*)
        }
    };
}

dispatch! {
    /// `a·b mod m` in `F_p[T]` for a monic `m = T^n − Σ c_j T^j` (`c` of
    /// length n; `a`, `b` of length ≤ n, entries in `[0, p)`): the product
    /// by the schoolbook rule, then the top half folded down from the top.
    pub fn mulmod / mulmod_avx2 / mulmod_generic(fp: &Fp, a: &[u64], b: &[u64], c: &[u64]) -> Vec<u64>
}

#[inline(always)]
fn mulmod_generic(fp: &Fp, a: &[u64], b: &[u64], c: &[u64]) -> Vec<u64> {
    let n = c.len();
    let p2 = fp.p2;
    let b32: Vec<u32> = b.iter().map(|&x| x as u32).collect();
    let c32: Vec<u32> = c.iter().map(|&x| x as u32).collect();
    let mut r = vec![0u64; 2 * n];
    for (i, &ai) in a.iter().enumerate() {
        let ai = ai as u32 as u64;
        if ai == 0 {
            continue;
        }
        let row = &mut r[i..i + b32.len()];
        for (x, &bj) in row.iter_mut().zip(&b32) {
            let t = *x + ai * bj as u64;
            *x = if t >= p2 { t - p2 } else { t };
        }
    }
    let fold = fold_row_kernel();
    for k in (n..2 * n).rev() {
        let top = fp.reduce(r[k]);
        if top == 0 {
            continue;
        }
        fold(&mut r[k - n..k], top, &c32, p2);
    }
    r.truncate(n);
    r.iter_mut().for_each(|x| *x = fp.reduce(*x));
    r
}

/// `row ← row + a·c` entrywise, entries kept below `p²` (`a < p`, entries
/// of `c` below p): the fold step of [`mulmod`].  The compiler does not
/// vectorise this loop by itself (it does the product's), so on AVX2 it is
/// written with intrinsics: four lanes of `vpmuludq`, the conditional
/// subtraction as a compare and a masked subtract (every value is below
/// 2^63, so the signed compare is exact).  The kernel for this processor
/// is chosen once per product, not per row.  Euclid's algorithm modulo p
/// ([`crate::roots::poisson`]) uses the same kernel for its row updates.
#[inline(always)]
pub fn fold_row_kernel() -> fn(&mut [u64], u64, &[u32], u64) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::is_x86_feature_detected!("avx2") {
            return |row, a, c, p2| {
                // SAFETY: the processor supports AVX2 (checked above).
                unsafe { fold_row_avx2(row, a, c, p2) }
            };
        }
    }
    fold_row_generic
}

#[inline(always)]
fn fold_row_generic(row: &mut [u64], a: u64, c: &[u32], p2: u64) {
    let a = a as u32 as u64;
    for (x, &cj) in row.iter_mut().zip(c) {
        let t = *x + a * cj as u64;
        *x = if t >= p2 { t - p2 } else { t };
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn fold_row_avx2(row: &mut [u64], a: u64, c: &[u32], p2: u64) {
    use std::arch::x86_64::*;
    let len = row.len().min(c.len());
    let (row, c) = (&mut row[..len], &c[..len]);
    let va = _mm256_set1_epi64x(a as u32 as i64);
    let vp2 = _mm256_set1_epi64x(p2 as i64);
    let vlim = _mm256_set1_epi64x(p2 as i64 - 1);
    let mut i = 0;
    while i + 4 <= len {
        // SAFETY: i + 4 ≤ len for both slices; unaligned loads and stores.
        unsafe {
            let cv = _mm256_cvtepu32_epi64(_mm_loadu_si128(c.as_ptr().add(i) as *const __m128i));
            let x = _mm256_loadu_si256(row.as_ptr().add(i) as *const __m256i);
            let t = _mm256_add_epi64(x, _mm256_mul_epu32(va, cv));
            let over = _mm256_cmpgt_epi64(t, vlim);
            let t = _mm256_sub_epi64(t, _mm256_and_si256(over, vp2));
            _mm256_storeu_si256(row.as_mut_ptr().add(i) as *mut __m256i, t);
        }
        i += 4;
    }
    fold_row_generic(&mut row[i..], a, &c[i..], p2);
}

dispatch! {
    /// `M·v` for a matrix stored by columns (entries in `[0, p)`).
    pub fn mat_vec / mat_vec_avx2 / mat_vec_generic(fp: &Fp, cols: &[Vec<u32>], v: &[u64]) -> Vec<u64>
}

#[inline(always)]
fn mat_vec_generic(fp: &Fp, cols: &[Vec<u32>], v: &[u64]) -> Vec<u64> {
    let p2 = fp.p2;
    let mut acc = vec![0u64; cols.first().map_or(0, |c| c.len())];
    for (col, &vj) in cols.iter().zip(v) {
        if vj == 0 {
            continue;
        }
        let vj = vj as u32 as u64;
        for (a, &m) in acc.iter_mut().zip(col) {
            let t = *a + m as u64 * vj;
            *a = if t >= p2 { t - p2 } else { t };
        }
    }
    acc.iter().map(|&a| fp.reduce(a)).collect()
}

dispatch! {
    /// Solves `K c = r` for the columns `k` (n vectors of length n, entries in
    /// `[0, p)`) and each right-hand side: Gauss–Jordan on the augmented
    /// matrix, rows kept below `p²` and reduced when they become pivots.
    /// `None` when `K` is singular.
    pub fn solve_columns / solve_columns_avx2 / solve_columns_generic(fp: &Fp, k: &[Vec<u64>], rhs: &[Vec<u64>]) -> Option<Vec<Vec<u64>>>
}

#[inline(always)]
fn solve_columns_generic(fp: &Fp, k: &[Vec<u64>], rhs: &[Vec<u64>]) -> Option<Vec<Vec<u64>>> {
    let n = k.len();
    let w = n + rhs.len();
    let p2 = fp.p2;
    let mut a: Vec<Vec<u64>> = (0..n)
        .map(|i| {
            k.iter()
                .map(|c| c[i])
                .chain(rhs.iter().map(|r| r[i]))
                .collect()
        })
        .collect();
    let mut prow32 = vec![0u32; w];
    for c in 0..n {
        crate::budget::check();
        // entries of column c are below p² (lazy): reduce them to find a pivot
        for row in a.iter_mut().skip(c) {
            row[c] = fp.reduce(row[c]);
        }
        let piv = (c..n).find(|&i| a[i][c] != 0)?;
        a.swap(c, piv);
        let inv = fp.inv(a[c][c]).expect("non-zero pivot");
        for x in a[c][c..].iter_mut() {
            *x = fp.mul(fp.reduce(*x), inv);
        }
        for (d, &s) in prow32[c..].iter_mut().zip(&a[c][c..]) {
            *d = s as u32;
        }
        for i in 0..n {
            if i == c {
                continue;
            }
            let f = fp.reduce(a[i][c]);
            if f == 0 {
                continue;
            }
            // a 32-bit factor: the loop vectorises (vpmuludq)
            let f = fp.neg(f) as u32 as u64;
            for (x, &y) in a[i][c..].iter_mut().zip(&prow32[c..]) {
                let t = *x + f * y as u64;
                *x = if t >= p2 { t - p2 } else { t };
            }
        }
    }
    Some(
        (0..rhs.len())
            .map(|r| (0..n).map(|i| fp.reduce(a[i][n + r])).collect())
            .collect(),
    )
}

dispatch! {
    /// `acc ← acc + a·x` entrywise, `acc` kept below `p²` (lazy: reduce
    /// with [`Fp::reduce`] before use); `a` and the entries of `x` in
    /// `[0, p)`.
    pub fn axpy_lazy / axpy_lazy_avx2 / axpy_lazy_generic(fp: &Fp, acc: &mut [u64], a: u64, x: &[u64]) -> ()
}

#[inline(always)]
fn axpy_lazy_generic(fp: &Fp, acc: &mut [u64], a: u64, x: &[u64]) {
    let p2 = fp.p2;
    let a = a as u32 as u64;
    for (y, &xi) in acc.iter_mut().zip(x) {
        let t = *y + a * (xi as u32 as u64);
        *y = if t >= p2 { t - p2 } else { t };
    }
}

dispatch! {
    /// `Σ aᵢ·bᵢ mod p` (entries in `[0, p)`), in four lazy lanes.
    pub fn dot / dot_avx2 / dot_generic(fp: &Fp, a: &[u64], b: &[u64]) -> u64
}

#[inline(always)]
fn dot_generic(fp: &Fp, a: &[u64], b: &[u64]) -> u64 {
    let p2 = fp.p2;
    let mut lanes = [0u64; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for l in 0..4 {
            let t = lanes[l] + (x[l] as u32 as u64) * (y[l] as u32 as u64);
            lanes[l] = if t >= p2 { t - p2 } else { t };
        }
    }
    let mut acc = 0u64;
    for l in lanes {
        acc = fp.add(acc, fp.reduce(l));
    }
    for (&x, &y) in ra.iter().zip(rb) {
        acc = fp.add(acc, fp.mul(x, y));
    }
    acc
}

dispatch! {
    /// `y ← y·a + d (mod p)` elementwise, the Horner step of Garner's
    /// mixed radix ([`super::reconstruct::CrtVec`]): `a < p < 2^31` with
    /// `w = ⌊a·2^32/p⌋` (Shoup's precomputed quotient), `y < 2^32` in and
    /// out (congruent, not reduced), `d < 2^31`.
    pub fn shoup_horner / shoup_horner_avx2 / shoup_horner_generic(y: &mut [u32], d: &[u32], a: u64, w: u64, p: u64) -> ()
}

#[inline(always)]
fn shoup_horner_generic(y: &mut [u32], d: &[u32], a: u64, w: u64, p: u64) {
    // 32-bit factors, so that every product is one `vpmuludq`
    let (a, w, p) = (a as u32 as u64, w as u32 as u64, p as u32 as u64);
    let two_p = 2 * p;
    for (yi, &di) in y.iter_mut().zip(d) {
        let x = u64::from(*yi);
        // q ≤ ⌊x·a/p⌋, q ≥ ⌊x·a/p⌋ − 1: the remainder is in [0, 2p)
        let q = (x * w) >> 32;
        let r = (x * a).wrapping_sub(q * p);
        let v = r + u64::from(di);
        *yi = if v >= two_p { v - two_p } else { v } as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::reconstruct::prime31;

    fn rand_vec(seed: &mut u64, n: usize, p: u64) -> Vec<u64> {
        (0..n)
            .map(|_| {
                *seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (*seed >> 33) % p
            })
            .collect()
    }

    /// The vectorised product equals the plain definition: the schoolbook
    /// product reduced by `T^n = Σ c_j T^j`, one step at a time.
    #[test]
    fn mulmod_agrees_with_the_definition() {
        let fp = Fp::new(prime31(3));
        let mut seed = 5;
        for n in [1usize, 2, 7, 31, 64, 65] {
            let a = rand_vec(&mut seed, n, fp.p);
            let b = rand_vec(&mut seed, n, fp.p);
            let c = rand_vec(&mut seed, n, fp.p);
            let mut r = vec![0u64; 2 * n];
            for i in 0..n {
                for j in 0..n {
                    r[i + j] = fp.add(r[i + j], fp.mul(a[i], b[j]));
                }
            }
            for k in (n..2 * n).rev() {
                let t = r[k];
                r[k] = 0;
                for j in 0..n {
                    r[k - n + j] = fp.add(r[k - n + j], fp.mul(t, c[j]));
                }
            }
            r.truncate(n);
            assert_eq!(mulmod(&fp, &a, &b, &c), r, "n = {n}");
            assert_eq!(mulmod_generic(&fp, &a, &b, &c), r, "n = {n}");
        }
    }

    /// `solve_columns` solves: `K·x = r` holds for every right-hand side,
    /// and a singular matrix gives `None`.
    #[test]
    fn axpy_and_dot_agree_with_the_definition() {
        let fp = Fp::new(prime31(2));
        let mut seed = 3;
        for n in [0usize, 1, 5, 16, 33] {
            let a = rand_vec(&mut seed, n, fp.p);
            let b = rand_vec(&mut seed, n, fp.p);
            let want = a
                .iter()
                .zip(&b)
                .fold(0, |s, (&x, &y)| fp.add(s, fp.mul(x, y)));
            assert_eq!(dot(&fp, &a, &b), want);
            let mut acc = b.clone();
            axpy_lazy(&fp, &mut acc, 12345, &a);
            axpy_lazy(&fp, &mut acc, fp.p - 1, &a);
            for i in 0..n {
                let w = fp.add(b[i], fp.mul(12344, a[i]));
                assert_eq!(fp.reduce(acc[i]), w);
            }
        }
    }

    #[test]
    fn solve_columns_solves() {
        let fp = Fp::new(prime31(1));
        let mut seed = 11;
        for n in [1usize, 3, 20, 41] {
            let k: Vec<Vec<u64>> = (0..n).map(|_| rand_vec(&mut seed, n, fp.p)).collect();
            let rhs: Vec<Vec<u64>> = (0..3).map(|_| rand_vec(&mut seed, n, fp.p)).collect();
            let sol = solve_columns(&fp, &k, &rhs).expect("random matrices are invertible");
            for (r, x) in rhs.iter().zip(&sol) {
                let cols: Vec<Vec<u32>> = k
                    .iter()
                    .map(|c| c.iter().map(|&v| v as u32).collect())
                    .collect();
                assert_eq!(&mat_vec(&fp, &cols, x), r);
            }
        }
        let mut k: Vec<Vec<u64>> = (0..4).map(|_| rand_vec(&mut seed, 4, fp.p)).collect();
        k[3] = k[1].clone();
        assert!(solve_columns(&fp, &k, &[vec![1, 2, 3, 4]]).is_none());
    }
}

#[cfg(test)]
mod fold_tests {
    use super::*;
    use crate::number::reconstruct::prime31;

    /// A pseudo-random number below `m` (a linear congruential generator
    /// on `seed`; `m ≤ 2^31`).
    fn lcg(seed: &mut u64, m: u64) -> u64 {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*seed >> 33) % m
    }

    /// The AVX2 fold step equals the portable one.
    #[test]
    fn fold_row_matches_generic() {
        let fp = Fp::new(prime31(2));
        let mut seed = 5u64;
        let mut rnd = |m: u64| lcg(&mut seed, m);
        for len in [0usize, 1, 3, 4, 5, 17, 114] {
            let c: Vec<u32> = (0..len).map(|_| rnd(fp.p) as u32).collect();
            let row0: Vec<u64> = (0..len).map(|_| rnd(fp.p2)).collect();
            let a = rnd(fp.p);
            let mut r1 = row0.clone();
            let mut r2 = row0.clone();
            fold_row_kernel()(&mut r1, a, &c, fp.p2);
            fold_row_generic(&mut r2, a, &c, fp.p2);
            assert_eq!(r1, r2, "len {len}");
        }
    }

    /// Shoup's Horner step (dispatched, AVX2 where available) is congruent
    /// to `y·a + d` modulo p and stays below 2^32, from the extremes of its
    /// input ranges too (y = 2^32 − 1, a = p − 1, d = 2^31 − 1).
    #[test]
    fn shoup_horner_is_a_horner_step() {
        let mut seed = 11u64;
        // 32 random bits from two draws
        let mut rnd = |m: u64| ((lcg(&mut seed, 1 << 31) << 1) | lcg(&mut seed, 2)) % m;
        for k in [0usize, 5, 300] {
            let p = prime31(k);
            for len in [0usize, 1, 4, 7, 115] {
                let mut y: Vec<u32> = (0..len).map(|_| rnd(1 << 32) as u32).collect();
                let mut d: Vec<u32> = (0..len).map(|_| rnd(1 << 31) as u32).collect();
                if len > 0 {
                    y[0] = u32::MAX;
                    d[0] = (1 << 31) - 1;
                }
                for a in [0, 1, rnd(p), p - 1] {
                    let before = y.clone();
                    shoup_horner(&mut y, &d, a, (a << 32) / p, p);
                    for i in 0..len {
                        let want = (u64::from(before[i]) * a + u64::from(d[i])) % p;
                        assert_eq!(u64::from(y[i]) % p, want, "p {p}, a {a}, len {len}");
                    }
                }
            }
        }
    }
}
