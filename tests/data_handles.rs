//! mjData handled every way a program may: copies made and copied into, a model copy used with
//! the same data, a struct copied by value, data freed and made again, resets
//! (capi-tests/data_handles.c). Both libraries must print the same state hashes, and the same
//! hashes of the whole array buffer after resets, and copies equal to their source byte for
//! byte: our C entry points reuse a view kept with each mjData, and none of these may leave it
//! stale; our resets and copies skip the pages never written.

mod common;
use common::*;

#[test]
fn data_handles_like_the_reference() {
    let models = [
        model("arm3.xml"),
        model("chain.xml"),
        model("extra/contact_primitives.xml"),
        // an array buffer of 4 MB: a mapping of its own, whose untouched pages resets skip
        model("extra/longchain_newton.xml"),
    ];
    let args: Vec<&str> = models.iter().map(String::as_str).collect();
    let (reference, ours) = both_outputs("data_handles", &args);
    assert_eq!(reference.matches("hash").count(), 60, "{reference}");
    assert_eq!(reference.matches("copy equal").count(), 20, "{reference}");
    assert_eq!(
        reference, ours,
        "data handling differs:\nreference:\n{reference}\nours:\n{ours}"
    );
    report(
        "data-handles",
        &format!("data handles: identical state hashes on both libraries\n{ours}"),
    );
}
