//! Sensors, evaluated in three stages (position, velocity, acceleration/force), each followed
//! by optional noise and the cutoff clamp. Subtree momenta and body accelerations are computed
//! only when a sensor of the stage needs them.

use super::linalg::{clip, min, mul_mat_t_vec, row};
use super::ray::{ray, ray_among, ray_geom, Targets};
use super::rne::rne_post_constraint;
use super::support::{contact_force, frame_arrays, object_acceleration, object_velocity};
use super::velocity::subtree_vel;
use super::{disabled, enabled, Data, EngineError, Model};
use crate::abi::*;
use crate::math::*;
use mjtSensor_::*;

const POS: i32 = mjtStage_::mjSTAGE_POS as i32;
const VEL: i32 = mjtStage_::mjSTAGE_VEL as i32;
const ACC: i32 = mjtStage_::mjSTAGE_ACC as i32;

fn is(ty: i32, s: mjtSensor_) -> bool {
    ty == s as i32
}

/// Object position and orientation of a frame sensor's object or reference.
#[inline]
fn frame<'d>(
    d: &'d Data,
    objtype: i32,
    id: i32,
    sensor: usize,
) -> Result<(&'d [f64], &'d [f64]), EngineError> {
    let id = id.max(0) as usize;
    match frame_arrays(d, objtype) {
        Some((pos, mat)) => Ok((&pos[3 * id..3 * id + 3], &mat[9 * id..9 * id + 9])),
        None => Err(invalid_object(sensor)),
    }
}

#[cold]
#[inline(never)]
fn invalid_object(sensor: usize) -> EngineError {
    EngineError(format!("Invalid object type in sensor {sensor}"))
}

/// Global orientation of an object as a quaternion.
fn frame_quat(
    m: &Model,
    d: &Data,
    objtype: i32,
    id: i32,
    sensor: usize,
) -> Result<Quat, EngineError> {
    use mjtObj_::*;
    let id = id.max(0) as usize;
    let t = |o: mjtObj_| objtype == o as i32;
    let (body, local) = if t(mjOBJ_XBODY) {
        return Ok(row(d.xquat, id));
    } else if t(mjOBJ_BODY) {
        (id, row(m.body_iquat(), id))
    } else if t(mjOBJ_GEOM) {
        (m.geom_bodyid()[id] as usize, row(m.geom_quat(), id))
    } else if t(mjOBJ_SITE) {
        (m.site_bodyid()[id] as usize, row(m.site_quat(), id))
    } else if t(mjOBJ_CAMERA) {
        (m.cam_bodyid()[id] as usize, row(m.cam_quat(), id))
    } else {
        return Err(EngineError(format!(
            "Invalid object type in sensor {sensor}"
        )));
    };
    Ok(mul_quat(&row(d.xquat, body), &local))
}

/// Value of the first efc row of a joint or tendon limit on object `id`, or 0.
fn limit_value(d: &Data, kind: mjtConstraint_, id: i32, values: &[f64], margin: bool) -> f64 {
    let start = (d.raw.ne + d.raw.nf).max(0) as usize;
    for j in start..d.raw.nefc.max(0) as usize {
        if d.efc_type[j] == kind as i32 && d.efc_id[j] == id {
            return if margin {
                values[j] - d.efc_margin[j]
            } else {
                values[j]
            };
        }
    }
    0.0
}

fn put_vec(d: &mut Data, adr: usize, v: &[f64]) {
    d.sensordata[adr..adr + v.len()].copy_from_slice(v);
}

/// Sensors disabled, or none in the model: each stage returns at once.
#[inline]
fn no_sensors(m: &Model) -> bool {
    disabled(m, mjtDisableBit_::mjDSBL_SENSOR) || m.raw.nsensor <= 0
}

/// Position-dependent sensors (mj_sensorPos).
#[inline]
pub fn sensor_pos(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if no_sensors(m) {
        return Ok(());
    }
    sensors_pos(m, d)
}

