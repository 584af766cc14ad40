//! `cargo xtask pgo`: records the profile the release build is optimized with
//! (`pgo/rujoco.profdata`, applied by `pgo/rustc` through `.cargo/config.toml`).
//!
//! Builds an instrumented library into target/pgo (and on a CPU with AVX2 its x86-64-v3 build,
//! `cargo xtask hwcaps`, into target/pgo-v3), runs `capi-tests/pgo_train.c` on each once per
//! model file (ours under models/, and the corpus when present: `RUJOCO_CORPUS`, else
//! ../shared/corpus), merges the counts with the toolchain's llvm-profdata (`rustup component
//! add llvm-tools`), lists the sources the profile belongs to in pgo/sources.txt and that
//! LLVM's major version in pgo/llvm-major (pgo/rustc uses the profile from it on). Only rujoco
//! runs: no other library is involved. target/release and the x86-64-v3 build's directory are
//! cleaned afterwards: cargo does not see a new profile by itself.

use std::path::{Path, PathBuf};
use std::process::{exit, Command, Stdio};
use std::time::{Duration, Instant};

use crate::sources::source_digests;
use crate::{cargo, fail, must, root, target_dir};

/// Driven steps of full physics per model (and half as many smooth).
const STEPS: &str = "400";
/// A model's run is stopped after this long.
const LIMIT: Duration = Duration::from_secs(60);

pub fn pgo() {
    let root = root();
    let (profdata, llvm_major) = llvm_profdata();
    // the sources the profile belongs to, read before the run (tests/speed.rs compares)
    let digests = source_digests(&root);

    // the instrumented library (pgo/rustc adds no profile next to -Cprofile-generate)
    let work = target_dir().join("pgo");
    let raw = work.join("raw");
    must(
        cargo()
            .args(["build", "--release", "--package", "rujoco", "--lib"])
            .env("RUSTFLAGS", format!("-Cprofile-generate={}", raw.display()))
            .env("CARGO_TARGET_DIR", &work)
            .current_dir(&root),
        "the instrumented build",
    );
    let mut raws = vec![train(&work, &raw)];
    // the x86-64-v3 build (`cargo xtask hwcaps`) as well, where this CPU runs it: a few
    // functions branch differently there, and their counts go in under their own hash
    if v3_runs_here() {
        let work = target_dir().join("pgo-v3");
        let raw = work.join("raw");
        let generate = format!("-Cprofile-generate={}", raw.display());
        must(
            cargo()
                .args(["rustc", "--release", "--package", "rujoco", "--lib", "--"])
                .args([generate.as_str(), "-Ctarget-cpu=x86-64-v3"])
                .env("CARGO_TARGET_DIR", &work)
                .current_dir(&root),
            "the instrumented x86-64-v3 build",
        );
        raws.push(train(&work, &raw));
    }

    let out = root.join("pgo/rujoco.profdata");
    std::fs::create_dir_all(out.parent().unwrap()).unwrap_or_else(|e| fail("pgo", e));
    must(
        Command::new(&profdata)
            .arg("merge")
            .arg("-o")
            .arg(&out)
            .args(&raws),
        "llvm-profdata merge",
    );
    std::fs::write(root.join("pgo/sources.txt"), digests)
        .unwrap_or_else(|e| fail("pgo/sources.txt", e));
    // an older LLVM cannot read the profile: pgo/rustc leaves it out there
    std::fs::write(root.join("pgo/llvm-major"), format!("{llvm_major}\n"))
        .unwrap_or_else(|e| fail("pgo/llvm-major", e));
    println!("{}", out.display());
    // the crates built on the old profile are rebuilt on the new one (cargo does not track it)
    let _ = cargo()
        .args(["clean", "--release"])
        .current_dir(&root)
        .status();
    let _ = std::fs::remove_dir_all(crate::hwcaps_build_dir());
}

