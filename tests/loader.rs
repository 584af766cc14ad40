//! The MJCF loader under hostile input: mutated copies of real models (attribute
//! values such as nan, inf, 1e308, -1, empty or wrong counts; dropped and duplicated elements;
//! flipped bytes; truncation) must get the reference's verdict: load or reject, never a crash
//! or a hang, never a model the reference rejects. A model we cannot compile yet may only be
//! rejected with a "not supported"/"not implemented" message (counted in the report).
//! Seeds: the corpus when present (see tests/corpus.rs) and our models/.

mod common;
use common::*;
use std::path::Path;

const VALUES: [&str; 16] = [
    "nan",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "-1",
    "0",
    "",
    "1 2",
    "abc",
    "1e-308",
    "0 0 0 0 0 0 0 0 0 0 0 0 0",
    "-0.5 2 nan",
    "100000",
    "0x10",
    "true",
];

/// Byte ranges of attribute values (between the quotes).
fn attribute_values(s: &str) -> Vec<(usize, usize)> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i + 1 < b.len() {
        if b[i] == b'=' && b[i + 1] == b'"' {
            if let Some(len) = s[i + 2..].find('"') {
                out.push((i + 2, i + 2 + len));
                i += 2 + len;
            }
        }
        i += 1;
    }
    out
}

/// Byte ranges of self-closing elements `<name ... />`.
fn empty_elements(s: &str) -> Vec<(usize, usize)> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    for (i, _) in s.match_indices('<') {
        if !b.get(i + 1).is_some_and(|c| c.is_ascii_alphabetic()) {
            continue;
        }
        if let Some(end) = s[i..].find('>') {
            if b[i + end - 1] == b'/' && !s[i..i + end].contains('<') {
                out.push((i, i + end + 1));
            }
        }
    }
    out
}

fn mutate(text: &str, rng: &mut Rng) -> Vec<u8> {
    let mut s = text.to_string();
    match rng.below(6) {
        0 | 1 => {
            let vals = attribute_values(&s);
            if !vals.is_empty() {
                let (a, b) = vals[rng.below(vals.len())];
                s.replace_range(a..b, VALUES[rng.below(VALUES.len())]);
            }
        }
        2 => {
            let els = empty_elements(&s);
            if !els.is_empty() {
                let (a, b) = els[rng.below(els.len())];
                s.replace_range(a..b, "");
            }
        }
        3 => {
            let els = empty_elements(&s);
            if !els.is_empty() {
                let (a, b) = els[rng.below(els.len())];
                let el = s[a..b].to_string();
                s.insert_str(b, &el);
            }
        }
        4 => {
            let mut bytes = s.into_bytes();
            if !bytes.is_empty() {
                let at = rng.below(bytes.len());
                bytes[at] ^= 1 + rng.below(255) as u8;
            }
            return bytes;
        }
        _ => {
            let mut bytes = s.into_bytes();
            bytes.truncate(rng.below(bytes.len()));
            return bytes;
        }
    }
    s.into_bytes()
}

/// A directory mirroring the seed's (symlinks to its entries), so relative includes and
/// assets resolve; the mutant is written into it.
fn mirror(seed: &Path, dir: &Path) {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).unwrap();
    for e in std::fs::read_dir(seed.parent().unwrap()).unwrap().flatten() {
        let _ = std::os::unix::fs::symlink(e.path(), dir.join(e.file_name()));
    }
}

fn unsupported(msg: &str) -> bool {
    msg.contains("not supported") || msg.contains("not implemented")
}

