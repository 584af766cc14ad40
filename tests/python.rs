//! MuJoCo's Python package on rujoco (python/): the same Python programs on the bindings built
//! against rujoco (`pip install ./python`), run on rujoco and, with Debian's libmujoco.so.2.2.2
//! in its place, on the reference, print the same numbers, and the same digests of the frames
//! they render headless through Mesa's llvmpipe (MUJOCO_GL=egl and MUJOCO_GL=osmesa). The two
//! venvs live under target/python (see build_venv).

mod common;

use common::*;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;

/// Packages installed beside the bindings (the releases that go with MuJoCo 2.2.2), with the
/// bindings' own requirements.
const PACKAGES: &[&str] = &[
    "numpy<2",
    "gymnasium==0.29.1",
    "imageio",
    "absl-py",
    "glfw",
    "pyopengl",
];

/// CMake arguments of the tests' wheel build (MuJoCo's setup.py reads MUJOCO_CMAKE_ARGS): the
/// same sources at -O1 without link-time optimization, which builds in two-thirds of the time
/// (150 s against 228 on two cores), except four sources that compile faster at -O0 (structs.cc
/// 52 s against 80; the others take longer at -O0); `pip install ./python` outside the tests
/// keeps MuJoCo's -O3 and LTO. Both sides run the same compiled bindings, so the comparisons
/// are unaffected.
const WHEEL_CMAKE_ARGS: &str = "-DCMAKE_INTERPROCEDURAL_OPTIMIZATION:BOOL=OFF \
     \"-DCMAKE_CXX_FLAGS_RELEASE:STRING=-O1 -DNDEBUG\" \
     -DRUJOCO_O0_SOURCES=structs.cc;indexers.cc;callbacks.cc;rollout.cc";

/// dm_control 1.0.7 and what it requires but mujoco (its METADATA), installed without
/// dependencies: pip would otherwise look for mujoco on PyPI while ours is being built.
const DM_CONTROL: &str = "dm_control==1.0.7";
const DM_CONTROL_DEPS: &[&str] = &[
    "absl-py>=0.7.0",
    "dm-env",
    "dm-tree!=0.1.2",
    "glfw",
    "labmaze",
    "lxml",
    "numpy>=1.9.0",
    "protobuf>=3.19.4",
    "pyopengl>=3.1.4",
    "pyparsing<3.0.0",
    "requests",
    "setuptools!=50.0.0",
    "scipy",
    "tqdm",
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
    (PACKAGES, DM_CONTROL, DM_CONTROL_DEPS, WHEEL_CMAKE_ARGS).hash(&mut h);
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
        // pip check reports on stdout
        let err = text(&out.stdout) + &text(&out.stderr);
        let tail: Vec<&str> = err.lines().rev().take(25).collect();
        Err(format!(
            "{what} failed:\n{}",
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        ))
    }
}

