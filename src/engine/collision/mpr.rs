//! Minkowski Portal Refinement for penetration of two convex sets, with the arithmetic of
//! libccd 2.1 in double precision (the version 2.2.2 links): same tests, tolerances and
//! operation order, so that contacts agree bit for bit given the same support functions.

use crate::math::Vec3;

/// libccd's epsilon (DBL_EPSILON).
pub const EPS: f64 = f64::EPSILON;

/// |x| < EPS.
#[inline]
pub fn is_zero(x: f64) -> bool {
    x.abs() < EPS
}

/// Equality up to EPS, absolute near zero and relative otherwise.
#[inline]
pub fn eq(a: f64, b: f64) -> bool {
    let ab = (a - b).abs();
    if ab.abs() < EPS {
        return true;
    }
    let (a, b) = (a.abs(), b.abs());
    if b > a {
        ab < EPS * b
    } else {
        ab < EPS * a
    }
}

/// Componentwise `eq`.
#[inline]
pub fn vec3_eq(a: &Vec3, b: &Vec3) -> bool {
    eq(a[0], b[0]) && eq(a[1], b[1]) && eq(a[2], b[2])
}

#[inline]
fn dot(a: &Vec3, b: &Vec3) -> f64 {
    let mut d = a[0] * b[0];
    d += a[1] * b[1];
    d += a[2] * b[2];
    d
}

#[inline]
fn cross(a: &Vec3, b: &Vec3) -> Vec3 {
    [
        (a[1] * b[2]) - (a[2] * b[1]),
        (a[2] * b[0]) - (a[0] * b[2]),
        (a[0] * b[1]) - (a[1] * b[0]),
    ]
}

