//! Drop-in proof: Debian's prebuilt /usr/bin/mujoco-testspeed, unmodified, runs on our library
//! through LD_LIBRARY_PATH; steps per second of both libraries are reported.

mod common;
use common::*;
use std::path::Path;
use std::process::Command;

const TESTSPEED: &str = "/usr/bin/mujoco-testspeed";
const STEPS: &str = "100000";

fn steps_per_second(out: &str) -> Option<f64> {
    out.lines()
        .find(|l| l.contains("Steps per second"))?
        .split(':')
        .nth(1)?
        .trim()
        .parse()
        .ok()
}

#[test]
fn testspeed_runs_on_ours() {
    require_reference();
    assert!(
        Path::new(TESTSPEED).exists(),
        "{TESTSPEED} missing: install libmujoco-samples"
    );
    our_lib();
    let lib_dir = lib_dir().canonicalize().unwrap();
    let ld = lib_dir.to_string_lossy().to_string();

    // the dynamic loader picks ours under LD_LIBRARY_PATH
    let ldd = Command::new("ldd")
        .arg(TESTSPEED)
        .env("LD_LIBRARY_PATH", &ld)
        .output()
        .expect("ldd missing");
    let line = text(&ldd.stdout)
        .lines()
        .find(|l| l.contains("libmujoco.so"))
        .unwrap_or("")
        .trim()
        .to_string();
    let resolved = line
        .split("=>")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .unwrap_or("");
    let resolved_dir = Path::new(resolved)
        .parent()
        .and_then(|p| p.canonicalize().ok());
    assert_eq!(
        resolved_dir.as_deref(),
        Some(lib_dir.as_path()),
        "ldd under LD_LIBRARY_PATH does not pick ours: {line}"
    );

    let arm3 = model("arm3.xml");
    let reference = run(TESTSPEED.as_ref(), &[&arm3, STEPS], &[], 120);
    let ref_sps = steps_per_second(&text(&reference.stdout));
    let ours = run(
        TESTSPEED.as_ref(),
        &[&arm3, STEPS],
        &[("LD_LIBRARY_PATH", &ld)],
        120,
    );
    let our_sps = steps_per_second(&text(&ours.stdout));
    let fmt = |s: Option<f64>| s.map_or("-".to_string(), |v| format!("{v:.0}"));
    let msg = format!(
        "drop-in: mujoco-testspeed models/arm3.xml {STEPS}: ldd -> {resolved}\n  steps per second: reference {}, ours {}{}\n",
        fmt(ref_sps),
        fmt(our_sps),
        match (ref_sps, our_sps) {
            (Some(r), Some(o)) => format!(" (ours/reference = {:.2})", o / r),
            _ => String::new(),
        }
    );
    eprint!("{msg}");
    report("dropin", &msg);
    assert!(
        ref_sps.is_some(),
        "reference testspeed failed:\n{}",
        text(&reference.stdout)
    );
    assert!(
        ours.status.success() && our_sps.is_some(),
        "testspeed on ours failed (exit {:?}):\n{}{}",
        ours.status.code(),
        text(&ours.stdout),
        text(&ours.stderr)
    );
}
