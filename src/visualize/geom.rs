//! One abstract geom: defaults (mjv_initGeom), connectors between two points
//! (mjv_makeConnector), materials, labels and the colors of selection and perturbation.

use crate::abi::cstr::set_cstr;
use crate::abi::*;
use crate::engine::support::id2name;
use crate::engine::Model;
use crate::math::misc::type2str;
use crate::math::quat::{quat2mat, quat_z2vec};
use crate::math::vec3::norm3;
use crate::math::Vec3;

pub const GEOM_PLANE: i32 = mjtGeom_::mjGEOM_PLANE as i32;
pub const GEOM_HFIELD: i32 = mjtGeom_::mjGEOM_HFIELD as i32;
pub const GEOM_SPHERE: i32 = mjtGeom_::mjGEOM_SPHERE as i32;
pub const GEOM_CAPSULE: i32 = mjtGeom_::mjGEOM_CAPSULE as i32;
pub const GEOM_CYLINDER: i32 = mjtGeom_::mjGEOM_CYLINDER as i32;
pub const GEOM_BOX: i32 = mjtGeom_::mjGEOM_BOX as i32;
pub const GEOM_MESH: i32 = mjtGeom_::mjGEOM_MESH as i32;
pub const GEOM_ARROW: i32 = mjtGeom_::mjGEOM_ARROW as i32;
pub const GEOM_ARROW1: i32 = mjtGeom_::mjGEOM_ARROW1 as i32;
pub const GEOM_ARROW2: i32 = mjtGeom_::mjGEOM_ARROW2 as i32;
pub const GEOM_LINE: i32 = mjtGeom_::mjGEOM_LINE as i32;
pub const GEOM_SKIN: i32 = mjtGeom_::mjGEOM_SKIN as i32;
pub const GEOM_LABEL: i32 = mjtGeom_::mjGEOM_LABEL as i32;
pub const GEOM_NONE: i32 = mjtGeom_::mjGEOM_NONE as i32;

pub const IDENTITY: [f64; 9] = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];

/// The larger of two numbers as C's mjMAX picks it (the second when they do not compare).
pub fn c_max<T: PartialOrd>(a: T, b: T) -> T {
    if a > b {
        a
    } else {
        b
    }
}

/// Doubles rounded to floats.
pub fn n2f<const N: usize>(v: &[f64]) -> [f32; N] {
    std::array::from_fn(|i| v[i] as f32)
}

/// The first `N` values of `v`.
pub fn arr<const N: usize, T: Copy>(v: &[T]) -> [T; N] {
    std::array::from_fn(|i| v[i])
}

/// Sets the given fields, the rest to their defaults (mjv_initGeom). Sizes of spheres,
/// capsules and cylinders expand to the three XYZ scales; no size gives 0.1 each.
pub fn init_geom(
    g: &mut mjvGeom,
    r#type: i32,
    size: Option<&[f64]>,
    pos: Option<&[f64]>,
    mat: Option<&[f64]>,
    rgba: Option<[f32; 4]>,
) {
    g.r#type = r#type;
    g.size = match size {
        Some(s) => match r#type {
            GEOM_SPHERE => [s[0] as f32; 3],
            GEOM_CAPSULE | GEOM_CYLINDER => [s[0] as f32, s[0] as f32, s[1] as f32],
            _ => n2f(s),
        },
        None => [0.1; 3],
    };
    g.pos = pos.map_or([0.0; 3], n2f);
    g.mat = n2f(mat.unwrap_or(&IDENTITY));
    g.rgba = rgba.unwrap_or([0.5, 0.5, 0.5, 1.0]);
    g.dataid = -1;
    g.texid = -1;
    g.texuniform = 0;
    g.texcoord = 0;
    g.texrepeat = [1.0, 1.0];
    g.emission = 0.0;
    g.specular = 0.5;
    g.shininess = 0.5;
    g.reflectance = 0.0;
    g.label[0] = 0;
    g.modelrbound = 0.0;
}

/// Can `type` connect two points (capsule, cylinder, arrows, line)?
pub fn is_connector(r#type: i32) -> bool {
    matches!(
        r#type,
        GEOM_CAPSULE | GEOM_CYLINDER | GEOM_ARROW | GEOM_ARROW1 | GEOM_ARROW2 | GEOM_LINE
    )
}

