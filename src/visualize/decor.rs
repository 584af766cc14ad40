//! Decorations computed from the state: slider-cranks, centers of mass, the kinematic tree,
//! rangefinder rays, applied forces, equality constraints, contacts and their forces.

use super::add::{Ctx, Full, Out, CAT_DECOR, CAT_DYNAMIC};
use super::geom::*;
use crate::abi::*;
use crate::engine::linalg::row;
use crate::engine::support::contact_force;
use crate::engine::{Data, MINVAL};
use crate::math::blas::mul_mat_vec;
use crate::math::vec3::{add3, add_scl3, dot3, mul_mat_vec3, norm3, scl3, sub3, transpose3};
use crate::math::Vec3;

const UNKNOWN: mjtObj_ = mjtObj_::mjOBJ_UNKNOWN;

pub fn slider_cranks(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.shows(CAT_DYNAMIC) {
        return Ok(());
    }
    let obj = mjtObj_::mjOBJ_ACTUATOR;
    let rgba = &m.raw.vis.rgba;
    let width = (c.scl * m.raw.vis.scale.slidercrank) as f64;
    for i in 0..m.raw.nu as usize {
        if m.actuator_trntype()[i] != mjtTrn_::mjTRN_SLIDERCRANK as i32 {
            continue;
        }
        let crank = m.actuator_trnid()[2 * i] as usize;
        let slider = m.actuator_trnid()[2 * i + 1] as usize;
        let rod = m.actuator_cranklength()[i];
        let axis = [2, 5, 8].map(|k| d.site_xmat[9 * slider + k]);
        let base: Vec3 = row(d.site_xpos, slider);
        let crank_pos: Vec3 = row(d.site_xpos, crank);
        let vec = sub3(&crank_pos, &base);
        let len = dot3(&vec, &axis);
        let mut det = len * len + rod * rod - dot3(&vec, &vec);
        let broken = det < 0.0;
        if broken {
            det = 0.0;
        }
        let len = len - det.sqrt();
        let end = add3(&scl3(&axis, len), &base);
        out.push(obj, i, CAT_DYNAMIC, |g| {
            make_connector(g, GEOM_CYLINDER, width, base, end);
            g.rgba = rgba.slidercrank;
            if c.label_is(mjtLabel_::mjLABEL_ACTUATOR) {
                label(m, obj, i, g);
            }
            true
        })?;
        let color = if broken {
            rgba.crankbroken
        } else {
            rgba.slidercrank
        };
        let ends = (end, crank_pos);
        out.connector(obj, i, CAT_DYNAMIC, GEOM_CAPSULE, width / 2.0, ends, color)?;
    }
    Ok(())
}

/// Centers of mass of the root bodies' subtrees.
pub fn com(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_COM) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    for i in 1..m.raw.nbody as usize {
        if m.body_rootid()[i] != i as i32 {
            continue;
        }
        out.push(UNKNOWN, i, CAT_DECOR, |g| {
            g.r#type = GEOM_SPHERE;
            g.size = [c.scl * m.raw.vis.scale.com; 3];
            g.pos = n2f(&d.subtree_com[3 * i..]);
            g.mat = n2f(&IDENTITY);
            g.rgba = m.raw.vis.rgba.com;
            true
        })?;
    }
    Ok(())
}

/// The kinematic tree: each body's center of mass through its joints, last to first, to its
/// parent's center of mass.
pub fn auto_connect(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_AUTOCONNECT) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    let width = (c.scl * m.raw.vis.scale.connect) as f64;
    let rgba = m.raw.vis.rgba.connect;
    for i in 1..m.raw.nbody as usize {
        let parent = m.body_parentid()[i] as usize;
        if parent == 0 {
            continue;
        }
        let mut cur: Vec3 = row(d.xipos, i);
        let adr = m.body_jntadr()[i];
        for j in (adr..adr + m.body_jntnum()[i]).rev() {
            let next: Vec3 = row(d.xanchor, j as usize);
            out.connector(
                UNKNOWN,
                i,
                CAT_DECOR,
                GEOM_CAPSULE,
                width,
                (cur, next),
                rgba,
            )?;
            cur = next;
        }
        let ends = (cur, row(d.xipos, parent));
        out.connector(UNKNOWN, i, CAT_DECOR, GEOM_CAPSULE, width, ends, rgba)?;
    }
    Ok(())
}

