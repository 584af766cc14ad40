//! Constraint instantiation, dense or sparse Jacobian: equality (connect, weld, joint, tendon),
//! dof and tendon friction, joint and tendon limit rows; their soft-constraint parameters
//! (diagApprox, impedance, KBIP, R, D), the reference acceleration, the projection AR for dual
//! solvers, and the constraint-state update of the primal cost. Contact rows: see contact.rs.

use super::inertia::solve_m2;
pub use super::jacdif::jac_dif_pair;
use super::linalg::{max, min};
use super::support::warning;
use super::{disabled, not_implemented, Data, EngineError, Model, MINVAL};
use super::{JNT_BALL, JNT_HINGE, JNT_SLIDE};
use crate::abi::view::Arena;
use crate::abi::*;
use crate::math::blas::{add_to_scl, mul_mat_t_vec, mul_mat_vec, norm, sqr_mat_td, transpose};
use crate::math::misc::{kept_or_neg_zero, minus_one};
use crate::math::sparse::{
    combine_sparse, compress_sparse, mirror_lower_sparse, mul_mat_vec_sparse,
    sqr_mat_td_sparse_lower, super_sparse, transpose_sparse, SparseRef,
};
use crate::math::*;
use mjtConstraintState_::*;
use mjtConstraint_::*;

const EQUALITY: i32 = mjCNSTR_EQUALITY as i32;
const FRICTION_DOF: i32 = mjCNSTR_FRICTION_DOF as i32;
const FRICTION_TENDON: i32 = mjCNSTR_FRICTION_TENDON as i32;
const LIMIT_JOINT: i32 = mjCNSTR_LIMIT_JOINT as i32;
const LIMIT_TENDON: i32 = mjCNSTR_LIMIT_TENDON as i32;
const CONTACT_ELLIPTIC: i32 = mjCNSTR_CONTACT_ELLIPTIC as i32;
const EQ_CONNECT: i32 = mjtEq_::mjEQ_CONNECT as i32;
const EQ_WELD: i32 = mjtEq_::mjEQ_WELD as i32;
const EQ_JOINT: i32 = mjtEq_::mjEQ_JOINT as i32;
const EQ_TENDON: i32 = mjtEq_::mjEQ_TENDON as i32;
const EQ_DISTANCE: i32 = mjtEq_::mjEQ_DISTANCE as i32;
const MINIMP: f64 = 0.0001;
const MAXIMP: f64 = 0.9999;

/// Is the friction cone pyramidal (mj_isPyramidal)?
pub fn is_pyramidal(m: &Model) -> bool {
    m.raw.opt.cone == mjtCone_::mjCONE_PYRAMIDAL as i32
}

pub use super::jacdif::is_sparse;

/// Does the solver work in the dual (mj_isDual)?
pub fn is_dual(m: &Model) -> bool {
    m.raw.opt.solver == mjtSolver_::mjSOL_PGS as i32 || m.raw.opt.noslip_iterations > 0
}

/// The constraint Jacobian of an mjData: dense (nefc x nv) or sparse with its transpose.
pub struct JacView<'x> {
    pub sparse: bool,
    pub nv: usize,
    pub nefc: usize,
    pub j: &'x [f64],
    pub rownnz: &'x [i32],
    pub rowadr: &'x [i32],
    pub colind: &'x [i32],
    pub jt: &'x [f64],
    pub t_rownnz: &'x [i32],
    pub t_rowadr: &'x [i32],
    pub t_colind: &'x [i32],
    /// supernodes of J and J' as make_constraint left them; None where the caller may have
    /// changed J since (the exported products)
    pub rowsuper: Option<&'x [i32]>,
    pub t_rowsuper: Option<&'x [i32]>,
}

/// Borrows the Jacobian fields of `d` (field by field, so other fields stay writable).
macro_rules! jac_view {
    ($m:expr, $d:expr) => {
        $crate::engine::constraint::JacView {
            sparse: $crate::engine::constraint::is_sparse($m),
            nv: $m.raw.nv as usize,
            nefc: $d.raw.nefc as usize,
            j: &*$d.efc_J,
            rownnz: &*$d.efc_J_rownnz,
            rowadr: &*$d.efc_J_rowadr,
            colind: &*$d.efc_J_colind,
            jt: &*$d.efc_JT,
            t_rownnz: &*$d.efc_JT_rownnz,
            t_rowadr: &*$d.efc_JT_rowadr,
            t_colind: &*$d.efc_JT_colind,
            rowsuper: Some(&*$d.efc_J_rowsuper),
            t_rowsuper: Some(&*$d.efc_JT_rowsuper),
        }
    };
}
pub(crate) use jac_view;

impl JacView<'_> {
    /// res = J * vec (mj_mulJacVec).
    pub fn mul_vec(&self, res: &mut [f64], vec: &[f64]) {
        if self.nefc == 0 {
            return;
        }
        if self.sparse {
            mul_mat_vec_sparse(
                res,
                self.j,
                vec,
                self.nefc,
                self.rownnz,
                self.rowadr,
                self.colind,
                self.rowsuper,
            );
        } else {
            mul_mat_vec(res, self.j, vec, self.nefc, self.nv);
        }
    }

    /// res = J' * vec (mj_mulJacTVec).
    pub fn mul_t_vec(&self, res: &mut [f64], vec: &[f64]) {
        if self.nefc == 0 {
            return;
        }
        if self.sparse {
            let (nnz, adr, ind) = (self.t_rownnz, self.t_rowadr, self.t_colind);
            mul_mat_vec_sparse(res, self.jt, vec, self.nv, nnz, adr, ind, self.t_rowsuper);
        } else {
            mul_mat_t_vec(res, self.j, vec, self.nefc, self.nv);
        }
    }

    /// Row i as (values, column indices); dense rows have no index list.
    pub fn row(&self, i: usize) -> (&[f64], Option<&[i32]>) {
        if self.sparse {
            let (adr, n) = (self.rowadr[i] as usize, self.rownnz[i] as usize);
            (&self.j[adr..adr + n], Some(&self.colind[adr..adr + n]))
        } else {
            (&self.j[i * self.nv..(i + 1) * self.nv], None)
        }
    }
}

