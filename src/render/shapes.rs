//! The built-in unit shapes as immediate-mode GL: spheres and half spheres, disks, cones,
//! cylinders, the haze cone and boxes, in the vertex order and float arithmetic of 2.2.2.

use super::gl::consts::*;
use super::gl::Gl;
use super::util::normalize;
use std::f64::consts::PI;

/// Angle of slice `j` of `n`: computed in double, stored as float.
fn azimuth(j: i32, n: i32) -> f32 {
    (2.0f32 as f64 * PI * j as f64 / n as f32 as f64) as f32
}

/// Vertex and normal on a sphere (sign 0) or on a capsule end centered at z=sign.
fn sphere_vertex(az: f32, el: f32, sign: i32) -> ([f32; 3], [f32; 3]) {
    let v = [
        az.cos() * el.cos(),
        az.sin() * el.cos(),
        sign as f32 + el.sin(),
    ];
    (v, [v[0], v[1], v[2] - sign as f32])
}

/// A quad (or triangle) of vertices with normals, in order or reversed.
fn emit(gl: &Gl, verts: &[([f32; 3], [f32; 3])], reversed: bool) {
    let mut put = |(v, n): &([f32; 3], [f32; 3])| {
        gl.normal3fv(n);
        gl.vertex3fv(v);
    };
    if reversed {
        verts.iter().rev().for_each(&mut put);
    } else {
        verts.iter().for_each(&mut put);
    }
}

/// Half a unit sphere on top of z=+1 (sign 1) or below z=-1 (sign -1).
pub fn half_sphere(gl: &Gl, sign: i32, nslice: i32, nstack: i32) {
    let pole = [0.0, 0.0, 2.0 * sign as f32];
    let pole_n = [0.0, 0.0, sign as f32];
    gl.glBegin(GL_TRIANGLES);
    let el1 =
        (PI / 2.0f32 as f64 * sign as f64 * (nstack - 1) as f64 / nstack as f32 as f64) as f32;
    for j in 0..nslice {
        let a = sphere_vertex(azimuth(j, nslice), el1, sign);
        let b = sphere_vertex(azimuth(j + 1, nslice), el1, sign);
        emit(gl, &[a, b, (pole, pole_n)], sign < 0);
    }
    gl.glEnd();
    gl.glBegin(GL_QUADS);
    for i in 0..nstack - 1 {
        let el =
            |k: i32| (PI / 2.0f32 as f64 * sign as f64 * k as f64 / nstack as f32 as f64) as f32;
        let (el1, el2) = (el(i), el(i + 1));
        for j in 0..nslice {
            let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
            let quad = [
                sphere_vertex(az1, el1, sign),
                sphere_vertex(az2, el1, sign),
                sphere_vertex(az2, el2, sign),
                sphere_vertex(az1, el2, sign),
            ];
            emit(gl, &quad, sign < 0);
        }
    }
    gl.glEnd();
}

/// Unit sphere.
pub fn sphere(gl: &Gl, nslice: i32, nstack: i32) {
    let half = nstack / 2;
    let el = |sign: i32, k: i32| (0.5 * PI * sign as f64 * k as f64 / half as f32 as f64) as f32;
    gl.glBegin(GL_TRIANGLES);
    for sign in [-1, 1] {
        let el1 = el(sign, half - 1);
        let pole = ([0.0, 0.0, sign as f32], [0.0, 0.0, sign as f32]);
        for j in 0..nslice {
            let a = sphere_vertex(azimuth(j, nslice), el1, 0);
            let b = sphere_vertex(azimuth(j + 1, nslice), el1, 0);
            emit(gl, &[a, b, pole], sign < 0);
        }
    }
    gl.glEnd();
    gl.glBegin(GL_QUADS);
    for sign in [-1, 1] {
        for i in 0..half - 1 {
            let (el1, el2) = (el(sign, i), el(sign, i + 1));
            for j in 0..nslice {
                let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
                let quad = [
                    sphere_vertex(az1, el1, 0),
                    sphere_vertex(az2, el1, 0),
                    sphere_vertex(az2, el2, 0),
                    sphere_vertex(az1, el2, 0),
                ];
                emit(gl, &quad, sign < 0);
            }
        }
    }
    gl.glEnd();
}