/// The venv of one side. Ours: the bindings built against our headers and library
/// (`pip install ./python`, as a wheel built while the packages install: pip's install of a
/// directory is a wheel build and the wheel's install) with the packages; the reference's: a
/// copy of ours with Debian's library in place of ours, so that both sides run the same
/// compiled bindings and differ only in the library (the drop-in case). Rebuilt when the
/// headers or the build backend change; ours gets the current libmujoco.so copied in at every
/// run.
fn build_venv(side: Side) -> Result<PathBuf, String> {
    let dir = target_dir().join("python");
    let venv = dir.join(format!("venv-{}", side.name()));
    let py = venv.join("bin/python");
    let stamp_file = venv.join("rujoco-stamp");
    let want = stamp();
    if std::fs::read_to_string(&stamp_file).ok().as_deref() != Some(want.as_str()) {
        let _ = std::fs::remove_dir_all(&venv);
        if side == Side::Ref {
            let Some(ours) = python(Side::Ours) else {
                return Err(
                    "the reference venv is a copy of ours, which could not be built".into(),
                );
            };
            let ours = ours.parent().and_then(Path::parent).unwrap();
            sh(
                Command::new("cp").arg("-a").arg(ours).arg(&venv),
                "cp -a venv-ours venv-ref",
            )?;
        } else {
            sh(
                Command::new("python3").args(["-m", "venv"]).arg(&venv),
                "python3 -m venv",
            )?;
            let pip = |args: &[&str]| {
                let mut c = Command::new(&py);
                c.args(["-m", "pip"]).args(args).current_dir(root());
                c
            };
            let wheels = dir.join("wheel");
            let _ = std::fs::remove_dir_all(&wheels);
            let (built, packages) = std::thread::scope(|s| {
                let built = s.spawn(|| {
                    let mut c = pip(&["wheel", "-q", "--no-deps", "-w"]);
                    c.env("MUJOCO_CMAKE_ARGS", WHEEL_CMAKE_ARGS);
                    sh(
                        c.arg(&wheels).arg(root().join("python")),
                        "pip wheel ./python",
                    )
                });
                let mut all = PACKAGES.to_vec();
                all.extend(DM_CONTROL_DEPS);
                let packages = sh(
                    &mut pip(&[&["install", "-q"], &all[..]].concat()),
                    "pip install",
                )
                .and_then(|()| {
                    sh(
                        &mut pip(&["install", "-q", "--no-deps", DM_CONTROL]),
                        "pip install dm_control",
                    )
                });
                (built.join().unwrap(), packages)
            });
            built?;
            packages?;
            let wheel = std::fs::read_dir(&wheels)
                .map_err(|e| format!("{}: {e}", wheels.display()))?
                .map(|e| e.unwrap().path())
                .find(|p| p.extension().is_some_and(|x| x == "whl"))
                .ok_or("pip wheel ./python made no wheel")?;
            sh(
                pip(&["install", "-q", "--no-deps"]).arg(&wheel),
                "pip install (the bindings' wheel)",
            )?;
            // every requirement of every package installed, mujoco 2.2.2 (ours) included
            sh(&mut pip(&["check"]), "pip check")?;
        }
        std::fs::write(&stamp_file, want).unwrap();
    }
    let lib = match side {
        Side::Ours => our_lib(),
        Side::Ref => PathBuf::from(REF_LIB),
    };
    let dest = site_packages(&venv).join("mujoco/libmujoco.so.2.2.2");
    let _ = std::fs::remove_file(&dest);
    std::fs::copy(lib, &dest).unwrap();
    // the x86-64-v3 build where the wheel carries it (the loader's pick beside $ORIGIN)
    let v3 = dest.with_file_name(HWCAPS_V3).join("libmujoco.so.2.2.2");
    if side == Side::Ours && our_v3_lib().is_some() {
        assert!(v3.exists(), "the wheel holds no {HWCAPS_V3} build");
    }
    if v3.exists() {
        let _ = std::fs::remove_file(&v3);
        if let (Side::Ours, Some(built)) = (side, our_v3_lib()) {
            std::fs::copy(built, &v3).unwrap();
        }
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

/// How the Python side gets OpenGL (MUJOCO_GL): none, or a headless Mesa (llvmpipe) context.
/// PYOPENGL_PLATFORM is left for the bindings and dm_control to derive from MUJOCO_GL.
#[derive(Clone, Copy, PartialEq)]
enum Gl {
    Disable,
    Egl,
    Osmesa,
}

impl Gl {
    fn name(self) -> &'static str {
        match self {
            Gl::Disable => "disable",
            Gl::Egl => "egl",
            Gl::Osmesa => "osmesa",
        }
    }
}

/// Runs a script with arguments in a venv from the repository root; stdout, or a failure.
fn run_py(side: Side, gl: Gl, script: &str, args: &[&str], seconds: u32) -> Option<String> {
    let py = python(side)?;
    let out = Command::new("timeout")
        .arg(seconds.to_string())
        .arg(py)
        .arg(root().join(script))
        .args(args)
        .current_dir(root())
        .env_remove("LD_LIBRARY_PATH")
        .env_remove("PYOPENGL_PLATFORM")
        .env("MUJOCO_GL", gl.name())
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let hint = match gl {
        Gl::Disable => "",
        Gl::Egl => " (EGL needs Mesa's libegl1 and libegl-mesa0: a software device, llvmpipe)",
        Gl::Osmesa => " (OSMesa needs Mesa's libosmesa6)",
    };
    assert!(
        out.status.success(),
        "{script} (MUJOCO_GL={}{hint}) on {} failed ({}):\n{}\n{}",
        gl.name(),
        side.name(),
        out.status,
        text(&out.stdout),
        text(&out.stderr)
    );
    Some(text(&out.stdout))
}

/// The same script on both sides: identical output line by line. Returns the reference's output.
fn same_output(name: &str, gl: Gl, script: &str, args: &[&str], seconds: u32) -> Option<String> {
    let start = std::time::Instant::now();
    // both sides at once (each is one Python process)
    let (ours, reference) = std::thread::scope(|s| {
        let reference = s.spawn(|| run_py(Side::Ref, gl, script, args, seconds));
        let ours = run_py(Side::Ours, gl, script, args, seconds);
        let reference = reference
            .join()
            .unwrap_or_else(|e| std::panic::resume_unwind(e));
        (ours, reference)
    });
    let (Some(ours), Some(reference)) = (ours, reference) else {
        return None;
    };
    let (a, b): (Vec<&str>, Vec<&str>) = (ours.lines().collect(), reference.lines().collect());
    let differ: Vec<String> = a
        .iter()
        .zip(&b)
        .filter(|(x, y)| x != y)
        .map(|(x, y)| format!("ours: {x}\n ref: {y}"))
        .collect();
    // frames rendered: the "N frames" the scripts print
    let frames: usize = b
        .iter()
        .flat_map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            (1..w.len())
                .filter(|&i| w[i].starts_with("frames"))
                .filter_map(|i| w[i - 1].parse::<usize>().ok())
                .collect::<Vec<_>>()
        })
        .sum();
    report(
        &format!("python-{name}"),
        &format!(
            "python {name} (MUJOCO_GL={}): {} lines ({frames} frames rendered), {} identical, \
             {} differ, {:.0} s for both sides\n",
            gl.name(),
            b.len(),
            b.len() - differ.len(),
            differ.len(),
            start.elapsed().as_secs_f64()
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
        "{script} (MUJOCO_GL={}): {} lines differ:\n{}",
        gl.name(),
        differ.len(),
        differ.join("\n")
    );
    Some(reference)
}

