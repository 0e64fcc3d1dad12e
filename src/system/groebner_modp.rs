//! Gröbner bases modulo a word-size prime by F4-style linear algebra
//! (Faugère 1999): polynomials in x, y, z over `F_p` (`p < 2^31`), grevlex
//! with x > y > z, the normal selection strategy by sugar degree, the
//! Gebauer–Möller criteria, and Macaulay-like matrices reduced with delayed
//! modular reduction.  Also normal forms, standard monomials and the
//! multiplication matrices of the quotient `F_p[x, y, z]/I_p`.
//!
//! Key idea: at each step, all critical pairs of the smallest sugar degree
//! are reduced together.  Their two halves `(lcm/lm(f))·f`, `(lcm/lm(g))·g`
//! become rows of one matrix; *symbolic preprocessing* adds a reducer
//! `m·h` (h in the basis) for every other monomial divisible by a leading
//! monomial; one half per leading monomial is a pivot row, the others are
//! reduced by the pivots (a dense accumulator per row, products summed in
//! `u64` below `p²`, one reduction per column), and the reduced rows are
//! brought to reduced row echelon form: their non-zero rows are the new
//! basis elements.  Every computed polynomial is a combination of the input
//! polynomials modulo p — which is all the completeness argument of
//! `roots::modrur` needs (see docs/maths.md).

use crate::number::prime31::Fp;

/// A monomial `x^a y^b z^c`, packed as `a | b << 8 | c << 16 | (a+b+c) << 24`
/// (exponents and degree below 128, so products never carry).
pub type Mono = u32;
/// A polynomial modulo p: terms by decreasing monomial (grevlex), non-zero
/// coefficients in `[1, p)`.
pub type ModPoly = Vec<(Mono, u32)>;

/// The largest total degree handled (exponents and degrees stay below 128).
pub const MAX_DEGREE: u32 = 120;

/// `x^a y^b z^c`.
#[inline]
pub fn mono(a: u32, b: u32, c: u32) -> Mono {
    a | (b << 8) | (c << 16) | ((a + b + c) << 24)
}

/// The exponents `[a, b, c]`.
#[inline]
pub fn exps(m: Mono) -> [u32; 3] {
    [m & 0xff, (m >> 8) & 0xff, (m >> 16) & 0xff]
}

/// Total degree.
#[inline]
pub fn degree(m: Mono) -> u32 {
    m >> 24
}

#[inline]
fn divides(a: Mono, b: Mono) -> bool {
    (a & 0xff) <= (b & 0xff) && (a & 0xff00) <= (b & 0xff00) && (a & 0xff_0000) <= (b & 0xff_0000)
}

#[inline]
fn lcm(a: Mono, b: Mono) -> Mono {
    let [a0, a1, a2] = exps(a);
    let [b0, b1, b2] = exps(b);
    mono(a0.max(b0), a1.max(b1), a2.max(b2))
}

#[inline]
fn coprime(a: Mono, b: Mono) -> bool {
    let [a0, a1, a2] = exps(a);
    let [b0, b1, b2] = exps(b);
    a0.min(b0) == 0 && a1.min(b1) == 0 && a2.min(b2) == 0
}

/// The position of `m` in grevlex (x > y > z) among all monomials, from 0
/// for 1: `rank(a) < rank(b)` iff `a < b`.  With `k` the degree, the
/// monomials of lower degree come first (`C(k+2, 3)` of them); within degree
/// `k` a smaller exponent of z, then of y, means a larger monomial.
#[inline]
pub fn rank(m: Mono) -> usize {
    let [_, y, z] = exps(m);
    let k = degree(m) as u8;
    // j = k − z ≤ k < 256: both lookups are in range (no bounds checks)
    let j = k - z as u8;
    TETRAHEDRAL[k as usize] + TRIANGULAR[j as usize] + (j as usize - y as usize)
}

/// `k(k + 1)(k + 2)/6` for `k < 256`: the monomials of degree below k.
const TETRAHEDRAL: [usize; 256] = {
    let mut t = [0usize; 256];
    let mut k = 0;
    while k < 256 {
        t[k] = k * (k + 1) * (k + 2) / 6;
        k += 1;
    }
    t
};

/// `j(j + 1)/2` for `j < 256`.
const TRIANGULAR: [usize; 256] = {
    let mut t = [0usize; 256];
    let mut j = 0;
    while j < 256 {
        t[j] = j * (j + 1) / 2;
        j += 1;
    }
    t
};

