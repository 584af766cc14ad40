//! Unit tests: algebraic properties and edge cases. Bit-exactness against MuJoCo 2.2.2 is checked
//! at test time against the installed reference (tests/mju.rs), never against stored results.

use super::blas::*;
use super::chol::*;
use super::misc::*;
use super::qcqp::*;
use super::*;

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

/// Small deterministic generator for test inputs.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
    }
    fn vec<const N: usize>(&mut self) -> [f64; N] {
        std::array::from_fn(|_| self.next())
    }
}

#[test]
fn eig3_reconstructs_matrix() {
    let mut rng = Rng(7);
    for _ in 0..200 {
        let a: [f64; 6] = rng.vec();
        let m = [a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2]];
        let e = eig3(&m);
        assert!(e.eigval[0] >= e.eigval[1] && e.eigval[1] >= e.eigval[2]);
        let d = [
            e.eigval[0],
            0.0,
            0.0,
            0.0,
            e.eigval[1],
            0.0,
            0.0,
            0.0,
            e.eigval[2],
        ];
        let r = mul_mat3_t(&mul_mat3(&e.eigvec, &d), &e.eigvec);
        // Jacobi stops once a rotation's cosine exceeds 1-1e-12 (angle ~1e-6), as in 2.2.2
        assert!(close(&r, &m, 1e-5), "{r:?} vs {m:?}");
    }
}

#[test]
fn chol_update_matches_refactorization() {
    let a = [4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0];
    let v = [0.3, -0.2, 0.7];
    let mut l = a;
    chol_factor(&mut l, 3, 1e-15);
    let mut x = v;
    assert_eq!(chol_update(&mut l, &mut x, 3, true), 3);
    let mut a2 = a;
    for i in 0..3 {
        for j in 0..3 {
            a2[3 * i + j] += v[i] * v[j];
        }
    }
    let mut l2 = a2;
    chol_factor(&mut l2, 3, 1e-15);
    for i in 0..3 {
        assert!(close(
            &l[3 * i..3 * i + i + 1],
            &l2[3 * i..3 * i + i + 1],
            1e-14
        ));
    }
}

#[test]
fn matrix_products_agree() {
    let mut rng = Rng(3);
    let (a, b): ([f64; 12], [f64; 12]) = (rng.vec(), rng.vec());
    // a: 3x4, b: 3x4
    let mut atb = [0.0; 16];
    mul_mat_t_mat(&mut atb, &a, &b, 3, 4, 4);
    let mut at = [0.0; 12];
    transpose(&mut at, &a, 3, 4);
    let mut atb2 = [0.0; 16];
    mul_mat_mat(&mut atb2, &at, &b, 4, 3, 4);
    assert!(close(&atb, &atb2, 1e-14));
    let mut abt = [0.0; 9];
    mul_mat_mat_t(&mut abt, &a, &b, 3, 4, 3);
    let mut bt = [0.0; 12];
    transpose(&mut bt, &b, 3, 4);
    let mut abt2 = [0.0; 9];
    mul_mat_mat(&mut abt2, &a, &bt, 3, 4, 3);
    assert!(close(&abt, &abt2, 1e-14));
    let mut ata = [0.0; 16];
    sqr_mat_td(&mut ata, &a, None, 3, 4);
    let mut ata2 = [0.0; 16];
    mul_mat_t_mat(&mut ata2, &a, &a, 3, 4, 4);
    assert!(close(&ata, &ata2, 1e-14));
    let ones = [1.0; 3];
    sqr_mat_td(&mut ata2, &a, Some(&ones), 3, 4);
    assert!(close(&ata, &ata2, 1e-14));
    let m: Mat3 = rng.vec();
    let n: Mat3 = rng.vec();
    assert!(close(
        &mul_mat3t_mat(&m, &n),
        &mul_mat3(&transpose3(&m), &n),
        1e-14
    ));
}

#[test]
fn normalization_edge_cases() {
    assert_eq!(normalize3(&[1e-16, 0.0, 0.0]), ([1.0, 0.0, 0.0], 1e-16));
    assert_eq!(normalize4(&[0.0; 4]).0, unit_quat());
    let mut v = [0.0, 0.0, 0.0];
    assert_eq!(normalize(&mut v), 0.0);
    assert_eq!(v, [1.0, 0.0, 0.0]);
    let (u, n) = normalize3(&[3.0, 4.0, 0.0]);
    assert_eq!(n, 5.0);
    assert!(close(&u, &[0.6, 0.8, 0.0], 1e-15));
}

#[test]
fn quaternion_identities() {
    let mut rng = Rng(11);
    for _ in 0..100 {
        let q = normalize4(&rng.vec()).0;
        let v: Vec3 = rng.vec();
        // rotation by quaternion and by its matrix agree; mat2quat inverts quat2mat up to sign
        let m = quat2mat(&q);
        assert!(close(&rot_vec_quat(&v, &q), &mul_mat_vec3(&m, &v), 1e-14));
        let q2 = mat2quat(&m);
        let s = if q2[0] * q[0] + q2[1] * q[1] + q2[2] * q[2] + q2[3] * q[3] < 0.0 {
            -1.0
        } else {
            1.0
        };
        assert!(close(&q2.map(|x| x * s), &q, 1e-14));
        // sub_quat is the velocity taking qb to qa in unit time
        let qb = normalize4(&rng.vec()).0;
        let w = sub_quat(&q, &qb);
        let qa = quat_integrate(&qb, &w, 1.0);
        let s = if qa[0] * q[0] < 0.0 { -1.0 } else { 1.0 };
        assert!(close(&qa.map(|x| x * s), &q, 1e-12));
        // poses: p * p^-1 is the identity
        let (np, nq) = neg_pose(&v, &q);
        let (p, r) = mul_pose(&v, &q, &np, &nq);
        assert!(close(&p, &[0.0; 3], 1e-14));
        assert!(close(&r, &unit_quat(), 1e-14));
        assert!(close(&trn_vec_pose(&v, &q, &np), &[0.0; 3], 1e-14));
        // mul_quat_axis is the product with a pure quaternion
        let a: Vec3 = rng.vec();
        let pure = [0.0, a[0], a[1], a[2]];
        assert!(close(&mul_quat_axis(&q, &a), &mul_quat(&q, &pure), 1e-14));
    }
}

#[test]
fn quat_z2vec_cases() {
    assert_eq!(quat_z2vec(&[0.0, 0.0, 2.0]), unit_quat());
    assert_eq!(quat_z2vec(&[0.0, 0.0, -2.0]), [0.0, 1.0, 0.0, 0.0]);
    assert_eq!(quat_z2vec(&[0.0; 3]), unit_quat());
    let v = [0.3, -0.4, 0.5];
    let q = quat_z2vec(&v);
    let z = rot_vec_quat(&[0.0, 0.0, 1.0], &q);
    assert!(close(&z, &normalize3(&v).0, 1e-15));
    assert_eq!(axis_angle2quat(&[1.0, 0.0, 0.0], 0.0), unit_quat());
}

