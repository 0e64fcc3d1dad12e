//! Gröbner bases over Q (Buchberger's algorithm with the Gebauer–Möller
//! criteria and the normal selection strategy), fraction-free on primitive
//! integer polynomials; reduced bases, zero-dimensionality, standard
//! monomials and normal forms in the quotient algebra.
//!
//! Key idea: for a zero-dimensional ideal `I`, `A = Q[x]/I` is a
//! finite-dimensional vector space with the standard monomials as basis;
//! multiplication by any polynomial is a matrix on `A`, and everything about
//! the finitely many solutions (their number, coordinates, values of other
//! polynomials) is linear algebra on those matrices (see
//! [`crate::system::quotient`]).  Every step is exact, so the basis — and
//! hence the solution set — is certified complete.

use crate::number::Q;
use crate::poly::mpoly::{MPoly, NVARS};
use crate::poly::{QMPoly, ZMPoly};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// Variables in a Gröbner computation (slots).
pub const GV: usize = 4;
/// Exponent vector in the Gröbner slots.
pub type Mono = [u16; GV];

/// Monomial orders.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MonoOrder {
    /// Graded reverse lexicographic order on all slots.
    GrevLex,
    /// Elimination order for the first `k` slots: grevlex on slots `0..k`,
    /// ties broken by grevlex on the remaining slots.
    Elim(usize),
}

fn deg(m: &Mono, from: usize, to: usize) -> u32 {
    m[from..to].iter().map(|&e| e as u32).sum()
}

fn grevlex_range(a: &Mono, b: &Mono, from: usize, to: usize) -> Ordering {
    let da = deg(a, from, to);
    let db = deg(b, from, to);
    if da != db {
        return da.cmp(&db);
    }
    for i in (from..to).rev() {
        if a[i] != b[i] {
            // smaller exponent in the last variable is the larger monomial
            return b[i].cmp(&a[i]);
        }
    }
    Ordering::Equal
}

/// Compares two monomials in the given order.
pub fn cmp_mono(a: &Mono, b: &Mono, ord: MonoOrder) -> Ordering {
    match ord {
        MonoOrder::GrevLex => grevlex_range(a, b, 0, GV),
        MonoOrder::Elim(k) => grevlex_range(a, b, 0, k).then_with(|| grevlex_range(a, b, k, GV)),
    }
}

fn divides(a: &Mono, b: &Mono) -> bool {
    (0..GV).all(|i| a[i] <= b[i])
}

fn mono_div(b: &Mono, a: &Mono) -> Mono {
    std::array::from_fn(|i| b[i] - a[i])
}

fn mono_mul(a: &Mono, b: &Mono) -> Mono {
    std::array::from_fn(|i| a[i] + b[i])
}

fn mono_lcm(a: &Mono, b: &Mono) -> Mono {
    std::array::from_fn(|i| a[i].max(b[i]))
}

fn coprime(a: &Mono, b: &Mono) -> bool {
    (0..GV).all(|i| a[i] == 0 || b[i] == 0)
}

/// A polynomial in the Gröbner slots: terms sorted decreasingly in the
/// order, integer coefficients.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GPoly {
    /// Terms, leading term first.
    pub terms: Vec<(Mono, BigInt)>,
}

impl GPoly {
    /// Leading monomial.
    pub fn lm(&self) -> &Mono {
        &self.terms[0].0
    }

    /// Leading coefficient.
    pub fn lc(&self) -> &BigInt {
        &self.terms[0].1
    }

