//! Constraint solvers (mj_fwdConstraint), dense or sparse: warm start, projected Gauss-Seidel
//! and noslip in the dual, and the primal conjugate-gradient and Newton methods with their exact
//! line search, with pyramidal and elliptic contact cones.

use super::constraint::{constraint_update, is_sparse, jac_view, with_arena};
use super::inertia::solve_ld;
use super::jacobian::{add_m_dense, add_m_sparse_with, m_row, mul_m};
use super::solver_dual::{cost_change, noslip_elliptic, noslip_pyramid, pgs_elliptic, residual};
use super::{disabled, tick, Data, EngineError, Model, MINVAL};
use crate::abi::view::Arena;
use crate::abi::*;
use crate::math::blas::{add_to_scl, dot, mul_mat_vec, norm, scl, sqr_mat_td_lower, sub_from};
use crate::math::chol::{chol_factor, chol_solve, chol_update, chol_update2};
use crate::math::chol_sparse::{
    chol_factor_sparse, chol_factor_sparse_preset, chol_solve_sparse, chol_sparse_pattern,
    chol_sparse_values, chol_update_sparse,
};
use crate::math::misc::{kept_or_neg_zero, minus_one};
use crate::math::sparse::{
    add_td_row, compress_sparse, dot_sparse, keep_nonfinite_rows, mul_mat_vec_sparse,
    sqr_mat_td_sparse_pattern, sqr_mat_td_sparse_values, SparseRef,
};
use mjtConstraintState_::*;

const SATISFIED: i32 = mjCNSTRSTATE_SATISFIED as i32;
const QUADRATIC: i32 = mjCNSTRSTATE_QUADRATIC as i32;
const LINEARNEG: i32 = mjCNSTRSTATE_LINEARNEG as i32;
const LINEARPOS: i32 = mjCNSTRSTATE_LINEARPOS as i32;
const CONE: i32 = mjCNSTRSTATE_CONE as i32;
const ELLIPTIC: i32 = mjtConstraint_::mjCNSTR_CONTACT_ELLIPTIC as i32;
const PYRAMIDAL: i32 = mjtConstraint_::mjCNSTR_CONTACT_PYRAMIDAL as i32;

/// Cost or gradient scaled by the mean inertia and the number of dofs.
fn rescale(m: &Model, x: f64) -> f64 {
    x / (m.raw.stat.meaninertia * m.raw.nv.max(1) as f64)
}

/// Records one iteration's statistics and counts it.
#[allow(clippy::too_many_arguments)]
fn save_stats(
    d: &mut Data,
    iter: &mut i32,
    improvement: f64,
    gradient: f64,
    lineslope: f64,
    nactive: i32,
    nchange: i32,
    neval: i32,
    nupdate: i32,
) {
    let i = (d.raw.solver_iter + *iter) as usize;
    *iter += 1;
    if i < mjNSOLVER {
        let s = &mut d.raw.solver[i];
        s.improvement = improvement;
        s.gradient = gradient;
        s.lineslope = lineslope;
        s.nactive = nactive;
        s.nchange = nchange;
        s.neval = neval;
        s.nupdate = nupdate;
    }
}

/// mj_fwdConstraint: qacc, efc_force and qfrc_constraint from the selected solver.
#[inline]
pub fn fwd_constraint(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let start = super::now();
    if d.raw.nefc == 0 {
        d.qacc.copy_from_slice(d.qacc_smooth);
        d.qacc_warmstart.copy_from_slice(d.qacc_smooth);
        d.qfrc_constraint.fill(0.0);
        d.raw.solver_iter = 0;
        return Ok(());
    }
    solve_constraints(m, d, start)
}

#[inline(never)]
fn solve_constraints(m: &Model, d: &mut Data, start: f64) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    jac_view!(m, d).mul_vec(d.efc_b, d.qacc_smooth);
    for i in 0..nefc {
        d.efc_b[i] -= d.efc_aref[i];
    }
    with_arena(d, |d, a| warmstart(m, d, a))?;
    d.raw.solver_iter = 0;
    let maxiter = m.raw.opt.iterations;
    match m.raw.opt.solver {
        s if s == mjtSolver_::mjSOL_PGS as i32 => with_arena(d, |d, a| pgs(m, d, a, maxiter))?,
        s if s == mjtSolver_::mjSOL_CG as i32 => {
            with_arena(d, |d, a| cg_newton(m, d, a, maxiter, false))?
        }
        s if s == mjtSolver_::mjSOL_NEWTON as i32 => {
            with_arena(d, |d, a| cg_newton(m, d, a, maxiter, true))?
        }
        s => return Err(EngineError(format!("Unknown solver type {s}"))),
    }
    d.qacc_warmstart[..nv].copy_from_slice(&d.qacc[..nv]);
    let noslip_iter = m.raw.opt.noslip_iterations;
    if noslip_iter > 0 {
        with_arena(d, |d, a| noslip(m, d, a, noslip_iter))?;
    }
    tick(d, mjtTimer_::mjTIMER_CONSTRAINT, start);
    Ok(())
}

/// Starts from the better of qacc_warmstart and qacc_smooth (PGS: of the warm-start forces
/// and zero).
fn warmstart(m: &Model, d: &mut Data, a: &mut Arena) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_WARMSTART) {
        d.qacc.copy_from_slice(d.qacc_smooth);
        d.efc_force[..nefc].fill(0.0);
        return Ok(());
    }
    let jar = a.alloc(nefc)?;
    d.qacc.copy_from_slice(d.qacc_warmstart);
    jac_view!(m, d).mul_vec(jar, d.qacc_warmstart);
    for i in 0..nefc {
        jar[i] -= d.efc_aref[i];
    }
    let mut cost_warmstart = constraint_update(m, d, jar, true, false)?;
    if m.raw.opt.solver == mjtSolver_::mjSOL_PGS as i32 {
        let mut pgs_warmstart = dot(d.efc_force, d.efc_b, nefc);
        let arf = a.alloc(nefc)?;
        if is_sparse(m) {
            let (nnz, adr, ind) = (&*d.efc_AR_rownnz, &*d.efc_AR_rowadr, &*d.efc_AR_colind);
            mul_mat_vec_sparse(arf, d.efc_AR, d.efc_force, nefc, nnz, adr, ind, None);
        } else {
            mul_mat_vec(arf, d.efc_AR, d.efc_force, nefc, nefc);
        }
        pgs_warmstart += 0.5 * dot(d.efc_force, arf, nefc);
        if pgs_warmstart > 0.0 {
            d.efc_force[..nefc].fill(0.0);
            d.qfrc_constraint[..nv].fill(0.0);
        }
    } else {
        let ma = a.alloc(nv)?;
        mul_m(m, d.qM, ma, d.qacc_warmstart);
        for i in 0..nv {
            cost_warmstart +=
                0.5 * (ma[i] - d.qfrc_smooth[i]) * (d.qacc_warmstart[i] - d.qacc_smooth[i]);
        }
        let b = std::mem::take(&mut d.efc_b);
        let cost_smooth = constraint_update(m, d, b, true, false);
        d.efc_b = b;
        if cost_warmstart > cost_smooth? {
            d.qacc.copy_from_slice(d.qacc_smooth);
        }
    }
    Ok(())
}

