//! Spatial algebra, quaternions, small dense and sparse linear algebra, and geometry.
//!
//! Everything here reproduces the arithmetic of MuJoCo 2.2.2 operation by operation,
//! so that results agree bit for bit with the reference:
//! - `vec3`, `quat`, `spatial`: 3D vectors/matrices, quaternions and poses, 6D spatial algebra
//!   (engine_util_spatial.c, engine_util_blas.c fixed-size part);
//! - `blas`, `chol`, `eig3`, `qcqp`, `misc`: mju_ vector/matrix operations, dense Cholesky,
//!   eigen-decomposition, small QCQPs, actuator curves and scalar helpers;
//! - `sparse`, `chol_sparse`: row-sparse matrices, sparse Cholesky and LU (engine_util_sparse.c,
//!   engine_util_solve.c);
//! - `wrap`: tendon wrapping (mju_wrap);
//! - `lanes`: `blas`'s four-lane dot sums in AVX registers (the x86-64-v3 build);

pub mod blas;
pub mod chol;
pub mod chol_sparse;
pub mod eig3;
#[cfg(all(target_arch = "x86_64", any(target_feature = "avx", test)))]
mod lanes;
pub mod misc;
pub mod qcqp;
pub mod quat;
pub mod sparse;
pub mod spatial;
pub mod vec3;
pub mod wrap;

#[cfg(test)]
pub(crate) mod tests;

pub use eig3::{eig3, Eig3};
pub use quat::*;
pub use spatial::*;
pub use vec3::*;

/// 3D vector.
pub type Vec3 = [f64; 3];
/// Quaternion (w, x, y, z).
pub type Quat = [f64; 4];
/// 3x3 matrix, row-major.
pub type Mat3 = [f64; 9];
/// Spatial vector: [rotational; linear].
pub type Vec6 = [f64; 6];

/// Smallest value treated as nonzero by normalizations.
pub const MINVAL: f64 = 1e-15;
/// The constant pi as MuJoCo spells it.
pub const PI: f64 = std::f64::consts::PI;

/// First `N` elements of a slice as an array.
#[inline]
pub fn arr<const N: usize>(s: &[f64]) -> [f64; N] {
    let mut r = [0.0; N];
    r.copy_from_slice(&s[..N]);
    r
}

/// First 3 elements of a slice.
#[inline]
pub fn v3(s: &[f64]) -> Vec3 {
    arr(s)
}

/// First 4 elements of a slice.
#[inline]
pub fn q4(s: &[f64]) -> Quat {
    arr(s)
}

/// First 9 elements of a slice.
#[inline]
pub fn m9(s: &[f64]) -> Mat3 {
    arr(s)
}

/// First 6 elements of a slice.
#[inline]
pub fn v6(s: &[f64]) -> Vec6 {
    arr(s)
}
