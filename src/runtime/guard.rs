//! Panic containment for calls into the core: a panic becomes an error message, and the
//! panic hook stays silent for panics caught here.

use std::cell::Cell;

thread_local! {
    /// Depth of `catch` calls on this thread: panics inside are reported as errors.
    static GUARDED: Cell<u32> = const { Cell::new(0) };
}

/// Runs `f`; a panic comes back as Err("`name`: internal error (why)").
pub fn catch<R>(name: &str, f: impl FnOnce() -> R) -> Result<R, String> {
    catch_explained(name, f, |_| None)
}

/// As `catch`, where `explain` may give the message of a panic from its payload (else the
/// internal error message).
pub fn catch_explained<R>(
    name: &str,
    f: impl FnOnce() -> R,
    explain: impl FnOnce(&(dyn std::any::Any + Send)) -> Option<String>,
) -> Result<R, String> {
    quiet_panics();
    // one lookup of the thread's counter (each costs a call in a shared library)
    let result = GUARDED.with(|g| {
        g.set(g.get() + 1);
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
        g.set(g.get() - 1);
        result
    });
    result.map_err(|p| {
        if let Some(msg) = explain(p.as_ref()) {
            return msg;
        }
        let why = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        format!("{name}: internal error ({why})")
    })
}

/// Installs (once) a panic hook that stays silent for panics `catch` reports, and defers to
/// the previous hook for any other panic. A flag rather than `std::sync::Once`: its slow path
/// reads a jump table, one more page a fresh process faults in on its first call.
fn quiet_panics() {
    use std::sync::atomic::{AtomicU8, Ordering};
    const UNSET: u8 = 0;
    const SETTING: u8 = 1;
    const SET: u8 = 2;
    static STATE: AtomicU8 = AtomicU8::new(UNSET);
    if STATE.load(Ordering::Acquire) == SET {
        return;
    }
    // set_hook panics on a panicking thread: that one goes on without
    if std::thread::panicking() {
        return;
    }
    if STATE
        .compare_exchange(UNSET, SETTING, Ordering::Acquire, Ordering::Acquire)
        .is_ok()
    {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if GUARDED.with(|g| g.get()) == 0 {
                previous(info);
            }
        }));
        STATE.store(SET, Ordering::Release);
        return;
    }
    // another thread is installing it
    while STATE.load(Ordering::Acquire) != SET {
        std::hint::spin_loop();
    }
}
