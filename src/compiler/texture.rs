//! Builtin textures (gradient, checker, flat; edge, cross and random marks), as 2.2.2 draws them.

use super::spec::Texture;

/// The C library's `rand()` after `srand(seed)` (glibc's additive feedback generator), which
/// 2.2.2 seeds with 123 before compiling so random texture marks are reproducible.
pub struct CRand {
    /// The last 32 outputs of the additive feedback r[i] = r[i-31] + r[i-3], at i mod 32.
    r: [u32; 32],
    i: usize,
}

impl CRand {
    pub fn new(seed: u32) -> Self {
        let mut init = [0u32; 34];
        init[0] = if seed == 0 { 1 } else { seed };
        for i in 1..31 {
            let prev = init[i - 1] as i32 as i64;
            let (hi, lo) = (prev / 127773, prev % 127773);
            let mut word = 16807 * lo - 2836 * hi;
            if word < 0 {
                word += 2147483647;
            }
            init[i] = word as u32;
        }
        for i in 31..34 {
            init[i] = init[i - 31];
        }
        let mut g = CRand { r: [0; 32], i: 34 };
        for (k, &v) in init.iter().enumerate().skip(2) {
            g.r[k % 32] = v;
        }
        for _ in 34..344 {
            g.step();
        }
        g
    }

    fn step(&mut self) -> u32 {
        let i = self.i;
        let v = self.r[(i - 31) % 32].wrapping_add(self.r[(i - 3) % 32]);
        self.r[i % 32] = v;
        self.i = i + 1;
        v
    }

    /// Next value in 0..=RAND_MAX.
    pub fn rand(&mut self) -> i32 {
        (self.step() >> 1) as i32
    }
}

const RAND_MAX: f64 = 2147483647.0;

fn byte(x: f64) -> u8 {
    (255.0 * x) as u8
}

fn rgb3(c: &[f64; 3]) -> [u8; 3] {
    [byte(c[0]), byte(c[1]), byte(c[2])]
}

/// The odd part of 2.2.2's sigmoid blend by `pos` in (-1, 1): exactly negated for -pos (square,
/// root and divisions keep the sign symmetric), so one evaluation serves both.
fn sigmoid(pos: f64) -> f64 {
    let correction = 1.0 / 2f64.sqrt();
    pos / (1.0 + pos * pos).sqrt() / correction
}

/// The color at blend weight 0.5 * (1 + odd), clamped to [0, 1].
fn blend(rgb1: &[f64; 3], rgb2: &[f64; 3], odd: f64) -> [u8; 3] {
    let alpha = (0.5 * (1.0 + odd)).clamp(0.0, 1.0);
    let mut out = [0u8; 3];
    for j in 0..3 {
        out[j] = byte(alpha * rgb1[j] + (1.0 - alpha) * rgb2[j]);
    }
    out
}

fn set(img: &mut [u8], width: usize, r: usize, c: usize, v: [u8; 3]) {
    let k = 3 * (r * width + c);
    img[k..k + 3].copy_from_slice(&v);
}

/// Four squares: `a` top left and bottom right, `b` elsewhere. The first row of each half is
/// drawn, the others copied from the row above.
fn checker(img: &mut [u8], a: [u8; 3], b: [u8; 3], width: usize, height: usize) {
    let len = 3 * width;
    for r in 0..height {
        if r == 0 || r == height / 2 {
            let (left, right) = if r < height / 2 { (a, b) } else { (b, a) };
            let row = &mut img[r * len..(r + 1) * len];
            for (c, px) in row.chunks_exact_mut(3).enumerate() {
                px.copy_from_slice(if c < width / 2 { &left } else { &right });
            }
        } else {
            img.copy_within((r - 1) * len..r * len, r * len);
        }
    }
}

fn marks(img: &mut [u8], t: &Texture, width: usize, height: usize, faces: usize, rng: &mut CRand) {
    let m = rgb3(&t.markrgb);
    let face = 3 * width * height;
    match t.mark {
        1 => {
            for f in 0..faces {
                let img = &mut img[f * face..(f + 1) * face];
                for r in 0..height {
                    set(img, width, r, 0, m);
                    set(img, width, r, width - 1, m);
                }
                for c in 0..width {
                    set(img, width, 0, c, m);
                    set(img, width, height - 1, c, m);
                }
            }
        }
        2 => {
            for f in 0..faces {
                let img = &mut img[f * face..(f + 1) * face];
                for r in 0..height {
                    set(img, width, r, width / 2, m);
                }
                for c in 0..width {
                    set(img, width, height / 2, c, m);
                }
            }
        }
        3 if t.random > 0.0 => {
            let total = faces * width * height;
            for p in 0..total {
                if (rng.rand() as f64) < t.random * RAND_MAX {
                    img[3 * p..3 * p + 3].copy_from_slice(&m);
                }
            }
        }
        _ => {}
    }
}

