//! Bodies with their joints, geoms and sites: compiled body by body in tree order, then the
//! body, joint, dof, geom and site arrays.

use super::cameras_lights::{compile_camera, compile_light};
use super::*;
use crate::compiler::mesh::Mesh;

/// Compiles the bodies in tree order; returns the compiled geoms and sites.
#[allow(clippy::too_many_arguments)]
pub(super) fn compile(
    bodies: &mut [FBody],
    joints: &mut [FJoint],
    gspecs: &[Geom],
    sspecs: &[(Site, usize)],
    cameras: &mut [(Camera, usize)],
    lights: &mut [(Light, usize)],
    nuser: &[usize; 8],
    opts: &CompilerOpts,
    settings: &Settings,
    hfields: &[HField],
    geom_hfield: &[Option<usize>],
    geom_mesh: &[Option<usize>],
    meshes: &[Mesh],
) -> Result<(Vec<FGeom>, Vec<FSite>), CError> {
    let mut geoms: Vec<Option<FGeom>> = (0..gspecs.len()).map(|_| None).collect();
    let mut sites: Vec<Option<FSite>> = (0..sspecs.len()).map(|_| None).collect();
    for i in 0..bodies.len() {
        let (name, line) = (bodies[i].spec.name.clone(), bodies[i].spec.line);
        let berr = |msg: String| CError::at(msg, &name, i, line);
        if bodies[i].spec.user.len() > nuser[0] {
            return Err(berr(format!(
                "user has more values than nuser_body in body '{name}' (id = {i})"
            )));
        }
        let b = &mut bodies[i];
        if !defined(b.pos[0]) && !opts.global {
            b.pos = [0.0; 3];
        }
        normalize(&mut b.quat);
        normalize(&mut b.iquat);
        let weldid = b.weldid;
        let children = b.children.clone();
        alt_set(
            &b.spec.alt.clone(),
            &mut b.quat,
            Some(&mut b.inertia),
            settings,
        )
        .map_err(|e| berr(format!("error '{e}' in frame alternative")))?;
        alt_set(
            &b.spec.ialt.clone(),
            &mut b.iquat,
            Some(&mut b.inertia),
            settings,
        )
        .map_err(|e| berr(format!("error '{e}' in inertia alternative")))?;
        for c in children {
            bodies[c].weldid = if bodies[c].joints.is_empty() {
                weldid
            } else {
                c
            };
        }
        let b = &bodies[i];
        let infer =
            i > 0 && (!b.spec.explicit_inertial || opts.inertiafromgeom == InertiaFromGeom::True);
        for &gid in &b.geoms {
            let g = &gspecs[gid];
            if g.user.len() > nuser[2] {
                let m = format!(
                    "user has more values than nuser_geom in geom '{}' (id = {gid})",
                    g.name
                );
                return Err(CError::at(m, &g.name, gid, g.line));
            }
            let assets = GeomAssets {
                hfield: geom_hfield[gid].map(|h| hfields[h].size),
                mesh: geom_mesh[gid].map(|m| &meshes[m]),
                fitaabb: opts.fitaabb,
                exactmeshinertia: opts.exactmeshinertia,
            };
            let out = compile_geom(g, gid, b.weldid == 0, infer, &assets, settings).map_err(
                |e| match e {
                    GeomError::Geom(m) => CError::at(m, &g.name, gid, g.line),
                    GeomError::Mesh(m) => {
                        let mid = geom_mesh[gid].unwrap_or(0);
                        CError::at(m, &meshes[mid].name, mid, meshes[mid].line)
                    }
                },
            )?;
            geoms[gid] = Some(FGeom {
                spec: g.clone(),
                body: i,
                out,
            });
        }
        let b = &mut bodies[i];
        let auto = !defined(b.ipos[0]) && opts.inertiafromgeom == InertiaFromGeom::Auto;
        if i > 0 && (opts.inertiafromgeom == InertiaFromGeom::True || auto) {
            let range = opts.inertiagrouprange;
            let sel: Vec<&GeomOut> = b
                .geoms
                .iter()
                .filter_map(|&g| geoms[g].as_ref())
                .filter(|g| g.spec.group >= range[0] && g.spec.group <= range[1])
                .map(|g| &g.out)
                .collect();
            if let Some((ipos, iquat, mass, inertia)) =
                geom_frame(&sel, settings).map_err(|e| CError::at(e.msg, &name, i, line))?
            {
                (b.ipos, b.iquat, b.mass, b.inertia) = (ipos, iquat, mass, inertia);
            }
        }
        if !defined(b.ipos[0]) && !defined(b.pos[0]) {
            return Err(berr("body pos and ipos are both undefined".into()));
        } else if !defined(b.ipos[0]) {
            b.ipos = b.pos;
            b.iquat = b.quat;
        } else if !defined(b.pos[0]) {
            b.pos = b.ipos;
            b.quat = b.iquat;
        }
        if i > 0 {
            b.mass = b.mass.max(opts.boundmass);
            for x in b.inertia.iter_mut() {
                *x = x.max(opts.boundinertia);
            }
            if b.mass < 0.0 || b.inertia.iter().any(|&x| x < 0.0) {
                return Err(berr("mass and inertia cannot be negative".into()));
            }
            let t = b.inertia;
            if t[0] + t[1] < t[2] || t[0] + t[2] < t[1] || t[1] + t[2] < t[0] {
                if opts.balanceinertia {
                    let avg = (t[0] + t[1] + t[2]) / 3.0;
                    b.inertia = [avg; 3];
                } else {
                    return Err(berr(
                        "inertia must satisfy A + B >= C; use 'balanceinertia' to fix".into(),
                    ));
                }
            }
        }
        let mut dofnum = 0;
        let jids = b.joints.clone();
        for &jid in &jids {
            let j = &mut joints[jid].spec;
            if j.user.len() > nuser[1] {
                let m = format!(
                    "user has more values than nuser_jnt in joint '{}' (id = {jid})",
                    j.name
                );
                return Err(CError::at(m, &j.name, jid, j.line));
            }
            dofnum += compile_joint(j, jid, opts.autolimits, opts.degree)
                .map_err(|m| CError::at(m, &j.name, jid, j.line))?;
        }
        let b = &mut bodies[i];
        b.dofnum = dofnum;
        if dofnum > 6 {
            return Err(berr(format!("more than 6 dofs in body '{name}'")));
        }
        let mut hasball = false;
        for &jid in &jids {
            let k = joints[jid].spec.kind;
            if matches!(k, JointType::Ball | JointType::Hinge) && hasball {
                return Err(berr(format!("ball followed by rotation in body '{name}'")));
            }
            hasball |= k == JointType::Ball;
        }
        if b.spec.mocap && (dofnum > 0 || b.parent != 0) {
            return Err(berr(format!(
                "mocap body '{name}' is not a fixed child of world"
            )));
        }
        for &sid in &b.sites {
            let s = &sspecs[sid].0;
            if s.user.len() > nuser[3] {
                let m = format!(
                    "user has more values than nuser_site in site '{}' (id = {sid})",
                    s.name
                );
                return Err(CError::at(m, &s.name, sid, s.line));
            }
            let out =
                compile_site(s, sid, settings).map_err(|m| CError::at(m, &s.name, sid, s.line))?;
            sites[sid] = Some(FSite {
                spec: s.clone(),
                body: i,
                out,
            });
        }
        for cid in bodies[i].cameras.clone() {
            compile_camera(&mut cameras[cid].0, cid, i, bodies, nuser[4], settings)?;
        }
        for lid in bodies[i].lights.clone() {
            compile_light(&mut lights[lid].0, lid, i, bodies)?;
        }

        // frames so far are in world coordinates when coordinate="global": make them local
        let b = &mut bodies[i];
        (b.gpos, b.gquat) = (b.pos, b.quat);
        if opts.global && i > 0 {
            let (bp, bq) = (b.pos, b.quat);
            let (ip, iq) = (b.ipos, b.iquat);
            b.ipos = local_pos(&ip, &bp, &bq);
            b.iquat = local_quat(&iq, &bq);
            let (pp, pq) = (
                bodies[bodies[i].parent].gpos,
                bodies[bodies[i].parent].gquat,
            );
            let b = &mut bodies[i];
            b.pos = local_pos(&bp, &pp, &pq);
            b.quat = local_quat(&bq, &pq);
        }
        if opts.global {
            let (bp, bq) = (bodies[i].gpos, bodies[i].gquat);
            for &g in &bodies[i].geoms {
                if let Some(g) = geoms[g].as_mut() {
                    g.out.pos = local_pos(&g.out.pos, &bp, &bq);
                    g.out.quat = local_quat(&g.out.quat, &bq);
                }
            }
            for &j in &bodies[i].joints {
                let j = &mut joints[j].spec;
                if j.kind != JointType::Free {
                    j.pos = local_pos(&j.pos, &bp, &bq);
                }
                j.axis = local_axis(&j.axis, &bq);
            }
            for &s in &bodies[i].sites {
                if let Some(s) = sites[s].as_mut() {
                    s.out.pos = local_pos(&s.out.pos, &bp, &bq);
                    s.out.quat = local_quat(&s.out.quat, &bq);
                }
            }
            for &c in &bodies[i].cameras {
                let c = &mut cameras[c].0;
                c.pos = local_pos(&c.pos, &bp, &bq);
                c.quat = local_quat(&c.quat, &bq);
            }
            for &l in &bodies[i].lights {
                let l = &mut lights[l].0;
                l.pos = local_pos(&l.pos, &bp, &bq);
                // 2.2.2 rotates the direction by the conjugate of the light's local rotation
                let lq = local_quat(&[1.0, 0.0, 0.0, 0.0], &bq);
                l.dir = mat_vec(&quat2mat(&conj(&lq)), &l.dir);
            }
        }
    }
    let geoms: Vec<FGeom> = geoms.into_iter().flatten().collect();
    let sites: Vec<FSite> = sites.into_iter().flatten().collect();
    Ok((geoms, sites))
}

