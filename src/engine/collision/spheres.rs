//! Spheres around all of a body's geoms (their bounding spheres, centred at the body's origin):
//! a body pair, or a geom and a body, whose spheres are apart beyond rounding has every geom
//! pair apart by mj_collideGeoms's own bounding-sphere test.

use super::margin_override;
use crate::engine::linalg::row;
use crate::engine::{Data, Model};
use crate::math::misc::max;
use crate::math::vec3::{dot3, sub3};
use crate::math::Vec3;

/// Relative slack of the body-sphere tests: far above the rounding of the sums and distances.
const SLACK: f64 = 1e-9;

/// Sphere around the bounding spheres of a body's geoms, centred at the body's origin:
/// (centre, radius, largest geom margin). None when some geom has no bounding sphere (planes
/// and height fields) or a value is not finite (f64::max would pass over NaN).
#[inline(always)]
pub(super) fn body_sphere(m: &Model, d: &Data, b: usize) -> Option<(Vec3, f64, f64)> {
    let c = row::<3>(d.xpos, b);
    let (mut radius, mut margin, mut ok) = (0.0f64, f64::NEG_INFINITY, true);
    for g in m.body_geoms(b) {
        let (r, gmargin) = (m.geom_rbound()[g], m.geom_margin()[g]);
        let dif = sub3(&row(d.geom_xpos, g), &c);
        let extent = dot3(&dif, &dif).sqrt() + r;
        ok &= r > 0.0 && extent.is_finite() && gmargin.is_finite();
        radius = radius.max(extent);
        margin = margin.max(gmargin);
    }
    ok.then_some((c, radius, margin))
}

/// Body spheres, each computed when first asked for, in 5 slots per body of scratch from the
/// arena: centre, radius (NaN: not yet known, infinite: none), margin.
pub(super) struct Spheres<'a>(&'a mut [f64]);

impl<'a> Spheres<'a> {
    /// Over `buf` (5 slots per body), every body's sphere unknown.
    pub(super) fn new(buf: &'a mut [f64]) -> Self {
        for s in buf.chunks_exact_mut(5) {
            s[3] = f64::NAN;
        }
        Spheres(buf)
    }

    pub(super) fn get(&mut self, m: &Model, d: &Data, b: usize) -> Option<(Vec3, f64, f64)> {
        let s = &mut self.0[5 * b..5 * b + 5];
        if s[3].is_nan() {
            let (c, radius, margin) =
                body_sphere(m, d, b).unwrap_or(([0.0; 3], f64::INFINITY, 0.0));
            s.copy_from_slice(&[c[0], c[1], c[2], radius, margin]);
        }
        (s[3] != f64::INFINITY).then(|| ([s[0], s[1], s[2]], s[3], s[4]))
    }
}

/// Is a sphere (centre p, radius r) apart from every geom of a body sphere (c, radius, margin)
/// by their own sphere test, whatever geom: beyond r + radius + the margin, with slack?
pub(super) fn beyond(
    m: &Model,
    p: &Vec3,
    r: f64,
    margin: f64,
    (c, radius, bmargin): (Vec3, f64, f64),
) -> bool {
    let sum = |v: &Vec3| v.iter().map(|x| x.abs()).sum::<f64>();
    spheres_beyond(
        margin_override(m),
        (*p, r, margin, sum(p)),
        (c, radius, bmargin, sum(&c)),
    )
}

/// `beyond` of two spheres given with the sums of their centres' magnitudes (centre, radius,
/// margin, sum), the margin override given.
#[inline(always)]
pub(super) fn spheres_beyond(
    overridden: Option<f64>,
    (p, r, margin, psum): (Vec3, f64, f64, f64),
    (c, radius, bmargin, csum): (Vec3, f64, f64, f64),
) -> bool {
    // (a NaN margin, which collide_geoms may take, makes no test: bmargin is finite)
    let margin = overridden.unwrap_or(max(bmargin, margin));
    let reach = r + radius + margin;
    let bound = reach + SLACK * (r.abs() + radius + margin.abs() + psum + csum);
    let dif = sub3(&p, &c);
    bound > 0.0 && dot3(&dif, &dif) > bound * bound
}
