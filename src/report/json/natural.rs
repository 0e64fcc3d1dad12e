//! JSON of `quadsect natural` (contract §4 JSON and the human summary).

use crate::geom::vec3::V3;
use crate::natural::Natural;
use crate::natural::numbers::{EPoint, Exact, normalize_axis_direction, normalize_plane};
use crate::natural::referee::Referee;
use crate::natural::result::{Component, NaturalReport, PlanarDeciders, Plane, Route};
use crate::natural::tangency::Section7;
use crate::number::decimal_bound;
use crate::number::fmt_q;

use super::write::{Json, Obj, W, arr, into_string, obj_w, to_value, wobj};
use crate::number::QSqrt;
use serde_json::Value;

/// `[value, bound]`: the double nearest the exact value's enclosure and a
/// proven bound on its error (`|x − value| ≤ bound`).
fn f64_w(x: &Exact) -> (f64, f64) {
    x.to_f64_bounded()
}

fn f64_point(p: &EPoint) -> [(f64, f64); 3] {
    [f64_w(&p[0]), f64_w(&p[1]), f64_w(&p[2])]
}

/// One component: its exact fields, then `f64` with the certified doubles
/// of the same numeric fields (`[value, bound]` each).  A plane and axis
/// directions are normalized once for both.
fn write_component(c: &Component, out: &mut Vec<u8>) {
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
        } => {
            let (normal, offset) = normalize_plane(plane);
            let c = ConicNumbers {
                normal: &normal,
                offset: &offset,
                center: center.as_ref(),
                vertex: vertex.as_ref(),
                axes2,
                dirs: &axis_dirs
                    .iter()
                    .map(|d| normalize_axis_direction(d, *kind))
                    .collect::<Vec<_>>(),
                focal2: focal2.as_ref(),
            };
            let mut obj = Obj::new(out);
            obj.field("type", "conic").field("conic", kind.as_str());
            c.write(&mut obj, true);
            obj.field("double", *double).field(
                "f64",
                W(|o: &mut Vec<u8>| {
                    let mut f = Obj::new(o);
                    c.write(&mut f, false);
                    f.end()
                }),
            );
            obj.end()
        }
        Component::Line {
            point,
            direction,
            double,
        } => wobj!(out;
            "type" => "line", "point" => epoint_w(point), "direction" => epoint_w(direction), "double" => *double,
            "f64" => obj_w! {"point" => f64_point(point), "direction" => f64_point(direction)},
        ),
        Component::Point { point, kind } => wobj!(out;
            "type" => "point", "point" => epoint_w(point), "kind" => kind.as_str(),
            "f64" => obj_w! {"point" => f64_point(point)},
        ),
        Component::Curve {
            degree,
            singular,
            branches,
        } => wobj!(out;
            "type" => "curve",
            "degree" => *degree,
            "singular_points" => arr(singular.iter().map(|p| obj_w! {"point" => epoint_w(&p.point), "kind" => p.kind.as_str(), "isolated" => p.is_isolated()})),
            "real_components" => branches.len(),
            "branches" => arr(branches.iter().map(branch_w)),
            "f64" => obj_w! {"singular_points" => arr(singular.iter().map(|p| f64_point(&p.point)))},
        ),
    }
}

/// The numeric fields of a conic (plane normalized, axis directions
/// normalized), written once exactly and once as certified doubles.
struct ConicNumbers<'a> {
    normal: &'a EPoint,
    offset: &'a Exact,
    center: Option<&'a EPoint>,
    vertex: Option<&'a EPoint>,
    axes2: &'a [Exact],
    dirs: &'a [EPoint],
    focal2: Option<&'a Exact>,
}

impl ConicNumbers<'_> {
    fn write(&self, obj: &mut Obj, exact: bool) {
        obj.field("plane", obj_w! {"normal" => point_in(self.normal, exact), "offset" => number_in(self.offset, exact)})
            .field("center", self.center.map(|p| point_in(p, exact)))
            .field("vertex", self.vertex.map(|p| point_in(p, exact)))
            .field("semi_axes2", arr(self.axes2.iter().map(|x| number_in(x, exact))))
            .field("axis_directions", arr(self.dirs.iter().map(|p| point_in(p, exact))))
            .field("focal_length2", self.focal2.map(|x| number_in(x, exact)));
    }
}

