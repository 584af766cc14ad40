//! Analytical derivatives of the smooth forces with respect to qvel (mjd_smooth_vel): actuator
//! gains and biases, dof and tendon damping, fluid forces, and the bias forces of RNE.

use super::actuation::fwd_actuation;
use super::fluid::{ellipsoid_max_moment, geom_semi_axes, inertia_box, local_fluid_velocity};
use super::fluid::{pow2, uses_ellipsoid, GeomFluid};
use super::forward::{fwd_velocity, step, step_skip};
use super::integrate::{differentiate_pos, integrate_pos};
use super::jacdif::is_sparse;
use super::jacobian::jac;
use super::linalg::{add_to, add_to_scl, max, min};
use super::{disabled, Data, EngineError, Model, JNT_BALL, JNT_FREE, MINVAL};
use crate::abi::view::Arena;
use crate::abi::*;
use crate::math::blas::{mul_mat_mat, mul_mat_t_mat, transpose};
use crate::math::*;

// ---------------------------------------------------------------- spatial algebra derivatives

/// Derivatives of a x b with respect to a (`da`) and b (`db`), row-major 3x3.
fn d_cross(a: &Vec3, b: &Vec3) -> (Mat3, Mat3) {
    let mut da = [0.0; 9];
    da[1] = b[2];
    da[2] = -b[1];
    da[3] = -b[2];
    da[5] = b[0];
    da[6] = b[1];
    da[7] = -b[0];
    let mut db = [0.0; 9];
    db[1] = -a[2];
    db[2] = a[1];
    db[3] = a[2];
    db[5] = -a[0];
    db[6] = -a[1];
    db[7] = a[0];
    (da, db)
}

/// Derivative of cross_motion(vel, v) with respect to vel.
fn d_cross_motion_vel(v: &[f64]) -> [f64; 36] {
    let mut d = [0.0; 36];
    d[2] = -v[1];
    d[1] = v[2];
    d[6 + 2] = v[0];
    d[6] = -v[2];
    d[12 + 1] = -v[0];
    d[12] = v[1];
    d[18 + 2] = -v[4];
    d[18 + 1] = v[5];
    d[18 + 5] = -v[1];
    d[18 + 4] = v[2];
    d[24 + 2] = v[3];
    d[24] = -v[5];
    d[24 + 5] = v[0];
    d[24 + 3] = -v[2];
    d[30 + 1] = -v[3];
    d[30] = v[4];
    d[30 + 4] = -v[0];
    d[30 + 3] = v[1];
    d
}

/// Derivative of cross_force(vel, f) with respect to vel.
fn d_cross_force_vel(f: &Vec6) -> [f64; 36] {
    let mut d = [0.0; 36];
    d[2] = -f[1];
    d[1] = f[2];
    d[5] = -f[4];
    d[4] = f[5];
    d[6 + 2] = f[0];
    d[6] = -f[2];
    d[6 + 5] = f[3];
    d[6 + 3] = -f[5];
    d[12 + 1] = -f[0];
    d[12] = f[1];
    d[12 + 4] = -f[3];
    d[12 + 3] = f[4];
    d[18 + 2] = -f[4];
    d[18 + 1] = f[5];
    d[24 + 2] = f[3];
    d[24] = -f[5];
    d[30 + 1] = -f[3];
    d[30] = f[4];
    d
}

/// Derivative of cross_force(vel, f) with respect to f.
fn d_cross_force_frc(vel: &[f64]) -> [f64; 36] {
    let mut d = [0.0; 36];
    d[1] = -vel[2];
    d[2] = vel[1];
    d[4] = -vel[5];
    d[5] = vel[4];
    d[6] = vel[2];
    d[6 + 2] = -vel[0];
    d[6 + 3] = vel[5];
    d[6 + 5] = -vel[3];
    d[12] = -vel[1];
    d[12 + 1] = vel[0];
    d[12 + 3] = -vel[4];
    d[12 + 4] = vel[3];
    d[18 + 4] = -vel[2];
    d[18 + 5] = vel[1];
    d[24 + 3] = vel[2];
    d[24 + 5] = -vel[0];
    d[30 + 3] = -vel[1];
    d[30 + 4] = vel[0];
    d
}

/// Derivative of mul_inert_vec(i, v) with respect to v.
fn d_mul_inert_vec(i: &[f64]) -> [f64; 36] {
    let mut d = [0.0; 36];
    d[0] = i[0];
    d[1] = i[3];
    d[2] = i[4];
    d[4] = -i[8];
    d[5] = i[7];
    d[6] = i[3];
    d[6 + 1] = i[1];
    d[6 + 2] = i[5];
    d[6 + 3] = i[8];
    d[6 + 5] = -i[6];
    d[12] = i[4];
    d[12 + 1] = i[5];
    d[12 + 2] = i[2];
    d[12 + 3] = -i[7];
    d[12 + 4] = i[6];
    d[18 + 1] = i[8];
    d[18 + 2] = -i[7];
    d[18 + 3] = i[9];
    d[24 + 2] = i[6];
    d[24] = -i[8];
    d[24 + 4] = i[9];
    d[30] = i[7];
    d[30 + 1] = -i[6];
    d[30 + 5] = i[9];
    d
}

// ---------------------------------------------------------------- J'*B*J accumulation

/// dfdv += J'*B*J for dense J (n x nv) and B (n x n).
fn add_jtbj(dfdv: &mut [f64], j: &[f64], b: &[f64], n: usize, nv: usize) {
    for r in 0..n {
        for c in 0..n {
            let bv = b[r * n + c];
            if bv == 0.0 {
                continue;
            }
            for k in 0..nv {
                let jv = j[r * nv + k];
                if jv != 0.0 {
                    add_to_scl(
                        &mut dfdv[k * nv..(k + 1) * nv],
                        &j[c * nv..(c + 1) * nv],
                        jv * bv,
                    );
                }
            }
        }
    }
}

/// Row-sparse matrix structure: rows `offset..offset+n` are used.
struct SparseRows<'s> {
    rownnz: &'s [i32],
    rowadr: &'s [i32],
    colind: &'s [i32],
}

/// dfdv += J'*B*J for row-sparse J (rows offset..offset+n) and dense B (n x n).
fn add_jtbj_sparse(
    dfdv: &mut [f64],
    j: &[f64],
    b: &[f64],
    n: usize,
    nv: usize,
    offset: usize,
    s: &SparseRows,
) {
    for r in 0..n {
        for c in 0..n {
            let bv = b[r * n + c];
            if bv == 0.0 {
                continue;
            }
            let (ra, rn) = (s.rowadr[offset + r] as usize, s.rownnz[offset + r] as usize);
            let (ca, cn) = (s.rowadr[offset + c] as usize, s.rownnz[offset + c] as usize);
            for ik in ra..ra + rn {
                let col = s.colind[ik] as usize * nv;
                let scl = j[ik] * bv;
                for jp in ca..ca + cn {
                    dfdv[col + s.colind[jp] as usize] += scl * j[jp];
                }
            }
        }
    }
}

/// Dofs of the kinematic chain of `body` in increasing order; returns their number.
fn body_jac_sparse(m: &Model, body: usize, ind: &mut [i32]) -> usize {
    let mut b = body;
    while b > 0 && m.body_dofnum()[b] == 0 {
        b = m.body_parentid()[b] as usize;
    }
    if b == 0 {
        return 0;
    }
    let last = m.body_dofadr()[b] + m.body_dofnum()[b] - 1;
    let mut nnz = 0;
    let mut dof = last;
    while dof >= 0 {
        nnz += 1;
        dof = m.dof_parentid()[dof as usize];
    }
    let mut cnt = 0;
    dof = last;
    while dof >= 0 {
        ind[nnz - cnt - 1] = dof;
        cnt += 1;
        dof = m.dof_parentid()[dof as usize];
    }
    nnz
}

