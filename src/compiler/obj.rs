//! Wavefront OBJ reading as MuJoCo 2.2.2 gets it from tinyobjloader: its number parser, its
//! shape boundaries (the first `g` or `o` after faces ends the first shape) and its ear-clipping
//! triangulation, so that vertices and faces come out bit for bit as in the reference.

/// What 2.2.2 keeps of an OBJ file.
#[derive(Debug, Default)]
pub struct Obj {
    pub vertices: Vec<f32>,
    pub normals: Vec<f32>,
    pub texcoords: Vec<f32>,
    /// Triangles of the first shape: (vertex, normal, texcoord) indices, -1 when absent.
    pub triangles: Vec<[Corner; 3]>,
    /// Whether the file has any shape at all.
    pub has_shape: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Corner {
    pub v: i32,
    pub vn: i32,
    pub vt: i32,
}

fn is_space(c: u8) -> bool {
    c == b' ' || c == b'\t'
}

/// tinyobjloader's number parser (not correctly rounded; the reference's vertices depend on it).
fn parse_double(s: &[u8]) -> Option<f64> {
    let mut i = 0;
    let mut sign = 1.0;
    let mut leading_dot = false;
    match s.first()? {
        b'+' | b'-' => {
            if s[0] == b'-' {
                sign = -1.0;
            }
            i = 1;
            leading_dot = s.get(1) == Some(&b'.');
        }
        c if c.is_ascii_digit() => {}
        b'.' => leading_dot = true,
        _ => return None,
    }
    let mut mantissa = 0.0f64;
    let mut exponent = 0i32;
    if !leading_dot {
        let start = i;
        while i < s.len() && s[i].is_ascii_digit() {
            mantissa = mantissa * 10.0 + (s[i] - b'0') as f64;
            i += 1;
        }
        if i == start {
            return None;
        }
    }
    if i < s.len() && s[i] == b'.' {
        i += 1;
        let mut read = 1;
        const POW: [f64; 8] = [1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001];
        while i < s.len() && s[i].is_ascii_digit() {
            let p = if read < 8 {
                POW[read as usize]
            } else {
                10f64.powf(-read as f64)
            };
            mantissa += (s[i] - b'0') as i32 as f64 * p;
            read += 1;
            i += 1;
        }
    } else if i < s.len() && !matches!(s[i], b'e' | b'E') {
        return Some(sign * mantissa);
    }
    if i < s.len() && matches!(s[i], b'e' | b'E') {
        i += 1;
        let mut esign = 1;
        match s.get(i) {
            Some(b'+') => i += 1,
            Some(b'-') => {
                esign = -1;
                i += 1
            }
            Some(c) if c.is_ascii_digit() => {}
            _ => return None,
        }
        let start = i;
        while i < s.len() && s[i].is_ascii_digit() {
            exponent = exponent.wrapping_mul(10).wrapping_add((s[i] - b'0') as i32);
            i += 1;
        }
        exponent *= esign;
        if i == start {
            return None;
        }
    }
    Some(if exponent != 0 {
        sign * ldexp(mantissa * 5f64.powf(exponent as f64), exponent)
    } else {
        sign * mantissa
    })
}

/// x * 2^e (C `ldexp`), scaling in exact power-of-two steps.
fn ldexp(mut x: f64, mut e: i32) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
    }
    x * 2f64.powi(e)
}

/// Next whitespace-separated number of a line, `default` when it does not parse.
fn real(line: &[u8], pos: &mut usize, default: f64) -> (f32, bool) {
    while *pos < line.len() && is_space(line[*pos]) {
        *pos += 1;
    }
    let start = *pos;
    while *pos < line.len() && !matches!(line[*pos], b' ' | b'\t' | b'\r') {
        *pos += 1;
    }
    match parse_double(&line[start..*pos]) {
        Some(v) => (v as f32, true),
        None => (default as f32, false),
    }
}

/// C `atoi` on the start of `s`.
fn atoi(s: &[u8]) -> i32 {
    let mut i = 0;
    while i < s.len() && matches!(s[i], b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c) {
        i += 1;
    }
    let mut neg = false;
    if i < s.len() && matches!(s[i], b'+' | b'-') {
        neg = s[i] == b'-';
        i += 1;
    }
    let mut v: i64 = 0;
    while i < s.len() && s[i].is_ascii_digit() {
        v = (v * 10 + (s[i] - b'0') as i64).min(1 << 40);
        i += 1;
    }
    (if neg { -v } else { v }) as i32
}

fn fix_index(idx: i32, n: usize) -> Option<i32> {
    match idx {
        0 => None,
        i if i > 0 => Some(i - 1),
        i => Some((n as i64 + i as i64) as i32),
    }
}

