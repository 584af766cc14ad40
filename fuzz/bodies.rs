//! The fuzz targets' bodies, shared by the cargo-fuzz targets (fuzz/fuzz_targets, libFuzzer on
//! nightly) and the stable driver of the test suite (tests/fuzz.rs). Each feeds bytes to the path
//! a user's file takes through the C API (a file in a VFS, loaded by mj_loadXML or
//! mj_loadModel) and steps a model that loads. Any crash, abort or hang is a finding.

#![allow(dead_code)]

use mujoco::abi::{mjData, mjModel, mjVFS};
use std::ffi::CString;
use std::os::raw::{c_char, c_int};

extern "C" {
    static mut mju_user_error: Option<unsafe extern "C" fn(*const c_char)>;
    static mut mju_user_warning: Option<unsafe extern "C" fn(*const c_char)>;
    fn mj_defaultVFS(vfs: *mut mjVFS);
    fn mj_makeEmptyFileVFS(vfs: *mut mjVFS, filename: *const c_char, filesize: c_int) -> c_int;
    fn mj_deleteVFS(vfs: *mut mjVFS);
    fn mj_loadXML(f: *const c_char, v: *const mjVFS, e: *mut c_char, n: c_int) -> *mut mjModel;
    fn mj_loadModel(f: *const c_char, v: *const mjVFS) -> *mut mjModel;
    fn mj_makeData(m: *const mjModel) -> *mut mjData;
    fn mj_step(m: *const mjModel, d: *mut mjData);
    fn mj_deleteData(d: *mut mjData);
    fn mj_deleteModel(m: *mut mjModel);
}

/// Errors and warnings are expected on bad input: kept quiet, never fatal (the default error
/// handler would end the process).
unsafe extern "C" fn quiet(_msg: *const c_char) {}

/// An error reported as "internal error" is a panic the library caught: a finding.
unsafe extern "C" fn on_error(msg: *const c_char) {
    let text = std::ffi::CStr::from_ptr(msg).to_string_lossy();
    if text.contains("internal error") {
        panic!("{text}");
    }
}

fn handlers() {
    // SAFETY: plain stores to the library's handler globals, before any call.
    unsafe {
        mju_user_error = Some(on_error);
        mju_user_warning = Some(quiet);
    }
}

/// A VFS holding the given files (name, bytes), freed on drop.
struct Vfs(Box<mjVFS>);

impl Vfs {
    fn new(files: &[(&str, &[u8])]) -> Vfs {
        // SAFETY: mjVFS is plain data (ints, chars, pointers); zero is its empty state.
        let mut v: Box<mjVFS> = unsafe { Box::new(std::mem::zeroed()) };
        // SAFETY: a valid VFS; each new file's buffer has the size asked for.
        unsafe {
            mj_defaultVFS(&mut *v);
            for (name, bytes) in files {
                let n = CString::new(*name).unwrap();
                if mj_makeEmptyFileVFS(&mut *v, n.as_ptr(), bytes.len() as c_int) == 0 {
                    let i = v.nfile as usize - 1;
                    let dst = v.filedata[i] as *mut u8;
                    std::ptr::copy_nonoverlapping(bytes.as_ptr(), dst, bytes.len());
                }
            }
        }
        Vfs(v)
    }
}

impl Drop for Vfs {
    fn drop(&mut self) {
        // SAFETY: made by Vfs::new.
        unsafe { mj_deleteVFS(&mut *self.0) }
    }
}

/// Steps a loaded model a few times and frees it; false when nothing loaded.
fn step_and_free(m: *mut mjModel) -> bool {
    if m.is_null() {
        return false;
    }
    // SAFETY: m came from the loader; d is made for it.
    unsafe {
        let d = mj_makeData(m);
        if !d.is_null() {
            for _ in 0..20 {
                mj_step(m, d);
            }
            mj_deleteData(d);
        }
        mj_deleteModel(m);
    }
    true
}

fn load_xml(main: &str, files: &[(&str, &[u8])]) -> bool {
    handlers();
    let vfs = Vfs::new(files);
    let name = CString::new(main).unwrap();
    let mut err = [0 as c_char; 1000];
    // SAFETY: valid VFS and error buffer.
    let m = unsafe { mj_loadXML(name.as_ptr(), &*vfs.0, err.as_mut_ptr(), err.len() as c_int) };
    // SAFETY: the loader NUL-terminates the buffer it was given.
    let text = unsafe { std::ffi::CStr::from_ptr(err.as_ptr()) }.to_string_lossy();
    assert!(!text.contains("internal error"), "{text}");
    step_and_free(m)
}

/// MJCF text; true when it loaded.
pub fn xml(data: &[u8]) -> bool {
    load_xml("model.xml", &[("model.xml", data)])
}

/// URDF text.
pub fn urdf(data: &[u8]) -> bool {
    load_xml("robot.urdf", &[("robot.urdf", data)])
}

/// An MJB file.
pub fn mjb(data: &[u8]) -> bool {
    handlers();
    let vfs = Vfs::new(&[("model.mjb", data)]);
    let name = CString::new("model.mjb").unwrap();
    // SAFETY: valid VFS.
    let m = unsafe { mj_loadModel(name.as_ptr(), &*vfs.0) };
    step_and_free(m)
}

/// A mesh file of the given extension (stl, obj, msh) in a free body.
pub fn mesh(ext: &str, data: &[u8]) -> bool {
    let file = format!("m.{ext}");
    let xml = format!(
        "<mujoco><asset><mesh name=\"m\" file=\"{file}\"/></asset><worldbody>\
         <geom type=\"plane\" size=\"1 1 1\"/><body pos=\"0 0 0.5\"><freejoint/>\
         <geom type=\"mesh\" mesh=\"m\"/></body></worldbody></mujoco>"
    );
    load_xml("model.xml", &[("model.xml", xml.as_bytes()), (&file, data)])
}

/// A PNG file as a 2D texture, a cube texture and a height field.
pub fn png(data: &[u8]) -> bool {
    let xml = "<mujoco><asset><texture name=\"t\" type=\"2d\" file=\"t.png\"/>\
        <texture name=\"c\" type=\"cube\" file=\"t.png\"/>\
        <material name=\"m\" texture=\"t\"/><hfield name=\"h\" file=\"t.png\" size=\"1 1 0.2 0.1\"/>\
        </asset><worldbody><geom type=\"hfield\" hfield=\"h\" material=\"m\"/>\
        <body pos=\"0 0 0.5\"><freejoint/><geom size=\"0.1\"/></body></worldbody></mujoco>";
    load_xml(
        "model.xml",
        &[("model.xml", xml.as_bytes()), ("t.png", data)],
    )
}

/// A target's body: true when the input loaded.
pub type Body = fn(&[u8]) -> bool;

/// The targets by name, for the drivers.
pub const TARGETS: [(&str, Body); 7] = [
    ("xml_loader", xml),
    ("mjb_loader", mjb),
    ("mesh_stl", |d| mesh("stl", d)),
    ("mesh_obj", |d| mesh("obj", d)),
    ("mesh_msh", |d| mesh("msh", d)),
    ("png", png),
    ("urdf", urdf),
];