/// The number of monomials of degree at most `k` (one more than the
/// largest rank among them).
#[inline]
fn ranks_up_to(k: u32) -> usize {
    let k = k as usize + 1;
    k * (k + 1) * (k + 2) / 6
}

/// Sorts terms decreasingly and drops zero coefficients.
pub fn normalize(p: &mut ModPoly) {
    p.retain(|t| t.1 != 0);
    p.sort_by_key(|t| std::cmp::Reverse(rank(t.0)));
}

/// Makes a non-zero polynomial monic.
fn make_monic(fp: &Fp, p: &mut ModPoly) {
    let c = p[0].1 as u64;
    if c != 1 {
        let inv = fp.inv(c).expect("non-zero leading coefficient");
        for t in p.iter_mut() {
            t.1 = fp.mul(t.1 as u64, inv) as u32;
        }
    }
}

/// Sparse rows of a Macaulay matrix: `(column, coefficient)`, columns
/// increasing (monomials decreasing).
type Row = Vec<(u32, u32)>;

/// A Macaulay matrix under construction: the rows `m·f` and the monomials
/// they involve, indexed by [`rank`].
struct Symbolic<'a> {
    polys: &'a [ModPoly],
    /// `(multiplier, index into polys)` per row.
    rows: Vec<(Mono, usize)>,
    /// Per rank: the monomial + 1, or 0 when absent.
    present: Vec<u32>,
    /// Per rank: the pivot row + 1 (a row whose leading monomial it is).
    pivot: Vec<u32>,
}

impl<'a> Symbolic<'a> {
    fn new(polys: &'a [ModPoly], max_degree: u32) -> Self {
        let n = ranks_up_to(max_degree);
        crate::budget::check_size("Macaulay matrix columns", n, 0);
        Symbolic {
            polys,
            rows: Vec::new(),
            present: vec![0; n],
            pivot: vec![0; n],
        }
    }

    /// Adds the row `m·polys[i]`; with `can_pivot` it becomes the pivot of
    /// its leading monomial when that has none yet.  Returns true for a
    /// pivot row.
    fn add_row(&mut self, m: Mono, i: usize, can_pivot: bool) -> bool {
        let r = self.rows.len();
        self.rows.push((m, i));
        for &(t, _) in &self.polys[i] {
            let mt = m + t;
            self.present[rank(mt)] = mt + 1;
        }
        let lead = rank(m + self.polys[i][0].0);
        if can_pivot && self.pivot[lead] == 0 {
            self.pivot[lead] = r as u32 + 1;
            true
        } else {
            false
        }
    }

    /// Symbolic preprocessing: a reducer for every monomial divisible by a
    /// leading monomial of `reducers` (indices into polys).
    fn preprocess(&mut self, reducers: &[usize]) {
        for r in (0..self.present.len()).rev() {
            let m = self.present[r];
            if m == 0 || self.pivot[r] != 0 {
                continue;
            }
            crate::budget::check();
            let m = m - 1;
            if let Some(&g) = reducers.iter().find(|&&g| divides(self.polys[g][0].0, m)) {
                self.add_row(m - self.polys[g][0].0, g, true);
            }
        }
    }

    /// The columns (present monomials, decreasing), the rank → column map,
    /// and the rows as sparse vectors.
    fn build(&self) -> Matrix {
        let mut col_of = vec![u32::MAX; self.present.len()];
        let mut cols = Vec::new();
        for r in (0..self.present.len()).rev() {
            if self.present[r] != 0 {
                col_of[r] = cols.len() as u32;
                cols.push(self.present[r] - 1);
            }
        }
        let rows: Vec<Row> = self
            .rows
            .iter()
            .map(|&(m, i)| {
                self.polys[i]
                    .iter()
                    .map(|&(t, c)| (col_of[rank(m + t)], c))
                    .collect()
            })
            .collect();
        let mut pivot_of_col = vec![u32::MAX; cols.len()];
        for (r, &pv) in self.pivot.iter().enumerate() {
            if pv != 0 {
                pivot_of_col[col_of[r] as usize] = pv - 1;
            }
        }
        Matrix {
            cols,
            rows,
            pivot_of_col,
        }
    }
}

struct Matrix {
    /// Monomial of each column (decreasing).
    cols: Vec<Mono>,
    rows: Vec<Row>,
    /// The pivot row of each column (`u32::MAX`: none).
    pivot_of_col: Vec<u32>,
}

