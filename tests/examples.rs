//! The C examples (examples/*.c), each compiled against Debian's MuJoCo 2.2.2 and against
//! ours: both runs must succeed with identical printed output; the Rust example
//! (examples/arm_ik.rs) must print what its C counterparts print on the reference.

mod common;
use common::*;

fn example(name: &str, model_file: &str) {
    let model_path = model(model_file);
    let args = [model_path.as_str()];
    require_reference();
    let src = vec![root().join("examples").join(format!("{name}.c"))];
    let reference = run(&compile_c(&src, name, Lib::Ref), &args, &[], 120);
    assert!(
        reference.status.success(),
        "{name} fails with the reference library:\n{}{}",
        text(&reference.stdout),
        text(&reference.stderr)
    );
    let ours = run(&compile_c(&src, name, Lib::Ours), &args, &[], 120);
    let (r, o) = (text(&reference.stdout), text(&ours.stdout));
    report(
        &format!("example-{name}"),
        &format!("example {name} (ours, exit {:?}):\n{o}", ours.status.code()),
    );
    assert!(
        ours.status.success() && r == o,
        "{name}: output with ours (exit status {:?}) differs from the reference.\n--- reference\n{r}--- ours\n{o}{}",
        ours.status.code(),
        text(&ours.stderr)
    );
}

#[test]
fn pendulum() {
    example("pendulum", "pendulum.xml");
}

#[test]
fn arm_forward_kinematics() {
    example("arm_fk", "arm3.xml");
}

#[test]
fn arm_inverse_kinematics() {
    example("arm_ik", "arm3.xml");
}

#[test]
fn arm_ik_pd_tracking() {
    example("arm_track", "arm3.xml");
}

/// The Rust example (examples/arm_ik.rs, compiled into this test over the crate's Rust API)
/// prints what the C example prints on the reference library.
#[path = "../examples/arm_ik.rs"]
mod arm_ik_rust;

fn rust_example(c_name: &str, extra: &[&str]) {
    require_reference();
    let model_path = model("arm3.xml");
    let src = vec![root().join("examples").join(format!("{c_name}.c"))];
    let reference = run(
        // its own executable name: the C example tests compile theirs at the same time
        &compile_c(&src, &format!("{c_name}-vs-rust"), Lib::Ref),
        &[model_path.as_str()],
        &[],
        120,
    );
    assert!(
        reference.status.success(),
        "{c_name} fails with the reference library"
    );
    let mut args: Vec<String> = extra.iter().map(|s| s.to_string()).collect();
    args.push(model_path.clone());
    let mut out = Vec::new();
    let status = arm_ik_rust::run(&args, &mut out);
    let (r, o) = (text(&reference.stdout), text(&out));
    report(
        &format!("example-rust-{c_name}"),
        &format!("Rust example arm_ik {extra:?} (exit {status}):\n{o}"),
    );
    assert!(
        status == 0 && r == o,
        "Rust arm_ik {extra:?} (exit {status}) differs from {c_name}.c on the reference.\n--- reference\n{r}--- rust\n{o}"
    );
}

#[test]
fn rust_arm_ik_prints_the_c_examples_output() {
    rust_example("arm_ik", &[]);
}

#[test]
fn rust_arm_ik_tracking_prints_the_c_examples_output() {
    rust_example("arm_track", &["--track"]);
}
