//! C character arrays of the ABI structs (names, labels) as byte strings.

use std::os::raw::c_char;

/// The C string in `buf` as bytes (up to the first NUL).
pub fn cbytes(buf: &[c_char]) -> &[u8] {
    // SAFETY: c_char and u8 have the same size and alignment.
    let b = unsafe { std::slice::from_raw_parts(buf.as_ptr() as *const u8, buf.len()) };
    let n = b.iter().position(|&c| c == 0).unwrap_or(b.len());
    &b[..n]
}

/// Copies `src` into `dst`, truncated to leave room for the terminating NUL.
pub fn set_cstr(dst: &mut [c_char], src: &[u8]) {
    let n = src.len().min(dst.len().saturating_sub(1));
    for (d, &s) in dst.iter_mut().zip(&src[..n]) {
        *d = s as c_char;
    }
    dst[n..].iter_mut().for_each(|d| *d = 0);
}
