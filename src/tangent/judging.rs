//! The judging polynomial D(u) by resultant elimination with branch
//! splitting (paper 004, contract §3) — the paper's own route, made sound.
//!
//! The Lagrange system `S_x − λE_x, S_y − λE_y, S_z − λE_z, E, S − u` is
//! eliminated one variable at a time with resultants.  A plain chain of
//! resultants vanishes identically when two equations share a factor (the
//! paper's examples: `S_y − λE_y = y·(b − λβ)`), so every polynomial is
//! first split into the factors that content extraction finds (monomial
//! factors, contents with respect to each variable), and the system is split
//! into branches, one per factor; a resultant that still vanishes is split at
//! the gcd of its two arguments.  Every branch yields a polynomial in u
//! vanishing at the critical values of that branch (resultants only add
//! roots), so their product vanishes at every critical value.  Elimination
//! in two orders and the gcd of the results strips many extraneous factors.
//!
//! Resultants can grow quickly on inputs without symmetry; a deterministic
//! size budget stops the computation (the exact critical values come from
//! the Gröbner route in [`super::critical`] in any case).

use super::ellipsoid::Ellipsoid;
use crate::elim::resultant_zmpoly;
use crate::poly::mpoly::{L, MPoly, U, X, Y, Z};
use crate::poly::{QMPoly, Ring, UPoly, ZMPoly, ZPoly};
use num_bigint::BigInt;
use num_traits::{One, Signed};

/// Largest number of terms allowed in an intermediate polynomial.
pub const TERM_BUDGET: usize = 4000;
/// Largest number of branches explored.
pub const BRANCH_BUDGET: usize = 256;

/// The result of the resultant elimination.
#[derive(Clone, Debug)]
pub struct Elimination {
    /// D(u) from the first order (λ, x, y, z), square-free.
    pub first: ZPoly,
    /// D(u) from the second order (λ, z, y, x), square-free.
    pub second: ZPoly,
    /// Their gcd: the reported judging polynomial of this route.
    pub gcd: ZPoly,
    /// Number of branches with solutions in the first order.
    pub branches: usize,
}

thread_local! {
    /// Deterministic work budget of one elimination (term operations).
    static FUEL: std::cell::Cell<i64> = const { std::cell::Cell::new(i64::MAX) };
}

/// Work budget of one elimination, in term operations.
pub const WORK_BUDGET: i64 = 3_000_000;

/// The work budget of one elimination while it runs: filled on creation,
/// emptied (back to unlimited) on drop — also when an exhausted compute
/// budget unwinds through the elimination, so that no later [`mpoly_gcd`]
/// on this thread inherits a spent budget.
struct Fuel;

impl Fuel {
    fn fill() -> Fuel {
        FUEL.with(|f| f.set(WORK_BUDGET));
        Fuel
    }
}

impl Drop for Fuel {
    fn drop(&mut self) {
        FUEL.with(|f| f.set(i64::MAX));
    }
}

fn burn(n: usize) -> bool {
    FUEL.with(|f| {
        let v = f.get().saturating_sub(n as i64);
        f.set(v);
        v > 0
    })
}

fn exhausted() -> bool {
    FUEL.with(|f| f.get() <= 0)
}

/// True when `a` and `b` are coprime as polynomials in `v`, proven by one
/// specialisation of the other variables that keeps both leading
/// coefficients non-zero: a common factor of positive degree in `v` would
/// survive it.  `false` means "not proven".
fn coprime_in(a: &ZMPoly, b: &ZMPoly, v: usize) -> bool {
    let others: Vec<usize> = a
        .vars()
        .into_iter()
        .chain(b.vars())
        .filter(|&w| w != v)
        .collect();
    let pts = [3i64, -5, 7, 11, -13, 17];
    let spec = |p: &ZMPoly| -> ZPoly {
        let mut q = p.clone();
        for (k, &w) in others.iter().enumerate() {
            q = q.eval_var(w, &BigInt::from(pts[k % pts.len()] + k as i64));
        }
        q.to_univariate(v).unwrap_or_else(ZPoly::zero)
    };
    let (sa, sb) = (spec(a), spec(b));
    if sa.degree() != a.degree_in(v).map(|d| d as usize)
        || sb.degree() != b.degree_in(v).map(|d| d as usize)
    {
        return false;
    }
    sa.gcd(&sb).degree() == Some(0)
}

