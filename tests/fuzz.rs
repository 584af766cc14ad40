//! Fuzzing entry points under the test suite, for a bounded time: the cargo-fuzz targets' bodies
//! (fuzz/bodies.rs: MJCF, MJB, STL, OBJ, MSH, PNG and URDF through the C API's loaders, then
//! steps) run over their seeds (fuzz/seeds) and deterministic mutations of them for a few
//! seconds each, in this process, after the inputs libFuzzer once found crashing
//! (fuzz/regressions): a crash, abort or hang fails the test. For coverage-guided
//! runs of any length with libFuzzer: `cargo +nightly fuzz run TARGET` in fuzz/ (README).

#[path = "../fuzz/bodies.rs"]
mod bodies;
mod common;
use common::*;
use std::time::{Duration, Instant};

/// Seconds per target.
const SECONDS: f64 = 3.0;

const TOKENS: [&[u8]; 14] = [
    b"nan",
    b"-1",
    b"0",
    b"1e308",
    b"-1e308",
    b"inf",
    b"\"",
    b"<",
    b"/>",
    b"\0",
    b"\xff\xff\xff\x7f",
    b"\x00\x00\x00\x80",
    b"\xff\xff\xff\xff",
    b"9999999",
];

/// One to four mutations of a seed: bit flips, byte values, token insertion or replacement,
/// deletion, duplication, truncation, a splice with another seed.
fn mutate(rng: &mut Rng, seed: &[u8], other: &[u8]) -> Vec<u8> {
    let mut b = seed.to_vec();
    for _ in 0..1 + rng.below(4) {
        let n = b.len();
        match rng.below(8) {
            0 if n > 0 => {
                let i = rng.below(n);
                b[i] ^= 1 << rng.below(8);
            }
            1 if n > 0 => {
                let i = rng.below(n);
                b[i] = rng.next() as u8;
            }
            2 => {
                let t = TOKENS[rng.below(TOKENS.len())];
                let i = rng.below(n + 1);
                b.splice(i..i, t.iter().copied());
            }
            3 if n > 0 => {
                let t = TOKENS[rng.below(TOKENS.len())];
                let i = rng.below(n);
                let j = (i + t.len()).min(n);
                b.splice(i..j, t.iter().copied());
            }
            4 if n > 0 => {
                let i = rng.below(n);
                let j = (i + 1 + rng.below(64)).min(n);
                b.drain(i..j);
            }
            5 if n > 0 => {
                let i = rng.below(n);
                let j = (i + 1 + rng.below(64)).min(n);
                let piece: Vec<u8> = b[i..j].to_vec();
                let k = rng.below(n + 1);
                b.splice(k..k, piece);
            }
            6 => b.truncate(rng.below(n + 1)),
            _ if !other.is_empty() => {
                let cut = rng.below(n + 1);
                let from = rng.below(other.len());
                b.truncate(cut);
                b.extend_from_slice(&other[from..]);
            }
            _ => {}
        }
    }
    b
}

/// The files of fuzz/`kind`/`target` (seeds: valid inputs; regressions: inputs that once
/// crashed, none of which may load or crash now).
fn inputs(kind: &str, target: &str) -> Vec<Vec<u8>> {
    let dir = root().join("fuzz").join(kind).join(target);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    files.iter().map(|f| std::fs::read(f).unwrap()).collect()
}

#[test]
fn fuzz_targets_bounded_run() {
    // a hang anywhere ends the process with a message instead of stalling the suite
    let limit = Duration::from_secs_f64(SECONDS * bodies::TARGETS.len() as f64 + 120.0);
    std::thread::spawn(move || {
        std::thread::sleep(limit);
        eprintln!("fuzz: no progress for {limit:?}: a hang");
        std::process::abort();
    });
    let mut lines = Vec::new();
    for (k, (name, body)) in bodies::TARGETS.iter().enumerate() {
        let seeds = inputs("seeds", name);
        assert!(!seeds.is_empty(), "no seeds for {name}");
        for (i, s) in seeds.iter().enumerate() {
            assert!(body(s), "{name}: seed {i} does not load");
        }
        let regressions = inputs("regressions", name);
        for r in &regressions {
            body(r);
        }
        let mut rng = Rng(0x5eed_0000 + k as u64);
        let (mut runs, mut loaded) = (0u64, 0u64);
        let start = Instant::now();
        while start.elapsed().as_secs_f64() < SECONDS {
            let a = &seeds[rng.below(seeds.len())];
            let b = &seeds[rng.below(seeds.len())];
            let input = mutate(&mut rng, a, b);
            loaded += body(&input) as u64;
            runs += 1;
        }
        lines.push(format!(
            "  {name:<11} {} seeds, {} regressions, {runs} mutated inputs in {SECONDS} s, {loaded} loaded and stepped",
            seeds.len(),
            regressions.len()
        ));
    }
    let msg = format!(
        "fuzz (stable driver: seeds and deterministic mutations, in process; no crash, abort or hang):\n{}\n",
        lines.join("\n")
    );
    report("fuzz", &msg);
    eprintln!("{msg}");
}
