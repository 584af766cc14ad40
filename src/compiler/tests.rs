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

#[test]
fn rope_composite_expands_into_a_chain() {
    let spec = read(
        r#"<mujoco><worldbody><body name="B1"><composite type="rope" count="4 1 1" spacing=".1">
        <joint kind="twist"/><geom type="capsule" size=".01 .02"/></composite></body>
        </worldbody></mujoco>"#,
    )
    .unwrap();
    let root = &spec.world.bodies[0];
    // root keeps its geom; children to the right (B2, B3) then to the left (B0)
    assert_eq!(root.geoms[0].name, "G1");
    let names: Vec<&str> = root.bodies.iter().map(|b| b.name.as_str()).collect();
    assert_eq!(names, ["B2", "B0"]);
    assert_eq!(root.bodies[0].bodies[0].name, "B3");
    let b2 = &root.bodies[0];
    let joints: Vec<&str> = b2.joints.iter().map(|j| j.name.as_str()).collect();
    assert_eq!(joints, ["J0_2", "J1_2", "JT2"]);
    assert_eq!(b2.joints[0].group, 3);
    // one twist constraint per non-root element
    assert_eq!(spec.equalities.len(), 3);
}

#[test]
fn skin_lists_stop_where_a_stream_would() {
    let spec = read(
        r#"<mujoco><asset><skin vertex="1 2.5e1 3x 4" face="1 2e3 4" texcoord="nan 1">
        <bone body="world" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0" vertweight="1"/>
        </skin></asset></mujoco>"#,
    )
    .unwrap();
    let s = &spec.skins[0];
    assert_eq!(s.vert, [1.0, 25.0, 3.0]);
    assert_eq!(s.face, [1, 2]);
    assert!(s.texcoord.is_empty());
}