/// res = efc_J * vec for the exported mj_mulJacVec.
pub fn mul_jac_vec(
    m: &Model,
    d: &mut Data,
    res: &mut [f64],
    vec: &[f64],
) -> Result<(), EngineError> {
    let j = JacView {
        rowsuper: None,
        ..jac_view!(m, d)
    };
    j.mul_vec(res, vec);
    Ok(())
}

/// res = efc_J' * vec for the exported mj_mulJacTVec.
pub fn mul_jac_t_vec(
    m: &Model,
    d: &mut Data,
    res: &mut [f64],
    vec: &[f64],
) -> Result<(), EngineError> {
    let j = JacView {
        t_rowsuper: None,
        ..jac_view!(m, d)
    };
    j.mul_t_vec(res, vec);
    Ok(())
}

/// Appends `size` rows unless they are empty (mj_addConstraint): dense rows are `size` x nv,
/// sparse rows `size` x chain.len() over the dofs in `chain`. Returns false when the buffer is
/// full (warning issued).
#[allow(clippy::too_many_arguments)]
pub(super) fn add_rows(
    m: &Model,
    d: &mut Data,
    jacobian: &[f64],
    chain: Option<&[i32]>,
    pos: Option<&[f64]>,
    margin: Option<&[f64]>,
    frictionloss: f64,
    size: usize,
    kind: i32,
    id: usize,
) -> Result<bool, EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    if nefc + size > m.raw.njmax as usize {
        warning(d.raw, mjtWarning_::mjWARN_CNSTRFULL as i32, m.raw.njmax)?;
        return Ok(false);
    }
    // contact rows are never skipped as empty
    let contact = super::contact::is_contact(kind);
    if !is_sparse(m) {
        if !contact && jacobian[..size * nv].iter().all(|&x| x == 0.0) {
            return Ok(true);
        }
        d.efc_J[nefc * nv..(nefc + size) * nv].copy_from_slice(&jacobian[..size * nv]);
    } else {
        let chain = chain.ok_or_else(|| {
            EngineError("Sparse mj_addConstraint called with dense arguments".into())
        })?;
        let n = chain.len();
        for i in nefc..nefc + size {
            let adr = if i > 0 {
                d.efc_J_rowadr[i - 1] + d.efc_J_rownnz[i - 1]
            } else {
                0
            };
            d.efc_J_rowadr[i] = adr;
            d.efc_J_rownnz[i] = n as i32;
            let adr = adr as usize;
            d.efc_J_colind[adr..adr + n].copy_from_slice(chain);
            d.efc_J[adr..adr + n].copy_from_slice(&jacobian[(i - nefc) * n..(i - nefc + 1) * n]);
        }
        if n == 0 && !contact {
            return Ok(true);
        }
    }
    for i in 0..size {
        d.efc_pos[nefc + i] = pos.map_or(0.0, |p| p[i]);
        d.efc_margin[nefc + i] = margin.map_or(0.0, |p| p[i]);
        d.efc_frictionloss[nefc + i] = frictionloss;
        d.efc_type[nefc + i] = kind;
        d.efc_id[nefc + i] = id as i32;
    }
    d.raw.nefc += size as i32;
    if kind == EQUALITY {
        d.raw.ne += size as i32;
    } else if kind == FRICTION_DOF || kind == FRICTION_TENDON {
        d.raw.nf += size as i32;
    }
    Ok(true)
}

/// Copies tendon i's Jacobian row into `jacobian` (dense: nv values; sparse: its nonzeros);
/// returns the row's (address, length) in the sparse `ten_J` (None when dense).
fn tendon_jac(m: &Model, d: &Data, i: usize, jacobian: &mut [f64]) -> Option<(usize, usize)> {
    let nv = m.raw.nv as usize;
    if is_sparse(m) {
        let (adr, n) = (d.ten_J_rowadr[i] as usize, d.ten_J_rownnz[i] as usize);
        jacobian[..n].copy_from_slice(&d.ten_J[adr..adr + n]);
        Some((adr, n))
    } else {
        jacobian[..nv].copy_from_slice(&d.ten_J[i * nv..(i + 1) * nv]);
        None
    }
}

/// Runs `f` with the dofs of a sparse tendon row (`tendon_jac`'s address and length) read in
/// place from `ten_J_colind`, as 2.2.2 passes them (no scratch chain on the stack).
fn with_tendon_chain<R>(
    d: &mut Data,
    adr: Option<(usize, usize)>,
    f: impl FnOnce(&mut Data, Option<&[i32]>) -> R,
) -> R {
    let colind = std::mem::take(&mut d.ten_J_colind);
    let r = f(d, adr.map(|(a, n)| &colind[a..a + n]));
    d.ten_J_colind = colind;
    r
}

/// Copies tendon i's Jacobian row into `jacobian` (dense: nv values; sparse: its nonzeros, with
/// their dofs in `chain`); returns the sparse length (0 when dense).
fn tendon_row(m: &Model, d: &Data, i: usize, jacobian: &mut [f64], chain: &mut [i32]) -> usize {
    let nv = m.raw.nv as usize;
    if is_sparse(m) {
        let (adr, n) = (d.ten_J_rowadr[i] as usize, d.ten_J_rownnz[i] as usize);
        jacobian[..n].copy_from_slice(&d.ten_J[adr..adr + n]);
        chain[..n].copy_from_slice(&d.ten_J_colind[adr..adr + n]);
        n
    } else {
        jacobian[..nv].copy_from_slice(&d.ten_J[i * nv..(i + 1) * nv]);
        0
    }
}

