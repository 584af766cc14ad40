//! C entry points of the MJCF loader: `mj_loadXML`.

use crate::abi::alloc::make_model;
use crate::abi::view::ModelMut;
use crate::abi::*;
use crate::capi::errmem;
use crate::compiler;
use crate::xml::{include, reader, schema, tree};
use std::os::raw::{c_char, c_int};

/// Copies `msg` into the caller's error buffer (truncated, NUL-terminated).
unsafe fn set_error(error: *mut c_char, error_sz: c_int, msg: &str) {
    if error.is_null() || error_sz <= 0 {
        return;
    }
    let n = msg.len().min(error_sz as usize - 1);
    std::ptr::copy_nonoverlapping(msg.as_ptr() as *const c_char, error, n);
    *error.add(n) = 0;
}

/// File contents from the VFS (name without its path, as mj_findFileVFS matches) or from disk.
unsafe fn load_text(filename: &str, vfs: *const mjVFS) -> Result<Vec<u8>, String> {
    if !vfs.is_null() {
        if let Ok(cname) = std::ffi::CString::new(filename) {
            let id = crate::capi::io::mj_findFileVFS(vfs, cname.as_ptr());
            let v = &*vfs;
            if id >= 0 && (id as usize) < v.filedata.len() && !v.filedata[id as usize].is_null() {
                let size = v.filesize[id as usize].max(0) as usize;
                return Ok(
                    std::slice::from_raw_parts(v.filedata[id as usize] as *const u8, size).to_vec(),
                );
            }
        }
    }
    std::fs::read(filename).map_err(|_| {
        format!(
            "XML parse error 3:\nError=XML_ERROR_FILE_NOT_FOUND ErrorID=3 (0x3) Line number=0: filename={filename}\n"
        )
    })
}

/// The model file (and its includes) to a model description.
unsafe fn parse(fname: &str, vfs: *const mjVFS) -> Result<compiler::spec::ModelSpec, String> {
    let bytes = load_text(fname, vfs)?;
    let text = String::from_utf8_lossy(&bytes);
    let mut root = tree::parse(text.trim_end_matches('\0'))?;
    if root.name.eq_ignore_ascii_case("robot") {
        return Err("XML Error: URDF models are not supported by this loader yet".into());
    }
    if !root.name.eq_ignore_ascii_case("mujoco") {
        return Err(format!(
            "XML Error: Unrecognized XML model type: '{}'",
            root.name
        ));
    }
    let mut included = vec![fname.to_string()];
    let dir = include::file_dir(fname);
    include::expand(
        &mut root,
        &dir,
        &mut |f: &str| load_text(f, vfs),
        &mut included,
    )?;
    schema::check(&root)?;
    let mut spec = reader::read(&root)?;
    compiler::image::load_files(&mut spec, &dir, &mut |f: &str| load_text(f, vfs).ok());
    Ok(spec)
}

thread_local! {
    /// Last warning raised while a model compiles (2.2.2 returns it in the error buffer).
    static COMPILE_WARNING: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
}

unsafe extern "C" fn keep_warning(msg: *const c_char) {
    let text = crate::capi::errmem::cstr(msg).into_owned();
    COMPILE_WARNING.with(|w| *w.borrow_mut() = text);
}

thread_local! {
    /// Errors raised by the engine during the test step (ignored, see `test_step`).
    static STEP_ERROR: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
}

unsafe extern "C" fn keep_error(msg: *const c_char) {
    let text = crate::capi::errmem::cstr(msg).into_owned();
    STEP_ERROR.with(|w| *w.borrow_mut() = text);
}

/// One step from the reset state, as 2.2.2's compiler takes: its warnings (unstable
/// simulation, singular inertia) reach the error buffer. Engine errors are not fatal here, so a
/// feature the engine lacks does not stop a model from loading.
unsafe fn test_step(m: *mut mjModel) {
    let saved = errmem::_mjPRIVATE__get_tls_error_fn();
    errmem::_mjPRIVATE__set_tls_error_fn(Some(keep_error));
    let d = crate::capi::io::mj_makeData(m);
    if !d.is_null() {
        crate::capi::io::mj_resetData(m, d);
        crate::capi::engine::mj_step(m, d);
        crate::capi::io::mj_deleteData(d);
    }
    errmem::_mjPRIVATE__set_tls_error_fn(saved);
    STEP_ERROR.with(|w| w.borrow_mut().clear());
}

/// Parses, compiles and allocates; returns the model or the error text.
unsafe fn load(filename: *const c_char, vfs: *const mjVFS) -> Result<*mut mjModel, String> {
    if filename.is_null() {
        return Err("mjParseXML: filename argument required\n".into());
    }
    let fname = std::ffi::CStr::from_ptr(filename)
        .to_string_lossy()
        .into_owned();
    let spec = parse(&fname, vfs)?;
    // from here on, as in 2.2.2's compiler, warnings go to the error buffer
    errmem::_mjPRIVATE__set_tls_warning_fn(Some(keep_warning));
    // 2.2.2's compiler seeds the C generator (later sensor noise draws from it)
    libc::srand(123);
    // SAFETY: all-zero bits are a valid mjModel header (null pointers, zero sizes).
    let blank: mjModel = std::mem::zeroed();
    let compiled = compiler::compile(spec, blank).map_err(|e| e.render())?;
    let m = make_model(&compiled.header).map_err(|e| format!("Error: {e}"))?;
    (*m).opt = compiled.option;
    (*m).vis = compiled.visual;
    {
        // SAFETY: m was just made by make_model and is not aliased.
        let mut mm = ModelMut::new(&mut *m);
        compiler::fill(&compiled, &mut mm);
    }
    // 2.2.2 allocates the model's mjData before mj_setConst and fails the load if it cannot
    match crate::abi::alloc::alloc_data(&*m) {
        Ok(d) => crate::abi::alloc::delete_data(d),
        Err(_) => {
            crate::abi::alloc::delete_model(m);
            return Err("Error: could not create mjData".into());
        }
    }
    if let Err(e) = compiler::set_const(&mut *m) {
        crate::abi::alloc::delete_model(m);
        return Err(format!("Error: engine error: {e}"));
    }
    {
        // SAFETY: as above; no other view of m is alive.
        let mut mm = ModelMut::new(&mut *m);
        compiler::auto_spring_damper(&compiled, &mut mm);
    }
    compiler::finish(&compiled, &mut (*m).stat);
    // SAFETY: m came from make_model.
    if let Some(msg) = crate::abi::validate::validate_references(crate::abi::view::Model::new(&*m))
    {
        crate::abi::alloc::delete_model(m);
        return Err(format!("Error: {msg}"));
    }
    test_step(m);
    Ok(m)
}

#[no_mangle]
pub unsafe extern "C" fn mj_loadXML(
    filename: *const c_char,
    vfs: *const mjVFS,
    error: *mut c_char,
    error_sz: c_int,
) -> *mut mjModel {
    COMPILE_WARNING.with(|w| w.borrow_mut().clear());
    let saved = errmem::_mjPRIVATE__get_tls_warning_fn();
    let result = std::panic::catch_unwind(|| load(filename, vfs));
    errmem::_mjPRIVATE__set_tls_warning_fn(saved);
    match result {
        Ok(Ok(m)) => {
            let warning = COMPILE_WARNING.with(|w| std::mem::take(&mut *w.borrow_mut()));
            set_error(error, error_sz, &warning);
            m
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
