//! MJB, 2.2.2's binary model format: a 4-int header, the int fields, mjOption, mjVisual,
//! mjStatistic, then every X-macro array unpadded, in order.

use super::alloc::{make_model, model_counts, walk_model_spans};
use super::*;

const ID: i32 = 54321;

/// Plain-old-data view of a struct's bytes.
fn bytes_of<T>(v: &T) -> &[u8] {
    // SAFETY: T is a repr(C) ABI struct without padding-sensitive invariants; reading bytes is fine.
    unsafe { std::slice::from_raw_parts(v as *const T as *const u8, std::mem::size_of::<T>()) }
}

/// The same, to be read into (no copy through the heap).
fn bytes_of_mut<T>(v: &mut T) -> &mut [u8] {
    // SAFETY: T accepts any bit pattern of its fields (numbers); callers use it only for
    // mjOption, mjVisual, mjStatistic and mjModel's int prefix.
    unsafe { std::slice::from_raw_parts_mut(v as *mut T as *mut u8, std::mem::size_of::<T>()) }
}

fn header() -> [i32; 4] {
    let (nint, nptr) = model_counts();
    [
        ID,
        std::mem::size_of::<mjtNum>() as i32,
        nint as i32,
        nptr as i32,
    ]
}

/// Serializes a model.
pub fn save(m: &mjModel) -> Vec<u8> {
    let mut out = Vec::with_capacity(alloc::size_model(m) as usize);
    write_parts(m, |b| out.extend_from_slice(b));
    out
}

/// Hands the serialized model to `put` piece by piece, in file order (no whole image in memory).
pub fn write_parts(m: &mjModel, mut put: impl FnMut(&[u8])) {
    let (nint, _) = model_counts();
    for v in header() {
        put(&v.to_ne_bytes());
    }
    put(&bytes_of(m)[..nint * 4]);
    put(bytes_of(&m.opt));
    put(bytes_of(&m.vis));
    put(bytes_of(&m.stat));
    // SAFETY: the buffer holds nbuffer bytes.
    let buf = unsafe { std::slice::from_raw_parts(m.buffer as *const u8, m.nbuffer as usize) };
    let _ = walk_model_spans(m, |off, len| -> Result<(), ()> {
        put(&buf[off..off + len]);
        Ok(())
    });
}

/// A 128-bit fingerprint of the serialized model: tells whether a model still holds what was
/// loaded without keeping a copy of it. Eight multiplicative lanes of 64 bits take the 8-byte
/// words in turn (eight chains side by side: the multiplier's latency is paid once per eight
/// words), folded into two words at the end. Each step is a bijection of the lane and of the
/// word, so one changed word always changes the fingerprint.
pub fn digest(m: &mjModel) -> [u64; 2] {
    const LANES: usize = 8;
    let step = |h: u64, w: u64| (h ^ w).wrapping_mul(0x9e37_79b9_7f4a_7c15).rotate_left(29);
    let mut lane: [u64; LANES] = std::array::from_fn(|i| 0xcbf2_9ce4_8422_2325 ^ (i as u64) << 56);
    let word = |b: &[u8]| u64::from_ne_bytes(b.try_into().unwrap());
    write_parts(m, |bytes| {
        let blocks = bytes.chunks_exact(8 * LANES);
        let rest = blocks.remainder();
        for block in blocks {
            for (h, w) in lane.iter_mut().zip(block.chunks_exact(8)) {
                *h = step(*h, word(w));
            }
        }
        let words = rest.chunks_exact(8);
        let tail = words.remainder();
        for (h, w) in lane.iter_mut().zip(words) {
            *h = step(*h, word(w));
        }
        for &b in tail {
            lane[LANES - 1] = step(lane[LANES - 1], b as u64 | 1 << 63);
        }
    });
    let fold = |seed: u64, k: u64| {
        lane.iter()
            .fold(seed, |h, &l| (h ^ l).wrapping_mul(k).rotate_left(23))
    };
    [
        fold(0x6c62_272e_07bb_0142, 0x0000_0100_0000_01b3),
        fold(0x2545_f491_4f6c_dd1d, 0xff51_afd7_ed55_8ccd),
    ]
}

/// Why an MJB image was refused: 2.2.2 warns about a bad file and reports a read past the end of
/// a memory buffer (VFS) as an error.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LoadError {
    Warning(String),
    Error(String),
}

impl LoadError {
    pub fn message(&self) -> &str {
        match self {
            LoadError::Warning(s) | LoadError::Error(s) => s,
        }
    }
}

/// The image read in order, its length known beforehand (a file's size, a buffer's length).
struct Reader<'a, R: std::io::Read> {
    src: &'a mut R,
    len: usize,
    pos: usize,
    /// from a memory buffer (VFS) rather than a file
    buffer: bool,
}

impl<R: std::io::Read> Reader<'_, R> {
    /// The next `dst.len()` bytes into `dst`; past the end, 2.2.2's message for the part
    /// (`what`), or its error for a memory buffer. A file that reads short says the same.
    fn read(&mut self, dst: &mut [u8], what: &str) -> Result<(), LoadError> {
        let short = || {
            if self.buffer {
                LoadError::Error("Attempting to read outside model buffer".into())
            } else {
                LoadError::Warning(what.to_string())
            }
        };
        if self.pos + dst.len() > self.len {
            return Err(short());
        }
        if dst.is_empty() {
            return Ok(());
        }
        self.src.read_exact(dst).map_err(|_| short())?;
        self.pos += dst.len();
        Ok(())
    }
}

