//! Integrators (semi-implicit Euler with implicit dof damping, RK4, implicit in velocity) and
//! qpos-space arithmetic.

use super::derivative::smooth_vel;
use super::forward::{forward_pass, transient, Omit};
use super::inertia::{factor_i, solve_ld};
use super::linalg::{add_to_scl, clip};
use super::{Data, EngineError, Model, JNT_BALL, JNT_FREE, JNT_HINGE, JNT_SLIDE};
use crate::abi::mjtStage_;
use crate::abi::view::ints_of;
use crate::math::chol_sparse::{factor_lu_sparse, solve_lu_sparse};
use crate::math::*;

/// qpos += qvel*dt on the joint manifold (mj_integratePos).
pub fn integrate_pos(m: &Model, qpos: &mut [f64], qvel: &[f64], dt: f64) {
    for j in 0..m.raw.njnt as usize {
        let mut padr = m.jnt_qposadr()[j] as usize;
        let mut vadr = m.jnt_dofadr()[j] as usize;
        match m.jnt_type()[j] {
            t @ (JNT_FREE | JNT_BALL) => {
                if t == JNT_FREE {
                    for i in 0..3 {
                        qpos[padr + i] += dt * qvel[vadr + i];
                    }
                    padr += 3;
                    vadr += 3;
                }
                let q = quat_integrate(&q4(&qpos[padr..]), &v3(&qvel[vadr..]), dt);
                qpos[padr..padr + 4].copy_from_slice(&q);
            }
            JNT_HINGE | JNT_SLIDE => qpos[padr] += dt * qvel[vadr],
            _ => {}
        }
    }
}

/// Velocity that moves qpos1 to qpos2 in time dt (mj_differentiatePos).
pub fn differentiate_pos(m: &Model, qvel: &mut [f64], dt: f64, qpos1: &[f64], qpos2: &[f64]) {
    for j in 0..m.raw.njnt as usize {
        let mut padr = m.jnt_qposadr()[j] as usize;
        let mut vadr = m.jnt_dofadr()[j] as usize;
        match m.jnt_type()[j] {
            t @ (JNT_FREE | JNT_BALL) => {
                if t == JNT_FREE {
                    for i in 0..3 {
                        qvel[vadr + i] = (qpos2[padr + i] - qpos1[padr + i]) / dt;
                    }
                    padr += 3;
                    vadr += 3;
                }
                let neg = neg_quat(&q4(&qpos1[padr..]));
                let dif = mul_quat(&neg, &q4(&qpos2[padr..]));
                qvel[vadr..vadr + 3].copy_from_slice(&quat2vel(&dif, dt));
            }
            JNT_HINGE | JNT_SLIDE => qvel[vadr] = (qpos2[padr] - qpos1[padr]) / dt,
            _ => {}
        }
    }
}

/// Advances act, qvel, qpos and time (act with `act_dot` when given, else d.act_dot; qpos with
/// `qvel` when given, else the new d.qvel).
fn advance(m: &Model, d: &mut Data, act_dot: Option<&[f64]>, qacc: &[f64], qvel: Option<&[f64]>) {
    let h = m.raw.opt.timestep;
    let (nu, na) = (m.raw.nu as usize, m.raw.na as usize);
    if na > 0 {
        add_to_scl(d.act, act_dot.unwrap_or(d.act_dot), h);
        for i in 0..na {
            let iu = i + nu - na;
            if m.actuator_actlimited()[iu] != 0 {
                d.act[i] = clip(
                    d.act[i],
                    m.actuator_actrange()[2 * iu],
                    m.actuator_actrange()[2 * iu + 1],
                );
            }
        }
    }
    add_to_scl(d.qvel, qacc, h);
    match qvel {
        Some(v) => integrate_pos(m, d.qpos, v, h),
        None => integrate_pos(m, d.qpos, d.qvel, h),
    }
    d.raw.time += h;
}

