//! Collision detection (mj_collision): the broad phase proposes body pairs, geom pairs are
//! filtered (contype/conaffinity, weld and parent exclusion, excludes, explicit pairs, bounding
//! spheres with margin), the narrow-phase routine of the type pair finds contacts, and their
//! parameters are mixed from the two geoms (or taken from the explicit pair).

use crate::engine::linalg::{row, row_ref};

mod big_frame;
mod body_frame;
pub mod bounds;
pub mod boxes;
pub mod broadphase;
mod candidates;
pub mod convex;
pub mod mpr;
pub mod narrow;
pub mod primitive;
mod spheres;
#[cfg(test)]
mod tests;
mod world_box;
use crate::abi::*;
use crate::engine::hooks;
use crate::engine::support::warning;
use crate::engine::{disabled, enabled, Data, EngineError, Model};
use crate::math::misc::{max, min};
use crate::math::spatial::make_frame;
use crate::math::*;
use primitive::ContactGeom;

/// Smallest friction coefficient of a contact (mjMINMU).
const MINMU: f64 = 1e-5;

/// The margin of every contact when the contact override is on.
#[inline(always)]
pub(super) fn margin_override(m: &Model) -> Option<f64> {
    enabled(m, mjtEnableBit_::mjENBL_OVERRIDE).then_some(m.raw.opt.o_margin)
}

pub(super) fn assign_margin(m: &Model, margin: f64) -> f64 {
    margin_override(m).unwrap_or(margin)
}

/// Distance of geom g's centre above the plane geom's surface.
fn plane_dist(d: &Data, plane: usize, g: usize) -> f64 {
    let mat = row::<9>(d.geom_xmat, plane);
    let dif = vec3::sub3(&row(d.geom_xpos, g), &row(d.geom_xpos, plane));
    vec3::dot3(&dif, &[mat[2], mat[5], mat[8]])
}

/// The built-in filter (mj_contactFilter) discards a dynamic geom pair when its bodies' weld
/// bodies are the same or parent and child (unless filterparent is disabled or one is the
/// world), or when the geoms' masks do not match (can_pair); the collision loop applies it a
/// body pair and a geom at a time. This is its test of the weld bodies: true discards every
/// geom pair of the two.
#[inline]
pub(super) fn welds_filtered(m: &Model, w1: i32, w2: i32) -> bool {
    let wparent = |w: i32| m.body_weldid()[m.body_parentid()[w as usize] as usize];
    if w1 == w2 {
        return true;
    }
    let filterparent = !disabled(m, mjtDisableBit_::mjDSBL_FILTERPARENT);
    welds_filtered_by(filterparent, (w1, wparent(w1)), (w2, wparent(w2)))
}

/// `welds_filtered` of (weld body, its parent's weld body) pairs, with filterparent on or off.
#[inline(always)]
pub(super) fn welds_filtered_by(
    filterparent: bool,
    (w1, p1): (i32, i32),
    (w2, p2): (i32, i32),
) -> bool {
    w1 == w2 || (filterparent && w1 != 0 && w2 != 0 && (w1 == p2 || w2 == p1))
}

/// Can geoms of these (contype, conaffinity) masks collide (the built-in filter's mask test)?
pub(super) fn can_pair((ct1, ca1): (i32, i32), (ct2, ca2): (i32, i32)) -> bool {
    ct1 & ca2 != 0 || ct2 & ca1 != 0
}

/// Contact parameters of a geom pair: condim, friction (5), solref, solimp, margin, gap.
struct Params {
    condim: i32,
    friction: [f64; 5],
    solref: [f64; mjNREF],
    solimp: [f64; mjNIMP],
}

