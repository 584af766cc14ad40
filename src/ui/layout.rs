//! mjui_resize: the rectangles of sections and items, in framebuffer units, from the theme
//! spacing scaled by the font scale.

use crate::abi::*;
use crate::math::misc::round;

/// Theme size `sz` (abstract pixels) in framebuffer units at the context's font scale.
pub fn scl(sz: i32, con: &mjrContext) -> i32 {
    round(sz as f64 * 0.01 * con.fontScale as f64).max(0)
}

fn is(it: &mjuiItem, t: mjtItem_) -> bool {
    it.r#type == t as i32
}

/// Lays out every section and item; sets ui.width, height and maxheight.
pub fn resize(ui: &mut mjUI, con: &mjrContext) {
    use mjtItem_::*;
    let sp = ui.spacing;
    let w_master = scl(sp.total, con);
    let w_scroll = scl(sp.scroll, con);
    let g_section = scl(sp.section, con);
    let g_itemside = scl(sp.itemside, con);
    let g_itemmid = scl(sp.itemmid, con);
    let g_itemver = scl(sp.itemver, con);
    let g_textver = scl(sp.textver, con);
    let g_label = scl(sp.label, con);
    let textheight = con.charHeight + 2 * g_textver;
    let colwidth = (w_master - w_scroll - 2 * g_section - 2 * g_itemside - g_itemmid) / 2;
    let radiocol = if ui.radiocol != 0 { ui.radiocol } else { 2 };

    let mut height = 0;
    let mut maxheight = 0;
    let nsect = ui.nsect.clamp(0, mjMAXUISECT as i32) as usize;
    for s in ui.sect[..nsect].iter_mut() {
        height += g_section;
        maxheight += g_section;

        s.rtitle.left = g_section;
        s.rtitle.width = w_master - w_scroll - 2 * g_section;
        if s.state < 2 {
            s.rtitle.bottom = height + textheight;
            s.rtitle.height = textheight;
        } else {
            s.rtitle.bottom = height;
            s.rtitle.height = 0;
        }
        height += s.rtitle.height;
        maxheight += s.rtitle.height;

        s.rcontent.left = s.rtitle.left;
        s.rcontent.width = s.rtitle.width;
        s.rcontent.height = 0;

        let nitem = s.nitem.clamp(0, mjMAXUIITEM as i32) as usize;
        let mut i = 0;
        while i < nitem {
            let oldcontent = s.rcontent;
            // items below a closed separator are skipped
            let skip = i > 0
                && !is(&s.item[i], mjITEM_SEPARATOR)
                && s.item[..i]
                    .iter()
                    .rev()
                    .find(|k| is(k, mjITEM_SEPARATOR))
                    .is_some_and(|k| k.state == mjSEPCLOSED);

            s.rcontent.height += if is(&s.item[i], mjITEM_SEPARATOR) {
                g_section
            } else {
                g_itemver
            };

            let t = s.item[i].r#type;
            let paired = i + 1 < nitem
                && s.item[i + 1].r#type == t
                && (t == mjITEM_BUTTON as i32
                    || t == mjITEM_CHECKINT as i32
                    || t == mjITEM_CHECKBYTE as i32);
            let first = i;
            if paired {
                let bottom = height + s.rcontent.height + textheight;
                let left = s.rcontent.left + g_itemside;
                let it = &mut s.item[i];
                it.rect.left = left;
                it.rect.width = colwidth;
                it.rect.height = textheight;
                let it1 = &mut s.item[i + 1];
                it1.rect.left = left + colwidth + g_itemmid;
                it1.rect.width = colwidth;
                it1.rect.height = textheight;
                it1.rect.bottom = bottom;
                if skip {
                    it1.rect.width = 0;
                    it1.rect.height = 0;
                }
                i += 1;
            } else {
                let content = s.rcontent;
                single_rect(
                    &mut s.item[i],
                    content,
                    [g_itemside, g_label, colwidth, textheight, g_textver],
                    radiocol,
                    con,
                );
            }

            let it = &mut s.item[first];
            it.rect.bottom = height + s.rcontent.height + it.rect.height;
            s.rcontent.height += it.rect.height;
            if skip {
                maxheight += s.rcontent.height - oldcontent.height;
                s.rcontent = oldcontent;
                it.rect.width = 0;
                it.rect.height = 0;
            }
            i += 1;
        }

        s.rcontent.height += g_itemver;
        s.rcontent.bottom = height + s.rcontent.height;
        if s.state != 0 {
            height += s.rcontent.height;
        }
        maxheight += s.rcontent.height;
    }
    height += g_section;
    maxheight += g_section;

    // bottoms measured from the top so far: turn them around
    for s in ui.sect[..nsect].iter_mut() {
        s.rtitle.bottom = height - s.rtitle.bottom;
        s.rcontent.bottom = height - s.rcontent.bottom;
        let nitem = s.nitem.clamp(0, mjMAXUIITEM as i32) as usize;
        for it in s.item[..nitem].iter_mut() {
            it.rect.bottom = height - it.rect.bottom;
        }
    }
    ui.width = w_master;
    ui.height = height;
    ui.maxheight = maxheight;
}

/// The rectangle of an item on a line of its own (bottom set by the caller).
/// `g` = [itemside gap, label width, column width, text height, text vertical gap].
fn single_rect(it: &mut mjuiItem, content: mjrRect, g: [i32; 5], radiocol: i32, con: &mjrContext) {
    use mjtItem_::*;
    let [g_itemside, g_label, colwidth, textheight, g_textver] = g;
    it.rect.left = content.left + g_itemside;
    let full = content.width - 2 * g_itemside;
    if is(it, mjITEM_STATIC) {
        it.rect.width = full;
        it.rect.height = (con.charHeight + g_textver) * it.multi().nelem;
    } else if is(it, mjITEM_BUTTON) || is(it, mjITEM_CHECKINT) || is(it, mjITEM_CHECKBYTE) {
        it.rect.width = colwidth;
        it.rect.height = textheight;
    } else if is(it, mjITEM_RADIO) {
        let nrow = (it.multi().nelem - 1) / radiocol + 1;
        it.rect.width = full;
        it.rect.height = textheight * nrow;
    } else {
        it.rect.width = full;
        it.rect.height = textheight;
    }
    // labeled controls leave room for the label
    if it.name[0] != 0 && (it.r#type >= mjITEM_RADIO as i32 || is(it, mjITEM_STATIC)) {
        it.rect.left = content.left + g_itemside + g_label;
        it.rect.width = content.width - (2 * g_itemside + g_label);
    }
}
