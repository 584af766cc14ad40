//! The Rust API (src/api) against the C API on the same core: every model of
//! capi-tests/models.list loads to the same MJB bytes with the same warning, and a driven
//! trajectory, Jacobians and the mass matrix are bit-identical; engine errors come back as Err;
//! names, keyframes and the thread-safety markers.

mod common;
use common::*;
use mujoco::abi::{mjData, mjModel, mjtObj_};
use mujoco::capi::{engine as cengine, io as cio, xml as cxml};
use mujoco::runtime::capture_errors;
use mujoco::{Data, Error, Model, ObjKind};
use std::ffi::CString;

/// A model loaded through mj_loadXML, freed on drop.
struct CModel(*mut mjModel, *mut mjData);

impl Drop for CModel {
    fn drop(&mut self) {
        unsafe {
            cio::mj_deleteData(self.1);
            cio::mj_deleteModel(self.0);
        }
    }
}

/// mj_loadXML's model and its error-buffer text.
fn c_load(path: &str) -> (Option<CModel>, String) {
    let name = CString::new(path).unwrap();
    let mut err = vec![0 as std::os::raw::c_char; 1000];
    let m = unsafe { cxml::mj_loadXML(name.as_ptr(), std::ptr::null(), err.as_mut_ptr(), 1000) };
    let text = unsafe { std::ffi::CStr::from_ptr(err.as_ptr()) }
        .to_string_lossy()
        .into_owned();
    if m.is_null() {
        return (None, text);
    }
    let d = unsafe { cio::mj_makeData(m) };
    (Some(CModel(m, d)), text)
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|v| v.to_bits()).collect()
}

/// Sinusoidal controls at step `k`.
fn drive(ctrl: &mut [f64], k: usize) {
    for (i, c) in ctrl.iter_mut().enumerate() {
        *c = (0.01 * k as f64 + i as f64).sin();
    }
}

/// One model: load verdicts, then 200 driven steps and the spatial quantities on both sides.
fn compare(path: &str) -> Result<&'static str, String> {
    let api = Model::from_xml(path);
    let (c, c_text) = c_load(path);
    let (api, c) = match (api, c) {
        (Err(Error::Load(msg)), None) if msg == c_text => return Ok("rejected by both"),
        (Ok(a), Some(c)) => (a, c),
        (a, c) => {
            return Err(format!(
                "verdicts differ: api {:?}, C {} ({c_text})",
                a.as_ref().err(),
                c.is_some()
            ))
        }
    };
    if api.load_warning().unwrap_or("") != c_text {
        return Err(format!("warning {:?} vs {c_text:?}", api.load_warning()));
    }
    let (cm, cd) = (c.0, c.1);
    let cm_ref = unsafe { &*cm };
    if api.to_mjb() != mujoco::abi::mjb::save(cm_ref) {
        return Err("compiled models differ".into());
    }
    if api.arrays().sensor_noise().iter().any(|&n| n != 0.0) {
        // noise draws from C's global rand(), shared with other tests
        return Ok("loaded (sensor noise: not stepped)");
    }
    let mut data: Data = api.make_data().map_err(|e| e.to_string())?;
    let (nq, nv, nu, na) = (api.nq(), api.nv(), api.nu(), api.na());
    let view = |p: *mut f64, n: usize| unsafe { std::slice::from_raw_parts_mut(p, n) };
    let ((), raised) = capture_errors(|| {
        for k in 0..200 {
            drive(view(unsafe { (*cd).ctrl }, nu), k);
            unsafe { cengine::mj_step(cm, cd) };
        }
        unsafe { cengine::mj_forward(cm, cd) };
    });
    let mut api_error = None;
    for k in 0..200 {
        drive(data.ctrl_mut(), k);
        if let Err(e) = data.step() {
            api_error = Some(e);
            break;
        }
    }
    if raised.is_some() || api_error.is_some() {
        // the same engine error on both sides (e.g. a feature not implemented)
        return match (raised, api_error) {
            (Some(r), Some(Error::Engine(a))) if r == a => Ok("same engine error"),
            (r, a) => Err(format!("errors differ: C {r:?}, api {a:?}")),
        };
    }
    data.forward().map_err(|e| e.to_string())?;
    let cdr = unsafe { &*cd };
    let same = [
        (data.qpos(), view(cdr.qpos, nq) as &[f64], "qpos"),
        (data.qvel(), view(cdr.qvel, nv), "qvel"),
        (data.act(), view(cdr.act, na), "act"),
    ];
    for (a, b, what) in same {
        if bits(a) != bits(b) {
            return Err(format!("{what} differs after 200 steps"));
        }
    }
    if data.time().to_bits() != cdr.time.to_bits() {
        return Err("time differs".into());
    }
    let mut full = vec![0.0; nv * nv];
    unsafe { cengine::mj_fullM(cm, full.as_mut_ptr(), cdr.qM) };
    let dense = data.full_mass_matrix();
    if bits(dense.transpose().as_slice()) != bits(&full) {
        return Err("full mass matrix differs".into());
    }
    let mut jp = vec![0.0; 3 * nv];
    let mut jr = vec![0.0; 3 * nv];
    for s in 0..api.nsite() {
        unsafe { cengine::mj_jacSite(cm, cd, jp.as_mut_ptr(), jr.as_mut_ptr(), s as i32) };
        let j = data.jac_site(s).map_err(|e| e.to_string())?;
        if bits(j.translation.transpose().as_slice()) != bits(&jp)
            || bits(j.rotation.transpose().as_slice()) != bits(&jr)
        {
            return Err(format!("site {s} Jacobian differs"));
        }
    }
    for b in 0..api.nbody() {
        unsafe { cengine::mj_jacBodyCom(cm, cd, jp.as_mut_ptr(), jr.as_mut_ptr(), b as i32) };
        let j = data.jac_body_com(b).map_err(|e| e.to_string())?;
        if bits(j.translation.transpose().as_slice()) != bits(&jp)
            || bits(j.rotation.transpose().as_slice()) != bits(&jr)
        {
            return Err(format!("body {b} com Jacobian differs"));
        }
        let p = data.body_pose(b).map_err(|e| e.to_string())?;
        let x = view(cdr.xpos, 3 * api.nbody());
        if bits(p.translation.vector.as_slice()) != bits(&x[3 * b..3 * b + 3]) {
            return Err(format!("body {b} pose differs"));
        }
    }
    Ok("bit-identical")
}

