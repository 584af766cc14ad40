//! OpenGL rendering (mjr_) against 2.2.2 under OSMesa (Mesa's software renderer): the context
//! mjr_makeContext makes for every model of the lists and the main corpus, its fields and the
//! content of its display lists, fonts, textures and skin buffers drawn or read back by plain
//! GL (capi-tests/render_context.c), identical on both libraries.

mod common;

use common::*;

const OSMESA_H: &str = "/usr/include/GL/osmesa.h";

fn compile(lib: Lib) -> std::path::PathBuf {
    let src = root().join("capi-tests/render_context.c");
    let out = work_dir("render").join(format!("render_context-{}", lib.name()));
    let (inc, dir) = match lib {
        Lib::Ref => (
            "/usr/include".to_string(),
            "/usr/lib/x86_64-linux-gnu".to_string(),
        ),
        _ => (
            root().join("include").to_string_lossy().into_owned(),
            lib_dir().to_string_lossy().into_owned(),
        ),
    };
    let status = std::process::Command::new("gcc")
        .args(["-O1", "-o"])
        .arg(&out)
        .arg(&src)
        .args(["-I", &inc, "-L", &dir, "-lmujoco", "-lOSMesa", "-lm"])
        .arg(format!("-Wl,-rpath,{dir}"))
        .status()
        .unwrap();
    assert!(status.success(), "render_context.c does not compile");
    out
}

#[test]
fn context_matches_reference() {
    require_reference();
    our_lib();
    assert!(
        std::path::Path::new(OSMESA_H).exists(),
        "{OSMESA_H} missing: install libosmesa6-dev (capi-tests/run-all does it)"
    );
    let (r, o) = (compile(Lib::Ref), compile(Lib::Ours));
    let mut files = models();
    files.extend(
        main_corpus_files()
            .iter()
            .map(|p| p.to_string_lossy().into_owned()),
    );
    let chunks: Vec<&[String]> = files.chunks(12).collect();
    let results = par_map(&chunks, |_, chunk| {
        let args: Vec<&str> = chunk.iter().map(String::as_str).collect();
        let reference = run(&r, &args, &[], 900);
        let ours = run(&o, &args, &[], 900);
        (
            text(&reference.stdout),
            text(&ours.stdout),
            text(&ours.stderr),
        )
    });
    let (mut lines, mut draws) = (0, 0);
    for (reference, ours, stderr) in &results {
        lines += reference.lines().count();
        draws += reference.lines().filter(|l| l.starts_with(" draw")).count();
        let mut model = "";
        for (a, b) in reference
            .lines()
            .zip(ours.lines().chain(std::iter::repeat("")))
        {
            if a.starts_with("model ") {
                model = a;
            }
            assert_eq!(a, b, "{model}: context differs\n{stderr}");
        }
        assert_eq!(reference.lines().count(), ours.lines().count(), "{stderr}");
    }
    report(
        "render-context",
        &format!(
            "mjr_makeContext: {} models, {lines} lines, {draws} display lists drawn: identical\n",
            files.len()
        ),
    );
    assert!(draws > 10 * files.len(), "only {draws} lists drawn");
}