/// Reduces `row` by monic pivot rows (`pivots[c]`: the row whose leading
/// column is `c`), leaving its first entry alone when `keep_lead`: every
/// other entry at a pivot column is eliminated.  `acc` is a zeroed scratch
/// vector as long as the rows, zeroed again on return.
fn reduce_row<'p>(
    fp: &Fp,
    acc: &mut [u64],
    row: &[(u32, u32)],
    pivots: &dyn Fn(usize) -> Option<&'p [(u32, u32)]>,
    keep_lead: bool,
) -> Row {
    let Some(&(start, _)) = row.first() else {
        return Vec::new();
    };
    for &(c, v) in row {
        acc[c as usize] = v as u64;
    }
    // the reduced row is usually about as long as the row
    let mut out = Vec::with_capacity(row.len());
    let (p, p2) = (fp.p, fp.p2);
    for c in start as usize..acc.len() {
        let a = acc[c];
        if a == 0 {
            continue;
        }
        acc[c] = 0;
        let a = fp.reduce(a);
        if a == 0 {
            continue;
        }
        if !(keep_lead && c == start as usize)
            && let Some(pr) = pivots(c)
        {
            let mult = p - a;
            for &(cc, v) in &pr[1..] {
                let t = acc[cc as usize] + mult * v as u64;
                acc[cc as usize] = if t >= p2 { t - p2 } else { t };
            }
            crate::budget::check();
        } else {
            out.push((c as u32, a as u32));
        }
    }
    out
}

/// Reduced row echelon form of rows whose leading columns are free of the
/// matrix pivots: returns the non-zero rows, monic, each reduced by the
/// others.
fn echelon(fp: &Fp, ncols: usize, rows: Vec<Row>) -> Vec<Row> {
    let mut acc = vec![0u64; ncols];
    let mut piv: Vec<Option<usize>> = vec![None; ncols];
    let mut done: Vec<Row> = Vec::new();
    for r in rows {
        let red = reduce_row(
            fp,
            &mut acc,
            &r,
            &|c| piv[c].map(|k| done[k].as_slice()),
            false,
        );
        if red.is_empty() {
            continue;
        }
        let mut red = red;
        let inv = fp.inv(red[0].1 as u64).expect("non-zero");
        for t in red.iter_mut() {
            t.1 = fp.mul(t.1 as u64, inv) as u32;
        }
        piv[red[0].0 as usize] = Some(done.len());
        done.push(red);
    }
    // back substitution, from the last leading column up
    let mut order: Vec<usize> = (0..done.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(done[k][0].0));
    let mut fin: Vec<Option<Row>> = vec![None; done.len()];
    let mut fpiv: Vec<Option<usize>> = vec![None; ncols];
    for k in order {
        let red = reduce_row(
            fp,
            &mut acc,
            &done[k],
            &|c| fpiv[c].and_then(|j| fin[j].as_deref()),
            true,
        );
        fpiv[red[0].0 as usize] = Some(k);
        fin[k] = Some(red);
    }
    fin.into_iter().flatten().collect()
}

#[derive(Clone, Copy, Debug)]
struct Pair {
    i: usize,
    j: usize,
    lcm: Mono,
    sugar: u32,
}

/// A reduced Gröbner basis modulo p (grevlex, x > y > z).
#[derive(Clone, Debug)]
pub struct ModGb {
    /// The prime field.
    pub fp: Fp,
    /// The reduced basis: monic, leading monomials increasing.
    pub polys: Vec<ModPoly>,
}

struct F4 {
    store: Vec<ModPoly>,
    sugar: Vec<u32>,
    active: Vec<usize>,
    pairs: Vec<Pair>,
}

impl F4 {
    fn lm(&self, i: usize) -> Mono {
        self.store[i][0].0
    }

    /// Gebauer–Möller: adds `h` (index) to the basis with the useful pairs.
    fn update(&mut self, h: usize) {
        let hm = self.lm(h);
        let sh = self.sugar[h] - degree(hm);
        let mut c: Vec<Pair> = self
            .active
            .iter()
            .map(|&g| {
                let l = lcm(self.lm(g), hm);
                let sg = self.sugar[g] - degree(self.lm(g));
                Pair {
                    i: g,
                    j: h,
                    lcm: l,
                    sugar: sg.max(sh) + degree(l),
                }
            })
            .collect();
        let mut d: Vec<Pair> = Vec::new();
        while let Some(p) = c.pop() {
            if coprime(self.lm(p.i), hm)
                || (!c.iter().any(|q| divides(q.lcm, p.lcm))
                    && !d.iter().any(|q| divides(q.lcm, p.lcm)))
            {
                d.push(p);
            }
        }
        let e: Vec<Pair> = d
            .into_iter()
            .filter(|p| !coprime(self.lm(p.i), hm))
            .collect();
        let store = &self.store;
        self.pairs.retain(|p| {
            !divides(hm, p.lcm)
                || lcm(store[p.i][0].0, hm) == p.lcm
                || lcm(store[p.j][0].0, hm) == p.lcm
        });
        self.pairs.extend(e);
        self.active.retain(|&g| !divides(hm, store[g][0].0));
        self.active.push(h);
    }
}

