//! Byte copies kept off the one relative alignment where the CPU's string copy is slow.
//!
//! glibc's memcpy (from 2112 bytes on, here) and the kernel's copy of a file read into memory
//! use `rep movsb`; on AMD EPYC it runs about 15x slower when the destination is 1-15 bytes past
//! the source modulo 4096 (a read of 300 kB from a file: 90 us against 11; gymnasium's ant
//! read its array of 447 kB at that alignment). Copies that would take that path go in pieces
//! short enough for glibc's vector loop, which is not.

/// Bytes in a piece: below glibc's `rep movsb` threshold (2112 by default on x86-64).
const PIECE: usize = 2048;

/// The period of the slow alignment: a page.
pub const PAGE: usize = 4096;

/// Whether a copy to `dst` from `src` (addresses or file offsets) is at the slow alignment.
pub fn slow(dst: usize, src: usize) -> bool {
    (1..16).contains(&(dst.wrapping_sub(src) & (PAGE - 1)))
}

/// `dst.copy_from_slice(src)`, in pieces where a single copy would be at the slow alignment.
pub fn copy(dst: &mut [u8], src: &[u8]) {
    if dst.len() < PIECE || !slow(dst.as_ptr() as usize, src.as_ptr() as usize) {
        return dst.copy_from_slice(src);
    }
    for (d, s) in dst.chunks_mut(PIECE).zip(src.chunks(PIECE)) {
        d.copy_from_slice(s);
    }
}

/// Bytes in memory read front to back, copied out by `copy`.
pub struct SliceReader<'a>(pub &'a [u8]);

impl std::io::Read for SliceReader<'_> {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        let n = out.len().min(self.0.len());
        let (head, rest) = self.0.split_at(n);
        copy(&mut out[..n], head);
        self.0 = rest;
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copies_at_every_alignment() {
        let src: Vec<u8> = (0..20000u32).map(|i| (i * 7 + i / 251) as u8).collect();
        let mut dst = vec![0u8; 20000 + 64];
        for k in 0..64 {
            dst.fill(0);
            copy(&mut dst[k..k + 9000], &src[..9000]);
            assert_eq!(&dst[k..k + 9000], &src[..9000]);
            assert!(dst[..k].iter().all(|&b| b == 0));
            assert!(dst[k + 9000..].iter().all(|&b| b == 0));
        }
    }

    #[test]
    fn the_slow_alignment() {
        assert!(!slow(4096, 0) && !slow(16, 0) && !slow(0, 8));
        assert!(slow(8, 0) && slow(4097, 0) && slow(15, 0) && slow(4103, 4100));
    }
}