/// Type, size, pos and mat of a connector from `a` to `b` (mjv_makeConnector; `type` passes
/// `is_connector`): capsules and cylinders are centered with half length, arrows and lines
/// start at `a`; the z axis turns onto b-a by the smallest rotation.
pub fn make_connector(g: &mut mjvGeom, r#type: i32, width: f64, a: Vec3, b: Vec3) {
    let dif = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    g.r#type = r#type;
    g.size = [width as f32, width as f32, norm3(&dif) as f32];
    if r#type == GEOM_CAPSULE || r#type == GEOM_CYLINDER {
        g.pos = n2f(&[
            0.5 * (a[0] + b[0]),
            0.5 * (a[1] + b[1]),
            0.5 * (a[2] + b[2]),
        ]);
        g.size[2] = (g.size[2] as f64 * 0.5) as f32;
    } else {
        g.pos = n2f(&a);
    }
    g.mat = n2f(&quat2mat(&quat_z2vec(&dif)));
}

/// Material properties, color and texture of an object with material `matid` and color
/// `rgba` (the color wins unless it is the default gray); dynamic geoms take the
/// transparency map when it is on.
pub fn set_material(m: &Model, g: &mut mjvGeom, matid: i32, rgba: &[f32], flags: &[u8]) {
    if matid >= 0 {
        let id = matid as usize;
        g.texrepeat = arr(&m.mat_texrepeat()[2 * id..]);
        g.rgba = arr(&m.mat_rgba()[4 * id..]);
        g.texuniform = m.mat_texuniform()[id] as i32;
        g.emission = m.mat_emission()[id];
        g.specular = m.mat_specular()[id];
        g.shininess = m.mat_shininess()[id];
        g.reflectance = m.mat_reflectance()[id];
    } else {
        g.texrepeat = [0.0; 2];
    }
    if rgba[..4] != [0.5, 0.5, 0.5, 1.0] || matid < 0 {
        g.rgba = arr(rgba);
    }
    if flags[mjtVisFlag_::mjVIS_TEXTURE as usize] != 0 && matid >= 0 {
        g.texid = m.mat_texid()[matid as usize];
    }
    if flags[mjtVisFlag_::mjVIS_TRANSPARENT as usize] != 0
        && g.category == mjtCatBit_::mjCAT_DYNAMIC as i32
    {
        g.rgba[3] *= m.raw.vis.map.alpha;
    }
}

/// The object's name, else its type and number, else its number.
pub fn label(m: &Model, objtype: mjtObj_, id: usize, g: &mut mjvGeom) {
    let text = match id2name(m, objtype as i32, id as i32) {
        Some(adr) => {
            let names = &m.names()[adr..];
            let n = names.iter().position(|&c| c == 0).unwrap_or(names.len());
            names[..n].iter().map(|&c| c as u8).collect::<Vec<u8>>()
        }
        None => match type2str(objtype as i32) {
            Some(t) => format!("{t} {id}").into_bytes(),
            None => id.to_string().into_bytes(),
        },
    };
    // at most 99 characters, the last byte of the label left as it was
    set_cstr(&mut g.label[..99], &text[..text.len().min(99)]);
}

/// Glow of the selected object.
pub fn mark_selected(m: &Model, g: &mut mjvGeom) {
    g.emission += m.raw.vis.global.glow;
}

/// Color of a perturbation object: red and green channels from `reference` as the main
/// (`active`) and secondary (`active2`) perturbation show.
pub fn mix_color(reference: &[f32; 4], active: bool, active2: bool) -> [f32; 4] {
    let mut r = [0.0; 4];
    r[0] = if active { reference[0] } else { 0.0 };
    if active2 {
        r[0] = c_max(r[0], reference[1]);
    }
    r[1] = if active { reference[1] } else { 0.0 };
    if active2 {
        r[1] = c_max(r[1], reference[0]);
    }
    r[2] = reference[2];
    r[3] = reference[3];
    r
}

/// Static (welded to the world, not mocap) or dynamic.
pub fn body_category(m: &Model, body: usize) -> i32 {
    if m.body_weldid()[body] == 0 && m.body_mocapid()[body] == -1 {
        mjtCatBit_::mjCAT_STATIC as i32
    } else {
        mjtCatBit_::mjCAT_DYNAMIC as i32
    }
}
