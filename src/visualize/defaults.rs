//! Default visualization structs: options, cameras, perturbation, figure.

use crate::abi::*;
use crate::math::misc::halton;
use std::os::raw::c_char;

/// Visualization flags on by default (mjVISSTRING's second column): texture, tendon,
/// rangefinder, perturbation object, static body, skin.
pub const VIS_DEFAULT_ON: [usize; 6] = [1, 7, 8, 13, 21, 22];

/// Rendering flags on by default (mjRNDSTRING's second column): shadow, reflection, skybox,
/// haze, cull face.
pub const RND_DEFAULT_ON: [usize; 5] = [0, 2, 4, 6, 9];

pub fn option() -> mjvOption {
    let mut o = mjvOption::default();
    let groups = [1, 1, 1, 0, 0, 0];
    o.geomgroup = groups;
    o.sitegroup = groups;
    o.jointgroup = groups;
    o.tendongroup = groups;
    o.actuatorgroup = groups;
    o.skingroup = groups;
    for i in VIS_DEFAULT_ON {
        o.flags[i] = 1;
    }
    o
}

pub fn camera() -> mjvCamera {
    mjvCamera {
        r#type: mjtCamera_::mjCAMERA_FREE as i32,
        fixedcamid: -1,
        trackbodyid: -1,
        lookat: [0.0; 3],
        distance: 2.0,
        azimuth: 90.0,
        elevation: -45.0,
    }
}

/// The free camera framing the model: at its center, 1.5 extents away, at the model's
/// azimuth and elevation.
pub fn free_camera(m: &mjModel) -> mjvCamera {
    mjvCamera {
        r#type: mjtCamera_::mjCAMERA_FREE as i32,
        fixedcamid: -1,
        trackbodyid: -1,
        lookat: m.stat.center,
        distance: 1.5 * m.stat.extent,
        azimuth: m.vis.global.azimuth as f64,
        elevation: m.vis.global.elevation as f64,
    }
}

pub fn perturb() -> mjvPerturb {
    mjvPerturb {
        skinselect: -1,
        refquat: [1.0, 0.0, 0.0, 0.0],
        scale: 1.0,
        ..Default::default()
    }
}

/// Line colors of a figure: eight fixed, the rest from Halton sequences.
const LINE_RGB: [[f64; 3]; 8] = [
    [1.0, 0.3, 0.3],
    [0.1, 1.0, 0.1],
    [0.3, 0.3, 1.0],
    [0.1, 1.0, 1.0],
    [1.0, 0.2, 1.0],
    [1.0, 1.0, 0.1],
    [1.0, 0.6, 0.2],
    [0.6, 0.7, 0.4],
];

fn set(dst: &mut [c_char], s: &str) {
    for (d, b) in dst.iter_mut().zip(s.bytes()) {
        *d = b as c_char;
    }
}

/// Fills `fig` with the default figure (every other field zero).
pub fn figure(fig: &mut mjvFigure) {
    // SAFETY: mjvFigure is plain data; all zeros is its cleared state.
    *fig = unsafe { std::mem::zeroed() };
    fig.highlightid = -1;
    fig.flg_legend = 1;
    fig.flg_ticklabel = [1, 1];
    fig.flg_extend = 1;
    fig.linewidth = 3.0;
    fig.gridwidth = 1.0;
    fig.gridsize = [2, 2];
    fig.gridrgb = [0.4; 3];
    fig.figurergba[3] = 1.0;
    fig.panergba[3] = 1.0;
    fig.legendrgba[3] = 0.3;
    fig.textrgb = [1.0; 3];
    fig.range = [[0.0, 1.0], [0.0, 1.0]];
    set(&mut fig.xformat, "%.0f");
    set(&mut fig.yformat, "%.2g");
    set(&mut fig.minwidth, "XXX");
    for (n, rgb) in fig.linergb.iter_mut().enumerate() {
        *rgb = if n < 8 {
            LINE_RGB[n].map(|x| x as f32)
        } else {
            // float constants promoted to double with the Halton value, rounded at the end
            [2, 3, 5].map(|b| (0.1f32 as f64 + 0.8f32 as f64 * halton(n as i32, b)) as f32)
        };
    }
}
