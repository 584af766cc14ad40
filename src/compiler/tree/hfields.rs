//! Height fields: elevation from a file, inline data or zeros, then the height field arrays.

use super::*;

pub(super) fn compile(hfields: &mut [HField]) -> Result<(), CError> {
    // height fields: elevation is all zero without a file
    for (id, hf) in hfields.iter_mut().enumerate() {
        let (name, line) = (hf.name.clone(), hf.line);
        let err = |m: String| CError::at(m, &name, id, line);
        if hf.size.iter().any(|&s| s <= 0.0) {
            return Err(err(format!(
                "size parameter is not positive in hfield '{name}' (id = {id})"
            )));
        }
        if !hf.file.is_empty() {
            if hf.nrow != 0 || hf.ncol != 0 {
                return Err(err(format!(
                    "hfield '{name}' (id = {id}) specified from file and manually"
                )));
            }
            let (nrow, ncol, data) = crate::compiler::image::hfield_file(hf, id).map_err(err)?;
            (hf.nrow, hf.ncol, hf.data) = (nrow as i32, ncol as i32, data);
        }
        if hf.nrow < 1 || hf.ncol < 1 {
            return Err(err(format!("hfield '{name}' (id = {id}) not specified")));
        }
    }
    Ok(())
}

impl Compiled {
    pub(super) fn fill_hfields(&self, m: &mut ModelMut) {
        let mut adr = 0;
        for (i, hf) in self.hfields.iter().enumerate() {
            put(m.hfield_size, i, &hf.size);
            m.hfield_nrow[i] = hf.nrow;
            m.hfield_ncol[i] = hf.ncol;
            m.hfield_adr[i] = adr;
            let a = adr as usize;
            m.hfield_data[a..a + hf.data.len()].copy_from_slice(&hf.data);
            adr += hf.nrow * hf.ncol;
        }
        for (g, hf) in self.geom_hfield.iter().enumerate() {
            if let Some(h) = hf {
                m.geom_dataid[g] = *h as i32;
            }
        }
    }
}
