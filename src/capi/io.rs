//! Model and data memory, MJB files, the virtual file system, defaults and version.

use super::errmem::{cstr, error, free, malloc, warning};
use super::guard;
use crate::abi::owned::ModelBox;
use crate::abi::view::EngineError;
use crate::abi::*;
use crate::engine::support;
use crate::loader::{self, vfs, vfs::Vfs};
use std::os::raw::{c_char, c_int, c_uchar, c_void};

#[no_mangle]
pub extern "C" fn mj_version() -> c_int {
    222
}

#[no_mangle]
pub extern "C" fn mj_versionString() -> *const c_char {
    c"2.2.2".as_ptr()
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultLROpt(opt: *mut mjLROpt) {
    if let Some(opt) = opt.as_mut() {
        *opt = alloc::default_lropt();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultSolRefImp(solref: *mut mjtNum, solimp: *mut mjtNum) {
    if !solref.is_null() {
        std::ptr::copy_nonoverlapping(alloc::default_solref().as_ptr(), solref, 2);
    }
    if !solimp.is_null() {
        std::ptr::copy_nonoverlapping(alloc::default_solimp().as_ptr(), solimp, 5);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultOption(opt: *mut mjOption) {
    if let Some(opt) = opt.as_mut() {
        *opt = alloc::default_option();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultVisual(vis: *mut mjVisual) {
    if let Some(vis) = vis.as_mut() {
        *vis = alloc::default_visual();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_copyModel(dest: *mut mjModel, src: *const mjModel) -> *mut mjModel {
    let Some(src) = src.as_ref() else {
        error("mj_copyModel: NULL source model");
        return std::ptr::null_mut();
    };
    guard("mj_copyModel", std::ptr::null_mut(), || {
        alloc::copy_model(dest, src).map_err(EngineError)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteModel(m: *mut mjModel) {
    alloc::delete_model(m)
}

#[no_mangle]
pub unsafe extern "C" fn mj_sizeModel(m: *const mjModel) -> c_int {
    m.as_ref().map_or(0, alloc::size_model)
}

#[no_mangle]
pub unsafe extern "C" fn mj_makeData(m: *const mjModel) -> *mut mjData {
    if m.is_null() {
        error("mj_makeData: NULL model");
        return std::ptr::null_mut();
    }
    // only read: the model is the caller's, never freed here
    let m = std::mem::ManuallyDrop::new(ModelBox::from_raw(m as *mut mjModel));
    match loader::new_data(&m) {
        Ok(d) => d.into_raw(),
        Err(e) if e.starts_with("Invalid") => {
            warning(&e);
            std::ptr::null_mut()
        }
        Err(e) => {
            error(&e);
            std::ptr::null_mut()
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_copyData(
    dest: *mut mjData,
    m: *const mjModel,
    src: *const mjData,
) -> *mut mjData {
    let (Some(m), Some(src)) = (m.as_ref(), src.as_ref()) else {
        error("mj_copyData: NULL argument");
        return std::ptr::null_mut();
    };
    guard("mj_copyData", std::ptr::null_mut(), || {
        alloc::copy_data(dest, m, src).map_err(EngineError)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetData(m: *const mjModel, d: *mut mjData) {
    if let (Some(m), Some(d)) = (m.as_ref(), d.as_mut()) {
        support::reset_data(&view::Model::new(m), &mut view::Data::new(m, d));
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetDataDebug(
    m: *const mjModel,
    d: *mut mjData,
    debug_value: c_uchar,
) {
    if let (Some(m), Some(d)) = (m.as_ref(), d.as_mut()) {
        alloc::fill_buffer(d, debug_value);
        let mut dv = view::Data::new(m, d);
        support::clear_header(&mut dv);
        support::reset_state(&view::Model::new(m), &mut dv);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetDataKeyframe(m: *const mjModel, d: *mut mjData, key: c_int) {
    if let (Some(m), Some(d)) = (m.as_ref(), d.as_mut()) {
        support::reset_data_keyframe(&view::Model::new(m), &mut view::Data::new(m, d), key);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteData(d: *mut mjData) {
    alloc::delete_data(d)
}

#[no_mangle]
pub unsafe extern "C" fn mj_stackAlloc(d: *mut mjData, size: c_int) -> *mut mjtNum {
    let Some(d) = d.as_mut() else {
        return std::ptr::null_mut();
    };
    if size <= 0 {
        return std::ptr::null_mut();
    }
    if d.pstack.saturating_add(size) > d.nstack {
        error("Stack overflow");
        return std::ptr::null_mut();
    }
    let p = d.stack.add(d.pstack as usize);
    d.pstack += size;
    d.maxuse_stack = d.maxuse_stack.max(d.pstack);
    p
}

/// The files of a C VFS, borrowed for the loader.
///
/// # Safety
/// `vfs` is NULL or a valid mjVFS whose file slots hold `filesize` bytes (or NULL).
pub unsafe fn vfs_files<'a>(vfs: *const mjVFS) -> Option<Vfs<'a>> {
    let v = vfs.as_ref()?;
    let mut files = Vfs::new();
    for i in 0..v.nfile.clamp(0, mjMAXVFS as i32) as usize {
        let p = v.filedata[i] as *const u8;
        let data =
            (!p.is_null()).then(|| std::slice::from_raw_parts(p, v.filesize[i].max(0) as usize));
        files.push(vfs_name(v, i), data);
    }
    Some(files)
}

#[no_mangle]
pub unsafe extern "C" fn mj_saveModel(
    m: *const mjModel,
    filename: *const c_char,
    buffer: *mut c_void,
    buffer_sz: c_int,
) {
    let Some(m) = m.as_ref() else {
        return;
    };
    if !buffer.is_null() {
        let image = mjb::save(m);
        if image.len() > buffer_sz.max(0) as usize {
            error("Attempting to write outside model buffer");
            return;
        }
        std::ptr::copy_nonoverlapping(image.as_ptr(), buffer as *mut u8, image.len());
    } else if !filename.is_null() {
        let name = cstr(filename);
        // streamed to the file, as 2.2.2 writes it (no second copy of a large model in memory)
        let written = std::fs::File::create(&*name).and_then(|f| {
            let mut w = std::io::BufWriter::new(f);
            let mut result = Ok(());
            mjb::write_parts(m, |b| {
                if result.is_ok() {
                    result = std::io::Write::write_all(&mut w, b);
                }
            });
            result.and_then(|_| std::io::Write::flush(&mut w))
        });
        if written.is_err() {
            warning(&format!("Could not open file '{name}'"));
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_loadModel(filename: *const c_char, vfs: *const mjVFS) -> *mut mjModel {
    let name = cstr(filename);
    super::guard("mj_loadModel", std::ptr::null_mut(), || {
        Ok(
            match loader::mjb::load_file(&name, vfs_files(vfs).as_ref()) {
                Ok(m) => m.into_raw(),
                Err(mjb::LoadError::Warning(e)) => {
                    warning(&e);
                    std::ptr::null_mut()
                }
                Err(mjb::LoadError::Error(e)) => {
                    error(&e);
                    std::ptr::null_mut()
                }
            },
        )
    })
}

fn vfs_name(vfs: &mjVFS, i: usize) -> &[u8] {
    let raw = &vfs.filename[i];
    let len = raw.iter().position(|&c| c == 0).unwrap_or(raw.len());
    // SAFETY: c_char and u8 have the same size and alignment.
    unsafe { std::slice::from_raw_parts(raw.as_ptr() as *const u8, len) }
}

fn vfs_find(vfs: &mjVFS, filename: &str) -> Option<usize> {
    let key = vfs::key(filename).ok()?;
    (0..vfs.nfile.clamp(0, mjMAXVFS as i32) as usize).find(|&i| vfs_name(vfs, i) == key.as_bytes())
}

/// Adds `data` under `filename`: 0 ok, 1 full, 2 repeated name.
unsafe fn vfs_add(vfs: &mut mjVFS, filename: &str, data: &[u8], size: usize) -> c_int {
    if vfs.nfile >= mjMAXVFS as i32 - 1 {
        return 1;
    }
    let key = match vfs::key(filename) {
        Ok(k) => k,
        Err(e) => {
            error(e);
            return -1;
        }
    };
    if vfs_find(vfs, filename).is_some() {
        return 2;
    }
    let i = vfs.nfile as usize;
    let buf = malloc(size.max(1)) as *mut u8;
    if buf.is_null() {
        return -1;
    }
    std::ptr::write_bytes(buf, 0, size.max(1));
    std::ptr::copy_nonoverlapping(data.as_ptr(), buf, data.len().min(size));
    vfs.filename[i] = [0; mjMAXVFSNAME];
    for (j, b) in key.bytes().enumerate() {
        vfs.filename[i][j] = b as c_char;
    }
    vfs.filedata[i] = buf as *mut c_void;
    vfs.filesize[i] = size as c_int;
    vfs.nfile += 1;
    0
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultVFS(vfs: *mut mjVFS) {
    if !vfs.is_null() {
        std::ptr::write_bytes(vfs, 0, 1);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_addFileVFS(
    vfs: *mut mjVFS,
    directory: *const c_char,
    filename: *const c_char,
) -> c_int {
    let Some(vfs) = vfs.as_mut() else {
        return -1;
    };
    // 2.2.2 reads `filename` as given (relative to the working directory): `directory` is not
    // used, and programs written for 2.2.2 rely on that
    let _ = directory;
    let name = cstr(filename);
    if vfs.nfile >= mjMAXVFS as i32 - 1 {
        return 1;
    }
    if vfs_find(vfs, &name).is_some() {
        return 2;
    }
    match file_to_memory(&name) {
        Some(data) => vfs_add(vfs, &name, &data, data.len()),
        None => -1,
    }
}

/// A whole file, read as 2.2.2's mju_fileToMemory reads it, with its warnings (a directory
/// opens, and its size does not fit an int).
pub fn file_to_memory(name: &str) -> Option<Vec<u8>> {
    use std::io::{Read, Seek, SeekFrom};
    let mut f = std::fs::File::open(name).ok()?;
    let size = match f.seek(SeekFrom::End(0)) {
        Ok(n) if n > i32::MAX as u64 => {
            warning(&format!(
                "File size over 2GB is not supported. File: '{name}'"
            ));
            return None;
        }
        Ok(n) => n as usize,
        Err(_) => {
            warning(&format!("Failed to calculate size for '{name}'"));
            return None;
        }
    };
    let mut buf = Vec::with_capacity(size);
    let read = f
        .seek(SeekFrom::Start(0))
        .and_then(|_| f.take(size as u64).read_to_end(&mut buf));
    if read.is_err() {
        warning(&format!("Read error while reading '{name}'"));
        return None;
    }
    Some(buf)
}

#[no_mangle]
pub unsafe extern "C" fn mj_makeEmptyFileVFS(
    vfs: *mut mjVFS,
    filename: *const c_char,
    filesize: c_int,
) -> c_int {
    let Some(vfs) = vfs.as_mut() else {
        return -1;
    };
    if vfs.nfile >= mjMAXVFS as i32 - 1 {
        return 1;
    }
    if filesize <= 0 {
        error("mj_makeEmptyFileVFS expects positive filesize");
        return -1;
    }
    vfs_add(vfs, &cstr(filename), &[], filesize as usize)
}

#[no_mangle]
pub unsafe extern "C" fn mj_findFileVFS(vfs: *const mjVFS, filename: *const c_char) -> c_int {
    match vfs.as_ref() {
        Some(vfs) => vfs_find(vfs, &cstr(filename)).map_or(-1, |i| i as c_int),
        None => -1,
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteFileVFS(vfs: *mut mjVFS, filename: *const c_char) -> c_int {
    let Some(vfs) = vfs.as_mut() else {
        return -1;
    };
    let Some(i) = vfs_find(vfs, &cstr(filename)) else {
        return -1;
    };
    free(vfs.filedata[i]);
    let n = vfs.nfile as usize;
    for j in i..n - 1 {
        vfs.filename[j] = vfs.filename[j + 1];
        vfs.filesize[j] = vfs.filesize[j + 1];
        vfs.filedata[j] = vfs.filedata[j + 1];
    }
    vfs.filename[n - 1] = [0; mjMAXVFSNAME];
    vfs.filesize[n - 1] = 0;
    vfs.filedata[n - 1] = std::ptr::null_mut();
    vfs.nfile -= 1;
    0
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteVFS(vfs: *mut mjVFS) {
    if let Some(v) = vfs.as_mut() {
        for i in 0..v.nfile.clamp(0, mjMAXVFS as i32) as usize {
            free(v.filedata[i]);
        }
        std::ptr::write_bytes(vfs, 0, 1);
    }
}

thread_local! {
    static LAST_VALIDATION: std::cell::RefCell<std::ffi::CString> = std::cell::RefCell::new(std::ffi::CString::default());
}

/// `mj_validateReferences` (exported by 2.2.2 outside mujoco.h): NULL when the model is sound,
/// else a message valid until this thread's next call.
#[no_mangle]
pub unsafe extern "C" fn mj_validateReferences(m: *const mjModel) -> *const c_char {
    let Some(m) = m.as_ref() else {
        return std::ptr::null();
    };
    match validate::validate_references(view::Model::new(m)) {
        None => std::ptr::null(),
        Some(msg) => LAST_VALIDATION.with(|c| {
            *c.borrow_mut() = std::ffi::CString::new(msg).unwrap_or_default();
            c.borrow().as_ptr()
        }),
    }
}