/// The rays of rangefinders that hit something.
pub fn rangefinders(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_RANGEFINDER) || !c.shows(CAT_DECOR) {
        return Ok(());
    }
    for i in 0..m.raw.nsensor as usize {
        if m.sensor_type()[i] != mjtSensor_::mjSENS_RANGEFINDER as i32 {
            continue;
        }
        let dst = d.sensordata[m.sensor_adr()[i] as usize];
        if dst < 0.0 {
            continue;
        }
        let s = m.sensor_objid()[i] as usize;
        let pos: Vec3 = row(d.site_xpos, s);
        let end = std::array::from_fn(|k| pos[k] + d.site_xmat[9 * s + 3 * k + 2] * dst);
        let rgba = m.raw.vis.rgba.rangefinder;
        out.connector(UNKNOWN, i, CAT_DECOR, GEOM_LINE, 0.01, (pos, end), rgba)?;
    }
    Ok(())
}

/// Forces applied to bodies (xfrc_applied), as arrows from their centers of mass.
pub fn applied_forces(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    let scale = m.raw.vis.map.force as f64 / m.raw.stat.meanmass;
    let width = (m.raw.vis.scale.forcewidth * c.scl) as f64;
    for i in 1..m.raw.nbody as usize {
        let xfrc = &d.xfrc_applied[6 * i..6 * i + 6];
        if xfrc.iter().all(|&x| x == 0.0) || !c.shows(CAT_DECOR) {
            continue;
        }
        let force: Vec3 = row(xfrc, 0);
        if c.flag(mjtVisFlag_::mjVIS_PERTFORCE) && norm3(&force) > MINVAL {
            let pos: Vec3 = row(d.xipos, i);
            let end = add3(&pos, &scl3(&force, scale));
            let rgba = m.raw.vis.rgba.force;
            out.connector(UNKNOWN, i, CAT_DECOR, GEOM_ARROW, width, (pos, end), rgba)?;
        }
    }
    Ok(())
}

/// Connect and weld constraints as a sphere at each end; distance constraints (contacts
/// marked 3 at the end of the list) as a capsule of their violation.
pub fn equalities(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    if !c.flag(mjtVisFlag_::mjVIS_CONSTRAINT) || !c.shows(CAT_DECOR) || m.raw.neq == 0 {
        return Ok(());
    }
    let obj = mjtObj_::mjOBJ_EQUALITY;
    let show_label = c.label_is(mjtLabel_::mjLABEL_CONSTRAINT);
    let size = [(c.scl * m.raw.vis.scale.constraint) as f64; 3];
    let neqdata = mjNEQDATA;
    for i in 0..m.raw.neq as usize {
        let t = m.eq_type()[i];
        let weld = t == mjtEq_::mjEQ_WELD as i32;
        if m.eq_active()[i] == 0 || !(t == mjtEq_::mjEQ_CONNECT as i32 || weld) {
            continue;
        }
        let (b1, b2) = (m.eq_obj1id()[i] as usize, m.eq_obj2id()[i] as usize);
        let data = &m.eq_data()[neqdata * i..];
        let at = |b: usize, off: usize| {
            add3(
                &mul_mat_vec3(&row(d.xmat, b), &row(&data[off..], 0)),
                &row(d.xpos, b),
            )
        };
        let ends = [
            (at(b1, if weld { 3 } else { 0 }), b1, m.raw.vis.rgba.connect),
            (
                at(b2, if weld { 0 } else { 3 }),
                b2,
                m.raw.vis.rgba.constraint,
            ),
        ];
        for (pos, body, rgba) in ends {
            out.push(obj, i, CAT_DECOR, |g| {
                let mat = &d.xmat[9 * body..];
                init_geom(
                    g,
                    GEOM_SPHERE,
                    Some(&size),
                    Some(&pos),
                    Some(mat),
                    Some(rgba),
                );
                if show_label {
                    label(m, obj, i, g);
                }
                true
            })?;
        }
    }
    let contacts = &d.contact[..d.raw.ncon.max(0) as usize];
    for con in contacts.iter().rev().take_while(|con| con.exclude == 3) {
        let i = (-con.efc_address - 2) as usize;
        let len = con.dist - m.eq_data()[neqdata * i];
        let normal: Vec3 = row(&con.frame, 0);
        let ends = (
            add_scl3(&con.pos, &normal, 0.5 * len),
            add_scl3(&con.pos, &normal, -0.5 * len),
        );
        out.push(obj, i, CAT_DECOR, |g| {
            make_connector(g, GEOM_CAPSULE, size[0], ends.0, ends.1);
            g.rgba = m.raw.vis.rgba.constraint;
            if show_label {
                label(m, obj, i, g);
            }
            true
        })?;
    }
    Ok(())
}

