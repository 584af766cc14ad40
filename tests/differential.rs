//! Differential checks against Debian's MuJoCo 2.2.2 (capi-tests/harness): every model of
//! capi-tests/models.list is run once through both libraries; each test compares one family
//! of results over all models and fails listing the quantities beyond tolerance.

mod common;
use common::*;
use std::path::{Path, PathBuf};
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
        // where the loader takes the x86-64-v3 build, the baseline one replays the same recording
        let v3 = loaded_lib() != our_lib();
        let ours = bin.join("harness-ours").to_string_lossy().into_owned();
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
            let mut pass = full.status.success();
            if v3 {
                let _ = std::fs::rename(dir.join("ours"), dir.join("ours-x86-64-v3"));
                let args = ["--glibc-hwcaps-mask", "none", &ours, "replay", model, &d];
                run(Path::new(LD_SO), &args, &[], 300);
                let b = run(&bin.join("harness-ref"), &["compare", &d, "-v"], &[], 120);
                std::fs::write(dir.join("report-baseline.txt"), &b.stdout).unwrap();
                pass &= b.status.success();
            }
            // a passing model's dumps (gigabytes over the list) go; a failing one's stay
            if pass {
                for f in ["ours", "ours-x86-64-v3", "ref"] {
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
fn loaded_library(prog: &Path, mask: Option<&str>) -> PathBuf {
    let p = prog.to_string_lossy();
    let mut args = vec![];
    if let Some(m) = mask {
        args.extend(["--glibc-hwcaps-mask", m]);
    }
    args.extend(["--list", &p]);
    let out = run(Path::new(LD_SO), &args, &[], 30);
    let list = text(&out.stdout);
    let file = list
        .lines()
        .find(|l| l.trim_start().starts_with("libmujoco.so"))
        .and_then(|l| l.split("=> ").nth(1))
        .and_then(|r| r.split_whitespace().next())
        .unwrap_or_else(|| panic!("no libmujoco in ld.so --list {p}:\n{list}"));
    PathBuf::from(file).canonicalize().unwrap()
}

/// Where a CPU has AVX2, the loader takes the x86-64-v3 build (`cargo xtask hwcaps`) and every
/// other test runs that one; the baseline build, which every other x86-64 runs, replayed every
/// model's recording too (the loader told to skip glibc-hwcaps/): every check group of it
/// passes at its tolerance. Elsewhere the baseline build is the one all the checks ran.
#[test]
fn baseline_build_on_every_model() {
    let (bin, base) = results();
    let ours = bin.join("harness-ours");
    let baseline = lib_dir().join("libmujoco.so.2.2.2").canonicalize().unwrap();
    let masked = loaded_library(&ours, Some("none"));
    assert_eq!(masked, baseline, "the masked replay loads another library");
    let plain = loaded_library(&ours, None);
    assert_eq!(
        plain,
        loaded_lib().canonicalize().unwrap(),
        "the checks load {plain:?}"
    );
    if plain == baseline {
        return;
    }
    let failed: Vec<String> = models()
        .into_iter()
        .filter_map(|model| {
            let file = base.join(stem(&model)).join("report-baseline.txt");
            let report = std::fs::read_to_string(file).unwrap_or_default();
            let pass = report.contains(" check groups pass") && !report.contains(" FAIL ");
            (!pass).then(|| format!("{model}:\n{report}"))
        })
        .collect();
    assert!(
        failed.is_empty(),
        "the baseline build differs from MuJoCo 2.2.2:\n{}",
        failed.join("\n")
    );
}
