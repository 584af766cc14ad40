//! URDF loading, mj_saveLastXML / mj_freeLastXML round trips and mj_printSchema against the
//! reference; Debian's prebuilt mujoco-testxml and mujoco-compile run on ours.

mod common;
use common::*;
use std::path::{Path, PathBuf};

const TESTXML: &str = "/usr/bin/mujoco-testxml";
const COMPILE: &str = "/usr/bin/mujoco-compile";

/// The driver built once per library (tests run in parallel and must not rebuild it mid-run).
fn xmlio(lib: Lib) -> PathBuf {
    static BINS: std::sync::Mutex<Vec<(Lib, PathBuf)>> = std::sync::Mutex::new(Vec::new());
    let mut bins = BINS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, p)) = bins.iter().find(|(l, _)| *l == lib) {
        return p.clone();
    }
    let p = compile_c(&[root().join("capi-tests/xmlio/xmlio.c")], "xmlio", lib);
    bins.push((lib, p.clone()));
    p
}

fn urdf_models() -> Vec<String> {
    let dir = root().join("models/extra");
    let mut v: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "urdf"))
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// MJB bytes of `model` loaded by `bin`, or the load error.
fn mjb(bin: &Path, model: &str, tag: &str) -> Result<Vec<u8>, String> {
    let out = work_dir("xml_io").join(format!("{tag}.mjb"));
    let _ = std::fs::remove_file(&out);
    let o = run(bin, &["mjb", model, &out.to_string_lossy()], &[], 120);
    if !o.status.success() {
        return Err(format!("{}{}", text(&o.stdout), text(&o.stderr)));
    }
    std::fs::read(&out).map_err(|e| e.to_string())
}

/// A scratch file next to `model` (saved MJCF refers to assets relative to its directory).
fn beside(model: &str, name: &str) -> String {
    let dir = Path::new(model).parent().unwrap_or(Path::new("."));
    dir.join(format!("_rujoco_{}_{name}", std::process::id()))
        .to_string_lossy()
        .into_owned()
}

#[test]
fn print_schema_matches_reference() {
    require_reference();
    let (r, o) = (xmlio(Lib::Ref), xmlio(Lib::Ours));
    for (html, pad) in [("0", "0"), ("1", "0"), ("1", "1")] {
        let files: Vec<Vec<u8>> = [(&r, "ref"), (&o, "ours")]
            .iter()
            .map(|(bin, tag)| {
                let f = work_dir("xml_io").join(format!("schema-{html}{pad}-{tag}.txt"));
                let out = run(bin, &["schema", &f.to_string_lossy(), html, pad], &[], 60);
                assert!(out.status.success(), "{}", text(&out.stdout));
                std::fs::read(&f).unwrap()
            })
            .collect();
        assert!(!files[0].is_empty());
        assert!(
            files[0] == files[1],
            "mj_printSchema html={html} pad={pad} differs"
        );
    }
}

#[test]
fn urdf_models_match_reference() {
    require_reference();
    let (r, o) = (xmlio(Lib::Ref), xmlio(Lib::Ours));
    let models = urdf_models();
    assert!(!models.is_empty());
    for m in &models {
        let a = mjb(&r, m, "urdf-ref").unwrap_or_else(|e| panic!("reference on {m}: {e}"));
        let b = mjb(&o, m, "urdf-ours").unwrap_or_else(|e| panic!("ours on {m}: {e}"));
        assert!(a == b, "{m}: compiled model differs from the reference");
    }
}

#[test]
fn bad_urdf_is_an_error_not_a_crash() {
    let o = xmlio(Lib::Ours);
    let src = std::fs::read_to_string(root().join("models/extra/urdf_arm.urdf")).unwrap();
    let dir = work_dir("xml_io");
    // drop each line in turn: every variant loads or fails with a message
    let lines: Vec<&str> = src.lines().collect();
    for i in 0..lines.len() {
        let mut v = lines.clone();
        v.remove(i);
        let f = dir.join("mutant.urdf");
        std::fs::write(&f, v.join("\n")).unwrap();
        let out = run(
            &o,
            &[
                "mjb",
                &f.to_string_lossy(),
                &dir.join("m.mjb").to_string_lossy(),
            ],
            &[],
            60,
        );
        let code = out.status.code();
        assert!(
            code == Some(0) || (code == Some(1) && text(&out.stdout).contains("load error")),
            "line {i} removed: {:?} {}{}",
            code,
            text(&out.stdout),
            text(&out.stderr)
        );
    }
}

