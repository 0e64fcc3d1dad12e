//! Zero-dimensional polynomial systems in x, y, z, solved exactly: a
//! Gröbner basis, the radical (Seidenberg), a separating linear form and the
//! rational univariate representation; the real zeros are the real roots of
//! the RUR's univariate polynomial (the form separates conjugate zeros).

use crate::error::Error;
use crate::number::{Q, qi};
use crate::poly::mpoly::{MPoly, X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZMPoly, ZPoly};
use crate::roots::RealAlg;
use crate::system::groebner::{GPoly, MonoOrder, groebner};
use crate::system::quotient::{
    QMatrix, Quotient, krylov_full_likely, krylov_shape, mat_comb, mat_vec,
    minpoly_and_squarefree_image,
};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// A rational univariate representation of the zeros of a radical
/// zero-dimensional system in x, y, z.
#[derive(Clone, Debug)]
pub struct Rur {
    /// Dimension of the quotient of the original ideal (zeros with
    /// multiplicity).
    pub multiplicity_dim: usize,
    /// Number of distinct zeros.
    pub points: usize,
    /// The separating form `t = c0·x + c1·y + c2·z`.
    pub form: [Q; 3],
    /// `f(t)`: square-free, its roots are the values of `t` at the zeros.
    pub f: ZPoly,
    /// `x, y, z` as polynomials in `t` (degree < deg f).
    pub coords: [QPoly; 3],
    /// The same as `k·P(t)` with `P` a primitive integer polynomial (see
    /// [`ZPoly::from_q`]), for fast evaluation.
    pub coords_z: [(ZPoly, Q); 3],
    /// Extra polynomials (e.g. S) as polynomials in `t`.
    pub extra: Vec<QPoly>,
    /// For each extra polynomial `p`, the square-free integer polynomial
    /// whose roots are exactly the values `p(ξ)` at the zeros ξ (complex
    /// ones included): the minimal polynomial of multiplication by `p` on
    /// the (radical) quotient algebra.
    pub extra_values: Vec<ZPoly>,
    /// The real roots of `f`, increasing: one per real zero.
    pub real_roots: Vec<RealAlg>,
    /// True when the ideal had to be made radical.
    pub made_radical: bool,
}

const SLOTS: [usize; 3] = [X, Y, Z];

/// Linear forms `l·(x, y, z)` tried in turn where a generic direction is
/// needed (sweeps and level curves): fixed, so results are reproducible.
pub const GENERIC_FORMS: [[i64; 3]; 5] =
    [[1, 2, 3], [3, -1, 2], [2, 5, -3], [7, 3, 11], [-5, 13, 4]];

fn to_g(p: &QMPoly) -> GPoly {
    GPoly::from_mpoly(p, &SLOTS, MonoOrder::GrevLex)
}

/// `dim_Q Q[x, y, z]/I` for the ideal I of `gens`, from its reduced
/// Gröbner basis over Q (grevlex): an upper bound on the number of complex
/// zeros, exact whatever happens at infinity.  `None` when I has infinitely
/// many zeros.
pub fn quotient_dimension(gens: &[QMPoly]) -> Option<usize> {
    let input: Vec<GPoly> = gens.iter().filter(|g| !g.is_zero()).map(to_g).collect();
    groebner(input, 3, MonoOrder::GrevLex)
        .standard_monomials()
        .map(|b| b.len())
}

