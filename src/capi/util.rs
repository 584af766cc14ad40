//! C entry points of the mju_ utility functions: thin wrappers over `crate::math`.
//!
//! Fixed-size arguments are read into local arrays before each result is written, in the order
//! 2.2.2 writes them, so a result aliasing an input gives 2.2.2's answer. The same holds for
//! mju_mulMatVec, mju_mulMatMatT and mju_transpose; other variable-size inputs overlapping the
//! result are copied first (2.2.2 would read partly overwritten inputs there).
//! NULL pointers (where C would crash) make a call return without effect.

use super::guard;
use crate::abi::*;
use crate::math::{self, blas, chol, misc, qcqp};
use std::cell::UnsafeCell;
use std::ffi::CStr;
use std::os::raw::{c_char, c_int};

macro_rules! nonnull {
    ($ret:expr; $($p:expr),+) => {
        if $($p.is_null())||+ {
            return $ret;
        }
    };
    ($($p:expr),+) => {
        if $($p.is_null())||+ {
            return;
        }
    };
}

/// Runs a core computation with panics contained.
fn run<R>(name: &str, fallback: R, f: impl FnOnce() -> R) -> R {
    guard(name, fallback, || Ok(f()))
}

/// The N values at p, read one by one: callers often have just stored some of them singly, and
/// one wide load over several such stores waits for them to reach the cache.
unsafe fn rd<const N: usize>(p: *const mjtNum) -> [f64; N] {
    std::array::from_fn(|i| std::ptr::read_volatile(p.add(i)))
}

unsafe fn wr<const N: usize>(p: *mut mjtNum, v: [f64; N]) {
    std::ptr::write(p as *mut [f64; N], v)
}

/// Writes res[0], res[1], ... in turn, each from inputs re-read after the previous write,
/// reproducing 2.2.2's result when the output aliases an input of a function without temporaries.
unsafe fn write_seq<const N: usize>(res: *mut f64, f: impl Fn() -> [f64; N]) {
    for i in 0..N {
        *res.add(i) = f()[i];
    }
}

fn len(n: c_int) -> usize {
    n.max(0) as usize
}

unsafe fn sl<'a, T>(p: *const T, n: usize) -> &'a [T] {
    if n == 0 || p.is_null() {
        &[]
    } else {
        std::slice::from_raw_parts(p, n)
    }
}

unsafe fn sl_mut<'a, T>(p: *mut T, n: usize) -> &'a mut [T] {
    if n == 0 || p.is_null() {
        &mut []
    } else {
        std::slice::from_raw_parts_mut(p, n)
    }
}

/// Input `p[..n]`, copied into `buf` when it overlaps the output `res[..rn]`.
unsafe fn input(p: *const f64, n: usize, res: *const f64, rn: usize, buf: &mut Vec<f64>) -> &[f64] {
    let (a, b) = (p as usize, res as usize);
    let size = std::mem::size_of::<f64>();
    if n > 0 && rn > 0 && a < b + rn * size && b < a + n * size {
        buf.extend_from_slice(sl(p, n));
        buf
    } else {
        sl(p, n)
    }
}

//------------------------------ 3D and 4D vectors ----------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_zero3(res: *mut mjtNum) {
    nonnull!(res);
    wr(res, [0.0; 3]);
}

#[no_mangle]
pub unsafe extern "C" fn mju_copy3(res: *mut mjtNum, data: *const mjtNum) {
    nonnull!(res, data);
    wr::<3>(res, rd(data));
}

#[no_mangle]
pub unsafe extern "C" fn mju_scl3(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum) {
    nonnull!(res, vec);
    wr(res, math::scl3(&rd(vec), scl));
}

