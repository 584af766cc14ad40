//! Framebuffers: choosing the window or offscreen buffer, reading and drawing pixels, blits
//! between them and from auxiliary buffers.

use super::gl::consts::*;
use super::gl::Gl;
use crate::abi::*;
use crate::engine::EngineError;

const WINDOW: i32 = mjtFramebuffer_::mjFB_WINDOW as i32;
const OFFSCREEN: i32 = mjtFramebuffer_::mjFB_OFFSCREEN as i32;

/// The window's front or back buffer.
fn window_buffer(con: &mjrContext) -> u32 {
    if con.windowDoublebuffer != 0 {
        GL_BACK
    } else {
        GL_FRONT
    }
}

fn bind(gl: &Gl, target: u32, fbo: u32, buffer: u32, read: bool) {
    gl.glBindFramebuffer(target, fbo);
    if read {
        gl.glReadBuffer(buffer);
    } else {
        gl.glDrawBuffer(buffer);
    }
}

/// Binds the window (0) or the offscreen buffer for reading and drawing.
fn bind_both(gl: &Gl, con: &mjrContext, window: bool) {
    let (fbo, buffer) = if window {
        (0, window_buffer(con))
    } else {
        (con.offFBO, GL_COLOR_ATTACHMENT0)
    };
    gl.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.glReadBuffer(buffer);
    gl.glDrawBuffer(buffer);
}

/// Makes `framebuffer` (mjFB_WINDOW or mjFB_OFFSCREEN) current, or the only one there is
/// (mjr_setBuffer).
pub fn set_buffer(gl: &Gl, framebuffer: i32, con: &mut mjrContext) -> Result<(), EngineError> {
    let (window, off) = (con.windowAvailable != 0, con.offFBO != 0);
    let chosen = match (window, off) {
        (false, false) => return Err(EngineError("No OpenGL framebuffer available".into())),
        (true, false) => WINDOW,
        (false, true) => OFFSCREEN,
        (true, true) => framebuffer,
    };
    bind_both(gl, con, chosen == WINDOW);
    con.currentBuffer = chosen;
    Ok(())
}

/// Makes the context's current buffer current again (mjr_restoreBuffer).
pub fn restore_buffer(gl: &Gl, con: &mjrContext) {
    bind_both(gl, con, con.currentBuffer == WINDOW);
}

/// Makes the offscreen buffer (resolved when multisampled) the read buffer.
fn read_offscreen(gl: &Gl, con: &mjrContext, rect: &mjrRect, mask: u32) {
    if con.offSamples != 0 {
        bind(
            gl,
            GL_READ_FRAMEBUFFER,
            con.offFBO,
            GL_COLOR_ATTACHMENT0,
            true,
        );
        bind(
            gl,
            GL_DRAW_FRAMEBUFFER,
            con.offFBO_r,
            GL_COLOR_ATTACHMENT0,
            false,
        );
        let (x0, y0, x1, y1) = corners(rect);
        gl.glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, mask, GL_NEAREST);
        bind(
            gl,
            GL_READ_FRAMEBUFFER,
            con.offFBO_r,
            GL_COLOR_ATTACHMENT0,
            true,
        );
    } else {
        bind(
            gl,
            GL_READ_FRAMEBUFFER,
            con.offFBO,
            GL_COLOR_ATTACHMENT0,
            true,
        );
    }
}

fn corners(r: &mjrRect) -> (i32, i32, i32, i32) {
    (r.left, r.bottom, r.left + r.width, r.bottom + r.height)
}

/// Pixel counts of a viewport.
pub fn pixels(r: &mjrRect) -> usize {
    r.width.max(0) as usize * r.height.max(0) as usize
}

