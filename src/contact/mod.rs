//! Ellipsoid–ellipsoid contact: exact, filtered, in bulk.
//!
//! Two solid ellipsoids are **separated**, **touching** (externally: one
//! common point, interiors disjoint) or **overlapping** (a common interior
//! point), and an overlap is of one [`Kind`]: the surfaces cross, one lies
//! inside the other (strictly, or touching from inside), or they are the
//! same ellipsoid.  The answer is exact — every double of the input is
//! taken at its exact binary value — and carries a [`Certificate`] that a
//! few exact operations re-check.
//!
//! # Input
//!
//! A [`Pose`] is what a physics or robotics code holds: a centre `c`,
//! semi-axes `r` (all > 0) and an invertible 3×3 matrix `R` (a rotation,
//! or any invertible matrix; column i is the direction of semi-axis i),
//! all doubles.  It denotes
//!
//! ```text
//! E = { x : Σᵢ ((Rᵀ(x − c))ᵢ / rᵢ)² ≤ 1 }   (= { c + R·diag(r)·u : |u| ≤ 1 } for a rotation)
//! ```
//!
//! with every double at its exact value — the convention of the tangent
//! point method's `Ellipsoid::from_frame` and of the C `qs_ellipsoid_f64`.
//! A rotation matrix rounded to doubles is not exactly orthogonal; the
//! ellipsoid is the one those numbers define, not a nearby one.  An [`ExactEllipsoid`] takes
//! the same data as exact rationals, or a quadric polynomial.
//!
//! # The mathematics (module `filter`, `exact`)
//!
//! With the canonical forms `q_A`, `q_B` (negative inside; for a pose
//! `q(x) = |D⁻¹Rᵀ(x − c)|² − 1`) and their 4×4 matrices A, B, let
//! `f(λ) = det(λA + B)` (Wang, Wang and Kim's characteristic polynomial).
//! For λ > 0 the minimum over x of the convex `λq_A + q_B` is
//! `f(λ)/det(λW_A + W_B)`; by convex duality its maximum over λ > 0 is
//! `min{ q_B(x) : q_A(x) ≤ 0 }`.  So the pair is separated iff `f(λ) > 0`
//! for some λ > 0, touching iff `max_{λ>0} f = 0`, overlapping iff `f < 0`
//! on λ > 0 — which is Wang–Wang–Kim's condition (two distinct positive
//! roots; a positive double root) with its proof.
//!
//! The doubles' route ([`contact`]) computes f's coefficients in `f64`
//! with rigorous error bounds, finds the dual maximiser numerically and
//! certifies either `f(λ) > 0` or a point inside both; only when neither
//! is certain (a touching pair, or one within ~10⁻¹⁴ of touching) does it
//! compute exactly (f over Z, square-free decomposition, root isolation).
//!
//! ```
//! use quadsect::contact::{self, Contact, Pose};
//! let id = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
//! let a = Pose::new([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], id)?;
//! let apart = Pose::new([2.5, 0.0, 0.0], [1.0, 1.0, 1.0], id)?;
//! let touching = Pose::new([2.0, 0.0, 0.0], [1.0, 1.0, 1.0], id)?;
//! assert_eq!(contact::contact(&a, &apart)?, Contact::Separated);
//! assert_eq!(contact::contact(&a, &touching)?, Contact::Touching);
//! # Ok::<(), quadsect::Error>(())
//! ```

mod exact;
mod filter;
mod program;

pub use filter::wwk_f64;

use crate::error::{Error, ErrorKind};
use crate::geom::quadric::QuadricForm;
use crate::number::{Q, QSqrt};
use num_traits::{One, Signed, Zero};

/// The three answers, with the codes of the bulk APIs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Contact {
    /// No common point.
    Separated = 0,
    /// Exactly one common point, interiors disjoint.
    Touching = 1,
    /// A common interior point.
    Overlapping = 2,
}

