//! Convex-convex collisions through MPR (libccd 2.1 semantics, see `ccd`) with 2.2.2's support
//! functions, normal correction for smooth geoms, optional multi-contact search by small
//! perturbations (mjENBL_MULTICCD), and plane-convex contacts with extra mesh vertices.

use super::mpr::{vec3_eq, ConvexPair};
use super::primitive::{ContactGeom, GeomPose, Pose};
use crate::math::blas::norm;
use crate::math::misc::{min, sign};
use crate::math::quat::{axis_angle2quat, quat2mat};
use crate::math::spatial::make_frame;
use crate::math::vec3::{
    add3, dist3, dot3, mul_mat3, mul_mat_t_vec3, mul_mat_vec3, normalize3, scl3, sub3, transpose3,
};
use crate::math::{Mat3, Vec3, MINVAL};

/// Vertices and (optional) hill-climbing graph of a convex mesh.
#[derive(Clone, Copy, Debug)]
pub struct MeshData<'a> {
    /// This mesh's vertices (mesh_vert from mesh_vertadr).
    pub vert: &'a [[f32; 3]],
    /// mesh_graph from this mesh's mesh_graphadr, when the mesh has a graph.
    pub graph: Option<&'a [i32]>,
}

/// Geom types with a support function.
#[derive(Clone, Copy, Debug)]
pub enum Shape<'a> {
    Sphere,
    Capsule,
    Ellipsoid,
    Cylinder,
    Box,
    Mesh(MeshData<'a>),
}

/// A convex geom: shape, pose and bounding radius (geom_rbound).
#[derive(Clone, Copy, Debug)]
pub struct ConvexGeom<'a> {
    pub shape: Shape<'a>,
    pub pose: Pose,
    pub rbound: f64,
}

/// MPR settings (mjOption mpr_iterations, mpr_tolerance).
#[derive(Clone, Copy, Debug)]
pub struct MprOptions {
    pub iterations: u64,
    pub tolerance: f64,
}

#[inline]
fn vdot(d: &Vec3, v: &[[f32; 3]], i: usize) -> f64 {
    let p = &v[i];
    d[0] * p[0] as f64 + d[1] * p[1] as f64 + d[2] * p[2] as f64
}

/// A mesh's hull graph (mesh_graph from its mesh_graphadr): per hull vertex its first edge and
/// its index among the mesh's vertices, and the -1-terminated neighbour lists.
struct HullGraph<'a> {
    edgeadr: &'a [i32],
    globalid: &'a [i32],
    localid: &'a [i32],
}

impl<'a> HullGraph<'a> {
    fn new(graph: &'a [i32]) -> Self {
        let numvert = graph[0] as usize;
        HullGraph {
            edgeadr: &graph[2..2 + numvert],
            globalid: &graph[2 + numvert..2 + 2 * numvert],
            localid: &graph[2 + 2 * numvert..],
        }
    }
}

/// Hill climb on a mesh's hull graph from hull vertex 0, 2.2.2's path: scan the current
/// vertex's neighbours in order, taking each one strictly better than the best so far, then
/// go on from the last taken. Returns the best vertex's local and global index.
fn climb(dir: &Vec3, v: &[[f32; 3]], graph: &[i32]) -> (usize, i32) {
    let HullGraph {
        edgeadr,
        globalid,
        localid,
    } = HullGraph::new(graph);
    let dot = |loc: usize| vdot(dir, v, globalid[loc] as usize);
    let (mut ibest, mut best) = (0, dot(0));
    loop {
        let start = ibest;
        let mut i = edgeadr[ibest] as usize;
        // Each improvement leaves the scan (a branch, not a select), so the next vertex's
        // address comes from prediction instead of waiting for the dot products.
        while let Some((loc, d)) = loop {
            let loc = match localid.get(i) {
                Some(&l) if l >= 0 => l as usize,
                _ => break None,
            };
            i += 1;
            let d = dot(loc);
            if d > best {
                break Some((loc, d));
            }
        } {
            (ibest, best) = (loc, d);
        }
        if ibest == start {
            return (ibest, globalid[ibest]);
        }
    }
}

