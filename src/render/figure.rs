//! 2D figures (mjr_figure): a background, an optional title, x-label and tick labels, a pane
//! with a grid, the data lines, a selection line, a legend and a highlighted line, in the order
//! of 2.2.2's GL calls and with its float arithmetic.

use super::gl::consts::*;
use super::gl::Gl;
use super::text::{char_width, init_2d, text_actual, text_width};
use crate::abi::*;
use std::os::raw::c_char;

const FONT_NORMAL: i32 = mjtFont_::mjFONT_NORMAL as i32;
const FONT_SHADOW: i32 = mjtFont_::mjFONT_SHADOW as i32;
/// Margin of the unit and data projections around the pane.
const OFFSET: f32 = 0.001;
/// Smallest extent of an axis range.
const MIN_RANGE: f32 = 1e-5;
/// Size of 2.2.2's text buffers (the terminating NUL included).
const BUF: usize = 100;
/// At most this many grid lines and tick labels per axis.
const MAX_TICKS: i32 = 20;
/// Floats per line in `linedata`.
const LINE_FLOATS: usize = 2 * mjMAXLINEPNT;

/// The bytes of a fixed-size C string: up to its NUL or the end of the array.
fn cstr(a: &[c_char]) -> Vec<u8> {
    a.iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect()
}

/// Draws `fig` in `viewport` and writes back the axis ranges in pixels and data units.
pub fn figure(gl: &Gl, viewport: mjrRect, fig: &mut mjvFigure, con: &mjrContext) {
    let mut vp = viewport;
    if vp.width <= 0 || vp.height <= 0 {
        return;
    }
    let pad = con.charHeight / 2;
    init_2d(gl);
    gl.glViewport(vp.left, vp.bottom, vp.width, vp.height);
    fill_unit_square(gl, &fig.figurergba);

    let range = data_ranges(fig);
    fig.xaxisdata = range[0];
    fig.yaxisdata = range[1];

    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    if vp.width <= 1 || vp.height <= 1 {
        return;
    }
    ortho_pixels(gl, &vp);
    if !draw_labels(gl, fig, con, &mut vp, pad) {
        return;
    }
    if fig.gridsize[0] > 1 && fig.gridsize[1] > 1 {
        draw_ticks(gl, fig, con, &range, &mut vp, pad);
    }

    vp.left += pad;
    vp.width -= 2 * pad;
    vp.bottom += pad;
    vp.height -= 2 * pad;
    if vp.width <= 0 || vp.height <= 0 {
        return;
    }
    gl.glViewport(vp.left, vp.bottom, vp.width, vp.height);
    fig.xaxispixel = [vp.left, vp.left + vp.width - 1];
    fig.yaxispixel = [vp.bottom, vp.bottom + vp.height - 1];
    draw_plot(gl, fig, con, &range, &vp, pad);
}

/// Title and x label; shrinks `vp` by their height. False where 2.2.2 stops (nothing left).
fn draw_labels(gl: &Gl, fig: &mjvFigure, con: &mjrContext, vp: &mut mjrRect, pad: i32) -> bool {
    let sy_title = draw_title(gl, fig, con, vp, pad);
    let sy_label = draw_xlabel(gl, fig, con, vp, pad);
    if sy_title == 0 && sy_label == 0 {
        return true;
    }
    let below = if sy_label != 0 { sy_label + pad / 2 } else { 0 };
    let above = if sy_title != 0 { sy_title + pad } else { 0 };
    vp.bottom += below;
    vp.height -= below + above;
    if vp.width <= 0 || vp.height <= 0 {
        return false;
    }
    gl.glViewport(vp.left, vp.bottom, vp.width, vp.height);
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    ortho_pixels(gl, vp);
    true
}

