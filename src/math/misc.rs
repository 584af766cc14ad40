//! Actuator curves, contact pyramids, scalar helpers, sorting and other small utilities.

use super::MINVAL;

/// Largest representable value MuJoCo accepts as sane.
pub const MAXVAL: f64 = 1e10;

/// -1 as a factor where 2.2.2 scales by -1: a product keeps a NaN's sign, a negation flips
/// it, and the compiler makes a product with a known -1 a negation; this one it cannot see.
#[inline(always)]
pub fn minus_one() -> f64 {
    std::hint::black_box(-1.0)
}

#[inline]
fn max_c(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// Active muscle force (negative); prm = (range[2], force, scale, lmin, lmax, vmax, fpmax, fvmax).
pub fn muscle_gain(len: f64, vel: f64, lengthrange: &[f64], acc0: f64, prm: &[f64]) -> f64 {
    let (r0, r1) = (prm[0], prm[1]);
    let mut force = prm[2];
    let scale = prm[3];
    let (lmin, lmax, vmax, fvmax) = (prm[4], prm[5], prm[6], prm[8]);
    if force < 0.0 {
        force = scale / max_c(MINVAL, acc0);
    }

    let a = 0.5 * (lmin + 1.0);
    let b = 0.5 * (1.0 + lmax);
    let l0 = (lengthrange[1] - lengthrange[0]) / max_c(MINVAL, r1 - r0);
    let l = r0 + (len - lengthrange[0]) / max_c(MINVAL, l0);
    let v = vel / max_c(MINVAL, l0 * vmax);

    let fl = if l >= lmin && l <= a {
        let x = (l - lmin) / max_c(MINVAL, a - lmin);
        0.5 * x * x
    } else if l <= 1.0 {
        let x = (1.0 - l) / max_c(MINVAL, 1.0 - a);
        1.0 - 0.5 * x * x
    } else if l <= b {
        let x = (l - 1.0) / max_c(MINVAL, b - 1.0);
        1.0 - 0.5 * x * x
    } else if l <= lmax {
        let x = (lmax - l) / max_c(MINVAL, lmax - b);
        0.5 * x * x
    } else {
        0.0
    };

    let y = fvmax - 1.0;
    let fv = if v <= -1.0 {
        0.0
    } else if v <= 0.0 {
        (v + 1.0) * (v + 1.0)
    } else if v <= y {
        fvmax - (y - v) * (y - v) / max_c(MINVAL, y)
    } else {
        fvmax
    };

    -force * fl * fv
}

/// Passive muscle force (negative).
pub fn muscle_bias(len: f64, lengthrange: &[f64], acc0: f64, prm: &[f64]) -> f64 {
    let (r0, r1) = (prm[0], prm[1]);
    let mut force = prm[2];
    let scale = prm[3];
    let (lmax, fpmax) = (prm[5], prm[7]);
    if force < 0.0 {
        force = scale / max_c(MINVAL, acc0);
    }
    let l0 = (lengthrange[1] - lengthrange[0]) / max_c(MINVAL, r1 - r0);
    let l = r0 + (len - lengthrange[0]) / max_c(MINVAL, l0);

    let b = 0.5 * (1.0 + lmax);
    if l <= 1.0 {
        0.0
    } else if l <= b {
        let x = (l - 1.0) / max_c(MINVAL, b - 1.0);
        -force * fpmax * 0.5 * x * x
    } else {
        let x = (l - b) / max_c(MINVAL, b - 1.0);
        -force * fpmax * (0.5 + x)
    }
}

/// Muscle activation rate; prm = (tau_act, tau_deact).
pub fn muscle_dynamics(ctrl: f64, act: f64, prm: &[f64]) -> f64 {
    let c = clip(ctrl, 0.0, 1.0);
    let a = clip(act, 0.0, 1.0);
    let tau = if c > act {
        prm[0] * (0.5 + 1.5 * a)
    } else {
        prm[1] / (0.5 + 1.5 * a)
    };
    (c - act) / max_c(MINVAL, tau)
}

/// Contact force (normal, tangents) to pyramid edge forces, 2*(dim-1) of them.
pub fn encode_pyramid(pyramid: &mut [f64], force: &[f64], mu: &[f64], dim: usize) {
    let a = force[0] / (dim as f64 - 1.0);
    for i in 0..dim.saturating_sub(1) {
        let b = min(a, force[i + 1] / mu[i]);
        pyramid[2 * i] = 0.5 * (a + b);
        pyramid[2 * i + 1] = 0.5 * (a - b);
    }
}

/// Pyramid edge forces back to the contact force (normal, tangents).
pub fn decode_pyramid(force: &mut [f64], pyramid: &[f64], mu: &[f64], dim: usize) {
    if dim == 1 {
        force[0] = pyramid[0];
        return;
    }
    force[0] = 0.0;
    for p in &pyramid[..2 * dim.saturating_sub(1)] {
        force[0] += p;
    }
    for i in 0..dim.saturating_sub(1) {
        force[i + 1] = (pyramid[2 * i] - pyramid[2 * i + 1]) * mu[i];
    }
}

/// Position after time t of x'' + b*x' + k*x = 0 from (pos0, vel0), solved analytically.
pub fn spring_damper(pos0: f64, vel0: f64, k: f64, b: f64, t: f64) -> f64 {
    let det = b * b - 4.0 * k;
    if det > MINVAL {
        let w = det.sqrt() / 2.0;
        let r1 = -b / 2.0 + w;
        let r2 = -b / 2.0 - w;
        let c1 = (pos0 * r2 - vel0) / (r2 - r1);
        let c2 = (pos0 * r1 - vel0) / (r1 - r2);
        c1 * (r1 * t).exp() + c2 * (r2 * t).exp()
    } else if det >= -MINVAL {
        let c1 = pos0;
        let c2 = vel0 + b * c1 / 2.0;
        (-b * t / 2.0).exp() * (c1 + c2 * t)
    } else {
        let w = det.abs().sqrt() / 2.0;
        let c1 = pos0;
        let c2 = (vel0 + b * c1 / 2.0) / w;
        (-b * t / 2.0).exp() * (c1 * (w * t).cos() + c2 * (w * t).sin())
    }
}

/// x * w, or +0 for a zero weight: the term of a sum that skips zero weights (as 2.2.2's
/// products do) without a branch. Adding +0 leaves any such sum as it was, since a sum that
/// starts at +0 is never -0; only x * 0 of an infinite or NaN x is kept out, as the skip does.
#[inline(always)]
pub fn weighted(x: f64, w: f64) -> f64 {
    if w != 0.0 {
        x * w
    } else {
        0.0
    }
}

/// x, or -0 where `keep` is false, by a bit mask (no branch): the term of a sum that leaves
/// some terms out, since s + -0 is s bit for bit for every s (-0 and NaN included).
#[inline(always)]
pub fn kept_or_neg_zero(x: f64, keep: bool) -> f64 {
    let mask = (keep as u64).wrapping_neg();
    f64::from_bits((x.to_bits() & mask) | ((-0.0f64).to_bits() & !mask))
}

/// a if a <= b, else b (NaN handling as in MuJoCo).
#[inline]
pub fn min(a: f64, b: f64) -> f64 {
    if a <= b {
        a
    } else {
        b
    }
}

/// a if a >= b, else b (NaN handling as in MuJoCo).
#[inline]
pub fn max(a: f64, b: f64) -> f64 {
    if a >= b {
        a
    } else {
        b
    }
}

#[inline]
pub fn clip(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}

#[inline]
pub fn sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else if x > 0.0 {
        1.0
    } else {
        0.0
    }
}

