//! The exact route of the contact predicate and every certificate.
//!
//! Forms are canonical (module [`super`]): `q(x) = xᵀWx + 2bᵀx + c`,
//! negative inside, and for a pose `q(x) = |D⁻¹Rᵀ(x − c)|² − 1`.
//! `f(λ) = det(λA + B)` has `f(0) = det B < 0` and a negative leading
//! coefficient `det A`; for λ > 0, `m(λ) = f(λ)/h(λ)` is the minimum of the
//! convex `λq_A + q_B` and, by strong duality, `max m = min{q_B : q_A ≤ 0}`.
//! Hence, from the positive real roots of f and their multiplicities:
//! a root of odd multiplicity (f changes sign, so is positive somewhere)
//! — **separated**; only roots of even multiplicity (f ≤ 0, zero there) —
//! **touching**; none (f < 0 on λ > 0) — **overlapping**.
//!
//! The kinds of an overlap come from the S-lemma (Slater holds: an
//! ellipsoid has interior points): `A ⊆ B` iff `B − μA ⪯ 0` for some
//! μ > 0, strictly inside iff `B − μA ≺ 0`; `B ⊆ A` with `⪰`/`≻`.  Such a μ
//! is either strictly inside a gap between the negative roots of f
//! (definite there) or a multiple negative root (semidefinite).

use super::program::{Ar, neg};
use super::{Certificate, Contact, Kind};
use crate::geom::quadric::QuadricForm;
use crate::number::{Q, QSqrt};
use crate::poly::ZPoly;
use crate::roots::RealAlg;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// The 4×4 symmetric matrix of a form.
pub(crate) fn matrix(q: &QuadricForm) -> [[Q; 4]; 4] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i, j) {
            (3, 3) => q.c.clone(),
            (3, k) | (k, 3) => q.b[k].clone(),
            (i, j) => q.a[i][j].clone(),
        })
    })
}

/// `det(λA + B)`, coefficients from the constant up (Laplace expansion on
/// the first two rows).
pub(crate) fn quartic<T: Ar>(a: &[[T; 4]; 4], b: &[[T; 4]; 4], zero: T) -> [T; 5] {
    // a 2×2 minor of λA + B: (λa + b)(λa' + b') − … as [c0, c1, c2]
    let lin = |i: usize, j: usize| [b[i][j].clone(), a[i][j].clone()];
    let pmul = |x: &[T; 2], y: &[T; 2]| -> [T; 3] {
        [
            x[0].mul(&y[0]),
            x[0].mul(&y[1]).add(&x[1].mul(&y[0])),
            x[1].mul(&y[1]),
        ]
    };
    let minor = |r: (usize, usize), c: (usize, usize)| -> [T; 3] {
        let p = pmul(&lin(r.0, c.0), &lin(r.1, c.1));
        let q = pmul(&lin(r.0, c.1), &lin(r.1, c.0));
        std::array::from_fn(|k| p[k].sub(&q[k]))
    };
    let mut f: [T; 5] = std::array::from_fn(|_| zero.clone());
    for i in 0..4 {
        for j in i + 1..4 {
            let rest: Vec<usize> = (0..4).filter(|&k| k != i && k != j).collect();
            let m1 = minor((0, 1), (i, j));
            let m2 = minor((2, 3), (rest[0], rest[1]));
            let plus = (1 + i + j) % 2 == 0;
            for x in 0..3 {
                for y in 0..3 {
                    let t = m1[x].mul(&m2[y]);
                    f[x + y] = if plus {
                        f[x + y].add(&t)
                    } else {
                        f[x + y].sub(&t)
                    };
                }
            }
        }
    }
    f
}

/// Definiteness of `n·A + d·B` (integer matrices) from the signs of its
/// leading principal minors, which Bareiss's fraction-free elimination
/// leaves on the diagonal: `Some(1)` positive definite (all > 0),
/// `Some(-1)` negative definite (signs −, +, −, +), `None` otherwise.
fn definite_z(a: &[[BigInt; 4]; 4], b: &[[BigInt; 4]; 4], n: &BigInt, d: &BigInt) -> Option<i32> {
    let mut w: [[BigInt; 4]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|j| n * &a[i][j] + d * &b[i][j]));
    let mut minors = [0i32; 4];
    let mut prev = BigInt::one();
    for k in 0..4 {
        if w[k][k].is_zero() {
            return None;
        }
        minors[k] = crate::number::sign_z(&w[k][k]);
        for i in k + 1..4 {
            for j in k + 1..4 {
                w[i][j] = (&w[i][j] * &w[k][k] - &w[i][k] * &w[k][j]) / &prev;
            }
        }
        prev = w[k][k].clone();
    }
    if minors.iter().all(|&s| s == 1) {
        Some(1)
    } else if minors == [-1, 1, -1, 1] {
        Some(-1)
    } else {
        None
    }
}

