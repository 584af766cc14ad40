//! MJB files (mj_loadModel).

use super::vfs::{self, Vfs};
use crate::abi::mjb::LoadError;
use crate::abi::owned::ModelBox;

/// The model in MJB file `filename` (from the VFS, else disk); errors are 2.2.2's warnings and
/// errors.
pub fn load_file(filename: &str, vfs: Option<&Vfs>) -> Result<ModelBox, LoadError> {
    let cannot_open = || LoadError::Warning(format!("Could not open file '{filename}'"));
    if vfs.is_some_and(|v| v.get(filename).is_some()) {
        let (bytes, buffer) = vfs::read(filename, vfs).ok_or_else(cannot_open)?;
        return ModelBox::from_mjb(&bytes, buffer);
    }
    let mut file = std::fs::File::open(filename).map_err(|_| cannot_open())?;
    match crate::runtime::file::regular_size(&file) {
        // a regular file is read straight into the model's arrays
        Some(len) => {
            // through a page of buffer, as stdio reads it: a fresh process's first load faults
            // in fewer new pages (a buffer the size of a 27 kB file took a fifth of its load)
            let mut src = crate::runtime::file::FileReader::new(file);
            ModelBox::from_mjb_reader(&mut src, len as usize, false)
        }
        // a pipe or a device read through once; what a read error leaves is what was read,
        // as 2.2.2's fread (a directory opens and reads nothing: an incomplete header)
        _ => {
            let mut bytes = Vec::new();
            let _ = std::io::Read::read_to_end(&mut file, &mut bytes);
            ModelBox::from_mjb(&bytes, false)
        }
    }
}