    /// True for zero.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    fn make_primitive(&mut self) {
        if self.terms.is_empty() {
            return;
        }
        let mut g = BigInt::zero();
        for (_, c) in &self.terms {
            // a gcd of huge numbers is slow: the clock is read per term
            crate::budget::check_for(c.bits());
            g = g.gcd(c);
            if g.is_one() {
                break;
            }
        }
        if self.terms[0].1.is_negative() {
            g = -g;
        }
        if !g.is_one() {
            for (_, c) in self.terms.iter_mut() {
                crate::budget::check_for(c.bits());
                *c = &*c / &g;
            }
        }
    }

    /// From a rational multivariate polynomial: `slots[i]` is the MPoly
    /// variable placed in slot `i`.  Other variables must not occur.
    pub fn from_mpoly(p: &QMPoly, slots: &[usize], ord: MonoOrder) -> GPoly {
        let (z, _) = p.to_primitive_z();
        Self::from_zmpoly(&z, slots, ord)
    }

    /// From an integer multivariate polynomial, keeping its coefficients as
    /// they are (no content removal, no sign change): use this where the
    /// scale matters (normal forms of a given polynomial).
    pub fn from_zmpoly_exact(p: &ZMPoly, slots: &[usize], ord: MonoOrder) -> GPoly {
        let mut terms: Vec<(Mono, BigInt)> = p
            .terms()
            .iter()
            .map(|(e, c)| {
                let mut m = [0u16; GV];
                for (i, &v) in slots.iter().enumerate() {
                    m[i] = e[v] as u16;
                }
                (m, c.clone())
            })
            .collect();
        terms.sort_by(|a, b| cmp_mono(&b.0, &a.0, ord));
        GPoly { terms }
    }

    /// From an integer multivariate polynomial, made primitive with a
    /// positive leading coefficient (an ideal generator: the scale does not
    /// matter).
    pub fn from_zmpoly(p: &ZMPoly, slots: &[usize], ord: MonoOrder) -> GPoly {
        let mut g = Self::from_zmpoly_exact(p, slots, ord);
        g.make_primitive();
        g
    }

    /// Back to a rational multivariate polynomial.
    pub fn to_mpoly(&self, slots: &[usize]) -> QMPoly {
        MPoly::from_terms(self.terms.iter().map(|(m, c)| {
            let mut e = [0u32; NVARS];
            for (i, &v) in slots.iter().enumerate() {
                e[v] = m[i] as u32;
            }
            (e, Q::from_integer(c.clone()))
        }))
    }
}

/// `k1·a − k2·(m·b)` for sorted term lists (k1, k2 integers), sorted.
fn lin_comb(
    a: &[(Mono, BigInt)],
    k1: &BigInt,
    b: &[(Mono, BigInt)],
    m: &Mono,
    k2: &BigInt,
    ord: MonoOrder,
) -> Vec<(Mono, BigInt)> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    // products by huge multipliers are slow: the clock is read per term
    let work = k1.bits() + k2.bits();
    while i < a.len() || j < b.len() {
        crate::budget::check_for(work);
        let bm = if j < b.len() {
            Some(mono_mul(&b[j].0, m))
        } else {
            None
        };
        let c = match (i < a.len(), &bm) {
            (true, Some(bm)) => cmp_mono(&a[i].0, bm, ord),
            (true, None) => Ordering::Greater,
            (false, _) => Ordering::Less,
        };
        match c {
            Ordering::Greater => {
                out.push((a[i].0, &a[i].1 * k1));
                i += 1;
            }
            Ordering::Less => {
                out.push((bm.unwrap_or([0; GV]), -(&b[j].1 * k2)));
                j += 1;
            }
            Ordering::Equal => {
                let v = &a[i].1 * k1 - &b[j].1 * k2;
                if !v.is_zero() {
                    out.push((a[i].0, v));
                }
                i += 1;
                j += 1;
            }
        }
    }
    out
}