/// Reads the viewport's colors (3 bytes a pixel) and depths from the current buffer
/// (mjr_readPixels).
pub fn read_pixels(
    gl: &Gl,
    rgb: Option<&mut [u8]>,
    depth: Option<&mut [f32]>,
    rect: mjrRect,
    con: &mjrContext,
) {
    let mask = if rgb.is_some() {
        GL_COLOR_BUFFER_BIT
    } else {
        0
    } | if depth.is_some() {
        GL_DEPTH_BUFFER_BIT
    } else {
        0
    };
    if mask == 0 {
        return;
    }
    let window = con.currentBuffer == WINDOW;
    if !window {
        read_offscreen(gl, con, &rect, mask);
    }
    let n = pixels(&rect);
    let (x, y, w, h) = (rect.left, rect.bottom, rect.width, rect.height);
    if let Some(rgb) = rgb {
        assert!(rgb.len() >= 3 * n);
        // SAFETY: rgb holds 3 bytes for each pixel (pack alignment 1).
        unsafe {
            gl.glReadPixels(
                x,
                y,
                w,
                h,
                GL_RGB,
                GL_UNSIGNED_BYTE,
                rgb.as_mut_ptr().cast(),
            )
        };
    }
    if let Some(depth) = depth {
        assert!(depth.len() >= n);
        let kind = (GL_DEPTH_COMPONENT, GL_FLOAT);
        // SAFETY: depth holds a float for each pixel.
        unsafe { gl.glReadPixels(x, y, w, h, kind.0, kind.1, depth.as_mut_ptr().cast()) };
    }
    if !window {
        restore_buffer(gl, con);
    }
}

/// Draws colors and depths into the viewport of the current buffer (mjr_drawPixels).
pub fn draw_pixels(gl: &Gl, rgb: Option<&[u8]>, depth: Option<&[f32]>, rect: mjrRect) {
    gl.glWindowPos2i(rect.left, rect.bottom);
    let n = pixels(&rect);
    if let Some(rgb) = rgb {
        assert!(rgb.len() >= 3 * n);
        // SAFETY: rgb holds 3 bytes for each pixel (unpack alignment 1).
        unsafe {
            gl.glDrawPixels(
                rect.width,
                rect.height,
                GL_RGB,
                GL_UNSIGNED_BYTE,
                rgb.as_ptr().cast(),
            )
        };
    }
    if let Some(depth) = depth {
        assert!(depth.len() >= n);
        let kind = (GL_DEPTH_COMPONENT, GL_FLOAT);
        // SAFETY: depth holds a float for each pixel.
        unsafe {
            gl.glDrawPixels(
                rect.width,
                rect.height,
                kind.0,
                kind.1,
                depth.as_ptr().cast(),
            )
        };
    }
}

/// Blits `src` of the current buffer to `dst` of the other one, through the resolve buffer
/// when multisampled (mjr_blitBuffer).
pub fn blit_buffer(
    gl: &Gl,
    src: mjrRect,
    dst: mjrRect,
    color: bool,
    depth: bool,
    con: &mjrContext,
) {
    let mask =
        if color { GL_COLOR_BUFFER_BIT } else { 0 } | if depth { GL_DEPTH_BUFFER_BIT } else { 0 };
    let resized = src.width != dst.width || src.height != dst.height;
    let filter = if !depth && resized {
        GL_LINEAR
    } else {
        GL_NEAREST
    };
    if con.windowAvailable == 0 || con.offFBO == 0 || mask == 0 {
        return;
    }
    let (s, d) = (corners(&src), corners(&dst));
    let blit = |a: (i32, i32, i32, i32), b: (i32, i32, i32, i32)| {
        gl.glBlitFramebuffer(a.0, a.1, a.2, a.3, b.0, b.1, b.2, b.3, mask, filter)
    };
    let color0 = GL_COLOR_ATTACHMENT0;
    if con.currentBuffer == WINDOW {
        if con.offSamples != 0 {
            bind(gl, GL_READ_FRAMEBUFFER, 0, window_buffer(con), true);
            bind(gl, GL_DRAW_FRAMEBUFFER, con.offFBO_r, color0, false);
            blit(s, d);
            bind(gl, GL_READ_FRAMEBUFFER, con.offFBO_r, color0, true);
            bind(gl, GL_DRAW_FRAMEBUFFER, con.offFBO, color0, false);
            blit(d, d);
        } else {
            bind(gl, GL_READ_FRAMEBUFFER, 0, window_buffer(con), true);
            bind(gl, GL_DRAW_FRAMEBUFFER, con.offFBO, color0, false);
            blit(s, d);
        }
    } else {
        if con.offSamples != 0 {
            bind(gl, GL_READ_FRAMEBUFFER, con.offFBO, color0, true);
            bind(gl, GL_DRAW_FRAMEBUFFER, con.offFBO_r, color0, false);
            blit(s, s);
            bind(gl, GL_READ_FRAMEBUFFER, con.offFBO_r, color0, true);
        } else {
            bind(gl, GL_READ_FRAMEBUFFER, con.offFBO, color0, true);
        }
        bind(gl, GL_DRAW_FRAMEBUFFER, 0, window_buffer(con), false);
        blit(s, d);
    }
    restore_buffer(gl, con);
}

