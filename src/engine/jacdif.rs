//! Jacobian differences of two body points, dense or over the merged dof chain of the two
//! bodies (mj_jacDifPair with its sparse helpers: merge chains, chain-indexed Jacobians).

use super::jacobian::jac;
use super::Model;
use crate::abi::mjtJacobian_;
use crate::math::blas::sub;
use crate::math::*;

/// Does the model use sparse Jacobians (mj_isSparse)?
pub fn is_sparse(m: &Model) -> bool {
    let j = m.raw.opt.jacobian;
    j == mjtJacobian_::mjJAC_SPARSE as i32
        || (j == mjtJacobian_::mjJAC_AUTO as i32 && m.raw.nv >= 60)
}

/// First body at or above `b` that has dofs (0 when none).
fn movable(m: &Model, mut b: usize) -> usize {
    while b != 0 && m.body_dofnum()[b] == 0 {
        b = m.body_parentid()[b] as usize;
    }
    b
}

/// Increasing union of the dof ancestor chains of two bodies; returns its length.
pub fn merge_chain(m: &Model, chain: &mut [i32], b1: usize, b2: usize) -> usize {
    let (b1, b2) = (movable(m, b1), movable(m, b2));
    if b1 == 0 && b2 == 0 {
        return 0;
    }
    let last = |b: usize| m.body_dofadr()[b] + m.body_dofnum()[b] - 1;
    let (mut da1, mut da2) = (last(b1), last(b2));
    let mut n = 0;
    while da1 >= 0 || da2 >= 0 {
        let top = da1.max(da2);
        chain[n] = top;
        if da1 == top {
            da1 = m.dof_parentid()[da1 as usize];
        }
        if da2 == top {
            da2 = m.dof_parentid()[da2 as usize];
        }
        n += 1;
    }
    chain[..n].reverse();
    n
}

/// Chain of two simple bodies: the dofs of the lower-numbered body, then the other's.
pub fn merge_chain_simple(m: &Model, chain: &mut [i32], b1: usize, b2: usize) -> usize {
    let (lo, hi) = if b1 > b2 { (b2, b1) } else { (b1, b2) };
    let (n1, n2) = (m.body_dofnum()[lo] as usize, m.body_dofnum()[hi] as usize);
    for i in 0..n1 {
        chain[i] = m.body_dofadr()[lo] + i as i32;
    }
    for i in 0..n2 {
        chain[n1 + i] = m.body_dofadr()[hi] + i as i32;
    }
    n1 + n2
}

/// Jacobian of a point on `body` in the columns of `chain` (mj_jacSparse): translation in
/// `jacp` and, when given, rotation in `jacr`, each 3 x nc with nc = chain.len().
#[allow(clippy::too_many_arguments)]
pub fn jac_sparse(
    m: &Model,
    cdof: &[f64],
    subtree_com: &[f64],
    jacp: &mut [f64],
    mut jacr: Option<&mut [f64]>,
    point: &Vec3,
    body: usize,
    chain: &[i32],
) {
    let nc = chain.len();
    jacp[..3 * nc].fill(0.0);
    if let Some(r) = jacr.as_deref_mut() {
        r[..3 * nc].fill(0.0);
    }
    let root = m.body_rootid()[body] as usize;
    let offset = sub3(point, &v3(&subtree_com[3 * root..]));
    let b = movable(m, body);
    if b == 0 {
        return;
    }
    let mut da = m.body_dofadr()[b] + m.body_dofnum()[b] - 1;
    let mut ci = nc as isize - 1;
    while da >= 0 {
        while ci >= 0 && chain[ci as usize] > da {
            ci -= 1;
        }
        let c = &cdof[6 * da as usize..6 * da as usize + 6];
        let k = ci as usize;
        if let Some(r) = jacr.as_deref_mut() {
            r[k] = c[0];
            r[k + nc] = c[1];
            r[k + 2 * nc] = c[2];
        }
        let t = cross(&v3(c), &offset);
        jacp[k] = c[3] + t[0];
        jacp[k + nc] = c[4] + t[1];
        jacp[k + 2 * nc] = c[5] + t[2];
        da = m.dof_parentid()[da as usize];
    }
}

