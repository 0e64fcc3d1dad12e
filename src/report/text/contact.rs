//! The human-readable text of an ellipsoid-contact answer.

use crate::contact::{Certificate, ContactReport};
use crate::number::fmt_q;
use std::fmt;

impl fmt::Display for ContactReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "contact: {} ({})",
            self.contact().as_str(),
            self.kind().as_str()
        )?;
        match self.certificate() {
            Certificate::Separated { lambda } => writeln!(
                f,
                "certificate: det(λA + B) > 0 at λ = {} (so λ·q_A + q_B > 0 everywhere)",
                fmt_q(lambda)
            ),
            Certificate::Touching { lambda, point } => writeln!(
                f,
                "certificate: touching point ({}, {}, {}), λ = {}",
                point[0].approx(20),
                point[1].approx(20),
                point[2].approx(20),
                lambda.approx(20)
            ),
            Certificate::Overlapping { point, .. } => writeln!(
                f,
                "certificate: a point inside both: ({}, {}, {})",
                fmt_q(&point[0]),
                fmt_q(&point[1]),
                fmt_q(&point[2])
            ),
            #[allow(unreachable_patterns)]
            _ => Ok(()),
        }
    }
}
