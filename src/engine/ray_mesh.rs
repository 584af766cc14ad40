//! Rays against triangle surfaces: meshes (mj_rayMesh), height fields (mj_rayHfield, with the
//! sides of their top box) and skins (mju_raySkin, nearest vertex too).

use super::linalg::row;
use super::ray::{box_faces, to_local};
use super::{Data, EngineError, Model, MINVAL};
use crate::abi::mjtGeom_::*;
use crate::math::misc::round;
use crate::math::vec3::{cross, dist3, dot3, norm3, normalize3};
use crate::math::Vec3;

/// Orthonormal basis (b0, b1) of the plane normal to the ray direction.
fn normal_plane(lvec: &Vec3) -> (Vec3, Vec3) {
    let mut b0 = [1.0, 1.0, 1.0];
    if lvec[0].abs() >= lvec[1].abs() && lvec[0].abs() >= lvec[2].abs() {
        b0[0] = 0.0;
    } else if lvec[1].abs() >= lvec[2].abs() {
        b0[1] = 0.0;
    } else {
        b0[2] = 0.0;
    }
    let s = -dot3(lvec, &b0) / dot3(lvec, lvec);
    let b1 = [
        b0[0] + lvec[0] * s,
        b0[1] + lvec[1] * s,
        b0[2] + lvec[2] * s,
    ];
    let b1 = normalize3(&b1).0;
    let b0 = normalize3(&cross(&b1, lvec)).0;
    (b0, b1)
}

/// Distance along the ray to the triangle v, or -1 (projection onto the normal plane).
fn triangle(v: &[Vec3; 3], lpnt: &Vec3, lvec: &Vec3, b0: &Vec3, b1: &Vec3) -> f64 {
    let mut dif = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            dif[i][j] = v[i][j] - lpnt[j];
        }
    }
    let mut planar = [[0.0; 2]; 3];
    for i in 0..3 {
        planar[i] = [dot3(b0, &dif[i]), dot3(b1, &dif[i])];
    }
    for k in 0..2 {
        if (planar[0][k] > 0.0 && planar[1][k] > 0.0 && planar[2][k] > 0.0)
            || (planar[0][k] < 0.0 && planar[1][k] < 0.0 && planar[2][k] < 0.0)
        {
            return -1.0;
        }
    }
    let a = [
        planar[0][0] - planar[2][0],
        planar[1][0] - planar[2][0],
        planar[0][1] - planar[2][1],
        planar[1][1] - planar[2][1],
    ];
    let b = [-planar[2][0], -planar[2][1]];
    let det = a[0] * a[3] - a[1] * a[2];
    if det.abs() < MINVAL {
        return -1.0;
    }
    let t0 = (a[3] * b[0] - a[1] * b[1]) / det;
    let t1 = (-a[2] * b[0] + a[0] * b[1]) / det;
    if t0 < 0.0 || t1 < 0.0 || t0 + t1 > 1.0 {
        return -1.0;
    }
    let e0 = sub(&v[0], &v[2]);
    let e1 = sub(&v[1], &v[2]);
    let e2 = sub(lpnt, &v[2]);
    let nrm = cross(&e0, &e1);
    let denom = dot3(lvec, &nrm);
    if denom.abs() < MINVAL {
        return -1.0;
    }
    -dot3(&e2, &nrm) / denom
}

