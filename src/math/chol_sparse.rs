//! Sparse reverse-order Cholesky (mat = L'*L, rows ending at the diagonal) and sparse LU
//! without fill-in, as 2.2.2 uses for the Newton solver and the implicit integrator.

use super::sparse::{combine_sparse, dot_sparse, same_pattern};
use super::MINVAL;

#[inline]
fn u(i: i32) -> usize {
    i as usize
}

/// Row slices of two distinct, non-overlapping rows of one array: (dst at `ad`, src at `as_`).
fn two_rows<T>(a: &mut [T], ad: usize, as_: usize) -> (&mut [T], &[T]) {
    if ad < as_ {
        let (lo, hi) = a.split_at_mut(as_);
        (&mut lo[ad..], hi)
    } else {
        let (lo, hi) = a.split_at_mut(ad);
        (hi, &lo[as_..])
    }
}

/// Factorizes in place; `mat` must have the uncompressed layout (room for fill-in in each row).
/// rownnz is shrunk so that every row ends at its diagonal. Diagonals below `mindiag` are
/// replaced by it; returns n minus their number. `buf` and `buf_ind` are scratch of size n.
#[allow(clippy::too_many_arguments)]
pub fn chol_factor_sparse(
    mat: &mut [f64],
    n: usize,
    mindiag: f64,
    rownnz: &mut [i32],
    rowadr: &[i32],
    colind: &mut [i32],
    buf: &mut [f64],
    buf_ind: &mut [i32],
) -> Result<usize, &'static str> {
    let mut rank = n;
    for r in 0..n {
        let a = u(rowadr[r]);
        while rownnz[r] > 0 && u(colind[a + u(rownnz[r]) - 1]) > r {
            rownnz[r] -= 1;
        }
        if rownnz[r] == 0 || u(colind[a + u(rownnz[r]) - 1]) != r {
            return Err("Matrix must have non-zero diagonal in mju_cholFactorSparse");
        }
    }

    for r in (0..n).rev() {
        let (nnz, adr) = (u(rownnz[r]), u(rowadr[r]));
        rank -= scale_row(&mut mat[adr..adr + nnz], mindiag);

        // row c -= L(r,c) * L(r, 0:c) for every c < r with L(r,c) != 0
        for i in 0..nnz - 1 {
            let c = u(colind[adr + i]);
            let ac = u(rowadr[c]);
            let scl = -mat[adr + i];
            let (dst, src) = two_rows(mat, ac, adr);
            let (dst_ind, src_ind) = two_rows(colind, ac, adr);
            let nnz_c = combine_sparse(
                dst,
                src,
                c + 1,
                1.0,
                scl,
                u(rownnz[c]),
                i + 1,
                dst_ind,
                src_ind,
                buf,
                buf_ind,
            );
            rownnz[c] = nnz_c as i32;
        }
    }
    Ok(rank)
}

/// Row r of the factor from what the rows below left of H's: its diagonal (the last entry;
/// `mindiag` where below it) to its square root, the entries before it times the root's
/// reciprocal. Returns 1 where the diagonal was replaced, else 0.
#[inline]
fn scale_row(row: &mut [f64], mindiag: f64) -> usize {
    let (rest, diag) = row.split_at_mut(row.len() - 1);
    let low = diag[0] < mindiag;
    diag[0] = if low { mindiag } else { diag[0] }.sqrt();
    let inv = 1.0 / diag[0];
    for x in rest {
        *x *= inv;
    }
    usize::from(low)
}