// ---------------------------------------------------------------- actuators

/// Derivative of the muscle gain with respect to velocity.
fn muscle_gain_vel(len: f64, vel: f64, lengthrange: &[f64], acc0: f64, prm: &[f64]) -> f64 {
    let (r0, r1) = (prm[0], prm[1]);
    let mut force = prm[2];
    let (scale, lmin, lmax, vmax, fvmax) = (prm[3], prm[4], prm[5], prm[6], prm[8]);
    let mx = |a: f64, b: f64| if a > b { a } else { b };
    if force < 0.0 {
        force = scale / mx(MINVAL, acc0);
    }
    let a = 0.5 * (lmin + 1.0);
    let b = 0.5 * (1.0 + lmax);
    let l0 = (lengthrange[1] - lengthrange[0]) / mx(MINVAL, r1 - r0);
    let l = r0 + (len - lengthrange[0]) / mx(MINVAL, l0);
    let v = vel / mx(MINVAL, l0 * vmax);
    let fl = if l >= lmin && l <= a {
        let x = (l - lmin) / mx(MINVAL, a - lmin);
        0.5 * x * x
    } else if l <= 1.0 {
        let x = (1.0 - l) / mx(MINVAL, 1.0 - a);
        1.0 - 0.5 * x * x
    } else if l <= b {
        let x = (l - 1.0) / mx(MINVAL, b - 1.0);
        1.0 - 0.5 * x * x
    } else if l <= lmax {
        let x = (lmax - l) / mx(MINVAL, lmax - b);
        0.5 * x * x
    } else {
        0.0
    };
    let y = fvmax - 1.0;
    let dfv = if v <= -1.0 {
        0.0
    } else if v <= 0.0 {
        2.0 * v + 2.0
    } else if v <= y {
        (-2.0 * v + 2.0 * y) / mx(MINVAL, y)
    } else {
        0.0
    };
    -force * fl * dfv / mx(MINVAL, l0 * vmax)
}

/// dfdv += d qfrc_actuator / d qvel.
fn actuator_vel(m: &Model, d: &Data, dfdv: &mut [f64]) {
    let nv = m.raw.nv as usize;
    let (nu, na) = (m.raw.nu as usize, m.raw.na as usize);
    if disabled(m, mjtDisableBit_::mjDSBL_ACTUATION) {
        return;
    }
    for i in 0..nu {
        let mut bias_vel = 0.0;
        let mut gain_vel = 0.0;
        if m.actuator_biastype()[i] == mjtBias_::mjBIAS_AFFINE as i32 {
            bias_vel = m.actuator_biasprm()[mjNBIAS * i + 2];
        }
        let gt = m.actuator_gaintype()[i];
        if gt == mjtGain_::mjGAIN_AFFINE as i32 {
            gain_vel = m.actuator_gainprm()[mjNGAIN * i + 2];
        } else if gt == mjtGain_::mjGAIN_MUSCLE as i32 {
            gain_vel = muscle_gain_vel(
                d.actuator_length[i],
                d.actuator_velocity[i],
                &m.actuator_lengthrange()[2 * i..2 * i + 2],
                m.actuator_acc0()[i],
                &m.actuator_gainprm()[mjNGAIN * i..mjNGAIN * (i + 1)],
            );
        }
        if gain_vel != 0.0 {
            if m.actuator_dyntype()[i] == mjtDyn_::mjDYN_NONE as i32 {
                bias_vel += gain_vel * d.ctrl[i];
            } else {
                bias_vel += gain_vel * d.act[i + na - nu];
            }
        }
        if bias_vel != 0.0 {
            add_jtbj(
                dfdv,
                &d.actuator_moment[i * nv..(i + 1) * nv],
                &[bias_vel],
                1,
                nv,
            );
        }
    }
}

// ---------------------------------------------------------------- fluid forces

/// Adds the 3x3 block `blk` to the 6x6 `b` at block row `col_quad`, block column `row_quad`.
fn add_to_quadrant(b: &mut [f64; 36], blk: &Mat3, col_quad: usize, row_quad: usize) {
    let (r, c) = (3 * row_quad, 3 * col_quad);
    for k in 0..3 {
        for l in 0..3 {
            b[6 * (c + k) + r + l] += blk[3 * k + l];
        }
    }
}

fn d_added_mass(b: &mut [f64; 36], lvel: &Vec6, rho: f64, vm: &Vec3, vi: &Vec3) {
    let lin = v3(&lvel[3..]);
    let ang = v3(&lvel[..3]);
    let lin_mom = [
        rho * vm[0] * lin[0],
        rho * vm[1] * lin[1],
        rho * vm[2] * lin[2],
    ];
    let ang_mom = [
        rho * vi[0] * ang[0],
        rho * vi[1] * ang[1],
        rho * vi[2] * ang[2],
    ];

    let (mut da, db) = d_cross(&ang_mom, &ang);
    add_to_quadrant(b, &db, 0, 0);
    for i in 0..9 {
        da[i] *= rho * vi[i % 3];
    }
    add_to_quadrant(b, &da, 0, 0);

    let (mut da, db) = d_cross(&lin_mom, &lin);
    add_to_quadrant(b, &db, 0, 1);
    for i in 0..9 {
        da[i] *= rho * vm[i % 3];
    }
    add_to_quadrant(b, &da, 0, 1);

    let (mut da, db) = d_cross(&lin_mom, &ang);
    add_to_quadrant(b, &db, 1, 0);
    for i in 0..9 {
        da[i] *= rho * vm[i % 3];
    }
    add_to_quadrant(b, &da, 1, 1);
}

/// res[k] += vec[k]*s for a 3-row of a 3x3 matrix.
#[inline]
fn add_row_scl(row: &mut [f64], vec: &Vec3, s: f64) {
    for k in 0..3 {
        row[k] += vec[k] * s;
    }
}

/// Lengths (max, mid) of the ellipsoid semi-axes.
fn max_mid(s: &Vec3) -> (f64, f64) {
    let d_max = max(max(s[0], s[1]), s[2]);
    let d_min = min(min(s[0], s[1]), s[2]);
    (d_max, s[0] + s[1] + s[2] - d_max - d_min)
}

fn d_viscous_torque(lvel: &Vec6, rho: f64, visc: f64, s: &Vec3, slender: f64, angc: f64) -> Mat3 {
    let (d_max, d_mid) = max_mid(s);
    let eq_d = 2.0 / 3.0 * (s[0] + s[1] + s[2]);
    let lin_visc_torque = PI * eq_d * eq_d * eq_d;
    let i_max = 8.0 / 15.0 * PI * d_mid * (d_max * d_max) * (d_max * d_max);
    let ii = [
        ellipsoid_max_moment(s, 0),
        ellipsoid_max_moment(s, 1),
        ellipsoid_max_moment(s, 2),
    ];
    let (x, y, z) = (lvel[0], lvel[1], lvel[2]);
    let coef = [
        angc * ii[0] + slender * (i_max - ii[0]),
        angc * ii[1] + slender * (i_max - ii[1]),
        angc * ii[2] + slender * (i_max - ii[2]),
    ];
    let mom_visc = [x * coef[0], y * coef[1], z * coef[2]];
    let density = rho / max(MINVAL, norm3(&mom_visc));
    let sq = [
        -density * x * coef[0] * coef[0],
        -density * y * coef[1] * coef[1],
        -density * z * coef[2] * coef[2],
    ];
    let lin_coef = visc * lin_visc_torque;
    let mut dm = [0.0; 9];
    let diag = x * sq[0] + y * sq[1] + z * sq[2] - lin_coef;
    dm[0] = diag;
    dm[4] = diag;
    dm[8] = diag;
    add_row_scl(&mut dm[0..3], &sq, x);
    add_row_scl(&mut dm[3..6], &sq, y);
    add_row_scl(&mut dm[6..9], &sq, z);
    dm
}

