//! The rendering context (mjr_makeContext and friends): display lists of the model's planes,
//! meshes and height fields and of the built-in shapes, textures, skin buffers, the shadow
//! map, the offscreen framebuffer, auxiliary buffers and the bitmap fonts.

use super::font_data as font;
use super::gl::consts::*;
use super::gl::{self, Gl};
use super::shapes;
use super::util::{dot, f3, make_normal};
use crate::abi::*;
use crate::engine::{EngineError, Model, MINVAL};
use crate::math::misc::round;
use crate::runtime::memory::{free, malloc};

fn err(msg: impl Into<String>) -> EngineError {
    EngineError(msg.into())
}

/// Cleared context (mjr_defaultContext).
pub fn default_context() -> mjrContext {
    // SAFETY: mjrContext is plain data; all zeros is its cleared state.
    unsafe { std::mem::zeroed() }
}

/// `n` consecutive display lists, their base in `base`.
fn allocate_lists(gl: &Gl, base: &mut u32, range: &mut i32, n: i32) -> Result<(), EngineError> {
    *range = n;
    if n != 0 {
        *base = gl.glGenLists(n);
        if *base == 0 {
            return Err(err("Could not allocate display lists"));
        }
    }
    Ok(())
}

/// Plane lists: list 0 a unit square of quads (planes without a grid), then one grid per
/// plane geom: padded to whole grid steps where finite, 200 steps past the far plane where
/// infinite.
fn make_planes(gl: &Gl, m: &Model, con: &mut mjrContext) -> Result<(), EngineError> {
    let zfar = m.raw.vis.map.zfar as f64 * m.raw.stat.extent;
    let nplane = m
        .geom_type()
        .iter()
        .filter(|&&t| t == mjtGeom_::mjGEOM_PLANE as i32)
        .count();
    allocate_lists(
        gl,
        &mut con.basePlane,
        &mut con.rangePlane,
        nplane as i32 + 1,
    )?;
    let nq = m.raw.vis.quality.numquads;
    gl.glNewList(con.basePlane, GL_COMPILE);
    gl.glBegin(GL_QUADS);
    gl.glNormal3d(0.0, 0.0, 1.0);
    let d = 2.0 / nq as f64;
    for x in 0..nq {
        for y in 0..nq {
            let at = |k: i32| d * k as f64 - 1.0;
            gl.glVertex3d(at(x), at(y), 0.0);
            gl.glVertex3d(at(x + 1), at(y), 0.0);
            gl.glVertex3d(at(x + 1), at(y + 1), 0.0);
            gl.glVertex3d(at(x), at(y + 1), 0.0);
        }
    }
    gl.glEnd();
    gl.glEndList();
    const NGRID: usize = mjMAXPLANEGRID;
    let mut list = con.basePlane + 1;
    for i in 0..m.raw.ngeom as usize {
        if m.geom_type()[i] != mjtGeom_::mjGEOM_PLANE as i32 {
            continue;
        }
        let size = &m.geom_size()[3 * i..3 * i + 3];
        let mut grid = [[0.0f64; NGRID + 1]; 2];
        let mut nn = [0usize; 2];
        for k in 0..2 {
            let sz = size[k];
            if sz > 0.0 {
                let step = larger(size[2], sz / (NGRID as f64 - 2.0));
                let mut n = (sz / larger(MINVAL, step)).floor() as i32;
                n -= n % 2;
                let pad = sz - n as f64 * step;
                let n = (n + 2) as usize;
                for x in 0..n {
                    let (left, right) = if x == 0 {
                        (-sz, -sz + pad)
                    } else {
                        let left = -sz + pad + (x as f64 - 1.0) * step * 2.0;
                        (left, left + if x == n - 1 { pad } else { step * 2.0 })
                    };
                    grid[k][x] = left;
                    grid[k][x + 1] = larger(left, right);
                }
                nn[k] = n;
            } else {
                let matid = m.geom_matid()[i];
                let repeat = (matid >= 0).then(|| m.mat_texrepeat()[2 * matid as usize + k]);
                let sx = match repeat {
                    Some(r) if r > 0.0 => (2.0 / r) as f64,
                    _ => 2.1 * zfar / (NGRID as f64 - 2.0),
                };
                let d = (2.1 * zfar + 2.0 * sx) / NGRID as f64;
                for x in 0..=NGRID {
                    grid[k][x] = d * x as f64 - d * (NGRID / 2) as f64;
                }
                nn[k] = NGRID;
            }
        }
        gl.glNewList(list, GL_COMPILE);
        gl.glBegin(GL_QUADS);
        gl.glNormal3d(0.0, 0.0, 1.0);
        for x in 0..nn[0] {
            for y in 0..nn[1] {
                gl.glVertex3d(grid[0][x], grid[1][y], 0.0);
                gl.glVertex3d(grid[0][x + 1], grid[1][y], 0.0);
                gl.glVertex3d(grid[0][x + 1], grid[1][y + 1], 0.0);
                gl.glVertex3d(grid[0][x], grid[1][y + 1], 0.0);
            }
        }
        gl.glEnd();
        gl.glEndList();
        list += 1;
    }
    Ok(())
}