/// Runs capi-tests/pgo_train.c on the instrumented library in `work`/release once per model
/// file; returns `raw`, the directory of its counts.
fn train(work: &Path, raw: &Path) -> PathBuf {
    let root = root();
    // counts of the build's own programs (build scripts) are not the library's
    let _ = std::fs::remove_dir_all(raw);
    std::fs::create_dir_all(raw).unwrap_or_else(|e| fail(&raw.display().to_string(), e));
    let lib = work.join("release");
    let train = work.join("pgo_train");
    must(
        Command::new("cc")
            .args(["-std=c11", "-O2", "-I"])
            .arg(root.join("include"))
            .arg(root.join("capi-tests/pgo_train.c"))
            .arg("-o")
            .arg(&train)
            .arg(lib.join("libmujoco.so"))
            .arg(format!("-Wl,-rpath,{}", lib.display()))
            .arg("-lm"),
        "compiling capi-tests/pgo_train.c",
    );
    let models = models(&root);
    let start = Instant::now();
    let mut stopped = 0;
    for m in &models {
        if !run_limited(Command::new(&train).arg(STEPS).arg(m)) {
            stopped += 1;
        }
    }
    println!(
        "xtask: {} model files run in {:.0} s on {} ({} stopped after {} s)",
        models.len(),
        start.elapsed().as_secs_f64(),
        lib.display(),
        stopped,
        LIMIT.as_secs()
    );
    raw.to_path_buf()
}

/// Does this CPU run x86-64-v3 code (the features of that level)?
fn v3_runs_here() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        has!("avx2")
            && has!("fma")
            && has!("bmi1")
            && has!("bmi2")
            && has!("lzcnt")
            && has!("movbe")
            && has!("f16c")
    }
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// The toolchain's own llvm-profdata (the raw format follows rustc's LLVM) and the major
/// version of that LLVM.
fn llvm_profdata() -> (PathBuf, String) {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let text = |args: &[&str]| {
        Command::new(&rustc)
            .args(args)
            .output()
            .ok()
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
            .unwrap_or_default()
    };
    let sysroot = text(&["--print", "sysroot"]);
    let version = text(&["-vV"]);
    let field = |name: &str| {
        version
            .lines()
            .find_map(|l| l.strip_prefix(name).map(str::to_string))
            .unwrap_or_default()
    };
    let host = field("host: ");
    let llvm = field("LLVM version: ");
    let major = llvm.split('.').next().unwrap_or_default().to_string();
    let tool = Path::new(&sysroot).join(format!("lib/rustlib/{host}/bin/llvm-profdata"));
    if !tool.is_file() {
        eprintln!(
            "xtask: {} is missing: rustup component add llvm-tools",
            tool.display()
        );
        exit(1);
    }
    if major.parse::<u32>().is_err() {
        eprintln!("xtask: rustc -vV gives no LLVM version");
        exit(1);
    }
    (tool, major)
}

/// The MJCF files the profile is recorded on, sorted: `RUJOCO_CORPUS`, else the corpus the
/// test suite runs: ../shared/corpus and the model trees of the packages `capi-tests/run-all`
/// fetches into target/third-party (capi-tests/corpus-dirs.txt, run-all's list; the mesh-heavy
/// arms, grippers and hands are among them).
fn models(root: &Path) -> Vec<PathBuf> {
    let corpus: Vec<PathBuf> = match std::env::var_os("RUJOCO_CORPUS") {
        Some(v) => std::env::split_paths(&v).collect(),
        None => {
            let tp = target_dir().join("third-party");
            let list = std::fs::read_to_string(root.join("capi-tests/corpus-dirs.txt"))
                .unwrap_or_else(|e| fail("capi-tests/corpus-dirs.txt", e));
            let fetched: Vec<PathBuf> = list
                .lines()
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .map(|d| tp.join(d))
                .collect();
            if !fetched.iter().any(|d| d.is_dir()) {
                eprintln!(
                    "xtask: no packages in {}: the profile leaves out the models \
                     capi-tests/run-all fetches (run it once first)",
                    tp.display()
                );
            }
            std::iter::once(root.join("../shared/corpus"))
                .chain(fetched)
                .collect()
        }
    };
    let mut files = Vec::new();
    for dir in std::iter::once(root.join("models")).chain(corpus) {
        xml_files(&dir, &mut files);
    }
    files.sort();
    files.dedup();
    files
}

fn xml_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            xml_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "xml") {
            out.push(p);
        }
    }
}

/// Runs `cmd` quietly; false when it was stopped at the limit.
fn run_limited(cmd: &mut Command) -> bool {
    let Ok(mut child) = cmd.stdout(Stdio::null()).stderr(Stdio::null()).spawn() else {
        return false;
    };
    let start = Instant::now();
    loop {
        if let Ok(Some(_)) = child.try_wait() {
            return true;
        }
        if start.elapsed() > LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return false;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}
