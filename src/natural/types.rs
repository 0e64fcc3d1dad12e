//! Natural quadrics — spheres, circular cylinders, right circular (double)
//! cones — with validated constructors, their rational implicit equations
//! and 4×4 matrices, exact rigid motions, and the input syntaxes (JSON of
//! contract §2 and the short human form `cone vertex=0,0,0 axis=1,0,0 tan2=1/3`).

use crate::error::{Error, ErrorKind};
#[cfg(test)]
use crate::geom::vec3::scale;
use crate::geom::vec3::{V3, add, cross, dot, norm2, sub};
use crate::number::{NumberMode, Q, fmt_q, parse_rational_with};
use crate::poly::QMPoly;
use crate::poly::mpoly::{MPoly, X, Y, Z};
use num_traits::{One, Signed, Zero};
#[cfg(feature = "serde")]
use serde_json::Value;

/// A sphere `|P − O|² = r2` (equation `|P − O|² − r2`, negative inside).
/// Built only by [`Sphere::new`], which checks `r2 > 0`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Sphere {
    /// Centre O.
    pub(crate) center: V3,
    /// Squared radius, `> 0`.
    pub(crate) r2: Q,
}

/// A circular cylinder `|(P − Q) × a|² = r2·|a|²` (negative inside).
/// Built only by [`Cylinder::new`], which checks a non-zero axis and
/// `r2 > 0`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Cylinder {
    /// A point Q of the axis.
    pub(crate) point: V3,
    /// Axis direction (non-zero, any length).
    pub(crate) axis: V3,
    /// Squared radius, `> 0`.
    pub(crate) r2: Q,
}

/// A right circular double cone `|a|²|P − V|² = (1 + t2)((P − V)·a)²`,
/// half-angle α with `tan²α = t2 > 0`.  Built only by [`Cone::new`], which
/// checks a non-zero axis and `t2 > 0`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Cone {
    /// Vertex V.
    pub(crate) vertex: V3,
    /// Axis direction (non-zero).
    pub(crate) axis: V3,
    /// `tan²α > 0`.
    pub(crate) t2: Q,
}

/// Any natural quadric.  Its parts can only be built by their checked
/// constructors, so a `Natural` is always a valid surface.
///
/// ```
/// use quadsect::{Natural, Cylinder, Rational, ErrorKind};
/// let r = |n: i64| Rational::from_integer(n.into());
/// let c = Cylinder::new([r(0), r(0), r(0)], [r(1), r(0), r(0)], r(1)).unwrap();
/// let q = Natural::Cylinder(c);
/// assert_eq!(q.to_string(), "cylinder point=0,0,0 axis=1,0,0 radius2=1");
/// assert_eq!("cylinder point=0,0,0 axis=1,0,0 radius2=1".parse::<Natural>().unwrap(), q);
/// let bad = Cylinder::new([r(0), r(0), r(0)], [r(0), r(0), r(0)], r(-1)).unwrap_err();
/// assert_eq!(bad.kind(), ErrorKind::BadQuadric);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Natural {
    /// A sphere.
    Sphere(Sphere),
    /// A cylinder.
    Cylinder(Cylinder),
    /// A cone.
    Cone(Cone),
}

fn positive(name: &str, v: &Q) -> Result<(), Error> {
    if v.is_positive() {
        Ok(())
    } else {
        Err(Error::new(
            ErrorKind::BadQuadric,
            format!("{name} must be > 0, got {}", fmt_q(v)),
        ))
    }
}

fn nonzero_axis(a: &V3) -> Result<(), Error> {
    if a.iter().all(|c| c.is_zero()) {
        Err(Error::new(
            ErrorKind::BadQuadric,
            "the axis direction must be non-zero",
        ))
    } else {
        Ok(())
    }
}

impl Sphere {
    /// A sphere; `r2 > 0` is required.
    pub fn new(center: V3, r2: Q) -> Result<Sphere, Error> {
        positive("radius2", &r2)?;
        Ok(Sphere { center, r2 })
    }

    /// The centre.
    pub fn center(&self) -> &V3 {
        &self.center
    }

