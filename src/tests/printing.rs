//! Printed approximations near zero (issue "right to the last printed
//! digit"): every `approx` of a real algebraic value is within 10⁻¹⁸
//! relative of the value however close to 0 it is, and the printed
//! isolating interval holds the value and excludes 0 when the value is not
//! 0.  The values come from near-tangent constructions (a configuration
//! moved by 10⁻ᵏ from a tangency, k up to 60) and from the paper examples;
//! the reference is an independent refinement of the exact value to an
//! absolute width far below its magnitude.

use crate::cli::examples::tangent::PAPER_004;
use crate::number::{Q, parse_rational, q};
use crate::poly::ZPoly;
use crate::roots::RealAlg;
use crate::tangent::decide_str;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

/// `10^-k` as a decimal literal.
fn tenth(k: u32) -> String {
    format!("1e-{k}")
}

/// The value refined independently: an absolute width of 2^-(b + 80),
/// where 2^-b is below |x| (found by refining until the interval leaves a
/// neighbourhood of 0, or the value is the rational 0).
fn reference(x: &RealAlg) -> Q {
    let (lo, hi) = x.interval();
    let mut r = if lo == hi {
        return lo;
    } else {
        RealAlg::new(&crate::poly::IntPoly::from_inner(x.poly()), &lo, &hi)
            .expect("a valid isolating interval")
    };
    let mut bits = 64u32;
    loop {
        r.refine_to(&Q::new(BigInt::one(), BigInt::one() << bits as usize));
        let (lo, hi) = r.interval();
        if lo == hi {
            return lo;
        }
        if lo.is_positive() || hi.is_negative() {
            let small = if lo.is_positive() { lo } else { -hi };
            let b = crate::number::floor_log2_q(&small);
            let target = (-b + 80).max(bits as i64) as usize;
            r.refine_to(&Q::new(BigInt::one(), BigInt::one() << target));
            let (lo, hi) = r.interval();
            return (lo + hi) / Q::from_integer(2.into());
        }
        assert!(bits < 4096, "a non-zero value below 2^-4096");
        bits *= 2;
    }
}

/// `lo ≤ x ≤ hi`, decided exactly.
fn holds(x: &RealAlg, lo: &Q, hi: &Q) -> bool {
    use std::cmp::Ordering::{Greater, Less};
    x.cmp_rational(lo) != Less && x.cmp_rational(hi) != Greater
}

/// The printed digits within 10⁻¹⁸ relative of the value.
fn assert_close(printed: &str, exact: &Q, what: &str) {
    let p = parse_rational(printed).unwrap_or_else(|e| panic!("{what}: `{printed}`: {e}"));
    if exact.is_zero() {
        assert!(p.is_zero(), "{what}: printed {printed} for 0");
        return;
    }
    let rel = ((&p - exact) / exact).abs();
    assert!(
        rel <= q(1, 1_000_000_000_000_000_000),
        "{what}: printed {printed}, value ≈ {}, relative error {}",
        crate::number::approx_decimal(exact, 25),
        crate::number::approx_decimal(&rel, 3)
    );
}

/// A value as printed (JSON `approx` and interval, human text, `describe`):
/// digits close to the value, the interval holding it and, unless it is 0,
/// excluding 0.
fn check_value(x: &RealAlg, what: &str) {
    let exact = reference(x);
    assert_close(&x.approx(20), &exact, what);
    let (_, [lo, hi], digits) = x.describe();
    assert_close(&digits, &exact, what);
    let (lo, hi) = (parse_rational(&lo).unwrap(), parse_rational(&hi).unwrap());
    assert!(holds(x, &lo, &hi), "{what}: [{lo}, {hi}] misses the value");
    if !exact.is_zero() {
        assert!(
            lo.is_positive() || hi.is_negative(),
            "{what}: the printed interval [{lo}, {hi}] of a non-zero value holds 0"
        );
    }
}

/// Every value of a tangent answer, printed every way.
fn check_report(e: &str, s: &str) {
    let r = decide_str(e, s).unwrap_or_else(|err| panic!("{e} / {s}: {err}"));
    let what = format!("{e} / {s}");
    for (name, v) in [("min", r.min()), ("max", r.max())] {
        if let Some(v) = v {
            check_value(v, &format!("{what}: {name}"));
        }
    }
    let c = r.certificate();
    for v in c.critical_values().iter().chain(c.nonreal_point_values()) {
        check_value(v, &format!("{what}: critical value"));
    }
    let json = serde_json::to_value(&r).unwrap();
    for key in ["min", "max"] {
        let v = &json[key];
        if v.is_null() {
            continue;
        }
        let value = match key {
            "min" => r.min(),
            _ => r.max(),
        }
        .unwrap();
        let exact = reference(value);
        assert_close(
            v["approx"].as_str().unwrap(),
            &exact,
            &format!("{what}: JSON {key}"),
        );
        let lo = parse_rational(v["interval"][0].as_str().unwrap()).unwrap();
        let hi = parse_rational(v["interval"][1].as_str().unwrap()).unwrap();
        assert!(holds(value, &lo, &hi), "{what}: JSON {key} interval");
        if !exact.is_zero() {
            assert!(
                lo.is_positive() || hi.is_negative(),
                "{what}: JSON {key} interval holds 0"
            );
        }
    }
}

