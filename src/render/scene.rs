//! Drawing the abstract scene (mjr_render): geoms with materials and textures, reflections
//! through the stencil buffer, shadow maps, skybox and haze, transparency sorted by distance,
//! labels, segmentation colors, stereo and the frame, in 2.2.2's order of GL calls.

use super::context::Builtin;
use super::gl::consts::*;
use super::gl::Gl;
use super::text::text_actual;
use super::util::{look_at, merge_sort, mul_mat44, ortho, perspective, reflect, row4, transform};
use crate::abi::view::Scene;
use crate::abi::*;
use crate::engine::{EngineError, MINVAL};
use crate::math::misc::halton;
use crate::visualize::interact::{average_camera, camera_in_model};

const GEOM_PLANE: i32 = mjtGeom_::mjGEOM_PLANE as i32;
const GEOM_BOX: i32 = mjtGeom_::mjGEOM_BOX as i32;
const GEOM_LINE: i32 = mjtGeom_::mjGEOM_LINE as i32;
const GEOM_SKIN: i32 = mjtGeom_::mjGEOM_SKIN as i32;

/// Is the viewer's head behind the plane through `pos` with normal the z axis of `mat`?
fn is_behind(head: &[f32; 3], pos: &[f32; 3], mat: &[f32; 9]) -> bool {
    (head[0] - pos[0]) * mat[2] + (head[1] - pos[1]) * mat[5] + (head[2] - pos[2]) * mat[8] < 0.0
}

fn is_reflective(g: &mjvGeom) -> bool {
    (g.r#type == GEOM_PLANE || g.r#type == GEOM_BOX) && g.transparent == 0 && g.reflectance > 0.0
}

#[derive(Clone, Copy, PartialEq)]
enum Tex {
    Shadow,
    Skybox,
    Regular,
}

/// Turns texturing of kind `kind` on or off for `geom`.
fn set_texture(gl: &Gl, kind: Tex, on: bool, con: &mjrContext, geom: Option<&mjvGeom>) {
    let gens = |caps: &[u32], on: bool| {
        for &c in caps {
            if on {
                gl.glEnable(c);
            } else {
                gl.glDisable(c);
            }
        }
    };
    if kind == Tex::Shadow {
        gl.glActiveTexture(GL_TEXTURE1);
        gens(
            &[
                GL_TEXTURE_2D,
                GL_TEXTURE_GEN_S,
                GL_TEXTURE_GEN_T,
                GL_TEXTURE_GEN_R,
                GL_TEXTURE_GEN_Q,
            ],
            on,
        );
        if on {
            gl.glBindTexture(GL_TEXTURE_2D, con.shadowTex);
        }
        return;
    }
    let g = geom.expect("a geom for regular and skybox textures");
    let tex = con.texture[g.texid as usize];
    if kind == Tex::Regular && g.texcoord != 0 {
        gl.glActiveTexture(GL_TEXTURE0);
        gens(&[GL_TEXTURE_2D], on);
        if on {
            gl.glBindTexture(GL_TEXTURE_2D, tex);
        }
    } else if kind == Tex::Regular
        && con.textureType[g.texid as usize] == mjtTexture_::mjTEXTURE_2D as i32
    {
        gl.glActiveTexture(GL_TEXTURE0);
        gens(&[GL_TEXTURE_2D, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T], on);
        if !on {
            return;
        }
        gl.glBindTexture(GL_TEXTURE_2D, tex);
        let mut scl = g.texrepeat;
        if g.dataid >= 0 {
            for k in 0..2 {
                if g.size[k] > 0.0 {
                    let s = g.size[k] as f64;
                    scl[k] = (scl[k] as f64 / if MINVAL > s { MINVAL } else { s }) as f32;
                }
            }
        }
        if g.texuniform != 0 {
            for k in 0..2 {
                if g.size[k] > 0.0 {
                    scl[k] *= g.size[k];
                }
            }
        }
        gl.tex_genfv(
            GL_S,
            GL_OBJECT_PLANE,
            &[(0.5 * scl[0] as f64) as f32, 0.0, 0.0, -0.5],
        );
        gl.tex_genfv(
            GL_T,
            GL_OBJECT_PLANE,
            &[0.0, (-0.5 * scl[1] as f64) as f32, 0.0, -0.5],
        );
    } else {
        gl.glActiveTexture(GL_TEXTURE0);
        gens(
            &[
                GL_TEXTURE_CUBE_MAP,
                GL_TEXTURE_GEN_S,
                GL_TEXTURE_GEN_T,
                GL_TEXTURE_GEN_R,
            ],
            on,
        );
        if !on {
            return;
        }
        gl.glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
        let planes: [[f32; 4]; 3] = if kind == Tex::Regular {
            let u = |k: usize| if g.texuniform != 0 { g.size[k] } else { 1.0 };
            [
                [u(0), 0.0, 0.0, 0.0],
                [0.0, u(1), 0.0, 0.0],
                [0.0, 0.0, u(2), 0.0],
            ]
        } else {
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, -1.0, 0.0, 0.0],
            ]
        };
        for (coord, p) in [GL_S, GL_T, GL_R].into_iter().zip(&planes) {
            gl.tex_genfv(coord, GL_OBJECT_PLANE, p);
        }
    }
}

