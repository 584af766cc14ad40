//! Skin vertices and normals in the scene (mjv_updateActiveSkin): each vertex blended from
//! its bones' current poses relative to their bind poses, normals from the area-weighted
//! face normals, then inflated along them.

use crate::abi::*;
use crate::engine::linalg::row;
use crate::engine::{Data, Model, MINVAL};
use crate::math::quat::{mul_quat, neg_quat, quat2mat};
use crate::math::vec3::{add3, cross, mul_mat_vec3, sub3};
use crate::math::{Quat, Vec3};

/// Updates the skins whose group `opt` shows; hidden skins get zero vertices and normals.
pub fn update_skins(m: &Model, d: &Data, vert: &mut [f32], normal: &mut [f32], opt: &mjvOption) {
    for i in 0..m.raw.nskin as usize {
        let vertadr = m.skin_vertadr()[i] as usize;
        let vertnum = m.skin_vertnum()[i] as usize;
        let verts = 3 * vertadr..3 * (vertadr + vertnum);
        vert[verts.clone()].fill(0.0);
        normal[verts.clone()].fill(0.0);
        if opt.skingroup[m.skin_group()[i] as usize] == 0 {
            continue;
        }
        let vert = &mut vert[verts.clone()];
        let normal = &mut normal[verts];
        blend_bones(m, d, i, vertadr, vert);
        let faceadr = m.skin_faceadr()[i] as usize;
        for k in faceadr..faceadr + m.skin_facenum()[i] as usize {
            let v = [0, 1, 2].map(|r| m.skin_face()[3 * k + r] as usize);
            let at = |id: usize, r: usize| vert[3 * id + r];
            let e01: Vec3 = std::array::from_fn(|r| (at(v[1], r) - at(v[0], r)) as f64);
            let e02: Vec3 = std::array::from_fn(|r| (at(v[2], r) - at(v[0], r)) as f64);
            let nrm = cross(&e01, &e02);
            for id in v {
                for t in 0..3 {
                    let n = &mut normal[3 * id + t];
                    *n = (*n as f64 + nrm[t]) as f32;
                }
            }
        }
        for n in normal.chunks_exact_mut(3) {
            let s = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let scl = (1.0 / if MINVAL > s as f64 { MINVAL } else { s as f64 }) as f32;
            n.iter_mut().for_each(|x| *x *= scl);
        }
        let inflate = m.skin_inflate()[i];
        if inflate != 0.0 {
            for (p, n) in vert.chunks_exact_mut(3).zip(normal.chunks_exact(3)) {
                for r in 0..3 {
                    p[r] += inflate * n[r];
                }
            }
        }
    }
}

/// Vertex positions of skin `i` (`vert` from its first vertex): the weighted sum over its
/// bones of each bone's motion from bind pose applied to the vertex.
fn blend_bones(m: &Model, d: &Data, i: usize, vertadr: usize, vert: &mut [f32]) {
    let boneadr = m.skin_boneadr()[i] as usize;
    for j in boneadr..boneadr + m.skin_bonenum()[i] as usize {
        let bindpos: Vec3 = std::array::from_fn(|k| m.skin_bonebindpos()[3 * j + k] as f64);
        let bindquat: Quat = std::array::from_fn(|k| m.skin_bonebindquat()[4 * j + k] as f64);
        let body = m.skin_bonebodyid()[j] as usize;
        let quat = mul_quat(&row(d.xquat, body), &neg_quat(&bindquat));
        let rotate = quat2mat(&quat);
        let translate = sub3(&row(d.xpos, body), &mul_mat_vec3(&rotate, &bindpos));
        let adr = m.skin_bonevertadr()[j] as usize;
        for k in adr..adr + m.skin_bonevertnum()[j] as usize {
            let vid = m.skin_bonevertid()[k] as usize;
            let weight = m.skin_bonevertweight()[k];
            let v = &m.skin_vert()[3 * (vertadr + vid)..];
            let pos: Vec3 = std::array::from_fn(|r| v[r] as f64);
            let moved = add3(&mul_mat_vec3(&rotate, &pos), &translate);
            for r in 0..3 {
                vert[3 * vid + r] += weight * moved[r] as f32;
            }
        }
    }
}
