//! Unit tests of the narrow phase: geometric properties of the contacts each pair produces.

use crate::math::tests::uniform;
use crate::math::*;

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

#[test]
fn mpr_spheres_and_boxes() {
    use super::mpr::*;
    let sphere = |c: Vec3, r: f64| {
        move |d: &Vec3| {
            let n = norm3(d);
            [
                c[0] + r * d[0] / n,
                c[1] + r * d[1] / n,
                c[2] + r * d[2] / n,
            ]
        }
    };
    // overlapping spheres along x: depth 0.3, direction +-x
    let mut pair = ConvexPair {
        center1: [0.0; 3],
        center2: [0.9, 0.0, 0.0],
        support1: sphere([0.0; 3], 0.5),
        support2: sphere([0.9, 0.0, 0.0], 0.7),
        max_iterations: 50,
        tolerance: 1e-9,
    };
    let (depth, dir, pos) = pair.mpr_penetration().unwrap();
    assert!((depth - 0.3).abs() < 1e-6, "{depth}");
    assert!((dir[0].abs() - 1.0).abs() < 1e-6 && dir[1].abs() < 1e-3 && dir[2].abs() < 1e-3);
    assert!((pos[0] - 0.35).abs() < 1e-3, "{pos:?}");

    // separated boxes: no penetration
    let cube = |c: Vec3, h: f64| {
        move |d: &Vec3| {
            let s = |x: f64| if x >= 0.0 { h } else { -h };
            [c[0] + s(d[0]), c[1] + s(d[1]), c[2] + s(d[2])]
        }
    };
    let mut apart = ConvexPair {
        center1: [0.0; 3],
        center2: [0.0, 0.0, 1.5],
        support1: cube([0.0; 3], 0.5),
        support2: cube([0.0, 0.0, 1.5], 0.5),
        max_iterations: 50,
        tolerance: 1e-6,
    };
    assert!(apart.mpr_penetration().is_none());

    let (d2, w) = point_tri_dist2(
        &[0.2, 0.2, 1.0],
        &[0.0; 3],
        &[1.0, 0.0, 0.0],
        &[0.0, 1.0, 0.0],
    );
    assert!((d2 - 1.0).abs() < 1e-15 && close(&w, &[0.2, 0.2, 0.0], 1e-15));
    let (d2, w) = point_segment_dist2(&[2.0, 1.0, 0.0], &[0.0; 3], &[1.0, 0.0, 0.0]);
    assert_eq!((d2, w), (2.0, [1.0, 0.0, 0.0]));
    assert!(eq(1.0, 1.0 + f64::EPSILON / 2.0) && !eq(1.0, 1.0 + 4.0 * f64::EPSILON));
}