#[test]
fn mutated_models_get_the_reference_verdict() {
    let l = loaders();
    let (reference, ours, seeds) = (&l.reference, &l.ours, &l.seeds);
    assert!(!seeds.is_empty(), "no seed model loads in both libraries");
    let count = if corpus_dirs().is_empty() { 300 } else { 1000 };
    let base = work_dir("mutants");
    let mut rng = Rng(2022);
    let mut files = Vec::new();
    for i in 0..count {
        let seed = Path::new(&seeds[rng.below(seeds.len())]);
        let dir = base.join(i.to_string());
        mirror(seed, &dir);
        let text = std::fs::read_to_string(seed).unwrap();
        let file = dir.join(format!(
            "mutant-{}",
            seed.file_name().unwrap().to_string_lossy()
        ));
        std::fs::write(&file, mutate(&text, &mut rng)).unwrap();
        files.push(file.to_string_lossy().into_owned());
    }
    let (r, o) = both_verdicts(reference, ours, &files);
    let (mut same, mut same_msg, mut unsup, mut ref_bad) = (0, 0, 0, 0);
    let mut wrong = Vec::new();
    for (f, (r, o)) in files.iter().zip(r.iter().zip(&o)) {
        let bad = |what: &str| format!("{what}: {f}\n    reference: {r}\n    ours:      {o}");
        if o.starts_with("crash") || o == "hang" {
            wrong.push(bad("crash or hang"));
        } else if r.starts_with("crash") || r == "hang" {
            ref_bad += 1;
        } else if r.starts_with("load") {
            if r == o {
                same += 1;
            } else if o.starts_with("reject") && unsupported(o) {
                unsup += 1;
            } else {
                wrong.push(bad("different verdict"));
            }
        } else if o.starts_with("reject") {
            same += 1;
            let strip = |s: &str| s.replace(&base.to_string_lossy().to_string(), "");
            same_msg += (strip(r) == strip(o)) as usize;
        } else {
            wrong.push(bad("loads what the reference rejects"));
        }
    }
    let msg = format!(
        "loader mutants: {count} mutants of {} seed models; same verdict {same}, of which \
         rejections with the identical message {same_msg}; rejected as not supported yet {unsup}; \
         reference crashed or hung {ref_bad}; wrong {}\n{}",
        seeds.len(),
        wrong.len(),
        wrong
            .iter()
            .take(20)
            .map(|w| format!("  {w}\n"))
            .collect::<String>()
    );
    report("loader-mutants", &msg);
    assert!(wrong.is_empty(), "{msg}");
}

/// A mesh file mutated: flipped bytes, truncation, or a 4-byte slot (sizes, coordinates, face
/// indices) set to a hostile value; text lines (OBJ) dropped, repeated or given a hostile number.
fn mutate_mesh(bytes: &[u8], rng: &mut Rng) -> Vec<u8> {
    let mut b = bytes.to_vec();
    if b.is_empty() {
        return b;
    }
    match rng.below(5) {
        0 => {
            let at = rng.below(b.len());
            b[at] ^= 1 + rng.below(255) as u8;
        }
        1 => b.truncate(rng.below(b.len())),
        2 if b.len() >= 4 => {
            let slots: [[u8; 4]; 8] = [
                f32::NAN.to_le_bytes(),
                f32::INFINITY.to_le_bytes(),
                1e30f32.to_le_bytes(),
                (-1i32).to_le_bytes(),
                0i32.to_le_bytes(),
                i32::MAX.to_le_bytes(),
                7i32.to_le_bytes(),
                300000i32.to_le_bytes(),
            ];
            let at = 4 * rng.below(b.len() / 4);
            b[at..at + 4].copy_from_slice(&slots[rng.below(slots.len())]);
        }
        _ => {
            let text = String::from_utf8_lossy(&b).into_owned();
            let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
            let i = rng.below(lines.len());
            match rng.below(3) {
                0 => {
                    lines.remove(i);
                }
                1 => lines.insert(i, lines[i].clone()),
                _ => {
                    let words: Vec<&str> = lines[i].split(' ').collect();
                    let w = rng.below(words.len());
                    let value = ["nan", "-1", "0", "1e40", "2/0", "-99", "x", ""][rng.below(8)];
                    lines[i] = words
                        .iter()
                        .enumerate()
                        .map(|(k, x)| if k == w { value } else { x })
                        .collect::<Vec<_>>()
                        .join(" ");
                }
            }
            b = lines.join("\n").into_bytes();
        }
    }
    b
}

/// Mesh file names (STL, OBJ, MSH) in a model's `file` attributes, resolved with its meshdir.
fn mesh_files(xml: &str, dir: &Path) -> Vec<(String, std::path::PathBuf)> {
    let attr = |name: &str| {
        xml.match_indices(&format!(" {name}=\""))
            .filter_map(|(i, m)| {
                let v = &xml[i + m.len()..];
                v.find('"').map(|e| v[..e].to_string())
            })
            .collect::<Vec<_>>()
    };
    let meshdir = attr("meshdir").into_iter().next().unwrap_or_default();
    attr("file")
        .into_iter()
        .filter(|f| {
            let l = f.to_ascii_lowercase();
            l.ends_with(".stl") || l.ends_with(".obj") || l.ends_with(".msh")
        })
        .map(|f| {
            let path = dir.join(&meshdir).join(&f);
            (f, path)
        })
        .filter(|(_, p)| p.is_file())
        .collect()
}

