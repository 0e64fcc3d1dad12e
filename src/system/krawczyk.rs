//! Certified real zeros of a square system `f₁ = f₂ = f₃ = 0` in x, y, z
//! (integer polynomials): Newton's method in exact dyadic arithmetic and
//! the Krawczyk test in fixed-point interval arithmetic.
//!
//! Key idea (Krawczyk 1969, Moore 1977): for a box X with centre c, any
//! matrix Y and the interval Jacobian J(X),
//! `K(X) = c − Y·f(c) + (I − Y·J(X))·(X − c)`.  Every zero of f in X lies in
//! K(X); when K(X) lies in the interior of X, X holds exactly one zero (and
//! it lies in K(X) ∩ X).  Y — an approximate inverse of J(c), rounded to
//! dyadics — only decides whether the test succeeds, never its truth, and
//! every interval operation rounds outward, so a success is a proof.
//!
//! The systems here are the original polynomials (low degree, small
//! coefficients): their intervals stay tight at a few dozen bits, where
//! evaluating an implicit representation of the same point (a univariate
//! parametrisation with large coefficients) would lose hundreds of bits to
//! cancellation.

use crate::number::Q;
use crate::poly::ZMPoly;
use crate::poly::mpoly::{X, Y, Z};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// An interval `[lo, hi]·2^-k` with integer ends, `k` the scale of the
/// computation (fixed point: products round outward back to `2^-k`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fix {
    /// The lower end times `2^k`.
    pub lo: BigInt,
    /// The upper end times `2^k`.
    pub hi: BigInt,
}

impl Fix {
    /// The point `v·2^-k`.
    pub fn point(v: BigInt) -> Fix {
        Fix {
            lo: v.clone(),
            hi: v,
        }
    }

    /// `⌊q·2^k⌋` … `⌈q·2^k⌉`.
    #[cfg(test)]
    pub fn of_q(q: &Q, k: usize) -> Fix {
        let lo = (q.numer() << k).div_floor(q.denom());
        let hi = -((-q.numer()) << k).div_floor(q.denom());
        Fix { lo, hi }
    }

    /// The ends as rationals.
    pub fn to_q(&self, k: usize) -> (Q, Q) {
        let d = BigInt::one() << k;
        (
            Q::new(self.lo.clone(), d.clone()),
            Q::new(self.hi.clone(), d),
        )
    }

    fn add(&self, o: &Fix) -> Fix {
        Fix {
            lo: &self.lo + &o.lo,
            hi: &self.hi + &o.hi,
        }
    }

    fn neg(&self) -> Fix {
        Fix {
            lo: -&self.hi,
            hi: -&self.lo,
        }
    }

    fn sub(&self, o: &Fix) -> Fix {
        self.add(&o.neg())
    }

    /// The product, rounded outward to the scale `2^-k`.
    pub fn mul(&self, o: &Fix, k: usize) -> Fix {
        let c = [
            &self.lo * &o.lo,
            &self.lo * &o.hi,
            &self.hi * &o.lo,
            &self.hi * &o.hi,
        ];
        let lo = c.iter().min().expect("four").clone();
        let hi = c.iter().max().expect("four").clone();
        Fix {
            lo: lo >> k,
            hi: -((-hi) >> k),
        }
    }

    /// Times an integer (exact).
    fn scale(&self, c: &BigInt) -> Fix {
        if c.is_negative() {
            Fix {
                lo: c * &self.hi,
                hi: c * &self.lo,
            }
        } else {
            Fix {
                lo: c * &self.lo,
                hi: c * &self.hi,
            }
        }
    }

    /// The sign when it is the same on the whole interval (0 otherwise).
    pub fn sign(&self) -> i32 {
        if self.lo.is_positive() {
            1
        } else if self.hi.is_negative() {
            -1
        } else {
            0
        }
    }

    fn contains_zero(&self) -> bool {
        self.sign() == 0
    }
}

/// `p` on a box of `Fix` intervals at scale `2^-k` (an enclosure of its
/// range: monomials from cached powers, products rounded outward).
pub fn eval_box(p: &ZMPoly, bx: &[Fix; 3], k: usize) -> Fix {
    eval_boxes(&[p], bx, k).pop().expect("one polynomial")
}