/// A number exactly or as a certified double `[value, bound]`.
fn number_in(x: &Exact, exact: bool) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        if exact {
            exact_w(x).write(out)
        } else {
            f64_w(x).write(out)
        }
    })
}

/// A point exactly or as certified doubles.
fn point_in(p: &EPoint, exact: bool) -> impl Json + '_ {
    arr(p.iter().map(move |x| number_in(x, exact)))
}

/// A real component of a curve: bounded or not, and a point on it — as
/// doubles with proven error bounds (`[value, bound]` per coordinate) and
/// exactly, as a root of the other quadric along a ruling of the cylinder
/// or cone (`point = ruling.point + t·ruling.direction`, `t` a root of
/// `a·t² + 2b·t + c`: `t = (−b + root·√(b² − ac))/a`, or `t` itself).
fn branch_w(b: &crate::natural::CurveBranch) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        let p = &b.start;
        let (rp, rd) = p.ruling();
        let q = p.quadratic();
        wobj!(out;
            "bounded" => b.bounded,
            "point" => p.approx(),
            "ruling" => obj_w! {"point" => arr(rp.iter().map(qsqrt_w)), "direction" => arr(rd.iter().map(qsqrt_w))},
            "along_ruling" => obj_w! {"a" => qsqrt_w(&q[0]), "b" => qsqrt_w(&q[1]), "c" => qsqrt_w(&q[2]), "root" => p.root(), "t" => p.parameter().map(qsqrt_w)},
        )
    })
}

fn deciders_w(d: &PlanarDeciders) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        wobj! {out;
            "thm8" => d.thm8,
            "lemma81_discriminant" => fmt_q(&d.discriminant),
            "lemma81_factors" => d.lemma81,
            "pencil_rank2_member" => d.pencil,
            "projection_conic" => d.projection.as_str(),
            "frame" => obj_w! {"origin" => v3(&d.frame[0]), "e1" => v3(&d.frame[1]), "e2" => v3(&d.frame[2])},
            "x_point" => d.x_point.as_ref().map(v3),
            "heights2_at_x" => d.heights_at_x.as_ref().map(|(a, b)| [fmt_q(a), fmt_q(b)]),
            "squared_heights_A_D" => d.parallelogram.as_ref().map(|v| arr(v.iter().map(exact_w))),
            "skeletal_lines" => arr(d.skeletal.iter().map(|ls| arr(ls.iter().map(|(p, w)| W(move |o: &mut Vec<u8>| wobj!(o; "point" => epoint_w(p), "direction" => epoint_w(w))))))),
        }
    })
}

fn section7_w(s: &Section7) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| match s {
        Section7::NotApplicable(why) => wobj!(out; "applies" => false, "reason" => *why),
        Section7::Disjoint => wobj!(out; "applies" => true, "verdict" => "disjoint"),
        Section7::Transversal => wobj!(out; "applies" => true, "verdict" => "transversal"),
        Section7::Tangent(p) => wobj!(out;
            "applies" => true,
            "verdict" => "tangent",
            "points" => arr(p.iter().map(qpoint_w)),
        ),
    })
}

/// `quadsect natural --json`.
///
/// For a request without components the fast route's answer has `class`,
/// `conics`, `lines`, `points`, `axes`, `thm8`, `method` and `route`
/// (`fast`); when the complete route had to answer, its whole report
/// follows with `route: "complete"` and the `fallback` reason.
pub fn natural_json(r: &NaturalReport) -> Value {
    to_value(&natural_bytes(r))
}

impl NaturalReport {
    /// The JSON of `quadsect natural --json` as compact text (what
    /// `serde_json::to_string` of the report gives), written straight into
    /// text without a `serde_json::Value` tree.
    ///
    /// ```
    /// let a: quadsect::Natural = "sphere center=0,0,0 radius2=4".parse().unwrap();
    /// let b: quadsect::Natural = "cylinder point=1,0,0 axis=0,0,1 radius2=1".parse().unwrap();
    /// let r = quadsect::classify(&a, &b).unwrap();
    /// assert_eq!(r.to_json_string(), serde_json::to_string(&r).unwrap());
    /// ```
    pub fn to_json_string(&self) -> String {
        natural_json_text(self)
    }
}

