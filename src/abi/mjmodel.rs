#![allow(non_camel_case_types, non_snake_case, non_upper_case_globals)]

use super::mjtnum::mjtNum;
use std::os::raw::{c_char, c_int, c_void};

/// Boolean flag type.
pub type mjtByte = std::os::raw::c_uchar;

#[allow(clippy::approx_constant, clippy::excessive_precision)]
pub const mjPI: f64 = 3.14159265358979323846;
pub const mjMAXVAL: f64 = 1.0E10;
pub const mjMINMU: f64 = 1.0E-5;
pub const mjMINIMP: f64 = 0.0001;
pub const mjMAXIMP: f64 = 0.9999;
pub const mjMAXCONPAIR: usize = 50;
pub const mjMAXVFS: usize = 2000;
pub const mjMAXVFSNAME: usize = 1000;
pub const mjNEQDATA: usize = 11;
pub const mjNDYN: usize = 10;
pub const mjNGAIN: usize = 10;
pub const mjNBIAS: usize = 10;
pub const mjNFLUID: usize = 12;
pub const mjNREF: usize = 2;
pub const mjNIMP: usize = 5;
pub const mjNSOLVER: usize = 1000;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtDisableBit_ {
    mjDSBL_CONSTRAINT = 1,
    mjDSBL_EQUALITY = 2,
    mjDSBL_FRICTIONLOSS = 4,
    mjDSBL_LIMIT = 8,
    mjDSBL_CONTACT = 16,
    mjDSBL_PASSIVE = 32,
    mjDSBL_GRAVITY = 64,
    mjDSBL_CLAMPCTRL = 128,
    mjDSBL_WARMSTART = 256,
    mjDSBL_FILTERPARENT = 512,
    mjDSBL_ACTUATION = 1024,
    mjDSBL_REFSAFE = 2048,
    mjDSBL_SENSOR = 4096,
    mjNDISABLE = 13,
}
pub type mjtDisableBit = mjtDisableBit_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtEnableBit_ {
    mjENBL_OVERRIDE = 1,
    mjENBL_ENERGY = 2,
    mjENBL_FWDINV = 4,
    mjENBL_SENSORNOISE = 8,
    mjENBL_MULTICCD = 16,
    mjNENABLE = 5,
}
pub type mjtEnableBit = mjtEnableBit_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtJoint_ {
    mjJNT_FREE = 0,
    mjJNT_BALL = 1,
    mjJNT_SLIDE = 2,
    mjJNT_HINGE = 3,
}
pub type mjtJoint = mjtJoint_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtGeom_ {
    mjGEOM_PLANE = 0,
    mjGEOM_HFIELD = 1,
    mjGEOM_SPHERE = 2,
    mjGEOM_CAPSULE = 3,
    mjGEOM_ELLIPSOID = 4,
    mjGEOM_CYLINDER = 5,
    mjGEOM_BOX = 6,
    mjGEOM_MESH = 7,
    mjNGEOMTYPES = 8,
    mjGEOM_ARROW = 100,
    mjGEOM_ARROW1 = 101,
    mjGEOM_ARROW2 = 102,
    mjGEOM_LINE = 103,
    mjGEOM_SKIN = 104,
    mjGEOM_LABEL = 105,
    mjGEOM_NONE = 1001,
}
pub type mjtGeom = mjtGeom_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtCamLight_ {
    mjCAMLIGHT_FIXED = 0,
    mjCAMLIGHT_TRACK = 1,
    mjCAMLIGHT_TRACKCOM = 2,
    mjCAMLIGHT_TARGETBODY = 3,
    mjCAMLIGHT_TARGETBODYCOM = 4,
}
pub type mjtCamLight = mjtCamLight_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtTexture_ {
    mjTEXTURE_2D = 0,
    mjTEXTURE_CUBE = 1,
    mjTEXTURE_SKYBOX = 2,
}
pub type mjtTexture = mjtTexture_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtIntegrator_ {
    mjINT_EULER = 0,
    mjINT_RK4 = 1,
    mjINT_IMPLICIT = 2,
}
pub type mjtIntegrator = mjtIntegrator_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtCollision_ {
    mjCOL_ALL = 0,
    mjCOL_PAIR = 1,
    mjCOL_DYNAMIC = 2,
}
pub type mjtCollision = mjtCollision_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtCone_ {
    mjCONE_PYRAMIDAL = 0,
    mjCONE_ELLIPTIC = 1,
}
pub type mjtCone = mjtCone_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtJacobian_ {
    mjJAC_DENSE = 0,
    mjJAC_SPARSE = 1,
    mjJAC_AUTO = 2,
}
pub type mjtJacobian = mjtJacobian_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtSolver_ {
    mjSOL_PGS = 0,
    mjSOL_CG = 1,
    mjSOL_NEWTON = 2,
}
pub type mjtSolver = mjtSolver_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtEq_ {
    mjEQ_CONNECT = 0,
    mjEQ_WELD = 1,
    mjEQ_JOINT = 2,
    mjEQ_TENDON = 3,
    mjEQ_DISTANCE = 4,
}
pub type mjtEq = mjtEq_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtWrap_ {
    mjWRAP_NONE = 0,
    mjWRAP_JOINT = 1,
    mjWRAP_PULLEY = 2,
    mjWRAP_SITE = 3,
    mjWRAP_SPHERE = 4,
    mjWRAP_CYLINDER = 5,
}
pub type mjtWrap = mjtWrap_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtTrn_ {
    mjTRN_JOINT = 0,
    mjTRN_JOINTINPARENT = 1,
    mjTRN_SLIDERCRANK = 2,
    mjTRN_TENDON = 3,
    mjTRN_SITE = 4,
    mjTRN_BODY = 5,
    mjTRN_UNDEFINED = 1000,
}
pub type mjtTrn = mjtTrn_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtDyn_ {
    mjDYN_NONE = 0,
    mjDYN_INTEGRATOR = 1,
    mjDYN_FILTER = 2,
    mjDYN_MUSCLE = 3,
    mjDYN_USER = 4,
}
pub type mjtDyn = mjtDyn_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtGain_ {
    mjGAIN_FIXED = 0,
    mjGAIN_AFFINE = 1,
    mjGAIN_MUSCLE = 2,
    mjGAIN_USER = 3,
}
pub type mjtGain = mjtGain_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtBias_ {
    mjBIAS_NONE = 0,
    mjBIAS_AFFINE = 1,
    mjBIAS_MUSCLE = 2,
    mjBIAS_USER = 3,
}
pub type mjtBias = mjtBias_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtObj_ {
    mjOBJ_UNKNOWN = 0,
    mjOBJ_BODY = 1,
    mjOBJ_XBODY = 2,
    mjOBJ_JOINT = 3,
    mjOBJ_DOF = 4,
    mjOBJ_GEOM = 5,
    mjOBJ_SITE = 6,
    mjOBJ_CAMERA = 7,
    mjOBJ_LIGHT = 8,
    mjOBJ_MESH = 9,
    mjOBJ_SKIN = 10,
    mjOBJ_HFIELD = 11,
    mjOBJ_TEXTURE = 12,
    mjOBJ_MATERIAL = 13,
    mjOBJ_PAIR = 14,
    mjOBJ_EXCLUDE = 15,
    mjOBJ_EQUALITY = 16,
    mjOBJ_TENDON = 17,
    mjOBJ_ACTUATOR = 18,
    mjOBJ_SENSOR = 19,
    mjOBJ_NUMERIC = 20,
    mjOBJ_TEXT = 21,
    mjOBJ_TUPLE = 22,
    mjOBJ_KEY = 23,
}
pub type mjtObj = mjtObj_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtConstraint_ {
    mjCNSTR_EQUALITY = 0,
    mjCNSTR_FRICTION_DOF = 1,
    mjCNSTR_FRICTION_TENDON = 2,
    mjCNSTR_LIMIT_JOINT = 3,
    mjCNSTR_LIMIT_TENDON = 4,
    mjCNSTR_CONTACT_FRICTIONLESS = 5,
    mjCNSTR_CONTACT_PYRAMIDAL = 6,
    mjCNSTR_CONTACT_ELLIPTIC = 7,
}
pub type mjtConstraint = mjtConstraint_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtConstraintState_ {
    mjCNSTRSTATE_SATISFIED = 0,
    mjCNSTRSTATE_QUADRATIC = 1,
    mjCNSTRSTATE_LINEARNEG = 2,
    mjCNSTRSTATE_LINEARPOS = 3,
    mjCNSTRSTATE_CONE = 4,
}
pub type mjtConstraintState = mjtConstraintState_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtSensor_ {
    mjSENS_TOUCH = 0,
    mjSENS_ACCELEROMETER = 1,
    mjSENS_VELOCIMETER = 2,
    mjSENS_GYRO = 3,
    mjSENS_FORCE = 4,
    mjSENS_TORQUE = 5,
    mjSENS_MAGNETOMETER = 6,
    mjSENS_RANGEFINDER = 7,
    mjSENS_JOINTPOS = 8,
    mjSENS_JOINTVEL = 9,
    mjSENS_TENDONPOS = 10,
    mjSENS_TENDONVEL = 11,
    mjSENS_ACTUATORPOS = 12,
    mjSENS_ACTUATORVEL = 13,
    mjSENS_ACTUATORFRC = 14,
    mjSENS_BALLQUAT = 15,
    mjSENS_BALLANGVEL = 16,
    mjSENS_JOINTLIMITPOS = 17,
    mjSENS_JOINTLIMITVEL = 18,
    mjSENS_JOINTLIMITFRC = 19,
    mjSENS_TENDONLIMITPOS = 20,
    mjSENS_TENDONLIMITVEL = 21,
    mjSENS_TENDONLIMITFRC = 22,
    mjSENS_FRAMEPOS = 23,
    mjSENS_FRAMEQUAT = 24,
    mjSENS_FRAMEXAXIS = 25,
    mjSENS_FRAMEYAXIS = 26,
    mjSENS_FRAMEZAXIS = 27,
    mjSENS_FRAMELINVEL = 28,
    mjSENS_FRAMEANGVEL = 29,
    mjSENS_FRAMELINACC = 30,
    mjSENS_FRAMEANGACC = 31,
    mjSENS_SUBTREECOM = 32,
    mjSENS_SUBTREELINVEL = 33,
    mjSENS_SUBTREEANGMOM = 34,
    mjSENS_CLOCK = 35,
    mjSENS_USER = 36,
}
pub type mjtSensor = mjtSensor_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtStage_ {
    mjSTAGE_NONE = 0,
    mjSTAGE_POS = 1,
    mjSTAGE_VEL = 2,
    mjSTAGE_ACC = 3,
}
pub type mjtStage = mjtStage_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtDataType_ {
    mjDATATYPE_REAL = 0,
    mjDATATYPE_POSITIVE = 1,
    mjDATATYPE_AXIS = 2,
    mjDATATYPE_QUATERNION = 3,
}
pub type mjtDataType = mjtDataType_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtLRMode_ {
    mjLRMODE_NONE = 0,
    mjLRMODE_MUSCLE = 1,
    mjLRMODE_MUSCLEUSER = 2,
    mjLRMODE_ALL = 3,
}
pub type mjtLRMode = mjtLRMode_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjLROpt_ {
    pub mode: c_int,
    pub useexisting: c_int,
    pub uselimit: c_int,
    pub accel: mjtNum,
    pub maxforce: mjtNum,
    pub timeconst: mjtNum,
    pub timestep: mjtNum,
    pub inttotal: mjtNum,
    pub inteval: mjtNum,
    pub tolrange: mjtNum,
}
pub type mjLROpt = mjLROpt_;

