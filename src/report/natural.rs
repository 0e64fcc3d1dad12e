//! Formatting of `quadsect natural` (SPEC §4 JSON and the human summary).

use crate::natural::exact::{EPoint, Exact, epoint_json, epoint_text, normalize_direction};
use crate::natural::result::Plane;
use crate::natural::result::{Component, NaturalReport, PlanarDeciders};
use crate::natural::tangency::Section7;
use crate::number::fmt_q;
use serde_json::{Value, json};

fn component_json(c: &Component) -> Value {
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
        } => json!({
            "type": "conic",
            "conic": kind.as_str(),
            "plane": plane_json(plane),
            "center": center.as_ref().map(epoint_json),
            "vertex": vertex.as_ref().map(epoint_json),
            "semi_axes2": axes2.iter().map(|a| a.json()).collect::<Vec<_>>(),
            "axis_directions": axis_dirs.iter().map(|d| epoint_json(&normalize_direction(d))).collect::<Vec<_>>(),
            "focal_length2": focal2.as_ref().map(|f| f.json()),
            "double": double,
        }),
        Component::Line {
            point,
            direction,
            double,
        } => json!({
            "type": "line", "point": epoint_json(point), "direction": epoint_json(direction), "double": double,
        }),
        Component::Point { point, kind } => json!({
            "type": "point", "point": epoint_json(point), "kind": kind.as_str(),
        }),
        Component::Curve { degree, singular } => json!({
            "type": "curve",
            "degree": degree,
            "singular_points": singular.iter().map(|(p, iso)| json!({"point": epoint_json(p), "isolated": iso})).collect::<Vec<_>>(),
        }),
    }
}

/// A plane with rational coefficients is scaled to primitive integers.
fn plane_json(p: &Plane) -> Value {
    let (n, o) = normalize_plane(p);
    json!({"normal": epoint_json(&n), "offset": o.json()})
}

fn normalize_plane(p: &Plane) -> (EPoint, Exact) {
    let mut all = p.normal.to_vec();
    all.push(p.offset.clone());
    let rat: Option<Vec<crate::number::Q>> = all
        .iter()
        .map(|c| match c {
            Exact::Quad(x) if x.is_rational() => Some(x.a.clone()),
            _ => None,
        })
        .collect();
    let Some(rat) = rat else {
        return (p.normal.clone(), p.offset.clone());
    };
    let as_point: EPoint = std::array::from_fn(|i| Exact::rational(rat[i].clone()));
    let n = normalize_direction(&as_point);
    // scale factor k with n = k·normal, applied to the offset too
    let idx = (0..3)
        .find(|&i| !num_traits::Zero::is_zero(&rat[i]))
        .unwrap_or(0);
    let k = match &n[idx] {
        Exact::Quad(x) => &x.a / &rat[idx],
        _ => crate::number::Q::from_integer(1.into()),
    };
    (n, Exact::rational(&rat[3] * &k))
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
        "squared_heights_A_D": d.parallelogram.as_ref().map(|v| v.iter().map(|x| x.json()).collect::<Vec<_>>()),
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
            "a": r.a.to_json(),
            "b": r.b.to_json(),
            "notes": r.notes,
            "reason": crate::report::budget_reason_json(e),
        });
    }
    json!({
        "class": r.class.as_str(),
        "conics": r.conics(),
        "lines": r.lines(),
        "points": r.points(),
        "axes": r.axes.as_ref().map(|a| a.as_str()),
        "thm8": r.thm8,
        "components": r.components.iter().map(component_json).collect::<Vec<_>>(),
        "method": r.method,
        "deciders": r.deciders.as_ref().map(deciders_json),
        "section7": r.section7.as_ref().map(section7_json),
        "a": r.a.to_json(),
        "b": r.b.to_json(),
        "notes": r.notes,
    })
}

fn pt(p: &EPoint) -> String {
    epoint_text(p)
}

