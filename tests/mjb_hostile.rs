//! The MJB loader under hostile input (`capi-tests/mjb_hostile.c`):
//! - every model of the lists and corpora saved and loaded back from memory is the same model
//!   (the loader's cross-checks refuse nothing real);
//! - truncated files, trailing bytes and bad headers, from a file and from a VFS buffer, get the
//!   reference's verdict and message;
//! - mutants of saved models (byte flips, truncation, size fields set to extremes, zeroed
//!   regions, header changes, entries of int arrays set to extremes) loaded and, when they load,
//!   stepped 100 times with controls: never a crash, a hang or an "internal error".

mod common;
use common::*;
use std::path::PathBuf;

/// Corpus models used as mutation seeds besides models/: small, with tendons, meshes, skins,
/// sites, equalities and actuators of every kind between them.
const SEEDS: [&str; 8] = [
    "arm26.xml",
    "slider_crank.xml",
    "car.xml",
    "loop.xml",
    "humanoid_body.xml",
    "rope.xml",
    "softbox.xml",
    "grid2pin.xml",
];

/// The program built against one library, once for all tests of this file (they run in
/// parallel: building it per test would rewrite the file while another test runs it).
fn program(lib: Lib) -> PathBuf {
    static OURS: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    static REF: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    let cell = if lib == Lib::Ours { &OURS } else { &REF };
    cell.get_or_init(|| {
        compile_c(
            &[root().join("capi-tests/mjb_hostile.c")],
            "mjb_hostile",
            lib,
        )
    })
    .clone()
}

fn seeds(prog: &std::path::Path) -> Vec<String> {
    let dir = work_dir("mjb_hostile");
    let mut xmls: Vec<PathBuf> = std::fs::read_dir(root().join("models"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "xml"))
        .collect();
    for f in corpus_files() {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        if SEEDS.contains(&name.as_str()) && !xmls.iter().any(|x| x.ends_with(&name)) {
            xmls.push(f);
        }
    }
    xmls.sort();
    let mut out = Vec::new();
    for x in xmls {
        let mjb = dir.join(x.file_stem().unwrap()).with_extension("mjb");
        let (xs, ms) = (x.to_string_lossy(), mjb.to_string_lossy());
        let o = run(prog, &["save", &xs, &ms], &[], 120);
        assert!(
            o.status.success(),
            "saving {xs} failed: {}",
            text(&o.stdout)
        );
        // a few MB at most: each mutant is a copy in a forked child
        if std::fs::metadata(&mjb).map(|m| m.len()).unwrap_or(0) < 9_000_000 {
            out.push(ms.into_owned());
        }
    }
    out
}

#[test]
fn saved_models_load_back_unchanged() {
    let prog = program(Lib::Ours);
    let mut files = models();
    files.extend(model_list("models-extra.list"));
    files.extend(
        corpus_files()
            .iter()
            .map(|p| p.to_string_lossy().into_owned()),
    );
    let chunks: Vec<&[String]> = files.chunks(40).collect();
    let outs = par_map(&chunks, |_, chunk| {
        let mut args = vec!["roundtrip"];
        args.extend(chunk.iter().map(String::as_str));
        let o = run(&prog, &args, &[], 600);
        assert!(o.status.success(), "roundtrip failed: {}", text(&o.stderr));
        text(&o.stdout)
    });
    let lines: Vec<String> = outs
        .iter()
        .flat_map(|o| o.lines().map(String::from))
        .collect();
    let bad: Vec<&String> = lines.iter().filter(|l| !l.ends_with(" same")).collect();
    let body = format!(
        "mjb round trip: {} of {} models that load are the same after save and load from memory\n{}",
        lines.len() - bad.len(),
        lines.len(),
        bad.iter().map(|l| format!("  {l}\n")).collect::<String>()
    );
    report("mjb-roundtrip", &body);
    assert!(bad.is_empty() && lines.len() >= 4, "{body}");
}

#[test]
fn file_and_buffer_verdicts_match_the_reference() {
    let ours = program(Lib::Ours);
    let reference = program(Lib::Ref);
    let dir = work_dir("mjb_hostile_probe");
    let mut body = String::new();
    for name in ["pendulum.xml", "arm3.xml"] {
        let mjb = dir.join(name).with_extension("mjb");
        let ms = mjb.to_string_lossy().into_owned();
        assert!(run(&reference, &["save", &model(name), &ms], &[], 60)
            .status
            .success());
        let theirs = text(&run(&reference, &["probe", &ms], &[], 120).stdout);
        let mine = text(&run(&ours, &["probe", &ms], &[], 120).stdout);
        body.push_str(&format!("{name}:\n{mine}"));
        assert_eq!(
            mine, theirs,
            "{name}: ours (left) and the reference's verdicts differ"
        );
        assert!(mine.contains("trailing-64 vfs ok") && mine.lines().count() == 16);
    }
    report("mjb-probe", &body);
}

