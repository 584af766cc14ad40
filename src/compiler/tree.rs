//! The kinematic tree and global lists: ids, per-object compilation, sizes, array filling.

use super::frame::*;
use super::objects::*;
use super::spec::*;
use super::CError;
use crate::abi::view::ModelMut;
use crate::abi::{mjModel, mjOption, mjVisual};

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
    actuators: Vec<Actuator>,
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

pub fn compile(spec: ModelSpec, mut h: mjModel) -> Result<Compiled, CError> {
    let opts = spec.compiler.clone();
    let settings = Settings {
        degree: opts.degree,
        eulerseq: &opts.eulerseq,
    };
    if opts.global {
        return Err(CError::msg(
            "coordinate=\"global\" is not supported by this compiler yet",
        ));
    }

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
    check_names(spec.pairs.iter().map(|p| (p.name.as_str(), p.line)), "pair")?;
    check_names(
        spec.excludes.iter().map(|e| (e.name.as_str(), e.line)),
        "exclude",
    )?;
    check_names(
        actuators.iter().map(|a| (a.name.as_str(), a.line)),
        "actuator",
    )?;
    check_names(keys.iter().map(|k| (k.name.as_str(), -1)), "key")?;

    let n = &spec.nuser;
    let nuser = [
        user_len(bodies.iter().map(|b| b.spec.user.len()), n[0]),
        user_len(joints.iter().map(|j| j.spec.user.len()), n[1]),
        user_len(gspecs.iter().map(|g| g.user.len()), n[2]),
        user_len(sspecs.iter().map(|s| s.0.user.len()), n[3]),
        user_len(cameras.iter().map(|c| c.0.user.len()), n[4]),
        user_len(std::iter::empty(), n[5]),
        user_len(actuators.iter().map(|a| a.user.len()), n[6]),
        user_len(std::iter::empty(), n[7]),
    ];

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
        if !defined(b.pos[0]) {
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
            let out = compile_geom(g, gid, b.weldid == 0, infer, &settings)
                .map_err(|m| CError::at(m, &g.name, gid, g.line))?;
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
        if !defined(b.ipos[0]) {
            b.ipos = b.pos;
            b.iquat = b.quat;
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
    }
    let geoms: Vec<FGeom> = geoms.into_iter().flatten().collect();
    let sites: Vec<FSite> = sites.into_iter().flatten().collect();

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
        if a.gaintype == 2 || a.biastype == 2 || a.dyntype == 3 {
            return Err(aerr(
                "muscle actuators are not supported by this compiler yet".into(),
            ));
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
            3 => {
                return Err(aerr(
                    "tendon transmissions are not supported by this compiler yet".into(),
                ))
            }
            _ => {
                return Err(aerr(format!(
                    "invalid transmission type in actuator '{name}' (id = {id})"
                )))
            }
        };
        trnid.push(ids);
    }

    // sizes
    h.nbody = bodies.len() as i32;
    h.njnt = joints.len() as i32;
    h.ngeom = geoms.len() as i32;
    h.nsite = sites.len() as i32;
    h.ncam = cameras.len() as i32;
    h.nlight = lights.len() as i32;
    h.nkey = keys.len() as i32;
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
    nnames += pairs.iter().map(|p| p.0.name.len() + 1).sum::<usize>();
    nnames += excludes.iter().map(|e| e.0.len() + 1).sum::<usize>();
    h.npair = pairs.len() as i32;
    h.nexclude = excludes.len() as i32;
    nnames += actuators.iter().map(|a| a.name.len() + 1).sum::<usize>();
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

    Ok(Compiled {
        header: h,
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
        actuators,
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

fn put<T: Copy>(dst: &mut [T], i: usize, src: &[T]) {
    let n = src.len();
    dst[i * n..(i + 1) * n].copy_from_slice(src);
}

fn null_pose(pos: &[f64; 3], quat: Option<&[f64; 4]>) -> bool {
    pos.iter().all(|&p| p == 0.0)
        && quat.map_or(true, |q| {
            q[0] == 1.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0
        })
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
        for (i, p) in self.pairs.iter().enumerate() {
            name(&mut m.name_pairadr[i], &p.0.name, m.names);
        }
        for (i, e) in self.excludes.iter().enumerate() {
            name(&mut m.name_excludeadr[i], &e.0, m.names);
        }
        for (i, a) in self.actuators.iter().enumerate() {
            name(&mut m.name_actuatoradr[i], &a.name, m.names);
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
                        m.qpos0[q..q + 3].copy_from_slice(&b.pos);
                        m.qpos0[q + 3..q + 7].copy_from_slice(&b.quat);
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
