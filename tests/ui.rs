//! The UI framework (mjui_) against 2.2.2: themes, building from definition tables with every
//! item type, layout at every font scale and spacing, and the messages for bad tables.

mod common;

use common::*;
use std::sync::OnceLock;

fn programs() -> &'static (std::path::PathBuf, std::path::PathBuf) {
    static P: OnceLock<(std::path::PathBuf, std::path::PathBuf)> = OnceLock::new();
    P.get_or_init(|| {
        let src = vec![root().join("capi-tests/ui_layout.c")];
        (
            compile_c(&src, "ui_layout", Lib::Ref),
            compile_c(&src, "ui_layout", Lib::Ours),
        )
    })
}

#[test]
fn layout_matches_reference() {
    let (r, o) = programs();
    let reference = text(&run(r, &[], &[], 60).stdout);
    let ours = text(&run(o, &[], &[], 60).stdout);
    let lines = reference.lines().count();
    let differ = reference
        .lines()
        .zip(ours.lines())
        .filter(|(a, b)| a != b)
        .count();
    report(
        "ui-layout",
        &format!("ui layout: {lines} lines (24 layouts, 8 themes), {differ} differ\n"),
    );
    assert!(lines > 800, "ui_layout printed {lines} lines");
    assert_eq!(ours, reference);
}

#[test]
fn bad_tables_give_reference_messages() {
    let (r, o) = programs();
    let mut cases = 0;
    for k in 0.. {
        let arg = k.to_string();
        let reference = run(r, &[&arg], &[], 30);
        if reference.status.code() == Some(2) {
            break;
        }
        let ours = run(o, &[&arg], &[], 30);
        assert_eq!(
            text(&ours.stdout),
            text(&reference.stdout),
            "bad table {k}: messages differ"
        );
        assert_eq!(ours.status.code(), reference.status.code(), "bad table {k}");
        cases += 1;
    }
    assert!(cases >= 17, "only {cases} bad tables ran");
}