#[test]
fn mutated_mesh_files_get_the_reference_verdict() {
    let l = loaders();
    let (reference, ours) = (&l.reference, &l.ours);
    let seeds: Vec<(String, Vec<(String, std::path::PathBuf)>)> = l
        .seeds
        .iter()
        .cloned()
        .filter_map(|f| {
            let xml = std::fs::read_to_string(&f).ok()?;
            let meshes = mesh_files(&xml, Path::new(&f).parent()?);
            (!meshes.is_empty()).then_some((f, meshes))
        })
        .collect();
    assert!(!seeds.is_empty(), "no seed model with mesh files");
    let count = 400;
    let base = work_dir("mesh-mutants");
    let mut rng = Rng(222);
    let mut files = Vec::new();
    for i in 0..count {
        let (seed, meshes) = &seeds[rng.below(seeds.len())];
        let seed = Path::new(seed);
        let (name, path) = &meshes[rng.below(meshes.len())];
        let dir = base.join(i.to_string());
        mirror(seed, &dir);
        let ext = &name[name.len() - 3..];
        let mutant = dir.join(format!("mutant-mesh.{ext}"));
        std::fs::write(
            &mutant,
            mutate_mesh(&std::fs::read(path).unwrap(), &mut rng),
        )
        .unwrap();
        let xml = std::fs::read_to_string(seed).unwrap().replace(
            &format!("file=\"{name}\""),
            &format!("file=\"{}\"", mutant.display()),
        );
        let file = dir.join(format!(
            "mutant-{}",
            seed.file_name().unwrap().to_string_lossy()
        ));
        std::fs::write(&file, xml).unwrap();
        files.push(file.to_string_lossy().into_owned());
    }
    let (r, o) = both_verdicts(reference, ours, &files);
    let (mut same, mut same_msg, mut loads, mut ref_bad) = (0, 0, 0, 0);
    let mut wrong = Vec::new();
    for (f, (r, o)) in files.iter().zip(r.iter().zip(&o)) {
        let bad = |what: &str| format!("{what}: {f}\n    reference: {r}\n    ours:      {o}");
        if o.starts_with("crash") || o == "hang" {
            wrong.push(bad("crash or hang"));
        } else if r.starts_with("crash") || r == "hang" {
            ref_bad += 1;
        } else if r.starts_with("load") == o.starts_with("load") {
            same += 1;
            loads += r.starts_with("load") as usize;
            same_msg += (r == o) as usize;
        } else {
            wrong.push(bad("different verdict"));
        }
    }
    let msg = format!(
        "mesh file mutants: {count} mutated STL/OBJ/MSH files of {} seed models; same verdict \
         {same} ({loads} load), identical verdict line {same_msg}; reference crashed or hung \
         {ref_bad}; wrong {}\n{}",
        seeds.len(),
        wrong.len(),
        wrong
            .iter()
            .take(20)
            .map(|w| format!("  {w}\n"))
            .collect::<String>()
    );
    report("mesh-mutants", &msg);
    assert!(wrong.is_empty(), "{msg}");
}

/// The corpus and project files as they are: every file the reference rejects (include
/// fragments, malformed_face.xml, features after 2.2.2) ours rejects too, and every file it
/// loads ours loads with the same sizes.
#[test]
fn corpus_files_get_the_reference_verdict() {
    let l = loaders();
    let mut wrong = Vec::new();
    let (mut rejected, mut same_msg) = (0, 0);
    for (f, (r, o)) in l
        .files
        .iter()
        .zip(l.reference_verdicts.iter().zip(&l.our_verdicts))
    {
        let rejects = |v: &str| v.starts_with("reject");
        if rejects(r) && rejects(o) {
            rejected += 1;
            same_msg += (r == o) as usize;
        } else if r != o {
            wrong.push(format!("{f}\n    reference: {r}\n    ours:      {o}"));
        }
    }
    let msg = format!(
        "corpus verdicts: {} files; the reference rejects {rejected}, ours too ({same_msg} with \
         the identical message); {} differ\n{}",
        l.files.len(),
        wrong.len(),
        wrong.iter().map(|w| format!("  {w}\n")).collect::<String>()
    );
    report("corpus-verdicts", &msg);
    assert!(wrong.is_empty(), "{msg}");
}
