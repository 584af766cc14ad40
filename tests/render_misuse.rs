//! Bad use of the OpenGL layer against 2.2.2 (capi-tests/render_misuse.c): every mjr_ entry
//! point and mjui_update/mjui_render with no current OpenGL context, contexts too old (Mesa's
//! version and extension overrides), contexts made or freed twice, sizes over the
//! implementation's limits, bad indices, NULL and empty buffers. Each case runs in a forked
//! child. Ours must print what 2.2.2 prints, case by case, except where 2.2.2 crashes (its
//! child dies of a signal) or does something undefined (cases marked "[ub]"): there ours must
//! report an error through mju_error and end normally.

mod common;

use common::*;
use std::path::PathBuf;

/// The test program against one library; `platform`: linked with OSMesa (else built with
/// NO_PLATFORM, no OpenGL platform library in the process).
fn compile(lib: Lib, platform: bool) -> PathBuf {
    let (name, flags) = if platform {
        ("render_misuse", ["-lOSMesa", "-Werror"])
    } else {
        ("render_misuse-noplatform", ["-DNO_PLATFORM", "-Werror"])
    };
    compile_gl("capi-tests/render_misuse.c", name, lib, &flags)
}

/// One case's output: its header line and the lines after it.
struct Case {
    header: String,
    lines: Vec<String>,
}

impl Case {
    fn name(&self) -> &str {
        self.header.trim_start_matches("case ")
    }
    fn undefined(&self) -> bool {
        self.header.ends_with(" [ub]")
    }
    fn crashed(&self) -> bool {
        self.lines.iter().any(|l| l.starts_with("  result: signal"))
    }
    fn clean_error(&self) -> bool {
        self.lines.iter().any(|l| l.starts_with("  error: "))
            && self.lines.last().map(String::as_str) == Some("  result: exit 0")
    }
}

fn cases(out: &str) -> Vec<Case> {
    let mut all: Vec<Case> = Vec::new();
    for line in out.lines() {
        if line.starts_with("case ") {
            all.push(Case {
                header: line.to_string(),
                lines: Vec::new(),
            });
        } else if let Some(c) = all.last_mut() {
            c.lines.push(line.to_string());
        }
    }
    all
}

#[derive(Default)]
struct Tally {
    identical: usize,
    crash: usize,
    undefined: usize,
    table: String,
}

/// Compares the two libraries' outputs case by case; returns the failures.
fn compare(reference: &str, ours: &str, tally: &mut Tally) -> Vec<String> {
    let (r, o) = (cases(reference), cases(ours));
    let mut failures = Vec::new();
    if r.len() != o.len() {
        failures.push(format!("{} cases in 2.2.2, {} in ours", r.len(), o.len()));
    }
    for (a, b) in r.iter().zip(&o) {
        if a.header != b.header {
            failures.push(format!("case order differs: {} / {}", a.header, b.header));
            continue;
        }
        let first = |c: &Case| {
            c.lines
                .iter()
                .find(|l| l.starts_with("  error") || l.starts_with("  warning"))
                .cloned()
                .unwrap_or_else(|| c.lines.first().cloned().unwrap_or_default())
        };
        if a.crashed() || a.undefined() {
            let what = if a.crashed() { "crashes" } else { "undefined" };
            if b.clean_error() {
                if a.crashed() {
                    tally.crash += 1;
                } else {
                    tally.undefined += 1;
                }
                tally.table.push_str(&format!(
                    "{}: 2.2.2 {what}; ours {}\n",
                    a.name(),
                    first(b).trim()
                ));
            } else {
                failures.push(format!(
                    "{}: 2.2.2 {what}, ours does not end with a clean error:\n{}",
                    a.name(),
                    b.lines.join("\n")
                ));
            }
            continue;
        }
        if a.lines == b.lines {
            tally.identical += 1;
            tally
                .table
                .push_str(&format!("{}: identical; {}\n", a.name(), first(a).trim()));
        } else {
            failures.push(format!(
                "{} differs\n 2.2.2:\n{}\n ours:\n{}",
                a.name(),
                a.lines.join("\n"),
                b.lines.join("\n")
            ));
        }
    }
    failures
}

#[test]
fn misuse_matches_reference() {
    require_osmesa();
    let mut tally = Tally::default();
    let mut failures = Vec::new();
    // the four programs (library, platform) built and run side by side
    let programs = [
        (Lib::Ref, true),
        (Lib::Ours, true),
        (Lib::Ref, false),
        (Lib::Ours, false),
    ];
    let outputs = par_map(&programs, |_, &(lib, platform)| {
        text(&run(&compile(lib, platform), &[], &[], 600).stdout)
    });
    for (pair, platform) in outputs.chunks(2).zip([true, false]) {
        let (reference, ours) = (&pair[0], &pair[1]);
        assert!(reference.contains("case "), "no output from 2.2.2");
        let label = if platform {
            ""
        } else {
            "no platform library: "
        };
        tally.table.push_str(&format!("-- {label}\n"));
        failures.extend(compare(reference, ours, &mut tally));
    }
    let summary = format!(
        "{} cases identical to 2.2.2; {} where 2.2.2 crashes and {} where it is undefined end \
         with a clean mju_error in ours\n",
        tally.identical, tally.crash, tally.undefined
    );
    report("render-misuse", &format!("{summary}{}", tally.table));
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    eprint!("{summary}");
}