#[inline(never)]
fn sensors_pos(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    // the geoms rangefinders see, taken at the first one (None: too many geoms, or none yet)
    let mut targets: Option<Option<Targets>> = None;
    let s = Sensors::of(m);
    let mut after = StageEnd::default();
    for i in 0..s.stage.len() {
        if s.stage[i] != POS {
            continue;
        }
        let ty = s.ty[i];
        after.note(&s, i, ty);
        let (objtype, objid) = (s.objtype[i], s.objid[i]);
        let (reftype, refid) = (s.reftype[i], s.refid[i]);
        let adr = s.adr[i] as usize;
        let id = objid.max(0) as usize;
        if is(ty, mjSENS_MAGNETOMETER) {
            let mat = row::<9>(d.site_xmat, id);
            mul_mat_t_vec(&mut d.sensordata[adr..], &mat, &m.raw.opt.magnetic, 3, 3);
        } else if is(ty, mjSENS_RANGEFINDER) {
            // distance along the site's z axis to the nearest geom, its own body excluded
            let mat = row::<9>(d.site_xmat, id);
            let dir = [mat[2], mat[5], mat[8]];
            let (pnt, body) = (row(d.site_xpos, id), m.site_bodyid()[id]);
            let (dist, _) = match targets.get_or_insert_with(|| Targets::new(m, None, true)) {
                Some(t) => ray_among(m, d, t, &pnt, &dir, body)?,
                None => ray(m, d, &pnt, &dir, None, true, body)?,
            };
            d.sensordata[adr] = dist;
        } else if is(ty, mjSENS_JOINTPOS) {
            d.sensordata[adr] = d.qpos[m.jnt_qposadr()[id] as usize];
        } else if is(ty, mjSENS_TENDONPOS) {
            d.sensordata[adr] = d.ten_length[id];
        } else if is(ty, mjSENS_ACTUATORPOS) {
            d.sensordata[adr] = d.actuator_length[id];
        } else if is(ty, mjSENS_BALLQUAT) {
            let a = m.jnt_qposadr()[id] as usize;
            let q = row::<4>(&d.qpos[a..], 0);
            put_vec(d, adr, &q);
        } else if is(ty, mjSENS_JOINTLIMITPOS) || is(ty, mjSENS_TENDONLIMITPOS) {
            let kind = if is(ty, mjSENS_JOINTLIMITPOS) {
                mjtConstraint_::mjCNSTR_LIMIT_JOINT
            } else {
                mjtConstraint_::mjCNSTR_LIMIT_TENDON
            };
            d.sensordata[adr] = limit_value(d, kind, objid, d.efc_pos, true);
        } else if is(ty, mjSENS_FRAMEPOS)
            || is(ty, mjSENS_FRAMEXAXIS)
            || is(ty, mjSENS_FRAMEYAXIS)
            || is(ty, mjSENS_FRAMEZAXIS)
        {
            // read in place: copying each frame out whole cost more than the sensor
            let (pos, mat) = frame(d, objtype, objid, i)?;
            let v = if is(ty, mjSENS_FRAMEPOS) {
                [pos[0], pos[1], pos[2]]
            } else {
                let k = (ty - mjSENS_FRAMEXAXIS as i32) as usize;
                [mat[k], mat[k + 3], mat[k + 6]]
            };
            let v = if refid == -1 {
                v
            } else {
                let (rpos, rmat) = frame(d, reftype, refid, i)?;
                let v = if is(ty, mjSENS_FRAMEPOS) {
                    sub3(&v, &row(rpos, 0))
                } else {
                    v
                };
                mul_mat_t_vec3(&row(rmat, 0), &v)
            };
            put_vec(d, adr, &v);
        } else if is(ty, mjSENS_FRAMEQUAT) {
            let q = frame_quat(m, d, objtype, objid, i)?;
            let q = if refid == -1 {
                q
            } else {
                let r = frame_quat(m, d, reftype, refid, i)?;
                mul_quat(&neg_quat(&r), &q)
            };
            put_vec(d, adr, &q);
        } else if is(ty, mjSENS_SUBTREECOM) {
            let c = row::<3>(d.subtree_com, id);
            put_vec(d, adr, &c);
        } else if is(ty, mjSENS_CLOCK) {
            d.sensordata[adr] = d.raw.time;
        } else if !is(ty, mjSENS_USER) {
            return Err(EngineError(format!(
                "Invalid sensor type in POS stage, sensor {i}"
            )));
        }
    }
    finish_stage(m, d, POS, after)
}

/// Velocity-dependent sensors (mj_sensorVel).
#[inline]
pub fn sensor_vel(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if no_sensors(m) {
        return Ok(());
    }
    sensors_vel(m, d)
}