fn d_viscous_drag(lvel: &Vec6, rho: f64, visc: f64, s: &Vec3, blunt: f64, slender: f64) -> Mat3 {
    let (d_max, d_mid) = max_mid(s);
    let eq_d = 2.0 / 3.0 * (s[0] + s[1] + s[2]);
    let a_max = PI * d_max * d_mid;
    let a = pow2(s[1] * s[2]);
    let b = pow2(s[2] * s[0]);
    let c = pow2(s[0] * s[1]);
    let (aa, bb, cc) = (a * a, b * b, c * c);
    let (x, y, z) = (lvel[3], lvel[4], lvel[5]);
    let (xx, yy, zz, xy, yz, xz) = (x * x, y * y, z * z, x * y, y * z, x * z);
    let proj_denom = aa * xx + bb * yy + cc * zz;
    let proj_num = a * xx + b * yy + c * zz;
    let da_coef = PI / max(MINVAL, (proj_num * proj_num * proj_num * proj_denom).sqrt());
    let a_proj = PI * (proj_denom / max(MINVAL, proj_num)).sqrt();
    let norm = (xx + yy + zz).sqrt();
    let inv_norm = 1.0 / max(MINVAL, norm);
    let lin_coef = visc * 3.0 * PI * eq_d;
    let quad_coef = rho * (a_proj * blunt + slender * (a_max - a_proj));
    let aproj_coef = rho * norm * (blunt - slender);
    let da = [
        aproj_coef * da_coef * a * x * (b * yy * (a - b) + c * zz * (a - c)),
        aproj_coef * da_coef * b * y * (a * xx * (b - a) + c * zz * (b - c)),
        aproj_coef * da_coef * c * z * (a * xx * (c - a) + b * yy * (c - b)),
    ];
    let mut dm = [xx, xy, xz, xy, yy, yz, xz, yz, zz];
    let inner = xx + yy + zz;
    dm[0] += inner;
    dm[4] += inner;
    dm[8] += inner;
    let sc = -quad_coef * inv_norm;
    for v in dm.iter_mut() {
        *v *= sc;
    }
    add_row_scl(&mut dm[0..3], &da, -x);
    add_row_scl(&mut dm[3..6], &da, -y);
    add_row_scl(&mut dm[6..9], &da, -z);
    dm[0] -= lin_coef;
    dm[4] -= lin_coef;
    dm[8] -= lin_coef;
    dm
}

fn d_kutta_lift(lvel: &Vec6, rho: f64, s: &Vec3, kutta: f64) -> Mat3 {
    let a = pow2(s[1] * s[2]);
    let b = pow2(s[2] * s[0]);
    let c = pow2(s[0] * s[1]);
    let (aa, bb, cc) = (a * a, b * b, c * c);
    let (x, y, z) = (lvel[3], lvel[4], lvel[5]);
    let (xx, yy, zz, xy, yz, xz) = (x * x, y * y, z * z, x * y, y * z, x * z);
    let proj_denom = aa * xx + bb * yy + cc * zz;
    let proj_num = a * xx + b * yy + c * zz;
    let norm2 = xx + yy + zz;
    let df_denom = PI * kutta * rho / max(MINVAL, (proj_denom * proj_num * norm2).sqrt());
    let dfx = yy * (a - b) + zz * (a - c);
    let dfy = xx * (b - a) + zz * (b - c);
    let dfz = xx * (c - a) + yy * (c - b);
    let proj_term = proj_num / max(MINVAL, proj_denom);
    let cos_term = proj_num / max(MINVAL, norm2);
    // [b, c] - a, [a, c] - b, [a, b] - c on the rows, zero diagonal (a, b, c are finite)
    let mut dm = [0.0, b - a, c - a, a - b, 0.0, c - b, a - c, b - c, 0.0];
    let s2 = 2.0 * proj_num;
    for v in dm.iter_mut() {
        *v *= s2;
    }
    let inner = [
        aa * proj_term - a + cos_term,
        bb * proj_term - b + cos_term,
        cc * proj_term - c + cos_term,
    ];
    add_row_scl(&mut dm[0..3], &inner, dfx);
    add_row_scl(&mut dm[3..6], &inner, dfy);
    add_row_scl(&mut dm[6..9], &inner, dfz);
    let outer = [xx, xy, xz, xy, yy, yz, xz, yz, zz];
    for k in 0..9 {
        dm[k] *= outer[k];
    }
    dm[0] -= dfx * proj_num;
    dm[4] -= dfy * proj_num;
    dm[8] -= dfz * proj_num;
    for v in dm.iter_mut() {
        *v *= df_denom;
    }
    dm
}

fn d_magnus(b: &mut [f64; 36], lvel: &Vec6, rho: f64, s: &Vec3, magnus: f64) {
    let volume = 4.0 / 3.0 * PI * s[0] * s[1] * s[2];
    let coef = magnus * rho * volume;
    let lin = [coef * lvel[3], coef * lvel[4], coef * lvel[5]];
    let ang = [coef * lvel[0], coef * lvel[1], coef * lvel[2]];
    let (d_ang, d_lin) = d_cross(&ang, &lin);
    add_to_quadrant(b, &d_ang, 1, 0);
    add_to_quadrant(b, &d_lin, 1, 1);
}

/// Jacobian workspace of one body: J (6 x nv, rotation rows first), compressed to the body's
/// chain when sparse, with its row structure.
struct BodyJac<'s> {
    j: &'s mut [f64],
    tmp: &'s mut [f64],
    rownnz: [i32; 6],
    rowadr: [i32; 6],
    colind: &'s mut [i32],
    nnz: usize,
    sparse: bool,
}

impl BodyJac<'_> {
    /// Compresses J to the chain columns (sparse) and rotates both halves into frame `mat`.
    fn finish(&mut self, nv: usize, mat: &Mat3) {
        let nnz = self.nnz;
        if self.sparse {
            for r in 0..6 {
                for k in 0..nnz {
                    self.j[r * nnz + k] = self.j[r * nv + self.colind[k] as usize];
                }
            }
        }
        for half in 0..2 {
            let blk = &mut self.j[3 * nnz * half..3 * nnz * (half + 1)];
            mul_mat_t_mat(self.tmp, mat, blk, 3, 3, nnz);
            blk.copy_from_slice(&self.tmp[..3 * nnz]);
        }
    }

    /// dfdv += J_r' * b * J_c over rows `r0..r0+n` of J (b is n x n).
    fn add(&self, dfdv: &mut [f64], b: &[f64], n: usize, r0: usize, nv: usize) {
        if self.sparse {
            let s = SparseRows {
                rownnz: &self.rownnz,
                rowadr: &self.rowadr,
                colind: self.colind,
            };
            add_jtbj_sparse(dfdv, self.j, b, n, nv, r0, &s);
        } else {
            add_jtbj(dfdv, &self.j[r0 * nv..], b, n, nv);
        }
    }
}

impl<'s> BodyJac<'s> {
    /// Workspace for bodies of `m`, from the arena (reused for every body): 2.2.2's 15 nv of
    /// stack per body, 21 nv for the ellipsoid model (`ellipsoid`: some body uses it).
    fn new(m: &Model, a: &mut Arena<'s>, ellipsoid: bool) -> Result<Self, EngineError> {
        let nv = m.raw.nv as usize;
        let bj = BodyJac {
            j: a.alloc(6 * nv)?,
            tmp: a.alloc(3 * nv)?,
            rownnz: [0; 6],
            rowadr: [0; 6],
            colind: a.alloc_int(6 * nv)?,
            nnz: nv,
            sparse: is_sparse(m),
        };
        if ellipsoid {
            // its compressed column indices: not needed here, taken for the stack's count
            a.alloc_int_stale(6 * nv)?;
        }
        Ok(bj)
    }

