//! The referee: how far two natural quadrics are from a different answer
//! (docs/maths.md, "The referee").
//!
//! A floating-point kernel that disagrees with the exact answer is either
//! wrong or looking at an input within rounding distance of another class.
//! The referee settles which with two numbers of relative perturbation
//! size, in the metric below:
//!
//! * **lo, proved**: every input within relative distance `lo` has the same
//!   class and counts.  The fast route's predicates ([`program`]) run on
//!   balls that hold every such input ([`BallR`], sound rounding): when
//!   every sign along the path is certified over the box, every input in it
//!   takes the same path to the same counts.  `lo` is the largest size of a
//!   logarithmic grid (`m/256 · 2^-e`, four steps per octave, down to
//!   2^-100) where this holds, found by bisection; `0` when none does (an
//!   exactly degenerate input, or one the predicates hand to the complete
//!   route).
//! * **hi, witnessed**: an explicit input at relative distance `hi`, given
//!   exactly, whose exact answer (the engine's, checked) differs.  It is
//!   found where the proof stops: the predicates run once more on balls of
//!   radius `lo`, carrying first-order derivatives with respect to every
//!   input number; each sign on the path is a polynomial `P` of the input,
//!   and `t = |P| / Σ|∂P/∂xᵢ|·wᵢ` is the size of the smallest move that
//!   reaches `P = 0` to first order (each number moving by at most `t·wᵢ`,
//!   in the direction that shrinks `|P|`).  Inputs a little beyond
//!   (`1.25t`, `2t`, `4t`, sorted by size) are classified exactly; the first
//!   whose answer differs is the witness.  Failing those, a few fixed
//!   pseudo-random directions at sizes growing by 16 from `1.25·lo`, and
//!   the quadrics pushed together or apart ([`Scene::approach`]) at sizes
//!   growing by 4 (all by size when nothing is proved).  The exact degenerate configurations
//!   next to the input (axes made parallel, coaxial or meeting, a common
//!   vertex, equal parameters: [`Scene::snaps`]) compete, and a witness on
//!   a ray is bisected toward the input.  No witness up to relative size
//!   1/2: `hi` is absent, with the reason.
//!
//! **The metric.**  For each quadric, its point (centre, axis point or
//! vertex) `p`, its axis `a` and its parameter `s` (`r2` or `tan²α`, as
//! stored): an input is within relative distance `ε` when
//! `‖p' − p‖∞ ≤ ε·L`, `‖a' − a‖∞ ≤ ε‖a‖∞` and `|s' − s| ≤ ε|s|`, kinds
//! unchanged, where `L` is the scene's length: the larger of the two
//! points' `‖p‖∞` and, for each sphere or cylinder, the least power of two
//! at or above its radius.  The components of a vector move relative to a
//! size, so a rounding of each coordinate of a point or a direction to a
//! double is within `2^-53`; a point near the origin is not held there
//! (a feature 10⁻⁹ off the origin in a scene of size 1 is 10⁻⁹ away from
//! the origin, not 100 %).

use super::predicates::{Outcome, classify_counts, definite4, matrix, member, program};
use super::prepared::{Kind, Prepared, QIn};
use super::result::{Class, Counts};
use super::types::{Cone, Cylinder, Natural, Sphere};
use crate::geom::vec3::{V3, add, cross, dot, is_zero, norm2, scale, sub};
use crate::number::Q;
use crate::number::filter::{BallR, SignRing};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cell::RefCell;

/// Numbers per quadric: point (3), axis (3), parameter.
const PER: usize = 7;
/// Numbers of a pair.
const N: usize = 2 * PER;
/// The grid's floor: `2^-100`.
const GRID_LAST: u32 = 400;
/// The largest perturbation a witness is looked for at.
const HI_MAX: f64 = 0.5;
/// Exact classifications tried along the derivatives' directions.
const GRADIENT_TRIALS: usize = 8;
/// Exact classifications tried along fixed pseudo-random directions.
const RANDOM_TRIALS: usize = 12;
/// The witness size tried first for an exactly degenerate input: any
/// size works there; a smaller one only makes the nearby numbers longer
/// and their exact classification slower.
const DEGENERATE_STEP: f64 = 1.0 / 1_099_511_627_776.0; // 2^-40

/// The stability of a natural pair's answer ([`super::NaturalReport::referee`]).
///
/// ```
/// use quadsect::{Natural, ClassifyOptions, Class};
/// // two unit spheres whose centres are 3/2 apart: a circle, 1/4 from tangency
/// let a: Natural = "sphere center=0,0,0 radius2=1".parse().unwrap();
/// let b: Natural = "sphere center=3/2,0,0 radius2=1".parse().unwrap();
/// let r = quadsect::classify_with(&a, &b, &ClassifyOptions::default().with_referee()).unwrap();
/// let f = r.referee().unwrap();
/// assert!(f.lo() > &quadsect::Rational::from_integer(0.into()));
/// let hi = f.hi().unwrap();
/// assert!(f.lo() < hi);
/// let near = f.nearby().unwrap();
/// assert_ne!(near.class(), Class::Conics); // the witness's exact answer differs
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Referee {
    pub(crate) lo: Q,
    pub(crate) hi: Option<Q>,
    pub(crate) nearby: Option<NearbyPair>,
    pub(crate) lo_reason: Option<&'static str>,
    pub(crate) hi_reason: Option<&'static str>,
}

/// An input near the given one with a different exact answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NearbyPair {
    pub(crate) a: Natural,
    pub(crate) b: Natural,
    pub(crate) counts: Counts,
}

impl Referee {
    /// The proved relative size: every input within it has the same class
    /// and counts (an exact dyadic; `0` when nothing is proved).
    pub fn lo(&self) -> &Q {
        &self.lo
    }

    /// The witnessed relative size: [`Referee::nearby`] is exactly this far
    /// from the input (`None` when no witness was found).
    pub fn hi(&self) -> Option<&Q> {
        self.hi.as_ref()
    }