#[test]
fn examples_same_numbers() {
    same_output(
        "pendulum",
        Gl::Disable,
        "examples/python/pendulum.py",
        &[],
        120,
    );
    same_output("arm", Gl::Disable, "examples/python/arm.py", &[], 120);
    same_output(
        "arm-env",
        Gl::Disable,
        "examples/python/arm_env.py",
        &[],
        120,
    );
    same_output(
        "gym-loop",
        Gl::Disable,
        "examples/python/gym_loop.py",
        &[],
        120,
    );
    let png = target_dir().join("python/render_headless.png");
    let png = png.to_str().unwrap();
    let mut outputs = Vec::new();
    for gl in [Gl::Egl, Gl::Osmesa] {
        let name = format!("render-headless-{}", gl.name());
        let args = ["models/arm3.xml", png];
        if let Some(out) = same_output(&name, gl, "examples/python/render_headless.py", &args, 120)
        {
            // four frames of a moving arm: four different images, and the PNG written
            let hashes: std::collections::HashSet<&str> = out
                .lines()
                .skip(1)
                .filter_map(|l| l.split_whitespace().nth(1))
                .filter(|h| h.len() == 32)
                .collect();
            assert_eq!(hashes.len(), 4, "{out}");
            let bytes = std::fs::read(png).unwrap();
            assert!(bytes.starts_with(b"\x89PNG"), "{png} is no PNG");
            outputs.push(out);
        }
    }
    if let [egl, osmesa] = &outputs[..] {
        // both are llvmpipe: noted, not required
        report(
            "python-render-headless-backends",
            &format!(
                "python render-headless: EGL and OSMesa frames identical: {}\n",
                if egl == osmesa { "yes" } else { "no" }
            ),
        );
    }
}

