//! Text dumps of models.

use super::errmem::{c_stdout, cstr, warning};
use crate::abi::*;
use crate::engine::print::{model_text, NumberFormat, FLOAT_FORMAT};
use std::os::raw::c_char;

/// Sends a dump to a file, or to C's stdout when no file is named.
unsafe fn emit(filename: *const c_char, text: &str, what: &str) {
    if filename.is_null() {
        c_stdout(text);
    } else {
        let name = cstr(filename);
        if std::fs::write(&*name, text).is_err() {
            warning(&format!("Could not open file '{name}' for writing {what}"));
        }
    }
}

fn number_format(float_format: *const c_char) -> NumberFormat {
    if float_format.is_null() {
        warning("WARNING: Received invalid float_format. Using default instead.");
        return NumberFormat::default_format();
    }
    // SAFETY: non-NULL C string from the caller.
    match NumberFormat::new(&unsafe { cstr(float_format) }) {
        Ok(f) => f,
        Err(e) => {
            warning(&e);
            warning("WARNING: Received invalid float_format. Using default instead.");
            NumberFormat::default_format()
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_printFormattedModel(
    m: *const mjModel,
    filename: *const c_char,
    float_format: *const c_char,
) {
    let Some(m) = m.as_ref() else {
        return;
    };
    let fmt = number_format(float_format);
    let text = super::guard("mj_printModel", None, || {
        Ok(Some(model_text(view::Model::new(m), &fmt, "2.2.2")))
    });
    if let Some(text) = text {
        emit(filename, &text, "mjModel");
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_printModel(m: *const mjModel, filename: *const c_char) {
    let f = std::ffi::CString::new(FLOAT_FORMAT).unwrap();
    mj_printFormattedModel(m, filename, f.as_ptr());
}

#[no_mangle]
pub unsafe extern "C" fn mj_printFormattedData(
    m: *const mjModel,
    d: *mut mjData,
    filename: *const c_char,
    float_format: *const c_char,
) {
    let (Some(m), Some(d)) = (m.as_ref(), d.as_mut()) else {
        return;
    };
    let fmt = number_format(float_format);
    if d.pstack != 0 {
        super::errmem::error("Attempting to print mjData when stack is in use");
        return;
    }
    // 2.2.2 takes nv*nv of stack for its dense matrices before printing the sizes.
    let scratch = m.nv.saturating_mul(m.nv);
    if scratch > d.nstack {
        super::errmem::error("Stack overflow");
        return;
    }
    d.pstack = scratch;
    d.maxuse_stack = d.maxuse_stack.max(scratch);
    let text = super::guard("mj_printData", None, || {
        let dv = view::Data::new(m, &mut *d);
        Ok(Some(crate::engine::print::data_text(
            view::Model::new(m),
            &dv,
            &fmt,
        )))
    });
    d.pstack = 0;
    if let Some(text) = text {
        emit(filename, &text, "mjModel");
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_printData(m: *const mjModel, d: *mut mjData, filename: *const c_char) {
    let f = std::ffi::CString::new(FLOAT_FORMAT).unwrap();
    mj_printFormattedData(m, d, filename, f.as_ptr());
}
