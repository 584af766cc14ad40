//! Object names: unique within each kind at compile time, the names buffer at fill time.

use super::*;

fn check_names<'a>(names: impl Iterator<Item = (&'a str, i32)>, what: &str) -> Result<(), CError> {
    let list: Vec<(&str, i32)> = names.collect();
    let mut seen = std::collections::HashSet::new();
    for (i, (name, line)) in list.iter().enumerate() {
        if !name.is_empty() && !seen.insert(*name) {
            return Err(CError::at(
                format!("repeated name in {what} array, position {i}"),
                name,
                i,
                *line,
            ));
        }
    }
    Ok(())
}

/// Rejects a repeated name in any kind's list, in 2.2.2's order of kinds.
#[allow(clippy::too_many_arguments)]
pub(super) fn check_all(
    spec: &ModelSpec,
    bodies: &[FBody],
    joints: &[FJoint],
    gspecs: &[Geom],
    sspecs: &[(Site, usize)],
    cameras: &[(Camera, usize)],
    lights: &[(Light, usize)],
    actuators: &[Actuator],
    keys: &[Key],
) -> Result<(), CError> {
    check_names(
        bodies.iter().map(|b| (b.spec.name.as_str(), b.spec.line)),
        "body",
    )?;
    check_names(
        joints.iter().map(|j| (j.spec.name.as_str(), j.spec.line)),
        "joint",
    )?;
    check_names(gspecs.iter().map(|g| (g.name.as_str(), g.line)), "geom")?;
    check_names(sspecs.iter().map(|s| (s.0.name.as_str(), s.0.line)), "site")?;
    check_names(
        cameras.iter().map(|c| (c.0.name.as_str(), c.0.line)),
        "camera",
    )?;
    check_names(
        lights.iter().map(|l| (l.0.name.as_str(), l.0.line)),
        "light",
    )?;
    check_names(
        spec.meshes.iter().map(|m| (m.name.as_str(), m.line)),
        "mesh",
    )?;
    check_names(spec.skins.iter().map(|s| (s.name.as_str(), s.line)), "skin")?;
    check_names(
        spec.hfields.iter().map(|h| (h.name.as_str(), h.line)),
        "hfield",
    )?;
    check_names(
        spec.textures.iter().map(|t| (t.name.as_str(), t.line)),
        "texture",
    )?;
    check_names(
        spec.materials.iter().map(|m| (m.name.as_str(), m.line)),
        "material",
    )?;
    check_names(spec.pairs.iter().map(|p| (p.name.as_str(), p.line)), "pair")?;
    check_names(
        spec.excludes.iter().map(|e| (e.name.as_str(), e.line)),
        "exclude",
    )?;
    check_names(
        spec.equalities.iter().map(|e| (e.name.as_str(), e.line)),
        "equality",
    )?;
    check_names(
        spec.tendons.iter().map(|t| (t.name.as_str(), t.line)),
        "tendon",
    )?;
    check_names(
        actuators.iter().map(|a| (a.name.as_str(), a.line)),
        "actuator",
    )?;
    check_names(spec.sensors.iter().map(|s| (s.name.as_str(), -1)), "sensor")?;
    check_names(
        spec.custom.numerics.iter().map(|x| (x.0.as_str(), x.1)),
        "numeric",
    )?;
    check_names(
        spec.custom.texts.iter().map(|x| (x.0.as_str(), x.1)),
        "text",
    )?;
    check_names(
        spec.custom.tuples.iter().map(|x| (x.0.as_str(), x.1)),
        "tuple",
    )?;
    check_names(keys.iter().map(|k| (k.name.as_str(), -1)), "key")?;
    Ok(())
}

