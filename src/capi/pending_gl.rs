//! UI (mjui_) entry points not implemented yet:
//! each reports itself through mju_error.

#![allow(unused_unsafe)]

use super::pending;
use crate::abi::*;
use std::os::raw::c_int;

#[no_mangle]
pub unsafe extern "C" fn mjui_update(
    _section: c_int,
    _item: c_int,
    _ui: *const mjUI,
    _state: *const mjuiState,
    _con: *const mjrContext,
) {
    pending("mjui_update");
}

#[no_mangle]
pub unsafe extern "C" fn mjui_event(
    _ui: *mut mjUI,
    _state: *mut mjuiState,
    _con: *const mjrContext,
) -> *mut mjuiItem {
    pending("mjui_event");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mjui_render(
    _ui: *mut mjUI,
    _state: *const mjuiState,
    _con: *const mjrContext,
) {
    pending("mjui_render");
}
