//! Physics over the corpus (common::corpus_dirs), for every model both libraries load: full
//! physics (mj_forward, mj_step and collision detection at 50 states of the reference's
//! trajectory: harness groups forward, step, collision), and, on the main corpus, smooth
//! dynamics with constraints and contacts disabled on both sides (forward and the body
//! Jacobians), compared within the
//! group tolerances raised to 1000x the reference's noise floor. A model our engine stops on
//! with "not implemented" is counted, never one that differs. Report: physics-corpus.txt.

mod common;
use common::*;

/// Models larger than this (nv) are left out: their dumps would run to many GBs (humanoid100,
/// nv 2700, stays in; the 1000-particle composite, nv 3000, with its contacts, does not).
const MAX_NV: i32 = 2700;

/// What one model gave.
enum Outcome {
    Skipped,
    Unsupported(String),
    /// smooth-dynamics parity, then the full-physics result: worst error, or what differs
    Checked {
        smooth: Result<bool, String>,
        full: Result<f64, String>,
    },
}

/// `smooth`: also the run with constraints and contacts disabled.
fn check(
    bin: &std::path::Path,
    f: &std::path::Path,
    dir: &std::path::Path,
    smooth: bool,
) -> Outcome {
    let _ = std::fs::remove_dir_all(dir);
    let (fs, ds) = (
        f.to_string_lossy().to_string(),
        dir.to_string_lossy().to_string(),
    );
    let rel = f.display().to_string();
    // the compiled model first: small, tells the size and whether ours loads it
    match harness_compare(
        bin,
        &fs,
        &ds,
        &["--model-only"],
        &["--groups", "model"],
        120,
    ) {
        None => return Outcome::Skipped,
        Some((false, _)) => return Outcome::Unsupported(format!("{rel}: compiler")),
        Some((true, _)) => {}
    }
    if model_nv(&ds) > MAX_NV {
        return Outcome::Skipped;
    }
    // smooth dynamics: constraints and contacts off on both sides
    let g = ["--groups", "forward,jacBody,jacSite"];
    let smooth_run = ["--groups", "forward,jacBody,jacSite", "--disable", "17"];
    let smooth = match smooth
        .then(|| harness_compare(bin, &fs, &ds, &smooth_run, &g, 600))
        .flatten()
    {
        Some((true, _)) => Ok(true),
        Some((false, out)) if !out.contains("not implemented") => {
            Err(format!("{rel} (constraints and contacts disabled):\n{out}"))
        }
        _ => Ok(false),
    };
    let g = ["--groups", "forward,step,collision"];
    let Some((ok, out)) = harness_compare(bin, &fs, &ds, &g, &g, 600) else {
        return Outcome::Skipped; // the reference stops on this model
    };
    let _ = std::fs::remove_dir_all(dir);
    let full = if ok {
        Ok(out
            .lines()
            .filter_map(|l| l.split("check groups pass; worst relative error ").nth(1))
            .filter_map(|w| w.split_whitespace().next()?.parse::<f64>().ok())
            .fold(0.0, f64::max))
    } else if out.contains("not implemented") {
        return Outcome::Unsupported(format!("{rel}: not implemented"));
    } else {
        Err(format!("{rel}:\n{out}"))
    };
    Outcome::Checked { smooth, full }
}

#[test]
fn corpus_physics() {
    let files = corpus_files();
    if files.is_empty() {
        eprintln!("corpus_physics: skipped, no corpus");
        return;
    }
    let bin = harness_bin();
    let base = work_dir("physics-corpus");
    let main = main_corpus_files();
    let outcomes = par_map(&files, |i, f| {
        check(&bin, f, &base.join(i.to_string()), main.contains(f))
    });
    let (mut same, mut unsupported, mut skipped) = (0, Vec::new(), 0);
    let mut differ = Vec::new();
    let mut worst = 0.0f64;
    let mut smooth = 0;
    for o in outcomes {
        match o {
            Outcome::Skipped => skipped += 1,
            Outcome::Unsupported(u) => unsupported.push(u),
            Outcome::Checked { smooth: s, full } => {
                match s {
                    Ok(true) => smooth += 1,
                    Ok(false) => {}
                    Err(d) => differ.push(d),
                }
                match full {
                    Ok(w) => {
                        worst = worst.max(w);
                        same += 1;
                    }
                    Err(d) => differ.push(d),
                }
            }
        }
    }
    let msg = format!(
        "physics corpus (forward, step, collision at 50 states): {same} of {} models at parity \
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
    let p = std::path::Path::new(dir).join("ref/model.bin");
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
