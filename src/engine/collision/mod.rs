//! Collision detection, up to the narrow phase: candidate geom pairs are filtered exactly as
//! 2.2.2 does (contype/conaffinity, weld and parent exclusion, excludes, explicit pairs,
//! bounding spheres with margin). Any pair that survives would need a narrow-phase routine,
//! which this slice does not have yet: that is reported as not implemented.

use crate::engine::linalg::{max, row};

pub mod boxes;
pub mod convex;
pub mod mpr;
pub mod primitive;
#[cfg(test)]
mod tests;
use crate::abi::*;
use crate::engine::{disabled, enabled, Data, EngineError, Model};
use crate::math::*;

const TYPE_NAMES: [&str; 8] = [
    "plane",
    "hfield",
    "sphere",
    "capsule",
    "ellipsoid",
    "cylinder",
    "box",
    "mesh",
];

/// Does 2.2.2 have a collision routine for these (ordered) geom types?
fn has_collider(t1: i32, t2: i32) -> bool {
    // plane and hfield never collide with each other or themselves
    !(t1 <= 1 && t2 <= 1)
}

fn assign_margin(m: &Model, margin: f64) -> f64 {
    if enabled(m, mjtEnableBit_::mjENBL_OVERRIDE) {
        m.raw.opt.o_margin
    } else {
        margin
    }
}

fn plane_dist(d: &Data, plane: usize, g: usize) -> f64 {
    let mat = row::<9>(d.geom_xmat, plane);
    let dif = sub3(&row(d.geom_xpos, g), &row(d.geom_xpos, plane));
    dot3(&dif, &[mat[2], mat[5], mat[8]])
}

/// Runs the filters of mj_collideGeoms; Err when the pair reaches the narrow phase.
fn test_pair(
    m: &Model,
    d: &Data,
    g1: usize,
    g2: usize,
    pair: Option<usize>,
) -> Result<(), EngineError> {
    let (g1, g2) = if m.geom_type()[g1] > m.geom_type()[g2] {
        (g2, g1)
    } else {
        (g1, g2)
    };
    let (t1, t2) = (m.geom_type()[g1], m.geom_type()[g2]);
    if !has_collider(t1, t2) {
        return Ok(());
    }
    let margin = match pair {
        None => {
            let weld1 = m.body_weldid()[m.geom_bodyid()[g1] as usize];
            let weld2 = m.body_weldid()[m.geom_bodyid()[g2] as usize];
            let wparent1 = m.body_weldid()[m.body_parentid()[weld1 as usize] as usize];
            let wparent2 = m.body_weldid()[m.body_parentid()[weld2 as usize] as usize];
            let filterparent =
                !disabled(m, mjtDisableBit_::mjDSBL_FILTERPARENT) && weld1 != 0 && weld2 != 0;
            let (ct1, ca1) = (m.geom_contype()[g1], m.geom_conaffinity()[g1]);
            let (ct2, ca2) = (m.geom_contype()[g2], m.geom_conaffinity()[g2]);
            if (ct1 & ca2) == 0 && (ct2 & ca1) == 0 {
                return Ok(());
            }
            if weld1 == weld2 {
                return Ok(());
            }
            if filterparent && (weld1 == wparent2 || weld2 == wparent1) {
                return Ok(());
            }
            max(m.geom_margin()[g1], m.geom_margin()[g2])
        }
        Some(p) => m.pair_margin()[p],
    };
    let margin = assign_margin(m, margin);
    let (r1, r2) = (m.geom_rbound()[g1], m.geom_rbound()[g2]);
    if r1 > 0.0
        && r2 > 0.0
        && dist3(&row(d.geom_xpos, g1), &row(d.geom_xpos, g2)) > r1 + r2 + margin
    {
        return Ok(());
    }
    let plane = mjtGeom_::mjGEOM_PLANE as i32;
    if t1 == plane && r2 > 0.0 && plane_dist(d, g1, g2) > margin + r2 {
        return Ok(());
    }
    if t2 == plane && r1 > 0.0 && plane_dist(d, g2, g1) > margin + r1 {
        return Ok(());
    }
    let name = |t: i32| TYPE_NAMES.get(t as usize).copied().unwrap_or("unknown");
    Err(EngineError(format!(
        "collision between {} and {} geoms is not implemented",
        name(t1),
        name(t2)
    )))
}

fn can_collide(m: &Model, g: usize) -> bool {
    m.geom_contype()[g] != 0 || m.geom_conaffinity()[g] != 0
}

/// mj_collision: ncon = 0, or an error when a contact could occur.
pub fn collision(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    d.raw.ncon = 0;
    let nbody = m.raw.nbody as usize;
    if disabled(m, mjtDisableBit_::mjDSBL_CONSTRAINT)
        || disabled(m, mjtDisableBit_::mjDSBL_CONTACT)
        || m.raw.nconmax == 0
        || nbody < 2
    {
        return Ok(());
    }
    let mode = m.raw.opt.collision;
    let dynamic_only = mode == mjtCollision_::mjCOL_DYNAMIC as i32;
    let pair_only = mode == mjtCollision_::mjCOL_PAIR as i32;
    if !dynamic_only {
        for p in 0..m.raw.npair as usize {
            test_pair(
                m,
                d,
                m.pair_geom1()[p] as usize,
                m.pair_geom2()[p] as usize,
                Some(p),
            )?;
        }
    }
    if pair_only {
        return Ok(());
    }
    let ngeom = m.raw.ngeom as usize;
    for g1 in 0..ngeom {
        if !can_collide(m, g1) {
            continue;
        }
        for g2 in g1 + 1..ngeom {
            if !can_collide(m, g2) {
                continue;
            }
            let (b1, b2) = (m.geom_bodyid()[g1], m.geom_bodyid()[g2]);
            if b1 == b2 {
                continue;
            }
            let (lo, hi) = if b1 < b2 { (b1, b2) } else { (b2, b1) };
            let signature = ((lo + 1) << 16) + (hi + 1);
            if m.exclude_signature().contains(&signature) {
                continue;
            }
            let merged = !dynamic_only
                && (0..m.raw.npair as usize).any(|p| {
                    m.pair_signature()[p] == signature
                        && ((m.pair_geom1()[p] as usize == g1 && m.pair_geom2()[p] as usize == g2)
                            || (m.pair_geom1()[p] as usize == g2
                                && m.pair_geom2()[p] as usize == g1))
                });
            if merged {
                continue;
            }
            test_pair(m, d, g1, g2, None)?;
        }
    }
    Ok(())
}