/// Nearest integer, ties rounded up.
pub fn round(x: f64) -> i32 {
    let lo = x.floor();
    let hi = x.ceil();
    to_int(if x - lo < hi - x { lo } else { hi })
}

/// double-to-int conversion as C performs it on x86-64: NaN and out-of-range values give
/// i32::MIN (the "integer indefinite" value), where Rust's `as` would saturate.
pub fn to_int(v: f64) -> i32 {
    if (-2147483648.0..2147483648.0).contains(&v) {
        v as i32
    } else {
        i32::MIN
    }
}

/// Names of mjtObj values, indexed by type (index 0, mjOBJ_UNKNOWN, has none).
pub const OBJ_NAMES: [&str; 24] = [
    "", "body", "xbody", "joint", "dof", "geom", "site", "camera", "light", "mesh", "skin",
    "hfield", "texture", "material", "pair", "exclude", "equality", "tendon", "actuator", "sensor",
    "numeric", "text", "tuple", "key",
];

/// Name of an object type, None for unknown types.
pub fn type2str(t: i32) -> Option<&'static str> {
    if t >= 1 && (t as usize) < OBJ_NAMES.len() {
        Some(OBJ_NAMES[t as usize])
    } else {
        None
    }
}

/// Object type of a name, 0 (mjOBJ_UNKNOWN) when not found.
pub fn str2type(s: &[u8]) -> i32 {
    OBJ_NAMES
        .iter()
        .skip(1)
        .position(|n| n.as_bytes() == s)
        .map_or(0, |i| i as i32 + 1)
}

