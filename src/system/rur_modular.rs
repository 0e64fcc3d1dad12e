//! Zero-dimensional systems in x, y, z by multi-modular computation with an
//! exact certificate: a Gröbner basis modulo 31-bit primes (F4,
//! [`crate::system::groebner_modp`]), the rational univariate representation modulo each
//! prime with a *polynomial* separating element `h`, Chinese remaindering
//! and rational reconstruction until the images stabilise, and then an exact
//! verification over Z of both directions:
//!
//! * **soundness** — every root τ of the reconstructed `D(u)` gives a common
//!   zero `ξ(τ) = (Gx(τ), Gy(τ), Gz(τ))/Φ(τ)` of the generators with
//!   `h(ξ(τ)) = τ`: `D` is square-free (so `Φ = c·D′` is invertible modulo
//!   `D`) and `D` divides the homogenised compositions
//!   `P^h(Gx, Gy, Gz, Φ)` of every generator `P` and
//!   `h^h(Gx, Gy, Gz, Φ) − u·Φ^deg h` in Z[u] (exact division, or a
//!   multi-modular quotient that is proven by a size bound);
//! * **completeness** — no zero is missing: for a prime p where the
//!   leading forms of the generators have no common projective zero, the
//!   number of standard monomials of the leading monomials of polynomials
//!   computed in `I_p` bounds `dim_Q Q[x]/I` from above (docs/maths.md); when
//!   it equals `deg D`, the `deg D` distinct verified zeros are all of them.
//!   When the leading forms share a zero at infinity modulo every prime
//!   tried (e.g. `S = x⁵y + …`, whose top form is singular along `x = 0`),
//!   the bound is `dim_Q Q[x]/I` from the reduced Gröbner basis over Q,
//!   computed once (it is cheap next to the Krylov step of the exact route).
//!
//! Nothing computed modulo p is trusted: a wrong or premature reconstruction
//! fails the exact checks and the caller falls back to the exact route.

use super::rur_check::{Check, CheckFailure, vanish_on_roots};
use crate::number::Q;
use crate::number::modkernel::{mat_vec, mulmod, solve_columns};
use crate::number::prime31::{CrtVec, Fp, prime31};
use crate::number::reconstruct::{rational_reconstruction, reconstruct_common};
use crate::poly::mpoly::{X, Y, Z};
use crate::poly::{QMPoly, ZMPoly, ZPoly};
use crate::roots::RealAlg;
use crate::system::groebner_modp::{
    ModPoly, ModQuotient, Mono, groebner_mod, mono, standard_monomials_of, zmpoly_mod,
};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Why the modular route gave no result (never a verdict: the caller falls
/// back to the exact route).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Declined(pub String);

/// How completeness was proven.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CountCertificate {
    /// The prime p where the leading forms have no common zero at infinity;
    /// `None` when they have one modulo every prime tried and the bound is
    /// `dim_Q Q[x]/I` from the reduced Gröbner basis over Q.
    pub prime: Option<u64>,
    /// The number of standard monomials of the leading monomials found in
    /// `I_p` (of the basis over Q when `prime` is `None`): an upper bound
    /// on the number of complex zeros over Q.
    pub bound: usize,
}

/// A verified rational univariate representation with respect to a
/// polynomial separating element `h`: the zeros of the system are exactly
/// `ξ(τ) = (coords[0](τ), coords[1](τ), coords[2](τ)) / denom(τ)` over the
/// roots τ of `f`, and `h(ξ(τ)) = τ`.
#[derive(Clone, Debug)]
pub struct ModularRur {
    /// Which of the candidate separating elements `h` was used.
    pub separating: usize,
    /// `f(u)`: primitive, square-free, of degree = the number of zeros; its
    /// roots are the values of `h` at the zeros (each taken once).
    pub f: ZPoly,
    /// The numerators of x, y, z.
    pub coords: [ZPoly; 3],
    /// The common denominator `Φ`, a constant multiple of `f′`.
    pub denom: ZPoly,
    /// The number of primes of the reconstruction.
    pub primes: usize,
    /// Completeness: the counting certificate.
    pub count: CountCertificate,
    /// The real roots of `f`, increasing (one per real zero).
    pub real_roots: Vec<RealAlg>,
    /// The generator (index into `gens`) whose check was left out because it
    /// is implied (see [`solve_modular_implied`]), with the linear form whose
    /// composition was proven coprime to `f`.
    pub implied: Option<usize>,
}