/// Full reduction of `f` by `basis`: returns `(r, s)` with `s·f ≡ r`
/// modulo the ideal, no term of `r` divisible by a leading monomial of the
/// basis, and `s` a non-zero rational.
pub fn reduce_full(f: &GPoly, basis: &[&GPoly], ord: MonoOrder) -> (GPoly, Q) {
    let mut p: Vec<(Mono, BigInt)> = f.terms.clone();
    let mut r: Vec<(Mono, BigInt)> = Vec::new();
    let mut scale = Q::one();
    let mut steps = 0usize;
    while !p.is_empty() {
        crate::budget::check_size(
            "a polynomial in a Gröbner reduction",
            p.len() + r.len(),
            p[0].1.bits(),
        );
        let (lm, lc) = (p[0].0, p[0].1.clone());
        match basis.iter().find(|g| divides(g.lm(), &lm)) {
            Some(g) => {
                let b = g.lc();
                let h = lc.gcd(b);
                let kb = b / &h;
                let ka = &lc / &h;
                let m = mono_div(&lm, g.lm());
                p = lin_comb(&p, &kb, &g.terms, &m, &ka, ord);
                if !kb.is_one() {
                    for (_, c) in r.iter_mut() {
                        crate::budget::check_for(kb.bits());
                        *c *= &kb;
                    }
                    scale *= Q::from_integer(kb);
                }
                steps += 1;
                if steps.is_multiple_of(8) {
                    // keep the coefficients small: divide out the common content
                    let mut g = BigInt::zero();
                    for (_, c) in p.iter().chain(r.iter()) {
                        crate::budget::check_for(c.bits());
                        g = g.gcd(c);
                        if g.is_one() {
                            break;
                        }
                    }
                    if !g.is_zero() && !g.is_one() {
                        for (_, c) in p.iter_mut().chain(r.iter_mut()) {
                            crate::budget::check_for(c.bits());
                            *c = &*c / &g;
                        }
                        scale /= Q::from_integer(g);
                    }
                }
            }
            None => {
                r.push(p.remove(0));
            }
        }
    }
    let mut out = GPoly { terms: r };
    if out.terms.is_empty() {
        return (out, scale);
    }
    let before = out.terms[0].1.clone();
    out.make_primitive();
    let after = out.terms[0].1.clone();
    // out = r · after/before
    scale *= Q::new(after, before);
    (out, scale)
}

/// A Gröbner basis with its order and slot map.
#[derive(Clone, Debug)]
pub struct GroebnerBasis {
    /// The monomial order.
    pub order: MonoOrder,
    /// Number of slots in use.
    pub nvars: usize,
    /// The reduced basis, primitive, positive leading coefficients.
    pub polys: Vec<GPoly>,
}

#[derive(Clone, Debug)]
struct Pair {
    i: usize,
    j: usize,
    lcm: Mono,
}

/// Computes the reduced Gröbner basis of the ideal generated by `input`
/// (zero polynomials are ignored).
pub fn groebner(input: Vec<GPoly>, nvars: usize, ord: MonoOrder) -> GroebnerBasis {
    let mut polys: Vec<GPoly> = Vec::new();
    let mut active: Vec<usize> = Vec::new();
    let mut pairs: Vec<Pair> = Vec::new();
    // interreduce the input a little: reduce each by the previous ones
    for f in input {
        if f.is_zero() {
            continue;
        }
        let basis: Vec<&GPoly> = active.iter().map(|&k| &polys[k]).collect();
        let (h, _) = reduce_full(&f, &basis, ord);
        if h.is_zero() {
            continue;
        }
        update(&mut polys, &mut active, &mut pairs, h);
    }
    let mut basis_terms = 0usize;
    while !pairs.is_empty() {
        crate::budget::check_now();
        // normal strategy: the pair with the smallest lcm
        let mut best = 0;
        for k in 1..pairs.len() {
            if cmp_mono(&pairs[k].lcm, &pairs[best].lcm, ord) == Ordering::Less {
                best = k;
            }
        }
        let pr = pairs.swap_remove(best);
        let (f, g) = (&polys[pr.i], &polys[pr.j]);
        let (a, b) = (f.lc(), g.lc());
        let h = a.gcd(b);
        let mf = mono_div(&pr.lcm, f.lm());
        let mg = mono_div(&pr.lcm, g.lm());
        // S = (b/h)·mf·f − (a/h)·mg·g
        let fm: Vec<(Mono, BigInt)> = f
            .terms
            .iter()
            .map(|(m, c)| (mono_mul(m, &mf), c.clone()))
            .collect();
        let s = lin_comb(&fm, &(b / &h), &g.terms, &mg, &(a / &h), ord);
        let mut sp = GPoly { terms: s };
        sp.make_primitive();
        if sp.is_zero() {
            continue;
        }
        let basis: Vec<&GPoly> = active.iter().map(|&k| &polys[k]).collect();
        let (red, _) = reduce_full(&sp, &basis, ord);
        if red.is_zero() {
            continue;
        }
        if red.terms.len() == 1 && red.terms[0].0 == [0; GV] {
            // the ideal is the whole ring
            return GroebnerBasis {
                order: ord,
                nvars,
                polys: vec![red],
            };
        }
        basis_terms += red.terms.len();
        crate::budget::check_size("a Gröbner basis", basis_terms, red.lc().bits());
        update(&mut polys, &mut active, &mut pairs, red);
    }
    // minimal basis
    let mut min: Vec<GPoly> = Vec::new();
    let mut cands: Vec<GPoly> = active.iter().map(|&k| polys[k].clone()).collect();
    cands.sort_by(|a, b| cmp_mono(a.lm(), b.lm(), ord));
    for c in cands {
        if !min.iter().any(|m| divides(m.lm(), c.lm())) {
            min.push(c);
        }
    }
    // reduced basis: tail-reduce each element by the others
    let mut reduced = Vec::with_capacity(min.len());
    for i in 0..min.len() {
        crate::budget::check();
        let others: Vec<&GPoly> = (0..min.len())
            .filter(|&j| j != i)
            .map(|j| &min[j])
            .collect();
        let (r, _) = reduce_full(&min[i], &others, ord);
        reduced.push(r);
    }
    reduced.sort_by(|a, b| cmp_mono(a.lm(), b.lm(), ord));
    GroebnerBasis {
        order: ord,
        nvars,
        polys: reduced,
    }
}

