//! Fluid forces on bodies (part of mj_passive): the inertia-box model, and the per-geom ellipsoid
//! model for bodies with a geom whose fluid interaction is switched on (geom_fluid[0] > 0).

use super::forward::apply_ft;
use super::linalg::{max, min};
use super::{Data, EngineError, Model, MINVAL};
use crate::abi::{mjNFLUID, mjtGeom_};
use crate::math::*;

/// Fluid coefficients of one geom, as stored in geom_fluid.
pub struct GeomFluid {
    pub interaction: f64,
    pub blunt_drag: f64,
    pub slender_drag: f64,
    pub ang_drag: f64,
    pub kutta_lift: f64,
    pub magnus_lift: f64,
    pub virtual_mass: Vec3,
    pub virtual_inertia: Vec3,
}

impl GeomFluid {
    pub fn read(m: &Model, g: usize) -> Self {
        let c = &m.geom_fluid()[mjNFLUID * g..mjNFLUID * (g + 1)];
        GeomFluid {
            interaction: c[0],
            blunt_drag: c[1],
            slender_drag: c[2],
            ang_drag: c[3],
            kutta_lift: c[4],
            magnus_lift: c[5],
            virtual_mass: v3(&c[6..]),
            virtual_inertia: v3(&c[9..]),
        }
    }
}

/// Does any geom of body `b` use the ellipsoid model?
pub fn uses_ellipsoid(m: &Model, b: usize) -> bool {
    m.body_geoms(b).any(|g| m.geom_fluid()[mjNFLUID * g] > 0.0)
}

/// Semi-axes of the ellipsoid that stands for geom `g` (mju_geomSemiAxes).
pub fn geom_semi_axes(m: &Model, g: usize) -> Vec3 {
    let s = &m.geom_size()[3 * g..3 * g + 3];
    match m.geom_type()[g] {
        t if t == mjtGeom_::mjGEOM_SPHERE as i32 => [s[0], s[0], s[0]],
        t if t == mjtGeom_::mjGEOM_CAPSULE as i32 => [s[0], s[0], s[1] + s[0]],
        t if t == mjtGeom_::mjGEOM_CYLINDER as i32 => [s[0], s[0], s[1]],
        _ => [s[0], s[1], s[2]],
    }
}

/// Velocity of the frame (pos, mat) on body `b` relative to the wind, in that frame.
pub fn local_fluid_velocity(m: &Model, d: &Data, b: usize, pos: &Vec3, mat: &Mat3) -> Vec6 {
    let com = v3(&d.subtree_com[3 * m.body_rootid()[b] as usize..]);
    let cvel = v6(&d.cvel[6 * b..]);
    let mut lvel = transform_spatial(&cvel, false, pos, &com, Some(mat));
    let wind = m.raw.opt.wind;
    let w6 = [0.0, 0.0, 0.0, wind[0], wind[1], wind[2]];
    let lwind = transform_spatial(&w6, false, pos, &com, Some(mat));
    for k in 3..6 {
        lvel[k] -= lwind[k];
    }
    lvel
}

/// Box dimensions with the inertia of body `b` (equal mass).
pub fn inertia_box(m: &Model, b: usize) -> Vec3 {
    let i = &m.body_inertia()[3 * b..3 * b + 3];
    let mass = m.body_mass()[b];
    let side = |a: f64, c: f64, e: f64| (max(MINVAL, a + c - e) / mass * 6.0).sqrt();
    [
        side(i[1], i[2], i[0]),
        side(i[0], i[2], i[1]),
        side(i[0], i[1], i[2]),
    ]
}

