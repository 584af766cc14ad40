//! Sparse row-compressed matrices: row i holds `rownnz[i]` values at `mat[rowadr[i]..]` with
//! increasing column indices `colind[rowadr[i]..]`. Index arrays are `i32` as in mjData.
//! Summation orders are those of 2.2.2's scalar (non-AVX) build.

#[inline]
fn u(i: i32) -> usize {
    i as usize
}

/// Do two index lists of equal length match? (Inline: short lists, no library call.)
#[inline]
pub fn same_pattern(a: &[i32], b: &[i32]) -> bool {
    let mut same = a.len() == b.len();
    for (x, y) in a.iter().zip(b) {
        same &= x == y;
    }
    same
}

/// vec1 (sparse, nnz1 values at indices ind1) . vec2 (dense), summed left to right.
pub fn dot_sparse(vec1: &[f64], vec2: &[f64], nnz1: usize, ind1: &[i32]) -> f64 {
    let mut s = 0.0;
    for (v, &i) in vec1[..nnz1].iter().zip(&ind1[..nnz1]) {
        s += v * vec2[u(i)];
    }
    s
}

/// Dot product of two sparse vectors.
pub fn dot_sparse2(
    vec1: &[f64],
    vec2: &[f64],
    nnz1: usize,
    ind1: &[i32],
    nnz2: usize,
    ind2: &[i32],
) -> f64 {
    let (mut i1, mut i2) = (0, 0);
    let mut s = 0.0;
    while i1 < nnz1 && i2 < nnz2 {
        let (a1, a2) = (ind1[i1], ind2[i2]);
        if a1 == a2 {
            s += vec1[i1] * vec2[i2];
            i1 += 1;
            i2 += 1;
        } else if a1 < a2 {
            i1 += 1;
        } else {
            i2 += 1;
        }
    }
    s
}

/// Dense nr x nc matrix to compressed sparse (exact zeros dropped).
pub fn dense2sparse(
    res: &mut [f64],
    mat: &[f64],
    nr: usize,
    nc: usize,
    rownnz: &mut [i32],
    rowadr: &mut [i32],
    colind: &mut [i32],
) {
    let mut adr = 0;
    for r in 0..nr {
        rownnz[r] = 0;
        rowadr[r] = adr as i32;
        for c in 0..nc {
            let v = mat[r * nc + c];
            if v != 0.0 {
                colind[adr] = c as i32;
                rownnz[r] += 1;
                res[adr] = v;
                adr += 1;
            }
        }
    }
}

/// Sparse to dense nr x nc.
pub fn sparse2dense(
    res: &mut [f64],
    mat: &[f64],
    nr: usize,
    nc: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) {
    res[..nr * nc].fill(0.0);
    for r in 0..nr {
        let adr = u(rowadr[r]);
        for i in 0..u(rownnz[r]) {
            res[r * nc + u(colind[adr + i])] = mat[adr + i];
        }
    }
}

/// res (nr) = sparse mat * dense vec. Each row is summed left to right; consecutive rows
/// with the same pattern are summed side by side (the same sums, computed together). Those
/// runs come from `rowsuper` (rows following each row with its pattern, as `super_sparse`
/// makes it) when the caller has one it made itself, else from comparing the patterns.
#[allow(clippy::too_many_arguments)]
pub fn mul_mat_vec_sparse(
    res: &mut [f64],
    mat: &[f64],
    vec: &[f64],
    nr: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
    rowsuper: Option<&[i32]>,
) {
    let mut r = 0;
    while r < nr {
        if rownnz[r] <= 0 {
            res[r] = 0.0;
            r += 1;
            continue;
        }
        let (adr, nnz) = (u(rowadr[r]), u(rownnz[r]));
        let ind = &colind[adr..adr + nnz];
        // rows r.. sharing the pattern, up to 4
        let run = match rowsuper {
            Some(sup) => (u(sup[r].max(0)) + 1).min(4).min(nr - r),
            None => {
                let same = |q: usize| {
                    q < nr && rownnz[q] == rownnz[r] && {
                        let a = u(rowadr[q]);
                        same_pattern(&colind[a..a + nnz], ind)
                    }
                };
                1 + (1..4).take_while(|&k| same(r + k)).count()
            }
        };
        let rows = &mut res[r..r + run];
        match run {
            4 => rows_times_vec::<4>(rows, mat, vec, &rowadr[r..], ind),
            3 => rows_times_vec::<3>(rows, mat, vec, &rowadr[r..], ind),
            2 => rows_times_vec::<2>(rows, mat, vec, &rowadr[r..], ind),
            _ => rows[0] = dot_sparse(&mat[adr..adr + nnz], vec, nnz, ind),
        }
        r += run;
    }
}

