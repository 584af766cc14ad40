//! Errors and warnings with 2.2.2's semantics: the user's handlers (global and per thread),
//! else print, log to MUJOCO_LOG.TXT and, for errors, exit.

use std::cell::Cell;
use std::ffi::CStr;
use std::io::Write;
use std::os::raw::{c_char, c_void};

/// A C message handler (mju_user_error, mju_user_warning, the thread-local hooks).
pub type MsgHandler = Option<unsafe extern "C" fn(*const c_char)>;

#[no_mangle]
pub static mut mju_user_error: Option<unsafe extern "C" fn(*const c_char)> = None;
#[no_mangle]
pub static mut mju_user_warning: Option<unsafe extern "C" fn(*const c_char)> = None;

thread_local! {
    static TLS_ERROR: Cell<MsgHandler> = const { Cell::new(None) };
    static TLS_WARNING: Cell<MsgHandler> = const { Cell::new(None) };
}

/// This thread's error hook (taken before mju_user_error).
pub fn tls_error_handler() -> MsgHandler {
    TLS_ERROR.with(|c| c.get())
}

pub fn set_tls_error_handler(h: MsgHandler) {
    TLS_ERROR.with(|c| c.set(h))
}

/// This thread's warning hook (taken before mju_user_warning).
pub fn tls_warning_handler() -> MsgHandler {
    TLS_WARNING.with(|c| c.get())
}

pub fn set_tls_warning_handler(h: MsgHandler) {
    TLS_WARNING.with(|c| c.set(h))
}

/// Removes the user's error and warning handlers.
pub fn clear_handlers() {
    // SAFETY: plain stores to the handler globals, as the C library does.
    unsafe {
        mju_user_error = None;
        mju_user_warning = None;
    }
}

/// Appends a dated entry to MUJOCO_LOG.TXT in the working directory, as 2.2.2 does.
pub fn write_log(kind: &str, msg: &str) {
    if let Ok(mut f) = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open("MUJOCO_LOG.TXT")
    {
        let mut date = [0 as c_char; 64];
        let _ = f.write_all(asctime_now(&mut date));
        let _ = write!(f, "{}: {}\n\n", kind, msg);
    }
}

/// The local time as asctime writes it, in `buf`.
fn asctime_now(buf: &mut [c_char; 64]) -> &[u8] {
    // SAFETY: plain libc time formatting into a local buffer of asctime_r's required size.
    unsafe {
        let t = libc::time(std::ptr::null_mut());
        let mut tm: libc::tm = std::mem::zeroed();
        libc::localtime_r(&t, &mut tm);
        if libc::asctime_r(&tm, buf.as_mut_ptr()).is_null() {
            return &[];
        }
        CStr::from_ptr(buf.as_ptr()).to_bytes()
    }
}

/// Writes to C's `stdout`, so output interleaves with the host program's printf as in C.
pub fn c_stdout(text: &str) {
    extern "C" {
        static mut stdout: *mut libc::FILE;
    }
    let bytes = text.as_bytes();
    // SAFETY: glibc's stdout stream is valid for the process lifetime.
    unsafe {
        libc::fwrite(bytes.as_ptr() as *const c_void, 1, bytes.len(), stdout);
    }
}

/// Flushes C's `stdout`.
pub fn c_stdout_flush() {
    extern "C" {
        static mut stdout: *mut libc::FILE;
    }
    // SAFETY: as in `c_stdout`.
    unsafe {
        libc::fflush(stdout);
    }
}

/// A message of at most 999 bytes on the stack (2.2.2's 1000-byte buffers), NUL-terminated
/// for C handlers: runtime warnings are reported without heap allocation.
pub struct MsgBuf {
    buf: [u8; 1000],
    len: usize,
}

impl MsgBuf {
    pub fn new() -> Self {
        MsgBuf {
            buf: [0; 1000],
            len: 0,
        }
    }

    /// The text written so far (truncation keeps whole characters).
    pub fn as_str(&self) -> &str {
        std::str::from_utf8(&self.buf[..self.len]).unwrap_or("")
    }

    /// The text, NUL-terminated, for C handlers.
    fn as_c(&self) -> *const c_char {
        self.buf.as_ptr() as *const c_char
    }
}

impl Default for MsgBuf {
    fn default() -> Self {
        Self::new()
    }
}

impl std::fmt::Write for MsgBuf {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        for c in s.chars().filter(|&c| c != '\0') {
            let n = c.len_utf8();
            if self.len + n > self.buf.len() - 1 {
                break;
            }
            c.encode_utf8(&mut self.buf[self.len..self.len + n]);
            self.len += n;
        }
        self.buf[self.len] = 0;
        Ok(())
    }
}

fn c_message(msg: &str) -> MsgBuf {
    let mut b = MsgBuf::new();
    let _ = std::fmt::Write::write_str(&mut b, msg);
    b
}