/// C's mjMAX on doubles.
fn larger(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// Mesh `id`'s lists (mjr_uploadMesh): the mesh with its vertex normals (the face normal where
/// they differ much, without texture coordinates), then its convex hull with face normals.
pub fn upload_mesh(gl: &Gl, m: &Model, con: &mjrContext, id: i32) -> Result<(), EngineError> {
    if id < 0 || id >= m.raw.nmesh {
        return Err(err(format!("Invalid mesh index {id}")));
    }
    let i = id as usize;
    let list = con.baseMesh + 2 * id as u32;
    gl.glDeleteLists(list, 2);
    let vertadr = m.mesh_vertadr()[i] as usize;
    let texadr = m.mesh_texcoordadr()[i];
    let (vert, normals, tex) = (m.mesh_vert(), m.mesh_normal(), m.mesh_texcoord());
    let corner = |v: i32| f3(vert, 3 * (v as usize + vertadr));
    let texcoord = |v: i32| {
        (texadr >= 0).then(|| {
            let a = 2 * (v as usize + texadr as usize);
            [tex[a], tex[a + 1]]
        })
    };
    gl.glNewList(list, GL_COMPILE);
    gl.glBegin(GL_TRIANGLES);
    let faceadr = m.mesh_faceadr()[i] as usize;
    for f in faceadr..faceadr + m.mesh_facenum()[i] as usize {
        let ids = &m.mesh_face()[3 * f..3 * f + 3];
        let normal = make_normal(&corner(ids[0]), &corner(ids[1]), &corner(ids[2]));
        for &v in ids {
            let n = f3(normals, 3 * (v as usize + vertadr));
            if let Some(t) = texcoord(v) {
                gl.tex_coord2fv(&t);
                gl.normal3fv(&n);
            } else if (dot(&n, &normal) as f64) < 0.8 {
                gl.normal3fv(&normal);
            } else {
                gl.normal3fv(&n);
            }
            gl.vertex3fv(&corner(v));
        }
    }
    gl.glEnd();
    gl.glEndList();
    let graphadr = m.mesh_graphadr()[i];
    if graphadr >= 0 {
        let g = &m.mesh_graph()[graphadr as usize..];
        let (numvert, numface) = (g[0] as usize, g[1] as usize);
        gl.glNewList(list + 1, GL_COMPILE);
        gl.glBegin(GL_TRIANGLES);
        for f in 0..numface {
            let j = 2 + 3 * numvert + 3 * numface + 3 * f;
            let ids = &g[j..j + 3];
            gl.normal3fv(&make_normal(
                &corner(ids[0]),
                &corner(ids[1]),
                &corner(ids[2]),
            ));
            for &v in ids {
                if let Some(t) = texcoord(v) {
                    gl.tex_coord2fv(&t);
                }
                gl.vertex3fv(&corner(v));
            }
        }
        gl.glEnd();
        gl.glEndList();
    }
    Ok(())
}

/// The last three vertices of a triangle strip, emitted as triangles of alternating winding.
struct Strip {
    n: usize,
    v: [[f32; 3]; 3],
}

impl Strip {
    fn add(&mut self, gl: &Gl, x: f32, y: f32, z: f32) {
        self.v = [self.v[1], self.v[2], [x, y, z]];
        self.n += 1;
        if self.n >= 3 {
            let [a, b, c] = &self.v;
            let (b, c) = if self.n % 2 == 1 { (b, c) } else { (c, b) };
            gl.normal3fv(&make_normal(a, b, c));
            gl.vertex3fv(a);
            gl.vertex3fv(b);
            gl.vertex3fv(c);
        }
    }
}

/// Height field `id`'s list (mjr_uploadHField): the surface as triangle strips row by row,
/// the four sides down to the base, and the bottom.
pub fn upload_hfield(gl: &Gl, m: &Model, con: &mjrContext, id: i32) -> Result<(), EngineError> {
    if id < 0 || id >= m.raw.nhfield {
        return Err(err(format!("Invalid height field index {id}")));
    }
    let i = id as usize;
    gl.glDeleteLists(con.baseHField + id as u32, 1);
    gl.glNewList(con.baseHField + id as u32, GL_COMPILE);
    let data = &m.hfield_data()[m.hfield_adr()[i] as usize..];
    let (nr, nc) = (m.hfield_nrow()[i], m.hfield_ncol()[i]);
    let width = 0.5f32 * (nc - 1) as f32;
    let height = 0.5f32 * (nr - 1) as f32;
    let sz: [f32; 4] = std::array::from_fn(|r| m.hfield_size()[4 * i + r] as f32);
    let x = |c: i32, w: f32| sz[0] * (c as f32 / w - 1.0);
    let y = |r: i32, h: f32| sz[1] * (r as f32 / h - 1.0);
    let at = |r: i32, c: i32| data[(r * nc + c) as usize];
    gl.glBegin(GL_TRIANGLES);
    for r in 0..nr - 1 {
        let mut strip = Strip {
            n: 0,
            v: [[0.0; 3]; 3],
        };
        for c in 0..nc {
            strip.add(gl, x(c, width), y(r + 1, height), at(r + 1, c) * sz[2]);
            strip.add(gl, x(c, width), y(r, height), at(r, c) * sz[2]);
        }
    }
    gl.glEnd();
    gl.glBegin(GL_QUADS);
    for r in 0..nr - 1 {
        gl.glNormal3f(-1.0, 0.0, 0.0);
        gl.glVertex3f(-sz[0], y(r + 1, height), -sz[3]);
        gl.glVertex3f(-sz[0], y(r, height), -sz[3]);
        gl.glVertex3f(-sz[0], y(r, height), at(r, 0) * sz[2]);
        gl.glVertex3f(-sz[0], y(r + 1, height), at(r + 1, 0) * sz[2]);
        gl.glNormal3f(1.0, 0.0, 0.0);
        gl.glVertex3f(sz[0], y(r, height), -sz[3]);
        gl.glVertex3f(sz[0], y(r + 1, height), -sz[3]);
        gl.glVertex3f(sz[0], y(r + 1, height), at(r + 1, nc - 1) * sz[2]);
        gl.glVertex3f(sz[0], y(r, height), at(r, nc - 1) * sz[2]);
    }
    for c in 0..nc - 1 {
        gl.glNormal3f(0.0, -1.0, 0.0);
        gl.glVertex3f(x(c, width), -sz[1], -sz[3]);
        gl.glVertex3f(x(c + 1, width), -sz[1], -sz[3]);
        gl.glVertex3f(x(c + 1, width), -sz[1], at(0, c + 1) * sz[2]);
        gl.glVertex3f(x(c, width), -sz[1], at(0, c) * sz[2]);
        gl.glNormal3f(0.0, 1.0, 0.0);
        gl.glVertex3f(x(c + 1, width), sz[1], -sz[3]);
        gl.glVertex3f(x(c, width), sz[1], -sz[3]);
        gl.glVertex3f(x(c, width), sz[1], at(nr - 1, c) * sz[2]);
        gl.glVertex3f(x(c + 1, width), sz[1], at(nr - 1, c + 1) * sz[2]);
    }
    let nq = m.raw.vis.quality.numquads;
    let half = 0.5f32 * nq as f32;
    gl.glNormal3f(0.0, 0.0, -1.0);
    for r in 0..nq {
        for c in 0..nq {
            gl.glVertex3f(x(c, half), y(r, half), -sz[3]);
            gl.glVertex3f(x(c, half), y(r + 1, half), -sz[3]);
            gl.glVertex3f(x(c + 1, half), y(r + 1, half), -sz[3]);
            gl.glVertex3f(x(c + 1, half), y(r, half), -sz[3]);
        }
    }
    gl.glEnd();
    gl.glEndList();
    Ok(())
}

/// The built-in shapes' display lists, in order from `baseBuiltin`.
#[derive(Clone, Copy)]
pub enum Builtin {
    Sphere,
    SphereTop,
    SphereBottom,
    Cylinder,
    CylinderOpen,
    Haze,
    Box,
    Cone,
    Num,
}

/// Display lists of the built-in shapes, at the model's quality.
fn make_builtin(gl: &Gl, m: &Model, con: &mut mjrContext) -> Result<(), EngineError> {
    let q = &m.raw.vis.quality;
    let (stacks, slices, quads) = (q.numstacks, q.numslices, q.numquads);
    allocate_lists(
        gl,
        &mut con.baseBuiltin,
        &mut con.rangeBuiltin,
        Builtin::Num as i32,
    )?;
    let list = |k: Builtin, draw: &dyn Fn()| {
        gl.glNewList(con.baseBuiltin + k as u32, GL_COMPILE);
        draw();
        gl.glEndList();
    };
    use Builtin::*;
    list(Sphere, &|| shapes::sphere(gl, slices, stacks));
    list(SphereTop, &|| {
        shapes::half_sphere(gl, 1, slices, stacks / 2)
    });
    list(SphereBottom, &|| {
        shapes::half_sphere(gl, -1, slices, stacks / 2)
    });
    list(Cylinder, &|| {
        shapes::disk(gl, -1, slices, stacks / 2);
        shapes::cylinder(gl, slices, stacks);
        shapes::disk(gl, 1, slices, stacks / 2);
    });
    list(CylinderOpen, &|| shapes::cylinder(gl, slices, stacks));
    let (haze, rgba) = (m.raw.vis.map.haze, m.raw.vis.rgba.haze);
    list(Haze, &|| shapes::haze(gl, slices, haze, &rgba));
    list(Box, &|| shapes::cube(gl, quads));
    list(Cone, &|| {
        shapes::cone(gl, slices, stacks);
        shapes::disk(gl, 0, slices, stacks);
    });
    Ok(())
}

/// Depth texture and framebuffer of the shadow map.
fn make_shadow(gl: &Gl, con: &mut mjrContext) -> Result<(), EngineError> {
    if con.shadowSize == 0 {
        return Ok(());
    }
    con.shadowFBO = gl.gen_framebuffer();
    if con.shadowFBO == 0 {
        return Err(err("Could not allocate shadow framebuffer"));
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, con.shadowFBO);
    let mut tex = [0u32];
    gl.gen_textures(&mut tex);
    con.shadowTex = tex[0];
    gl.glActiveTexture(GL_TEXTURE1);
    gl.glEnable(GL_TEXTURE_2D);
    gl.glBindTexture(GL_TEXTURE_2D, con.shadowTex);
    let size = con.shadowSize;
    let depth = GL_DEPTH_COMPONENT;
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        depth as i32,
        size,
        size,
        depth,
        GL_FLOAT,
        None,
    );
    for (pname, value) in [
        (GL_TEXTURE_MIN_FILTER, GL_NEAREST),
        (GL_TEXTURE_MAG_FILTER, GL_NEAREST),
        (GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE),
        (GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE),
        (GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE),
        (GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL),
        (GL_DEPTH_TEXTURE_MODE, GL_INTENSITY),
    ] {
        gl.glTexParameteri(GL_TEXTURE_2D, pname, value as i32);
    }
    for coord in [GL_S, GL_T, GL_R, GL_Q] {
        gl.glTexGeni(coord, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR as i32);
    }
    let attach = GL_DEPTH_ATTACHMENT;
    gl.glFramebufferTexture2D(GL_FRAMEBUFFER, attach, GL_TEXTURE_2D, con.shadowTex, 0);
    gl.glDrawBuffer(GL_NONE);
    gl.glReadBuffer(GL_NONE);
    let status = gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if status != GL_FRAMEBUFFER_COMPLETE {
        return Err(err(format!(
            "Shadow framebuffer is not complete, error 0x{status:x}"
        )));
    }
    gl.glDisable(GL_TEXTURE_2D);
    Ok(())
}

