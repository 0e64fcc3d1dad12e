//! The Poisson route (issue 17): the exact RUR of a square system from
//! resultants computed modulo primes, the value polynomial, the extras of
//! the square subsystem, the verdict from signs — each checked against an
//! independent computation: the exact divisions of the compositions (the
//! verification of the old modular route), the exact route over Q, direct
//! definitions of resultants and characteristic polynomials.

use crate::number::Q;
use crate::number::prime31::{Fp, prime31};
use crate::poly::modp::ModAlgebra;
use crate::poly::mpoly::{X, Y, Z};
use crate::poly::{QMPoly, ZMPoly, parse_poly};
use crate::roots::RealAlg;
use crate::system::groebner_modp::zmpoly_mod;
use crate::system::rur_check::{Check, vanish_on_roots};
use crate::system::rur_square::solve_square;
use crate::system::square_resultant::SquareSystem;
use crate::tangent::witness::WitnessSearch;
use crate::tangent::{Ellipsoid, Verdict};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

fn zpoly(s: &str) -> ZMPoly {
    parse_poly(s).unwrap().to_primitive_z().0
}

/// The forms of `solve_square` used by the tangent route.
const FORMS: [[i64; 3]; 4] = crate::tangent::square_subsystem::FORMS;

/// The RUR satisfies every equation at every root, exactly: `w` divides
/// the homogenised compositions `W^k·f(V/W)` at `(V, w′)` in Z[u] (the
/// exact check of the old route, independent of the CRT and of the bound),
/// and it has as many roots as the Bézout number, all simple.
#[test]
fn the_rur_is_exact() {
    for gens in [
        ["x^2 - 2", "y - x - 1", "z^2 - 3"],
        [
            "x^2 + 2y^2 + 3z^2 - 6",
            "x^3 - 2x*y + z - 1",
            "y^3 + x*z - 2",
        ],
        [
            "2x^2 + y^2 + z^2 + x*y - 5",
            "x^2*y - z^3 + y - 1",
            "x*z^2 + y^2 - 3z + 2",
        ],
    ] {
        let f = gens.map(zpoly);
        let mut sys = SquareSystem::new(f.clone()).unwrap();
        let rur = solve_square(&mut sys, &FORMS, 5000).unwrap();
        assert_eq!(rur.w.degree(), Some(sys.bezout()), "{gens:?}");
        assert!(rur.w.gcd(&rur.wd).degree() == Some(0), "w square-free");
        let checks: Vec<Check> = f
            .iter()
            .map(|p| Check {
                p: p.clone(),
                k: p.total_degree().unwrap(),
                u_coef: BigInt::zero(),
            })
            .collect();
        vanish_on_roots(&rur.w, &rur.v, &rur.wd, &checks)
            .unwrap_or_else(|e| panic!("{gens:?}: a generator does not vanish at the RUR ({e:?})"));
        // ℓ(ξ(τ)) = τ: the separating form maps back to the root
        let l = format!("{}*x + {}*y + {}*z", rur.form[0], rur.form[1], rur.form[2]);
        let lcheck = Check {
            p: zpoly(&l),
            k: 1,
            u_coef: BigInt::one(),
        };
        // with a primitive ℓ the check is ℓ^h(V, w′) − u·w′ ≡ 0
        vanish_on_roots(&rur.w, &rur.v, &rur.wd, &[lcheck]).unwrap();
        // the a-priori bound holds the coefficients it was used for
        let bits = rur.w.coeffs().iter().map(|c| c.bits()).max().unwrap();
        assert!(bits <= rur.bound_bits, "{bits} > {}", rur.bound_bits);
        // the coordinate eliminants: of degree Bézout with lc ±lc(w), each
        // vanishing at its coordinate of every zero; ℓ's is w itself
        let elims = crate::system::rur_square::coordinate_eliminants(&rur, 5000).unwrap();
        for (v, p) in elims.iter().enumerate() {
            assert_eq!(p.degree(), Some(sys.bezout()), "{gens:?}");
            assert_eq!(p.lc().abs(), rur.w.lc().abs(), "{gens:?}");
            let unit: [i64; 3] = std::array::from_fn(|i| i64::from(i == v));
            if rur.form == unit {
                assert_eq!(p, &rur.w, "{gens:?}");
            }
            let as_poly = ZMPoly::from_terms(p.coeffs().iter().enumerate().map(|(i, c)| {
                let mut e = [0u32; crate::poly::mpoly::NVARS];
                e[[X, Y, Z][v]] = i as u32;
                (e, c.clone())
            }));
            let check = Check {
                p: as_poly,
                k: sys.bezout() as u32,
                u_coef: BigInt::zero(),
            };
            vanish_on_roots(&rur.w, &rur.v, &rur.wd, &[check])
                .unwrap_or_else(|e| panic!("{gens:?}: eliminant {v} ({e:?})"));
        }
    }
}

