//! Compilation of single objects: frames, joints, geom mass and inertia, body inertial frame.

use super::frame::*;
use super::spec::*;
use super::CError;

/// Geom types (mjtGeom).
pub const PLANE: i32 = 0;
pub const SPHERE: i32 = 2;
pub const CAPSULE: i32 = 3;
pub const ELLIPSOID: i32 = 4;
pub const CYLINDER: i32 = 5;
pub const BOX: i32 = 6;
pub const MESH: i32 = 7;

/// Number of size parameters per geom type.
const GEOM_NSIZE: [usize; 8] = [3, 0, 1, 2, 3, 2, 3, 0];

pub struct Settings<'a> {
    pub degree: bool,
    pub eulerseq: &'a [u8; 3],
}

/// Applies the alternative orientation specs to `quat` (and `inertia` for fullinertia).
pub fn alt_set(
    alt: &Alt,
    quat: &mut [f64; 4],
    inertia: Option<&mut [f64; 3]>,
    s: &Settings,
) -> Result<(), &'static str> {
    let mut alt = *alt;
    if defined(alt.axisangle[0]) {
        if s.degree {
            alt.axisangle[3] = alt.axisangle[3] / 180.0 * std::f64::consts::PI;
        }
        if normalize(&mut alt.axisangle[..3]) < EPS {
            return Err("axisangle too small");
        }
        let ang2 = alt.axisangle[3] / 2.0;
        *quat = [
            ang2.cos(),
            ang2.sin() * alt.axisangle[0],
            ang2.sin() * alt.axisangle[1],
            ang2.sin() * alt.axisangle[2],
        ];
    }
    if defined(alt.xyaxes[0]) {
        let (x, y) = alt.xyaxes.split_at_mut(3);
        if normalize(x) < EPS {
            return Err("xaxis too small");
        }
        let d = dot3(x, y);
        for i in 0..3 {
            y[i] -= x[i] * d;
        }
        if normalize(y) < EPS {
            return Err("yaxis too small");
        }
        let mut z = cross(x, y);
        if normalize(&mut z) < EPS {
            return Err("cross(xaxis, yaxis) too small");
        }
        *quat = frame2quat(x, y, &z);
    }
    if defined(alt.zaxis[0]) {
        if normalize(&mut alt.zaxis) < EPS {
            return Err("zaxis too small");
        }
        *quat = z2quat(&alt.zaxis);
    }
    if defined(alt.fullinertia[0]) {
        let f = &alt.fullinertia;
        let full = [f[0], f[3], f[4], f[3], f[1], f[5], f[4], f[5], f[2]];
        let (eigval, q) = eig3(&full);
        *quat = q;
        if let Some(inertia) = inertia {
            *inertia = eigval;
        }
        if eigval[2] < EPS {
            return Err("inertia must have positive eigenvalues");
        }
    }
    if defined(alt.euler[0]) {
        if s.degree {
            for e in alt.euler.iter_mut() {
                *e = *e / 180.0 * std::f64::consts::PI;
            }
        }
        *quat = [1.0, 0.0, 0.0, 0.0];
        for i in 0..3 {
            let half = alt.euler[i] / 2.0;
            let mut rot = [half.cos(), 0.0, 0.0, 0.0];
            let sa = half.sin();
            match s.eulerseq[i] {
                b'x' | b'X' => rot[1] = sa,
                b'y' | b'Y' => rot[2] = sa,
                b'z' | b'Z' => rot[3] = sa,
                _ => return Err("euler sequence can only contain x, y, z, X, Y, Z"),
            }
            *quat = if s.eulerseq[i].is_ascii_lowercase() {
                mulquat_unit(quat, &rot)
            } else {
                mulquat_unit(&rot, quat)
            };
        }
        normalize(quat);
    }
    Ok(())
}

fn check_size(size: &[f64; 3], kind: i32, what: &str, name: &str, id: usize) -> Result<(), String> {
    if kind == PLANE {
        if size[2] <= 0.0 {
            return Err(format!(
                "plane size(3) must be positive in object '{name}' (id = {id})"
            ));
        }
    } else if size[..GEOM_NSIZE[kind as usize]].iter().any(|&s| s <= 0.0) {
        let _ = what;
        return Err(format!(
            "sizes must be positive in object '{name}' (id = {id})"
        ));
    }
    Ok(())
}

