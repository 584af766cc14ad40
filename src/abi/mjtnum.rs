//! Scalar type of the engine.

/// Floating-point type of every physics quantity.
pub type mjtNum = f64;

pub const mjMINVAL: f64 = 1.0E-15;
