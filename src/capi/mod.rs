//! The `extern "C"` surface: argument checks, panic containment, calls into the core.

#![allow(non_snake_case, non_upper_case_globals, clippy::missing_safety_doc)]

pub mod engine;
pub mod errmem;
pub mod globals;
pub mod io;
#[rustfmt::skip]
pub mod pending;
#[rustfmt::skip]
pub mod pending_internal;
pub mod print;
pub mod util;
pub mod xml;

use crate::abi::view::EngineError;

/// Reports an entry point that has no implementation yet.
pub fn pending(name: &str) {
    errmem::error(&format!("{name} is not implemented"));
}

/// Runs `f`, turning a core error or a panic into `mju_error`; returns `fallback` then.
pub fn guard<R>(name: &str, fallback: R, f: impl FnOnce() -> Result<R, EngineError>) -> R {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(r)) => r,
        Ok(Err(e)) => {
            errmem::error(&e.0);
            fallback
        }
        Err(_) => {
            errmem::error(&format!("{name}: internal error"));
            fallback
        }
    }
}