/// The pane in the plot viewport `vp`: background, grid, lines, selection, legend and
/// highlighted line.
fn draw_plot(
    gl: &Gl,
    fig: &mjvFigure,
    con: &mjrContext,
    range: &[[f32; 2]; 2],
    vp: &mjrRect,
    pad: i32,
) {
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    let (lo, hi) = (-OFFSET as f64, (1.0 + OFFSET) as f64);
    gl.glOrtho(lo, hi, lo, hi, -1.0, 1.0);
    fill_unit_square(gl, &fig.panergba);

    gl.glEnableClientState(GL_VERTEX_ARRAY);
    if fig.gridsize[0] > 1 && fig.gridsize[1] > 1 {
        draw_grid(gl, fig);
    }
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    ortho_data(gl, range);
    for n in (0..mjMAXLINE).rev() {
        if fig.linepnt[n] != 0 {
            draw_line(gl, fig, n, fig.linewidth);
        }
    }
    if fig.flg_selection != 0 {
        gl.glColor3f(1.0, 1.0, 1.0);
        gl.glLineWidth(3.0);
        gl.glBegin(GL_LINES);
        gl.glVertex2f(fig.selection, range[1][0]);
        gl.glVertex2f(fig.selection, range[1][1]);
        gl.glEnd();
    }

    let mut hlight = fig.highlightid;
    if fig.flg_legend != 0 {
        match draw_legend(gl, fig, con, vp, pad) {
            None => return,
            Some(Some(n)) => hlight = n,
            Some(None) => {}
        }
    }
    if (0..mjMAXLINE as i32).contains(&hlight) {
        draw_highlight(gl, fig, con, range, hlight as usize);
    }
    gl.glDisableClientState(GL_VERTEX_ARRAY);
}

/// The unit square blended in `rgba`.
fn fill_unit_square(gl: &Gl, rgba: &[f32; 4]) {
    gl.glEnable(GL_BLEND);
    gl.color4fv(rgba);
    gl.glBegin(GL_QUADS);
    gl.glVertex2d(0.0, 0.0);
    gl.glVertex2d(0.0, 1.0);
    gl.glVertex2d(1.0, 1.0);
    gl.glVertex2d(1.0, 0.0);
    gl.glEnd();
    gl.glDisable(GL_BLEND);
}

/// Orthographic projection in the pixels of `vp`.
fn ortho_pixels(gl: &Gl, vp: &mjrRect) {
    gl.glOrtho(
        0.0,
        (vp.width - 1) as f64,
        0.0,
        (vp.height - 1) as f64,
        -1.0,
        1.0,
    );
}

/// Orthographic projection in data units, with a small margin.
fn ortho_data(gl: &Gl, range: &[[f32; 2]; 2]) {
    let difx = range[0][1] - range[0][0];
    let dify = range[1][1] - range[1][0];
    gl.glOrtho(
        (range[0][0] - difx * OFFSET) as f64,
        (range[0][1] + difx * OFFSET) as f64,
        (range[1][0] - dify * OFFSET) as f64,
        (range[1][1] + dify * OFFSET) as f64,
        -1.0,
        1.0,
    );
}

/// Floats of all lines from line `n` on (2.2.2 reads past a line's end into the next ones).
fn line_floats(fig: &mjvFigure, n: usize) -> &[f32] {
    &fig.linedata.as_flattened()[n * LINE_FLOATS..]
}

/// Axis ranges: the figure's where valid, otherwise (or also, with flg_extend) the span of
/// the finite data, widened to at least MIN_RANGE; y symmetric about 0 on request.
fn data_ranges(fig: &mjvFigure) -> [[f32; 2]; 2] {
    let mut range = fig.range;
    for axis in 0..2 {
        let mut valid = fig.range[axis][0] < fig.range[axis][1];
        if !valid || fig.flg_extend != 0 {
            for n in 0..mjMAXLINE {
                let data = line_floats(fig, n);
                let pnt = (fig.linepnt[n].max(0) as usize).min(data.len() / 2);
                for v in (0..pnt).map(|i| data[2 * i + axis]) {
                    if !v.is_finite() {
                        continue;
                    }
                    if !valid {
                        range[axis] = [v, v];
                        valid = true;
                    } else {
                        if range[axis][0] > v {
                            range[axis][0] = v;
                        }
                        if range[axis][1] < v {
                            range[axis][1] = v;
                        }
                    }
                }
            }
        }
        let extent = range[axis][1] - range[axis][0];
        if extent < MIN_RANGE {
            let needed = MIN_RANGE - extent;
            range[axis][0] -= 0.5 * needed;
            range[axis][1] += 0.5 * needed;
        }
    }
    if fig.flg_symmetric != 0 {
        let (a, b) = (range[1][0].abs(), range[1][1].abs());
        let ymax = if a > b { a } else { b };
        range[1] = [-ymax, ymax];
    }
    range
}