/// [`eval_box`] for several polynomials on one box (e.g. a system and its
/// Jacobian): the powers of the coordinates and each monomial's product are
/// computed once and shared, so the enclosures are those of [`eval_box`],
/// for a fraction of the products.
pub fn eval_boxes(ps: &[&ZMPoly], bx: &[Fix; 3], k: usize) -> Vec<Fix> {
    let d = ps
        .iter()
        .map(|p| p.total_degree().unwrap_or(0) as usize)
        .max()
        .unwrap_or(0);
    let one = Fix::point(BigInt::one() << k);
    let pows: Vec<Vec<Fix>> = bx
        .iter()
        .map(|b| {
            let mut v = vec![one.clone(), b.clone()];
            for e in 2..=d.max(1) {
                let next = if e % 2 == 0 {
                    let h = &v[e / 2];
                    let sq = h.mul(h, k);
                    // an even power is ≥ 0
                    Fix {
                        lo: if h.contains_zero() {
                            BigInt::zero()
                        } else {
                            sq.lo
                        },
                        hi: sq.hi,
                    }
                } else {
                    v[e - 1].mul(b, k)
                };
                v.push(next);
            }
            v
        })
        .collect();
    let mut monos: std::collections::HashMap<[u32; 3], Fix> = std::collections::HashMap::new();
    ps.iter()
        .map(|p| {
            let mut acc = Fix::point(BigInt::zero());
            for (ex, c) in p.terms() {
                let e = [ex[X], ex[Y], ex[Z]];
                let t = monos.entry(e).or_insert_with(|| {
                    pows[0][e[0] as usize]
                        .mul(&pows[1][e[1] as usize], k)
                        .mul(&pows[2][e[2] as usize], k)
                });
                acc = acc.add(&t.scale(c));
            }
            acc
        })
        .collect()
}

/// A square system with its Jacobian.
#[derive(Clone, Debug)]
pub struct System {
    f: [ZMPoly; 3],
    jac: [[ZMPoly; 3]; 3],
}

/// A point with dyadic coordinates `m_i / 2^k` (a common scale).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dyadic3 {
    /// The numerators.
    pub m: [BigInt; 3],
    /// The scale.
    pub k: usize,
}

impl Dyadic3 {
    /// `⌊x_i·2^k⌋ / 2^k`.
    #[cfg(test)]
    pub fn floor_of(x: &[Q; 3], k: usize) -> Dyadic3 {
        Dyadic3 {
            m: std::array::from_fn(|i| (x[i].numer() << k).div_floor(x[i].denom())),
            k,
        }
    }

    /// `⌊num_i·2^k / den_i⌋ / 2^k` (integers, no rational arithmetic).
    pub fn floor_ratio(num: &[BigInt; 3], den: &[BigInt; 3], k: usize) -> Dyadic3 {
        Dyadic3 {
            m: std::array::from_fn(|i| {
                let (mut n, mut d) = (num[i].clone(), den[i].clone());
                if d.is_negative() {
                    n = -n;
                    d = -d;
                }
                (n << k).div_floor(&d)
            }),
            k,
        }
    }

    /// The same point at the scale `k2` (rounded down when coarser).
    fn at_scale(&self, k2: usize) -> [BigInt; 3] {
        std::array::from_fn(|i| {
            if k2 >= self.k {
                &self.m[i] << (k2 - self.k)
            } else {
                &self.m[i] >> (self.k - k2)
            }
        })
    }

    /// The bit size of the largest coordinate's integer part.
    fn magnitude(&self) -> usize {
        self.m
            .iter()
            .map(|m| m.bits() as usize)
            .max()
            .unwrap_or(0)
            .saturating_sub(self.k)
    }
}

/// A box `c ± r` (per coordinate) at scale `2^-k` holding exactly one zero.
#[derive(Clone, Debug)]
pub struct ZeroBox {
    /// The enclosure of the zero (K(X) ∩ X), per coordinate.
    pub enclosure: [Fix; 3],
    /// The scale.
    pub k: usize,
}

impl ZeroBox {
    /// The midpoint of the enclosure (dyadic).
    pub fn center(&self) -> Dyadic3 {
        Dyadic3 {
            m: std::array::from_fn(|i| &self.enclosure[i].lo + &self.enclosure[i].hi),
            k: self.k + 1,
        }
    }

