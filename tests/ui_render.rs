//! The UI framework drawn and driven (mjui_update, mjui_event, mjui_render) against 2.2.2
//! under OSMesa: two simulate-like panels with every item type at several font scales and
//! themes, then scripted mouse, wheel, key and resize events (capi-tests/ui_render.c). Every
//! returned item, data value, UI tracking and edit field and the hash of every frame's
//! pixels must be identical.

mod common;

use common::*;

#[test]
fn ui_matches_reference() {
    require_osmesa();
    let progs = [Lib::Ref, Lib::Ours]
        .map(|lib| compile_gl("capi-tests/ui_render.c", "ui_render", lib, &["-lOSMesa"]));
    let outputs = par_map(&progs, |_, p| run(p, &[], &[], 600));
    let (reference, ours) = (text(&outputs[0].stdout), text(&outputs[1].stdout));
    let stderr = text(&outputs[1].stderr);
    let (mut frames, mut events, mut differ) = (0, 0, 0);
    let mut first = None;
    for (k, (a, b)) in reference
        .lines()
        .zip(ours.lines().chain(std::iter::repeat("")))
        .enumerate()
    {
        frames += a.starts_with("frame ") as usize;
        events += a.starts_with("event ") as usize;
        if a != b {
            differ += 1;
            first.get_or_insert(format!("line {}:\n  2.2.2: {a}\n  ours:  {b}", k + 1));
        }
    }
    report(
        "ui-render",
        &format!(
            "mjui_update/event/render: {frames} frames, {events} events, {} lines; {differ} \
             lines differ\n",
            reference.lines().count()
        ),
    );
    assert!(outputs[0].status.success(), "reference run failed");
    assert_eq!(differ, 0, "{}\n{stderr}", first.unwrap_or_default());
    assert_eq!(reference.lines().count(), ours.lines().count(), "{stderr}");
    assert!(
        frames > 1000 && events > 1000,
        "only {frames} frames, {events} events"
    );
}