/// The reduced Gröbner basis of the ideal generated by `input` modulo the
/// prime of `fp` (zero polynomials are ignored).  `None` when a degree
/// exceeds [`MAX_DEGREE`].
pub fn groebner_mod(fp: &Fp, input: &[ModPoly]) -> Option<ModGb> {
    let mut f4 = F4 {
        store: Vec::new(),
        sugar: Vec::new(),
        active: Vec::new(),
        pairs: Vec::new(),
    };
    // the generators enter at their degree (sugar)
    let mut pending: Vec<usize> = Vec::new();
    for p in input {
        let mut p = p.clone();
        normalize(&mut p);
        if p.is_empty() {
            continue;
        }
        if degree(p[0].0) > MAX_DEGREE {
            return None;
        }
        make_monic(fp, &mut p);
        f4.sugar.push(degree(p[0].0));
        f4.store.push(p);
        pending.push(f4.store.len() - 1);
    }
    loop {
        crate::budget::check_now();
        let s = f4
            .pairs
            .iter()
            .map(|p| p.sugar)
            .chain(pending.iter().map(|&g| f4.sugar[g]))
            .min();
        let Some(s) = s else { break };
        if s > MAX_DEGREE {
            return None;
        }
        // (multiplier, polynomial, is a generator)
        let mut rows: Vec<(Mono, usize, bool)> = Vec::new();
        let mut k = 0;
        while k < f4.pairs.len() {
            if f4.pairs[k].sugar == s {
                let p = f4.pairs.swap_remove(k);
                rows.push((p.lcm - f4.lm(p.i), p.i, false));
                rows.push((p.lcm - f4.lm(p.j), p.j, false));
            } else {
                k += 1;
            }
        }
        pending.retain(|&g| {
            if f4.sugar[g] == s {
                rows.push((0, g, true));
                false
            } else {
                true
            }
        });
        rows.sort_unstable();
        rows.dedup();
        let max_deg = rows
            .iter()
            .map(|&(m, i, _)| degree(m) + degree(f4.store[i][0].0))
            .max()
            .unwrap_or(0);
        let new = {
            let mut sym = Symbolic::new(&f4.store, max_deg);
            let mut todo = Vec::new();
            // a generator is not in the basis yet: it is reduced, never a pivot
            for &(m, i, generator) in &rows {
                if !sym.add_row(m, i, !generator) {
                    todo.push(sym.rows.len() - 1);
                }
            }
            sym.preprocess(&f4.active);
            let mat = sym.build();
            let ncols = mat.cols.len();
            crate::budget::check_size("F4 matrix", mat.rows.len() * ncols, 0);
            let mut acc = vec![0u64; ncols];
            let pivots = |c: usize| match mat.pivot_of_col[c] {
                u32::MAX => None,
                r => Some(mat.rows[r as usize].as_slice()),
            };
            let reduced: Vec<Row> = todo
                .iter()
                .map(|&r| reduce_row(fp, &mut acc, &mat.rows[r], &pivots, false))
                .filter(|r| !r.is_empty())
                .collect();
            let ech = echelon(fp, ncols, reduced);
            ech.into_iter()
                .map(|r| {
                    r.into_iter()
                        .map(|(c, v)| (mat.cols[c as usize], v))
                        .collect::<ModPoly>()
                })
                .collect::<Vec<ModPoly>>()
        };
        let mut new = new;
        new.sort_by_key(|p| rank(p[0].0));
        for p in new {
            if p[0].0 == 0 {
                // a non-zero constant: the unit ideal
                return Some(ModGb {
                    fp: *fp,
                    polys: vec![vec![(0, 1)]],
                });
            }
            f4.store.push(p);
            f4.sugar.push(s);
            let h = f4.store.len() - 1;
            f4.update(h);
        }
    }
    // the active elements form a minimal basis; reduce their tails
    let mut act = f4.active.clone();
    act.sort_by_key(|&g| rank(f4.lm(g)));
    let targets: Vec<ModPoly> = act.iter().map(|&g| f4.store[g].clone()).collect();
    let basis: Vec<ModPoly> = targets.clone();
    let polys = reduce_all(fp, &basis, &targets, true);
    Some(ModGb { fp: *fp, polys })
}

