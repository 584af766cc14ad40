//! Image files for textures and height fields: PNG (decoded to 8-bit RGB or grey the way
//! 2.2.2's lodepng converts: 16-bit keeps the high byte, grey from colour keeps red, alpha
//! is dropped) and MuJoCo's custom binary formats.

/// A decoded image: `width * height` pixels of `channels` bytes, rows top to bottom.
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub data: Vec<u8>,
}

/// Whether a file name selects the PNG decoder (case-insensitive ".png" suffix).
pub fn is_png(name: &str) -> bool {
    name.len() >= 4 && name[name.len() - 4..].eq_ignore_ascii_case(".png")
}

/// Decodes a PNG to 8-bit RGB (`grey == false`) or 8-bit grey (`grey == true`).
pub fn decode_png(bytes: &[u8], grey: bool) -> Result<Image, String> {
    // lodepng's texts for the commonest failures; others come from the png crate
    if bytes.len() < 29 {
        return Err("PNG file is smaller than a PNG header".into());
    }
    if bytes[..8] != [137, 80, 78, 71, 13, 10, 26, 10] {
        return Err("incorrect PNG signature, it's no PNG or corrupted".into());
    }
    let mut dec = png::Decoder::new(std::io::Cursor::new(bytes));
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().map_err(|e| e.to_string())?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| "image too large".to_string())?;
    // deflate expands at most about 1032:1: a header asking for more pixels than the file's
    // data can hold is corrupt (and its buffer could exceed memory)
    if size / 1032 > bytes.len() + 4096 {
        return Err("image data too small for the image size in the header".into());
    }
    let mut buf = vec![0u8; size];
    let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let (width, height) = (info.width as usize, info.height as usize);
    let nc = info.color_type.samples();
    let out_nc = if grey { 1 } else { 3 };
    let mut data = Vec::with_capacity(width * height * out_nc);
    for r in 0..height {
        let row = &buf[r * info.line_size..r * info.line_size + width * nc];
        for px in row.chunks_exact(nc) {
            // grey (+alpha) inputs replicate the grey value; colour inputs keep red for grey
            let rgb = if nc < 3 {
                [px[0]; 3]
            } else {
                [px[0], px[1], px[2]]
            };
            if grey {
                data.push(rgb[0]);
            } else {
                data.extend_from_slice(&rgb);
            }
        }
    }
    Ok(Image {
        width,
        height,
        data,
    })
}

fn read_i32(b: &[u8], i: usize) -> i32 {
    i32::from_ne_bytes([b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]])
}

/// Custom texture file: int32 width, int32 height, then width*height RGB bytes.
/// `Err(true)` for bad dimensions, `Err(false)` for a bad file size.
pub fn decode_custom_texture(b: &[u8]) -> Result<Image, bool> {
    if b.len() < 8 {
        return Err(true);
    }
    let (w, h) = (read_i32(b, 0), read_i32(b, 1));
    if w < 1 || h < 1 {
        return Err(true);
    }
    let n = (w as usize) * (h as usize) * 3;
    if b.len() != 8 + n {
        return Err(false);
    }
    Ok(Image {
        width: w as usize,
        height: h as usize,
        data: b[8..].to_vec(),
    })
}

/// Custom height field file: int32 nrow, int32 ncol, then nrow*ncol float32.
/// Returns (nrow, ncol, data) or an error message without the hfield context.
pub fn decode_custom_hfield(b: &[u8]) -> Result<(usize, usize, Vec<f32>), &'static str> {
    if b.len() < 8 {
        return Err("could not read");
    }
    let (nrow, ncol) = (read_i32(b, 0), read_i32(b, 1));
    if nrow < 1 || ncol < 1 {
        return Err("non-positive hfield dimensions");
    }
    let n = (nrow as usize) * (ncol as usize);
    if b.len() != 8 + 4 * n {
        return Err("unexpected file size");
    }
    let data = (0..n)
        .map(|i| f32::from_bits(read_i32(b, 2 + i) as u32))
        .collect();
    Ok((nrow as usize, ncol as usize, data))
}