/// One `v[/vt][/vn]` group; `pos` moves past it (tinyobjloader reads the line as a C string:
/// a NUL byte ends it).
fn corner(line: &[u8], pos: &mut usize, n: [usize; 3]) -> Option<Corner> {
    let skip = |p: &mut usize| {
        while *p < line.len() && !matches!(line[*p], b'/' | b' ' | b'\t' | b'\r' | 0) {
            *p += 1;
        }
    };
    let mut c = Corner {
        v: fix_index(atoi(&line[*pos..]), n[0])?,
        vn: -1,
        vt: -1,
    };
    skip(pos);
    if line.get(*pos) != Some(&b'/') {
        return Some(c);
    }
    *pos += 1;
    if line.get(*pos) == Some(&b'/') {
        *pos += 1;
        c.vn = fix_index(atoi(&line[*pos..]), n[1])?;
        skip(pos);
        return Some(c);
    }
    c.vt = fix_index(atoi(&line[*pos..]), n[2])?;
    skip(pos);
    if line.get(*pos) != Some(&b'/') {
        return Some(c);
    }
    *pos += 1;
    c.vn = fix_index(atoi(&line[*pos..]), n[1])?;
    skip(pos);
    Some(c)
}

/// Lines as tinyobjloader splits them: "\n", "\r\n" or "\r".
fn lines(text: &[u8]) -> Vec<&[u8]> {
    let mut out = Vec::new();
    let mut start = 0;
    let mut i = 0;
    while i < text.len() {
        match text[i] {
            b'\n' => {
                out.push(&text[start..i]);
                start = i + 1;
            }
            b'\r' => {
                out.push(&text[start..i]);
                if text.get(i + 1) == Some(&b'\n') {
                    i += 1;
                }
                start = i + 1;
            }
            _ => {}
        }
        i += 1;
    }
    if start < text.len() {
        out.push(&text[start..]);
    }
    out
}

/// Reads an OBJ file; the error is tinyobjloader's text.
pub fn read(text: &[u8]) -> Result<Obj, String> {
    let mut o = Obj::default();
    let mut faces: Vec<Vec<Corner>> = Vec::new();
    // first shape: closed at the first g/o that follows faces (or lines and points, for o)
    let mut first_done = false;
    let mut prims = false;
    for (k, line) in lines(text).into_iter().enumerate() {
        let mut p = 0;
        while p < line.len() && is_space(line[p]) {
            p += 1;
        }
        let t = &line[p..];
        if t.is_empty() || t[0] == 0 || t[0] == b'#' {
            continue;
        }
        let at = |i: usize| t.get(i).copied().unwrap_or(0);
        if at(0) == b'v' && is_space(at(1)) {
            let mut q = p + 2;
            for _ in 0..3 {
                o.vertices.push(real(line, &mut q, 0.0).0);
            }
        } else if at(0) == b'v' && at(1) == b'n' && is_space(at(2)) {
            let mut q = p + 3;
            for _ in 0..3 {
                o.normals.push(real(line, &mut q, 0.0).0);
            }
        } else if at(0) == b'v' && at(1) == b't' && is_space(at(2)) {
            let mut q = p + 3;
            for _ in 0..2 {
                o.texcoords.push(real(line, &mut q, 0.0).0);
            }
        } else if matches!(at(0), b'f' | b'l' | b'p') && is_space(at(1)) {
            let mut q = p + 2;
            if at(0) == b'f' {
                while q < line.len() && is_space(line[q]) {
                    q += 1;
                }
            }
            let n = [
                o.vertices.len() / 3,
                o.normals.len() / 3,
                o.texcoords.len() / 2,
            ];
            let mut face = Vec::new();
            while q < line.len() && !matches!(line[q], b'\r' | b'\n' | 0) {
                let what = if at(0) == b'f' {
                    "`f' line(e.g. zero value for face index"
                } else if at(0) == b'l' {
                    "`l' line(e.g. zero value for vertex index"
                } else {
                    "`p' line(e.g. zero value for vertex index"
                };
                let c = corner(line, &mut q, n)
                    .ok_or_else(|| format!("Failed parse {what}. line {})\n", k + 1))?;
                face.push(c);
                while q < line.len() && matches!(line[q], b' ' | b'\t' | b'\r') {
                    q += 1;
                }
            }
            if at(0) == b'f' {
                if !first_done {
                    faces.push(face);
                }
            } else {
                prims = true;
            }
        } else if matches!(at(0), b'g' | b'o') && is_space(at(1)) {
            let ends = !faces.is_empty() || (at(0) == b'o' && prims);
            if !first_done && ends {
                first_done = true;
            }
            if !first_done {
                prims = false;
            }
        }
    }
    o.has_shape = !faces.is_empty() || prims;
    for f in &faces {
        triangulate(f, &o.vertices, &mut o.triangles);
    }
    Ok(o)
}

/// Point-in-triangle test (crossing number), as tinyobjloader's `pnpoly`.
fn pnpoly(vx: &[f32; 3], vy: &[f32; 3], tx: f32, ty: f32) -> bool {
    let mut c = false;
    let mut j = 2;
    for i in 0..3 {
        if ((vy[i] > ty) != (vy[j] > ty))
            && (tx < (vx[j] - vx[i]) * (ty - vy[i]) / (vy[j] - vy[i]) + vx[i])
        {
            c = !c;
        }
        j = i;
    }
    c
}