/// Equality rows: connect (3), weld (6), joint or tendon coupling (1).
#[inline(never)]
fn equality(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let sparse = is_sparse(m);
    let j0 = a.alloc(6 * nv)?;
    let j1 = a.alloc(6 * nv)?;
    let jd = a.alloc(6 * nv)?;
    // the chains and the merge buffers only for sparse Jacobians, as 2.2.2 takes them
    let (chain, chain2, buf_ind, buf): (&mut [i32], &mut [i32], &mut [i32], &mut [f64]) = if sparse
    {
        (
            a.alloc_int(nv)?,
            a.alloc_int(nv)?,
            a.alloc_int(nv)?,
            a.alloc(nv)?,
        )
    } else {
        (&mut [], &mut [], &mut [], &mut [])
    };
    for i in 0..m.raw.neq as usize {
        if m.eq_active()[i] == 0 {
            continue;
        }
        let data = &m.eq_data()[mjNEQDATA * i..mjNEQDATA * (i + 1)];
        let id = [m.eq_obj1id()[i], m.eq_obj2id()[i]];
        let mut cpos = [0.0; 6];
        let size;
        let mut n;
        match m.eq_type()[i] {
            EQ_CONNECT | EQ_WELD => {
                let weld = m.eq_type()[i] == EQ_WELD;
                let mut pos = [[0.0; 3]; 2];
                for k in 0..2 {
                    let b = id[k] as usize;
                    // connect: anchor k on body k; weld: anchor 1-k on body k
                    let at = if weld { 3 * (1 - k) } else { 3 * k };
                    let local = mul_mat_vec3(&m9(&d.xmat[9 * b..]), &v3(&data[at..]));
                    pos[k] = add3(&local, &v3(&d.xpos[3 * b..]));
                }
                cpos[..3].copy_from_slice(&sub3(&pos[0], &pos[1]));
                let (b0, b1) = (id[0] as usize, id[1] as usize);
                n = jac_dif_pair(
                    m,
                    d.cdof,
                    d.subtree_com,
                    chain,
                    b1,
                    b0,
                    &pos[1],
                    &pos[0],
                    j1,
                    j0,
                    jd,
                    weld,
                );
                j0[..3 * n].copy_from_slice(&jd[..3 * n]);
                if weld {
                    j0[3 * n..6 * n].copy_from_slice(&jd[3 * nv..3 * nv + 3 * n]);
                    let q = mul_quat(&q4(&d.xquat[4 * b0..]), &q4(&data[6..]));
                    let q1 = neg_quat(&q4(&d.xquat[4 * b1..]));
                    let q2 = mul_quat(&q1, &q);
                    cpos[3..].copy_from_slice(&q2[1..]);
                    for k in 0..n {
                        let axis = [j0[3 * n + k], j0[4 * n + k], j0[5 * n + k]];
                        let q3 = mul_quat(&mul_quat_axis(&q1, &axis), &q);
                        j0[3 * n + k] = 0.5 * q3[1];
                        j0[4 * n + k] = 0.5 * q3[2];
                        j0[5 * n + k] = 0.5 * q3[3];
                    }
                    let torquescale = data[10];
                    for x in &mut j0[3 * n..6 * n] {
                        *x *= torquescale;
                    }
                    size = 6;
                } else {
                    size = 3;
                }
            }
            EQ_JOINT | EQ_TENDON => {
                let joint = m.eq_type()[i] == EQ_JOINT;
                let mut pos = [0.0; 2];
                let mut refpos = [0.0; 2];
                let nobj = if id[1] >= 0 { 2 } else { 1 };
                let mut nnz = [0usize; 2];
                for k in 0..nobj {
                    let ob = id[k] as usize;
                    let jk = if k == 0 { &mut *j0 } else { &mut *j1 };
                    let ck = if k == 0 { &mut *chain } else { &mut *chain2 };
                    if joint {
                        let qadr = m.jnt_qposadr()[ob] as usize;
                        let dof = m.jnt_dofadr()[ob];
                        pos[k] = d.qpos[qadr];
                        refpos[k] = m.qpos0()[qadr];
                        if sparse {
                            nnz[k] = 1;
                            ck[0] = dof;
                            jk[0] = 1.0;
                        } else {
                            jk[..nv].fill(0.0);
                            jk[dof as usize] = 1.0;
                        }
                    } else {
                        pos[k] = d.ten_length[ob];
                        refpos[k] = m.tendon_length0()[ob];
                        nnz[k] = tendon_row(m, d, ob, jk, ck);
                    }
                }
                n = nnz[0];
                if nobj == 2 {
                    let dif = pos[1] - refpos[1];
                    cpos[0] = pos[0]
                        - refpos[0]
                        - data[0]
                        - (data[1] * dif
                            + data[2] * dif * dif
                            + data[3] * dif * dif * dif
                            + data[4] * dif * dif * dif * dif);
                    let deriv = data[1]
                        + 2.0 * data[2] * dif
                        + 3.0 * data[3] * dif * dif
                        + 4.0 * data[4] * dif * dif * dif;
                    if sparse {
                        n = combine_sparse(
                            j0, j1, nv, 1.0, -deriv, nnz[0], nnz[1], chain, chain2, buf, buf_ind,
                        );
                    } else {
                        add_to_scl(&mut j0[..nv], &j1[..nv], -deriv);
                    }
                } else {
                    cpos[0] = pos[0] - refpos[0] - data[0];
                }
                size = 1;
            }
            EQ_DISTANCE => {
                return Err(EngineError(
                    "distance equality constraints are no longer supported".into(),
                ))
            }
            t => return Err(EngineError(format!("Invalid equality constraint type {t}"))),
        }
        let ch = if sparse { Some(&chain[..n]) } else { None };
        if !add_rows(m, d, j0, ch, Some(&cpos), None, 0.0, size, EQUALITY, i)? {
            break;
        }
    }
    Ok(())
}

