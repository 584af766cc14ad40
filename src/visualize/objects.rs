//! The model's own objects in the scene: geoms (infinite planes re-centered under the
//! viewer), sites, cameras, lights and tendons, with their frames when asked.

use super::add::{group_on, Ctx, Full, Out, CAT_DECOR, CAT_DYNAMIC};
use super::catenary::catenary;
use super::geom::*;
use crate::abi::*;
use crate::engine::linalg::row;
use crate::engine::{disabled, Data, MINVAL};
use crate::math::misc::round;
use crate::math::quat::{quat2mat, quat_z2vec};
use crate::math::vec3::{add_scl3, add_to_scl3, dot3, norm3, transpose3};
use crate::math::Vec3;

const UNKNOWN: mjtObj_ = mjtObj_::mjOBJ_UNKNOWN;

/// Length and width of a frame's axes.
fn frame_size(c: &Ctx) -> (f64, f64) {
    let s = &c.m.raw.vis.scale;
    (
        (s.framelength * c.scl) as f64,
        (s.framewidth * c.scl) as f64,
    )
}

pub fn geoms(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    let mut planeid = -1;
    for i in 0..m.raw.ngeom as usize {
        let gtype = m.geom_type()[i];
        if gtype == GEOM_PLANE {
            planeid += 1;
        }
        let category = body_category(m, m.geom_bodyid()[i] as usize);
        if !c.shows(category) || !group_on(&c.opt.geomgroup, m.geom_group()[i]) {
            continue;
        }
        let head = out.scn.raw.camera.map(|cam| cam.pos);
        let mut shown = false;
        out.push(mjtObj_::mjOBJ_GEOM, i, category, |g| {
            let size = &m.geom_size()[3 * i..];
            let (pos, mat) = (&d.geom_xpos[3 * i..], &d.geom_xmat[9 * i..]);
            init_geom(g, gtype, Some(size), Some(pos), Some(mat), None);
            let dataid = m.geom_dataid()[i];
            g.dataid = dataid;
            g.modelrbound = m.geom_rbound()[i] as f32;
            set_material(
                m,
                g,
                m.geom_matid()[i],
                &m.geom_rgba()[4 * i..],
                &c.opt.flags,
            );
            if gtype == GEOM_MESH && dataid >= 0 && m.mesh_texcoordadr()[dataid as usize] >= 0 {
                g.texcoord = 1;
            }
            if g.rgba[3] == 0.0 {
                return false;
            }
            if c.pert.select > 0 && c.pert.select == m.geom_bodyid()[i] {
                mark_selected(m, g);
            }
            if c.label_is(mjtLabel_::mjLABEL_GEOM) {
                label(m, mjtObj_::mjOBJ_GEOM, i, g);
            }
            if gtype == GEOM_MESH {
                g.dataid *= 2;
                let hull = m.mesh_graphadr()[dataid as usize] >= 0;
                if hull && c.flag(mjtVisFlag_::mjVIS_CONVEXHULL) {
                    g.dataid += 1;
                }
            } else if gtype == GEOM_PLANE {
                g.dataid = planeid;
                g.pos = n2f(&plane_position(c, d, &head, i));
            }
            shown = true;
            true
        })?;
        if shown && c.shows(CAT_DECOR) && c.frame_is(mjtFrame_::mjFRAME_GEOM) {
            let (length, width) = frame_size(c);
            out.frame(i, row(d.geom_xpos, i), &d.geom_xmat[9 * i..], length, width)?;
        }
    }
    Ok(())
}

/// Position of plane geom `i`: an infinite direction moves, in whole grid (or texture)
/// steps, to below the viewer's head (the middle of the scene's two GL cameras).
fn plane_position(c: &Ctx, d: &Data, head: &[[f32; 3]; 2], i: usize) -> Vec3 {
    let m = &c.m;
    let mut pos: Vec3 = row(d.geom_xpos, i);
    let size = &m.geom_size()[3 * i..];
    if size[0] > 0.0 && size[1] > 0.0 {
        return pos;
    }
    let vec: Vec3 =
        std::array::from_fn(|j| 0.5 * (head[0][j] + head[1][j]) as f64 - d.geom_xpos[3 * i + j]);
    let ax = transpose3(&row(d.geom_xmat, i));
    for k in 0..2 {
        if size[k] > 0.0 {
            continue;
        }
        let zfar = m.raw.vis.map.zfar as f64 * m.raw.stat.extent;
        let matid = m.geom_matid()[i];
        let step = if matid >= 0 && m.mat_texrepeat()[2 * matid as usize + k] > 0.0 {
            (2.0 / m.mat_texrepeat()[2 * matid as usize + k]) as f64
        } else {
            2.1 * zfar / (mjMAXPLANEGRID as f64 - 2.0)
        };
        let axis: Vec3 = row(&ax, k);
        let dx = dot3(&vec, &axis);
        let dx = 2.0 * step * round(0.5 * dx / step) as f64;
        add_to_scl3(&mut pos, &axis, dx);
    }
    pos
}

