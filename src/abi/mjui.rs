//! mjui.h: the user interface (state, theme, items, sections).

#![allow(non_camel_case_types, non_snake_case, non_upper_case_globals)]

use super::mjrender::mjrRect;
use std::os::raw::{c_char, c_int, c_void};

pub const mjMAXUISECT: usize = 10;
pub const mjMAXUIITEM: usize = 80;
pub const mjMAXUITEXT: usize = 300;
pub const mjMAXUINAME: usize = 40;
pub const mjMAXUIMULTI: usize = 35;
pub const mjMAXUIEDIT: usize = 7;
pub const mjMAXUIRECT: usize = 25;
pub const mjSEPCLOSED: c_int = 1000;

pub const mjKEY_ESCAPE: c_int = 256;
pub const mjKEY_ENTER: c_int = 257;
pub const mjKEY_TAB: c_int = 258;
pub const mjKEY_BACKSPACE: c_int = 259;
pub const mjKEY_INSERT: c_int = 260;
pub const mjKEY_DELETE: c_int = 261;
pub const mjKEY_RIGHT: c_int = 262;
pub const mjKEY_LEFT: c_int = 263;
pub const mjKEY_DOWN: c_int = 264;
pub const mjKEY_UP: c_int = 265;
pub const mjKEY_PAGE_UP: c_int = 266;
pub const mjKEY_PAGE_DOWN: c_int = 267;
pub const mjKEY_HOME: c_int = 268;
pub const mjKEY_END: c_int = 269;
pub const mjKEY_F1: c_int = 290;
pub const mjKEY_F2: c_int = 291;
pub const mjKEY_F3: c_int = 292;
pub const mjKEY_F4: c_int = 293;
pub const mjKEY_F5: c_int = 294;
pub const mjKEY_F6: c_int = 295;
pub const mjKEY_F7: c_int = 296;
pub const mjKEY_F8: c_int = 297;
pub const mjKEY_F9: c_int = 298;
pub const mjKEY_F10: c_int = 299;
pub const mjKEY_F11: c_int = 300;
pub const mjKEY_F12: c_int = 301;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtButton_ {
    mjBUTTON_NONE = 0,
    mjBUTTON_LEFT = 1,
    mjBUTTON_RIGHT = 2,
    mjBUTTON_MIDDLE = 3,
}
pub type mjtButton = mjtButton_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtEvent_ {
    mjEVENT_NONE = 0,
    mjEVENT_MOVE = 1,
    mjEVENT_PRESS = 2,
    mjEVENT_RELEASE = 3,
    mjEVENT_SCROLL = 4,
    mjEVENT_KEY = 5,
    mjEVENT_RESIZE = 6,
}
pub type mjtEvent = mjtEvent_;

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mjtItem_ {
    mjITEM_END = -2,
    mjITEM_SECTION = -1,
    mjITEM_SEPARATOR = 0,
    mjITEM_STATIC = 1,
    mjITEM_BUTTON = 2,
    mjITEM_CHECKINT = 3,
    mjITEM_CHECKBYTE = 4,
    mjITEM_RADIO = 5,
    mjITEM_RADIOLINE = 6,
    mjITEM_SELECT = 7,
    mjITEM_SLIDERINT = 8,
    mjITEM_SLIDERNUM = 9,
    mjITEM_EDITINT = 10,
    mjITEM_EDITNUM = 11,
    mjITEM_EDITTXT = 12,
    mjNITEM = 13,
}
pub type mjtItem = mjtItem_;