/// N rows of one pattern `ind` (at rowadr[0..N]) times vec, each summed left to right.
fn rows_times_vec<const N: usize>(
    res: &mut [f64],
    mat: &[f64],
    vec: &[f64],
    rowadr: &[i32],
    ind: &[i32],
) {
    let nnz = ind.len();
    let m: [&[f64]; N] = std::array::from_fn(|q| &mat[u(rowadr[q])..u(rowadr[q]) + nnz]);
    let mut s = [0.0; N];
    for (k, &i) in ind.iter().enumerate() {
        let x = vec[u(i)];
        for q in 0..N {
            s[q] += m[q][k] * x;
        }
    }
    res[..N].copy_from_slice(&s);
}

/// res = res*a + vec*b
fn add_to_scl_scl(res: &mut [f64], vec: &[f64], a: f64, b: f64) {
    for (r, v) in res.iter_mut().zip(vec) {
        *r = *r * a + v * b;
    }
}

/// dst = a*dst + b*src for sparse vectors of dimension n; the pattern of dst becomes the union.
/// `buf`/`buf_ind` are scratch of at least dst_nnz. Returns the new nnz of dst.
#[allow(clippy::too_many_arguments)]
pub fn combine_sparse(
    dst: &mut [f64],
    src: &[f64],
    n: usize,
    a: f64,
    b: f64,
    dst_nnz: usize,
    src_nnz: usize,
    dst_ind: &mut [i32],
    src_ind: &[i32],
    buf: &mut [f64],
    buf_ind: &mut [i32],
) -> usize {
    if dst_nnz == src_nnz && same_pattern(&dst_ind[..dst_nnz], &src_ind[..src_nnz]) {
        add_to_scl_scl(&mut dst[..dst_nnz], &src[..dst_nnz], a, b);
        return dst_nnz;
    }
    // in place while every src index so far is in dst (the common case in factorizations)
    let (mut k, mut si) = (0, 0);
    while k < dst_nnz {
        let sadr = if si < src_nnz { src_ind[si] } else { i32::MAX };
        let dadr = dst_ind[k];
        if sadr == dadr {
            dst[k] = a * dst[k] + b * src[si];
            si += 1;
        } else if sadr < dadr {
            break;
        } else {
            dst[k] *= a;
        }
        k += 1;
    }
    if k == dst_nnz {
        // the rest of src comes after every dst index
        let rest = src_nnz - si;
        for (x, y) in dst[k..k + rest].iter_mut().zip(&src[si..src_nnz]) {
            *x = b * y;
        }
        dst_ind[k..k + rest].copy_from_slice(&src_ind[si..src_nnz]);
        return k + rest;
    }

    // general merge of the remaining dst (moved to buf) and src, from position k
    let buf_nnz = dst_nnz - k;
    buf[..buf_nnz].copy_from_slice(&dst[k..dst_nnz]);
    buf_ind[..buf_nnz].copy_from_slice(&dst_ind[k..dst_nnz]);
    let end = n as i32 + 1;
    let (mut bi, mut nnz) = (0, k);
    let dst_nnz = buf_nnz;
    let adr = |ind: &[i32], i: usize, len: usize| if i < len { ind[i] } else { end };
    let mut badr = adr(buf_ind, bi, dst_nnz);
    let mut sadr = adr(src_ind, si, src_nnz);
    while bi < dst_nnz || si < src_nnz {
        if badr == sadr {
            dst[nnz] = a * buf[bi] + b * src[si];
            dst_ind[nnz] = badr;
            bi += 1;
            si += 1;
            badr = adr(buf_ind, bi, dst_nnz);
            sadr = adr(src_ind, si, src_nnz);
        } else if badr < sadr {
            dst[nnz] = a * buf[bi];
            dst_ind[nnz] = badr;
            bi += 1;
            badr = adr(buf_ind, bi, dst_nnz);
        } else {
            dst[nnz] = b * src[si];
            dst_ind[nnz] = sadr;
            si += 1;
            sadr = adr(src_ind, si, src_nnz);
        }
        nnz += 1;
    }
    nnz
}

