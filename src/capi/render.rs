//! C entry points of OpenGL rendering (mjr_): argument checks, then `crate::render`.

use super::{errmem, guard};
use crate::abi::*;
use crate::engine::{EngineError, Model};
use crate::render::gl::Gl;
use crate::render::{context, figure, framebuffer, scene, text};
use std::os::raw::{c_char, c_int, c_uchar};

/// Runs `f` with the loaded GL (or none) as `guard` does: errors and panics are reported
/// through mju_error. Where `f` calls a GL function that is not loaded (2.2.2 calls through a
/// NULL pointer and crashes), the error says so.
pub(super) fn with_gl<R>(
    name: &str,
    fallback: R,
    f: impl FnOnce(&'static Gl) -> Result<R, EngineError>,
) -> R {
    let gl = crate::render::gl::loaded_or_absent();
    let explain = |p: &(dyn std::any::Any + Send)| {
        crate::render::gl::is_missing(p).map(|function| {
            if crate::render::gl::loaded().is_none() {
                format!(
                    "{name}: OpenGL not initialized; call mjr_makeContext with a current \
                     OpenGL context"
                )
            } else {
                format!("{name}: OpenGL function {function} not available")
            }
        })
    };
    super::guard_explained(name, fallback, || f(gl), explain)
}

/// A NULL context is reported (2.2.2 would crash).
unsafe fn context_ref<'a>(name: &str, con: *const mjrContext) -> Option<&'a mjrContext> {
    let c = con.as_ref();
    if c.is_none() {
        errmem::error(&format!("{name}: NULL context"));
    }
    c
}

/// A viewport with nothing to draw (2.2.2 returns before reading the context).
fn empty(viewport: &mjrRect) -> bool {
    viewport.width <= 0 || viewport.height <= 0
}

unsafe fn context_mut<'a>(name: &str, con: *mut mjrContext) -> Option<&'a mut mjrContext> {
    let c = con.as_mut();
    if c.is_none() {
        errmem::error(&format!("{name}: NULL context"));
    }
    c
}

#[no_mangle]
pub unsafe extern "C" fn mjr_defaultContext(con: *mut mjrContext) {
    if let Some(con) = con.as_mut() {
        *con = context::default_context();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjr_makeContext(
    m: *const mjModel,
    con: *mut mjrContext,
    fontscale: c_int,
) {
    let Some(con) = context_mut("mjr_makeContext", con) else {
        return;
    };
    // GL is loaded inside; a function the implementation lacks is reported as with_gl does
    with_gl("mjr_makeContext", (), |_| {
        let m = m.as_ref().map(|m| Model::new(m));
        context::make_context(m.as_ref(), con, fontscale, (800, 600))
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_freeContext(con: *mut mjrContext) {
    if let Some(con) = con.as_mut() {
        guard("mjr_freeContext", (), || {
            context::free_context(crate::render::gl::loaded(), con);
            Ok(())
        })
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjr_changeFont(fontscale: c_int, con: *mut mjrContext) {
    let Some(con) = context_mut("mjr_changeFont", con) else {
        return;
    };
    with_gl("mjr_changeFont", (), |gl| {
        context::change_font(gl, fontscale, con)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_addAux(
    index: c_int,
    width: c_int,
    height: c_int,
    samples: c_int,
    con: *mut mjrContext,
) {
    let Some(con) = context_mut("mjr_addAux", con) else {
        return;
    };
    with_gl("mjr_addAux", (), |gl| {
        context::add_aux(gl, index, (width, height), samples, con)
    })
}

type Upload = fn(&Gl, &Model, &mjrContext, i32) -> Result<(), EngineError>;

unsafe fn upload(name: &str, m: *const mjModel, con: *const mjrContext, id: c_int, f: Upload) {
    let (Some(m), Some(con)) = (m.as_ref(), context_ref(name, con)) else {
        return errmem::error(&format!("{name}: NULL model"));
    };
    with_gl(name, (), |gl| f(gl, &Model::new(m), con, id))
}

#[no_mangle]
pub unsafe extern "C" fn mjr_uploadTexture(
    m: *const mjModel,
    con: *const mjrContext,
    texid: c_int,
) {
    upload("mjr_uploadTexture", m, con, texid, context::upload_texture)
}

#[no_mangle]
pub unsafe extern "C" fn mjr_uploadMesh(m: *const mjModel, con: *const mjrContext, meshid: c_int) {
    upload("mjr_uploadMesh", m, con, meshid, context::upload_mesh)
}

#[no_mangle]
pub unsafe extern "C" fn mjr_uploadHField(
    m: *const mjModel,
    con: *const mjrContext,
    hfieldid: c_int,
) {
    upload("mjr_uploadHField", m, con, hfieldid, context::upload_hfield)
}

#[no_mangle]
pub unsafe extern "C" fn mjr_setBuffer(framebuffer: c_int, con: *mut mjrContext) {
    let Some(con) = context_mut("mjr_setBuffer", con) else {
        return;
    };
    with_gl("mjr_setBuffer", (), |gl| {
        framebuffer::set_buffer(gl, framebuffer, con)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_restoreBuffer(con: *const mjrContext) {
    let Some(con) = context_ref("mjr_restoreBuffer", con) else {
        return;
    };
    with_gl("mjr_restoreBuffer", (), |gl| {
        framebuffer::restore_buffer(gl, con);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_readPixels(
    rgb: *mut c_uchar,
    depth: *mut f32,
    viewport: mjrRect,
    con: *const mjrContext,
) {
    // 2.2.2 returns before reading the context when there is nothing to read
    if rgb.is_null() && depth.is_null() {
        return;
    }
    let Some(con) = context_ref("mjr_readPixels", con) else {
        return;
    };
    let n = framebuffer::pixels(&viewport);
    let rgb = (!rgb.is_null()).then(|| std::slice::from_raw_parts_mut(rgb, 3 * n));
    let depth = (!depth.is_null()).then(|| std::slice::from_raw_parts_mut(depth, n));
    with_gl("mjr_readPixels", (), |gl| {
        framebuffer::read_pixels(gl, rgb, depth, viewport, con);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_drawPixels(
    rgb: *const c_uchar,
    depth: *const f32,
    viewport: mjrRect,
    _con: *const mjrContext,
) {
    let n = framebuffer::pixels(&viewport);
    let rgb = (!rgb.is_null()).then(|| std::slice::from_raw_parts(rgb, 3 * n));
    let depth = (!depth.is_null()).then(|| std::slice::from_raw_parts(depth, n));
    with_gl("mjr_drawPixels", (), |gl| {
        framebuffer::draw_pixels(gl, rgb, depth, viewport);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_blitBuffer(
    src: mjrRect,
    dst: mjrRect,
    flg_color: c_int,
    flg_depth: c_int,
    con: *const mjrContext,
) {
    let Some(con) = context_ref("mjr_blitBuffer", con) else {
        return;
    };
    with_gl("mjr_blitBuffer", (), |gl| {
        framebuffer::blit_buffer(gl, src, dst, flg_color != 0, flg_depth != 0, con);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_setAux(index: c_int, con: *const mjrContext) {
    let Some(con) = context_ref("mjr_setAux", con) else {
        return;
    };
    with_gl("mjr_setAux", (), |gl| framebuffer::set_aux(gl, index, con))
}

#[no_mangle]
pub unsafe extern "C" fn mjr_blitAux(
    index: c_int,
    src: mjrRect,
    left: c_int,
    bottom: c_int,
    con: *const mjrContext,
) {
    let Some(con) = context_ref("mjr_blitAux", con) else {
        return;
    };
    with_gl("mjr_blitAux", (), |gl| {
        framebuffer::blit_aux(gl, index, src, (left, bottom), con)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_maxViewport(con: *const mjrContext) -> mjrRect {
    let zero = mjrRect {
        left: 0,
        bottom: 0,
        width: 0,
        height: 0,
    };
    let Some(con) = context_ref("mjr_maxViewport", con) else {
        return zero;
    };
    with_gl("mjr_maxViewport", zero, |gl| {
        Ok(framebuffer::max_viewport(gl, con))
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_finish() {
    with_gl("mjr_finish", (), |gl| {
        gl.glFinish();
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_getError() -> c_int {
    with_gl("mjr_getError", 0, |gl| Ok(gl.glGetError() as c_int))
}

#[no_mangle]
pub unsafe extern "C" fn mjr_findRect(
    x: c_int,
    y: c_int,
    nrect: c_int,
    rect: *const mjrRect,
) -> c_int {
    if rect.is_null() || nrect <= 0 {
        return -1;
    }
    let rects = std::slice::from_raw_parts(rect, nrect as usize);
    rects
        .iter()
        .position(|r| {
            x >= r.left && x < r.left + r.width && y >= r.bottom && y < r.bottom + r.height
        })
        .map_or(-1, |i| i as c_int)
}

/// A C string's bytes (empty for NULL).
unsafe fn bytes<'a>(s: *const c_char) -> &'a [u8] {
    if s.is_null() {
        &[]
    } else {
        std::ffi::CStr::from_ptr(s).to_bytes()
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjr_render(viewport: mjrRect, scn: *mut mjvScene, con: *const mjrContext) {
    // a NULL context is reported where 2.2.2 would first read it (it returns before that for
    // an empty viewport or a scene without cameras)
    let Some(scn) = scn.as_mut() else {
        return errmem::error("mjr_render: NULL scene");
    };
    with_gl("mjr_render", (), |gl| {
        let mut view = crate::abi::view::Scene::new(scn);
        scene::render(gl, viewport, &mut view, con.as_ref())
    })
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mjr_text(
    font: c_int,
    txt: *const c_char,
    con: *const mjrContext,
    x: f32,
    y: f32,
    r: f32,
    g: f32,
    b: f32,
) {
    let Some(con) = context_ref("mjr_text", con) else {
        return;
    };
    let txt = bytes(txt);
    with_gl("mjr_text", (), |gl| {
        text::text(gl, font, txt, con, x, y, [r, g, b]);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_overlay(
    font: c_int,
    gridpos: c_int,
    viewport: mjrRect,
    overlay: *const c_char,
    overlay2: *const c_char,
    con: *const mjrContext,
) {
    if empty(&viewport) {
        return;
    }
    let Some(con) = context_ref("mjr_overlay", con) else {
        return;
    };
    let (o1, o2) = (bytes(overlay), bytes(overlay2));
    with_gl("mjr_overlay", (), |gl| {
        text::overlay(gl, font, gridpos, viewport, o1, o2, con);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_rectangle(viewport: mjrRect, r: f32, g: f32, b: f32, a: f32) {
    with_gl("mjr_rectangle", (), |gl| {
        text::rectangle(gl, viewport, [r, g, b, a]);
        Ok(())
    })
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mjr_label(
    viewport: mjrRect,
    font: c_int,
    txt: *const c_char,
    r: f32,
    g: f32,
    b: f32,
    a: f32,
    rt: f32,
    gt: f32,
    bt: f32,
    con: *const mjrContext,
) {
    if empty(&viewport) {
        return;
    }
    let Some(con) = context_ref("mjr_label", con) else {
        return;
    };
    let txt = (!txt.is_null()).then(|| bytes(txt));
    with_gl("mjr_label", (), |gl| {
        text::label(gl, viewport, font, txt, [r, g, b, a], [rt, gt, bt], con);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjr_figure(
    viewport: mjrRect,
    fig: *mut mjvFigure,
    con: *const mjrContext,
) {
    let Some(con) = context_ref("mjr_figure", con) else {
        return;
    };
    // 2.2.2 returns for an empty viewport before reading the figure
    if viewport.width <= 0 || viewport.height <= 0 {
        return;
    }
    let Some(fig) = fig.as_mut() else {
        return errmem::error("mjr_figure: NULL figure");
    };
    // 2.2.2 reads a line's points on into the next lines' data, and past the figure (where
    // it may crash) when there are more than that
    for (n, &pnt) in fig.linepnt.iter().enumerate() {
        let room = (mjMAXLINE - n) * mjMAXLINEPNT;
        if pnt > 0 && pnt as usize > room {
            return errmem::error(&format!(
                "mjr_figure: linepnt[{n}] is {pnt}, more points than the figure holds from \
                 line {n} on ({room})"
            ));
        }
    }
    with_gl("mjr_figure", (), |gl| {
        figure::figure(gl, viewport, fig, con);
        Ok(())
    })
}