/// Zeros at infinity: the quotient modulo p is not of the Bézout
/// dimension, and the system is declined, not solved wrongly.
#[test]
fn zeros_at_infinity_are_declined() {
    // x·y = 1, x·z = 2 share the zero (0 : 0 : 0 : 1)… at infinity: the
    // leading forms x·y, x·z, y·z − z² have the common zero (1 : 0 : 0)
    let mut sys = SquareSystem::new(["x*y - 1", "x*z - 2", "y*z - z^2 + x"].map(zpoly)).unwrap();
    let d = solve_square(&mut sys, &FORMS, 200).unwrap_err();
    assert!(
        d.0.contains("infinity") || d.0.contains("common zero"),
        "{d:?}"
    );
}

/// The leading-form resultant of three linear forms is their determinant
/// (up to a sign fixed by the degrees), modulo p; it is multiplicative in
/// each form.
#[test]
fn leading_resultant_of_linear_forms_is_the_determinant() {
    let fp = Fp::new(prime31(7));
    let res = |gens: [&str; 3]| -> u64 {
        let mut sys = SquareSystem::new(gens.map(zpoly)).unwrap();
        assert!(sys.choose_dehomogenisation(&[prime31(0), prime31(1)]));
        sys.leading_resultant_mod(&fp).unwrap()
    };
    // det [[2,1,0],[1,3,1],[0,1,4]] = 2·11 − 1·4 = 18
    let r = res(["2x + y + 1", "x + 3y + z - 2", "y + 4z + 5"]);
    assert!(r == 18 || r == fp.p - 18, "{r}");
    // multiplicative: Res(F·G, H, K) = Res(F, H, K)·Res(G, H, K)
    let a = res(["x + 2y - z + 1", "x^2 + y^2 + 3z^2 - 1", "x*y + z^2 + 2"]);
    let b = res(["3x - y + 2z", "x^2 + y^2 + 3z^2 - 1", "x*y + z^2 + 2"]);
    let ab = res([
        "(x + 2y - z + 1)*(3x - y + 2z)",
        "x^2 + y^2 + 3z^2 - 1",
        "x*y + z^2 + 2",
    ]);
    let prod = fp.mul(a, b);
    assert!(ab == prod || ab == fp.neg(prod), "{ab} vs {prod}");
}

