//! C entry points of the UI framework (mjui_): argument checks, then `crate::ui`.

use super::guard;
use crate::abi::*;
use crate::ui;
use std::os::raw::c_int;

/// The definition table at `def` up to and including its mjITEM_END entry.
///
/// # Safety
/// `def` points to an array of mjuiDef that ends with an mjITEM_END entry.
unsafe fn def_table<'a>(def: *const mjuiDef) -> &'a [mjuiDef] {
    let mut n = 0;
    while (*def.add(n)).r#type != mjtItem_::mjITEM_END as c_int {
        n += 1;
    }
    std::slice::from_raw_parts(def, n + 1)
}

#[no_mangle]
pub extern "C" fn mjui_themeSpacing(ind: c_int) -> mjuiThemeSpacing {
    ui::theme::spacing(ind)
}

#[no_mangle]
pub extern "C" fn mjui_themeColor(ind: c_int) -> mjuiThemeColor {
    ui::theme::color(ind)
}

#[no_mangle]
pub unsafe extern "C" fn mjui_add(ui: *mut mjUI, def: *const mjuiDef) {
    let (Some(ui), false) = (ui.as_mut(), def.is_null()) else {
        return;
    };
    let defs = def_table(def);
    guard("mjui_add", (), || {
        ui::build::add(ui, defs);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjui_addToSection(ui: *mut mjUI, sect: c_int, def: *const mjuiDef) {
    let (Some(ui), false) = (ui.as_mut(), def.is_null()) else {
        return;
    };
    if !(0..mjMAXUISECT as c_int).contains(&sect) {
        crate::runtime::message::error("mjui_addToSection: invalid section");
        return;
    }
    let defs = def_table(def);
    guard("mjui_addToSection", (), || {
        ui::build::add_to_section(ui, sect, defs);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjui_resize(ui: *mut mjUI, con: *const mjrContext) {
    if let (Some(ui), Some(con)) = (ui.as_mut(), con.as_ref()) {
        guard("mjui_resize", (), || {
            ui::layout::resize(ui, con);
            Ok(())
        })
    }
}
