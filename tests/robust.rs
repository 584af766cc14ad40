//! No crash on bad arguments: capi-tests/robust.c calls the API with invalid ids, NULL
//! pointers and negative sizes (where 2.2.2 reads out of bounds or crashes); every call must
//! return, reporting through mju_error where the arguments are unusable.

mod common;
use common::*;

#[test]
fn bad_arguments_never_crash() {
    let prog = compile_c(&[root().join("capi-tests/robust.c")], "robust", Lib::Ours);
    let mut summary = String::new();
    for name in [
        "arm3.xml",
        "chain.xml",
        "freebox.xml",
        "extra/tendon_wrap.xml",
    ] {
        let model = common::model(name);
        let o = run(&prog, &[&model], &[], 60);
        let out = text(&o.stdout);
        let last = out.lines().last().unwrap_or("");
        assert!(
            o.status.success() && last.starts_with("done"),
            "robust.c on {name} stopped (exit {:?}) after:\n{}\n{}",
            o.status.code(),
            out.lines().rev().take(3).collect::<Vec<_>>().join("\n"),
            text(&o.stderr)
        );
        summary.push_str(&format!("  {name}: {last}\n"));
    }
    report(
        "robust",
        &format!("bad arguments (invalid ids, NULL, negative sizes): no crash\n{summary}"),
    );
}
