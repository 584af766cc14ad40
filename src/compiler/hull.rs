//! Convex-hull graph of a mesh (`mesh_graph`), from qhull 2020.2 through `hull.c`.
//!
//! Layout, as 2.2.2 stores it: numvert, numface, vert_edgeadr[numvert], vert_globalid[numvert],
//! edge_localid[numvert + 3*numface] (each vertex's hull neighbours, -1 terminated),
//! face_globalid[3*numface].

use std::os::raw::c_int;

#[repr(C)]
struct RawHull {
    numvert: c_int,
    numface: c_int,
    vert_point: *mut c_int,
    nbr_adr: *mut c_int,
    nbr: *mut c_int,
    face_point: *mut c_int,
    face_top: *mut c_int,
}

extern "C" {
    fn rj_hull_build(points: *mut f64, npoint: c_int, out: *mut RawHull) -> c_int;
    fn rj_hull_free(h: *mut RawHull);
}

/// qhull's hull, copied out: vertices, facet neighbours per vertex, triangles.
struct Hull {
    vert_point: Vec<i32>,
    nbr_adr: Vec<i32>,
    nbr: Vec<i32>,
    face_point: Vec<i32>,
    face_top: Vec<i32>,
}

fn qhull(points: &mut [f64]) -> Result<Hull, i32> {
    let mut raw = RawHull {
        numvert: 0,
        numface: 0,
        vert_point: std::ptr::null_mut(),
        nbr_adr: std::ptr::null_mut(),
        nbr: std::ptr::null_mut(),
        face_point: std::ptr::null_mut(),
        face_top: std::ptr::null_mut(),
    };
    // SAFETY: hull.c reads 3*npoint doubles from `points` and fills `raw` with arrays it
    // allocated (sizes given by numvert, numface and nbr_adr), which we copy and free.
    unsafe {
        let status = rj_hull_build(points.as_mut_ptr(), (points.len() / 3) as c_int, &mut raw);
        if status != 0 {
            return Err(status);
        }
        let (nv, nf) = (raw.numvert as usize, raw.numface as usize);
        let copy = |p: *const c_int, n: usize| std::slice::from_raw_parts(p, n).to_vec();
        let nbr_adr = copy(raw.nbr_adr, nv + 1);
        let hull = Hull {
            vert_point: copy(raw.vert_point, nv),
            nbr: copy(raw.nbr, nbr_adr[nv] as usize),
            nbr_adr,
            face_point: copy(raw.face_point, 3 * nf),
            face_top: copy(raw.face_top, nf),
        };
        rj_hull_free(&mut raw);
        Ok(hull)
    }
}

/// What went wrong making a graph.
pub enum GraphError {
    /// qhull failed ("qhull error")
    Qhull,
    /// a hull facet that is not a triangle, or an inconsistent graph (fatal in 2.2.2)
    Fatal(&'static str),
}

/// The hull graph of `vert` (float xyz); None for fewer than 4 vertices.
pub fn graph(vert: &[f32]) -> Result<Option<Vec<i32>>, GraphError> {
    let nvert = vert.len() / 3;
    if nvert < 4 {
        return Ok(None);
    }
    let mut points: Vec<f64> = vert.iter().map(|&x| x as f64).collect();
    let h = qhull(&mut points).map_err(|s| match s {
        2 => GraphError::Fatal("Qhull did not return triangle"),
        _ => GraphError::Qhull,
    })?;
    let (nv, nf) = (h.vert_point.len(), h.face_top.len());
    if h.vert_point.iter().any(|&p| p < 0 || p as usize >= nvert) {
        crate::runtime::warning("Could not construct convex hull graph");
        return Ok(None);
    }
    let mut g = vec![0i32; 2 + 3 * nv + 6 * nf];
    g[0] = nv as i32;
    g[1] = nf as i32;
    let (edgeadr, rest) = g[2..].split_at_mut(nv);
    let (globalid, rest) = rest.split_at_mut(nv);
    let (edges, faces) = rest.split_at_mut(nv + 3 * nf);
    let mut adr = 0;
    for i in 0..nv {
        let pid = h.vert_point[i];
        edgeadr[i] = adr as i32;
        globalid[i] = pid;
        let start = adr;
        for &f in &h.nbr[h.nbr_adr[i] as usize..h.nbr_adr[i + 1] as usize] {
            for &q in &h.face_point[3 * f as usize..3 * f as usize + 3] {
                if q != pid && !edges[start..adr].contains(&q) {
                    if adr >= edges.len() {
                        return Err(GraphError::Fatal("Wrong size in convex hull graph"));
                    }
                    edges[adr] = q;
                    adr += 1;
                }
            }
        }
        if adr >= edges.len() {
            return Err(GraphError::Fatal("Wrong size in convex hull graph"));
        }
        edges[adr] = -1;
        adr += 1;
    }
    if adr != nv + 3 * nf {
        return Err(GraphError::Fatal("Wrong size in convex hull graph"));
    }
    for f in 0..nf {
        let ind = if h.face_top[f] != 0 {
            [1, 0, 2]
        } else {
            [0, 1, 2]
        };
        for k in 0..3 {
            faces[3 * f + ind[k]] = h.face_point[3 * f + k];
        }
    }
    for e in edges.iter_mut().filter(|e| **e >= 0) {
        match globalid.iter().position(|&p| p == *e) {
            Some(local) => *e = local as i32,
            None => return Err(GraphError::Fatal("Vertex id not found in convex hull")),
        }
    }
    Ok(Some(g))
}
