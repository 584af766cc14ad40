//! Shared helpers of the integration tests: paths, the reference library, compiling and
//! running the C programs, report files.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};

pub const REF_INCLUDE: &str = "/usr/include/mujoco/mujoco.h";
pub const REF_LIB: &str = "/usr/lib/x86_64-linux-gnu/libmujoco.so.2.2.2";
pub const EIGEN: &str = "/usr/include/eigen3/Eigen/Dense";

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root().join("target"))
}

/// Directory of our built library (target/release); fails the test when the x86-64-v3 copy
/// beside it (`cargo xtask hwcaps`), which the loader takes on a CPU with AVX2, is older.
pub fn lib_dir() -> PathBuf {
    let dir = target_dir().join("release");
    let age = |p: PathBuf| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    if let (Some(base), Some(v3)) = (
        age(dir.join("libmujoco.so")),
        age(dir.join(HWCAPS_V3).join("libmujoco.so.2.2.2")),
    ) {
        assert!(
            v3 >= base,
            "{} is older than target/release/libmujoco.so: run `cargo xtask hwcaps`",
            dir.join(HWCAPS_V3).display()
        );
    }
    dir
}

/// Where the loader finds the x86-64-v3 build beside the baseline one.
pub const HWCAPS_V3: &str = "glibc-hwcaps/x86-64-v3";

/// Our x86-64-v3 build (`cargo xtask hwcaps`), when there is one.
pub fn our_v3_lib() -> Option<PathBuf> {
    Some(lib_dir().join(HWCAPS_V3).join("libmujoco.so.2.2.2")).filter(|p| p.exists())
}

/// The file of ours a program linked against target/release loads on this CPU: the x86-64-v3
/// build where the loader supports that level (as `ld.so --help` lists it), else the baseline.
/// For programs that dlopen a path.
pub fn loaded_lib() -> PathBuf {
    let help = Command::new(LD_SO).arg("--help").output();
    let v3 = help.is_ok_and(|o| text(&o.stdout).contains("x86-64-v3 (supported"));
    match our_v3_lib() {
        Some(p) if v3 => p,
        _ => our_lib(),
    }
}

/// The dynamic loader, to run a program with `--glibc-hwcaps-mask` (the baseline library
/// on any CPU).
pub const LD_SO: &str = "/lib64/ld-linux-x86-64.so.2";

/// Our shared library; fails the test when it has not been built.
pub fn our_lib() -> PathBuf {
    let lib = lib_dir().join("libmujoco.so");
    assert!(
        lib.exists(),
        "{} is missing: run `cargo build --release` first",
        lib.display()
    );
    lib
}

/// Fails the test with a clear message when Debian's MuJoCo 2.2.2 is not installed.
pub fn require_reference() {
    for (path, what) in [(REF_INCLUDE, "headers"), (REF_LIB, "library")] {
        assert!(
            Path::new(path).exists(),
            "reference MuJoCo 2.2.2 {what} missing ({path}): install Debian's libmujoco-dev \
             (capi-tests/run-all does it)"
        );
    }
}

pub fn require_eigen() {
    assert!(
        Path::new(EIGEN).exists(),
        "Eigen missing ({EIGEN}): install libeigen3-dev"
    );
}

