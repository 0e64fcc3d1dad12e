//! The complete classification of two natural quadrics (contract §4): class,
//! counts and exact components, with the part-1 deciders where they apply.
//!
//! Order of decisions:
//! 1. proportional equations → `same-surface`;
//! 2. two spheres; a sphere centred on an axis; two quadrics on one axis →
//!    circles ([`super::coaxial`]);
//! 3. coplanar distinct axes with a degenerate projection conic (Lemma 8.1)
//!    → the planar constructions of §4–§6 ([`super::planar`]);
//! 4. everything else (skew axes, coplanar axes with a non-degenerate
//!    projection conic — including §5.1 — and a sphere off the axis) → the
//!    exact topology of the intersection curve ([`super::topology`]): a
//!    genuine curve (with its acnodes), isolated tangency points (§7), a
//!    common ruling plus a twisted cubic, or nothing.

use super::coaxial::{center_on_axis, same_axis, sphere_on_axis, sphere_sphere};
use super::deciders::{AxesRelation, AxialPlane, pencil_has_planar_member, relation, thm8};
use super::planar::{parallelogram_heights, planar_components, skeletal_lines};
use super::result::{Class, Component, Counts, NaturalReport, PlanarDeciders, class_of};
use super::tangency::{Section7, section7};
use super::topology::classify_nonplanar;
use super::types::{Natural, parse_natural};
use crate::error::Error;
use crate::poly::QMPoly;
use crate::poly::mpoly::{MPoly, NVARS};

/// True when the two equations are proportional (the same surface).
pub fn same_surface(a: &Natural, b: &Natural) -> bool {
    a.equation().to_primitive_z().0 == b.equation().to_primitive_z().0
}

fn conic_string(f: &super::deciders::Conic2) -> String {
    // F(s, t) printed with x = s, y = t
    let mut terms = Vec::new();
    let two = crate::number::qi(2);
    let mono = |i: u32, j: u32| {
        let mut e = [0u32; NVARS];
        e[0] = i;
        e[1] = j;
        e
    };
    terms.push((mono(2, 0), f[0][0].clone()));
    terms.push((mono(1, 1), &f[0][1] * &two));
    terms.push((mono(0, 2), f[1][1].clone()));
    terms.push((mono(1, 0), &f[0][2] * &two));
    terms.push((mono(0, 1), &f[1][2] * &two));
    terms.push((mono(0, 0), f[2][2].clone()));
    let p: QMPoly = MPoly::from_terms(terms);
    p.to_string_canonical().replace('x', "s").replace('y', "t")
}

/// Classifies two natural quadrics under the default budget.
///
/// Cost: planar cases (coplanar axes, spheres, a common axis) take exact
/// operations on a few small polynomials (tens to hundreds of µs); skew
/// axes and other non-planar cases compute the topology of the
/// intersection curve (a zero-dimensional system of degree ≤ 16 and a
/// sweep), ≈ 0.5–3 ms on small integers.
///
/// ```
/// use quadsect::{Class, Natural, classify};
/// let a: Natural = "cone vertex=0,0,0 axis=1,0,0 tan2=1".parse().unwrap();
/// let b: Natural = "cone vertex=0,0,0 axis=0,1,0 tan2=3".parse().unwrap();
/// let r = classify(&a, &b).unwrap();
/// assert_eq!(r.class(), Class::Lines);
/// assert_eq!(r.thm8(), Some(true)); // a common vertex
/// ```
pub fn classify(a: &Natural, b: &Natural) -> Result<NaturalReport, Error> {
    super::predicates::classify_with(a, b, &super::predicates::ClassifyOptions::default())
}

