//! mj_printModel and mj_printData write the reference's text (after 50 steps, on models.list
//! and a few corpus models), and the VFS functions give the reference's codes and load the
//! same models from memory (capi-tests/printvfs.c on both libraries). Every printed number
//! is compared, `maxuse_stack` (the stack's high-water mark) included.

mod common;
use common::*;
use std::path::Path;

fn corpus_sample() -> Vec<String> {
    let want = [
        "model/humanoid/humanoid.xml",
        "suite/quadruped.xml",
        "model/mug/mug.xml",
        "testdata/torus.xml",
    ];
    corpus_files()
        .into_iter()
        .map(|f| f.to_string_lossy().into_owned())
        .filter(|f| want.iter().any(|w| f.ends_with(w)))
        .collect()
}

/// A directory of links to the entries beside `model` (the VFS driver works in it, and the
/// warnings it logs land there, not beside the model); returns the model's path in it.
fn mirror(model: &str, dir: &Path) -> String {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).unwrap();
    let m = Path::new(model);
    for e in std::fs::read_dir(m.parent().unwrap()).unwrap().flatten() {
        if e.file_name() != "MUJOCO_LOG.TXT" {
            let _ = std::os::unix::fs::symlink(e.path(), dir.join(e.file_name()));
        }
    }
    dir.canonicalize()
        .unwrap()
        .join(m.file_name().unwrap())
        .to_string_lossy()
        .into_owned()
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap_or_else(|_| format!("({name} missing)"))
}

#[test]
fn print_and_vfs_match_reference() {
    let src = [root().join("capi-tests/printvfs.c")];
    let (r, o) = (
        compile_c(&src, "printvfs", Lib::Ref),
        compile_c(&src, "printvfs", Lib::Ours),
    );
    let mut models = models();
    models.extend(corpus_sample());
    let base = work_dir("printvfs");
    let (mut same, mut vfs_same) = (0, 0);
    let mut wrong = Vec::new();
    for (i, m) in models.iter().enumerate() {
        let (dr, dout) = (
            base.join(format!("{i}-ref")),
            base.join(format!("{i}-ours")),
        );
        for d in [&dr, &dout] {
            let _ = std::fs::remove_dir_all(d);
            std::fs::create_dir_all(d).unwrap();
        }
        let (dr, dout) = (dr.canonicalize().unwrap(), dout.canonicalize().unwrap());
        let (drs, dos) = (dr.to_string_lossy(), dout.to_string_lossy());
        let pr = text(&run(&r, &["print", m, &drs], &[], 120).stdout);
        let po = text(&run(&o, &["print", m, &dos], &[], 120).stdout);
        if pr == po
            && read(&dr, "model.txt") == read(&dout, "model.txt")
            && read(&dr, "data.txt") == read(&dout, "data.txt")
        {
            same += 1;
        } else {
            wrong.push(format!("print: {m}"));
        }
        let mr = mirror(m, &base.join(format!("{i}-ref-vfs")));
        let mo = mirror(m, &base.join(format!("{i}-ours-vfs")));
        let vr = text(&run(&r, &["vfs", &mr, &drs], &[], 120).stdout);
        let vo = text(&run(&o, &["vfs", &mo, &dos], &[], 120).stdout);
        if vr == vo && read(&dr, "vfs_model.txt") == read(&dout, "vfs_model.txt") {
            vfs_same += 1;
        } else {
            wrong.push(format!(
                "vfs: {m}\n    reference: {vr}\n    ours:      {vo}"
            ));
        }
    }
    let msg = format!(
        "mj_printModel / mj_printData: {same} of {} models print identically (maxuse_stack \
         included); VFS: {vfs_same} identical\n{}",
        models.len(),
        wrong.iter().map(|w| format!("  {w}\n")).collect::<String>()
    );
    report("print-vfs", &msg);
    assert!(wrong.is_empty(), "{msg}");
}

/// With no handler installed, warnings print to stdout and go to MUJOCO_LOG.TXT as the
/// reference writes them (capi-tests/warning_log.c on both libraries).
#[test]
fn default_warnings_print_and_log_as_reference() {
    require_reference();
    let src = [root().join("capi-tests/warning_log.c")];
    let (r, o) = (
        run(&compile_c(&src, "warning_log", Lib::Ref), &[], &[], 60),
        run(&compile_c(&src, "warning_log", Lib::Ours), &[], &[], 60),
    );
    assert!(
        r.status.success() && o.status.success(),
        "warning_log failed"
    );
    let (r, o) = (text(&r.stdout), text(&o.stdout));
    assert!(
        r.contains("MUJOCO_LOG.TXT\nDATE\nWARNING: a plain warning\n"),
        "unexpected reference output:\n{r}"
    );
    assert_eq!(o, r, "default warning output differs from the reference");
}