impl Compiled {
    /// Length of the names buffer.
    pub(super) fn count_names(&self) -> usize {
        let len = |s: &str| s.len() + 1;
        let mut n = len(&self.modelname);
        n += self.bodies.iter().map(|b| len(&b.spec.name)).sum::<usize>();
        n += self.joints.iter().map(|j| len(&j.spec.name)).sum::<usize>();
        n += self.geoms.iter().map(|g| len(&g.spec.name)).sum::<usize>();
        n += self.sites.iter().map(|s| len(&s.spec.name)).sum::<usize>();
        n += self.cameras.iter().map(|c| len(&c.0.name)).sum::<usize>();
        n += self.lights.iter().map(|l| len(&l.0.name)).sum::<usize>();
        n += self.meshes.iter().map(|m| len(&m.name)).sum::<usize>();
        n += self.skins.iter().map(|s| len(&s.name)).sum::<usize>();
        n += self.hfields.iter().map(|h| len(&h.name)).sum::<usize>();
        n += self.texture_names.iter().map(|t| len(t)).sum::<usize>();
        n += self.materials.iter().map(|m| len(&m.name)).sum::<usize>();
        n += self.pairs.iter().map(|p| len(&p.0.name)).sum::<usize>();
        n += self.excludes.iter().map(|e| len(&e.0)).sum::<usize>();
        n += self
            .tendons
            .iter()
            .map(|t| len(&t.spec.name))
            .sum::<usize>();
        n += self
            .equalities
            .iter()
            .map(|e| len(&e.0.name))
            .sum::<usize>();
        n += self.actuators.iter().map(|a| len(&a.name)).sum::<usize>();
        n += self
            .sensors
            .iter()
            .map(|s| len(&s.spec.name))
            .sum::<usize>();
        let custom = &self.custom;
        n += custom.numerics.iter().map(|x| len(&x.0)).sum::<usize>();
        n += custom.texts.iter().map(|x| len(&x.0)).sum::<usize>();
        n += custom.tuples.iter().map(|x| len(&x.0)).sum::<usize>();
        n += self.keys.iter().map(|k| len(&k.name)).sum::<usize>();
        n
    }

    pub(super) fn fill_names(&self, m: &mut ModelMut) {
        let mut adr = 0usize;
        let mut name = |dst: &mut i32, s: &str, names: &mut [i8]| {
            *dst = adr as i32;
            for (k, b) in s.bytes().enumerate() {
                names[adr + k] = b as i8;
            }
            adr += s.len();
            names[adr] = 0;
            adr += 1;
        };
        let mut scratch = 0;
        name(&mut scratch, &self.modelname, m.names);
        for (i, b) in self.bodies.iter().enumerate() {
            name(&mut m.name_bodyadr[i], &b.spec.name, m.names);
        }
        for (i, j) in self.joints.iter().enumerate() {
            name(&mut m.name_jntadr[i], &j.spec.name, m.names);
        }
        for (i, g) in self.geoms.iter().enumerate() {
            name(&mut m.name_geomadr[i], &g.spec.name, m.names);
        }
        for (i, s) in self.sites.iter().enumerate() {
            name(&mut m.name_siteadr[i], &s.spec.name, m.names);
        }
        for (i, c) in self.cameras.iter().enumerate() {
            name(&mut m.name_camadr[i], &c.0.name, m.names);
        }
        for (i, l) in self.lights.iter().enumerate() {
            name(&mut m.name_lightadr[i], &l.0.name, m.names);
        }
        for (i, mesh) in self.meshes.iter().enumerate() {
            name(&mut m.name_meshadr[i], &mesh.name, m.names);
        }
        for (i, sk) in self.skins.iter().enumerate() {
            name(&mut m.name_skinadr[i], &sk.name, m.names);
        }
        for (i, hf) in self.hfields.iter().enumerate() {
            name(&mut m.name_hfieldadr[i], &hf.name, m.names);
        }
        for (i, t) in self.texture_names.iter().enumerate() {
            name(&mut m.name_texadr[i], t, m.names);
        }
        for (i, mat) in self.materials.iter().enumerate() {
            name(&mut m.name_matadr[i], &mat.name, m.names);
        }
        for (i, p) in self.pairs.iter().enumerate() {
            name(&mut m.name_pairadr[i], &p.0.name, m.names);
        }
        for (i, e) in self.excludes.iter().enumerate() {
            name(&mut m.name_excludeadr[i], &e.0, m.names);
        }
        for (i, e) in self.equalities.iter().enumerate() {
            name(&mut m.name_eqadr[i], &e.0.name, m.names);
        }
        for (i, t) in self.tendons.iter().enumerate() {
            name(&mut m.name_tendonadr[i], &t.spec.name, m.names);
        }
        for (i, a) in self.actuators.iter().enumerate() {
            name(&mut m.name_actuatoradr[i], &a.name, m.names);
        }
        for (i, s) in self.sensors.iter().enumerate() {
            name(&mut m.name_sensoradr[i], &s.spec.name, m.names);
        }
        for (i, x) in self.custom.numerics.iter().enumerate() {
            name(&mut m.name_numericadr[i], &x.0, m.names);
        }
        for (i, x) in self.custom.texts.iter().enumerate() {
            name(&mut m.name_textadr[i], &x.0, m.names);
        }
        for (i, x) in self.custom.tuples.iter().enumerate() {
            name(&mut m.name_tupleadr[i], &x.0, m.names);
        }
        for (i, k) in self.keys.iter().enumerate() {
            name(&mut m.name_keyadr[i], &k.name, m.names);
        }
    }
}
