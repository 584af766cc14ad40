//! Joint-space inertia: composite rigid bodies (qM), its sparse L'DL factorization and solves.

use super::linalg::{add_to, dot6, row};
use super::support::warning;
use super::tree::{rows_by_depth, DEPTH};
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
/// at least `PULL_DEPTH` entries a row on average (humanoids, rodent, dog: a quarter to half
/// off the factorization). In shallower or smaller trees (hands, arms, free bodies) the push
/// is faster.
const PULL_MIN_NV: usize = 12;
const PULL_DEPTH: usize = 7;

/// The tree whose last dof is `last`: whether it pulls, and its first dof (the root: a row
/// of one entry). Rows lie in dof order, a tree's dofs in a run, so that a dof's ancestors
/// (its row's length less one) all lie between the root and it: the root is found in a few
/// jumps back by that many.
fn tree_pulls(madr: &[i32], nm: usize, last: usize) -> (bool, usize) {
    let len = |k: usize| madr.get(k + 1).map_or(nm, |&a| a as usize) - madr[k] as usize;
    let mut root = last;
    while root > 0 && len(root) > 1 {
        root = root.saturating_sub(len(root) - 1);
    }
    let (n, entries) = (
        last + 1 - root,
        len(last) + madr[last] as usize - madr[root] as usize,
    );
    (n >= PULL_MIN_NV && entries >= PULL_DEPTH * n, root)
}