#[derive(Clone, Copy, PartialEq, PartialOrd)]
enum Mode {
    Normal,
    ShadowMap,
    ShadowCast,
    Segment,
    IdColor,
}

/// The scene's skins: buffers of the context and face counts of the scene.
struct Skins<'a> {
    facenum: &'a [i32],
}

/// Draws one geom in `mode`.
fn render_geom(gl: &Gl, g: &mjvGeom, mode: Mode, head: &[f32; 3], skins: &Skins, con: &mjrContext) {
    if mode == Mode::ShadowCast && g.r#type == GEOM_LINE {
        return;
    }
    let m = &g.mat;
    let mat = [
        m[0], m[3], m[6], 0.0, m[1], m[4], m[7], 0.0, m[2], m[5], m[8], 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    let behind = is_behind(head, &g.pos, &g.mat);
    let textured =
        g.texid >= 0 && con.ntexture > 0 && (mode == Mode::Normal || mode == Mode::ShadowMap);
    if textured {
        set_texture(gl, Tex::Regular, true, con, Some(g));
    }
    let mut rgba = g.rgba;
    if g.r#type == GEOM_PLANE && behind && mode == Mode::Normal {
        rgba[3] = (rgba[3] as f64 * 0.3) as f32;
    }
    let emission = if mode == Mode::Normal {
        [
            g.emission * rgba[0],
            g.emission * rgba[1],
            g.emission * rgba[2],
            1.0,
        ]
    } else {
        [0.0, 0.0, 0.0, 1.0]
    };
    gl.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, &emission);
    gl.color4fv(&rgba);
    gl.glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, g.shininess * 128.0);
    gl.materialfv(
        GL_FRONT_AND_BACK,
        GL_SPECULAR,
        &[g.specular, g.specular, g.specular, 1.0],
    );
    if mode == Mode::IdColor {
        let id = g.segid + 1;
        let seg = [
            (id & 0xFF) as u8,
            ((id >> 8) & 0xFF) as u8,
            ((id >> 16) & 0xFF) as u8,
            0xFF,
        ];
        // SAFETY: GL reads 4 bytes.
        unsafe { gl.glColor4ubv(seg.as_ptr()) };
    } else if mode == Mode::Segment {
        let c = |b: i32| (0.1f32 as f64 + 0.8f32 as f64 * halton(g.segid + 10, b)) as f32;
        gl.color4fv(&[c(2), c(3), c(5), 1.0]);
    }
    gl.glPushMatrix();
    if g.r#type != GEOM_SKIN {
        gl.glTranslatef(g.pos[0], g.pos[1], g.pos[2]);
        gl.mult_matrixf(&mat);
    }
    let size = &g.size;
    let builtin = |b: Builtin| gl.glCallList(con.baseBuiltin + b as u32);
    use mjtGeom_::*;
    match g.r#type {
        t if t == mjGEOM_PLANE as i32 => {
            let mut face = 0;
            if behind {
                face = gl.get_integer(GL_CULL_FACE_MODE);
                if face == GL_BACK as i32 {
                    gl.glCullFace(GL_FRONT);
                }
            }
            if g.dataid >= 0 {
                gl.glCallList(con.basePlane + g.dataid as u32 + 1);
            } else {
                gl.glScalef(size[0], size[1], 1.0);
                gl.glCallList(con.basePlane);
            }
            if behind && face == GL_BACK as i32 {
                gl.glCullFace(GL_BACK);
            }
        }
        t if t == mjGEOM_HFIELD as i32 && g.dataid >= 0 => {
            gl.glCallList(con.baseHField + g.dataid as u32);
        }
        t if t == mjGEOM_SPHERE as i32 || t == mjGEOM_ELLIPSOID as i32 => {
            gl.glScalef(size[0], size[1], size[2]);
            builtin(Builtin::Sphere);
        }
        t if t == mjGEOM_CAPSULE as i32 => {
            let av = (0.5 * (size[0] + size[1]) as f64) as f32;
            gl.glScalef(size[0], size[1], size[2]);
            builtin(Builtin::CylinderOpen);
            gl.glScalef(1.0, 1.0, av / size[2]);
            gl.glTranslatef(0.0, 0.0, (size[2] - av) / av);
            builtin(Builtin::SphereTop);
            gl.glTranslatef(0.0, 0.0, 2.0 * (av - size[2]) / av);
            builtin(Builtin::SphereBottom);
        }
        t if t == mjGEOM_CYLINDER as i32 => {
            gl.glScalef(size[0], size[1], size[2]);
            builtin(Builtin::Cylinder);
        }
        t if t == mjGEOM_BOX as i32 => {
            gl.glScalef(size[0], size[1], size[2]);
            builtin(Builtin::Box);
        }
        t if t == mjGEOM_MESH as i32 && g.dataid >= 0 => {
            gl.glCallList(con.baseMesh + g.dataid as u32);
        }
        t if t == mjGEOM_ARROW as i32 || t == mjGEOM_ARROW1 as i32 => {
            gl.glScalef(size[0], size[1], size[2] / 6.0);
            gl.glTranslatef(0.0, 0.0, 1.0);
            builtin(Builtin::Cylinder);
            gl.glTranslatef(0.0, 0.0, 1.0);
            if t == mjGEOM_ARROW as i32 {
                gl.glScalef(1.75, 1.75, 1.0);
            }
            builtin(Builtin::Cone);
        }
        t if t == mjGEOM_ARROW2 as i32 => {
            gl.glScalef(size[0], size[1], size[2] / 3.0);
            builtin(Builtin::CylinderOpen);
            gl.glScalef(1.75, 1.75, 0.5);
            gl.glTranslatef(0.0, 0.0, -2.0);
            gl.glRotatef(180.0, 1.0, 0.0, 0.0);
            builtin(Builtin::Cone);
            gl.glRotatef(180.0, 1.0, 0.0, 0.0);
            gl.glTranslatef(0.0, 0.0, 4.0);
            builtin(Builtin::Cone);
        }
        t if t == mjGEOM_LINE as i32 => {
            gl.glLineWidth(3.0 * con.lineWidth);
            let lighting = gl.glIsEnabled(GL_LIGHTING);
            gl.glDisable(GL_LIGHTING);
            gl.glBegin(GL_LINES);
            gl.glVertex3f(0.0, 0.0, 0.0);
            gl.glVertex3f(0.0, 0.0, size[2]);
            gl.glEnd();
            gl.glLineWidth(con.lineWidth);
            if lighting != 0 {
                gl.glEnable(GL_LIGHTING);
            }
        }
        t if t == GEOM_SKIN => render_skin(gl, g.objid as usize, skins, con),
        _ => {}
    }
    gl.glPopMatrix();
    if textured {
        set_texture(gl, Tex::Regular, false, con, Some(g));
    }
}

