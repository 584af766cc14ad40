//! Tendon wrapping around spheres and cylinders (mju_wrap).

use super::blas::{add, dot, mul_mat_t_vec, mul_mat_vec, norm, normalize, scl_in_place, sub};
use super::vec3::{add3, cross, dot3, norm3, normalize3, scl3, sub3};
use super::{Mat3, Vec3, MINVAL, PI};

/// Whether 2D segments p1-p2 and p3-p4 intersect.
fn segments_intersect(p1: &[f64], p2: &[f64], p3: &[f64], p4: &[f64]) -> bool {
    let det = (p4[1] - p3[1]) * (p2[0] - p1[0]) - (p4[0] - p3[0]) * (p2[1] - p1[1]);
    if det.abs() < MINVAL {
        return false;
    }
    let a = ((p4[0] - p3[0]) * (p1[1] - p3[1]) - (p4[1] - p3[1]) * (p1[0] - p3[0])) / det;
    let b = ((p2[0] - p1[0]) * (p1[1] - p3[1]) - (p2[1] - p1[1]) * (p1[0] - p3[0])) / det;
    (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)
}

/// Arc length on the circle of radius `rad` from p0 to p1, going the way selected by `ind`.
fn arc_length(p0: &[f64], p1: &[f64], ind: usize, rad: f64) -> f64 {
    let mut u = [p0[0], p0[1]];
    let mut v = [p1[0], p1[1]];
    normalize(&mut u);
    normalize(&mut v);
    let mut angle = dot(&u, &v, 2).acos();
    let side = p0[1] * p1[0] - p0[0] * p1[1];
    if (side > 0.0 && ind != 0) || (side < 0.0 && ind == 0) {
        angle = 2.0 * PI - angle;
    }
    rad * angle
}

/// Wrap of the 2D segment d[0..2]-d[2..4] around the circle of radius `rad` at the origin,
/// optionally toward the side point `sd`. Returns the tangent points and the arc length.
fn wrap_circle(d: &[f64; 4], sd: Option<&[f64; 2]>, rad: f64) -> Option<([f64; 4], f64)> {
    let sqlen0 = d[0] * d[0] + d[1] * d[1];
    let sqlen1 = d[2] * d[2] + d[3] * d[3];
    let sqrad = rad * rad;
    let dif = [d[2] - d[0], d[3] - d[1]];
    if sqlen0 < sqrad || sqlen1 < sqrad || rad < MINVAL {
        return None;
    }
    let dd = dif[0] * dif[0] + dif[1] * dif[1];
    if dd < MINVAL {
        return None;
    }

    // closest point of the segment to the origin
    let a = (-(dif[0] * d[0] + dif[1] * d[1]) / dd).clamp_c(0.0, 1.0);
    let near = [a * dif[0] + d[0], a * dif[1] + d[1]];
    if near[0] * near[0] + near[1] * near[1] > sqrad && sd.is_none_or(|s| dot(s, &near, 2) >= 0.0) {
        return None;
    }

    let mut sol = [[0.0; 4]; 2];
    let mut good = [0.0; 2];
    for i in 0..2 {
        let sqrt0 = (sqlen0 - sqrad).sqrt();
        let sqrt1 = (sqlen1 - sqrad).sqrt();
        let sgn = if i == 0 { 1.0 } else { -1.0 };
        let s = &mut sol[i];
        s[0] = (d[0] * sqrad + sgn * rad * d[1] * sqrt0) / sqlen0;
        s[1] = (d[1] * sqrad - sgn * rad * d[0] * sqrt0) / sqlen0;
        s[2] = (d[2] * sqrad - sgn * rad * d[3] * sqrt1) / sqlen1;
        s[3] = (d[3] * sqrad + sgn * rad * d[2] * sqrt1) / sqlen1;

        let mut t = [0.0; 2];
        good[i] = match sd {
            Some(sd) => {
                add(&mut t, &s[..2], &s[2..]);
                normalize(&mut t);
                dot(&t, sd, 2)
            }
            None => {
                sub(&mut t, &s[..2], &s[2..]);
                -dot(&t, &t, 2)
            }
        };
        if segments_intersect(&d[..2], &s[..2], &d[2..], &s[2..]) {
            good[i] = -10000.0;
        }
    }

    let i = if good[0] > good[1] { 0 } else { 1 };
    let pnt = sol[i];
    if segments_intersect(&d[..2], &pnt[..2], &d[2..], &pnt[2..]) {
        return None;
    }
    Some((pnt, arc_length(&pnt[..2], &pnt[2..], i, rad)))
}

