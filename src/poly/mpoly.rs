//! Sparse multivariate polynomials over a [`Ring`], in the variables
//! `x, y, z, u` of the input syntax and the internal `l` (the Lagrange
//! multiplier λ) and `t` (a separating variable).
//!
//! Terms are kept sorted by decreasing lexicographic order of exponents
//! (x > y > z > u > l > t), without zero coefficients, so equality is
//! structural.  The canonical *printed* order is graded (see
//! [`MPoly::to_string_canonical`]).

use super::ring::Ring;
use super::upoly::UPoly;
use crate::number::{Q, fmt_q};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::HashMap;
use std::ops::{Add, Mul, Neg, Sub};

/// Number of variables.
pub const NVARS: usize = 6;
/// Exponent vector of a monomial.
pub type Exps = [u32; NVARS];
/// Printed names of the variables, by index.
pub const VAR_NAMES: [&str; NVARS] = ["x", "y", "z", "u", "l", "t"];

/// Index of the variable `x`.
pub const X: usize = 0;
/// Index of the variable `y`.
pub const Y: usize = 1;
/// Index of the variable `z`.
pub const Z: usize = 2;
/// Index of the variable `u` (the critical value in the tangent method).
pub const U: usize = 3;
/// Index of the Lagrange multiplier λ, printed `l`.
pub const L: usize = 4;
/// Index of an auxiliary variable `t`.
pub const T: usize = 5;

/// A sparse multivariate polynomial.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct MPoly<C> {
    terms: Vec<(Exps, C)>,
}

/// Multivariate polynomials over Q (what the parser produces).
pub type QMPoly = MPoly<Q>;
/// Multivariate polynomials over Z.
pub type ZMPoly = MPoly<BigInt>;

fn exps_add(a: &Exps, b: &Exps) -> Exps {
    let mut r = [0u32; NVARS];
    for i in 0..NVARS {
        r[i] = a[i] + b[i];
    }
    r
}

fn exps_divides(a: &Exps, b: &Exps) -> bool {
    (0..NVARS).all(|i| a[i] <= b[i])
}

fn exps_sub(b: &Exps, a: &Exps) -> Exps {
    let mut r = [0u32; NVARS];
    for i in 0..NVARS {
        r[i] = b[i] - a[i];
    }
    r
}

/// Total degree of an exponent vector.
pub fn exps_degree(e: &Exps) -> u32 {
    e.iter().sum()
}

impl<C: Ring> MPoly<C> {
    /// The zero polynomial.
    pub fn zero() -> Self {
        MPoly { terms: Vec::new() }
    }

    /// A constant.
    pub fn constant(c: C) -> Self {
        if c.ris_zero() {
            MPoly::zero()
        } else {
            MPoly {
                terms: vec![([0; NVARS], c)],
            }
        }
    }

    /// The variable with index `v`.
    pub fn var(v: usize) -> Self {
        let mut e = [0; NVARS];
        e[v] = 1;
        MPoly {
            terms: vec![(e, C::rone())],
        }
    }

    /// The monomial `c · ∏ vars^e`.
    pub fn monomial(c: C, e: Exps) -> Self {
        if c.ris_zero() {
            MPoly::zero()
        } else {
            MPoly {
                terms: vec![(e, c)],
            }
        }
    }

    /// Builds a polynomial from arbitrary terms (combined, sorted, zeros
    /// removed).
    pub fn from_terms(terms: impl IntoIterator<Item = (Exps, C)>) -> Self {
        let mut map: HashMap<Exps, C> = HashMap::new();
        for (e, c) in terms {
            match map.get_mut(&e) {
                Some(v) => v.radd_assign(&c),
                None => {
                    map.insert(e, c);
                }
            }
        }
        let mut terms: Vec<(Exps, C)> = map.into_iter().filter(|(_, c)| !c.ris_zero()).collect();
        terms.sort_by_key(|t| std::cmp::Reverse(t.0));
        MPoly { terms }
    }

