//! Optional: the corpus of real models (common::corpus_dirs: $RUJOCO_CORPUS, else ../shared/corpus;
//! run-all sets RUJOCO_CORPUS to the dm_control 1.0.7 suite from PyPI when ../shared is absent,
//! plus the other packages' models), run once per test process for both tests:
//! - compiled models: a model we cannot compile yet must be rejected with an error, never loaded
//!   with other values; the report (corpus.txt) counts identical models;
//!   RUJOCO_CORPUS_STRICT=1 requires every model identical;
//! - physics, for every model both libraries load: full physics (mj_forward, mj_step and
//!   collision detection at 50 states of the reference's trajectory, 10 above nv 60: harness
//!   groups forward, step, collision), and, on the main corpus, smooth dynamics with constraints and contacts
//!   disabled on both sides (forward and the body Jacobians), compared within the group
//!   tolerances raised to 1000x the reference's noise floor. A model our engine stops on with
//!   "not implemented" is counted, never one that differs. Report: physics-corpus.txt.

mod common;
use common::*;
use std::path::Path;
use std::sync::OnceLock;

/// Models larger than this (nv) get no physics runs: their dumps would run to many GBs
/// (humanoid100, nv 2700, stays in; the 1000-particle composite, nv 3000, with its contacts,
/// does not).
const MAX_NV: i32 = 2700;

/// Models larger than this (nv) are checked at 10 states of the trajectory instead of 50: their
/// state checks and dumps took most of the test's time.
const FEW_STATES_NV: i32 = 60;

/// What one model's physics gave.
enum Physics {
    Skipped,
    Unsupported(String),
    /// smooth-dynamics parity, then the full-physics result: worst error, or what differs
    Checked {
        smooth: Result<bool, String>,
        full: Result<f64, String>,
    },
}

/// One corpus file: its path as reported, the compiled-model comparison (None: the reference
/// rejects it; else identical, and the comparator's line of the model group) and the physics.
struct Model {
    rel: String,
    compiled: Option<(bool, String)>,
    physics: Physics,
}

/// Every corpus file through both libraries, once per test process (None: no corpus).
fn corpus() -> Option<&'static [Model]> {
    static RUNS: OnceLock<Vec<Model>> = OnceLock::new();
    let dirs = corpus_dirs();
    if dirs.is_empty() {
        return None;
    }
    Some(RUNS.get_or_init(|| {
        let bin = harness_bin();
        let base = work_dir("corpus");
        let main = main_corpus_files();
        let files = corpus_files();
        // one run per file, in the corpus's order: the main corpus, which holds the largest
        // models, first, so that no large model is left running alone at the end
        let runs = par_map_harness(&files, |i, f| {
            let ds = base.join(i.to_string()).to_string_lossy().into_owned();
            let run = check(&bin, f, &ds, main.contains(f));
            let _ = std::fs::remove_dir_all(&ds);
            run
        });
        runs.into_iter()
            .zip(&files)
            .map(|((compiled, physics), f)| {
                let rel = dirs
                    .iter()
                    .find_map(|d| f.strip_prefix(d.parent().unwrap_or(d)).ok())
                    .unwrap_or(f)
                    .display()
                    .to_string();
                Model {
                    rel,
                    compiled,
                    physics,
                }
            })
            .collect()
    }))
}

/// One file: the compiled model (None: the reference rejects the file; else identical, and the
/// comparator's line), and the physics when both libraries load it to the same model: full
/// physics (with the compiled model, in one run), and with `smooth` the run with constraints
/// and contacts disabled.
fn check(bin: &Path, f: &Path, ds: &str, smooth: bool) -> (Option<(bool, String)>, Physics) {
    let _ = std::fs::remove_dir_all(ds);
    let fs = f.to_string_lossy();
    let rel = f.display().to_string();
    let (states, max_nv) = (FEW_STATES_NV.to_string(), MAX_NV.to_string());
    let sized = [
        "--states",
        "10",
        "--states-above",
        &states,
        "--max-nv",
        &max_nv,
    ];
    let Some((run, out)) = harness_run(bin, &fs, ds, "model,forward,step,collision", &sized) else {
        return (None, Physics::Skipped); // include files, malformed models
    };
    let line = |group: &str| {
        out.lines()
            .map(str::trim)
            .find(|l| l.split_whitespace().next() == Some(group))
            .unwrap_or("")
            .to_string()
    };
    let model = line("model");
    let compiled = Some((model.contains(" PASS "), model));
    if !compiled.as_ref().is_some_and(|c| c.0) {
        return (compiled, Physics::Unsupported(format!("{rel}: compiler")));
    }
    if !run.physics {
        return (compiled, Physics::Skipped); // the reference stops, or nv above MAX_NV
    }
    let full = if run.passed {
        Ok(["forward", "step", "collision"]
            .iter()
            .filter_map(|g| {
                line(g)
                    .split("worst ")
                    .nth(1)?
                    .split_whitespace()
                    .next()?
                    .parse()
                    .ok()
            })
            .fold(0.0, f64::max))
    } else if out.contains("not implemented") {
        return (
            compiled,
            Physics::Unsupported(format!("{rel}: not implemented")),
        );
    } else {
        Err(format!("{rel}:\n{out}"))
    };
    // smooth dynamics: constraints and contacts off on both sides
    let smooth_run = [&["--disable", "17"], &sized[..]].concat();
    let smooth = match smooth
        .then(|| harness_run(bin, &fs, ds, "forward,jacBody,jacSite", &smooth_run))
        .flatten()
    {
        Some((r, _)) if r.physics && r.passed => Ok(true),
        Some((r, out)) if r.physics && !out.contains("not implemented") => {
            Err(format!("{rel} (constraints and contacts disabled):\n{out}"))
        }
        _ => Ok(false),
    };
    (compiled, Physics::Checked { smooth, full })
}

