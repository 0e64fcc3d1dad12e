//! Exact numbers `(u + v√d)/den` with integers `u, v, den` (`den > 0`) for
//! the constructions: the arithmetic of Q(√d) without a gcd per operation
//! (STYLE: denominators cleared once — [`Zf::to_qsqrt`] reduces once, at
//! the output).  All operands of one construction share the radicand `d`,
//! a positive integer that is not a square (or `d = 1`: rationals).

use crate::number::{Q, QSqrt};
use num_bigint::BigInt as Z;
use num_traits::{One, Signed, Zero};

/// `(u + v√d)/den`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Zf {
    pub u: Z,
    pub v: Z,
    pub den: Z,
}

/// The sign of `u + v√d` (`d > 0`).
pub(crate) fn sign_uv(u: &Z, v: &Z, d: &Z) -> i32 {
    let (su, sv) = (sgn(u), sgn(v));
    if sv == 0 || su == sv {
        return su;
    }
    if su == 0 {
        return sv;
    }
    // opposite signs: compare u² with v²d
    su * sgn(&(u * u - v * v * d))
}

fn sgn(x: &Z) -> i32 {
    match x.sign() {
        num_bigint::Sign::Minus => -1,
        num_bigint::Sign::NoSign => 0,
        num_bigint::Sign::Plus => 1,
    }
}

impl Zf {
    /// The integer `x`.
    pub fn int(x: Z) -> Zf {
        Zf {
            u: x,
            v: Z::zero(),
            den: Z::one(),
        }
    }

    /// `(u + v√d)/1`.
    pub fn uv(u: Z, v: Z) -> Zf {
        Zf {
            u,
            v,
            den: Z::one(),
        }
    }

    pub fn zero() -> Zf {
        Zf::int(Z::zero())
    }

    pub fn is_zero(&self) -> bool {
        self.u.is_zero() && self.v.is_zero()
    }

    /// The exact sign.
    pub fn sign(&self, d: &Z) -> i32 {
        sign_uv(&self.u, &self.v, d)
    }

    pub fn add(&self, o: &Zf) -> Zf {
        if self.den == o.den {
            return Zf {
                u: &self.u + &o.u,
                v: &self.v + &o.v,
                den: self.den.clone(),
            };
        }
        Zf {
            u: &self.u * &o.den + &o.u * &self.den,
            v: &self.v * &o.den + &o.v * &self.den,
            den: &self.den * &o.den,
        }
    }

    pub fn neg(&self) -> Zf {
        Zf {
            u: -&self.u,
            v: -&self.v,
            den: self.den.clone(),
        }
    }

    pub fn sub(&self, o: &Zf) -> Zf {
        self.add(&o.neg())
    }

    pub fn mul(&self, o: &Zf, d: &Z) -> Zf {
        Zf {
            u: &self.u * &o.u + &self.v * &o.v * d,
            v: &self.u * &o.v + &self.v * &o.u,
            den: &self.den * &o.den,
        }
    }

    /// `self · k` for an integer `k`.
    pub fn scale(&self, k: &Z) -> Zf {
        Zf {
            u: &self.u * k,
            v: &self.v * k,
            den: self.den.clone(),
        }
    }

    /// `self / k` for an integer `k ≠ 0`.
    pub fn div_z(&self, k: &Z) -> Zf {
        debug_assert!(!k.is_zero());
        let den = &self.den * k;
        if den.is_negative() {
            Zf {
                u: -&self.u,
                v: -&self.v,
                den: -den,
            }
        } else {
            Zf {
                u: self.u.clone(),
                v: self.v.clone(),
                den,
            }
        }
    }

    /// `1/self` (`self ≠ 0`): `den·(u − v√d)/(u² − v²d)`.
    pub fn inv(&self, d: &Z) -> Zf {
        let n = &self.u * &self.u - &self.v * &self.v * d;
        Zf {
            u: &self.u * &self.den,
            v: -(&self.v * &self.den),
            den: Z::one(),
        }
        .div_z(&n)
    }

    /// `self / o` (`o ≠ 0`).
    pub fn div(&self, o: &Zf, d: &Z) -> Zf {
        self.mul(&o.inv(d), d)
    }

    /// The value as an element of Q(√d) (reduced: one gcd per part).
    pub fn to_qsqrt(&self, d: &Z) -> QSqrt {
        let q = |n: &Z| crate::number::q_new(n.clone(), self.den.clone());
        if self.v.is_zero() || d.is_one() {
            return QSqrt::rational(q(&(&self.u + &self.v)));
        }
        QSqrt::from_parts_nonsquare(q(&self.u), q(&self.v), Q::from_integer(d.clone()))
    }
}

/// A radicand for a construction: `d` itself when it is not a square, else
/// 1 with the square root returned (so that `u + v√d = u + v·r`).
pub(crate) fn radicand(d: Z) -> (Z, Option<Z>) {
    if d.is_one() {
        return (d, Some(Z::one()));
    }
    match crate::number::exact_sqrt_z(&d) {
        Some(r) => (Z::one(), Some(r)),
        None => (d, None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn field_operations_match_qsqrt() {
        let d = Z::from(7);
        let x = Zf {
            u: Z::from(3),
            v: Z::from(-2),
            den: Z::from(5),
        };
        let y = Zf {
            u: Z::from(-1),
            v: Z::from(4),
            den: Z::from(3),
        };
        let (qx, qy) = (x.to_qsqrt(&d), y.to_qsqrt(&d));
        assert!(x.add(&y).to_qsqrt(&d).sub(&qx.add(&qy)).is_zero());
        assert!(x.mul(&y, &d).to_qsqrt(&d).sub(&qx.mul(&qy)).is_zero());
        assert!(
            x.div(&y, &d)
                .to_qsqrt(&d)
                .sub(&qx.div(&qy).unwrap())
                .is_zero()
        );
        assert_eq!(x.sign(&d), qx.signum());
        assert_eq!(y.sign(&d), qy.signum());
        // 3 − 2√7 < 0, −1 + 4√7 > 0
        assert_eq!((x.sign(&d), y.sign(&d)), (-1, 1));
    }
}