/// Greatest common divisor of integer multivariate polynomials (recursive
/// primitive PRS, with a specialisation test for the frequent coprime
/// case), with positive leading coefficient.
pub fn mpoly_gcd(a: &ZMPoly, b: &ZMPoly) -> ZMPoly {
    if a.is_zero() {
        return b.primitive().0;
    }
    if b.is_zero() {
        return a.primitive().0;
    }
    let mut vars: Vec<usize> = a.vars();
    vars.extend(b.vars());
    vars.sort();
    vars.dedup();
    let Some(&v) = vars.first() else {
        // both constants
        let g = num_integer::Integer::gcd(&a.constant_term(), &b.constant_term());
        return MPoly::constant(g);
    };
    let (ca, pa) = content_in(a, v);
    let (cb, pb) = content_in(b, v);
    let c = mpoly_gcd(&ca, &cb);
    if pa.degree_in(v).unwrap_or(0) == 0
        || pb.degree_in(v).unwrap_or(0) == 0
        || exhausted()
        || coprime_in(&pa, &pb, v)
    {
        return c;
    }
    let (mut p, mut q) = (pa.to_upoly(v), pb.to_upoly(v));
    if p.degree() < q.degree() {
        std::mem::swap(&mut p, &mut q);
    }
    while !q.is_zero() {
        if q.degree() == Some(0) {
            return c;
        }
        let work: usize = p.coeffs().iter().map(|x| x.len()).sum::<usize>()
            * q.coeffs().iter().map(|x| x.len()).sum::<usize>();
        if !burn(work) {
            return c;
        }
        let r = p.pseudo_rem(&q);
        let size: usize = r.coeffs().iter().map(|x| x.len()).sum();
        let bits = r
            .coeffs()
            .iter()
            .flat_map(|x| x.terms().iter().map(|(_, c)| c.bits()))
            .max()
            .unwrap_or(0);
        if size > 2_000 || bits > 4_096 {
            FUEL.with(|f| f.set(0));
            return c;
        }
        p = q;
        q = primitive_upoly(&r);
    }
    let g = MPoly::from_upoly(&primitive_upoly(&p), v);
    let (g, _) = g.primitive();
    normalize_sign(&(&c * &g))
}

fn normalize_sign(p: &ZMPoly) -> ZMPoly {
    match p.leading() {
        Some((_, c)) if c.is_negative() => -p,
        _ => p.clone(),
    }
}

/// Content of `p` as a polynomial in `v` (gcd of its coefficients) and the
/// primitive part.
fn content_in(p: &ZMPoly, v: usize) -> (ZMPoly, ZMPoly) {
    let up = p.to_upoly(v);
    // a constant (or monomial-free) coefficient forces content 1 quickly
    if up.coeffs().iter().any(|c| c.is_constant() && !c.is_zero()) {
        return (MPoly::constant(BigInt::one()), p.clone());
    }
    let mut c = ZMPoly::zero();
    for k in up.coeffs() {
        c = mpoly_gcd(&c, k);
        if c.is_constant() {
            break;
        }
    }
    if c.is_zero() {
        return (MPoly::constant(BigInt::one()), p.clone());
    }
    let pp = p.div_exact(&c).unwrap_or_else(|| p.clone());
    (c, pp)
}

fn primitive_upoly(p: &UPoly<ZMPoly>) -> UPoly<ZMPoly> {
    let mut c = ZMPoly::zero();
    for k in p.coeffs() {
        if exhausted() {
            return p.clone();
        }
        c = mpoly_gcd(&c, k);
        if c.is_constant() {
            break;
        }
    }
    if c.is_zero() || c.ris_one() {
        return p.clone();
    }
    p.div_exact_scalar(&c).unwrap_or_else(|| p.clone())
}