    /// True when the two boxes are disjoint (some coordinate separates).
    pub fn disjoint(&self, o: &ZeroBox) -> bool {
        let k = self.k.max(o.k);
        (0..3).any(|i| {
            let (a, b) = (
                self.enclosure[i].clone().rescale(self.k, k),
                o.enclosure[i].clone().rescale(o.k, k),
            );
            a.hi < b.lo || b.hi < a.lo
        })
    }
}

impl Fix {
    /// The same interval at a finer scale `k2 ≥ k` (exact).
    fn rescale(self, k: usize, k2: usize) -> Fix {
        Fix {
            lo: self.lo << (k2 - k),
            hi: self.hi << (k2 - k),
        }
    }
}

/// `⌊n·2^e / d⌋` for `d ≠ 0` (e may be negative: then `⌊n / (d·2^-e)⌋`).
fn floor_scaled(n: &BigInt, d: &BigInt, e: i64) -> BigInt {
    let (n, d) = if d.is_negative() {
        (-n, -d)
    } else {
        (n.clone(), d.clone())
    };
    if e >= 0 {
        (n << e as usize).div_floor(&d)
    } else {
        n.div_floor(&(d << (-e) as usize))
    }
}

impl System {
    /// The system `f` (three polynomials in x, y, z).  Each equation is
    /// multiplied by a power of two that brings its largest coefficient to
    /// the size of the largest of all (same zeros): the rows of the
    /// Jacobian are then of comparable size, and the approximate inverse,
    /// kept to a number of bits relative to its largest entry, loses none
    /// of its columns (with one equation of 3-bit and two of 300-bit
    /// coefficients it otherwise would, and the test would fail).
    pub fn new(f: [ZMPoly; 3]) -> System {
        let bits = f
            .clone()
            .map(|p| p.terms().iter().map(|(_, c)| c.bits()).max().unwrap_or(0));
        let top = bits.iter().copied().max().unwrap_or(0);
        let f: [ZMPoly; 3] = std::array::from_fn(|i| {
            let sh = (top - bits[i]) as usize;
            if sh == 0 {
                return f[i].clone();
            }
            f[i].scale(&(BigInt::one() << sh))
        });
        let jac = std::array::from_fn(|i| std::array::from_fn(|j| f[i].derivative([X, Y, Z][j])));
        System { f, jac }
    }

    /// The equations and the Jacobian (for the float filter).
    pub(crate) fn parts(&self) -> (&[ZMPoly; 3], &[[ZMPoly; 3]; 3]) {
        (&self.f, &self.jac)
    }

    fn degrees(&self) -> [usize; 3] {
        std::array::from_fn(|i| self.f[i].total_degree().unwrap_or(0) as usize)
    }

    /// The values and the Jacobian at the dyadic point `m / 2^k`, exactly,
    /// as integers: `f_i·2^(k·d_i)` and `∂_j f_i·2^(k·(d_i − 1))` (rows
    /// scaled by powers of two, so no rational arithmetic is needed).
    fn scaled_at(&self, x: &Dyadic3) -> ([BigInt; 3], [[BigInt; 3]; 3]) {
        let (m, k) = (&x.m, x.k);
        let degs = self.degrees();
        let top = degs.iter().copied().max().unwrap_or(0);
        // powers m_v^e (e ≤ top) and monomials m^α·2^(k(top − |α|)), each
        // computed once: every term is then one product and a shift
        let pw: Vec<Vec<BigInt>> = m
            .iter()
            .map(|mv| {
                let mut v = vec![BigInt::one()];
                for e in 1..=top {
                    let next = &v[e - 1] * mv;
                    v.push(next);
                }
                v
            })
            .collect();
        let mut monos: std::collections::HashMap<[u32; 3], BigInt> =
            std::collections::HashMap::new();
        let mut mono = |ex: [u32; 3]| -> BigInt {
            monos
                .entry(ex)
                .or_insert_with(|| {
                    &pw[0][ex[0] as usize] * &pw[1][ex[1] as usize] * &pw[2][ex[2] as usize]
                })
                .clone()
        };
        let mut ev = |p: &ZMPoly, d: usize| -> BigInt {
            let mut acc = BigInt::zero();
            for (ex, c) in p.terms() {
                let deg = (ex[X] + ex[Y] + ex[Z]) as usize;
                let t = c * mono([ex[X], ex[Y], ex[Z]]);
                acc += t << (k * (d - deg));
            }
            acc
        };
        let f = std::array::from_fn(|i| ev(&self.f[i], degs[i]));
        let j = std::array::from_fn(|i| {
            std::array::from_fn(|l| ev(&self.jac[i][l], degs[i].saturating_sub(1)))
        });
        (f, j)
    }