    /// The witness: an input at distance [`Referee::hi`] and its answer.
    pub fn nearby(&self) -> Option<&NearbyPair> {
        self.nearby.as_ref()
    }

    /// Why `lo` is 0, when it is.
    pub fn lo_reason(&self) -> Option<&str> {
        self.lo_reason
    }

    /// Why there is no witness, when there is none.
    pub fn hi_reason(&self) -> Option<&str> {
        self.hi_reason
    }
}

impl NearbyPair {
    /// The first quadric of the witness.
    pub fn a(&self) -> &Natural {
        &self.a
    }

    /// The second quadric of the witness.
    pub fn b(&self) -> &Natural {
        &self.b
    }

    /// Its exact class.
    pub fn class(&self) -> Class {
        self.counts.class
    }

    /// Its real affine conics.
    pub fn conics(&self) -> usize {
        self.counts.conics
    }

    /// Its real affine lines.
    pub fn lines(&self) -> usize {
        self.counts.lines
    }

    /// Its isolated real points (acnodes included).
    pub fn points(&self) -> usize {
        self.counts.points
    }
}

/// The pair's numbers, their scales and their ball images.
struct Scene {
    kinds: [Kind; 2],
    /// The numbers (point, axis, parameter per quadric).
    x: [Q; N],
    /// The exact scale `wᵢ` each may move by per unit of relative size
    /// (`‖p‖∞`, `‖a‖∞`, `|s|`; 0 for a sphere's axis).
    w: [Q; N],
    /// The numbers as balls in scaled units (see [`Scene::new`]).
    m: [f64; N],
    r0: [f64; N],
    /// Upper bounds of the scaled `wᵢ`.
    wup: [f64; N],
}

/// The least power of two at or above `√r2` (`r2 > 0`), exactly.
fn radius_bound(r2: &Q) -> Q {
    let mut k = lg(r2).div_euclid(2) - 1;
    let pow = |k: i64| -> Q {
        let one = BigInt::one();
        if k >= 0 {
            Q::from_integer(one << k as usize)
        } else {
            Q::new(one.clone(), one << (-k) as usize)
        }
    };
    while &(pow(k) * pow(k)) < r2 {
        k += 1;
    }
    pow(k)
}

/// `⌊log₂|x|⌋` within one (`x ≠ 0`).
fn lg(x: &Q) -> i64 {
    x.numer().bits() as i64 - x.denom().bits() as i64
}

/// The top (≤ 64) bits of `|z|` as a double and the exponent dropped.
fn top(z: &BigInt) -> (f64, i64) {
    let b = z.bits();
    let sh = b.saturating_sub(64);
    let t = (z.magnitude() >> sh).to_u64().unwrap_or(u64::MAX) as f64;
    (t, sh as i64)
}

/// `x·2^shift` as a ball of the real-valued filter: the top bits of
/// numerator and denominator (truncation < 2^-63 each), two conversions
/// and a division (one rounding each) and an exact power of two: relative
/// error below `6u`, plus `2^-1000` for results near underflow.
fn ball_of(x: &Q, shift: i64) -> (f64, f64) {
    if x.is_zero() {
        return (0.0, 0.0);
    }
    let (tn, en) = top(x.numer());
    let (td, ed) = top(x.denom());
    let e = en - ed + shift;
    let mut v = tn / td;
    if x.is_negative() {
        v = -v;
    }
    // the exponent in two halves so that neither power overflows
    let v = if e.abs() <= 2000 {
        v * 2f64.powi((e / 2) as i32) * 2f64.powi((e - e / 2) as i32)
    } else if e > 0 {
        f64::INFINITY
    } else {
        0.0
    };
    // exact: a numerator of at most 53 bits over a power of two, the
    // result a normal double
    let exact = x.numer().bits() <= 53
        && x.denom().bits() - 1 == x.denom().trailing_zeros().unwrap_or(0)
        && v.abs() >= f64::MIN_POSITIVE;
    let r = if exact {
        0.0
    } else {
        6.0 * (f64::EPSILON / 2.0) * v.abs() + 1e-300
    };
    (v, if v.is_finite() { r } else { f64::INFINITY })
}

