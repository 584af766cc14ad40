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
        let date = asctime_now(&mut date);
        // one write per entry, as C's buffered stream makes it (a warning per solver
        // iteration must not cost a system call per piece)
        let mut entry = [0u8; 1200];
        let mut w = std::io::Cursor::new(&mut entry[..]);
        if w.write_all(date).is_ok() && write!(w, "{kind}: {msg}\n\n").is_ok() {
            let n = w.position() as usize;
            let _ = f.write_all(&entry[..n]);
        } else {
            let _ = f.write_all(date);
            let _ = write!(f, "{kind}: {msg}\n\n");
        }
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
    buf: [u8; MSG_MAX],
    len: usize,
}

impl MsgBuf {
    pub fn new() -> Self {
        MsgBuf {
            buf: [0; MSG_MAX],
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
        for part in s.split('\0') {
            let kept = cut(part, self.buf.len() - 1 - self.len);
            let n = kept.len();
            self.buf[self.len..self.len + n].copy_from_slice(kept.as_bytes());
            self.len += n;
            if n < part.len() {
                break;
            }
        }
        self.buf[self.len] = 0;
        Ok(())
    }
}

/// Calls `f` with `msg` as a NUL-terminated C string (NULs inside dropped), whole: on the
/// stack when it fits, as the engine's messages do, else on the heap.
fn with_c_message(msg: &str, f: impl FnOnce(*const c_char)) {
    if msg.len() < MSG_MAX {
        let mut b = MsgBuf::new();
        let _ = std::fmt::Write::write_str(&mut b, msg);
        f(b.as_c());
    } else {
        let text = std::ffi::CString::new(msg.replace('\0', "")).unwrap_or_default();
        f(text.as_ptr());
    }
}

/// Length of the buffers 2.2.2 formats messages into (snprintf): at most this minus one bytes.
const MSG_MAX: usize = 1000;

/// `msg` cut as a formatting into 2.2.2's message buffer cuts it.
pub fn truncated(msg: &str) -> &str {
    cut(msg, MSG_MAX - 1)
}

/// The longest start of `s` of at most `max` bytes that ends on a character boundary.
fn cut(s: &str, max: usize) -> &str {
    let mut n = s.len().min(max);
    while !s.is_char_boundary(n) {
        n -= 1;
    }
    &s[..n]
}

/// Reports a fatal error: thread-local hook, user handler, or print, log and exit.
pub fn error(msg: &str) {
    // SAFETY: handlers are C callbacks taking a NUL-terminated string.
    unsafe {
        if let Some(h) = tls_error_handler() {
            with_c_message(msg, |p| h(p));
        } else if let Some(h) = mju_user_error {
            with_c_message(msg, |p| h(p));
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
    // SAFETY: as in `error`.
    unsafe {
        if let Some(h) = tls_warning_handler() {
            with_c_message(msg, |p| h(p));
        } else if let Some(h) = mju_user_warning {
            with_c_message(msg, |p| h(p));
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

#[cfg(test)]
mod tests {
    use super::MsgBuf;
    use std::fmt::Write;

    fn text(b: &MsgBuf) -> &str {
        std::str::from_utf8(&b.buf[..b.len]).unwrap()
    }

    #[test]
    fn message_buffer_drops_nul_and_truncates_on_char_boundary() {
        let mut b = MsgBuf::new();
        write!(b, "a\0b{}", 7).unwrap();
        assert_eq!(text(&b), "ab7");
        assert_eq!(b.buf[b.len], 0);
        let mut b = MsgBuf::new();
        b.write_str(&"x".repeat(998)).unwrap();
        b.write_str("é and more").unwrap(); // two bytes where one is left
        assert_eq!(b.len, 998);
        b.write_str("y").unwrap();
        assert_eq!(text(&b), format!("{}y", "x".repeat(998)));
        b.write_str("z").unwrap();
        assert_eq!(b.len, 999);
        assert_eq!(b.buf[999], 0);
    }
}