    /// Newton's step and an approximate inverse of the Jacobian at the
    /// dyadic point `x`: `(x − J⁻¹f, Y)`, the step rounded to scale
    /// `2^-bits` and Y to about `bits` significant bits (`None` when the
    /// Jacobian is singular there).
    fn step(&self, x: &Dyadic3, bits: usize) -> Option<(Dyadic3, [[Fix; 3]; 3], usize)> {
        let (f, j) = self.scaled_at(x);
        let k = x.k;
        // J = D⁻¹·J̃, D = diag(2^(k(d_i − 1))); f = E⁻¹·f̃, E = diag(2^(k d_i)):
        // J⁻¹f = adj(J̃)·f̃ / (det·2^k) and J⁻¹ = adj(J̃)·D / det
        let cof = |r: usize, c: usize| -> BigInt {
            let rs: Vec<usize> = (0..3).filter(|&t| t != r).collect();
            let cs: Vec<usize> = (0..3).filter(|&t| t != c).collect();
            let v = &j[rs[0]][cs[0]] * &j[rs[1]][cs[1]] - &j[rs[0]][cs[1]] * &j[rs[1]][cs[0]];
            if (r + c).is_multiple_of(2) { v } else { -v }
        };
        let adj: [[BigInt; 3]; 3] = std::array::from_fn(|a| std::array::from_fn(|b| cof(b, a)));
        let det = &j[0][0] * &adj[0][0] + &j[0][1] * &adj[1][0] + &j[0][2] * &adj[2][0];
        if det.is_zero() {
            return None;
        }
        let xb = x.at_scale(bits);
        let next = Dyadic3 {
            m: std::array::from_fn(|i| {
                let mut num = BigInt::zero();
                for l in 0..3 {
                    num += &adj[i][l] * &f[l];
                }
                // x_i − num/(det·2^k) at scale 2^-bits
                &xb[i] - floor_scaled(&num, &det, bits as i64 - k as i64)
            }),
            k: bits,
        };
        // Y at the scale that keeps `bits` significant bits of its largest
        // entry
        let degs = self.degrees();
        let num: [[BigInt; 3]; 3] = std::array::from_fn(|a| {
            std::array::from_fn(|b| &adj[a][b] << (k * degs[b].saturating_sub(1)))
        });
        let top = num.iter().flatten().map(|v| v.bits()).max().unwrap_or(0) as i64;
        let ky = (bits as i64 - (top - det.bits() as i64)).max(0) as usize;
        let y = std::array::from_fn(|a| {
            std::array::from_fn(|b| Fix::point(floor_scaled(&num[a][b], &det, ky as i64)))
        });
        Some((next, y, ky))
    }

