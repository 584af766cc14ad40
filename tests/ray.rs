//! Ray casting: capi-tests/ray.c casts 8,424 rays with mj_ray (filters, static geoms off,
//! excluded bodies, direction lengths from 1e-8 to 1e160) against models/extra/ray_scene.xml,
//! with every geom type, and each geom alone through mju_rayGeom, mj_rayMesh and mj_rayHfield.
//! Geom ids and distance bits must equal the reference's. capi-tests/ray_hfield.c does the same
//! for height fields.

mod common;
use common::*;

/// Output of capi-tests/NAME.c run on `scene` (under models/), built against the reference
/// and against ours.
fn both(name: &str, scene: &str) -> (String, String) {
    both_outputs(name, &[&model(scene)])
}

#[test]
fn rays_like_the_reference() {
    let (reference, ours) = both("ray", "extra/ray_scene.xml");
    let summary = reference
        .lines()
        .find(|l| l.starts_with("mj_ray:"))
        .unwrap_or_else(|| panic!("no summary: {reference}"))
        .to_string();
    // most rays must hit something, or the test would prove little
    let hits: usize = summary
        .split_whitespace()
        .nth(3)
        .and_then(|h| h.parse().ok())
        .unwrap_or(0);
    assert!(hits > 3000, "{summary}");
    assert_eq!(
        reference, ours,
        "rays differ:\nreference:\n{reference}\nours:\n{ours}"
    );
    report(
        "ray",
        &format!("rays: identical ids and distance bits ({summary})\n"),
    );
}

/// Height fields: capi-tests/ray_hfield.c fills models/extra/ray_hfield.xml's two fields with
/// bumps and casts 42,900 rays with mj_rayHfield (and mj_ray) from points above, inside, beside
/// and below them, in axis-aligned, vertical, grazing and other directions; the distance bits
/// must equal the reference's.
#[test]
fn height_field_rays_like_the_reference() {
    let (reference, ours) = both("ray_hfield", "extra/ray_hfield.xml");
    // many rays must hit, or the test would prove little
    let hits: usize = reference
        .split_whitespace()
        .nth(3)
        .and_then(|h| h.parse().ok())
        .unwrap_or(0);
    assert!(hits > 5000, "{reference}");
    assert_eq!(reference, ours, "height field rays differ");
    report(
        "ray-hfield",
        &format!(
            "height field rays: identical distance bits ({})\n",
            reference.trim()
        ),
    );
}