/// How a run went: whether the physics ran (the reference did not stop, nv at most MAX_NV) and
/// whether every compared group passed.
struct Run {
    physics: bool,
    passed: bool,
}

/// The harness on one file: the reference records and ours replays `groups` with `args`, the
/// reference compares them (only the compiled model when the physics did not run). None when
/// the reference rejects the file; else how it went and the comparator's output.
fn harness_run(
    bin: &Path,
    model: &str,
    ds: &str,
    groups: &str,
    args: &[&str],
) -> Option<(Run, String)> {
    let side = |exe: &str, mode: &str| {
        let a: Vec<&str> = [mode, model, ds, "--groups", groups]
            .into_iter()
            .chain(args.iter().copied())
            .collect();
        run(&bin.join(exe), &a, &[], 600).status.success()
    };
    let recorded = side("harness-ref", "record");
    let status =
        std::fs::read_to_string(Path::new(ds).join("ref/model.status")).unwrap_or_default();
    if status.trim() != "ok" {
        return None;
    }
    side("harness-ours", "replay");
    let physics = recorded && model_nv(ds) <= MAX_NV;
    let compared = if physics { groups } else { "model" };
    let c = run(
        &bin.join("harness-ref"),
        &["compare", ds, "--groups", compared],
        &[],
        600,
    );
    let passed = c.status.success();
    Some((Run { physics, passed }, text(&c.stdout)))
}

#[test]
fn corpus_compiled_models() {
    let Some(models) = corpus() else {
        eprintln!("corpus_compiled_models: skipped, no corpus");
        return;
    };
    let (mut same, mut differ, mut rejected) = (Vec::new(), Vec::new(), 0);
    for m in models {
        match &m.compiled {
            None => rejected += 1,
            Some((true, _)) => same.push(&m.rel),
            Some((false, why)) => differ.push(format!("{}: {why}", m.rel)),
        }
    }
    let msg = format!(
        "corpus ({}): {} of {} models compile identically to 2.2.2 ({} files the reference rejects skipped)\n{}",
        corpus_dirs()
            .iter()
            .map(|d| d.display().to_string())
            .collect::<Vec<_>>()
            .join(", "),
        same.len(),
        same.len() + differ.len(),
        rejected,
        differ.iter().map(|d| format!("  differs: {d}\n")).collect::<String>()
    );
    report("corpus", &msg);
    // A model we cannot compile yet must be rejected with an error, never loaded with other values.
    let wrong: Vec<&String> = differ
        .iter()
        .filter(|d| !d.contains("mj_loadXML failed"))
        .collect();
    assert!(
        wrong.is_empty(),
        "models loaded with values other than 2.2.2's: {wrong:?}\n{msg}"
    );
    if std::env::var("RUJOCO_CORPUS_STRICT").is_ok_and(|v| v == "1") {
        assert!(differ.is_empty(), "{msg}");
    }
}

#[test]
fn corpus_physics() {
    let Some(models) = corpus() else {
        eprintln!("corpus_physics: skipped, no corpus");
        return;
    };
    let (mut same, mut unsupported, mut skipped) = (0, Vec::new(), 0);
    let mut differ = Vec::new();
    let mut worst = 0.0f64;
    let mut smooth = 0;
    for m in models {
        match &m.physics {
            Physics::Skipped => skipped += 1,
            Physics::Unsupported(u) => unsupported.push(u),
            Physics::Checked { smooth: s, full } => {
                match s {
                    Ok(true) => smooth += 1,
                    Ok(false) => {}
                    Err(d) => differ.push(d),
                }
                match full {
                    Ok(w) => {
                        worst = worst.max(*w);
                        same += 1;
                    }
                    Err(d) => differ.push(d),
                }
            }
        }
    }
    let msg = format!(
        "physics corpus (forward, step, collision at 50 states, 10 above nv {FEW_STATES_NV}): {same} of {} models at parity \
         (worst relative error {worst:.2e}); {} stop on features not supported yet; {} differ; \
         {skipped} skipped (reference rejects or stops, or nv > {MAX_NV}); with constraints and \
         contacts disabled (main corpus), forward and Jacobians at parity on {smooth}\n{}{}",
        same + unsupported.len() + differ.len(),
        unsupported.len(),
        differ.len(),
        unsupported
            .iter()
            .map(|u| format!("  unsupported: {u}\n"))
            .collect::<String>(),
        differ
            .iter()
            .map(|d| format!("  DIFFERS: {d}\n"))
            .collect::<String>(),
    );
    report("physics-corpus", &msg);
    assert!(differ.is_empty(), "{msg}");
}

/// nv of the reference's compiled model in a harness directory.
fn model_nv(dir: &str) -> i32 {
    let p = Path::new(dir).join("ref/model.bin");
    let bytes = std::fs::read(p).unwrap_or_default();
    // record "nv" of type 'i': name length, name, type, byte count, value
    let key = b"size.nv";
    let mut i = 4;
    while i + 4 <= bytes.len() {
        let nl = u32::from_le_bytes(bytes[i..i + 4].try_into().unwrap()) as usize;
        let name = &bytes[i + 4..(i + 4 + nl).min(bytes.len())];
        let t = i + 4 + nl;
        if t + 9 > bytes.len() {
            break;
        }
        let nb = u64::from_le_bytes(bytes[t + 1..t + 9].try_into().unwrap()) as usize;
        if name == key && nb == 4 {
            return i32::from_le_bytes(bytes[t + 9..t + 13].try_into().unwrap());
        }
        i = t + 9 + nb;
    }
    0
}
