//! The mjData stack as 2.2.2 uses it (capi-tests/stack.c on both libraries): `maxuse_stack`
//! after a driven trajectory and after each stage and API function that takes scratch (the
//! solvers and cones, noslip, the integrators, mj_compareFwdInv, the Jacobian helpers,
//! mjd_transitionFD, mj_printData, mj_setConst), the stack top every callback sees, and the
//! stack size below which mj_step stops with "Stack overflow", on models.list,
//! models-extra.list and the main corpus, with and
//! without constraints and contacts (disable flags 17). Every line must be the reference's.
//! Report: stack.txt.

mod common;
use common::*;

#[test]
fn stack_use_like_the_reference() {
    let src = [root().join("capi-tests/stack.c")];
    let (r, o) = (
        compile_c(&src, "stack", Lib::Ref),
        compile_c(&src, "stack", Lib::Ours),
    );
    let mut files = models();
    files.extend(model_list("models-extra.list"));
    files.extend(
        main_corpus_files()
            .iter()
            .map(|p| p.to_string_lossy().into_owned()),
    );
    let runs: Vec<(String, &str)> = files
        .iter()
        .flat_map(|f| [(f.clone(), "0"), (f.clone(), "17")])
        .collect();
    let results = par_map(&runs, |_, (f, flags)| {
        let line = |prog: &std::path::Path| text(&run(prog, &[f, flags], &[], 600).stdout);
        (line(&r), line(&o))
    });
    let (mut same, mut checked) = (0, 0);
    let mut wrong = Vec::new();
    for ((f, flags), (lr, lo)) in runs.iter().zip(&results) {
        if lr.trim().is_empty() || lr.starts_with("load-error") {
            continue;
        }
        checked += 1;
        if lr == lo {
            same += 1;
        } else {
            let (wr, wo): (Vec<&str>, Vec<&str>) = (
                lr.split_whitespace().collect(),
                lo.split_whitespace().collect(),
            );
            let first = wr
                .iter()
                .zip(&wo)
                .find(|(a, b)| a != b)
                .map(|(a, b)| format!("reference {a}, ours {b}"))
                .unwrap_or_else(|| format!("reference {lr:?}, ours {lo:?}"));
            wrong.push(format!("{f} (disable {flags}): {first}"));
        }
    }
    let msg = format!(
        "stack use (maxuse_stack after the trajectory, the stages and functions, overflow \
         point): {same} of {checked} runs as the reference's\n{}",
        wrong.iter().map(|w| format!("  {w}\n")).collect::<String>()
    );
    report("stack", &msg);
    assert!(checked > 0, "no model checked");
    assert!(wrong.is_empty(), "{msg}");
}