/// Berlekamp–Massey, inverses and characteristic polynomials modulo p:
/// `χ(s)` vanishes in the algebra (Cayley–Hamilton), `a·a⁻¹ = 1`, and the
/// characteristic polynomial of T is f itself.
#[test]
fn algebra_mod_p_is_consistent() {
    let fp = Fp::new(prime31(5));
    let mut seed = 17u64;
    let mut rnd = |n: usize| crate::poly::modp::residues_for_tests(&fp, &mut seed, n);
    for n in [1usize, 2, 5, 16, 33] {
        let mut f = rnd(n);
        f.push(1);
        let alg = ModAlgebra::from_poly(fp, &f).unwrap();
        let s = rnd(n);
        let chi = alg.charpoly(&s);
        assert_eq!(chi.len(), n + 1);
        assert_eq!(chi[n], 1);
        // Σ χ_i s^i = 0
        let mut acc = vec![0u64; n];
        let mut pw = vec![0u64; n];
        pw[0] = 1;
        for &c in &chi {
            for (a, &p) in acc.iter_mut().zip(&pw) {
                *a = fp.add(*a, fp.mul(c, p));
            }
            pw = alg.mul(&pw, &s);
        }
        assert!(acc.iter().all(|&a| a == 0), "Cayley–Hamilton, n = {n}");
        if let Some(inv) = alg.inv(&s) {
            let one = alg.mul(&s, &inv);
            assert_eq!(one[0], 1);
            assert!(one[1..].iter().all(|&a| a == 0));
        }
        if n > 1 {
            let mut t = vec![0u64; n];
            t[1] = 1;
            assert_eq!(alg.charpoly(&t), f, "charpoly(T) = f");
            // evaluation with one coordinate T itself = the general one
            let poly = zmpoly_mod(
                &fp,
                &parse_poly("3*x^2*y*z^3 - x*y^4 + 7*z^5 + y^2*z - 2*x + 5")
                    .unwrap()
                    .to_primitive_z()
                    .0,
            );
            let (a, b) = (rnd(n), rnd(n));
            for sep in 0..3 {
                let mut xyz = [a.clone(), b.clone(), a.clone()];
                xyz[sep] = t.clone();
                let refs = [&xyz[0][..], &xyz[1][..], &xyz[2][..]];
                assert_eq!(
                    alg.eval_sep(&poly, refs, sep),
                    alg.eval(&poly, refs),
                    "eval_sep, n = {n}, sep = {sep}"
                );
            }
        }
    }
}

/// The characteristic polynomial by baby steps, giant steps and Newton's
/// identities equals its definition where f splits: for
/// `f = ∏(T − aᵢ)` with distinct `aᵢ`, `χ_s(u) = ∏(u − s(aᵢ))`.  Sizes
/// around the square numbers, where the number of baby steps changes.
#[test]
fn charpoly_is_the_product_over_the_roots_of_a_split_f() {
    let fp = Fp::new(prime31(7));
    let mut seed = 41u64;
    let mut rnd = |n: usize| crate::poly::modp::residues_for_tests(&fp, &mut seed, n);
    // (Σ cᵢ Xⁱ)·(X − a), ascending
    let times_linear = |c: &[u64], a: u64| -> Vec<u64> {
        let mut out = vec![0u64; c.len() + 1];
        for (i, &ci) in c.iter().enumerate() {
            out[i + 1] = fp.add(out[i + 1], ci);
            out[i] = fp.add(out[i], fp.neg(fp.mul(ci, a)));
        }
        out
    };
    let eval = |c: &[u64], x: u64| {
        c.iter()
            .rev()
            .fold(0, |acc, &ci| fp.add(fp.mul(acc, x), ci))
    };
    for n in [1usize, 2, 3, 4, 8, 9, 10, 15, 16, 17, 48, 49, 120] {
        let mut roots = rnd(n);
        roots.sort_unstable();
        roots.dedup();
        let n = roots.len();
        let f = roots
            .iter()
            .fold(vec![1u64], |acc, &a| times_linear(&acc, a));
        let alg = ModAlgebra::from_poly(fp, &f).unwrap();
        for s in [rnd(n), {
            // a constant: one eigenvalue of multiplicity n
            let mut t = vec![0u64; n];
            t[0] = 3;
            t
        }] {
            let want = roots
                .iter()
                .fold(vec![1u64], |acc, &a| times_linear(&acc, eval(&s, a)));
            assert_eq!(alg.charpoly(&s), want, "n = {n}");
        }
    }
}

fn ellipsoid(e: &str) -> Ellipsoid {
    Ellipsoid::from_poly(&parse_poly(e).unwrap()).unwrap()
}

