//! 2D drawing: text in the bitmap fonts, text overlays in the corners of a viewport,
//! rectangles and labels.

use super::gl::consts::*;
use super::gl::Gl;
use crate::abi::*;

/// Width of character `c` in the normal (or big) font, read where 2.2.2 reads it: codes past
/// the 127-entry table continue into the fields after it.
pub fn char_width(con: &mjrContext, c: u8, big: bool) -> i32 {
    let c = c as usize;
    let tail = [
        con.charHeight,
        con.charHeightBig,
        con.glInitialized,
        con.windowAvailable,
        con.windowSamples,
        con.windowStereo,
        con.windowDoublebuffer,
        con.currentBuffer,
    ];
    let table = if big {
        &con.charWidthBig
    } else {
        &con.charWidth
    };
    if c < 127 {
        return table[c];
    }
    match (big, c - 127) {
        (false, k) if k < 127 => con.charWidthBig[k],
        (false, k) => tail[k - 127],
        (true, k) => tail.get(k).copied().unwrap_or(0),
    }
}

/// Width of `text` in pixels in the normal font.
pub fn text_width(con: &mjrContext, text: &[u8]) -> i32 {
    text.iter().map(|&c| char_width(con, c, false)).sum()
}

/// GL state for 2D drawing in the unit square.
pub fn init_2d(gl: &Gl) {
    for cap in [GL_NORMALIZE, GL_DEPTH_TEST] {
        gl.glDisable(cap);
    }
    gl.glShadeModel(GL_FLAT);
    for cap in [GL_CULL_FACE, GL_LIGHTING, GL_COLOR_MATERIAL, GL_BLEND] {
        gl.glDisable(cap);
    }
    gl.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    gl.glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
    gl.glMatrixMode(GL_MODELVIEW);
    gl.glLoadIdentity();
}

const FONT_SHADOW: i32 = mjtFont_::mjFONT_SHADOW as i32;
const FONT_BIG: i32 = mjtFont_::mjFONT_BIG as i32;

/// Text at (x, y, z) with the current GL state (mjr_textActual); the shadow font draws a
/// half-transparent black shadow first.
#[allow(clippy::too_many_arguments)]
pub fn text_actual(
    gl: &Gl,
    font: i32,
    txt: &[u8],
    con: &mjrContext,
    (x, y, z): (f32, f32, f32),
    rgb: [f32; 3],
) {
    if con.rangeFont == 0 {
        return;
    }
    if font == FONT_SHADOW {
        gl.glListBase(con.baseFontShadow);
        gl.glColor4f(0.0, 0.0, 0.0, 0.5);
        gl.glRasterPos3f(x, y, z);
        gl.call_lists_bytes(txt);
    }
    let base = if font == FONT_BIG {
        con.baseFontBig
    } else {
        con.baseFontNormal
    };
    gl.glListBase(base);
    gl.glColor4f(rgb[0], rgb[1], rgb[2], 1.0);
    gl.glRasterPos3f(x, y, z);
    gl.call_lists_bytes(txt);
}

/// Text at relative (x, y) (mjr_text).
pub fn text(gl: &Gl, font: i32, txt: &[u8], con: &mjrContext, x: f32, y: f32, rgb: [f32; 3]) {
    init_2d(gl);
    text_actual(gl, font, txt, con, (x, y, 0.0), rgb);
}

/// One column of an overlay at `gridpos`, `skip` pixels in from the side: a dark box and the
/// lines of `overlay` (at most mjMAXOVERLAY characters). Returns the width for the next column.
#[allow(clippy::too_many_arguments)]
fn overlay_column(
    gl: &Gl,
    font: i32,
    viewport: &mjrRect,
    skip: i32,
    gridpos: i32,
    rgb: [f32; 3],
    overlay: &[u8],
    con: &mjrContext,
) -> i32 {
    const PAD: i32 = 5;
    let big = font == FONT_BIG;
    let line_height = if big {
        con.charHeightBig
    } else {
        con.charHeight
    };
    let overlay = &overlay[..overlay.len().min(mjMAXOVERLAY)];
    let (mut nr, mut nc, mut ncthis) = (line_height, 0, 0);
    for &c in overlay {
        if c != b'\n' {
            ncthis += char_width(con, c, big);
            nc = nc.max(ncthis);
        } else {
            nr += PAD + line_height;
            ncthis = 0;
        }
    }
    let (w, h) = (PAD + nc + 8, PAD + nr);
    let v = viewport;
    let left = v.left + skip + PAD;
    let right = v.left + v.width - skip - 1 - PAD - w;
    let top = v.bottom + v.height - 1 - PAD - h;
    let bottom = v.bottom + PAD;
    use mjtGridPos_::*;
    let (x, y) = match gridpos {
        g if g == mjGRID_TOPLEFT as i32 => (left, top),
        g if g == mjGRID_TOPRIGHT as i32 => (right, top),
        g if g == mjGRID_BOTTOMLEFT as i32 => (left, bottom),
        g if g == mjGRID_BOTTOMRIGHT as i32 => (right, bottom),
        _ => (i32::MIN, i32::MIN),
    };
    if x != i32::MIN {
        gl.glViewport(x, y, w, h);
    }
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    gl.glOrtho(0.0, (w - 1) as f64, 0.0, (h - 1) as f64, -1.0, 1.0);
    gl.glMatrixMode(GL_MODELVIEW);
    gl.glLoadIdentity();
    gl.glEnable(GL_BLEND);
    gl.glColor4d(0.0, 0.0, 0.0, 0.5);
    gl.glBegin(GL_QUADS);
    gl.glNormal3d(0.0, 0.0, 1.0);
    gl.glVertex2d(0.0, 0.0);
    gl.glVertex2d(0.0, h as f64);
    gl.glVertex2d(w as f64, h as f64);
    gl.glVertex2d(w as f64, 0.0);
    gl.glEnd();
    gl.glDisable(GL_BLEND);
    let mut nr = line_height;
    let mut line: Vec<u8> = Vec::with_capacity(overlay.len());
    for (i, &c) in overlay.iter().enumerate() {
        let last = i + 1 == overlay.len();
        if c == b'\n' || last {
            if c != b'\n' {
                line.push(c);
            }
            text_actual(gl, font, &line, con, (3.0, (h - nr) as f32, 0.0), rgb);
            nr += PAD + line_height;
            line.clear();
        } else {
            line.push(c);
        }
    }
    w - 2
}

