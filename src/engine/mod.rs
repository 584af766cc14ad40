//! The simulation pipeline, one module per stage of MuJoCo's computation chapter.

#![allow(clippy::needless_range_loop)] // index loops mirror the reference algorithms

pub mod actuation;
pub mod collision;
pub mod constraint;
pub mod contact;
pub mod derivative;
pub mod fluid;
pub mod forward;
pub mod hooks;
pub mod inertia;
pub mod integrate;
pub mod inverse;
pub mod jacdif;
pub mod jacobian;
pub mod kinematics;
pub mod lengthrange;
pub mod linalg;
pub mod passive;
pub mod print;
pub mod ray;
pub mod ray_mesh;
pub mod rne;
pub mod sensor;
pub mod setconst;
pub mod solver;
pub mod solver_dual;
pub mod support;
pub mod tendon;
pub mod transmission;
pub mod tree;
pub mod velocity;

pub use crate::abi::view::{Data, EngineError, Model};

use crate::abi::*;

/// Joint type codes as stored in `jnt_type`.
pub const JNT_FREE: i32 = mjtJoint_::mjJNT_FREE as i32;
pub const JNT_BALL: i32 = mjtJoint_::mjJNT_BALL as i32;
pub const JNT_SLIDE: i32 = mjtJoint_::mjJNT_SLIDE as i32;
pub const JNT_HINGE: i32 = mjtJoint_::mjJNT_HINGE as i32;

/// Geom type codes as stored in `geom_type`.
pub mod geom {
    use crate::abi::mjtGeom_::*;
    pub const PLANE: i32 = mjGEOM_PLANE as i32;
    pub const HFIELD: i32 = mjGEOM_HFIELD as i32;
    pub const SPHERE: i32 = mjGEOM_SPHERE as i32;
    pub const CAPSULE: i32 = mjGEOM_CAPSULE as i32;
    pub const ELLIPSOID: i32 = mjGEOM_ELLIPSOID as i32;
    pub const CYLINDER: i32 = mjGEOM_CYLINDER as i32;
    pub const BOX: i32 = mjGEOM_BOX as i32;
    pub const MESH: i32 = mjGEOM_MESH as i32;
}

/// Largest magnitude accepted in qpos, qvel, qacc and ctrl.
pub const MAXVAL: f64 = 1e10;
/// Smallest value used in denominators.
pub const MINVAL: f64 = 1e-15;

/// Is the disable flag set?
pub fn disabled(m: &Model, flag: mjtDisableBit_) -> bool {
    m.raw.opt.disableflags & flag as i32 != 0
}

/// Is the enable flag set?
pub fn enabled(m: &Model, flag: mjtEnableBit_) -> bool {
    m.raw.opt.enableflags & flag as i32 != 0
}

/// Counts one pass through a timed stage (no timer callback: durations stay 0).
pub fn tick(d: &mut Data, timer: mjtTimer_, start: f64) {
    let t = &mut d.raw.timer[timer as usize];
    t.duration += now() - start;
    t.number += 1;
}

/// The user's clock (mjcb_time), 0 without one: timer durations are differences of it.
pub fn now() -> f64 {
    crate::runtime::callbacks::call_time().unwrap_or(0.0)
}

/// Shorthand for a "not implemented" error.
pub fn not_implemented(what: &str) -> EngineError {
    EngineError(format!("{what} not implemented"))
}
