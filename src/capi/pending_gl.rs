//! Visualization (mjv_), OpenGL rendering (mjr_) and UI (mjui_) entry points not implemented yet:
//! each reports itself through mju_error.

#![allow(unused_unsafe)]

use super::pending;
use crate::abi::*;
use std::os::raw::{c_char, c_int, c_uchar};

#[no_mangle]
pub unsafe extern "C" fn mjr_defaultContext(_con: *mut mjrContext) {
    pending("mjr_defaultContext");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_makeContext(
    _m: *const mjModel,
    _con: *mut mjrContext,
    _fontscale: c_int,
) {
    pending("mjr_makeContext");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_changeFont(_fontscale: c_int, _con: *mut mjrContext) {
    pending("mjr_changeFont");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_addAux(
    _index: c_int,
    _width: c_int,
    _height: c_int,
    _samples: c_int,
    _con: *mut mjrContext,
) {
    pending("mjr_addAux");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_freeContext(_con: *mut mjrContext) {
    pending("mjr_freeContext");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_uploadTexture(
    _m: *const mjModel,
    _con: *const mjrContext,
    _texid: c_int,
) {
    pending("mjr_uploadTexture");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_uploadMesh(
    _m: *const mjModel,
    _con: *const mjrContext,
    _meshid: c_int,
) {
    pending("mjr_uploadMesh");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_uploadHField(
    _m: *const mjModel,
    _con: *const mjrContext,
    _hfieldid: c_int,
) {
    pending("mjr_uploadHField");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_restoreBuffer(_con: *const mjrContext) {
    pending("mjr_restoreBuffer");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_setBuffer(_framebuffer: c_int, _con: *mut mjrContext) {
    pending("mjr_setBuffer");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_readPixels(
    _rgb: *mut c_uchar,
    _depth: *mut f32,
    _viewport: mjrRect,
    _con: *const mjrContext,
) {
    pending("mjr_readPixels");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_drawPixels(
    _rgb: *const c_uchar,
    _depth: *const f32,
    _viewport: mjrRect,
    _con: *const mjrContext,
) {
    pending("mjr_drawPixels");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_blitBuffer(
    _src: mjrRect,
    _dst: mjrRect,
    _flg_color: c_int,
    _flg_depth: c_int,
    _con: *const mjrContext,
) {
    pending("mjr_blitBuffer");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_setAux(_index: c_int, _con: *const mjrContext) {
    pending("mjr_setAux");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_blitAux(
    _index: c_int,
    _src: mjrRect,
    _left: c_int,
    _bottom: c_int,
    _con: *const mjrContext,
) {
    pending("mjr_blitAux");
}

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
pub unsafe extern "C" fn mjr_maxViewport(_con: *const mjrContext) -> mjrRect {
    pending("mjr_maxViewport");
    unsafe { std::mem::zeroed() }
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
pub unsafe extern "C" fn mjr_finish() {
    pending("mjr_finish");
}

#[no_mangle]
pub unsafe extern "C" fn mjr_getError() -> c_int {
    pending("mjr_getError");
    0
}

#[no_mangle]
pub unsafe extern "C" fn mjr_findRect(
    _x: c_int,
    _y: c_int,
    _nrect: c_int,
    _rect: *const mjrRect,
) -> c_int {
    pending("mjr_findRect");
    0
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
