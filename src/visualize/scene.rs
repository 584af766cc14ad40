//! The scene's buffers: mjv_makeScene and mjv_freeScene (memory through mju_malloc/mju_free).

use super::defaults::RND_DEFAULT_ON;
use crate::abi::*;
use crate::runtime::memory::{free, malloc};
use crate::runtime::message::error;
use std::os::raw::c_void;

/// Releases the scene's buffers and clears it (mjv_freeScene).
///
/// # Safety
/// The scene's pointers are NULL or from `make`.
pub unsafe fn free_scene(scn: &mut mjvScene) {
    for p in [
        scn.geoms as *mut c_void,
        scn.geomorder as *mut c_void,
        scn.skinfacenum as *mut c_void,
        scn.skinvertadr as *mut c_void,
        scn.skinvertnum as *mut c_void,
        scn.skinvert as *mut c_void,
        scn.skinnormal as *mut c_void,
    ] {
        free(p);
    }
    *scn = std::mem::zeroed();
}

/// Allocates the scene for `m` (or for no model) with room for `maxgeom` geoms (mjv_makeScene).
///
/// # Safety
/// As for `free_scene`; `m` is a compiled model or None.
pub unsafe fn make_scene(m: Option<&mjModel>, scn: &mut mjvScene, maxgeom: i32) {
    free_scene(scn);
    if maxgeom > 0 {
        let n = maxgeom as usize;
        scn.maxgeom = maxgeom;
        scn.geoms = malloc(n * std::mem::size_of::<mjvGeom>()) as *mut mjvGeom;
        scn.geomorder = malloc(n * std::mem::size_of::<i32>()) as *mut i32;
        if scn.geoms.is_null() || scn.geomorder.is_null() {
            error("Could not allocate geom buffers");
            return;
        }
    }
    for i in RND_DEFAULT_ON {
        scn.flags[i] = 1;
    }
    scn.scale = 1.0;
    scn.rotate[0] = 1.0;
    let Some(m) = m.filter(|m| m.nskin > 0) else {
        return;
    };
    let nskin = m.nskin as usize;
    scn.nskin = m.nskin;
    let facenum = std::slice::from_raw_parts(m.skin_facenum, nskin);
    let vertadr = std::slice::from_raw_parts(m.skin_vertadr, nskin);
    let vertnum = std::slice::from_raw_parts(m.skin_vertnum, nskin);
    let totvert: usize = vertnum.iter().map(|&n| n as usize).sum();
    let ints = nskin * std::mem::size_of::<i32>();
    let floats = 3 * totvert * std::mem::size_of::<f32>();
    scn.skinfacenum = malloc(ints) as *mut i32;
    scn.skinvertadr = malloc(ints) as *mut i32;
    scn.skinvertnum = malloc(ints) as *mut i32;
    scn.skinvert = malloc(floats) as *mut f32;
    scn.skinnormal = malloc(floats) as *mut f32;
    if scn.skinfacenum.is_null()
        || scn.skinvertadr.is_null()
        || scn.skinvertnum.is_null()
        || scn.skinvert.is_null()
        || scn.skinnormal.is_null()
    {
        error("Could not allocate skin buffers");
        return;
    }
    std::ptr::copy_nonoverlapping(facenum.as_ptr(), scn.skinfacenum, nskin);
    std::ptr::copy_nonoverlapping(vertadr.as_ptr(), scn.skinvertadr, nskin);
    std::ptr::copy_nonoverlapping(vertnum.as_ptr(), scn.skinvertnum, nskin);
}
