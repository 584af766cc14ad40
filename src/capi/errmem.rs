//! Errors, warnings and memory with 2.2.2 semantics: user handlers, thread-local hooks, log file.

use std::cell::Cell;
use std::ffi::CStr;
use std::io::Write;
use std::os::raw::{c_char, c_int, c_void};

pub type MsgHandler = Option<unsafe extern "C" fn(*const c_char)>;

#[no_mangle]
pub static mut mju_user_error: Option<unsafe extern "C" fn(*const c_char)> = None;
#[no_mangle]
pub static mut mju_user_warning: Option<unsafe extern "C" fn(*const c_char)> = None;
#[no_mangle]
pub static mut mju_user_malloc: Option<unsafe extern "C" fn(usize) -> *mut c_void> = None;
#[no_mangle]
pub static mut mju_user_free: Option<unsafe extern "C" fn(*mut c_void)> = None;

thread_local! {
    static TLS_ERROR: Cell<MsgHandler> = const { Cell::new(None) };
    static TLS_WARNING: Cell<MsgHandler> = const { Cell::new(None) };
    static XML_PRECISION: Cell<c_int> = const { Cell::new(0) };
}

#[no_mangle]
pub extern "C" fn _mjPRIVATE__get_tls_error_fn() -> MsgHandler {
    TLS_ERROR.with(|c| c.get())
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__set_tls_error_fn(h: MsgHandler) {
    TLS_ERROR.with(|c| c.set(h))
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__get_tls_warning_fn() -> MsgHandler {
    TLS_WARNING.with(|c| c.get())
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__set_tls_warning_fn(h: MsgHandler) {
    TLS_WARNING.with(|c| c.set(h))
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__get_xml_precision() -> c_int {
    XML_PRECISION.with(|c| c.get())
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__set_xml_precision(p: c_int) {
    XML_PRECISION.with(|c| c.set(p))
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
        if let Some(h) = _mjPRIVATE__get_tls_error_fn() {
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
        if let Some(h) = _mjPRIVATE__get_tls_warning_fn() {
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

/// Reads a C string argument; NULL reads as empty.
pub unsafe fn cstr<'a>(s: *const c_char) -> std::borrow::Cow<'a, str> {
    if s.is_null() {
        "".into()
    } else {
        CStr::from_ptr(s).to_string_lossy()
    }
}

/// Formats a printf-style message with one `%d`/`%i` or `%s` argument.
fn format1(fmt: &str, arg: &str) -> String {
    let mut out = String::new();
    let mut it = fmt.chars().peekable();
    let mut used = false;
    while let Some(c) = it.next() {
        if c == '%' {
            match it.peek() {
                Some('%') => {
                    it.next();
                    out.push('%');
                }
                Some('d') | Some('i') | Some('s') if !used => {
                    it.next();
                    out.push_str(arg);
                    used = true;
                }
                _ => out.push('%'),
            }
        } else {
            out.push(c);
        }
    }
    out
}

#[no_mangle]
pub unsafe extern "C" fn mju_error(msg: *const c_char) {
    error(&cstr(msg));
}
#[no_mangle]
pub unsafe extern "C" fn mju_warning(msg: *const c_char) {
    warning(&cstr(msg));
}
#[no_mangle]
pub unsafe extern "C" fn mju_error_i(msg: *const c_char, i: c_int) {
    error(&format1(&cstr(msg), &i.to_string()));
}
#[no_mangle]
pub unsafe extern "C" fn mju_warning_i(msg: *const c_char, i: c_int) {
    warning(&format1(&cstr(msg), &i.to_string()));
}
#[no_mangle]
pub unsafe extern "C" fn mju_error_s(msg: *const c_char, text: *const c_char) {
    error(&format1(&cstr(msg), &cstr(text)));
}
#[no_mangle]
pub unsafe extern "C" fn mju_warning_s(msg: *const c_char, text: *const c_char) {
    warning(&format1(&cstr(msg), &cstr(text)));
}

#[no_mangle]
pub extern "C" fn mju_clearHandlers() {
    // SAFETY: plain stores to the handler globals, as the C API does.
    unsafe {
        mju_user_error = None;
        mju_user_warning = None;
        mju_user_malloc = None;
        mju_user_free = None;
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_writeLog(kind: *const c_char, msg: *const c_char) {
    write_log(&cstr(kind), &cstr(msg));
}

/// Allocates through the user allocator, or 64-byte aligned and padded to 64 bytes.
pub fn malloc(size: usize) -> *mut c_void {
    // SAFETY: C allocation; the result is checked for NULL.
    let ptr = unsafe {
        if let Some(f) = mju_user_malloc {
            f(size)
        } else {
            let padded = size.div_ceil(64).max(1) * 64;
            let mut p: *mut c_void = std::ptr::null_mut();
            if libc::posix_memalign(&mut p, 64, padded) != 0 {
                std::ptr::null_mut()
            } else {
                p
            }
        }
    };
    if ptr.is_null() {
        error("Could not allocate memory");
    }
    ptr
}

/// Allocates zeroed memory: through the user allocator and then cleared, else with `calloc`,
/// whose large blocks come from fresh pages never touched until used (a model's stack may span
/// gigabytes the simulation never reaches; 16-byte alignment).
pub fn malloc_zeroed(size: usize) -> *mut c_void {
    // SAFETY: C allocation; the result is checked for NULL and cleared to its full size.
    let ptr = unsafe {
        let user = mju_user_malloc;
        if user.is_some() {
            let p = malloc(size);
            if !p.is_null() {
                std::ptr::write_bytes(p as *mut u8, 0, size);
            }
            return p;
        }
        libc::calloc(size.max(1), 1)
    };
    if ptr.is_null() {
        error("Could not allocate memory");
    }
    ptr
}

/// Frees memory from `malloc` or `malloc_zeroed`, through the user deallocator when set.
///
/// # Safety
/// `ptr` is NULL or came from `malloc` or `malloc_zeroed` and was not freed.
pub unsafe fn free(ptr: *mut c_void) {
    if ptr.is_null() {
        return;
    }
    if let Some(f) = mju_user_free {
        f(ptr)
    } else {
        libc::free(ptr)
    }
}

#[no_mangle]
pub extern "C" fn mju_malloc(size: usize) -> *mut c_void {
    malloc(size)
}
#[no_mangle]
pub unsafe extern "C" fn mju_free(ptr: *mut c_void) {
    free(ptr)
}