/// All principal minors of a symmetric 4×4 matrix over Q(√d) are ≥ 0
/// (`s = 1`) or have the signs of a negative semidefinite matrix (`s = −1`):
/// the criterion of semidefiniteness.
fn semidefinite(m: &[[QSqrt; 4]; 4], s: i32) -> bool {
    for mask in 1u32..16 {
        let idx: Vec<usize> = (0..4).filter(|k| mask & (1 << k) != 0).collect();
        let d = det_sub(m, &idx);
        let k = idx.len() as i32;
        // (−1)^k·det ≥ 0 for negative semidefinite
        let sign = d.signum() * if s < 0 && k % 2 == 1 { -1 } else { 1 };
        if sign < 0 {
            return false;
        }
    }
    true
}

/// The determinant of the principal submatrix on `idx` (cofactor expansion).
fn det_sub(m: &[[QSqrt; 4]; 4], idx: &[usize]) -> QSqrt {
    if idx.len() == 1 {
        return m[idx[0]][idx[0]].clone();
    }
    let mut s = QSqrt::rational(Q::zero());
    let r = idx[0];
    for (pos, &c) in idx.iter().enumerate() {
        if m[r][c].is_zero() {
            continue;
        }
        // minor: rows idx[1..], columns idx without c
        let rows: Vec<usize> = idx[1..].to_vec();
        let cols: Vec<usize> = idx.iter().copied().filter(|&x| x != c).collect();
        let sub = det_rc(m, &rows, &cols);
        let t = m[r][c].mul(&sub);
        s = if pos % 2 == 0 { s.add(&t) } else { s.sub(&t) };
    }
    s
}

fn det_rc(m: &[[QSqrt; 4]; 4], rows: &[usize], cols: &[usize]) -> QSqrt {
    if rows.len() == 1 {
        return m[rows[0]][cols[0]].clone();
    }
    let mut s = QSqrt::rational(Q::zero());
    for (pos, &c) in cols.iter().enumerate() {
        if m[rows[0]][c].is_zero() {
            continue;
        }
        let cs: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
        let t = m[rows[0]][c].mul(&det_rc(m, &rows[1..], &cs));
        s = if pos % 2 == 0 { s.add(&t) } else { s.sub(&t) };
    }
    s
}

/// The exact value of a form at a rational point.
#[cfg(test)]
pub(crate) fn value(q: &QuadricForm, x: &[Q; 3]) -> Q {
    q.eval(x)
}

/// `Xᵀ(L·M)X` for `X = (D·x, D)`, with `L` the lcm of the form's
/// denominators and `D` that of the point's, in integers (no gcd per
/// operation): the form's value at x is `s/(L·D²)`.
fn homogeneous_value(q: &QuadricForm, x: &[Q; 3]) -> (BigInt, BigInt, BigInt) {
    let l = crate::geom::quadric::common_denominator(&[q]);
    let m = q.int_matrix(&l);
    let d = crate::number::denom_lcm(x.iter());
    let xs: [BigInt; 4] = std::array::from_fn(|i| {
        if i == 3 {
            d.clone()
        } else {
            x[i].numer() * (&d / x[i].denom())
        }
    });
    let mut s = BigInt::zero();
    for i in 0..4 {
        let mut row = BigInt::zero();
        for j in 0..4 {
            row += &m[i][j] * &xs[j];
        }
        s += row * &xs[i];
    }
    (s, l, d)
}

/// The value of a form at a rational point ([`homogeneous_value`] and one
/// division).
fn value_fast(q: &QuadricForm, x: &[Q; 3]) -> Q {
    let (s, l, d) = homogeneous_value(q, x);
    Q::new(s, l * &d * &d)
}

/// The sign of a form at a rational point ([`homogeneous_value`]).
pub(crate) fn sign_at(q: &QuadricForm, x: &[Q; 3]) -> i32 {
    crate::number::sign_z(&homogeneous_value(q, x).0)
}

/// The centre `−W⁻¹b` of a form.
pub(crate) fn centre(q: &QuadricForm) -> [Q; 3] {
    // −W⁻¹b = −adj(W)·b / det W
    let w = &q.a;
    let cof = |i: usize, j: usize| {
        let (i1, i2, j1, j2) = ((i + 1) % 3, (i + 2) % 3, (j + 1) % 3, (j + 2) % 3);
        &w[i1][j1] * &w[i2][j2] - &w[i1][j2] * &w[i2][j1]
    };
    let c: [[Q; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| cof(i, j)));
    let det = (0..3).fold(Q::zero(), |s, j| s + &w[0][j] * &c[0][j]);
    std::array::from_fn(|i| -(0..3).fold(Q::zero(), |s, j| s + &c[j][i] * &q.b[j]) / &det)
}

