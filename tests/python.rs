//! MuJoCo's Python package on rujoco (python/): the same Python programs on the bindings built
//! against rujoco and against Debian's 2.2.2 print the same numbers. The two venvs live under
//! target/python and are rebuilt only when the headers or the build backend change; ours gets
//! the current libmujoco.so copied in at every run.

mod common;

use common::*;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;

/// Packages installed beside the bindings (the releases that go with MuJoCo 2.2.2).
const PACKAGES: &[&str] = &[
    "numpy<2",
    "dm_control==1.0.7",
    "gymnasium==0.29.1",
    "imageio",
];

#[derive(Clone, Copy, PartialEq)]
enum Side {
    Ours,
    Ref,
}

impl Side {
    fn name(self) -> &'static str {
        match self {
            Side::Ours => "ours",
            Side::Ref => "ref",
        }
    }
}

fn stamp() -> String {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("include/mujoco"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.push(root().join("python/rujoco_build.py"));
    files.push(root().join("python/pyproject.toml"));
    files.sort();
    for f in files {
        std::fs::read(&f).unwrap().hash(&mut h);
    }
    PACKAGES.hash(&mut h);
    format!("{:016x}\n", h.finish())
}

fn sh(cmd: &mut Command, what: &str) -> Result<(), String> {
    let out = cmd
        .env_remove("LD_LIBRARY_PATH")
        .stdin(Stdio::null())
        .output()
        .map_err(|e| format!("{what}: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        let err = text(&out.stderr);
        let tail: Vec<&str> = err.lines().rev().take(25).collect();
        Err(format!(
            "{what} failed:\n{}",
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        ))
    }
}

/// Debian's 2.2.2 headers and library in the layout the bindings' setup.py looks for.
fn reference_stage(dir: &Path) -> PathBuf {
    let stage = dir.join("reference-mujoco");
    let _ = std::fs::remove_dir_all(&stage);
    std::fs::create_dir_all(stage.join("lib")).unwrap();
    std::fs::create_dir_all(stage.join("include/mujoco")).unwrap();
    for e in std::fs::read_dir("/usr/include/mujoco").unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(
            &p,
            stage.join("include/mujoco").join(p.file_name().unwrap()),
        )
        .unwrap();
    }
    std::fs::copy(REF_LIB, stage.join("lib/libmujoco.so.2.2.2")).unwrap();
    std::os::unix::fs::symlink("libmujoco.so.2.2.2", stage.join("lib/libmujoco.so")).unwrap();
    stage
}

fn build_venv(side: Side) -> Result<PathBuf, String> {
    let dir = target_dir().join("python");
    let venv = dir.join(format!("venv-{}", side.name()));
    let py = venv.join("bin/python");
    let stamp_file = venv.join("rujoco-stamp");
    let want = stamp();
    if std::fs::read_to_string(&stamp_file).ok().as_deref() != Some(want.as_str()) {
        let _ = std::fs::remove_dir_all(&venv);
        sh(
            Command::new("python3").args(["-m", "venv"]).arg(&venv),
            "python3 -m venv",
        )?;
        let mut pip = Command::new(&py);
        pip.args(["-m", "pip", "install", "-q"])
            .arg(root().join("python"))
            .args(PACKAGES)
            .current_dir(root());
        if side == Side::Ref {
            pip.env("RUJOCO_BINDINGS_MUJOCO_PATH", reference_stage(&dir));
        }
        sh(&mut pip, &format!("pip install ./python ({})", side.name()))?;
        std::fs::write(&stamp_file, want).unwrap();
    }
    if side == Side::Ours {
        let site = site_packages(&venv);
        std::fs::copy(our_lib(), site.join("mujoco/libmujoco.so.2.2.2")).unwrap();
    }
    Ok(py)
}

fn site_packages(venv: &Path) -> PathBuf {
    let lib = venv.join("lib");
    let py = std::fs::read_dir(&lib)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| {
            p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("python3")
        })
        .unwrap();
    py.join("site-packages")
}

