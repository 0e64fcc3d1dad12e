//! Formatting of `quadsect tangent` (SPEC §3 JSON and the human summary).

use crate::number::QSqrt;
use crate::poly::ZPoly;
use crate::poly::mpoly::{L, MPoly, T, U};
use crate::roots::RealAlg;
use crate::tangent::quadric::Branch;
use crate::tangent::{Method, TangentReport, WitnessPoint};
use serde_json::{Value, json};

/// A univariate integer polynomial printed in the variable with index `v`.
pub fn upoly_string(p: &ZPoly, v: usize) -> String {
    MPoly::from_univariate(&p.to_q(), v).to_string_canonical()
}

/// A real algebraic number as SPEC's ALG object, its polynomial printed in
/// the variable `v`.
pub fn alg_json_in(a: &RealAlg, v: usize) -> Value {
    let (lo, hi) = a.interval();
    json!({
        "poly": upoly_string(&a.poly(), v),
        "interval": [crate::number::fmt_q(&lo), crate::number::fmt_q(&hi)],
        "approx": a.approx(20),
    })
}

/// An element of Q(√d) as `{"a", "b", "d", "approx"}`.
pub fn qsqrt_json(x: &QSqrt) -> Value {
    json!({
        "a": crate::number::fmt_q(&x.a),
        "b": crate::number::fmt_q(&x.b),
        "d": crate::number::fmt_q(&x.d),
        "approx": x.approx(20),
    })
}

fn witness_json(w: &Option<WitnessPoint>) -> Value {
    match w {
        None => Value::Null,
        Some(w) => json!({
            "point": w.coords.iter().map(qsqrt_json).collect::<Vec<_>>(),
            "value": qsqrt_json(&w.value),
            "sign": w.sign,
        }),
    }
}

fn side_str(s: Option<i32>) -> Value {
    match s {
        Some(1) => json!("+"),
        Some(-1) => json!("-"),
        _ => Value::Null,
    }
}

fn method_json(m: &Method) -> Value {
    match m {
        Method::Constant => json!({"method": "constant"}),
        Method::Pencil(an) => json!({
            "method": "pencil-discriminant",
            "scale": an.scale.to_string(),
            "char_poly": upoly_string(&an.char_poly, L),
            "delta": upoly_string(&an.delta, L),
            "secular_poly": upoly_string(&an.secular, L),
            "test": "gcd(P, delta) = 1 and D(u) = disc_l(F - u delta) of degree 6 and square-free: every real root of D is S at a real critical point",
            "extreme_multipliers": an.extreme_multipliers.as_ref().map(|(a, b)| vec![alg_json_in(a, L), alg_json_in(b, L)]),
        }),
        Method::Lambda(an) => {
            let mults: Vec<Value> = an
                .critical
                .iter()
                .map(|c| {
                    let branch = match &c.branch {
                        Branch::Generic => json!({"kind": "generic"}),
                        Branch::Singular { dim, single_point } => {
                            json!({"kind": "singular", "solution_dim": dim, "single_point": single_point})
                        }
                    };
                    json!({
                        "lambda": alg_json_in(&c.lambda, L),
                        "value": crate::report::alg_json(&c.value),
                        "real_points": c.real,
                        "branch": branch,
                    })
                })
                .collect();
            json!({
                "method": "lambda-parametrisation",
                "delta": upoly_string(&ZPoly::from_q(&an.delta).0, L),
                "secular_poly": upoly_string(&ZPoly::from_q(&an.secular).0, L),
                "secular_generic": upoly_string(&ZPoly::from_q(&an.secular_generic).0, L),
                "multipliers": mults,
            })
        }
        Method::Separable(sa) => {
            let names = ["x", "y", "z"];
            let branches: Vec<Value> = sa
                .branches
                .iter()
                .map(|b| {
                    json!({
                        "lambda": b.lambda.as_ref().map(crate::number::fmt_q),
                        "free": b.free.iter().map(|&j| names[j]).collect::<Vec<_>>(),
                        "coordinate_poly": upoly_string(&b.coordinate_poly, sa.general),
                        "value_map": MPoly::from_univariate(&b.value_map, sa.general).to_string_canonical(),
                        "value_poly": upoly_string(&b.value_poly, U),
                        "real_points": b.real_points.iter().map(|(x, v)| json!({
                            "coordinate": alg_json_in(x, sa.general),
                            "value": crate::report::alg_json(v),
                        })).collect::<Vec<_>>(),
                        "roots_with_nonreal_points": b.nonreal_roots,
                        "curves": b.curves,
                    })
                })
                .collect();
            json!({
                "method": "separable-branches",
                "general_coordinate": names[sa.general],
                "kappa": sa.kappa.iter().map(|k| k.as_ref().map(crate::number::fmt_q)).collect::<Vec<_>>(),
                "rho": MPoly::from_univariate(&sa.rho, sa.general).to_string_canonical(),
                "branches": branches,
            })
        }
        Method::CriticalIdeal(an) => {
            let elim = an.elimination.as_ref().map(|e| {
                json!({
                    "order_l_x_y_z": upoly_string(&e.first, U),
                    "order_l_z_y_x": upoly_string(&e.second, U),
                    "gcd": upoly_string(&e.gcd, U),
                    "branches_with_solutions": e.branches,
                })
            });
            let coords: Vec<String> = an
                .rur
                .coords
                .iter()
                .map(|c| MPoly::from_univariate(c, T).to_string_canonical())
                .collect();
            json!({
                "method": "critical-ideal-rur",
                "critical_points": an.rur.points,
                "with_multiplicity": an.rur.multiplicity_dim,
                "made_radical": an.rur.made_radical,
                "separating_form": an.rur.form.iter().map(crate::number::fmt_q).collect::<Vec<_>>(),
                "rur_poly": upoly_string(&an.rur.f, T),
                "rur_coordinates": coords,
                "rur_value": MPoly::from_univariate(&an.value_poly, T).to_string_canonical(),
                "real_critical_points": an.rur.real_roots.iter().map(|a| alg_json_in(a, T)).collect::<Vec<_>>(),
                "resultant_elimination": elim,
            })
        }
        Method::ModularRur(an) => {
            let r = &an.rur;
            json!({
                "method": "critical-ideal-modular-rur",
                "critical_points": r.points(),
                "separating_element": "S",
                "rur_poly": upoly_string(&r.f, U),
                "rur_coordinates": r.coords.iter().map(|c| upoly_string(c, U)).collect::<Vec<_>>(),
                "rur_denominator": upoly_string(&r.denom, U),
                "real_critical_points": r.real_roots.len(),
                "reconstruction_primes": r.primes,
                "soundness": "rur_poly D(u) is square-free and divides, in Z[u], the homogenised compositions of E, of the three minors of ∇S × ∇E and of S − u at (x, y, z) = rur_coordinates / rur_denominator: every root u of D is S at a critical point, distinct roots at distinct points",
                "completeness": {
                    "prime": r.count.prime,
                    "count_bound": r.count.bound,
                    "argument": "the leading forms of E and of the minors have no common zero at infinity modulo prime, so the number of complex critical points is at most count_bound (the standard monomials of a Gröbner basis modulo prime); count_bound = deg D, so the roots of D are all the critical values",
                },
                "resultant_elimination": Value::Null,
            })
        }
        Method::LevelSets(ls) => json!({
            "method": "level-sets",
            "levels": ls.levels.iter().map(|(q, ne)| json!({"level": crate::number::fmt_q(q), "real_points": ne})).collect::<Vec<_>>(),
            "linear_form": ls.form.iter().map(crate::number::fmt_q).collect::<Vec<_>>(),
        }),
    }
}