/// [`natural_json`] as compact JSON text, written without a `Value` tree
/// (the batch protocol, the bindings).
pub fn natural_json_text(r: &NaturalReport) -> String {
    into_string(natural_bytes(r))
}

fn natural_bytes(r: &NaturalReport) -> Vec<u8> {
    let mut out = Vec::with_capacity(1024);
    write_natural(r, &mut out);
    out
}

/// Writes the answer (see [`natural_json`]) into `out`.
pub(crate) fn write_natural(r: &NaturalReport, out: &mut Vec<u8>) {
    if let Some(e) = &r.exhausted {
        wobj!(out;
            "class" => r.class.as_str(),
            "conics" => (),
            "lines" => (),
            "points" => (),
            "axes" => (),
            "thm8" => (),
            "components" => [(); 0],
            "method" => r.method,
            "a" => natural_input_w(&r.a),
            "b" => natural_input_w(&r.b),
            "notes" => r.notes,
            "reason" => obj_w! {"kind" => "budget", "limit" => e.limit().as_str(), "message" => e.to_string()},
        );
        return;
    }
    // the keys every answer starts with: class, counts, axes, thm8
    let mut obj = Obj::new(out);
    obj.field("class", r.class.as_str())
        .field("conics", r.conics())
        .field("lines", r.lines())
        .field("points", r.points())
        .field("axes", r.axes.as_ref().map(|a| a.as_str()))
        .field("thm8", r.thm8);
    if r.route == Some(Route::Fast) {
        obj.field("method", r.method).field("route", "fast");
        if let Some(f) = &r.referee {
            obj.field("referee", referee_w(f));
        }
        return obj.end();
    }
    obj.field(
        "components",
        arr(r
            .components
            .iter()
            .map(|c| W(move |o: &mut Vec<u8>| write_component(c, o)))),
    )
    .field("method", r.method)
    .field("deciders", r.deciders.as_ref().map(deciders_w))
    .field("section7", r.section7.as_ref().map(section7_w))
    .field("a", natural_input_w(&r.a))
    .field("b", natural_input_w(&r.b))
    .field("notes", &r.notes)
    .field(
        "certificate",
        (!r.member_planes.is_empty())
            .then_some(obj_w! {"planes" => arr(r.member_planes.iter().map(plane_w))}),
    );
    if let Some(Route::Complete(why)) = r.route {
        obj.field("route", "complete").field("fallback", why);
    }
    if let Some(f) = &r.referee {
        obj.field("referee", referee_w(f));
    }
    obj.end()
}

/// The referee (contract §4b): `lo`/`hi` as decimals rounded inward
/// (three digits, `lo` down, `hi` up) and exactly, the nearby input and
/// its answer, and the reasons when `lo` is 0 or `hi` is absent.
fn referee_w(f: &Referee) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        let nearby = f.nearby.as_ref().map(|n| {
            obj_w! {
                "a" => natural_input_w(&n.a),
                "b" => natural_input_w(&n.b),
                "answer" => obj_w! {
                    "class" => n.counts.class.as_str(),
                    "conics" => n.counts.conics,
                    "lines" => n.counts.lines,
                    "points" => n.counts.points
                }
            }
        });
        wobj!(out;
            "lo" => decimal_bound(&f.lo, false),
            "hi" => f.hi.as_ref().map(|h| decimal_bound(h, true)),
            "lo_exact" => fmt_q(&f.lo),
            "hi_exact" => f.hi.as_ref().map(fmt_q),
            "nearby" => nearby,
            "lo_reason" => f.lo_reason,
            "reason" => f.hi_reason,
        )
    })
}

/// A plane `{"normal", "offset"}` (normal·P = offset), exact, normalized
/// as the conics' planes.
fn plane_w(p: &Plane) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        let (normal, offset) = normalize_plane(p);
        obj_w! {"normal" => point_in(&normal, true), "offset" => number_in(&offset, true)}
            .write(out)
    })
}