/// Wrap when the side point is inside the circle: both tangent points coincide.
/// Returns None when there is no wrap.
fn wrap_inside(d: &[f64; 4], rad: f64) -> Option<[f64; 4]> {
    const MAXITER: usize = 20;
    const ZINIT: f64 = 1.0 - 1e-7;
    const TOL: f64 = 1e-6;

    let len0 = norm(&d[..2]);
    let len1 = norm(&d[2..]);
    let dif = [d[2] - d[0], d[3] - d[1]];
    let dd = dif[0] * dif[0] + dif[1] * dif[1];
    if len0 <= rad || len1 <= rad || rad < MINVAL || len0 < MINVAL || len1 < MINVAL {
        return None;
    }

    // segment crossing the circle: no wrap
    if dd > MINVAL {
        let a = -(dif[0] * d[0] + dif[1] * d[1]) / dd;
        if a > 0.0 && a < 1.0 {
            let t = [d[0] + dif[0] * a, d[1] + dif[1] * a];
            if norm(&t) <= rad {
                return None;
            }
        }
    }

    // fallback: the normalized average of the endpoints
    let mut pnt = [0.0; 4];
    pnt[0] = 0.5 * (d[0] + d[2]);
    pnt[1] = 0.5 * (d[1] + d[3]);
    normalize(&mut pnt[..2]);
    scl_in_place(&mut pnt[..2], rad);
    pnt[2] = pnt[0];
    pnt[3] = pnt[1];

    // solve asin(A*z) + asin(B*z) - 2*asin(z) + G = 0 by Newton's method
    let ca = rad / len0;
    let cb = rad / len1;
    let cos_g = (len0 * len0 + len1 * len1 - dd) / (2.0 * len0 * len1);
    if cos_g < -1.0 + MINVAL {
        return None;
    } else if cos_g > 1.0 - MINVAL {
        return Some(pnt);
    }
    let g = cos_g.acos();
    let fun = |z: f64| (ca * z).asin() + (cb * z).asin() - 2.0 * z.asin() + g;

    let mut z = ZINIT;
    let mut f = fun(z);
    if f > 0.0 {
        return Some(pnt);
    }
    let mut iter = 0;
    while iter < MAXITER && f.abs() > TOL {
        let df = ca / MINVAL.max_c((1.0 - z * z * ca * ca).sqrt())
            + cb / MINVAL.max_c((1.0 - z * z * cb * cb).sqrt())
            - 2.0 / MINVAL.max_c((1.0 - z * z).sqrt());
        if df > -MINVAL {
            return Some(pnt);
        }
        let z1 = z - f / df;
        if z1 > z {
            return Some(pnt);
        }
        z = z1;
        f = fun(z);
        if f > TOL {
            return Some(pnt);
        }
        iter += 1;
    }
    if iter >= MAXITER {
        return Some(pnt);
    }

    // rotate the endpoint on the positive side by the solved angle
    let (mut v, ang) = if d[0] * d[3] - d[1] * d[2] > 0.0 {
        ([d[0], d[1]], z.asin() - (ca * z).asin())
    } else {
        ([d[2], d[3]], z.asin() - (cb * z).asin())
    };
    normalize(&mut v);
    pnt[0] = rad * (ang.cos() * v[0] - ang.sin() * v[1]);
    pnt[1] = rad * (ang.sin() * v[0] + ang.cos() * v[1]);
    pnt[2] = pnt[0];
    pnt[3] = pnt[1];
    Some(pnt)
}

/// C-style comparisons (first argument wins ties and NaN falls through), as mju_max/clip.
trait CCmp {
    fn max_c(self, b: f64) -> f64;
    fn clamp_c(self, lo: f64, hi: f64) -> f64;
}
impl CCmp for f64 {
    fn max_c(self, b: f64) -> f64 {
        if self >= b {
            self
        } else {
            b
        }
    }
    fn clamp_c(self, lo: f64, hi: f64) -> f64 {
        if self < lo {
            lo
        } else if self > hi {
            hi
        } else {
            self
        }
    }
}

