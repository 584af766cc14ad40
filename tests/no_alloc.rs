//! mj_step and mj_forward take no memory from the heap: every allocation in this test binary
//! goes through a counting allocator, and none may happen while stepping.

use mujoco::abi::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::ffi::CString;
use std::os::raw::{c_char, c_int};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Set on the thread under measurement: only its allocations count (the test runner's own
    /// threads may allocate at any time).
    static MEASURED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

fn count() {
    if MEASURED.with(|m| m.get()) {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

extern "C" {
    fn mj_loadXML(
        filename: *const c_char,
        vfs: *const mjVFS,
        error: *mut c_char,
        error_sz: c_int,
    ) -> *mut mjModel;
    fn mj_makeData(m: *const mjModel) -> *mut mjData;
    fn mj_step(m: *const mjModel, d: *mut mjData);
    fn mj_forward(m: *const mjModel, d: *mut mjData);
    fn mj_deleteData(d: *mut mjData);
    fn mj_deleteModel(m: *mut mjModel);
}

/// libc's malloc is not counted by the Rust allocator: count mju_malloc too.
static C_ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe extern "C" fn counting_malloc(size: usize) -> *mut std::os::raw::c_void {
    if MEASURED.with(|m| m.get()) {
        C_ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
    }
    libc_malloc(size)
}

extern "C" {
    #[link_name = "malloc"]
    fn libc_malloc(size: usize) -> *mut std::os::raw::c_void;
    #[link_name = "free"]
    fn libc_free(p: *mut std::os::raw::c_void);
}

unsafe extern "C" fn counting_free(p: *mut std::os::raw::c_void) {
    libc_free(p)
}

unsafe extern "C" fn fail(msg: *const c_char) {
    eprintln!(
        "mju_error: {}",
        std::ffi::CStr::from_ptr(msg).to_string_lossy()
    );
    std::process::exit(1);
}

#[test]
fn stepping_does_not_allocate() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
    MEASURED.with(|m| m.set(true));
    unsafe {
        mujoco::capi::errmem::mju_user_malloc = Some(counting_malloc);
        mujoco::capi::errmem::mju_user_free = Some(counting_free);
        mujoco::capi::errmem::mju_user_error = Some(fail);
    }
    let extra = [
        "extra/constraints_newton",
        "extra/constraints_pgs_sparse",
        "extra/constraints_cg",
        "extra/frictionloss_noslip",
        "extra/longchain_newton",
        "extra/tendon_wrap_sparse",
        "extra/tendon_constraints",
        "extra/transmissions",
        "extra/activation",
        "extra/fluid_box",
        "extra/implicit_fluid_sparse",
        "extra/sensors_all",
        "extra/fwdinv_constraints",
        "extra/rangefinder",
        "extra/contact_primitives",
        "extra/contact_cg_elliptic_dense_ns5",
        "extra/contact_newton_elliptic_sparse_ns0",
        "extra/contact_pgs_elliptic_sparse_ns5",
        "extra/contact_pgs_pyramidal_dense_ns5",
        "extra/callbacks",
        "extra/lengthrange",
        "extra/mesh_files",
        "extra/mesh_inline",
        "extra/fusestatic",
        "extra/adhesion_pyramidal_sparse",
        "extra/composite_chains",
    ];
    for name in ["pendulum", "arm3", "freebox", "chain"]
        .into_iter()
        .chain(extra)
    {
        let path = CString::new(format!("{dir}/{name}.xml")).unwrap();
        let mut err = [0 as c_char; 500];
        unsafe {
            let m = mj_loadXML(path.as_ptr(), std::ptr::null(), err.as_mut_ptr(), 500);
            assert!(!m.is_null(), "{name} did not load");
            let d = mj_makeData(m);
            for _ in 0..10 {
                mj_step(m, d);
            }
            let before = (
                ALLOCATIONS.load(Ordering::SeqCst),
                C_ALLOCATIONS.load(Ordering::SeqCst),
            );
            for _ in 0..1000 {
                mj_step(m, d);
                mj_forward(m, d);
            }
            let after = (
                ALLOCATIONS.load(Ordering::SeqCst),
                C_ALLOCATIONS.load(Ordering::SeqCst),
            );
            println!(
                "{name}: {} Rust and {} C allocations in 1000 mj_step + mj_forward",
                after.0 - before.0,
                after.1 - before.1
            );
            assert_eq!(before, after, "{name}: mj_step/mj_forward allocated");
            mj_deleteData(d);
            mj_deleteModel(m);
        }
    }
    warning_and_reset_do_not_allocate();
}

static WARNINGS: AtomicUsize = AtomicUsize::new(0);

unsafe extern "C" fn count_warning(_msg: *const c_char) {
    WARNINGS.fetch_add(1, Ordering::SeqCst);
}

/// An unstable state (NaN velocity) warns and resets on every step (the warning count cleared
/// so that each one is reported): the warning path, its message and the reset take no heap
/// memory either. Runs inside `stepping_does_not_allocate` (the C counters are global).
fn warning_and_reset_do_not_allocate() {
    let path = CString::new(concat!(env!("CARGO_MANIFEST_DIR"), "/models/pendulum.xml")).unwrap();
    unsafe {
        let mut err = [0 as c_char; 500];
        let m = mj_loadXML(path.as_ptr(), std::ptr::null(), err.as_mut_ptr(), 500);
        assert!(!m.is_null(), "pendulum did not load");
        let d = mj_makeData(m);
        mj_step(m, d);
        mujoco::capi::errmem::mju_user_warning = Some(count_warning);
        let before = (
            ALLOCATIONS.load(Ordering::SeqCst),
            C_ALLOCATIONS.load(Ordering::SeqCst),
        );
        for _ in 0..100 {
            *(*d).qvel = f64::NAN;
            (*d).warning[mjtWarning_::mjWARN_BADQVEL as usize].number = 0;
            mj_step(m, d);
        }
        let after = (
            ALLOCATIONS.load(Ordering::SeqCst),
            C_ALLOCATIONS.load(Ordering::SeqCst),
        );
        mujoco::capi::errmem::mju_user_warning = None;
        let warned = WARNINGS.load(Ordering::SeqCst);
        println!("{warned} warnings in 100 unstable steps");
        assert_eq!(warned, 100, "every unstable step warns");
        assert_eq!(before, after, "the warning path allocated");
        mj_deleteData(d);
        mj_deleteModel(m);
    }
}
