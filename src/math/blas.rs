//! Dense vectors and matrices of any size, with MuJoCo's summation orders.
//!
//! Matrices are row-major slices. Functions taking `res` overwrite its first elements.

use super::MINVAL;

pub fn zero(res: &mut [f64]) {
    res.fill(0.0);
}

pub fn copy(res: &mut [f64], vec: &[f64]) {
    res.copy_from_slice(&vec[..res.len()]);
}

pub fn sum(vec: &[f64]) -> f64 {
    let mut s = 0.0;
    for x in vec {
        s += x;
    }
    s
}

/// Sum of absolute values.
pub fn l1(vec: &[f64]) -> f64 {
    let mut s = 0.0;
    for x in vec {
        s += x.abs();
    }
    s
}

/// res = vec * s
pub fn scl(res: &mut [f64], vec: &[f64], s: f64) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r = v * s;
    }
}

/// res *= s
pub fn scl_in_place(res: &mut [f64], s: f64) {
    for r in res.iter_mut() {
        *r *= s;
    }
}

/// res = a + b
pub fn add(res: &mut [f64], a: &[f64], b: &[f64]) {
    for ((r, x), y) in res.iter_mut().zip(a).zip(b) {
        *r = x + y;
    }
}

/// res = a - b
pub fn sub(res: &mut [f64], a: &[f64], b: &[f64]) {
    for ((r, x), y) in res.iter_mut().zip(a).zip(b) {
        *r = x - y;
    }
}

/// res += vec
pub fn add_to(res: &mut [f64], vec: &[f64]) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r += v;
    }
}

/// res -= vec
pub fn sub_from(res: &mut [f64], vec: &[f64]) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r -= v;
    }
}

/// res += vec * s
pub fn add_to_scl(res: &mut [f64], vec: &[f64], s: f64) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r += v * s;
    }
}

/// res = a + b * s
pub fn add_scl(res: &mut [f64], a: &[f64], b: &[f64], s: f64) {
    for ((r, x), y) in res.iter_mut().zip(a).zip(b) {
        *r = x + y * s;
    }
}

/// Dot product of the first `n` elements, summed in four interleaved partial sums
/// over blocks of four, then the remainder (MuJoCo's order).
pub fn dot(a: &[f64], b: &[f64], n: usize) -> f64 {
    let n4 = n & !3;
    let s = lane_sum(&a[..n4], &b[..n4]);
    add_remainder(s, &a[n4..n], &b[n4..n])
}

/// `dot` of four vectors with one (`b`): each sum in `dot`'s order, b read once for all four.
pub fn dot4(a: [&[f64]; 4], b: &[f64], n: usize) -> [f64; 4] {
    let n4 = n & !3;
    let s = lane_sum4(a.map(|x| &x[..n4]), &b[..n4]);
    std::array::from_fn(|r| add_remainder(s[r], &a[r][n4..n], &b[n4..n]))
}

/// The four partial sums of blocks of four, combined (p2 + p0) + (p3 + p1); length a multiple
/// of 4. Never -0: each partial sum starts at +0 and a sum is -0 only of two -0. In an AVX build
/// with 2.2.2's operands in 2.2.2's places, so NaN signs agree too (`lanes`).
#[inline(always)]
fn lane_sum(a: &[f64], b: &[f64]) -> f64 {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx"))]
    return super::lanes::lane_sum(a, b);
    #[cfg(not(all(target_arch = "x86_64", target_feature = "avx")))]
    return lane_sum_portable(a, b);
}

/// `lane_sum` of four vectors with one `b` (of b's length), b read once.
#[inline(always)]
fn lane_sum4(a: [&[f64]; 4], b: &[f64]) -> [f64; 4] {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx"))]
    return super::lanes::lane_sum4(a, b);
    #[cfg(not(all(target_arch = "x86_64", target_feature = "avx")))]
    return lane_sum4_portable(a, b);
}

/// The portable form (where the build does not target AVX; the tests compare the two).
#[cfg_attr(target_feature = "avx", allow(dead_code))]
#[inline(always)]
pub(crate) fn lane_sum_portable(a: &[f64], b: &[f64]) -> f64 {
    let mut p = [0.0f64; 4];
    for (x, y) in a.chunks_exact(4).zip(b.chunks_exact(4)) {
        for k in 0..4 {
            p[k] += y[k] * x[k];
        }
    }
    (p[2] + p[0]) + (p[3] + p[1])
}