/// dst = a*dst + b*src where the pattern of src is contained in that of dst.
#[allow(clippy::too_many_arguments)]
pub fn combine_sparse_inc(
    dst: &mut [f64],
    src: &[f64],
    n: usize,
    a: f64,
    b: f64,
    dst_nnz: usize,
    src_nnz: usize,
    dst_ind: &[i32],
    src_ind: &[i32],
) {
    if dst_nnz == src_nnz && same_pattern(&dst_ind[..dst_nnz], &src_ind[..src_nnz]) {
        add_to_scl_scl(&mut dst[..dst_nnz], &src[..dst_nnz], a, b);
        return;
    }
    if a != 1.0 {
        for x in &mut dst[..dst_nnz] {
            *x *= a;
        }
    }
    let end = n as i32 + 1;
    let adr = |ind: &[i32], i: usize, len: usize| if i < len { ind[i] } else { end };
    let (mut di, mut si) = (0, 0);
    let mut dadr = adr(dst_ind, di, dst_nnz);
    let mut sadr = adr(src_ind, si, src_nnz);
    while di < dst_nnz {
        if dadr == sadr {
            dst[di] += b * src[si];
            di += 1;
            si += 1;
            dadr = adr(dst_ind, di, dst_nnz);
            sadr = adr(src_ind, si, src_nnz);
        } else if dadr < sadr {
            di += 1;
            dadr = adr(dst_ind, di, dst_nnz);
        } else {
            si += 1;
            sadr = adr(src_ind, si, src_nnz);
        }
    }
}

/// Moves rows together so that row r starts where row r-1 ends; rowadr is updated.
pub fn compress_sparse(
    mat: &mut [f64],
    nr: usize,
    rownnz: &[i32],
    rowadr: &mut [i32],
    colind: &mut [i32],
) {
    if nr == 0 {
        return;
    }
    rowadr[0] = 0;
    let mut adr = u(rownnz[0]);
    for r in 1..nr {
        let (old, n) = (u(rowadr[r]), u(rownnz[r]));
        rowadr[r] = adr as i32;
        if old != adr {
            // rows only move towards the front: a forward copy handles overlap
            let shift = old - adr;
            let (mv, cv) = (&mut mat[adr..old + n], &mut colind[adr..old + n]);
            for k in 0..n {
                mv[k] = mv[k + shift];
                cv[k] = cv[k + shift];
            }
        }
        adr += n;
    }
}

/// res = mat^T (mat is nr x nc), compressed. Leaves res and res_colind as 2.2.2's transpose
/// does, which writes row rt at rt * nr and then moves the rows to the front: the compressed
/// rows first, then, past them, what of each row at rt * nr the moves did not write over.
/// Written here in that end state directly: rows counted, filled in place, then each row's
/// part past the compressed ones copied out row by row (2.2.2's scatter over nc strides of nr
/// touches a page per entry).
#[allow(clippy::too_many_arguments)]
pub fn transpose_sparse(
    res: &mut [f64],
    mat: &[f64],
    nr: usize,
    nc: usize,
    res_rownnz: &mut [i32],
    res_rowadr: &mut [i32],
    res_colind: &mut [i32],
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) {
    let (res_rownnz, res_rowadr) = (&mut res_rownnz[..nc], &mut res_rowadr[..nc]);
    res_rownnz.fill(0);
    for r in 0..nr {
        let adr = u(rowadr[r]);
        for &c in &colind[adr..adr + u(rownnz[r])] {
            res_rownnz[u(c)] += 1;
        }
    }
    // each row's end, then filled back to its start
    let mut nnz = 0i32;
    for (a, &n) in res_rowadr.iter_mut().zip(res_rownnz.iter()) {
        *a = nnz;
        nnz += n;
    }
    for r in 0..nr {
        let adr = u(rowadr[r]);
        let n = u(rownnz[r]);
        for (&c, &v) in colind[adr..adr + n].iter().zip(&mat[adr..adr + n]) {
            let k = u(res_rowadr[u(c)]);
            res_colind[k] = r as i32;
            res[k] = v;
            res_rowadr[u(c)] += 1;
        }
    }
    let nnz = u(nnz);
    for rt in 0..nc {
        let n = u(res_rownnz[rt]);
        res_rowadr[rt] -= n as i32;
        let (from, to) = (u(res_rowadr[rt]), rt * nr);
        // the part of row rt at rt * nr that lies past the compressed rows
        let skip = nnz.saturating_sub(to).min(n);
        res.copy_within(from + skip..from + n, to + skip);
        res_colind.copy_within(from + skip..from + n, to + skip);
    }
}

