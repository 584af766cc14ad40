//! Float vector helpers of the renderer (normals, frames), in float as 2.2.2 computes them.

pub fn cross(b: &[f32; 3], c: &[f32; 3]) -> [f32; 3] {
    [
        b[1] * c[2] - b[2] * c[1],
        b[2] * c[0] - b[0] * c[2],
        b[0] * c[1] - b[1] * c[0],
    ]
}

/// Unit vector; +z for tiny vectors.
pub fn normalize(v: &mut [f32; 3]) {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if len < 1e-10 {
        *v = [0.0, 0.0, 1.0];
    } else {
        let scl = 1.0 / len;
        v.iter_mut().for_each(|x| *x *= scl);
    }
}

/// Unit normal of the triangle (p1, p2, p3).
pub fn make_normal(p1: &[f32; 3], p2: &[f32; 3], p3: &[f32; 3]) -> [f32; 3] {
    let v1 = [p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]];
    let v2 = [p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]];
    let mut n = cross(&v1, &v2);
    normalize(&mut n);
    n
}

pub fn dot(a: &[f32], b: &[f32]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Three floats of `v` from `at`.
pub fn f3(v: &[f32], at: usize) -> [f32; 3] {
    [v[at], v[at + 1], v[at + 2]]
}

use super::gl::Gl;

/// res = a * b, 4x4 column-major, accumulated in float.
pub fn mul_mat44(a: &[f32; 16], b: &[f32; 16]) -> [f32; 16] {
    let mut res = [0.0f32; 16];
    for r in 0..4 {
        for c in 0..4 {
            for i in 0..4 {
                res[r + 4 * c] += a[r + 4 * i] * b[i + 4 * c];
            }
        }
    }
    res
}

/// Row `r` of a column-major 4x4 matrix.
pub fn row4(a: &[f32; 16], r: usize) -> [f32; 4] {
    [a[r], a[r + 4], a[r + 8], a[r + 12]]
}

/// A unit vector orthogonal to `v`.
pub fn ortho(v: &[f32; 3]) -> [f32; 3] {
    let mut res = cross(v, &[-1.0, 0.0, 0.0]);
    if (res[0] * res[0] + res[1] * res[1] + res[2] * res[2]) as f64 > 0.01 {
        normalize(&mut res);
        return res;
    }
    res = cross(v, &[0.0, 1.0, 0.0]);
    normalize(&mut res);
    res
}

/// Multiplies the current matrix by the view from `eye` along `forward` with `up`.
pub fn look_at(gl: &Gl, eye: &[f32; 3], forward: &[f32; 3], up: &[f32; 3]) {
    let mut f = *forward;
    normalize(&mut f);
    let mut s = cross(&f, up);
    normalize(&mut s);
    let mut u = cross(&s, &f);
    normalize(&mut u);
    gl.mult_matrixf(&[
        s[0],
        u[0],
        -f[0],
        0.0,
        s[1],
        u[1],
        -f[1],
        0.0,
        s[2],
        u[2],
        -f[2],
        0.0,
        -dot(&s, eye),
        -dot(&u, eye),
        dot(&f, eye),
        1.0,
    ]);
}

/// Perspective projection of vertical field of view `fovy` degrees.
pub fn perspective(gl: &Gl, fovy: f32, aspect: f32, znear: f32, zfar: f32) {
    let h = (fovy as f64 / 360.0 * std::f64::consts::PI).tan() * znear as f64;
    let w = h * aspect as f64;
    gl.glFrustum(-w, w, -h, h, znear as f64, zfar as f64);
}

/// Multiplies the current matrix by the reflection in the plane through `pos` with normal
/// the z axis of `mat`.
pub fn reflect(gl: &Gl, pos: &[f32; 3], mat: &[f32; 9]) {
    let v = [mat[2], mat[5], mat[8]];
    let mut vvt = [0.0f32; 9];
    for i in 0..3 {
        for j in 0..3 {
            vvt[3 * i + j] = v[i] * v[j];
        }
    }
    gl.mult_matrixf(&[
        1.0 - 2.0 * vvt[0],
        -2.0 * vvt[1],
        -2.0 * vvt[2],
        0.0,
        -2.0 * vvt[3],
        1.0 - 2.0 * vvt[4],
        -2.0 * vvt[5],
        0.0,
        -2.0 * vvt[6],
        -2.0 * vvt[7],
        1.0 - 2.0 * vvt[8],
        0.0,
        2.0 * dot(&vvt[0..3], pos),
        2.0 * dot(&vvt[3..6], pos),
        2.0 * dot(&vvt[6..9], pos),
        1.0,
    ]);
}

/// Multiplies the current matrix by the model's room transform.
pub fn transform(gl: &Gl, translate: &[f32; 3], rotate: &[f32; 4], scale: f32) {
    let q = rotate.map(|x| x as f64);
    let mat = crate::math::quat::quat2mat(&q);
    let m = |i: usize| scale * mat[i] as f32;
    gl.mult_matrixf(&[
        m(0),
        m(3),
        m(6),
        0.0,
        m(1),
        m(4),
        m(7),
        0.0,
        m(2),
        m(5),
        m(8),
        0.0,
        translate[0],
        translate[1],
        translate[2],
        1.0,
    ]);
}

/// Stable merge sort of `items` by `cmp`, merging as glibc's qsort does (2.2.2's geom order).
pub fn merge_sort<T: Copy>(items: &mut [T], cmp: &impl Fn(&T, &T) -> i32) {
    let n = items.len();
    if n <= 1 {
        return;
    }
    let n1 = n / 2;
    let (a, b) = items.split_at_mut(n1);
    merge_sort(a, cmp);
    merge_sort(b, cmp);
    let mut merged = Vec::with_capacity(n);
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if cmp(&a[i], &b[j]) <= 0 {
            merged.push(a[i]);
            i += 1;
        } else {
            merged.push(b[j]);
            j += 1;
        }
    }
    merged.extend_from_slice(&a[i..]);
    merged.extend_from_slice(&b[j..]);
    items.copy_from_slice(&merged);
}
