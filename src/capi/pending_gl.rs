//! OpenGL rendering (mjr_) entry points not implemented yet:
//! each reports itself through mju_error.

#![allow(unused_unsafe)]

use super::pending;
use crate::abi::*;

#[no_mangle]
pub unsafe extern "C" fn mjr_figure(
    _viewport: mjrRect,
    _fig: *mut mjvFigure,
    _con: *const mjrContext,
) {
    pending("mjr_figure");
}
