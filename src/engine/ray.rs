//! Ray casting (mj_ray, mju_rayGeom): distance along the ray direction to the nearest surface
//! point, or -1 when the ray misses. Meshes, height fields and skins: ray_mesh.rs.

use super::geom::*;
use super::linalg::row;
use super::{Data, EngineError, Model, MINVAL};
use crate::math::{norm3, Mat3, Vec3};

/// Number of geom groups (mjNGROUP).
const NGROUP: i32 = 6;

/// Ray point and direction in the geom frame.
pub fn to_local(pos: &Vec3, mat: &Mat3, pnt: &Vec3, vec: &Vec3) -> (Vec3, Vec3) {
    let dif = [pnt[0] - pos[0], pnt[1] - pos[1], pnt[2] - pos[2]];
    let tr = |v: &Vec3| {
        [
            mat[0] * v[0] + mat[3] * v[1] + mat[6] * v[2],
            mat[1] * v[0] + mat[4] * v[1] + mat[7] * v[2],
            mat[2] * v[0] + mat[5] * v[1] + mat[8] * v[2],
        ]
    };
    (tr(&dif), tr(vec))
}

/// Roots of a*x^2 + 2*b*x + c = 0 (both -1 without real roots) and the smallest
/// non-negative one, or -1.
fn quadratic(a: f64, b: f64, c: f64) -> (f64, [f64; 2]) {
    let det = b * b - a * c;
    if det < MINVAL {
        return (-1.0, [-1.0, -1.0]);
    }
    let det = det.sqrt();
    let x = [(-b - det) / a, (-b + det) / a];
    let best = if x[0] >= 0.0 {
        x[0]
    } else if x[1] >= 0.0 {
        x[1]
    } else {
        -1.0
    };
    (best, x)
}

/// Keeps the smaller non-negative distance.
fn nearer(x: f64, sol: f64) -> f64 {
    if x < 0.0 || sol < x {
        sol
    } else {
        x
    }
}

fn plane(pos: &Vec3, mat: &Mat3, size: &[f64], pnt: &Vec3, vec: &Vec3) -> f64 {
    let (lp, lv) = to_local(pos, mat, pnt, vec);
    // only rays coming towards the front face
    if lv[2] > -MINVAL {
        return -1.0;
    }
    let x = -lp[2] / lv[2];
    if x < 0.0 {
        return -1.0;
    }
    let p0 = lp[0] + x * lv[0];
    let p1 = lp[1] + x * lv[1];
    if (size[0] <= 0.0 || p0.abs() <= size[0]) && (size[1] <= 0.0 || p1.abs() <= size[1]) {
        x
    } else {
        -1.0
    }
}

/// (a, b, c) of the ray's quadratic a*x^2 + 2*b*x + c = 0 against a sphere.
#[inline(always)]
fn sphere_terms(pos: &Vec3, radius: f64, pnt: &Vec3, vec: &Vec3) -> (f64, f64, f64) {
    let dif = [pnt[0] - pos[0], pnt[1] - pos[1], pnt[2] - pos[2]];
    let a = vec[0] * vec[0] + vec[1] * vec[1] + vec[2] * vec[2];
    let b = vec[0] * dif[0] + vec[1] * dif[1] + vec[2] * dif[2];
    let c = dif[0] * dif[0] + dif[1] * dif[1] + dif[2] * dif[2] - radius * radius;
    (a, b, c)
}

fn sphere(pos: &Vec3, radius: f64, pnt: &Vec3, vec: &Vec3) -> f64 {
    let (a, b, c) = sphere_terms(pos, radius, pnt, vec);
    quadratic(a, b, c).0
}

