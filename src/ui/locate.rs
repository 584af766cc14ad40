//! Where things are in a laid-out UI: the mouse relative to the UI and its items, the
//! scrollbar, and the elements of radio, radioline and select items.

use super::layout::scl;
use crate::abi::*;
use crate::math::misc::round;
use crate::render::text::text_width;

pub fn is(it: &mjuiItem, t: mjtItem_) -> bool {
    it.r#type == t as i32
}

/// Column count of radio items (0 means 2).
pub fn radio_cols(ui: &mjUI) -> i32 {
    if ui.radiocol != 0 {
        ui.radiocol
    } else {
        2
    }
}

/// Number of elements of a multi item, kept within the name table.
pub fn nelem(it: &mjuiItem) -> i32 {
    it.multi().nelem.clamp(0, mjMAXUIMULTI as i32)
}

/// The rectangle of the UI in the window.
pub fn ui_rect(ui: &mjUI, state: &mjuiState) -> mjrRect {
    let id = ui.rectid.clamp(0, mjMAXUIRECT as i32 - 1) as usize;
    state.rect[id]
}

/// Section `sect` (1-based) and item `item` if both exist.
pub fn item_at(ui: &mjUI, sect: i32, item: i32) -> Option<&mjuiItem> {
    let s = ui.sect.get(usize::try_from(sect - 1).ok()?)?;
    s.item.get(usize::try_from(item).ok()?)
}

/// Mouse position in UI coordinates (scroll and offset undone).
pub fn mouse_in_ui(ui: &mjUI, state: &mjuiState) -> (i32, i32) {
    let (mut x, mut y) = (state.x as i32, state.y as i32);
    let rect = ui_rect(ui, state);
    if ui.height > rect.height {
        y -= ui.scroll;
    }
    x -= rect.left;
    y -= (rect.height - ui.height) + rect.bottom;
    (x, y)
}

/// Mouse position relative to `rect` (0 to 1 inside).
pub fn mouse_in_rect(rect: mjrRect, ui: &mjUI, state: &mjuiState) -> (f64, f64) {
    let (x, y) = mouse_in_ui(ui, state);
    (
        (x - rect.left) as f64 / rect.width as f64,
        (y - rect.bottom) as f64 / rect.height as f64,
    )
}

/// Rectangle of element `n` of a radio item.
pub fn radio_element(it: &mjuiItem, n: i32, ui: &mjUI, con: &mjrContext) -> mjrRect {
    let g_itemmid = scl(ui.spacing.itemmid, con);
    let g_textver = scl(ui.spacing.textver, con);
    let ncol = radio_cols(ui);
    let nrow = (it.multi().nelem - 1) / ncol + 1;
    let cellwidth = (it.rect.width - (ncol - 1) * g_itemmid) / ncol;
    let cellheight = con.charHeight + 2 * g_textver;
    let (row, col) = (n / ncol, n % ncol);
    let mut r = mjrRect {
        left: it.rect.left + col * (cellwidth + g_itemmid),
        bottom: it.rect.bottom + (nrow - 1 - row) * cellheight,
        width: cellwidth,
        height: cellheight,
    };
    if col == ncol - 1 {
        r.width = it.rect.width - r.left + it.rect.left;
    }
    r
}

/// Radio element under the mouse, if any.
pub fn find_radio(it: &mjuiItem, ui: &mjUI, state: &mjuiState) -> Option<i32> {
    let ncol = radio_cols(ui);
    let nrow = (it.multi().nelem - 1) / ncol + 1;
    let (rx, ry) = mouse_in_rect(it.rect, ui, state);
    let ry = 1.0 - ry;
    let row = ((ry * nrow as f64).floor() as i32).min(nrow - 1).max(0);
    let col = ((rx * ncol as f64).floor() as i32).min(ncol - 1).max(0);
    let ind = row * ncol + col;
    (ind < it.multi().nelem).then_some(ind)
}

/// Separators (offsets from the item's left) between radioline elements: nelem+1 entries.
pub fn radioline_seps(it: &mjuiItem, con: &mjrContext) -> Vec<i32> {
    let n = nelem(it) as usize;
    let mut sep = vec![0; n + 1];
    if n == 0 {
        return sep;
    }
    let names = &it.multi().name;
    let widths: Vec<i32> = (0..n)
        .map(|i| text_width(con, crate::abi::cstr::cbytes(&names[i])))
        .collect();
    let total: i32 = widths.iter().sum();
    let extra = (it.rect.width - total) as f64 / n as f64;
    for i in 0..n {
        let share = round((i + 1) as f64 * extra) - round(i as f64 * extra);
        sep[i + 1] = sep[i] + widths[i] + share;
    }
    sep[n] = it.rect.width;
    sep
}

