//! Dense Cholesky factorization, solve and rank-one update (lower triangle, in place).

use super::blas::{dot, dot4};
use super::MINVAL;

/// Factorizes the n x n matrix in place as L*L' (L in the lower triangle; the strict upper
/// triangle is left untouched). Diagonal values below `mindiag` are replaced by it;
/// returns n minus the number of replacements.
pub fn chol_factor(mat: &mut [f64], n: usize, mindiag: f64) -> usize {
    let mut rank = n;
    for j in 0..n {
        let mut d = mat[j * (n + 1)];
        if j > 0 {
            d -= dot(&mat[j * n..], &mat[j * n..], j);
        }
        if d < mindiag {
            d = mindiag;
            rank -= 1;
        }
        mat[j * (n + 1)] = d.sqrt();
        let inv = 1.0 / mat[j * (n + 1)];
        // the rows below: four at a time share the loads of row j (each sum in dot's order)
        let (head, below) = mat.split_at_mut((j + 1) * n);
        let rowj = &head[j * n..j * n + j];
        let mut quads = below.chunks_exact_mut(4 * n);
        for q in &mut quads {
            let s = dot4(
                [
                    &q[..j],
                    &q[n..n + j],
                    &q[2 * n..2 * n + j],
                    &q[3 * n..3 * n + j],
                ],
                rowj,
                j,
            );
            for (r, s) in s.iter().enumerate() {
                q[r * n + j] = (q[r * n + j] - s) * inv;
            }
        }
        for row in quads.into_remainder().chunks_exact_mut(n) {
            let s = dot(&row[..j], rowj, j);
            row[j] = (row[j] - s) * inv;
        }
    }
    rank
}

/// Solves L*L' * x = x in place, given the factor from `chol_factor`.
pub fn chol_solve_in_place(mat: &[f64], x: &mut [f64], n: usize) {
    let (mat, x) = (&mat[..n * n], &mut x[..n]);
    for i in 0..n {
        if i > 0 {
            let s = dot(&mat[i * n..], x, i);
            x[i] -= s;
        }
        x[i] /= mat[i * (n + 1)];
    }
    for i in (0..n).rev() {
        // x[i] -= L[j][i] * x[j] for j > i, in increasing j
        let (head, tail) = x.split_at_mut(i + 1);
        let mut xi = head[i];
        for (row, xj) in mat[(i + 1) * n..].chunks_exact(n).zip(tail.iter()) {
            xi -= row[i] * xj;
        }
        head[i] = xi / mat[i * (n + 1)];
    }
}

/// res = (L*L')^-1 * vec.
pub fn chol_solve(res: &mut [f64], mat: &[f64], vec: &[f64], n: usize) {
    res[..n].copy_from_slice(&vec[..n]);
    chol_solve_in_place(mat, res, n);
}

/// Updates the factor to that of L*L' + x*x' (flg_plus) or L*L' - x*x'; `x` is overwritten.
/// Returns n minus the number of diagonals clamped to MINVAL.
pub fn chol_update(mat: &mut [f64], x: &mut [f64], n: usize, flg_plus: bool) -> usize {
    let mut rank = n;
    let (mat, x) = (&mut mat[..n * n], &mut x[..n]);
    for k in 0..n {
        update_column(mat, x, n, k, flg_plus, &mut rank);
    }
    rank
}

/// Two rank-one updates in turn, x1's and then x2's, as two calls of `chol_update` would make
/// them; x2's runs one column behind x1's, so that their chains of dependent operations
/// overlap (column k of x2's update needs only column k of x1's). Returns both ranks.
pub fn chol_update2(
    mat: &mut [f64],
    x1: &mut [f64],
    plus1: bool,
    x2: &mut [f64],
    plus2: bool,
    n: usize,
) -> (usize, usize) {
    let (mut rank1, mut rank2) = (n, n);
    let (mat, x1, x2) = (&mut mat[..n * n], &mut x1[..n], &mut x2[..n]);
    for k in 0..=n {
        if k < n {
            update_column(mat, x1, n, k, plus1, &mut rank1);
        }
        if k > 0 {
            update_column(mat, x2, n, k - 1, plus2, &mut rank2);
        }
    }
    (rank1, rank2)
}

/// Column k of a rank-one update: L(k..n, k) and x(k+1..n).
#[inline(always)]
fn update_column(
    mat: &mut [f64],
    x: &mut [f64],
    n: usize,
    k: usize,
    flg_plus: bool,
    rank: &mut usize,
) {
    let xk = x[k];
    if xk == 0.0 {
        return;
    }
    let lkk = mat[k * (n + 1)];
    let mut t = lkk * lkk + if flg_plus { xk * xk } else { -xk * xk };
    if t < MINVAL {
        t = MINVAL;
        *rank -= 1;
    }
    let r = t.sqrt();
    let c = r / lkk;
    let cinv = 1.0 / c;
    let s = xk / lkk;
    mat[k * (n + 1)] = r;
    // column k below the diagonal, then x from the updated column: each row i > k uses
    // only its own entries, so both passes run row by row
    let rows = mat[(k + 1) * n..]
        .chunks_exact_mut(n)
        .zip(x[k + 1..].iter_mut());
    if flg_plus {
        for (row, xi) in rows {
            let m = (row[k] + s * *xi) * cinv;
            row[k] = m;
            *xi = c * *xi - s * m;
        }
    } else {
        for (row, xi) in rows {
            let m = (row[k] - s * *xi) * cinv;
            row[k] = m;
            *xi = c * *xi - s * m;
        }
    }
}
