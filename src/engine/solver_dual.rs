//! Block operations of the dual solvers on contacts: the diagonal block of AR, the residual of
//! a block, the cost change of a block update, the elliptic-cone update of PGS and the friction
//! updates of noslip (pyramid edge pairs, elliptic tangents) through the QCQP.

use super::{Data, EngineError};
use crate::math::blas::{dot, mul_mat_vec, sub};
use crate::math::misc::max;
use crate::math::qcqp::{qcqp, qcqp2, qcqp3};
use crate::math::sparse::dot_sparse;
use crate::math::MINVAL;

/// The n x n block of AR at (start, start); with `sub_r`, R off the diagonal, clamped at 1e-10.
pub fn extract_block(
    d: &Data,
    sparse: bool,
    ac: &mut [f64],
    start: usize,
    n: usize,
    sub_r: bool,
) -> Result<(), EngineError> {
    let nefc = d.raw.nefc as usize;
    if sparse {
        let adr = d.efc_AR_rowadr[start] as usize;
        let nnz = d.efc_AR_rownnz[start] as usize;
        let k = (0..nnz)
            .find(|&k| d.efc_AR_colind[adr + k] == start as i32)
            .ok_or_else(|| EngineError("Internal error in extractComponent".into()))?;
        for j in 0..n {
            let a = d.efc_AR_rowadr[start + j] as usize + k;
            ac[j * n..(j + 1) * n].copy_from_slice(&d.efc_AR[a..a + n]);
        }
    } else {
        for j in 0..n {
            let a = start + (start + j) * nefc;
            ac[j * n..(j + 1) * n].copy_from_slice(&d.efc_AR[a..a + n]);
        }
    }
    if sub_r {
        for j in 0..n {
            ac[j * (n + 1)] -= d.efc_R[start + j];
            ac[j * (n + 1)] = max(1e-10, ac[j * (n + 1)]);
        }
    }
    Ok(())
}

/// res = b + AR*force over rows i..i+dim (with `sub_r`, minus R*force).
pub fn residual(d: &Data, sparse: bool, res: &mut [f64], i: usize, dim: usize, sub_r: bool) {
    let nefc = d.raw.nefc as usize;
    for j in 0..dim {
        let r = i + j;
        res[j] = d.efc_b[r]
            + if sparse {
                let adr = d.efc_AR_rowadr[r] as usize;
                let n = d.efc_AR_rownnz[r] as usize;
                dot_sparse(&d.efc_AR[adr..], d.efc_force, n, &d.efc_AR_colind[adr..])
            } else {
                dot(&d.efc_AR[r * nefc..], d.efc_force, nefc)
            };
    }
    if sub_r {
        for j in 0..dim {
            res[j] -= d.efc_R[i + j] * d.efc_force[i + j];
        }
    }
}

/// Cost change of a block update; an increase (> 1e-10) restores the old force and counts 0.
pub fn cost_change(a: &[f64], force: &mut [f64], old: &[f64], res: &[f64], dim: usize) -> f64 {
    let change = if dim == 1 {
        let delta = force[0] - old[0];
        0.5 * delta * delta * a[0] + delta * res[0]
    } else {
        let (mut delta, mut v) = ([0.0; 6], [0.0; 6]);
        sub(&mut delta[..dim], &force[..dim], &old[..dim]);
        mul_mat_vec(&mut v, a, &delta, dim, dim);
        0.5 * dot(&delta, &v, dim) + dot(&delta, res, dim)
    };
    if change > 1e-10 {
        force[..dim].copy_from_slice(&old[..dim]);
        return 0.0;
    }
    change
}

/// Tangential forces v (n = dim-1) minimizing the block's quadratic inside the friction
/// ellipse of normal force fn_, put on the ellipse when the bound is active.
fn friction_qcqp(v: &mut [f64; 6], ac: &[f64], bc: &[f64], mu: &[f64], fnormal: f64, n: usize) {
    let active = match n {
        2 => {
            let (x, act) = qcqp2(ac, bc, mu, fnormal);
            v[..2].copy_from_slice(&x);
            act
        }
        3 => {
            let (x, act) = qcqp3(ac, bc, mu, fnormal);
            v[..3].copy_from_slice(&x);
            act
        }
        _ => qcqp(&mut v[..], ac, bc, mu, fnormal, n).unwrap_or(false),
    };
    if active {
        let mut s = 0.0;
        for j in 0..n {
            s += v[j] * v[j] / (mu[j] * mu[j]);
        }
        let s = (fnormal * fnormal / max(MINVAL, s)).sqrt();
        for x in &mut v[..n] {
            *x *= s;
        }
    }
}

