//! Pictures of answers: SVG text, no dependency (issue 38).
//!
//! [`NaturalReport::svg`](crate::NaturalReport::svg) draws two natural
//! quadrics and their intersection (a 3D view, and the axial plane of the
//! papers' figures when the axes are coplanar);
//! [`TangentReport::svg`](crate::TangentReport::svg) draws the ellipsoid
//! coloured by the sign of the surface, with the witness points of the
//! certificate.
//!
//! **What is exact in a picture.**  Every decision shown (class, counts,
//! verdict, the kinds of the components) and every label comes from the
//! exact answer.  The strokes are doubles: conics, lines and points from
//! their exact data (centres, semi-axes, directions, coordinates, converted
//! to the nearest doubles); a space curve through certified points of the
//! ruling parameterisation the exact topology uses (ball arithmetic, each
//! point within 2^-30 of its size of a point of the curve); the places
//! where the tangent method's extremes are attained proven by a Krawczyk
//! box (not drawn when the proof fails); the level curve S = 0
//! on E through points proven by Krawczyk boxes (ball arithmetic; a point
//! the test declines leaves a gap); the surfaces' silhouettes and the
//! tangent method's shading from the equations evaluated in doubles (not
//! certified).  A picture shows; the certificate proves.

pub(crate) mod natural;
#[cfg(feature = "png")]
pub(crate) mod png;
pub(crate) mod tangent;

use crate::number::Q;
use num_traits::ToPrimitive;
use std::fmt::Write as _;

/// A 3-vector of doubles.
pub(crate) type P3 = [f64; 3];

pub(crate) fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub(crate) fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub(crate) fn scale(a: P3, s: f64) -> P3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub(crate) fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub(crate) fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub(crate) fn norm(a: P3) -> f64 {
    dot(a, a).sqrt()
}
/// `a / |a|` (`a` itself when it is 0).
pub(crate) fn unit(a: P3) -> P3 {
    let n = norm(a);
    if n > 0.0 { scale(a, 1.0 / n) } else { a }
}
/// A unit vector perpendicular to the unit `a`.
pub(crate) fn perpendicular(a: P3) -> P3 {
    let other = if a[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    unit(cross(a, other))
}

/// The nearest double of a rational (0 beyond the double range is never
/// reached by drawable data; an infinite value is clamped to ±1e300).
pub(crate) fn qf(q: &Q) -> f64 {
    q.to_f64().unwrap_or(0.0).clamp(-1e300, 1e300)
}

pub(crate) fn q3(v: &[Q; 3]) -> P3 {
    [qf(&v[0]), qf(&v[1]), qf(&v[2])]
}

/// An orthographic camera: the scene point `center` at the panel's
/// middle, `px` pixels per unit, looking along `-eye`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Camera {
    pub center: P3,
    pub eye: P3,
    pub right: P3,
    pub up: P3,
    pub px: f64,
    pub origin: (f64, f64),
}

impl Camera {
    /// Looking from the direction `eye` (towards the scene), `z` up when
    /// it can be.
    pub fn new(center: P3, eye: P3, px: f64, origin: (f64, f64)) -> Camera {
        let eye = unit(eye);
        let world_up = if eye[2].abs() > 0.95 {
            [0.0, 1.0, 0.0]
        } else {
            [0.0, 0.0, 1.0]
        };
        let right = unit(cross(world_up, eye));
        let up = cross(eye, right);
        Camera {
            center,
            eye,
            right,
            up,
            px,
            origin,
        }
    }

    /// Panel coordinates of a point.
    pub fn project(&self, p: P3) -> (f64, f64) {
        let d = sub(p, self.center);
        (
            self.origin.0 + self.px * dot(d, self.right),
            self.origin.1 - self.px * dot(d, self.up),
        )
    }
}

/// An SVG document under construction.
pub(crate) struct Svg {
    out: String,
    clips: usize,
}

/// XML text with `&`, `<`, `>` and `"` escaped.
pub(crate) fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            c => o.push(c),
        }
    }
    o
}

/// A short label of an exact value: the text itself when short, else its
/// approximation.
pub(crate) fn short(text: String, approx: impl FnOnce() -> String) -> String {
    if text.chars().count() <= 18 {
        text
    } else {
        format!("≈{}", approx())
    }
}

pub(crate) fn short_q(q: &Q) -> String {
    short(crate::number::fmt_q(q), || format!("{:.6}", qf(q)))
}

