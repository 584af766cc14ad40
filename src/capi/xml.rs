//! C entry points of the MJCF loader: `mj_loadXML`, `mj_saveLastXML`, `mj_printSchema`.

use crate::abi::*;
use crate::loader::xml;
use crate::xml::schema;
use std::os::raw::{c_char, c_int};

/// Copies `msg` into the caller's error buffer (truncated, NUL-terminated).
pub unsafe fn set_error(error: *mut c_char, error_sz: c_int, msg: &str) {
    if error.is_null() || error_sz <= 0 {
        return;
    }
    let n = msg.len().min(error_sz as usize - 1);
    std::ptr::copy_nonoverlapping(msg.as_ptr() as *const c_char, error, n);
    *error.add(n) = 0;
}

#[no_mangle]
pub unsafe extern "C" fn mj_loadXML(
    filename: *const c_char,
    vfs: *const mjVFS,
    error: *mut c_char,
    error_sz: c_int,
) -> *mut mjModel {
    if filename.is_null() {
        set_error(error, error_sz, "mjParseXML: filename argument required\n");
        return std::ptr::null_mut();
    }
    let fname = std::ffi::CStr::from_ptr(filename).to_string_lossy();
    let files = super::io::vfs_files(vfs);
    match std::panic::catch_unwind(|| xml::load(&fname, files.as_ref())) {
        Ok(Ok(loaded)) => {
            set_error(error, error_sz, &loaded.warning);
            xml::remember(loaded).into_raw()
        }
        Ok(Err(msg)) => {
            set_error(error, error_sz, &msg);
            std::ptr::null_mut()
        }
        Err(_) => {
            set_error(error, error_sz, "Error: internal error in mj_loadXML");
            std::ptr::null_mut()
        }
    }
}

/// Writes the last loaded model as MJCF; 1 on success, 0 with the error text otherwise.
#[no_mangle]
pub unsafe extern "C" fn mj_saveLastXML(
    filename: *const c_char,
    m: *const mjModel,
    error: *mut c_char,
    error_sz: c_int,
) -> c_int {
    let name = super::errmem::cstr(filename);
    match xml::save_last(&name, m.as_ref()) {
        Ok(()) => {
            set_error(error, error_sz, "");
            1
        }
        Err(msg) => {
            set_error(error, error_sz, &msg);
            0
        }
    }
}

/// Forgets the last loaded model.
#[no_mangle]
pub unsafe extern "C" fn mj_freeLastXML() {
    xml::forget();
}

/// The MJCF schema as text or HTML: written to `filename` and/or copied (truncated) to
/// `buffer`; returns its length.
#[no_mangle]
pub unsafe extern "C" fn mj_printSchema(
    filename: *const c_char,
    buffer: *mut c_char,
    buffer_sz: c_int,
    flg_html: c_int,
    flg_pad: c_int,
) -> c_int {
    let text = schema::print(flg_html != 0, flg_pad != 0);
    if !filename.is_null() {
        let name = std::ffi::CStr::from_ptr(filename).to_string_lossy();
        let _ = std::fs::write(name.as_ref(), &text);
    }
    if !buffer.is_null() && buffer_sz > 0 {
        // strncpy then terminate at the last byte, as 2.2.2 does
        let n = text.len().min(buffer_sz as usize);
        std::ptr::copy_nonoverlapping(text.as_ptr() as *const c_char, buffer, n);
        if n < buffer_sz as usize {
            std::ptr::write_bytes(buffer.add(n), 0, buffer_sz as usize - n);
        }
        *buffer.add(buffer_sz as usize - 1) = 0;
    }
    text.len() as c_int
}
