//! Human-readable text of `quadsect tangent` (contract §3 JSON and the human summary).

use crate::poly::ZPoly;
use crate::poly::mpoly::{L, MPoly, U};
use crate::roots::RealAlg;
use crate::tangent::{Analysis, TangentReport, WitnessPoint};

/// A univariate integer polynomial printed in the variable with index `v`.
pub fn upoly_string(p: &ZPoly, v: usize) -> String {
    MPoly::from_univariate(p, v).to_string_canonical()
}

fn alg_human(a: &RealAlg) -> String {
    match a.as_rational() {
        Some(q) => format!("{}  (≈ {})", crate::number::fmt_q(q), a.approx(20)),
        None => {
            let mut a = a.clone();
            let approx = a.approx_in_place(20);
            let (lo, hi) = a.interval();
            format!(
                "≈ {}  (root of {} in ({}, {}))",
                approx,
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
    if r.verdict == crate::tangent::Verdict::Undecided {
        return s;
    }
    if let Some(m) = &r.min {
        s.push_str(&format!("min S|E   {}\n", alg_human(m)));
    }
    if let Some(m) = &r.max {
        s.push_str(&format!("max S|E   {}\n", alg_human(m)));
    }
    if r.values_skipped() {
        s.push_str("D(u)      not computed (verdict only)\n");
    } else {
        s.push_str(&format!("D(u)      {}\n", upoly_string(&r.judging_poly, U)));
    }
    let c = &r.certificate;
    s.push_str("certificate\n");
    let method = method_human(&c.method);
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
    if let Analysis::CriticalIdeal(an) = &c.method
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

/// The computation behind the critical values, in one line.
fn method_human(m: &Analysis) -> String {
    match m {
        Analysis::Constant => "S is constant".to_string(),
        Analysis::Undecided => "none".to_string(),
        Analysis::Pencil(an) => format!(
            "pencil: F(λ) = det(Ŝ − λÊ) = {}, δ(λ) = {}, P = F'δ − Fδ' = {} (Ŝ, Ê: {}·S, {}·E); gcd(P, δ) = 1 and D = disc_λ(F − uδ) square-free of degree 6, so every real root of D is a critical value at a real point",
            upoly_string(&an.char_poly, L),
            upoly_string(&an.delta, L),
            upoly_string(&an.secular, L),
            an.scale,
            an.scale
        ),
        Analysis::Lambda(an) => format!(
            "λ-parametrisation: secular polynomial P(λ) = {} (degree {}), δ(λ) = {}",
            upoly_string(&ZPoly::from_q(&an.secular).0, L),
            an.secular.degree().unwrap_or(0),
            upoly_string(&ZPoly::from_q(&an.delta).0, L)
        ),
        Analysis::Separable(sa) => {
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
        Analysis::CriticalIdeal(an) => format!(
            "critical ideal E = 0, ∇S×∇E = 0: {} critical points ({} with multiplicity), RUR in t = {}·x + {}·y + {}·z, {} real",
            an.rur.points,
            an.rur.multiplicity_dim,
            an.rur.form[0],
            an.rur.form[1],
            an.rur.form[2],
            an.rur.real_roots.len()
        ),
        Analysis::ModularRur(an) => format!(
            "critical ideal E = 0, ∇S×∇E = 0, multi-modular: {} critical points, RUR in u = {} ({}; {} primes, verified exactly), {} real; complete: at most {} critical points by {}",
            an.rur.points(),
            crate::report::separating_element(an),
            if an.shift.is_none() {
                "its polynomial is D(u)"
            } else {
                "S alone takes equal values at distinct points; D(u) from the values of S"
            },
            an.rur.primes,
            an.rur.real_roots.len(),
            an.rur.count.bound,
            match an.rur.count.prime {
                Some(p) => format!("the count modulo {p}"),
                None => "the Gröbner basis over Q (zeros at infinity modulo every prime tried)"
                    .to_string(),
            }
        ) + &an
            .conics
            .iter()
            .map(|c| {
                format!(
                    "; plus the conic E ∩ {{{} = 0}}, all critical (a power of {} divides the minors), where S = {}",
                    ["x", "y", "z"][c.var],
                    ["x", "y", "z"][c.var],
                    crate::number::fmt_q(&c.value)
                )
            })
            .collect::<String>(),
        Analysis::Poisson(an) => format!(
            "critical points as zeros of the square system E = 0, a·m = b·m = 0 (m = ∇S×∇E, a, b ⊥ n = ({}, {}, {})) with no zeros at infinity: {} zeros, {} of them extra (n·∇E = n·∇S = 0, none critical), {} critical points, {} real; {}",
            an.direction[0],
            an.direction[1],
            an.direction[2],
            an.rur.w.degree().unwrap_or(0),
            an.extras.degree().unwrap_or(0),
            an.points(),
            an.real_points.len(),
            {
                let rur = format!(
                    "RUR in t = {}·x + {}·y + {}·z",
                    an.rur.form[0], an.rur.form[1], an.rur.form[2]
                );
                let rur_bound = match &an.rur.census {
                    Some(c) => format!(
                        "{} bits (a-posteriori: all {} complex zeros in certified boxes; Sombra's was {})",
                        c.bits,
                        c.zeros.boxes.len(),
                        an.rur.sombra_bits
                    ),
                    None => format!("{} bits (Sombra)", an.rur.bound_bits),
                };
                if an.judging.is_some() {
                    let judging = match (an.value_direct_bits, &an.rur.census) {
                        (Some(d), Some(_)) => format!(
                            "{rur_bound} and {d} bits (S on the boxes; Sombra's was {})",
                            an.value_bound_bits
                        ),
                        (Some(d), None) => format!(
                            "{rur_bound} and {} bits (Sombra; replaced by {d} bits from the Mahler measures of the coordinate eliminants)",
                            an.value_bound_bits
                        ),
                        (None, _) => format!("{rur_bound} and {} bits (Sombra)", an.value_bound_bits),
                    };
                    format!(
                        "{rur} and D(u) are resultants, computed modulo {} and {} primes beyond bounds of {judging} (exact, no verification needed)",
                        an.rur.primes, an.value_primes
                    )
                } else {
                    format!(
                        "{rur}, a resultant computed modulo {} primes beyond a bound of {rur_bound} (exact, no verification needed); signs of S proven on enclosures of the real critical points (value_enclosures)",
                        an.rur.primes
                    )
                }
            }
        ),
        Analysis::NonReduced(an) => {
            let inner = match (&an.field, an.factors.len()) {
                (Some(f), _) => format!(
                    "the critical points off S = 0 from E = 0, G × ∇E = 0 with G = ({}, {}, {}), by {}",
                    f.field[0].to_string_canonical(),
                    f.field[1].to_string_canonical(),
                    f.field[2].to_string_canonical(),
                    method_human(&f.analysis)
                ),
                (None, 1) => match an.factor_reports.first() {
                    Some((_, r)) => format!(
                        "the factor on E by {}",
                        method_human(&r.certificate.method)
                    ),
                    None => String::new(),
                },
                (None, _) => "a factor is a multiple of E: S = 0 on all of E".to_string(),
            };
            format!("square-free part: S = {}; {inner}", an.product())
        }
        Analysis::LevelSets(ls) => format!(
            "curves of critical points: {} level curves tested",
            ls.levels.len()
        ),
    }
}

impl std::fmt::Display for TangentReport {
    /// The human summary (as `quadsect tangent` prints it).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&tangent_human(self))
    }
}