impl Scene {
    fn new(a: &Natural, b: &Natural) -> Scene {
        let parts = |q: &Natural| -> (Kind, [Q; 3], [Q; 3], Q) {
            match q {
                Natural::Sphere(s) => (
                    Kind::Sphere,
                    s.center.clone(),
                    std::array::from_fn(|_| Q::zero()),
                    s.r2.clone(),
                ),
                Natural::Cylinder(c) => (
                    Kind::Cylinder,
                    c.point.clone(),
                    c.axis.clone(),
                    c.r2.clone(),
                ),
                Natural::Cone(c) => (Kind::Cone, c.vertex.clone(), c.axis.clone(), c.t2.clone()),
            }
        };
        let (pa, pb) = (parts(a), parts(b));
        let kinds = [pa.0, pb.0];
        let mut x: [Q; N] = std::array::from_fn(|_| Q::zero());
        let mut w: [Q; N] = std::array::from_fn(|_| Q::zero());
        let norm = |v: &[Q; 3]| v.iter().map(|c| c.abs()).max().unwrap_or_else(Q::zero);
        // the scene's length: the points' size and each radius (as the
        // power of two at or above it: exact)
        let mut size = norm(&pa.1).max(norm(&pb.1));
        for (k, _, _, s) in [&pa, &pb] {
            if *k != Kind::Cone {
                size = size.max(radius_bound(s));
            }
        }
        for (q, (_, p, ax, s)) in [pa, pb].into_iter().enumerate() {
            let base = q * PER;
            let na = norm(&ax);
            for k in 0..3 {
                x[base + k] = p[k].clone();
                w[base + k] = size.clone();
                x[base + 3 + k] = ax[k].clone();
                w[base + 3 + k] = na.clone();
            }
            w[base + 6] = s.abs();
            x[base + 6] = s;
        }
        // one power of two for lengths (points, and r2 as a squared
        // length), one per axis: the class and the metric do not change
        let mut big: Option<i64> = None;
        for q in 0..2 {
            let base = q * PER;
            for k in 0..3 {
                if !x[base + k].is_zero() {
                    big = big.max(Some(lg(&x[base + k])));
                }
            }
            if kinds[q] != Kind::Cone {
                big = big.max(Some(lg(&x[base + 6]) / 2));
            }
        }
        let kp = -big.unwrap_or(0);
        let mut m = [0.0; N];
        let mut r0 = [0.0; N];
        for q in 0..2 {
            let base = q * PER;
            let ka = -(0..3)
                .filter(|&k| !x[base + 3 + k].is_zero())
                .map(|k| lg(&x[base + 3 + k]))
                .max()
                .unwrap_or(0);
            for k in 0..3 {
                (m[base + k], r0[base + k]) = ball_of(&x[base + k], kp);
                (m[base + 3 + k], r0[base + 3 + k]) = ball_of(&x[base + 3 + k], ka);
            }
            let ks = if kinds[q] == Kind::Cone { 0 } else { 2 * kp };
            (m[base + 6], r0[base + 6]) = ball_of(&x[base + 6], ks);
        }
        let mut wup = [0.0; N];
        let (sm, sr) = ball_of(&w[0], kp);
        for q in 0..2 {
            let base = q * PER;
            for k in 0..3 {
                wup[base + k] = (sm.abs() + sr) * INFL;
            }
            let up = (0..3)
                .map(|k| m[base + 3 + k].abs() + r0[base + 3 + k])
                .fold(0.0, f64::max);
            for k in 0..3 {
                if !w[base + 3 + k].is_zero() {
                    wup[base + 3 + k] = up * INFL;
                }
            }
            wup[base + 6] = (m[base + 6].abs() + r0[base + 6]) * INFL;
        }
        Scene {
            kinds,
            x,
            w,
            m,
            r0,
            wup,
        }
    }

    /// The balls holding every input within relative distance `eps`.
    fn balls(&self, eps: f64) -> [QIn<BallR>; 2] {
        let ball = |i: usize| BallR {
            m: self.m[i],
            r: (self.r0[i] + eps * self.wup[i]) * INFL,
        };
        qin_pair(&self.kinds, ball)
    }

    /// True when the predicates decide `target` on every input within
    /// relative distance `eps`.
    fn proves(&self, eps: f64, target: &Counts) -> bool {
        decides(self.balls(eps), target)
    }

    /// [`Scene::proves`] by the mean-value form ([`Mv`]): slower (15
    /// balls a quantity), much tighter where the predicates cancel.
    fn proves_mv(&self, eps: f64, target: &Counts) -> bool {
        decides(self.mv_inputs(eps), target)
    }

    /// The mean-value inputs of the box of relative size `eps` (sets
    /// [`MV_WIDTH`]).
    fn mv_inputs(&self, eps: f64) -> [QIn<Mv>; 2] {
        let h: [f64; N] = std::array::from_fn(|i| eps * self.wup[i] * INFL);
        MV_WIDTH.with(|w| w.set(h));
        let mv = |i: usize| {
            let mut g = [ZERO; N];
            g[i] = BallR::int(1);
            Mv {
                c: BallR {
                    m: self.m[i],
                    r: self.r0[i],
                },
                b: BallR {
                    m: self.m[i],
                    r: (self.r0[i] + h[i]) * INFL,
                },
                g,
            }
        };
        qin_pair(&self.kinds, mv)
    }

    /// A member `cos θ·A − sin θ·B` of the pencil definite at the input
    /// itself, in the middle of the widest run of definite members among
    /// 64 angles (the most robust), as the pair `(sin θ, cos θ)` of
    /// doubles; `None` when no sampled member is definite.
    fn definite_member(&self) -> Option<(f64, f64)> {
        let [x, y] = self.balls(0.0);
        let (a, b) = (matrix(&x), matrix(&y));
        const K: usize = 64;
        let angle = |k: usize| std::f64::consts::PI * ((k as f64 + 0.5) / K as f64 - 0.5);
        let definite: Vec<bool> = (0..K)
            .map(|k| {
                let (n, d) = (
                    BallR::input(angle(k).sin(), 0),
                    BallR::input(angle(k).cos(), 0),
                );
                matches!(definite4(&member(&a, &b, &n, &d)), Some((true, _)))
            })
            .collect();
        // the longest run of definite members (θ and θ + π give opposite
        // members, so the half-turn sampled covers every member up to sign)
        let mut best: Option<(usize, usize)> = None;
        let mut k = 0;
        while k < K {
            if definite[k] {
                let start = k;
                while k < K && definite[k] {
                    k += 1;
                }
                if best.is_none_or(|(s, e)| e - s < k - start) {
                    best = Some((start, k));
                }
            } else {
                k += 1;
            }
        }
        let (s, e) = best?;
        let th = angle((s + e - 1) / 2);
        Some((th.sin(), th.cos()))
    }

    /// True when the member `(n, d)` is definite for every input within
    /// relative size `eps` (mean-value form): every such input is empty
    /// (a definite member has no real point).
    fn proves_empty(&self, eps: f64, (n, d): (f64, f64)) -> bool {
        let [x, y] = self.mv_inputs(eps);
        let (a, b) = (matrix(&x), matrix(&y));
        let (n, d) = (
            Mv::constant(BallR::input(n, 0)),
            Mv::constant(BallR::input(d, 0)),
        );
        matches!(definite4(&member(&a, &b, &n, &d)), Some((true, _)))
    }

    /// The input moved by `size·wᵢ` in the direction `dir` (signs), or
    /// `None` when that is not a valid pair.
    fn moved(&self, size: &Q, dir: &[i8; N]) -> Option<(Natural, Natural)> {
        let y: [Q; N] = std::array::from_fn(|i| match dir[i] {
            0 => self.x[i].clone(),
            d => &self.x[i] + size * &self.w[i] * Q::from_integer(BigInt::from(d)),
        });
        self.pair_of(&y)
    }