/// The complete route: class, counts and exact components (no budget of
/// its own; [`super::predicates::classify_with`] runs it under one).
pub(crate) fn classify_complete(a: &Natural, b: &Natural) -> Result<NaturalReport, Error> {
    crate::budget::check_now();
    let axes = relation(a, b);
    let t8 = axes.as_ref().and_then(|r| thm8(a, b, r));
    let mut notes = Vec::new();
    let mut deciders = None;
    let mut sec7 = None;
    if same_surface(a, b) {
        return Ok(NaturalReport {
            a: a.clone(),
            b: b.clone(),
            class: Class::SameSurface,
            axes,
            thm8: t8,
            components: vec![],
            deciders: None,
            section7: None,
            method: "proportional equations",
            notes,
            counts: Counts::same_surface(),
            components_computed: true,
            route: None,
            exhausted: None,
            member_planes: Vec::new(),
            referee: None,
        });
    }
    let (components, method): (Vec<Component>, &'static str) = match (a, b) {
        (Natural::Sphere(s1), Natural::Sphere(s2)) => {
            (sphere_sphere(s1, s2), "sphere-sphere (radical plane)")
        }
        (Natural::Sphere(s), q) | (q, Natural::Sphere(s)) => {
            if center_on_axis(s, q) {
                (sphere_on_axis(s, q), "sphere centred on the axis (circles)")
            } else {
                let (c, n) = classify_nonplanar(a, b)?;
                notes.extend(n);
                (c, "intersection-curve topology")
            }
        }
        _ => {
            match axes.as_ref() {
                Some(AxesRelation::Coincident) => (same_axis(a, b), "common axis (circles)"),
                Some(AxesRelation::Intersecting(_)) | Some(AxesRelation::Parallel) => {
                    let h = AxialPlane::new(a, b)
                        .ok_or_else(|| Error::internal("coplanar axes without an axial plane"))?;
                    let pencil = pencil_has_planar_member(a, b);
                    let lemma = h.lemma81_planar();
                    if t8.is_some_and(|t| t != lemma) || pencil != lemma {
                        notes.push(format!(
                        "deciders disagree (thm8 {t8:?}, Lemma 8.1 {lemma}, pencil {pencil}) — please report"
                    ));
                    }
                    deciders = Some(PlanarDeciders {
                        thm8: t8,
                        lemma81: lemma,
                        discriminant: h.discriminant.clone(),
                        pencil,
                        x_point: h.x_point.as_ref().map(|(s, t)| h.point(s, t)),
                        heights_at_x: h.heights_at_x(),
                        projection: conic_string(&h.projection),
                        frame: [h.o.clone(), h.e1.clone(), h.e2.clone()],
                        skeletal: vec![
                            skeletal_lines(&h, &h.heights[0]),
                            skeletal_lines(&h, &h.heights[1]),
                        ],
                        parallelogram: match (a, b) {
                            (Natural::Cone(c1), Natural::Cone(c2))
                                if c1.vertex == c2.vertex && lemma =>
                            {
                                parallelogram_heights(&h, &c1.axis, &c1.t2)
                            }
                            _ => None,
                        },
                    });
                    if lemma {
                        (
                            planar_components(&h),
                            "axial plane: projection conic factors (Lemma 8.1)",
                        )
                    } else {
                        let (c, n) = classify_nonplanar(a, b)?;
                        notes.extend(n);
                        (
                            c,
                            "intersection-curve topology (projection conic does not factor)",
                        )
                    }
                }
                _ => {
                    let (c, n) = classify_nonplanar(a, b)?;
                    notes.extend(n);
                    let s7 = section7(a, b);
                    if !section7_agrees(&s7, &c) {
                        notes.push(format!("the §7 decider ({s7:?}) disagrees with the curve topology — please report"));
                    }
                    sec7 = Some(s7);
                    (c, "intersection-curve topology (skew axes)")
                }
            }
        }
    };
    let class = class_of(&components);
    let counts = Counts::of_components(&components);
    Ok(NaturalReport {
        a: a.clone(),
        b: b.clone(),
        class,
        axes,
        thm8: t8,
        components,
        deciders,
        section7: sec7,
        method,
        notes,
        counts,
        components_computed: true,
        route: None,
        exhausted: None,
        member_planes: Vec::new(),
        referee: None,
    })
}

/// Does the §7 verdict match the components found by the topology?
pub fn section7_agrees(s7: &Section7, comps: &[Component]) -> bool {
    let class = class_of(comps);
    match s7 {
        Section7::NotApplicable(_) => true,
        Section7::Disjoint => class == Class::Empty,
        Section7::Transversal => class == Class::Curve,
        Section7::Tangent(p) => {
            class == Class::Points
                && comps
                    .iter()
                    .filter(|c| matches!(c, Component::Point { .. }))
                    .count()
                    == p.len()
        }
    }
}

/// Parses two quadrics (short syntax, or JSON with the feature `serde`)
/// and classifies them.
///
/// ```
/// use quadsect::Class;
/// use quadsect::natural::classify_str;
/// let r = classify_str(
///     "cylinder point=0,0,0 axis=1,0,0 radius2=1",
///     "cylinder point=0,0,0 axis=0,1,0 radius2=1").unwrap();
/// assert_eq!(r.class(), Class::Conics);
/// assert_eq!((r.conics(), r.lines(), r.points()), (2, 0, 0));
/// ```
pub fn classify_str(a: &str, b: &str) -> Result<NaturalReport, Error> {
    let qa = parse_natural(a).map_err(|e| e.context("in the first quadric"))?;
    let qb = parse_natural(b).map_err(|e| e.context("in the second quadric"))?;
    classify(&qa, &qb)
}

/// Runs the reference route ([`classify_complete`]) beside an answer: its
/// part-1 deciders and §7 verdict are attached to the report, and its class,
/// counts and components are compared with the answer's (a disagreement is
/// a note asking for a report).  The cross-check of
/// [`super::ClassifyOptions::deciders`].
pub(crate) fn add_reference_deciders(r: &mut NaturalReport) -> Result<(), Error> {
    if r.class == Class::Undecided {
        return Ok(());
    }
    let reference = classify_complete(&r.a, &r.b)?;
    r.deciders = reference.deciders.clone();
    r.section7 = reference.section7.clone();
    if reference.counts != r.counts {
        r.notes.push(format!(
            "the reference route found {} ({}, {}, {}) — please report",
            reference.class.as_str(),
            reference.conics(),
            reference.lines(),
            reference.points()
        ));
    } else if r.components_computed
        && !super::result::same_components(&reference.components, &r.components)
    {
        r.notes
            .push("the reference route built other components — please report".into());
    }
    for n in &reference.notes {
        if n.contains("please report") {
            r.notes.push(format!("reference route: {n}"));
        }
    }
    Ok(())
}