/// Support point of the geom (inflated by margin/2) in global direction `gdir` (mjccd_support).
/// `meshindex` receives the best vertex (global index without graph, local with graph).
/// Kept out of line: one copy of the hull climb serves both geoms of a pair (inlined into
/// MPR's support of the pair, one per geom, the profiled build's climbs ran 20% slower).
#[inline(never)]
pub fn support(g: &ConvexGeom, gdir: &Vec3, margin: f64, meshindex: &mut i32) -> Vec3 {
    let size = &g.pose.size;
    let dir = mul_mat_t_vec3(&g.pose.mat, gdir);
    let mut res = match g.shape {
        Shape::Sphere => scl3(&dir, size[0]),
        Shape::Capsule => {
            let mut r = scl3(&dir, size[0]);
            r[2] += sign(dir[2]) * size[1];
            r
        }
        Shape::Ellipsoid => {
            let r = [dir[0] * size[0], dir[1] * size[1], dir[2] * size[2]];
            let mut r = normalize3(&r).0;
            for i in 0..3 {
                r[i] *= size[i];
            }
            r
        }
        Shape::Cylinder => {
            let t = (dir[0] * dir[0] + dir[1] * dir[1]).sqrt();
            let (x, y) = if t > MINVAL {
                (dir[0] / t * size[0], dir[1] / t * size[0])
            } else {
                (0.0, 0.0)
            };
            [x, y, sign(dir[2]) * size[1]]
        }
        Shape::Box => [
            sign(dir[0]) * size[0],
            sign(dir[1]) * size[1],
            sign(dir[2]) * size[2],
        ],
        Shape::Mesh(mesh) => {
            let v = mesh.vert;
            let best = match mesh.graph {
                None => {
                    let (mut best, mut ibest) = (-1e10, -1i32);
                    for i in 0..v.len() {
                        let d = vdot(&dir, v, i);
                        if d > best {
                            best = d;
                            ibest = i as i32;
                        }
                    }
                    *meshindex = ibest;
                    ibest
                }
                Some(graph) => {
                    let (local, global) = climb(&dir, v, graph);
                    *meshindex = local as i32;
                    global
                }
            };
            if best < 0 {
                [0.0; 3]
            } else {
                let b = best as usize;
                v[b].map(f64::from)
            }
        }
    };
    for i in 0..3 {
        res[i] += dir[i] * margin / 2.0;
    }
    add3(&mul_mat_vec3(&g.pose.mat, &res), &g.pose.pos)
}

/// One MPR contact between g1 and g2 (mjc_MPRIteration), normal corrected by `fix_normal`.
/// Returns whether a contact was written to `con`.
pub fn mpr_contact(
    g1: &ConvexGeom,
    g2: &ConvexGeom,
    margin: f64,
    opt: &MprOptions,
    con: &mut ContactGeom,
) -> bool {
    let (mut i1, mut i2) = (-1, -1);
    let mut pair = ConvexPair {
        center1: g1.pose.pos,
        center2: g2.pose.pos,
        support1: |d: &Vec3| support(g1, d, margin, &mut i1),
        support2: |d: &Vec3| support(g2, d, margin, &mut i2),
        max_iterations: opt.iterations,
        tolerance: opt.tolerance,
    };
    let Some((depth, dir, pos)) = pair.mpr_penetration() else {
        return false;
    };
    if vec3_eq(&dir, &[0.0; 3]) {
        return false;
    }
    con.dist = margin - depth;
    con.frame = [dir[0], dir[1], dir[2], 0.0, 0.0, 0.0];
    con.pos = pos;
    fix_normal(con, g1, g2);
    true
}

/// Point outside an ellipsoid: normal by ray-projection iterations (false when it fails at once).
fn ellipsoid_normal_inside(nrm: &mut Vec3, pos: &Vec3, size: &Vec3) -> bool {
    let s2inv = [
        1.0 / (size[0] * size[0]),
        1.0 / (size[1] * size[1]),
        1.0 / (size[2] * size[2]),
    ];
    let c =
        pos[0] * pos[0] * s2inv[0] + pos[1] * pos[1] * s2inv[1] + pos[2] * pos[2] * s2inv[2] - 1.0;
    if c > 0.0 {
        return false;
    }
    *nrm = normalize3(nrm).0;
    for iter in 0..30 {
        let a =
            nrm[0] * nrm[0] * s2inv[0] + nrm[1] * nrm[1] * s2inv[1] + nrm[2] * nrm[2] * s2inv[2];
        let b =
            pos[0] * nrm[0] * s2inv[0] + pos[1] * nrm[1] * s2inv[1] + pos[2] * nrm[2] * s2inv[2];
        let det = b * b - a * c;
        if det < MINVAL || a < MINVAL {
            return iter > 0;
        }
        let x = (-b + det.sqrt()) / a;
        if x < 0.0 {
            return iter > 0;
        }
        let pnt = [
            pos[0] + x * nrm[0],
            pos[1] + x * nrm[1],
            pos[2] + x * nrm[2],
        ];
        let newnrm = normalize3(&[pnt[0] * s2inv[0], pnt[1] * s2inv[1], pnt[2] * s2inv[2]]).0;
        let change = dist3(nrm, &newnrm);
        *nrm = newnrm;
        if change < 1e-6 {
            break;
        }
    }
    true
}