/// Local force [torque; force] of the inertia-box model for local velocity `lvel`.
fn box_force(m: &Model, bx: &Vec3, lvel: &Vec6) -> Vec6 {
    let (rho, visc) = (m.raw.opt.density, m.raw.opt.viscosity);
    let mut f = [0.0; 6];
    if visc > 0.0 {
        let diam = (bx[0] + bx[1] + bx[2]) / 3.0;
        let sa = -PI * diam * diam * diam * visc;
        let sl = -3.0 * PI * diam * visc;
        for k in 0..3 {
            f[k] = lvel[k] * sa;
            f[3 + k] = lvel[3 + k] * sl;
        }
    }
    if rho > 0.0 {
        f[3] -= 0.5 * rho * bx[1] * bx[2] * lvel[3].abs() * lvel[3];
        f[4] -= 0.5 * rho * bx[0] * bx[2] * lvel[4].abs() * lvel[4];
        f[5] -= 0.5 * rho * bx[0] * bx[1] * lvel[5].abs() * lvel[5];
        let p4 = |x: f64| x * x * x * x;
        f[0] -= rho * bx[0] * (p4(bx[1]) + p4(bx[2])) * lvel[0].abs() * lvel[0] / 64.0;
        f[1] -= rho * bx[1] * (p4(bx[0]) + p4(bx[2])) * lvel[1].abs() * lvel[1] / 64.0;
        f[2] -= rho * bx[2] * (p4(bx[0]) + p4(bx[1])) * lvel[2].abs() * lvel[2] / 64.0;
    }
    f
}

/// Force of fluid mass carried along with the body (accelerations ignored).
fn added_mass_force(lvel: &Vec6, rho: f64, c: &GeomFluid, f: &mut Vec6) {
    let ang = v3(&lvel[..3]);
    let lin = v3(&lvel[3..]);
    let vm = &c.virtual_mass;
    let vi = &c.virtual_inertia;
    let lin_mom = [
        rho * vm[0] * lin[0],
        rho * vm[1] * lin[1],
        rho * vm[2] * lin[2],
    ];
    let ang_mom = [
        rho * vi[0] * ang[0],
        rho * vi[1] * ang[1],
        rho * vi[2] * ang[2],
    ];
    let force = cross(&lin_mom, &ang);
    let t1 = cross(&lin_mom, &lin);
    let t2 = cross(&ang_mom, &ang);
    for k in 0..3 {
        f[k] += t1[k];
    }
    for k in 0..3 {
        f[k] += t2[k];
    }
    for k in 0..3 {
        f[3 + k] += force[k];
    }
}

#[inline]
pub fn pow2(x: f64) -> f64 {
    x * x
}

#[inline]
pub fn pow4(x: f64) -> f64 {
    (x * x) * (x * x)
}

/// Largest moment of inertia (up to density) of the ellipsoid `s` about axis `dir`.
#[inline]
pub fn ellipsoid_max_moment(s: &Vec3, dir: usize) -> f64 {
    let (d0, d1, d2) = (s[dir], s[(dir + 1) % 3], s[(dir + 2) % 3]);
    8.0 / 15.0 * PI * d0 * pow4(max(d1, d2))
}

/// Lift (Magnus, Kutta-Joukowski) and drag (viscous and quadratic) on an ellipsoid.
fn viscous_force(lvel: &Vec6, rho: f64, visc: f64, s: &Vec3, c: &GeomFluid, f: &mut Vec6) {
    let ang = v3(&lvel[..3]);
    let lin = v3(&lvel[3..]);
    let volume = 4.0 / 3.0 * PI * s[0] * s[1] * s[2];
    let d_max = max(max(s[0], s[1]), s[2]);
    let d_min = min(min(s[0], s[1]), s[2]);
    let d_mid = s[0] + s[1] + s[2] - d_max - d_min;
    let a_max = PI * d_max * d_mid;

    let mut magnus = cross(&ang, &lin);
    for x in magnus.iter_mut() {
        *x *= c.magnus_lift * rho * volume;
    }

    let proj_denom = pow4(s[1] * s[2]) * pow2(lin[0])
        + pow4(s[2] * s[0]) * pow2(lin[1])
        + pow4(s[0] * s[1]) * pow2(lin[2]);
    let proj_num =
        pow2(s[1] * s[2] * lin[0]) + pow2(s[2] * s[0] * lin[1]) + pow2(s[0] * s[1] * lin[2]);
    let a_proj = PI * (proj_denom / max(MINVAL, proj_num)).sqrt();
    let normal = [
        pow2(s[1] * s[2]) * lin[0],
        pow2(s[2] * s[0]) * lin[1],
        pow2(s[0] * s[1]) * lin[2],
    ];
    let cos_alpha = proj_num / max(MINVAL, norm3(&lin) * proj_denom);
    let mut circ = cross(&normal, &lin);
    for x in circ.iter_mut() {
        *x *= c.kutta_lift * rho * cos_alpha * a_proj;
    }
    let kutta = cross(&circ, &lin);

    let eq_d = 2.0 / 3.0 * (s[0] + s[1] + s[2]);
    let lin_visc_force = 3.0 * PI * eq_d;
    let lin_visc_torque = PI * eq_d * eq_d * eq_d;
    let i_max = 8.0 / 15.0 * PI * d_mid * pow4(d_max);
    let ii = [
        ellipsoid_max_moment(s, 0),
        ellipsoid_max_moment(s, 1),
        ellipsoid_max_moment(s, 2),
    ];
    let mom_visc = [
        ang[0] * (c.ang_drag * ii[0] + c.slender_drag * (i_max - ii[0])),
        ang[1] * (c.ang_drag * ii[1] + c.slender_drag * (i_max - ii[1])),
        ang[2] * (c.ang_drag * ii[2] + c.slender_drag * (i_max - ii[2])),
    ];
    let drag_lin = visc * lin_visc_force
        + rho * norm3(&lin) * (a_proj * c.blunt_drag + c.slender_drag * (a_max - a_proj));
    let drag_ang = visc * lin_visc_torque + rho * norm3(&mom_visc);
    for k in 0..3 {
        f[k] -= drag_ang * ang[k];
    }
    for k in 0..3 {
        f[3 + k] += magnus[k] + kutta[k] - drag_lin * lin[k];
    }
}