/// Lines of `out` with pixel digests (rendered frames), for comparing the two GL backends.
fn pixel_lines(out: &str) -> Vec<&str> {
    out.lines().filter(|l| l.contains(" pixels ")).collect()
}

/// Every task of the suite, quadruped/escape included (its terrain goes up through
/// mjr_uploadHField): physics numbers for 200 steps and, for each of the suite's models (the
/// first of the tasks that share one), physics.render frames (RGB from cameras -1 and 0, depth,
/// segmentation) under EGL; under OSMesa (the same llvmpipe behind another context) a shorter
/// run of tasks with height fields, meshes, textures and many bodies.
#[test]
fn dm_control_suite_same_numbers_and_pixels() {
    let egl = same_output(
        "dm-control-egl",
        Gl::Egl,
        "tests/python/dmc.py",
        &["200", "--render"],
        900,
    );
    let osmesa = same_output(
        "dm-control-osmesa",
        Gl::Osmesa,
        "tests/python/dmc.py",
        &[
            "20",
            "--render",
            "quadruped/escape",
            "dog/fetch",
            "humanoid_CMU/run",
            "manipulator/bring_ball",
            "fish/swim",
            "cartpole/swingup",
        ],
        900,
    );
    if let Some(out) = &osmesa {
        assert_eq!(out.lines().count(), 6, "{out}");
        assert_eq!(pixel_lines(out).len(), 6, "{out}");
    }
    if let Some(out) = &egl {
        // every task, each model of the suite rendered once (29 of its 50 tasks): the others
        // name the task whose frames stand for theirs
        let pixels = pixel_lines(out);
        let stand_ins = out
            .lines()
            .filter(|l| l.contains(" rendered with "))
            .count();
        assert_eq!(pixels.len() + stand_ins, out.lines().count(), "{out}");
        assert!(pixels.len() >= 29, "{out}");
        assert!(out.lines().count() >= 50, "{out}");
        assert!(
            pixels.iter().any(|l| l.starts_with("quadruped/escape")),
            "{out}"
        );
    }
}

/// Gymnasium's v4 environments: numbers and env.render() frames, rgb_array for each and
/// depth_array for two, under EGL (200 steps) and OSMesa (20 steps).
#[test]
fn gymnasium_same_numbers_and_pixels() {
    same_output(
        "gymnasium-egl",
        Gl::Egl,
        "tests/python/gym_envs.py",
        &["200", "--render"],
        600,
    );
    same_output(
        "gymnasium-osmesa",
        Gl::Osmesa,
        "tests/python/gym_envs.py",
        &["20", "--render"],
        600,
    );
}

#[test]
fn common_errors_same_messages() {
    same_output("errors", Gl::Disable, "tests/python/errors.py", &[], 120);
}

/// MuJoCo's own Python tests (bindings_test, rollout_test, render_test) pass on ours under
/// both headless backends, with the reference's counts; render_test really renders (nothing
/// skipped).
#[test]
fn upstream_python_tests_pass() {
    let args = [
        "mujoco.bindings_test",
        "mujoco.rollout_test",
        "mujoco.render_test",
    ];
    for gl in [Gl::Egl, Gl::Osmesa] {
        let (Some(ours), Some(reference)) = (
            run_py(Side::Ours, gl, "tests/python/upstream.py", &args, 600),
            run_py(Side::Ref, gl, "tests/python/upstream.py", &args, 600),
        ) else {
            return;
        };
        let summary = |s: &str| {
            s.lines()
                .filter(|l| l.starts_with("ran ") || l.starts_with("module "))
                .collect::<Vec<_>>()
                .join("; ")
        };
        report(
            &format!("python-upstream-{}", gl.name()),
            &format!(
                "python upstream tests (MUJOCO_GL={}): ours {}\n",
                gl.name(),
                summary(&ours)
            ),
        );
        assert_eq!(summary(&ours), summary(&reference));
        assert!(summary(&ours).contains("failures 0, errors 0"), "{ours}");
        assert!(
            summary(&ours).contains("module mujoco.render_test: ran 3, skipped 0"),
            "{ours}"
        );
    }
}