/// `quadsect tangent --json`.
pub fn tangent_json(r: &TangentReport) -> Value {
    let c = &r.certificate;
    let mut cert = method_json(&c.method);
    if let Value::Object(m) = &mut cert {
        m.insert(
            "critical_values".into(),
            Value::Array(
                c.critical_values
                    .iter()
                    .map(crate::report::alg_json)
                    .collect(),
            ),
        );
        m.insert(
            "nonreal_point_values".into(),
            Value::Array(
                c.nonreal_point_values
                    .iter()
                    .map(crate::report::alg_json)
                    .collect(),
            ),
        );
        m.insert("witness_negative".into(), witness_json(&c.negative_witness));
        m.insert("witness_positive".into(), witness_json(&c.positive_witness));
        m.insert("notes".into(), json!(c.notes));
        if let Some(reason) = &r.reason {
            m.insert("reason".into(), json!(reason));
        }
    }
    json!({
        "intersect": r.intersect,
        "touching": r.touching,
        "side": side_str(r.side),
        "containment": r.containment.map(|c| c.as_str()),
        "min": r.min.as_ref().map(crate::report::alg_json),
        "max": r.max.as_ref().map(crate::report::alg_json),
        "judging_poly": upoly_string(&r.judging_poly, U),
        "certificate": cert,
        "verdict": r.verdict.as_str(),
    })
}

fn alg_human(a: &RealAlg) -> String {
    match a.as_rational() {
        Some(q) => format!("{}  (≈ {})", crate::number::fmt_q(q), a.approx(20)),
        None => {
            let (lo, hi) = a.interval();
            format!(
                "≈ {}  (root of {} in ({}, {}))",
                a.approx(20),
                upoly_string(&a.poly(), U),
                crate::number::fmt_q(&lo),
                crate::number::fmt_q(&hi)
            )
        }
    }
}

fn point_human(w: &WitnessPoint) -> String {
    let c: Vec<String> = w.coords.iter().map(|x| x.to_string()).collect();
    format!(
        "({})  S = {} ≈ {}",
        c.join(", "),
        w.value,
        w.value.approx(12)
    )
}