/// Solves a 3×3 system over Q(√d) by Cramer's rule.
fn solve3(m: &[[QSqrt; 3]; 3], r: &[QSqrt; 3]) -> Option<[QSqrt; 3]> {
    let det3 = |m: &[[QSqrt; 3]; 3]| {
        let t = |a: usize, b: usize, c: usize| m[0][a].mul(&m[1][b]).mul(&m[2][c]);
        t(0, 1, 2)
            .add(&t(1, 2, 0))
            .add(&t(2, 0, 1))
            .sub(&t(0, 2, 1))
            .sub(&t(1, 0, 2))
            .sub(&t(2, 1, 0))
    };
    let d = det3(m);
    if d.is_zero() {
        return None;
    }
    let mut out: [QSqrt; 3] = std::array::from_fn(|_| QSqrt::rational(Q::zero()));
    for k in 0..3 {
        let mut mk = m.clone();
        for i in 0..3 {
            mk[i][k] = r[i].clone();
        }
        out[k] = det3(&mk).div(&d)?;
    }
    Some(out)
}

/// `λ₀A + B` over Q(√d).
fn pencil_at(a: &QuadricForm, b: &QuadricForm, l: &QSqrt) -> [[QSqrt; 4]; 4] {
    let (am, bm) = (matrix(a), matrix(b));
    std::array::from_fn(|i| {
        std::array::from_fn(|j| l.scale(&am[i][j]).add(&QSqrt::rational(bm[i][j].clone())))
    })
}

/// `λ₀A + B` as a matrix over Q(√d) and its kernel point `x` (the last
/// coordinate scaled to 1) from the 3×3 block, when there is one.
fn kernel_point(
    a: &QuadricForm,
    b: &QuadricForm,
    l: &QSqrt,
) -> Option<([QSqrt; 3], [[QSqrt; 4]; 4])> {
    let am = matrix(a);
    let bm = matrix(b);
    let m: [[QSqrt; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| l.scale(&am[i][j]).add(&QSqrt::rational(bm[i][j].clone())))
    });
    let w: [[QSqrt; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].clone()));
    let rhs: [QSqrt; 3] = std::array::from_fn(|i| m[i][3].neg());
    let x = solve3(&w, &rhs)?;
    Some((x, m))
}

/// A form's value at a point of Q(√d)³.
fn value_s(q: &QuadricForm, x: &[QSqrt; 3]) -> QSqrt {
    let mut s = QSqrt::rational(q.c.clone());
    for i in 0..3 {
        s = s.add(&x[i].scale(&(&q.b[i] * Q::from_integer(2.into()))));
        for j in 0..3 {
            s = s.add(&x[i].mul(&x[j]).scale(&q.a[i][j]));
        }
    }
    s
}

/// The real roots of a square-free factor as values of Q(√d) when the
/// factor has degree ≤ 2 (the multiple roots of a quartic always do).
fn small_roots(p: &ZPoly) -> Vec<QSqrt> {
    let c = p.coeffs();
    let q = |z: &BigInt| Q::from_integer(z.clone());
    match p.degree() {
        Some(1) => vec![QSqrt::rational(-q(&c[0]) / q(&c[1]))],
        Some(2) => {
            let (a, b, cc) = (q(&c[2]), q(&c[1]), q(&c[0]));
            let disc = &b * &b - Q::from_integer(4.into()) * &a * &cc;
            if disc.is_negative() {
                return vec![];
            }
            let two_a = Q::from_integer(2.into()) * &a;
            let x0 = -&b / &two_a;
            let s = Q::one() / &two_a;
            let mut r = vec![
                QSqrt::new(x0.clone(), -&s, disc.clone()),
                QSqrt::new(x0, s, disc),
            ];
            r.sort_by(|x, y| x.cmp_exact(y));
            r
        }
        _ => vec![],
    }
}

