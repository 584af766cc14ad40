//! The numerical mju_ utilities (capi-tests/mju_calls.c) on the same pseudo-random inputs
//! through Debian's MuJoCo 2.2.2 and ours: worst relative error |a-b|/max(1,|a|,|b|) per
//! function must stay under 1e-12; text results must match exactly.

mod common;
use common::*;
use std::collections::BTreeMap;

const TOL: f64 = 1e-12;

fn rel_err(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        return if a.is_nan() && b.is_nan() {
            0.0
        } else {
            f64::INFINITY
        };
    }
    if a == b {
        return 0.0;
    }
    if a.is_infinite() || b.is_infinite() {
        return f64::INFINITY;
    }
    (a - b).abs() / 1f64.max(a.abs()).max(b.abs())
}

#[test]
fn mju_utilities_match_reference() {
    require_reference();
    let src = vec![root().join("capi-tests/mju_calls.c")];
    let reference = run(&compile_c(&src, "mju_calls", Lib::Ref), &[], &[], 60);
    assert!(
        reference.status.success(),
        "mju_calls fails with the reference library"
    );
    let ours = run(&compile_c(&src, "mju_calls", Lib::Ours), &[], &[], 60);
    let (r, o) = (text(&reference.stdout), text(&ours.stdout));
    assert!(
        ours.status.success(),
        "mju_calls fails with ours (exit {:?}):\n{}",
        ours.status.code(),
        o.lines().rev().take(5).collect::<Vec<_>>().join("\n")
    );
    let mut worst: BTreeMap<String, (f64, String)> = BTreeMap::new();
    let (mut identical, total) = (0, r.lines().count());
    for (i, (a, b)) in r
        .lines()
        .zip(o.lines().chain(std::iter::repeat("")))
        .enumerate()
    {
        let name = a.split('#').next().unwrap_or("").to_string();
        let e = if a == b {
            identical += 1;
            0.0
        } else {
            let (mut wa, mut wb) = (a.split_whitespace(), b.split_whitespace());
            let (ta, tb) = (wa.next(), wb.next());
            let na: Vec<f64> = wa.map(|t| t.parse().unwrap_or(f64::NAN)).collect();
            let nb: Vec<f64> = wb.map(|t| t.parse().unwrap_or(f64::NAN)).collect();
            if ta != tb || na.len() != nb.len() || na.iter().any(|x| x.is_nan()) {
                f64::INFINITY
            } else {
                na.iter()
                    .zip(&nb)
                    .map(|(&x, &y)| rel_err(x, y))
                    .fold(0.0, f64::max)
            }
        };
        let w = worst.entry(name).or_insert((0.0, String::new()));
        if e > w.0 {
            *w = (e, format!("line {}: ref {a} | ours {b}", i + 1));
        }
    }
    let failing: Vec<String> = worst
        .iter()
        .filter(|(_, (e, _))| e.is_nan() || *e > TOL)
        .map(|(n, (e, at))| format!("  {n}: {e:.2e}  {at}"))
        .collect();
    let max = worst.values().map(|w| w.0).fold(0.0, f64::max);
    let msg = format!(
        "mju: {} functions, {identical} of {total} result lines bit-identical, worst relative error {max:.2e}, {} functions over {TOL:e}\n",
        worst.len(),
        failing.len()
    );
    report("mju", &msg);
    assert!(failing.is_empty(), "{msg}{}", failing.join("\n"));
}
