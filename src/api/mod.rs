//! The safe Rust API: load a [`Model`], simulate it with a [`Data`].
//!
//! It runs the same core as the C API (never through the `extern "C"` functions), so results
//! are the same bits as `mj_step` and friends give.
//!
//! ```
//! use mujoco::{Data, Model};
//!
//! let model = Model::from_xml_str(r#"
//!     <mujoco>
//!       <worldbody>
//!         <body name="pole">
//!           <joint name="hinge" type="hinge" axis="0 1 0"/>
//!           <geom type="capsule" fromto="0 0 0 0 0 -0.5" size="0.02"/>
//!           <site name="tip" pos="0 0 -0.5"/>
//!         </body>
//!       </worldbody>
//!       <actuator><motor name="torque" joint="hinge"/></actuator>
//!     </mujoco>"#)?;
//! let mut data = model.make_data()?;
//! data.joint_mut("hinge")?.qpos_mut()[0] = 0.5;
//! data.actuator_mut("torque")?.set_ctrl(0.1);
//! for _ in 0..100 {
//!     data.step()?;
//! }
//! let tip = data.site("tip")?.position();
//! assert!(data.time() > 0.19 && tip.z < 0.0);
//! # Ok::<(), mujoco::Error>(())
//! ```
//!
//! Errors: every call returns `Result<_, Error>`. An engine error (2.2.2's `mju_error`,
//! which exits the process by default in C) comes back as [`Error::Engine`] with its message:
//! the core returns its errors as values, and while an API call runs, this thread's error
//! hook (`_mjPRIVATE__set_tls_error_fn`'s) takes errors raised by user callbacks. A panic
//! inside the core (a bug) is caught and returned the same way. Engine warnings keep 2.2.2's
//! behaviour (`mju_user_warning`, else printed and logged) and are counted in
//! `data.raw().warning`.
//!
//! Threads: a [`Model`] is immutable once loaded and is `Send + Sync`, so one model can be
//! shared by reference among threads, each with its own [`Data`] (`Send`, not `Sync`).

mod data;
mod error;
mod model;
mod named;

pub use data::{Data, Jacobian};
pub use error::Error;
pub use model::{Model, ObjKind};
pub use named::{Actuator, ActuatorMut, Body, Joint, JointMut, Sensor, Site};