/// Rotates the local [torque; force] by `mat` and applies it at `pos` on body `b`.
fn apply_local(
    m: &Model,
    d: &mut Data,
    lfrc: &Vec6,
    mat: &Mat3,
    pos: &Vec3,
    b: usize,
) -> Result<(), EngineError> {
    let torque = mul_mat_vec3(mat, &v3(&lfrc[..3]));
    let force = mul_mat_vec3(mat, &v3(&lfrc[3..]));
    let qfrc = std::mem::take(&mut d.qfrc_passive);
    let r = apply_ft(m, d, Some(&force), Some(&torque), pos, b, qfrc);
    d.qfrc_passive = qfrc;
    r
}

/// Adds the fluid forces of all bodies to qfrc_passive (density or viscosity > 0).
#[inline]
pub fn fluid(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    if !(m.raw.opt.viscosity > 0.0 || m.raw.opt.density > 0.0) {
        return Ok(());
    }
    fluid_bodies(m, d)
}

#[inline(never)]
fn fluid_bodies(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    for b in 1..m.raw.nbody as usize {
        if m.body_mass()[b] < MINVAL {
            continue;
        }
        if uses_ellipsoid(m, b) {
            ellipsoid_fluid(m, d, b)?;
        } else {
            inertia_box_fluid(m, d, b)?;
        }
    }
    Ok(())
}

/// Inertia-box model of body `b` (mj_inertiaBoxFluidModel).
fn inertia_box_fluid(m: &Model, d: &mut Data, b: usize) -> Result<(), EngineError> {
    let bx = inertia_box(m, b);
    let pos = v3(&d.xipos[3 * b..]);
    let mat = m9(&d.ximat[9 * b..]);
    let lvel = local_fluid_velocity(m, d, b, &pos, &mat);
    let lfrc = box_force(m, &bx, &lvel);
    apply_local(m, d, &lfrc, &mat, &pos, b)
}

/// Ellipsoid model of the geoms of body `b` (mj_ellipsoidFluidModel).
fn ellipsoid_fluid(m: &Model, d: &mut Data, b: usize) -> Result<(), EngineError> {
    for g in m.body_geoms(b) {
        let s = geom_semi_axes(m, g);
        let c = GeomFluid::read(m, g);
        if c.interaction == 0.0 {
            continue;
        }
        let pos = v3(&d.geom_xpos[3 * g..]);
        let mat = m9(&d.geom_xmat[9 * g..]);
        let lvel = local_fluid_velocity(m, d, b, &pos, &mat);
        let mut lfrc = [0.0; 6];
        added_mass_force(&lvel, m.raw.opt.density, &c, &mut lfrc);
        viscous_force(
            &lvel,
            m.raw.opt.density,
            m.raw.opt.viscosity,
            &s,
            &c,
            &mut lfrc,
        );
        for x in lfrc.iter_mut() {
            *x *= c.interaction;
        }
        apply_local(m, d, &lfrc, &mat, &pos, b)?;
    }
    Ok(())
}
