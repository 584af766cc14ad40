//! Abstract visualization (mjv_): default structs, the scene's buffers and its contents from a
//! model and its state. Beside the engine, never inside it; rendering reads the scene.

#![allow(clippy::needless_range_loop)] // index loops mirror the reference algorithms

mod add;
pub mod camera;
mod catenary;
mod decor;
pub mod defaults;
pub mod geom;
pub mod interact;
pub mod lights;
mod objects;
pub mod scene;
pub mod skin;

use crate::abi::view::Scene;
use crate::abi::*;
use crate::engine::{support, Data, EngineError, Model};
use add::{Ctx, Out, CAT_STATIC};

/// Adds the geoms of the categories in `catmask` (mjv_addGeoms); a full buffer stops adding
/// with a warning.
pub fn add_geoms(
    m: &Model,
    d: &mut Data,
    opt: &mjvOption,
    pert: Option<&mjvPerturb>,
    catmask: i32,
    scn: &mut Scene,
) -> Result<(), EngineError> {
    let local = defaults::perturb();
    let mut catmask = catmask;
    if opt.flags[mjtVisFlag_::mjVIS_STATIC as usize] == 0 {
        catmask &= !CAT_STATIC;
    }
    let c = Ctx {
        m: *m,
        opt,
        pert: pert.unwrap_or(&local),
        catmask,
        scl: m.raw.stat.meansize as f32,
    };
    if add::add_all(&c, d, &mut Out { scn }).is_err() {
        let full = mjtWarning_::mjWARN_VGEOMFULL as i32;
        support::warning(d.raw, full, scn.raw.maxgeom)?;
    }
    Ok(())
}

/// The whole scene (mjv_updateScene): geoms, lights, cameras (unless `cam` is None) and the
/// shown skins.
pub fn update_scene(
    m: &Model,
    d: &mut Data,
    opt: &mjvOption,
    pert: Option<&mjvPerturb>,
    cam: Option<&mut mjvCamera>,
    catmask: i32,
    scn: &mut Scene,
) -> Result<(), EngineError> {
    scn.raw.ngeom = 0;
    add_geoms(m, d, opt, pert, catmask, scn)?;
    lights::make_lights(m, d, scn.raw);
    if let Some(cam) = cam {
        camera::update_camera(m, d, cam, scn.raw)?;
    }
    if opt.flags[mjtVisFlag_::mjVIS_SKIN as usize] != 0 {
        skin::update_skins(m, d, scn.skinvert, scn.skinnormal, opt);
    }
    Ok(())
}