fn sub(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn vertex(vert: &[f32], i: usize) -> Vec3 {
    [
        vert[3 * i] as f64,
        vert[3 * i + 1] as f64,
        vert[3 * i + 2] as f64,
    ]
}

/// mj_rayMesh: nearest triangle of the mesh geom `g` hit by the ray, or -1.
pub fn ray_mesh(m: &Model, d: &Data, g: usize, pnt: &Vec3, vec: &Vec3) -> Result<f64, EngineError> {
    if m.geom_type()[g] != mjGEOM_MESH as i32 {
        return Err(EngineError(
            "mj_rayMesh: geom with mesh type expected".into(),
        ));
    }
    let (pos, mat) = (row(d.geom_xpos, g), row(d.geom_xmat, g));
    let size = &m.geom_size()[3 * g..3 * g + 3];
    if box_faces(&pos, &mat, size, pnt, vec, &mut [0.0; 6]) < 0.0 {
        return Ok(-1.0);
    }
    let (lpnt, lvec) = to_local(&pos, &mat, pnt, vec);
    let (b0, b1) = normal_plane(&lvec);
    let id = m.geom_dataid()[g] as usize;
    let vadr = m.mesh_vertadr()[id] as usize;
    let fadr = m.mesh_faceadr()[id] as usize;
    let mut x = -1.0;
    for f in fadr..fadr + m.mesh_facenum()[id] as usize {
        let fv = &m.mesh_face()[3 * f..3 * f + 3];
        let v = [0, 1, 2].map(|k| vertex(m.mesh_vert(), fv[k] as usize + vadr));
        let sol = triangle(&v, &lpnt, &lvec, &b0, &b1);
        if sol >= 0.0 && (x < 0.0 || sol < x) {
            x = sol;
        }
    }
    Ok(x)
}

/// mj_rayHfield: the base box, the grid triangles under the ray's path through the top box,
/// and the sides of the top box below the elevation at their edge.
pub fn ray_hfield(
    m: &Model,
    d: &Data,
    g: usize,
    pnt: &Vec3,
    vec: &Vec3,
) -> Result<f64, EngineError> {
    if m.geom_type()[g] != mjGEOM_HFIELD as i32 {
        return Err(EngineError(
            "mj_rayHfield: geom with hfield type expected".into(),
        ));
    }
    let hid = m.geom_dataid()[g] as usize;
    let (nrow, ncol) = (m.hfield_nrow()[hid] as usize, m.hfield_ncol()[hid] as usize);
    let size: [f64; 4] = row(m.hfield_size(), hid);
    let adr = m.hfield_adr()[hid] as usize;
    let data = &m.hfield_data()[adr..adr + nrow * ncol];
    let (pos, mat) = (row::<3>(d.geom_xpos, g), row::<9>(d.geom_xmat, g));
    let z = [mat[2], mat[5], mat[8]];
    let base_size = [size[0], size[1], size[3] * 0.5];
    let base_pos = [0, 1, 2].map(|k| pos[k] - z[k] * size[3] * 0.5);
    let top_size = [size[0], size[1], size[2] * 0.5];
    let top_pos = [0, 1, 2].map(|k| pos[k] + z[k] * size[2] * 0.5);

    let mut x = box_faces(&base_pos, &mat, &base_size, pnt, vec, &mut [0.0; 6]);
    let mut all = [0.0; 6];
    let top = box_faces(&top_pos, &mat, &top_size, pnt, vec, &mut all);
    if top < 0.0 {
        return Ok(x);
    }
    let (lpnt, lvec) = to_local(&pos, &mat, pnt, vec);
    let (b0, b1) = normal_plane(&lvec);
    let mut seg = [0.0, top];
    for &a in &all {
        if a > seg[1] {
            seg = [top, a];
        }
    }
    let dx = (2.0 * size[0]) / (ncol as f64 - 1.0);
    let dy = (2.0 * size[1]) / (nrow as f64 - 1.0);
    let sx = seg.map(|s| (lpnt[0] + s * lvec[0] + size[0]) / dx);
    let sy = seg.map(|s| (lpnt[1] + s * lvec[1] + size[1]) / dy);
    let cmin = (sx[0].min(sx[1]).floor() as i64 - 1).max(0);
    let cmax = (sx[0].max(sx[1]).ceil() as i64 + 1).min(ncol as i64 - 1);
    let rmin = (sy[0].min(sy[1]).floor() as i64 - 1).max(0);
    let rmax = (sy[0].max(sy[1]).ceil() as i64 + 1).min(nrow as i64 - 1);
    let h = |r: usize, c: usize| data[r * ncol + c] as f64 * size[2];
    // 2.2.2 tests every cell of the rectangle; the nearest hit is the same if the cells far
    // from the ray's footprint in the plane are left out: per row, those more than PAD cells
    // beside where the ray's line crosses the row's strip (x keeps the smallest hit, whatever
    // the order)
    const PAD: f64 = 2.0;
    // a height gap far above rounding: the line passes the cell's triangles by more
    let margin = 1e-6 * (1.0 + size[0] + size[1] + size[2] + norm3(&lpnt));
    let slope = (lvec[0] * dy) / (lvec[1] * dx);
    let columns = |r: usize| -> (usize, usize) {
        let (lo, hi) = (cmin.max(0) as usize, cmax.max(0) as usize);
        let at = |gy: f64| sx[0] + (gy - sy[0]) * slope;
        let (a, b) = (at(r as f64), at(r as f64 + 1.0));
        let (c0, c1) = ((a.min(b) - PAD).floor(), (a.max(b) + PAD).ceil());
        if !(c0.is_finite() && c1.is_finite()) {
            return (lo, hi);
        }
        let c0 = c0.clamp(lo as f64, hi as f64) as usize;
        let c1 = c1.clamp(lo as f64, hi as f64) as usize;
        (c0, c1.max(c0))
    };
    // rows in the order the ray meets them: once a hit is known, rows more than PAD beyond
    // its row cannot hold a nearer one
    let rows = rmin.max(0) as usize..rmax.max(0) as usize;
    let ahead = lvec[1] < 0.0;
    let nrows = rows.len();
    for k in 0..nrows {
        let r = if ahead {
            rows.end - 1 - k
        } else {
            rows.start + k
        };
        if x >= 0.0 && lvec[1] != 0.0 {
            let gy = (lpnt[1] + x * lvec[1] + size[1]) / dy;
            let beyond = if ahead {
                (r as f64 + 1.0) < gy - PAD
            } else {
                r as f64 > gy + PAD
            };
            if beyond {
                break;
            }
        }
        let (c0, c1) = columns(r);
        let (y0, y1) = (dy * r as f64 - size[1], dy * (r + 1) as f64 - size[1]);
        // the whole row first, then cell by cell
        let (xa, xb) = (dx * c0 as f64 - size[0], dx * c1 as f64 - size[0]);
        if c1 > c0 {
            // the range of the stored values (a NaN one is skipped: its triangles never hit)
            let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
            for i in r..r + 2 {
                for &v in &data[i * ncol + c0..=i * ncol + c1] {
                    lo = if v < lo { v } else { lo };
                    hi = if v > hi { v } else { hi };
                }
            }
            let heights = [lo as f64 * size[2], hi as f64 * size[2]];
            if lo <= hi && clear_of(&lpnt, &lvec, [xa, xb, y0, y1], heights, margin) {
                continue;
            }
        }
        for c in c0..c1 {
            let (x0, x1) = (dx * c as f64 - size[0], dx * (c + 1) as f64 - size[0]);
            let corners = [(r, c), (r, c + 1), (r + 1, c), (r + 1, c + 1)];
            if clear_of(
                &lpnt,
                &lvec,
                [x0, x1, y0, y1],
                corners.map(|(i, j)| h(i, j)),
                margin,
            ) {
                continue;
            }
            let va = [
                [x0, y0, h(r, c)],
                [x1, y1, h(r + 1, c + 1)],
                [x1, y0, h(r, c + 1)],
            ];
            let sol = triangle(&va, &lpnt, &lvec, &b0, &b1);
            if sol >= 0.0 && (x < 0.0 || sol < x) {
                x = sol;
            }
            let vb = [
                [x0, y0, h(r, c)],
                [x1, y1, h(r + 1, c + 1)],
                [x0, y1, h(r + 1, c)],
            ];
            let sol = triangle(&vb, &lpnt, &lvec, &b0, &b1);
            if sol >= 0.0 && (x < 0.0 || sol < x) {
                x = sol;
            }
        }
    }
    // 2.2.2 indexes the side rows with nrow as the stride; outside the data it reads memory
    // that is not the height field's: 0 here
    let at = |i: i64| -> f64 {
        usize::try_from(i)
            .ok()
            .and_then(|i| data.get(i))
            .map_or(0.0, |&v| v as f64)
    };
    for i in 0..4 {
        if all[i] >= 0.0 && (all[i] < x || x < 0.0) {
            let zn = (lpnt[2] + all[i] * lvec[2]) / size[2];
            let (y, y0, z0, z1);
            if i < 2 {
                y = (lpnt[1] + all[i] * lvec[1] + size[1]) / dy;
                y0 = (nrow as f64 - 2.0).min(y.floor()).max(0.0);
                let col = if i == 1 { ncol as i64 - 1 } else { 0 };
                z0 = at(round(y0) as i64 * nrow as i64 + col);
                z1 = at(round(y0 + 1.0) as i64 * nrow as i64 + col);
            } else {
                y = (lpnt[0] + all[i] * lvec[0] + size[0]) / dx;
                y0 = (ncol as f64 - 2.0).min(y.floor()).max(0.0);
                let off = if i == 3 {
                    (nrow as i64 - 1) * ncol as i64
                } else {
                    0
                };
                z0 = at(round(y0) as i64 + off);
                z1 = at(round(y0 + 1.0) as i64 + off);
            }
            if zn < z0 * (y0 + 1.0 - y) + z1 * (y - y0) {
                x = all[i];
            }
        }
    }
    Ok(x)
}

/// Does the line lpnt + t*lvec pass over the rectangle [x0, x1] x [y0, y1] wholly above or
/// below `heights` (those of the grid points in it) by more than `margin`? Then it meets none
/// of the triangles there. False when unsure (a vertical line, NaN).
fn clear_of(
    lpnt: &Vec3,
    lvec: &Vec3,
    [x0, x1, y0, y1]: [f64; 4],
    heights: impl IntoIterator<Item = f64>,
    margin: f64,
) -> bool {
    // the line's parameter range over the cell's footprint (an axis it does not move along
    // leaves the range open)
    let slab = |p: f64, v: f64, lo: f64, hi: f64| -> (f64, f64) {
        if v == 0.0 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            let (a, b) = ((lo - p) / v, (hi - p) / v);
            (a.min(b), a.max(b))
        }
    };
    let (ax, bx) = slab(lpnt[0], lvec[0], x0, x1);
    let (ay, by) = slab(lpnt[1], lvec[1], y0, y1);
    let (t0, t1) = (ax.max(ay), bx.min(by));
    if !(t0.is_finite() && t1.is_finite()) {
        return false;
    }
    // hits behind the start do not count: only the part ahead (less `margin` of length)
    let back = margin / norm3(lvec);
    if t1 < -back {
        return true;
    }
    let t0 = t0.max(-back);
    let (z0, z1) = (lpnt[2] + t0 * lvec[2], lpnt[2] + t1 * lvec[2]);
    let (zlo, zhi) = (z0.min(z1), z0.max(z1));
    let (hmin, hmax) = heights
        .into_iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    zlo > hmax + margin || zhi < hmin - margin
}

