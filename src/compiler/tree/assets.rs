//! Asset names, and the references of geoms, sites, tendons and materials to assets.

use super::*;

/// Asset ids referred to by other objects.
pub(super) struct AssetRefs {
    pub geom_hfield: Vec<Option<usize>>,
    pub geom_mesh: Vec<Option<usize>>,
    pub geom_matid: Vec<i32>,
    pub site_matid: Vec<i32>,
    pub tendon_matid: Vec<i32>,
    pub mat_texid: Vec<i32>,
}

pub(super) fn resolve(
    spec: &mut ModelSpec,
    gspecs: &[Geom],
    sspecs: &[(Site, usize)],
) -> Result<AssetRefs, CError> {
    // unnamed assets take the name of their file, without directory and extension
    let file_name = |file: &str| {
        let base = file.rsplit(['/', '\\']).next().unwrap_or("");
        match base.rfind('.') {
            Some(dot) => base[..dot].to_string(),
            None => base.to_string(),
        }
    };
    for (id, m) in spec.meshes.iter_mut().enumerate() {
        if m.name.is_empty() {
            m.name = file_name(&m.file);
            if m.name.is_empty() {
                return Err(CError::at("empty name in mesh".into(), &m.name, id, m.line));
            }
        }
    }
    for (id, hf) in spec.hfields.iter_mut().enumerate() {
        if hf.name.is_empty() {
            hf.name = file_name(&hf.file);
            if hf.name.is_empty() {
                let msg = "empty name in height field".into();
                return Err(CError::at(msg, &hf.name, id, hf.line));
            }
        }
    }
    for (id, t) in spec.textures.iter_mut().enumerate() {
        if t.name.is_empty() {
            t.name = file_name(&t.file_names[0]);
            if t.name.is_empty() && t.kind != 2 {
                return Err(CError::at(
                    "empty name in texture".into(),
                    &t.name,
                    id,
                    t.line,
                ));
            }
        }
    }
    for (id, m) in spec.materials.iter().enumerate() {
        if m.name.is_empty() {
            return Err(CError::at(
                "empty name in material".into(),
                &m.name,
                id,
                m.line,
            ));
        }
    }
    let find_mat = |n: &str| spec.materials.iter().position(|m| m.name == n);
    let mut geom_hfield: Vec<Option<usize>> = vec![None; gspecs.len()];
    let mut geom_mesh: Vec<Option<usize>> = vec![None; gspecs.len()];
    let mut geom_matid = vec![-1; gspecs.len()];
    for (i, g) in gspecs.iter().enumerate() {
        let missing = |what: &str, n: &str| {
            CError::at(
                format!("{what} '{n}' not found in geom {i}"),
                &g.name,
                i,
                g.line,
            )
        };
        if !g.material.is_empty() {
            let m = find_mat(&g.material).ok_or_else(|| missing("material", &g.material))?;
            geom_matid[i] = m as i32;
        }
        if !g.mesh.is_empty() {
            let m = spec.meshes.iter().position(|m| m.name == g.mesh);
            geom_mesh[i] = Some(m.ok_or_else(|| missing("mesh", &g.mesh))?);
        }
        if !g.hfield.is_empty() {
            let h = spec.hfields.iter().position(|h| h.name == g.hfield);
            geom_hfield[i] = Some(h.ok_or_else(|| missing("hfield", &g.hfield))?);
        }
    }
    let mut site_matid = vec![-1; sspecs.len()];
    for (i, (s, _)) in sspecs.iter().enumerate() {
        if !s.material.is_empty() {
            let m = find_mat(&s.material).ok_or_else(|| {
                CError::at(
                    format!("material '{}' not found in site {i}", s.material),
                    &s.name,
                    i,
                    s.line,
                )
            })?;
            site_matid[i] = m as i32;
        }
    }
    let mut tendon_matid = vec![-1; spec.tendons.len()];
    for (i, t) in spec.tendons.iter().enumerate() {
        if !t.material.is_empty() {
            let m = find_mat(&t.material).ok_or_else(|| {
                CError::at(
                    format!("material '{}' not found in tendon {i}", t.material),
                    &t.name,
                    i,
                    t.line,
                )
            })?;
            tendon_matid[i] = m as i32;
        }
    }
    let mut mat_texid = vec![-1; spec.materials.len()];
    for (i, m) in spec.materials.iter().enumerate() {
        if !m.texture.is_empty() {
            let t = spec
                .textures
                .iter()
                .position(|t| t.name == m.texture)
                .ok_or_else(|| {
                    CError::at(
                        format!("texture '{}' not found in material {i}", m.texture),
                        &m.name,
                        i,
                        m.line,
                    )
                })?;
            mat_texid[i] = t as i32;
        }
    }
    Ok(AssetRefs {
        geom_hfield,
        geom_mesh,
        geom_matid,
        site_matid,
        tendon_matid,
        mat_texid,
    })
}
