//! Orientation and inertia arithmetic of the model compiler (double precision, 2.2.2's order).

pub const EPS: f64 = 1e-14;
pub const MINVAL: f64 = 1e-15;

pub fn defined(x: f64) -> bool {
    !x.is_nan()
}

/// Normalizes in place; returns the previous norm, or 0 (vector unchanged) when tiny.
pub fn normalize(v: &mut [f64]) -> f64 {
    let nrm2: f64 = v.iter().fold(0.0, |s, x| s + x * x);
    if nrm2 < EPS {
        return 0.0;
    }
    let nrm = nrm2.sqrt();
    for x in v.iter_mut() {
        *x /= nrm;
    }
    nrm
}

pub fn dot3(a: &[f64], b: &[f64]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(b: &[f64], c: &[f64]) -> [f64; 3] {
    [
        b[1] * c[2] - b[2] * c[1],
        b[2] * c[0] - b[0] * c[2],
        b[0] * c[1] - b[1] * c[0],
    ]
}

/// Quaternion product, normalized (compiler convention).
pub fn mulquat_unit(qa: &[f64; 4], qb: &[f64; 4]) -> [f64; 4] {
    let mut r = mulquat(qa, qb);
    normalize(&mut r);
    r
}

/// Plain quaternion product.
pub fn mulquat(qa: &[f64; 4], qb: &[f64; 4]) -> [f64; 4] {
    [
        qa[0] * qb[0] - qa[1] * qb[1] - qa[2] * qb[2] - qa[3] * qb[3],
        qa[0] * qb[1] + qa[1] * qb[0] + qa[2] * qb[3] - qa[3] * qb[2],
        qa[0] * qb[2] - qa[1] * qb[3] + qa[2] * qb[0] + qa[3] * qb[1],
        qa[0] * qb[3] + qa[1] * qb[2] - qa[2] * qb[1] + qa[3] * qb[0],
    ]
}

/// Rotation matrix (row-major) of a quaternion, compiler variant (no identity shortcut).
pub fn quat2mat(q: &[f64; 4]) -> [f64; 9] {
    let (q00, q11, q22, q33) = (q[0] * q[0], q[1] * q[1], q[2] * q[2], q[3] * q[3]);
    [
        q00 + q11 - q22 - q33,
        2.0 * (q[1] * q[2] - q[0] * q[3]),
        2.0 * (q[1] * q[3] + q[0] * q[2]),
        2.0 * (q[1] * q[2] + q[0] * q[3]),
        q00 - q11 + q22 - q33,
        2.0 * (q[2] * q[3] - q[0] * q[1]),
        2.0 * (q[1] * q[3] - q[0] * q[2]),
        2.0 * (q[2] * q[3] + q[0] * q[1]),
        q00 - q11 - q22 + q33,
    ]
}

/// Minimal rotation taking (0,0,1) to `vec`.
pub fn z2quat(vec: &[f64; 3]) -> [f64; 4] {
    let c = cross(&[0.0, 0.0, 1.0], vec);
    let mut axis = c;
    let s = normalize(&mut axis);
    if s < 1e-10 {
        axis = [1.0, 0.0, 0.0];
    }
    let ang = s.atan2(vec[2]);
    let (sn, cs) = ((ang / 2.0).sin(), (ang / 2.0).cos());
    [cs, axis[0] * sn, axis[1] * sn, axis[2] * sn]
}

/// Quaternion of the frame whose axes (matrix columns) are x, y, z.
pub fn frame2quat(x: &[f64], y: &[f64], z: &[f64]) -> [f64; 4] {
    let m = [x, y, z]; // m[column][row]
    let mut q = [0.0; 4];
    if m[0][0] + m[1][1] + m[2][2] > 0.0 {
        q[0] = 0.5 * (1.0 + m[0][0] + m[1][1] + m[2][2]).sqrt();
        q[1] = 0.25 * (m[1][2] - m[2][1]) / q[0];
        q[2] = 0.25 * (m[2][0] - m[0][2]) / q[0];
        q[3] = 0.25 * (m[0][1] - m[1][0]) / q[0];
    } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
        q[1] = 0.5 * (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt();
        q[0] = 0.25 * (m[1][2] - m[2][1]) / q[1];
        q[2] = 0.25 * (m[1][0] + m[0][1]) / q[1];
        q[3] = 0.25 * (m[2][0] + m[0][2]) / q[1];
    } else if m[1][1] > m[2][2] {
        q[2] = 0.5 * (1.0 - m[0][0] + m[1][1] - m[2][2]).sqrt();
        q[0] = 0.25 * (m[2][0] - m[0][2]) / q[2];
        q[1] = 0.25 * (m[1][0] + m[0][1]) / q[2];
        q[3] = 0.25 * (m[2][1] + m[1][2]) / q[2];
    } else {
        q[3] = 0.5 * (1.0 - m[0][0] - m[1][1] + m[2][2]).sqrt();
        q[0] = 0.25 * (m[0][1] - m[1][0]) / q[3];
        q[1] = 0.25 * (m[2][0] + m[0][2]) / q[3];
        q[2] = 0.25 * (m[2][1] + m[1][2]) / q[3];
    }
    normalize(&mut q);
    q
}

/// Conjugate quaternion.
pub fn conj(q: &[f64; 4]) -> [f64; 4] {
    [q[0], -q[1], -q[2], -q[3]]
}

/// mat * v for a row-major 3x3 matrix.
pub fn mat_vec(mat: &[f64; 9], v: &[f64; 3]) -> [f64; 3] {
    [
        mat[0] * v[0] + mat[1] * v[1] + mat[2] * v[2],
        mat[3] * v[0] + mat[4] * v[1] + mat[5] * v[2],
        mat[6] * v[0] + mat[7] * v[1] + mat[8] * v[2],
    ]
}

/// Global direction expressed in the frame with orientation `quat`.
pub fn local_axis(v: &[f64; 3], quat: &[f64; 4]) -> [f64; 3] {
    mat_vec(&quat2mat(&conj(quat)), v)
}

/// Global point expressed in the frame (pos, quat).
pub fn local_pos(p: &[f64; 3], pos: &[f64; 3], quat: &[f64; 4]) -> [f64; 3] {
    local_axis(&[p[0] - pos[0], p[1] - pos[1], p[2] - pos[2]], quat)
}

/// Rotation from `parent` to `child`.
pub fn local_quat(child: &[f64; 4], parent: &[f64; 4]) -> [f64; 4] {
    mulquat_unit(&conj(parent), child)
}

/// Full inertia (xx, yy, zz, xy, xz, yz) of a body with diagonal inertia `local` in frame `quat`.
pub fn global_inertia(local: &[f64; 3], quat: &[f64; 4]) -> [f64; 6] {
    let m = quat2mat(quat);
    let t = [
        m[0] * local[0],
        m[3] * local[0],
        m[6] * local[0],
        m[1] * local[1],
        m[4] * local[1],
        m[7] * local[1],
        m[2] * local[2],
        m[5] * local[2],
        m[8] * local[2],
    ];
    [
        m[0] * t[0] + m[1] * t[3] + m[2] * t[6],
        m[3] * t[1] + m[4] * t[4] + m[5] * t[7],
        m[6] * t[2] + m[7] * t[5] + m[8] * t[8],
        m[0] * t[1] + m[1] * t[4] + m[2] * t[7],
        m[0] * t[2] + m[1] * t[5] + m[2] * t[8],
        m[3] * t[2] + m[4] * t[5] + m[5] * t[8],
    ]
}

/// Parallel-axis term of a point mass at offset `v`.
pub fn offcenter(mass: f64, v: &[f64; 3]) -> [f64; 6] {
    [
        mass * (v[1] * v[1] + v[2] * v[2]),
        mass * (v[0] * v[0] + v[2] * v[2]),
        mass * (v[0] * v[0] + v[1] * v[1]),
        -mass * v[0] * v[1],
        -mass * v[0] * v[2],
        -mass * v[1] * v[2],
    ]
}

// ---- engine-precision helpers used by the eigen decomposition ----

fn normalize4(v: &mut [f64; 4]) {
    let norm = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]).sqrt();
    if norm < MINVAL {
        *v = [1.0, 0.0, 0.0, 0.0];
    } else {
        let inv = 1.0 / norm;
        for x in v.iter_mut() {
            *x *= inv;
        }
    }
}