/// rowsuper[r] = number of following rows with the same pattern as row r.
pub fn super_sparse(
    nr: usize,
    rowsuper: &mut [i32],
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) {
    if nr == 0 {
        return;
    }
    for r in 0..nr - 1 {
        rowsuper[r] = if rownnz[r] != rownnz[r + 1] {
            0
        } else {
            let n = u(rownnz[r]);
            let (a, b) = (u(rowadr[r]), u(rowadr[r + 1]));
            same_pattern(&colind[a..a + n], &colind[b..b + n]) as i32
        };
    }
    rowsuper[nr - 1] = 0;
    for r in (0..nr - 1).rev() {
        if rowsuper[r] != 0 {
            rowsuper[r] += rowsuper[r + 1];
        }
    }
}

/// buffer[col] += v[q] * mat[c + q][col] for q = 0..N in turn, over the columns col <= r of
/// rows c.. (N rows of one pattern).
fn add_rows_below<const N: usize>(
    buffer: &mut [f64],
    mat: &[f64],
    m: &SparseRef,
    c: usize,
    r: usize,
    v: &[f64; 4],
) {
    let start = u(m.rowadr[c]);
    let nnz = u(m.rownnz[c]);
    let cols = &m.colind[start..start + nnz];
    let rows: [&[f64]; N] = std::array::from_fn(|q| {
        let a = u(m.rowadr[c + q]);
        &mat[a..a + nnz]
    });
    for (k, &col) in cols.iter().enumerate() {
        let col = u(col);
        if col > r {
            break;
        }
        let mut b = buffer[col];
        for q in 0..N {
            b += v[q] * rows[q][k];
        }
        buffer[col] = b;
    }
}

/// Sparse pattern and index inputs of `sqr_mat_td_sparse_lower`.
pub struct SparseRef<'a> {
    pub rownnz: &'a [i32],
    pub rowadr: &'a [i32],
    pub colind: &'a [i32],
    pub rowsuper: Option<&'a [i32]>,
}

/// Mirrors the lower triangle that `sqr_mat_td_sparse_lower` wrote (rows of stride nc ending
/// at their diagonal) to the upper one: the whole of mju_sqrMatTDSparse's result.
pub fn mirror_lower_sparse(
    res: &mut [f64],
    nc: usize,
    res_rownnz: &mut [i32],
    res_colind: &mut [i32],
) {
    for r in 1..nc {
        let end = (nc * r + u(res_rownnz[r])).saturating_sub(1);
        for a in nc * r..end {
            let col = u(res_colind[a]);
            let a1 = nc * col + u(res_rownnz[col]);
            res_rownnz[col] += 1;
            res[a1] = res[a];
            res_colind[a1] = r as i32;
        }
    }
}