    /// The exact relative distance of the numbers `y` from the input
    /// (`None`: a number that may not move moved).
    fn distance_to(&self, y: &[Q; N]) -> Option<Q> {
        let mut worst = Q::zero();
        for i in 0..N {
            let dx = (&y[i] - &self.x[i]).abs();
            if self.w[i].is_zero() {
                if !dx.is_zero() {
                    return None;
                }
            } else {
                worst = worst.max(dx / &self.w[i]);
            }
        }
        Some(worst)
    }

    /// [`Scene::distance_to`] in doubles (for ordering candidates only).
    fn distance_estimate(&self, y: &[Q; N]) -> Option<f64> {
        let mut worst = 0.0f64;
        for i in 0..N {
            if y[i] == self.x[i] {
                continue;
            }
            let w = self.w[i].to_f64().filter(|w| *w > 0.0)?;
            let dx = (&y[i] - &self.x[i]).to_f64()?.abs();
            worst = worst.max(dx / w);
        }
        Some(worst)
    }

    /// The direction moving the two points toward each other (`sign` 1;
    /// apart for −1) coordinate by coordinate, the radii² and tan² growing
    /// (shrinking), the axes kept.
    fn approach(&self, sign: i8) -> [i8; N] {
        let mut d = [0i8; N];
        for q in 0..2 {
            let (b, o) = (q * PER, (1 - q) * PER);
            for k in 0..3 {
                d[b + k] = match self.x[o + k].cmp(&self.x[b + k]) {
                    std::cmp::Ordering::Greater => sign,
                    std::cmp::Ordering::Less => -sign,
                    std::cmp::Ordering::Equal => 0,
                };
            }
            d[b + 6] = sign;
        }
        d
    }

    /// Exact degenerate configurations next to the input, built by moving
    /// one quadric: its axis parallel to the other's (the same length),
    /// then its point onto the other's axis (coaxial); its axis moved
    /// along the common normal until the axes meet; a cone's vertex onto
    /// the other cone's; its parameter equal to the other's (same kind),
    /// alone and with the axes made coaxial; a sphere's centre onto the
    /// other's axis, or that axis through the centre.  A modeller's
    /// design intent is usually one of these, one rounding away.
    fn snaps(&self) -> Vec<[Q; N]> {
        let v = |x: &[Q; N], b: usize| -> V3 { [x[b].clone(), x[b + 1].clone(), x[b + 2].clone()] };
        let inf = |u: &V3| u.iter().map(|c| c.abs()).max().unwrap_or_else(Q::zero);
        // the foot of x on the line (p, a)
        let foot = |x: &V3, p: &V3, a: &V3| add(p, &scale(a, &(dot(&sub(x, p), a) / norm2(a))));
        let mut out = Vec::new();
        for q in 0..2 {
            let (bq, bo) = (q * PER, (1 - q) * PER);
            let (kq, ko) = (self.kinds[q], self.kinds[1 - q]);
            let (pq, aq, po, ao) = (
                v(&self.x, bq),
                v(&self.x, bq + 3),
                v(&self.x, bo),
                v(&self.x, bo + 3),
            );
            let with = |changes: &[(usize, &V3)], param: bool| -> [Q; N] {
                let mut y = self.x.clone();
                for (off, u) in changes {
                    for k in 0..3 {
                        y[bq + off + k] = u[k].clone();
                    }
                }
                if param {
                    y[bq + 6] = self.x[bo + 6].clone();
                }
                y
            };
            match (kq, ko) {
                (Kind::Sphere, Kind::Sphere) => {}
                (Kind::Sphere, _) => out.push(with(&[(0, &foot(&pq, &po, &ao))], false)),
                (_, Kind::Sphere) => {
                    let shift = sub(&po, &foot(&po, &pq, &aq));
                    out.push(with(&[(0, &add(&pq, &shift))], false));
                }
                _ => {
                    let mut k = inf(&aq) / inf(&ao);
                    if dot(&aq, &ao).is_negative() {
                        k = -k;
                    }
                    let par = scale(&ao, &k);
                    let on_axis = foot(&pq, &po, &ao);
                    out.push(with(&[(3, &par)], false));
                    out.push(with(&[(3, &par), (0, &on_axis)], false));
                    let n = cross(&aq, &ao);
                    if !is_zero(&n) {
                        let off = scale(&n, &(dot(&sub(&pq, &po), &n) / norm2(&n)));
                        out.push(with(&[(0, &sub(&pq, &off))], false));
                    }
                    if kq == Kind::Cone && ko == Kind::Cone {
                        out.push(with(&[(0, &po)], false));
                        out.push(with(&[(0, &po), (3, &par)], false));
                    }
                    if kq == ko {
                        out.push(with(&[], true));
                        out.push(with(&[(3, &par), (0, &on_axis)], true));
                    }
                }
            }
        }
        out
    }

    /// The pair of the numbers `y`, or `None` when they are not a valid
    /// pair.
    fn pair_of(&self, y: &[Q; N]) -> Option<(Natural, Natural)> {
        let one = |q: usize| -> Option<Natural> {
            let b = q * PER;
            let p = [y[b].clone(), y[b + 1].clone(), y[b + 2].clone()];
            let ax = [y[b + 3].clone(), y[b + 4].clone(), y[b + 5].clone()];
            let s = y[b + 6].clone();
            Some(match self.kinds[q] {
                Kind::Sphere => Natural::Sphere(Sphere::new(p, s).ok()?),
                Kind::Cylinder => Natural::Cylinder(Cylinder::new(p, ax, s).ok()?),
                Kind::Cone => Natural::Cone(Cone::new(p, ax, s).ok()?),
            })
        };
        Some((one(0)?, one(1)?))
    }
}

/// `1 + 2^-48`: radii rounded up (see `number::filter`).
const INFL: f64 = 1.0 + 1.0 / 281_474_976_710_656.0;