#[repr(C)]
pub struct mjVFS_ {
    pub nfile: c_int,
    pub filename: [[c_char; mjMAXVFSNAME]; mjMAXVFS],
    pub filesize: [c_int; mjMAXVFS],
    pub filedata: [*mut c_void; mjMAXVFS],
}
pub type mjVFS = mjVFS_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjOption_ {
    pub timestep: mjtNum,
    pub apirate: mjtNum,
    pub impratio: mjtNum,
    pub tolerance: mjtNum,
    pub noslip_tolerance: mjtNum,
    pub mpr_tolerance: mjtNum,
    pub gravity: [mjtNum; 3],
    pub wind: [mjtNum; 3],
    pub magnetic: [mjtNum; 3],
    pub density: mjtNum,
    pub viscosity: mjtNum,
    pub o_margin: mjtNum,
    pub o_solref: [mjtNum; mjNREF],
    pub o_solimp: [mjtNum; mjNIMP],
    pub integrator: c_int,
    pub collision: c_int,
    pub cone: c_int,
    pub jacobian: c_int,
    pub solver: c_int,
    pub iterations: c_int,
    pub noslip_iterations: c_int,
    pub mpr_iterations: c_int,
    pub disableflags: c_int,
    pub enableflags: c_int,
}
pub type mjOption = mjOption_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisualGlobal_ {
    pub fovy: f32,
    pub ipd: f32,
    pub azimuth: f32,
    pub elevation: f32,
    pub linewidth: f32,
    pub glow: f32,
    pub offwidth: c_int,
    pub offheight: c_int,
}
pub type mjVisualGlobal = mjVisualGlobal_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisualQuality_ {
    pub shadowsize: c_int,
    pub offsamples: c_int,
    pub numslices: c_int,
    pub numstacks: c_int,
    pub numquads: c_int,
}
pub type mjVisualQuality = mjVisualQuality_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisualHeadlight_ {
    pub ambient: [f32; 3],
    pub diffuse: [f32; 3],
    pub specular: [f32; 3],
    pub active: c_int,
}
pub type mjVisualHeadlight = mjVisualHeadlight_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisualMap_ {
    pub stiffness: f32,
    pub stiffnessrot: f32,
    pub force: f32,
    pub torque: f32,
    pub alpha: f32,
    pub fogstart: f32,
    pub fogend: f32,
    pub znear: f32,
    pub zfar: f32,
    pub haze: f32,
    pub shadowclip: f32,
    pub shadowscale: f32,
    pub actuatortendon: f32,
}
pub type mjVisualMap = mjVisualMap_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisualScale_ {
    pub forcewidth: f32,
    pub contactwidth: f32,
    pub contactheight: f32,
    pub connect: f32,
    pub com: f32,
    pub camera: f32,
    pub light: f32,
    pub selectpoint: f32,
    pub jointlength: f32,
    pub jointwidth: f32,
    pub actuatorlength: f32,
    pub actuatorwidth: f32,
    pub framelength: f32,
    pub framewidth: f32,
    pub constraint: f32,
    pub slidercrank: f32,
}
pub type mjVisualScale = mjVisualScale_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisualRgba_ {
    pub fog: [f32; 4],
    pub haze: [f32; 4],
    pub force: [f32; 4],
    pub inertia: [f32; 4],
    pub joint: [f32; 4],
    pub actuator: [f32; 4],
    pub actuatornegative: [f32; 4],
    pub actuatorpositive: [f32; 4],
    pub com: [f32; 4],
    pub camera: [f32; 4],
    pub light: [f32; 4],
    pub selectpoint: [f32; 4],
    pub connect: [f32; 4],
    pub contactpoint: [f32; 4],
    pub contactforce: [f32; 4],
    pub contactfriction: [f32; 4],
    pub contacttorque: [f32; 4],
    pub contactgap: [f32; 4],
    pub rangefinder: [f32; 4],
    pub constraint: [f32; 4],
    pub slidercrank: [f32; 4],
    pub crankbroken: [f32; 4],
}
pub type mjVisualRgba = mjVisualRgba_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjVisual_ {
    pub global: mjVisualGlobal,
    pub quality: mjVisualQuality,
    pub headlight: mjVisualHeadlight,
    pub map: mjVisualMap,
    pub scale: mjVisualScale,
    pub rgba: mjVisualRgba,
}
pub type mjVisual = mjVisual_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjStatistic_ {
    pub meaninertia: mjtNum,
    pub meanmass: mjtNum,
    pub meansize: mjtNum,
    pub extent: mjtNum,
    pub center: [mjtNum; 3],
}
pub type mjStatistic = mjStatistic_;

