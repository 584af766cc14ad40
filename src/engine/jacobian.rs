//! Jacobians of points and frames; products with the sparse inertia matrix.

use super::linalg::{add_to_scl, row};
use super::tree::{deep, DofPath};
use super::{Data, EngineError, Model};
use crate::abi::view::Arena;
use crate::math::*;

/// Jacobian rows (3 x nv each) of a global point attached to `body` (mj_jac):
/// translation into `jacp`, rotation into `jacr`.
pub fn jac(
    m: &Model,
    cdof: &[f64],
    subtree_com: &[f64],
    point: &Vec3,
    body: usize,
    mut jacp: Option<&mut [f64]>,
    mut jacr: Option<&mut [f64]>,
) {
    let nv = m.raw.nv as usize;
    if let Some(j) = jacp.as_deref_mut() {
        j[..3 * nv].fill(0.0);
    }
    if let Some(j) = jacr.as_deref_mut() {
        j[..3 * nv].fill(0.0);
    }
    let offset = sub3(point, &row(subtree_com, m.body_rootid()[body] as usize));
    let mut b = body;
    while b != 0 && m.body_dofnum()[b] == 0 {
        b = m.body_parentid()[b] as usize;
    }
    if b == 0 {
        return;
    }
    let mut da = m.body_dofadr()[b] + m.body_dofnum()[b] - 1;
    while da >= 0 {
        let i = da as usize;
        let c = row::<6>(cdof, i);
        if let Some(j) = jacr.as_deref_mut() {
            j[i] = c[0];
            j[i + nv] = c[1];
            j[i + 2 * nv] = c[2];
        }
        if let Some(j) = jacp.as_deref_mut() {
            let t = cross(&[c[0], c[1], c[2]], &offset);
            j[i] = c[3] + t[0];
            j[i + nv] = c[4] + t[1];
            j[i + 2 * nv] = c[5] + t[2];
        }
        da = m.dof_parentid()[i];
    }
}

/// Jacobian of the subtree center of mass of `body` (mj_jacSubtreeCom).
pub fn jac_subtree_com(
    m: &Model,
    d: &mut Data,
    jacp: &mut [f64],
    body: usize,
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nbody = m.raw.nbody as usize;
    jacp[..3 * nv].fill(0.0);
    d.arena.scope(|a| -> Result<(), EngineError> {
        let jb = a.alloc(3 * nv)?;
        for b in body..nbody {
            if b > body && (m.body_parentid()[b] as usize) < body {
                break;
            }
            jac(
                m,
                d.cdof,
                d.subtree_com,
                &row(d.xipos, b),
                b,
                Some(&mut *jb),
                None,
            );
            add_to_scl(&mut jacp[..3 * nv], jb, m.body_mass()[b]);
        }
        Ok(())
    })?;
    let s = 1.0 / m.body_subtreemass()[body];
    for x in &mut jacp[..3 * nv] {
        *x *= s;
    }
    Ok(())
}

/// Point Jacobian and the Jacobian of a rotating axis (mj_jacPointAxis).
pub fn jac_point_axis(
    m: &Model,
    d: &mut Data,
    jac_point: Option<&mut [f64]>,
    jac_axis: Option<&mut [f64]>,
    point: &Vec3,
    axis: &Vec3,
    body: usize,
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    d.arena.scope(|a| -> Result<(), EngineError> {
        let jacr = a.alloc(3 * nv)?;
        match jac_point {
            Some(p) => jac(
                m,
                d.cdof,
                d.subtree_com,
                point,
                body,
                Some(p),
                Some(&mut *jacr),
            ),
            None => {
                let p = a.alloc(3 * nv)?;
                jac(
                    m,
                    d.cdof,
                    d.subtree_com,
                    point,
                    body,
                    Some(p),
                    Some(&mut *jacr),
                )
            }
        }
        if let Some(ja) = jac_axis {
            for i in 0..nv {
                ja[i] = jacr[nv + i] * axis[2] - jacr[2 * nv + i] * axis[1];
                ja[nv + i] = jacr[2 * nv + i] * axis[0] - jacr[i] * axis[2];
                ja[2 * nv + i] = jacr[i] * axis[1] - jacr[nv + i] * axis[0];
            }
        }
        Ok(())
    })
}

/// Dense nv x nv matrix from the sparse inertia layout (mj_fullM).
pub fn full_m(m: &Model, dst: &mut [f64], mat: &[f64]) {
    let nv = m.raw.nv as usize;
    dst[..nv * nv].fill(0.0);
    let mut adr = 0;
    for i in 0..nv {
        let mut j = i as i32;
        while j >= 0 {
            let ju = j as usize;
            dst[i * nv + ju] = mat[adr];
            dst[ju * nv + i] = mat[adr];
            j = m.dof_parentid()[ju];
            adr += 1;
        }
    }
}