/// The Poisson route against the exact route over Q: the same judging
/// polynomial, the same real critical values, and the verdict from signs
/// alone the same as the verdict from the values.
fn agrees_with_the_exact_route(e: &str, s: &str) {
    let ell = ellipsoid(e);
    let sp = parse_poly(s).unwrap();
    let an = crate::tangent::square_subsystem::analyze(&ell, &sp, true)
        .unwrap_or_else(|d| panic!("{s} on {e}: declined ({d:?})"));
    let exact = match crate::tangent::critical::analyze(&ell, &sp).unwrap() {
        crate::tangent::critical::Outcome::Finite(x) => x,
        crate::tangent::critical::Outcome::Curves(_) => panic!("curves"),
    };
    assert_eq!(an.judging.as_ref(), Some(&exact.judging), "{s} on {e}");
    assert_eq!(an.points(), exact.rur.points, "{s} on {e}");
    let mut a = an.real_values();
    a.sort();
    a.dedup();
    let mut b = exact.real_values();
    b.sort();
    b.dedup();
    assert_eq!(a, b, "{s} on {e}");
    // verdict only: when every sign is decided from boxes (the float
    // filter first), one enclosure per real critical point, each holding
    // an exact critical value of its sign
    let vo_an = crate::tangent::square_subsystem::analyze(&ell, &sp, false).unwrap();
    if vo_an.judging.is_none() {
        assert_eq!(
            vo_an.enclosures.len(),
            vo_an.real_points.len(),
            "{s} on {e}"
        );
        for (sign, (lo, hi)) in &vo_an.enclosures {
            assert!(lo <= hi, "{s} on {e}");
            let held: Vec<&RealAlg> = b
                .iter()
                .filter(|v| v.cmp_rational(lo).is_ge() && v.cmp_rational(hi).is_le())
                .collect();
            assert!(
                !held.is_empty(),
                "{s} on {e}: [{lo}, {hi}] holds no critical value"
            );
            if *sign != 0 {
                let want = sign.cmp(&0);
                assert!(
                    held.iter().all(|v| v.cmp_rational(&Q::zero()) == want),
                    "{s} on {e}"
                );
            }
        }
    }
    let full = crate::tangent::decide_poly(&ell.poly, &sp).unwrap();
    let opts = crate::tangent::TangentOptions::default().without_values();
    let vo = crate::tangent::decide_with(
        &ell,
        &crate::poly::Polynomial::from_inner(sp.clone()),
        &opts,
    )
    .unwrap();
    assert_eq!(vo.verdict(), full.verdict(), "{s} on {e}");
    assert_eq!(vo.side(), full.side(), "{s} on {e}");
    if vo.verdict() == Verdict::Intersecting {
        assert!(vo.certificate().negative_witness().is_some());
        assert!(vo.certificate().positive_witness().is_some());
    }
}

#[test]
fn poisson_route_agrees_on_fixed_cases() {
    for (e, s) in [
        ("x^2 + 2y^2 + 3z^2 + x*z - 6", "x^3 - 2x*y + z^2 + y*z - 1"),
        (
            "2x^2 + y^2 + 3z^2 + x*y - y*z - 7",
            "x^3 + y^3 - z^3 + x*z - 2y + 1",
        ),
        // a critical point on the silhouette z = 0 of the first direction
        // (the extras of n = e_z are then not simple): another direction
        ("x^2 + y^2 + z^2 - 1", "x^3 + y^3 + z^3 + x*y/3"),
        // separated pairs (every real critical value positive)
        ("x^2 + 2y^2 + 3z^2 - 2", "x^3 + y^3 + 2z^3 + x*y + 5"),
        ("x^2 + 2y^2 + 3z^2 - 2", "x^3 + y^2*z - x*z + 4"),
    ] {
        agrees_with_the_exact_route(e, s);
    }
}

/// D(u) with its CRT stopped by the direct bound (the Mahler measures of
/// the coordinate eliminants) is D(u) with the Landau–Sombra bound: the
/// same polynomial, from fewer primes.
#[test]
fn the_direct_bound_gives_the_same_judging_polynomial() {
    for (e, s) in [
        (
            "18*x*x - 12*x*y + 10*x*z + 23*y*y - 24*y*z + 14*z*z - 2*x + 3*y + 2*z - 27",
            "x^4 + y^4 + z^4 - x*y - 2",
        ),
        (
            "x^2 + y^2 + z^2 - 4",
            "x^4 + 2x^3*y - y^3*z + 3x*z^3 - 2y^2*z^2 + x^2 - y*z + z - 2",
        ),
    ] {
        let (ell, sp) = (ellipsoid(e), parse_poly(s).unwrap());
        let direct = crate::tangent::square_subsystem::analyze(&ell, &sp, true).unwrap();
        let bits = direct.value_direct_bits.expect("the direct bound is used");
        assert!(bits < direct.value_bound_bits, "{s} on {e}");
        crate::tangent::square_subsystem::GENERAL_BOUND_ONLY.with(|c| c.set(true));
        let general = crate::tangent::square_subsystem::analyze(&ell, &sp, true).unwrap();
        crate::tangent::square_subsystem::GENERAL_BOUND_ONLY.with(|c| c.set(false));
        assert!(general.value_direct_bits.is_none());
        assert_eq!(direct.judging, general.judging, "{s} on {e}");
        assert!(direct.value_primes < general.value_primes, "{s} on {e}");
    }
}

