//! mjvisualize.h: abstract visualization (scene, cameras, perturbation, figures).

#![allow(non_camel_case_types, non_snake_case, non_upper_case_globals)]

use super::mjmodel::mjtByte;
use super::mjtnum::mjtNum;
use std::os::raw::{c_char, c_int};

pub const mjNGROUP: usize = 6;
pub const mjMAXLIGHT: usize = 100;
pub const mjMAXOVERLAY: usize = 500;
pub const mjMAXLINE: usize = 100;
pub const mjMAXLINEPNT: usize = 1000;
pub const mjMAXPLANEGRID: usize = 200;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtCatBit_ {
    mjCAT_STATIC = 1,
    mjCAT_DYNAMIC = 2,
    mjCAT_DECOR = 4,
    mjCAT_ALL = 7,
}
pub type mjtCatBit = mjtCatBit_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtMouse_ {
    mjMOUSE_NONE = 0,
    mjMOUSE_ROTATE_V = 1,
    mjMOUSE_ROTATE_H = 2,
    mjMOUSE_MOVE_V = 3,
    mjMOUSE_MOVE_H = 4,
    mjMOUSE_ZOOM = 5,
    mjMOUSE_SELECT = 6,
}
pub type mjtMouse = mjtMouse_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtPertBit_ {
    mjPERT_TRANSLATE = 1,
    mjPERT_ROTATE = 2,
}
pub type mjtPertBit = mjtPertBit_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtCamera_ {
    mjCAMERA_FREE = 0,
    mjCAMERA_TRACKING = 1,
    mjCAMERA_FIXED = 2,
    mjCAMERA_USER = 3,
}
pub type mjtCamera = mjtCamera_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtLabel_ {
    mjLABEL_NONE = 0,
    mjLABEL_BODY = 1,
    mjLABEL_JOINT = 2,
    mjLABEL_GEOM = 3,
    mjLABEL_SITE = 4,
    mjLABEL_CAMERA = 5,
    mjLABEL_LIGHT = 6,
    mjLABEL_TENDON = 7,
    mjLABEL_ACTUATOR = 8,
    mjLABEL_CONSTRAINT = 9,
    mjLABEL_SKIN = 10,
    mjLABEL_SELECTION = 11,
    mjLABEL_SELPNT = 12,
    mjLABEL_CONTACTFORCE = 13,
    mjNLABEL = 14,
}
pub type mjtLabel = mjtLabel_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtFrame_ {
    mjFRAME_NONE = 0,
    mjFRAME_BODY = 1,
    mjFRAME_GEOM = 2,
    mjFRAME_SITE = 3,
    mjFRAME_CAMERA = 4,
    mjFRAME_LIGHT = 5,
    mjFRAME_CONTACT = 6,
    mjFRAME_WORLD = 7,
    mjNFRAME = 8,
}
pub type mjtFrame = mjtFrame_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtVisFlag_ {
    mjVIS_CONVEXHULL = 0,
    mjVIS_TEXTURE = 1,
    mjVIS_JOINT = 2,
    mjVIS_CAMERA = 3,
    mjVIS_ACTUATOR = 4,
    mjVIS_ACTIVATION = 5,
    mjVIS_LIGHT = 6,
    mjVIS_TENDON = 7,
    mjVIS_RANGEFINDER = 8,
    mjVIS_CONSTRAINT = 9,
    mjVIS_INERTIA = 10,
    mjVIS_SCLINERTIA = 11,
    mjVIS_PERTFORCE = 12,
    mjVIS_PERTOBJ = 13,
    mjVIS_CONTACTPOINT = 14,
    mjVIS_CONTACTFORCE = 15,
    mjVIS_CONTACTSPLIT = 16,
    mjVIS_TRANSPARENT = 17,
    mjVIS_AUTOCONNECT = 18,
    mjVIS_COM = 19,
    mjVIS_SELECT = 20,
    mjVIS_STATIC = 21,
    mjVIS_SKIN = 22,
    mjNVISFLAG = 23,
}
pub type mjtVisFlag = mjtVisFlag_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtRndFlag_ {
    mjRND_SHADOW = 0,
    mjRND_WIREFRAME = 1,
    mjRND_REFLECTION = 2,
    mjRND_ADDITIVE = 3,
    mjRND_SKYBOX = 4,
    mjRND_FOG = 5,
    mjRND_HAZE = 6,
    mjRND_SEGMENT = 7,
    mjRND_IDCOLOR = 8,
    mjRND_CULL_FACE = 9,
    mjNRNDFLAG = 10,
}
pub type mjtRndFlag = mjtRndFlag_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtStereo_ {
    mjSTEREO_NONE = 0,
    mjSTEREO_QUADBUFFERED = 1,
    mjSTEREO_SIDEBYSIDE = 2,
}
pub type mjtStereo = mjtStereo_;

