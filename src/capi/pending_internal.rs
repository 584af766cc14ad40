//! Symbols 2.2.2 exports outside mujoco.h not implemented yet: each reports that through `mju_error`.

#![allow(unused_variables, unused_imports)]

use crate::abi::*;
use std::os::raw::{c_char, c_int, c_void};

use super::pending;

#[no_mangle]
pub unsafe extern "C" fn mj_jacDifPair(m: *const mjModel, d: *const mjData, chain: *mut c_int, b1: c_int, b2: c_int, pos1: *const mjtNum, pos2: *const mjtNum, jac1p: *mut mjtNum, jac2p: *mut mjtNum, jacdifp: *mut mjtNum, jac1r: *mut mjtNum, jac2r: *mut mjtNum, jacdifr: *mut mjtNum) -> c_int {
    pending("mj_jacDifPair");
    0 as c_int
}

