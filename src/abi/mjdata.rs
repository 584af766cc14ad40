#![allow(non_camel_case_types, non_snake_case, non_upper_case_globals)]

use super::mjmodel::*;
use super::mjtnum::mjtNum;
use std::os::raw::{c_int, c_void};

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtWarning_ {
    mjWARN_INERTIA = 0,
    mjWARN_CONTACTFULL = 1,
    mjWARN_CNSTRFULL = 2,
    mjWARN_VGEOMFULL = 3,
    mjWARN_BADQPOS = 4,
    mjWARN_BADQVEL = 5,
    mjWARN_BADQACC = 6,
    mjWARN_BADCTRL = 7,
    mjNWARNING = 8,
}
pub type mjtWarning = mjtWarning_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtTimer_ {
    mjTIMER_STEP = 0,
    mjTIMER_FORWARD = 1,
    mjTIMER_INVERSE = 2,
    mjTIMER_POSITION = 3,
    mjTIMER_VELOCITY = 4,
    mjTIMER_ACTUATION = 5,
    mjTIMER_ACCELERATION = 6,
    mjTIMER_CONSTRAINT = 7,
    mjTIMER_POS_KINEMATICS = 8,
    mjTIMER_POS_INERTIA = 9,
    mjTIMER_POS_COLLISION = 10,
    mjTIMER_POS_MAKE = 11,
    mjTIMER_POS_PROJECT = 12,
    mjNTIMER = 13,
}
pub type mjtTimer = mjtTimer_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjContact_ {
    pub dist: mjtNum,
    pub pos: [mjtNum; 3],
    pub frame: [mjtNum; 9],
    pub includemargin: mjtNum,
    pub friction: [mjtNum; 5],
    pub solref: [mjtNum; mjNREF],
    pub solimp: [mjtNum; mjNIMP],
    pub mu: mjtNum,
    pub H: [mjtNum; 36],
    pub dim: c_int,
    pub geom1: c_int,
    pub geom2: c_int,
    pub exclude: c_int,
    pub efc_address: c_int,
}
pub type mjContact = mjContact_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjWarningStat_ {
    pub lastinfo: c_int,
    pub number: c_int,
}
pub type mjWarningStat = mjWarningStat_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjTimerStat_ {
    pub duration: mjtNum,
    pub number: c_int,
}
pub type mjTimerStat = mjTimerStat_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjSolverStat_ {
    pub improvement: mjtNum,
    pub gradient: mjtNum,
    pub lineslope: mjtNum,
    pub nactive: c_int,
    pub nchange: c_int,
    pub neval: c_int,
    pub nupdate: c_int,
}
pub type mjSolverStat = mjSolverStat_;

