//! Actuator transmissions: lengths and moment arms (joint and joint-in-parent only).

use super::{not_implemented, Data, EngineError, Model, JNT_BALL, JNT_HINGE, JNT_SLIDE};
use crate::abi::mjtTrn_;
use crate::math::*;

/// actuator_length and actuator_moment (mj_transmission).
pub fn transmission(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nu = m.raw.nu as usize;
    let nv = m.raw.nv as usize;
    if nu == 0 {
        return Ok(());
    }
    d.actuator_moment.fill(0.0);
    for i in 0..nu {
        let id = m.actuator_trnid()[2 * i] as usize;
        let gear = &m.actuator_gear()[6 * i..6 * i + 6];
        let trn = m.actuator_trntype()[i];
        let inparent = trn == mjtTrn_::mjTRN_JOINTINPARENT as i32;
        if trn != mjtTrn_::mjTRN_JOINT as i32 && !inparent {
            return Err(not_implemented(&format!(
                "actuator transmission type {trn} is"
            )));
        }
        let moment = &mut d.actuator_moment[i * nv..(i + 1) * nv];
        let qadr = m.jnt_qposadr()[id] as usize;
        let dadr = m.jnt_dofadr()[id] as usize;
        match m.jnt_type()[id] {
            JNT_SLIDE | JNT_HINGE => {
                d.actuator_length[i] = d.qpos[qadr] * gear[0];
                moment[dadr] = gear[0];
            }
            JNT_BALL => {
                let q = q4(&d.qpos[qadr..]);
                let axis = quat2vel(&q, 1.0);
                let g = v3(gear);
                let gear_axis = if inparent {
                    rot_vec_quat(&g, &neg_quat(&q))
                } else {
                    g
                };
                d.actuator_length[i] = dot3(&axis, &gear_axis);
                moment[dadr..dadr + 3].copy_from_slice(&gear_axis);
            }
            _ => {
                d.actuator_length[i] = 0.0;
                let q = q4(&d.qpos[qadr + 3..]);
                let g = v3(&gear[3..]);
                let gear_axis = if inparent {
                    rot_vec_quat(&g, &neg_quat(&q))
                } else {
                    g
                };
                moment[dadr..dadr + 3].copy_from_slice(&gear[..3]);
                moment[dadr + 3..dadr + 6].copy_from_slice(&gear_axis);
            }
        }
    }
    Ok(())
}