/// Dry-friction rows of dofs (tendon friction is not implemented).
fn friction(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_FRICTIONLOSS) {
        return Ok(());
    }
    let sparse = is_sparse(m);
    let j = a.alloc(nv)?;
    for i in 0..nv {
        let f = m.dof_frictionloss()[i];
        if f > 0.0 {
            if sparse {
                j[0] = 1.0;
            } else {
                j.fill(0.0);
                j[i] = 1.0;
            }
            let ch = [i as i32];
            let ch = if sparse { Some(&ch[..]) } else { None };
            if !add_rows(m, d, j, ch, None, None, f, 1, FRICTION_DOF, i)? {
                break;
            }
        }
    }
    for i in 0..m.raw.ntendon as usize {
        let f = m.tendon_frictionloss()[i];
        if f > 0.0 {
            let adr = tendon_jac(m, d, i, j);
            let added = with_tendon_chain(d, adr, |d, ch| {
                add_rows(m, d, j, ch, None, None, f, 1, FRICTION_TENDON, i)
            })?;
            if !added {
                break;
            }
        }
    }
    Ok(())
}

/// Joint-limit rows (tendon limits are not implemented).
fn limits(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_LIMIT) {
        return Ok(());
    }
    let sparse = is_sparse(m);
    let j = a.alloc(nv)?;
    for i in 0..m.raw.njnt as usize {
        if m.jnt_limited()[i] == 0 {
            continue;
        }
        let margin = m.jnt_margin()[i];
        let qadr = m.jnt_qposadr()[i] as usize;
        let dofadr = m.jnt_dofadr()[i] as usize;
        match m.jnt_type()[i] {
            JNT_SLIDE | JNT_HINGE => {
                let value = d.qpos[qadr];
                for side in [-1.0f64, 1.0] {
                    let lim = m.jnt_range()[2 * i + (side > 0.0) as usize];
                    let dist = side * (lim - value);
                    if dist < margin {
                        let ch = [dofadr as i32];
                        let ch = if sparse {
                            j[0] = -side;
                            Some(&ch[..])
                        } else {
                            j.fill(0.0);
                            j[dofadr] = -side;
                            None
                        };
                        let (p, mg) = ([dist], [margin]);
                        if !add_rows(m, d, j, ch, Some(&p), Some(&mg), 0.0, 1, LIMIT_JOINT, i)? {
                            // 2.2.2 leaves only the side loop here
                            break;
                        }
                    }
                }
            }
            JNT_BALL => {
                let (axis, value) = normalize3(&quat2vel(&q4(&d.qpos[qadr..]), 1.0));
                let dist = max(m.jnt_range()[2 * i], m.jnt_range()[2 * i + 1]) - value;
                if dist < margin {
                    let a0 = dofadr as i32;
                    let ch = [a0, a0 + 1, a0 + 2];
                    let ch = if sparse {
                        j[..3].copy_from_slice(&scl3(&axis, minus_one()));
                        Some(&ch[..])
                    } else {
                        j.fill(0.0);
                        j[dofadr..dofadr + 3].copy_from_slice(&scl3(&axis, minus_one()));
                        None
                    };
                    let (p, mg) = ([dist], [margin]);
                    if !add_rows(m, d, j, ch, Some(&p), Some(&mg), 0.0, 1, LIMIT_JOINT, i)? {
                        break;
                    }
                }
            }
            _ => {}
        }
    }
    for i in 0..m.raw.ntendon as usize {
        if m.tendon_limited()[i] == 0 {
            continue;
        }
        let value = d.ten_length[i];
        let margin = m.tendon_margin()[i];
        for side in [-1.0f64, 1.0] {
            let lim = m.tendon_range()[2 * i + (side > 0.0) as usize];
            let dist = side * (lim - value);
            if dist < margin {
                let adr = tendon_jac(m, d, i, j);
                let len = adr.map_or(nv, |(_, n)| n);
                for x in &mut j[..len] {
                    *x *= -side;
                }
                let (p, mg) = ([dist], [margin]);
                let added = with_tendon_chain(d, adr, |d, ch| {
                    add_rows(m, d, j, ch, Some(&p), Some(&mg), 0.0, 1, LIMIT_TENDON, i)
                })?;
                if !added {
                    break;
                }
            }
        }
    }
    Ok(())
}

/// Approximate inverse inertia of each row (mj_diagApprox).
fn diag_approx(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let iw = m.body_invweight0();
    let dw = m.dof_invweight0();
    let tw = m.tendon_invweight0();
    let nefc = d.raw.nefc as usize;
    let mut i = 0;
    while i < nefc {
        if super::contact::is_contact(d.efc_type[i]) {
            i += super::contact::diag_approx(m, d, i);
            continue;
        }
        let id = d.efc_id[i] as usize;
        d.efc_diagApprox[i] = match d.efc_type[i] {
            EQUALITY => match m.eq_type()[id] {
                // weld rows use translational weights only: 2.2.2's row counter for weld
                // resets on every equality row
                EQ_CONNECT | EQ_WELD => {
                    let (b1, b2) = (m.eq_obj1id()[id] as usize, m.eq_obj2id()[id] as usize);
                    iw[2 * b1] + iw[2 * b2]
                }
                EQ_JOINT => {
                    let mut v = dw[m.jnt_dofadr()[m.eq_obj1id()[id] as usize] as usize];
                    let o2 = m.eq_obj2id()[id];
                    if o2 >= 0 {
                        v += dw[m.jnt_dofadr()[o2 as usize] as usize];
                    }
                    v
                }
                EQ_TENDON => {
                    let mut v = tw[m.eq_obj1id()[id] as usize];
                    let o2 = m.eq_obj2id()[id];
                    if o2 >= 0 {
                        v += tw[o2 as usize];
                    }
                    v
                }
                _ => return Err(not_implemented("this equality type is")),
            },
            FRICTION_DOF => dw[id],
            LIMIT_JOINT => dw[m.jnt_dofadr()[id] as usize],
            FRICTION_TENDON | LIMIT_TENDON => tw[id],
            _ => return Err(not_implemented("this constraint type is")),
        };
        i += 1;
    }
    Ok(())
}