fn component_human(c: &Component) -> String {
    match c {
        Component::Conic {
            plane,
            kind,
            center,
            vertex,
            axes2,
            focal2,
            double,
            ..
        } => {
            let mut s = format!(
                "{}{} in the plane {}·P = {}",
                kind.as_str(),
                if *double {
                    " (double: the surfaces touch along it)"
                } else {
                    ""
                },
                pt(&plane.normal),
                plane.offset.text()
            );
            if let Some(c) = center {
                s.push_str(&format!(", centre {}", pt(c)));
            }
            if let Some(v) = vertex {
                s.push_str(&format!(", vertex {}", pt(v)));
            }
            if !axes2.is_empty() {
                let a: Vec<String> = axes2
                    .iter()
                    .map(|x| format!("{} ≈ {}", x.text(), x.approx(8)))
                    .collect();
                s.push_str(&format!(", semi-axes² {}", a.join(" and ")));
            }
            if let Some(f) = focal2 {
                s.push_str(&format!(", focal length² {}", f.text()));
            }
            s
        }
        Component::Line {
            point,
            direction,
            double,
        } => format!(
            "{}line through {} with direction {}",
            if *double { "double " } else { "" },
            pt(point),
            pt(&normalize_direction(direction))
        ),
        Component::Point { point, kind } => {
            format!("isolated point ({}) {}", kind.as_str(), pt(point))
        }
        Component::Curve { degree, singular } => {
            let mut s = format!("space curve of degree {}", degree);
            for (p, iso) in singular {
                s.push_str(&format!(
                    "; singular point {} ({})",
                    pt(p),
                    if *iso { "isolated" } else { "branches cross" }
                ));
            }
            s
        }
    }
}

/// `quadsect natural` for people.
pub fn natural_human(r: &NaturalReport) -> String {
    if let Some(e) = &r.exhausted {
        return format!("class     {}\nreason    {e}\n", r.class.as_str());
    }
    let mut s = format!(
        "class     {}  ({} conics, {} lines, {} points)\n",
        r.class.as_str(),
        r.conics(),
        r.lines(),
        r.points()
    );
    s.push_str(&format!(
        "axes      {}\nthm8      {}\nmethod    {}\n",
        r.axes
            .as_ref()
            .map(|a| a.as_str())
            .unwrap_or("— (a sphere)"),
        match r.thm8 {
            Some(true) => "true (common inscribed sphere / equal angles)",
            Some(false) => "false",
            None => "— (does not apply)",
        },
        r.method
    ));
    if let Some(d) = &r.deciders {
        s.push_str(&format!(
            "Lemma 8.1 F(s,t) = {}, discriminant {}; pencil member of rank ≤ 2: {}\n",
            d.projection,
            fmt_q(&d.discriminant),
            if d.pencil { "yes" } else { "no" }
        ));
        if let Some(p) = &d.parallelogram {
            let v: Vec<String> = p
                .iter()
                .map(|x| format!("{} ≈ {}", x.text(), x.approx(8)))
                .collect();
            s.push_str(&format!(
                "§6 parallelogram: squared heights at A and D {}\n",
                v.join(", ")
            ));
        }
        if let (Some(x), Some((h1, h2))) = (&d.x_point, &d.heights_at_x) {
            s.push_str(&format!(
                "X = ({}, {}, {}), squared heights {} and {}\n",
                fmt_q(&x[0]),
                fmt_q(&x[1]),
                fmt_q(&x[2]),
                fmt_q(h1),
                fmt_q(h2)
            ));
        }
    }
    if let Some(s7) = &r.section7 {
        let v = match s7 {
            Section7::NotApplicable(why) => format!("does not apply ({why})"),
            Section7::Disjoint => "disjoint (case 1)".into(),
            Section7::Transversal => "transversal".into(),
            Section7::Tangent(p) => format!("tangent at {} point(s)", p.len()),
        };
        s.push_str(&format!("§7        {v}\n"));
    }
    if r.components.is_empty() {
        s.push_str("no real intersection\n");
    }
    for (i, c) in r.components.iter().enumerate() {
        s.push_str(&format!("  {}. {}\n", i + 1, component_human(c)));
    }
    for n in &r.notes {
        s.push_str(&format!("note: {n}\n"));
    }
    s
}