/// efc_state from dual forces; returns the number of active constraints.
fn dual_state(d: &mut Data) -> Result<i32, EngineError> {
    let (ne, nf, nefc) = (d.raw.ne as usize, d.raw.nf as usize, d.raw.nefc as usize);
    let (force, floss, state) = (&*d.efc_force, &*d.efc_frictionloss, &mut *d.efc_state);
    let mut nactive = (ne + nf) as i32;
    for s in &mut state[..ne] {
        *s = QUADRATIC;
    }
    for i in ne..ne + nf {
        state[i] = if force[i] <= -floss[i] {
            LINEARPOS
        } else if force[i] >= floss[i] {
            LINEARNEG
        } else {
            QUADRATIC
        };
    }
    let mut i = ne + nf;
    while i < nefc {
        if d.efc_type[i] != ELLIPTIC {
            if force[i] <= 0.0 {
                state[i] = SATISFIED;
            } else {
                state[i] = QUADRATIC;
                nactive += 1;
            }
            i += 1;
            continue;
        }
        // elliptic: the zone of the force mapped to the regular cone
        let con = &d.contact[d.efc_id[i] as usize];
        let (dim, mu) = (con.dim as usize, con.mu);
        let mut f = [0.0; 6];
        f[0] = force[i] / mu;
        for j in 1..dim {
            f[j] = force[i + j] / con.friction[j - 1];
        }
        let (n, t) = (f[0], norm(&f[1..dim]));
        let result = if mu * n >= t {
            SATISFIED
        } else {
            nactive += dim as i32;
            if n + mu * t <= 0.0 {
                QUADRATIC
            } else {
                CONE
            }
        };
        state[i..i + dim].fill(result);
        i += dim;
    }
    Ok(nactive)
}

/// res = 1/diag(AR), or 1/max(MINVAL, diag(AR) - R) with `sub_r` (ARdiaginv).
fn ar_diag_inv(d: &Data, sparse: bool, res: &mut [f64], sub_r: bool) -> Result<(), EngineError> {
    let nefc = d.raw.nefc as usize;
    for i in 0..nefc {
        let k = if sparse {
            let adr = d.efc_AR_rowadr[i] as usize;
            let n = d.efc_AR_rownnz[i] as usize;
            match (adr..adr + n).find(|&k| d.efc_AR_colind[k] == i as i32) {
                Some(k) => k,
                None => return Err(EngineError("AR has no diagonal element".into())),
            }
        } else {
            i * (nefc + 1)
        };
        res[i] = if sub_r {
            1.0 / crate::math::misc::max(MINVAL, d.efc_AR[k] - d.efc_R[i])
        } else {
            1.0 / d.efc_AR[k]
        };
    }
    Ok(())
}

/// Row i of AR times efc_force.
fn ar_row_dot(d: &Data, sparse: bool, i: usize) -> f64 {
    let nefc = d.raw.nefc as usize;
    if sparse {
        let adr = d.efc_AR_rowadr[i] as usize;
        let n = d.efc_AR_rownnz[i] as usize;
        dot_sparse(&d.efc_AR[adr..], d.efc_force, n, &d.efc_AR_colind[adr..])
    } else {
        dot(&d.efc_AR[i * nefc..], d.efc_force, nefc)
    }
}

/// qfrc_constraint = J'*force, qacc = qacc_smooth + M^-1 qfrc_constraint (dualFinish).
fn dual_finish(m: &Model, d: &mut Data) {
    let nv = m.raw.nv as usize;
    jac_view!(m, d).mul_t_vec(d.qfrc_constraint, d.efc_force);
    solve_ld(m, d.qacc, Some(d.qfrc_constraint), 1, d.qLD, d.qLDiagInv);
    for i in 0..nv {
        d.qacc[i] += d.qacc_smooth[i];
    }
}

