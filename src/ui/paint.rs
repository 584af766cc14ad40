//! Drawing primitives of the UI in framebuffer units: clipped text, boxes, ovals, section
//! symbols and shortcut labels.

#![allow(non_upper_case_globals)] // the ABI's key names in patterns

use super::layout::scl;
use crate::abi::cstr::cbytes;
use crate::abi::*;
use crate::math::misc::round;
use crate::render::gl::consts::*;
use crate::render::gl::Gl;
use crate::render::text::char_width;
use std::f64::consts::PI;

/// Width of the first `limit` characters of `text` (all when `limit` is negative).
pub fn width_upto(text: &[u8], con: &mjrContext, limit: i32) -> i32 {
    if limit == 0 {
        return 0;
    }
    let n = if limit < 1 {
        text.len()
    } else {
        text.len().min(limit as usize)
    };
    text[..n].iter().map(|&c| char_width(con, c, false)).sum()
}

/// Drawing state: GL, the context and the UI's colors.
pub struct Pen<'a> {
    pub gl: &'a Gl,
    pub con: &'a mjrContext,
    pub ui: &'a mjUI,
}

impl Pen<'_> {
    pub fn scl(&self, sz: i32) -> i32 {
        scl(sz, self.con)
    }

    /// Text at (x, y), cut before the character that reaches `maxwidth`.
    pub fn text(&self, txt: &[u8], x: i32, y: i32, maxwidth: i32, rgb: &[f32; 3]) {
        let mut width = 0;
        let mut len = 0;
        for &c in txt {
            width += char_width(self.con, c, false);
            if width >= maxwidth {
                break;
            }
            len += 1;
        }
        let gl = self.gl;
        gl.glListBase(self.con.baseFontNormal);
        gl.color3fv(rgb);
        gl.glRasterPos3i(x, y, 0);
        gl.call_lists_bytes(&txt[..len]);
    }

    /// A C string field as text.
    pub fn name(&self, name: &[std::os::raw::c_char], x: i32, y: i32, maxw: i32, rgb: &[f32; 3]) {
        self.text(cbytes(name), x, y, maxw, rgb);
    }

    /// Text centered in `r`.
    pub fn text_centered(&self, r: mjrRect, txt: &[u8], rgb: &[f32; 3]) {
        let dy = (r.height - self.con.charHeight) / 2;
        let dx = ((r.width - width_upto(txt, self.con, -1)) / 2).max(0);
        self.text(txt, r.left + dx, r.bottom + dy, r.width - dx, rgb);
    }

    fn quad(&self, l: i32, b: i32, r: i32, t: i32) {
        let gl = self.gl;
        gl.glBegin(GL_QUADS);
        gl.glVertex2i(l, b);
        gl.glVertex2i(r, b);
        gl.glVertex2i(r, t);
        gl.glVertex2i(l, t);
        gl.glEnd();
    }

    /// A filled box; with `back`, an outline filled with `back` inside.
    pub fn rect(&self, r: mjrRect, rgb: &[f32; 3], back: Option<&[f32; 3]>) {
        self.gl.color3fv(rgb);
        self.quad(r.left, r.bottom, r.left + r.width, r.bottom + r.height);
        if let Some(back) = back {
            let m = self.scl(2);
            self.gl.color3fv(back);
            self.quad(
                r.left + m,
                r.bottom + m,
                r.left + r.width - m,
                r.bottom + r.height - m,
            );
        }
    }

    /// A box shaded from `bottom` to `top` color.
    pub fn gradient(&self, r: mjrRect, bottom: &[f32; 3], top: &[f32; 3]) {
        let gl = self.gl;
        gl.glBegin(GL_QUADS);
        gl.color3fv(bottom);
        gl.glVertex2i(r.left, r.bottom);
        gl.glVertex2i(r.left + r.width, r.bottom);
        gl.color3fv(top);
        gl.glVertex2i(r.left + r.width, r.bottom + r.height);
        gl.glVertex2i(r.left, r.bottom + r.height);
        gl.glEnd();
    }

    fn oval_polygon(&self, lc: [f64; 2], rc: [f64; 2], radius: f64) {
        const N: i32 = 20;
        let gl = self.gl;
        gl.glBegin(GL_POLYGON);
        for (c, start) in [(lc, 0.5), (rc, 1.5)] {
            for i in 0..=N {
                let a = PI * (start + i as f64 / N as f64);
                gl.glVertex2d(c[0] + radius * a.cos(), c[1] + radius * a.sin());
            }
        }
        gl.glEnd();
    }

    /// A button's oval (wider than high); with `back`, an outline filled with `back`.
    pub fn oval(&self, r: mjrRect, rgb: &[f32; 3], back: Option<&[f32; 3]>) {
        if r.height > r.width {
            return;
        }
        let radius = 0.5 * r.height as f64;
        let lc = [r.left as f64 + radius, r.bottom as f64 + radius];
        let rc = [(r.left + r.width) as f64 - radius, r.bottom as f64 + radius];
        self.gl.color3fv(rgb);
        self.oval_polygon(lc, rc, radius);
        if let Some(back) = back {
            self.gl.color3fv(back);
            self.oval_polygon(lc, rc, radius - self.scl(2) as f64);
        }
    }

    /// The open (down) or closed (left, hollow) triangle at the right of a section title or
    /// separator.
    pub fn symbol(&self, r: mjrRect, open: bool, sep: bool) {
        let (gl, ui, con) = (self.gl, self.ui, self.con);
        let cx = r.left + r.width - self.scl(ui.spacing.texthor);
        let cy = r.bottom + r.height / 2;
        let d = round(con.charHeight as f64 * if sep { 0.28 } else { 0.33 });
        gl.color3fv(&ui.color.sectsymbol);
        gl.glBegin(GL_TRIANGLES);
        if open {
            gl.glVertex2i(cx, cy + d);
            gl.glVertex2i(cx - 2 * d, cy + d);
            gl.glVertex2i(cx - d, cy - d);
            gl.glEnd();
            return;
        }
        gl.glVertex2i(cx, cy - d);
        gl.glVertex2i(cx, cy + d);
        gl.glVertex2i(cx - 2 * d, cy);
        gl.glEnd();
        let margin = con.fontScale as f64 * 0.015;
        let u = 0.5 * 5f64.sqrt() * margin;
        let y = d as f64 - u - 0.5 * margin;
        let c = &ui.color;
        let a = if sep { &c.master } else { &c.secttitle };
        let mix = |k: usize| ((a[k] + c.sectpane[k]) as f64 * 0.5) as f32;
        gl.glColor3f(mix(0), mix(1), mix(2));
        gl.glBegin(GL_TRIANGLES);
        let (cx, cy) = (cx as f64, cy as f64);
        gl.glVertex2d(cx - margin, cy - y);
        gl.glVertex2d(cx - margin, cy + y);
        gl.glVertex2d(cx - 2.0 * d as f64 + 2.0 * u, cy);
        gl.glEnd();
    }

    /// The shortcut of a section or item, in a box at the right of `r`.
    pub fn shortcut(&self, mut r: mjrRect, modifier: i32, key: i32) {
        let mut text: Vec<u8> = match modifier {
            1 => b"Ctrl ".to_vec(),
            2 => b"Shift ".to_vec(),
            4 => b"Alt ".to_vec(),
            _ => Vec::new(),
        };
        if key > 32 && key <= 126 {
            text.push(key as u8);
        } else {
            text.extend_from_slice(key_name(key).as_bytes());
        }
        let textver = self.scl(self.ui.spacing.textver);
        let width = width_upto(&text, self.con, -1) + 2 * textver;
        r.left += r.width - width;
        r.width = width;
        r.bottom += textver;
        r.height -= 2 * textver;
        self.rect(r, &self.ui.color.shortcut, None);
        let font = &self.ui.color.fontactive;
        self.text(&text, r.left + textver, r.bottom, r.width, font);
    }
}

/// Name of a special key in shortcut labels ("" if none).
fn key_name(key: i32) -> String {
    match key {
        32 => "Space".into(),
        mjKEY_ESCAPE => "Esc".into(),
        mjKEY_ENTER => "Enter".into(),
        mjKEY_TAB => "Tab".into(),
        mjKEY_BACKSPACE => "BackSpace".into(),
        mjKEY_INSERT => "Ins".into(),
        mjKEY_DELETE => "Del".into(),
        mjKEY_RIGHT => "Right".into(),
        mjKEY_LEFT => "Left".into(),
        mjKEY_DOWN => "Down".into(),
        mjKEY_UP => "Up".into(),
        mjKEY_PAGE_UP => "PgUp".into(),
        mjKEY_PAGE_DOWN => "PgDn".into(),
        mjKEY_HOME => "Home".into(),
        mjKEY_END => "End".into(),
        k if (mjKEY_F1..=mjKEY_F1 + 11).contains(&k) => format!("F{}", k - mjKEY_F1 + 1),
        _ => String::new(),
    }
}
