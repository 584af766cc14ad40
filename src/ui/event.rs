//! mjui_event: mouse, wheel, key and resize events applied to a UI: section and separator
//! toggles, item values, slider drags, select boxes, text editing and shortcuts.

#![allow(non_upper_case_globals)] // the ABI's key names in patterns

use super::draw::update;
use super::edit;
use super::host::{enabled, Host};
use super::layout::{resize, scl};
use super::locate::{self, find_mouse, find_radio, find_radioline, find_select};
use super::locate::{mouse_in_rect, ui_rect};
use crate::abi::*;
use crate::engine::EngineError;
use crate::math::misc::round;
use crate::render::gl::Gl;
use mjtEvent_::*;
use mjtItem_::*;

/// An item by (0-based section, item).
pub type ItemId = (usize, usize);

/// Everything an event handler needs besides the UI and the state.
pub struct Env<'a> {
    pub gl: &'a Gl,
    pub con: &'a mjrContext,
    pub host: &'a dyn Host,
}

impl Env<'_> {
    fn update(&self, s: i32, i: i32, ui: &mjUI, st: &mjuiState) -> Result<(), EngineError> {
        update(self.gl, s, i, ui, st, self.con, self.host)
    }
}

fn id(sect: i32, item: i32) -> Option<ItemId> {
    Some((usize::try_from(sect - 1).ok()?, usize::try_from(item).ok()?))
        .filter(|&(s, i)| s < mjMAXUISECT && i < mjMAXUIITEM)
}

fn get(ui: &mjUI, (s, i): ItemId) -> &mjuiItem {
    &ui.sect[s].item[i]
}

/// Records `changed` as the item whose edit was committed.
fn set_edit_changed(ui: &mut mjUI, changed: Option<ItemId>) {
    ui.editchanged = match changed {
        Some((s, i)) => &mut ui.sect[s].item[i] as *mut mjuiItem,
        None => std::ptr::null_mut(),
    };
}

/// Sets a slider's value from the mouse position.
fn set_slider(it: &mjuiItem, ui: &mjUI, state: &mjuiState, host: &dyn Host) {
    let (rx, _) = mouse_in_rect(it.rect, ui, state);
    let sl = it.slider();
    let rx = rx.clamp_c();
    let div = if 1.0 > sl.divisions {
        1.0
    } else {
        sl.divisions
    };
    let rx = (round(rx * sl.divisions) as f64 / div).clamp_c();
    let val = sl.range[0] * (1.0 - rx) + sl.range[1] * rx;
    if locate::is(it, mjITEM_SLIDERINT) {
        host.set_int(it, 0, round(val));
    } else {
        host.set_num(it, 0, val);
    }
}

trait ClampC {
    fn clamp_c(self) -> f64;
}

impl ClampC for f64 {
    /// mjMAX(0, mjMIN(1, x)) as the C macros compute it.
    fn clamp_c(self) -> f64 {
        let m = if 1.0 < self { 1.0 } else { self };
        if 0.0 > m {
            0.0
        } else {
            m
        }
    }
}

/// Handles one event; returns the item whose value changed (or whose edit was committed).
pub fn event(
    env: &Env,
    ui: &mut mjUI,
    state: &mut mjuiState,
) -> Result<Option<ItemId>, EngineError> {
    ui.editchanged = std::ptr::null_mut();
    let t = state.r#type;
    let mouse =
        t == mjEVENT_PRESS as i32 || t == mjEVENT_MOVE as i32 || t == mjEVENT_RELEASE as i32;
    if mouse && state.button != mjtButton_::mjBUTTON_LEFT as i32 {
        if state.button == mjtButton_::mjBUTTON_RIGHT as i32 {
            if t == mjEVENT_PRESS as i32 {
                ui.mousehelp = 1;
                env.update(-1, -1, ui, state)?;
            } else if t == mjEVENT_RELEASE as i32 {
                ui.mousehelp = 0;
                env.update(-1, -1, ui, state)?;
            }
        }
        return Ok(None);
    }
    match t {
        x if x == mjEVENT_MOVE as i32 => on_move(env, ui, state),
        x if x == mjEVENT_PRESS as i32 => on_press(env, ui, state),
        x if x == mjEVENT_RELEASE as i32 => on_release(env, ui, state),
        x if x == mjEVENT_SCROLL as i32 => {
            ui.scroll -= round(state.sy * scl(ui.spacing.linescroll, env.con) as f64);
            clamp_scroll(ui, state);
            Ok(None)
        }
        x if x == mjEVENT_KEY as i32 => on_key(env, ui, state),
        x if x == mjEVENT_RESIZE as i32 => {
            clamp_scroll(ui, state);
            Ok(None)
        }
        _ => Ok(None),
    }
}