    /// The Krawczyk test on the box `c ± r` (each coordinate) at scale
    /// `2^-k`, with the preconditioner `y` at scale `2^-ky`: the box with
    /// the enclosure `K(X) ∩ X` when `K(X)` lies in the interior of X
    /// (exactly one zero in X), `None` otherwise.
    fn krawczyk(
        &self,
        c: &Dyadic3,
        r: &BigInt,
        y: &[[Fix; 3]; 3],
        ky: usize,
        k: usize,
    ) -> Option<ZeroBox> {
        let cf = c.at_scale(k);
        let xb: [Fix; 3] = std::array::from_fn(|i| Fix {
            lo: &cf[i] - r,
            hi: &cf[i] + r,
        });
        let cb: [Fix; 3] = std::array::from_fn(|i| Fix::point(cf[i].clone()));
        let fc = eval_boxes(&[&self.f[0], &self.f[1], &self.f[2]], &cb, k);
        let jac: Vec<&ZMPoly> = self.jac.iter().flatten().collect();
        let jv = eval_boxes(&jac, &xb, k);
        let jx: [[Fix; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| jv[3 * i + j].clone()));
        let dev = Fix {
            lo: -r.clone(),
            hi: r.clone(),
        };
        let mut out: [Fix; 3] = std::array::from_fn(|_| Fix::point(BigInt::zero()));
        for i in 0..3 {
            // c − Y·f(c)   (Y at scale ky: y·v is at scale k + ky, shift back)
            let mut ki = cb[i].clone();
            for j in 0..3 {
                ki = ki.sub(&y[i][j].mul(&fc[j], ky));
            }
            // (I − Y·J(X))_{il} · (X − c)_l
            for l in 0..3 {
                let mut m = if i == l {
                    Fix::point(BigInt::one() << k)
                } else {
                    Fix::point(BigInt::zero())
                };
                for j in 0..3 {
                    m = m.sub(&y[i][j].mul(&jx[j][l], ky));
                }
                ki = ki.add(&m.mul(&dev, k));
            }
            if !(ki.lo > xb[i].lo && ki.hi < xb[i].hi) {
                return None;
            }
            out[i] = ki;
        }
        Some(ZeroBox { enclosure: out, k })
    }

    /// A certified box around the zero near `x`, its half-width about
    /// `2^-bits` relative to the point: Newton's iteration to about `bits`
    /// bits, then the Krawczyk test on radii growing from there.  `None`
    /// when the test fails (no zero near `x`, a singular Jacobian, or a
    /// zero too ill-conditioned for `bits`).
    pub fn certify(&self, x: &Dyadic3, bits: usize) -> Option<ZeroBox> {
        let k = bits + 16 + x.magnitude();
        let mut p = Dyadic3 {
            m: x.at_scale(k),
            k,
        };
        // Newton doubles the correct bits per step: one step after a start
        // good to about `bits`/2 bits, more when the test then fails
        let mut steps = 0;
        for round in 0..4 {
            crate::budget::check();
            let (next, y, ky) = self.step(&p, k)?;
            p = next;
            steps += 1;
            if round == 0 && steps < 1 {
                continue;
            }
            // radii 2^(mag − bits + 4) (absolute, at scale 2^-k), then ×2^8
            let mut e = (k + x.magnitude() + 4).saturating_sub(bits);
            for _ in 0..3 {
                let r = BigInt::one() << e;
                if let Some(b) = self.krawczyk(&p, &r, &y, ky, k) {
                    return Some(b);
                }
                e += 8;
            }
        }
        None
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::poly::parse_poly;

    /// The system of three polynomials given as text.
    pub(crate) fn sys(f: [&str; 3]) -> System {
        System::new(f.map(|s| parse_poly(s).unwrap().to_primitive_z().0))
    }

    /// `n/d`.
    pub(crate) fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }

    /// A box is certified around a true zero, contains it, and a point far
    /// from any zero is not certified.
    #[test]
    fn certifies_the_zero_it_should() {
        // zeros (±√2, 1, ±√2 + 1)
        let s = sys(["x^2 - 2", "y - 1", "z - x - 1"]);
        let b = s
            .certify(
                &Dyadic3::floor_of(&[q(141, 100), q(1, 1), q(241, 100)], 30),
                60,
            )
            .unwrap();
        let (lo, hi) = b.enclosure[0].to_q(b.k);
        // √2 ∈ [lo, hi]: lo² ≤ 2 ≤ hi², and the box is narrow
        assert!(&lo * &lo <= q(2, 1) && &hi * &hi >= q(2, 1));
        assert!(&hi - &lo < q(1, 1 << 40));
        let (zl, zh) = b.enclosure[2].to_q(b.k);
        assert!(zl < q(242, 100) && zh > q(241, 100));
        // no zero near the origin: Newton goes away or the test fails there
        let far = s.certify(&Dyadic3::floor_of(&[q(0, 1), q(5, 1), q(0, 1)], 30), 60);
        if let Some(b2) = far {
            // it may converge to a genuine zero: then it must be one of them
            let (l, h) = b2.enclosure[0].to_q(b2.k);
            assert!(&l * &l <= q(2, 1) && &h * &h >= q(2, 1));
        }
        // two zeros give disjoint boxes
        let c = s
            .certify(
                &Dyadic3::floor_of(&[q(-141, 100), q(1, 1), q(-41, 100)], 30),
                60,
            )
            .unwrap();
        assert!(b.disjoint(&c));
    }

