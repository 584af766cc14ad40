//! The rows of actuator_moment (capi-tests/moments.c): after resets (the debug pattern too),
//! copies into data in another state, a buffer copied by hand, and actuators edited to other
//! joints and transmission types between calls, with dense and sparse Jacobians. Both
//! libraries must print the same hashes of the whole matrix and the actuation it drives: ours
//! zeroes of a joint actuator's row only the columns the last transmission wrote, the whole
//! matrix after anything else wrote the buffer.

mod common;
use common::*;

#[test]
fn moment_rows_like_the_reference() {
    let models = [
        model("extra/moment_rows.xml"),
        model("extra/tendon_wrap_sparse.xml"),
    ];
    let args: Vec<&str> = models.iter().map(String::as_str).collect();
    let (reference, ours) = both_outputs("moments", &args);
    assert_eq!(reference.matches("hash").count(), 28, "{reference}");
    assert_eq!(
        reference, ours,
        "actuator_moment differs:\nreference:\n{reference}\nours:\n{ours}"
    );
    report(
        "moments",
        &format!("actuator_moment rows: identical on both libraries\n{ours}"),
    );
}
