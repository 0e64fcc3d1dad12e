//! Square-free decomposition of multivariate polynomials over Q (issue 35):
//! `S = c·∏ Tᵢ^kᵢ` with the `Tᵢ` primitive integer polynomials, square-free
//! and pairwise coprime, one per multiplicity `kᵢ`.
//!
//! * **The usual case costs one specialisation per variable**
//!   ([`is_squarefree`]).  For a variable v of S, set the other variables to
//!   residues modulo a word-size prime p: if the image `s(t)` keeps S's
//!   degree in v and `gcd(s, s′) = 1` modulo p, no square of a polynomial
//!   containing v divides S.  (A factor F² with v in F would leave F̄² in s:
//!   F's leading coefficient in v divides S's, which stays non-zero, so F̄
//!   keeps its degree ≥ 1; and F̄² | s gives F̄ | gcd(s, s′), p being larger
//!   than the degree.)  Every non-constant factor contains some variable,
//!   so one such image per variable *proves* that S is square-free — no gcd
//!   is computed.  The same argument with two polynomials proves that they
//!   are coprime ([`coprime`]).
//! * **Otherwise Yun's algorithm** with respect to x gives the factors that
//!   contain x, with their multiplicities; what is left (S's content with
//!   respect to x) is decomposed with respect to y, then z.  The gcds are
//!   the heuristic gcd of Char, Geddes and Gonnet ([`gcd`]): evaluate the
//!   last variable at a large integer ξ, take the gcd of the images
//!   (recursively, down to one variable: there Brown's modular gcd of
//!   [`ZPoly`](crate::poly::ZPoly), whose cost does not grow as deg ·
//!   bits(ξ)), read a candidate back from its ξ-adic
//!   digits, and accept it only when it divides both inputs exactly — for
//!   `ξ ≥ 2·min(‖a‖∞, ‖b‖∞) + 2` an accepted candidate is the gcd.
//! * **The result is checked exactly**: `S = c·∏ Tᵢ^kᵢ` by expansion, every
//!   `Tᵢ` square-free and every pair coprime by the specialisation test.
//!   When a step gives up (a heuristic gcd exceeds its size limit, a check
//!   is not proven) there is no decomposition, and the caller works with S
//!   as given: slower, never wrong.

use super::mpoly::{MPoly, NVARS, ZMPoly};
use crate::number::Q;
use crate::number::prime31::{Fp, prime31};
use crate::number::reconstruct::symmetric_mod;
use crate::poly::QMPoly;
use crate::poly::modp::poly_gcd_mod;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// `S = constant · ∏ factor^multiplicity`: the factors primitive integer
/// polynomials with positive leading coefficient, square-free and pairwise
/// coprime (proven), multiplicities distinct and increasing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SquareFree {
    /// The rational constant c.
    pub constant: Q,
    /// `(Tᵢ, kᵢ)`, increasing in `kᵢ`.
    pub factors: Vec<(ZMPoly, u32)>,
}

impl SquareFree {
    /// True when some factor is repeated (`kᵢ ≥ 2`).
    pub fn is_proper(&self) -> bool {
        self.factors.iter().any(|(_, k)| *k >= 2)
    }
}

/// The largest size (bits) of the integers a heuristic gcd may build:
/// `bits(ξ)·(deg + 1)` per evaluation.  Beyond, the gcd gives up.
pub const MAX_HEURISTIC_BITS: u64 = 1 << 20;

/// The number of specialisations tried per variable before a test says
/// "not proven".
const TRIES: usize = 3;

/// A fixed pseudo-random sequence (xorshift) for the specialisation points.
struct Points(u64);

impl Points {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// A point with every coordinate a residue.
    fn point(&mut self, m: &Fp) -> [u64; NVARS] {
        std::array::from_fn(|_| m.reduce(self.next()))
    }
}

/// The image of `p` in `F_p[t]`: the variable `v` kept as t, the others set
/// to `point` (residues); coefficients ascending.
fn image(p: &ZMPoly, v: usize, point: &[u64; NVARS], m: &Fp) -> Vec<u64> {
    let d = p.degree_in(v).unwrap_or(0) as usize;
    let mut out = vec![0u64; d + 1];
    for (e, c) in p.terms() {
        crate::budget::check();
        let mut t = m.reduce_big(c);
        for (w, &k) in e.iter().enumerate() {
            if w != v && k > 0 {
                t = m.mul(t, m.pow(point[w], u64::from(k)));
            }
        }
        let i = e[v] as usize;
        out[i] = m.add(out[i], t);
    }
    out
}

