//! `fusestatic`: bodies without joints merge into their parents (mass, inertia, geoms, sites,
//! children), as 2.2.2 does it after compiling the tree, ids renumbered depth-first.

use super::{FBody, FGeom, FJoint, FSite};
use crate::compiler::frame::{global_inertia, mat_vec, mulquat_unit, offcenter, quat2mat};
use crate::compiler::objects::{alt_set, Settings};
use crate::compiler::spec::Alt;
use crate::compiler::CError;

const MINVAL: f64 = 1e-15;

/// The frame (pos, quat), given in the frame `by`, expressed in by's parent frame.
fn change_frame(pos: &mut [f64; 3], quat: &mut [f64; 4], by_pos: &[f64; 3], by_quat: &[f64; 4]) {
    let add = mat_vec(&quat2mat(by_quat), pos);
    *pos = std::array::from_fn(|k| by_pos[k] + add[k]);
    *quat = mulquat_unit(by_quat, quat);
}

/// Adds body `b`'s mass and inertia to its parent `p`.
fn merge_inertia(bodies: &mut [FBody], b: usize, p: usize, s: &Settings) -> Result<(), CError> {
    let (bpos, bquat) = (bodies[b].pos, bodies[b].quat);
    let child = &mut bodies[b];
    change_frame(&mut child.ipos, &mut child.iquat, &bpos, &bquat);
    let mass = [bodies[p].mass, bodies[b].mass];
    let inertia = [bodies[p].inertia, bodies[b].inertia];
    let ipos = [bodies[p].ipos, bodies[b].ipos];
    let iquat = [bodies[p].iquat, bodies[b].iquat];
    let par = &mut bodies[p];
    par.mass = 0.0;
    par.ipos = [0.0; 3];
    for (m, p) in mass.iter().zip(&ipos) {
        par.mass += m;
        for (c, x) in par.ipos.iter_mut().zip(p) {
            *c += m * x;
        }
    }
    if par.mass < MINVAL {
        par.mass = 0.0;
        par.inertia = [0.0; 3];
        par.ipos = [0.0; 3];
        par.iquat = [1.0, 0.0, 0.0, 0.0];
        return Ok(());
    }
    for k in 0..3 {
        par.ipos[k] /= par.mass;
    }
    let mut total = [0.0; 6];
    for j in 0..2 {
        let d = std::array::from_fn(|k| ipos[j][k] - par.ipos[k]);
        let a = global_inertia(&inertia[j], &iquat[j]);
        let o = offcenter(mass[j], &d);
        for k in 0..6 {
            total[k] += a[k] + o[k];
        }
    }
    let alt = Alt {
        fullinertia: total,
        ..Alt::default()
    };
    alt_set(&alt, &mut par.iquat, Some(&mut par.inertia), s)
        .map_err(|e| CError::msg(&format!("error '{e}' in fusing static body inertias")))
}

/// Fuses static bodies; the caller has checked that nothing refers to body, geom or site ids.
pub(super) fn fuse_static(
    bodies: &mut Vec<FBody>,
    joints: &mut Vec<FJoint>,
    geoms: &mut Vec<FGeom>,
    sites: &mut Vec<FSite>,
    s: &Settings,
) -> Result<(), CError> {
    let mut i = 1;
    while i < bodies.len() {
        let b = i;
        if !bodies[b].joints.is_empty() || bodies[b].spec.mocap {
            i += 1;
            continue;
        }
        let p = bodies[b].parent;
        if p > 0 && bodies[b].mass >= MINVAL {
            merge_inertia(bodies, b, p, s)?;
        }
        let (bpos, bquat) = (bodies[b].pos, bodies[b].quat);
        let children = std::mem::take(&mut bodies[b].children);
        for &c in &children {
            let child = &mut bodies[c];
            change_frame(&mut child.pos, &mut child.quat, &bpos, &bquat);
            child.parent = p;
        }
        let at = bodies[p].children.iter().position(|&c| c == b).unwrap_or(0);
        bodies[p].children.splice(at..at + 1, children);
        for g in std::mem::take(&mut bodies[b].geoms) {
            let o = &mut geoms[g].out;
            change_frame(&mut o.pos, &mut o.quat, &bpos, &bquat);
            bodies[p].geoms.push(g);
        }
        for t in std::mem::take(&mut bodies[b].sites) {
            let o = &mut sites[t].out;
            change_frame(&mut o.pos, &mut o.quat, &bpos, &bquat);
            bodies[p].sites.push(t);
        }
        bodies.remove(b);
        let renum = |x: &mut usize| {
            if *x > b {
                *x -= 1;
            }
        };
        for body in bodies.iter_mut() {
            renum(&mut body.parent);
            body.children.iter_mut().for_each(renum);
        }
        // the next body now has index b: look at it in the next round
        reindex(bodies, joints, geoms, sites);
    }
    Ok(())
}

/// Depth-first ids of joints, geoms and sites, parents and weld ids, as after a fuse.
fn reindex(
    bodies: &mut [FBody],
    joints: &mut Vec<FJoint>,
    geoms: &mut Vec<FGeom>,
    sites: &mut Vec<FSite>,
) {
    let (mut jorder, mut gorder, mut sorder) = (Vec::new(), Vec::new(), Vec::new());
    let mut stack = vec![0usize];
    while let Some(b) = stack.pop() {
        for c in bodies[b].children.clone() {
            bodies[c].parent = b;
            bodies[c].weldid = if bodies[c].joints.is_empty() {
                bodies[b].weldid
            } else {
                c
            };
        }
        for (list, order) in [
            (&mut bodies[b].joints, &mut jorder),
            (&mut bodies[b].geoms, &mut gorder),
            (&mut bodies[b].sites, &mut sorder),
        ] {
            for x in list.iter_mut() {
                order.push(*x);
                *x = order.len() - 1;
            }
        }
        stack.extend(bodies[b].children.iter().rev());
    }
    permute(joints, &jorder);
    permute(geoms, &gorder);
    permute(sites, &sorder);
    for (id, body) in bodies.iter().enumerate() {
        for &j in &body.joints {
            joints[j].body = id;
        }
        for &g in &body.geoms {
            geoms[g].body = id;
        }
        for &t in &body.sites {
            sites[t].body = id;
        }
    }
}

/// Reorders `v` so that new element k is old element `order[k]`.
fn permute<T>(v: &mut Vec<T>, order: &[usize]) {
    let mut old: Vec<Option<T>> = std::mem::take(v).into_iter().map(Some).collect();
    v.extend(order.iter().filter_map(|&k| old[k].take()));
}