/// Full reduction of each target by monic `basis` polynomials (one matrix
/// for all targets); with `keep_lead` the leading term of each target is
/// kept (tail reduction).
fn reduce_all(fp: &Fp, basis: &[ModPoly], targets: &[ModPoly], keep_lead: bool) -> Vec<ModPoly> {
    let mut polys: Vec<ModPoly> = basis.to_vec();
    let nb = polys.len();
    polys.extend(targets.iter().cloned());
    let max_deg = polys
        .iter()
        .filter(|p| !p.is_empty())
        .map(|p| degree(p[0].0))
        .max()
        .unwrap_or(0);
    let mut sym = Symbolic::new(&polys, max_deg);
    let mut trows = Vec::with_capacity(targets.len());
    for (k, t) in targets.iter().enumerate() {
        if t.is_empty() {
            trows.push(None);
            continue;
        }
        // target rows are never pivots (they are what gets reduced)
        let r = sym.rows.len();
        sym.rows.push((0, nb + k));
        for &(m, _) in t {
            sym.present[rank(m)] = m + 1;
        }
        trows.push(Some(r));
    }
    let reducers: Vec<usize> = (0..nb).collect();
    sym.preprocess(&reducers);
    let mat = sym.build();
    let mut acc = vec![0u64; mat.cols.len()];
    let pivots = |c: usize| match mat.pivot_of_col[c] {
        u32::MAX => None,
        r => Some(mat.rows[r as usize].as_slice()),
    };
    trows
        .into_iter()
        .map(|r| match r {
            None => Vec::new(),
            Some(r) => reduce_row(fp, &mut acc, &mat.rows[r], &pivots, keep_lead)
                .into_iter()
                .map(|(c, v)| (mat.cols[c as usize], v))
                .collect(),
        })
        .collect()
}

impl ModGb {
    /// True when the ideal is the whole ring.
    pub fn is_unit(&self) -> bool {
        self.polys.len() == 1 && self.polys[0][0].0 == 0
    }

    /// The leading monomials.
    pub fn leading(&self) -> Vec<Mono> {
        self.polys.iter().map(|p| p[0].0).collect()
    }

    /// The normal forms of `targets` (full reduction; the basis is reduced).
    pub fn normal_forms(&self, targets: &[ModPoly]) -> Vec<ModPoly> {
        reduce_all(&self.fp, &self.polys, targets, false)
    }

    /// The standard monomials, increasing, when every variable has a pure
    /// power among the leading monomials (`None` otherwise).
    pub fn standard_monomials(&self) -> Option<Vec<Mono>> {
        standard_monomials_of(&self.leading())
    }
}

/// The monomials divisible by none of `lms`, increasing, when `lms` holds a
/// pure power of each of x, y, z (`None` otherwise: infinitely many).
pub fn standard_monomials_of(lms: &[Mono]) -> Option<Vec<Mono>> {
    let pure = |v: usize| {
        lms.iter()
            .filter_map(|&m| {
                let e = exps(m);
                (e.iter().enumerate().all(|(w, &x)| w == v || x == 0) && e[v] > 0).then_some(e[v])
            })
            .min()
    };
    let (a, b, c) = (pure(0)?, pure(1)?, pure(2)?);
    if lms.contains(&0) {
        return Some(Vec::new());
    }
    let mut out = Vec::new();
    for i in 0..a {
        for j in 0..b {
            for k in 0..c {
                crate::budget::check();
                let m = mono(i, j, k);
                if !lms.iter().any(|&l| divides(l, m)) {
                    out.push(m);
                }
            }
        }
    }
    out.sort_by_key(|&m| rank(m));
    Some(out)
}

/// The quotient `A_p = F_p[x, y, z]/I_p` of a zero-dimensional ideal: the
/// standard monomials and the multiplication matrices of x, y, z.
#[derive(Clone, Debug)]
pub struct ModQuotient {
    /// The basis of `A_p`, increasing.
    pub basis: Vec<Mono>,
    /// `mult[v][j]`: the coordinates of `x_v · basis[j]` (dense, length
    /// `basis.len()`).
    pub mult: [Vec<Vec<u32>>; 3],
}

