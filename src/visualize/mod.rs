//! Abstract visualization (mjv_): default structs, the scene's buffers and its contents from a
//! model and its state. Beside the engine, never inside it; rendering reads the scene.

pub mod defaults;
pub mod scene;
