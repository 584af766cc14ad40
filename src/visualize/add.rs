//! The scene's geoms from the model and its state (mjv_addGeoms), category by category in
//! 2.2.2's order: skins, inertia boxes, perturbation, frames, selection, labels, joints,
//! actuators (here), then the model's objects and decorations (objects.rs, decor.rs).

use super::geom::*;
use super::{decor, objects};
use crate::abi::view::Scene;
use crate::abi::*;
use crate::engine::linalg::row;
use crate::engine::{Data, Model, MINVAL};
use crate::math::blas::mul_mat_vec;
use crate::math::quat::quat2mat;
use crate::math::vec3::{add3, mul_mat_vec3};
use crate::math::Vec3;

pub const CAT_STATIC: i32 = mjtCatBit_::mjCAT_STATIC as i32;
pub const CAT_DYNAMIC: i32 = mjtCatBit_::mjCAT_DYNAMIC as i32;
pub const CAT_DECOR: i32 = mjtCatBit_::mjCAT_DECOR as i32;

/// The geom buffer is full: adding stops there.
pub struct Full;

/// What the categories read: the model, its state's options and the perturbation.
pub struct Ctx<'a> {
    pub m: Model<'a>,
    pub opt: &'a mjvOption,
    pub pert: &'a mjvPerturb,
    pub catmask: i32,
    /// The model's mean size, as a float.
    pub scl: f32,
}

impl Ctx<'_> {
    pub fn flag(&self, f: mjtVisFlag_) -> bool {
        self.opt.flags[f as usize] != 0
    }

    pub fn shows(&self, category: i32) -> bool {
        category & self.catmask != 0
    }

    pub fn label_is(&self, l: mjtLabel_) -> bool {
        self.opt.label == l as i32
    }

    pub fn frame_is(&self, f: mjtFrame_) -> bool {
        self.opt.frame == f as i32
    }
}

/// Is the group (clamped to the valid range) shown?
pub fn group_on(groups: &[u8; mjNGROUP], group: i32) -> bool {
    groups[group.clamp(0, mjNGROUP as i32 - 1) as usize] != 0
}

/// The scene the geoms go to.
pub struct Out<'s, 'a> {
    pub scn: &'s mut Scene<'a>,
}

impl Out<'_, '_> {
    /// Adds a geom of object `objid` (of type `objtype`, in `category`), cleared, then set by
    /// `fill`; it stays unless `fill` returns false. Fails when the buffer is full.
    pub fn push(
        &mut self,
        objtype: mjtObj_,
        objid: usize,
        category: i32,
        fill: impl FnOnce(&mut mjvGeom) -> bool,
    ) -> Result<(), Full> {
        let n = self.scn.raw.ngeom;
        if n >= self.scn.raw.maxgeom {
            return Err(Full);
        }
        let g = &mut self.scn.geoms[n as usize];
        init_geom(g, GEOM_NONE, None, None, None, None);
        g.objtype = objtype as i32;
        g.objid = objid as i32;
        g.category = category;
        g.segid = n;
        if fill(g) {
            self.scn.raw.ngeom += 1;
        }
        Ok(())
    }

    /// A connector from `a` to `b` with a fixed color.
    #[allow(clippy::too_many_arguments)]
    pub fn connector(
        &mut self,
        objtype: mjtObj_,
        objid: usize,
        category: i32,
        kind: i32,
        width: f64,
        (a, b): (Vec3, Vec3),
        rgba: [f32; 4],
    ) -> Result<(), Full> {
        self.push(objtype, objid, category, |g| {
            make_connector(g, kind, width, a, b);
            g.rgba = rgba;
            true
        })
    }

    /// The three axes of a frame at `pos` with orientation `mat`: red, green and blue
    /// cylinders of the given length and width (decoration of object `objid`).
    pub fn frame(
        &mut self,
        objid: usize,
        pos: Vec3,
        mat: &[f64],
        length: f64,
        width: f64,
    ) -> Result<(), Full> {
        for j in 0..3 {
            let mut axis = [0.0; 3];
            axis[j] = length;
            let mut vec = [0.0; 3];
            mul_mat_vec(&mut vec, mat, &axis, 3, 3);
            let end = add3(&pos, &vec);
            let mut rgba = [0.0f32, 0.0, 0.0, 1.0];
            rgba[j] = 0.9;
            let unknown = mjtObj_::mjOBJ_UNKNOWN;
            self.connector(
                unknown,
                objid,
                CAT_DECOR,
                GEOM_CYLINDER,
                width,
                (pos, end),
                rgba,
            )?;
        }
        Ok(())
    }
}