fn clamp_scroll(ui: &mut mjUI, state: &mjuiState) {
    let max = ui.height - ui_rect(ui, state).height;
    ui.scroll = ui.scroll.min(max).max(0);
}

fn on_move(env: &Env, ui: &mut mjUI, state: &mjuiState) -> Result<Option<ItemId>, EngineError> {
    if ui.mousesect == -1 {
        let h = ui_rect(ui, state).height;
        ui.scroll -= round(state.dy * ui.height as f64 / h as f64);
        clamp_scroll(ui, state);
        return Ok(None);
    }
    let Some(rec) = id(ui.mousesect, ui.mouseitem) else {
        return Ok(None);
    };
    let (s, i) = (rec.0 as i32, rec.1 as i32);
    let it = *get(ui, rec);
    let t = it.r#type;
    if t == mjITEM_SLIDERINT as i32 || t == mjITEM_SLIDERNUM as i32 {
        set_slider(&it, ui, state, env.host);
        env.update(s, i, ui, state)?;
        return Ok(Some(rec));
    }
    if t == mjITEM_EDITINT as i32 || t == mjITEM_EDITNUM as i32 || t == mjITEM_EDITTXT as i32 {
        edit::set_cursor(it.rect, ui, state, env.con);
    }
    env.update(s, i, ui, state)?;
    Ok(None)
}

fn on_press(env: &Env, ui: &mut mjUI, state: &mjuiState) -> Result<Option<ItemId>, EngineError> {
    let (sect_cur, item_cur) = find_mouse(ui, state, env.con);
    if let Some(ed) = id(ui.editsect, ui.edititem) {
        let (es, ei) = (ui.editsect, ui.edititem);
        let it_edit = *get(ui, ed);
        if es == sect_cur && ei == item_cur {
            ui.mousesect = sect_cur;
            ui.mouseitem = item_cur;
            edit::set_cursor(it_edit.rect, ui, state, env.con);
            env.update(es - 1, ei, ui, state)?;
            return Ok(None);
        }
        let (bytes, len) = edit::edit_bytes(ui);
        if edit::store(&bytes[..len], &it_edit, env.host) {
            set_edit_changed(ui, Some(ed));
        }
        ui.editsect = 0;
        env.update(es - 1, ei, ui, state)?;
    }
    ui.mousesect = 0;
    match sect_cur {
        -1 => {
            ui.mousesect = -1;
            ui.mouseitem = 0;
        }
        -2 => ui.scroll = ui.height - ui_rect(ui, state).height,
        -3 => ui.scroll = 0,
        s if s > 0 && item_cur < 0 => {
            toggle_section(ui, state, s as usize - 1);
            resize(ui, env.con);
            env.update(-1, -1, ui, state)?;
        }
        s if s > 0 => return press_item(env, ui, state, (s as usize - 1, item_cur as usize)),
        _ => {}
    }
    Ok(edit_changed(ui))
}

/// The recorded edit-changed item.
fn edit_changed(ui: &mjUI) -> Option<ItemId> {
    let p = ui.editchanged as *const mjuiItem;
    if p.is_null() {
        return None;
    }
    (0..mjMAXUISECT).find_map(|s| {
        let items = &ui.sect[s].item;
        let i = items.iter().position(|it| std::ptr::eq(it, p))?;
        Some((s, i))
    })
}

/// A click on section `n`'s title: toggles it; a double click sets all to its state.
fn toggle_section(ui: &mut mjUI, state: &mjuiState, n: usize) {
    if state.doubleclick != 0 {
        let nsect = ui.nsect.clamp(0, mjMAXUISECT as i32) as usize;
        let st = ui.sect[n].state;
        for s in ui.sect[..nsect].iter_mut() {
            if s.state < 2 && st < 2 {
                s.state = st;
            }
        }
    } else if ui.sect[n].state < 2 {
        ui.sect[n].state = 1 - ui.sect[n].state;
    }
}