/// Lays out the pattern of `chol_factor_sparse`'s factor of H = J'*D*J + M ahead of the
/// values. In: the rows of J'*D*J's pattern (rownnz, rowadr, colind: lower triangle,
/// ascending, packed at the front of colind). Out: the factor's rows, ascending, one after
/// another at the end of colind (less 4n ints of scratch): row r holds its J'*D*J columns,
/// stored as `!col` (marked, see `chol_sparse_values`), M's (its diagonal, and r's ancestors
/// in `parent` where `simple[r]` is 0) and the fill-in of the factorization, which row r takes
/// from its children in the elimination tree (the rows whose largest index below the diagonal
/// is r). Returns false when the rows do not fit beside the input.
pub fn chol_sparse_pattern(
    n: usize,
    rownnz: &mut [i32],
    rowadr: &mut [i32],
    colind: &mut [i32],
    parent: &[i32],
    simple: &[i32],
) -> bool {
    let Some(len) = colind.len().checked_sub(4 * n) else {
        return false;
    };
    let (rows, work) = colind.split_at_mut(len);
    let (head, work) = work.split_at_mut(n);
    let (next, work) = work.split_at_mut(n);
    let (mut a, mut b) = work.split_at_mut(n);
    head.fill(-1);
    let mut top = len;
    for r in (0..n).rev() {
        let ri = r as i32;
        // M's columns, ascending, in b
        let mut nm = 0;
        let mut j = ri;
        while j >= 0 {
            b[nm] = j;
            nm += 1;
            if simple[r] != 0 {
                break;
            }
            j = parent[u(j)];
        }
        b[..nm].reverse();
        // with J'*D*J's (marked) in a
        let (start, end) = (u(rowadr[r]), u(rowadr[r]) + u(rownnz[r]));
        if end > len {
            return false;
        }
        let own = &rows[start..end];
        let mut na = merge_marked(own, &b[..nm], a, true);
        // and each child's, less its diagonal
        let mut ch = head[r];
        while ch >= 0 {
            let cu = u(ch);
            let at = u(rowadr[cu]);
            let theirs = &rows[at..at + u(rownnz[cu]) - 1];
            na = merge_marked(&a[..na], theirs, b, false);
            std::mem::swap(&mut a, &mut b);
            ch = next[cu];
        }
        // rows below r still hold their input below row r's
        if top < start + na {
            return false;
        }
        top -= na;
        rows[top..top + na].copy_from_slice(&a[..na]);
        rowadr[r] = top as i32;
        rownnz[r] = na as i32;
        if na >= 2 {
            let up = u(unmark(a[na - 2]));
            next[r] = head[up];
            head[up] = ri;
        }
    }
    true
}

/// A column stored marked (`!col`) or not, as the column.
#[inline]
fn unmark(v: i32) -> i32 {
    v ^ (v >> 31)
}

/// Merges two ascending column lists into `out` (duplicates once) and returns its length.
/// `x` may hold marked columns (`!col`), which stay marked; with `mark_y` the columns of y
/// are marked (J'*D*J's own), else y's marks are dropped (a child's).
fn merge_marked(x: &[i32], y: &[i32], out: &mut [i32], mark_y: bool) -> usize {
    let yv = |v: i32| if mark_y { !unmark(v) } else { unmark(v) };
    let (mut i, mut k, mut nout) = (0, 0, 0);
    while i < x.len() && k < y.len() {
        let (cx, cy) = (unmark(x[i]), unmark(y[k]));
        out[nout] = if cx < cy {
            i += 1;
            x[i - 1]
        } else if cy < cx {
            k += 1;
            yv(y[k - 1])
        } else {
            i += 1;
            k += 1;
            if mark_y {
                !cx
            } else {
                x[i - 1]
            }
        };
        nout += 1;
    }
    for &v in &x[i..] {
        out[nout] = v;
        nout += 1;
    }
    for &v in &y[k..] {
        out[nout] = yv(v);
        nout += 1;
    }
    nout
}

/// Values of the rows `chol_sparse_pattern` laid out: each row's values come from
/// `row(r, buffer)`, which adds row r of H into `buffer` (the columns of J'*D*J set to 0,
/// every other column of the row to -0, the value 2.2.2's merge of a new column gives:
/// -0 + x is x bit for bit). The marks are removed.
pub fn chol_sparse_values(
    mat: &mut [f64],
    n: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &mut [i32],
    buffer: &mut [f64],
    mut row: impl FnMut(usize, &mut [f64]),
) {
    for r in 0..n {
        let (adr, nnz) = (u(rowadr[r]), u(rownnz[r]));
        for c in &mut colind[adr..adr + nnz] {
            // 0 for a marked column, else -0 (the sign bit of the unmarked)
            let v = *c;
            *c = unmark(v);
            buffer[u(*c)] = f64::from_bits(u64::from(v >= 0) << 63);
        }
        row(r, buffer);
        for (x, &c) in mat[adr..adr + nnz].iter_mut().zip(&colind[adr..adr + nnz]) {
            *x = buffer[u(c)];
        }
    }
}

