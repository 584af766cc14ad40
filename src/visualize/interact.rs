//! Interaction: room and model space, the viewer's camera, mouse motion applied to cameras,
//! perturbations and the model's room transform, perturbation forces and poses, and
//! selection by a ray through the image.

use crate::abi::*;
use crate::engine::linalg::row;
use crate::engine::ray::ray;
use crate::engine::ray_mesh::ray_skin;
use crate::engine::support::object_velocity;
use crate::engine::{Data, EngineError, Model, JNT_FREE, MINVAL};
use crate::math::blas::normalize;
use crate::math::quat::*;
use crate::math::vec3::*;
use crate::math::{Quat, Vec3};
use crate::visualize::geom::{c_max, n2f};
use std::f64::consts::PI;

fn err(msg: &str) -> EngineError {
    EngineError(msg.into())
}

fn f2n<const N: usize>(v: &[f32; N]) -> [f64; N] {
    v.map(|x| x as f64)
}

/// Pose in room space to model space (mjv_room2model).
pub fn room2model(pos: &Vec3, quat: &Quat, scn: &mjvScene) -> Result<(Vec3, Quat), EngineError> {
    if (scn.scale as f64) < MINVAL {
        return Err(err("mjvScene scale too small in mjv_room2model"));
    }
    if scn.enabletransform == 0 {
        return Ok((*pos, *quat));
    }
    let (invpos, invquat) = neg_pose(&f2n(&scn.translate), &f2n(&scn.rotate));
    let (p, q) = mul_pose(&invpos, &invquat, pos, quat);
    Ok((scl3(&p, 1.0 / scn.scale as f64), q))
}

/// Pose in model space to room space (mjv_model2room).
pub fn model2room(pos: &Vec3, quat: &Quat, scn: &mjvScene) -> Result<(Vec3, Quat), EngineError> {
    if (scn.scale as f64) < MINVAL {
        return Err(err("mjvScene scale too small in mjv_model2room"));
    }
    if scn.enabletransform == 0 {
        return Ok((*pos, *quat));
    }
    let (p, q) = mul_pose(&f2n(&scn.translate), &f2n(&scn.rotate), pos, quat);
    Ok((scl3(&p, scn.scale as f64), q))
}

fn check_near(scn: &mjvScene, name: &str) -> Result<(), EngineError> {
    if scn.camera.iter().any(|c| (c.frustum_near as f64) < MINVAL) {
        return Err(err(&format!("mjvScene frustum_near too small in {name}")));
    }
    Ok(())
}

/// The viewer's head position, forward and up directions in model space: the average of the
/// two GL cameras (mjv_cameraInModel).
pub fn camera_in_model(scn: &mjvScene) -> Result<(Vec3, Vec3, Vec3), EngineError> {
    check_near(scn, "mjv_cameraInModel")?;
    let (mut head, mut forward, mut up) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    for cam in &scn.camera {
        let pos = f2n(&cam.pos);
        let fwd = normalize3(&f2n(&cam.forward)).0;
        let u = normalize3(&f2n(&cam.up)).0;
        let left = normalize3(&cross(&u, &fwd)).0;
        let mat = [
            left[0], u[0], fwd[0], left[1], u[1], fwd[1], left[2], u[2], fwd[2],
        ];
        let (modelpos, modelquat) = room2model(&pos, &mat2quat(&mat), scn)?;
        let modelmat = quat2mat(&modelquat);
        add_to_scl3(&mut head, &modelpos, 0.5);
        for i in 0..3 {
            forward[i] += 0.5 * modelmat[3 * i + 2];
            up[i] += 0.5 * modelmat[3 * i + 1];
        }
    }
    Ok((head, normalize3(&forward).0, normalize3(&up).0))
}

/// As `camera_in_model`, in room space (mjv_cameraInRoom).
pub fn camera_in_room(scn: &mjvScene) -> Result<(Vec3, Vec3, Vec3), EngineError> {
    check_near(scn, "mjv_cameraInRoom")?;
    let (mut head, mut forward, mut up) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    for cam in &scn.camera {
        add_to_scl3(&mut head, &f2n(&cam.pos), 0.5);
        add_to_scl3(&mut forward, &f2n(&cam.forward), 0.5);
        add_to_scl3(&mut up, &f2n(&cam.up), 0.5);
    }
    Ok((head, normalize3(&forward).0, normalize3(&up).0))
}

