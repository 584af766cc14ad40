//! Model sizes: object counts, array lengths, the dof tree's nM and nD, the stack.

use super::*;

impl Compiled {
    pub(super) fn count_sizes(
        &mut self,
        nconmax: i32,
        njmax: i32,
        nuserdata: i32,
        nstack: i32,
    ) -> Result<(), CError> {
        let nnames = self.count_names();
        let Compiled {
            header: h,
            bodies,
            joints,
            geoms,
            sites,
            cameras,
            lights,
            keys,
            sensors: csensors,
            actuators,
            meshes,
            skins,
            hfields,
            textures,
            materials,
            pairs,
            equalities,
            tendons,
            excludes,
            custom,
            nuser,
            ..
        } = self;
        h.nbody = bodies.len() as i32;
        h.njnt = joints.len() as i32;
        h.ngeom = geoms.len() as i32;
        h.nsite = sites.len() as i32;
        h.ncam = cameras.len() as i32;
        h.nlight = lights.len() as i32;
        h.nkey = keys.len() as i32;
        h.nsensor = csensors.len() as i32;
        let nsensordata: i64 = csensors.iter().map(|s| s.dim as i64).sum();
        if nsensordata > i32::MAX as i64 {
            return Err(CError::msg("could not create mjData"));
        }
        h.nsensordata = nsensordata as i32;
        h.nq = joints.iter().map(|j| j.spec.kind.nq()).sum::<usize>() as i32;
        h.nv = joints.iter().map(|j| j.spec.kind.nv()).sum::<usize>() as i32;
        for a in actuators.iter() {
            if a.dyntype == 0 && h.na > 0 {
                return Err(CError::msg(
                    "stateless actuators must come before stateful actuators",
                ));
            }
            h.nu += 1;
            h.na += (a.dyntype != 0) as i32;
        }
        h.nmesh = meshes.len() as i32;
        for m in meshes.iter() {
            h.nmeshvert += (m.vert.len() / 3) as i32;
            h.nmeshface += (m.face.len() / 3) as i32;
            h.nmeshtexvert += (m.texcoord.len() / 2) as i32;
            h.nmeshgraph += m.graph.len() as i32;
        }
        crate::compiler::skin::sizes(skins, h);
        h.nhfield = hfields.len() as i32;
        h.nhfielddata = hfields.iter().map(|h| h.nrow * h.ncol).sum();
        h.ntex = textures.len() as i32;
        h.ntexdata = textures.iter().map(|t| t.3.len() as i32).sum();
        h.nmat = materials.len() as i32;
        h.npair = pairs.len() as i32;
        h.neq = equalities.len() as i32;
        h.ntendon = tendons.len() as i32;
        h.nwrap = tendons.iter().map(|t| t.wraps.len() as i32).sum();
        h.nemax = equalities
            .iter()
            .map(|e| [3, 7, 1, 1][e.0.kind as usize])
            .sum();
        h.nexclude = excludes.len() as i32;
        h.nnumeric = custom.numerics.len() as i32;
        h.nnumericdata = custom.numerics.iter().map(|x| x.2.len() as i32).sum();
        h.ntext = custom.texts.len() as i32;
        h.ntextdata = custom.texts.iter().map(|x| x.2.len() as i32 + 1).sum();
        h.ntuple = custom.tuples.len() as i32;
        h.ntupledata = custom.tuples.iter().map(|x| x.2.len() as i32).sum();
        h.nnames = nnames as i32;
        h.nconmax = if nconmax < 0 { 100 } else { nconmax };
        h.njmax = if njmax < 0 { 500 } else { njmax };
        h.nuserdata = nuserdata;
        for b in bodies.iter_mut() {
            if b.spec.mocap {
                b.mocapid = h.nmocap;
                h.nmocap += 1;
            }
        }
        [
            h.nuser_body,
            h.nuser_jnt,
            h.nuser_geom,
            h.nuser_site,
            h.nuser_cam,
            h.nuser_tendon,
            h.nuser_actuator,
            h.nuser_sensor,
        ] = nuser.map(|x| x as i32);

        // dof tree: nM, nD
        let mut dof_parent: Vec<i32> = Vec::new();
        let mut lastdof = vec![-1i32; bodies.len()];
        for (i, b) in bodies.iter().enumerate() {
            lastdof[i] = if i == 0 { -1 } else { lastdof[b.parent] };
            for &j in &b.joints {
                for _ in 0..joints[j].spec.kind.nv() {
                    dof_parent.push(lastdof[i]);
                    lastdof[i] = dof_parent.len() as i32 - 1;
                }
            }
        }
        let mut nm = 0;
        for i in 0..dof_parent.len() {
            let mut j = i as i32;
            while j >= 0 {
                nm += 1;
                j = dof_parent[j as usize];
            }
        }
        h.nM = nm;
        h.nD = 2 * nm - h.nv;

        // stack: user value or heuristic
        h.nstack = if nstack > 0 {
            nstack
        } else {
            let a = (h.njmax + h.neq + h.nv) as i64;
            let b = (h.nq
                + h.nv
                + h.nu
                + h.na
                + h.nbody
                + h.njnt
                + h.ngeom
                + h.nsite
                + h.neq
                + h.ntendon
                + h.nwrap) as i64;
            (5 * a * a + 20 * b).clamp(1000, i32::MAX as i64) as i32
        };
        Ok(())
    }
}