/// Text of a warning (mjtWarning) with its info number.
pub fn warning_text(warning: i32, info: i32) -> String {
    let mut s = String::new();
    let _ = write_warning_text(&mut s, warning, info);
    s
}

/// Writes the text of `warning_text` (no allocation of its own).
pub fn write_warning_text(
    w: &mut impl std::fmt::Write,
    warning: i32,
    info: i32,
) -> std::fmt::Result {
    match warning {
        0 => write!(
            w,
            "Inertia matrix is too close to singular at DOF {info}. Check model."
        ),
        1 => write!(
            w,
            "Pre-allocated contact buffer is full. Increase nconmax above {info}."
        ),
        2 => write!(
            w,
            "Pre-allocated constraint buffer is full. Increase njmax above {info}."
        ),
        3 => write!(
            w,
            "Pre-allocated visual geom buffer is full. Increase maxgeom above {info}."
        ),
        4 => write!(
            w,
            "Nan, Inf or huge value in QPOS at DOF {info}. The simulation is unstable."
        ),
        5 => write!(
            w,
            "Nan, Inf or huge value in QVEL at DOF {info}. The simulation is unstable."
        ),
        6 => write!(
            w,
            "Nan, Inf or huge value in QACC at DOF {info}. The simulation is unstable."
        ),
        7 => write!(
            w,
            "Nan, Inf or huge value in CTRL at ACTUATOR {info}. The simulation is unstable."
        ),
        _ => write!(w, "Unknown warning type {warning}."),
    }
}

/// NaN or magnitude above MAXVAL.
#[inline]
pub fn is_bad(x: f64) -> bool {
    !(-MAXVAL..=MAXVAL).contains(&x)
}

pub fn is_zero(vec: &[f64]) -> bool {
    vec.iter().all(|&x| x == 0.0)
}

/// Polar Box-Muller sample pair from a uniform integer source in [0, rand_max].
pub fn standard_normal(mut rand: impl FnMut() -> i32, rand_max: i32) -> (f64, f64) {
    let scale = 2.0 / rand_max as f64;
    loop {
        let x1 = scale * rand() as f64 - 1.0;
        let x2 = scale * rand() as f64 - 1.0;
        let w = x1 * x1 + x2 * x2;
        if w < 1.0 && w != 0.0 {
            let w = ((-2.0 * w.ln()) / w).sqrt();
            return (x1 * w, x2 * w);
        }
    }
}

/// Sorts increasingly by insertion (stable; NaN handling as in MuJoCo).
pub fn insertion_sort<T: Copy + PartialOrd>(list: &mut [T]) {
    for i in 1..list.len() {
        let x = list[i];
        let mut j = i;
        while j > 0 && list[j - 1] > x {
            list[j] = list[j - 1];
            j -= 1;
        }
        list[j] = x;
    }
}

/// Element `index` of the Halton sequence in `base`.
pub fn halton(index: i32, base: i32) -> f64 {
    let mut n0 = index;
    let b = base as f64;
    let mut f = 1.0 / b;
    let mut h = 0.0;
    while n0 > 0 {
        let n1 = n0 / base;
        let r = n0 - n1 * base;
        h += f * r as f64;
        f /= b;
        n0 = n1;
    }
    h
}

/// Smooth step on [0, 1] made of two half-parabolas.
pub fn sigmoid(x: f64) -> f64 {
    if x <= 0.0 {
        0.0
    } else if x >= 1.0 {
        1.0
    } else if x == 0.5 {
        0.5
    } else if x < 0.5 {
        2.0 * x * x
    } else {
        1.0 - 2.0 * (1.0 - x) * (1.0 - x)
    }
}
