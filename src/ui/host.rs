//! What UI items point at (the caller's ints, bytes, numbers and strings) and the UI's
//! predicate: reached through `Host`, which the C boundary supplies.

use crate::abi::*;

/// Reads and writes the data of items and evaluates the UI's predicate.
pub trait Host {
    /// Element `i` of an int item (check, radio, select, slider, edit).
    fn int(&self, it: &mjuiItem, i: usize) -> i32;
    fn set_int(&self, it: &mjuiItem, i: usize, v: i32);
    /// The byte of a checkbyte item.
    fn byte(&self, it: &mjuiItem) -> u8;
    fn set_byte(&self, it: &mjuiItem, v: u8);
    /// Element `i` of a number item (slider, edit).
    fn num(&self, it: &mjuiItem, i: usize) -> f64;
    fn set_num(&self, it: &mjuiItem, i: usize, v: f64);
    /// The string of a text edit item: at most mjMAXUINAME bytes, up to its NUL.
    fn text(&self, it: &mjuiItem) -> Vec<u8>;
    /// Writes all mjMAXUINAME bytes of a text edit item.
    fn set_text(&self, it: &mjuiItem, text: &[u8; mjMAXUINAME]);
    /// The UI's predicate (set) for `category`.
    fn predicate(&self, ui: &mjUI, category: i32) -> i32;
}

/// Whether an item of this state is enabled: 0 or less never, 1 always, else the predicate.
pub fn enabled(state: i32, ui: &mjUI, host: &dyn Host) -> bool {
    if state <= 0 {
        false
    } else if state == 1 || ui.predicate.is_none() {
        true
    } else {
        host.predicate(ui, state) != 0
    }
}
