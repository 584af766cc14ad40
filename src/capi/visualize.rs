//! C entry points of abstract visualization (mjv_): argument checks, then `crate::visualize`.

use super::{errmem, guard};
use crate::abi::view::{Data, EngineError, Model, Scene};
use crate::abi::*;
use crate::visualize::{camera, defaults, geom, lights, scene, skin};
use std::os::raw::c_int;

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultCamera(cam: *mut mjvCamera) {
    if let Some(cam) = cam.as_mut() {
        *cam = defaults::camera();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultFreeCamera(m: *const mjModel, cam: *mut mjvCamera) {
    if let (Some(m), Some(cam)) = (m.as_ref(), cam.as_mut()) {
        *cam = defaults::free_camera(m);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultPerturb(pert: *mut mjvPerturb) {
    if let Some(pert) = pert.as_mut() {
        *pert = defaults::perturb();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultOption(opt: *mut mjvOption) {
    if let Some(opt) = opt.as_mut() {
        *opt = defaults::option();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultFigure(fig: *mut mjvFigure) {
    if let Some(fig) = fig.as_mut() {
        defaults::figure(fig);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_defaultScene(scn: *mut mjvScene) {
    if let Some(scn) = scn.as_mut() {
        *scn = std::mem::zeroed();
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_makeScene(m: *const mjModel, scn: *mut mjvScene, maxgeom: c_int) {
    if let Some(scn) = scn.as_mut() {
        scene::make_scene(m.as_ref(), scn, maxgeom);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_freeScene(scn: *mut mjvScene) {
    if let Some(scn) = scn.as_mut() {
        scene::free_scene(scn);
    }
}

/// Runs `f` on views of the model, data and scene under `guard`, after NULL checks.
unsafe fn with_scene(
    name: &str,
    m: *const mjModel,
    d: *mut mjData,
    scn: *mut mjvScene,
    f: impl FnOnce(&Model, &mut Data, &mut Scene) -> Result<(), EngineError>,
) {
    if m.is_null() || d.is_null() || scn.is_null() {
        errmem::error(&format!("{name}: NULL model, data or scene"));
        return;
    }
    guard(name, (), || {
        let mv = Model::new(&*m);
        let mut dv = Data::new(&*m, &mut *d);
        let mut sv = Scene::new(&mut *scn);
        f(&mv, &mut dv, &mut sv)
    })
}

unsafe fn slice<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    (!p.is_null()).then(|| std::slice::from_raw_parts(p, n))
}

#[no_mangle]
pub unsafe extern "C" fn mjv_initGeom(
    geom: *mut mjvGeom,
    r#type: c_int,
    size: *const mjtNum,
    pos: *const mjtNum,
    mat: *const mjtNum,
    rgba: *const f32,
) {
    let Some(g) = geom.as_mut() else { return };
    let rgba = slice(rgba, 4).map(geom::arr);
    geom::init_geom(
        g,
        r#type,
        slice(size, 3),
        slice(pos, 3),
        slice(mat, 9),
        rgba,
    );
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mjv_makeConnector(
    geom: *mut mjvGeom,
    r#type: c_int,
    width: mjtNum,
    a0: mjtNum,
    a1: mjtNum,
    a2: mjtNum,
    b0: mjtNum,
    b1: mjtNum,
    b2: mjtNum,
) {
    if !geom::is_connector(r#type) {
        errmem::error(&format!("Invalid geom type {type} for connector"));
        return;
    }
    if let Some(g) = geom.as_mut() {
        geom::make_connector(g, r#type, width, [a0, a1, a2], [b0, b1, b2]);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_addGeoms(
    m: *const mjModel,
    d: *mut mjData,
    opt: *const mjvOption,
    pert: *const mjvPerturb,
    catmask: c_int,
    scn: *mut mjvScene,
) {
    let Some(opt) = opt.as_ref() else {
        return errmem::error("mjv_addGeoms: NULL option");
    };
    with_scene("mjv_addGeoms", m, d, scn, |m, d, scn| {
        crate::visualize::add_geoms(m, d, opt, pert.as_ref(), catmask, scn)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_makeLights(m: *const mjModel, d: *mut mjData, scn: *mut mjvScene) {
    with_scene("mjv_makeLights", m, d, scn, |m, d, scn| {
        lights::make_lights(m, d, scn.raw);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_updateCamera(
    m: *const mjModel,
    d: *mut mjData,
    cam: *mut mjvCamera,
    scn: *mut mjvScene,
) {
    // 2.2.2 returns quietly without a model or camera
    let Some(cam) = cam.as_mut().filter(|_| !m.is_null()) else {
        return;
    };
    with_scene("mjv_updateCamera", m, d, scn, |m, d, scn| {
        camera::update_camera(m, d, cam, scn.raw)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_updateScene(
    m: *const mjModel,
    d: *mut mjData,
    opt: *const mjvOption,
    pert: *const mjvPerturb,
    cam: *mut mjvCamera,
    catmask: c_int,
    scn: *mut mjvScene,
) {
    let Some(opt) = opt.as_ref() else {
        return errmem::error("mjv_updateScene: NULL option");
    };
    with_scene("mjv_updateScene", m, d, scn, |m, d, scn| {
        crate::visualize::update_scene(m, d, opt, pert.as_ref(), cam.as_mut(), catmask, scn)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_updateActiveSkin(
    m: *const mjModel,
    d: *mut mjData,
    scn: *mut mjvScene,
    opt: *const mjvOption,
) {
    let Some(opt) = opt.as_ref() else {
        return errmem::error("mjv_updateActiveSkin: NULL option");
    };
    with_scene("mjv_updateActiveSkin", m, d, scn, |m, d, scn| {
        skin::update_skins(m, d, scn.skinvert, scn.skinnormal, opt);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_updateSkin(m: *const mjModel, d: *mut mjData, scn: *mut mjvScene) {
    let opt = defaults::option();
    mjv_updateActiveSkin(m, d, scn, &opt);
    errmem::warning("mjv_updateSkin is deprecated, please use mjv_updateActiveSkin.");
}