/// `chol_factor_sparse` on rows whose pattern already holds the factor's
/// (`chol_sparse_pattern`): each update of a row adds into columns it has, in place, the
/// same sums in the same order. Errors if a row lacks its diagonal or an update's column.
pub fn chol_factor_sparse_preset(
    mat: &mut [f64],
    n: usize,
    mindiag: f64,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) -> Result<usize, &'static str> {
    let mut rank = n;
    for r in (0..n).rev() {
        let (nnz, adr) = (u(rownnz[r]), u(rowadr[r]));
        if nnz == 0 || u(colind[adr + nnz - 1]) != r {
            return Err("Matrix must have non-zero diagonal in mju_cholFactorSparse");
        }
        rank -= scale_row(&mut mat[adr..adr + nnz], mindiag);

        // row c += -L(r,c) * L(r, 0:c) for every c < r with L(r,c) != 0 (rows c lie below r)
        let (below, from_r) = mat.split_at_mut(adr);
        let src = &from_r[..nnz];
        let src_ind = &colind[adr..adr + nnz];
        for i in 0..nnz - 1 {
            let c = u(src_ind[i]);
            let (ac, nc) = (u(rowadr[c]), u(rownnz[c]));
            let scl = -src[i];
            let dst = &mut below[ac..ac + nc];
            if nc == i + 1 {
                for (x, &y) in dst.iter_mut().zip(&src[..=i]) {
                    *x += scl * y;
                }
                continue;
            }
            let dst_ind = &colind[ac..ac + nc];
            let mut k = 0;
            for (&y, &yc) in src[..=i].iter().zip(&src_ind[..=i]) {
                while k < nc && dst_ind[k] != yc {
                    k += 1;
                }
                if k == nc {
                    return Err("Varying sparsity pattern in mju_cholFactorSparse");
                }
                dst[k] += scl * y;
                k += 1;
            }
        }
    }
    Ok(rank)
}

/// res = (L'*L)^-1 * vec for the factor of `chol_factor_sparse`.
pub fn chol_solve_sparse(
    res: &mut [f64],
    mat: &[f64],
    vec: &[f64],
    n: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) {
    res[..n].copy_from_slice(&vec[..n]);
    chol_solve_sparse_in_place(res, mat, n, rownnz, rowadr, colind);
}

/// In-place form of `chol_solve_sparse`. Where the rows split into two blocks that share no
/// column (no row past the split reaches before it: separate trees of the factor), the two run
/// side by side, a row of each in turn, so that their chains of divisions overlap; each value
/// takes its updates in the same order as one pass over all rows.
pub fn chol_solve_sparse_in_place(
    res: &mut [f64],
    mat: &[f64],
    n: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) {
    let split = independent_split(n, rownnz, rowadr, colind);
    let f = Factor {
        mat,
        rownnz,
        rowadr,
        colind,
    };
    let (lo, hi) = (split, n - split);
    for k in 1..=hi {
        if k <= lo {
            f.back(res, lo - k);
        }
        f.back(res, n - k);
    }
    for k in 0..hi {
        if k < lo {
            f.fore(res, k);
        }
        f.fore(res, split + k);
    }
}

/// A sparse factor's rows, the diagonal last in each.
struct Factor<'a> {
    mat: &'a [f64],
    rownnz: &'a [i32],
    rowadr: &'a [i32],
    colind: &'a [i32],
}

