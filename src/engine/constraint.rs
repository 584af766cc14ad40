//! Constraint instantiation (dense Jacobian): equality, dof friction and joint-limit rows, their
//! soft-constraint parameters (diagApprox, impedance, KBIP, R, D), the reference acceleration,
//! the projection AR for dual solvers, and the constraint-state update of the primal cost.
//! Tendon rows, contact rows and the sparse Jacobian are reported as not implemented.

use super::inertia::solve_m2;
use super::jacobian::jac;
use super::linalg::max;
use super::support::warning;
use super::{disabled, not_implemented, Data, EngineError, Model, MINVAL};
use super::{JNT_BALL, JNT_HINGE, JNT_SLIDE};
use crate::abi::view::Arena;
use crate::abi::*;
use crate::math::blas::{add_to_scl, mul_mat_t_vec, mul_mat_vec, norm, sqr_mat_td, transpose};
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

/// Is the constraint Jacobian sparse (mj_isSparse)?
pub fn is_sparse(m: &Model) -> bool {
    let j = m.raw.opt.jacobian;
    j == mjtJacobian_::mjJAC_SPARSE as i32
        || (j == mjtJacobian_::mjJAC_AUTO as i32 && m.raw.nv >= 60)
}

/// Does the solver work in the dual (mj_isDual)?
pub fn is_dual(m: &Model) -> bool {
    m.raw.opt.solver == mjtSolver_::mjSOL_PGS as i32 || m.raw.opt.noslip_iterations > 0
}

/// res = efc_J * vec (mj_mulJacVec, dense Jacobian).
pub fn mul_jac_vec(m: &Model, nefc: usize, efc_j: &[f64], res: &mut [f64], vec: &[f64]) {
    if nefc > 0 {
        mul_mat_vec(res, efc_j, vec, nefc, m.raw.nv as usize);
    }
}

/// res = efc_J' * vec (mj_mulJacTVec, dense Jacobian).
pub fn mul_jac_t_vec(m: &Model, nefc: usize, efc_j: &[f64], res: &mut [f64], vec: &[f64]) {
    if nefc > 0 {
        mul_mat_t_vec(res, efc_j, vec, nefc, m.raw.nv as usize);
    }
}

/// Appends `size` rows (dense, `size` x nv) unless they are all zero for a non-contact
/// constraint (mj_addConstraint). Returns false when the buffer is full (warning issued).
#[allow(clippy::too_many_arguments)]
fn add_rows(
    m: &Model,
    d: &mut Data,
    jacobian: &[f64],
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
    if jacobian[..size * nv].iter().all(|&x| x == 0.0) {
        return Ok(true);
    }
    d.efc_J[nefc * nv..(nefc + size) * nv].copy_from_slice(&jacobian[..size * nv]);
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

/// Equality rows: connect (3), weld (6), joint coupling (1).
fn equality(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_EQUALITY) || m.raw.nemax == 0 {
        return Ok(());
    }
    let j0 = a.alloc(6 * nv)?;
    let j1 = a.alloc(6 * nv)?;
    for i in 0..m.raw.neq as usize {
        if m.eq_active()[i] == 0 {
            continue;
        }
        let data = &m.eq_data()[mjNEQDATA as usize * i..mjNEQDATA as usize * (i + 1)];
        let id = [m.eq_obj1id()[i], m.eq_obj2id()[i]];
        let mut cpos = [0.0; 6];
        let size;
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
                let (j0p, j0r) = j0.split_at_mut(3 * nv);
                let (j1p, j1r) = j1.split_at_mut(3 * nv);
                let (r1, r0) = if weld {
                    (Some(j1r), Some(j0r))
                } else {
                    (None, None)
                };
                jac(m, d.cdof, d.subtree_com, &pos[1], b1, Some(j1p), r1);
                jac(m, d.cdof, d.subtree_com, &pos[0], b0, Some(j0p), r0);
                let n = if weld { 6 * nv } else { 3 * nv };
                for k in 0..n {
                    j0[k] -= j1[k];
                }
                if weld {
                    let q = mul_quat(&q4(&d.xquat[4 * b0..]), &q4(&data[6..]));
                    let q1 = neg_quat(&q4(&d.xquat[4 * b1..]));
                    let q2 = mul_quat(&q1, &q);
                    cpos[3..].copy_from_slice(&q2[1..]);
                    for k in 0..nv {
                        let axis = [j0[3 * nv + k], j0[4 * nv + k], j0[5 * nv + k]];
                        let q3 = mul_quat(&mul_quat_axis(&q1, &axis), &q);
                        j0[3 * nv + k] = 0.5 * q3[1];
                        j0[4 * nv + k] = 0.5 * q3[2];
                        j0[5 * nv + k] = 0.5 * q3[3];
                    }
                    let torquescale = data[10];
                    for x in &mut j0[3 * nv..6 * nv] {
                        *x *= torquescale;
                    }
                    size = 6;
                } else {
                    size = 3;
                }
            }
            EQ_JOINT => {
                let mut pos = [0.0; 2];
                let mut refpos = [0.0; 2];
                let nobj = if id[1] >= 0 { 2 } else { 1 };
                for k in 0..nobj {
                    let jn = id[k] as usize;
                    let qadr = m.jnt_qposadr()[jn] as usize;
                    pos[k] = d.qpos[qadr];
                    refpos[k] = m.qpos0()[qadr];
                    let jk = if k == 0 { &mut *j0 } else { &mut *j1 };
                    jk[..nv].fill(0.0);
                    jk[m.jnt_dofadr()[jn] as usize] = 1.0;
                }
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
                    add_to_scl(&mut j0[..nv], &j1[..nv], -deriv);
                } else {
                    cpos[0] = pos[0] - refpos[0] - data[0];
                }
                size = 1;
            }
            EQ_TENDON => return Err(not_implemented("tendon equality constraints are")),
            EQ_DISTANCE => {
                return Err(EngineError(
                    "distance equality constraints are no longer supported".into(),
                ))
            }
            t => return Err(EngineError(format!("Invalid equality constraint type {t}"))),
        }
        if !add_rows(m, d, j0, Some(&cpos), None, 0.0, size, EQUALITY, i)? {
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
    let j = a.alloc(nv)?;
    for i in 0..nv {
        let f = m.dof_frictionloss()[i];
        if f > 0.0 {
            j.fill(0.0);
            j[i] = 1.0;
            if !add_rows(m, d, j, None, None, f, 1, FRICTION_DOF, i)? {
                break;
            }
        }
    }
    if m.tendon_frictionloss().iter().any(|&f| f > 0.0) {
        return Err(not_implemented("tendon frictionloss constraints are"));
    }
    Ok(())
}

