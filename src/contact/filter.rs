//! The floating-point filter of the contact predicate: the quartic's
//! coefficients in `f64` with rigorous error bounds ([`super::program`]), a
//! numeric search of the dual, and two certified tests.
//!
//! For λ > 0 the function `φ_λ = λ·q_A + q_B` is a strictly convex
//! quadratic whose minimum is `m(λ) = f(λ)/h(λ)` (`f = det(λA + B)`,
//! `h = det(λM_A + M_B) > 0`, the Schur complement).  So
//!
//! * **separated** as soon as `f(λ) > 0` at one λ > 0: then `φ_λ > 0`
//!   everywhere, and no point has `q_A ≤ 0` and `q_B ≤ 0`;
//! * **overlapping** as soon as one point has `q_A < 0` and `q_B < 0`.
//!
//! `m` is concave with `m'(λ) = q_A(x_λ)` (`x_λ` the minimiser of `φ_λ`),
//! so its maximiser λ* is found by a safeguarded Newton iteration on the
//! sign of `G = f'h − fh'` (the sign of m'), which falls from
//! `q_A(c_B)` at 0⁺ to `q_A(c_A) < 0` at ∞.  By strong duality (Slater)
//! `m(λ*) = min { q_B(x) : q_A(x) ≤ 0 }`: positive when separated, zero when
//! touching, negative when overlapping.  Separated: `f(λ*)` is certified
//! positive from the coefficients' error bounds.  Overlapping: `x_{λ*}`
//! lies on A (`m'(λ*) = 0`) inside B; moved towards `c_A` by half the way
//! to where q_B could reach 0 (convexity of q_B), it is a point inside both,
//! certified by evaluating both forms at its (exact) double coordinates.
//! A touching pair, or one too close to touching for doubles, is left to
//! the exact route (`None`).

use super::program::{Mag, Pencil, U, err, pencil, pose_form, pose_value};
use super::{Contact, Pose};

/// What the filter proved, with the evidence the report turns into a
/// certificate.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Filtered {
    /// `f(λ) > 0` at this λ (in the scaled normalisation of the module
    /// [`super::program`]: the forms `|K(x − c)|² − σ²`).
    Separated { lambda: f64 },
    /// Both forms are negative at this point.
    Overlapping { point: [f64; 3] },
}

impl Filtered {
    pub(crate) fn contact(&self) -> Contact {
        match self {
            Filtered::Separated { .. } => Contact::Separated,
            Filtered::Overlapping { .. } => Contact::Overlapping,
        }
    }
}

/// The pose's data in both runs.
struct Both {
    k: [[f64; 3]; 3],
    km: [[Mag; 3]; 3],
    rho: f64,
    rhom: Mag,
}

fn mags3(x: &[f64; 3]) -> [Mag; 3] {
    [Mag(x[0].abs()), Mag(x[1].abs()), Mag(x[2].abs())]
}

fn mags33(x: &[[f64; 3]; 3]) -> [[Mag; 3]; 3] {
    [mags3(&x[0]), mags3(&x[1]), mags3(&x[2])]
}

/// A certified sign of an `f64` value with its [`Mag`] bound: `Some(±1)`
/// when the error bound excludes 0.
#[inline]
fn certain(v: f64, mag: Mag) -> Option<i32> {
    let e = err(mag.0);
    if !(e.is_finite() && v.is_finite()) {
        None
    } else if v > e {
        Some(1)
    } else if v < -e {
        Some(-1)
    } else {
        None
    }
}

/// The polynomials' values and derivatives at λ (plain `f64`).
#[inline]
fn evals(f: &[f64; 5], h: &[f64; 4], l: f64) -> (f64, f64, f64, f64, f64, f64) {
    let f0 = (((f[4] * l + f[3]) * l + f[2]) * l + f[1]) * l + f[0];
    let f1 = ((4.0 * f[4] * l + 3.0 * f[3]) * l + 2.0 * f[2]) * l + f[1];
    let f2 = (12.0 * f[4] * l + 6.0 * f[3]) * l + 2.0 * f[2];
    let h0 = ((h[3] * l + h[2]) * l + h[1]) * l + h[0];
    let h1 = (3.0 * h[3] * l + 2.0 * h[2]) * l + h[1];
    let h2 = 6.0 * h[3] * l + 2.0 * h[2];
    (f0, f1, f2, h0, h1, h2)
}

