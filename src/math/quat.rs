//! Quaternions (w, x, y, z) and poses (position, quaternion).

use super::vec3::{add3, cross, dot3, normalize3, scl3};
use super::{Mat3, Quat, Vec3, MINVAL, PI};

#[inline]
pub fn unit_quat() -> Quat {
    [1.0, 0.0, 0.0, 0.0]
}

#[inline]
fn is_unit(q: &Quat) -> bool {
    // all four compares, no early exit: one vector compare
    (q[0] == 1.0) & (q[1] == 0.0) & (q[2] == 0.0) & (q[3] == 0.0)
}

/// Hamilton product qa * qb.
#[inline]
pub fn mul_quat(a: &Quat, b: &Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// Conjugate quaternion.
#[inline]
pub fn neg_quat(q: &Quat) -> Quat {
    [q[0], -q[1], -q[2], -q[3]]
}

/// q * (0, axis).
#[inline]
pub fn mul_quat_axis(q: &Quat, a: &Vec3) -> Quat {
    [
        -q[1] * a[0] - q[2] * a[1] - q[3] * a[2],
        q[0] * a[0] + q[2] * a[2] - q[3] * a[1],
        q[0] * a[1] + q[3] * a[0] - q[1] * a[2],
        q[0] * a[2] + q[1] * a[1] - q[2] * a[0],
    ]
}

/// Rotates v by q; exact copy for the identity quaternion.
#[inline]
pub fn rot_vec_quat(v: &Vec3, q: &Quat) -> Vec3 {
    if is_unit(q) {
        return *v;
    }
    let t = [
        q[0] * v[0] + q[2] * v[2] - q[3] * v[1],
        q[0] * v[1] + q[3] * v[0] - q[1] * v[2],
        q[0] * v[2] + q[1] * v[1] - q[2] * v[0],
    ];
    [
        v[0] + 2.0 * (q[2] * t[2] - q[3] * t[1]),
        v[1] + 2.0 * (q[3] * t[0] - q[1] * t[2]),
        v[2] + 2.0 * (q[1] * t[1] - q[2] * t[0]),
    ]
}

/// Rotation matrix of q; exact identity for the identity quaternion.
pub fn quat2mat(q: &Quat) -> Mat3 {
    if is_unit(q) {
        return [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    }
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    let (ww, wx, wy, wz) = (w * w, w * x, w * y, w * z);
    let (xx, xy, xz) = (x * x, x * y, x * z);
    let (yy, yz, zz) = (y * y, y * z, z * z);
    [
        ww + xx - yy - zz,
        2.0 * (xy - wz),
        2.0 * (xz + wy),
        2.0 * (xy + wz),
        ww - xx + yy - zz,
        2.0 * (yz - wx),
        2.0 * (xz - wy),
        2.0 * (yz + wx),
        ww - xx - yy + zz,
    ]
}

/// Quaternion of a rotation matrix (largest-component branch), normalized.
pub fn mat2quat(m: &Mat3) -> Quat {
    let mut q = [0.0; 4];
    if m[0] + m[4] + m[8] > 0.0 {
        q[0] = 0.5 * (1.0 + m[0] + m[4] + m[8]).sqrt();
        q[1] = 0.25 * (m[7] - m[5]) / q[0];
        q[2] = 0.25 * (m[2] - m[6]) / q[0];
        q[3] = 0.25 * (m[3] - m[1]) / q[0];
    } else if m[0] > m[4] && m[0] > m[8] {
        q[1] = 0.5 * (1.0 + m[0] - m[4] - m[8]).sqrt();
        q[0] = 0.25 * (m[7] - m[5]) / q[1];
        q[2] = 0.25 * (m[1] + m[3]) / q[1];
        q[3] = 0.25 * (m[2] + m[6]) / q[1];
    } else if m[4] > m[8] {
        q[2] = 0.5 * (1.0 - m[0] + m[4] - m[8]).sqrt();
        q[0] = 0.25 * (m[2] - m[6]) / q[2];
        q[1] = 0.25 * (m[1] + m[3]) / q[2];
        q[3] = 0.25 * (m[5] + m[7]) / q[2];
    } else {
        q[3] = 0.5 * (1.0 - m[0] - m[4] + m[8]).sqrt();
        q[0] = 0.25 * (m[3] - m[1]) / q[3];
        q[1] = 0.25 * (m[2] + m[6]) / q[3];
        q[2] = 0.25 * (m[5] + m[7]) / q[3];
    }
    normalize4(&q).0
}

/// Unit quaternion and the norm before normalization; identity when the norm is below MINVAL.
#[inline]
pub fn normalize4(q: &Quat) -> (Quat, f64) {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    if n < MINVAL {
        (unit_quat(), n)
    } else {
        let inv = 1.0 / n;
        ([q[0] * inv, q[1] * inv, q[2] * inv, q[3] * inv], n)
    }
}

/// Rotation by `angle` about the unit `axis`; exact identity for angle 0.
#[inline]
pub fn axis_angle2quat(axis: &Vec3, angle: f64) -> Quat {
    if angle == 0.0 {
        return unit_quat();
    }
    let s = (angle * 0.5).sin();
    [(angle * 0.5).cos(), axis[0] * s, axis[1] * s, axis[2] * s]
}

/// Angular velocity that rotates by q in time dt.
pub fn quat2vel(q: &Quat, dt: f64) -> Vec3 {
    let (axis, sin_half) = normalize3(&[q[1], q[2], q[3]]);
    let mut speed = 2.0 * sin_half.atan2(q[0]);
    if speed > PI {
        speed -= 2.0 * PI;
    }
    speed /= dt;
    scl3(&axis, speed)
}

/// Velocity v with qb * quat(v) = qa.
pub fn sub_quat(qa: &Quat, qb: &Quat) -> Vec3 {
    let dif = mul_quat(&neg_quat(qb), qa);
    quat2vel(&dif, 1.0)
}

/// Time derivative of q under angular velocity vel.
#[inline]
pub fn deriv_quat(q: &Quat, vel: &Vec3) -> Quat {
    [
        0.5 * (-vel[0] * q[1] - vel[1] * q[2] - vel[2] * q[3]),
        0.5 * (vel[0] * q[0] + vel[1] * q[3] - vel[2] * q[2]),
        0.5 * (-vel[0] * q[3] + vel[1] * q[0] + vel[2] * q[1]),
        0.5 * (vel[0] * q[2] - vel[1] * q[1] + vel[2] * q[0]),
    ]
}

/// q rotated by the local angular displacement vel*scale, normalized.
pub fn quat_integrate(q: &Quat, vel: &Vec3, scale: f64) -> Quat {
    let (axis, n) = normalize3(vel);
    let rot = axis_angle2quat(&axis, scale * n);
    normalize4(&mul_quat(q, &rot)).0
}

/// Quaternion rotating the z axis onto v (identity for tiny or parallel v).
pub fn quat_z2vec(v: &Vec3) -> Quat {
    let z = [0.0, 0.0, 1.0];
    let (vn, n) = normalize3(v);
    if n < MINVAL {
        return unit_quat();
    }
    let (axis, a) = normalize3(&cross(&z, &vn));
    if a.abs() < MINVAL {
        if dot3(&vn, &z) < 0.0 {
            return [0.0, 1.0, 0.0, 0.0];
        }
        return unit_quat();
    }
    axis_angle2quat(&axis, a.atan2(dot3(&vn, &z)))
}

/// Compiler-side quaternion normalization: divides by the norm, leaves tiny vectors alone.
fn normvec4_user(q: &mut Quat) {
    let mut n = 0.0;
    for x in q.iter() {
        n += x * x;
    }
    if n < 1e-14 {
        return;
    }
    let n = f64::sqrt(n);
    for x in q.iter_mut() {
        *x /= n;
    }
}

/// Quaternion of Euler angles (radians) in the sequence `seq` as the model compiler builds it:
/// lowercase letters are moving axes (post-multiply), uppercase fixed axes (pre-multiply).
pub fn euler2quat(angles: &Vec3, seq: &[u8]) -> Result<Quat, &'static str> {
    let mut q = unit_quat();
    for (i, angle) in angles.iter().enumerate() {
        let c = seq.get(i).copied().unwrap_or(0);
        let half = angle / 2.0;
        let mut rot = [half.cos(), 0.0, 0.0, 0.0];
        let s = half.sin();
        match c {
            b'x' | b'X' => rot[1] = s,
            b'y' | b'Y' => rot[2] = s,
            b'z' | b'Z' => rot[3] = s,
            _ => return Err("euler sequence can only contain x, y, z, X, Y, Z"),
        }
        let mut t = if c.is_ascii_lowercase() {
            mul_quat(&q, &rot)
        } else {
            mul_quat(&rot, &q)
        };
        normvec4_user(&mut t);
        q = t;
    }
    normvec4_user(&mut q);
    Ok(q)
}

/// Composition of poses: (pos1, quat1) * (pos2, quat2).
pub fn mul_pose(pos1: &Vec3, quat1: &Quat, pos2: &Vec3, quat2: &Quat) -> (Vec3, Quat) {
    let q = normalize4(&mul_quat(quat1, quat2)).0;
    let p = add3(&rot_vec_quat(pos2, quat1), pos1);
    (p, q)
}

/// Inverse pose.
pub fn neg_pose(pos: &Vec3, quat: &Quat) -> (Vec3, Quat) {
    let q = neg_quat(quat);
    let p = scl3(&rot_vec_quat(pos, &q), super::misc::minus_one());
    (p, q)
}

/// quat * vec + pos.
#[inline]
pub fn trn_vec_pose(pos: &Vec3, quat: &Quat, vec: &Vec3) -> Vec3 {
    add3(&rot_vec_quat(vec, quat), pos)
}
