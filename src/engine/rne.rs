//! Recursive Newton-Euler: bias forces (gravity, Coriolis, centrifugal) and M*qacc.

use super::linalg::{dot6, put, row};
use super::support::contact_force;
use super::{disabled, Data, EngineError, Model};
use crate::abi::{mjNEQDATA, mjtConstraint_, mjtDisableBit_};
use crate::math::misc::{self, is_zero};
use crate::math::*;

/// result = M(qpos)*qacc + C(qpos,qvel); without the inertial term when `qacc` is None (mj_rne).
pub fn rne_with(
    m: &Model,
    d: &mut Data,
    qacc: Option<&[f64]>,
    result: &mut [f64],
) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    let nv = m.raw.nv as usize;
    d.arena.scope(|a| -> Result<(), EngineError> {
        let cacc = a.alloc(6 * nbody)?;
        let cfrc = a.alloc(6 * nbody)?;
        if !disabled(m, mjtDisableBit_::mjDSBL_GRAVITY) {
            cacc[3..6].copy_from_slice(&scl3(&m.raw.opt.gravity, misc::minus_one()));
        }
        for i in 1..nbody {
            let bda = m.body_dofadr()[i].max(0) as usize;
            let n = m.body_dofnum()[i] as usize;
            let p = m.body_parentid()[i] as usize;
            // rows as arrays: one bounds check a row, not one an element
            let mut acc: Vec6 = row(cacc, p);
            let tmp = mul_dof_vec(&d.cdof_dot[6 * bda..], &d.qvel[bda..], n);
            for k in 0..6 {
                acc[k] += tmp[k];
            }
            if let Some(qacc) = qacc {
                let tmp = mul_dof_vec(&d.cdof[6 * bda..], &qacc[bda..], n);
                for k in 0..6 {
                    acc[k] += tmp[k];
                }
            }
            put(cacc, i, &acc);
            let ci = &d.cinert[10 * i..10 * i + 10];
            let cv = row::<6>(d.cvel, i);
            let mut f = mul_inert_vec(ci, &acc);
            let tmp = mul_inert_vec(ci, &cv);
            let tmp1 = cross_force(&cv, &tmp);
            for k in 0..6 {
                f[k] += tmp1[k];
            }
            put(cfrc, i, &f);
        }
        cfrc[..6].fill(0.0);
        for i in (1..nbody).rev() {
            let p = m.body_parentid()[i] as usize;
            if p != 0 {
                let (child, mut sum): (Vec6, Vec6) = (row(cfrc, i), row(cfrc, p));
                for k in 0..6 {
                    sum[k] += child[k];
                }
                put(cfrc, p, &sum);
            }
        }
        for i in 0..nv {
            let b = m.dof_bodyid()[i] as usize;
            result[i] = dot6(&d.cdof[6 * i..6 * i + 6], &cfrc[6 * b..6 * b + 6]);
        }
        Ok(())
    })
}

/// qfrc_bias by abbreviated RNE (no acceleration term).
pub fn rne_bias(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let out = std::mem::take(&mut d.qfrc_bias);
    let r = rne_with(m, d, None, &mut out[..nv]);
    d.qfrc_bias = out;
    r
}

/// Adds (`sign` 1) or subtracts (-1) a world-oriented torque:force applied at `point` to
/// cfrc_ext of `body`, as a force at the com of the body's tree.
fn add_ext(m: &Model, d: &mut Data, body: usize, frc: &Vec6, point: &Vec3, sign: f64) {
    let com = row(d.subtree_com, m.body_rootid()[body] as usize);
    let f = transform_spatial(frc, true, &com, point, None);
    let ext = &mut d.cfrc_ext[6 * body..6 * body + 6];
    for k in 0..6 {
        if sign > 0.0 {
            ext[k] += f[k];
        } else {
            ext[k] -= f[k];
        }
    }
}

