//! Project tasks, run as `cargo xtask TASK`:
//!
//! - `install --prefix DIR [--libdir lib]`: builds rujoco (release) and installs the headers,
//!   `libmujoco.so.2.2.2` (with the `libmujoco.so` link), `libmujoco.a`, a pkg-config file and a
//!   CMake package (`find_package(mujoco)`, target `mujoco::mujoco`), all relocatable; honors
//!   `DESTDIR`; records what it wrote for `uninstall`.
//! - `uninstall --prefix DIR [--libdir lib]`: removes exactly what `install` wrote.
//! - `deb`: a Debian package in target/debian/ that stands in for libmujoco2.2.2 and
//!   libmujoco-dev.
//! - `pgo`: records the profile the release build is optimized with (`pgo/rujoco.profdata`),
//!   then the function order (`order`).
//! - `order`: records the order the shared library's functions are laid out in
//!   (`pgo/symbol-order.txt`; needs valgrind).
//! - `hwcaps`: builds the library again for x86-64-v3 (AVX2) beside target/release's, in
//!   `glibc-hwcaps/x86-64-v3/`, where glibc's loader takes it on a CPU that has AVX2 (install
//!   and deb build it and install it there too).
//!
//! `--no-build` takes target/release as it is (the tests use it).

mod files;
mod order;
mod pgo;
mod sources;
mod symbols;

use std::path::{Path, PathBuf};
use std::process::{exit, Command};

const VERSION: &str = "2.2.2";
const MANIFEST: &str = "share/rujoco/install_manifest.txt";

fn usage() -> ! {
    eprintln!(
        "usage: cargo xtask install --prefix DIR [--libdir DIR] [--no-build]\n       \
         cargo xtask uninstall --prefix DIR [--libdir DIR]\n       \
         cargo xtask deb [--no-build]\n       \
         cargo xtask pgo\n       \
         cargo xtask order\n       \
         cargo xtask hwcaps"
    );
    exit(2)
}

/// Options of install and uninstall.
struct Layout {
    prefix: PathBuf,
    libdir: String,
    /// `DESTDIR`: a staging root the files go under (the paths inside stay those of `prefix`)
    destdir: Option<PathBuf>,
    /// take target/release as it is (`--no-build`)
    no_build: bool,
}

impl Layout {
    fn parse(args: &[String]) -> Layout {
        let mut prefix = None;
        let mut libdir = "lib".to_string();
        let mut no_build = false;
        let mut it = args.iter();
        while let Some(a) = it.next() {
            match a.as_str() {
                "--no-build" => no_build = true,
                "--prefix" => prefix = it.next().map(PathBuf::from),
                "--libdir" => libdir = it.next().cloned().unwrap_or_else(|| usage()),
                _ => usage(),
            }
        }
        let Some(prefix) = prefix else { usage() };
        if Path::new(&libdir).is_absolute() || libdir.contains("..") {
            eprintln!("xtask: --libdir is relative to the prefix");
            exit(2);
        }
        let destdir = std::env::var_os("DESTDIR")
            .filter(|d| !d.is_empty())
            .map(PathBuf::from);
        Layout {
            prefix,
            libdir,
            destdir,
            no_build,
        }
    }

    /// Where a path under the prefix is written.
    fn staged(&self, rel: &str) -> PathBuf {
        let full = self.prefix.join(rel);
        match &self.destdir {
            Some(d) => d.join(full.strip_prefix("/").unwrap_or(&full)),
            None => full,
        }
    }
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root().join("target"))
}

/// The cargo that runs this task.
fn cargo() -> Command {
    Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
}

/// Runs `cmd`; exits with "xtask: `what` failed" unless it succeeds.
fn must(cmd: &mut Command, what: &str) {
    if !cmd.status().is_ok_and(|s| s.success()) {
        eprintln!("xtask: {what} failed");
        exit(1);
    }
}

fn build() {
    must(
        cargo()
            .args(["build", "--release", "--package", "rujoco", "--lib"])
            .current_dir(root()),
        "cargo build --release",
    );
    hwcaps();
}

/// Where glibc's loader looks, beside a library's directory, for the copy built for x86-64-v3
/// (AVX2), and takes it on a CPU that has the level.
const HWCAPS_V3: &str = "glibc-hwcaps/x86-64-v3";

/// Where cargo builds the x86-64-v3 library (its own target directory: other flags).
fn hwcaps_build_dir() -> PathBuf {
    target_dir().join("x86-64-v3")
}

/// The library built again for x86-64-v3, into target/release/glibc-hwcaps/x86-64-v3/. The
/// same arithmetic (Rust never fuses a product and a sum), in wider registers. The flag goes to
/// rujoco's own compilation only (`cargo rustc`): build scripts and dependencies stay baseline,
/// so the build runs on any x86-64, and rujoco's symbols keep the names the recorded profile
/// (pgo/) knows them by.
fn hwcaps() {
    if !cfg!(all(target_arch = "x86_64", target_os = "linux")) {
        return;
    }
    let work = hwcaps_build_dir();
    must(
        cargo()
            .args(["rustc", "--release", "--package", "rujoco", "--lib"])
            .args(["--", "-Ctarget-cpu=x86-64-v3"])
            .env("CARGO_TARGET_DIR", &work)
            .current_dir(root()),
        "the x86-64-v3 build",
    );
    let built = work.join("release/libmujoco.so");
    let dir = target_dir().join("release").join(HWCAPS_V3);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| fail(&dir.display().to_string(), e));
    let dst = dir.join(format!("libmujoco.so.{VERSION}"));
    // a new file (not copied over the old one, which a running program may have mapped)
    let tmp = dir.join(".libmujoco.so.tmp");
    std::fs::copy(&built, &tmp).unwrap_or_else(|e| fail(&built.display().to_string(), e));
    std::fs::rename(&tmp, &dst).unwrap_or_else(|e| fail(&dst.display().to_string(), e));
}

