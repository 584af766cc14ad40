//! Frames, names, masses, warnings, energy and data reset.

use super::linalg::{dot, put, row};
use super::{
    disabled, enabled, Data, EngineError, Model, JNT_BALL, JNT_FREE, JNT_HINGE, JNT_SLIDE,
};
use crate::abi::*;
use crate::math::misc::decode_pyramid;
use crate::math::*;

/// The arrays a body's frames are read from (rows of 3, 9 and 4 a body), up to some body.
pub(crate) struct BodyFrames<'a> {
    pub xpos: &'a [f64],
    pub xmat: &'a [f64],
    pub xquat: &'a [f64],
    pub xipos: &'a [f64],
    pub ximat: &'a [f64],
}

impl<'a> BodyFrames<'a> {
    pub fn of(d: &'a Data) -> Self {
        BodyFrames {
            xpos: d.xpos,
            xmat: d.xmat,
            xquat: d.xquat,
            xipos: d.xipos,
            ximat: d.ximat,
        }
    }
}

/// Global position of a point given relative to `body` (mj_local2Global); `sameframe` 1 takes
/// the body frame's origin, 2 the inertial frame's.
#[inline(always)]
pub(crate) fn local_pos_to_global(f: &BodyFrames, pos: &Vec3, body: usize, sameframe: u8) -> Vec3 {
    match sameframe {
        0 => add3(&mul_mat_vec3(&row(f.xmat, body), pos), &row(f.xpos, body)),
        1 => row(f.xpos, body),
        _ => row(f.xipos, body),
    }
}

/// Global orientation of a frame given relative to `body` (mj_local2Global); `sameframe` 1
/// takes the body frame's, 2 the inertial frame's.
#[inline(always)]
pub(crate) fn local_quat_to_global(
    f: &BodyFrames,
    quat: &Quat,
    body: usize,
    sameframe: u8,
) -> Mat3 {
    match sameframe {
        0 => quat2mat(&mul_quat(&row(f.xquat, body), quat)),
        1 => row(f.xmat, body),
        _ => row(f.ximat, body),
    }
}

/// Global pose of a frame given relative to `body`: both of the above.
#[inline(always)]
pub fn local_to_global(
    d: &Data,
    pos: &Vec3,
    quat: &Quat,
    body: usize,
    sameframe: u8,
) -> (Vec3, Mat3) {
    let f = BodyFrames::of(d);
    (
        local_pos_to_global(&f, pos, body, sameframe),
        local_quat_to_global(&f, quat, body, sameframe),
    )
}

/// Counts a warning; reports it through mju_warning the first time (mj_warning).
pub fn warning(d: &mut mjData, kind: i32, info: i32) -> Result<(), EngineError> {
    if !(0..mjtWarning_::mjNWARNING as i32).contains(&kind) {
        return Err(EngineError(format!("Invalid warning type {kind}")));
    }
    let w = &mut d.warning[kind as usize];
    w.lastinfo = info;
    if w.number == 0 {
        use std::fmt::Write;
        let mut text = crate::runtime::MsgBuf::new();
        let _ = crate::math::misc::write_warning_text(&mut text, kind, info);
        let _ = write!(text, " Time = {:.4}.", d.time);
        crate::runtime::warning(text.as_str());
    }
    d.warning[kind as usize].number += 1;
    Ok(())
}

/// mj_resetData on the views: clear header and arrays, qpos = qpos0, mocap from bodies.
pub fn reset_data(m: &Model, d: &mut Data) {
    clear_header(d);
    d.clear_arrays();
    reset_state(m, d);
}

/// mj_resetData on data whose arrays are all zero already (fresh from `alloc_data`): the same
/// result without clearing them again, which would touch every page of a large buffer.
pub fn reset_fresh_data(m: &Model, d: &mut Data) {
    clear_header(d);
    reset_state(m, d);
}

/// Clears the header: stack use, diagnostics, sizes, time, energy.
pub fn clear_header(d: &mut Data) {
    d.arena.reset_peak();
    let r = &mut *d.raw;
    r.pstack = 0;
    r.maxuse_stack = 0;
    r.maxuse_con = 0;
    r.maxuse_efc = 0;
    for w in r.warning.iter_mut() {
        w.lastinfo = 0;
        w.number = 0;
    }
    for t in r.timer.iter_mut() {
        t.duration = 0.0;
        t.number = 0;
    }
    for s in r.solver.iter_mut() {
        s.improvement = 0.0;
        s.gradient = 0.0;
        s.lineslope = 0.0;
        s.nactive = 0;
        s.nchange = 0;
        s.neval = 0;
        s.nupdate = 0;
    }
    r.solver_iter = 0;
    r.solver_nnz = 0;
    r.solver_fwdinv = [0.0; 2];
    r.ne = 0;
    r.nf = 0;
    r.nefc = 0;
    r.ncon = 0;
    r.time = 0.0;
    r.energy = [0.0; 2];
}

