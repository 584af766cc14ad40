//! Skins that composites generate: two-sided sheets for grids and cloth (optionally refined by
//! a bicubic subgrid), and closed surfaces for box, cylinder and ellipsoid.

use super::composite::{CompSkin, Composite};
use super::spec::{Bone, Skin};
use std::collections::HashMap;

fn new_skin(c: &Composite, s: &CompSkin) -> Skin {
    Skin {
        name: format!("{}Skin", c.prefix),
        material: s.material.clone(),
        rgba: s.rgba,
        inflate: s.inflate,
        group: s.group,
        ..Skin::default()
    }
}

fn bone(body: String, pos: [f32; 3], vertid: Vec<i32>, vertweight: Vec<f32>) -> Bone {
    Bone {
        body,
        bindpos: pos,
        bindquat: [1.0, 0.0, 0.0, 0.0],
        vertid,
        vertweight,
    }
}

/// Vertices, texture coordinates and faces of a two-sided `c0` x `c1` sheet; `pos` places
/// vertex (ix, iy).
fn sheet(sk: &mut Skin, texcoord: bool, c0: i32, c1: i32, pos: &dyn Fn(i32, i32) -> [f32; 3]) {
    let nn = c0 * c1;
    for side in 0..2 {
        let (a, b) = ((side == 0) as i32, (side == 1) as i32);
        for ix in 0..c0 {
            for iy in 0..c1 {
                sk.vert.extend_from_slice(&pos(ix, iy));
                if texcoord {
                    sk.texcoord.push(ix as f32 / (c0 - 1) as f32);
                    sk.texcoord.push(iy as f32 / (c1 - 1) as f32);
                }
                if ix < c0 - 1 && iy < c1 - 1 {
                    let o = side * nn;
                    sk.face.extend_from_slice(&[
                        o + ix * c1 + iy,
                        o + (ix + 1) * c1 + iy + b,
                        o + (ix + 1) * c1 + iy + a,
                        o + ix * c1 + iy,
                        o + (ix + a) * c1 + iy + 1,
                        o + (ix + b) * c1 + iy + 1,
                    ]);
                }
            }
        }
    }
    // thin edge triangles joining the two sides
    for ix in 0..c0 - 1 {
        let (v, w) = (ix * c1, (ix + 1) * c1);
        sk.face
            .extend_from_slice(&[v, nn + w, w, v, nn + v, nn + w]);
    }
    for ix in 0..c0 - 1 {
        let (v, w) = (ix * c1 + c1 - 1, (ix + 1) * c1 + c1 - 1);
        sk.face
            .extend_from_slice(&[v, w, nn + w, v, nn + w, nn + v]);
    }
    for iy in 0..c1 - 1 {
        sk.face
            .extend_from_slice(&[iy, iy + 1, nn + iy + 1, iy, nn + iy + 1, nn + iy]);
    }
    for iy in 0..c1 - 1 {
        let v = iy + (c0 - 1) * c1;
        sk.face
            .extend_from_slice(&[v, nn + v + 1, v + 1, v, nn + v, nn + v + 1]);
    }
}

/// Sheet skin with one vertex pair per body.
pub fn grid(c: &Composite, s: &CompSkin) -> Skin {
    let mut sk = new_skin(c, s);
    let [c0, c1, _] = c.count;
    sheet(&mut sk, s.texcoord, c0, c1, &|_, _| [0.0; 3]);
    let n = c0 * c1;
    for ix in 0..c0 {
        for iy in 0..c1 {
            let v = ix * c1 + iy;
            let name = format!("{}B{ix}_{iy}", c.prefix);
            sk.bones
                .push(bone(name, [0.0; 3], vec![v, n + v], vec![1.0, 1.0]));
        }
    }
    sk
}