/// Does the ray meet the sphere at a non-negative distance: `sphere(..) >= 0` without its
/// divisions. Its larger root decides (the smaller never exceeds it), and that root's sign is
/// its numerator's when the divisor `a` is finite; otherwise the root is computed as there.
#[inline(always)]
fn meets_sphere(pos: &Vec3, radius: f64, pnt: &Vec3, vec: &Vec3) -> bool {
    let (a, b, c) = sphere_terms(pos, radius, pnt, vec);
    let det = b * b - a * c;
    if det < MINVAL {
        return false;
    }
    let num = -b + det.sqrt();
    if num > 0.0 && a < f64::INFINITY {
        true
    } else {
        num / a >= 0.0
    }
}

/// `meets_sphere` for a ray whose `a` (its direction's squared length) lies in [1e-300, 1e280],
/// without branching on the outcome: there a root's numerator below -1e-40 divides to a
/// negative root, so the numerator's sign decides but in that sliver near zero. The numerator
/// -b + sqrt(det) is >= 0 exactly when the rounded root is >= b, so the root is taken only
/// where det lies within 1e-12 of b^2 (b in [1e-20, 1e150]): elsewhere det >= MINVAL with
/// b <= 0 or det above b^2 meets, det below b^2 (by at least 1e-12, so that the numerator is
/// under -1e-40) misses.
#[inline(always)]
fn meets_sphere_sure(pos: &Vec3, radius: f64, pnt: &Vec3, vec: &Vec3) -> bool {
    let (a, b, c) = sphere_terms(pos, radius, pnt, vec);
    let det = b * b - a * c;
    let det_ok = det >= MINVAL;
    let scaled = (1e-20..=1e150).contains(&b);
    let p = b * b;
    let above = scaled & (det > p * (1.0 + 1e-12));
    let below = scaled & (det < p * (1.0 - 1e-12));
    if !det_ok | (b <= 0.0) | above | below {
        return det_ok & !below;
    }
    // det >= MINVAL from here
    let num = -b + det.sqrt();
    if (num > -1e-40) & (num < 0.0) {
        return num / a >= 0.0;
    }
    num >= 0.0
}

/// Capsule, once the ray meets its bounding sphere.
fn capsule(pos: &Vec3, mat: &Mat3, size: &[f64], pnt: &Vec3, vec: &Vec3) -> f64 {
    let (lp, lv) = to_local(pos, mat, pnt, vec);
    let mut x = -1.0;

    // round side, between the flat ends
    let a = lv[0] * lv[0] + lv[1] * lv[1];
    let b = lv[0] * lp[0] + lv[1] * lp[1];
    let c = lp[0] * lp[0] + lp[1] * lp[1] - size[0] * size[0];
    let (sol, _) = quadratic(a, b, c);
    if sol >= 0.0 && (lp[2] + sol * lv[2]).abs() <= size[1] {
        x = nearer(x, sol);
    }

    // caps: the outer half of each end sphere
    let mut ldif = [lp[0], lp[1], lp[2] - size[1]];
    let a = lv[0] * lv[0] + lv[1] * lv[1] + lv[2] * lv[2];
    let b = lv[0] * ldif[0] + lv[1] * ldif[1] + lv[2] * ldif[2];
    let c = ldif[0] * ldif[0] + ldif[1] * ldif[1] + ldif[2] * ldif[2] - size[0] * size[0];
    let (_, xx) = quadratic(a, b, c);
    for s in xx {
        if s >= 0.0 && lp[2] + s * lv[2] >= size[1] {
            x = nearer(x, s);
        }
    }
    ldif[2] = lp[2] + size[1];
    let b = lv[0] * ldif[0] + lv[1] * ldif[1] + lv[2] * ldif[2];
    let c = ldif[0] * ldif[0] + ldif[1] * ldif[1] + ldif[2] * ldif[2] - size[0] * size[0];
    let (_, xx) = quadratic(a, b, c);
    for s in xx {
        if s >= 0.0 && lp[2] + s * lv[2] <= -size[1] {
            x = nearer(x, s);
        }
    }
    x
}