/// Point inside an ellipsoid: normal from a diagonal QCQP.
fn ellipsoid_normal_outside(nrm: &mut Vec3, pos: &Vec3, size: &Vec3) -> bool {
    let s2 = [size[0] * size[0], size[1] * size[1], size[2] * size[2]];
    let ps2 = [
        pos[0] * pos[0] * s2[0],
        pos[1] * pos[1] * s2[1],
        pos[2] * pos[2] * s2[2],
    ];
    let mut la = 0.0;
    for _ in 0..30 {
        let r = [1.0 / (s2[0] + la), 1.0 / (s2[1] + la), 1.0 / (s2[2] + la)];
        let val = ps2[0] * r[0] * r[0] + ps2[1] * r[1] * r[1] + ps2[2] * r[2] * r[2] - 1.0;
        if val < 1e-6 {
            break;
        }
        let deriv = -2.0
            * (ps2[0] * r[0] * r[0] * r[0]
                + ps2[1] * r[1] * r[1] * r[1]
                + ps2[2] * r[2] * r[2] * r[2]);
        if deriv > -MINVAL {
            break;
        }
        let delta = -val / deriv;
        if delta < 1e-6 {
            break;
        }
        la += delta;
    }
    *nrm = normalize3(&[
        pos[0] / (s2[0] + la),
        pos[1] / (s2[1] + la),
        pos[2] / (s2[2] + la),
    ])
    .0;
    true
}

/// Replaces the MPR normal by the analytic surface normal of sphere, capsule, ellipsoid and
/// cylinder geoms where it is well defined (mjc_fixNormal).
pub fn fix_normal(con: &mut ContactGeom, g1: &ConvexGeom, g2: &ConvexGeom) {
    fix_normal_of(con, [Some(g1), Some(g2)]);
}

/// `fix_normal` where a side may be a geom without support function (heightfield).
#[allow(clippy::collapsible_match)]
fn fix_normal_of(con: &mut ContactGeom, geoms: [Option<&ConvexGeom>; 2]) {
    let smooth = |g: &ConvexGeom| {
        matches!(
            g.shape,
            Shape::Sphere | Shape::Capsule | Shape::Ellipsoid | Shape::Cylinder
        )
    };
    let geoms = geoms.map(|g| g.filter(|g| smooth(g)));
    if geoms[0].is_none() && geoms[1].is_none() {
        return;
    }
    let f = con.frame;
    let mut normal = [[f[0], f[1], f[2]], [-f[0], -f[1], -f[2]]];
    let mut processed = [false; 2];
    for i in 0..2 {
        let Some(g) = geoms[i] else {
            continue;
        };
        let (mat, size) = (&g.pose.mat, &g.pose.size);
        let pos = mul_mat_t_vec3(mat, &sub3(&con.pos, &g.pose.pos));
        let mut nrm = mul_mat_t_vec3(mat, &normal[i]);
        match g.shape {
            Shape::Sphere => {
                nrm = pos;
                processed[i] = true;
            }
            Shape::Capsule => {
                nrm[2] = if pos[2] < -size[1] {
                    pos[2] + size[1]
                } else if pos[2] > size[1] {
                    pos[2] - size[1]
                } else {
                    0.0
                };
                nrm[0] = pos[0];
                nrm[1] = pos[1];
                processed[i] = true;
            }
            Shape::Ellipsoid => {
                if !(size[0] < MINVAL || size[1] < MINVAL || size[2] < MINVAL) {
                    let d = pos[0] * pos[0] / (size[0] * size[0])
                        + pos[1] * pos[1] / (size[1] * size[1])
                        + pos[2] * pos[2] / (size[2] * size[2]);
                    processed[i] = if d <= 1.0 {
                        ellipsoid_normal_inside(&mut nrm, &pos, size)
                    } else {
                        ellipsoid_normal_outside(&mut nrm, &pos, size)
                    };
                }
            }
            Shape::Cylinder => {
                // comparisons as 2.2.2 spells them, so that NaN takes the same branches
                #[allow(clippy::neg_cmp_op_on_partial_ord)]
                if !(pos[2].abs() > 0.95 * size[1]) {
                    let flat = (size[1] - pos[2].abs()).abs();
                    let round = (size[0] - norm(&pos[..2])).abs();
                    #[allow(clippy::neg_cmp_op_on_partial_ord)]
                    if !(flat < 0.25 * round) {
                        nrm = [pos[0], pos[1], 0.0];
                        processed[i] = true;
                    }
                }
            }
            _ => {}
        }
        if processed[i] {
            normal[i] = mul_mat_vec3(mat, &normalize3(&nrm).0);
        }
    }

    let n = if processed[0] && processed[1] {
        normalize3(&sub3(&normal[0], &normal[1])).0
    } else if processed[0] {
        normal[0]
    } else if processed[1] {
        scl3(&normal[1], crate::math::misc::minus_one())
    } else {
        return;
    };
    con.frame = [n[0], n[1], n[2], 0.0, 0.0, 0.0];
}