/// Parses an MJB image (a file's contents, or a memory buffer when `buffer`) into a new model;
/// errors carry 2.2.2's texts. A buffer may hold more than the model, as 2.2.2 reads it.
pub fn load(data: &[u8], buffer: bool) -> Result<*mut mjModel, LoadError> {
    let mut src = crate::runtime::copy::SliceReader(data);
    load_from(&mut src, data.len(), buffer)
}

/// `load` from an image of `len` bytes read in order from `src` (a file read straight into the
/// model's arrays, with no copy of the whole image).
pub fn load_from<R: std::io::Read>(
    src: &mut R,
    len: usize,
    buffer: bool,
) -> Result<*mut mjModel, LoadError> {
    let (nint, _) = model_counts();
    let warn = |s: &str| LoadError::Warning(s.to_string());
    let mut r = Reader {
        src,
        len,
        pos: 0,
        buffer,
    };
    let mut head = [0u8; 16];
    r.read(&mut head, "Model file has an incomplete header")?;
    let expected = header();
    let msgs = [
        "Model missing header ID",
        "Model and executable have different floating point precision",
        "Model and executable have different number of ints in mjModel",
        "Model and executable have different number of pointers in mjModel",
    ];
    for i in 0..4 {
        let v = i32::from_ne_bytes(head[4 * i..4 * i + 4].try_into().unwrap());
        if v != expected[i] {
            return Err(warn(msgs[i]));
        }
    }
    // SAFETY: all-zero bits are a valid mjModel; only the int prefix is filled.
    let mut sizes: mjModel = unsafe { std::mem::zeroed() };
    r.read(
        &mut bytes_of_mut(&mut sizes)[..nint * 4],
        "Model file does not contain enough ints",
    )?;
    let m = make_model(&sizes, true).map_err(|_| warn("Corrupted model, wrong size parameters"))?;
    // SAFETY: m is a fresh model; its buffer has nbuffer bytes.
    unsafe {
        let mm = &mut *m;
        if mm.nbuffer != sizes.nbuffer {
            alloc::delete_model(m);
            return Err(warn("Corrupted model, wrong size parameters"));
        }
        let result = (|| -> Result<(), LoadError> {
            r.read(
                bytes_of_mut(&mut mm.opt),
                "Model file does not have a complete mjOption",
            )?;
            r.read(
                bytes_of_mut(&mut mm.vis),
                "Model file does not have a complete mjVisual",
            )?;
            r.read(
                bytes_of_mut(&mut mm.stat),
                "Model file does not have a complete mjStatistic",
            )?;
            let buf = std::slice::from_raw_parts_mut(mm.buffer as *mut u8, mm.nbuffer as usize);
            // the arrays, and zeros between them (the buffer may hold an old model's bytes)
            let mut end = 0;
            walk_model_spans(mm, |off, len| {
                if end < off {
                    buf[end..off].fill(0);
                }
                end = off + len;
                if len == 0 {
                    return Ok(());
                }
                r.read(
                    &mut buf[off..end],
                    "Model file does not contain a large enough buffer",
                )
            })?;
            buf[end..].fill(0);
            if !buffer && r.pos != r.len {
                return Err(warn("Model file is too large"));
            }
            if let Some(e) = validate::validate_references(view::Model::new(mm)) {
                return Err(warn(e));
            }
            consistency::check(view::Model::new(mm)).map_err(LoadError::Warning)
        })();
        if let Err(e) = result {
            alloc::delete_model(m);
            return Err(e);
        }
    }
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One flipped bit anywhere in the arrays (8-byte words and the bytes of a span's tail) or
    /// the options changes the fingerprint; flipped back, it is the same again.
    #[test]
    fn digest_sees_every_changed_bit() {
        let file = concat!(env!("CARGO_MANIFEST_DIR"), "/models/extra/tendon_wrap.xml");
        let mut model = crate::loader::xml::load(file, None).unwrap().model;
        let m = model.raw();
        let before = digest(m);
        let buf = m.buffer as *mut u8;
        let mut spans = Vec::new();
        let _ = walk_model_spans(m, |off, len| -> Result<(), ()> {
            spans.push((off, len));
            Ok(())
        });
        let tails = spans.iter().filter(|s| s.1 % 8 != 0).count();
        assert!(tails > 0, "no span with a tail in this model");
        let mut tried = 0;
        for (off, len) in spans.into_iter().filter(|s| s.1 > 0) {
            for at in [off, off + len / 2, off + len - 1] {
                for bit in [0, 7] {
                    // SAFETY: `at` lies in the model's buffer; the bit is flipped back.
                    unsafe { *buf.add(at) ^= 1 << bit };
                    let changed = digest(m);
                    unsafe { *buf.add(at) ^= 1 << bit };
                    assert_ne!(changed, before, "byte {at} bit {bit}");
                    tried += 1;
                }
            }
        }
        assert!(tried > 500, "{tried}");
        assert_eq!(digest(m), before);
        model.opt_mut().timestep *= 2.0;
        assert_ne!(digest(model.raw()), before);
    }
}