impl ModularRur {
    /// Number of zeros.
    pub fn points(&self) -> usize {
        self.f.degree().unwrap_or(0)
    }

    /// A rational approximation of the real zero number `i`: the coordinates
    /// at a `2^-bits` approximation of its τ, rounded down to dyadics with
    /// `bits + 16` fractional bits (`None` if the denominator vanishes there).
    pub fn approx_point(&self, i: usize, bits: u32) -> Option<[Q; 3]> {
        let t = self.real_roots[i].to_rational_approx(bits);
        let (dn, dd) = self.denom.eval_homogeneous(t.numer(), t.denom());
        if dn.is_zero() {
            return None;
        }
        Some(std::array::from_fn(|k| {
            // eval_homogeneous gives (value·d^N, d^N): the ratio is exact
            let (n, d) = self.coords[k].eval_homogeneous(t.numer(), t.denom());
            let (mut num, mut den) = (n * &dd, d * &dn);
            if den.is_negative() {
                num = -num;
                den = -den;
            }
            crate::number::dyadic_floor(&num, &den, bits as usize + 16)
        }))
    }
}

/// The images modulo one prime.
struct Image {
    lms: Vec<Mono>,
    /// `f_0 … f_(N−1)` (f monic), then the Kronecker numerators of x, y, z.
    residues: Vec<u64>,
}

enum ImageFail {
    /// No common zero modulo p.
    Unit,
    /// Infinitely many zeros modulo p.
    NotZeroDimensional,
    /// No linear form gave a cyclic quotient (not radical modulo p).
    NotRadical,
    /// `h` does not separate the zeros modulo p.
    NotSeparating,
    /// A degree beyond the F4 limit.
    TooLarge,
}

/// The RUR modulo p with respect to the first of `hs` that separates the
/// zeros (only `hs[i]` when `fixed = Some(i)`): the minimal polynomial `f`
/// of `h` on the quotient and the Kronecker numerators
/// `G_v = v(u)·f′(u) mod f`.  Returns the index of the element used.
fn image_mod_p(
    fp: &Fp,
    gens: &[ModPoly],
    hs: &[ModPoly],
    fixed: Option<usize>,
) -> Result<(usize, Image), ImageFail> {
    let gb = groebner_mod(fp, gens).ok_or(ImageFail::TooLarge)?;
    if gb.is_unit() {
        return Err(ImageFail::Unit);
    }
    let quo = ModQuotient::new(&gb).ok_or(ImageFail::NotZeroDimensional)?;
    let n = quo.dim();
    let nf_h = gb.normal_forms(hs);
    let hv: Vec<Vec<u64>> = nf_h
        .iter()
        .map(|p| quo.coords(p).expect("normal forms are on the basis"))
        .collect();
    let one = 0; // the basis is increasing: 1 comes first
    let mut e1 = vec![0u64; n];
    e1[one] = 1;
    let xs: Vec<Vec<u64>> = (0..3)
        .map(|v| quo.mult[v][one].iter().map(|&c| c as u64).collect())
        .collect();
    // a separating linear form t = x + a·y + b·z gives A ≅ F_p[T]/(m_t)
    let mut kp = None;
    for (a, b) in [(12345u64, 678), (31, 1_000_003), (7_777_777, 2)] {
        let cols = quo.combined_columns(fp, [1, a, b]);
        let mut kry = Vec::with_capacity(n + 1);
        kry.push(e1.clone());
        for _ in 0..n {
            crate::budget::check();
            let next = mat_vec(fp, &cols, n, kry.last().expect("non-empty"));
            kry.push(next);
        }
        let top = kry.pop().expect("n + 1 vectors");
        let mut rhs = vec![top, xs[0].clone(), xs[1].clone(), xs[2].clone()];
        rhs.extend(hv.iter().cloned());
        if let Some(sol) = solve_columns(fp, &kry, &rhs) {
            kp = Some(sol);
            break;
        }
    }
    let sol = kp.ok_or(ImageFail::NotRadical)?;
    // in K_p = F_p[T]/(m_t): T^n = Σ c_j T^j; U = h(T)
    let c = &sol[0];
    let choices: Vec<usize> = match fixed {
        Some(i) => vec![i],
        None => (0..hs.len()).collect(),
    };
    for hi in choices {
        let u = &sol[4 + hi];
        let mut pows: Vec<Vec<u64>> = Vec::with_capacity(n + 1);
        let mut cur = e1.clone();
        for _ in 0..=n {
            crate::budget::check();
            let next = mulmod(fp, &cur, u, c);
            pows.push(cur);
            cur = next;
        }
        let top = pows.pop().expect("n + 1 powers");
        let rhs = vec![top, sol[1].clone(), sol[2].clone(), sol[3].clone()];
        let Some(s2) = solve_columns(fp, &pows, &rhs) else {
            continue;
        };
        // f(u) = u^n − Σ s2[0]_j u^j, monic; store f_j = −s2[0]_j
        let fc = &s2[0];
        let f_low: Vec<u64> = fc.iter().map(|&x| fp.neg(x)).collect();
        // f′(u) = n u^(n−1) + Σ j f_j u^(j−1)
        let mut fd = vec![0u64; n];
        for j in 1..n {
            fd[j - 1] = fp.mul(j as u64 % fp.p, f_low[j]);
        }
        fd[n - 1] = n as u64 % fp.p;
        // h generates A (its powers span it): f is square-free iff A is
        // reduced, so a repeated factor means the ideal is not radical
        // modulo p (a multiple critical point), which no number of primes
        // would cure
        let mut f_full = f_low.clone();
        f_full.push(1);
        if crate::poly::modp::poly_gcd_mod(fp, &f_full, &fd).len() > 1 {
            return Err(ImageFail::NotRadical);
        }
        let mut residues = f_low;
        for coords in &s2[1..4] {
            residues.extend(mulmod(fp, coords, &fd, fc));
        }
        return Ok((
            hi,
            Image {
                lms: gb.leading(),
                residues,
            },
        ));
    }
    Err(ImageFail::NotSeparating)
}

