//! Box-box collision (mjc_BoxBox of 2.2.2): separating-axis test over the 6 face normals and
//! 9 edge-edge axes, then face-face or edge-face contact generation, with 2.2.2's arithmetic
//! (including its quirks: face contacts report half the depth, and the edge path reuses a
//! scalar across corner tests). Comparisons are spelled as in 2.2.2 so that NaN takes the same
//! branches.
#![allow(clippy::manual_range_contains)]

use super::primitive::{ContactGeom, GeomPose};
use crate::math::vec3::{
    add3, dot3, mul_mat3_t, mul_mat3t_mat, mul_mat_t_vec3, mul_mat_vec3, normalize3, scl3, sub3,
    transpose3,
};
use crate::math::{Mat3, Vec3, MINVAL};

/// Most contacts `box_box` can produce.
pub const MAX_BOX_CONTACTS: usize = 24;

#[inline]
fn add_scl(a: &Vec3, b: &[f64], s: f64) -> Vec3 {
    [a[0] + b[0] * s, a[1] + b[1] * s, a[2] + b[2] * s]
}

#[inline]
fn row(m: &Mat3, i: usize) -> Vec3 {
    [m[3 * i], m[3 * i + 1], m[3 * i + 2]]
}

#[inline]
fn sgn(b: bool) -> f64 {
    if b {
        1.0
    } else {
        -1.0
    }
}

/// Axis permutation and signs taking face `face` (0..6: -x,-y,-z... as 2.2.2 numbers them)
/// to +z: the rotation matrix, and (index, factor) per output axis.
fn face_frame(face: i32) -> (Mat3, [usize; 3], [f64; 3]) {
    let mut rm = [0.0; 9];
    let (mut i, mut f) = ([0, 1, 2], [1.0, 1.0, 1.0]);
    match face {
        0 => {
            rm[2] = -1.0;
            rm[4] = 1.0;
            rm[6] = 1.0;
            i = [2, 1, 0];
            f[0] = -1.0;
        }
        1 => {
            rm[0] = 1.0;
            rm[5] = -1.0;
            rm[7] = 1.0;
            i = [0, 2, 1];
            f[1] = -1.0;
        }
        2 => {
            rm[0] = 1.0;
            rm[4] = 1.0;
            rm[8] = 1.0;
        }
        3 => {
            rm[2] = 1.0;
            rm[4] = 1.0;
            rm[6] = -1.0;
            i = [2, 1, 0];
            f[2] = -1.0;
        }
        4 => {
            rm[0] = 1.0;
            rm[5] = 1.0;
            rm[7] = -1.0;
            i = [0, 2, 1];
            f[2] = -1.0;
        }
        5 => {
            rm[0] = -1.0;
            rm[4] = 1.0;
            rm[8] = -1.0;
            f[0] = -1.0;
            f[2] = -1.0;
        }
        _ => {}
    }
    (rm, i, f)
}

#[inline]
fn rot_axis(v: &Vec3, i: &[usize; 3], f: &[f64; 3]) -> Vec3 {
    [v[i[0]] * f[0], v[i[1]] * f[1], v[i[2]] * f[2]]
}

#[inline]
fn rot_rows(m: &Mat3, i: &[usize; 3], f: &[f64; 3]) -> Mat3 {
    let mut r = [0.0; 9];
    for k in 0..3 {
        r[3 * k..3 * k + 3].copy_from_slice(&scl3(&row(m, i[k]), f[k]));
    }
    r
}

