//! JSON of `quadsect natural` (contract §4 JSON and the human summary).

use crate::geom::vec3::V3;
use crate::natural::Natural;
use crate::natural::exact::{EPoint, Exact, normalize_direction, normalize_plane};
use crate::natural::result::Plane;
use crate::natural::result::{Component, NaturalReport, PlanarDeciders, Route};
use crate::natural::tangency::Section7;
use crate::number::fmt_q;

use serde_json::{Value, json};

/// `[value, bound]`: the double nearest the exact value's enclosure and a
/// proven bound on its error (`|x − value| ≤ bound`).
fn f64_json(x: &Exact) -> Value {
    let (v, b) = x.to_f64_bounded();
    Value::from(vec![v, b])
}

fn f64_point(p: &EPoint) -> Value {
    Value::Array(p.iter().map(f64_json).collect())
}

/// The certified doubles of a component's numeric fields (the same fields
/// as printed exactly, `[value, bound]` each).
fn component_f64_json(c: &Component) -> Value {
    match c {
        Component::Conic {
            plane,
            center,
            vertex,
            axes2,
            axis_dirs,
            focal2,
            ..
        } => {
            let (n, o) = normalize_plane(plane);
            obj! {
                "plane" => obj! {"normal" => f64_point(&n), "offset" => f64_json(&o)},
                "center" => center.as_ref().map(f64_point),
                "vertex" => vertex.as_ref().map(f64_point),
                "semi_axes2" => axes2.iter().map(f64_json).collect::<Vec<_>>(),
                "axis_directions" => axis_dirs.iter().map(|d| f64_point(&normalize_direction(d))).collect::<Vec<_>>(),
                "focal_length2" => focal2.as_ref().map(f64_json),
            }
        }
        Component::Line {
            point, direction, ..
        } => obj! {"point" => f64_point(point), "direction" => f64_point(direction)},
        Component::Point { point, .. } => obj! {"point" => f64_point(point)},
        Component::Curve { singular, .. } => obj! {
            "singular_points" => singular.iter().map(|p| f64_point(&p.point)).collect::<Vec<_>>(),
        },
    }
}

fn component_json(c: &Component) -> Value {
    let mut v = component_exact_json(c);
    if let Value::Object(m) = &mut v {
        m.insert("f64".into(), component_f64_json(c));
    }
    v
}

fn component_exact_json(c: &Component) -> Value {
    match c {
        Component::Conic {
            plane,
            kind,
            center,
            vertex,
            axes2,
            axis_dirs,
            focal2,
            double,
        } => obj! {
            "type" => "conic",
            "conic" => kind.as_str(),
            "plane" => plane_json(plane),
            "center" => center.as_ref().map(epoint_json),
            "vertex" => vertex.as_ref().map(epoint_json),
            "semi_axes2" => axes2.iter().map(exact_json).collect::<Vec<_>>(),
            "axis_directions" => axis_dirs.iter().map(|d| epoint_json(&normalize_direction(d))).collect::<Vec<_>>(),
            "focal_length2" => focal2.as_ref().map(exact_json),
            "double" => *double,
        },
        Component::Line {
            point,
            direction,
            double,
        } => obj! {
            "type" => "line", "point" => epoint_json(point), "direction" => epoint_json(direction), "double" => *double,
        },
        Component::Point { point, kind } => obj! {
            "type" => "point", "point" => epoint_json(point), "kind" => kind.as_str(),
        },
        Component::Curve {
            degree,
            singular,
            branches,
        } => obj! {
            "type" => "curve",
            "degree" => *degree,
            "singular_points" => singular.iter().map(|p| obj! {"point" => epoint_json(&p.point), "kind" => p.kind.as_str(), "isolated" => p.is_isolated()}).collect::<Vec<_>>(),
            "real_components" => branches.len(),
            "branches" => branches.iter().map(branch_json).collect::<Vec<_>>(),
        },
    }
}

/// A real component of a curve: bounded or not, and a point on it — as
/// doubles with proven error bounds (`[value, bound]` per coordinate) and
/// exactly, as a root of the other quadric along a ruling of the cylinder
/// or cone (`point = ruling.point + t·ruling.direction`, `t` a root of
/// `a·t² + 2b·t + c`: `t = (−b + root·√(b² − ac))/a`, or `t` itself).
fn branch_json(b: &crate::natural::CurveBranch) -> Value {
    let p = &b.start;
    let (rp, rd) = p.ruling();
    let q = p.quadratic();
    let e = |x: &crate::number::QSqrt| exact_json(&Exact::Quad(x.clone()));
    obj! {
        "bounded" => b.bounded,
        "point" => p.approx().iter().map(|&(v, err)| Value::from(vec![v, err])).collect::<Vec<_>>(),
        "ruling" => obj! {"point" => rp.iter().map(e).collect::<Vec<_>>(), "direction" => rd.iter().map(e).collect::<Vec<_>>()},
        "along_ruling" => obj! {"a" => e(&q[0]), "b" => e(&q[1]), "c" => e(&q[2]), "root" => p.root(), "t" => p.parameter().map(e)},
    }
}

/// A plane with rational coefficients is scaled to primitive integers.
fn plane_json(p: &Plane) -> Value {
    let (n, o) = normalize_plane(p);
    obj! {"normal" => epoint_json(&n), "offset" => exact_json(&o)}
}

fn q3(v: &[crate::number::Q; 3]) -> Value {
    json!(v.iter().map(fmt_q).collect::<Vec<_>>())
}

