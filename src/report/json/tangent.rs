//! JSON of `quadsect tangent` (contract §3 JSON and the human summary).

use crate::number::{Q, QSqrt};
use crate::poly::ZPoly;
use crate::poly::mpoly::{L, MPoly, T, U};
use crate::report::upoly_string;
use crate::roots::RealAlg;
use crate::tangent::quadric::Branch;
use crate::tangent::{Analysis, TangentReport, Undecided, WitnessPoint};
use serde_json::{Value, json};

/// A real algebraic number as the contract's ALG object, its polynomial printed in
/// the variable `v`.
///
/// The interval printed is the one the 20 digits were read from: it
/// excludes 0 for a non-zero value (the sign shows).
pub fn alg_json_in(a: &RealAlg, v: usize) -> Value {
    let mut a = a.clone();
    let approx = a.approx_in_place(20);
    let (lo, hi) = a.interval();
    json!({
        "poly": upoly_string(&a.poly(), v),
        "interval": [crate::number::fmt_q(&lo), crate::number::fmt_q(&hi)],
        "approx": approx,
    })
}

/// Why a verdict is undecided: `{"kind": "budget"|"no-certificate",
/// "limit": "time"|"memory"|"size"|"cancelled"|null, "message"}`.
pub fn undecided_json(u: &Undecided) -> Value {
    match u {
        Undecided::Budget(e) => {
            json!({"kind": "budget", "limit": e.limit().as_str(), "message": e.to_string()})
        }
        Undecided::NoCertificate(why) => {
            json!({"kind": "no-certificate", "limit": null, "message": why})
        }
    }
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

/// The conics of critical points split off before the RUR.
fn conics_json(conics: &[crate::tangent::modular::CriticalConic]) -> Vec<Value> {
    conics.iter().map(|c| json!({
        "plane": format!("{} = 0", ["x", "y", "z"][c.var]),
        "value": crate::number::fmt_q(&c.value),
        "point": c.point.iter().map(qsqrt_json).collect::<Vec<_>>(),
        "argument": "the minors of ∇S × ∇E share a power of this variable as a factor, so they vanish on the plane: every point of E on it is critical and S is constant there (value, at point); generators are the minors divided by their common monomial, and the judging polynomial has the factor u − value",
    })).collect()
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

fn method_json(m: &Analysis) -> Value {
    match m {
        Analysis::Constant => json!({"method": "constant"}),
        Analysis::Undecided => json!({"method": "none"}),
        Analysis::Pencil(an) => json!({
            "method": "pencil-discriminant",
            "scale": an.scale.to_string(),
            "char_poly": upoly_string(&an.char_poly, L),
            "delta": upoly_string(&an.delta, L),
            "secular_poly": upoly_string(&an.secular, L),
            "test": "gcd(P, delta) = 1 and D(u) = disc_l(F - u delta) of degree 6 and square-free: every real root of D is S at a real critical point",
            "extreme_multipliers": an.extreme_multipliers.as_ref().map(|(a, b)| vec![alg_json_in(a, L), alg_json_in(b, L)]),
        }),
        Analysis::Lambda(an) => {
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
        Analysis::Separable(sa) => {
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
        Analysis::CriticalIdeal(an) => {
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
                "system": an.generators.iter().map(|g| g.to_string_canonical()).collect::<Vec<_>>(),
                "critical_points": an.rur.points,
                "with_multiplicity": an.rur.multiplicity_dim,
                "made_radical": an.rur.made_radical,
                "separating_form": an.rur.form.iter().map(crate::number::fmt_q).collect::<Vec<_>>(),
                "rur_poly": upoly_string(&an.rur.f, T),
                "rur_coordinates": coords,
                "rur_value": MPoly::from_univariate(&an.value_poly, T).to_string_canonical(),
                "real_critical_points": an.rur.real_roots.iter().map({
                    let mut w = AlgWriter::new(T);
                    move |a| w.json(a)
                }).collect::<Vec<_>>(),
                "critical_conics": conics_json(&an.conics),
                "resultant_elimination": elim,
            })
        }
        Analysis::ModularRur(an) => {
            let r = &an.rur;
            json!({
                "method": "critical-ideal-modular-rur",
                "critical_points": r.points(),
                "generators": an.generators.iter().map(|g| g.to_string_canonical()).collect::<Vec<_>>(),
                "separating_element": crate::report::separating_element(an),
                "rur_poly": upoly_string(&r.f, U),
                "rur_coordinates": r.coords.iter().map(|c| upoly_string(c, U)).collect::<Vec<_>>(),
                "rur_denominator": upoly_string(&r.denom, U),
                "real_critical_points": r.real_roots.len(),
                "critical_conics": conics_json(&an.conics),
                "value_of_s": if an.shift.is_some() {
                    json!([upoly_string(&ZPoly::from_q(&an.value_num).0, U), upoly_string(&ZPoly::from_q(&an.value_den).0, U)])
                } else {
                    Value::Null
                },
                "implied_minor": r.implied.map(|j| json!({
                    "minor": j,
                    "argument": format!(
                        "∇E · (∇S × ∇E) = 0, and gcd(rur_poly, the composition of ∂E/∂{} at the RUR) = 1, so ∂E/∂{} ≠ 0 at every critical point and minor {} (generators[{}]) vanishes where the other generators do: its check is left out",
                        ["x", "y", "z"][j - 1], ["x", "y", "z"][j - 1], j, j
                    ),
                })),
                "reconstruction_primes": r.primes,
                "soundness": if an.shift.is_none() {
                    "rur_poly D(u) is square-free and divides, in Z[u], the homogenised compositions of E, of the three minors of ∇S × ∇E and of S − u at (x, y, z) = rur_coordinates / rur_denominator: every root u of D is S at a critical point, distinct roots at distinct points"
                } else {
                    "rur_poly f(u) is square-free and divides, in Z[u], the homogenised compositions of E, of the three minors of ∇S × ∇E and of h − u (h = separating_element) at (x, y, z) = rur_coordinates / rur_denominator: every root u of f is h at a critical point, distinct roots at distinct points; S there is value_of_s[0](u) / value_of_s[1](u), so the critical values are the roots of the judging polynomial, the square-free part of Res_u(f(u), v·value_of_s[1](u) − value_of_s[0](u)) in v"
                },
                "completeness": {
                    "prime": r.count.prime,
                    "count_bound": r.count.bound,
                    "argument": if r.count.prime.is_some() {
                        "the leading forms of E and of the minors have no common zero at infinity modulo prime, so the number of complex critical points is at most count_bound (the standard monomials of a Gröbner basis modulo prime); count_bound = deg D, so the roots of D are all the critical values"
                    } else {
                        "the leading forms of E and of the minors share a zero at infinity modulo every prime tried (prime is null); count_bound is dim_Q Q[x,y,z]/I, the number of standard monomials of the reduced Gröbner basis over Q (grevlex) of E and the minors, an upper bound on the number of complex critical points; count_bound = deg D, so the roots of D are all the critical values"
                    },
                },
                "resultant_elimination": Value::Null,
            })
        }
        Analysis::Poisson(an) => {
            let r = &an.rur;
            json!({
                "method": "critical-ideal-poisson-rur",
                "critical_points": an.points(),
                "direction": an.direction,
                "square_system": an.generators.iter().map(|g| g.to_string_canonical()).collect::<Vec<_>>(),
                "leading_resultant": r.leading_resultant().to_string(),
                "zeros": r.w.degree().unwrap_or(0),
                "separating_form": r.form,
                "rur_poly": upoly_string(&r.w, T),
                "rur_coordinates": r.v.iter().map(|c| upoly_string(c, T)).collect::<Vec<_>>(),
                "rur_denominator": upoly_string(&r.wd, T),
                "extra_factor": upoly_string(&an.extras, T),
                "critical_factor": upoly_string(&an.critical, T),
                "real_critical_points": an.real_points.iter().map({
                    let mut w = AlgWriter::new(T);
                    move |a| w.json(a)
                }).collect::<Vec<_>>(),
                "primes": {"rur": r.primes, "judging": an.value_primes},
                "bound_bits": {"rur": r.bound_bits, "rur_sombra": r.sombra_bits, "judging": an.value_bound_bits},
                "rur_census": r.census.as_ref().map(|c| json!({
                    "leading_resultant_primes": c.rbar_primes,
                    "coordinate_bits": c.coordinate_bits,
                    "bound_bits": c.bits,
                    "boxes": c.zeros.boxes.iter().map(|b| json!({
                        "centre": b.centre.iter().map(|z| [z.re, z.im]).collect::<Vec<_>>(),
                        "half_width": b.half,
                    })).collect::<Vec<_>>(),
                })),
                "coordinate_mahler_bits": an.coordinate_mahler_bits,
                "judging_direct_bits": an.value_direct_bits,
                "squarefree_prime": r.squarefree_prime,
                "extras_prime": an.extras_prime,
                "value_enclosures": an.enclosures.iter().map(|(sign, (lo, hi))| json!({
                    "sign": sign,
                    "interval": [crate::number::fmt_q(lo), crate::number::fmt_q(hi)],
                })).collect::<Vec<_>>(),
                "soundness": "rur_poly w(t) = Res(t − ℓ, F) and the numerators V = −∂_ε Res(t − ℓ − ε·(x, y, z), F) are resultants of F = square_system (integer polynomials in its coefficients, by the Poisson formula ± leading_resultant · charpoly(ℓ) and the Kronecker numerators on Q[x, y, z]/F); their residues modulo primes where the quotient has dimension zeros = d1·d2·d3 are the residues computed there, and the CRT modulus exceeds twice bound_bits.rur, so they are exact; bound_bits.rur is Sombra's bound (bound_bits.rur_sombra) or, when rur_census is given, the a-posteriori bound |leading_resultant|·∏(1 + |ℓ(ξ)|)·Σ|v(ξ)| over all zeros ξ: each of rur_census.boxes (centre ± half_width in the real and imaginary part of each coordinate) is proved by the Krawczyk test in complex ball arithmetic to hold exactly one zero of F, they are pairwise disjoint, and there are zeros = d1·d2·d3 of them, the number of zeros with multiplicity (leading_resultant ≠ 0: none at infinity), so they hold all zeros and |ℓ|, |v| are bounded on them (leading_resultant exactly, by its own CRT over rur_census.leading_resultant_primes primes beyond Sombra's bound on it); w is square-free modulo squarefree_prime, so the zeros of F are exactly (x, y, z) = rur_coordinates(t) / w′(t) over the roots t of w, all simple",
                "extras": "a zero of F with m = ∇S × ∇E ≠ 0 has m ∥ n, hence n·∇E = n·∇S = 0; extra_factor = gcd(w, (n·∇E)(x(t), y(t), z(t))·w′(t)) holds those zeros, and n·m does not vanish at any of them (modulo extras_prime), so none is critical: the critical points are the roots of critical_factor = w / extra_factor",
                "judging": "judging_poly is the primitive part (scaled to S) of leading_resultant^d · ∏ (u − S′(ξ)) over the critical points ξ, an integer polynomial (Gauss's lemma on Res(u − S′, F)) whose residues are the characteristic polynomials of S′(ξ(t)) modulo critical_factor; the CRT modulus exceeds the bound 2^(N + bound_bits.judging)·√(zeros + 1) (Landau, Sombra), or, when judging_direct_bits is given and smaller, twice 2^judging_direct_bits = |leading_resultant|^d·2^N·‖S′‖₁^N·2^(d·Σ coordinate_mahler_bits) (N critical points, d = deg S′): |S′(ξ)| ≤ ‖S′‖₁·∏_v max(1, |v(ξ)|)^d, and ∏ over all zeros of max(1, |v(ξ)|) = M(P_v)/|leading_resultant| ≤ ‖P_v‖₂/|leading_resultant| ≤ 2^coordinate_mahler_bits[v] (Landau's inequality) for the eliminants P_v = Res(u − v, F), computed exactly beyond bound_bits.rur like w; with rur_census, judging_direct_bits = d·bits(leading_resultant) + b with ∏(1 + |S′(ξ)|) < 2^b over the boxes (S′ enclosed on each), which bounds every coefficient of leading_resultant^d·∏(u − S′(ξ))",
                "resultant_elimination": Value::Null,
            })
        }
        Analysis::NonReduced(an) => json!({
            "method": "square-free-part",
            "constant": crate::number::fmt_q(&an.constant),
            "factors": an.factors.iter().map(|(t, k)| json!({
                "factor": t.to_string_canonical(),
                "multiplicity": k,
            })).collect::<Vec<_>>(),
            "factor_reports": an.factor_reports.iter().map(|(i, r)| json!({
                "factor": i,
                "report": tangent_json(r),
            })).collect::<Vec<_>>(),
            "field": an.field.as_ref().map(|f| f.field.iter().map(|g| g.to_string_canonical()).collect::<Vec<_>>()),
            "critical_system": an.field.as_ref().map(|f| method_json(&f.analysis)),
            "argument": if an.factors.len() == 1 {
                "S = constant·T^k (T = factors[0], k its multiplicity, square-free): the critical points of S on E are the points of E on T = 0 (value 0; E meets T = 0 iff factor_reports[0] says intersect) and the critical points of T (value constant·v^k where T = v); E is connected, so S takes on E the values constant·v^k for v in [min T, max T]; judging_poly is the square-free part of Res_v(D_T(v), u − constant·v^k), times u when E meets T = 0"
            } else {
                "S = constant·∏ Tᵢ^kᵢ (factors, square-free, pairwise coprime): off S = 0, ∇S = constant·∏ Tᵢ^(kᵢ−1)·G with G = field = Σ kᵢ·(∏_(j≠i) Tⱼ)·∇Tᵢ, so the critical points of S on E are the points of E on the factors with kᵢ ≥ 2 (value 0; factor_reports decide whether E meets each) and the zeros of E = 0, G × ∇E = 0, solved by critical_system with the values of S (its minors are those of G × ∇E, not ∇S × ∇E); judging_poly is that system's, times u when E meets a repeated factor. When a factor is a multiple of E (its report is the only one, field is null), S = 0 on all of E"
            },
        }),
        Analysis::LevelSets(ls) => json!({
            "method": "level-sets",
            "levels": ls.levels.iter().map(|(q, ne)| json!({"level": crate::number::fmt_q(q), "real_points": ne})).collect::<Vec<_>>(),
            "linear_form": ls.form.iter().map(crate::number::fmt_q).collect::<Vec<_>>(),
        }),
    }
}

/// A value printed: (polynomial index, interval asked, interval printed,
/// digits).
type Printed = (usize, (Q, Q), (Q, Q), String);

/// [`crate::report::alg_json`] with the strings of the defining polynomials
/// cached: the critical values, min and max usually share D(u), whose
/// decimal digits are written once.
struct AlgWriter {
    /// The variable the polynomials are printed in.
    var: usize,
    cache: Vec<(ZPoly, String)>,
    /// The 20-digit approximations by (polynomial index, interval): min
    /// and max repeat critical values, each root is refined once; with the
    /// refined interval printed.
    approx: Vec<Printed>,
}

impl AlgWriter {
    fn new(var: usize) -> AlgWriter {
        AlgWriter {
            var,
            cache: Vec::new(),
            approx: Vec::new(),
        }
    }

    /// The index of `p`'s string in the cache (written on first use).
    fn index(&mut self, p: std::borrow::Cow<'_, ZPoly>) -> usize {
        match self.cache.iter().position(|(q, _)| *q == *p) {
            Some(k) => k,
            None => {
                let s = upoly_string(&p, self.var);
                self.cache.push((p.into_owned(), s));
                self.cache.len() - 1
            }
        }
    }

    /// `p` printed (D(u) is usually printed already, for the critical
    /// values).
    fn poly(&mut self, p: &ZPoly) -> String {
        let k = self.index(std::borrow::Cow::Borrowed(p));
        self.cache[k].1.clone()
    }

    fn json(&mut self, a: &RealAlg) -> Value {
        let k = self.index(std::borrow::Cow::Owned(a.poly()));
        let key = a.interval();
        let (iv, approx) = match self.approx.iter().find(|(j, b, _, _)| *j == k && *b == key) {
            Some((_, _, iv, s)) => (iv.clone(), s.clone()),
            None => {
                // the interval printed is the one the digits were read from
                // (off 0 for a non-zero value)
                let mut c = a.clone();
                let s = c.approx_in_place(20);
                let iv = c.interval();
                self.approx.push((k, key, iv.clone(), s.clone()));
                (iv, s)
            }
        };
        json!({
            "poly": self.cache[k].1,
            "interval": [crate::number::fmt_q(&iv.0), crate::number::fmt_q(&iv.1)],
            "approx": approx,
        })
    }
}

/// `quadsect tangent --json`.
pub fn tangent_json(r: &TangentReport) -> Value {
    let c = &r.certificate;
    let mut algs = AlgWriter::new(U);
    let mut cert = method_json(&c.method);
    if let Value::Object(m) = &mut cert {
        m.insert(
            "critical_values".into(),
            Value::Array(c.critical_values.iter().map(|v| algs.json(v)).collect()),
        );
        m.insert(
            "nonreal_point_values".into(),
            Value::Array(
                c.nonreal_point_values
                    .iter()
                    .map(|v| algs.json(v))
                    .collect(),
            ),
        );
        m.insert("witness_negative".into(), witness_json(&c.negative_witness));
        m.insert("witness_positive".into(), witness_json(&c.positive_witness));
        // side·(S − τE) positive definite in (x, y, z, 1): S ≠ 0 on E
        m.insert(
            "s_lemma".into(),
            c.s_lemma
                .as_ref()
                .map_or(Value::Null, |t| json!({"tau": crate::number::fmt_q(t)})),
        );
        m.insert("notes".into(), json!(c.notes));
    }
    let mut out = json!({
        "intersect": r.intersect,
        "touching": r.touching,
        "side": side_str(r.side),
        "containment": r.containment.map(|c| c.as_str()),
        "min": r.min.as_ref().map(|v| algs.json(v)),
        "max": r.max.as_ref().map(|v| algs.json(v)),
        // null: the caller asked for the verdict only and D(u) was skipped
        "judging_poly": if r.values_skipped() {
            Value::Null
        } else {
            json!(algs.poly(&r.judging_poly))
        },
        "certificate": cert,
        "verdict": r.verdict.as_str(),
    });
    // why an undecided answer is undecided: the budget that ran out, or
    // the step that could not produce a certificate
    if let (Some(reason), Value::Object(m)) = (&r.reason, &mut out) {
        m.insert("reason".into(), undecided_json(reason));
    }
    out
}