fn fail(what: &str, e: std::io::Error) -> ! {
    eprintln!("xtask: {what}: {e}");
    exit(1)
}

/// Writes the files of an installation under `layout`, returning their paths under the prefix.
fn install(layout: &Layout) -> Vec<String> {
    if !layout.no_build {
        build();
    }
    let release = target_dir().join("release");
    let mut written = Vec::new();
    for f in files::install_set(&root(), &release, &layout.libdir) {
        let dst = layout.staged(&f.rel);
        if let Some(dir) = dst.parent() {
            std::fs::create_dir_all(dir).unwrap_or_else(|e| fail(&dir.display().to_string(), e));
        }
        let _ = std::fs::remove_file(&dst);
        let result = match &f.content {
            files::Content::Copy(src) => std::fs::copy(src, &dst).map(|_| ()),
            files::Content::Text(t) => std::fs::write(&dst, t),
            files::Content::Link(to) => std::os::unix::fs::symlink(to, &dst),
        };
        result.unwrap_or_else(|e| fail(&dst.display().to_string(), e));
        written.push(f.rel);
    }
    let manifest = layout.staged(MANIFEST);
    std::fs::create_dir_all(manifest.parent().unwrap()).unwrap_or_else(|e| fail(MANIFEST, e));
    written.push(MANIFEST.to_string());
    std::fs::write(&manifest, written.join("\n") + "\n").unwrap_or_else(|e| fail(MANIFEST, e));
    written
}

fn uninstall(layout: &Layout) {
    let manifest = layout.staged(MANIFEST);
    let list = std::fs::read_to_string(&manifest).unwrap_or_else(|e| {
        fail(
            &format!(
                "no installation at {} ({})",
                layout.prefix.display(),
                MANIFEST
            ),
            e,
        )
    });
    let mut dirs = std::collections::BTreeSet::new();
    for rel in list.lines().filter(|l| !l.is_empty()) {
        let p = layout.staged(rel);
        if std::fs::symlink_metadata(&p).is_ok() {
            std::fs::remove_file(&p).unwrap_or_else(|e| fail(&p.display().to_string(), e));
        }
        let mut d = Path::new(rel).parent();
        while let Some(dir) = d.filter(|d| !d.as_os_str().is_empty()) {
            dirs.insert(dir.to_path_buf());
            d = dir.parent();
        }
    }
    // directories the installation made and left empty, deepest first
    let mut dirs: Vec<PathBuf> = dirs.into_iter().collect();
    dirs.sort_by_key(|d| std::cmp::Reverse(d.components().count()));
    for d in dirs {
        let _ = std::fs::remove_dir(layout.staged(&d.to_string_lossy()));
    }
}

fn deb(no_build: bool) {
    let stage = target_dir().join("debian/stage");
    let _ = std::fs::remove_dir_all(&stage);
    let layout = Layout {
        prefix: PathBuf::from("/usr"),
        libdir: "lib/x86_64-linux-gnu".into(),
        destdir: Some(stage.clone()),
        no_build,
    };
    install(&layout);
    // the manifest is for `uninstall`; dpkg keeps its own list
    let _ = std::fs::remove_dir_all(stage.join("usr/share/rujoco"));
    let doc = stage.join("usr/share/doc/rujoco");
    std::fs::create_dir_all(&doc).unwrap_or_else(|e| fail("doc", e));
    std::fs::write(doc.join("copyright"), files::copyright())
        .unwrap_or_else(|e| fail("copyright", e));
    let control = stage.join("DEBIAN");
    std::fs::create_dir_all(&control).unwrap_or_else(|e| fail("DEBIAN", e));
    let size_kb = dir_size(&stage.join("usr")) / 1024;
    std::fs::write(control.join("control"), files::control(size_kb))
        .unwrap_or_else(|e| fail("control", e));
    std::fs::write(control.join("triggers"), "activate-noawait ldconfig\n")
        .unwrap_or_else(|e| fail("triggers", e));
    let out = target_dir().join(format!("debian/{}", files::deb_name()));
    let ok = Command::new("dpkg-deb")
        .args(["--build", "--root-owner-group", "-Zxz"])
        .arg(&stage)
        .arg(&out)
        .status()
        .map(|s| s.success())
        .unwrap_or(false);
    if !ok {
        eprintln!("xtask: dpkg-deb failed (Debian's dpkg-deb is needed)");
        exit(1);
    }
    println!("{}", out.display());
}

fn dir_size(p: &Path) -> u64 {
    let Ok(meta) = std::fs::symlink_metadata(p) else {
        return 0;
    };
    if !meta.is_dir() {
        return meta.len();
    }
    std::fs::read_dir(p)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| dir_size(&e.path()))
        .sum()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("install") => {
            let layout = Layout::parse(&args[1..]);
            for f in install(&layout) {
                println!("installed {}", layout.prefix.join(f).display());
            }
        }
        Some("uninstall") => uninstall(&Layout::parse(&args[1..])),
        Some("deb") if args.len() == 1 => deb(false),
        Some("deb") if args.len() == 2 && args[1] == "--no-build" => deb(true),
        Some("pgo") if args.len() == 1 => {
            pgo::pgo();
            order::order();
        }
        Some("order") if args.len() == 1 => order::order(),
        Some("hwcaps") if args.len() == 1 => hwcaps(),
        _ => usage(),
    }
}
