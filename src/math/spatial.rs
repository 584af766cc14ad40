//! 6D spatial vectors [rotation; translation] and 10-element com inertias.

use super::misc::weighted;
use super::vec3::{cross, mul_mat_t_vec3, sub3};
use super::{v3, Mat3, Vec3, Vec6};

/// Moves a motion (flg_force false) or force vector from `oldpos` to `newpos`,
/// then rotates it by rotnew2old^T when given.
pub fn transform_spatial(
    vec: &Vec6,
    flg_force: bool,
    newpos: &Vec3,
    oldpos: &Vec3,
    rotnew2old: Option<&Mat3>,
) -> Vec6 {
    let mut tran = *vec;
    let dif = sub3(newpos, oldpos);
    let (top, bot) = (v3(&vec[..3]), v3(&vec[3..]));
    if flg_force {
        let c = cross(&dif, &bot);
        tran[..3].copy_from_slice(&sub3(&top, &c));
    } else {
        let c = cross(&dif, &top);
        tran[3..].copy_from_slice(&sub3(&bot, &c));
    }
    match rotnew2old {
        Some(r) => {
            let mut res = [0.0; 6];
            res[..3].copy_from_slice(&mul_mat_t_vec3(r, &v3(&tran[..3])));
            res[3..].copy_from_slice(&mul_mat_t_vec3(r, &v3(&tran[3..])));
            res
        }
        None => tran,
    }
}

/// Motion cross product v x u.
pub fn cross_motion(v: &Vec6, u: &Vec6) -> Vec6 {
    let mut r = [
        -v[2] * u[1] + v[1] * u[2],
        v[2] * u[0] - v[0] * u[2],
        -v[1] * u[0] + v[0] * u[1],
        -v[2] * u[4] + v[1] * u[5],
        v[2] * u[3] - v[0] * u[5],
        -v[1] * u[3] + v[0] * u[4],
    ];
    r[3] += -v[5] * u[1] + v[4] * u[2];
    r[4] += v[5] * u[0] - v[3] * u[2];
    r[5] += -v[4] * u[0] + v[3] * u[1];
    r
}

/// Force cross product v x* f.
pub fn cross_force(v: &Vec6, f: &Vec6) -> Vec6 {
    let mut r = [
        -v[2] * f[1] + v[1] * f[2],
        v[2] * f[0] - v[0] * f[2],
        -v[1] * f[0] + v[0] * f[1],
        -v[2] * f[4] + v[1] * f[5],
        v[2] * f[3] - v[0] * f[5],
        -v[1] * f[3] + v[0] * f[4],
    ];
    r[0] += -v[5] * f[4] + v[4] * f[5];
    r[1] += v[5] * f[3] - v[3] * f[5];
    r[2] += -v[4] * f[3] + v[3] * f[4];
    r
}

/// Com-frame inertia (10 numbers) of a body with principal `inert`, orientation `mat`,
/// offset `dif` from the com and `mass`.
pub fn inert_com(inert: &Vec3, mat: &Mat3, dif: &Vec3, mass: f64) -> [f64; 10] {
    let t = [
        mat[0] * inert[0],
        mat[3] * inert[0],
        mat[6] * inert[0],
        mat[1] * inert[1],
        mat[4] * inert[1],
        mat[7] * inert[1],
        mat[2] * inert[2],
        mat[5] * inert[2],
        mat[8] * inert[2],
    ];
    let mut r = [0.0; 10];
    r[0] = mat[0] * t[0] + mat[1] * t[3] + mat[2] * t[6];
    r[1] = mat[3] * t[1] + mat[4] * t[4] + mat[5] * t[7];
    r[2] = mat[6] * t[2] + mat[7] * t[5] + mat[8] * t[8];
    r[3] = mat[0] * t[1] + mat[1] * t[4] + mat[2] * t[7];
    r[4] = mat[0] * t[2] + mat[1] * t[5] + mat[2] * t[8];
    r[5] = mat[3] * t[2] + mat[4] * t[5] + mat[5] * t[8];
    r[0] += mass * (dif[1] * dif[1] + dif[2] * dif[2]);
    r[1] += mass * (dif[0] * dif[0] + dif[2] * dif[2]);
    r[2] += mass * (dif[0] * dif[0] + dif[1] * dif[1]);
    r[3] -= mass * dif[0] * dif[1];
    r[4] -= mass * dif[0] * dif[2];
    r[5] -= mass * dif[1] * dif[2];
    r[6] = mass * dif[0];
    r[7] = mass * dif[1];
    r[8] = mass * dif[2];
    r[9] = mass;
    r
}

/// Com inertia (10 numbers) times a spatial vector.
pub fn mul_inert_vec(i: &[f64], v: &Vec6) -> Vec6 {
    [
        i[0] * v[0] + i[3] * v[1] + i[4] * v[2] - i[8] * v[4] + i[7] * v[5],
        i[3] * v[0] + i[1] * v[1] + i[5] * v[2] + i[8] * v[3] - i[6] * v[5],
        i[4] * v[0] + i[5] * v[1] + i[2] * v[2] - i[7] * v[3] + i[6] * v[4],
        i[8] * v[1] - i[7] * v[2] + i[9] * v[3],
        i[6] * v[2] - i[8] * v[0] + i[9] * v[4],
        i[7] * v[0] - i[6] * v[1] + i[9] * v[5],
    ]
}

/// Motion axis in the com frame: hinge (with offset) or slide.
pub fn dof_com(axis: &Vec3, offset: Option<&Vec3>) -> Vec6 {
    match offset {
        Some(o) => {
            let c = cross(axis, o);
            [axis[0], axis[1], axis[2], c[0], c[1], c[2]]
        }
        None => [0.0, 0.0, 0.0, axis[0], axis[1], axis[2]],
    }
}

/// Sum of `n` 6D rows of `dofs` weighted by `vec` (mju_mulDofVec; zero weights skipped:
/// `weighted`). Inlined: its result read back from memory just written stalled.
#[inline(always)]
pub fn mul_dof_vec(dofs: &[f64], vec: &[f64], n: usize) -> Vec6 {
    let mut r = [0.0; 6];
    if n == 1 {
        for k in 0..6 {
            r[k] = dofs[k] * vec[0];
        }
    } else if n > 1 {
        for (row, &s) in dofs[..6 * n].chunks_exact(6).zip(&vec[..n]) {
            for k in 0..6 {
                r[k] += weighted(row[k], s);
            }
        }
    }
    r
}

/// Orthonormal frame from a normal (rows 0..3) and an optional tangent hint (rows 3..6).
/// Returns None when the normal is shorter than 0.5 (MuJoCo raises an error then).
pub fn make_frame(frame: &Mat3) -> Option<Mat3> {
    use super::vec3::{dot3, norm3, normalize3, scl3};
    let (x, n) = normalize3(&v3(&frame[..3]));
    if n < 0.5 {
        return None;
    }
    let mut y = v3(&frame[3..6]);
    if norm3(&y) < 0.5 {
        y = if x[1] < 0.5 && x[1] > -0.5 {
            [0.0, 1.0, 0.0]
        } else {
            [0.0, 0.0, 1.0]
        };
    }
    let t = scl3(&x, dot3(&x, &y));
    let y = normalize3(&sub3(&y, &t)).0;
    let z = cross(&x, &y);
    Some([x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]])
}
