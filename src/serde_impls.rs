//! `Serialize` / `Deserialize` (feature `serde`).
//!
//! Reports serialize to exactly the JSON of the CLI's `--json` (the field
//! names and key order documented in `docs/contract.md`); the CLI prints
//! them through these impls.  Inputs deserialize from their text forms: a
//! polynomial or an ellipsoid from a string in the input syntax, a natural
//! quadric from the JSON object form or the short syntax.

use crate::kernel::{ResultantReport, RootsReport};
use crate::natural::{Natural, NaturalReport};
use crate::poly::{IntPoly, Polynomial};
use crate::roots::RealAlg;
use crate::tangent::{Ellipsoid, TangentReport};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

macro_rules! serialize_via_json {
    ($t:ty, $f:path) => {
        impl Serialize for $t {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                $f(self).serialize(s)
            }
        }
    };
}

serialize_via_json!(TangentReport, crate::report::tangent_json);
serialize_via_json!(NaturalReport, crate::report::natural_json);
serialize_via_json!(RootsReport, crate::report::roots_json);
serialize_via_json!(ResultantReport, crate::report::resultant_json);
serialize_via_json!(RealAlg, crate::report::alg_json);
serialize_via_json!(Natural, crate::report::natural_input_json);

/// Serializes as its canonical text (which parses back).
macro_rules! serde_as_text {
    ($t:ty) => {
        impl Serialize for $t {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(&self.to_string())
            }
        }

        impl<'de> Deserialize<'de> for $t {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<$t, D::Error> {
                let text = String::deserialize(d)?;
                text.parse().map_err(D::Error::custom)
            }
        }
    };
}

serde_as_text!(Polynomial);
serde_as_text!(IntPoly);
serde_as_text!(Ellipsoid);

impl<'de> Deserialize<'de> for Natural {
    /// The JSON object form (`{"kind":"cone","vertex":["0","0","0"],…}`) or
    /// a string in the short syntax.
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Natural, D::Error> {
        let v = serde_json::Value::deserialize(d)?;
        match &v {
            serde_json::Value::String(s) => crate::natural::parse_natural(s),
            other => crate::natural::types::from_json(other),
        }
        .map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_round_trip_through_serde() {
        let p: Polynomial = "x^2 - 2/3*y".parse().unwrap();
        let j = serde_json::to_string(&p).unwrap();
        assert_eq!(j, "\"x^2 - 2/3*y\"");
        assert_eq!(serde_json::from_str::<Polynomial>(&j).unwrap(), p);
        let n: Natural = "cone vertex=0,0,0 axis=1,0,0 tan2=1/3".parse().unwrap();
        let j = serde_json::to_string(&n).unwrap();
        assert_eq!(
            j,
            r#"{"kind":"cone","vertex":["0","0","0"],"axis":["1","0","0"],"tan2":"1/3"}"#
        );
        assert_eq!(serde_json::from_str::<Natural>(&j).unwrap(), n);
        assert!(serde_json::from_str::<Natural>(r#""sphere center=0,0,0 radius2=-1""#).is_err());
        assert!(serde_json::from_str::<Ellipsoid>(r#""x^2+y^2-z^2-1""#).is_err());
    }

    #[test]
    fn reports_serialize_as_the_cli_json_in_documented_order() {
        let r = crate::tangent::decide_str("x^2+y^2+z^2-25", "(x-9)^2/9+y^2/4+z^2/16-1").unwrap();
        let j = serde_json::to_string(&r).unwrap();
        let keys = [
            "\"intersect\"",
            "\"touching\"",
            "\"side\"",
            "\"containment\"",
            "\"min\"",
            "\"max\"",
            "\"judging_poly\"",
            "\"certificate\"",
            "\"verdict\"",
        ];
        let pos: Vec<usize> = keys.iter().map(|k| j.find(k).unwrap()).collect();
        assert!(pos.windows(2).all(|w| w[0] < w[1]), "{j}");
        assert!(j.contains("\"verdict\":\"separated\""));
    }
}
