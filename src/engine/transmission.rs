//! Actuator transmissions: lengths and moment arms (joint, joint-in-parent, slider-crank,
//! tendon, site with and without reference site, body adhesion).

use super::jacdif::{is_sparse, jac_dif_pair};
use super::jacobian::jac;
use super::{Data, EngineError, Model, JNT_BALL, JNT_HINGE, JNT_SLIDE};
use crate::abi::view::Arena;
use crate::abi::{mjtCone_, mjtTrn_};
use crate::math::blas::{add_to, mul_mat_mat, mul_mat_t_vec, scl, scl_in_place, sub_from};
use crate::math::misc::is_zero;
use crate::math::*;

const TRN_JOINT: i32 = mjtTrn_::mjTRN_JOINT as i32;
const TRN_JOINTINPARENT: i32 = mjtTrn_::mjTRN_JOINTINPARENT as i32;
const TRN_SLIDERCRANK: i32 = mjtTrn_::mjTRN_SLIDERCRANK as i32;
const TRN_TENDON: i32 = mjtTrn_::mjTRN_TENDON as i32;
const TRN_SITE: i32 = mjtTrn_::mjTRN_SITE as i32;
const TRN_BODY: i32 = mjtTrn_::mjTRN_BODY as i32;

/// Scratch of mj_transmission, taken from the stack as 2.2.2 takes it: three 3 x nv Jacobians
/// for the whole call, then, kept to the end once taken, the reference-site Jacobian and the
/// rotational moment (site transmissions with a reference site) and the body-transmission
/// buffers.
struct Scratch<'s> {
    jac: &'s mut [f64],
    jac_a: &'s mut [f64],
    jac_s: &'s mut [f64],
    jac_ref: Option<&'s mut [f64]>,
    moment_tmp: Option<&'s mut [f64]>,
    body: Option<BodyScratch<'s>>,
}

/// The body transmission's buffers: contact markers over the rows, the moment of excluded
/// contacts, the Jacobian difference and the two Jacobians (3 x nv), the sparse chain.
struct BodyScratch<'s> {
    efc_force: &'s mut [f64],
    exclude: &'s mut [f64],
    jacdif: &'s mut [f64],
    jac1: &'s mut [f64],
    jac2: &'s mut [f64],
    chain: &'s mut [i32],
}

/// The kinematic quantities the Jacobian-based transmissions read.
struct Kin<'k> {
    site_xpos: &'k [f64],
    site_xmat: &'k [f64],
    xquat: &'k [f64],
    cdof: &'k [f64],
    subtree_com: &'k [f64],
}

/// actuator_length and actuator_moment (mj_transmission).
#[inline]
pub fn transmission(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if m.raw.nu == 0 {
        return Ok(());
    }
    actuator_transmission(m, d)
}

#[inline(never)]
fn actuator_transmission(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nu = m.raw.nu as usize;
    let nv = m.raw.nv as usize;
    let trntype = &m.actuator_trntype()[..nu];
    if trntype
        .iter()
        .all(|&t| matches!(t, TRN_JOINT | TRN_JOINTINPARENT | TRN_TENDON))
    {
        // no scratch needed: the common case of motors on joints and tendons (the stack
        // still counts the three Jacobians 2.2.2 takes)
        d.arena.account(9 * nv)?;
        clear_moments(m, d);
        for (i, &t) in trntype.iter().enumerate() {
            if t == TRN_TENDON {
                tendon(m, d, i);
            } else {
                joint(m, d, i);
            }
        }
        return Ok(());
    }
    super::constraint::with_arena(d, |d, a| -> Result<(), EngineError> {
        let mut s = Scratch {
            // written whole before they are read (not cleared, as in 2.2.2)
            jac: a.alloc_stale(3 * nv)?,
            jac_a: a.alloc_stale(3 * nv)?,
            jac_s: a.alloc_stale(3 * nv)?,
            jac_ref: None,
            moment_tmp: None,
            body: None,
        };
        clear_moments(m, d);
        for i in 0..nu {
            let t = m.actuator_trntype()[i];
            match t {
                TRN_JOINT | TRN_JOINTINPARENT => joint(m, d, i),
                TRN_TENDON => tendon(m, d, i),
                TRN_BODY => body(m, d, a, &mut s, i)?,
                TRN_SLIDERCRANK | TRN_SITE => {
                    let k = Kin {
                        site_xpos: d.site_xpos,
                        site_xmat: d.site_xmat,
                        xquat: d.xquat,
                        cdof: d.cdof,
                        subtree_com: d.subtree_com,
                    };
                    let moment = &mut d.actuator_moment[i * nv..(i + 1) * nv];
                    d.actuator_length[i] = if t == TRN_SITE {
                        site(m, &k, a, &mut s, i, moment)?
                    } else {
                        slider_crank(m, &k, a, &mut s, i, moment)?
                    };
                }
                _ => return Err(EngineError(format!("Unknown transmission type {t}"))),
            }
        }
        Ok(())
    })
}