/// Every category in 2.2.2's order, until the buffer is full.
pub fn add_all(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    skins(c, d, out)?;
    inertia(c, d, out)?;
    perturbation(c, d, out)?;
    body_frames(c, d, out)?;
    selection(c, d, out)?;
    body_labels(c, d, out)?;
    joints(c, d, out)?;
    actuators(c, d, out)?;
    objects::geoms(c, d, out)?;
    objects::sites(c, d, out)?;
    objects::cameras(c, d, out)?;
    objects::lights(c, d, out)?;
    objects::tendons(c, d, out)?;
    decor::slider_cranks(c, d, out)?;
    decor::com(c, d, out)?;
    decor::auto_connect(c, d, out)?;
    decor::rangefinders(c, d, out)?;
    decor::applied_forces(c, d, out)?;
    decor::equalities(c, d, out)?;
    if c.shows(CAT_DECOR) {
        decor::contacts(c, d, out)?;
    }
    Ok(())
}

fn skins(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_SKIN) || !c.shows(CAT_DYNAMIC) {
        return Ok(());
    }
    for i in 0..m.raw.nskin as usize {
        out.push(mjtObj_::mjOBJ_SKIN, i, CAT_DYNAMIC, |g| {
            let bone = m.skin_bonebodyid()[m.skin_boneadr()[i] as usize] as usize;
            init_geom(g, GEOM_SKIN, None, Some(&d.xpos[3 * bone..]), None, None);
            set_material(
                m,
                g,
                m.skin_matid()[i],
                &m.skin_rgba()[4 * i..],
                &c.opt.flags,
            );
            if c.pert.skinselect == i as i32 {
                mark_selected(m, g);
            }
            if m.skin_texcoordadr()[i] >= 0 {
                g.texcoord = 1;
            }
            if g.rgba[3] == 0.0 {
                return false;
            }
            if c.label_is(mjtLabel_::mjLABEL_SKIN) {
                label(m, mjtObj_::mjOBJ_SKIN, i, g);
            }
            true
        })?;
    }
    Ok(())
}

/// Boxes of the bodies' equivalent inertia.
fn inertia(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_INERTIA) {
        return Ok(());
    }
    for i in 1..m.raw.nbody as usize {
        let mass = m.body_mass()[i];
        if !(mass > MINVAL && c.shows(body_category(m, i))) {
            continue;
        }
        // 2.2.2 files every inertia box as dynamic, static bodies' too
        out.push(mjtObj_::mjOBJ_BODY, i, CAT_DYNAMIC, |g| {
            let inr: [f64; 3] = row(m.body_inertia(), i);
            let side = |a: usize, b: usize, k: usize| {
                ((inr[a] + inr[b] - inr[k]) * 6.0 / mass).sqrt() / 2.0
            };
            let mut sz = [side(1, 2, 0), side(0, 2, 1), side(0, 1, 2)];
            if c.flag(mjtVisFlag_::mjVIS_SCLINERTIA) {
                let density = mass / c_max(MINVAL, 8.0 * sz[0] * sz[1] * sz[2]);
                let s = (density * 0.001).powf(1.0 / 3.0);
                sz = sz.map(|x| x * s);
            }
            let rgba = Some(m.raw.vis.rgba.inertia);
            let (pos, mat) = (&d.xipos[3 * i..], &d.ximat[9 * i..]);
            init_geom(g, GEOM_BOX, Some(&sz), Some(pos), Some(mat), rgba);
            if c.pert.select == i as i32 {
                mark_selected(m, g);
            }
            if c.label_is(mjtLabel_::mjLABEL_BODY)
                || (c.label_is(mjtLabel_::mjLABEL_SELECTION) && c.pert.select == i as i32)
            {
                label(m, mjtObj_::mjOBJ_BODY, i, g);
            }
            true
        })?;
    }
    Ok(())
}

