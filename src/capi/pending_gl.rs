//! Visualization (mjv_), OpenGL rendering (mjr_) and UI (mjui_) entry points not implemented yet:
//! each reports itself through mju_error.

#![allow(unused_unsafe)]

use super::pending;
use crate::abi::*;
use std::os::raw::{c_char, c_int};

#[no_mangle]
pub unsafe extern "C" fn mjr_text(
    _font: c_int,
    _txt: *const c_char,
    _con: *const mjrContext,
    _x: f32,
    _y: f32,
    _r: f32,
    _g: f32,
    _b: f32,
) {
    pending("mjr_text");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_overlay(
    _font: c_int,
    _gridpos: c_int,
    _viewport: mjrRect,
    _overlay: *const c_char,
    _overlay2: *const c_char,
    _con: *const mjrContext,
) {
    pending("mjr_overlay");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_rectangle(_viewport: mjrRect, _r: f32, _g: f32, _b: f32, _a: f32) {
    pending("mjr_rectangle");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_label(
    _viewport: mjrRect,
    _font: c_int,
    _txt: *const c_char,
    _r: f32,
    _g: f32,
    _b: f32,
    _a: f32,
    _rt: f32,
    _gt: f32,
    _bt: f32,
    _con: *const mjrContext,
) {
    pending("mjr_label");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_figure(
    _viewport: mjrRect,
    _fig: *mut mjvFigure,
    _con: *const mjrContext,
) {
    pending("mjr_figure");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_render(
    _viewport: mjrRect,
    _scn: *mut mjvScene,
    _con: *const mjrContext,
) {
    pending("mjr_render");
}

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
