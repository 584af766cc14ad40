//! The narrow phase: which routine handles which pair of geom types (2.2.2's
//! mjCOLLISIONFUNC table), and the geometry each routine reads from the model and data.

use super::boxes;
use super::convex::{self, ConvexGeom, HField, MeshData, MprOptions, Shape};
use super::primitive::{self as prim, ContactGeom, GeomPose, Pose};
use crate::abi::mjtEnableBit_;
use crate::engine::geom::*;
use crate::engine::linalg::row;
use crate::engine::{enabled, Data, Model};

pub use super::convex::MAX_CONTACT_PAIR;

/// Is there a routine for these types (t1 <= t2)? Planes and height fields never meet each
/// other.
pub fn has_collider(t1: i32, t2: i32) -> bool {
    (PLANE..=MESH).contains(&t1) && (PLANE..=MESH).contains(&t2) && !(t1 <= HFIELD && t2 <= HFIELD)
}

/// Geom g's pose as the model and data hold it.
#[inline(always)]
fn pose<'a>(m: &Model<'a>, d: &'a Data, g: usize) -> GeomPose<'a> {
    GeomPose {
        pos: row_ref(d.geom_xpos, g),
        mat: row_ref(d.geom_xmat, g),
        size: row_ref(m.geom_size(), g),
    }
}

/// Row i of an array of rows of N.
#[inline(always)]
fn row_ref<const N: usize>(a: &[f64], i: usize) -> &[f64; N] {
    a[N * i..N * i + N].try_into().expect("N values")
}

fn convex_geom<'a>(m: &Model<'a>, d: &Data, g: usize) -> ConvexGeom<'a> {
    let shape = match m.geom_type()[g] {
        SPHERE => Shape::Sphere,
        CAPSULE => Shape::Capsule,
        ELLIPSOID => Shape::Ellipsoid,
        CYLINDER => Shape::Cylinder,
        BOX => Shape::Box,
        _ => {
            let id = m.geom_dataid()[g].max(0) as usize;
            let (adr, num) = (m.mesh_vertadr()[id] as usize, m.mesh_vertnum()[id] as usize);
            let graphadr = m.mesh_graphadr()[id];
            Shape::Mesh(MeshData {
                vert: &m.mesh_vert_xyz()[adr..adr + num],
                graph: (graphadr >= 0).then(|| &m.mesh_graph()[graphadr as usize..]),
            })
        }
    };
    ConvexGeom {
        shape,
        pose: Pose {
            pos: row(d.geom_xpos, g),
            mat: row(d.geom_xmat, g),
            size: row(m.geom_size(), g),
        },
        rbound: m.geom_rbound()[g],
    }
}

fn mpr_options(m: &Model) -> MprOptions {
    MprOptions {
        iterations: m.raw.opt.mpr_iterations.max(0) as u64,
        tolerance: m.raw.opt.mpr_tolerance,
    }
}

/// Contacts of geoms g1, g2 (types ordered, a routine exists) into `con`; returns their number.
pub fn collide(
    m: &Model,
    d: &Data,
    g1: usize,
    g2: usize,
    margin: f64,
    con: &mut [ContactGeom; MAX_CONTACT_PAIR],
) -> usize {
    let (t1, t2) = (m.geom_type()[g1], m.geom_type()[g2]);
    let (p1, p2) = (pose(m, d, g1), pose(m, d, g2));
    let opt = mpr_options(m);
    let multiccd = enabled(m, mjtEnableBit_::mjENBL_MULTICCD);
    match (t1, t2) {
        (PLANE, SPHERE) => prim::plane_sphere(&p1, &p2, margin, con),
        (PLANE, CAPSULE) => prim::plane_capsule(&p1, &p2, margin, con),
        (PLANE, CYLINDER) => prim::plane_cylinder(&p1, &p2, margin, con),
        (PLANE, BOX) => prim::plane_box(&p1, &p2, margin, con),
        (PLANE, _) => convex::plane_convex(&p1, &convex_geom(m, d, g2), margin, con),
        (HFIELD, _) => {
            let id = m.geom_dataid()[g1].max(0) as usize;
            let (nrow, ncol) = (m.hfield_nrow()[id] as usize, m.hfield_ncol()[id] as usize);
            let adr = m.hfield_adr()[id] as usize;
            let hf = HField {
                size: row(m.hfield_size(), id),
                nrow,
                ncol,
                data: &m.hfield_data()[adr..adr + nrow * ncol],
            };
            convex::convex_hfield(&hf, &p1, &convex_geom(m, d, g2), margin, &opt, con)
        }
        (SPHERE, SPHERE) => prim::sphere_sphere(&p1, &p2, margin, con),
        (SPHERE, CAPSULE) => prim::sphere_capsule(&p1, &p2, margin, con),
        (SPHERE, BOX) => prim::sphere_box(&p1, &p2, margin, con),
        (CAPSULE, CAPSULE) => prim::capsule_capsule(&p1, &p2, margin, con),
        (CAPSULE, BOX) => prim::capsule_box(&p1, &p2, margin, con),
        (BOX, BOX) => boxes::box_box(&p1, &p2, margin, con),
        _ => convex::convex(
            &convex_geom(m, d, g1),
            &convex_geom(m, d, g2),
            margin,
            &opt,
            multiccd,
            con,
        ),
    }
}
