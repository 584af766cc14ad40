// The sources a recorded profile belongs to: one FNV-1a digest per file under src/ and of
// Cargo.lock, as "digest path" lines. Shared with tests/speed.rs (include!), which compares them
// with pgo/sources.txt.

/// "digest path" lines of the profile's sources under `root`, sorted by path.
pub fn source_digests(root: &std::path::Path) -> String {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else {
                out.push(p);
            }
        }
    }
    let mut files = vec![root.join("Cargo.lock")];
    walk(&root.join("src"), &mut files);
    files.sort();
    let mut lines = String::new();
    for f in files {
        let bytes = std::fs::read(&f).unwrap_or_default();
        let digest = bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
            (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
        });
        let rel = f.strip_prefix(root).unwrap_or(&f).display().to_string();
        lines.push_str(&format!("{digest:016x} {rel}\n"));
    }
    lines
}