/// The exact decision and its certificate.
pub(crate) fn decide(
    a: &QuadricForm,
    b: &QuadricForm,
    ca: &[Q; 3],
    cb: &[Q; 3],
    hint: Option<Hint>,
    want_kind: bool,
) -> Result<(Contact, Kind, Certificate), crate::Error> {
    // integer matrices A' = L_A·A, B' = L_B·B: det(λ'A' + B') is a positive
    // multiple of f(κλ'), κ = L_A/L_B; λ' below, canonical λ = κλ' out
    let (la, lb) = (
        crate::geom::quadric::common_denominator(&[a]),
        crate::geom::quadric::common_denominator(&[b]),
    );
    let (ai, bi) = (a.int_matrix(&la), b.int_matrix(&lb));
    let kappa = Q::new(la, lb);
    let f = ZPoly::new(quartic(&ai, &bi, BigInt::zero()).to_vec());
    let pos_c = |lc: &Q| f.sign_at(&(lc / &kappa)) > 0;
    let ctx = Ctx {
        a,
        b,
        ai: &ai,
        bi: &bi,
        kappa: &kappa,
        ca,
        cb,
    };
    // separated by the hint? (a rational λ > 0 with f(λ) > 0)
    if let Some(Hint::Lambda(l)) = &hint
        && l.is_positive()
        && pos_c(l)
    {
        return Ok((
            Contact::Separated,
            Kind::Separated,
            Certificate::Separated {
                lambda: shorter_positive(&pos_c, l),
            },
        ));
    }
    if let Some(Hint::Point(p)) = &hint
        && sign_at(a, p) < 0
        && sign_at(b, p) < 0
    {
        let (kind, evidence) = if want_kind {
            kind_of(&ctx, &f)?
        } else {
            (Kind::Unclassified, None)
        };
        return Ok((
            Contact::Overlapping,
            kind,
            Certificate::Overlapping {
                point: p.clone(),
                evidence,
            },
        ));
    }
    // the positive roots and their multiplicities
    let mut odd: Vec<RealAlg> = vec![];
    let mut even: Vec<(ZPoly, u32)> = vec![];
    for (fac, mult) in f.squarefree_decomposition() {
        if fac.degree().unwrap_or(0) == 0 {
            continue;
        }
        let pos: Vec<RealAlg> = RealAlg::roots_of(&fac)
            .into_iter()
            .filter(|r| r.signum() > 0)
            .collect();
        if pos.is_empty() {
            continue;
        }
        if mult % 2 == 1 {
            odd.extend(pos);
        } else {
            even.push((fac, mult));
        }
    }
    if !odd.is_empty() {
        // f changes sign at the smallest positive root of odd multiplicity
        // (from − to +); a rational between it and the next root is a λ
        let mut roots: Vec<RealAlg> = RealAlg::roots_of(&f)
            .into_iter()
            .filter(|r| r.signum() > 0)
            .collect();
        roots.sort_by(|x, y| x.cmp_exact(y));
        let lambda = positive_point(&f, &roots)
            .map(|l| l * &kappa)
            .ok_or_else(|| crate::Error::internal("contact: no λ with f(λ) > 0 found"))?;
        return Ok((
            Contact::Separated,
            Kind::Separated,
            Certificate::Separated { lambda },
        ));
    }
    if let Some((fac, _)) = even.first() {
        let l0 = small_roots(fac)
            .into_iter()
            .find(|r| r.signum() > 0)
            .ok_or_else(|| crate::Error::internal("contact: a double root beyond Q(√d)"))?
            .scale(&kappa);
        let (x, _) = kernel_point(a, b, &l0)
            .ok_or_else(|| crate::Error::internal("contact: singular block at λ₀"))?;
        if !(value_s(a, &x).is_zero() && value_s(b, &x).is_zero()) {
            return Err(crate::Error::internal(
                "contact: the touching point is not on both ellipsoids",
            ));
        }
        return Ok((
            Contact::Touching,
            Kind::ExternallyTouching,
            Certificate::Touching {
                lambda: l0,
                point: x,
            },
        ));
    }
    // overlapping: a point inside both
    let p = witness(a, b, ca, cb)?;
    let (kind, evidence) = if want_kind {
        kind_of(&ctx, &f)?
    } else {
        (Kind::Unclassified, None)
    };
    Ok((
        Contact::Overlapping,
        kind,
        Certificate::Overlapping { point: p, evidence },
    ))
}

/// A λ of few bits near `l` (where f > 0) with f(λ) > 0 still: `l`
/// rounded to 2, 4, …, 64 significant bits, the first that works.
fn shorter_positive(pos: &impl Fn(&Q) -> bool, l: &Q) -> Q {
    let e = crate::number::floor_log2_q(l);
    for k in [2i64, 4, 8, 16, 24, 32, 48, 64] {
        let sh = e - k;
        let c = if sh >= 0 {
            let unit = Q::from_integer(BigInt::one() << sh as usize);
            (l / &unit).round() * unit
        } else {
            let unit = Q::from_integer(BigInt::one() << (-sh) as usize);
            (l * &unit).round() / unit
        };
        if c.is_positive() && pos(&c) {
            return c;
        }
    }
    l.clone()
}

/// The contact from `f = det(λA + B)` alone (any positive scaling of A,
/// B and λ): the positive roots and their multiplicities (module doc).
pub(crate) fn classify_quartic(f: &ZPoly) -> Contact {
    let mut even = false;
    for (fac, mult) in f.squarefree_decomposition() {
        if fac.degree().unwrap_or(0) == 0 {
            continue;
        }
        if RealAlg::roots_of(&fac).iter().any(|r| r.signum() > 0) {
            if mult % 2 == 1 {
                return Contact::Separated;
            }
            even = true;
        }
    }
    if even {
        Contact::Touching
    } else {
        Contact::Overlapping
    }
}

