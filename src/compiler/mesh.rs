//! Mesh assets: STL, OBJ and MSH files or inline data, vertex normals, the convex-hull graph,
//! and the volume and shell inertial frames that mesh geoms take, all as 2.2.2 computes them
//! (float vertex arithmetic where the reference uses floats).

use super::spec::Mesh as MeshSpec;
use crate::math::quat::{normalize4, quat2mat as engine_quat2mat};
use crate::math::vec3::mul_mat_t_vec3;

const MINVAL: f64 = 1e-15;

/// Inertia kinds (mjtMeshType): the solid, or a thin shell over the surface.
pub const VOLUME: usize = 0;
pub const SHELL: usize = 1;

/// A compiled mesh.
#[derive(Debug, Clone, Default)]
pub struct Mesh {
    pub name: String,
    pub line: i32,
    pub vert: Vec<f32>,
    pub normal: Vec<f32>,
    /// empty: none
    pub texcoord: Vec<f32>,
    pub face: Vec<i32>,
    /// empty: none
    pub graph: Vec<i32>,
    /// per inertia kind: centre, principal frame, equivalent box half-sizes, volume (or area)
    pub pos: [[f64; 3]; 2],
    pub quat: [[f64; 4]; 2],
    pub boxsz: [[f64; 3]; 2],
    pub volume: [f64; 2],
    pub aabb: [f64; 3],
    /// the first validity problem Process found, reported when inertia is asked for
    pub invalid: Option<&'static str>,
}

impl Mesh {
    fn check(&self) -> Result<(), String> {
        match self.invalid {
            Some(what) => Err(format!("{what}: {}", self.name)),
            None => Ok(()),
        }
    }
    /// Volume (or area) of the given kind; errors for an invalid mesh.
    pub fn volume(&self, kind: usize) -> Result<f64, String> {
        self.check()?;
        Ok(self.volume[kind])
    }
    /// Half-sizes of the equivalent inertia box; errors for an invalid mesh.
    pub fn inertia_box(&self, kind: usize) -> Result<[f64; 3], String> {
        self.check()?;
        Ok(self.boxsz[kind])
    }
}

/// Compiler settings meshes depend on.
pub struct MeshOpts {
    pub convexhull: bool,
    pub exactmeshinertia: bool,
}

/// Data read from a file or given inline, before processing.
#[derive(Default)]
struct Raw {
    vert: Option<Vec<f32>>,
    normal: Option<Vec<f32>>,
    texcoord: Option<Vec<f32>>,
    face: Option<Vec<i32>>,
    edges: Vec<(i32, i32)>,
}

fn i32_at(b: &[u8], i: usize) -> i32 {
    i32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]])
}

fn f32_at(b: &[u8], i: usize) -> f32 {
    f32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]])
}

fn righthanded(spec: &MeshSpec) -> bool {
    spec.scale[0] * spec.scale[1] * spec.scale[2] > 0.0
}

/// Binary STL, with repeated vertices merged.
fn load_stl(spec: &MeshSpec, file: &str, raw: &mut Raw) -> Result<(), String> {
    let b = spec
        .bytes
        .as_deref()
        .ok_or_else(|| format!("could not open STL file '{file}'"))?;
    if b.is_empty() {
        return Err(format!("STL file '{file}' is empty"));
    }
    if b.len() < 84 {
        return Err(format!("invalid header in STL file '{file}'"));
    }
    let nface = i32_at(b, 80);
    if !(1..=200000).contains(&nface) {
        return Err(format!(
            "number of faces should be between 1 and 200000 in STL file '{file}'; perhaps this is an ASCII file?"
        ));
    }
    let nface = nface as usize;
    if nface * 50 != b.len() - 84 {
        return Err(format!(
            "STL file '{file}' has wrong size; perhaps this is an ASCII file?"
        ));
    }
    let right = righthanded(spec);
    let mut vert = Vec::with_capacity(9 * nface);
    let mut face = vec![0i32; 3 * nface];
    for i in 0..nface {
        for j in 0..3 {
            let at = 84 + 50 * i + 12 * (j + 1);
            let v = [f32_at(b, at), f32_at(b, at + 4), f32_at(b, at + 8)];
            for x in v {
                if !x.is_finite() {
                    return Err(format!("STL file '{file}' contains invalid vertices."));
                }
                if (x as f64).abs() > (1u64 << 30) as f64 {
                    return Err(format!(
                        "vertex coordinates in STL file '{file}' exceed maximum bounds"
                    ));
                }
            }
            let id = (vert.len() / 3) as i32;
            if right || j == 0 {
                face[3 * i + j] = id;
            } else {
                face[3 * i + 3 - j] = id;
            }
            vert.extend_from_slice(&v);
        }
    }
    remove_repeated(&mut vert, &mut face);
    raw.vert = Some(vert);
    raw.face = Some(face);
    Ok(())
}