/// Box (g1) and box (g2). `con` must hold MAX_BOX_CONTACTS.
pub fn box_box(g1: &GeomPose, g2: &GeomPose, margin: f64, con: &mut [ContactGeom]) -> usize {
    let (pos1, mat1, size1) = (&g1.pos, &g1.mat, &g1.size);
    let (pos2, mat2, size2) = (&g2.pos, &g2.mat, &g2.size);
    let margin2 = margin * margin;
    let mut code: i32 = -1;

    let pos21 = mul_mat_t_vec3(mat1, &sub3(pos2, pos1));
    let pos12 = mul_mat_t_vec3(mat2, &sub3(pos1, pos2));
    let rot = mul_mat3t_mat(mat1, mat2);
    let rott = transpose3(&rot);
    let rotabs = rot.map(f64::abs);
    let rottabs = rott.map(f64::abs);
    let plen2 = mul_mat_vec3(&rotabs, size2);
    let plen1 = mul_mat_t_vec3(&rotabs, size1);

    let mut penetration = margin;
    for i in 0..3 {
        penetration += size1[i] * 3.0 + size2[i] * 3.0;
    }

    // face axes
    for i in 0..3 {
        let c1 = -pos21[i].abs() + size1[i] + plen2[i];
        let c2 = -pos12[i].abs() + size2[i] + plen1[i];
        if c1 < -margin || c2 < -margin {
            return 0;
        }
        if c1 < penetration {
            penetration = c1;
            code = i as i32 + 3 * (pos21[i] < 0.0) as i32;
        }
        if c2 < penetration {
            penetration = c2;
            code = i as i32 + 3 * (pos12[i] < 0.0) as i32 + 6;
        }
    }

    // edge-edge axes
    let (mut cle1, mut cle2) = (0usize, 0usize);
    let mut clnorm = [0.0; 3];
    let mut inside = false;
    for i in 0..3 {
        for j in 0..3 {
            let mut t = [0.0; 3];
            match i {
                0 => {
                    t[1] = -rott[3 * j + 2];
                    t[2] = rott[3 * j + 1];
                }
                1 => {
                    t[0] = rott[3 * j + 2];
                    t[2] = -rott[3 * j];
                }
                _ => {
                    t[0] = -rott[3 * j + 1];
                    t[1] = rott[3 * j];
                }
            }
            let (t, c1) = normalize3(&t);
            if c1 < MINVAL {
                continue;
            }
            let c2 = dot3(&pos21, &t);
            let mut c3 = 0.0;
            for k in 0..3 {
                if k != i {
                    c3 += size1[k] * t[k].abs();
                }
            }
            for k in 0..3 {
                if k != j {
                    c3 += size2[k] * rotabs[3 * i + 3 - k - j] / c1;
                }
            }
            c3 -= c2.abs();
            if c3 < -margin {
                return 0;
            }
            if c3 < penetration * (1.0 - 1e-12) {
                penetration = c3;
                cle1 = 0;
                for (k, tk) in t.iter().enumerate() {
                    if k != i && ((*tk > 0.0) ^ (c2 < 0.0)) {
                        cle1 += 1 << k;
                    }
                }
                cle2 = 0;
                for k in 0..3 {
                    if k != j
                        && ((rot[3 * i + 3 - k - j] > 0.0) ^ (c2 < 0.0) ^ ((k + 3 - j) % 3 == 1))
                    {
                        cle2 += 1 << k;
                    }
                }
                code = 12 + (i * 3 + j) as i32;
                clnorm = t;
                inside = c2 < 0.0;
            }
        }
    }

    if code == -1 {
        return 0;
    }
    if code >= 12 {
        return edge_edge(
            g1,
            g2,
            margin,
            margin2,
            code - 12,
            cle1,
            cle2,
            &clnorm,
            inside,
            &rot,
            &rotabs,
            &rottabs,
            &pos21,
            con,
        );
    }

    // face of one box against the other box
    let q1 = code % 6;
    let q2 = code / 6;
    let (rotmore, ii, ff) = face_frame(q1);
    let (r, mut p, t1, s) = if q2 != 0 {
        (
            mul_mat3_t(&rotmore, &rot),
            rot_axis(&pos12, &ii, &ff),
            rot_axis(size2, &ii, &ff),
            *size1,
        )
    } else {
        (
            rot_rows(&rot, &ii, &ff),
            rot_axis(&pos21, &ii, &ff),
            rot_axis(size1, &ii, &ff),
            *size2,
        )
    };
    let rt = transpose3(&r);
    let ss = t1.map(f64::abs);
    let (lx, ly, hz) = (ss[0], ss[1], ss[2]);
    p[2] -= hz;

    let mut clcorner = 0usize;
    for i in 0..3 {
        if r[6 + i] < 0.0 {
            clcorner += 1 << i;
        }
    }
    let mut lp = p;
    for i in 0..3 {
        lp = add_scl(&lp, &rt[3 * i..], s[i] * sgn(clcorner & (1 << i) != 0));
    }

    let mut pts = [[0.0; 3]; 6];
    let mut m = 0;
    pts[m] = lp;
    m += 1;
    for i in 0..3 {
        if r[6 + i].abs() < 0.5 {
            let f = if clcorner & (1 << i) != 0 { -2.0 } else { 2.0 };
            pts[m] = scl3(&row(&rt, i), s[i] * f);
            m += 1;
        }
    }
    pts[3] = add3(&pts[0], &pts[1]);
    pts[4] = add3(&pts[0], &pts[2]);
    pts[5] = add3(&pts[3], &pts[2]);

    let mut lines_buf = [([0.0; 3], [0.0; 3]); 4];
    let mut k = 0;
    if m > 1 {
        lines_buf[k] = (pts[0], pts[1]);
        k += 1;
    }
    if m > 2 {
        lines_buf[k] = (pts[0], pts[2]);
        lines_buf[k + 1] = (pts[3], pts[2]);
        lines_buf[k + 2] = (pts[4], pts[1]);
        k += 3;
    }

    let mut points = [[0.0; 3]; MAX_BOX_CONTACTS];
    let mut n = 0;
    for (a0, dir) in &lines_buf[..k] {
        let line = [a0[0], a0[1], a0[2], dir[0], dir[1], dir[2]];
        for q in 0..2 {
            let (a, b, c, d) = (line[q], line[3 + q], line[1 - q], line[4 - q]);
            if b.abs() > MINVAL {
                for j in [-1.0, 1.0] {
                    let l = ss[q] * j;
                    let c1 = (l - a) * (1.0 / b);
                    if c1 < 0.0 || c1 > 1.0 {
                        continue;
                    }
                    let c2 = c + d * c1;
                    if c2.abs() > ss[1 - q] {
                        continue;
                    }
                    points[n] = add_scl(a0, dir, c1);
                    n += 1;
                }
            }
        }
    }

    let (a, b, c, d) = (pts[1][0], pts[2][0], pts[1][1], pts[2][1]);
    let c1 = a * d - b * c;
    if m > 2 {
        for i in 0..4 {
            let llx = if i / 2 != 0 { lx } else { -lx };
            let lly = if i % 2 != 0 { ly } else { -ly };
            let x = llx - pts[0][0];
            let y = lly - pts[0][1];
            let u = (x * d - y * b) * (1.0 / c1);
            let v = (y * a - x * c) * (1.0 / c1);
            if u <= 0.0 || v <= 0.0 || u >= 1.0 || v >= 1.0 {
                continue;
            }
            points[n] = [llx, lly, pts[0][2] + u * pts[1][2] + v * pts[2][2]];
            n += 1;
        }
    }
    for i in 0..(1usize << (m - 1)) {
        let t = pts[if i == 0 { 0 } else { i + 2 }];
        if i != 0 && (t[0] <= -lx || t[0] >= lx || t[1] <= -ly || t[1] >= ly) {
            continue;
        }
        points[n] = t;
        n += 1;
    }

    let total = n;
    n = 0;
    for i in 0..total {
        if points[i][2] > margin {
            continue;
        }
        points[n] = points[i];
        points[n][2] *= 0.5;
        n += 1;
    }

    let r = mul_mat3_t(if q2 != 0 { mat2 } else { mat1 }, &rotmore);
    let p = if q2 != 0 { *pos2 } else { *pos1 };
    let sign = if q2 != 0 { -1.0 } else { 1.0 };
    let normal = [sign * r[2], sign * r[5], sign * r[8]];
    let mut frame = [0.0; 6];
    frame[..3].copy_from_slice(&normal);
    con[0].frame = frame;
    for i in 0..n {
        let c = &mut con[i];
        c.dist = points[i][2];
        points[i][2] += hz;
        c.pos = add3(&mul_mat_vec3(&r, &points[i]), p);
        c.frame = frame;
    }
    n
}