/// Solves a zero-dimensional system in x, y, z exactly: `Ok(None)` when the
/// system has infinitely many complex zeros.
pub fn solve_zero_dim(gens: &[QMPoly], extra: &[QMPoly]) -> Result<Option<Rur>, Error> {
    let ord = MonoOrder::GrevLex;
    let input: Vec<GPoly> = gens.iter().filter(|g| !g.is_zero()).map(to_g).collect();
    let gb = groebner(input.clone(), 3, ord);
    if gb.is_unit() {
        return Ok(Some(Rur {
            multiplicity_dim: 0,
            points: 0,
            form: [qi(1), qi(0), qi(0)],
            f: ZPoly::constant(1.into()),
            coords: [QPoly::zero(), QPoly::zero(), QPoly::zero()],
            coords_z: std::array::from_fn(|_| (ZPoly::zero(), Q::zero())),
            extra: extra.iter().map(|_| QPoly::zero()).collect(),
            extra_values: extra.iter().map(|_| ZPoly::constant(1.into())).collect(),
            real_roots: vec![],
            made_radical: false,
        }));
    }
    let Some(mut quo) = Quotient::new(gb) else {
        return Ok(None);
    };
    let multiplicity_dim = quo.dim();
    // Fast path: a form t whose minimal polynomial has degree dim A makes A
    // cyclic, A ≅ Q[T]/(m); then I is radical iff m is square-free, and
    // otherwise Q[x]/√I ≅ Q[T]/(sqfree(m)) (`radical_shape`).  Else fall
    // back to Seidenberg: the minimal polynomials of x, y, z must be
    // square-free, √I = I + (sqfree(m_x)(x), …).
    let mut made_radical = false;
    let mut mats = [quo.var_matrix(0), quo.var_matrix(1), quo.var_matrix(2)];
    let mut rhs = shape_targets(&quo, &mats, extra);
    let mut sq_add: Vec<QMPoly> = Vec::new();
    let mut sq_nf: Vec<QMPoly> = Vec::new();
    let mut cyclic = false;
    let mut ready = None;
    for (a, b) in [(1i64, 1i64), (2, -1), (-1, 3)] {
        let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
        // exact Krylov vectors (long integers) only for a form that makes A
        // cyclic modulo a prime: a non-cyclic A skips all three
        if !krylov_full_likely(&mt, &quo.one()) {
            continue;
        }
        let (mp, sol) = krylov_shape(&mt, &quo.one(), &rhs)?;
        if let Some(sol) = sol {
            cyclic = true;
            let (mz, _) = ZPoly::from_q(&mp);
            let sq = mz.squarefree_part();
            if sq.degree() != mz.degree() {
                // A ≅ Q[T]/(m_t) by x ↦ X(T): the radical's quotient is
                // Q[T]/(sqfree m_t), with the same shape reduced modulo it
                // (no second Gröbner basis, whose generator sqfree(m_t)(t)
                // would be dense of high degree)
                return Ok(Some(radical_shape(
                    [qi(1), qi(a), qi(b)],
                    &sq,
                    sol,
                    multiplicity_dim,
                )));
            }
            ready = Some(([qi(1), qi(a), qi(b)], mp.clone(), sol));
            break;
        }
    }
    if !cyclic {
        for (v, m) in mats.iter().enumerate() {
            if let (_, Some((sq, nf))) = minpoly_and_squarefree_image(m, &quo.one())? {
                sq_add.push(MPoly::from_univariate(&sq.to_q(), SLOTS[v]));
                // the normal form of sq(v) modulo I: I + (sq(v)) = I + (nf),
                // nf supported on the standard monomials (low degree)
                sq_nf.push(basis_poly(&quo, nf));
            }
        }
    }
    if !sq_add.is_empty() {
        // √I = I + (sq_x(x), sq_y(y), sq_z(z)) (Seidenberg): first by the
        // multi-modular route, whose certificate does not need the basis
        // over Q of √I (slow with dense univariate generators of degree
        // 30–80 and long coefficients)
        let got = crate::budget::run_optional(|| {
            radical_by_modular(gens, &sq_nf, extra, multiplicity_dim)
        });
        if let Some(rur) = got.flatten() {
            return Ok(Some(rur));
        }
        made_radical = true;
        ready = None;
        let mut all = input;
        all.extend(sq_add.iter().map(to_g));
        let gb2 = groebner(all, 3, ord);
        quo = Quotient::new(gb2).ok_or_else(|| {
            Error::internal("radical of a zero-dimensional ideal is not zero-dimensional")
        })?;
        mats = [quo.var_matrix(0), quo.var_matrix(1), quo.var_matrix(2)];
        rhs = shape_targets(&quo, &mats, extra);
    }
    let d = quo.dim();
    // a separating linear form: one whose minimal polynomial has degree
    // dim A; the shape (x, y, z and the extras as polynomials in t) comes
    // with it
    let candidates = [
        (1, 1),
        (2, -1),
        (-1, 3),
        (0, 0),
        (1, 0),
        (0, 1),
        (1, -1),
        (2, 1),
        (1, 2),
        (3, 5),
        (5, -7),
        (7, 11),
    ]
    .into_iter()
    .chain((-20i64..=20).flat_map(|a| (-20i64..=20).map(move |b| (a, b))));
    let one = quo.one();
    let mut chosen = ready;
    for (a, b) in candidates {
        if chosen.is_some() {
            break;
        }
        crate::budget::check_now();
        let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
        if !krylov_full_likely(&mt, &one) {
            continue;
        }
        if let (mp, Some(sol)) = krylov_shape(&mt, &one, &rhs)? {
            chosen = Some(([qi(1), qi(a), qi(b)], mp, sol));
        }
    }
    let (form, mp, sol) =
        chosen.ok_or_else(|| Error::internal("no separating linear form found"))?;
    debug_assert_eq!(mp.degree(), Some(d));
    let polys: Vec<QPoly> = sol.into_iter().map(QPoly::new).collect();
    let (f, _) = ZPoly::from_q(&mp);
    let real_roots = RealAlg::roots_of(&f);
    let extra_values = extra
        .iter()
        .map(|p| value_minpoly(&quo, p))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Some(Rur {
        multiplicity_dim,
        points: d,
        form,
        f,
        coords: [polys[0].clone(), polys[1].clone(), polys[2].clone()],
        coords_z: std::array::from_fn(|k| ZPoly::from_q(&polys[k])),
        extra: polys[3..].to_vec(),
        extra_values,
        real_roots,
        made_radical,
    }))
}

