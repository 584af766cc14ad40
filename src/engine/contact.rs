//! Contact constraints: the rows of each included contact in the contact frame
//! (mj_instantiateContact: frictionless, pyramidal edges or elliptic dimensions), their
//! approximate inverse inertia, and the friction-dimension regularisation (impratio, mu).

use super::constraint::add_rows;
use super::jacdif::jac_dif_pair;
use super::support::warning;
use super::{disabled, Data, EngineError, Model, MINVAL};
use crate::abi::view::Arena;
use crate::abi::*;
use crate::math::blas::{add_scl, mul_mat_mat};
use crate::math::misc::max;
use mjtConstraint_::*;

pub const FRICTIONLESS: i32 = mjCNSTR_CONTACT_FRICTIONLESS as i32;
pub const PYRAMIDAL: i32 = mjCNSTR_CONTACT_PYRAMIDAL as i32;
pub const ELLIPTIC: i32 = mjCNSTR_CONTACT_ELLIPTIC as i32;

/// Is this constraint type a contact row?
pub fn is_contact(kind: i32) -> bool {
    kind == FRICTIONLESS || kind == PYRAMIDAL || kind == ELLIPTIC
}

/// Rows of every contact not excluded; stops with the buffer-full warning when the next
/// contact's rows do not fit.
#[inline]
pub fn instantiate(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    if disabled(m, mjtDisableBit_::mjDSBL_CONTACT) || d.raw.ncon <= 0 {
        return Ok(());
    }
    contact_rows(m, d, a)
}

#[inline(never)]
fn contact_rows(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let ncon = d.raw.ncon.max(0) as usize;
    let nv = m.raw.nv as usize;
    let pyramid = super::constraint::is_pyramidal(m);
    let sparse = super::constraint::is_sparse(m);
    // 2.2.2's 24 nv (+ nv for the sparse chain); the pyramid edges reuse the difference
    let jac = a.alloc_stale(6 * nv)?;
    let jacdif = a.alloc_stale(6 * nv)?;
    let jac1 = a.alloc_stale(6 * nv)?;
    let jac2 = a.alloc_stale(6 * nv)?;
    let chain: &mut [i32] = if sparse { a.alloc_int(nv)? } else { &mut [] };
    for i in 0..ncon {
        if d.contact[i].exclude != 0 {
            continue;
        }
        // the fields used below (the whole contact is a large copy)
        let con = {
            let c = &d.contact[i];
            Fields {
                dim: c.dim,
                geom1: c.geom1,
                geom2: c.geom2,
                pos: c.pos,
                frame: c.frame,
                dist: c.dist,
                includemargin: c.includemargin,
                friction: c.friction,
            }
        };
        let dim = con.dim.clamp(1, 6) as usize;
        let b1 = m.geom_bodyid()[con.geom1 as usize] as usize;
        let b2 = m.geom_bodyid()[con.geom2 as usize] as usize;
        let need = if dim == 1 {
            1
        } else if pyramid {
            2 * (dim - 1)
        } else {
            dim
        };
        if d.raw.nefc as usize + need > m.raw.njmax.max(0) as usize {
            warning(d.raw, mjtWarning_::mjWARN_CNSTRFULL as i32, m.raw.njmax)?;
            break;
        }
        d.contact[i].efc_address = d.raw.nefc;
        let n = jac_dif_pair(
            m,
            d.cdof,
            d.subtree_com,
            chain,
            b1,
            b2,
            &con.pos,
            &con.pos,
            jac1,
            jac2,
            jacdif,
            dim > 3,
        );
        if n == 0 {
            d.contact[i].efc_address = -1;
            d.contact[i].exclude = 4;
            continue;
        }
        // the difference Jacobian in the contact frame: normal, tangents, then rotations
        mul_mat_mat(
            jac,
            &con.frame,
            &jacdif[..3 * n],
            if dim > 1 { 3 } else { 1 },
            3,
            n,
        );
        if dim > 3 {
            let (_, rot) = jacdif.split_at(3 * nv);
            mul_mat_mat(&mut jac[3 * n..], &con.frame, &rot[..3 * n], dim - 3, 3, n);
        }
        let ch = if sparse { Some(&chain[..n]) } else { None };
        if dim == 1 {
            let (p, mg) = ([con.dist], [con.includemargin]);
            add_rows(m, d, jac, ch, Some(&p), Some(&mg), 0.0, 1, FRICTIONLESS, i)?;
        } else if pyramid {
            let (p, mg) = ([con.dist; 2], [con.includemargin; 2]);
            for k in 1..dim {
                let mu = con.friction[k - 1];
                let (first, second) = jacdif.split_at_mut(n);
                add_scl(first, &jac[..n], &jac[k * n..(k + 1) * n], mu);
                add_scl(&mut second[..n], &jac[..n], &jac[k * n..(k + 1) * n], -mu);
                add_rows(m, d, jacdif, ch, Some(&p), Some(&mg), 0.0, 2, PYRAMIDAL, i)?;
            }
        } else {
            let (mut p, mut mg) = ([0.0; 6], [0.0; 6]);
            p[0] = con.dist;
            mg[0] = con.includemargin;
            add_rows(m, d, jac, ch, Some(&p), Some(&mg), 0.0, dim, ELLIPTIC, i)?;
        }
    }
    Ok(())
}

