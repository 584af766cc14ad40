//! C entry points of the simulation pipeline: build the views once, run the core under `guard`.

use super::errmem;
use super::guard;
use crate::abi::view::{Data, EngineError, Model, ModelMut};
use crate::abi::*;
use crate::engine::{self, constraint, forward, inertia, integrate, jacobian, kinematics, support};
use std::os::raw::{c_char, c_int};

unsafe fn slice<'a>(p: *const f64, n: usize) -> &'a [f64] {
    if p.is_null() || n == 0 {
        &[]
    } else {
        std::slice::from_raw_parts(p, n)
    }
}

unsafe fn slice_mut<'a>(p: *mut f64, n: usize) -> &'a mut [f64] {
    if p.is_null() || n == 0 {
        &mut []
    } else {
        std::slice::from_raw_parts_mut(p, n)
    }
}

/// The `n` values at `vec` that a call reads while writing the `len` values at `res`: in
/// place, or a copy where the two overlap (their slices must not).
unsafe fn input_apart<'a>(
    vec: *const f64,
    n: usize,
    res: *const f64,
    len: usize,
) -> std::borrow::Cow<'a, [f64]> {
    let v = slice(vec, n);
    let (v0, r0) = (vec as usize, res as usize);
    if v.is_empty() || len == 0 || v0 + 8 * n <= r0 || r0 + 8 * len <= v0 {
        std::borrow::Cow::Borrowed(v)
    } else {
        std::borrow::Cow::Owned(v.to_vec())
    }
}

/// Reports a NULL model through mju_error (2.2.2 would crash): true when `m` is NULL.
fn null_model(name: &str, m: *const mjModel) -> bool {
    if m.is_null() {
        errmem::error(&format!("{name}: NULL model"));
    }
    m.is_null()
}

unsafe fn arr3(p: *const f64) -> [f64; 3] {
    [*p, *p.add(1), *p.add(2)]
}

