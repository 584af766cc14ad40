//! 2D figures (mjr_figure) against 2.2.2 under OSMesa: capi-tests/render_figure.c draws figures
//! covering every field of mjvFigure (lines, legends, highlight, selection, ranges, grids,
//! tick formats, titles with subplots, colors, viewports, font scales) and prints per case
//! the fields mjr_figure writes back and a hash of the pixels; both libraries must agree.

mod common;

use common::*;

const OSMESA_H: &str = "/usr/include/GL/osmesa.h";

fn compile(lib: Lib) -> std::path::PathBuf {
    let src = root().join("capi-tests/render_figure.c");
    let out = work_dir("render").join(format!("render_figure-{}", lib.name()));
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
        .args(["-O1", "-Wall", "-o"])
        .arg(&out)
        .arg(&src)
        .args(["-I", &inc, "-L", &dir, "-lmujoco", "-lOSMesa", "-lm"])
        .arg(format!("-Wl,--disable-new-dtags,-rpath,{dir}"))
        .status()
        .unwrap();
    assert!(status.success(), "render_figure.c does not compile");
    out
}

#[test]
fn figures_match_reference() {
    require_reference();
    our_lib();
    assert!(
        std::path::Path::new(OSMESA_H).exists(),
        "{OSMESA_H} missing: install libosmesa6-dev (capi-tests/run-all does it)"
    );
    let (r, o) = (compile(Lib::Ref), compile(Lib::Ours));
    let reference = text(&run(&r, &[], &[], 300).stdout);
    let ours = run(&o, &[], &[], 300);
    let (out, stderr) = (text(&ours.stdout), text(&ours.stderr));
    let cases = reference.lines().filter(|l| l.starts_with("case ")).count();
    let differ: Vec<&str> = reference
        .lines()
        .zip(out.lines().chain(std::iter::repeat("")))
        .filter(|(a, b)| a != b)
        .map(|(a, _)| a)
        .collect();
    report(
        "render-figure",
        &format!(
            "mjr_figure: {cases} figures, {} identical\n",
            cases - differ.iter().filter(|l| l.starts_with("case ")).count()
        ),
    );
    for (a, b) in reference
        .lines()
        .zip(out.lines().chain(std::iter::repeat("")))
    {
        assert_eq!(a, b, "figure differs\n{stderr}");
    }
    assert_eq!(reference.lines().count(), out.lines().count(), "{stderr}");
    assert!(cases > 30, "only {cases} figures drawn");
}
