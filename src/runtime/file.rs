//! Open files: what the OS says about them, and reading them into memory.

use std::io::Read;
use std::os::fd::AsRawFd;

use super::copy::{self, PAGE};

/// The size of `file` where it is a regular file. Asked through fstat: std's metadata asks
/// statx with an empty path, a string the kernel reads from this library's constants (one more
/// page a fresh process faults in on its first load).
pub fn regular_size(file: &std::fs::File) -> Option<u64> {
    // SAFETY: all-zero bits are a valid stat; fstat fills it for the open descriptor.
    let mut st: libc::stat = unsafe { std::mem::zeroed() };
    if unsafe { libc::fstat(file.as_raw_fd(), &mut st) } != 0 {
        return None;
    }
    (st.st_mode & libc::S_IFMT == libc::S_IFREG).then_some(st.st_size as u64)
}

/// Bytes of the space a long read at the slow alignment goes through.
const BOUNCE: usize = 16 * PAGE;

/// A file read front to back by a loader that reads it straight into its arrays, as stdio
/// reads it: a read of a page or more goes to the caller's memory, a shorter one through a
/// page of buffer. The kernel's copies and ours keep off `copy`'s slow alignment: the buffer
/// takes the file's bytes where their address has their file offset's place in a page, and a
/// long read at the slow alignment goes through a space of its own likewise.
pub struct FileReader {
    file: std::fs::File,
    /// Offset in the file of the next byte read from it.
    pos: usize,
    /// Its unread bytes at `start..end`.
    page: Vec<u8>,
    start: usize,
    end: usize,
    /// The space of a long read at the slow alignment, made when first needed.
    bounce: Vec<u8>,
}

impl FileReader {
    pub fn new(file: std::fs::File) -> Self {
        FileReader {
            file,
            pos: 0,
            page: vec![0; PAGE],
            start: 0,
            end: 0,
            bounce: Vec::new(),
        }
    }
}

/// Reads at most `want` bytes of `file` at `*pos` into `space`, from the first byte whose
/// address is at the position's place in a page; returns where and how many.
fn read_in_phase(
    file: &mut std::fs::File,
    pos: &mut usize,
    space: &mut [u8],
    want: usize,
) -> std::io::Result<(usize, usize)> {
    let at = pos.wrapping_sub(space.as_ptr() as usize) & (PAGE - 1);
    let n = want.min(space.len() - at);
    let got = file.read(&mut space[at..at + n])?;
    *pos += got;
    Ok((at, got))
}

impl Read for FileReader {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        if self.start == self.end && out.len() >= PAGE {
            if !copy::slow(out.as_ptr() as usize, self.pos) {
                let got = self.file.read(out)?;
                self.pos += got;
                return Ok(got);
            }
            if self.bounce.is_empty() {
                self.bounce = vec![0; BOUNCE];
            }
            let space = &mut self.bounce;
            let (at, got) = read_in_phase(&mut self.file, &mut self.pos, space, out.len())?;
            copy::copy(&mut out[..got], &space[at..at + got]);
            return Ok(got);
        }
        if self.start == self.end {
            let (at, got) = read_in_phase(&mut self.file, &mut self.pos, &mut self.page, PAGE)?;
            (self.start, self.end) = (at, at + got);
        }
        let n = out.len().min(self.end - self.start);
        copy::copy(&mut out[..n], &self.page[self.start..self.start + n]);
        self.start += n;
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every split of a file into reads, short and long, at every alignment of the
    /// destination, gives its bytes.
    #[test]
    fn reads_the_file_whole() {
        let bytes: Vec<u8> = (0..200_000u32).map(|i| (i * 13 + i / 509) as u8).collect();
        let path = std::env::temp_dir().join(format!("rujoco-filereader-{}", std::process::id()));
        std::fs::write(&path, &bytes).unwrap();
        let sizes = [1, 7, 100, 4095, 4096, 4097, 9000, 70_000, 3, 65_536, 12];
        let mut got = vec![0u8; bytes.len() + PAGE];
        let base = got.as_ptr() as usize;
        // destinations at distances 0, 1, 8, 15, 16 and 100 from the file offsets (modulo a page)
        for skew in [0, 1, 8, 15, 16, 100].map(|d: usize| d.wrapping_sub(base) & (PAGE - 1)) {
            let mut r = FileReader::new(std::fs::File::open(&path).unwrap());
            got.fill(0);
            let mut at = 0;
            for &n in sizes.iter().cycle() {
                let n = n.min(bytes.len() - at);
                if n == 0 {
                    break;
                }
                r.read_exact(&mut got[skew + at..skew + at + n]).unwrap();
                at += n;
            }
            assert_eq!(&got[skew..skew + bytes.len()], &bytes[..]);
            assert_eq!(r.read(&mut [0u8; 4]).unwrap(), 0);
        }
        let _ = std::fs::remove_file(&path);
    }
}
