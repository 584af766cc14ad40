//! Debian's prebuilt `mujoco-simulate` and `mujoco-basic` (GLFW windows, GLX) under Xvfb on
//! rujoco and on 2.2.2: a scripted sequence of mouse and key events through xdotool, the window
//! captured after each (xwd) must be byte-identical. The model is the three-link arm, whose
//! hinges turn about the gravity axis: it stays at rest, so every frame is the same whenever it
//! is drawn and the captures do not depend on timing.

mod common;

use common::*;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

const SIMULATE: &str = "/usr/bin/mujoco-simulate";
const BASIC: &str = "/usr/bin/mujoco-basic";

fn require_tools() {
    require_reference();
    our_lib();
    for (path, package) in [
        (SIMULATE, "libmujoco-samples"),
        (BASIC, "libmujoco-samples"),
        ("/usr/bin/xdotool", "xdotool"),
        ("/usr/bin/xwd", "x11-apps"),
    ] {
        assert!(
            Path::new(path).exists(),
            "{path} missing: install {package} (capi-tests/run-all does it)"
        );
    }
}

fn xdotool(display: &str, args: &[&str]) -> String {
    let o = Command::new("timeout")
        .arg("30")
        .arg("xdotool")
        .args(args)
        .env("DISPLAY", display)
        .output()
        .unwrap();
    text(&o.stdout)
}

/// The window's content as xwd writes it, less its header (which names the window).
fn capture(display: &str, window: &str) -> Vec<u8> {
    let o = Command::new("timeout")
        .args(["30", "xwd", "-silent", "-id", window])
        .env("DISPLAY", display)
        .output()
        .unwrap();
    assert!(o.status.success(), "xwd failed: {}", text(&o.stderr));
    let header = u32::from_be_bytes(o.stdout[..4].try_into().unwrap()) as usize;
    o.stdout[header.min(o.stdout.len())..].to_vec()
}

fn fnv(b: &[u8]) -> u64 {
    b.iter().fold(0xcbf29ce484222325u64, |h, &x| {
        (h ^ x as u64).wrapping_mul(0x100000001b3)
    })
}

/// `program` on the arm under a fresh X server, once its window shows: the server, the
/// program and the window id; else the program's exit status and output (it stopped first).
fn launch(program: &str, lib: Lib) -> Result<(Xvfb, std::process::Child, String), String> {
    let x = Xvfb::start();
    let libdir = lib_dir();
    let mut cmd = Command::new(program);
    cmd.arg(model("arm3.xml"))
        .env("DISPLAY", &x.display)
        .env_remove("LD_LIBRARY_PATH")
        .current_dir(work_dir("simulate"))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    if lib == Lib::Ours {
        cmd.env("LD_LIBRARY_PATH", &libdir);
    }
    let mut child = cmd.spawn().unwrap();
    for _ in 0..300 {
        let window = xdotool(&x.display, &["search", "--onlyvisible", "--name", "."])
            .lines()
            .next()
            .unwrap_or("")
            .to_string();
        if !window.is_empty() {
            return Ok((x, child, window));
        }
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let _ = child.kill();
    let o = child.wait_with_output().unwrap();
    Err(format!(
        "no window in 30 s ({}): {}{}",
        o.status,
        text(&o.stdout),
        text(&o.stderr)
    ))
}

/// Runs `program` on the arm under a fresh X server, plays `script` (name, xdotool arguments
/// with WIN for the window), and returns a hash of the window after each step. A program that
/// stops before its window shows gets a second start on a new server (GLFW has once failed to
/// open a just-started Xvfb, on either library); a second failure fails the test.
fn play(program: &str, lib: Lib, script: &[(&str, Vec<&str>)]) -> Vec<(String, u64)> {
    let (x, mut child, window) = match launch(program, lib) {
        Ok(started) => started,
        Err(first) => {
            eprintln!("{program} on {lib:?}: {first}; starting it again");
            launch(program, lib).unwrap_or_else(|e| panic!("{program} on {lib:?}: {e}"))
        }
    };
    std::thread::sleep(Duration::from_secs(3));
    let mut out = Vec::new();
    for (name, args) in script {
        let args: Vec<&str> = args
            .iter()
            .map(|a| if *a == "WIN" { window.as_str() } else { a })
            .collect();
        if !args.is_empty() {
            xdotool(&x.display, &args);
        }
        std::thread::sleep(Duration::from_millis(400));
        assert!(
            child.try_wait().unwrap().is_none(),
            "{program} on {lib:?} stopped at step {name}"
        );
        let image = capture(&x.display, &window);
        if let Some(dir) = std::env::var_os("RUJOCO_CAPTURES") {
            let file = format!(
                "{}-{lib:?}-{}.xwd-data",
                out.len(),
                program.rsplit('/').next().unwrap()
            );
            std::fs::write(Path::new(&dir).join(file), &image).unwrap();
        }
        out.push((name.to_string(), fnv(&image)));
    }
    let _ = child.kill();
    let o = child.wait_with_output().unwrap();
    let stderr = text(&o.stderr);
    assert!(
        !stderr.contains("ERROR") && !stderr.contains("rror:"),
        "{program} on {lib:?}: {stderr}"
    );
    out
}

fn compare(name: &str, program: &str, script: &[(&str, Vec<&str>)]) {
    // one program at a time: the captures wait on the window, not on a loaded machine
    static ONE: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _one = ONE.lock().unwrap_or_else(|e| e.into_inner());
    require_tools();
    let reference = play(program, Lib::Ref, script);
    let ours = play(program, Lib::Ours, script);
    let distinct = {
        let mut h: Vec<u64> = reference.iter().map(|x| x.1).collect();
        h.sort();
        h.dedup();
        h.len()
    };
    let differ: Vec<String> = reference
        .iter()
        .zip(&ours)
        .filter(|(a, b)| a != b)
        .map(|(a, _)| a.0.clone())
        .collect();
    report(
        name,
        &format!(
            "{program} under Xvfb: {} captures ({distinct} distinct), {} differ {differ:?}\n",
            reference.len(),
            differ.len()
        ),
    );
    assert!(
        differ.is_empty(),
        "{program}: captures differ after {differ:?}"
    );
    assert!(
        distinct * 2 > reference.len(),
        "the script changed too little: {distinct} distinct"
    );
}

fn click(x: &'static str, y: &'static str) -> Vec<&'static str> {
    vec!["mousemove", "--window", "WIN", x, y, "click", "1"]
}