/// Title byte `i`, zero past the array.
fn title_at(title: &[u8], i: usize) -> u8 {
    title.get(i).copied().unwrap_or(0)
}

/// Start and length of subplot `subplot`'s title: titles are separated by 2+ spaces.
fn subplot_title(title: &[u8], subplot: i32) -> (usize, usize) {
    let at = |i| title_at(title, i);
    let (mut adr, mut cnt) = (0, 0);
    while cnt < subplot && at(adr) != 0 {
        while at(adr) != 0 && at(adr) != b' ' {
            adr += 1;
        }
        let mut spaces = 0;
        while at(adr) == b' ' {
            adr += 1;
            spaces += 1;
        }
        if spaces > 1 {
            cnt += 1;
        }
    }
    let word = |c: u8| c != 0 && c != b' ';
    let mut len = 0;
    while word(at(adr + len)) || word(at(adr + len + 1)) {
        len += 1;
    }
    (adr, len)
}

/// The selected subplot title centered at the top, within the neighbouring titles dimmed
/// toward the background. Returns its height (0 without a title).
fn draw_title(gl: &Gl, fig: &mjvFigure, con: &mjrContext, vp: &mjrRect, pad: i32) -> i32 {
    if fig.title[0] == 0 {
        return 0;
    }
    let title: Vec<u8> = fig.title.iter().map(|&c| c as u8).collect();
    let (adr, len) = subplot_title(&title, fig.subplot);
    if len == 0 {
        return 0;
    }
    let cw = |i: usize| char_width(con, title[i], false);
    let sy = con.charHeight;
    let sx: i32 = (adr..adr + len).map(cw).sum();
    let left = (vp.width / 2 - sx / 2).max(0);
    let (mut left1, mut adr1) = (left, adr);
    while adr1 > 0 && left1 >= cw(adr1 - 1) {
        left1 -= cw(adr1 - 1);
        adr1 -= 1;
    }
    let (mut len1, mut right1) = (0, left1);
    while title_at(&title, adr1 + len1) != 0 && right1 + cw(adr1 + len1) < vp.width {
        right1 += cw(adr1 + len1);
        len1 += 1;
    }
    let y = (vp.height - pad - sy) as f32;
    let mix = |i: usize| (0.4 * fig.textrgb[i] as f64 + 0.6 * fig.figurergba[i] as f64) as f32;
    gl.glListBase(con.baseFontNormal);
    gl.glColor4f(mix(0), mix(1), mix(2), 1.0);
    gl.glRasterPos3f(left1 as f32, y, 0.0);
    gl.call_lists_bytes(&title[adr1..adr1 + len1]);
    let rgb = fig.textrgb;
    gl.glListBase(con.baseFontNormal);
    gl.glColor4f(rgb[0], rgb[1], rgb[2], 1.0);
    gl.glRasterPos3f(left as f32, y, 0.0);
    gl.call_lists_bytes(&title[adr..adr + len]);
    sy
}

/// The x-axis label centered at the bottom. Returns its height (0 without a label).
fn draw_xlabel(gl: &Gl, fig: &mjvFigure, con: &mjrContext, vp: &mjrRect, pad: i32) -> i32 {
    let label = cstr(&fig.xlabel);
    if label.is_empty() {
        return 0;
    }
    let sx = text_width(con, &label);
    let x = (vp.width / 2 - sx / 2).max(0) as f32;
    text_actual(
        gl,
        FONT_NORMAL,
        &label,
        con,
        (x, pad as f32, 0.0),
        fig.textrgb,
    );
    con.charHeight
}