    /// Sets the row structure for `body` (sparse: its chain of dofs in every row).
    fn set_body(&mut self, m: &Model, body: usize) {
        if !self.sparse {
            return;
        }
        let nnz = body_jac_sparse(m, body, self.colind);
        self.nnz = nnz;
        for r in 0..6 {
            self.rownnz[r] = nnz as i32;
            self.rowadr[r] = (r * nnz) as i32;
        }
        // the chain stays in the first row, copies follow for the other rows
        for r in 1..6 {
            for k in 0..nnz {
                self.colind[r * nnz + k] = self.colind[k];
            }
        }
    }
}

/// Inertia-box fluid model of body `b`: dfdv += d force / d qvel.
fn inertia_box_fluid_vel(m: &Model, d: &Data, bj: &mut BodyJac, dfdv: &mut [f64], b: usize) {
    let nv = m.raw.nv as usize;
    let bx = inertia_box(m, b);
    let pos = v3(&d.xipos[3 * b..]);
    let mat = m9(&d.ximat[9 * b..]);
    let lvel = local_fluid_velocity(m, d, b, &pos, &mat);
    bj.set_body(m, b);
    {
        let (rot, tran) = bj.j.split_at_mut(3 * nv);
        jac(m, d.cdof, d.subtree_com, &pos, b, Some(tran), Some(rot));
    }
    bj.finish(nv, &mat);
    let (rho, visc) = (m.raw.opt.density, m.raw.opt.viscosity);
    if visc > 0.0 {
        let diam = (bx[0] + bx[1] + bx[2]) / 3.0;
        let bv = -PI * diam * diam * diam * visc;
        for r in 0..3 {
            bj.add(dfdv, &[bv], 1, r, nv);
        }
        let bv = -3.0 * PI * diam * visc;
        for r in 0..3 {
            bj.add(dfdv, &[bv], 1, 3 + r, nv);
        }
    }
    if rho > 0.0 {
        let p4 = |x: f64| x * x * x * x;
        let bv = -rho * bx[0] * (p4(bx[1]) + p4(bx[2])) * 2.0 * lvel[0].abs() / 64.0;
        bj.add(dfdv, &[bv], 1, 0, nv);
        let bv = -rho * bx[1] * (p4(bx[0]) + p4(bx[2])) * 2.0 * lvel[1].abs() / 64.0;
        bj.add(dfdv, &[bv], 1, 1, nv);
        let bv = -rho * bx[2] * (p4(bx[0]) + p4(bx[1])) * 2.0 * lvel[2].abs() / 64.0;
        bj.add(dfdv, &[bv], 1, 2, nv);
        let bv = -0.5 * rho * bx[1] * bx[2] * 2.0 * lvel[3].abs();
        bj.add(dfdv, &[bv], 1, 3, nv);
        let bv = -0.5 * rho * bx[0] * bx[2] * 2.0 * lvel[4].abs();
        bj.add(dfdv, &[bv], 1, 4, nv);
        let bv = -0.5 * rho * bx[0] * bx[1] * 2.0 * lvel[5].abs();
        bj.add(dfdv, &[bv], 1, 5, nv);
    }
}

/// Ellipsoid fluid model of the geoms of body `b`: dfdv += d force / d qvel.
fn ellipsoid_fluid_vel(m: &Model, d: &Data, bj: &mut BodyJac, dfdv: &mut [f64], b: usize) {
    let nv = m.raw.nv as usize;
    bj.set_body(m, b);
    let (rho, visc) = (m.raw.opt.density, m.raw.opt.viscosity);
    for g in m.body_geoms(b) {
        let s = geom_semi_axes(m, g);
        let c = GeomFluid::read(m, g);
        if c.interaction == 0.0 {
            continue;
        }
        let pos = v3(&d.geom_xpos[3 * g..]);
        let mat = m9(&d.geom_xmat[9 * g..]);
        let lvel = local_fluid_velocity(m, d, b, &pos, &mat);
        {
            let (rot, tran) = bj.j.split_at_mut(3 * nv);
            let gb = m.geom_bodyid()[g] as usize;
            jac(m, d.cdof, d.subtree_com, &pos, gb, Some(tran), Some(rot));
        }
        bj.finish(nv, &mat);

        let mut bm = [0.0; 36];
        d_magnus(&mut bm, &lvel, rho, &s, c.magnus_lift);
        add_to_quadrant(&mut bm, &d_kutta_lift(&lvel, rho, &s, c.kutta_lift), 1, 1);
        let dd = d_viscous_drag(&lvel, rho, visc, &s, c.blunt_drag, c.slender_drag);
        add_to_quadrant(&mut bm, &dd, 1, 1);
        let dt = d_viscous_torque(&lvel, rho, visc, &s, c.slender_drag, c.ang_drag);
        add_to_quadrant(&mut bm, &dt, 0, 0);
        d_added_mass(&mut bm, &lvel, rho, &c.virtual_mass, &c.virtual_inertia);
        bj.add(dfdv, &bm, 6, 0, nv);
    }
}

// ---------------------------------------------------------------- passive forces

/// dfdv += d qfrc_passive / d qvel (mjd_passive_vel).
pub fn passive_vel(m: &Model, d: &mut Data, dfdv: &mut [f64]) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_PASSIVE) {
        return Ok(());
    }
    for i in 0..nv {
        dfdv[i * (nv + 1)] -= m.dof_damping()[i];
    }
    for i in 0..m.raw.ntendon as usize {
        let damping = m.tendon_damping()[i];
        if damping > 0.0 {
            let b = [-damping];
            if is_sparse(m) {
                let s = SparseRows {
                    rownnz: d.ten_J_rownnz,
                    rowadr: d.ten_J_rowadr,
                    colind: d.ten_J_colind,
                };
                add_jtbj_sparse(dfdv, d.ten_J, &b, 1, nv, i, &s);
            } else {
                add_jtbj(dfdv, &d.ten_J[i * nv..(i + 1) * nv], &b, 1, nv);
            }
        }
    }
    if m.raw.opt.viscosity > 0.0 || m.raw.opt.density > 0.0 {
        let fluid = |b: &usize| m.body_mass()[*b] >= MINVAL;
        let ellipsoid = (1..m.raw.nbody as usize)
            .filter(fluid)
            .any(|b| uses_ellipsoid(m, b));
        d.with_scratch(|d, a| -> Result<(), EngineError> {
            let mut bj = BodyJac::new(m, a, ellipsoid)?;
            for b in (1..m.raw.nbody as usize).filter(fluid) {
                if uses_ellipsoid(m, b) {
                    ellipsoid_fluid_vel(m, d, &mut bj, dfdv, b);
                } else {
                    inertia_box_fluid_vel(m, d, &mut bj, dfdv, b);
                }
            }
            Ok(())
        })?;
    }
    Ok(())
}

// ---------------------------------------------------------------- bias forces (RNE)

/// Columns `lo..hi` of a body's derivative blocks that can be nonzero: its dofs and its
/// ancestors' (dofs lie in depth-first order, so those in between are zeros). Everything else
/// in the blocks is +0, as 2.2.2's full-width products leave it while their factors are
/// finite; from the first that is not (`wide`), the products run over the whole width.
#[derive(Clone, Copy)]
struct Cols {
    lo: usize,
    hi: usize,
}

impl Cols {
    /// The columns of body i's blocks once all its dofs are in: from its topmost ancestor
    /// with dofs to its own last one (an empty range for a body with none on its path).
    fn of(m: &Model, i: usize) -> Cols {
        let (parent, adr, num) = (m.body_parentid(), m.body_dofadr(), m.body_dofnum());
        let (mut lo, mut hi) = (usize::MAX, 0);
        let mut b = i;
        while b > 0 {
            if num[b] > 0 {
                lo = adr[b] as usize;
                hi = hi.max(lo + num[b] as usize);
            }
            b = parent[b] as usize;
        }
        Cols { lo: lo.min(hi), hi }
    }
}