/// Projected Gauss-Seidel on the dual (mj_solPGS); elliptic contacts as blocks.
fn pgs(m: &Model, d: &mut Data, a: &mut Arena, maxiter: i32) -> Result<(), EngineError> {
    let (ne, nf, nefc) = (d.raw.ne as usize, d.raw.nf as usize, d.raw.nefc as usize);
    let arinv = a.alloc(nefc)?;
    let oldstate = a.alloc_int(nefc)?;
    let sparse = is_sparse(m);
    ar_diag_inv(d, sparse, arinv, false)?;
    dual_state(d)?;
    let mut iter = 0;
    while iter < maxiter {
        let mut improvement = 0.0;
        let mut i = 0;
        while i < nefc {
            if d.efc_type[i] == ELLIPTIC {
                let dim = d.contact[d.efc_id[i] as usize].dim as usize;
                let (mut res, mut old, mut athis) = ([0.0; 6], [0.0; 6], [0.0; 36]);
                residual(d, sparse, &mut res, i, dim, false);
                old[..dim].copy_from_slice(&d.efc_force[i..i + dim]);
                pgs_elliptic(d, sparse, i, dim, arinv[i], &res, &old, &mut athis)?;
                improvement -= cost_change(&athis, &mut d.efc_force[i..i + dim], &old, &res, dim);
                i += dim;
                continue;
            }
            let res = d.efc_b[i] + ar_row_dot(d, sparse, i);
            let old = d.efc_force[i];
            let f = &mut d.efc_force[i];
            *f -= res * arinv[i];
            if i >= ne && i < ne + nf {
                let fl = d.efc_frictionloss[i];
                if *f < -fl {
                    *f = -fl;
                } else if *f > fl {
                    *f = fl;
                }
            } else if i >= ne + nf && *f < 0.0 {
                *f = 0.0;
            }
            let athis = 1.0 / arinv[i];
            let delta = *f - old;
            let mut change = 0.5 * delta * delta * athis + delta * res;
            if change > 1e-10 {
                *f = old;
                change = 0.0;
            }
            improvement -= change;
            i += 1;
        }
        oldstate.copy_from_slice(&d.efc_state[..nefc]);
        let nactive = dual_state(d)?;
        let nchange = (0..nefc).filter(|&i| oldstate[i] != d.efc_state[i]).count() as i32;
        improvement = rescale(m, improvement);
        save_stats(d, &mut iter, improvement, 0.0, 0.0, nactive, nchange, 0, 0);
        if improvement < m.raw.opt.tolerance {
            break;
        }
    }
    d.raw.solver_iter += iter;
    d.raw.solver_nnz = if sparse {
        d.efc_AR_rownnz[..nefc].iter().sum()
    } else {
        (nefc * nefc) as i32
    };
    dual_finish(m, d);
    Ok(())
}

/// Dual clean-up of friction forces with the constraint regularizer removed (mj_solNoSlip):
/// dof and tendon friction, then contact friction (pyramid edge pairs, elliptic tangents).
fn noslip(m: &Model, d: &mut Data, a: &mut Arena, maxiter: i32) -> Result<(), EngineError> {
    let (ne, nf, nefc) = (d.raw.ne as usize, d.raw.nf as usize, d.raw.nefc as usize);
    let sparse = is_sparse(m);
    let arinv = a.alloc(nefc)?;
    let oldstate = a.alloc_int(nefc)?;
    ar_diag_inv(d, sparse, arinv, true)?;
    dual_state(d)?;
    let mut iter = 0;
    while iter < maxiter {
        let mut improvement = 0.0;
        if iter == 0 {
            for i in 0..nefc {
                improvement += 0.5 * d.efc_force[i] * d.efc_force[i] * d.efc_R[i];
            }
        }
        for i in ne..ne + nf {
            let mut res = d.efc_b[i] + ar_row_dot(d, sparse, i);
            res -= d.efc_R[i] * d.efc_force[i];
            let old = d.efc_force[i];
            let fl = d.efc_frictionloss[i];
            let f = &mut d.efc_force[i];
            *f -= res * arinv[i];
            if *f < -fl {
                *f = -fl;
            } else if *f > fl {
                *f = fl;
            }
            let delta = *f - old;
            improvement -= 0.5 * delta * delta / arinv[i] + delta * res;
        }
        let mut i = ne + nf;
        while i < nefc {
            let kind = d.efc_type[i];
            if kind != PYRAMIDAL && kind != ELLIPTIC {
                i += 1;
                continue;
            }
            let dim = d.contact[d.efc_id[i] as usize].dim as usize;
            match kind {
                PYRAMIDAL => {
                    noslip_pyramid(d, sparse, i, dim, &mut improvement)?;
                    i += 2 * (dim - 1);
                }
                ELLIPTIC => {
                    improvement += noslip_elliptic(d, sparse, i, dim)?;
                    i += dim;
                }
                _ => i += 1,
            }
        }
        oldstate.copy_from_slice(&d.efc_state[..nefc]);
        let nactive = dual_state(d)?;
        let nchange = (0..nefc).filter(|&i| oldstate[i] != d.efc_state[i]).count() as i32;
        improvement = rescale(m, improvement);
        save_stats(d, &mut iter, improvement, 0.0, 0.0, nactive, nchange, 0, 0);
        if improvement < m.raw.opt.noslip_tolerance {
            break;
        }
    }
    d.raw.solver_iter += iter;
    dual_finish(m, d);
    Ok(())
}

/// Working state of the CG and Newton solvers.
struct Ctx<'b> {
    jaref: &'b mut [f64],
    jv: &'b mut [f64],
    ma: &'b mut [f64],
    mv: &'b mut [f64],
    grad: &'b mut [f64],
    mgrad: &'b mut [f64],
    search: &'b mut [f64],
    quad: &'b mut [f64],
    newton: bool,
    h: &'b mut [f64],
    hcone: &'b mut [f64],
    sparse: bool,
    /// Where the factor's rows start in h and colind, and their total length.
    first: usize,
    nnz: usize,
    rownnz: &'b mut [i32],
    rowadr: &'b mut [i32],
    colind: &'b mut [i32],
    cost: f64,
    quad_gauss: [f64; 3],
    nactive: i32,
    ncone: i32,
    nupdate: i32,
    ls_iter: i32,
    ls_slope: f64,
    /// some row past the frictions is an elliptic cone's (set by `prepare`)
    elliptic: bool,
}

/// A line-search point: step, cost and its first two derivatives.
#[derive(Clone, Copy, Default)]
struct Pnt {
    alpha: f64,
    cost: f64,
    deriv: [f64; 2],
}

/// Constraint update at the current Jaref, plus the Gauss cost.
fn update_constraint(m: &Model, d: &mut Data, c: &mut Ctx) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    c.cost = constraint_update(m, d, c.jaref, true, c.newton)?;
    c.nactive = d.efc_state[..nefc]
        .iter()
        .filter(|&&s| s != SATISFIED)
        .count() as i32;
    c.ncone = d.efc_state[..nefc].iter().filter(|&&s| s == CONE).count() as i32;
    let mut gauss = 0.0;
    for (((ma, fs), qacc), qs) in c.ma[..nv]
        .iter()
        .zip(&d.qfrc_smooth[..nv])
        .zip(&d.qacc[..nv])
        .zip(&d.qacc_smooth[..nv])
    {
        gauss += 0.5 * (ma - fs) * (qacc - qs);
    }
    c.quad_gauss[0] = gauss;
    c.cost += gauss;
    Ok(())
}