/// Three systems the census certifies: a quartic on a general ellipsoid, a
/// dense quartic on a sphere, a quintic on an axis-aligned ellipsoid.
const CENSUS_CASES: [(&str, &str); 3] = [
    (
        "18*x*x - 12*x*y + 10*x*z + 23*y*y - 24*y*z + 14*z*z - 2*x + 3*y + 2*z - 27",
        "x^4 + y^4 + z^4 - x*y - 2",
    ),
    (
        "x^2 + y^2 + z^2 - 4",
        "x^4 + 2x^3*y - y^3*z + 3x*z^3 - 2y^2*z^2 + x^2 - y*z + z - 2",
    ),
    (
        "x^2 + 2*y^2 + 3*z^2 - 7",
        "x^5 - 3x^2*y^3 + y*z^4 - 2x*y*z + z^3 - x + 4",
    ),
];

/// The census route (an a-posteriori bound from certified boxes around
/// all complex zeros) and Sombra's a-priori bound give the same RUR and
/// the same D(u); the census's bound holds every coefficient it was used
/// for, its R̄ is w's leading coefficient, it has one box per zero, and it
/// saves primes.
#[test]
fn the_census_bound_gives_the_same_rur_and_judging_polynomial() {
    use crate::system::rur_square::NO_CENSUS;
    for (e, s) in CENSUS_CASES {
        let (ell, sp) = (ellipsoid(e), parse_poly(s).unwrap());
        let with = crate::tangent::square_subsystem::analyze(&ell, &sp, true).unwrap();
        NO_CENSUS.with(|c| c.set(true));
        let without = crate::tangent::square_subsystem::analyze(&ell, &sp, true);
        NO_CENSUS.with(|c| c.set(false));
        let without = without.unwrap();
        assert!(without.rur.census.is_none());
        let c = with.rur.census.as_ref().expect("the census certifies");
        assert_eq!(with.rur.w, without.rur.w, "{s} on {e}");
        assert_eq!(with.rur.v, without.rur.v, "{s} on {e}");
        assert_eq!(with.judging, without.judging, "{s} on {e}");
        assert_eq!(c.zeros.boxes.len(), with.rur.w.degree().unwrap());
        assert_eq!(c.rbar.abs(), with.rur.w.lc().abs());
        let top = std::iter::once(&with.rur.w)
            .chain(with.rur.v.iter())
            .flat_map(|p| p.coeffs())
            .map(|x| x.bits())
            .max()
            .unwrap();
        assert!(
            top <= c.bits && c.bits == with.rur.bound_bits,
            "{top} vs {}",
            c.bits
        );
        assert!(with.rur.primes < without.rur.primes, "{s} on {e}");
        // the eliminant bound from the census holds the exact eliminants
        let elims = crate::system::rur_square::coordinate_eliminants(&without.rur, 5000).unwrap();
        for (v, p) in elims.iter().enumerate() {
            let bits = p.coeffs().iter().map(|x| x.bits()).max().unwrap();
            assert!(
                bits <= c.rbar.bits() + c.coordinate_bits[v],
                "{s} on {e}: v = {v}"
            );
        }
        // D(u)'s bound from the census holds D(u) before the scaling
        assert!(with.value_direct_bits.unwrap() < without.value_direct_bits.unwrap_or(u64::MAX));
    }
}