/// The derivative of an image.
fn derivative_mod(s: &[u64], m: &Fp) -> Vec<u64> {
    (1..s.len())
        .map(|k| m.mul(s[k], m.reduce(k as u64)))
        .collect()
}

/// True when `p` is proven square-free by one specialisation per variable
/// (see the module documentation); `false` means "not proven" (p may still
/// be square-free).  Constants are square-free.
pub fn is_squarefree(p: &ZMPoly) -> bool {
    let mut pts = Points(0x9e37_79b9_7f4a_7c15);
    p.vars().into_iter().all(|v| {
        let d = p.degree_in(v).unwrap_or(0) as usize;
        (0..TRIES).any(|i| {
            let m = Fp::new(prime31(i));
            let s = image(p, v, &pts.point(&m), &m);
            s[d] != 0 && poly_gcd_mod(&m, &s, &derivative_mod(&s, &m)).len() == 1
        })
    })
}

/// True when `a` and `b` are proven coprime by one specialisation per
/// shared variable (a common factor contains a variable of both); `false`
/// means "not proven".
pub fn coprime(a: &ZMPoly, b: &ZMPoly) -> bool {
    if a.is_zero() || b.is_zero() {
        return a.is_constant() && b.is_constant() && !(a.is_zero() && b.is_zero());
    }
    let vb = b.vars();
    let mut pts = Points(0x2545_f491_4f6c_dd1d);
    a.vars().into_iter().filter(|v| vb.contains(v)).all(|v| {
        let (da, db) = (
            a.degree_in(v).unwrap_or(0) as usize,
            b.degree_in(v).unwrap_or(0) as usize,
        );
        (0..TRIES).any(|i| {
            let m = Fp::new(prime31(i));
            let pt = pts.point(&m);
            let (sa, sb) = (image(a, v, &pt, &m), image(b, v, &pt, &m));
            sa[da] != 0 && sb[db] != 0 && poly_gcd_mod(&m, &sa, &sb).len() == 1
        })
    })
}

/// The largest absolute value of a coefficient.
fn max_norm(p: &ZMPoly) -> BigInt {
    p.terms()
        .iter()
        .map(|(_, c)| c.abs())
        .max()
        .unwrap_or_else(BigInt::zero)
}

/// `p` with the variable `v` set to the integer `xi`.
fn eval_at(p: &ZMPoly, v: usize, xi: &BigInt) -> ZMPoly {
    let d = p.degree_in(v).unwrap_or(0) as usize;
    let mut pw = vec![BigInt::one()];
    for k in 1..=d {
        let next = &pw[k - 1] * xi;
        pw.push(next);
    }
    MPoly::from_terms(p.terms().iter().map(|(e, c)| {
        let mut f = *e;
        let k = f[v] as usize;
        f[v] = 0;
        (f, c * &pw[k])
    }))
}

/// The polynomial in `v` whose ξ-adic expansion (symmetric digits, one
/// polynomial in the other variables per power of `v`) is `gamma`.
fn xi_adic(gamma: &ZMPoly, v: usize, xi: &BigInt) -> ZMPoly {
    let mut rest = gamma.clone();
    let mut terms = Vec::new();
    let mut k = 0u32;
    while !rest.is_zero() {
        crate::budget::check();
        let digit = rest.map(|c| symmetric_mod(c, xi));
        for (e, c) in digit.terms() {
            let mut f = *e;
            f[v] += k;
            terms.push((f, c.clone()));
        }
        rest = (&rest - &digit).map(|c| c / xi);
        k += 1;
    }
    MPoly::from_terms(terms)
}

/// True when `d` divides `p` exactly (degrees compared first).
fn divides(d: &ZMPoly, p: &ZMPoly) -> bool {
    (0..NVARS).all(|v| d.degree_in(v) <= p.degree_in(v)) && p.div_exact(d).is_some()
}