fn key(k: &'static str) -> Vec<&'static str> {
    vec!["key", "--window", "WIN", k]
}

#[test]
fn simulate_matches_reference() {
    // positions in the 853x682 window simulate opens on a 1280x1024 screen
    let script: Vec<(&str, Vec<&str>)> = vec![
        ("start", vec![]),
        ("collapse file", click("60", "20")),
        ("collapse option", click("60", "55")),
        ("collapse simulation", click("60", "89")),
        ("expand physics", click("60", "157")),
        ("expand joint", click("650", "20")),
        ("expand control", click("650", "149")),
        ("pause", key("space")),
        (
            "open integrator list",
            vec![
                "mousemove",
                "--window",
                "WIN",
                "177",
                "187",
                "mousedown",
                "1",
            ],
        ),
        (
            "choose integrator",
            vec!["mousemove", "--window", "WIN", "177", "247", "mouseup", "1"],
        ),
        ("edit timestep", click("177", "371")),
        (
            "type",
            vec!["key", "--window", "WIN", "End", "BackSpace", "1"],
        ),
        ("commit", key("Return")),
        (
            "drag control slider",
            vec![
                "mousemove",
                "--window",
                "WIN",
                "720",
                "209",
                "mousedown",
                "1",
                "mousemove",
                "--window",
                "WIN",
                "760",
                "209",
                "mousemove",
                "--window",
                "WIN",
                "790",
                "210",
                "mouseup",
                "1",
            ],
        ),
        (
            "zoom out",
            vec![
                "mousemove",
                "--window",
                "WIN",
                "430",
                "300",
                "click",
                "5",
                "click",
                "5",
                "click",
                "5",
            ],
        ),
        (
            "zoom out more",
            vec!["click", "5", "click", "5", "click", "5", "click", "5"],
        ),
        ("help", key("F1")),
        ("help off", key("F1")),
        ("sensor figure", key("F4")),
        ("sensor off", key("F4")),
        ("wireframe", key("w")),
        ("shadows off", key("s")),
        ("joints", key("j")),
        ("inertia", key("i")),
        ("segmentation", key("comma")),
        ("no left panel", key("Tab")),
        ("no right panel", key("shift+Tab")),
        (
            "both panels",
            vec!["key", "--window", "WIN", "Tab", "shift+Tab"],
        ),
    ];
    compare("simulate", SIMULATE, &script);
}

#[test]
fn basic_matches_reference() {
    let script: Vec<(&str, Vec<&str>)> = vec![
        ("start", vec![]),
        (
            "zoom",
            vec![
                "mousemove",
                "--window",
                "WIN",
                "400",
                "300",
                "click",
                "5",
                "click",
                "5",
            ],
        ),
        (
            "zoom in",
            vec!["click", "4", "click", "4", "click", "4", "click", "4"],
        ),
        ("reset", key("BackSpace")),
    ];
    compare("basic", BASIC, &script);
}