/// The real roots read off the census boxes (no isolation) are the roots
/// an isolation finds, in the same order, and the boxes of the real zeros
/// have real centres.
#[test]
fn census_boxes_give_the_real_roots_of_the_isolation() {
    for (e, s) in CENSUS_CASES {
        let (ell, sp) = (ellipsoid(e), parse_poly(s).unwrap());
        let an = crate::tangent::square_subsystem::analyze(&ell, &sp, false).unwrap();
        let c = an.rur.census.as_ref().expect("the census certifies");
        let from_boxes = crate::tangent::square_subsystem::census_real_roots(
            &an.critical,
            &c.zeros,
            an.rur.form,
        )
        .expect("every box is classified");
        let isolated = RealAlg::roots_of(&an.critical);
        assert!(!isolated.is_empty());
        assert_eq!(from_boxes.len(), isolated.len(), "{s} on {e}");
        for (a, b) in from_boxes.iter().zip(&isolated) {
            assert_eq!(a.cmp_exact(b), std::cmp::Ordering::Equal, "{s} on {e}");
        }
        let real_boxes = c.zeros.boxes.iter().filter(|b| b.is_real()).count();
        assert!(real_boxes >= isolated.len(), "{s} on {e}");
        assert!(
            c.zeros
                .boxes
                .iter()
                .all(|b| b.is_real() || b.misses_real_space())
        );
    }
}

/// The census proves statements about F, never about the candidate: from
/// a wrong candidate it still encloses the true zeros (every real zero of
/// the exact RUR lies in one of its boxes) or declines; at a double zero
/// it declines.
#[test]
fn the_census_is_about_the_system_not_the_candidate() {
    use crate::system::census::census;
    let gens = [
        "x^2 + 2y^2 + 3z^2 - 6",
        "x^3 - 2x*y + z - 1",
        "y^3 + x*z - 2",
    ]
    .map(zpoly);
    let mut sys = SquareSystem::new(gens.clone()).unwrap();
    let rur = solve_square(&mut sys, &FORMS, 5000).unwrap();
    let mut wrong = rur.w.coeffs().to_vec();
    wrong[0] += BigInt::from(1);
    let wrong = crate::poly::ZPoly::new(wrong);
    for w in [&rur.w, &wrong] {
        let Some(c) = census(&gens, w, &rur.v) else {
            continue;
        };
        assert_eq!(c.boxes.len(), 18);
        for t in RealAlg::roots_of(&rur.w) {
            let mut t = t;
            t.refine_to(&Q::new(BigInt::one(), BigInt::one() << 80usize));
            let p = rur.point_at(&t.to_rational_approx(80)).unwrap();
            let inside = c.boxes.iter().any(|b| {
                (0..3).all(|k| {
                    let x = crate::number::float::nearest_double(&p[k]).unwrap();
                    (x - b.centre[k].re).abs() <= b.half * 1.001 && b.centre[k].im.abs() <= b.half
                })
            });
            assert!(inside, "a real zero outside every box");
        }
    }
    // a double zero: x² = 0, y = 1, z = 2 (N = 2 with multiplicity)
    let gens = ["x^2", "y - 1", "z - 2"].map(zpoly);
    let zp = |v: &[i64]| crate::poly::ZPoly::new(v.iter().map(|&c| BigInt::from(c)).collect());
    let w = zp(&[0, 0, 1]);
    let v = [zp(&[0, 0]), zp(&[0, 2]), zp(&[0, 4])];
    assert!(census(&gens, &w, &v).is_none());
}

