//! Cameras and lights: their frames and targets, then their arrays.

use super::*;

pub(super) fn compile_camera(
    c: &mut Camera,
    id: usize,
    body: usize,
    bodies: &[FBody],
    nuser: usize,
    s: &Settings,
) -> Result<(), CError> {
    let name = c.name.clone();
    let err = |m: String| CError::at(m, &name, id, c.line);
    if c.user.len() > nuser {
        return Err(err(format!(
            "user has more values than nuser_cam in camera '{name}' (id = {id})"
        )));
    }
    let alt = c.alt;
    alt_set(&alt, &mut c.quat, None, s).map_err(|e| {
        err(format!(
            "alternative specification error '{e}' in site {id}"
        ))
    })?;
    normalize(&mut c.quat);
    c.user.resize(nuser, 0.0);
    target_id(&c.target, "camera", &name, id, c.line, body, bodies).map(|_| ())
}

/// Body id named by a camera/light `target` (-1 when none).
fn target_id(
    target: &str,
    what: &str,
    name: &str,
    id: usize,
    line: i32,
    body: usize,
    bodies: &[FBody],
) -> Result<i32, CError> {
    let mut tid = -1;
    if !target.is_empty() {
        match find_body(bodies, target) {
            Some(b) => tid = b as i32,
            None => {
                return Err(CError::at(
                    format!("unknown target body in {what} '{name}' (id = {id})"),
                    name,
                    id,
                    line,
                ))
            }
        }
    }
    if tid == body as i32 {
        return Err(CError::at(
            format!("parent-targeting in {what} '{name}' (id = {id})"),
            name,
            id,
            line,
        ));
    }
    Ok(tid)
}

pub(super) fn compile_light(
    l: &mut Light,
    id: usize,
    body: usize,
    bodies: &[FBody],
) -> Result<(), CError> {
    let nrm2: f64 = l.dir.iter().map(|x| x * x).sum();
    if normalize(&mut l.dir) < MINVAL || nrm2 < EPS {
        return Err(CError::at(
            format!("zero direction in light '{}' (id = {id})", l.name),
            &l.name,
            id,
            l.line,
        ));
    }
    target_id(&l.target, "light", &l.name, id, l.line, body, bodies).map(|_| ())
}

impl Compiled {
    pub(super) fn fill_cameras_lights(&self, m: &mut ModelMut) {
        let target = |t: &str| {
            if t.is_empty() {
                -1
            } else {
                find_body(&self.bodies, t).map_or(-1, |b| b as i32)
            }
        };
        for (i, (c, b)) in self.cameras.iter().enumerate() {
            m.cam_bodyid[i] = *b as i32;
            m.cam_mode[i] = c.mode;
            m.cam_targetbodyid[i] = target(&c.target);
            put(m.cam_pos, i, &c.pos);
            put(m.cam_quat, i, &c.quat);
            m.cam_fovy[i] = c.fovy;
            m.cam_ipd[i] = c.ipd;
            put(m.cam_user, i, &c.user);
        }
        for (i, (l, b)) in self.lights.iter().enumerate() {
            m.light_bodyid[i] = *b as i32;
            m.light_mode[i] = l.mode;
            m.light_targetbodyid[i] = target(&l.target);
            m.light_directional[i] = l.directional as u8;
            m.light_castshadow[i] = l.castshadow as u8;
            m.light_active[i] = l.active as u8;
            put(m.light_pos, i, &l.pos);
            put(m.light_dir, i, &l.dir);
            put(m.light_attenuation, i, &l.attenuation);
            m.light_cutoff[i] = l.cutoff;
            m.light_exponent[i] = l.exponent;
            put(m.light_ambient, i, &l.ambient);
            put(m.light_diffuse, i, &l.diffuse);
            put(m.light_specular, i, &l.specular);
        }
    }
}
