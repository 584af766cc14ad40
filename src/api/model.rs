//! A compiled model, owned.

use super::{Data, Error};
use crate::abi::mjModel;
use crate::abi::owned::ModelBox;
use crate::engine::support;
use crate::loader::{self, vfs::Vfs};
use crate::runtime::guard::catch;

/// Kinds of named objects (a subset of `mjtObj`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ObjKind {
    Body,
    Joint,
    Geom,
    Site,
    Camera,
    Tendon,
    Actuator,
    Sensor,
    Key,
}

impl ObjKind {
    fn code(self) -> i32 {
        use crate::abi::mjtObj_::*;
        (match self {
            ObjKind::Body => mjOBJ_BODY,
            ObjKind::Joint => mjOBJ_JOINT,
            ObjKind::Geom => mjOBJ_GEOM,
            ObjKind::Site => mjOBJ_SITE,
            ObjKind::Camera => mjOBJ_CAMERA,
            ObjKind::Tendon => mjOBJ_TENDON,
            ObjKind::Actuator => mjOBJ_ACTUATOR,
            ObjKind::Sensor => mjOBJ_SENSOR,
            ObjKind::Key => mjOBJ_KEY,
        }) as i32
    }

    pub(crate) fn label(self) -> &'static str {
        match self {
            ObjKind::Body => "body",
            ObjKind::Joint => "joint",
            ObjKind::Geom => "geom",
            ObjKind::Site => "site",
            ObjKind::Camera => "camera",
            ObjKind::Tendon => "tendon",
            ObjKind::Actuator => "actuator",
            ObjKind::Sensor => "sensor",
            ObjKind::Key => "keyframe",
        }
    }
}

/// A compiled model (`mjModel`): loaded from MJCF/URDF or MJB, freed on drop.
///
/// Immutable once loaded: share it by reference among threads, one [`Data`] per thread.
///
/// ```
/// let model = mujoco::Model::from_xml("models/arm3.xml")?;
/// assert_eq!((model.nq(), model.nv(), model.nu()), (3, 3, 3));
/// assert_eq!(model.id(mujoco::ObjKind::Joint, "elbow"), Some(1));
/// let copy = mujoco::Model::from_mjb(&model.to_mjb())?;
/// assert_eq!(copy.to_mjb(), model.to_mjb());
/// # Ok::<(), mujoco::Error>(())
/// ```
pub struct Model {
    pub(crate) raw: ModelBox,
    warning: Option<String>,
}

impl std::fmt::Debug for Model {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Model")
            .field("nq", &self.nq())
            .field("nv", &self.nv())
            .field("nu", &self.nu())
            .field("nbody", &self.nbody())
            .finish_non_exhaustive()
    }
}

impl Model {
    fn load(filename: &str, vfs: Option<&Vfs>) -> Result<Model, Error> {
        match catch("mj_loadXML", || loader::xml::load(filename, vfs)) {
            Ok(Ok(loaded)) => Ok(Model {
                warning: (!loaded.warning.is_empty()).then_some(loaded.warning),
                raw: loaded.model,
            }),
            Ok(Err(msg)) | Err(msg) => Err(Error::Load(msg)),
        }
    }

    /// Loads an MJCF or URDF file (with its includes, meshes, textures), as `mj_loadXML`.
    ///
    /// Loading seeds C's `rand()` with 123, as 2.2.2's compiler does (sensor noise draws from
    /// it).
    pub fn from_xml(path: impl AsRef<std::path::Path>) -> Result<Model, Error> {
        Self::load(&path.as_ref().to_string_lossy(), None)
    }

    /// Loads MJCF text; the files it names are read from disk (relative to the working
    /// directory).
    pub fn from_xml_str(xml: &str) -> Result<Model, Error> {
        Self::from_xml_with_assets(xml, &[])
    }

