//! 3D vectors and 3x3 matrices.

use super::misc::weighted;
use super::{Mat3, Vec3, MINVAL};

#[inline]
pub fn add3(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

#[inline]
pub fn sub3(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
pub fn scl3(a: &Vec3, s: f64) -> Vec3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// a + b*s (mju_addScl3).
#[inline]
pub fn add_scl3(a: &Vec3, b: &Vec3, s: f64) -> Vec3 {
    [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]
}

/// a += b*s (mju_addToScl3).
#[inline]
pub fn add_to_scl3(a: &mut Vec3, b: &Vec3, s: f64) {
    a[0] += b[0] * s;
    a[1] += b[1] * s;
    a[2] += b[2] * s;
}

#[inline]
pub fn dot3(a: &Vec3, b: &Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub fn cross(a: &Vec3, b: &Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline]
pub fn norm3(a: &Vec3) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

#[inline]
pub fn dist3(a: &Vec3, b: &Vec3) -> f64 {
    norm3(&sub3(a, b))
}

/// Unit vector and the length before normalization; (1,0,0) when the length is below MINVAL.
#[inline]
pub fn normalize3(v: &Vec3) -> (Vec3, f64) {
    let n = norm3(v);
    if n < MINVAL {
        ([1.0, 0.0, 0.0], n)
    } else {
        let inv = 1.0 / n;
        ([v[0] * inv, v[1] * inv, v[2] * inv], n)
    }
}

/// mat * v (mju_rotVecMat).
#[inline]
pub fn mul_mat_vec3(m: &Mat3, v: &Vec3) -> Vec3 {
    [
        m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
        m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
        m[6] * v[0] + m[7] * v[1] + m[8] * v[2],
    ]
}

/// mat^T * v (mju_rotVecMatT).
#[inline]
pub fn mul_mat_t_vec3(m: &Mat3, v: &Vec3) -> Vec3 {
    [
        m[0] * v[0] + m[3] * v[1] + m[6] * v[2],
        m[1] * v[0] + m[4] * v[1] + m[7] * v[2],
        m[2] * v[0] + m[5] * v[1] + m[8] * v[2],
    ]
}

/// a * b, accumulated row by row as mju_mulMatMat does (zero entries of `a` skipped: `weighted`).
#[inline(always)]
pub fn mul_mat3(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut r = [0.0; 9];
    for i in 0..3 {
        for k in 0..3 {
            let s = a[3 * i + k];
            for j in 0..3 {
                r[3 * i + j] += weighted(b[3 * k + j], s);
            }
        }
    }
    r
}

/// a * b^T, each entry a mju_dot of length 3.
#[inline(always)]
pub fn mul_mat3_t(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut r = [0.0; 9];
    for i in 0..3 {
        for j in 0..3 {
            r[3 * i + j] = 0.0
                + (a[3 * i] * b[3 * j] + a[3 * i + 1] * b[3 * j + 1] + a[3 * i + 2] * b[3 * j + 2]);
        }
    }
    r
}

/// a^T * b, accumulated as mju_mulMatTMat does (zero entries of `a` skipped: `weighted`).
#[inline(always)]
pub fn mul_mat3t_mat(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut r = [0.0; 9];
    for i in 0..3 {
        for j in 0..3 {
            let s = a[3 * i + j];
            for k in 0..3 {
                r[3 * j + k] += weighted(b[3 * i + k], s);
            }
        }
    }
    r
}

#[inline]
pub fn transpose3(m: &Mat3) -> Mat3 {
    [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]]
}