/// Mixes the parameters of two geoms (dynamic pairs): by priority, else max/solmix.
fn mixed(m: &Model, g1: usize, g2: usize) -> Params {
    let (p1, p2) = (m.geom_priority()[g1], m.geom_priority()[g2]);
    let mut friction = [0.0; 5];
    let (mut solref, mut solimp) = ([0.0; mjNREF], [0.0; mjNIMP]);
    let condim;
    if p1 != p2 {
        let gp = if p1 > p2 { g1 } else { g2 };
        condim = m.geom_condim()[gp];
        for i in 0..3 {
            friction[2 * i] = m.geom_friction()[3 * gp + i];
        }
        solref.copy_from_slice(&m.geom_solref()[mjNREF * gp..mjNREF * (gp + 1)]);
        solimp.copy_from_slice(&m.geom_solimp()[mjNIMP * gp..mjNIMP * (gp + 1)]);
    } else {
        condim = m.geom_condim()[g1].max(m.geom_condim()[g2]);
        for i in 0..3 {
            friction[2 * i] = max(m.geom_friction()[3 * g1 + i], m.geom_friction()[3 * g2 + i]);
        }
        let (s1, s2) = (m.geom_solmix()[g1], m.geom_solmix()[g2]);
        let mix = if s1 >= MINVAL && s2 >= MINVAL {
            s1 / (s1 + s2)
        } else if s1 < MINVAL && s2 < MINVAL {
            0.5
        } else if s1 < MINVAL {
            0.0
        } else {
            1.0
        };
        let (r1, r2) = (
            &m.geom_solref()[mjNREF * g1..mjNREF * (g1 + 1)],
            &m.geom_solref()[mjNREF * g2..mjNREF * (g2 + 1)],
        );
        for i in 0..mjNREF {
            solref[i] = if r1[0] > 0.0 && r2[0] > 0.0 {
                mix * r1[i] + (1.0 - mix) * r2[i]
            } else {
                min(r1[i], r2[i])
            };
        }
        for i in 0..mjNIMP {
            solimp[i] = m.geom_solimp()[mjNIMP * g1 + i] * mix;
            solimp[i] += m.geom_solimp()[mjNIMP * g2 + i] * (1.0 - mix);
        }
    }
    friction[1] = friction[0];
    friction[3] = friction[4];
    Params {
        condim,
        friction,
        solref,
        solimp,
    }
}

fn pair_params(m: &Model, p: usize) -> Params {
    let mut friction = [0.0; 5];
    friction.copy_from_slice(&m.pair_friction()[5 * p..5 * p + 5]);
    let (mut solref, mut solimp) = ([0.0; mjNREF], [0.0; mjNIMP]);
    solref.copy_from_slice(&m.pair_solref()[mjNREF * p..mjNREF * (p + 1)]);
    solimp.copy_from_slice(&m.pair_solimp()[mjNIMP * p..mjNIMP * (p + 1)]);
    Params {
        condim: m.pair_dim()[p],
        friction,
        solref,
        solimp,
    }
}

/// Removes box-box contacts at a position a later contact repeats (2.2.2 keeps the last).
fn dedup_box_box(con: &mut [ContactGeom], n: usize) -> usize {
    let mut keep = [true; narrow::MAX_CONTACT_PAIR];
    for i in 0..n.saturating_sub(1) {
        if (i + 1..n).any(|j| con[i].pos == con[j].pos) {
            keep[i] = false;
        }
    }
    let mut k = 0;
    for j in 0..n {
        if keep[j] {
            con[k] = con[j];
            k += 1;
        }
    }
    k
}

/// Where a geom pair comes from.
#[derive(Clone, Copy)]
pub(super) enum Source {
    /// An explicit pair: its index.
    Pair(usize),
    /// The broad phase: `filtered` is the built-in filter's verdict, which stands unless a
    /// user filter (mjcb_contactfilter) is set.
    Dynamic { filtered: bool },
}

/// The bounding-sphere test of mj_collideGeoms: true when the geoms (g1 of the lower type) are
/// farther apart than their bounding radii and the margin.
#[inline(always)]
fn spheres_apart(m: &Model, d: &Data, g1: usize, g2: usize, margin: f64) -> bool {
    let (r1, r2) = (m.geom_rbound()[g1], m.geom_rbound()[g2]);
    let dif = vec3::sub3(&row(d.geom_xpos, g1), &row(d.geom_xpos, g2));
    r1 > 0.0 && r2 > 0.0 && beyond_reach(vec3::dot3(&dif, &dif), r1 + r2 + margin)
}

/// sqrt(dist2) > reach, decided from the squares unless they are within 1e-12 of each other:
/// outside that band the rounded root falls on the same side of reach (it is within 2^-53 of
/// the exact root, the bounds within 3e-16 of reach * reach times 1 -+ 1e-12), and the root's
/// latency is saved. Reaches whose square under- or overflows, and NaN, take the root.
#[inline(always)]
pub(super) fn beyond_reach(dist2: f64, reach: f64) -> bool {
    if clearly_within(dist2, reach) {
        return false;
    }
    if clearly_beyond(dist2, reach) {
        return true;
    }
    dist2.sqrt() > reach
}

/// Relative band around reach * reach inside which only the root decides (`beyond_reach`).
const ROOT_BAND: f64 = 1e-12;

/// Is reach's square a normal, finite number (false for NaN)?
#[inline(always)]
fn square_in_range(reach: f64) -> bool {
    (reach > 1e-150) & (reach < 1e150)
}

