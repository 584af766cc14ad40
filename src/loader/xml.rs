//! MJCF and URDF models: file to MJCF tree and description, compilation, the compiler's
//! engine steps (constants, length ranges, test step) and the model kept for mj_saveLastXML.

use super::vfs::Vfs;
use super::{new_data, setconst::set_const};
use crate::abi::owned::{blank_model_header, DataBox, ModelBox};
use crate::abi::*;
use crate::compiler;
use crate::engine::forward;
use crate::runtime;
use crate::xml::{include, reader, schema, tree, urdf, writer};
use std::sync::Mutex;

/// A compiled model with what its load leaves besides it.
pub struct Loaded {
    pub model: ModelBox,
    /// The last warning raised while compiling (2.2.2 returns it in the error buffer), or "".
    pub warning: String,
    /// The MJCF tree it was compiled from (URDF converted).
    pub mjcf: tree::Element,
}

/// Text of a model file: from the VFS (a slot without memory is skipped), else disk.
fn load_text(filename: &str, vfs: Option<&Vfs>) -> Result<Vec<u8>, String> {
    if let Some(Some(data)) = vfs.and_then(|v| v.get(filename)) {
        return Ok(data.to_vec());
    }
    std::fs::read(filename).map_err(|_| {
        format!(
            "XML parse error 3:\nError=XML_ERROR_FILE_NOT_FOUND ErrorID=3 (0x3) Line number=0: filename={filename}\n"
        )
    })
}

/// The model file (and its includes) to its MJCF tree and model description.
fn parse(
    fname: &str,
    vfs: Option<&Vfs>,
) -> Result<(tree::Element, compiler::spec::ModelSpec), String> {
    let bytes = load_text(fname, vfs)?;
    let text = String::from_utf8_lossy(&bytes);
    let mut root = tree::parse(text.trim_end_matches('\0'))?;
    if root.name.eq_ignore_ascii_case("robot") {
        // 2.2.2 reads URDF without the MJCF schema check
        let mjcf = urdf::convert(&root)?;
        let spec = reader::read(&mjcf)?;
        return Ok((mjcf, spec));
    }
    if !root.name.eq_ignore_ascii_case("mujoco") {
        return Err(format!(
            "XML Error: Unrecognized XML model type: '{}'",
            root.name
        ));
    }
    let mut included = vec![fname.to_string()];
    let dir = include::file_dir(fname);
    include::expand(
        &mut root,
        &dir,
        &mut |f: &str| load_text(f, vfs),
        &mut included,
    )?;
    schema::check(&root)?;
    let mut spec = reader::read(&root)?;
    compiler::image::load_files(&mut spec, &dir, &mut |f: &str| load_text(f, vfs).ok());
    Ok((root, spec))
}

/// One step from the reset state, as 2.2.2's compiler takes: its warnings (unstable
/// simulation, singular inertia) reach the caller's capture, and the first engine error
/// (raised through mju_error by a callback, or returned) rejects the model. A feature this
/// engine lacks ("not implemented") does not stop a model from loading: the user meets it at
/// the first step. `d` is fresh (reset) data.
fn test_step(m: &ModelBox, d: &mut DataBox) -> Result<(), String> {
    let (stepped, raised) = runtime::capture_errors(|| {
        runtime::guard::catch("mj_step", || forward::step(&m.view(), &mut d.view(m)))
    });
    let returned = match stepped {
        Ok(Ok(())) => None,
        Ok(Err(e)) => Some(e.0),
        Err(panic) => Some(panic),
    };
    match raised.or(returned) {
        Some(e) if !e.contains("not implemented") => Err(e),
        _ => Ok(()),
    }
}

