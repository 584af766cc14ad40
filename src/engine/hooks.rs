//! The user's callbacks (2.2.2's mjcb_*), called where 2.2.2 calls them. The callback receives
//! the model and data the engine is working on; the stack top is marked first, so that the
//! callback's own stack allocations (or engine calls) land above the engine's live scratch.
//! Callers hold no borrow of data arrays across the call.

use super::{Data, Model};
use crate::abi::mjData;
use crate::runtime::callbacks::{self, ActCallback};

/// Runs `f` on the raw data with the stack top at `top` (mjMARKSTACK for the callback).
fn marked<R>(raw: &mut mjData, top: usize, f: impl FnOnce(&mut mjData) -> R) -> R {
    let saved = raw.pstack;
    raw.pstack = top as i32;
    let r = f(raw);
    raw.pstack = saved;
    r
}

/// mjcb_control, before actuation.
pub fn control(m: &Model, d: &mut Data) {
    let top = d.arena.used();
    marked(d.raw, top, |raw| callbacks::call_generic(false, m.raw, raw));
}

/// mjcb_passive, at the end of the passive forces.
pub fn passive(m: &Model, d: &mut Data) {
    let top = d.arena.used();
    marked(d.raw, top, |raw| callbacks::call_generic(true, m.raw, raw));
}

/// mjcb_act_gain, mjcb_act_bias or mjcb_act_dyn of a user actuator; None when not set.
/// Takes the raw data: actuation calls it while its scratch borrows the arena.
pub fn act(m: &Model, raw: &mut mjData, top: usize, which: ActCallback, i: usize) -> Option<f64> {
    marked(raw, top, |raw| callbacks::call_act(which, m.raw, raw, i))
}

/// mjcb_sensor for the user sensors of a stage (mjtStage).
pub fn sensor(m: &Model, d: &mut Data, top: usize, stage: i32) {
    marked(d.raw, top, |raw| callbacks::call_sensor(m.raw, raw, stage));
}

/// Is any callback set that receives the data?
pub fn any_set() -> bool {
    callbacks::any_engine_callback()
}

/// Is mjcb_contactfilter set?
pub fn contact_filter_set() -> bool {
    callbacks::contactfilter_set()
}

/// mjcb_contactfilter of a dynamic geom pair: Some(true) discards; None when not set.
pub fn contact_filter(m: &Model, d: &mut Data, top: usize, g1: usize, g2: usize) -> Option<bool> {
    marked(d.raw, top, |raw| {
        callbacks::call_contactfilter(m.raw, raw, g1, g2)
    })
}
