//! Separable surfaces: `S = f₁(x) + f₂(y) + f₃(z)` against an ellipsoid
//! with axes parallel to the coordinate axes, when only one coordinate is
//! "general" (paper 004's Example 4 and its kind).
//!
//! Write `E = Σ Aᵢ wᵢ² − R` with `wᵢ = xᵢ − pᵢ` (p the centre, Aᵢ, R > 0).
//! The Lagrange conditions split by coordinate: `fᵢ'(xᵢ) = 2λAᵢwᵢ`.  A
//! coordinate j is *proportional* when `fⱼ'(xⱼ) = 2κⱼAⱼwⱼ` identically
//! (fⱼ is κⱼ times E's square in that coordinate, up to a constant); its
//! condition reads `wⱼ·(κⱼ − λ) = 0`.  With exactly one other coordinate g
//! (the general one), every critical point lies on one of these branches,
//! and every point of a branch is critical:
//!
//! * **axis branch**: `wⱼ = 0` for both proportional j, so
//!   `ρ(x_g) := R − A_g w_g² = 0` (two real points on the g-axis);
//! * **one branch per distinct κ** among the proportional coordinates:
//!   `λ = κ`, x_g a root of `h_κ = f_g'(x_g) − 2κA_g w_g`, the free
//!   coordinates (those with κⱼ = κ) on `Σ Aⱼwⱼ² = ρ(x_g)` and the others
//!   at the centre.  Such a point is real iff x_g is real and `ρ(x_g) ≥ 0`
//!   (a curve of critical points when two coordinates are free and ρ > 0).
//!
//! On every branch S takes the value `V(x_g) = S_g(x_g) + κ·ρ(x_g)`, where
//! `S_g` is S on the g-axis through the centre (κ = 0 on the axis branch),
//! so the branch's value polynomial is the univariate resultant
//! `Res_x(h, u − V(x))` and D(u) is the square-free product over branches —
//! the paper's resultant elimination with branch splitting, done in one
//! variable.  The real critical values are `V(ξ)` over the real roots ξ of
//! h with `ρ(ξ) ≥ 0`, decided exactly; the other roots of D(u) are values
//! at non-real points.

use super::ellipsoid::Ellipsoid;
use super::witness::WitnessSearch;
use super::witness::{WitnessPoint, find_witness};
use crate::number::{Q, sqrt_bounds};
use crate::poly::mpoly::{X, Y, Z};
use crate::poly::{QMPoly, QPoly, ZPoly};
use crate::roots::{RealAlg, value_polynomial, values_with};
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// One branch of the critical set.
#[derive(Clone, Debug)]
pub struct SeparableBranch {
    /// λ on the branch (`None` on the axis branch, where λ varies).
    pub lambda: Option<Q>,
    /// The proportional coordinates that are free on the branch.
    pub free: Vec<usize>,
    /// The polynomial whose roots are the general coordinate (square-free).
    pub coordinate_poly: ZPoly,
    /// S on the branch as a polynomial in the general coordinate.
    pub value_map: QPoly,
    /// `Res_x(coordinate_poly, u − value_map)`, square-free.
    pub value_poly: ZPoly,
    /// Real roots of `coordinate_poly` that carry real points, with the
    /// value of S there.
    pub real_points: Vec<(RealAlg, RealAlg)>,
    /// Real roots of `coordinate_poly` whose points are not real (ρ < 0).
    pub nonreal_roots: usize,
    /// True when the real points form curves (two free coordinates, ρ > 0).
    pub curves: bool,
}

/// The separable analysis.
#[derive(Clone, Debug)]
pub struct SeparableAnalysis {
    /// Index of the general coordinate (0, 1, 2 for x, y, z).
    pub general: usize,
    /// κⱼ of the proportional coordinates (`None` at the general one).
    pub kappa: [Option<Q>; 3],
    /// `ρ(x_g) = R − A_g (x_g − p_g)²`.
    pub rho: QPoly,
    /// The branches (axis branch first).
    pub branches: Vec<SeparableBranch>,
    /// D(u): the square-free product of the branch value polynomials.
    pub judging: ZPoly,
    /// E's diagonal `Aᵢ` and centre.
    axes: [Q; 3],
    center: [Q; 3],
}