#[test]
fn primitive_collisions() {
    use super::primitive::*;
    let eye = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let plane = Pose {
        pos: [0.0; 3],
        mat: eye,
        size: [0.0; 3],
    };
    let mut con = [ContactGeom::default(); 4];

    let ball = Pose {
        pos: [0.0, 0.0, 0.08],
        mat: eye,
        size: [0.1, 0.0, 0.0],
    };
    assert_eq!(plane_sphere(&plane.geom(), &ball.geom(), 0.0, &mut con), 1);
    assert!((con[0].dist + 0.02).abs() < 1e-15);
    assert!(close(&con[0].pos, &[0.0, 0.0, -0.01], 1e-15));
    assert_eq!(con[0].frame, [0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);

    // box resting 1 mm into the plane: four corners
    let cube = Pose {
        pos: [0.0, 0.0, 0.099],
        mat: eye,
        size: [0.1; 3],
    };
    assert_eq!(plane_box(&plane.geom(), &cube.geom(), 0.0, &mut con), 4);
    assert!(con.iter().all(|c| (c.dist + 0.001).abs() < 1e-12));

    // vertical capsule: only the lower end touches, tangent along the axis
    let cap = Pose {
        pos: [0.0, 0.0, 0.25],
        mat: eye,
        size: [0.05, 0.2, 0.0],
    };
    assert_eq!(plane_capsule(&plane.geom(), &cap.geom(), 0.01, &mut con), 1);
    assert_eq!(&con[0].frame[3..], &[0.0, 0.0, 1.0]);

    // cylinder standing on its disk: one rim point and two more of the inscribed triangle
    let cyl = Pose {
        pos: [0.0, 0.0, 0.099],
        mat: eye,
        size: [0.2, 0.1, 0.0],
    };
    assert_eq!(plane_cylinder(&plane.geom(), &cyl.geom(), 0.0, &mut con), 3);

    // parallel capsules side by side: two contacts
    let c1 = Pose {
        pos: [0.0; 3],
        mat: eye,
        size: [0.1, 0.3, 0.0],
    };
    let c2 = Pose {
        pos: [0.15, 0.0, 0.0],
        mat: eye,
        size: [0.1, 0.3, 0.0],
    };
    assert_eq!(capsule_capsule(&c1.geom(), &c2.geom(), 0.0, &mut con), 2);
    assert!((con[0].dist + 0.05).abs() < 1e-15 && con[0].normal() == [1.0, 0.0, 0.0]);

    let s = Pose {
        pos: [0.0, 0.12, 0.2],
        mat: eye,
        size: [0.05, 0.0, 0.0],
    };
    assert_eq!(sphere_capsule(&s.geom(), &c1.geom(), 0.0, &mut con), 1);
    assert!((con[0].dist + 0.03).abs() < 1e-15);
    assert_eq!(sphere_sphere(&s.geom(), &ball.geom(), 0.0, &mut con), 0);
}

#[test]
fn box_collisions() {
    use super::boxes::*;
    use super::primitive::*;
    let eye = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let mut con = [ContactGeom::default(); MAX_BOX_CONTACTS];

    // stacked cubes overlapping by 1 cm: four corner contacts; 2.2.2 reports half the depth
    let b1 = Pose {
        pos: [0.0; 3],
        mat: eye,
        size: [0.5; 3],
    };
    let b2 = Pose {
        pos: [0.1, 0.05, 0.69],
        mat: eye,
        size: [0.2; 3],
    };
    let n = box_box(&b1.geom(), &b2.geom(), 0.0, &mut con);
    assert!(n >= 4, "{n}");
    for c in &con[..n] {
        assert!((c.dist + 0.0).abs() <= 0.0101 && c.dist < 0.0, "{c:?}");
        assert!((c.normal()[2].abs() - 1.0).abs() < 1e-12);
    }
    let far = Pose {
        pos: [0.0, 0.0, 2.0],
        ..b2
    };
    assert_eq!(box_box(&b1.geom(), &far.geom(), 0.0, &mut con), 0);

    // sphere resting on a box face, capsule lying on it
    let s = Pose {
        pos: [0.0, 0.0, 0.59],
        mat: eye,
        size: [0.1, 0.0, 0.0],
    };
    assert_eq!(sphere_box(&s.geom(), &b1.geom(), 0.0, &mut con), 1);
    assert!((con[0].dist + 0.01).abs() < 1e-12, "{:?}", con[0]);
    assert!(close(&con[0].normal(), &[0.0, 0.0, -1.0], 1e-15));
    let lying = [1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0];
    let cap = Pose {
        pos: [0.0, 0.0, 0.59],
        mat: lying,
        size: [0.1, 0.2, 0.0],
    };
    assert_eq!(capsule_box(&cap.geom(), &b1.geom(), 0.0, &mut con), 2);
    assert!(con[..2].iter().all(|c| (c.dist + 0.01).abs() < 1e-12));
}

#[test]
fn convex_collisions() {
    use super::convex::*;
    use super::primitive::*;
    let eye = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let opt = MprOptions {
        iterations: 50,
        tolerance: 1e-6,
    };
    let mut con = [ContactGeom::default(); 5];
    let ball = ConvexGeom {
        shape: Shape::Sphere,
        pose: Pose {
            pos: [0.0, 0.0, 0.29],
            mat: eye,
            size: [0.1, 0.0, 0.0],
        },
        rbound: 0.1,
    };
    let block = ConvexGeom {
        shape: Shape::Box,
        pose: Pose {
            pos: [0.0; 3],
            mat: eye,
            size: [0.2; 3],
        },
        rbound: 0.35,
    };
    assert_eq!(convex(&ball, &block, 0.0, &opt, true, &mut con), 1);
    assert!((con[0].dist + 0.01).abs() < 1e-5, "{:?}", con[0]);
    assert!(close(&con[0].normal(), &[0.0, 0.0, -1.0], 1e-6));

    // mesh tetrahedron above a plane, one vertex below it
    let vert: [[f32; 3]; 4] = [
        [0.0, 0.0, -0.05],
        [0.3, 0.0, 0.1],
        [0.0, 0.3, 0.1],
        [0.1, 0.1, 0.3],
    ];
    let tet = ConvexGeom {
        shape: Shape::Mesh(MeshData {
            vert: &vert,
            graph: None,
        }),
        pose: Pose {
            pos: [0.0; 3],
            mat: eye,
            size: [0.0; 3],
        },
        rbound: 0.4,
    };
    let plane = Pose {
        pos: [0.0; 3],
        mat: eye,
        size: [0.0; 3],
    };
    let mut pc = [ContactGeom::default(); 3];
    assert_eq!(plane_convex(&plane.geom(), &tet, 0.0, &mut pc), 1);
    assert_eq!(pc[0].dist, -0.05000000074505806);
    let mut idx = -1;
    assert_eq!(
        support(&tet, &[1.0, 0.0, 0.0], 0.0, &mut idx),
        [0.30000001192092896, 0.0, 0.10000000149011612]
    );
    assert_eq!(idx, 1);
}

#[test]
fn heightfield_collision() {
    use super::convex::*;
    use super::primitive::*;
    let eye = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let data = [0.5f32; 16];
    let hf = HField {
        size: [1.0, 1.0, 0.2, 0.1],
        nrow: 4,
        ncol: 4,
        data: &data,
    };
    let ground = Pose {
        pos: [0.0; 3],
        mat: eye,
        size: [0.0; 3],
    };
    let ball = ConvexGeom {
        shape: Shape::Sphere,
        pose: Pose {
            pos: [0.1, 0.2, 0.19],
            mat: eye,
            size: [0.1, 0.0, 0.0],
        },
        rbound: 0.1,
    };
    let opt = MprOptions {
        iterations: 50,
        tolerance: 1e-6,
    };
    let mut con = [ContactGeom::default(); MAX_CONTACT_PAIR];
    let n = convex_hfield(&hf, &ground.geom(), &ball, 0.0, &opt, &mut con);
    assert!(n >= 1);
    // flat surface at z = 0.1: the sphere sinks 1 cm
    assert!(
        con[..n].iter().all(|c| (c.dist + 0.01).abs() < 1e-5),
        "{:?}",
        &con[..n]
    );
    let high = ConvexGeom {
        pose: Pose {
            pos: [0.1, 0.2, 0.5],
            ..ball.pose
        },
        ..ball
    };
    assert_eq!(
        convex_hfield(&hf, &ground.geom(), &high, 0.0, &opt, &mut con),
        0
    );
}

thread_local! {
    /// Set: the broad phase always sweeps in the principal frame.
    pub static SWEEP_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// Set: the sweep tests the active bodies one at a time.
    pub static SCALAR_SWEEP: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// Times the broad phase found its pairs without the frame.
    pub static FRAMELESS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
    /// Set: the collision loop tests every geom pair one at a time.
    pub static ONE_BY_ONE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// Body pairs and geoms the enclosing-sphere tests skipped.
    pub static SPHERE_SKIPS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
    /// Geom pairs the face-axis tests in body frames skipped.
    pub static FRAME_SKIPS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
    /// Set: no body pair is dropped by its world boxes.
    pub static NO_WORLD_BOXES: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    /// Body pairs dropped by their world boxes.
    pub static WORLD_BOX_SKIPS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// The contacts (as text) of kinematics and collision at qpos `q`, with `switch` off, then on.
fn both_ways(
    data: &mut crate::api::Data,
    q: &[f64],
    switch: &'static std::thread::LocalKey<std::cell::Cell<bool>>,
) -> [Vec<String>; 2] {
    [false, true].map(|on| {
        // (kinematics normalizes the quaternions in qpos)
        data.qpos_mut().copy_from_slice(q);
        switch.with(|f| f.set(on));
        let found = data
            .with_core(|m, d| {
                crate::engine::kinematics::kinematics(m, d)?;
                super::collision(m, d)?;
                let con = &d.contact[..d.raw.ncon as usize];
                Ok(con.iter().map(|c| format!("{c:?}")).collect::<Vec<_>>())
            })
            .unwrap();
        switch.with(|f| f.set(false));
        found
    })
}

/// The collision loop's candidate pairs (found a body and a geom at a time by enclosing
/// spheres, then without branches) give the contacts of the pairs tested one at a time, bit
/// for bit: random poses of four free bodies of several geoms each, from interpenetrating to
/// apart, over world geoms; with the geoms' margins and with the contact override.
#[test]
fn candidate_pairs_give_the_contacts_of_each_pair() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/extra");
    let mut uniform = uniform(777);
    for file in [
        "geom_clusters.xml",
        "geom_clusters_override.xml",
        "geom_large.xml",
    ] {
        let xml = std::fs::read_to_string(dir.join(file)).unwrap();
        let model = crate::api::Model::from_xml_str(&xml).unwrap();
        let mut data = model.make_data().unwrap();
        let (nq, qpos0) = (model.raw().nq as usize, data.qpos().to_vec());
        SPHERE_SKIPS.with(|n| n.set(0));
        FRAME_SKIPS.with(|n| n.set(0));
        let mut touching = 0;
        for k in 0..600 {
            // the bodies spread over a box that shrinks and grows again
            let spread = 0.1 + 0.6 * ((k % 60) as f64 / 60.0);
            let q: Vec<f64> = (0..nq)
                .map(|i| qpos0[i] + spread * (uniform() - 0.5))
                .collect();
            let contacts = both_ways(&mut data, &q, &ONE_BY_ONE);
            assert_eq!(contacts[0], contacts[1]);
            touching += contacts[0].len();
        }
        let skips = SPHERE_SKIPS.with(|n| n.get());
        let frame_skips = FRAME_SKIPS.with(|n| n.get());
        assert!(
            skips > 1000 && frame_skips > 1000 && touching > 1000,
            "{skips} skips, {frame_skips} in body frames, {touching} contacts"
        );
    }
}

/// Body pairs dropped by their world boxes give no contact: the contacts with the test off and
/// on agree bit for bit, on random poses of free bodies of several geoms each, from
/// interpenetrating to apart, with the geoms' margins and with the contact override, and on
/// random joint angles of the Shadow hand (227 mesh geoms) where run-all has fetched it.
#[test]
fn world_boxes_drop_no_contact() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("models/extra");
    let mut files: Vec<_> = [
        "geom_clusters.xml",
        "geom_clusters_override.xml",
        "geom_large.xml",
        "frameless_pairs.xml",
    ]
    .map(|f| dir.join(f))
    .into();
    let hand = root.join(
        "target/third-party/dexterity-0.0.15/dexterity/models/vendor/shadow_robot/\
         shadow_hand_description/mjcf/shadow_hand_series_e.xml",
    );
    files.extend(hand.is_file().then_some(hand));
    let mut uniform = uniform(4242);
    let mut skips = 0;
    for file in &files {
        let model = crate::api::Model::from_xml(file).unwrap();
        let mut data = model.make_data().unwrap();
        let (nq, qpos0) = (model.raw().nq as usize, data.qpos().to_vec());
        let arrays = model.arrays();
        let hinges =
            nq == arrays.jnt_range().len() / 2 && arrays.jnt_limited().iter().all(|&l| l != 0);
        let before = WORLD_BOX_SKIPS.with(|n| n.get());
        let (mut touching, mut near) = (0, 0);
        for k in 0..600 {
            let spread = 0.1 + 0.6 * ((k % 60) as f64 / 60.0);
            let q: Vec<f64> = if hinges {
                // hinge joints across their ranges
                (0..nq)
                    .map(|i| {
                        let r = &arrays.jnt_range()[2 * i..2 * i + 2];
                        r[0] + (r[1] - r[0]) * uniform()
                    })
                    .collect()
            } else {
                (0..nq)
                    .map(|i| qpos0[i] + spread * (uniform() - 0.5))
                    .collect()
            };
            let [with, without] = both_ways(&mut data, &q, &NO_WORLD_BOXES);
            assert_eq!(with, without, "{file:?}");
            touching += with.len();
            near += (!with.is_empty()) as usize;
        }
        let dropped = WORLD_BOX_SKIPS.with(|n| n.get()) - before;
        assert!(
            dropped > 10 && touching > 300 && near > 100,
            "{file:?}: {dropped} body pairs dropped, {touching} contacts in {near} poses"
        );
        skips += dropped;
    }
    assert!(skips > 900, "{skips} body pairs dropped");
}

