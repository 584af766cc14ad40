//! mj_setLengthRange and the compiler's length-range step: the views are rebuilt around each
//! simulated side, as the model's range is written between them.

use super::errmem;
use super::guard;
use crate::abi::view::{Data, Model, ModelMut};
use crate::abi::*;
use crate::engine::lengthrange::{begin_side, drive, plan, Extremes, Plan};
use crate::engine::EngineError;
use std::os::raw::{c_char, c_int};

/// A number as C's "%g" prints it.
fn g(x: f64) -> String {
    let mut buf = [0u8; 64];
    // SAFETY: the format takes exactly one double; buf is large enough for any %g output.
    let n = unsafe {
        libc::snprintf(
            buf.as_mut_ptr() as *mut libc::c_char,
            buf.len(),
            c"%g".as_ptr(),
            x,
        )
    };
    String::from_utf8_lossy(&buf[..(n.max(0) as usize).min(buf.len() - 1)]).into_owned()
}

/// Length range of actuator `i`: Ok(Err(message)) for the errors mj_setLengthRange reports
/// through its buffer.
///
/// # Safety
/// `m` and `d` must be a valid model and data made for it.
pub unsafe fn set_length_range(
    m: *mut mjModel,
    d: *mut mjData,
    i: usize,
    opt: &mjLROpt,
) -> Result<Result<(), String>, EngineError> {
    let todo = plan(&Model::new(&*m), i, opt);
    let put = |side: usize, v: f64| {
        let mm = ModelMut::new(&mut *m);
        mm.actuator_lengthrange[2 * i + side] = v;
    };
    match todo {
        Plan::Keep => return Ok(Ok(())),
        Plan::Limits(r) => {
            put(0, r[0]);
            put(1, r[1]);
            return Ok(Ok(()));
        }
        Plan::Simulate => {}
    }
    // one view per step, as 2.2.2's calls of mj_step1 and mj_step2 (scratch is per call)
    let mut ext = [(0.0, 0.0); 2];
    for (side, out) in ext.iter_mut().enumerate() {
        begin_side(&Model::new(&*m), &mut Data::new(&*m, &mut *d));
        let mut e = Extremes::default();
        while (*d).time < opt.inttotal {
            let len = drive(&Model::new(&*m), &mut Data::new(&*m, &mut *d), i, side, opt)?;
            if (*d).time == 0.0 {
                return Ok(Err(format!(
                    "Unstable lengthrange simulation in actuator {i}"
                )));
            }
            e.update((*d).time, len, opt);
        }
        *out = (e.min, e.max);
        put(side, if side == 0 { e.min } else { e.max });
    }
    let lr = [
        (*m).actuator_lengthrange.add(2 * i).read(),
        (*m).actuator_lengthrange.add(2 * i + 1).read(),
    ];
    let dif = lr[1] - lr[0];
    if dif <= 0.0 {
        return Ok(Err(format!(
            "Invalid lengthrange ({}, {}) in actuator {i}",
            g(lr[0]),
            g(lr[1])
        )));
    }
    for (side, sep) in [(0, "  "), (1, " ")] {
        let (lmin, lmax) = ext[side];
        if lmax - lmin > opt.tolrange * dif {
            return Ok(Err(format!(
                "Lengthrange computation did not converge in actuator {i}:\n  eval ({}, {})\n{sep}range ({}, {})",
                g(lmin),
                g(lmax),
                g(lr[0]),
                g(lr[1])
            )));
        }
    }
    Ok(Ok(()))
}

/// The compiler's step: every actuator with contacts, passive forces, gravity, actuation and
/// friction loss off (and the option's time step), options restored after; the first error.
///
/// # Safety
/// `m` must be a valid model, not aliased.
pub unsafe fn compile_length_ranges(
    m: *mut mjModel,
    d: *mut mjData,
    opt: &mjLROpt,
) -> Result<(), String> {
    let nu = (*m).nu.max(0) as usize;
    let needed = (0..nu).any(|i| {
        matches!(
            plan(&Model::new(&*m), i, opt),
            Plan::Simulate | Plan::Limits(_)
        )
    });
    if !needed {
        return Ok(());
    }
    let saved = (*m).opt;
    use mjtDisableBit_::*;
    (*m).opt.disableflags = mjDSBL_FRICTIONLOSS as i32
        | mjDSBL_CONTACT as i32
        | mjDSBL_PASSIVE as i32
        | mjDSBL_GRAVITY as i32
        | mjDSBL_ACTUATION as i32;
    if opt.timestep > 0.0 {
        (*m).opt.timestep = opt.timestep;
    }
    let mut result = Ok(());
    for i in 0..nu {
        match set_length_range(m, d, i, opt) {
            Ok(Ok(())) => {}
            Ok(Err(msg)) => {
                result = Err(msg);
                break;
            }
            Err(e) => {
                result = Err(format!("engine error: {}", e.0));
                break;
            }
        }
    }
    (*m).opt = saved;
    result
}

#[no_mangle]
pub unsafe extern "C" fn mj_setLengthRange(
    m: *mut mjModel,
    d: *mut mjData,
    index: c_int,
    opt: *const mjLROpt,
    error: *mut c_char,
    error_sz: c_int,
) -> c_int {
    if m.is_null() || d.is_null() || opt.is_null() {
        errmem::error("mj_setLengthRange: NULL model, data or options");
        return 0;
    }
    if index < 0 || index >= (*m).nu {
        errmem::error("Invalid actuator index in mj_setLengthRange");
        return 0;
    }
    let opt = *opt;
    guard("mj_setLengthRange", 0, || {
        Ok(match set_length_range(m, d, index as usize, &opt)? {
            Ok(()) => 1,
            Err(msg) => {
                if !error.is_null() && error_sz > 0 {
                    let n = msg.len().min(error_sz as usize - 1);
                    std::ptr::copy_nonoverlapping(msg.as_ptr(), error as *mut u8, n);
                    *error.add(n) = 0;
                }
                0
            }
        })
    })
}