    /// The squared radius.
    pub fn radius2(&self) -> &Q {
        &self.r2
    }
}

impl Cylinder {
    /// A cylinder; non-zero axis and `r2 > 0` are required.
    pub fn new(point: V3, axis: V3, r2: Q) -> Result<Cylinder, Error> {
        nonzero_axis(&axis)?;
        positive("radius2", &r2)?;
        Ok(Cylinder { point, axis, r2 })
    }

    /// The point of the axis it was given with.
    pub fn point(&self) -> &V3 {
        &self.point
    }

    /// The axis direction (as given).
    pub fn axis(&self) -> &V3 {
        &self.axis
    }

    /// The squared radius.
    pub fn radius2(&self) -> &Q {
        &self.r2
    }
}

impl Cone {
    /// A cone; non-zero axis and `t2 > 0` are required.
    pub fn new(vertex: V3, axis: V3, t2: Q) -> Result<Cone, Error> {
        nonzero_axis(&axis)?;
        positive("tan2", &t2)?;
        Ok(Cone { vertex, axis, t2 })
    }

    /// The vertex.
    pub fn vertex(&self) -> &V3 {
        &self.vertex
    }

    /// The axis direction (as given).
    pub fn axis(&self) -> &V3 {
        &self.axis
    }

    /// `tan²α` of the half-angle α.
    pub fn tan2(&self) -> &Q {
        &self.t2
    }

    /// `sin²α = t2/(1 + t2)`.
    pub fn sin2(&self) -> Q {
        &self.t2 / (Q::one() + &self.t2)
    }
}

/// Converts the accepted angle parameters to `tan²α`, exactly:
/// `tan` (> 0) squared, `cos2` in (0, 1) to `(1 − cos2)/cos2`, `sin2` in
/// (0, 1) to `sin2/(1 − sin2)`.
pub fn tan2_from(kind: &str, v: &Q) -> Result<Q, Error> {
    let one = Q::one();
    match kind {
        "tan2" => Ok(v.clone()),
        "tan" => {
            if !v.is_positive() {
                return Err(Error::new(
                    ErrorKind::BadQuadric,
                    format!(
                        "tan must be > 0 (a half-angle in (0, 90°)), got {}",
                        fmt_q(v)
                    ),
                ));
            }
            Ok(v * v)
        }
        "cos2" => {
            if !(v.is_positive() && v < &one) {
                return Err(Error::new(
                    ErrorKind::BadQuadric,
                    format!("cos2 must lie in (0, 1), got {}", fmt_q(v)),
                ));
            }
            Ok((&one - v) / v)
        }
        "sin2" => {
            if !(v.is_positive() && v < &one) {
                return Err(Error::new(
                    ErrorKind::BadQuadric,
                    format!("sin2 must lie in (0, 1), got {}", fmt_q(v)),
                ));
            }
            Ok(v / (&one - v))
        }
        _ => Err(Error::internal(format!("unknown angle parameter {kind}"))),
    }
}

