//! The forward pipeline and mj_step: position, velocity, actuation, acceleration, constraint.

use super::actuation::{actuation, fwd_actuation};
use super::collision::collision;
use super::constraint::{make_constraint, project_constraint, reference_constraint};
use super::inertia::{crb, factor_m, solve_ld};
use super::integrate::{euler, implicit, runge_kutta};
use super::jacobian::jac;
use super::kinematics::{camlight, com_pos, kinematics};
use super::linalg::{add_to, is_bad, mul_mat_t_vec, mul_mat_vec, row};
use super::passive::passive;
use super::rne::rne_bias;
use super::sensor::{sensor_acc, sensor_pos, sensor_vel};
use super::support::{energy_pos, energy_vel, reset_data, warning};
use super::transmission::{moment_span, transmission};
use super::velocity::com_vel;
use super::{enabled, now, tick, Data, EngineError, Model};
use crate::abi::*;
use crate::math::blas::dot_span;
use mjtTimer_::*;

pub use super::tendon::tendon;

/// Results a forward pass may leave out: a later pass of the same step overwrites them before
/// anything can read them (see `transient`).
#[derive(Clone, Copy, Default)]
pub struct Omit {
    /// Cameras and lights (mj_camlight).
    pub cameras: bool,
    /// Potential and kinetic energy.
    pub energy: bool,
}

/// Position-dependent stage (mj_fwdPosition).
pub fn fwd_position(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    position(m, d, Omit::default())
}

fn position(m: &Model, d: &mut Data, omit: Omit) -> Result<(), EngineError> {
    let start = now();
    let mut t = now();
    kinematics(m, d)?;
    com_pos(m, d)?;
    if !omit.cameras {
        camlight(m, d, false);
    }
    tendon(m, d)?;
    tick(d, mjTIMER_POS_KINEMATICS, t);
    t = now();
    crb(m, d, true);
    factor_m(m, d)?;
    tick(d, mjTIMER_POS_INERTIA, t);
    t = now();
    collision(m, d)?;
    tick(d, mjTIMER_POS_COLLISION, t);
    t = now();
    make_constraint(m, d)?;
    transmission(m, d)?;
    tick(d, mjTIMER_POS_MAKE, t);
    t = now();
    project_constraint(m, d)?;
    tick(d, mjTIMER_POS_PROJECT, t);
    tick(d, mjTIMER_POSITION, start);
    Ok(())
}

/// Velocity-dependent stage (mj_fwdVelocity).
pub fn fwd_velocity(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    velocity(m, d, false)
}

/// mj_fwdVelocity; `spans` as in `actuation`.
fn velocity(m: &Model, d: &mut Data, spans: bool) -> Result<(), EngineError> {
    let start = now();
    let (nu, nv) = (m.raw.nu as usize, m.raw.nv as usize);
    super::tendon::tendon_velocity(m, d);
    if spans && d.qvel.iter().all(|v| v.is_finite()) {
        let ten_j = (&*d.ten_J_rownnz, &*d.ten_J_rowadr, &*d.ten_J_colind);
        for i in 0..nu {
            let (lo, hi) = moment_span(m, ten_j, i);
            d.actuator_velocity[i] = dot_span(&d.actuator_moment[i * nv..], d.qvel, nv, lo, hi);
        }
    } else {
        mul_mat_vec(d.actuator_velocity, d.actuator_moment, d.qvel, nu, nv);
    }
    com_vel(m, d);
    passive(m, d)?;
    reference_constraint(m, d);
    rne_bias(m, d)?;
    tick(d, mjTIMER_VELOCITY, start);
    Ok(())
}

/// Adds the Cartesian force and torque at `point` on `body` to `qfrc` (mj_applyFT).
pub fn apply_ft(
    m: &Model,
    d: &mut Data,
    force: Option<&[f64; 3]>,
    torque: Option<&[f64; 3]>,
    point: &[f64; 3],
    body: usize,
    qfrc: &mut [f64],
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    if body >= m.raw.nbody as usize {
        return Err(EngineError(format!("Invalid body {body} in applyFT")));
    }
    d.arena.scope(|a| -> Result<(), EngineError> {
        let jacp = a.alloc(3 * nv)?;
        let jacr = a.alloc(3 * nv)?;
        let qforce = a.alloc(nv)?;
        jac(
            m,
            d.cdof,
            d.subtree_com,
            point,
            body,
            Some(&mut *jacp),
            Some(&mut *jacr),
        );
        if let Some(f) = force {
            mul_mat_t_vec(qforce, jacp, f, 3, nv);
            add_to(&mut qfrc[..nv], qforce);
        }
        if let Some(t) = torque {
            mul_mat_t_vec(qforce, jacr, t, 3, nv);
            add_to(&mut qfrc[..nv], qforce);
        }
        Ok(())
    })
}