/// The content (non-negative gcd of the coefficients) by Lehmer's gcd
/// ([`crate::number::gcd_z`]: the integers here reach 10⁵ bits, where the
/// binary gcd is several times slower).
fn content(p: &ZMPoly) -> BigInt {
    let mut g = BigInt::zero();
    for (_, c) in p.terms() {
        g = crate::number::gcd_z(&g, c);
        if g.is_one() {
            break;
        }
    }
    g
}

/// `p / content(p)`, leading coefficient positive (zero stays zero).
fn primitive(p: &ZMPoly) -> ZMPoly {
    let mut g = content(p);
    if g.is_zero() {
        return p.clone();
    }
    if p.leading().is_some_and(|(_, c)| c.is_negative()) {
        g = -g;
    }
    p.map(|c| c / &g)
}

/// The gcd of `a` and `b` with its integer content (`|content|` times the
/// primitive gcd), or `None` when the heuristic gave up.
fn gcd_with_content(a: &ZMPoly, b: &ZMPoly) -> Option<ZMPoly> {
    if a.is_zero() {
        return Some(primitive(b).scale(&content(b)));
    }
    if b.is_zero() {
        return Some(primitive(a).scale(&content(a)));
    }
    let c = crate::number::gcd_z(&content(a), &content(b));
    let g = gcd_primitive(&primitive(a), &primitive(b))?;
    Some(g.scale(&c))
}

/// The gcd of primitive non-zero `a` and `b`, primitive with positive
/// leading coefficient (heuristic gcd, see the module documentation).
fn gcd_primitive(a: &ZMPoly, b: &ZMPoly) -> Option<ZMPoly> {
    let one = || MPoly::constant(BigInt::one());
    if a.is_constant() || b.is_constant() || coprime(a, b) {
        return Some(one());
    }
    let mut vars = a.vars();
    vars.extend(b.vars());
    vars.sort_unstable();
    vars.dedup();
    let v = *vars.iter().max()?;
    if vars.len() == 1 {
        // one variable: Brown's modular gcd (no evaluation at a big ξ,
        // whose integers grow as deg · bits(ξ))
        let g = a.to_univariate(v)?.gcd(&b.to_univariate(v)?);
        return Some(primitive(&MPoly::from_univariate(&g, v)));
    }
    let d = a.degree_in(v).max(b.degree_in(v)).unwrap_or(0) as u64;
    let mut xi: BigInt = max_norm(a).min(max_norm(b)) * 2 + 29;
    for _ in 0..6 {
        crate::budget::check_now();
        if xi.bits() * (d + 1) > MAX_HEURISTIC_BITS {
            return None;
        }
        if let Some(gamma) = gcd_with_content(&eval_at(a, v, &xi), &eval_at(b, v, &xi)) {
            let g = primitive(&xi_adic(&gamma, v, &xi));
            if !g.is_zero() && divides(&g, a) && divides(&g, b) {
                return Some(g);
            }
        }
        xi = xi * 73794 / 27011;
    }
    None
}

/// The gcd of `a` and `b` up to an integer factor: primitive, positive
/// leading coefficient; `None` when the heuristic gave up.  Exact when it
/// answers: the candidate divides both, and ξ exceeds twice the smaller
/// norm.
pub fn gcd(a: &ZMPoly, b: &ZMPoly) -> Option<ZMPoly> {
    Some(primitive(&gcd_with_content(a, b)?))
}

/// Yun's algorithm with respect to `v` on a primitive `a`: the square-free
/// factors that contain `v`, with their multiplicities, and the quotient of
/// `a` by their product (its content with respect to `v`, up to sign).
fn yun(a: &ZMPoly, v: usize) -> Option<(Vec<(ZMPoly, u32)>, ZMPoly)> {
    let b = a.derivative(v);
    let c = gcd(a, &b)?;
    let mut w = a.div_exact(&c)?;
    let y = b.div_exact(&c)?;
    let mut z = &y - &w.derivative(v);
    let mut out = Vec::new();
    let mut i = 1u32;
    let limit = a.degree_in(v).unwrap_or(0) + 1;
    while w.degree_in(v).unwrap_or(0) > 0 {
        crate::budget::check_now();
        if i > limit {
            return None;
        }
        let g = gcd(&w, &z)?;
        if !g.is_constant() {
            out.push((g.clone(), i));
        }
        w = w.div_exact(&g)?;
        let y = z.div_exact(&g)?;
        z = &y - &w.derivative(v);
        i += 1;
    }
    let prod = out
        .iter()
        .fold(MPoly::constant(BigInt::one()), |acc, (g, k)| {
            &acc * &g.pow(*k)
        });
    let left = a.div_exact(&prod)?;
    Some((out, left))
}