/// The cost's gradient, grad = Ma - qfrc_smooth - qfrc_constraint.
fn update_gradient(m: &Model, d: &Data, c: &mut Ctx) {
    let nv = m.raw.nv as usize;
    for (((g, ma), fs), fc) in c.grad[..nv]
        .iter_mut()
        .zip(&c.ma[..nv])
        .zip(&d.qfrc_smooth[..nv])
        .zip(&d.qfrc_constraint[..nv])
    {
        *g = ma - fs - fc;
    }
}

/// The preconditioned gradient Mgrad: grad through the Hessian (Newton) or the mass matrix.
fn precondition(m: &Model, d: &Data, c: &mut Ctx) {
    let nv = m.raw.nv as usize;
    let h = if c.ncone > 0 { &*c.hcone } else { &*c.h };
    if c.newton && c.sparse {
        let (nnz, adr, ind) = (&*c.rownnz, &*c.rowadr, &*c.colind);
        chol_solve_sparse(c.mgrad, h, c.grad, nv, nnz, adr, ind);
    } else if c.newton {
        chol_solve(c.mgrad, h, c.grad, nv);
    } else {
        solve_ld(m, c.mgrad, Some(c.grad), 1, d.qLD, d.qLDiagInv);
    }
}

/// Quadratic pieces of the cost along the search direction.
fn prepare(m: &Model, d: &Data, c: &mut Ctx) {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    let v = &*c.search;
    c.quad_gauss[1] = dot(v, c.ma, nv) - dot(v, d.qfrc_smooth, nv);
    c.quad_gauss[2] = 0.5 * dot(v, c.mv, nv);
    c.elliptic = false;
    let mut i = 0;
    while i < nefc {
        let (jv, jaref, dd) = (c.jv[i], c.jaref[i], d.efc_D[i]);
        let dj0 = dd * jaref;
        let mut q = [jaref * dj0, jv * dj0, jv * dd * jv];
        let mut next = i + 1;
        if d.efc_type[i] == ELLIPTIC {
            // vector quadratic (bottom zone), and the cone quantities in the following
            // rows' slots (dim >= 3): U0, V0, UU, UV, VV, Dm
            let con = &d.contact[d.efc_id[i] as usize];
            let (dim, mu) = (con.dim as usize, con.mu);
            let (mut u, mut v) = ([0.0; 6], [0.0; 6]);
            for j in 1..dim {
                let dj = d.efc_D[i + j] * c.jaref[i + j];
                q[0] += c.jaref[i + j] * dj;
                q[1] += c.jv[i + j] * dj;
                q[2] += c.jv[i + j] * d.efc_D[i + j] * c.jv[i + j];
            }
            u[0] = jaref * mu;
            v[0] = jv * mu;
            for j in 1..dim {
                u[j] = c.jaref[i + j] * con.friction[j - 1];
                v[j] = c.jv[i + j] * con.friction[j - 1];
            }
            let (mut uu, mut uv, mut vv) = (0.0, 0.0, 0.0);
            for j in 1..dim {
                uu += u[j] * u[j];
                uv += u[j] * v[j];
                vv += v[j] * v[j];
            }
            let dm = dd / (mu * mu * (1.0 + mu * mu));
            c.quad[3 * i + 3..3 * i + 9].copy_from_slice(&[u[0], v[0], uu, uv, vv, dm]);
            next = i + dim;
            c.elliptic = true;
        }
        q[0] *= 0.5;
        q[2] *= 0.5;
        c.quad[3 * i..3 * i + 3].copy_from_slice(&q);
        i = next;
    }
}

fn add_to3(a: &mut [f64; 3], b: &[f64]) {
    a[0] += b[0];
    a[1] += b[1];
    a[2] += b[2];
}

/// Cost and derivatives at p.alpha along the search direction.
fn eval(d: &Data, c: &mut Ctx, p: &mut Pnt) {
    let (ne, nf, nefc) = (d.raw.ne as usize, d.raw.nf as usize, d.raw.nefc as usize);
    let alpha = p.alpha;
    let mut total = c.quad_gauss;
    for i in 0..ne {
        add_to3(&mut total, &c.quad[3 * i..]);
    }
    for i in ne..ne + nf {
        let (start, dir) = (c.jaref[i], c.jv[i]);
        let x = start + alpha * dir;
        let f = d.efc_frictionloss[i];
        let rf = d.efc_R[i] * f;
        if -rf < x && x < rf {
            add_to3(&mut total, &c.quad[3 * i..]);
        } else if x <= -rf {
            add_to3(&mut total, &[f * (-0.5 * rf - start), -f * dir, 0.0]);
        } else {
            add_to3(&mut total, &[f * (-0.5 * rf + start), f * dir, 0.0]);
        }
    }
    let (mut cost, mut d0, mut d1) = (0.0, 0.0, 0.0);
    let mut i = ne + nf;
    if !c.elliptic {
        add_active(&mut total, c.quad, c.jaref, c.jv, alpha, i..nefc);
        i = nefc;
    }
    while i < nefc {
        if d.efc_type[i] != ELLIPTIC {
            // among elliptic cones: an active row adds its quadratic, an inactive one -0
            let active = c.jaref[i] + alpha * c.jv[i] < 0.0;
            let q = &c.quad[3 * i..3 * i + 3];
            for k in 0..3 {
                total[k] += kept_or_neg_zero(q[k], active);
            }
            i += 1;
            continue;
        }
        let con = &d.contact[d.efc_id[i] as usize];
        let mu = con.mu;
        let q = &c.quad[3 * i..3 * i + 9];
        let (u0, v0, uu, uv, vv, dm) = (q[3], q[4], q[5], q[6], q[7], q[8]);
        let n = u0 + alpha * v0;
        let tsqr = uu + alpha * (2.0 * uv + alpha * vv);
        if tsqr <= 0.0 {
            if n < 0.0 {
                add_to3(&mut total, q);
            }
        } else {
            let t = tsqr.sqrt();
            if n >= mu * t {
                // top zone: no cost
            } else if mu * n + t <= 0.0 {
                add_to3(&mut total, q);
            } else {
                let n1 = v0;
                let t1 = (uv + alpha * vv) / t;
                let t2 = vv / t - (uv + alpha * vv) * t1 / (t * t);
                cost += 0.5 * dm * (n - mu * t) * (n - mu * t);
                d0 += dm * (n - mu * t) * (n1 - mu * t1);
                d1 += dm * ((n1 - mu * t1) * (n1 - mu * t1) + (n - mu * t) * (-mu * t2));
            }
        }
        i += con.dim as usize;
    }
    let cost = cost + (alpha * alpha * total[2] + alpha * total[1] + total[0]);
    let d0 = d0 + (2.0 * alpha * total[2] + total[1]);
    let mut d1 = d1 + 2.0 * total[2];
    if d1 <= 0.0 {
        crate::runtime::warning("Linesearch objective is not convex");
        d1 = MINVAL;
    }
    p.cost = cost;
    p.deriv = [d0, d1];
    c.ls_iter += 1;
}