/// The most primes [`radical_by_modular`] lets the multi-modular route try.
const RADICAL_PRIMES: usize = 600;

/// The RUR of `√I = I + (sq_x(x), sq_y(y), sq_z(z))` (Seidenberg's lemma:
/// an ideal containing a square-free polynomial in each variable is radical
/// in characteristic 0; `sq_v` is the square-free part of the exact minimal
/// polynomial of v on `Q[x]/I`, so it vanishes at every zero of I) by the
/// multi-modular route ([`super::rur_modular`]) with a linear separating form.
/// Its certificate is exact: every root of `f` gives a zero of the
/// generators (`sq_v` included, verified over Z), and the count of
/// standard monomials modulo a prime bounds the number of zeros from above
/// (the leading forms include `x^a`, `y^b`, `z^c`: no zero at infinity).
/// `x, y, z` are then `Gᵥ·Φ⁻¹ mod f`, and each extra `p` is
/// `p(X(t), Y(t), Z(t)) mod f`, exactly.  `None` when the route declines
/// (the caller computes the basis over Q of √I instead).
fn radical_by_modular(
    gens: &[QMPoly],
    sq_add: &[QMPoly],
    extra: &[QMPoly],
    multiplicity_dim: usize,
) -> Option<Rur> {
    let mut all: Vec<QMPoly> = gens.iter().filter(|g| !g.is_zero()).cloned().collect();
    all.extend(sq_add.iter().cloned());
    let forms: Vec<[Q; 3]> = [(1i64, 1i64), (2, -1), (-1, 3)]
        .iter()
        .map(|&(a, b)| [qi(1), qi(a), qi(b)])
        .collect();
    let hs: Vec<QMPoly> = forms.iter().map(linear_form).collect();
    let mr = super::rur_modular::solve_modular_implied(&all, &hs, RADICAL_PRIMES, &[]).ok()?;
    // Φ is a constant multiple of f′, invertible modulo the square-free f
    let mut coords: [QPoly; 3] = std::array::from_fn(|_| QPoly::zero());
    for (k, c) in coords.iter_mut().enumerate() {
        *c = super::rur_square::quotient_mod_f(&mr.coords[k], &mr.denom, &mr.f, RADICAL_PRIMES)?;
    }
    // each extra p = k·p′ (p′ primitive, integral, degree e) at ξ(t) is
    // k·p′ʰ(G, Φ)/Φ^e: numerator and denominator exactly over Z (not
    // reduced: no fractions), their quotient modulo f lifted modularly
    let mut extra_polys = Vec::with_capacity(extra.len());
    let mut extra_values = Vec::with_capacity(extra.len());
    let one = QPoly::constant(qi(1));
    for p in extra {
        let (pz, k) = p.to_primitive_z();
        let (num, den) = eval_homogeneous(&pz, &mr.coords, &mr.denom);
        let q = super::rur_square::quotient_mod_f(&num, &den, &mr.f, RADICAL_PRIMES)?.scale(&k);
        extra_values.push(crate::roots::value_polynomial(&mr.f, &q, &one));
        extra_polys.push(q);
    }
    Some(Rur {
        multiplicity_dim,
        points: mr.f.degree().unwrap_or(0),
        form: forms[mr.separating].clone(),
        f: mr.f.clone(),
        coords_z: std::array::from_fn(|k| ZPoly::from_q(&coords[k])),
        coords,
        extra: extra_polys,
        extra_values,
        real_roots: mr.real_roots,
        made_radical: true,
    })
}

