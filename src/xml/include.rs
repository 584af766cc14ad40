//! `<include file="..."/>`: replaced by the children of the named file's root, recursively.

use super::reader::xerr;
use super::tree::{self, Element};

/// Directory part of a path, with its trailing separator ("" when none).
pub fn file_dir(path: &str) -> String {
    match path.rfind(['/', '\\']) {
        Some(p) => path[..=p].to_string(),
        None => String::new(),
    }
}

/// Expands every include below `el`. Names are taken relative to `dir` (the main model's
/// directory, as 2.2.2 does); `load` reads a file (VFS or disk); a file may be included once.
pub fn expand(
    el: &mut Element,
    dir: &str,
    load: &mut dyn FnMut(&str) -> Result<Vec<u8>, String>,
    included: &mut Vec<String>,
) -> Result<(), String> {
    let mut i = 0;
    while i < el.children.len() {
        if !el.children[i].name.eq_ignore_ascii_case("include") {
            expand(&mut el.children[i], dir, load, included)?;
            i += 1;
            continue;
        }
        let inc = &el.children[i];
        if !inc.children.is_empty() {
            return Err(xerr(inc, "Include element cannot have children"));
        }
        let file = inc
            .attr("file")
            .ok_or_else(|| xerr(inc, "required attribute missing: 'file'"))?;
        let filename = format!("{dir}{file}");
        if included.iter().any(|f| f.eq_ignore_ascii_case(&filename)) {
            return Err(xerr(inc, &format!("File '{filename}' already included")));
        }
        let parsed = load(&filename).and_then(|bytes| {
            let text = String::from_utf8_lossy(&bytes)
                .trim_end_matches('\0')
                .to_string();
            tree::parse(&text)
        });
        let root = parsed.map_err(|e| xerr(inc, &format!("Include error: '{e}'")))?;
        included.push(filename.clone());
        if root.children.is_empty() {
            return Err(xerr(inc, &format!("Empty include file '{filename}'")));
        }
        let n = root.children.len();
        el.children.splice(i..=i, root.children);
        // the inserted elements are expanded as the loop reaches them
        let _ = n;
    }
    Ok(())
}
