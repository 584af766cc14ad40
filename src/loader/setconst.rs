//! mj_setConst: the model's constants from its qpos0 configuration.

use crate::abi::owned::{DataBox, ModelBox};
use crate::engine::setconst::{compute, store, subtree_mass};
use crate::engine::EngineError;

/// Sets subtree masses, qpos0-derived constants and statistics of `m`, using `d` as scratch.
pub fn set_const(m: &mut ModelBox, d: &mut DataBox) -> Result<(), EngineError> {
    let nbody = m.raw().nbody.max(0) as usize;
    subtree_mass(&mut m.view_mut(), nbody);
    let consts = compute(&m.view(), &mut d.view(m))?;
    let mut stat = m.raw().stat;
    store(&mut m.view_mut(), &mut stat, consts);
    *m.stat_mut() = stat;
    Ok(())
}
