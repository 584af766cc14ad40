//! Actuator length ranges by simulation: mj_setLengthRange and the compiler's step over all
//! actuators. The model's range is written between the simulated sides.

use crate::abi::owned::{DataBox, ModelBox};
use crate::abi::*;
use crate::engine::lengthrange::{begin_side, drive, plan, Extremes, Plan};
use crate::engine::EngineError;
use crate::runtime::message::format_g as g;

/// Length range of actuator `i` (< nu): Ok(Err(message)) for the errors mj_setLengthRange
/// reports through its buffer.
pub fn set_length_range(
    m: &mut ModelBox,
    d: &mut DataBox,
    i: usize,
    opt: &mjLROpt,
) -> Result<Result<(), String>, EngineError> {
    let put = |m: &mut ModelBox, side: usize, v: f64| {
        m.view_mut().actuator_lengthrange[2 * i + side] = v;
    };
    match plan(&m.view(), i, opt) {
        Plan::Keep => return Ok(Ok(())),
        Plan::Limits(r) => {
            put(m, 0, r[0]);
            put(m, 1, r[1]);
            return Ok(Ok(()));
        }
        Plan::Simulate => {}
    }
    // one view per step, as 2.2.2's calls of mj_step1 and mj_step2 (scratch is per call)
    let mut ext = [(0.0, 0.0); 2];
    for (side, out) in ext.iter_mut().enumerate() {
        begin_side(&m.view(), &mut d.view(m));
        let mut e = Extremes::default();
        while d.raw().time < opt.inttotal {
            let len = drive(&m.view(), &mut d.view(m), i, side, opt)?;
            if d.raw().time == 0.0 {
                return Ok(Err(format!(
                    "Unstable lengthrange simulation in actuator {i}"
                )));
            }
            e.update(d.raw().time, len, opt);
        }
        *out = (e.min, e.max);
        put(m, side, if side == 0 { e.min } else { e.max });
    }
    let lr = [
        m.view().actuator_lengthrange()[2 * i],
        m.view().actuator_lengthrange()[2 * i + 1],
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
pub fn compile_length_ranges(
    m: &mut ModelBox,
    d: &mut DataBox,
    opt: &mjLROpt,
) -> Result<(), String> {
    let nu = m.raw().nu.max(0) as usize;
    let needed =
        (0..nu).any(|i| matches!(plan(&m.view(), i, opt), Plan::Simulate | Plan::Limits(_)));
    if !needed {
        return Ok(());
    }
    let saved = m.raw().opt;
    use mjtDisableBit_::*;
    m.opt_mut().disableflags = mjDSBL_FRICTIONLOSS as i32
        | mjDSBL_CONTACT as i32
        | mjDSBL_PASSIVE as i32
        | mjDSBL_GRAVITY as i32
        | mjDSBL_ACTUATION as i32;
    if opt.timestep > 0.0 {
        m.opt_mut().timestep = opt.timestep;
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
    *m.opt_mut() = saved;
    result
}
