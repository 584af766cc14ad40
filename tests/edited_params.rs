//! Contact parameters edited in mjModel after loading, NaN among them (capi-tests/
//! edited_params.c): 2.2.2 mixes a pair's margin, gap, friction and solref with mju_max and
//! mju_min, which pass a NaN on in one argument order only, and tests its bounding spheres
//! with the margin that gives; our filters ahead of that test must let such pairs through.
//! A NaN impratio likewise reaches the elliptic cones' R (mju_max(mjMINVAL, impratio)). Sizes
//! edited to zero or NaN (the bounding radius as compiled) must not let the box tests skip a
//! pair whose routine, taking a zero half-size as no bound, finds a contact.
//! Both libraries must print the same hashes of every contact and of the state.

mod common;
use common::*;

#[test]
fn edited_contact_parameters_like_the_reference() {
    let models = [
        model("extra/contact_primitives.xml"),
        // bodies of many geoms: the geom pairs of a body pair are tested together
        model("extra/geom_clusters.xml"),
        // a body of 40 geoms against bodies of few: tested in the large body's frame (the
        // last geom edited is a small body's)
        model("extra/geom_large.xml"),
        // elliptic cones (impratio), Newton and PGS
        model("extra/contact_newton_elliptic_dense_ns5.xml"),
        model("extra/contact_pgs_elliptic_sparse_ns5.xml"),
    ];
    let args: Vec<&str> = models.iter().map(String::as_str).collect();
    let (reference, ours) = both_outputs("edited_params", &args);
    assert_eq!(reference.matches("hash").count(), 165, "{reference}");
    // the edits change the runs: most hashes differ from the model as loaded
    let loaded: Vec<&str> = reference
        .lines()
        .filter(|l| l.starts_with("as loaded"))
        .map(|l| &l[l.len() - 16..])
        .collect();
    let changed = reference
        .lines()
        .filter(|l| l.contains(" hash ") && !l.starts_with("as loaded"))
        .filter(|l| !loaded.contains(&&l[l.len() - 16..]))
        .count();
    assert!(
        changed >= 40,
        "only {changed} edits changed the run:\n{reference}"
    );
    let sizes = reference
        .lines()
        .filter(|l| l.starts_with("size") && !loaded.contains(&&l[l.len() - 16..]))
        .count();
    assert!(
        sizes >= 8,
        "only {sizes} size edits changed the run:\n{reference}"
    );
    assert_eq!(
        reference, ours,
        "edited parameters differ:\nreference:\n{reference}\nours:\n{ours}"
    );
    report(
        "edited-params",
        &format!(
            "edited contact parameters: identical contacts and states on both libraries\n{ours}"
        ),
    );
}