fn ellipsoid(pos: &Vec3, mat: &Mat3, size: &[f64], pnt: &Vec3, vec: &Vec3) -> f64 {
    let (lp, lv) = to_local(pos, mat, pnt, vec);
    let s = [
        1.0 / (size[0] * size[0]),
        1.0 / (size[1] * size[1]),
        1.0 / (size[2] * size[2]),
    ];
    let a = s[0] * lv[0] * lv[0] + s[1] * lv[1] * lv[1] + s[2] * lv[2] * lv[2];
    let b = s[0] * lv[0] * lp[0] + s[1] * lv[1] * lp[1] + s[2] * lv[2] * lp[2];
    let c = s[0] * lp[0] * lp[0] + s[1] * lp[1] * lp[1] + s[2] * lp[2] * lp[2] - 1.0;
    quadratic(a, b, c).0
}

/// Cylinder, once the ray meets its bounding sphere.
fn cylinder(pos: &Vec3, mat: &Mat3, size: &[f64], pnt: &Vec3, vec: &Vec3) -> f64 {
    let (lp, lv) = to_local(pos, mat, pnt, vec);
    let mut x = -1.0;

    // flat ends, within the radius
    if lv[2].abs() > MINVAL {
        for side in [-1.0, 1.0] {
            let sol = (side * size[1] - lp[2]) / lv[2];
            if sol >= 0.0 {
                let p0 = lp[0] + sol * lv[0];
                let p1 = lp[1] + sol * lv[1];
                if p0 * p0 + p1 * p1 <= size[0] * size[0] {
                    x = nearer(x, sol);
                }
            }
        }
    }

    // round side, between the flat ends
    let a = lv[0] * lv[0] + lv[1] * lv[1];
    let b = lv[0] * lp[0] + lv[1] * lp[1];
    let c = lp[0] * lp[0] + lp[1] * lp[1] - size[0] * size[0];
    let (sol, _) = quadratic(a, b, c);
    if sol >= 0.0 && (lp[2] + sol * lv[2]).abs() <= size[1] {
        x = nearer(x, sol);
    }
    x
}

/// Box intersection; `all` receives the distance to each face (-x, +x, -y, +y, -z, +z) that
/// the ray crosses inside the face, else -1.
pub fn box_faces(
    pos: &Vec3,
    mat: &Mat3,
    size: &[f64],
    pnt: &Vec3,
    vec: &Vec3,
    all: &mut [f64; 6],
) -> f64 {
    *all = [-1.0; 6];
    if !meets_sphere(pos, bounding_radius(BOX, size).unwrap_or(0.0), pnt, vec) {
        return -1.0;
    }
    box_inside(pos, mat, size, pnt, vec, all)
}

/// `box_faces` once the ray meets the bounding sphere (`all` all -1).
fn box_inside(
    pos: &Vec3,
    mat: &Mat3,
    size: &[f64],
    pnt: &Vec3,
    vec: &Vec3,
    all: &mut [f64; 6],
) -> f64 {
    const FACE: [[usize; 2]; 3] = [[1, 2], [0, 2], [0, 1]];
    let (lp, lv) = to_local(pos, mat, pnt, vec);
    let mut x = -1.0;
    for i in 0..3 {
        if lv[i].abs() > MINVAL {
            for side in [-1.0, 1.0] {
                let sol = (side * size[i] - lp[i]) / lv[i];
                if sol >= 0.0 {
                    let [j, k] = FACE[i];
                    let p0 = lp[j] + sol * lv[j];
                    let p1 = lp[k] + sol * lv[k];
                    if p0.abs() <= size[j] && p1.abs() <= size[k] {
                        x = nearer(x, sol);
                        all[2 * i + (side > 0.0) as usize] = sol;
                    }
                }
            }
        }
    }
    x
}

/// Distance from `pnt` along `vec` to a primitive geom of type `geomtype` at (pos, mat) with
/// `size`, or -1 on a miss (mju_rayGeom; meshes and height fields excluded).
pub fn ray_geom(
    pos: &Vec3,
    mat: &Mat3,
    size: &[f64],
    pnt: &Vec3,
    vec: &Vec3,
    geomtype: i32,
) -> Result<f64, EngineError> {
    primitive(pos, mat, size, pnt, vec, geomtype)
        .ok_or_else(|| EngineError(format!("mju_rayGeom: unexpected geom type {geomtype}")))
}

