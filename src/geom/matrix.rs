//! Small exact matrices: 3×3 over Q (determinant, inverse) and the 4×4
//! integer matrices of quadrics (adjugate of the leading block).

use crate::number::Q;
use num_bigint::BigInt;

/// A 4×4 integer matrix `[[A, b], [bᵀ, c]]`.
pub type Mat4 = [[BigInt; 4]; 4];

/// Adjugate and determinant of the leading 3×3 block of an integer matrix.
pub fn adj3_int(m: &Mat4) -> ([[BigInt; 3]; 3], BigInt) {
    let cof = |i: usize, j: usize| -> BigInt {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        &m[r0][c0] * &m[r1][c1] - &m[r0][c1] * &m[r1][c0]
    };
    // adj[i][j] = cofactor(j, i); the cyclic index choice carries the sign
    let adj: [[BigInt; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| cof(j, i)));
    let det: BigInt = (0..3).map(|j| &m[0][j] * &adj[j][0]).sum();
    (adj, det)
}

/// Determinant of a 3×3 rational matrix.
pub fn det3(a: &[[Q; 3]; 3]) -> Q {
    &a[0][0] * (&a[1][1] * &a[2][2] - &a[1][2] * &a[2][1])
        - &a[0][1] * (&a[1][0] * &a[2][2] - &a[1][2] * &a[2][0])
        + &a[0][2] * (&a[1][0] * &a[2][1] - &a[1][1] * &a[2][0])
}