/// A renderbuffer of `format`, multisampled when `samples` is not 0, attached to the bound
/// framebuffer at `attachment`.
fn attach_renderbuffer(
    gl: &Gl,
    samples: i32,
    format: u32,
    (width, height): (i32, i32),
    attachment: u32,
    what: &str,
) -> Result<u32, EngineError> {
    let id = gl.gen_renderbuffer();
    if id == 0 {
        return Err(err(format!("Could not allocate {what}")));
    }
    gl.glBindRenderbuffer(GL_RENDERBUFFER, id);
    if samples != 0 {
        gl.glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
        gl.glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, id);
    Ok(id)
}

fn check_framebuffer(gl: &Gl, what: &str) -> Result<(), EngineError> {
    let status = gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if status != GL_FRAMEBUFFER_COMPLETE {
        return Err(err(format!("{what} is not complete, error 0x{status:x}")));
    }
    Ok(())
}

/// The offscreen framebuffer (color, depth and stencil; multisampled with a resolve buffer).
fn make_offscreen(gl: &Gl, con: &mut mjrContext) -> Result<(), EngineError> {
    if con.offWidth == 0 || con.offHeight == 0 {
        return Ok(());
    }
    con.offFBO = gl.gen_framebuffer();
    if con.offFBO == 0 {
        return Err(err("Could not allocate offscreen framebuffer"));
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, con.offFBO);
    let max = gl.get_integer(GL_MAX_SAMPLES);
    if con.offSamples > max {
        con.offSamples = max;
    }
    let size = (con.offWidth, con.offHeight);
    let s = con.offSamples;
    con.offColor = attach_renderbuffer(
        gl,
        s,
        GL_RGBA8,
        size,
        GL_COLOR_ATTACHMENT0,
        "offscreen color buffer",
    )?;
    con.offDepthStencil = attach_renderbuffer(
        gl,
        s,
        GL_DEPTH24_STENCIL8,
        size,
        GL_DEPTH_STENCIL_ATTACHMENT,
        "offscreen depth and stencil buffer",
    )?;
    check_framebuffer(gl, "Offscreen framebuffer")?;
    con.offSamples = gl.get_renderbuffer_parameter(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES);
    if con.offSamples != 0 {
        con.offFBO_r = gl.gen_framebuffer();
        if con.offFBO_r == 0 {
            return Err(err("Could not allocate offscreen framebuffer_r"));
        }
        gl.glBindFramebuffer(GL_FRAMEBUFFER, con.offFBO_r);
        con.offColor_r = attach_renderbuffer(
            gl,
            0,
            GL_RGBA8,
            size,
            GL_COLOR_ATTACHMENT0,
            "offscreen color buffer_r",
        )?;
        con.offDepthStencil_r = attach_renderbuffer(
            gl,
            0,
            GL_DEPTH24_STENCIL8,
            size,
            GL_DEPTH_STENCIL_ATTACHMENT,
            "offscreen depth and stencil buffer_r",
        )?;
        check_framebuffer(gl, "Offscreen framebuffer_r")?;
    }
    Ok(())
}