/// `quadsect tangent` for people: the verdict in one line, then min/max with
/// approximations, D(u) and the certificate.
pub fn tangent_human(r: &TangentReport) -> String {
    let mut s = String::new();
    let side = match r.side {
        Some(1) => ", S > 0 on E (E lies on the positive side of S)".to_string(),
        Some(-1) => ", S < 0 on E (E lies on the negative side of S)".to_string(),
        _ => String::new(),
    };
    let cont = r
        .containment
        .map(|c| format!(", {}", c.as_str()))
        .unwrap_or_default();
    s.push_str(&format!(
        "verdict   {}{}{}\n",
        r.verdict.as_str(),
        side,
        cont
    ));
    if let Some(reason) = &r.reason {
        s.push_str(&format!("reason    {reason}\n"));
    }
    if let Some(m) = &r.min {
        s.push_str(&format!("min S|E   {}\n", alg_human(m)));
    }
    if let Some(m) = &r.max {
        s.push_str(&format!("max S|E   {}\n", alg_human(m)));
    }
    s.push_str(&format!("D(u)      {}\n", upoly_string(&r.judging_poly, U)));
    let c = &r.certificate;
    s.push_str("certificate\n");
    let method = match &c.method {
        Method::Constant => "S is constant".to_string(),
        Method::Pencil(an) => format!(
            "pencil: F(λ) = det(Ŝ − λÊ) = {}, δ(λ) = {}, P = F'δ − Fδ' = {} (Ŝ, Ê: {}·S, {}·E); gcd(P, δ) = 1 and D = disc_λ(F − uδ) square-free of degree 6, so every real root of D is a critical value at a real point",
            upoly_string(&an.char_poly, L),
            upoly_string(&an.delta, L),
            upoly_string(&an.secular, L),
            an.scale,
            an.scale
        ),
        Method::Lambda(an) => format!(
            "λ-parametrisation: secular polynomial P(λ) = {} (degree {}), δ(λ) = {}",
            upoly_string(&ZPoly::from_q(&an.secular).0, L),
            an.secular.degree().unwrap_or(0),
            upoly_string(&ZPoly::from_q(&an.delta).0, L)
        ),
        Method::Separable(sa) => {
            let names = ["x", "y", "z"];
            let g = names[sa.general];
            let parts: Vec<String> = sa
                .branches
                .iter()
                .map(|b| {
                    let head = match &b.lambda {
                        None => "others at the centre".to_string(),
                        Some(k) => {
                            let f: Vec<&str> = b.free.iter().map(|&j| names[j]).collect();
                            format!("λ = {}, {} free", crate::number::fmt_q(k), f.join(", "))
                        }
                    };
                    format!(
                        "[{head}: {} = 0, values {} = 0, {} real]",
                        upoly_string(&b.coordinate_poly, sa.general),
                        upoly_string(&b.value_poly, U),
                        b.real_points.len()
                    )
                })
                .collect();
            format!(
                "separable S, general coordinate {g}: {} branches, D(u) = product of Res_{g}(branch, u − S) {}",
                sa.branches.len(),
                parts.join(" ")
            )
        }
        Method::CriticalIdeal(an) => format!(
            "critical ideal E = 0, ∇S×∇E = 0: {} critical points ({} with multiplicity), RUR in t = {}·x + {}·y + {}·z, {} real",
            an.rur.points,
            an.rur.multiplicity_dim,
            an.rur.form[0],
            an.rur.form[1],
            an.rur.form[2],
            an.rur.real_roots.len()
        ),
        Method::ModularRur(an) => format!(
            "critical ideal E = 0, ∇S×∇E = 0, multi-modular: {} critical points, RUR in u = S (its polynomial is D(u); {} primes, verified exactly), {} real; complete: at most {} critical points by the count modulo {}",
            an.rur.points(),
            an.rur.primes,
            an.rur.real_roots.len(),
            an.rur.count.bound,
            an.rur.count.prime
        ),
        Method::LevelSets(ls) => format!(
            "curves of critical points: {} level curves tested",
            ls.levels.len()
        ),
    };
    s.push_str(&format!("  method               {method}\n"));
    let vals: Vec<String> = c.critical_values.iter().map(|v| v.approx(12)).collect();
    s.push_str(&format!("  real critical values {}\n", vals.join(", ")));
    if !c.nonreal_point_values.is_empty() {
        let v: Vec<String> = c
            .nonreal_point_values
            .iter()
            .map(|v| v.approx(12))
            .collect();
        s.push_str(&format!(
            "  roots of D(u) at non-real critical points (not attained): {}\n",
            v.join(", ")
        ));
    }
    if let Some(w) = &c.negative_witness {
        s.push_str(&format!("  point of E with S < 0  {}\n", point_human(w)));
    }
    if let Some(w) = &c.positive_witness {
        s.push_str(&format!("  point of E with S > 0  {}\n", point_human(w)));
    }
    if let Method::CriticalIdeal(an) = &c.method
        && let Some(e) = &an.elimination
    {
        s.push_str(&format!(
            "  resultant elimination (gcd of two orders) {}\n",
            upoly_string(&e.gcd, U)
        ));
    }
    for n in &c.notes {
        s.push_str(&format!("  note: {n}\n"));
    }
    s
}
