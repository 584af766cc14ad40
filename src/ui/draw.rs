//! mjui_update: drawing sections and items into the UI's auxiliary buffer; mjui_render:
//! copying that image into the window with its scrollbar.

use super::edit;
use super::host::{enabled, Host};
use super::locate::{self, find_mouse, find_select, item_at, nelem, radio_element, ui_rect};
use super::paint::{width_upto, Pen};
use crate::abi::cstr::cbytes;
use crate::abi::*;
use crate::engine::EngineError;
use crate::math::misc::round;
use crate::render::framebuffer::{blit_aux, restore_buffer, set_aux};
use crate::render::gl::consts::*;
use crate::render::gl::Gl;
use crate::render::text::rectangle;
use crate::runtime::message::format_c;
use mjtItem_::*;

/// C's fmax/fmin as the mjMAX/mjMIN macros compute them (NaN passes through).
fn cmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

fn cmin(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// Theme gaps in framebuffer units and state shared by the items of one update.
struct Ctx<'a> {
    pen: Pen<'a>,
    host: &'a dyn Host,
    state: &'a mjuiState,
    texthor: i32,
    textver: i32,
    label: i32,
    itemside: i32,
    cellheight: i32,
    /// Section and item under the mouse.
    mouse: (i32, i32),
}

fn init_gl(gl: &Gl, ui: &mjUI) {
    for cap in [
        GL_NORMALIZE,
        GL_DEPTH_TEST,
        GL_CULL_FACE,
        GL_LIGHTING,
        GL_COLOR_MATERIAL,
        GL_BLEND,
    ] {
        gl.glDisable(cap);
    }
    gl.glShadeModel(GL_SMOOTH);
    gl.glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    gl.glOrtho(0.0, ui.width as f64, 0.0, ui.height as f64, -1.0, 1.0);
    gl.glMatrixMode(GL_MODELVIEW);
    gl.glLoadIdentity();
    gl.glViewport(0, 0, ui.width, ui.height);
}

/// Redraws item `item` of section `section`, a whole section (item < 0) or everything
/// (section < 0) into the UI's auxiliary buffer (mjui_update).
pub fn update(
    gl: &Gl,
    section: i32,
    item: i32,
    ui: &mjUI,
    state: &mjuiState,
    con: &mjrContext,
    host: &dyn Host,
) -> Result<(), EngineError> {
    let pen = Pen { gl, con, ui };
    let textver = pen.scl(ui.spacing.textver);
    let cx = Ctx {
        texthor: pen.scl(ui.spacing.texthor),
        textver,
        label: pen.scl(ui.spacing.label),
        itemside: pen.scl(ui.spacing.itemside),
        cellheight: con.charHeight + 2 * textver,
        mouse: find_mouse(ui, state, con),
        pen,
        host,
        state,
    };
    set_aux(gl, ui.auxid, con)?;
    init_gl(gl, ui);
    if section < 0 {
        let m = &ui.color.master;
        gl.glClearColor(m[0], m[1], m[2], 1.0);
        gl.glClear(GL_COLOR_BUFFER_BIT);
    }
    let nsect = ui.nsect.clamp(0, mjMAXUISECT as i32);
    let sections = if section >= 0 {
        section..(section + 1).min(nsect)
    } else {
        0..nsect
    };
    for n in sections {
        draw_section(
            &cx,
            n,
            section < 0 || item < 0,
            (section >= 0).then_some(item),
        );
    }
    if let Some(it) = item_at(ui, ui.mousesect, ui.mouseitem) {
        if locate::is(it, mjITEM_SELECT) {
            draw_open_select(&cx, it);
        }
    }
    restore_buffer(gl, con);
    Ok(())
}

/// Section `n`: title and pane when `whole`, then its items (only `only` when given and not
/// negative).
fn draw_section(cx: &Ctx, n: i32, whole: bool, only: Option<i32>) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    let s = &ui.sect[n as usize];
    let maxwidth =
        (s.rtitle.width - 2 * cx.itemside - pen.scl(ui.spacing.itemmid)) / 2 - 2 * cx.texthor;
    if whole {
        if s.state < 2 {
            pen.gradient(s.rtitle, &ui.color.sectpane, &ui.color.secttitle);
            pen.symbol(s.rtitle, s.state != 0, false);
            let (x, y) = (s.rtitle.left + cx.texthor, s.rtitle.bottom + cx.textver);
            pen.name(&s.name, x, y, 2 * maxwidth, &ui.color.sectfont);
            if ui.mousehelp != 0 && s.shortcut != 0 {
                pen.shortcut(s.rtitle, s.modifier, s.shortcut);
            }
        }
        if s.state != 0 {
            pen.rect(s.rcontent, &ui.color.sectpane, None);
        }
    }
    if s.state == 0 {
        return;
    }
    let nitem = s.nitem.clamp(0, mjMAXUIITEM as i32);
    let items = match only {
        Some(i) if i >= 0 => i..(i + 1).min(nitem),
        _ => 0..nitem,
    };
    for i in items {
        let it = &s.item[i as usize];
        if it.rect.height != 0 {
            draw_item(cx, s, it, (n, i), maxwidth);
        }
    }
}

