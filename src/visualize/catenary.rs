//! The curve of a string of given length hanging between two points under gravity: a
//! straight line when taut, a bead on a near-vertical string, else a catenary sampled at
//! `NCATENARY` points (found by Newton's method on a change of variables).

use crate::engine::MINVAL;
use crate::math::vec3::{add_scl3, add_to_scl3, dist3, dot3, normalize3, scl3, sub3};
use crate::math::Vec3;

pub const NCATENARY: usize = 31;

/// cosh(x), and sinh(x), from one exponential.
fn cosh_sinh(x: f64) -> (f64, f64) {
    let e = x.exp();
    (0.5 * (e + 1.0 / e), 0.5 * (e - 1.0 / e))
}

fn residual(b: f64, intercept: f64) -> f64 {
    let (_, sinh) = cosh_sinh(0.5 / b);
    1.0 / (2.0 * b * sinh - 1.0).sqrt() - intercept
}

fn gradient(b: f64) -> f64 {
    let a = 0.5 / b;
    let (cosh, sinh) = cosh_sinh(a);
    (a * cosh - sinh) * (2.0 * b * sinh - 1.0).powf(-1.5)
}

/// Flatness b of the catenary with vertical offset `v`, horizontal extent `h`, `length`.
fn solve(v: f64, h: f64, length: f64) -> f64 {
    let intercept = 1.0 / ((length * length - v * v).sqrt() / h - 1.0).sqrt();
    let mut b = intercept / 24f64.sqrt();
    for _ in 0..50 {
        let res = residual(b, intercept);
        if res.abs() < 1e-9 {
            break;
        }
        let mut step = -res / gradient(b);
        // halve the step while it does not reduce the residual
        for _ in 0..10 {
            if residual(b + step, intercept).abs() < res.abs() {
                break;
            }
            step *= 0.5;
        }
        b += step;
    }
    b
}

/// Points from `x0` to `x1` along a string of `length` (mjv_catenary), and their number.
pub fn catenary(x0: &Vec3, x1: &Vec3, gravity: &Vec3, length: f64) -> ([Vec3; NCATENARY], usize) {
    let mut p = [[0.0; 3]; NCATENARY];
    p[0] = *x0;
    if dist3(x0, x1) > length {
        p[1] = *x1;
        return (p, 2);
    }
    let (up, _) = normalize3(&scl3(gravity, crate::math::misc::minus_one()));
    let x01 = sub3(x1, x0);
    let (mut across, norm) = normalize3(&sub3(&x01, &scl3(&up, dot3(&up, &x01))));
    if norm < MINVAL {
        across = [0.0; 3];
    }
    let h = dot3(&x01, &across);
    let v = dot3(&x01, &up);
    if length > 100.0 * h {
        // a bead hanging on a near-vertical string
        let d_up = -0.5 * ((length * length - h * h).sqrt() - v);
        let d_across = h * d_up / (2.0 * d_up - v);
        p[1] = *x0;
        add_to_scl3(&mut p[1], &up, d_up);
        add_to_scl3(&mut p[1], &across, d_across);
        p[2] = *x1;
        return (p, 3);
    }
    let bh = solve(v, h, length) * h;
    let h_offset = -0.5 * (((length + v) / (length - v)).ln() * bh - h);
    let v_offset = -cosh_sinh(h_offset / bh).0 * bh;
    for (i, point) in p.iter_mut().enumerate().take(NCATENARY - 1).skip(1) {
        let horizontal = i as f64 * h / NCATENARY as f64;
        *point = add_scl3(x0, &across, horizontal);
        let vertical = bh * cosh_sinh((horizontal - h_offset) / bh).0 + v_offset;
        add_to_scl3(point, &up, vertical);
    }
    p[NCATENARY - 1] = *x1;
    (p, NCATENARY)
}