/// Zeroes the inputs and the arrays mj_forward does not fill; qpos = qpos0, mocap from bodies.
pub fn reset_state(m: &Model, d: &mut Data) {
    for a in [
        &mut d.qpos,
        &mut d.qvel,
        &mut d.act,
        &mut d.ctrl,
        &mut d.qfrc_applied,
        &mut d.xfrc_applied,
    ] {
        a.fill(0.0);
    }
    for a in [
        &mut d.qacc,
        &mut d.qacc_warmstart,
        &mut d.act_dot,
        &mut d.userdata,
        &mut d.sensordata,
    ] {
        a.fill(0.0);
    }
    d.mocap_pos.fill(0.0);
    d.mocap_quat.fill(0.0);
    // a model of sizes only (as the Python bindings' unpickling makes) has no qpos0 and no
    // mocap bodies: qpos stays zero, mocap quaternions are the identity
    if !m.raw.qpos0.is_null() {
        d.qpos.copy_from_slice(m.qpos0());
    }
    if m.raw.body_mocapid.is_null() {
        for q in d.mocap_quat.chunks_exact_mut(4) {
            q[0] = 1.0;
        }
        return;
    }
    for (i, &id) in m.body_mocapid().iter().enumerate() {
        if id >= 0 {
            put(d.mocap_pos, id as usize, &row::<3>(m.body_pos(), i));
            put(d.mocap_quat, id as usize, &row::<4>(m.body_quat(), i));
        }
    }
}

/// mj_resetDataKeyframe: reset, then take time, state, mocap poses and controls from keyframe
/// `key` when it exists.
pub fn reset_data_keyframe(m: &Model, d: &mut Data, key: i32) {
    reset_data(m, d);
    if key < 0 || key >= m.raw.nkey {
        return;
    }
    let k = key as usize;
    d.raw.time = m.key_time()[k];
    let rows = [
        (&mut d.qpos, m.key_qpos()),
        (&mut d.qvel, m.key_qvel()),
        (&mut d.act, m.key_act()),
        (&mut d.mocap_pos, m.key_mpos()),
        (&mut d.mocap_quat, m.key_mquat()),
        (&mut d.ctrl, m.key_ctrl()),
    ];
    for (dst, src) in rows {
        let n = dst.len();
        dst.copy_from_slice(&src[k * n..(k + 1) * n]);
    }
}

/// Names of objects of `objtype`: (count, name addresses).
fn name_table<'a>(m: &Model<'a>, objtype: i32) -> &'a [i32] {
    use mjtObj_::*;
    let t = |o: mjtObj_| o as i32;
    match objtype {
        x if x == t(mjOBJ_BODY) || x == t(mjOBJ_XBODY) => m.name_bodyadr(),
        x if x == t(mjOBJ_JOINT) => m.name_jntadr(),
        x if x == t(mjOBJ_GEOM) => m.name_geomadr(),
        x if x == t(mjOBJ_SITE) => m.name_siteadr(),
        x if x == t(mjOBJ_CAMERA) => m.name_camadr(),
        x if x == t(mjOBJ_LIGHT) => m.name_lightadr(),
        x if x == t(mjOBJ_MESH) => m.name_meshadr(),
        x if x == t(mjOBJ_SKIN) => m.name_skinadr(),
        x if x == t(mjOBJ_HFIELD) => m.name_hfieldadr(),
        x if x == t(mjOBJ_TEXTURE) => m.name_texadr(),
        x if x == t(mjOBJ_MATERIAL) => m.name_matadr(),
        x if x == t(mjOBJ_PAIR) => m.name_pairadr(),
        x if x == t(mjOBJ_EXCLUDE) => m.name_excludeadr(),
        x if x == t(mjOBJ_EQUALITY) => m.name_eqadr(),
        x if x == t(mjOBJ_TENDON) => m.name_tendonadr(),
        x if x == t(mjOBJ_ACTUATOR) => m.name_actuatoradr(),
        x if x == t(mjOBJ_SENSOR) => m.name_sensoradr(),
        x if x == t(mjOBJ_NUMERIC) => m.name_numericadr(),
        x if x == t(mjOBJ_TEXT) => m.name_textadr(),
        x if x == t(mjOBJ_TUPLE) => m.name_tupleadr(),
        x if x == t(mjOBJ_KEY) => m.name_keyadr(),
        _ => &[],
    }
}