/// True when the predicates, run in a tier of enclosures, certify every
/// sign on their path and end at `target`.
fn decides<R: SignRing>([x, y]: [QIn<R>; 2], target: &Counts) -> bool {
    matches!(
        program(&x, &y),
        Some((Outcome::Counts(c, ..) | Outcome::Planar(c, ..), _)) if &c == target
    )
}

/// The pair's inputs in a ring, number `i` given by `v(i)`.
fn qin_pair<R: SignRing>(kinds: &[Kind; 2], v: impl Fn(usize) -> R) -> [QIn<R>; 2] {
    std::array::from_fn(|q| {
        let b = q * PER;
        QIn {
            kind: kinds[q],
            c: [v(b), v(b + 1), v(b + 2)],
            q: R::int(1),
            a: [v(b + 3), v(b + 4), v(b + 5)],
            pn: v(b + 6),
            pd: R::int(1),
        }
    })
}

/// The size `m/256 · 2^-e` of grid step `j` (`j = 4e + f`, `m` the
/// 8-bit rounding of `2^(8 − f/4)`): exact in `f64` and in Q.
fn grid(j: u32) -> f64 {
    const M: [f64; 4] = [256.0, 215.0, 181.0, 152.0];
    M[(j % 4) as usize] / 256.0 * 2f64.powi(-((j / 4) as i32))
}

/// A ball with first-order derivatives with respect to the 14 numbers:
/// every sign asked is recorded (value, derivatives) in [`TRACE`].
#[derive(Clone, Debug)]
struct Probe {
    b: BallR,
    g: [f64; N],
}

/// One sign of the path: the value's midpoint, its derivatives, the sign.
type Step = (f64, [f64; N], Option<i32>);

thread_local! {
    static TRACE: RefCell<Vec<Step>> = const { RefCell::new(Vec::new()) };
}

impl SignRing for Probe {
    fn from_z(z: &BigInt) -> Self {
        Probe {
            b: BallR::from_z(z),
            g: [0.0; N],
        }
    }
    fn int(v: i64) -> Self {
        Probe {
            b: BallR::int(v),
            g: [0.0; N],
        }
    }
    fn add(&self, o: &Self) -> Self {
        Probe {
            b: self.b.add(&o.b),
            g: std::array::from_fn(|i| self.g[i] + o.g[i]),
        }
    }
    fn sub(&self, o: &Self) -> Self {
        Probe {
            b: self.b.sub(&o.b),
            g: std::array::from_fn(|i| self.g[i] - o.g[i]),
        }
    }
    fn mul(&self, o: &Self) -> Self {
        Probe {
            b: self.b.mul(&o.b),
            g: std::array::from_fn(|i| self.g[i] * o.b.m + o.g[i] * self.b.m),
        }
    }
    fn neg(&self) -> Self {
        Probe {
            b: self.b.neg(),
            g: std::array::from_fn(|i| -self.g[i]),
        }
    }
    fn sign(&self) -> Option<i32> {
        let s = self.b.sign();
        TRACE.with(|t| t.borrow_mut().push((self.b.m, self.g, s)));
        s
    }
    fn approx(&self) -> f64 {
        self.b.m
    }
    fn exact(&self) -> Option<BigInt> {
        None
    }
}

/// The mean-value form (Moore): a quantity as a ball at the centre `c`
/// (the input itself), a ball `b` over the whole box, and balls `g` of its
/// 14 partial derivatives over the box.  For `y` in the box,
/// `P(y) = P(x) + ∇P(ξ)·(y − x)` with `ξ` on the segment, in the box, so
/// `P(y) ∈ c + Σ gᵢ·[−hᵢ, hᵢ]` (`hᵢ` the box's half-width in number `i`,
/// [`MV_WIDTH`]): a cancellation in `P` costs only in the second-order
/// term, where the plain ball `b` pays it at first order.  A sign is
/// certified when either enclosure certifies it.
#[derive(Clone, Debug)]
struct Mv {
    c: BallR,
    b: BallR,
    g: [BallR; N],
}

thread_local! {
    /// The half-widths `hᵢ = ε·wᵢ` of the box [`Mv`] runs on.
    static MV_WIDTH: std::cell::Cell<[f64; N]> = const { std::cell::Cell::new([0.0; N]) };
}

/// The exact zero ball.
const ZERO: BallR = BallR { m: 0.0, r: 0.0 };

impl Mv {
    fn constant(b: BallR) -> Mv {
        Mv {
            c: b,
            b,
            g: [ZERO; N],
        }
    }
}

impl SignRing for Mv {
    fn from_z(z: &BigInt) -> Self {
        Mv::constant(BallR::from_z(z))
    }
    fn int(v: i64) -> Self {
        Mv::constant(BallR::int(v))
    }
    fn add(&self, o: &Self) -> Self {
        Mv {
            c: self.c.add(&o.c),
            b: self.b.add(&o.b),
            g: std::array::from_fn(|i| self.g[i].add(&o.g[i])),
        }
    }
    fn sub(&self, o: &Self) -> Self {
        Mv {
            c: self.c.sub(&o.c),
            b: self.b.sub(&o.b),
            g: std::array::from_fn(|i| self.g[i].sub(&o.g[i])),
        }
    }
    fn mul(&self, o: &Self) -> Self {
        Mv {
            c: self.c.mul(&o.c),
            b: self.b.mul(&o.b),
            // the product rule, each factor enclosed over the box
            g: std::array::from_fn(|i| self.g[i].mul(&o.b).add(&self.b.mul(&o.g[i]))),
        }
    }
    fn neg(&self) -> Self {
        Mv {
            c: self.c.neg(),
            b: self.b.neg(),
            g: std::array::from_fn(|i| self.g[i].neg()),
        }
    }
    fn sign(&self) -> Option<i32> {
        if let Some(s) = self.b.sign() {
            return Some(s);
        }
        let h = MV_WIDTH.with(|w| w.get());
        let mut r = self.c.r;
        for i in 0..N {
            r += (self.g[i].m.abs() + self.g[i].r) * h[i];
        }
        // N + 1 sums and N products of non-negative terms: INFL² covers
        // their roundings (see number::filter)
        let r = r * INFL * INFL;
        let m = self.c.m;
        if m > r {
            Some(1)
        } else if m < -r {
            Some(-1)
        } else {
            None
        }
    }
    fn approx(&self) -> f64 {
        self.c.m
    }
    fn exact(&self) -> Option<BigInt> {
        None
    }
}

