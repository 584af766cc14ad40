//! Vector kernels for the engine: MuJoCo-order BLAS from `math`, plus row access helpers.

pub use crate::math::blas::{add_to, add_to_scl, mul_mat_mat_t, mul_mat_t_vec, mul_mat_vec};
pub use crate::math::misc::{clip, is_bad, max, min};

/// Dot product over the common length, in MuJoCo's summation order.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    crate::math::blas::dot(a, b, a.len().min(b.len()))
}

/// Writes the `N` values of `v` at row `i` of a flat array of `N`-rows.
#[inline]
pub fn put<const N: usize>(dst: &mut [f64], i: usize, v: &[f64; N]) {
    dst[N * i..N * i + N].copy_from_slice(v);
}

/// Reads row `i` of a flat array of `N`-rows.
#[inline]
pub fn row<const N: usize>(src: &[f64], i: usize) -> [f64; N] {
    crate::math::arr(&src[N * i..N * i + N])
}
