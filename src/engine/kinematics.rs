//! Position stage: body frames (mj_kinematics), com-based inertias and motion axes
//! (mj_comPos), cameras and lights (mj_camlight).

use super::linalg::{put, row};
use super::support::local_to_global;
use super::{Data, EngineError, Model, JNT_BALL, JNT_FREE, JNT_HINGE, JNT_SLIDE, MINVAL};
use crate::abi::mjtCamLight_;
use crate::math::*;

/// Normalizes the quaternions of ball and free joints in a qpos-like vector.
pub fn normalize_quat(m: &Model, qpos: &mut [f64]) {
    for j in 0..m.jnt_type().len() {
        let t = m.jnt_type()[j];
        if t == JNT_BALL || t == JNT_FREE {
            let adr = m.jnt_qposadr()[j] as usize + if t == JNT_FREE { 3 } else { 0 };
            let q = normalize4(&q4(&qpos[adr..])).0;
            qpos[adr..adr + 4].copy_from_slice(&q);
        }
    }
}

/// Global poses of bodies, joint anchors and axes, inertial frames, geoms and sites.
pub fn kinematics(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    put(d.xpos, 0, &[0.0; 3]);
    put(d.xquat, 0, &unit_quat());
    put(d.xipos, 0, &[0.0; 3]);
    let eye = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    put(d.xmat, 0, &eye);
    put(d.ximat, 0, &eye);

    normalize_quat(m, d.qpos);
    for i in 0..m.raw.nmocap as usize {
        let q = normalize4(&row::<4>(d.mocap_quat, i)).0;
        put(d.mocap_quat, i, &q);
    }

    for i in 1..nbody {
        let jntadr = m.body_jntadr()[i];
        let jntnum = m.body_jntnum()[i] as usize;
        let (mut pos, mut quat);
        if jntnum == 1 && m.jnt_type()[jntadr as usize] == JNT_FREE {
            let jid = jntadr as usize;
            let qadr = m.jnt_qposadr()[jid] as usize;
            pos = v3(&d.qpos[qadr..]);
            quat = q4(&d.qpos[qadr + 3..]);
            put(d.xanchor, jid, &pos);
            put(d.xaxis, jid, &[0.0, 0.0, 1.0]);
        } else {
            let pid = m.body_parentid()[i] as usize;
            let mocap = m.body_mocapid()[i];
            let (bpos, bquat) = if mocap >= 0 {
                (
                    row::<3>(d.mocap_pos, mocap as usize),
                    row::<4>(d.mocap_quat, mocap as usize),
                )
            } else {
                (row::<3>(m.body_pos(), i), row::<4>(m.body_quat(), i))
            };
            let vec = mul_mat_vec3(&row(d.xmat, pid), &bpos);
            pos = add3(&row(d.xpos, pid), &vec);
            quat = mul_quat(&row(d.xquat, pid), &bquat);

            for j in 0..jntnum {
                let jid = jntadr as usize + j;
                let qadr = m.jnt_qposadr()[jid] as usize;
                let jtype = m.jnt_type()[jid];
                let jaxis = row::<3>(m.jnt_axis(), jid);
                let jpos = row::<3>(m.jnt_pos(), jid);
                let xaxis = rot_vec_quat(&jaxis, &quat);
                let xanchor = add3(&rot_vec_quat(&jpos, &quat), &pos);
                match jtype {
                    JNT_SLIDE => {
                        add_to_scl3(&mut pos, &xaxis, d.qpos[qadr] - m.qpos0()[qadr]);
                    }
                    JNT_BALL | JNT_HINGE => {
                        let qloc = if jtype == JNT_BALL {
                            q4(&d.qpos[qadr..])
                        } else {
                            axis_angle2quat(&jaxis, d.qpos[qadr] - m.qpos0()[qadr])
                        };
                        quat = mul_quat(&quat, &qloc);
                        let vec = sub3(&xanchor, &pos);
                        let vec1 = rot_vec_quat(&jpos, &quat);
                        pos[0] += vec[0] - vec1[0];
                        pos[1] += vec[1] - vec1[1];
                        pos[2] += vec[2] - vec1[2];
                    }
                    _ => return Err(EngineError(format!("Unknown joint type {jtype}"))),
                }
                put(d.xanchor, jid, &xanchor);
                put(d.xaxis, jid, &xaxis);
            }
        }
        let quat = normalize4(&quat).0;
        put(d.xquat, i, &quat);
        put(d.xpos, i, &pos);
        put(d.xmat, i, &quat2mat(&quat));
    }

    for i in 1..nbody {
        let (p, r) = local_to_global(
            d,
            &row(m.body_ipos(), i),
            &row(m.body_iquat(), i),
            i,
            m.body_sameframe()[i],
        );
        put(d.xipos, i, &p);
        put(d.ximat, i, &r);
    }
    for i in 0..m.raw.ngeom as usize {
        let b = m.geom_bodyid()[i] as usize;
        let (p, r) = local_to_global(
            d,
            &row(m.geom_pos(), i),
            &row(m.geom_quat(), i),
            b,
            m.geom_sameframe()[i],
        );
        put(d.geom_xpos, i, &p);
        put(d.geom_xmat, i, &r);
    }
    for i in 0..m.raw.nsite as usize {
        let b = m.site_bodyid()[i] as usize;
        let (p, r) = local_to_global(
            d,
            &row(m.site_pos(), i),
            &row(m.site_quat(), i),
            b,
            m.site_sameframe()[i],
        );
        put(d.site_xpos, i, &p);
        put(d.site_xmat, i, &r);
    }
    Ok(())
}

