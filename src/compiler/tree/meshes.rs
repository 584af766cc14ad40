//! Meshes: compiled from their files or data, then packed into the mesh arrays.

use super::*;
use crate::compiler::mesh::{self, Mesh};

/// Compiles every mesh (a colliding mesh geom needs the convex hull).
pub(super) fn compile(
    spec: &mut ModelSpec,
    opts: &CompilerOpts,
    gspecs: &[Geom],
    geom_mesh: &[Option<usize>],
) -> Result<Vec<Mesh>, CError> {
    let mut needhull = vec![false; spec.meshes.len()];
    for (g, m) in gspecs.iter().zip(geom_mesh) {
        if let Some(m) = m {
            if g.kind == MESH && (g.contype != 0 || g.conaffinity != 0) {
                needhull[*m] = true;
            }
        }
    }
    let mesh_opts = mesh::MeshOpts {
        convexhull: opts.convexhull,
        exactmeshinertia: opts.exactmeshinertia,
    };
    let mut meshes = Vec::with_capacity(spec.meshes.len());
    for (id, m) in spec.meshes.iter_mut().enumerate() {
        meshes.push(
            mesh::compile(m, &mesh_opts, needhull[id])
                .map_err(|e| CError::at(e, &m.name, id, m.line))?,
        );
        // the file's bytes are read: free them before the next mesh (a lower load peak)
        m.bytes = None;
    }
    Ok(meshes)
}

impl Compiled {
    pub(super) fn fill_meshes(&self, m: &mut ModelMut) {
        let (mut vadr, mut tadr, mut fadr, mut gadr) = (0usize, 0usize, 0usize, 0usize);
        for (i, mesh) in self.meshes.iter().enumerate() {
            let (nv, nf) = (mesh.vert.len() / 3, mesh.face.len() / 3);
            m.mesh_vertadr[i] = vadr as i32;
            m.mesh_vertnum[i] = nv as i32;
            m.mesh_texcoordadr[i] = if mesh.texcoord.is_empty() {
                -1
            } else {
                tadr as i32
            };
            m.mesh_faceadr[i] = fadr as i32;
            m.mesh_facenum[i] = nf as i32;
            m.mesh_graphadr[i] = if mesh.graph.is_empty() {
                -1
            } else {
                gadr as i32
            };
            m.mesh_vert[3 * vadr..3 * (vadr + nv)].copy_from_slice(&mesh.vert);
            m.mesh_normal[3 * vadr..3 * (vadr + nv)].copy_from_slice(&mesh.normal[..3 * nv]);
            m.mesh_face[3 * fadr..3 * (fadr + nf)].copy_from_slice(&mesh.face);
            let nt = mesh.texcoord.len();
            m.mesh_texcoord[2 * tadr..2 * tadr + nt].copy_from_slice(&mesh.texcoord);
            let ng = mesh.graph.len();
            m.mesh_graph[gadr..gadr + ng].copy_from_slice(&mesh.graph);
            vadr += nv;
            fadr += nf;
            tadr += nt / 2;
            gadr += ng;
        }
        for (g, mesh) in self.geom_mesh.iter().enumerate() {
            if let (Some(id), true) = (mesh, self.geoms[g].out.mesh_kept) {
                m.geom_dataid[g] = *id as i32;
            }
        }
    }
}
