//! Debian's prebuilt `mujoco-record` (GLFW with an invisible window, GLX) under Xvfb with Mesa's
//! software renderer, on models with textures, meshes, skins, height fields and transparency:
//! the raw RGB frames it writes, with their time overlay, are byte-identical on rujoco and on
//! 2.2.2.

mod common;

use common::*;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

const RECORD: &str = "/usr/bin/mujoco-record";

/// An X server on a free display, stopped when dropped.
pub struct Xvfb {
    child: Child,
    pub display: String,
}

impl Xvfb {
    pub fn start() -> Xvfb {
        assert!(
            Command::new("sh")
                .args(["-c", "command -v Xvfb"])
                .stdout(Stdio::null())
                .status()
                .unwrap()
                .success(),
            "Xvfb missing: install xvfb (capi-tests/run-all does it)"
        );
        for n in 0..50 {
            let num = 150 + (std::process::id() as usize + n) % 400;
            let socket = format!("/tmp/.X11-unix/X{num}");
            if Path::new(&socket).exists() || Path::new(&format!("/tmp/.X{num}-lock")).exists() {
                continue;
            }
            let mut child = Command::new("Xvfb")
                .arg(format!(":{num}"))
                .args(["-screen", "0", "1280x1024x24", "-nolisten", "tcp"])
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .expect("cannot start Xvfb");
            for _ in 0..100 {
                if Path::new(&socket).exists() {
                    return Xvfb {
                        child,
                        display: format!(":{num}"),
                    };
                }
                if let Ok(Some(_)) = child.try_wait() {
                    break;
                }
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            let _ = child.kill();
            let _ = child.wait();
        }
        panic!("could not start Xvfb on a free display");
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn corpus_model(rel: &str) -> Option<PathBuf> {
    corpus_dirs()
        .iter()
        .map(|d| d.join(rel))
        .find(|p| p.exists())
}

/// Records `model` for `seconds` on one library; returns the frames' bytes.
fn record(model: &str, seconds: &str, lib: Lib, display: &str, out: &Path) -> Vec<u8> {
    let _ = std::fs::remove_file(out);
    let libdir = lib_dir().to_string_lossy().into_owned();
    let mut envs = vec![("DISPLAY", display), ("MUJOCO_GL", "glfw")];
    if lib == Lib::Ours {
        envs.push(("LD_LIBRARY_PATH", &libdir));
    }
    let o = run(
        Path::new(RECORD),
        &[model, seconds, "30", &out.to_string_lossy()],
        &envs,
        600,
    );
    // record.cc ends main with `return 1` after a complete recording
    assert!(
        o.status.code() == Some(1) && o.stderr.is_empty(),
        "mujoco-record {model} on {lib:?} failed: {}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    std::fs::read(out).unwrap()
}

#[test]
fn record_frames_match_reference() {
    require_reference();
    our_lib();
    assert!(
        Path::new(RECORD).exists(),
        "{RECORD} missing: install libmujoco-samples (capi-tests/run-all does it)"
    );
    let mut models: Vec<(String, &str)> = vec![(model("arm3.xml"), "1")];
    for (rel, seconds) in [
        ("mujoco-2.2.2/model/humanoid/humanoid.xml", "1"), // shadows, reflection, skybox
        ("mujoco-2.2.2/model/mug/mug.xml", "0.5"),         // mesh, 2D texture from PNG
        ("mujoco-2.2.2/model/flag/flag.xml", "0.5"),       // skin, composite
        ("dm_control-1.0.7/suite/quadruped.xml", "0.5"),   // height field
        ("dm_control-1.0.7/suite/dog.xml", "0.3"),         // skin, meshes, textures
        ("dm_control-1.0.7/suite/fish.xml", "0.5"),        // transparency, fluid
    ] {
        if let Some(p) = corpus_model(rel) {
            models.push((p.to_string_lossy().into_owned(), seconds));
        }
    }
    let x = Xvfb::start();
    let dir = work_dir("record");
    let mut lines = String::new();
    let mut bytes = 0;
    for (i, (m, seconds)) in models.iter().enumerate() {
        let reference = record(
            m,
            seconds,
            Lib::Ref,
            &x.display,
            &dir.join(format!("{i}-ref")),
        );
        let ours = record(
            m,
            seconds,
            Lib::Ours,
            &x.display,
            &dir.join(format!("{i}-ours")),
        );
        assert!(!reference.is_empty(), "{m}: nothing recorded");
        assert_eq!(
            ours.len(),
            reference.len(),
            "{m}: {} bytes recorded on ours, {} on 2.2.2",
            ours.len(),
            reference.len()
        );
        let first = ours.iter().zip(&reference).position(|(a, b)| a != b);
        assert!(
            first.is_none(),
            "{m}: the recordings differ from byte {first:?} on"
        );
        let n = reference.len();
        bytes += n;
        for lib in ["ref", "ours"] {
            let _ = std::fs::remove_file(dir.join(format!("{i}-{lib}")));
        }
        lines.push_str(&format!(
            "  {m} ({seconds} s at 30 fps): {n} bytes identical\n"
        ));
    }
    report(
        "record",
        &format!(
            "mujoco-record under Xvfb (GLX): {} models, {bytes} bytes of frames byte-identical\n{lines}",
            models.len()
        ),
    );
    assert!(models.len() >= 4, "only {} models recorded", models.len());
}
