//! ABI checks: struct layout against Debian's 2.2.2 headers, exported symbols and SONAME of
//! the built library, headers up to date with the build, and how much is still pending.

mod common;
use common::*;
use std::collections::BTreeSet;
use std::process::Command;

#[test]
fn layout_matches_reference() {
    require_reference();
    let src = vec![root().join("capi-tests/layout.c")];
    let reference = run(&compile_c(&src, "layout", Lib::Ref), &[], &[], 30);
    let ours = run(&compile_c(&src, "layout", Lib::Ours), &[], &[], 30);
    assert!(reference.status.success() && ours.status.success());
    let (r, o) = (text(&reference.stdout), text(&ours.stdout));
    let rl: Vec<&str> = r.lines().collect();
    let ol: Vec<&str> = o.lines().collect();
    let mut diffs = Vec::new();
    for i in 0..rl.len().max(ol.len()) {
        let (a, b) = (
            rl.get(i).copied().unwrap_or("<none>"),
            ol.get(i).copied().unwrap_or("<none>"),
        );
        if a != b {
            diffs.push(format!("  reference: {a}\n  ours:      {b}"));
        }
    }
    report(
        "layout",
        &format!(
            "layout: {} lines compared, {} differ\n",
            rl.len(),
            diffs.len()
        ),
    );
    assert!(
        diffs.is_empty(),
        "{} layout lines differ:\n{}",
        diffs.len(),
        diffs.join("\n")
    );
    assert!(
        rl.len() > 800,
        "layout program printed only {} lines",
        rl.len()
    );
}

/// Every function and variable of 2.2.2's mujoco.h is declared by our mujoco.h with the same
/// type (capi-tests/api_decls.c, compiled with -Werror).
#[test]
fn declarations_match_reference() {
    let compile = |include: Option<std::path::PathBuf>| {
        let mut cmd = Command::new("gcc");
        cmd.args(["-std=c11", "-Wall", "-Werror", "-fsyntax-only"]);
        if let Some(i) = include {
            cmd.arg("-I").arg(i);
        }
        cmd.arg(root().join("capi-tests/api_decls.c"));
        cmd.output()
            .expect("gcc not found: install build-essential")
    };
    require_reference();
    let reference = compile(None);
    assert!(
        reference.status.success(),
        "api_decls.c fails with the reference headers:\n{}",
        text(&reference.stderr)
    );
    let ours = compile(Some(root().join("include")));
    let errors: Vec<String> = text(&ours.stderr)
        .lines()
        .filter(|l| l.contains("error"))
        .map(String::from)
        .collect();
    report(
        "declarations",
        &format!(
            "declarations: {} errors against our mujoco.h\n",
            errors.len()
        ),
    );
    assert!(
        ours.status.success(),
        "our include/mujoco/mujoco.h lacks or mistypes {} declarations of 2.2.2:\n{}",
        errors.len(),
        errors.join("\n")
    );
}

/// API symbols a library defines (nm -D --defined-only), with their nm type letter.
fn api_symbols(lib: &std::path::Path) -> Vec<(String, char)> {
    let o = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(lib)
        .output()
        .expect("nm (binutils) missing");
    assert!(o.status.success(), "nm failed on {}", lib.display());
    let api = |n: &str| {
        [
            "mj_",
            "mju_",
            "mjd_",
            "mjv_",
            "mjr_",
            "mjui_",
            "mjcb_",
            "_mjPRIVATE_",
            "mjCOLLISIONFUNC",
        ]
        .iter()
        .any(|p| n.starts_with(p))
            || (n.starts_with("mj") && n.ends_with("STRING"))
    };
    text(&o.stdout)
        .lines()
        .filter_map(|l| {
            let mut w = l.split_whitespace().rev();
            let name = w.next()?;
            let kind = w.next()?.chars().next()?;
            let name = name.split('@').next().unwrap().to_string();
            api(&name).then_some((name, kind))
        })
        .collect()
}

