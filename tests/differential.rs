//! Differential checks against Debian's MuJoCo 2.2.2 (capi-tests/harness): every model of
//! capi-tests/models.list is run once through both libraries; each test compares one family
//! of results over all models and fails listing the quantities beyond tolerance.

mod common;
use common::*;
use std::path::PathBuf;
use std::sync::OnceLock;

fn stem(model: &str) -> String {
    PathBuf::from(model)
        .file_stem()
        .unwrap()
        .to_string_lossy()
        .into_owned()
}

/// Records the reference and replays ours for every listed model, once per test process.
fn results() -> &'static (PathBuf, PathBuf) {
    static RESULTS: OnceLock<(PathBuf, PathBuf)> = OnceLock::new();
    RESULTS.get_or_init(|| {
        let bin = harness_bin();
        let base = work_dir("diff");
        // the list's end holds its largest models: they start first
        let mut order = models();
        order.reverse();
        par_map_harness(&order, |_, model| {
            let dir = base.join(stem(model));
            let _ = std::fs::remove_dir_all(&dir);
            let d = dir.to_string_lossy().to_string();
            let r = run(&bin.join("harness-ref"), &["record", model, &d], &[], 300);
            assert!(
                r.status.success(),
                "reference run failed on {model}:\n{}{}",
                text(&r.stdout),
                text(&r.stderr)
            );
            run(&bin.join("harness-ours"), &["replay", model, &d], &[], 300);
            let full = run(&bin.join("harness-ref"), &["compare", &d, "-v"], &[], 120);
            std::fs::write(dir.join("report.txt"), &full.stdout).unwrap();
            // a passing model's dumps (gigabytes over the list) go; a failing one's stay
            if full.status.success() {
                for f in ["ours", "ref"] {
                    let _ = std::fs::remove_dir_all(dir.join(f));
                }
                let _ = std::fs::remove_file(dir.join("states.bin"));
            }
        });
        let summary: String = models()
            .iter()
            .map(|m| {
                let t = std::fs::read_to_string(base.join(stem(m)).join("report.txt"))
                    .unwrap_or_default();
                let last = t.lines().last().unwrap_or("no report").trim().to_string();
                format!("  {m}: {last}\n")
            })
            .collect();
        report(
            "differential",
            &format!("differential (details: target/capi-tests/diff/*/report.txt):\n{summary}"),
        );
        (bin, base)
    })
}

/// The given check groups of every model, read from the comparator's full report (its lines
/// start with the group name: one a quantity, then the group's summary); fails listing the
/// failing lines and summaries.
fn check(groups: &str) {
    let (_, base) = results();
    let mut failures = String::new();
    let mut all = String::new();
    for model in models() {
        let report_file = base.join(stem(&model)).join("report.txt");
        let full = std::fs::read_to_string(&report_file).unwrap_or_default();
        let mut out = format!("model {model}\n");
        let mut failed = String::new();
        for g in groups.split(',') {
            let lines: Vec<&str> = full
                .lines()
                .filter(|l| l.split_whitespace().next() == Some(g))
                .collect();
            let summary = lines.iter().find(|l| l.contains(" quantities, "));
            match summary {
                Some(s) if !s.contains(" FAIL ") => out.push_str(&format!("{s}\n")),
                _ => {
                    for l in lines.iter().filter(|l| l.contains(" FAIL ")) {
                        failed.push_str(&format!("{l}\n"));
                    }
                    if lines.is_empty() {
                        failed.push_str(&format!("  {g:<16} FAIL  no result\n"));
                    }
                }
            }
        }
        out.push_str(&failed);
        if !failed.is_empty() {
            failures.push_str(&out);
        }
        all.push_str(&out);
    }
    report(&format!("differential-{}", groups.replace(',', "-")), &all);
    assert!(
        failures.is_empty(),
        "differences from MuJoCo 2.2.2 (relative error |a-b|/max(1,|a|,|b|)):\n{failures}"
    );
}

#[test]
fn compiled_model_fields() {
    check("model");
}

#[test]
fn forward_at_trajectory_states() {
    check("forward");
}

#[test]
fn jacobians() {
    check("jacSite,jacBody,jacBodyCom,jacGeom,jac,jacPointAxis");
}

#[test]
fn mass_matrix_functions() {
    check("fullM,mulM,mulM2,solveM,consistency");
}

#[test]
fn position_integration_and_differentiation() {
    check("integratePos,differentiatePos");
}

#[test]
fn names() {
    check("names");
}