impl ModQuotient {
    /// The quotient of a zero-dimensional reduced basis (`None` otherwise).
    pub fn new(gb: &ModGb) -> Option<ModQuotient> {
        let basis = gb.standard_monomials()?;
        let n = basis.len();
        let index = |m: Mono| basis.binary_search_by_key(&rank(m), |&b| rank(b)).ok();
        // the border: products x_v·b that are not standard
        let mut border: Vec<Mono> = Vec::new();
        for &b in &basis {
            for v in [mono(1, 0, 0), mono(0, 1, 0), mono(0, 0, 1)] {
                if index(b + v).is_none() {
                    border.push(b + v);
                }
            }
        }
        border.sort_unstable();
        border.dedup();
        let targets: Vec<ModPoly> = border.iter().map(|&m| vec![(m, 1)]).collect();
        let nfs = gb.normal_forms(&targets);
        let mut mult: [Vec<Vec<u32>>; 3] = std::array::from_fn(|_| vec![vec![0u32; n]; n]);
        for (j, &b) in basis.iter().enumerate() {
            for (v, vm) in [mono(1, 0, 0), mono(0, 1, 0), mono(0, 0, 1)]
                .into_iter()
                .enumerate()
            {
                let col = &mut mult[v][j];
                match index(b + vm) {
                    Some(i) => col[i] = 1,
                    None => {
                        let k = border.binary_search(&(b + vm)).expect("border monomial");
                        for &(m, c) in &nfs[k] {
                            col[index(m)?] = c;
                        }
                    }
                }
            }
        }
        Some(ModQuotient { basis, mult })
    }

    /// The matrix of the multiplication by `Σ c_v·x_v` modulo p, by
    /// columns one after the other (for
    /// [`mat_vec`](crate::number::modkernel::mat_vec)).
    pub fn combined_columns(&self, fp: &Fp, c: [u64; 3]) -> Vec<u32> {
        let n = self.dim();
        let mult = &self.mult;
        (0..n)
            .flat_map(|j| {
                (0..n).map(move |i| {
                    let s = c[0] * mult[0][j][i] as u64
                        + c[1] * mult[1][j][i] as u64
                        + c[2] * mult[2][j][i] as u64;
                    fp.reduce(s) as u32
                })
            })
            .collect()
    }

    /// Dimension of `A_p`.
    pub fn dim(&self) -> usize {
        self.basis.len()
    }

    /// The coordinates of a normal form (a polynomial on the basis).
    pub fn coords(&self, nf: &ModPoly) -> Option<Vec<u64>> {
        let mut v = vec![0u64; self.dim()];
        for &(m, c) in nf {
            let i = self
                .basis
                .binary_search_by_key(&rank(m), |&b| rank(b))
                .ok()?;
            v[i] = c as u64;
        }
        Some(v)
    }
}

/// The multiplication by one variable on the quotient `A_p`, sparse: most
/// products `x_v·b` of a standard monomial are standard monomials again
/// (a unit column); only the border needs a normal form (a dense column).
/// With the smallest variable of grevlex the border is a small fraction of
/// the basis, so a product costs far less than `dim²`.
#[derive(Clone, Debug)]
pub struct SparseMult {
    /// Per column j: the index i with `x_v·b_j = b_i`, or `u32::MAX`.
    unit: Vec<u32>,
    /// The dense columns `(j, coordinates of NF(x_v·b_j))`.
    dense: Vec<(usize, Vec<u64>)>,
}

impl SparseMult {
    /// The multiplication by the variable `v` (0, 1, 2 for x, y, z) on the
    /// quotient with standard monomials `basis` (increasing).
    pub fn new(gb: &ModGb, basis: &[Mono], v: usize) -> Option<SparseMult> {
        let mut index = vec![u32::MAX; ranks_up_to(degree_bound(basis) + 1)];
        for (i, &b) in basis.iter().enumerate() {
            index[rank(b)] = i as u32;
        }
        let mut var = [0u32; 3];
        var[v] = 1;
        let vm = mono(var[0], var[1], var[2]);
        let mut unit = vec![u32::MAX; basis.len()];
        let mut border: Vec<(usize, Mono)> = Vec::new();
        for (j, &b) in basis.iter().enumerate() {
            let m = b + vm;
            match index.get(rank(m)) {
                Some(&i) if i != u32::MAX => unit[j] = i,
                _ => border.push((j, m)),
            }
        }
        let targets: Vec<ModPoly> = border.iter().map(|&(_, m)| vec![(m, 1)]).collect();
        let nfs = gb.normal_forms(&targets);
        let n = basis.len();
        let mut dense = Vec::with_capacity(border.len());
        for ((j, _), nf) in border.iter().zip(nfs) {
            let mut col = vec![0u64; n];
            for (m, c) in nf {
                let i = *index.get(rank(m))?;
                if i == u32::MAX {
                    return None;
                }
                col[i as usize] = c as u64;
            }
            dense.push((*j, col));
        }
        Some(SparseMult { unit, dense })
    }

