//! The geom pairs of a body pair that may touch, found without branching on each pair: most
//! fail the masks or the bounding-sphere test, in no pattern a branch predictor learns. Used
//! when no user contact filter is to see every pair (one that a warning handler sets while a
//! body pair is being tested sees pairs from the next one); the candidates then pass the
//! face-axis tests of the two bodies' frames (`body_frame`), and collide_geoms makes the exact
//! tests.

use super::big_frame::{Large, Pair, MAX_LARGE, MAX_SMALL};
use super::body_frame::{Frames, MAX_GEOMS};
use super::spheres::{beyond, Spheres};
use super::{
    assign_margin, can_pair, clearly_beyond, collide_geoms, margin_override, narrow, Buffer, Source,
};
use crate::engine::linalg::row;
use crate::engine::{Data, EngineError, Model};
use crate::math::misc::max;
use crate::math::vec3::sub3;

/// Fewest geom pairs of a body pair worth this way (with fewer, the tests one by one are faster).
pub(super) const MIN_PAIRS: usize = 16;

/// Off: every body pair goes one geom pair at a time (the tests compare the two ways).
#[cfg(test)]
pub(super) fn enabled() -> bool {
    !super::tests::ONE_BY_ONE.with(|f| f.get())
}
#[cfg(not(test))]
#[inline(always)]
pub(super) fn enabled() -> bool {
    true
}

#[cfg(test)]
fn frame_skipped() {
    super::tests::FRAME_SKIPS.with(|n| n.set(n.get() + 1));
}
#[cfg(not(test))]
#[inline(always)]
fn frame_skipped() {}

#[cfg(test)]
fn skipped() {
    skipped_many(1);
}
#[cfg(not(test))]
#[inline(always)]
fn skipped() {}

#[cfg(test)]
fn skipped_many(k: u32) {
    super::tests::SPHERE_SKIPS.with(|n| n.set(n.get() + k as usize));
}
#[cfg(not(test))]
#[inline(always)]
fn skipped_many(_: u32) {}

/// The geom pairs of bodies b1 and b2 (built-in filter passed at the body level, no explicit
/// pair of theirs, no user contact filter) through collide_geoms, in order.
#[allow(clippy::too_many_arguments)]
pub(super) fn collide_bodies(
    m: &Model,
    d: &mut Data,
    top: usize,
    (b1, b2): (usize, usize),
    geoms1: std::ops::Range<usize>,
    geoms2: std::ops::Range<usize>,
    spheres: &mut Spheres,
    (frames, large): (&mut Option<Frames>, &mut Option<Large>),
    con: &mut Buffer,
) -> Result<(), EngineError> {
    let s2 = spheres.get(m, d, b2);
    if let (Some(s1), Some(s2)) = (spheres.get(m, d, b1), s2) {
        if beyond(m, &s1.0, s1.1, s1.2, s2) {
            skipped();
            return Ok(());
        }
    }
    let (contype, conaffinity) = (m.geom_contype(), m.geom_conaffinity());
    let masks2 = geoms2
        .clone()
        .fold((0, 0), |(t, a), g| (t | contype[g], a | conaffinity[g]));
    // (bodies of at most MAX_GEOMS geoms: one block of 64, bits from each body's first geom;
    // the candidates' masks pair, so both geoms of each may collide)
    let framed = geoms1.len() <= MAX_GEOMS && geoms2.len() <= MAX_GEOMS;
    // the bodies' frames, emptied when a pair first needs them
    let mut reset = false;
    // a body of many geoms against one of few: both in the large one's frame
    let fits = |big: &std::ops::Range<usize>, few: &std::ops::Range<usize>| {
        big.len() > MAX_GEOMS && big.len() <= MAX_LARGE && few.len() <= MAX_SMALL
    };
    let large_side = if fits(&geoms1, &geoms2) {
        1
    } else if fits(&geoms2, &geoms1) {
        2
    } else {
        0
    };
    let mut near = [u64::MAX; MAX_LARGE / 64];
    let pair = (large_side != 0).then(|| {
        let store = large.get_or_insert_with(Large::default);
        let (l, s) = if large_side == 1 {
            ((b1, geoms1.clone()), geoms2.clone())
        } else {
            ((b2, geoms2.clone()), geoms1.clone())
        };
        let lgeoms = l.1.clone();
        let pair = Pair::new(m, d, store, l, s);
        let overridden = margin_override(m);
        for (w, base) in lgeoms.clone().step_by(64).enumerate() {
            near[w] = pair.near(m, base..lgeoms.end.min(base + 64), overridden);
        }
        pair
    });
    for base1 in geoms1.clone().step_by(64) {
        // the geoms of this block of 64: a large body's near the small body's only
        let len = (geoms1.end - base1).min(64);
        let all = u64::MAX >> (64 - len);
        let mut rows = if large_side == 1 {
            near[(base1 - geoms1.start) / 64]
        } else {
            all
        };
        skipped_many((all & !rows).count_ones());
        while rows != 0 {
            let g1 = base1 + rows.trailing_zeros() as usize;
            rows &= rows - 1;
            // a geom that pairs with none of the other body's geoms, or is far from all
            if !can_pair((contype[g1], conaffinity[g1]), masks2) {
                continue;
            }
            let r1 = m.geom_rbound()[g1];
            if let Some(s2) = s2 {
                if r1 > 0.0 && beyond(m, &row(d.geom_xpos, g1), r1, m.geom_margin()[g1], s2) {
                    skipped();
                    continue;
                }
            }
            for base in geoms2.clone().step_by(64) {
                // a large body's geoms near the small body's only
                let near2 = if large_side == 2 {
                    near[(base - geoms2.start) / 64]
                } else {
                    u64::MAX
                };
                if near2 == 0 {
                    continue;
                }
                let mut bits = candidates(m, d, g1, base..geoms2.end.min(base + 64)) & near2;
                if let (Some(pair), true) = (&pair, bits != 0) {
                    bits = pairs_not_apart_large(m, pair, g1, base, large_side == 1, bits);
                }
                if bits != 0 && framed {
                    let frames = frames.get_or_insert_with(Frames::default);
                    if !reset {
                        frames.reset(d, (b1, b2), (geoms1.start, geoms2.start));
                        reset = true;
                    }
                    bits = pairs_not_apart(m, d, g1 - geoms1.start, bits, frames);
                }
                while bits != 0 {
                    let g2 = base + bits.trailing_zeros() as usize;
                    bits &= bits - 1;
                    let source = Source::Dynamic { filtered: false };
                    collide_geoms(m, d, top, g1, g2, source, con)?;
                }
            }
        }
    }
    Ok(())
}