#[test]
fn euler_sequences() {
    let q = euler2quat(&[0.0, 0.0, PI / 2.0], b"xyz").unwrap();
    assert!(close(&q, &[0.5f64.sqrt(), 0.0, 0.0, 0.5f64.sqrt()], 1e-15));
    // intrinsic xyz equals extrinsic ZYX
    let a = [0.3, -0.2, 0.9];
    let q1 = euler2quat(&a, b"xyz").unwrap();
    let q2 = euler2quat(&[a[2], a[1], a[0]], b"ZYX").unwrap();
    assert!(close(&q1, &q2, 1e-15));
    assert!(euler2quat(&a, b"xqz").is_err());
}

#[test]
fn spatial_algebra() {
    let mut rng = Rng(5);
    for _ in 0..50 {
        let (v, u, f): (Vec6, Vec6, Vec6) = (rng.vec(), rng.vec(), rng.vec());
        // <v x* f, u> = -<f, v x u>
        let lhs = dot(&cross_force(&v, &f), &u, 6);
        let rhs = -dot(&f, &cross_motion(&v, &u), 6);
        assert!((lhs - rhs).abs() < 1e-12);
        // power is invariant under a change of reference point
        let (p0, p1): (Vec3, Vec3) = (rng.vec(), rng.vec());
        let vm = transform_spatial(&v, false, &p1, &p0, None);
        let fm = transform_spatial(&f, true, &p1, &p0, None);
        assert!((dot(&vm, &fm, 6) - dot(&v, &f, 6)).abs() < 1e-12);
        // mul_dof_vec is a weighted sum of rows
        let w = [0.5, 0.0, -1.5];
        let rows: Vec<f64> = v.iter().chain(&u).chain(&f).copied().collect();
        let s = mul_dof_vec(&rows, &w, 3);
        let e: Vec<f64> = (0..6).map(|k| 0.5 * v[k] - 1.5 * f[k]).collect();
        assert!(close(&s, &e, 1e-14));
        assert_eq!(mul_dof_vec(&rows, &w, 0), [0.0; 6]);
    }
    // inertia of a point-free body: the com-frame inertia times a velocity
    let i = inert_com(&[1.0, 2.0, 3.0], &quat2mat(&unit_quat()), &[0.0; 3], 2.0);
    assert_eq!(
        mul_inert_vec(&i, &[1.0, 1.0, 1.0, 1.0, 1.0, 1.0]),
        [1.0, 2.0, 3.0, 2.0, 2.0, 2.0]
    );
    let f = make_frame(&[0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    assert_eq!(f, [0.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0]);
    assert!(make_frame(&[0.1; 9]).is_none());
}

#[test]
fn qcqp_constraint() {
    let a = [2.0, 0.3, 0.3, 1.0];
    let b = [-3.0, 2.0];
    let d = [1.0, 0.5];
    let (x, active) = qcqp2(&a, &b, &d, 0.4);
    assert!(active);
    let c = (x[0] / d[0]).powi(2) + (x[1] / d[1]).powi(2);
    assert!((c - 0.16).abs() < 1e-8);
    let mut xn = [0.0; 2];
    assert_eq!(qcqp(&mut xn, &a, &b, &d, 0.4, 2), Some(true));
    assert!(close(&xn, &x, 1e-8));
    let (x, active) = qcqp2(&a, &b, &d, 100.0);
    assert!(!active);
    assert!(close(
        &[2.0 * x[0] + 0.3 * x[1], 0.3 * x[0] + x[1]],
        &[3.0, -2.0],
        1e-12
    ));
    let a3 = [2.0, 0.3, 0.0, 0.3, 1.0, 0.1, 0.0, 0.1, 1.5];
    let (x3, active) = qcqp3(&a3, &[1.0, 1.0, -1.0], &[1.0; 3], 0.1);
    assert!(active);
    assert!((x3.iter().map(|v| v * v).sum::<f64>() - 0.01).abs() < 1e-8);
    assert_eq!(
        qcqp(&mut [0.0; 6], &[0.0; 36], &[0.0; 6], &[1.0; 6], 1.0, 6),
        None
    );
}

#[test]
fn scalar_helpers() {
    assert_eq!(round(2.5), 3);
    assert_eq!(round(-2.5), -2);
    assert_eq!(round(0.49999999999999994), 0);
    assert_eq!(round(f64::NAN), i32::MIN);
    assert_eq!(round(1e10), i32::MIN);
    assert!(min(f64::NAN, 1.0) == 1.0 && max(1.0, f64::NAN).is_nan());
    assert_eq!(clip(5.0, -1.0, 1.0), 1.0);
    assert_eq!(sign(-0.0), 0.0);
    assert!(is_bad(f64::NAN) && is_bad(-2e10) && !is_bad(1e10));
    assert!(is_zero(&[0.0, -0.0]) && !is_zero(&[0.0, 1e-300]));
    assert_eq!(sigmoid(0.25), 0.125);
    assert_eq!(sigmoid(0.75), 0.875);
    assert_eq!(halton(1, 2), 0.5);
    assert_eq!(halton(3, 2), 0.75);
    assert!((halton(5, 3) - 7.0 / 9.0).abs() < 1e-15);
    let mut l = [3.0, -1.0, 2.0, -1.0, 0.5];
    insertion_sort(&mut l);
    assert_eq!(l, [-1.0, -1.0, 0.5, 2.0, 3.0]);
    let mut li = [3, 1, 2];
    insertion_sort(&mut li);
    assert_eq!(li, [1, 2, 3]);
}

#[test]
fn names_and_texts() {
    for t in 1..24 {
        let n = type2str(t).unwrap();
        assert_eq!(str2type(n.as_bytes()), t);
    }
    assert_eq!(type2str(0), None);
    assert_eq!(type2str(24), None);
    assert_eq!(str2type(b"nothing"), 0);
    assert_eq!(
        warning_text(1, 100),
        "Pre-allocated contact buffer is full. Increase nconmax above 100."
    );
    assert_eq!(warning_text(9, 0), "Unknown warning type 9.");
}

#[test]
fn actuator_curves() {
    let prm = [0.75, 1.05, -1.0, 200.0, 0.5, 1.6, 1.5, 1.3, 1.2];
    let lr = [0.2, 0.6];
    assert!(muscle_gain(0.45, 0.3, &lr, 0.8, &prm) < 0.0);
    assert_eq!(muscle_bias(0.1, &lr, 0.8, &prm), 0.0);
    assert!(muscle_bias(0.7, &lr, 0.8, &prm) < 0.0);
    assert!(muscle_dynamics(1.0, 0.2, &[0.01, 0.04]) > 0.0);
    assert!(muscle_dynamics(0.0, 0.2, &[0.01, 0.04]) < 0.0);
    assert!(spring_damper(0.3, -1.2, 5.0, 0.7, 0.25).is_finite());
    // critically damped and overdamped branches start at pos0
    assert_eq!(spring_damper(0.3, -1.2, 1.0, 2.0, 0.0), 0.3);
    assert!((spring_damper(0.3, -1.2, 1.0, 3.0, 0.0) - 0.3).abs() < 1e-15);
}

#[test]
fn pyramid_roundtrip() {
    let force = [2.0, 0.3, -0.2, 0.1];
    let mu = [0.9, 0.9, 0.5];
    let mut p = [0.0; 6];
    encode_pyramid(&mut p, &force, &mu, 4);
    let mut f = [0.0; 4];
    decode_pyramid(&mut f, &p, &mu, 4);
    assert!(close(&f, &force, 1e-15));
    let mut f1 = [0.0];
    decode_pyramid(&mut f1, &[1.5], &[], 1);
    assert_eq!(f1, [1.5]);
}

#[test]
fn standard_normal_uses_source() {
    let mut k = 0;
    let seq = [3, 1, 2, 2];
    let (a, b) = standard_normal(
        || {
            k += 1;
            seq[(k - 1) % 4]
        },
        4,
    );
    // x1 = 0.5, x2 = -0.5, w = 0.5
    let w = ((-2.0 * 0.5f64.ln()) / 0.5).sqrt();
    assert_eq!((a, b), (0.5 * w, -0.5 * w));
}

#[test]
fn misc_vector_ops() {
    let a = [1.0, -2.0, 3.0];
    assert_eq!(sum(&a), 2.0);
    assert_eq!(l1(&a), 6.0);
    let mut r = [0.0; 3];
    add_scl(&mut r, &a, &a, 2.0);
    assert_eq!(r, [3.0, -6.0, 9.0]);
    sub_from(&mut r, &a);
    add_to_scl(&mut r, &a, -2.0);
    assert_eq!(r, [0.0; 3]);
    assert_eq!(dist3(&[1.0, 2.0, 2.0], &[0.0; 3]), 3.0);
    assert_eq!(cross(&[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]);
    assert_eq!(v3(&[1.0, 2.0, 3.0, 4.0]), [1.0, 2.0, 3.0]);
    let mut mtv = [9.0; 2];
    mul_mat_t_vec(&mut mtv, &[1.0, 2.0, 3.0, 4.0], &[0.0, 1.0], 2, 2);
    assert_eq!(mtv, [3.0, 4.0]);
    assert_eq!(quat2vel(&unit_quat(), 0.1), [0.0; 3]);
    assert_eq!(
        deriv_quat(&unit_quat(), &[2.0, 0.0, 0.0]),
        [0.0, 1.0, 0.0, 0.0]
    );
}

#[test]
fn sparse_products_match_dense() {
    use super::sparse::*;
    let (nr, nc) = (4, 5);
    #[rustfmt::skip]
    let a = [
        1.0, 0.0, 2.0, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.0, 0.0,
        0.0, 3.0, 0.0, -1.0, 0.5,
        0.0, 3.0, 0.0, 2.0, 1.5,
    ];
    let (mut s, mut nnz, mut adr, mut col) = ([0.0; 20], [0; 4], [0; 4], [0; 20]);
    dense2sparse(&mut s, &a, nr, nc, &mut nnz, &mut adr, &mut col);
    assert_eq!(nnz, [2, 0, 3, 3]);
    let mut back = [9.0; 20];
    sparse2dense(&mut back, &s, nr, nc, &nnz, &adr, &col);
    assert_eq!(back, a);

    let v = [1.0, -1.0, 0.5, 2.0, -3.0];
    let (mut y, mut yd) = ([0.0; 4], [0.0; 4]);
    mul_mat_vec_sparse(&mut y, &s, &v, nr, &nnz, &adr, &col, None);
    mul_mat_vec(&mut yd, &a, &v, nr, nc);
    assert!(close(&y, &yd, 1e-15));

    let (mut t, mut tn, mut ta, mut tc) = ([0.0; 20], [0; 5], [0; 5], [0; 20]);
    transpose_sparse(
        &mut t, &s, nr, nc, &mut tn, &mut ta, &mut tc, &nnz, &adr, &col,
    );
    let mut td = [0.0; 20];
    sparse2dense(&mut td, &t, nc, nr, &tn, &ta, &tc);
    let mut at = [0.0; 20];
    transpose(&mut at, &a, nr, nc);
    assert_eq!(td, at);

    let mut sup = [0; 4];
    super_sparse(nr, &mut sup, &nnz, &adr, &col);
    assert_eq!(sup, [0, 0, 1, 0]);
    let mut sup_t = [0; 5];
    super_sparse(nc, &mut sup_t, &tn, &ta, &tc);

    // A' * diag * A, with and without supernodes
    let diag = [1.0, 2.0, 0.5, 3.0];
    let mut dense = [0.0; 25];
    sqr_mat_td(&mut dense, &a, Some(&diag), nr, nc);
    for use_super in [false, true] {
        let m = SparseRef {
            rownnz: &nnz,
            rowadr: &adr,
            colind: &col,
            rowsuper: use_super.then_some(&sup[..]),
        };
        let mt = SparseRef {
            rownnz: &tn,
            rowadr: &ta,
            colind: &tc,
            rowsuper: use_super.then_some(&sup_t[..]),
        };
        let (mut h, mut hn, mut ha, mut hc) = ([0.0; 25], [0; 5], [0; 5], [0; 25]);
        let (mut chain, mut buffer) = ([0; 10], [0.0; 5]);
        sqr_mat_td_sparse_lower(
            &mut h,
            &s,
            &t,
            Some(&diag),
            nc,
            &mut hn,
            &mut ha,
            &mut hc,
            &m,
            &mt,
            &mut chain,
            &mut buffer,
            |_| true,
        );
        mirror_lower_sparse(&mut h, nc, &mut hn, &mut hc);
        let mut hd = [0.0; 25];
        sparse2dense(&mut hd, &h, nc, nc, &hn, &ha, &hc);
        assert!(close(&hd, &dense, 1e-14), "{hd:?}");
    }

    // combining sparse rows
    let (mut dst, mut di) = ([1.0, 2.0, 0.0, 0.0], [0, 2, 0, 0]);
    let (mut buf, mut bi) = ([0.0; 5], [0; 5]);
    let n = combine_sparse(
        &mut dst,
        &[4.0, 5.0],
        5,
        2.0,
        -1.0,
        2,
        2,
        &mut di,
        &[2, 4],
        &mut buf,
        &mut bi,
    );
    assert_eq!(
        (n, &dst[..3], &di[..3]),
        (3, &[2.0, 0.0, -5.0][..], &[0, 2, 4][..])
    );
    assert_eq!(dot_sparse2(&dst, &[1.0, 1.0], 3, &di, 2, &[0, 4]), -3.0);
}

/// J'*D*J rows with the rows of D = +0 left out (`keep_nonfinite_rows`, `add_td_row` with
/// skip_zero) give the sums with them, bit for bit: random patterns with runs of rows alike,
/// D zero on about half the rows, -0 among the values, infinities and NaNs in some rows.
#[test]
fn td_rows_without_zero_rows_give_the_same_sums() {
    use super::sparse::*;
    let mut uniform = uniform(4242);
    for trial in 0..300 {
        let (nr, nc) = (1 + trial % 23, 1 + trial % 17);
        let mut a = vec![0.0; nr * nc];
        for r in 0..nr {
            // every third row repeats the pattern of the row before (supernodes)
            let like = r > 0 && r % 3 == 0;
            for c in 0..nc {
                let on = if like {
                    a[(r - 1) * nc + c] != 0.0
                } else {
                    uniform() < 0.4
                };
                if on {
                    a[r * nc + c] = match (uniform() * 40.0) as i32 {
                        0 => f64::INFINITY,
                        1 => f64::NAN,
                        2 => -0.0,
                        _ => uniform() - 0.5,
                    };
                }
                if a[r * nc + c].to_bits() == (-0.0f64).to_bits() {
                    a[r * nc + c] = 1e-300 * -1e-300; // -0, still in the pattern below
                }
            }
        }
        // the pattern: nonzero bits (a -0 entry counts)
        let (mut s, mut nnz, mut adr, mut col) = (
            vec![0.0; nr * nc],
            vec![0; nr],
            vec![0; nr],
            vec![0; nr * nc],
        );
        let mut k = 0;
        for r in 0..nr {
            adr[r] = k as i32;
            for c in 0..nc {
                if a[r * nc + c].to_bits() != 0 {
                    s[k] = a[r * nc + c];
                    col[k] = c as i32;
                    k += 1;
                }
            }
            nnz[r] = k as i32 - adr[r];
        }
        let (mut t, mut tn, mut ta, mut tc) = (
            vec![0.0; nr * nc],
            vec![0; nc],
            vec![0; nc],
            vec![0; nr * nc],
        );
        transpose_sparse(
            &mut t, &s, nr, nc, &mut tn, &mut ta, &mut tc, &nnz, &adr, &col,
        );
        let (mut sup, mut sup_t) = (vec![0; nr], vec![0; nc]);
        super_sparse(nr, &mut sup, &nnz, &adr, &col);
        super_sparse(nc, &mut sup_t, &tn, &ta, &tc);
        let m = SparseRef {
            rownnz: &nnz,
            rowadr: &adr,
            colind: &col,
            rowsuper: Some(&sup),
        };
        let mt = SparseRef {
            rownnz: &tn,
            rowadr: &ta,
            colind: &tc,
            rowsuper: Some(&sup_t),
        };
        let diag: Vec<f64> = (0..nr)
            .map(|_| if uniform() < 0.5 { 0.0 } else { uniform() })
            .collect();
        let mut marked = diag.clone();
        keep_nonfinite_rows(&mut marked, &s, &m);
        for r in 0..nc {
            let (mut all, mut some) = (vec![0.0; nc], vec![0.0; nc]);
            add_td_row(&mut all, r, &s, &t, Some(&diag), false, &m, &mt);
            add_td_row(&mut some, r, &s, &t, Some(&marked), true, &m, &mt);
            let same = all
                .iter()
                .zip(&some)
                .all(|(x, y)| x.to_bits() == y.to_bits());
            assert!(same, "trial {trial} row {r}: {all:?} {some:?}");
        }
    }
}

#[test]
fn sparse_cholesky_and_lu_solve() {
    use super::chol_sparse::*;
    // symmetric positive definite with a tree pattern (parents 0 <- 1, 0 <- 3; 2 alone),
    // uncompressed (stride n) layout
    let n = 4;
    #[rustfmt::skip]
    let dense = [
        4.0, 1.0, 0.0, 0.5,
        1.0, 3.0, 0.0, 0.0,
        0.0, 0.0, 2.0, 0.0,
        0.5, 0.0, 0.0, 5.0,
    ];
    let mut mat = [0.0; 16];
    let mut colind = [0; 16];
    let mut rownnz = [0; 4];
    let rowadr = [0, 4, 8, 12];
    for r in 0..n {
        for c in 0..n {
            if dense[r * n + c] != 0.0 {
                let k = rowadr[r] as usize + rownnz[r] as usize;
                mat[k] = dense[r * n + c];
                colind[k] = c as i32;
                rownnz[r] += 1;
            }
        }
    }
    let (lu_mat, lu_nnz, lu_col) = (mat, rownnz, colind);
    let (mut buf, mut bi) = ([0.0; 4], [0; 4]);
    let rank = chol_factor_sparse(
        &mut mat,
        n,
        1e-15,
        &mut rownnz,
        &rowadr,
        &mut colind,
        &mut buf,
        &mut bi,
    );
    assert_eq!(rank, Ok(4));
    let b = [1.0, -2.0, 0.5, 3.0];
    let mut x = [0.0; 4];
    chol_solve_sparse(&mut x, &mat, &b, n, &rownnz, &rowadr, &colind);
    let mut ax = [0.0; 4];
    mul_mat_vec(&mut ax, &dense, &x, n, n);
    assert!(close(&ax, &b, 1e-14));

    // update: factor of A + v v' with v inside the pattern
    let (mut v, mut vi) = ([0.5, 0.2], [0, 3]);
    let mut up = mat;
    let r = chol_update_sparse(
        &mut up, &mut v, n, true, &rownnz, &rowadr, &colind, 2, &mut vi, &mut buf, &mut bi,
    );
    assert_eq!(r, Ok(4));
    let mut dense2 = dense;
    dense2[0] += 0.25;
    dense2[3] += 0.1;
    dense2[12] += 0.1;
    dense2[15] += 0.04;
    chol_solve_sparse(&mut x, &up, &b, n, &rownnz, &rowadr, &colind);
    mul_mat_vec(&mut ax, &dense2, &x, n, n);
    assert!(close(&ax, &b, 1e-14));

    // LU on the same pattern, compressed layout
    let mut lu = [0.0; 16];
    let mut col = [0; 16];
    let mut adr = [0; 4];
    let mut k = 0;
    for r in 0..n {
        adr[r] = k as i32;
        for i in 0..lu_nnz[r] as usize {
            lu[k] = lu_mat[4 * r + i];
            col[k] = lu_col[4 * r + i];
            k += 1;
        }
    }
    let mut scratch = [0; 4];
    assert_eq!(
        factor_lu_sparse(&mut lu, n, &mut scratch, &lu_nnz, &adr, &col),
        Ok(())
    );
    assert_eq!(
        solve_lu_sparse(&mut x, &lu, &b, n, &lu_nnz, &adr, &col),
        Ok(())
    );
    mul_mat_vec(&mut ax, &dense, &x, n, n);
    assert!(close(&ax, &b, 1e-14));
}

#[test]
fn sparse_mat_vec_supernodes_sum_like_single_rows() {
    use super::sparse::*;
    // runs of 1 to 6 rows sharing a pattern, then rows of their own
    let (nc, mut rows) = (7, Vec::new());
    for (run, pat) in [
        (6, vec![0, 2, 3, 6]),
        (3, vec![1, 4]),
        (1, vec![0, 5]),
        (2, vec![2, 3, 4, 5, 6]),
    ] {
        for k in 0..run {
            let mut row = vec![0.0; nc];
            for (j, &c) in pat.iter().enumerate() {
                row[c] = 0.1 + 1.7 * (k * 7 + j) as f64 / 3.0;
            }
            rows.push(row);
        }
    }
    rows.push(vec![0.0; nc]);
    let nr = rows.len();
    let a: Vec<f64> = rows.concat();
    let (mut s, mut nnz, mut adr, mut col) = (
        vec![0.0; nr * nc],
        vec![0; nr],
        vec![0; nr],
        vec![0; nr * nc],
    );
    dense2sparse(&mut s, &a, nr, nc, &mut nnz, &mut adr, &mut col);
    let mut sup = vec![0; nr];
    super_sparse(nr, &mut sup, &nnz, &adr, &col);
    assert_eq!(&sup[..6], &[5, 4, 3, 2, 1, 0]);
    let v: Vec<f64> = (0..nc).map(|i| 1.0 / (i as f64 + 0.3)).collect();
    let (mut by_super, mut by_compare) = (vec![9.0; nr], vec![9.0; nr]);
    mul_mat_vec_sparse(&mut by_super, &s, &v, nr, &nnz, &adr, &col, Some(&sup));
    mul_mat_vec_sparse(&mut by_compare, &s, &v, nr, &nnz, &adr, &col, None);
    for r in 0..nr {
        let (a0, n) = (adr[r] as usize, nnz[r] as usize);
        let single = dot_sparse(&s[a0..a0 + n], &v, n, &col[a0..a0 + n]);
        assert_eq!(by_super[r].to_bits(), single.to_bits(), "row {r}");
        assert_eq!(by_compare[r].to_bits(), single.to_bits(), "row {r}");
    }
}

#[test]
fn paired_chol_updates_are_two_updates_in_turn() {
    let n = 7;
    let mut a = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            a[i * n + j] =
                1.0 / (1.0 + (i as f64 - j as f64).abs()) + if i == j { 3.0 } else { 0.0 };
        }
    }
    chol_factor(&mut a, n, 1e-15);
    let v1: Vec<f64> = (0..n)
        .map(|i| if i == 2 { 0.0 } else { 0.3 * i as f64 - 0.8 })
        .collect();
    let v2: Vec<f64> = (0..n).map(|i| 0.9 - 0.17 * i as f64).collect();
    // plus then plus, plus then minus, and a minus that loses rank
    for (p1, p2, scale) in [(true, true, 1.0), (true, false, 1.0), (false, true, 40.0)] {
        let w1: Vec<f64> = v1.iter().map(|x| x * scale).collect();
        let (mut l, mut x1, mut x2) = (a.clone(), w1.clone(), v2.clone());
        let r1 = chol_update(&mut l, &mut x1, n, p1);
        let r2 = chol_update(&mut l, &mut x2, n, p2);
        let (mut lp, mut y1, mut y2) = (a.clone(), w1.clone(), v2.clone());
        assert_eq!(chol_update2(&mut lp, &mut y1, p1, &mut y2, p2, n), (r1, r2));
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&l), bits(&lp));
        assert_eq!((bits(&x1), bits(&x2)), (bits(&y1), bits(&y2)));
    }
}