/// The broad phase's pairs found without the principal frame give the contacts of 2.2.2's
/// sweep, bit for bit: random poses of free bodies and joints on our two test models (self
/// collisions, masks, an exclude, an explicit pair, margins, the contact override), on the
/// first with self collisions masked out, partly and wholly, and on free bodies of several
/// geoms each, visual ones among them (body spheres, pairs left out before listed).
#[test]
fn frameless_broadphase_gives_the_sweeps_contacts() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/extra");
    let pairs = std::fs::read_to_string(dir.join("frameless_pairs.xml")).unwrap();
    let over = std::fs::read_to_string(dir.join("frameless_override.xml")).unwrap();
    let masked = pairs.replace(
        "contype=\"1\" conaffinity=\"1\"",
        "contype=\"1\" conaffinity=\"0\"",
    );
    // no two swept geoms' masks match, the floor's still do
    let apart = masked
        .replace("conaffinity=\"3\"", "conaffinity=\"0\"")
        .replace("conaffinity=\"2\"", "conaffinity=\"0\"")
        .replace(
            "contype=\"2\" conaffinity=\"1\"",
            "contype=\"2\" conaffinity=\"0\"",
        )
        .replace("type=\"plane\"", "type=\"plane\" conaffinity=\"3\"");
    assert!(masked != pairs && apart != masked);
    let mut uniform = uniform(12345);
    let clusters = std::fs::read_to_string(dir.join("geom_clusters.xml")).unwrap();
    for xml in [&pairs, &over, &masked, &apart, &clusters] {
        let model = crate::api::Model::from_xml_str(xml).unwrap();
        let mut data = model.make_data().unwrap();
        let arrays = model.arrays();
        let swept_affinity = (arrays.geom_bodyid().iter().zip(arrays.geom_conaffinity()))
            .filter(|(&b, _)| b != 0)
            .fold(0, |a, (_, &c)| a | c);
        assert_eq!(swept_affinity == 0, std::ptr::eq(xml, &apart));
        let (nq, qpos0) = (model.raw().nq as usize, data.qpos().to_vec());
        FRAMELESS.with(|n| n.set(0));
        let mut touching = 0;
        for _ in 0..400 {
            // poses from resting on one another to well apart
            let q: Vec<f64> = (0..nq)
                .map(|i| qpos0[i] + 0.6 * (uniform() - 0.5))
                .collect();
            let contacts = both_ways(&mut data, &q, &SWEEP_ONLY);
            assert_eq!(contacts[0], contacts[1]);
            touching += contacts[0].len();
        }
        assert!(FRAMELESS.with(|n| n.get()) > 100 && touching > 100);
    }
}

