//! Broad phase (mj_broadphase): candidate body pairs. Bodies that carry geoms of the world, or
//! planes and height fields welded to it, pair with every body; the others are swept and pruned
//! along the principal axes of the geom centres. Pairs come out sorted by signature
//! (`(b1 << 16) + b2`, b1 < b2), duplicates included, as in 2.2.2.

use crate::abi::mjtGeom_;
use crate::abi::view::Arena;
use crate::engine::hooks;
use crate::engine::linalg::row;
use crate::engine::{Data, EngineError, Model};
use crate::math::eig3::eig3;
use crate::math::misc::{max, min};
use crate::math::vec3::{dot3, sub3};
use crate::math::Mat3;

use super::spheres::{body_sphere, spheres_beyond};
use super::{can_pair, dynamic_pair_apart, margin_override, welds_filtered_by};
use crate::abi::mjtDisableBit_;
use crate::engine::disabled;

/// Does the body have a geom with contype or conaffinity?
pub fn can_collide(m: &Model, b: usize) -> bool {
    body_masks(m, b) != (0, 0)
}

/// The contype and conaffinity masks of all of a body's geoms together.
fn body_masks(m: &Model, b: usize) -> (i32, i32) {
    m.body_geoms(b).fold((0, 0), |(t, a), g| {
        (t | m.geom_contype()[g], a | m.geom_conaffinity()[g])
    })
}

fn has_plane_or_hfield(m: &Model, b: usize) -> bool {
    m.body_geoms(b).any(|g| {
        let t = m.geom_type()[g];
        t == mjtGeom_::mjGEOM_PLANE as i32 || t == mjtGeom_::mjGEOM_HFIELD as i32
    })
}

/// A body's (contype, conaffinity) in one slot, contype in the upper 32 bits.
fn pack_masks((t, a): (i32, i32)) -> u64 {
    (u64::from(t as u32) << 32) | u64::from(a as u32)
}

fn unpack_masks(k: u64) -> (i32, i32) {
    ((k >> 32) as u32 as i32, k as u32 as i32)
}

/// Marks the upper end of a body's box in the sweep's records (the body below it).
const UPPER: u64 = 0x10000;

/// The pair list under construction (capacity nbody*(nbody-1)/2, as 2.2.2's buffer).
struct Pairs<'a> {
    pair: &'a mut [i32],
    n: usize,
}

impl Pairs<'_> {
    /// Adds a body pair; with `filter`, single-geom bodies must pass contype/conaffinity.
    fn add(&mut self, m: &Model, filter: bool, b1: usize, b2: usize) -> Result<(), EngineError> {
        if self.n >= self.pair.len() {
            return Err(EngineError("Broadphase buffer full".into()));
        }
        if filter && m.body_geomnum()[b1] == 1 && m.body_geomnum()[b2] == 1 {
            let (g1, g2) = (m.body_geomadr()[b1] as usize, m.body_geomadr()[b2] as usize);
            if m.geom_contype()[g1] & m.geom_conaffinity()[g2] == 0
                && m.geom_contype()[g2] & m.geom_conaffinity()[g1] == 0
            {
                return Ok(());
            }
        }
        let (lo, hi) = if b1 < b2 { (b1, b2) } else { (b2, b1) };
        self.pair[self.n] = ((lo << 16) + hi) as i32;
        self.n += 1;
        Ok(())
    }
}

/// Stable top-down merge sort of `items` by `less_eq` (glibc's qsort_r, which 2.2.2 calls, is
/// this merge sort: ties and even inconsistent comparisons come out the same).
pub fn merge_sort<T: Copy>(items: &mut [T], tmp: &mut [T], le: &impl Fn(&T, &T) -> bool) {
    let n = items.len();
    if n <= 1 {
        return;
    }
    let n1 = n / 2;
    {
        let (a, b) = items.split_at_mut(n1);
        merge_sort(a, tmp, le);
        merge_sort(b, tmp, le);
    }
    let (mut i, mut j, mut k) = (0, n1, 0);
    while i < n1 && j < n {
        if le(&items[i], &items[j]) {
            tmp[k] = items[i];
            i += 1;
        } else {
            tmp[k] = items[j];
            j += 1;
        }
        k += 1;
    }
    while i < n1 {
        tmp[k] = items[i];
        i += 1;
        k += 1;
    }
    items[..k].copy_from_slice(&tmp[..k]);
}

