//! Velocity stage: body spatial velocities (cvel) and time derivatives of motion axes (cdof_dot).

use super::linalg::{put, row};
use super::{Data, Model, JNT_BALL, JNT_FREE};
use crate::math::*;

fn add6(a: &mut Vec6, b: &Vec6) {
    for k in 0..6 {
        a[k] += b[k];
    }
}

/// mj_comVel.
pub fn com_vel(m: &Model, d: &mut Data) {
    put(d.cvel, 0, &[0.0; 6]);
    for i in 1..m.raw.nbody as usize {
        let bda = m.body_dofadr()[i] as usize;
        let dofnum = m.body_dofnum()[i] as usize;
        let mut cvel = row::<6>(d.cvel, m.body_parentid()[i] as usize);
        let mut j = 0;
        while j < dofnum {
            let t = m.jnt_type()[m.dof_jntid()[bda + j] as usize];
            if t == JNT_FREE || t == JNT_BALL {
                if t == JNT_FREE {
                    for k in 0..3 {
                        put(d.cdof_dot, bda + j + k, &[0.0; 6]);
                    }
                    let tmp = mul_dof_vec(&d.cdof[6 * bda..], &d.qvel[bda..], 3);
                    add6(&mut cvel, &tmp);
                    j += 3;
                }
                for k in 0..3 {
                    let cd = cross_motion(&cvel, &row(d.cdof, bda + j + k));
                    put(d.cdof_dot, bda + j + k, &cd);
                }
                let tmp = mul_dof_vec(&d.cdof[6 * (bda + j)..], &d.qvel[bda + j..], 3);
                add6(&mut cvel, &tmp);
                j += 3;
            } else {
                let c = row::<6>(d.cdof, bda + j);
                put(d.cdof_dot, bda + j, &cross_motion(&cvel, &c));
                let tmp = mul_dof_vec(&c, &d.qvel[bda + j..], 1);
                add6(&mut cvel, &tmp);
                j += 1;
            }
        }
        put(d.cvel, i, &cvel);
    }
}