/// The sweep that meets the active bodies four at a time (their bounds and masks beside the
/// list) gives the pair list of the one at a time: random poses of 40 free bodies, of one geom
/// or two, of several masks (and of masks that all meet), packed from overlapping to apart,
/// some on the same spot (equal keys), some with NaN positions (the merge sort's order, bodies
/// whose upper end comes first).
#[test]
fn sweep_four_at_a_time_gives_the_pairs_of_one_at_a_time() {
    let mixed = [(0, 1), (1, 1), (1, 0), (2, 2), (1, 2), (3, 1)];
    for masks in [&mixed[..], &[(1, 1), (3, 1)]] {
        sweep_both_ways(masks);
    }
}

fn sweep_both_ways(masks: &[(i32, i32)]) {
    let mut xml = String::from("<mujoco><worldbody><geom type=\"plane\" size=\"5 5 .1\"/>");
    for b in 0..40 {
        let (t, a) = masks[b % masks.len()];
        xml += &format!("<body pos=\"0 0 {b}\"><freejoint/>");
        xml += &format!("<geom size=\".1\" contype=\"{t}\" conaffinity=\"{a}\"/>");
        if b % 5 == 0 {
            xml += "<geom size=\".05\" pos=\".2 0 0\" contype=\"1\" conaffinity=\"0\"/>";
        }
        xml += "</body>";
    }
    xml += "</worldbody></mujoco>";
    let model = crate::api::Model::from_xml_str(&xml).unwrap();
    let mut data = model.make_data().unwrap();
    let (nq, qpos0) = (model.raw().nq as usize, data.qpos().to_vec());
    let mut uniform = uniform(4242);
    let mut listed = 0;
    for k in 0..300 {
        let spread = 0.2 + 3.0 * ((k % 30) as f64 / 30.0);
        let mut q: Vec<f64> = (0..nq)
            .map(|i| qpos0[i] + spread * (uniform() - 0.5))
            .collect();
        // bodies 1 and 2 on the spot of body 0
        for j in 1..3 {
            let (a, b) = q.split_at_mut(7 * j);
            b[..3].copy_from_slice(&a[..3]);
        }
        if k % 7 == 0 {
            q[7 * (k % 40)] = f64::NAN;
        }
        let pairs = [false, true].map(|scalar| {
            data.qpos_mut().copy_from_slice(&q);
            SWEEP_ONLY.with(|f| f.set(true));
            SCALAR_SWEEP.with(|f| f.set(scalar));
            let found = data
                .with_core(|m, d| {
                    crate::engine::kinematics::kinematics(m, d)?;
                    d.with_scratch(|d, a| {
                        super::broadphase::broadphase(m, d, a).map(|p| p.to_vec())
                    })
                })
                .unwrap();
            SWEEP_ONLY.with(|f| f.set(false));
            SCALAR_SWEEP.with(|f| f.set(false));
            found
        });
        assert_eq!(pairs[0], pairs[1]);
        listed += pairs[0].len();
    }
    // each pose lists the floor's 40 pairs and the swept ones
    assert!(listed > 300 * 40 + 2000, "{listed} pairs");
}