/// Colors of an item: font, decoration and second decoration.
struct Colors {
    font: [f32; 3],
    decor: [f32; 3],
    decor2: [f32; 3],
    active: bool,
}

fn draw_item(cx: &Ctx, s: &mjuiSection, it: &mjuiItem, (n, i): (i32, i32), maxwidth: i32) {
    let ui = cx.pen.ui;
    let c = &ui.color;
    let active = enabled(it.state, ui, cx.host);
    let mut col = Colors {
        font: if active { c.fontactive } else { c.fontinactive },
        decor: c.decorinactive,
        decor2: c.decorinactive2,
        active,
    };
    let label_x = s.rcontent.left + cx.itemside + cx.texthor;
    let t = it.r#type;
    if t == mjITEM_SEPARATOR as i32 {
        draw_separator(cx, it);
    } else if t == mjITEM_STATIC as i32 {
        draw_static(cx, it, label_x, &col);
    } else if t == mjITEM_BUTTON as i32 {
        draw_button(cx, it, (n, i), maxwidth, &mut col);
    } else if t == mjITEM_CHECKINT as i32 || t == mjITEM_CHECKBYTE as i32 {
        draw_check(cx, it, maxwidth, &mut col);
    } else if t == mjITEM_RADIO as i32 {
        draw_radio(cx, it, label_x, &mut col);
    } else if t == mjITEM_RADIOLINE as i32 {
        draw_radioline(cx, it, label_x, &mut col);
    } else if t == mjITEM_SELECT as i32 {
        draw_select(cx, it, label_x, &mut col);
    } else if t == mjITEM_SLIDERINT as i32 || t == mjITEM_SLIDERNUM as i32 {
        draw_slider(cx, it, label_x, &mut col);
    } else if t == mjITEM_EDITINT as i32 || t == mjITEM_EDITNUM as i32 || t == mjITEM_EDITTXT as i32
    {
        draw_edit(cx, it, (n, i), label_x, &mut col);
    } else {
        crate::runtime::message::error("mjui_update: internal error: unexpected item type");
    }
}

/// The item's name in the label column.
fn label(cx: &Ctx, it: &mjuiItem, x: i32, y: i32, col: &Colors) {
    cx.pen
        .name(&it.name, x, y, cx.label - 2 * cx.texthor, &col.font);
}

fn draw_separator(cx: &Ctx, it: &mjuiItem) {
    let (pen, c) = (&cx.pen, &cx.pen.ui.color);
    let r = it.rect;
    pen.gradient(r, &c.sectpane, &c.master);
    let (x, y) = (r.left + cx.texthor, r.bottom + cx.textver);
    pen.name(&it.name, x, y, r.width - 2 * cx.texthor, &c.sectfont);
    if it.state == mjSEPCLOSED + 1 {
        pen.symbol(r, true, true);
    } else if it.state == mjSEPCLOSED {
        pen.symbol(r, false, true);
    }
}

fn draw_static(cx: &Ctx, it: &mjuiItem, label_x: i32, col: &Colors) {
    let pen = &cx.pen;
    let r = it.rect;
    let n = nelem(it);
    let line = pen.con.charHeight + cx.textver;
    label(cx, it, label_x, r.bottom + cx.textver + (n - 1) * line, col);
    let pane = &pen.ui.color.sectpane;
    pen.rect(r, pane, Some(pane));
    for k in 0..n {
        let y = r.bottom + cx.textver + (n - k - 1) * line;
        let txt = &it.multi().name[k as usize];
        pen.name(
            txt,
            r.left + cx.texthor,
            y,
            r.width - 2 * cx.texthor,
            &col.font,
        );
    }
}