/// Bitmap font lists (normal, shadow, big) of characters 32 to 126 at `scale`.
fn make_font(gl: &Gl, con: &mut mjrContext, scale: i32) -> Result<(), EngineError> {
    let (normal, back, big): (&[u8], &[u8], &[u8]) = match scale {
        50 => (&font::NORMAL50, &font::BACK50, &font::BIG50),
        100 => (&font::NORMAL100, &font::BACK100, &font::BIG100),
        150 => (&font::NORMAL150, &font::BACK150, &font::BIG150),
        200 => (&font::NORMAL200, &font::BACK200, &font::BIG200),
        250 => (&font::NORMAL250, &font::BACK250, &font::BIG250),
        300 => (&font::NORMAL300, &font::BACK300, &font::BIG300),
        _ => return Err(err("Invalid fontscale")),
    };
    con.fontScale = scale;
    con.rangeFont = 128;
    con.baseFontNormal = gl.glGenLists(128);
    con.baseFontShadow = gl.glGenLists(128);
    con.baseFontBig = gl.glGenLists(128);
    if con.baseFontNormal == 0 || con.baseFontShadow == 0 || con.baseFontBig == 0 {
        return Err(err("Could not allocate font lists"));
    }
    let (mut adr, mut adr_big) = (0usize, 0usize);
    for ch in 32u8..=126 {
        if normal[adr] != ch || back[adr] != ch || big[adr_big] != ch {
            return Err(err("Invalid font data index"));
        }
        let c = ch as usize;
        con.charWidth[c] = normal[adr + 1] as i32;
        con.charWidthBig[c] = big[adr_big + 1] as i32;
        con.charHeight = normal[adr + 2] as i32;
        con.charHeightBig = big[adr_big + 2] as i32;
        let (w, h) = (con.charWidth[c], con.charHeight);
        let (wb, hb) = (con.charWidthBig[c], con.charHeightBig);
        for (base, data, at, w, h) in [
            (con.baseFontNormal, normal, adr, w, h),
            (con.baseFontShadow, back, adr, w, h),
            (con.baseFontBig, big, adr_big, wb, hb),
        ] {
            gl.glNewList(base + c as u32, GL_COMPILE);
            gl.bitmap(w, h, w as f32, &data[at + 3..]);
            gl.glEndList();
        }
        adr += 3 + ((w - 1) / 8 + 1) as usize * h as usize;
        adr_big += 3 + ((wb - 1) / 8 + 1) as usize * hb as usize;
    }
    if normal[adr] != 123 || back[adr] != 123 || big[adr_big] != 123 {
        return Err(err("Invalid font data termination"));
    }
    Ok(())
}