/// cfrc_ext of the connect and weld constraints among the equality rows of efc.
fn equality_ext(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    use crate::abi::mjtEq_::*;
    let ne = d.raw.ne.max(0) as usize;
    let mut i = 0;
    while i < ne {
        if d.efc_type[i] != mjtConstraint_::mjCNSTR_EQUALITY as i32 {
            return Err(EngineError(format!(
                "Row {i} of efc is not an equality constraint"
            )));
        }
        let id = d.efc_id[i] as usize;
        let ty = m.eq_type()[id];
        let data = &m.eq_data()[mjNEQDATA * id..mjNEQDATA * (id + 1)];
        match ty {
            x if x == mjEQ_CONNECT as i32 || x == mjEQ_WELD as i32 => {
                let weld = x == mjEQ_WELD as i32;
                let mut frc = [0.0; 6];
                frc[3..].copy_from_slice(&d.efc_force[i..i + 3]);
                if weld {
                    frc[..3].copy_from_slice(&d.efc_force[i + 3..i + 6]);
                }
                let b1 = m.eq_obj1id()[id] as usize;
                if b1 != 0 {
                    let local = v3(&data[if weld { 3 } else { 0 }..]);
                    let p = add3(&mul_mat_vec3(&row(d.xmat, b1), &local), &row(d.xpos, b1));
                    add_ext(m, d, b1, &frc, &p, 1.0);
                }
                let b2 = m.eq_obj2id()[id] as usize;
                if b2 != 0 {
                    let local = v3(&data[if weld { 0 } else { 3 }..]);
                    let p = add3(&mul_mat_vec3(&row(d.xmat, b2), &local), &row(d.xpos, b2));
                    add_ext(m, d, b2, &frc, &p, -1.0);
                }
                i += if weld { 6 } else { 3 };
            }
            x if x == mjEQ_JOINT as i32 || x == mjEQ_TENDON as i32 => i += 1,
            x if x == mjEQ_DISTANCE as i32 => {
                return Err(EngineError(
                    "distance equality constraints are no longer supported".into(),
                ))
            }
            x => return Err(EngineError(format!("Unknown constraint type type {x}"))),
        }
    }
    Ok(())
}

/// Body accelerations (cacc), interaction forces with the parent (cfrc_int) and external forces
/// (cfrc_ext: applied, contact, connect/weld) after the constraint solve (mj_rnePostConstraint).
pub fn rne_post_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    d.cacc[..6].fill(0.0);
    if !disabled(m, mjtDisableBit_::mjDSBL_GRAVITY) {
        d.cacc[3..6].copy_from_slice(&scl3(&m.raw.opt.gravity, misc::minus_one()));
    }

    // applied forces, rearranged as torque:force
    d.cfrc_ext.fill(0.0);
    for i in 1..nbody {
        let x = row::<6>(d.xfrc_applied, i);
        if !is_zero(&x) {
            let frc = [x[3], x[4], x[5], x[0], x[1], x[2]];
            add_ext(m, d, i, &frc, &row(d.xipos, i), 1.0);
        }
    }

    // contact forces, rotated from the contact frame (force and torque swapped)
    for c in 0..d.raw.ncon.max(0) as usize {
        let con = &d.contact[c];
        if con.efc_address < 0 {
            continue;
        }
        let (frame, pos, g1, g2) = (con.frame, con.pos, con.geom1, con.geom2);
        let lfrc = contact_force(m, d, c as i32);
        let mut frc = [0.0; 6];
        frc[..3].copy_from_slice(&mul_mat_t_vec3(&frame, &v3(&lfrc[3..])));
        frc[3..].copy_from_slice(&mul_mat_t_vec3(&frame, &v3(&lfrc[..3])));
        let b1 = m.geom_bodyid()[g1 as usize] as usize;
        if b1 != 0 {
            add_ext(m, d, b1, &frc, &pos, -1.0);
        }
        let b2 = m.geom_bodyid()[g2 as usize] as usize;
        if b2 != 0 {
            add_ext(m, d, b2, &frc, &pos, 1.0);
        }
    }

    equality_ext(m, d)?;

    // forward pass: cacc and the net force of each body
    d.cfrc_int[..6].fill(0.0);
    for i in 1..nbody {
        let bda = m.body_dofadr()[i].max(0) as usize;
        let n = m.body_dofnum()[i] as usize;
        let p = m.body_parentid()[i] as usize;
        let vel = mul_dof_vec(&d.cdof_dot[6 * bda..], &d.qvel[bda..], n);
        let mut acc: Vec6 = row(d.cacc, p);
        for k in 0..6 {
            acc[k] += vel[k];
        }
        let qa = mul_dof_vec(&d.cdof[6 * bda..], &d.qacc[bda..], n);
        for k in 0..6 {
            acc[k] += qa[k];
        }
        put(d.cacc, i, &acc);

        let ci = &d.cinert[10 * i..10 * i + 10];
        let cv = row::<6>(d.cvel, i);
        let mut body = mul_inert_vec(ci, &acc);
        let corr = cross_force(&cv, &mul_inert_vec(ci, &cv));
        let ext: Vec6 = row(d.cfrc_ext, i);
        for k in 0..6 {
            body[k] += corr[k];
            body[k] -= ext[k];
        }
        put(d.cfrc_int, i, &body);
    }

    // backward pass: children's forces into parents
    for i in (1..nbody).rev() {
        let p = m.body_parentid()[i] as usize;
        let (child, mut sum): (Vec6, Vec6) = (row(d.cfrc_int, i), row(d.cfrc_int, p));
        for k in 0..6 {
            sum[k] += child[k];
        }
        put(d.cfrc_int, p, &sum);
    }
    Ok(())
}