/// Height field from a grey PNG: rows are stored bottom to top.
pub fn hfield_from_grey(img: &Image) -> Vec<f32> {
    let (w, h) = (img.width, img.height);
    let mut data = vec![0f32; w * h];
    for r in 0..h {
        for c in 0..w {
            data[c + (h - 1 - r) * w] = img.data[c + r * w] as f32;
        }
    }
    data
}

/// Maps elevation to [0, 1] as 2.2.2 does (in f32; a flat field becomes all zero).
/// Returns false when the range is invalid (empty data).
pub fn normalize_hfield(data: &mut [f32]) -> bool {
    let (mut emin, mut emax) = (1e10f32, -1e10f32);
    for &v in data.iter() {
        emin = emin.min(v);
        emax = emax.max(v);
    }
    if emin > emax {
        return false;
    }
    for v in data.iter_mut() {
        *v -= emin;
        if (emax - emin) as f64 > 1e-15 {
            *v /= emax - emin;
        }
    }
    true
}

/// Flips an RGB image in place, horizontally and/or vertically.
pub fn flip(img: &mut Image, hflip: bool, vflip: bool) {
    let (w, h) = (img.width, img.height);
    if hflip {
        for r in 0..h {
            for c in 0..w / 2 {
                let (a, b) = (3 * (r * w + c), 3 * (r * w + w - 1 - c));
                for k in 0..3 {
                    img.data.swap(a + k, b + k);
                }
            }
        }
    }
    if vflip {
        for r in 0..h / 2 {
            for c in 0..w {
                let (a, b) = (3 * (r * w + c), 3 * ((h - 1 - r) * w + c));
                for k in 0..3 {
                    img.data.swap(a + k, b + k);
                }
            }
        }
    }
}

/// File name as 2.2.2 builds it: absolute names stay, else model dir + asset dir + name.
pub fn full_name(model_dir: &str, asset_dir: &str, file: &str, strippath: bool) -> String {
    let file = if strippath {
        file.rsplit(['/', '\\']).next().unwrap_or(file)
    } else {
        file
    };
    let absolute = |p: &str| p.starts_with(['/', '\\']) || p.contains(":/") || p.contains(":\\");
    // a non-empty asset directory ends with a separator
    let mut asset_dir = asset_dir.to_string();
    if !asset_dir.is_empty() && !asset_dir.ends_with(['/', '\\']) {
        asset_dir.push('/');
    }
    let asset_dir = asset_dir.as_str();
    if absolute(file) {
        file.to_string()
    } else if absolute(asset_dir) {
        format!("{asset_dir}{file}")
    } else {
        format!("{model_dir}{asset_dir}{file}")
    }
}

/// Reads the files that height fields name (before compiling, while the VFS is at hand).
pub fn load_files(
    spec: &mut crate::compiler::spec::ModelSpec,
    model_dir: &str,
    load: &mut dyn FnMut(&str) -> Option<Vec<u8>>,
) {
    let c = &spec.compiler;
    for m in spec.meshes.iter_mut().filter(|m| !m.file.is_empty()) {
        m.short_file = if c.strippath {
            m.file.rsplit(['/', '\\']).next().unwrap_or("").to_string()
        } else {
            m.file.clone()
        };
        let name = full_name(model_dir, &c.meshdir, &m.file, c.strippath);
        m.bytes = load(&name);
        m.file = name;
    }
    for hf in spec.hfields.iter_mut().filter(|h| !h.file.is_empty()) {
        let name = full_name(model_dir, &c.meshdir, &hf.file, c.strippath);
        hf.bytes = load(&name).filter(|b| !b.is_empty());
        hf.file = name;
    }
    for sk in spec.skins.iter_mut().filter(|s| !s.file.is_empty()) {
        sk.path = full_name(model_dir, &c.meshdir, &sk.file, c.strippath);
        sk.bytes = load(&sk.path);
    }
    for t in spec.textures.iter_mut() {
        for k in 0..7 {
            if !t.file_names[k].is_empty() {
                let name = full_name(model_dir, &c.texturedir, &t.file_names[k], c.strippath);
                t.bytes[k] = load(&name).filter(|b| !b.is_empty());
                t.file_names[k] = name;
            }
        }
    }
}