/// Runs a pipeline function on views of (m, d) under `guard`.
pub(super) unsafe fn run<R>(
    name: &str,
    fallback: R,
    m: *const mjModel,
    d: *mut mjData,
    f: impl FnOnce(&Model, &mut Data) -> Result<R, EngineError>,
) -> R {
    if m.is_null() || d.is_null() {
        errmem::error(&format!("{name}: NULL model or data"));
        return fallback;
    }
    guard(name, fallback, || {
        let mv = Model::new(&*m);
        Data::with(&*m, &mut *d, |dv| f(&mv, dv))
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_step(m: *const mjModel, d: *mut mjData) {
    run("mj_step", (), m, d, forward::step)
}

#[no_mangle]
pub unsafe extern "C" fn mj_step1(m: *const mjModel, d: *mut mjData) {
    run("mj_step1", (), m, d, forward::step1)
}

#[no_mangle]
pub unsafe extern "C" fn mj_step2(m: *const mjModel, d: *mut mjData) {
    run("mj_step2", (), m, d, forward::step2)
}

#[no_mangle]
pub unsafe extern "C" fn mj_forward(m: *const mjModel, d: *mut mjData) {
    run("mj_forward", (), m, d, forward::forward)
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdPosition(m: *const mjModel, d: *mut mjData) {
    run("mj_fwdPosition", (), m, d, forward::fwd_position)
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdVelocity(m: *const mjModel, d: *mut mjData) {
    run("mj_fwdVelocity", (), m, d, forward::fwd_velocity)
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdActuation(m: *const mjModel, d: *mut mjData) {
    run(
        "mj_fwdActuation",
        (),
        m,
        d,
        engine::actuation::fwd_actuation,
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdAcceleration(m: *const mjModel, d: *mut mjData) {
    run("mj_fwdAcceleration", (), m, d, forward::fwd_acceleration)
}

#[no_mangle]
pub unsafe extern "C" fn mj_fwdConstraint(m: *const mjModel, d: *mut mjData) {
    run("mj_fwdConstraint", (), m, d, forward::fwd_constraint)
}

#[no_mangle]
pub unsafe extern "C" fn mj_Euler(m: *const mjModel, d: *mut mjData) {
    run("mj_Euler", (), m, d, |m, d| integrate::euler(m, d, false))
}

#[no_mangle]
pub unsafe extern "C" fn mj_kinematics(m: *const mjModel, d: *mut mjData) {
    run("mj_kinematics", (), m, d, kinematics::kinematics)
}

#[no_mangle]
pub unsafe extern "C" fn mj_comPos(m: *const mjModel, d: *mut mjData) {
    run("mj_comPos", (), m, d, kinematics::com_pos)
}

#[no_mangle]
pub unsafe extern "C" fn mj_camlight(m: *const mjModel, d: *mut mjData) {
    run("mj_camlight", (), m, d, |m, d| {
        kinematics::camlight(m, d, false);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_tendon(m: *const mjModel, d: *mut mjData) {
    run("mj_tendon", (), m, d, forward::tendon)
}

#[no_mangle]
pub unsafe extern "C" fn mj_transmission(m: *const mjModel, d: *mut mjData) {
    run(
        "mj_transmission",
        (),
        m,
        d,
        engine::transmission::transmission,
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_crb(m: *const mjModel, d: *mut mjData) {
    run("mj_crb", (), m, d, |m, d| {
        inertia::crb(m, d, true);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_factorM(m: *const mjModel, d: *mut mjData) {
    run("mj_factorM", (), m, d, inertia::factor_m)
}

#[no_mangle]
pub unsafe extern "C" fn mj_comVel(m: *const mjModel, d: *mut mjData) {
    run("mj_comVel", (), m, d, |m, d| {
        engine::velocity::com_vel(m, d);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_passive(m: *const mjModel, d: *mut mjData) {
    run("mj_passive", (), m, d, engine::passive::passive)
}

#[no_mangle]
pub unsafe extern "C" fn mj_checkPos(m: *const mjModel, d: *mut mjData) {
    run("mj_checkPos", (), m, d, forward::check_pos)
}

#[no_mangle]
pub unsafe extern "C" fn mj_checkVel(m: *const mjModel, d: *mut mjData) {
    run("mj_checkVel", (), m, d, forward::check_vel)
}

#[no_mangle]
pub unsafe extern "C" fn mj_checkAcc(m: *const mjModel, d: *mut mjData) {
    run("mj_checkAcc", (), m, d, forward::check_acc)
}

#[no_mangle]
pub unsafe extern "C" fn mj_energyPos(m: *const mjModel, d: *mut mjData) {
    run("mj_energyPos", (), m, d, |m, d| {
        support::energy_pos(m, d);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_energyVel(m: *const mjModel, d: *mut mjData) {
    run("mj_energyVel", (), m, d, support::energy_vel)
}

#[no_mangle]
pub unsafe extern "C" fn mj_collision(m: *const mjModel, d: *mut mjData) {
    run("mj_collision", (), m, d, engine::collision::collision)
}

#[no_mangle]
pub unsafe extern "C" fn mj_forwardSkip(
    m: *const mjModel,
    d: *mut mjData,
    skipstage: c_int,
    skipsensor: c_int,
) {
    run("mj_forwardSkip", (), m, d, |m, d| {
        forward::forward_skip(m, d, skipstage, skipsensor != 0)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_stepSkip(
    m: *const mjModel,
    d: *mut mjData,
    skipstage: c_int,
    skipsensor: c_int,
) {
    run("mj_stepSkip", (), m, d, |m, d| {
        forward::step_skip(m, d, skipstage, skipsensor != 0)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_EulerSkip(m: *const mjModel, d: *mut mjData, skipfactor: c_int) {
    run("mj_EulerSkip", (), m, d, |m, d| {
        integrate::euler(m, d, skipfactor != 0)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_RungeKutta(m: *const mjModel, d: *mut mjData, N: c_int) {
    run("mj_RungeKutta", (), m, d, |m, d| {
        integrate::runge_kutta(m, d, N.max(0) as usize)
    })
}

// 2.2.2 exports the next eight symbols outside mujoco.h: `cbindgen:ignore` keeps them out of it.

unsafe fn ints_mut<'a>(p: *mut c_int, n: usize) -> &'a mut [i32] {
    if p.is_null() || n == 0 {
        &mut []
    } else {
        std::slice::from_raw_parts_mut(p, n)
    }
}

unsafe fn ints<'a>(p: *const c_int, n: usize) -> &'a [i32] {
    if p.is_null() || n == 0 {
        &[]
    } else {
        std::slice::from_raw_parts(p, n)
    }
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mj_implicit(m: *const mjModel, d: *mut mjData) {
    run("mj_implicit", (), m, d, |m, d| {
        integrate::implicit(m, d, false)
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mj_implicitSkip(m: *const mjModel, d: *mut mjData, skipfactor: c_int) {
    run("mj_implicitSkip", (), m, d, |m, d| {
        integrate::implicit(m, d, skipfactor != 0)
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mj_makeMSparse(
    m: *const mjModel,
    d: *mut mjData,
    rownnz: *mut c_int,
    rowadr: *mut c_int,
    colind: *mut c_int,
) {
    run("mj_makeMSparse", (), m, d, |mv, dv| {
        let (nv, nd) = (mv.raw.nv.max(0) as usize, mv.raw.nD.max(0) as usize);
        let scratch = dv.arena.alloc_int(nv)?;
        integrate::make_m_sparse(
            mv,
            ints_mut(rownnz, nv),
            ints_mut(rowadr, nv),
            ints_mut(colind, nd),
            scratch,
        )
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mj_setMSparse(
    m: *const mjModel,
    d: *mut mjData,
    dst: *mut mjtNum,
    rownnz: *const c_int,
    rowadr: *const c_int,
    colind: *const c_int,
) {
    let _ = colind;
    run("mj_setMSparse", (), m, d, |mv, dv| {
        let (nv, nd) = (mv.raw.nv.max(0) as usize, mv.raw.nD.max(0) as usize);
        let scratch = dv.arena.alloc_int(nv)?;
        integrate::set_m_sparse(
            mv,
            dv.qM,
            slice_mut(dst, nd),
            ints(rownnz, nv),
            ints(rowadr, nv),
            scratch,
        );
        Ok(())
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mjd_passive_vel(m: *const mjModel, d: *mut mjData, DfDv: *mut mjtNum) {
    run("mjd_passive_vel", (), m, d, |mv, dv| {
        let nv = mv.raw.nv.max(0) as usize;
        engine::derivative::passive_vel(mv, dv, slice_mut(DfDv, nv * nv))
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mjd_smooth_vel(m: *const mjModel, d: *mut mjData) {
    run("mjd_smooth_vel", (), m, d, engine::derivative::smooth_vel)
}

#[no_mangle]
pub unsafe extern "C" fn mjd_transitionFD(
    m: *const mjModel,
    d: *mut mjData,
    eps: mjtNum,
    centered: mjtByte,
    A: *mut mjtNum,
    B: *mut mjtNum,
    C: *mut mjtNum,
    D: *mut mjtNum,
) {
    if m.is_null() || d.is_null() {
        errmem::error("mjd_transitionFD: NULL model or data");
        return;
    }
    guard("mjd_transitionFD", (), || {
        let mv = Model::new(&*m);
        let (nv, na, nu) = (mv.raw.nv as usize, mv.raw.na as usize, mv.raw.nu as usize);
        let (ndx, ns) = (2 * nv + na, mv.raw.nsensordata as usize);
        let opt = |p: *mut mjtNum, n: usize| (!p.is_null()).then(|| slice_mut(p, n));
        // every step runs on a fresh view of d, so that its scratch is released in between
        let mut with = |f: &mut dyn FnMut(&mut Data) -> Result<(), EngineError>| {
            let mut dv = Data::new(&*m, &mut *d);
            f(&mut dv)
        };
        engine::derivative::transition_fd(
            &mv,
            &mut with,
            eps,
            centered != 0,
            opt(A, ndx * ndx),
            opt(B, ndx * nu),
            opt(C, ns * ndx),
            opt(D, ns * nu),
        )
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mjd_passive_velFD(
    m: *const mjModel,
    d: *mut mjData,
    eps: mjtNum,
    DfDv: *mut mjtNum,
) {
    run("mjd_passive_velFD", (), m, d, |mv, dv| {
        let nv = mv.raw.nv.max(0) as usize;
        engine::derivative::passive_vel_fd(mv, dv, eps, slice_mut(DfDv, nv * nv))
    })
}

/// cbindgen:ignore
#[no_mangle]
pub unsafe extern "C" fn mjd_smooth_velFD(m: *const mjModel, d: *mut mjData, eps: mjtNum) {
    run("mjd_smooth_velFD", (), m, d, |mv, dv| {
        engine::derivative::smooth_vel_fd(mv, dv, eps)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_solveM(
    m: *const mjModel,
    d: *mut mjData,
    x: *mut mjtNum,
    y: *const mjtNum,
    n: c_int,
) {
    run("mj_solveM", (), m, d, |mv, dv| {
        let len = n.max(0) as usize * mv.raw.nv as usize;
        let x = slice_mut(x, len);
        let y = if y == x.as_ptr() {
            None
        } else {
            Some(slice(y, len))
        };
        inertia::solve_ld(mv, x, y, n.max(0) as usize, dv.qLD, dv.qLDiagInv);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_solveM2(
    m: *const mjModel,
    d: *mut mjData,
    x: *mut mjtNum,
    y: *const mjtNum,
    n: c_int,
) {
    run("mj_solveM2", (), m, d, |mv, dv| {
        let len = n.max(0) as usize * mv.raw.nv as usize;
        let tmp: Vec<f64> = slice(y, len).to_vec();
        inertia::solve_m2(
            mv,
            slice_mut(x, len),
            &tmp,
            n.max(0) as usize,
            dv.qLD,
            dv.qLDiagSqrtInv,
        );
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_solveLD(
    m: *const mjModel,
    x: *mut mjtNum,
    y: *const mjtNum,
    n: c_int,
    qLD: *const mjtNum,
    qLDiagInv: *const mjtNum,
) {
    if null_model("mj_solveLD", m) {
        return;
    }
    guard("mj_solveLD", (), || {
        let mv = Model::new(&*m);
        let len = n.max(0) as usize * mv.raw.nv as usize;
        let x = slice_mut(x, len);
        let y = if y == x.as_ptr() {
            None
        } else {
            Some(slice(y, len))
        };
        let qld = slice(qLD, mv.raw.nM as usize);
        let dinv = slice(qLDiagInv, mv.raw.nv as usize);
        inertia::solve_ld(&mv, x, y, n.max(0) as usize, qld, dinv);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_factorI(
    m: *const mjModel,
    d: *mut mjData,
    M: *const mjtNum,
    qLD: *mut mjtNum,
    qLDiagInv: *mut mjtNum,
    qLDiagSqrtInv: *mut mjtNum,
) {
    run("mj_factorI", (), m, d, |mv, dv| {
        let (nm, nv) = (mv.raw.nM as usize, mv.raw.nv as usize);
        let mat: Vec<f64> = slice(M, nm).to_vec();
        let sqrt_inv = if qLDiagSqrtInv.is_null() {
            None
        } else {
            Some(slice_mut(qLDiagSqrtInv, nv))
        };
        inertia::factor_i(
            mv,
            dv.raw,
            &mat,
            slice_mut(qLD, nm),
            slice_mut(qLDiagInv, nv),
            sqrt_inv,
        )
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_rne(
    m: *const mjModel,
    d: *mut mjData,
    flg_acc: c_int,
    result: *mut mjtNum,
) {
    run("mj_rne", (), m, d, |mv, dv| {
        let nv = mv.raw.nv as usize;
        let mut out = vec![0.0; nv];
        let qacc: Vec<f64> = dv.qacc.to_vec();
        engine::rne::rne_with(mv, dv, (flg_acc != 0).then_some(&qacc[..]), &mut out)?;
        slice_mut(result, nv).copy_from_slice(&out);
        Ok(())
    })
}

/// Jacobian rows at `point` on `body`, from the raw data (the C signature has a const mjData).
/// The object's id when it is valid (0 <= id < n), else an error through mju_error: 2.2.2
/// reads out of bounds here, we refuse.
unsafe fn checked_id(
    name: &str,
    m: *const mjModel,
    d: *const mjData,
    id: c_int,
    n: impl Fn(&mjModel) -> i32,
) -> Option<usize> {
    if m.is_null() || d.is_null() {
        errmem::error(&format!("{name}: NULL model or data"));
        return None;
    }
    if id < 0 || id >= n(&*m) {
        errmem::error(&format!("{name}: invalid id {id}"));
        return None;
    }
    Some(id as usize)
}

unsafe fn jac_raw(
    m: *const mjModel,
    d: *const mjData,
    jacp: *mut f64,
    jacr: *mut f64,
    point: [f64; 3],
    body: c_int,
) {
    if m.is_null() || d.is_null() {
        errmem::error("mj_jac: NULL model or data");
        return;
    }
    guard("mj_jac", (), || {
        let mv = Model::new(&*m);
        let (nv, nbody) = (mv.raw.nv as usize, mv.raw.nbody as usize);
        if body < 0 || body as usize >= nbody {
            return Err(EngineError(format!("Invalid body {body} in mj_jac")));
        }
        let cdof = slice((*d).cdof, 6 * nv);
        let com = slice((*d).subtree_com, 3 * nbody);
        let p = (!jacp.is_null()).then(|| slice_mut(jacp, 3 * nv));
        let r = (!jacr.is_null()).then(|| slice_mut(jacr, 3 * nv));
        jacobian::jac(&mv, cdof, com, &point, body as usize, p, r);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_jac(
    m: *const mjModel,
    d: *const mjData,
    jacp: *mut mjtNum,
    jacr: *mut mjtNum,
    point: *const mjtNum,
    body: c_int,
) {
    jac_raw(m, d, jacp, jacr, arr3(point), body)
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacBody(
    m: *const mjModel,
    d: *const mjData,
    jacp: *mut mjtNum,
    jacr: *mut mjtNum,
    body: c_int,
) {
    let Some(i) = checked_id("mj_jacBody", m, d, body, |m| m.nbody) else {
        return;
    };
    jac_raw(m, d, jacp, jacr, arr3((*d).xpos.add(3 * i)), body)
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacBodyCom(
    m: *const mjModel,
    d: *const mjData,
    jacp: *mut mjtNum,
    jacr: *mut mjtNum,
    body: c_int,
) {
    let Some(i) = checked_id("mj_jacBodyCom", m, d, body, |m| m.nbody) else {
        return;
    };
    jac_raw(m, d, jacp, jacr, arr3((*d).xipos.add(3 * i)), body)
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacGeom(
    m: *const mjModel,
    d: *const mjData,
    jacp: *mut mjtNum,
    jacr: *mut mjtNum,
    geom: c_int,
) {
    let Some(g) = checked_id("mj_jacGeom", m, d, geom, |m| m.ngeom) else {
        return;
    };
    jac_raw(
        m,
        d,
        jacp,
        jacr,
        arr3((*d).geom_xpos.add(3 * g)),
        *(*m).geom_bodyid.add(g),
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacSite(
    m: *const mjModel,
    d: *const mjData,
    jacp: *mut mjtNum,
    jacr: *mut mjtNum,
    site: c_int,
) {
    let Some(s) = checked_id("mj_jacSite", m, d, site, |m| m.nsite) else {
        return;
    };
    jac_raw(
        m,
        d,
        jacp,
        jacr,
        arr3((*d).site_xpos.add(3 * s)),
        *(*m).site_bodyid.add(s),
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacSubtreeCom(
    m: *const mjModel,
    d: *mut mjData,
    jacp: *mut mjtNum,
    body: c_int,
) {
    if checked_id("mj_jacSubtreeCom", m, d, body, |m| m.nbody).is_none() {
        return;
    }
    run("mj_jacSubtreeCom", (), m, d, |mv, dv| {
        let nv = mv.raw.nv as usize;
        let mut out = vec![0.0; 3 * nv];
        jacobian::jac_subtree_com(mv, dv, &mut out, body.max(0) as usize)?;
        slice_mut(jacp, 3 * nv).copy_from_slice(&out);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_jacPointAxis(
    m: *const mjModel,
    d: *mut mjData,
    jacPoint: *mut mjtNum,
    jacAxis: *mut mjtNum,
    point: *const mjtNum,
    axis: *const mjtNum,
    body: c_int,
) {
    if checked_id("mj_jacPointAxis", m, d, body, |m| m.nbody).is_none() {
        return;
    }
    let (p, a) = (arr3(point), arr3(axis));
    run("mj_jacPointAxis", (), m, d, |mv, dv| {
        let nv = mv.raw.nv as usize;
        let jp = (!jacPoint.is_null()).then(|| slice_mut(jacPoint, 3 * nv));
        let ja = (!jacAxis.is_null()).then(|| slice_mut(jacAxis, 3 * nv));
        jacobian::jac_point_axis(mv, dv, jp, ja, &p, &a, body.max(0) as usize)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_fullM(m: *const mjModel, dst: *mut mjtNum, M: *const mjtNum) {
    if null_model("mj_fullM", m) {
        return;
    }
    guard("mj_fullM", (), || {
        let mv = Model::new(&*m);
        let nv = mv.raw.nv as usize;
        jacobian::full_m(&mv, slice_mut(dst, nv * nv), slice(M, mv.raw.nM as usize));
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulM(
    m: *const mjModel,
    d: *const mjData,
    res: *mut mjtNum,
    vec: *const mjtNum,
) {
    if null_model("mj_mulM", m) {
        return;
    }
    guard("mj_mulM", (), || {
        let mv = Model::new(&*m);
        let nv = mv.raw.nv as usize;
        let v = input_apart(vec, nv, res, nv);
        jacobian::mul_m(
            &mv,
            slice((*d).qM, mv.raw.nM as usize),
            slice_mut(res, nv),
            &v,
        );
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulM2(
    m: *const mjModel,
    d: *const mjData,
    res: *mut mjtNum,
    vec: *const mjtNum,
) {
    if null_model("mj_mulM2", m) {
        return;
    }
    guard("mj_mulM2", (), || {
        let mv = Model::new(&*m);
        let nv = mv.raw.nv as usize;
        let v = input_apart(vec, nv, res, nv);
        let qld = slice((*d).qLD, mv.raw.nM as usize);
        let sqrt_inv = slice((*d).qLDiagSqrtInv, nv);
        jacobian::mul_m2(&mv, qld, sqrt_inv, slice_mut(res, nv), &v);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_addM(
    m: *const mjModel,
    d: *mut mjData,
    dst: *mut mjtNum,
    rownnz: *mut c_int,
    rowadr: *mut c_int,
    colind: *mut c_int,
) {
    run("mj_addM", (), m, d, |mv, dv| {
        let nv = mv.raw.nv as usize;
        if !rownnz.is_null() && !rowadr.is_null() && !colind.is_null() {
            let rownnz = std::slice::from_raw_parts_mut(rownnz, nv);
            let rowadr = std::slice::from_raw_parts(rowadr as *const c_int, nv);
            // uncompressed rows: each may grow to nv entries
            let len = rowadr
                .iter()
                .map(|&a| a.max(0) as usize + nv)
                .max()
                .unwrap_or(0);
            let colind = std::slice::from_raw_parts_mut(colind, len);
            return jacobian::add_m_sparse(mv, dv, slice_mut(dst, len), rownnz, rowadr, colind);
        }
        jacobian::add_m_dense(mv, dv.qM, slice_mut(dst, nv * nv), true);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_applyFT(
    m: *const mjModel,
    d: *mut mjData,
    force: *const mjtNum,
    torque: *const mjtNum,
    point: *const mjtNum,
    body: c_int,
    qfrc_target: *mut mjtNum,
) {
    let f = (!force.is_null()).then(|| arr3(force));
    let t = (!torque.is_null()).then(|| arr3(torque));
    let p = arr3(point);
    run("mj_applyFT", (), m, d, |mv, dv| {
        let nv = mv.raw.nv as usize;
        let mut q: Vec<f64> = slice(qfrc_target, nv).to_vec();
        forward::apply_ft(
            mv,
            dv,
            f.as_ref(),
            t.as_ref(),
            &p,
            body.max(0) as usize,
            &mut q,
        )?;
        slice_mut(qfrc_target, nv).copy_from_slice(&q);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_name2id(m: *const mjModel, type_: c_int, name: *const c_char) -> c_int {
    if m.is_null() || name.is_null() {
        return -1;
    }
    guard("mj_name2id", -1, || {
        let mv = Model::new(&*m);
        Ok(support::name2id(
            &mv,
            type_,
            std::ffi::CStr::from_ptr(name).to_bytes(),
        ))
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_id2name(m: *const mjModel, type_: c_int, id: c_int) -> *const c_char {
    if m.is_null() {
        return std::ptr::null();
    }
    guard("mj_id2name", std::ptr::null(), || {
        let mv = Model::new(&*m);
        Ok(match support::id2name(&mv, type_, id) {
            Some(adr) => (*m).names.add(adr) as *const c_char,
            None => std::ptr::null(),
        })
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_differentiatePos(
    m: *const mjModel,
    qvel: *mut mjtNum,
    dt: mjtNum,
    qpos1: *const mjtNum,
    qpos2: *const mjtNum,
) {
    if null_model("mj_differentiatePos", m) {
        return;
    }
    guard("mj_differentiatePos", (), || {
        let mv = Model::new(&*m);
        let (nq, nv) = (mv.raw.nq as usize, mv.raw.nv as usize);
        let (p1, p2) = (
            input_apart(qpos1, nq, qvel, nv),
            input_apart(qpos2, nq, qvel, nv),
        );
        integrate::differentiate_pos(&mv, slice_mut(qvel, nv), dt, &p1, &p2);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_integratePos(
    m: *const mjModel,
    qpos: *mut mjtNum,
    qvel: *const mjtNum,
    dt: mjtNum,
) {
    if null_model("mj_integratePos", m) {
        return;
    }
    guard("mj_integratePos", (), || {
        let mv = Model::new(&*m);
        let (nq, nv) = (mv.raw.nq as usize, mv.raw.nv as usize);
        let v = input_apart(qvel, nv, qpos, nq);
        integrate::integrate_pos(&mv, slice_mut(qpos, nq), &v, dt);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_normalizeQuat(m: *const mjModel, qpos: *mut mjtNum) {
    if null_model("mj_normalizeQuat", m) {
        return;
    }
    guard("mj_normalizeQuat", (), || {
        let mv = Model::new(&*m);
        kinematics::normalize_quat(&mv, slice_mut(qpos, mv.raw.nq as usize));
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_local2Global(
    d: *mut mjData,
    xpos: *mut mjtNum,
    xmat: *mut mjtNum,
    pos: *const mjtNum,
    quat: *const mjtNum,
    body: c_int,
    sameframe: mjtByte,
) {
    let b = body.max(0) as usize;
    let d = &*d;
    // the rows up to body b
    let rows = |p: *const f64, n: usize| slice(p, n * (b + 1));
    let frames = support::BodyFrames {
        xpos: rows(d.xpos, 3),
        xmat: rows(d.xmat, 9),
        xquat: rows(d.xquat, 4),
        xipos: rows(d.xipos, 3),
        ximat: rows(d.ximat, 9),
    };
    // each output computed only when asked for, as 2.2.2 does
    if !xpos.is_null() && !pos.is_null() {
        let p = support::local_pos_to_global(&frames, &arr3(pos), b, sameframe);
        slice_mut(xpos, 3).copy_from_slice(&p);
    }
    if !xmat.is_null() && !quat.is_null() {
        let q = crate::math::arr(slice(quat, 4));
        let r = support::local_quat_to_global(&frames, &q, b, sameframe);
        slice_mut(xmat, 9).copy_from_slice(&r);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mj_getTotalmass(m: *const mjModel) -> mjtNum {
    if null_model("mj_getTotalmass", m) {
        return 0.0;
    }
    guard("mj_getTotalmass", 0.0, || {
        Ok(support::total_mass(&Model::new(&*m)))
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_setTotalmass(m: *mut mjModel, newmass: mjtNum) {
    guard("mj_setTotalmass", (), || {
        let mm = ModelMut::new(&mut *m);
        support::set_total_mass(mm.body_mass, mm.body_inertia, newmass);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_warning(d: *mut mjData, warning: c_int, info: c_int) {
    guard("mj_warning", (), || {
        support::warning(&mut *d, warning, info)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_setConst(m: *mut mjModel, d: *mut mjData) {
    if m.is_null() || d.is_null() {
        errmem::error("mj_setConst: NULL model or data");
        return;
    }
    let (mut m, mut d) = super::borrow_boxes(m, d);
    guard("mj_setConst", (), || {
        crate::loader::setconst::set_const(&mut m, &mut d)
    })
}

/// Runs `f` on views of a model and data the C signature declares const (only read).
pub(super) unsafe fn run_const<R>(
    name: &str,
    fallback: R,
    m: *const mjModel,
    d: *const mjData,
    f: impl FnOnce(&Model, &Data) -> Result<R, EngineError>,
) -> R {
    if m.is_null() || d.is_null() {
        errmem::error(&format!("{name}: NULL model or data"));
        return fallback;
    }
    guard(name, fallback, || {
        let mv = Model::new(&*m);
        // the view is only read: nothing is written through the const pointer (but the view
        // kept with the data, the first time)
        match Data::kept(&*m, &*d) {
            Some(dv) => f(&mv, dv),
            None => f(&mv, &Data::new(&*m, &mut *(d as *mut mjData))),
        }
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_subtreeVel(m: *const mjModel, d: *mut mjData) {
    run("mj_subtreeVel", (), m, d, |m, d| {
        engine::velocity::subtree_vel(m, d)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_rnePostConstraint(m: *const mjModel, d: *mut mjData) {
    run(
        "mj_rnePostConstraint",
        (),
        m,
        d,
        engine::rne::rne_post_constraint,
    )
}

/// Checks an object id against the count of its type before a frame lookup.
fn frame_object(
    m: &Model,
    objtype: c_int,
    objid: c_int,
    caller: &str,
) -> Result<usize, EngineError> {
    use mjtObj_::*;
    let n = match objtype {
        x if x == mjOBJ_BODY as c_int || x == mjOBJ_XBODY as c_int => m.raw.nbody,
        x if x == mjOBJ_GEOM as c_int => m.raw.ngeom,
        x if x == mjOBJ_SITE as c_int => m.raw.nsite,
        x if x == mjOBJ_CAMERA as c_int => m.raw.ncam,
        _ => {
            return Err(EngineError(format!(
                "Invalid object type {objtype} in {caller}"
            )))
        }
    };
    if objid < 0 || objid >= n {
        return Err(EngineError(format!(
            "Invalid object id {objid} in {caller}"
        )));
    }
    Ok(objid as usize)
}

#[no_mangle]
pub unsafe extern "C" fn mj_objectVelocity(
    m: *const mjModel,
    d: *const mjData,
    objtype: c_int,
    objid: c_int,
    res: *mut mjtNum,
    flg_local: c_int,
) {
    run_const("mj_objectVelocity", (), m, d, |mv, dv| {
        let id = frame_object(mv, objtype, objid, "mj_objectVelocity")?;
        let v = support::object_velocity(mv, dv, objtype, id, flg_local != 0)?;
        slice_mut(res, 6).copy_from_slice(&v);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_objectAcceleration(
    m: *const mjModel,
    d: *const mjData,
    objtype: c_int,
    objid: c_int,
    res: *mut mjtNum,
    flg_local: c_int,
) {
    run_const("mj_objectAcceleration", (), m, d, |mv, dv| {
        let id = frame_object(mv, objtype, objid, "mj_objectAcceleration")?;
        let v = support::object_acceleration(mv, dv, objtype, id, flg_local != 0)?;
        slice_mut(res, 6).copy_from_slice(&v);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_contactForce(
    m: *const mjModel,
    d: *const mjData,
    id: c_int,
    result: *mut mjtNum,
) {
    run_const("mj_contactForce", (), m, d, |mv, dv| {
        let res = slice_mut(result, 6).try_into().expect("6 values");
        support::contact_force_to(mv, dv, id, res);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_sensorPos(m: *const mjModel, d: *mut mjData) {
    run("mj_sensorPos", (), m, d, engine::sensor::sensor_pos)
}

#[no_mangle]
pub unsafe extern "C" fn mj_sensorVel(m: *const mjModel, d: *mut mjData) {
    run("mj_sensorVel", (), m, d, engine::sensor::sensor_vel)
}

#[no_mangle]
pub unsafe extern "C" fn mj_sensorAcc(m: *const mjModel, d: *mut mjData) {
    run("mj_sensorAcc", (), m, d, engine::sensor::sensor_acc)
}

#[no_mangle]
pub unsafe extern "C" fn mj_inverse(m: *const mjModel, d: *mut mjData) {
    run("mj_inverse", (), m, d, engine::inverse::inverse)
}

#[no_mangle]
pub unsafe extern "C" fn mj_inverseSkip(
    m: *const mjModel,
    d: *mut mjData,
    skipstage: c_int,
    skipsensor: c_int,
) {
    run("mj_inverseSkip", (), m, d, |m, d| {
        engine::inverse::inverse_skip(m, d, skipstage, skipsensor != 0)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_invPosition(m: *const mjModel, d: *mut mjData) {
    run("mj_invPosition", (), m, d, engine::inverse::inv_position)
}

#[no_mangle]
pub unsafe extern "C" fn mj_invVelocity(m: *const mjModel, d: *mut mjData) {
    run("mj_invVelocity", (), m, d, engine::inverse::inv_velocity)
}

#[no_mangle]
pub unsafe extern "C" fn mj_invConstraint(m: *const mjModel, d: *mut mjData) {
    run(
        "mj_invConstraint",
        (),
        m,
        d,
        engine::inverse::inv_constraint,
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_compareFwdInv(m: *const mjModel, d: *mut mjData) {
    run(
        "mj_compareFwdInv",
        (),
        m,
        d,
        engine::inverse::compare_fwd_inv,
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_makeConstraint(m: *const mjModel, d: *mut mjData) {
    run("mj_makeConstraint", (), m, d, constraint::make_constraint)
}

#[no_mangle]
pub unsafe extern "C" fn mj_projectConstraint(m: *const mjModel, d: *mut mjData) {
    run(
        "mj_projectConstraint",
        (),
        m,
        d,
        constraint::project_constraint,
    )
}

#[no_mangle]
pub unsafe extern "C" fn mj_referenceConstraint(m: *const mjModel, d: *mut mjData) {
    run("mj_referenceConstraint", (), m, d, |m, d| {
        constraint::reference_constraint(m, d);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_constraintUpdate(
    m: *const mjModel,
    d: *mut mjData,
    jar: *const mjtNum,
    cost: *mut mjtNum,
    flg_cone_hessian: c_int,
) {
    let nefc = if d.is_null() {
        0
    } else {
        (*d).nefc.max(0) as usize
    };
    let jar: Vec<f64> = slice(jar, nefc).to_vec();
    run("mj_constraintUpdate", (), m, d, |m, d| {
        let c = constraint::constraint_update(m, d, &jar, !cost.is_null(), flg_cone_hessian != 0)?;
        if !cost.is_null() {
            *cost = c;
        }
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_addContact(
    m: *const mjModel,
    d: *mut mjData,
    con: *const mjContact,
) -> c_int {
    run("mj_addContact", 1, m, d, |m, d| {
        if d.raw.ncon >= m.raw.nconmax {
            support::warning(d.raw, mjtWarning_::mjWARN_CONTACTFULL as i32, m.raw.nconmax)?;
            return Ok(1);
        }
        d.contact[d.raw.ncon as usize] = std::ptr::read(con);
        d.raw.ncon += 1;
        Ok(0)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_isPyramidal(m: *const mjModel) -> c_int {
    if null_model("mj_isPyramidal", m) {
        return 0;
    }
    constraint::is_pyramidal(&Model::new(&*m)) as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_isSparse(m: *const mjModel) -> c_int {
    if null_model("mj_isSparse", m) {
        return 0;
    }
    constraint::is_sparse(&Model::new(&*m)) as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_isDual(m: *const mjModel) -> c_int {
    if null_model("mj_isDual", m) {
        return 0;
    }
    constraint::is_dual(&Model::new(&*m)) as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulJacVec(
    m: *const mjModel,
    d: *mut mjData,
    res: *mut mjtNum,
    vec: *const mjtNum,
) {
    if m.is_null() || d.is_null() {
        return;
    }
    let v: Vec<f64> = slice(vec, (*m).nv as usize).to_vec();
    let nefc = (*d).nefc.max(0) as usize;
    run("mj_mulJacVec", (), m, d, |m, d| {
        constraint::mul_jac_vec(m, d, slice_mut(res, nefc), &v)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mju_rayGeom(
    pos: *const mjtNum,
    mat: *const mjtNum,
    size: *const mjtNum,
    pnt: *const mjtNum,
    vec: *const mjtNum,
    geomtype: c_int,
) -> mjtNum {
    guard("mju_rayGeom", -1.0, || {
        let m: [f64; 9] = crate::math::arr(slice(mat, 9));
        engine::ray::ray_geom(
            &arr3(pos),
            &m,
            slice(size, 3),
            &arr3(pnt),
            &arr3(vec),
            geomtype,
        )
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_mulJacTVec(
    m: *const mjModel,
    d: *mut mjData,
    res: *mut mjtNum,
    vec: *const mjtNum,
) {
    if m.is_null() || d.is_null() {
        return;
    }
    let nefc = (*d).nefc.max(0) as usize;
    let v: Vec<f64> = slice(vec, nefc).to_vec();
    let nv = (*m).nv as usize;
    run("mj_mulJacTVec", (), m, d, |m, d| {
        constraint::mul_jac_t_vec(m, d, slice_mut(res, nv), &v)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_rayHfield(
    m: *const mjModel,
    d: *const mjData,
    geomid: c_int,
    pnt: *const mjtNum,
    vec: *const mjtNum,
) -> mjtNum {
    let Some(g) = checked_id("mj_rayHfield", m, d, geomid, |m| m.ngeom) else {
        return -1.0;
    };
    let (p, v) = (arr3(pnt), arr3(vec));
    run_const("mj_rayHfield", -1.0, m, d, |mv, dv| {
        engine::ray_mesh::ray_hfield(mv, dv, g, &p, &v)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_rayMesh(
    m: *const mjModel,
    d: *const mjData,
    geomid: c_int,
    pnt: *const mjtNum,
    vec: *const mjtNum,
) -> mjtNum {
    let Some(g) = checked_id("mj_rayMesh", m, d, geomid, |m| m.ngeom) else {
        return -1.0;
    };
    let (p, v) = (arr3(pnt), arr3(vec));
    run_const("mj_rayMesh", -1.0, m, d, |mv, dv| {
        engine::ray_mesh::ray_mesh(mv, dv, g, &p, &v)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mju_raySkin(
    nface: c_int,
    nvert: c_int,
    face: *const c_int,
    vert: *const f32,
    pnt: *const mjtNum,
    vec: *const mjtNum,
    vertid: *mut c_int,
) -> mjtNum {
    if face.is_null() && nface > 0 || vert.is_null() && nvert > 0 {
        errmem::error("mju_raySkin: NULL face or vertex array");
        return -1.0;
    }
    guard("mju_raySkin", -1.0, || {
        let face: &[i32] = if face.is_null() {
            &[]
        } else {
            std::slice::from_raw_parts(face, 3 * nface.max(0) as usize)
        };
        let vert: &[f32] = if vert.is_null() {
            &[]
        } else {
            std::slice::from_raw_parts(vert, 3 * nvert.max(0) as usize)
        };
        if face.iter().any(|&f| f < 0 || f >= nvert) {
            return Err(EngineError("mju_raySkin: face vertex out of range".into()));
        }
        let (x, id) = engine::ray_mesh::ray_skin(face, vert, &arr3(pnt), &arr3(vec));
        if !vertid.is_null() && id >= 0 {
            *vertid = id;
        }
        Ok(x)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mj_ray(
    m: *const mjModel,
    d: *const mjData,
    pnt: *const mjtNum,
    vec: *const mjtNum,
    geomgroup: *const mjtByte,
    flg_static: mjtByte,
    bodyexclude: c_int,
    geomid: *mut c_int,
) -> mjtNum {
    let (p, v) = (arr3(pnt), arr3(vec));
    let groups = (!geomgroup.is_null()).then(|| std::slice::from_raw_parts(geomgroup, 6));
    run_const("mj_ray", -1.0, m, d, |mv, dv| {
        let (dist, id) = engine::ray::ray(mv, dv, &p, &v, groups, flg_static != 0, bodyexclude)?;
        if !geomid.is_null() {
            *geomid = id;
        }
        Ok(dist)
    })
}

/// The entries of mjCOLLISIONFUNC: contacts of geoms g1, g2 (types in table order) within
/// `margin` into `con`, which must hold mjMAXCONPAIR (50); returns their number. Only the
/// geometric fields (dist, pos, frame) are set, as by 2.2.2's collision functions.
pub unsafe extern "C" fn collide_pair(
    m: *const mjModel,
    d: *const mjData,
    con: *mut mjContact,
    g1: c_int,
    g2: c_int,
    margin: mjtNum,
) -> c_int {
    if con.is_null() || checked_id("mjCOLLISIONFUNC", m, d, g1, |m| m.ngeom).is_none() {
        return 0;
    }
    let Some(g2) = checked_id("mjCOLLISIONFUNC", m, d, g2, |m| m.ngeom) else {
        return 0;
    };
    run_const("mjCOLLISIONFUNC", 0, m, d, |mv, dv| {
        let (g1, t1, t2) = (g1 as usize, mv.geom_type()[g1 as usize], mv.geom_type()[g2]);
        if t1 > t2 || !engine::collision::narrow::has_collider(t1, t2) {
            return Err(EngineError(
                "mjCOLLISIONFUNC: geom types out of table order".into(),
            ));
        }
        let mut buf = [Default::default(); engine::collision::narrow::MAX_CONTACT_PAIR];
        let n = engine::collision::narrow::collide(mv, dv, g1, g2, margin, &mut buf);
        for (k, c) in buf[..n].iter().enumerate() {
            let out = &mut *con.add(k);
            out.dist = c.dist;
            out.pos = c.pos;
            out.frame[..6].copy_from_slice(&c.frame);
        }
        Ok(n as c_int)
    })
}

/// mj_jacDifPair (exported by 2.2.2 outside mujoco.h): Jacobians of points on two bodies and
/// their difference, over the merged dof chain when sparse; returns the chain length (nv dense).
#[no_mangle]
pub unsafe extern "C" fn mj_jacDifPair(
    m: *const mjModel,
    d: *const mjData,
    chain: *mut c_int,
    b1: c_int,
    b2: c_int,
    pos1: *const mjtNum,
    pos2: *const mjtNum,
    jac1p: *mut mjtNum,
    jac2p: *mut mjtNum,
    jacdifp: *mut mjtNum,
    jac1r: *mut mjtNum,
    jac2r: *mut mjtNum,
    jacdifr: *mut mjtNum,
) -> c_int {
    let Some(b1) = checked_id("mj_jacDifPair", m, d, b1, |m| m.nbody) else {
        return 0;
    };
    let Some(b2) = checked_id("mj_jacDifPair", m, d, b2, |m| m.nbody) else {
        return 0;
    };
    let (p1, p2) = (arr3(pos1), arr3(pos2));
    let rot = !jacdifr.is_null();
    run_const("mj_jacDifPair", 0, m, d, |mv, dv| {
        let nv = mv.raw.nv as usize;
        let (mut j1, mut j2, mut jd) = (vec![0.0; 6 * nv], vec![0.0; 6 * nv], vec![0.0; 6 * nv]);
        let mut ch = vec![0i32; nv];
        let n = engine::jacdif::jac_dif_pair(
            mv,
            dv.cdof,
            dv.subtree_com,
            &mut ch,
            b1,
            b2,
            &p1,
            &p2,
            &mut j1,
            &mut j2,
            &mut jd,
            rot,
        );
        let out = |dst: *mut mjtNum, src: &[f64]| {
            if !dst.is_null() {
                slice_mut(dst, 3 * n).copy_from_slice(&src[..3 * n]);
            }
        };
        let simple =
            constraint::is_sparse(mv) && mv.body_simple()[b1] != 0 && mv.body_simple()[b2] != 0;
        if !simple {
            out(jac1p, &j1);
            out(jac2p, &j2);
            if rot {
                out(jac1r, &j1[3 * nv..]);
                out(jac2r, &j2[3 * nv..]);
            }
        }
        out(jacdifp, &jd);
        if rot {
            out(jacdifr, &jd[3 * nv..]);
        }
        if !chain.is_null() && constraint::is_sparse(mv) {
            std::slice::from_raw_parts_mut(chain, n).copy_from_slice(&ch[..n]);
        }
        Ok(n as c_int)
    })
}
