//! Model constants that depend on qpos0 (mj_setConst): subtree masses, inverse weights,
//! reference lengths, actuator_acc0, dof_M0, camera/light offsets and the statistics.

use super::forward::tendon;
use super::inertia::{crb, factor_m, solve_ld};
use super::jacobian::jac;
use super::kinematics::{camlight, com_pos, kinematics};
use super::linalg::{dot, max, min, mul_mat_mat_t, put, row};
use super::transmission::transmission;
use super::{Data, EngineError, Model, JNT_BALL, JNT_FREE};
use crate::abi::view::ModelMut;
use crate::abi::*;
use crate::math::*;

/// Subtree masses (written first: everything else reads only the model's inputs).
pub fn subtree_mass(mm: &mut ModelMut, nbody: usize) {
    for i in 0..nbody {
        mm.body_subtreemass[i] = mm.body_mass[i];
    }
    for i in (1..nbody).rev() {
        let p = mm.body_parentid[i] as usize;
        mm.body_subtreemass[p] += mm.body_subtreemass[i];
    }
}

/// Everything mj_setConst computes after the subtree masses, for the caller to store.
pub struct Consts {
    pub dof_m0: Vec<f64>,
    pub actuator_length0: Vec<f64>,
    pub tendon_length0: Vec<f64>,
    pub tendon_invweight0: Vec<f64>,
    pub tendon_lengthspring: Vec<f64>,
    pub body_invweight0: Vec<f64>,
    pub dof_invweight0: Vec<f64>,
    pub actuator_acc0: Vec<f64>,
    pub eq_data: Vec<f64>,
    pub cam: Vec<([f64; 3], [f64; 3], [f64; 9])>,
    pub light: Vec<([f64; 3], [f64; 3], [f64; 3])>,
    pub stat: mjStatistic,
}

/// set0, setStat and setSpring of mj_setConst, run in `d`; each of set0 and setStat releases
/// its stack scratch, as in 2.2.2.
pub fn compute(m: &Model, d: &mut Data) -> Result<Consts, EngineError> {
    let nbody = m.raw.nbody as usize;
    let mut c = d.scoped(|d| set0(m, d))?;
    c.stat = d.scoped(|d| -> Result<mjStatistic, EngineError> {
        let body = d.arena.alloc(nbody)?;
        Ok(set_stat(m, d, body))
    })?;

    // setSpring: leave d in qpos_spring, as 2.2.2 does
    d.qpos.copy_from_slice(m.qpos_spring());
    kinematics(m, d)?;
    com_pos(m, d)?;
    tendon(m, d)?;
    transmission(m, d)?;
    c.tendon_lengthspring = (m.tendon_lengthspring().iter().zip(d.ten_length.iter()))
        .map(|(&s, &l)| if s < 0.0 { l } else { s })
        .collect();
    Ok(c)
}

