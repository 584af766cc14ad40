//! `cargo xtask order`: records the order the shared library's functions are laid out in
//! (`pgo/symbol-order.txt`, passed to the linker by build.rs).
//!
//! A program's first call into a fresh process runs code spread over the whole library, and
//! each 64 KB of it touched costs a page fault: loading a small MJB file took a third longer
//! than 2.2.2's. Builds the release library in the linker's own layout (its call-graph order
//! from the build profile), runs `capi-tests/order_train.c` on it under callgrind over every
//! model under models/, split at the calls of a program's first phases, and lists every
//! function in the linker's layout, which the engine's speed depends on, but for those of MJB
//! loading and then of mj_makeData (each phase's by instructions, most first; none the steps
//! run), which it lists last, together. The engine laid out by instructions instead stepped
//! arm3 4% slower; the block at the front of the code, 2-5%; at the end, the speed test's
//! models step within 3% either way. Needs valgrind. Only rujoco runs.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::symbols::text_symbols;
use crate::{cargo, fail, must, root, target_dir};

/// Driven steps of full physics per model (and half as many smooth).
const STEPS: &str = "50";

/// The phases, by the callgrind trigger that ends each (a function takes one trigger: the MJB
/// phase ends where mj_loadXML starts, after mj_deleteModel; the steps where the next model's
/// mj_loadModel starts).
const PHASES: [(&str, &str); 4] = [
    ("--dump-before=mj_loadXML", "mj_loadModel"),
    ("--dump-after=mj_loadXML", "mj_loadXML"),
    ("--dump-after=mj_makeData", "mj_makeData"),
    ("--dump-before=mj_loadModel", "steps"),
];

/// The phases laid out together at the end, in this order.
const BLOCK: [usize; 2] = [0, 2];

pub fn order() {
    let root = root();
    // the linker's own layout
    must(
        cargo()
            .args(["build", "--release", "--package", "rujoco", "--lib"])
            .env("RUJOCO_SYMBOL_ORDER", "0")
            .current_dir(&root),
        "the release build",
    );
    let work = target_dir().join("order");
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap_or_else(|e| fail(&work.display().to_string(), e));
    // a copy of the library, alone in its directory: glibc's loader would take the x86-64-v3
    // build beside target/release's (glibc-hwcaps/), which callgrind may not run
    let lib = work.join("libmujoco.so.2.2.2");
    std::fs::copy(target_dir().join("release/libmujoco.so"), &lib)
        .unwrap_or_else(|e| fail("copying the library", e));
    let layout = text_symbols(&output(
        Command::new("nm").args(["-n", "--defined-only"]).arg(&lib),
    ));
    // the programs, against that copy: the MJB files come from capi-tests/loader.c
    let program = |name: &str| {
        let exe = work.join(name);
        must(
            Command::new("cc")
                .args(["-std=c11", "-O2", "-I"])
                .arg(root.join("include"))
                .arg(root.join(format!("capi-tests/{name}.c")))
                .arg("-o")
                .arg(&exe)
                .arg(&lib)
                .arg(format!("-Wl,-rpath,{}", work.display()))
                .arg("-lm"),
            &format!("compiling capi-tests/{name}.c"),
        );
        exe
    };
    let (loader, train) = (program("loader"), program("order_train"));
    let xmls = models(&root);
    let saved = output(Command::new(&loader).arg("mjbsave").arg(&work).args(&xmls));
    let mut args = vec![STEPS.to_string()];
    for (xml, mjb) in xmls.iter().zip(saved.lines()) {
        if mjb != "-" {
            args.push(mjb.to_string());
            args.push(xml.display().to_string());
        }
    }
    let out = work.join("callgrind.out");
    let mut grind = Command::new("valgrind");
    grind
        .args(["--tool=callgrind", "--demangle=no"])
        .arg(format!("--callgrind-out-file={}", out.display()));
    for (trigger, _) in PHASES {
        grind.arg(trigger);
    }
    must(
        grind.arg(&train).args(&args),
        "callgrind (is valgrind installed?)",
    );

    // instructions of each library function, by phase
    let mut cost: Vec<HashMap<String, u64>> = vec![HashMap::new(); PHASES.len()];
    for dump in dumps(&work) {
        let text = std::fs::read_to_string(&dump).unwrap_or_else(|e| fail("callgrind dump", e));
        // the program's end closes the last steps
        let phase = PHASES
            .iter()
            .position(|(t, _)| text.contains(&format!("desc: Trigger: {t}\n")))
            .unwrap_or(PHASES.len() - 1);
        for (f, n) in functions(&dump) {
            *cost[phase].entry(f).or_default() += n;
        }
    }
    // what the steps run too stays where the linker put it, beside the engine (the data's
    // views, built on every call, moved away: arm3 stepped 4% slower)
    let steps = PHASES.len() - 1;
    let mut seen: HashSet<String> = cost[steps].keys().cloned().collect();
    let mut block = Vec::new();
    for p in BLOCK {
        let mut fs: Vec<(String, u64)> = std::mem::take(&mut cost[p]).into_iter().collect();
        fs.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        let before = block.len();
        block.extend(
            fs.into_iter()
                .map(|f| f.0)
                .filter(|f| seen.insert(f.clone())),
        );
        println!("xtask: {}: {} functions", PHASES[p].1, block.len() - before);
    }
    let moved: HashSet<&String> = block.iter().collect();
    let mut lines = vec![
        "# rujoco's function order (cargo xtask order), which the linker lays out first to last:"
            .to_string(),
        "# the linker's own layout, but for MJB loading's and mj_makeData's functions, last"
            .to_string(),
    ];
    lines.extend(layout.iter().filter(|f| !moved.contains(f)).cloned());
    println!("xtask: the rest: {} functions", lines.len() - 2);
    lines.extend(block.iter().cloned());
    let file = root.join("pgo/symbol-order.txt");
    std::fs::write(&file, lines.join("\n") + "\n")
        .unwrap_or_else(|e| fail("pgo/symbol-order.txt", e));
    println!("{}", file.display());
}