/// res (nc x nc, uncompressed with stride nc) = mat^T * diag * mat, mat being nr x nc and
/// matT its transpose, in the lower triangle (each row ends at its diagonal): enough for a
/// Cholesky factorization, which reads nothing above the diagonal; `mirror_lower_sparse` then
/// gives the whole matrix. `chain` needs 2*nc ints and `buffer` nc values of scratch;
/// `merged` as `sqr_mat_td_sparse_pattern` takes it.
#[allow(clippy::too_many_arguments)]
pub fn sqr_mat_td_sparse_lower(
    res: &mut [f64],
    mat: &[f64],
    mat_t: &[f64],
    diag: Option<&[f64]>,
    nc: usize,
    res_rownnz: &mut [i32],
    res_rowadr: &mut [i32],
    res_colind: &mut [i32],
    m: &SparseRef,
    mt: &SparseRef,
    chain: &mut [i32],
    buffer: &mut [f64],
    merged: impl Fn(usize) -> bool,
) {
    let rows = (&mut *res_rownnz, &mut *res_rowadr, &mut *res_colind);
    sqr_mat_td_sparse_pattern(nc, rows, m, mt, chain, false, merged);
    sqr_mat_td_sparse_values(
        res, mat, mat_t, diag, nc, res_rownnz, res_rowadr, res_colind, m, mt, buffer,
    );
}

/// The pattern of `sqr_mat_td_sparse_lower`'s rows: each row at r*nc, or (`packed`) right
/// after the one before; returns the number of entries. Row r is the union of the rows of m
/// at the columns of mt's row r, up to r; only those columns c where `merged(c)` are merged,
/// which leaves the union as it is where each column left out has its row of m within the
/// row of a merged column of the same mt row (ancestors' dofs on completed chains: a tree's
/// root dof is on every row that holds one of its dofs).
pub fn sqr_mat_td_sparse_pattern(
    nc: usize,
    (res_rownnz, res_rowadr, res_colind): (&mut [i32], &mut [i32], &mut [i32]),
    m: &SparseRef,
    mt: &SparseRef,
    chain: &mut [i32],
    packed: bool,
    merged: impl Fn(usize) -> bool,
) -> usize {
    let mut next = 0;
    for r in 0..nc {
        res_rowadr[r] = if packed { next } else { r * nc } as i32;
        let same_as_prev = r > 0 && mt.rowsuper.is_some_and(|s| s[r - 1] > 0);
        if same_as_prev {
            res_rownnz[r] = res_rownnz[r - 1];
            let n = u(res_rownnz[r]);
            let (src, dst) = (u(res_rowadr[r - 1]), u(res_rowadr[r]));
            res_colind.copy_within(src..src + n, dst);
            if mt.rownnz[r] != 0 {
                res_colind[dst + n] = r as i32;
                res_rownnz[r] += 1;
            }
            next = u(res_rowadr[r]) + u(res_rownnz[r]);
            continue;
        }
        let mut nchain = 0;
        let (mut inew, mut iold) = (0, nc);
        let mut lastadded: i32 = -1;
        let ri = r as i32;
        let adr_t = u(mt.rowadr[r]);
        for i in 0..u(mt.rownnz[r]) {
            let c = mt.colind[adr_t + i];
            if !merged(u(c)) {
                continue;
            }
            if let Some(rs) = m.rowsuper {
                if lastadded >= 0 && c - lastadded <= rs[u(lastadded)] {
                    continue;
                }
            }
            lastadded = c;

            std::mem::swap(&mut inew, &mut iold);
            let mut nnew = 0;
            let mut a = 0;
            let c = u(c);
            let (start, end) = (u(m.rowadr[c]), u(m.rowadr[c]) + u(m.rownnz[c]));
            for &col in &m.colind[start..end] {
                while a < nchain && chain[iold + a] < col && chain[iold + a] <= ri {
                    chain[inew + nnew] = chain[iold + a];
                    nnew += 1;
                    a += 1;
                }
                if col > ri {
                    break;
                }
                if a < nchain && chain[iold + a] == col {
                    a += 1;
                }
                chain[inew + nnew] = col;
                nnew += 1;
            }
            while a < nchain && chain[iold + a] <= ri {
                chain[inew + nnew] = chain[iold + a];
                nnew += 1;
                a += 1;
            }
            nchain = nnew;
        }
        res_rownnz[r] = nchain as i32;
        let dst = u(res_rowadr[r]);
        res_colind[dst..dst + nchain].copy_from_slice(&chain[inew..inew + nchain]);
        next = dst + nchain;
    }
    next
}