/// Zeroes actuator_moment for the transmissions to write into: of a joint actuator's row,
/// which `joint` writes in its joint's columns, the columns the last call wrote (as
/// `Data::moments` records) where they were others; the other rows whole; the whole matrix
/// where the record is not known (a reset, a copy, a data's first step, a failed call). The
/// rows are 2.2.2's: zero but where written.
fn clear_moments(m: &Model, d: &mut Data) {
    let nv = m.raw.nv as usize;
    let nu = m.raw.nu as usize;
    let (moment, rec) = d.moments();
    let known = std::mem::take(rec.known);
    if !known {
        moment.fill(0.0);
    }
    if rec.spans.len() != nu {
        return;
    }
    for (i, (row, span)) in moment
        .chunks_exact_mut(nv.max(1))
        .zip(rec.spans.iter_mut())
        .enumerate()
    {
        let on_joint = matches!(m.actuator_trntype()[i], TRN_JOINT | TRN_JOINTINPARENT);
        let (lo, hi) = if on_joint {
            joint_columns(m, i)
        } else {
            (0, nv)
        };
        if known {
            let (a, b) = (span[0] as usize, span[1] as usize);
            if !on_joint {
                row.fill(0.0);
            } else if (a, b) != (lo, hi) {
                // `joint` writes its own columns whole
                row[a.min(b).min(nv)..b.min(nv)].fill(0.0);
            }
        }
        *span = [lo as u32, hi as u32];
    }
    *rec.known = true;
}

/// The columns `lo..hi` of actuator `i`'s moment row that `transmission` may set (the rest
/// it leaves zero): the joint's dofs, the tendon's sparse Jacobian columns, else all.
/// `ten_j`: the sparse tendon Jacobian's rownnz, rowadr and colind.
pub fn moment_span(m: &Model, ten_j: (&[i32], &[i32], &[i32]), i: usize) -> (usize, usize) {
    let nv = m.raw.nv as usize;
    let id = m.actuator_trnid()[2 * i] as usize;
    match m.actuator_trntype()[i] {
        TRN_JOINT | TRN_JOINTINPARENT => joint_columns(m, i),
        TRN_TENDON if is_sparse(m) => {
            let (rownnz, rowadr, colind) = ten_j;
            let adr = rowadr[id] as usize;
            let cols = &colind[adr..adr + rownnz[id] as usize];
            match (cols.iter().min(), cols.iter().max()) {
                (Some(&lo), Some(&hi)) => (lo as usize, hi as usize + 1),
                _ => (0, 0),
            }
        }
        _ => (0, nv),
    }
}

/// The dofs of the joint of joint actuator `i`: the columns its moment row may set.
fn joint_columns(m: &Model, i: usize) -> (usize, usize) {
    let id = m.actuator_trnid()[2 * i] as usize;
    let dadr = m.jnt_dofadr()[id] as usize;
    let ndof = match m.jnt_type()[id] {
        JNT_SLIDE | JNT_HINGE => 1,
        JNT_BALL => 3,
        _ => 6,
    };
    (dadr, dadr + ndof)
}