/// The contact of two poses of doubles, exactly, from the scaled integer
/// forms of [`super::program`]: each matrix times a power of two 2^k (its
/// semi-axes times 2^k, the same ellipsoid: `Rᵀ/r` is unchanged), then every length times one
/// power of two (both ellipsoids scaled alike), so that every input is an
/// integer; `f` is then a polynomial over Z with the roots of the
/// canonical one scaled by `ρ_B/ρ_A > 0`.
///
/// The filter's hints are tried first: `f(λ̃) > 0` at the scaled λ* proves
/// separation, both forms negative at the candidate point prove overlap
/// (two exact evaluations); the roots' multiplicities decide otherwise.
pub(crate) fn decide_poses(
    a: &super::Pose,
    b: &super::Pose,
    hints: &super::filter::Hints,
) -> Contact {
    use super::program::{pencil, pose_form, pose_value};
    // x = m·2^e
    let dec = |x: f64| -> (BigInt, i32) {
        if x == 0.0 {
            return (BigInt::zero(), 0);
        }
        let bits = x.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i32;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), exp - 1075)
        };
        let m = BigInt::from(m);
        (if x < 0.0 { -m } else { m }, e)
    };
    let shift = |(m, e): &(BigInt, i32), by: i32| -> BigInt {
        let s = e + by;
        debug_assert!(s >= 0);
        m << (s as usize)
    };
    let min_e = |xs: &[f64]| {
        xs.iter()
            .filter(|x| **x != 0.0)
            .map(|x| dec(*x).1)
            .min()
            .unwrap_or(0)
    };
    let k: Vec<i32> = [a, b].iter().map(|p| -min_e(&p.matrix.concat())).collect();
    // lengths: c·2^L and r·2^(L + k) integral
    let mut l = 0i32;
    for (p, kp) in [a, b].iter().zip(&k) {
        l = l.max(-min_e(&p.center));
        l = l.max(-min_e(&p.semi_axes) - kp);
    }
    if let Some(x) = &hints.point {
        l = l.max(-min_e(x));
    }
    let ints = |p: &super::Pose, kp: i32| {
        let m: [[BigInt; 3]; 3] = p.matrix.map(|row| row.map(|x| shift(&dec(x), kp)));
        let r: [BigInt; 3] = p.semi_axes.map(|x| shift(&dec(x), l + kp));
        let c: [BigInt; 3] = p.center.map(|x| shift(&dec(x), l));
        (m, r, c)
    };
    let (ma, ra, ca) = ints(a, k[0]);
    let (mb, rb, cb) = ints(b, k[1]);
    let (wa, rho_a, ka) = pose_form(&ra, &ma);
    let (wb, rho_b, kb) = pose_form(&rb, &mb);
    if let Some(x) = &hints.point {
        // q̃ = 2^(6(L+k))·q: the signs at 2^L·x are those of the forms at x
        let xs: [BigInt; 3] = x.map(|v| shift(&dec(v), l));
        if pose_value(&ka, &rho_a, &ca, &xs).is_negative()
            && pose_value(&kb, &rho_b, &cb, &xs).is_negative()
        {
            return Contact::Overlapping;
        }
    }
    let t: [BigInt; 3] = std::array::from_fn(|i| &cb[i] - &ca[i]);
    let p = pencil(wa, rho_a, wb, rho_b, t);
    let f = ZPoly::new(p.f.to_vec());
    if let Some(lam) = hints.lambda.filter(|v| v.is_finite() && *v > 0.0) {
        // λ̃ = λ·2^(6(k_B − k_A)) (the scales of the module doc)
        let (m, e) = dec(lam);
        let e = e as i64 + 6 * (k[1] - k[0]) as i64;
        let q = if e >= 0 {
            Q::from_integer(m << e as usize)
        } else {
            Q::new(m, BigInt::one() << (-e) as usize)
        };
        if f.sign_at(&q) > 0 {
            return Contact::Separated;
        }
    }
    classify_quartic(&f)
}

/// A rational λ > 0 with f(λ) > 0, between sorted positive roots.
fn positive_point(f: &ZPoly, roots: &[RealAlg]) -> Option<Q> {
    for w in roots.windows(2) {
        let (mut lo, mut hi) = (w[0].clone(), w[1].clone());
        // separate the two intervals, then try the simplest rational between
        for _ in 0..4000 {
            let (_, l_hi) = lo.interval();
            let (h_lo, _) = hi.interval();
            if l_hi < h_lo {
                let m = simplest_between(&l_hi, &h_lo);
                if f.sign_at(&m) > 0 {
                    return Some(m);
                }
                break;
            }
            lo.bisect();
            hi.bisect();
        }
    }
    None
}