/// The torus `(x²+y²+z²+3)² − 16(x²+y²)` (tube radius 1 about the circle of
/// radius 2) and a unit sphere touching it at (8/5·(3/5, 4/5), …): the
/// sphere's centre moved by `sign·10^-k` along `dir`.
fn torus_case(k: u32, sign: i32, dir: usize) -> (String, String) {
    let d = tenth(k);
    let s = if sign > 0 { "-" } else { "+" };
    let mut c = ["54/25".to_string(), "72/25".to_string(), "6/5".to_string()];
    c[dir] = format!("{}{s}{d}", c[dir]);
    (
        format!("(x-({}))^2+(y-({}))^2+(z-({}))^2-1", c[0], c[1], c[2]),
        "(x^2+y^2+z^2+3)^2-16(x^2+y^2)".to_string(),
    )
}

/// The plane `n·x = c` against `x²/a + y²/b + z²/c − 1`: its extreme
/// `±√(a n₀² + b n₁² + c n₂²)` cut by a decimal `c` that agrees with it to
/// `k` digits, so that the min or max is an irrational of size 10^-k.
fn plane_case(k: u32, axes: [i64; 3], n: [i64; 3], above: bool) -> (String, String) {
    let r2: i64 = (0..3).map(|i| axes[i] * n[i] * n[i]).sum();
    // ⌊√r2 · 10^k⌋ (or ⌈…⌉) in integers
    let scale = BigInt::from(10).pow(k);
    let m = (BigInt::from(r2) * &scale * &scale).sqrt();
    let m = if above { m + 1 } else { m };
    (
        format!("x^2/{}+y^2/{}+z^2/{}-1", axes[0], axes[1], axes[2]),
        format!("{}x+{}y+{}z-{}/{}", n[0], n[1], n[2], m, scale),
    )
}

#[test]
fn a_tiny_root_isolated_from_zero_prints_right() {
    // 2^170·u² − 3: the positive root is √3·2^-85 ≈ 4.48e-26, isolated in (0, 256)
    let p = ZPoly::new(vec![
        BigInt::from(-3),
        BigInt::zero(),
        BigInt::one() << 170usize,
    ]);
    let x = RealAlg::new(
        &crate::poly::IntPoly::from_inner(p.clone()),
        &Q::zero(),
        &Q::from_integer(256.into()),
    )
    .unwrap();
    check_value(&x, "√3·2^-85");
    assert!(x.approx(20).starts_with("4.4772"), "{}", x.approx(20));
    // and the negative one, isolated in (−1, 0)
    let y = RealAlg::new(
        &crate::poly::IntPoly::from_inner(p.clone()),
        &Q::from_integer((-1).into()),
        &Q::zero(),
    )
    .unwrap();
    check_value(&y, "−√3·2^-85");
    assert!(y.approx(20).starts_with("-4.4772"));
    // a root straddled by an interval around 0 (−1, 1) of 10^60·u − 7·u²… :
    // 10^60·u² + u − 10^-60 has roots near ±10^-60 … use integers
    let p = ZPoly::new(vec![
        BigInt::from(-1),
        BigInt::from(1),
        BigInt::from(10).pow(120),
    ]);
    for iv in [(q(0, 1), q(1, 1)), (q(-1, 1), q(0, 1))] {
        let x = RealAlg::new(&crate::poly::IntPoly::from_inner(p.clone()), &iv.0, &iv.1).unwrap();
        check_value(&x, "a root of 10^120·u² + u − 1");
    }
}

#[test]
fn quadratic_irrationals_print_right_under_cancellation() {
    // a + b√d with a ≈ −b√d to 70 digits
    let d = Q::from_integer(2.into());
    let scale = BigInt::from(10).pow(70);
    let a = Q::new((BigInt::from(2) * &scale * &scale).sqrt(), scale);
    let x = crate::number::QSqrt::new(-a.clone(), Q::one(), d);
    let printed = x.approx(20);
    // √2 − ⌊√2·10^70⌋/10^70 lies in (0, 10^-70)
    let p = parse_rational(&printed).unwrap();
    let exact_lo = x.to_rational_approx(400);
    let rel = ((&p - &exact_lo) / &exact_lo).abs();
    assert!(rel < q(1, 1_000_000_000_000_000_000), "{printed}");
    assert!(p.is_positive() && p < Q::new(BigInt::one(), BigInt::from(10).pow(69)));
}

#[test]
fn torus_near_tangencies_print_right() {
    for k in [5, 29, 45, 60] {
        for sign in [1, -1] {
            let (e, s) = torus_case(k, sign, 0);
            check_report(&e, &s);
        }
    }
}

#[test]
fn paper_examples_print_right() {
    for ex in PAPER_004 {
        check_report(ex.ellipsoid, ex.surface);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]

    /// Near-tangent constructions, a surface moved by 10⁻ᵏ from a tangency
    /// (k ≤ 60): every printed value is right to its last digit.
    #[test]
    fn near_tangent_values_print_right(
        k in 1u32..=60,
        family in 0usize..2,
        sign in prop::sample::select(vec![-1, 1]),
        dir in 0usize..3,
        axes in prop::array::uniform3(1i64..9),
        n in prop::array::uniform3(-4i64..5),
    ) {
        let (e, s) = if family == 0 {
            torus_case(k, sign, dir)
        } else {
            let n = if n == [0, 0, 0] { [1, 2, 3] } else { n };
            plane_case(k, axes, n, sign > 0)
        };
        check_report(&e, &s);
    }
}
