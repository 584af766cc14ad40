//! Constraint instantiation: this slice has no constraint solver, so any constraint that would
//! become active is reported as not implemented; with none, the constraint sizes stay 0.

use super::linalg::max;
use super::{disabled, not_implemented, Data, EngineError, Model, JNT_BALL, JNT_HINGE, JNT_SLIDE};
use crate::abi::mjtDisableBit_;
use crate::math::*;

/// mj_makeConstraint for a model whose constraints are all inactive.
pub fn make_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    d.raw.ne = 0;
    d.raw.nf = 0;
    d.raw.nefc = 0;
    if disabled(m, mjtDisableBit_::mjDSBL_CONSTRAINT) || m.raw.njmax == 0 {
        return Ok(());
    }
    if !disabled(m, mjtDisableBit_::mjDSBL_EQUALITY)
        && m.raw.nemax != 0
        && m.eq_active().iter().any(|&a| a != 0)
    {
        return Err(not_implemented("equality constraints are"));
    }
    if !disabled(m, mjtDisableBit_::mjDSBL_FRICTIONLOSS)
        && (m.dof_frictionloss().iter().any(|&f| f > 0.0)
            || m.tendon_frictionloss().iter().any(|&f| f > 0.0))
    {
        return Err(not_implemented("frictionloss constraints are"));
    }
    if !disabled(m, mjtDisableBit_::mjDSBL_LIMIT) {
        for i in 0..m.raw.njnt as usize {
            if m.jnt_limited()[i] == 0 {
                continue;
            }
            let margin = m.jnt_margin()[i];
            let qadr = m.jnt_qposadr()[i] as usize;
            let active = match m.jnt_type()[i] {
                JNT_SLIDE | JNT_HINGE => {
                    let v = d.qpos[qadr];
                    -(m.jnt_range()[2 * i] - v) < margin || (m.jnt_range()[2 * i + 1] - v) < margin
                }
                JNT_BALL => {
                    let (_, angle) = normalize3(&quat2vel(&q4(&d.qpos[qadr..]), 1.0));
                    max(m.jnt_range()[2 * i], m.jnt_range()[2 * i + 1]) - angle < margin
                }
                _ => false,
            };
            if active {
                return Err(not_implemented("joint limit constraints are"));
            }
        }
        if m.tendon_limited().iter().any(|&l| l != 0) {
            return Err(not_implemented("tendon limit constraints are"));
        }
    }
    if d.raw.ncon > 0 {
        return Err(not_implemented("contact constraints are"));
    }
    d.raw.maxuse_con = d.raw.maxuse_con.max(d.raw.ncon);
    d.raw.maxuse_efc = d.raw.maxuse_efc.max(d.raw.nefc);
    Ok(())
}