pub fn sites(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    for i in 0..m.raw.nsite as usize {
        let category = body_category(m, m.site_bodyid()[i] as usize);
        if !c.shows(category) || !group_on(&c.opt.sitegroup, m.site_group()[i]) {
            continue;
        }
        let mut shown = false;
        out.push(mjtObj_::mjOBJ_SITE, i, category, |g| {
            let size = &m.site_size()[3 * i..];
            let (pos, mat) = (&d.site_xpos[3 * i..], &d.site_xmat[9 * i..]);
            init_geom(g, m.site_type()[i], Some(size), Some(pos), Some(mat), None);
            set_material(
                m,
                g,
                m.site_matid()[i],
                &m.site_rgba()[4 * i..],
                &c.opt.flags,
            );
            if g.rgba[3] == 0.0 {
                return false;
            }
            if c.pert.select > 0 && c.pert.select == m.site_bodyid()[i] {
                mark_selected(m, g);
            }
            if c.label_is(mjtLabel_::mjLABEL_SITE) {
                label(m, mjtObj_::mjOBJ_SITE, i, g);
            }
            shown = true;
            true
        })?;
        if shown && c.shows(CAT_DECOR) && c.frame_is(mjtFrame_::mjFRAME_SITE) {
            let (length, width) = frame_size(c);
            out.frame(i, row(d.site_xpos, i), &d.site_xmat[9 * i..], length, width)?;
        }
    }
    Ok(())
}

/// Each camera as a box with a darker lens in front.
pub fn cameras(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_CAMERA) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    let size = c.scl * m.raw.vis.scale.camera;
    let framed = c.frame_is(mjtFrame_::mjFRAME_CAMERA);
    for i in 0..m.raw.ncam as usize {
        // 2.2.2 files the cameras after the first as unknown objects when frames are shown
        let obj = if i > 0 && framed {
            UNKNOWN
        } else {
            mjtObj_::mjOBJ_CAMERA
        };
        let (pos, mat) = (&d.cam_xpos[3 * i..], &d.cam_xmat[9 * i..]);
        out.push(obj, i, CAT_DECOR, |g| {
            g.r#type = GEOM_BOX;
            g.size = [1.0, 0.8, 0.4].map(|f: f64| (size as f64 * f) as f32);
            g.pos = n2f(pos);
            g.mat = n2f(mat);
            g.rgba = m.raw.vis.rgba.camera;
            if c.label_is(mjtLabel_::mjLABEL_CAMERA) {
                label(m, mjtObj_::mjOBJ_CAMERA, i, g);
            }
            true
        })?;
        out.push(obj, i, CAT_DECOR, |g| {
            g.pos = std::array::from_fn(|k| (pos[k] - size as f64 * 0.6 * mat[3 * k + 2]) as f32);
            g.r#type = GEOM_CYLINDER;
            g.size = [0.4, 0.4, 0.3].map(|f: f64| (size as f64 * f) as f32);
            g.mat = n2f(mat);
            g.rgba = m.raw.vis.rgba.camera;
            for k in 0..3 {
                g.rgba[k] = (g.rgba[k] as f64 * 0.5) as f32;
            }
            true
        })?;
        if framed {
            let (length, width) = frame_size(c);
            out.frame(i, row(d.cam_xpos, i), mat, length, width)?;
        }
    }
    Ok(())
}