impl Contact {
    /// `separated`, `touching` or `overlapping`.
    pub fn as_str(self) -> &'static str {
        match self {
            Contact::Separated => "separated",
            Contact::Touching => "touching",
            Contact::Overlapping => "overlapping",
        }
    }
}

/// How the two ellipsoids meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Kind {
    /// Separated.
    Separated,
    /// Touching from outside.
    ExternallyTouching,
    /// Overlapping, neither inside the other: the surfaces cross.
    SurfacesCross,
    /// A lies in B's interior (the surfaces do not meet).
    AInsideB,
    /// B lies in A's interior.
    BInsideA,
    /// One lies inside the other and the surfaces touch.
    InternallyTouching,
    /// The same ellipsoid.
    Identical,
    /// Overlapping; the kind was not asked for.
    Unclassified,
}

impl Kind {
    /// The contract's name: `separated`, `externally-touching`,
    /// `surfaces-cross`, `A-inside-B`, `B-inside-A`, `internally-touching`,
    /// `identical`, `unclassified`.
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Separated => "separated",
            Kind::ExternallyTouching => "externally-touching",
            Kind::SurfacesCross => "surfaces-cross",
            Kind::AInsideB => "A-inside-B",
            Kind::BInsideA => "B-inside-A",
            Kind::InternallyTouching => "internally-touching",
            Kind::Identical => "identical",
            Kind::Unclassified => "unclassified",
        }
    }
}

/// The evidence of an overlap's kind (canonical forms, module doc).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Evidence {
    /// `B − μA` is negative definite (A inside B: `q_B < μq_A ≤ 0` on A) or
    /// positive definite (B inside A), μ > 0.
    Inside {
        /// μ.
        mu: Q,
    },
    /// `B − μA` is negative semidefinite (`a_in_b`: A ⊆ B) or positive
    /// semidefinite (B ⊆ A), μ > 0 a double root of `f(−μ)`, and `point`
    /// (when the surfaces touch) lies on both.
    Semidefinite {
        /// μ.
        mu: QSqrt,
        /// A ⊆ B (else B ⊆ A).
        a_in_b: bool,
        /// The common point of the surfaces.
        point: Option<[QSqrt; 3]>,
    },
    /// Points inside A outside B and inside B outside A (`None`: not found
    /// by the search, so the kind is not re-checkable from the certificate).
    Cross {
        /// `q_A < 0 < q_B`.
        a_only: Option<[Q; 3]>,
        /// `q_B < 0 < q_A`.
        b_only: Option<[Q; 3]>,
    },
    /// `B = μA`, μ > 0.
    Identical {
        /// μ.
        mu: Q,
    },
}

/// What proves the answer (canonical forms `q_A`, `q_B` and matrices A, B).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Certificate {
    /// λ > 0 with `det(λA + B) > 0`: then `λq_A + q_B` (convex, its
    /// minimum `det(λA + B)/det(λW_A + W_B)`) is positive everywhere, so no
    /// point is in both.
    Separated {
        /// λ.
        lambda: Q,
    },
    /// λ > 0 and a point on both surfaces where `λ∇q_A + ∇q_B = 0`: the
    /// convex `λq_A + q_B ≥ 0` vanishes only there.
    Touching {
        /// λ (rational or in Q(√d)).
        lambda: QSqrt,
        /// The touching point.
        point: [QSqrt; 3],
    },
    /// A point with `q_A < 0` and `q_B < 0`, and the kind's evidence (when
    /// the kind was asked for).
    Overlapping {
        /// The common interior point.
        point: [Q; 3],
        /// The kind's evidence.
        evidence: Option<Evidence>,
    },
}

/// An ellipsoid given as a physics code holds it (module doc), in doubles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub(crate) center: [f64; 3],
    pub(crate) semi_axes: [f64; 3],
    pub(crate) matrix: [[f64; 3]; 3],
}

