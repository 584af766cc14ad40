//! Building a UI from definition tables (mjui_add, mjui_addToSection): sections, items and
//! their type-specific properties parsed from the `other` strings.

use crate::abi::cstr::{cbytes, set_cstr};
use crate::abi::*;
use crate::math::misc::round;
use crate::runtime::message::error;

/// The numbers at the start of `text` as C's sscanf("%lf %lf ...") reads them: whitespace
/// separated, stopping at the first token that does not begin with a number.
pub fn scan_numbers(text: &[u8], max: usize) -> Vec<f64> {
    let mut out = Vec::new();
    let mut i = 0;
    while out.len() < max {
        while i < text.len() && text[i].is_ascii_whitespace() {
            i += 1;
        }
        let n = number_prefix(&text[i..]);
        if n == 0 {
            break;
        }
        let s = std::str::from_utf8(&text[i..i + n]).unwrap_or("");
        match s.parse::<f64>() {
            Ok(v) => out.push(v),
            Err(_) => break,
        }
        i += n;
    }
    out
}

/// Length of the longest prefix of `t` that strtod reads as a decimal number.
fn number_prefix(t: &[u8]) -> usize {
    let mut i = 0;
    if i < t.len() && (t[i] == b'+' || t[i] == b'-') {
        i += 1;
    }
    let lower: Vec<u8> = t[i..]
        .iter()
        .take(8)
        .map(|c| c.to_ascii_lowercase())
        .collect();
    for word in [&b"infinity"[..], b"inf", b"nan"] {
        if lower.starts_with(word) {
            return i + word.len();
        }
    }
    let digits = |i: &mut usize| {
        let s = *i;
        while *i < t.len() && t[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - s
    };
    let mut n = digits(&mut i);
    if i < t.len() && t[i] == b'.' {
        i += 1;
        n += digits(&mut i);
    }
    if n == 0 {
        return 0;
    }
    if i < t.len() && (t[i] == b'e' || t[i] == b'E') {
        let mut j = i + 1;
        if j < t.len() && (t[j] == b'+' || t[j] == b'-') {
            j += 1;
        }
        if digits(&mut j) > 0 {
            i = j;
        }
    }
    i
}

/// A shortcut specification: modifier character (' ', 'C'ontrol, 'S'hift, 'A'lt) then a
/// character or '#' and a key code; empty for none. Gives (modifier, key).
fn parse_shortcut(text: &[u8]) -> Option<(i32, i32)> {
    if text.is_empty() {
        return Some((0, 0));
    }
    if text.len() < 2 || text.len() > 5 {
        error("mjui_add: invalid shortcut specification");
        return None;
    }
    let modifier = match text[0] {
        b' ' => 0,
        b'C' => 1,
        b'S' => 2,
        b'A' => 4,
        _ => {
            error("mjui_add: invalid shortcut modifier");
            return None;
        }
    };
    if text[1] == b'#' {
        match scan_int(&text[2..]) {
            Some(k) => Some((modifier, k)),
            None => {
                error("mjui_add: invalid shortcut numeric code");
                None
            }
        }
    } else if text.len() != 2 {
        error("mjui_add: invalid shortcut");
        None
    } else {
        Some((modifier, text[1] as i32))
    }
}

/// C's sscanf("%d"): optional whitespace and sign, then digits.
fn scan_int(t: &[u8]) -> Option<i32> {
    let s = std::str::from_utf8(t).ok()?.trim_start();
    let end = s
        .char_indices()
        .find(|&(i, c)| !(c.is_ascii_digit() || (i == 0 && (c == '+' || c == '-'))))
        .map_or(s.len(), |(i, _)| i);
    let v: i64 = s[..end].parse().ok()?;
    Some(v as i32)
}

/// mjui_add: appends the sections and items of `defs` (up to its mjITEM_END entry).
pub fn add(ui: &mut mjUI, defs: &[mjuiDef]) {
    for def in defs {
        let ok = match def.r#type {
            t if t == mjtItem_::mjITEM_END as i32 => return,
            t if t == mjtItem_::mjITEM_SECTION as i32 => add_section(ui, def),
            t if (0..mjtItem_::mjNITEM as i32).contains(&t) => add_item(ui, def),
            _ => {
                error("mjui_add: invalid item type");
                false
            }
        };
        if !ok {
            return;
        }
    }
}

fn add_section(ui: &mut mjUI, def: &mjuiDef) -> bool {
    if ui.nsect >= mjMAXUISECT as i32 {
        error("mjui_add: too many sections");
        return false;
    }
    let name = cbytes(&def.name);
    if name.len() >= mjMAXUINAME - 1 {
        error("mjui_add: section name too long");
        return false;
    }
    if !(0..=2).contains(&def.state) {
        error("mjui_add: invalid section state");
        return false;
    }
    ui.nsect += 1;
    let se = &mut ui.sect[ui.nsect as usize - 1];
    // SAFETY: mjuiSection is plain data; all zeros is its cleared state.
    *se = unsafe { std::mem::zeroed() };
    set_cstr(&mut se.name, name);
    se.state = def.state;
    match parse_shortcut(cbytes(&def.other)) {
        Some((m, k)) => {
            se.modifier = m;
            se.shortcut = k;
            true
        }
        None => false,
    }
}

