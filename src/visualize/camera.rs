//! The scene's two GL cameras (mjv_updateCamera): a free or tracking camera orbiting its
//! look-at point, or a model camera; eyes apart by the interpupillary distance.

use crate::abi::*;
use crate::engine::linalg::row;
use crate::engine::{Data, EngineError, Model};
use crate::math::vec3::{add_scl3, add_to_scl3, sub3};
use crate::math::Vec3;

pub fn update_camera(
    m: &Model,
    d: &Data,
    cam: &mut mjvCamera,
    scn: &mut mjvScene,
) -> Result<(), EngineError> {
    if cam.r#type == mjtCamera_::mjCAMERA_USER as i32 {
        return Ok(());
    }
    let znear = m.raw.vis.map.znear as f64 * m.raw.stat.extent;
    let zfar = m.raw.vis.map.zfar as f64 * m.raw.stat.extent;
    let (headpos, forward, up, right, ipd, fovy): (Vec3, Vec3, Vec3, Vec3, f64, f64);
    match cam.r#type {
        t if t == mjtCamera_::mjCAMERA_FREE as i32 || t == mjtCamera_::mjCAMERA_TRACKING as i32 => {
            ipd = m.raw.vis.global.ipd as f64;
            fovy = m.raw.vis.global.fovy as f64;
            if t == mjtCamera_::mjCAMERA_TRACKING as i32 {
                let body = cam.trackbodyid;
                if body < 0 || body >= m.raw.nbody {
                    return Err(EngineError("Track body id is outside valid range".into()));
                }
                let com: Vec3 = row(d.subtree_com, body as usize);
                let step = sub3(&com, &cam.lookat);
                add_to_scl3(&mut cam.lookat, &step, 0.2);
            }
            let radians = |deg: f64| deg / 180.0 * std::f64::consts::PI;
            let (sa, ca) = (radians(cam.azimuth).sin(), radians(cam.azimuth).cos());
            let (se, ce) = (radians(cam.elevation).sin(), radians(cam.elevation).cos());
            forward = [ce * ca, ce * sa, se];
            up = [-se * ca, -se * sa, ce];
            right = [sa, -ca, 0.0];
            headpos = add_scl3(&cam.lookat, &forward, -cam.distance);
        }
        t if t == mjtCamera_::mjCAMERA_FIXED as i32 => {
            let id = cam.fixedcamid;
            if id < 0 || id >= m.raw.ncam {
                return Err(EngineError("Fixed camera id is outside valid range".into()));
            }
            let id = id as usize;
            ipd = m.cam_ipd()[id];
            fovy = m.cam_fovy()[id];
            let mat = &d.cam_xmat[9 * id..9 * id + 9];
            forward = [-mat[2], -mat[5], -mat[8]];
            up = [mat[1], mat[4], mat[7]];
            right = [mat[0], mat[3], mat[6]];
            headpos = row(d.cam_xpos, id);
        }
        _ => {
            return Err(EngineError(
                "Unknown camera type in mjv_updateCamera".into(),
            ))
        }
    }
    // symmetric frustum: float tangent of the half angle, as 2.2.2 computes it
    let half = (fovy * (std::f64::consts::PI / 360.0) as f32 as f64) as f32;
    let top = znear as f32 * half.tan();
    for (view, gl) in scn.camera.iter_mut().enumerate() {
        let eye = if view == 1 { ipd } else { -ipd };
        for i in 0..3 {
            gl.pos[i] = (headpos[i] + eye * 0.5 * right[i]) as f32;
            gl.forward[i] = forward[i] as f32;
            gl.up[i] = up[i] as f32;
        }
        gl.frustum_center = 0.0;
        gl.frustum_top = top;
        gl.frustum_bottom = -top;
        gl.frustum_near = znear as f32;
        gl.frustum_far = zfar as f32;
    }
    scn.enabletransform = 0;
    Ok(())
}
