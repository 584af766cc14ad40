//! Narrow-phase collisions between primitive geoms (plane, sphere, capsule, cylinder, box
//! against plane; sphere and capsule pairs; sphere and capsule against box) with 2.2.2's
//! arithmetic.
//!
//! Each function writes contacts into `con` (which must hold the maximum for the pair: 1 for
//! sphere pairs, 2 for capsules, 4 otherwise) and returns their number. Like 2.2.2 they may
//! leave partial values in the slots past the returned count.

use crate::math::vec3::{add3, cross, dist3, dot3, norm3, normalize3, scl3, sub3};
use crate::math::{Mat3, Vec3, MINVAL};

/// Position, orientation and size of a geom (geom_xpos, geom_xmat, geom_size), read where they
/// are: a copy made just before a routine reads it stalls on its own stores.
#[derive(Clone, Copy, Debug)]
pub struct GeomPose<'a> {
    pub pos: &'a Vec3,
    pub mat: &'a Mat3,
    pub size: &'a Vec3,
}

/// A pose of one's own (a convex geom's, which MPR rotates; tests).
#[derive(Clone, Copy, Debug, Default)]
pub struct Pose {
    pub pos: Vec3,
    pub mat: Mat3,
    pub size: Vec3,
}

impl Pose {
    pub fn geom(&self) -> GeomPose<'_> {
        GeomPose {
            pos: &self.pos,
            mat: &self.mat,
            size: &self.size,
        }
    }
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
    con.set_normal(&zaxis(plane.mat));
    let cdist = dot3(&sub3(center, plane.pos), &con.normal());
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
    plane_sphere_at(&mut con[0], margin, g1, g2.pos, g2.size[0])
}

