//! `#[repr(C)]` mirrors of MuJoCo 2.2.2's public types: the only layout dictated from outside.

#![allow(non_camel_case_types, non_snake_case, non_upper_case_globals, clippy::upper_case_acronyms)]

pub mod mjdata;
pub mod mjmodel;
pub mod mjtnum;
#[macro_use]
pub mod xmacro;
pub mod view;

pub use mjdata::*;
pub use mjmodel::*;
pub use mjtnum::*;
