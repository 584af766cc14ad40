//! Joint-space inertia: composite rigid bodies (qM), its sparse L'DL factorization and solves.

use super::linalg::{add_to, dot6, row};
use super::support::warning;
use super::tree::{deep, DofPath};
use super::{Data, EngineError, Model, MINVAL};
use crate::abi::{mjData, mjtWarning_};
use crate::math::*;

/// Composite rigid body inertias and qM (mj_crbSkip); `skipsimple` copies dof_M0 for simple dofs.
pub fn crb(m: &Model, d: &mut Data, skipsimple: bool) {
    let nbody = m.raw.nbody as usize;
    let nv = m.raw.nv as usize;
    let body_parent = m.body_parentid();
    let (madr, simple, parent) = (m.dof_Madr(), m.dof_simplenum(), m.dof_parentid());
    let (m0, armature, dof_body) = (m.dof_M0(), m.dof_armature(), m.dof_bodyid());
    let crb = &mut *d.crb;
    crb.copy_from_slice(d.cinert);
    for i in (1..nbody).rev() {
        let p = body_parent[i] as usize;
        if p > 0 {
            let (lo, hi) = crb.split_at_mut(10 * i);
            add_to(&mut lo[10 * p..10 * p + 10], &hi[..10]);
        }
    }
    let (qm, cdof) = (&mut *d.qM, &*d.cdof);
    qm.fill(0.0);
    for i in (0..nv).rev() {
        let mut adr = madr[i] as usize;
        if skipsimple && simple[i] != 0 {
            qm[adr] = m0[i];
            continue;
        }
        qm[adr] = armature[i];
        let b = dof_body[i] as usize;
        let tmp = mul_inert_vec(&crb[10 * b..10 * b + 10], &row(cdof, i));
        let mut j = i as i32;
        while j >= 0 {
            let ju = j as usize;
            qm[adr] += dot6(&cdof[6 * ju..6 * ju + 6], &tmp);
            j = parent[ju];
            adr += 1;
        }
    }
}

/// Trees where each row pulls its updates (see `factor_i`): at least this many dofs, and
/// at least `PULL_DEPTH` ancestors a dof on average (humanoid_CMU, dog: about half off the
/// factorization). Where rows are shorter (humanoid, nine a dof; rodent, ten) pulling gains
/// nothing, and in small trees the push is faster.
const PULL_MIN_NV: usize = 20;
const PULL_DEPTH: usize = 12;

/// Sparse L'*D*L factorization of an inertia-like matrix (mj_factorI).
///
/// 2.2.2 pushes each row k, from the last, into the rows of its ancestors i:
/// `M(i,:) -= M(k,:) * (M(k,i) / M(k,k))`. In deep trees each row i pulls those same updates
/// instead, in the same order (k descending), into registers (`pull`).
pub fn factor_i(
    m: &Model,
    raw: &mut mjData,
    mat: &[f64],
    qld: &mut [f64],
    diag_inv: &mut [f64],
    sqrt_inv: Option<&mut [f64]>,
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let (madr, simple, parent) = (m.dof_Madr(), m.dof_simplenum(), m.dof_parentid());
    let nm = qld.len();
    qld.copy_from_slice(&mat[..nm]);
    let pulls = nv >= PULL_MIN_NV && nm >= PULL_DEPTH * nv;
    for k in (0..nv).rev() {
        let akk = madr[k] as usize;
        if pulls {
            pull(qld, madr, simple, k, &mut diag_inv[..nv]);
        }
        if qld[akk] < MINVAL {
            warning(raw, mjtWarning_::mjWARN_INERTIA as i32, k as i32)?;
            qld[akk] = MINVAL;
        }
        if pulls || simple[k] != 0 {
            continue;
        }
        // row k: its diagonal, then one entry per ancestor; each ancestor's own row is the
        // rest of row k from that ancestor's entry on (rows lie in dof order, ancestors first)
        let end = madr.get(k + 1).map_or(nm, |&a| a as usize);
        let (head, row) = qld.split_at_mut(akk);
        let row = &mut row[..end - akk];
        let dkk = row[0];
        let mut i = parent[k];
        for t in 1..row.len() {
            let tmp = row[t] / dkk;
            let ai = madr[i as usize] as usize;
            let n = row.len() - t;
            for (x, y) in head[ai..ai + n].iter_mut().zip(&row[t..]) {
                *x -= y * tmp;
                // kept scalar: the next rows read these entries back one at a time, which
                // wide stores cannot forward (a tenth off a humanoid's factorization)
                std::hint::black_box(());
            }
            row[t] = tmp;
            i = parent[i as usize];
        }
    }
    // the diagonal gathered first, so that the divisions and roots run on whole vectors
    // (each lane rounds as the scalar instruction does)
    let diag = &mut diag_inv[..nv];
    for (x, &a) in diag.iter_mut().zip(madr) {
        *x = qld[a as usize];
    }
    match sqrt_inv {
        Some(s) => {
            for (x, s) in diag.iter_mut().zip(&mut s[..nv]) {
                *s = 1.0 / x.sqrt();
                *x = 1.0 / *x;
            }
        }
        None => {
            for x in diag.iter_mut() {
                *x = 1.0 / *x;
            }
        }
    }
    Ok(())
}