impl Factor<'_> {
    #[inline(always)]
    fn row(&self, i: usize) -> (&[f64], &[i32]) {
        let (adr, nnz) = (u(self.rowadr[i]), u(self.rownnz[i]));
        (&self.mat[adr..adr + nnz], &self.colind[adr..adr + nnz - 1])
    }

    /// Row i of x <- L'^-1 x (rows from the last): x_i divided, then scattered into its columns.
    #[inline(always)]
    fn back(&self, res: &mut [f64], i: usize) {
        if res[i] != 0.0 {
            let (l, cols) = self.row(i);
            res[i] /= l[l.len() - 1];
            let t = res[i];
            for (&c, &v) in cols.iter().zip(l) {
                res[u(c)] -= v * t;
            }
        }
    }

    /// Row i of x <- L^-1 x (rows from the first): its columns gathered, then the division.
    #[inline(always)]
    fn fore(&self, res: &mut [f64], i: usize) {
        let (l, cols) = self.row(i);
        if !cols.is_empty() {
            let s = dot_sparse(l, res, cols.len(), cols);
            res[i] -= s;
        }
        res[i] /= l[l.len() - 1];
    }
}

/// The row nearest n/2, at or below it, before which no later row has a column (0: none).
fn independent_split(n: usize, rownnz: &[i32], rowadr: &[i32], colind: &[i32]) -> usize {
    let mut first = n;
    for i in (1..n).rev() {
        // a row's columns ascend; its first is the smallest
        let c = if rownnz[i] > 1 {
            u(colind[u(rowadr[i])])
        } else {
            i
        };
        first = first.min(c);
        if i <= n / 2 && first >= i {
            return i;
        }
    }
    0
}

/// Rank-one update L'*L +/- x*x' of the factor, x sparse (x_nnz values at x_ind, both
/// overwritten). The sparsity pattern of mat must not change. `buf`/`buf_ind`: scratch of n.
#[allow(clippy::too_many_arguments)]
pub fn chol_update_sparse(
    mat: &mut [f64],
    x: &mut [f64],
    n: usize,
    flg_plus: bool,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
    x_nnz: usize,
    x_ind: &mut [i32],
    buf: &mut [f64],
    buf_ind: &mut [i32],
) -> Result<usize, &'static str> {
    let mut rank = n;
    let mut i = x_nnz as isize - 1;
    while i >= 0 {
        let iu = i as usize;
        let row = u(x_ind[iu]);
        let (nnz, adr) = (u(rownnz[row]), u(rowadr[row]));
        let diag = mat[adr + nnz - 1];
        let mut t = diag * diag
            + if flg_plus {
                x[iu] * x[iu]
            } else {
                -x[iu] * x[iu]
            };
        if t < MINVAL {
            t = MINVAL;
            rank -= 1;
        }
        let r = t.sqrt();
        let c = r / diag;
        let s = x[iu] / diag;
        mat[adr + nnz - 1] = r;

        // row = (row + s*x)/c, pattern unchanged
        let new_nnz = combine_sparse_fixed(
            &mut mat[adr..],
            x,
            n,
            1.0 / c,
            if flg_plus { s / c } else { -s / c },
            nnz - 1,
            iu,
            &colind[adr..],
            x_ind,
            buf,
            buf_ind,
        );
        if new_nnz != nnz - 1 {
            return Err("Varying sparsity pattern in mju_cholUpdateSparse");
        }

        // x = c*x - s*row
        let new_x_nnz = combine_sparse(
            x,
            &mat[adr..],
            n,
            c,
            -s,
            iu,
            nnz - 1,
            x_ind,
            &colind[adr..],
            buf,
            buf_ind,
        );
        i = i - 1 + (new_x_nnz as isize - i);
    }
    Ok(rank)
}

