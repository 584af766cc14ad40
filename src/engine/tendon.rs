//! Tendon lengths, Jacobians and wrap paths (mj_tendon): fixed tendons over joints, spatial
//! tendons through sites, around sphere and cylinder geoms, and split by pulleys.

use super::jacdif::{is_sparse, jac_dif_pair};
use super::jacobian::jac;
use super::{Data, EngineError, Model};
use crate::abi::mjtWrap_::*;
use crate::math::blas::{add_to_scl, mul_mat_t_vec, mul_mat_vec, sub};
use crate::math::misc::round;
use crate::math::sparse::{combine_sparse, mul_mat_vec_sparse};
use crate::math::wrap::wrap;
use crate::math::*;

const WRAP_NONE: i32 = mjWRAP_NONE as i32;
const WRAP_JOINT: i32 = mjWRAP_JOINT as i32;
const WRAP_PULLEY: i32 = mjWRAP_PULLEY as i32;
const WRAP_SPHERE: i32 = mjWRAP_SPHERE as i32;
const WRAP_CYLINDER: i32 = mjWRAP_CYLINDER as i32;

/// Sorts a sparse row by column (insertion sort, stable like the reference's).
fn sort_row(ind: &mut [i32], val: &mut [f64]) {
    for k in 1..ind.len() {
        let (x, y) = (ind[k], val[k]);
        let mut j = k;
        while j > 0 && ind[j - 1] > x {
            ind[j] = ind[j - 1];
            val[j] = val[j - 1];
            j -= 1;
        }
        ind[j] = x;
        val[j] = y;
    }
}

/// ten_length, ten_J (dense, or sparse rows), ten_wrapadr/num, wrap_obj, wrap_xpos.
#[inline]
pub fn tendon(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if m.raw.ntendon == 0 {
        return Ok(());
    }
    tendon_paths(m, d)
}