/// Gebauer–Möller update: adds `h` to the basis and the useful new pairs,
/// discarding pairs that the criteria prove redundant.
fn update(polys: &mut Vec<GPoly>, active: &mut Vec<usize>, pairs: &mut Vec<Pair>, h: GPoly) {
    let hi = polys.len();
    let hm = *h.lm();
    polys.push(h);
    let mut c: Vec<Pair> = active
        .iter()
        .map(|&g| Pair {
            i: g,
            j: hi,
            lcm: mono_lcm(polys[g].lm(), &hm),
        })
        .collect();
    // chain criterion among the new pairs
    let mut d: Vec<Pair> = Vec::new();
    while let Some(p) = c.pop() {
        crate::budget::check();
        let pm = polys[p.i].lm();
        if coprime(pm, &hm)
            || (!c.iter().any(|q| divides(&q.lcm, &p.lcm))
                && !d.iter().any(|q| divides(&q.lcm, &p.lcm)))
        {
            d.push(p);
        }
    }
    let e: Vec<Pair> = d
        .into_iter()
        .filter(|p| !coprime(polys[p.i].lm(), &hm))
        .collect();
    // old pairs made redundant by h
    pairs.retain(|p| {
        !divides(&hm, &p.lcm)
            || mono_lcm(polys[p.i].lm(), &hm) == p.lcm
            || mono_lcm(polys[p.j].lm(), &hm) == p.lcm
    });
    pairs.extend(e);
    active.retain(|&g| !divides(&hm, polys[g].lm()));
    active.push(hi);
}

impl GroebnerBasis {
    /// True when the ideal is the whole ring (no common zero).
    pub fn is_unit(&self) -> bool {
        self.polys.len() == 1
            && self.polys[0].terms.len() == 1
            && self.polys[0].terms[0].0 == [0; GV]
    }

    /// True when the ideal has finitely many complex zeros: every variable
    /// has a pure power among the leading monomials.
    pub fn is_zero_dimensional(&self) -> bool {
        (0..self.nvars).all(|v| {
            self.polys.iter().any(|g| {
                let m = g.lm();
                m[v] > 0 && (0..GV).all(|w| w == v || m[w] == 0)
            })
        })
    }

    /// The standard monomials (a basis of the quotient), increasing in the
    /// order; `None` when the ideal is not zero-dimensional.
    pub fn standard_monomials(&self) -> Option<Vec<Mono>> {
        if !self.is_zero_dimensional() {
            return None;
        }
        if self.is_unit() {
            return Some(vec![]);
        }
        let mut out: Vec<Mono> = vec![[0; GV]];
        let mut frontier = vec![[0u16; GV]];
        while let Some(m) = frontier.pop() {
            crate::budget::check_size("the monomial basis of a quotient algebra", out.len(), 0);
            for v in 0..self.nvars {
                let mut n = m;
                n[v] += 1;
                if out.contains(&n) {
                    continue;
                }
                if self.polys.iter().any(|g| divides(g.lm(), &n)) {
                    continue;
                }
                out.push(n);
                frontier.push(n);
            }
        }
        out.sort_by(|a, b| cmp_mono(a, b, self.order));
        Some(out)
    }