/// total += the quadratics (`quad`, three a row) of the rows in `rows` active at alpha
/// (Jaref + alpha*Jv < 0), in order. The active rows of 64 are found first, so that the sums
/// skip the others without a branch on each (their signs change along the search and would
/// mispredict).
fn add_active(
    total: &mut [f64; 3],
    quad: &[f64],
    jaref: &[f64],
    jv: &[f64],
    alpha: f64,
    rows: std::ops::Range<usize>,
) {
    let mut i = rows.start;
    while i < rows.end {
        let n = (rows.end - i).min(64);
        let mut active = 0u64;
        for (k, (a, v)) in jaref[i..i + n].iter().zip(&jv[i..i + n]).enumerate() {
            active |= ((a + alpha * v < 0.0) as u64) << k;
        }
        while active != 0 {
            let k = i + active.trailing_zeros() as usize;
            add_to3(total, &quad[3 * k..3 * k + 3]);
            active &= active - 1;
        }
        i += n;
    }
}

/// Replaces p by a better candidate on the same side of the minimum; evaluates its Newton step.
fn update_bracket(d: &Data, c: &mut Ctx, p: &mut Pnt, cand: &[Pnt; 3], next: &mut Pnt) -> bool {
    let mut flag = false;
    for q in cand {
        if (p.deriv[0] < 0.0 && q.deriv[0] < 0.0 && p.deriv[0] < q.deriv[0])
            || (p.deriv[0] > 0.0 && q.deriv[0] > 0.0 && p.deriv[0] > q.deriv[0])
        {
            *p = *q;
            flag = true;
        }
    }
    if flag {
        next.alpha = p.alpha - p.deriv[0] / p.deriv[1];
        eval(d, c, next);
    }
    flag
}

/// Exact line search along c.search (2.2.2's bracketed Newton search); returns the step.
fn search(m: &Model, d: &mut Data, c: &mut Ctx) -> f64 {
    const LS_MAXITER: i32 = 50;
    const LS_TOLSCL: f64 = 0.01;
    let nv = m.raw.nv as usize;
    c.ls_iter = 0;
    c.ls_slope = 1.0;
    let snorm = norm(&c.search[..nv]);
    if snorm < MINVAL {
        return 0.0;
    }
    let gtol =
        m.raw.opt.tolerance * LS_TOLSCL * snorm * m.raw.stat.meaninertia * m.raw.nv.max(1) as f64;
    let slopescl = 1.0 / (snorm * m.raw.stat.meaninertia * m.raw.nv.max(1) as f64);
    mul_m(m, d.qM, c.mv, c.search);
    jac_view!(m, d).mul_vec(c.jv, c.search);
    prepare(m, d, c);
    let d: &Data = d;

    let mut p0 = Pnt::default();
    eval(d, c, &mut p0);
    let mut p1 = Pnt {
        alpha: p0.alpha - p0.deriv[0] / p0.deriv[1],
        ..Pnt::default()
    };
    eval(d, c, &mut p1);
    if p0.cost < p1.cost {
        p1 = p0;
    }
    if p1.deriv[0].abs() < gtol {
        c.ls_slope = p1.deriv[0].abs() * slopescl;
        return p1.alpha;
    }
    let dir = if p1.deriv[0] < 0.0 { 1.0 } else { -1.0 };
    let mut p2 = Pnt::default();
    let mut p2update = false;
    while p1.deriv[0] * dir <= -gtol && c.ls_iter < LS_MAXITER {
        p2 = p1;
        p2update = true;
        p1.alpha -= p1.deriv[0] / p1.deriv[1];
        eval(d, c, &mut p1);
        if p1.deriv[0].abs() < gtol {
            c.ls_slope = p1.deriv[0].abs() * slopescl;
            return p1.alpha;
        }
    }
    if c.ls_iter >= LS_MAXITER || !p2update {
        c.ls_slope = p1.deriv[0].abs() * slopescl;
        return p1.alpha;
    }
    let mut p2next = p1;
    let mut p1next = Pnt {
        alpha: p1.alpha - p1.deriv[0] / p1.deriv[1],
        ..Pnt::default()
    };
    eval(d, c, &mut p1next);
    while c.ls_iter < LS_MAXITER {
        let mut pmid = Pnt {
            alpha: 0.5 * (p1.alpha + p2.alpha),
            ..Pnt::default()
        };
        eval(d, c, &mut pmid);
        let cand = [p1next, p2next, pmid];
        let mut best: Option<usize> = None;
        let mut bestcost = 0.0;
        for (i, q) in cand.iter().enumerate() {
            if q.deriv[0].abs() < gtol && (best.is_none() || q.cost < bestcost) {
                bestcost = q.cost;
                best = Some(i);
            }
        }
        if let Some(b) = best {
            c.ls_slope = cand[b].deriv[0].abs() * slopescl;
            return cand[b].alpha;
        }
        let b1 = update_bracket(d, c, &mut p1, &cand, &mut p1next);
        let b2 = update_bracket(d, c, &mut p2, &cand, &mut p2next);
        if !b1 && !b2 {
            c.ls_slope = pmid.deriv[0].abs() * slopescl;
            return pmid.alpha;
        }
    }
    if p1.cost <= p2.cost && p1.cost < p0.cost {
        c.ls_slope = p1.deriv[0].abs() * slopescl;
        p1.alpha
    } else if p2.cost <= p1.cost && p2.cost < p0.cost {
        c.ls_slope = p2.deriv[0].abs() * slopescl;
        p2.alpha
    } else {
        0.0
    }
}