/// Skin `i` from its vertex buffers.
fn render_skin(gl: &Gl, i: usize, skins: &Skins, con: &mjrContext) {
    // SAFETY: the context's skin name arrays hold nskin names; the scene's skin `i` exists.
    let vbo = |p: *mut u32| unsafe { *p.add(i) };
    let null = std::ptr::null();
    gl.glEnableClientState(GL_VERTEX_ARRAY);
    gl.glBindBuffer(GL_ARRAY_BUFFER, vbo(con.skinvertVBO));
    // SAFETY: offset 0 into the bound buffer.
    unsafe { gl.glVertexPointer(3, GL_FLOAT, 0, null) };
    gl.glEnableClientState(GL_NORMAL_ARRAY);
    gl.glBindBuffer(GL_ARRAY_BUFFER, vbo(con.skinnormalVBO));
    // SAFETY: as above.
    unsafe { gl.glNormalPointer(GL_FLOAT, 0, null) };
    let tex = vbo(con.skintexcoordVBO);
    if tex != 0 {
        gl.glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        gl.glBindBuffer(GL_ARRAY_BUFFER, tex);
        // SAFETY: as above.
        unsafe { gl.glTexCoordPointer(2, GL_FLOAT, 0, null) };
    } else {
        gl.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    }
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo(con.skinfaceVBO));
    // SAFETY: the bound element buffer holds the skin's faces.
    unsafe { gl.glDrawElements(GL_TRIANGLES, 3 * skins.facenum[i], GL_UNSIGNED_INT, null) };
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    for state in [GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY] {
        gl.glDisableClientState(state);
    }
}

/// Draws geom `id` with its color times `reflectance` (a reflected image).
fn render_reflection(
    gl: &Gl,
    g: &mjvGeom,
    reflectance: f32,
    head: &[f32; 3],
    skins: &Skins,
    con: &mjrContext,
) {
    let mut dim = *g;
    for k in 0..3 {
        dim.rgba[k] *= reflectance;
    }
    render_geom(gl, &dim, Mode::Normal, head, skins, con);
}

fn set_enabled(gl: &Gl, cap: u32, on: bool) {
    if on {
        gl.glEnable(cap);
    } else {
        gl.glDisable(cap);
    }
}

fn init_gl3(gl: &Gl, flags: &[u8], con: &mjrContext) {
    let flag = |f: mjtRndFlag_| flags[f as usize] != 0;
    gl.glEnable(GL_MULTISAMPLE);
    gl.glEnable(GL_LIGHTING);
    set_enabled(gl, GL_FOG, flag(mjtRndFlag_::mjRND_FOG));
    gl.glDisable(GL_BLEND);
    gl.glEnable(GL_NORMALIZE);
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthMask(1);
    set_enabled(gl, GL_CULL_FACE, flag(mjtRndFlag_::mjRND_CULL_FACE));
    gl.glShadeModel(GL_SMOOTH);
    gl.glDepthFunc(GL_LEQUAL);
    gl.glDepthRange(0.0, 1.0);
    gl.glAlphaFunc(GL_GEQUAL, 0.99);
    gl.glClearColor(0.0, 0.0, 0.0, 0.0);
    gl.glClearDepth(1.0);
    gl.glClearStencil(0);
    gl.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    let wire = flag(mjtRndFlag_::mjRND_WIREFRAME);
    gl.glPolygonMode(GL_FRONT_AND_BACK, if wire { GL_LINE } else { GL_FILL });
    gl.glLineWidth(con.lineWidth);
    gl.glFrontFace(GL_CCW);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[1.0; 4]);
    gl.glEnable(GL_COLOR_MATERIAL);
    gl.glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
}