/// A rational polynomial modulo p (`None` when a denominator vanishes).
fn qmpoly_mod(fp: &Fp, p: &QMPoly) -> Option<ModPoly> {
    let mut out: ModPoly = Vec::with_capacity(p.len());
    for (e, c) in p.terms() {
        let d = fp.reduce_big(c.denom());
        let n = fp.reduce_big(c.numer());
        out.push((mono(e[X], e[Y], e[Z]), fp.mul(n, fp.inv(d)?) as u32));
    }
    crate::system::groebner_modp::normalize(&mut out);
    Some(out)
}

/// The homogeneous part of highest degree.
fn leading_form(p: &ZMPoly) -> ZMPoly {
    let d = p.total_degree().unwrap_or(0);
    ZMPoly::from_terms(
        p.terms()
            .iter()
            .filter(|(e, _)| e.iter().sum::<u32>() == d)
            .cloned(),
    )
}

/// True when the leading forms have no common zero in P²(F̄_p): their
/// ideal modulo p contains a pure power of each variable.
fn no_zeros_at_infinity(fp: &Fp, gens: &[ZMPoly]) -> bool {
    let forms: Vec<ModPoly> = gens
        .iter()
        .map(|g| zmpoly_mod(fp, &leading_form(g)))
        .collect();
    match groebner_mod(fp, &forms) {
        Some(gb) => gb.is_unit() || standard_monomials_of(&gb.leading()).is_some(),
        None => false,
    }
}

/// The candidate over Q: `f = u^n + Σ nums[j] u^j / den` (monic) and the
/// numerators `G_v = Σ nums[n(v+1) + j] u^j / den`.
struct Candidate {
    n: usize,
    nums: Vec<BigInt>,
    den: BigInt,
}

fn candidate_of(values: &[BigInt], m: &BigInt, n: usize) -> Option<Candidate> {
    let (nums, den) = reconstruct_common(values, m)?;
    Some(Candidate { n, nums, den })
}