/// The venv's python, built on first use; None (with the reason printed) where the build
/// dependencies cannot be had.
fn python(side: Side) -> Option<&'static PathBuf> {
    static OURS: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    static REF: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    let cell = if side == Side::Ours { &OURS } else { &REF };
    let r = cell.get_or_init(|| {
        require_reference();
        our_lib();
        build_venv(side)
    });
    match r {
        Ok(p) => Some(p),
        Err(e) if e.contains("needs the Debian packages") || e.contains("No matching") => {
            eprintln!("SKIP: {e}");
            None
        }
        Err(e) => panic!("{e}"),
    }
}

/// Runs a script with arguments in a venv from the repository root; stdout, or a failure.
fn run_py(side: Side, script: &str, args: &[&str], seconds: u32) -> Option<String> {
    let py = python(side)?;
    let out = Command::new("timeout")
        .arg(seconds.to_string())
        .arg(py)
        .arg(root().join(script))
        .args(args)
        .current_dir(root())
        .env_remove("LD_LIBRARY_PATH")
        .env("MUJOCO_GL", "disable")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{script} on {} failed ({}):\n{}\n{}",
        side.name(),
        out.status,
        text(&out.stdout),
        text(&out.stderr)
    );
    Some(text(&out.stdout))
}

/// The same script on both sides: identical output line by line.
fn same_output(name: &str, script: &str, args: &[&str], seconds: u32) {
    let (Some(ours), Some(reference)) = (
        run_py(Side::Ours, script, args, seconds),
        run_py(Side::Ref, script, args, seconds),
    ) else {
        return;
    };
    let (a, b): (Vec<&str>, Vec<&str>) = (ours.lines().collect(), reference.lines().collect());
    let differ: Vec<String> = a
        .iter()
        .zip(&b)
        .filter(|(x, y)| x != y)
        .map(|(x, y)| format!("ours: {x}\n ref: {y}"))
        .collect();
    report(
        &format!("python-{name}"),
        &format!(
            "python {name}: {} lines, {} identical, {} differ\n",
            b.len(),
            b.len() - differ.len(),
            differ.len()
        ),
    );
    assert!(!b.is_empty(), "{script} printed nothing on the reference");
    assert_eq!(
        a.len(),
        b.len(),
        "{script}: line counts differ:\n{ours}\n---\n{reference}"
    );
    assert!(
        differ.is_empty(),
        "{script}: {} lines differ:\n{}",
        differ.len(),
        differ.join("\n")
    );
}

#[test]
fn examples_same_numbers() {
    same_output("pendulum", "examples/python/pendulum.py", &[], 120);
    same_output("arm", "examples/python/arm.py", &[], 120);
    same_output("arm-env", "examples/python/arm_env.py", &[], 120);
    same_output("gym-loop", "examples/python/gym_loop.py", &[], 120);
}

#[test]
fn dm_control_suite_same_numbers() {
    // quadruped/escape uploads its terrain through mjr_ (not implemented yet)
    same_output(
        "dm-control",
        "tests/python/dmc.py",
        &["200", "quadruped/escape"],
        900,
    );
}

#[test]
fn gymnasium_same_numbers() {
    same_output("gymnasium", "tests/python/gym_envs.py", &["200"], 600);
}

#[test]
fn common_errors_same_messages() {
    same_output("errors", "tests/python/errors.py", &[], 120);
}

/// MuJoCo's own Python tests (bindings_test, rollout_test) pass on ours; the tests that use
/// mjr_ wait for the OpenGL layer.
#[test]
fn upstream_python_tests_pass() {
    let args = [
        "mujoco.bindings_test",
        "mujoco.rollout_test",
        "--without",
        "Mjr",
        "mjr_",
    ];
    let (Some(ours), Some(reference)) = (
        run_py(Side::Ours, "tests/python/upstream.py", &args, 600),
        run_py(Side::Ref, "tests/python/upstream.py", &args, 600),
    ) else {
        return;
    };
    let summary = |s: &str| {
        s.lines()
            .find(|l| l.starts_with("ran "))
            .unwrap_or("")
            .to_string()
    };
    report(
        "python-upstream",
        &format!("python upstream tests: ours {}\n", summary(&ours)),
    );
    assert_eq!(summary(&ours), summary(&reference));
    assert!(summary(&ours).contains("failures 0, errors 0"), "{ours}");
}