/// A degenerate critical point (the critical ideal is not radical: 12
/// points, 14 with multiplicity) makes every square subsystem non-radical:
/// the route declines, and the exact route answers.
#[test]
fn multiple_critical_points_are_declined() {
    let (e, s) = ("x^2 + y^2 + z^2 - 1", "x^3 - 2y*z + x*y*z + 5");
    let d = crate::tangent::square_subsystem::analyze(&ellipsoid(e), &parse_poly(s).unwrap(), true)
        .unwrap_err();
    assert!(d.0.contains("multiple zeros"), "{d:?}");
    let r = crate::tangent::decide_str(e, s).unwrap();
    assert_eq!(r.verdict(), Verdict::Separated);
    assert_eq!(
        r.certificate().method(),
        crate::tangent::Method::CriticalIdeal
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10, .. ProptestConfig::default() })]

    /// Random cubics against rotated, shifted ellipsoids (Cayley rotations
    /// give rational rotation matrices): the Poisson route and the exact
    /// route agree exactly, and the verdict from signs is the verdict.
    #[test]
    fn poisson_route_agrees_with_the_exact_route(
        c in prop::collection::vec(-3i64..4, 10),
        axes in (1i64..4, 1i64..4, 1i64..4),
        rot in (-2i64..3, -2i64..3, 1i64..3),
        r in 2i64..9,
    ) {
        let s = format!(
            "{}x^3 + {}y^3 + {}z^3 + {}x^2*y + {}y^2*z + {}x*z^2 + {}x*y*z + {}x^2 + {}y + {}",
            c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9]
        );
        let sp = parse_poly(&s).unwrap();
        prop_assume!(sp.total_degree() == Some(3));
        // E = Σ axes_i·(R·p)_i² − r with R a Cayley rotation
        let (a, b, d) = rot;
        let rm = crate::cayley_rotation(&Q::from_integer(a.into()), &Q::from_integer(b.into()), &Q::new(1.into(), d.into()));
        let p = [QMPoly::var(X), QMPoly::var(Y), QMPoly::var(Z)];
        let ax = [axes.0, axes.1, axes.2];
        let mut e = QMPoly::constant(Q::from_integer((-r).into()));
        for i in 0..3 {
            let mut row = QMPoly::zero();
            for j in 0..3 {
                row = &row + &p[j].scale(&rm[i][j]);
            }
            e = &e + &(&row * &row).scale(&Q::from_integer(ax[i].into()));
        }
        let es = e.to_string_canonical();
        let ell = Ellipsoid::from_poly(&e).unwrap();
        // inputs with curves of critical points or symmetric values go to
        // other routes; here only the general-position ones are compared
        prop_assume!(crate::tangent::square_subsystem::analyze(&ell, &sp, true).is_ok());
        prop_assume!(matches!(
            crate::tangent::critical::analyze(&ell, &sp),
            Ok(crate::tangent::critical::Outcome::Finite(_))
        ));
        agrees_with_the_exact_route(&es, &s);
    }
}

/// The witnesses near the least and the greatest critical value (they share
/// the approximate values of S at the real critical points, computed once)
/// have the asked signs, and a witness asked for another S (here −S, whose
/// greatest value is −min S) is searched with that S's own values: it lies
/// near the point where S is least.
#[test]
fn witnesses_of_min_and_max_and_of_another_surface() {
    let ell = ellipsoid("2x^2 + y^2 + 3z^2 + x*y - y*z - 7");
    let sp = parse_poly("x^3 + y^3 - z^3 + x*z - 2y + 1").unwrap();
    let an = crate::tangent::square_subsystem::analyze(&ell, &sp, true).unwrap();
    let vals = an.real_values();
    let (lo, hi) = (vals.first().unwrap(), vals.last().unwrap());
    assert!(lo.signum() < 0 && hi.signum() > 0, "an intersecting pair");
    let neg = an.witness(lo, &ell, &sp, -1).expect("a negative witness");
    let pos = an.witness(hi, &ell, &sp, 1).expect("a positive witness");
    assert_eq!((neg.sign, pos.sign), (-1, 1));
    let minus = -sp.clone();
    let an_minus = crate::tangent::square_subsystem::analyze(&ell, &minus, true).unwrap();
    let top = an_minus.real_values().last().unwrap().clone();
    let w = an.witness(&top, &ell, &minus, 1).expect("a witness for −S");
    assert_eq!(w.sign, 1);
    let approx = |p: &crate::tangent::WitnessPoint| -> Vec<f64> {
        p.coords
            .iter()
            .map(|c| c.approx(20).parse::<f64>().unwrap())
            .collect()
    };
    for (a, b) in approx(&w).iter().zip(approx(&neg)) {
        assert!(
            (a - b).abs() < 0.05,
            "{:?} vs {:?}",
            approx(&w),
            approx(&neg)
        );
    }
}