/// A text overlay of one or two columns at a corner of the viewport (mjr_overlay).
pub fn overlay(
    gl: &Gl,
    font: i32,
    gridpos: i32,
    viewport: mjrRect,
    overlay: &[u8],
    overlay2: &[u8],
    con: &mjrContext,
) {
    if viewport.width <= 0 || viewport.height <= 0 {
        return;
    }
    init_2d(gl);
    let (gray, white) = ([0.7, 0.7, 0.7], [1.0, 1.0, 1.0]);
    if overlay2.is_empty() {
        overlay_column(gl, font, &viewport, 0, gridpos, white, overlay, con);
        return;
    }
    let left = gridpos == mjtGridPos_::mjGRID_TOPLEFT as i32
        || gridpos == mjtGridPos_::mjGRID_BOTTOMLEFT as i32;
    let (first, second) = if left {
        ((overlay, gray), (overlay2, white))
    } else {
        ((overlay2, white), (overlay, gray))
    };
    let skip = overlay_column(gl, font, &viewport, 0, gridpos, first.1, first.0, con);
    overlay_column(gl, font, &viewport, skip, gridpos, second.1, second.0, con);
}

/// A filled rectangle blended over the viewport (mjr_rectangle).
pub fn rectangle(gl: &Gl, viewport: mjrRect, rgba: [f32; 4]) {
    if viewport.width <= 0 || viewport.height <= 0 {
        return;
    }
    init_2d(gl);
    gl.glViewport(
        viewport.left,
        viewport.bottom,
        viewport.width,
        viewport.height,
    );
    gl.glEnable(GL_BLEND);
    gl.glColor4f(rgba[0], rgba[1], rgba[2], rgba[3]);
    gl.glBegin(GL_QUADS);
    gl.glVertex2f(0.0, 0.0);
    gl.glVertex2f(0.0, 1.0);
    gl.glVertex2f(1.0, 1.0);
    gl.glVertex2f(1.0, 0.0);
    gl.glEnd();
    gl.glDisable(GL_BLEND);
}

/// A rectangle with text centered on it (mjr_label).
pub fn label(
    gl: &Gl,
    viewport: mjrRect,
    font: i32,
    txt: Option<&[u8]>,
    rgba: [f32; 4],
    text_rgb: [f32; 3],
    con: &mjrContext,
) {
    if viewport.width <= 0 || viewport.height <= 0 {
        return;
    }
    for cap in [
        GL_NORMALIZE,
        GL_DEPTH_TEST,
        GL_CULL_FACE,
        GL_LIGHTING,
        GL_COLOR_MATERIAL,
    ] {
        gl.glDisable(cap);
    }
    gl.glShadeModel(GL_FLAT);
    gl.glEnable(GL_BLEND);
    gl.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    let (w, h) = (viewport.width, viewport.height);
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    gl.glOrtho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0);
    gl.glMatrixMode(GL_MODELVIEW);
    gl.glLoadIdentity();
    gl.glViewport(viewport.left, viewport.bottom, w, h);
    gl.glBegin(GL_QUADS);
    gl.glColor4f(rgba[0], rgba[1], rgba[2], rgba[3]);
    gl.glVertex2i(0, 0);
    gl.glVertex2i(w, 0);
    gl.glVertex2i(w, h);
    gl.glVertex2i(0, h);
    gl.glEnd();
    let Some(txt) = txt.filter(|_| con.rangeFont != 0) else {
        return;
    };
    let big = font == FONT_BIG;
    let width: i32 = txt.iter().map(|&c| char_width(con, c, big)).sum();
    let cx = (w - width) / 2;
    let cy = (h - if big {
        con.charHeightBig
    } else {
        con.charHeight
    }) / 2;
    gl.glListBase(if big {
        con.baseFontBig
    } else {
        con.baseFontNormal
    });
    gl.glColor3f(text_rgb[0], text_rgb[1], text_rgb[2]);
    gl.glRasterPos2i(cx.max(0), cy);
    gl.call_lists_bytes(txt);
}