/// Semi-implicit Euler, implicit in dof damping (mj_EulerSkip).
pub fn euler(m: &Model, d: &mut Data, skipfactor: bool) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nm = m.raw.nM as usize;
    // 2.2.2's scratch: qfrc and qacc, and M + h*B when it factors
    let qfrc = d.arena.alloc_stale(nv)?;
    let qacc = d.arena.alloc_stale(nv)?;
    if !m.dof_damping().iter().any(|&b| b > 0.0) {
        qacc.copy_from_slice(d.qacc);
    } else {
        if !skipfactor {
            let mhb = d.arena.alloc_stale(nm)?;
            mhb.copy_from_slice(d.qM);
            let h = m.raw.opt.timestep;
            for i in 0..nv {
                mhb[m.dof_Madr()[i] as usize] += h * m.dof_damping()[i];
            }
            factor_i(m, d.raw, mhb, d.qH, d.qHDiagInv, None)?;
        }
        for i in 0..nv {
            qfrc[i] = d.qfrc_smooth[i] + d.qfrc_constraint[i];
        }
        qacc.copy_from_slice(qfrc);
        solve_ld(m, qacc, None, 1, d.qH, d.qHDiagInv);
    }
    advance(m, d, None, qacc, None);
    Ok(())
}

const RK4_A: [f64; 9] = [0.5, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 1.0];
const RK4_B: [f64; 4] = [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0];

/// Explicit Runge-Kutta of order 4 (mj_RungeKutta).
pub fn runge_kutta(m: &Model, d: &mut Data, n: usize) -> Result<(), EngineError> {
    if n != 4 {
        return Err(EngineError("Supported RK orders: N=4".into()));
    }
    let (nq, nv, na) = (m.raw.nq as usize, m.raw.nv as usize, m.raw.na as usize);
    let h = m.raw.opt.timestep;
    let time = d.raw.time;
    let (a, b) = (&RK4_A, &RK4_B);

    let dx = d.arena.alloc(2 * nv + na)?;
    let mut xs: [&mut [f64]; 4] = Default::default();
    let mut fs: [&mut [f64]; 4] = Default::default();
    for i in 0..n {
        xs[i] = d.arena.alloc(nq + nv + na)?;
        fs[i] = d.arena.alloc(nv + na)?;
    }
    let mut t = [0.0; 3];
    for i in 1..n {
        let mut c = 0.0;
        for j in 0..i {
            c += a[(i - 1) * (n - 1) + j];
        }
        t[i - 1] = d.raw.time + c * h;
    }

    xs[0][..nq].copy_from_slice(d.qpos);
    xs[0][nq..nq + nv].copy_from_slice(d.qvel);
    fs[0][..nv].copy_from_slice(d.qacc);
    if na > 0 {
        xs[0][nq + nv..].copy_from_slice(d.act);
        fs[0][nv..].copy_from_slice(d.act_dot);
    }

    for i in 1..n {
        dx.fill(0.0);
        for j in 0..i {
            let aij = a[(i - 1) * (n - 1) + j];
            add_to_scl(&mut dx[..nv], &xs[j][nq..nq + nv], aij);
            add_to_scl(&mut dx[nv..], &fs[j][..nv + na], aij);
        }
        let (head, tail) = xs.split_at_mut(i);
        let xi = &mut *tail[0];
        xi.copy_from_slice(head[0]);
        integrate_pos(m, &mut xi[..nq], &dx[..nv], h);
        add_to_scl(&mut xi[nq..], &dx[nv..], h);

        d.qpos.copy_from_slice(&xi[..nq]);
        d.qvel.copy_from_slice(&xi[nq..nq + nv]);
        if na > 0 {
            d.act.copy_from_slice(&xi[nq + nv..]);
        }
        d.raw.time = t[i - 1];

        // the last pass's cameras, lights and energy stay; earlier ones are overwritten
        let omit = if i + 1 < n {
            transient(m, false)
        } else {
            Omit::default()
        };
        forward_pass(m, d, mjtStage_::mjSTAGE_NONE as i32, true, omit)?;
        fs[i][..nv].copy_from_slice(d.qacc);
        if na > 0 {
            fs[i][nv..].copy_from_slice(d.act_dot);
        }
    }

    dx.fill(0.0);
    for j in 0..n {
        add_to_scl(&mut dx[..nv], &xs[j][nq..nq + nv], b[j]);
        add_to_scl(&mut dx[nv..], &fs[j][..nv + na], b[j]);
    }

    d.raw.time = time;
    d.qpos.copy_from_slice(&xs[0][..nq]);
    d.qvel.copy_from_slice(&xs[0][nq..nq + nv]);
    d.act.copy_from_slice(&xs[0][nq + nv..]);

    let (vel, rest) = dx.split_at(nv);
    let (acc, act_dot) = rest.split_at(nv);
    advance(m, d, Some(act_dot), acc, Some(vel));
    Ok(())
}