fn check_aux(index: i32) -> Result<usize, EngineError> {
    if !(0..mjNAUX as i32).contains(&index) {
        return Err(EngineError("Invalid aux buffer index".into()));
    }
    Ok(index as usize)
}

/// Makes auxiliary buffer `index` current (mjr_setAux).
pub fn set_aux(gl: &Gl, index: i32, con: &mjrContext) -> Result<(), EngineError> {
    let i = check_aux(index)?;
    if con.auxFBO[i] == 0 {
        return Err(EngineError(format!("auxFBO {index} does not exist")));
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, con.auxFBO[i]);
    gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.glDrawBuffer(GL_COLOR_ATTACHMENT0);
    Ok(())
}

/// Blits `src` of auxiliary buffer `index` (resolved) to (left, bottom) of the current
/// buffer (mjr_blitAux).
pub fn blit_aux(
    gl: &Gl,
    index: i32,
    src: mjrRect,
    (left, bottom): (i32, i32),
    con: &mjrContext,
) -> Result<(), EngineError> {
    let i = check_aux(index)?;
    if con.auxFBO[i] == 0 {
        return Ok(());
    }
    let color0 = GL_COLOR_ATTACHMENT0;
    let (x0, y0, x1, y1) = corners(&src);
    bind(gl, GL_READ_FRAMEBUFFER, con.auxFBO[i], color0, true);
    bind(gl, GL_DRAW_FRAMEBUFFER, con.auxFBO_r[i], color0, false);
    let (bit, near) = (GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl.glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, bit, near);
    bind(gl, GL_READ_FRAMEBUFFER, con.auxFBO_r[i], color0, true);
    if con.currentBuffer == WINDOW {
        bind(gl, GL_DRAW_FRAMEBUFFER, 0, window_buffer(con), false);
    } else {
        bind(gl, GL_DRAW_FRAMEBUFFER, con.offFBO, color0, false);
    }
    let (w, h) = (src.width, src.height);
    gl.glBlitFramebuffer(
        x0,
        y0,
        x1,
        y1,
        left,
        bottom,
        left + w,
        bottom + h,
        bit,
        near,
    );
    restore_buffer(gl, con);
    Ok(())
}

/// The whole current buffer: the offscreen size, or the window's scissor box
/// (mjr_maxViewport).
pub fn max_viewport(gl: &Gl, con: &mjrContext) -> mjrRect {
    let mut r = mjrRect {
        left: 0,
        bottom: 0,
        width: con.offWidth,
        height: con.offHeight,
    };
    if con.currentBuffer == WINDOW {
        let dims: [i32; 4] = gl.get_integers(GL_SCISSOR_BOX);
        r.width = dims[2];
        r.height = dims[3];
    }
    r
}