impl Compiled {
    /// Moving bodies need mass and inertia (or a static child that has them); a free joint
    /// stands alone in a child of the world.
    pub(super) fn check_tree(&self) -> Result<(), CError> {
        let (bodies, joints) = (&self.bodies, &self.joints);
        let heavy = |b: &FBody| b.mass >= MINVAL && b.inertia.iter().all(|&x| x >= MINVAL);
        for (i, b) in bodies.iter().enumerate().skip(1) {
            if !b.joints.is_empty()
                && !heavy(b)
                && !b
                    .children
                    .iter()
                    .any(|&c| bodies[c].joints.is_empty() && heavy(&bodies[c]))
            {
                let msg =
                    "mass and inertia of moving bodies must be larger than mjMINVAL".to_string();
                return Err(CError::at(msg, &b.spec.name, i, b.spec.line));
            }
        }
        for (bi, b) in bodies.iter().enumerate() {
            for &j in &b.joints {
                if joints[j].spec.kind == JointType::Free && (b.joints.len() > 1) {
                    return Err(CError::at(
                        "free joint can only appear by itself".into(),
                        &b.spec.name,
                        bi,
                        b.spec.line,
                    ));
                }
                if joints[j].spec.kind == JointType::Free && b.parent != 0 {
                    return Err(CError::at(
                        "free joint can only be used on top level".into(),
                        &b.spec.name,
                        bi,
                        b.spec.line,
                    ));
                }
            }
        }
        Ok(())
    }