    /// Equations of very different coefficient sizes (one with 3-bit, two
    /// with 300-bit coefficients, as E against a big-coefficient S) are
    /// certified as well as the balanced system with the same zeros.
    #[test]
    fn unbalanced_rows_are_certified() {
        let big = BigInt::one() << 300usize;
        let scaled = |t: &str| {
            parse_poly(t)
                .unwrap()
                .to_primitive_z()
                .0
                .scale(&(&big + BigInt::from(7)))
        };
        let plain = |t: &str| parse_poly(t).unwrap().to_primitive_z().0;
        let eqs = ["x^2 + y^2 + z^2 - 4", "x*y - 1", "z - x + y"];
        let start = Dyadic3::floor_of(&[q(1618, 1000), q(618, 1000), q(1, 1)], 30);
        let balanced = System::new(eqs.map(plain));
        let b = balanced.certify(&start, 64).expect("balanced system");
        let unbalanced = System::new([plain(eqs[0]), scaled(eqs[1]), scaled(eqs[2])]);
        let c = unbalanced.certify(&start, 64).expect("unbalanced system");
        // the same zero: the enclosures overlap in every coordinate
        for i in 0..3 {
            let (l1, h1) = b.enclosure[i].to_q(b.k);
            let (l2, h2) = c.enclosure[i].to_q(c.k);
            assert!(l1 <= h2 && l2 <= h1, "coordinate {i}");
            assert!(&h2 - &l2 < q(1, 1 << 40));
        }
    }

    /// The enclosure of a polynomial on a box contains its values there.
    #[test]
    fn shared_monomials_give_the_same_enclosures() {
        // a system and its Jacobian share monomials (x·y, z², …)
        let ps: Vec<ZMPoly> = [
            "x^3 - 2*x*y + z^2 - 3",
            "x*y + z^2 + 1",
            "3*x^2 - 2*y",
            "x^3",
            "7",
        ]
        .iter()
        .map(|t| parse_poly(t).unwrap().to_primitive_z().0)
        .collect();
        let k = 24;
        let bx = [
            Fix {
                lo: BigInt::from(-9_000_000),
                hi: BigInt::from(-8_000_000),
            },
            Fix {
                lo: BigInt::from(-100),
                hi: BigInt::from(12_000_000),
            },
            Fix::point(BigInt::from(5_000_000)),
        ];
        let refs: Vec<&ZMPoly> = ps.iter().collect();
        let shared = eval_boxes(&refs, &bx, k);
        assert_eq!(shared.len(), ps.len());
        for (p, e) in ps.iter().zip(&shared) {
            let alone = eval_box(p, &bx, k);
            assert_eq!((&e.lo, &e.hi), (&alone.lo, &alone.hi), "{p:?}");
        }
    }

    #[test]
    fn eval_box_encloses() {
        let p = parse_poly("x^3 - 2*x*y + z^2 - 3")
            .unwrap()
            .to_primitive_z()
            .0;
        let k = 20;
        let bx = [
            Fix::of_q(&q(-1, 2), k),
            Fix::of_q(&q(3, 4), k),
            Fix::of_q(&q(5, 3), k),
        ];
        // widen to a box and check the corners
        let wide: [Fix; 3] = std::array::from_fn(|i| Fix {
            lo: &bx[i].lo - (BigInt::one() << 10),
            hi: &bx[i].hi + (BigInt::one() << 10),
        });
        let e = eval_box(&p, &wide, k);
        for corner in 0..8 {
            let pt: [Q; 3] = std::array::from_fn(|i| {
                let v = if corner >> i & 1 == 1 {
                    &wide[i].hi
                } else {
                    &wide[i].lo
                };
                crate::number::dyadic(v.clone(), k)
            });
            let mut full: [Q; crate::poly::mpoly::NVARS] = std::array::from_fn(|_| Q::zero());
            full[..3].clone_from_slice(&pt);
            let v = p.to_q().eval(&full);
            let (lo, hi) = e.to_q(k);
            assert!(lo <= v && v <= hi);
        }
    }
}