    /// `Mᵀ·x` (entries in `[0, p)`): a unit column gives one entry, a
    /// dense column a dot product.
    pub fn apply_transposed(&self, fp: &Fp, x: &[u64]) -> Vec<u64> {
        let mut y = vec![0u64; x.len()];
        for (j, &i) in self.unit.iter().enumerate() {
            if i != u32::MAX {
                y[j] = x[i as usize];
            }
        }
        for (j, col) in &self.dense {
            y[*j] = crate::number::modkernel::dot(fp, col, x);
        }
        y
    }

    /// `M·x` (entries in `[0, p)`).
    pub fn apply(&self, fp: &Fp, x: &[u64]) -> Vec<u64> {
        let mut y = vec![0u64; x.len()];
        for (j, &i) in self.unit.iter().enumerate() {
            if i != u32::MAX {
                y[i as usize] = x[j];
            }
        }
        for (j, col) in &self.dense {
            let xj = x[*j];
            if xj != 0 {
                crate::number::modkernel::axpy_lazy(fp, &mut y, xj, col);
            }
        }
        // unit entries are below p and lazy sums below p²: one reduction
        y.iter_mut().for_each(|v| *v = fp.reduce(*v));
        y
    }
}

/// The largest degree of a monomial of `basis`.
fn degree_bound(basis: &[Mono]) -> u32 {
    basis.iter().map(|&b| degree(b)).max().unwrap_or(0)
}

