//! OpenGL rendering (mjr_) against 2.2.2 under OSMesa (Mesa's software renderer): the context
//! mjr_makeContext makes for every model of the lists and the main corpus, its fields and the
//! content of its display lists, fonts, textures and skin buffers drawn or read back by plain
//! GL (capi-tests/render_context.c), identical on both libraries.

mod common;

use common::*;

#[test]
fn context_matches_reference() {
    require_osmesa();
    let (r, o) = (
        compile_gl(
            "capi-tests/render_context.c",
            "render_context",
            Lib::Ref,
            &["-lOSMesa"],
        ),
        compile_gl(
            "capi-tests/render_context.c",
            "render_context",
            Lib::Ours,
            &["-lOSMesa"],
        ),
    );
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

/// Runs `prog` of both libraries over the models in chunks; returns every differing line with
/// its model, and the reference's output.
fn differences(
    name: &str,
    files: &[String],
    chunk: usize,
    flags: impl Fn(usize) -> Vec<&'static str> + Sync,
) -> (Vec<String>, String) {
    let src = format!("capi-tests/{name}.c");
    let r = compile_gl(&src, name, Lib::Ref, &["-lOSMesa"]);
    let o = compile_gl(&src, name, Lib::Ours, &["-lOSMesa"]);
    let chunks: Vec<&[String]> = files.chunks(chunk).collect();
    let results = par_map(&chunks, |i, chunk| {
        let mut args = flags(i);
        args.extend(chunk.iter().map(String::as_str));
        let reference = run(&r, &args, &[], 1200);
        let ours = run(&o, &args, &[], 1200);
        (
            text(&reference.stdout),
            text(&ours.stdout),
            text(&ours.stderr),
        )
    });
    let (mut differ, mut all) = (Vec::new(), String::new());
    for (reference, ours, stderr) in &results {
        all.push_str(reference);
        let mut model = "";
        for (a, b) in reference
            .lines()
            .zip(ours.lines().chain(std::iter::repeat("")))
        {
            if a.starts_with("model ") {
                model = a;
            }
            if a != b {
                differ.push(format!("{model}\n reference: {a}\n ours:      {b}"));
            }
        }
        if reference.lines().count() != ours.lines().count() {
            differ.push(format!("output ends differently\n{stderr}"));
        }
    }
    (differ, all)
}

/// mjr_render over every rendering flag, labels, transparency, stereo, frames, cameras and the
/// model transform, in the window and offscreen buffers, plus text, overlays, rectangles and
/// labels (capi-tests/render_scene.c): color and depth identical to 2.2.2's.
#[test]
fn scene_matches_reference() {
    require_osmesa();
    // every case on the models of the list, three on the rest of the main corpus; the
    // models' own shadow-map size in the first chunk (with the 2D drawing), at most 1024 in
    // the rest (the test took 162 s with all at their own size, 87 s so)
    let files = models();
    let (mut differ, mut all) = differences("render_scene", &files, 6, |i| {
        if i == 0 {
            vec!["2d"]
        } else {
            vec!["small"]
        }
    });
    let corpus: Vec<String> = main_corpus_files()
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let (d, a) = differences("render_scene", &corpus, 8, |_| vec!["quick", "small"]);
    differ.extend(d);
    all.push_str(&a);
    let nmodels = files.len() + corpus.len();
    let frames = all.lines().filter(|l| l.contains(" rgb ")).count();
    let lit = all
        .lines()
        .filter(|l| l.contains(" rgb ") && !l.contains(" lit 0 "))
        .count();
    report(
        "render-scene",
        &format!(
            "mjr_render and 2D drawing: {nmodels} models, {frames} frames (color and depth), {} differ\n",
            differ.len()
        ),
    );
    assert!(
        differ.is_empty(),
        "{} of {frames} frames differ:\n{}",
        differ.len(),
        differ[..differ.len().min(20)].join("\n")
    );
    assert!(
        frames > 20 * files.len() && lit > frames / 2,
        "{frames} frames, {lit} lit"
    );
}

/// examples/render_headless.c with no display, through EGL (surfaceless) and through OSMesa,
/// built against each library: the same PNG bytes all four ways.
#[test]
fn headless_example_matches_reference() {
    require_osmesa();
    assert!(
        std::path::Path::new("/usr/include/EGL/egl.h").exists(),
        "EGL headers missing: install libegl-dev (capi-tests/run-all does it)"
    );
    let dir = work_dir("render");
    let build = |lib: Lib, gl: &str| {
        let flags: &[&str] = if gl == "osmesa" {
            &["-DOSMESA", "-lOSMesa"]
        } else {
            &["-lEGL"]
        };
        let name = format!("render_headless-{gl}");
        compile_gl("examples/render_headless.c", &name, lib, flags)
    };
    let mut models = vec![model("arm3.xml")];
    models.extend(
        corpus_dirs()
            .iter()
            .map(|d| d.join("mujoco-2.2.2/model/mug/mug.xml"))
            .filter(|p| p.exists())
            .map(|p| p.to_string_lossy().into_owned())
            .take(1),
    );
    let mut images = 0;
    for (i, m) in models.iter().enumerate() {
        let mut pngs = Vec::new();
        for gl in ["egl", "osmesa"] {
            for lib in [Lib::Ref, Lib::Ours] {
                let png = dir.join(format!("headless-{i}-{gl}-{}.png", lib.name()));
                let _ = std::fs::remove_file(&png);
                let prog = build(lib, gl);
                let o = run(
                    &prog,
                    &[m, &png.to_string_lossy(), "100"],
                    &[("DISPLAY", "")],
                    300,
                );
                assert!(
                    o.status.success(),
                    "render_headless ({gl}, {lib:?}) on {m}: {}{}",
                    text(&o.stdout),
                    text(&o.stderr)
                );
                pngs.push((format!("{gl} {lib:?}"), std::fs::read(&png).unwrap()));
            }
        }
        for (what, bytes) in &pngs[1..] {
            assert!(
                bytes == &pngs[0].1,
                "{m}: the PNG of {what} differs from {}",
                pngs[0].0
            );
        }
        assert!(pngs[0].1.len() > 640 * 480 * 3, "{m}: PNG too small");
        images += pngs.len();
    }
    report(
        "render-headless",
        &format!(
            "examples/render_headless.c: {} models, {images} PNGs (EGL and OSMesa, ours and 2.2.2) byte-identical\n",
            models.len()
        ),
    );
}