/// Id of the object of `objtype` named `name`, or -1 (mj_name2id).
pub fn name2id(m: &Model, objtype: i32, name: &[u8]) -> i32 {
    let names = m.names();
    for (i, &adr) in name_table(m, objtype).iter().enumerate() {
        let rest = &names[(adr as usize).min(names.len())..];
        // strncmp over the rest of the names buffer, leaving at the first difference: equal
        // when the name is followed by its end
        let named = rest.get(..name.len()).is_some_and(|head| {
            head.iter().zip(name).all(|(&a, &b)| a as u8 == b)
                && rest.get(name.len()).is_none_or(|&c| c == 0)
        });
        if named {
            return i as i32;
        }
    }
    -1
}

/// Address in `names` of the name of object `id`, or None when invalid or empty (mj_id2name).
pub fn id2name(m: &Model, objtype: i32, id: i32) -> Option<usize> {
    let adr = name_table(m, objtype);
    if id < 0 || id as usize >= adr.len() {
        return None;
    }
    let a = adr[id as usize] as usize;
    (m.names().get(a).copied().unwrap_or(0) != 0).then_some(a)
}

/// Sum of body masses (mj_getTotalmass).
pub fn total_mass(m: &Model) -> f64 {
    let mut res = 0.0;
    for &b in &m.body_mass()[1..] {
        res += b;
    }
    res
}

/// Scales masses and inertias to a new total (mj_setTotalmass).
pub fn set_total_mass(body_mass: &mut [f64], body_inertia: &mut [f64], newmass: f64) {
    let mut total = 0.0;
    for &b in &body_mass[1..] {
        total += b;
    }
    let scale = super::linalg::max(
        super::MINVAL,
        newmass / super::linalg::max(super::MINVAL, total),
    );
    for i in 1..body_mass.len() {
        body_mass[i] *= scale;
        body_inertia[3 * i] *= scale;
        body_inertia[3 * i + 1] *= scale;
        body_inertia[3 * i + 2] *= scale;
    }
}

/// Potential energy: gravity and joint springs (mj_energyPos).
pub fn energy_pos(m: &Model, d: &mut Data) {
    if !enabled(m, mjtEnableBit_::mjENBL_ENERGY) {
        d.raw.energy = [0.0; 2];
        return;
    }
    let mut e = 0.0;
    if !disabled(m, mjtDisableBit_::mjDSBL_GRAVITY) {
        for i in 1..m.raw.nbody as usize {
            e -= m.body_mass()[i] * dot3(&m.raw.opt.gravity, &row(d.xipos, i));
        }
    }
    if !disabled(m, mjtDisableBit_::mjDSBL_PASSIVE) {
        for j in 0..m.raw.njnt as usize {
            let k = m.jnt_stiffness()[j];
            let mut padr = m.jnt_qposadr()[j] as usize;
            match m.jnt_type()[j] {
                t @ (JNT_FREE | JNT_BALL) => {
                    if t == JNT_FREE {
                        let dif = sub3(&v3(&d.qpos[padr..]), &v3(&m.qpos_spring()[padr..]));
                        e += 0.5 * k * dot3(&dif, &dif);
                        padr += 3;
                    }
                    let dif = sub_quat(&q4(&d.qpos[padr..]), &q4(&m.qpos_spring()[padr..]));
                    e += 0.5 * k * dot3(&dif, &dif);
                }
                JNT_SLIDE | JNT_HINGE => {
                    let dq = d.qpos[padr] - m.qpos_spring()[padr];
                    e += 0.5 * k * dq * dq;
                }
                _ => {}
            }
        }
        for i in 0..m.raw.ntendon as usize {
            let dl = d.ten_length[i] - m.tendon_lengthspring()[i];
            e += 0.5 * m.tendon_stiffness()[i] * dl * dl;
        }
    }
    d.raw.energy[0] = e;
}

/// Kinetic energy 0.5 qvel' M qvel (mj_energyVel).
pub fn energy_vel(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if !enabled(m, mjtEnableBit_::mjENBL_ENERGY) {
        return Ok(());
    }
    let nv = m.raw.nv as usize;
    let e = d.arena.scope(|a| -> Result<f64, EngineError> {
        let vec = a.alloc(nv)?;
        super::jacobian::mul_m(m, d.qM, vec, d.qvel);
        Ok(0.5 * dot(vec, d.qvel))
    })?;
    d.raw.energy[1] = e;
    Ok(())
}

