//! rujoco: a physics engine with the ABI and results of MuJoCo 2.2.2.

pub mod abi;
pub mod api;
pub mod capi;
pub mod compiler;
pub mod engine;
pub mod loader;
pub mod math;
pub mod runtime;
pub mod xml;

pub use api::{Data, Error, Model, ObjKind};