/// The signs on the path at relative size `eps`, each with its
/// derivatives (up to the first sign the balls cannot decide).
fn trace(scene: &Scene, eps: f64) -> Vec<Step> {
    let balls = scene.balls(eps);
    let probe = |i: usize| {
        let q = i / PER;
        let k = i % PER;
        let b = &balls[q];
        let ball = match k {
            0..=2 => b.c[k],
            3..=5 => b.a[k - 3],
            _ => b.pn,
        };
        let mut g = [0.0; N];
        g[i] = 1.0;
        Probe { b: ball, g }
    };
    let [x, y] = qin_pair(&scene.kinds, probe);
    TRACE.with(|t| t.borrow_mut().clear());
    let _ = program(&x, &y);
    TRACE.with(|t| std::mem::take(&mut *t.borrow_mut()))
}

/// `v` rounded up to 8 significant bits, exactly as a rational.
fn short_dyadic(v: f64) -> Q {
    let e = v.log2().floor() as i32 - 7;
    let m = (v / 2f64.powi(e)).ceil();
    let q = Q::from_integer(BigInt::from(m as i64));
    if e >= 0 {
        q * Q::from_integer(BigInt::one() << e as usize)
    } else {
        q / Q::from_integer(BigInt::one() << (-e) as usize)
    }
}

/// A fixed pseudo-random sign vector (a linear congruential sequence).
fn random_direction(seed: u64) -> [i8; N] {
    let mut s = seed
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    std::array::from_fn(|_| {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        if (s >> 33) & 1 == 1 { 1 } else { -1 }
    })
}

