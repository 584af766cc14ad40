//! Entry points of the 2.2.2 API not implemented yet: each reports that through `mju_error`.

#![allow(unused_variables)]

use crate::abi::*;
use std::os::raw::{c_char, c_int, c_void};

use super::pending;

#[no_mangle]
pub unsafe extern "C" fn mj_defaultVFS(vfs: *mut mjVFS) {
    pending("mj_defaultVFS");
}

#[no_mangle]
pub unsafe extern "C" fn mj_addFileVFS(vfs: *mut mjVFS, directory: *const c_char, filename: *const c_char) -> c_int {
    pending("mj_addFileVFS");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_makeEmptyFileVFS(vfs: *mut mjVFS, filename: *const c_char, filesize: c_int) -> c_int {
    pending("mj_makeEmptyFileVFS");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_findFileVFS(vfs: *const mjVFS, filename: *const c_char) -> c_int {
    pending("mj_findFileVFS");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteFileVFS(vfs: *mut mjVFS, filename: *const c_char) -> c_int {
    pending("mj_deleteFileVFS");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteVFS(vfs: *mut mjVFS) {
    pending("mj_deleteVFS");
}

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
pub unsafe extern "C" fn mj_inverse(m: *const mjModel, d: *mut mjData) {
    pending("mj_inverse");
}

#[no_mangle]
pub unsafe extern "C" fn mj_inverseSkip(m: *const mjModel, d: *mut mjData, skipstage: c_int, skipsensor: c_int) {
    pending("mj_inverseSkip");
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultLROpt(opt: *mut mjLROpt) {
    pending("mj_defaultLROpt");
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultSolRefImp(solref: *mut mjtNum, solimp: *mut mjtNum) {
    pending("mj_defaultSolRefImp");
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultOption(opt: *mut mjOption) {
    pending("mj_defaultOption");
}

#[no_mangle]
pub unsafe extern "C" fn mj_defaultVisual(vis: *mut mjVisual) {
    pending("mj_defaultVisual");
}

#[no_mangle]
pub unsafe extern "C" fn mj_copyModel(dest: *mut mjModel, src: *const mjModel) -> *mut mjModel {
    pending("mj_copyModel");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mj_saveModel(m: *const mjModel, filename: *const c_char, buffer: *mut c_void, buffer_sz: c_int) {
    pending("mj_saveModel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_loadModel(filename: *const c_char, vfs: *const mjVFS) -> *mut mjModel {
    pending("mj_loadModel");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteModel(m: *mut mjModel) {
    pending("mj_deleteModel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_sizeModel(m: *const mjModel) -> c_int {
    pending("mj_sizeModel");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_makeData(m: *const mjModel) -> *mut mjData {
    pending("mj_makeData");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mj_copyData(dest: *mut mjData, m: *const mjModel, src: *const mjData) -> *mut mjData {
    pending("mj_copyData");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetData(m: *const mjModel, d: *mut mjData) {
    pending("mj_resetData");
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetDataDebug(m: *const mjModel, d: *mut mjData, debug_value: std::os::raw::c_uchar) {
    pending("mj_resetDataDebug");
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetDataKeyframe(m: *const mjModel, d: *mut mjData, key: c_int) {
    pending("mj_resetDataKeyframe");
}

#[no_mangle]
pub unsafe extern "C" fn mj_stackAlloc(d: *mut mjData, size: c_int) -> *mut mjtNum {
    pending("mj_stackAlloc");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mj_deleteData(d: *mut mjData) {
    pending("mj_deleteData");
}

#[no_mangle]
pub unsafe extern "C" fn mj_resetCallbacks() {
    pending("mj_resetCallbacks");
}

#[no_mangle]
pub unsafe extern "C" fn mj_setLengthRange(m: *mut mjModel, d: *mut mjData, index: c_int, opt: *const mjLROpt, error: *mut c_char, error_sz: c_int) -> c_int {
    pending("mj_setLengthRange");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_printFormattedModel(m: *const mjModel, filename: *const c_char, float_format: *const c_char) {
    pending("mj_printFormattedModel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_printModel(m: *const mjModel, filename: *const c_char) {
    pending("mj_printModel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_printFormattedData(m: *const mjModel, d: *mut mjData, filename: *const c_char, float_format: *const c_char) {
    pending("mj_printFormattedData");
}

#[no_mangle]
pub unsafe extern "C" fn mj_printData(m: *const mjModel, d: *mut mjData, filename: *const c_char) {
    pending("mj_printData");
}

#[no_mangle]
pub unsafe extern "C" fn mju_printMat(mat: *const mjtNum, nr: c_int, nc: c_int) {
    pending("mju_printMat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_printMatSparse(mat: *const mjtNum, nr: c_int, rownnz: *const c_int, rowadr: *const c_int, colind: *const c_int) {
    pending("mju_printMatSparse");
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
pub unsafe extern "C" fn mj_subtreeVel(m: *const mjModel, d: *mut mjData) {
    pending("mj_subtreeVel");
}

#[no_mangle]
pub unsafe extern "C" fn mj_rnePostConstraint(m: *const mjModel, d: *mut mjData) {
    pending("mj_rnePostConstraint");
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
pub unsafe extern "C" fn mj_version() -> c_int {
    pending("mj_version");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_versionString() -> *const c_char {
    pending("mj_versionString");
    std::ptr::null()
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
pub unsafe extern "C" fn mj_activate(filename: *const c_char) -> c_int {
    pending("mj_activate");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_deactivate() {
    pending("mj_deactivate");
}

#[no_mangle]
pub unsafe extern "C" fn mju_zero3(res: *mut mjtNum) {
    pending("mju_zero3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_copy3(res: *mut mjtNum, data: *const mjtNum) {
    pending("mju_copy3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_scl3(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum) {
    pending("mju_scl3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_add3(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum) {
    pending("mju_add3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_sub3(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum) {
    pending("mju_sub3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_addTo3(res: *mut mjtNum, vec: *const mjtNum) {
    pending("mju_addTo3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_subFrom3(res: *mut mjtNum, vec: *const mjtNum) {
    pending("mju_subFrom3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_addToScl3(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum) {
    pending("mju_addToScl3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_addScl3(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum, scl: mjtNum) {
    pending("mju_addScl3");
}

#[no_mangle]
pub unsafe extern "C" fn mju_normalize3(res: *mut mjtNum) -> mjtNum {
    pending("mju_normalize3");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_norm3(vec: *const mjtNum) -> mjtNum {
    pending("mju_norm3");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_dot3(vec1: *const mjtNum, vec2: *const mjtNum) -> mjtNum {
    pending("mju_dot3");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_dist3(pos1: *const mjtNum, pos2: *const mjtNum) -> mjtNum {
    pending("mju_dist3");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_rotVecMat(res: *mut mjtNum, vec: *const mjtNum, mat: *const mjtNum) {
    pending("mju_rotVecMat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_rotVecMatT(res: *mut mjtNum, vec: *const mjtNum, mat: *const mjtNum) {
    pending("mju_rotVecMatT");
}

#[no_mangle]
pub unsafe extern "C" fn mju_cross(res: *mut mjtNum, a: *const mjtNum, b: *const mjtNum) {
    pending("mju_cross");
}

#[no_mangle]
pub unsafe extern "C" fn mju_zero4(res: *mut mjtNum) {
    pending("mju_zero4");
}

#[no_mangle]
pub unsafe extern "C" fn mju_unit4(res: *mut mjtNum) {
    pending("mju_unit4");
}

#[no_mangle]
pub unsafe extern "C" fn mju_copy4(res: *mut mjtNum, data: *const mjtNum) {
    pending("mju_copy4");
}

#[no_mangle]
pub unsafe extern "C" fn mju_normalize4(res: *mut mjtNum) -> mjtNum {
    pending("mju_normalize4");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_zero(res: *mut mjtNum, n: c_int) {
    pending("mju_zero");
}

#[no_mangle]
pub unsafe extern "C" fn mju_copy(res: *mut mjtNum, data: *const mjtNum, n: c_int) {
    pending("mju_copy");
}

#[no_mangle]
pub unsafe extern "C" fn mju_sum(vec: *const mjtNum, n: c_int) -> mjtNum {
    pending("mju_sum");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_L1(vec: *const mjtNum, n: c_int) -> mjtNum {
    pending("mju_L1");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_scl(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum, n: c_int) {
    pending("mju_scl");
}

#[no_mangle]
pub unsafe extern "C" fn mju_add(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum, n: c_int) {
    pending("mju_add");
}

#[no_mangle]
pub unsafe extern "C" fn mju_sub(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum, n: c_int) {
    pending("mju_sub");
}

#[no_mangle]
pub unsafe extern "C" fn mju_addTo(res: *mut mjtNum, vec: *const mjtNum, n: c_int) {
    pending("mju_addTo");
}

#[no_mangle]
pub unsafe extern "C" fn mju_subFrom(res: *mut mjtNum, vec: *const mjtNum, n: c_int) {
    pending("mju_subFrom");
}

#[no_mangle]
pub unsafe extern "C" fn mju_addToScl(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum, n: c_int) {
    pending("mju_addToScl");
}

#[no_mangle]
pub unsafe extern "C" fn mju_addScl(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum, scl: mjtNum, n: c_int) {
    pending("mju_addScl");
}

#[no_mangle]
pub unsafe extern "C" fn mju_normalize(res: *mut mjtNum, n: c_int) -> mjtNum {
    pending("mju_normalize");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_norm(res: *const mjtNum, n: c_int) -> mjtNum {
    pending("mju_norm");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_dot(vec1: *const mjtNum, vec2: *const mjtNum, n: c_int) -> mjtNum {
    pending("mju_dot");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatVec(res: *mut mjtNum, mat: *const mjtNum, vec: *const mjtNum, nr: c_int, nc: c_int) {
    pending("mju_mulMatVec");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatTVec(res: *mut mjtNum, mat: *const mjtNum, vec: *const mjtNum, nr: c_int, nc: c_int) {
    pending("mju_mulMatTVec");
}

#[no_mangle]
pub unsafe extern "C" fn mju_transpose(res: *mut mjtNum, mat: *const mjtNum, nr: c_int, nc: c_int) {
    pending("mju_transpose");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatMat(res: *mut mjtNum, mat1: *const mjtNum, mat2: *const mjtNum, r1: c_int, c1: c_int, c2: c_int) {
    pending("mju_mulMatMat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatMatT(res: *mut mjtNum, mat1: *const mjtNum, mat2: *const mjtNum, r1: c_int, c1: c_int, r2: c_int) {
    pending("mju_mulMatMatT");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatTMat(res: *mut mjtNum, mat1: *const mjtNum, mat2: *const mjtNum, r1: c_int, c1: c_int, c2: c_int) {
    pending("mju_mulMatTMat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_sqrMatTD(res: *mut mjtNum, mat: *const mjtNum, diag: *const mjtNum, nr: c_int, nc: c_int) {
    pending("mju_sqrMatTD");
}

#[no_mangle]
pub unsafe extern "C" fn mju_transformSpatial(res: *mut mjtNum, vec: *const mjtNum, flg_force: c_int, newpos: *const mjtNum, oldpos: *const mjtNum, rotnew2old: *const mjtNum) {
    pending("mju_transformSpatial");
}

#[no_mangle]
pub unsafe extern "C" fn mju_rotVecQuat(res: *mut mjtNum, vec: *const mjtNum, quat: *const mjtNum) {
    pending("mju_rotVecQuat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_negQuat(res: *mut mjtNum, quat: *const mjtNum) {
    pending("mju_negQuat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulQuat(res: *mut mjtNum, quat1: *const mjtNum, quat2: *const mjtNum) {
    pending("mju_mulQuat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulQuatAxis(res: *mut mjtNum, quat: *const mjtNum, axis: *const mjtNum) {
    pending("mju_mulQuatAxis");
}

#[no_mangle]
pub unsafe extern "C" fn mju_axisAngle2Quat(res: *mut mjtNum, axis: *const mjtNum, angle: mjtNum) {
    pending("mju_axisAngle2Quat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_quat2Vel(res: *mut mjtNum, quat: *const mjtNum, dt: mjtNum) {
    pending("mju_quat2Vel");
}

#[no_mangle]
pub unsafe extern "C" fn mju_subQuat(res: *mut mjtNum, qa: *const mjtNum, qb: *const mjtNum) {
    pending("mju_subQuat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_quat2Mat(res: *mut mjtNum, quat: *const mjtNum) {
    pending("mju_quat2Mat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mat2Quat(quat: *mut mjtNum, mat: *const mjtNum) {
    pending("mju_mat2Quat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_derivQuat(res: *mut mjtNum, quat: *const mjtNum, vel: *const mjtNum) {
    pending("mju_derivQuat");
}

#[no_mangle]
pub unsafe extern "C" fn mju_quatIntegrate(quat: *mut mjtNum, vel: *const mjtNum, scale: mjtNum) {
    pending("mju_quatIntegrate");
}

#[no_mangle]
pub unsafe extern "C" fn mju_quatZ2Vec(quat: *mut mjtNum, vec: *const mjtNum) {
    pending("mju_quatZ2Vec");
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulPose(posres: *mut mjtNum, quatres: *mut mjtNum, pos1: *const mjtNum, quat1: *const mjtNum, pos2: *const mjtNum, quat2: *const mjtNum) {
    pending("mju_mulPose");
}

#[no_mangle]
pub unsafe extern "C" fn mju_negPose(posres: *mut mjtNum, quatres: *mut mjtNum, pos: *const mjtNum, quat: *const mjtNum) {
    pending("mju_negPose");
}

#[no_mangle]
pub unsafe extern "C" fn mju_trnVecPose(res: *mut mjtNum, pos: *const mjtNum, quat: *const mjtNum, vec: *const mjtNum) {
    pending("mju_trnVecPose");
}

#[no_mangle]
pub unsafe extern "C" fn mju_cholFactor(mat: *mut mjtNum, n: c_int, mindiag: mjtNum) -> c_int {
    pending("mju_cholFactor");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_cholSolve(res: *mut mjtNum, mat: *const mjtNum, vec: *const mjtNum, n: c_int) {
    pending("mju_cholSolve");
}

#[no_mangle]
pub unsafe extern "C" fn mju_cholUpdate(mat: *mut mjtNum, x: *mut mjtNum, n: c_int, flg_plus: c_int) -> c_int {
    pending("mju_cholUpdate");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_eig3(eigval: *mut mjtNum, eigvec: *mut mjtNum, quat: *mut mjtNum, mat: *const mjtNum) -> c_int {
    pending("mju_eig3");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_muscleGain(len: mjtNum, vel: mjtNum, lengthrange: *const mjtNum, acc0: mjtNum, prm: *const mjtNum) -> mjtNum {
    pending("mju_muscleGain");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_muscleBias(len: mjtNum, lengthrange: *const mjtNum, acc0: mjtNum, prm: *const mjtNum) -> mjtNum {
    pending("mju_muscleBias");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_muscleDynamics(ctrl: mjtNum, act: mjtNum, prm: *const mjtNum) -> mjtNum {
    pending("mju_muscleDynamics");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_encodePyramid(pyramid: *mut mjtNum, force: *const mjtNum, mu: *const mjtNum, dim: c_int) {
    pending("mju_encodePyramid");
}

#[no_mangle]
pub unsafe extern "C" fn mju_decodePyramid(force: *mut mjtNum, pyramid: *const mjtNum, mu: *const mjtNum, dim: c_int) {
    pending("mju_decodePyramid");
}

#[no_mangle]
pub unsafe extern "C" fn mju_springDamper(pos0: mjtNum, vel0: mjtNum, Kp: mjtNum, Kv: mjtNum, dt: mjtNum) -> mjtNum {
    pending("mju_springDamper");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_min(a: mjtNum, b: mjtNum) -> mjtNum {
    pending("mju_min");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_max(a: mjtNum, b: mjtNum) -> mjtNum {
    pending("mju_max");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_clip(x: mjtNum, min: mjtNum, max: mjtNum) -> mjtNum {
    pending("mju_clip");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_sign(x: mjtNum) -> mjtNum {
    pending("mju_sign");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_round(x: mjtNum) -> c_int {
    pending("mju_round");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_type2Str(type_: c_int) -> *const c_char {
    pending("mju_type2Str");
    std::ptr::null()
}

#[no_mangle]
pub unsafe extern "C" fn mju_str2Type(str: *const c_char) -> c_int {
    pending("mju_str2Type");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_warningText(warning: c_int, info: c_int) -> *const c_char {
    pending("mju_warningText");
    std::ptr::null()
}

#[no_mangle]
pub unsafe extern "C" fn mju_isBad(x: mjtNum) -> c_int {
    pending("mju_isBad");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_isZero(vec: *mut mjtNum, n: c_int) -> c_int {
    pending("mju_isZero");
    0 as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_standardNormal(num2: *mut mjtNum) -> mjtNum {
    pending("mju_standardNormal");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_f2n(res: *mut mjtNum, vec: *const f32, n: c_int) {
    pending("mju_f2n");
}

#[no_mangle]
pub unsafe extern "C" fn mju_n2f(res: *mut f32, vec: *const mjtNum, n: c_int) {
    pending("mju_n2f");
}

#[no_mangle]
pub unsafe extern "C" fn mju_d2n(res: *mut mjtNum, vec: *const f64, n: c_int) {
    pending("mju_d2n");
}

#[no_mangle]
pub unsafe extern "C" fn mju_n2d(res: *mut f64, vec: *const mjtNum, n: c_int) {
    pending("mju_n2d");
}

#[no_mangle]
pub unsafe extern "C" fn mju_insertionSort(list: *mut mjtNum, n: c_int) {
    pending("mju_insertionSort");
}

#[no_mangle]
pub unsafe extern "C" fn mju_insertionSortInt(list: *mut c_int, n: c_int) {
    pending("mju_insertionSortInt");
}

#[no_mangle]
pub unsafe extern "C" fn mju_Halton(index: c_int, base: c_int) -> mjtNum {
    pending("mju_Halton");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mju_strncpy(dst: *mut c_char, src: *const c_char, n: c_int) -> *mut c_char {
    pending("mju_strncpy");
    std::ptr::null_mut()
}

#[no_mangle]
pub unsafe extern "C" fn mju_sigmoid(x: mjtNum) -> mjtNum {
    pending("mju_sigmoid");
    0.0
}

#[no_mangle]
pub unsafe extern "C" fn mjd_transitionFD(m: *const mjModel, d: *mut mjData, eps: mjtNum, centered: mjtByte, A: *mut mjtNum, B: *mut mjtNum, C: *mut mjtNum, D: *mut mjtNum) {
    pending("mjd_transitionFD");
}