/// One texture image file, decoded (PNG or custom) and flipped as the texture asks.
fn texture_image(t: &crate::compiler::spec::Texture, k: usize, id: usize) -> Result<Image, String> {
    let file = &t.file_names[k];
    let bytes = t.bytes[k].as_deref();
    let mut img = if is_png(file) {
        let img = match bytes {
            Some(b) => decode_png(b, false),
            None => Err("failed to open file for reading".to_string()),
        }
        .map_err(|e| format!("PNG file load error '{e}' in texture id = {id}"))?;
        if img.width < 1 || img.height < 1 {
            return Err(format!("Empty PNG file in texture '{file}' (id {id})"));
        }
        img
    } else {
        let b = bytes.ok_or_else(|| format!("could not open texture file '{file}'"))?;
        decode_custom_texture(b).map_err(|dims| {
            let what = if dims {
                "non-positive texture dimensions"
            } else {
                "unexpected file size"
            };
            format!("Non-PNG texture, assuming custom binary file format,\n{what} in file '{file}'")
        })?
    };
    flip(&mut img, t.hflip, t.vflip);
    Ok(img)
}

/// Fills the faces not loaded with rgb1.
fn fill_faces(rgb: &mut [u8], width: usize, loaded: &[bool; 6], rgb1: &[f64; 3]) {
    let face = 3 * width * width;
    for (i, _) in loaded.iter().enumerate().filter(|(_, l)| !**l) {
        for px in rgb[i * face..(i + 1) * face].chunks_exact_mut(3) {
            for j in 0..3 {
                px[j] = (255.0 * rgb1[j]) as u8;
            }
        }
    }
}

/// A texture from files: (width, height, rgb) or the error message.
pub fn texture_files(
    t: &crate::compiler::spec::Texture,
    id: usize,
) -> Result<(usize, usize, Vec<u8>), String> {
    if !t.file_names[0].is_empty() {
        if t.kind == 0 {
            let img = texture_image(t, 0, id)?;
            return Ok((img.width, img.height, img.data));
        }
        let g = t.gridsize;
        if g[0] < 1 || g[1] < 1 || g[0] * g[1] > 12 {
            return Err(format!(
                "gridsize must be non-zero and no more than 12 squares in texture '{}' (id {id})",
                t.name
            ));
        }
        let img = texture_image(t, 0, id)?;
        let (w, h) = (img.width, img.height);
        let (g0, g1) = (g[0] as usize, g[1] as usize);
        if w / g1 != h / g0 || w % g1 != 0 || h % g0 != 0 {
            return Err(format!(
                "PNG size must be integer multiple of gridsize in texture '{}' (id {id})",
                t.file_names[0]
            ));
        }
        if g0 == 1 && g1 == 1 {
            return Ok((w, w, img.data[..3 * w * w].to_vec()));
        }
        let width = w / g1;
        let mut rgb = vec![0u8; 3 * width * 6 * width];
        let mut loaded = [false; 6];
        let layout = t.gridlayout.as_bytes();
        for k in 0..g0 * g1 {
            let sym = layout.get(k).copied().unwrap_or(0);
            let i = match b"RLUDFB".iter().position(|&s| s == sym) {
                Some(i) => i,
                None if sym == b'.' => continue,
                None => {
                    return Err(format!(
                        "gridlayout symbol is not among '.RLUDFB' in texture '{}' (id {id})",
                        t.file_names[0]
                    ))
                }
            };
            let (rstart, cstart) = (width * (k / g1), width * (k % g1));
            for j in 0..width {
                let src = (j + rstart) * 3 * w + 3 * cstart;
                let dst = i * 3 * width * width + j * 3 * width;
                rgb[dst..dst + 3 * width].copy_from_slice(&img.data[src..src + 3 * width]);
            }
            loaded[i] = true;
        }
        fill_faces(&mut rgb, width, &loaded, &t.rgb1);
        return Ok((width, 6 * width, rgb));
    }
    // separate cube faces
    let mut rgb: Vec<u8> = Vec::new();
    let mut width = 0;
    let mut loaded = [false; 6];
    for i in 0..6 {
        if t.file_names[i + 1].is_empty() {
            continue;
        }
        let short = t.file_names[i + 1].rsplit(['/', '\\']).next().unwrap_or("");
        let img = texture_image(t, i + 1, id)?;
        if img.width != img.height {
            return Err(format!(
                "Non-square PNG file '{short}' in cube or skybox id {id}"
            ));
        }
        if rgb.is_empty() {
            width = img.width;
            rgb = vec![0u8; 3 * width * 6 * width];
        } else if width != img.width {
            return Err(format!(
                "PNG file '{short}' has incompatible size in texture id {id}"
            ));
        }
        let face = 3 * width * width;
        rgb[i * face..(i + 1) * face].copy_from_slice(&img.data[..face]);
        loaded[i] = true;
    }
    fill_faces(&mut rgb, width, &loaded, &t.rgb1);
    Ok((width, 6 * width, rgb))
}