/// solref and solimp of row i after the safety adjustments.
fn sol_params(m: &Model, d: &Data, i: usize) -> ([f64; 2], [f64; 5]) {
    let id = d.efc_id[i] as usize;
    let contact;
    let (sr, si) = match d.efc_type[i] {
        t if super::contact::is_contact(t) => {
            contact = (d.contact[id].solref, d.contact[id].solimp);
            (&contact.0[..], &contact.1[..])
        }
        EQUALITY => (m.eq_solref(), m.eq_solimp()),
        LIMIT_JOINT => (m.jnt_solref(), m.jnt_solimp()),
        FRICTION_DOF => (m.dof_solref(), m.dof_solimp()),
        LIMIT_TENDON => (m.tendon_solref_lim(), m.tendon_solimp_lim()),
        _ => (m.tendon_solref_fri(), m.tendon_solimp_fri()),
    };
    let k = if super::contact::is_contact(d.efc_type[i]) {
        0
    } else {
        id
    };
    let mut solref: [f64; 2] = arr(&sr[2 * k..]);
    let mut solimp: [f64; 5] = arr(&si[5 * k..]);
    if (solref[0] > 0.0) ^ (solref[1] > 0.0) {
        crate::runtime::warning("mixed solref format, replacing with default");
        solref = [0.02, 1.0];
    }
    if !disabled(m, mjtDisableBit_::mjDSBL_REFSAFE) && solref[0] > 0.0 {
        solref[0] = max(solref[0], 2.0 * m.raw.opt.timestep);
    }
    solimp[0] = min(MAXIMP, max(MINIMP, solimp[0]));
    solimp[1] = min(MAXIMP, max(MINIMP, solimp[1]));
    solimp[2] = max(0.0, solimp[2]);
    solimp[3] = min(MAXIMP, max(MINIMP, solimp[3]));
    solimp[4] = max(1.0, solimp[4]);
    (solref, solimp)
}

/// Impedance and its derivative at distance `pos` (with margin) for `solimp`.
fn impedance(solimp: &[f64; 5], pos: f64, margin: f64) -> (f64, f64) {
    if solimp[0] == solimp[1] || solimp[2] <= MINVAL {
        return (0.5 * (solimp[0] + solimp[1]), 0.0);
    }
    let mut x = (pos - margin) / solimp[2];
    let mut sgn = 1.0;
    if x < 0.0 {
        x = -x;
        sgn = -1.0;
    }
    if x >= 1.0 || x <= 0.0 {
        return (if x >= 1.0 { solimp[1] } else { solimp[0] }, 0.0);
    }
    let (y, yp);
    if solimp[4] == 1.0 {
        y = x;
        yp = 1.0;
    } else if x <= solimp[3] {
        let a = 1.0 / solimp[3].powf(solimp[4] - 1.0);
        y = a * x.powf(solimp[4]);
        yp = solimp[4] * a * x.powf(solimp[4] - 1.0);
    } else {
        let b = 1.0 / (1.0 - solimp[3]).powf(solimp[4] - 1.0);
        y = 1.0 - b * (1.0 - x).powf(solimp[4]);
        yp = solimp[4] * b * (1.0 - x).powf(solimp[4] - 1.0);
    }
    (
        solimp[0] + y * (solimp[1] - solimp[0]),
        yp * sgn * (solimp[1] - solimp[0]) / solimp[2],
    )
}

/// Distance used for the impedance of the constraint starting at row i, and its row count.
fn pos_dim(m: &Model, d: &Data, i: usize) -> (f64, usize) {
    let id = d.efc_id[i] as usize;
    if super::contact::is_contact(d.efc_type[i]) {
        return (d.efc_pos[i], super::contact::rows(d, i));
    }
    if d.efc_type[i] == EQUALITY {
        match m.eq_type()[id] {
            EQ_WELD => {
                let ratio = m.eq_data()[mjNEQDATA * id + 10];
                let mut p = [0.0; 6];
                p[..3].copy_from_slice(&d.efc_pos[i..i + 3]);
                for k in 3..6 {
                    p[k] = d.efc_pos[i + k] * ratio;
                }
                return (norm(&p), 6);
            }
            EQ_CONNECT => return (norm(&d.efc_pos[i..i + 3]), 3),
            _ => {}
        }
    }
    (d.efc_pos[i], 1)
}