/// Row-sparse structure of the inertia matrix with both triangles (mj_makeMSparse); `scratch`
/// needs nv ints.
pub fn make_m_sparse(
    m: &Model,
    rownnz: &mut [i32],
    rowadr: &mut [i32],
    colind: &mut [i32],
    scratch: &mut [i32],
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let parent = m.dof_parentid();
    rownnz[..nv].fill(0);
    for i in (0..nv).rev() {
        rownnz[i] += 1;
        let mut j = parent[i];
        while j >= 0 {
            rownnz[i] += 1;
            rownnz[j as usize] += 1;
            j = parent[j as usize];
        }
    }
    if nv > 0 {
        rowadr[0] = 0;
    }
    for i in 1..nv {
        rowadr[i] = rowadr[i - 1] + rownnz[i - 1];
    }
    let remaining = &mut scratch[..nv];
    remaining.copy_from_slice(&rownnz[..nv]);
    for i in (0..nv).rev() {
        remaining[i] -= 1;
        colind[(rowadr[i] + remaining[i]) as usize] = i as i32;
        let mut j = parent[i];
        while j >= 0 {
            let ju = j as usize;
            remaining[i] -= 1;
            colind[(rowadr[i] + remaining[i]) as usize] = j;
            remaining[ju] -= 1;
            colind[(rowadr[ju] + remaining[ju]) as usize] = i as i32;
            j = parent[ju];
        }
    }
    if remaining.iter().any(|&r| r != 0) {
        return Err(EngineError(
            "Error in mj_makeMSparse: unexpected remaining".into(),
        ));
    }
    Ok(())
}

/// dst = qM on the structure of `make_m_sparse` (mj_setMSparse); `scratch` needs nv ints.
pub fn set_m_sparse(
    m: &Model,
    qm: &[f64],
    dst: &mut [f64],
    rownnz: &[i32],
    rowadr: &[i32],
    scratch: &mut [i32],
) {
    let nv = m.raw.nv as usize;
    let parent = m.dof_parentid();
    let remaining = &mut scratch[..nv];
    remaining.copy_from_slice(&rownnz[..nv]);
    for i in (0..nv).rev() {
        let mut adr = m.dof_Madr()[i] as usize;
        remaining[i] -= 1;
        dst[(rowadr[i] + remaining[i]) as usize] = qm[adr];
        adr += 1;
        let mut j = parent[i];
        while j >= 0 {
            let ju = j as usize;
            remaining[i] -= 1;
            dst[(rowadr[i] + remaining[i]) as usize] = qm[adr];
            remaining[ju] -= 1;
            dst[(rowadr[ju] + remaining[ju]) as usize] = qm[adr];
            adr += 1;
            j = parent[ju];
        }
    }
}

/// Integrator implicit in velocity: (M - h*qDeriv) qacc = qfrc (mj_implicitSkip).
pub fn implicit(m: &Model, d: &mut Data, skipfactor: bool) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nd = m.raw.nD as usize;
    let qfrc = d.arena.alloc(nv)?;
    let qacc = d.arena.alloc(nv)?;
    if !skipfactor {
        // mj_makeMSparse and mj_setMSparse take their nv ints for the call; the factorization
        // uses qacc as its int scratch (as 2.2.2)
        d.arena.scope(|a| -> Result<(), EngineError> {
            let scratch = a.alloc_int(nv)?;
            make_m_sparse(m, d.D_rownnz, d.D_rowadr, d.D_colind, scratch)
        })?;
        smooth_vel(m, d)?;
        d.arena.scope(|a| -> Result<(), EngineError> {
            let scratch = a.alloc_int(nv)?;
            set_m_sparse(m, d.qM, d.qLU, d.D_rownnz, d.D_rowadr, scratch);
            Ok(())
        })?;
        add_to_scl(&mut d.qLU[..nd], &d.qDeriv[..nd], -m.raw.opt.timestep);
        factor_lu_sparse(d.qLU, nv, ints_of(qacc), d.D_rownnz, d.D_rowadr, d.D_colind)
            .map_err(|e| EngineError(e.into()))?;
    }
    for i in 0..nv {
        qfrc[i] = d.qfrc_smooth[i] + d.qfrc_constraint[i];
    }
    solve_lu_sparse(qacc, d.qLU, qfrc, nv, d.D_rownnz, d.D_rowadr, d.D_colind)
        .map_err(|e| EngineError(e.into()))?;
    advance(m, d, None, qacc, None);
    Ok(())
}