/// Subtree centers of mass, com-frame inertias (cinert) and motion axes (cdof).
pub fn com_pos(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    d.subtree_com.fill(0.0);
    d.arena.scope(|a| -> Result<(), EngineError> {
        let mass = a.alloc(nbody)?;
        for i in (0..nbody).rev() {
            let mut c = row::<3>(d.subtree_com, i);
            add_to_scl3(&mut c, &row(d.xipos, i), m.body_mass()[i]);
            mass[i] += m.body_mass()[i];
            put(d.subtree_com, i, &c);
            if i > 0 {
                let p = m.body_parentid()[i] as usize;
                let pc = add3(&row(d.subtree_com, p), &c);
                put(d.subtree_com, p, &pc);
                mass[p] += mass[i];
            }
            let c = if mass[i] < MINVAL {
                row(d.xipos, i)
            } else {
                scl3(&c, 1.0 / if MINVAL > mass[i] { MINVAL } else { mass[i] })
            };
            put(d.subtree_com, i, &c);
        }
        Ok(())
    })?;

    for i in 1..nbody {
        let root = m.body_rootid()[i] as usize;
        let offset = sub3(&row(d.xipos, i), &row(d.subtree_com, root));
        let ci = inert_com(
            &row(m.body_inertia(), i),
            &row(d.ximat, i),
            &offset,
            m.body_mass()[i],
        );
        put(d.cinert, i, &ci);
    }

    for j in 0..m.raw.njnt as usize {
        let da = m.jnt_dofadr()[j] as usize;
        let bi = m.jnt_bodyid()[j] as usize;
        let offset = sub3(
            &row(d.subtree_com, m.body_rootid()[bi] as usize),
            &row(d.xanchor, j),
        );
        match m.jnt_type()[j] {
            t @ (JNT_FREE | JNT_BALL) => {
                let mut k = da;
                if t == JNT_FREE {
                    for i in 0..3 {
                        let mut c = [0.0; 6];
                        c[3 + i] = 1.0;
                        put(d.cdof, da + i, &c);
                    }
                    k += 3;
                }
                let xm = row::<9>(d.xmat, bi);
                for i in 0..3 {
                    let axis = [xm[i], xm[i + 3], xm[i + 6]];
                    put(d.cdof, k + i, &dof_com(&axis, Some(&offset)));
                }
            }
            JNT_SLIDE => put(d.cdof, da, &dof_com(&row(d.xaxis, j), None)),
            JNT_HINGE => put(d.cdof, da, &dof_com(&row(d.xaxis, j), Some(&offset))),
            _ => {}
        }
    }
    Ok(())
}