impl Natural {
    /// `sphere`, `cylinder` or `cone`.
    pub fn kind(&self) -> &'static str {
        match self {
            Natural::Sphere(_) => "sphere",
            Natural::Cylinder(_) => "cylinder",
            Natural::Cone(_) => "cone",
        }
    }

    /// True for cylinders and cones.
    pub fn is_axial(&self) -> bool {
        !matches!(self, Natural::Sphere(_))
    }

    /// The axis line (a point and a direction), for axial quadrics.
    pub fn axis_line(&self) -> Option<(V3, V3)> {
        match self {
            Natural::Sphere(_) => None,
            Natural::Cylinder(c) => Some((c.point.clone(), c.axis.clone())),
            Natural::Cone(c) => Some((c.vertex.clone(), c.axis.clone())),
        }
    }

    /// The implicit equation (negative inside), contract §2.
    pub fn equation(&self) -> QMPoly {
        let p: [QMPoly; 3] = [MPoly::var(X), MPoly::var(Y), MPoly::var(Z)];
        let diff = |c: &V3| -> [QMPoly; 3] {
            std::array::from_fn(|i| &p[i] - &MPoly::constant(c[i].clone()))
        };
        let lin = |u: &[QMPoly; 3], a: &V3| -> QMPoly {
            &(&u[0].scale(&a[0]) + &u[1].scale(&a[1])) + &u[2].scale(&a[2])
        };
        match self {
            Natural::Sphere(s) => {
                let d = diff(&s.center);
                &dot(&d, &d) - &MPoly::constant(s.r2.clone())
            }
            Natural::Cylinder(c) => {
                let d = diff(&c.point);
                let a2 = norm2(&c.axis);
                let da = lin(&d, &c.axis);
                // |d × a|² = |d|²|a|² − (d·a)²
                &(&dot(&d, &d).scale(&a2) - &(&da * &da)) - &MPoly::constant(&c.r2 * &a2)
            }
            Natural::Cone(c) => {
                let d = diff(&c.vertex);
                let a2 = norm2(&c.axis);
                let da = lin(&d, &c.axis);
                &dot(&d, &d).scale(&a2) - &(&da * &da).scale(&(Q::one() + &c.t2))
            }
        }
    }

    /// The symmetric 4×4 matrix `M` with `equation(P) = [P 1] M [P 1]ᵀ`.
    pub fn matrix(&self) -> [[Q; 4]; 4] {
        let f = crate::geom::QuadricForm::from_poly(&self.equation())
            .expect("natural quadric equations have degree 2");
        let mut m: [[Q; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| Q::zero()));
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] = f.a[i][j].clone();
            }
            m[i][3] = f.b[i].clone();
            m[3][i] = f.b[i].clone();
        }
        m[3][3] = f.c.clone();
        m
    }

    /// Parses the short syntax (or, with the feature `serde`, the JSON
    /// form) with the numbers read in `mode` (see [`crate::NumberMode`]).
    pub fn parse_in(text: &str, mode: NumberMode) -> Result<Natural, Error> {
        parse_natural_in(text, mode)
    }

    /// Applies the rigid motion `P ↦ R P + t`, checked: `R` must be an exact
    /// rotation (`R Rᵀ = I`, `det R = 1`; e.g. a Cayley rotation).
    pub fn moved_by(&self, r: &[[Q; 3]; 3], t: &V3) -> Result<Natural, Error> {
        if !crate::geom::is_rotation(r) {
            return Err(Error::new(
                ErrorKind::Input,
                "a rigid motion needs an exact rotation matrix (R Rᵀ = I, det R = 1)",
            ));
        }
        Ok(self.moved(r, t))
    }

    /// Applies the rigid motion `P ↦ R P + t` (R orthogonal, unchecked).
    pub(crate) fn moved(&self, r: &[[Q; 3]; 3], t: &V3) -> Natural {
        let rot = |v: &V3| -> V3 {
            std::array::from_fn(|i| {
                (0..3)
                    .map(|j| &r[i][j] * &v[j])
                    .fold(Q::zero(), |a, b| a + b)
            })
        };
        let pt = |v: &V3| add(&rot(v), t);
        match self {
            Natural::Sphere(s) => Natural::Sphere(Sphere {
                center: pt(&s.center),
                r2: s.r2.clone(),
            }),
            Natural::Cylinder(c) => Natural::Cylinder(Cylinder {
                point: pt(&c.point),
                axis: rot(&c.axis),
                r2: c.r2.clone(),
            }),
            Natural::Cone(c) => Natural::Cone(Cone {
                vertex: pt(&c.vertex),
                axis: rot(&c.axis),
                t2: c.t2.clone(),
            }),
        }
    }

    /// Uniform scaling `P ↦ k P` (k ≠ 0): radii² scale by k², angles stay.
    #[cfg(test)]
    pub(crate) fn scaled(&self, k: &Q) -> Natural {
        let sc = |v: &V3| scale(v, k);
        match self {
            Natural::Sphere(s) => Natural::Sphere(Sphere {
                center: sc(&s.center),
                r2: &s.r2 * k * k,
            }),
            Natural::Cylinder(c) => Natural::Cylinder(Cylinder {
                point: sc(&c.point),
                axis: c.axis.clone(),
                r2: &c.r2 * k * k,
            }),
            Natural::Cone(c) => Natural::Cone(Cone {
                vertex: sc(&c.vertex),
                axis: c.axis.clone(),
                t2: c.t2.clone(),
            }),
        }
    }

    /// The short human syntax.
    pub fn to_short(&self) -> String {
        let v = |p: &V3| p.iter().map(fmt_q).collect::<Vec<_>>().join(",");
        match self {
            Natural::Sphere(s) => {
                format!("sphere center={} radius2={}", v(&s.center), fmt_q(&s.r2))
            }
            Natural::Cylinder(c) => format!(
                "cylinder point={} axis={} radius2={}",
                v(&c.point),
                v(&c.axis),
                fmt_q(&c.r2)
            ),
            Natural::Cone(c) => format!(
                "cone vertex={} axis={} tan2={}",
                v(&c.vertex),
                v(&c.axis),
                fmt_q(&c.t2)
            ),
        }
    }
}

