//! Text dumps of models.

use super::errmem::{c_stdout, cstr, warning};
use crate::abi::*;
use crate::engine::print::{model_text, NumberWriter, FLOAT_FORMAT};
use std::ffi::CString;
use std::os::raw::c_char;

/// printf-style formatting of one number with a validated single-conversion format.
pub struct NumberFormat(CString);

impl NumberFormat {
    /// The format if it is a valid single float conversion (2.2.2's rules), else the default.
    pub fn new(format: &str) -> Result<Self, String> {
        validate_float_format(format)?;
        Ok(NumberFormat(
            CString::new(format).map_err(|_| "bad format")?,
        ))
    }

    pub fn default_format() -> Self {
        NumberFormat(CString::new(FLOAT_FORMAT).unwrap())
    }

    fn format(&self, out: &mut String, v: f64) {
        let mut buf = [0u8; 512];
        // SAFETY: the format was validated to take exactly one double.
        let n = unsafe {
            libc::snprintf(
                buf.as_mut_ptr() as *mut libc::c_char,
                buf.len(),
                self.0.as_ptr(),
                v,
            )
        };
        let n = (n.max(0) as usize).min(buf.len() - 1);
        out.push_str(&String::from_utf8_lossy(&buf[..n]));
    }
}

/// 2.2.2's check of a user float format: `%`, flags, width, precision, optional `L`, one of fgGeE.
pub fn validate_float_format(f: &str) -> Result<(), String> {
    if f.len() > 20 {
        return Err("Format string longer than limit of 20.".into());
    }
    let b = f.as_bytes();
    let mut i = 0;
    if b.first() != Some(&b'%') {
        return Err("Format string must start with '%'.".into());
    }
    i += 1;
    let mut seen = [0; 5];
    while let Some(k) = b.get(i).and_then(|c| b"-+ #0".iter().position(|x| x == c)) {
        seen[k] += 1;
        if seen[k] > 1 {
            return Err("Format string contains repeated flag.".into());
        }
        i += 1;
    }
    while b.get(i).is_some_and(|c| c.is_ascii_digit()) {
        i += 1;
    }
    if b.get(i) == Some(&b'.') {
        i += 1;
        while b.get(i).is_some_and(|c| c.is_ascii_digit()) {
            i += 1;
        }
    }
    if b.get(i) == Some(&b'L') {
        i += 1;
    }
    if !b.get(i).is_some_and(|c| b"fgGeE".contains(c)) {
        return Err("Format string specifier must be one of \"fgGeE\".".into());
    }
    i += 1;
    if i == b.len() {
        Ok(())
    } else {
        Err(format!(
            "Unable to match format string {f} with expected pattern for a single float."
        ))
    }
}

impl NumberWriter for NumberFormat {
    fn real(&self, out: &mut String, v: f64) {
        self.format(out, v)
    }
}

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