fn draw_button(cx: &Ctx, it: &mjuiItem, (n, i): (i32, i32), maxwidth: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.button;
    }
    let pressed = ui.mousesect == n + 1 && ui.mouseitem == i && cx.mouse == (n + 1, i);
    let back = (!pressed).then_some(&ui.color.sectpane);
    pen.oval(it.rect, &col.decor, back);
    let (x, y) = (it.rect.left + cx.texthor, it.rect.bottom + cx.textver);
    pen.name(&it.name, x, y, maxwidth, &col.font);
    let single = it.single();
    if ui.mousehelp != 0 && single.shortcut != 0 {
        pen.shortcut(it.rect, single.modifier, single.shortcut);
    }
}

fn draw_check(cx: &Ctx, it: &mjuiItem, maxwidth: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.check;
    }
    let on = if locate::is(it, mjITEM_CHECKINT) {
        cx.host.int(it, 0) != 0
    } else {
        cx.host.byte(it) != 0
    };
    let back = (!on).then_some(&ui.color.sectpane);
    pen.rect(it.rect, &col.decor, back);
    let (x, y) = (it.rect.left + cx.texthor, it.rect.bottom + cx.textver);
    pen.name(&it.name, x, y, maxwidth, &col.font);
    let single = it.single();
    if ui.mousehelp != 0 && single.shortcut != 0 {
        pen.shortcut(it.rect, single.modifier, single.shortcut);
    }
}

fn draw_radio(cx: &Ctx, it: &mjuiItem, label_x: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.radio;
    }
    let y = it.rect.bottom + it.rect.height - cx.cellheight + cx.textver;
    label(cx, it, label_x, y, col);
    pen.rect(it.rect, &col.decor, Some(&ui.color.sectpane));
    let sel = radio_element(it, cx.host.int(it, 0), ui, pen.con);
    pen.rect(sel, &col.decor, None);
    for k in 0..nelem(it) {
        let r = radio_element(it, k, ui, pen.con);
        let txt = &it.multi().name[k as usize];
        let (x, y) = (r.left + cx.texthor, r.bottom + cx.textver);
        pen.name(txt, x, y, r.width - 2 * cx.texthor, &col.font);
    }
}

fn draw_radioline(cx: &Ctx, it: &mjuiItem, label_x: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.radio;
    }
    label(cx, it, label_x, it.rect.bottom + cx.textver, col);
    pen.rect(it.rect, &col.decor, Some(&ui.color.sectpane));
    let sep = locate::radioline_seps(it, pen.con);
    let element = |k: usize| {
        let mut r = it.rect;
        let (a, b) = (sep.get(k).copied(), sep.get(k + 1).copied());
        r.left += a.unwrap_or(0);
        r.width = b.unwrap_or(0) - a.unwrap_or(0);
        r
    };
    let sel = cx.host.int(it, 0);
    pen.rect(element(sel.max(0) as usize), &col.decor, None);
    for k in 0..nelem(it) as usize {
        pen.text_centered(element(k), cbytes(&it.multi().name[k]), &col.font);
    }
}

fn draw_select(cx: &Ctx, it: &mjuiItem, label_x: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.select;
    }
    label(cx, it, label_x, it.rect.bottom + cx.textver, col);
    pen.rect(it.rect, &col.decor, None);
    if it.multi().nelem > 0 {
        let k = cx.host.int(it, 0).clamp(0, mjMAXUIMULTI as i32 - 1) as usize;
        let (x, y) = (it.rect.left + cx.texthor, it.rect.bottom + cx.textver);
        let w = it.rect.width - 2 * cx.texthor;
        pen.name(&it.multi().name[k], x, y, w, &col.font);
    }
}

fn draw_slider(cx: &Ctx, it: &mjuiItem, label_x: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.slider;
        col.decor2 = ui.color.slider2;
    }
    let int = locate::is(it, mjITEM_SLIDERINT);
    let value = if int {
        cx.host.int(it, 0) as f64
    } else {
        cx.host.num(it, 0)
    };
    let sl = it.slider();
    let sel = (value - sl.range[0]) / cmax(1e-10, sl.range[1] - sl.range[0]);
    let sel = cmin(1.0, cmax(0.0, sel));
    let mut r = it.rect;
    pen.rect(r, &col.decor, None);
    r.width = round(r.width as f64 * sel);
    pen.rect(r, &col.decor2, None);
    if sl.divisions <= 20.0 {
        r.width = pen.scl(2);
        r.height = cx.textver;
        for k in 1..sl.divisions as i32 {
            let left =
                (it.rect.left - r.width / 2) as f64 + (it.rect.width * k) as f64 / sl.divisions;
            r.left = left as i32;
            pen.rect(r, &ui.color.sectpane, None);
        }
    }
    label(cx, it, label_x, it.rect.bottom + cx.textver, col);
    let text = if int {
        cx.host.int(it, 0).to_string()
    } else {
        format_c(c"%.3g", &[value])
    };
    let (x, y) = (it.rect.left + cx.texthor, it.rect.bottom + cx.textver);
    pen.text(
        text.as_bytes(),
        x,
        y,
        it.rect.width - 2 * cx.texthor,
        &col.font,
    );
}

