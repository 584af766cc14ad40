//! Peak resident memory while loading a large model (dm_control's dog, 24.6 MB compiled, with
//! meshes, a skin and textures) stays within the reference's, and over ten rounds of load,
//! mj_makeData, a step and freeing both too; `capi-tests/loadmem.c` built against each library
//! reports its own high-water mark.

mod common;
use common::*;

/// dog.xml from the corpora; the dm_control suite that run-all fetches always has it.
fn dog() -> Option<std::path::PathBuf> {
    corpus_dirs()
        .into_iter()
        .flat_map(|d| {
            [
                d.join("suite/dog.xml"),
                d.join("dm_control-1.0.7/suite/dog.xml"),
                d.join("dog.xml"),
            ]
        })
        .find(|p| p.is_file())
}

fn peak_kb(prog: &std::path::Path, args: &[&str]) -> (u64, u64) {
    let o = run(prog, args, &[], 300);
    let out = text(&o.stdout);
    assert!(
        o.status.success(),
        "{} {args:?} failed: {out}{}",
        prog.display(),
        text(&o.stderr)
    );
    let mut it = out.split_whitespace();
    let mut field = |name: &str| -> u64 {
        assert_eq!(it.next(), Some(name), "unexpected output: {out}");
        it.next()
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("bad output: {out}"))
    };
    (field("peak"), field("rss"))
}

/// The two loadmem programs and the model they measure, with a note when dog.xml is absent;
/// built once for both tests (they run in parallel).
fn setup() -> &'static (std::path::PathBuf, std::path::PathBuf, String, String) {
    static SETUP: std::sync::OnceLock<(std::path::PathBuf, std::path::PathBuf, String, String)> =
        std::sync::OnceLock::new();
    SETUP.get_or_init(|| {
        let src = [root().join("capi-tests/loadmem.c")];
        let ours = compile_c(&src, "loadmem", Lib::Ours);
        let reference = compile_c(&src, "loadmem", Lib::Ref);
        let (model, note) = match dog() {
            Some(p) => (p, String::new()),
            None => (
                std::path::PathBuf::from(model("chain.xml")),
                " (dog.xml not found in the corpora: chain.xml instead)".to_string(),
            ),
        };
        (ours, reference, model.to_string_lossy().into_owned(), note)
    })
}

#[test]
fn dog_load_peak_within_reference() {
    let (ours, reference, model, note) = setup().clone();
    // best of 3 per side: the peak is deterministic up to page-level noise
    let best = |prog: &std::path::Path| (0..3).map(|_| peak_kb(prog, &[&model])).min().unwrap();
    let (rp, rr) = best(&reference);
    let (op, or) = best(&ours);
    let ratio = op as f64 / rp as f64;
    // a small model's peak is mostly each library's own code and data: 1.1x there
    let limit = if note.is_empty() { 1.0 } else { 1.1 };
    let body = format!(
        "load memory: {model}{note}\n  peak: ours {op} kB, reference {rp} kB, ratio {ratio:.3} (limit {limit})\n  resident after load: ours {or} kB, reference {rr} kB\n"
    );
    report("load-memory", &body);
    assert!(ratio <= limit, "{body}");
}

/// Repeated load/free rounds: what the heap keeps between rounds must not lift the peak above
/// the reference's (the mjData stack is mapped apart, so freeing it returns its pages), nor
/// leave more resident after the last round (a large load's freed temporaries go back).
#[test]
fn dog_load_free_cycles_peak_within_reference() {
    let (ours, reference, model, note) = setup().clone();
    let args = [model.as_str(), "10"];
    let best = |prog: &std::path::Path| (0..2).map(|_| peak_kb(prog, &args)).min().unwrap();
    let (rp, rr) = best(&reference);
    let (op, or) = best(&ours);
    let ratio = op as f64 / rp as f64;
    let rss_ratio = or as f64 / rr as f64;
    // a small model's peak is mostly each library's own code and data: 1.1x there
    let limit = if note.is_empty() { 1.0 } else { 1.1 };
    let body = format!(
        "load/free cycles: {model}{note}, 10 rounds of load, mj_makeData, mj_step, free\n  peak: ours {op} kB, reference {rp} kB, ratio {ratio:.3} (limit {limit})\n  resident after the last round: ours {or} kB, reference {rr} kB, ratio {rss_ratio:.3} (limit {limit})\n"
    );
    report("load-cycles-memory", &body);
    assert!(ratio <= limit && rss_ratio <= limit, "{body}");
}