/// Writes +/- the Jacobian of a simple body's own dofs into columns from `start` of the
/// 3 x nc differences (translation, and rotation when given) (mj_jacSparseSimple).
#[allow(clippy::too_many_arguments)]
fn jac_sparse_simple(
    m: &Model,
    cdof: &[f64],
    subtree_com: &[f64],
    jacdifp: &mut [f64],
    mut jacdifr: Option<&mut [f64]>,
    point: &Vec3,
    body: usize,
    second: bool,
    nc: usize,
    start: usize,
) {
    let root = m.body_rootid()[body] as usize;
    let offset = sub3(point, &v3(&subtree_com[3 * root..]));
    let adr = m.body_dofadr()[body].max(0) as usize;
    let sign = |x: f64| if second { x } else { -x };
    for (k, da) in (adr..adr + m.body_dofnum()[body].max(0) as usize).enumerate() {
        let c = &cdof[6 * da..6 * da + 6];
        if let Some(r) = jacdifr.as_deref_mut() {
            for a in 0..3 {
                r[start + k + a * nc] = sign(c[a]);
            }
        }
        let t = cross(&v3(c), &offset);
        for a in 0..3 {
            jacdifp[start + k + a * nc] = sign(c[3 + a] + t[a]);
        }
    }
}

/// Jacobian difference jac(pos2 on b2) - jac(pos1 on b1) (mj_jacDifPair): translation in
/// `jacdif[..3n]` and, with `rot`, rotation in `jacdif[3nv..3nv + 3n]`; `jac1`, `jac2` hold the
/// two Jacobians the same way (scratch of 3nv, or 6nv with `rot`). Dense: n = nv; sparse: the
/// merged chain of n dofs is written to `chain`. Returns n (0: nothing to do).
#[allow(clippy::too_many_arguments)]
pub fn jac_dif_pair(
    m: &Model,
    cdof: &[f64],
    subtree_com: &[f64],
    chain: &mut [i32],
    b1: usize,
    b2: usize,
    pos1: &Vec3,
    pos2: &Vec3,
    jac1: &mut [f64],
    jac2: &mut [f64],
    jacdif: &mut [f64],
    rot: bool,
) -> usize {
    let nv = m.raw.nv as usize;
    if nv == 0 {
        return 0;
    }
    let simple = m.body_simple()[b1] != 0 && m.body_simple()[b2] != 0;
    let sparse = is_sparse(m);
    let n = if !sparse {
        nv
    } else if simple {
        merge_chain_simple(m, chain, b1, b2)
    } else {
        merge_chain(m, chain, b1, b2)
    };
    if n == 0 {
        return 0;
    }
    let (j1p, j1r) = jac1.split_at_mut(3 * nv);
    let (j2p, j2r) = jac2.split_at_mut(3 * nv);
    let (jdp, jdr) = jacdif.split_at_mut(3 * nv);
    fn pick(r: &mut [f64], rot: bool) -> Option<&mut [f64]> {
        rot.then_some(r)
    }
    if sparse && simple {
        let (n1, n2) = (m.body_dofnum()[b1] as usize, m.body_dofnum()[b2] as usize);
        let s1 = if b1 < b2 { 0 } else { n2 };
        let s2 = if b2 < b1 { 0 } else { n1 };
        jac_sparse_simple(
            m,
            cdof,
            subtree_com,
            jdp,
            pick(&mut *jdr, rot),
            pos1,
            b1,
            false,
            n,
            s1,
        );
        jac_sparse_simple(
            m,
            cdof,
            subtree_com,
            jdp,
            pick(&mut *jdr, rot),
            pos2,
            b2,
            true,
            n,
            s2,
        );
        return n;
    }
    if sparse {
        jac_sparse(
            m,
            cdof,
            subtree_com,
            j1p,
            pick(j1r, rot),
            pos1,
            b1,
            &chain[..n],
        );
        jac_sparse(
            m,
            cdof,
            subtree_com,
            j2p,
            pick(j2r, rot),
            pos2,
            b2,
            &chain[..n],
        );
    } else {
        jac(
            m,
            cdof,
            subtree_com,
            pos1,
            b1,
            Some(&mut *j1p),
            pick(j1r, rot),
        );
        jac(
            m,
            cdof,
            subtree_com,
            pos2,
            b2,
            Some(&mut *j2p),
            pick(j2r, rot),
        );
    }
    sub(&mut jdp[..3 * n], &j2p[..3 * n], &j1p[..3 * n]);
    if rot {
        sub(&mut jdr[..3 * n], &j2r[..3 * n], &j1r[..3 * n]);
    }
    n
}