/// Pos, quat and size from `fromto`.
fn from_to(
    ft: &[f64; 6],
    kind: i32,
    size: &mut [f64; 3],
    pos: &mut [f64; 3],
) -> Result<[f64; 4], ()> {
    let mut vec = [ft[0] - ft[3], ft[1] - ft[4], ft[2] - ft[5]];
    size[1] = normalize(&mut vec) / 2.0;
    if size[1] < EPS {
        return Err(());
    }
    if kind == ELLIPSOID || kind == BOX {
        size[2] = size[1];
        size[1] = size[0];
    }
    *pos = [
        (ft[0] + ft[3]) / 2.0,
        (ft[1] + ft[4]) / 2.0,
        (ft[2] + ft[5]) / 2.0,
    ];
    Ok(z2quat(&vec))
}

/// A compiled geom: frame in the body, mass properties.
pub struct GeomOut {
    pub pos: [f64; 3],
    pub quat: [f64; 4],
    pub size: [f64; 3],
    pub mass: f64,
    pub inertia: [f64; 3],
    /// geom_fluid: switch, 5 coefficients, virtual mass (3), virtual inertia (3)
    pub fluid: [f64; 12],
    /// a mesh geom keeps its mesh (geom_dataid); a primitive fitted to a mesh does not
    pub mesh_kept: bool,
}

/// Added-mass coefficient of an ellipsoid with semi-axes (dx, dy, dz) along x, by 15-point
/// Gauss-Kronrod quadrature over l in [0, inf) mapped through l = x^3/(1-x)^2.
fn added_mass_kappa(dx: f64, dy: f64, dz: f64) -> f64 {
    const W: [f64; 15] = [
        0.01146766, 0.03154605, 0.05239501, 0.07032663, 0.08450236, 0.09517529, 0.10221647,
        0.10474107, 0.10221647, 0.09517529, 0.08450236, 0.07032663, 0.05239501, 0.03154605,
        0.01146766,
    ];
    const L: [f64; 15] = [
        7.865151709349917e-08,
        1.7347976913907274e-05,
        0.0003548008144506193,
        0.002846636252924549,
        0.014094260903596077,
        0.053063261727396636,
        0.17041978741317773,
        0.5,
        1.4036301548686991,
        3.9353484827022642,
        11.644841677041734,
        39.53187807410903,
        177.5711362220801,
        1429.4772912937397,
        54087.416549217705,
    ];
    const D: [f64; 15] = [
        5.538677720489877e-05,
        0.002080868285293228,
        0.016514126520723166,
        0.07261900344370877,
        0.23985243401862602,
        0.6868318249020725,
        1.8551129519182894,
        5.0,
        14.060031152313941,
        43.28941239611009,
        156.58546376397112,
        747.9826085305024,
        5827.4042950027115,
        116754.0197944512,
        25482945.327264845,
    ];
    let (ix, iy, iz) = (1.0 / (dx * dx), 1.0 / (dy * dy), 1.0 / (dz * dz));
    let scale = (dx * dx * dx * dy * dz).powf(0.4);
    let mut kappa = 0.0;
    for i in 0..15 {
        let lambda = scale * L[i];
        let denom = (1.0 + lambda * ix)
            * ((1.0 + lambda * ix) * (1.0 + lambda * iy) * (1.0 + lambda * iz)).sqrt();
        kappa += scale * D[i] / denom * W[i];
    }
    kappa * ix
}

/// C++ std::max(MINVAL, x).
fn at_least_minval(x: f64) -> f64 {
    if MINVAL < x {
        x
    } else {
        MINVAL
    }
}

