//! Simulation speed against the reference, side by side in one run (best of 3, alternating):
//! the models the issues name, with constraints and contacts disabled (smooth dynamics) and
//! with full physics. Reports ratios (target/capi-tests/reports/speed.txt); a model our engine
//! cannot run yet is reported as such. Fails only if a run breaks in an unexpected way.

mod common;
use common::*;
use std::path::{Path, PathBuf};

const STEPS: &str = "2000";
/// mjDSBL_CONSTRAINT | mjDSBL_CONTACT
const SMOOTH: &str = "3";

/// The first corpus or models/ file with this name under a directory matching `under`.
fn find(name: &str, under: &str) -> Option<PathBuf> {
    let mut files = corpus_files();
    xml_files(&root().join("models"), &mut files);
    files
        .into_iter()
        .find(|f| f.file_name().is_some_and(|n| n == name) && f.to_string_lossy().contains(under))
}

fn rate(prog: &Path, flags: &str, model: &Path) -> Result<f64, String> {
    let m = model.to_string_lossy();
    let o = run(prog, &[STEPS, flags, &m], &[], 600);
    let out = text(&o.stdout);
    let line = out.lines().next().unwrap_or("").to_string();
    match line.strip_prefix("steps/s ") {
        Some(r) => r.trim().parse().map_err(|_| line.clone()),
        None if line.starts_with("error") => Err(line),
        None => panic!("bench broke on {m}: {out}{}", text(&o.stderr)),
    }
}

#[test]
fn speed_against_the_reference() {
    let src = [root().join("capi-tests/bench.c")];
    let reference = compile_c(&src, "bench", Lib::Ref);
    let ours = compile_c(&src, "bench", Lib::Ours);
    let models = [
        ("arm3", "arm3.xml", "models"),
        ("humanoid", "humanoid.xml", "humanoid/"),
        ("humanoid100", "humanoid100.xml", ""),
        ("cheetah", "cheetah.xml", "suite"),
        ("walker", "walker.xml", "suite"),
        ("quadruped", "quadruped.xml", "suite"),
    ];
    let mut lines = Vec::new();
    for (label, flags) in [
        ("constraints and contacts disabled", SMOOTH),
        ("full physics", "0"),
    ] {
        lines.push(format!("  {label}:"));
        for (name, file, under) in models {
            let Some(path) = find(file, under).or_else(|| find(file, "")) else {
                lines.push(format!("    {name:<12} model not found"));
                continue;
            };
            let (mut best_ref, mut best_ours) = (0.0f64, 0.0f64);
            let mut failure = None;
            for _ in 0..3 {
                match (rate(&reference, flags, &path), rate(&ours, flags, &path)) {
                    (Ok(r), Ok(o)) => {
                        best_ref = best_ref.max(r);
                        best_ours = best_ours.max(o);
                    }
                    (Err(e), _) => failure = Some(format!("reference stops: {e}")),
                    (_, Err(e)) => failure = Some(format!("ours stops: {e}")),
                }
                if failure.is_some() {
                    break;
                }
            }
            lines.push(match failure {
                Some(f) => format!("    {name:<12} {f}"),
                None => format!(
                    "    {name:<12} reference {best_ref:>10.0} steps/s  ours {best_ours:>10.0} steps/s  ratio {:.2}x",
                    best_ours / best_ref
                ),
            });
        }
    }
    let msg = format!(
        "speed ({STEPS} steps, best of 3, ours/reference):\n{}\n",
        lines.join("\n")
    );
    report("speed", &msg);
    eprintln!("{msg}");
}