#[test]
fn one_step_from_each_state() {
    check("step");
}

#[test]
fn stepped_trajectories() {
    check("traj");
}

/// The harness compares the reference with itself without a difference: validates recording,
/// the transplanted model and the comparator (independent of our library's progress).
/// Every group must show exactly zero error, except the Eigen self-consistency residuals.
/// Every third model of the list: the machinery is the same for all.
#[test]
fn harness_self_check() {
    let bin = harness_bin();
    let base = work_dir("diff-self");
    let picked: Vec<String> = models().into_iter().step_by(3).collect();
    par_map(&picked, |_, model| {
        let dir = base.join(stem(model));
        let _ = std::fs::remove_dir_all(&dir);
        let d = dir.to_string_lossy().to_string();
        let r = run(&bin.join("harness-ref"), &["record", model, &d], &[], 300);
        assert!(r.status.success(), "reference run failed on {model}");
        run(&bin.join("harness-ref"), &["replay", model, &d], &[], 300);
        let c = run(&bin.join("harness-ref"), &["compare", &d], &[], 120);
        let _ = std::fs::remove_dir_all(&dir);
        let out = text(&c.stdout);
        assert!(
            c.status.success(),
            "reference differs from itself on {model}:\n{out}"
        );
        for line in out.lines().filter(|l| l.contains(" quantities, ")) {
            let exact =
                line.contains("worst 0.00e+00") || line.trim_start().starts_with("consistency");
            assert!(exact, "reference differs from itself on {model}:\n{line}");
        }
    });
}

/// The library the loader picks for `prog` (`ld.so --list`), with `mask` as
/// `--glibc-hwcaps-mask` when given.
fn loaded_library(prog: &std::path::Path, mask: Option<&str>) -> String {
    let p = prog.to_string_lossy();
    let mut args = vec![];
    if let Some(m) = mask {
        args.extend(["--glibc-hwcaps-mask", m]);
    }
    args.extend(["--list", &p]);
    let out = run(std::path::Path::new(LD_SO), &args, &[], 30);
    let list = text(&out.stdout);
    list.lines()
        .find(|l| l.trim_start().starts_with("libmujoco.so"))
        .and_then(|l| l.split("=> ").nth(1))
        .unwrap_or_else(|| panic!("no libmujoco in ld.so --list {p}:\n{list}"))
        .to_string()
}

/// Where a CPU has AVX2, the loader takes the x86-64-v3 build (`cargo xtask hwcaps`) and every
/// other test runs that one: the baseline build, which every other x86-64 runs, gets the whole
/// model list here (reference recorded, ours replayed with the loader told to skip
/// glibc-hwcaps/, compared, every group at its tolerance).
#[test]
fn baseline_build_on_every_model() {
    let bin = harness_bin();
    let ours = bin.join("harness-ours");
    let base = lib_dir().join("libmujoco.so.2.2.2");
    let base = base.to_string_lossy();
    let masked = loaded_library(&ours, Some("none"));
    assert!(masked.starts_with(&*base), "masked run loads {masked}");
    if lib_dir().join(HWCAPS_V3).exists()
        && std::arch::is_x86_feature_detected!("avx2")
        && std::arch::is_x86_feature_detected!("fma")
        && std::arch::is_x86_feature_detected!("bmi2")
    {
        let plain = loaded_library(&ours, None);
        assert!(plain.contains(HWCAPS_V3), "the other tests run {plain}");
    }
    let dirs = work_dir("diff-baseline");
    let failed: Vec<String> = par_map_harness(&models(), |_, model| {
        let dir = dirs.join(stem(model));
        let _ = std::fs::remove_dir_all(&dir);
        let d = dir.to_string_lossy().to_string();
        let r = run(&bin.join("harness-ref"), &["record", model, &d], &[], 300);
        assert!(r.status.success(), "reference run failed on {model}");
        let ours = ours.to_string_lossy();
        let args = ["--glibc-hwcaps-mask", "none", &ours, "replay", model, &d];
        run(std::path::Path::new(LD_SO), &args, &[], 300);
        let c = run(&bin.join("harness-ref"), &["compare", &d], &[], 120);
        if c.status.success() {
            let _ = std::fs::remove_dir_all(&dir);
            return None;
        }
        Some(format!("{model}:\n{}", text(&c.stdout)))
    })
    .into_iter()
    .flatten()
    .collect();
    assert!(
        failed.is_empty(),
        "the baseline build differs from MuJoCo 2.2.2:\n{}",
        failed.join("\n")
    );
}
