//! C entry points of the UI framework (mjui_): argument checks, then `crate::ui`.

use super::guard;
use super::render::with_gl;
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

/// Item data and the predicate reached through the C pointers of mjUI (the caller of
/// mjui_update and mjui_event vouches for them, as with 2.2.2).
struct CHost;

impl CHost {
    fn ptr<T>(it: &mjuiItem, i: usize) -> Option<*mut T> {
        (!it.pdata.is_null()).then(|| (it.pdata as *mut T).wrapping_add(i))
    }
}

impl ui::host::Host for CHost {
    fn int(&self, it: &mjuiItem, i: usize) -> i32 {
        // SAFETY: an int item's pdata points to its ints.
        Self::ptr::<i32>(it, i).map_or(0, |p| unsafe { p.read_unaligned() })
    }
    fn set_int(&self, it: &mjuiItem, i: usize, v: i32) {
        // SAFETY: as in `int`.
        Self::ptr::<i32>(it, i).inspect(|&p| unsafe { p.write_unaligned(v) });
    }
    fn byte(&self, it: &mjuiItem) -> u8 {
        // SAFETY: a checkbyte's pdata points to its byte.
        Self::ptr::<u8>(it, 0).map_or(0, |p| unsafe { p.read() })
    }
    fn set_byte(&self, it: &mjuiItem, v: u8) {
        // SAFETY: as in `byte`.
        Self::ptr::<u8>(it, 0).inspect(|&p| unsafe { p.write(v) });
    }
    fn num(&self, it: &mjuiItem, i: usize) -> f64 {
        // SAFETY: a number item's pdata points to its mjtNums.
        Self::ptr::<f64>(it, i).map_or(0.0, |p| unsafe { p.read_unaligned() })
    }
    fn set_num(&self, it: &mjuiItem, i: usize, v: f64) {
        // SAFETY: as in `num`.
        Self::ptr::<f64>(it, i).inspect(|&p| unsafe { p.write_unaligned(v) });
    }
    fn text(&self, it: &mjuiItem) -> Vec<u8> {
        let mut out = Vec::new();
        for i in 0..mjMAXUINAME {
            // SAFETY: a text item's pdata points to mjMAXUINAME chars (or a shorter string).
            let c = Self::ptr::<u8>(it, i).map_or(0, |p| unsafe { p.read() });
            if c == 0 {
                break;
            }
            out.push(c);
        }
        out
    }
    fn set_text(&self, it: &mjuiItem, text: &[u8; mjMAXUINAME]) {
        if let Some(p) = Self::ptr::<u8>(it, 0) {
            // SAFETY: a text item's pdata has room for mjMAXUINAME chars.
            unsafe { std::ptr::copy_nonoverlapping(text.as_ptr(), p, mjMAXUINAME) }
        }
    }
    fn predicate(&self, ui: &mjUI, category: c_int) -> c_int {
        // SAFETY: the UI's predicate is a C function taking its userdata.
        ui.predicate
            .map_or(1, |f| unsafe { f(category, ui.userdata) })
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjui_update(
    section: c_int,
    item: c_int,
    ui: *const mjUI,
    state: *const mjuiState,
    con: *const mjrContext,
) {
    let (Some(ui), Some(state), Some(con)) = (ui.as_ref(), state.as_ref(), con.as_ref()) else {
        return;
    };
    with_gl("mjui_update", (), |gl| {
        ui::draw::update(gl, section, item, ui, state, con, &CHost)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjui_event(
    ui: *mut mjUI,
    state: *mut mjuiState,
    con: *const mjrContext,
) -> *mut mjuiItem {
    let (Some(ui), Some(state), Some(con)) = (ui.as_mut(), state.as_mut(), con.as_ref()) else {
        return std::ptr::null_mut();
    };
    let changed = with_gl("mjui_event", None, |gl| {
        let env = ui::event::Env {
            gl,
            con,
            host: &CHost,
        };
        ui::event::event(&env, ui, state)
    });
    match changed {
        Some((s, i)) => &mut ui.sect[s].item[i] as *mut mjuiItem,
        None => std::ptr::null_mut(),
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjui_render(
    ui: *mut mjUI,
    state: *const mjuiState,
    con: *const mjrContext,
) {
    let (Some(ui), Some(state), Some(con)) = (ui.as_mut(), state.as_ref(), con.as_ref()) else {
        return;
    };
    with_gl("mjui_render", (), |gl| ui::draw::render(gl, ui, state, con))
}