/// The referee of a pair whose exact class and counts are `target`.
pub(crate) fn referee(a: &Natural, b: &Natural, target: &Counts) -> Referee {
    let scene = Scene::new(a, b);
    // lo: the largest grid size the balls prove (bisection: a proof at a
    // size holds at every smaller one, the balls only shrink)
    let mut lo_j = None;
    let mut lo_reason = None;
    if scene.proves(grid(GRID_LAST), target) {
        let (mut proved, mut refused) = (GRID_LAST, 3u32);
        while proved - refused > 1 {
            crate::budget::check_now();
            let mid = (proved + refused) / 2;
            if scene.proves(grid(mid), target) {
                proved = mid;
            } else {
                refused = mid;
            }
        }
        lo_j = Some(proved);
    } else {
        lo_reason = Some(if scene.proves(0.0, target) {
            "the answer changes, or the predicates cannot tell, within relative size 2^-100 \
             (an exactly degenerate input: a tangency, parallel or meeting axes, a common vertex)"
        } else {
            "the predicates do not decide this input on balls (the complete route answers it): \
             nothing proved"
        });
    }
    let lo_f = lo_j.map_or(0.0, grid);
    let lo = Q::from_float(lo_f).unwrap_or_else(Q::zero);

    // hi: candidates from the path's signs at lo, then fixed directions
    let movable: [bool; N] = std::array::from_fn(|i| !scene.w[i].is_zero());
    let mut trials: Vec<(f64, [i8; N])> = Vec::new();
    for (m, g, sign) in trace(&scene, lo_f) {
        let slope: f64 = (0..N).map(|i| g[i].abs() * scene.wup[i]).sum();
        if !(slope > 0.0 && slope.is_finite() && m.is_finite()) {
            continue;
        }
        let t = m.abs() / slope;
        let toward: [i8; N] = std::array::from_fn(|i| {
            if !movable[i] || g[i] == 0.0 {
                0
            } else if (g[i] > 0.0) == (m > 0.0) {
                -1
            } else {
                1
            }
        });
        let away: [i8; N] = std::array::from_fn(|i| -toward[i]);
        // an undecided sign (its midpoint is rounding noise) or a zero:
        // both ways, at a size of its own
        let unknown = m == 0.0 || sign.is_none();
        let base = if t > 0.0 && !unknown {
            t
        } else {
            t.max(DEGENERATE_STEP)
        };
        for f in [1.25, 2.0, 4.0] {
            let size = (f * base).max(f * lo_f);
            trials.push((size, toward));
            if unknown {
                trials.push((size, away));
            }
        }
    }
    trials.sort_by(|p, q| p.0.total_cmp(&q.0));
    trials.dedup();
    trials.truncate(GRADIENT_TRIALS);
    let start = (1.25 * lo_f).max(DEGENERATE_STEP);
    let mut size = start;
    let mut seed = 0u64;
    let mut random = Vec::new();
    while size <= HI_MAX && random.len() < RANDOM_TRIALS {
        for _ in 0..2 {
            seed += 1;
            let d = random_direction(seed);
            random.push((
                size,
                std::array::from_fn(|i| if movable[i] { d[i] } else { 0 }),
            ));
        }
        size *= 16.0;
    }
    trials.extend(random);
    // the two quadrics pushed together (points toward each other, radii
    // and angles growing) or apart: where a gap closes or opens
    for (sign, extra) in [(1i8, 0), (-1i8, 1)] {
        let dir = scene.approach(sign);
        let mut size = start.max(1.0 / 1024.0) * 2f64.powi(extra);
        while size <= HI_MAX {
            trials.push((size, dir));
            size *= 4.0;
        }
    }
    // nothing proved: the input may sit on the boundary, where any small
    // move may change the answer — the small fixed directions first
    if lo_j.is_none() {
        trials.sort_by(|p, q| p.0.total_cmp(&q.0));
    }

    // the exact answer at size t along dir, when it differs
    let differs = |t: &Q, dir: &[i8; N]| -> Option<NearbyPair> {
        crate::budget::check_now();
        let (na, nb) = scene.moved(t, dir)?;
        let r = classify_counts(&Prepared::new(&na), &Prepared::new(&nb)).ok()?;
        (r.counts != *target && r.counts.class != Class::Undecided).then_some(NearbyPair {
            a: na,
            b: nb,
            counts: r.counts,
        })
    };
    let mut witness = None;
    for (size, dir) in trials {
        if size > HI_MAX {
            continue;
        }
        let t = short_dyadic(size);
        if t <= lo {
            continue;
        }
        if let Some(n) = differs(&t, &dir) {
            witness = Some((t, n, dir));
            break;
        }
    }
    // the exact degenerate configurations next to the input: a closer
    // witness than the first-order search finds when the boundary is of
    // higher codimension (coaxial: all of a cross product and an offset)
    // (ordered by a double estimate of their distance: the exact one, a
    // maximum of quotients of long rationals, only for the one kept)
    let mut snapped: Vec<(f64, [Q; N])> = scene
        .snaps()
        .into_iter()
        .filter_map(|y| {
            let d = scene.distance_estimate(&y)?;
            (d > lo_f && d <= HI_MAX).then_some((d, y))
        })
        .collect();
    snapped.sort_by(|p, q| p.0.total_cmp(&q.0));
    let mut snap_witness = None;
    for (d, y) in snapped {
        if witness
            .as_ref()
            .is_some_and(|(t, ..)| t.to_f64().is_some_and(|t| t < d * 0.5))
        {
            break;
        }
        crate::budget::check_now();
        let Some((na, nb)) = scene.pair_of(&y) else {
            continue;
        };
        let Some(d) = scene.distance_to(&y) else {
            continue;
        };
        if let Ok(r) = classify_counts(&Prepared::new(&na), &Prepared::new(&nb))
            && r.counts != *target
            && r.counts.class != Class::Undecided
        {
            snap_witness = Some((
                d,
                NearbyPair {
                    a: na,
                    b: nb,
                    counts: r.counts,
                },
            ));
            break;
        }
    }
    // a closer witness on the same ray: bisection over the grid between
    // lo (or t/64) and t (every candidate checked exactly)
    if let Some((t, _, dir)) = witness.as_ref().filter(|_| lo_j.is_some()) {
        let tf = t.to_f64().unwrap_or(HI_MAX);
        let mut far = (0..=GRID_LAST).find(|&j| grid(j) < tf);
        let near_floor = (tf / 64.0).max(lo_f);
        let mut near = (0..=GRID_LAST)
            .find(|&j| grid(j) <= near_floor)
            .unwrap_or(GRID_LAST);
        let mut best = None;
        while let Some(f) = far {
            if near <= f + 1 {
                break;
            }
            let mid = (f + near) / 2;
            let size = Q::from_float(grid(mid)).unwrap_or_else(Q::zero);
            if size > lo
                && let Some(n) = differs(&size, dir)
            {
                best = Some((size, n));
                far = Some(mid);
            } else {
                near = mid;
            }
        }
        if let Some((size, n)) = best {
            witness = Some((size, n, *dir));
        }
    }
    // lo again by the mean-value form, between the balls' lo and the
    // witness (nothing at or beyond hi can be proved): bisection
    let mut witness = witness.map(|(t, n, _)| (t, n));
    if let Some((d, n)) = snap_witness
        && witness.as_ref().is_none_or(|(t, _)| d < *t)
    {
        witness = Some((d, n));
    }
    let top = witness
        .as_ref()
        .and_then(|(t, _)| t.to_f64())
        .unwrap_or(HI_MAX * 2.0);
    // the largest grid size in (lower, top) where `proves` holds, given
    // that it holds at grid step `lower` (bisection)
    let widest = |lower: u32, proves: &dyn Fn(f64) -> bool| -> u32 {
        let mut refused = (0..lower).rev().find(|&j| grid(j) >= top).unwrap_or(0);
        let mut proved = lower;
        while proved - refused > 1 {
            crate::budget::check_now();
            let mid = (proved + refused) / 2;
            if proves(grid(mid)) {
                proved = mid;
            } else {
                refused = mid;
            }
        }
        proved
    };
    if let Some(lj) = lo_j {
        lo_j = Some(widest(lj, &|e| scene.proves_mv(e, target)));
    }
    // an empty answer also holds wherever one member of the pencil stays
    // definite (Finsler–Calabi), whatever path the predicates take there
    if target.class == Class::Empty
        && let Some(nd) = scene.definite_member()
        && scene.proves_empty(grid(GRID_LAST), nd)
    {
        let j = widest(GRID_LAST, &|e| scene.proves_empty(e, nd));
        if lo_j.is_none_or(|lj| j < lj) {
            lo_j = Some(j);
            lo_reason = None;
        }
    }
    let lo = lo_j.map_or_else(Q::zero, |j| Q::from_float(grid(j)).unwrap_or_else(Q::zero));
    let (hi, nearby, hi_reason) = match witness {
        Some((t, n)) => (Some(t), Some(n), None),
        None => (
            None,
            None,
            Some("no input with a different answer found up to relative size 1/2"),
        ),
    };
    Referee {
        lo,
        hi,
        nearby,
        lo_reason,
        hi_reason,
    }
}

/// The input moved by `fracᵢ·size·wᵢ` for each number (`|fracᵢ| ≤ 1`: a
/// point of the ball of relative size `size`), or `None` when that is not a
/// valid pair (tests: random inputs inside the proved ball).
#[cfg(test)]
pub(crate) fn within(
    a: &Natural,
    b: &Natural,
    size: &Q,
    frac: &[Q; N],
) -> Option<(Natural, Natural)> {
    let s = Scene::new(a, b);
    let mut moved = s.x.clone();
    for i in 0..N {
        moved[i] = &s.x[i] + &frac[i] * size * &s.w[i];
    }
    let one = Scene { x: moved, ..s };
    one.moved(&Q::zero(), &[0; N])
}

