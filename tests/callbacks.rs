//! User callbacks: capi-tests/callbacks.c installs mjcb_control, mjcb_passive, mjcb_act_gain,
//! mjcb_act_bias, mjcb_act_dyn, mjcb_sensor, mjcb_contactfilter and mjcb_time (a counter, so that
//! timer durations count the clock's calls and the filter counts its own) and steps a model
//! with user actuators and sensors and contacts, and one of bodies with several geoms whose
//! pairs the built-in filter would discard (the user's filter must still see each), then calls
//! mjCOLLISIONFUNC for every geom pair; both libraries must print the same, digit for digit.

mod common;
use common::*;

#[test]
fn callbacks_like_the_reference() {
    let src = [root().join("capi-tests/callbacks.c")];
    let (ref_prog, our_prog) = (
        compile_c(&src, "callbacks", Lib::Ref),
        compile_c(&src, "callbacks", Lib::Ours),
    );
    let mut lasts = Vec::new();
    // callbacks.xml: user actuators and sensors; weld_filter.xml: bodies of several geoms whose
    // pairs the built-in filter discards and the user's filter must still see
    for name in ["extra/callbacks.xml", "extra/weld_filter.xml"] {
        let model = common::model(name);
        let out = |prog: &std::path::Path| {
            let o = run(prog, &[&model], &[], 120);
            assert!(o.status.success(), "{}{}", text(&o.stdout), text(&o.stderr));
            text(&o.stdout)
        };
        let (reference, ours) = (out(&ref_prog), out(&our_prog));
        assert!(reference.contains("calls: control 501"), "{reference}");
        assert!(!reference.contains(" filter 0\n"), "{reference}");
        assert_eq!(
            reference, ours,
            "callbacks differ on {name}:\nreference:\n{reference}\nours:\n{ours}"
        );
        lasts.push(format!("{name}: {}", ours.lines().last().unwrap_or("")));
    }
    report(
        "callbacks",
        &format!(
            "callbacks: identical output on both libraries ({})\n",
            lasts.join("; ")
        ),
    );
}
