//! One model, many threads: a shared read-only `mjModel`, one `mjData` per thread, each thread
//! stepping its own simulation while others load models and use thread-local error hooks. Every
//! thread's final state is bit-identical to a run on the main thread.
//!
//! `cargo run --release --example threads -- [--steps N] [--loads L] [MODEL.xml ...]` prints
//! "<file> same" per model (N steps per run, 300 by default; L loads per loading thread, 3 by
//! default).
//! The test suite also runs it under ThreadSanitizer (tests/threads.rs).

use mujoco::abi::{mjData, mjModel, mjVFS};
use std::ffi::CString;
use std::os::raw::{c_char, c_int};

extern "C" {
    static mut mju_user_warning: Option<unsafe extern "C" fn(*const c_char)>;
    fn _mjPRIVATE__set_tls_warning_fn(h: Option<unsafe extern "C" fn(*const c_char)>);
    fn mj_loadXML(f: *const c_char, v: *const mjVFS, e: *mut c_char, n: c_int) -> *mut mjModel;
    fn mj_makeData(m: *const mjModel) -> *mut mjData;
    fn mj_resetDataKeyframe(m: *const mjModel, d: *mut mjData, key: c_int);
    fn mj_step(m: *const mjModel, d: *mut mjData);
    fn mj_forward(m: *const mjModel, d: *mut mjData);
    fn mj_deleteData(d: *mut mjData);
    fn mj_deleteModel(m: *mut mjModel);
}

const STEPPERS: usize = 4;
const LOADERS: usize = 2;
/// Steps per run: --steps N, else DEFAULT_STEPS.
const DEFAULT_STEPS: usize = 300;
static STEPS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
/// Loads per loading thread and model: --loads L, else DEFAULT_LOADS.
const DEFAULT_LOADS: usize = 3;
static LOADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();

unsafe extern "C" fn quiet(_msg: *const c_char) {}

/// A model shared by reference across threads (the library only reads it while stepping).
#[derive(Clone, Copy)]
struct Shared(*const mjModel);
// SAFETY: mj_step and mj_makeData only read the model; nothing writes it while shared.
unsafe impl Send for Shared {}
unsafe impl Sync for Shared {}

fn load(file: &str) -> Option<*mut mjModel> {
    let name = CString::new(file).unwrap();
    let mut err = [0 as c_char; 1000];
    // SAFETY: a NUL-terminated name and an error buffer of the given size.
    let m = unsafe { mj_loadXML(name.as_ptr(), std::ptr::null(), err.as_mut_ptr(), 1000) };
    (!m.is_null()).then_some(m)
}

/// qpos, qvel and act after the driven steps from keyframe 0 (or the reset state).
fn simulate(m: Shared) -> Vec<f64> {
    // SAFETY: m is a loaded model; d is made for it and freed here.
    unsafe {
        let m = m.0;
        let d = mj_makeData(m);
        if (*m).nkey > 0 {
            mj_resetDataKeyframe(m, d, 0);
        }
        let (nq, nv, na, nu) = (
            (*m).nq as usize,
            (*m).nv as usize,
            (*m).na as usize,
            (*m).nu as usize,
        );
        for s in 0..*STEPS.get().unwrap_or(&DEFAULT_STEPS) {
            for i in 0..nu {
                *(*d).ctrl.add(i) = (0.01 * s as f64 * (1.0 + 0.3 * i as f64) + i as f64).sin();
            }
            mj_step(m, d);
        }
        let mut out = std::slice::from_raw_parts((*d).qpos, nq).to_vec();
        out.extend_from_slice(std::slice::from_raw_parts((*d).qvel, nv));
        out.extend_from_slice(std::slice::from_raw_parts((*d).act, na));
        mj_deleteData(d);
        out
    }
}

/// What a thread does: step the shared model (`file` None) or load models of its own.
struct Job {
    model: Shared,
    file: Option<CString>,
    out: Vec<f64>,
}

extern "C" fn job(arg: *mut libc::c_void) -> *mut libc::c_void {
    // SAFETY: arg is the &mut Job given to pthread_create, alive until pthread_join.
    let job = unsafe { &mut *(arg as *mut Job) };
    match &job.file {
        None => job.out = simulate(job.model),
        Some(file) => {
            // SAFETY: this thread's own hook, cleared before it ends.
            unsafe { _mjPRIVATE__set_tls_warning_fn(Some(quiet)) };
            for _ in 0..*LOADS.get().unwrap_or(&DEFAULT_LOADS) {
                if let Some(m) = load(file.to_str().unwrap()) {
                    // SAFETY: a model of this thread's own.
                    unsafe {
                        let d = mj_makeData(m);
                        mj_forward(m, d);
                        mj_deleteData(d);
                        mj_deleteModel(m);
                    }
                }
            }
            unsafe { _mjPRIVATE__set_tls_warning_fn(None) };
        }
    }
    std::ptr::null_mut()
}

/// STEPPERS threads stepping the shared model and LOADERS threads loading `file`, as POSIX
/// threads (their creation and join are what ThreadSanitizer sees as synchronization); the
/// steppers' final states.
fn run_threads(model: Shared, file: &str) -> Vec<Vec<f64>> {
    let mut jobs: Vec<Job> = (0..STEPPERS + LOADERS)
        .map(|k| Job {
            model,
            file: (k >= STEPPERS).then(|| CString::new(file).unwrap()),
            out: Vec::new(),
        })
        .collect();
    let mut ids = Vec::new();
    for j in jobs.iter_mut() {
        let mut t: libc::pthread_t = 0;
        // SAFETY: j outlives the thread (joined below).
        let rc = unsafe {
            libc::pthread_create(
                &mut t,
                std::ptr::null(),
                job,
                j as *mut Job as *mut libc::c_void,
            )
        };
        assert_eq!(rc, 0, "pthread_create");
        ids.push(t);
    }
    for t in ids {
        // SAFETY: a thread created above, joined once.
        unsafe { libc::pthread_join(t, std::ptr::null_mut()) };
    }
    jobs.into_iter().take(STEPPERS).map(|j| j.out).collect()
}

fn main() {
    // SAFETY: set before any other thread runs.
    unsafe { mju_user_warning = Some(quiet) };
    let mut files: Vec<String> = std::env::args().skip(1).collect();
    while files.len() > 1 && matches!(files[0].as_str(), "--steps" | "--loads") {
        let n = files[1].parse().expect("--steps N, --loads L: a number");
        let cell = if files[0] == "--steps" {
            &STEPS
        } else {
            &LOADS
        };
        cell.set(n).expect("--steps and --loads once each");
        files.drain(..2);
    }
    let files = if files.is_empty() {
        vec!["models/chain.xml".to_string()]
    } else {
        files
    };
    for file in &files {
        let Some(m) = load(file) else {
            println!("{file} reject");
            continue;
        };
        let shared = Shared(m);
        let expect = simulate(shared);
        let results = run_threads(shared, file);
        let same = results.iter().all(|r| {
            r.iter()
                .zip(&expect)
                .all(|(a, b)| a.to_bits() == b.to_bits())
        });
        println!("{file} {}", if same { "same" } else { "differs" });
        // SAFETY: no thread uses the model any more.
        unsafe { mj_deleteModel(m) };
    }
}