/// Value of tick `i` of `n` spanning `r`.
fn tick_value(r: &[f32; 2], i: i32, n: i32) -> f32 {
    r[0] + (r[1] - r[0]) * i as f32 / (n - 1) as f32
}

/// Tick labels below and left of the pane; shrinks `vp` by the space they take.
fn draw_ticks(
    gl: &Gl,
    fig: &mjvFigure,
    con: &mjrContext,
    range: &[[f32; 2]; 2],
    vp: &mut mjrRect,
    pad: i32,
) {
    let (xformat, yformat) = (cstr(&fig.xformat), cstr(&fig.yformat));
    let xtick_height = if fig.flg_ticklabel[0] != 0 {
        con.charHeight + pad
    } else {
        0
    };
    let ny = MAX_TICKS.min(fig.gridsize[1]);
    let mut ytick_width = 0;
    if fig.flg_ticklabel[1] != 0 {
        let minwidth = cstr(&fig.minwidth);
        if !minwidth.is_empty() {
            ytick_width = text_width(con, &minwidth);
        }
        for i in 0..ny {
            let txt = tick_text(&yformat, tick_value(&range[1], i, ny));
            ytick_width = ytick_width.max(text_width(con, &txt));
        }
        ytick_width += pad;
    }
    // 2.2.2 colors tick labels with the red of textrgb only
    let gray = [fig.textrgb[0]; 3];
    if fig.flg_ticklabel[0] != 0 {
        let n = MAX_TICKS.min(fig.gridsize[0]);
        for i in 0..n {
            let txt = tick_text(&xformat, tick_value(&range[0], i, n));
            let w = text_width(con, &txt);
            let shift = if i == 0 {
                0
            } else if i == n - 1 {
                -w
            } else {
                -w / 2
            };
            let span = (vp.width - 2 * pad - ytick_width) * i;
            let x = (pad + ytick_width + shift) as f32 + span as f32 / (n - 1) as f32;
            text_actual(gl, FONT_NORMAL, &txt, con, (x, pad as f32, 0.0), gray);
        }
    }
    if fig.flg_ticklabel[1] != 0 {
        for i in 0..ny {
            let txt = tick_text(&yformat, tick_value(&range[1], i, ny));
            let w = text_width(con, &txt);
            let span = (vp.height - 2 * pad - xtick_height) * i;
            let base = pad + xtick_height - con.charHeight / 2;
            let y = base as f32 + span as f32 / (ny - 1) as f32;
            let x = (ytick_width - w) as f32;
            text_actual(gl, FONT_NORMAL, &txt, con, (x, y, 0.0), gray);
        }
    }
    vp.left += ytick_width;
    vp.width -= ytick_width;
    vp.bottom += xtick_height;
    vp.height -= xtick_height;
}

/// A tick label: `num` printed with the figure's format, trailing zeros after a decimal
/// point removed (and the point itself when nothing follows it).
fn tick_text(format: &[u8], num: f32) -> Vec<u8> {
    let mut txt = format_number(format, num as f64);
    let mut i = txt.len();
    while i > 0 && txt[i - 1] == b'0' {
        i -= 1;
    }
    if i <= 1 {
        return txt;
    }
    if txt[i - 1] == b'.' {
        txt.truncate(i - 1);
        return txt;
    }
    let digits = txt[..i]
        .iter()
        .rev()
        .take_while(|c| c.is_ascii_digit())
        .count();
    if digits < i && txt[i - 1 - digits] == b'.' {
        txt.truncate(i);
    }
    txt
}

/// Whether `format` takes at most one floating-point conversion and nothing else, so that
/// snprintf may be given one double.
fn takes_one_double(format: &[u8]) -> bool {
    let mut convs = 0;
    let mut it = format.iter().copied().peekable();
    while let Some(c) = it.next() {
        if c != b'%' {
            continue;
        }
        if it.peek() == Some(&b'%') {
            it.next();
            continue;
        }
        while matches!(
            it.peek(),
            Some(b'-' | b'+' | b' ' | b'#' | b'\'' | b'0'..=b'9' | b'.')
        ) {
            it.next();
        }
        if it.peek() == Some(&b'l') {
            it.next();
        }
        match it.next() {
            Some(b'f' | b'F' | b'e' | b'E' | b'g' | b'G' | b'a' | b'A') => convs += 1,
            _ => return false,
        }
    }
    convs <= 1
}