/// Merges bit-identical vertices, keeping the first of each run in 2.2.2's sort order.
fn remove_repeated(vert: &mut Vec<f32>, face: &mut [i32]) {
    let n = vert.len() / 3;
    let key: Vec<f32> = vert
        .chunks_exact(3)
        .map(|v| (v[0] as f64 + 1e-2 * v[1] as f64 + 1e-4 * v[2] as f64) as f32)
        .collect();
    let mut index: Vec<usize> = (0..n).collect();
    // glibc's qsort is a stable merge sort here
    index.sort_by(|&a, &b| {
        key[a]
            .partial_cmp(&key[b])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    drop(key);
    let mut redirect: Vec<usize> = (0..n).collect();
    let mut repeated = 0;
    for i in 1..n {
        let (a, b) = (index[i], index[i - 1]);
        if vert[3 * a..3 * a + 3] == vert[3 * b..3 * b + 3] {
            redirect[a] = b;
            repeated += 1;
        }
    }
    if repeated == 0 {
        return;
    }
    for i in 0..n {
        let mut j = i;
        while redirect[j] != j {
            j = redirect[j];
        }
        redirect[i] = j;
    }
    let mut newid = vec![-1i32; n];
    let mut j = 0;
    for i in 0..n {
        if redirect[i] == i {
            newid[i] = j as i32;
            vert.copy_within(3 * i..3 * i + 3, 3 * j);
            j += 1;
        }
    }
    vert.truncate(3 * j);
    for f in face.iter_mut() {
        *f = newid[redirect[*f as usize]];
    }
}

/// OBJ: every triangle corner becomes its own vertex, as 2.2.2 copies them.
fn load_obj(spec: &MeshSpec, file: &str, raw: &mut Raw) -> Result<(), String> {
    let parse_err = |e: String| format!("could not parse OBJ file '{file}': \n{e}");
    let b = spec
        .bytes
        .as_deref()
        .ok_or_else(|| parse_err(format!("Cannot open file [{file}]\n")))?;
    let o = super::obj::read(b).map_err(parse_err)?;
    if !o.has_shape {
        raw.vert = Some(o.vertices).filter(|v| !v.is_empty());
        raw.normal = Some(o.normals).filter(|v| !v.is_empty());
        raw.texcoord = Some(o.texcoords).filter(|v| !v.is_empty());
        return Ok(());
    }
    let right = righthanded(spec);
    let (has_n, has_t) = (!o.normals.is_empty(), !o.texcoords.is_empty());
    let (mut vert, mut normal, mut texcoord, mut face) = (vec![], vec![], vec![], vec![]);
    // an index out of range reads past the arrays in 2.2.2 (it still loads): zeros here
    let get = |a: &[f32], i: i32, k: usize| -> Vec<f32> {
        usize::try_from(i)
            .ok()
            .and_then(|i| a.get(i * k..i * k + k))
            .map_or(vec![0.0; k], <[f32]>::to_vec)
    };
    for t in &o.triangles {
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            raw.edges.push((t[a].v, t[b].v));
        }
        let first = (vert.len() / 3) as i32;
        for c in t {
            vert.extend(get(&o.vertices, c.v, 3));
            if has_n {
                normal.extend(get(&o.normals, c.vn, 3));
            }
            if has_t {
                let uv = get(&o.texcoords, c.vt, 2);
                texcoord.extend([uv[0], 1.0 - uv[1]]);
            }
        }
        if right {
            face.extend_from_slice(&[first, first + 1, first + 2]);
        } else {
            face.extend_from_slice(&[first, first + 2, first + 1]);
        }
    }
    raw.vert = Some(vert).filter(|v| !v.is_empty());
    raw.normal = Some(normal).filter(|v| !v.is_empty());
    raw.texcoord = Some(texcoord).filter(|v| !v.is_empty());
    raw.face = Some(face).filter(|v| !v.is_empty());
    Ok(())
}

/// MuJoCo's binary MSH: sizes, vertices, normals, texcoords, faces.
fn load_msh(spec: &MeshSpec, file: &str, raw: &mut Raw) -> Result<(), String> {
    let b = spec
        .bytes
        .as_deref()
        .ok_or_else(|| format!("could not open MSH file '{file}'"))?;
    if b.is_empty() {
        return Err(format!("MSH file '{file}' is empty"));
    }
    if b.len() < 16 {
        return Err(format!("missing header in MSH file '{file}'"));
    }
    let [nvert, nnormal, ntex, nface] = [0, 4, 8, 12].map(|i| i32_at(b, i));
    if nvert < 4
        || nface < 0
        || nnormal < 0
        || ntex < 0
        || (nnormal > 0 && nnormal != nvert)
        || (ntex > 0 && ntex != nvert)
    {
        return Err(format!("invalid sizes in MSH file '{file}'"));
    }
    let [nv, nn, nt, nf] = [nvert, nnormal, ntex, nface].map(|x| x as usize);
    if b.len() != 16 + 12 * nv + 12 * nn + 8 * nt + 12 * nf {
        return Err(format!("unexpected file size in MSH file '{file}'"));
    }
    let floats = |at: usize, n: usize| (0..n).map(|k| f32_at(b, at + 4 * k)).collect::<Vec<_>>();
    let mut at = 16;
    raw.vert = Some(floats(at, 3 * nv));
    at += 12 * nv;
    if nn > 0 {
        raw.normal = Some(floats(at, 3 * nv));
        at += 12 * nv;
    }
    if nt > 0 {
        raw.texcoord = Some(floats(at, 2 * nv));
        at += 8 * nv;
    }
    if nf > 0 {
        let mut face: Vec<i32> = (0..3 * nf).map(|k| i32_at(b, at + 4 * k)).collect();
        if !righthanded(spec) {
            for f in face.chunks_mut(3) {
                f.swap(1, 2);
            }
        }
        raw.face = Some(face);
    }
    Ok(())
}

/// Compiles a mesh; `needhull`: a colliding mesh geom uses it.
pub fn compile(spec: &MeshSpec, opts: &MeshOpts, needhull: bool) -> Result<Mesh, String> {
    let mut raw = Raw::default();
    if !spec.file.is_empty() {
        let file = spec.file.as_str();
        let ext = file
            .len()
            .checked_sub(3)
            .and_then(|i| file.get(i..))
            .unwrap_or("");
        match ext.to_ascii_lowercase().as_str() {
            "stl" => load_stl(spec, file, &mut raw)?,
            "obj" => load_obj(spec, file, &mut raw)?,
            "msh" => load_msh(spec, file, &mut raw)?,
            _ => return Err(format!("Unknown mesh file type: {}", spec.short_file)),
        }
    }
    if !spec.vertex.is_empty() {
        if raw.vert.is_some() {
            return Err("repeated vertex specification".into());
        }
        if spec.vertex.len() < 12 {
            return Err("at least 4 verices required".into());
        }
        if !spec.vertex.len().is_multiple_of(3) {
            return Err("vertex data must be a multiple of 3".into());
        }
        raw.vert = Some(spec.vertex.clone());
    }
    let nvert = raw.vert.as_ref().map_or(0, |v| v.len() / 3);
    if !spec.normal.is_empty() {
        if raw.normal.is_some() {
            return Err("repeated normal specification".into());
        }
        if spec.normal.len() != 3 * nvert {
            return Err("vertex and normal data incompatible size".into());
        }
        raw.normal = Some(spec.normal.clone());
    }
    if !spec.texcoord.is_empty() {
        if raw.texcoord.is_some() {
            return Err("repeated texcoord specification".into());
        }
        if spec.texcoord.len() != 2 * nvert {
            return Err("vertex and texcoord data incompatible size".into());
        }
        raw.texcoord = Some(spec.texcoord.clone());
    }
    if !spec.face.is_empty() {
        if raw.face.is_some() {
            return Err("repeated face specification".into());
        }
        if !spec.face.len().is_multiple_of(3) {
            return Err("face data must be a multiple of 3".into());
        }
        raw.face = Some(spec.face.clone());
        if raw.edges.is_empty() {
            for f in spec.face.chunks(3) {
                raw.edges.extend([(f[0], f[1]), (f[1], f[2]), (f[2], f[0])]);
            }
        }
    }
    raw.edges.sort_unstable();
    let orientation_ok = raw.edges.windows(2).all(|w| w[0] != w[1]);

    let Some(vert) = raw.vert else {
        return Err("no vertices".into());
    };
    let mut m = Mesh {
        name: spec.name.clone(),
        line: spec.line,
        vert,
        quat: [[1.0, 0.0, 0.0, 0.0]; 2],
        ..Mesh::default()
    };
    if (opts.convexhull && needhull) || raw.face.is_none() {
        m.graph = match super::hull::graph(&m.vert) {
            Ok(g) => g.unwrap_or_default(),
            Err(super::hull::GraphError::Qhull) => return Err("qhull error".into()),
            Err(super::hull::GraphError::Fatal(e)) => return Err(e.into()),
        };
    }
    m.face = match raw.face {
        Some(f) => f,
        None => {
            if m.graph.is_empty() {
                return Err("no faces and no convex hull".into());
            }
            let (nv, nf) = (m.graph[0] as usize, m.graph[1] as usize);
            let start = 2 + 3 * nv + 3 * nf;
            m.graph[start..start + 3 * nf].to_vec()
        }
    };
    m.texcoord = raw.texcoord.unwrap_or_default();
    m.normal = match raw.normal {
        Some(n) => n,
        None => normals(&m.vert, &m.face, spec.smoothnormal)?,
    };
    if !orientation_ok {
        m.invalid = Some("faces have inconsistent orientation");
    }
    process(&mut m, spec, opts)?;
    Ok(m)
}

fn vertex(vert: &[f32], face: &[i32], k: usize) -> Result<[f32; 3], String> {
    let i = face[k];
    if i < 0 || 3 * i as usize + 2 >= vert.len() {
        return Err(format!(
            "vertex index out of range in face {} of the mesh",
            k / 3
        ));
    }
    let i = 3 * i as usize;
    Ok([vert[i], vert[i + 1], vert[i + 2]])
}

/// mju_normalize3: the norm; (1,0,0) below MINVAL.
fn normalize3(v: &mut [f64; 3]) -> f64 {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if n < MINVAL {
        *v = [1.0, 0.0, 0.0];
    } else if (n - 1.0).abs() > MINVAL {
        let inv = 1.0 / n;
        v.iter_mut().for_each(|x| *x *= inv);
    }
    n
}

/// Area-weighted vertex normals; without `smooth`, faces at large angles are taken out again.
fn normals(vert: &[f32], face: &[i32], smooth: bool) -> Result<Vec<f32>, String> {
    let nf = face.len() / 3;
    let mut normal = vec![0f32; vert.len()];
    let face_normal = |i: usize| -> Result<([f64; 3], f64), String> {
        let v0 = vertex(vert, face, 3 * i)?;
        let v1 = vertex(vert, face, 3 * i + 1)?;
        let v2 = vertex(vert, face, 3 * i + 2)?;
        let e1: [f64; 3] = std::array::from_fn(|j| (v1[j] - v0[j]) as f64);
        let e2: [f64; 3] = std::array::from_fn(|j| (v2[j] - v0[j]) as f64);
        let mut n = super::frame::cross(&e1, &e2);
        let area = normalize3(&mut n);
        Ok((n, area))
    };
    for i in 0..nf {
        let (n, area) = face_normal(i)?;
        for j in 0..3 {
            let v = face[3 * i + j] as usize;
            for k in 0..3 {
                normal[3 * v + k] = (normal[3 * v + k] as f64 + n[k] * area) as f32;
            }
        }
    }
    if !smooth {
        let mut remove = vec![0f32; vert.len()];
        for i in 0..nf {
            let (n, area) = face_normal(i)?;
            for j in 0..3 {
                let v = face[3 * i + j] as usize;
                let mut vn: [f64; 3] = std::array::from_fn(|k| normal[3 * v + k] as f64);
                normalize3(&mut vn);
                if super::frame::dot3(&n, &vn) < 0.8 {
                    for k in 0..3 {
                        remove[3 * v + k] = (remove[3 * v + k] as f64 + n[k] * area) as f32;
                    }
                }
            }
        }
        for (n, r) in normal.iter_mut().zip(&remove) {
            *n -= r;
        }
    }
    for n in normal.chunks_mut(3) {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        if len as f64 > MINVAL {
            n.iter_mut().for_each(|x| *x /= len);
        } else {
            n.copy_from_slice(&[0.0, 0.0, 1.0]);
        }
    }
    Ok(normal)
}

/// Area, unit normal and centre of a triangle (centre in float, as 2.2.2 sums it).
fn area_normal_center(a: &[f32; 3], b: &[f32; 3], c: &[f32; 3]) -> (f64, [f64; 3], [f64; 3]) {
    let cen: [f64; 3] = std::array::from_fn(|i| ((a[i] + b[i] + c[i]) / 3.0) as f64);
    let e1: [f64; 3] = std::array::from_fn(|i| (b[i] - a[i]) as f64);
    let e2: [f64; 3] = std::array::from_fn(|i| (c[i] - a[i]) as f64);
    let mut n = super::frame::cross(&e1, &e2);
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len < MINVAL {
        return (0.0, n, cen);
    }
    n.iter_mut().for_each(|x| *x /= len);
    (len / 2.0, n, cen)
}

/// Reference frame, scale, centring, principal axes and inertia boxes for both kinds.
fn process(m: &mut Mesh, spec: &MeshSpec, opts: &MeshOpts) -> Result<(), String> {
    let nv = m.vert.len() / 3;
    let nf = m.face.len() / 3;
    if m.normal.len() < 3 * nv {
        m.normal.resize(3 * nv, 0.0);
    }
    for kind in [VOLUME, SHELL] {
        let mut facecen = [0.0f64; 3];
        if kind == VOLUME {
            let rp = spec.refpos.map(|x| x as f32);
            if rp != [0.0; 3] {
                for v in m.vert.chunks_mut(3) {
                    for k in 0..3 {
                        v[k] -= rp[k];
                    }
                }
            }
            if spec.refquat != [1.0, 0.0, 0.0, 0.0] {
                let mat = engine_quat2mat(&normalize4(&spec.refquat).0);
                for i in 0..nv {
                    for a in [&mut m.vert, &mut m.normal] {
                        let p: [f64; 3] = std::array::from_fn(|k| a[3 * i + k] as f64);
                        let r = mul_mat_t_vec3(&mat, &p);
                        for k in 0..3 {
                            a[3 * i + k] = r[k] as f32;
                        }
                    }
                }
            }
            if spec.scale != [1.0; 3] {
                for i in 0..nv {
                    for a in [&mut m.vert, &mut m.normal] {
                        for k in 0..3 {
                            a[3 * i + k] = (a[3 * i + k] as f64 * spec.scale[k]) as f32;
                        }
                    }
                }
            }
            for n in m.normal.chunks_mut(3) {
                let len = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
                if len as f64 > MINVAL {
                    let s = 1.0 / len.sqrt();
                    n.iter_mut().for_each(|x| *x *= s);
                } else {
                    n.copy_from_slice(&[0.0, 0.0, 1.0]);
                }
            }
            let mut area = 0.0;
            for i in 0..nf {
                for j in 0..3 {
                    let f = m.face[3 * i + j];
                    if f < 0 || f as usize >= nv {
                        return Err(format!(
                            "vertex index out of range in {} (index = {i})",
                            m.name
                        ));
                    }
                }
                let (a, _, cen) = tri_data(m, i);
                for j in 0..3 {
                    facecen[j] += a * cen[j];
                }
                area += a;
            }
            if area < MINVAL {
                m.invalid.get_or_insert("mesh surface area is too small");
                return Ok(());
            }
            facecen.iter_mut().for_each(|x| *x /= area);
        }

        // centre of mass from pyramids on the faces (shell: the faces themselves)
        let signed = |kind: usize, a: f64, nrm: &[f64; 3], vec: &[f64; 3]| {
            let vol = if kind == SHELL {
                a
            } else {
                super::frame::dot3(vec, nrm) * a / 3.0
            };
            if opts.exactmeshinertia {
                vol
            } else {
                vol.abs()
            }
        };
        let mut com = [0.0f64; 3];
        let mut volume = 0.0;
        for i in 0..nf {
            let (a, nrm, cen) = tri_data(m, i);
            let vec: [f64; 3] = std::array::from_fn(|j| cen[j] - facecen[j]);
            let vol = signed(kind, a, &nrm, &vec);
            volume += vol;
            for j in 0..3 {
                com[j] += vol * (cen[j] * 3.0 / 4.0 + facecen[j] / 4.0);
            }
        }
        m.volume[kind] = volume;
        if volume < MINVAL {
            m.invalid.get_or_insert("mesh volume is too small");
            return Ok(());
        }
        com.iter_mut().for_each(|x| *x /= volume);
        m.pos[kind] = com;
        if kind == VOLUME {
            for v in m.vert.chunks_mut(3) {
                for j in 0..3 {
                    v[j] = (v[j] as f64 - com[j]) as f32;
                }
            }
        }

        // products of inertia
        const K: [[usize; 2]; 6] = [[0, 0], [1, 1], [2, 2], [0, 1], [0, 2], [1, 2]];
        let mut p = [0.0f64; 6];
        volume = 0.0;
        let div = if kind == SHELL { 12.0 } else { 20.0 };
        for i in 0..nf {
            let (a, nrm, cen) = tri_data(m, i);
            let vol = signed(kind, a, &nrm, &cen);
            volume += vol;
            let [d, e, f] = [0, 1, 2].map(|c| corner(m, i, c));
            for j in 0..6 {
                let [r, c] = K[j];
                let s: f32 = 2.0 * (d[r] * d[c] + e[r] * e[c] + f[r] * f[c])
                    + d[r] * e[c]
                    + d[c] * e[r]
                    + d[r] * f[c]
                    + d[c] * f[r]
                    + e[r] * f[c]
                    + e[c] * f[r];
                p[j] += spec.density * vol / div * s as f64;
            }
        }
        m.volume[kind] = volume;
        let inert = [p[1] + p[2], p[0] + p[2], p[0] + p[1], -p[3], -p[4], -p[5]];
        let full = [
            inert[0], inert[3], inert[4], inert[3], inert[1], inert[5], inert[4], inert[5],
            inert[2],
        ];
        let (ev, equat) = super::frame::eig3(&full);
        if ev[2] <= 0.0 {
            m.invalid
                .get_or_insert("eigenvalue of mesh inertia must be positive");
            return Ok(());
        }
        if ev[0] + ev[1] < ev[2] || ev[0] + ev[2] < ev[1] || ev[1] + ev[2] < ev[0] {
            m.invalid
                .get_or_insert("eigenvalues of mesh inertia violate A + B >= C");
            return Ok(());
        }
        let mass = volume * spec.density;
        m.boxsz[kind] = [
            (6.0 * (ev[1] + ev[2] - ev[0]) / mass).sqrt() / 2.0,
            (6.0 * (ev[0] + ev[2] - ev[1]) / mass).sqrt() / 2.0,
            (6.0 * (ev[0] + ev[1] - ev[2]) / mass).sqrt() / 2.0,
        ];
        m.quat[kind] = equat;
        if kind == VOLUME {
            let q = equat;
            let mat = super::frame::quat2mat(&[q[0], -q[1], -q[2], -q[3]]);
            for i in 0..nv {
                for a in [&mut m.vert, &mut m.normal] {
                    let v: [f64; 3] = std::array::from_fn(|k| a[3 * i + k] as f64);
                    let r = super::frame::mat_vec(&mat, &v);
                    for k in 0..3 {
                        a[3 * i + k] = r[k] as f32;
                    }
                }
            }
            for v in m.vert.chunks(3) {
                for (a, &x) in m.aabb.iter_mut().zip(v) {
                    *a = a.max((x as f64).abs());
                }
            }
        }
    }
    Ok(())
}

fn corner(m: &Mesh, i: usize, c: usize) -> [f32; 3] {
    let v = 3 * m.face[3 * i + c] as usize;
    [m.vert[v], m.vert[v + 1], m.vert[v + 2]]
}

fn tri_data(m: &Mesh, i: usize) -> (f64, [f64; 3], [f64; 3]) {
    area_normal_center(&corner(m, i, 0), &corner(m, i, 1), &corner(m, i, 2))
}

/// Size and offset of a primitive geom fitted to a mesh; `kind` selects the inertia box.
pub fn fit(
    m: &Mesh,
    geom_type: i32,
    kind: usize,
    fitaabb: bool,
    fitscale: f64,
    size: &mut [f64; 3],
) -> Result<[f64; 3], String> {
    use super::objects::{BOX, CAPSULE, CYLINDER, ELLIPSOID, SPHERE};
    let meshpos;
    if !fitaabb {
        let b = m.inertia_box(kind)?;
        match geom_type {
            SPHERE => size[0] = (b[0] + b[1] + b[2]) / 3.0,
            CAPSULE => {
                size[0] = (b[0] + b[1]) / 2.0;
                size[1] = (b[2] - size[0] / 2.0).max(0.0);
            }
            CYLINDER => {
                size[0] = (b[0] + b[1]) / 2.0;
                size[1] = b[2];
            }
            ELLIPSOID | BOX => *size = b,
            _ => return Err(format!("invalid geom type in fitting mesh {}", m.name)),
        }
        meshpos = m.pos[kind];
    } else {
        let mut lo = [1e10f64; 3];
        let mut hi = [-1e10f64; 3];
        for v in m.vert.chunks(3) {
            for j in 0..3 {
                lo[j] = lo[j].min(v[j] as f64);
                hi[j] = hi[j].max(v[j] as f64);
            }
        }
        let cen: [f64; 3] = std::array::from_fn(|j| (lo[j] + hi[j]) / 2.0);
        meshpos = cen;
        let verts = || {
            m.vert
                .chunks(3)
                .map(|v| [v[0] as f64, v[1] as f64, v[2] as f64])
        };
        match geom_type {
            SPHERE => {
                size[0] = 0.0;
                for v in verts() {
                    let d = [v[0] - cen[0], v[1] - cen[1], v[2] - cen[2]];
                    size[0] = size[0].max((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt());
                }
            }
            CAPSULE | CYLINDER => {
                size[0] = 0.0;
                size[1] = 0.0;
                let xy = |v: &[f64; 3]| {
                    ((v[0] - cen[0]) * (v[0] - cen[0]) + (v[1] - cen[1]) * (v[1] - cen[1])).sqrt()
                };
                for v in verts() {
                    size[0] = size[0].max(xy(&v));
                    size[1] = size[1].max((v[2] - cen[2]).abs());
                }
                if geom_type == CAPSULE {
                    size[1] = 0.0;
                    for v in verts() {
                        let h = size[0] * (xy(&v) / size[0]).acos().sin();
                        size[1] = size[1].max((v[2] - cen[2]).abs() - h);
                    }
                }
            }
            ELLIPSOID | BOX => *size = std::array::from_fn(|j| hi[j] - cen[j]),
            _ => return Err(format!("invalid fittype in mesh {}", m.name)),
        }
    }
    for s in size.iter_mut() {
        *s *= fitscale;
    }
    Ok(meshpos)
}