/// efc_R, efc_D, efc_KBIP and the adjusted efc_diagApprox (mj_makeImpedance).
fn make_impedance(m: &Model, d: &mut Data) {
    let nefc = d.raw.nefc as usize;
    let mut i = 0;
    while i < nefc {
        let (solref, solimp) = sol_params(m, d, i);
        let (pos, dim) = pos_dim(m, d, i);
        let (imp, imp_p) = impedance(&solimp, pos, d.efc_margin[i]);
        // stiffness and damping: the same for every row of the constraint
        let stiffness = if solref[0] > 0.0 {
            1.0 / max(
                MINVAL,
                solimp[1] * solimp[1] * solref[0] * solref[0] * solref[1] * solref[1],
            )
        } else {
            -solref[0] / max(MINVAL, solimp[1] * solimp[1])
        };
        let damping = if solref[1] > 0.0 {
            2.0 / max(MINVAL, solimp[1] * solref[0])
        } else {
            -solref[1] / max(MINVAL, solimp[1])
        };
        for j in i..i + dim {
            d.efc_R[j] = max(MINVAL, (1.0 - imp) * d.efc_diagApprox[j] / imp);
            let tp = d.efc_type[j];
            let frictional =
                tp == FRICTION_DOF || tp == FRICTION_TENDON || (tp == CONTACT_ELLIPTIC && j > i);
            let k = &mut d.efc_KBIP[4 * j..4 * j + 4];
            k[0] = if frictional { 0.0 } else { stiffness };
            k[1] = damping;
            k[2] = imp;
            k[3] = imp_p;
        }
        i += dim;
    }
    super::contact::friction_regularization(m, d);
    for (dd, &r) in d.efc_D[..nefc].iter_mut().zip(&d.efc_R[..nefc]) {
        *dd = 1.0 / r;
    }
    let kbip = d.efc_KBIP[..4 * nefc].chunks_exact(4);
    for ((a, &r), k) in d.efc_diagApprox[..nefc]
        .iter_mut()
        .zip(&d.efc_R[..nefc])
        .zip(kbip)
    {
        *a = r * k[2] / (1.0 - k[2]);
    }
}

/// Runs `f` with a scratch arena taken from `d` (released afterwards); inside `f`, `d.arena`
/// is empty, so scratch must come from the arena argument.
pub fn with_arena<R>(d: &mut Data, f: impl FnOnce(&mut Data, &mut Arena) -> R) -> R {
    let mut arena = std::mem::replace(&mut d.arena, Arena::over(&mut []));
    let r = arena.scope(|a| f(d, a));
    d.arena = arena;
    r
}

/// mj_makeConstraint: rows of all active constraints and their soft parameters.
pub fn make_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    d.raw.ne = 0;
    d.raw.nf = 0;
    d.raw.nefc = 0;
    if disabled(m, mjtDisableBit_::mjDSBL_CONSTRAINT) || m.raw.njmax == 0 {
        return Ok(());
    }
    // each instantiation frees its scratch before the next (2.2.2's mark and free per call)
    with_arena(d, |d, a| -> Result<(), EngineError> {
        if !disabled(m, mjtDisableBit_::mjDSBL_EQUALITY) && m.raw.nemax != 0 {
            a.scope(|a| equality(m, d, a))?;
        }
        a.scope(|a| friction(m, d, a))?;
        a.scope(|a| limits(m, d, a))?;
        a.scope(|a| super::contact::instantiate(m, d, a))
    })?;
    d.raw.maxuse_con = d.raw.maxuse_con.max(d.raw.ncon);
    d.raw.maxuse_efc = d.raw.maxuse_efc.max(d.raw.nefc);
    if d.raw.nefc == 0 {
        return Ok(());
    }
    if is_sparse(m) {
        let (nefc, nv) = (d.raw.nefc as usize, m.raw.nv as usize);
        transpose_sparse(
            d.efc_JT,
            d.efc_J,
            nefc,
            nv,
            d.efc_JT_rownnz,
            d.efc_JT_rowadr,
            d.efc_JT_colind,
            d.efc_J_rownnz,
            d.efc_J_rowadr,
            d.efc_J_colind,
        );
        super_sparse(
            nefc,
            d.efc_J_rowsuper,
            d.efc_J_rownnz,
            d.efc_J_rowadr,
            d.efc_J_colind,
        );
        super_sparse(
            nv,
            d.efc_JT_rowsuper,
            d.efc_JT_rownnz,
            d.efc_JT_rowadr,
            d.efc_JT_colind,
        );
    }
    diag_approx(m, d)?;
    make_impedance(m, d);
    Ok(())
}

/// efc_AR = J M^-1 J' + diag(R) for dual solvers (mj_projectConstraint).
#[inline]
pub fn project_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if d.raw.nefc == 0 || !is_dual(m) {
        return Ok(());
    }
    project_dual(m, d)
}

#[inline(never)]
fn project_dual(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nefc = d.raw.nefc as usize;
    let nv = m.raw.nv as usize;
    with_arena(d, |d, a| -> Result<(), EngineError> {
        let jm2 = a.alloc(nefc * nv)?;
        let jm2t = a.alloc(nv * nefc)?;
        if is_sparse(m) {
            return project_sparse(m, d, a, jm2, jm2t);
        }
        solve_m2(m, jm2, d.efc_J, nefc, d.qLD, d.qLDiagSqrtInv);
        transpose(jm2t, jm2, nefc, nv);
        sqr_mat_td(d.efc_AR, jm2t, None, nv, nefc);
        for r in 0..nefc {
            d.efc_AR[r * (nefc + 1)] += d.efc_R[r];
        }
        Ok(())
    })
}