#[repr(C)]
pub struct mjModel_ {
    pub nq: c_int,
    pub nv: c_int,
    pub nu: c_int,
    pub na: c_int,
    pub nbody: c_int,
    pub njnt: c_int,
    pub ngeom: c_int,
    pub nsite: c_int,
    pub ncam: c_int,
    pub nlight: c_int,
    pub nmesh: c_int,
    pub nmeshvert: c_int,
    pub nmeshtexvert: c_int,
    pub nmeshface: c_int,
    pub nmeshgraph: c_int,
    pub nskin: c_int,
    pub nskinvert: c_int,
    pub nskintexvert: c_int,
    pub nskinface: c_int,
    pub nskinbone: c_int,
    pub nskinbonevert: c_int,
    pub nhfield: c_int,
    pub nhfielddata: c_int,
    pub ntex: c_int,
    pub ntexdata: c_int,
    pub nmat: c_int,
    pub npair: c_int,
    pub nexclude: c_int,
    pub neq: c_int,
    pub ntendon: c_int,
    pub nwrap: c_int,
    pub nsensor: c_int,
    pub nnumeric: c_int,
    pub nnumericdata: c_int,
    pub ntext: c_int,
    pub ntextdata: c_int,
    pub ntuple: c_int,
    pub ntupledata: c_int,
    pub nkey: c_int,
    pub nmocap: c_int,
    pub nuser_body: c_int,
    pub nuser_jnt: c_int,
    pub nuser_geom: c_int,
    pub nuser_site: c_int,
    pub nuser_cam: c_int,
    pub nuser_tendon: c_int,
    pub nuser_actuator: c_int,
    pub nuser_sensor: c_int,
    pub nnames: c_int,
    pub nM: c_int,
    pub nD: c_int,
    pub nemax: c_int,
    pub njmax: c_int,
    pub nconmax: c_int,
    pub nstack: c_int,
    pub nuserdata: c_int,
    pub nsensordata: c_int,
    pub nbuffer: c_int,
    pub opt: mjOption,
    pub vis: mjVisual,
    pub stat: mjStatistic,
    pub buffer: *mut c_void,
    pub qpos0: *mut mjtNum,
    pub qpos_spring: *mut mjtNum,
    pub body_parentid: *mut c_int,
    pub body_rootid: *mut c_int,
    pub body_weldid: *mut c_int,
    pub body_mocapid: *mut c_int,
    pub body_jntnum: *mut c_int,
    pub body_jntadr: *mut c_int,
    pub body_dofnum: *mut c_int,
    pub body_dofadr: *mut c_int,
    pub body_geomnum: *mut c_int,
    pub body_geomadr: *mut c_int,
    pub body_simple: *mut mjtByte,
    pub body_sameframe: *mut mjtByte,
    pub body_pos: *mut mjtNum,
    pub body_quat: *mut mjtNum,
    pub body_ipos: *mut mjtNum,
    pub body_iquat: *mut mjtNum,
    pub body_mass: *mut mjtNum,
    pub body_subtreemass: *mut mjtNum,
    pub body_inertia: *mut mjtNum,
    pub body_invweight0: *mut mjtNum,
    pub body_user: *mut mjtNum,
    pub jnt_type: *mut c_int,
    pub jnt_qposadr: *mut c_int,
    pub jnt_dofadr: *mut c_int,
    pub jnt_bodyid: *mut c_int,
    pub jnt_group: *mut c_int,
    pub jnt_limited: *mut mjtByte,
    pub jnt_solref: *mut mjtNum,
    pub jnt_solimp: *mut mjtNum,
    pub jnt_pos: *mut mjtNum,
    pub jnt_axis: *mut mjtNum,
    pub jnt_stiffness: *mut mjtNum,
    pub jnt_range: *mut mjtNum,
    pub jnt_margin: *mut mjtNum,
    pub jnt_user: *mut mjtNum,
    pub dof_bodyid: *mut c_int,
    pub dof_jntid: *mut c_int,
    pub dof_parentid: *mut c_int,
    pub dof_Madr: *mut c_int,
    pub dof_simplenum: *mut c_int,
    pub dof_solref: *mut mjtNum,
    pub dof_solimp: *mut mjtNum,
    pub dof_frictionloss: *mut mjtNum,
    pub dof_armature: *mut mjtNum,
    pub dof_damping: *mut mjtNum,
    pub dof_invweight0: *mut mjtNum,
    pub dof_M0: *mut mjtNum,
    pub geom_type: *mut c_int,
    pub geom_contype: *mut c_int,
    pub geom_conaffinity: *mut c_int,
    pub geom_condim: *mut c_int,
    pub geom_bodyid: *mut c_int,
    pub geom_dataid: *mut c_int,
    pub geom_matid: *mut c_int,
    pub geom_group: *mut c_int,
    pub geom_priority: *mut c_int,
    pub geom_sameframe: *mut mjtByte,
    pub geom_solmix: *mut mjtNum,
    pub geom_solref: *mut mjtNum,
    pub geom_solimp: *mut mjtNum,
    pub geom_size: *mut mjtNum,
    pub geom_rbound: *mut mjtNum,
    pub geom_pos: *mut mjtNum,
    pub geom_quat: *mut mjtNum,
    pub geom_friction: *mut mjtNum,
    pub geom_margin: *mut mjtNum,
    pub geom_gap: *mut mjtNum,
    pub geom_fluid: *mut mjtNum,
    pub geom_user: *mut mjtNum,
    pub geom_rgba: *mut f32,
    pub site_type: *mut c_int,
    pub site_bodyid: *mut c_int,
    pub site_matid: *mut c_int,
    pub site_group: *mut c_int,
    pub site_sameframe: *mut mjtByte,
    pub site_size: *mut mjtNum,
    pub site_pos: *mut mjtNum,
    pub site_quat: *mut mjtNum,
    pub site_user: *mut mjtNum,
    pub site_rgba: *mut f32,
    pub cam_mode: *mut c_int,
    pub cam_bodyid: *mut c_int,
    pub cam_targetbodyid: *mut c_int,
    pub cam_pos: *mut mjtNum,
    pub cam_quat: *mut mjtNum,
    pub cam_poscom0: *mut mjtNum,
    pub cam_pos0: *mut mjtNum,
    pub cam_mat0: *mut mjtNum,
    pub cam_fovy: *mut mjtNum,
    pub cam_ipd: *mut mjtNum,
    pub cam_user: *mut mjtNum,
    pub light_mode: *mut c_int,
    pub light_bodyid: *mut c_int,
    pub light_targetbodyid: *mut c_int,
    pub light_directional: *mut mjtByte,
    pub light_castshadow: *mut mjtByte,
    pub light_active: *mut mjtByte,
    pub light_pos: *mut mjtNum,
    pub light_dir: *mut mjtNum,
    pub light_poscom0: *mut mjtNum,
    pub light_pos0: *mut mjtNum,
    pub light_dir0: *mut mjtNum,
    pub light_attenuation: *mut f32,
    pub light_cutoff: *mut f32,
    pub light_exponent: *mut f32,
    pub light_ambient: *mut f32,
    pub light_diffuse: *mut f32,
    pub light_specular: *mut f32,
    pub mesh_vertadr: *mut c_int,
    pub mesh_vertnum: *mut c_int,
    pub mesh_texcoordadr: *mut c_int,
    pub mesh_faceadr: *mut c_int,
    pub mesh_facenum: *mut c_int,
    pub mesh_graphadr: *mut c_int,
    pub mesh_vert: *mut f32,
    pub mesh_normal: *mut f32,
    pub mesh_texcoord: *mut f32,
    pub mesh_face: *mut c_int,
    pub mesh_graph: *mut c_int,
    pub skin_matid: *mut c_int,
    pub skin_group: *mut c_int,
    pub skin_rgba: *mut f32,
    pub skin_inflate: *mut f32,
    pub skin_vertadr: *mut c_int,
    pub skin_vertnum: *mut c_int,
    pub skin_texcoordadr: *mut c_int,
    pub skin_faceadr: *mut c_int,
    pub skin_facenum: *mut c_int,
    pub skin_boneadr: *mut c_int,
    pub skin_bonenum: *mut c_int,
    pub skin_vert: *mut f32,
    pub skin_texcoord: *mut f32,
    pub skin_face: *mut c_int,
    pub skin_bonevertadr: *mut c_int,
    pub skin_bonevertnum: *mut c_int,
    pub skin_bonebindpos: *mut f32,
    pub skin_bonebindquat: *mut f32,
    pub skin_bonebodyid: *mut c_int,
    pub skin_bonevertid: *mut c_int,
    pub skin_bonevertweight: *mut f32,
    pub hfield_size: *mut mjtNum,
    pub hfield_nrow: *mut c_int,
    pub hfield_ncol: *mut c_int,
    pub hfield_adr: *mut c_int,
    pub hfield_data: *mut f32,
    pub tex_type: *mut c_int,
    pub tex_height: *mut c_int,
    pub tex_width: *mut c_int,
    pub tex_adr: *mut c_int,
    pub tex_rgb: *mut mjtByte,
    pub mat_texid: *mut c_int,
    pub mat_texuniform: *mut mjtByte,
    pub mat_texrepeat: *mut f32,
    pub mat_emission: *mut f32,
    pub mat_specular: *mut f32,
    pub mat_shininess: *mut f32,
    pub mat_reflectance: *mut f32,
    pub mat_rgba: *mut f32,
    pub pair_dim: *mut c_int,
    pub pair_geom1: *mut c_int,
    pub pair_geom2: *mut c_int,
    pub pair_signature: *mut c_int,
    pub pair_solref: *mut mjtNum,
    pub pair_solimp: *mut mjtNum,
    pub pair_margin: *mut mjtNum,
    pub pair_gap: *mut mjtNum,
    pub pair_friction: *mut mjtNum,
    pub exclude_signature: *mut c_int,
    pub eq_type: *mut c_int,
    pub eq_obj1id: *mut c_int,
    pub eq_obj2id: *mut c_int,
    pub eq_active: *mut mjtByte,
    pub eq_solref: *mut mjtNum,
    pub eq_solimp: *mut mjtNum,
    pub eq_data: *mut mjtNum,
    pub tendon_adr: *mut c_int,
    pub tendon_num: *mut c_int,
    pub tendon_matid: *mut c_int,
    pub tendon_group: *mut c_int,
    pub tendon_limited: *mut mjtByte,
    pub tendon_width: *mut mjtNum,
    pub tendon_solref_lim: *mut mjtNum,
    pub tendon_solimp_lim: *mut mjtNum,
    pub tendon_solref_fri: *mut mjtNum,
    pub tendon_solimp_fri: *mut mjtNum,
    pub tendon_range: *mut mjtNum,
    pub tendon_margin: *mut mjtNum,
    pub tendon_stiffness: *mut mjtNum,
    pub tendon_damping: *mut mjtNum,
    pub tendon_frictionloss: *mut mjtNum,
    pub tendon_lengthspring: *mut mjtNum,
    pub tendon_length0: *mut mjtNum,
    pub tendon_invweight0: *mut mjtNum,
    pub tendon_user: *mut mjtNum,
    pub tendon_rgba: *mut f32,
    pub wrap_type: *mut c_int,
    pub wrap_objid: *mut c_int,
    pub wrap_prm: *mut mjtNum,
    pub actuator_trntype: *mut c_int,
    pub actuator_dyntype: *mut c_int,
    pub actuator_gaintype: *mut c_int,
    pub actuator_biastype: *mut c_int,
    pub actuator_trnid: *mut c_int,
    pub actuator_group: *mut c_int,
    pub actuator_ctrllimited: *mut mjtByte,
    pub actuator_forcelimited: *mut mjtByte,
    pub actuator_actlimited: *mut mjtByte,
    pub actuator_dynprm: *mut mjtNum,
    pub actuator_gainprm: *mut mjtNum,
    pub actuator_biasprm: *mut mjtNum,
    pub actuator_ctrlrange: *mut mjtNum,
    pub actuator_forcerange: *mut mjtNum,
    pub actuator_actrange: *mut mjtNum,
    pub actuator_gear: *mut mjtNum,
    pub actuator_cranklength: *mut mjtNum,
    pub actuator_acc0: *mut mjtNum,
    pub actuator_length0: *mut mjtNum,
    pub actuator_lengthrange: *mut mjtNum,
    pub actuator_user: *mut mjtNum,
    pub sensor_type: *mut c_int,
    pub sensor_datatype: *mut c_int,
    pub sensor_needstage: *mut c_int,
    pub sensor_objtype: *mut c_int,
    pub sensor_objid: *mut c_int,
    pub sensor_reftype: *mut c_int,
    pub sensor_refid: *mut c_int,
    pub sensor_dim: *mut c_int,
    pub sensor_adr: *mut c_int,
    pub sensor_cutoff: *mut mjtNum,
    pub sensor_noise: *mut mjtNum,
    pub sensor_user: *mut mjtNum,
    pub numeric_adr: *mut c_int,
    pub numeric_size: *mut c_int,
    pub numeric_data: *mut mjtNum,
    pub text_adr: *mut c_int,
    pub text_size: *mut c_int,
    pub text_data: *mut c_char,
    pub tuple_adr: *mut c_int,
    pub tuple_size: *mut c_int,
    pub tuple_objtype: *mut c_int,
    pub tuple_objid: *mut c_int,
    pub tuple_objprm: *mut mjtNum,
    pub key_time: *mut mjtNum,
    pub key_qpos: *mut mjtNum,
    pub key_qvel: *mut mjtNum,
    pub key_act: *mut mjtNum,
    pub key_mpos: *mut mjtNum,
    pub key_mquat: *mut mjtNum,
    pub key_ctrl: *mut mjtNum,
    pub name_bodyadr: *mut c_int,
    pub name_jntadr: *mut c_int,
    pub name_geomadr: *mut c_int,
    pub name_siteadr: *mut c_int,
    pub name_camadr: *mut c_int,
    pub name_lightadr: *mut c_int,
    pub name_meshadr: *mut c_int,
    pub name_skinadr: *mut c_int,
    pub name_hfieldadr: *mut c_int,
    pub name_texadr: *mut c_int,
    pub name_matadr: *mut c_int,
    pub name_pairadr: *mut c_int,
    pub name_excludeadr: *mut c_int,
    pub name_eqadr: *mut c_int,
    pub name_tendonadr: *mut c_int,
    pub name_actuatoradr: *mut c_int,
    pub name_sensoradr: *mut c_int,
    pub name_numericadr: *mut c_int,
    pub name_textadr: *mut c_int,
    pub name_tupleadr: *mut c_int,
    pub name_keyadr: *mut c_int,
    pub names: *mut c_char,
}
pub type mjModel = mjModel_;