/// Saves every model with ours, then loads the saved file with both libraries: each must give
/// the model it gives for the original.
#[test]
fn save_last_xml_round_trip() {
    require_reference();
    let (r, o) = (xmlio(Lib::Ref), xmlio(Lib::Ours));
    let mut models = models();
    models.extend(urdf_models());
    let corpus = root().join("../shared/corpus");
    if corpus.exists() {
        let out = std::process::Command::new("find")
            .arg(&corpus)
            .args(["-name", "*.xml"])
            .output()
            .unwrap();
        let mut c: Vec<String> = text(&out.stdout).lines().map(String::from).collect();
        c.sort();
        models.extend(c);
    }
    let (mut tried, mut same_ref, mut same_ours) = (0, 0, 0);
    let mut failures = Vec::new();
    for m in &models {
        if m.contains("_rujoco_") || m.contains("_tempfile_") {
            continue;
        }
        let Ok(ours) = mjb(&o, m, "rt-ours") else {
            continue; // a model ours rejects has nothing to save
        };
        tried += 1;
        // the saved file goes into a directory of links to the model's directory, so that its
        // asset files resolve (never into the shared corpus, which other test runs read)
        let dir = work_dir("xml_io").join("round-trip");
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        if let Some(parent) = std::path::Path::new(m).parent() {
            for e in std::fs::read_dir(parent).into_iter().flatten().flatten() {
                let _ = std::os::unix::fs::symlink(e.path(), dir.join(e.file_name()));
            }
        }
        let saved = dir
            .join("_rujoco_round_trip.xml")
            .to_string_lossy()
            .into_owned();
        let s = run(&o, &["save", m, &saved], &[], 120);
        let back_ours = mjb(&o, &saved, "rt-ours-back");
        let back_ref = mjb(&r, &saved, "rt-ref-back");
        let _ = std::fs::remove_file(&saved);
        assert!(s.status.success(), "{m}: {}", text(&s.stdout));
        if back_ours.as_ref().is_ok_and(|b| *b == ours) {
            same_ours += 1;
        } else {
            failures.push(format!("{m}: ours reloads a different model"));
        }
        match (mjb(&r, m, "rt-ref"), back_ref) {
            (Ok(a), Ok(b)) if a == b => same_ref += 1,
            (a, b) => failures.push(format!(
                "{m}: reference on saved file differs ({:?} / {:?})",
                a.err(),
                b.err()
            )),
        }
    }
    report(
        "xml_io",
        &format!(
            "mj_saveLastXML round trip: {tried} models loaded by ours; reloaded identically by \
             ours {same_ours}, by the reference {same_ref}\n{}\n",
            failures.join("\n")
        ),
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn max_difference(out: &str) -> Option<f64> {
    out.lines()
        .find(|l| l.contains("Max difference"))?
        .split(':')
        .nth(1)?
        .trim()
        .parse()
        .ok()
}

/// Debian's prebuilt testxml (load, mj_saveLastXML, reload, compare) on both libraries. 2.2.2
/// writes compiled values rounded, so its reloaded model differs by rounding; ours writes the
/// model as loaded and must reload it exactly.
#[test]
fn testxml_runs_on_ours() {
    require_reference();
    if !Path::new(TESTXML).exists() {
        eprintln!("{TESTXML} missing: install libmujoco-samples");
        return;
    }
    let ld = lib_dir()
        .canonicalize()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    let mut lines = Vec::new();
    // testxml takes only file names containing ".xml"
    for m in models().into_iter().filter(|m| m.contains(".xml")) {
        let r = run(TESTXML.as_ref(), &[&m], &[], 120);
        let o = run(TESTXML.as_ref(), &[&m], &[("LD_LIBRARY_PATH", &ld)], 120);
        let (rd, od) = (
            max_difference(&text(&r.stdout)),
            max_difference(&text(&o.stdout)),
        );
        assert!(
            rd.is_some(),
            "reference testxml on {m}: {}",
            text(&r.stdout)
        );
        assert_eq!(od, Some(0.0), "our testxml on {m}: {}", text(&o.stdout));
        assert_eq!(o.status.code(), r.status.code(), "{m}");
        lines.push(format!(
            "{m}: max difference ref {:e}, ours 0",
            rd.unwrap_or(0.0)
        ));
    }
    report("testxml", &lines.join("\n"));
}

/// mujoco-compile writes MJCF through mj_saveLastXML: a URDF compiled to MJCF by ours loads
/// in the reference as the URDF itself does.
#[test]
fn compile_urdf_to_mjcf_on_ours() {
    require_reference();
    if !Path::new(COMPILE).exists() {
        eprintln!("{COMPILE} missing: install libmujoco-samples");
        return;
    }
    let r = xmlio(Lib::Ref);
    let ld = lib_dir()
        .canonicalize()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    for m in urdf_models() {
        let out = beside(&m, "compiled.xml");
        let o = run(
            COMPILE.as_ref(),
            &[&m, &out],
            &[("LD_LIBRARY_PATH", &ld)],
            120,
        );
        let back = mjb(&r, &out, "compile-back");
        let _ = std::fs::remove_file(&out);
        assert!(o.status.success(), "{m}: {}", text(&o.stdout));
        let orig = mjb(&r, &m, "compile-orig").unwrap();
        assert!(back.is_ok_and(|b| b == orig), "{m}: compiled MJCF differs");
    }
}

/// 2.2.2 writes values changed in the model after loading; ours cannot yet and must say so.
#[test]
fn save_changed_model_is_refused() {
    let o = xmlio(Lib::Ours);
    let m = root().join("models/extra/urdf_arm.urdf");
    let saved = beside(&m.to_string_lossy(), "changed.xml");
    let out = run(&o, &["changed", &m.to_string_lossy(), &saved], &[], 60);
    let _ = std::fs::remove_file(&saved);
    let t = text(&out.stdout);
    assert!(
        t.starts_with("saved 0:") && t.contains("not implemented"),
        "{t}"
    );
}

/// Attribute mutants of the URDF test models (dropped, not a number, too short, negated):
/// ours loads exactly those the reference loads, into the identical model, and otherwise fails
/// with a message (where the reference crashes, ours must not).
#[test]
fn urdf_mutants_match_reference() {
    require_reference();
    let (r, o) = (xmlio(Lib::Ref), xmlio(Lib::Ours));
    let dir = work_dir("xml_io");
    let (mut total, mut loaded, mut same_msg, mut failed) = (0, 0, 0, 0);
    for m in urdf_models() {
        let src = std::fs::read_to_string(&m).unwrap();
        let mut mutants = Vec::new();
        let mut at = 0;
        while let Some(q) = src[at..].find("=\"") {
            let start = at + q + 2;
            let end = start + src[start..].find('"').unwrap();
            let key = src[..at + q].rfind(' ').unwrap();
            let val = &src[start..end];
            let first = val.split(' ').next().unwrap_or("");
            mutants.push(format!("{}{}", &src[..key], &src[end + 1..]));
            mutants.push(format!("{}x{}", &src[..start], &src[end..]));
            mutants.push(format!("{}{first}{}", &src[..start], &src[end..]));
            mutants.push(format!("{}-{val}{}", &src[..start], &src[end..]));
            at = end;
        }
        for text_ in mutants {
            let f = dir.join("attr-mutant.urdf");
            std::fs::write(&f, &text_).unwrap();
            let f = f.to_string_lossy().into_owned();
            let (a, b) = (mjb(&r, &f, "mut-ref"), mjb(&o, &f, "mut-ours"));
            total += 1;
            match (a, b) {
                (Ok(a), Ok(b)) => {
                    assert!(a == b, "mutant loads differently:\n{text_}");
                    loaded += 1;
                }
                (Err(a), Err(b)) => {
                    failed += 1;
                    // the reference crashes (empty output) on an unknown joint type
                    assert!(b.contains("load error"), "{b}");
                    same_msg += usize::from(a == b);
                }
                (a, b) => panic!("reference {:?} / ours {:?} on\n{text_}", a.err(), b.err()),
            }
        }
    }
    report(
        "urdf_mutants",
        &format!(
            "{total} URDF mutants: {loaded} load identically, {failed} fail in both \
             ({same_msg} with the same message)\n"
        ),
    );
}