/// `c₀x + c₁y + c₂z`.
pub(crate) fn linear_form(c: &[Q; 3]) -> QMPoly {
    let mut p = QMPoly::zero();
    for (k, ck) in c.iter().enumerate() {
        p = &p + &MPoly::var(SLOTS[k]).scale(ck);
    }
    p
}

/// `pʰ(G₀, G₁, G₂, Φ)` and `Φ^e` (e the degree of p) over Z, so that
/// `p(G/Φ) = num/den` wherever Φ ≠ 0; powers cached.
fn eval_homogeneous(p: &ZMPoly, g: &[ZPoly; 3], phi: &ZPoly) -> (ZPoly, ZPoly) {
    let e = p.total_degree().unwrap_or(0) as usize;
    let power = |b: &ZPoly| -> Vec<ZPoly> {
        let mut v = vec![ZPoly::constant(BigInt::one())];
        for _ in 0..e {
            crate::budget::check();
            let next = v.last().expect("non-empty") * b;
            v.push(next);
        }
        v
    };
    let pows: [Vec<ZPoly>; 3] = std::array::from_fn(|k| power(&g[k]));
    let phis = power(phi);
    let mut acc = ZPoly::zero();
    for (ex, c) in p.terms() {
        crate::budget::check();
        let mut term = phis[e - (0..3).map(|k| ex[SLOTS[k]] as usize).sum::<usize>()].scale(c);
        for k in 0..3 {
            let a = ex[SLOTS[k]] as usize;
            if a > 0 {
                term = &term * &pows[k][a];
            }
        }
        acc = &acc + &term;
    }
    (acc, phis[e].clone())
}

/// The RUR of `√I` when `A = Q[x]/I` is cyclic for the form `t`: with
/// `A ≅ Q[T]/(m_t)` (x, y, z and the extras are `sol` as polynomials in T),
/// the nilradical is `(sqfree(m_t))/(m_t)`, so `Q[x]/√I ≅ Q[T]/(sq)` and
/// the zeros are `ξ(τ) = (X(τ), Y(τ), Z(τ))` over the roots τ of `sq`, each
/// coordinate and extra reduced modulo `sq`.
fn radical_shape(form: [Q; 3], sq: &ZPoly, sol: Vec<Vec<Q>>, multiplicity_dim: usize) -> Rur {
    let sqq = sq.to_q();
    let polys: Vec<QPoly> = sol.into_iter().map(|c| QPoly::new(c).rem(&sqq)).collect();
    let one = QPoly::constant(qi(1));
    let extra_values = polys[3..]
        .iter()
        .map(|p| crate::roots::value_polynomial(sq, p, &one))
        .collect();
    Rur {
        multiplicity_dim,
        points: sq.degree().unwrap_or(0),
        form,
        f: sq.clone(),
        coords: [polys[0].clone(), polys[1].clone(), polys[2].clone()],
        coords_z: std::array::from_fn(|k| ZPoly::from_q(&polys[k])),
        extra: polys[3..].to_vec(),
        extra_values,
        real_roots: RealAlg::roots_of(sq),
        made_radical: true,
    }
}

/// The vectors whose shape is wanted: the coordinates x, y, z and the
/// extras, in the monomial basis of the quotient.
fn shape_targets(quo: &Quotient, mats: &[QMatrix; 3], extra: &[QMPoly]) -> Vec<Vec<Q>> {
    let one = quo.one();
    let mut rhs: Vec<Vec<Q>> = mats.iter().map(|m| mat_vec(m, &one)).collect();
    rhs.extend(extra.iter().map(|p| nf_rational(quo, p)));
    rhs
}