fn disk_vertex(az: f32, r: f32, sign: i32) -> [f32; 3] {
    [az.cos() * r, az.sin() * r, sign as f32]
}

/// Disk at z=sign facing up (1) or down (-1); sign 0: at z=0 facing down.
pub fn disk(gl: &Gl, sign: i32, nslice: i32, nstack: i32) {
    let normal = [0.0, 0.0, if sign == 0 { -1.0 } else { sign as f32 }];
    let put = |vs: &[[f32; 3]]| {
        if sign > 0 {
            vs.iter().for_each(|v| gl.vertex3fv(v));
        } else {
            vs.iter().rev().for_each(|v| gl.vertex3fv(v));
        }
    };
    gl.glBegin(GL_TRIANGLES);
    gl.normal3fv(&normal);
    let r1 = 1.0f32 / nstack as f32;
    for j in 0..nslice {
        let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
        put(&[
            disk_vertex(az1, r1, sign),
            disk_vertex(az2, r1, sign),
            [0.0, 0.0, sign as f32],
        ]);
    }
    gl.glEnd();
    gl.glBegin(GL_QUADS);
    gl.normal3fv(&normal);
    for i in 0..nstack - 1 {
        let r1 = (i + 1) as f32 / nstack as f32;
        let r2 = (i + 2) as f32 / nstack as f32;
        for j in 0..nslice {
            let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
            put(&[
                disk_vertex(az1, r2, sign),
                disk_vertex(az2, r2, sign),
                disk_vertex(az2, r1, sign),
                disk_vertex(az1, r1, sign),
            ]);
        }
    }
    gl.glEnd();
}

fn cone_vertex(az: f32, r: f32) -> ([f32; 3], [f32; 3]) {
    let scale = 1.0f32 / 2.0f32.sqrt();
    (
        [az.cos() * r, az.sin() * r, 1.0 - r],
        [az.cos() * scale, az.sin() * scale, scale],
    )
}

/// Open cone from the unit circle at z=0 to the apex at z=1.
pub fn cone(gl: &Gl, nslice: i32, nstack: i32) {
    gl.glBegin(GL_TRIANGLES);
    let r1 = 1.0f32 / nstack as f32;
    for j in 0..nslice {
        let a = cone_vertex(azimuth(j, nslice), r1);
        let b = cone_vertex(azimuth(j + 1, nslice), r1);
        let mut n = [a.1[0] + b.1[0], a.1[1] + b.1[1], a.1[2] + b.1[2]];
        normalize(&mut n);
        emit(gl, &[a, b, ([0.0, 0.0, 1.0], n)], false);
    }
    gl.glEnd();
    gl.glBegin(GL_QUADS);
    for i in 0..nstack - 1 {
        let r1 = (i + 1) as f32 / nstack as f32;
        let r2 = (i + 2) as f32 / nstack as f32;
        for j in 0..nslice {
            let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
            let quad = [
                cone_vertex(az1, r2),
                cone_vertex(az2, r2),
                cone_vertex(az2, r1),
                cone_vertex(az1, r1),
            ];
            emit(gl, &quad, false);
        }
    }
    gl.glEnd();
}

fn cylinder_vertex(az: f32, h: f32) -> ([f32; 3], [f32; 3]) {
    let v = [az.cos(), az.sin(), h];
    let len = (v[0] * v[0] + v[1] * v[1]).sqrt();
    (v, [v[0] / len, v[1] / len, 0.0])
}