/// The square-free decomposition of a non-zero `p` (see the module
/// documentation), or `None` when a step gave up or a check was not
/// proven.  A square-free `p` gives the single factor `(pp(p), 1)`.
pub fn squarefree_decomposition(p: &QMPoly) -> Option<SquareFree> {
    let (z, _) = p.to_primitive_z();
    if z.is_zero() {
        return None;
    }
    // the product of the factors of each multiplicity, across the passes
    let mut by_mult: Vec<(u32, ZMPoly)> = Vec::new();
    let mut rest = z;
    for v in 0..NVARS {
        if rest.degree_in(v).unwrap_or(0) == 0 {
            continue;
        }
        let (parts, left) = yun(&rest, v)?;
        for (g, k) in parts {
            match by_mult.iter_mut().find(|(j, _)| *j == k) {
                Some((_, f)) => *f = &*f * &g,
                None => by_mult.push((k, g)),
            }
        }
        rest = primitive(&left);
    }
    if !rest.is_constant() {
        return None;
    }
    by_mult.sort_by_key(|(k, _)| *k);
    let factors: Vec<(ZMPoly, u32)> = by_mult
        .into_iter()
        .map(|(k, f)| (primitive(&f), k))
        .collect();
    // exact checks: the product, square-free factors, coprime pairs
    let prod = factors
        .iter()
        .fold(MPoly::constant(BigInt::one()), |acc, (f, k)| {
            &acc * &f.pow(*k)
        })
        .to_q();
    let (lp, lq) = (p.leading()?, prod.leading()?);
    if lp.0 != lq.0 {
        return None;
    }
    let constant = &lp.1 / &lq.1;
    if prod.scale(&constant) != *p {
        return None;
    }
    let proven = factors.iter().all(|(f, _)| is_squarefree(f))
        && factors
            .iter()
            .enumerate()
            .all(|(i, (f, _))| factors[i + 1..].iter().all(|(g, _)| coprime(f, g)));
    proven.then_some(SquareFree { constant, factors })
}