    /// Full reduction of a polynomial: `(r, s)` with `s·f ≡ r` modulo the
    /// ideal.
    pub fn reduce(&self, f: &GPoly) -> (GPoly, Q) {
        let basis: Vec<&GPoly> = self.polys.iter().collect();
        reduce_full(f, &basis, self.order)
    }

    /// Verifies the Gröbner property: every S-polynomial reduces to 0.
    #[cfg(test)]
    pub fn verify(&self) -> bool {
        let basis: Vec<&GPoly> = self.polys.iter().collect();
        for i in 0..self.polys.len() {
            for j in i + 1..self.polys.len() {
                let (f, g) = (&self.polys[i], &self.polys[j]);
                let l = mono_lcm(f.lm(), g.lm());
                let (a, b) = (f.lc(), g.lc());
                let h = a.gcd(b);
                let mf = mono_div(&l, f.lm());
                let mg = mono_div(&l, g.lm());
                let fm: Vec<(Mono, BigInt)> = f
                    .terms
                    .iter()
                    .map(|(m, c)| (mono_mul(m, &mf), c.clone()))
                    .collect();
                let s = GPoly {
                    terms: lin_comb(&fm, &(b / &h), &g.terms, &mg, &(a / &h), self.order),
                };
                if !s.is_zero() && !reduce_full(&s, &basis, self.order).0.is_zero() {
                    return false;
                }
            }
        }
        true
    }

    /// The elements that involve only the slots `from..` (for an
    /// elimination order `Elim(from)`: generators of the elimination ideal).
    pub fn eliminated(&self, from: usize) -> Vec<GPoly> {
        self.polys
            .iter()
            .filter(|g| {
                g.terms
                    .iter()
                    .all(|(m, _)| m[..from].iter().all(|&e| e == 0))
            })
            .cloned()
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn gp(s: &str, ord: MonoOrder) -> GPoly {
        GPoly::from_mpoly(&parse_poly(s).unwrap(), &[0, 1, 2, 3], ord)
    }

    #[test]
    fn small_systems() {
        let ord = MonoOrder::GrevLex;
        // circle ∩ line: two points
        let g = groebner(vec![gp("x^2+y^2-1", ord), gp("x-y", ord)], 2, ord);
        assert!(g.verify());
        assert_eq!(g.standard_monomials().unwrap().len(), 2);
        // Cyclic-3: 6 solutions
        let c3 = groebner(
            vec![gp("x+y+z", ord), gp("x*y+y*z+z*x", ord), gp("x*y*z-1", ord)],
            3,
            ord,
        );
        assert!(c3.verify());
        assert_eq!(c3.standard_monomials().unwrap().len(), 6);
        // inconsistent
        let u = groebner(vec![gp("x^2+1", ord), gp("x", ord)], 1, ord);
        assert!(u.is_unit());
        // positive-dimensional
        let p = groebner(vec![gp("x*y", ord), gp("x*z", ord)], 3, ord);
        assert!(!p.is_zero_dimensional());
        // elimination: (x - t^2, y - t^3) eliminating t (slot 0 = x here; use order Elim(1) with t in slot 0)
        let e = MonoOrder::Elim(1);
        let g = groebner(vec![gp("y - x^2", e), gp("z - x^3", e)], 3, e);
        let el = g.eliminated(1);
        assert!(el.iter().any(|p| p.terms.len() == 2)); // z^2 - y^3
        assert!(g.verify());
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_groebner() {
        use crate::poly::parse_poly;
        use crate::system::groebner::{GPoly, MonoOrder, groebner};
        let slots = [0, 1, 2];
        let f: Vec<GPoly> = ["x^2 + y^2 - 1", "x - y"]
            .iter()
            .map(|s| GPoly::from_mpoly(&parse_poly(s).unwrap(), &slots, MonoOrder::GrevLex))
            .collect();
        let g = groebner(f, 2, MonoOrder::GrevLex);
        assert!(g.is_zero_dimensional());
        assert_eq!(g.standard_monomials().unwrap().len(), 2);
    }
}