/// The harness binaries (capi-tests/build: harness-ref and harness-ours); returns their directory.
pub fn harness_bin() -> PathBuf {
    require_reference();
    require_eigen();
    our_lib();
    let o = Command::new(root().join("capi-tests/build"))
        .output()
        .expect("bash missing");
    assert!(
        o.status.success(),
        "building the harness failed:\n{}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    PathBuf::from(text(&o.stdout).trim())
}

/// A scratch directory under target/capi-tests.
pub fn work_dir(name: &str) -> PathBuf {
    let d = target_dir().join("capi-tests").join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Lib {
    Ref,
    Ours,
}

impl Lib {
    pub fn name(self) -> &'static str {
        match self {
            Lib::Ref => "ref",
            Lib::Ours => "ours",
        }
    }
}

/// Compiles C sources against one library's headers and links it; returns the executable.
/// DT_RPATH (not RUNPATH) pins the library: cargo's LD_LIBRARY_PATH cannot swap it.
pub fn compile_c(srcs: &[PathBuf], name: &str, lib: Lib) -> PathBuf {
    let out = work_dir("bin").join(format!("{name}-{}", lib.name()));
    let opts = [
        "-std=c11",
        "-O2",
        "-Wall",
        "-Werror=implicit-function-declaration",
    ];
    gcc(&out, &opts, srcs, lib, &[]);
    out
}

/// Runs gcc: `opts`, the sources, then the library (headers, -lmujoco, rpath), `after_lib`
/// (libraries that must follow it) and libm, into `out`; fails the test with gcc's errors.
fn gcc(out: &Path, opts: &[&str], srcs: &[PathBuf], lib: Lib, after_lib: &[&str]) {
    let tmp = partial(out);
    let mut cmd = Command::new("gcc");
    cmd.args(opts).arg("-o").arg(&tmp).args(srcs);
    match lib {
        Lib::Ref => {
            require_reference();
            cmd.arg(REF_LIB)
                .arg("-Wl,--disable-new-dtags,-rpath,/usr/lib/x86_64-linux-gnu");
        }
        Lib::Ours => {
            our_lib();
            let dir = lib_dir();
            cmd.arg("-I").arg(root().join("include"));
            cmd.arg(format!("-L{}", dir.display())).arg("-lmujoco");
            cmd.arg(format!("-Wl,--disable-new-dtags,-rpath,{}", dir.display()));
        }
    }
    cmd.args(after_lib).arg("-lm");
    let o = cmd
        .output()
        .expect("gcc not found: install build-essential");
    assert!(
        o.status.success(),
        "compiling {} against {} failed:\n{}",
        out.display(),
        lib.name(),
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::rename(&tmp, out).unwrap();
}

/// Where a compiler writes `out` before it is renamed into place: test executables run side by
/// side may build the same program, and none may run a half-written one.
fn partial(out: &Path) -> PathBuf {
    let mut p = out.as_os_str().to_owned();
    p.push(format!(".{}.tmp", std::process::id()));
    PathBuf::from(p)
}

/// MuJoCo 4.0.0 from its PyPI wheel (mujoco-core), unpacked by capi-tests/run-all into
/// target/third-party: (include dir, library file). For speed comparisons only.
pub fn v4_lib() -> Option<(PathBuf, PathBuf)> {
    let dir = target_dir().join("third-party/mujoco-core-4.0.0/mujoco");
    let (inc, lib) = (dir.join("include"), dir.join("libmujoco.so.4.0.0"));
    (inc.join("mujoco/mujoco.h").is_file() && lib.is_file()).then_some((inc, lib))
}

/// Compiles C sources against MuJoCo 4.0.0's headers and library; None when it is not there.
pub fn compile_c_v4(srcs: &[PathBuf], name: &str) -> Option<PathBuf> {
    let (inc, lib) = v4_lib()?;
    let out = work_dir("bin").join(format!("{name}-v4"));
    let tmp = partial(&out);
    let o = Command::new("gcc")
        .args(["-std=c11", "-O2", "-o"])
        .arg(&tmp)
        .args(srcs)
        .arg("-I")
        .arg(&inc)
        .arg(&lib)
        .arg(format!(
            "-Wl,--disable-new-dtags,-rpath,{}",
            lib.parent().unwrap().display()
        ))
        .arg("-lm")
        .output()
        .expect("gcc not found: install build-essential");
    assert!(
        o.status.success(),
        "compiling {name} against MuJoCo 4.0.0 failed:\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::rename(&tmp, &out).unwrap();
    Some(out)
}

/// Deterministic pseudo-random numbers (splitmix64), for mutants and fuzz inputs.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Runs a command with stdin closed and a time limit (coreutils `timeout`), without the
/// LD_LIBRARY_PATH cargo sets for tests (it would point libmujoco.so.2.2.2 at ours).
pub fn run(prog: &Path, args: &[&str], envs: &[(&str, &str)], seconds: u32) -> Output {
    let mut cmd = Command::new("timeout");
    // a scratch working directory: mju_error writes MUJOCO_LOG.TXT there
    cmd.arg(seconds.to_string())
        .arg(prog)
        .args(args)
        .current_dir(work_dir("run"));
    cmd.stdin(Stdio::null()).env_remove("LD_LIBRARY_PATH");
    for (k, v) in envs {
        cmd.env(k, v);
    }
    cmd.output()
        .unwrap_or_else(|e| panic!("cannot run {}: {e}", prog.display()))
}

/// Output of capi-tests/NAME.c run with `args`, built against the reference and against ours
/// (each run must succeed within two minutes).
pub fn both_outputs(name: &str, args: &[&str]) -> (String, String) {
    let src = [root().join(format!("capi-tests/{name}.c"))];
    let out = |lib| {
        let prog = compile_c(&src, name, lib);
        let o = run(&prog, args, &[], 120);
        assert!(o.status.success(), "{}{}", text(&o.stdout), text(&o.stderr));
        text(&o.stdout)
    };
    (out(Lib::Ref), out(Lib::Ours))
}

pub fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Writes a report that capi-tests/run-all prints after the tests (target/capi-tests/reports).
pub fn report(name: &str, body: &str) {
    let dir = work_dir("reports");
    std::fs::write(dir.join(format!("{name}.txt")), body).unwrap();
}

/// The models of the differential checks (capi-tests/models.list), as absolute paths.
pub fn models() -> Vec<String> {
    model_list("models.list")
}

/// The models of a list file of capi-tests/, as absolute paths.
pub fn model_list(file: &str) -> Vec<String> {
    let list = std::fs::read_to_string(root().join("capi-tests").join(file)).unwrap();
    list.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| root().join(l).to_string_lossy().into_owned())
        .collect()
}

/// A model of models/ as an absolute path.
pub fn model(name: &str) -> String {
    root()
        .join("models")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

/// The corpus directories of real models: `$RUJOCO_CORPUS` (colon-separated; capi-tests/run-all
/// sets it to ../shared/corpus or the dm_control suite, plus dm_control's and Gymnasium's other
/// models fetched from PyPI), else ../shared/corpus when present. Canonical paths.
pub fn corpus_dirs() -> Vec<PathBuf> {
    let dirs: Vec<PathBuf> = match std::env::var_os("RUJOCO_CORPUS") {
        Some(v) => std::env::split_paths(&v).collect(),
        None => vec![root().join("../shared/corpus")],
    };
    dirs.into_iter()
        .filter(|p| p.is_dir())
        .filter_map(|p| p.canonicalize().ok())
        .collect()
}

/// The .xml files under a directory, sorted, recursively.
pub fn xml_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            xml_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "xml") {
            out.push(p);
        }
    }
}

