//! Skins: file loading (SKN), checks, weight normalization, and their mjModel arrays.

use super::spec::{Bone, Skin};
use super::CError;
use crate::abi::mjModel;
use crate::abi::view::ModelMut;

const MINVAL: f64 = 1e-15;

/// A skin ready for the model: material and bodies resolved, weights normalized.
pub struct CSkin {
    pub name: String,
    matid: i32,
    rgba: [f32; 4],
    group: i32,
    inflate: f32,
    vert: Vec<f32>,
    texcoord: Vec<f32>,
    face: Vec<i32>,
    bones: Vec<Bone>,
    bodyid: Vec<i32>,
}

/// Name a skin gets from its file when it has none.
pub fn default_name(s: &Skin) -> String {
    if !s.name.is_empty() {
        return s.name.clone();
    }
    let base = s.file.rsplit(['/', '\\']).next().unwrap_or("");
    match base.rfind('.') {
        Some(k) => base[..k].to_string(),
        None => base.to_string(),
    }
}

fn i32_at(b: &[u8], k: usize) -> i32 {
    i32::from_le_bytes([b[4 * k], b[4 * k + 1], b[4 * k + 2], b[4 * k + 3]])
}

fn f32_at(b: &[u8], k: usize) -> f32 {
    f32::from_bits(i32_at(b, k) as u32)
}

/// Reads an SKN file into the skin.
fn load_skn(s: &mut Skin) -> Result<(), String> {
    let file = s.path.clone();
    let b = match &s.bytes {
        None => return Err(format!("could not open SKN file '{file}'")),
        Some(b) if b.is_empty() => return Err(format!("SKN file '{file}' is empty")),
        Some(b) => b.clone(),
    };
    if b.len() < 16 {
        return Err(format!("missing header in SKN file '{file}'"));
    }
    let (nvert, ntex, nface, nbone) = (i32_at(&b, 0), i32_at(&b, 1), i32_at(&b, 2), i32_at(&b, 3));
    if nvert < 0 || ntex < 0 || nface < 0 || nbone < 0 {
        return Err(format!("negative size in header of SKN file '{file}'"));
    }
    let need = 16i64 + 12 * nvert as i64 + 8 * ntex as i64 + 12 * nface as i64;
    if (b.len() as i64) < need {
        return Err(format!("insufficient data in SKN file '{file}'"));
    }
    let words = (b.len() / 4) as i64;
    let mut k = 4usize;
    s.vert = (0..3 * nvert as usize).map(|i| f32_at(&b, k + i)).collect();
    k += 3 * nvert as usize;
    s.texcoord = (0..2 * ntex as usize).map(|i| f32_at(&b, k + i)).collect();
    k += 2 * ntex as usize;
    s.face = (0..3 * nface as usize).map(|i| i32_at(&b, k + i)).collect();
    k += 3 * nface as usize;
    s.bones.clear();
    for i in 0..nbone {
        if words - (k as i64) < 18 {
            return Err(format!("insufficient data in SKN file '{file}', bone {i}"));
        }
        let raw = &b[4 * k..4 * k + 40];
        let end = raw.iter().take(39).position(|&c| c == 0).unwrap_or(39);
        let mut bone = Bone {
            body: String::from_utf8_lossy(&raw[..end]).into_owned(),
            ..Bone::default()
        };
        k += 10;
        for j in 0..3 {
            bone.bindpos[j] = f32_at(&b, k + j);
        }
        k += 3;
        for j in 0..4 {
            bone.bindquat[j] = f32_at(&b, k + j);
        }
        k += 4;
        let vcount = i32_at(&b, k);
        k += 1;
        if vcount < 1 {
            return Err(format!(
                "vertex count must be positive in SKN file '{file}', bone {i}"
            ));
        }
        if words - (k as i64) < 2 * vcount as i64 {
            return Err(format!(
                "insufficient vertex data in SKN file '{file}', bone {i}"
            ));
        }
        let n = vcount as usize;
        bone.vertid = (0..n).map(|j| i32_at(&b, k + j)).collect();
        k += n;
        bone.vertweight = (0..n).map(|j| f32_at(&b, k + j)).collect();
        k += n;
        s.bones.push(bone);
    }
    if b.len() != 4 * k {
        return Err(format!("unexpected buffer size in SKN file '{file}'"));
    }
    Ok(())
}