/// geom_fluid of an ellipsoid-model geom.
fn fluid_coefs(kind: i32, size: &[f64; 3], coefs: &[f64; 5]) -> [f64; 12] {
    let (dx, dy, dz) = match kind {
        SPHERE => (size[0], size[0], size[0]),
        CAPSULE => (size[0], size[0], size[1] + size[0]),
        CYLINDER => (size[0], size[0], size[1]),
        _ => (size[0], size[1], size[2]),
    };
    let volume = 4.0 / 3.0 * std::f64::consts::PI * dx * dy * dz;
    let kx = added_mass_kappa(dx, dy, dz);
    let ky = added_mass_kappa(dy, dz, dx);
    let kz = added_mass_kappa(dz, dx, dy);
    let sq = |v: f64| v * v;
    let ixf = sq(dy * dy - dz * dz) * (kz - ky).abs()
        / at_least_minval((2.0 * (dy * dy - dz * dz) + (dy * dy + dz * dz) * (ky - kz)).abs());
    let iyf = sq(dz * dz - dx * dx) * (kx - kz).abs()
        / at_least_minval((2.0 * (dz * dz - dx * dx) + (dz * dz + dx * dx) * (kz - kx)).abs());
    let izf = sq(dx * dx - dy * dy) * (ky - kx).abs()
        / at_least_minval((2.0 * (dx * dx - dy * dy) + (dx * dx + dy * dy) * (kx - ky)).abs());
    [
        1.0,
        coefs[0],
        coefs[1],
        coefs[2],
        coefs[3],
        coefs[4],
        volume * kx / at_least_minval(2.0 - kx),
        volume * ky / at_least_minval(2.0 - ky),
        volume * kz / at_least_minval(2.0 - kz),
        volume * ixf / 5.0,
        volume * iyf / 5.0,
        volume * izf / 5.0,
    ]
}

fn volume(kind: i32, s: &[f64; 3]) -> f64 {
    use std::f64::consts::PI;
    match kind {
        SPHERE => 4.0 * PI * s[0] * s[0] * s[0] / 3.0,
        CAPSULE => PI * (s[0] * s[0] * (2.0 * s[1]) + 4.0 * s[0] * s[0] * s[0] / 3.0),
        CYLINDER => PI * s[0] * s[0] * (2.0 * s[1]),
        ELLIPSOID => 4.0 * PI * s[0] * s[1] * s[2] / 3.0,
        BOX => s[0] * s[1] * s[2] * 8.0,
        _ => 0.0,
    }
}

fn geom_inertia(kind: i32, mass: f64, s: &[f64; 3]) -> [f64; 3] {
    match kind {
        SPHERE => [2.0 * mass * s[0] * s[0] / 5.0; 3],
        CAPSULE => {
            let height = 2.0 * s[1];
            let r = s[0];
            let sphere_mass = mass * 4.0 * r / (4.0 * r + 3.0 * height);
            let cyl_mass = mass - sphere_mass;
            let mut i0 = cyl_mass * (3.0 * r * r + height * height) / 12.0;
            let mut i2 = cyl_mass * r * r / 2.0;
            let sphere_inertia = 2.0 * sphere_mass * r * r / 5.0;
            i0 += sphere_inertia + sphere_mass * height * (3.0 * r + 2.0 * height) / 8.0;
            i2 += sphere_inertia;
            [i0, i0, i2]
        }
        CYLINDER => {
            let height = 2.0 * s[1];
            let i0 = mass * (3.0 * s[0] * s[0] + height * height) / 12.0;
            [i0, i0, mass * s[0] * s[0] / 2.0]
        }
        ELLIPSOID => [
            mass * (s[1] * s[1] + s[2] * s[2]) / 5.0,
            mass * (s[0] * s[0] + s[2] * s[2]) / 5.0,
            mass * (s[0] * s[0] + s[1] * s[1]) / 5.0,
        ],
        BOX => [
            mass * (s[1] * s[1] + s[2] * s[2]) / 3.0,
            mass * (s[0] * s[0] + s[2] * s[2]) / 3.0,
            mass * (s[0] * s[0] + s[1] * s[1]) / 3.0,
        ],
        _ => [0.0; 3],
    }
}