/// Completes row i with the updates of its non-simple descendants k, the last first, in
/// blocks of up to 8 columns held in registers. Its descendants are the dofs after it with
/// longer rows, up to the first that is not (dofs lie in depth-first order, which
/// `abi::consistency` requires of a loaded model), found through the ends of its children's
/// subtrees: `ends` (factor_i's diag_inv, until the inverses replace them) keeps each row's end
/// for its parent's search. i's column and those of its ancestors are the last entries of
/// each such row. The quotient M(k,i)/M(k,k) is taken where first used and
/// stored in place of M(k,i), which no later row reads.
fn pull(qld: &mut [f64], madr: &[i32], simple: &[i32], i: usize, ends: &mut [f64]) {
    let (nv, nm) = (ends.len(), qld.len());
    let start = |k: usize| madr.get(k).map_or(nm, |&a| a as usize);
    let len = start(i + 1) - start(i);
    // past the subtrees of i's children, found by their ends (each greater than its dof)
    let mut end = i + 1;
    while end < nv && start(end + 1) - start(end) > len {
        end = ends[end] as usize;
    }
    ends[i] = end as f64;
    // a simple dof whose run of simple dofs holds all its descendants gets no update
    if simple[i] > 0 && i + simple[i] as usize >= end {
        return;
    }
    let e = start(end);
    let rows = Desc {
        madr,
        simple,
        row: (start(i), len),
        desc: (i + 1, end, e),
    };
    let mut col = 0;
    while col < len {
        col += match col {
            0 => rows.block::<true>(qld, col),
            _ => rows.block::<false>(qld, col),
        };
    }
}

/// A row to complete and its descendants.
struct Desc<'a> {
    madr: &'a [i32],
    simple: &'a [i32],
    /// The row's address and length.
    row: (usize, usize),
    /// Descendants first..end, and the address where row end - 1 ends.
    desc: (usize, usize, usize),
}

impl Desc<'_> {
    /// The next block of up to 8 columns from col; gives its width.
    #[inline(always)]
    fn block<const FIRST: bool>(&self, qld: &mut [f64], col: usize) -> usize {
        match self.row.1 - col {
            1 => self.pull::<1, FIRST>(qld, col),
            2 => self.pull::<2, FIRST>(qld, col),
            3 => self.pull::<3, FIRST>(qld, col),
            4 => self.pull::<4, FIRST>(qld, col),
            5 => self.pull::<5, FIRST>(qld, col),
            6 => self.pull::<6, FIRST>(qld, col),
            7 => self.pull::<7, FIRST>(qld, col),
            _ => self.pull::<8, FIRST>(qld, col),
        }
    }

    /// Columns col..col+W; the FIRST block also takes and stores the quotients. Gives W.
    #[inline(always)]
    fn pull<const W: usize, const FIRST: bool>(&self, qld: &mut [f64], col: usize) -> usize {
        let (ai, len) = self.row;
        let (first, end, mut e) = self.desc;
        let mut acc: [f64; W] = qld[ai + col..ai + col + W].try_into().unwrap();
        for k in (first..end).rev() {
            // row k ends at e; its last len entries are column i's and those of i's ancestors
            let ak = self.madr[k] as usize;
            let at = e - len;
            e = ak;
            if self.simple[k] != 0 {
                continue;
            }
            let u: [f64; W] = qld[at + col..at + col + W].try_into().unwrap();
            let l = if FIRST {
                let l = u[0] / qld[ak];
                qld[at] = l;
                l
            } else {
                qld[at]
            };
            for s in 0..W {
                acc[s] -= u[s] * l;
            }
        }
        qld[ai + col..ai + col + W].copy_from_slice(&acc);
        W
    }
}