/// Radioline element under the mouse, if any.
pub fn find_radioline(
    it: &mjuiItem,
    ui: &mjUI,
    state: &mjuiState,
    con: &mjrContext,
) -> Option<i32> {
    let sep = radioline_seps(it, con);
    let (rx, _) = mouse_in_rect(it.rect, ui, state);
    let x = round(rx * it.rect.width as f64);
    (0..nelem(it)).find(|&i| x >= sep[i as usize] && x < sep[i as usize + 1])
}

/// Element of the open select box under the mouse, if the mouse tracks a select item.
pub fn find_select(it: &mjuiItem, ui: &mjUI, state: &mjuiState, con: &mjrContext) -> Option<i32> {
    if !(ui.mousesect > 0 && ui.mouseitem >= 0 && is(it, mjtItem_::mjITEM_SELECT)) {
        return None;
    }
    let cellheight = con.charHeight + 2 * scl(ui.spacing.textver, con);
    let n = it.multi().nelem;
    let mut r = it.rect;
    r.height = n * cellheight;
    r.bottom -= r.height;
    let (rx, ry) = mouse_in_rect(r, ui, state);
    if ry > 0.0 && ry < 1.0 && rx > 0.0 && rx < 1.0 {
        let k = ((ry * n as f64).floor() as i32).min(n - 1).max(0);
        Some(n - 1 - k).filter(|&v| v >= 0)
    } else {
        None
    }
}

/// The scrollbar of a UI shown in `rect` and its thumb.
pub fn scroll_rects(rect: mjrRect, ui: &mjUI, con: &mjrContext) -> (mjrRect, mjrRect) {
    let w = scl(ui.spacing.scroll, con);
    let mut bar = rect;
    bar.left = rect.left + rect.width - w;
    bar.width = w;
    let tstart = ui.scroll as f64 / ui.height as f64;
    let tend = (ui.scroll + rect.height) as f64 / ui.height as f64;
    let mut thumb = bar;
    thumb.bottom = rect.bottom + round(rect.height as f64 * (1.0 - tend));
    thumb.height = round(rect.height as f64 * (tend - tstart));
    (bar, thumb)
}

pub fn inside(x: i32, y: i32, r: mjrRect) -> bool {
    x >= r.left && x <= r.left + r.width && y >= r.bottom && y <= r.bottom + r.height
}

/// Inside the oval (rounded ends) of a button.
fn inside_oval(x: i32, y: i32, r: mjrRect) -> bool {
    if !inside(x, y, r) {
        return false;
    }
    let radius = r.height / 2;
    if x >= r.left + radius && x <= r.left + r.width - radius {
        return true;
    }
    let dy = y - (r.bottom + radius);
    let dx = x - (r.left + radius);
    if dx < 0 && dx * dx + dy * dy < radius * radius {
        return true;
    }
    let dx = x - (r.left + r.width - radius);
    dx > 0 && dx * dx + dy * dy < radius * radius
}

/// What the mouse is over: (sect, item). sect -1 thumb, -2 bar below it, -3 bar above it,
/// n+1 section n (item -1 its title, else the item), 0 nothing.
pub fn find_mouse(ui: &mjUI, state: &mjuiState, con: &mjrContext) -> (i32, i32) {
    let (x, y) = (state.x as i32, state.y as i32);
    let rect = ui_rect(ui, state);
    if ui.height > rect.height {
        let (bar, thumb) = scroll_rects(rect, ui, con);
        if inside(x, y, bar) {
            let sect = if inside(x, y, thumb) {
                -1
            } else if y < thumb.bottom {
                -2
            } else {
                -3
            };
            return (sect, -1);
        }
    }
    let (x, y) = mouse_in_ui(ui, state);
    let nsect = ui.nsect.clamp(0, mjMAXUISECT as i32) as usize;
    for (n, s) in ui.sect[..nsect].iter().enumerate() {
        if s.state < 2 && inside(x, y, s.rtitle) {
            return (n as i32 + 1, -1);
        }
        if s.state != 0 && inside(x, y, s.rcontent) {
            let nitem = s.nitem.clamp(0, mjMAXUIITEM as i32) as usize;
            for (i, it) in s.item[..nitem].iter().enumerate() {
                let hit = if is(it, mjtItem_::mjITEM_BUTTON) {
                    inside_oval(x, y, it.rect)
                } else {
                    inside(x, y, it.rect)
                };
                if hit {
                    return (n as i32 + 1, i as i32);
                }
            }
        }
    }
    (0, 0)
}
