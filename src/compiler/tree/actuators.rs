//! Actuators: limits, muscle parameters and transmission targets, then their arrays.

use super::*;

/// Checks the actuators and resolves their limits; returns the transmission target ids.
pub(super) fn compile(
    actuators: &mut [Actuator],
    nuser: usize,
    autolimits: bool,
    bodies: &[FBody],
    joints: &[FJoint],
    sites: &[FSite],
    tendons: &[CTendon],
) -> Result<Vec<[i32; 2]>, CError> {
    let mut trnid = Vec::new();
    for (id, a) in actuators.iter_mut().enumerate() {
        let aerr = |m: String| CError::at(m, &a.name.clone(), id, a.line);
        if a.user.len() > nuser {
            return Err(aerr(format!(
                "user has more values than nuser_actuator in actuator '{}' (id = {id})",
                a.name
            )));
        }
        for (lim, range, attr) in [
            (&mut a.forcelimited, a.forcerange, "force"),
            (&mut a.ctrllimited, a.ctrlrange, "ctrl"),
            (&mut a.actlimited, a.actrange, "act"),
        ] {
            if *lim == 2 {
                let hasrange = !(range[0] == 0.0 && range[1] == 0.0);
                if !autolimits && hasrange {
                    return Err(CError::at(
                        limited_msg("actuator", attr),
                        &a.name,
                        id,
                        a.line,
                    ));
                }
                *lim = hasrange as i32;
            }
        }
        let name = a.name.clone();
        let aerr = |m: String| CError::at(m, &name, id, a.line);
        if a.forcerange[0] >= a.forcerange[1] && a.forcelimited != 0 {
            return Err(aerr(format!(
                "invalid force range for actuator '{name}' (id = {id})"
            )));
        }
        if a.ctrlrange[0] >= a.ctrlrange[1] && a.ctrllimited != 0 {
            return Err(aerr(format!(
                "invalid control range for actuator '{name}' (id = {id})"
            )));
        }
        if a.actrange[0] >= a.actrange[1] && a.actlimited != 0 {
            return Err(aerr(format!(
                "invalid activation range for actuator '{name}' (id = {id})"
            )));
        }
        if a.actlimited != 0 && a.dyntype == 0 {
            return Err(aerr(format!(
                "actrange specified but dyntype is 'none' in actuator '{name}' (id = {id})"
            )));
        }
        for (i, prm) in [(2, a.gainprm), (2, a.biasprm)].iter().enumerate() {
            let muscle = if i == 0 {
                a.gaintype == prm.0
            } else {
                a.biastype == prm.0
            };
            if !muscle {
                continue;
            }
            let p = prm.1;
            if p[0] >= p[1] {
                return Err(aerr(format!(
                    "range[0]<range[1] required in muscle '{name}' (id = {id})"
                )));
            }
            if p[4] >= 1.0 || p[5] <= 1.0 {
                return Err(aerr(format!(
                    "lmin<1<lmax required in muscle '{name}' (id = {id})"
                )));
            }
            if p[3] <= 0.0 || p[6] <= 0.0 || p[7] <= 0.0 || p[8] <= 0.0 {
                return Err(aerr(format!(
                    "positive scale, vmax, fpmax, fvmax required in muscle '{name}' (id = {id})"
                )));
            }
        }
        if a.target.is_empty() {
            return Err(aerr(format!(
                "missing transmission target for actuator '{name}' (id = {id})"
            )));
        }
        let find_site = |n: &str| sites.iter().position(|st| st.spec.name == n);
        let missing = |n: &str| {
            aerr(format!(
                "transmission target '{n}' not found in actuator {id}"
            ))
        };
        let ids = match a.trntype {
            0 | 1 => match joints.iter().position(|j| j.spec.name == a.target) {
                Some(j) => [j as i32, -1],
                None => {
                    let t = &a.target;
                    return Err(aerr(format!(
                        "unknown transmission target '{t}' for actuator id = {id}"
                    )));
                }
            },
            2 => {
                if a.slidersite.is_empty() {
                    return Err(aerr(format!(
                        "missing base site for slider-crank '{name}' (id = {id})"
                    )));
                }
                let Some(slider) = find_site(&a.slidersite) else {
                    let ss = &a.slidersite;
                    return Err(aerr(format!(
                        "base site '{ss}' not found for actuator {id}"
                    )));
                };
                if a.cranklength <= 0.0 {
                    return Err(aerr(format!(
                        "crank length must be positive in actuator '{name}' (id = {id})"
                    )));
                }
                [
                    find_site(&a.target).ok_or_else(|| missing(&a.target))? as i32,
                    slider as i32,
                ]
            }
            4 => {
                let mut refsite = -1;
                if !a.refsite.is_empty() {
                    let Some(r) = find_site(&a.refsite) else {
                        let rs = &a.refsite;
                        return Err(aerr(format!(
                            "reference site '{rs}' not found for actuator {id}"
                        )));
                    };
                    refsite = r as i32;
                }
                [
                    find_site(&a.target).ok_or_else(|| missing(&a.target))? as i32,
                    refsite,
                ]
            }
            5 => [
                find_body(bodies, &a.target).ok_or_else(|| missing(&a.target))? as i32,
                -1,
            ],
            3 => [
                tendons
                    .iter()
                    .position(|t| t.spec.name == a.target)
                    .ok_or_else(|| missing(&a.target))? as i32,
                -1,
            ],
            _ => {
                return Err(aerr(format!(
                    "invalid transmission type in actuator '{name}' (id = {id})"
                )))
            }
        };
        trnid.push(ids);
    }
    Ok(trnid)
}

impl Compiled {
    pub(super) fn fill_actuators(&self, m: &mut ModelMut) {
        let nua = self.nuser[6];
        for (i, a) in self.actuators.iter().enumerate() {
            m.actuator_trntype[i] = a.trntype;
            m.actuator_dyntype[i] = a.dyntype;
            m.actuator_gaintype[i] = a.gaintype;
            m.actuator_biastype[i] = a.biastype;
            put(m.actuator_trnid, i, &self.trnid[i]);
            m.actuator_group[i] = a.group;
            m.actuator_ctrllimited[i] = a.ctrllimited as u8;
            m.actuator_forcelimited[i] = a.forcelimited as u8;
            m.actuator_actlimited[i] = a.actlimited as u8;
            m.actuator_cranklength[i] = a.cranklength;
            put(m.actuator_gear, i, &a.gear);
            put(m.actuator_dynprm, i, &a.dynprm);
            put(m.actuator_gainprm, i, &a.gainprm);
            put(m.actuator_biasprm, i, &a.biasprm);
            put(m.actuator_ctrlrange, i, &a.ctrlrange);
            put(m.actuator_forcerange, i, &a.forcerange);
            put(m.actuator_actrange, i, &a.actrange);
            put(m.actuator_lengthrange, i, &a.lengthrange);
            let mut user = a.user.clone();
            user.resize(nua, 0.0);
            put(m.actuator_user, i, &user);
        }
    }
}