/// The minimal polynomial of multiplication by `p` on the radical quotient
/// `A`: `∏ (u − v)` over the distinct values `v = p(ξ)` at the zeros, as a
/// primitive square-free integer polynomial.  (Its Krylov sequence starts
/// at 1, which generates `A` as a module over itself, so the relative
/// minimal polynomial is the full one.)
fn value_minpoly(quo: &Quotient, p: &QMPoly) -> Result<ZPoly, Error> {
    if p.is_zero() {
        return Ok(ZPoly::from_i64s(&[0, 1]));
    }
    let (z, k) = p.to_primitive_z();
    let g = GPoly::from_zmpoly_exact(&z, &SLOTS, MonoOrder::GrevLex);
    let m = mat_comb(&[(k, &quo.mult_matrix(&g))]);
    let (mp, _) = krylov_shape(&m, &quo.one(), &[])?;
    Ok(ZPoly::from_q(&mp).0.squarefree_part())
}

/// `Σ c_j·b_j` over the standard monomials `b_j`.
fn basis_poly(quo: &Quotient, coords: Vec<Q>) -> QMPoly {
    QMPoly::from_terms(
        quo.basis
            .iter()
            .zip(coords)
            .filter(|(_, c)| !c.is_zero())
            .map(|(m, c)| {
                let mut e = [0u32; crate::poly::mpoly::NVARS];
                for k in 0..3 {
                    e[SLOTS[k]] = m[k] as u32;
                }
                (e, c)
            }),
    )
}

/// Normal-form coordinates of a rational polynomial.
fn nf_rational(quo: &Quotient, p: &QMPoly) -> Vec<Q> {
    if p.is_zero() {
        return vec![Q::zero(); quo.dim()];
    }
    // p = k·z exactly; the Gröbner conversion must keep z's scale and sign
    let (z, k) = p.to_primitive_z();
    let g = GPoly::from_zmpoly_exact(&z, &SLOTS, MonoOrder::GrevLex);
    quo.nf(&g).into_iter().map(|c| c * &k).collect()
}

