//! Narrow-phase collisions between primitive geoms (plane, sphere, capsule, cylinder, box
//! against plane; sphere and capsule pairs; sphere and box) with 2.2.2's arithmetic.
//!
//! Each function writes contacts into `con` (which must hold the maximum for the pair: 1 for
//! sphere pairs, 2 for capsules, 4 otherwise) and returns their number. Like 2.2.2 they may
//! leave partial values in the slots past the returned count.

use super::vec3::{add3, cross, dist3, dot3, norm3, normalize3, scl3, sub3};
use super::{Mat3, Vec3, MINVAL};

/// Position, orientation and size of a geom (geom_xpos, geom_xmat, geom_size).
#[derive(Clone, Copy, Debug, Default)]
pub struct GeomPose {
    pub pos: Vec3,
    pub mat: Mat3,
    pub size: Vec3,
}

/// The geometric part of an mjContact: distance, position and the first two frame rows
/// (normal, then a tangent hint that is zero when free).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactGeom {
    pub dist: f64,
    pub pos: Vec3,
    pub frame: [f64; 6],
}

impl ContactGeom {
    fn set_normal(&mut self, n: &Vec3) {
        self.frame[..3].copy_from_slice(n);
    }
    fn set_tangent(&mut self, t: &Vec3) {
        self.frame[3..].copy_from_slice(t);
    }
    pub fn normal(&self) -> Vec3 {
        [self.frame[0], self.frame[1], self.frame[2]]
    }
}

#[inline]
fn zaxis(mat: &Mat3) -> Vec3 {
    [mat[2], mat[5], mat[8]]
}

/// pos + v*s, as mju_addToScl3 on a copy of pos.
#[inline]
fn add_scl(pos: &Vec3, v: &Vec3, s: f64) -> Vec3 {
    [pos[0] + v[0] * s, pos[1] + v[1] * s, pos[2] + v[2] * s]
}

#[inline]
fn clamp1(x: f64) -> f64 {
    x.clamp(-1.0, 1.0)
}

fn plane_sphere_at(
    con: &mut ContactGeom,
    margin: f64,
    plane: &GeomPose,
    center: &Vec3,
    radius: f64,
) -> usize {
    con.set_normal(&zaxis(&plane.mat));
    let cdist = dot3(&sub3(center, &plane.pos), &con.normal());
    if cdist > margin + radius {
        return 0;
    }
    con.dist = cdist - radius;
    let t = scl3(&con.normal(), -con.dist / 2.0 - radius);
    con.pos = add3(center, &t);
    con.set_tangent(&[0.0; 3]);
    1
}

/// Plane (g1) and sphere (g2).
pub fn plane_sphere(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    plane_sphere_at(&mut con[0], margin, g1, &g2.pos, g2.size[0])
}

/// Plane (g1) and capsule (g2): a sphere test at each end.
pub fn plane_capsule(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let axis = zaxis(&g2.mat);
    let segment = scl3(&axis, g2.size[1]);
    let n1 = plane_sphere_at(
        &mut con[0],
        margin,
        g1,
        &add3(&g2.pos, &segment),
        g2.size[0],
    );
    let n2 = plane_sphere_at(
        &mut con[n1],
        margin,
        g1,
        &sub3(&g2.pos, &segment),
        g2.size[0],
    );
    if n1 > 0 {
        con[0].set_tangent(&axis);
    }
    if n2 > 0 {
        con[n1].set_tangent(&axis);
    }
    n1 + n2
}

/// Plane (g1) and cylinder (g2): up to two rim points and two more on the lower disk.
pub fn plane_cylinder(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let normal = zaxis(&g1.mat);
    let mut axis = zaxis(&g2.mat);
    let (pos2, size2) = (&g2.pos, &g2.size);

    let mut prjaxis = dot3(&normal, &axis);
    if prjaxis > 0.0 {
        axis = scl3(&axis, -1.0);
        prjaxis = -prjaxis;
    }
    let dist0 = dot3(&sub3(pos2, &g1.pos), &normal);

    // radial direction towards the plane, scaled to the radius
    let mut vec = sub3(&scl3(&axis, prjaxis), &normal);
    let len = norm3(&vec);
    if len >= MINVAL {
        let scl = size2[0] / len;
        vec = [vec[0] * scl, vec[1] * scl, vec[2] * scl];
    } else {
        let m = &g2.mat;
        vec = [m[0] * size2[0], m[3] * size2[0], m[6] * size2[0]];
    }
    let prjvec = dot3(&vec, &normal);
    axis = scl3(&axis, size2[1]);
    prjaxis *= size2[1];

    let mut cnt = 0;
    let rim = add3(pos2, &vec);
    let d = dist0 + prjaxis + prjvec;
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(d <= margin) {
        return 0;
    }
    let c = &mut con[cnt];
    c.dist = d;
    c.pos = add_scl(&add3(&rim, &axis), &normal, -c.dist * 0.5);
    c.set_normal(&normal);
    c.set_tangent(&[0.0; 3]);
    cnt += 1;

    let d = dist0 - prjaxis + prjvec;
    if d <= margin {
        let c = &mut con[cnt];
        c.dist = d;
        c.pos = add_scl(&sub3(&rim, &axis), &normal, -c.dist * 0.5);
        c.set_normal(&normal);
        c.set_tangent(&[0.0; 3]);
        cnt += 1;
    }

    let prjvec1 = -prjvec * 0.5;
    let d = dist0 + prjaxis + prjvec1;
    if d <= margin {
        let side = normalize3(&cross(&vec, &axis)).0;
        let side = scl3(&side, size2[0] * 3.0f64.sqrt() / 2.0);
        for base in [add3(pos2, &side), sub3(pos2, &side)] {
            let c = &mut con[cnt];
            c.dist = d;
            let p = add_scl(&add3(&base, &axis), &vec, -0.5);
            c.pos = add_scl(&p, &normal, -c.dist * 0.5);
            c.set_normal(&normal);
            c.set_tangent(&[0.0; 3]);
            cnt += 1;
        }
    }
    cnt
}

