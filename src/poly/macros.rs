//! Operator forwarding for the polynomial types (as num-bigint's
//! `macros.rs`): each type implements `&a op &b` once, and these macros
//! derive the owned and mixed forms from it.

/// `Add`, `Sub`, `Mul` on owned and mixed operands of `$ty<$p>` through
/// the by-reference implementation, and `Neg` on an owned value through
/// `-&value`.
macro_rules! forward_owned_ops {
    ($ty:ident, $p:ident) => {
        $crate::poly::macros::forward_owned_ops!(@bin $ty, $p, Add, add);
        $crate::poly::macros::forward_owned_ops!(@bin $ty, $p, Sub, sub);
        $crate::poly::macros::forward_owned_ops!(@bin $ty, $p, Mul, mul);
        impl<$p: Ring> Neg for $ty<$p> {
            type Output = $ty<$p>;
            fn neg(self) -> $ty<$p> {
                -&self
            }
        }
    };
    (@bin $ty:ident, $p:ident, $tr:ident, $m:ident) => {
        impl<$p: Ring> $tr for $ty<$p> {
            type Output = $ty<$p>;
            fn $m(self, o: $ty<$p>) -> $ty<$p> {
                (&self).$m(&o)
            }
        }
        impl<$p: Ring> $tr<&$ty<$p>> for $ty<$p> {
            type Output = $ty<$p>;
            fn $m(self, o: &$ty<$p>) -> $ty<$p> {
                (&self).$m(o)
            }
        }
        impl<$p: Ring> $tr<$ty<$p>> for &$ty<$p> {
            type Output = $ty<$p>;
            fn $m(self, o: $ty<$p>) -> $ty<$p> {
                self.$m(&o)
            }
        }
    };
}
pub(crate) use forward_owned_ops;
