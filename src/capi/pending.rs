//! Entry points of the 2.2.2 API not implemented yet: each reports that through `mju_error`.

#![allow(unused_variables, unused_imports)]

use crate::abi::*;
use std::os::raw::{c_char, c_int, c_void};

use super::pending;

#[no_mangle]
pub unsafe extern "C" fn mj_loadXML(filename: *const c_char, vfs: *const mjVFS, error: *mut c_char, error_sz: c_int) -> *mut mjModel {
    pending("mj_loadXML");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mj_saveLastXML(filename: *const c_char, m: *const mjModel, error: *mut c_char, error_sz: c_int) -> c_int {
    pending("mj_saveLastXML");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_freeLastXML() {
    pending("mj_freeLastXML");
}

#[no_mangle]
pub unsafe extern "C" fn mj_printSchema(filename: *const c_char, buffer: *mut c_char, buffer_sz: c_int, flg_html: c_int, flg_pad: c_int) -> c_int {
    pending("mj_printSchema");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_step(m: *const mjModel, d: *mut mjData) {
    pending("mj_step");
}

#[no_mangle]
pub unsafe extern "C" fn mj_step1(m: *const mjModel, d: *mut mjData) {
    pending("mj_step1");
}

#[no_mangle]
pub unsafe extern "C" fn mj_step2(m: *const mjModel, d: *mut mjData) {
    pending("mj_step2");
}

#[no_mangle]
pub unsafe extern "C" fn mj_forward(m: *const mjModel, d: *mut mjData) {
    pending("mj_forward");
}

#[no_mangle]
pub unsafe extern "C" fn mj_inverse(m: *const mjModel, d: *mut mjData) {
    pending("mj_inverse");
}

#[no_mangle]
pub unsafe extern "C" fn mj_forwardSkip(m: *const mjModel, d: *mut mjData, skipstage: c_int, skipsensor: c_int) {
    pending("mj_forwardSkip");
}

#[no_mangle]
pub unsafe extern "C" fn mj_inverseSkip(m: *const mjModel, d: *mut mjData, skipstage: c_int, skipsensor: c_int) {
    pending("mj_inverseSkip");
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetCallbacks() {
    pending("mj_resetCallbacks");
}

#[no_mangle]
pub unsafe extern "C" fn mj_setConst(m: *mut mjModel, d: *mut mjData) {
    pending("mj_setConst");
}

#[no_mangle]
pub unsafe extern "C" fn mj_setLengthRange(m: *mut mjModel, d: *mut mjData, index: c_int, opt: *const mjLROpt, error: *mut c_char, error_sz: c_int) -> c_int {
    pending("mj_setLengthRange");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdPosition(m: *const mjModel, d: *mut mjData) {
    pending("mj_fwdPosition");
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdVelocity(m: *const mjModel, d: *mut mjData) {
    pending("mj_fwdVelocity");
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdActuation(m: *const mjModel, d: *mut mjData) {
    pending("mj_fwdActuation");
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdAcceleration(m: *const mjModel, d: *mut mjData) {
    pending("mj_fwdAcceleration");
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_fwdConstraint");
}

#[no_mangle]
pub unsafe extern "C" fn mj_Euler(m: *const mjModel, d: *mut mjData) {
    pending("mj_Euler");
}

#[no_mangle]
pub unsafe extern "C" fn mj_RungeKutta(m: *const mjModel, d: *mut mjData, N: c_int) {
    pending("mj_RungeKutta");
}

#[no_mangle]
pub unsafe extern "C" fn mj_invPosition(m: *const mjModel, d: *mut mjData) {
    pending("mj_invPosition");
}

#[no_mangle]
pub unsafe extern "C" fn mj_invVelocity(m: *const mjModel, d: *mut mjData) {
    pending("mj_invVelocity");
}

#[no_mangle]
pub unsafe extern "C" fn mj_invConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_invConstraint");
}

#[no_mangle]
pub unsafe extern "C" fn mj_compareFwdInv(m: *const mjModel, d: *mut mjData) {
    pending("mj_compareFwdInv");
}

#[no_mangle]
pub unsafe extern "C" fn mj_sensorPos(m: *const mjModel, d: *mut mjData) {
    pending("mj_sensorPos");
}

#[no_mangle]
pub unsafe extern "C" fn mj_sensorVel(m: *const mjModel, d: *mut mjData) {
    pending("mj_sensorVel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_sensorAcc(m: *const mjModel, d: *mut mjData) {
    pending("mj_sensorAcc");
}

#[no_mangle]
pub unsafe extern "C" fn mj_energyPos(m: *const mjModel, d: *mut mjData) {
    pending("mj_energyPos");
}

#[no_mangle]
pub unsafe extern "C" fn mj_energyVel(m: *const mjModel, d: *mut mjData) {
    pending("mj_energyVel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_checkPos(m: *const mjModel, d: *mut mjData) {
    pending("mj_checkPos");
}

#[no_mangle]
pub unsafe extern "C" fn mj_checkVel(m: *const mjModel, d: *mut mjData) {
    pending("mj_checkVel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_checkAcc(m: *const mjModel, d: *mut mjData) {
    pending("mj_checkAcc");
}

#[no_mangle]
pub unsafe extern "C" fn mj_kinematics(m: *const mjModel, d: *mut mjData) {
    pending("mj_kinematics");
}

#[no_mangle]
pub unsafe extern "C" fn mj_comPos(m: *const mjModel, d: *mut mjData) {
    pending("mj_comPos");
}

#[no_mangle]
pub unsafe extern "C" fn mj_camlight(m: *const mjModel, d: *mut mjData) {
    pending("mj_camlight");
}

#[no_mangle]
pub unsafe extern "C" fn mj_tendon(m: *const mjModel, d: *mut mjData) {
    pending("mj_tendon");
}

#[no_mangle]
pub unsafe extern "C" fn mj_transmission(m: *const mjModel, d: *mut mjData) {
    pending("mj_transmission");
}

#[no_mangle]
pub unsafe extern "C" fn mj_crb(m: *const mjModel, d: *mut mjData) {
    pending("mj_crb");
}

#[no_mangle]
pub unsafe extern "C" fn mj_factorM(m: *const mjModel, d: *mut mjData) {
    pending("mj_factorM");
}

#[no_mangle]
pub unsafe extern "C" fn mj_solveM(m: *const mjModel, d: *mut mjData, x: *mut mjtNum, y: *const mjtNum, n: c_int) {
    pending("mj_solveM");
}

#[no_mangle]
pub unsafe extern "C" fn mj_solveM2(m: *const mjModel, d: *mut mjData, x: *mut mjtNum, y: *const mjtNum, n: c_int) {
    pending("mj_solveM2");
}

#[no_mangle]
pub unsafe extern "C" fn mj_comVel(m: *const mjModel, d: *mut mjData) {
    pending("mj_comVel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_passive(m: *const mjModel, d: *mut mjData) {
    pending("mj_passive");
}

#[no_mangle]
pub unsafe extern "C" fn mj_subtreeVel(m: *const mjModel, d: *mut mjData) {
    pending("mj_subtreeVel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_rne(m: *const mjModel, d: *mut mjData, flg_acc: c_int, result: *mut mjtNum) {
    pending("mj_rne");
}

#[no_mangle]
pub unsafe extern "C" fn mj_rnePostConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_rnePostConstraint");
}

#[no_mangle]
pub unsafe extern "C" fn mj_collision(m: *const mjModel, d: *mut mjData) {
    pending("mj_collision");
}

#[no_mangle]
pub unsafe extern "C" fn mj_makeConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_makeConstraint");
}

#[no_mangle]
pub unsafe extern "C" fn mj_projectConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_projectConstraint");
}

#[no_mangle]
pub unsafe extern "C" fn mj_referenceConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_referenceConstraint");
}

#[no_mangle]
pub unsafe extern "C" fn mj_constraintUpdate(m: *const mjModel, d: *mut mjData, jar: *const mjtNum, cost: *mut mjtNum, flg_coneHessian: c_int) {
    pending("mj_constraintUpdate");
}

#[no_mangle]
pub unsafe extern "C" fn mj_addContact(m: *const mjModel, d: *mut mjData, con: *const mjContact) -> c_int {
    pending("mj_addContact");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_isPyramidal(m: *const mjModel) -> c_int {
    pending("mj_isPyramidal");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_isSparse(m: *const mjModel) -> c_int {
    pending("mj_isSparse");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_isDual(m: *const mjModel) -> c_int {
    pending("mj_isDual");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulJacVec(m: *const mjModel, d: *mut mjData, res: *mut mjtNum, vec: *const mjtNum) {
    pending("mj_mulJacVec");
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulJacTVec(m: *const mjModel, d: *mut mjData, res: *mut mjtNum, vec: *const mjtNum) {
    pending("mj_mulJacTVec");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jac(m: *const mjModel, d: *const mjData, jacp: *mut mjtNum, jacr: *mut mjtNum, point: *const mjtNum, body: c_int) {
    pending("mj_jac");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacBody(m: *const mjModel, d: *const mjData, jacp: *mut mjtNum, jacr: *mut mjtNum, body: c_int) {
    pending("mj_jacBody");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacBodyCom(m: *const mjModel, d: *const mjData, jacp: *mut mjtNum, jacr: *mut mjtNum, body: c_int) {
    pending("mj_jacBodyCom");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacSubtreeCom(m: *const mjModel, d: *mut mjData, jacp: *mut mjtNum, body: c_int) {
    pending("mj_jacSubtreeCom");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacGeom(m: *const mjModel, d: *const mjData, jacp: *mut mjtNum, jacr: *mut mjtNum, geom: c_int) {
    pending("mj_jacGeom");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacSite(m: *const mjModel, d: *const mjData, jacp: *mut mjtNum, jacr: *mut mjtNum, site: c_int) {
    pending("mj_jacSite");
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacPointAxis(m: *const mjModel, d: *mut mjData, jacPoint: *mut mjtNum, jacAxis: *mut mjtNum, point: *const mjtNum, axis: *const mjtNum, body: c_int) {
    pending("mj_jacPointAxis");
}

#[no_mangle]
pub unsafe extern "C" fn mj_name2id(m: *const mjModel, type_: c_int, name: *const c_char) -> c_int {
    pending("mj_name2id");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_id2name(m: *const mjModel, type_: c_int, id: c_int) -> *const c_char {
    pending("mj_id2name");
    std::ptr::null()
}

#[no_mangle]
pub unsafe extern "C" fn mj_fullM(m: *const mjModel, dst: *mut mjtNum, M: *const mjtNum) {
    pending("mj_fullM");
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulM(m: *const mjModel, d: *const mjData, res: *mut mjtNum, vec: *const mjtNum) {
    pending("mj_mulM");
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulM2(m: *const mjModel, d: *const mjData, res: *mut mjtNum, vec: *const mjtNum) {
    pending("mj_mulM2");
}

#[no_mangle]
pub unsafe extern "C" fn mj_addM(m: *const mjModel, d: *mut mjData, dst: *mut mjtNum, rownnz: *mut c_int, rowadr: *mut c_int, colind: *mut c_int) {
    pending("mj_addM");
}

#[no_mangle]
pub unsafe extern "C" fn mj_applyFT(m: *const mjModel, d: *mut mjData, force: *const mjtNum, torque: *const mjtNum, point: *const mjtNum, body: c_int, qfrc_target: *mut mjtNum) {
    pending("mj_applyFT");
}

#[no_mangle]
pub unsafe extern "C" fn mj_objectVelocity(m: *const mjModel, d: *const mjData, objtype: c_int, objid: c_int, res: *mut mjtNum, flg_local: c_int) {
    pending("mj_objectVelocity");
}

#[no_mangle]
pub unsafe extern "C" fn mj_objectAcceleration(m: *const mjModel, d: *const mjData, objtype: c_int, objid: c_int, res: *mut mjtNum, flg_local: c_int) {
    pending("mj_objectAcceleration");
}

#[no_mangle]
pub unsafe extern "C" fn mj_contactForce(m: *const mjModel, d: *const mjData, id: c_int, result: *mut mjtNum) {
    pending("mj_contactForce");
}

#[no_mangle]
pub unsafe extern "C" fn mj_differentiatePos(m: *const mjModel, qvel: *mut mjtNum, dt: mjtNum, qpos1: *const mjtNum, qpos2: *const mjtNum) {
    pending("mj_differentiatePos");
}

#[no_mangle]
pub unsafe extern "C" fn mj_integratePos(m: *const mjModel, qpos: *mut mjtNum, qvel: *const mjtNum, dt: mjtNum) {
    pending("mj_integratePos");
}

#[no_mangle]
pub unsafe extern "C" fn mj_normalizeQuat(m: *const mjModel, qpos: *mut mjtNum) {
    pending("mj_normalizeQuat");
}

#[no_mangle]
pub unsafe extern "C" fn mj_local2Global(d: *mut mjData, xpos: *mut mjtNum, xmat: *mut mjtNum, pos: *const mjtNum, quat: *const mjtNum, body: c_int, sameframe: mjtByte) {
    pending("mj_local2Global");
}

#[no_mangle]
pub unsafe extern "C" fn mj_getTotalmass(m: *const mjModel) -> mjtNum {
    pending("mj_getTotalmass");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mj_setTotalmass(m: *mut mjModel, newmass: mjtNum) {
    pending("mj_setTotalmass");
}

#[no_mangle]
pub unsafe extern "C" fn mj_ray(m: *const mjModel, d: *const mjData, pnt: *const mjtNum, vec: *const mjtNum, geomgroup: *const mjtByte, flg_static: mjtByte, bodyexclude: c_int, geomid: *mut c_int) -> mjtNum {
    pending("mj_ray");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mj_rayHfield(m: *const mjModel, d: *const mjData, geomid: c_int, pnt: *const mjtNum, vec: *const mjtNum) -> mjtNum {
    pending("mj_rayHfield");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mj_rayMesh(m: *const mjModel, d: *const mjData, geomid: c_int, pnt: *const mjtNum, vec: *const mjtNum) -> mjtNum {
    pending("mj_rayMesh");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_rayGeom(pos: *const mjtNum, mat: *const mjtNum, size: *const mjtNum, pnt: *const mjtNum, vec: *const mjtNum, geomtype: c_int) -> mjtNum {
    pending("mju_rayGeom");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_raySkin(nface: c_int, nvert: c_int, face: *const c_int, vert: *const f32, pnt: *const mjtNum, vec: *const mjtNum, vertid: *mut c_int) -> mjtNum {
    pending("mju_raySkin");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mj_warning(d: *mut mjData, warning: c_int, info: c_int) {
    pending("mj_warning");
}

#[no_mangle]
pub unsafe extern "C" fn mj_activate(filename: *const c_char) -> c_int {
    pending("mj_activate");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_deactivate() {
    pending("mj_deactivate");
}

#[no_mangle]
pub unsafe extern "C" fn mjd_transitionFD(m: *const mjModel, d: *mut mjData, eps: mjtNum, centered: mjtByte, A: *mut mjtNum, B: *mut mjtNum, C: *mut mjtNum, D: *mut mjtNum) {
    pending("mjd_transitionFD");
}
