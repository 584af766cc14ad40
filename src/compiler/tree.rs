//! The model compiler's driver: objects in 2.2.2's order of compilation, sizes, array filling.
//! Each kind of object is compiled and filled in its own module.

use super::frame::*;
use super::objects::*;
use super::spec::*;
use super::CError;
use crate::abi::view::ModelMut;
use crate::abi::{mjModel, mjOption, mjVisual};
use sensors::CSensor;
use tendons::CTendon;

mod actuators;
mod assets;
mod bodies;
mod cameras_lights;
mod contacts;
mod custom;
mod equalities;
mod fuse;
mod hfields;
mod keys;
mod meshes;
mod names;
mod sensors;
mod sizes;
mod tendons;
mod textures;

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
    textures: Vec<textures::TexImage>,
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

fn user_len(lens: impl Iterator<Item = usize>, given: i32) -> usize {
    if given >= 0 {
        given as usize
    } else {
        lens.max().unwrap_or(0)
    }
}

pub fn compile(mut spec: ModelSpec, h: mjModel) -> Result<Compiled, CError> {
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
        std::mem::take(&mut spec.world),
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
    let mut actuators = std::mem::take(&mut spec.actuators);
    let mut keys = std::mem::take(&mut spec.keys);
    while keys.len() < spec.nkey.max(0) as usize {
        keys.push(Key::default());
    }

    // repeated names, then user data sizes
    names::check_all(
        &spec, &bodies, &joints, &gspecs, &sspecs, &cameras, &lights, &actuators, &keys,
    )?;
    let sensors = std::mem::take(&mut spec.sensors);
    let custom = std::mem::take(&mut spec.custom);

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

    // asset names and references, meshes, then the tree body by body
    let assets::AssetRefs {
        geom_hfield,
        geom_mesh,
        geom_matid,
        site_matid,
        tendon_matid,
        mat_texid,
    } = assets::resolve(&mut spec, &gspecs, &sspecs)?;
    let meshes = meshes::compile(&mut spec, &opts, &gspecs, &geom_mesh)?;
    let (geoms, sites) = bodies::compile(
        &mut bodies,
        &mut joints,
        &gspecs,
        &sspecs,
        &mut cameras,
        &mut lights,
        &nuser,
        &opts,
        &settings,
        &spec.hfields,
        &geom_hfield,
        &geom_mesh,
        &meshes,
    )?;

    // skins, height fields, textures and materials
    let skins = {
        let body = |n: &str| find_body(&bodies, n);
        let mats = &spec.materials;
        let matid = |n: &str| mats.iter().position(|m| m.name == n);
        super::skin::compile(std::mem::take(&mut spec.skins), &body, &matid)?
    };

    hfields::compile(&mut spec.hfields)?;
    let hfields = std::mem::take(&mut spec.hfields);
    let textures = textures::compile(&spec.textures)?;
    let materials = std::mem::take(&mut spec.materials);
    // objects referring to the tree: pairs and excludes, equalities, tendons, actuators, sensors
    let (pairs, excludes) = contacts::compile(
        std::mem::take(&mut spec.pairs),
        std::mem::take(&mut spec.excludes),
        &geoms,
        &bodies,
    )?;
    let equalities = equalities::compile(
        std::mem::take(&mut spec.equalities),
        &bodies,
        &joints,
        &spec.tendons,
        opts.global,
    )?;
    let tendon_specs = std::mem::take(&mut spec.tendons);
    let tendons = tendons::compile_all(
        tendon_specs,
        nuser[5],
        &joints,
        &geoms,
        &sites,
        opts.autolimits,
    )?;
    let trnid = actuators::compile(
        &mut actuators,
        nuser[6],
        opts.autolimits,
        &bodies,
        &joints,
        &sites,
        &tendons,
    )?;

    // actuator length ranges are computed after set_const (capi load: mj_setLengthRange)
    let csensors = sensors::compile_all(
        sensors, nuser[7], &bodies, &joints, &geoms, &sites, &cameras, &lights, &tendons,
        &actuators,
    )?;

    // the compiled model; then tuples, which may refer to any object
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
    let mut c = Compiled {
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
        tuple_ids: Vec::new(),
        keys,
        trnid,
        nuser,
        settotalmass: opts.settotalmass,
    };
    c.tuple_ids = c.resolve_tuples()?;

    // static bodies into their parents, when no other object refers to body ids
    let refs = !c.skins.is_empty()
        || !c.pairs.is_empty()
        || !c.excludes.is_empty()
        || !c.equalities.is_empty()
        || !c.tendons.is_empty()
        || !c.actuators.is_empty()
        || !c.sensors.is_empty()
        || !c.custom.tuples.is_empty()
        || !c.cameras.is_empty()
        || !c.lights.is_empty();
    if opts.fusestatic && !refs {
        let c = &mut c;
        fuse::fuse_static(
            &mut c.bodies,
            &mut c.joints,
            &mut c.geoms,
            &mut c.sites,
            &settings,
        )?;
    }
    // sizes, then the checks that need them
    c.count_sizes(spec.nconmax, spec.njmax, spec.nuserdata, spec.nstack)?;
    c.check_tree()?;
    c.check_keys()?;
    Ok(c)
}

fn find_body(bodies: &[FBody], name: &str) -> Option<usize> {
    bodies.iter().position(|b| b.spec.name == name)
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

    /// Writes every array of a model allocated with the compiled sizes; the bulk (skins,
    /// height fields, textures, meshes) is freed as soon as it is copied, and `trim` called
    /// after the two largest kinds, so that their pages can serve the model's.
    pub fn fill(&mut self, m: &mut ModelMut, trim: &dyn Fn()) {
        self.fill_names(m);
        self.fill_tree(m);
        self.fill_cameras_lights(m);
        super::skin::fill(&self.skins, m);
        self.skins = Vec::new();
        self.fill_hfields(m);
        self.hfields = Vec::new();
        self.fill_textures_materials(m);
        self.textures = Vec::new();
        trim();
        self.fill_meshes(m);
        self.meshes = Vec::new();
        trim();
        self.fill_contacts(m);
        self.fill_equalities(m);
        self.fill_tendons(m);
        self.fill_actuators(m);
        self.fill_custom(m);
        self.fill_sensors(m);
        self.fill_keys(m);
        self.scale_total_mass(m);
    }
}
