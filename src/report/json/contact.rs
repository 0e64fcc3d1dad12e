//! The JSON of an ellipsoid-contact answer (docs/contract.md, "Ellipsoid
//! contact").

use super::tangent::qsqrt_json;
use crate::contact::{Certificate, ContactReport, Evidence};
use crate::number::{Q, fmt_q};
use serde_json::{Value, json};

fn q3(x: &[Q; 3]) -> Value {
    Value::Array(x.iter().map(|v| Value::String(fmt_q(v))).collect())
}

fn evidence_json(e: &Evidence) -> Value {
    match e {
        Evidence::Inside { mu } => json!({
            "type": "definite",
            "mu": fmt_q(mu),
            "claim": "B − μ·A is definite (negative: A inside B; positive: B inside A)",
        }),
        Evidence::Semidefinite { mu, a_in_b, point } => json!({
            "type": "semidefinite",
            "mu": qsqrt_json(mu),
            "sign": if *a_in_b { "negative" } else { "positive" },
            "point": point.as_ref().map(|p| p.iter().map(qsqrt_json).collect::<Vec<_>>()),
            "claim": "B − μ·A is semidefinite (negative: A ⊆ B; positive: B ⊆ A) and point lies on both surfaces",
        }),
        Evidence::Cross { a_only, b_only } => json!({
            "type": "cross",
            "a_only": a_only.as_ref().map(q3),
            "b_only": b_only.as_ref().map(q3),
            "claim": "q_A(a_only) < 0 < q_B(a_only) and q_B(b_only) < 0 < q_A(b_only)",
        }),
        Evidence::Identical { mu } => json!({
            "type": "identical",
            "mu": fmt_q(mu),
            "claim": "B = μ·A",
        }),
        #[allow(unreachable_patterns)]
        _ => Value::Null,
    }
}

/// `{"contact", "kind", "route", "certificate"}`.
pub fn contact_json(r: &ContactReport) -> Value {
    let cert = match r.certificate() {
        Certificate::Separated { lambda } => json!({
            "type": "separating-pencil",
            "lambda": fmt_q(lambda),
            "claim": "λ > 0 and det(λ·A + B) > 0, so min(λ·q_A + q_B) > 0",
        }),
        Certificate::Touching { lambda, point } => json!({
            "type": "touching-point",
            "lambda": qsqrt_json(lambda),
            "point": point.iter().map(qsqrt_json).collect::<Vec<_>>(),
            "claim": "λ > 0, q_A(point) = q_B(point) = 0 and λ·∇q_A + ∇q_B = 0 at point",
        }),
        Certificate::Overlapping { point, evidence } => json!({
            "type": "common-interior-point",
            "point": q3(point),
            "approx": point.iter().map(|v| crate::number::approx_decimal(v, 17)).collect::<Vec<_>>(),
            "kind_evidence": evidence.as_ref().map(evidence_json),
            "claim": "q_A(point) < 0 and q_B(point) < 0",
        }),
        #[allow(unreachable_patterns)]
        _ => Value::Null,
    };
    json!({
        "contact": r.contact().as_str(),
        "kind": r.kind().as_str(),
        "route": r.route(),
        "certificate": cert,
    })
}
