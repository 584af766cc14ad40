//! A bounding-box test ahead of the costlier narrow-phase routines. Every routine reports a
//! contact only where the two geoms come within the margin (MPR: where the geoms grown by half
//! the margin each meet), so a pair whose boxes are farther apart than the margin along a face
//! axis of one of them gets no contact: skipping its routine leaves every result as it was.

use crate::engine::geom::*;
use crate::math::Vec3;

/// A geom's pose and the half-extents of its box in its own frame.
pub struct Bound {
    pub pos: Vec3,
    pub mat: [f64; 9],
    pub h: Vec3,
}

/// Half-extents of a geom's box from its type and size. A mesh geom's size is its mesh's
/// largest |coordinate| per axis (what the compiler writes, its bounding radius the norm of
/// that): taken only where the radius still says so. Sizes that are zero, negative or NaN (an
/// edited model: a routine may not bound the geom by them, box routines take a zero half-size
/// as no bound) give none, and so does a mesh whose size and radius disagree.
pub fn extent(t: i32, s: &[f64; 3], rbound: f64) -> Option<Vec3> {
    let (h, used) = match t {
        SPHERE => ([s[0]; 3], 1),
        CAPSULE => ([s[0], s[0], s[1] + s[0]], 2),
        CYLINDER => ([s[0], s[0], s[1]], 2),
        ELLIPSOID | BOX => (*s, 3),
        MESH if rbound > 0.0 && (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt() == rbound => {
            (*s, 3)
        }
        _ => return None,
    };
    s[..used].iter().all(|x| *x > 0.0).then_some(h)
}

/// Do these types (t1 <= t2) go to a routine worth a bounding-box test first: MPR (a mesh,
/// ellipsoid or cylinder against a non-plane) or capsule-box? Cheap routines, and box-box with
/// its own separating-axis exits, are left alone.
pub fn worth_testing(t1: i32, t2: i32) -> bool {
    let mpr = |t: i32| matches!(t, ELLIPSOID | CYLINDER | MESH);
    t1 >= SPHERE && (mpr(t1) || mpr(t2) || (t1 == CAPSULE && t2 == BOX))
}

/// Half-width of b's box along the unit axis u.
fn radius(b: &Bound, u: &Vec3) -> f64 {
    (0..3)
        .map(|j| b.h[j] * (u[0] * b.mat[j] + u[1] * b.mat[3 + j] + u[2] * b.mat[6 + j]).abs())
        .sum()
}

/// Are a and b apart by more than `margin` along a face axis of either box? The slack covers
/// rounding here and in the routines, and MPR's absolute tolerances (it takes the origin to lie
/// on the centres' line within 1.5e-8 / |centre distance|).
pub fn apart(a: &Bound, b: &Bound, margin: f64) -> bool {
    let dif = [
        b.pos[0] - a.pos[0],
        b.pos[1] - a.pos[1],
        b.pos[2] - a.pos[2],
    ];
    let dist = (dif[0] * dif[0] + dif[1] * dif[1] + dif[2] * dif[2]).sqrt();
    let size = |g: &Bound| g.h[0] + g.h[1] + g.h[2];
    // (coincident centres: an infinite limit; NaN: no gap compares greater)
    let limit = margin + 1e-6 * (size(a) + size(b)) + 1e-7 / dist;
    for (g, other) in [(a, b), (b, a)] {
        for k in 0..3 {
            let u = [g.mat[k], g.mat[3 + k], g.mat[6 + k]];
            let gap =
                (u[0] * dif[0] + u[1] * dif[1] + u[2] * dif[2]).abs() - g.h[k] - radius(other, &u);
            if gap > limit {
                return true;
            }
        }
    }
    false
}