fn init_lights(gl: &Gl, scn: &mut mjvScene, head: &[f32; 3], gaze: &[f32; 3]) {
    let global = if scn.nlight != 0 { 0.0 } else { 0.3 };
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[global, global, global, 1.0]);
    gl.glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
    gl.glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    if scn.lights[0].headlight != 0 {
        scn.lights[0].pos = *head;
        scn.lights[0].dir = *gaze;
    }
    let n = scn.nlight.clamp(0, mjMAXLIGHT as i32) as usize;
    for (i, l) in scn.lights[..n].iter().enumerate() {
        let light = GL_LIGHT0 + i as u32;
        // 2.2.2 passes the 3 colors where GL reads 4: the fourth is the next float in mjvLight
        let flags = f32::from_ne_bytes([l.headlight, l.directional, l.castshadow, 0]);
        let c = |v: [f32; 3], next: f32| [v[0], v[1], v[2], next];
        gl.lightfv(light, GL_AMBIENT, &c(l.ambient, l.diffuse[0]));
        gl.lightfv(light, GL_DIFFUSE, &c(l.diffuse, l.specular[0]));
        gl.lightfv(light, GL_SPECULAR, &c(l.specular, flags));
        let (exponent, cutoff, att) = if l.directional != 0 {
            (0.0, 180.0, [1.0, 0.0, 0.0])
        } else {
            (l.exponent, l.cutoff, l.attenuation)
        };
        gl.glLightf(light, GL_SPOT_EXPONENT, exponent);
        gl.glLightf(light, GL_SPOT_CUTOFF, cutoff);
        gl.glLightf(light, GL_CONSTANT_ATTENUATION, att[0]);
        gl.glLightf(light, GL_LINEAR_ATTENUATION, att[1]);
        gl.glLightf(light, GL_QUADRATIC_ATTENUATION, att[2]);
    }
    for i in 0..n {
        gl.glDisable(GL_LIGHT0 + i as u32);
    }
}

/// Projection and view of camera `view` (the average of both for -1); returns both matrices.
fn set_view(gl: &Gl, view: i32, viewport: &mjrRect, scn: &mjvScene) -> ([f32; 16], [f32; 16]) {
    let cam = if view >= 0 {
        scn.camera[view as usize]
    } else {
        average_camera(&scn.camera[0], &scn.camera[1])
    };
    let halfwidth = 0.5f32 * viewport.width as f32 / viewport.height as f32
        * (cam.frustum_top - cam.frustum_bottom);
    gl.glMatrixMode(GL_PROJECTION);
    gl.glLoadIdentity();
    gl.glFrustum(
        (cam.frustum_center - halfwidth) as f64,
        (cam.frustum_center + halfwidth) as f64,
        cam.frustum_bottom as f64,
        cam.frustum_top as f64,
        cam.frustum_near as f64,
        cam.frustum_far as f64,
    );
    let project = gl.get_floats::<16>(GL_PROJECTION_MATRIX);
    gl.glMatrixMode(GL_MODELVIEW);
    gl.glLoadIdentity();
    look_at(gl, &cam.pos, &cam.forward, &cam.up);
    if scn.enabletransform != 0 {
        transform(gl, &scn.translate, &scn.rotate, scn.scale);
    }
    (project, gl.get_floats::<16>(GL_MODELVIEW_MATRIX))
}

/// Position and direction of light `n`.
fn adjust_light(gl: &Gl, l: &mjvLight, n: usize) {
    let light = GL_LIGHT0 + n as u32;
    if l.directional != 0 {
        gl.lightfv(light, GL_POSITION, &[-l.dir[0], -l.dir[1], -l.dir[2], 0.0]);
    } else {
        gl.lightfv(
            light,
            GL_SPOT_DIRECTION,
            &[l.dir[0], l.dir[1], l.dir[2], 0.0],
        );
        gl.lightfv(light, GL_POSITION, &[l.pos[0], l.pos[1], l.pos[2], 1.0]);
    }
}

/// Bounding radius of a scene geom: the model's for model geoms, else from its size.
fn rbound(g: &mjvGeom) -> f32 {
    if g.objtype == mjtObj_::mjOBJ_GEOM as i32 {
        return g.modelrbound;
    }
    let s = &g.size;
    use mjtGeom_::*;
    match g.r#type {
        t if t == mjGEOM_SPHERE as i32 => s[0],
        t if t == mjGEOM_CAPSULE as i32 => s[0] + s[2],
        t if t == mjGEOM_CYLINDER as i32 => (s[0] * s[0] + s[2] * s[2]).sqrt(),
        t if t == mjGEOM_BOX as i32 => (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt(),
        _ => {
            let m12 = if s[1] > s[2] { s[1] } else { s[2] };
            if s[0] > m12 {
                s[0]
            } else {
                m12
            }
        }
    }
}

/// What the passes of one view draw with.
struct Draw<'a> {
    gl: &'a Gl,
    con: &'a mjrContext,
    geoms: &'a [mjvGeom],
    /// Transparent geoms, nearest first.
    order: &'a [i32],
    lights: &'a [mjvLight],
    head: [f32; 3],
    skins: Skins<'a>,
    additive: bool,
    wire: u32,
}