impl Pose {
    /// Checks the data: every number finite, semi-axes > 0, the matrix
    /// exactly invertible (its determinant is computed exactly when the
    /// double-precision one is too small to tell).
    pub fn new(
        center: [f64; 3],
        semi_axes: [f64; 3],
        matrix: [[f64; 3]; 3],
    ) -> Result<Pose, Error> {
        let bad = |why: String| Error::new(ErrorKind::NotAnEllipsoid, why);
        if let Some(i) = (0..3).find(|&i| !center[i].is_finite()) {
            return Err(bad(format!(
                "centre coordinate {i} is {} (not finite)",
                center[i]
            )));
        }
        if let Some(i) = (0..3).find(|&i| !(semi_axes[i].is_finite() && semi_axes[i] > 0.0)) {
            return Err(bad(format!(
                "semi-axis {i} is {} (must be finite and > 0)",
                semi_axes[i]
            )));
        }
        for (i, row) in matrix.iter().enumerate() {
            if let Some(j) = (0..3).find(|&j| !row[j].is_finite()) {
                return Err(bad(format!(
                    "matrix entry [{i}][{j}] is {} (not finite)",
                    row[j]
                )));
            }
        }
        if !filter::det_nonzero(&matrix) && {
            let q: [[Q; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| qf(matrix[i][j])));
            crate::geom::matrix::det3(&q).is_zero()
        } {
            return Err(bad(
                "the matrix is singular (its exact determinant is 0)".into()
            ));
        }
        Ok(Pose {
            center,
            semi_axes,
            matrix,
        })
    }

    /// The centre.
    pub fn center(&self) -> [f64; 3] {
        self.center
    }
    /// The semi-axes.
    pub fn semi_axes(&self) -> [f64; 3] {
        self.semi_axes
    }
    /// The matrix (rows).
    pub fn matrix(&self) -> [[f64; 3]; 3] {
        self.matrix
    }
}

/// The exact value of a double.
fn qf(x: f64) -> Q {
    Q::from_float(x).expect("finite")
}

/// An ellipsoid with exact data: a pose of rationals, or a quadric.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactEllipsoid {
    form: QuadricForm,
    /// The centre `−W⁻¹b`.
    centre: [Q; 3],
    /// `ρ = (det R · r₁r₂r₃)²` of a pose (the filter's scale), and the pose
    /// itself when it is made of doubles.
    rho: Option<Q>,
    pose: Option<Pose>,
}

impl ExactEllipsoid {
    /// The ellipsoid of a pose of doubles, exactly.
    pub fn from_pose(p: &Pose) -> ExactEllipsoid {
        let c = p.center.map(qf);
        let r = p.semi_axes.map(qf);
        let m = p.matrix.map(|row| row.map(qf));
        let mut e = ExactEllipsoid::pose_q(c, r, m);
        e.pose = Some(*p);
        e
    }

    /// The ellipsoid `{x : |diag(r)⁻¹Rᵀ(x − c)| ≤ 1}` of exact data
    /// (semi-axes > 0, R invertible).
    pub fn from_pose_exact(
        center: [Q; 3],
        semi_axes: [Q; 3],
        matrix: [[Q; 3]; 3],
    ) -> Result<ExactEllipsoid, Error> {
        let bad = |why: String| Error::new(ErrorKind::NotAnEllipsoid, why);
        if let Some(i) = (0..3).find(|&i| !semi_axes[i].is_positive()) {
            return Err(bad(format!(
                "semi-axis {i} is {} (must be > 0)",
                semi_axes[i]
            )));
        }
        if crate::geom::matrix::det3(&matrix).is_zero() {
            return Err(bad(
                "the matrix is singular (its exact determinant is 0)".into()
            ));
        }
        Ok(ExactEllipsoid::pose_q(center, semi_axes, matrix))
    }