/// res (6 x nv) = mat (6 x 6) * src (6 x nv) as mul_mat_mat computes it (each element's terms
/// in order, zeros of mat skipped), over the columns `cols` while mat is finite (elsewhere the
/// terms are zeros: the result there is +0), else (and from then on: `wide`) over all.
fn times6(res: &mut [f64], mat: &[f64; 36], src: &[f64], nv: usize, cols: Cols, wide: &mut bool) {
    // an exponent of all ones: infinite or NaN
    const EXP: u64 = 0x7ff0_0000_0000_0000;
    *wide |= mat
        .iter()
        .fold(false, |a, x| a | (x.to_bits() & EXP == EXP));
    if *wide {
        mul_mat_mat(res, mat, src, 6, 6, nv);
        return;
    }
    res[..6 * nv].fill(0.0);
    let Cols { lo, hi } = cols;
    let mut c = lo;
    while c + 4 <= hi {
        times6_cols::<4>(res, mat, src, nv, c);
        c += 4;
    }
    if c + 2 <= hi {
        times6_cols::<2>(res, mat, src, nv, c);
        c += 2;
    }
    if c < hi {
        times6_cols::<1>(res, mat, src, nv, c);
    }
}

/// row[c..c+W] += src[k][c..c+W] * s[k] for k = 0..6 in turn (src: 6 rows of nv), the sums
/// held in registers.
#[inline(always)]
fn sub_rows<const W: usize>(row: &mut [f64], src: &[f64], s: &[f64; 6], nv: usize, c: usize) {
    let mut acc: [f64; W] = row[c..c + W].try_into().unwrap();
    for k in 0..6 {
        for q in 0..W {
            acc[q] += src[k * nv + c + q] * s[k];
        }
    }
    row[c..c + W].copy_from_slice(&acc);
}

/// Columns c..c+W of `times6`, each row's sums held in registers over k.
#[inline(always)]
fn times6_cols<const W: usize>(res: &mut [f64], mat: &[f64; 36], src: &[f64], nv: usize, c: usize) {
    let v: [[f64; W]; 6] =
        std::array::from_fn(|k| src[k * nv + c..k * nv + c + W].try_into().unwrap());
    for i in 0..6 {
        let mut acc = [0.0; W];
        for k in 0..6 {
            let s = mat[i * 6 + k];
            if s != 0.0 {
                for q in 0..W {
                    acc[q] += v[k][q] * s;
                }
            }
        }
        res[i * nv + c..i * nv + c + W].copy_from_slice(&acc);
    }
}

/// Derivatives of cvel (nbody x 6 x nv) and cdof_dot (nv x 6 x nv) with respect to qvel.
/// Only the world's block of dcvel need be zero on entry; every other is written.
fn com_vel_vel(m: &Model, d: &Data, dcvel: &mut [f64], dcdofdot: &mut [f64], wide: &mut bool) {
    let nv = m.raw.nv as usize;
    let blk = 6 * nv;
    let add_cdof = |dcvel: &mut [f64], i: usize, j: usize, n: usize| {
        for k in 0..6 {
            for q in 0..n {
                dcvel[i * blk + k * nv + j + q] += d.cdof[(j + q) * 6 + k];
            }
        }
    };
    for i in 1..m.raw.nbody as usize {
        let p = m.body_parentid()[i] as usize;
        dcvel.copy_within(p * blk..(p + 1) * blk, i * blk);
        let start = m.body_dofadr()[i].max(0) as usize;
        let end = start + m.body_dofnum()[i] as usize;
        // the columns so far: the parent's, then each dof's as it comes in
        let mut cols = Cols::of(m, p);
        let take = |cols: &mut Cols, j: usize, n: usize| {
            *cols = Cols {
                lo: if cols.hi > cols.lo { cols.lo } else { j },
                hi: j + n,
            };
        };
        let mut j = start;
        while j < end {
            let t = m.jnt_type()[m.dof_jntid()[j] as usize];
            if t == JNT_FREE || t == JNT_BALL {
                if t == JNT_FREE {
                    dcdofdot[j * blk..(j + 3) * blk].fill(0.0);
                    add_cdof(dcvel, i, j, 3);
                    take(&mut cols, j, 3);
                    j += 3;
                }
                for k in 0..3 {
                    let mat = d_cross_motion_vel(&d.cdof[6 * (j + k)..]);
                    let src = &dcvel[i * blk..(i + 1) * blk];
                    times6(&mut dcdofdot[(j + k) * blk..], &mat, src, nv, cols, wide);
                }
                add_cdof(dcvel, i, j, 3);
                take(&mut cols, j, 3);
                j += 3;
            } else {
                let mat = d_cross_motion_vel(&d.cdof[6 * j..]);
                let src = &dcvel[i * blk..(i + 1) * blk];
                times6(&mut dcdofdot[j * blk..], &mat, src, nv, cols, wide);
                add_cdof(dcvel, i, j, 1);
                take(&mut cols, j, 1);
                j += 1;
            }
        }
    }
}

#[cfg(not(test))]
fn full_width() -> bool {
    false
}

#[cfg(test)]
fn full_width() -> bool {
    tests::FULL_WIDTH.with(|f| f.get())
}

/// dfdv -= d qfrc_bias / d qvel.
fn rne_vel(m: &Model, d: &mut Data, dfdv: &mut [f64]) -> Result<(), EngineError> {
    d.with_scratch(|d, a| rne_vel_in(m, d, a, dfdv))
}

fn rne_vel_in(m: &Model, d: &mut Data, a: &mut Arena, dfdv: &mut [f64]) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let nbody = m.raw.nbody as usize;
    let blk = 6 * nv;
    // every block is written before it is read (the world's zeroed here)
    let dcvel = a.alloc_stale(nbody * blk)?;
    let dcdofdot = a.alloc_stale(nv * blk)?;
    let dcacc = a.alloc_stale(nbody * blk)?;
    let dcfrc = a.alloc_stale(nbody * blk)?;
    dcvel[..blk].fill(0.0);
    dcacc[..blk].fill(0.0);
    let mut wide = full_width();
    com_vel_vel(m, d, dcvel, dcdofdot, &mut wide);
    for i in 1..nbody {
        let p = m.body_parentid()[i] as usize;
        let cols = Cols::of(m, i);
        dcacc.copy_within(p * blk..(p + 1) * blk, i * blk);
        let acc = &mut dcacc[i * blk..(i + 1) * blk];
        let start = m.body_dofadr()[i].max(0) as usize;
        for j in start..start + m.body_dofnum()[i] as usize {
            for k in 0..6 {
                acc[k * nv + j] += d.cdof_dot[j * 6 + k];
            }
            // the terms past the columns are zeros while qvel is finite
            wide |= !d.qvel[j].is_finite();
            let (lo, hi) = if wide { (0, nv) } else { (cols.lo, cols.hi) };
            for k in 0..6 {
                let (r, src) = (k * nv + lo..k * nv + hi, &dcdofdot[j * blk..(j + 1) * blk]);
                add_to_scl(&mut acc[r.clone()], &src[r], d.qvel[j]);
            }
        }

        let cinert = &d.cinert[10 * i..10 * i + 10];
        let dmul = d_mul_inert_vec(cinert);
        let (head, rest) = dcfrc.split_at_mut(i * blk);
        let body = &mut rest[..blk];
        times6(body, &dmul, acc, nv, cols, &mut wide);

        let cvel = &d.cvel[6 * i..6 * i + 6];
        let tmp = mul_inert_vec(cinert, &v6(cvel));
        let mut mat = d_cross_force_vel(&tmp);
        let mat1 = d_cross_force_frc(cvel);
        // mat1 * dmul, every column
        let mut mat2 = [0.0; 36];
        times6_cols::<4>(&mut mat2, &mat1, &dmul, 6, 0);
        times6_cols::<2>(&mut mat2, &mat1, &dmul, 6, 4);
        add_to(&mut mat, &mat2);

        let world = &mut head[..blk];
        times6(
            world,
            &mat,
            &dcvel[i * blk..(i + 1) * blk],
            nv,
            cols,
            &mut wide,
        );
        add_to(body, world);
    }
    dcfrc[..blk].fill(0.0);
    for i in (1..nbody).rev() {
        let p = m.body_parentid()[i] as usize;
        if p != 0 {
            let (head, rest) = dcfrc.split_at_mut(i * blk);
            add_to(&mut head[p * blk..(p + 1) * blk], &rest[..blk]);
        }
    }
    // dfdv row i -= the six rows of its body's dcfrc times cdof_i, each element's in order
    for i in 0..nv {
        let b = m.dof_bodyid()[i] as usize;
        let frc = &dcfrc[b * blk..(b + 1) * blk];
        let s: [f64; 6] = std::array::from_fn(|k| -d.cdof[i * 6 + k]);
        let row = &mut dfdv[i * nv..(i + 1) * nv];
        let mut c = 0;
        while c + 4 <= nv {
            sub_rows::<4>(row, frc, &s, nv, c);
            c += 4;
        }
        for c in c..nv {
            sub_rows::<1>(row, frc, &s, nv, c);
        }
    }
    Ok(())
}