/// A rational of small height strictly inside `(lo, hi)` when `lo < hi`
/// (in the middle half: the midpoint rounded to a dyadic with as few bits
/// as that allows); `lo` when they are equal.
pub(crate) fn simplest_between(lo: &Q, hi: &Q) -> Q {
    let width = hi - lo;
    if width.is_zero() {
        return lo.clone();
    }
    let mid = (lo + hi) / Q::from_integer(2.into());
    let quarter = &width / Q::from_integer(4.into());
    let (lo, hi) = (lo + &quarter, hi - &quarter);
    let mut k: u32 = 0;
    loop {
        let scale = Q::from_integer(BigInt::one() << k);
        let c = (&mid * &scale).round() / &scale;
        if c >= lo && c <= hi {
            return c;
        }
        k += 1;
    }
}

/// A rational point inside both ellipsoids of an overlapping pair:
/// the centres first, then the minimiser `x_λ` of `λq_A + q_B` at λ where
/// `q_A(x_λ)` (falling in λ) and `q_B(x_λ)` (rising) are both negative.
fn witness(
    a: &QuadricForm,
    b: &QuadricForm,
    ca: &[Q; 3],
    cb: &[Q; 3],
) -> Result<[Q; 3], crate::Error> {
    if sign_at(a, cb) < 0 {
        return Ok(cb.clone());
    }
    if sign_at(b, ca) < 0 {
        return Ok(ca.clone());
    }
    let x_at = |l: &Q| -> Option<[Q; 3]> {
        let w: [[QSqrt; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| QSqrt::rational(l.mul(&a.a[i][j]).add(&b.a[i][j])))
        });
        let r: [QSqrt; 3] =
            std::array::from_fn(|i| QSqrt::rational(neg(&l.mul(&a.b[i]).add(&b.b[i]))));
        let x = solve3(&w, &r)?;
        Some(std::array::from_fn(|i| x[i].a().clone()))
    };
    // q_A(x_λ) falls and q_B(x_λ) rises with λ, and both are negative on
    // an open interval (module doc): bisect, doubling or halving first
    let two = Q::from_integer(2.into());
    let (mut lo, mut hi): (Option<Q>, Option<Q>) = (None, None);
    let mut l = Q::one();
    for _ in 0..100_000 {
        crate::budget::check();
        let x = x_at(&l).ok_or_else(|| crate::Error::internal("contact: singular pencil"))?;
        let (qa, qb) = (sign_at(a, &x), sign_at(b, &x));
        if qa < 0 && qb < 0 {
            return Ok(x);
        }
        if qa >= 0 {
            lo = Some(l.clone());
        } else {
            hi = Some(l.clone());
        }
        l = match (&lo, &hi) {
            (Some(x), Some(y)) => (x + y) / &two,
            (Some(x), None) => x * &two,
            (None, Some(y)) => y / &two,
            (None, None) => unreachable!(),
        };
    }
    Err(crate::Error::internal(
        "contact: no point inside both found",
    ))
}

/// The pair as the exact route holds it: the canonical forms, their
/// integer matrices (`L_A·A`, `L_B·B`), `κ = L_A/L_B` and the centres.
struct Ctx<'a> {
    a: &'a QuadricForm,
    b: &'a QuadricForm,
    ai: &'a [[BigInt; 4]; 4],
    bi: &'a [[BigInt; 4]; 4],
    kappa: &'a Q,
    ca: &'a [Q; 3],
    cb: &'a [Q; 3],
}