/// The bounding-box test, and the face-axis test of the body frames (`body_frame`), skip a pair
/// only where its routine finds no contact: random pairs of every type pair of geoms with a
/// size, placed around touching (some with parallel faces), with margins.
#[test]
fn bounding_boxes_apart_only_without_contacts() {
    use super::body_frame::{axis_apart, slack};
    use super::bounds::{self, Bound};
    use super::boxes::box_box;
    use super::convex::{self, ConvexGeom, MeshData, MprOptions, Shape};
    use super::primitive::*;
    use crate::engine::geom::*;
    use crate::math::quat::{normalize4, quat2mat};

    let mut seed = 12345u64;
    let mut rnd = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    // a convex mesh: an irregular octahedron, and its bounding radius
    let vert: [[f32; 3]; 6] = [
        [0.3, 0.0, 0.0],
        [-0.2, 0.0, 0.0],
        [0.0, 0.25, 0.0],
        [0.0, -0.15, 0.0],
        [0.0, 0.0, 0.35],
        [0.0, 0.0, -0.1],
    ];
    // its largest |coordinate| per axis (the size the compiler gives its geoms) and radius
    let mesh_aabb = [0.3, 0.25, 0.35];
    let mesh_rbound = norm3(&mesh_aabb);
    let opt = MprOptions {
        iterations: 1000,
        tolerance: 1e-6,
    };
    let types = [SPHERE, CAPSULE, ELLIPSOID, CYLINDER, BOX, MESH];
    let (mut skipped, mut contacts, mut faces) = (0, 0, 0);
    for trial in 0..60000 {
        let (mut t1, mut t2) = (types[trial % 6], types[(trial / 6) % 6]);
        if t1 > t2 {
            (t1, t2) = (t2, t1);
        }
        let mut pose = |shift: f64| {
            let q = [rnd() - 0.5, rnd() - 0.5, rnd() - 0.5, rnd() - 0.5];
            Pose {
                pos: [
                    shift * (rnd() - 0.5),
                    shift * (rnd() - 0.5),
                    shift * (rnd() - 0.5),
                ],
                mat: quat2mat(&normalize4(&q).0),
                size: [0.05 + 0.3 * rnd(), 0.05 + 0.3 * rnd(), 0.05 + 0.3 * rnd()],
            }
        };
        let (mut p1, mut p2) = (pose(0.0), pose(1.2));
        // the same axes (faces parallel, as of geoms in one body's frame)
        if trial % 5 == 0 {
            p2.mat = p1.mat;
        }
        // meshes: sized as compiled (a box test) or not (no test)
        for (t, p) in [(t1, &mut p1), (t2, &mut p2)] {
            if t == MESH && trial % 4 < 2 {
                p.size = mesh_aabb;
            }
        }
        let margin = if trial % 3 == 0 { 0.0 } else { 0.05 * rnd() };
        let shape = |t: i32| match t {
            SPHERE => Shape::Sphere,
            CAPSULE => Shape::Capsule,
            ELLIPSOID => Shape::Ellipsoid,
            CYLINDER => Shape::Cylinder,
            BOX => Shape::Box,
            _ => Shape::Mesh(MeshData {
                vert: &vert,
                graph: None,
            }),
        };
        let rbound = |t: i32, p: &Pose| {
            if t == MESH {
                mesh_rbound
            } else {
                norm3(&bounds::extent(t, &p.size, 0.0).unwrap())
            }
        };
        let bound = |t: i32, p: &Pose| {
            bounds::extent(t, &p.size, rbound(t, p)).map(|h| Bound {
                pos: p.pos,
                mat: p.mat,
                h,
            })
        };
        let mut con = [ContactGeom::default(); convex::MAX_CONTACT_PAIR];
        let (g1, g2) = (&p1.geom(), &p2.geom());
        let n = match (t1, t2) {
            (SPHERE, SPHERE) => sphere_sphere(g1, g2, margin, &mut con),
            (SPHERE, CAPSULE) => sphere_capsule(g1, g2, margin, &mut con),
            (SPHERE, BOX) => sphere_box(g1, g2, margin, &mut con),
            (CAPSULE, CAPSULE) => capsule_capsule(g1, g2, margin, &mut con),
            (CAPSULE, BOX) => capsule_box(g1, g2, margin, &mut con),
            (BOX, BOX) => box_box(g1, g2, margin, &mut con),
            _ => {
                let g = |t: i32, p: &Pose| ConvexGeom {
                    shape: shape(t),
                    pose: *p,
                    rbound: rbound(t, p),
                };
                convex::convex(&g(t1, &p1), &g(t2, &p2), margin, &opt, false, &mut con)
            }
        };
        contacts += (n > 0) as usize;
        // (a geom without a box, a mesh not sized as compiled, is in no test)
        let (Some(b1), Some(b2)) = (bound(t1, &p1), bound(t2, &p2)) else {
            continue;
        };
        if bounds::worth_testing(t1, t2) && bounds::apart(&b1, &b2, margin) {
            skipped += 1;
            assert_eq!(n, 0, "types {t1} {t2}: {p1:?} {p2:?} margin {margin}");
        }
        // the face-axis test of the body frames, with the box's centre at the frame's origin
        for (own, other) in [(&b1, &b2), (&b2, &b1)] {
            let c = mul_mat_t_vec3(&own.mat, &sub3(&other.pos, &own.pos));
            let rot = mul_mat3t_mat(&own.mat, &other.mat).map(f64::abs);
            let e = other.h;
            let r = [0, 1, 2].map(|k| (0..3).map(|j| e[j] * rot[3 * k + j]).sum::<f64>());
            let (h, size) = (own.h, e[0] + e[1] + e[2]);
            let limit = margin + slack(h[0] + h[1] + h[2], &[0.0; 3]) + slack(size, &c);
            if (0..3).any(|k| axis_apart(c[k], h[k] + r[k], limit)) {
                faces += 1;
                assert_eq!(n, 0, "faces of {t1} {t2}: {p1:?} {p2:?} margin {margin}");
            }
        }
    }
    assert!(
        skipped > 5000 && faces > 20000 && contacts > 10000,
        "{skipped} skipped, {faces} apart along faces, {contacts} in contact"
    );

    // edited sizes, and meshes whose size is not their vertices' bound, give no box
    assert!(bounds::extent(BOX, &[0.1, -0.1, 0.1], 0.2).is_none());
    assert!(bounds::extent(CAPSULE, &[f64::NAN, 0.1, 0.0], 0.2).is_none());
    assert!(bounds::extent(MESH, &[0.0; 3], 0.0).is_none());
    // a zero half-size, which box routines take as no bound, gives no box either
    assert!(bounds::extent(BOX, &[0.1, 0.1, 0.0], 0.2).is_none());
    assert!(bounds::extent(SPHERE, &[0.0, 0.0, 0.0], 0.0).is_none());
    assert!(bounds::extent(CYLINDER, &[0.1, f64::NAN, 0.0], 0.2).is_none());
    assert!(bounds::extent(MESH, &mesh_aabb, mesh_rbound * 1.01).is_none());
    assert!(bounds::extent(MESH, &mesh_aabb, f64::INFINITY).is_none());
    assert!(bounds::extent(MESH, &mesh_aabb, f64::NAN).is_none());
    assert_eq!(
        bounds::extent(MESH, &mesh_aabb, mesh_rbound),
        Some(mesh_aabb)
    );
}