/// Rotates a pose by `rot` about `origin` (in place on copies).
fn rotate_pose(origin: &Vec3, rot: &Mat3, pose: &mut Pose) {
    pose.mat = mul_mat3(rot, &pose.mat);
    let rel = sub3(origin, &pose.pos);
    let vec = sub3(&mul_mat_vec3(rot, &rel), &rel);
    pose.pos = sub3(&pose.pos, &vec);
}

/// Convex-convex contacts (mjc_Convex): one MPR contact, plus up to 4 from perturbed poses
/// when `multiccd` and neither geom is a sphere or ellipsoid. `con` must hold 5.
pub fn convex(
    g1: &ConvexGeom,
    g2: &ConvexGeom,
    margin: f64,
    opt: &MprOptions,
    multiccd: bool,
    con: &mut [ContactGeom],
) -> usize {
    let mut ncon = mpr_contact(g1, g2, margin, opt, &mut con[0]) as usize;
    let round = |g: &ConvexGeom| matches!(g.shape, Shape::Sphere | Shape::Ellipsoid);
    if ncon == 0 || !multiccd || round(g1) || round(g2) {
        return ncon;
    }
    let mut frame = [0.0; 9];
    frame[..6].copy_from_slice(&con[0].frame);
    let Some(frame) = make_frame(&frame) else {
        return ncon;
    };
    let tolerance = 1e-3 * min(g1.rbound, g2.rbound);
    let axes = [
        [frame[3], frame[4], frame[5]],
        [frame[6], frame[7], frame[8]],
    ];
    for axis in &axes {
        for angle in [-1e-3, 1e-3] {
            let rot = quat2mat(&axis_angle2quat(axis, angle));
            let origin = con[0].pos;
            let (mut p1, mut p2) = (*g1, *g2);
            rotate_pose(&origin, &rot, &mut p1.pose);
            rotate_pose(&origin, &transpose3(&rot), &mut p2.pose);
            let found = mpr_contact(&p1, &p2, margin, opt, &mut con[ncon]);
            if found && (0..ncon).all(|i| dist3(&con[i].pos, &con[ncon].pos) > tolerance) {
                con[ncon].dist = con[0].dist;
                ncon += 1;
            }
        }
    }
    ncon
}