/// Reports a fatal error: thread-local hook, user handler, or print, log and exit.
pub fn error(msg: &str) {
    let text = c_message(msg);
    // SAFETY: handlers are C callbacks taking a NUL-terminated string.
    unsafe {
        if let Some(h) = tls_error_handler() {
            h(text.as_c());
        } else if let Some(h) = mju_user_error {
            h(text.as_c());
        } else {
            write_log("ERROR", msg);
            c_stdout(&format!("ERROR: {msg}\n\nPress Enter to exit ..."));
            c_stdout_flush();
            libc::getchar();
            libc::exit(1);
        }
    }
}

/// Reports a warning: thread-local hook, user handler, or print and log.
pub fn warning(msg: &str) {
    let text = c_message(msg);
    // SAFETY: as in `error`.
    unsafe {
        if let Some(h) = tls_warning_handler() {
            h(text.as_c());
        } else if let Some(h) = mju_user_warning {
            h(text.as_c());
        } else {
            write_log("WARNING", msg);
            c_stdout("WARNING: ");
            c_stdout(msg);
            c_stdout("\n\n");
        }
    }
}

thread_local! {
    /// Messages caught by `capture_errors` (the first) and `capture_warnings` (the last).
    static CAUGHT_ERROR: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
    static CAUGHT_WARNING: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

unsafe extern "C" fn catch_error(msg: *const c_char) {
    let text = CStr::from_ptr(msg).to_string_lossy().into_owned();
    CAUGHT_ERROR.with(|c| {
        c.borrow_mut().get_or_insert(text);
    });
}

unsafe extern "C" fn catch_warning(msg: *const c_char) {
    let text = CStr::from_ptr(msg).to_string_lossy().into_owned();
    CAUGHT_WARNING.with(|c| *c.borrow_mut() = Some(text));
}

/// Runs `f` with this thread's error hook taking the errors raised meanwhile (mju_error
/// returns to its caller); gives the first one. The previous hook is restored.
pub fn capture_errors<R>(f: impl FnOnce() -> R) -> (R, Option<String>) {
    capture(
        &CAUGHT_ERROR,
        catch_error,
        tls_error_handler,
        set_tls_error_handler,
        f,
    )
}

/// Runs `f` with this thread's warning hook taking the warnings raised meanwhile; gives the
/// last one. The previous hook is restored.
pub fn capture_warnings<R>(f: impl FnOnce() -> R) -> (R, Option<String>) {
    capture(
        &CAUGHT_WARNING,
        catch_warning,
        tls_warning_handler,
        set_tls_warning_handler,
        f,
    )
}

fn capture<R>(
    slot: &'static std::thread::LocalKey<std::cell::RefCell<Option<String>>>,
    hook: unsafe extern "C" fn(*const c_char),
    get: fn() -> MsgHandler,
    set: fn(MsgHandler),
    f: impl FnOnce() -> R,
) -> (R, Option<String>) {
    /// Restores the previous hook, also when `f` unwinds.
    struct Restore(fn(MsgHandler), MsgHandler);
    impl Drop for Restore {
        fn drop(&mut self) {
            (self.0)(self.1)
        }
    }
    let outer = slot.with(|c| c.borrow_mut().take());
    let restore = Restore(set, get());
    set(Some(hook));
    let r = f();
    drop(restore);
    let caught = slot.with(|c| std::mem::replace(&mut *c.borrow_mut(), outer));
    (r, caught)
}

/// A number as C's "%g" prints it (messages that quote 2.2.2's format).
pub fn format_g(x: f64) -> String {
    format_c(c"%g", &[x])
}

/// Doubles formatted by C's snprintf with `fmt` (labels that quote 2.2.2's formats); `fmt`
/// takes exactly `args.len()` doubles, at most six.
pub fn format_c(fmt: &std::ffi::CStr, args: &[f64]) -> String {
    let mut buf = [0u8; 256];
    let (p, n, f) = (
        buf.as_mut_ptr() as *mut libc::c_char,
        buf.len(),
        fmt.as_ptr(),
    );
    let a = |i: usize| args.get(i).copied().unwrap_or(0.0);
    // SAFETY: the caller's format takes the doubles passed; buf bounds the output.
    let len = unsafe {
        match args.len() {
            1 => libc::snprintf(p, n, f, a(0)),
            3 => libc::snprintf(p, n, f, a(0), a(1), a(2)),
            6 => libc::snprintf(p, n, f, a(0), a(1), a(2), a(3), a(4), a(5)),
            _ => panic!("format_c takes 1, 3 or 6 numbers"),
        }
    };
    String::from_utf8_lossy(&buf[..(len.max(0) as usize).min(buf.len() - 1)]).into_owned()
}
