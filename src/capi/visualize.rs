//! C entry points of abstract visualization (mjv_): argument checks, then `crate::visualize`.

use super::engine::{run, run_const};
use super::{errmem, guard};
use crate::abi::view::{scene_skinvert, Data, EngineError, Model, Scene};
use crate::abi::*;
use crate::visualize::{camera, defaults, geom, interact, lights, scene, skin};
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

unsafe fn read<const N: usize>(p: *const mjtNum) -> Option<[mjtNum; N]> {
    slice(p, N).map(|s| std::array::from_fn(|i| s[i]))
}

unsafe fn write(p: *mut mjtNum, v: &[mjtNum]) {
    if !p.is_null() {
        std::ptr::copy_nonoverlapping(v.as_ptr(), p, v.len());
    }
}

type PoseMap = fn(&[f64; 3], &[f64; 4], &mjvScene) -> Result<([f64; 3], [f64; 4]), EngineError>;

/// A pose transform of the scene (room2model, model2room) on C arrays.
unsafe fn transform_pose(
    name: &str,
    pos: *mut mjtNum,
    quat: *mut mjtNum,
    frompos: *const mjtNum,
    fromquat: *const mjtNum,
    scn: *const mjvScene,
    f: PoseMap,
) {
    let (Some(p), Some(q), Some(scn)) = (read::<3>(frompos), read::<4>(fromquat), scn.as_ref())
    else {
        return errmem::error(&format!("{name}: NULL argument"));
    };
    guard(name, (), || {
        let (p, q) = f(&p, &q, scn)?;
        write(pos, &p);
        write(quat, &q);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_room2model(
    modelpos: *mut mjtNum,
    modelquat: *mut mjtNum,
    roompos: *const mjtNum,
    roomquat: *const mjtNum,
    scn: *const mjvScene,
) {
    let f = interact::room2model;
    transform_pose(
        "mjv_room2model",
        modelpos,
        modelquat,
        roompos,
        roomquat,
        scn,
        f,
    )
}

#[no_mangle]
pub unsafe extern "C" fn mjv_model2room(
    roompos: *mut mjtNum,
    roomquat: *mut mjtNum,
    modelpos: *const mjtNum,
    modelquat: *const mjtNum,
    scn: *const mjvScene,
) {
    let f = interact::model2room;
    transform_pose(
        "mjv_model2room",
        roompos,
        roomquat,
        modelpos,
        modelquat,
        scn,
        f,
    )
}

type CameraFrame = fn(&mjvScene) -> Result<([f64; 3], [f64; 3], [f64; 3]), EngineError>;

unsafe fn camera_frame(
    name: &str,
    headpos: *mut mjtNum,
    forward: *mut mjtNum,
    up: *mut mjtNum,
    scn: *const mjvScene,
    f: CameraFrame,
) {
    let Some(scn) = scn.as_ref() else {
        return errmem::error(&format!("{name}: NULL scene"));
    };
    guard(name, (), || {
        let (h, fw, u) = f(scn)?;
        write(headpos, &h);
        write(forward, &fw);
        write(up, &u);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_cameraInModel(
    headpos: *mut mjtNum,
    forward: *mut mjtNum,
    up: *mut mjtNum,
    scn: *const mjvScene,
) {
    let f = interact::camera_in_model;
    camera_frame("mjv_cameraInModel", headpos, forward, up, scn, f)
}

#[no_mangle]
pub unsafe extern "C" fn mjv_cameraInRoom(
    headpos: *mut mjtNum,
    forward: *mut mjtNum,
    up: *mut mjtNum,
    scn: *const mjvScene,
) {
    let f = interact::camera_in_room;
    camera_frame("mjv_cameraInRoom", headpos, forward, up, scn, f)
}

#[no_mangle]
pub unsafe extern "C" fn mjv_frustumHeight(scn: *const mjvScene) -> mjtNum {
    let Some(scn) = scn.as_ref() else {
        errmem::error("mjv_frustumHeight: NULL scene");
        return 0.0;
    };
    guard("mjv_frustumHeight", 0.0, || interact::frustum_height(scn))
}

#[no_mangle]
pub unsafe extern "C" fn mjv_alignToCamera(
    res: *mut mjtNum,
    vec: *const mjtNum,
    forward: *const mjtNum,
) {
    if let (Some(v), Some(f)) = (read::<3>(vec), read::<3>(forward)) {
        write(res, &interact::align_to_camera(&v, &f));
    }
}

#[no_mangle]
pub unsafe extern "C" fn mjv_moveCamera(
    m: *const mjModel,
    action: c_int,
    reldx: mjtNum,
    reldy: mjtNum,
    scn: *const mjvScene,
    cam: *mut mjvCamera,
) {
    let (Some(m), Some(scn), Some(cam)) = (m.as_ref(), scn.as_ref(), cam.as_mut()) else {
        return errmem::error("mjv_moveCamera: NULL argument");
    };
    guard("mjv_moveCamera", (), || {
        interact::move_camera(&Model::new(m), action, reldx, reldy, scn, cam)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_movePerturb(
    m: *const mjModel,
    d: *const mjData,
    action: c_int,
    reldx: mjtNum,
    reldy: mjtNum,
    scn: *const mjvScene,
    pert: *mut mjvPerturb,
) {
    let (Some(scn), Some(pert)) = (scn.as_ref(), pert.as_mut()) else {
        return errmem::error("mjv_movePerturb: NULL argument");
    };
    run_const("mjv_movePerturb", (), m, d, |m, d| {
        interact::move_perturb(m, d, action, reldx, reldy, scn, pert)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_moveModel(
    m: *const mjModel,
    action: c_int,
    reldx: mjtNum,
    reldy: mjtNum,
    roomup: *const mjtNum,
    scn: *mut mjvScene,
) {
    let (Some(m), Some(up), Some(scn)) = (m.as_ref(), read::<3>(roomup), scn.as_mut()) else {
        return errmem::error("mjv_moveModel: NULL argument");
    };
    guard("mjv_moveModel", (), || {
        interact::move_model(&Model::new(m), action, reldx, reldy, &up, scn)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_initPerturb(
    m: *const mjModel,
    d: *const mjData,
    scn: *const mjvScene,
    pert: *mut mjvPerturb,
) {
    let (Some(scn), Some(pert)) = (scn.as_ref(), pert.as_mut()) else {
        return errmem::error("mjv_initPerturb: NULL argument");
    };
    run_const("mjv_initPerturb", (), m, d, |m, d| {
        interact::init_perturb(m, d, scn, pert)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_applyPerturbPose(
    m: *const mjModel,
    d: *mut mjData,
    pert: *const mjvPerturb,
    flg_paused: c_int,
) {
    let Some(pert) = pert.as_ref() else {
        return errmem::error("mjv_applyPerturbPose: NULL perturbation");
    };
    run("mjv_applyPerturbPose", (), m, d, |m, d| {
        interact::apply_perturb_pose(m, d, pert, flg_paused != 0);
        Ok(())
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_applyPerturbForce(
    m: *const mjModel,
    d: *mut mjData,
    pert: *const mjvPerturb,
) {
    let Some(pert) = pert.as_ref() else {
        return errmem::error("mjv_applyPerturbForce: NULL perturbation");
    };
    run("mjv_applyPerturbForce", (), m, d, |m, d| {
        interact::apply_perturb_force(m, d, pert)
    })
}

#[no_mangle]
pub unsafe extern "C" fn mjv_averageCamera(
    cam1: *const mjvGLCamera,
    cam2: *const mjvGLCamera,
) -> mjvGLCamera {
    match (cam1.as_ref(), cam2.as_ref()) {
        (Some(a), Some(b)) => interact::average_camera(a, b),
        _ => {
            errmem::error("mjv_averageCamera: NULL camera");
            mjvGLCamera::default()
        }
    }
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mjv_select(
    m: *const mjModel,
    d: *const mjData,
    vopt: *const mjvOption,
    aspectratio: mjtNum,
    relx: mjtNum,
    rely: mjtNum,
    scn: *const mjvScene,
    selpnt: *mut mjtNum,
    geomid: *mut c_int,
    skinid: *mut c_int,
) -> c_int {
    let (Some(opt), Some(scn)) = (vopt.as_ref(), scn.as_ref()) else {
        errmem::error("mjv_select: NULL argument");
        return -1;
    };
    run_const("mjv_select", -1, m, d, |m, d| {
        let skinvert = scene_skinvert(scn);
        let s = interact::select(m, d, opt, aspectratio, relx, rely, scn, skinvert)?;
        if let Some(p) = s.point {
            write(selpnt, &p);
        }
        for (out, v) in [(geomid, s.geom), (skinid, s.skin)] {
            if !out.is_null() {
                *out = v;
            }
        }
        Ok(s.body)
    })
}