/// Bounding box of a body's geoms (with margins) along the rows of `frame`: (min, max) per axis.
fn body_aabb(m: &Model, d: &Data, b: usize, frame: &Mat3) -> [f64; 6] {
    let mut aabb = [0.0; 6];
    for (i, g) in m.body_geoms(b).enumerate() {
        let pos = row::<3>(d.geom_xpos, g);
        let r = m.geom_rbound()[g] + m.geom_margin()[g];
        for j in 0..3 {
            let axis = [frame[3 * j], frame[3 * j + 1], frame[3 * j + 2]];
            let c = dot3(&pos, &axis);
            let (lo, hi) = (c - r, c + r);
            if i == 0 {
                aabb[2 * j] = lo;
                aabb[2 * j + 1] = hi;
            } else {
                aabb[2 * j] = min(aabb[2 * j], lo);
                aabb[2 * j + 1] = max(aabb[2 * j + 1], hi);
            }
        }
    }
    aabb
}

/// Principal axes (rows) of the centres of the geoms not on the world, of which there is one.
fn principal_frame(m: &Model, d: &Data) -> Mat3 {
    let ngeom = m.raw.ngeom as usize;
    let mut cen = [0.0; 3];
    let mut cnt = 0usize;
    for g in (0..ngeom).filter(|&g| m.geom_bodyid()[g] != 0) {
        let p = row::<3>(d.geom_xpos, g);
        for k in 0..3 {
            cen[k] += p[k];
        }
        cnt += 1;
    }
    for c in &mut cen {
        *c /= cnt as f64;
    }
    let mut cov = [0.0; 9];
    for g in (0..ngeom).filter(|&g| m.geom_bodyid()[g] != 0) {
        let dif = sub3(&row::<3>(d.geom_xpos, g), &cen);
        let (d00, d01, d02) = (dif[0] * dif[0], dif[0] * dif[1], dif[0] * dif[2]);
        let (d11, d12, d22) = (dif[1] * dif[1], dif[1] * dif[2], dif[2] * dif[2]);
        for (c, v) in cov
            .iter_mut()
            .zip([d00, d01, d02, d01, d11, d12, d02, d12, d22])
        {
            *c += v;
        }
    }
    for c in &mut cov {
        *c /= cnt as f64;
    }
    eig3(&cov).eigvec
}

/// Always sweep in the principal frame (the tests compare the two ways).
#[cfg(test)]
fn sweep_only() -> bool {
    super::tests::SWEEP_ONLY.with(|f| f.get())
}
#[cfg(not(test))]
#[inline(always)]
fn sweep_only() -> bool {
    false
}

/// The sweep tests the active bodies one at a time (the tests compare the two ways).
#[cfg(test)]
fn scalar_sweep() -> bool {
    super::tests::SCALAR_SWEEP.with(|f| f.get())
}
#[cfg(not(test))]
#[inline(always)]
fn scalar_sweep() -> bool {
    false
}

#[cfg(test)]
fn frameless_taken() {
    super::tests::FRAMELESS.with(|n| n.set(n.get() + 1));
}
#[cfg(not(test))]
#[inline(always)]
fn frameless_taken() {}

/// Most swept bodies, and geom pairs tested, with which `pairs_without_frame` is tried.
const MAX_FRAMELESS_BODIES: usize = 22;
const MAX_FRAMELESS_TESTS: usize = 200;