    /// The terms, in decreasing lexicographic order.
    pub fn terms(&self) -> &[(Exps, C)] {
        &self.terms
    }

    /// True for zero.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// True when the polynomial is a constant (zero included).
    pub fn is_constant(&self) -> bool {
        self.terms.iter().all(|(e, _)| e.iter().all(|&k| k == 0))
    }

    /// The constant term.
    pub fn constant_term(&self) -> C {
        self.terms
            .iter()
            .find(|(e, _)| e.iter().all(|&k| k == 0))
            .map(|(_, c)| c.clone())
            .unwrap_or_else(C::rzero)
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// True when there are no terms.
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Total degree (`None` for zero).
    pub fn total_degree(&self) -> Option<u32> {
        self.terms.iter().map(|(e, _)| exps_degree(e)).max()
    }

    /// Degree in the variable `v` (`None` for zero).
    pub fn degree_in(&self, v: usize) -> Option<u32> {
        self.terms.iter().map(|(e, _)| e[v]).max()
    }

    /// Indices of the variables that occur.
    pub fn vars(&self) -> Vec<usize> {
        (0..NVARS)
            .filter(|&v| self.terms.iter().any(|(e, _)| e[v] > 0))
            .collect()
    }

    /// Leading term in lexicographic order.
    pub fn leading(&self) -> Option<&(Exps, C)> {
        self.terms.first()
    }

    /// Multiplication by a scalar.
    pub fn scale(&self, k: &C) -> Self {
        if k.ris_zero() {
            return MPoly::zero();
        }
        MPoly {
            terms: self
                .terms
                .iter()
                .map(|(e, c)| (*e, c.rmul(k)))
                .filter(|(_, c)| !c.ris_zero())
                .collect(),
        }
    }

    /// Applies `f` to the coefficients.
    pub fn map<D: Ring>(&self, f: impl Fn(&C) -> D) -> MPoly<D> {
        MPoly {
            terms: self
                .terms
                .iter()
                .map(|(e, c)| (*e, f(c)))
                .filter(|(_, c)| !c.ris_zero())
                .collect(),
        }
    }

    /// Multiplication by a monomial.
    pub fn mul_monomial(&self, e: &Exps, k: &C) -> Self {
        if k.ris_zero() {
            return MPoly::zero();
        }
        MPoly {
            terms: self
                .terms
                .iter()
                .map(|(f, c)| (exps_add(e, f), c.rmul(k)))
                .filter(|(_, c)| !c.ris_zero())
                .collect(),
        }
    }

    fn merge(&self, o: &Self, negate: bool) -> Self {
        let mut out = Vec::with_capacity(self.terms.len() + o.terms.len());
        let (mut i, mut j) = (0, 0);
        let a = &self.terms;
        let b = &o.terms;
        while i < a.len() || j < b.len() {
            if j == b.len() || (i < a.len() && a[i].0 > b[j].0) {
                out.push(a[i].clone());
                i += 1;
            } else if i == a.len() || b[j].0 > a[i].0 {
                let c = if negate {
                    b[j].1.rneg()
                } else {
                    b[j].1.clone()
                };
                out.push((b[j].0, c));
                j += 1;
            } else {
                let c = if negate {
                    a[i].1.rsub(&b[j].1)
                } else {
                    a[i].1.radd(&b[j].1)
                };
                if !c.ris_zero() {
                    out.push((a[i].0, c));
                }
                i += 1;
                j += 1;
            }
        }
        MPoly { terms: out }
    }

    /// `self^e`.
    pub fn pow(&self, e: u32) -> Self {
        let mut r = MPoly::constant(C::rone());
        let mut b = self.clone();
        let mut e = e;
        while e > 0 {
            if e & 1 == 1 {
                r = &r * &b;
            }
            e >>= 1;
            if e > 0 {
                b = &b * &b;
            }
        }
        r
    }

    /// Partial derivative with respect to the variable `v`.
    pub fn derivative(&self, v: usize) -> Self {
        MPoly::from_terms(self.terms.iter().filter(|(e, _)| e[v] > 0).map(|(e, c)| {
            let mut f = *e;
            f[v] -= 1;
            (f, c.rmul(&C::from_i64(e[v] as i64)))
        }))
    }

    /// Substitutes the polynomial `g` for the variable `v`.
    pub fn substitute(&self, v: usize, g: &Self) -> Self {
        let up = self.to_upoly(v);
        let mut acc = MPoly::zero();
        for c in up.coeffs().iter().rev() {
            crate::budget::check();
            acc = &(&acc * g) + c;
        }
        acc
    }

    /// Substitutes polynomials for several variables at once (`subs[v]` for
    /// variable `v`, `None` keeps it).
    pub fn substitute_all(&self, subs: &[Option<Self>; NVARS]) -> Self {
        let mut acc = MPoly::zero();
        let mut powers: Vec<HashMap<u32, Self>> = vec![HashMap::new(); NVARS];
        for (e, c) in &self.terms {
            crate::budget::check();
            let mut t = MPoly::constant(c.clone());
            let mut keep = [0u32; NVARS];
            for v in 0..NVARS {
                if e[v] == 0 {
                    continue;
                }
                match &subs[v] {
                    Some(g) => {
                        let p = powers[v].entry(e[v]).or_insert_with(|| g.pow(e[v])).clone();
                        t = &t * &p;
                    }
                    None => keep[v] = e[v],
                }
            }
            acc = &acc + &t.mul_monomial(&keep, &C::rone());
        }
        acc
    }

    /// Value when the variable `v` is set to the constant `a`.
    pub fn eval_var(&self, v: usize, a: &C) -> Self {
        self.substitute(v, &MPoly::constant(a.clone()))
    }

    /// View as a univariate polynomial in `v` whose coefficients are
    /// polynomials in the other variables.
    pub fn to_upoly(&self, v: usize) -> UPoly<MPoly<C>> {
        let d = self.degree_in(v).unwrap_or(0) as usize;
        let mut buckets: Vec<Vec<(Exps, C)>> = vec![Vec::new(); d + 1];
        for (e, c) in &self.terms {
            let mut f = *e;
            f[v] = 0;
            buckets[e[v] as usize].push((f, c.clone()));
        }
        UPoly::new(
            buckets
                .into_iter()
                .map(|mut t| {
                    t.sort_by_key(|x| std::cmp::Reverse(x.0));
                    MPoly { terms: t }
                })
                .collect(),
        )
    }

    /// Inverse of [`MPoly::to_upoly`].
    pub fn from_upoly(p: &UPoly<MPoly<C>>, v: usize) -> Self {
        let mut terms = Vec::new();
        for (k, c) in p.coeffs().iter().enumerate() {
            for (e, a) in &c.terms {
                let mut f = *e;
                f[v] += k as u32;
                terms.push((f, a.clone()));
            }
        }
        MPoly::from_terms(terms)
    }

    /// View as a univariate polynomial in `v` with scalar coefficients, when
    /// no other variable occurs.
    pub fn to_univariate(&self, v: usize) -> Option<UPoly<C>> {
        let d = self.degree_in(v).unwrap_or(0) as usize;
        let mut c = vec![C::rzero(); d + 1];
        for (e, a) in &self.terms {
            if (0..NVARS).any(|w| w != v && e[w] != 0) {
                return None;
            }
            c[e[v] as usize] = a.clone();
        }
        Some(UPoly::new(c))
    }

    /// The univariate polynomial `p(v)` as a multivariate one.
    pub fn from_univariate(p: &UPoly<C>, v: usize) -> Self {
        MPoly::from_terms(p.coeffs().iter().enumerate().map(|(k, c)| {
            let mut e = [0; NVARS];
            e[v] = k as u32;
            (e, c.clone())
        }))
    }

    /// Exact division: `Some(q)` with `q·b = self`, or `None`.
    pub fn div_exact(&self, b: &Self) -> Option<Self> {
        let (eb, cb) = b.terms.first()?.clone();
        if b.terms.len() == 1 {
            // division by a monomial
            let mut out = Vec::with_capacity(self.terms.len());
            for (e, c) in &self.terms {
                if !exps_divides(&eb, e) {
                    return None;
                }
                out.push((exps_sub(e, &eb), c.div_exact(&cb)?));
            }
            return Some(MPoly { terms: out });
        }
        let mut r = self.clone();
        let mut q = Vec::new();
        while let Some((er, cr)) = r.terms.first().cloned() {
            crate::budget::check();
            if !exps_divides(&eb, &er) {
                return None;
            }
            let e = exps_sub(&er, &eb);
            let c = cr.div_exact(&cb)?;
            r = r.merge(&b.mul_monomial(&e, &c), true);
            q.push((e, c));
        }
        Some(MPoly { terms: q })
    }

    /// Renames variables: variable `v` becomes `perm[v]`.
    pub fn permute_vars(&self, perm: &[usize; NVARS]) -> Self {
        MPoly::from_terms(self.terms.iter().map(|(e, c)| {
            let mut f = [0; NVARS];
            for v in 0..NVARS {
                f[perm[v]] += e[v];
            }
            (f, c.clone())
        }))
    }
}

impl MPoly<Q> {
    /// Value at a point (all variables given; unused ones may be anything).
    pub fn eval(&self, point: &[Q; NVARS]) -> Q {
        let mut acc = Q::zero();
        for (e, c) in &self.terms {
            let mut t = c.clone();
            for v in 0..NVARS {
                if e[v] > 0 {
                    t *= num_traits::pow(point[v].clone(), e[v] as usize);
                }
            }
            acc += t;
        }
        acc
    }