/// Bounding-sphere radius of a compiled geom.
pub fn rbound(kind: i32, s: &[f64; 3]) -> f64 {
    match kind {
        SPHERE => s[0],
        CAPSULE => s[0] + s[1],
        CYLINDER => (s[0] * s[0] + s[1] * s[1]).sqrt(),
        ELLIPSOID => s[0].max(s[1]).max(s[2]),
        BOX | MESH => (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt(),
        _ => 0.0,
    }
}

/// The assets a geom names, and the compiler settings for meshes.
pub struct GeomAssets<'a> {
    /// size of the named height field
    pub hfield: Option<[f64; 4]>,
    /// the named mesh, compiled
    pub mesh: Option<&'a super::mesh::Mesh>,
    pub fitaabb: bool,
    pub exactmeshinertia: bool,
}

/// A geom compilation error: about the geom itself, or about the mesh it uses.
pub enum GeomError {
    Geom(String),
    Mesh(String),
}

impl From<String> for GeomError {
    fn from(m: String) -> Self {
        GeomError::Geom(m)
    }
}

/// Compiles a geom; `mesh_ok` tells whether a mesh geom keeps its mesh (false when fitted).
pub fn compile_geom(
    g: &Geom,
    id: usize,
    static_body: bool,
    infer: bool,
    a: &GeomAssets,
    s: &Settings,
) -> Result<GeomOut, GeomError> {
    let name = g.name.as_str();
    let hfield = a.hfield;
    if let Some(a) = g.unsupported {
        return Err(format!("geom attribute '{a}' is not supported by this compiler yet").into());
    }
    if ![1, 3, 4, 6].contains(&g.condim) {
        return Err(format!("invalid condim in geom '{name}' (id = {id})").into());
    }
    if g.kind == MESH && a.mesh.is_none() {
        return Err(format!("mesh geom '{name}' (id = {id}) must have valid meshid").into());
    }
    if (g.kind == 1) != hfield.is_some() {
        return Err(format!("hfield geom '{name}' (id = {id}) must have valid hfieldid").into());
    }
    if (g.kind == PLANE || g.kind == 1) && !static_body {
        return Err(format!(
            "plane and hfield only allowed in static bodies: geom '{name}' (id = {id})"
        )
        .into());
    }
    let mut quat = g.quat;
    normalize(&mut quat);
    let mut pos = g.pos;
    let mut size = g.size;
    if defined(g.fromto[0]) {
        if ![CAPSULE, CYLINDER, ELLIPSOID, BOX].contains(&g.kind) {
            return Err(format!(
                "fromto requires capsule, cylinder, box or ellipsoid in geom '{name}' (id = {id})"
            )
            .into());
        }
        if pos.iter().any(|&p| p != 0.0) {
            return Err(format!("both pos and fromto defined in geom '{name}' (id = {id})").into());
        }
        quat = from_to(&g.fromto, g.kind, &mut size, &mut pos)
            .map_err(|_| format!("fromto points too close in geom '{name}' (id = {id})"))?;
    } else {
        alt_set(&g.alt, &mut quat, None, s)
            .map_err(|e| format!("alternative specification error '{e}' in geom {id}"))?;
    }
    let kind_inertia = g.shellinertia as usize;
    let mut mesh = a.mesh;
    if let Some(m) = mesh {
        if defined(g.fromto[0]) {
            return Err(
                format!("fromto cannot be used with mesh geom '{name}' (id = {id})").into(),
            );
        }
        let meshpos = if g.kind != MESH {
            let p = super::mesh::fit(m, g.kind, kind_inertia, a.fitaabb, g.fitscale, &mut size)
                .map_err(GeomError::Mesh)?;
            mesh = None;
            p
        } else {
            m.pos[kind_inertia]
        };
        let add = mat_vec(&quat2mat(&quat), &meshpos);
        for k in 0..3 {
            pos[k] += add[k];
        }
        quat = mulquat_unit(&quat, &m.quat[kind_inertia]);
    }
    check_size(&size, g.kind, "geom", name, id)?;
    if let Some(hf) = hfield {
        size = [hf[0], hf[1], 0.5 * (hf[2] + hf[3])];
    } else if let Some(m) = mesh {
        size = m.aabb;
    }
    let (mut mass, mut inertia) = (0.0, [0.0; 3]);
    if infer {
        let vol = || -> Result<f64, GeomError> {
            match mesh {
                Some(m) if a.exactmeshinertia => m.volume(kind_inertia).map_err(GeomError::Mesh),
                Some(m) => Ok(m.boxsz[0][0] * m.boxsz[0][1] * m.boxsz[0][2] * 8.0),
                None => Ok(volume(g.kind, &size)),
            }
        };
        let inertia_of = |mass: f64| -> Result<[f64; 3], GeomError> {
            match mesh {
                Some(m) => {
                    let b = m.inertia_box(kind_inertia).map_err(GeomError::Mesh)?;
                    Ok([
                        mass * (b[1] * b[1] + b[2] * b[2]) / 3.0,
                        mass * (b[0] * b[0] + b[2] * b[2]) / 3.0,
                        mass * (b[0] * b[0] + b[1] * b[1]) / 3.0,
                    ])
                }
                None if g.shellinertia => Err(format!(
                    "typeinertia currently only available for meshes'{name}' (id = {id})"
                )
                .into()),
                None => Ok(geom_inertia(g.kind, mass, &size)),
            }
        };
        let mut density = g.density;
        if defined(g.mass) {
            if g.mass == 0.0 {
                density = 0.0;
            } else if vol()? > MINVAL {
                mass = g.mass;
                density = g.mass / vol()?;
                inertia = inertia_of(mass)?;
            }
        } else {
            mass = density * vol()?;
            inertia = inertia_of(mass)?;
        }
        if mass < 0.0 || inertia.iter().any(|&x| x < 0.0) || density < 0.0 {
            return Err(format!(
                "mass, inertia or density are negative in geom '{name}' (id = {id})"
            )
            .into());
        }
    }
    let fluid = if g.fluid_switch {
        fluid_coefs(g.kind, &size, &g.fluid_coefs)
    } else {
        [0.0; 12]
    };
    Ok(GeomOut {
        pos,
        quat,
        size,
        mass,
        inertia,
        fluid,
        mesh_kept: mesh.is_some(),
    })
}