/// Detects the separable case and analyses it; `None` when S or E do not
/// have the shape (the general routes apply).
pub fn analyze(e: &Ellipsoid, s: &QMPoly) -> Option<SeparableAnalysis> {
    let a = &e.form.a;
    if (0..3).any(|i| (0..3).any(|j| i != j && !a[i][j].is_zero())) {
        return None;
    }
    if s.terms()
        .iter()
        .any(|(ex, _)| ex.iter().filter(|&&k| k > 0).count() > 1)
    {
        return None;
    }
    let axes: [Q; 3] = std::array::from_fn(|i| a[i][i].clone());
    let center = e.center.clone();
    let r = -&e.center_value;
    let two = Q::from_integer(2.into());
    // S on each coordinate axis through the centre
    let lines: Vec<QPoly> = (0..3)
        .map(|i| {
            let mut p = s.clone();
            for v in [X, Y, Z] {
                if v != i {
                    p = p.eval_var(v, &center[v]);
                }
            }
            p.to_univariate(i).unwrap_or_else(QPoly::zero)
        })
        .collect();
    // proportional coordinates: f' = 2κA(x − p)
    let kappa: [Option<Q>; 3] = std::array::from_fn(|i| {
        let d = lines[i].derivative();
        match d.degree() {
            None => Some(Q::zero()),
            Some(1) if crate::roots::eval_q(&d, &center[i]).is_zero() => {
                Some(&d.coeff(1) / &(&two * &axes[i]))
            }
            _ => None,
        }
    });
    let general: Vec<usize> = (0..3).filter(|&i| kappa[i].is_none()).collect();
    let [g] = general[..] else {
        return None;
    };
    let w = QPoly::new(vec![-&center[g], Q::one()]);
    let rho = &QPoly::constant(r) - &(&w * &w).scale(&axes[g]);
    let sg = &lines[g];
    let mut branches = vec![branch(None, vec![], &rho, sg, &rho)];
    let mut ks: Vec<Q> = kappa.iter().flatten().cloned().collect();
    ks.sort();
    ks.dedup();
    for k in ks {
        let free: Vec<usize> = (0..3).filter(|&j| kappa[j].as_ref() == Some(&k)).collect();
        let h = &sg.derivative() - &w.scale(&(&two * &k * &axes[g]));
        let v = sg + &rho.scale(&k);
        branches.push(branch(Some(k), free, &h, &v, &rho));
    }
    let mut judging = ZPoly::constant(1.into());
    for b in &branches {
        judging = &judging * &b.value_poly;
    }
    let judging = judging.squarefree_part();
    Some(SeparableAnalysis {
        general: g,
        kappa,
        rho,
        branches,
        judging,
        axes,
        center,
    })
}

/// One branch: roots of `h`, the real ones with `ρ ≥ 0`, values `v`.
fn branch(
    lambda: Option<Q>,
    free: Vec<usize>,
    h: &QPoly,
    v: &QPoly,
    rho: &QPoly,
) -> SeparableBranch {
    let (hz, _) = ZPoly::from_q(h);
    let hz = hz.squarefree_part();
    let one = QPoly::constant(Q::one());
    if hz.degree().unwrap_or(0) == 0 {
        return SeparableBranch {
            lambda,
            free,
            coordinate_poly: hz,
            value_map: v.clone(),
            value_poly: ZPoly::constant(1.into()),
            real_points: vec![],
            nonreal_roots: 0,
            curves: false,
        };
    }
    let value_poly = value_polynomial(&hz, v, &one);
    let roots = RealAlg::roots_of(&hz);
    let (real, nonreal): (Vec<RealAlg>, Vec<RealAlg>) = if lambda.is_none() {
        (roots, vec![])
    } else {
        roots.into_iter().partition(|x| x.sign_of_q(rho) >= 0)
    };
    let curves = free.len() > 1 && real.iter().any(|x| x.sign_of_q(rho) > 0);
    let values = values_with(&hz, &real, v, &one, &value_poly);
    let real_points = real
        .into_iter()
        .zip(values)
        .map(|(x, val)| (x, val.expect("denominator 1")))
        .collect();
    SeparableBranch {
        lambda,
        free,
        coordinate_poly: hz,
        value_map: v.clone(),
        value_poly,
        real_points,
        nonreal_roots: nonreal.len(),
        curves,
    }
}