#[test]
fn api_matches_the_c_api_on_the_model_list() {
    let files = models();
    let results: Vec<_> = files.iter().map(|f| (f, compare(f))).collect();
    let failures: Vec<String> = results
        .iter()
        .filter_map(|(f, r)| r.as_ref().err().map(|e| format!("{f}: {e}")))
        .collect();
    let mut counts = std::collections::BTreeMap::new();
    for (_, r) in &results {
        *counts.entry(*r.as_ref().unwrap_or(&"differ")).or_insert(0) += 1;
    }
    report(
        "rust-api",
        &format!(
            "Rust API against the C API: {} models: {counts:?}\n{}",
            files.len(),
            failures.join("\n")
        ),
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn engine_errors_come_back_as_err() {
    // the stack suffices for the test step but not once the boxes touch the floor
    let xml = r#"<mujoco><size nstack="500"/><worldbody><geom type="plane" size="5 5 .1"/>
        <body pos="0 0 0.3"><freejoint/><geom type="box" size=".1 .1 .1"/></body>
        <body pos="0.05 0 0.6"><freejoint/><geom type="box" size=".1 .1 .1"/></body>
        <body pos="0 0.05 0.9"><freejoint/><geom type="box" size=".1 .1 .1"/></body>
        </worldbody></mujoco>"#;
    let model = Model::from_xml_str(xml).unwrap();
    let mut data = model.make_data().unwrap();
    let err = (0..2000).find_map(|_| data.step().err());
    assert_eq!(err, Some(Error::Engine("Stack overflow".into())));
    // a reset data simulates again
    data.reset();
    assert!(data.step().is_ok());
}

#[test]
fn raised_errors_are_captured_not_fatal() {
    // what a user callback calling mju_error during an API call meets: the first message is
    // kept and the process goes on
    let ((), raised) = capture_errors(|| {
        mujoco::runtime::error("first");
        mujoco::runtime::error("second");
    });
    assert_eq!(raised.as_deref(), Some("first"));
    let ((), none) = capture_errors(|| ());
    assert_eq!(none, None);
}

#[test]
fn load_errors_carry_the_c_message() {
    let bad = model("arm3.xml").replace("arm3.xml", "no-such-model.xml");
    let (c, text) = c_load(&bad);
    assert!(c.is_none());
    assert_eq!(Model::from_xml(&bad).err(), Some(Error::Load(text)));
    let err = Model::from_xml_str(
        "<mujoco><worldbody><body><joint type='bogus'/></body></worldbody></mujoco>",
    );
    assert!(
        matches!(err, Err(Error::Load(ref m)) if m.contains("bogus")),
        "{err:?}"
    );
    assert!(Model::from_mjb(b"not an mjb").is_err());
    assert!(Model::from_xml_str("").is_err());
}

#[test]
fn xml_text_with_in_memory_assets() {
    let part = br#"<mujoco><worldbody><body name="b"><freejoint/>
        <geom type="box" size=".1 .1 .1"/></body></worldbody></mujoco>"#;
    let xml = r#"<mujoco><include file="dir/Part.xml"/></mujoco>"#;
    let model = Model::from_xml_with_assets(xml, &[("part.XML", part)]).unwrap();
    assert_eq!((model.nq(), model.nv(), model.nbody()), (7, 6, 2));
    assert!(matches!(
        Model::from_xml_with_assets(xml, &[("", part)]),
        Err(Error::Invalid(_))
    ));
    assert!(matches!(Model::from_xml_str(xml), Err(Error::Load(_))));
}

#[test]
fn named_access_and_keyframes() {
    let arm = model("arm3.xml");
    let model = Model::from_xml(&arm).unwrap();
    let mut data = model.make_data().unwrap();
    assert_eq!(model.id(ObjKind::Joint, "wrist"), Some(2));
    assert_eq!(model.name(ObjKind::Actuator, 1).as_deref(), Some("elbow"));
    assert_eq!(model.name(ObjKind::Actuator, 7), None);
    assert!(matches!(
        data.joint("knee"),
        Err(Error::NotFound { kind: "joint", .. })
    ));
    assert!(data.reset_keyframe(1).is_err());
    data.reset_keyframe_named("home").unwrap();
    assert_eq!(data.joint("elbow").unwrap().qpos(), &[-1.0]);
    data.joint_mut("elbow").unwrap().qvel_mut()[0] = 0.5;
    data.actuator_mut("wrist").unwrap().set_ctrl(1.5);
    assert_eq!(data.qvel(), &[0.0, 0.5, 0.0]);
    assert_eq!(data.actuator("wrist").unwrap().ctrl(), 1.5);
    data.step1().unwrap();
    data.step2().unwrap();
    assert!(data.time() > 0.0);
    data.inverse().unwrap();
    assert_eq!(data.qfrc_inverse().len(), 3);
    let ee = data.site("ee").unwrap();
    let pose = ee.pose();
    assert_eq!(pose.translation.vector, ee.position());
    assert!(data.jac_site(5).is_err());
    assert!(data.integrate_qpos(&[0.0; 2], 1.0).is_err());
    assert_eq!(data.body_positions().shape(), (3, 6));
    // names in the C API's numbering
    assert_eq!(
        model.id(ObjKind::Site, "ee"),
        Some(unsafe {
            let m = Model::from_xml(&arm).unwrap();
            let name = CString::new("ee").unwrap();
            cengine::mj_name2id(m.raw(), mjtObj_::mjOBJ_SITE as i32, name.as_ptr()) as usize
        })
    );
}

#[test]
fn models_are_shared_across_threads() {
    fn send_sync<T: Send + Sync>() {}
    fn send<T: Send>() {}
    send_sync::<Model>();
    send::<Data>();
    let model = Model::from_xml(model("arm3.xml")).unwrap();
    let runs: Vec<Vec<u64>> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..2)
            .map(|_| {
                s.spawn(|| {
                    let mut d = model.make_data().unwrap();
                    for k in 0..100 {
                        drive(d.ctrl_mut(), k);
                        d.step().unwrap();
                    }
                    bits(d.qpos())
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(runs[0], runs[1]);
    let copy = Model::from_mjb(&model.to_mjb()).unwrap();
    assert_eq!(copy.to_mjb(), model.to_mjb());
}
