//! Sensors: objects, dimensions and stages, then the sensor arrays.

use super::*;

#[allow(clippy::too_many_arguments)]
pub(super) fn compile_all(
    sensors: Vec<Sensor>,
    nuser: usize,
    bodies: &[FBody],
    joints: &[FJoint],
    geoms: &[FGeom],
    sites: &[FSite],
    cameras: &[(Camera, usize)],
    lights: &[(Light, usize)],
    tendons: &[CTendon],
    actuators: &[Actuator],
) -> Result<Vec<CSensor>, CError> {
    let mut csensors = Vec::new();
    for (id, s) in sensors.into_iter().enumerate() {
        let find = |objtype: i32, name: &str| -> Option<usize> {
            match objtype {
                1 | 2 => find_body(bodies, name),
                3 => joints.iter().position(|j| j.spec.name == name),
                5 => geoms.iter().position(|g| g.spec.name == name),
                6 => sites.iter().position(|x| x.spec.name == name),
                7 => cameras.iter().position(|c| c.0.name == name),
                17 => tendons.iter().position(|t| t.spec.name == name),
                8 => lights.iter().position(|l| l.0.name == name),
                18 => actuators.iter().position(|a| a.name == name),
                _ => None,
            }
        };
        let c = compile_sensor(s, id, nuser, &find, joints, tendons)?;
        csensors.push(c);
    }
    Ok(csensors)
}

/// A compiled sensor.
pub(super) struct CSensor {
    pub(super) spec: Sensor,
    pub(super) objid: i32,
    pub(super) refid: i32,
    pub(super) dim: i32,
    pub(super) datatype: i32,
    pub(super) needstage: i32,
}