#[test]
fn hostile_mjb_files_never_crash() {
    let prog = program(Lib::Ours);
    let seeds = seeds(&prog);
    let total = if corpus_files().is_empty() { 300 } else { 1000 };
    let jobs = jobs().max(1);
    let parts: Vec<usize> = (0..jobs).collect();
    let outs = par_map(&parts, |_, &k| {
        let count = (total / jobs).to_string();
        let seed = (1000 + k).to_string();
        let mut args = vec!["mutants", seed.as_str(), count.as_str()];
        args.extend(seeds.iter().map(String::as_str));
        let o = run(&prog, &args, &[], 900);
        assert!(o.status.success(), "mutants failed: {}", text(&o.stderr));
        text(&o.stdout)
    });
    let lines: Vec<String> = outs
        .iter()
        .flat_map(|o| o.lines().map(String::from))
        .collect();
    let verdict = |l: &String| l.split_whitespace().nth(3).unwrap_or("").to_string();
    let mut counts = std::collections::BTreeMap::new();
    for l in &lines {
        *counts.entry(verdict(l)).or_insert(0) += 1;
    }
    let bad: Vec<&String> = lines
        .iter()
        .filter(|l| {
            let v = verdict(l);
            v == "crash" || v == "hang" || l.contains("internal error") || v.is_empty()
        })
        .collect();
    let mut body = format!(
        "hostile mjb: {} mutants of {} seeds: {}\n",
        lines.len(),
        seeds.len(),
        counts
            .iter()
            .map(|(k, v)| format!("{k} {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for l in &bad {
        body.push_str(&format!("  FAIL {l}\n"));
    }
    report("mjb-hostile", &body);
    assert!(
        lines.len() >= total * 9 / 10 && counts.get("ok").copied().unwrap_or(0) > 0,
        "{body}"
    );
    assert!(bad.is_empty(), "{body}");
}

#[test]
fn activation_count_changed_is_refused_at_load() {
    // an arm26 MJB with na changed from 6 to 12 used to load and fail in mj_step with an
    // internal error; every seed with na moved by one or doubled must now be refused at load
    let prog = program(Lib::Ours);
    let dir = work_dir("mjb_hostile_na");
    let mut checked = 0;
    for seed in seeds(&prog) {
        let bytes = std::fs::read(&seed).unwrap();
        // the int fields follow the 4-int header: nq, nv, nu, na, ...
        let na = i32::from_ne_bytes(bytes[28..32].try_into().unwrap());
        for changed in [na + 1, 2 * na + 1] {
            let mut b = bytes.clone();
            b[28..32].copy_from_slice(&changed.to_ne_bytes());
            let f = dir.join("na.mjb");
            std::fs::write(&f, &b).unwrap();
            let out = text(&run(&prog, &["step", &f.to_string_lossy()], &[], 60).stdout);
            // key_act has na columns: with keyframes the buffer size tells first
            assert!(
                out.trim() == "reject Invalid model: na inconsistent with actuator_dyntype."
                    || out.trim() == "reject Corrupted model, wrong size parameters",
                "{seed} with na {na} -> {changed}: {out}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 8, "only {checked} cases");
}

/// Dofs out of depth-first order (a subtree that is not a run of dofs, which the compiler
/// never makes and the factorization relies on): refused at load with the field named.
#[test]
fn dofs_out_of_depth_first_order_refused() {
    let prog = program(Lib::Ours);
    let dir = work_dir("mjb_hostile_dof_order");
    let xml = dir.join("tree.xml");
    std::fs::write(
        &xml,
        r#"<mujoco><worldbody>
  <body name="a"><joint axis="0 1 0"/><geom size=".1"/>
    <body name="c" pos="0 0 -.3"><joint axis="0 1 0"/><geom size=".1"/></body></body>
  <body name="b" pos="1 0 0"><joint axis="0 1 0"/><geom size=".1"/></body>
</worldbody></mujoco>"#,
    )
    .unwrap();
    let mjb = dir.join("tree.mjb");
    let (xs, ms) = (xml.to_string_lossy(), mjb.to_string_lossy());
    assert!(run(&prog, &["save", &xs, &ms], &[], 60).status.success());
    let ints = |v: [i32; 6]| v.iter().flat_map(|x| x.to_ne_bytes()).collect::<Vec<u8>>();
    // dof_parentid and dof_Madr, adjacent in the file: a, c (child of a), b; then a, b, c
    let (depth_first, reordered) = (ints([-1, 0, -1, 0, 1, 3]), ints([-1, -1, 0, 0, 1, 2]));
    let mut bytes = std::fs::read(&mjb).unwrap();
    let at = bytes
        .windows(depth_first.len())
        .position(|w| w == depth_first)
        .expect("dof_parentid and dof_Madr in the MJB");
    let out = text(&run(&prog, &["step", &ms], &[], 60).stdout);
    assert!(!out.starts_with("reject"), "the model as saved: {out}");
    bytes[at..at + reordered.len()].copy_from_slice(&reordered);
    std::fs::write(&mjb, &bytes).unwrap();
    let out = text(&run(&prog, &["step", &ms], &[], 60).stdout);
    assert_eq!(
        out.trim(),
        "reject Invalid model: dof_parentid not in depth-first order."
    );
}
