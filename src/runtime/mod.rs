//! The runtime layer under the engine: errors and warnings, heap memory, the user's callbacks
//! and the random source. Process-wide state with 2.2.2's semantics; the C API re-exports it.

#![allow(non_upper_case_globals)]

pub mod callbacks;
pub mod copy;
pub mod file;
pub mod guard;
pub mod memory;
pub mod message;
pub mod random;

pub use message::{capture_errors, capture_warnings, error, warning, MsgBuf};
