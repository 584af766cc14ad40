//! C entry points of the MJCF loader: `mj_loadXML`.

use crate::abi::alloc::make_model;
use crate::abi::view::ModelMut;
use crate::abi::*;
use crate::capi::errmem;
use crate::compiler;
use crate::xml::{include, reader, schema, tree, urdf, writer};
use std::os::raw::{c_char, c_int};
use std::sync::Mutex;

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

/// The last model loaded, as 2.2.2 keeps it for `mj_saveLastXML`: its MJCF tree and the
/// fingerprint of the model compiled from it.
struct LastModel {
    mjcf: tree::Element,
    digest: [u64; 2],
}

static LAST_MODEL: Mutex<Option<LastModel>> = Mutex::new(None);

/// The model file (and its includes) to its MJCF tree and model description.
unsafe fn parse(
    fname: &str,
    vfs: *const mjVFS,
) -> Result<(tree::Element, compiler::spec::ModelSpec), String> {
    let bytes = load_text(fname, vfs)?;
    let text = String::from_utf8_lossy(&bytes);
    let mut root = tree::parse(text.trim_end_matches('\0'))?;
    if root.name.eq_ignore_ascii_case("robot") {
        // 2.2.2 reads URDF without the MJCF schema check
        let mjcf = urdf::convert(&root)?;
        let spec = reader::read(&mjcf)?;
        return Ok((mjcf, spec));
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
    Ok((root, spec))
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
    // the first error ends 2.2.2's test step
    STEP_ERROR.with(|w| {
        if w.borrow().is_empty() {
            *w.borrow_mut() = text;
        }
    });
}

/// One step from the reset state, as 2.2.2's compiler takes: its warnings (unstable
/// simulation, singular inertia) reach the error buffer, and an engine error rejects the model
/// (Err: the message). A feature this engine lacks ("not implemented") does not stop a model
/// from loading: the user meets it at the first mj_step.
unsafe fn test_step(m: *mut mjModel, d: *mut mjData) -> Result<(), String> {
    let saved = errmem::_mjPRIVATE__get_tls_error_fn();
    errmem::_mjPRIVATE__set_tls_error_fn(Some(keep_error));
    crate::capi::io::mj_resetData(m, d);
    crate::capi::engine::mj_step(m, d);
    errmem::_mjPRIVATE__set_tls_error_fn(saved);
    let error = STEP_ERROR.with(|w| std::mem::take(&mut *w.borrow_mut()));
    if error.is_empty() || error.contains("not implemented") {
        Ok(())
    } else {
        Err(error)
    }
}

/// The compiler's steps that run the engine on `d`: constants, spring-dampers, length ranges,
/// statistics overrides, reference checks and the test step.
///
/// # Safety
/// `m` is a valid model, not aliased; `d` was made for it.
unsafe fn finish_compile(
    m: *mut mjModel,
    d: *mut mjData,
    compiled: &compiler::Compiled,
) -> Result<(), String> {
    crate::capi::engine::set_const_views(&mut *m, &mut *d)
        .map_err(|e| format!("Error: engine error: {e}"))?;
    {
        // SAFETY: no other view of m is alive.
        let mut mm = ModelMut::new(&mut *m);
        compiler::auto_spring_damper(compiled, &mut mm);
    }
    crate::capi::lengthrange::compile_length_ranges(m, d, &compiled.lropt)
        .map_err(|e| format!("Error: {e}"))?;
    compiler::finish(compiled, &mut (*m).stat);
    if let Some(msg) = crate::abi::validate::validate_references(crate::abi::view::Model::new(&*m))
    {
        return Err(format!("Error: {msg}"));
    }
    test_step(m, d).map_err(|e| format!("Error: engine error: {e}"))
}

/// Parses, compiles and allocates; returns the model or the error text.
unsafe fn load(filename: *const c_char, vfs: *const mjVFS) -> Result<*mut mjModel, String> {
    if filename.is_null() {
        return Err("mjParseXML: filename argument required\n".into());
    }
    let fname = std::ffi::CStr::from_ptr(filename)
        .to_string_lossy()
        .into_owned();
    let (mjcf, spec) = parse(&fname, vfs)?;
    // from here on, as in 2.2.2's compiler, warnings go to the error buffer
    errmem::_mjPRIVATE__set_tls_warning_fn(Some(keep_warning));
    // 2.2.2's compiler seeds the C generator (later sensor noise draws from it)
    crate::runtime::random::seed(123);
    // SAFETY: all-zero bits are a valid mjModel header (null pointers, zero sizes).
    let blank: mjModel = std::mem::zeroed();
    let mut compiled = compiler::compile(spec, blank).map_err(|e| e.render())?;
    let m = make_model(&compiled.header).map_err(|e| format!("Error: {e}"))?;
    (*m).opt = compiled.option;
    (*m).vis = compiled.visual;
    {
        // SAFETY: m was just made by make_model and is not aliased.
        let mut mm = ModelMut::new(&mut *m);
        compiler::fill(&compiled, &mut mm);
    }
    compiler::release_bulk(&mut compiled);
    // as 2.2.2's compiler: one mjData serves mj_setConst, the length ranges and the test step
    let d = match crate::capi::io::new_data(&*m) {
        Ok(d) => d,
        Err(_) => {
            crate::abi::alloc::delete_model(m);
            return Err("Error: could not create mjData".into());
        }
    };
    let finished = finish_compile(m, d, &compiled);
    crate::abi::alloc::delete_data(d);
    if let Err(e) = finished {
        crate::abi::alloc::delete_model(m);
        return Err(e);
    }
    if let Ok(mut last) = LAST_MODEL.lock() {
        *last = Some(LastModel {
            mjcf,
            digest: crate::abi::mjb::digest(&*m),
        });
    }
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

/// Writes the last loaded model as MJCF; 1 on success, 0 with the error text otherwise.
#[no_mangle]
pub unsafe extern "C" fn mj_saveLastXML(
    filename: *const c_char,
    m: *const mjModel,
    error: *mut c_char,
    error_sz: c_int,
) -> c_int {
    let text = match LAST_MODEL.lock() {
        Ok(last) => last.as_ref().map(|l| {
            // 2.2.2 copies values the user changed in m back into the file; we write the
            // model as loaded, so a changed (or another) model is refused
            let same = m
                .as_ref()
                .is_none_or(|m| crate::abi::mjb::digest(m) == l.digest);
            (writer::to_text(&l.mjcf), same)
        }),
        Err(_) => None,
    };
    let Some((text, same)) = text else {
        set_error(error, error_sz, "No XML model loaded");
        return 0;
    };
    if !same {
        set_error(
            error,
            error_sz,
            "mj_saveLastXML: saving a model that differs from the last loaded one is not implemented",
        );
        return 0;
    }
    let name = if filename.is_null() {
        String::new()
    } else {
        std::ffi::CStr::from_ptr(filename)
            .to_string_lossy()
            .into_owned()
    };
    if std::fs::write(&name, text).is_err() {
        set_error(error, error_sz, "File not found");
        return 0;
    }
    set_error(error, error_sz, "");
    1
}

/// Forgets the last loaded model.
#[no_mangle]
pub unsafe extern "C" fn mj_freeLastXML() {
    if let Ok(mut last) = LAST_MODEL.lock() {
        *last = None;
    }
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