#[inline(never)]
fn tendon_paths(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nten = m.raw.ntendon as usize;
    let nv = m.raw.nv as usize;
    let sparse = is_sparse(m);
    let (wtype, wobj, wprm) = (m.wrap_type(), m.wrap_objid(), m.wrap_prm());
    let site = |xpos: &[f64], id: usize| v3(&xpos[3 * id..]);

    d.arena.scope(|a| -> Result<(), EngineError> {
        let jac1 = a.alloc(3 * nv)?;
        let jac2 = a.alloc(3 * nv)?;
        let jacdif = a.alloc(3 * nv)?;
        let tmp = a.alloc(nv)?;
        let n = if sparse { nv } else { 0 };
        let chain = a.alloc_int(n)?;
        let buf_ind = a.alloc_int(n)?;
        let buf = a.alloc(n)?;

        d.ten_length.fill(0.0);
        if sparse {
            d.ten_J_rownnz.fill(0);
        } else {
            d.ten_J[..nten * nv].fill(0.0);
        }
        let mut wcnt = 0usize;

        for i in 0..nten {
            let adr = m.tendon_adr()[i] as usize;
            let num = m.tendon_num()[i] as usize;
            d.ten_wrapadr[i] = wcnt as i32;
            d.ten_wrapnum[i] = 0;
            if sparse {
                d.ten_J_rowadr[i] = if i > 0 {
                    d.ten_J_rowadr[i - 1] + d.ten_J_rownnz[i - 1]
                } else {
                    0
                };
            }
            let ra = if sparse {
                d.ten_J_rowadr[i] as usize
            } else {
                i * nv
            };

            // fixed tendon: linear in the joint positions
            if wtype[adr] == WRAP_JOINT {
                for j in adr..adr + num {
                    let k = wobj[j] as usize;
                    let coef = wprm[j];
                    d.ten_length[i] += coef * d.qpos[m.jnt_qposadr()[k] as usize];
                    let dof = m.jnt_dofadr()[k];
                    if sparse {
                        let p = ra + d.ten_J_rownnz[i] as usize;
                        d.ten_J[p] = coef;
                        d.ten_J_colind[p] = dof;
                        d.ten_J_rownnz[i] += 1;
                    } else {
                        d.ten_J[ra + dof as usize] = coef;
                    }
                }
                if sparse {
                    let nnz = d.ten_J_rownnz[i] as usize;
                    sort_row(
                        &mut d.ten_J_colind[ra..ra + nnz],
                        &mut d.ten_J[ra..ra + nnz],
                    );
                }
                continue;
            }

            // spatial tendon: straight segments between sites, possibly wrapped around a geom
            let mut divisor = 1.0;
            let mut j = 0;
            while j + 1 < num {
                let (tp0, id0) = (wtype[adr + j], wobj[adr + j] as usize);
                let (tp1, mut id1) = (wtype[adr + j + 1], wobj[adr + j + 1] as usize);

                if tp0 == WRAP_PULLEY || tp1 == WRAP_PULLEY {
                    if tp0 == WRAP_PULLEY {
                        divisor = wprm[adr + j];
                        d.wrap_xpos[3 * wcnt..3 * wcnt + 3].fill(0.0);
                        d.wrap_obj[wcnt] = -2;
                        d.ten_wrapnum[i] += 1;
                        wcnt += 1;
                    }
                    j += 1;
                    continue;
                }

                let mut wpnt = [0.0; 12];
                let mut wbody = [0usize; 4];
                wpnt[..3].copy_from_slice(&site(d.site_xpos, id0));
                wbody[0] = m.site_bodyid()[id0] as usize;

                // site-geom-site: up to two tangent points on the geom
                let mut wrapped: Option<f64> = None;
                let mut tpw = WRAP_NONE;
                let mut idw = 0;
                if tp1 == WRAP_SPHERE || tp1 == WRAP_CYLINDER {
                    tpw = tp1;
                    idw = id1;
                    id1 = wobj[adr + j + 2] as usize;
                    let sideid = round(wprm[adr + j + 1]);
                    if sideid < -1 || sideid >= m.raw.nsite {
                        return Err(EngineError(format!("Invalid sideid {sideid} in wrap_prm")));
                    }
                    let side = (sideid >= 0).then(|| site(d.site_xpos, sideid as usize));
                    let gpos = v3(&d.geom_xpos[3 * idw..]);
                    let gmat: Mat3 = arr(&d.geom_xmat[9 * idw..9 * idw + 9]);
                    if let Some((len, pts)) = wrap(
                        &site(d.site_xpos, id0),
                        &site(d.site_xpos, id1),
                        &gpos,
                        &gmat,
                        m.geom_size()[3 * idw],
                        tpw == WRAP_CYLINDER,
                        side.as_ref(),
                    ) {
                        wpnt[3..9].copy_from_slice(&pts);
                        wrapped = Some(len);
                    }
                }

                let end = site(d.site_xpos, id1);
                let nseg = match wrapped {
                    None => {
                        wpnt[3..6].copy_from_slice(&end);
                        wbody[1] = m.site_bodyid()[id1] as usize;
                        d.ten_length[i] += dist3(&v3(&wpnt), &v3(&wpnt[3..])) / divisor;
                        1
                    }
                    Some(wlen) => {
                        wpnt[9..12].copy_from_slice(&end);
                        wbody[1] = m.geom_bodyid()[idw] as usize;
                        wbody[2] = wbody[1];
                        wbody[3] = m.site_bodyid()[id1] as usize;
                        d.ten_length[i] += (dist3(&v3(&wpnt), &v3(&wpnt[3..]))
                            + wlen
                            + dist3(&v3(&wpnt[6..]), &v3(&wpnt[9..])))
                            / divisor;
                        3
                    }
                };

                // Jacobian of each segment whose end points move with different bodies
                for k in 0..nseg {
                    if wbody[k] == wbody[k + 1] {
                        continue;
                    }
                    let p0 = v3(&wpnt[3 * k..]);
                    let p1 = v3(&wpnt[3 * k + 3..]);
                    let dif = normalize3(&sub3(&p1, &p0)).0;
                    if sparse {
                        let nc = jac_dif_pair(
                            m,
                            d.cdof,
                            d.subtree_com,
                            chain,
                            wbody[k],
                            wbody[k + 1],
                            &p0,
                            &p1,
                            jac1,
                            jac2,
                            jacdif,
                            false,
                        );
                        if nc == 0 {
                            continue;
                        }
                        mul_mat_t_vec(tmp, jacdif, &dif, 3, nc);
                        let nnz = combine_sparse(
                            &mut d.ten_J[ra..],
                            tmp,
                            nv,
                            1.0,
                            1.0 / divisor,
                            d.ten_J_rownnz[i] as usize,
                            nc,
                            &mut d.ten_J_colind[ra..],
                            &chain[..nc],
                            buf,
                            buf_ind,
                        );
                        d.ten_J_rownnz[i] = nnz as i32;
                    } else {
                        jac(
                            m,
                            d.cdof,
                            d.subtree_com,
                            &p0,
                            wbody[k],
                            Some(&mut *jac1),
                            None,
                        );
                        jac(
                            m,
                            d.cdof,
                            d.subtree_com,
                            &p1,
                            wbody[k + 1],
                            Some(&mut *jac2),
                            None,
                        );
                        sub(jacdif, jac2, jac1);
                        mul_mat_t_vec(tmp, jacdif, &dif, 3, nv);
                        add_to_scl(&mut d.ten_J[ra..ra + nv], tmp, 1.0 / divisor);
                    }
                }

                // path points: the start site, and the two tangent points when wrapped
                let npnt = if wrapped.is_some() { 3 } else { 1 };
                d.wrap_xpos[3 * wcnt..3 * (wcnt + npnt)].copy_from_slice(&wpnt[..3 * npnt]);
                d.wrap_obj[wcnt] = -1;
                if npnt == 3 {
                    d.wrap_obj[wcnt + 1] = idw as i32;
                    d.wrap_obj[wcnt + 2] = idw as i32;
                }
                d.ten_wrapnum[i] += npnt as i32;
                wcnt += npnt;

                j += if tpw != WRAP_NONE { 2 } else { 1 };

                // the last site before a pulley or the end of the tendon
                if j + 1 == num || (j + 1 < num && wtype[adr + j + 1] == WRAP_PULLEY) {
                    d.wrap_xpos[3 * wcnt..3 * wcnt + 3].copy_from_slice(&end);
                    d.wrap_obj[wcnt] = -1;
                    d.ten_wrapnum[i] += 1;
                    wcnt += 1;
                }
            }
        }
        Ok(())
    })
}

/// ten_velocity = ten_J * qvel, dense or sparse.
pub fn tendon_velocity(m: &Model, d: &mut Data) {
    let nten = m.raw.ntendon as usize;
    if is_sparse(m) {
        mul_mat_vec_sparse(
            d.ten_velocity,
            d.ten_J,
            d.qvel,
            nten,
            d.ten_J_rownnz,
            d.ten_J_rowadr,
            d.ten_J_colind,
            None,
        );
    } else {
        mul_mat_vec(d.ten_velocity, d.ten_J, d.qvel, nten, m.raw.nv as usize);
    }
}