/// Bicubic interpolation matrix: coefficients from the values and derivatives at the corners
/// (0,0), (1,0), (1,1), (0,1), in the order f, f_x, f_y, f_xy.
#[rustfmt::skip]
const BICUBIC: [f64; 256] = [
    1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0.,
    0., 0., 0., 0., 0., 0., 0., 0., 1., 0., 0., 0., 0., 0., 0., 0.,
    -3., 0., 0., 3., 0., 0., 0., 0., -2., 0., 0., -1., 0., 0., 0., 0.,
    2., 0., 0., -2., 0., 0., 0., 0., 1., 0., 0., 1., 0., 0., 0., 0.,
    0., 0., 0., 0., 1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0.,
    0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0., 1., 0., 0., 0.,
    0., 0., 0., 0., -3., 0., 0., 3., 0., 0., 0., 0., -2., 0., 0., -1.,
    0., 0., 0., 0., 2., 0., 0., -2., 0., 0., 0., 0., 1., 0., 0., 1.,
    -3., 3., 0., 0., -2., -1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0.,
    0., 0., 0., 0., 0., 0., 0., 0., -3., 3., 0., 0., -2., -1., 0., 0.,
    9., -9., 9., -9., 6., 3., -3., -6., 6., -6., -3., 3., 4., 2., 1., 2.,
    -6., 6., -6., 6., -4., -2., 2., 4., -3., 3., 3., -3., -2., -1., -1., -2.,
    2., -2., 0., 0., 1., 1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 0.,
    0., 0., 0., 0., 0., 0., 0., 0., 2., -2., 0., 0., 1., 1., 0., 0.,
    -6., 6., -6., 6., -3., -3., 3., 3., -4., 4., 2., -2., -2., -2., -1., -1.,
    4., -4., 4., -4., 2., 2., -2., -2., 2., -2., -2., 2., 1., 1., 1., 1.,
];

/// Finite-difference weights of a derivative at corner coordinate `k` (0 or 1) of a cell, over
/// the 4 neighbor coordinates -1..=2; `edge` is 0 at the low border, 2 at the high one.
fn stencil(k: usize, edge: usize) -> [f64; 4] {
    let mut w = [0.0; 4];
    let c = k + 1;
    if (edge == 0 && k == 0) || (edge == 2 && k == 1) {
        w[1] = -1.0;
        w[2] = 1.0;
    } else {
        w[c - 1] = -0.5;
        w[c + 1] = 0.5;
    }
    w
}

/// Matrix from the 16 neighbor values to the 16 corner quantities, for a cell at border case
/// (ex, ey).
fn differences(ex: usize, ey: usize) -> [f64; 256] {
    const CORNERS: [(usize, usize); 4] = [(0, 0), (1, 0), (1, 1), (0, 1)];
    let mut d = [0.0; 256];
    for (r, &(cx, cy)) in CORNERS.iter().enumerate() {
        let mut unit_x = [0.0; 4];
        unit_x[cx + 1] = 1.0;
        let mut unit_y = [0.0; 4];
        unit_y[cy + 1] = 1.0;
        let rows = [
            (unit_x, unit_y),
            (stencil(cx, ex), unit_y),
            (unit_x, stencil(cy, ey)),
            (stencil(cx, ex), stencil(cy, ey)),
        ];
        for (q, (wx, wy)) in rows.iter().enumerate() {
            for i in 0..4 {
                for j in 0..4 {
                    d[(4 * q + r) * 16 + 4 * i + j] = wx[i] * wy[j];
                }
            }
        }
    }
    d
}