/// Plane (g1) against a convex geom (g2): its deepest point, and for meshes up to two more
/// vertices below the margin (mjc_PlaneConvex). `con` must hold 3.
pub fn plane_convex(
    plane: &GeomPose,
    g2: &ConvexGeom,
    margin: f64,
    con: &mut [ContactGeom],
) -> usize {
    const MAXPLANEMESH: usize = 3;
    const TOLPLANEMESH: f64 = 0.3;
    let m1 = &plane.mat;
    let normal = [m1[2], m1[5], m1[8]];
    let dir = [-m1[2], -m1[5], -m1[8]];
    let mut meshindex = -1;
    let vec = support(g2, &dir, 0.0, &mut meshindex);
    let dist = dot3(&normal, &sub3(&vec, plane.pos));
    if dist > margin {
        return 0;
    }
    con[0].dist = dist;
    con[0].pos = add_scl(&vec, &normal, -0.5 * dist);
    con[0].frame = [normal[0], normal[1], normal[2], 0.0, 0.0, 0.0];

    let Shape::Mesh(mesh) = g2.shape else {
        return 1;
    };
    let v = mesh.vert;
    let (pos2, mat2) = (&g2.pose.pos, &g2.pose.mat);
    let locdir = mul_mat_t_vec3(mat2, &dir);
    let threshold = dot3(&normal, &sub3(pos2, plane.pos)) - margin;
    let first = con[0].pos;
    let mut count = 1;
    let add = |con: &mut ContactGeom, k: usize| -> usize {
        let vert = v[k].map(f64::from);
        let pnt = add3(&mul_mat_vec3(mat2, &vert), pos2);
        if dist3(&pnt, &first) < TOLPLANEMESH * g2.rbound {
            return 0;
        }
        con.dist = dot3(&normal, &sub3(&pnt, plane.pos));
        con.pos = add_scl(&pnt, &normal, -0.5 * con.dist);
        con.frame = [normal[0], normal[1], normal[2], 0.0, 0.0, 0.0];
        1
    };
    match mesh.graph {
        None => {
            let mut i = 0;
            while i < v.len() && count < MAXPLANEMESH {
                if vdot(&locdir, v, i) > threshold && i as i32 != meshindex {
                    count += add(&mut con[count], i);
                }
                i += 1;
            }
        }
        Some(graph) if meshindex >= 0 => {
            let HullGraph {
                edgeadr,
                globalid,
                localid,
            } = HullGraph::new(graph);
            let mut i = edgeadr[meshindex as usize] as usize;
            while localid[i] >= 0 && count < MAXPLANEMESH {
                let k = globalid[localid[i] as usize] as usize;
                if vdot(&locdir, v, k) > threshold {
                    count += add(&mut con[count], k);
                }
                i += 1;
            }
        }
        Some(_) => {}
    }
    count
}

#[inline]
fn add_scl(a: &Vec3, b: &Vec3, s: f64) -> Vec3 {
    [a[0] + b[0] * s, a[1] + b[1] * s, a[2] + b[2] * s]
}

/// A heightfield: sizes (x, y, top, bottom), grid and elevation data in [0, 1].
#[derive(Clone, Copy, Debug)]
pub struct HField<'a> {
    pub size: [f64; 4],
    pub nrow: usize,
    pub ncol: usize,
    pub data: &'a [f32],
}

/// Most contacts of one geom pair (mjMAXCONPAIR).
pub const MAX_CONTACT_PAIR: usize = 50;