/// The exact relative distance of pair `(c, d)` from `(a, b)` in the
/// referee's metric (`None`: kinds differ, or a number that may not move
/// moved).
#[cfg(test)]
pub(crate) fn distance(a: &Natural, b: &Natural, c: &Natural, d: &Natural) -> Option<Q> {
    let (s, t) = (Scene::new(a, b), Scene::new(c, d));
    if s.kinds != t.kinds {
        return None;
    }
    s.distance_to(&t.x)
}

/// [`referee`] under the running budget, which it may exhaust without
/// taking the decided answer with it: the referee then proves nothing and
/// names the budget (nested runs keep the outer deadline and limits).
pub(crate) fn referee_within(a: &Natural, b: &Natural, target: &Counts) -> Referee {
    crate::budget::run(&crate::budget::Budget::unlimited(), || {
        referee(a, b, target)
    })
    .unwrap_or_else(|_| Referee {
        lo: Q::zero(),
        hi: None,
        nearby: None,
        lo_reason: Some("the compute budget ran out during the referee: nothing proved"),
        hi_reason: Some("the compute budget ran out during the referee"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::natural::ClassifyOptions;

    fn nat(s: &str) -> Natural {
        s.parse().unwrap()
    }

    fn judge(a: &str, b: &str) -> (Counts, Referee) {
        let (a, b) = (nat(a), nat(b));
        let r =
            crate::natural::classify_with(&a, &b, &ClassifyOptions::default().without_components())
                .unwrap();
        let f = referee(&a, &b, &r.counts);
        (r.counts, f)
    }

    /// The witness is exactly `hi` away and its exact answer differs.
    fn check_witness(a: &str, b: &str, counts: &Counts, f: &Referee) {
        let (a, b) = (nat(a), nat(b));
        let n = f.nearby().expect("a witness");
        let hi = f.hi().unwrap();
        assert!(f.lo() < hi, "lo {} < hi {}", f.lo(), hi);
        assert_eq!(distance(&a, &b, &n.a, &n.b).as_ref(), Some(hi));
        let r = crate::natural::classify_with(&n.a, &n.b, &ClassifyOptions::default()).unwrap();
        assert_eq!(r.counts, n.counts);
        assert_ne!(&r.counts, counts);
    }

    #[test]
    fn two_spheres_near_tangency() {
        let (a, b) = (
            "sphere center=0,0,0 radius2=1",
            "sphere center=3/2,0,0 radius2=1",
        );
        let (c, f) = judge(a, b);
        assert_eq!(c.class, Class::Conics);
        check_witness(a, b, &c, &f);
        // the tangency is at centre distance 2: about 1/4 relative (the
        // centre's x and both radii² move), so lo and hi straddle it
        let hi = f.hi().unwrap().to_f64().unwrap();
        let lo = f.lo().to_f64().unwrap();
        assert!(lo > 0.01 && hi < 0.5, "lo {lo} hi {hi}");
        assert!(hi / lo <= 10.0, "lo {lo} hi {hi}");
    }

    #[test]
    fn degenerate_inputs_have_lo_zero_and_a_tiny_witness() {
        for (a, b) in [
            // tangent spheres: a point
            (
                "sphere center=0,0,0 radius2=1",
                "sphere center=2,0,0 radius2=1",
            ),
            // coaxial cylinder and cone: circles
            (
                "cylinder point=0,0,0 axis=0,0,1 radius2=1",
                "cone vertex=0,0,5 axis=0,0,1 tan2=1",
            ),
            // parallel cylinders: lines
            (
                "cylinder point=0,0,0 axis=0,0,1 radius2=1",
                "cylinder point=1,0,0 axis=0,0,1 radius2=1",
            ),
        ] {
            let (c, f) = judge(a, b);
            assert!(f.lo().is_zero(), "{a} / {b}: lo {}", f.lo());
            assert!(f.lo_reason().is_some());
            check_witness(a, b, &c, &f);
            assert!(
                f.hi().unwrap() < &Q::new(1.into(), BigInt::from(1u64 << 30)),
                "{}",
                f.hi().unwrap()
            );
        }
    }

    #[test]
    fn a_skew_pair_far_from_degenerate_is_stable() {
        let (a, b) = (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,5 axis=0,1,1 radius2=1/4",
        );
        let (c, f) = judge(a, b);
        // empty, far from any other answer (the axes are 5/√2 apart, the
        // radii sum to 3/2); the balls' overestimation of the pencil's
        // discriminant keeps lo near 10^-4 (docs/BENCHMARKS.md, "The referee")
        assert!(f.lo() > &Q::new(1.into(), 100_000.into()), "lo {}", f.lo());
        if f.hi().is_some() {
            check_witness(a, b, &c, &f);
        }
    }

    #[test]
    fn a_referee_out_of_budget_keeps_the_answer() {
        let (a, b) = (
            nat("sphere center=0,0,0 radius2=1"),
            nat("sphere center=3/2,0,0 radius2=1"),
        );
        let target = Counts::new(Class::Conics, 1, 0, 0);
        let zero =
            crate::budget::Budget::default().with_time_limit(Some(std::time::Duration::ZERO));
        // the outer run (the classification's) survives the referee's exhaustion
        let f = crate::budget::run(&zero, || referee_within(&a, &b, &target)).unwrap();
        assert!(f.lo().is_zero() && f.hi().is_none());
        assert!(f.hi_reason().unwrap().contains("budget"));
        // with time, the same call referees
        let f = referee_within(&a, &b, &target);
        assert!(f.hi().is_some());
    }

    #[test]
    fn grid_steps_decrease() {
        for j in 0..GRID_LAST {
            assert!(grid(j + 1) < grid(j));
            assert_eq!(Q::from_float(grid(j)).unwrap().to_f64().unwrap(), grid(j));
        }
    }
}