#[repr(C)]
pub struct mjData_ {
    pub nstack: c_int,
    pub nbuffer: c_int,
    pub pstack: c_int,
    pub maxuse_stack: c_int,
    pub maxuse_con: c_int,
    pub maxuse_efc: c_int,
    pub warning: [mjWarningStat; 8],
    pub timer: [mjTimerStat; 13],
    pub solver: [mjSolverStat; mjNSOLVER],
    pub solver_iter: c_int,
    pub solver_nnz: c_int,
    pub solver_fwdinv: [mjtNum; 2],
    pub ne: c_int,
    pub nf: c_int,
    pub nefc: c_int,
    pub ncon: c_int,
    pub time: mjtNum,
    pub energy: [mjtNum; 2],
    pub buffer: *mut c_void,
    pub stack: *mut mjtNum,
    pub qpos: *mut mjtNum,
    pub qvel: *mut mjtNum,
    pub act: *mut mjtNum,
    pub qacc_warmstart: *mut mjtNum,
    pub ctrl: *mut mjtNum,
    pub qfrc_applied: *mut mjtNum,
    pub xfrc_applied: *mut mjtNum,
    pub mocap_pos: *mut mjtNum,
    pub mocap_quat: *mut mjtNum,
    pub qacc: *mut mjtNum,
    pub act_dot: *mut mjtNum,
    pub userdata: *mut mjtNum,
    pub sensordata: *mut mjtNum,
    pub xpos: *mut mjtNum,
    pub xquat: *mut mjtNum,
    pub xmat: *mut mjtNum,
    pub xipos: *mut mjtNum,
    pub ximat: *mut mjtNum,
    pub xanchor: *mut mjtNum,
    pub xaxis: *mut mjtNum,
    pub geom_xpos: *mut mjtNum,
    pub geom_xmat: *mut mjtNum,
    pub site_xpos: *mut mjtNum,
    pub site_xmat: *mut mjtNum,
    pub cam_xpos: *mut mjtNum,
    pub cam_xmat: *mut mjtNum,
    pub light_xpos: *mut mjtNum,
    pub light_xdir: *mut mjtNum,
    pub subtree_com: *mut mjtNum,
    pub cdof: *mut mjtNum,
    pub cinert: *mut mjtNum,
    pub ten_wrapadr: *mut c_int,
    pub ten_wrapnum: *mut c_int,
    pub ten_J_rownnz: *mut c_int,
    pub ten_J_rowadr: *mut c_int,
    pub ten_J_colind: *mut c_int,
    pub ten_length: *mut mjtNum,
    pub ten_J: *mut mjtNum,
    pub wrap_obj: *mut c_int,
    pub wrap_xpos: *mut mjtNum,
    pub actuator_length: *mut mjtNum,
    pub actuator_moment: *mut mjtNum,
    pub crb: *mut mjtNum,
    pub qM: *mut mjtNum,
    pub qLD: *mut mjtNum,
    pub qLDiagInv: *mut mjtNum,
    pub qLDiagSqrtInv: *mut mjtNum,
    pub contact: *mut mjContact,
    pub efc_type: *mut c_int,
    pub efc_id: *mut c_int,
    pub efc_J_rownnz: *mut c_int,
    pub efc_J_rowadr: *mut c_int,
    pub efc_J_rowsuper: *mut c_int,
    pub efc_J_colind: *mut c_int,
    pub efc_JT_rownnz: *mut c_int,
    pub efc_JT_rowadr: *mut c_int,
    pub efc_JT_rowsuper: *mut c_int,
    pub efc_JT_colind: *mut c_int,
    pub efc_J: *mut mjtNum,
    pub efc_JT: *mut mjtNum,
    pub efc_pos: *mut mjtNum,
    pub efc_margin: *mut mjtNum,
    pub efc_frictionloss: *mut mjtNum,
    pub efc_diagApprox: *mut mjtNum,
    pub efc_KBIP: *mut mjtNum,
    pub efc_D: *mut mjtNum,
    pub efc_R: *mut mjtNum,
    pub efc_AR_rownnz: *mut c_int,
    pub efc_AR_rowadr: *mut c_int,
    pub efc_AR_colind: *mut c_int,
    pub efc_AR: *mut mjtNum,
    pub ten_velocity: *mut mjtNum,
    pub actuator_velocity: *mut mjtNum,
    pub cvel: *mut mjtNum,
    pub cdof_dot: *mut mjtNum,
    pub qfrc_bias: *mut mjtNum,
    pub qfrc_passive: *mut mjtNum,
    pub efc_vel: *mut mjtNum,
    pub efc_aref: *mut mjtNum,
    pub subtree_linvel: *mut mjtNum,
    pub subtree_angmom: *mut mjtNum,
    pub qH: *mut mjtNum,
    pub qHDiagInv: *mut mjtNum,
    pub D_rownnz: *mut c_int,
    pub D_rowadr: *mut c_int,
    pub D_colind: *mut c_int,
    pub qDeriv: *mut mjtNum,
    pub qLU: *mut mjtNum,
    pub actuator_force: *mut mjtNum,
    pub qfrc_actuator: *mut mjtNum,
    pub qfrc_smooth: *mut mjtNum,
    pub qacc_smooth: *mut mjtNum,
    pub efc_b: *mut mjtNum,
    pub efc_force: *mut mjtNum,
    pub efc_state: *mut c_int,
    pub qfrc_constraint: *mut mjtNum,
    pub qfrc_inverse: *mut mjtNum,
    pub cacc: *mut mjtNum,
    pub cfrc_int: *mut mjtNum,
    pub cfrc_ext: *mut mjtNum,
}
pub type mjData = mjData_;

pub type mjfGeneric = Option<unsafe extern "C" fn(m: *const mjModel, d: *mut mjData)>;
pub type mjfConFilt = Option<
    unsafe extern "C" fn(m: *const mjModel, d: *mut mjData, geom1: c_int, geom2: c_int) -> c_int,
>;
pub type mjfSensor = Option<unsafe extern "C" fn(m: *const mjModel, d: *mut mjData, stage: c_int)>;
pub type mjfTime = Option<unsafe extern "C" fn() -> mjtNum>;
pub type mjfAct =
    Option<unsafe extern "C" fn(m: *const mjModel, d: *const mjData, id: c_int) -> mjtNum>;
pub type mjfCollision = Option<
    unsafe extern "C" fn(
        m: *const mjModel,
        d: *const mjData,
        con: *mut mjContact,
        g1: c_int,
        g2: c_int,
        margin: mjtNum,
    ) -> c_int,
>;
