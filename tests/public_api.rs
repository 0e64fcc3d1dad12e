//! A user's view: the three jobs through the crate-root API only (this file
//! is an external crate, so it sees nothing but the public API).  CI runs it
//! with the default features and with `--no-default-features`.

use quadsect::Class;
use quadsect::Verdict;
use quadsect::natural::Component;
use quadsect::tangent::{Method, Side, Undecided};
use quadsect::{
    Budget, ClassifyOptions, Cone, Cylinder, Ellipsoid, ErrorKind, IntPoly, Limit, Natural,
    Polynomial, QSqrt, Rational, RealAlg, Sign, Sphere, TangentOptions, Var,
};
use std::collections::{BTreeMap, HashSet};
use std::time::Duration;

fn r(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

#[test]
fn tangent_job_with_certificate() {
    let e: Ellipsoid = "x^2+y^2+z^2-25".parse().unwrap();
    // paper Example 1 (separated) and a crossing variant
    let s: Polynomial = "(x-9)^2/9+y^2/4+z^2/16-1".parse().unwrap();
    let rep = quadsect::decide(&e, &s).unwrap();
    assert_eq!(rep.verdict(), Verdict::Separated);
    assert_eq!(rep.side(), Some(Side::Positive));
    assert_eq!(rep.min().unwrap(), &RealAlg::from(q(7, 9)));
    assert_eq!(rep.max().unwrap(), &RealAlg::from(q(187, 9)));
    // the trap: values at non-real critical points are listed, never counted
    let nonreal = rep.certificate().nonreal_point_values();
    assert!(nonreal.contains(&RealAlg::from(q(-1233, 112))));
    assert!(rep.to_string().contains("separated"));

    let s2: Polynomial = "(x-6)^2/9+y^2/4+z^2/16-1".parse().unwrap();
    let rep = quadsect::decide(&e, &s2).unwrap();
    assert_eq!(rep.verdict(), Verdict::Intersecting);
    let neg = rep.certificate().negative_witness().unwrap();
    let pos = rep.certificate().positive_witness().unwrap();
    assert_eq!((neg.sign(), pos.sign()), (Sign::Negative, Sign::Positive));
    assert!(neg.value() < pos.value());
    assert!(!matches!(
        rep.certificate().method(),
        Method::None | Method::Constant
    ));
}

#[test]
fn ellipsoid_constructors_check() {
    let id = [[r(1), r(0), r(0)], [r(0), r(1), r(0)], [r(0), r(0), r(1)]];
    let e = Ellipsoid::from_axes([r(0), r(0), r(0)], [r(5), r(5), r(5)], id.clone()).unwrap();
    assert_eq!(
        e.polynomial().to_string(),
        "1/25*x^2 + 1/25*y^2 + 1/25*z^2 - 1"
    );
    let rot = quadsect::cayley_rotation(&q(1, 2), &r(1), &q(-1, 3));
    assert!(quadsect::is_rotation(&rot));
    let moved = Ellipsoid::from_axes([r(1), r(2), r(3)], [r(1), r(2), r(3)], rot).unwrap();
    assert_eq!(moved.center(), &[r(1), r(2), r(3)]);
    // not a rotation, zero semi-axis, singular frame, hyperboloid: checked errors
    let mut bad = id.clone();
    bad[0][1] = r(1);
    assert!(Ellipsoid::from_axes([r(0), r(0), r(0)], [r(1), r(1), r(1)], bad.clone()).is_err());
    assert!(Ellipsoid::from_frame([r(0), r(0), r(0)], [r(1), r(1), r(1)], bad).is_ok());
    assert!(Ellipsoid::from_axes([r(0), r(0), r(0)], [r(0), r(1), r(1)], id).is_err());
    let err = "x^2+y^2-z^2-1".parse::<Ellipsoid>().unwrap_err();
    assert_eq!(err.kind(), ErrorKind::NotAnEllipsoid);
    assert!(
        !err.to_string().contains("--"),
        "library messages name no CLI flag: {err}"
    );
}

#[test]
fn natural_job_typed_and_parsed() {
    let a = Natural::Cylinder(Cylinder::new([r(0), r(0), r(0)], [r(1), r(0), r(0)], r(1)).unwrap());
    let b: Natural = "cylinder point=0,0,0 axis=0,1,0 radius2=1".parse().unwrap();
    let rep = quadsect::classify(&a, &b).unwrap();
    assert_eq!(rep.class(), Class::Conics);
    assert_eq!((rep.conics(), rep.lines(), rep.points()), (2, 0, 0));
    assert_eq!(rep.thm8(), Some(true));
    assert!(
        rep.components()
            .iter()
            .all(|c| matches!(c, Component::Conic { .. }))
    );
    assert_eq!(rep.class().to_string(), "conics");

    let c = Natural::Cone(Cone::new([r(0), r(0), r(0)], [r(1), r(0), r(0)], r(1)).unwrap());
    let d: Natural = "cone vertex=0,0,0 axis=0,1,0 tan2=3".parse().unwrap();
    assert_eq!(quadsect::classify(&c, &d).unwrap().class(), Class::Lines);

    let s1 = Natural::Sphere(Sphere::new([r(0), r(0), r(0)], r(1)).unwrap());
    let same = quadsect::classify(&s1, &s1).unwrap();
    assert_eq!(same.class(), Class::SameSurface);
    assert!(!same.to_string().contains("no real intersection"));

    // typed constructors refuse what is not a surface
    assert_eq!(
        Sphere::new([r(0), r(0), r(0)], r(0)).unwrap_err().kind(),
        ErrorKind::BadQuadric
    );
    assert!(Cone::new([r(0), r(0), r(0)], [r(0), r(0), r(0)], r(1)).is_err());
    assert!(
        "cone vertex=0,0,0 axis=1,0,0 tan2=-1"
            .parse::<Natural>()
            .is_err()
    );
    // a rigid motion must be a rotation
    let rot = quadsect::cayley_rotation(&r(1), &r(2), &r(3));
    let moved = a.moved_by(&rot, &[r(1), r(0), r(0)]).unwrap();
    assert_eq!(
        quadsect::classify(&moved, &b.moved_by(&rot, &[r(1), r(0), r(0)]).unwrap())
            .unwrap()
            .class(),
        Class::Conics
    );
    let mut not_rot = rot.clone();
    not_rot[0][0] = r(2);
    assert!(a.moved_by(&not_rot, &[r(0), r(0), r(0)]).is_err());
    assert_eq!(quadsect::natural::thm8(&a, &b), Some(true));
}

#[test]
fn kernel_job() {
    let p: Polynomial = "(x^2-2)^3 (x-1/3)".parse().unwrap();
    let rep = quadsect::roots(&p).unwrap();
    assert_eq!((rep.distinct_real(), rep.real_with_multiplicity()), (3, 7));
    let roots: Vec<RealAlg> = rep.roots().map(|x| x.value()).collect();
    assert!(roots.windows(2).all(|w| w[0] < w[1]));
    let mults: Vec<u32> = rep.roots().map(|x| x.multiplicity()).collect();
    assert_eq!(mults, vec![3, 1, 3]);
    assert_eq!(roots[1], RealAlg::from(q(1, 3)));
    assert_eq!(rep.variable(), Some(Var::X));

    let f: Polynomial = "x^2 + y^2 - 1".parse().unwrap();
    let g = Polynomial::var(Var::X) - Polynomial::var(Var::Y);
    let res = quadsect::resultant(&f, &g, Var::X).unwrap();
    assert_eq!(res.resultant(), 2 * Polynomial::var(Var::Y).pow(2) - 1);
    assert_eq!(
        quadsect::roots(&"x*y".parse().unwrap()).unwrap_err().kind(),
        ErrorKind::NotUnivariate
    );
}

#[test]
fn exact_numbers_order_and_hash() {
    let p: IntPoly = "u^2 - 2".parse().unwrap();
    let s2 = RealAlg::new(&p, &r(1), &r(2)).unwrap();
    let p4: IntPoly = "u^4 - 4".parse().unwrap();
    let s2b = RealAlg::new(&p4, &r(0), &r(3)).unwrap();
    assert_eq!(s2, s2b);
    let mut map = BTreeMap::new();
    map.insert(s2.clone(), "sqrt2");
    map.insert(RealAlg::from(q(3, 2)), "3/2");
    map.insert(RealAlg::from(r(1)), "1");
    assert_eq!(
        map.values().copied().collect::<Vec<_>>(),
        ["1", "sqrt2", "3/2"]
    );
    let set: HashSet<RealAlg> = [s2.clone(), s2b].into_iter().collect();
    assert_eq!(set.len(), 1, "equal numbers hash equally");
    // the misuse cases of the issue are checked errors now
    assert_eq!(
        RealAlg::new(&p, &r(0), &r(1)).unwrap_err().kind(),
        ErrorKind::Input
    );
    let sq: IntPoly = "(u^2-2)^2".parse().unwrap();
    assert_eq!(RealAlg::new(&sq, &r(1), &r(2)).unwrap(), s2);
    assert!(s2 > q(7, 5) && s2 < q(3, 2));
    let x = QSqrt::try_new(r(0), r(1), r(2)).unwrap();
    assert_eq!(x.to_real_alg(), s2);
    assert!(QSqrt::try_new(r(0), r(1), r(-2)).is_err());
}

#[test]
fn budgets_are_answers() {
    let e: Ellipsoid = "x^2+y^2+z^2-1".parse().unwrap();
    let s: Polynomial = "x^5+y^5+z^5+x*y*z-1/3".parse().unwrap();
    let zero = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
    let rep = quadsect::decide_with(&e, &s, &TangentOptions::with_budget(zero.clone())).unwrap();
    assert_eq!(rep.verdict(), Verdict::Undecided);
    match rep.undecided() {
        Some(Undecided::Budget(x)) => assert_eq!(x.limit(), Limit::Time),
        other => panic!("expected a budget reason, got {other:?}"),
    }
    let a: Natural = "cylinder point=0,0,0 axis=1,0,0 radius2=1".parse().unwrap();
    let b: Natural = "cone vertex=0,1,0 axis=0,1,0 tan2=1".parse().unwrap();
    // a classification that runs out of budget is an answer too: class
    // `undecided`, with the limit that was hit
    let rep = quadsect::classify_with(&a, &b, &ClassifyOptions::with_budget(zero.clone())).unwrap();
    assert_eq!(rep.class(), Class::Undecided);
    assert_eq!(rep.exhausted().map(|x| x.limit()), Some(Limit::Time));
    let big: Polynomial = "(x^40-2)(x^41-3)".parse().unwrap();
    let err = quadsect::roots_with(&big, &zero).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::Budget);
    assert_eq!(err.exit_code(), 3);
}

#[cfg(feature = "serde")]
#[test]
fn serde_gives_the_cli_json() {
    let rep = quadsect::tangent::decide_str("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1").unwrap();
    let v = serde_json::to_value(&rep).unwrap();
    assert_eq!(v["verdict"], "separated");
    assert_eq!(v["min"]["interval"][0], "7/9");
    let n: Natural = serde_json::from_str(
        r#"{"kind":"cone","vertex":["0","0","0"],"axis":["1","0","0"],"sin2":"1/4"}"#,
    )
    .unwrap();
    assert_eq!(n, "cone vertex=0,0,0 axis=1,0,0 tan2=1/3".parse().unwrap());
    let line = quadsect::batch::answer_line(r#"{"id":7,"op":"roots","poly":"x^2-2"}"#);
    assert_eq!(line["id"], 7);
    assert_eq!(line["result"]["distinct_real"], 2);
}