/// Slider-crank: length of the slider along its axis, with its derivatives; returns length.
fn slider_crank(
    m: &Model,
    k: &Kin,
    a: &mut Arena,
    s: &mut Scratch,
    i: usize,
    moment: &mut [f64],
) -> Result<f64, EngineError> {
    let nv = m.raw.nv as usize;
    let id = m.actuator_trnid()[2 * i] as usize;
    let ids = m.actuator_trnid()[2 * i + 1] as usize;
    let gear = m.actuator_gear()[6 * i];
    let rod = m.actuator_cranklength()[i];
    let mat = &k.site_xmat[9 * ids..9 * ids + 9];
    let axis = [mat[2], mat[5], mat[8]];
    let spos = v3(&k.site_xpos[3 * ids..]);
    let vec = sub3(&v3(&k.site_xpos[3 * id..]), &spos);

    // length = a'v - sqrt(det), det = (a'v)^2 + r^2 - v'v
    let av = dot3(&vec, &axis);
    let det = av * av + rod * rod - dot3(&vec, &vec);
    let (length, dlda, dldv) = if det <= 0.0 {
        (av, vec, axis)
    } else {
        let sdet = det.sqrt();
        let dldv = add3(&scl3(&axis, 1.0 - av / sdet), &scl3(&vec, 1.0 / sdet));
        (av - sdet, scl3(&vec, 1.0 - av / sdet), dldv)
    };

    // Jacobians of the slider axis (jac_a) and of vec (jac)
    // mj_jacPointAxis takes its rotation Jacobian from the stack for the call
    a.scope(|a| -> Result<(), EngineError> {
        let jacr = a.alloc(3 * nv)?;
        point_axis(m, k, s, jacr, &spos, &axis, m.site_bodyid()[ids] as usize);
        Ok(())
    })?;
    let pos = v3(&k.site_xpos[3 * id..]);
    jac(
        m,
        k.cdof,
        k.subtree_com,
        &pos,
        m.site_bodyid()[id] as usize,
        Some(&mut *s.jac),
        None,
    );
    sub_from(s.jac, s.jac_s);

    for j in 0..nv {
        for r in 0..3 {
            moment[j] += dlda[r] * s.jac_a[r * nv + j] + dldv[r] * s.jac[r * nv + j];
        }
    }
    for v in moment.iter_mut() {
        *v *= gear;
    }
    Ok(length * gear)
}

/// Point Jacobian into `s.jac_s` and the axis Jacobian into `s.jac_a` (mj_jacPointAxis).
fn point_axis(
    m: &Model,
    k: &Kin,
    s: &mut Scratch,
    jacr: &mut [f64],
    point: &Vec3,
    axis: &Vec3,
    body: usize,
) {
    let nv = m.raw.nv as usize;
    jac(
        m,
        k.cdof,
        k.subtree_com,
        point,
        body,
        Some(&mut *s.jac_s),
        Some(&mut *jacr),
    );
    for j in 0..nv {
        let c = cross(&[jacr[j], jacr[nv + j], jacr[2 * nv + j]], axis);
        for r in 0..3 {
            s.jac_a[r * nv + j] = c[r];
        }
    }
}

/// Tendon transmission: the tendon's length and Jacobian scaled by the gear.
fn tendon(m: &Model, d: &mut Data, i: usize) {
    let nv = m.raw.nv as usize;
    let id = m.actuator_trnid()[2 * i] as usize;
    let gear = m.actuator_gear()[6 * i];
    d.actuator_length[i] = d.ten_length[id] * gear;
    let moment = &mut d.actuator_moment[i * nv..(i + 1) * nv];
    if is_sparse(m) {
        let adr = d.ten_J_rowadr[id] as usize;
        for j in adr..adr + d.ten_J_rownnz[id] as usize {
            moment[d.ten_J_colind[j] as usize] = d.ten_J[j] * gear;
        }
    } else {
        scl(moment, &d.ten_J[id * nv..(id + 1) * nv], gear);
    }
}