/// d.qDeriv = d (qfrc_actuator + qfrc_passive - qfrc_bias) / d qvel on the D_* sparsity
/// (mjd_smooth_vel).
pub fn smooth_vel(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    // dfdv stays to the caller's release; the nested stages free theirs
    let dfdv = d.arena.alloc(nv * nv)?;
    actuator_vel(m, d, dfdv);
    passive_vel(m, d, dfdv)?;
    rne_vel(m, d, dfdv)?;
    for i in 0..nv {
        let adr = d.D_rowadr[i] as usize;
        for a in adr..adr + d.D_rownnz[i] as usize {
            d.qDeriv[a] = dfdv[i * nv + d.D_colind[a] as usize];
        }
    }
    Ok(())
}

/// dfdv += forward-difference d qfrc_passive / d qvel (mjd_passive_velFD); expects the
/// velocity stage to be current.
pub fn passive_vel_fd(
    m: &Model,
    d: &mut Data,
    eps: f64,
    dfdv: &mut [f64],
) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let base = d.arena.alloc(nv)?;
    let fd = d.arena.alloc(nv)?;
    base.copy_from_slice(&d.qfrc_passive[..nv]);
    for i in 0..nv {
        let save = d.qvel[i];
        d.qvel[i] = save + eps;
        fwd_velocity(m, d)?;
        d.qvel[i] = save;
        for j in 0..nv {
            fd[j] = (d.qfrc_passive[j] - base[j]) * (1.0 / eps);
        }
        for j in 0..nv {
            dfdv[j * nv + i] += fd[j];
        }
    }
    fwd_velocity(m, d)
}

/// qfrc_actuator + qfrc_passive - qfrc_bias after the velocity and actuation stages.
fn smooth_force(m: &Model, d: &mut Data, out: &mut [f64]) -> Result<(), EngineError> {
    fwd_velocity(m, d)?;
    fwd_actuation(m, d)?;
    for j in 0..out.len() {
        out[j] = d.qfrc_actuator[j] + d.qfrc_passive[j];
    }
    for j in 0..out.len() {
        out[j] -= d.qfrc_bias[j];
    }
    Ok(())
}

/// Centered-difference approximation of smooth_vel on the D_* sparsity (mjd_smooth_velFD).
pub fn smooth_vel_fd(m: &Model, d: &mut Data, eps: f64) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let plus = d.arena.alloc(nv)?;
    let minus = d.arena.alloc(nv)?;
    let fd = d.arena.alloc(nv)?;
    let cnt = d.arena.alloc_int(nv)?;
    for i in 0..nv {
        let save = d.qvel[i];
        d.qvel[i] = save + eps;
        smooth_force(m, d, plus)?;
        d.qvel[i] = save - eps;
        smooth_force(m, d, minus)?;
        d.qvel[i] = save;
        for j in 0..nv {
            fd[j] = (plus[j] - minus[j]) * (0.5 / eps);
        }
        for j in 0..nv {
            let adr = (d.D_rowadr[j] + cnt[j]) as usize;
            if cnt[j] < d.D_rownnz[j] && d.D_colind[adr] == i as i32 {
                d.qDeriv[adr] = fd[j];
                cnt[j] += 1;
            }
        }
    }
    if (0..nv).any(|i| cnt[i] != d.D_rownnz[i]) {
        return Err(EngineError(
            "error in constructing FD sparse derivative".into(),
        ));
    }
    fwd_velocity(m, d)?;
    fwd_actuation(m, d)
}

// ---------------------------------------------------------------- finite-differenced transitions

/// Runs a closure on a fresh view of the data (so each step starts with an empty arena).
pub type WithData<'h> =
    dyn FnMut(&mut dyn FnMut(&mut Data) -> Result<(), EngineError>) -> Result<(), EngineError> + 'h;

/// Outputs of `step_fd`, each optional, rows per input (transposed control-theory layout).
#[derive(Default)]
pub struct StepFd<'o> {
    pub dydq: Option<&'o mut [f64]>,
    pub dydv: Option<&'o mut [f64]>,
    pub dyda: Option<&'o mut [f64]>,
    pub dydu: Option<&'o mut [f64]>,
    pub dsdq: Option<&'o mut [f64]>,
    pub dsdv: Option<&'o mut [f64]>,
    pub dsda: Option<&'o mut [f64]>,
    pub dsdu: Option<&'o mut [f64]>,
}

fn get_state(m: &Model, d: &Data, state: &mut [f64], sensor: Option<&mut [f64]>) {
    let (nq, nv, na) = (m.raw.nq as usize, m.raw.nv as usize, m.raw.na as usize);
    state[..nq].copy_from_slice(&d.qpos[..nq]);
    state[nq..nq + nv].copy_from_slice(&d.qvel[..nv]);
    state[nq + nv..nq + nv + na].copy_from_slice(&d.act[..na]);
    if let Some(s) = sensor {
        let ns = m.raw.nsensordata as usize;
        s[..ns].copy_from_slice(&d.sensordata[..ns]);
    }
}

fn set_state(m: &Model, d: &mut Data, state: &[f64], ctrl: Option<&[f64]>, warm: Option<&[f64]>) {
    let (nq, nv, na) = (m.raw.nq as usize, m.raw.nv as usize, m.raw.na as usize);
    d.qpos[..nq].copy_from_slice(&state[..nq]);
    d.qvel[..nv].copy_from_slice(&state[nq..nq + nv]);
    d.act[..na].copy_from_slice(&state[nq + nv..nq + nv + na]);
    if let Some(c) = ctrl {
        d.ctrl.copy_from_slice(c);
    }
    if let Some(w) = warm {
        d.qacc_warmstart[..nv].copy_from_slice(w);
    }
}

/// dx = (x2 - x1) / h.
fn diff(dx: &mut [f64], x1: &[f64], x2: &[f64], h: f64, n: usize) {
    let inv_h = 1.0 / h;
    for i in 0..n {
        dx[i] = inv_h * (x2[i] - x1[i]);
    }
}