/// The capsule-box edge scan as 2.2.2 runs it, one edge at a time with its branches: the
/// reference of `closest_edges`.
fn closest_edges_one_by_one(
    pos: &Vec3,
    halfaxis: &Vec3,
    halflength: f64,
    size2: &Vec3,
    best: &mut super::primitive::Closest,
) {
    for j in 0..3 {
        for i in 0..8usize {
            if i & (1 << j) != 0 {
                continue;
            }
            let sgn = |bit: usize| if i & bit != 0 { 1.0 } else { -1.0 };
            let mut corner = [sgn(1) * size2[0], sgn(2) * size2[1], sgn(4) * size2[2]];
            corner[j] = 0.0;
            let dif = vec3::sub3(&corner, pos);
            let ma = size2[j] * size2[j];
            let mb = -size2[j] * halfaxis[j];
            let mc = halflength * halflength;
            let u = -size2[j] * dif[j];
            let v = vec3::dot3(halfaxis, &dif);
            let det = ma * mc - mb * mb;
            if det.abs() < MINVAL {
                continue;
            }
            let idet = 1.0 / det;
            let mut x1 = (mc * u - mb * v) * idet;
            let mut x2 = (ma * v - mb * u) * idet;
            let (mut s1, mut s2) = (1, 1);
            if x1 > 1.0 {
                x1 = 1.0;
                s1 = 2;
                x2 = (v - mb) * (1.0 / mc);
            } else if x1 < -1.0 {
                x1 = -1.0;
                s1 = 0;
                x2 = (v + mb) * (1.0 / mc);
            }
            let clamp_x1 = |x1: f64, s1: &mut i32| {
                if x1 > 1.0 {
                    *s1 = 2;
                    1.0
                } else if x1 < -1.0 {
                    *s1 = 0;
                    -1.0
                } else {
                    x1
                }
            };
            if x2 > 1.0 {
                x2 = 1.0;
                s2 = 2;
                x1 = clamp_x1((u - mb) * (1.0 / ma), &mut s1);
            } else if x2 < -1.0 {
                x2 = -1.0;
                s2 = 0;
                x1 = clamp_x1((u + mb) * (1.0 / ma), &mut s1);
            }
            let mut d = [
                dif[0] + halfaxis[0] * -x2,
                dif[1] + halfaxis[1] * -x2,
                dif[2] + halfaxis[2] * -x2,
            ];
            d[j] += size2[j] * x1;
            let dist = vec3::dot3(&d, &d);
            let c1 = s1 * 3 + s2;
            if dist < best.dist - MINVAL {
                *best = super::primitive::Closest {
                    dist,
                    segpos: x2,
                    boxpos: x1,
                    cltype: c1,
                    corner: i + (1 << j) * (c1 / 6) as usize,
                    edge: j,
                };
            }
        }
    }
}