/// Rows zero outside a span, with exact cancellations and signed zeros inside it.
fn span_rows(rng: &mut Rng, n: usize) -> Vec<(Vec<f64>, usize, usize)> {
    let mut rows = Vec::new();
    for lo in 0..n {
        for hi in lo..=n {
            let mut row = vec![0.0; n];
            for (k, x) in row[lo..hi].iter_mut().enumerate() {
                *x = match k % 4 {
                    0 => rng.next(),
                    1 => -0.0,
                    2 => 1.0,
                    _ => -1.0,
                };
            }
            rows.push((row, lo, hi));
        }
    }
    rows
}

#[test]
fn dot_span_is_dot_to_the_bit() {
    let mut rng = Rng(17);
    for n in 0..14 {
        let mut b: Vec<f64> = (0..n).map(|_| rng.next()).collect();
        if n > 2 {
            b[1] = -0.0;
            b[2] = 1.0;
        }
        for (row, lo, hi) in span_rows(&mut rng, n) {
            let (x, y) = (dot(&row, &b, n), dot_span(&row, &b, n, lo, hi));
            assert_eq!(x.to_bits(), y.to_bits(), "n {n} span {lo}..{hi}: {x} {y}");
        }
    }
}

#[test]
fn mul_mat_t_vec_span_is_whole_rows_to_the_bit() {
    let mut rng = Rng(19);
    for nc in 1..10 {
        let rows = span_rows(&mut rng, nc);
        let nr = rows.len();
        let mat: Vec<f64> = rows.iter().flat_map(|r| r.0.clone()).collect();
        let mut vec: Vec<f64> = (0..nr).map(|_| rng.next()).collect();
        vec[nr / 2] = f64::INFINITY; // taken whole: 0 * inf is NaN in every column
        vec[nr / 3] = 0.0;
        let (mut x, mut y) = (vec![1.0; nc], vec![2.0; nc]);
        // whole rows, as MuJoCo takes them: res = 0, then res += row * weight per nonzero weight
        x.fill(0.0);
        for (r, &w) in vec.iter().enumerate() {
            if w != 0.0 {
                add_to_scl(&mut x, &mat[r * nc..(r + 1) * nc], w);
            }
        }
        mul_mat_t_vec_span(&mut y, &mat, &vec, nr, nc, |r| (rows[r].1, rows[r].2));
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&x), bits(&y), "nc {nc}");
    }
}

