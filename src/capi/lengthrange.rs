//! C entry point of the actuator length ranges: `mj_setLengthRange`.

use super::errmem;
use super::guard;
use crate::abi::*;
use crate::loader::lengthrange::set_length_range;
use std::os::raw::{c_char, c_int};

#[no_mangle]
pub unsafe extern "C" fn mj_setLengthRange(
    m: *mut mjModel,
    d: *mut mjData,
    index: c_int,
    opt: *const mjLROpt,
    error: *mut c_char,
    error_sz: c_int,
) -> c_int {
    if m.is_null() || d.is_null() || opt.is_null() {
        errmem::error("mj_setLengthRange: NULL model, data or options");
        return 0;
    }
    if index < 0 || index >= (*m).nu {
        errmem::error("Invalid actuator index in mj_setLengthRange");
        return 0;
    }
    let opt = *opt;
    let (mut m, mut d) = super::borrow_boxes(m, d);
    guard("mj_setLengthRange", 0, || {
        Ok(
            match set_length_range(&mut m, &mut d, index as usize, &opt)? {
                Ok(()) => 1,
                Err(msg) => {
                    super::xml::set_error(error, error_sz, &msg);
                    0
                }
            },
        )
    })
}
