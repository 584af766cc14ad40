//! Actuation: clamped controls, gains and biases, actuator forces mapped to joint space.

use super::linalg::{clip, is_bad, mul_mat_t_vec};
use super::support::warning;
use super::{disabled, not_implemented, tick, Data, EngineError, Model};
use crate::abi::*;

/// actuator_force, qfrc_actuator, act_dot (mj_fwdActuation; stateless, fixed/affine only).
pub fn fwd_actuation(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nu = m.raw.nu as usize;
    let na = m.raw.na as usize;
    d.qfrc_actuator.fill(0.0);
    d.actuator_force.fill(0.0);
    if nu == 0 || disabled(m, mjtDisableBit_::mjDSBL_ACTUATION) {
        return Ok(());
    }
    if na > 0 {
        return Err(not_implemented(
            "actuator dynamics (stateful actuators) are",
        ));
    }
    d.arena.scope(|a| -> Result<(), EngineError> {
        let ctrl = a.alloc(nu)?;
        let noclamp = disabled(m, mjtDisableBit_::mjDSBL_CLAMPCTRL);
        for i in 0..nu {
            ctrl[i] = if !noclamp && m.actuator_ctrllimited()[i] != 0 {
                clip(
                    d.ctrl[i],
                    m.actuator_ctrlrange()[2 * i],
                    m.actuator_ctrlrange()[2 * i + 1],
                )
            } else {
                d.ctrl[i]
            };
        }
        for i in 0..nu {
            if is_bad(ctrl[i]) {
                warning(d.raw, mjtWarning_::mjWARN_BADCTRL as i32, i as i32)?;
                ctrl.fill(0.0);
                break;
            }
        }
        let force = &mut *d.actuator_force;
        for i in 0..nu {
            let prm = &m.actuator_gainprm()[mjNGAIN * i..mjNGAIN * (i + 1)];
            let len = d.actuator_length[i];
            let vel = d.actuator_velocity[i];
            let gain = match m.actuator_gaintype()[i] {
                x if x == mjtGain_::mjGAIN_FIXED as i32 => prm[0],
                x if x == mjtGain_::mjGAIN_AFFINE as i32 => prm[0] + prm[1] * len + prm[2] * vel,
                x => return Err(not_implemented(&format!("actuator gain type {x} is"))),
            };
            if m.actuator_dyntype()[i] != mjtDyn_::mjDYN_NONE as i32 {
                return Err(not_implemented("actuator dynamics are"));
            }
            force[i] = gain * ctrl[i];
            let prm = &m.actuator_biasprm()[mjNBIAS * i..mjNBIAS * (i + 1)];
            let bias = match m.actuator_biastype()[i] {
                x if x == mjtBias_::mjBIAS_NONE as i32 => 0.0,
                x if x == mjtBias_::mjBIAS_AFFINE as i32 => prm[0] + prm[1] * len + prm[2] * vel,
                x => return Err(not_implemented(&format!("actuator bias type {x} is"))),
            };
            force[i] += bias;
        }
        for i in 0..nu {
            if m.actuator_forcelimited()[i] != 0 {
                force[i] = clip(
                    force[i],
                    m.actuator_forcerange()[2 * i],
                    m.actuator_forcerange()[2 * i + 1],
                );
            }
        }
        mul_mat_t_vec(d.qfrc_actuator, d.actuator_moment, force, nu, nv);
        Ok(())
    })?;
    tick(d, mjtTimer_::mjTIMER_ACTUATION);
    Ok(())
}