/// Sparse projection: rows of J completed to full dof chains, back-substituted through L'.
fn project_sparse(
    m: &Model,
    d: &mut Data,
    a: &mut Arena,
    jm2: &mut [f64],
    jm2t: &mut [f64],
) -> Result<(), EngineError> {
    let nefc = d.raw.nefc as usize;
    let nv = m.raw.nv as usize;
    let rownnz = a.alloc_int(nefc)?;
    let rowadr = a.alloc_int(nefc)?;
    let colind = a.alloc_int(nefc * nv)?;
    let rowsuper = a.alloc_int(nefc)?;
    let rownnz_t = a.alloc_int(nv)?;
    let rowadr_t = a.alloc_int(nv)?;
    let colind_t = a.alloc_int(nv * nefc)?;
    let rowsuper_t = a.alloc_int(nv)?;
    let parent = m.dof_parentid();
    for r in 0..nefc {
        let adr = if r > 0 {
            (rowadr[r - 1] + rownnz[r - 1]) as usize
        } else {
            0
        };
        let (jadr, mut remain) = (d.efc_J_rowadr[r] as usize, d.efc_J_rownnz[r] as usize);
        let mut nnz = 0;
        loop {
            rownnz[r] = nnz as i32;
            rowadr[r] = adr as i32;
            let prev_src = if remain > 0 {
                d.efc_J_colind[jadr + remain - 1]
            } else {
                -1
            };
            let prev_dst = if nnz > 0 {
                parent[colind[adr + nnz - 1] as usize]
            } else {
                -1
            };
            if prev_src < 0 && prev_dst < 0 {
                break;
            }
            if prev_src >= prev_dst {
                colind[adr + nnz] = prev_src;
                jm2[adr + nnz] = d.efc_J[jadr + remain - 1];
                remain -= 1;
            } else {
                colind[adr + nnz] = prev_dst;
                jm2[adr + nnz] = 0.0;
            }
            nnz += 1;
        }
        colind[adr..adr + nnz].reverse();
        jm2[adr..adr + nnz].reverse();
        // one path from the root (a body's contact with the world, a joint's limit): the
        // ancestors of each entry are the entries before it, nearest first
        let cols = &colind[adr..adr + nnz];
        if cols.windows(2).all(|w| parent[w[1] as usize] == w[0]) {
            let row = &mut jm2[adr..adr + nnz];
            for i in (0..nnz).rev() {
                let xi = row[i];
                if xi != 0.0 {
                    let c = cols[i] as usize;
                    row[i] *= d.qLDiagSqrtInv[c];
                    let madr = m.dof_Madr()[c] as usize + 1;
                    for (x, l) in row[..i].iter_mut().rev().zip(&d.qLD[madr..madr + i]) {
                        *x -= l * xi;
                    }
                }
            }
            continue;
        }
        for i in (0..nnz).rev() {
            let xi = jm2[adr + i];
            let mut pi = i;
            if xi != 0.0 {
                let c = colind[adr + i] as usize;
                jm2[adr + i] *= d.qLDiagSqrtInv[c];
                let mut madr = m.dof_Madr()[c] as usize + 1;
                let mut j = parent[c];
                while j >= 0 {
                    while colind[adr + pi] > j {
                        pi -= 1;
                    }
                    jm2[adr + pi] -= d.qLD[madr] * xi;
                    madr += 1;
                    j = parent[j as usize];
                }
            }
        }
    }
    transpose_sparse(
        jm2t, jm2, nefc, nv, rownnz_t, rowadr_t, colind_t, rownnz, rowadr, colind,
    );
    super_sparse(nefc, rowsuper, rownnz, rowadr, colind);
    super_sparse(nv, rowsuper_t, rownnz_t, rowadr_t, colind_t);
    let chain = a.alloc_int(2 * nefc)?;
    let buffer = a.alloc(nefc)?;
    let pat_t = SparseRef {
        rownnz: rownnz_t,
        rowadr: rowadr_t,
        colind: colind_t,
        rowsuper: Some(rowsuper_t),
    };
    let pat = SparseRef {
        rownnz,
        rowadr,
        colind,
        rowsuper: Some(rowsuper),
    };
    sqr_mat_td_sparse_lower(
        d.efc_AR,
        jm2t,
        jm2,
        None,
        nefc,
        d.efc_AR_rownnz,
        d.efc_AR_rowadr,
        d.efc_AR_colind,
        &pat_t,
        &pat,
        chain,
        buffer,
        // rows coupled through a dof are coupled through its tree's root, on both
        |c| parent[c] < 0,
    );
    mirror_lower_sparse(d.efc_AR, nefc, d.efc_AR_rownnz, d.efc_AR_colind);
    compress_sparse(
        d.efc_AR,
        nefc,
        d.efc_AR_rownnz,
        d.efc_AR_rowadr,
        d.efc_AR_colind,
    );
    for i in 0..nefc {
        let adr = d.efc_AR_rowadr[i] as usize;
        for k in adr..adr + d.efc_AR_rownnz[i] as usize {
            if d.efc_AR_colind[k] == i as i32 {
                d.efc_AR[k] += d.efc_R[i];
                break;
            }
        }
    }
    Ok(())
}

/// efc_vel and efc_aref (mj_referenceConstraint).
#[inline]
pub fn reference_constraint(m: &Model, d: &mut Data) {
    if d.raw.nefc == 0 {
        return;
    }
    reference_acceleration(m, d)
}

#[inline(never)]
fn reference_acceleration(m: &Model, d: &mut Data) {
    let nefc = d.raw.nefc as usize;
    jac_view!(m, d).mul_vec(d.efc_vel, d.qvel);
    for i in 0..nefc {
        let k = &d.efc_KBIP[4 * i..4 * i + 4];
        d.efc_aref[i] = -k[1] * d.efc_vel[i] - k[0] * k[2] * (d.efc_pos[i] - d.efc_margin[i]);
    }
}

