//! A body of many geoms (a palm of convex pieces) against a body of few, in the frame of the
//! large one: each geom's box is taken by its half-widths along the frame's axes (a box around
//! it). A geom of the large body whose box is apart from the box around all of the small
//! body's geoms, or apart from one of them, by more than the margin along one of the axes
//! gives no contact with it (the test of `body_frame`, with its slack). The large body's geoms
//! are put in its frame once per collision pass, the small body's once per body pair.

use super::body_frame::{axis_apart, box_of, slack};
use crate::engine::linalg::{row, row_ref};
use crate::engine::{Data, Model};
use crate::math::misc::max;
use crate::math::vec3::{mul_mat3t_mat, mul_mat_t_vec3, sub3};
use crate::math::{Mat3, Vec3};

/// Most geoms of the large body, and of the small one.
pub(super) const MAX_LARGE: usize = 256;
pub(super) const MAX_SMALL: usize = 16;

/// Boxes in a frame: centres and half-widths along its axes, slack of their tests; `boxed`:
/// bits of the geoms that have a box.
#[derive(Clone, Copy)]
struct Boxes<const N: usize> {
    c: [[f64; N]; 3],
    w: [[f64; N]; 3],
    slack: [f64; N],
    boxed: [u64; 4],
}

impl<const N: usize> Default for Boxes<N> {
    fn default() -> Self {
        Boxes {
            c: [[0.0; N]; 3],
            w: [[0.0; N]; 3],
            slack: [0.0; N],
            boxed: [0; 4],
        }
    }
}

impl<const N: usize> Boxes<N> {
    /// Geoms `geoms` (at most N) in the frame (mat, pos).
    fn fill(&mut self, m: &Model, d: &Data, geoms: std::ops::Range<usize>, mat: &Mat3, pos: &Vec3) {
        self.boxed = [0; 4];
        for (i, g) in geoms.enumerate() {
            let Some(h) = box_of(m, g) else { continue };
            let rot = mul_mat3t_mat(mat, row_ref::<9>(d.geom_xmat, g)).map(f64::abs);
            let c = mul_mat_t_vec3(mat, &sub3(row_ref(d.geom_xpos, g), pos));
            for k in 0..3 {
                self.c[k][i] = c[k];
                self.w[k][i] = h[0] * rot[3 * k] + h[1] * rot[3 * k + 1] + h[2] * rot[3 * k + 2];
            }
            self.slack[i] = slack(h[0] + h[1] + h[2], &c);
            self.boxed[i / 64] |= 1 << (i % 64);
        }
    }

    fn has_box(&self, i: usize) -> bool {
        self.boxed[i / 64] & (1 << (i % 64)) != 0
    }
}

/// Is a geom whose centre lies `dif` along an axis from the centre of the box around the small
/// body's geoms, with half-widths `w` and `all_w` there, apart from that box by more than
/// `limit`, and from each small geom by 1e-7 / their centres' distance (`axis_apart`; a small
/// geom's centre lies in the box, so at least |dif| - all_w from the geom's)?
fn beyond_all(dif: f64, w: f64, all_w: f64, limit: f64) -> bool {
    let dif = dif.abs();
    let excess = dif - w - all_w - limit;
    excess > 0.0 && excess * (dif - all_w) > 1e-7
}

/// The large body's geoms in its frame, for the collision pass.
pub(super) struct Large {
    body: usize,
    boxes: Boxes<MAX_LARGE>,
}

impl Default for Large {
    fn default() -> Self {
        Large {
            body: usize::MAX,
            boxes: Boxes::default(),
        }
    }
}

/// A body pair: the small body's geoms in the large body's frame, and the box around them.
pub(super) struct Pair<'a> {
    large: &'a Large,
    /// First geom of the large body and of the small one.
    start: (usize, usize),
    small: Boxes<MAX_SMALL>,
    /// Around every small geom with a box (None: one has none, or a margin is NaN).
    all: Option<(Vec3, Vec3, f64, f64)>,
}

impl<'a> Pair<'a> {
    /// Body `large` (geoms `lgeoms`, at most MAX_LARGE) and the small body's geoms `sgeoms` (at
    /// most MAX_SMALL).
    pub(super) fn new(
        m: &Model,
        d: &Data,
        store: &'a mut Large,
        (large, lgeoms): (usize, std::ops::Range<usize>),
        sgeoms: std::ops::Range<usize>,
    ) -> Self {
        let (mat, pos) = (row::<9>(d.xmat, large), row::<3>(d.xpos, large));
        if store.body != large {
            store.boxes.fill(m, d, lgeoms.clone(), &mat, &pos);
            store.body = large;
        }
        let mut small = Boxes::default();
        small.fill(m, d, sgeoms.clone(), &mat, &pos);
        let n = sgeoms.len();
        let margins = m.geom_margin();
        let every =
            (small.boxed[0] == (1u64 << n) - 1) && sgeoms.clone().all(|g| !margins[g].is_nan());
        let all = every.then(|| {
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            let (mut s, mut margin) = (0.0f64, f64::NEG_INFINITY);
            for i in 0..n {
                for k in 0..3 {
                    lo[k] = lo[k].min(small.c[k][i] - small.w[k][i]);
                    hi[k] = hi[k].max(small.c[k][i] + small.w[k][i]);
                }
                s = s.max(small.slack[i]);
                margin = margin.max(margins[sgeoms.start + i]);
            }
            let c = std::array::from_fn(|k| 0.5 * (lo[k] + hi[k]));
            let w = std::array::from_fn(|k| 0.5 * (hi[k] - lo[k]));
            // (the rounding of the bounds and their halves)
            let s = s + 1e-9 * (0..3).map(|k| lo[k].abs() + hi[k].abs()).sum::<f64>();
            (c, w, s, margin)
        });
        Pair {
            large: store,
            start: (lgeoms.start, sgeoms.start),
            small,
            all,
        }
    }

    /// The large body's geoms of `geoms` (at most 64, bits from its start) whose boxes are not
    /// apart from the box around the small body's geoms (all where there is none).
    pub(super) fn near(
        &self,
        m: &Model,
        geoms: std::ops::Range<usize>,
        overridden: Option<f64>,
    ) -> u64 {
        let all_bits = if geoms.len() == 64 {
            u64::MAX
        } else {
            (1u64 << geoms.len()) - 1
        };
        let Some((c, w, s, smargin)) = self.all else {
            return all_bits;
        };
        let (b, margins) = (&self.large.boxes, m.geom_margin());
        let mut near = 0u64;
        for g in geoms.clone() {
            let i = g - self.start.0;
            let margin = overridden.unwrap_or(max(margins[g], smargin));
            let limit = margin + b.slack[i] + s;
            let apart = b.has_box(i)
                & !margins[g].is_nan()
                & (0..3).fold(false, |any, k| {
                    any | beyond_all(c[k] - b.c[k][i], b.w[k][i], w[k], limit)
                });
            near |= u64::from(!apart) << (g - geoms.start);
        }
        near
    }

    /// Are the large body's geom gl and the small body's geom gs apart by more than `margin`
    /// (the pair's, not NaN) along one of the frame's axes?
    pub(super) fn apart(&self, gl: usize, gs: usize, margin: f64) -> bool {
        let (i, j) = (gl - self.start.0, gs - self.start.1);
        let (b, s) = (&self.large.boxes, &self.small);
        if !b.has_box(i) || !s.has_box(j) {
            return false;
        }
        let limit = margin + b.slack[i] + s.slack[j];
        (0..3).any(|k| axis_apart(s.c[k][j] - b.c[k][i], s.w[k][j] + b.w[k][i], limit))
    }
}