/// Each light as a cylinder set back along its direction (so that it casts no shadow).
pub fn lights(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_LIGHT) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    let size = c.scl * m.raw.vis.scale.light;
    let framed = c.frame_is(mjtFrame_::mjFRAME_LIGHT);
    for i in 0..m.raw.nlight as usize {
        // as for cameras: unknown objects after the first when frames are shown
        let obj = if i > 0 && framed {
            UNKNOWN
        } else {
            mjtObj_::mjOBJ_LIGHT
        };
        let dir: Vec3 = row(d.light_xdir, i);
        let mat = quat2mat(&quat_z2vec(&dir));
        let back = (-c.scl * m.raw.vis.scale.light) as f64 - 0.0001;
        let pos = add_scl3(&row(d.light_xpos, i), &dir, back);
        out.push(obj, i, CAT_DECOR, |g| {
            g.r#type = GEOM_CYLINDER;
            g.size = [0.8, 0.8, 1.0].map(|f: f64| (size as f64 * f) as f32);
            g.pos = n2f(&pos);
            g.mat = n2f(&mat);
            g.rgba = m.raw.vis.rgba.light;
            if c.label_is(mjtLabel_::mjLABEL_LIGHT) {
                label(m, mjtObj_::mjOBJ_LIGHT, i, g);
            }
            true
        })?;
        if framed {
            let (length, width) = frame_size(c);
            out.frame(i, row(d.light_xpos, i), &mat, length, width)?;
        }
    }
    Ok(())
}

/// The straight segments of tendon `t`'s path as capsules (half width inside wrapping
/// objects, times `widen`), with its material; `then` finishes each (it is told the first).
#[allow(clippy::too_many_arguments)]
pub fn tendon_path(
    c: &Ctx,
    d: &Data,
    out: &mut Out,
    t: usize,
    objtype: mjtObj_,
    objid: usize,
    category: i32,
    widen: f64,
    then: impl Fn(&mut mjvGeom, bool),
) -> Result<(), Full> {
    let m = &c.m;
    let adr = d.ten_wrapadr[t] as usize;
    let width = m.tendon_width()[t];
    for j in adr..(adr + d.ten_wrapnum[t] as usize).saturating_sub(1) {
        let (obj0, obj1) = (d.wrap_obj[j], d.wrap_obj[j + 1]);
        if obj0 == -2 || obj1 == -2 {
            continue;
        }
        let w = if obj0 >= 0 && obj1 >= 0 {
            0.5 * width
        } else {
            width
        } * widen;
        out.push(objtype, objid, category, |g| {
            let ends = (row(d.wrap_xpos, j), row(d.wrap_xpos, j + 1));
            make_connector(g, GEOM_CAPSULE, w, ends.0, ends.1);
            set_material(
                m,
                g,
                m.tendon_matid()[t],
                &m.tendon_rgba()[4 * t..],
                &c.opt.flags,
            );
            then(g, j == adr);
            true
        })?;
    }
    Ok(())
}

/// Does tendon `t` hang as a string under gravity (two points, length limited from 0, no
/// stiffness, damping or friction)?
fn hangs(c: &Ctx, t: usize) -> bool {
    let m = &c.m;
    !disabled(m, mjtDisableBit_::mjDSBL_GRAVITY)
        && norm3(&m.raw.opt.gravity) > MINVAL
        && m.tendon_num()[t] == 2
        && m.tendon_limited()[t] == 1
        && m.tendon_range()[2 * t] == 0.0
        && m.tendon_stiffness()[t] == 0.0
        && m.tendon_damping()[t] == 0.0
        && m.tendon_frictionloss()[t] == 0.0
}

pub fn tendons(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_TENDON) || !c.shows(CAT_DYNAMIC) {
        return Ok(());
    }
    let obj = mjtObj_::mjOBJ_TENDON;
    let show_label = c.label_is(mjtLabel_::mjLABEL_TENDON);
    for i in 0..m.raw.ntendon as usize {
        if !group_on(&c.opt.tendongroup, m.tendon_group()[i]) {
            continue;
        }
        if !hangs(c, i) {
            tendon_path(c, d, out, i, obj, i, CAT_DYNAMIC, 1.0, |g, first| {
                if show_label && first {
                    label(m, obj, i, g);
                }
            })?;
            continue;
        }
        let adr = d.ten_wrapadr[i] as usize;
        let (x0, x1) = (row(d.wrap_xpos, adr), row(d.wrap_xpos, adr + 1));
        let length = m.tendon_range()[2 * i + 1];
        let (points, n) = catenary(&x0, &x1, &m.raw.opt.gravity, length);
        for j in 0..n - 1 {
            out.push(obj, i, CAT_DYNAMIC, |g| {
                let w = m.tendon_width()[i];
                make_connector(g, GEOM_CAPSULE, w, points[j], points[j + 1]);
                set_material(
                    m,
                    g,
                    m.tendon_matid()[i],
                    &m.tendon_rgba()[4 * i..],
                    &c.opt.flags,
                );
                // 2.2.2 labels every segment of a hanging tendon
                if show_label {
                    label(m, obj, i, g);
                }
                true
            })?;
        }
    }
    Ok(())
}