/// H = M + J'*D*J over quadratic rows, Cholesky-factorized (HessianDirect). Scratch as
/// 2.2.2's: D (nefc) for the factorization, each sparse step's own above it; the cone update
/// after D is released.
fn hessian_direct(m: &Model, d: &mut Data, a: &mut Arena, c: &mut Ctx) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    a.scope(|a| -> Result<(), EngineError> {
        let hdiag = a.alloc_stale(nefc)?;
        for i in 0..nefc {
            hdiag[i] = if d.efc_state[i] == QUADRATIC {
                d.efc_D[i]
            } else {
                0.0
            };
        }
        if c.sparse {
            let pat = SparseRef {
                rownnz: d.efc_J_rownnz,
                rowadr: d.efc_J_rowadr,
                colind: d.efc_J_colind,
                rowsuper: Some(d.efc_J_rowsuper),
            };
            let pat_t = SparseRef {
                rownnz: d.efc_JT_rownnz,
                rowadr: d.efc_JT_rowadr,
                colind: d.efc_JT_colind,
                rowsuper: Some(d.efc_JT_rowsuper),
            };
            // rows out of the quadratic state add only zeros, left out where finite
            keep_nonfinite_rows(hdiag, d.efc_J, &pat);
            let preset = a.scope(|a| -> Result<bool, EngineError> {
                let chain = a.alloc_int_stale(2 * nv)?;
                let buf = a.alloc_stale(nv)?;
                let (rownnz, rowadr, colind) = (&mut *c.rownnz, &mut *c.rowadr, &mut *c.colind);
                let rows = (&mut *rownnz, &mut *rowadr, &mut *colind);
                sqr_mat_td_sparse_pattern(nv, rows, &pat, &pat_t, chain, true, |_| true);
                let (parent, simple) = (m.dof_parentid(), m.dof_simplenum());
                if chol_sparse_pattern(nv, rownnz, rowadr, colind, parent, simple) {
                    // H = J'*D*J + M row by row, into the factor's pattern
                    chol_sparse_values(c.h, nv, rownnz, rowadr, colind, buf, |r, buf| {
                        add_td_row(buf, r, d.efc_J, d.efc_JT, Some(hdiag), true, &pat, &pat_t);
                        for (j, adr) in m_row(m, r) {
                            buf[j] += d.qM[adr];
                        }
                    });
                    return Ok(true);
                }
                // rows nv apart, filled in by the merges of adding M and factorizing
                let rows = (&mut *rownnz, &mut *rowadr, &mut *colind);
                sqr_mat_td_sparse_pattern(nv, rows, &pat, &pat_t, chain, false, |_| true);
                sqr_mat_td_sparse_values(
                    c.h,
                    d.efc_J,
                    d.efc_JT,
                    Some(hdiag),
                    nv,
                    rownnz,
                    rowadr,
                    colind,
                    &pat,
                    &pat_t,
                    buf,
                );
                Ok(false)
            })?;
            let rank = if preset {
                // the scratch 2.2.2 takes to add M (unless every dof is simple) and to factorize
                if m.dof_simplenum()[..nv].contains(&0) {
                    a.account(2 * nv * nv + 4 * nv)?;
                }
                a.account(2 * nv)?;
                chol_factor_sparse_preset(c.h, nv, MINVAL, c.rownnz, c.rowadr, c.colind)
                    .map_err(|e| EngineError(e.into()))?
            } else {
                add_m_sparse_with(m, d.qM, a, c.h, c.rownnz, c.rowadr, c.colind, false)?;
                let rank = a.scope(|a| -> Result<usize, EngineError> {
                    let buf_ind = a.alloc_int_stale(nv)?;
                    let buf = a.alloc_stale(nv)?;
                    chol_factor_sparse(c.h, nv, MINVAL, c.rownnz, c.rowadr, c.colind, buf, buf_ind)
                        .map_err(|e| EngineError(e.into()))
                })?;
                compress_sparse(c.h, nv, c.rownnz, c.rowadr, c.colind);
                rank
            };
            c.first = c.rowadr[0] as usize;
            if rank != nv {
                return Err(EngineError(
                    "Rank-defficient Hessian in HessianDirect".into(),
                ));
            }
            c.nnz = c.rownnz[..nv].iter().sum::<i32>() as usize;
        } else {
            sqr_mat_td_lower(c.h, d.efc_J, Some(hdiag), nefc, nv);
            add_m_dense(m, d.qM, c.h, false);
            chol_factor(c.h, nv, MINVAL);
            (c.first, c.nnz) = (0, nv * nv);
        }
        Ok(())
    })?;
    if c.ncone > 0 {
        hessian_cone(m, d, a, c)?;
    }
    c.nupdate = nefc as i32;
    Ok(())
}

