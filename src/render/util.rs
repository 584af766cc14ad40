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