pub type mjfItemEnable = Option<unsafe extern "C" fn(category: c_int, data: *mut c_void) -> c_int>;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjuiState_ {
    pub nrect: c_int,
    pub rect: [mjrRect; mjMAXUIRECT],
    pub userdata: *mut c_void,
    pub r#type: c_int,
    pub left: c_int,
    pub right: c_int,
    pub middle: c_int,
    pub doubleclick: c_int,
    pub button: c_int,
    pub buttontime: f64,
    pub x: f64,
    pub y: f64,
    pub dx: f64,
    pub dy: f64,
    pub sx: f64,
    pub sy: f64,
    pub control: c_int,
    pub shift: c_int,
    pub alt: c_int,
    pub key: c_int,
    pub keytime: f64,
    pub mouserect: c_int,
    pub dragrect: c_int,
    pub dragbutton: c_int,
}
pub type mjuiState = mjuiState_;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjuiThemeSpacing_ {
    pub total: c_int,
    pub scroll: c_int,
    pub label: c_int,
    pub section: c_int,
    pub itemside: c_int,
    pub itemmid: c_int,
    pub itemver: c_int,
    pub texthor: c_int,
    pub textver: c_int,
    pub linescroll: c_int,
    pub samples: c_int,
}
pub type mjuiThemeSpacing = mjuiThemeSpacing_;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct mjuiThemeColor_ {
    pub master: [f32; 3],
    pub thumb: [f32; 3],
    pub secttitle: [f32; 3],
    pub sectfont: [f32; 3],
    pub sectsymbol: [f32; 3],
    pub sectpane: [f32; 3],
    pub shortcut: [f32; 3],
    pub fontactive: [f32; 3],
    pub fontinactive: [f32; 3],
    pub decorinactive: [f32; 3],
    pub decorinactive2: [f32; 3],
    pub button: [f32; 3],
    pub check: [f32; 3],
    pub radio: [f32; 3],
    pub select: [f32; 3],
    pub select2: [f32; 3],
    pub slider: [f32; 3],
    pub slider2: [f32; 3],
    pub edit: [f32; 3],
    pub edit2: [f32; 3],
    pub cursor: [f32; 3],
}
pub type mjuiThemeColor = mjuiThemeColor_;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjuiItemSingle_ {
    pub modifier: c_int,
    pub shortcut: c_int,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjuiItemMulti_ {
    pub nelem: c_int,
    pub name: [[c_char; mjMAXUINAME]; mjMAXUIMULTI],
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjuiItemSlider_ {
    pub range: [f64; 2],
    pub divisions: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mjuiItemEdit_ {
    pub nelem: c_int,
    pub range: [[f64; 2]; mjMAXUIEDIT],
}

/// The type-specific part of an item: an anonymous union in mjui.h (build.rs inlines it).
#[repr(C)]
#[derive(Clone, Copy)]
pub union mjuiItemUnion_ {
    pub single: mjuiItemSingle_,
    pub multi: mjuiItemMulti_,
    pub slider: mjuiItemSlider_,
    pub edit: mjuiItemEdit_,
}

#[repr(C)]
#[derive(Clone, Copy)]
pub struct mjuiItem_ {
    pub r#type: c_int,
    pub name: [c_char; mjMAXUINAME],
    pub state: c_int,
    pub pdata: *mut c_void,
    pub sectionid: c_int,
    pub itemid: c_int,
    pub u: mjuiItemUnion_,
    pub rect: mjrRect,
}
pub type mjuiItem = mjuiItem_;

#[repr(C)]
#[derive(Clone, Copy)]
pub struct mjuiSection_ {
    pub name: [c_char; mjMAXUINAME],
    pub state: c_int,
    pub modifier: c_int,
    pub shortcut: c_int,
    pub nitem: c_int,
    pub item: [mjuiItem; mjMAXUIITEM],
    pub rtitle: mjrRect,
    pub rcontent: mjrRect,
}
pub type mjuiSection = mjuiSection_;

#[repr(C)]
#[derive(Clone, Copy)]
pub struct mjUI_ {
    pub spacing: mjuiThemeSpacing,
    pub color: mjuiThemeColor,
    pub predicate: mjfItemEnable,
    pub userdata: *mut c_void,
    pub rectid: c_int,
    pub auxid: c_int,
    pub radiocol: c_int,
    pub width: c_int,
    pub height: c_int,
    pub maxheight: c_int,
    pub scroll: c_int,
    pub mousesect: c_int,
    pub mouseitem: c_int,
    pub mousehelp: c_int,
    pub editsect: c_int,
    pub edititem: c_int,
    pub editcursor: c_int,
    pub editscroll: c_int,
    pub edittext: [c_char; mjMAXUITEXT],
    pub editchanged: *mut mjuiItem,
    pub nsect: c_int,
    pub sect: [mjuiSection; mjMAXUISECT],
}
pub type mjUI = mjUI_;

#[repr(C)]
#[derive(Clone, Copy)]
pub struct mjuiDef_ {
    pub r#type: c_int,
    pub name: [c_char; mjMAXUINAME],
    pub state: c_int,
    pub pdata: *mut c_void,
    pub other: [c_char; mjMAXUITEXT],
}
pub type mjuiDef = mjuiDef_;

impl mjuiItem_ {
    /// The check and button part (every variant is plain data: any bits are a valid value).
    pub fn single(&self) -> &mjuiItemSingle_ {
        // SAFETY: all union variants are integers, doubles and chars, valid for any bits.
        unsafe { &self.u.single }
    }
    pub fn single_mut(&mut self) -> &mut mjuiItemSingle_ {
        // SAFETY: as in `single`.
        unsafe { &mut self.u.single }
    }
    /// The static, radio and select part.
    pub fn multi(&self) -> &mjuiItemMulti_ {
        // SAFETY: as in `single`.
        unsafe { &self.u.multi }
    }
    pub fn multi_mut(&mut self) -> &mut mjuiItemMulti_ {
        // SAFETY: as in `single`.
        unsafe { &mut self.u.multi }
    }
    /// The slider part.
    pub fn slider(&self) -> &mjuiItemSlider_ {
        // SAFETY: as in `single`.
        unsafe { &self.u.slider }
    }
    pub fn slider_mut(&mut self) -> &mut mjuiItemSlider_ {
        // SAFETY: as in `single`.
        unsafe { &mut self.u.slider }
    }
    /// The edit part.
    pub fn edit(&self) -> &mjuiItemEdit_ {
        // SAFETY: as in `single`.
        unsafe { &self.u.edit }
    }
    pub fn edit_mut(&mut self) -> &mut mjuiItemEdit_ {
        // SAFETY: as in `single`.
        unsafe { &mut self.u.edit }
    }
}
