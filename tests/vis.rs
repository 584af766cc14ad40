//! Abstract visualization (mjv_) against 2.2.2: default structs and scenes, printed field by
//! field with exact floats by capi-tests/vis.c on each library, must be identical.

mod common;

use common::*;
use std::sync::OnceLock;

fn programs() -> &'static (std::path::PathBuf, std::path::PathBuf) {
    static P: OnceLock<(std::path::PathBuf, std::path::PathBuf)> = OnceLock::new();
    P.get_or_init(|| {
        let src = vec![root().join("capi-tests/vis.c")];
        (
            compile_c(&src, "vis", Lib::Ref),
            compile_c(&src, "vis", Lib::Ours),
        )
    })
}

/// The models of the lists and the main corpus, as arguments.
fn all_models() -> Vec<String> {
    let mut files = models();
    files.extend(model_list("models-extra.list"));
    files.extend(
        main_corpus_files()
            .iter()
            .map(|p| p.to_string_lossy().into_owned()),
    );
    files
}

/// Runs `vis MODE` with the models in chunks on both libraries; returns the first line that
/// differs (with its model) or None, and the number of lines compared.
fn compare(mode: &str, files: &[String]) -> (Option<String>, usize) {
    let (r, o) = programs();
    let mut chunks: Vec<&[String]> = files.chunks(8).collect();
    if chunks.is_empty() {
        chunks.push(&[]);
    }
    let results = par_map(&chunks, |_, chunk| {
        let args: Vec<&str> = std::iter::once(mode)
            .chain(chunk.iter().map(String::as_str))
            .collect();
        let reference = text(&run(r, &args, &[], 600).stdout);
        let ours = run(o, &args, &[], 600);
        (reference, text(&ours.stdout), text(&ours.stderr))
    });
    let mut lines = 0;
    for (reference, ours, stderr) in results {
        lines += reference.lines().count();
        let mut model = String::new();
        for (a, b) in reference
            .lines()
            .zip(ours.lines().chain(std::iter::repeat("")))
        {
            if a.starts_with("model ") {
                model = a.to_string();
            }
            if a != b {
                return (
                    Some(format!(
                        "{model}\n reference: {a}\n ours:      {b}\n{stderr}"
                    )),
                    lines,
                );
            }
        }
        if ours.lines().count() != reference.lines().count() {
            return (Some(format!("extra output:\n{ours}")), lines);
        }
    }
    (None, lines)
}

#[test]
fn defaults_match_reference() {
    let (differ, lines) = compare("defaults", &[]);
    assert!(lines > 40, "vis defaults printed {lines} lines");
    assert!(differ.is_none(), "{}", differ.unwrap());
}

#[test]
fn scene_buffers_match_reference() {
    let files = all_models();
    let (differ, lines) = compare("scene", &files);
    report(
        "vis-scene",
        &format!(
            "mjv_makeScene/defaultFreeCamera: {} models, {lines} lines\n",
            files.len()
        ),
    );
    assert!(lines > 10 * files.len(), "vis scene printed {lines} lines");
    assert!(differ.is_none(), "{}", differ.unwrap());
}

/// The first line where `update-verbose` output on `model` differs between the libraries.
fn first_difference(model: &str) -> String {
    let (r, o) = programs();
    let args = ["update-verbose", model];
    let reference = text(&run(r, &args, &[], 600).stdout);
    let ours = run(o, &args, &[], 600);
    let ours_text = text(&ours.stdout);
    let mut last_config = "";
    for (a, b) in reference.lines().zip(ours_text.lines()) {
        if a.starts_with(" config") {
            last_config = a;
            continue;
        }
        if a != b {
            return format!("{model}\n after {last_config}\n reference: {a}\n ours:      {b}");
        }
    }
    format!("{model}: outputs differ in length\n{}", text(&ours.stderr))
}

#[test]
fn scenes_match_reference() {
    let files = all_models();
    let (differ, lines) = compare("update", &files);
    let configs = lines.saturating_sub(files.len());
    report(
        "vis-update",
        &format!(
            "mjv_updateScene: {} models, {configs} scenes (options, labels, frames, categories, \
             perturbations, cameras, full buffers): {}\n",
            files.len(),
            if differ.is_none() {
                "all identical"
            } else {
                "DIFFER"
            }
        ),
    );
    if let Some(d) = differ {
        let model = d.lines().next().unwrap_or("").trim_start_matches("model ");
        panic!("{d}\n{}", first_difference(model));
    }
    assert!(configs > 40 * files.len(), "only {configs} scenes compared");
}

#[test]
fn interaction_matches_reference() {
    let files = all_models();
    let (differ, lines) = compare("interact", &files);
    report(
        "vis-interact",
        &format!(
            "mjv_ interaction (camera queries, moveCamera/Model/Perturb, initPerturb, \
             applyPerturbForce/Pose, select on a 9x9 grid): {} models, {lines} lines: {}\n",
            files.len(),
            if differ.is_none() {
                "all identical"
            } else {
                "DIFFER"
            }
        ),
    );
    assert!(differ.is_none(), "{}", differ.unwrap());
    assert!(lines > 150 * files.len(), "only {lines} lines compared");
}