/// Does the candidate reduce to the residues modulo another prime?
fn agrees_mod(fp: &Fp, cand: &Candidate, residues: &[u64]) -> bool {
    let Some(di) = fp.inv(fp.reduce_big(&cand.den)) else {
        return false;
    };
    cand.nums
        .iter()
        .zip(residues)
        .all(|(x, &r)| fp.mul(fp.reduce_big(x), di) == r)
}

/// The exact checks of a candidate: soundness of every zero, returned as
/// the integer form `(f, [Gx, Gy, Gz], Φ)` when all pass.
/// The composition `K^h(G, Φ) = k_x·G_x + k_y·G_y + k_z·G_z + k_0·Φ` of a
/// linear form `K`, over Z (`K` made primitive first).
fn compose_linear(k: &QMPoly, gs: &[ZPoly; 3], phi: &ZPoly) -> ZPoly {
    let (kz, _) = k.to_primitive_z();
    let mut acc = ZPoly::zero();
    for (e, c) in kz.terms() {
        let part = match (e[X], e[Y], e[Z]) {
            (1, 0, 0) => &gs[0],
            (0, 1, 0) => &gs[1],
            (0, 0, 1) => &gs[2],
            _ => phi,
        };
        acc = &acc + &part.scale(c);
    }
    acc
}

/// Verifies a candidate; `implied` as in [`solve_modular_implied`] (indices
/// into `gens`).  Returns `f`, the coordinates, `Φ` and the generator whose
/// check was left out.
#[allow(clippy::type_complexity)]
fn verify(
    gens: &[ZMPoly],
    h: &QMPoly,
    cand: &Candidate,
    implied: &[(usize, QMPoly)],
) -> Result<(ZPoly, [ZPoly; 3], ZPoly, Option<usize>), String> {
    let n = cand.n;
    // f = (nums_f + Δ·u^n)/Δ, x_v = G_v/f′ = nums_v/(Δ·f′)
    let mut fz = cand.nums[..n].to_vec();
    fz.push(cand.den.clone());
    let f_scaled = ZPoly::new(fz);
    let phi = f_scaled.derivative();
    let gs: [ZPoly; 3] =
        std::array::from_fn(|k| ZPoly::new(cand.nums[n * (k + 1)..n * (k + 2)].to_vec()));
    let f = f_scaled.primitive_part();
    if f.degree() != Some(n) {
        return Err("degree of the reconstructed polynomial".into());
    }
    // remove the common content of the numerators and Φ
    let mut g_all = phi.content();
    for g in &gs {
        g_all = g_all.gcd(&g.content());
    }
    let (phi, gs) = if g_all.is_one() || g_all.is_zero() {
        (phi, gs)
    } else {
        let dv = |p: &ZPoly| ZPoly::new(p.coeffs().iter().map(|c| c / &g_all).collect());
        (dv(&phi), std::array::from_fn(|k| dv(&gs[k])))
    };
    if f.gcd(&f.derivative()).degree() != Some(0) {
        return Err("the reconstructed polynomial is not square-free".into());
    }
    // a generator implied by the others where the linear form K is non-zero:
    // K ≠ 0 at every root iff gcd(f, K^h(G, Φ)) = 1 (Φ ≠ 0 there)
    let skip = implied.iter().find_map(|(i, k)| {
        let comp = compose_linear(k, &gs, &phi);
        (!comp.is_zero() && f.gcd(&comp).degree() == Some(0)).then_some(*i)
    });
    let mut checks: Vec<Check> = gens
        .iter()
        .enumerate()
        .filter(|(i, _)| Some(*i) != skip)
        .map(|(_, g)| Check {
            p: g.clone(),
            k: g.total_degree().unwrap_or(0),
            u_coef: BigInt::zero(),
        })
        .collect();
    // hk·hz(ξ) = u:  hk_n·hz^h(G, Φ) − hk_d·u·Φ^kh ≡ 0 (mod f)
    let (hz, hk) = h.to_primitive_z();
    checks.push(Check {
        k: hz.total_degree().unwrap_or(0),
        p: hz.scale(hk.numer()),
        u_coef: hk.denom().clone(),
    });
    let h_check = checks.len() - 1;
    match vanish_on_roots(&f, &gs, &phi, &checks) {
        Ok(()) => Ok((f, gs, phi, skip)),
        Err(CheckFailure::NotDivisible(i)) | Err(CheckFailure::Undecided(i)) if i == h_check => {
            Err("the separating element does not take the value u".into())
        }
        Err(e) => Err(format!("generator check failed: {e:?}")),
    }
}