/// Texture names for the model's textures, each uploaded.
fn make_textures(gl: &Gl, m: &Model, con: &mut mjrContext) -> Result<(), EngineError> {
    let ntex = m.raw.ntex;
    if ntex as usize > mjMAXTEXTURE {
        return Err(err(format!("Maximum number of textures is {mjMAXTEXTURE}")));
    }
    if ntex as usize > con.texture.len() {
        // 2.2.2 would write past its 100 texture slots
        return Err(err(format!(
            "Maximum number of textures is {}",
            con.texture.len()
        )));
    }
    con.ntexture = ntex;
    if ntex == 0 {
        return Ok(());
    }
    gl.gen_textures(&mut con.texture[..ntex as usize]);
    for i in 0..ntex as usize {
        con.textureType[i] = m.tex_type()[i];
        upload_texture(gl, m, con, i as i32)?;
    }
    Ok(())
}

/// Texture `id`'s image (mjr_uploadTexture): 2D with object-linear mapping, or a cube map
/// (one image repeated on all faces, or six faces).
pub fn upload_texture(gl: &Gl, m: &Model, con: &mjrContext, id: i32) -> Result<(), EngineError> {
    if id < 0 || id >= m.raw.ntex {
        return Err(err(format!("Invalid texture index {id}")));
    }
    let i = id as usize;
    let (w, h) = (m.tex_width()[i], m.tex_height()[i]);
    let cube = m.tex_type()[i] != mjtTexture_::mjTEXTURE_2D as i32;
    let all = m.tex_rgb();
    let adr = m.tex_adr()[i];
    let rgb = all.get(adr.max(0) as usize..).unwrap_or(&[]);
    // bytes glTexImage2D reads: 2.2.2 hands GL the model's data whatever the texture's size
    let side = |n: i32| n.max(0) as usize;
    let need = match (cube, w == h) {
        (false, _) => 3 * side(w) * side(h),
        (true, true) => 3 * side(w) * side(w),
        (true, false) => 6 * 3 * side(w) * side(w),
    };
    let data = if adr >= 0 && need <= rgb.len() {
        Some(rgb)
    } else {
        // GL reads nothing of an image it rejects for its size, as it does past its limit;
        // else 2.2.2 would read past the model's texture data
        let max = gl.get_integer(if cube {
            GL_MAX_CUBE_MAP_TEXTURE_SIZE
        } else {
            GL_MAX_TEXTURE_SIZE
        });
        let rejected = w < 0 || w > max || (!cube && (h < 0 || h > max));
        if !rejected {
            return Err(err(format!(
                "mjr_uploadTexture: texture {id} of {w} x {h} is larger than its data in the \
                 model"
            )));
        }
        None
    };
    let planes: [(u32, [f32; 4]); 3] = [
        (GL_S, [1.0, 0.0, 0.0, 0.0]),
        (GL_T, [0.0, 1.0, 0.0, 0.0]),
        (GL_R, [0.0, 0.0, 1.0, 0.0]),
    ];
    gl.glActiveTexture(GL_TEXTURE0);
    let (target, wrap, ncoord) = if !cube {
        (GL_TEXTURE_2D, GL_REPEAT, 2)
    } else {
        (GL_TEXTURE_CUBE_MAP, GL_CLAMP_TO_EDGE, 3)
    };
    gl.glEnable(target);
    gl.glBindTexture(target, con.texture[i]);
    let wraps = [GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R];
    for pname in &wraps[..ncoord] {
        gl.glTexParameteri(target, *pname, wrap as i32);
    }
    gl.glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.glTexParameteri(
        target,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    for (coord, _) in &planes[..ncoord] {
        gl.glTexGeni(*coord, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
    }
    for (coord, plane) in &planes[..ncoord] {
        gl.tex_genfv(*coord, GL_OBJECT_PLANE, plane);
    }
    if target == GL_TEXTURE_2D {
        gl.tex_image_2d(target, GL_RGB as i32, w, h, GL_RGB, GL_UNSIGNED_BYTE, data);
    } else {
        let face = 3 * side(w) * side(w);
        for f in 0..6 {
            let data = data.map(|d| if w == h { d } else { &d[f * face..] });
            let t = GL_TEXTURE_CUBE_MAP_POSITIVE_X + f as u32;
            gl.tex_image_2d(t, GL_RGB as i32, w, w, GL_RGB, GL_UNSIGNED_BYTE, data);
        }
    }
    gl.glGenerateMipmap(target);
    gl.glDisable(target);
    Ok(())
}

/// An array of `n` GL names from mju_malloc (freed by `free_context`).
fn names(n: usize) -> Result<&'static mut [u32], EngineError> {
    let p = malloc(n * std::mem::size_of::<u32>()) as *mut u32;
    if p.is_null() {
        return Err(err("Could not allocate skin buffers"));
    }
    // SAFETY: a fresh allocation of n u32, owned by the context until free_context.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// Vertex buffers of the skins: texture coordinates and faces now, vertices and normals at
/// each render.
fn make_skins(gl: &Gl, m: &Model, con: &mut mjrContext) -> Result<(), EngineError> {
    let nskin = m.raw.nskin as usize;
    con.nskin = m.raw.nskin;
    if nskin == 0 {
        return Ok(());
    }
    let (vert, normal, texcoord, face) =
        (names(nskin)?, names(nskin)?, names(nskin)?, names(nskin)?);
    con.skinvertVBO = vert.as_mut_ptr();
    con.skinnormalVBO = normal.as_mut_ptr();
    con.skintexcoordVBO = texcoord.as_mut_ptr();
    con.skinfaceVBO = face.as_mut_ptr();
    gl.gen_buffers(vert);
    gl.gen_buffers(normal);
    gl.gen_buffers(texcoord);
    gl.gen_buffers(face);
    for i in 0..nskin {
        let adr = m.skin_texcoordadr()[i];
        if adr >= 0 {
            gl.glBindBuffer(GL_ARRAY_BUFFER, texcoord[i]);
            let n = 2 * m.skin_vertnum()[i] as usize;
            let data = &m.skin_texcoord()[2 * adr as usize..2 * adr as usize + n];
            gl.buffer_data(GL_ARRAY_BUFFER, data, GL_STATIC_DRAW);
        } else {
            gl.delete_buffers(&texcoord[i..i + 1]);
            texcoord[i] = 0;
        }
        gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, face[i]);
        let fadr = 3 * m.skin_faceadr()[i] as usize;
        let data = &m.skin_face()[fadr..fadr + 3 * m.skin_facenum()[i] as usize];
        gl.buffer_data(GL_ELEMENT_ARRAY_BUFFER, data, GL_STATIC_DRAW);
    }
    Ok(())
}

/// Loads GL on first use and records what the window offers (mjr_makeContext's start).
fn init_gl(con: &mut mjrContext) -> Result<&'static Gl, EngineError> {
    let gl = gl::load()
        .map_err(err)?
        .ok_or_else(|| err("gladLoadGL error"))?;
    if con.glInitialized == 0 {
        if !gl.version_1_5() {
            return Err(err("OpenGL version 1.5 or higher required"));
        }
        if !gl.has_extension("GL_ARB_framebuffer_object") {
            return Err(err("OpenGL ARB_framebuffer_object required"));
        }
        if !gl.has_extension("GL_ARB_vertex_buffer_object") {
            return Err(err("OpenGL ARB_vertex_buffer_object required"));
        }
        con.glInitialized = 1;
        gl.glBindFramebuffer(GL_FRAMEBUFFER, 0);
        match gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) {
            GL_FRAMEBUFFER_COMPLETE => con.windowAvailable = 1,
            GL_FRAMEBUFFER_UNDEFINED => con.windowAvailable = 0,
            s => {
                return Err(err(format!(
                    "Default framebuffer is not complete, error 0x{s:x}"
                )))
            }
        }
    }
    if con.windowAvailable != 0 {
        con.windowStereo = gl.get_boolean(GL_STEREO) as i32;
        con.windowDoublebuffer = gl.get_boolean(GL_DOUBLEBUFFER) as i32;
        con.windowSamples = if gl.get_integer(GL_SAMPLE_BUFFERS) != 0 {
            gl.get_integer(GL_SAMPLES)
        } else {
            0
        };
    }
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    Ok(gl)
}

