//! 10,000-step runs (2,000 for models of more than 100 bodies or 60 dofs, or with a height field
//! of more than 10,000 points: composites, crowds of humanoids, stacks of free bodies, long
//! chains, terrains):
//! no NaN and no warning the reference does not also give, no crash, no hang.
//! Models: capi-tests/models.list (must match), then the models of models-extra.list and the
//! main corpus (../shared/corpus or the dm_control suite, when present) that both libraries
//! load: a run our engine stops with "not implemented" is counted as not supported yet,
//! anything else must match the reference.

mod common;
use common::*;
use std::path::Path;

const STEPS: &str = "10000";

/// The main corpus (common::main_corpus_files): the other packages' models get the physics
/// corpus checks along 1000-step trajectories (tests/corpus.rs).
fn corpus_models() -> Vec<String> {
    main_corpus_files()
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect()
}

fn outcomes(prog: &Path, files: &[String]) -> Vec<String> {
    let mut args = vec![STEPS];
    args.extend(files.iter().map(String::as_str));
    let o = run(prog, &args, &[], 3600);
    let lines: Vec<String> = text(&o.stdout).lines().map(str::to_string).collect();
    assert_eq!(
        lines.len(),
        files.len(),
        "longrun output incomplete:\n{}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    lines
}

#[test]
fn ten_thousand_steps_like_the_reference() {
    let src = [root().join("capi-tests/longrun.c")];
    let reference = compile_c(&src, "longrun", Lib::Ref);
    let ours = compile_c(&src, "longrun", Lib::Ours);
    let strict = models();
    let mut files = strict.clone();
    for f in model_list("models-extra.list")
        .into_iter()
        .chain(corpus_models())
    {
        if !files.contains(&f) {
            files.push(f);
        }
    }
    // runs of a few files per library, the reference's first (the slower), shared out to the
    // cores as they free: neither library's runs wait on the other's
    let chunks: Vec<&[String]> = files.chunks(4).collect();
    let jobs: Vec<(&Path, &[String])> = [&reference, &ours]
        .iter()
        .flat_map(|prog| chunks.iter().map(move |c| (prog.as_path(), *c)))
        .collect();
    let mut lines = par_map(&jobs, |_, (prog, chunk)| outcomes(prog, chunk)).into_iter();
    let r: Vec<String> = lines.by_ref().take(chunks.len()).flatten().collect();
    let o: Vec<String> = lines.flatten().collect();
    let (mut same, mut unsupported, mut skipped) = (0, 0, 0);
    let mut wrong = Vec::new();
    for (f, (r, o)) in files.iter().zip(r.iter().zip(&o)) {
        let rel = f.strip_prefix(&*root().to_string_lossy()).unwrap_or(f);
        if !r.starts_with("ok") {
            skipped += 1; // include files, models the reference rejects or stops on
        } else if r == o {
            same += 1;
        } else if !strict.contains(f) && o.contains("not implemented") {
            unsupported += 1;
        } else if !strict.contains(f) && o.starts_with("load-error") {
            unsupported += 1; // the loader's verdicts are tests/corpus.rs's and loader.rs's
        } else {
            wrong.push(format!("{rel}\n    reference: {r}\n    ours:      {o}"));
        }
    }
    let msg = format!(
        "long runs ({STEPS} steps, 2000 above 100 bodies, 60 dofs or 10,000 height-field points): {same} models end like the reference (NaN, warnings); \
         {unsupported} stop on features not supported yet; {} differ; {skipped} files skipped \
         (the reference rejects or stops)\n{}",
        wrong.len(),
        wrong.iter().map(|w| format!("  {w}\n")).collect::<String>()
    );
    report("long-run", &msg);
    assert!(wrong.is_empty(), "{msg}");
}