/// Splits `p` into factors found by content extraction (monomial factors,
/// and contents with respect to each variable).  The product of the factors
/// equals `p` up to a constant.
pub fn easy_factors(p: &ZMPoly) -> Vec<ZMPoly> {
    let mut out = Vec::new();
    let mut todo = vec![p.primitive().0];
    while let Some(f) = todo.pop() {
        crate::budget::check();
        if f.is_constant() {
            continue;
        }
        let mut split = false;
        for v in f.vars() {
            // monomial factor v
            if f.terms().iter().all(|(e, _)| e[v] > 0) {
                let vp = MPoly::var(v);
                if let Some(q) = f.div_exact(&vp) {
                    out.push(vp);
                    todo.push(q);
                    split = true;
                    break;
                }
            }
            let (c, pp) = content_in(&f, v);
            if !c.is_constant() && !pp.is_constant() {
                todo.push(c);
                todo.push(pp);
                split = true;
                break;
            }
        }
        if !split {
            out.push(normalize_sign(&f));
        }
    }
    out.sort_by_key(|f| f.len());
    out.dedup();
    out
}

enum Fail {
    Budget,
    Positive,
}

struct Ctx {
    branches: usize,
    with_solutions: usize,
}

/// Eliminates `order` from `system`; returns the product of the branch
/// polynomials in u (or a failure).
fn eliminate_rec(system: Vec<ZMPoly>, order: &[usize], ctx: &mut Ctx) -> Result<ZPoly, Fail> {
    crate::budget::check_now();
    ctx.branches += 1;
    if ctx.branches > BRANCH_BUDGET || exhausted() {
        return Err(Fail::Budget);
    }
    let mut sys: Vec<ZMPoly> = Vec::new();
    for p in system {
        if p.is_zero() {
            continue;
        }
        if p.is_constant() {
            return Ok(ZPoly::constant(BigInt::one())); // empty branch
        }
        if p.len() > TERM_BUDGET {
            return Err(Fail::Budget);
        }
        let (pp, _) = p.primitive();
        if !sys.contains(&pp) {
            sys.push(pp);
        }
    }
    // split at the first reducible polynomial
    for i in 0..sys.len() {
        let f = easy_factors(&sys[i]);
        if f.len() > 1 {
            let mut acc = ZPoly::constant(BigInt::one());
            for fac in f {
                let mut s2 = sys.clone();
                s2[i] = fac;
                acc = &acc * &eliminate_rec(s2, order, ctx)?;
            }
            return Ok(acc);
        }
    }
    let Some((&v, rest)) = order.split_first() else {
        // only u left: the gcd of the branch's polynomials
        let mut g = ZPoly::zero();
        for p in &sys {
            let up = p.to_univariate(U).ok_or(Fail::Positive)?;
            g = if g.is_zero() { up } else { g.gcd(&up) };
        }
        if g.is_zero() {
            return Err(Fail::Positive);
        }
        if g.degree().unwrap_or(0) > 0 {
            ctx.with_solutions += 1;
        }
        return Ok(g.primitive_part());
    };
    let (with_v, mut without): (Vec<ZMPoly>, Vec<ZMPoly>) = sys
        .into_iter()
        .partition(|p| p.degree_in(v).unwrap_or(0) > 0);
    if with_v.len() <= 1 {
        // v is determined by (at most) one equation: no condition on the rest
        return eliminate_rec(without, rest, ctx);
    }
    let pi = (0..with_v.len())
        .min_by_key(|&i| (with_v[i].degree_in(v).unwrap_or(0), with_v[i].len()))
        .unwrap_or(0);
    let pivot = &with_v[pi];
    for (j, q) in with_v.iter().enumerate() {
        if j == pi {
            continue;
        }
        if !burn(pivot.len() * q.len() * 16) {
            return Err(Fail::Budget);
        }
        let r = resultant_zmpoly(pivot, q, v);
        if exhausted() {
            return Err(Fail::Budget);
        }
        if r.is_zero() {
            // common factor: V(p, q) = V(g) ∪ V(p/g, q/g)
            let g = mpoly_gcd(pivot, q);
            let (p2, q2) = (
                pivot.div_exact(&g).unwrap_or_else(|| pivot.clone()),
                q.div_exact(&g).unwrap_or_else(|| q.clone()),
            );
            let others: Vec<ZMPoly> = with_v
                .iter()
                .enumerate()
                .filter(|&(k, _)| k != pi && k != j)
                .map(|(_, p)| p.clone())
                .chain(without.iter().cloned())
                .collect();
            let mut a = others.clone();
            a.push(g);
            let mut b = others;
            b.push(p2);
            b.push(q2);
            let ra = eliminate_rec(a, order, ctx)?;
            let rb = eliminate_rec(b, order, ctx)?;
            return Ok(&ra * &rb);
        }
        let bits = r.terms().iter().map(|(_, c)| c.bits()).max().unwrap_or(0);
        if r.len() > TERM_BUDGET || bits > 20_000 {
            return Err(Fail::Budget);
        }
        without.push(r);
    }
    eliminate_rec(without, rest, ctx)
}