/// Frustum height at unit distance, averaged over the two cameras (mjv_frustumHeight).
pub fn frustum_height(scn: &mjvScene) -> Result<f64, EngineError> {
    check_near(scn, "mjv_frustumHeight")?;
    let [a, b] = &scn.camera;
    let height = (a.frustum_top - a.frustum_bottom) / a.frustum_near
        + (b.frustum_top - b.frustum_bottom) / b.frustum_near;
    Ok(0.5 * height as f64)
}

/// `vec` turned in the horizontal plane by the angle from (0,1) to forward's (x,y)
/// (mjv_alignToCamera).
pub fn align_to_camera(vec: &Vec3, forward: &Vec3) -> Vec3 {
    let mut y = [forward[0], forward[1]];
    normalize(&mut y);
    let x = [y[1], -y[0]];
    [
        vec[0] * x[0] + vec[1] * y[0],
        vec[0] * x[1] + vec[1] * y[1],
        vec[2],
    ]
}

/// Mouse motion (dx, dy) of `action` as a world vector aligned with the camera.
fn convert_2d(action: i32, dx: f64, dy: f64, forward: &Vec3) -> Result<Vec3, EngineError> {
    use mjtMouse_::*;
    let vec = match action {
        a if a == mjMOUSE_ROTATE_V as i32 => [dy, 0.0, dx],
        a if a == mjMOUSE_ROTATE_H as i32 => [dy, dx, 0.0],
        a if a == mjMOUSE_MOVE_V as i32 => [dx, 0.0, -dy],
        a if a == mjMOUSE_MOVE_H as i32 => [dx, -dy, 0.0],
        a if a == mjMOUSE_ZOOM as i32 => [0.0; 3],
        _ => {
            return Err(err(&format!(
                "Unexpected mouse action {action} in convert2D"
            )));
        }
    };
    Ok(align_to_camera(&vec, forward))
}

fn is(action: i32, a: mjtMouse_) -> bool {
    action == a as i32
}

/// Rotates, moves or zooms a free or tracking camera (mjv_moveCamera).
pub fn move_camera(
    m: &Model,
    action: i32,
    dx: f64,
    dy: f64,
    scn: &mjvScene,
    cam: &mut mjvCamera,
) -> Result<(), EngineError> {
    use mjtMouse_::*;
    if cam.r#type == mjtCamera_::mjCAMERA_FIXED as i32 {
        return Ok(());
    }
    let extent = m.raw.stat.extent;
    if is(action, mjMOUSE_ROTATE_V) || is(action, mjMOUSE_ROTATE_H) {
        cam.azimuth -= dx * 180.0;
        cam.elevation -= dy * 180.0;
    } else if is(action, mjMOUSE_MOVE_V) || is(action, mjMOUSE_MOVE_H) {
        if cam.r#type == mjtCamera_::mjCAMERA_TRACKING as i32 {
            return Ok(());
        }
        let (head, forward, _) = camera_in_model(scn)?;
        let vec = convert_2d(action, dx, dy, &forward)?;
        // the look-at point follows the mouse on screen
        let scl = frustum_height(scn)? * dot3(&sub3(&cam.lookat, &head), &forward);
        add_to_scl3(&mut cam.lookat, &vec, -scl);
    } else if is(action, mjMOUSE_ZOOM) {
        cam.distance -= (1.0 + cam.distance / extent / 3.0).ln() * dy * 9.0 * extent;
    } else {
        return Err(err(&format!(
            "Unexpected action {action} in mjv_moveCamera"
        )));
    }
    if cam.azimuth > 180.0 {
        cam.azimuth -= 360.0;
    }
    if cam.azimuth < -180.0 {
        cam.azimuth += 360.0;
    }
    cam.elevation = cam.elevation.clamp(-89.0, 89.0);
    if cam.distance < 0.01 * extent {
        cam.distance = 0.01 * extent;
    }
    if cam.distance > 100.0 * extent {
        cam.distance = 100.0 * extent;
    }
    Ok(())
}

/// Inertial frame orientation of body `b`.
fn xiquat(m: &Model, d: &Data, b: usize) -> Quat {
    mul_quat(&row(d.xquat, b), &row(m.body_iquat(), b))
}