#[inline(never)]
fn sensors_vel(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let mut have_subtree = false;
    let s = Sensors::of(m);
    let mut after = StageEnd::default();
    for i in 0..s.stage.len() {
        if s.stage[i] != VEL {
            continue;
        }
        let ty = s.ty[i];
        after.note(&s, i, ty);
        let (objtype, objid) = (s.objtype[i], s.objid[i]);
        let (reftype, refid) = (s.reftype[i], s.refid[i]);
        let adr = s.adr[i] as usize;
        let id = objid.max(0) as usize;
        let site = mjtObj_::mjOBJ_SITE as i32;
        if !have_subtree
            && (is(ty, mjSENS_SUBTREELINVEL) || is(ty, mjSENS_SUBTREEANGMOM) || is(ty, mjSENS_USER))
        {
            subtree_vel(m, d)?;
            have_subtree = true;
        }
        if is(ty, mjSENS_VELOCIMETER) || is(ty, mjSENS_GYRO) {
            let v = object_velocity(m, d, site, id, true)?;
            let part = if is(ty, mjSENS_GYRO) {
                &v[..3]
            } else {
                &v[3..]
            };
            put_vec(d, adr, part);
        } else if is(ty, mjSENS_JOINTVEL) {
            d.sensordata[adr] = d.qvel[m.jnt_dofadr()[id] as usize];
        } else if is(ty, mjSENS_TENDONVEL) {
            d.sensordata[adr] = d.ten_velocity[id];
        } else if is(ty, mjSENS_ACTUATORVEL) {
            d.sensordata[adr] = d.actuator_velocity[id];
        } else if is(ty, mjSENS_BALLANGVEL) {
            let a = m.jnt_dofadr()[id] as usize;
            let w = row::<3>(&d.qvel[a..], 0);
            put_vec(d, adr, &w);
        } else if is(ty, mjSENS_JOINTLIMITVEL) || is(ty, mjSENS_TENDONLIMITVEL) {
            let kind = if is(ty, mjSENS_JOINTLIMITVEL) {
                mjtConstraint_::mjCNSTR_LIMIT_JOINT
            } else {
                mjtConstraint_::mjCNSTR_LIMIT_TENDON
            };
            d.sensordata[adr] = limit_value(d, kind, objid, d.efc_vel, false);
        } else if is(ty, mjSENS_FRAMELINVEL) || is(ty, mjSENS_FRAMEANGVEL) {
            let mut v = object_velocity(m, d, objtype, id, false)?;
            if refid > -1 {
                let pos: Vec3 = row(frame(d, objtype, objid, i)?.0, 0);
                let (rpos, rmat) = frame(d, reftype, refid, i)?;
                let (rpos, rmat): (Vec3, Mat3) = (row(rpos, 0), row(rmat, 0));
                let vref = object_velocity(m, d, reftype, refid as usize, false)?;
                let mut rel = [0.0; 6];
                for k in 0..6 {
                    rel[k] = v[k] - vref[k];
                }
                // rotating reference frame: add the transport term to the linear part
                let c = cross(&sub3(&pos, &rpos), &v3(&vref[..3]));
                for k in 0..3 {
                    rel[3 + k] += c[k];
                }
                v[..3].copy_from_slice(&mul_mat_t_vec3(&rmat, &v3(&rel[..3])));
                v[3..].copy_from_slice(&mul_mat_t_vec3(&rmat, &v3(&rel[3..])));
            }
            let part = if is(ty, mjSENS_FRAMELINVEL) {
                &v[3..]
            } else {
                &v[..3]
            };
            put_vec(d, adr, part);
        } else if is(ty, mjSENS_SUBTREELINVEL) {
            let v = row::<3>(d.subtree_linvel, id);
            put_vec(d, adr, &v);
        } else if is(ty, mjSENS_SUBTREEANGMOM) {
            let v = row::<3>(d.subtree_angmom, id);
            put_vec(d, adr, &v);
        } else if !is(ty, mjSENS_USER) {
            return Err(EngineError(format!(
                "Invalid type in VEL stage, sensor {i}"
            )));
        }
    }
    finish_stage(m, d, VEL, after)
}