/// An integer polynomial in x, y, z (slots `X, Y, Z` of an
/// [`crate::poly::ZMPoly`]) modulo p.
///
/// # Panics
///
/// When a term's degree is 128 or more: its monomial does not fit [`Mono`]
/// (callers decline such degrees first, see [`MAX_DEGREE`]; a packed
/// monomial would silently be another one).
pub fn zmpoly_mod(fp: &Fp, p: &crate::poly::ZMPoly) -> ModPoly {
    use crate::poly::mpoly::{X, Y, Z};
    let mut out: ModPoly = p
        .terms()
        .iter()
        .map(|(e, c)| {
            let d = e[X] + e[Y] + e[Z];
            assert!(
                d < 128,
                "a monomial of degree {d} does not fit the F4 packing"
            );
            (mono(e[X], e[Y], e[Z]), fp.reduce_big(c) as u32)
        })
        .collect();
    normalize(&mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::prime31::prime31;
    use crate::poly::parse_poly;
    use crate::system::groebner::{GPoly, MonoOrder, groebner};

    /// A degree that does not fit the packing panics instead of packing
    /// another monomial (fuzzing found `y^788` reaching here).
    #[test]
    #[should_panic(expected = "does not fit the F4 packing")]
    fn zmpoly_mod_refuses_degrees_beyond_the_packing() {
        let p = parse_poly("y^788 + x - 1").unwrap().to_primitive_z().0;
        let _ = zmpoly_mod(&Fp::new(prime31(0)), &p);
    }

    #[test]
    fn rank_is_the_grevlex_order() {
        let mut ms = Vec::new();
        for a in 0..6 {
            for b in 0..6 {
                for c in 0..6 {
                    ms.push(mono(a, b, c));
                }
            }
        }
        let slots = [0usize, 1, 2];
        for &m in &ms {
            for &n in &ms {
                let to = |m: Mono| {
                    let e = exps(m);
                    let mut g = [0u16; 4];
                    for i in 0..3 {
                        g[slots[i]] = e[i] as u16;
                    }
                    g
                };
                let want = crate::system::groebner::cmp_mono(&to(m), &to(n), MonoOrder::GrevLex);
                assert_eq!(rank(m).cmp(&rank(n)), want, "{:?} {:?}", exps(m), exps(n));
            }
        }
        // ranks are consecutive: 0, 1, 2, … over degrees 0..=k
        let mut r: Vec<usize> = (0..=5u32)
            .flat_map(|k| {
                (0..=k).flat_map(move |a| (0..=k - a).map(move |b| mono(a, b, k - a - b)))
            })
            .map(rank)
            .collect();
        r.sort_unstable();
        assert_eq!(r, (0..ranks_up_to(5)).collect::<Vec<_>>());
    }

    /// The reduced basis over Q, made monic and reduced modulo p.
    fn q_basis_mod(fp: &Fp, gens: &[&str]) -> Vec<ModPoly> {
        let ord = MonoOrder::GrevLex;
        let input: Vec<GPoly> = gens
            .iter()
            .map(|g| GPoly::from_mpoly(&parse_poly(g).unwrap(), &[0, 1, 2], ord))
            .collect();
        let gb = groebner(input, 3, ord);
        gb.polys
            .iter()
            .map(|g| {
                let z = g.to_mpoly(&[0, 1, 2]).to_primitive_z().0;
                let mut p = zmpoly_mod(fp, &z);
                make_monic(fp, &mut p);
                p
            })
            .collect()
    }

    fn mod_basis(fp: &Fp, gens: &[&str]) -> ModGb {
        let input: Vec<ModPoly> = gens
            .iter()
            .map(|g| zmpoly_mod(fp, &parse_poly(g).unwrap().to_primitive_z().0))
            .collect();
        groebner_mod(fp, &input).unwrap()
    }

    /// The F4 basis modulo p is the exact reduced basis over Q reduced
    /// modulo p (for primes dividing no denominator of it).
    #[test]
    fn f4_basis_is_the_rational_basis_mod_p() {
        let systems: [&[&str]; 5] = [
            &["x^2+y^2-1", "x-y"],
            &["x+y+z", "x*y+y*z+z*x", "x*y*z-1"],
            &["x^2+2y^2+3z^2-6", "x*y - z", "y^2 - x*z + 1"],
            // a critical system E = 0, ∇S × ∇E = 0 (S = x³ − 2xy + z² − 1)
            &[
                "x^2+2y^2+3z^2-6",
                "-2*x*6*z + 2*z*4*y",
                "2*z*2*x - (3*x^2-2*y)*6*z",
                "(3*x^2-2*y)*4*y + 2*x*2*x",
            ],
            &["x^3 - y*z + 2", "y^3 - x*z - 1", "z^3 - x*y + x - 3"],
        ];
        for k in [0usize, 3] {
            let fp = Fp::new(prime31(k));
            for gens in systems {
                let g = mod_basis(&fp, gens);
                assert_eq!(g.polys, q_basis_mod(&fp, gens), "{gens:?}");
            }
        }
    }

    #[test]
    fn unit_and_positive_dimensional_ideals() {
        let fp = Fp::new(prime31(1));
        assert!(mod_basis(&fp, &["x^2+1", "x", "y"]).is_unit());
        let g = mod_basis(&fp, &["x*y", "x*z"]);
        assert!(!g.is_unit() && g.standard_monomials().is_none());
    }

    #[test]
    fn multiplication_matrices_commute_and_match_normal_forms() {
        let fp = Fp::new(prime31(2));
        let g = mod_basis(&fp, &["x^2+2y^2+3z^2-6", "x*y - z", "y^2 - x*z + 1"]);
        let q = ModQuotient::new(&g).unwrap();
        let n = q.dim();
        assert_eq!(n, g.standard_monomials().unwrap().len());
        let mul = |a: &Vec<Vec<u32>>, b: &Vec<Vec<u32>>| -> Vec<Vec<u64>> {
            // column j of a·b = a · (column j of b)
            (0..n)
                .map(|j| {
                    (0..n)
                        .map(|i| {
                            (0..n).fold(0u64, |s, k| {
                                fp.add(s, fp.mul(a[k][i] as u64, b[j][k] as u64))
                            })
                        })
                        .collect()
                })
                .collect()
        };
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            assert_eq!(mul(&q.mult[a], &q.mult[b]), mul(&q.mult[b], &q.mult[a]));
        }
        // x·1 is the normal form of x
        let nf = g.normal_forms(&[vec![(mono(1, 0, 0), 1)]]);
        let v = q.coords(&nf[0]).unwrap();
        let one = q.basis.iter().position(|&m| m == 0).unwrap();
        let col: Vec<u64> = q.mult[0][one].iter().map(|&c| c as u64).collect();
        assert_eq!(v, col);
    }
}