impl Draw<'_> {
    /// The transparent geoms' indices, nearest first.
    fn transparent(&self) -> impl DoubleEndedIterator<Item = usize> + '_ {
        self.order.iter().map(|&j| j as usize)
    }

    fn geom(&self, g: &mjvGeom, mode: Mode) {
        render_geom(self.gl, g, mode, &self.head, &self.skins, self.con);
    }

    /// Blending of transparent geoms: additive, or over what is drawn.
    fn blend_transparent(&self) {
        let dst = if self.additive {
            GL_ONE
        } else {
            GL_ONE_MINUS_SRC_ALPHA
        };
        self.gl.glBlendFunc(GL_SRC_ALPHA, dst);
    }
}

/// Reflections in every reflective plane or box facing the viewer, through the stencil buffer.
fn reflections(pass: &Draw) {
    let (gl, con, geoms, head, skins, wire) = (
        pass.gl,
        pass.con,
        pass.geoms,
        pass.head,
        &pass.skins,
        pass.wire,
    );
    for i in 0..geoms.len() {
        if !is_reflective(&geoms[i]) {
            continue;
        }
        let mut mirror = geoms[i];
        if mirror.r#type == GEOM_BOX {
            mirror.r#type = GEOM_PLANE;
            for k in 0..3 {
                mirror.pos[k] += mirror.size[2] * mirror.mat[3 * k + 2];
            }
        }
        if is_behind(&head, &mirror.pos, &mirror.mat) {
            continue;
        }
        gl.glDisable(GL_DEPTH_TEST);
        gl.glColorMask(0, 0, 0, 0);
        gl.glEnable(GL_STENCIL_TEST);
        gl.glClear(GL_STENCIL_BUFFER_BIT);
        gl.glStencilFunc(GL_ALWAYS, 1, 0xFF);
        gl.glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
        gl.glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        render_geom(gl, &mirror, Mode::Normal, &head, skins, con);
        gl.glPolygonMode(GL_FRONT_AND_BACK, wire);
        gl.glEnable(GL_DEPTH_TEST);
        gl.glColorMask(1, 1, 1, 1);
        gl.glStencilFunc(GL_EQUAL, 1, 0xFF);
        gl.glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        gl.glEnable(GL_CLIP_PLANE0);
        let (p, mm) = (&mirror.pos, &mirror.mat);
        let d = p[0] * mm[2] + p[1] * mm[5] + p[2] * mm[8];
        gl.clip_plane(
            GL_CLIP_PLANE0,
            &[-mm[2] as f64, -mm[5] as f64, -mm[8] as f64, d as f64],
        );
        gl.glFrontFace(GL_CW);
        gl.glPushMatrix();
        reflect(gl, &mirror.pos, &mirror.mat);
        for (j, l) in pass.lights.iter().enumerate() {
            adjust_light(gl, l, j);
            gl.glEnable(GL_LIGHT0 + j as u32);
        }
        let r = mirror.reflectance;
        for j in 0..geoms.len() {
            if geoms[j].transparent == 0 && i != j {
                render_reflection(gl, &geoms[j], r, &head, skins, con);
            }
        }
        gl.glDepthMask(0);
        gl.glEnable(GL_BLEND);
        pass.blend_transparent();
        for j in pass.transparent().filter(|&j| j != i) {
            render_reflection(gl, &geoms[j], r, &head, skins, con);
        }
        if !pass.additive {
            for j in pass.transparent().rev().filter(|&j| j != i) {
                render_reflection(gl, &geoms[j], r, &head, skins, con);
            }
        }
        gl.glDepthMask(1);
        gl.glDisable(GL_BLEND);
        for j in 0..pass.lights.len() {
            gl.glDisable(GL_LIGHT0 + j as u32);
        }
        gl.glDisable(GL_STENCIL_TEST);
        gl.glDisable(GL_CLIP_PLANE0);
        gl.glPopMatrix();
        gl.glFrontFace(GL_CCW);
    }
}

/// Where the camera's view draws: its projection and view matrices, buffer and viewport.
struct Target {
    project: [f32; 16],
    view: [f32; 16],
    framebuffer: u32,
    drawbuffer: u32,
    viewport: mjrRect,
}