#[test]
fn exports_every_reference_symbol() {
    require_reference();
    let reference: BTreeSet<String> = api_symbols(REF_LIB.as_ref())
        .into_iter()
        .map(|s| s.0)
        .collect();
    let ours: BTreeSet<String> = api_symbols(&our_lib()).into_iter().map(|s| s.0).collect();
    if let Some(v3) = our_v3_lib() {
        let same = api_symbols(&v3)
            .into_iter()
            .map(|s| s.0)
            .collect::<BTreeSet<_>>()
            == ours;
        assert!(same, "the x86-64-v3 build exports other symbols");
    }
    let missing: Vec<&String> = reference.difference(&ours).collect();
    report(
        "symbols",
        &format!(
            "symbols: reference exports {} API symbols, ours {}, missing {}\n",
            reference.len(),
            ours.len(),
            missing.len()
        ),
    );
    assert!(
        missing.is_empty(),
        "{} symbols of libmujoco 2.2.2 not exported by ours: {missing:?}",
        missing.len()
    );
}

#[test]
fn soname_is_2_2_2() {
    for lib in std::iter::once(our_lib()).chain(our_v3_lib()) {
        let o = Command::new("readelf")
            .arg("-d")
            .arg(&lib)
            .output()
            .expect("readelf (binutils) missing");
        let t = text(&o.stdout);
        assert!(
            t.contains("Library soname: [libmujoco.so.2.2.2]"),
            "SONAME of {} is not libmujoco.so.2.2.2:\n{t}",
            lib.display()
        );
    }
    assert!(
        lib_dir().join("libmujoco.so.2.2.2").exists(),
        "target/release/libmujoco.so.2.2.2 link missing"
    );
}

/// Informational: exported functions implemented vs still calling pending() anywhere in the
/// C shell.
#[test]
fn pending_count() {
    let mut pending = 0;
    for f in std::fs::read_dir(root().join("src/capi")).unwrap() {
        let p = f.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        if name.ends_with(".rs") {
            pending += std::fs::read_to_string(&p)
                .unwrap()
                .matches("pending(\"")
                .count();
        }
    }
    let functions = api_symbols(&our_lib())
        .iter()
        .filter(|s| s.1 == 'T')
        .count();
    let msg = format!(
        "pending: {} of {} exported functions implemented, {} still pending\n",
        functions.saturating_sub(pending),
        functions,
        pending
    );
    eprint!("{msg}");
    report("pending", &msg);
}

/// The generated headers in include/ are committed as the build writes them.
#[test]
fn headers_are_fresh() {
    let inside = Command::new("git")
        .args(["rev-parse", "--is-inside-work-tree"])
        .current_dir(root())
        .output();
    if !matches!(inside, Ok(ref o) if o.status.success()) {
        eprintln!("headers_are_fresh: skipped, not a git checkout");
        return;
    }
    let o = Command::new("git")
        .args(["diff", "--exit-code", "--", "include/"])
        .current_dir(root())
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "include/ differs from the committed headers after the build: commit the regenerated headers\n{}",
        text(&o.stdout)
    );
}

/// Our mujoco.h declares exactly the functions 2.2.2's declares: no more (internal exports
/// such as mj_stepSkip stay out of it, as in 2.2.2), no fewer.
#[test]
fn header_declares_the_same_functions() {
    require_reference();
    let names = |path: std::path::PathBuf| -> std::collections::BTreeSet<String> {
        let text = std::fs::read_to_string(&path).unwrap();
        let mut set = std::collections::BTreeSet::new();
        for (i, _) in text.match_indices('(') {
            let head = &text[..i];
            let start = head
                .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .map_or(0, |p| p + 1);
            let name = &head[start..];
            if ["mj_", "mju_", "mjd_"].iter().any(|p| name.starts_with(p)) {
                set.insert(name.to_string());
            }
        }
        set
    };
    let reference = names(std::path::PathBuf::from(REF_INCLUDE));
    let ours = names(root().join("include/mujoco/mujoco.h"));
    let extra: Vec<_> = ours.difference(&reference).collect();
    let missing: Vec<_> = reference.difference(&ours).collect();
    assert!(
        extra.is_empty() && missing.is_empty(),
        "mujoco.h differs from 2.2.2's: extra {extra:?}, missing {missing:?}"
    );
}
