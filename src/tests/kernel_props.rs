//! Property tests of the exact kernel: independent deciders must agree.

use crate::elim::{
    resultant_bivariate_modular, resultant_modular, resultant_subresultant, resultant_sylvester,
};
use crate::number::Q;
use crate::poly::mpoly::{MPoly, NVARS, X, Y};
use crate::poly::{QMPoly, ZMPoly, ZPoly, parse_poly};
use crate::roots::{RealAlg, SturmSequence, analyze_roots, isolate_real_roots};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use proptest::prelude::*;
use std::cmp::Ordering;

fn zpoly(max_deg: usize, bits: u32) -> impl Strategy<Value = ZPoly> {
    let bound = if bits >= 62 { i64::MAX } else { 1i64 << bits };
    prop::collection::vec(-bound..bound, 1..=max_deg + 1).prop_map(|c| ZPoly::from_i64s(&c))
}

/// Polynomials with built-in structure: products of small random factors,
/// some repeated (multiple roots), some linear with rational roots.
fn structured() -> impl Strategy<Value = ZPoly> {
    prop::collection::vec((zpoly(3, 4), 1u32..=3), 1..=4).prop_map(|fs| {
        fs.into_iter().fold(ZPoly::from_i64s(&[1]), |acc, (f, k)| {
            if f.is_zero() { acc } else { &acc * &f.pow(k) }
        })
    })
}

fn big_zpoly() -> impl Strategy<Value = ZPoly> {
    prop::collection::vec(prop::collection::vec(any::<u32>(), 7), 2..=9).prop_map(|rows| {
        ZPoly::new(
            rows.iter()
                .enumerate()
                .map(|(i, limbs)| {
                    let mut x = BigInt::zero();
                    for l in limbs {
                        x = (x << 32usize) + BigInt::from(*l);
                    }
                    if i % 3 == 1 { -x } else { x }
                })
                .collect(),
        )
    })
}