/// sqrt(dist2) > reach, certain from the squares alone (false where it is not; no branch).
#[inline(always)]
pub(super) fn clearly_beyond(dist2: f64, reach: f64) -> bool {
    square_in_range(reach) & (dist2 > reach * reach * (1.0 + ROOT_BAND))
}

/// sqrt(dist2) <= reach, certain from the squares alone (false where it is not; no branch).
#[inline(always)]
fn clearly_within(dist2: f64, reach: f64) -> bool {
    square_in_range(reach) & (dist2 < reach * reach * (1.0 - ROOT_BAND))
}

/// The bounding-box test (`bounds`) of geoms g1 and g2 (none where one has no box).
fn boxes_apart(m: &Model, d: &Data, g1: usize, g2: usize, margin: f64) -> bool {
    match (bound(m, d, g1), bound(m, d, g2)) {
        (Some(b1), Some(b2)) => bounds::apart(&b1, &b2, margin),
        _ => false,
    }
}

/// Geom g's pose and box, built in the caller (returned through memory, its fields were read
/// back before their stores completed).
#[inline(always)]
fn bound(m: &Model, d: &Data, g: usize) -> Option<bounds::Bound> {
    let h = bounds::extent(
        m.geom_type()[g],
        row_ref(m.geom_size(), g),
        m.geom_rbound()[g],
    )?;
    Some(bounds::Bound {
        pos: row(d.geom_xpos, g),
        mat: row(d.geom_xmat, g),
        h,
    })
}

/// Can this dynamic geom pair give no contact, whatever the broad phase says (no collider for
/// its types, or apart by mj_collideGeoms's bounding-sphere test)?
pub(super) fn dynamic_pair_apart(m: &Model, d: &Data, g1: usize, g2: usize) -> bool {
    let (g1, g2) = if m.geom_type()[g1] > m.geom_type()[g2] {
        (g2, g1)
    } else {
        (g1, g2)
    };
    if !narrow::has_collider(m.geom_type()[g1], m.geom_type()[g2]) {
        return true;
    }
    let margin = assign_margin(m, max(m.geom_margin()[g1], m.geom_margin()[g2]));
    spheres_apart(m, d, g1, g2, margin)
}

/// Tests one geom pair (mj_collideGeoms).
/// Returns Ok(false) when the contact buffer is full (2.2.2 stops adding then).
/// `top`: the stack in use (a user contact filter allocates above it).
pub(super) fn collide_geoms(
    m: &Model,
    d: &mut Data,
    top: usize,
    g1: usize,
    g2: usize,
    source: Source,
    con: &mut Buffer,
) -> Result<bool, EngineError> {
    let (g1, g2) = if m.geom_type()[g1] > m.geom_type()[g2] {
        (g2, g1)
    } else {
        (g1, g2)
    };
    let (t1, t2) = (m.geom_type()[g1], m.geom_type()[g2]);
    if !narrow::has_collider(t1, t2) {
        return Ok(true);
    }
    let pair = match source {
        Source::Pair(p) => Some(p),
        Source::Dynamic { filtered } => {
            if hooks::contact_filter(m, d, top, g1, g2).unwrap_or(filtered) {
                return Ok(true);
            }
            None
        }
    };
    let (margin, gap) = match pair {
        None => (
            max(m.geom_margin()[g1], m.geom_margin()[g2]),
            max(m.geom_gap()[g1], m.geom_gap()[g2]),
        ),
        Some(p) => (m.pair_margin()[p], m.pair_gap()[p]),
    };
    let margin = assign_margin(m, margin);
    let (r1, r2) = (m.geom_rbound()[g1], m.geom_rbound()[g2]);
    if spheres_apart(m, d, g1, g2, margin) {
        return Ok(true);
    }
    let plane = mjtGeom_::mjGEOM_PLANE as i32;
    if t1 == plane && r2 > 0.0 && plane_dist(d, g1, g2) > margin + r2 {
        return Ok(true);
    }
    if t2 == plane && r1 > 0.0 && plane_dist(d, g2, g1) > margin + r1 {
        return Ok(true);
    }
    if bounds::worth_testing(t1, t2) && boxes_apart(m, d, g1, g2, margin) {
        return Ok(true);
    }

    let con = con.get();
    let mut n = narrow::collide(m, d, g1, g2, margin, con);
    if n == 0 {
        return Ok(true);
    }
    let boxed = mjtGeom_::mjGEOM_BOX as i32;
    if t1 == boxed && t2 == boxed {
        n = dedup_box_box(con, n);
    }
    let mut p = match pair {
        None => mixed(m, g1, g2),
        Some(p) => pair_params(m, p),
    };
    for f in &mut p.friction {
        *f = max(MINMU, *f);
    }
    if enabled(m, mjtEnableBit_::mjENBL_OVERRIDE) {
        p.solref = m.raw.opt.o_solref;
        p.solimp = m.raw.opt.o_solimp;
    }
    if !(1..=6).contains(&p.condim) {
        return Err(EngineError(format!("Invalid condim value: {}", n - 1)));
    }
    for c in &con[..n] {
        let mut frame = [0.0; 9];
        frame[..6].copy_from_slice(&c.frame);
        let frame = make_frame(&frame)
            .ok_or_else(|| EngineError("mju_makeFrame: xaxis must be a unit vector".into()))?;
        let includemargin = margin - gap;
        let contact = mjContact {
            dist: c.dist,
            pos: c.pos,
            frame,
            includemargin,
            friction: p.friction,
            solref: p.solref,
            solimp: p.solimp,
            mu: 0.0,
            H: [0.0; 36],
            dim: p.condim,
            geom1: g1 as i32,
            geom2: g2 as i32,
            // 2.2.2 includes a contact when dist < includemargin: NaN distances are excluded
            exclude: if c.dist < includemargin { 0 } else { 1 },
            efc_address: -1,
        };
        if !add_contact(m, d, contact)? {
            return Ok(false);
        }
    }
    Ok(true)
}

