//! The UI framework (mjui_): themes, building from definition tables, layout, events and
//! drawing. Beside the engine, never inside it; drawing goes through the OpenGL layer.

pub mod build;
pub mod draw;
mod edit;
pub mod event;
pub mod host;
pub mod layout;
mod locate;
mod paint;
pub mod theme;
