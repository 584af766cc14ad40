//! Concurrent use (examples/threads.rs): one shared model stepped by four threads while two
//! more load models and use thread-local warning hooks; every thread's final state is
//! bit-identical to a single-threaded run. The same program also runs (with fewer steps) under
//! ThreadSanitizer when the nightly toolchain with its sanitizer runtime is present: no race
//! may be reported.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The listed models and a few corpus models with contacts, tendons and muscles.
fn models_for_threads() -> Vec<String> {
    let mut files = models();
    for name in ["humanoid.xml", "arm26.xml", "quadruped.xml", "dog.xml"] {
        if let Some(f) = corpus_files().into_iter().find(|f| f.ends_with(name)) {
            files.push(f.to_string_lossy().into_owned());
        }
    }
    files
}

fn check(
    prog: &Path,
    (steps, loads): (&str, &str),
    files: &[String],
    envs: &[(&str, &str)],
) -> (usize, String) {
    let args: Vec<&str> = ["--steps", steps, "--loads", loads]
        .into_iter()
        .chain(files.iter().map(String::as_str))
        .collect();
    let o = run(prog, &args, envs, 1800);
    let out = text(&o.stdout);
    let err = text(&o.stderr);
    assert!(
        o.status.success(),
        "{} failed ({:?}):\n{out}{err}",
        prog.display(),
        o.status
    );
    assert!(
        !err.contains("ThreadSanitizer"),
        "ThreadSanitizer reports:\n{err}"
    );
    let same = out.lines().filter(|l| l.ends_with(" same")).count();
    let bad: Vec<&str> = out.lines().filter(|l| !l.ends_with(" same")).collect();
    assert!(
        bad.is_empty(),
        "threads differ from a single-threaded run: {bad:?}"
    );
    (same, out)
}

/// The nightly toolchain and its ThreadSanitizer runtime, or why not.
fn nightly_tsan() -> Result<(), String> {
    let o = Command::new("rustc")
        .args(["+nightly", "--print", "target-libdir"])
        .output()
        .map_err(|e| format!("rustup not found ({e})"))?;
    if !o.status.success() {
        return Err("no nightly toolchain".into());
    }
    let dir = PathBuf::from(text(&o.stdout).trim());
    let has_rt = std::fs::read_dir(&dir)
        .map(|d| {
            d.flatten()
                .any(|e| e.file_name().to_string_lossy().contains("rt.tsan"))
        })
        .unwrap_or(false);
    has_rt
        .then_some(())
        .ok_or_else(|| format!("no ThreadSanitizer runtime in {}", dir.display()))
}

#[test]
fn threads_share_a_model() {
    let prog = target_dir().join("release/examples/threads");
    assert!(prog.is_file(), "{} not built", prog.display());
    let files = models_for_threads();
    let (same, _) = check(&prog, ("300", "3"), &files, &[]);
    let mut body = format!(
        "threads: {same} of {} models bit-identical in 4 threads after 300 steps (2 more loading)\n",
        files.len()
    );

    match nightly_tsan() {
        Err(why) => body.push_str(&format!("ThreadSanitizer: not run ({why})\n")),
        Ok(()) => {
            let o = Command::new(root().join("capi-tests/build-tsan"))
                .output()
                .expect("bash");
            assert!(
                o.status.success(),
                "building under ThreadSanitizer failed:\n{}",
                text(&o.stderr)
            );
            let tsan = PathBuf::from(text(&o.stdout).trim());
            let opts = format!(
                "halt_on_error=1 suppressions={}",
                root().join("capi-tests/tsan.supp").display()
            );
            // fewer steps and loads: the same code runs in every step and every load, and the
            // instrumented run is slow (loading took most of it)
            let (same, _) = check(&tsan, ("50", "1"), &files, &[("TSAN_OPTIONS", &opts)]);
            body.push_str(&format!(
                "ThreadSanitizer: {same} models (50 steps, one load per loading thread), no race reported (nightly, \
                 -Zsanitizer=thread)\n"
            ));
        }
    }
    report("threads", &body);
}