// ------------------------------------------------------------------ parsing

fn parse_vec(s: &str, what: &str, mode: NumberMode) -> Result<V3, Error> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(Error::new(
            ErrorKind::BadQuadric,
            format!("{what} needs three comma-separated numbers, got \"{s}\""),
        ));
    }
    let mut out: V3 = std::array::from_fn(|_| Q::zero());
    for (i, p) in parts.iter().enumerate() {
        out[i] = parse_rational_with(p, mode)
            .map_err(|e| Error::new(ErrorKind::BadQuadric, format!("{what}: {e} in \"{p}\"")))?;
    }
    Ok(out)
}

fn parse_num(s: &str, what: &str, mode: NumberMode) -> Result<Q, Error> {
    parse_rational_with(s, mode)
        .map_err(|e| Error::new(ErrorKind::BadQuadric, format!("{what}: {e} in \"{s}\"")))
}

/// Builds a quadric from named fields (shared by both syntaxes).
fn build(kind: &str, fields: &[(String, String)], mode: NumberMode) -> Result<Natural, Error> {
    let get = |k: &str| fields.iter().find(|(n, _)| n == k).map(|(_, v)| v.as_str());
    let allowed: &[&str] = match kind {
        "sphere" => &["center", "radius2"],
        "cylinder" => &["point", "axis", "radius2"],
        "cone" => &["vertex", "axis", "tan2", "tan", "cos2", "sin2"],
        _ => {
            return Err(Error::new(
                ErrorKind::BadQuadric,
                format!("unknown kind \"{kind}\" (expected sphere, cylinder or cone)"),
            ));
        }
    };
    for (n, _) in fields {
        if !allowed.contains(&n.as_str()) {
            return Err(Error::new(
                ErrorKind::BadQuadric,
                format!(
                    "unknown field \"{n}\" for a {kind} (expected {})",
                    allowed.join(", ")
                ),
            ));
        }
        if fields.iter().filter(|(m, _)| m == n).count() > 1 {
            return Err(Error::new(
                ErrorKind::BadQuadric,
                format!("field \"{n}\" given twice"),
            ));
        }
    }
    let need = |k: &str| -> Result<&str, Error> {
        get(k).ok_or_else(|| Error::new(ErrorKind::BadQuadric, format!("a {kind} needs \"{k}\"")))
    };
    match kind {
        "sphere" => Ok(Natural::Sphere(Sphere::new(
            parse_vec(need("center")?, "center", mode)?,
            parse_num(need("radius2")?, "radius2", mode)?,
        )?)),
        "cylinder" => Ok(Natural::Cylinder(Cylinder::new(
            parse_vec(need("point")?, "point", mode)?,
            parse_vec(need("axis")?, "axis", mode)?,
            parse_num(need("radius2")?, "radius2", mode)?,
        )?)),
        _ => {
            let angle: Vec<&str> = ["tan2", "tan", "cos2", "sin2"]
                .into_iter()
                .filter(|k| get(k).is_some())
                .collect();
            if angle.len() != 1 {
                return Err(Error::new(
                    ErrorKind::BadQuadric,
                    format!(
                        "a cone needs exactly one of tan2, tan, cos2, sin2 (got {})",
                        if angle.is_empty() {
                            "none".to_string()
                        } else {
                            angle.join(", ")
                        }
                    ),
                ));
            }
            let v = parse_num(get(angle[0]).unwrap_or(""), angle[0], mode)?;
            let t2 = tan2_from(angle[0], &v)?;
            Ok(Natural::Cone(Cone::new(
                parse_vec(need("vertex")?, "vertex", mode)?,
                parse_vec(need("axis")?, "axis", mode)?,
                t2,
            )?))
        }
    }
}

