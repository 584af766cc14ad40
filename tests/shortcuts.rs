//! Inputs at the edge of the shortcuts that leave out work 2.2.2 does (capi-tests/shortcuts.c):
//! non-finite and huge positions and spring positions of free and ball joints without
//! stiffness. The outputs (bit patterns of qfrc_passive and qacc) must be the reference's.

mod common;
use common::*;

#[test]
fn shortcuts_at_their_edges_match_reference() {
    require_reference();
    let src = vec![root().join("capi-tests/shortcuts.c")];
    let reference = run(&compile_c(&src, "shortcuts", Lib::Ref), &[], &[], 60);
    let ours = run(&compile_c(&src, "shortcuts", Lib::Ours), &[], &[], 60);
    assert!(
        reference.status.success(),
        "shortcuts fails on the reference"
    );
    assert!(ours.status.success(), "shortcuts fails on ours");
    let (r, o) = (text(&reference.stdout), text(&ours.stdout));
    let cases = r.lines().filter(|l| l.starts_with("case")).count();
    let differ: Vec<(&str, &str)> = r.lines().zip(o.lines()).filter(|(a, b)| a != b).collect();
    let msg = format!(
        "shortcuts: {cases} cases (free and ball joints, NaN, infinities, huge and subnormal \
         values in qpos and qpos_spring), {} output lines differ\n",
        differ.len() + r.lines().count().abs_diff(o.lines().count())
    );
    report("shortcuts", &msg);
    assert!(
        cases > 100 && r.lines().count() == o.lines().count(),
        "{msg}"
    );
    assert!(
        differ.is_empty(),
        "{msg}first difference:\n{:?}",
        differ.first()
    );
}