    /// The canonical form of a pose: `W = R·D⁻²·Rᵀ`, `b = −Wc`,
    /// `c₀ = cᵀWc − 1`.
    fn pose_q(c: [Q; 3], r: [Q; 3], m: [[Q; 3]; 3]) -> ExactEllipsoid {
        use crate::number::{q_add, q_mul};
        // W = R·diag(1/r²)·Rᵀ (the cross-cancelling products of `number`)
        let inv2: [Q; 3] = std::array::from_fn(|k| q_mul(&r[k], &r[k]).recip());
        let w: [[Q; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (0..3).fold(Q::zero(), |s, k| {
                    q_add(&s, &q_mul(&q_mul(&m[i][k], &m[j][k]), &inv2[k]))
                })
            })
        });
        let wc: [Q; 3] = std::array::from_fn(|i| {
            (0..3).fold(Q::zero(), |s, k| q_add(&s, &q_mul(&w[i][k], &c[k])))
        });
        let cwc = (0..3).fold(Q::zero(), |s, k| q_add(&s, &q_mul(&c[k], &wc[k])));
        let sigma = q_mul(&q_mul(&r[0], &r[1]), &r[2]);
        ExactEllipsoid {
            form: QuadricForm {
                a: w,
                b: wc.map(|x| -x),
                c: cwc - Q::one(),
            },
            centre: c,
            rho: Some(q_mul(&sigma, &sigma)),
            pose: None,
        }
    }

    /// The ellipsoid `q ≤ 0` of a polynomial of degree 2 whose quadratic
    /// part is definite, with a real interior; the sign is taken so that
    /// the interior is negative (`1 − x² − y² − z²` is the unit ball too).
    pub fn from_poly(p: &crate::Polynomial) -> Result<ExactEllipsoid, Error> {
        let bad = |why: &str| Error::new(ErrorKind::NotAnEllipsoid, why.to_string());
        let mut form = QuadricForm::from_poly(p.inner())
            .ok_or_else(|| bad("not a polynomial of degree 2 in x, y, z"))?;
        let lead = |f: &QuadricForm| {
            let a = &f.a;
            let d1 = a[0][0].clone();
            let d2 = &a[0][0] * &a[1][1] - &a[0][1] * &a[1][0];
            let d3 = crate::geom::matrix::det3(a);
            (d1, d2, d3)
        };
        let (d1, d2, d3) = lead(&form);
        if d1.is_negative() && d2.is_positive() && d3.is_negative() {
            form = form.neg();
        } else if !(d1.is_positive() && d2.is_positive() && d3.is_positive()) {
            return Err(bad("the quadratic part is not definite"));
        }
        let m = exact::matrix(&form);
        let det4 =
            exact::quartic(&m, &m.clone().map(|r| r.map(|_| Q::zero())), Q::zero())[4].clone();
        if !det4.is_negative() {
            return Err(bad(
                "the quadric has no real interior (an empty or one-point ellipsoid)",
            ));
        }
        let centre = exact::centre(&form);
        Ok(ExactEllipsoid {
            form,
            centre,
            rho: None,
            pose: None,
        })
    }

    /// The canonical quadric form `xᵀWx + 2bᵀx + c` (negative inside).
    pub fn form_matrix(&self) -> [[Q; 4]; 4] {
        exact::matrix(&self.form)
    }
}

impl std::str::FromStr for ExactEllipsoid {
    type Err = Error;
    fn from_str(s: &str) -> Result<ExactEllipsoid, Error> {
        ExactEllipsoid::from_poly(&s.parse()?)
    }
}

/// The answer for one pair with its certificate.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactReport {
    contact: Contact,
    kind: Kind,
    certificate: Certificate,
    route: &'static str,
}

impl ContactReport {
    /// Separated, touching or overlapping.
    pub fn contact(&self) -> Contact {
        self.contact
    }
    /// The kind (of an overlap; `separated`/`externally-touching` otherwise).
    pub fn kind(&self) -> Kind {
        self.kind
    }
    /// The certificate.
    pub fn certificate(&self) -> &Certificate {
        &self.certificate
    }
    /// `filter` when doubles decided (the certificate is then built exactly
    /// from the filter's λ or point), `exact` otherwise.
    pub fn route(&self) -> &'static str {
        self.route
    }
}