/// Pixel k of n at 2k/(n-1), evaluated as the C source does: integer product, then a double
/// division.
fn pixel(k: usize, n: usize) -> f64 {
    (2 * k) as f64 / (n as f64 - 1.0)
}

/// The gradient skybox: sides blend by elevation, up and down by angle from the pole. Each row
/// goes in passes over its pixels (roots and divisions, then asin and acos, then blends), so
/// that the arithmetic runs two pixels per instruction; every value is computed as per pixel.
fn gradient_cube(img: &mut [u8], t: &Texture, width: usize) {
    let face = 3 * width * width;
    let half_pi = 0.5 * std::f64::consts::PI;
    let xx: Vec<f64> = (0..width)
        .map(|c| {
            let x = pixel(c, width) - 1.0;
            1.0 + x * x
        })
        .collect();
    let (mut side, mut up) = (vec![0.0; width], vec![0.0; width]);
    for r in 0..width {
        let y = 1.0 - pixel(r, width);
        for ((s, u), a) in side.iter_mut().zip(up.iter_mut()).zip(&xx) {
            let norm = (a + y * y).sqrt();
            *s = y / norm;
            *u = 1.0 / norm;
        }
        for (s, u) in side.iter_mut().zip(up.iter_mut()) {
            *s = s.asin();
            *u = u.acos();
        }
        for (s, u) in side.iter_mut().zip(up.iter_mut()) {
            *s = sigmoid(*s / half_pi);
            // -elup's weight: 1 + (-q) is 1 - q exactly
            *u = sigmoid(1.0 - *u / half_pi);
        }
        for c in 0..width {
            let k = 3 * (r * width + c);
            let s = blend(&t.rgb1, &t.rgb2, side[c]);
            for f in [0, 1, 4, 5] {
                img[f * face + k..f * face + k + 3].copy_from_slice(&s);
            }
            let (u, d) = (2 * face + k, 3 * face + k);
            img[u..u + 3].copy_from_slice(&blend(&t.rgb1, &t.rgb2, up[c]));
            img[d..d + 3].copy_from_slice(&blend(&t.rgb1, &t.rgb2, -up[c]));
        }
    }
}

/// Pixels (RGB bytes) of a builtin texture; `height` is the full height (6 faces for cubes).
pub fn builtin(t: &Texture, width: usize, height: usize, rng: &mut CRand) -> Vec<u8> {
    let mut img = vec![0u8; 3 * width * height];
    let (c1, c2) = (rgb3(&t.rgb1), rgb3(&t.rgb2));
    if t.kind == 0 {
        match t.builtin {
            1 => {
                // a row at a time: roots and sigmoids first, two pixels per instruction
                let mut q = vec![0.0; width];
                for r in 0..height {
                    let y = 1.0 - pixel(r, height);
                    for (c, q) in q.iter_mut().enumerate() {
                        let x = pixel(c, width) - 1.0;
                        *q = sigmoid(2.0 * (x * x + y * y).sqrt() - 1.0);
                    }
                    for (c, &q) in q.iter().enumerate() {
                        set(&mut img, width, r, c, blend(&t.rgb2, &t.rgb1, q));
                    }
                }
            }
            2 => checker(&mut img, c1, c2, width, height),
            3 => img.chunks_mut(3).for_each(|p| p.copy_from_slice(&c1)),
            _ => {}
        }
        marks(&mut img, t, width, height, 1, rng);
    } else {
        let face = 3 * width * width;
        match t.builtin {
            1 => gradient_cube(&mut img, t, width),
            2 => {
                for f in 0..6 {
                    let (a, b) = if f < 4 { (c1, c2) } else { (c2, c1) };
                    checker(&mut img[f * face..(f + 1) * face], a, b, width, width);
                }
            }
            3 => {
                for f in 0..6 {
                    let v = if f == 3 { c2 } else { c1 };
                    img[f * face..(f + 1) * face]
                        .chunks_mut(3)
                        .for_each(|p| p.copy_from_slice(&v));
                }
            }
            _ => {}
        }
        // random marks cover the whole image; edges and crosses each face
        if t.mark == 3 {
            marks(&mut img, t, width, height, 1, rng);
        } else {
            marks(&mut img, t, width, width, 6, rng);
        }
    }
    img
}