/// The compiler's steps that run the engine on `d`: constants, spring-dampers, length ranges,
/// statistics overrides, reference checks and the test step.
fn finish_compile(
    m: &mut ModelBox,
    mut d: DataBox,
    compiled: &compiler::Compiled,
) -> Result<(), String> {
    set_const(m, &mut d).map_err(|e| format!("Error: engine error: {e}"))?;
    compiler::auto_spring_damper(compiled, &mut m.view_mut());
    super::lengthrange::compile_length_ranges(m, &mut d, &compiled.lropt)
        .map_err(|e| format!("Error: {e}"))?;
    compiler::finish(compiled, m.stat_mut());
    if let Some(msg) = validate::validate_references(m.view()) {
        return Err(format!("Error: {msg}"));
    }
    // the test step starts from fresh data, the reset state: clearing the used data would
    // touch every page of its buffer, most of which the step never reaches
    drop(d);
    let mut d = new_data(m).map_err(|_| "Error: could not create mjData".to_string())?;
    test_step(m, &mut d).map_err(|e| format!("Error: engine error: {e}"))
}

/// Compiles a parsed model; warnings meanwhile go to the caller's capture.
fn compile(spec: compiler::spec::ModelSpec) -> Result<ModelBox, String> {
    // 2.2.2's compiler seeds the C generator (later sensor noise draws from it)
    runtime::random::seed(123);
    let mut compiled = compiler::compile(spec, blank_model_header()).map_err(|e| e.render())?;
    let mut m = ModelBox::new(&compiled.header).map_err(|e| format!("Error: {e}"))?;
    *m.opt_mut() = compiled.option;
    *m.vis_mut() = compiled.visual;
    let nbuffer = m.raw().nbuffer.max(0) as usize;
    let trim = || runtime::memory::release_free_heap(nbuffer);
    compiler::fill(&mut compiled, &mut m.view_mut(), &trim);
    // as 2.2.2's compiler: one mjData serves mj_setConst and the length ranges
    let d = new_data(&m).map_err(|_| "Error: could not create mjData".to_string())?;
    finish_compile(&mut m, d, &compiled)?;
    Ok(m)
}

/// Loads the MJCF or URDF file `filename` (from the VFS, else disk), includes, meshes,
/// textures and skins too; Err carries 2.2.2's message.
pub fn load(filename: &str, vfs: Option<&Vfs>) -> Result<Loaded, String> {
    let (mjcf, spec) = parse(filename, vfs)?;
    // from here on, as in 2.2.2's compiler, warnings go to the error buffer
    let (model, warning) = runtime::capture_warnings(|| compile(spec));
    let model = model?;
    runtime::memory::release_free_heap(model.raw().nbuffer.max(0) as usize);
    Ok(Loaded {
        model,
        warning: warning.unwrap_or_default(),
        mjcf,
    })
}

/// The last model loaded through the C API, as 2.2.2 keeps it for `mj_saveLastXML`: its MJCF
/// tree and the fingerprint of the model compiled from it.
struct LastModel {
    mjcf: tree::Element,
    digest: [u64; 2],
}

static LAST_MODEL: Mutex<Option<LastModel>> = Mutex::new(None);

/// Keeps `loaded` as the last model; gives its model back.
pub fn remember(loaded: Loaded) -> ModelBox {
    if let Ok(mut last) = LAST_MODEL.lock() {
        *last = Some(LastModel {
            mjcf: loaded.mjcf,
            digest: mjb::digest(loaded.model.raw()),
        });
    }
    loaded.model
}

/// Forgets the last model.
pub fn forget() {
    if let Ok(mut last) = LAST_MODEL.lock() {
        *last = None;
    }
}

/// Writes the last model as MJCF to `filename`; `m`, when given, must be that model unchanged.
pub fn save_last(filename: &str, m: Option<&mjModel>) -> Result<(), String> {
    let text = match LAST_MODEL.lock() {
        Ok(last) => last.as_ref().map(|l| {
            // 2.2.2 copies values the user changed in m back into the file; we write the
            // model as loaded, so a changed (or another) model is refused
            let same = m.is_none_or(|m| mjb::digest(m) == l.digest);
            (writer::to_text(&l.mjcf), same)
        }),
        Err(_) => None,
    };
    let Some((text, same)) = text else {
        return Err("No XML model loaded".into());
    };
    if !same {
        return Err(
            "mj_saveLastXML: saving a model that differs from the last loaded one is not implemented"
                .into(),
        );
    }
    std::fs::write(filename, text).map_err(|_| "File not found".to_string())
}
