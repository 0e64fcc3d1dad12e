//! S of degree ≥ 3, general position: the critical points of S on E by the
//! multi-modular route ([`crate::system::rur_modular`]) with S itself as the
//! separating element.
//!
//! The critical points are the zeros of `E = 0, ∇S × ∇E = 0`
//! ([`super::critical`]).  When S takes distinct values at distinct
//! critical points (general position), the rational univariate
//! representation with respect to S has `f = D(u)`: its roots are exactly
//! the critical values, each from one critical point, and a critical point
//! is real iff its value is real (a non-real point and its conjugate would
//! share a real value).  So the real critical values are the real roots of
//! D(u), and no root of D(u) comes from a non-real point.  The RUR is
//! verified exactly (soundness) and proven complete by the counting
//! certificate; symmetric inputs (equal values, curves, multiple points)
//! are declined and go to the exact route.

use super::ellipsoid::Ellipsoid;
use super::witness::WitnessSearch;
use super::witness::{WitnessPoint, witness_at_value};
use crate::number::{Q, QSqrt, q};
use crate::poly::mpoly::{MPoly, X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::RealAlg;
use crate::roots::{value_polynomial, values_with};
use crate::system::linear_form;
use crate::system::rur_modular::{Declined, ModularRur, solve_modular_implied};
use num_traits::{One, Signed, ToPrimitive, Zero};

/// When S alone does not separate the critical points (symmetric inputs),
/// `S + c·ℓ` for these `(ℓ, c)` is tried in turn.
pub const SHIFTS: [([i64; 3], (i64, i64)); 2] = [([1, 2, 3], (1, 3)), ([3, -1, 2], (1, 5))];

/// The largest number of primes tried before the route gives up.
pub const MAX_PRIMES: usize = 4000;

/// The verified critical points of S on E with S as separating element.
#[derive(Clone, Debug)]
pub struct ModularAnalysis {
    /// The generators `E, (∇S × ∇E)₁, ₂, ₃`.
    pub generators: Vec<QMPoly>,
    /// The verified RUR with respect to `h = S + c·ℓ` (`shift = (ℓ, c)`, or
    /// `None` for `h = S`, when `rur.f` is D(u) itself).
    pub rur: ModularRur,
    /// The shift of the separating element.
    pub shift: Option<([Q; 3], Q)>,
    /// `S = value_num(u)/value_den(u)` at the critical point of RUR root u.
    pub value_num: QPoly,
    /// See `value_num`.
    pub value_den: QPoly,
    /// The value of S at each real critical point (order of
    /// `rur.real_roots`).
    pub values: Vec<RealAlg>,
    /// D(u): all critical values (complex points included), square-free.
    pub judging: ZPoly,
    /// Conics of critical points split off before the RUR (see
    /// [`CriticalConic`]); their values are in `judging` and in
    /// [`ModularAnalysis::real_values`].
    pub conics: Vec<CriticalConic>,
}

/// A conic of critical points: when `x_v^k` (k ≥ 1) divides the three
/// minors of `∇S × ∇E`, they vanish on the plane `x_v = 0`, so every point
/// of the conic `E ∩ {x_v = 0}` is critical and S is constant on it (its
/// derivative along E vanishes there; the conic of an ellipsoid is
/// connected).  The other critical points are the zeros of E and the
/// minors divided by the common monomial.
#[derive(Clone, Debug)]
pub struct CriticalConic {
    /// The variable (0, 1, 2: x, y, z) that vanishes on the plane.
    pub var: usize,
    /// S on the conic.
    pub value: Q,
    /// An exact real point of the conic (S = `value` there).
    pub point: [QSqrt; 3],
}

impl ModularAnalysis {
    /// The values attained by real critical points (with `h = S`: the real
    /// roots of D(u), increasing).
    pub fn real_values(&self) -> Vec<RealAlg> {
        with_conic_values(&self.values, &self.conics)
    }
}

impl WitnessSearch for ModularAnalysis {
    /// A witness near the real critical point whose value is `v`.
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        if let Some(w) = conic_witness(&self.conics, v, want) {
            return Some(w);
        }
        witness_at_value(&self.values, v, e, s, want, &|i, bits| {
            self.rur.approx_point(i, bits)
        })
    }
}

/// The values at the real critical points followed by those of the
/// conics of critical points.
pub(crate) fn with_conic_values(values: &[RealAlg], conics: &[CriticalConic]) -> Vec<RealAlg> {
    let mut v = values.to_vec();
    v.extend(conics.iter().map(|c| RealAlg::rational(c.value.clone())));
    v
}

