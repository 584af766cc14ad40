//! Source compatibility: the sample programs Debian ships with MuJoCo 2.2.2 (their C++ sources,
//! package libmujoco-samples) compile unchanged against our headers, link to our library, and
//! the compiled testspeed runs a model on it with the same contact/constraint counts.

mod common;
use common::*;
use std::path::PathBuf;
use std::process::Command;

const SAMPLES: &str = "/usr/share/doc/libmujoco-samples/examples";

fn compile_sample(name: &str, tag: &str) -> PathBuf {
    let src = PathBuf::from(SAMPLES).join(format!("{name}.cc"));
    assert!(
        src.exists(),
        "{} missing: install libmujoco-samples",
        src.display()
    );
    let out = work_dir("bin").join(format!("sample-{name}-{tag}-ours"));
    let dir = lib_dir();
    our_lib();
    let o = Command::new("g++")
        .args(["-std=c++17", "-O2", "-o"])
        .arg(&out)
        .arg(&src)
        .arg("-I")
        .arg(root().join("include"))
        .arg(format!("-L{}", dir.display()))
        .args(["-lmujoco", "-lpthread"])
        .arg(format!("-Wl,--disable-new-dtags,-rpath,{}", dir.display()))
        .output()
        .expect("g++ not found: install build-essential");
    assert!(
        o.status.success(),
        "{name}.cc does not compile against our headers:\n{}",
        text(&o.stderr)
    );
    out
}

#[test]
fn debian_samples_compile_against_our_headers() {
    for name in ["testspeed", "compile", "derivative", "testxml"] {
        compile_sample(name, "compat");
    }
}

#[test]
fn sample_testspeed_built_on_ours_runs() {
    let bin = compile_sample("testspeed", "run");
    let o = run(&bin, &[&model("arm3.xml"), "2000", "1", "0"], &[], 120);
    let out = text(&o.stdout);
    assert!(
        o.status.success(),
        "testspeed failed:\n{out}{}",
        text(&o.stderr)
    );
    for line in [
        "Steps per second",
        "Contacts per step    : 0.00",
        "Constraints per step : 0.00",
    ] {
        assert!(
            out.contains(line),
            "testspeed output lacks \"{line}\":\n{out}"
        );
    }
}
