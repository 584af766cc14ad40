//! Velocity stage: body spatial velocities (cvel) and time derivatives of motion axes (cdof_dot).

use super::linalg::{max, put, row};
use super::{Data, EngineError, Model, JNT_BALL, JNT_FREE, MINVAL};
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

/// Velocity of body `i`'s inertial frame, global orientation (mj_objectVelocity for mjOBJ_BODY).
fn body_com_vel(m: &Model, d: &Data, i: usize) -> Vec6 {
    let com = row(d.subtree_com, m.body_rootid()[i] as usize);
    transform_spatial(&row(d.cvel, i), false, &row(d.xipos, i), &com, None)
}

/// subtree_linvel (com velocity) and subtree_angmom (angular momentum about the subtree com)
/// of every body (mj_subtreeVel).
pub fn subtree_vel(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    // the body velocities, kept on the stack as 2.2.2 keeps them (6 per body)
    d.with_scratch(|d, a| -> Result<(), EngineError> {
        let body_vel = a.alloc_stale(6 * nbody)?;
        subtree_vel_with(m, d, body_vel);
        Ok(())
    })
}

fn subtree_vel_with(m: &Model, d: &mut Data, body_vel: &mut [f64]) {
    let nbody = m.raw.nbody as usize;
    for i in 0..nbody {
        let vel = body_com_vel(m, d, i);
        put(body_vel, i, &vel);
        let mass = m.body_mass()[i];
        put(d.subtree_linvel, i, &scl3(&v3(&vel[3..]), mass));
        let ximat = row::<9>(d.ximat, i);
        let mut w = mul_mat_t_vec3(&ximat, &v3(&vel[..3]));
        for k in 0..3 {
            w[k] *= m.body_inertia()[3 * i + k];
        }
        put(d.subtree_angmom, i, &mul_mat_vec3(&ximat, &w));
    }

    // momenta summed into parents, then divided by the subtree masses
    for i in (0..nbody).rev() {
        if i > 0 {
            let p = m.body_parentid()[i] as usize;
            let sum = add3(&row(d.subtree_linvel, p), &row(d.subtree_linvel, i));
            put(d.subtree_linvel, p, &sum);
        }
        let inv = 1.0 / max(MINVAL, m.body_subtreemass()[i]);
        let v = scl3(&row(d.subtree_linvel, i), inv);
        put(d.subtree_linvel, i, &v);
    }

    for i in (1..nbody).rev() {
        let p = m.body_parentid()[i] as usize;
        let vel = row::<6>(body_vel, i);
        let com_i = row::<3>(d.subtree_com, i);
        let linvel_i = row::<3>(d.subtree_linvel, i);

        // body momentum about the subtree com, added to the subtree, which goes to the parent
        let dx = sub3(&row(d.xipos, i), &com_i);
        let dp = scl3(&sub3(&v3(&vel[3..]), &linvel_i), m.body_mass()[i]);
        let own = add3(&row(d.subtree_angmom, i), &cross(&dx, &dp));
        put(d.subtree_angmom, i, &own);
        let mut parent = add3(&row(d.subtree_angmom, p), &own);

        // momentum of the subtree's com motion about the parent's com
        let dx = sub3(&com_i, &row(d.subtree_com, p));
        let dv = scl3(
            &sub3(&linvel_i, &row(d.subtree_linvel, p)),
            m.body_subtreemass()[i],
        );
        parent = add3(&parent, &cross(&dx, &dv));
        put(d.subtree_angmom, p, &parent);
    }
}