fn deciders_json(d: &PlanarDeciders) -> Value {
    json!({
        "thm8": d.thm8,
        "lemma81_discriminant": fmt_q(&d.discriminant),
        "lemma81_factors": d.lemma81,
        "pencil_rank2_member": d.pencil,
        "projection_conic": d.projection,
        "frame": {"origin": q3(&d.frame[0]), "e1": q3(&d.frame[1]), "e2": q3(&d.frame[2])},
        "x_point": d.x_point.as_ref().map(q3),
        "heights2_at_x": d.heights_at_x.as_ref().map(|(a, b)| json!([fmt_q(a), fmt_q(b)])),
        "squared_heights_A_D": d.parallelogram.as_ref().map(|v| v.iter().map(exact_json).collect::<Vec<_>>()),
        "skeletal_lines": d.skeletal.iter().map(|ls| ls.iter().map(|(p, w)| json!({"point": epoint_json(p), "direction": epoint_json(w)})).collect::<Vec<_>>()).collect::<Vec<_>>(),
    })
}

fn section7_json(s: &Section7) -> Value {
    match s {
        Section7::NotApplicable(why) => json!({"applies": false, "reason": why}),
        Section7::Disjoint => json!({"applies": true, "verdict": "disjoint"}),
        Section7::Transversal => json!({"applies": true, "verdict": "transversal"}),
        Section7::Tangent(p) => json!({
            "applies": true,
            "verdict": "tangent",
            "points": p.iter().map(|x| epoint_json(&crate::natural::exact::epoint(x))).collect::<Vec<_>>(),
        }),
    }
}

/// `quadsect natural --json`.
///
/// For a request without components the fast route's answer has `class`,
/// `conics`, `lines`, `points`, `axes`, `thm8`, `method` and `route`
/// (`fast`); when the complete route had to answer, its whole report
/// follows with `route: "complete"` and the `fallback` reason.
pub fn natural_json(r: &NaturalReport) -> Value {
    if let Some(e) = &r.exhausted {
        return json!({
            "class": r.class.as_str(),
            "conics": null,
            "lines": null,
            "points": null,
            "axes": null,
            "thm8": null,
            "components": [],
            "method": r.method,
            "a": natural_input_json(&r.a),
            "b": natural_input_json(&r.b),
            "notes": r.notes,
            "reason": {"kind": "budget", "limit": e.limit().as_str(), "message": e.to_string()},
        });
    }
    match r.route {
        Some(Route::Fast) => {
            let mut m = class_and_counts(r);
            m.insert("method".into(), json!(r.method));
            m.insert("route".into(), json!("fast"));
            return Value::Object(m);
        }
        Some(Route::Complete(why)) => {
            let mut v = complete_json(r);
            if let Value::Object(m) = &mut v {
                m.insert("route".into(), json!("complete"));
                m.insert("fallback".into(), json!(why));
            }
            return v;
        }
        None => {}
    }
    complete_json(r)
}

/// The keys both routes start with: class, counts, axes, thm8.
fn class_and_counts(r: &NaturalReport) -> serde_json::Map<String, Value> {
    let Value::Object(m) = json!({
        "class": r.class.as_str(),
        "conics": r.conics(),
        "lines": r.lines(),
        "points": r.points(),
        "axes": r.axes.as_ref().map(|a| a.as_str()),
        "thm8": r.thm8,
    }) else {
        unreachable!("json! of an object literal")
    };
    m
}

fn complete_json(r: &NaturalReport) -> Value {
    let mut m = class_and_counts(r);
    let rest = obj! {
        "components" => r.components.iter().map(component_json).collect::<Vec<_>>(),
        "method" => r.method,
        "deciders" => r.deciders.as_ref().map(deciders_json),
        "section7" => r.section7.as_ref().map(section7_json),
        "a" => natural_input_json(&r.a),
        "b" => natural_input_json(&r.b),
        "notes" => r.notes.clone(),
    };
    if let Value::Object(rest) = rest {
        m.extend(rest);
    }
    Value::Object(m)
}

/// JSON: a string for a rational, `{"a","b","d","approx"}` for a
/// quadratic irrational, `{"poly","interval","approx"}` otherwise.
pub fn exact_json(x: &Exact) -> Value {
    match x {
        Exact::Quad(x) if x.is_rational() => Value::from(fmt_q(&x.a)),
        Exact::Quad(x) => {
            let x = x.normalized();
            obj! {"a" => fmt_q(&x.a), "b" => fmt_q(&x.b), "d" => fmt_q(&x.d), "approx" => x.approx(20)}
        }
        Exact::Alg(a) => super::kernel::alg_json(a),
    }
}

/// JSON of a point.
pub fn epoint_json(p: &EPoint) -> Value {
    Value::Array(p.iter().map(exact_json).collect())
}

/// The JSON form of contract §2 (numbers as exact strings).
pub fn natural_input_json(q: &Natural) -> Value {
    let v = |p: &V3| -> Value { json!(p.iter().map(fmt_q).collect::<Vec<_>>()) };
    match q {
        Natural::Sphere(s) => {
            json!({"kind": "sphere", "center": v(&s.center), "radius2": fmt_q(&s.r2)})
        }
        Natural::Cylinder(c) => {
            json!({"kind": "cylinder", "point": v(&c.point), "axis": v(&c.axis), "radius2": fmt_q(&c.r2)})
        }
        Natural::Cone(c) => {
            json!({"kind": "cone", "vertex": v(&c.vertex), "axis": v(&c.axis), "tan2": fmt_q(&c.t2)})
        }
    }
}
