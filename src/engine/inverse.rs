//! Inverse dynamics: the generalized force qfrc_inverse that produces the given qacc
//! (mj_inverse), and the comparison of forward and inverse results (mj_compareFwdInv).

use super::collision::collision;
use super::constraint::make_constraint;
use super::forward::{fwd_velocity, tendon, xfrc_accumulate, Omit};
use super::inertia::{crb, factor_m};
use super::kinematics::{camlight, com_pos, kinematics};
use super::linalg::dot;
use super::rne::rne_with;
use super::sensor::sensor_acc;
use super::transmission::transmission;
use super::{now, tick, Data, EngineError, Model};
use crate::abi::*;
use mjtTimer_::*;

/// Position-dependent stage of inverse dynamics; transmission comes with the kinematics here
/// and there is no constraint projection (mj_invPosition).
pub fn inv_position(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let start = now();
    let mut t = now();
    kinematics(m, d)?;
    com_pos(m, d)?;
    camlight(m, d, false);
    tendon(m, d)?;
    transmission(m, d)?;
    tick(d, mjTIMER_POS_KINEMATICS, t);
    t = now();
    crb(m, d, true);
    factor_m(m, d)?;
    tick(d, mjTIMER_POS_INERTIA, t);
    t = now();
    collision(m, d)?;
    tick(d, mjTIMER_POS_COLLISION, t);
    t = now();
    make_constraint(m, d)?;
    tick(d, mjTIMER_POS_MAKE, t);
    tick(d, mjTIMER_POSITION, start);
    Ok(())
}

/// Velocity-dependent stage of inverse dynamics: the same as the forward one (mj_invVelocity).
pub fn inv_velocity(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    fwd_velocity(m, d)
}

/// Constraint forces that produce qacc (mj_invConstraint); zero without constraints.
pub fn inv_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let start = now();
    let nefc = d.raw.nefc as usize;
    if nefc == 0 {
        d.qfrc_constraint.fill(0.0);
    } else {
        super::constraint::with_arena(d, |d, a| -> Result<(), EngineError> {
            let jar = a.alloc(nefc)?;
            super::constraint::jac_view!(m, d).mul_vec(jar, d.qacc);
            for i in 0..nefc {
                jar[i] -= d.efc_aref[i];
            }
            super::constraint::constraint_update(m, d, jar, false, false).map(|_| ())
        })?;
    }
    tick(d, mjTIMER_CONSTRAINT, start);
    Ok(())
}

/// Inverse dynamics reusing the stages before `skipstage` (mj_inverseSkip).
pub fn inverse_skip(
    m: &Model,
    d: &mut Data,
    skipstage: i32,
    skipsensor: bool,
) -> Result<(), EngineError> {
    let start = now();
    let stages = (skipstage, skipsensor, Omit::default());
    super::forward::pos_vel_stages(m, d, stages, inv_position, inv_velocity)?;
    inv_constraint(m, d)?;
    let nv = m.raw.nv as usize;
    let qacc = std::mem::take(&mut d.qacc);
    let out = std::mem::take(&mut d.qfrc_inverse);
    let r = rne_with(m, d, Some(&qacc[..nv]), &mut out[..nv]);
    d.qacc = qacc;
    d.qfrc_inverse = out;
    r?;
    if !skipsensor {
        sensor_acc(m, d)?;
    }

    // qfrc_inverse += armature*qacc - qfrc_passive - qfrc_constraint
    for i in 0..nv {
        d.qfrc_inverse[i] +=
            m.dof_armature()[i] * d.qacc[i] - d.qfrc_passive[i] - d.qfrc_constraint[i];
    }
    tick(d, mjTIMER_INVERSE, start);
    Ok(())
}

/// mj_inverse.
pub fn inverse(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    inverse_skip(m, d, mjtStage_::mjSTAGE_NONE as i32, false)
}

/// Norms of the differences between forward and inverse dynamics, leaving the forward results
/// in place (mj_compareFwdInv): solver_fwdinv = (|qfrc_constraint fwd - inv|,
/// |applied + actuator forces - qfrc_inverse|); both 0 without constraints.
pub fn compare_fwd_inv(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let (nv, nefc) = (m.raw.nv as usize, d.raw.nefc.max(0) as usize);
    d.raw.solver_fwdinv = [0.0; 2];
    if nefc == 0 {
        return Ok(());
    }
    d.scoped(|d| compare_scoped(m, d, nv, nefc))
}

fn compare_scoped(m: &Model, d: &mut Data, nv: usize, nefc: usize) -> Result<(), EngineError> {
    // scratch to the end of the comparison (the forward results must survive the inverse)
    let qforce = d.arena.alloc(nv)?;
    let dif = d.arena.alloc(nv)?;
    let save_constraint = d.arena.alloc(nv)?;
    let save_force = d.arena.alloc(nefc)?;

    for i in 0..nv {
        qforce[i] = d.qfrc_applied[i] + d.qfrc_actuator[i];
    }
    xfrc_accumulate(m, d, qforce)?;
    save_constraint.copy_from_slice(&d.qfrc_constraint[..nv]);
    save_force.copy_from_slice(&d.efc_force[..nefc]);

    inverse_skip(m, d, mjtStage_::mjSTAGE_VEL as i32, true)?;

    for i in 0..nv {
        dif[i] = save_constraint[i] - d.qfrc_constraint[i];
    }
    d.raw.solver_fwdinv[0] = dot(dif, dif).sqrt();
    for i in 0..nv {
        dif[i] = qforce[i] - d.qfrc_inverse[i];
    }
    d.raw.solver_fwdinv[1] = dot(dif, dif).sqrt();

    d.qfrc_constraint[..nv].copy_from_slice(save_constraint);
    d.efc_force[..nefc].copy_from_slice(save_force);
    Ok(())
}
