//! Optional: compiled-model comparison over a corpus of real models (MuJoCo's and dm_control's),
//! run only when a corpus is present (common::corpus_dirs: $RUJOCO_CORPUS, else ../shared/corpus; run-all
//! sets RUJOCO_CORPUS to the dm_control 1.0.7 suite from PyPI when ../shared is absent).
//! A model we cannot compile yet must be rejected with an error, never loaded with other values;
//! the report (target/capi-tests/reports/corpus.txt) counts identical models; RUJOCO_CORPUS_STRICT=1
//! requires every model identical.

mod common;
use common::*;

#[test]
fn corpus_compiled_models() {
    let dirs = corpus_dirs();
    if dirs.is_empty() {
        eprintln!("corpus_compiled_models: skipped, no corpus");
        return;
    }
    let bin = harness_bin();
    let files = corpus_files();
    let base = work_dir("corpus");
    // per model: None when the reference rejects it, else (identical, path, first line)
    let results = par_map(&files, |i, f| {
        let dir = base.join(i.to_string());
        let _ = std::fs::remove_dir_all(&dir);
        let (fs, ds) = (
            f.to_string_lossy().to_string(),
            dir.to_string_lossy().to_string(),
        );
        let (ok, out) = harness_compare(
            &bin,
            &fs,
            &ds,
            &["--model-only"],
            &["--groups", "model"],
            120,
        )?; // None: include files and deliberately malformed models
        let rel = dirs
            .iter()
            .find_map(|d| f.strip_prefix(d.parent().unwrap_or(d)).ok())
            .unwrap_or(f)
            .display()
            .to_string();
        let why = out.lines().next().unwrap_or("").trim().to_string();
        Some((ok, rel, why))
    });
    let (mut same, mut differ, mut rejected) = (Vec::new(), Vec::new(), 0);
    for r in results {
        match r {
            None => rejected += 1,
            Some((true, rel, _)) => same.push(rel),
            Some((false, rel, why)) => differ.push(format!("{rel}: {why}")),
        }
    }
    let msg = format!(
        "corpus ({}): {} of {} models compile identically to 2.2.2 ({} files the reference rejects skipped)\n{}",
        dirs.iter()
            .map(|d| d.display().to_string())
            .collect::<Vec<_>>()
            .join(", "),
        same.len(),
        same.len() + differ.len(),
        rejected,
        differ.iter().map(|d| format!("  differs: {d}\n")).collect::<String>()
    );
    report("corpus", &msg);
    // A model we cannot compile yet must be rejected with an error, never loaded with other values.
    let wrong: Vec<&String> = differ
        .iter()
        .filter(|d| !d.contains("mj_loadXML failed"))
        .collect();
    assert!(
        wrong.is_empty(),
        "models loaded with values other than 2.2.2's: {wrong:?}\n{msg}"
    );
    if std::env::var("RUJOCO_CORPUS_STRICT").is_ok_and(|v| v == "1") {
        assert!(differ.is_empty(), "{msg}");
    }
}