    pub(super) fn fill_tree(&self, m: &mut ModelMut) {
        let h = &self.header;
        let (mut jntadr, mut dofadr, mut qposadr) = (0usize, 0usize, 0usize);
        let mut lastdof = vec![-1i32; self.bodies.len()];
        let [nub, nuj, nug, nus, ..] = self.nuser;
        for (i, b) in self.bodies.iter().enumerate() {
            m.body_parentid[i] = b.parent as i32;
            m.body_weldid[i] = b.weldid as i32;
            m.body_mocapid[i] = b.mocapid;
            m.body_jntnum[i] = b.joints.len() as i32;
            m.body_jntadr[i] = if b.joints.is_empty() {
                -1
            } else {
                jntadr as i32
            };
            m.body_dofnum[i] = b.dofnum as i32;
            m.body_dofadr[i] = if b.dofnum > 0 { dofadr as i32 } else { -1 };
            m.body_geomnum[i] = b.geoms.len() as i32;
            m.body_geomadr[i] = b.geoms.first().map_or(-1, |&g| g as i32);
            let (pos, quat) = if i > 0 {
                (b.pos, b.quat)
            } else {
                ([0.0; 3], [1.0, 0.0, 0.0, 0.0])
            };
            let (ipos, iquat) = if i > 0 {
                (b.ipos, b.iquat)
            } else {
                ([0.0; 3], [1.0, 0.0, 0.0, 0.0])
            };
            put(m.body_pos, i, &pos);
            put(m.body_quat, i, &quat);
            put(m.body_ipos, i, &ipos);
            put(m.body_iquat, i, &iquat);
            m.body_mass[i] = b.mass;
            put(m.body_inertia, i, &b.inertia);
            let mut user = b.spec.user.clone();
            user.resize(nub, 0.0);
            put(m.body_user, i, &user);
            m.body_rootid[i] = if i == 0 || b.parent == 0 {
                i as i32
            } else {
                m.body_rootid[b.parent]
            };
            lastdof[i] = if i == 0 { -1 } else { lastdof[b.parent] };
            m.body_sameframe[i] = null_pose(&ipos, Some(&iquat)) as u8;
            let p = b.parent;
            m.body_simple[i] = (m.body_sameframe[i] != 0
                && (m.body_rootid[i] == i as i32
                    || (m.body_parentid[p] == 0 && m.body_dofnum[p] == 0)))
                as u8;
            if m.body_parentid[i] > 0 {
                m.body_simple[p] = 0;
            }
            let mut rotfound = false;
            for &jid in &b.joints {
                let j = &self.joints[jid].spec;
                m.jnt_type[jid] = j.kind as i32;
                m.jnt_group[jid] = j.group;
                m.jnt_limited[jid] = j.limited as u8;
                m.jnt_qposadr[jid] = qposadr as i32;
                m.jnt_dofadr[jid] = dofadr as i32;
                m.jnt_bodyid[jid] = self.joints[jid].body as i32;
                put(m.jnt_pos, jid, &j.pos);
                put(m.jnt_axis, jid, &j.axis);
                m.jnt_stiffness[jid] = j.stiffness;
                put(m.jnt_range, jid, &j.range);
                put(m.jnt_solref, jid, &j.solref_limit);
                put(m.jnt_solimp, jid, &j.solimp_limit);
                m.jnt_margin[jid] = j.margin;
                let mut user = j.user.clone();
                user.resize(nuj, 0.0);
                put(m.jnt_user, jid, &user);
                let axis_count = j.axis.iter().filter(|&&a| a != 0.0).count();
                if rotfound
                    || !null_pose(&j.pos, None)
                    || (matches!(j.kind, JointType::Hinge | JointType::Slide) && axis_count > 1)
                {
                    m.body_simple[i] = 0;
                }
                rotfound |= matches!(j.kind, JointType::Ball | JointType::Hinge);
                let q = qposadr;
                match j.kind {
                    JointType::Free => {
                        m.qpos0[q..q + 3].copy_from_slice(&b.gpos);
                        m.qpos0[q + 3..q + 7].copy_from_slice(&b.gquat);
                        let v: Vec<f64> = m.qpos0[q..q + 7].to_vec();
                        m.qpos_spring[q..q + 7].copy_from_slice(&v);
                    }
                    JointType::Ball => {
                        m.qpos0[q..q + 4].copy_from_slice(&[1.0, 0.0, 0.0, 0.0]);
                        m.qpos_spring[q..q + 4].copy_from_slice(&[1.0, 0.0, 0.0, 0.0]);
                    }
                    _ => {
                        m.qpos0[q] = j.reference;
                        m.qpos_spring[q] = j.springref;
                    }
                }
                for _ in 0..j.kind.nv() {
                    m.dof_bodyid[dofadr] = i as i32;
                    m.dof_jntid[dofadr] = jid as i32;
                    put(m.dof_solref, dofadr, &j.solref_friction);
                    put(m.dof_solimp, dofadr, &j.solimp_friction);
                    m.dof_frictionloss[dofadr] = j.frictionloss;
                    m.dof_armature[dofadr] = j.armature;
                    m.dof_damping[dofadr] = j.damping;
                    m.dof_parentid[dofadr] = lastdof[i];
                    lastdof[i] = dofadr as i32;
                    dofadr += 1;
                }
                jntadr += 1;
                qposadr += j.kind.nq();
            }
            for &gid in &b.geoms {
                let g = &self.geoms[gid];
                let s = &g.spec;
                m.geom_type[gid] = s.kind;
                m.geom_contype[gid] = s.contype;
                m.geom_conaffinity[gid] = s.conaffinity;
                m.geom_condim[gid] = s.condim;
                m.geom_bodyid[gid] = g.body as i32;
                m.geom_dataid[gid] = -1;
                put(m.geom_fluid, gid, &g.out.fluid);
                m.geom_matid[gid] = -1;
                m.geom_group[gid] = s.group;
                m.geom_priority[gid] = s.priority;
                put(m.geom_size, gid, &g.out.size);
                put(m.geom_pos, gid, &g.out.pos);
                put(m.geom_quat, gid, &g.out.quat);
                put(m.geom_friction, gid, &s.friction);
                m.geom_solmix[gid] = s.solmix;
                put(m.geom_solref, gid, &s.solref);
                put(m.geom_solimp, gid, &s.solimp);
                m.geom_margin[gid] = s.margin;
                m.geom_gap[gid] = s.gap;
                let mut user = s.user.clone();
                user.resize(nug, 0.0);
                put(m.geom_user, gid, &user);
                put(m.geom_rgba, gid, &s.rgba);
                m.geom_sameframe[gid] = if null_pose(&g.out.pos, Some(&g.out.quat)) {
                    1
                } else if g.out.pos == b.ipos && g.out.quat == b.iquat {
                    2
                } else {
                    0
                };
                m.geom_rbound[gid] = rbound(s.kind, &g.out.size);
            }
            for &sid in &b.sites {
                let st = &self.sites[sid];
                let s = &st.spec;
                m.site_type[sid] = s.kind;
                m.site_bodyid[sid] = st.body as i32;
                m.site_matid[sid] = -1;
                m.site_group[sid] = s.group;
                put(m.site_size, sid, &st.out.size);
                put(m.site_pos, sid, &st.out.pos);
                put(m.site_quat, sid, &st.out.quat);
                let mut user = s.user.clone();
                user.resize(nus, 0.0);
                put(m.site_user, sid, &user);
                put(m.site_rgba, sid, &s.rgba);
                m.site_sameframe[sid] = if null_pose(&st.out.pos, Some(&st.out.quat)) {
                    1
                } else if st.out.pos == b.ipos && st.out.quat == b.iquat {
                    2
                } else {
                    0
                };
            }
        }
        let nv = h.nv as usize;
        let mut nm = 0;
        for i in 0..nv {
            m.dof_Madr[i] = nm;
            let mut j = i as i32;
            while j >= 0 {
                nm += 1;
                j = m.dof_parentid[j as usize];
            }
        }
        let mut scnt = 0;
        for i in (0..nv).rev() {
            if m.body_simple[m.dof_bodyid[i] as usize] != 0 {
                scnt += 1;
                m.dof_simplenum[i] = scnt;
            } else {
                scnt = 0;
                m.dof_simplenum[i] = 0;
            }
        }
    }

    /// Scales masses and inertias to `settotalmass`.
    pub(super) fn scale_total_mass(&self, m: &mut ModelMut) {
        if self.settotalmass > 0.0 {
            let total: f64 = m.body_mass.iter().skip(1).sum();
            let scale = MINVAL.max(self.settotalmass / MINVAL.max(total));
            for i in 1..self.bodies.len() {
                m.body_mass[i] *= scale;
                for k in 0..3 {
                    m.body_inertia[3 * i + k] *= scale;
                }
            }
        }
    }
}