#[inline]
fn sub(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
fn add(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

#[inline]
fn scale(a: &Vec3, k: f64) -> Vec3 {
    [a[0] * k, a[1] * k, a[2] * k]
}

#[inline]
fn normalized(a: &Vec3) -> Vec3 {
    let k = 1.0 / dot(a, a).sqrt();
    scale(a, k)
}

#[inline]
fn dist2(a: &Vec3, b: &Vec3) -> f64 {
    let d = sub(a, b);
    dot(&d, &d)
}

/// Squared distance from p to segment x0-b, and the closest point.
pub fn point_segment_dist2(p: &Vec3, x0: &Vec3, b: &Vec3) -> (f64, Vec3) {
    let d = sub(b, x0);
    let a = sub(x0, p);
    let mut t = -dot(&a, &d);
    t /= dot(&d, &d);
    if t < 0.0 || is_zero(t) {
        (dist2(x0, p), *x0)
    } else if t > 1.0 || eq(t, 1.0) {
        (dist2(b, p), *b)
    } else {
        let w = add(&scale(&d, t), x0);
        (dist2(&w, p), w)
    }
}

/// Squared distance from p to triangle x0-b-c, and the closest point.
pub fn point_tri_dist2(p: &Vec3, x0: &Vec3, b: &Vec3, c: &Vec3) -> (f64, Vec3) {
    let d1 = sub(b, x0);
    let d2 = sub(c, x0);
    let a = sub(x0, p);
    let v = dot(&d1, &d1);
    let w = dot(&d2, &d2);
    let pp = dot(&a, &d1);
    let q = dot(&a, &d2);
    let r = dot(&d1, &d2);

    let d = w * v - r * r;
    let (s, t) = if is_zero(d) {
        (-1.0, -1.0)
    } else {
        let s = (q * r - w * pp) / d;
        (s, (-s * r - q) / w)
    };

    if (is_zero(s) || s > 0.0)
        && (eq(s, 1.0) || s < 1.0)
        && (is_zero(t) || t > 0.0)
        && (eq(t, 1.0) || t < 1.0)
        && (eq(t + s, 1.0) || t + s < 1.0)
    {
        let wit = add(&add(x0, &scale(&d1, s)), &scale(&d2, t));
        (dist2(&wit, p), wit)
    } else {
        let mut best = point_segment_dist2(p, x0, b);
        for (e0, e1) in [(x0, c), (b, c)] {
            let cand = point_segment_dist2(p, e0, e1);
            if cand.0 < best.0 {
                best = cand;
            }
        }
        best
    }
}

/// A point of the Minkowski difference with the two support points it came from.
#[derive(Clone, Copy, Default, Debug)]
struct Support {
    v: Vec3,
    v1: Vec3,
    v2: Vec3,
}

/// Two convex sets given by centers and support functions (direction not normalized by callee).
pub struct ConvexPair<F1, F2> {
    pub center1: Vec3,
    pub center2: Vec3,
    pub support1: F1,
    pub support2: F2,
    /// Maximum number of refinement iterations in the penetration phase.
    pub max_iterations: u64,
    /// Portal tolerance.
    pub tolerance: f64,
}

impl<F1: FnMut(&Vec3) -> Vec3, F2: FnMut(&Vec3) -> Vec3> ConvexPair<F1, F2> {
    fn support(&mut self, dir: &Vec3) -> Support {
        let v1 = (self.support1)(dir);
        let v2 = (self.support2)(&scale(dir, -1.0));
        Support {
            v: sub(&v1, &v2),
            v1,
            v2,
        }
    }

    /// Penetration (depth, direction, position) of the two sets, None when they do not
    /// intersect (ccdMPRPenetration).
    pub fn mpr_penetration(&mut self) -> Option<(f64, Vec3, Vec3)> {
        let mut p = [Support::default(); 4];
        match self.discover_portal(&mut p) {
            Portal::Outside => None,
            Portal::TouchV1 => {
                let pos = scale(&add(&p[1].v1, &p[1].v2), 0.5);
                Some((0.0, [0.0; 3], pos))
            }
            Portal::OnSegment => {
                let pos = scale(&add(&p[1].v1, &p[1].v2), 0.5);
                let dir = p[1].v;
                let depth = dot(&dir, &dir).sqrt();
                Some((depth, normalized(&dir), pos))
            }
            Portal::Built => {
                if !self.refine_portal(&mut p) {
                    return None;
                }
                Some(self.find_penetration(&mut p))
            }
        }
    }

    fn discover_portal(&mut self, p: &mut [Support; 4]) -> Portal {
        p[0] = Support {
            v: sub(&self.center1, &self.center2),
            v1: self.center1,
            v2: self.center2,
        };
        if vec3_eq(&p[0].v, &[0.0; 3]) {
            p[0].v = add(&p[0].v, &[EPS * 10.0, 0.0, 0.0]);
        }

        let mut dir = normalized(&scale(&p[0].v, -1.0));
        p[1] = self.support(&dir);
        let d = dot(&p[1].v, &dir);
        if is_zero(d) || d < 0.0 {
            return Portal::Outside;
        }

        dir = cross(&p[0].v, &p[1].v);
        if is_zero(dot(&dir, &dir)) {
            return if vec3_eq(&p[1].v, &[0.0; 3]) {
                Portal::TouchV1
            } else {
                Portal::OnSegment
            };
        }

        dir = normalized(&dir);
        p[2] = self.support(&dir);
        let d = dot(&p[2].v, &dir);
        if is_zero(d) || d < 0.0 {
            return Portal::Outside;
        }

        let face_dir = |p: &[Support; 4]| {
            let va = sub(&p[1].v, &p[0].v);
            let vb = sub(&p[2].v, &p[0].v);
            normalized(&cross(&va, &vb))
        };
        dir = face_dir(p);
        if dot(&dir, &p[0].v) > 0.0 {
            p.swap(1, 2);
            dir = scale(&dir, -1.0);
        }

        loop {
            p[3] = self.support(&dir);
            let d = dot(&p[3].v, &dir);
            if is_zero(d) || d < 0.0 {
                return Portal::Outside;
            }

            let mut cont = false;
            let d = dot(&cross(&p[1].v, &p[3].v), &p[0].v);
            if d < 0.0 && !is_zero(d) {
                p[2] = p[3];
                cont = true;
            }
            if !cont {
                let d = dot(&cross(&p[3].v, &p[2].v), &p[0].v);
                if d < 0.0 && !is_zero(d) {
                    p[1] = p[3];
                    cont = true;
                }
            }
            if !cont {
                return Portal::Built;
            }
            dir = face_dir(p);
        }
    }

    fn refine_portal(&mut self, p: &mut [Support; 4]) -> bool {
        loop {
            let dir = portal_dir(p);
            if encapsulates_origin(p, &dir) {
                return true;
            }
            let v4 = self.support(&dir);
            if !can_encapsulate_origin(&v4, &dir) || reach_tolerance(p, &v4, &dir, self.tolerance) {
                return false;
            }
            expand_portal(p, &v4);
        }
    }

    fn find_penetration(&mut self, p: &mut [Support; 4]) -> (f64, Vec3, Vec3) {
        let mut iterations: u64 = 0;
        loop {
            let dir = portal_dir(p);
            let v4 = self.support(&dir);
            if reach_tolerance(p, &v4, &dir, self.tolerance) || iterations > self.max_iterations {
                let (d2, w) = point_tri_dist2(&[0.0; 3], &p[1].v, &p[2].v, &p[3].v);
                let depth = d2.sqrt();
                let pdir = if is_zero(depth) {
                    [0.0; 3]
                } else {
                    normalized(&w)
                };
                return (depth, pdir, find_pos(p));
            }
            expand_portal(p, &v4);
            iterations += 1;
        }
    }
}

enum Portal {
    Outside,
    TouchV1,
    OnSegment,
    Built,
}

fn portal_dir(p: &[Support; 4]) -> Vec3 {
    let v2v1 = sub(&p[2].v, &p[1].v);
    let v3v1 = sub(&p[3].v, &p[1].v);
    normalized(&cross(&v2v1, &v3v1))
}

fn encapsulates_origin(p: &[Support; 4], dir: &Vec3) -> bool {
    let d = dot(dir, &p[1].v);
    is_zero(d) || d > 0.0
}

fn can_encapsulate_origin(v4: &Support, dir: &Vec3) -> bool {
    let d = dot(&v4.v, dir);
    is_zero(d) || d > 0.0
}

fn reach_tolerance(p: &[Support; 4], v4: &Support, dir: &Vec3, tol: f64) -> bool {
    let dv1 = dot(&p[1].v, dir);
    let dv2 = dot(&p[2].v, dir);
    let dv3 = dot(&p[3].v, dir);
    let dv4 = dot(&v4.v, dir);
    let m = (dv4 - dv1).min(dv4 - dv2).min(dv4 - dv3);
    eq(m, tol) || m < tol
}

fn expand_portal(p: &mut [Support; 4], v4: &Support) {
    let v4v0 = cross(&v4.v, &p[0].v);
    if dot(&p[1].v, &v4v0) > 0.0 {
        if dot(&p[2].v, &v4v0) > 0.0 {
            p[1] = *v4;
        } else {
            p[3] = *v4;
        }
    } else if dot(&p[3].v, &v4v0) > 0.0 {
        p[2] = *v4;
    } else {
        p[1] = *v4;
    }
}

fn find_pos(p: &[Support; 4]) -> Vec3 {
    let dir = portal_dir(p);
    let mut b = [
        dot(&cross(&p[1].v, &p[2].v), &p[3].v),
        dot(&cross(&p[3].v, &p[2].v), &p[0].v),
        dot(&cross(&p[0].v, &p[1].v), &p[3].v),
        dot(&cross(&p[2].v, &p[1].v), &p[0].v),
    ];
    let mut sum = b[0] + b[1] + b[2] + b[3];
    if is_zero(sum) || sum < 0.0 {
        b[0] = 0.0;
        b[1] = dot(&cross(&p[2].v, &p[3].v), &dir);
        b[2] = dot(&cross(&p[3].v, &p[1].v), &dir);
        b[3] = dot(&cross(&p[1].v, &p[2].v), &dir);
        sum = b[1] + b[2] + b[3];
    }
    let inv = 1.0 / sum;

    let mut p1 = [0.0; 3];
    let mut p2 = [0.0; 3];
    for (s, bi) in p.iter().zip(b) {
        p1 = add(&p1, &scale(&s.v1, bi));
        p2 = add(&p2, &scale(&s.v2, bi));
    }
    let p1 = scale(&p1, inv);
    let p2 = scale(&p2, inv);
    scale(&add(&p1, &p2), 0.5)
}