/// The .xml files of the first corpus directory: the corpus the issues name (../shared/corpus,
/// or the dm_control suite where it is absent), without the other packages run-all fetches.
pub fn main_corpus_files() -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Some(d) = corpus_dirs().first() {
        xml_files(d, &mut out);
    }
    out
}

/// Every .xml file of the corpus directories.
pub fn corpus_files() -> Vec<PathBuf> {
    let mut out = Vec::new();
    for d in corpus_dirs() {
        xml_files(&d, &mut out);
    }
    out
}

/// Workers for per-model loops: $RUJOCO_TEST_JOBS, else the machine's cores.
pub fn jobs() -> usize {
    std::env::var("RUJOCO_TEST_JOBS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1)
}

/// `f` over `items` on `jobs()` threads; results in the items' order.
pub fn par_map<T: Sync, R: Send>(items: &[T], f: impl Fn(usize, &T) -> R + Sync) -> Vec<R> {
    par_map_on(jobs(), items, f)
}

/// par_map on one worker more than `jobs()`, for the harness's runs: they wait on their child
/// processes and files often enough to leave a core idle otherwise.
pub fn par_map_harness<T: Sync, R: Send>(items: &[T], f: impl Fn(usize, &T) -> R + Sync) -> Vec<R> {
    par_map_on(jobs() + 1, items, f)
}

/// `f` over `items` on `workers` threads; results in the items' order.
pub fn par_map_on<T: Sync, R: Send>(
    workers: usize,
    items: &[T],
    f: impl Fn(usize, &T) -> R + Sync,
) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;
    let next = AtomicUsize::new(0);
    let out: Mutex<Vec<Option<R>>> = Mutex::new((0..items.len()).map(|_| None).collect());
    std::thread::scope(|s| {
        for _ in 0..workers.min(items.len()) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(item) = items.get(i) else { break };
                let r = f(i, item);
                out.lock().unwrap()[i] = Some(r);
            });
        }
    });
    out.into_inner()
        .unwrap()
        .into_iter()
        .map(|r| r.expect("every item mapped"))
        .collect()
}

/// `capi-tests/loader.c` built on each library: `verdict FILE...` prints one line a file.
pub fn verdicts(prog: &Path, files: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for chunk in files.chunks(200) {
        let args: Vec<&str> = std::iter::once("verdict")
            .chain(chunk.iter().map(String::as_str))
            .collect();
        let o = run(prog, &args, &[], 3600);
        let t = text(&o.stdout);
        let lines: Vec<String> = t.lines().map(str::to_string).collect();
        assert_eq!(
            lines.len(),
            chunk.len(),
            "loader verdict output incomplete:\n{t}{}",
            text(&o.stderr)
        );
        out.extend(lines);
    }
    out
}

