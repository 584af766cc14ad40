//! Entry points of the 2.2.2 API not implemented yet: each reports that through `mju_error`.

#![allow(unused_variables, unused_imports)]

use crate::abi::*;
use std::os::raw::{c_char, c_int, c_void};

use super::pending;

#[no_mangle]
pub unsafe extern "C" fn mj_saveLastXML(filename: *const c_char, m: *const mjModel, error: *mut c_char, error_sz: c_int) -> c_int {
    pending("mj_saveLastXML");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_freeLastXML() {
    pending("mj_freeLastXML");
}

#[no_mangle]
pub unsafe extern "C" fn mj_printSchema(filename: *const c_char, buffer: *mut c_char, buffer_sz: c_int, flg_html: c_int, flg_pad: c_int) -> c_int {
    pending("mj_printSchema");
    0 as c_int
}