/// Parses the JSON object form of contract §2 (numbers as strings; JSON
/// integers are accepted too, floats are refused as inexact).
#[cfg(feature = "serde")]
pub fn from_json(v: &Value) -> Result<Natural, Error> {
    from_json_in(v, NumberMode::Exact)
}

/// [`from_json`] with the numbers read in the given mode (float mode: each
/// literal becomes its nearest double).
#[cfg(feature = "serde")]
pub fn from_json_in(v: &Value, mode: NumberMode) -> Result<Natural, Error> {
    let obj = v.as_object().ok_or_else(|| {
        Error::new(
            ErrorKind::BadQuadric,
            "a natural quadric must be a JSON object",
        )
    })?;
    let kind = obj
        .get("kind")
        .and_then(|k| k.as_str())
        .ok_or_else(|| Error::new(ErrorKind::BadQuadric, "missing string field \"kind\""))?;
    let num = |name: &str, x: &Value| -> Result<String, Error> {
        match x {
            Value::String(s) => Ok(s.clone()),
            Value::Number(n) if n.is_i64() || n.is_u64() => Ok(n.to_string()),
            Value::Number(_) => Err(Error::new(
                ErrorKind::BadQuadric,
                format!(
                    "field \"{name}\": write non-integers as exact strings (\"7/9\", \"0.1\"), not JSON floats"
                ),
            )),
            _ => Err(Error::new(
                ErrorKind::BadQuadric,
                format!("field \"{name}\" must be a number given as a string"),
            )),
        }
    };
    let mut fields = Vec::new();
    for (k, x) in obj {
        if k == "kind" {
            continue;
        }
        let s = match x {
            Value::Array(items) => {
                let parts: Result<Vec<String>, Error> = items.iter().map(|it| num(k, it)).collect();
                parts?.join(",")
            }
            other => num(k, other)?,
        };
        fields.push((k.clone(), s));
    }
    build(kind, &fields, mode)
}

/// Parses the short human syntax, e.g. `cone vertex=0,0,0 axis=1,0,0
/// tan2=1/3`, or a JSON object (when the text starts with `{`).
pub fn parse_natural(text: &str) -> Result<Natural, Error> {
    parse_natural_in(text, NumberMode::Exact)
}

/// [`parse_natural`] with the numbers read in the given mode: in
/// [`NumberMode::Float`] each literal is replaced by its nearest double,
/// so `axis=0.7071067811865476,…` is the double a program would use.
pub fn parse_natural_in(text: &str, mode: NumberMode) -> Result<Natural, Error> {
    let t = text.trim();
    if t.starts_with('{') {
        #[cfg(feature = "serde")]
        {
            let v: Value = serde_json::from_str(t)
                .map_err(|e| Error::new(ErrorKind::BadQuadric, format!("invalid JSON: {e}")))?;
            return from_json_in(&v, mode);
        }
        #[cfg(not(feature = "serde"))]
        return Err(Error::new(
            ErrorKind::BadQuadric,
            "the JSON form of a natural quadric needs the crate feature `serde`; use the short syntax (e.g. `sphere center=0,0,0 radius2=1`)",
        ));
    }
    let mut words = t.split_whitespace();
    let kind = words
        .next()
        .ok_or_else(|| Error::new(ErrorKind::BadQuadric, "empty quadric description"))?;
    let mut fields = Vec::new();
    for w in words {
        let (k, v) = w.split_once('=').ok_or_else(|| {
            Error::new(
                ErrorKind::BadQuadric,
                format!("expected name=value, got \"{w}\" (e.g. axis=1,0,0)"),
            )
        })?;
        fields.push((k.to_string(), v.to_string()));
    }
    build(kind, &fields, mode)
}