/// Verdicts of both libraries: chunks of files of either library on `jobs()` workers, so that
/// the faster library's runs do not leave a core idle.
pub fn both_verdicts(
    reference: &Path,
    ours: &Path,
    files: &[String],
) -> (Vec<String>, Vec<String>) {
    let chunks: Vec<&[String]> = files.chunks(50).collect();
    let runs: Vec<(&Path, &[String])> = chunks
        .iter()
        .map(|&c| (reference, c))
        .chain(chunks.iter().map(|&c| (ours, c)))
        .collect();
    let mut out = par_map(&runs, |_, &(prog, chunk)| verdicts(prog, chunk)).into_iter();
    let r = out.by_ref().take(chunks.len()).flatten().collect();
    (r, out.flatten().collect())
}

/// The loader programs, the corpus and project files, and both libraries' verdicts on them.
pub struct Loaders {
    pub reference: PathBuf,
    pub ours: PathBuf,
    pub files: Vec<String>,
    pub reference_verdicts: Vec<String>,
    pub our_verdicts: Vec<String>,
    /// The files both libraries load with the same sizes (the mutation seeds).
    pub seeds: Vec<String>,
}

/// `loaders` computed once per test binary.
pub fn loaders() -> &'static Loaders {
    static LOADERS: std::sync::OnceLock<Loaders> = std::sync::OnceLock::new();
    LOADERS.get_or_init(|| {
        let src = [root().join("capi-tests/loader.c")];
        let reference = compile_c(&src, "loader", Lib::Ref);
        let ours = compile_c(&src, "loader", Lib::Ours);
        let mut files = corpus_files();
        xml_files(&root().join("models"), &mut files);
        let files: Vec<String> = files
            .iter()
            .map(|p| p.to_string_lossy().into_owned())
            .collect();
        let (r, o) = both_verdicts(&reference, &ours, &files);
        let seeds = files
            .iter()
            .zip(r.iter().zip(&o))
            .filter(|(_, (r, o))| r.starts_with("load") && r == o)
            .map(|(f, _)| f.clone())
            .collect();
        Loaders {
            reference,
            ours,
            files,
            reference_verdicts: r,
            our_verdicts: o,
            seeds,
        }
    })
}

/// An X server on a free display, stopped when dropped.
pub struct Xvfb {
    child: Child,
    pub display: String,
}

impl Xvfb {
    /// Starts Xvfb (1280x1024, 24 bits) on a display it picks itself (-displayfd: the first
    /// display no running server holds, atomically, so test executables running side by side
    /// never share one).
    pub fn start() -> Xvfb {
        static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        assert!(
            Command::new("sh")
                .args(["-c", "command -v Xvfb"])
                .stdout(Stdio::null())
                .status()
                .unwrap()
                .success(),
            "Xvfb missing: install xvfb (capi-tests/run-all does it)"
        );
        let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let file = work_dir("xvfb").join(format!("{}-{n}", std::process::id()));
        let _ = std::fs::remove_file(&file);
        let mut child = Command::new("sh")
            .args([
                "-c",
                "exec Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>\"$1\"",
                "sh",
            ])
            .arg(&file)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("cannot start Xvfb");
        // the number arrives, newline-terminated, once the server accepts connections
        for _ in 0..400 {
            let written = std::fs::read_to_string(&file).unwrap_or_default();
            if let Some(num) = written.strip_suffix('\n') {
                let _ = std::fs::remove_file(&file);
                return Xvfb {
                    child,
                    display: format!(":{}", num.trim()),
                };
            }
            if let Ok(Some(status)) = child.try_wait() {
                panic!("Xvfb stopped before it took a display: {status}");
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        let _ = child.kill();
        let _ = child.wait();
        panic!("Xvfb took no display in 20 s");
    }
}

impl Drop for Xvfb {
    /// SIGTERM first: the server then removes its lock file and socket.
    fn drop(&mut self) {
        let _ = Command::new("kill")
            .args(["-TERM", &self.child.id().to_string()])
            .status();
        for _ in 0..100 {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Mesa's OSMesa header, present when the GL tests can build.
pub const OSMESA_H: &str = "/usr/include/GL/osmesa.h";

/// Requires the reference, our library and OSMesa's headers for a rendering test.
pub fn require_osmesa() {
    require_reference();
    our_lib();
    assert!(
        Path::new(OSMESA_H).exists(),
        "{OSMESA_H} missing: install libosmesa6-dev (capi-tests/run-all does it)"
    );
}

/// A C file (a path below the repository root) built against one library with extra flags
/// after the library (GL platform libraries, defines); the binary is `name-<lib>` in
/// target/capi-tests/render.
pub fn compile_gl(src: &str, name: &str, lib: Lib, flags: &[&str]) -> PathBuf {
    let out = work_dir("render").join(format!("{name}-{}", lib.name()));
    gcc(
        &out,
        &["-std=gnu11", "-O1", "-Wall"],
        &[root().join(src)],
        lib,
        flags,
    );
    out
}
