//! File lookup with 2.2.2's virtual file system semantics: a file is found by its name
//! without directory, case-insensitively; what the VFS lacks is read from disk.

use std::borrow::Cow;

/// The longest VFS name, terminator included (mjMAXVFSNAME).
const MAX_NAME: usize = crate::abi::mjMAXVFSNAME;

/// In-memory files by VFS name (as `mjVFS` holds them, or built in Rust).
#[derive(Default, Clone)]
pub struct Vfs<'a> {
    /// (stored name, contents; None for a slot without memory)
    files: Vec<(&'a [u8], Option<&'a [u8]>)>,
}

impl<'a> Vfs<'a> {
    pub fn new() -> Self {
        Vfs { files: Vec::new() }
    }

    /// Adds a file under its stored name (already a VFS key: no directory, lower case).
    pub fn push(&mut self, name: &'a [u8], data: Option<&'a [u8]>) {
        self.files.push((name, data));
    }

    /// The index of `filename` (mj_findFileVFS).
    pub fn find(&self, filename: &str) -> Option<usize> {
        let key = key(filename).ok()?;
        self.files.iter().position(|f| f.0 == key.as_bytes())
    }

    /// The contents of `filename` when the VFS holds it (None for a slot without memory).
    pub fn get(&self, filename: &str) -> Option<Option<&'a [u8]>> {
        self.find(filename).map(|i| self.files[i].1)
    }
}

/// The VFS key of a file name: no directory, lower case.
pub fn key(filename: &str) -> Result<String, &'static str> {
    let base = filename.rsplit(['/', '\\']).next().unwrap_or("");
    if base.is_empty() {
        return Err("Empty filename in VFS");
    }
    if base.len() >= MAX_NAME {
        return Err("Filename too long in VFS");
    }
    Ok(base.to_ascii_lowercase())
}

/// A file from the VFS (borrowed, `true`; a slot without memory reads as empty), else from
/// disk (`false`).
pub fn read<'a>(filename: &str, vfs: Option<&Vfs<'a>>) -> Option<(Cow<'a, [u8]>, bool)> {
    if let Some(data) = vfs.and_then(|v| v.get(filename)) {
        return Some((Cow::Borrowed(data.unwrap_or_default()), true));
    }
    std::fs::read(filename).ok().map(|b| (b.into(), false))
}