/// Hcone = H plus the cone Hessians of contacts in the cone state, as rank-one updates of the
/// factor by the rows of L'J (L: Cholesky factor of the contact's H).
fn hessian_cone(m: &Model, d: &mut Data, a: &mut Arena, c: &mut Ctx) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    let rows = c.first..c.first + c.nnz;
    c.hcone[rows.clone()].copy_from_slice(&c.h[rows]);
    a.scope(|a| -> Result<(), EngineError> {
        let ltj = a.alloc(6 * nv)?;
        let row = a.alloc(nv)?;
        let ind = a.alloc_int(nv)?;
        // the sparse update's own scratch (mju_cholUpdateSparse takes it per call)
        let (buf_ind, buf): (&mut [i32], &mut [f64]) = if c.sparse {
            (a.alloc_int_stale(nv)?, a.alloc_stale(nv)?)
        } else {
            (&mut [], &mut [])
        };
        let mut i = 0;
        while i < nefc {
            if d.efc_state[i] != CONE {
                i += 1;
                continue;
            }
            let con = &d.contact[d.efc_id[i] as usize];
            let dim = con.dim as usize;
            let mut local = [0.0; 36];
            local[..dim * dim].copy_from_slice(&con.H[..dim * dim]);
            chol_factor(&mut local, dim, MINVAL);
            let n = if c.sparse {
                d.efc_J_rownnz[i] as usize
            } else {
                nv
            };
            ltj[..dim * n].fill(0.0);
            for r in 0..dim {
                let jrow = if c.sparse {
                    let adr = d.efc_J_rowadr[i + r] as usize;
                    &d.efc_J[adr..adr + n]
                } else {
                    &d.efc_J[(i + r) * nv..(i + r + 1) * nv]
                };
                for col in 0..=r {
                    add_to_scl(&mut ltj[col * n..(col + 1) * n], jrow, local[r * dim + col]);
                }
            }
            if !c.sparse && nv <= PAIRED_NV {
                // the rows in pairs, overlapping (chol_update2), in local arrays
                let (mut first, mut second) = ([0.0; PAIRED_NV], [0.0; PAIRED_NV]);
                let mut r = 0;
                while r < dim {
                    first[..nv].copy_from_slice(&ltj[r * nv..(r + 1) * nv]);
                    if r + 1 < dim {
                        second[..nv].copy_from_slice(&ltj[(r + 1) * nv..(r + 2) * nv]);
                        chol_update2(c.hcone, &mut first, true, &mut second, true, nv);
                        r += 2;
                    } else {
                        chol_update(c.hcone, &mut first, nv, true);
                        r += 1;
                    }
                }
                c.nupdate += dim as i32;
                i += dim;
                continue;
            }
            for r in 0..dim {
                row[..n].copy_from_slice(&ltj[r * n..(r + 1) * n]);
                if c.sparse {
                    let adr = d.efc_J_rowadr[i + r] as usize;
                    ind[..n].copy_from_slice(&d.efc_J_colind[adr..adr + n]);
                    chol_update_sparse(
                        c.hcone, row, nv, true, c.rownnz, c.rowadr, c.colind, n, ind, buf, buf_ind,
                    )
                    .map_err(|e| EngineError(e.into()))?;
                } else {
                    chol_update(c.hcone, row, nv, true);
                }
            }
            c.nupdate += dim as i32;
            i += dim;
        }
        Ok(())
    })
}

/// Largest nv whose dense rank-one updates run in pairs (`chol_update2`).
const PAIRED_NV: usize = 64;

/// Rank-one updates of the factor for rows whose quadratic state changed (HessianIncremental).
/// A rank loss releases the scratch and refactors.
fn hessian_incremental(
    m: &Model,
    d: &mut Data,
    a: &mut Arena,
    c: &mut Ctx,
    oldstate: &[i32],
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    c.nupdate = 0;
    let refactor = a.scope(|a| -> Result<bool, EngineError> {
        let hvec = a.alloc_stale(nv)?;
        let vec_ind = a.alloc_int_stale(nv)?;
        let lost = a.scope(|a| -> Result<bool, EngineError> {
            // the sparse update's own scratch (2.2.2 takes it in each update, so only once a
            // row changes), released before the cone update
            let mut scratch: Option<(&mut [i32], &mut [f64])> = None;
            // dense rows waiting to be paired (local arrays: 2.2.2's scratch is one vector),
            // set up at the first changed row
            let mut pair: Option<[[f64; PAIRED_NV]; 2]> = None;
            let mut pending: Option<bool> = None;
            for i in 0..nefc {
                let (was, is) = (oldstate[i] == QUADRATIC, d.efc_state[i] == QUADRATIC);
                if was == is {
                    continue;
                }
                let s = d.efc_D[i].sqrt();
                let rank = if c.sparse {
                    let (n, adr) = (d.efc_J_rownnz[i] as usize, d.efc_J_rowadr[i] as usize);
                    for k in 0..n {
                        hvec[k] = d.efc_J[adr + k] * s;
                    }
                    vec_ind[..n].copy_from_slice(&d.efc_J_colind[adr..adr + n]);
                    if scratch.is_none() {
                        scratch = Some((a.alloc_int_stale(nv)?, a.alloc_stale(nv)?));
                    }
                    let Some((buf_ind, buf)) = scratch.as_mut() else {
                        unreachable!()
                    };
                    chol_update_sparse(
                        c.h, hvec, nv, is, c.rownnz, c.rowadr, c.colind, n, vec_ind, buf, buf_ind,
                    )
                    .map_err(|e| EngineError(e.into()))?
                } else if nv <= PAIRED_NV {
                    // held until the next changed row, so that the two updates overlap
                    let [first, second] = pair.get_or_insert([[0.0; PAIRED_NV]; 2]);
                    let slot = if pending.is_some() {
                        &mut *second
                    } else {
                        &mut *first
                    };
                    for k in 0..nv {
                        slot[k] = d.efc_J[i * nv + k] * s;
                    }
                    match pending.take() {
                        None => {
                            pending = Some(is);
                            continue;
                        }
                        Some(was_plus) => {
                            let (r1, r2) = chol_update2(c.h, first, was_plus, second, is, nv);
                            // a rank loss in the first discards the second with H (refactored)
                            c.nupdate += 1;
                            if r1 < nv {
                                return Ok(true);
                            }
                            r2
                        }
                    }
                } else {
                    for k in 0..nv {
                        hvec[k] = d.efc_J[i * nv + k] * s;
                    }
                    chol_update(c.h, hvec, nv, is)
                };
                c.nupdate += 1;
                if rank < nv {
                    return Ok(true);
                }
            }
            if let (Some(is), Some([first, _])) = (pending, pair.as_mut()) {
                let rank = chol_update(c.h, first, nv, is);
                c.nupdate += 1;
                if rank < nv {
                    return Ok(true);
                }
            }
            Ok(false)
        })?;
        if lost {
            return Ok(true);
        }
        // the cone update runs above vec and vec_ind, as in 2.2.2
        if c.ncone > 0 {
            hessian_cone(m, d, a, c)?;
        }
        Ok(false)
    })?;
    if refactor {
        return hessian_direct(m, d, a, c);
    }
    Ok(())
}