/// The swept pairs that matter, found without the principal frame (2.2.2 computes it in every
/// step: an iterative eigen-decomposition): a pair of swept bodies whose geoms' masks or weld
/// bodies the collision loop filters out, or whose every geom pair the masks let through fails
/// mj_collideGeoms's bounding-sphere test (all at once where the spheres around the two bodies
/// are apart), gives no contact whether listed or not: it is left out; any other pair whose
/// geoms' bounding spheres (with margins, as in the boxes) overlap by more than any rounding
/// is in the sweep's list in every frame: it is listed. (An excluded pair is tested as any
/// other: the loop's merge with the exclude list, which it reads as sorted, decides for it.)
/// When every pair is one or the other, the contacts are the sweep's. False (nothing added)
/// when some pair is in between, a user contact filter is to see every listed pair, a swept
/// body also pairs with all bodies (its pairs would be listed twice), or some position is not
/// finite or too large for the sweep's f32 keys. `bodies` and `masks`: scratch of at least one
/// slot per swept body.
fn pairs_without_frame(
    m: &Model,
    d: &Data,
    pairs: &mut Pairs,
    bodies: &mut [u64],
    masks: &mut [u64],
) -> Result<bool, EngineError> {
    if hooks::contact_filter_set() {
        return Ok(false);
    }
    let nbody = m.raw.nbody as usize;
    let (rbound, margin) = (m.geom_rbound(), m.geom_margin());
    let (contype, conaffinity) = (m.geom_contype(), m.geom_conaffinity());
    let (weldid, parentid) = (m.body_weldid(), m.body_parentid());
    const LARGE: f64 = 1e30;
    // the swept bodies, each with the masks of all its geoms together (no pair of masks
    // matches where these do not), its weld body and that one's parent's, and its sphere
    // (`body_sphere`) with the sum of its centre's magnitudes
    let mut welds = [(0i32, 0i32); MAX_FRAMELESS_BODIES];
    let mut sphere = [None; MAX_FRAMELESS_BODIES];
    let mut n = 0;
    for b in 1..nbody {
        let geoms = m.body_geoms(b);
        let (t, a) = geoms
            .clone()
            .fold((0, 0), |(t, a), g| (t | contype[g], a | conaffinity[g]));
        if t == 0 && a == 0 {
            continue;
        }
        for g in geoms {
            let p = row::<3>(d.geom_xpos, g);
            if !(p.iter().all(|x| x.abs() < LARGE)
                && (0.0..LARGE).contains(&(rbound[g] + margin[g])))
            {
                return Ok(false);
            }
        }
        let w = weldid[b];
        if w == 0 && has_plane_or_hfield(m, b) {
            return Ok(false);
        }
        bodies[n] = b as u64;
        masks[n] = pack_masks((t, a));
        welds[n] = (w, weldid[parentid[w as usize] as usize]);
        sphere[n] =
            body_sphere(m, d, b).map(|(c, r, bm)| (c, r, bm, c.iter().map(|x| x.abs()).sum()));
        n += 1;
    }
    let filterparent = !disabled(m, mjtDisableBit_::mjDSBL_FILTERPARENT);
    let overridden = margin_override(m);
    let start = pairs.n;
    let mut tests = 0;
    for i in 0..n {
        let (b1, masks1) = (bodies[i] as usize, unpack_masks(masks[i]));
        for j in i + 1..n {
            let b2 = bodies[j] as usize;
            if !can_pair(masks1, unpack_masks(masks[j]))
                || welds_filtered_by(filterparent, welds[i], welds[j])
            {
                continue;
            }
            // every geom pair apart: no contact
            if let (Some(s1), Some(s2)) = (sphere[i], sphere[j]) {
                if spheres_beyond(overridden, s1, s2) {
                    continue;
                }
            }
            match frameless_pair(m, d, m.body_geoms(b1), m.body_geoms(b2), &mut tests) {
                Some(true) => pairs.add(m, true, b1, b2)?,
                Some(false) => {}
                None => {
                    pairs.n = start;
                    return Ok(false);
                }
            }
        }
    }
    Ok(true)
}