/// Squared distance from a point to a line (point `p`, direction `a`).
pub fn dist2_point_line(x: &V3, p: &V3, a: &V3) -> Q {
    let c = cross(&sub(x, p), a);
    norm2(&c) / norm2(a)
}

/// Signed axial coordinate `(x − p)·a / |a|²` of the projection of `x` on
/// the line `p + s a`.
pub fn axial_param(x: &V3, p: &V3, a: &V3) -> Q {
    dot(&sub(x, p), a) / norm2(a)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::qi;

    #[test]
    fn parse_forms_agree() {
        let a = parse_natural("cone vertex=0,0,0 axis=1,0,0 tan2=1/3").unwrap();
        let b = parse_natural(
            r#"{"kind":"cone","vertex":["0","0","0"],"axis":["1","0","0"],"sin2":"1/4"}"#,
        )
        .unwrap();
        assert_eq!(a, b);
        for bad in [
            "cone vertex=0,0,0 axis=1,0,0",
            "cone vertex=0,0,0 axis=1,0,0 tan2=1 tan=1",
            "cone vertex=0,0,0 axis=1,0,0 tan2=-1",
            "cone vertex=0,0,0 axis=1,0,0 cos2=1",
            "sphere center=0,0 radius2=1",
            "sphere center=0,0,0 radius2=0",
            "torus center=0,0,0",
            "sphere center=0,0,0 radius2=1 axis=1,0,0",
            r#"{"kind":"sphere","center":[0.5,0,0],"radius2":"1"}"#,
        ] {
            assert!(parse_natural(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn equations_vanish_on_the_surface() {
        let c = parse_natural("cone vertex=1,2,3 axis=0,0,2 tan2=1").unwrap();
        let e = c.equation();
        let mut pt: [Q; crate::poly::mpoly::NVARS] = std::array::from_fn(|_| Q::zero());
        pt[0] = qi(2);
        pt[1] = qi(2);
        pt[2] = qi(4); // V + (1, 0, 1): angle 45°
        assert_eq!(e.eval(&pt), Q::zero());
    }
}

impl std::str::FromStr for Natural {
    type Err = Error;
    /// The short syntax (`cone vertex=0,0,0 axis=1,0,0 tan2=1/3`) or, with
    /// the feature `serde`, the JSON object form.
    fn from_str(s: &str) -> Result<Natural, Error> {
        parse_natural(s)
    }
}

impl std::fmt::Display for Natural {
    /// The short syntax (parses back to the same quadric).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.to_short())
    }
}

#[cfg(test)]
mod doc_examples {
    //! The examples that were doc comments of crate-private items.

    #[test]
    fn doc_parse_natural() {
        use crate::natural::parse_natural;
        let c = parse_natural("cone vertex=0,0,0 axis=1,0,0 cos2=3/4").unwrap();
        assert_eq!(c.to_short(), "cone vertex=0,0,0 axis=1,0,0 tan2=1/3");
        assert!(parse_natural("cylinder point=0,0,0 axis=0,0,0 radius2=1").is_err());
    }
}

#[cfg(test)]
mod doc_examples_more {
    //! Examples that were doc comments of crate-private items.

    #[test]
    fn doc_parse_natural_in() {
        use crate::natural::types::parse_natural_in;
        use crate::number::{NumberMode, double_value};
        let c = parse_natural_in("sphere center=0.1,0,0 radius2=1", NumberMode::Float).unwrap();
        let crate::natural::Natural::Sphere(s) = c else {
            unreachable!()
        };
        assert_eq!(s.center[0], double_value(0.1).unwrap());
    }
}