fn check_isolation(p: &ZPoly) {
    let iv = isolate_real_roots(p);
    let sq = p.squarefree_part();
    for w in iv.windows(2) {
        assert!(w[0].hi <= w[1].lo, "intervals overlap: {w:?}");
    }
    for r in &iv {
        if r.is_exact() {
            assert_eq!(sq.sign_at(&r.lo), 0, "exact root is not a root");
        } else {
            assert!(r.lo < r.hi);
            assert!(
                sq.sign_at(&r.lo) * sq.sign_at(&r.hi) < 0,
                "no sign change on {r:?}"
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, .. ProptestConfig::default() })]

    /// Interval enclosures are true enclosures: at random exact points of
    /// a random interval the value of p (and of p/q where q keeps its sign)
    /// lies inside, and a point interval gives the exact value.
    #[test]
    fn enclosures_contain_exact_values(p in zpoly(7, 40), q in zpoly(3, 8),
                                       a in (-400i64..400, 1i64..50), w in (0i64..300, 1i64..90),
                                       ts in prop::collection::vec(0i64..=64, 1..6)) {
        use crate::roots::{enclose_mean_value, ratio_enclosure};
        let a = Q::new(a.0.into(), a.1.into());
        let b = &a + Q::new(w.0.into(), w.1.into());
        let (lo, hi) = enclose_mean_value(&p, &a, &b);
        let (qz, qk) = (q.clone(), Q::new(3.into(), (-7).into()));
        let ratio = ratio_enclosure(&(p.clone(), Q::new(5.into(), 2.into())), &(qz.clone(), qk.clone()), &a, &b);
        for t in ts {
            let x = &a + (&b - &a) * Q::new(t.into(), 64.into());
            let v = p.eval_q(&x);
            prop_assert!(lo <= v && v <= hi, "p({}) = {} outside [{}, {}]", x, v, lo, hi);
            if let Some((rl, rh)) = &ratio {
                let r = v * Q::new(5.into(), 2.into()) / (qz.eval_q(&x) * &qk);
                prop_assert!(rl <= &r && &r <= rh, "ratio outside its enclosure");
            }
        }
        let (el, eh) = enclose_mean_value(&p, &a, &a);
        prop_assert!(el == p.eval_q(&a) && eh == el);
    }

    /// Sturm count == number of VCA intervals == count via the square-free
    /// factorisation (per-factor isolation in `analyze_roots`).
    #[test]
    fn sturm_equals_vca_equals_squarefree(p in prop_oneof![zpoly(12, 8), structured(), big_zpoly()]) {
        prop_assume!(p.degree().unwrap_or(0) > 0);
        let s = SturmSequence::new(&p);
        let v = isolate_real_roots(&p);
        let r = analyze_roots(&p);
        prop_assert_eq!(s.count_all(), v.len());
        prop_assert_eq!(s.count_all(), r.distinct_real);
        prop_assert_eq!(s.count_positive(), r.positive);
        prop_assert_eq!(s.count_negative(), r.negative);
        prop_assert_eq!(s.has_root_at_zero(), r.zero_multiplicity > 0);
        // Descartes bounds are upper bounds with the right parity
        let pos_mult: u32 = r.roots.iter().filter(|x| x.interval.lo > Q::zero() || (x.interval.lo.is_zero() && !x.interval.is_exact())).map(|x| x.multiplicity).sum();
        prop_assert!(pos_mult as usize <= r.descartes_positive_bound);
        prop_assert_eq!((r.descartes_positive_bound - pos_mult as usize) % 2, 0);
    }

    /// Each isolating interval brackets a sign change (or is an exact root)
    /// and the intervals are disjoint.
    #[test]
    fn intervals_isolate(p in prop_oneof![zpoly(12, 8), structured(), big_zpoly()]) {
        prop_assume!(p.degree().unwrap_or(0) > 0);
        check_isolation(&p);
    }

    /// Roots built in (rational roots, possibly very close) are all found.
    #[test]
    fn constructed_rational_roots_are_found(roots in prop::collection::btree_set((-50i64..50, 1i64..20), 1..8)) {
        let mut p = ZPoly::from_i64s(&[1]);
        let mut values: Vec<Q> = Vec::new();
        for (a, b) in &roots {
            let q = Q::new(BigInt::from(*a), BigInt::from(*b));
            if values.contains(&q) { continue; }
            values.push(q);
            p = &p * &ZPoly::from_i64s(&[-*a, *b]);
        }
        values.sort();
        let iv = isolate_real_roots(&p);
        prop_assert_eq!(iv.len(), values.len());
        for (r, v) in iv.iter().zip(values.iter()) {
            if r.is_exact() { prop_assert_eq!(&r.lo, v); } else { prop_assert!(&r.lo < v && v < &r.hi); }
        }
    }

    /// The sign at a dyadic point `m/2^k` (fixed-width Horner under a
    /// headroom bound, `BigInt` beyond it) equals the sign of the exact
    /// rational value, for points of every size, at built-in roots too.
    #[test]
    fn dyadic_signs_equal_rational_signs(p in prop_oneof![zpoly(30, 62), big_zpoly(), structured()],
                                         root in (-300i64..300, 0u32..12),
                                         m in prop_oneof![any::<i64>().prop_map(BigInt::from),
                                                          (any::<i64>(), 0usize..80).prop_map(|(a, s)| BigInt::from(a) << s)],
                                         k in 0u64..90) {
        use crate::poly::zpoly::DyadicSigner;
        // p with a dyadic root a/2^e, evaluated there and at m/2^k
        let (a, e) = root;
        let pr = &p * &ZPoly::new(vec![BigInt::from(-a), BigInt::one() << e as usize]);
        for poly in [&p, &pr] {
            let s = DyadicSigner::new(poly);
            for (x, kx) in [(m.clone(), k), (BigInt::from(a) << (k as usize), k + u64::from(e))] {
                let exact = poly.sign_at(&Q::new(x.clone(), BigInt::one() << kx as usize));
                prop_assert_eq!(s.sign_at(&x, kx), exact, "p = {:?} at {}/2^{}", poly, x, kx);
                prop_assert_eq!(poly.sign_at_dyadic(&x, kx), exact);
            }
        }
        prop_assert_eq!(DyadicSigner::new(&pr).sign_at(&(BigInt::from(a) << (k as usize)), k + u64::from(e)), 0);
    }

    /// Res(f, g) = 0 iff deg gcd(f, g) > 0.
    #[test]
    fn resultant_vanishes_iff_common_root(f in zpoly(6, 6), g in zpoly(6, 6), h in zpoly(2, 3)) {
        prop_assume!(!f.is_zero() && !g.is_zero());
        let (f2, g2) = if h.degree().unwrap_or(0) > 0 { (&f * &h, &g * &h) } else { (f, g) };
        let r = resultant_modular(&f2, &g2);
        let gd = f2.gcd(&g2).degree().unwrap_or(0);
        prop_assert_eq!(r.is_zero(), gd > 0);
    }

    /// Res(f, g) = (-1)^(deg f · deg g) Res(g, f).
    #[test]
    fn resultant_antisymmetry(f in zpoly(8, 20), g in zpoly(8, 20)) {
        prop_assume!(!f.is_zero() && !g.is_zero());
        let a = resultant_modular(&f, &g);
        let b = resultant_modular(&g, &f);
        let odd = (f.degree().unwrap() * g.degree().unwrap()) % 2 == 1;
        prop_assert_eq!(a, if odd { -b } else { b });
    }

    /// Sylvester–Bareiss == subresultant == multi-modular over Z.
    #[test]
    fn three_resultants_agree(f in prop_oneof![zpoly(9, 30), big_zpoly()], g in prop_oneof![zpoly(9, 30), big_zpoly()]) {
        prop_assume!(!f.is_zero() && !g.is_zero());
        let a = resultant_sylvester(&f, &g);
        let b = resultant_subresultant(&f, &g);
        let c = resultant_modular(&f, &g);
        prop_assert_eq!(&a, &b);
        prop_assert_eq!(&a, &c);
    }

    /// The same agreement with coefficients in Z[y] (the generic code over a
    /// polynomial ring, and the bivariate evaluation/interpolation route).
    #[test]
    fn multivariate_resultants_agree(cf in prop::collection::vec((0u32..4, 0u32..3, -9i64..9), 1..8),
                                     cg in prop::collection::vec((0u32..3, 0u32..4, -9i64..9), 1..8)) {
        let mk = |c: &Vec<(u32, u32, i64)>| -> ZMPoly {
            MPoly::from_terms(c.iter().map(|&(i, j, k)| {
                let mut e = [0u32; NVARS]; e[X] = i; e[Y] = j; (e, BigInt::from(k))
            }))
        };
        let f = mk(&cf);
        let g = mk(&cg);
        prop_assume!(!f.is_zero() && !g.is_zero());
        prop_assume!(f.vars().contains(&Y) || g.vars().contains(&Y));
        let a = resultant_sylvester(&f.to_upoly(X), &g.to_upoly(X));
        let b = resultant_subresultant(&f.to_upoly(X), &g.to_upoly(X));
        let c = resultant_bivariate_modular(&f, &g, X, Y);
        prop_assert_eq!(&a, &b);
        prop_assert_eq!(&a, &c);
    }

    /// parse(print(p)) == p.
    #[test]
    fn parse_print_roundtrip(terms in prop::collection::vec((0u32..4, 0u32..4, 0u32..3, 0u32..3, -1000i64..1000, 1i64..50), 0..10)) {
        let p: QMPoly = MPoly::from_terms(terms.iter().map(|&(a, b, c, d, n, m)| {
            let mut e = [0u32; NVARS]; e[0] = a; e[1] = b; e[2] = c; e[3] = d;
            (e, Q::new(BigInt::from(n), BigInt::from(m)))
        }));
        let s = p.to_string_canonical();
        let back = parse_poly(&s).unwrap();
        prop_assert_eq!(back, p);
    }

    /// The parser never panics, whatever the input.
    #[test]
    fn parser_total_on_random_text(s in "[-+*/^()xyzu0-9.eE /a-d\\t]{0,40}") {
        let _ = parse_poly(&s);
    }

    /// Comparison of real algebraic numbers agrees with their order as
    /// isolated roots of a product, and sign queries agree with comparison.
    #[test]
    fn algebraic_comparison_consistent(f in zpoly(5, 5), g in zpoly(5, 5)) {
        prop_assume!(f.degree().unwrap_or(0) > 0 && g.degree().unwrap_or(0) > 0);
        let ra = RealAlg::roots_of(&f);
        let rb = RealAlg::roots_of(&g);
        let prod = &f.squarefree_part() * &g.squarefree_part();
        let all = RealAlg::roots_of(&prod);
        for a in &ra {
            for b in &rb {
                let c = a.cmp_exact(b);
                prop_assert_eq!(b.cmp_exact(a), c.reverse());
                // a == b forces g(a) == 0
                prop_assert!(c != Ordering::Equal || a.sign_of(&g) == 0);
            }
            // g(a) == 0 iff a is exactly one of the roots of g
            prop_assert_eq!(
                a.sign_of(&g) == 0,
                rb.iter().filter(|x| x.cmp_exact(a) == Ordering::Equal).count() == 1
            );
            // each root of f is one of the roots of f·g
            prop_assert_eq!(all.iter().filter(|x| x.cmp_exact(a) == Ordering::Equal).count(), 1);
        }
        // sorted and strictly increasing
        for w in all.windows(2) {
            prop_assert_eq!(w[0].cmp_exact(&w[1]), Ordering::Less);
        }
    }
}