/// Joint-limit rows (tendon limits are not implemented).
fn limits(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_LIMIT) {
        return Ok(());
    }
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
                        j.fill(0.0);
                        j[dofadr] = -side;
                        if !add_rows(
                            m,
                            d,
                            j,
                            Some(&[dist]),
                            Some(&[margin]),
                            0.0,
                            1,
                            LIMIT_JOINT,
                            i,
                        )? {
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
                    j.fill(0.0);
                    j[dofadr..dofadr + 3].copy_from_slice(&scl3(&axis, -1.0));
                    if !add_rows(
                        m,
                        d,
                        j,
                        Some(&[dist]),
                        Some(&[margin]),
                        0.0,
                        1,
                        LIMIT_JOINT,
                        i,
                    )? {
                        break;
                    }
                }
            }
            _ => {}
        }
    }
    if m.tendon_limited().iter().any(|&l| l != 0) {
        return Err(not_implemented("tendon limit constraints are"));
    }
    Ok(())
}

/// Approximate inverse inertia of each row (mj_diagApprox) for the non-contact types.
fn diag_approx(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let iw = m.body_invweight0();
    let dw = m.dof_invweight0();
    for i in 0..d.raw.nefc as usize {
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
                _ => return Err(not_implemented("this equality type is")),
            },
            FRICTION_DOF => dw[id],
            LIMIT_JOINT => dw[m.jnt_dofadr()[id] as usize],
            _ => return Err(not_implemented("this constraint type is")),
        };
    }
    Ok(())
}

/// solref and solimp of row i after the safety adjustments.
fn sol_params(m: &Model, d: &Data, i: usize) -> ([f64; 2], [f64; 5]) {
    let id = d.efc_id[i] as usize;
    let (sr, si) = match d.efc_type[i] {
        EQUALITY => (m.eq_solref(), m.eq_solimp()),
        LIMIT_JOINT => (m.jnt_solref(), m.jnt_solimp()),
        FRICTION_DOF => (m.dof_solref(), m.dof_solimp()),
        LIMIT_TENDON => (m.tendon_solref_lim(), m.tendon_solimp_lim()),
        _ => (m.tendon_solref_fri(), m.tendon_solimp_fri()),
    };
    let mut solref: [f64; 2] = arr(&sr[2 * id..]);
    let mut solimp: [f64; 5] = arr(&si[5 * id..]);
    if (solref[0] > 0.0) ^ (solref[1] > 0.0) {
        crate::capi::errmem::warning("mixed solref format, replacing with default");
        solref = [0.02, 1.0];
    }
    if !disabled(m, mjtDisableBit_::mjDSBL_REFSAFE) && solref[0] > 0.0 {
        solref[0] = max(solref[0], 2.0 * m.raw.opt.timestep);
    }
    solimp[0] = min_c(MAXIMP, max(MINIMP, solimp[0]));
    solimp[1] = min_c(MAXIMP, max(MINIMP, solimp[1]));
    solimp[2] = max(0.0, solimp[2]);
    solimp[3] = min_c(MAXIMP, max(MINIMP, solimp[3]));
    solimp[4] = max(1.0, solimp[4]);
    (solref, solimp)
}