/// Factorizes qM into qLD, qLDiagInv, qLDiagSqrtInv (mj_factorM).
pub fn factor_m(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    factor_i(m, d.raw, d.qM, d.qLD, d.qLDiagInv, Some(d.qLDiagSqrtInv))
}

/// Solves L'*D*L x = x in place for one vector.
fn solve_ld1(m: &Model, x: &mut [f64], qld: &[f64], diag_inv: &[f64]) {
    let nv = m.raw.nv as usize;
    let (simple, madr, parent) = (m.dof_simplenum(), m.dof_Madr(), m.dof_parentid());
    let x = &mut x[..nv];
    scatter_to_ancestors(m, x, qld);
    for (xi, di) in x.iter_mut().zip(&diag_inv[..nv]) {
        *xi *= di;
    }
    for i in 0..nv {
        if simple[i] == 0 {
            let mut adr = madr[i] as usize + 1;
            let mut j = parent[i];
            let mut tmp = x[i];
            while j >= 0 {
                let ju = j as usize;
                tmp -= qld[adr] * x[ju];
                adr += 1;
                j = parent[ju];
            }
            x[i] = tmp;
        }
    }
}

/// x = inv(L') * x: each dof from the last, x(j) -= L(i,j) * x(i) for its ancestors j.
#[inline(always)]
fn scatter_to_ancestors(m: &Model, x: &mut [f64], qld: &[f64]) {
    let nv = m.raw.nv as usize;
    if deep(nv, m.raw.nM as usize, PULL_DEPTH) {
        return scatter_to_ancestors_on_path(m, x, qld);
    }
    let (simple, madr, parent) = (m.dof_simplenum(), m.dof_Madr(), m.dof_parentid());
    for i in (0..nv).rev() {
        let tmp = x[i];
        if simple[i] == 0 && tmp != 0.0 {
            by_parents(x, &qld[madr[i] as usize + 1..], parent[i], parent, tmp);
        }
    }
}

/// `scatter_to_ancestors` in deep trees, the ancestors read from a `DofPath`.
#[inline(never)]
fn scatter_to_ancestors_on_path(m: &Model, x: &mut [f64], qld: &[f64]) {
    let nv = m.raw.nv as usize;
    let (simple, madr, parent) = (m.dof_simplenum(), m.dof_Madr(), m.dof_parentid());
    let mut path = DofPath::new();
    for i in (0..nv).rev() {
        let tmp = x[i];
        if simple[i] != 0 || tmp == 0.0 {
            continue;
        }
        let l = &qld[madr[i] as usize + 1..];
        match path.prev(i, parent) {
            Some(a) => {
                for (&l, &j) in l[..a.len()].iter().zip(a.iter().rev()) {
                    x[j as usize] -= l * tmp;
                }
            }
            None => by_parents(x, l, parent[i], parent, tmp),
        }
    }
}

/// x(j) -= l(t) * s in turn for the ancestors j of a dof, found through dof_parentid from `j`.
#[inline(always)]
fn by_parents(x: &mut [f64], l: &[f64], mut j: i32, parent: &[i32], s: f64) {
    for &l in l {
        if j < 0 {
            break;
        }
        let ju = j as usize;
        x[ju] -= l * s;
        j = parent[ju];
    }
}

/// x = inv(L'*D*L) * y for `n` vectors of length nv (mj_solveLD); x and y may be the same.
pub fn solve_ld(
    m: &Model,
    x: &mut [f64],
    y: Option<&[f64]>,
    n: usize,
    qld: &[f64],
    diag_inv: &[f64],
) {
    let nv = m.raw.nv as usize;
    if let Some(y) = y {
        x[..n * nv].copy_from_slice(&y[..n * nv]);
    }
    for v in 0..n {
        solve_ld1(m, &mut x[v * nv..(v + 1) * nv], qld, diag_inv);
    }
}

/// x = sqrt(inv(D)) * inv(L') * y for `n` vectors (mj_solveM2).
pub fn solve_m2(m: &Model, x: &mut [f64], y: &[f64], n: usize, qld: &[f64], sqrt_inv: &[f64]) {
    let nv = m.raw.nv as usize;
    x[..n * nv].copy_from_slice(&y[..n * nv]);
    for v in 0..n {
        let x = &mut x[v * nv..(v + 1) * nv];
        scatter_to_ancestors(m, x, qld);
        for i in 0..nv {
            x[i] *= sqrt_inv[i];
        }
    }
}