impl Svg {
    pub fn new(w: f64, h: f64, title: &str) -> Svg {
        let mut out = String::with_capacity(64 * 1024);
        let _ = write!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n\
             <title>{}</title>\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n",
            escape(title)
        );
        Svg { out, clips: 0 }
    }

    /// Opens a group clipped to a rectangle; [`Svg::end_group`] closes it.
    pub fn clipped(&mut self, x: f64, y: f64, w: f64, h: f64) {
        self.clips += 1;
        let id = self.clips;
        let _ = writeln!(
            self.out,
            "<clipPath id=\"c{id}\"><rect x=\"{x:.1}\" y=\"{y:.1}\" width=\"{w:.1}\" height=\"{h:.1}\"/></clipPath>\n<g clip-path=\"url(#c{id})\">"
        );
    }

    pub fn end_group(&mut self) {
        self.out.push_str("</g>\n");
    }

    pub fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, fill: &str, stroke: &str) {
        let _ = writeln!(
            self.out,
            "<rect x=\"{x:.1}\" y=\"{y:.1}\" width=\"{w:.1}\" height=\"{h:.1}\" fill=\"{fill}\" stroke=\"{stroke}\"/>"
        );
    }

    /// An open polyline (nothing for fewer than two points).
    pub fn polyline(&mut self, pts: &[(f64, f64)], stroke: &str, width: f64, dash: Option<&str>) {
        if pts.len() < 2 {
            return;
        }
        self.out.push_str("<polyline fill=\"none\" points=\"");
        for (x, y) in pts {
            let _ = write!(self.out, "{x:.1},{y:.1} ");
        }
        let _ = write!(
            self.out,
            "\" stroke=\"{stroke}\" stroke-width=\"{width}\" stroke-linejoin=\"round\" stroke-linecap=\"round\""
        );
        if let Some(d) = dash {
            let _ = write!(self.out, " stroke-dasharray=\"{d}\"");
        }
        self.out.push_str("/>\n");
    }

    /// Many separate segments as one path (the level curve S = 0).
    pub fn segments(&mut self, segs: &[[(f64, f64); 2]], stroke: &str, width: f64) {
        if segs.is_empty() {
            return;
        }
        self.out.push_str("<path fill=\"none\" d=\"");
        for [a, b] in segs {
            let _ = write!(self.out, "M{:.1} {:.1}L{:.1} {:.1}", a.0, a.1, b.0, b.1);
        }
        let _ = writeln!(
            self.out,
            "\" stroke=\"{stroke}\" stroke-width=\"{width}\" stroke-linecap=\"round\"/>"
        );
    }

    pub fn polygon(&mut self, pts: &[(f64, f64)], fill: &str, stroke: &str) {
        self.out.push_str("<polygon points=\"");
        for (x, y) in pts {
            let _ = write!(self.out, "{x:.1},{y:.1} ");
        }
        let _ = writeln!(self.out, "\" fill=\"{fill}\" stroke=\"{stroke}\"/>");
    }

    pub fn circle(&mut self, c: (f64, f64), r: f64, fill: &str, stroke: &str, width: f64) {
        let _ = writeln!(
            self.out,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{r:.1}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{width}\"/>",
            c.0, c.1
        );
    }

    pub fn text(&mut self, at: (f64, f64), size: f64, fill: &str, s: &str) {
        self.text_anchored(at, size, fill, s, false);
    }

    /// Text starting at `at`, or ending there when `end` (a label left of
    /// its mark, near a panel's right edge).
    pub fn text_anchored(&mut self, at: (f64, f64), size: f64, fill: &str, s: &str, end: bool) {
        let anchor = if end { " text-anchor=\"end\"" } else { "" };
        let _ = writeln!(
            self.out,
            "<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"{size}\" fill=\"{fill}\"{anchor}>{}</text>",
            at.0,
            at.1,
            escape(s)
        );
    }

    pub fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// Splits a sampled 3D path at the points outside the ball `(c, r)` and
/// projects the pieces.
pub(crate) fn inside_pieces(cam: &Camera, pts: &[P3], c: P3, r: f64) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for &p in pts {
        if p.iter().all(|v| v.is_finite()) && norm(sub(p, c)) <= r {
            cur.push(cam.project(p));
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// The parameters `t` where the line `p + t·d` (unit `d`) crosses the
/// sphere `(c, r)`, or `None` when it misses.
pub(crate) fn line_in_ball(p: P3, d: P3, c: P3, r: f64) -> Option<(f64, f64)> {
    let w = sub(p, c);
    let b = dot(w, d);
    let disc = b * b - dot(w, w) + r * r;
    (disc > 0.0).then(|| (-b - disc.sqrt(), -b + disc.sqrt()))
}

/// Eigenvalues and unit eigenvectors (columns) of a symmetric 3×3 matrix
/// by Jacobi rotations (for drawing only).
pub(crate) fn symmetric_eigen(mut a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        if off < 1e-15 * (a[0][0].abs() + a[1][1].abs() + a[2][2].abs()) {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for k in 0..3 {
                let (akp, akq) = (a[k][p], a[k][q]);
                a[k][p] = c * akp - s * akq;
                a[k][q] = s * akp + c * akq;
            }
            for k in 0..3 {
                let (apk, aqk) = (a[p][k], a[q][k]);
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
            }
            for row in v.iter_mut() {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_of_a_rotated_diagonal() {
        let (l, v) = symmetric_eigen([[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 5.0]]);
        let mut s = l;
        s.sort_by(f64::total_cmp);
        assert!((s[0] - 1.0).abs() < 1e-12 && (s[1] - 3.0).abs() < 1e-12);
        // A v = λ v for each column
        let a = [[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 5.0]];
        for j in 0..3 {
            for i in 0..3 {
                let av: f64 = (0..3).map(|k| a[i][k] * v[k][j]).sum();
                assert!((av - l[j] * v[i][j]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
    }
}