/// Splits a polygon into triangles by ear clipping in its dominant plane.
fn triangulate(face: &[Corner], v: &[f32], out: &mut Vec<[Corner; 3]>) {
    let n = face.len();
    if n < 3 {
        return;
    }
    let coord = |c: Corner, a: usize| -> Option<f32> { v.get(3 * c.v as usize + a).copied() };
    let mut axes = [1usize, 2];
    for k in 0..n {
        let p: Vec<Option<[f32; 3]>> = (0..3)
            .map(|d| {
                let c = face[(k + d) % n];
                Some([coord(c, 0)?, coord(c, 1)?, coord(c, 2)?])
            })
            .collect();
        let (Some(a), Some(b), Some(c)) = (p[0], p[1], p[2]) else {
            continue;
        };
        let e0 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let e1 = [c[0] - b[0], c[1] - b[1], c[2] - b[2]];
        let cx = (e0[1] * e1[2] - e0[2] * e1[1]).abs();
        let cy = (e0[2] * e1[0] - e0[0] * e1[2]).abs();
        let cz = (e0[0] * e1[1] - e0[1] * e1[0]).abs();
        if cx > f32::EPSILON || cy > f32::EPSILON || cz > f32::EPSILON {
            if !(cx > cy && cx > cz) {
                axes[0] = 0;
                if cz > cx && cz > cy {
                    axes[1] = 1;
                }
            }
            break;
        }
    }
    let mut area = 0.0f32;
    for k in 0..n {
        let (c0, c1) = (face[k], face[(k + 1) % n]);
        if let (Some(x0), Some(y0), Some(x1), Some(y1)) = (
            coord(c0, axes[0]),
            coord(c0, axes[1]),
            coord(c1, axes[0]),
            coord(c1, axes[1]),
        ) {
            area += (x0 * y1 - y0 * x1) * 0.5;
        }
    }
    let mut rest = face.to_vec();
    let mut guess = 0usize;
    let mut iterations = n;
    let mut previous = n;
    while rest.len() > 3 && iterations > 0 {
        let m = rest.len();
        if guess >= m {
            guess -= m;
        }
        if previous != m {
            previous = m;
            iterations = m;
        } else {
            iterations -= 1;
        }
        let mut ind = [rest[0]; 3];
        let (mut vx, mut vy) = ([0.0f32; 3], [0.0f32; 3]);
        for k in 0..3 {
            ind[k] = rest[(guess + k) % m];
            if let (Some(x), Some(y)) = (coord(ind[k], axes[0]), coord(ind[k], axes[1])) {
                (vx[k], vy[k]) = (x, y);
            }
        }
        let cross = (vx[1] - vx[0]) * (vy[2] - vy[1]) - (vy[1] - vy[0]) * (vx[2] - vx[1]);
        if cross * area < 0.0 {
            guess += 1;
            continue;
        }
        let overlap = (3..m).any(|other| {
            let c = rest[(guess + other) % m];
            match (coord(c, axes[0]), coord(c, axes[1])) {
                (Some(tx), Some(ty)) => pnpoly(&vx, &vy, tx, ty),
                _ => false,
            }
        });
        if overlap {
            guess += 1;
            continue;
        }
        out.push(ind);
        rest.remove((guess + 1) % m);
    }
    if rest.len() == 3 {
        out.push([rest[0], rest[1], rest[2]]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_as_tinyobjloader_reads_them() {
        assert_eq!(parse_double(b"1.5"), Some(1.5));
        assert_eq!(parse_double(b"-.25"), Some(-0.25));
        assert_eq!(parse_double(b"2e3"), Some(2000.0));
        assert_eq!(parse_double(b"x"), None);
        // fraction digits accumulate term by term, not correctly rounded
        let v = parse_double(b"0.123456789").unwrap();
        let mut m = 0.0;
        for (k, d) in [1, 2, 3, 4, 5, 6, 7, 8, 9].iter().enumerate() {
            m += *d as f64 * 10f64.powi(-(k as i32 + 1));
        }
        assert!((v - m).abs() < 1e-15);
    }

    #[test]
    fn quads_split_into_two_triangles() {
        let o = read(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").unwrap();
        let t: Vec<[i32; 3]> = o.triangles.iter().map(|t| t.map(|c| c.v)).collect();
        assert_eq!(t, vec![[0, 1, 2], [0, 2, 3]]);
        assert!(read(b"v 0 0 0\nf 0 1 2\n").is_err());
    }

    #[test]
    fn a_nul_byte_ends_the_line() {
        let o = read(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1/1/3\0\0\x80\x7f/3 2 3\nf 1 2 3\n").unwrap();
        let t: Vec<[i32; 3]> = o.triangles.iter().map(|t| t.map(|c| c.v)).collect();
        assert_eq!(t, vec![[0, 1, 2]]);
    }
}