pub struct SiteOut {
    pub pos: [f64; 3],
    pub quat: [f64; 4],
    pub size: [f64; 3],
}

pub fn compile_site(st: &Site, id: usize, s: &Settings) -> Result<SiteOut, String> {
    let name = st.name.as_str();
    if let Some(a) = st.unsupported {
        return Err(format!(
            "site attribute '{a}' is not supported by this compiler yet"
        ));
    }
    if st.kind == 7 || st.kind == 1 || st.kind == PLANE {
        return Err(format!(
            "meshes, hfields and planes not allowed in site '{name}' (id = {id})"
        ));
    }
    let (mut pos, mut quat, mut size) = (st.pos, st.quat, st.size);
    if defined(st.fromto[0]) {
        if ![CAPSULE, CYLINDER, ELLIPSOID, BOX].contains(&st.kind) {
            return Err(format!(
                "fromto requires capsule, cylinder, box or ellipsoid in geom '{name}' (id = {id})"
            ));
        }
        if pos.iter().any(|&p| p != 0.0) {
            return Err(format!(
                "both pos and fromto defined in geom '{name}' (id = {id})"
            ));
        }
        quat = from_to(&st.fromto, st.kind, &mut size, &mut pos)
            .map_err(|_| format!("fromto points too close in geom '{name}' (id = {id})"))?;
    } else {
        alt_set(&st.alt, &mut quat, None, s)
            .map_err(|e| format!("alternative specification error '{e}' in site {id}"))?;
    }
    normalize(&mut quat);
    check_size(&size, st.kind, "site", name, id)?;
    Ok(SiteOut { pos, quat, size })
}

