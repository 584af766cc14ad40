//! OpenGL rendering (mjr_): the context of display lists, textures and framebuffers made from
//! a model, and drawing of the abstract scene and of 2D overlays. Beside the engine, never
//! inside it; OpenGL is loaded at run time (gl.rs).

#![allow(clippy::needless_range_loop)] // index loops mirror the reference algorithms

pub mod context;
pub mod figure;
#[rustfmt::skip]
mod font_data;
pub mod framebuffer;
pub mod gl;
pub mod scene;
mod shapes;
pub mod text;
mod util;
