//! MJB files (mj_loadModel).

use super::vfs::{self, Vfs};
use crate::abi::mjb::LoadError;
use crate::abi::owned::ModelBox;

/// The model in MJB file `filename` (from the VFS, else disk); errors are 2.2.2's warnings and
/// errors.
pub fn load_file(filename: &str, vfs: Option<&Vfs>) -> Result<ModelBox, LoadError> {
    let (bytes, buffer) = vfs::read(filename, vfs)
        .ok_or_else(|| LoadError::Warning(format!("Could not open file '{filename}'")))?;
    ModelBox::from_mjb(&bytes, buffer)
}