fn press_item(
    env: &Env,
    ui: &mut mjUI,
    state: &mjuiState,
    cur: ItemId,
) -> Result<Option<ItemId>, EngineError> {
    let it = *get(ui, cur);
    if !enabled(it.state, ui, env.host) {
        return Ok(edit_changed(ui));
    }
    let (s1, i) = (cur.0 as i32 + 1, cur.1 as i32);
    let host = env.host;
    let t = it.r#type;
    let mut change = false;
    let mut track = false;
    if t == mjITEM_SEPARATOR as i32 {
        if it.state == mjSEPCLOSED + 1 || it.state == mjSEPCLOSED {
            let open = it.state == mjSEPCLOSED;
            ui.sect[cur.0].item[cur.1].state = mjSEPCLOSED + open as i32;
            resize(ui, env.con);
            env.update(-1, -1, ui, state)?;
        }
        return Ok(edit_changed(ui));
    } else if t == mjITEM_BUTTON as i32 {
        (track, change) = (true, true);
    } else if t == mjITEM_CHECKINT as i32 {
        host.set_int(&it, 0, 1i32.wrapping_sub(host.int(&it, 0)));
        change = true;
    } else if t == mjITEM_CHECKBYTE as i32 {
        host.set_byte(&it, 1u8.wrapping_sub(host.byte(&it)));
        change = true;
    } else if t == mjITEM_RADIO as i32 || t == mjITEM_RADIOLINE as i32 {
        let k = if t == mjITEM_RADIO as i32 {
            find_radio(&it, ui, state)
        } else {
            find_radioline(&it, ui, state, env.con)
        };
        if let Some(k) = k {
            host.set_int(&it, 0, k);
            change = true;
        }
    } else if t == mjITEM_SELECT as i32 {
        track = true;
    } else if t == mjITEM_SLIDERINT as i32 || t == mjITEM_SLIDERNUM as i32 {
        set_slider(&it, ui, state, host);
        (track, change) = (true, true);
    } else if t == mjITEM_EDITINT as i32 || t == mjITEM_EDITNUM as i32 || t == mjITEM_EDITTXT as i32
    {
        start_edit(env, ui, state, &it, (s1, i));
        track = true;
    }
    if track {
        ui.mousesect = s1;
        ui.mouseitem = i;
    }
    env.update(s1 - 1, i, ui, state)?;
    Ok(if change { Some(cur) } else { edit_changed(ui) })
}

/// Starts editing an item: its text, cursor at the mouse.
fn start_edit(env: &Env, ui: &mut mjUI, state: &mjuiState, it: &mjuiItem, (s1, i): (i32, i32)) {
    let text = edit::show(it, env.host);
    let (mut bytes, _) = edit::edit_bytes(ui);
    bytes[..text.len()].copy_from_slice(&text);
    bytes[text.len()] = 0;
    edit::set_edit_bytes(ui, &bytes);
    ui.editscroll = 0;
    edit::set_cursor(it.rect, ui, state, env.con);
    ui.editsect = s1;
    ui.edititem = i;
}

fn on_release(env: &Env, ui: &mut mjUI, state: &mjuiState) -> Result<Option<ItemId>, EngineError> {
    let rec = id(ui.mousesect, ui.mouseitem);
    if let Some(rec) = rec {
        let it = *get(ui, rec);
        if locate::is(&it, mjITEM_SELECT) {
            let k = find_select(&it, ui, state, env.con);
            if let Some(k) = k {
                env.host.set_int(&it, 0, k);
            }
            ui.mousesect = 0;
            env.update(-1, -1, ui, state)?;
            if k.is_some() {
                return Ok(Some(rec));
            }
        } else if locate::is(&it, mjITEM_BUTTON) {
            ui.mousesect = 0;
            env.update(rec.0 as i32, rec.1 as i32, ui, state)?;
        }
    }
    ui.mousesect = 0;
    Ok(None)
}

fn on_key(env: &Env, ui: &mut mjUI, state: &mut mjuiState) -> Result<Option<ItemId>, EngineError> {
    match id(ui.editsect, ui.edititem) {
        Some(ed) => edit_key(env, ui, state, ed),
        None => shortcut(env, ui, state),
    }
}