/// Makes the context for `m` (or offscreen buffer and fonts only without a model) at
/// `fontscale` rounded to a multiple of 50 in [100, 300] (mjr_makeContext); the offscreen
/// buffer is `default_size` without a model. OpenGL errors left over become warnings.
pub fn make_context(
    m: Option<&Model>,
    con: &mut mjrContext,
    fontscale: i32,
    default_size: (i32, i32),
) -> Result<(), EngineError> {
    let fontscale = (50 * round(fontscale as f64 / 50.0)).clamp(100, 300);
    let gl = init_gl(con)?;
    free_context(Some(gl), con);
    let Some(m) = m else {
        (con.offWidth, con.offHeight) = default_size;
        con.offSamples = 0;
        make_offscreen(gl, con)?;
        make_font(gl, con, fontscale)?;
        return super::framebuffer::set_buffer(gl, mjtFramebuffer_::mjFB_WINDOW as i32, con);
    };
    let (vis, extent) = (&m.raw.vis, m.raw.stat.extent);
    con.shadowClip = (extent * vis.map.shadowclip as f64) as f32;
    con.shadowScale = vis.map.shadowscale;
    con.offWidth = vis.global.offwidth;
    con.offHeight = vis.global.offheight;
    con.offSamples = vis.quality.offsamples;
    con.fogStart = (extent * vis.map.fogstart as f64) as f32;
    con.fogEnd = (extent * vis.map.fogend as f64) as f32;
    con.fogRGBA = vis.rgba.fog;
    con.lineWidth = vis.global.linewidth;
    con.shadowSize = vis.quality.shadowsize;
    gl.glFogi(GL_FOG_MODE, GL_LINEAR as i32);
    gl.glFogf(GL_FOG_START, con.fogStart);
    gl.glFogf(GL_FOG_END, con.fogEnd);
    gl.fogfv(GL_FOG_COLOR, &con.fogRGBA);
    gl.glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH as i32);
    gl.glHint(GL_FOG_HINT, GL_NICEST);
    make_offscreen(gl, con)?;
    make_shadow(gl, con)?;
    make_textures(gl, m, con)?;
    make_planes(gl, m, con)?;
    allocate_lists(gl, &mut con.baseMesh, &mut con.rangeMesh, 2 * m.raw.nmesh)?;
    for i in 0..m.raw.nmesh {
        upload_mesh(gl, m, con, i)?;
    }
    allocate_lists(gl, &mut con.baseHField, &mut con.rangeHField, m.raw.nhfield)?;
    for i in 0..m.raw.nhfield {
        upload_hfield(gl, m, con, i)?;
    }
    make_builtin(gl, m, con)?;
    make_skins(gl, m, con)?;
    make_font(gl, con, fontscale)?;
    if gl.has_extension("GL_ARB_seamless_cube_map") {
        gl.glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    }
    super::framebuffer::set_buffer(gl, mjtFramebuffer_::mjFB_WINDOW as i32, con)?;
    loop {
        let e = gl.glGetError();
        if e == 0 {
            break;
        }
        crate::runtime::warning(&format!(
            "OpenGL error 0x{e:x} in or before mjr_makeContext"
        ));
    }
    Ok(())
}