#[no_mangle]
pub unsafe extern "C" fn mju_add3(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum) {
    nonnull!(res, vec1, vec2);
    wr(res, math::add3(&rd(vec1), &rd(vec2)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_sub3(res: *mut mjtNum, vec1: *const mjtNum, vec2: *const mjtNum) {
    nonnull!(res, vec1, vec2);
    wr(res, math::sub3(&rd(vec1), &rd(vec2)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_addTo3(res: *mut mjtNum, vec: *const mjtNum) {
    nonnull!(res, vec);
    wr(res, math::add3(&rd(res), &rd(vec)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_subFrom3(res: *mut mjtNum, vec: *const mjtNum) {
    nonnull!(res, vec);
    wr(res, math::sub3(&rd(res), &rd(vec)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_addToScl3(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum) {
    nonnull!(res, vec);
    let mut r = rd(res);
    math::add_to_scl3(&mut r, &rd(vec), scl);
    wr(res, r);
}

#[no_mangle]
pub unsafe extern "C" fn mju_addScl3(
    res: *mut mjtNum,
    vec1: *const mjtNum,
    vec2: *const mjtNum,
    scl: mjtNum,
) {
    nonnull!(res, vec1, vec2);
    wr(res, math::add_scl3(&rd(vec1), &rd(vec2), scl));
}

#[no_mangle]
pub unsafe extern "C" fn mju_normalize3(res: *mut mjtNum) -> mjtNum {
    nonnull!(0.0; res);
    let (v, n) = math::normalize3(&rd(res));
    wr(res, v);
    n
}

#[no_mangle]
pub unsafe extern "C" fn mju_norm3(vec: *const mjtNum) -> mjtNum {
    nonnull!(0.0; vec);
    math::norm3(&rd(vec))
}

#[no_mangle]
pub unsafe extern "C" fn mju_dot3(vec1: *const mjtNum, vec2: *const mjtNum) -> mjtNum {
    nonnull!(0.0; vec1, vec2);
    math::dot3(&rd(vec1), &rd(vec2))
}

#[no_mangle]
pub unsafe extern "C" fn mju_dist3(pos1: *const mjtNum, pos2: *const mjtNum) -> mjtNum {
    nonnull!(0.0; pos1, pos2);
    math::dist3(&rd(pos1), &rd(pos2))
}

#[no_mangle]
pub unsafe extern "C" fn mju_rotVecMat(res: *mut mjtNum, vec: *const mjtNum, mat: *const mjtNum) {
    nonnull!(res, vec, mat);
    wr(res, math::mul_mat_vec3(&rd(mat), &rd(vec)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_rotVecMatT(res: *mut mjtNum, vec: *const mjtNum, mat: *const mjtNum) {
    nonnull!(res, vec, mat);
    wr(res, math::mul_mat_t_vec3(&rd(mat), &rd(vec)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_cross(res: *mut mjtNum, a: *const mjtNum, b: *const mjtNum) {
    nonnull!(res, a, b);
    write_seq::<3>(res, || math::cross(&rd(a), &rd(b)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_zero4(res: *mut mjtNum) {
    nonnull!(res);
    wr(res, [0.0; 4]);
}

#[no_mangle]
pub unsafe extern "C" fn mju_unit4(res: *mut mjtNum) {
    nonnull!(res);
    wr(res, math::unit_quat());
}

#[no_mangle]
pub unsafe extern "C" fn mju_copy4(res: *mut mjtNum, data: *const mjtNum) {
    nonnull!(res, data);
    wr::<4>(res, rd(data));
}

#[no_mangle]
pub unsafe extern "C" fn mju_normalize4(res: *mut mjtNum) -> mjtNum {
    nonnull!(0.0; res);
    let (q, n) = math::normalize4(&rd(res));
    wr(res, q);
    n
}

//------------------------------ vectors of any size --------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_zero(res: *mut mjtNum, n: c_int) {
    blas::zero(sl_mut(res, len(n)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_copy(res: *mut mjtNum, data: *const mjtNum, n: c_int) {
    nonnull!(res, data);
    if !std::ptr::eq(res, data) {
        std::ptr::copy(data, res, len(n));
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_sum(vec: *const mjtNum, n: c_int) -> mjtNum {
    blas::sum(sl(vec, len(n)))
}

#[no_mangle]
pub unsafe extern "C" fn mju_L1(vec: *const mjtNum, n: c_int) -> mjtNum {
    blas::l1(sl(vec, len(n)))
}

/// res[..n] = f(a[..n], b[..n]) elementwise, with inputs copied when they overlap res.
unsafe fn binary(
    res: *mut f64,
    a: *const f64,
    b: *const f64,
    n: c_int,
    f: impl FnOnce(&mut [f64], &[f64], &[f64]),
) {
    nonnull!(res, a, b);
    let n = len(n);
    let (mut ba, mut bb) = (Vec::new(), Vec::new());
    let a = input(a, n, res, n, &mut ba);
    let b = input(b, n, res, n, &mut bb);
    f(sl_mut(res, n), a, b);
}

/// res[..n] = f(res[..n], a[..n]), with `a` copied when it overlaps res.
unsafe fn update(res: *mut f64, a: *const f64, n: c_int, f: impl FnOnce(&mut [f64], &[f64])) {
    nonnull!(res, a);
    let n = len(n);
    let mut ba = Vec::new();
    let a = input(a, n, res, n, &mut ba);
    f(sl_mut(res, n), a);
}

#[no_mangle]
pub unsafe extern "C" fn mju_scl(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum, n: c_int) {
    if std::ptr::eq(res, vec) {
        blas::scl_in_place(sl_mut(res, len(n)), scl);
    } else {
        update(res, vec, n, |r, v| blas::scl(r, v, scl));
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_add(
    res: *mut mjtNum,
    vec1: *const mjtNum,
    vec2: *const mjtNum,
    n: c_int,
) {
    binary(res, vec1, vec2, n, blas::add);
}

#[no_mangle]
pub unsafe extern "C" fn mju_sub(
    res: *mut mjtNum,
    vec1: *const mjtNum,
    vec2: *const mjtNum,
    n: c_int,
) {
    binary(res, vec1, vec2, n, blas::sub);
}

#[no_mangle]
pub unsafe extern "C" fn mju_addTo(res: *mut mjtNum, vec: *const mjtNum, n: c_int) {
    update(res, vec, n, blas::add_to);
}

#[no_mangle]
pub unsafe extern "C" fn mju_subFrom(res: *mut mjtNum, vec: *const mjtNum, n: c_int) {
    update(res, vec, n, blas::sub_from);
}

#[no_mangle]
pub unsafe extern "C" fn mju_addToScl(res: *mut mjtNum, vec: *const mjtNum, scl: mjtNum, n: c_int) {
    update(res, vec, n, |r, v| blas::add_to_scl(r, v, scl));
}

#[no_mangle]
pub unsafe extern "C" fn mju_addScl(
    res: *mut mjtNum,
    vec1: *const mjtNum,
    vec2: *const mjtNum,
    scl: mjtNum,
    n: c_int,
) {
    binary(res, vec1, vec2, n, |r, a, b| blas::add_scl(r, a, b, scl));
}

#[no_mangle]
pub unsafe extern "C" fn mju_normalize(res: *mut mjtNum, n: c_int) -> mjtNum {
    nonnull!(0.0; res);
    if n <= 0 {
        // 2.2.2 sees a zero norm and still sets the first element
        *res = 1.0;
        return 0.0;
    }
    blas::normalize(sl_mut(res, len(n)))
}

#[no_mangle]
pub unsafe extern "C" fn mju_norm(res: *const mjtNum, n: c_int) -> mjtNum {
    blas::norm(sl(res, len(n)))
}

#[no_mangle]
pub unsafe extern "C" fn mju_dot(vec1: *const mjtNum, vec2: *const mjtNum, n: c_int) -> mjtNum {
    nonnull!(0.0; vec1, vec2);
    let n = len(n);
    blas::dot(sl(vec1, n), sl(vec2, n), n)
}

//------------------------------ matrices ------------------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatVec(
    res: *mut mjtNum,
    mat: *const mjtNum,
    vec: *const mjtNum,
    nr: c_int,
    nc: c_int,
) {
    nonnull!(res, mat, vec);
    let (nr, nc) = (len(nr), len(nc));
    // one dot product per output, written in turn as 2.2.2 does (exact even when res aliases vec)
    for r in 0..nr {
        *res.add(r) = blas::dot(sl(mat.add(r * nc), nc), sl(vec, nc), nc);
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatTVec(
    res: *mut mjtNum,
    mat: *const mjtNum,
    vec: *const mjtNum,
    nr: c_int,
    nc: c_int,
) {
    nonnull!(res, mat, vec);
    let (nr, nc) = (len(nr), len(nc));
    let (mut bm, mut bv) = (Vec::new(), Vec::new());
    let m = input(mat, nr * nc, res, nc, &mut bm);
    let v = input(vec, nr, res, nc, &mut bv);
    run("mju_mulMatTVec", (), || {
        blas::mul_mat_t_vec(sl_mut(res, nc), m, v, nr, nc)
    });
}

#[no_mangle]
pub unsafe extern "C" fn mju_transpose(res: *mut mjtNum, mat: *const mjtNum, nr: c_int, nc: c_int) {
    nonnull!(res, mat);
    let (nr, nc) = (len(nr), len(nc));
    // element by element in 2.2.2's order, so that in-place calls give 2.2.2's result
    for i in 0..nr {
        for j in 0..nc {
            *res.add(j * nr + i) = *mat.add(i * nc + j);
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatMat(
    res: *mut mjtNum,
    mat1: *const mjtNum,
    mat2: *const mjtNum,
    r1: c_int,
    c1: c_int,
    c2: c_int,
) {
    nonnull!(res, mat1, mat2);
    let (r1, c1, c2) = (len(r1), len(c1), len(c2));
    let (mut b1, mut b2) = (Vec::new(), Vec::new());
    let m1 = input(mat1, r1 * c1, res, r1 * c2, &mut b1);
    let m2 = input(mat2, c1 * c2, res, r1 * c2, &mut b2);
    run("mju_mulMatMat", (), || {
        blas::mul_mat_mat(sl_mut(res, r1 * c2), m1, m2, r1, c1, c2)
    });
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatMatT(
    res: *mut mjtNum,
    mat1: *const mjtNum,
    mat2: *const mjtNum,
    r1: c_int,
    c1: c_int,
    r2: c_int,
) {
    nonnull!(res, mat1, mat2);
    let (r1, c1, r2) = (len(r1), len(c1), len(r2));
    for i in 0..r1 {
        for j in 0..r2 {
            *res.add(i * r2 + j) =
                blas::dot(sl(mat1.add(i * c1), c1), sl(mat2.add(j * c1), c1), c1);
        }
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulMatTMat(
    res: *mut mjtNum,
    mat1: *const mjtNum,
    mat2: *const mjtNum,
    r1: c_int,
    c1: c_int,
    c2: c_int,
) {
    nonnull!(res, mat1, mat2);
    let (r1, c1, c2) = (len(r1), len(c1), len(c2));
    let (mut b1, mut b2) = (Vec::new(), Vec::new());
    let m1 = input(mat1, r1 * c1, res, c1 * c2, &mut b1);
    let m2 = input(mat2, r1 * c2, res, c1 * c2, &mut b2);
    run("mju_mulMatTMat", (), || {
        blas::mul_mat_t_mat(sl_mut(res, c1 * c2), m1, m2, r1, c1, c2)
    });
}

#[no_mangle]
pub unsafe extern "C" fn mju_sqrMatTD(
    res: *mut mjtNum,
    mat: *const mjtNum,
    diag: *const mjtNum,
    nr: c_int,
    nc: c_int,
) {
    nonnull!(res, mat);
    let (nr, nc) = (len(nr), len(nc));
    let (mut bm, mut bd) = (Vec::new(), Vec::new());
    let m = input(mat, nr * nc, res, nc * nc, &mut bm);
    let d = (!diag.is_null()).then(|| input(diag, nr, res, nc * nc, &mut bd));
    run("mju_sqrMatTD", (), || {
        blas::sqr_mat_td(sl_mut(res, nc * nc), m, d, nr, nc)
    });
}

//------------------------------ spatial algebra and quaternions --------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_transformSpatial(
    res: *mut mjtNum,
    vec: *const mjtNum,
    flg_force: c_int,
    newpos: *const mjtNum,
    oldpos: *const mjtNum,
    rotnew2old: *const mjtNum,
) {
    nonnull!(res, vec, newpos, oldpos);
    let rot: Option<math::Mat3> = (!rotnew2old.is_null()).then(|| rd(rotnew2old));
    wr(
        res,
        math::transform_spatial(
            &rd(vec),
            flg_force != 0,
            &rd(newpos),
            &rd(oldpos),
            rot.as_ref(),
        ),
    );
}

#[no_mangle]
pub unsafe extern "C" fn mju_rotVecQuat(res: *mut mjtNum, vec: *const mjtNum, quat: *const mjtNum) {
    nonnull!(res, vec, quat);
    wr(res, math::rot_vec_quat(&rd(vec), &rd(quat)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_negQuat(res: *mut mjtNum, quat: *const mjtNum) {
    nonnull!(res, quat);
    wr(res, math::neg_quat(&rd(quat)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulQuat(res: *mut mjtNum, quat1: *const mjtNum, quat2: *const mjtNum) {
    nonnull!(res, quat1, quat2);
    wr(res, math::mul_quat(&rd(quat1), &rd(quat2)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulQuatAxis(
    res: *mut mjtNum,
    quat: *const mjtNum,
    axis: *const mjtNum,
) {
    nonnull!(res, quat, axis);
    wr(res, math::mul_quat_axis(&rd(quat), &rd(axis)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_axisAngle2Quat(res: *mut mjtNum, axis: *const mjtNum, angle: mjtNum) {
    nonnull!(res, axis);
    wr(res, math::axis_angle2quat(&rd(axis), angle));
}

#[no_mangle]
pub unsafe extern "C" fn mju_quat2Vel(res: *mut mjtNum, quat: *const mjtNum, dt: mjtNum) {
    nonnull!(res, quat);
    wr(res, math::quat2vel(&rd(quat), dt));
}

#[no_mangle]
pub unsafe extern "C" fn mju_subQuat(res: *mut mjtNum, qa: *const mjtNum, qb: *const mjtNum) {
    nonnull!(res, qa, qb);
    wr(res, math::sub_quat(&rd(qa), &rd(qb)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_quat2Mat(res: *mut mjtNum, quat: *const mjtNum) {
    nonnull!(res, quat);
    wr(res, math::quat2mat(&rd(quat)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_mat2Quat(quat: *mut mjtNum, mat: *const mjtNum) {
    nonnull!(quat, mat);
    wr(quat, math::mat2quat(&rd(mat)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_derivQuat(res: *mut mjtNum, quat: *const mjtNum, vel: *const mjtNum) {
    nonnull!(res, quat, vel);
    write_seq::<4>(res, || math::deriv_quat(&rd(quat), &rd(vel)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_quatIntegrate(quat: *mut mjtNum, vel: *const mjtNum, scale: mjtNum) {
    nonnull!(quat, vel);
    wr(quat, math::quat_integrate(&rd(quat), &rd(vel), scale));
}

#[no_mangle]
pub unsafe extern "C" fn mju_quatZ2Vec(quat: *mut mjtNum, vec: *const mjtNum) {
    nonnull!(quat, vec);
    wr(quat, math::quat_z2vec(&rd(vec)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_mulPose(
    posres: *mut mjtNum,
    quatres: *mut mjtNum,
    pos1: *const mjtNum,
    quat1: *const mjtNum,
    pos2: *const mjtNum,
    quat2: *const mjtNum,
) {
    nonnull!(posres, quatres, pos1, quat1, pos2, quat2);
    let q = math::mul_quat(&rd(quat1), &rd(quat2));
    wr(quatres, math::normalize4(&q).0);
    wr(posres, math::rot_vec_quat(&rd(pos2), &rd(quat1)));
    wr(posres, math::add3(&rd(posres), &rd(pos1)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_negPose(
    posres: *mut mjtNum,
    quatres: *mut mjtNum,
    pos: *const mjtNum,
    quat: *const mjtNum,
) {
    nonnull!(posres, quatres, pos, quat);
    wr(quatres, math::neg_quat(&rd(quat)));
    wr(posres, math::rot_vec_quat(&rd(pos), &rd(quatres)));
    wr(posres, math::scl3(&rd(posres), misc::minus_one()));
}

#[no_mangle]
pub unsafe extern "C" fn mju_trnVecPose(
    res: *mut mjtNum,
    pos: *const mjtNum,
    quat: *const mjtNum,
    vec: *const mjtNum,
) {
    nonnull!(res, pos, quat, vec);
    wr(res, math::rot_vec_quat(&rd(vec), &rd(quat)));
    wr(res, math::add3(&rd(res), &rd(pos)));
}

//------------------------------ decompositions ------------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_cholFactor(mat: *mut mjtNum, n: c_int, mindiag: mjtNum) -> c_int {
    nonnull!(0; mat);
    let n = len(n);
    run("mju_cholFactor", 0, || {
        chol::chol_factor(sl_mut(mat, n * n), n, mindiag) as c_int
    })
}

#[no_mangle]
pub unsafe extern "C" fn mju_cholSolve(
    res: *mut mjtNum,
    mat: *const mjtNum,
    vec: *const mjtNum,
    n: c_int,
) {
    nonnull!(res, mat, vec);
    let n = len(n);
    let mut b = Vec::new();
    let v = input(vec, n, res, n, &mut b);
    run("mju_cholSolve", (), || {
        let r = sl_mut(res, n);
        if v.as_ptr() != r.as_ptr() {
            r.copy_from_slice(v);
        }
        chol::chol_solve_in_place(sl(mat, n * n), r, n)
    });
}

#[no_mangle]
pub unsafe extern "C" fn mju_cholUpdate(
    mat: *mut mjtNum,
    x: *mut mjtNum,
    n: c_int,
    flg_plus: c_int,
) -> c_int {
    nonnull!(0; mat, x);
    let n = len(n);
    run("mju_cholUpdate", 0, || {
        chol::chol_update(sl_mut(mat, n * n), sl_mut(x, n), n, flg_plus != 0) as c_int
    })
}

#[no_mangle]
pub unsafe extern "C" fn mju_eig3(
    eigval: *mut mjtNum,
    eigvec: *mut mjtNum,
    quat: *mut mjtNum,
    mat: *const mjtNum,
) -> c_int {
    nonnull!(0; eigval, eigvec, quat, mat);
    let e = math::eig3(&rd(mat));
    wr(eigval, e.eigval);
    wr(eigvec, e.eigvec);
    wr(quat, e.quat);
    e.iter
}

#[no_mangle]
pub unsafe extern "C" fn mju_QCQP2(
    res: *mut mjtNum,
    Ain: *const mjtNum,
    bin: *const mjtNum,
    d: *const mjtNum,
    r: mjtNum,
) -> c_int {
    nonnull!(0; res, Ain, bin, d);
    let (x, active) = qcqp::qcqp2(&rd::<4>(Ain), &rd::<2>(bin), &rd::<2>(d), r);
    wr(res, x);
    active as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_QCQP3(
    res: *mut mjtNum,
    Ain: *const mjtNum,
    bin: *const mjtNum,
    d: *const mjtNum,
    r: mjtNum,
) -> c_int {
    nonnull!(0; res, Ain, bin, d);
    let (x, active) = qcqp::qcqp3(&rd::<9>(Ain), &rd::<3>(bin), &rd::<3>(d), r);
    wr(res, x);
    active as c_int
}

//------------------------------ actuators and contacts ----------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_muscleGain(
    len: mjtNum,
    vel: mjtNum,
    lengthrange: *const mjtNum,
    acc0: mjtNum,
    prm: *const mjtNum,
) -> mjtNum {
    nonnull!(0.0; lengthrange, prm);
    misc::muscle_gain(len, vel, &rd::<2>(lengthrange), acc0, &rd::<9>(prm))
}

#[no_mangle]
pub unsafe extern "C" fn mju_muscleBias(
    len: mjtNum,
    lengthrange: *const mjtNum,
    acc0: mjtNum,
    prm: *const mjtNum,
) -> mjtNum {
    nonnull!(0.0; lengthrange, prm);
    misc::muscle_bias(len, &rd::<2>(lengthrange), acc0, &rd::<9>(prm))
}

#[no_mangle]
pub unsafe extern "C" fn mju_muscleDynamics(
    ctrl: mjtNum,
    act: mjtNum,
    prm: *const mjtNum,
) -> mjtNum {
    nonnull!(0.0; prm);
    misc::muscle_dynamics(ctrl, act, &rd::<2>(prm))
}

#[no_mangle]
pub unsafe extern "C" fn mju_encodePyramid(
    pyramid: *mut mjtNum,
    force: *const mjtNum,
    mu: *const mjtNum,
    dim: c_int,
) {
    nonnull!(pyramid, force, mu);
    let dim = len(dim);
    if dim < 1 {
        return;
    }
    let f: Vec<f64> = sl(force, dim).to_vec();
    let m: Vec<f64> = sl(mu, dim - 1).to_vec();
    run("mju_encodePyramid", (), || {
        misc::encode_pyramid(sl_mut(pyramid, 2 * (dim - 1)), &f, &m, dim)
    });
}

#[no_mangle]
pub unsafe extern "C" fn mju_decodePyramid(
    force: *mut mjtNum,
    pyramid: *const mjtNum,
    mu: *const mjtNum,
    dim: c_int,
) {
    nonnull!(force, pyramid, mu);
    let dim = len(dim);
    if dim < 1 {
        // 2.2.2 clears the normal force and sums no edges
        *force = 0.0;
        return;
    }
    let p: Vec<f64> = sl(pyramid, if dim == 1 { 1 } else { 2 * (dim - 1) }).to_vec();
    let m: Vec<f64> = sl(mu, dim - 1).to_vec();
    run("mju_decodePyramid", (), || {
        misc::decode_pyramid(sl_mut(force, dim), &p, &m, dim)
    });
}

#[no_mangle]
pub unsafe extern "C" fn mju_springDamper(
    pos0: mjtNum,
    vel0: mjtNum,
    Kp: mjtNum,
    Kv: mjtNum,
    dt: mjtNum,
) -> mjtNum {
    misc::spring_damper(pos0, vel0, Kp, Kv, dt)
}

//------------------------------ scalars -------------------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_min(a: mjtNum, b: mjtNum) -> mjtNum {
    misc::min(a, b)
}

#[no_mangle]
pub unsafe extern "C" fn mju_max(a: mjtNum, b: mjtNum) -> mjtNum {
    misc::max(a, b)
}

#[no_mangle]
pub unsafe extern "C" fn mju_clip(x: mjtNum, min: mjtNum, max: mjtNum) -> mjtNum {
    misc::clip(x, min, max)
}

#[no_mangle]
pub unsafe extern "C" fn mju_sign(x: mjtNum) -> mjtNum {
    misc::sign(x)
}

#[no_mangle]
pub unsafe extern "C" fn mju_round(x: mjtNum) -> c_int {
    misc::round(x)
}

#[no_mangle]
pub unsafe extern "C" fn mju_isBad(x: mjtNum) -> c_int {
    misc::is_bad(x) as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_isZero(vec: *mut mjtNum, n: c_int) -> c_int {
    misc::is_zero(sl(vec, len(n))) as c_int
}

#[no_mangle]
pub unsafe extern "C" fn mju_sigmoid(x: mjtNum) -> mjtNum {
    misc::sigmoid(x)
}

#[no_mangle]
pub unsafe extern "C" fn mju_Halton(index: c_int, base: c_int) -> mjtNum {
    run("mju_Halton", 0.0, || misc::halton(index, base))
}

#[no_mangle]
pub unsafe extern "C" fn mju_standardNormal(num2: *mut mjtNum) -> mjtNum {
    let (a, b) = crate::runtime::random::standard_normal();
    if !num2.is_null() {
        *num2 = b;
    }
    a
}

//------------------------------ conversions, sorting, strings ---------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_f2n(res: *mut mjtNum, vec: *const f32, n: c_int) {
    nonnull!(res, vec);
    for i in 0..len(n) {
        *res.add(i) = *vec.add(i) as f64;
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_n2f(res: *mut f32, vec: *const mjtNum, n: c_int) {
    nonnull!(res, vec);
    for i in 0..len(n) {
        *res.add(i) = *vec.add(i) as f32;
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_d2n(res: *mut mjtNum, vec: *const f64, n: c_int) {
    nonnull!(res, vec);
    std::ptr::copy(vec, res, len(n));
}

#[no_mangle]
pub unsafe extern "C" fn mju_n2d(res: *mut f64, vec: *const mjtNum, n: c_int) {
    nonnull!(res, vec);
    std::ptr::copy(vec, res, len(n));
}

#[no_mangle]
pub unsafe extern "C" fn mju_insertionSort(list: *mut mjtNum, n: c_int) {
    misc::insertion_sort(sl_mut(list, len(n)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_insertionSortInt(list: *mut c_int, n: c_int) {
    misc::insertion_sort(sl_mut(list, len(n)));
}

#[no_mangle]
pub unsafe extern "C" fn mju_strncpy(
    dst: *mut c_char,
    src: *const c_char,
    n: c_int,
) -> *mut c_char {
    if !dst.is_null() && !src.is_null() && n > 0 {
        libc::strncpy(dst, src, n as usize);
        *dst.add(n as usize - 1) = 0;
    }
    dst
}

const OBJ_CNAMES: [&CStr; 24] = [
    c"",
    c"body",
    c"xbody",
    c"joint",
    c"dof",
    c"geom",
    c"site",
    c"camera",
    c"light",
    c"mesh",
    c"skin",
    c"hfield",
    c"texture",
    c"material",
    c"pair",
    c"exclude",
    c"equality",
    c"tendon",
    c"actuator",
    c"sensor",
    c"numeric",
    c"text",
    c"tuple",
    c"key",
];

#[no_mangle]
pub unsafe extern "C" fn mju_type2Str(type_: c_int) -> *const c_char {
    match misc::type2str(type_) {
        Some(_) => OBJ_CNAMES[type_ as usize].as_ptr(),
        None => std::ptr::null(),
    }
}

#[no_mangle]
pub unsafe extern "C" fn mju_str2Type(str: *const c_char) -> c_int {
    nonnull!(0; str);
    misc::str2type(CStr::from_ptr(str).to_bytes())
}

/// A static text buffer handed out to C, as 2.2.2's function-local static arrays.
struct TextBuf(UnsafeCell<[c_char; 1000]>);
// SAFETY: written only by mju_warningText, whose 2.2.2 version is equally unsynchronized.
unsafe impl Sync for TextBuf {}
static WARNING_TEXT: TextBuf = TextBuf(UnsafeCell::new([0; 1000]));

#[no_mangle]
pub unsafe extern "C" fn mju_warningText(warning: c_int, info: c_int) -> *const c_char {
    let text = misc::warning_text(warning, info);
    let buf = &mut *WARNING_TEXT.0.get();
    let n = text.len().min(buf.len() - 1);
    for (d, s) in buf.iter_mut().zip(&text.as_bytes()[..n]) {
        *d = *s as c_char;
    }
    buf[n] = 0;
    buf.as_ptr()
}

//------------------------------ printing ------------------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_printMat(mat: *const mjtNum, nr: c_int, nc: c_int) {
    nonnull!(mat);
    let (nr, nc) = (len(nr), len(nc));
    for r in 0..nr {
        for c in 0..nc {
            libc::printf(c"%.8f ".as_ptr(), *mat.add(r * nc + c));
        }
        libc::printf(c"\n".as_ptr());
    }
    libc::printf(c"\n".as_ptr());
}

#[no_mangle]
pub unsafe extern "C" fn mju_printMatSparse(
    mat: *const mjtNum,
    nr: c_int,
    rownnz: *const c_int,
    rowadr: *const c_int,
    colind: *const c_int,
) {
    nonnull!(mat, rownnz, rowadr, colind);
    for r in 0..len(nr) {
        let adr = *rowadr.add(r);
        for a in adr..adr + *rownnz.add(r) {
            let a = a as usize;
            libc::printf(
                c"(%d %d): %9.6f  ".as_ptr(),
                r as c_int,
                *colind.add(a),
                *mat.add(a),
            );
        }
        libc::printf(c"\n".as_ptr());
    }
    libc::printf(c"\n".as_ptr());
}

//------------------------------ model helpers -------------------------------------------------

#[no_mangle]
pub unsafe extern "C" fn mju_geomSemiAxes(
    m: *const mjModel,
    geom_id: c_int,
    semiaxes: *mut mjtNum,
) {
    nonnull!(m, semiaxes);
    let m = &*m;
    if geom_id < 0 || geom_id >= m.ngeom {
        return;
    }
    let g = geom_id as usize;
    let size: [f64; 3] = rd(m.geom_size.add(3 * g));
    let s = match *m.geom_type.add(g) {
        t if t == mjtGeom_::mjGEOM_SPHERE as c_int => [size[0]; 3],
        t if t == mjtGeom_::mjGEOM_CAPSULE as c_int => [size[0], size[0], size[1] + size[0]],
        t if t == mjtGeom_::mjGEOM_CYLINDER as c_int => [size[0], size[0], size[1]],
        _ => size,
    };
    wr(semiaxes, s);
}
