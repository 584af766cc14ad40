//! Textures and materials: texture images (builtin or from files), then the texture and
//! material arrays and the material ids of geoms, sites and tendons.

use super::*;

/// A texture image: (mjtTexture, width, height, RGB bytes).
pub(super) type TexImage = (i32, i32, i32, Vec<u8>);

pub(super) fn compile(textures: &[Texture]) -> Result<Vec<TexImage>, CError> {
    // textures (random marks draw from the C generator seeded as 2.2.2 seeds it)
    let mut rng = crate::compiler::texture::CRand::new(123);
    let mut images = Vec::new();
    for (id, t) in textures.iter().enumerate() {
        let err = |m: String| CError::at(m, &t.name, id, t.line);
        let name = &t.name;
        if t.builtin != 0 {
            if t.width < 1 || t.height < 1 {
                return Err(err(format!(
                    "Invalid width or height of builtin texture '{name}' (id {id})"
                )));
            }
            let width = t.width as usize;
            let height = if t.kind != 0 {
                6 * width
            } else {
                t.height as usize
            };
            if width.saturating_mul(height) > (i32::MAX / 3) as usize {
                return Err(err(format!(
                    "Could not allocate memory for texture '{name}' (id {id})"
                )));
            }
            let rgb = crate::compiler::texture::builtin(t, width, height, &mut rng);
            images.push((t.kind, width as i32, height as i32, rgb));
        } else if !t.file_names[0].is_empty()
            || (t.kind != 0 && t.file_names[1..].iter().any(|f| !f.is_empty()))
        {
            let (w, h, rgb) = crate::compiler::image::texture_files(t, id).map_err(err)?;
            images.push((t.kind, w as i32, h as i32, rgb));
        } else if t.kind == 0 {
            return Err(err(format!(
                "Cannot load 2D texture from separate files, texture '{name}' (id {id})"
            )));
        } else {
            return Err(err(format!(
                "No cubefiles defined in cube or skybox texture '{name}' (id {id})"
            )));
        }
    }
    Ok(images)
}

impl Compiled {
    pub(super) fn fill_textures_materials(&self, m: &mut ModelMut) {
        let mut adr = 0;
        for (i, (kind, width, height, rgb)) in self.textures.iter().enumerate() {
            m.tex_type[i] = *kind;
            m.tex_height[i] = *height;
            m.tex_width[i] = *width;
            m.tex_adr[i] = adr as i32;
            m.tex_rgb[adr..adr + rgb.len()].copy_from_slice(rgb);
            adr += rgb.len();
        }
        for (i, mat) in self.materials.iter().enumerate() {
            m.mat_texid[i] = self.mat_texid[i];
            m.mat_texuniform[i] = mat.texuniform as u8;
            put(m.mat_texrepeat, i, &mat.texrepeat);
            m.mat_emission[i] = mat.emission;
            m.mat_specular[i] = mat.specular;
            m.mat_shininess[i] = mat.shininess;
            m.mat_reflectance[i] = mat.reflectance;
            put(m.mat_rgba, i, &mat.rgba);
        }
        for (g, &id) in self.geom_matid.iter().enumerate() {
            m.geom_matid[g] = id;
        }
        for (s, &id) in self.site_matid.iter().enumerate() {
            m.site_matid[s] = id;
        }
        for (t, &id) in self.tendon_matid.iter().enumerate() {
            m.tendon_matid[t] = id;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Empty file attributes name no file: a cube texture with only those is rejected, as
    /// 2.2.2 rejects it (it loaded as an empty texture here).
    #[test]
    fn empty_file_attributes_are_no_cube_files() {
        let t = Texture {
            name: "body".into(),
            ..Default::default()
        };
        let e = compile(&[t]).err().map(|e| e.msg).unwrap_or_default();
        assert!(
            e.contains("No cubefiles defined in cube or skybox texture 'body' (id 0)"),
            "{e}"
        );
    }
}