/// Wraps the straight path x0-x1 around a sphere (`cylinder` false) or a cylinder of radius
/// `radius` with frame (xpos, xmat), optionally toward the side point `side`.
/// Returns the wrap length and the two tangent points (global frame), or None for no wrap.
pub fn wrap(
    x0: &Vec3,
    x1: &Vec3,
    xpos: &Vec3,
    xmat: &Mat3,
    radius: f64,
    cylinder: bool,
    side: Option<&Vec3>,
) -> Option<(f64, [f64; 6])> {
    let local = |x: &Vec3| {
        let mut r = [0.0; 3];
        mul_mat_t_vec(&mut r, xmat, &sub3(x, xpos), 3, 3);
        r
    };
    let p0 = local(x0);
    let p1 = local(x1);
    if norm3(&p0) < MINVAL || norm3(&p1) < MINVAL {
        return None;
    }

    // 2D frame of the wrapping plane
    let axis: [Vec3; 2] = if !cylinder {
        let a0 = normalize3(&p0).0;
        let (mut normal, nrm) = normalize3(&cross(&p0, &p1));
        if nrm < MINVAL {
            // p0, p1 parallel: any normal, from the axis missing the largest component
            let mut i = 0;
            if a0[1].abs() > a0[0].abs() && a0[1].abs() > a0[2].abs() {
                i = 1;
            }
            if a0[2].abs() > a0[0].abs() && a0[2].abs() > a0[1].abs() {
                i = 2;
            }
            let mut a1 = [1.0; 3];
            a1[i] = 0.0;
            normal = normalize3(&cross(&a0, &a1)).0;
        }
        [a0, normalize3(&cross(&normal, &a0)).0]
    } else {
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    };

    let d = [
        dot3(&p0, &axis[0]),
        dot3(&p0, &axis[1]),
        dot3(&p1, &axis[0]),
        dot3(&p1, &axis[1]),
    ];
    let sd = side.map(|side| {
        let s = local(side);
        let mut sd = [dot3(&s, &axis[0]), dot3(&s, &axis[1])];
        if norm(&sd) >= radius {
            normalize(&mut sd);
            scl_in_place(&mut sd, radius);
        } else {
            sd = [0.0, 0.0];
        }
        sd
    });

    let (pnt, mut wlen) = match sd {
        Some(s) if s[0] == 0.0 && s[1] == 0.0 => (wrap_inside(&d, radius)?, 0.0),
        _ => wrap_circle(&d, sd.as_ref(), radius)?,
    };

    let mut res = [0.0; 6];
    for i in 0..2 {
        let p = add3(&scl3(&axis[0], pnt[2 * i]), &scl3(&axis[1], pnt[2 * i + 1]));
        res[3 * i..3 * i + 3].copy_from_slice(&p);
    }

    if cylinder {
        let l0 = ((p0[0] - res[0]) * (p0[0] - res[0]) + (p0[1] - res[1]) * (p0[1] - res[1])).sqrt();
        let l1 = ((p1[0] - res[3]) * (p1[0] - res[3]) + (p1[1] - res[4]) * (p1[1] - res[4])).sqrt();
        res[2] = p0[2] + (p1[2] - p0[2]) * l0 / (l0 + wlen + l1);
        res[5] = p0[2] + (p1[2] - p0[2]) * (l0 + wlen) / (l0 + wlen + l1);
        let height = (res[5] - res[2]).abs();
        wlen = (wlen * wlen + height * height).sqrt();
    }

    let mut w = [0.0; 6];
    mul_mat_vec(&mut w[..3], xmat, &res[..3], 3, 3);
    mul_mat_vec(&mut w[3..], xmat, &res[3..], 3, 3);
    let (a, b) = ([w[0], w[1], w[2]], [w[3], w[4], w[5]]);
    w[..3].copy_from_slice(&add3(&a, xpos));
    w[3..].copy_from_slice(&add3(&b, xpos));
    Some((wlen, w))
}
