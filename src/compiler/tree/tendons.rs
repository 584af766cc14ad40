//! Tendons: limits and wrap paths, then the tendon and wrap arrays.

use super::*;

pub(super) fn compile_all(
    specs: Vec<Tendon>,
    nuser: usize,
    joints: &[FJoint],
    geoms: &[FGeom],
    sites: &[FSite],
    autolimits: bool,
) -> Result<Vec<CTendon>, CError> {
    let mut tendons = Vec::new();
    for (id, t) in specs.into_iter().enumerate() {
        let wraps = compile_tendon(&t, id, nuser, joints, geoms, sites, autolimits)?;
        tendons.push(wraps);
    }
    Ok(tendons)
}

/// A compiled tendon: its description (limits resolved) and path as (mjtWrap, object id, prm).
pub(super) struct CTendon {
    pub(super) spec: Tendon,
    pub(super) wraps: Vec<(i32, i32, f64)>,
}

fn compile_tendon(
    t: &Tendon,
    id: usize,
    nuser: usize,
    joints: &[FJoint],
    geoms: &[FGeom],
    sites: &[FSite],
    autolimits: bool,
) -> Result<CTendon, CError> {
    let name = t.name.as_str();
    let err = |m: String| CError::at(m, name, id, t.line);
    if t.user.len() > nuser {
        return Err(err(format!(
            "user has more values than nuser_tendon in tendon '{name}' (id = {id})"
        )));
    }
    let sz = t.path.len();
    if sz == 0 {
        return Err(err(format!(
            "tendon '{name}' (id = {id}): path cannot be empty"
        )));
    }
    let spatial = t.path[0].kind != 1;
    if spatial && sz < 2 {
        return Err(err(format!(
            "tendon '{name}' (id = {id}): spatial path must contain at least two objects"
        )));
    }
    if spatial && t.width <= 0.0 {
        return Err(err(format!(
            "tendon '{name}' (id = {id}) must have positive width"
        )));
    }
    let mut wraps = Vec::new();
    for (k, w) in t.path.iter().enumerate() {
        let werr = |m: String| CError::at(m, &w.name, k, w.line);
        let find_site = |n: &str| sites.iter().position(|s| s.spec.name == n);
        let wrap = match w.kind {
            1 => {
                let j = joints.iter().position(|j| j.spec.name == w.name);
                let j = j.ok_or_else(|| {
                    werr(format!(
                        "joint '{}' not found in tendon {id}, wrap {k}",
                        w.name
                    ))
                })?;
                (1, j as i32, w.prm)
            }
            4 => {
                let g = geoms.iter().position(|g| g.spec.name == w.name);
                let g = g.ok_or_else(|| {
                    werr(format!(
                        "geom '{}' not found in tendon {id}, wrap {k}",
                        w.name
                    ))
                })?;
                let kind = match geoms[g].spec.kind {
                    CYLINDER => 5,
                    SPHERE => 4,
                    _ => {
                        let m = format!(
                            "geom '{}' in tendon {id}, wrap {k} is not sphere or cylinder",
                            w.name
                        );
                        return Err(werr(m));
                    }
                };
                let mut side = -1;
                if !w.sidesite.is_empty() {
                    let s = find_site(&w.sidesite).ok_or_else(|| {
                        werr(format!(
                            "side site '{}' not found in tendon {id}, wrap {k}",
                            w.sidesite
                        ))
                    })?;
                    side = s as i32;
                }
                (kind, g as i32, side as f64)
            }
            2 => {
                if w.prm < 0.0 {
                    return Err(werr(format!(
                        "pulley has negative divisor in tendon {id}, wrap {k}"
                    )));
                }
                (2, -1, w.prm)
            }
            _ => {
                let s = find_site(&w.name)
                    .ok_or_else(|| werr(format!("site '{}' not found in wrap {k}", w.name)))?;
                (3, s as i32, w.prm)
            }
        };
        wraps.push(wrap);
    }
    for i in 0..sz {
        let kind = wraps[i].0;
        let prev = if i > 0 { wraps[i - 1].0 } else { -1 };
        let next = if i + 1 < sz { wraps[i + 1].0 } else { -1 };
        if !spatial {
            if kind != 1 {
                return Err(err(format!(
                    "tendon '{name}' (id = {id}): spatial object found in fixed path at pos {i}"
                )));
            }
            continue;
        }
        match kind {
            2 => {
                if prev == 2 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): consequtive pulleys (pos {i})"
                    )));
                }
                if i == sz - 1 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): path ends with pulley"
                    )));
                }
            }
            3 => {
                if (i == 0 || prev == 2) && (i == sz - 1 || next == 2) {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): site {i} needs a neighbor that is not a pulley"
                    )));
                }
                if next == 3 && wraps[i].1 == wraps[i + 1].1 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): site {i} is repeated"
                    )));
                }
            }
            4 | 5 => {
                if prev != 3 || next != 3 {
                    return Err(err(format!(
                        "tendon '{name}' (id = {id}): geom at pos {i} not bracketed by sites"
                    )));
                }
            }
            _ => {
                return Err(err(format!(
                    "tendon '{name} (id = {id})': joint wrap found in spatial path at pos {i}"
                )));
            }
        }
    }
    let mut spec = t.clone();
    if spec.limited == 2 {
        let hasrange = !(spec.range[0] == 0.0 && spec.range[1] == 0.0);
        if !autolimits && hasrange {
            return Err(err(limited_msg("tendon", "")));
        }
        spec.limited = hasrange as i32;
    }
    if spec.range[0] >= spec.range[1] && spec.limited != 0 {
        return Err(err(format!(
            "invalid limits in tendon '{name} (id = {id})'"
        )));
    }
    spec.user.resize(nuser, 0.0);
    Ok(CTendon { spec, wraps })
}

impl Compiled {
    pub(super) fn fill_tendons(&self, m: &mut ModelMut) {
        let mut adr = 0;
        for (i, t) in self.tendons.iter().enumerate() {
            let s = &t.spec;
            m.tendon_adr[i] = adr as i32;
            m.tendon_num[i] = t.wraps.len() as i32;
            m.tendon_group[i] = s.group;
            m.tendon_limited[i] = s.limited as u8;
            m.tendon_width[i] = s.width;
            put(m.tendon_solref_lim, i, &s.solref_limit);
            put(m.tendon_solimp_lim, i, &s.solimp_limit);
            put(m.tendon_solref_fri, i, &s.solref_friction);
            put(m.tendon_solimp_fri, i, &s.solimp_friction);
            put(m.tendon_range, i, &s.range);
            m.tendon_margin[i] = s.margin;
            m.tendon_stiffness[i] = s.stiffness;
            m.tendon_damping[i] = s.damping;
            m.tendon_frictionloss[i] = s.frictionloss;
            m.tendon_lengthspring[i] = s.springlength;
            put(m.tendon_user, i, &s.user);
            put(m.tendon_rgba, i, &s.rgba);
            for (k, w) in t.wraps.iter().enumerate() {
                m.wrap_type[adr + k] = w.0;
                m.wrap_objid[adr + k] = w.1;
                m.wrap_prm[adr + k] = w.2;
            }
            adr += t.wraps.len();
        }
    }
}