/// The maximiser of m = f/h on λ > 0 (numeric, to about 2⁻³⁰ relative;
/// `None` when m' < 0 already at 0⁺, i.e. c_B lies in A).  `done(λ)`,
/// asked at every iterate, stops the search early (a λ that already
/// proves the answer).
fn maximiser(f: &[f64; 5], h: &[f64; 4], start: f64, done: impl Fn(f64) -> bool) -> Option<f64> {
    let g = |l: f64| {
        let (f0, f1, f2, h0, h1, h2) = evals(f, h, l);
        (f1 * h0 - f0 * h1, f2 * h0 - f0 * h2)
    };
    if f[1] * h[0] - f[0] * h[1] <= 0.0 {
        return None;
    }
    // bracket lo < λ* < hi by doubling steps on a log scale
    let (mut lo, mut hi);
    let mut l = if start.is_finite() && start > 0.0 {
        start
    } else {
        1.0
    };
    if done(l) {
        return Some(l);
    }
    if g(l).0 > 0.0 {
        lo = l;
        let mut step = 2.0f64;
        loop {
            l *= step;
            if !l.is_finite() {
                return Some(lo);
            }
            if g(l).0 <= 0.0 {
                hi = l;
                break;
            }
            lo = l;
            step *= step;
        }
    } else {
        hi = l;
        let mut step = 2.0f64;
        loop {
            l /= step;
            if l == 0.0 {
                return Some(hi);
            }
            if g(l).0 > 0.0 {
                lo = l;
                break;
            }
            hi = l;
            step *= step;
        }
    }
    // safeguarded Newton on G, to ~10⁻⁹ relative (λ* needs only to lie
    // where f > 0: a band of relative width ≈ √ε at distance ε from touching)
    let mut x = (lo * hi).sqrt();
    for _ in 0..80 {
        if done(x) {
            break;
        }
        let (gv, gd) = g(x);
        if gv > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        if hi - lo <= 4.0 * U * hi {
            break;
        }
        let mut nx = x - gv / gd;
        let newton = nx > lo && nx < hi && gd < 0.0;
        if !newton {
            nx = if hi / lo > 4.0 {
                (lo * hi).sqrt()
            } else {
                0.5 * (lo + hi)
            };
        }
        let small = newton && (nx - x).abs() <= 1e-9 * x;
        x = nx;
        if small {
            break;
        }
    }
    Some(x)
}

/// Certifies `f(λ) > 0` from the coefficients and their error bounds.
fn certify_positive(f: &[f64; 5], e: &[f64; 5], l: f64) -> bool {
    // f(λ) ≥ Σ cₖλᵏ − Σ eₖλᵏ; Horner's own error ≤ γ₈·Σ|cₖ|λᵏ
    let v = (((f[4] * l + f[3]) * l + f[2]) * l + f[1]) * l + f[0];
    let a = (((f[4].abs() * l + f[3].abs()) * l + f[2].abs()) * l + f[1].abs()) * l + f[0].abs();
    let eb = (((e[4] * l + e[3]) * l + e[2]) * l + e[1]) * l + e[0];
    let bound = a * (40.0 * U) + eb * (1.0 + 40.0 * U) + 1e-300;
    v.is_finite() && bound.is_finite() && v > bound
}

/// What the filter found when it could not prove the answer: the dual
/// maximiser and the candidate point, for the exact route to try first.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Hints {
    /// λ* (scaled forms).
    pub lambda: Option<f64>,
    /// A point that should be inside both.
    pub point: Option<[f64; 3]>,
}