/// Moves or turns the perturbation's reference (mjv_movePerturb); turns stay within 90
/// degrees of the selected body.
pub fn move_perturb(
    m: &Model,
    d: &Data,
    action: i32,
    dx: f64,
    dy: f64,
    scn: &mjvScene,
    pert: &mut mjvPerturb,
) -> Result<(), EngineError> {
    use mjtMouse_::*;
    let (_, forward, _) = camera_in_model(scn)?;
    let vec = convert_2d(action, dx, dy, &forward)?;
    if is(action, mjMOUSE_MOVE_V) || is(action, mjMOUSE_MOVE_H) {
        add_to_scl3(&mut pert.refpos, &vec, pert.scale);
    } else if is(action, mjMOUSE_ROTATE_V) || is(action, mjMOUSE_ROTATE_H) {
        let (axis, angle) = normalize3(&vec);
        let q = mul_quat(&axis_angle2quat(&axis, angle * PI * 2.0), &pert.refquat);
        pert.refquat = normalize4(&q).0;
        let sel = pert.select;
        if sel > 0 && sel < m.raw.nbody {
            let body = xiquat(m, d, sel as usize);
            let rel = mul_quat(&neg_quat(&body), &pert.refquat);
            let (axis, angle) = normalize3(&quat2vel(&rel, 1.0));
            // not a range test: a NaN angle is left alone, as in 2.2.2
            #[allow(clippy::manual_range_contains)]
            let outside = angle < -PI * 0.5 || angle > PI * 0.5;
            if outside {
                let angle = c_max(-PI * 0.5, if PI * 0.5 < angle { PI * 0.5 } else { angle });
                pert.refquat = mul_quat(&body, &axis_angle2quat(&axis, angle));
            }
        }
    }
    Ok(())
}

/// Rotates, moves or scales the model in the room (mjv_moveModel), when transforming.
pub fn move_model(
    m: &Model,
    action: i32,
    dx: f64,
    dy: f64,
    roomup: &Vec3,
    scn: &mut mjvScene,
) -> Result<(), EngineError> {
    use mjtMouse_::*;
    if scn.enabletransform == 0 {
        return Ok(());
    }
    let (_, camforward, _) = camera_in_room(scn)?;
    let roomforward = normalize3(&add_scl3(&camforward, roomup, -dot3(&camforward, roomup))).0;
    let roomright = normalize3(&cross(&roomforward, roomup)).0;
    let extent = m.raw.stat.extent;
    if is(action, mjMOUSE_ROTATE_V) || is(action, mjMOUSE_ROTATE_H) {
        let first = if is(action, mjMOUSE_ROTATE_V) {
            roomup
        } else {
            &roomforward
        };
        let vec: Vec3 = std::array::from_fn(|i| first[i] * dx + roomright[i] * dy);
        let (axis, angle) = normalize3(&vec);
        let q = mul_quat(&axis_angle2quat(&axis, angle * PI), &f2n(&scn.rotate));
        scn.rotate = n2f(&normalize4(&q).0);
    } else if is(action, mjMOUSE_MOVE_V) || is(action, mjMOUSE_MOVE_H) {
        let second = if is(action, mjMOUSE_MOVE_V) {
            roomup
        } else {
            &roomforward
        };
        for i in 0..3 {
            let step = (roomright[i] * dx - second[i] * dy) as f32 as f64 * extent;
            scn.translate[i] = (scn.translate[i] as f64 + step) as f32;
        }
    } else if is(action, mjMOUSE_ZOOM) {
        let step = ((1.0 + scn.scale / 3.0) as f64).ln() * dy * 3.0;
        scn.scale += step as f32;
        scn.scale = scn.scale.clamp(0.01, 100.0);
    } else {
        return Err(err(&format!("Unexpected action {action} in mjv_moveModel")));
    }
    Ok(())
}

/// Reference pose from the selected body, and the mouse-to-space scale (mjv_initPerturb).
pub fn init_perturb(
    m: &Model,
    d: &Data,
    scn: &mjvScene,
    pert: &mut mjvPerturb,
) -> Result<(), EngineError> {
    let sel = pert.select;
    if sel <= 0 || sel >= m.raw.nbody {
        return Ok(());
    }
    pert.refpos = row(d.xipos, sel as usize);
    pert.refquat = xiquat(m, d, sel as usize);
    let (head, forward, _) = camera_in_model(scn)?;
    pert.scale = frustum_height(scn)? * dot3(&sub3(&pert.refpos, &head), &forward);
    Ok(())
}