/// res = M * vec with M in the sparse inertia layout (mj_mulM).
pub fn mul_m(m: &Model, qm: &[f64], res: &mut [f64], vec: &[f64]) {
    let nv = m.raw.nv as usize;
    if deep(nv, m.raw.nM as usize, 8) {
        return mul_m_on_path(m, qm, res, vec);
    }
    let (madr, simple, parent) = (m.dof_Madr(), m.dof_simplenum(), m.dof_parentid());
    let (res, vec) = (&mut res[..nv], &vec[..nv]);
    // res[i] is first written at step i (only dofs after i add to it, their ancestors being
    // before them): 2.2.2's cleared +0 is added in place of a load, and nothing is cleared
    for i in 0..nv {
        let adr = madr[i] as usize;
        let vi = vec[i];
        if simple[i] != 0 {
            res[i] = qm[adr] * vi;
        } else {
            let ri = 0.0 + qm[adr] * vi;
            res[i] = by_parents(&qm[adr + 1..], parent[i], parent, vec, res, vi, ri);
        }
    }
}

/// `mul_m` in deep trees, the ancestors read from a `DofPath` (humanoid: a fifth faster,
/// the dog: two fifths).
#[inline(never)]
fn mul_m_on_path(m: &Model, qm: &[f64], res: &mut [f64], vec: &[f64]) {
    let nv = m.raw.nv as usize;
    let (madr, simple, parent) = (m.dof_Madr(), m.dof_simplenum(), m.dof_parentid());
    let (res, vec) = (&mut res[..nv], &vec[..nv]);
    // as in `mul_m`: res[i] is first written at step i
    let mut path = DofPath::new();
    for i in 0..nv {
        let adr = madr[i] as usize;
        let vi = vec[i];
        let ancestors = path.next(i, parent[i]);
        if simple[i] != 0 {
            res[i] = qm[adr] * vi;
            continue;
        }
        let mut ri = 0.0 + qm[adr] * vi;
        if let Some(a) = ancestors {
            for (&q, &j) in qm[adr + 1..adr + 1 + a.len()].iter().zip(a.iter().rev()) {
                let ju = j as usize;
                ri += q * vec[ju];
                res[ju] += q * vi;
            }
        } else {
            ri = by_parents(&qm[adr + 1..], parent[i], parent, vec, res, vi, ri);
        }
        res[i] = ri;
    }
}

/// The rest of a row of mj_mulM, its ancestors found through dof_parentid from `j`:
/// ri += M(i,j) * vec(j) and res(j) += M(i,j) * vec(i) in turn; gives ri.
#[inline(always)]
fn by_parents(
    row: &[f64],
    mut j: i32,
    parent: &[i32],
    vec: &[f64],
    res: &mut [f64],
    vi: f64,
    mut ri: f64,
) -> f64 {
    for &q in row {
        if j < 0 {
            break;
        }
        let ju = j as usize;
        ri += q * vec[ju];
        res[ju] += q * vi;
        j = parent[ju];
    }
    ri
}

/// res = M^(1/2) * vec using the factorization (mj_mulM2).
pub fn mul_m2(m: &Model, qld: &[f64], sqrt_inv: &[f64], res: &mut [f64], vec: &[f64]) {
    let nv = m.raw.nv as usize;
    res[..nv].fill(0.0);
    for i in 0..nv {
        if m.dof_simplenum()[i] != 0 {
            res[i] = vec[i] / sqrt_inv[i];
        } else {
            let mut adr = m.dof_Madr()[i] as usize;
            res[i] += vec[i] / sqrt_inv[i];
            let mut j = m.dof_parentid()[i];
            adr += 1;
            while j >= 0 {
                let ju = j as usize;
                res[i] += qld[adr] * vec[ju];
                j = m.dof_parentid()[ju];
                adr += 1;
            }
        }
    }
}

/// dst += M, dst dense nv x nv (mj_addM without sparse arguments); with `upper` false, only
/// the lower triangle of dst (what a Cholesky factorization reads).
pub fn add_m_dense(m: &Model, qm: &[f64], dst: &mut [f64], upper: bool) {
    let nv = m.raw.nv as usize;
    for i in 0..nv {
        for (j, adr) in m_row(m, i) {
            dst[i * nv + j] += qm[adr];
            if upper && j < i {
                dst[j * nv + i] += qm[adr];
            }
        }
    }
}

/// The entries of row i of M's lower triangle that mj_addM adds, as (column, address in qM):
/// the diagonal, then i's ancestors unless dof i is simple.
pub(crate) fn m_row<'b>(m: &'b Model, i: usize) -> MRow<'b> {
    MRow {
        parent: m.dof_parentid(),
        simple: m.dof_simplenum()[i] != 0,
        j: i as i32,
        adr: m.dof_Madr()[i] as usize,
    }
}