fn draw_edit(cx: &Ctx, it: &mjuiItem, (n, i): (i32, i32), label_x: i32, col: &mut Colors) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    if col.active {
        col.decor = ui.color.edit;
    }
    label(cx, it, label_x, it.rect.bottom + cx.textver, col);
    let (x, y) = (it.rect.left + cx.texthor, it.rect.bottom + cx.textver);
    let w = it.rect.width - 2 * cx.texthor;
    if !(ui.editsect > 0 && ui.editsect == n + 1 && ui.edititem == i) {
        pen.rect(it.rect, &col.decor, Some(&ui.color.sectpane));
        pen.text(&edit::show(it, cx.host), x, y, w, &col.font);
        return;
    }
    let (bytes, len) = edit::edit_bytes(ui);
    let text = &bytes[..len];
    let fill = if edit::valid(text, it) {
        &col.decor
    } else {
        &ui.color.edit2
    };
    pen.rect(it.rect, fill, None);
    let shown = text.get(ui.editscroll.max(0) as usize..).unwrap_or(&[]);
    let k = width_upto(shown, pen.con, ui.editcursor - ui.editscroll);
    let one = pen.scl(1);
    let cursor = mjrRect {
        left: it.rect.left + cx.texthor + k - one,
        bottom: it.rect.bottom + cx.textver / 2,
        width: 2 * one,
        height: it.rect.height - 2 * (cx.textver / 2),
    };
    pen.rect(cursor, &ui.color.cursor, None);
    pen.text(shown, x, y, w, &col.font);
}

/// The open list of a select item the mouse holds, over the items below it.
fn draw_open_select(cx: &Ctx, it: &mjuiItem) {
    let (pen, ui) = (&cx.pen, cx.pen.ui);
    let n = it.multi().nelem;
    let mut r = it.rect;
    r.left -= cx.itemside;
    r.width += 2 * cx.itemside;
    r.height = n * cx.cellheight + cx.itemside;
    r.bottom -= r.height;
    pen.rect(r, &ui.color.sectpane, None);
    let mut r = it.rect;
    r.height = n * cx.cellheight;
    r.bottom -= r.height;
    pen.rect(r, &ui.color.select2, None);
    if let Some(k) = find_select(it, ui, cx.state, pen.con) {
        let mut r1 = r;
        r1.bottom = r.bottom + (n - 1 - k) * cx.cellheight;
        r1.height = cx.cellheight;
        pen.rect(r1, &ui.color.select, None);
    }
    for k in 0..nelem(it) {
        let y = r.bottom + cx.textver + (n - 1 - k) * cx.cellheight;
        let txt = &it.multi().name[k as usize];
        let w = r.width - 2 * cx.texthor;
        pen.name(txt, r.left + cx.texthor, y, w, &ui.color.fontactive);
    }
}

/// Copies the UI's image into its rectangle of the current buffer, scrolled, with the
/// scrollbar's thumb when it does not fit (mjui_render).
pub fn render(
    gl: &Gl,
    ui: &mut mjUI,
    state: &mjuiState,
    con: &mjrContext,
) -> Result<(), EngineError> {
    let rect = ui_rect(ui, state);
    let m = ui.color.master;
    rectangle(gl, rect, [m[0], m[1], m[2], 1.0]);
    if ui.scroll > 0 && ui.height - ui.scroll < rect.height {
        ui.scroll = (ui.height - rect.height).max(0);
    }
    let src = mjrRect {
        left: 0,
        bottom: (ui.height - ui.scroll - rect.height).max(0),
        width: ui.width,
        height: rect.height.min(ui.height - ui.scroll),
    };
    let bottom = rect.bottom + (rect.height - ui.height + ui.scroll).max(0);
    blit_aux(gl, ui.auxid, src, (rect.left, bottom), con)?;
    if ui.height > rect.height {
        let (_, thumb) = locate::scroll_rects(rect, ui, con);
        let t = ui.color.thumb;
        rectangle(gl, thumb, [t[0], t[1], t[2], 1.0]);
    }
    Ok(())
}