#[test]
fn sparse_cholesky_pattern_laid_out_ahead_gives_the_same_factor() {
    use super::chol_sparse::*;
    let mut rng = Rng(19);
    for trial in 0..200 {
        let n = 1 + trial % 37;
        let parent: Vec<i32> = (0..n)
            .map(|r| match r {
                0 => -1,
                _ if rng.next() < -1.0 => -1,
                _ => ((rng.next() + 2.0) / 4.0 * r as f64) as i32,
            })
            .collect();
        let simple: Vec<i32> = (0..n).map(|_| (rng.next() > 1.0) as i32).collect();
        let density = (rng.next() + 2.0) / 16.0;
        // own patterns (lower, diagonal left to the mass matrix's part), packed
        let (mut own, mut own_nnz, mut own_adr) = (vec![], vec![0; n], vec![0; n]);
        // the whole lower pattern, rows n apart, diagonally dominant values
        let (mut mat, mut colind, mut rownnz) = (vec![0.0; n * n], vec![0; n * n], vec![0; n]);
        let rowadr: Vec<i32> = (0..n).map(|r| (r * n) as i32).collect();
        for r in 0..n {
            let mut cols = vec![r];
            own_adr[r] = own.len() as i32;
            for c in 0..r {
                if (rng.next() + 2.0) / 4.0 < density {
                    own.push(c as i32);
                    cols.push(c);
                }
            }
            own_nnz[r] = own.len() as i32 - own_adr[r];
            if simple[r] == 0 {
                let mut j = parent[r];
                while j >= 0 {
                    cols.push(j as usize);
                    j = parent[j as usize];
                }
            }
            cols.sort();
            cols.dedup();
            for &c in &cols {
                let k = r * n + rownnz[r] as usize;
                mat[k] = if c == r { 4.0 * n as f64 } else { rng.next() };
                colind[k] = c as i32;
                rownnz[r] += 1;
            }
        }
        let (in_mat, in_nnz, in_col) = (mat.clone(), rownnz.clone(), colind.clone());
        let (mut buf, mut bi) = (vec![0.0; n], vec![0; n]);
        let rank = chol_factor_sparse(
            &mut mat,
            n,
            1e-15,
            &mut rownnz,
            &rowadr,
            &mut colind,
            &mut buf,
            &mut bi,
        );
        assert_eq!(rank, Ok(n));

        // the factor's pattern laid out ahead, then its values: the same factor, bit for bit
        let mut pn = own_nnz.clone();
        let mut padr = own_adr.clone();
        let room = own.len() + rownnz.iter().sum::<i32>() as usize + 4 * n;
        let mut pc = own.clone();
        pc.resize(room, 0);
        let fits = chol_sparse_pattern(n, &mut pn, &mut padr, &mut pc, &parent, &simple);
        assert!(fits, "trial {trial}");
        assert_eq!(pn, rownnz, "trial {trial}");
        let mut pm = vec![f64::NAN; room];
        let mut buf = vec![f64::NAN; n];
        chol_sparse_values(&mut pm, n, &pn, &padr, &mut pc, &mut buf, |r, buf| {
            for k in r * n..r * n + in_nnz[r] as usize {
                buf[in_col[k] as usize] = in_mat[k];
            }
        });
        let rank = chol_factor_sparse_preset(&mut pm, n, 1e-15, &pn, &padr, &pc);
        assert_eq!(rank, Ok(n));
        for r in 0..n {
            let (s, d, k) = (r * n, padr[r] as usize, rownnz[r] as usize);
            assert_eq!(&pc[d..d + k], &colind[s..s + k], "trial {trial} row {r}");
            let same = pm[d..d + k].iter().zip(&mat[s..s + k]);
            assert!(same.into_iter().all(|(a, b)| a.to_bits() == b.to_bits()));
            if r > 0 {
                assert_eq!(padr[r], padr[r - 1] + pn[r - 1]);
            }
        }
        // too little room for the rows: no pattern
        let (mut pn, mut padr) = (own_nnz.clone(), own_adr.clone());
        let mut pc = own.clone();
        pc.resize(own.len().max(room - own.len() - 1), 0);
        assert!(!chol_sparse_pattern(
            n, &mut pn, &mut padr, &mut pc, &parent, &simple
        ));
    }
}