/// One pair of swept bodies for `pairs_without_frame`: Some(false) when it can give no contact
/// (every geom pair the masks let through is apart by the sphere test, or has no collider),
/// else Some(true) when listed in every frame, None when neither is certain (or the tests run
/// out).
fn frameless_pair(
    m: &Model,
    d: &Data,
    geoms1: std::ops::Range<usize>,
    geoms2: std::ops::Range<usize>,
    tests: &mut usize,
) -> Option<bool> {
    let (rbound, margin) = (m.geom_rbound(), m.geom_margin());
    let (contype, conaffinity) = (m.geom_contype(), m.geom_conaffinity());
    let mask = |g: usize| (contype[g], conaffinity[g]);
    let mut apart = true;
    'pairs: for g1 in geoms1.clone() {
        for g2 in geoms2.clone() {
            if can_pair(mask(g1), mask(g2)) {
                *tests += 1;
                if *tests > MAX_FRAMELESS_TESTS {
                    return None;
                }
                if !dynamic_pair_apart(m, d, g1, g2) {
                    apart = false;
                    break 'pairs;
                }
            }
        }
    }
    if apart {
        return Some(false);
    }
    for g1 in geoms1 {
        let p1 = row::<3>(d.geom_xpos, g1);
        let r1 = rbound[g1] + margin[g1];
        for g2 in geoms2.clone() {
            *tests += 1;
            if *tests > MAX_FRAMELESS_TESTS {
                return None;
            }
            let p2 = row::<3>(d.geom_xpos, g2);
            let r2 = rbound[g2] + margin[g2];
            let dif = sub3(&p1, &p2);
            let dist2 = dot3(&dif, &dif);
            // far more than the rounding of the boxes' bounds (their f32 keys included)
            let scale: f64 = p1.iter().chain(&p2).map(|x| x.abs()).sum();
            let slack = 1e-6 * (scale + r1 + r2);
            let overlap = r1 + r2 - slack;
            if overlap > 0.0 && dist2 < overlap * overlap {
                return Some(true);
            }
        }
    }
    None
}

/// Candidate body pairs into `pair` (from the arena), sorted by signature; returns their count.
pub fn broadphase<'a>(
    m: &Model,
    d: &Data,
    a: &mut Arena<'a>,
) -> Result<&'a mut [i32], EngineError> {
    let nbody = m.raw.nbody as usize;
    let maxpair = nbody * (nbody - 1) / 2;
    // 2.2.2 takes a slot per pair and fills half of it: the other halves serve the sweep
    let (pair, spare) = a.alloc_int_stale_spare(maxpair)?;
    let mut pairs = Pairs { pair, n: 0 };

    // the world's geoms, and planes or height fields welded to it, meet every body
    for b1 in (0..nbody).filter(|&b| can_collide(m, b)) {
        let all = (b1 == 0 && m.body_geomnum()[0] > 0)
            || (m.body_weldid()[b1] == 0 && has_plane_or_hfield(m, b1));
        if all {
            for b2 in (0..nbody).filter(|&b2| b2 != b1) {
                pairs.add(m, false, b1, b2)?;
            }
        }
    }

    if m.geom_bodyid().iter().any(|&b| b != 0) {
        // its buffers are released on return, the pair list stays (the contact filter then
        // sees 2.2.2's stack top)
        a.scope(|a| sweep_and_prune(m, d, a, &mut pairs, spare))?;
    }

    // integers: any sort gives glibc's order
    let n = pairs.n;
    pairs.pair[..n].sort_unstable();
    Ok(&mut pairs.pair[..n])
}

