//! Passive forces: joint springs (quaternion springs for ball and free joints), dof dampers.

use super::{disabled, Data, EngineError, Model, JNT_BALL, JNT_FREE, JNT_HINGE, JNT_SLIDE};
use crate::abi::mjtDisableBit_;
use crate::math::blas::add_to_scl;
use crate::math::*;

/// qfrc_passive (mj_passive): joint and tendon springs and dampers, fluid forces.
pub fn passive(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    d.qfrc_passive.fill(0.0);
    if disabled(m, mjtDisableBit_::mjDSBL_PASSIVE) {
        return Ok(());
    }
    let f = &mut *d.qfrc_passive;
    let (stiffness, qposadr, dofadr) = (m.jnt_stiffness(), m.jnt_qposadr(), m.jnt_dofadr());
    for (j, &t) in m.jnt_type().iter().enumerate() {
        let k = stiffness[j];
        let mut padr = qposadr[j] as usize;
        let mut dadr = dofadr[j] as usize;
        match t {
            t @ (JNT_FREE | JNT_BALL)
                if k == 0.0 && finite_spring(d.qpos, m.qpos_spring(), padr, t) =>
            {
                // 0 * (a finite difference) is a zero, and subtracting a zero leaves the
                // cleared force +0: skips the quaternion difference (an atan2) of each joint
            }
            t @ (JNT_FREE | JNT_BALL) => {
                if t == JNT_FREE {
                    for i in 0..3 {
                        f[dadr + i] -= k * (d.qpos[padr + i] - m.qpos_spring()[padr + i]);
                    }
                    dadr += 3;
                    padr += 3;
                }
                let dif = sub_quat(&q4(&d.qpos[padr..]), &q4(&m.qpos_spring()[padr..]));
                for i in 0..3 {
                    f[dadr + i] -= k * dif[i];
                }
            }
            JNT_SLIDE | JNT_HINGE => {
                f[dadr] -= k * (d.qpos[padr] - m.qpos_spring()[padr]);
            }
            _ => {}
        }
    }
    for ((x, b), v) in f.iter_mut().zip(m.dof_damping()).zip(&*d.qvel) {
        *x -= b * v;
    }
    let sparse = super::jacdif::is_sparse(m);
    let nv = m.raw.nv as usize;
    for i in 0..m.raw.ntendon as usize {
        let frc = -m.tendon_stiffness()[i] * (d.ten_length[i] - m.tendon_lengthspring()[i])
            - m.tendon_damping()[i] * d.ten_velocity[i];
        if sparse {
            let adr = d.ten_J_rowadr[i] as usize;
            for j in adr..adr + d.ten_J_rownnz[i] as usize {
                f[d.ten_J_colind[j] as usize] += d.ten_J[j] * frc;
            }
        } else {
            add_to_scl(f, &d.ten_J[i * nv..(i + 1) * nv], frc);
        }
    }
    super::fluid::fluid(m, d)?;
    super::hooks::passive(m, d);
    Ok(())
}

/// Whether the positions and spring positions of a free or ball joint are all finite, so that
/// their difference (a quaternion difference for the rotation) is finite too.
fn finite_spring(qpos: &[f64], spring: &[f64], padr: usize, t: i32) -> bool {
    let n = if t == JNT_FREE { 7 } else { 4 };
    let (q, s) = (&qpos[padr..padr + n], &spring[padr..padr + n]);
    q.iter().chain(s).all(|x| x.is_finite())
}