/// The contact of two poses: the doubles' filter, exact when it cannot
/// decide.  Errors only on an internal failure.
pub fn contact(a: &Pose, b: &Pose) -> Result<Contact, Error> {
    match filter::decide(a, b) {
        Ok(r) => Ok(r.contact()),
        Err(hints) => Ok(exact::decide_poses(a, b, &hints)),
    }
}

/// The contact of two poses by the exact route alone (no filter): the
/// independent decider of the tests and the benchmarks' labels.
pub fn contact_exact(a: &Pose, b: &Pose) -> Result<Contact, Error> {
    Ok(exact::decide_poses(a, b, &filter::Hints::default()))
}

/// True when the doubles' filter alone decides the pair (no exact
/// arithmetic) — for benchmarks.
pub fn filter_decides(a: &Pose, b: &Pose) -> bool {
    filter::decide(a, b).is_ok()
}

/// The contact of two exact ellipsoids with its kind and certificate.
pub fn contact_report(a: &ExactEllipsoid, b: &ExactEllipsoid) -> Result<ContactReport, Error> {
    let mut route = "exact";
    let mut hint = None;
    if let (Some(pa), Some(pb)) = (&a.pose, &b.pose)
        && let Ok(f) = filter::decide(pa, pb)
    {
        route = "filter";
        hint = Some(match f {
            filter::Filtered::Separated { lambda } => {
                // scaled forms: λ_canonical = λ·ρ_A/ρ_B
                let (ra, rb) = (a.rho.clone().unwrap(), b.rho.clone().unwrap());
                exact::Hint::Lambda(qf(lambda) * ra / rb)
            }
            filter::Filtered::Overlapping { point } => exact::Hint::Point(point.map(qf)),
        });
    }
    let (contact, kind, certificate) =
        exact::decide(&a.form, &b.form, &a.centre, &b.centre, hint, true)?;
    Ok(ContactReport {
        contact,
        kind,
        certificate,
        route,
    })
}

/// Structure-of-arrays input of the bulk API: for n ellipsoids, `center`
/// and `semi_axes` hold 3n doubles (x, y, z per ellipsoid), `matrix` 9n
/// (row-major per ellipsoid) — the memory of NumPy arrays of shapes (n, 3),
/// (n, 3), (n, 3, 3).
#[derive(Clone, Copy, Debug)]
pub struct Poses<'a> {
    /// 3n centre coordinates.
    pub center: &'a [f64],
    /// 3n semi-axes.
    pub semi_axes: &'a [f64],
    /// 9n matrix entries.
    pub matrix: &'a [f64],
}

impl Poses<'_> {
    fn len(&self, what: &str) -> Result<usize, Error> {
        let n = self.center.len() / 3;
        if self.center.len() != 3 * n || self.semi_axes.len() != 3 * n || self.matrix.len() != 9 * n
        {
            return Err(Error::new(
                ErrorKind::Input,
                format!(
                    "{what}: {} centre, {} semi-axis and {} matrix numbers (expected 3n, 3n and 9n)",
                    self.center.len(),
                    self.semi_axes.len(),
                    self.matrix.len()
                ),
            ));
        }
        Ok(n)
    }

    fn get(&self, i: usize) -> Result<Pose, Error> {
        let c = &self.center[3 * i..3 * i + 3];
        let r = &self.semi_axes[3 * i..3 * i + 3];
        let m = &self.matrix[9 * i..9 * i + 9];
        Pose::new(
            [c[0], c[1], c[2]],
            [r[0], r[1], r[2]],
            [[m[0], m[1], m[2]], [m[3], m[4], m[5]], [m[6], m[7], m[8]]],
        )
    }
}

