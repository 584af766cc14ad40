//! Vector kernels for the engine: MuJoCo-order BLAS from `math`, plus row access helpers.

pub use crate::math::blas::{add_to, add_to_scl, mul_mat_mat_t, mul_mat_t_vec, mul_mat_vec};
pub use crate::math::misc::{clip, is_bad, max, min};

/// Dot product over the common length, in MuJoCo's summation order.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    crate::math::blas::dot(a, b, a.len().min(b.len()))
}

/// Dot product of 6-vectors, bit-identical to `dot` with n = 6 (zero-started partial sums kept).
#[inline(always)]
pub fn dot6(a: &[f64], b: &[f64]) -> f64 {
    let (a, b) = (&a[..6], &b[..6]);
    let s =
        ((0.0 + a[0] * b[0]) + (0.0 + a[2] * b[2])) + ((0.0 + a[1] * b[1]) + (0.0 + a[3] * b[3]));
    s + (a[4] * b[4] + a[5] * b[5])
}

/// Writes the `N` values of `v` at row `i` of a flat array of `N`-rows.
#[inline]
pub fn put<const N: usize>(dst: &mut [f64], i: usize, v: &[f64; N]) {
    dst[N * i..N * i + N].copy_from_slice(v);
}

/// Row `i` of a flat array of `N`-rows, in place (a copy whose parts were just stored and is
/// read back whole stalls on store forwarding).
#[inline]
pub fn row_ref<const N: usize>(src: &[f64], i: usize) -> &[f64; N] {
    src[N * i..N * i + N].try_into().expect("row of N")
}

/// Reads row `i` of a flat array of `N`-rows.
#[inline]
pub fn row<const N: usize>(src: &[f64], i: usize) -> [f64; N] {
    crate::math::arr(&src[N * i..N * i + N])
}
