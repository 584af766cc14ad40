//! `#[repr(C)]` mirrors of MuJoCo 2.2.2's public types: the only layout dictated from outside.

#![allow(
    non_camel_case_types,
    non_snake_case,
    non_upper_case_globals,
    clippy::upper_case_acronyms
)]

#[macro_use]
pub mod xmacro;

macro_rules! elem_ty {
    (int) => {
        i32
    };
    (mjtNum) => {
        f64
    };
    (float) => {
        f32
    };
    (char) => {
        std::os::raw::c_char
    };
    (mjtByte) => {
        u8
    };
    (mjContact) => {
        mjContact
    };
}

/// Second dimension of an X-macro row.
macro_rules! dim2 {
    ($m:expr, @ $f:ident * $k:literal) => {
        ($m.$f as usize) * $k
    };
    ($m:expr, $k:expr) => {
        $k as usize
    };
}

/// Number of elements of an X-macro row, saturating at zero for corrupt sizes.
macro_rules! row_len {
    ($m:expr, $d1:ident, $($d2:tt)+) => { ($m.$d1.max(0) as usize) * dim2!($m, $($d2)+) };
}

pub mod alloc;
pub mod consistency;
pub mod cstr;
pub mod mjb;
pub mod mjdata;
pub mod mjmodel;
pub mod mjrender;
pub mod mjtnum;
pub mod mjui;
pub mod mjvisualize;
pub mod owned;
pub mod validate;
pub mod view;

pub use mjdata::*;
pub use mjmodel::*;
pub use mjrender::*;
pub use mjtnum::*;
pub use mjui::*;
pub use mjvisualize::*;
