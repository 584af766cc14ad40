//! The `extern "C"` surface: argument checks, panic containment, calls into the core.

#![allow(non_snake_case, non_upper_case_globals, clippy::missing_safety_doc)]

pub mod engine;
pub mod errmem;
pub mod globals;
pub mod io;
pub mod lengthrange;
pub mod print;
pub mod render;
pub mod ui;
pub mod util;
pub mod visualize;
pub mod xml;

use crate::abi::owned::{DataBox, ModelBox};
use crate::abi::view::EngineError;
use crate::abi::{mjData, mjModel};
use std::mem::ManuallyDrop;

/// Reports an entry point that has no implementation yet (none is left; kept for new API).
pub fn pending(name: &str) {
    errmem::error(&format!("{name} is not implemented"));
}

/// Runs `f`, turning a core error or a panic into `mju_error`; returns `fallback` then.
pub fn guard<R>(name: &str, fallback: R, f: impl FnOnce() -> Result<R, EngineError>) -> R {
    guard_explained(name, fallback, f, |_| None)
}

/// As `guard`, where `explain` may word the message of a panic from its payload.
pub fn guard_explained<R>(
    name: &str,
    fallback: R,
    f: impl FnOnce() -> Result<R, EngineError>,
    explain: impl FnOnce(&(dyn std::any::Any + Send)) -> Option<String>,
) -> R {
    match crate::runtime::guard::catch_explained(name, f, explain) {
        Ok(Ok(r)) => r,
        Ok(Err(e)) => {
            errmem::error(&e.0);
            fallback
        }
        Err(msg) => {
            errmem::error(&msg);
            fallback
        }
    }
}

/// The caller's model and data as the core's owning types, never freed here (also not when
/// the core panics).
///
/// # Safety
/// `m` and `d` are non-NULL, from mj_makeModel/mj_loadXML and mj_makeData(m), not aliased.
pub unsafe fn borrow_boxes(
    m: *mut mjModel,
    d: *mut mjData,
) -> (ManuallyDrop<ModelBox>, ManuallyDrop<DataBox>) {
    let m = ManuallyDrop::new(ModelBox::from_raw(m));
    let d = ManuallyDrop::new(DataBox::from_raw(d, &m));
    (m, d)
}
