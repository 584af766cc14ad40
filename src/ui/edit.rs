//! Edit items: their text from and to the data, its validity, accepted keys, and the cursor
//! and scroll of the text being edited.

use super::host::Host;
use super::layout::scl;
use super::locate::{is, mouse_in_rect};
use crate::abi::*;
use crate::math::misc::round;
use crate::render::text::char_width;
use crate::runtime::message::format_c;
use mjtItem_::*;

/// Length of the prefix glibc's scanf "%lf" takes as its field (sign, digits, one point,
/// exponent; or inf/nan).
fn field_len(t: &[u8]) -> usize {
    let mut i = 0;
    if i < t.len() && (t[i] == b'+' || t[i] == b'-') {
        i += 1;
    }
    let lower: Vec<u8> = t[i..].iter().take(8).map(u8::to_ascii_lowercase).collect();
    for word in [&b"infinity"[..], b"inf", b"nan"] {
        if lower.starts_with(word) {
            return i + word.len();
        }
    }
    let (mut digit, mut dot, mut exp) = (false, false, false);
    while i < t.len() {
        let c = t[i];
        let sign_after_e = exp && (c == b'+' || c == b'-') && matches!(t[i - 1], b'e' | b'E');
        if c.is_ascii_digit() {
            digit = true;
        } else if c == b'.' && !exp && !dot {
            dot = true;
        } else if digit && !exp && (c == b'e' || c == b'E') {
            exp = true;
        } else if !sign_after_e {
            break;
        }
        i += 1;
    }
    i
}

/// The numbers sscanf(text, "%lf %lf ...") converts, up to mjMAXUIEDIT: a field without
/// digits (such as "-" or ".") ends the conversion; an exponent without digits ("1e-") is
/// taken and ignored, as glibc does.
pub fn scan(text: &[u8]) -> Vec<f64> {
    let mut out = Vec::new();
    let mut i = 0;
    while out.len() < mjMAXUIEDIT {
        while i < text.len() && text[i].is_ascii_whitespace() {
            i += 1;
        }
        let n = field_len(&text[i..]);
        let mut field = &text[i..i + n];
        if let [head @ .., b'e' | b'E', b'+' | b'-'] | [head @ .., b'e' | b'E'] = field {
            field = head;
        }
        let field = std::str::from_utf8(field).unwrap_or("");
        match field.parse::<f64>() {
            Ok(v) if n > 0 => out.push(v),
            _ => break,
        }
        i += n;
    }
    out
}

/// The values of numeric edit text, or 1 (count), 2 (range) or 3 (not an int) when invalid.
fn parse(text: &[u8], it: &mjuiItem) -> Result<Vec<f64>, i32> {
    let val = scan(text);
    let e = it.edit();
    if val.len() as i32 != e.nelem {
        return Err(1);
    }
    let out_of_range = val
        .iter()
        .zip(&e.range)
        .any(|(&v, r)| r[0] < r[1] && (v < r[0] || v > r[1]));
    if out_of_range {
        return Err(2);
    }
    if is(it, mjITEM_EDITINT) && val.iter().any(|&v| v != (v as i32) as f64) {
        return Err(3);
    }
    Ok(val)
}

/// Whether `text` is valid for the edit item (text always is).
pub fn valid(text: &[u8], it: &mjuiItem) -> bool {
    is(it, mjITEM_EDITTXT) || parse(text, it).is_ok()
}

/// Stores valid `text` in the item's data; false (nothing stored) when invalid.
pub fn store(text: &[u8], it: &mjuiItem, host: &dyn Host) -> bool {
    if is(it, mjITEM_EDITTXT) {
        let mut buf = [0u8; mjMAXUINAME];
        let n = text.len().min(mjMAXUINAME - 1);
        buf[..n].copy_from_slice(&text[..n]);
        host.set_text(it, &buf);
        return true;
    }
    let Ok(val) = parse(text, it) else {
        return false;
    };
    for (i, &v) in val.iter().enumerate() {
        if is(it, mjITEM_EDITINT) {
            host.set_int(it, i, v as i32);
        } else {
            host.set_num(it, i, v);
        }
    }
    true
}

/// The text showing the item's data: the string, or the values ("%d" or "%.4g") two spaces
/// apart.
pub fn show(it: &mjuiItem, host: &dyn Host) -> Vec<u8> {
    if is(it, mjITEM_EDITTXT) {
        let mut t = host.text(it);
        t.truncate(mjMAXUINAME - 1);
        return t;
    }
    let n = it.edit().nelem.clamp(0, mjMAXUIEDIT as i32) as usize;
    let mut text = Vec::new();
    for i in 0..n {
        let v = if is(it, mjITEM_EDITINT) {
            host.int(it, i).to_string()
        } else {
            format_c(c"%.4g", &[host.num(it, i)])
        };
        text.extend_from_slice(v.as_bytes());
        if i + 1 < n {
            text.extend_from_slice(b"  ");
        }
    }
    text.truncate(mjMAXUITEXT - 1);
    text
}

const NUMPAD_0: i32 = 320;
const NUMPAD_9: i32 = 329;

