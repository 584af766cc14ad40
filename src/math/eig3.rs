//! Eigen-decomposition of symmetric 3x3 matrices by quaternion Jacobi rotations.

use super::blas::{mul_mat_mat_fixed, mul_mat_t_mat_fixed};
use super::quat::{mul_quat, normalize4, quat2mat, unit_quat};
use super::{Mat3, Quat, Vec3};

const EIG_EPS: f64 = 1e-12;

/// cos(pi/4) as 2.2.2 spells it: 15 digits, deliberately not FRAC_1_SQRT_2.
#[allow(clippy::approx_constant)]
const COS45: f64 = 0.707106781186548;

/// Result of `eig3`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eig3 {
    /// Eigenvalues in decreasing order.
    pub eigval: Vec3,
    /// Eigenvectors as the columns of this rotation matrix.
    pub eigvec: Mat3,
    /// The same rotation as a quaternion.
    pub quat: Quat,
    /// Jacobi iterations used.
    pub iter: i32,
}

/// Eigenvalues (decreasing) and eigenvector frame of a symmetric matrix (mju_eig3).
pub fn eig3(mat: &Mat3) -> Eig3 {
    let mut q = unit_quat();
    let mut eigval = [0.0; 3];
    let mut iter = 0;
    while iter < 500 {
        let v = quat2mat(&q);
        let t = mul_mat_t_mat_fixed::<3, 3, 3>(&v, mat);
        let d = mul_mat_mat_fixed::<3, 3, 3>(t.as_flattened(), &v);
        let d = d.as_flattened();
        eigval = [d[0], d[4], d[8]];

        let (rk, ck, rotk) = if d[1].abs() > d[2].abs() && d[1].abs() > d[5].abs() {
            (0, 1, 2)
        } else if d[2].abs() > d[5].abs() {
            (0, 2, 1)
        } else {
            (1, 2, 0)
        };
        let off = d[3 * rk + ck];
        if off.abs() < EIG_EPS {
            break;
        }

        let tau = (d[4 * ck] - d[4 * rk]) / (2.0 * off);
        let tn = if tau >= 0.0 {
            1.0 / (tau + (1.0 + tau * tau).sqrt())
        } else {
            -1.0 / (-tau + (1.0 + tau * tau).sqrt())
        };
        let c = 1.0 / (1.0 + tn * tn).sqrt();
        if c > 1.0 - EIG_EPS {
            break;
        }

        let mut r = [0.0; 4];
        let h = (0.5 - 0.5 * c).sqrt();
        r[rotk + 1] = if tau >= 0.0 { -h } else { h };
        if rotk == 1 {
            r[rotk + 1] = -r[rotk + 1];
        }
        r[0] = (1.0 - r[rotk + 1] * r[rotk + 1]).sqrt();
        let r = normalize4(&r).0;
        q = normalize4(&mul_quat(&q, &r)).0;
        iter += 1;
    }

    for j in 0..3 {
        let j1 = j % 2;
        if eigval[j1] < eigval[j1 + 1] {
            eigval.swap(j1, j1 + 1);
            let mut r = [COS45, 0.0, 0.0, 0.0];
            r[(j1 + 2) % 3 + 1] = r[0];
            q = normalize4(&mul_quat(&q, &r)).0;
        }
    }

    Eig3 {
        eigval,
        eigvec: quat2mat(&q),
        quat: q,
        iter,
    }
}
