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

use super::prime31::Fp;

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
/// (`poly::modp`) uses the same kernel for its row updates.
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
    /// `M·v` for a matrix of `rows` rows stored by columns, one after the
    /// other in `cols` (entries in `[0, p)`).
    pub fn mat_vec / mat_vec_avx2 / mat_vec_generic(fp: &Fp, cols: &[u32], rows: usize, v: &[u64]) -> Vec<u64>
}

#[inline(always)]
fn mat_vec_generic(fp: &Fp, cols: &[u32], rows: usize, v: &[u64]) -> Vec<u64> {
    let p2 = fp.p2 as i64;
    let mut acc = vec![0u64; rows];
    if rows == 0 {
        return acc;
    }
    for (col, &vj) in cols.chunks_exact(rows).zip(v) {
        if vj == 0 {
            continue;
        }
        let vj = vj as u32 as u64;
        for (a, &m) in acc.iter_mut().zip(col) {
            // below p² + p² < 2^63: the signed compare is exact
            let t = *a + m as u64 * vj;
            *a = if t as i64 >= p2 { t - p2 as u64 } else { t };
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
    /// `Σ aᵢ·bᵢ mod p` (entries below 2^32, e.g. in `[0, p)`): each
    /// product (below 2^64) split into its low and high 32 bits, each part
    /// summed without any reduction (no overflow below 2^32 terms), so the loop
    /// is multiplies, masks, shifts and adds only; two reductions at the
    /// end.
    pub fn dot / dot_avx2 / dot_generic(fp: &Fp, a: &[u64], b: &[u64]) -> u64
}

#[inline(always)]
fn dot_generic(fp: &Fp, a: &[u64], b: &[u64]) -> u64 {
    const LOW: u64 = 0xffff_ffff;
    let (mut lo, mut hi) = (0u64, 0u64);
    // integer sums: the compiler spreads them over vector lanes
    for (&x, &y) in a.iter().zip(b) {
        let t = (x as u32 as u64) * (y as u32 as u64);
        lo += t & LOW;
        hi += t >> 32;
    }
    // h·2^32 + l, each part reduced first
    fp.reduce(fp.reduce(hi) * fp.c32 + fp.reduce(lo))
}

dispatch! {
    /// `y ← y·a + d (mod p)` elementwise, the Horner step of Garner's
    /// mixed radix ([`super::prime31::CrtVec`]): `a < p < 2^31` with
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

dispatch! {
    /// `acc_j ← (acc_j + a·c_j) mod p`, reduced, for a fixed vector c with
    /// Shoup's quotients `cw_j = ⌊c_j·2^32/p⌋` ([`shoup_quotients`]);
    /// `a`, `acc_j`, `c_j` in `[0, p)`.  `a·c_j − ⌊a·cw_j/2^32⌋·p` is in
    /// `[0, 2p)` (`a < 2^32`), so two conditional subtractions reduce, with
    /// 32-bit factors only: the step `T·v mod f` of a multiplication
    /// matrix's columns, vectorised.
    pub fn axpy_shoup / axpy_shoup_avx2 / axpy_shoup_generic(p: u64, acc: &mut [u64], a: u64, c: &[u64], cw: &[u64]) -> ()
}

#[inline(always)]
fn axpy_shoup_generic(p: u64, acc: &mut [u64], a: u64, c: &[u64], cw: &[u64]) {
    let (a, p) = (a as u32 as u64, p as u32 as u64);
    for (y, (&cj, &wj)) in acc.iter_mut().zip(c.iter().zip(cw)) {
        let q = (a * (wj as u32 as u64)) >> 32;
        let r = (a * (cj as u32 as u64)).wrapping_sub(q * p);
        let r = if r >= p { r - p } else { r };
        let t = *y + r;
        *y = if t >= p { t - p } else { t };
    }
}

dispatch! {
    /// Lazy entries (below `p²`) reduced modulo p, as 32-bit words.  For
    /// `2^30 < p < 2^31` with `m = ⌊2^62/p⌋ < 2^32`, the quotient estimate
    /// `q = ⌊⌊x/2^30⌋·m/2^32⌋` satisfies `x/p − 3 < q ≤ x/p`, so
    /// `x − q·p` is in `[0, 3p)` and two conditional subtractions finish:
    /// 32-bit factors only, vectorised (Barrett's reduction takes a
    /// 128-bit product per entry).  Smaller primes take [`Fp::reduce`].
    pub fn reduce_to_u32 / reduce_to_u32_avx2 / reduce_to_u32_generic(fp: &Fp, x: &[u64]) -> Vec<u32>
}

#[inline(always)]
fn reduce_to_u32_generic(fp: &Fp, x: &[u64]) -> Vec<u32> {
    let p = fp.p;
    if p <= 1 << 30 {
        return x.iter().map(|&v| fp.reduce(v) as u32).collect();
    }
    let m = (1u64 << 62) / p;
    x.iter()
        .map(|&v| {
            debug_assert!(v < fp.p2);
            let q = (((v >> 30) as u32 as u64) * (m as u32 as u64)) >> 32;
            let r = v - q * p;
            let r = if r >= p { r - p } else { r };
            (if r >= p { r - p } else { r }) as u32
        })
        .collect()
}

/// Shoup's quotients `⌊c_j·2^32/p⌋` of a fixed vector (entries below p),
/// for [`axpy_shoup`].
pub fn shoup_quotients(p: u64, c: &[u64]) -> Vec<u64> {
    c.iter().map(|&x| (x << 32) / p).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::prime31::prime31;

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

    /// Shoup's product reduces exactly, also at the extremes `p − 1`.
    #[test]
    fn axpy_shoup_agrees_with_the_definition() {
        for k in [0usize, 3, 17] {
            let fp = Fp::new(prime31(k));
            let mut seed = 9;
            for n in [0usize, 1, 5, 16, 33] {
                let mut c = rand_vec(&mut seed, n, fp.p);
                let mut acc = rand_vec(&mut seed, n, fp.p);
                if n > 0 {
                    c[0] = fp.p - 1;
                    acc[0] = fp.p - 1;
                }
                let cw = shoup_quotients(fp.p, &c);
                for a in [0, 1, 12345, fp.p - 1] {
                    let want: Vec<u64> = acc
                        .iter()
                        .zip(&c)
                        .map(|(&y, &x)| fp.add(y, fp.mul(a, x)))
                        .collect();
                    let mut got = acc.clone();
                    axpy_shoup(fp.p, &mut got, a, &c, &cw);
                    assert_eq!(got, want, "p = {}, n = {n}, a = {a}", fp.p);
                    let mut plain = acc.clone();
                    axpy_shoup_generic(fp.p, &mut plain, a, &c, &cw);
                    assert_eq!(plain, want);
                }
            }
        }
    }

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
            assert_eq!(dot_generic(&fp, &a, &b), want);
            let mut acc = b.clone();
            axpy_lazy(&fp, &mut acc, 12345, &a);
            axpy_lazy(&fp, &mut acc, fp.p - 1, &a);
            for i in 0..n {
                let w = fp.add(b[i], fp.mul(12344, a[i]));
                assert_eq!(fp.reduce(acc[i]), w);
            }
        }
    }

    /// The vectorised reduction equals Barrett's on random lazy entries and
    /// at the extremes (0, multiples of p, `p² − 1`), for several primes.
    #[test]
    fn reduce_to_u32_agrees_with_barrett() {
        let mut seed = 77u64;
        for k in [0usize, 1, 40, 5000] {
            let fp = Fp::new(prime31(k));
            let p = fp.p;
            let mut x: Vec<u64> = (0..1000)
                .map(|_| {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    seed % fp.p2
                })
                .collect();
            x.extend([
                0,
                1,
                p - 1,
                p,
                p + 1,
                2 * p,
                3 * p - 1,
                (p - 1) * p,
                fp.p2 - 1,
            ]);
            let want: Vec<u32> = x.iter().map(|&v| fp.reduce(v) as u32).collect();
            assert_eq!(reduce_to_u32(&fp, &x), want, "p = {p}");
            assert_eq!(reduce_to_u32_generic(&fp, &x), want, "p = {p}");
        }
        // a small prime takes Barrett's reduction (p² − 1 ≡ p − 1)
        let small = Fp::new(1_000_003);
        assert_eq!(
            reduce_to_u32(&small, &[small.p2 - 1, 5]),
            vec![1_000_002, 5]
        );
    }

    /// The split sums of [`dot`] at their largest: every entry `p − 1`.
    #[test]
    fn dot_of_the_largest_entries() {
        for k in [0usize, 5] {
            let fp = Fp::new(prime31(k));
            for n in [1usize, 3, 4, 1001, 100_003] {
                let a = vec![fp.p - 1; n];
                // (p − 1)² = 1 (mod p)
                assert_eq!(dot(&fp, &a, &a), n as u64 % fp.p);
                assert_eq!(dot_generic(&fp, &a, &a), n as u64 % fp.p);
            }
        }
    }

    /// `solve_columns` solves: `K·x = r` holds for every right-hand side,
    /// and a singular matrix gives `None`.
    #[test]
    fn solve_columns_solves() {
        let fp = Fp::new(prime31(1));
        let mut seed = 11;
        for n in [1usize, 3, 20, 41] {
            let k: Vec<Vec<u64>> = (0..n).map(|_| rand_vec(&mut seed, n, fp.p)).collect();
            let rhs: Vec<Vec<u64>> = (0..3).map(|_| rand_vec(&mut seed, n, fp.p)).collect();
            let sol = solve_columns(&fp, &k, &rhs).expect("random matrices are invertible");
            for (r, x) in rhs.iter().zip(&sol) {
                let cols: Vec<u32> = k.iter().flatten().map(|&v| v as u32).collect();
                assert_eq!(&mat_vec(&fp, &cols, n, x), r);
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
    use crate::number::prime31::prime31;

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
