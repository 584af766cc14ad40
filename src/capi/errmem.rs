//! C entry points of the runtime layer: errors, warnings, log, memory, thread-local hooks.

use crate::runtime::{memory, message};
use std::cell::Cell;
use std::ffi::CStr;
use std::os::raw::{c_char, c_int, c_void};

pub use crate::runtime::memory::{free, malloc, malloc_zeroed, mju_user_free, mju_user_malloc};
pub use crate::runtime::message::{
    c_stdout, c_stdout_flush, error, mju_user_error, mju_user_warning, truncated, warning,
    write_log, MsgBuf, MsgHandler,
};

thread_local! {
    static XML_PRECISION: Cell<c_int> = const { Cell::new(0) };
}

#[no_mangle]
pub extern "C" fn _mjPRIVATE__get_tls_error_fn() -> MsgHandler {
    message::tls_error_handler()
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__set_tls_error_fn(h: MsgHandler) {
    message::set_tls_error_handler(h)
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__get_tls_warning_fn() -> MsgHandler {
    message::tls_warning_handler()
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__set_tls_warning_fn(h: MsgHandler) {
    message::set_tls_warning_handler(h)
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__get_xml_precision() -> c_int {
    XML_PRECISION.with(|c| c.get())
}
#[no_mangle]
pub extern "C" fn _mjPRIVATE__set_xml_precision(p: c_int) {
    XML_PRECISION.with(|c| c.set(p))
}

/// Reads a C string argument; NULL reads as empty.
pub unsafe fn cstr<'a>(s: *const c_char) -> std::borrow::Cow<'a, str> {
    if s.is_null() {
        "".into()
    } else {
        CStr::from_ptr(s).to_string_lossy()
    }
}

/// Formats a printf-style message with one `%d`/`%i` or `%s` argument, cut as 2.2.2's
/// 1000-byte buffer cuts it.
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
    out.truncate(truncated(&out).len());
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
    message::clear_handlers();
    memory::clear_handlers();
}

#[no_mangle]
pub unsafe extern "C" fn mju_writeLog(kind: *const c_char, msg: *const c_char) {
    write_log(&cstr(kind), &cstr(msg));
}

#[no_mangle]
pub extern "C" fn mju_malloc(size: usize) -> *mut c_void {
    malloc(size)
}
#[no_mangle]
pub unsafe extern "C" fn mju_free(ptr: *mut c_void) {
    free(ptr)
}