/// The connector to the mouse perturbation's target and the target's pose.
fn perturbation(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let (m, pert) = (&c.m, c.pert);
    if !c.flag(mjtVisFlag_::mjVIS_PERTOBJ) || !c.shows(CAT_DECOR) || pert.select <= 0 {
        return Ok(());
    }
    let i = pert.select as usize;
    let unknown = mjtObj_::mjOBJ_UNKNOWN;
    let xipos: Vec3 = row(d.xipos, i);
    let refmat = quat2mat(&pert.refquat);
    let bit = |flags: i32, b: mjtPertBit_| flags & b as i32 > 0;
    let translate = mjtPertBit_::mjPERT_TRANSLATE;
    if bit(pert.active | pert.active2, translate) {
        let width = (c.scl * m.raw.vis.scale.constraint) as f64;
        let rgba = mix_color(
            &m.raw.vis.rgba.constraint,
            bit(pert.active, translate),
            bit(pert.active2, translate),
        );
        let ends = (xipos, pert.refpos);
        out.connector(unknown, i, CAT_DECOR, GEOM_CAPSULE, width, ends, rgba)?;
        out.push(unknown, i, CAT_DECOR, |g| {
            let sz = [2.0 * width; 3];
            init_geom(
                g,
                GEOM_SPHERE,
                Some(&sz),
                Some(&pert.refpos),
                Some(&refmat),
                Some(rgba),
            );
            true
        })?;
    }
    let rotate = mjtPertBit_::mjPERT_ROTATE;
    if bit(pert.active | pert.active2, rotate) {
        let rgba = mix_color(
            &m.raw.vis.rgba.inertia,
            bit(pert.active, rotate),
            bit(pert.active2, rotate),
        );
        out.push(unknown, i, CAT_DECOR, |g| {
            let sz = [c.scl as f64; 3];
            init_geom(
                g,
                GEOM_BOX,
                Some(&sz),
                Some(&xipos),
                Some(&refmat),
                Some(rgba),
            );
            true
        })?;
    }
    Ok(())
}

/// The world frame (twice the size) or every body's frame.
fn body_frames(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.shows(CAT_DECOR) {
        return Ok(());
    }
    let first = if c.frame_is(mjtFrame_::mjFRAME_WORLD) {
        0
    } else {
        1
    };
    let end = if c.frame_is(mjtFrame_::mjFRAME_BODY) {
        m.raw.nbody as usize
    } else {
        1
    };
    let scale = &m.raw.vis.scale;
    for i in first..end {
        let (length, width) = if i == 0 {
            (
                scale.framelength * c.scl * 2.0,
                scale.framewidth * c.scl * 2.0,
            )
        } else {
            (scale.framelength * c.scl, scale.framewidth * c.scl)
        };
        if i > 0 && body_category(m, i) & !c.catmask != 0 {
            continue;
        }
        out.frame(
            i,
            row(d.xpos, i),
            &d.xmat[9 * i..],
            length as f64,
            width as f64,
        )?;
    }
    Ok(())
}

/// The selected point, with its coordinates as label if asked.
fn selection(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let (m, pert) = (&c.m, c.pert);
    if !c.shows(CAT_DECOR) || pert.select <= 0 || !c.flag(mjtVisFlag_::mjVIS_SELECT) {
        return Ok(());
    }
    let b = pert.select as usize;
    let selpos = add3(
        &mul_mat_vec3(&row(d.xmat, b), &pert.localpos),
        &row(d.xpos, b),
    );
    out.push(mjtObj_::mjOBJ_UNKNOWN, 0, CAT_DECOR, |g| {
        g.r#type = GEOM_SPHERE;
        g.size = [c.scl * m.raw.vis.scale.selectpoint; 3];
        g.pos = n2f(&selpos);
        g.mat = n2f(&IDENTITY);
        g.rgba = m.raw.vis.rgba.selectpoint;
        if c.label_is(mjtLabel_::mjLABEL_SELPNT) {
            let l = pert.localpos;
            let values = [selpos[0], selpos[1], selpos[2], l[0], l[1], l[2]];
            let text = crate::runtime::message::format_c(
                c"%.3f %.3f %.3f (local %.3f %.3f %.3f)",
                &values,
            );
            crate::abi::cstr::set_cstr(&mut g.label, text.as_bytes());
        }
        true
    })
}