/// The values of `sqr_mat_td_sparse_lower`'s rows, whose pattern is in place.
#[allow(clippy::too_many_arguments)]
pub fn sqr_mat_td_sparse_values(
    res: &mut [f64],
    mat: &[f64],
    mat_t: &[f64],
    diag: Option<&[f64]>,
    nc: usize,
    res_rownnz: &[i32],
    res_rowadr: &[i32],
    res_colind: &[i32],
    m: &SparseRef,
    mt: &SparseRef,
    buffer: &mut [f64],
) {
    // values of the lower triangle
    for r in 0..nc {
        let adr = u(res_rowadr[r]);
        let n = u(res_rownnz[r]);
        for &ci in &res_colind[adr..adr + n] {
            buffer[u(ci)] = 0.0;
        }
        add_td_row(buffer, r, mat, mat_t, diag, false, m, mt);
        for (x, &ci) in res[adr..adr + n].iter_mut().zip(&res_colind[adr..adr + n]) {
            *x = buffer[u(ci)];
        }
    }
}

/// Marks the rows of mat whose diag is 0 and that hold an infinity or NaN with -0, which
/// `add_td_row` with `skip_zero` keeps (their products are NaN, not zeros; -0 and +0 give the
/// same results bit for bit in every term).
pub fn keep_nonfinite_rows(diag: &mut [f64], mat: &[f64], m: &SparseRef) {
    for (i, x) in diag.iter_mut().enumerate() {
        if *x == 0.0 {
            let (n, adr) = (u(m.rownnz[i]), u(m.rowadr[i]));
            if !mat[adr..adr + n].iter().all(|v| v.is_finite()) {
                *x = -0.0;
            }
        }
    }
}

/// buffer[c] += (mat' * diag * mat)[r][c] for the columns c <= r of row r's pattern, each
/// element's terms in order of the rows of mat. With `skip_zero`, rows of mat whose diag is +0
/// are left out: for the caller to ask only where those rows are finite (their terms zeros)
/// and the sums in buffer start at +0 (which zeros leave as they are).
#[allow(clippy::too_many_arguments)]
pub fn add_td_row(
    buffer: &mut [f64],
    r: usize,
    mat: &[f64],
    mat_t: &[f64],
    diag: Option<&[f64]>,
    skip_zero: bool,
    m: &SparseRef,
    mt: &SparseRef,
) {
    let adr_t = u(mt.rowadr[r]);
    let nnz_t = u(mt.rownnz[r]);
    let (cols_t, vals_t) = (
        &mt.colind[adr_t..adr_t + nnz_t],
        &mat_t[adr_t..adr_t + nnz_t],
    );
    let mut i = 0;
    while i < nnz_t {
        // rows c, c+1, .. of mat with one pattern (a supernode) add into buffer together:
        // each element still gets their terms one after another, in order of c
        let c = u(cols_t[i]);
        let run = match m.rowsuper {
            Some(sup) => {
                let max = (u(sup[c].max(0)) + 1).min(4).min(nnz_t - i);
                1 + (1..max).take_while(|&q| u(cols_t[i + q]) == c + q).count()
            }
            None => 1,
        };
        if let (true, Some(d)) = (skip_zero, diag) {
            if d[c..c + run].iter().all(|x| x.to_bits() == 0) {
                i += run;
                continue;
            }
        }
        let v: [f64; 4] = std::array::from_fn(|q| match (q < run, diag) {
            (false, _) => 0.0,
            (true, Some(d)) => vals_t[i + q] * d[c + q],
            (true, None) => vals_t[i + q],
        });
        match run {
            4 => add_rows_below::<4>(buffer, mat, m, c, r, &v),
            3 => add_rows_below::<3>(buffer, mat, m, c, r, &v),
            2 => add_rows_below::<2>(buffer, mat, m, c, r, &v),
            _ => add_rows_below::<1>(buffer, mat, m, c, r, &v),
        }
        i += run;
    }
}