/// Moves the selected body to the reference pose (mjv_applyPerturbPose): a mocap body
/// always; when paused, a free body or the free root of the selected body through qpos.
pub fn apply_perturb_pose(m: &Model, d: &mut Data, pert: &mjvPerturb, paused: bool) {
    let sel = pert.select;
    if sel <= 0 || sel >= m.raw.nbody || (pert.active | pert.active2) == 0 {
        return;
    }
    let sel = sel as usize;
    let root = m.body_rootid()[sel] as usize;
    let (pos1, quat1) = neg_pose(&row(m.body_ipos(), sel), &row(m.body_iquat(), sel));
    let (refpos, refquat) = mul_pose(&pert.refpos, &pert.refquat, &pos1, &quat1);
    let free =
        |b: usize| m.body_jntnum()[b] == 1 && m.jnt_type()[m.body_jntadr()[b] as usize] == JNT_FREE;
    let qadr = |b: usize| m.jnt_qposadr()[m.body_jntadr()[b] as usize] as usize;
    let mocap = m.body_mocapid()[sel];
    if mocap >= 0 {
        let id = mocap as usize;
        d.mocap_pos[3 * id..3 * id + 3].copy_from_slice(&refpos);
        d.mocap_quat[4 * id..4 * id + 4].copy_from_slice(&refquat);
    } else if paused && free(sel) {
        let a = qadr(sel);
        d.qpos[a..a + 3].copy_from_slice(&refpos);
        d.qpos[a + 3..a + 7].copy_from_slice(&refquat);
    } else if paused && free(root) {
        // root <- ref * neg(child) * root
        let a = qadr(root);
        let (rpos, rquat): (Vec3, Quat) = (row(&d.qpos[a..], 0), row(&d.qpos[a + 3..], 0));
        let (cpos, cquat) = neg_pose(&row(d.xpos, sel), &row(d.xquat, sel));
        let (pos2, quat2) = mul_pose(&cpos, &cquat, &rpos, &rquat);
        let (pos, quat) = mul_pose(&refpos, &refquat, &pos2, &quat2);
        d.qpos[a..a + 3].copy_from_slice(&pos);
        d.qpos[a + 3..a + 7].copy_from_slice(&quat);
    }
}

/// A critically damped spring from the selected body to the reference, as applied force
/// and torque (mjv_applyPerturbForce).
pub fn apply_perturb_force(m: &Model, d: &mut Data, pert: &mjvPerturb) -> Result<(), EngineError> {
    let sel = pert.select;
    let active = pert.active | pert.active2;
    if sel < 0 || sel >= m.raw.nbody || active == 0 {
        return Ok(());
    }
    let sel = sel as usize;
    let bvel = object_velocity(m, d, mjtObj_::mjOBJ_BODY as i32, sel, false)?;
    let map = &m.raw.vis.map;
    let invweight = m.body_invweight0();

    let stiffness = map.stiffness as f64;
    let mass = 1.0 / c_max(MINVAL, invweight[2 * sel]);
    let damping = -(map.stiffness.sqrt() as f64) * mass;
    let mut force = scl3(&sub3(&pert.refpos, &row(d.xipos, sel)), stiffness * mass);
    add_to_scl3(&mut force, &row(&bvel, 1), damping);

    let stiffness = map.stiffnessrot as f64;
    let mass = 1.0 / c_max(MINVAL, invweight[2 * sel + 1]);
    let damping = -(map.stiffnessrot.sqrt() as f64) * mass;
    let dif = mul_quat(&pert.refquat, &neg_quat(&xiquat(m, d, sel)));
    let mut torque = quat2vel(&dif, 1.0 / (stiffness * mass));
    add_to_scl3(&mut torque, &row(&bvel, 0), damping);

    if active & mjtPertBit_::mjPERT_TRANSLATE as i32 == 0 {
        force = [0.0; 3];
    }
    if active & mjtPertBit_::mjPERT_ROTATE as i32 == 0 {
        torque = [0.0; 3];
    }
    d.xfrc_applied[6 * sel..6 * sel + 3].copy_from_slice(&force);
    d.xfrc_applied[6 * sel + 3..6 * sel + 6].copy_from_slice(&torque);
    Ok(())
}