/// Shadows of every light that casts them: a depth map from the light, then the lit geoms
/// again with the map as texture.
fn shadows(pass: &Draw, cam: &mjvGLCamera, t: &Target) {
    let (gl, con, geoms, head, skins) = (pass.gl, pass.con, pass.geoms, pass.head, &pass.skins);
    let (cam_project, cam_view, viewport) = (t.project, t.view, t.viewport);
    for (i, l) in pass.lights.iter().enumerate() {
        if l.castshadow == 0 {
            continue;
        }
        let up = ortho(&l.dir);
        gl.glMatrixMode(GL_PROJECTION);
        gl.glLoadIdentity();
        let (near, far) = (cam.frustum_near, cam.frustum_far);
        if l.directional != 0 {
            let c = con.shadowClip as f64;
            gl.glOrtho(-c, c, -c, c, near as f64, far as f64);
        } else {
            let fovy = 2.0 * l.cutoff * con.shadowScale;
            let fovy = if (fovy as f64) < 160.0 { fovy } else { 160.0 };
            perspective(gl, fovy, 1.0, near, far);
        }
        let light_project = gl.get_floats::<16>(GL_PROJECTION_MATRIX);
        gl.glMatrixMode(GL_MODELVIEW);
        gl.glLoadIdentity();
        look_at(gl, &l.pos, &l.dir, &up);
        let light_view = gl.get_floats::<16>(GL_MODELVIEW_MATRIX);
        gl.glBindFramebuffer(GL_FRAMEBUFFER, con.shadowFBO);
        gl.glDrawBuffer(GL_NONE);
        gl.glClear(GL_DEPTH_BUFFER_BIT);
        gl.glViewport(1, 1, con.shadowSize - 2, con.shadowSize - 2);
        gl.glCullFace(GL_FRONT);
        gl.glShadeModel(GL_FLAT);
        gl.glDisable(GL_LIGHTING);
        gl.glColorMask(0, 0, 0, 0);
        for g in geoms.iter() {
            render_geom(gl, g, Mode::ShadowCast, &head, skins, con);
        }
        gl.glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
        gl.glDrawBuffer(t.drawbuffer);
        gl.glViewport(
            viewport.left,
            viewport.bottom,
            viewport.width,
            viewport.height,
        );
        gl.glCullFace(GL_BACK);
        gl.glShadeModel(GL_SMOOTH);
        gl.glEnable(GL_LIGHTING);
        gl.glColorMask(1, 1, 1, 1);
        gl.glMatrixMode(GL_PROJECTION);
        gl.load_matrixf(&cam_project);
        gl.glMatrixMode(GL_MODELVIEW);
        gl.load_matrixf(&cam_view);
        let bias = [
            0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.5, 0.5, 0.5, 1.0,
        ];
        let texture = mul_mat44(&bias, &mul_mat44(&light_project, &light_view));
        set_texture(gl, Tex::Shadow, true, con, None);
        for (r, coord) in [GL_S, GL_T, GL_R, GL_Q].into_iter().enumerate() {
            gl.tex_genfv(coord, GL_EYE_PLANE, &row4(&texture, r));
        }
        gl.glEnable(GL_ALPHA_TEST);
        gl.glEnable(GL_BLEND);
        gl.glBlendFunc(GL_ONE, GL_ONE);
        gl.glEnable(GL_LIGHT0 + i as u32);
        for g in geoms.iter().filter(|g| g.transparent == 0) {
            render_geom(gl, g, Mode::ShadowMap, &head, skins, con);
        }
        gl.glDisable(GL_LIGHT0 + i as u32);
        gl.glDisable(GL_BLEND);
        gl.glDisable(GL_ALPHA_TEST);
        set_texture(gl, Tex::Shadow, false, con, None);
    }
}

/// The skybox around the viewer, with haze towards the horizon.
fn skybox(pass: &Draw, cam: &mjvGLCamera, raw: &mjvScene) {
    let (gl, con, geoms, head, wire) = (pass.gl, pass.con, pass.geoms, pass.head, pass.wire);
    let flag = |f: mjtRndFlag_| raw.flags[f as usize] != 0;
    gl.glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    let skybox = (0..con.ntexture.max(0) as usize)
        .find(|&i| con.textureType[i] == mjtTexture_::mjTEXTURE_SKYBOX as i32);
    if let Some(t) = skybox {
        // SAFETY: mjvGeom is plain data; zeros with a texture id stand for the sky.
        let mut sky: mjvGeom = unsafe { std::mem::zeroed() };
        sky.texid = t as i32;
        gl.glDisable(GL_LIGHTING);
        gl.glDisable(GL_COLOR_MATERIAL);
        gl.glCullFace(GL_FRONT);
        gl.glPushMatrix();
        gl.glTranslatef(head[0], head[1], head[2]);
        let mut dst = cam.frustum_far * 0.70;
        if raw.enabletransform != 0 {
            dst /= raw.scale;
        }
        gl.glScalef(dst, dst, dst);
        set_texture(gl, Tex::Skybox, true, con, Some(&sky));
        gl.glColor4f(1.0, 1.0, 1.0, 1.0);
        gl.glCallList(con.baseBuiltin + Builtin::Cylinder as u32);
        set_texture(gl, Tex::Skybox, false, con, Some(&sky));
        if flag(mjtRndFlag_::mjRND_HAZE) {
            haze(gl, geoms, &head, dst, con);
        }
        gl.glPopMatrix();
        gl.glEnable(GL_LIGHTING);
        gl.glEnable(GL_COLOR_MATERIAL);
        gl.glCullFace(GL_BACK);
    }
    gl.glPolygonMode(GL_FRONT_AND_BACK, wire);
}

/// The frame around the viewport.
fn frame(gl: &Gl, raw: &mjvScene, viewport: &mjrRect) {
    let fw = raw.framewidth;
    if fw != 0 {
        let c = raw.framergb;
        gl.glClearColor(c[0], c[1], c[2], 0.0);
        gl.glEnable(GL_SCISSOR_TEST);
        let v = &viewport;
        for (x, y, w, h) in [
            (v.left, v.bottom, v.width, fw),
            (v.left, v.bottom + v.height - fw, v.width, fw),
            (v.left, v.bottom, fw, v.height),
            (v.left + v.width - fw, v.bottom, fw, v.height),
        ] {
            gl.glScissor(x, y, w, h);
            gl.glClear(GL_COLOR_BUFFER_BIT);
        }
        gl.glDisable(GL_SCISSOR_TEST);
    }
}