/// The point of a conic of critical points where S is `value`, when its
/// sign is `want`.
pub(crate) fn conic_witness(
    conics: &[CriticalConic],
    value: &RealAlg,
    want: i32,
) -> Option<WitnessPoint> {
    let c = conics.iter().find(|c| {
        value.cmp_exact(&RealAlg::rational(c.value.clone())) == std::cmp::Ordering::Equal
    })?;
    let sign = c.value.signum().to_i32().unwrap_or(0);
    (sign == want).then(|| WitnessPoint {
        coords: c.point.clone(),
        value: QSqrt::rational(c.value.clone()),
        sign,
    })
}

/// The conics of critical points of S on E and the minors of `∇S × ∇E`
/// divided by their common monomial (see [`CriticalConic`]); the minors
/// unchanged and no conic when there is no common monomial or a section
/// is not as expected.
pub(crate) fn split_conics(
    e: &QMPoly,
    s: &QMPoly,
    cross: &[QMPoly],
) -> (Vec<CriticalConic>, Vec<QMPoly>) {
    let common = common_monomial(cross);
    let mut conics = Vec::new();
    for v in (0..3).filter(|&v| common[v] > 0) {
        match critical_conic(e, s, v) {
            Ok(c) => conics.extend(c),
            Err(_) => return (Vec::new(), cross.to_vec()),
        }
    }
    (
        conics,
        cross.iter().map(|m| divide_monomial(m, common)).collect(),
    )
}

/// The largest monomial dividing every term of `ps` (its exponents).
fn common_monomial(ps: &[QMPoly]) -> [u32; 3] {
    let mut m = [u32::MAX; 3];
    for p in ps {
        for (ex, _) in p.terms() {
            for (k, v) in [X, Y, Z].into_iter().enumerate() {
                m[k] = m[k].min(ex[v]);
            }
        }
    }
    m.map(|x| if x == u32::MAX { 0 } else { x })
}

/// `p / (x^m₀ y^m₁ z^m₂)` for a monomial dividing every term.
fn divide_monomial(p: &QMPoly, m: [u32; 3]) -> QMPoly {
    MPoly::from_terms(p.terms().iter().map(|(ex, c)| {
        let mut e = *ex;
        for (k, v) in [X, Y, Z].into_iter().enumerate() {
            e[v] -= m[k];
        }
        (e, c.clone())
    }))
}

/// The conic `E ∩ {x_v = 0}` when it has a real point: S there (constant,
/// see [`CriticalConic`]) and an exact point.  With `Q₂(u, w) = E|_{x_v=0}`
/// (positive definite quadratic part), the centre `(u₀, w₀)` and
/// `μ = Q₂(u₀, w₀)`: no real point when μ > 0, the centre alone when μ = 0,
/// else the points `(u₀, w₀ ± √(−μ/C))`, C the coefficient of w².
fn critical_conic(e: &QMPoly, s: &QMPoly, v: usize) -> Result<Option<CriticalConic>, Declined> {
    let decline = |m: &str| Err(Declined(m.into()));
    let vars = [X, Y, Z];
    let others: Vec<usize> = (0..3).filter(|&k| k != v).collect();
    let (iu, iw) = (others[0], others[1]);
    let q2 = e.substitute(vars[v], &MPoly::zero());
    // A u² + B uw + C w² + D u + F w + G, made positive definite
    let mut c: [Q; 6] = std::array::from_fn(|_| Q::zero());
    for (ex, k) in q2.terms() {
        let slot = match (ex[vars[iu]], ex[vars[iw]]) {
            (2, 0) => 0,
            (1, 1) => 1,
            (0, 2) => 2,
            (1, 0) => 3,
            (0, 1) => 4,
            (0, 0) => 5,
            _ => return decline("the ellipsoid is not quadratic"),
        };
        c[slot] += k;
    }
    if c[0].is_negative() {
        for x in c.iter_mut() {
            *x = -x.clone();
        }
    }
    let [a, b, cc, d, f, g] = c;
    let two = Q::from_integer(2.into());
    let det = &(&(&two * &two) * &a) * &cc - &b * &b;
    if !det.is_positive() || !cc.is_positive() {
        return decline("the section of the ellipsoid is not an ellipse");
    }
    let u0 = (&(&b * &f) - &(&(&two * &cc) * &d)) / &det;
    let w0 = (&(&b * &d) - &(&(&two * &a) * &f)) / &det;
    let mu = &(&(&(&a * &u0) * &u0) + &(&(&b * &u0) * &w0)) + &(&(&cc * &w0) * &w0);
    let mu = &(&(&mu + &(&d * &u0)) + &(&f * &w0)) + &g;
    if mu.is_positive() {
        return Ok(None);
    }
    let mut point: [QSqrt; 3] = std::array::from_fn(|_| QSqrt::rational(Q::zero()));
    point[iu] = QSqrt::rational(u0.clone());
    let mut other = point.clone();
    if mu.is_zero() {
        point[iw] = QSqrt::rational(w0);
        other = point.clone();
    } else {
        let r = -(&mu / &cc);
        point[iw] = QSqrt::try_new(w0.clone(), Q::one(), r.clone())
            .map_err(|_| Declined("a conic point".into()))?;
        other[iw] =
            QSqrt::try_new(w0, -Q::one(), r).map_err(|_| Declined("a conic point".into()))?;
    }
    let value = crate::geom::eval_qsqrt(s, &point);
    // S is constant on the conic: the same rational value at both points
    if !value.is_rational() || crate::geom::eval_qsqrt(s, &other) != value {
        return decline("S is not constant on a conic of critical points");
    }
    Ok(Some(CriticalConic {
        var: v,
        value: value.a().clone(),
        point,
    }))
}