/// The fields of a contact that its constraint rows read.
struct Fields {
    dim: i32,
    geom1: i32,
    geom2: i32,
    pos: [f64; 3],
    frame: [f64; 9],
    dist: f64,
    includemargin: f64,
    friction: [f64; 5],
}

/// diagApprox of the contact rows starting at row i; returns how many rows it set.
pub fn diag_approx(m: &Model, d: &mut Data, i: usize) -> usize {
    let con = &d.contact[d.efc_id[i] as usize];
    let iw = m.body_invweight0();
    let b1 = m.geom_bodyid()[con.geom1 as usize] as usize;
    let b2 = m.geom_bodyid()[con.geom2 as usize] as usize;
    let (dim, friction) = (con.dim as usize, con.friction);
    let tran = iw[2 * b1] + iw[2 * b2];
    let rot = iw[2 * b1 + 1] + iw[2 * b2 + 1];
    match d.efc_type[i] {
        FRICTIONLESS => {
            d.efc_diagApprox[i] = tran;
            1
        }
        ELLIPTIC => {
            for j in 0..dim {
                d.efc_diagApprox[i + j] = if j < 3 { tran } else { rot };
            }
            dim
        }
        _ => {
            for j in 0..dim - 1 {
                let f = friction[j];
                let v = tran + f * f * if j < 2 { tran } else { rot };
                d.efc_diagApprox[i + 2 * j] = v;
                d.efc_diagApprox[i + 2 * j + 1] = v;
            }
            2 * (dim - 1)
        }
    }
}

/// Rows of the contact constraint starting at row i (elliptic: dim, pyramidal: 2(dim-1)).
pub fn rows(d: &Data, i: usize) -> usize {
    let dim = d.contact[d.efc_id[i] as usize].dim as usize;
    match d.efc_type[i] {
        ELLIPTIC => dim,
        PYRAMIDAL => 2 * (dim - 1),
        _ => 1,
    }
}

/// Friction regularisation after the impedance: R of the first friction dimension is the
/// normal's divided by impratio, the contact's mu follows; elliptic dimensions scale by the
/// friction ratios, pyramid edges share one R.
pub fn friction_regularization(m: &Model, d: &mut Data) {
    let nefc = d.raw.nefc as usize;
    let mut i = (d.raw.ne + d.raw.nf) as usize;
    while i < nefc {
        let kind = d.efc_type[i];
        if kind != PYRAMIDAL && kind != ELLIPTIC {
            i += 1;
            continue;
        }
        let id = d.efc_id[i] as usize;
        let dim = d.contact[id].dim as usize;
        let friction = d.contact[id].friction;
        d.efc_R[i + 1] = d.efc_R[i] / max(MINVAL, m.raw.opt.impratio);
        let mu = friction[0] * (d.efc_R[i + 1] / d.efc_R[i]).sqrt();
        d.contact[id].mu = mu;
        if kind == ELLIPTIC {
            for j in 1..dim - 1 {
                d.efc_R[i + j + 1] =
                    d.efc_R[i + 1] * friction[0] * friction[0] / (friction[j] * friction[j]);
            }
            i += dim;
        } else {
            let r = 2.0 * mu * mu * d.efc_R[i];
            for j in 0..2 * (dim - 1) {
                d.efc_R[i + j] = r;
            }
            i += 2 * (dim - 1);
        }
    }
}