/// Replaces the context's fonts (mjr_changeFont).
pub fn change_font(gl: &Gl, scale: i32, con: &mut mjrContext) -> Result<(), EngineError> {
    free_fonts(gl, con);
    make_font(gl, con, scale)
}

fn free_fonts(gl: &Gl, con: &mut mjrContext) {
    if con.rangeFont != 0 {
        for base in [con.baseFontNormal, con.baseFontShadow, con.baseFontBig] {
            gl.glDeleteLists(base, con.rangeFont);
        }
    }
    con.baseFontNormal = 0;
    con.baseFontShadow = 0;
    con.baseFontBig = 0;
    con.rangeFont = 0;
}

/// Auxiliary buffer `index` of the given size and samples, with its resolve buffer
/// (mjr_addAux); a size below 1 only frees it.
pub fn add_aux(
    gl: &Gl,
    index: i32,
    (width, height): (i32, i32),
    samples: i32,
    con: &mut mjrContext,
) -> Result<(), EngineError> {
    if !(0..mjNAUX as i32).contains(&index) {
        return Err(err("Invalid aux buffer index"));
    }
    let i = index as usize;
    free_aux(gl, con, i);
    if width < 1 || height < 1 {
        return Ok(());
    }
    let max = gl.get_integer(GL_MAX_RENDERBUFFER_SIZE);
    if width > max || height > max {
        return Err(err(
            "Auxiliary buffer size exceeds maximum allowed by OpenGL implementation",
        ));
    }
    let samples = samples.min(gl.get_integer(GL_MAX_SAMPLES));
    con.auxWidth[i] = width;
    con.auxHeight[i] = height;
    con.auxSamples[i] = samples;
    con.auxFBO[i] = gl.gen_framebuffer();
    if con.auxFBO[i] == 0 {
        return Err(err("Could not allocate auxiliary framebuffer"));
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, con.auxFBO[i]);
    con.auxColor[i] = gl.gen_renderbuffer();
    if con.auxColor[i] == 0 {
        return Err(err("Could not allocate auxiliary color buffer"));
    }
    gl.glBindRenderbuffer(GL_RENDERBUFFER, con.auxColor[i]);
    gl.glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    let color = GL_COLOR_ATTACHMENT0;
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, color, GL_RENDERBUFFER, con.auxColor[i]);
    check_framebuffer(gl, "Auxiliary framebuffer")?;
    con.auxFBO_r[i] = gl.gen_framebuffer();
    if con.auxFBO_r[i] == 0 {
        return Err(err("Could not allocate auxiliary resolve framebuffer"));
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, con.auxFBO_r[i]);
    con.auxColor_r[i] = gl.gen_renderbuffer();
    if con.auxColor_r[i] == 0 {
        return Err(err("Could not allocate auxiliary color resolve buffer"));
    }
    gl.glBindRenderbuffer(GL_RENDERBUFFER, con.auxColor_r[i]);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, color, GL_RENDERBUFFER, con.auxColor_r[i]);
    check_framebuffer(gl, "Auxiliary framebuffer resolve")?;
    super::framebuffer::restore_buffer(gl, con);
    Ok(())
}