/// Body labels where no inertia box carries them.
fn body_labels(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let (m, pert) = (&c.m, c.pert);
    let body = c.label_is(mjtLabel_::mjLABEL_BODY);
    let selected = c.label_is(mjtLabel_::mjLABEL_SELECTION);
    if !c.shows(CAT_DECOR) || !(body || selected) || c.flag(mjtVisFlag_::mjVIS_INERTIA) {
        return Ok(());
    }
    for i in 1..m.raw.nbody as usize {
        if !(body || pert.select == i as i32) || body_category(m, i) & !c.catmask != 0 {
            continue;
        }
        out.push(mjtObj_::mjOBJ_UNKNOWN, i, CAT_DECOR, |g| {
            g.r#type = GEOM_LABEL;
            g.pos = n2f(&d.xipos[3 * i..]);
            g.mat = n2f(&d.ximat[9 * i..]);
            label(m, mjtObj_::mjOBJ_BODY, i, g);
            true
        })?;
    }
    Ok(())
}

/// The arrow (slide, hinge), box (free) or sphere (ball) of a joint of body `body`, at
/// `length` and `width`.
fn joint_shape(
    d: &Data,
    g: &mut mjvGeom,
    jnt: usize,
    r#type: i32,
    body: usize,
    length: f64,
    width: f64,
) {
    let anchor: Vec3 = row(d.xanchor, jnt);
    let axis: Vec3 = row(d.xaxis, jnt);
    match r#type {
        crate::engine::JNT_FREE | crate::engine::JNT_BALL => {
            g.r#type = if r#type == crate::engine::JNT_FREE {
                GEOM_BOX
            } else {
                GEOM_SPHERE
            };
            g.size = [(0.3 * length) as f32; 3];
            g.pos = n2f(&anchor);
            g.mat = n2f(&d.xmat[9 * body..]);
        }
        _ => {
            let kind = if r#type == crate::engine::JNT_SLIDE {
                GEOM_ARROW
            } else {
                GEOM_ARROW1
            };
            let end = [
                anchor[0] + length * axis[0],
                anchor[1] + length * axis[1],
                anchor[2] + length * axis[2],
            ];
            make_connector(g, kind, width, anchor, end);
        }
    }
}

fn joints(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_JOINT) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    let scale = &m.raw.vis.scale;
    for i in 0..m.raw.njnt as usize {
        if !group_on(&c.opt.jointgroup, m.jnt_group()[i]) {
            continue;
        }
        let length = (scale.jointlength * c.scl) as f64;
        let width = (scale.jointwidth * c.scl) as f64;
        out.push(mjtObj_::mjOBJ_JOINT, i, CAT_DECOR, |g| {
            let body = m.jnt_bodyid()[i] as usize;
            joint_shape(d, g, i, m.jnt_type()[i], body, length, width);
            g.rgba = m.raw.vis.rgba.joint;
            if c.label_is(mjtLabel_::mjLABEL_JOINT) {
                label(m, mjtObj_::mjOBJ_JOINT, i, g);
            }
            true
        })?;
    }
    Ok(())
}

/// Color of actuator `i`: its control (or activation) between the negative, neutral and
/// positive colors over the range extended to include zero.
fn actuator_color(c: &Ctx, d: &Data, i: usize) -> [f32; 4] {
    let m = &c.m;
    let (mut rmin, mut rmax) = (-1.0, 1.0);
    let activation = c.flag(mjtVisFlag_::mjVIS_ACTIVATION);
    if m.actuator_ctrllimited()[i] != 0 {
        (rmin, rmax) = (
            m.actuator_ctrlrange()[2 * i],
            m.actuator_ctrlrange()[2 * i + 1],
        );
    } else if activation && m.actuator_actlimited()[i] != 0 {
        (rmin, rmax) = (
            m.actuator_actrange()[2 * i],
            m.actuator_actrange()[2 * i + 1],
        );
    }
    let mut rng = if rmin >= 0.0 {
        [-1.0, rmin, rmax]
    } else if rmax <= 0.0 {
        [rmin, rmax, 1.0]
    } else {
        [rmin, 0.0, rmax]
    };
    if rng[1] - rng[0] < MINVAL {
        rng[0] = rng[1] - MINVAL;
    }
    if rng[2] - rng[1] < MINVAL {
        rng[2] = rng[1] + MINVAL;
    }
    let clip = crate::math::misc::clip;
    let act = if activation && m.actuator_dyntype()[i] != 0 {
        let (nu, na) = (m.raw.nu as usize, m.raw.na as usize);
        clip(d.act[i + na - nu], rng[0], rng[2])
    } else {
        clip(d.ctrl[i], rng[0], rng[2])
    };
    let (amin, amean, amax): (f32, f32, f32);
    if act <= rng[1] {
        amin = ((rng[1] - act) / c_max(MINVAL, rng[1] - rng[0])) as f32;
        amean = 1.0 - amin;
        amax = 0.0;
    } else {
        amax = ((act - rng[1]) / c_max(MINVAL, rng[2] - rng[1])) as f32;
        amean = 1.0 - amax;
        amin = 0.0;
    }
    let v = &m.raw.vis.rgba;
    std::array::from_fn(|j| {
        amin * v.actuatornegative[j] + amean * v.actuator[j] + amax * v.actuatorpositive[j]
    })
}