    /// Writes `self = k · P` with `P` an integer polynomial with content 1
    /// whose leading (lex) coefficient is positive.  Zero gives `(0, 0)`.
    pub fn to_primitive_z(&self) -> (ZMPoly, Q) {
        if self.ris_zero() {
            return (MPoly::zero(), Q::zero());
        }
        let l = crate::number::denom_lcm(self.terms.iter().map(|(_, c)| c));
        let z: ZMPoly = self.map(|c| c.numer() * (&l / c.denom()));
        let (p, g) = z.primitive();
        (p, Q::new(g, l))
    }

    /// Canonical string: terms by decreasing total degree, then decreasing
    /// lexicographic order (x > y > z > u > l > t); coefficients as integers
    /// or `a/b`; `*` between factors.  `parse(print(p)) == p`.
    pub fn to_string_canonical(&self) -> String {
        fmt_terms(&self.terms, fmt_q)
    }
}

impl MPoly<BigInt> {
    /// Content (non-negative gcd of the coefficients).
    pub fn content(&self) -> BigInt {
        let mut g = BigInt::zero();
        for (_, c) in &self.terms {
            g = g.gcd(c);
            if g.is_one() {
                break;
            }
        }
        g
    }

    /// `(P, c)` with `self = c·P`, `P` of content 1 and positive leading
    /// coefficient.
    pub fn primitive(&self) -> (ZMPoly, BigInt) {
        if self.ris_zero() {
            return (MPoly::zero(), BigInt::zero());
        }
        let mut g = self.content();
        if self.terms[0].1.is_negative() {
            g = -g;
        }
        (self.map(|c| c / &g), g)
    }

