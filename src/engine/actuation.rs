//! Actuation: clamped controls, gains and biases (fixed, affine, muscle), actuator forces mapped
//! to joint space, and activation rates of stateful actuators.

use super::hooks;
use super::linalg::{clip, is_bad, max, mul_mat_t_vec};
use super::support::warning;
use super::transmission::moment_span;
use super::{disabled, tick, Data, EngineError, Model, MINVAL};
use crate::abi::*;
use crate::math::blas::mul_mat_t_vec_span;
use crate::math::misc::{muscle_bias, muscle_dynamics, muscle_gain};
use crate::runtime::callbacks::ActCallback;

const GAIN_FIXED: i32 = mjtGain_::mjGAIN_FIXED as i32;
const GAIN_AFFINE: i32 = mjtGain_::mjGAIN_AFFINE as i32;
const GAIN_MUSCLE: i32 = mjtGain_::mjGAIN_MUSCLE as i32;
const BIAS_NONE: i32 = mjtBias_::mjBIAS_NONE as i32;
const BIAS_AFFINE: i32 = mjtBias_::mjBIAS_AFFINE as i32;
const BIAS_MUSCLE: i32 = mjtBias_::mjBIAS_MUSCLE as i32;
const DYN_NONE: i32 = mjtDyn_::mjDYN_NONE as i32;
const DYN_INTEGRATOR: i32 = mjtDyn_::mjDYN_INTEGRATOR as i32;
const DYN_FILTER: i32 = mjtDyn_::mjDYN_FILTER as i32;
const DYN_MUSCLE: i32 = mjtDyn_::mjDYN_MUSCLE as i32;

/// Gain of actuator `i` at its current length and velocity; None for a user gain.
fn gain(m: &Model, i: usize, len: f64, vel: f64) -> Option<f64> {
    let prm = &m.actuator_gainprm()[mjNGAIN * i..mjNGAIN * (i + 1)];
    Some(match m.actuator_gaintype()[i] {
        GAIN_FIXED => prm[0],
        GAIN_AFFINE => prm[0] + prm[1] * len + prm[2] * vel,
        GAIN_MUSCLE => muscle_gain(
            len,
            vel,
            &m.actuator_lengthrange()[2 * i..2 * i + 2],
            m.actuator_acc0()[i],
            prm,
        ),
        _ => return None,
    })
}

/// Bias of actuator `i` at its current length and velocity; None for a user bias.
fn bias(m: &Model, i: usize, len: f64, vel: f64) -> Option<f64> {
    let prm = &m.actuator_biasprm()[mjNBIAS * i..mjNBIAS * (i + 1)];
    Some(match m.actuator_biastype()[i] {
        BIAS_NONE => 0.0,
        BIAS_AFFINE => prm[0] + prm[1] * len + prm[2] * vel,
        BIAS_MUSCLE => muscle_bias(
            len,
            &m.actuator_lengthrange()[2 * i..2 * i + 2],
            m.actuator_acc0()[i],
            prm,
        ),
        _ => return None,
    })
}

/// Activation rate of stateful actuator `i` with activation `act` and clamped control `ctrl`;
/// None for user dynamics.
fn act_rate(m: &Model, i: usize, ctrl: f64, act: f64) -> Option<f64> {
    let prm = &m.actuator_dynprm()[mjNDYN * i..mjNDYN * (i + 1)];
    Some(match m.actuator_dyntype()[i] {
        DYN_INTEGRATOR => ctrl,
        DYN_FILTER => (ctrl - act) / max(MINVAL, prm[0]),
        DYN_MUSCLE => muscle_dynamics(ctrl, act, prm),
        _ => return None,
    })
}

/// actuator_force, qfrc_actuator, act_dot (mj_fwdActuation).
pub fn fwd_actuation(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    actuation(m, d, false)
}

/// mj_fwdActuation; `spans`: the moment rows are as `transmission` left them (zero outside
/// `moment_span`), so that the force products skip their zeros.
#[inline]
pub fn actuation(m: &Model, d: &mut Data, spans: bool) -> Result<(), EngineError> {
    let start = super::now();
    d.qfrc_actuator.fill(0.0);
    d.actuator_force.fill(0.0);
    // act_dot is left as it was here, as in the reference
    if m.raw.nu == 0 || disabled(m, mjtDisableBit_::mjDSBL_ACTUATION) {
        return Ok(());
    }
    actuator_forces(m, d, spans, start)
}

#[inline(never)]
fn actuator_forces(m: &Model, d: &mut Data, spans: bool, start: f64) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nu = m.raw.nu as usize;
    let na = m.raw.na as usize;
    d.arena.scope(|a| -> Result<(), EngineError> {
        let ctrl = a.alloc_stale(nu)?;
        let noclamp = disabled(m, mjtDisableBit_::mjDSBL_CLAMPCTRL);
        for i in 0..nu {
            ctrl[i] = if !noclamp && m.actuator_ctrllimited()[i] != 0 {
                clip(
                    d.ctrl[i],
                    m.actuator_ctrlrange()[2 * i],
                    m.actuator_ctrlrange()[2 * i + 1],
                )
            } else {
                d.ctrl[i]
            };
        }
        for i in 0..nu {
            if is_bad(ctrl[i]) {
                warning(d.raw, mjtWarning_::mjWARN_BADCTRL as i32, i as i32)?;
                ctrl.fill(0.0);
                break;
            }
        }
        for i in 0..nu {
            let (len, vel) = (d.actuator_length[i], d.actuator_velocity[i]);
            let top = a.used();
            let g = gain(m, i, len, vel)
                .or_else(|| hooks::act(m, d.raw, top, ActCallback::Gain, i))
                .unwrap_or(1.0);
            let input = if m.actuator_dyntype()[i] == DYN_NONE {
                ctrl[i]
            } else {
                d.act[i + na - nu]
            };
            // the force holds gain*input while a user bias is computed, as in 2.2.2
            d.actuator_force[i] = g * input;
            let b = bias(m, i, len, vel)
                .or_else(|| hooks::act(m, d.raw, top, ActCallback::Bias, i))
                .unwrap_or(0.0);
            d.actuator_force[i] += b;
        }
        for i in 0..nu {
            if m.actuator_forcelimited()[i] != 0 {
                d.actuator_force[i] = clip(
                    d.actuator_force[i],
                    m.actuator_forcerange()[2 * i],
                    m.actuator_forcerange()[2 * i + 1],
                );
            }
        }
        if spans {
            let ten_j = (&*d.ten_J_rownnz, &*d.ten_J_rowadr, &*d.ten_J_colind);
            let span = |i| moment_span(m, ten_j, i);
            mul_mat_t_vec_span(
                d.qfrc_actuator,
                d.actuator_moment,
                d.actuator_force,
                nu,
                nv,
                span,
            );
        } else {
            mul_mat_t_vec(d.qfrc_actuator, d.actuator_moment, d.actuator_force, nu, nv);
        }
        for i in nu - na..nu {
            let j = i + na - nu;
            let top = a.used();
            d.act_dot[j] = act_rate(m, i, ctrl[i], d.act[j])
                .or_else(|| hooks::act(m, d.raw, top, ActCallback::Dyn, i))
                .unwrap_or(0.0);
        }
        Ok(())
    })?;
    tick(d, mjtTimer_::mjTIMER_ACTUATION, start);
    Ok(())
}
