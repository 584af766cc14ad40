//! Model description to `mjModel`: object compilation, sizes, array filling.
//!
//! `compile` does all work that needs no engine; `fill` writes the arrays of a model allocated
//! with the sizes it found; the loader then runs the engine's qpos0-dependent constants (mj_setConst).

pub mod composite;
mod composite_skin;
pub mod frame;
mod hull;
pub mod image;
pub mod mesh;
mod obj;
pub mod objects;
pub mod skin;
pub mod spec;
#[cfg(test)]
mod tests;
pub mod texture;
mod tree;

use crate::abi::view::ModelMut;
use crate::abi::{mjModel, mjStatistic};
pub use tree::Compiled;

/// Compiler error: message and, when known, the object (name, id, line) it concerns.
#[derive(Debug, Clone)]
pub struct CError {
    pub msg: String,
    pub obj: Option<(String, usize, i32)>,
}

impl CError {
    pub fn msg(msg: &str) -> Self {
        CError {
            msg: msg.to_string(),
            obj: None,
        }
    }
    pub fn at(msg: String, name: &str, id: usize, line: i32) -> Self {
        CError {
            msg,
            obj: Some((name.to_string(), id, line)),
        }
    }
    /// The text 2.2.2 puts in the error buffer.
    pub fn render(&self) -> String {
        let mut s = format!("Error: {}", self.msg);
        if let Some((name, id, line)) = &self.obj {
            if *line >= 0 {
                s += &format!("\nObject name = {name}, id = {id}, line = {line}, column = -1");
            } else {
                s += &format!("\nObject name = {name}, id = {id}");
            }
        }
        s
    }
}

/// Compiles a model description. `blank` is an all-zero mjModel; the result holds it with the
/// sizes set (`header`), ready for `make_model`, and the data for `fill`.
pub fn compile(spec: spec::ModelSpec, blank: mjModel) -> Result<Compiled, CError> {
    tree::compile(spec, blank)
}

/// Writes every array of `m` (allocated from `c.header`), freeing the bulk as it goes
/// (`Compiled::fill`).
pub fn fill(c: &mut Compiled, m: &mut ModelMut, trim: &dyn Fn()) {
    c.fill(m, trim);
}

/// Joint stiffness and damping from `springdamper` (time constant, damping ratio), using the
/// inverse weights mj_setConst computed.
pub fn auto_spring_damper(c: &Compiled, m: &mut ModelMut) {
    c.auto_spring_damper(m);
}

/// Applies the user's `<statistic>` overrides after mj_setConst.
pub fn finish(c: &Compiled, stat: &mut mjStatistic) {
    let o = &c.stat_override;
    let set = |dst: &mut f64, v: f64| {
        if !v.is_nan() {
            *dst = v;
        }
    };
    set(&mut stat.extent, o[3]);
    set(&mut stat.meaninertia, o[0]);
    set(&mut stat.meanmass, o[1]);
    set(&mut stat.meansize, o[2]);
    if !c.center[0].is_nan() {
        stat.center = c.center;
    }
}