    /// Converts to rational coefficients.
    pub fn to_q(&self) -> QMPoly {
        self.map(|c| Q::from_integer(c.clone()))
    }

    /// Canonical string (as for [`MPoly::to_string_canonical`] over Q).
    pub fn to_string_canonical(&self) -> String {
        fmt_terms(&self.terms, |c| c.to_string())
    }
}

fn fmt_terms<C: Ring>(terms: &[(Exps, C)], fmt_c: impl Fn(&C) -> String) -> String {
    if terms.is_empty() {
        return "0".to_string();
    }
    let mut ts: Vec<&(Exps, C)> = terms.iter().collect();
    ts.sort_by(|a, b| {
        exps_degree(&b.0)
            .cmp(&exps_degree(&a.0))
            .then(b.0.cmp(&a.0))
    });
    let mut s = String::new();
    for (k, (e, c)) in ts.iter().enumerate() {
        let cs = fmt_c(c);
        let (neg, mag) = match cs.strip_prefix('-') {
            Some(m) => (true, m.to_string()),
            None => (false, cs),
        };
        if k == 0 {
            if neg {
                s.push('-');
            }
        } else {
            s.push_str(if neg { " - " } else { " + " });
        }
        let mono: Vec<String> = (0..NVARS)
            .filter(|&v| e[v] > 0)
            .map(|v| {
                if e[v] == 1 {
                    VAR_NAMES[v].to_string()
                } else {
                    format!("{}^{}", VAR_NAMES[v], e[v])
                }
            })
            .collect();
        if mono.is_empty() {
            s.push_str(&mag);
        } else {
            if mag != "1" {
                s.push_str(&mag);
                s.push('*');
            }
            s.push_str(&mono.join("*"));
        }
    }
    s
}

impl<C: Ring> Add for &MPoly<C> {
    type Output = MPoly<C>;
    fn add(self, o: &MPoly<C>) -> MPoly<C> {
        self.merge(o, false)
    }
}

impl<C: Ring> Sub for &MPoly<C> {
    type Output = MPoly<C>;
    fn sub(self, o: &MPoly<C>) -> MPoly<C> {
        self.merge(o, true)
    }
}

/// Upper bounds on the number of terms and the coefficient bit size of
/// `a · b`, from the operands: at most `|a|·|b|` terms, and at most the
/// dense count `∏ (deg_v a + deg_v b + 1)`; coefficients of at most
/// `bits(a) + bits(b) + ⌈log₂ min(|a|, |b|)⌉` bits.
fn product_size<C: Ring>(a: &MPoly<C>, b: &MPoly<C>) -> (usize, u64) {
    let degs = |p: &MPoly<C>| {
        let mut d = [0u32; NVARS];
        for (e, _) in &p.terms {
            for v in 0..NVARS {
                d[v] = d[v].max(e[v]);
            }
        }
        d
    };
    let (da, db) = (degs(a), degs(b));
    let dense = (0..NVARS).fold(1usize, |acc, v| {
        acc.saturating_mul(da[v] as usize + db[v] as usize + 1)
    });
    let (ta, tb) = (a.terms.len(), b.terms.len());
    let terms = ta.saturating_mul(tb).min(dense);
    let bits = a.bit_size() + b.bit_size() + super::upoly::log2_ceil(ta.min(tb));
    (terms, bits)
}

impl<C: Ring> Mul for &MPoly<C> {
    type Output = MPoly<C>;
    fn mul(self, o: &MPoly<C>) -> MPoly<C> {
        if self.ris_zero() || o.ris_zero() {
            return MPoly::zero();
        }
        if o.terms.len() == 1 {
            return self.mul_monomial(&o.terms[0].0, &o.terms[0].1);
        }
        if self.terms.len() == 1 {
            return o.mul_monomial(&self.terms[0].0, &self.terms[0].1);
        }
        let (terms, bits) = product_size(self, o);
        crate::budget::check_size("a product of polynomials", terms, bits);
        // a row is `o.terms.len()` products of coefficients of up to
        // `bits` bits: when that is much work the clock is read every row
        // (read every 64 rows, a product of large coefficients ran seconds
        // past its deadline)
        let row_work = bits.saturating_mul(o.terms.len() as u64);
        let mut map: HashMap<Exps, C> = HashMap::with_capacity(terms);
        for (ea, ca) in &self.terms {
            crate::budget::check_for(row_work);
            for (eb, cb) in &o.terms {
                let e = exps_add(ea, eb);
                let p = ca.rmul(cb);
                match map.get_mut(&e) {
                    Some(v) => v.radd_assign(&p),
                    None => {
                        map.insert(e, p);
                    }
                }
            }
        }
        let mut terms: Vec<(Exps, C)> = map.into_iter().filter(|(_, c)| !c.ris_zero()).collect();
        terms.sort_by_key(|t| std::cmp::Reverse(t.0));
        MPoly { terms }
    }
}

impl<C: Ring> Neg for &MPoly<C> {
    type Output = MPoly<C>;
    fn neg(self) -> MPoly<C> {
        MPoly {
            terms: self.terms.iter().map(|(e, c)| (*e, c.rneg())).collect(),
        }
    }
}

super::macros::forward_owned_ops!(MPoly, C);

impl<C: Ring> Ring for MPoly<C> {
    fn rzero() -> Self {
        MPoly::zero()
    }
    fn rone() -> Self {
        MPoly::constant(C::rone())
    }
    fn from_i64(n: i64) -> Self {
        MPoly::constant(C::from_i64(n))
    }
    fn ris_zero(&self) -> bool {
        self.terms.is_empty()
    }
    fn radd(&self, o: &Self) -> Self {
        self + o
    }
    fn rsub(&self, o: &Self) -> Self {
        self - o
    }
    fn rmul(&self, o: &Self) -> Self {
        self * o
    }
    fn rneg(&self) -> Self {
        -self
    }
    fn div_exact(&self, o: &Self) -> Option<Self> {
        MPoly::div_exact(self, o)
    }
    fn bit_size(&self) -> u64 {
        self.terms
            .iter()
            .map(|(_, c)| c.bit_size())
            .max()
            .unwrap_or(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(i: usize) -> ZMPoly {
        MPoly::var(i)
    }

    #[test]
    fn arithmetic_and_division() {
        let x = v(X);
        let y = v(Y);
        let one = ZMPoly::constant(BigInt::one());
        let a = &(&x + &y) * &(&x - &one);
        let b = &x + &y;
        assert_eq!(a.div_exact(&b), Some(&x - &one));
        assert_eq!(b.div_exact(&(&x - &one)), None);
        assert_eq!(a.degree_in(X), Some(2));
        let up = a.to_upoly(X);
        assert_eq!(ZMPoly::from_upoly(&up, X), a);
        assert_eq!(a.derivative(X), &(&x + &x) + &(&y - &one));
        assert_eq!(a.substitute(Y, &one), &(&x + &one) * &(&x - &one));
    }

    /// Found by `fuzz/` (parse_poly: `(9 + y/7/ 9)^416 -/8 …` ran 1.5 s
    /// under a 0.5 s budget): a product with large coefficients read the
    /// clock every 64 rows, so it ran up to 64 rows past its deadline.  It
    /// now stops within a row or two.
    #[test]
    fn a_product_of_large_rows_stops_a_row_after_its_deadline() {
        use crate::budget::{self, Budget};
        use std::time::{Duration, Instant};
        // 200 terms with 60 000-bit coefficients: one row is 200 products
        // of 60 000-bit integers (milliseconds)
        let big = |n: usize| -> ZMPoly {
            MPoly::from_terms((0..n).map(|i| {
                let mut e = [0; NVARS];
                e[X] = i as u32;
                (e, num_traits::pow(BigInt::from(3), 37_000 + i))
            }))
        };
        let (a, b, two_rows) = (big(200), big(200), big(2));
        let t0 = Instant::now();
        let _ = &two_rows * &b;
        let row = t0.elapsed() / 2;
        let limit = Duration::from_millis(5);
        let t0 = Instant::now();
        let r = budget::run(&Budget::unlimited().with_time_limit(Some(limit)), || {
            &a * &b
        });
        let took = t0.elapsed();
        assert!(r.is_err(), "200 rows end after the deadline");
        assert!(
            took <= limit + 8 * row + Duration::from_millis(20),
            "{took:?} with a limit of {limit:?} and rows of {row:?}"
        );
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_to_string_canonical() {
        use crate::poly::parse_poly;
        let p = parse_poly("3(x-1)^2 - y/2").unwrap();
        assert_eq!(p.to_string_canonical(), "3*x^2 - 6*x - 1/2*y + 3");
    }
}