#[test]
fn sign_of_detects_zero_exactly() {
    // α = √2 + tiny: q(α) for q = x^2 - 2 at a root of (x^2 - 2)(x - 3) is 0
    let p = &ZPoly::from_i64s(&[-2, 0, 1]) * &ZPoly::from_i64s(&[-3, 1]);
    let roots = RealAlg::roots_of(&p);
    assert_eq!(roots.len(), 3);
    let q = ZPoly::from_i64s(&[-2, 0, 1]);
    assert_eq!(
        roots.iter().map(|r| r.sign_of(&q)).collect::<Vec<_>>(),
        vec![0, 0, 1]
    );
    // a number 10^-40 away from √2 is not √2
    let big = num_traits::pow(BigInt::from(10), 40);
    let near = ZPoly::new(vec![
        -(BigInt::from(2) * &big * &big + BigInt::one()),
        BigInt::zero(),
        &big * &big,
    ]);
    let r = RealAlg::roots_of(&near);
    assert!(r[1].sign_of(&q).is_positive());
    let s2 = &roots[1];
    assert_eq!(s2.cmp_exact(&r[1]), Ordering::Less);
}

proptest! {
    /// `QSqrt`'s order across fields (one squaring in Q(√d₁)) agrees with
    /// the order of the same numbers as real algebraic numbers (their
    /// minimal polynomials' isolating intervals), and equal values hash
    /// equally whatever the form of the radicand (`b√(k²d) = bk·√d`).
    #[test]
    fn qsqrt_order_across_fields_agrees_with_real_algebraic(
        a in (-40i64..40, 1i64..9), b in (-40i64..40, 1i64..9), d in 2i64..30,
        a2 in (-40i64..40, 1i64..9), b2 in (-40i64..40, 1i64..9), d2 in 2i64..30,
        k in 1i64..5,
    ) {
        use crate::number::QSqrt;
        use std::hash::{Hash, Hasher};
        let q = |(n, m): (i64, i64)| Q::new(n.into(), m.into());
        let x = QSqrt::new(q(a), q(b), Q::from_integer(d.into()));
        let y = QSqrt::new(q(a2), q(b2), Q::from_integer(d2.into()));
        prop_assert_eq!(x.cmp(&y), x.to_real_alg().cmp_exact(&y.to_real_alg()));
        // near-equal values across fields: y moved onto x's rational part
        let z = QSqrt::new(q(a), q(b2), Q::from_integer(d2.into()));
        prop_assert_eq!(x.cmp(&z), x.to_real_alg().cmp_exact(&z.to_real_alg()));
        let hash = |v: &QSqrt| {
            let mut h = std::collections::hash_map::DefaultHasher::new();
            v.hash(&mut h);
            h.finish()
        };
        let other_form = QSqrt::new(q(a), q(b) / Q::from_integer(k.into()), Q::from_integer((k * k * d).into()));
        prop_assert_eq!(&x, &other_form);
        prop_assert_eq!(hash(&x), hash(&other_form));
    }
}
