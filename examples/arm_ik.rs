//! The three-link arm of `models/arm3.xml` through the Rust API: forward kinematics from the
//! site pose, damped-least-squares inverse kinematics through the site Jacobian, and (with
//! `--track`) PD tracking of a circling target through the arm's motors under `step`.
//!
//! ```sh
//! cargo run --release --example arm_ik                    # prints what examples/arm_ik.c prints
//! cargo run --release --example arm_ik -- --track         # prints what examples/arm_track.c prints
//! cargo run --release --example arm_ik -- [--track] path/to/arm.xml
//! ```

use mujoco::{Data, Error, Model, ObjKind};
use std::io::Write;

/// Solves the symmetric positive definite 3x3 system `a x = b` by Cholesky.
fn solve3(a: &[[f64; 3]; 3], b: &[f64; 3]) -> [f64; 3] {
    let mut l = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..=i {
            let mut s = a[i][j];
            for (x, y) in l[i][..j].iter().zip(&l[j][..j]) {
                s -= x * y;
            }
            l[i][j] = if i == j { s.sqrt() } else { s / l[j][j] };
        }
    }
    let mut y = [0.0; 3];
    for i in 0..3 {
        y[i] = b[i];
        for k in 0..i {
            y[i] -= l[i][k] * y[k];
        }
        y[i] /= l[i][i];
    }
    let mut x = [0.0; 3];
    for i in (0..3).rev() {
        x[i] = y[i];
        for k in i + 1..3 {
            x[i] -= l[k][i] * x[k];
        }
        x[i] /= l[i][i];
    }
    x
}

/// `iters` DLS steps on `data`'s qpos moving site `site` towards `target`:
/// dq = J^T (J J^T + lambda^2 I)^-1 e; returns the final error norm.
fn ik_solve(
    data: &mut Data,
    site: usize,
    target: &[f64; 3],
    lambda: f64,
    iters: usize,
) -> Result<f64, Error> {
    let nv = data.model().nv();
    let mut err = 0.0;
    for it in 0..=iters {
        data.forward()?;
        let p = data.site_pose(site)?.translation.vector;
        let e = [target[0] - p.x, target[1] - p.y, target[2] - p.z];
        err = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
        if it == iters {
            break;
        }
        let jac = data.jac_site(site)?.translation;
        let mut a = [[0.0; 3]; 3];
        for (i, row) in a.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                let mut s = 0.0;
                for k in 0..nv {
                    s += jac[(i, k)] * jac[(j, k)];
                }
                *v = s + if i == j { lambda * lambda } else { 0.0 };
            }
        }
        let w = solve3(&a, &e);
        let dq: Vec<f64> = (0..nv)
            .map(|k| jac[(0, k)] * w[0] + jac[(1, k)] * w[1] + jac[(2, k)] * w[2])
            .collect();
        data.integrate_qpos(&dq, 1.0)?;
    }
    Ok(err)
}

/// IK of the site "ee" onto the mocap body "target" (examples/arm_ik.c); exit status.
fn reach(model: &Model, out: &mut dyn Write) -> Result<i32, Error> {
    let mut data = model.make_data()?;
    let ee = model.require_id(ObjKind::Site, "ee")?;
    let body = model.require_id(ObjKind::Body, "target")?;
    let t = &model.arrays().body_pos()[3 * body..3 * body + 3];
    let target = [t[0], t[1], t[2]];
    let _ = writeln!(out, "target {:.6} {:.6} {:.6}", t[0], t[1], t[2]);
    // start from a bent configuration; one DLS step at a time to print the error
    data.qpos_mut().copy_from_slice(&[0.3, 0.8, -0.5]);
    let mut err = 0.0;
    for it in 0..30 {
        err = ik_solve(&mut data, ee, &target, 0.05, 1)?;
        if it < 6 || it % 10 == 9 {
            let _ = writeln!(out, "iteration {:2}  error {:.9}", it + 1, err);
        }
    }
    data.forward()?;
    let q = data.qpos();
    let _ = writeln!(out, "qpos {:.6} {:.6} {:.6}", q[0], q[1], q[2]);
    let p = data.site("ee")?.position();
    let _ = writeln!(out, "ee   {:.6} {:.6} {:.6}", p.x, p.y, p.z);
    let reached = err < 1e-4;
    let _ = writeln!(out, "{}", if reached { "reached" } else { "not reached" });
    Ok(if reached { 0 } else { 2 })
}