/// Solves the zero-dimensional system `gens = 0` (in x, y, z) with the
/// separating element `h`, multi-modularly, with exact verification (see
/// the module documentation).  `Err` says why no verified answer was found
/// (the caller then uses the exact route): the system is not
/// zero-dimensional, not radical, `h` does not separate its zeros, there
/// are zeros at infinity modulo every prime tried, or the reconstruction
/// did not verify within `max_primes`.
#[cfg(test)]
pub fn solve_modular(
    gens: &[QMPoly],
    hs: &[QMPoly],
    max_primes: usize,
) -> Result<ModularRur, Declined> {
    solve_modular_implied(gens, hs, max_primes, &[])
}

/// [`solve_modular`], where the caller knows identities `Σ K_j·gens_j = 0`
/// with linear `K_j`: each `(j, K_j)` of `implied` says that `gens_j`
/// vanishes wherever the other generators vanish and `K_j ≠ 0`.  The first
/// `K_j` proven non-zero at every verified zero (its composition is coprime
/// to `f`) lets the verification leave out the check of `gens_j`, the most
/// expensive part of the route.
pub fn solve_modular_implied(
    gens: &[QMPoly],
    hs: &[QMPoly],
    max_primes: usize,
    implied: &[(usize, QMPoly)],
) -> Result<ModularRur, Declined> {
    let kept: Vec<usize> = (0..gens.len()).filter(|&i| !gens[i].is_zero()).collect();
    let zgens: Vec<ZMPoly> = kept.iter().map(|&i| gens[i].to_primitive_z().0).collect();
    // the implied relations in the indices of zgens
    let implied_z: Vec<(usize, QMPoly)> = implied
        .iter()
        .filter_map(|(j, k)| Some((kept.iter().position(|i| i == j)?, k.clone())))
        .collect();
    let maxdeg = zgens
        .iter()
        .map(|g| g.total_degree().unwrap_or(0))
        .chain(hs.iter().filter_map(|h| h.total_degree()))
        .max()
        .unwrap_or(0);
    if maxdeg > crate::system::groebner_modp::MAX_DEGREE / 4 {
        return Err(Declined("degree too large for the modular route".into()));
    }
    let decline = |s: &str| Err(Declined(s.into()));
    let mut reference: Option<(Vec<Mono>, CrtVec)> = None;
    let mut count: Option<CountCertificate> = None;
    let mut candidate: Option<Candidate> = None;
    let mut probe: Option<(BigInt, BigInt)> = None;
    let (mut next_probe, mut next_full) = (0u64, 0u64);
    let (mut unlucky, mut fails) = (0usize, 0usize);
    let mut tried_count = 0usize;
    let mut exact_tried = false;
    // the separating element, fixed at the first prime that has one
    let mut chosen: Option<usize> = None;
    for k in 0..max_primes {
        crate::budget::check_now();
        let fp = Fp::new(prime31(k));
        let Some(hp) = hs
            .iter()
            .map(|h| qmpoly_mod(&fp, h))
            .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let gp: Vec<ModPoly> = zgens.iter().map(|g| zmpoly_mod(&fp, g)).collect();
        let img = match image_mod_p(&fp, &gp, &hp, chosen) {
            Ok((i, img)) => {
                chosen = Some(i);
                img
            }
            Err(e) => {
                fails += 1;
                if fails >= 2 {
                    return decline(match e {
                        ImageFail::Unit => "no common zero modulo two primes",
                        ImageFail::NotZeroDimensional => {
                            "infinitely many zeros (curves of critical points)"
                        }
                        ImageFail::NotRadical => "the ideal is not radical",
                        ImageFail::NotSeparating => {
                            "the separating element takes equal values at distinct zeros"
                        }
                        ImageFail::TooLarge => "degree too large for the modular route",
                    });
                }
                continue;
            }
        };
        let n = img.residues.len() / 4;
        match &mut reference {
            Some((lms, _)) if *lms == img.lms => {}
            Some((lms, _)) => {
                unlucky += 1;
                let smaller = standard_monomials_of(&img.lms)
                    .map(|s| s.len())
                    .unwrap_or(usize::MAX)
                    < standard_monomials_of(lms)
                        .map(|s| s.len())
                        .unwrap_or(usize::MAX);
                if unlucky > 4 {
                    return decline("the leading monomials differ from prime to prime");
                }
                if !smaller {
                    continue;
                }
                reference = None;
                count = None;
                candidate = None;
                probe = None;
                (next_probe, next_full) = (0, 0);
            }
            None => {}
        }
        let (_, crt) = reference.get_or_insert_with(|| (img.lms.clone(), CrtVec::new(4 * n)));
        if count.is_none() && tried_count < 4 {
            tried_count += 1;
            if no_zeros_at_infinity(&fp, &zgens) {
                count = Some(CountCertificate {
                    prime: Some(fp.p),
                    bound: n,
                });
            }
        }
        if let Some(c) = &candidate {
            if agrees_mod(&fp, c, &img.residues) {
                // zeros at infinity modulo every prime tried: the count of
                // the basis over Q instead (once; cheap next to the exact
                // route that would run otherwise)
                if count.is_none() && !exact_tried {
                    exact_tried = true;
                    count = super::rur_groebner::quotient_dimension(gens)
                        .map(|bound| CountCertificate { prime: None, bound });
                }
                let Some(cc) = count.clone() else {
                    return decline(
                        "zeros at infinity modulo every prime tried, and infinitely many zeros over Q",
                    );
                };
                let c = candidate.take().expect("present");
                let hi = chosen.expect("an image was computed");
                match verify(&zgens, &hs[hi], &c, &implied_z) {
                    Ok((f, coords, denom, skipped)) => {
                        if f.degree() != Some(cc.bound) {
                            return decline("the verified zeros do not reach the counting bound");
                        }
                        let real_roots = RealAlg::roots_of(&f);
                        return Ok(ModularRur {
                            separating: hi,
                            f,
                            coords,
                            denom,
                            primes: crt.primes(),
                            count: cc,
                            real_roots,
                            implied: skipped.map(|z| kept[z]),
                        });
                    }
                    Err(_) => {
                        probe = None;
                        let mb = crt.modulus_bits();
                        next_probe = mb + (mb / 8).max(31);
                        next_full = next_probe;
                    }
                }
            } else {
                candidate = None;
                probe = None;
            }
        }
        // the probe (the constant coefficient of f) against this prime
        let probe_ok = probe.as_ref().is_some_and(|(pn, pd)| {
            fp.inv(fp.reduce_big(pd))
                .is_some_and(|di| fp.mul(fp.reduce_big(pn), di) == img.residues[0])
        });
        if !probe_ok {
            probe = None;
        }
        crt.push(&fp, &img.residues);
        let mb = crt.modulus_bits();
        crate::budget::check_size("modular RUR", 4 * n, mb);
        // rational reconstruction is tried on a geometric schedule: first
        // the probe alone; once it agrees with a further prime, everything
        if probe_ok && candidate.is_none() && mb >= next_full {
            crt.flush();
            candidate = candidate_of(crt.values(), crt.modulus(), n);
            if candidate.is_none() {
                next_full = mb + (mb / 8).max(31);
            }
        }
        if probe.is_none() && mb >= next_probe {
            crt.flush();
            probe = rational_reconstruction(&crt.values()[0], crt.modulus());
            if probe.is_none() {
                next_probe = mb + (mb / 8).max(31);
            }
        }
    }
    decline("the reconstruction did not stabilise within the prime limit")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn critical_system(e: &str, s: &str) -> (Vec<QMPoly>, QMPoly) {
        let e = parse_poly(e).unwrap();
        let s = parse_poly(s).unwrap();
        let gs = [s.derivative(X), s.derivative(Y), s.derivative(Z)];
        let ge = [e.derivative(X), e.derivative(Y), e.derivative(Z)];
        let c = [
            &(&gs[1] * &ge[2]) - &(&gs[2] * &ge[1]),
            &(&gs[2] * &ge[0]) - &(&gs[0] * &ge[2]),
            &(&gs[0] * &ge[1]) - &(&gs[1] * &ge[0]),
        ];
        (vec![e, c[0].clone(), c[1].clone(), c[2].clone()], s)
    }

    #[test]
    fn modular_rur_agrees_with_the_exact_rur() {
        for (e, s) in [
            ("x^2+2y^2+3z^2+x*z-6", "x^3 - 2x*y + z^2 + y*z - 1"),
            ("2x^2+y^2+3z^2+x*y-y*z-7", "x^3+y^3-z^3+x*z-2y+1"),
        ] {
            let (gens, s) = critical_system(e, s);
            let m = solve_modular(&gens, std::slice::from_ref(&s), 500).unwrap();
            let exact = super::super::solve_zero_dim(&gens, std::slice::from_ref(&s))
                .unwrap()
                .unwrap();
            assert_eq!(m.points(), exact.points);
            // the same critical values: f is the value polynomial
            assert_eq!(m.f, exact.extra_values[0]);
            assert_eq!(m.real_roots.len(), exact.real_roots.len());
        }
    }

    /// S singular at points of E (`∇S = 0` where `xy = ±1/√3, z = 0`, to
    /// fifth order in z): multiple critical points. The cyclic algebra
    /// modulo p gives a non-square-free f, which is declined at once
    /// (it once reconstructed the same non-square-free candidate until the
    /// prime limit).
    #[test]
    fn multiple_critical_points_are_declined_as_not_radical() {
        let (gens, s) = critical_system("3x^2+y^2+2z^2+x*y-4", "x^3*y^3+z^6-x*y+1");
        let shifted = &s + &parse_poly("x/3+2y/3+z").unwrap();
        let err = solve_modular(&gens, &[s, shifted], 500).unwrap_err();
        assert_eq!(err.0, "the ideal is not radical");
    }

    #[test]
    fn an_implied_minor_is_left_out_and_the_answer_is_the_same() {
        let (e, s) = ("2x^2+y^2+3z^2+x*y-y*z-7", "x^3+y^3-z^3+x*z-2y+1");
        let (gens, s) = critical_system(e, s);
        let ep = parse_poly(e).unwrap();
        let implied: Vec<(usize, QMPoly)> = (0..3)
            .map(|j| (j + 1, ep.derivative([X, Y, Z][j])))
            .collect();
        let full = solve_modular(&gens, std::slice::from_ref(&s), 500).unwrap();
        let short = solve_modular_implied(&gens, std::slice::from_ref(&s), 500, &implied).unwrap();
        assert_eq!(full.implied, None);
        assert_eq!(
            short.implied,
            Some(1),
            "E_x is non-zero at every critical point"
        );
        assert_eq!((short.f, short.coords), (full.f, full.coords));
    }

    #[test]
    fn a_form_that_vanishes_at_a_zero_leaves_nothing_out() {
        // zeros (±√2, 1, ±√2); h = x + 3y + 5z separates them
        let gens: Vec<QMPoly> = ["x^2-2", "y-1", "z-x"]
            .map(|g| parse_poly(g).unwrap())
            .to_vec();
        let h = parse_poly("x+3y+5z").unwrap();
        let hs = std::slice::from_ref(&h);
        let at = |k: &str| {
            solve_modular_implied(&gens, hs, 200, &[(2, parse_poly(k).unwrap())])
                .unwrap()
                .implied
        };
        assert_eq!(at("x"), Some(2), "x ≠ 0 at both zeros");
        assert_eq!(at("y-1"), None, "y − 1 vanishes at the zeros");
        assert_eq!(at("x-z+1/2*y-1/2"), None, "vanishes at both zeros");
        assert_eq!(at("0"), None);
    }

    #[test]
    fn symmetric_systems_are_declined_not_guessed() {
        // S and E even in z: the critical points (x, y, ±z) share their value
        let (gens, s) = critical_system("x^2+2y^2+3z^2-6", "x^3 - 2x*y + z^2 - 1");
        let d = solve_modular(&gens, std::slice::from_ref(&s), 100).unwrap_err();
        assert!(d.0.contains("equal values"), "{d:?}");
    }
}
