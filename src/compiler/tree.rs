//! The kinematic tree and global lists: ids, per-object compilation, sizes, array filling.

use super::frame::*;
use super::objects::*;
use super::spec::*;
use super::CError;
use crate::abi::view::ModelMut;
use crate::abi::{mjModel, mjOption, mjVisual};

mod fuse;

struct FBody {
    spec: Body,
    parent: usize,
    children: Vec<usize>,
    joints: Vec<usize>,
    geoms: Vec<usize>,
    sites: Vec<usize>,
    cameras: Vec<usize>,
    lights: Vec<usize>,
    weldid: usize,
    dofnum: usize,
    mocapid: i32,
    pos: [f64; 3],
    quat: [f64; 4],
    ipos: [f64; 3],
    iquat: [f64; 4],
    mass: f64,
    inertia: [f64; 3],
    /// body frame in world coordinates (differs from pos/quat with coordinate="global")
    gpos: [f64; 3],
    gquat: [f64; 4],
}

struct FGeom {
    spec: Geom,
    body: usize,
    out: GeomOut,
}

struct FSite {
    spec: Site,
    body: usize,
    out: SiteOut,
}

struct FJoint {
    spec: Joint,
    body: usize,
}

/// A compiled model, ready to be copied into an allocated `mjModel`.
pub struct Compiled {
    pub header: mjModel,
    /// options of the actuator length-range computation (`<compiler><lengthrange>`)
    pub lropt: crate::abi::mjLROpt,
    pub option: mjOption,
    pub visual: mjVisual,
    pub stat_override: [f64; 4],
    pub center: [f64; 3],
    modelname: String,
    bodies: Vec<FBody>,
    joints: Vec<FJoint>,
    geoms: Vec<FGeom>,
    sites: Vec<FSite>,
    /// (camera with target resolved into `mode`-independent id, body)
    cameras: Vec<(Camera, usize)>,
    lights: Vec<(Light, usize)>,
    /// (pair, geom ids, body signature), sorted by signature
    pairs: Vec<(Pair, [i32; 2], i32)>,
    /// (name, body signature), sorted by signature
    excludes: Vec<(String, i32)>,
    /// (constraint, object ids)
    equalities: Vec<(Equality, [i32; 2])>,
    tendons: Vec<CTendon>,
    /// (mjtTexture, width, height, RGB bytes)
    textures: Vec<(i32, i32, i32, Vec<u8>)>,
    texture_names: Vec<String>,
    hfields: Vec<HField>,
    skins: Vec<super::skin::CSkin>,
    geom_hfield: Vec<Option<usize>>,
    meshes: Vec<super::mesh::Mesh>,
    geom_mesh: Vec<Option<usize>>,
    materials: Vec<Material>,
    mat_texid: Vec<i32>,
    geom_matid: Vec<i32>,
    site_matid: Vec<i32>,
    tendon_matid: Vec<i32>,
    actuators: Vec<Actuator>,
    sensors: Vec<CSensor>,
    custom: Custom,
    tuple_ids: Vec<Vec<i32>>,
    keys: Vec<Key>,
    trnid: Vec<[i32; 2]>,
    nuser: [usize; 8],
    settotalmass: f64,
}

/// Objects of the tree in 2.2.2's list order (bodies depth-first, each body's objects in turn).
#[derive(Default)]
struct Lists {
    cameras: Vec<(Camera, usize)>,
    lights: Vec<(Light, usize)>,
}

#[allow(clippy::too_many_arguments)]
fn flatten(
    b: Body,
    parent: usize,
    bodies: &mut Vec<FBody>,
    joints: &mut Vec<FJoint>,
    geoms: &mut Vec<Geom>,
    gbody: &mut Vec<usize>,
    sites: &mut Vec<(Site, usize)>,
    lists: &mut Lists,
) -> usize {
    let id = bodies.len();
    let mut spec = b;
    let children = std::mem::take(&mut spec.bodies);
    let mut fb = FBody {
        parent,
        children: Vec::new(),
        joints: Vec::new(),
        geoms: Vec::new(),
        sites: Vec::new(),
        cameras: Vec::new(),
        lights: Vec::new(),
        weldid: 0,
        dofnum: 0,
        mocapid: -1,
        pos: spec.pos,
        quat: spec.quat,
        ipos: spec.ipos,
        iquat: spec.iquat,
        mass: spec.mass,
        inertia: spec.inertia,
        gpos: [0.0; 3],
        gquat: [1.0, 0.0, 0.0, 0.0],
        spec,
    };
    for g in std::mem::take(&mut fb.spec.geoms) {
        fb.geoms.push(geoms.len());
        geoms.push(g);
        gbody.push(id);
    }
    for j in std::mem::take(&mut fb.spec.joints) {
        fb.joints.push(joints.len());
        joints.push(FJoint { spec: j, body: id });
    }
    for s in std::mem::take(&mut fb.spec.sites) {
        fb.sites.push(sites.len());
        sites.push((s, id));
    }
    for c in std::mem::take(&mut fb.spec.cameras) {
        fb.cameras.push(lists.cameras.len());
        lists.cameras.push((c, id));
    }
    for l in std::mem::take(&mut fb.spec.lights) {
        fb.lights.push(lists.lights.len());
        lists.lights.push((l, id));
    }
    bodies.push(fb);
    for c in children {
        let cid = flatten(c, id, bodies, joints, geoms, gbody, sites, lists);
        bodies[id].children.push(cid);
    }
    id
}

fn check_names<'a>(names: impl Iterator<Item = (&'a str, i32)>, what: &str) -> Result<(), CError> {
    let list: Vec<(&str, i32)> = names.collect();
    let mut seen = std::collections::HashSet::new();
    for (i, (name, line)) in list.iter().enumerate() {
        if !name.is_empty() && !seen.insert(*name) {
            return Err(CError::at(
                format!("repeated name in {what} array, position {i}"),
                name,
                i,
                *line,
            ));
        }
    }
    Ok(())
}

fn user_len(lens: impl Iterator<Item = usize>, given: i32) -> usize {
    if given >= 0 {
        given as usize
    } else {
        lens.max().unwrap_or(0)
    }
}

