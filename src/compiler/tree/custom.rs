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
                let by_name = |mut names: std::slice::Iter<'_, &str>| {
                    names.position(|n| *n == oname.as_str())
                };
                let found = match kind {
                    1 | 2 => find_body(bodies, oname),
                    3 => by_name(
                        joints
                            .iter()
                            .map(|j| j.spec.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    5 => by_name(
                        geoms
                            .iter()
                            .map(|g| g.spec.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    6 => by_name(
                        sites
                            .iter()
                            .map(|s| s.spec.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    7 => by_name(
                        cameras
                            .iter()
                            .map(|c| c.0.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    8 => by_name(
                        lights
                            .iter()
                            .map(|l| l.0.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    11 => by_name(
                        hfields
                            .iter()
                            .map(|h| h.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    12 => by_name(
                        texture_names
                            .iter()
                            .map(|t| t.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    13 => by_name(
                        materials
                            .iter()
                            .map(|m| m.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    14 => by_name(
                        pairs
                            .iter()
                            .map(|p| p.0.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    15 => by_name(
                        excludes
                            .iter()
                            .map(|e| e.0.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    16 => by_name(
                        equalities
                            .iter()
                            .map(|e| e.0.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    17 => by_name(
                        tendons
                            .iter()
                            .map(|t| t.spec.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    18 => by_name(
                        actuators
                            .iter()
                            .map(|a| a.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    19 => by_name(
                        csensors
                            .iter()
                            .map(|s| s.spec.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    20 => by_name(
                        custom
                            .numerics
                            .iter()
                            .map(|x| x.0.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    21 => by_name(
                        custom
                            .texts
                            .iter()
                            .map(|x| x.0.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    22 => by_name(
                        custom
                            .tuples
                            .iter()
                            .map(|x| x.0.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
                    23 => by_name(
                        keys.iter()
                            .map(|k| k.name.as_str())
                            .collect::<Vec<&str>>()
                            .iter(),
                    ),
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