/// Sweep along the first axis (f32 keys, as 2.2.2), pruning by the other two. `spare`:
/// scratch for `sweep`, which takes over where it holds 4 slots per swept body.
fn sweep_and_prune(
    m: &Model,
    d: &Data,
    a: &mut Arena,
    pairs: &mut Pairs,
    spare: &mut [f64],
) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    let aabb = a.alloc(6 * nbody)?;
    // the swept bodies, and the masks of all their geoms together
    let (mut count, mut contype, mut conaffinity) = (0, 0, 0);
    for b in 1..nbody {
        let (t, a) = body_masks(m, b);
        if t != 0 || a != 0 {
            (count, contype, conaffinity) = (count + 1, contype | t, conaffinity | a);
        }
    }
    if count == 0 {
        return Ok(());
    }
    // 2.2.2's mjtBroadphase in one stack slot each: the body (+UPPER for a box's upper end) in the
    // low 32 bits, its f32 bound on axis 0 in the high ones; 2*count slots for the sorted list
    // and 2*count for the active list (which also serves as the merge sort's buffer)
    let entries = a.alloc_u64_stale(2 * count)?;
    let active = a.alloc_u64_stale(2 * count)?;
    if count == 1 {
        // a lone body pairs with nobody here, whatever the frame: skip finding it
        return Ok(());
    }
    if !sweep_only() {
        // no two swept geoms' masks match: the collision loop skips whatever the sweep lists
        // (unless a user contact filter is to see each pair)
        if contype & conaffinity == 0 && !hooks::contact_filter_set() {
            frameless_taken();
            return Ok(());
        }
        if count <= MAX_FRAMELESS_BODIES && pairs_without_frame(m, d, pairs, entries, active)? {
            frameless_taken();
            return Ok(());
        }
    }
    let frame = principal_frame(m, d);
    for b in 1..nbody {
        aabb[6 * b..6 * b + 6].copy_from_slice(&body_aabb(m, d, b, &frame));
    }
    for (j, b) in (1..nbody).filter(|&b| can_collide(m, b)).enumerate() {
        let (lo, hi) = (aabb[6 * b] as f32, aabb[6 * b + 1] as f32);
        entries[2 * j] = (u64::from(lo.to_bits()) << 32) | b as u64;
        entries[2 * j + 1] = (u64::from(hi.to_bits()) << 32) | (b as u64 + UPPER);
    }
    let key = |e: &u64| -> f32 { f32::from_bits((e >> 32) as u32) };
    let ismax = |e: u64| e & 0xFFFF_FFFF;
    // 2.2.2's comparison: less -> -1, equal -> 0, else (also NaN) -> 1; merged first if <= 0
    // without NaN keys the order is total: the stable order is the key order with ties in
    // creation order (body, then lower before upper end), which an unstable sort reproduces
    if entries.iter().any(|e| key(e).is_nan()) {
        merge_sort(entries, active, &|x, y| key(x) <= key(y));
    } else {
        // as integers: the key's order-preserving bits (-0 as +0, they compare equal), then
        // the body, then the upper end after the lower; back to the body (+UPPER) once sorted
        for e in entries.iter_mut() {
            let bits = match (*e >> 32) as u32 {
                0x8000_0000 => 0,
                b => b,
            };
            let total = if bits & 0x8000_0000 != 0 {
                !bits
            } else {
                bits | 0x8000_0000
            };
            let low = ismax(*e);
            *e = (u64::from(total) << 32) | ((low & 0xFFFF) << 1) | (low >> 16);
        }
        entries.sort_unstable();
        for e in entries.iter_mut() {
            *e = ((*e & 0xFFFF_FFFF) >> 1) + (*e & 1) * UPPER;
        }
    }

    // the buffer cannot fill before the last of the swept pairs, so no pair left out by its
    // masks (never added) would have met it full ("Broadphase buffer full")
    let room = pairs.n + count * (count - 1) / 2 <= pairs.pair.len();
    if room && spare.len() >= 4 * count && !scalar_sweep() {
        return sweep(m, pairs, entries, active, &mut aabb[..], spare);
    }
    let mut nactive = 0;
    for &e in entries.iter() {
        let e = ismax(e);
        if e & UPPER == 0 {
            let b2 = e as usize;
            for &b1 in &active[..nactive] {
                let b1 = b1 as usize;
                let (p, q) = (&aabb[6 * b1..6 * b1 + 6], &aabb[6 * b2..6 * b2 + 6]);
                if p[2] > q[3] || p[3] < q[2] || p[4] > q[5] || p[5] < q[4] {
                    continue;
                }
                pairs.add(m, true, b1, b2)?;
            }
            active[nactive] = e;
            nactive += 1;
        } else {
            let remove = e & 0xFFFF;
            if let Some(k) = active[..nactive].iter().position(|&x| x == remove) {
                active.copy_within(k + 1..nactive, k);
                nactive -= 1;
            }
        }
    }
    Ok(())
}

