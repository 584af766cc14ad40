//! C entry points of abstract visualization (mjv_): argument checks, then `crate::visualize`.

use crate::abi::*;
use crate::visualize::{defaults, scene};
use std::os::raw::c_int;

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultCamera(cam: *mut mjvCamera) {
    if let Some(cam) = cam.as_mut() {
        *cam = defaults::camera();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultFreeCamera(m: *const mjModel, cam: *mut mjvCamera) {
    if let (Some(m), Some(cam)) = (m.as_ref(), cam.as_mut()) {
        *cam = defaults::free_camera(m);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultPerturb(pert: *mut mjvPerturb) {
    if let Some(pert) = pert.as_mut() {
        *pert = defaults::perturb();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultOption(opt: *mut mjvOption) {
    if let Some(opt) = opt.as_mut() {
        *opt = defaults::option();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultFigure(fig: *mut mjvFigure) {
    if let Some(fig) = fig.as_mut() {
        defaults::figure(fig);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultScene(scn: *mut mjvScene) {
    if let Some(scn) = scn.as_mut() {
        *scn = std::mem::zeroed();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_makeScene(m: *const mjModel, scn: *mut mjvScene, maxgeom: c_int) {
    if let Some(scn) = scn.as_mut() {
        scene::make_scene(m.as_ref(), scn, maxgeom);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_freeScene(scn: *mut mjvScene) {
    if let Some(scn) = scn.as_mut() {
        scene::free_scene(scn);
    }
}