/// ds = (s2 - s1) / h on the state manifold.
fn state_diff(m: &Model, ds: &mut [f64], s1: &[f64], s2: &[f64], h: f64) {
    let (nq, nv, na) = (m.raw.nq as usize, m.raw.nv as usize, m.raw.na as usize);
    if nq == nv {
        diff(ds, s1, s2, h, nq + nv + na);
    } else {
        differentiate_pos(m, &mut ds[..nv], h, &s1[..nq], &s2[..nq]);
        diff(&mut ds[nv..], &s1[nq..], &s2[nq..], h, nv + na);
    }
}

/// Forward, backward or centered difference of sensor vectors (centered as 2.2.2 computes it).
fn clamped_diff(
    dx: &mut [f64],
    x: &[f64],
    plus: Option<&[f64]>,
    minus: Option<&[f64]>,
    h: f64,
    n: usize,
) {
    match (plus, minus) {
        (Some(p), None) => diff(dx, x, p, h, n),
        (None, Some(mi)) => diff(dx, mi, x, h, n),
        (Some(p), Some(mi)) => diff(dx, p, mi, 2.0 * h, n),
        (None, None) => dx[..n].fill(0.0),
    }
}

fn clamped_state_diff(
    m: &Model,
    ds: &mut [f64],
    s: &[f64],
    plus: Option<&[f64]>,
    minus: Option<&[f64]>,
    h: f64,
) {
    match (plus, minus) {
        (Some(p), None) => state_diff(m, ds, s, p, h),
        (None, Some(mi)) => state_diff(m, ds, mi, s, h),
        (Some(p), Some(mi)) => state_diff(m, ds, mi, p, 2.0 * h),
        (None, None) => {
            // 2.2.2 zeroes nq+nv+na values from the row (past it when nq > nv: into the next
            // row, which is written after, or past the last row's end): within the output here
            let n = (m.raw.nq + m.raw.nv + m.raw.na) as usize;
            let n = n.min(ds.len());
            ds[..n].fill(0.0)
        }
    }
}

fn in_range(x1: f64, x2: f64, r: &[f64]) -> bool {
    x1 >= r[0] && x1 <= r[1] && x2 >= r[0] && x2 <= r[1]
}

/// Which input a finite-difference pass nudges.
#[derive(Clone, Copy)]
enum Input {
    Act,
    Vel,
    Pos,
}

/// Finite-differenced Jacobians of the next state and the sensors of mj_step (mjd_stepFD).
pub fn step_fd(
    m: &Model,
    with: &mut WithData,
    eps: f64,
    centered: bool,
    out: StepFd,
) -> Result<(), EngineError> {
    let (nq, nv, na, nu) = (
        m.raw.nq as usize,
        m.raw.nv as usize,
        m.raw.na as usize,
        m.raw.nu as usize,
    );
    let ns = m.raw.nsensordata as usize;
    let nx = nq + nv + na;
    let ndx = 2 * nv + na;
    let mut state = vec![0.0; nx];
    let mut next = vec![0.0; nx];
    let mut next_plus = vec![0.0; nx];
    let mut next_minus = vec![0.0; nx];
    let use_warm = !disabled(m, mjtDisableBit_::mjDSBL_WARMSTART);
    let mut warm = vec![0.0; nv];
    let StepFd {
        dydq,
        dydv,
        dyda,
        dydu,
        dsdq,
        dsdv,
        dsda,
        dsdu,
    } = out;
    let skipsensor = dsdq.is_none() && dsdv.is_none() && dsda.is_none() && dsdu.is_none();
    let mut sensor = vec![0.0; ns];
    let mut sensor_plus = vec![0.0; ns];
    let mut sensor_minus = vec![0.0; ns];
    let mut ctrl = vec![0.0; nu];
    let dpos = std::cell::RefCell::new(vec![0.0; nv]);

    // the buffers live on the heap; the stack counts what 2.2.2 takes for them (states,
    // warm start, sensors, controls, and the position nudge in the position pass), so the
    // nudged steps run at its stack depth
    let base = 4 * nx + if use_warm { nv } else { 0 } + if skipsensor { 0 } else { 3 * ns } + nu;
    let dpos_words = std::cell::Cell::new(0);
    let outer = with;
    let with = &mut |f: &mut dyn FnMut(&mut Data) -> Result<(), EngineError>| {
        outer(&mut |d| {
            d.arena.alloc_stale(base + dpos_words.get())?;
            f(d)
        })
    };

    with(&mut |d| {
        ctrl.copy_from_slice(&d.ctrl[..nu]);
        get_state(m, d, &mut state, None);
        if use_warm {
            warm.copy_from_slice(&d.qacc_warmstart[..nv]);
        }
        Ok(())
    })?;
    let warm_opt = use_warm.then_some(&warm[..]);
    with(&mut |d| {
        step(m, d)?;
        get_state(m, d, &mut next, (!skipsensor).then_some(&mut sensor[..]));
        set_state(m, d, &state, Some(&ctrl), warm_opt);
        Ok(())
    })?;

    // one nudged step: `nudge` edits the data, the result lands in (nx, sens)
    let mut nudged = |nudge: &dyn Fn(&mut Data) -> Result<(), EngineError>,
                      skipstage: mjtStage_,
                      reset_ctrl: bool,
                      nx_out: &mut [f64],
                      sens: &mut [f64]|
     -> Result<(), EngineError> {
        with(&mut |d| {
            nudge(d)?;
            step_skip(m, d, skipstage as i32, skipsensor)?;
            get_state(m, d, nx_out, (!skipsensor).then_some(&mut *sens));
            let c = reset_ctrl.then_some(&ctrl[..]);
            set_state(m, d, &state, c, warm_opt);
            Ok(())
        })
    };

    if dydu.is_some() || dsdu.is_some() {
        let (mut dydu, mut dsdu) = (dydu, dsdu);
        for i in 0..nu {
            let limited = m.actuator_ctrllimited()[i] != 0;
            let range = &m.actuator_ctrlrange()[2 * i..2 * i + 2];
            let fwd = !limited || in_range(ctrl[i], ctrl[i] + eps, range);
            if fwd {
                nudged(
                    &|d: &mut Data| {
                        d.ctrl[i] += eps;
                        Ok(())
                    },
                    mjtStage_::mjSTAGE_VEL,
                    true,
                    &mut next_plus,
                    &mut sensor_plus,
                )?;
            }
            let back = (centered || !fwd) && (!limited || in_range(ctrl[i] - eps, ctrl[i], range));
            if back {
                nudged(
                    &|d: &mut Data| {
                        d.ctrl[i] -= eps;
                        Ok(())
                    },
                    mjtStage_::mjSTAGE_VEL,
                    true,
                    &mut next_minus,
                    &mut sensor_minus,
                )?;
            }
            if let Some(o) = dydu.as_deref_mut() {
                clamped_state_diff(
                    m,
                    &mut o[i * ndx..],
                    &next,
                    fwd.then_some(&next_plus[..]),
                    back.then_some(&next_minus[..]),
                    eps,
                );
            }
            if let Some(o) = dsdu.as_deref_mut() {
                clamped_diff(
                    &mut o[i * ns..],
                    &sensor,
                    fwd.then_some(&sensor_plus[..]),
                    back.then_some(&sensor_minus[..]),
                    eps,
                    ns,
                );
            }
        }
    }

    let passes = [
        (Input::Act, dyda, dsda, na, mjtStage_::mjSTAGE_VEL),
        (Input::Vel, dydv, dsdv, nv, mjtStage_::mjSTAGE_POS),
        (Input::Pos, dydq, dsdq, nv, mjtStage_::mjSTAGE_NONE),
    ];
    for (input, mut dy, mut ds, n, skip) in passes {
        if dy.is_none() && ds.is_none() {
            continue;
        }
        if matches!(input, Input::Pos) {
            dpos_words.set(nv);
        }
        for i in 0..n {
            let nudge = |d: &mut Data, sgn: f64| -> Result<(), EngineError> {
                match input {
                    Input::Act => d.act[i] += sgn * eps,
                    Input::Vel => d.qvel[i] += sgn * eps,
                    Input::Pos => pos_nudge(m, d, &mut dpos.borrow_mut(), i, sgn * eps),
                }
                Ok(())
            };
            nudged(
                &|d| nudge(d, 1.0),
                skip,
                false,
                &mut next_plus,
                &mut sensor_plus,
            )?;
            if centered {
                nudged(
                    &|d| nudge(d, -1.0),
                    skip,
                    false,
                    &mut next_minus,
                    &mut sensor_minus,
                )?;
            }
            if let Some(o) = dy.as_deref_mut() {
                if centered {
                    state_diff(m, &mut o[i * ndx..], &next_minus, &next_plus, 2.0 * eps);
                } else {
                    state_diff(m, &mut o[i * ndx..], &next, &next_plus, eps);
                }
            }
            if let Some(o) = ds.as_deref_mut() {
                if centered {
                    diff(&mut o[i * ns..], &sensor_minus, &sensor_plus, 2.0 * eps, ns);
                } else {
                    diff(&mut o[i * ns..], &sensor, &sensor_plus, eps, ns);
                }
            }
        }
    }
    Ok(())
}