/// Site transmission: wrench gear in the site frame, or the site's pose relative to a
/// reference site; returns the length.
fn site<'s>(
    m: &Model,
    k: &Kin,
    a: &mut Arena<'s>,
    s: &mut Scratch<'s>,
    i: usize,
    moment: &mut [f64],
) -> Result<f64, EngineError> {
    let nv = m.raw.nv as usize;
    let id = m.actuator_trnid()[2 * i] as usize;
    let refid = m.actuator_trnid()[2 * i + 1];
    let gear = &m.actuator_gear()[6 * i..6 * i + 6];
    let (gt, gr) = (v3(gear), v3(&gear[3..]));
    let body = |sid: usize| m.site_bodyid()[sid] as usize;
    let pos = |sid: usize| v3(&k.site_xpos[3 * sid..]);
    let xmat = |sid: usize| -> Mat3 { arr(&k.site_xmat[9 * sid..9 * sid + 9]) };
    let (cdof, com) = (k.cdof, k.subtree_com);
    jac(
        m,
        cdof,
        com,
        &pos(id),
        body(id),
        Some(&mut *s.jac),
        Some(&mut *s.jac_s),
    );

    if refid < 0 {
        let wt = mul_mat_vec3(&xmat(id), &gt);
        let wr = mul_mat_vec3(&xmat(id), &gr);
        mul_mat_t_vec(moment, s.jac, &wt, 3, nv);
        mul_mat_t_vec(s.jac, s.jac_s, &wr, 3, nv);
        add_to(moment, &s.jac[..nv]);
        return Ok(0.0);
    }

    let refid = refid as usize;
    if s.jac_ref.is_none() {
        s.jac_ref = Some(a.alloc(3 * nv)?);
    }
    let rmat = xmat(refid);
    let mut length = 0.0;
    if !is_zero(&gt) {
        let vec = mul_mat_t_vec3(&rmat, &sub3(&pos(id), &pos(refid)));
        length += dot3(&vec, &gt);
        jac(
            m,
            cdof,
            com,
            &pos(refid),
            body(refid),
            s.jac_ref.as_deref_mut(),
            None,
        );
        sub_from(s.jac, s.jac_ref.as_deref().unwrap_or(&[]));
        mul_mat_t_vec(moment, s.jac, &mul_mat_vec3(&rmat, &gt), 3, nv);
    }
    if !is_zero(&gr) {
        let quat = |sid: usize| {
            let b = body(sid);
            mul_quat(&q4(&m.site_quat()[4 * sid..]), &q4(&k.xquat[4 * b..]))
        };
        let vec = sub_quat(&quat(id), &quat(refid));
        length += dot3(&vec, &gr);
        jac(
            m,
            cdof,
            com,
            &pos(refid),
            body(refid),
            None,
            s.jac_ref.as_deref_mut(),
        );
        sub_from(s.jac_s, s.jac_ref.as_deref().unwrap_or(&[]));
        if s.moment_tmp.is_none() {
            s.moment_tmp = Some(a.alloc(nv)?);
        }
        let tmp = s.moment_tmp.as_deref_mut().unwrap_or(&mut []);
        mul_mat_t_vec(tmp, s.jac_s, &mul_mat_vec3(&rmat, &gr), 3, nv);
        add_to(moment, tmp);
    }
    Ok(length)
}

