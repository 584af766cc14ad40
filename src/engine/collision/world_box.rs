//! Boxes along the world axes around all of a body's geoms: each geom's box (`box_of`) taken by
//! its half-widths along the world axes and grown by the slack of its tests (`slack`), as
//! `big_frame` takes them along a body's axes. Two bodies whose boxes are apart along a world
//! axis by more than the largest margin of their geoms have every geom pair apart along it by
//! `axis_apart` (the distance of two geoms' centres there is at least the gap): no pair of
//! theirs gives a contact. The sweep lists body pairs by bounding spheres; this drops most of
//! those that only these meet.

use super::body_frame::{box_of, slack};
use crate::engine::linalg::row_ref;
use crate::engine::{Data, Model};
use crate::math::misc::max;
use crate::math::Vec3;

/// Off: no body pair is dropped by its boxes (the tests compare the two ways).
#[cfg(test)]
pub(super) fn enabled() -> bool {
    !super::tests::NO_WORLD_BOXES.with(|f| f.get())
}
#[cfg(not(test))]
#[inline(always)]
pub(super) fn enabled() -> bool {
    true
}

#[cfg(test)]
pub(super) fn skipped() {
    super::tests::WORLD_BOX_SKIPS.with(|n| n.set(n.get() + 1));
}
#[cfg(not(test))]
#[inline(always)]
pub(super) fn skipped() {}

/// Bodies with an id below this have a box (more would take more stack than they save).
pub(super) const MAX_BODIES: usize = 64;

/// A body's box: lower and upper bounds, and the largest margin of its geoms.
#[derive(Clone, Copy)]
pub(super) struct BodyBox {
    lo: Vec3,
    hi: Vec3,
    margin: f64,
}

/// Bodies a chunk of boxes holds (a chunk is set up when one of its bodies first needs it).
const CHUNK: usize = 8;

const NO_BOX: BodyBox = BodyBox {
    lo: [0.0; 3],
    hi: [0.0; 3],
    margin: 0.0,
};

/// The boxes of the bodies below MAX_BODIES, each found when first asked for in a collision
/// pass.
pub(super) struct WorldBoxes {
    known: u64,
    boxed: u64,
    chunks: [Option<[BodyBox; CHUNK]>; MAX_BODIES / CHUNK],
}

impl Default for WorldBoxes {
    fn default() -> Self {
        WorldBoxes {
            known: 0,
            boxed: 0,
            chunks: [None; MAX_BODIES / CHUNK],
        }
    }
}

impl WorldBoxes {
    /// Body b's box; None for bodies from MAX_BODIES on and where a geom has no box or a
    /// value is not finite.
    pub(super) fn get(&mut self, m: &Model, d: &Data, b: usize) -> Option<BodyBox> {
        if b >= MAX_BODIES {
            return None;
        }
        let bit = 1u64 << b;
        let chunk = &mut self.chunks[b / CHUNK];
        if self.known & bit == 0 {
            self.known |= bit;
            if let Some(found) = body_box(m, d, b) {
                chunk.get_or_insert([NO_BOX; CHUNK])[b % CHUNK] = found;
                self.boxed |= bit;
            }
        }
        if self.boxed & bit == 0 {
            return None;
        }
        chunk.as_ref().map(|c| c[b % CHUNK])
    }
}

fn body_box(m: &Model, d: &Data, b: usize) -> Option<BodyBox> {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let mut margin = f64::NEG_INFINITY;
    let mut finite = true;
    for g in m.body_geoms(b) {
        let h = box_of(m, g)?;
        let (c, mat) = (row_ref::<3>(d.geom_xpos, g), row_ref::<9>(d.geom_xmat, g));
        let s = slack(h[0] + h[1] + h[2], c);
        for k in 0..3 {
            let w =
                h[0] * mat[3 * k].abs() + h[1] * mat[3 * k + 1].abs() + h[2] * mat[3 * k + 2].abs();
            let (l, u) = (c[k] - w - s, c[k] + w + s);
            finite &= l.is_finite() & u.is_finite();
            lo[k] = lo[k].min(l);
            hi[k] = hi[k].max(u);
        }
        let gm = m.geom_margin()[g];
        finite &= gm.is_finite();
        margin = margin.max(gm);
    }
    (finite && margin.is_finite()).then_some(BodyBox { lo, hi, margin })
}

/// Are the two bodies' boxes apart along a world axis by more than the margin (the override,
/// else the larger of the two bodies' largest) and 1e-7 / the gap?
pub(super) fn apart(a: &BodyBox, b: &BodyBox, overridden: Option<f64>) -> bool {
    let margin = overridden.unwrap_or(max(a.margin, b.margin));
    (0..3).fold(false, |any, k| {
        let gap = max(b.lo[k] - a.hi[k], a.lo[k] - b.hi[k]);
        let excess = gap - margin;
        any | ((excess > 0.0) & (excess * gap > 1e-7))
    })
}