/// Body, global position and orientation of an object with a spatial frame (body, xbody, geom,
/// site, camera); None for other object types.
#[inline(always)]
pub fn object_frame(m: &Model, d: &Data, objtype: i32, id: usize) -> Option<(usize, Vec3, Mat3)> {
    use mjtObj_::*;
    let (pos, mat) = frame_arrays(d, objtype)?;
    let body = match objtype {
        x if x == mjOBJ_GEOM as i32 => m.geom_bodyid()[id] as usize,
        x if x == mjOBJ_SITE as i32 => m.site_bodyid()[id] as usize,
        x if x == mjOBJ_CAMERA as i32 => m.cam_bodyid()[id] as usize,
        _ => id,
    };
    Some((body, row(pos, id), row(mat, id)))
}

/// Global positions (3 a row) and orientations (9 a row) of the objects of a type with a
/// spatial frame (body: its inertial frame, xbody, geom, site, camera); None for other types.
#[inline(always)]
pub fn frame_arrays<'d>(d: &'d Data, objtype: i32) -> Option<(&'d [f64], &'d [f64])> {
    use mjtObj_::*;
    let t = |o: mjtObj_| o as i32;
    match objtype {
        x if x == t(mjOBJ_BODY) => Some((d.xipos, d.ximat)),
        x if x == t(mjOBJ_XBODY) => Some((d.xpos, d.xmat)),
        x if x == t(mjOBJ_GEOM) => Some((d.geom_xpos, d.geom_xmat)),
        x if x == t(mjOBJ_SITE) => Some((d.site_xpos, d.site_xmat)),
        x if x == t(mjOBJ_CAMERA) => Some((d.cam_xpos, d.cam_xmat)),
        _ => None,
    }
}

/// Body, position, com of its tree and optional rotation of an object for the spatial
/// transforms of mj_objectVelocity / mj_objectAcceleration.
#[inline(always)]
fn motion_frame(
    m: &Model,
    d: &Data,
    objtype: i32,
    id: usize,
    local: bool,
    caller: &str,
) -> Result<(usize, Vec3, Vec3, Option<Mat3>), EngineError> {
    let Some((body, pos, mat)) = object_frame(m, d, objtype, id) else {
        return Err(invalid_type(objtype, caller));
    };
    let com = row(d.subtree_com, m.body_rootid()[body] as usize);
    Ok((body, pos, com, local.then_some(mat)))
}

#[cold]
fn invalid_type(objtype: i32, caller: &str) -> EngineError {
    EngineError(format!("Invalid object type {objtype} in {caller}"))
}

/// 6D velocity [rotation; translation] of an object, global or in its frame (mj_objectVelocity).
#[inline(always)]
pub fn object_velocity(
    m: &Model,
    d: &Data,
    objtype: i32,
    id: usize,
    local: bool,
) -> Result<Vec6, EngineError> {
    let (body, pos, com, rot) = motion_frame(m, d, objtype, id, local, "mj_objectVelocity")?;
    Ok(transform_spatial(
        &row(d.cvel, body),
        false,
        &pos,
        &com,
        rot.as_ref(),
    ))
}

/// 6D acceleration of an object, with the centripetal term of the linear part; needs `cacc`
/// from mj_rnePostConstraint (mj_objectAcceleration).
#[inline(always)]
pub fn object_acceleration(
    m: &Model,
    d: &Data,
    objtype: i32,
    id: usize,
    local: bool,
) -> Result<Vec6, EngineError> {
    let (body, pos, com, rot) = motion_frame(m, d, objtype, id, local, "mj_objectAcceleration")?;
    let vel = transform_spatial(&row(d.cvel, body), false, &pos, &com, rot.as_ref());
    let mut acc = transform_spatial(&row(d.cacc, body), false, &pos, &com, rot.as_ref());
    let c = cross(&v3(&vel[..3]), &v3(&vel[3..]));
    for k in 0..3 {
        acc[3 + k] += c[k];
    }
    Ok(acc)
}

/// Force:torque of contact `id` in the contact frame; zero for an invalid or excluded contact
/// (mj_contactForce).
pub fn contact_force(m: &Model, d: &Data, id: i32) -> Vec6 {
    let mut res = [0.0; 6];
    contact_force_to(m, d, id, &mut res);
    res
}

/// `contact_force` written into `res` (the C entry's result: no copy read back).
#[inline]
pub fn contact_force_to(m: &Model, d: &Data, id: i32, res: &mut [f64; 6]) {
    *res = [0.0; 6];
    if id < 0 || id >= d.raw.ncon {
        return;
    }
    let con = &d.contact[id as usize];
    if con.efc_address < 0 {
        return;
    }
    let adr = con.efc_address as usize;
    let dim = con.dim.max(0) as usize;
    if m.raw.opt.cone == mjtCone_::mjCONE_PYRAMIDAL as i32 {
        decode_pyramid(res, &d.efc_force[adr..], &con.friction, dim);
    } else {
        res[..dim].copy_from_slice(&d.efc_force[adr..adr + dim]);
    }
}
