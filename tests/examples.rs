//! The C examples (examples/*.c), each compiled against Debian's MuJoCo 2.2.2 and against
//! ours: both runs must succeed with identical printed output.

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