fn edit_key(
    env: &Env,
    ui: &mut mjUI,
    state: &mut mjuiState,
    ed: ItemId,
) -> Result<Option<ItemId>, EngineError> {
    let key = state.key;
    state.key = 0;
    let it = *get(ui, ed);
    let (es, ei) = (ed.0 as i32, ed.1 as i32);
    let (mut text, len) = edit::edit_bytes(ui);
    let cur = ui.editcursor;
    match key {
        mjKEY_ESCAPE => ui.editsect = 0,
        mjKEY_ENTER => {
            if edit::store(&text[..len], &it, env.host) {
                ui.editsect = 0;
                env.update(es, ei, ui, state)?;
                set_edit_changed(ui, Some(ed));
                return Ok(Some(ed));
            }
        }
        mjKEY_LEFT if state.control != 0 => ui.editcursor = 0,
        mjKEY_LEFT => ui.editcursor = (cur - 1).max(0),
        mjKEY_RIGHT if state.control != 0 => ui.editcursor = len as i32,
        mjKEY_RIGHT => ui.editcursor = (cur + 1).min(len as i32),
        mjKEY_HOME => ui.editcursor = 0,
        mjKEY_END => ui.editcursor = len as i32,
        mjKEY_BACKSPACE => {
            if cur > 0 {
                let c = (cur as usize).min(len + 1);
                text.copy_within(c..=len, c - 1);
                edit::set_edit_bytes(ui, &text);
                ui.editcursor = cur - 1;
            }
        }
        mjKEY_DELETE => {
            if cur >= 0 && (cur as usize) < len {
                let c = cur as usize;
                text.copy_within(c + 1..=len, c);
                edit::set_edit_bytes(ui, &text);
            }
        }
        _ => insert_key(ui, key, state.shift != 0, &it),
    }
    if ui.editsect > 0 {
        edit::reveal_cursor(it.rect, ui, env.con);
    }
    env.update(es, ei, ui, state)?;
    Ok(None)
}

/// Inserts the character `key` types at the cursor, if the item accepts it.
fn insert_key(ui: &mut mjUI, key: i32, shift: bool, it: &mjuiItem) {
    let (mut text, len) = edit::edit_bytes(ui);
    let Some(c) = edit::typed(key, len, it, shift) else {
        return;
    };
    let cur = ui.editcursor.clamp(0, len as i32) as usize;
    text.copy_within(cur..=len, cur + 1);
    text[cur] = c;
    edit::set_edit_bytes(ui, &text);
    ui.editcursor += 1;
}

fn matches(state: &mjuiState, modifier: i32, key: i32) -> bool {
    let m =
        (state.control != 0) as i32 + 2 * (state.shift != 0) as i32 + 4 * (state.alt != 0) as i32;
    key != 0 && state.key == key && m == modifier
}

/// Section shortcuts (open that section alone) and button and check shortcuts.
fn shortcut(
    env: &Env,
    ui: &mut mjUI,
    state: &mut mjuiState,
) -> Result<Option<ItemId>, EngineError> {
    let nsect = ui.nsect.clamp(0, mjMAXUISECT as i32) as usize;
    if let Some(n) = (0..nsect).find(|&n| matches(state, ui.sect[n].modifier, ui.sect[n].shortcut))
    {
        for s in ui.sect[..nsect].iter_mut().filter(|s| s.state < 2) {
            s.state = 0;
        }
        if ui.sect[n].state < 2 {
            ui.sect[n].state = 1;
        }
        resize(ui, env.con);
        env.update(-1, -1, ui, state)?;
        state.key = 0;
        return Ok(None);
    }
    for n in 0..nsect {
        let nitem = ui.sect[n].nitem.clamp(0, mjMAXUIITEM as i32) as usize;
        for i in 0..nitem {
            let it = ui.sect[n].item[i];
            let t = it.r#type;
            let single = t == mjITEM_BUTTON as i32
                || t == mjITEM_CHECKINT as i32
                || t == mjITEM_CHECKBYTE as i32;
            if !(single && matches(state, it.single().modifier, it.single().shortcut)) {
                continue;
            }
            state.key = 0;
            if !enabled(it.state, ui, env.host) {
                return Ok(None);
            }
            let host = env.host;
            if t == mjITEM_CHECKINT as i32 {
                host.set_int(&it, 0, 1i32.wrapping_sub(host.int(&it, 0)));
                env.update(n as i32, i as i32, ui, state)?;
            } else if t == mjITEM_CHECKBYTE as i32 {
                host.set_byte(&it, 1u8.wrapping_sub(host.byte(&it)));
                env.update(n as i32, i as i32, ui, state)?;
            }
            return Ok(Some((n, i)));
        }
    }
    Ok(None)
}