/// The square-free decomposition of `p` when `p` has a repeated factor;
/// `None` when `p` is square-free — proven in the usual case by
/// [`is_squarefree`] alone, without a gcd — or when the decomposition gave
/// up (the caller then works with `p` as given).
pub fn repeated_factors(p: &QMPoly) -> Option<SquareFree> {
    let (z, _) = p.to_primitive_z();
    if is_squarefree(&z) {
        return None;
    }
    squarefree_decomposition(p).filter(SquareFree::is_proper)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn z(s: &str) -> ZMPoly {
        parse_poly(s).unwrap().to_primitive_z().0
    }

    #[test]
    fn specialisation_tests() {
        assert!(is_squarefree(&z("x^2*y - z^3 + 1")));
        assert!(is_squarefree(&z("x*y*z")));
        assert!(!is_squarefree(&z("(x*y - z)^2")));
        // a square free of x: caught by the test in y
        assert!(!is_squarefree(&z("(y - z)^2*(x + 1)")));
        assert!(coprime(&z("x + y"), &z("x - y")));
        assert!(coprime(&z("x + 1"), &z("y + 1")));
        assert!(!coprime(&z("(x + y)*(z - 1)"), &z("(x + y)*(z + 1)")));
    }

    #[test]
    fn heuristic_gcd() {
        let g = gcd(&z("(x*y - z)^2*(x + 2)"), &z("(x*y - z)*(x - 3)^2")).unwrap();
        assert_eq!(g, z("x*y - z"));
        let g = gcd(
            &z("(x^2 + y^2 - 1)^3*(z - 1)"),
            &z("(x^2 + y^2 - 1)^2*(z + 1)"),
        )
        .unwrap();
        assert_eq!(g, z("(x^2 + y^2 - 1)^2"));
        assert_eq!(gcd(&z("x + y"), &z("x - y")).unwrap(), z("1"));
        // large coefficients
        let g = gcd(
            &z("(123456789*x*y - 987654321*z^2 + 5)*(x - 7*y)^2"),
            &z("(123456789*x*y - 987654321*z^2 + 5)^2*(x + z)"),
        )
        .unwrap();
        assert_eq!(g, z("123456789*x*y - 987654321*z^2 + 5"));
    }

    #[test]
    fn decompositions() {
        let p = parse_poly("-3/2*(x*y - z)^2").unwrap();
        let d = squarefree_decomposition(&p).unwrap();
        assert_eq!(d.constant, Q::new((-3).into(), 2.into()));
        assert_eq!(d.factors, vec![(z("x*y - z"), 2)]);
        let p = parse_poly("(x + y + z - 1)^2*(x - y)^3*(2z + 1)").unwrap();
        let d = squarefree_decomposition(&p).unwrap();
        let ks: Vec<u32> = d.factors.iter().map(|(_, k)| *k).collect();
        assert_eq!(ks, vec![1, 2, 3]);
        assert_eq!(d.factors[1].0, z("x + y + z - 1"));
        assert_eq!(d.factors[2].0, z("x - y"));
        // factors of one multiplicity are multiplied, across the passes
        let p = parse_poly("(x^2 + y^2 - 1)^2*(z - 1)^2*(y - 2)^2").unwrap();
        let d = squarefree_decomposition(&p).unwrap();
        assert_eq!(d.factors, vec![(z("(x^2 + y^2 - 1)*(z - 1)*(y - 2)"), 2)]);
        // square-free input: one factor of multiplicity 1, and no repeated factors
        let p = parse_poly("x^3 - 2x*y + z^2 - 1").unwrap();
        assert_eq!(squarefree_decomposition(&p).unwrap().factors.len(), 1);
        assert!(repeated_factors(&p).is_none());
        assert!(repeated_factors(&parse_poly("(x^3 - y)^2*z").unwrap()).is_some());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 32, .. proptest::prelude::ProptestConfig::default() })]

        /// Products of random small factors with multiplicities 1–3: the
        /// decomposition multiplies back to S, and each multiplicity's
        /// factor is the product of the inputs of that multiplicity.
        #[test]
        fn products_decompose(c in proptest::collection::vec(-3i64..4, 12), ks in proptest::collection::vec(1u32..4, 3)) {
            let fs = [
                format!("{}x^2 + {}y*z + {}x + 1", c[0], c[1], c[2]),
                format!("{}y^2 + {}x*z + {}z - 2", c[3], c[4], c[5]),
                format!("{}z + {}x + {}y + 3", c[6] + 4, c[7], c[8]),
            ];
            let fs: Vec<QMPoly> = fs.iter().map(|f| parse_poly(f).unwrap()).collect();
            let zs: Vec<ZMPoly> = fs.iter().map(|f| f.to_primitive_z().0).collect();
            // distinct, square-free, pairwise coprime inputs only
            proptest::prop_assume!(zs.iter().all(|z| !z.is_constant() && is_squarefree(z)));
            proptest::prop_assume!(coprime(&zs[0], &zs[1]) && coprime(&zs[0], &zs[2]) && coprime(&zs[1], &zs[2]));
            let s = fs.iter().zip(&ks).fold(QMPoly::constant(Q::from_integer(c[9].into()) + Q::new(1.into(), 2.into())), |acc, (f, k)| &acc * &f.pow(*k));
            let d = squarefree_decomposition(&s).unwrap();
            let back = d.factors.iter().fold(QMPoly::constant(d.constant.clone()), |acc, (f, k)| &acc * &f.to_q().pow(*k));
            proptest::prop_assert_eq!(&back, &s);
            for (f, k) in &d.factors {
                let want = zs.iter().zip(&ks).filter(|(_, j)| *j == k).fold(ZMPoly::constant(BigInt::one()), |acc, (z, _)| &acc * z);
                proptest::prop_assert_eq!(f, &want.primitive().0);
            }
            proptest::prop_assert_eq!(repeated_factors(&s).is_some(), ks.iter().any(|k| *k >= 2));
        }
    }
}