/// Iterator of `m_row`.
pub(crate) struct MRow<'a> {
    parent: &'a [i32],
    simple: bool,
    j: i32,
    adr: usize,
}

impl Iterator for MRow<'_> {
    type Item = (usize, usize);

    #[inline]
    fn next(&mut self) -> Option<(usize, usize)> {
        if self.j < 0 {
            return None;
        }
        let item = (self.j as usize, self.adr);
        self.j = if self.simple { -1 } else { self.parent[item.0] };
        self.adr += 1;
        Some(item)
    }
}

/// dst += src (sparse, mj_combineSparse with a = b = 1); returns the new nnz of dst.
fn combine_sparse(
    dst: &mut [f64],
    dst_ind: &mut [i32],
    dst_nnz: usize,
    src: &[f64],
    src_ind: &[i32],
    buf: &mut [f64],
    buf_ind: &mut [i32],
) -> usize {
    let n = i32::MAX as usize - 1; // past every column index
    crate::math::sparse::combine_sparse(
        dst,
        src,
        n,
        1.0,
        1.0,
        dst_nnz,
        src.len(),
        dst_ind,
        src_ind,
        buf,
        buf_ind,
    )
}

/// dst += M for a sparse uncompressed destination (mj_addM with row descriptors).
pub fn add_m_sparse(
    m: &Model,
    d: &mut Data,
    dst: &mut [f64],
    rownnz: &mut [i32],
    rowadr: &[i32],
    colind: &mut [i32],
) -> Result<(), EngineError> {
    add_m_sparse_with(m, d.qM, &mut d.arena, dst, rownnz, rowadr, colind, true)
}

/// `add_m_sparse` for a given qM, with scratch from `arena`; with `upper` false, M's lower
/// triangle only, into rows of dst that end at their diagonal (what a Cholesky factorization
/// reads), each value as the whole sum gives it.
#[allow(clippy::too_many_arguments)]
pub fn add_m_sparse_with(
    m: &Model,
    qm: &[f64],
    arena: &mut Arena,
    dst: &mut [f64],
    rownnz: &mut [i32],
    rowadr: &[i32],
    colind: &mut [i32],
    upper: bool,
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let madr = m.dof_Madr();
    let simple = m.dof_simplenum();
    let mut nsimple = 0;
    for i in 0..nv {
        if simple[i] == 0 {
            continue;
        }
        nsimple += 1;
        let adr = rowadr[i] as usize;
        if rownnz[i] == 0 {
            colind[adr] = i as i32;
            dst[adr] = qm[madr[i] as usize];
            rownnz[i] = 1;
        } else {
            let end = adr + rownnz[i] as usize;
            match (adr..end).find(|&k| colind[k] == i as i32) {
                Some(k) => dst[k] += qm[madr[i] as usize],
                None => {
                    return Err(EngineError(
                        "mj_addM sparse: dst row expected to be empty".into(),
                    ))
                }
            }
        }
    }
    if nsimple == nv {
        return Ok(());
    }
    arena.scope(|a| -> Result<(), EngineError> {
        let mat = a.alloc_stale(nv * nv)?;
        let mcol = a.alloc_int_stale(nv * nv)?;
        let mnnz = a.alloc_int(nv)?;
        // the rows' addresses (2.2.2 takes these nv ints too): i*nv for the mirror, one row
        // after another otherwise (far less memory touched)
        let madr_row = a.alloc_int_stale(nv)?;
        let buf = a.alloc(nv)?;
        let buf_ind = a.alloc_int(nv)?;
        // lower triangle of M, rows in ascending column order
        let mut next = 0;
        for i in 0..nv {
            let row = if upper { i * nv } else { next };
            madr_row[i] = row as i32;
            if simple[i] != 0 {
                continue;
            }
            let mut adr = madr[i] as usize;
            let mut j = i as i32;
            let mut cnt = 0;
            while j >= 0 {
                mat[row + cnt] = qm[adr];
                mcol[row + cnt] = j;
                cnt += 1;
                adr += 1;
                j = m.dof_parentid()[j as usize];
            }
            mnnz[i] = cnt as i32;
            mat[row..row + cnt].reverse();
            mcol[row..row + cnt].reverse();
            next = row + cnt;
        }
        // the upper triangle too (simple rows are empty: nothing to mirror from them)
        if upper {
            crate::math::sparse::mirror_lower_sparse(mat, nv, mnnz, mcol);
        }
        for i in 0..nv {
            if simple[i] != 0 {
                continue;
            }
            let adr = rowadr[i] as usize;
            let (row, cnt) = (madr_row[i] as usize, mnnz[i] as usize);
            rownnz[i] = combine_sparse(
                &mut dst[adr..],
                &mut colind[adr..],
                rownnz[i] as usize,
                &mat[row..row + cnt],
                &mcol[row..row + cnt],
                buf,
                buf_ind,
            ) as i32;
        }
        Ok(())
    })
}