/// The sweep over the sorted ends with the active bodies' bounds on axes 1 and 2 kept beside
/// them (`spare`: 4 slots per swept body), and the masks of those with one geom (in the
/// active list's second half, unused: one slot per swept body is enough): each new body
/// meets the active ones four at a time with the same tests (NaN bounds overlap), the pairs of
/// two one-geom bodies whose masks do not match left out in the same lanes (as `Pairs::add`
/// does). A body leaves the active list by swapping in the last one, its place found
/// in `aabb`'s slot for its lower bound on axis 0 (read already): the pairs come in another
/// order, the same pairs (the list is sorted after).
fn sweep(
    m: &Model,
    pairs: &mut Pairs,
    entries: &[u64],
    active: &mut [u64],
    aabb: &mut [f64],
    spare: &mut [f64],
) -> Result<(), EngineError> {
    let n = spare.len() / 4;
    let (lo1, rest) = spare.split_at_mut(n);
    let (hi1, rest) = rest.split_at_mut(n);
    let (lo2, hi2) = rest.split_at_mut(n);
    // the active list's second half holds the masks (`pack_masks`)
    let (active, masks_of) = active.split_at_mut(active.len() / 2);
    // a body's masks if it has one geom, else all bits (no filter: a swept body's masks are
    // not both 0, so they meet all bits)
    let masks = |b: usize| match m.body_geomnum()[b] {
        1 => {
            let g = m.body_geomadr()[b] as usize;
            (m.geom_contype()[g], m.geom_conaffinity()[g])
        }
        _ => (-1, -1),
    };
    // when every two swept bodies' masks meet, no pair is left out for them
    let (mut all_t, mut all_a) = (-1, -1);
    for &e in entries {
        let b = (e & 0xFFFF) as usize;
        aabb[6 * b] = -1.0;
        let (t, a) = masks(b);
        (all_t, all_a) = (all_t & t, all_a & a);
    }
    let filter = all_t & all_a == 0;
    let mut nactive = 0;
    for &e in entries {
        let e = e & 0xFFFF_FFFF;
        let b = (e & 0xFFFF) as usize;
        if e & UPPER == 0 {
            let q = [
                aabb[6 * b + 2],
                aabb[6 * b + 3],
                aabb[6 * b + 4],
                aabb[6 * b + 5],
            ];
            let (ct, ca) = masks(b);
            let near =
                |k: usize| !((lo1[k] > q[1]) | (hi1[k] < q[0]) | (lo2[k] > q[3]) | (hi2[k] < q[2]));
            let listed = &active[..nactive];
            if filter {
                let meet = |k: usize| can_pair(unpack_masks(masks_of[k]), (ct, ca));
                add_passing(m, pairs, listed, b, |k| near(k) & meet(k))?;
            } else {
                add_passing(m, pairs, listed, b, near)?;
            }
            active[nactive] = b as u64;
            (lo1[nactive], hi1[nactive], lo2[nactive], hi2[nactive]) = (q[0], q[1], q[2], q[3]);
            masks_of[nactive] = pack_masks((ct, ca));
            aabb[6 * b] = nactive as f64;
            nactive += 1;
        } else if aabb[6 * b] >= 0.0 {
            let (k, last) = (aabb[6 * b] as usize, nactive - 1);
            active[k] = active[last];
            (lo1[k], hi1[k], lo2[k], hi2[k]) = (lo1[last], hi1[last], lo2[last], hi2[last]);
            masks_of[k] = masks_of[last];
            aabb[6 * active[k] as usize] = k as f64;
            aabb[6 * b] = -1.0;
            nactive -= 1;
        }
    }
    Ok(())
}

/// Adds the pairs of body b with the active bodies that `pass` lets through (by their place),
/// testing four at a time.
#[inline(always)]
fn add_passing(
    m: &Model,
    pairs: &mut Pairs,
    active: &[u64],
    b: usize,
    pass: impl Fn(usize) -> bool,
) -> Result<(), EngineError> {
    let n = active.len();
    for base in (0..n).step_by(4) {
        let mut hits = 0u32;
        for k in 0..4 {
            hits |= u32::from(pass((base + k).min(n - 1))) << k;
        }
        hits &= (1u32 << (n - base).min(4)) - 1;
        while hits != 0 {
            let k = base + hits.trailing_zeros() as usize;
            hits &= hits - 1;
            pairs.add(m, false, active[k] as usize, b)?;
        }
    }
    Ok(())
}