fn lagrange_system(e: &QMPoly, s: &QMPoly) -> Vec<ZMPoly> {
    let l = MPoly::var(L);
    let mut out = Vec::new();
    for v in [X, Y, Z] {
        let f = &s.derivative(v) - &(&l * &e.derivative(v));
        out.push(f.to_primitive_z().0);
    }
    out.push(e.to_primitive_z().0);
    out.push((s - &MPoly::var(U)).to_primitive_z().0);
    out
}

/// Eliminates x, y, z, λ from the Lagrange system in the order `order`.
pub fn eliminate_in_order(e: &QMPoly, s: &QMPoly, order: &[usize]) -> Option<(ZPoly, usize)> {
    let mut ctx = Ctx {
        branches: 0,
        with_solutions: 0,
    };
    let fuel = Fuel::fill();
    let d = eliminate_rec(lagrange_system(e, s), order, &mut ctx).ok();
    let spent = exhausted();
    drop(fuel);
    let d = d?;
    if spent {
        return None;
    }
    if d.degree().unwrap_or(0) == 0 {
        return None;
    }
    Some((d.squarefree_part(), ctx.with_solutions))
}

/// The judging polynomial by resultants in the orders (λ, x, y, z) and
/// (λ, z, y, x), and their gcd; `None` when a size budget was exceeded or a
/// branch stayed positive-dimensional.
pub fn eliminate(e: &Ellipsoid, s: &QMPoly) -> Option<Elimination> {
    // Without a factor to split on, the resultant chain of a general
    // (e.g. rotated) system is the expensive and fruitless case measured in
    // shared/bench: the exact critical values come from the Gröbner route.
    if !lagrange_system(&e.poly, s)
        .iter()
        .any(|p| easy_factors(p).len() > 1)
    {
        return None;
    }
    let (first, branches) = eliminate_in_order(&e.poly, s, &[L, X, Y, Z])?;
    let (second, _) = eliminate_in_order(&e.poly, s, &[L, Z, Y, X])?;
    let gcd = first.gcd(&second);
    Some(Elimination {
        first,
        second,
        gcd,
        branches,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::parse_poly;

    fn z(s: &str) -> ZMPoly {
        parse_poly(s).unwrap().to_primitive_z().0
    }

    #[test]
    fn gcd_and_factors() {
        let a = z("(x + y)*(x - 2*y*z + 1)");
        let b = z("(x + y)*(3*x + z)");
        assert_eq!(mpoly_gcd(&a, &b), z("x + y"));
        let f = easy_factors(&z("y*(1 - 12*u)"));
        assert_eq!(f.len(), 2);
        let f = easy_factors(&z("x^2*y + x^2*z"));
        assert_eq!(f.len(), 2); // x (twice, deduplicated), y + z
    }
}