impl Rur {
    /// A rational approximation of the real zero number `i`: the
    /// coordinates at a `2^-bits` approximation of its `t`, rounded down to
    /// dyadics with `bits + 16` fractional bits.
    pub fn approx_point(&self, i: usize, bits: u32) -> [Q; 3] {
        let t = self.real_roots[i].to_rational_approx(bits);
        std::array::from_fn(|k| {
            let (p, c) = &self.coords_z[k];
            let (n, d) = p.eval_homogeneous(t.numer(), t.denom());
            crate::number::dyadic_floor(&(n * c.numer()), &(d * c.denom()), bits as usize + 16)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;
    use crate::roots::value_polynomial;

    fn check(gens: &[&str], extra: &str) -> Rur {
        let gens: Vec<QMPoly> = gens.iter().map(|g| parse_poly(g).unwrap()).collect();
        let p = parse_poly(extra).unwrap();
        let rur = solve_zero_dim(&gens, std::slice::from_ref(&p))
            .unwrap()
            .unwrap();
        // the quotient's minimal polynomial agrees with the resultant
        // Res_t(f(t), u − p(t)) made square-free
        let by_resultant = value_polynomial(&rur.f, &rur.extra[0], &QPoly::constant(qi(1)));
        assert_eq!(rur.extra_values[0], by_resultant);
        // and the shape really parametrises the zeros: the generators vanish
        // on (x(t), y(t), z(t)) modulo f
        let fq = rur.f.to_q();
        for g in &gens {
            let mut acc = QPoly::zero();
            for (e, c) in g.terms() {
                let mut t = QPoly::constant(c.clone());
                for (k, &v) in SLOTS.iter().enumerate() {
                    for _ in 0..e[v] {
                        t = (&t * &rur.coords[k]).rem(&fq);
                    }
                }
                acc = &acc + &t;
            }
            assert!(
                acc.rem(&fq).is_zero(),
                "generator does not vanish on the shape"
            );
        }
        rur
    }

    /// A quotient that is neither radical nor cyclic: `I = ((x+y)², y²,
    /// z² + x − 1)` has the local algebra `C[x, y]/(x², y²)` (not cyclic
    /// for any form) at `(0, 0, ±1)`.  Its radical comes from the
    /// multi-modular route on I plus Seidenberg's generators (here `x + y`
    /// and `y`), directly and through [`solve_zero_dim`]: two points,
    /// `S = x + 2y + 3z + 5` taking 2 and 8.
    #[test]
    fn a_non_cyclic_quotient_gets_its_radical_by_the_modular_route() {
        let gens: Vec<QMPoly> = ["x^2 + 2*x*y + y^2", "y^2", "z^2 + x - 1"]
            .iter()
            .map(|g| parse_poly(g).unwrap())
            .collect();
        let s = parse_poly("x + 2*y + 3*z + 5").unwrap();
        let sq: Vec<QMPoly> = ["x + y", "y"]
            .iter()
            .map(|g| parse_poly(g).unwrap())
            .collect();
        let direct = radical_by_modular(&gens, &sq, std::slice::from_ref(&s), 8).unwrap();
        let via = check(
            &["x^2 + 2*x*y + y^2", "y^2", "z^2 + x - 1"],
            "x + 2*y + 3*z + 5",
        );
        for r in [&direct, &via] {
            assert_eq!(r.points, 2);
            assert_eq!(r.multiplicity_dim, 8);
            assert!(r.made_radical);
            assert_eq!(r.extra_values[0], ZPoly::from_i64s(&[16, -10, 1]));
            assert!(r.coords[0].is_zero() && r.coords[1].is_zero());
        }
        // a wrong "radical" generator (z, which does not vanish on V(I))
        // leaves no zero to verify: declined, never a wrong RUR
        let wrong = vec![parse_poly("z").unwrap()];
        let r = radical_by_modular(&gens, &wrong, std::slice::from_ref(&s), 8);
        assert!(r.is_none_or(|r| r.points == 0));
    }

    #[test]
    fn shape_and_values_of_a_sphere_and_two_planes() {
        // x² + y² + z² = 9, x = y, z = 1: two points (±2, ±2, 1)
        let r = check(&["x^2+y^2+z^2-9", "x-y", "z-1"], "x + 3z");
        assert_eq!(r.points, 2);
        assert_eq!(r.real_roots.len(), 2);
    }

    #[test]
    fn shape_and_values_of_a_critical_system() {
        // critical points of a cubic on an ellipsoid: 3 equations
        let r = check(
            &["x^2+2y^2+3z^2-6", "x*y - z", "y^2 - x*z + 1"],
            "x*y*z + x^2",
        );
        assert!(r.points > 0);
    }

    /// Multiple zeros with a cyclic quotient: the radical comes from the
    /// shape modulo sqfree(m_t), with no second Gröbner basis.  In the
    /// plane z = 0 the unit circle meets its tangent y = 1 at (0, 1)
    /// (a double zero) and the line x = 1/2 at (1/2, ±√3/2).
    #[test]
    fn multiple_zeros_of_a_cyclic_quotient_give_the_radical_shape() {
        let r = check(&["x^2+y^2-1", "(y-1)*(2x-1)", "z"], "x + y");
        assert_eq!(r.multiplicity_dim, 4);
        assert!(r.made_radical);
        assert_eq!(r.points, 3);
        assert_eq!(r.real_roots.len(), 3);
        // x + y at the points: 1 and 1/2 ± √3/2, the roots of
        // (u − 1)(2u² − 2u − 1) = 2u³ − 4u² + u + 1
        assert_eq!(r.extra_values[0], ZPoly::from_i64s(&[1, 1, -4, 2]));
    }

    #[test]
    fn repeated_values_give_a_smaller_value_polynomial() {
        // four points (±1, ±2, 0) and (±2, ±1, 0): p = x² + y² is 5 at all
        let r = check(&["x^2+y^2-5", "x*y-2", "z"], "x^2+y^2");
        assert_eq!(r.points, 4);
        assert_eq!(r.extra_values[0], ZPoly::from_i64s(&[-5, 1]));
    }
}