/// Heightfield (pose `hpose`) against a convex geom: MPR against the triangular prisms of the
/// grid cells under the geom (mjc_ConvexHField). `con` must hold MAX_CONTACT_PAIR.
pub fn convex_hfield(
    hf: &HField,
    hpose: &GeomPose,
    g2: &ConvexGeom,
    margin: f64,
    opt: &MprOptions,
    con: &mut [ContactGeom],
) -> usize {
    use crate::math::blas::mul_mat_t_vec;
    use crate::math::misc::to_int;
    use crate::math::vec3::mul_mat3t_mat;
    let size1 = &hf.size;
    let (pos1, mat1) = (hpose.pos, hpose.mat);

    // geom position in the heightfield frame, bounding-sphere test
    let mut pos = [0.0; 3];
    mul_mat_t_vec(&mut pos, mat1, &sub3(&g2.pose.pos, pos1), 3, 3);
    let r2 = g2.rbound;
    for i in 0..2 {
        if (size1[i] < pos[i] - r2 - margin) || (-size1[i] > pos[i] + r2 + margin) {
            return 0;
        }
    }
    if size1[2] < pos[2] - r2 - margin || -size1[3] > pos[2] + r2 + margin {
        return 0;
    }

    // the geom in the heightfield frame, and its bounding box
    let mut local = *g2;
    local.pose.mat = mul_mat3t_mat(mat1, &g2.pose.mat);
    local.pose.pos = pos;
    let mut idx = -1;
    let mut extent = |d: Vec3, k: usize| support(&local, &d, 0.0, &mut idx)[k];
    let xmax = extent([1.0, 0.0, 0.0], 0);
    let xmin = extent([-1.0, 0.0, 0.0], 0);
    let ymax = extent([0.0, 1.0, 0.0], 1);
    let ymin = extent([0.0, -1.0, 0.0], 1);
    let zmax = extent([0.0, 0.0, 1.0], 2);
    let zmin = extent([0.0, 0.0, -1.0], 2);
    if (xmin - margin > size1[0])
        || (xmax + margin < -size1[0])
        || (ymin - margin > size1[1])
        || (ymax + margin < -size1[1])
        || (zmin - margin > size1[2])
        || (zmax + margin < -size1[3])
    {
        return 0;
    }

    // sub-grid under the geom
    let (nrow, ncol) = (hf.nrow as i32, hf.ncol as i32);
    let cmin = to_int(((xmin + size1[0]) / (2.0 * size1[0]) * (ncol - 1) as f64).floor()).max(0);
    let cmax =
        to_int(((xmax + size1[0]) / (2.0 * size1[0]) * (ncol - 1) as f64).ceil()).min(ncol - 1);
    let rmin = to_int(((ymin + size1[1]) / (2.0 * size1[1]) * (nrow - 1) as f64).floor()).max(0);
    let rmax =
        to_int(((ymax + size1[1]) / (2.0 * size1[1]) * (nrow - 1) as f64).ceil()).min(nrow - 1);

    let dx = (2.0 * size1[0]) / (ncol - 1) as f64;
    let dy = (2.0 * size1[1]) / (nrow - 1) as f64;
    let dr = [1, 0];
    let mut prism = [[0.0f64; 3]; 6];
    for v in &mut prism[..3] {
        v[2] = -size1[3];
    }

    let mut cnt = 0;
    'grid: for r in rmin..rmax {
        let mut nvert = 0;
        for c in cmin..=cmax {
            for d in dr {
                let row = r + d;
                let z = hf.data[(row * ncol + c) as usize] as f64 * size1[2] + margin;
                let (x, y) = (dx * c as f64 - size1[0], dy * row as f64 - size1[1]);
                prism[0] = prism[1];
                prism[1] = prism[2];
                prism[3] = prism[4];
                prism[4] = prism[5];
                prism[2][0] = x;
                prism[5][0] = x;
                prism[2][1] = y;
                prism[5][1] = y;
                prism[5][2] = z;
                nvert += 1;
                if nvert <= 2 {
                    continue;
                }
                if prism[3][2] < zmin && prism[4][2] < zmin && prism[5][2] < zmin {
                    continue;
                }

                let mut center = [0.0; 3];
                for v in &prism {
                    center = add3(&center, v);
                }
                let center = scl3(&center, 1.0 / 6.0);
                let p = prism;
                let mut i2 = -1;
                let mut pair = ConvexPair {
                    center1: center,
                    center2: local.pose.pos,
                    support1: |dir: &Vec3| {
                        let start = if dir[2] < 0.0 { 0 } else { 3 };
                        let mut ibest = start;
                        let mut best = dot3(&p[start], dir);
                        for (i, v) in p.iter().enumerate().take(start + 3).skip(start + 1) {
                            let t = dot3(v, dir);
                            if t > best {
                                ibest = i;
                                best = t;
                            }
                        }
                        p[ibest]
                    },
                    support2: |dir: &Vec3| support(&local, dir, margin, &mut i2),
                    max_iterations: opt.iterations,
                    tolerance: opt.tolerance,
                };
                if let Some((depth, dir, vpos)) = pair.mpr_penetration() {
                    if !vec3_eq(&dir, &[0.0; 3]) {
                        let n = mul_mat_vec3(mat1, &dir);
                        let c = &mut con[cnt];
                        c.dist = -depth;
                        c.frame = [n[0], n[1], n[2], 0.0, 0.0, 0.0];
                        c.pos = add3(&mul_mat_vec3(mat1, &vpos), pos1);
                        cnt += 1;
                        if cnt >= MAX_CONTACT_PAIR {
                            break 'grid;
                        }
                    }
                }
            }
        }
    }

    for c in &mut con[..cnt] {
        fix_normal_of(c, [None, Some(g2)]);
    }
    cnt
}