/// The candidate bits of geom i of the first body (bits: geoms of the second from its first)
/// that the face-axis tests in the two bodies' frames leave: a pair apart in either gives no
/// contact.
fn pairs_not_apart(m: &Model, d: &Data, i: usize, bits: u64, frames: &mut Frames) -> u64 {
    let margins = m.geom_margin();
    let [f1, f2] = &mut frames.0;
    let (start1, start2) = f1.start();
    let mut kept = bits;
    let mut rest = bits;
    while rest != 0 {
        let j = rest.trailing_zeros() as usize;
        rest &= rest - 1;
        let (m1, m2) = (margins[start1 + i], margins[start2 + j]);
        // (a NaN margin, which collide_geoms may take in one order, makes no test)
        if m1.is_nan() || m2.is_nan() {
            continue;
        }
        let margin = assign_margin(m, max(m1, m2));
        if f1.apart(m, d, i, j, margin) || f2.apart(m, d, j, i, margin) {
            frame_skipped();
            kept &= !(1 << j);
        }
    }
    kept
}

/// The candidate bits of geom g1 (bits: geoms of the other body from `base`) that the tests in
/// the large body's frame leave (`g1_large`: g1 is of the large body).
fn pairs_not_apart_large(
    m: &Model,
    pair: &Pair,
    g1: usize,
    base: usize,
    g1_large: bool,
    bits: u64,
) -> u64 {
    let margins = m.geom_margin();
    let mut kept = bits;
    let mut rest = bits;
    while rest != 0 {
        let j = rest.trailing_zeros() as usize;
        rest &= rest - 1;
        let g2 = base + j;
        let (m1, m2) = (margins[g1], margins[g2]);
        // (a NaN margin, which collide_geoms may take in one order, makes no test)
        if m1.is_nan() || m2.is_nan() {
            continue;
        }
        let margin = assign_margin(m, max(m1, m2));
        let (gl, gs) = if g1_large { (g1, g2) } else { (g2, g1) };
        if pair.apart(gl, gs, margin) {
            frame_skipped();
            kept &= !(1 << j);
        }
    }
    kept
}

/// The geoms g2 of `geoms2` (at most 64) that may touch g1, as bits from its start: the masks
/// match, a collider exists and the bounding spheres are not clearly apart (collide_geoms
/// returns at once for the others, and makes the exact test).
#[inline]
fn candidates(m: &Model, d: &Data, g1: usize, geoms2: std::ops::Range<usize>) -> u64 {
    let (contype, conaffinity) = (m.geom_contype(), m.geom_conaffinity());
    let (types, rbound, margins) = (m.geom_type(), m.geom_rbound(), m.geom_margin());
    let (mask1, t1, r1) = ((contype[g1], conaffinity[g1]), types[g1], rbound[g1]);
    let (p1, margin1) = (row::<3>(d.geom_xpos, g1), margins[g1]);
    // collide_geoms takes 2.2.2's max of the margins in type order: NaN where one is NaN in
    // one of the orders, so a NaN margin on either side rules the test out
    let nan1 = margin1.is_nan();
    let overridden = margin_override(m);
    let mut bits = 0;
    for g2 in geoms2.clone() {
        let paired = can_pair(mask1, (contype[g2], conaffinity[g2]));
        let collider = narrow::has_collider(t1, types[g2]);
        // spheres_apart (symmetric in the two geoms) where the squares decide it
        let r2 = rbound[g2];
        let reach = r1 + r2 + overridden.unwrap_or(max(margin1, margins[g2]));
        let dif = sub3(&p1, &row(d.geom_xpos, g2));
        let dist2 = dif[0] * dif[0] + dif[1] * dif[1] + dif[2] * dif[2];
        let apart = (r1 > 0.0) & (r2 > 0.0) & !nan1 & clearly_beyond(dist2, reach);
        bits |= u64::from(paired & collider & !apart) << (g2 - geoms2.start);
    }
    bits
}