/// `num` printed by C's snprintf with the user's `format` into a buffer of BUF bytes; empty
/// for formats that would not take a single double.
fn format_number(format: &[u8], num: f64) -> Vec<u8> {
    if !takes_one_double(format) {
        return Vec::new();
    }
    let Ok(fmt) = std::ffi::CString::new(format) else {
        return Vec::new();
    };
    let mut buf = [0u8; BUF];
    // SAFETY: the format takes at most one double (checked above); buf bounds the output.
    let len = unsafe { libc::snprintf(buf.as_mut_ptr().cast(), BUF, fmt.as_ptr(), num) };
    buf[..(len.max(0) as usize).min(BUF - 1)].to_vec()
}

/// The grid: vertical then horizontal lines across the unit pane.
fn draw_grid(gl: &Gl, fig: &mjvFigure) {
    let lines = |size: i32, vertical: bool| -> Vec<f32> {
        let n = MAX_TICKS.min(size);
        (0..n)
            .flat_map(|i| {
                let t = i as f32 / (n - 1) as f32;
                if vertical {
                    [t, 0.0, t, 1.0]
                } else {
                    [0.0, t, 1.0, t]
                }
            })
            .collect()
    };
    let (vertical, horizontal) = (lines(fig.gridsize[0], true), lines(fig.gridsize[1], false));
    vertex_pointer(gl, &vertical);
    gl.color3fv(&fig.gridrgb);
    gl.glLineWidth(fig.gridwidth);
    draw_arrays(gl, &vertical, GL_LINES, vertical.len() as i32 / 2);
    vertex_pointer(gl, &horizontal);
    draw_arrays(gl, &horizontal, GL_LINES, horizontal.len() as i32 / 2);
}

/// Points `data` to GL as the 2D vertex array.
fn vertex_pointer(gl: &Gl, data: &[f32]) {
    // SAFETY: GL keeps the pointer; `draw_arrays` reads it only while `data` is borrowed.
    unsafe { gl.glVertexPointer(2, GL_FLOAT, 0, data.as_ptr().cast()) };
}

/// Draws `count` vertices of `data`, the array last given to `vertex_pointer` (at most the
/// vertices it holds; a negative count is passed on for GL to reject).
fn draw_arrays(gl: &Gl, data: &[f32], mode: u32, count: i32) {
    let count = count.min((data.len() / 2).min(i32::MAX as usize) as i32);
    gl.glDrawArrays(mode, 0, count);
}

/// Line `n` of the figure in its color with `width`.
fn draw_line(gl: &Gl, fig: &mjvFigure, n: usize, width: f32) {
    let data = line_floats(fig, n);
    vertex_pointer(gl, data);
    gl.color3fv(&fig.linergb[n]);
    gl.glLineWidth(width);
    let mode = if fig.flg_barplot != 0 {
        GL_LINES
    } else {
        GL_LINE_STRIP
    };
    draw_arrays(gl, data, mode, fig.linepnt[n]);
}