/// Are bodies b1 and b2 apart by their world boxes (`world_box`), so that none of their
/// dynamic geom pairs gives a contact? Never where a user contact filter is to see each pair.
#[inline(always)]
fn world_boxes_apart(
    m: &Model,
    d: &Data,
    boxes: &mut Option<world_box::WorldBoxes>,
    b1: usize,
    b2: usize,
) -> bool {
    if b1.max(b2) >= world_box::MAX_BODIES || hooks::contact_filter_set() || !world_box::enabled() {
        return false;
    }
    let boxes = boxes.get_or_insert_with(world_box::WorldBoxes::default);
    let Some(x) = boxes.get(m, d, b1) else {
        return false;
    };
    let Some(y) = boxes.get(m, d, b2) else {
        return false;
    };
    let apart = world_box::apart(&x, &y, margin_override(m));
    if apart {
        world_box::skipped();
    }
    apart
}

/// Contacts a narrow-phase collider reports for one geom pair.
pub(super) type Contacts = [ContactGeom; narrow::MAX_CONTACT_PAIR];

/// The contacts of one geom pair at a time, set up when a collider first runs (colliders write
/// every field of the contacts they report, so one buffer serves all pairs).
pub(super) struct Buffer(Option<Contacts>);

impl Buffer {
    fn get(&mut self) -> &mut Contacts {
        self.0
            .get_or_insert_with(|| [ContactGeom::default(); narrow::MAX_CONTACT_PAIR])
    }
}

/// Appends a contact (mj_addContact); false with the buffer-full warning when there is no room.
fn add_contact(m: &Model, d: &mut Data, con: mjContact) -> Result<bool, EngineError> {
    let n = d.raw.ncon.max(0) as usize;
    if n >= m.raw.nconmax.max(0) as usize {
        warning(d.raw, mjtWarning_::mjWARN_CONTACTFULL as i32, m.raw.nconmax)?;
        return Ok(false);
    }
    d.contact[n] = con;
    d.raw.ncon += 1;
    Ok(true)
}

/// mj_collision: fills d.contact and d.ncon.
#[inline]
pub fn collision(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    d.raw.ncon = 0;
    if disabled(m, mjtDisableBit_::mjDSBL_CONSTRAINT)
        || disabled(m, mjtDisableBit_::mjDSBL_CONTACT)
        || m.raw.nconmax == 0
        || m.raw.nbody < 2
    {
        return Ok(());
    }
    collide_all(m, d)
}