    /// Loads MJCF text with in-memory assets (name, contents) for the files it names (looked
    /// up by file name without directory, case-insensitively, as 2.2.2's VFS does; other
    /// files are read from disk).
    pub fn from_xml_with_assets(xml: &str, assets: &[(&str, &[u8])]) -> Result<Model, Error> {
        const NAME: &str = "__model__.xml";
        let keys = assets
            .iter()
            .map(|(name, _)| loader::vfs::key(name).map_err(|e| Error::Invalid(e.into())))
            .collect::<Result<Vec<_>, _>>()?;
        let mut vfs = Vfs::new();
        vfs.push(NAME.as_bytes(), Some(xml.as_bytes()));
        for (key, (_, data)) in keys.iter().zip(assets) {
            vfs.push(key.as_bytes(), Some(data));
        }
        Self::load(NAME, Some(&vfs))
    }

    /// Loads an MJB image (as `mj_loadModel` reads a file).
    pub fn from_mjb(bytes: &[u8]) -> Result<Model, Error> {
        match catch("mj_loadModel", || ModelBox::from_mjb(bytes, false)) {
            Ok(Ok(raw)) => Ok(Model { raw, warning: None }),
            Ok(Err(e)) => Err(Error::Load(e.message().to_string())),
            Err(msg) => Err(Error::Load(msg)),
        }
    }

    /// The MJB image (what `mj_saveModel` writes).
    pub fn to_mjb(&self) -> Vec<u8> {
        self.raw.save()
    }

    /// The last warning the compiler raised (what `mj_loadXML` leaves in its error buffer).
    pub fn load_warning(&self) -> Option<&str> {
        self.warning.as_deref()
    }

    /// New simulation data for this model, reset (`mj_makeData`).
    pub fn make_data(&self) -> Result<Data<'_>, Error> {
        match catch("mj_makeData", || loader::new_data(&self.raw)) {
            Ok(Ok(raw)) => Ok(Data::new(self, raw)),
            Ok(Err(msg)) | Err(msg) => Err(Error::Engine(msg)),
        }
    }

    /// Every `mjModel` array by its 2.2.2 name, read-only (`model.arrays().body_pos()`).
    pub fn arrays(&self) -> crate::abi::view::Model<'_> {
        self.raw.view()
    }

    /// The `mjModel` header: sizes, options, statistics (read-only).
    pub fn raw(&self) -> &mjModel {
        self.raw.raw()
    }

    /// Id of the object of `kind` named `name`.
    pub fn id(&self, kind: ObjKind, name: &str) -> Option<usize> {
        let id = support::name2id(&self.raw.view(), kind.code(), name.as_bytes());
        usize::try_from(id).ok()
    }

    /// Id of the object, or [`Error::NotFound`].
    pub fn require_id(&self, kind: ObjKind, name: &str) -> Result<usize, Error> {
        self.id(kind, name).ok_or_else(|| Error::NotFound {
            kind: kind.label(),
            name: name.into(),
        })
    }

    /// Name of object `id` of `kind` (None when out of range; "" when unnamed).
    pub fn name(&self, kind: ObjKind, id: usize) -> Option<String> {
        let id = i32::try_from(id).ok()?;
        let adr = support::id2name(&self.raw.view(), kind.code(), id)?;
        let bytes: Vec<u8> = (self.raw.view().names().get(adr..)?.iter())
            .take_while(|&&c| c != 0)
            .map(|&c| c as u8)
            .collect();
        Some(String::from_utf8_lossy(&bytes).into_owned())
    }

    pub fn nq(&self) -> usize {
        self.raw().nq.max(0) as usize
    }
    pub fn nv(&self) -> usize {
        self.raw().nv.max(0) as usize
    }
    pub fn nu(&self) -> usize {
        self.raw().nu.max(0) as usize
    }
    pub fn na(&self) -> usize {
        self.raw().na.max(0) as usize
    }
    pub fn nbody(&self) -> usize {
        self.raw().nbody.max(0) as usize
    }
    pub fn njnt(&self) -> usize {
        self.raw().njnt.max(0) as usize
    }
    pub fn nsite(&self) -> usize {
        self.raw().nsite.max(0) as usize
    }
    pub fn nsensor(&self) -> usize {
        self.raw().nsensor.max(0) as usize
    }
    pub fn nsensordata(&self) -> usize {
        self.raw().nsensordata.max(0) as usize
    }
    pub fn nkey(&self) -> usize {
        self.raw().nkey.max(0) as usize
    }

    /// The simulation time step.
    pub fn timestep(&self) -> f64 {
        self.raw().opt.timestep
    }
}
