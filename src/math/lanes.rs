//! `blas`'s four-lane dot sums in one AVX register, the shape of 2.2.2's compiled mju_dot: lane
//! k holds partial sum k, each product is taken as b * a and added to its lane, and the lanes
//! combine as (p2 + p0) + (p3 + p1), no product fused with its sum. Where two NaNs meet, x86
//! keeps the first operand's, and AVX's three-operand instructions keep these orders, so NaN
//! signs agree with 2.2.2's too. Used where the build targets AVX (the x86-64-v3 library, which
//! glibc's loader takes on a CPU with AVX2); compiled in the tests too, to compare the forms.

use std::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_castpd256_pd128, _mm256_extractf128_pd, _mm256_mul_pd,
    _mm256_set_pd, _mm256_setzero_pd, _mm_add_pd, _mm_add_sd, _mm_cvtsd_f64, _mm_unpackhi_pd,
};

/// The partial sums of blocks of four, combined; length a multiple of 4.
#[cfg(target_feature = "avx")]
#[inline(always)]
pub fn lane_sum(a: &[f64], b: &[f64]) -> f64 {
    // SAFETY: the build targets AVX, so the CPU runs it (the only condition of calling a
    // function compiled for it).
    unsafe { lane_sum_avx(a, b) }
}

/// Four `lane_sum`s of `a[r]` with one `b` (of b's length), b read once.
#[cfg(target_feature = "avx")]
#[inline(always)]
pub fn lane_sum4(a: [&[f64]; 4], b: &[f64]) -> [f64; 4] {
    // SAFETY: as in `lane_sum`.
    unsafe { lane_sum4_avx(a, b) }
}

#[target_feature(enable = "avx")]
pub(crate) fn lane_sum_avx(a: &[f64], b: &[f64]) -> f64 {
    let mut p = _mm256_setzero_pd();
    for (x, y) in a.chunks_exact(4).zip(b.chunks_exact(4)) {
        p = _mm256_add_pd(p, _mm256_mul_pd(load(y), load(x)));
    }
    combine(p)
}

#[target_feature(enable = "avx")]
pub(crate) fn lane_sum4_avx(a: [&[f64]; 4], b: &[f64]) -> [f64; 4] {
    let mut p = [_mm256_setzero_pd(); 4];
    for (c, y) in b.chunks_exact(4).enumerate() {
        let y = load(y);
        for (pr, ar) in p.iter_mut().zip(&a) {
            *pr = _mm256_add_pd(*pr, _mm256_mul_pd(y, load(&ar[4 * c..4 * c + 4])));
        }
    }
    p.map(|v| combine(v))
}

/// Four consecutive values (one unaligned load once the bounds are known).
#[inline]
#[target_feature(enable = "avx")]
fn load(x: &[f64]) -> __m256d {
    let x: &[f64; 4] = x.try_into().unwrap();
    _mm256_set_pd(x[3], x[2], x[1], x[0])
}

#[inline]
#[target_feature(enable = "avx")]
fn combine(p: __m256d) -> f64 {
    let s = _mm_add_pd(_mm256_extractf128_pd::<1>(p), _mm256_castpd256_pd128(p));
    _mm_cvtsd_f64(_mm_add_sd(s, _mm_unpackhi_pd(s, s)))
}