/// The legend at the top right of the pane: named lines from `legendoffset` on, as many as
/// fit. Returns None where 2.2.2 stops drawing the figure (a pane of one pixel), else the
/// line whose name the highlight point falls on.
fn draw_legend(
    gl: &Gl,
    fig: &mjvFigure,
    con: &mjrContext,
    vp: &mjrRect,
    pad: i32,
) -> Option<Option<i32>> {
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    if vp.width <= 1 || vp.height <= 1 {
        return None;
    }
    ortho_pixels(gl, vp);
    let ch = con.charHeight;
    let first = fig.legendoffset.max(0) as usize;
    let names: Vec<(usize, Vec<u8>)> = (first..mjMAXLINE)
        .map(|n| (n, cstr(&fig.linename[n])))
        .filter(|(_, s)| !s.is_empty())
        .collect();
    let (mut lw, mut lh, mut cnt) = (0, 0, 0);
    for (_, name) in &names {
        lw = lw.max(text_width(con, name));
        lh += ch;
        cnt += 1;
        if lh + 2 * pad >= vp.height {
            cnt -= 1;
            lh -= ch;
            break;
        }
    }
    let hx = fig.highlight[0] - vp.left;
    let hy = fig.highlight[1] - vp.bottom;
    let mut hcnt = -1;
    if hx >= vp.width - pad - lw
        && hx <= vp.width - pad
        && hy >= vp.height - pad - lh
        && hy <= vp.height - pad
    {
        hcnt = (vp.height - pad - hy).checked_div(ch).unwrap_or(-1);
    }
    if cnt != 0 {
        legend_box(gl, fig, vp, (lw, lh), pad);
    }
    let mut hlight = None;
    for (cnt, (n, name)) in (0..).zip(&names) {
        let x = vp.width - pad - text_width(con, name);
        let y = vp.height - pad - (cnt + 1) * ch;
        let pos = (x as f32, y as f32, 0.0);
        text_actual(gl, FONT_SHADOW, name, con, pos, fig.linergb[*n]);
        if hcnt == cnt {
            hlight = Some(*n as i32);
        }
        if (cnt + 2) * ch + 2 * pad >= vp.height {
            break;
        }
    }
    Some(hlight)
}

/// The legend's background, `size` of text plus padding, at the top right of the pane.
fn legend_box(gl: &Gl, fig: &mjvFigure, vp: &mjrRect, size: (i32, i32), pad: i32) {
    let x0 = (vp.width - 2 * pad - size.0) as f64;
    let y0 = (vp.height - 2 * pad - size.1) as f64;
    let (x1, y1) = (vp.width as f64, vp.height as f64);
    gl.glEnable(GL_BLEND);
    gl.color4fv(&fig.legendrgba);
    gl.glBegin(GL_QUADS);
    gl.glVertex2d(x0, y0);
    gl.glVertex2d(x0, y1);
    gl.glVertex2d(x1, y1);
    gl.glVertex2d(x1, y0);
    gl.glEnd();
    gl.glDisable(GL_BLEND);
}

/// Float `i` of the flattened line data; 2.2.2 reads the two floats before the data (the
/// last two point counts) when a highlighted first line has no points.
fn line_float(fig: &mjvFigure, i: isize) -> f32 {
    if i < 0 {
        let k = (mjMAXLINE as isize + i) as usize;
        return f32::from_bits(fig.linepnt[k] as u32);
    }
    fig.linedata.as_flattened()[i as usize]
}

/// Line `n` redrawn five times wider, and with a selection line, the data point nearest to
/// it printed near the lower left corner.
fn draw_highlight(gl: &Gl, fig: &mjvFigure, con: &mjrContext, range: &[[f32; 2]; 2], n: usize) {
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    ortho_data(gl, range);
    draw_line(gl, fig, n, 5.0 * fig.linewidth);
    if fig.flg_selection == 0 {
        return;
    }
    let data = line_floats(fig, n);
    let pnt = (fig.linepnt[n].max(0) as usize).min(data.len() / 2);
    let mut best: Option<(usize, f32)> = None;
    for i in 0..pnt {
        let d = (fig.selection - data[2 * i]).abs();
        if best.is_none_or(|(_, b)| b > d) {
            best = Some((i, d));
        }
    }
    let ibest = best.map_or(-1, |(i, _)| i as isize);
    let at = (n * LINE_FLOATS) as isize + 2 * ibest;
    let (x, y) = (line_float(fig, at), line_float(fig, at + 1));
    let g = |v: f32| crate::runtime::message::format_c(c"%.4g", &[v as f64]);
    let txt = format!("( {} : {} )", g(x), g(y));
    let r = |a: usize| (0.9 * range[a][0] as f64 + 0.1 * range[a][1] as f64) as f32;
    text_actual(
        gl,
        FONT_SHADOW,
        txt.as_bytes(),
        con,
        (r(0), r(1), 0.0),
        fig.textrgb,
    );
}