/// Body (adhesion) transmission: the moment is minus the average of the normal Jacobians of
/// the body's contacts (active contacts through efc_J, contacts in the margin gap directly).
fn body<'s>(
    m: &Model,
    d: &mut Data,
    a: &mut Arena<'s>,
    s: &mut Scratch<'s>,
    i: usize,
) -> Result<(), EngineError> {
    let id = m.actuator_trnid()[2 * i];
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc.max(0) as usize;
    let ncon = d.raw.ncon.max(0) as usize;
    let elliptic = m.raw.opt.cone == mjtCone_::mjCONE_ELLIPTIC as i32;
    let sparse = is_sparse(m);
    d.actuator_length[i] = 0.0;
    // 2.2.2 keeps the first body transmission's buffers for the next ones, marked by the rows'
    // buffer, which it does not get without rows (an empty allocation): then every body
    // transmission takes new ones
    if s.body.is_none() || nefc == 0 {
        s.body = Some(BodyScratch {
            efc_force: a.alloc(nefc)?,
            exclude: a.alloc(nv)?,
            jacdif: a.alloc(3 * nv)?,
            jac1: a.alloc(3 * nv)?,
            jac2: a.alloc(3 * nv)?,
            chain: if sparse { a.alloc_int(nv)? } else { &mut [] },
        });
    }
    let Some(b) = s.body.as_mut() else {
        return Ok(());
    };
    // the normal projection goes to the first row of jac, as in 2.2.2
    let normal = &mut s.jac[..nv];
    let efc_force = &mut *b.efc_force;
    efc_force.fill(0.0);
    b.exclude.fill(0.0);
    let mut counter = 0;
    for c in d.contact.iter().take(ncon) {
        let b1 = m.geom_bodyid()[c.geom1 as usize];
        let b2 = m.geom_bodyid()[c.geom2 as usize];
        if b1 != id && b2 != id {
            continue;
        }
        if c.exclude == 0 {
            counter += 1;
            let adr = c.efc_address.max(0) as usize;
            if c.dim == 1 || elliptic {
                if let Some(f) = efc_force.get_mut(adr) {
                    *f = 1.0;
                }
            } else {
                let npyramid = (c.dim - 1) as usize;
                for f in efc_force.iter_mut().skip(adr).take(2 * npyramid) {
                    *f = 0.5 / npyramid as f64;
                }
            }
        } else if c.exclude == 1 {
            counter += 1;
            let n = jac_dif_pair(
                m,
                d.cdof,
                d.subtree_com,
                b.chain,
                b1 as usize,
                b2 as usize,
                &c.pos,
                &c.pos,
                b.jac1,
                b.jac2,
                b.jacdif,
                false,
            );
            mul_mat_mat(normal, &c.frame[..3], b.jacdif, 1, 3, n);
            if sparse {
                for k in 0..n {
                    b.exclude[b.chain[k] as usize] += normal[k];
                }
            } else {
                add_to(b.exclude, &normal[..nv]);
            }
        }
    }
    if counter > 0 {
        let moment = &mut d.actuator_moment[i * nv..(i + 1) * nv];
        super::constraint::jac_view!(m, d).mul_t_vec(moment, efc_force);
        add_to(moment, b.exclude);
        scl_in_place(moment, -1.0 / counter as f64);
    }
    Ok(())
}

/// Joint transmission: scalar gear for slide/hinge, 3D or 6D wrench gear for ball/free.
fn joint(m: &Model, d: &mut Data, i: usize) {
    let nv = m.raw.nv as usize;
    let id = m.actuator_trnid()[2 * i] as usize;
    let gear = &m.actuator_gear()[6 * i..6 * i + 6];
    let inparent = m.actuator_trntype()[i] == TRN_JOINTINPARENT;
    let moment = &mut d.actuator_moment[i * nv..(i + 1) * nv];
    let qadr = m.jnt_qposadr()[id] as usize;
    let dadr = m.jnt_dofadr()[id] as usize;
    match m.jnt_type()[id] {
        JNT_SLIDE | JNT_HINGE => {
            d.actuator_length[i] = d.qpos[qadr] * gear[0];
            moment[dadr] = gear[0];
        }
        JNT_BALL => {
            let q = q4(&d.qpos[qadr..]);
            let axis = quat2vel(&q, 1.0);
            let g = v3(gear);
            let gear_axis = if inparent {
                rot_vec_quat(&g, &neg_quat(&q))
            } else {
                g
            };
            d.actuator_length[i] = dot3(&axis, &gear_axis);
            moment[dadr..dadr + 3].copy_from_slice(&gear_axis);
        }
        _ => {
            d.actuator_length[i] = 0.0;
            let q = q4(&d.qpos[qadr + 3..]);
            let g = v3(&gear[3..]);
            let gear_axis = if inparent {
                rot_vec_quat(&g, &neg_quat(&q))
            } else {
                g
            };
            moment[dadr..dadr + 3].copy_from_slice(&gear[..3]);
            moment[dadr + 3..dadr + 6].copy_from_slice(&gear_axis);
        }
    }
}