/// mju_raySkin: nearest skin triangle hit (distance, or -1) and its vertex nearest to the hit.
pub fn ray_skin(face: &[i32], vert: &[f32], pnt: &Vec3, vec: &Vec3) -> (f64, i32) {
    let nvert = vert.len() / 3;
    let mut bx = [[0.0f64; 2]; 3];
    for i in 0..nvert {
        for j in 0..3 {
            let v = vert[3 * i + j] as f64;
            if bx[j][0] > v || i == 0 {
                bx[j][0] = v;
            }
            if bx[j][1] < v || i == 0 {
                bx[j][1] = v;
            }
        }
    }
    let pos = [0, 1, 2].map(|j| 0.5 * (bx[j][0] + bx[j][1]));
    let size = [0, 1, 2].map(|j| 0.5 * (bx[j][1] - bx[j][0]));
    let eye = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let mut vertid = -1;
    if box_faces(&pos, &eye, &size, pnt, vec, &mut [0.0; 6]) < 0.0 {
        return (-1.0, vertid);
    }
    let (b0, b1) = normal_plane(vec);
    let mut x = -1.0;
    for f in face.chunks_exact(3) {
        let v = [0, 1, 2].map(|k| vertex(vert, f[k] as usize));
        let sol = triangle(&v, pnt, vec, &b0, &b1);
        if sol >= 0.0 && (x < 0.0 || sol < x) {
            x = sol;
            let hit = [0, 1, 2].map(|k| pnt[k] + vec[k] * sol);
            let mut best = dist3(&hit, &v[0]);
            vertid = f[0];
            for j in 1..3 {
                let dj = dist3(&hit, &v[j]);
                if dj < best {
                    best = dj;
                    vertid = f[j];
                }
            }
        }
    }
    (x, vertid)
}