impl SeparableAnalysis {
    /// The values attained by real critical points.
    pub fn real_values(&self) -> Vec<RealAlg> {
        self.branches
            .iter()
            .flat_map(|b| b.real_points.iter().map(|(_, v)| v.clone()))
            .collect()
    }

    /// True when some branch has curves of real critical points.
    pub fn has_curves(&self) -> bool {
        self.branches.iter().any(|b| b.curves)
    }
}

impl WitnessSearch for SeparableAnalysis {
    /// A witness near a real critical point whose value is `v`.
    fn witness(&self, v: &RealAlg, e: &Ellipsoid, s: &QMPoly, want: i32) -> Option<WitnessPoint> {
        let (b, xi) = self.branches.iter().find_map(|b| {
            b.real_points
                .iter()
                .find(|(_, w)| w.cmp_exact(v) == Ordering::Equal)
                .map(|(x, _)| (b, x))
        })?;
        let g = self.general;
        let approx = |bits: u32| -> Option<[Q; 3]> {
            let mut p = self.center.clone();
            p[g] = xi.to_rational_approx(bits);
            if let Some(&j) = b.free.first() {
                // the whole ρ on one free coordinate: A_j w_j² = ρ(x_g)
                let rho = crate::roots::eval_q(&self.rho, &p[g]);
                let rho = if rho.is_negative() { Q::zero() } else { rho };
                let (wj, _) = sqrt_bounds(&(&rho / &self.axes[j]), bits);
                p[j] = &self.center[j] + &wj;
            }
            Some(p)
        };
        find_witness(e, s, want, false, &approx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn run(e: &str, s: &str) -> Option<SeparableAnalysis> {
        let e = Ellipsoid::from_poly(&parse_poly(e).unwrap()).unwrap();
        analyze(&e, &parse_poly(s).unwrap())
    }

    #[test]
    fn detects_the_shape() {
        // paper 004 Example 4: x general, y and z proportional (κ = 1/12, 1/23)
        let a = run("2x^2+3y^2+4z^2-25", "(x-1)^4/9+y^2/4+4z^2/23-1").unwrap();
        assert_eq!(a.general, 0);
        assert_eq!(a.kappa[1], Some(crate::number::q(1, 12)));
        assert_eq!(a.kappa[2], Some(crate::number::q(1, 23)));
        assert_eq!(a.branches.len(), 3);
        assert_eq!(a.judging.degree(), Some(8));
        // rotated E, mixed monomials in S, two general coordinates: declined
        assert!(run("2x^2+3y^2+4z^2+xy-25", "x^4+y^2+z^2").is_none());
        assert!(run("x^2+y^2+z^2-4", "x^3+xy+z^2").is_none());
        assert!(run("x^2+y^2+z^2-4", "x^4+y^4+z^2").is_none());
    }

    #[test]
    fn off_centre_ellipsoid_and_curves() {
        // E centred at (1, -1, 2); S's y, z part is −3·(E's y, z squares):
        // one branch λ = −3 with y and z free, h = 3x² + 6(x − 1), roots
        // x = −1 ± √3; ρ = 9 − (x − 1)² is > 0 at −1 + √3 (a curve of
        // critical points) and < 0 at −1 − √3 (non-real points)
        let a = run("(x-1)^2+2(y+1)^2+(z-2)^2-9", "x^3-6(y+1)^2-3(z-2)^2+5").unwrap();
        assert_eq!(a.general, 0);
        assert_eq!(a.branches.len(), 2);
        let b = &a.branches[1];
        assert_eq!(b.lambda, Some(crate::number::qi(-3)));
        assert_eq!(b.free, vec![1, 2]);
        assert!(b.curves && a.has_curves());
        assert_eq!((b.real_points.len(), b.nonreal_roots), (1, 1));
        // the value there is V(ξ) = ξ³ + 5 − 3ρ(ξ) at ξ = −1 + √3
        let xi = &b.real_points[0].0;
        assert_eq!(xi.sign_of(&ZPoly::from_i64s(&[-2, 2, 1])), 0);
        let x = xi.to_rational_approx(80);
        let rho = crate::roots::eval_q(&a.rho, &x);
        let want = &x * &x * &x + crate::number::qi(5) - &rho * crate::number::qi(3);
        let got = b.real_points[0].1.to_rational_approx(80);
        assert!((&want - &got).abs() < crate::number::q(1, 1 << 30));
    }
}