/// Uniform numbers in [0, 1) from a 64-bit linear congruential generator.
pub(crate) fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// dot4 gives dot's four sums bit for bit, and chol_factor (rows four at a time) the factor of
/// rows one at a time, on random vectors and matrices of every remainder length.
#[test]
fn dot4_and_chol_factor_as_one_row_at_a_time() {
    use super::blas::{dot, dot4};
    use super::chol::chol_factor;
    let mut unit = uniform(99);
    let mut uniform = move || unit() - 0.5;
    for n in 0..24 {
        let a: Vec<Vec<f64>> = (0..4)
            .map(|_| (0..n).map(|_| uniform()).collect())
            .collect();
        let b: Vec<f64> = (0..n).map(|_| uniform()).collect();
        let four = dot4([&a[0], &a[1], &a[2], &a[3]], &b, n);
        for r in 0..4 {
            assert_eq!(four[r].to_bits(), dot(&a[r], &b, n).to_bits());
        }
    }
    for n in 1..14 {
        // A*A' + n*I, and a copy factored one row at a time as before
        let a: Vec<f64> = (0..n * n).map(|_| uniform()).collect();
        let mut mat = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                mat[i * n + j] = dot(&a[i * n..], &a[j * n..], n) + if i == j { 0.1 } else { 0.0 };
            }
        }
        let mut one = mat.clone();
        for j in 0..n {
            let d = one[j * (n + 1)] - dot(&one[j * n..], &one[j * n..], j);
            one[j * (n + 1)] = d.max(1e-15).sqrt();
            let inv = 1.0 / one[j * (n + 1)];
            for i in j + 1..n {
                let s = dot(&one[i * n..], &one[j * n..], j);
                one[i * n + j] = (one[i * n + j] - s) * inv;
            }
        }
        assert_eq!(chol_factor(&mut mat, n, 1e-15), n);
        for (x, y) in mat.iter().zip(&one) {
            assert_eq!(x.to_bits(), y.to_bits());
        }
    }
}