/// Sheet skin refined by `subgrid` points between bodies, vertices bound to the 16 nearest
/// bodies with bicubic weights.
pub fn grid_subgrid(c: &Composite, s: &CompSkin) -> Result<Skin, String> {
    use crate::math::blas::mul_mat_mat;
    let sub = s.subgrid;
    let m = (2 + sub as i64) as usize;
    let np = m * m;
    let step = 1.0 / (1 + sub) as f64;
    // a huge subgrid fails to allocate, as 2.2.2's does
    let zeros = |n: usize| -> Result<Vec<f64>, String> {
        let mut v = Vec::new();
        v.try_reserve_exact(n)
            .map_err(|_| "Could not allocate memory".to_string())?;
        v.resize(n, 0.0);
        Ok(v)
    };
    let mut weight = zeros(9 * np * 16)?;
    let mut xy = zeros(np * 16)?;
    for sx in 0..m {
        for sy in 0..m {
            let (x, y) = (sx as f64 * step, sy as f64 * step);
            let row = &mut xy[16 * (sx * m + sy)..16 * (sx * m + sy + 1)];
            let px = [1.0, x, x * x, x * x * x];
            for i in 0..4 {
                for j in 0..4 {
                    // x^i y^j multiplied left to right, as the reference does
                    let mut v = px[i];
                    for _ in 0..j {
                        v *= y;
                    }
                    row[4 * i + j] = v;
                }
            }
        }
    }
    let mut xy_w = zeros(np * 16)?;
    mul_mat_mat(&mut xy_w, &xy, &BICUBIC, np, 16, 16);
    for ex in 0..3 {
        for ey in 0..3 {
            let d = differences(ex, ey);
            let k = ex * 3 + ey;
            mul_mat_mat(
                &mut weight[k * np * 16..(k + 1) * np * 16],
                &xy_w,
                &d,
                np,
                16,
                16,
            );
        }
    }

    let mut sk = new_skin(c, s);
    let [n0, n1, _] = c.count;
    let fine = c.spacing / (1 + sub) as f64;
    let c0 = n0 + (n0 - 1) * sub;
    let c1 = n1 + (n1 - 1) * sub;
    let nn = c0 * c1;
    sheet(&mut sk, s.texcoord, c0, c1, &|ix, iy| {
        [(ix as f64 * fine) as f32, (iy as f64 * fine) as f32, 0.0]
    });
    for ix in 0..n0 {
        for iy in 0..n1 {
            let name = format!("{}B{ix}_{iy}", c.prefix);
            let pos = [
                (ix as f64 * c.spacing) as f32,
                (iy as f64 * c.spacing) as f32,
                0.0,
            ];
            sk.bones.push(bone(name, pos, Vec::new(), Vec::new()));
        }
    }
    let edge = |i: i32, n: i32| {
        if i == 0 {
            0
        } else if i == n - 2 {
            2
        } else {
            1
        }
    };
    for ix in 0..n0 - 1 {
        for iy in 0..n1 - 1 {
            let k = 3 * edge(ix, n0) + edge(iy, n1);
            let mut boneid = [0i32; 16];
            for dx in -1..3 {
                for dy in -1..3 {
                    boneid[((dx + 1) * 4 + dy + 1) as usize] = (ix + dx) * n1 + iy + dy;
                }
            }
            let last_x = (ix == n0 - 2) as i32;
            let last_y = (iy == n1 - 2) as i32;
            for dx in 0..1 + sub + last_x {
                for dy in 0..1 + sub + last_y {
                    let vid = (ix * (1 + sub) + dx) * c1 + iy * (1 + sub) + dy;
                    let row = (dx * (2 + sub) + dy) as usize;
                    for (bi, &b) in boneid.iter().enumerate() {
                        let w = weight[k * np * 16 + row * 16 + bi];
                        if w != 0.0 {
                            let bone = &mut sk.bones[b as usize];
                            bone.vertid.extend_from_slice(&[vid, vid + nn]);
                            bone.vertweight.extend_from_slice(&[w as f32, w as f32]);
                        }
                    }
                }
            }
        }
    }
    Ok(sk)
}

/// One face of a box skin: its own vertices, one bone per body.
fn box_face(
    sk: &mut Skin,
    texcoord: bool,
    c0: i32,
    c1: i32,
    side: i32,
    vcnt: &mut i32,
    name: &dyn Fn(i32, i32) -> String,
) {
    let v0 = *vcnt;
    let (a, b) = ((side == 0) as i32, (side == 1) as i32);
    for i0 in 0..c0 {
        for i1 in 0..c1 {
            sk.vert.extend_from_slice(&[0.0; 3]);
            if texcoord {
                sk.texcoord.push(i0 as f32 / (c0 - 1) as f32);
                sk.texcoord.push(i1 as f32 / (c1 - 1) as f32);
            }
            if i0 < c0 - 1 && i1 < c1 - 1 {
                sk.face.extend_from_slice(&[
                    v0 + i0 * c1 + i1,
                    v0 + (i0 + 1) * c1 + i1 + b,
                    v0 + (i0 + 1) * c1 + i1 + a,
                    v0 + i0 * c1 + i1,
                    v0 + (i0 + a) * c1 + i1 + 1,
                    v0 + (i0 + b) * c1 + i1 + 1,
                ]);
            }
            sk.bones.push(bone(
                name(i0, i1),
                [0.0; 3],
                vec![v0 + i0 * c1 + i1],
                vec![1.0],
            ));
        }
    }
    *vcnt += c0 * c1;
}

