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
        let mut d = mat[adr + nnz - 1];
        if d < mindiag {
            d = mindiag;
            rank -= 1;
        }
        mat[adr + nnz - 1] = d.sqrt();
        let inv = 1.0 / mat[adr + nnz - 1];
        for x in &mut mat[adr..adr + nnz - 1] {
            *x *= inv;
        }

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

/// Sizes of the rows of `chol_factor_sparse`'s factor, from the pattern alone: row r holds
/// its own (rownnz, rowadr, colind: lower triangle, any order), its diagonal, r's ancestors in
/// `parent` where `simple[r]` is 0 (the mass matrix's pattern), and the fill-in, which the
/// factorization takes from every row whose pattern holds r. Sizes go to `count`; `work`
/// takes 4n ints and the rows' patterns. Returns their total, or None when `work` is too
/// small.
#[allow(clippy::too_many_arguments)]
pub fn chol_sparse_counts(
    n: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
    parent: &[i32],
    simple: &[i32],
    count: &mut [i32],
    work: &mut [i32],
) -> Option<usize> {
    let len = work.len().checked_sub(4 * n)?;
    let (lists, rest) = work.split_at_mut(len);
    let (mark, rest) = rest.split_at_mut(n);
    let (head, rest) = rest.split_at_mut(n);
    let (next, start) = rest.split_at_mut(n);
    mark.fill(-1);
    head.fill(-1);
    // each row's pattern goes (unordered) below the one before, from the end of `lists`; the
    // fill of row r comes from its children in the elimination tree (the rows whose largest
    // index below the diagonal is r), whose patterns are read once, there
    let mut top = len;
    for r in (0..n).rev() {
        let ri = r as i32;
        let end = top;
        let mut up = -1;
        let mut add = |j: i32, lists: &mut [i32], top: &mut usize| -> Option<()> {
            if mark[u(j)] != ri {
                mark[u(j)] = ri;
                *top = top.checked_sub(1)?;
                lists[*top] = j;
                if j < ri && j > up {
                    up = j;
                }
            }
            Some(())
        };
        add(ri, lists, &mut top)?;
        let a = u(rowadr[r]);
        for &j in &colind[a..a + u(rownnz[r])] {
            add(j, lists, &mut top)?;
        }
        if simple[r] == 0 {
            let mut j = parent[r];
            while j >= 0 {
                add(j, lists, &mut top)?;
                j = parent[u(j)];
            }
        }
        let mut c = head[r];
        while c >= 0 {
            let cu = u(c);
            let s = u(start[cu]);
            for k in s..s + u(count[cu]) {
                let j = lists[k];
                if j != c {
                    add(j, lists, &mut top)?;
                }
            }
            c = next[cu];
        }
        count[r] = (end - top) as i32;
        start[r] = top as i32;
        if up >= 0 {
            next[r] = head[u(up)];
            head[u(up)] = ri;
        }
    }
    Some(len - top)
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

/// In-place form of `chol_solve_sparse`.
pub fn chol_solve_sparse_in_place(
    res: &mut [f64],
    mat: &[f64],
    n: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) {
    for i in (0..n).rev() {
        if res[i] != 0.0 {
            let (adr, nnz) = (u(rowadr[i]), u(rownnz[i]));
            res[i] /= mat[adr + nnz - 1];
            let t = res[i];
            for (&c, &l) in colind[adr..adr + nnz - 1]
                .iter()
                .zip(&mat[adr..adr + nnz - 1])
            {
                res[u(c)] -= l * t;
            }
        }
    }
    for i in 0..n {
        let (adr, nnz) = (u(rowadr[i]), u(rownnz[i]));
        if nnz > 1 {
            let s = dot_sparse(&mat[adr..adr + nnz], res, nnz - 1, &colind[adr..adr + nnz]);
            res[i] -= s;
        }
        res[i] /= mat[adr + nnz - 1];
    }
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