/// Plane (g1) and box (g2): the (at most 4) lowest corners within the margin.
pub fn plane_box(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let norm = zaxis(&g1.mat);
    let dist = dot3(&sub3(&g2.pos, &g1.pos), &norm);
    let s = &g2.size;
    let mut cnt = 0;
    for i in 0..8 {
        let v = [
            if i & 1 != 0 { s[0] } else { -s[0] },
            if i & 2 != 0 { s[1] } else { -s[1] },
            if i & 4 != 0 { s[2] } else { -s[2] },
        ];
        let corner = super::vec3::mul_mat_vec3(&g2.mat, &v);
        let ldist = dot3(&norm, &corner);
        if dist + ldist > margin || ldist > 0.0 {
            continue;
        }
        let c = &mut con[cnt];
        c.dist = dist + ldist;
        c.set_normal(&norm);
        c.set_tangent(&[0.0; 3]);
        c.pos = add3(&add3(&corner, &g2.pos), &scl3(&norm, -c.dist / 2.0));
        cnt += 1;
        if cnt >= 4 {
            return 4;
        }
    }
    cnt
}

/// Spheres of radii r1, r2 at p1, p2; coincident centers use the cross product of the
/// geoms' z axes (mat1, mat2) as normal.
#[allow(clippy::too_many_arguments)]
fn sphere_sphere_at(
    con: &mut ContactGeom,
    margin: f64,
    p1: &Vec3,
    mat1: &Mat3,
    r1: f64,
    p2: &Vec3,
    mat2: &Mat3,
    r2: f64,
) -> usize {
    let cdist = dist3(p1, p2);
    if cdist > margin + r1 + r2 {
        return 0;
    }
    con.dist = cdist - r1 - r2;
    let (mut n, len) = normalize3(&sub3(p2, p1));
    if len < MINVAL {
        n = normalize3(&cross(&zaxis(mat1), &zaxis(mat2))).0;
    }
    con.set_normal(&n);
    con.pos = add3(&scl3(&n, r1 + con.dist / 2.0), p1);
    con.set_tangent(&[0.0; 3]);
    1
}

/// Two spheres.
pub fn sphere_sphere(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    sphere_sphere_at(
        &mut con[0],
        margin,
        &g1.pos,
        &g1.mat,
        g1.size[0],
        &g2.pos,
        &g2.mat,
        g2.size[0],
    )
}

/// Sphere (g1) and capsule (g2).
pub fn sphere_capsule(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let m = &g2.mat;
    let h = g2.size[1];
    let axis = [m[2] * h, m[5] * h, m[8] * h];
    let vec = sub3(&g1.pos, &g2.pos);
    let x = clamp1(dot3(&axis, &vec) / dot3(&axis, &axis));
    let near = add3(&scl3(&axis, x), &g2.pos);
    sphere_sphere_at(
        &mut con[0],
        margin,
        &g1.pos,
        &g1.mat,
        g1.size[0],
        &near,
        &g2.mat,
        g2.size[0],
    )
}