/// mul_mat3, mul_mat3t_mat and mul_dof_vec (zero entries or weights skipped by selection) give
/// the branchy skip's bits: random values with zeros, signed zeros, infinities and NaN.
#[test]
fn small_products_skip_zeros_as_branches() {
    let branchy = |a: &Mat3, b: &Mat3, at: bool| {
        let mut r = [0.0; 9];
        for i in 0..3 {
            for k in 0..3 {
                let s = if at { a[3 * k + i] } else { a[3 * i + k] };
                if s != 0.0 {
                    for j in 0..3 {
                        r[3 * i + j] += b[3 * k + j] * s;
                    }
                }
            }
        }
        r
    };
    let mut r = uniform(11);
    let special = [
        0.0,
        -0.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        1.0,
        -1.0,
    ];
    let pick = |r: &mut dyn FnMut() -> f64| {
        let u = r();
        if u < 0.5 {
            special[(r() * special.len() as f64) as usize % special.len()]
        } else {
            4.0 * r() - 2.0
        }
    };
    for _ in 0..20_000 {
        let a: Mat3 = std::array::from_fn(|_| pick(&mut r));
        let b: Mat3 = std::array::from_fn(|_| pick(&mut r));
        let bits = |m: Mat3| m.map(f64::to_bits);
        assert_eq!(bits(mul_mat3(&a, &b)), bits(branchy(&a, &b, false)));
        assert_eq!(bits(mul_mat3t_mat(&a, &b)), bits(branchy(&a, &b, true)));
        // mul_dof_vec: 1 to 3 rows of a and b as six-vectors, weighted by b's last entries
        let dofs: Vec<f64> = a.iter().chain(&b).copied().collect();
        for n in 1..=3 {
            let w = &b[9 - n..];
            // one row: scaled as it is (its -0 kept); more: summed from +0, zero weights skipped
            let mut want: [f64; 6] = std::array::from_fn(|k| dofs[k] * w[0]);
            if n > 1 {
                want = [0.0; 6];
            }
            for j in 0..n {
                if n > 1 && w[j] != 0.0 {
                    for k in 0..6 {
                        want[k] += dofs[6 * j + k] * w[j];
                    }
                }
            }
            let got = spatial::mul_dof_vec(&dofs, w, n);
            assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "{n}");
        }
    }
}

