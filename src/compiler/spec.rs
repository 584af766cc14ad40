//! Model description: what an MJCF file says, with defaults applied, before compilation.
//!
//! Undefined values are NaN where the compiler must know whether they were given.

use crate::abi::alloc::{default_option, default_solimp, default_solref, default_visual};
use crate::abi::{mjOption, mjVisual};

pub const NAN: f64 = f64::NAN;

/// Source position of an object, for error messages (-1: unknown).
pub type Line = i32;

/// Alternative orientation specifications; first entry NaN when not given.
#[derive(Debug, Clone, Copy)]
pub struct Alt {
    pub axisangle: [f64; 4],
    pub xyaxes: [f64; 6],
    pub zaxis: [f64; 3],
    pub euler: [f64; 3],
    pub fullinertia: [f64; 6],
}

impl Default for Alt {
    fn default() -> Self {
        Alt {
            axisangle: [NAN; 4],
            xyaxes: [NAN; 6],
            zaxis: [NAN; 3],
            euler: [NAN; 3],
            fullinertia: [NAN; 6],
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointType {
    Free = 0,
    Ball = 1,
    Slide = 2,
    Hinge = 3,
}

impl JointType {
    pub fn nq(self) -> usize {
        [7, 4, 1, 1][self as usize]
    }
    pub fn nv(self) -> usize {
        [6, 3, 1, 1][self as usize]
    }
}

#[derive(Debug, Clone)]
pub struct Joint {
    pub name: String,
    pub line: Line,
    pub kind: JointType,
    pub group: i32,
    pub pos: [f64; 3],
    pub axis: [f64; 3],
    pub springdamper: [f64; 2],
    /// 0 false, 1 true, 2 auto
    pub limited: i32,
    pub solref_limit: [f64; 2],
    pub solimp_limit: [f64; 5],
    pub solref_friction: [f64; 2],
    pub solimp_friction: [f64; 5],
    pub stiffness: f64,
    pub range: [f64; 2],
    pub margin: f64,
    pub reference: f64,
    pub springref: f64,
    pub armature: f64,
    pub damping: f64,
    pub frictionloss: f64,
    pub user: Vec<f64>,
}

impl Default for Joint {
    fn default() -> Self {
        Joint {
            name: String::new(),
            line: -1,
            kind: JointType::Hinge,
            group: 0,
            pos: [0.0; 3],
            axis: [0.0, 0.0, 1.0],
            springdamper: [0.0; 2],
            limited: 2,
            solref_limit: default_solref(),
            solimp_limit: default_solimp(),
            solref_friction: default_solref(),
            solimp_friction: default_solimp(),
            stiffness: 0.0,
            range: [0.0; 2],
            margin: 0.0,
            reference: 0.0,
            springref: 0.0,
            armature: 0.0,
            damping: 0.0,
            frictionloss: 0.0,
            user: Vec::new(),
        }
    }
}

#[derive(Debug, Clone)]
pub struct Geom {
    pub name: String,
    pub line: Line,
    /// mjtGeom value
    pub kind: i32,
    pub size: [f64; 3],
    pub contype: i32,
    pub conaffinity: i32,
    pub condim: i32,
    pub group: i32,
    pub priority: i32,
    pub friction: [f64; 3],
    pub solmix: f64,
    pub solref: [f64; 2],
    pub solimp: [f64; 5],
    pub margin: f64,
    pub gap: f64,
    pub rgba: [f32; 4],
    /// NaN: not given
    pub mass: f64,
    pub density: f64,
    pub fromto: [f64; 6],
    pub pos: [f64; 3],
    pub quat: [f64; 4],
    pub alt: Alt,
    pub fluid_switch: bool,
    pub fluid_coefs: [f64; 5],
    /// Attributes the compiler does not handle yet.
    pub unsupported: Option<&'static str>,
    pub material: String,
    pub hfield: String,
    pub mesh: String,
    pub fitscale: f64,
    /// inertia from the mesh surface (shellinertia) instead of its volume
    pub shellinertia: bool,
    pub user: Vec<f64>,
}

impl Default for Geom {
    fn default() -> Self {
        Geom {
            name: String::new(),
            line: -1,
            kind: 2,
            size: [0.0; 3],
            contype: 1,
            conaffinity: 1,
            condim: 3,
            group: 0,
            priority: 0,
            friction: [1.0, 0.005, 0.0001],
            solmix: 1.0,
            solref: default_solref(),
            solimp: default_solimp(),
            margin: 0.0,
            gap: 0.0,
            rgba: [0.5, 0.5, 0.5, 1.0],
            mass: NAN,
            density: 1000.0,
            fromto: [NAN; 6],
            pos: [0.0; 3],
            quat: [1.0, 0.0, 0.0, 0.0],
            alt: Alt::default(),
            fluid_switch: false,
            fluid_coefs: [0.5, 0.25, 1.5, 1.0, 1.0],
            unsupported: None,
            material: String::new(),
            hfield: String::new(),
            mesh: String::new(),
            fitscale: 1.0,
            shellinertia: false,
            user: Vec::new(),
        }
    }
}

#[derive(Debug, Clone)]
pub struct Site {
    pub name: String,
    pub line: Line,
    pub kind: i32,
    pub size: [f64; 3],
    pub group: i32,
    pub pos: [f64; 3],
    pub quat: [f64; 4],
    pub rgba: [f32; 4],
    pub fromto: [f64; 6],
    pub alt: Alt,
    pub unsupported: Option<&'static str>,
    pub material: String,
    pub user: Vec<f64>,
}

impl Default for Site {
    fn default() -> Self {
        Site {
            name: String::new(),
            line: -1,
            kind: 2,
            size: [0.005; 3],
            group: 0,
            pos: [0.0; 3],
            quat: [1.0, 0.0, 0.0, 0.0],
            rgba: [0.5, 0.5, 0.5, 1.0],
            fromto: [NAN; 6],
            alt: Alt::default(),
            unsupported: None,
            material: String::new(),
            user: Vec::new(),
        }
    }
}

#[derive(Debug, Clone)]
pub struct Actuator {
    pub name: String,
    pub line: Line,
    pub group: i32,
    pub ctrllimited: i32,
    pub forcelimited: i32,
    pub actlimited: i32,
    pub ctrlrange: [f64; 2],
    pub forcerange: [f64; 2],
    pub actrange: [f64; 2],
    pub lengthrange: [f64; 2],
    pub gear: [f64; 6],
    pub cranklength: f64,
    /// mjtTrn value; -1 undefined (mjTRN_UNDEFINED is 1000 in 2.2.2)
    pub trntype: i32,
    pub dyntype: i32,
    pub gaintype: i32,
    pub biastype: i32,
    pub dynprm: [f64; 10],
    pub gainprm: [f64; 10],
    pub biasprm: [f64; 10],
    pub target: String,
    pub slidersite: String,
    pub refsite: String,
    pub user: Vec<f64>,
}

impl Default for Actuator {
    fn default() -> Self {
        let mut one = [0.0; 10];
        one[0] = 1.0;
        Actuator {
            name: String::new(),
            line: -1,
            group: 0,
            ctrllimited: 2,
            forcelimited: 2,
            actlimited: 2,
            ctrlrange: [0.0; 2],
            forcerange: [0.0; 2],
            actrange: [0.0; 2],
            lengthrange: [0.0; 2],
            gear: [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            cranklength: 0.0,
            trntype: TRN_UNDEFINED,
            dyntype: 0,
            gaintype: 0,
            biastype: 0,
            dynprm: one,
            gainprm: one,
            biasprm: [0.0; 10],
            target: String::new(),
            slidersite: String::new(),
            refsite: String::new(),
            user: Vec::new(),
        }
    }
}

pub const TRN_UNDEFINED: i32 = 1000;

#[derive(Debug, Clone)]
pub struct Camera {
    pub name: String,
    pub line: Line,
    /// mjtCamLight value
    pub mode: i32,
    pub target: String,
    pub pos: [f64; 3],
    pub quat: [f64; 4],
    pub alt: Alt,
    pub fovy: f64,
    pub ipd: f64,
    pub user: Vec<f64>,
}

impl Default for Camera {
    fn default() -> Self {
        Camera {
            name: String::new(),
            line: -1,
            mode: 0,
            target: String::new(),
            pos: [0.0; 3],
            quat: [1.0, 0.0, 0.0, 0.0],
            alt: Alt::default(),
            fovy: 45.0,
            ipd: 0.068,
            user: Vec::new(),
        }
    }
}

#[derive(Debug, Clone)]
pub struct Light {
    pub name: String,
    pub line: Line,
    pub mode: i32,
    pub target: String,
    pub directional: bool,
    pub castshadow: bool,
    pub active: bool,
    pub pos: [f64; 3],
    pub dir: [f64; 3],
    pub attenuation: [f32; 3],
    pub cutoff: f32,
    pub exponent: f32,
    pub ambient: [f32; 3],
    pub diffuse: [f32; 3],
    pub specular: [f32; 3],
}

impl Default for Light {
    fn default() -> Self {
        Light {
            name: String::new(),
            line: -1,
            mode: 0,
            target: String::new(),
            directional: false,
            castshadow: true,
            active: true,
            pos: [0.0; 3],
            dir: [0.0, 0.0, -1.0],
            attenuation: [1.0, 0.0, 0.0],
            cutoff: 45.0,
            exponent: 10.0,
            ambient: [0.0; 3],
            diffuse: [0.7; 3],
            specular: [0.3; 3],
        }
    }
}

/// Explicit contact pair (`<contact><pair>`).
#[derive(Debug, Clone)]
pub struct Pair {
    pub name: String,
    pub line: Line,
    pub geom1: String,
    pub geom2: String,
    pub condim: i32,
    pub solref: [f64; 2],
    pub solimp: [f64; 5],
    pub margin: f64,
    pub gap: f64,
    pub friction: [f64; 5],
}

impl Default for Pair {
    fn default() -> Self {
        Pair {
            name: String::new(),
            line: -1,
            geom1: String::new(),
            geom2: String::new(),
            condim: 3,
            solref: default_solref(),
            solimp: default_solimp(),
            margin: 0.0,
            gap: 0.0,
            friction: [1.0, 1.0, 0.005, 0.0001, 0.0001],
        }
    }
}

/// Excluded body pair (`<contact><exclude>`).
#[derive(Debug, Clone, Default)]
pub struct Exclude {
    pub name: String,
    pub line: Line,
    pub body1: String,
    pub body2: String,
}

/// A sensor (`<sensor>` child); types and object kinds as mjtSensor / mjtObj values.
#[derive(Debug, Clone, Default)]
pub struct Sensor {
    pub name: String,
    pub kind: i32,
    pub objtype: i32,
    pub objname: String,
    pub reftype: i32,
    pub refname: String,
    pub cutoff: f64,
    pub noise: f64,
    pub user: Vec<f64>,
    /// user sensors only
    pub dim: i32,
    pub needstage: i32,
    pub datatype: i32,
}

/// Equality constraint; `kind` as mjtEq.
#[derive(Debug, Clone)]
pub struct Equality {
    pub name: String,
    pub line: Line,
    pub kind: i32,
    pub name1: String,
    pub name2: String,
    pub active: bool,
    pub solref: [f64; 2],
    pub solimp: [f64; 5],
    pub data: [f64; 11],
}

impl Default for Equality {
    fn default() -> Self {
        let mut data = [0.0; 11];
        data[1] = 1.0;
        data[10] = 1.0;
        Equality {
            name: String::new(),
            line: -1,
            kind: 0,
            name1: String::new(),
            name2: String::new(),
            active: true,
            solref: default_solref(),
            solimp: default_solimp(),
            data,
        }
    }
}

/// One element of a tendon path; `kind` as mjtWrap (sphere stands for any geom until compiled).
#[derive(Debug, Clone, Default)]
pub struct Wrap {
    pub kind: i32,
    pub name: String,
    pub sidesite: String,
    pub prm: f64,
    pub line: Line,
}

#[derive(Debug, Clone)]
pub struct Tendon {
    pub name: String,
    pub line: Line,
    pub group: i32,
    pub material: String,
    pub limited: i32,
    pub width: f64,
    pub solref_limit: [f64; 2],
    pub solimp_limit: [f64; 5],
    pub solref_friction: [f64; 2],
    pub solimp_friction: [f64; 5],
    pub range: [f64; 2],
    pub margin: f64,
    pub stiffness: f64,
    pub damping: f64,
    pub frictionloss: f64,
    pub springlength: f64,
    pub rgba: [f32; 4],
    pub user: Vec<f64>,
    pub path: Vec<Wrap>,
}

impl Default for Tendon {
    fn default() -> Self {
        Tendon {
            name: String::new(),
            line: -1,
            group: 0,
            material: String::new(),
            limited: 2,
            width: 0.003,
            solref_limit: default_solref(),
            solimp_limit: default_solimp(),
            solref_friction: default_solref(),
            solimp_friction: default_solimp(),
            range: [0.0; 2],
            margin: 0.0,
            stiffness: 0.0,
            damping: 0.0,
            frictionloss: 0.0,
            springlength: -1.0,
            rgba: [0.5, 0.5, 0.5, 1.0],
            user: Vec::new(),
            path: Vec::new(),
        }
    }
}

/// `<hfield>` given by size and grid (elevation from files is not supported yet).
#[derive(Debug, Clone, Default)]
pub struct HField {
    pub name: String,
    pub line: Line,
    pub file: String,
    pub nrow: i32,
    pub ncol: i32,
    pub size: [f64; 4],
    /// contents of `file` (None when it could not be read), set before compiling
    pub bytes: Option<Vec<u8>>,
    /// elevation (rows bottom to top), empty for an all-zero field
    pub data: Vec<f32>,
}

/// `<mesh>`: a file or inline data (empty vectors: not given).
#[derive(Debug, Clone)]
pub struct Mesh {
    pub name: String,
    pub line: Line,
    /// the file as written (after strippath), and its full name once the loader resolved it
    pub short_file: String,
    pub file: String,
    /// contents of `file` (None when it could not be read), set before compiling
    pub bytes: Option<Vec<u8>>,
    pub scale: [f64; 3],
    pub refpos: [f64; 3],
    pub refquat: [f64; 4],
    pub smoothnormal: bool,
    pub vertex: Vec<f32>,
    pub normal: Vec<f32>,
    pub texcoord: Vec<f32>,
    pub face: Vec<i32>,
    /// geom density of the mesh's default class: 2.2.2 weighs the inertia integrals by it
    pub density: f64,
}

impl Default for Mesh {
    fn default() -> Self {
        Mesh {
            name: String::new(),
            line: -1,
            short_file: String::new(),
            file: String::new(),
            bytes: None,
            scale: [1.0; 3],
            refpos: [0.0; 3],
            refquat: [1.0, 0.0, 0.0, 0.0],
            smoothnormal: false,
            vertex: Vec::new(),
            normal: Vec::new(),
            texcoord: Vec::new(),
            face: Vec::new(),
            density: 1000.0,
        }
    }
}

/// `<texture>`; `kind` 0 2d, 1 cube, 2 skybox; `builtin` none, gradient, checker, flat;
/// `mark` none, edge, cross, random.
#[derive(Debug, Clone)]
pub struct Texture {
    pub name: String,
    pub line: Line,
    pub kind: i32,
    pub builtin: i32,
    pub mark: i32,
    pub rgb1: [f64; 3],
    pub rgb2: [f64; 3],
    pub markrgb: [f64; 3],
    pub random: f64,
    pub width: i32,
    pub height: i32,
    /// `file`, then `fileright`, `fileleft`, `fileup`, `filedown`, `filefront`, `fileback`
    pub file_names: [String; 7],
    /// contents of those files (None when missing or unreadable), set before compiling
    pub bytes: [Option<Vec<u8>>; 7],
    pub gridsize: [i32; 2],
    pub gridlayout: String,
    pub hflip: bool,
    pub vflip: bool,
}

impl Default for Texture {
    fn default() -> Self {
        Texture {
            name: String::new(),
            line: -1,
            kind: 1,
            builtin: 0,
            mark: 0,
            rgb1: [0.8; 3],
            rgb2: [0.5; 3],
            markrgb: [0.0; 3],
            random: 0.01,
            width: 0,
            height: 0,
            file_names: Default::default(),
            bytes: Default::default(),
            gridsize: [1, 1],
            gridlayout: "............".into(),
            hflip: false,
            vflip: false,
        }
    }
}

/// One bone of a skin: body, bind pose, vertices and their weights.
#[derive(Debug, Clone, Default)]
pub struct Bone {
    pub body: String,
    pub bindpos: [f32; 3],
    pub bindquat: [f32; 4],
    pub vertid: Vec<i32>,
    pub vertweight: Vec<f32>,
}

/// `<skin>` asset or a composite's skin.
#[derive(Debug, Clone)]
pub struct Skin {
    pub name: String,
    pub line: Line,
    pub file: String,
    /// `file` with the model and mesh directories, set before compiling
    pub path: String,
    pub material: String,
    pub rgba: [f32; 4],
    pub inflate: f32,
    pub group: i32,
    pub vert: Vec<f32>,
    pub texcoord: Vec<f32>,
    pub face: Vec<i32>,
    pub bones: Vec<Bone>,
    /// contents of `file` (None when it could not be read), set before compiling
    pub bytes: Option<Vec<u8>>,
}

impl Default for Skin {
    fn default() -> Self {
        Skin {
            name: String::new(),
            line: -1,
            file: String::new(),
            path: String::new(),
            material: String::new(),
            rgba: [0.5, 0.5, 0.5, 1.0],
            inflate: 0.0,
            group: 0,
            vert: Vec::new(),
            texcoord: Vec::new(),
            face: Vec::new(),
            bones: Vec::new(),
            bytes: None,
        }
    }
}

#[derive(Debug, Clone)]
pub struct Material {
    pub name: String,
    pub line: Line,
    pub texture: String,
    pub texuniform: bool,
    pub texrepeat: [f32; 2],
    pub emission: f32,
    pub specular: f32,
    pub shininess: f32,
    pub reflectance: f32,
    pub rgba: [f32; 4],
}

impl Default for Material {
    fn default() -> Self {
        Material {
            name: String::new(),
            line: -1,
            texture: String::new(),
            texuniform: false,
            texrepeat: [1.0; 2],
            emission: 0.0,
            specular: 0.5,
            shininess: 0.5,
            reflectance: 0.0,
            rgba: [1.0; 4],
        }
    }
}

/// `<custom>` entries: numeric (name, size, data), text (name, data), tuple (name, elements).
#[derive(Debug, Clone, Default)]
pub struct Custom {
    pub numerics: Vec<(String, Line, Vec<f64>)>,
    pub texts: Vec<(String, Line, String)>,
    pub tuples: Vec<(String, Line, Vec<TupleElement>)>,
}

/// One tuple element: mjtObj, object name, parameter.
pub type TupleElement = (i32, String, f64);

/// A default class: the values new elements of each kind start from.
#[derive(Debug, Clone, Default)]
pub struct DefaultClass {
    pub name: String,
    pub parent: Option<usize>,
    pub joint: Joint,
    pub geom: Geom,
    pub site: Site,
    pub camera: Camera,
    pub light: Light,
    pub pair: Pair,
    pub material: Material,
    pub equality: Equality,
    pub tendon: Tendon,
    pub actuator: Actuator,
    pub mesh: Mesh,
}

#[derive(Debug, Clone)]
pub struct Body {
    pub name: String,
    pub line: Line,
    /// NaN first entry: not given
    pub pos: [f64; 3],
    pub quat: [f64; 4],
    pub alt: Alt,
    pub mocap: bool,
    pub explicit_inertial: bool,
    pub ipos: [f64; 3],
    pub iquat: [f64; 4],
    pub ialt: Alt,
    pub mass: f64,
    pub inertia: [f64; 3],
    pub user: Vec<f64>,
    pub joints: Vec<Joint>,
    pub geoms: Vec<Geom>,
    pub sites: Vec<Site>,
    pub cameras: Vec<Camera>,
    pub lights: Vec<Light>,
    pub bodies: Vec<Body>,
}

impl Default for Body {
    fn default() -> Self {
        Body {
            name: String::new(),
            line: -1,
            pos: [NAN, 0.0, 0.0],
            quat: [1.0, 0.0, 0.0, 0.0],
            alt: Alt::default(),
            mocap: false,
            explicit_inertial: false,
            ipos: [NAN, 0.0, 0.0],
            iquat: [1.0, 0.0, 0.0, 0.0],
            ialt: Alt::default(),
            mass: 0.0,
            inertia: [0.0; 3],
            user: Vec::new(),
            joints: Vec::new(),
            geoms: Vec::new(),
            sites: Vec::new(),
            cameras: Vec::new(),
            lights: Vec::new(),
            bodies: Vec::new(),
        }
    }
}

#[derive(Debug, Clone, Default)]
pub struct Key {
    pub name: String,
    pub time: f64,
    pub qpos: Vec<f64>,
    pub qvel: Vec<f64>,
    pub act: Vec<f64>,
    pub mpos: Vec<f64>,
    pub mquat: Vec<f64>,
    pub ctrl: Vec<f64>,
}

/// `inertiafromgeom` setting.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InertiaFromGeom {
    False = 0,
    True = 1,
    Auto = 2,
}

/// `<compiler>` settings that the slice uses.
#[derive(Debug, Clone)]
pub struct CompilerOpts {
    pub autolimits: bool,
    pub boundmass: f64,
    pub boundinertia: f64,
    pub settotalmass: f64,
    pub balanceinertia: bool,
    pub global: bool,
    pub degree: bool,
    pub eulerseq: [u8; 3],
    pub discardvisual: bool,
    pub inertiafromgeom: InertiaFromGeom,
    pub inertiagrouprange: [i32; 2],
    /// `<lengthrange>`: mode (none, muscle, muscleuser, all), useexisting, uselimit
    pub lr_mode: i32,
    pub lr_useexisting: bool,
    pub lr_uselimit: bool,
    /// accel, maxforce, timeconst, timestep, inttotal, inteval, tolrange
    pub lr_numbers: [f64; 7],
    pub meshdir: String,
    pub texturedir: String,
    pub strippath: bool,
    pub convexhull: bool,
    pub exactmeshinertia: bool,
    pub fitaabb: bool,
    pub fusestatic: bool,
}

impl Default for CompilerOpts {
    fn default() -> Self {
        CompilerOpts {
            meshdir: String::new(),
            texturedir: String::new(),
            strippath: false,
            convexhull: true,
            exactmeshinertia: false,
            fitaabb: false,
            fusestatic: false,
            autolimits: false,
            boundmass: 0.0,
            boundinertia: 0.0,
            settotalmass: -1.0,
            balanceinertia: false,
            global: false,
            degree: true,
            eulerseq: *b"xyz",
            discardvisual: false,
            inertiafromgeom: InertiaFromGeom::Auto,
            inertiagrouprange: [0, 5],
            lr_mode: 1,
            lr_useexisting: true,
            lr_uselimit: false,
            lr_numbers: [20.0, 0.0, 1.0, 0.01, 10.0, 2.0, 0.05],
        }
    }
}

/// Everything the reader found.
#[derive(Debug, Clone)]
pub struct ModelSpec {
    pub modelname: String,
    pub compiler: CompilerOpts,
    pub option: mjOption,
    pub visual: mjVisual,
    pub njmax: i32,
    pub nconmax: i32,
    pub nstack: i32,
    pub nuserdata: i32,
    pub nkey: i32,
    /// nuser_body, jnt, geom, site, cam, tendon, actuator, sensor (-1: automatic)
    pub nuser: [i32; 8],
    /// meaninertia, meanmass, meansize, extent overrides (NaN: computed)
    pub stat_override: [f64; 4],
    pub center: [f64; 3],
    pub defaults: Vec<DefaultClass>,
    pub world: Body,
    pub actuators: Vec<Actuator>,
    pub hfields: Vec<HField>,
    pub meshes: Vec<Mesh>,
    pub skins: Vec<Skin>,
    pub textures: Vec<Texture>,
    pub materials: Vec<Material>,
    pub pairs: Vec<Pair>,
    pub excludes: Vec<Exclude>,
    pub equalities: Vec<Equality>,
    pub tendons: Vec<Tendon>,
    pub sensors: Vec<Sensor>,
    pub custom: Custom,
    pub keys: Vec<Key>,
}

impl Default for ModelSpec {
    fn default() -> Self {
        let world = Body {
            name: "world".into(),
            pos: [0.0; 3],
            ipos: [0.0; 3],
            ..Body::default()
        };
        ModelSpec {
            modelname: "MuJoCo Model".into(),
            compiler: CompilerOpts::default(),
            option: default_option(),
            visual: default_visual(),
            njmax: -1,
            nconmax: -1,
            nstack: -1,
            nuserdata: 0,
            nkey: 0,
            nuser: [-1; 8],
            stat_override: [NAN; 4],
            center: [NAN, 0.0, 0.0],
            defaults: vec![DefaultClass {
                name: "main".into(),
                ..DefaultClass::default()
            }],
            world,
            actuators: Vec::new(),
            hfields: Vec::new(),
            meshes: Vec::new(),
            skins: Vec::new(),
            textures: Vec::new(),
            materials: Vec::new(),
            pairs: Vec::new(),
            excludes: Vec::new(),
            equalities: Vec::new(),
            tendons: Vec::new(),
            sensors: Vec::new(),
            custom: Custom::default(),
            keys: Vec::new(),
        }
    }
}
