//! Zero-dimensional polynomial systems in x, y, z, solved exactly: a
//! Gröbner basis, the radical (Seidenberg), a separating linear form and the
//! rational univariate representation; the real zeros are the real roots of
//! the RUR's univariate polynomial (the form separates conjugate zeros).

use super::{RealAlg, eval_q};
use crate::elim::groebner::{GPoly, MonoOrder, groebner};
use crate::elim::quotient::{Quotient, krylov_minpoly, mat_comb, solve_columns};
use crate::error::Error;
use crate::number::{Q, qi};
use crate::poly::mpoly::{MPoly, X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZPoly};
use num_traits::Zero;

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
    /// Extra polynomials (e.g. S) as polynomials in `t`.
    pub extra: Vec<QPoly>,
    /// The real roots of `f`, increasing: one per real zero.
    pub real_roots: Vec<RealAlg>,
    /// True when the ideal had to be made radical.
    pub made_radical: bool,
}

const SLOTS: [usize; 3] = [X, Y, Z];

fn to_g(p: &QMPoly) -> GPoly {
    GPoly::from_mpoly(p, &SLOTS, MonoOrder::GrevLex)
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
            extra: extra.iter().map(|_| QPoly::zero()).collect(),
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
    // otherwise √I = I + (sqfree(m)(t)).  Else fall back to Seidenberg: the
    // minimal polynomials of x, y, z must be square-free.
    let mut made_radical = false;
    let mut mats = [quo.var_matrix(0), quo.var_matrix(1), quo.var_matrix(2)];
    let mut sq_add: Vec<QMPoly> = Vec::new();
    let mut cyclic = false;
    let mut ready = None;
    for (a, b) in [(1i64, 1i64), (2, -1), (-1, 3)] {
        let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
        let (mp, vecs) = krylov_minpoly(&mt, &quo.one());
        if mp.degree() == Some(quo.dim()) {
            cyclic = true;
            ready = Some(([qi(1), qi(a), qi(b)], mp.clone(), vecs));
            let (mz, _) = ZPoly::from_q(&mp);
            let sq = mz.squarefree_part();
            if sq.degree() != mz.degree() {
                let t: QMPoly =
                    &(&MPoly::var(X) + &MPoly::var(Y).scale(&qi(a))) + &MPoly::var(Z).scale(&qi(b));
                let tz = MPoly::from_univariate(&sq.to_q(), X);
                sq_add.push(tz.substitute(X, &t));
            }
            break;
        }
    }
    if !cyclic {
        for (v, m) in mats.iter().enumerate() {
            let (mp, _) = krylov_minpoly(m, &quo.one());
            let (mz, _) = ZPoly::from_q(&mp);
            let sq = mz.squarefree_part();
            if sq.degree() != mz.degree() {
                sq_add.push(MPoly::from_univariate(&sq.to_q(), SLOTS[v]));
            }
        }
    }
    if !sq_add.is_empty() {
        made_radical = true;
        ready = None;
        let mut all = input;
        all.extend(sq_add.iter().map(to_g));
        let gb2 = groebner(all, 3, ord);
        quo = Quotient::new(gb2).ok_or_else(|| {
            Error::Internal("radical of a zero-dimensional ideal is not zero-dimensional".into())
        })?;
        mats = [quo.var_matrix(0), quo.var_matrix(1), quo.var_matrix(2)];
    }
    let d = quo.dim();
    // a separating linear form
    let candidates: [(i64, i64); 12] = [
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
    ];
    let one = quo.one();
    let mut chosen = ready;
    for (a, b) in candidates {
        if chosen.is_some() {
            break;
        }
        let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
        let (mp, vecs) = krylov_minpoly(&mt, &one);
        if mp.degree() == Some(d) {
            chosen = Some(([qi(1), qi(a), qi(b)], mp, vecs));
            break;
        }
    }
    let (form, mp, vecs) = match chosen {
        Some(c) => c,
        None => {
            // deterministic wider search
            let mut found = None;
            'outer: for a in -20i64..=20 {
                for b in -20i64..=20 {
                    let mt = mat_comb(&[(qi(1), &mats[0]), (qi(a), &mats[1]), (qi(b), &mats[2])]);
                    let (mp, vecs) = krylov_minpoly(&mt, &one);
                    if mp.degree() == Some(d) {
                        found = Some(([qi(1), qi(a), qi(b)], mp, vecs));
                        break 'outer;
                    }
                }
            }
            found.ok_or_else(|| Error::Internal("no separating linear form found".into()))?
        }
    };
    // shape: coordinates of x, y, z, extras in the basis 1, t, …, t^(d-1)
    let mut rhs: Vec<Vec<Q>> = (0..3)
        .map(|v| crate::elim::quotient::mat_vec(&mats[v], &one))
        .collect();
    for p in extra {
        rhs.push(nf_rational(&quo, p));
    }
    let sol = solve_columns(&vecs, &rhs).ok_or_else(|| {
        Error::Internal("Krylov basis of a separating element is singular".into())
    })?;
    let polys: Vec<QPoly> = sol.into_iter().map(QPoly::new).collect();
    let (f, _) = ZPoly::from_q(&mp);
    let real_roots = RealAlg::roots_of(&f);
    Ok(Some(Rur {
        multiplicity_dim,
        points: d,
        form,
        f,
        coords: [polys[0].clone(), polys[1].clone(), polys[2].clone()],
        extra: polys[3..].to_vec(),
        real_roots,
        made_radical,
    }))
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
    /// A rational approximation of the real zero number `i`.
    pub fn approx_point(&self, i: usize, bits: u32) -> [Q; 3] {
        let t = self.real_roots[i].to_rational_approx(bits);
        std::array::from_fn(|k| eval_q(&self.coords[k], &t))
    }
}