/// Open cylinder of radius 1 from z=-1 to z=1.
pub fn cylinder(gl: &Gl, nslice: i32, nstack: i32) {
    gl.glBegin(GL_QUADS);
    for i in 0..nstack {
        let h1 = (2 * i) as f32 / nstack as f32 - 1.0;
        let h2 = (2 * (i + 1)) as f32 / nstack as f32 - 1.0;
        for j in 0..nslice {
            let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
            let quad = [
                cylinder_vertex(az1, h1),
                cylinder_vertex(az2, h1),
                cylinder_vertex(az2, h2),
                cylinder_vertex(az1, h2),
            ];
            emit(gl, &quad, false);
        }
    }
    gl.glEnd();
}

/// Truncated cone of the horizon haze, opaque at its middle ring, clear at both ends.
pub fn haze(gl: &Gl, nslice: i32, r: f32, rgba: &[f32; 4]) {
    let alpha = 1.0f32.atan2(r);
    let beta = (0.75 * PI) as f32 - alpha;
    let h = 0.5f32.sqrt() * r * alpha.sin() / beta.sin();
    let vertex = |az: f32, h: f32| {
        [
            az.cos() * (1.0 - r * (1.0 - h)),
            az.sin() * (1.0 - r * (1.0 - h)),
            h,
        ]
    };
    gl.glBegin(GL_QUADS);
    gl.glNormal3f(0.0, 0.0, 1.0);
    for i in 0..2 {
        let (h1, h2) = if i == 0 { (0.0, h) } else { (h, 1.0) };
        let (c1, c2) = (
            if i == 1 { 1.0 } else { 0.0 },
            if i == 0 { 1.0 } else { 0.0 },
        );
        for j in 0..nslice {
            let (az1, az2) = (azimuth(j, nslice), azimuth(j + 1, nslice));
            gl.glColor4f(rgba[0], rgba[1], rgba[2], c1);
            gl.vertex3fv(&vertex(az1, h1));
            gl.vertex3fv(&vertex(az2, h1));
            gl.glColor4f(rgba[0], rgba[1], rgba[2], c2);
            gl.vertex3fv(&vertex(az2, h2));
            gl.vertex3fv(&vertex(az1, h2));
        }
    }
    gl.glEnd();
}

/// The unit box [-1,1]^3, each face divided into `n` x `n` quads.
pub fn cube(gl: &Gl, n: i32) {
    let d = 2.0f32 / n as f32;
    let at = |k: i32| d * k as f32 - 1.0;
    gl.glBegin(GL_QUADS);
    for x in 0..n {
        for y in 0..n {
            let (x0, x1, y0, y1) = (at(x), at(x + 1), at(y), at(y + 1));
            let faces: [([f32; 3], [[f32; 3]; 4]); 6] = [
                (
                    [0.0, 0.0, 1.0],
                    [[x0, y0, 1.0], [x1, y0, 1.0], [x1, y1, 1.0], [x0, y1, 1.0]],
                ),
                (
                    [0.0, 0.0, -1.0],
                    [
                        [x0, y1, -1.0],
                        [x1, y1, -1.0],
                        [x1, y0, -1.0],
                        [x0, y0, -1.0],
                    ],
                ),
                (
                    [1.0, 0.0, 0.0],
                    [[1.0, x0, y0], [1.0, x1, y0], [1.0, x1, y1], [1.0, x0, y1]],
                ),
                (
                    [-1.0, 0.0, 0.0],
                    [
                        [-1.0, x0, y1],
                        [-1.0, x1, y1],
                        [-1.0, x1, y0],
                        [-1.0, x0, y0],
                    ],
                ),
                (
                    [0.0, -1.0, 0.0],
                    [
                        [x0, -1.0, y0],
                        [x1, -1.0, y0],
                        [x1, -1.0, y1],
                        [x0, -1.0, y1],
                    ],
                ),
                (
                    [0.0, 1.0, 0.0],
                    [[x0, 1.0, y1], [x1, 1.0, y1], [x1, 1.0, y0], [x0, 1.0, y0]],
                ),
            ];
            for (normal, quad) in &faces {
                gl.glNormal3f(normal[0], normal[1], normal[2]);
                quad.iter().for_each(|v| gl.glVertex3f(v[0], v[1], v[2]));
            }
        }
    }
    gl.glEnd();
}