/// Two capsules: closest points of the segments, or up to two end tests when parallel.
pub fn capsule_capsule(
    g1: &GeomPose,
    g2: &GeomPose,
    margin: f64,
    con: &mut [ContactGeom],
) -> usize {
    let (m1, m2) = (&g1.mat, &g2.mat);
    let (h1, h2) = (g1.size[1], g2.size[1]);
    let axis1 = [m1[2] * h1, m1[5] * h1, m1[8] * h1];
    let axis2 = [m2[2] * h2, m2[5] * h2, m2[8] * h2];
    let (pos1, pos2) = (&g1.pos, &g2.pos);
    let dif = sub3(pos1, pos2);

    let ma = dot3(&axis1, &axis1);
    let mb = -dot3(&axis1, &axis2);
    let mc = dot3(&axis2, &axis2);
    let u = -dot3(&axis1, &dif);
    let v = dot3(&axis2, &dif);
    let det = ma * mc - mb * mb;

    let (r1, r2) = (g1.size[0], g2.size[0]);
    let test = |con: &mut ContactGeom, x1: f64, x2: f64| {
        let v1 = add3(&scl3(&axis1, x1), pos1);
        let v2 = add3(&scl3(&axis2, x2), pos2);
        sphere_sphere_at(con, margin, &v1, m1, r1, &v2, m2, r2)
    };

    if det.abs() >= MINVAL {
        let mut x1 = (mc * u - mb * v) / det;
        let mut x2 = (ma * v - mb * u) / det;
        if x1 > 1.0 {
            x1 = 1.0;
            x2 = (v - mb) / mc;
        } else if x1 < -1.0 {
            x1 = -1.0;
            x2 = (v + mb) / mc;
        }
        if x2 > 1.0 {
            x2 = 1.0;
            x1 = clamp1((u - mb) / ma);
        } else if x2 < -1.0 {
            x2 = -1.0;
            x1 = clamp1((u + mb) / ma);
        }
        return test(&mut con[0], x1, x2);
    }

    // parallel axes: ends of the first segment, then of the second
    let end = |con: &mut ContactGeom, first: bool, sign: f64| {
        if first {
            let x2 = clamp1(if sign > 0.0 {
                (v - mb) / mc
            } else {
                (v + mb) / mc
            });
            let v1 = if sign > 0.0 {
                add3(pos1, &axis1)
            } else {
                sub3(pos1, &axis1)
            };
            let v2 = add3(&scl3(&axis2, x2), pos2);
            sphere_sphere_at(con, margin, &v1, m1, r1, &v2, m2, r2)
        } else {
            let x1 = clamp1(if sign > 0.0 {
                (u - mb) / ma
            } else {
                (u + mb) / ma
            });
            let v2 = if sign > 0.0 {
                add3(pos2, &axis2)
            } else {
                sub3(pos2, &axis2)
            };
            let v1 = add3(&scl3(&axis1, x1), pos1);
            sphere_sphere_at(con, margin, &v1, m1, r1, &v2, m2, r2)
        }
    };
    let mut n = end(&mut con[0], true, 1.0);
    n += end(&mut con[n], true, -1.0);
    if n >= 2 {
        return n;
    }
    n += end(&mut con[n], false, 1.0);
    if n >= 2 {
        return n;
    }
    n + end(&mut con[n], false, -1.0)
}

/// Sphere (g1) and box (g2).
pub fn sphere_box(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    use super::vec3::{mul_mat_t_vec3, mul_mat_vec3};
    let (size1, size2) = (&g1.size, &g2.size);
    let center = mul_mat_t_vec3(&g2.mat, &sub3(&g1.pos, &g2.pos));
    let mut clamped = center;
    for i in 0..3 {
        let l = size2[i];
        if l > 0.0 {
            if clamped[i] < -l {
                clamped[i] = -l;
            } else if clamped[i] > l {
                clamped[i] = l;
            }
        }
    }
    let (dir, dist) = normalize3(&sub3(&clamped, &center));
    if dist - size1[0] > margin {
        return 0;
    }

    let (pos, normal) = if dist <= MINVAL {
        // center inside the box: push out through the nearest face
        let mut closest = (size2[0] + size2[1] + size2[2]) * 2.0;
        let mut k = 0;
        for i in 0..6 {
            let face = if i % 2 == 1 {
                size2[i / 2]
            } else {
                -size2[i / 2]
            };
            let d = (face - center[i / 2]).abs();
            if closest > d {
                closest = d;
                k = i;
            }
        }
        let mut nearest = [0.0; 3];
        nearest[k / 2] = if k % 2 == 1 { -1.0 } else { 1.0 };
        (
            add_scl(&center, &nearest, (size1[0] - closest) / 2.0),
            nearest,
        )
    } else {
        let deepest = add_scl(&center, &dir, size1[0]);
        let mut pos = [0.0; 3];
        for i in 0..3 {
            pos[i] = (0.0 + clamped[i] * 0.5) + deepest[i] * 0.5;
        }
        (pos, dir)
    };

    let c = &mut con[0];
    c.set_normal(&mul_mat_vec3(&g2.mat, &normal));
    c.pos = add3(&mul_mat_vec3(&g2.mat, &pos), &g2.pos);
    c.dist = dist - size1[0];
    c.set_tangent(&[0.0; 3]);
    1
}