/// The modular analysis, or why it does not apply (the caller then uses the
/// exact route of [`super::critical`]); `cross` are the minors of the critical system (`∇S × ∇E` for S as
/// given; see [`super::critical::CriticalSystem`]).
pub fn analyze(
    e: &Ellipsoid,
    s: &QMPoly,
    cross: &[QMPoly; 3],
) -> Result<ModularAnalysis, Declined> {
    // a monomial dividing the three minors: conics of critical points
    let (conics, minors) = split_conics(&e.poly, s, cross);
    let mut gens = vec![e.poly.clone()];
    gens.extend(minors);
    let form = |l: &[i64; 3]| linear_form(&l.map(|x| q(x, 1)));
    let mut hs = vec![s.clone()];
    for (l, (cn, cd)) in SHIFTS {
        hs.push(s + &form(&l).scale(&q(cn, cd)));
    }
    // ∇E · (∇S × ∇E) = 0: where E_x ≠ 0 (resp. E_y, E_z) the first (second,
    // third) minor follows from the other two
    let implied: Vec<(usize, QMPoly)> = [X, Y, Z]
        .iter()
        .enumerate()
        .map(|(j, &v)| (j + 1, e.poly.derivative(v)))
        .collect();
    let rur = solve_modular_implied(&gens, &hs, MAX_PRIMES, &implied)?;
    if rur.points() == 0 {
        return Err(Declined("no critical point".into()));
    }
    let den = rur.denom.to_q();
    if rur.separating == 0 {
        let values = rur.real_roots.clone();
        let judging = with_conics(rur.f.clone(), &conics);
        return Ok(ModularAnalysis {
            generators: gens,
            rur,
            shift: None,
            value_num: QPoly::new(vec![Q::zero(), Q::one()]) * &den,
            value_den: den,
            values,
            judging,
            conics,
        });
    }
    // S(ξ(u)) = u − c·ℓ(ξ(u)) = (u·Φ(u) − c·Σ ℓᵢ Gᵢ(u)) / Φ(u)
    let (l, (cn, cd)) = SHIFTS[rur.separating - 1];
    let c = q(cn, cd);
    let mut lin = QPoly::zero();
    for (k, &lk) in l.iter().enumerate() {
        lin = &lin + &rur.coords[k].to_q().scale(&(&c * q(lk, 1)));
    }
    let num = &(QPoly::new(vec![Q::zero(), Q::one()]) * &den) - &lin;
    let judging = value_polynomial(&rur.f, &num, &den);
    let values = values_with(&rur.f, &rur.real_roots, &num, &den, &judging)
        .into_iter()
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| Declined("the denominator vanishes at a real root".into()))?;
    let judging = with_conics(judging, &conics);
    Ok(ModularAnalysis {
        generators: gens,
        rur,
        shift: Some((l.map(|x| q(x, 1)), c)),
        value_num: num,
        value_den: den,
        values,
        judging,
        conics,
    })
}

/// D(u) times `u − c` for the value c of each conic of critical points,
/// square-free.
pub(crate) fn with_conics(judging: ZPoly, conics: &[CriticalConic]) -> ZPoly {
    if conics.is_empty() {
        return judging;
    }
    let mut p = judging.to_q();
    for c in conics {
        p = &p * &QPoly::new(vec![-c.value.clone(), Q::one()]);
    }
    ZPoly::from_q(&p).0.squarefree_part()
}