/// The portable form (where the build does not target AVX; the tests compare the two).
#[cfg_attr(target_feature = "avx", allow(dead_code))]
#[inline(always)]
pub(crate) fn lane_sum4_portable(a: [&[f64]; 4], b: &[f64]) -> [f64; 4] {
    let mut p = [[0.0f64; 4]; 4];
    for (c, y) in b.chunks_exact(4).enumerate() {
        for (pr, ar) in p.iter_mut().zip(&a) {
            let x = &ar[4 * c..4 * c + 4];
            for k in 0..4 {
                pr[k] += y[k] * x[k];
            }
        }
    }
    p.map(|p| (p[2] + p[0]) + (p[3] + p[1]))
}

/// `s` plus the products of the last (at most 3) elements, summed first.
#[inline(always)]
fn add_remainder(s: f64, ra: &[f64], rb: &[f64]) -> f64 {
    match ra.len() {
        3 => s + (ra[0] * rb[0] + ra[1] * rb[1] + ra[2] * rb[2]),
        2 => s + (ra[0] * rb[0] + ra[1] * rb[1]),
        1 => s + ra[0] * rb[0],
        _ => s,
    }
}

/// `dot(a, b, n)` for an `a` that is zero outside `lo..hi` and a finite `b`, over the blocks
/// that hold `lo..hi` only: the skipped terms are all +-0, and adding +-0 to a partial sum
/// (never -0) leaves it as it is, so the result is the same to the bit.
pub fn dot_span(a: &[f64], b: &[f64], n: usize, lo: usize, hi: usize) -> f64 {
    let n4 = n & !3;
    let (c0, c1) = ((lo & !3).min(n4), ((hi + 3) & !3).min(n4));
    let s = if c0 < c1 {
        lane_sum(&a[c0..c1], &b[c0..c1])
    } else {
        0.0
    };
    if hi > n4 {
        add_remainder(s, &a[n4..n], &b[n4..n])
    } else {
        s
    }
}

pub fn norm(vec: &[f64]) -> f64 {
    dot(vec, vec, vec.len()).sqrt()
}

/// Normalizes in place, returns the norm before; (1,0,..,0) when the norm is below MINVAL.
pub fn normalize(vec: &mut [f64]) -> f64 {
    let n = norm(vec);
    if n < MINVAL {
        if let Some((first, rest)) = vec.split_first_mut() {
            *first = 1.0;
            rest.fill(0.0);
        }
    } else {
        let inv = 1.0 / n;
        for x in vec.iter_mut() {
            *x *= inv;
        }
    }
    n
}

/// res (nr) = mat (nr x nc) * vec (nc)
pub fn mul_mat_vec(res: &mut [f64], mat: &[f64], vec: &[f64], nr: usize, nc: usize) {
    for r in 0..nr {
        res[r] = dot(&mat[r * nc..], vec, nc);
    }
}

/// res (nc) = mat^T * vec (nr), rows with zero weight skipped.
pub fn mul_mat_t_vec(res: &mut [f64], mat: &[f64], vec: &[f64], nr: usize, nc: usize) {
    mul_mat_t_vec_span(res, mat, vec, nr, nc, |_| (0, nc));
}

/// `mul_mat_t_vec` for a `mat` whose row r is zero outside `span(r)`: the same result to the
/// bit (res starts at +0 and never becomes -0, so adding +-0 leaves it); a row whose weight
/// is not finite is taken whole, as 0 * inf is not 0.
pub fn mul_mat_t_vec_span(
    res: &mut [f64],
    mat: &[f64],
    vec: &[f64],
    nr: usize,
    nc: usize,
    span: impl Fn(usize) -> (usize, usize),
) {
    let res = &mut res[..nc];
    zero(res);
    for r in 0..nr {
        let s = vec[r];
        if s != 0.0 {
            let (lo, hi) = if s.is_finite() { span(r) } else { (0, nc) };
            add_to_scl(&mut res[lo..hi], &mat[r * nc + lo..r * nc + hi], s);
        }
    }
}

/// res (nc x nr) = mat^T
pub fn transpose(res: &mut [f64], mat: &[f64], nr: usize, nc: usize) {
    for i in 0..nr {
        for j in 0..nc {
            res[j * nr + i] = mat[i * nc + j];
        }
    }
}