/// Compiles a joint in place (limits, units, axis); returns its number of dofs.
pub fn compile_joint(
    j: &mut Joint,
    id: usize,
    autolimits: bool,
    degree: bool,
) -> Result<usize, String> {
    let name = j.name.clone();
    let [tc, dr] = j.springdamper;
    if (tc != 0.0 || dr != 0.0) && (tc <= 0.0 || dr <= 0.0) {
        return Err(format!(
            "when defined, springdamper values must be positive in joint '{name}' (id = {id})"
        ));
    }
    if j.kind == JointType::Free {
        j.limited = 0;
    } else if j.limited == 2 {
        let hasrange = !(j.range[0] == 0.0 && j.range[1] == 0.0);
        if !autolimits && hasrange {
            return Err(limited_msg("joint", ""));
        }
        j.limited = hasrange as i32;
    }
    if j.limited != 0 {
        if j.range[0] >= j.range[1] && j.kind != JointType::Ball {
            return Err(format!(
                "range[0] should be smaller than range[1] in joint '{name}' (id = {id})"
            ));
        }
        if j.range[0] != 0.0 && j.kind == JointType::Ball {
            return Err(format!(
                "range[0] should be 0 in ball joint '{name}' (id = {id})"
            ));
        }
        if degree && matches!(j.kind, JointType::Hinge | JointType::Ball) {
            for r in j.range.iter_mut() {
                if *r != 0.0 {
                    *r *= std::f64::consts::PI / 180.0;
                }
            }
        }
    }
    if matches!(j.kind, JointType::Free | JointType::Ball) {
        j.axis = [0.0, 0.0, 1.0];
    }
    if j.kind == JointType::Free {
        j.pos = [0.0; 3];
    }
    if normalize(&mut j.axis) < EPS {
        return Err(format!("axis too small in joint '{name}' (id = {id})"));
    }
    if j.kind == JointType::Hinge && degree {
        j.reference *= std::f64::consts::PI / 180.0;
        j.springref *= std::f64::consts::PI / 180.0;
    }
    Ok(j.kind.nv())
}

/// 2.2.2's message for a range given without its `limited` flag.
pub fn limited_msg(entity: &str, attr: &str) -> String {
    format!(
        "{entity} has `{attr}range` but not `{attr}limited`. set the autolimits=\"true\" compiler option, \
         specify `{attr}limited` explicitly (\"true\" or \"false\"), or remove the `{attr}range` attribute."
    )
}

/// Inertial frame of a body: position, orientation, mass, principal inertia.
pub type Inertial = ([f64; 3], [f64; 4], f64, [f64; 3]);

/// Inertial frame of a body from its selected geoms.
pub fn geom_frame(geoms: &[&GeomOut], s: &Settings) -> Result<Option<Inertial>, CError> {
    match geoms.len() {
        0 => Ok(None),
        1 => Ok(Some((
            geoms[0].pos,
            geoms[0].quat,
            geoms[0].mass,
            geoms[0].inertia,
        ))),
        _ => {
            let mut mass = 0.0;
            let mut com = [0.0; 3];
            for g in geoms {
                mass += g.mass;
                for (c, p) in com.iter_mut().zip(g.pos) {
                    *c += g.mass * p;
                }
            }
            if mass < MINVAL {
                return Err(CError::msg(
                    "body mass is too small, cannot compute center of mass",
                ));
            }
            let ipos = [com[0] / mass, com[1] / mass, com[2] / mass];
            let mut toti = [0.0; 6];
            for g in geoms {
                let d = [g.pos[0] - ipos[0], g.pos[1] - ipos[1], g.pos[2] - ipos[2]];
                let i0 = global_inertia(&g.inertia, &g.quat);
                let i1 = offcenter(g.mass, &d);
                for k in 0..6 {
                    toti[k] = toti[k] + i0[k] + i1[k];
                }
            }
            let alt = Alt {
                fullinertia: toti,
                ..Alt::default()
            };
            let mut iquat = [1.0, 0.0, 0.0, 0.0];
            let mut inertia = [0.0; 3];
            alt_set(&alt, &mut iquat, Some(&mut inertia), s).map_err(|e| {
                CError::msg(&format!("error '{e}' in alternative for principal axes"))
            })?;
            Ok(Some((ipos, iquat, mass, inertia)))
        }
    }
}
