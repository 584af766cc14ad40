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
    // the baseline build, or the x86-64-v3 one beside it on a CPU with AVX2
    assert_eq!(
        Path::new(resolved).canonicalize().ok(),
        loaded_lib().canonicalize().ok(),
        "ldd under LD_LIBRARY_PATH does not pick ours: {line}"
    );

    // best of three alternating runs: the machine's cores are shared
    let arm3 = model("arm3.xml");
    let (mut ref_sps, mut our_sps) = (None::<f64>, None::<f64>);
    let (mut reference, mut ours) = (None, None);
    for _ in 0..3 {
        let r = run(TESTSPEED.as_ref(), &[&arm3, STEPS], &[], 120);
        let o = run(
            TESTSPEED.as_ref(),
            &[&arm3, STEPS],
            &[("LD_LIBRARY_PATH", &ld)],
            120,
        );
        let best = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(x), Some(y)) => Some(x.max(y)),
            (x, y) => x.or(y),
        };
        ref_sps = best(ref_sps, steps_per_second(&text(&r.stdout)));
        our_sps = best(our_sps, steps_per_second(&text(&o.stdout)));
        let failed = !o.status.success();
        reference = Some(r);
        ours = Some(o);
        if failed {
            break;
        }
    }
    let (reference, ours) = (reference.unwrap(), ours.unwrap());
    let fmt = |s: Option<f64>| s.map_or("-".to_string(), |v| format!("{v:.0}"));
    let msg = format!(
        "drop-in: mujoco-testspeed models/arm3.xml {STEPS}: ldd -> {resolved}\n  steps per second (best of 3): reference {}, ours {}{}\n",
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

const DERIVATIVE: &str = "/usr/bin/mujoco-derivative";

/// Debian's prebuilt mujoco-derivative, unmodified, on ours: its finite-difference
/// derivatives of forward and inverse dynamics agree with the reference's (the printed
/// accuracy table is identical); the timing lines are reported.
#[test]
fn derivative_runs_on_ours() {
    require_reference();
    assert!(
        Path::new(DERIVATIVE).exists(),
        "{DERIVATIVE} missing: install libmujoco-samples"
    );
    our_lib();
    let ld = lib_dir()
        .canonicalize()
        .unwrap()
        .to_string_lossy()
        .to_string();
    let humanoid = corpus_files()
        .into_iter()
        .find(|f| f.ends_with("model/humanoid/humanoid.xml"))
        .map(|f| f.to_string_lossy().into_owned());
    let models = [
        Some(model("arm3.xml")),
        Some(model("extra/contact_primitives.xml")),
        humanoid,
    ];
    let mut summary = String::new();
    for m in models.into_iter().flatten() {
        let args = [m.as_str(), "1", "20", "3", "5", "50", "1e-6"];
        let reference = run(Path::new(DERIVATIVE), &args, &[], 300);
        let ours = run(
            Path::new(DERIVATIVE),
            &args,
            &[("LD_LIBRARY_PATH", &ld)],
            300,
        );
        let (r, o) = (text(&reference.stdout), text(&ours.stdout));
        assert!(
            reference.status.success(),
            "reference mujoco-derivative failed on {m}:\n{r}"
        );
        assert!(
            ours.status.success(),
            "mujoco-derivative on ours failed on {m}:\n{o}{}",
            text(&ours.stderr)
        );
        let timing = |l: &&str| l.starts_with("inverse :") || l.starts_with("forward :");
        let strip = |s: &str| {
            s.lines()
                .filter(|l| !timing(l))
                .collect::<Vec<_>>()
                .join("\n")
        };
        assert_eq!(strip(&r), strip(&o), "derivatives differ on {m}");
        let times = |s: &str| {
            s.lines()
                .filter(timing)
                .map(str::trim)
                .collect::<Vec<_>>()
                .join(", ")
        };
        let name = Path::new(&m)
            .file_name()
            .unwrap()
            .to_string_lossy()
            .to_string();
        summary.push_str(&format!(
            "  {name}: accuracy table identical; reference {}; ours {}\n",
            times(&r),
            times(&o)
        ));
    }
    report(
        "dropin-derivative",
        &format!("drop-in: mujoco-derivative on ours (LD_LIBRARY_PATH)\n{summary}"),
    );
}

const COMPILE: &str = "/usr/bin/mujoco-compile";

/// Debian's prebuilt mujoco-compile writes the same MJB bytes on ours as on the reference, for
/// every model of models.list and of the corpus that the reference compiles and we support.
#[test]
fn compile_writes_identical_mjb() {
    require_reference();
    assert!(
        Path::new(COMPILE).exists(),
        "{COMPILE} missing: install libmujoco-samples"
    );
    our_lib();
    let ld = lib_dir()
        .canonicalize()
        .unwrap()
        .to_string_lossy()
        .to_string();
    let mut files = models();
    files.extend(
        corpus_files()
            .into_iter()
            .map(|f| f.to_string_lossy().into_owned()),
    );
    let dir = work_dir("mjb");
    /// What mujoco-compile gave on both libraries.
    #[derive(PartialEq)]
    enum Mjb {
        Rejected,
        Same,
        Unsupported,
        Differs,
    }
    let verdicts = par_map(&files, |i, f| {
        let (r, o) = (
            dir.join(format!("{i}-ref.mjb")),
            dir.join(format!("{i}-ours.mjb")),
        );
        let _ = (std::fs::remove_file(&r), std::fs::remove_file(&o));
        let (rs, os) = (r.to_string_lossy(), o.to_string_lossy());
        run(Path::new(COMPILE), &[f, &rs], &[], 120);
        let Ok(want) = std::fs::read(&r) else {
            return Mjb::Rejected;
        };
        let out = run(
            Path::new(COMPILE),
            &[f, &os],
            &[("LD_LIBRARY_PATH", &ld)],
            120,
        );
        let verdict = match std::fs::read(&o) {
            Ok(got) if got == want => Mjb::Same,
            Err(_) if text(&out.stdout).contains("not supported") => Mjb::Unsupported,
            _ => Mjb::Differs,
        };
        // only a differing pair is kept to look at (all pairs take gigabytes)
        if verdict != Mjb::Differs {
            let _ = (std::fs::remove_file(&r), std::fs::remove_file(&o));
        }
        verdict
    });
    let count = |kind: Mjb| verdicts.iter().filter(|&v| *v == kind).count();
    let (same, unsupported) = (count(Mjb::Same), count(Mjb::Unsupported));
    let differ: Vec<&String> = files
        .iter()
        .zip(&verdicts)
        .filter(|(_, v)| **v == Mjb::Differs)
        .map(|(f, _)| f)
        .collect();
    let msg = format!(
        "mujoco-compile to MJB: {same} byte-identical, {unsupported} not supported yet, {} differ\n{}",
        differ.len(),
        differ.iter().map(|f| format!("  differs: {f}\n")).collect::<String>()
    );
    report("mjb", &msg);
    assert!(differ.is_empty() && same > 0, "{msg}");
}