/// `combine_sparse` on a destination whose index array must stay as is: the merged pattern is
/// computed in scratch and only its size is reported, values are written as 2.2.2 writes them.
#[allow(clippy::too_many_arguments)]
fn combine_sparse_fixed(
    dst: &mut [f64],
    src: &[f64],
    n: usize,
    a: f64,
    b: f64,
    dst_nnz: usize,
    src_nnz: usize,
    dst_ind: &[i32],
    src_ind: &[i32],
    buf: &mut [f64],
    buf_ind: &mut [i32],
) -> usize {
    if dst_nnz == src_nnz && same_pattern(&dst_ind[..dst_nnz], &src_ind[..src_nnz]) {
        for (d, s) in dst[..dst_nnz].iter_mut().zip(src) {
            *d = *d * a + s * b;
        }
        return dst_nnz;
    }
    buf[..dst_nnz].copy_from_slice(&dst[..dst_nnz]);
    buf_ind[..dst_nnz].copy_from_slice(&dst_ind[..dst_nnz]);
    let end = n as i32 + 1;
    let adr = |ind: &[i32], i: usize, len: usize| if i < len { ind[i] } else { end };
    let (mut bi, mut si, mut nnz) = (0, 0, 0);
    let mut badr = adr(buf_ind, bi, dst_nnz);
    let mut sadr = adr(src_ind, si, src_nnz);
    while bi < dst_nnz || si < src_nnz {
        let v = if badr == sadr {
            let v = a * buf[bi] + b * src[si];
            bi += 1;
            si += 1;
            v
        } else if badr < sadr {
            let v = a * buf[bi];
            bi += 1;
            v
        } else {
            let v = b * src[si];
            si += 1;
            v
        };
        if nnz < dst.len() {
            dst[nnz] = v;
        }
        nnz += 1;
        badr = adr(buf_ind, bi, dst_nnz);
        sadr = adr(src_ind, si, src_nnz);
    }
    nnz
}

/// Sparse LU without fill-in (tree topology), reverse order: LU holds L + U with the original
/// matrix = (U+I)*L. `scratch` needs n ints.
pub fn factor_lu_sparse(
    lu: &mut [f64],
    n: usize,
    scratch: &mut [i32],
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) -> Result<(), &'static str> {
    let remaining = &mut scratch[..n];
    remaining.copy_from_slice(&rownnz[..n]);
    for i in (0..n).rev() {
        let ii = (rowadr[i] + remaining[i] - 1) as usize;
        remaining[i] -= 1;
        if u(colind[ii]) != i {
            return Err("missing diagonal element in mju_factorLUSparse");
        }
        if lu[ii].abs() < MINVAL {
            return Err("diagonal element too small in mju_factorLUSparse");
        }
        for j in (0..i).rev() {
            let ji = rowadr[j] + remaining[j] - 1;
            if ji < 0 || u(colind[u(ji)]) != i {
                continue;
            }
            let ji = u(ji);
            remaining[j] -= 1;
            lu[ji] /= lu[ii];
            let luji = lu[ji];
            let (mut icnt, mut jcnt) = (u(rowadr[i]), u(rowadr[j]));
            let jend = u(rowadr[j] + remaining[j]);
            while jcnt < jend {
                if colind[icnt] == colind[jcnt] {
                    lu[jcnt] -= lu[icnt] * luji;
                    icnt += 1;
                    jcnt += 1;
                } else if colind[icnt] > colind[jcnt] {
                    jcnt += 1;
                } else {
                    return Err("mju_factorLUSparse requires fill-in");
                }
            }
            if icnt != u(rowadr[i] + remaining[i]) || jcnt != jend {
                return Err("row processing incomplete in mju_factorLUSparse");
            }
        }
    }
    for i in 0..n {
        if remaining[i] < 0 || u(colind[u(rowadr[i] + remaining[i])]) != i {
            return Err("unexpected sparse matrix structure in mju_factorLUSparse");
        }
    }
    Ok(())
}

/// Solves mat*res = vec given the factor of `factor_lu_sparse`.
pub fn solve_lu_sparse(
    res: &mut [f64],
    lu: &[f64],
    vec: &[f64],
    n: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) -> Result<(), &'static str> {
    for i in (0..n).rev() {
        res[i] = vec[i];
        let a = u(rowadr[i]);
        let mut j = rownnz[i] as isize - 1;
        while u(colind[a + j as usize]) > i {
            let k = a + j as usize;
            res[i] -= res[u(colind[k])] * lu[k];
            j -= 1;
        }
        if u(colind[a + j as usize]) != i {
            return Err("diagonal of U not reached in mju_factorLUSparse");
        }
    }
    for i in 0..n {
        let a = u(rowadr[i]);
        let mut j = 0;
        while u(colind[a + j]) < i {
            res[i] -= res[u(colind[a + j])] * lu[a + j];
            j += 1;
        }
        res[i] /= lu[a + j];
        if u(colind[a + j]) != i {
            return Err("diagonal of L not reached in mju_factorLUSparse");
        }
    }
    Ok(())
}