/// Renders the scene into the viewport of the current buffer (mjr_render).
pub fn render(
    gl: &Gl,
    mut viewport: mjrRect,
    scn: &mut Scene,
    con: Option<&mjrContext>,
) -> Result<(), EngineError> {
    if viewport.width <= 0 || viewport.height <= 0 {
        return Ok(());
    }
    let raw = &mut *scn.raw;
    let ngeom = raw.ngeom.clamp(0, scn.geoms.len() as i32) as usize;
    let nlight = raw.nlight.clamp(0, mjMAXLIGHT as i32) as usize;
    let cam = average_camera(&raw.camera[0], &raw.camera[1]);
    if (cam.frustum_near as f64) < MINVAL {
        if raw.ngeom != 0 {
            return Err(EngineError(
                "mjvScene frustum_near too small in mjr_render".into(),
            ));
        }
        return Ok(());
    }
    // 2.2.2 reads a NULL context from here on (and crashes)
    let Some(con) = con else {
        return Err(EngineError("mjr_render: NULL context".into()));
    };
    for i in 0..raw.nskin.max(0) as usize {
        let (adr, n) = (
            3 * scn.skinvertadr[i] as usize,
            3 * scn.skinvertnum[i] as usize,
        );
        for (p, data) in [
            (con.skinvertVBO, &scn.skinvert),
            (con.skinnormalVBO, &scn.skinnormal),
        ] {
            // SAFETY: the context holds nskin buffer names.
            gl.glBindBuffer(GL_ARRAY_BUFFER, unsafe { *p.add(i) });
            gl.buffer_data(GL_ARRAY_BUFFER, &data[adr..adr + n], GL_STREAM_DRAW);
        }
    }
    let window = con.currentBuffer == mjtFramebuffer_::mjFB_WINDOW as i32;
    let mut drawbuffer = if !window {
        GL_COLOR_ATTACHMENT0
    } else if con.windowDoublebuffer != 0 {
        GL_BACK
    } else {
        GL_FRONT
    };
    let (hpos, hfwd, _) = camera_in_model(raw)?;
    let head = hpos.map(|x| x as f32);
    let forward = hfwd.map(|x| x as f32);
    init_lights(gl, raw, &head, &forward);
    let geoms = &mut scn.geoms[..ngeom];
    let mut nt = 0;
    for (i, g) in geoms.iter_mut().enumerate() {
        if (g.rgba[3] as f64) < 0.995
            || (g.r#type == GEOM_PLANE && is_behind(&head, &g.pos, &g.mat))
        {
            scn.geomorder[nt] = i as i32;
            nt += 1;
            g.transparent = 1;
            let d: [f32; 3] = std::array::from_fn(|k| g.pos[k] - head[k]);
            g.camdist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            g.camdist -= rbound(g);
            if g.r#type == GEOM_PLANE {
                g.camdist = 1e10;
            }
        } else {
            g.transparent = 0;
        }
    }
    let order = &mut scn.geomorder[..nt];
    merge_sort(order, &|a: &i32, b: &i32| {
        let (d1, d2) = (geoms[*a as usize].camdist, geoms[*b as usize].camdist);
        if d1 < d2 {
            -1
        } else if d1 == d2 {
            0
        } else {
            1
        }
    });
    let mut found = false;
    for g in geoms.iter_mut() {
        if found {
            g.reflectance = 0.0;
        } else if is_reflective(g) {
            found = true;
        }
    }
    let flags = raw.flags;
    let flag = |f: mjtRndFlag_| flags[f as usize] != 0;
    init_gl3(gl, &flags, con);
    gl.glViewport(
        viewport.left,
        viewport.bottom,
        viewport.width,
        viewport.height,
    );
    gl.glScissor(
        viewport.left,
        viewport.bottom,
        viewport.width,
        viewport.height,
    );
    gl.glEnable(GL_SCISSOR_TEST);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.glDisable(GL_SCISSOR_TEST);
    let mut stereo = raw.stereo;
    let quad = mjtStereo_::mjSTEREO_QUADBUFFERED as i32;
    let side = mjtStereo_::mjSTEREO_SIDEBYSIDE as i32;
    if stereo == quad && (!window || con.windowStereo == 0) {
        stereo = side;
    }
    if stereo == side {
        viewport.width /= 2;
    }
    let order: &[i32] = order;
    let wire = if flag(mjtRndFlag_::mjRND_WIREFRAME) {
        GL_LINE
    } else {
        GL_FILL
    };
    let geoms: &[mjvGeom] = geoms;
    let draw = Draw {
        gl,
        con,
        geoms,
        order,
        lights: &raw.lights[..nlight],
        head,
        skins: Skins {
            facenum: scn.skinfacenum,
        },
        additive: flag(mjtRndFlag_::mjRND_ADDITIVE),
        wire,
    };
    let views: &[i32] = if stereo != 0 { &[0, 1] } else { &[-1] };
    for &view in views {
        if stereo == quad {
            drawbuffer = match (con.windowDoublebuffer != 0, view != 0) {
                (true, true) => GL_BACK_RIGHT,
                (true, false) => GL_BACK_LEFT,
                (false, true) => GL_FRONT_RIGHT,
                (false, false) => GL_FRONT_LEFT,
            };
            gl.glDrawBuffer(drawbuffer);
            if view != 0 {
                gl.glClear(GL_DEPTH_BUFFER_BIT);
            }
        } else if stereo == side {
            if view != 0 {
                viewport.left += viewport.width;
            }
            gl.glViewport(
                viewport.left,
                viewport.bottom,
                viewport.width,
                viewport.height,
            );
        }
        let (cam_project, cam_view) = set_view(gl, view, &viewport, raw);

        if flag(mjtRndFlag_::mjRND_SEGMENT) {
            gl.glShadeModel(GL_FLAT);
            for cap in [GL_LIGHTING, GL_COLOR_MATERIAL] {
                gl.glDisable(cap);
            }
            gl.glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            for cap in [GL_FOG, GL_MULTISAMPLE] {
                gl.glDisable(cap);
            }
            let mode = if flag(mjtRndFlag_::mjRND_IDCOLOR) {
                Mode::IdColor
            } else {
                Mode::Segment
            };
            for g in geoms.iter().filter(|g| g.segid >= 0) {
                draw.geom(g, mode);
            }
            continue;
        }

        if flag(mjtRndFlag_::mjRND_REFLECTION) {
            reflections(&draw);
        }
        let cast_shadows = flag(mjtRndFlag_::mjRND_SHADOW) && con.shadowFBO != 0;
        for (i, l) in raw.lights[..nlight].iter().enumerate() {
            adjust_light(gl, l, i);
            if l.castshadow == 0 || !cast_shadows {
                gl.glEnable(GL_LIGHT0 + i as u32);
            }
        }
        gl.glEnable(GL_BLEND);
        gl.glBlendFunc(GL_ONE, GL_ONE);
        for g in geoms.iter().filter(|g| is_reflective(g)) {
            draw.geom(g, Mode::Normal);
        }
        gl.glDisable(GL_BLEND);
        for g in geoms
            .iter()
            .filter(|g| g.transparent == 0 && !is_reflective(g))
        {
            draw.geom(g, Mode::Normal);
        }
        for i in 0..nlight {
            gl.glDisable(GL_LIGHT0 + i as u32);
        }

        gl.fogfv(GL_FOG_COLOR, &[0.0; 4]);
        if cast_shadows {
            let target = Target {
                project: cam_project,
                view: cam_view,
                framebuffer: if window { 0 } else { con.offFBO },
                drawbuffer,
                viewport,
            };
            shadows(&draw, &cam, &target);
        }
        gl.fogfv(GL_FOG_COLOR, &con.fogRGBA);

        if flag(mjtRndFlag_::mjRND_SKYBOX) {
            skybox(&draw, &cam, raw);
        }
        for i in 0..nlight {
            gl.glEnable(GL_LIGHT0 + i as u32);
        }
        gl.glDepthMask(0);
        gl.glEnable(GL_BLEND);
        draw.blend_transparent();
        for j in draw.transparent() {
            draw.geom(&geoms[j], Mode::Normal);
        }
        if !draw.additive {
            for j in draw.transparent().rev() {
                draw.geom(&geoms[j], Mode::Normal);
            }
        }
        gl.glDepthMask(1);
        gl.glDisable(GL_BLEND);
        for i in 0..nlight {
            gl.glDisable(GL_LIGHT0 + i as u32);
        }

        gl.glDisable(GL_DEPTH_TEST);
        gl.glDisable(GL_LIGHTING);
        let shadow_font = mjtFont_::mjFONT_SHADOW as i32;
        for g in geoms.iter().filter(|g| g.label[0] != 0) {
            let label = crate::abi::cstr::cbytes(&g.label);
            let at = (g.pos[0], g.pos[1], g.pos[2]);
            text_actual(gl, shadow_font, label, con, at, [1.0, 1.0, 1.0]);
        }
        gl.glEnable(GL_DEPTH_TEST);
        gl.glEnable(GL_LIGHTING);
    }

    frame(gl, raw, &viewport);
    super::framebuffer::restore_buffer(gl, con);
    Ok(())
}

/// The haze over the first infinite plane, when the head is above it.
fn haze(gl: &Gl, geoms: &[mjvGeom], head: &[f32; 3], dst: f32, con: &mjrContext) {
    let Some(g) = geoms
        .iter()
        .find(|g| g.r#type == GEOM_PLANE && g.size[0] == 0.0 && g.size[1] == 0.0)
    else {
        return;
    };
    let m = &g.mat;
    let elevation =
        ((head[0] - g.pos[0]) * m[2] + (head[1] - g.pos[1]) * m[5] + (head[2] - g.pos[2]) * m[8])
            / dst;
    if elevation < 0.0 {
        return;
    }
    gl.mult_matrixf(&[
        m[0], m[3], m[6], 0.0, m[1], m[4], m[7], 0.0, m[2], m[5], m[8], 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.glTranslatef(0.0, 0.0, -elevation);
    gl.glScalef(1.0, 1.0, elevation);
    gl.glEnable(GL_BLEND);
    gl.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.glCallList(con.baseBuiltin + Builtin::Haze as u32);
    gl.glDisable(GL_BLEND);
}