/// Elevation of a height field from its file, normalised; (nrow, ncol, data) or the error.
pub fn hfield_file(
    hf: &crate::compiler::spec::HField,
    id: usize,
) -> Result<(usize, usize, Vec<f32>), String> {
    let file = &hf.file;
    let (nrow, ncol, mut data) = if is_png(file) {
        let img = match &hf.bytes {
            Some(b) => decode_png(b, true),
            None => Err("failed to open file for reading".to_string()),
        }
        .map_err(|e| format!("PNG load error '{e}' in hfield id = {id}"))?;
        if img.width < 1 || img.height < 1 {
            return Err(format!(
                "Zero dimension in PNG hfield '{}' (id = {id})",
                hf.name
            ));
        }
        (img.height, img.width, hfield_from_grey(&img))
    } else {
        let Some(bytes) = &hf.bytes else {
            return Err(format!("could not open hfield file '{file}'"));
        };
        decode_custom_hfield(bytes).map_err(|e| match e {
            "could not read" => format!("hfield missing header '{file}'"),
            _ => format!("{e} in file '{file}'"),
        })?
    };
    if !normalize_hfield(&mut data) {
        return Err(format!("invalid data range in hfield '{file}'"));
    }
    Ok((nrow, ncol, data))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn encode(w: u32, h: u32, ct: png::ColorType, bd: png::BitDepth, data: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, w, h);
            enc.set_color(ct);
            enc.set_depth(bd);
            let mut wr = enc.write_header().unwrap();
            wr.write_image_data(data).unwrap();
        }
        out
    }

    #[test]
    fn rgba_and_16bit_and_grey() {
        let p = encode(
            2,
            1,
            png::ColorType::Rgba,
            png::BitDepth::Eight,
            &[1, 2, 3, 4, 5, 6, 7, 8],
        );
        assert_eq!(decode_png(&p, false).unwrap().data, vec![1, 2, 3, 5, 6, 7]);
        assert_eq!(decode_png(&p, true).unwrap().data, vec![1, 5]);
        let p = encode(
            1,
            1,
            png::ColorType::Rgb,
            png::BitDepth::Sixteen,
            &[9, 1, 8, 2, 7, 3],
        );
        assert_eq!(decode_png(&p, false).unwrap().data, vec![9, 8, 7]);
        let p = encode(
            4,
            1,
            png::ColorType::Grayscale,
            png::BitDepth::Two,
            &[0b00_01_10_11],
        );
        assert_eq!(decode_png(&p, false).unwrap().data.len(), 12);
        assert_eq!(decode_png(&p, true).unwrap().data, vec![0, 85, 170, 255]);
        assert!(decode_png(b"not a png", false).is_err());
    }

    #[test]
    fn hfield_rows_and_range() {
        let img = Image {
            width: 2,
            height: 2,
            data: vec![0, 10, 20, 40],
        };
        let mut d = hfield_from_grey(&img);
        assert_eq!(d, vec![20.0, 40.0, 0.0, 10.0]);
        assert!(normalize_hfield(&mut d));
        assert_eq!(d, vec![0.5, 1.0, 0.0, 0.25]);
        assert!(!normalize_hfield(&mut []));
    }
}