/// Sparse L'*D*L factorization of an inertia-like matrix (mj_factorI).
///
/// 2.2.2 pushes each row k, from the last, into the rows of its ancestors i:
/// `M(i,:) -= M(k,:) * (M(k,i) / M(k,k))`. In deep trees each row i pulls those same updates
/// instead, in the same order (k descending), into registers (`pull`); trees are independent,
/// so each is factorized either way.
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
    let mut last = nv;
    while last > 0 {
        let (pulls, root) = tree_pulls(madr, nm, last - 1);
        if pulls {
            for k in (root..last).rev() {
                pull(qld, madr, simple, k, &mut diag_inv[..nv]);
                check_diagonal(raw, qld, madr[k] as usize, k)?;
            }
        } else {
            for k in (root..last).rev() {
                check_diagonal(raw, qld, madr[k] as usize, k)?;
                if simple[k] == 0 {
                    push(qld, madr, parent, k);
                }
            }
        }
        last = root;
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

/// A diagonal below MINVAL is raised to it, with mjWARN_INERTIA.
#[inline(always)]
fn check_diagonal(
    raw: &mut mjData,
    qld: &mut [f64],
    akk: usize,
    k: usize,
) -> Result<(), EngineError> {
    if qld[akk] < MINVAL {
        warning(raw, mjtWarning_::mjWARN_INERTIA as i32, k as i32)?;
        qld[akk] = MINVAL;
    }
    Ok(())
}

/// Pushes row k into the rows of its ancestors, each scaled by its entry over the diagonal.
#[inline(always)]
fn push(qld: &mut [f64], madr: &[i32], parent: &[i32], k: usize) {
    // row k: its diagonal, then one entry per ancestor; each ancestor's own row is the rest
    // of row k from that ancestor's entry on (rows lie in dof order, ancestors first)
    let akk = madr[k] as usize;
    let end = madr.get(k + 1).map_or(qld.len(), |&a| a as usize);
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

/// Completes row i with the updates of its non-simple descendants k, the last first, in
/// blocks of up to 16 columns held in registers. Its descendants are the dofs after it with
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
    // blocks of 16 columns (the wider, the fewer passes over the descendants; 24 was slower)
    // counted from the row's end, as its ancestors read it (their last entries): measured
    // faster than from its start (dog: a fifth off the factorization with both)
    let mut col = rows.block::<true>(qld, 0, (len - 1) % 16 + 1);
    while col < len {
        col += rows.block::<false>(qld, col, 16);
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
    /// The block of `w` (1 to 16) columns from col; gives w.
    #[inline(always)]
    fn block<const FIRST: bool>(&self, qld: &mut [f64], col: usize, w: usize) -> usize {
        match w {
            1 => self.pull::<1, FIRST>(qld, col),
            2 => self.pull::<2, FIRST>(qld, col),
            3 => self.pull::<3, FIRST>(qld, col),
            4 => self.pull::<4, FIRST>(qld, col),
            5 => self.pull::<5, FIRST>(qld, col),
            6 => self.pull::<6, FIRST>(qld, col),
            7 => self.pull::<7, FIRST>(qld, col),
            8 => self.pull::<8, FIRST>(qld, col),
            9 => self.pull::<9, FIRST>(qld, col),
            10 => self.pull::<10, FIRST>(qld, col),
            11 => self.pull::<11, FIRST>(qld, col),
            12 => self.pull::<12, FIRST>(qld, col),
            13 => self.pull::<13, FIRST>(qld, col),
            14 => self.pull::<14, FIRST>(qld, col),
            15 => self.pull::<15, FIRST>(qld, col),
            _ => self.pull::<16, FIRST>(qld, col),
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

/// Trees where solves run by depth (`push_by_depth`, `gather_from_ancestors`): at least this
/// many entries a row on average (dog: a sixth off a solve; rodent, humanoid_CMU: 3-5%). In
/// shallower trees (humanoid) they gain nothing on 2.2.2's walk along dof_parentid.
const SOLVE_DEPTH: usize = 10;

/// The factor's nM entries where solves run by depth: in deep trees whose rows follow the
/// tree by depth.
fn by_depth<'a>(m: &Model, qld: &'a [f64]) -> Option<&'a [f64]> {
    let (nv, nm) = (m.raw.nv as usize, m.raw.nM as usize);
    let deep = nm >= SOLVE_DEPTH * nv && rows_by_depth(m.dof_Madr(), m.dof_parentid(), nm);
    deep.then(|| &qld[..nm])
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

/// `solve_ld1` where the rows follow the tree by depth (`tree::rows_by_depth`).
#[inline(never)]
fn solve_ld1_by_depth(m: &Model, x: &mut [f64], qld: &[f64], diag_inv: &[f64]) {
    let nv = m.raw.nv as usize;
    let (simple, madr, parent) = (m.dof_simplenum(), m.dof_Madr(), m.dof_parentid());
    let x = &mut x[..nv];
    push_by_depth(madr, simple, parent, x, qld);
    for (xi, di) in x.iter_mut().zip(&diag_inv[..nv]) {
        *xi *= di;
    }
    gather_from_ancestors(madr, simple, x, qld);
}

/// x = inv(L) * x where the rows follow the tree by depth (`tree::rows_by_depth`): each dof
/// from the first, x(i) -= L(i,j) * x(j) over its ancestors j from its parent up, in a
/// register; the ancestors' values kept by depth, so that no parent is looked up.
fn gather_from_ancestors(madr: &[i32], simple: &[i32], x: &mut [f64], qld: &[f64]) {
    let nm = qld.len();
    let mut on_path = [0.0; DEPTH];
    for i in 0..x.len() {
        let (a, e) = (
            madr[i] as usize,
            madr.get(i + 1).map_or(nm, |&a| a as usize),
        );
        let d = e - a - 1;
        let mut t = x[i];
        if simple[i] == 0 {
            for (l, v) in qld[a + 1..e].iter().zip(on_path[..d].iter().rev()) {
                t -= l * v;
            }
            x[i] = t;
        }
        on_path[d] = t;
    }
}

/// x = inv(L') * x: each dof from the last, x(j) -= L(i,j) * x(i) for its ancestors j.
#[inline(always)]
fn scatter_to_ancestors(m: &Model, x: &mut [f64], qld: &[f64]) {
    let nv = m.raw.nv as usize;
    let (simple, madr, parent) = (m.dof_simplenum(), m.dof_Madr(), m.dof_parentid());
    for i in (0..nv).rev() {
        let tmp = x[i];
        if simple[i] == 0 && tmp != 0.0 {
            by_parents(x, &qld[madr[i] as usize + 1..], parent[i], parent, tmp);
        }
    }
}

/// `scatter_to_ancestors` where the rows follow the tree by depth. The ancestors of the dof
/// at hand are kept by depth in `on_path` (slot DEPTH-1-k for depth k), each from its first
/// update on, so that a dof's updates run four ancestors at a time, in blocks at the same
/// slots whatever the dof. Slots past the dof's ancestors take terms too, unused: a dof's own
/// slot and deeper ones are dead once it is reached (the dof before it is its parent, or a
/// leaf whose new ancestors are read from x).
fn push_by_depth(madr: &[i32], simple: &[i32], parent: &[i32], x: &mut [f64], qld: &[f64]) {
    let (nv, nm) = (x.len(), qld.len());
    let mut on_path = [0.0; DEPTH];
    let slot = |k: usize| DEPTH - 1 - k;
    // the depth of the dof after the one at hand (0 before the last: all its ancestors new)
    let mut below = 0;
    for i in (0..nv).rev() {
        let (a, e) = (
            madr[i] as usize,
            madr.get(i + 1).map_or(nm, |&a| a as usize),
        );
        let d = e - a - 1;
        if d + 1 == below {
            // the parent of the dof after it: complete
            x[i] = on_path[slot(d)];
        } else {
            // a leaf; its ancestors from the depth of the dof after it on are new
            let mut j = parent[i];
            for k in (below..d).rev() {
                on_path[slot(k)] = x[j as usize];
                j = parent[j as usize];
            }
        }
        below = d;
        let xi = x[i];
        if simple[i] != 0 || xi == 0.0 || d == 0 {
            continue;
        }
        if a < 3 {
            for k in 0..d {
                on_path[slot(k)] -= qld[a + d - k] * xi;
            }
            continue;
        }
        for c in 0..d.div_ceil(4) {
            let lo = a + d - 4 * c - 3;
            let l: &[f64; 4] = qld[lo..lo + 4].try_into().unwrap();
            let s = slot(4 * c + 3);
            let v: &mut [f64; 4] = (&mut on_path[s..s + 4]).try_into().unwrap();
            for t in 0..4 {
                v[t] -= l[t] * xi;
            }
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
    match by_depth(m, qld) {
        Some(qld) => {
            for v in 0..n {
                solve_ld1_by_depth(m, &mut x[v * nv..(v + 1) * nv], qld, diag_inv);
            }
        }
        None => {
            for v in 0..n {
                solve_ld1(m, &mut x[v * nv..(v + 1) * nv], qld, diag_inv);
            }
        }
    }
}

/// x = sqrt(inv(D)) * inv(L') * y for `n` vectors (mj_solveM2).
pub fn solve_m2(m: &Model, x: &mut [f64], y: &[f64], n: usize, qld: &[f64], sqrt_inv: &[f64]) {
    let nv = m.raw.nv as usize;
    x[..n * nv].copy_from_slice(&y[..n * nv]);
    let deep = by_depth(m, qld);
    for v in 0..n {
        let x = &mut x[v * nv..(v + 1) * nv];
        match deep {
            Some(qld) => {
                let (simple, madr, parent) = (m.dof_simplenum(), m.dof_Madr(), m.dof_parentid());
                push_by_depth(madr, simple, parent, x, qld)
            }
            None => scatter_to_ancestors(m, x, qld),
        }
        for i in 0..nv {
            x[i] *= sqrt_inv[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::engine::MINVAL;

    /// A body with `n` links of `joint` below it, nested.
    fn chain(joint: &str, n: usize) -> String {
        let mut s = String::new();
        for _ in 0..n {
            s += &format!(r#"<body pos=".1 0 0"><joint {joint}/><geom size=".05" mass=".2"/>"#);
        }
        s + &"</body>".repeat(n)
    }

    /// 2.2.2's factorization: each row from the last pushed into its ancestors' rows.
    fn factor_pushed(madr: &[i32], parent: &[i32], simple: &[i32], qld: &mut [f64]) {
        let nm = qld.len();
        let len = |k: usize| madr.get(k + 1).map_or(nm, |&a| a as usize) - madr[k] as usize;
        for k in (0..madr.len()).rev() {
            let akk = madr[k] as usize;
            if qld[akk] < MINVAL {
                qld[akk] = MINVAL;
            }
            if simple[k] != 0 {
                continue;
            }
            let (mut i, mut adr) = (parent[k], akk + 1);
            while i >= 0 {
                let tmp = qld[adr] / qld[akk];
                let ai = madr[i as usize] as usize;
                for t in 0..len(i as usize) {
                    qld[ai + t] -= qld[adr + t] * tmp;
                }
                qld[adr] = tmp;
                (i, adr) = (parent[i as usize], adr + 1);
            }
        }
    }

    /// 2.2.2's solve: scatter to the ancestors along dof_parentid, skipping simple and zero
    /// entries; scale; gather from the ancestors.
    fn solve_by_parents(madr: &[i32], parent: &[i32], simple: &[i32], l: &[f64], x: &mut [f64]) {
        let nv = x.len();
        for i in (0..nv).rev() {
            let tmp = x[i];
            if simple[i] == 0 && tmp != 0.0 {
                let (mut j, mut adr) = (parent[i], madr[i] as usize + 1);
                while j >= 0 {
                    x[j as usize] -= l[adr] * tmp;
                    (j, adr) = (parent[j as usize], adr + 1);
                }
            }
        }
        for i in 0..nv {
            x[i] *= 1.0 / l[madr[i] as usize];
        }
        for i in 0..nv {
            if simple[i] == 0 {
                let (mut j, mut adr, mut tmp) = (parent[i], madr[i] as usize + 1, x[i]);
                while j >= 0 {
                    tmp -= l[adr] * x[j as usize];
                    (j, adr) = (parent[j as usize], adr + 1);
                }
                x[i] = tmp;
            }
        }
    }

    /// 2.2.2's mj_mulM: each dof's row times vec, and its ancestors' sums take its terms.
    fn mul_by_parents(
        madr: &[i32],
        parent: &[i32],
        simple: &[i32],
        qm: &[f64],
        v: &[f64],
    ) -> Vec<f64> {
        let mut res = vec![0.0; v.len()];
        for i in 0..v.len() {
            let adr = madr[i] as usize;
            if simple[i] != 0 {
                res[i] = qm[adr] * v[i];
                continue;
            }
            res[i] += qm[adr] * v[i];
            let (mut j, mut adr) = (parent[i], adr + 1);
            while j >= 0 {
                let ju = j as usize;
                res[i] += qm[adr] * v[ju];
                res[ju] += qm[adr] * v[i];
                (j, adr) = (parent[ju], adr + 1);
            }
        }
        res
    }

    /// Factorizations of trees that pull and trees that push, solves and products by depth
    /// and along dof_parentid, give 2.2.2's bit for bit: a forest of a branching deep tree, free bodies,
    /// a small arm and a point mass on slides (simple dofs), and a deep tree alone; random
    /// states, some with NaN, and right-hand sides with zeros, -0, NaN and infinities.
    #[test]
    fn factor_and_solve_by_tree_as_in_2_2_2() {
        let branches = |n: usize, joint: &str| (0..3).map(|_| chain(joint, n)).collect::<String>();
        let forest = format!(
            r#"<body><freejoint/><geom size=".1"/>{}</body>
            <body pos="1 0 0"><freejoint/><geom size=".1"/></body>
            <body pos="2 0 0"><freejoint/><geom size=".1"/></body>
            <body pos="0 1 0">{}</body>
            <body pos="0 2 0"><joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 1 0"/>
              <geom size=".1"/></body>"#,
            branches(6, r#"axis="0 1 0""#),
            chain(r#"axis="0 0 1""#, 3)
        );
        let deep = format!(
            r#"<body><freejoint/><geom size=".1"/>{}{}</body>"#,
            chain(r#"axis="0 1 0""#, 8),
            branches(6, r#"type="ball""#)
        );
        let mut uniform = crate::math::tests::uniform(7);
        let mut modes = [false; 3];
        for body in [forest, deep] {
            let xml = format!(
                r#"<mujoco><option><flag contact="disable"/></option>
                <worldbody>{body}</worldbody></mujoco>"#
            );
            let model = crate::api::Model::from_xml_str(&xml).unwrap();
            let mut data = model.make_data().unwrap();
            let (nq, nv) = (model.raw().nq as usize, model.raw().nv as usize);
            let qpos0 = data.qpos().to_vec();
            for k in 0..60 {
                let mut q: Vec<f64> = (0..nq).map(|i| qpos0[i] + uniform() - 0.5).collect();
                if k % 10 == 3 {
                    q[k % nq] = f64::NAN;
                }
                data.qpos_mut().copy_from_slice(&q);
                data.with_core(|m, d| {
                    let (madr, parent, simple) =
                        (m.dof_Madr(), m.dof_parentid(), m.dof_simplenum());
                    modes[2] |= simple.iter().any(|&s| s != 0);
                    crate::engine::forward::fwd_position(m, d)?;
                    let mut want = d.qM.to_vec();
                    factor_pushed(madr, parent, simple, &mut want);
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(d.qLD), bits(&want), "factor, state {k}");
                    let pulls = super::tree_pulls(madr, want.len(), nv - 1).0;
                    let deep = super::by_depth(m, d.qLD).is_some();
                    modes[0] |= pulls;
                    modes[1] |= deep;
                    for r in 0..8 {
                        let mut y: Vec<f64> = (0..nv).map(|_| uniform() - 0.5).collect();
                        for i in 0..nv {
                            y[i] = match (i + r) % 7 {
                                1 => 0.0,
                                2 if r == 2 => -0.0,
                                3 if r == 3 => f64::NAN,
                                4 if r == 4 => f64::INFINITY,
                                _ => y[i],
                            };
                        }
                        let mut want_x = y.clone();
                        solve_by_parents(madr, parent, simple, &want, &mut want_x);
                        let mut x = y.clone();
                        super::solve_ld(m, &mut x, None, 1, d.qLD, d.qLDiagInv);
                        assert_eq!(bits(&x), bits(&want_x), "solve, state {k}, rhs {r}");
                        let want_mv = mul_by_parents(madr, parent, simple, d.qM, &y);
                        let mut mv = vec![f64::NAN; nv];
                        crate::engine::jacobian::mul_m(m, d.qM, &mut mv, &y);
                        assert_eq!(bits(&mv), bits(&want_mv), "mulM, state {k}, rhs {r}");
                    }
                    Ok(())
                })
                .unwrap();
            }
        }
        assert_eq!(
            modes, [true; 3],
            "a tree that pulls, a solve by depth, a simple dof"
        );
    }
}