/// The kind of an overlap and its evidence (`f` of the integer matrices).
fn kind_of(ctx: &Ctx<'_>, f: &ZPoly) -> Result<(Kind, Option<super::Evidence>), crate::Error> {
    use super::Evidence;
    let (a, b) = (ctx.a, ctx.b);
    let am = matrix(a);
    let bm = matrix(b);
    // identical up to a positive factor: B = μA
    if let Some(mu) = proportional(&am, &bm) {
        return Ok((Kind::Identical, Some(Evidence::Identical { mu })));
    }
    let mut neg_roots: Vec<RealAlg> = RealAlg::roots_of(f)
        .into_iter()
        .filter(|r| r.signum() < 0)
        .collect();
    neg_roots.sort_by(|x, y| x.cmp_exact(y));
    // one rational in each gap of (−∞, 0) between the negative roots
    let mut samples: Vec<Q> = vec![];
    let mut prev: Option<RealAlg> = None;
    for r in neg_roots
        .iter()
        .chain(std::iter::once(&RealAlg::rational(Q::zero())))
    {
        let mut r = r.clone();
        let s = match &prev {
            None => {
                let (lo, _) = r.interval();
                lo - Q::one()
            }
            Some(p) => {
                let mut p = p.clone();
                let mut s = None;
                for _ in 0..4000 {
                    let (_, p_hi) = p.interval();
                    let (r_lo, _) = r.interval();
                    if p_hi < r_lo {
                        s = Some(simplest_between(&p_hi, &r_lo));
                        break;
                    }
                    p.bisect();
                    r.bisect();
                }
                s.ok_or_else(|| crate::Error::internal("contact: roots not separated"))?
            }
        };
        samples.push(s);
        prev = Some(r);
    }
    for s in &samples {
        if !s.is_negative() {
            continue;
        }
        // s·A' + B' is a positive multiple of (κs)·A + B
        let mu = -(s * ctx.kappa);
        match definite_z(ctx.ai, ctx.bi, s.numer(), s.denom()) {
            Some(-1) => {
                return Ok((Kind::AInsideB, Some(Evidence::Inside { mu })));
            }
            Some(1) => {
                return Ok((Kind::BInsideA, Some(Evidence::Inside { mu })));
            }
            _ => {}
        }
    }
    // semidefinite at a multiple negative root: touching from inside
    for (fac, mult) in f.squarefree_decomposition() {
        if mult < 2 {
            continue;
        }
        for l0 in small_roots(&fac) {
            if l0.signum() >= 0 {
                continue;
            }
            let l0 = l0.scale(ctx.kappa);
            let m = pencil_at(a, b, &l0);
            // a touching point: the kernel of λ₀A + B with last coordinate 1
            // (when the 3×3 block is invertible; else the kind stands on
            // the gap samples, below, without a point)
            let x = kernel_point(a, b, &l0)
                .map(|(x, _)| x)
                .filter(|x| value_s(a, x).is_zero() && value_s(b, x).is_zero());
            for s in [-1, 1] {
                if semidefinite(&m, s) {
                    // no gap gave a definite pencil, so the containment is
                    // not strict: the surfaces meet (S-lemma, module doc)
                    return Ok((
                        Kind::InternallyTouching,
                        Some(Evidence::Semidefinite {
                            mu: l0.neg(),
                            a_in_b: s < 0,
                            point: x,
                        }),
                    ));
                }
            }
        }
    }
    // neither contains the other: a point of each outside the other
    let a_only = outside_point(a, b, ctx.ca, ctx.cb);
    let b_only = outside_point(b, a, ctx.cb, ctx.ca);
    Ok((
        Kind::SurfacesCross,
        Some(Evidence::Cross { a_only, b_only }),
    ))
}

/// `B = μA` with μ > 0?
fn proportional(a: &[[Q; 4]; 4], b: &[[Q; 4]; 4]) -> Option<Q> {
    let (i, j) = (0..4)
        .flat_map(|i| (0..4).map(move |j| (i, j)))
        .find(|&(i, j)| !a[i][j].is_zero())?;
    let mu = &b[i][j] / &a[i][j];
    if !mu.is_positive() {
        return None;
    }
    for i in 0..4 {
        for j in 0..4 {
            if &a[i][j] * &mu != b[i][j] {
                return None;
            }
        }
    }
    Some(mu)
}

/// A rational point with `q_P < 0 < q_O` (inside P, outside O), searched
/// along rays from P's centre: the direction away from O's centre, P's
/// coordinate axes and the diagonals, each at 0.999 of the way to P's
/// surface (a rational below the square root).
fn outside_point(p: &QuadricForm, o: &QuadricForm, cp: &[Q; 3], co: &[Q; 3]) -> Option<[Q; 3]> {
    let mut dirs: Vec<[Q; 3]> = vec![std::array::from_fn(|i| &cp[i] - &co[i])];
    for x in -1i64..=1 {
        for y in -1i64..=1 {
            for z in -1i64..=1 {
                if (x, y, z) != (0, 0, 0) {
                    dirs.push([
                        Q::from_integer(x.into()),
                        Q::from_integer(y.into()),
                        Q::from_integer(z.into()),
                    ]);
                }
            }
        }
    }
    let depth = neg(&value_fast(p, cp)); // −q_P(c_P) > 0
    if let Some(x) = outside_search(p, o, cp) {
        return Some(x);
    }
    for v in dirs {
        // q_P(c + s v) = q_P(c) + s²·vᵀWv
        let vwv = {
            let mut s = Q::zero();
            for i in 0..3 {
                for j in 0..3 {
                    s += &p.a[i][j] * &v[i] * &v[j];
                }
            }
            s
        };
        if !vwv.is_positive() {
            continue;
        }
        let s2 = &depth / &vwv; // s_max²
        let (lo, _) = crate::number::sqrt_bounds(&s2, 40);
        for frac in [999i64, 9] {
            let s = &lo * Q::new(frac.into(), (frac + 1).into());
            let x: [Q; 3] = std::array::from_fn(|i| &cp[i] + &s * &v[i]);
            if sign_at(p, &x) < 0 && sign_at(o, &x) > 0 {
                return Some(x);
            }
        }
    }
    None
}