/// Compiles every skin; `body` finds a body id by name, `matid` a material id.
pub fn compile(
    skins: Vec<Skin>,
    body: &dyn Fn(&str) -> Option<usize>,
    matid: &dyn Fn(&str) -> Option<usize>,
) -> Result<Vec<CSkin>, CError> {
    let mut out = Vec::with_capacity(skins.len());
    for (id, s) in skins.into_iter().enumerate() {
        let name = default_name(&s);
        let line = s.line;
        let err = |m: String| CError::at(m, &name, id, line);
        let mat = if s.material.is_empty() {
            -1
        } else {
            match matid(&s.material) {
                Some(m) => m as i32,
                None => {
                    return Err(err(format!(
                        "material '{}' not found in skin {id}",
                        s.material
                    )))
                }
            }
        };
        out.push((s, name, mat, line));
    }
    let mut res = Vec::with_capacity(out.len());
    for (id, (mut s, name, mat, line)) in out.into_iter().enumerate() {
        let err = |m: String| CError::at(m, &name, id, line);
        if !s.file.is_empty() {
            if !s.vert.is_empty()
                || !s.texcoord.is_empty()
                || !s.face.is_empty()
                || !s.bones.is_empty()
            {
                return Err(err(format!(
                    "Data already exists, trying to load from skin file: {}",
                    s.file
                )));
            }
            let f = &s.file;
            let ext = if f.len() >= 3 {
                &f[f.len() - 3..]
            } else {
                f.as_str()
            };
            if !ext.eq_ignore_ascii_case("skn") {
                return Err(err(format!("Unknown skin file type: {f}")));
            }
            load_skn(&mut s).map_err(err)?;
        }
        if s.vert.is_empty() || s.face.is_empty() || s.bones.is_empty() {
            return Err(err("Missing data in skin".into()));
        }
        if s.vert.len() % 3 != 0 {
            return Err(err("Vertex data must be multiple of 3".into()));
        }
        if !s.texcoord.is_empty() && s.texcoord.len() != 2 * s.vert.len() / 3 {
            return Err(err("Vertex and texcoord data incompatible size".into()));
        }
        if s.face.len() % 3 != 0 {
            return Err(err("Face data must be multiple of 3".into()));
        }
        let mut bodyid = Vec::with_capacity(s.bones.len());
        for b in &s.bones {
            match body(&b.body) {
                Some(i) => bodyid.push(i as i32),
                None => return Err(err(format!("unknown body '{}' in skin", b.body))),
            }
        }
        let nvert = s.vert.len() / 3;
        let mut total = vec![0.0f32; nvert];
        for b in &s.bones {
            if b.vertweight.len() != b.vertid.len() || b.vertid.is_empty() {
                return Err(err(
                    "vertid and vertweight must have same non-zero size in skin".into(),
                ));
            }
            for (&v, &w) in b.vertid.iter().zip(&b.vertweight) {
                if v < 0 || v as usize >= nvert {
                    return Err(err(format!("vertid {v} out of range in skin")));
                }
                total[v as usize] += w;
            }
        }
        if let Some(i) = total.iter().position(|&w| w as f64 <= MINVAL) {
            return Err(err(format!(
                "vertex {i} must have positive total weight in skin"
            )));
        }
        for b in s.bones.iter_mut() {
            for (v, w) in b.vertid.iter().zip(b.vertweight.iter_mut()) {
                *w /= total[*v as usize];
            }
            let q = b.bindquat.map(|x| x as f64);
            let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
            let q = if n < MINVAL {
                [1.0, 0.0, 0.0, 0.0]
            } else {
                q.map(|x| x / n)
            };
            b.bindquat = q.map(|x| x as f32);
        }
        res.push(CSkin {
            name,
            matid: mat,
            rgba: s.rgba,
            group: s.group,
            inflate: s.inflate,
            vert: s.vert,
            texcoord: s.texcoord,
            face: s.face,
            bones: s.bones,
            bodyid,
        });
    }
    Ok(res)
}

/// Sets the skin sizes of the model header.
pub fn sizes(skins: &[CSkin], h: &mut mjModel) {
    h.nskin = skins.len() as i32;
    h.nskinvert = skins.iter().map(|s| s.vert.len() / 3).sum::<usize>() as i32;
    h.nskintexvert = skins.iter().map(|s| s.texcoord.len() / 2).sum::<usize>() as i32;
    h.nskinface = skins.iter().map(|s| s.face.len() / 3).sum::<usize>() as i32;
    h.nskinbone = skins.iter().map(|s| s.bones.len()).sum::<usize>() as i32;
    h.nskinbonevert = skins
        .iter()
        .flat_map(|s| s.bones.iter().map(|b| b.vertid.len()))
        .sum::<usize>() as i32;
}

/// Writes the skin arrays.
pub fn fill(skins: &[CSkin], m: &mut ModelMut) {
    let (mut vert, mut tex, mut face, mut bone, mut bvert) =
        (0usize, 0usize, 0usize, 0usize, 0usize);
    for (i, s) in skins.iter().enumerate() {
        m.skin_matid[i] = s.matid;
        m.skin_rgba[4 * i..4 * i + 4].copy_from_slice(&s.rgba);
        m.skin_group[i] = s.group;
        m.skin_inflate[i] = s.inflate;
        m.skin_vertadr[i] = vert as i32;
        m.skin_vertnum[i] = (s.vert.len() / 3) as i32;
        m.skin_texcoordadr[i] = if s.texcoord.is_empty() {
            -1
        } else {
            tex as i32
        };
        m.skin_faceadr[i] = face as i32;
        m.skin_facenum[i] = (s.face.len() / 3) as i32;
        m.skin_boneadr[i] = bone as i32;
        m.skin_bonenum[i] = s.bones.len() as i32;
        m.skin_vert[3 * vert..3 * vert + s.vert.len()].copy_from_slice(&s.vert);
        m.skin_texcoord[2 * tex..2 * tex + s.texcoord.len()].copy_from_slice(&s.texcoord);
        m.skin_face[3 * face..3 * face + s.face.len()].copy_from_slice(&s.face);
        for (j, b) in s.bones.iter().enumerate() {
            let k = bone + j;
            m.skin_bonebindpos[3 * k..3 * k + 3].copy_from_slice(&b.bindpos);
            m.skin_bonebindquat[4 * k..4 * k + 4].copy_from_slice(&b.bindquat);
            m.skin_bonebodyid[k] = s.bodyid[j];
            m.skin_bonevertadr[k] = bvert as i32;
            m.skin_bonevertnum[k] = b.vertid.len() as i32;
            let n = b.vertid.len();
            m.skin_bonevertid[bvert..bvert + n].copy_from_slice(&b.vertid);
            m.skin_bonevertweight[bvert..bvert + n].copy_from_slice(&b.vertweight);
            bvert += n;
        }
        vert += s.vert.len() / 3;
        tex += s.texcoord.len() / 2;
        face += s.face.len() / 3;
        bone += s.bones.len();
    }
}