/// Standard output of `cmd`, which must succeed.
fn output(cmd: &mut Command) -> String {
    let o = cmd.output().unwrap_or_else(|e| fail("order", e));
    if !o.status.success() {
        eprintln!(
            "xtask: {cmd:?} failed:\n{}",
            String::from_utf8_lossy(&o.stderr)
        );
        std::process::exit(1);
    }
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The callgrind dump files in `dir`.
fn dumps(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| d.flatten().map(|e| e.path()).collect())
        .unwrap_or_default();
    v.retain(|p| {
        p.file_name()
            .is_some_and(|n| n.to_string_lossy().starts_with("callgrind.out"))
    });
    v.sort();
    v
}

/// (symbol, instructions) of each function of libmujoco.so in a callgrind dump, from
/// callgrind_annotate's table ("COUNT (PERCENT)  FILE:SYMBOL [OBJECT]").
fn functions(dump: &Path) -> Vec<(String, u64)> {
    let text = output(
        Command::new("callgrind_annotate")
            .arg("--threshold=100")
            .arg(dump),
    );
    text.lines()
        .filter_map(|l| {
            let (head, object) = l.trim_end().strip_suffix(']')?.rsplit_once(" [")?;
            if !object.ends_with("/libmujoco.so") && !object.ends_with("/libmujoco.so.2.2.2") {
                return None;
            }
            let mut words = head.split_whitespace();
            let count: u64 = words.next()?.replace(',', "").parse().ok()?;
            // a recursion level's suffix ('2) is callgrind's, not the symbol's
            let symbol = words.last()?.rsplit_once(':')?.1;
            let symbol = symbol.split_once('\'').map_or(symbol, |s| s.0);
            (!symbol.starts_with("0x")).then(|| (symbol.to_string(), count))
        })
        .collect()
}

/// The MJCF files under models/, sorted.
fn models(root: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in [root.join("models"), root.join("models/extra")] {
        if let Ok(entries) = std::fs::read_dir(&dir) {
            files.extend(
                entries
                    .flatten()
                    .map(|e| e.path())
                    .filter(|p| p.extension().is_some_and(|x| x == "xml")),
            );
        }
    }
    files.sort();
    files
}