/// Contact points, contact frames and contact forces (whole, or normal and friction).
pub fn contacts(c: &Ctx, d: &Data, out: &mut Out) -> Result<(), Full> {
    let m = &c.m;
    let point = c.flag(mjtVisFlag_::mjVIS_CONTACTPOINT);
    let force = c.flag(mjtVisFlag_::mjVIS_CONTACTFORCE);
    let frame = c.frame_is(mjtFrame_::mjFRAME_CONTACT);
    if !point && !force && !frame {
        return Ok(());
    }
    let scl = m.raw.stat.meansize;
    let (scale, rgba) = (&m.raw.vis.scale, &m.raw.vis.rgba);
    for (i, con) in d.contact[..d.raw.ncon.max(0) as usize].iter().enumerate() {
        // rotation with the contact normal along z
        let mut tmp = [0.0; 9];
        tmp[..6].copy_from_slice(&con.frame[3..]);
        tmp[6..].copy_from_slice(&con.frame[..3]);
        let mat = transpose3(&tmp);
        let included = con.efc_address >= 0;
        if point {
            out.push(UNKNOWN, i, CAT_DECOR, |g| {
                g.r#type = GEOM_CYLINDER;
                let w = (scale.contactwidth as f64 * scl) as f32;
                g.size = [w, w, (scale.contactheight as f64 * scl) as f32];
                g.pos = n2f(&con.pos);
                g.mat = n2f(&mat);
                g.rgba = if included {
                    rgba.contactpoint
                } else {
                    rgba.contactgap
                };
                true
            })?;
        }
        if frame {
            let length = scale.framelength as f64 * scl / 2.0;
            let width = scale.framewidth as f64 * scl / 2.0;
            out.frame(i, con.pos, &mat, length, width)?;
        }
        if !included || !force {
            continue;
        }
        contact_forces(c, d, out, i, con)?;
    }
    Ok(())
}

/// The force arrows of contact `i` (included in the solver).
fn contact_forces(c: &Ctx, d: &Data, out: &mut Out, i: usize, con: &mjContact) -> Result<(), Full> {
    let m = &c.m;
    let mat = transpose3(&con.frame);
    let confrc = contact_force(m, d, i as i32);
    let mut frc = [0.0; 3];
    let n = (con.dim.clamp(0, 3)) as usize;
    frc[..n].copy_from_slice(&confrc[..n]);
    if norm3(&frc) < MINVAL {
        return Ok(());
    }
    let split = c.flag(mjtVisFlag_::mjVIS_CONTACTSPLIT) && con.dim > 1;
    let body1 = m.geom_bodyid()[con.geom1 as usize];
    let body2 = m.geom_bodyid()[con.geom2 as usize];
    let kind = if body1 > 0 && body2 > 0 && !split {
        GEOM_ARROW2
    } else {
        GEOM_ARROW
    };
    let scale = m.raw.vis.map.force as f64 / m.raw.stat.meanmass;
    let width = m.raw.vis.scale.forcewidth as f64 * m.raw.stat.meansize;
    let parts = if split { 1..3 } else { 0..1 };
    let first = parts.start;
    for j in parts {
        let mut vec = [0.0; 3];
        match j {
            0 => mul_mat_vec(&mut vec, &mat, &frc, 3, 3),
            1 => vec = [mat[0] * frc[0], mat[3] * frc[0], mat[6] * frc[0]],
            _ => {
                vec = std::array::from_fn(|r| mat[3 * r + 1] * frc[1] + mat[3 * r + 2] * frc[2]);
            }
        }
        vec = scl3(&vec, scale);
        if body1 > body2 {
            vec = scl3(&vec, crate::math::misc::minus_one());
        }
        let end = add3(&con.pos, &vec);
        out.push(UNKNOWN, i, CAT_DECOR, |g| {
            make_connector(g, kind, width, con.pos, end);
            let rgba = &m.raw.vis.rgba;
            g.rgba = if j == 2 {
                rgba.contactfriction
            } else {
                rgba.contactforce
            };
            if c.label_is(mjtLabel_::mjLABEL_CONTACTFORCE) && j == first {
                let text = crate::runtime::message::format_c(c"%-.3g", &[norm3(&frc)]);
                crate::abi::cstr::set_cstr(&mut g.label, text.as_bytes());
            }
            true
        })?;
    }
    Ok(())
}