/// The average of two GL cameras, up made orthogonal to forward (mjv_averageCamera).
pub fn average_camera(a: &mjvGLCamera, b: &mjvGLCamera) -> mjvGLCamera {
    let pos = scl3(&add3(&f2n(&a.pos), &f2n(&b.pos)), 0.5);
    let forward = normalize3(&add3(&f2n(&a.forward), &f2n(&b.forward))).0;
    let mut up = add3(&f2n(&a.up), &f2n(&b.up));
    let projection = dot3(&up, &forward);
    add_to_scl3(&mut up, &forward, -projection);
    let up = normalize3(&up).0;
    let mean = |x: f32, y: f32| 0.5f32 * (x + y);
    mjvGLCamera {
        pos: n2f(&pos),
        forward: n2f(&forward),
        up: n2f(&up),
        frustum_center: mean(a.frustum_center, b.frustum_center),
        frustum_bottom: mean(a.frustum_bottom, b.frustum_bottom),
        frustum_top: mean(a.frustum_top, b.frustum_top),
        frustum_near: mean(a.frustum_near, b.frustum_near),
        frustum_far: mean(a.frustum_far, b.frustum_far),
    }
}

/// What the viewer sees at image point (relx, rely) (mjv_select).
pub struct Selection {
    pub body: i32,
    pub geom: i32,
    pub skin: i32,
    /// The point hit; None when nothing is.
    pub point: Option<Vec3>,
}

/// The geom or skin hit by the ray from the viewer through image point (relx, rely) of a
/// viewport with `aspect` ratio (mjv_select); `skinvert` are the scene's skin vertices.
#[allow(clippy::too_many_arguments)]
pub fn select(
    m: &Model,
    d: &Data,
    opt: &mjvOption,
    aspect: f64,
    relx: f64,
    rely: f64,
    scn: &mjvScene,
    skinvert: &[f32],
) -> Result<Selection, EngineError> {
    let cam = average_camera(&scn.camera[0], &scn.camera[1]);
    let (pos, forward, up) = camera_in_model(scn)?;
    let left = normalize3(&cross(&up, &forward)).0;
    let height = (cam.frustum_top - cam.frustum_bottom) as f64;
    let halfwidth = 0.5 * aspect * height;
    let mut dir = scl3(&forward, cam.frustum_near as f64);
    add_to_scl3(&mut dir, &up, cam.frustum_bottom as f64 + rely * height);
    let across = cam.frustum_center as f64 + (2.0 * relx - 1.0) * halfwidth;
    add_to_scl3(&mut dir, &left, -across);
    let dir = normalize3(&dir).0;

    let with_static = opt.flags[mjtVisFlag_::mjVIS_STATIC as usize] != 0;
    let (geomdist, geom) = ray(m, d, &pos, &dir, Some(&opt.geomgroup), with_static, -1)?;
    let (mut skindist, mut body, mut skin) = (-1.0, -1, -1);
    if opt.flags[mjtVisFlag_::mjVIS_SKIN as usize] != 0 {
        for i in 0..m.raw.nskin as usize {
            let faces = &m.skin_face()[3 * m.skin_faceadr()[i] as usize..];
            let faces = &faces[..3 * m.skin_facenum()[i] as usize];
            let verts = &skinvert[3 * m.skin_vertadr()[i] as usize..];
            let verts = &verts[..3 * m.skin_vertnum()[i] as usize];
            let (dist, vertid) = ray_skin(faces, verts, &pos, &dir);
            if !(dist >= 0.0 && (dist < skindist || skindist < 0.0)) {
                continue;
            }
            skindist = dist;
            // the bone with the largest weight on the vertex hit
            let mut best = -1.0f32;
            let boneadr = m.skin_boneadr()[i] as usize;
            for j in boneadr..boneadr + m.skin_bonenum()[i] as usize {
                let adr = m.skin_bonevertadr()[j] as usize;
                for k in adr..adr + m.skin_bonevertnum()[j] as usize {
                    let weight = m.skin_bonevertweight()[k];
                    if m.skin_bonevertid()[k] == vertid && weight > best {
                        best = weight;
                        body = m.skin_bonebodyid()[j];
                        skin = i as i32;
                    }
                }
            }
        }
    }
    let none = Selection {
        body: -1,
        geom,
        skin,
        point: None,
    };
    if geomdist < 0.0 && skindist < 0.0 {
        return Ok(none);
    }
    if geomdist >= 0.0 && (skindist < 0.0 || skindist > geomdist) {
        return Ok(Selection {
            body: m.geom_bodyid()[geom as usize],
            geom,
            skin: -1,
            point: Some(add_scl3(&pos, &dir, geomdist)),
        });
    }
    Ok(Selection {
        body,
        geom: -1,
        skin,
        point: Some(add_scl3(&pos, &dir, skindist)),
    })
}
