//! Face-axis tests of a body pair's geoms in the frame of one of the two bodies. A geom with no
//! rotation of its own has its box's face axes along its body's axes: a geom of the other body
//! farther from that box than the margin along one of them gives no contact (the test of
//! `bounds::apart`, with its slack and more). A geom is put in the frame (one rotation) when a
//! pair first needs it; each pair's test is then a few subtractions.

use super::bounds::extent;
use crate::engine::linalg::{row, row_ref};
use crate::engine::{Data, Model};
use crate::math::vec3::{mul_mat3t_mat, mul_mat_t_vec3, sub3};
use crate::math::{Mat3, Vec3};

/// The most geoms of a body that a frame holds.
pub(super) const MAX_GEOMS: usize = 32;

/// Geoms of one body in a frame: centres and half-widths along its axes, and the slack of
/// their tests.
#[derive(Default)]
struct Geoms {
    c: [[f64; MAX_GEOMS]; 3],
    r: [[f64; MAX_GEOMS]; 3],
    slack: [f64; MAX_GEOMS],
}

/// A body pair in the frame of one of its bodies, filled a geom at a time as pairs need them:
/// that body's geoms with no rotation of their own with their half-extents, the other body's
/// with the half-widths of their boxes along the frame's axes.
#[derive(Default)]
pub(super) struct Frame {
    /// First geom of the frame's body and of the other body.
    start: (usize, usize),
    mat: Mat3,
    pos: Vec3,
    other_mat: Mat3,
    /// |the other body's rotation in this frame|, for its geoms with none of their own.
    other_rot: Mat3,
    /// Bits: own geoms tested for alignment, own geoms aligned (and filled in), other geoms
    /// filled in.
    own_known: u64,
    own_aligned: u64,
    other_filled: u64,
    own: Geoms,
    other: Geoms,
}

/// The frames of the two bodies of a pair.
#[derive(Default)]
pub(super) struct Frames(pub(super) [Frame; 2]);

impl Frames {
    /// Empties both frames for bodies b1 and b2, whose geoms start at `start1` and `start2`
    /// (at most MAX_GEOMS each).
    pub(super) fn reset(
        &mut self,
        d: &Data,
        (b1, b2): (usize, usize),
        (start1, start2): (usize, usize),
    ) {
        let [f1, f2] = &mut self.0;
        f1.reset(d, (b1, b2), (start1, start2));
        f2.reset(d, (b2, b1), (start2, start1));
    }
}

impl Frame {
    /// First geom of the frame's body and of the other body.
    pub(super) fn start(&self) -> (usize, usize) {
        self.start
    }

    fn reset(&mut self, d: &Data, (b, b_other): (usize, usize), start: (usize, usize)) {
        self.start = start;
        self.mat = row(d.xmat, b);
        self.pos = row(d.xpos, b);
        self.other_mat = row(d.xmat, b_other);
        self.other_rot = mul_mat3t_mat(&self.mat, &self.other_mat).map(f64::abs);
        (self.own_known, self.own_aligned, self.other_filled) = (0, 0, 0);
    }

    /// Geom g's centre in the frame, and the slack of its tests from its size.
    fn centre(&self, d: &Data, g: usize, size: f64) -> (Vec3, f64) {
        let c = mul_mat_t_vec3(&self.mat, &sub3(row_ref(d.geom_xpos, g), &self.pos));
        (c, slack(size, &c))
    }

    /// Finds whether own geom i is aligned with the frame (with a box along its axes), and
    /// fills it in if so.
    #[inline(never)]
    fn learn_own(&mut self, m: &Model, d: &Data, i: usize) {
        let bit = 1u64 << i;
        self.own_known |= bit;
        let g = self.start.0 + i;
        if same(row_ref(d.geom_xmat, g), &self.mat) {
            if let Some(h) = box_of(m, g) {
                let (c, slack) = self.centre(d, g, h[0] + h[1] + h[2]);
                store(&mut self.own, i, c, h, slack);
                self.own_aligned |= bit;
            }
        }
    }

    /// Fills in the other body's geom j; one without a box (a plane, a height field, an
    /// edited size) gets widths no test passes.
    #[inline(never)]
    fn fill_other(&mut self, m: &Model, d: &Data, j: usize) {
        self.other_filled |= 1u64 << j;
        let g = self.start.1 + j;
        let (r, size) = match box_of(m, g) {
            Some(h) => {
                let geom_mat = row_ref::<9>(d.geom_xmat, g);
                let rot = if same(geom_mat, &self.other_mat) {
                    self.other_rot
                } else {
                    mul_mat3t_mat(&self.mat, geom_mat).map(f64::abs)
                };
                let width =
                    |k: usize| h[0] * rot[3 * k] + h[1] * rot[3 * k + 1] + h[2] * rot[3 * k + 2];
                ([width(0), width(1), width(2)], h[0] + h[1] + h[2])
            }
            None => ([f64::INFINITY; 3], 0.0),
        };
        let (c, slack) = self.centre(d, g, size);
        store(&mut self.other, j, c, r, slack);
    }

    /// Is the frame body's geom i (of its range) farther than `margin` from the other body's
    /// geom j along one of the frame's axes, beyond the slack?
    #[inline(always)]
    pub(super) fn apart(&mut self, m: &Model, d: &Data, i: usize, j: usize, margin: f64) -> bool {
        if self.own_known & (1 << i) == 0 {
            self.learn_own(m, d, i);
        }
        if self.own_aligned & (1 << i) == 0 {
            return false;
        }
        if self.other_filled & (1 << j) == 0 {
            self.fill_other(m, d, j);
        }
        let (a, b) = (&self.own, &self.other);
        let limit = margin + a.slack[i] + b.slack[j];
        (0..3).any(|k| axis_apart(b.c[k][j] - a.c[k][i], a.r[k][i] + b.r[k][j], limit))
    }
}

/// Slack of a geom's tests, from its size (the sum of its half-extents) and centre in the
/// frame: far above the rounding of the rotation and of the colliders' own tests.
pub(super) fn slack(size: f64, c: &Vec3) -> f64 {
    1e-6 * size + 1e-9 * (c[0].abs() + c[1].abs() + c[2].abs())
}

/// Are two geoms whose centres lie `dif` apart along an axis, and whose half-widths there sum
/// to `widths`, apart by more than `limit` (the margin and the slacks) and 1e-7 / the centres'
/// distance (the tolerance of `bounds::apart`; the distance is at least |dif|)?
#[inline(always)]
pub(super) fn axis_apart(dif: f64, widths: f64, limit: f64) -> bool {
    let dif = dif.abs();
    let excess = dif - widths - limit;
    excess > 0.0 && excess * dif > 1e-7
}

/// Are the two rotations equal (each entry, with no early exit)?
#[inline(always)]
fn same(a: &Mat3, b: &Mat3) -> bool {
    a.iter().zip(b).fold(true, |all, (x, y)| all & (x == y))
}

pub(super) fn box_of(m: &Model, g: usize) -> Option<Vec3> {
    extent(
        m.geom_type()[g],
        row_ref(m.geom_size(), g),
        m.geom_rbound()[g],
    )
}

fn store(s: &mut Geoms, i: usize, c: Vec3, r: Vec3, slack: f64) {
    for k in 0..3 {
        s.c[k][i] = c[k];
        s.r[k][i] = r[k];
    }
    s.slack[i] = slack;
}
