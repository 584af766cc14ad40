//! The main job (`cargo run --release [model.xml]`): simulates the embedded default model or a
//! given one, printing model name, sizes, steps per second ("steps/s") and the final state.

mod common;
use common::*;

fn main_job(args: &[&str], expect: &str) {
    let bin = std::path::PathBuf::from(env!("CARGO_BIN_EXE_rujoco"));
    let o = run(&bin, args, &[], 300);
    let out = text(&o.stdout);
    report(
        &format!("main-job{}", if args.is_empty() { "" } else { "-model" }),
        &out,
    );
    assert!(
        o.status.success(),
        "rujoco {args:?} failed (exit {:?}):\n{out}{}",
        o.status.code(),
        text(&o.stderr)
    );
    let lower = out.to_lowercase();
    for word in [expect, "nq=", "steps/s", "qpos"] {
        assert!(
            lower.contains(word),
            "rujoco {args:?} output lacks \"{word}\":\n{out}"
        );
    }
}

#[test]
fn default_model() {
    main_job(&[], "chain");
}

#[test]
fn given_model() {
    let pendulum = model("pendulum.xml");
    main_job(&[&pendulum], "pendulum");
}
