//! MJB files (mj_loadModel).

use super::vfs::{self, Vfs};
use crate::abi::mjb::LoadError;
use crate::abi::owned::ModelBox;

/// The model in MJB file `filename` (from the VFS, else disk); errors are 2.2.2's warnings and
/// errors.
pub fn load_file(filename: &str, vfs: Option<&Vfs>) -> Result<ModelBox, LoadError> {
    let in_vfs = vfs.is_some_and(|v| v.get(filename).is_some());
    if !in_vfs {
        // a regular file is read straight into the model's arrays
        if let Ok(file) = std::fs::File::open(filename) {
            if let Some(meta) = file.metadata().ok().filter(|m| m.is_file()) {
                let len = meta.len() as usize;
                let mut src = std::io::BufReader::with_capacity(len.min(1 << 16), file);
                return ModelBox::from_mjb_reader(&mut src, len, false);
            }
        }
    }
    let (bytes, buffer) = vfs::read(filename, vfs)
        .ok_or_else(|| LoadError::Warning(format!("Could not open file '{filename}'")))?;
    ModelBox::from_mjb(&bytes, buffer)
}
