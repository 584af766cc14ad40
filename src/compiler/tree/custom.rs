//! Custom numeric, text and tuple data: tuple elements resolved to object ids, then the
//! custom data arrays.

use super::*;

impl Compiled {
    /// Object ids of each tuple's elements, by type and name.
    pub(super) fn resolve_tuples(&self) -> Result<Vec<Vec<i32>>, CError> {
        let Compiled {
            bodies,
            joints,
            geoms,
            sites,
            cameras,
            lights,
            hfields,
            texture_names,
            materials,
            pairs,
            excludes,
            equalities,
            tendons,
            actuators,
            sensors: csensors,
            custom,
            keys,
            ..
        } = self;
        let mut tuple_ids = Vec::new();
        for (id, (name, line, elems)) in custom.tuples.iter().enumerate() {
            if elems.is_empty() {
                return Err(CError::at(
                    format!("tuple '{name}' (id = {id}) is empty"),
                    name,
                    id,
                    *line,
                ));
            }
            let mut ids = Vec::new();
            for (kind, oname, _) in elems {
                let found = match kind {
                    1 | 2 => find_body(bodies, oname),
                    3 => position_of(joints.iter().map(|j| j.spec.name.as_str()), oname),
                    5 => position_of(geoms.iter().map(|g| g.spec.name.as_str()), oname),
                    6 => position_of(sites.iter().map(|s| s.spec.name.as_str()), oname),
                    7 => position_of(cameras.iter().map(|c| c.0.name.as_str()), oname),
                    8 => position_of(lights.iter().map(|l| l.0.name.as_str()), oname),
                    11 => position_of(hfields.iter().map(|h| h.name.as_str()), oname),
                    12 => position_of(texture_names.iter().map(|t| t.as_str()), oname),
                    13 => position_of(materials.iter().map(|m| m.name.as_str()), oname),
                    14 => position_of(pairs.iter().map(|p| p.0.name.as_str()), oname),
                    15 => position_of(excludes.iter().map(|e| e.0.as_str()), oname),
                    16 => position_of(equalities.iter().map(|e| e.0.name.as_str()), oname),
                    17 => position_of(tendons.iter().map(|t| t.spec.name.as_str()), oname),
                    18 => position_of(actuators.iter().map(|a| a.name.as_str()), oname),
                    19 => position_of(csensors.iter().map(|s| s.spec.name.as_str()), oname),
                    20 => position_of(custom.numerics.iter().map(|x| x.0.as_str()), oname),
                    21 => position_of(custom.texts.iter().map(|x| x.0.as_str()), oname),
                    22 => position_of(custom.tuples.iter().map(|x| x.0.as_str()), oname),
                    23 => position_of(keys.iter().map(|k| k.name.as_str()), oname),
                    _ => None,
                };
                let Some(found) = found else {
                    return Err(CError::at(
                        format!("unrecognized object '{oname}' in tuple {id}"),
                        name,
                        id,
                        *line,
                    ));
                };
                ids.push(found as i32);
            }
            tuple_ids.push(ids);
        }
        Ok(tuple_ids)
    }

    pub(super) fn fill_custom(&self, m: &mut ModelMut) {
        let mut adr = 0;
        for (i, x) in self.custom.numerics.iter().enumerate() {
            m.numeric_adr[i] = adr as i32;
            m.numeric_size[i] = x.2.len() as i32;
            m.numeric_data[adr..adr + x.2.len()].copy_from_slice(&x.2);
            adr += x.2.len();
        }
        let mut adr = 0;
        for (i, x) in self.custom.texts.iter().enumerate() {
            m.text_adr[i] = adr as i32;
            m.text_size[i] = x.2.len() as i32 + 1;
            for (k, b) in x.2.bytes().enumerate() {
                m.text_data[adr + k] = b as std::os::raw::c_char;
            }
            adr += x.2.len() + 1;
        }
        let mut adr = 0;
        for (i, x) in self.custom.tuples.iter().enumerate() {
            m.tuple_adr[i] = adr as i32;
            m.tuple_size[i] = x.2.len() as i32;
            for (k, (kind, _, prm)) in x.2.iter().enumerate() {
                m.tuple_objtype[adr + k] = *kind;
                m.tuple_objid[adr + k] = self.tuple_ids[i][k];
                m.tuple_objprm[adr + k] = *prm;
            }
            adr += x.2.len();
        }
    }
}

/// Index of the first of the names equal to the given one.
fn position_of<'a>(mut names: impl Iterator<Item = &'a str>, name: &str) -> Option<usize> {
    names.position(|n| n == name)
}