/// IK plus PD tracking of a circling target through the motors (examples/arm_track.c).
fn track(model: &Model, out: &mut dyn Write) -> Result<i32, Error> {
    let mut data = model.make_data()?;
    let mut ik = model.make_data()?;
    let ee = model.require_id(ObjKind::Site, "ee")?;
    if model.id(ObjKind::Key, "home").is_some() {
        data.reset_keyframe_named("home")?;
    }
    let arrays = model.arrays();
    let (kp, kd) = (20.0, 3.0);
    let mut worst: f64 = 0.0;
    let _ = writeln!(
        out,
        "  time    target x  target y   ee x      ee y     error"
    );
    for step in 1..=2500 {
        let t = data.time();
        let target = [0.45 + 0.15 * t.cos(), 0.15 + 0.15 * t.sin(), 0.05];
        // desired angles: IK from the current configuration
        ik.qpos_mut().copy_from_slice(data.qpos());
        ik_solve(&mut ik, ee, &target, 0.05, 3)?;
        for i in 0..model.nu() {
            let j = arrays.actuator_trnid()[2 * i] as usize;
            let (qa, va) = (
                arrays.jnt_qposadr()[j] as usize,
                arrays.jnt_dofadr()[j] as usize,
            );
            let u = kp * (ik.qpos()[qa] - data.qpos()[qa]) - kd * data.qvel()[va];
            let (lo, hi) = (
                arrays.actuator_ctrlrange()[2 * i],
                arrays.actuator_ctrlrange()[2 * i + 1],
            );
            data.ctrl_mut()[i] = if u < lo {
                lo
            } else if u > hi {
                hi
            } else {
                u
            };
        }
        data.step()?;
        let p = data.site_position(ee)?;
        let (dx, dy) = (p.x - target[0], p.y - target[1]);
        let err = (dx * dx + dy * dy).sqrt();
        if step > 1000 && err > worst {
            worst = err;
        }
        if step % 250 == 0 {
            let _ = writeln!(
                out,
                "{:6.3}  {:9.6} {:9.6} {:9.6} {:9.6}  {:.6}",
                data.time(),
                target[0],
                target[1],
                p.x,
                p.y,
                err
            );
        }
    }
    let _ = writeln!(out, "worst tracking error after 2 s: {worst:.6}");
    Ok(if worst < 0.05 { 0 } else { 2 })
}

/// Runs the example on `args` (without the program name); the exit status.
pub fn run(args: &[String], out: &mut dyn Write) -> i32 {
    let tracking = args.iter().any(|a| a == "--track");
    let path = args
        .iter()
        .find(|a| *a != "--track")
        .map_or("models/arm3.xml", String::as_str);
    let model = match Model::from_xml(path) {
        Ok(m) => m,
        Err(Error::Load(msg)) => {
            let _ = writeln!(out, "cannot load {path}: {msg}");
            return 1;
        }
        Err(e) => {
            let _ = writeln!(out, "cannot load {path}: {e}");
            return 1;
        }
    };
    let result = if tracking {
        track(&model, out)
    } else {
        reach(&model, out)
    };
    result.unwrap_or_else(|e| {
        let _ = writeln!(out, "{e}");
        3
    })
}

#[allow(dead_code)]
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let status = run(&args, &mut std::io::stdout().lock());
    std::process::exit(status);
}