fn min_c(a: f64, b: f64) -> f64 {
    crate::math::misc::min(a, b)
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
    if d.efc_type[i] == EQUALITY {
        match m.eq_type()[id] {
            EQ_WELD => {
                let ratio = m.eq_data()[mjNEQDATA as usize * id + 10];
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

/// efc_R, efc_D, efc_KBIP and the adjusted efc_diagApprox (mj_makeImpedance), no contacts.
fn make_impedance(m: &Model, d: &mut Data) {
    let nefc = d.raw.nefc as usize;
    let mut i = 0;
    while i < nefc {
        let (solref, solimp) = sol_params(m, d, i);
        let (pos, dim) = pos_dim(m, d, i);
        let (imp, imp_p) = impedance(&solimp, pos, d.efc_margin[i]);
        for j in i..i + dim {
            d.efc_R[j] = max(MINVAL, (1.0 - imp) * d.efc_diagApprox[j] / imp);
            let tp = d.efc_type[j];
            let k = &mut d.efc_KBIP[4 * j..4 * j + 4];
            k[0] = if tp == FRICTION_DOF || tp == FRICTION_TENDON {
                0.0
            } else if solref[0] > 0.0 {
                1.0 / max(
                    MINVAL,
                    solimp[1] * solimp[1] * solref[0] * solref[0] * solref[1] * solref[1],
                )
            } else {
                -solref[0] / max(MINVAL, solimp[1] * solimp[1])
            };
            k[1] = if solref[1] > 0.0 {
                2.0 / max(MINVAL, solimp[1] * solref[0])
            } else {
                -solref[1] / max(MINVAL, solimp[1])
            };
            k[2] = imp;
            k[3] = imp_p;
        }
        i += dim;
    }
    for i in 0..nefc {
        d.efc_D[i] = 1.0 / d.efc_R[i];
    }
    for i in 0..nefc {
        let imp = d.efc_KBIP[4 * i + 2];
        d.efc_diagApprox[i] = d.efc_R[i] * imp / (1.0 - imp);
    }
}

/// Runs `f` with a scratch arena taken from `d` (released afterwards).
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
    with_arena(d, |d, a| -> Result<(), EngineError> {
        equality(m, d, a)?;
        friction(m, d, a)?;
        limits(m, d, a)
    })?;
    if !disabled(m, mjtDisableBit_::mjDSBL_CONTACT) && d.raw.ncon > 0 {
        return Err(not_implemented("contact constraints are"));
    }
    d.raw.maxuse_con = d.raw.maxuse_con.max(d.raw.ncon);
    d.raw.maxuse_efc = d.raw.maxuse_efc.max(d.raw.nefc);
    if d.raw.nefc == 0 {
        return Ok(());
    }
    if is_sparse(m) {
        return Err(not_implemented("the sparse constraint Jacobian is"));
    }
    diag_approx(m, d)?;
    make_impedance(m, d);
    Ok(())
}

/// efc_AR = J M^-1 J' + diag(R) for dual solvers (mj_projectConstraint, dense).
pub fn project_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nefc = d.raw.nefc as usize;
    let nv = m.raw.nv as usize;
    if nefc == 0 || !is_dual(m) {
        return Ok(());
    }
    if is_sparse(m) {
        return Err(not_implemented("the sparse constraint Jacobian is"));
    }
    with_arena(d, |d, a| -> Result<(), EngineError> {
        let jm2 = a.alloc(nefc * nv)?;
        let jm2t = a.alloc(nv * nefc)?;
        solve_m2(m, jm2, d.efc_J, nefc, d.qLD, d.qLDiagSqrtInv);
        transpose(jm2t, jm2, nefc, nv);
        sqr_mat_td(d.efc_AR, jm2t, None, nv, nefc);
        for r in 0..nefc {
            d.efc_AR[r * (nefc + 1)] += d.efc_R[r];
        }
        Ok(())
    })
}

/// efc_vel and efc_aref (mj_referenceConstraint).
pub fn reference_constraint(m: &Model, d: &mut Data) {
    let nefc = d.raw.nefc as usize;
    mul_jac_vec(m, nefc, d.efc_J, d.efc_vel, d.qvel);
    for i in 0..nefc {
        let k = &d.efc_KBIP[4 * i..4 * i + 4];
        d.efc_aref[i] = -k[1] * d.efc_vel[i] - k[0] * k[2] * (d.efc_pos[i] - d.efc_margin[i]);
    }
}

/// efc_state, efc_force and qfrc_constraint at jar = J*qacc - aref; returns the constraint
/// cost when asked (mj_constraintUpdate). Elliptic cones need contacts and are not handled.
pub fn constraint_update(
    m: &Model,
    d: &mut Data,
    jar: &[f64],
    want_cost: bool,
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
    for i in ne + nf..nefc {
        if d.efc_type[i] == CONTACT_ELLIPTIC {
            return Err(not_implemented("elliptic contact constraints are"));
        }
        if jar[i] >= 0.0 {
            force[i] = 0.0;
            state[i] = mjCNSTRSTATE_SATISFIED as i32;
        } else {
            if want_cost {
                s += 0.5 * dd[i] * jar[i] * jar[i];
            }
            state[i] = mjCNSTRSTATE_QUADRATIC as i32;
        }
    }
    mul_jac_t_vec(m, nefc, d.efc_J, d.qfrc_constraint, d.efc_force);
    Ok(s)
}