/// Edge of box 1 against edge of box 2 (code 0..9 = 3*edge axis of box 1 + axis of box 2).
#[allow(clippy::too_many_arguments)]
fn edge_edge(
    g1: &GeomPose,
    g2: &GeomPose,
    margin: f64,
    margin2: f64,
    code: i32,
    cle1: usize,
    cle2: usize,
    clnorm: &Vec3,
    inside: bool,
    rot: &Mat3,
    rotabs: &Mat3,
    rottabs: &Mat3,
    pos21: &Vec3,
    con: &mut [ContactGeom],
) -> usize {
    let (pos1, mat1, size1, size2) = (&g1.pos, &g1.mat, &g1.size, &g2.size);
    let q1 = (code / 3) as usize;
    let q2 = (code % 3) as usize;
    let (mut ax1, mut ax2) = match q2 {
        0 => (1, 2),
        1 => (0, 2),
        _ => (1, 0),
    };
    let (mut pax1, mut pax2) = match q1 {
        0 => (1, 2),
        1 => (0, 2),
        _ => (1, 0),
    };
    if rotabs[3 * q1 + ax1] < rotabs[3 * q1 + ax2] {
        ax1 = ax2;
        ax2 = 3 - q2 - ax1;
    }
    if rottabs[3 * q2 + pax1] < rottabs[3 * q2 + pax2] {
        pax1 = pax2;
        pax2 = 3 - q1 - pax1;
    }
    let _ = pax1;
    let clface = if cle1 & (1 << pax2) != 0 {
        pax2
    } else {
        pax2 + 3
    } as i32;

    let (rotmore, ii, ff) = face_frame(clface);
    let mut p = rot_axis(pos21, &ii, &ff);
    let rnorm = rot_axis(clnorm, &ii, &ff);
    let r = rot_rows(rot, &ii, &ff);
    let s = mul_mat_t_vec3(&rotmore, size1).map(f64::abs);
    let rt = transpose3(&r);
    let (lx, ly, hz) = (s[0], s[1], s[2]);
    p[2] -= hz;

    // the two edges of box 2 nearest the face, as 4 points
    let mut points = [[0.0; 3]; MAX_BOX_CONTACTS];
    let mut depth = [0.0; MAX_BOX_CONTACTS];
    let bit = |b: usize| cle2 & (1 << b) != 0;
    for (n, s1) in [(0, sgn(bit(ax1))), (2, -sgn(bit(ax1)))] {
        let mut e = add_scl(&p, &rt[3 * ax1..], size2[ax1] * s1);
        e = add_scl(&e, &rt[3 * ax2..], size2[ax2] * sgn(bit(ax2)));
        points[n] = add_scl(&e, &rt[3 * q2..], size2[q2]);
        points[n + 1] = add_scl(&e, &rt[3 * q2..], -size2[q2]);
    }
    let axi = [
        points[0],
        sub3(&points[1], &points[0]),
        sub3(&points[2], &points[0]),
    ];

    if rnorm[2].abs() < MINVAL {
        return 0;
    }
    let innorm = (1.0 / rnorm[2]) * if inside { -1.0 } else { 1.0 };

    // project the 4 points along the normal onto the face plane
    let mut pu = [[0.0; 3]; 4];
    let mut ppts2 = [[0.0; 2]; 4];
    for i in 0..4 {
        let c1 = -points[i][2] * (1.0 / rnorm[2]);
        pu[i] = points[i];
        points[i] = add_scl(&points[i], &rnorm, c1);
        ppts2[i] = [points[i][0], points[i][1]];
    }
    let pts = [
        points[0],
        sub3(&points[1], &points[0]),
        sub3(&points[2], &points[0]),
    ];

    let lines = [
        ((pts[0], pts[1]), (axi[0], axi[1])),
        ((pts[0], pts[2]), (axi[0], axi[2])),
        (
            (add3(&pts[0], &pts[1]), pts[2]),
            (add3(&axi[0], &axi[1]), axi[2]),
        ),
        (
            (add3(&pts[0], &pts[2]), pts[1]),
            (add3(&axi[0], &axi[2]), axi[1]),
        ),
    ];

    // crossings of the projected edges with the face outline
    let mut n = 0;
    for ((l0, ld), (u0, ud)) in &lines {
        let line = [l0[0], l0[1], l0[2], ld[0], ld[1], ld[2]];
        for q in 0..2 {
            let (a, b, c, d) = (line[q], line[3 + q], line[1 - q], line[4 - q]);
            if b.abs() > MINVAL {
                for j in [-1.0, 1.0] {
                    let l = s[q] * j;
                    let c1 = (l - a) * (1.0 / b);
                    if c1 < 0.0 || c1 > 1.0 {
                        continue;
                    }
                    let c2 = c + d * c1;
                    if c2.abs() > s[1 - q] {
                        continue;
                    }
                    if (u0[2] + ud[2] * c1) * innorm > margin {
                        continue;
                    }
                    let mut pt = add_scl(&scl3(u0, 0.5), ud, 0.5 * c1);
                    pt[q] += 0.5 * l;
                    pt[1 - q] += 0.5 * c2;
                    depth[n] = pt[2] * innorm * 2.0;
                    points[n] = pt;
                    n += 1;
                }
            }
        }
    }
    let nl = n;

    // face corners inside the projected parallelogram (2.2.2 reuses c1 here)
    let (a, b, c, d) = (pts[1][0], pts[2][0], pts[1][1], pts[2][1]);
    let mut c1 = a * d - b * c;
    for i in 0..4 {
        let llx = if i / 2 != 0 { lx } else { -lx };
        let lly = if i % 2 != 0 { ly } else { -ly };
        let x = llx - pts[0][0];
        let y = lly - pts[0][1];
        let mut u = (x * d - y * b) * (1.0 / c1);
        let mut v = (y * a - x * c) * (1.0 / c1);
        let out_u = u < 0.0 || u > 1.0;
        let out_v = v < 0.0 || v > 1.0;
        if (nl == 0 && out_u && out_v) || (nl != 0 && (out_u || out_v)) {
            continue;
        }
        u = u.clamp(0.0, 1.0);
        v = v.clamp(0.0, 1.0);
        let mut t = scl3(&pu[0], 1.0 - u - v);
        t = add_scl(&t, &pu[1], u);
        t = add_scl(&t, &pu[2], v);
        let corner = [llx, lly, 0.0];
        let dif = sub3(&corner, &t);
        c1 = dot3(&dif, &dif);
        if t[2] > 0.0 && c1 > margin2 {
            continue;
        }
        points[n] = scl3(&add3(&corner, &t), 0.5);
        depth[n] = c1.sqrt() * if t[2] < 0.0 { -1.0 } else { 1.0 };
        n += 1;
    }
    let nf = n;

    // projected edge ends above the face
    for i in 0..4 {
        let (x, y) = (ppts2[i][0], ppts2[i][1]);
        let out_x = x < -lx || x > lx;
        let out_y = y < -ly || y > ly;
        if nl == 0 {
            if nf != 0 && out_x && out_y {
                continue;
            }
        } else if out_x || out_y {
            continue;
        }
        let mut c1 = 0.0;
        for j in 0..2 {
            if ppts2[i][j] < -s[j] {
                c1 += (ppts2[i][j] + s[j]) * (ppts2[i][j] + s[j]);
            } else if ppts2[i][j] > s[j] {
                c1 += (ppts2[i][j] - s[j]) * (ppts2[i][j] - s[j]);
            }
        }
        c1 += pu[i][2] * innorm * pu[i][2] * innorm;
        if pu[i][2] > 0.0 && c1 > margin2 {
            continue;
        }
        let mut t = [ppts2[i][0] * 0.5, ppts2[i][1] * 0.5, 0.0];
        for j in 0..2 {
            if ppts2[i][j] < -s[j] {
                t[j] = -s[j] * 0.5;
            } else if ppts2[i][j] > s[j] {
                t[j] = s[j] * 0.5;
            }
        }
        points[n] = add_scl(&t, &pu[i], 0.5);
        depth[n] = c1.sqrt() * if pu[i][2] < 0.0 { -1.0 } else { 1.0 };
        n += 1;
    }

    let r = mul_mat3_t(mat1, &rotmore);
    // (a product, as 2.2.2's: `misc::minus_one`)
    let normal = scl3(
        &mul_mat_vec3(&r, &rnorm),
        std::hint::black_box(if inside { -1.0 } else { 1.0 }),
    );
    let mut frame = [0.0; 6];
    frame[..3].copy_from_slice(&normal);
    con[0].frame = frame;
    for i in 0..n {
        let c = &mut con[i];
        c.dist = depth[i];
        points[i][2] += hz;
        c.pos = add3(&mul_mat_vec3(&r, &points[i]), pos1);
        c.frame = frame;
    }
    n
}