/// Radius of the sphere whose test a primitive's own test starts with (None: no such test).
fn bounding_radius(ty: i32, size: &[f64]) -> Option<f64> {
    match ty {
        SPHERE => Some(size[0]),
        CAPSULE => Some(size[0] + size[1]),
        CYLINDER => Some((size[0] * size[0] + size[1] * size[1]).sqrt()),
        BOX => Some((size[0] * size[0] + size[1] * size[1] + size[2] * size[2]).sqrt()),
        _ => None,
    }
}

/// `ray_geom` for the primitive types; None for the others.
fn primitive(pos: &Vec3, mat: &Mat3, size: &[f64], pnt: &Vec3, vec: &Vec3, ty: i32) -> Option<f64> {
    match bounding_radius(ty, size) {
        Some(r) if !meets_sphere(pos, r, pnt, vec) => Some(-1.0),
        _ => primitive_inside(pos, mat, size, pnt, vec, ty),
    }
}

/// A primitive's own test, once the ray meets its bounding sphere; None for other types.
#[inline]
fn primitive_inside(
    pos: &Vec3,
    mat: &Mat3,
    size: &[f64],
    pnt: &Vec3,
    vec: &Vec3,
    ty: i32,
) -> Option<f64> {
    Some(match ty {
        PLANE => plane(pos, mat, size, pnt, vec),
        SPHERE => sphere(pos, size[0], pnt, vec),
        CAPSULE => capsule(pos, mat, size, pnt, vec),
        ELLIPSOID => ellipsoid(pos, mat, size, pnt, vec),
        CYLINDER => cylinder(pos, mat, size, pnt, vec),
        BOX => box_inside(pos, mat, size, pnt, vec, &mut [-1.0; 6]),
        _ => return None,
    })
}

/// The model arrays that decide which geoms a ray sees, taken once per cast.
struct Visibility<'a> {
    body: &'a [i32],
    matid: &'a [i32],
    rgba: &'a [f32],
    mat_rgba: &'a [f32],
    ty: &'a [i32],
    group: &'a [i32],
}

impl<'a> Visibility<'a> {
    fn of(m: &'a Model) -> Self {
        Visibility {
            body: m.geom_bodyid(),
            matid: m.geom_matid(),
            rgba: m.geom_rgba(),
            mat_rgba: m.mat_rgba(),
            ty: m.geom_type(),
            group: m.geom_group(),
        }
    }

    /// Is geom `g` left out: the excluded body, invisible (alpha 0, own or material), static
    /// when static geoms are off, or a hidden group (planes and height fields ignore groups)?
    fn eliminated(&self, g: usize, groups: Option<&[u8]>, with_static: bool, exclude: i32) -> bool {
        let body = self.body[g];
        if body == exclude {
            return true;
        }
        let mat = self.matid[g];
        if mat < 0 && self.rgba[4 * g + 3] == 0.0 {
            return true;
        }
        if mat >= 0 && self.mat_rgba[4 * mat as usize + 3] == 0.0 {
            return true;
        }
        if !with_static && body == 0 {
            return true;
        }
        let ty = self.ty[g];
        if ty == PLANE || ty == HFIELD {
            return false;
        }
        match groups {
            None => false,
            Some(gr) => gr[self.group[g].clamp(0, NGROUP - 1) as usize] == 0,
        }
    }
}