/// Sum of the normal forces of the contacts of the site's body whose normal ray, cast from the
/// contact point, hits the site's zone (mjSENS_TOUCH).
fn touch(m: &Model, d: &Data, site: usize) -> Result<f64, EngineError> {
    let body = m.site_bodyid()[site];
    let mut total = 0.0;
    for j in 0..d.raw.ncon.max(0) as usize {
        let con = &d.contact[j];
        let b1 = m.geom_bodyid()[con.geom1 as usize];
        let b2 = m.geom_bodyid()[con.geom2 as usize];
        if con.efc_address < 0 || (body != b1 && body != b2) {
            continue;
        }
        let normal = contact_force(m, d, j as i32)[0];
        if normal <= 0.0 {
            continue;
        }
        let (mut ray, _) = normalize3(&scl3(&v3(&con.frame[..3]), normal));
        if body == b2 {
            ray = scl3(&ray, crate::math::misc::minus_one());
        }
        let hit = ray_geom(
            &row(d.site_xpos, site),
            &row(d.site_xmat, site),
            &m.site_size()[3 * site..3 * site + 3],
            &con.pos,
            &ray,
            m.site_type()[site],
        )?;
        if hit >= 0.0 {
            total += normal;
        }
    }
    Ok(total)
}

/// Acceleration- and force-dependent sensors (mj_sensorAcc).
#[inline]
pub fn sensor_acc(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if no_sensors(m) {
        return Ok(());
    }
    sensors_acc(m, d)
}

#[inline(never)]
fn sensors_acc(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let mut have_rne = false;
    let s = Sensors::of(m);
    let mut after = StageEnd::default();
    for i in 0..s.stage.len() {
        if s.stage[i] != ACC {
            continue;
        }
        let ty = s.ty[i];
        after.note(&s, i, ty);
        let (objtype, objid) = (s.objtype[i], s.objid[i]);
        let adr = s.adr[i] as usize;
        let id = objid.max(0) as usize;
        if !have_rne
            && !is(ty, mjSENS_TOUCH)
            && !is(ty, mjSENS_ACTUATORFRC)
            && !is(ty, mjSENS_JOINTLIMITFRC)
            && !is(ty, mjSENS_TENDONLIMITFRC)
        {
            rne_post_constraint(m, d)?;
            have_rne = true;
        }
        if is(ty, mjSENS_TOUCH) {
            d.sensordata[adr] = touch(m, d, id)?;
        } else if is(ty, mjSENS_ACCELEROMETER) {
            let a = object_acceleration(m, d, mjtObj_::mjOBJ_SITE as i32, id, true)?;
            put_vec(d, adr, &a[3..]);
        } else if is(ty, mjSENS_FORCE) || is(ty, mjSENS_TORQUE) {
            // interaction force between the site's body and its parent, in the site frame
            let body = m.site_bodyid()[id] as usize;
            let root = m.body_rootid()[body] as usize;
            let mat = row::<9>(d.site_xmat, id);
            let f = transform_spatial(
                &row(d.cfrc_int, body),
                true,
                &row(d.site_xpos, id),
                &row(d.subtree_com, root),
                Some(&mat),
            );
            let part = if is(ty, mjSENS_FORCE) {
                &f[3..]
            } else {
                &f[..3]
            };
            put_vec(d, adr, part);
        } else if is(ty, mjSENS_ACTUATORFRC) {
            d.sensordata[adr] = d.actuator_force[id];
        } else if is(ty, mjSENS_JOINTLIMITFRC) || is(ty, mjSENS_TENDONLIMITFRC) {
            let kind = if is(ty, mjSENS_JOINTLIMITFRC) {
                mjtConstraint_::mjCNSTR_LIMIT_JOINT
            } else {
                mjtConstraint_::mjCNSTR_LIMIT_TENDON
            };
            d.sensordata[adr] = limit_value(d, kind, objid, d.efc_force, false);
        } else if is(ty, mjSENS_FRAMELINACC) || is(ty, mjSENS_FRAMEANGACC) {
            let a = object_acceleration(m, d, objtype, id, false)?;
            let part = if is(ty, mjSENS_FRAMELINACC) {
                &a[3..]
            } else {
                &a[..3]
            };
            put_vec(d, adr, part);
        } else if !is(ty, mjSENS_USER) {
            return Err(EngineError(format!(
                "Invalid type in ACC stage, sensor {i}"
            )));
        }
    }
    finish_stage(m, d, ACC, after)
}

/// The sensor arrays the stages read, as slices taken once.
struct Sensors<'m> {
    stage: &'m [i32],
    ty: &'m [i32],
    objtype: &'m [i32],
    objid: &'m [i32],
    reftype: &'m [i32],
    refid: &'m [i32],
    adr: &'m [i32],
    cutoff: &'m [f64],
}