/// Poses of cameras and lights, including tracking and targeting modes.
/// `fixed` treats every camera and light as fixed (mj_setConst does this).
#[inline]
pub fn camlight(m: &Model, d: &mut Data, fixed: bool) {
    if m.raw.ncam > 0 || m.raw.nlight > 0 {
        cameras_lights(m, d, fixed);
    }
}

#[inline(never)]
fn cameras_lights(m: &Model, d: &mut Data, fixed: bool) {
    const TRACK: i32 = mjtCamLight_::mjCAMLIGHT_TRACK as i32;
    const TRACKCOM: i32 = mjtCamLight_::mjCAMLIGHT_TRACKCOM as i32;
    const TARGET: i32 = mjtCamLight_::mjCAMLIGHT_TARGETBODY as i32;
    const TARGETCOM: i32 = mjtCamLight_::mjCAMLIGHT_TARGETBODYCOM as i32;

    for i in 0..m.raw.ncam as usize {
        let id = m.cam_bodyid()[i] as usize;
        let id1 = m.cam_targetbodyid()[i];
        let (p, r) = local_to_global(d, &row(m.cam_pos(), i), &row(m.cam_quat(), i), id, 0);
        put(d.cam_xpos, i, &p);
        put(d.cam_xmat, i, &r);
        let mode = if fixed { 0 } else { m.cam_mode()[i] };
        match mode {
            TRACK | TRACKCOM => {
                put(d.cam_xmat, i, &row::<9>(m.cam_mat0(), i));
                let p = if mode == TRACK {
                    add3(&row(d.xpos, id), &row(m.cam_pos0(), i))
                } else {
                    add3(&row(d.subtree_com, id), &row(m.cam_poscom0(), i))
                };
                put(d.cam_xpos, i, &p);
            }
            TARGET | TARGETCOM if id1 >= 0 => {
                let target = if mode == TARGET {
                    row::<3>(d.xpos, id1 as usize)
                } else {
                    row::<3>(d.subtree_com, id1 as usize)
                };
                let z = normalize3(&sub3(&row(d.cam_xpos, i), &target)).0;
                let x = normalize3(&cross(&[0.0, 0.0, 1.0], &z)).0;
                let y = normalize3(&cross(&z, &x)).0;
                let mat = [x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]];
                put(d.cam_xmat, i, &mat);
            }
            _ => {}
        }
    }

    for i in 0..m.raw.nlight as usize {
        let id = m.light_bodyid()[i] as usize;
        let id1 = m.light_targetbodyid()[i];
        let lp = row::<3>(m.light_pos(), i);
        let p = add3(&mul_mat_vec3(&row(d.xmat, id), &lp), &row(d.xpos, id));
        put(d.light_xpos, i, &p);
        let mut dir = rot_vec_quat(&row(m.light_dir(), i), &row(d.xquat, id));
        let mode = if fixed { 0 } else { m.light_mode()[i] };
        match mode {
            TRACK | TRACKCOM => {
                dir = row(m.light_dir0(), i);
                let p = if mode == TRACK {
                    add3(&row(d.xpos, id), &row(m.light_pos0(), i))
                } else {
                    add3(&row(d.subtree_com, id), &row(m.light_poscom0(), i))
                };
                put(d.light_xpos, i, &p);
            }
            TARGET | TARGETCOM if id1 >= 0 => {
                let target = if mode == TARGET {
                    row::<3>(d.xpos, id1 as usize)
                } else {
                    row::<3>(d.subtree_com, id1 as usize)
                };
                dir = sub3(&target, &row(d.light_xpos, i));
            }
            _ => {}
        }
        put(d.light_xdir, i, &normalize3(&dir).0);
    }
}