/// Nearest geom hit by the ray from `pnt` along `vec`: (distance, geom id), or (-1, -1)
/// (mj_ray).
pub fn ray(
    m: &Model,
    d: &Data,
    pnt: &Vec3,
    vec: &Vec3,
    groups: Option<&[u8]>,
    with_static: bool,
    exclude: i32,
) -> Result<(f64, i32), EngineError> {
    check_vec(vec)?;
    let vis = Visibility::of(m);
    let size = m.geom_size();
    let ngeom = m.raw.ngeom as usize;
    let sure = sure(vec);
    let mut best = (-1.0, -1);
    // geoms in blocks: first the bounding-sphere tests of the whole block, without branching
    // on their outcome, then the geoms left, in order (the first nearest one is kept)
    let mut left = [0u32; BLOCK];
    for start in (0..ngeom).step_by(BLOCK) {
        let mut n = 0;
        for g in start..ngeom.min(start + BLOCK) {
            if vis.eliminated(g, groups, with_static, exclude) {
                continue;
            }
            let r = bounding_radius(vis.ty[g], &size[3 * g..3 * g + 3]);
            left[n] = g as u32;
            n += meets(d, g, r, sure, pnt, vec) as usize;
        }
        nearest(m, d, &left[..n], pnt, vec, &mut best)?;
    }
    Ok(best)
}

/// Geoms per block of bounding-sphere tests.
const BLOCK: usize = 64;

/// Most geoms `Targets` holds (on the call stack).
pub const TARGETS_MAX: usize = 256;

/// The geoms rays of one visibility filter can see (each ray's excluded body aside), in
/// order, with their bounding radii: prepared once for many casts (rangefinders).
pub struct Targets {
    n: usize,
    /// geom id, or !id for a type without a bounding sphere
    geom: [i32; TARGETS_MAX],
    radius: [f64; TARGETS_MAX],
}

impl Targets {
    /// None when the model has more than TARGETS_MAX geoms (then `ray` casts each).
    pub fn new(m: &Model, groups: Option<&[u8]>, with_static: bool) -> Option<Targets> {
        let ngeom = m.raw.ngeom as usize;
        if ngeom > TARGETS_MAX {
            return None;
        }
        let vis = Visibility::of(m);
        let size = m.geom_size();
        let mut t = Targets {
            n: 0,
            geom: [0; TARGETS_MAX],
            radius: [0.0; TARGETS_MAX],
        };
        for g in 0..ngeom {
            if vis.eliminated(g, groups, with_static, -1) {
                continue;
            }
            (t.geom[t.n], t.radius[t.n]) = match bounding_radius(vis.ty[g], &size[3 * g..3 * g + 3])
            {
                Some(r) => (g as i32, r),
                None => (!(g as i32), 0.0),
            };
            t.n += 1;
        }
        Some(t)
    }
}

/// `ray` over prepared targets: the same result as `ray` with the targets' filter.
pub fn ray_among(
    m: &Model,
    d: &Data,
    t: &Targets,
    pnt: &Vec3,
    vec: &Vec3,
    exclude: i32,
) -> Result<(f64, i32), EngineError> {
    check_vec(vec)?;
    let body = m.geom_bodyid();
    let sure = sure(vec);
    let mut best = (-1.0, -1);
    let mut left = [0u32; BLOCK];
    for (geom, radius) in t.geom[..t.n]
        .chunks(BLOCK)
        .zip(t.radius[..t.n].chunks(BLOCK))
    {
        let mut n = 0;
        for (&code, &r) in geom.iter().zip(radius) {
            let (g, r) = if code >= 0 {
                (code as usize, Some(r))
            } else {
                (!code as usize, None)
            };
            left[n] = g as u32;
            n += (meets(d, g, r, sure, pnt, vec) & (body[g] != exclude)) as usize;
        }
        nearest(m, d, &left[..n], pnt, vec, &mut best)?;
    }
    Ok(best)
}

/// mj_ray's check of the direction.
fn check_vec(vec: &Vec3) -> Result<(), EngineError> {
    if norm3(vec) < MINVAL {
        return Err(EngineError("mj_ray: vector length is too small".into()));
    }
    Ok(())
}

/// Does the direction's squared length allow `meets_sphere_sure`?
fn sure(vec: &Vec3) -> bool {
    let a = vec[0] * vec[0] + vec[1] * vec[1] + vec[2] * vec[2];
    (1e-300..1e280).contains(&a)
}