#[test]
fn sqr_pattern_of_completed_chains_merges_only_tree_roots() {
    use super::sparse::*;
    let mut rng = Rng(41);
    for trial in 0..200 {
        // a forest of nv dofs (parents before children), rows on chains completed to roots
        let nv = 2 + trial % 19;
        let parent: Vec<i32> = (0..nv)
            .map(|i| {
                let r = rng.next();
                if i == 0 || r < -1.2 {
                    -1
                } else {
                    ((r + 2.0) / 4.0 * i as f64) as i32
                }
            })
            .collect();
        let nr = 1 + (rng.next() + 2.0) as usize * 5;
        let (mut nnz, mut adr, mut col) = (vec![], vec![], vec![]);
        for r in 0..nr {
            let mut on = vec![false; nv];
            for _ in 0..(rng.next() + 2.0) as usize {
                let mut c = (((rng.next() + 2.0) / 4.0 * nv as f64) as usize).min(nv - 1) as i32;
                while c >= 0 {
                    on[c as usize] = true;
                    c = parent[c as usize];
                }
            }
            // now and then an empty row, or rows repeated (supernodes)
            if r > 0 && rng.next() < -1.0 {
                let (a, n) = (adr[r - 1] as usize, nnz[r - 1] as usize);
                on = vec![false; nv];
                for &c in &col[a..a + n] {
                    on[c as usize] = true;
                }
            }
            adr.push(col.len() as i32);
            col.extend((0..nv as i32).filter(|&c| on[c as usize]));
            nnz.push(col.len() as i32 - adr[r]);
        }
        let vals = vec![1.0; col.len()];
        let (mut t, mut tn, mut ta, mut tc) = (
            vec![0.0; nr * nv],
            vec![0; nv],
            vec![0; nv],
            vec![0; nr * nv],
        );
        transpose_sparse(
            &mut t, &vals, nr, nv, &mut tn, &mut ta, &mut tc, &nnz, &adr, &col,
        );
        let (mut sup, mut sup_t) = (vec![0; nr], vec![0; nv]);
        super_sparse(nr, &mut sup, &nnz, &adr, &col);
        super_sparse(nv, &mut sup_t, &tn, &ta, &tc);
        // A = B'B with B = the transpose (nv x nr): its rows merge the dofs' rows
        let m = SparseRef {
            rownnz: &tn,
            rowadr: &ta,
            colind: &tc,
            rowsuper: Some(&sup_t),
        };
        let mt = SparseRef {
            rownnz: &nnz,
            rowadr: &adr,
            colind: &col,
            rowsuper: Some(&sup),
        };
        let pattern = |merged: &dyn Fn(usize) -> bool| {
            let (mut n, mut a, mut c) = (vec![0; nr], vec![0; nr], vec![-1; nr * nr]);
            let mut chain = vec![0; 2 * nr];
            let rows = (&mut n[..], &mut a[..], &mut c[..]);
            sqr_mat_td_sparse_pattern(nr, rows, &m, &mt, &mut chain, false, merged);
            (n, a, c)
        };
        let all = pattern(&|_| true);
        let roots = pattern(&|c| parent[c] < 0);
        assert_eq!(all, roots, "trial {trial}");
        assert!(all.0.iter().zip(&nnz).all(|(&p, &n)| (p > 0) == (n > 0)));
    }
}

/// The sparse Cholesky solve, which runs two blocks of rows side by side where they share no
/// column, gives the solve of one pass over the rows bit for bit: factors of random forests
/// (trees joined across the middle or not, zeros in the right side).
#[test]
fn sparse_cholesky_solve_in_two_blocks_as_in_one_pass() {
    use super::chol_sparse::*;
    use super::sparse::dot_sparse;
    let mut rng = uniform(23);
    let mut splits = 0;
    for trial in 0..400 {
        let n = 1 + trial % 41;
        // a row's columns: its ancestors in a random forest, whose trees are contiguous
        let (mut mat, mut colind, mut rownnz, mut rowadr) = (vec![], vec![], vec![], vec![]);
        let parent: Vec<i64> = (0..n)
            .map(|r: usize| {
                if r == 0 || rng() >= 0.8 {
                    return -1;
                }
                // joined to an earlier row, sometimes across all of them
                let lo = if rng() < 0.2 { 0 } else { r.saturating_sub(4) };
                (lo + ((r - lo) as f64 * rng()) as usize) as i64
            })
            .collect();
        for r in 0..n {
            let mut cols = vec![];
            let mut j = parent[r];
            while j >= 0 {
                cols.push(j as i32);
                j = parent[j as usize];
            }
            cols.sort();
            rowadr.push(colind.len() as i32);
            rownnz.push(cols.len() as i32 + 1);
            for &c in &cols {
                colind.push(c);
                mat.push(rng() - 0.5);
            }
            colind.push(r as i32);
            mat.push(1.0 + 3.0 * rng());
        }
        let b: Vec<f64> = (0..n)
            .map(|_| if rng() < 0.2 { 0.0 } else { rng() - 0.5 })
            .collect();
        // one pass: L' from the last row, then L from the first
        let mut want = b.clone();
        for i in (0..n).rev() {
            let (adr, nnz) = (rowadr[i] as usize, rownnz[i] as usize);
            if want[i] != 0.0 {
                want[i] /= mat[adr + nnz - 1];
                for k in adr..adr + nnz - 1 {
                    want[colind[k] as usize] -= mat[k] * want[i];
                }
            }
        }
        for i in 0..n {
            let (adr, nnz) = (rowadr[i] as usize, rownnz[i] as usize);
            if nnz > 1 {
                want[i] -= dot_sparse(&mat[adr..], &want, nnz - 1, &colind[adr..]);
            }
            want[i] /= mat[adr + nnz - 1];
        }
        let mut got = vec![0.0; n];
        chol_solve_sparse(&mut got, &mat, &b, n, &rownnz, &rowadr, &colind);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&got), bits(&want), "trial {trial}");
        splits += (1..n).any(|s| (s..n).all(|r| parent[r] < 0 || parent[r] >= s as i64)) as usize;
    }
    assert!(splits > 100, "{splits} forests with two blocks");
}