fn compile_sensor(
    mut s: Sensor,
    id: usize,
    nuser: usize,
    find: &dyn Fn(i32, &str) -> Option<usize>,
    joints: &[FJoint],
    tendons: &[CTendon],
) -> Result<CSensor, CError> {
    let name = s.name.clone();
    let err = |m: &str| CError::at(format!("{m} in sensor '{name}' (id = {id})"), &name, id, -1);
    if s.user.len() > nuser {
        return Err(err("user has more values than nuser_sensor"));
    }
    s.user.resize(nuser, 0.0);
    if s.noise < 0.0 {
        return Err(err("negative noise"));
    }
    if s.cutoff < 0.0 {
        return Err(err("negative cutoff"));
    }
    let (mut objid, mut refid) = (-1, -1);
    if s.objtype != 0 {
        if s.objname.is_empty() {
            return Err(err("missing name of sensorized object"));
        }
        objid = find(s.objtype, &s.objname)
            .ok_or_else(|| err("unrecognized name of sensorized object"))? as i32;
    } else if s.kind != 35 {
        return Err(err("invalid type"));
    }
    let frame_obj = |t: i32| matches!(t, 1 | 2 | 5 | 6 | 7);
    if s.reftype != 0 {
        if s.refname.is_empty() {
            return Err(err("missing name of reference frame object"));
        }
        refid = find(s.reftype, &s.refname)
            .ok_or_else(|| err("unrecognized name of reference frame object"))?
            as i32;
        if !frame_obj(s.reftype) {
            return Err(CError::at(
                format!("reference frame object must be (x)body, geom, site or camera: sensor '{name}' (id = {id})"),
                &name,
                id,
                -1,
            ));
        }
    }
    let attached = |what: &str| {
        CError::at(
            format!("sensor must be attached to {what}: sensor '{name}' (id = {id})"),
            &name,
            id,
            -1,
        )
    };
    let joint = |k: i32| {
        joints
            .get(objid.max(0) as usize)
            .map(|j| (j.spec.kind, j.spec.limited))
            .filter(|_| k == 3)
    };
    // (dim, datatype, needstage); stages: 1 pos, 2 vel, 3 acc; datatypes: 0 real, 1 positive, 2 axis, 3 quat
    let stage3 = |k: i32, base: i32| [1, 2, 3][(k - base) as usize];
    let (dim, datatype, needstage) = match s.kind {
        0..=7 => {
            if s.objtype != 6 {
                return Err(attached("site"));
            }
            let (dim, dt) = if s.kind == 0 || s.kind == 7 {
                (1, 1)
            } else {
                (3, 0)
            };
            let stage = match s.kind {
                6 | 7 => 1,
                2 | 3 => 2,
                _ => 3,
            };
            (dim, dt, stage)
        }
        8 | 9 => {
            let Some((kind, _)) = joint(s.objtype) else {
                return Err(attached("joint"));
            };
            if !matches!(kind, JointType::Slide | JointType::Hinge) {
                return Err(err("joint must be slide or hinge"));
            }
            (1, 0, s.kind - 7)
        }
        10 | 11 => {
            if s.objtype != 17 {
                return Err(attached("tendon"));
            }
            (1, 0, s.kind - 9)
        }
        12..=14 => {
            if s.objtype != 18 {
                return Err(attached("actuator"));
            }
            (1, 0, stage3(s.kind, 12))
        }
        15 | 16 => {
            let Some((kind, _)) = joint(s.objtype) else {
                return Err(attached("joint"));
            };
            if kind != JointType::Ball {
                return Err(err("joint must be ball"));
            }
            if s.kind == 15 {
                (4, 3, 1)
            } else {
                (3, 0, 2)
            }
        }
        17..=19 => {
            let Some((_, limited)) = joint(s.objtype) else {
                return Err(attached("joint"));
            };
            if limited == 0 {
                return Err(err("joint must be limited"));
            }
            (1, 0, stage3(s.kind, 17))
        }
        20..=22 => {
            if s.objtype != 17 {
                return Err(attached("tendon"));
            }
            if tendons[objid as usize].spec.limited == 0 {
                return Err(err("tendon must be limited"));
            }
            (1, 0, stage3(s.kind, 20))
        }
        23..=31 => {
            if !frame_obj(s.objtype) {
                return Err(attached("(x)body, geom, site or camera"));
            }
            let dim = if s.kind == 24 { 4 } else { 3 };
            let dt = match s.kind {
                24 => 3,
                25..=27 => 2,
                _ => 0,
            };
            let stage = match s.kind {
                30 | 31 => 3,
                28 | 29 => 2,
                _ => 1,
            };
            (dim, dt, stage)
        }
        32..=34 => {
            if s.objtype != 1 {
                return Err(attached("body"));
            }
            (3, 0, if s.kind == 32 { 1 } else { 2 })
        }
        35 => (1, 0, 1),
        36 => {
            if s.dim < 0 {
                return Err(CError::at(
                    format!("sensor dim must be positive: sensor '{name}' (id = {id})"),
                    &name,
                    id,
                    -1,
                ));
            }
            if s.datatype == 2 && s.dim != 3 {
                return Err(err("datatype AXIS requires dim=3"));
            }
            if s.datatype == 3 && s.dim != 4 {
                return Err(err("datatype QUATERNION requires dim=4"));
            }
            (s.dim, s.datatype, s.needstage)
        }
        _ => return Err(err("invalid type")),
    };
    if s.cutoff > 0.0 && (datatype == 2 || datatype == 3) {
        return Err(err("cutoff applied to axis or quaternion datatype"));
    }
    Ok(CSensor {
        spec: s,
        objid,
        refid,
        dim,
        datatype,
        needstage,
    })
}

impl Compiled {
    pub(super) fn fill_sensors(&self, m: &mut ModelMut) {
        let mut adr = 0;
        for (i, s) in self.sensors.iter().enumerate() {
            m.sensor_type[i] = s.spec.kind;
            m.sensor_datatype[i] = s.datatype;
            m.sensor_needstage[i] = s.needstage;
            m.sensor_objtype[i] = s.spec.objtype;
            m.sensor_objid[i] = s.objid;
            m.sensor_reftype[i] = s.spec.reftype;
            m.sensor_refid[i] = s.refid;
            m.sensor_dim[i] = s.dim;
            m.sensor_cutoff[i] = s.spec.cutoff;
            m.sensor_noise[i] = s.spec.noise;
            put(m.sensor_user, i, &s.spec.user);
            m.sensor_adr[i] = adr;
            adr += s.dim;
        }
    }
}