/// Does the ray meet geom `g`'s bounding sphere of radius `r` (None: no sphere test)?
#[inline(always)]
fn meets(d: &Data, g: usize, r: Option<f64>, sure: bool, pnt: &Vec3, vec: &Vec3) -> bool {
    let pos = row(d.geom_xpos, g);
    match r {
        None => true,
        Some(r) if sure => meets_sphere_sure(&pos, r, pnt, vec),
        Some(r) => meets_sphere(&pos, r, pnt, vec),
    }
}

/// The exact tests of the geoms `left` (in order) into `best`: the first nearest is kept.
fn nearest(
    m: &Model,
    d: &Data,
    left: &[u32],
    pnt: &Vec3,
    vec: &Vec3,
    best: &mut (f64, i32),
) -> Result<(), EngineError> {
    let (ty, size) = (m.geom_type(), m.geom_size());
    for &g in left {
        let g = g as usize;
        let ty = ty[g];
        let x = if ty == MESH {
            super::ray_mesh::ray_mesh(m, d, g, pnt, vec)?
        } else if ty == HFIELD {
            super::ray_mesh::ray_hfield(m, d, g, pnt, vec)?
        } else {
            let (pos, mat) = (row(d.geom_xpos, g), row(d.geom_xmat, g));
            primitive_inside(&pos, &mat, &size[3 * g..3 * g + 3], pnt, vec, ty)
                .ok_or_else(|| EngineError(format!("mj_ray: unexpected geom type {ty}")))?
        };
        if x >= 0.0 && (x < best.0 || best.0 < 0.0) {
            *best = (x, g as i32);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bounding-sphere test with its root always taken (before the shortcut).
    fn meets_sphere_rooted(pos: &Vec3, radius: f64, pnt: &Vec3, vec: &Vec3) -> bool {
        let (a, b, c) = sphere_terms(pos, radius, pnt, vec);
        let det = b * b - a * c;
        let num = -b + det.sqrt();
        if (num > -1e-40) & (num < 0.0) {
            return det >= MINVAL && num / a >= 0.0;
        }
        (det >= MINVAL) & (num >= 0.0)
    }

    #[test]
    fn sphere_shortcut_decides_as_the_root() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut unit = || (next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
        let (mut hits, mut misses, mut origin_on_surface) = (0, 0, 0);
        for i in 0..400_000 {
            let scale = 10f64.powi((i % 61) - 30);
            let pos = [unit() * scale, unit() * scale, unit() * scale];
            let pnt = [unit() * scale, unit() * scale, unit() * scale];
            let mut vec = [unit(), unit(), unit()];
            if i % 7 == 0 {
                vec = [unit() * 1e-100, unit() * 1e-100, unit() * 1e-100];
            }
            let dist =
                ((pnt[0] - pos[0]).powi(2) + (pnt[1] - pos[1]).powi(2) + (pnt[2] - pos[2]).powi(2))
                    .sqrt();
            // every third: the ray starts on (within a few ulps of) the sphere
            let radius = if i % 3 == 0 {
                origin_on_surface += 1;
                dist * (1.0 + ((i / 3) % 9) as f64 * f64::EPSILON - 4.0 * f64::EPSILON)
            } else {
                unit().abs() * scale * 2.0
            };
            let a = vec[0] * vec[0] + vec[1] * vec[1] + vec[2] * vec[2];
            if !(1e-300..1e280).contains(&a) {
                continue;
            }
            let want = meets_sphere_rooted(&pos, radius, &pnt, &vec);
            assert_eq!(
                meets_sphere_sure(&pos, radius, &pnt, &vec),
                want,
                "pos {pos:?} radius {radius:e} pnt {pnt:?} vec {vec:?}"
            );
            if want {
                hits += 1;
            } else {
                misses += 1;
            }
        }
        assert!(hits > 50_000 && misses > 50_000 && origin_on_surface > 100_000);
    }
}
