//! Entry points of the 2.2.2 API not implemented yet: each reports that through `mju_error`.

#![allow(unused_variables, unused_imports)]

use crate::abi::*;
use std::os::raw::{c_char, c_int, c_void};

use super::pending;

#[no_mangle]
pub unsafe extern "C" fn mj_setLengthRange(m: *mut mjModel, d: *mut mjData, index: c_int, opt: *const mjLROpt, error: *mut c_char, error_sz: c_int) -> c_int {
    pending("mj_setLengthRange");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_rayHfield(m: *const mjModel, d: *const mjData, geomid: c_int, pnt: *const mjtNum, vec: *const mjtNum) -> mjtNum {
    pending("mj_rayHfield");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mj_rayMesh(m: *const mjModel, d: *const mjData, geomid: c_int, pnt: *const mjtNum, vec: *const mjtNum) -> mjtNum {
    pending("mj_rayMesh");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_raySkin(nface: c_int, nvert: c_int, face: *const c_int, vert: *const f32, pnt: *const mjtNum, vec: *const mjtNum, vertid: *mut c_int) -> mjtNum {
    pending("mju_raySkin");
    0.0
}

