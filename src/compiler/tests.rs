//! Unit tests of the compiler's arithmetic and of the MJCF reader (no reference library).

use super::frame::*;
use super::spec::JointType;
use super::texture::CRand;
use crate::xml::{reader, schema, tree};

fn read(text: &str) -> Result<super::spec::ModelSpec, String> {
    let root = tree::parse(text)?;
    schema::check(&root)?;
    reader::read(&root)
}

#[test]
fn c_rand_matches_glibc_after_srand_123() {
    let mut r = CRand::new(123);
    let got: Vec<i32> = (0..5).map(|_| r.rand()).collect();
    assert_eq!(
        got,
        [128959393, 1692901013, 436085873, 748533630, 776550279]
    );
}

#[test]
fn eig3_sorts_eigenvalues_decreasing() {
    let (val, q) = eig3(&[1.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 2.0]);
    assert_eq!(val, [3.0, 2.0, 1.0]);
    let n: f64 = q.iter().map(|x| x * x).sum();
    assert!((n - 1.0).abs() < 1e-15);
}

#[test]
fn z2quat_maps_z_to_vector() {
    let q = z2quat(&[0.0, 1.0, 0.0]);
    let m = quat2mat(&q);
    // third column is the image of z
    assert!((m[2]).abs() < 1e-15 && (m[5] - 1.0).abs() < 1e-15 && m[8].abs() < 1e-15);
}

#[test]
fn defaults_and_childclass_apply() {
    let spec = read(
        r#"<mujoco><default><joint damping="2"/><default class="c"><geom size="0.5"/></default></default>
        <worldbody><body childclass="c"><joint/><geom/></body></worldbody></mujoco>"#,
    )
    .unwrap();
    let b = &spec.world.bodies[0];
    assert_eq!(b.joints[0].damping, 2.0);
    assert_eq!(b.joints[0].kind, JointType::Hinge);
    assert_eq!(b.geoms[0].size[0], 0.5);
}

#[test]
fn reader_errors_name_element_and_line() {
    let e =
        read("<mujoco>\n<worldbody>\n<geom size=\"1 x\"/>\n</worldbody>\n</mujoco>").unwrap_err();
    assert_eq!(
        e,
        "XML Error: problem reading attribute 'size'\nElement 'geom', line 3\n"
    );
    let e = read("<mujoco>\n<worldbody>\n<geom bar=\"1\"/>\n</worldbody>\n</mujoco>").unwrap_err();
    assert!(e.contains("unrecognized attribute: 'bar'") && e.contains("line 3"));
    let e = read("<mujoco>\n<worldbody>\n<body>\n</worldbody>\n</mujoco>").unwrap_err();
    assert!(e.starts_with("XML parse error 14:"));
}

#[test]
fn garbage_never_panics() {
    for text in [
        "",
        "<",
        "<mujoco",
        "<mujoco><",
        "\u{0}",
        "<mujoco><option timestep=\"1e999\"/></mujoco>",
        "<a/><b/>",
    ] {
        let _ = read(text);
    }
}
