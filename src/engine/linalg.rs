//! Dense vector kernels with the summation order of MuJoCo 2.2.2's BLAS-like helpers.

/// Dot product, summed in four interleaved partial sums as 2.2.2 does.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let mut res = 0.0;
    let mut i = 0;
    if n >= 4 {
        let (mut r0, mut r1, mut r2, mut r3) = (0.0, 0.0, 0.0, 0.0);
        while i + 4 <= n {
            r0 += a[i] * b[i];
            r1 += a[i + 1] * b[i + 1];
            r2 += a[i + 2] * b[i + 2];
            r3 += a[i + 3] * b[i + 3];
            i += 4;
        }
        res = (r0 + r2) + (r1 + r3);
    }
    match n - i {
        3 => res += a[i] * b[i] + a[i + 1] * b[i + 1] + a[i + 2] * b[i + 2],
        2 => res += a[i] * b[i] + a[i + 1] * b[i + 1],
        1 => res += a[i] * b[i],
        _ => {}
    }
    res
}

/// res += vec * s
#[inline]
pub fn add_to_scl(res: &mut [f64], vec: &[f64], s: f64) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r += v * s;
    }
}

/// res += vec
#[inline]
pub fn add_to(res: &mut [f64], vec: &[f64]) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r += v;
    }
}

/// res = mat * vec, mat nr x nc row-major.
pub fn mul_mat_vec(res: &mut [f64], mat: &[f64], vec: &[f64], nr: usize, nc: usize) {
    for r in 0..nr {
        res[r] = dot(&mat[r * nc..(r + 1) * nc], &vec[..nc]);
    }
}

/// res = mat' * vec, mat nr x nc row-major; zero entries of vec are skipped.
pub fn mul_mat_t_vec(res: &mut [f64], mat: &[f64], vec: &[f64], nr: usize, nc: usize) {
    res[..nc].fill(0.0);
    for r in 0..nr {
        let s = vec[r];
        if s != 0.0 {
            add_to_scl(&mut res[..nc], &mat[r * nc..(r + 1) * nc], s);
        }
    }
}

/// res = mat1 * mat2', mat1 r1 x c1, mat2 r2 x c1.
pub fn mul_mat_mat_t(res: &mut [f64], mat1: &[f64], mat2: &[f64], r1: usize, c1: usize, r2: usize) {
    for i in 0..r1 {
        for j in 0..r2 {
            res[i * r2 + j] = dot(&mat1[i * c1..(i + 1) * c1], &mat2[j * c1..(j + 1) * c1]);
        }
    }
}

/// NaN or beyond +-1e10.
#[inline]
pub fn is_bad(x: f64) -> bool {
    x.is_nan() || !(-super::MAXVAL..=super::MAXVAL).contains(&x)
}

/// Clamp as mju_clip does (NaN passes through).
#[inline]
pub fn clip(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}

/// mju_min: `a` on ties.
#[inline]
pub fn min(a: f64, b: f64) -> f64 {
    if a <= b {
        a
    } else {
        b
    }
}

/// mju_max: `a` on ties.
#[inline]
pub fn max(a: f64, b: f64) -> f64 {
    if a >= b {
        a
    } else {
        b
    }
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
