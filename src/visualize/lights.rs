//! The scene's lights (mjv_makeLights): the headlight, then the model's active lights.

use crate::abi::*;
use crate::engine::{Data, Model};
use crate::visualize::geom::{arr, n2f};

pub fn make_lights(m: &Model, d: &Data, scn: &mut mjvScene) {
    scn.nlight = 0;
    let head = &m.raw.vis.headlight;
    if head.active != 0 {
        scn.lights[0] = mjvLight {
            headlight: 1,
            directional: 1,
            castshadow: 0,
            ambient: head.ambient,
            diffuse: head.diffuse,
            specular: head.specular,
            ..Default::default()
        };
        scn.nlight = 1;
    }
    for i in 0..m.raw.nlight as usize {
        if scn.nlight as usize >= mjMAXLIGHT {
            break;
        }
        if m.light_active()[i] == 0 {
            continue;
        }
        let directional = m.light_directional()[i];
        let mut light = mjvLight {
            directional,
            castshadow: m.light_castshadow()[i],
            ambient: arr(&m.light_ambient()[3 * i..]),
            diffuse: arr(&m.light_diffuse()[3 * i..]),
            specular: arr(&m.light_specular()[3 * i..]),
            pos: n2f(&d.light_xpos[3 * i..]),
            dir: n2f(&d.light_xdir[3 * i..]),
            ..Default::default()
        };
        if directional == 0 {
            light.attenuation = arr(&m.light_attenuation()[3 * i..]);
            light.exponent = m.light_exponent()[i];
            light.cutoff = m.light_cutoff()[i];
        }
        scn.lights[scn.nlight as usize] = light;
        scn.nlight += 1;
    }
}
