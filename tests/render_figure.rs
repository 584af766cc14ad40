//! 2D figures (mjr_figure) against 2.2.2 under OSMesa: capi-tests/render_figure.c draws figures
//! covering every field of mjvFigure (lines, legends, highlight, selection, ranges, grids,
//! tick formats, titles with subplots, colors, viewports, font scales) and prints per case
//! the fields mjr_figure writes back and a hash of the pixels; both libraries must agree.

mod common;

use common::*;

#[test]
fn figures_match_reference() {
    require_osmesa();
    let src = "capi-tests/render_figure.c";
    let r = compile_gl(src, "render_figure", Lib::Ref, &["-lOSMesa"]);
    let o = compile_gl(src, "render_figure", Lib::Ours, &["-lOSMesa"]);
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
