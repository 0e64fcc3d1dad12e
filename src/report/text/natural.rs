//! Human-readable text of `quadsect natural` (contract §4 JSON and the human summary).

use crate::natural::numbers::{EPoint, epoint_text, normalize_direction};
use crate::natural::result::{Class, Component, NaturalReport, Route};
use crate::natural::tangency::Section7;
use crate::number::fmt_q;

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
        Component::Curve {
            degree,
            singular,
            branches,
        } => {
            let mut s = format!("space curve of degree {}", degree);
            for p in singular {
                s.push_str(&format!(
                    "; singular point {} ({})",
                    pt(&p.point),
                    p.kind.as_str()
                ));
            }
            if !branches.is_empty() {
                let bounded = branches.iter().filter(|b| b.bounded).count();
                s.push_str(&format!(
                    "; {} ({} bounded, {} unbounded)",
                    plural(branches.len(), "real component", "real components"),
                    bounded,
                    branches.len() - bounded
                ));
                for b in branches {
                    let a = b.start.approx();
                    s.push_str(&format!(
                        "\n      {} branch through ≈ ({:.9}, {:.9}, {:.9})",
                        if b.bounded { "closed" } else { "open" },
                        a[0].0,
                        a[1].0,
                        a[2].0
                    ));
                }
            }
            s
        }
    }
}

/// `1 conic`, `2 conics`, `0 conics`.
fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// `quadsect natural` for people.
pub fn natural_human(r: &NaturalReport) -> String {
    if let Some(e) = &r.exhausted {
        return format!("class     {}\nreason    {e}\n", r.class.as_str());
    }
    let counts = if r.class == Class::SameSurface {
        "the two equations are proportional: every point of one is on the other".to_string()
    } else {
        format!(
            "{}, {}, {}",
            plural(r.conics(), "conic", "conics"),
            plural(r.lines(), "line", "lines"),
            plural(r.points(), "point", "points")
        )
    };
    let mut s = format!("class     {}  ({counts})\n", r.class.as_str());
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
    if r.components.is_empty() && r.class != Class::SameSurface && r.components_computed {
        s.push_str("no real intersection\n");
    }
    for (i, c) in r.components.iter().enumerate() {
        s.push_str(&format!("  {}. {}\n", i + 1, component_human(c)));
    }
    for n in &r.notes {
        s.push_str(&format!("note: {n}\n"));
    }
    match r.route {
        Some(Route::Fast) => s.push_str("route     fast (no components computed)\n"),
        Some(Route::Complete(why)) => s.push_str(&format!("route     complete ({why})\n")),
        None => {}
    }
    if let Some(f) = &r.referee {
        s.push_str(&referee_human(f));
    }
    s
}

/// The referee's lines of the human summary.
fn referee_human(f: &crate::natural::Referee) -> String {
    use crate::number::decimal_bound;
    let mut s = format!(
        "referee   lo {} (proved: every input within this relative size has the same answer)\n",
        decimal_bound(&f.lo, false)
    );
    if let Some(why) = f.lo_reason {
        s.push_str(&format!("          lo is 0: {why}\n"));
    }
    match (&f.hi, &f.nearby) {
        (Some(h), Some(n)) => {
            s.push_str(&format!(
                "          hi {} (witnessed: this input, that far, is {} — {} conic(s), {} line(s), {} point(s))\n",
                decimal_bound(h, true),
                n.counts.class.as_str(),
                n.counts.conics,
                n.counts.lines,
                n.counts.points
            ));
            s.push_str(&format!("          nearby A  {}\n", n.a));
            s.push_str(&format!("          nearby B  {}\n", n.b));
        }
        _ => s.push_str(&format!(
            "          hi none: {}\n",
            f.hi_reason.unwrap_or("no witness")
        )),
    }
    s
}

impl std::fmt::Display for NaturalReport {
    /// The human summary (as `quadsect natural` prints it).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&natural_human(self))
    }
}