/// efc_state, efc_force and qfrc_constraint at jar = J*qacc - aref; returns the constraint
/// cost when asked (mj_constraintUpdate); `cone_hessian` also sets the Hessian of the cone cost
/// of contacts in the cone state (contact H).
pub fn constraint_update(
    m: &Model,
    d: &mut Data,
    jar: &[f64],
    want_cost: bool,
    cone_hessian: bool,
) -> Result<f64, EngineError> {
    let (ne, nf, nefc) = (d.raw.ne as usize, d.raw.nf as usize, d.raw.nefc as usize);
    let nv = m.raw.nv as usize;
    if nefc == 0 {
        d.qfrc_constraint[..nv].fill(0.0);
        return Ok(0.0);
    }
    let (dd, r, floss) = (&*d.efc_D, &*d.efc_R, &*d.efc_frictionloss);
    let force = &mut *d.efc_force;
    let state = &mut *d.efc_state;
    let mut s = 0.0;
    for i in 0..nefc {
        force[i] = -dd[i] * jar[i];
    }
    for i in 0..ne {
        if want_cost {
            s += 0.5 * dd[i] * jar[i] * jar[i];
        }
        state[i] = mjCNSTRSTATE_QUADRATIC as i32;
    }
    for i in ne..ne + nf {
        if jar[i] <= -r[i] * floss[i] {
            if want_cost {
                s += -0.5 * r[i] * floss[i] * floss[i] - floss[i] * jar[i];
            }
            force[i] = floss[i];
            state[i] = mjCNSTRSTATE_LINEARNEG as i32;
        } else if jar[i] >= r[i] * floss[i] {
            if want_cost {
                s += -0.5 * r[i] * floss[i] * floss[i] + floss[i] * jar[i];
            }
            force[i] = -floss[i];
            state[i] = mjCNSTRSTATE_LINEARPOS as i32;
        } else {
            if want_cost {
                s += 0.5 * dd[i] * jar[i] * jar[i];
            }
            state[i] = mjCNSTRSTATE_QUADRATIC as i32;
        }
    }
    let mut i = ne + nf;
    while i < nefc {
        if d.efc_type[i] == CONTACT_ELLIPTIC {
            let con = &mut d.contact[d.efc_id[i] as usize];
            let dim = con.dim as usize;
            elliptic_update(
                con,
                &jar[i..i + dim],
                &dd[i..i + dim],
                &mut force[i..i + dim],
                &mut state[i..i + dim],
                want_cost.then_some(&mut s),
                cone_hessian,
            );
            i += dim;
            continue;
        }
        // chosen by bit masks, without branches (states flip between iterations and
        // mispredict): a satisfied row's force is +0 and its cost term -0 (NaN: quadratic)
        let quadratic = jar[i] < 0.0 || jar[i].is_nan();
        let keep = (quadratic as u64).wrapping_neg();
        force[i] = f64::from_bits(force[i].to_bits() & keep);
        state[i] = if quadratic {
            mjCNSTRSTATE_QUADRATIC as i32
        } else {
            mjCNSTRSTATE_SATISFIED as i32
        };
        if want_cost {
            s += kept_or_neg_zero(0.5 * dd[i] * jar[i] * jar[i], quadratic);
        }
        i += 1;
    }
    jac_view!(m, d).mul_t_vec(d.qfrc_constraint, d.efc_force);
    Ok(s)
}

/// One elliptic contact in the constraint update: the zone of jar in the dual cone (top:
/// free, bottom: quadratic, middle: cone), its forces, cost (added to `cost` in 2.2.2's order)
/// and (cone zone) cost Hessian.
fn elliptic_update(
    con: &mut mjContact,
    jar: &[f64],
    dd: &[f64],
    force: &mut [f64],
    state: &mut [i32],
    cost: Option<&mut f64>,
    cone_hessian: bool,
) {
    let dim = jar.len();
    let (mu, friction) = (con.mu, con.friction);
    let mut u = [0.0; 6];
    u[0] = jar[0] * mu;
    for j in 1..dim {
        u[j] = jar[j] * friction[j - 1];
    }
    let n = u[0];
    // condim 3: the norm of the two products as `norm` sums them (+0 plus a sum of squares,
    // never -0, is that sum), from registers: a vector load of `u` just stored element by
    // element waits for the stores
    let t = if dim == 3 {
        let (u1, u2) = (jar[1] * friction[0], jar[2] * friction[1]);
        (u1 * u1 + u2 * u2).sqrt()
    } else {
        norm(&u[1..dim])
    };
    let st;
    if n >= mu * t || (t <= 0.0 && n >= 0.0) {
        force.fill(0.0);
        st = mjCNSTRSTATE_SATISFIED as i32;
    } else if mu * n + t <= 0.0 || (t <= 0.0 && n < 0.0) {
        if let Some(s) = cost {
            for j in 0..dim {
                *s += 0.5 * dd[j] * jar[j] * jar[j];
            }
        }
        st = mjCNSTRSTATE_QUADRATIC as i32;
    } else {
        let dm = dd[0] / (mu * mu * (1.0 + mu * mu));
        let nmt = n - mu * t;
        if let Some(s) = cost {
            *s += 0.5 * dm * nmt * nmt;
        }
        force[0] = -dm * nmt * mu;
        for j in 1..dim {
            force[j] = -force[0] / t * u[j] * friction[j - 1];
        }
        st = mjCNSTRSTATE_CONE as i32;
        if cone_hessian {
            let h = &mut con.H;
            let scl = -mu / t;
            h[0] = 1.0;
            for j in 1..dim {
                h[j] = scl * u[j];
            }
            let scl = mu * n / (t * t * t);
            for k in 1..dim {
                for j in k..dim {
                    h[k * dim + j] = scl * u[j] * u[k];
                }
            }
            let scl = mu * mu - mu * n / t;
            for j in 1..dim {
                h[j * (dim + 1)] += scl;
            }
            for k in 0..dim {
                let scl = dm * if k == 0 { mu } else { friction[k - 1] };
                for j in k..dim {
                    h[k * dim + j] *= scl * if j == 0 { mu } else { friction[j - 1] };
                }
            }
            for k in 0..dim {
                for j in k + 1..dim {
                    h[j * dim + k] = h[k * dim + j];
                }
            }
        }
    }
    state.fill(st);
}