impl<'m> Sensors<'m> {
    fn of(m: &'m Model) -> Self {
        let n = m.raw.nsensor.max(0) as usize;
        Sensors {
            stage: &m.sensor_needstage()[..n],
            ty: &m.sensor_type()[..n],
            objtype: &m.sensor_objtype()[..n],
            objid: &m.sensor_objid()[..n],
            reftype: &m.sensor_reftype()[..n],
            refid: &m.sensor_refid()[..n],
            adr: &m.sensor_adr()[..n],
            cutoff: &m.sensor_cutoff()[..n],
        }
    }
}

/// What a stage's sensors need after they are computed, noted as the stage visits them.
#[derive(Default, Clone, Copy)]
struct StageEnd {
    user: bool,
    cutoff: bool,
}

impl StageEnd {
    #[inline(always)]
    fn note(&mut self, s: &Sensors, i: usize, ty: i32) {
        self.user |= ty == mjSENS_USER as i32;
        self.cutoff |= s.cutoff[i] > 0.0;
    }
}

/// User sensors of `stage` (mjcb_sensor), then noise (when enabled) and cutoff.
fn finish_stage(m: &Model, d: &mut Data, stage: i32, after: StageEnd) -> Result<(), EngineError> {
    if after.user {
        let top = d.arena.used();
        super::hooks::sensor(m, d, top, stage);
    }
    if enabled(m, mjtEnableBit_::mjENBL_SENSORNOISE) {
        add_noise(m, d, stage)?;
    }
    if after.cutoff {
        apply_cutoff(m, d, stage);
    }
    Ok(())
}

/// mjMAX as the C macro evaluates it.
fn c_max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// Gaussian noise of standard deviation sensor_noise: added to real and positive values,
/// a random rotation of that angle for axes and quaternions. Draws from C's rand().
fn add_noise(m: &Model, d: &mut Data, stage: i32) -> Result<(), EngineError> {
    use mjtDataType_::*;
    let normal = crate::runtime::random::standard_normal;
    for i in 0..m.raw.nsensor as usize {
        let noise = m.sensor_noise()[i];
        if m.sensor_needstage()[i] != stage || noise.is_nan() || noise <= 0.0 {
            continue;
        }
        let adr = m.sensor_adr()[i] as usize;
        let dim = m.sensor_dim()[i] as usize;
        let ty = m.sensor_datatype()[i];
        if ty == mjDATATYPE_REAL as i32 || ty == mjDATATYPE_POSITIVE as i32 {
            for x in &mut d.sensordata[adr..adr + dim] {
                let (r, _) = normal();
                if ty == mjDATATYPE_POSITIVE as i32 {
                    if *x > 0.0 {
                        *x = c_max(0.0, *x + r * noise);
                    }
                } else {
                    *x += r * noise;
                }
            }
        } else {
            let (r0, r1) = normal();
            let (r2, r3) = normal();
            let (axis, _) = normalize3(&[r1, r2, r3]);
            let q = axis_angle2quat(&axis, r0 * noise);
            if ty == mjDATATYPE_AXIS as i32 {
                let v = rot_vec_quat(&v3(&d.sensordata[adr..]), &q);
                put_vec(d, adr, &v);
            } else if ty == mjDATATYPE_QUATERNION as i32 {
                let v = mul_quat(&q4(&d.sensordata[adr..]), &q);
                put_vec(d, adr, &v);
            } else {
                return Err(EngineError(format!("Unknown datatype in sensor {i}")));
            }
        }
    }
    Ok(())
}

/// Clamps real sensors to [-cutoff, cutoff] and positive ones to cutoff (sensor_cutoff > 0).
fn apply_cutoff(m: &Model, d: &mut Data, stage: i32) {
    use mjtDataType_::*;
    for i in 0..m.raw.nsensor as usize {
        let cutoff = m.sensor_cutoff()[i];
        if m.sensor_needstage()[i] != stage || cutoff.is_nan() || cutoff <= 0.0 {
            continue;
        }
        let adr = m.sensor_adr()[i] as usize;
        let dim = m.sensor_dim()[i] as usize;
        let ty = m.sensor_datatype()[i];
        for x in &mut d.sensordata[adr..adr + dim] {
            if ty == mjDATATYPE_REAL as i32 {
                *x = clip(*x, -cutoff, cutoff);
            } else if ty == mjDATATYPE_POSITIVE as i32 {
                *x = min(cutoff, *x);
            }
        }
    }
}