fn add_item(ui: &mut mjUI, def: &mjuiDef) -> bool {
    use mjtItem_::*;
    if ui.nsect <= 0 {
        error("mjui_add: item defined outside section");
        return false;
    }
    let sectionid = ui.nsect - 1;
    let se = &mut ui.sect[sectionid as usize];
    if se.nitem >= mjMAXUIITEM as i32 {
        error("mjui_add: too many items in section");
        return false;
    }
    let name = cbytes(&def.name);
    if name.len() >= mjMAXUINAME {
        error("mjui_add: item name too long");
        return false;
    }
    if def.state < 0 {
        error("mjui_add: invalid item state");
        return false;
    }
    se.nitem += 1;
    let itemid = se.nitem - 1;
    let it = &mut se.item[itemid as usize];
    // SAFETY: mjuiItem is plain data; all zeros is its cleared state.
    *it = unsafe { std::mem::zeroed() };
    it.r#type = def.r#type;
    it.state = def.state;
    it.pdata = def.pdata;
    set_cstr(&mut it.name, name);
    it.sectionid = sectionid;
    it.itemid = itemid;

    let t = it.r#type;
    if t > mjITEM_BUTTON as i32 && it.pdata.is_null() {
        error("mjui_add: no data pointer for item with data");
        return false;
    }
    if t <= mjITEM_BUTTON as i32 && !it.pdata.is_null() {
        error("mjui_add: data pointer for item without data");
        return false;
    }
    let other = cbytes(&def.other);
    let is = |k: mjtItem_| t == k as i32;
    if is(mjITEM_BUTTON) || is(mjITEM_CHECKINT) || is(mjITEM_CHECKBYTE) {
        let Some((m, k)) = parse_shortcut(other) else {
            return false;
        };
        let s = it.single_mut();
        s.modifier = m;
        s.shortcut = k;
        true
    } else if is(mjITEM_STATIC) || is(mjITEM_RADIO) || is(mjITEM_RADIOLINE) || is(mjITEM_SELECT) {
        parse_multi(it.multi_mut(), other)
    } else if is(mjITEM_SLIDERINT) || is(mjITEM_SLIDERNUM) {
        let x = scan_numbers(other, 3);
        if x.len() != 2 && x.len() != 3 {
            error("mjui_add: slider expects 'min max [div]'");
            return false;
        }
        let s = it.slider_mut();
        s.range = [x[0], x[1]];
        s.divisions = if x.len() == 3 {
            x[2].max(1.0)
        } else if is(mjITEM_SLIDERINT) {
            (x[1] - x[0]).max(1.0)
        } else {
            200.0
        };
        true
    } else if is(mjITEM_EDITINT) || is(mjITEM_EDITNUM) {
        parse_edit(it.edit_mut(), other)
    } else {
        // edit text: nothing to parse
        it.edit_mut().nelem = 0;
        true
    }
}

/// Element names separated by '\n'.
fn parse_multi(m: &mut mjuiItemMulti_, other: &[u8]) -> bool {
    m.nelem = 0;
    let mut i = 0;
    while i < other.len() {
        if m.nelem >= mjMAXUIMULTI as i32 {
            error("mjui_add: too many multi elements");
            return false;
        }
        let start = i;
        while i < other.len() && other[i] != b'\n' {
            i += 1;
        }
        if i == start || i - start >= mjMAXUINAME - 1 {
            error("mjui_add: invalid multi element name");
            return false;
        }
        set_cstr(&mut m.name[m.nelem as usize], &other[start..i]);
        m.nelem += 1;
        i += 1;
    }
    true
}

/// "n [min max]*n": number of elements, then optionally a range for each.
fn parse_edit(e: &mut mjuiItemEdit_, other: &[u8]) -> bool {
    let x = scan_numbers(other, 1 + 2 * mjMAXUIEDIT);
    if x.is_empty() {
        error("mjui_add: edit length missing");
        return false;
    }
    e.nelem = round(x[0]);
    if e.nelem < 1 || e.nelem > mjMAXUIEDIT as i32 {
        error("mjui_add: invalid edit length");
        return false;
    }
    if x.len() > 1 && e.nelem as usize * 2 != x.len() - 1 {
        error("mjui_add: incorrent number of edit ranges");
        return false;
    }
    if x.len() > 1 {
        for i in 0..e.nelem as usize {
            e.range[i] = [x[1 + 2 * i], x[2 + 2 * i]];
        }
    }
    true
}

/// mjui_addToSection: `defs` go into section `sect` (which must exist).
pub fn add_to_section(ui: &mut mjUI, sect: i32, defs: &[mjuiDef]) {
    let nsect = ui.nsect;
    ui.nsect = sect + 1;
    add(ui, defs);
    ui.nsect = nsect;
}
