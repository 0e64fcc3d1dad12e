//! The complete real-root summary of a univariate polynomial: counts by
//! sign, multiplicities (from the square-free factorisation), Descartes'
//! bounds, and one disjoint isolating interval per distinct real root.

use super::algebraic::RealAlg;
use super::isolate::{RootInterval, bisect_once, descartes_bounds, isolate_squarefree};
use crate::poly::ZPoly;
use num_traits::Zero;

/// One distinct real root.
#[derive(Clone, Debug)]
pub struct RealRoot {
    /// Isolating interval (`lo == hi` for an exact rational root).
    pub interval: RootInterval,
    /// Multiplicity as a root of the input.
    pub multiplicity: u32,
    /// Square-free factor of the input that vanishes there.
    pub factor: ZPoly,
}

impl RealRoot {
    /// The root as a real algebraic number.
    pub fn value(&self) -> RealAlg {
        RealAlg::from_interval(&self.factor, &self.interval)
    }
}

/// What `quadsect roots` reports.
#[derive(Clone, Debug)]
pub struct RootReport {
    /// Number of distinct real roots.
    pub distinct_real: usize,
    /// Distinct positive roots.
    pub positive: usize,
    /// Distinct negative roots.
    pub negative: usize,
    /// Multiplicity of the root 0 (0 when 0 is not a root).
    pub zero_multiplicity: u32,
    /// Real roots counted with multiplicity.
    pub real_with_multiplicity: u32,
    /// Sign variations of p (after removing the root 0).
    pub descartes_positive_bound: usize,
    /// Sign variations of p(-x) (after removing the root 0).
    pub descartes_negative_bound: usize,
    /// The roots, increasing, with disjoint intervals.
    pub roots: Vec<RealRoot>,
}

fn overlap(a: &RootInterval, b: &RootInterval) -> bool {
    match (a.is_exact(), b.is_exact()) {
        (true, true) => a.lo == b.lo,
        (true, false) => b.lo < a.lo && a.lo < b.hi,
        (false, true) => a.lo < b.lo && b.lo < a.hi,
        (false, false) => a.lo < b.hi && b.lo < a.hi,
    }
}

/// Analyses the real roots of a non-zero integer polynomial.
pub fn analyze_roots(p: &ZPoly) -> RootReport {
    let mut roots: Vec<RealRoot> = Vec::new();
    for (f, mult) in p.squarefree_decomposition() {
        if f.degree() == Some(1) {
            // a linear factor: the root is the rational -f0/f1, exactly
            let r = crate::number::Q::new(-f.coeff(0), f.coeff(1));
            roots.push(RealRoot {
                interval: RootInterval {
                    lo: r.clone(),
                    hi: r,
                },
                multiplicity: mult,
                factor: f.clone(),
            });
            continue;
        }
        for iv in isolate_squarefree(&f) {
            roots.push(RealRoot {
                interval: iv,
                multiplicity: mult,
                factor: f.clone(),
            });
        }
    }
    // roots of different (coprime) factors are distinct: refine until the
    // intervals are pairwise disjoint
    loop {
        let mut changed = false;
        for i in 0..roots.len() {
            for j in i + 1..roots.len() {
                if overlap(&roots[i].interval, &roots[j].interval) {
                    let (a, b) = roots.split_at_mut(j);
                    bisect_once(&a[i].factor, &mut a[i].interval);
                    bisect_once(&b[0].factor, &mut b[0].interval);
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    roots.sort_by(|a, b| {
        a.interval
            .lo
            .cmp(&b.interval.lo)
            .then(a.interval.hi.cmp(&b.interval.hi))
    });
    let zero_multiplicity = p.zero_root_multiplicity() as u32;
    let positive = roots
        .iter()
        .filter(|r| {
            r.interval.lo > Zero::zero() || (r.interval.lo.is_zero() && !r.interval.is_exact())
        })
        .count();
    let negative = roots
        .iter()
        .filter(|r| {
            r.interval.hi < Zero::zero() || (r.interval.hi.is_zero() && !r.interval.is_exact())
        })
        .count();
    let (dp, dn) = descartes_bounds(p);
    RootReport {
        distinct_real: roots.len(),
        positive,
        negative,
        zero_multiplicity,
        real_with_multiplicity: roots.iter().map(|r| r.multiplicity).sum(),
        descartes_positive_bound: dp,
        descartes_negative_bound: dn,
        roots,
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_analyze_roots() {
        use crate::poly::ZPoly;
        use crate::roots::analyze_roots;
        let r = analyze_roots(&ZPoly::from_i64s(&[0, -2, 0, 1])); // x^3 - 2x
        assert_eq!((r.positive, r.negative, r.zero_multiplicity), (1, 1, 1));
    }
}