fn free_aux(gl: &Gl, con: &mut mjrContext, i: usize) {
    for rb in [con.auxColor[i], con.auxColor_r[i]] {
        if rb != 0 {
            gl.delete_renderbuffer(rb);
        }
    }
    for fb in [con.auxFBO[i], con.auxFBO_r[i]] {
        if fb != 0 {
            gl.delete_framebuffer(fb);
        }
    }
    con.auxColor[i] = 0;
    con.auxColor_r[i] = 0;
    con.auxFBO[i] = 0;
    con.auxFBO_r[i] = 0;
}

/// Frees the context's GL objects and buffers and clears it, keeping what it knows of the
/// window (mjr_freeContext). Without loaded GL only the memory is freed.
pub fn free_context(gl: Option<&Gl>, con: &mut mjrContext) {
    if let Some(gl) = gl {
        if con.ntexture > 0 {
            gl.delete_textures(&con.texture[..(con.ntexture as usize).min(con.texture.len())]);
        }
        for rb in [
            con.offColor,
            con.offColor_r,
            con.offDepthStencil,
            con.offDepthStencil_r,
        ] {
            if rb != 0 {
                gl.delete_renderbuffer(rb);
            }
        }
        for fb in [con.offFBO, con.offFBO_r] {
            if fb != 0 {
                gl.delete_framebuffer(fb);
            }
        }
        if con.shadowTex != 0 {
            gl.delete_textures(&[con.shadowTex]);
        }
        if con.shadowFBO != 0 {
            gl.delete_framebuffer(con.shadowFBO);
        }
        for i in 0..mjNAUX {
            free_aux(gl, con, i);
        }
        for (base, range) in [
            (con.basePlane, con.rangePlane),
            (con.baseMesh, con.rangeMesh),
            (con.baseHField, con.rangeHField),
            (con.baseBuiltin, con.rangeBuiltin),
        ] {
            if range != 0 {
                gl.glDeleteLists(base, range);
            }
        }
        free_fonts(gl, con);
    }
    if con.nskin > 0 {
        let n = con.nskin as usize;
        for p in [
            con.skinvertVBO,
            con.skinnormalVBO,
            con.skintexcoordVBO,
            con.skinfaceVBO,
        ] {
            if let (Some(gl), false) = (gl, p.is_null()) {
                // SAFETY: the context's skin name arrays hold nskin names (make_skins).
                gl.delete_buffers(unsafe { std::slice::from_raw_parts(p, n) });
            }
            // SAFETY: from mju_malloc in make_skins, or NULL.
            unsafe { free(p as *mut std::ffi::c_void) };
        }
    }
    let keep = (
        con.glInitialized,
        con.windowAvailable,
        con.windowSamples,
        con.windowStereo,
        con.windowDoublebuffer,
    );
    *con = default_context();
    (
        con.glInitialized,
        con.windowAvailable,
        con.windowSamples,
        con.windowStereo,
        con.windowDoublebuffer,
    ) = keep;
}
