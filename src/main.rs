//! `rujoco [model.xml|model.mjb] [steps]`: load a model (the embedded chain when none is given),
//! simulate it, and print the model, the speed and the final state.

use mujoco::abi::*;
use mujoco::capi::errmem::{mju_user_error, mju_user_warning};
use mujoco::capi::io::{
    mj_deleteData, mj_deleteModel, mj_loadModel, mj_makeData, mj_resetDataKeyframe,
};
use std::ffi::{CStr, CString};
use std::os::raw::{c_char, c_int};
use std::time::Instant;

extern "C" {
    fn mj_loadXML(
        filename: *const c_char,
        vfs: *const mjVFS,
        error: *mut c_char,
        error_sz: c_int,
    ) -> *mut mjModel;
    fn mj_step(m: *const mjModel, d: *mut mjData);
}

const DEFAULT_MODEL: &str = include_str!("../models/chain.xml");

unsafe extern "C" fn on_error(msg: *const c_char) {
    eprintln!("error: {}", CStr::from_ptr(msg).to_string_lossy());
    std::process::exit(1);
}

unsafe extern "C" fn on_warning(msg: *const c_char) {
    eprintln!("warning: {}", CStr::from_ptr(msg).to_string_lossy());
}

fn load(path: &str) -> Result<*mut mjModel, String> {
    let cpath = CString::new(path).map_err(|_| "bad path".to_string())?;
    let mut err = [0 as c_char; 1000];
    // SAFETY: valid C strings and an error buffer of the size passed.
    let m = unsafe {
        if path.ends_with(".mjb") {
            mj_loadModel(cpath.as_ptr(), std::ptr::null())
        } else {
            mj_loadXML(
                cpath.as_ptr(),
                std::ptr::null(),
                err.as_mut_ptr(),
                err.len() as c_int,
            )
        }
    };
    if m.is_null() {
        // SAFETY: the loader NUL-terminates its message.
        let msg = unsafe { CStr::from_ptr(err.as_ptr()) }
            .to_string_lossy()
            .into_owned();
        return Err(format!("could not load {path}: {msg}"));
    }
    Ok(m)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let steps: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    // SAFETY: installing handlers before any other call into the library.
    unsafe {
        mju_user_error = Some(on_error);
        mju_user_warning = Some(on_warning);
    }
    let (path, label, _tmp) = match args.first() {
        Some(p) => (p.clone(), p.clone(), None),
        None => {
            let dir = std::env::temp_dir().join(format!("rujoco-{}", std::process::id()));
            std::fs::create_dir_all(&dir).expect("temp dir");
            let file = dir.join("chain.xml");
            std::fs::write(&file, DEFAULT_MODEL).expect("write default model");
            (
                file.to_string_lossy().into_owned(),
                "embedded default model".to_string(),
                Some(TempDir(dir)),
            )
        }
    };
    let m = match load(&path) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    // SAFETY: m is a valid model from the loader; d is made for it.
    unsafe {
        let mm = &*m;
        let d = mj_makeData(m);
        if mm.nkey > 0 {
            mj_resetDataKeyframe(m, d, 0);
        }
        let name = CStr::from_ptr(mm.names).to_string_lossy();
        println!("model      {name} ({label})");
        println!(
            "sizes      nq={} nv={} nu={} na={} nbody={} njnt={} ngeom={} nsite={}",
            mm.nq, mm.nv, mm.nu, mm.na, mm.nbody, mm.njnt, mm.ngeom, mm.nsite
        );
        println!(
            "timestep   {} s, integrator {}",
            mm.opt.timestep,
            ["Euler", "RK4", "implicit"][mm.opt.integrator.clamp(0, 2) as usize]
        );
        let start = Instant::now();
        for _ in 0..steps {
            mj_step(m, d);
        }
        let secs = start.elapsed().as_secs_f64();
        let dd = &*d;
        println!(
            "simulated  {steps} steps, {:.3} s of model time in {:.3} s wall",
            dd.time, secs
        );
        println!(
            "speed      {:.0} steps/s ({:.1}x real time)",
            steps as f64 / secs,
            dd.time / secs
        );
        let show = |label: &str, p: *const f64, n: i32| {
            let v: Vec<String> = (0..n.max(0) as usize)
                .map(|i| format!("{:.6}", *p.add(i)))
                .collect();
            println!("{label:<10} [{}]", v.join(", "));
        };
        show("qpos", dd.qpos, mm.nq);
        show("qvel", dd.qvel, mm.nv);
        let warnings: i32 = dd.warning.iter().map(|w| w.number).sum();
        println!("warnings   {warnings}");
        mj_deleteData(d);
        mj_deleteModel(m);
    }
}

/// Removes the directory holding the embedded model at exit.
struct TempDir(std::path::PathBuf);

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
