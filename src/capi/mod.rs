//! The `extern "C"` surface: argument checks, panic containment, calls into the core.

#![allow(non_snake_case, non_upper_case_globals, clippy::missing_safety_doc)]

pub mod engine;
pub mod errmem;
pub mod globals;
pub mod io;
pub mod lengthrange;
pub mod print;
pub mod util;
pub mod xml;

use crate::abi::view::EngineError;

/// Reports an entry point that has no implementation yet (none is left; kept for new API).
pub fn pending(name: &str) {
    errmem::error(&format!("{name} is not implemented"));
}

/// Runs `f`, turning a core error or a panic into `mju_error`; returns `fallback` then.
pub fn guard<R>(name: &str, fallback: R, f: impl FnOnce() -> Result<R, EngineError>) -> R {
    quiet_panics();
    GUARDED.with(|g| g.set(g.get() + 1));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    GUARDED.with(|g| g.set(g.get() - 1));
    match result {
        Ok(Ok(r)) => r,
        Ok(Err(e)) => {
            errmem::error(&e.0);
            fallback
        }
        Err(p) => {
            let why = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            errmem::error(&format!("{name}: internal error ({why})"));
            fallback
        }
    }
}

thread_local! {
    /// Depth of `guard` calls on this thread: panics inside are reported through mju_error.
    static GUARDED: std::cell::Cell<u32> = const { std::cell::Cell::new(0) };
}

/// Installs (once) a panic hook that stays silent for panics `guard` reports, and defers to
/// the previous hook for any other panic.
fn quiet_panics() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if GUARDED.with(|g| g.get()) == 0 {
                previous(info);
            }
        }));
    });
}