/// `closest_edges` (four edges at a time, clamps by selection) finds the edge, positions and
/// distance of the one-edge-at-a-time scan bit for bit: random segments and boxes, axes along
/// the box's (degenerate determinants), zero sizes, starting bests that the edges do or do not
/// beat, and NaN.
#[test]
fn capsule_box_edges_as_one_at_a_time() {
    use super::primitive::{closest_edges, Closest};
    let mut r = uniform(7);
    let mut differ = 0;
    let mut taken = 0;
    // how often each edge code (s1*3 + s2) wins: every clamping combination is exercised
    let mut codes = [0; 10];
    for k in 0..200_000 {
        let mut v = |s: f64| (2.0 * r() - 1.0) * s;
        let pos = [v(1.5), v(1.5), v(1.5)];
        let mut axis = [v(1.0), v(1.0), v(1.0)];
        if k % 7 == 0 {
            axis = [0.0; 3];
            axis[k % 3] = 1.0;
        }
        let n = vec3::norm3(&axis).max(1e-300);
        let halflength = v(1.0).abs();
        let halfaxis = [
            axis[0] / n * halflength,
            axis[1] / n * halflength,
            axis[2] / n * halflength,
        ];
        let mut size2 = [v(1.0).abs(), v(1.0).abs(), v(1.0).abs()];
        if k % 11 == 0 {
            size2[k % 3] = 0.0;
        }
        let start = Closest {
            dist: if k % 5 == 0 { v(0.5).abs() } else { 100.0 },
            segpos: 0.0,
            boxpos: 0.0,
            cltype: -4,
            corner: 0,
            edge: 0,
        };
        let mut pos = pos;
        if k % 997 == 0 {
            pos[k % 3] = f64::NAN;
        }
        let (mut a, mut b) = (start, start);
        closest_edges(&pos, &halfaxis, halflength, &size2, &mut a);
        closest_edges_one_by_one(&pos, &halfaxis, halflength, &size2, &mut b);
        let same = a.dist.to_bits() == b.dist.to_bits()
            && a.segpos.to_bits() == b.segpos.to_bits()
            && a.boxpos.to_bits() == b.boxpos.to_bits()
            && (a.cltype, a.corner, a.edge) == (b.cltype, b.corner, b.edge);
        differ += !same as usize;
        taken += (b.cltype != -4) as usize;
        codes[b.cltype.clamp(-1, 8) as usize + 1] += 1;
    }
    assert_eq!(differ, 0);
    assert!(taken > 100_000, "{taken}");
    assert!(codes[1..].iter().all(|&c| c > 100), "{codes:?}");
}

