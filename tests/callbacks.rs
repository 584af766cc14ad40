//! User callbacks: capi-tests/callbacks.c installs mjcb_control, mjcb_passive, mjcb_act_gain,
//! mjcb_act_bias, mjcb_act_dyn, mjcb_sensor, mjcb_contactfilter and mjcb_time (a counter, so that
//! timer durations count the clock's calls) and steps a model with user
//! actuators and sensors and contacts, then calls mjCOLLISIONFUNC for every geom pair; both
//! libraries must print the same, digit for digit.

mod common;
use common::*;

#[test]
fn callbacks_like_the_reference() {
    let src = [root().join("capi-tests/callbacks.c")];
    let model = common::model("extra/callbacks.xml");
    let out = |lib| {
        let prog = compile_c(&src, "callbacks", lib);
        let o = run(&prog, &[&model], &[], 120);
        assert!(o.status.success(), "{}{}", text(&o.stdout), text(&o.stderr));
        text(&o.stdout)
    };
    let (reference, ours) = (out(Lib::Ref), out(Lib::Ours));
    assert!(reference.contains("calls: control 501"), "{reference}");
    assert_eq!(
        reference, ours,
        "callbacks differ:\nreference:\n{reference}\nours:\n{ours}"
    );
    let last = ours.lines().last().unwrap_or("");
    report(
        "callbacks",
        &format!("callbacks: identical output on both libraries ({last})\n"),
    );
}