fn actuators(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_ACTUATOR) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    let scale = &m.raw.vis.scale;
    let obj = mjtObj_::mjOBJ_ACTUATOR;
    let show_label = c.label_is(mjtLabel_::mjLABEL_ACTUATOR);
    for i in 0..m.raw.nu as usize {
        if !group_on(&c.opt.actuatorgroup, m.actuator_group()[i]) {
            continue;
        }
        let rgba = actuator_color(c, d, i);
        let j = m.actuator_trnid()[2 * i] as usize;
        let trn = m.actuator_trntype()[i];
        if trn == mjtTrn_::mjTRN_JOINT as i32
            || trn == mjtTrn_::mjTRN_JOINTINPARENT as i32
            || trn == mjtTrn_::mjTRN_SITE as i32
        {
            out.push(obj, i, CAT_DECOR, |g| {
                let own = Some(g.rgba);
                if trn == mjtTrn_::mjTRN_SITE as i32 {
                    let sz = row::<3>(m.site_size(), j).map(|x| x * 1.05);
                    let (pos, mat) = (&d.site_xpos[3 * j..], &d.site_xmat[9 * j..]);
                    init_geom(g, m.site_type()[j], Some(&sz), Some(pos), Some(mat), own);
                } else {
                    let jt = m.jnt_type()[j];
                    let body = m.jnt_bodyid()[j] as usize;
                    if jt == crate::engine::JNT_HINGE || jt == crate::engine::JNT_SLIDE {
                        let length = (scale.actuatorlength * c.scl) as f64;
                        let width = (scale.actuatorwidth * c.scl) as f64;
                        joint_shape(d, g, j, jt, body, length, width);
                    } else {
                        let sz = [(scale.jointlength * c.scl) as f64 * 0.33; 3];
                        let kind = if jt == crate::engine::JNT_BALL {
                            GEOM_SPHERE
                        } else {
                            GEOM_BOX
                        };
                        let (pos, mat) = (&d.xanchor[3 * j..], &d.xmat[9 * body..]);
                        init_geom(g, kind, Some(&sz), Some(pos), Some(mat), own);
                    }
                }
                g.rgba = rgba;
                if show_label {
                    label(m, obj, i, g);
                }
                true
            })?;
        } else if trn == mjtTrn_::mjTRN_BODY as i32 {
            let adr = m.body_geomadr()[j].max(0) as usize;
            for k in adr..adr + m.body_geomnum()[j] as usize {
                let gt = m.geom_type()[k];
                if gt == GEOM_PLANE || gt == GEOM_HFIELD || gt == GEOM_MESH {
                    continue;
                }
                out.push(obj, i, CAT_DECOR, |g| {
                    let sz = row::<3>(m.geom_size(), k).map(|x| x * 1.05);
                    let (pos, mat) = (&d.geom_xpos[3 * k..], &d.geom_xmat[9 * k..]);
                    init_geom(g, gt, Some(&sz), Some(pos), Some(mat), Some(g.rgba));
                    g.rgba = rgba;
                    true
                })?;
            }
        } else if trn == mjtTrn_::mjTRN_TENDON as i32 && d.ten_wrapnum[j] != 0 {
            let widen = m.raw.vis.map.actuatortendon as f64;
            objects::tendon_path(c, d, out, j, obj, i, CAT_DECOR, widen, |g, first| {
                g.rgba = rgba;
                if show_label && first {
                    label(m, obj, i, g);
                }
            })?;
        }
    }
    Ok(())
}
