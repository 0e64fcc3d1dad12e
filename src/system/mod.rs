//! Zero-dimensional polynomial systems in x, y, z: Gröbner bases over Q
//! ([`groebner`]) and modulo word primes ([`groebner_modp`], F4), the
//! quotient algebra `Q[x]/I` ([`quotient`]), the rational univariate
//! representation (RUR) by its three routes — over Q from a Gröbner basis
//! ([`rur_groebner`]), multi-modular with an exact check ([`rur_modular`],
//! [`rur_check`]), and from resultants of a square system that need no
//! check ([`square_resultant`], [`rur_square`]) — and certified boxes
//! around the zeros ([`krawczyk`], its floating-point filter
//! [`krawczyk_filter`], and the census of all complex zeros, [`census`]).
//!
//! Key idea: every route ends in the same exact object, a RUR
//! `D(u) = 0, x = Gx(u)/Φ(u), …` whose real zeros are the real roots of one
//! univariate integer polynomial (the floor below, [`crate::roots`]); the
//! routes differ in how much they compute over Q and what certifies the
//! result (an exact check, a resultant bound, a census of boxes).  This
//! floor sits above `roots` (univariate) and `elim` (resultants) and below
//! `geom` and the two domains.

pub mod census;
pub mod groebner;
pub mod groebner_modp;
pub mod krawczyk;
pub mod krawczyk_filter;
pub mod quotient;
pub mod rur_check;
pub mod rur_groebner;
pub mod rur_modular;
pub mod rur_square;
pub mod square_resultant;

pub(crate) use rur_groebner::linear_form;
pub use rur_groebner::{GENERIC_FORMS, Rur, solve_zero_dim};
