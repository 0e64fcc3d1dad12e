//! Exact rigid motions: Cayley rotations (exact rational orthogonal
//! matrices) and the image of a polynomial surface under a rotation.

use crate::number::{Q, qi};
use crate::poly::QMPoly;
use crate::poly::mpoly::{MPoly, NVARS};
use num_traits::{One, Zero};

/// The Cayley rotation of the rational vector `(a, b, c)`: an exact
/// rational orthogonal matrix with determinant 1 (every rotation whose angle
/// is not π has this form).
pub fn cayley_rotation(a: &Q, b: &Q, c: &Q) -> [[Q; 3]; 3] {
    let n = a * a + b * b + c * c;
    let d = Q::one() + &n;
    let two = qi(2);
    let m = [
        [
            Q::one() + a * a - b * b - c * c,
            &two * (a * b - c),
            &two * (a * c + b),
        ],
        [
            &two * (a * b + c),
            Q::one() - a * a + b * b - c * c,
            &two * (b * c - a),
        ],
        [
            &two * (a * c - b),
            &two * (b * c + a),
            Q::one() - a * a - b * b + c * c,
        ],
    ];
    std::array::from_fn(|i| std::array::from_fn(|j| &m[i][j] / &d))
}

/// `p(Rᵀ x)`: the polynomial of the rotated surface.
pub fn rotate(p: &QMPoly, r: &[[Q; 3]; 3]) -> QMPoly {
    let mut subs: [Option<QMPoly>; NVARS] = Default::default();
    for (i, s) in subs.iter_mut().enumerate().take(3) {
        let mut acc = MPoly::zero();
        for j in 0..3 {
            acc = &acc + &MPoly::var(j).scale(&r[j][i]);
        }
        *s = Some(acc);
    }
    p.substitute_all(&subs)
}

/// True when `r` is a rotation: `r rᵀ = I` and `det r = 1`.
pub fn is_rotation(r: &[[Q; 3]; 3]) -> bool {
    let orthogonal = (0..3).all(|i| {
        (0..3).all(|j| {
            let s: Q = (0..3).map(|k| &r[i][k] * &r[j][k]).sum();
            if i == j { s.is_one() } else { s.is_zero() }
        })
    });
    orthogonal && super::matrix::det3(r).is_one()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::q;

    #[test]
    fn cayley_rotations_are_rotations() {
        for (a, b, c) in [
            (qi(1), q(2, 3), qi(-2)),
            (qi(0), qi(0), qi(0)),
            (q(-5, 7), qi(3), q(1, 9)),
        ] {
            let r = cayley_rotation(&a, &b, &c);
            assert!(is_rotation(&r));
        }
        let mut r = cayley_rotation(&qi(1), &qi(2), &qi(3));
        r[0][0] += qi(1);
        assert!(!is_rotation(&r));
        // a reflection is orthogonal but not a rotation
        let refl = [
            [qi(-1), qi(0), qi(0)],
            [qi(0), qi(1), qi(0)],
            [qi(0), qi(0), qi(1)],
        ];
        assert!(!is_rotation(&refl));
    }

    #[test]
    fn rotating_a_sphere_about_its_centre_keeps_it() {
        let p = crate::poly::parse_poly("x^2+y^2+z^2-1").unwrap();
        let r = cayley_rotation(&q(1, 2), &qi(-1), &q(3, 4));
        assert_eq!(rotate(&p, &r), p);
        let e = crate::poly::parse_poly("x^2+2y^2+3z^2-1").unwrap();
        assert_ne!(rotate(&e, &r), e);
    }
}