#[inline(never)]
fn collide_all(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    let npair = m.raw.npair.max(0) as usize;
    let mut con = Buffer(None);
    if m.raw.opt.collision == mjtCollision_::mjCOL_PAIR as i32 {
        for p in 0..npair {
            let (g1, g2) = (m.pair_geom1()[p] as usize, m.pair_geom2()[p] as usize);
            collide_geoms(m, d, d.arena.used(), g1, g2, Source::Pair(p), &mut con)?;
        }
        return Ok(());
    }
    let merge = npair > 0 && m.raw.opt.collision == mjtCollision_::mjCOL_ALL as i32;
    d.with_scratch(|d, a| -> Result<(), EngineError> {
        let pairs = broadphase::broadphase(m, d, a)?;
        let (mut spheres, mut frames, mut large) = (None, None, None);
        let mut boxes = None;
        let nexclude = m.raw.nexclude.max(0) as usize;
        let (mut pairadr, mut exadr) = (0usize, 0usize);
        for &bp in pairs.iter() {
            let (b1, b2) = (((bp >> 16) & 0xFFFF) as usize, (bp & 0xFFFF) as usize);
            let signature = (((b1 + 1) << 16) + b2 + 1) as i32;
            let start = pairadr;
            let mut merged = false;
            if merge {
                while pairadr < npair && m.pair_signature()[pairadr] <= signature {
                    merged |= m.pair_signature()[pairadr] == signature;
                    let (g1, g2) = (
                        m.pair_geom1()[pairadr] as usize,
                        m.pair_geom2()[pairadr] as usize,
                    );
                    collide_geoms(m, d, a.used(), g1, g2, Source::Pair(pairadr), &mut con)?;
                    pairadr += 1;
                }
            }
            while exadr < nexclude && m.exclude_signature()[exadr] < signature {
                exadr += 1;
            }
            if exadr < nexclude && m.exclude_signature()[exadr] == signature {
                continue;
            }
            let (n1, n2) = (m.body_geomnum()[b1], m.body_geomnum()[b2]);
            if n1 == 0 || n2 == 0 {
                continue;
            }
            // pairs the built-in filter discards are skipped here unless a user filter is to
            // see each (the filter, or a warning handler, may set one between two calls)
            let (w1, w2) = (m.body_weldid()[b1], m.body_weldid()[b2]);
            let welded = welds_filtered(m, w1, w2);
            if welded && !hooks::contact_filter_set() {
                continue;
            }
            // (a single geom pair gets collide_geoms's own tests; the world's geoms, a floor
            // among them mostly, have no box around them all that is worth finding)
            if (n1 > 1 || n2 > 1) && b1 != 0 && world_boxes_apart(m, d, &mut boxes, b1, b2) {
                continue;
            }
            let (a1, a2) = (m.body_geomadr()[b1] as usize, m.body_geomadr()[b2] as usize);
            let (geoms1, geoms2) = (a1..a1 + n1 as usize, a2..a2 + n2 as usize);
            let (contype, conaffinity) = (m.geom_contype(), m.geom_conaffinity());
            let mask = |g: usize| (contype[g], conaffinity[g]);
            let many =
                geoms1.len() * geoms2.len() >= candidates::MIN_PAIRS && candidates::enabled();
            if many && !merged && !hooks::contact_filter_set() {
                let bodies = (b1, b2);
                // (the sweep's scratch was larger: the stack's high-water mark stays)
                let spheres = match spheres {
                    Some(ref mut s) => s,
                    None => spheres.insert(spheres::Spheres::new(a.alloc_stale(5 * nbody)?)),
                };
                candidates::collide_bodies(
                    m,
                    d,
                    a.used(),
                    bodies,
                    geoms1,
                    geoms2,
                    spheres,
                    (&mut frames, &mut large),
                    &mut con,
                )?;
                continue;
            }
            let masks2 = geoms2
                .clone()
                .fold((0, 0), |(t, a), g| (t | contype[g], a | conaffinity[g]));
            for g1 in geoms1 {
                // a geom that pairs with none of the other body's geoms
                if n2 > 1 && !can_pair(mask(g1), masks2) && !hooks::contact_filter_set() {
                    continue;
                }
                for g2 in geoms2.clone() {
                    let paired = can_pair(mask(g1), mask(g2));
                    if !paired && !hooks::contact_filter_set() {
                        continue;
                    }
                    let listed = merged
                        && (start..pairadr).any(|k| {
                            let (p1, p2) = (m.pair_geom1()[k] as usize, m.pair_geom2()[k] as usize);
                            (p1 == g1 && p2 == g2) || (p1 == g2 && p2 == g1)
                        });
                    if !listed {
                        let filtered = welded || !paired;
                        collide_geoms(
                            m,
                            d,
                            a.used(),
                            g1,
                            g2,
                            Source::Dynamic { filtered },
                            &mut con,
                        )?;
                    }
                }
            }
        }
        if merge {
            while pairadr < npair {
                let (g1, g2) = (
                    m.pair_geom1()[pairadr] as usize,
                    m.pair_geom2()[pairadr] as usize,
                );
                collide_geoms(m, d, a.used(), g1, g2, Source::Pair(pairadr), &mut con)?;
                pairadr += 1;
            }
        }
        Ok(())
    })
}
