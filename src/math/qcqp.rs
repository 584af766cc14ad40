//! Small quadratic programs with an ellipsoidal constraint:
//! min 0.5*x'*A*x + x'*b  s.t.  sum (x_i/d_i)^2 <= r^2, by Newton iteration on the multiplier.

use super::blas::{dot, scl_in_place};
use super::chol::{chol_factor, chol_solve};

/// 2D case; A is 2x2 row-major. Returns (x, constrained).
pub fn qcqp2(a: &[f64], b: &[f64], d: &[f64], r: f64) -> ([f64; 2], bool) {
    let b1 = b[0] * d[0];
    let b2 = b[1] * d[1];
    let a11 = a[0] * d[0] * d[0];
    let a22 = a[3] * d[1] * d[1];
    let a12 = a[1] * d[0] * d[1];

    let mut la = 0.0;
    let (mut v1, mut v2) = (0.0, 0.0);
    for _ in 0..20 {
        let det = (a11 + la) * (a22 + la) - a12 * a12;
        if det < 1e-10 {
            return ([0.0, 0.0], false);
        }
        let detinv = 1.0 / det;
        let p11 = (a22 + la) * detinv;
        let p22 = (a11 + la) * detinv;
        let p12 = -a12 * detinv;

        v1 = -p11 * b1 - p12 * b2;
        v2 = -p12 * b1 - p22 * b2;

        let val = v1 * v1 + v2 * v2 - r * r;
        if val < 1e-10 {
            break;
        }
        let deriv = -2.0 * (p11 * v1 * v1 + 2.0 * p12 * v1 * v2 + p22 * v2 * v2);
        let delta = -val / deriv;
        if delta < 1e-10 {
            break;
        }
        la += delta;
    }
    ([v1 * d[0], v2 * d[1]], la != 0.0)
}

/// 3D case; A is 3x3 row-major. Returns (x, constrained).
pub fn qcqp3(a: &[f64], b: &[f64], d: &[f64], r: f64) -> ([f64; 3], bool) {
    let b1 = b[0] * d[0];
    let b2 = b[1] * d[1];
    let b3 = b[2] * d[2];
    let a11 = a[0] * d[0] * d[0];
    let a22 = a[4] * d[1] * d[1];
    let a33 = a[8] * d[2] * d[2];
    let a12 = a[1] * d[0] * d[1];
    let a13 = a[2] * d[0] * d[2];
    let a23 = a[5] * d[1] * d[2];

    let mut la = 0.0;
    let (mut v1, mut v2, mut v3) = (0.0, 0.0, 0.0);
    for _ in 0..20 {
        let mut p11 = (a22 + la) * (a33 + la) - a23 * a23;
        let mut p22 = (a11 + la) * (a33 + la) - a13 * a13;
        let mut p33 = (a11 + la) * (a22 + la) - a12 * a12;
        let mut p12 = a13 * a23 - a12 * (a33 + la);
        let mut p13 = a12 * a23 - a13 * (a22 + la);
        let mut p23 = a12 * a13 - a23 * (a11 + la);

        let det = (a11 + la) * p11 + a12 * p12 + a13 * p13;
        if det < 1e-10 {
            return ([0.0; 3], false);
        }
        let detinv = 1.0 / det;
        p11 *= detinv;
        p22 *= detinv;
        p33 *= detinv;
        p12 *= detinv;
        p13 *= detinv;
        p23 *= detinv;

        v1 = -p11 * b1 - p12 * b2 - p13 * b3;
        v2 = -p12 * b1 - p22 * b2 - p23 * b3;
        v3 = -p13 * b1 - p23 * b2 - p33 * b3;

        let val = v1 * v1 + v2 * v2 + v3 * v3 - r * r;
        if val < 1e-10 {
            break;
        }
        let deriv = -2.0 * (p11 * v1 * v1 + p22 * v2 * v2 + p33 * v3 * v3)
            - 4.0 * (p12 * v1 * v2 + p13 * v1 * v3 + p23 * v2 * v3);
        let delta = -val / deriv;
        if delta < 1e-10 {
            break;
        }
        la += delta;
    }
    ([v1 * d[0], v2 * d[1], v3 * d[2]], la != 0.0)
}

/// General case for n <= 5 (None for larger n); A is n x n row-major.
/// Writes x into `res[..n]` and returns whether the constraint is active.
pub fn qcqp(
    res: &mut [f64],
    a_in: &[f64],
    b_in: &[f64],
    d: &[f64],
    r: f64,
    n: usize,
) -> Option<bool> {
    if n > 5 {
        return None;
    }
    let mut a = [0.0; 25];
    let mut b = [0.0; 5];
    for i in 0..n {
        b[i] = b_in[i] * d[i];
        for j in 0..n {
            a[j + i * n] = a_in[j + i * n] * d[i] * d[j];
        }
    }

    let mut la = 0.0;
    let mut ala = [0.0; 25];
    let mut tmp = [0.0; 5];
    for _ in 0..20 {
        ala[..n * n].copy_from_slice(&a[..n * n]);
        for i in 0..n {
            ala[i * (n + 1)] += la;
        }
        if chol_factor(&mut ala[..n * n], n, 1e-10) < n {
            res[..n].fill(0.0);
            return Some(false);
        }
        chol_solve(res, &ala, &b, n);
        scl_in_place(&mut res[..n], super::misc::minus_one());

        let val = dot(res, res, n) - r * r;
        if val < 1e-10 {
            break;
        }
        chol_solve(&mut tmp, &ala, res, n);
        let deriv = -2.0 * dot(res, &tmp, n);
        let delta = -val / deriv;
        if delta < 1e-10 {
            break;
        }
        la += delta;
    }
    for i in 0..n {
        res[i] *= d[i];
    }
    Some(la != 0.0)
}