/// The character `key` types into an edit item whose text has `len` bytes (Shift gives
/// upper case and the US layout's shifted symbols); None if not accepted.
pub fn typed(key: i32, len: usize, it: &mjuiItem, shift: bool) -> Option<u8> {
    if is(it, mjITEM_EDITTXT) {
        if len >= mjMAXUINAME - 1 || !(32..=127).contains(&key) {
            return None;
        }
        let c = key as u8;
        if c.is_ascii_uppercase() && !shift {
            return Some(c.to_ascii_lowercase());
        }
        if !shift {
            return Some(c);
        }
        let from = b"`-=[]\\;',./";
        let to = b"~_+{}|:\"<>?";
        return Some(from.iter().position(|&f| f == c).map_or(c, |k| to[k]));
    }
    if !(is(it, mjITEM_EDITINT) || is(it, mjITEM_EDITNUM)) || len >= mjMAXUITEXT - 1 {
        return None;
    }
    let num = is(it, mjITEM_EDITNUM);
    match key {
        NUMPAD_0..=NUMPAD_9 => Some((key - NUMPAD_0) as u8 + b'0'),
        0x30..=0x39 | 0x20 | 0x2B | 0x2D => Some(key as u8),
        0x3D => Some(b'+'),
        0x45 | 0x65 if num => Some(b'e'),
        0x2E if num => Some(b'.'),
        _ => None,
    }
}

/// The edit text as bytes (all of the array) and its length.
pub fn edit_bytes(ui: &mjUI) -> ([u8; mjMAXUITEXT], usize) {
    let mut b = [0u8; mjMAXUITEXT];
    for (d, &s) in b.iter_mut().zip(&ui.edittext) {
        *d = s as u8;
    }
    let len = b.iter().position(|&c| c == 0).unwrap_or(mjMAXUITEXT);
    (b, len)
}

pub fn set_edit_bytes(ui: &mut mjUI, b: &[u8; mjMAXUITEXT]) {
    for (d, &s) in ui.edittext.iter_mut().zip(b) {
        *d = s as std::os::raw::c_char;
    }
}

/// Scrolls the edit text so that the cursor shows in the box `r`.
pub fn reveal_cursor(r: mjrRect, ui: &mut mjUI, con: &mjrContext) {
    if ui.editcursor <= ui.editscroll {
        ui.editscroll = ui.editcursor;
        return;
    }
    let (text, _) = edit_bytes(ui);
    // the byte before the text is the top byte of editscroll
    let at = |i: i32| match usize::try_from(i) {
        Ok(i) => text.get(i).copied().unwrap_or(0),
        Err(_) => (ui.editscroll as u32 >> 24) as u8,
    };
    let mut width = r.width - 2 * scl(ui.spacing.texthor, con);
    let mut i = ui.editcursor;
    while width >= 0 && i >= ui.editscroll {
        i -= 1;
        width -= char_width(con, at(i), false);
    }
    if width < 0 {
        ui.editscroll = i + 1;
    }
}

/// Places the edit cursor where the mouse is in the box `r`.
pub fn set_cursor(r: mjrRect, ui: &mut mjUI, state: &mjuiState, con: &mjrContext) {
    let texthor = scl(ui.spacing.texthor, con);
    let mut r1 = r;
    r1.left += texthor;
    r1.width -= 2 * texthor;
    let (rx, _) = mouse_in_rect(r1, ui, state);
    let (text, len) = edit_bytes(ui);
    if rx < 0.0 {
        ui.editcursor = 0;
        ui.editscroll = 0;
    } else if rx > 1.0 {
        ui.editcursor = len as i32;
        reveal_cursor(r, ui, con);
    } else {
        let target = round(r1.width as f64 * rx);
        let (mut best, mut bestdif, mut cumsum) = (ui.editscroll, target, 0);
        for i in ui.editscroll.max(0)..len as i32 {
            cumsum += char_width(con, text[i as usize], false);
            if bestdif > (cumsum - target).abs() {
                bestdif = (cumsum - target).abs();
                best = i + 1;
            }
        }
        ui.editcursor = best;
    }
}

#[cfg(test)]
mod tests {
    use super::scan;

    /// Counts and first values glibc's sscanf gives for these texts.
    #[test]
    fn scan_as_glibc() {
        let cases: [(&str, &[f64]); 12] = [
            ("1e 2", &[1.0, 2.0]),
            ("1e- 2", &[1.0, 2.0]),
            ("1.5E+0.5", &[1.5, 0.5]),
            ("-.5", &[-0.5]),
            ("+", &[]),
            ("1..2", &[1.0, 0.2]),
            ("1e5e3", &[1e5]),
            ("1-2", &[1.0, -2.0]),
            ("1 . 2", &[1.0]),
            ("-infinity 2", &[f64::NEG_INFINITY, 2.0]),
            ("in", &[]),
            ("1 2 3 4 5 6 7 8", &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]),
        ];
        for (text, want) in cases {
            assert_eq!(scan(text.as_bytes()), want, "{text}");
        }
    }
}