/// A point with coordinates in Q(√d).
fn qpoint_w(x: &[QSqrt; 3]) -> impl Json + '_ {
    arr(x.iter().map(qsqrt_w))
}

/// An element of Q(√d): a string for a rational, `{"a","b","d","approx"}`
/// for a quadratic irrational (radicand normalized).
fn qsqrt_w(x: &QSqrt) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| {
        if x.is_rational() {
            fmt_q(&x.a).write(out)
        } else {
            let x = x.normalized();
            wobj!(out; "a" => fmt_q(&x.a), "b" => fmt_q(&x.b), "d" => fmt_q(&x.d), "approx" => if num_traits::Zero::is_zero(&x.b) { x.approx(20) } else { x.approx_irrational(20) })
        }
    })
}

/// JSON: a string for a rational, `{"a","b","d","approx"}` for a
/// quadratic irrational, `{"poly","interval","approx"}` otherwise.
fn exact_w(x: &Exact) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| match x {
        Exact::Quad(x) => qsqrt_w(x).write(out),
        Exact::Alg(a) => super::kernel::alg_w(a).write(out),
    })
}

fn epoint_w(p: &EPoint) -> impl Json + '_ {
    arr(p.iter().map(exact_w))
}

fn natural_input_w(q: &Natural) -> impl Json + '_ {
    W(move |out: &mut Vec<u8>| match q {
        Natural::Sphere(s) => {
            wobj!(out; "kind" => "sphere", "center" => v3(&s.center), "radius2" => fmt_q(&s.r2))
        }
        Natural::Cylinder(c) => {
            wobj!(out; "kind" => "cylinder", "point" => v3(&c.point), "axis" => v3(&c.axis), "radius2" => fmt_q(&c.r2))
        }
        Natural::Cone(c) => {
            wobj!(out; "kind" => "cone", "vertex" => v3(&c.vertex), "axis" => v3(&c.axis), "tan2" => fmt_q(&c.t2))
        }
    })
}

/// A vector's three exact coordinates as strings.
fn v3(p: &V3) -> [String; 3] {
    [fmt_q(&p[0]), fmt_q(&p[1]), fmt_q(&p[2])]
}

/// The JSON form of contract §2 (numbers as exact strings).
pub fn natural_input_json(q: &Natural) -> Value {
    let mut out = Vec::new();
    natural_input_w(q).write(&mut out);
    to_value(&out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The three shapes of an answer keep the documented key order: the
    /// complete route's answer to a request for counts only ends with
    /// `route` and `fallback`, the fast one has no components, and the
    /// text parses back to the same `Value`.
    #[test]
    fn key_order_of_each_route() {
        let a: Natural = "sphere center=0,0,0 radius2=4".parse().unwrap();
        let b: Natural = "cone vertex=0,0,3 axis=0,0,1 tan2=1".parse().unwrap();
        let mut r = crate::natural::classify::classify_complete(&a, &b).unwrap();
        let keys = |r: &NaturalReport| -> Vec<String> {
            let v: Value = serde_json::from_str(&natural_json_text(r)).unwrap();
            assert_eq!(v, natural_json(r));
            v.as_object().unwrap().keys().cloned().collect()
        };
        let head = ["class", "conics", "lines", "points", "axes", "thm8"];
        let complete: Vec<&str> = head
            .iter()
            .copied()
            .chain([
                "components",
                "method",
                "deciders",
                "section7",
                "a",
                "b",
                "notes",
                "certificate",
            ])
            .collect();
        assert_eq!(keys(&r), complete);
        r.route = Some(Route::Complete("a reason"));
        let mut with_fallback = complete.clone();
        with_fallback.extend(["route", "fallback"]);
        assert_eq!(keys(&r), with_fallback);
        assert!(natural_json_text(&r).ends_with(r#","route":"complete","fallback":"a reason"}"#));
        r.route = Some(Route::Fast);
        let fast: Vec<&str> = head.iter().copied().chain(["method", "route"]).collect();
        assert_eq!(keys(&r), fast);
    }
}