/// Primal solver: Newton (Hessian-preconditioned) or Polak-Ribiere CG (mj_solCGNewton).
fn cg_newton(
    m: &Model,
    d: &mut Data,
    a: &mut Arena,
    maxiter: i32,
    newton: bool,
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nefc = d.raw.nefc as usize;
    let hn = if newton { nv * nv } else { 0 };
    let mut c = Ctx {
        jaref: a.alloc_stale(nefc)?,
        jv: a.alloc_stale(nefc)?,
        ma: a.alloc_stale(nv)?,
        mv: a.alloc_stale(nv)?,
        grad: a.alloc_stale(nv)?,
        mgrad: a.alloc_stale(nv)?,
        search: a.alloc_stale(nv)?,
        quad: a.alloc_stale(3 * nefc)?,
        newton,
        h: a.alloc_stale(hn)?,
        hcone: a.alloc_stale(hn)?,
        sparse: is_sparse(m),
        first: 0,
        nnz: 0,
        rownnz: a.alloc_int_stale(if newton { nv } else { 0 })?,
        rowadr: a.alloc_int_stale(if newton { nv } else { 0 })?,
        colind: a.alloc_int_stale(hn)?,
        cost: 0.0,
        quad_gauss: [0.0; 3],
        nactive: 0,
        ncone: 0,
        nupdate: 0,
        ls_iter: 0,
        ls_slope: 1.0,
        elliptic: false,
    };
    // CG's previous gradients (2.2.2 also takes nv for their difference)
    let ncg = if newton { 0 } else { nv };
    let gradold = a.alloc_stale(ncg)?;
    let mgradold = a.alloc_stale(ncg)?;
    a.alloc_stale(ncg)?;
    let oldstate = a.alloc_int_stale(nefc)?;

    mul_m(m, d.qM, c.ma, d.qacc);
    jac_view!(m, d).mul_vec(c.jaref, d.qacc);
    sub_from(&mut c.jaref[..nefc], &d.efc_aref[..nefc]);
    update_constraint(m, d, &mut c)?;
    if newton {
        hessian_direct(m, d, a, &mut c)?;
    }
    update_gradient(m, d, &mut c);
    precondition(m, d, &mut c);
    scl(&mut c.search[..nv], &c.mgrad[..nv], minus_one());

    let mut iter = 0;
    while iter < maxiter {
        let alpha = search(m, d, &mut c);
        if alpha == 0.0 {
            break;
        }
        add_to_scl(&mut d.qacc[..nv], &c.search[..nv], alpha);
        add_to_scl(&mut c.ma[..nv], &c.mv[..nv], alpha);
        add_to_scl(&mut c.jaref[..nefc], &c.jv[..nefc], alpha);
        if !newton {
            gradold.copy_from_slice(c.grad);
            mgradold.copy_from_slice(c.mgrad);
        }
        oldstate.copy_from_slice(&d.efc_state[..nefc]);
        let oldcost = c.cost;
        update_constraint(m, d, &mut c)?;
        if newton {
            hessian_incremental(m, d, a, &mut c, oldstate)?;
        }
        update_gradient(m, d, &mut c);
        let nchange = (0..nefc).filter(|&i| d.efc_state[i] != oldstate[i]).count() as i32;
        let improvement = rescale(m, oldcost - c.cost);
        let gradient = rescale(m, norm(&c.grad[..nv]));
        let (slope, nactive, neval, nupdate) = (c.ls_slope, c.nactive, c.ls_iter, c.nupdate);
        save_stats(
            d,
            &mut iter,
            improvement,
            gradient,
            slope,
            nactive,
            nchange,
            neval,
            nupdate,
        );
        // Mgrad only sets the next search direction: the last iteration skips its solve
        if improvement < m.raw.opt.tolerance || gradient < m.raw.opt.tolerance || iter >= maxiter {
            break;
        }
        precondition(m, d, &mut c);
        if newton {
            scl(&mut c.search[..nv], &c.mgrad[..nv], minus_one());
        } else {
            // Polak-Ribiere; the denominator uses the old Mgrad before it is overwritten
            let den = crate::math::misc::max(MINVAL, dot(gradold, mgradold, nv));
            for i in 0..nv {
                mgradold[i] = c.mgrad[i] - mgradold[i];
            }
            let mut beta = dot(c.grad, mgradold, nv) / den;
            if beta < 0.0 {
                beta = 0.0;
            }
            for i in 0..nv {
                c.search[i] = -c.mgrad[i] + beta * c.search[i];
            }
        }
    }
    d.raw.solver_iter += iter;
    d.raw.solver_nnz = match (newton, c.sparse) {
        (false, _) => 0,
        (true, true) => (2 * c.nnz - nv) as i32,
        (true, false) => (nv * nv) as i32,
    };
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// add_active adds the same rows in the same order as a test of each row in turn: random
    /// rows across several blocks of 64, signs that flip with alpha, NaN and zero steps, a
    /// total starting at -0.
    #[test]
    fn active_rows_summed_as_row_by_row() {
        let mut rng = crate::math::tests::uniform(5);
        for trial in 0..300 {
            let n = trial % 200;
            let pick = |rng: &mut dyn FnMut() -> f64| match (rng() * 20.0) as i32 {
                0 => f64::NAN,
                1 => 0.0,
                2 => -0.0,
                _ => rng() - 0.5,
            };
            let jaref: Vec<f64> = (0..n).map(|_| pick(&mut rng)).collect();
            let jv: Vec<f64> = (0..n).map(|_| pick(&mut rng)).collect();
            let quad: Vec<f64> = (0..3 * n).map(|_| (rng() - 0.5) * 1e3).collect();
            let alpha = [0.0, rng(), -rng(), 1e300][trial % 4];
            let start = if n > 0 { trial % n } else { 0 };
            let mut want = [-0.0, 0.25, -0.0];
            for i in start..n {
                if jaref[i] + alpha * jv[i] < 0.0 {
                    add_to3(&mut want, &quad[3 * i..]);
                }
            }
            let mut got = [-0.0, 0.25, -0.0];
            add_active(&mut got, &quad, &jaref, &jv, alpha, start..n);
            assert_eq!(
                got.map(f64::to_bits),
                want.map(f64::to_bits),
                "trial {trial}"
            );
        }
    }
}
