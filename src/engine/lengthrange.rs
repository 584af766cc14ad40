//! Actuator length ranges by simulation (mj_setLengthRange): for actuators the mode selects,
//! an existing range or the joint/tendon limits, else the extremes the actuator length reaches
//! when its moment arm is driven one way, then the other, with damped velocities.

use super::forward::{step1, step2};
use super::inertia::solve_ld;
use super::support::reset_data;
use super::{Data, EngineError, Model, MINVAL};
use crate::abi::*;
use crate::math::blas::norm;
use crate::math::misc::max;

/// What to do for one actuator.
pub enum Plan {
    /// leave its range as it is
    Keep,
    /// take these limits
    Limits([f64; 2]),
    /// simulate both sides
    Simulate,
}

/// Mode, existing range and limits (the parts of mj_setLengthRange before simulation).
pub fn plan(m: &Model, i: usize, opt: &mjLROpt) -> Plan {
    let muscle = m.actuator_gaintype()[i] == mjtGain_::mjGAIN_MUSCLE as i32
        || m.actuator_biastype()[i] == mjtBias_::mjBIAS_MUSCLE as i32;
    let user = m.actuator_gaintype()[i] == mjtGain_::mjGAIN_USER as i32
        || m.actuator_biastype()[i] == mjtBias_::mjBIAS_USER as i32;
    let mode = opt.mode;
    if mode == mjtLRMode::mjLRMODE_NONE as i32
        || (mode == mjtLRMode::mjLRMODE_MUSCLE as i32 && !muscle)
        || (mode == mjtLRMode::mjLRMODE_MUSCLEUSER as i32 && !muscle && !user)
    {
        return Plan::Keep;
    }
    let lr = &m.actuator_lengthrange()[2 * i..2 * i + 2];
    if opt.useexisting != 0 && lr[0] < lr[1] {
        return Plan::Keep;
    }
    let id = m.actuator_trnid()[2 * i] as usize;
    if opt.uselimit != 0 {
        let tt = m.actuator_trntype()[i];
        let joint = tt == mjtTrn_::mjTRN_JOINT as i32 || tt == mjtTrn_::mjTRN_JOINTINPARENT as i32;
        if joint && m.jnt_limited()[id] != 0 {
            return Plan::Limits([m.jnt_range()[2 * id], m.jnt_range()[2 * id + 1]]);
        }
        if tt == mjtTrn_::mjTRN_TENDON as i32 && m.tendon_limited()[id] != 0 {
            return Plan::Limits([m.tendon_range()[2 * id], m.tendon_range()[2 * id + 1]]);
        }
    }
    Plan::Simulate
}

/// One step driving actuator `i` to `side` (0: shorter, 1: longer); its length after (evalAct).
pub fn drive(
    m: &Model,
    d: &mut Data,
    i: usize,
    side: usize,
    opt: &mjLROpt,
) -> Result<f64, EngineError> {
    let nv = m.raw.nv as usize;
    let decay = (-m.raw.opt.timestep / max(0.01, opt.timeconst)).exp();
    for v in &mut d.qvel[..nv] {
        *v *= decay;
    }
    step1(m, d)?;
    let moment = &d.actuator_moment[i * nv..(i + 1) * nv];
    solve_ld(m, d.qfrc_applied, Some(moment), 1, d.qLD, d.qLDiagInv);
    let nrm = norm(&d.qfrc_applied[..nv]);
    let scl = (2.0 * side as f64 - 1.0) * opt.accel / max(MINVAL, nrm);
    for k in 0..nv {
        d.qfrc_applied[k] = d.actuator_moment[i * nv + k] * scl;
    }
    let nrm = norm(&d.qfrc_applied[..nv]);
    if opt.maxforce > 0.0 && nrm > opt.maxforce {
        let scl = opt.maxforce / max(MINVAL, nrm);
        for f in &mut d.qfrc_applied[..nv] {
            *f *= scl;
        }
    }
    step2(m, d)?;
    Ok(d.actuator_length[i])
}

/// Extremes of the actuator length over the last `inteval` of a side's simulation.
#[derive(Default)]
pub struct Extremes {
    pub min: f64,
    pub max: f64,
    updated: bool,
}

impl Extremes {
    /// Records the length after a step that ended at `time`.
    pub fn update(&mut self, time: f64, len: f64, opt: &mjLROpt) {
        if time > opt.inttotal - opt.inteval {
            if len < self.min || !self.updated {
                self.min = len;
            }
            if len > self.max || !self.updated {
                self.max = len;
            }
            self.updated = true;
        }
    }
}

/// Starts a side's simulation from the reset state.
pub fn begin_side(m: &Model, d: &mut Data) {
    reset_data(m, d);
}
