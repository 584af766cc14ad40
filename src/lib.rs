//! rujoco: a physics engine with the ABI and results of MuJoCo 2.2.2.
//!
//! Two faces over one core:
//!
//! - the C library (`libmujoco.so.2.2.2`, the 2.2.2 headers): [`capi`], the exported
//!   `mj_*`/`mju_*` functions;
//! - the safe Rust API: [`Model`] and [`Data`] (module [`api`]), with nalgebra types for poses,
//!   Jacobians and the mass matrix, and errors as [`Error`] values.
//!
//! ```
//! let model = mujoco::Model::from_xml("models/arm3.xml")?;
//! let mut data = model.make_data()?;
//! data.actuator_mut("elbow")?.set_ctrl(1.0);
//! for _ in 0..500 {
//!     data.step()?;
//! }
//! let ee = data.site("ee")?.pose();
//! println!("t = {:.3}, end effector at {}", data.time(), ee.translation.vector);
//! # Ok::<(), mujoco::Error>(())
//! ```
//!
//! Layers, from the top: [`capi`] and [`api`] → [`loader`] → [`xml`] → [`compiler`] →
//! [`engine`] → [`math`] → [`runtime`] → [`abi`].

pub mod abi;
pub mod api;
pub mod capi;
pub mod compiler;
pub mod engine;
pub mod loader;
pub mod math;
pub mod render;
pub mod runtime;
pub mod ui;
pub mod visualize;
pub mod xml;

pub use api::{Data, Error, Model, ObjKind};