/// qfrc += forces of xfrc_applied (mj_xfrcAccumulate).
#[inline]
pub fn xfrc_accumulate(m: &Model, d: &mut Data, qfrc: &mut [f64]) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    // one pass without early exit over all bodies first (vectorized): mostly none has a force
    if nbody < 2 || !any_nonzero(&d.xfrc_applied[6..6 * nbody]) {
        return Ok(());
    }
    xfrc_apply(m, d, qfrc)
}

#[inline(never)]
fn xfrc_apply(m: &Model, d: &mut Data, qfrc: &mut [f64]) -> Result<(), EngineError> {
    for i in 1..m.raw.nbody as usize {
        let x = row::<6>(d.xfrc_applied, i);
        if x.iter().any(|&v| v != 0.0) {
            let point = row::<3>(d.xipos, i);
            apply_ft(
                m,
                d,
                Some(&[x[0], x[1], x[2]]),
                Some(&[x[3], x[4], x[5]]),
                &point,
                i,
                qfrc,
            )?;
        }
    }
    Ok(())
}

/// Is some value not +-0 (NaN counts)?
fn any_nonzero(x: &[f64]) -> bool {
    x.iter().fold(false, |any, &v| any | (v != 0.0))
}

/// qfrc_smooth and qacc_smooth (mj_fwdAcceleration).
pub fn fwd_acceleration(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let start = now();
    let nv = m.raw.nv as usize;
    for i in 0..nv {
        d.qfrc_smooth[i] = d.qfrc_passive[i] - d.qfrc_bias[i];
    }
    add_to(d.qfrc_smooth, d.qfrc_applied);
    add_to(d.qfrc_smooth, d.qfrc_actuator);
    let smooth = std::mem::take(&mut d.qfrc_smooth);
    let r = xfrc_accumulate(m, d, &mut *smooth);
    d.qfrc_smooth = smooth;
    r?;
    solve_ld(m, d.qacc_smooth, Some(d.qfrc_smooth), 1, d.qLD, d.qLDiagInv);
    tick(d, mjTIMER_ACCELERATION, start);
    Ok(())
}

/// mj_fwdConstraint: the constraint solver.
pub fn fwd_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    super::solver::fwd_constraint(m, d)
}

/// Resets and warns when qpos has a bad value (mj_checkPos).
pub fn check_pos(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if let Some(i) = first_bad(d.qpos) {
        bad_state(m, d, mjtWarning_::mjWARN_BADQPOS, i)?;
    }
    Ok(())
}

/// Resets and warns when qvel has a bad value (mj_checkVel).
pub fn check_vel(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if let Some(i) = first_bad(d.qvel) {
        bad_state(m, d, mjtWarning_::mjWARN_BADQVEL, i)?;
    }
    Ok(())
}

/// Resets, warns and recomputes when qacc has a bad value (mj_checkAcc).
pub fn check_acc(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if let Some(i) = first_bad(d.qacc) {
        bad_state(m, d, mjtWarning_::mjWARN_BADQACC, i)?;
        forward(m, d)?;
    }
    Ok(())
}

/// Index of the first NaN or out-of-range value: a vectorized pass first, as mostly none is.
#[inline]
fn first_bad(x: &[f64]) -> Option<usize> {
    if !x.iter().fold(false, |any, &v| any | is_bad(v)) {
        return None;
    }
    x.iter().position(|&v| is_bad(v))
}

fn bad_state(m: &Model, d: &mut Data, kind: mjtWarning_, i: usize) -> Result<(), EngineError> {
    warning(d.raw, kind as i32, i as i32)?;
    reset_data(m, d);
    let w = &mut d.raw.warning[kind as usize];
    w.number += 1;
    w.lastinfo = i as i32;
    Ok(())
}

/// The position and velocity stages not skipped, each followed by its sensors and energy:
/// shared by forward and inverse dynamics, which differ only in the stage functions.
pub fn pos_vel_stages(
    m: &Model,
    d: &mut Data,
    (skipstage, skipsensor, omit): (i32, bool, Omit),
    position: impl FnOnce(&Model, &mut Data) -> Result<(), EngineError>,
    velocity: impl FnOnce(&Model, &mut Data) -> Result<(), EngineError>,
) -> Result<(), EngineError> {
    let energy = enabled(m, mjtEnableBit_::mjENBL_ENERGY) && !omit.energy;
    if skipstage < mjtStage_::mjSTAGE_POS as i32 {
        position(m, d)?;
        if !skipsensor {
            sensor_pos(m, d)?;
        }
        if energy {
            energy_pos(m, d);
        }
    }
    if skipstage < mjtStage_::mjSTAGE_VEL as i32 {
        velocity(m, d)?;
        if !skipsensor {
            sensor_vel(m, d)?;
        }
        if energy {
            energy_vel(m, d)?;
        }
    }
    Ok(())
}

/// Forward dynamics, skipping stages up to `skipstage` (mj_forwardSkip).
pub fn forward_skip(
    m: &Model,
    d: &mut Data,
    skipstage: i32,
    skipsensor: bool,
) -> Result<(), EngineError> {
    forward_pass(m, d, skipstage, skipsensor, Omit::default())
}

/// Fewest dofs for which the moment products go by spans (below, whole rows cost less).
const SPAN_MIN_NV: usize = 48;