/// The portable four-lane sums follow the lane order written out element by element, and the
/// AVX ones (where the CPU has AVX) agree with them bit for bit but for the sign of a NaN, on
/// random vectors with signed zeros, infinities and NaNs of both signs, of lengths 0 to 40.
#[cfg(target_arch = "x86_64")]
#[test]
fn avx_lane_sums_as_portable() {
    use super::blas::{lane_sum4_portable, lane_sum_portable};
    use super::lanes::{lane_sum4_avx, lane_sum_avx};
    let avx = std::is_x86_feature_detected!("avx");
    let same = |x: f64, y: f64| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
    // Lane k sums the products of elements k, k + 4, ..., in order; then (2 + 0) + (3 + 1).
    let lanes = |a: &[f64], b: &[f64]| {
        let lane = |k: usize| {
            let mut s = 0.0;
            for i in (k..a.len()).step_by(4) {
                s += b[i] * a[i];
            }
            s
        };
        (lane(2) + lane(0)) + (lane(3) + lane(1))
    };
    let mut unit = uniform(5);
    let special = [
        0.0,
        -0.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        -f64::NAN,
    ];
    let mut value = move || {
        let u = unit();
        if u < 0.1 {
            special[(unit() * 6.0) as usize % 6]
        } else if u < 0.2 {
            -0.0
        } else {
            4.0 * unit() - 2.0
        }
    };
    let (mut nan, mut checked) = (0, 0);
    for n in (0..=40).step_by(4) {
        for _ in 0..200 {
            let a: Vec<Vec<f64>> = (0..4).map(|_| (0..n).map(|_| value()).collect()).collect();
            let b: Vec<f64> = (0..n).map(|_| value()).collect();
            let rows = [&a[0][..], &a[1][..], &a[2][..], &a[3][..]];
            let four_portable = lane_sum4_portable(rows, &b);
            // SAFETY: called only where the CPU runs AVX (detected above).
            let four = avx.then(|| unsafe { lane_sum4_avx(rows, &b) });
            for r in 0..4 {
                let want = lanes(&a[r], &b);
                let one = lane_sum_portable(&a[r], &b);
                assert!(same(one, want));
                assert!(same(four_portable[r], want));
                if let Some(four) = four {
                    // SAFETY: as above.
                    let one_avx = unsafe { lane_sum_avx(&a[r], &b) };
                    assert_eq!(four[r].to_bits(), one_avx.to_bits());
                    assert!(same(one_avx, want));
                    checked += 1;
                }
                nan += want.is_nan() as usize;
            }
        }
    }
    assert!(nan > 1000, "{nan} NaN sums");
    assert!(
        !avx || checked == 11 * 200 * 4,
        "{checked} AVX sums checked"
    );
}

/// The transpose leaves its whole output as 2.2.2's does (every row written at stride nr,
/// then the rows moved to the front; mjData shows the leftovers past the compressed rows):
/// random patterns of Jacobian shapes, the outputs holding the same old values beforehand.
#[test]
fn transpose_sparse_leaves_what_strided_rows_leave() {
    use super::sparse::*;
    let mut rng = Rng(11);
    for case in 0..300 {
        let nr = 1 + case % 37;
        let nc = 1 + (case * 7) % 29;
        let (mut mat, mut nnz, mut adr, mut col) = (vec![], vec![0; nr], vec![0; nr], vec![]);
        for r in 0..nr {
            adr[r] = mat.len() as i32;
            for c in 0..nc {
                if rng.next() > 0.8 + (case % 3) as f64 * 0.5 {
                    mat.push(rng.next());
                    col.push(c as i32);
                }
            }
            nnz[r] = mat.len() as i32 - adr[r];
        }
        let old: Vec<f64> = (0..nr * nc + 5).map(|_| rng.next()).collect();
        let old_col: Vec<i32> = (0..nr * nc + 5).map(|i| -(i as i32)).collect();
        // 2.2.2's way: rows at rt * nr, then compressed
        let (mut want, mut want_col) = (old.clone(), old_col.clone());
        let (mut want_nnz, mut want_adr) = (vec![0; nc], vec![0; nc]);
        for (rt, a) in want_adr.iter_mut().enumerate() {
            *a = (rt * nr) as i32;
        }
        for r in 0..nr {
            for i in adr[r] as usize..(adr[r] + nnz[r]) as usize {
                let rt = col[i] as usize;
                let k = rt * nr + want_nnz[rt] as usize;
                want[k] = mat[i];
                want_col[k] = r as i32;
                want_nnz[rt] += 1;
            }
        }
        compress_sparse(&mut want, nc, &want_nnz, &mut want_adr, &mut want_col);
        let (mut got, mut got_col) = (old.clone(), old_col.clone());
        let (mut got_nnz, mut got_adr) = (vec![7; nc], vec![7; nc]);
        transpose_sparse(
            &mut got,
            &mat,
            nr,
            nc,
            &mut got_nnz,
            &mut got_adr,
            &mut got_col,
            &nnz,
            &adr,
            &col,
        );
        assert_eq!(got_nnz, want_nnz, "case {case}");
        assert_eq!(got_adr, want_adr, "case {case}");
        assert_eq!(got_col, want_col, "case {case}");
        assert!(
            got.iter()
                .zip(&want)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "case {case}"
        );
    }
}