/// Plane (g1) and capsule (g2): a sphere test at each end.
pub fn plane_capsule(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let axis = zaxis(g2.mat);
    let segment = scl3(&axis, g2.size[1]);
    let n1 = plane_sphere_at(&mut con[0], margin, g1, &add3(g2.pos, &segment), g2.size[0]);
    let n2 = plane_sphere_at(
        &mut con[n1],
        margin,
        g1,
        &sub3(g2.pos, &segment),
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
    let normal = zaxis(g1.mat);
    let mut axis = zaxis(g2.mat);
    let (pos2, size2) = (&g2.pos, &g2.size);

    let mut prjaxis = dot3(&normal, &axis);
    if prjaxis > 0.0 {
        axis = scl3(&axis, crate::math::misc::minus_one());
        prjaxis = -prjaxis;
    }
    let dist0 = dot3(&sub3(pos2, g1.pos), &normal);

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
    let norm = zaxis(g1.mat);
    let dist = dot3(&sub3(g2.pos, g1.pos), &norm);
    let s = &g2.size;
    let mut cnt = 0;
    for i in 0..8 {
        let v = [
            if i & 1 != 0 { s[0] } else { -s[0] },
            if i & 2 != 0 { s[1] } else { -s[1] },
            if i & 4 != 0 { s[2] } else { -s[2] },
        ];
        let corner = crate::math::vec3::mul_mat_vec3(g2.mat, &v);
        let ldist = dot3(&norm, &corner);
        if dist + ldist > margin || ldist > 0.0 {
            continue;
        }
        let c = &mut con[cnt];
        c.dist = dist + ldist;
        c.set_normal(&norm);
        c.set_tangent(&[0.0; 3]);
        c.pos = add3(&add3(&corner, g2.pos), &scl3(&norm, -c.dist / 2.0));
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
        g1.pos,
        g1.mat,
        g1.size[0],
        g2.pos,
        g2.mat,
        g2.size[0],
    )
}

/// Sphere (g1) and capsule (g2).
pub fn sphere_capsule(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let m = &g2.mat;
    let h = g2.size[1];
    let axis = [m[2] * h, m[5] * h, m[8] * h];
    let vec = sub3(g1.pos, g2.pos);
    let x = clamp1(dot3(&axis, &vec) / dot3(&axis, &axis));
    let near = add3(&scl3(&axis, x), g2.pos);
    sphere_sphere_at(
        &mut con[0],
        margin,
        g1.pos,
        g1.mat,
        g1.size[0],
        &near,
        g2.mat,
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
    sphere_box_at(&mut con[0], margin, g1.pos, g1.size[0], g2)
}

/// Sphere of radius r at p and box g2.
fn sphere_box_at(con: &mut ContactGeom, margin: f64, p: &Vec3, r: f64, g2: &GeomPose) -> usize {
    use crate::math::vec3::{mul_mat_t_vec3, mul_mat_vec3};
    let size2 = &g2.size;
    let size1 = [r];
    let center = mul_mat_t_vec3(g2.mat, &sub3(p, g2.pos));
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

    let c = con;
    c.set_normal(&mul_mat_vec3(g2.mat, &normal));
    c.pos = add3(&mul_mat_vec3(g2.mat, &pos), g2.pos);
    c.dist = dist - size1[0];
    c.set_tangent(&[0.0; 3]);
    1
}

/// Capsule (g1) and box (g2): the segment point closest to the box, plus a second point along
/// the capsule when it lies along an edge or face (2.2.2's heuristics), each tested as a sphere.
pub fn capsule_box(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    use crate::math::vec3::{mul_mat_t_vec3, mul_mat_vec3};
    let (size1, size2) = (&g1.size, &g2.size);
    let halflength = size1[1];
    let mut secondpos = -4.0;

    // capsule center and axis in the box frame
    let pos = mul_mat_t_vec3(g2.mat, &sub3(g1.pos, g2.pos));
    let axis = mul_mat_t_vec3(g2.mat, &zaxis(g1.mat));
    let halfaxis = scl3(&axis, halflength);
    let mut axisdir = 0usize;
    for (k, h) in halfaxis.iter().enumerate() {
        if *h > 0.0 {
            axisdir += 1 << k;
        }
    }

    let bestdistmax = margin + 2.0 * (size1[0] + halflength + size2[0] + size2[1] + size2[2]);
    let mut best = Closest {
        dist: bestdistmax,
        segpos: 0.0,
        boxpos: 0.0,
        cltype: -4,
        corner: 0,
        edge: 0,
    };
    let mut clface: i32 = -1;

    // an end of the segment against a face
    for i in [-1.0f64, 1.0] {
        let end = add_scl(&pos, &halfaxis, i);
        let mut clamped = end;
        let (mut nclamp, mut face) = (0, -1);
        for j in 0..3 {
            if clamped[j] < -size2[j] {
                nclamp += 1;
                face = j as i32;
                clamped[j] = -size2[j];
            } else if clamped[j] > size2[j] {
                nclamp += 1;
                face = j as i32;
                clamped[j] = size2[j];
            }
        }
        if nclamp > 1 {
            continue;
        }
        let d = sub3(&clamped, &end);
        let dist = dot3(&d, &d);
        if dist < best.dist {
            best.dist = dist;
            best.segpos = i;
            best.cltype = -2 + i as i32;
            clface = face;
        }
    }
    closest_edges(&pos, &halfaxis, halflength, size2, &mut best);
    let Closest {
        segpos: bestsegmentpos,
        boxpos: bestboxpos,
        cltype,
        corner: clcorner,
        edge: cledge,
        ..
    } = best;

    if cltype == -4 {
        return 0;
    }

    let second = if cltype >= 0 && cltype / 3 != 1 {
        // closest to a box corner
        corner_second(axisdir ^ clcorner, &axis, &halfaxis, size2, bestsegmentpos)
    } else if cltype >= 0 {
        // closest to the middle of a box edge
        edge_second(
            axisdir,
            clcorner,
            cledge,
            &axis,
            &halfaxis,
            size2,
            bestsegmentpos,
            bestboxpos,
        )
    } else if clface == -1 {
        None
    } else {
        // an end is closest to a face: the farthest point still above that face
        let mul = if cltype == -3 { 1.0 } else { -1.0 };
        let mut sp = 2.0;
        let other = add_scl(&pos, &halfaxis, -mul);
        for i in 0..3 {
            if i as i32 != clface {
                for lim in [size2[i], -size2[i]] {
                    let e = (lim - other[i]) / halfaxis[i] * mul;
                    if e > 0.0 && e < sp {
                        sp = e;
                    }
                }
            }
        }
        Some(sp * mul)
    };
    if let Some(sp) = second {
        secondpos = sp;
    }

    let at = |segpos: f64| {
        let local = add_scl(&pos, &halfaxis, segpos);
        add3(&mul_mat_vec3(g2.mat, &local), g2.pos)
    };
    let mut n = sphere_box_at(&mut con[0], margin, &at(bestsegmentpos), size1[0], g2);
    if secondpos > -3.0 {
        n += sphere_box_at(
            &mut con[n],
            margin,
            &at(secondpos + bestsegmentpos),
            size1[0],
            g2,
        );
    }
    n
}

/// The closest feature pair found so far in `capsule_box`: squared distance, position on the
/// segment and on the box edge, type (-3/-1: an end against a face; else the clamping code
/// s1*3 + s2 of an edge, 0: at -1, 1: inside, 2: at +1), corner and edge axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Closest {
    pub dist: f64,
    pub segpos: f64,
    pub boxpos: f64,
    pub cltype: i32,
    pub corner: usize,
    pub edge: usize,
}

/// The segment (centre `pos`, half axis `halfaxis` of length `halflength`, box frame)
/// against the 12 box edges, updating `best` in 2.2.2's order (axis j, then corner i with bit
/// j clear, ascending; a closer edge by more than MINVAL wins). The four edges along one axis
/// are computed together, each lane choosing its clamps by selection rather than branches.
pub(crate) fn closest_edges(
    pos: &Vec3,
    halfaxis: &Vec3,
    halflength: f64,
    size2: &Vec3,
    best: &mut Closest,
) {
    edges_along::<0>(pos, halfaxis, halflength, size2, best);
    edges_along::<1>(pos, halfaxis, halflength, size2, best);
    edges_along::<2>(pos, halfaxis, halflength, size2, best);
}

/// `closest_edges` for the four edges along box axis J (a constant: no array is indexed by a
/// computed axis, which would go through memory).
#[inline(always)]
fn edges_along<const J: usize>(
    pos: &Vec3,
    halfaxis: &Vec3,
    halflength: f64,
    size2: &Vec3,
    best: &mut Closest,
) {
    let mc = halflength * halflength;
    let ma = size2[J] * size2[J];
    let mb = -size2[J] * halfaxis[J];
    let det = ma * mc - mb * mb;
    if det.abs() < MINVAL {
        return;
    }
    let (idet, imc, ima) = (1.0 / det, 1.0 / mc, 1.0 / ma);
    // the corners with bit J clear, ascending: l's bits with a zero inserted at J
    let corners = [0usize, 1, 2, 3].map(|l| (l >> J) << (J + 1) | (l & ((1 << J) - 1)));
    let lanes = corners.map(|i| {
        let sgn = |bit: usize| if i & bit != 0 { 1.0 } else { -1.0 };
        let mut corner = [sgn(1) * size2[0], sgn(2) * size2[1], sgn(4) * size2[2]];
        corner[J] = 0.0;
        let dif = sub3(&corner, pos);
        let u = -size2[J] * dif[J];
        let v = dot3(halfaxis, &dif);
        let (x1, x2) = ((mc * u - mb * v) * idet, (ma * v - mb * u) * idet);
        // x1 clamped first, x2 then following from it
        let (hi, lo) = (x1 > 1.0, x1 < -1.0);
        let s1 = clamped(hi, lo, 2, 0, 1);
        let x2 = clamped(hi, lo, (v - mb) * imc, (v + mb) * imc, x2);
        let x1 = clamped(hi, lo, 1.0, -1.0, x1);
        // then x2, x1 following from it and clamped (s1 kept where it is not)
        let (hi, lo) = (x2 > 1.0, x2 < -1.0);
        let s2 = clamped(hi, lo, 2, 0, 1);
        let (x1, s1) = if hi || lo {
            let y = if hi { (u - mb) * ima } else { (u + mb) * ima };
            clamped(y > 1.0, y < -1.0, (1.0, 2), (-1.0, 0), (y, s1))
        } else {
            (x1, s1)
        };
        let x2 = clamped(hi, lo, 1.0, -1.0, x2);
        let mut d = add_scl(&dif, halfaxis, -x2);
        d[J] += size2[J] * x1;
        (dot3(&d, &d), x1, x2, s1 * 3 + s2)
    });
    for (i, (dist, x1, x2, c1)) in corners.into_iter().zip(lanes) {
        if dist < best.dist - MINVAL {
            *best = Closest {
                dist,
                segpos: x2,
                boxpos: x1,
                cltype: c1,
                corner: i + (1 << J) * (c1 / 6) as usize,
                edge: J,
            };
        }
    }
}

/// A clamp's three outcomes: `above` where `hi`, `below` where `lo`, else `inside` (chosen by
/// selection; each argument is computed either way).
#[inline(always)]
fn clamped<T>(hi: bool, lo: bool, above: T, below: T, inside: T) -> T {
    if hi {
        above
    } else if lo {
        below
    } else {
        inside
    }
}

/// Second segment position when a box corner is closest (None: capsule points at the corner).
fn corner_second(rel: usize, axis: &Vec3, halfaxis: &Vec3, size2: &Vec3, best: f64) -> Option<f64> {
    let (mul, c1, de, dp) = match rel {
        1 | 2 | 4 => (1.0, rel, 1.0 - best, 1.0 + best),
        3 | 5 | 6 => (-1.0, 7 - rel, 1.0 + best, 1.0 - best),
        _ => return None,
    };
    let (ax, ax1, ax2) = match c1 {
        1 => (0, 1, 2),
        2 => (1, 2, 0),
        _ => (2, 0, 1),
    };
    let mut sp;
    if axis[ax] * axis[ax] > 0.5 {
        // along the box edge
        sp = de;
        let e = 2.0 * size2[ax] / halfaxis[ax].abs();
        if e < sp {
            sp = e;
        }
        sp *= mul;
    } else {
        // along a box face
        sp = dp;
        for a in [ax1, ax2] {
            let e = 2.0 * size2[a] / halfaxis[a].abs();
            if e < sp {
                sp = e;
            }
        }
        sp *= -mul;
    }
    Some(sp)
}

/// Second segment position when the middle of a box edge is closest (None: T configuration).
#[allow(clippy::too_many_arguments)]
fn edge_second(
    axisdir: usize,
    clcorner: usize,
    cledge: usize,
    axis: &Vec3,
    halfaxis: &Vec3,
    size2: &Vec3,
    best: f64,
    bestboxpos: f64,
) -> Option<f64> {
    let c1 = (axisdir ^ clcorner) & (7 - (1 << cledge));
    if c1 != 1 && c1 != 2 && c1 != 4 {
        return None;
    }
    let ax = cledge;
    let (mut ax1, ax2) = match cledge {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    };
    // the face the capsule is closer to being parallel with
    if axis[ax1].abs() > axis[ax2].abs() {
        ax1 = ax2;
    }
    let ax2 = 3 - ax - ax1;

    let (mul, mut sp) = if c1 & (1 << ax2) != 0 {
        (1.0, 1.0 - best)
    } else {
        (-1.0, 1.0 + best)
    };
    let e = 2.0 * size2[ax2] / halfaxis[ax2].abs();
    if e < sp {
        sp = e;
    }
    let e2 = if ((axisdir & (1 << ax)) != 0) == ((c1 & (1 << ax2)) != 0) {
        1.0 - bestboxpos
    } else {
        1.0 + bestboxpos
    };
    let e = size2[ax] * e2 / halfaxis[ax].abs();
    if e < sp {
        sp = e;
    }
    Some(sp * mul)
}