/// res (r1 x c2) = mat1 (r1 x c1) * mat2 (c1 x c2), zeros of mat1 skipped.
pub fn mul_mat_mat(res: &mut [f64], mat1: &[f64], mat2: &[f64], r1: usize, c1: usize, c2: usize) {
    zero(&mut res[..r1 * c2]);
    for i in 0..r1 {
        for k in 0..c1 {
            let s = mat1[i * c1 + k];
            if s != 0.0 {
                add_to_scl(
                    &mut res[i * c2..(i + 1) * c2],
                    &mat2[k * c2..(k + 1) * c2],
                    s,
                );
            }
        }
    }
}

/// `mul_mat_mat` on fixed sizes (same operations in the same order, unrolled by the compiler).
#[inline(always)]
pub fn mul_mat_mat_fixed<const R1: usize, const C1: usize, const C2: usize>(
    mat1: &[f64],
    mat2: &[f64],
) -> [[f64; C2]; R1] {
    let mut res = [[0.0; C2]; R1];
    for (i, row) in res.iter_mut().enumerate() {
        for k in 0..C1 {
            let s = mat1[i * C1 + k];
            if s != 0.0 {
                for (j, r) in row.iter_mut().enumerate() {
                    *r += mat2[k * C2 + j] * s;
                }
            }
        }
    }
    res
}

/// `mul_mat_t_mat` on fixed sizes (same operations in the same order).
#[inline(always)]
pub fn mul_mat_t_mat_fixed<const R1: usize, const C1: usize, const C2: usize>(
    mat1: &[f64],
    mat2: &[f64],
) -> [[f64; C2]; C1] {
    let mut res = [[0.0; C2]; C1];
    for i in 0..R1 {
        for (j, row) in res.iter_mut().enumerate() {
            let s = mat1[i * C1 + j];
            if s != 0.0 {
                for (k, r) in row.iter_mut().enumerate() {
                    *r += mat2[i * C2 + k] * s;
                }
            }
        }
    }
    res
}

/// res (r1 x r2) = mat1 (r1 x c1) * mat2^T (mat2 is r2 x c1).
pub fn mul_mat_mat_t(res: &mut [f64], mat1: &[f64], mat2: &[f64], r1: usize, c1: usize, r2: usize) {
    for i in 0..r1 {
        for j in 0..r2 {
            res[i * r2 + j] = dot(&mat1[i * c1..], &mat2[j * c1..], c1);
        }
    }
}

/// res (c1 x c2) = mat1^T * mat2 (mat1 is r1 x c1, mat2 r1 x c2), zeros of mat1 skipped.
pub fn mul_mat_t_mat(res: &mut [f64], mat1: &[f64], mat2: &[f64], r1: usize, c1: usize, c2: usize) {
    zero(&mut res[..c1 * c2]);
    for i in 0..r1 {
        for j in 0..c1 {
            let s = mat1[i * c1 + j];
            if s != 0.0 {
                add_to_scl(
                    &mut res[j * c2..(j + 1) * c2],
                    &mat2[i * c2..(i + 1) * c2],
                    s,
                );
            }
        }
    }
}

/// res (nc x nc) = mat^T * diag(d) * mat, or mat^T * mat without `diag`; mat is nr x nc.
/// The lower triangle is accumulated, then mirrored.
pub fn sqr_mat_td(res: &mut [f64], mat: &[f64], diag: Option<&[f64]>, nr: usize, nc: usize) {
    sqr_mat_td_lower(res, mat, diag, nr, nc);
    for i in 0..nc {
        for j in i + 1..nc {
            res[i * nc + j] = res[j * nc + i];
        }
    }
}

/// The lower triangle of `sqr_mat_td` (zeros above it), with the same values: enough for a
/// Cholesky factorization, which reads nothing above the diagonal.
pub fn sqr_mat_td_lower(res: &mut [f64], mat: &[f64], diag: Option<&[f64]>, nr: usize, nc: usize) {
    zero(&mut res[..nc * nc]);
    match diag {
        Some(d) => {
            for j in 0..nr {
                if d[j] != 0.0 {
                    for i in 0..nc {
                        let s = mat[j * nc + i];
                        if s != 0.0 {
                            add_to_scl(&mut res[i * nc..i * nc + i + 1], &mat[j * nc..], s * d[j]);
                        }
                    }
                }
            }
        }
        None => {
            for i in 0..nc {
                for j in 0..nr {
                    let s = mat[j * nc + i];
                    if s != 0.0 {
                        add_to_scl(&mut res[i * nc..i * nc + i + 1], &mat[j * nc..], s);
                    }
                }
            }
        }
    }
}