/// beyond_reach (squares outside a 1e-12 band) decides as the square root does: random
/// distances around the reach, within a few ulps of it or of its square, zeros, the extremes
/// and NaN.
#[test]
fn beyond_reach_as_the_square_root() {
    use super::beyond_reach;
    let mut r = uniform(23);
    let special = [
        0.0,
        -0.0,
        1e-160,
        1e-150,
        1e150,
        1e160,
        f64::MIN_POSITIVE,
        f64::MAX,
        f64::INFINITY,
        f64::NAN,
        -1.0,
    ];
    let mut by_squares = 0;
    for k in 0..2_000_000 {
        let reach = match k % 10 {
            0 => special[(r() * special.len() as f64) as usize % special.len()],
            _ => (10.0f64).powf(12.0 * r() - 6.0),
        };
        let dist = match k % 4 {
            // within a few ulps of the reach
            0 => f64::from_bits((reach.abs().to_bits() as i64 + (r() * 16.0) as i64 - 8) as u64),
            1 => reach * (1.0 + (r() - 0.5) * 1e-11),
            2 => special[(r() * special.len() as f64) as usize % special.len()],
            _ => reach * 4.0 * r(),
        };
        // squares within a few ulps of the reach's square: where a root rounds onto the reach
        let dist2 = match k % 3 {
            0 => f64::from_bits(((reach * reach).to_bits() as i64 + (r() * 8.0) as i64 - 4) as u64),
            _ => dist * dist,
        };
        let want = dist2.sqrt() > reach;
        assert_eq!(
            beyond_reach(dist2, reach),
            want,
            "dist2 {dist2:e} reach {reach:e}"
        );
        let r2 = reach * reach;
        by_squares += (dist2 < r2 * (1.0 - 1e-12) || dist2 > r2 * (1.0 + 1e-12)) as usize;
    }
    assert!(by_squares > 800_000, "{by_squares}");
}