/// Engine quaternion to matrix (identity shortcut for the null rotation).
fn quat2mat_engine(q: &[f64; 4]) -> [f64; 9] {
    if q[0] == 1.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0 {
        return [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    }
    let (q00, q01, q02, q03) = (q[0] * q[0], q[0] * q[1], q[0] * q[2], q[0] * q[3]);
    let (q11, q12, q13) = (q[1] * q[1], q[1] * q[2], q[1] * q[3]);
    let (q22, q23, q33) = (q[2] * q[2], q[2] * q[3], q[3] * q[3]);
    [
        q00 + q11 - q22 - q33,
        2.0 * (q12 - q03),
        2.0 * (q13 + q02),
        2.0 * (q12 + q03),
        q00 - q11 + q22 - q33,
        2.0 * (q23 - q01),
        2.0 * (q13 - q02),
        2.0 * (q23 + q01),
        q00 - q11 - q22 + q33,
    ]
}

/// res = a' * b for 3x3 row-major, accumulated row by row skipping zeros.
fn mul_t(a: &[f64; 9], b: &[f64; 9]) -> [f64; 9] {
    let mut r = [0.0; 9];
    for i in 0..3 {
        for j in 0..3 {
            let t = a[i * 3 + j];
            if t != 0.0 {
                for k in 0..3 {
                    r[j * 3 + k] += b[i * 3 + k] * t;
                }
            }
        }
    }
    r
}

fn mul(a: &[f64; 9], b: &[f64; 9]) -> [f64; 9] {
    let mut r = [0.0; 9];
    for i in 0..3 {
        for k in 0..3 {
            let t = a[i * 3 + k];
            if t != 0.0 {
                for j in 0..3 {
                    r[i * 3 + j] += b[k * 3 + j] * t;
                }
            }
        }
    }
    r
}

/// Eigenvalues (decreasing) and eigenvector frame quaternion of a symmetric 3x3 matrix,
/// by Jacobi rotations expressed as quaternions.
pub fn eig3(mat: &[f64; 9]) -> ([f64; 3], [f64; 4]) {
    const TOL: f64 = 1e-12;
    let mut quat = [1.0, 0.0, 0.0, 0.0];
    let mut eigval = [0.0; 3];
    for _ in 0..500 {
        let v = quat2mat_engine(&quat);
        let d = mul(&mul_t(&v, mat), &v);
        eigval = [d[0], d[4], d[8]];
        let (rk, ck, rotk) = if d[1].abs() > d[2].abs() && d[1].abs() > d[5].abs() {
            (0, 1, 2)
        } else if d[2].abs() > d[5].abs() {
            (0, 2, 1)
        } else {
            (1, 2, 0)
        };
        if d[3 * rk + ck].abs() < TOL {
            break;
        }
        let tau = (d[4 * ck] - d[4 * rk]) / (2.0 * d[3 * rk + ck]);
        let t = if tau >= 0.0 {
            1.0 / (tau + (1.0 + tau * tau).sqrt())
        } else {
            -1.0 / (-tau + (1.0 + tau * tau).sqrt())
        };
        let c = 1.0 / (1.0 + t * t).sqrt();
        if c > 1.0 - TOL {
            break;
        }
        let mut rot = [0.0; 4];
        let s = (0.5 - 0.5 * c).sqrt();
        rot[rotk + 1] = if tau >= 0.0 { -s } else { s };
        if rotk == 1 {
            rot[rotk + 1] = -rot[rotk + 1];
        }
        rot[0] = (1.0 - rot[rotk + 1] * rot[rotk + 1]).sqrt();
        normalize4(&mut rot);
        quat = mulquat(&quat, &rot);
        normalize4(&mut quat);
    }
    for j in 0..3 {
        let j1 = j % 2;
        if eigval[j1] < eigval[j1 + 1] {
            eigval.swap(j1, j1 + 1);
            // cos(pi/4) as 2.2.2 writes it (15 digits, not FRAC_1_SQRT_2)
            #[allow(clippy::approx_constant)]
            let mut rot = [0.707106781186548, 0.0, 0.0, 0.0];
            rot[(j1 + 2) % 3 + 1] = rot[0];
            quat = mulquat(&quat, &rot);
            normalize4(&mut quat);
        }
    }
    (eigval, quat)
}
