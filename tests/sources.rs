//! Source compatibility: the sample programs Debian ships with MuJoCo 2.2.2 (their C++ sources,
//! package libmujoco-samples) compile unchanged against our headers, link to our library, and
//! the compiled testspeed runs a model on it with the same contact/constraint counts; basic.cc
//! and record.cc (GLFW, EGL, OSMesa) compile too, and record.cc built on ours for OSMesa writes
//! the frames it writes when built on Debian's.

mod common;
use common::*;
use std::path::PathBuf;
use std::process::Command;

const SAMPLES: &str = "/usr/share/doc/libmujoco-samples/examples";

fn compile_sample(name: &str, tag: &str) -> PathBuf {
    compile_sample_with(name, tag, &[], Lib::Ours)
}

/// A sample compiled with extra flags (platform defines, GL libraries) against one library.
fn compile_sample_with(name: &str, tag: &str, flags: &[&str], lib: Lib) -> PathBuf {
    let src = PathBuf::from(SAMPLES).join(format!("{name}.cc"));
    assert!(
        src.exists(),
        "{} missing: install libmujoco-samples",
        src.display()
    );
    let out = work_dir("bin").join(format!("sample-{name}-{tag}-{}", lib.name()));
    let (include, dir) = match lib {
        Lib::Ref => (
            PathBuf::from("/usr/include"),
            PathBuf::from("/usr/lib/x86_64-linux-gnu"),
        ),
        _ => {
            our_lib();
            (root().join("include"), lib_dir())
        }
    };
    let o = Command::new("g++")
        .args(["-std=c++17", "-O2", "-o"])
        .arg(&out)
        .arg(&src)
        .arg("-I")
        .arg(&include)
        .arg(format!("-L{}", dir.display()))
        .args(["-lmujoco", "-lpthread"])
        .args(flags)
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
fn debian_gl_samples_compile_against_our_headers() {
    compile_sample_with("basic", "compat", &["-lglfw"], Lib::Ours);
    compile_sample_with("record", "glfw", &["-lglfw"], Lib::Ours);
    compile_sample_with("record", "egl", &["-DMJ_EGL", "-lEGL"], Lib::Ours);
    compile_sample_with("record", "osmesa", &["-DMJ_OSMESA", "-lOSMesa"], Lib::Ours);
}

/// record.cc built for OSMesa (no display) against our headers and library writes the same
/// frames as when built against Debian's.
#[test]
fn sample_record_built_on_ours_matches() {
    require_reference();
    let flags = ["-DMJ_OSMESA", "-lOSMesa"];
    let ours = compile_sample_with("record", "osmesa-run", &flags, Lib::Ours);
    let reference = compile_sample_with("record", "osmesa-run", &flags, Lib::Ref);
    let dir = work_dir("sources");
    let mut frames = Vec::new();
    for (bin, tag) in [(&reference, "ref"), (&ours, "ours")] {
        let out = dir.join(format!("record-{tag}.rgb"));
        let o = run(
            bin,
            &[&model("arm3.xml"), "0.5", "30", &out.to_string_lossy()],
            &[],
            300,
        );
        assert!(
            o.status.code() == Some(1) && o.stderr.is_empty(),
            "record ({tag}) failed: {}{}",
            text(&o.stdout),
            text(&o.stderr)
        );
        frames.push(std::fs::read(&out).unwrap());
    }
    assert!(
        frames[0].len() >= 640 * 480 * 3 * 10,
        "{} bytes",
        frames[0].len()
    );
    assert!(frames[0] == frames[1], "record.cc (OSMesa) frames differ");
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