/// Array lengths; C spells them with the enum values, so the headers do not define these.
pub const mjNVISFLAG: usize = 23;
pub const mjNRNDFLAG: usize = 10;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjvPerturb_ {
    pub select: c_int,
    pub skinselect: c_int,
    pub active: c_int,
    pub active2: c_int,
    pub refpos: [mjtNum; 3],
    pub refquat: [mjtNum; 4],
    pub localpos: [mjtNum; 3],
    pub scale: mjtNum,
}
pub type mjvPerturb = mjvPerturb_;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjvCamera_ {
    pub r#type: c_int,
    pub fixedcamid: c_int,
    pub trackbodyid: c_int,
    pub lookat: [mjtNum; 3],
    pub distance: mjtNum,
    pub azimuth: mjtNum,
    pub elevation: mjtNum,
}
pub type mjvCamera = mjvCamera_;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjvGLCamera_ {
    pub pos: [f32; 3],
    pub forward: [f32; 3],
    pub up: [f32; 3],
    pub frustum_center: f32,
    pub frustum_bottom: f32,
    pub frustum_top: f32,
    pub frustum_near: f32,
    pub frustum_far: f32,
}
pub type mjvGLCamera = mjvGLCamera_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjvGeom_ {
    pub r#type: c_int,
    pub dataid: c_int,
    pub objtype: c_int,
    pub objid: c_int,
    pub category: c_int,
    pub texid: c_int,
    pub texuniform: c_int,
    pub texcoord: c_int,
    pub segid: c_int,
    pub texrepeat: [f32; 2],
    pub size: [f32; 3],
    pub pos: [f32; 3],
    pub mat: [f32; 9],
    pub rgba: [f32; 4],
    pub emission: f32,
    pub specular: f32,
    pub shininess: f32,
    pub reflectance: f32,
    pub label: [c_char; 100],
    pub camdist: f32,
    pub modelrbound: f32,
    pub transparent: mjtByte,
}
pub type mjvGeom = mjvGeom_;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjvLight_ {
    pub pos: [f32; 3],
    pub dir: [f32; 3],
    pub attenuation: [f32; 3],
    pub cutoff: f32,
    pub exponent: f32,
    pub ambient: [f32; 3],
    pub diffuse: [f32; 3],
    pub specular: [f32; 3],
    pub headlight: mjtByte,
    pub directional: mjtByte,
    pub castshadow: mjtByte,
}
pub type mjvLight = mjvLight_;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjvOption_ {
    pub label: c_int,
    pub frame: c_int,
    pub geomgroup: [mjtByte; mjNGROUP],
    pub sitegroup: [mjtByte; mjNGROUP],
    pub jointgroup: [mjtByte; mjNGROUP],
    pub tendongroup: [mjtByte; mjNGROUP],
    pub actuatorgroup: [mjtByte; mjNGROUP],
    pub skingroup: [mjtByte; mjNGROUP],
    pub flags: [mjtByte; mjNVISFLAG],
}
pub type mjvOption = mjvOption_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjvScene_ {
    pub maxgeom: c_int,
    pub ngeom: c_int,
    pub geoms: *mut mjvGeom,
    pub geomorder: *mut c_int,
    pub nskin: c_int,
    pub skinfacenum: *mut c_int,
    pub skinvertadr: *mut c_int,
    pub skinvertnum: *mut c_int,
    pub skinvert: *mut f32,
    pub skinnormal: *mut f32,
    pub nlight: c_int,
    pub lights: [mjvLight; mjMAXLIGHT],
    pub camera: [mjvGLCamera; 2],
    pub enabletransform: mjtByte,
    pub translate: [f32; 3],
    pub rotate: [f32; 4],
    pub scale: f32,
    pub stereo: c_int,
    pub flags: [mjtByte; mjNRNDFLAG],
    pub framewidth: c_int,
    pub framergb: [f32; 3],
}
pub type mjvScene = mjvScene_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjvFigure_ {
    pub flg_legend: c_int,
    pub flg_ticklabel: [c_int; 2],
    pub flg_extend: c_int,
    pub flg_barplot: c_int,
    pub flg_selection: c_int,
    pub flg_symmetric: c_int,
    pub linewidth: f32,
    pub gridwidth: f32,
    pub gridsize: [c_int; 2],
    pub gridrgb: [f32; 3],
    pub figurergba: [f32; 4],
    pub panergba: [f32; 4],
    pub legendrgba: [f32; 4],
    pub textrgb: [f32; 3],
    pub linergb: [[f32; 3]; mjMAXLINE],
    pub range: [[f32; 2]; 2],
    pub xformat: [c_char; 20],
    pub yformat: [c_char; 20],
    pub minwidth: [c_char; 20],
    pub title: [c_char; 1000],
    pub xlabel: [c_char; 100],
    pub linename: [[c_char; 100]; mjMAXLINE],
    pub legendoffset: c_int,
    pub subplot: c_int,
    pub highlight: [c_int; 2],
    pub highlightid: c_int,
    pub selection: f32,
    pub linepnt: [c_int; mjMAXLINE],
    pub linedata: [[f32; 2000]; mjMAXLINE], // 2 * mjMAXLINEPNT
    pub xaxispixel: [c_int; 2],
    pub yaxispixel: [c_int; 2],
    pub xaxisdata: [f32; 2],
    pub yaxisdata: [f32; 2],
}
pub type mjvFigure = mjvFigure_;