/// qpos moved by `h` along dof `i` (a unit velocity integrated over h).
fn pos_nudge(m: &Model, d: &mut Data, dpos: &mut [f64], i: usize, h: f64) {
    dpos.fill(0.0);
    dpos[i] = 1.0;
    integrate_pos(m, d.qpos, dpos, h);
}

/// Transition matrices A, B, C, D of mj_step by finite differences (mjd_transitionFD).
#[allow(clippy::too_many_arguments)]
pub fn transition_fd(
    m: &Model,
    with: &mut WithData,
    eps: f64,
    centered: bool,
    a: Option<&mut [f64]>,
    b: Option<&mut [f64]>,
    c: Option<&mut [f64]>,
    dm: Option<&mut [f64]>,
) -> Result<(), EngineError> {
    let (nv, na, nu) = (m.raw.nv as usize, m.raw.na as usize, m.raw.nu as usize);
    let ns = m.raw.nsensordata as usize;
    let ndx = 2 * nv + na;
    let mut at = vec![0.0; if a.is_some() { ndx * ndx } else { 0 }];
    let mut bt = vec![0.0; if b.is_some() { nu * ndx } else { 0 }];
    let mut ct = vec![0.0; if c.is_some() { ndx * ns } else { 0 }];
    let mut dt = vec![0.0; if dm.is_some() { nu * ns } else { 0 }];
    // the stack counts the transposed matrices as 2.2.2 takes them there
    let words = at.len() + bt.len() + ct.len() + dt.len();
    let outer = with;
    let with = &mut |f: &mut dyn FnMut(&mut Data) -> Result<(), EngineError>| {
        outer(&mut |d| {
            d.arena.alloc_stale(words)?;
            f(d)
        })
    };
    let mut out = StepFd::default();
    if a.is_some() {
        let (q, rest) = at.split_at_mut(ndx * nv);
        let (v, act) = rest.split_at_mut(ndx * nv);
        (out.dydq, out.dydv, out.dyda) = (Some(q), Some(v), Some(act));
    }
    if c.is_some() {
        let (q, rest) = ct.split_at_mut(ns * nv);
        let (v, act) = rest.split_at_mut(ns * nv);
        (out.dsdq, out.dsdv, out.dsda) = (Some(q), Some(v), Some(act));
    }
    if b.is_some() {
        out.dydu = Some(&mut bt);
    }
    if dm.is_some() {
        out.dsdu = Some(&mut dt);
    }
    step_fd(m, with, eps, centered, out)?;
    if let Some(a) = a {
        transpose(a, &at, ndx, ndx);
    }
    if let Some(b) = b {
        transpose(b, &bt, nu, ndx);
    }
    if let Some(c) = c {
        transpose(c, &ct, ndx, ns);
    }
    if let Some(dm) = dm {
        transpose(dm, &dt, nu, ns);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    thread_local! {
        /// Set: the velocity derivatives of the bias forces over every column, as 2.2.2.
        pub static FULL_WIDTH: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    }

    /// The velocity derivative of the bias forces over each body's own columns gives 2.2.2's
    /// over every column, bit for bit: two trees (free, ball, hinge and slide joints, welded
    /// bodies, branches) in random states, some with NaN or infinite velocities or positions.
    #[test]
    fn bias_derivative_over_ancestor_columns_as_over_all() {
        let xml = r#"<mujoco><option integrator="implicit"/><worldbody>
          <body><freejoint/><geom size=".1" mass="1"/>
            <body pos=".2 0 0"><joint type="ball"/><geom size=".1" mass=".5"/>
              <body pos=".2 0 0"><geom size=".05" mass=".2"/>
                <body pos="0 .2 0"><joint axis="0 1 0"/><joint type="slide" axis="1 0 0"/>
                  <geom size=".05" mass=".1"/></body></body></body>
            <body pos="0 .3 0"><joint axis="1 0 0"/><geom size=".1" mass=".3"/>
              <body pos="0 .2 0"><joint axis="0 0 1"/><geom size=".1" mass=".3"/></body></body>
          </body>
          <body pos="1 0 0"><joint axis="0 1 0"/><geom size=".1" mass="1"/>
            <body pos=".2 0 0"><joint type="ball"/><geom size=".1" mass=".4"/></body></body>
        </worldbody></mujoco>"#;
        let model = crate::api::Model::from_xml_str(xml).unwrap();
        let mut data = model.make_data().unwrap();
        let (nq, nv) = (model.raw().nq as usize, model.raw().nv as usize);
        let qpos0 = data.qpos().to_vec();
        let mut uniform = crate::math::tests::uniform(99);
        let mut odd = 0;
        for k in 0..300 {
            let mut q: Vec<f64> = (0..nq).map(|i| qpos0[i] + uniform() - 0.5).collect();
            let mut v: Vec<f64> = (0..nv).map(|_| 4.0 * (uniform() - 0.5)).collect();
            match k % 10 {
                1 => v[k % nv] = f64::NAN,
                2 => v[k % nv] = f64::INFINITY,
                3 => q[k % nq] = f64::NAN,
                4 => v[k % nv] = 0.0,
                _ => {}
            }
            let derivs = [false, true].map(|full| {
                data.qpos_mut().copy_from_slice(&q);
                data.qvel_mut().copy_from_slice(&v);
                FULL_WIDTH.with(|f| f.set(full));
                let got = data
                    .with_core(|m, d| {
                        crate::engine::forward::fwd_position(m, d)?;
                        crate::engine::forward::fwd_velocity(m, d)?;
                        d.arena.scope(|a| {
                            let scratch = a.alloc_int(nv)?;
                            let (nnz, adr, ind) =
                                (&mut *d.D_rownnz, &mut *d.D_rowadr, &mut *d.D_colind);
                            crate::engine::integrate::make_m_sparse(m, nnz, adr, ind, scratch)
                        })?;
                        super::smooth_vel(m, d)?;
                        let n = d.D_rownnz[..nv].iter().sum::<i32>() as usize;
                        Ok(d.qDeriv[..n]
                            .iter()
                            .map(|x| x.to_bits())
                            .collect::<Vec<_>>())
                    })
                    .unwrap();
                FULL_WIDTH.with(|f| f.set(false));
                got
            });
            assert_eq!(derivs[0], derivs[1], "state {k}");
            odd += derivs[0].iter().any(|&x| !f64::from_bits(x).is_finite()) as usize;
        }
        assert!(odd > 30, "{odd} states with derivatives not finite");
    }
}