pub fn compile(mut spec: ModelSpec, mut h: mjModel) -> Result<Compiled, CError> {
    let opts = spec.compiler.clone();
    let settings = Settings {
        degree: opts.degree,
        eulerseq: &opts.eulerseq,
    };

    // lists in tree order
    let mut bodies = Vec::new();
    let mut joints = Vec::new();
    let mut gspecs = Vec::new();
    let mut gbody = Vec::new();
    let mut sspecs = Vec::new();
    let mut lists = Lists::default();
    flatten(
        spec.world,
        0,
        &mut bodies,
        &mut joints,
        &mut gspecs,
        &mut gbody,
        &mut sspecs,
        &mut lists,
    );
    let mut cameras = lists.cameras;
    let mut lights = lists.lights;
    let mut actuators = spec.actuators;
    let mut keys = spec.keys;
    while keys.len() < spec.nkey.max(0) as usize {
        keys.push(Key::default());
    }

    check_names(
        bodies.iter().map(|b| (b.spec.name.as_str(), b.spec.line)),
        "body",
    )?;
    check_names(
        joints.iter().map(|j| (j.spec.name.as_str(), j.spec.line)),
        "joint",
    )?;
    check_names(gspecs.iter().map(|g| (g.name.as_str(), g.line)), "geom")?;
    check_names(sspecs.iter().map(|s| (s.0.name.as_str(), s.0.line)), "site")?;
    check_names(
        cameras.iter().map(|c| (c.0.name.as_str(), c.0.line)),
        "camera",
    )?;
    check_names(
        lights.iter().map(|l| (l.0.name.as_str(), l.0.line)),
        "light",
    )?;
    check_names(
        spec.meshes.iter().map(|m| (m.name.as_str(), m.line)),
        "mesh",
    )?;
    check_names(spec.skins.iter().map(|s| (s.name.as_str(), s.line)), "skin")?;
    check_names(
        spec.hfields.iter().map(|h| (h.name.as_str(), h.line)),
        "hfield",
    )?;
    check_names(
        spec.textures.iter().map(|t| (t.name.as_str(), t.line)),
        "texture",
    )?;
    check_names(
        spec.materials.iter().map(|m| (m.name.as_str(), m.line)),
        "material",
    )?;
    check_names(spec.pairs.iter().map(|p| (p.name.as_str(), p.line)), "pair")?;
    check_names(
        spec.excludes.iter().map(|e| (e.name.as_str(), e.line)),
        "exclude",
    )?;
    check_names(
        spec.equalities.iter().map(|e| (e.name.as_str(), e.line)),
        "equality",
    )?;
    check_names(
        spec.tendons.iter().map(|t| (t.name.as_str(), t.line)),
        "tendon",
    )?;
    check_names(
        actuators.iter().map(|a| (a.name.as_str(), a.line)),
        "actuator",
    )?;
    let sensors = spec.sensors;
    check_names(sensors.iter().map(|s| (s.name.as_str(), -1)), "sensor")?;
    let custom = spec.custom;
    check_names(
        custom.numerics.iter().map(|x| (x.0.as_str(), x.1)),
        "numeric",
    )?;
    check_names(custom.texts.iter().map(|x| (x.0.as_str(), x.1)), "text")?;
    check_names(custom.tuples.iter().map(|x| (x.0.as_str(), x.1)), "tuple")?;
    check_names(keys.iter().map(|k| (k.name.as_str(), -1)), "key")?;

    let n = &spec.nuser;
    let nuser = [
        user_len(bodies.iter().map(|b| b.spec.user.len()), n[0]),
        user_len(joints.iter().map(|j| j.spec.user.len()), n[1]),
        user_len(gspecs.iter().map(|g| g.user.len()), n[2]),
        user_len(sspecs.iter().map(|s| s.0.user.len()), n[3]),
        user_len(cameras.iter().map(|c| c.0.user.len()), n[4]),
        user_len(spec.tendons.iter().map(|t| t.user.len()), n[5]),
        user_len(actuators.iter().map(|a| a.user.len()), n[6]),
        user_len(sensors.iter().map(|s| s.user.len()), n[7]),
    ];

    // asset names, then references to assets
    // unnamed assets take the name of their file, without directory and extension
    let file_name = |file: &str| {
        let base = file.rsplit(['/', '\\']).next().unwrap_or("");
        match base.rfind('.') {
            Some(dot) => base[..dot].to_string(),
            None => base.to_string(),
        }
    };
    for (id, m) in spec.meshes.iter_mut().enumerate() {
        if m.name.is_empty() {
            m.name = file_name(&m.file);
            if m.name.is_empty() {
                return Err(CError::at("empty name in mesh".into(), &m.name, id, m.line));
            }
        }
    }
    for (id, hf) in spec.hfields.iter_mut().enumerate() {
        if hf.name.is_empty() {
            hf.name = file_name(&hf.file);
            if hf.name.is_empty() {
                let msg = "empty name in height field".into();
                return Err(CError::at(msg, &hf.name, id, hf.line));
            }
        }
    }
    for (id, t) in spec.textures.iter_mut().enumerate() {
        if t.name.is_empty() {
            t.name = file_name(&t.file_names[0]);
            if t.name.is_empty() && t.kind != 2 {
                return Err(CError::at(
                    "empty name in texture".into(),
                    &t.name,
                    id,
                    t.line,
                ));
            }
        }
    }
    for (id, m) in spec.materials.iter().enumerate() {
        if m.name.is_empty() {
            return Err(CError::at(
                "empty name in material".into(),
                &m.name,
                id,
                m.line,
            ));
        }
    }
    let find_mat = |n: &str| spec.materials.iter().position(|m| m.name == n);
    let mut geom_hfield: Vec<Option<usize>> = vec![None; gspecs.len()];
    let mut geom_mesh: Vec<Option<usize>> = vec![None; gspecs.len()];
    let mut geom_matid = vec![-1; gspecs.len()];
    for (i, g) in gspecs.iter().enumerate() {
        let missing = |what: &str, n: &str| {
            CError::at(
                format!("{what} '{n}' not found in geom {i}"),
                &g.name,
                i,
                g.line,
            )
        };
        if !g.material.is_empty() {
            let m = find_mat(&g.material).ok_or_else(|| missing("material", &g.material))?;
            geom_matid[i] = m as i32;
        }
        if !g.mesh.is_empty() {
            let m = spec.meshes.iter().position(|m| m.name == g.mesh);
            geom_mesh[i] = Some(m.ok_or_else(|| missing("mesh", &g.mesh))?);
        }
        if !g.hfield.is_empty() {
            let h = spec.hfields.iter().position(|h| h.name == g.hfield);
            geom_hfield[i] = Some(h.ok_or_else(|| missing("hfield", &g.hfield))?);
        }
    }
    let mut site_matid = vec![-1; sspecs.len()];
    for (i, (s, _)) in sspecs.iter().enumerate() {
        if !s.material.is_empty() {
            let m = find_mat(&s.material).ok_or_else(|| {
                CError::at(
                    format!("material '{}' not found in site {i}", s.material),
                    &s.name,
                    i,
                    s.line,
                )
            })?;
            site_matid[i] = m as i32;
        }
    }
    let mut tendon_matid = vec![-1; spec.tendons.len()];
    for (i, t) in spec.tendons.iter().enumerate() {
        if !t.material.is_empty() {
            let m = find_mat(&t.material).ok_or_else(|| {
                CError::at(
                    format!("material '{}' not found in tendon {i}", t.material),
                    &t.name,
                    i,
                    t.line,
                )
            })?;
            tendon_matid[i] = m as i32;
        }
    }
    let mut mat_texid = vec![-1; spec.materials.len()];
    for (i, m) in spec.materials.iter().enumerate() {
        if !m.texture.is_empty() {
            let t = spec
                .textures
                .iter()
                .position(|t| t.name == m.texture)
                .ok_or_else(|| {
                    CError::at(
                        format!("texture '{}' not found in material {i}", m.texture),
                        &m.name,
                        i,
                        m.line,
                    )
                })?;
            mat_texid[i] = t as i32;
        }
    }

    // meshes (a colliding mesh geom needs the convex hull)
    let mut needhull = vec![false; spec.meshes.len()];
    for (g, m) in gspecs.iter().zip(&geom_mesh) {
        if let Some(m) = m {
            if g.kind == MESH && (g.contype != 0 || g.conaffinity != 0) {
                needhull[*m] = true;
            }
        }
    }
    let mesh_opts = super::mesh::MeshOpts {
        convexhull: opts.convexhull,
        exactmeshinertia: opts.exactmeshinertia,
    };
    let mut meshes = Vec::with_capacity(spec.meshes.len());
    for (id, m) in spec.meshes.iter().enumerate() {
        meshes.push(
            super::mesh::compile(m, &mesh_opts, needhull[id])
                .map_err(|e| CError::at(e, &m.name, id, m.line))?,
        );
    }

    // bodies, with their geoms, joints and sites
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
            &settings,
        )
        .map_err(|e| berr(format!("error '{e}' in frame alternative")))?;
        alt_set(
            &b.spec.ialt.clone(),
            &mut b.iquat,
            Some(&mut b.inertia),
            &settings,
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
                hfield: geom_hfield[gid].map(|h| spec.hfields[h].size),
                mesh: geom_mesh[gid].map(|m| &meshes[m]),
                fitaabb: opts.fitaabb,
                exactmeshinertia: opts.exactmeshinertia,
            };
            let out = compile_geom(g, gid, b.weldid == 0, infer, &assets, &settings).map_err(
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
                geom_frame(&sel, &settings).map_err(|e| CError::at(e.msg, &name, i, line))?
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
                compile_site(s, sid, &settings).map_err(|m| CError::at(m, &s.name, sid, s.line))?;
            sites[sid] = Some(FSite {
                spec: s.clone(),
                body: i,
                out,
            });
        }
        for cid in bodies[i].cameras.clone() {
            compile_camera(&mut cameras[cid].0, cid, i, &bodies, nuser[4], &settings)?;
        }
        for lid in bodies[i].lights.clone() {
            compile_light(&mut lights[lid].0, lid, i, &bodies)?;
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
    let mut geoms: Vec<FGeom> = geoms.into_iter().flatten().collect();
    let mut sites: Vec<FSite> = sites.into_iter().flatten().collect();

    let skins = {
        let body = |n: &str| find_body(&bodies, n);
        let mats = &spec.materials;
        let matid = |n: &str| mats.iter().position(|m| m.name == n);
        super::skin::compile(std::mem::take(&mut spec.skins), &body, &matid)?
    };

    // height fields: elevation is all zero without a file
    for (id, hf) in spec.hfields.iter_mut().enumerate() {
        let (name, line) = (hf.name.clone(), hf.line);
        let err = |m: String| CError::at(m, &name, id, line);
        if hf.size.iter().any(|&s| s <= 0.0) {
            return Err(err(format!(
                "size parameter is not positive in hfield '{name}' (id = {id})"
            )));
        }
        if !hf.file.is_empty() {
            if hf.nrow != 0 || hf.ncol != 0 {
                return Err(err(format!(
                    "hfield '{name}' (id = {id}) specified from file and manually"
                )));
            }
            let (nrow, ncol, data) = super::image::hfield_file(hf, id).map_err(err)?;
            (hf.nrow, hf.ncol, hf.data) = (nrow as i32, ncol as i32, data);
        }
        if hf.nrow < 1 || hf.ncol < 1 {
            return Err(err(format!("hfield '{name}' (id = {id}) not specified")));
        }
    }
    let hfields = spec.hfields;

    // textures (random marks draw from the C generator seeded as 2.2.2 seeds it)
    let mut rng = super::texture::CRand::new(123);
    let mut textures = Vec::new();
    for (id, t) in spec.textures.iter().enumerate() {
        let err = |m: String| CError::at(m, &t.name, id, t.line);
        let name = &t.name;
        if t.builtin != 0 {
            if t.width < 1 || t.height < 1 {
                return Err(err(format!(
                    "Invalid width or height of builtin texture '{name}' (id {id})"
                )));
            }
            let width = t.width as usize;
            let height = if t.kind != 0 {
                6 * width
            } else {
                t.height as usize
            };
            if width.saturating_mul(height) > (i32::MAX / 3) as usize {
                return Err(err(format!(
                    "Could not allocate memory for texture '{name}' (id {id})"
                )));
            }
            let rgb = super::texture::builtin(t, width, height, &mut rng);
            textures.push((t.kind, width as i32, height as i32, rgb));
        } else if !t.file_names[0].is_empty() || (t.kind != 0 && t.files) {
            let (w, h, rgb) = super::image::texture_files(t, id).map_err(err)?;
            textures.push((t.kind, w as i32, h as i32, rgb));
        } else if t.kind == 0 {
            return Err(err(format!(
                "Cannot load 2D texture from separate files, texture '{name}' (id {id})"
            )));
        } else {
            return Err(err(format!(
                "No cubefiles defined in cube or skybox texture '{name}' (id {id})"
            )));
        }
    }
    let materials = spec.materials;

    // contact pairs and exclusions, sorted by body signature
    let signature = |b1: usize, b2: usize| (((b1 + 1) << 16) + b2 + 1) as i32;
    let mut pairs = Vec::new();
    for (id, p) in spec.pairs.into_iter().enumerate() {
        let perr = |m: String| CError::at(m, &p.name, id, p.line);
        if ![1, 3, 4, 6].contains(&p.condim) {
            return Err(perr(format!("invalid condim in collision {id}")));
        }
        let find = |n: &str| geoms.iter().position(|g| g.spec.name == n);
        let Some(mut g1) = find(&p.geom1) else {
            return Err(perr(format!(
                "geom '{}' not found in collision {id}",
                p.geom1
            )));
        };
        let Some(mut g2) = find(&p.geom2) else {
            return Err(perr(format!(
                "geom '{}' not found in collision {id}",
                p.geom2
            )));
        };
        if geoms[g1].body > geoms[g2].body {
            std::mem::swap(&mut g1, &mut g2);
        }
        let sig = signature(geoms[g1].body, geoms[g2].body);
        pairs.push((p, [g1 as i32, g2 as i32], sig));
    }
    let mut excludes = Vec::new();
    for (id, e) in spec.excludes.into_iter().enumerate() {
        let find = |n: &str| find_body(&bodies, n);
        let missing = |n: &str| {
            CError::at(
                format!("body '{n}' not found in bodypair {id}"),
                &e.name,
                id,
                e.line,
            )
        };
        let b1 = find(&e.body1).ok_or_else(|| missing(&e.body1))?;
        let b2 = find(&e.body2).ok_or_else(|| missing(&e.body2))?;
        excludes.push((e.name.clone(), signature(b1.min(b2), b1.max(b2))));
    }
    pairs.sort_by_key(|p| p.2);
    excludes.sort_by_key(|e| e.1);

    // equality constraints
    let mut equalities = Vec::new();
    for (id, mut e) in spec.equalities.into_iter().enumerate() {
        let name = e.name.clone();
        let err = |m: String| CError::at(m, &name, id, e.line);
        let find = |n: &str| -> Option<usize> {
            match e.kind {
                0 | 1 => find_body(&bodies, n),
                2 => joints.iter().position(|j| j.spec.name == n),
                3 => spec.tendons.iter().position(|t| t.name == n),
                _ => None,
            }
        };
        if !(0..=3).contains(&e.kind) {
            return Err(err(format!(
                "invalid type in equality constraint '{name}' (id = {id})'"
            )));
        }
        let o1 = find(&e.name1).ok_or_else(|| {
            err(format!(
                "unknown element '{}' in equality constraint {id}",
                e.name1
            ))
        })?;
        let mut o2 = -1i32;
        if !e.name2.is_empty() {
            o2 = find(&e.name2).ok_or_else(|| {
                err(format!(
                    "unknown element '{}' in equality constraint {id}",
                    e.name2
                ))
            })? as i32;
        }
        if opts.global && e.kind <= 1 {
            // anchors are given in world coordinates: connect in body1, weld in body2 (if named)
            let frame = if e.kind == 0 {
                Some(o1)
            } else if o2 >= 0 {
                Some(o2 as usize)
            } else {
                None
            };
            if let Some(f) = frame {
                let (bp, bq) = (bodies[f].gpos, bodies[f].gquat);
                let a = local_pos(&[e.data[0], e.data[1], e.data[2]], &bp, &bq);
                e.data[..3].copy_from_slice(&a);
            }
        }
        if e.kind <= 1 && o2 == -1 {
            o2 = 0;
        }
        if o1 as i32 == o2 {
            return Err(err(format!(
                "element '{}' is repeated in equality constraint {id}",
                e.name1
            )));
        }
        if e.kind == 2 {
            let scalar = |k: JointType| matches!(k, JointType::Hinge | JointType::Slide);
            let k2 = if o2 >= 0 {
                joints[o2 as usize].spec.kind
            } else {
                JointType::Hinge
            };
            if !scalar(joints[o1].spec.kind) || !scalar(k2) {
                return Err(err(format!(
                    "only HINGE and SLIDE joint allowed in constraint '{name}' (id = {id})"
                )));
            }
        }
        let _ = &mut e;
        equalities.push((e, [o1 as i32, o2]));
    }

    // tendons
    let mut tendons = Vec::new();
    for (id, t) in spec.tendons.into_iter().enumerate() {
        let wraps = compile_tendon(&t, id, nuser[5], &joints, &geoms, &sites, opts.autolimits)?;
        tendons.push(wraps);
    }

    // actuators
    let mut trnid = Vec::new();
    for (id, a) in actuators.iter_mut().enumerate() {
        let aerr = |m: String| CError::at(m, &a.name.clone(), id, a.line);
        if a.user.len() > nuser[6] {
            return Err(aerr(format!(
                "user has more values than nuser_actuator in actuator '{}' (id = {id})",
                a.name
            )));
        }
        for (lim, range, attr) in [
            (&mut a.forcelimited, a.forcerange, "force"),
            (&mut a.ctrllimited, a.ctrlrange, "ctrl"),
            (&mut a.actlimited, a.actrange, "act"),
        ] {
            if *lim == 2 {
                let hasrange = !(range[0] == 0.0 && range[1] == 0.0);
                if !opts.autolimits && hasrange {
                    return Err(CError::at(
                        limited_msg("actuator", attr),
                        &a.name,
                        id,
                        a.line,
                    ));
                }
                *lim = hasrange as i32;
            }
        }
        let name = a.name.clone();
        let aerr = |m: String| CError::at(m, &name, id, a.line);
        if a.forcerange[0] >= a.forcerange[1] && a.forcelimited != 0 {
            return Err(aerr(format!(
                "invalid force range for actuator '{name}' (id = {id})"
            )));
        }
        if a.ctrlrange[0] >= a.ctrlrange[1] && a.ctrllimited != 0 {
            return Err(aerr(format!(
                "invalid control range for actuator '{name}' (id = {id})"
            )));
        }
        if a.actrange[0] >= a.actrange[1] && a.actlimited != 0 {
            return Err(aerr(format!(
                "invalid activation range for actuator '{name}' (id = {id})"
            )));
        }
        if a.actlimited != 0 && a.dyntype == 0 {
            return Err(aerr(format!(
                "actrange specified but dyntype is 'none' in actuator '{name}' (id = {id})"
            )));
        }
        for (i, prm) in [(2, a.gainprm), (2, a.biasprm)].iter().enumerate() {
            let muscle = if i == 0 {
                a.gaintype == prm.0
            } else {
                a.biastype == prm.0
            };
            if !muscle {
                continue;
            }
            let p = prm.1;
            if p[0] >= p[1] {
                return Err(aerr(format!(
                    "range[0]<range[1] required in muscle '{name}' (id = {id})"
                )));
            }
            if p[4] >= 1.0 || p[5] <= 1.0 {
                return Err(aerr(format!(
                    "lmin<1<lmax required in muscle '{name}' (id = {id})"
                )));
            }
            if p[3] <= 0.0 || p[6] <= 0.0 || p[7] <= 0.0 || p[8] <= 0.0 {
                return Err(aerr(format!(
                    "positive scale, vmax, fpmax, fvmax required in muscle '{name}' (id = {id})"
                )));
            }
        }
        if a.target.is_empty() {
            return Err(aerr(format!(
                "missing transmission target for actuator '{name}' (id = {id})"
            )));
        }
        let find_site = |n: &str| sites.iter().position(|st| st.spec.name == n);
        let missing = |n: &str| {
            aerr(format!(
                "transmission target '{n}' not found in actuator {id}"
            ))
        };
        let ids = match a.trntype {
            0 | 1 => match joints.iter().position(|j| j.spec.name == a.target) {
                Some(j) => [j as i32, -1],
                None => {
                    let t = &a.target;
                    return Err(aerr(format!(
                        "unknown transmission target '{t}' for actuator id = {id}"
                    )));
                }
            },
            2 => {
                if a.slidersite.is_empty() {
                    return Err(aerr(format!(
                        "missing base site for slider-crank '{name}' (id = {id})"
                    )));
                }
                let Some(slider) = find_site(&a.slidersite) else {
                    let ss = &a.slidersite;
                    return Err(aerr(format!(
                        "base site '{ss}' not found for actuator {id}"
                    )));
                };
                if a.cranklength <= 0.0 {
                    return Err(aerr(format!(
                        "crank length must be positive in actuator '{name}' (id = {id})"
                    )));
                }
                [
                    find_site(&a.target).ok_or_else(|| missing(&a.target))? as i32,
                    slider as i32,
                ]
            }
            4 => {
                let mut refsite = -1;
                if !a.refsite.is_empty() {
                    let Some(r) = find_site(&a.refsite) else {
                        let rs = &a.refsite;
                        return Err(aerr(format!(
                            "reference site '{rs}' not found for actuator {id}"
                        )));
                    };
                    refsite = r as i32;
                }
                [
                    find_site(&a.target).ok_or_else(|| missing(&a.target))? as i32,
                    refsite,
                ]
            }
            5 => [
                find_body(&bodies, &a.target).ok_or_else(|| missing(&a.target))? as i32,
                -1,
            ],
            3 => [
                tendons
                    .iter()
                    .position(|t| t.spec.name == a.target)
                    .ok_or_else(|| missing(&a.target))? as i32,
                -1,
            ],
            _ => {
                return Err(aerr(format!(
                    "invalid transmission type in actuator '{name}' (id = {id})"
                )))
            }
        };
        trnid.push(ids);
    }

    // actuator length ranges are computed after set_const (capi load: mj_setLengthRange)

    // sensors
    let mut csensors = Vec::new();
    for (id, s) in sensors.into_iter().enumerate() {
        let find = |objtype: i32, name: &str| -> Option<usize> {
            match objtype {
                1 | 2 => find_body(&bodies, name),
                3 => joints.iter().position(|j| j.spec.name == name),
                5 => geoms.iter().position(|g| g.spec.name == name),
                6 => sites.iter().position(|x| x.spec.name == name),
                7 => cameras.iter().position(|c| c.0.name == name),
                17 => tendons.iter().position(|t| t.spec.name == name),
                8 => lights.iter().position(|l| l.0.name == name),
                18 => actuators.iter().position(|a| a.name == name),
                _ => None,
            }
        };
        let c = compile_sensor(s, id, nuser[7], &find, &joints, &tendons)?;
        csensors.push(c);
    }

    // custom tuples: object ids by type and name
    let mut tuple_ids = Vec::new();
    for (id, (name, line, elems)) in custom.tuples.iter().enumerate() {
        if elems.is_empty() {
            return Err(CError::at(
                format!("tuple '{name}' (id = {id}) is empty"),
                name,
                id,
                *line,
            ));
        }
        let mut ids = Vec::new();
        for (kind, oname, _) in elems {
            let by_name =
                |mut names: std::slice::Iter<'_, &str>| names.position(|n| *n == oname.as_str());
            let found = match kind {
                1 | 2 => find_body(&bodies, oname),
                3 => by_name(
                    joints
                        .iter()
                        .map(|j| j.spec.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                5 => by_name(
                    geoms
                        .iter()
                        .map(|g| g.spec.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                6 => by_name(
                    sites
                        .iter()
                        .map(|s| s.spec.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                7 => by_name(
                    cameras
                        .iter()
                        .map(|c| c.0.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                8 => by_name(
                    lights
                        .iter()
                        .map(|l| l.0.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                11 => by_name(
                    hfields
                        .iter()
                        .map(|h| h.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                12 => by_name(
                    spec.textures
                        .iter()
                        .map(|t| t.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                13 => by_name(
                    materials
                        .iter()
                        .map(|m| m.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                14 => by_name(
                    pairs
                        .iter()
                        .map(|p| p.0.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                15 => by_name(
                    excludes
                        .iter()
                        .map(|e| e.0.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                16 => by_name(
                    equalities
                        .iter()
                        .map(|e| e.0.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                17 => by_name(
                    tendons
                        .iter()
                        .map(|t| t.spec.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                18 => by_name(
                    actuators
                        .iter()
                        .map(|a| a.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                19 => by_name(
                    csensors
                        .iter()
                        .map(|s| s.spec.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                20 => by_name(
                    custom
                        .numerics
                        .iter()
                        .map(|x| x.0.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                21 => by_name(
                    custom
                        .texts
                        .iter()
                        .map(|x| x.0.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                22 => by_name(
                    custom
                        .tuples
                        .iter()
                        .map(|x| x.0.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                23 => by_name(
                    keys.iter()
                        .map(|k| k.name.as_str())
                        .collect::<Vec<&str>>()
                        .iter(),
                ),
                _ => None,
            };
            let Some(found) = found else {
                return Err(CError::at(
                    format!("unrecognized object '{oname}' in tuple {id}"),
                    name,
                    id,
                    *line,
                ));
            };
            ids.push(found as i32);
        }
        tuple_ids.push(ids);
    }

    // static bodies into their parents, when no other object refers to body ids
    let refs = !skins.is_empty()
        || !pairs.is_empty()
        || !excludes.is_empty()
        || !equalities.is_empty()
        || !tendons.is_empty()
        || !actuators.is_empty()
        || !csensors.is_empty()
        || !custom.tuples.is_empty()
        || !cameras.is_empty()
        || !lights.is_empty();
    if opts.fusestatic && !refs {
        fuse::fuse_static(&mut bodies, &mut joints, &mut geoms, &mut sites, &settings)?;
    }

    // sizes
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
    for a in &actuators {
        if a.dyntype == 0 && h.na > 0 {
            return Err(CError::msg(
                "stateless actuators must come before stateful actuators",
            ));
        }
        h.nu += 1;
        h.na += (a.dyntype != 0) as i32;
    }
    let mut nnames = spec.modelname.len() + 1;
    nnames += bodies.iter().map(|b| b.spec.name.len() + 1).sum::<usize>();
    nnames += joints.iter().map(|j| j.spec.name.len() + 1).sum::<usize>();
    nnames += geoms.iter().map(|g| g.spec.name.len() + 1).sum::<usize>();
    nnames += sites.iter().map(|s| s.spec.name.len() + 1).sum::<usize>();
    nnames += cameras.iter().map(|c| c.0.name.len() + 1).sum::<usize>();
    nnames += lights.iter().map(|l| l.0.name.len() + 1).sum::<usize>();
    nnames += meshes.iter().map(|m| m.name.len() + 1).sum::<usize>();
    h.nmesh = meshes.len() as i32;
    for m in &meshes {
        h.nmeshvert += (m.vert.len() / 3) as i32;
        h.nmeshface += (m.face.len() / 3) as i32;
        h.nmeshtexvert += (m.texcoord.len() / 2) as i32;
        h.nmeshgraph += m.graph.len() as i32;
    }
    nnames += skins.iter().map(|s| s.name.len() + 1).sum::<usize>();
    super::skin::sizes(&skins, &mut h);
    nnames += hfields.iter().map(|h| h.name.len() + 1).sum::<usize>();
    h.nhfield = hfields.len() as i32;
    h.nhfielddata = hfields.iter().map(|h| h.nrow * h.ncol).sum();
    nnames += spec
        .textures
        .iter()
        .map(|t| t.name.len() + 1)
        .sum::<usize>();
    nnames += materials.iter().map(|m| m.name.len() + 1).sum::<usize>();
    h.ntex = textures.len() as i32;
    h.ntexdata = textures.iter().map(|t| t.3.len() as i32).sum();
    h.nmat = materials.len() as i32;
    nnames += pairs.iter().map(|p| p.0.name.len() + 1).sum::<usize>();
    nnames += excludes.iter().map(|e| e.0.len() + 1).sum::<usize>();
    h.npair = pairs.len() as i32;
    h.neq = equalities.len() as i32;
    h.ntendon = tendons.len() as i32;
    h.nwrap = tendons.iter().map(|t| t.wraps.len() as i32).sum();
    nnames += tendons.iter().map(|t| t.spec.name.len() + 1).sum::<usize>();
    h.nemax = equalities
        .iter()
        .map(|e| [3, 7, 1, 1][e.0.kind as usize])
        .sum();
    nnames += equalities.iter().map(|e| e.0.name.len() + 1).sum::<usize>();
    h.nexclude = excludes.len() as i32;
    nnames += actuators.iter().map(|a| a.name.len() + 1).sum::<usize>();
    nnames += csensors
        .iter()
        .map(|s| s.spec.name.len() + 1)
        .sum::<usize>();
    nnames += custom.numerics.iter().map(|x| x.0.len() + 1).sum::<usize>();
    nnames += custom.texts.iter().map(|x| x.0.len() + 1).sum::<usize>();
    nnames += custom.tuples.iter().map(|x| x.0.len() + 1).sum::<usize>();
    h.nnumeric = custom.numerics.len() as i32;
    h.nnumericdata = custom.numerics.iter().map(|x| x.2.len() as i32).sum();
    h.ntext = custom.texts.len() as i32;
    h.ntextdata = custom.texts.iter().map(|x| x.2.len() as i32 + 1).sum();
    h.ntuple = custom.tuples.len() as i32;
    h.ntupledata = custom.tuples.iter().map(|x| x.2.len() as i32).sum();
    nnames += keys.iter().map(|k| k.name.len() + 1).sum::<usize>();
    h.nnames = nnames as i32;
    h.nconmax = if spec.nconmax < 0 { 100 } else { spec.nconmax };
    h.njmax = if spec.njmax < 0 { 500 } else { spec.njmax };
    h.nuserdata = spec.nuserdata;
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

    // moving bodies need mass and inertia (or a static child that has them)
    let heavy = |b: &FBody| b.mass >= MINVAL && b.inertia.iter().all(|&x| x >= MINVAL);
    for (i, b) in bodies.iter().enumerate().skip(1) {
        if !b.joints.is_empty()
            && !heavy(b)
            && !b
                .children
                .iter()
                .any(|&c| bodies[c].joints.is_empty() && heavy(&bodies[c]))
        {
            let msg = "mass and inertia of moving bodies must be larger than mjMINVAL".to_string();
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

    // keys: sizes known now
    for (id, k) in keys.iter().enumerate() {
        let kerr = |what: &str, n: i32| {
            CError::at(
                format!("key {id}: invalid {what} size, expected length {n}"),
                &k.name,
                id,
                -1,
            )
        };
        let checks = [
            (&k.qpos, h.nq, "qpos"),
            (&k.qvel, h.nv, "qvel"),
            (&k.act, h.na, "act"),
            (&k.mpos, 3 * h.nmocap, "mpos"),
            (&k.mquat, 4 * h.nmocap, "mquat"),
            (&k.ctrl, h.nu, "ctrl"),
        ];
        for (v, n, what) in checks {
            if !v.is_empty() && v.len() != n as usize {
                return Err(kerr(what, n));
            }
        }
    }

    // stack: user value or heuristic
    h.nstack = if spec.nstack > 0 {
        spec.nstack
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

    let n = &opts.lr_numbers;
    let lropt = crate::abi::mjLROpt {
        mode: opts.lr_mode,
        useexisting: opts.lr_useexisting as i32,
        uselimit: opts.lr_uselimit as i32,
        accel: n[0],
        maxforce: n[1],
        timeconst: n[2],
        timestep: n[3],
        inttotal: n[4],
        inteval: n[5],
        tolrange: n[6],
    };
    Ok(Compiled {
        header: h,
        lropt,
        option: spec.option,
        visual: spec.visual,
        stat_override: spec.stat_override,
        center: spec.center,
        modelname: spec.modelname,
        bodies,
        joints,
        geoms,
        sites,
        cameras,
        lights,
        pairs,
        excludes,
        equalities,
        tendons,
        textures,
        texture_names: spec.textures.iter().map(|t| t.name.clone()).collect(),
        hfields,
        skins,
        geom_hfield,
        meshes,
        geom_mesh,
        materials,
        mat_texid,
        geom_matid,
        site_matid,
        tendon_matid,
        actuators,
        sensors: csensors,
        custom,
        tuple_ids,
        keys,
        trnid,
        nuser,
        settotalmass: opts.settotalmass,
    })
}

fn find_body(bodies: &[FBody], name: &str) -> Option<usize> {
    bodies.iter().position(|b| b.spec.name == name)
}

fn compile_camera(
    c: &mut Camera,
    id: usize,
    body: usize,
    bodies: &[FBody],
    nuser: usize,
    s: &Settings,
) -> Result<(), CError> {
    let name = c.name.clone();
    let err = |m: String| CError::at(m, &name, id, c.line);
    if c.user.len() > nuser {
        return Err(err(format!(
            "user has more values than nuser_cam in camera '{name}' (id = {id})"
        )));
    }
    let alt = c.alt;
    alt_set(&alt, &mut c.quat, None, s).map_err(|e| {
        err(format!(
            "alternative specification error '{e}' in site {id}"
        ))
    })?;
    normalize(&mut c.quat);
    c.user.resize(nuser, 0.0);
    target_id(&c.target, "camera", &name, id, c.line, body, bodies).map(|_| ())
}

/// Body id named by a camera/light `target` (-1 when none).
fn target_id(
    target: &str,
    what: &str,
    name: &str,
    id: usize,
    line: i32,
    body: usize,
    bodies: &[FBody],
) -> Result<i32, CError> {
    let mut tid = -1;
    if !target.is_empty() {
        match find_body(bodies, target) {
            Some(b) => tid = b as i32,
            None => {
                return Err(CError::at(
                    format!("unknown target body in {what} '{name}' (id = {id})"),
                    name,
                    id,
                    line,
                ))
            }
        }
    }
    if tid == body as i32 {
        return Err(CError::at(
            format!("parent-targeting in {what} '{name}' (id = {id})"),
            name,
            id,
            line,
        ));
    }
    Ok(tid)
}

fn compile_light(l: &mut Light, id: usize, body: usize, bodies: &[FBody]) -> Result<(), CError> {
    let nrm2: f64 = l.dir.iter().map(|x| x * x).sum();
    if normalize(&mut l.dir) < MINVAL || nrm2 < EPS {
        return Err(CError::at(
            format!("zero direction in light '{}' (id = {id})", l.name),
            &l.name,
            id,
            l.line,
        ));
    }
    target_id(&l.target, "light", &l.name, id, l.line, body, bodies).map(|_| ())
}

/// A compiled tendon: its description (limits resolved) and path as (mjtWrap, object id, prm).
struct CTendon {
    spec: Tendon,
    wraps: Vec<(i32, i32, f64)>,
}

fn compile_tendon(
    t: &Tendon,
    id: usize,
    nuser: usize,
    joints: &[FJoint],
    geoms: &[FGeom],
    sites: &[FSite],
    autolimits: bool,
) -> Result<CTendon, CError> {
    let name = t.name.as_str();
    let err = |m: String| CError::at(m, name, id, t.line);
    if t.user.len() > nuser {
        return Err(err(format!(
            "user has more values than nuser_tendon in tendon '{name}' (id = {id})"
        )));
    }
    let sz = t.path.len();
    if sz == 0 {
        return Err(err(format!(
            "tendon '{name}' (id = {id}): path cannot be empty"
        )));
    }
    let spatial = t.path[0].kind != 1;
    if spatial && sz < 2 {
        return Err(err(format!(
            "tendon '{name}' (id = {id}): spatial path must contain at least two objects"
        )));
    }
    if spatial && t.width <= 0.0 {
        return Err(err(format!(
            "tendon '{name}' (id = {id}) must have positive width"
        )));
    }
    let mut wraps = Vec::new();
    for (k, w) in t.path.iter().enumerate() {
        let werr = |m: String| CError::at(m, &w.name, k, w.line);
        let find_site = |n: &str| sites.iter().position(|s| s.spec.name == n);
        let wrap = match w.kind {
            1 => {
                let j = joints.iter().position(|j| j.spec.name == w.name);
                let j = j.ok_or_else(|| {
                    werr(format!(
                        "joint '{}' not found in tendon {id}, wrap {k}",
                        w.name
                    ))
                })?;
                (1, j as i32, w.prm)
            }
            4 => {
                let g = geoms.iter().position(|g| g.spec.name == w.name);
                let g = g.ok_or_else(|| {
                    werr(format!(
                        "geom '{}' not found in tendon {id}, wrap {k}",
                        w.name
                    ))
                })?;
                let kind = match geoms[g].spec.kind {
                    CYLINDER => 5,
                    SPHERE => 4,
                    _ => {
                        let m = format!(
                            "geom '{}' in tendon {id}, wrap {k} is not sphere or cylinder",
                            w.name
                        );
                        return Err(werr(m));
                    }
                };
                let mut side = -1;
                if !w.sidesite.is_empty() {
                    let s = find_site(&w.sidesite).ok_or_else(|| {
                        werr(format!(
                            "side site '{}' not found in tendon {id}, wrap {k}",
                            w.sidesite
                        ))
                    })?;
                    side = s as i32;
                }
                (kind, g as i32, side as f64)
            }
            2 => {
                if w.prm < 0.0 {
                    return Err(werr(format!(
                        "pulley has negative divisor in tendon {id}, wrap {k}"
                    )));
                }
                (2, -1, w.prm)
            }
            _ => {
                let s = find_site(&w.name)
                    .ok_or_else(|| werr(format!("site '{}' not found in wrap {k}", w.name)))?;
                (3, s as i32, w.prm)
            }
        };
        wraps.push(wrap);
    }
    for i in 0..sz {
        let kind = wraps[i].0;
        let prev = if i > 0 { wraps[i - 1].0 } else { -1 };
        let next = if i + 1 < sz { wraps[i + 1].0 } else { -1 };
        if !spatial {
            if kind != 1 {
                return Err(err(format!(
                    "tendon '{name}' (id = {id}): spatial object found in fixed path at pos {i}"
                )));
            }
            continue;
        }
        match kind {
            2 => {
                if prev == 2 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): consequtive pulleys (pos {i})"
                    )));
                }
                if i == sz - 1 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): path ends with pulley"
                    )));
                }
            }
            3 => {
                if (i == 0 || prev == 2) && (i == sz - 1 || next == 2) {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): site {i} needs a neighbor that is not a pulley"
                    )));
                }
                if next == 3 && wraps[i].1 == wraps[i + 1].1 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): site {i} is repeated"
                    )));
                }
            }
            4 | 5 => {
                if prev != 3 || next != 3 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): geom at pos {i} not bracketed by sites"
                    )));
                }
            }
            _ => {
                return Err(err(format!(
                    "tendon '{name} (id = {id})': joint wrap found in spatial path at pos {i}"
                )));
            }
        }
    }
    let mut spec = t.clone();
    if spec.limited == 2 {
        let hasrange = !(spec.range[0] == 0.0 && spec.range[1] == 0.0);
        if !autolimits && hasrange {
            return Err(err(limited_msg("tendon", "")));
        }
        spec.limited = hasrange as i32;
    }
    if spec.range[0] >= spec.range[1] && spec.limited != 0 {
        return Err(err(format!(
            "invalid limits in tendon '{name} (id = {id})'"
        )));
    }
    spec.user.resize(nuser, 0.0);
    Ok(CTendon { spec, wraps })
}

/// A compiled sensor.
struct CSensor {
    spec: Sensor,
    objid: i32,
    refid: i32,
    dim: i32,
    datatype: i32,
    needstage: i32,
}

fn compile_sensor(
    mut s: Sensor,
    id: usize,
    nuser: usize,
    find: &dyn Fn(i32, &str) -> Option<usize>,
    joints: &[FJoint],
    tendons: &[CTendon],
) -> Result<CSensor, CError> {
    let name = s.name.clone();
    let err = |m: &str| CError::at(format!("{m} in sensor '{name}' (id = {id})"), &name, id, -1);
    if s.user.len() > nuser {
        return Err(err("user has more values than nuser_sensor"));
    }
    s.user.resize(nuser, 0.0);
    if s.noise < 0.0 {
        return Err(err("negative noise"));
    }
    if s.cutoff < 0.0 {
        return Err(err("negative cutoff"));
    }
    let (mut objid, mut refid) = (-1, -1);
    if s.objtype != 0 {
        if s.objname.is_empty() {
            return Err(err("missing name of sensorized object"));
        }
        objid = find(s.objtype, &s.objname)
            .ok_or_else(|| err("unrecognized name of sensorized object"))? as i32;
    } else if s.kind != 35 {
        return Err(err("invalid type"));
    }
    let frame_obj = |t: i32| matches!(t, 1 | 2 | 5 | 6 | 7);
    if s.reftype != 0 {
        if s.refname.is_empty() {
            return Err(err("missing name of reference frame object"));
        }
        refid = find(s.reftype, &s.refname)
            .ok_or_else(|| err("unrecognized name of reference frame object"))?
            as i32;
        if !frame_obj(s.reftype) {
            return Err(CError::at(
                format!("reference frame object must be (x)body, geom, site or camera: sensor '{name}' (id = {id})"),
                &name,
                id,
                -1,
            ));
        }
    }
    let attached = |what: &str| {
        CError::at(
            format!("sensor must be attached to {what}: sensor '{name}' (id = {id})"),
            &name,
            id,
            -1,
        )
    };
    let joint = |k: i32| {
        joints
            .get(objid.max(0) as usize)
            .map(|j| (j.spec.kind, j.spec.limited))
            .filter(|_| k == 3)
    };
    // (dim, datatype, needstage); stages: 1 pos, 2 vel, 3 acc; datatypes: 0 real, 1 positive, 2 axis, 3 quat
    let stage3 = |k: i32, base: i32| [1, 2, 3][(k - base) as usize];
    let (dim, datatype, needstage) = match s.kind {
        0..=7 => {
            if s.objtype != 6 {
                return Err(attached("site"));
            }
            let (dim, dt) = if s.kind == 0 || s.kind == 7 {
                (1, 1)
            } else {
                (3, 0)
            };
            let stage = match s.kind {
                6 | 7 => 1,
                2 | 3 => 2,
                _ => 3,
            };
            (dim, dt, stage)
        }
        8 | 9 => {
            let Some((kind, _)) = joint(s.objtype) else {
                return Err(attached("joint"));
            };
            if !matches!(kind, JointType::Slide | JointType::Hinge) {
                return Err(err("joint must be slide or hinge"));
            }
            (1, 0, s.kind - 7)
        }
        10 | 11 => {
            if s.objtype != 17 {
                return Err(attached("tendon"));
            }
            (1, 0, s.kind - 9)
        }
        12..=14 => {
            if s.objtype != 18 {
                return Err(attached("actuator"));
            }
            (1, 0, stage3(s.kind, 12))
        }
        15 | 16 => {
            let Some((kind, _)) = joint(s.objtype) else {
                return Err(attached("joint"));
            };
            if kind != JointType::Ball {
                return Err(err("joint must be ball"));
            }
            if s.kind == 15 {
                (4, 3, 1)
            } else {
                (3, 0, 2)
            }
        }
        17..=19 => {
            let Some((_, limited)) = joint(s.objtype) else {
                return Err(attached("joint"));
            };
            if limited == 0 {
                return Err(err("joint must be limited"));
            }
            (1, 0, stage3(s.kind, 17))
        }
        20..=22 => {
            if s.objtype != 17 {
                return Err(attached("tendon"));
            }
            if tendons[objid as usize].spec.limited == 0 {
                return Err(err("tendon must be limited"));
            }
            (1, 0, stage3(s.kind, 20))
        }
        23..=31 => {
            if !frame_obj(s.objtype) {
                return Err(attached("(x)body, geom, site or camera"));
            }
            let dim = if s.kind == 24 { 4 } else { 3 };
            let dt = match s.kind {
                24 => 3,
                25..=27 => 2,
                _ => 0,
            };
            let stage = match s.kind {
                30 | 31 => 3,
                28 | 29 => 2,
                _ => 1,
            };
            (dim, dt, stage)
        }
        32..=34 => {
            if s.objtype != 1 {
                return Err(attached("body"));
            }
            (3, 0, if s.kind == 32 { 1 } else { 2 })
        }
        35 => (1, 0, 1),
        36 => {
            if s.dim < 0 {
                return Err(CError::at(
                    format!("sensor dim must be positive: sensor '{name}' (id = {id})"),
                    &name,
                    id,
                    -1,
                ));
            }
            if s.datatype == 2 && s.dim != 3 {
                return Err(err("datatype AXIS requires dim=3"));
            }
            if s.datatype == 3 && s.dim != 4 {
                return Err(err("datatype QUATERNION requires dim=4"));
            }
            (s.dim, s.datatype, s.needstage)
        }
        _ => return Err(err("invalid type")),
    };
    if s.cutoff > 0.0 && (datatype == 2 || datatype == 3) {
        return Err(err("cutoff applied to axis or quaternion datatype"));
    }
    Ok(CSensor {
        spec: s,
        objid,
        refid,
        dim,
        datatype,
        needstage,
    })
}

fn put<T: Copy>(dst: &mut [T], i: usize, src: &[T]) {
    let n = src.len();
    dst[i * n..(i + 1) * n].copy_from_slice(src);
}

fn null_pose(pos: &[f64; 3], quat: Option<&[f64; 4]>) -> bool {
    pos.iter().all(|&p| p == 0.0)
        && quat.is_none_or(|q| q[0] == 1.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0)
}

fn normalize4_engine(q: &mut [f64]) {
    let norm = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    if norm < MINVAL {
        q.copy_from_slice(&[1.0, 0.0, 0.0, 0.0]);
    } else {
        let inv = 1.0 / norm;
        for x in q.iter_mut() {
            *x *= inv;
        }
    }
}

impl Compiled {
    pub fn auto_spring_damper(&self, m: &mut ModelMut) {
        let max = |a: f64, b: f64| if a > b { a } else { b };
        for (n, j) in self.joints.iter().enumerate() {
            let [timeconst, dampratio] = j.spec.springdamper;
            if timeconst <= 0.0 || dampratio <= 0.0 {
                continue;
            }
            let adr = m.jnt_dofadr[n] as usize;
            let ndim = j.spec.kind.nv();
            let mut inertia = 0.0;
            for i in 0..ndim {
                inertia += m.dof_invweight0[adr + i];
            }
            inertia = ndim as f64 / max(MINVAL, inertia);
            m.jnt_stiffness[n] =
                inertia / max(MINVAL, timeconst * timeconst * dampratio * dampratio);
            let damping = 2.0 * inertia / max(MINVAL, timeconst);
            for i in 0..ndim {
                m.dof_damping[adr + i] = damping;
            }
        }
    }

    /// Frees the bulk arrays `fill` has copied into the model (meshes, skins, textures, height
    /// fields); what the compiler's later steps read stays.
    pub fn release_bulk(&mut self) {
        self.meshes = Vec::new();
        self.skins = Vec::new();
        self.textures = Vec::new();
        self.hfields = Vec::new();
    }

    pub fn fill(&self, m: &mut ModelMut) {
        let h = &self.header;
        // names
        let mut adr = 0usize;
        let mut name = |dst: &mut i32, s: &str, names: &mut [i8]| {
            *dst = adr as i32;
            for (k, b) in s.bytes().enumerate() {
                names[adr + k] = b as i8;
            }
            adr += s.len();
            names[adr] = 0;
            adr += 1;
        };
        let mut scratch = 0;
        name(&mut scratch, &self.modelname, m.names);
        for (i, b) in self.bodies.iter().enumerate() {
            name(&mut m.name_bodyadr[i], &b.spec.name, m.names);
        }
        for (i, j) in self.joints.iter().enumerate() {
            name(&mut m.name_jntadr[i], &j.spec.name, m.names);
        }
        for (i, g) in self.geoms.iter().enumerate() {
            name(&mut m.name_geomadr[i], &g.spec.name, m.names);
        }
        for (i, s) in self.sites.iter().enumerate() {
            name(&mut m.name_siteadr[i], &s.spec.name, m.names);
        }
        for (i, c) in self.cameras.iter().enumerate() {
            name(&mut m.name_camadr[i], &c.0.name, m.names);
        }
        for (i, l) in self.lights.iter().enumerate() {
            name(&mut m.name_lightadr[i], &l.0.name, m.names);
        }
        for (i, mesh) in self.meshes.iter().enumerate() {
            name(&mut m.name_meshadr[i], &mesh.name, m.names);
        }
        for (i, sk) in self.skins.iter().enumerate() {
            name(&mut m.name_skinadr[i], &sk.name, m.names);
        }
        for (i, hf) in self.hfields.iter().enumerate() {
            name(&mut m.name_hfieldadr[i], &hf.name, m.names);
        }
        for (i, t) in self.texture_names.iter().enumerate() {
            name(&mut m.name_texadr[i], t, m.names);
        }
        for (i, mat) in self.materials.iter().enumerate() {
            name(&mut m.name_matadr[i], &mat.name, m.names);
        }
        for (i, p) in self.pairs.iter().enumerate() {
            name(&mut m.name_pairadr[i], &p.0.name, m.names);
        }
        for (i, e) in self.excludes.iter().enumerate() {
            name(&mut m.name_excludeadr[i], &e.0, m.names);
        }
        for (i, e) in self.equalities.iter().enumerate() {
            name(&mut m.name_eqadr[i], &e.0.name, m.names);
        }
        for (i, t) in self.tendons.iter().enumerate() {
            name(&mut m.name_tendonadr[i], &t.spec.name, m.names);
        }
        for (i, a) in self.actuators.iter().enumerate() {
            name(&mut m.name_actuatoradr[i], &a.name, m.names);
        }
        for (i, s) in self.sensors.iter().enumerate() {
            name(&mut m.name_sensoradr[i], &s.spec.name, m.names);
        }
        for (i, x) in self.custom.numerics.iter().enumerate() {
            name(&mut m.name_numericadr[i], &x.0, m.names);
        }
        for (i, x) in self.custom.texts.iter().enumerate() {
            name(&mut m.name_textadr[i], &x.0, m.names);
        }
        for (i, x) in self.custom.tuples.iter().enumerate() {
            name(&mut m.name_tupleadr[i], &x.0, m.names);
        }
        for (i, k) in self.keys.iter().enumerate() {
            name(&mut m.name_keyadr[i], &k.name, m.names);
        }

        // kinematic tree
        let (mut jntadr, mut dofadr, mut qposadr) = (0usize, 0usize, 0usize);
        let mut lastdof = vec![-1i32; self.bodies.len()];
        let [nub, nuj, nug, nus, _, _, nua, _] = self.nuser;
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
        let target = |t: &str| {
            if t.is_empty() {
                -1
            } else {
                find_body(&self.bodies, t).map_or(-1, |b| b as i32)
            }
        };
        for (i, (c, b)) in self.cameras.iter().enumerate() {
            m.cam_bodyid[i] = *b as i32;
            m.cam_mode[i] = c.mode;
            m.cam_targetbodyid[i] = target(&c.target);
            put(m.cam_pos, i, &c.pos);
            put(m.cam_quat, i, &c.quat);
            m.cam_fovy[i] = c.fovy;
            m.cam_ipd[i] = c.ipd;
            put(m.cam_user, i, &c.user);
        }
        for (i, (l, b)) in self.lights.iter().enumerate() {
            m.light_bodyid[i] = *b as i32;
            m.light_mode[i] = l.mode;
            m.light_targetbodyid[i] = target(&l.target);
            m.light_directional[i] = l.directional as u8;
            m.light_castshadow[i] = l.castshadow as u8;
            m.light_active[i] = l.active as u8;
            put(m.light_pos, i, &l.pos);
            put(m.light_dir, i, &l.dir);
            put(m.light_attenuation, i, &l.attenuation);
            m.light_cutoff[i] = l.cutoff;
            m.light_exponent[i] = l.exponent;
            put(m.light_ambient, i, &l.ambient);
            put(m.light_diffuse, i, &l.diffuse);
            put(m.light_specular, i, &l.specular);
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

        // assets
        super::skin::fill(&self.skins, m);
        let mut adr = 0;
        for (i, hf) in self.hfields.iter().enumerate() {
            put(m.hfield_size, i, &hf.size);
            m.hfield_nrow[i] = hf.nrow;
            m.hfield_ncol[i] = hf.ncol;
            m.hfield_adr[i] = adr;
            let a = adr as usize;
            m.hfield_data[a..a + hf.data.len()].copy_from_slice(&hf.data);
            adr += hf.nrow * hf.ncol;
        }
        for (g, hf) in self.geom_hfield.iter().enumerate() {
            if let Some(h) = hf {
                m.geom_dataid[g] = *h as i32;
            }
        }
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
        let mut adr = 0;
        for (i, (kind, width, height, rgb)) in self.textures.iter().enumerate() {
            m.tex_type[i] = *kind;
            m.tex_height[i] = *height;
            m.tex_width[i] = *width;
            m.tex_adr[i] = adr as i32;
            m.tex_rgb[adr..adr + rgb.len()].copy_from_slice(rgb);
            adr += rgb.len();
        }
        for (i, mat) in self.materials.iter().enumerate() {
            m.mat_texid[i] = self.mat_texid[i];
            m.mat_texuniform[i] = mat.texuniform as u8;
            put(m.mat_texrepeat, i, &mat.texrepeat);
            m.mat_emission[i] = mat.emission;
            m.mat_specular[i] = mat.specular;
            m.mat_shininess[i] = mat.shininess;
            m.mat_reflectance[i] = mat.reflectance;
            put(m.mat_rgba, i, &mat.rgba);
        }
        for (g, &id) in self.geom_matid.iter().enumerate() {
            m.geom_matid[g] = id;
        }
        for (s, &id) in self.site_matid.iter().enumerate() {
            m.site_matid[s] = id;
        }
        for (t, &id) in self.tendon_matid.iter().enumerate() {
            m.tendon_matid[t] = id;
        }

        // contact pairs, exclusions
        for (i, (p, g, sig)) in self.pairs.iter().enumerate() {
            m.pair_dim[i] = p.condim;
            m.pair_geom1[i] = g[0];
            m.pair_geom2[i] = g[1];
            m.pair_signature[i] = *sig;
            put(m.pair_solref, i, &p.solref);
            put(m.pair_solimp, i, &p.solimp);
            m.pair_margin[i] = p.margin;
            m.pair_gap[i] = p.gap;
            put(m.pair_friction, i, &p.friction);
        }
        for (i, e) in self.excludes.iter().enumerate() {
            m.exclude_signature[i] = e.1;
        }
        for (i, (e, ids)) in self.equalities.iter().enumerate() {
            m.eq_type[i] = e.kind;
            m.eq_obj1id[i] = ids[0];
            m.eq_obj2id[i] = ids[1];
            m.eq_active[i] = e.active as u8;
            put(m.eq_solref, i, &e.solref);
            put(m.eq_solimp, i, &e.solimp);
            put(m.eq_data, i, &e.data);
        }
        let mut adr = 0;
        for (i, t) in self.tendons.iter().enumerate() {
            let s = &t.spec;
            m.tendon_adr[i] = adr as i32;
            m.tendon_num[i] = t.wraps.len() as i32;
            m.tendon_group[i] = s.group;
            m.tendon_limited[i] = s.limited as u8;
            m.tendon_width[i] = s.width;
            put(m.tendon_solref_lim, i, &s.solref_limit);
            put(m.tendon_solimp_lim, i, &s.solimp_limit);
            put(m.tendon_solref_fri, i, &s.solref_friction);
            put(m.tendon_solimp_fri, i, &s.solimp_friction);
            put(m.tendon_range, i, &s.range);
            m.tendon_margin[i] = s.margin;
            m.tendon_stiffness[i] = s.stiffness;
            m.tendon_damping[i] = s.damping;
            m.tendon_frictionloss[i] = s.frictionloss;
            m.tendon_lengthspring[i] = s.springlength;
            put(m.tendon_user, i, &s.user);
            put(m.tendon_rgba, i, &s.rgba);
            for (k, w) in t.wraps.iter().enumerate() {
                m.wrap_type[adr + k] = w.0;
                m.wrap_objid[adr + k] = w.1;
                m.wrap_prm[adr + k] = w.2;
            }
            adr += t.wraps.len();
        }

        // actuators
        for (i, a) in self.actuators.iter().enumerate() {
            m.actuator_trntype[i] = a.trntype;
            m.actuator_dyntype[i] = a.dyntype;
            m.actuator_gaintype[i] = a.gaintype;
            m.actuator_biastype[i] = a.biastype;
            put(m.actuator_trnid, i, &self.trnid[i]);
            m.actuator_group[i] = a.group;
            m.actuator_ctrllimited[i] = a.ctrllimited as u8;
            m.actuator_forcelimited[i] = a.forcelimited as u8;
            m.actuator_actlimited[i] = a.actlimited as u8;
            m.actuator_cranklength[i] = a.cranklength;
            put(m.actuator_gear, i, &a.gear);
            put(m.actuator_dynprm, i, &a.dynprm);
            put(m.actuator_gainprm, i, &a.gainprm);
            put(m.actuator_biasprm, i, &a.biasprm);
            put(m.actuator_ctrlrange, i, &a.ctrlrange);
            put(m.actuator_forcerange, i, &a.forcerange);
            put(m.actuator_actrange, i, &a.actrange);
            put(m.actuator_lengthrange, i, &a.lengthrange);
            let mut user = a.user.clone();
            user.resize(nua, 0.0);
            put(m.actuator_user, i, &user);
        }

        // custom data
        let mut adr = 0;
        for (i, x) in self.custom.numerics.iter().enumerate() {
            m.numeric_adr[i] = adr as i32;
            m.numeric_size[i] = x.2.len() as i32;
            m.numeric_data[adr..adr + x.2.len()].copy_from_slice(&x.2);
            adr += x.2.len();
        }
        let mut adr = 0;
        for (i, x) in self.custom.texts.iter().enumerate() {
            m.text_adr[i] = adr as i32;
            m.text_size[i] = x.2.len() as i32 + 1;
            for (k, b) in x.2.bytes().enumerate() {
                m.text_data[adr + k] = b as std::os::raw::c_char;
            }
            adr += x.2.len() + 1;
        }
        let mut adr = 0;
        for (i, x) in self.custom.tuples.iter().enumerate() {
            m.tuple_adr[i] = adr as i32;
            m.tuple_size[i] = x.2.len() as i32;
            for (k, (kind, _, prm)) in x.2.iter().enumerate() {
                m.tuple_objtype[adr + k] = *kind;
                m.tuple_objid[adr + k] = self.tuple_ids[i][k];
                m.tuple_objprm[adr + k] = *prm;
            }
            adr += x.2.len();
        }

        // sensors
        let mut adr = 0;
        for (i, s) in self.sensors.iter().enumerate() {
            m.sensor_type[i] = s.spec.kind;
            m.sensor_datatype[i] = s.datatype;
            m.sensor_needstage[i] = s.needstage;
            m.sensor_objtype[i] = s.spec.objtype;
            m.sensor_objid[i] = s.objid;
            m.sensor_reftype[i] = s.spec.reftype;
            m.sensor_refid[i] = s.refid;
            m.sensor_dim[i] = s.dim;
            m.sensor_cutoff[i] = s.spec.cutoff;
            m.sensor_noise[i] = s.spec.noise;
            put(m.sensor_user, i, &s.spec.user);
            m.sensor_adr[i] = adr;
            adr += s.dim;
        }

        // keyframes: missing entries default to qpos0, zeros, mocap body poses
        let (nq, na, nu, nmocap) = (
            h.nq as usize,
            h.na as usize,
            h.nu as usize,
            h.nmocap as usize,
        );
        for (i, k) in self.keys.iter().enumerate() {
            m.key_time[i] = k.time;
            let qpos = if k.qpos.is_empty() {
                m.qpos0.to_vec()
            } else {
                k.qpos.clone()
            };
            m.key_qpos[i * nq..(i + 1) * nq].copy_from_slice(&qpos);
            if !k.qvel.is_empty() {
                m.key_qvel[i * nv..(i + 1) * nv].copy_from_slice(&k.qvel);
            }
            if !k.act.is_empty() {
                m.key_act[i * na..(i + 1) * na].copy_from_slice(&k.act);
            }
            for (b, body) in self.bodies.iter().enumerate() {
                if body.mocapid >= 0 {
                    let id = body.mocapid as usize;
                    let pos = [
                        m.body_pos[3 * b],
                        m.body_pos[3 * b + 1],
                        m.body_pos[3 * b + 2],
                    ];
                    let quat: Vec<f64> = m.body_quat[4 * b..4 * b + 4].to_vec();
                    if k.mpos.is_empty() {
                        m.key_mpos[3 * (i * nmocap + id)..3 * (i * nmocap + id) + 3]
                            .copy_from_slice(&pos);
                    }
                    if k.mquat.is_empty() {
                        m.key_mquat[4 * (i * nmocap + id)..4 * (i * nmocap + id) + 4]
                            .copy_from_slice(&quat);
                    }
                }
            }
            if !k.mpos.is_empty() {
                m.key_mpos[i * 3 * nmocap..(i + 1) * 3 * nmocap].copy_from_slice(&k.mpos);
            }
            if !k.mquat.is_empty() {
                m.key_mquat[i * 4 * nmocap..(i + 1) * 4 * nmocap].copy_from_slice(&k.mquat);
            }
            if !k.ctrl.is_empty() {
                m.key_ctrl[i * nu..(i + 1) * nu].copy_from_slice(&k.ctrl);
            }
            // quaternions normalized when copied and again when the model is finalized
            for _ in 0..2 {
                for (j, jt) in self.joints.iter().enumerate() {
                    let adr = i * nq + m.jnt_qposadr[j] as usize;
                    match jt.spec.kind {
                        JointType::Ball => normalize4_engine(&mut m.key_qpos[adr..adr + 4]),
                        JointType::Free => normalize4_engine(&mut m.key_qpos[adr + 3..adr + 7]),
                        _ => {}
                    }
                }
            }
            for j in 0..nmocap {
                let adr = 4 * (i * nmocap + j);
                normalize4_engine(&mut m.key_mquat[adr..adr + 4]);
            }
        }

        // total mass
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