/// mj_forwardSkip leaving out `omit`.
pub fn forward_pass(
    m: &Model,
    d: &mut Data,
    skipstage: i32,
    skipsensor: bool,
    omit: Omit,
) -> Result<(), EngineError> {
    let start = now();
    let stages = (skipstage, skipsensor, omit);
    // the moment rows are transmission's own when it ran in this pass and no callback, which
    // could write them, runs before the actuation
    let spans = m.raw.nv as usize >= SPAN_MIN_NV
        && skipstage < mjtStage_::mjSTAGE_POS as i32
        && !super::hooks::any_set();
    let velocity = |m: &Model, d: &mut Data| velocity(m, d, spans);
    pos_vel_stages(m, d, stages, |m, d| position(m, d, omit), velocity)?;
    super::hooks::control(m, d);
    actuation(m, d, spans)?;
    fwd_acceleration(m, d)?;
    fwd_constraint(m, d)?;
    if !skipsensor {
        sensor_acc(m, d)?;
    }
    tick(d, mjTIMER_FORWARD, start);
    Ok(())
}

/// mj_forward.
pub fn forward(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    forward_skip(m, d, mjtStage_::mjSTAGE_NONE as i32, false)
}

fn check_fwdinv(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if enabled(m, mjtEnableBit_::mjENBL_FWDINV) {
        super::inverse::compare_fwd_inv(m, d)?;
    }
    Ok(())
}

/// mj_step: forward dynamics, then the selected integrator.
pub fn step(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    step_skip(m, d, mjtStage_::mjSTAGE_NONE as i32, false)
}

/// mj_step reusing stages up to `skipstage` (mj_stepSkip).
pub fn step_skip(
    m: &Model,
    d: &mut Data,
    skipstage: i32,
    skipsensor: bool,
) -> Result<(), EngineError> {
    let start = now();
    check_pos(m, d)?;
    check_vel(m, d)?;
    let rk4 = m.raw.opt.integrator == mjtIntegrator_::mjINT_RK4 as i32;
    let omit = if rk4 {
        transient(m, !skipsensor)
    } else {
        Omit::default()
    };
    forward_pass(m, d, skipstage, skipsensor, omit)?;
    check_acc(m, d)?;
    check_fwdinv(m, d)?;
    match m.raw.opt.integrator {
        x if x == mjtIntegrator_::mjINT_EULER as i32 => {
            euler(m, d, skipstage >= mjtStage_::mjSTAGE_POS as i32)?
        }
        x if x == mjtIntegrator_::mjINT_RK4 as i32 => runge_kutta(m, d, 4)?,
        x if x == mjtIntegrator_::mjINT_IMPLICIT as i32 => {
            implicit(m, d, skipstage >= mjtStage_::mjSTAGE_VEL as i32)?
        }
        _ => return Err(EngineError("Invalid integrator".into())),
    }
    tick(d, mjTIMER_STEP, start);
    Ok(())
}

/// What a forward pass followed by another in the same step may leave out: cameras, lights and
/// energy, which the later pass overwrites (RK4 runs four passes a step), unless a user
/// callback could read them in between, mjENBL_FWDINV compares the pass, or (`sensors`: the
/// pass computes sensors) a sensor reads a camera.
pub fn transient(m: &Model, sensors: bool) -> Omit {
    if crate::runtime::callbacks::any_engine_callback() || enabled(m, mjtEnableBit_::mjENBL_FWDINV)
    {
        return Omit::default();
    }
    let camera = mjtObj_::mjOBJ_CAMERA as i32;
    let reads_camera =
        sensors && (m.sensor_objtype().contains(&camera) || m.sensor_reftype().contains(&camera));
    Omit {
        cameras: !reads_camera,
        energy: true,
    }
}

/// First half of mj_step, before the user sets controls and applied forces (mj_step1).
pub fn step1(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let start = now();
    check_pos(m, d)?;
    check_vel(m, d)?;
    fwd_position(m, d)?;
    sensor_pos(m, d)?;
    energy_pos(m, d);
    fwd_velocity(m, d)?;
    sensor_vel(m, d)?;
    energy_vel(m, d)?;
    super::hooks::control(m, d);
    tick(d, mjTIMER_STEP, start);
    Ok(())
}

/// Second half of mj_step: actuation to integration; RK4 falls back to Euler (mj_step2).
pub fn step2(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let start = now();
    fwd_actuation(m, d)?;
    fwd_acceleration(m, d)?;
    fwd_constraint(m, d)?;
    sensor_acc(m, d)?;
    check_acc(m, d)?;
    check_fwdinv(m, d)?;
    if m.raw.opt.integrator == mjtIntegrator_::mjINT_IMPLICIT as i32 {
        implicit(m, d, false)?;
    } else {
        euler(m, d, false)?;
    }
    // step2 does not count as a separate step
    d.raw.timer[mjTIMER_STEP as usize].number -= 1;
    tick(d, mjTIMER_STEP, start);
    Ok(())
}
