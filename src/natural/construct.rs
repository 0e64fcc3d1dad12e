//! Constructions: the components of an intersection built from the fast
//! route's decision ([`super::predicates::Case`]) — CGAL's split of predicates
//! and constructions.  The predicates have decided the class and counts
//! (from signs, mostly in floating-point balls); a construction computes in
//! exact integers only what that case needs, and never classifies again.

use super::predicates::Case;
use super::prepared::{Kind, Prepared};
use super::result::{Component, Plane};
use super::types::Natural;
use crate::error::Error;
use num_bigint::BigInt;

/// The note of a line and a twisted cubic (the reference route's words).
pub(crate) const TWISTED_CUBIC_NOTE: &str = "the surfaces share a ruling: the rest of the intersection is a twisted cubic (missing from the paper's Table 1)";

/// What a construction built: the components, remarks, and the real planes
/// of a pencil member `κ·P₁·P₂` when it found them (the certificate).
pub(crate) type Built = (Vec<Component>, Vec<String>, Vec<Plane>);

/// The components of the intersection of `a` and `b` in the decided
/// `case`, and remarks.
pub(crate) fn components(
    a: &Prepared,
    b: &Prepared,
    case: Case,
    conics: Option<&super::predicates::PlanarConics>,
) -> Result<Built, Error> {
    let (na, nb) = (a.natural(), b.natural());
    let mut planes = Vec::new();
    let comps = match case {
        Case::SameSurface | Case::Empty => vec![],
        Case::TwoSpheres => match (na, nb) {
            (Natural::Sphere(s1), Natural::Sphere(s2)) => super::coaxial::sphere_sphere(s1, s2),
            _ => return Err(Error::internal("two spheres expected")),
        },
        Case::SphereOnAxis => match (na, nb) {
            (Natural::Sphere(s), q) | (q, Natural::Sphere(s)) => {
                super::coaxial::sphere_on_axis(s, q)
            }
            _ => return Err(Error::internal("a sphere expected")),
        },
        Case::SameAxis => super::coaxial::same_axis(na, nb),
        Case::Planar { parallel } => {
            let (x, y) = (a.prep.tier::<BigInt>(), b.prep.tier::<BigInt>());
            if x.kind == Kind::Sphere || y.kind == Kind::Sphere {
                return Err(Error::internal("a planar case with a sphere"));
            }
            let (comps, member) = super::build_planar::planar_components(&x, &y, parallel, conics);
            planes = member;
            comps
        }
        Case::Smooth | Case::Nodal { .. } | Case::ConePoint { .. } | Case::PlanePair { .. } => {
            let (x, y) = (a.prep.tier::<BigInt>(), b.prep.tier::<BigInt>());
            super::build_pencil::pencil_components(&x, &y, case)?
        }
        Case::Rulings => {
            // a common ruling: both vertices lie on it (σ = 0 for either
            // quadric's rulings); the line and the points where the rest of
            // the curve crosses it from the rulings of P, the branches of
            // the rest by them too ([`super::curve::common_ruling`]); the
            // rarer shapes (two common lines, β = 0 tangent to Γ, a line of
            // singular points) from the exact algebra of the reference route
            let (x, y) = (a.prep.tier::<BigInt>(), b.prep.tier::<BigInt>());
            let (p, q) = super::build_pencil::ruling_choice(&x, &y);
            let rulings = super::curve::Rulings::new(p, q);
            let built = super::curve::common_ruling(p, q, &rulings);
            let (mut comps, mut notes) = match built {
                Some((point, direction, crossings)) => (
                    vec![
                        Component::Line {
                            point,
                            direction,
                            double: false,
                        },
                        Component::Curve {
                            degree: 3,
                            singular: crossings
                                .into_iter()
                                .map(|point| super::result::SingularPoint {
                                    point,
                                    kind: super::result::SingularKind::Crossing,
                                })
                                .collect(),
                            branches: vec![],
                        },
                    ],
                    vec![TWISTED_CUBIC_NOTE.to_string()],
                ),
                None => super::topology::classify_nonplanar(na, nb)?,
            };
            match super::build_pencil::branches_on(&rulings, p) {
                Ok((traced, _)) if !traced.is_empty() => {
                    for c in comps.iter_mut() {
                        if let Component::Curve { branches, .. } = c {
                            *branches = traced.clone();
                        }
                    }
                }
                Ok(_) => {
                    notes.push("the branches of the cubic were not traced (none found)".into())
                }
                Err(e) => notes.push(format!("the branches of the cubic were not traced ({e})")),
            }
            return Ok((
                comps.into_iter().map(small_directions).collect(),
                notes,
                planes,
            ));
        }
    };
    Ok((
        comps.into_iter().map(small_directions).collect(),
        Vec::new(),
        planes,
    ))
}

/// Directions of lines and conic axes scaled to their smallest form
/// ([`super::numbers::primitive_direction`]).
fn small_directions(mut c: Component) -> Component {
    use super::numbers::primitive_direction;
    match &mut c {
        Component::Line { direction, .. } => *direction = primitive_direction(direction),
        Component::Conic { axis_dirs, .. } => {
            for d in axis_dirs.iter_mut() {
                *d = primitive_direction(d);
            }
        }
        _ => {}
    }
    c
}