/// The numeric search of [`outside_point`]: P's interior is
/// `{c + L⁻ᵀu : |u| < 1}` with `W_P = LLᵀ` (Cholesky, in doubles); q_O is
/// sampled at 0.999·u for 96 directions u spread on the sphere, the best
/// one refined by projected gradient ascent, and the candidates with
/// `q_O > 0` in doubles are checked exactly (as rationals).
fn outside_search(p: &QuadricForm, o: &QuadricForm, cp: &[Q; 3]) -> Option<[Q; 3]> {
    use num_traits::ToPrimitive;
    let f = |x: &Q| x.to_f64().unwrap_or(f64::NAN);
    let w: [[f64; 3]; 3] = p.a.each_ref().map(|r| r.each_ref().map(f));
    // Cholesky W = LLᵀ
    let mut l = [[0.0f64; 3]; 3];
    for i in 0..3 {
        for j in 0..=i {
            let s: f64 = w[i][j] - (0..j).map(|k| l[i][k] * l[j][k]).sum::<f64>();
            if i == j {
                if s.is_nan() || s <= 0.0 {
                    return None;
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    let depth = f(&neg(&value_fast(p, cp))).sqrt();
    let c = cp.each_ref().map(f);
    // x(u) = c + depth·L⁻ᵀu: solve Lᵀ y = u (back substitution)
    let x_of = |u: &[f64; 3]| -> [f64; 3] {
        let mut y = [0.0; 3];
        for i in (0..3).rev() {
            let s: f64 = u[i] - (i + 1..3).map(|k| l[k][i] * y[k]).sum::<f64>();
            y[i] = s / l[i][i];
        }
        std::array::from_fn(|i| c[i] + 0.999 * depth * y[i])
    };
    let wo: [[f64; 3]; 3] = o.a.each_ref().map(|r| r.each_ref().map(f));
    let (bo, co) = (o.b.each_ref().map(f), f(&o.c));
    let qo = |x: &[f64; 3]| -> f64 {
        let mut s = co;
        for i in 0..3 {
            s += 2.0 * bo[i] * x[i];
            for j in 0..3 {
                s += wo[i][j] * x[i] * x[j];
            }
        }
        s
    };
    let n = 96;
    let mut cands: Vec<(f64, [f64; 3])> = (0..n)
        .map(|k| {
            // a Fibonacci sphere
            let z = 1.0 - (2 * k + 1) as f64 / n as f64;
            let r = (1.0 - z * z).sqrt();
            let t = k as f64 * 2.399_963_229_728_653;
            let u = [r * t.cos(), r * t.sin(), z];
            (qo(&x_of(&u)), u)
        })
        .collect();
    cands.sort_by(|a, b| b.0.total_cmp(&a.0));
    // refine the best by projected gradient ascent on the sphere
    let mut u = cands[0].1;
    let mut best = cands[0].0;
    let mut step = 0.1;
    for _ in 0..60 {
        let h = 1e-6;
        let g: [f64; 3] = std::array::from_fn(|i| {
            let mut v = u;
            v[i] += h;
            (qo(&x_of(&v)) - qo(&x_of(&u))) / h
        });
        let mut v: [f64; 3] = std::array::from_fn(|i| u[i] + step * g[i]);
        let nv = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        v = v.map(|x| x / nv);
        let val = qo(&x_of(&v));
        if val > best {
            best = val;
            u = v;
            step *= 1.5;
        } else {
            step *= 0.5;
        }
    }
    cands.insert(0, (best, u));
    for (val, u) in cands.iter().take(8) {
        if val.is_nan() || *val <= 0.0 {
            break;
        }
        let x = x_of(u);
        let Some(xq) = x
            .iter()
            .map(|v| Q::from_float(*v))
            .collect::<Option<Vec<Q>>>()
        else {
            continue;
        };
        let xq: [Q; 3] = [xq[0].clone(), xq[1].clone(), xq[2].clone()];
        if sign_at(p, &xq) < 0 && sign_at(o, &xq) > 0 {
            return Some(xq);
        }
    }
    None
}

/// Hints from the filter, already in the canonical normalisation.
#[derive(Clone, Debug)]
pub(crate) enum Hint {
    Lambda(Q),
    Point([Q; 3]),
}

/// `Σ cₖλᵏ` exactly.
#[cfg(test)]
pub(crate) fn eval(c: &[Q], l: &Q) -> Q {
    super::program::horner(c, l)
}