/// The filter: `Ok` when doubles prove the answer, else the hints.
pub(crate) fn decide(a: &Pose, b: &Pose) -> Result<Filtered, Hints> {
    let (ma, rho_a, ka) = pose_form(&a.semi_axes, &a.matrix);
    let (mb, rho_b, kb) = pose_form(&b.semi_axes, &b.matrix);
    let t: [f64; 3] = std::array::from_fn(|i| b.center[i] - a.center[i]);
    let p: Pencil<f64> = pencil(ma, rho_a, mb, rho_b, t);
    let (mma, mrho_a, kma) = pose_form(&mags3(&a.semi_axes), &mags33(&a.matrix));
    let (mmb, mrho_b, kmb) = pose_form(&mags3(&b.semi_axes), &mags33(&b.matrix));
    let tm: [Mag; 3] = std::array::from_fn(|i| Mag(b.center[i].abs() + a.center[i].abs()));
    let pm: Pencil<Mag> = pencil(mma, mrho_a, mmb, mrho_b, tm);
    let e: [f64; 5] = std::array::from_fn(|k| err(pm.f[k].0));
    if !p.rho.iter().all(|r| r.is_finite() && *r > 0.0) {
        return Err(Hints::default());
    }
    let start = p.rho[1] / p.rho[0];
    let lstar = maximiser(&p.f, &p.h, start, |l| certify_positive(&p.f, &e, l));
    if let Some(l) = lstar
        && certify_positive(&p.f, &e, l)
    {
        return Ok(Filtered::Separated { lambda: l });
    }
    // overlapping? a point inside both, certified
    let sa = Both {
        k: ka,
        km: kma,
        rho: rho_a,
        rhom: mrho_a,
    };
    let sb = Both {
        k: kb,
        km: kmb,
        rho: rho_b,
        rhom: mrho_b,
    };
    let inside_both = |x: &[f64; 3]| -> bool {
        let xm = mags3(x);
        let ca = a.center;
        let cb = b.center;
        let qa = pose_value(&sa.k, &sa.rho, &ca, x);
        let qam = pose_value(&sa.km, &sa.rhom, &mags3(&ca), &xm);
        let qb = pose_value(&sb.k, &sb.rho, &cb, x);
        let qbm = pose_value(&sb.km, &sb.rhom, &mags3(&cb), &xm);
        certain(qa, qam) == Some(-1) && certain(qb, qbm) == Some(-1)
    };
    let Some(l) = lstar else {
        // c_B lies in A (m' ≤ 0 at 0⁺)
        return if inside_both(&b.center) {
            Ok(Filtered::Overlapping { point: b.center })
        } else {
            Err(Hints {
                lambda: None,
                point: Some(b.center),
            })
        };
    };
    let hints = Hints {
        lambda: Some(l),
        point: None,
    };
    // x_λ relative to c_A: (λM_A + M_B) y = M_B t
    let hm: [f64; 6] = std::array::from_fn(|i| l * p.ma[i] + p.mb[i]);
    let u = super::program::sym_vec(&p.mb, &t);
    let Some(y) = solve_sym(&hm, &u) else {
        return Err(hints);
    };
    let qa_y = quad(&p.ma, &y) - p.rho[0];
    let d: [f64; 3] = std::array::from_fn(|i| y[i] - t[i]);
    let qb_y = quad(&p.mb, &d) - p.rho[1];
    let qb_0 = quad(&p.mb, &t) - p.rho[1]; // q_B at c_A
    if qb_y.is_nan() || qb_y >= 0.0 {
        return Err(hints);
    }
    // y' = (1 − s)·y: q_B(y') ≤ (1 − s) q_B(y) + s q_B(0) < 0 for s < s₀
    let s = if qb_0 < 0.0 {
        1.0
    } else {
        0.5 * (-qb_y / (qb_0 - qb_y))
    };
    let s = s.max((2.0 * qa_y / p.rho[0]).max(0.0)).min(1.0);
    let x: [f64; 3] = std::array::from_fn(|i| a.center[i] + (1.0 - s) * y[i]);
    if inside_both(&x) {
        return Ok(Filtered::Overlapping { point: x });
    }
    for c in [a.center, b.center] {
        if inside_both(&c) {
            return Ok(Filtered::Overlapping { point: c });
        }
    }
    Err(Hints {
        lambda: Some(l),
        point: x.iter().all(|v| v.is_finite()).then_some(x),
    })
}

/// True when the determinant of `m` is certainly non-zero in doubles.
pub(crate) fn det_nonzero(m: &[[f64; 3]; 3]) -> bool {
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let v = det(m);
    let a = m.map(|r| r.map(f64::abs));
    // the same program on |m| with + for −: the Mag bound (depth 5)
    let mag = a[0][0] * (a[1][1] * a[2][2] + a[1][2] * a[2][1])
        + a[0][1] * (a[1][0] * a[2][2] + a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] + a[1][1] * a[2][0]);
    certain(v, Mag(mag.max(super::program::TINY))).is_some_and(|s| s != 0)
}

/// `yᵀSy`.
fn quad(s: &[f64; 6], y: &[f64; 3]) -> f64 {
    let sy = super::program::sym_vec(s, y);
    super::program::dot3(y, &sy)
}

/// Solves `S y = b` for a positive definite symmetric S (Cramer).
fn solve_sym(s: &[f64; 6], b: &[f64; 3]) -> Option<[f64; 3]> {
    let adj = super::program::adj_sym(s);
    let det = super::program::det_sym(s);
    if !(det.is_finite() && det > 0.0) {
        return None;
    }
    let y = super::program::sym_vec(&adj, b);
    let y = [y[0] / det, y[1] / det, y[2] / det];
    y.iter().all(|v| v.is_finite()).then_some(y)
}

/// The plain-double Wang–Wang–Kim test (the peer of the benchmark): the
/// quartic's coefficients in `f64` and its positive roots by the usual
/// tolerance — separated when two distinct positive roots, touching when a
/// positive double root within `tol`, overlapping otherwise.  Not used by
/// any decision; it exists to be measured against.
pub fn wwk_f64(a: &Pose, b: &Pose, tol: f64) -> Contact {
    let (ma, rho_a, _) = pose_form(&a.semi_axes, &a.matrix);
    let (mb, rho_b, _) = pose_form(&b.semi_axes, &b.matrix);
    let t: [f64; 3] = std::array::from_fn(|i| b.center[i] - a.center[i]);
    let p = pencil(ma, rho_a, mb, rho_b, t);
    // roots of the quartic on λ > 0: the maximum of f there, by Newton on f'
    // from the maximiser of m (as a physics code would: one bracketed
    // search), compared with the tolerance relative to the coefficients
    let scale = p.f.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let Some(l) = maximiser(&p.f, &p.h, rho_b / rho_a, |_| false) else {
        return Contact::Overlapping;
    };
    let v = evals(&p.f, &p.h, l).0 / (scale * (1.0 + l).powi(4));
    if v > tol {
        Contact::Separated
    } else if v >= -tol {
        Contact::Touching
    } else {
        Contact::Overlapping
    }
}