/// set0: the constants at qpos0. Its scratch comes first on the stack (Jacobian and solve
/// buffers, and 2.2.2's saved camera and light modes), the stages run above it. The
/// statistics and the spring lengths are left to the caller.
fn set0(m: &Model, d: &mut Data) -> Result<Consts, EngineError> {
    let (nv, nbody, nu) = (m.raw.nv as usize, m.raw.nbody as usize, m.raw.nu as usize);
    let jacm = d.arena.alloc(6 * nv)?;
    let tmp = d.arena.alloc(6 * nv)?;
    d.arena.alloc_int_stale(m.raw.ncam.max(0) as usize)?;
    d.arena.alloc_int_stale(m.raw.nlight.max(0) as usize)?;
    d.qpos.copy_from_slice(m.qpos0());
    kinematics(m, d)?;
    com_pos(m, d)?;
    camlight(m, d, true);
    crb(m, d, false);
    let dof_m0: Vec<f64> = (0..nv).map(|i| d.qM[m.dof_Madr()[i] as usize]).collect();
    factor_m(m, d)?;
    tendon(m, d)?;
    transmission(m, d)?;
    let actuator_length0 = d.actuator_length.to_vec();
    let tendon_length0 = d.ten_length.to_vec();

    let mut a = [0.0; 36];
    let mut body_invweight0 = vec![0.0; 2 * nbody];
    for i in 1..nbody {
        if nv > 0 {
            let (jp, jr) = jacm.split_at_mut(3 * nv);
            jac(
                m,
                d.cdof,
                d.subtree_com,
                &row(d.xipos, i),
                i,
                Some(jp),
                Some(jr),
            );
            solve_ld(m, tmp, Some(jacm), 6, d.qLD, d.qLDiagInv);
            mul_mat_mat_t(&mut a, jacm, tmp, 6, nv, 6);
        }
        body_invweight0[2 * i] = (a[0] + a[7] + a[14]) / 3.0;
        body_invweight0[2 * i + 1] = (a[21] + a[28] + a[35]) / 3.0;
    }

    let mut dof_invweight0 = vec![0.0; nv];
    for j in 0..m.raw.njnt as usize {
        let id = m.jnt_dofadr()[j] as usize;
        let dnum = match m.jnt_type()[j] {
            JNT_FREE => 6,
            JNT_BALL => 3,
            _ => 1,
        };
        if nv > 0 {
            jacm[..dnum * nv].fill(0.0);
            for k in 0..dnum {
                jacm[k * (nv + 1) + id] = 1.0;
            }
            solve_ld(m, tmp, Some(&jacm[..dnum * nv]), dnum, d.qLD, d.qLDiagInv);
            mul_mat_mat_t(&mut a, jacm, tmp, dnum, nv, dnum);
        }
        match dnum {
            6 => {
                let t = (a[0] + a[7] + a[14]) / 3.0;
                let r = (a[21] + a[28] + a[35]) / 3.0;
                dof_invweight0[id..id + 3].fill(t);
                dof_invweight0[id + 3..id + 6].fill(r);
            }
            3 => dof_invweight0[id..id + 3].fill((a[0] + a[4] + a[8]) / 3.0),
            _ => dof_invweight0[id] = a[0],
        }
    }

    let tendon_invweight0 = tendon_invweight(m, d, tmp)?;

    let mut actuator_acc0 = vec![0.0; nu];
    if nv > 0 {
        for (i, acc0) in actuator_acc0.iter_mut().enumerate() {
            solve_ld(
                m,
                tmp,
                Some(&d.actuator_moment[i * nv..(i + 1) * nv]),
                1,
                d.qLD,
                d.qLDiagInv,
            );
            *acc0 = dot(&tmp[..nv], &tmp[..nv]).sqrt();
        }
    }

    let eq_data = equality_data(m, d);

    let mut cam = Vec::with_capacity(m.raw.ncam as usize);
    for i in 0..m.raw.ncam as usize {
        let id = m.cam_bodyid()[i] as usize;
        let id1 = m.cam_targetbodyid()[i];
        let xp = row::<3>(d.cam_xpos, i);
        let com = row::<3>(d.subtree_com, if id1 >= 0 { id1 as usize } else { id });
        cam.push((
            sub3(&xp, &row(d.xpos, id)),
            sub3(&xp, &com),
            row::<9>(d.cam_xmat, i),
        ));
    }
    let mut light = Vec::with_capacity(m.raw.nlight as usize);
    for i in 0..m.raw.nlight as usize {
        let id = m.light_bodyid()[i] as usize;
        let id1 = m.light_targetbodyid()[i];
        let xp = row::<3>(d.light_xpos, i);
        let com = row::<3>(d.subtree_com, if id1 >= 0 { id1 as usize } else { id });
        light.push((
            sub3(&xp, &row(d.xpos, id)),
            sub3(&xp, &com),
            row::<3>(d.light_xdir, i),
        ));
    }

    Ok(Consts {
        dof_m0,
        actuator_length0,
        tendon_length0,
        tendon_invweight0,
        body_invweight0,
        dof_invweight0,
        actuator_acc0,
        eq_data,
        cam,
        light,
        tendon_lengthspring: Vec::new(),
        stat: mjStatistic {
            meaninertia: 0.0,
            meanmass: 0.0,
            meansize: 0.0,
            extent: 0.0,
            center: [0.0; 3],
        },
    })
}