/// PGS update of the elliptic contact at rows i..i+dim: normal or ray update, then the
/// friction update with the normal fixed. `athis` receives the AR block (for the cost change).
#[allow(clippy::too_many_arguments)]
pub fn pgs_elliptic(
    d: &mut Data,
    sparse: bool,
    i: usize,
    dim: usize,
    arinv: f64,
    res: &[f64],
    old: &[f64],
    athis: &mut [f64; 36],
) -> Result<(), EngineError> {
    let mu = d.contact[d.efc_id[i] as usize].friction;
    extract_block(d, sparse, athis, i, dim, false)?;
    let force = &mut d.efc_force[i..i + dim];
    if force[0] < MINVAL {
        force[0] -= res[0] * arinv;
        if force[0] < 0.0 {
            force[0] = 0.0;
        }
        force[1..].fill(0.0);
    } else {
        let mut v = [0.0; 6];
        v[..dim].copy_from_slice(force);
        let mut v1 = [0.0; 6];
        mul_mat_vec(&mut v1, &athis[..], &v, dim, dim);
        let denom = dot(&v, &v1, dim);
        if denom >= MINVAL {
            let mut x = -dot(&v, res, dim) / denom;
            if force[0] + x * v[0] < 0.0 {
                x = -v[0] / force[0];
            }
            for j in 0..dim {
                force[j] += x * v[j];
            }
        }
    }
    let n = dim - 1;
    let (mut ac, mut bc) = ([0.0; 25], [0.0; 5]);
    bc[..n].copy_from_slice(&res[1..dim]);
    for j in 0..n {
        ac[j * n..(j + 1) * n].copy_from_slice(&athis[(j + 1) * dim + 1..(j + 1) * dim + 1 + n]);
        bc[j] -= dot(&ac[j * n..], &old[1..], n);
        bc[j] += athis[(j + 1) * dim] * (force[0] - old[0]);
    }
    if force[0] < MINVAL {
        force[1..].fill(0.0);
    } else {
        let mut v = [0.0; 6];
        friction_qcqp(&mut v, &ac, &bc, &mu, force[0], n);
        force[1..].copy_from_slice(&v[..n]);
    }
    Ok(())
}

/// Noslip update of a pyramidal contact's edge pairs from row i, accumulating `improvement`.
pub fn noslip_pyramid(
    d: &mut Data,
    sparse: bool,
    i: usize,
    dim: usize,
    improvement: &mut f64,
) -> Result<(), EngineError> {
    let mut j = i;
    while j < i + 2 * (dim - 1) {
        let (mut res, mut old, mut ac, mut bc) = ([0.0; 2], [0.0; 2], [0.0; 4], [0.0; 2]);
        residual(d, sparse, &mut res, j, 2, true);
        old.copy_from_slice(&d.efc_force[j..j + 2]);
        extract_block(d, sparse, &mut ac, j, 2, true)?;
        bc.copy_from_slice(&res);
        for k in 0..2 {
            bc[k] -= dot(&ac[k * 2..], &old, 2);
        }
        let f = &mut d.efc_force[j..j + 2];
        let mid = 0.5 * (f[0] + f[1]);
        let k1 = ac[0] + ac[3] - ac[1] - ac[2];
        let k0 = mid * (ac[0] - ac[3]) + bc[0] - bc[1];
        if k1 < MINVAL {
            f[0] = mid;
            f[1] = mid;
        } else {
            let y = -k0 / k1;
            if y < -mid {
                f[0] = 0.0;
                f[1] = 2.0 * mid;
            } else if y > mid {
                f[0] = 2.0 * mid;
                f[1] = 0.0;
            } else {
                f[0] = mid + y;
                f[1] = mid - y;
            }
        }
        *improvement -= cost_change(&ac, f, &old, &res, 2);
        j += 2;
    }
    Ok(())
}

/// Noslip update of an elliptic contact's tangential forces (rows i+1..i+dim); returns the
/// improvement.
pub fn noslip_elliptic(
    d: &mut Data,
    sparse: bool,
    i: usize,
    dim: usize,
) -> Result<f64, EngineError> {
    let mu = d.contact[d.efc_id[i] as usize].friction;
    let n = dim - 1;
    let (mut res, mut old, mut ac, mut bc) = ([0.0; 5], [0.0; 5], [0.0; 25], [0.0; 5]);
    residual(d, sparse, &mut res, i + 1, n, true);
    old[..n].copy_from_slice(&d.efc_force[i + 1..i + dim]);
    extract_block(d, sparse, &mut ac, i + 1, n, true)?;
    bc[..n].copy_from_slice(&res[..n]);
    for j in 0..n {
        bc[j] -= dot(&ac[j * n..], &old, n);
    }
    let fnormal = d.efc_force[i];
    let f = &mut d.efc_force[i + 1..i + dim];
    if fnormal < MINVAL {
        f.fill(0.0);
    } else {
        let mut v = [0.0; 6];
        friction_qcqp(&mut v, &ac, &bc, &mu, fnormal, n);
        f.copy_from_slice(&v[..n]);
    }
    Ok(-cost_change(&ac, f, &old, &res, n))
}
