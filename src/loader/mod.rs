//! Loading models: MJCF and URDF files (through the XML reader and the compiler, then the
//! compiler's engine steps), MJB images, and files from a virtual file system or disk. Safe
//! functions returning owned models; the C API wraps them.

pub mod lengthrange;
pub mod mjb;
pub mod setconst;
pub mod vfs;
pub mod xml;

use crate::abi::owned::{DataBox, ModelBox};
use crate::engine::support::reset_fresh_data;

/// Data for `m`, reset (mj_makeData); its arrays come zeroed from the allocation.
pub fn new_data(m: &ModelBox) -> Result<DataBox, String> {
    let mut d = DataBox::new(m)?;
    reset_fresh_data(&m.view(), &mut d.view(m));
    Ok(d)
}