/// tendon_invweight0 = J M^-1 J' per tendon at qpos0; `tmp` is scratch of 2*nv.
fn tendon_invweight(m: &Model, d: &Data, tmp: &mut [f64]) -> Result<Vec<f64>, EngineError> {
    let nv = m.raw.nv as usize;
    let mut w = m.tendon_invweight0().to_vec();
    if nv == 0 {
        return Ok(w);
    }
    let sparse = super::jacdif::is_sparse(m);
    for (i, wi) in w.iter_mut().enumerate() {
        let (jrow, x) = tmp.split_at_mut(nv);
        if sparse {
            jrow.fill(0.0);
            let adr = d.ten_J_rowadr[i] as usize;
            for j in adr..adr + d.ten_J_rownnz[i] as usize {
                jrow[d.ten_J_colind[j] as usize] = d.ten_J[j];
            }
        } else {
            jrow.copy_from_slice(&d.ten_J[i * nv..(i + 1) * nv]);
        }
        solve_ld(m, x, Some(jrow), 1, d.qLD, d.qLDiagInv);
        *wi = dot(jrow, &x[..nv]);
    }
    Ok(w)
}

/// eq_data of connect and weld constraints completed from the qpos0 configuration.
fn equality_data(m: &Model, d: &Data) -> Vec<f64> {
    let mut data = m.eq_data().to_vec();
    for i in 0..m.raw.neq as usize {
        let id1 = m.eq_obj1id()[i] as usize;
        let id2 = m.eq_obj2id()[i] as usize;
        let e = &mut data[mjNEQDATA * i..mjNEQDATA * (i + 1)];
        let t = m.eq_type()[i];
        if t == mjtEq_::mjEQ_CONNECT as i32 {
            let pos = add3(&mul_mat_vec3(&row(d.xmat, id1), &v3(e)), &row(d.xpos, id1));
            let pos = sub3(&pos, &row(d.xpos, id2));
            e[3..6].copy_from_slice(&mul_mat_t_vec3(&row(d.xmat, id2), &pos));
        } else if t == mjtEq_::mjEQ_WELD as i32 {
            if e[6] != 0.0 || e[7] != 0.0 || e[8] != 0.0 || e[9] != 0.0 {
                let q = normalize4(&q4(&e[6..])).0;
                e[6..10].copy_from_slice(&q);
                continue;
            }
            let pos = add3(&mul_mat_vec3(&row(d.xmat, id2), &v3(e)), &row(d.xpos, id2));
            let pos = sub3(&pos, &row(d.xpos, id1));
            e[3..6].copy_from_slice(&mul_mat_t_vec3(&row(d.xmat, id1), &pos));
            let q = mul_quat(&neg_quat(&row(d.xquat, id1)), &row(d.xquat, id2));
            e[6..10].copy_from_slice(&q);
        }
    }
    data
}

fn update_box(lo: &mut [f64; 3], hi: &mut [f64; 3], pos: &[f64; 3], r: f64) {
    for i in 0..3 {
        lo[i] = min(lo[i], pos[i] - r);
        hi[i] = max(hi[i], pos[i] + r);
    }
}