/// D(u)'s real roots isolated from approximations of the values: the same
/// roots as Descartes' rule whenever the signs of D at the separators
/// alternate (good, rough and misplaced approximations alike), narrow
/// brackets where an approximation is within 2^-24, the isolating interval
/// between separators otherwise, and `None` when a sign does not alternate,
/// an approximation is missing or two coincide.
/// The separators of D(u)'s roots: the dyadic with the fewest bits in an
/// interval lies in it, and no dyadic with one bit less does.
#[test]
fn shortest_dyadics() {
    use crate::tangent::square_subsystem::short_dyadic_in;
    let q = |n: i64, d: i64| Q::new(BigInt::from(n), BigInt::from(d));
    for (lo, hi, want) in [
        (q(1, 3), q(2, 3), (BigInt::from(1), 1)),
        (q(-5, 2), q(7, 1), (BigInt::from(-2), 0)),
        (q(1, 1000), q(3, 1000), (BigInt::from(1), 9)),
        (
            q(7, 5),
            q(7_000_001, 5_000_000),
            (BigInt::from(2_936_013), 21),
        ),
    ] {
        let (m, k) = short_dyadic_in(&lo, &hi);
        let x = crate::number::dyadic(m.clone(), k as usize);
        assert!(lo <= x && x <= hi, "{lo}..{hi}: {x}");
        assert_eq!((m, k), want, "{lo}..{hi}");
    }
}

#[test]
fn judging_roots_from_approximate_values() {
    use crate::tangent::square_subsystem::isolate_by_values;
    // (u + 2)(u − 1)(u − 3)(u² + 1): real roots −2, 1, 3
    let d = [[2, 1], [-1, 1], [-3, 1], [1, 0]]
        .iter()
        .fold(crate::poly::ZPoly::from_i64s(&[1, 0, 1]), |acc, f| {
            &acc * &crate::poly::ZPoly::from_i64s(f)
        });
    let exact = crate::roots::RealAlg::roots_of(&d);
    let q = |n: i64, den: i64| Some(Q::new(BigInt::from(n), BigInt::from(den)));
    let width = |r: &crate::roots::RealAlg| {
        let (lo, hi) = r.interval();
        hi - lo
    };
    let tiny = Q::new(BigInt::one(), BigInt::one() << 20usize);
    // within 2^-40: narrow brackets
    let near = [q(-2, 1), q(1_099_511_627_777, 1_099_511_627_776), q(3, 1)];
    let roots = isolate_by_values(&d, &near).expect("isolated");
    assert_eq!(roots, exact);
    assert!(
        roots
            .iter()
            .all(|r| width(r) <= &tiny * Q::from_integer(BigInt::from(4)))
    );
    // within 2^-100: brackets of about 2^-86, narrow enough to print 20
    // digits without refining
    let close = Q::one() + Q::new(BigInt::one(), BigInt::one() << 100usize);
    let roots = isolate_by_values(&d, &[q(-2, 1), Some(close), q(3, 1)]).expect("isolated");
    assert_eq!(roots, exact);
    let w84 = Q::new(BigInt::one(), BigInt::one() << 84usize);
    assert!(width(&roots[1]) <= w84, "{:?}", roots[1].interval());
    // off by 10^-3: still isolated, the brackets stay between separators
    let rough = [q(-2001, 1000), q(1001, 1000), q(2999, 1000)];
    let roots = isolate_by_values(&d, &rough).expect("isolated");
    assert_eq!(roots, exact);
    assert!(roots.iter().all(|r| width(r) > tiny.clone()));
    // 3/2 for the root 3: the signs still alternate, so still isolated
    let misplaced = [q(-2, 1), q(1, 1), q(3, 2)];
    assert_eq!(isolate_by_values(&d, &misplaced).expect("isolated"), exact);
    // 3 and 5 for the roots 1 and 3: D > 0 at both separators
    assert!(isolate_by_values(&d, &[q(-2, 1), q(3, 1), q(5, 1)]).is_none());
    // fewer approximations than real roots: D's sign at +∞ does not match
    assert!(isolate_by_values(&d, &[q(-2, 1), q(1, 1)]).is_none());
    assert!(isolate_by_values(&d, &[q(-2, 1), None, q(3, 1)]).is_none());
    assert!(isolate_by_values(&d, &[q(-2, 1), q(1, 1), q(1, 1)]).is_none());
}