/// One face of a smooth skin: shared vertices looked up by body name.
fn smooth_face(
    sk: &mut Skin,
    c0: i32,
    c1: i32,
    side: i32,
    vmap: &HashMap<String, i32>,
    name: &dyn Fn(i32, i32) -> String,
) {
    let v = |a: i32, b: i32| vmap.get(&name(a, b)).copied().unwrap_or(0);
    for i0 in 0..c0 {
        for i1 in 0..c1 {
            if i0 < c0 - 1 && i1 < c1 - 1 {
                let (v00, v01, v10, v11) =
                    (v(i0, i1), v(i0, i1 + 1), v(i0 + 1, i1), v(i0 + 1, i1 + 1));
                if side == 0 {
                    sk.face.extend_from_slice(&[v00, v10, v11, v00, v11, v01]);
                } else {
                    sk.face.extend_from_slice(&[v00, v01, v11, v00, v11, v10]);
                }
            }
            sk.bones
                .push(bone(name(i0, i1), [0.0; 3], vec![v(i0, i1)], vec![1.0]));
        }
    }
}

/// Closed skin of a box, cylinder or ellipsoid composite.
pub fn solid(c: &Composite, s: &CompSkin) -> Skin {
    let mut sk = new_skin(c, s);
    let p = c.prefix.as_str();
    let [n0, n1, n2] = c.count;
    let (l0, l1, l2) = (n0 - 1, n1 - 1, n2 - 1);
    let tex = s.texcoord;
    let mut vcnt = 0;
    let kind = super::composite::TYPES[c.kind];
    if kind == "box" {
        box_face(&mut sk, tex, n0, n1, 1, &mut vcnt, &|a, b| {
            format!("{p}B{a}_{b}_0")
        });
        box_face(&mut sk, tex, n0, n1, 0, &mut vcnt, &|a, b| {
            format!("{p}B{a}_{b}_{l2}")
        });
        box_face(&mut sk, tex, n0, n2, 0, &mut vcnt, &|a, b| {
            format!("{p}B{a}_0_{b}")
        });
        box_face(&mut sk, tex, n0, n2, 1, &mut vcnt, &|a, b| {
            format!("{p}B{a}_{l1}_{b}")
        });
        box_face(&mut sk, tex, n1, n2, 1, &mut vcnt, &|a, b| {
            format!("{p}B0_{a}_{b}")
        });
        box_face(&mut sk, tex, n1, n2, 0, &mut vcnt, &|a, b| {
            format!("{p}B{l0}_{a}_{b}")
        });
        return sk;
    }
    let cyl = kind == "cylinder";
    let mut vmap = HashMap::new();
    for ix in 0..n0 {
        for iy in 0..n1 {
            for iz in 0..n2 {
                let xedge = ix == 0 || ix == l0;
                let yedge = iy == 0 || iy == l1;
                let zedge = iz == 0 || iz == l2;
                if !(xedge || yedge || (!cyl && zedge)) {
                    continue;
                }
                sk.vert.extend_from_slice(&[0.0; 3]);
                if tex {
                    let (x, y) = if xedge {
                        (iy as f32 / l1 as f32, iz as f32 / l2 as f32)
                    } else if yedge || cyl {
                        (ix as f32 / l0 as f32, iz as f32 / l2 as f32)
                    } else {
                        (ix as f32 / l0 as f32, iy as f32 / l1 as f32)
                    };
                    sk.texcoord.extend_from_slice(&[x, y]);
                }
                vmap.insert(format!("{p}B{ix}_{iy}_{iz}"), vcnt);
                vcnt += 1;
            }
        }
    }
    if !cyl {
        smooth_face(&mut sk, n0, n1, 1, &vmap, &|a, b| format!("{p}B{a}_{b}_0"));
        smooth_face(&mut sk, n0, n1, 0, &vmap, &|a, b| {
            format!("{p}B{a}_{b}_{l2}")
        });
    }
    smooth_face(&mut sk, n0, n2, 0, &vmap, &|a, b| format!("{p}B{a}_0_{b}"));
    smooth_face(&mut sk, n0, n2, 1, &vmap, &|a, b| {
        format!("{p}B{a}_{l1}_{b}")
    });
    smooth_face(&mut sk, n1, n2, 1, &vmap, &|a, b| format!("{p}B0_{a}_{b}"));
    smooth_face(&mut sk, n1, n2, 0, &vmap, &|a, b| {
        format!("{p}B{l0}_{a}_{b}")
    });
    if cyl {
        box_face(&mut sk, tex, n0, n1, 1, &mut vcnt, &|a, b| {
            format!("{p}B{a}_{b}_0")
        });
        box_face(&mut sk, tex, n0, n1, 0, &mut vcnt, &|a, b| {
            format!("{p}B{a}_{b}_{l2}")
        });
    }
    sk
}