/// Extent, center, mean size, mass and inertia (setStat); `body` is scratch of nbody.
fn set_stat(m: &Model, d: &Data, body: &mut [f64]) -> mjStatistic {
    let mut stat = m.raw.stat;
    let (nbody, nv) = (m.raw.nbody as usize, m.raw.nv as usize);
    let mut lo = [1e10; 3];
    let mut hi = [-1e10; 3];
    for i in 1..nbody {
        update_box(&mut lo, &mut hi, &row(d.xpos, i), 0.0);
        update_box(&mut lo, &mut hi, &row(d.xipos, i), 0.0);
    }
    for i in 0..m.raw.njnt as usize {
        update_box(&mut lo, &mut hi, &row(d.xanchor, i), 0.0);
    }
    for i in 0..m.raw.nsite as usize {
        update_box(&mut lo, &mut hi, &row(d.site_xpos, i), 0.0);
    }
    for i in 0..m.raw.ngeom as usize {
        let mut rbound = 0.0;
        if m.geom_rbound()[i] > 0.0 {
            rbound = m.geom_rbound()[i];
        } else if m.geom_type()[i] == mjtGeom_::mjGEOM_PLANE as i32 {
            let (s0, s1) = (m.geom_size()[3 * i], m.geom_size()[3 * i + 1]);
            rbound = if s0 != 0.0 || s1 != 0.0 {
                (if s0 > s1 { s0 } else { s1 }) * 0.1
            } else {
                1.0
            };
        } else if m.geom_type()[i] == mjtGeom_::mjGEOM_HFIELD as i32 {
            let j = m.geom_dataid()[i] as usize;
            let h = &m.hfield_size()[4 * j..4 * j + 4];
            let mx = |a: f64, b: f64| if a > b { a } else { b };
            rbound = mx(h[0], mx(h[1], mx(h[2], h[3]))) * 0.1;
        }
        update_box(&mut lo, &mut hi, &row(d.geom_xpos, i), rbound);
    }
    let c = add3(&lo, &hi);
    stat.center = scl3(&c, 0.5);
    if hi[0] > lo[0] {
        stat.extent = max(1e-5, max(hi[0] - lo[0], max(hi[1] - lo[1], hi[2] - lo[2])));
    }

    let body = &mut body[..nbody];
    body.fill(0.0);
    for i in 0..m.raw.njnt as usize {
        let anchor = row::<3>(d.xanchor, i);
        let id = m.jnt_bodyid()[i] as usize;
        body[id] = max(body[id], dist3(&row(d.xipos, id), &anchor));
        let id = m.body_parentid()[id] as usize;
        body[id] = max(body[id], dist3(&row(d.xipos, id), &anchor));
    }
    body[0] = 0.0;
    for i in 1..nbody {
        for g in m.body_geoms(i) {
            if m.geom_rbound()[g] > 0.0 {
                body[i] = max(
                    body[i],
                    m.geom_rbound()[g] + dist3(&row(d.xipos, i), &row(d.geom_xpos, g)),
                );
            }
        }
    }
    if nbody > 1 {
        stat.meansize = 0.0;
        for b in body.iter_mut().skip(1) {
            *b = max(*b, 1e-5);
            stat.meansize += *b / (nbody - 1) as f64;
        }
    }
    stat.extent = max(stat.extent, 2.0 * stat.meansize);
    if nbody > 1 {
        stat.meanmass = 0.0;
        for i in 1..nbody {
            stat.meanmass += m.body_mass()[i];
        }
        stat.meanmass /= (nbody - 1) as f64;
    }
    if nv > 0 {
        stat.meaninertia = 0.0;
        for i in 0..nv {
            stat.meaninertia += d.qM[m.dof_Madr()[i] as usize];
        }
        stat.meaninertia /= nv as f64;
    }
    stat
}

/// Stores computed constants into the model.
pub fn store(mm: &mut ModelMut, stat_out: &mut mjStatistic, c: Consts) {
    mm.dof_M0.copy_from_slice(&c.dof_m0);
    mm.actuator_length0.copy_from_slice(&c.actuator_length0);
    mm.tendon_length0.copy_from_slice(&c.tendon_length0);
    mm.tendon_invweight0.copy_from_slice(&c.tendon_invweight0);
    mm.tendon_lengthspring
        .copy_from_slice(&c.tendon_lengthspring);
    mm.body_invweight0.copy_from_slice(&c.body_invweight0);
    mm.dof_invweight0.copy_from_slice(&c.dof_invweight0);
    mm.actuator_acc0.copy_from_slice(&c.actuator_acc0);
    mm.eq_data.copy_from_slice(&c.eq_data);
    for (i, (pos0, poscom0, mat0)) in c.cam.iter().enumerate() {
        put(mm.cam_pos0, i, pos0);
        put(mm.cam_poscom0, i, poscom0);
        put(mm.cam_mat0, i, mat0);
    }
    for (i, (pos0, poscom0, dir0)) in c.light.iter().enumerate() {
        put(mm.light_pos0, i, pos0);
        put(mm.light_poscom0, i, poscom0);
        put(mm.light_dir0, i, dir0);
    }
    *stat_out = c.stat;
}
