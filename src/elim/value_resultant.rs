//! The values of a rational function at the roots of a univariate
//! polynomial, as one resultant: `Res_λ(φ(λ), sd·u·den(λ) − sn·num(λ))`,
//! whose roots in u are `(sn/sd)·num(λ)/den(λ)` over the roots λ of φ.
//!
//! Key idea (Poisson's product formula for resultants): modulo a word
//! prime p the resultant is `lc(φ)^k·Res(φ, den)` times the characteristic
//! polynomial of the multiplication by `num/den` in `F_p[λ]/(φ)` — linear
//! algebra in word arithmetic ([`crate::poly::modp`]) instead of a
//! determinant of polynomials — and the Chinese remainder theorem up to
//! Hadamard's bound on the Sylvester matrix gives it exactly: no
//! verification step.

use crate::number::prime31::{BlockResidues, CrtVec, Fp, prime31};
use crate::poly::ZPoly;
use crate::poly::modp::{ModAlgebra, rem_mod, resultant_mod};
use num_bigint::BigInt;
use num_traits::Signed;

/// `Res_λ(φ(λ), sd·u·den(λ) − sn·num(λ))` exactly, for `φ` of degree
/// n ≥ 1 and integer `num`, `den` (not zero), by the CRT over word primes
/// up to Hadamard's bound on the Sylvester matrix (L1 norms of the rows):
/// modulo p it is `lc(φ)^(k − deg den)·Res(φ, den)·Σ_i sn^(n−i)·sd^i·χ_i·u^i`,
/// k = max(deg num, deg den) and χ the characteristic polynomial of the
/// multiplication by `num/den` in `F_p[λ]/(φ)` (Poisson's formula, ∏ over
/// the roots of φ of `sd·den·u − sn·num`).  `None` when `Res(φ, den)`
/// vanishes modulo the first primes (den vanishes at a root of φ, or is
/// likely to), so that the caller's general resultant runs instead.
pub(crate) fn value_resultant(
    phi: &ZPoly,
    num: &ZPoly,
    den: &ZPoly,
    sn: &BigInt,
    sd: &BigInt,
) -> Option<ZPoly> {
    let n = phi.degree().filter(|&n| n >= 1)?;
    let (dn, dd) = (num.degree()?, den.degree()?);
    let k = dn.max(dd);
    let l1 = |p: &ZPoly| -> BigInt { p.coeffs().iter().map(|c| c.abs()).sum() };
    let g1 = sd.abs() * l1(den) + sn.abs() * l1(num);
    let bound = k as u64 * l1(phi).bits() + n as u64 * g1.bits();
    crate::budget::check_size("a resultant", n + 1, bound);
    let ints: Vec<&BigInt> = [phi, num, den]
        .iter()
        .flat_map(|p| p.coeffs())
        .chain([sn, sd])
        .collect();
    let mut blocks = BlockResidues::new(ints);
    let mut crt = CrtVec::new(n + 1);
    let mut degenerate = 0usize;
    for j in 0..MAX_VALUE_PRIMES {
        crate::budget::check_now();
        if crt.modulus_bits() > bound + 1 {
            return Some(ZPoly::new(crt.symmetric_values()));
        }
        let fp = Fp::new(prime31(j));
        let all = blocks.residues(j, &fp);
        let (fm, rest) = all.split_at(n + 1);
        let (nm, rest) = rest.split_at(dn + 1);
        let (dm, rest) = rest.split_at(dd + 1);
        let (snp, sdp) = (rest[0], rest[1]);
        if fm[n] == 0 || nm[dn] == 0 || dm[dd] == 0 || snp == 0 || sdp == 0 {
            continue;
        }
        let res = resultant_mod(&fp, fm, dm);
        if res == 0 {
            degenerate += 1;
            if crt.primes() == 0 && degenerate >= 4 {
                return None;
            }
            continue;
        }
        let alg = ModAlgebra::from_poly(fp, fm)?;
        let reduce = |a: &[u64]| -> Vec<u64> {
            let mut r = rem_mod(&fp, a, fm);
            r.resize(n, 0);
            r
        };
        // den is invertible modulo φ_p: their resultant is not zero
        let dinv = alg.inv(&reduce(dm))?;
        let chi = alg.charpoly(&alg.mul(&reduce(nm), &dinv));
        let mut c = fp.mul(fp.pow(fm[n], (k - dd) as u64), res);
        // c·sn^(n−i)·sd^i from i = 0 up
        c = fp.mul(c, fp.pow(snp, n as u64));
        let ratio = fp.mul(sdp, fp.inv(snp).expect("non-zero"));
        let mut out = vec![0u64; n + 1];
        for (o, &x) in out.iter_mut().zip(&chi) {
            *o = fp.mul(c, x);
            c = fp.mul(c, ratio);
        }
        crt.push(&fp, &out);
    }
    None
}

/// The largest number of primes of [`value_resultant`].
const MAX_VALUE_PRIMES: usize = 200_000;