/// The owned arrays of a list of poses, in the layout of [`Poses`].
#[derive(Clone, Debug, Default)]
pub struct PoseArrays {
    /// 3n centre coordinates.
    pub center: Vec<f64>,
    /// 3n semi-axes.
    pub semi_axes: Vec<f64>,
    /// 9n matrix entries (row-major per pose).
    pub matrix: Vec<f64>,
}

impl PoseArrays {
    /// The arrays of `poses`, in order.
    pub fn new<'a>(poses: impl IntoIterator<Item = &'a Pose>) -> PoseArrays {
        let mut out = PoseArrays::default();
        for p in poses {
            out.center.extend(p.center);
            out.semi_axes.extend(p.semi_axes);
            out.matrix.extend(p.matrix.concat());
        }
        out
    }

    /// The borrowed view the bulk API takes.
    pub fn view(&self) -> Poses<'_> {
        Poses {
            center: &self.center,
            semi_axes: &self.semi_axes,
            matrix: &self.matrix,
        }
    }
}

/// The integer matrix of a quaternion q (`RRᵀ = N²I`, `N = |q|²`): the
/// rotation `R/N` times N, exact in doubles — the benchmarks' and tests'
/// exactly touching pairs rest on it.
pub(crate) fn quaternion_matrix(q: [i64; 4]) -> [[f64; 3]; 3] {
    let [w, x, y, z] = q;
    [
        [
            w * w + x * x - y * y - z * z,
            2 * (x * y - w * z),
            2 * (x * z + w * y),
        ],
        [
            2 * (x * y + w * z),
            w * w - x * x + y * y - z * z,
            2 * (y * z - w * x),
        ],
        [
            2 * (x * z - w * y),
            2 * (y * z + w * x),
            w * w - x * x - y * y + z * z,
        ],
    ]
    .map(|row| row.map(|v| v as f64))
}

/// The contact of n pairs `(a[i], b[i])` into `out` (n codes), on
/// `threads` threads (0: the machine's parallelism).  A bad pose is an
/// error naming its row (and nothing is written after it in that chunk).
pub fn contact_many(
    a: Poses<'_>,
    b: Poses<'_>,
    out: &mut [Contact],
    threads: usize,
) -> Result<(), Error> {
    let n = a.len("first ellipsoids")?;
    let nb = b.len("second ellipsoids")?;
    if nb != n || out.len() != n {
        return Err(Error::new(
            ErrorKind::Input,
            format!(
                "{n} first ellipsoids, {nb} second ellipsoids, room for {} answers",
                out.len()
            ),
        ));
    }
    let threads = if threads == 0 {
        std::thread::available_parallelism().map_or(1, |t| t.get())
    } else {
        threads
    }
    .clamp(1, n.max(1));
    let run = |start: usize, chunk: &mut [Contact]| -> Result<(), Error> {
        for (k, o) in chunk.iter_mut().enumerate() {
            let i = start + k;
            let pa = a
                .get(i)
                .map_err(|e| e.context(&format!("in row {i} of the first ellipsoids")))?;
            let pb = b
                .get(i)
                .map_err(|e| e.context(&format!("in row {i} of the second ellipsoids")))?;
            *o = contact(&pa, &pb).map_err(|e| e.context(&format!("in row {i}")))?;
        }
        Ok(())
    };
    if threads == 1 || n < 256 {
        return run(0, out);
    }
    let per = n.div_ceil(threads);
    let results: Vec<Result<(), Error>> = std::thread::scope(|s| {
        let handles: Vec<_> = out
            .chunks_mut(per)
            .enumerate()
            .map(|(k, chunk)| {
                let run = &run;
                s.spawn(move || run(k * per, chunk))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| {
                h.join()
                    .unwrap_or_else(|_| Err(Error::internal("a contact thread panicked")))
            })
            .collect()
    });
    results.into_iter().collect()
}

#[cfg(test)]
mod tests;
