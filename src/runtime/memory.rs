//! Heap memory through the user's allocator (mju_user_malloc, mju_user_free) or the C heap.

use super::message::error;
use std::os::raw::c_void;

#[no_mangle]
pub static mut mju_user_malloc: Option<unsafe extern "C" fn(usize) -> *mut c_void> = None;
#[no_mangle]
pub static mut mju_user_free: Option<unsafe extern "C" fn(*mut c_void)> = None;

/// Removes the user's allocator.
pub fn clear_handlers() {
    // SAFETY: plain stores to the handler globals, as the C library does.
    unsafe {
        mju_user_malloc = None;
        mju_user_free = None;
    }
}

/// Allocates through the user allocator, or 64-byte aligned and padded to 64 bytes.
pub fn malloc(size: usize) -> *mut c_void {
    // SAFETY: C allocation; the result is checked for NULL.
    let ptr = unsafe {
        if let Some(f) = mju_user_malloc {
            f(size)
        } else {
            let padded = size.div_ceil(64).max(1) * 64;
            let mut p: *mut c_void = std::ptr::null_mut();
            if libc::posix_memalign(&mut p, 64, padded) != 0 {
                std::ptr::null_mut()
            } else {
                p
            }
        }
    };
    if ptr.is_null() {
        error("Could not allocate memory");
    }
    ptr
}

/// Allocates zeroed memory: through the user allocator and then cleared, else with `calloc`,
/// whose large blocks come from fresh pages never touched until used (a model's stack may span
/// gigabytes the simulation never reaches; 16-byte alignment).
pub fn malloc_zeroed(size: usize) -> *mut c_void {
    // SAFETY: C allocation; the result is checked for NULL and cleared to its full size.
    let ptr = unsafe {
        let user = mju_user_malloc;
        if user.is_some() {
            let p = malloc(size);
            if !p.is_null() {
                std::ptr::write_bytes(p as *mut u8, 0, size);
            }
            return p;
        }
        libc::calloc(size.max(1), 1)
    };
    if ptr.is_null() {
        error("Could not allocate memory");
    }
    ptr
}

/// mjModel buffers and mjData stacks of this size and more are mapped from the kernel
/// directly when no user allocator is set, and unmapped when freed: their pages go back at
/// once and the heap does not fragment around them (a heap's reused block is cleared, which
/// touches every page, and freeing it returns nothing). Most of a stack is never touched and
/// stays out of resident memory; a model buffer is filled whole, so its pages come mapped.
const LARGE_BLOCK: usize = 1 << 20;

/// Offset of a mapped block's first byte in its mapping: 2 KB + 64 keeps the 64-byte alignment
/// and starts the arrays mid-page (at offset 64, cheetah stepped 2-3% slower).
const MAP_OFFSET: usize = 2048 + 64;

/// Model buffers of this size and more are mapped (and kept as the spare when freed): below
/// glibc's first mmap threshold (128 KB) they come from the heap, as its own arrays do.
const MODEL_BLOCK: usize = 128 << 10;

/// Whether `alloc_large(size, _)` maps a block of its own now (no user allocator, large).
pub fn maps(size: usize) -> bool {
    maps_from(size, LARGE_BLOCK)
}

/// Whether a block of `size` is mapped when blocks of `threshold` and more are.
fn maps_from(size: usize, threshold: usize) -> bool {
    // SAFETY: reads the handler global, as the C library does.
    let user = unsafe { mju_user_malloc };
    user.is_none() && size >= threshold
}

/// `size` zero bytes: through the user allocator (then cleared), else mapped when large
/// (64-byte aligned; `populate`: its pages in at once), else from the C heap. A mapping's
/// first word holds its length (a spare block handed out again may be longer than asked).
pub fn alloc_large(size: usize, populate: bool) -> *mut c_void {
    if !maps(size) {
        return malloc_zeroed(size);
    }
    map_block(size, populate)
}

/// A fresh mapping holding `size` zero bytes past `MAP_OFFSET`, its length in its first word.
fn map_block(size: usize, populate: bool) -> *mut c_void {
    let populate = if populate { libc::MAP_POPULATE } else { 0 };
    let ptr = size
        .checked_add(MAP_OFFSET)
        .map_or(std::ptr::null_mut(), |len| {
            // SAFETY: an anonymous private mapping of `len` bytes, its first word written.
            unsafe {
                let base = libc::mmap(
                    std::ptr::null_mut(),
                    len,
                    libc::PROT_READ | libc::PROT_WRITE,
                    libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | populate,
                    -1,
                    0,
                );
                if base == libc::MAP_FAILED {
                    std::ptr::null_mut()
                } else {
                    (base as *mut usize).write(len);
                    (base as *mut u8).add(MAP_OFFSET) as *mut c_void
                }
            }
        });
    if ptr.is_null() {
        error("Could not allocate memory");
    }
    ptr
}

/// Largest model buffer kept mapped when freed, for the next model (glibc's heap keeps freed
/// blocks up to its largest mmap threshold, 32 MB, and 2.2.2's models come from it).
const SPARE_MAX: usize = 32 << 20;

/// The mapping (base address, length) of the last model buffer freed, if it was mapped and
/// at most `SPARE_MAX`: a model loaded or copied next takes over its pages, written already,
/// instead of the kernel clearing and mapping in fresh ones.
static SPARE: std::sync::Mutex<Option<(usize, usize)>> = std::sync::Mutex::new(None);

/// A block for a model buffer of `size` bytes, freed by `free_model_block`. `overwrite`: the
/// caller writes every byte, so it may hold old bytes; else it is zeroed. A large one is the
/// spare mapping when that fits, otherwise a fresh one (its pages put in at once when
/// `overwrite`); a small one comes from the heap.
pub fn alloc_model_block(size: usize, overwrite: bool) -> *mut c_void {
    if !maps_from(size, MODEL_BLOCK) {
        // from the heap (as 2.2.2's): cleared only when the caller does not overwrite it
        return if overwrite {
            malloc(size)
        } else {
            malloc_zeroed(size)
        };
    }
    if let Some(ptr) = take_spare(size) {
        if !overwrite {
            // SAFETY: the spare mapping holds at least `size` bytes past its offset.
            unsafe { std::ptr::write_bytes(ptr as *mut u8, 0, size) };
        }
        return ptr;
    }
    map_block(size, overwrite)
}

/// The spare mapping's block when it holds `size` bytes and is at most twice as long.
fn take_spare(size: usize) -> Option<*mut c_void> {
    let need = size.checked_add(MAP_OFFSET)?;
    let mut slot = SPARE.lock().ok()?;
    let (base, len) = (*slot)?;
    if len < need || len / 2 > need {
        return None;
    }
    *slot = None;
    Some((base as *mut u8).wrapping_add(MAP_OFFSET) as *mut c_void)
}

/// Frees a block from `alloc_model_block` of the same `size`: a mapping of at most
/// `SPARE_MAX` becomes the spare (the one before it is unmapped).
///
/// # Safety
/// `ptr` is NULL or came from `alloc_model_block(size, _)` and was not freed.
pub unsafe fn free_model_block(ptr: *mut c_void, size: usize) {
    if ptr.is_null() || !maps_from(size, MODEL_BLOCK) {
        return free(ptr);
    }
    let base = (ptr as *mut u8).sub(MAP_OFFSET);
    let len = (base as *const usize).read();
    if len > SPARE_MAX {
        return unmap_block(ptr);
    }
    let old = match SPARE.lock() {
        Ok(mut slot) => slot.replace((base as usize, len)),
        Err(_) => return unmap_block(ptr),
    };
    if let Some((b, l)) = old {
        libc::munmap(b as *mut c_void, l);
    }
}

/// Pages of a block mapped by `alloc_large` that were never written (nor swapped out) read as
/// zeros without being there: the kernel's page map (/proc/self/pagemap) says which, read a
/// chunk at a time as a walk over the block goes forward. Where the map cannot be read, every
/// page counts as touched.
pub(crate) struct PageMap {
    fd: i32,
    /// log2 of the page size.
    shift: u32,
    /// Page number of `entries[0]`, and how many entries were read.
    first: usize,
    len: usize,
    entries: [u64; 512],
}

impl PageMap {
    /// Present (bit 63) or swapped out (bit 62): the page holds what was written to it.
    const HELD: u64 = 3 << 62;

    /// A map of the process's pages; `mapped` false (a block not from our own mapping, whose
    /// untouched pages need not read as zeros) counts every page as touched.
    pub fn new(mapped: bool) -> Self {
        // SAFETY: sysconf, and open of a NUL-terminated path (closed on drop). Opened for each
        // clearing: a descriptor kept open would read its opener's map in a forked child.
        let (fd, page) = unsafe {
            let page = libc::sysconf(libc::_SC_PAGESIZE) as usize;
            if !mapped || !page.is_power_of_two() {
                (-1, 4096)
            } else {
                let path = c"/proc/self/pagemap";
                (
                    libc::open(path.as_ptr(), libc::O_RDONLY | libc::O_CLOEXEC),
                    page,
                )
            }
        };
        let shift = page.trailing_zeros();
        let mut map = PageMap {
            fd,
            shift,
            first: 0,
            len: 0,
            entries: [0; 512],
        };
        // a map that shows the page of this value (just written) as untouched is not the
        // kernel's (an emulated /proc): then every page counts as touched
        let probe = std::hint::black_box(&map.entries) as *const _ as usize;
        if map.untouched(probe) {
            map.give_up();
        }
        map
    }

    /// Whether the page holding address `addr` was never written.
    fn untouched(&mut self, addr: usize) -> bool {
        if self.fd < 0 {
            return false;
        }
        let page = addr >> self.shift;
        if page < self.first || page >= self.first + self.len {
            let bytes = std::mem::size_of_val(&self.entries);
            // SAFETY: reads into our own array of `bytes` bytes.
            let n = unsafe {
                libc::pread(
                    self.fd,
                    self.entries.as_mut_ptr() as *mut c_void,
                    bytes,
                    (page * 8) as libc::off_t,
                )
            };
            self.first = page;
            self.len = n.max(0) as usize / 8;
            if self.len == 0 {
                // not readable after all
                self.give_up();
                return false;
            }
        }
        self.entries[page - self.first] & Self::HELD == 0
    }

    /// Zeroes `len` bytes at `ptr`, skipping the pages never written (zeros already, and left
    /// out of resident memory).
    ///
    /// # Safety
    /// `ptr..ptr + len` is writable, and lies in a block of `alloc_large` that mapped its own
    /// pages when this map was made with `mapped` true.
    pub unsafe fn clear(&mut self, ptr: *mut u8, len: usize) {
        if self.fd < 0 {
            return std::ptr::write_bytes(ptr, 0, len);
        }
        let shift = self.shift;
        page_runs(
            ptr as usize,
            len,
            shift,
            |at| self.untouched(ptr as usize + at),
            |untouched, from, to| {
                if !untouched {
                    std::ptr::write_bytes(ptr.add(from), 0, to - from);
                }
            },
        );
    }

    /// Counts every page as touched from here on.
    fn give_up(&mut self) {
        if self.fd >= 0 {
            // SAFETY: our own descriptor, closed once (then forgotten).
            unsafe { libc::close(self.fd) };
            self.fd = -1;
        }
    }
}

/// Copies `len` bytes from `src` to `dst`, each with its own map (`src_map` of src's block,
/// `dst_map` of dst's): a page that src never wrote is zeros, so it is not read, and is
/// written only where dst's page holds data. Blocks that do not start at the same offset in a
/// page are copied whole.
///
/// # Safety
/// As `PageMap::clear` for each map and block; the ranges do not overlap.
pub(crate) unsafe fn copy_pages(
    dst_map: &mut PageMap,
    src_map: &mut PageMap,
    dst: *mut u8,
    src: *const u8,
    len: usize,
) {
    let shift = src_map.shift;
    let page = 1usize << shift;
    if src_map.fd < 0 || (dst as usize ^ src as usize) & (page - 1) != 0 {
        return std::ptr::copy_nonoverlapping(src, dst, len);
    }
    // what to do with the bytes from `at` to the end of their page
    #[derive(PartialEq)]
    enum Act {
        Skip,
        Zero,
        Copy,
    }
    let act = |at: usize| {
        if !src_map.untouched(src as usize + at) {
            Act::Copy
        } else if dst_map.untouched(dst as usize + at) {
            Act::Skip
        } else {
            Act::Zero
        }
    };
    page_runs(src as usize, len, shift, act, |what, from, to| match what {
        Act::Skip => {}
        Act::Zero => std::ptr::write_bytes(dst.add(from), 0, to - from),
        Act::Copy => std::ptr::copy_nonoverlapping(src.add(from), dst.add(from), to - from),
    });
}

/// Walks the `len` bytes from address `base` a page at a time (pages of 2^`shift` bytes):
/// `act` says what to do from an offset to the end of its page, and `apply` gets each run of
/// pages with the same action as (action, from, to), offsets from `base`.
fn page_runs<A: PartialEq>(
    base: usize,
    len: usize,
    shift: u32,
    mut act: impl FnMut(usize) -> A,
    mut apply: impl FnMut(A, usize, usize),
) {
    let next = |at: usize| ((((base + at) >> shift) + 1) << shift).min(base + len) - base;
    let mut at = 0;
    while at < len {
        let what = act(at);
        let mut stop = next(at);
        while stop < len && act(stop) == what {
            stop = next(stop);
        }
        apply(what, at, stop);
        at = stop;
    }
}

impl Drop for PageMap {
    fn drop(&mut self) {
        self.give_up();
    }
}

/// Frees a block from `alloc_large` of the same `size`.
///
/// # Safety
/// `ptr` is NULL or came from `alloc_large(size, _)` and was not freed.
pub unsafe fn free_large(ptr: *mut c_void, size: usize) {
    // mapped exactly when `alloc_large` maps (no user allocator), whatever deallocator is set
    if ptr.is_null() || !maps(size) {
        return free(ptr);
    }
    unmap_block(ptr)
}

/// Unmaps a block from `map_block`.
///
/// # Safety
/// `ptr` came from `map_block` and was not freed.
unsafe fn unmap_block(ptr: *mut c_void) {
    let base = (ptr as *mut u8).sub(MAP_OFFSET);
    let len = (base as *const usize).read();
    libc::munmap(base as *mut c_void, len);
}

/// Frees memory from `malloc` or `malloc_zeroed`, through the user deallocator when set.
///
/// # Safety
/// `ptr` is NULL or came from `malloc` or `malloc_zeroed` and was not freed.
pub unsafe fn free(ptr: *mut c_void) {
    if ptr.is_null() {
        return;
    }
    if let Some(f) = mju_user_free {
        f(ptr)
    } else {
        libc::free(ptr)
    }
}

/// Models of this size and more come from loads whose temporaries (meshes, skins, textures)
/// are worth handing back; smaller loads leave theirs on the heap for the next load to reuse.
const LARGE_LOAD: usize = 16 << 20;

/// After loading a model of `model_bytes`, hands the C heap's free pages back to the kernel
/// when the model is large: the compiler's temporaries are freed by then, and otherwise they
/// stay resident and grow over load/free rounds. The next load maps its pages in again.
pub fn release_free_heap(model_bytes: usize) {
    if model_bytes < LARGE_LOAD {
        return;
    }
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: glibc's trim only returns unused heap pages; no block is moved or freed.
    unsafe {
        libc::malloc_trim(0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Clearing a mapped block: every byte of the range is zero afterwards (pages written,
    /// written and paged out, written in part, never written), the bytes around it are kept,
    /// and the pages never written are still not there.
    #[test]
    fn clearing_skips_only_pages_never_written() {
        // SAFETY: sysconf.
        let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) } as usize;
        let size = 512 * page;
        assert!(maps(size));
        let block = alloc_large(size, false) as *mut u8;
        // SAFETY: all within the fresh block of `size` bytes.
        unsafe {
            let bytes =
                |from: usize, to: usize| std::slice::from_raw_parts_mut(block.add(from), to - from);
            bytes(0, 100).fill(7);
            bytes(page, 2 * page).fill(1);
            bytes(5 * page - 8, 5 * page + 8).fill(2);
            bytes(20 * page, 23 * page).fill(3);
            bytes(40 * page, 41 * page).fill(4);
            // to swap where there is swap (it stays otherwise), which must count as written
            libc::madvise(
                block.add(40 * page) as *mut c_void,
                page,
                21, /* MADV_PAGEOUT */
            );
            bytes(size - 100, size).fill(9);
            let mut map = PageMap::new(true);
            map.clear(block.add(100), size - 200);
            let mut map = PageMap::new(true);
            // the kernel's map, where there is one, passes the probe of `new`
            let readable = std::fs::File::open("/proc/self/pagemap").is_ok();
            assert_eq!(map.fd >= 0, readable);
            if map.fd >= 0 {
                // left out by the clearing (before the reads below, which map pages in)
                assert!(map.untouched(block.add(300 * page) as usize));
                assert!(!map.untouched(block.add(page) as usize));
            }
            assert!(bytes(0, 100).iter().all(|&b| b == 7));
            assert!(bytes(100, size - 100).iter().all(|&b| b == 0));
            assert!(bytes(size - 100, size).iter().all(|&b| b == 9));
            free_large(block as *mut c_void, size);
        }
    }

    /// A model buffer of a few hundred KB is mapped and kept when freed: the next one of about
    /// its size takes the same pages, zeroed unless the caller overwrites them all.
    #[test]
    fn freed_model_buffer_is_taken_by_the_next() {
        let size = 300 << 10;
        assert!(maps_from(size, MODEL_BLOCK) && !maps(size));
        let a = alloc_model_block(size, false) as *mut u8;
        // SAFETY: all within blocks of `size` bytes from alloc_model_block, freed once each.
        unsafe {
            assert!(std::slice::from_raw_parts(a, size).iter().all(|&b| b == 0));
            std::ptr::write_bytes(a, 7, size);
            free_model_block(a as *mut c_void, size);
            let b = alloc_model_block(size - 1000, false) as *mut u8;
            assert_eq!(a, b, "the spare");
            assert!(std::slice::from_raw_parts(b, size - 1000)
                .iter()
                .all(|&b| b == 0));
            std::ptr::write_bytes(b, 7, size - 1000);
            free_model_block(b as *mut c_void, size - 1000);
            let c = alloc_model_block(size, true) as *mut u8;
            assert_eq!(a, c, "the spare, not cleared");
            assert_eq!(*c, 7);
            free_model_block(c as *mut c_void, size);
            // much smaller: a fresh block, the spare kept
            let d = alloc_model_block(size / 3, false);
            free_model_block(d, size / 3);
        }
    }

    /// Blocks not mapped by us are cleared whole.
    #[test]
    fn clearing_elsewhere_writes_every_byte() {
        let mut v = vec![5u8; 3 * 4096 + 17];
        let mut map = PageMap::new(false);
        // SAFETY: within the vector.
        unsafe { map.clear(v.as_mut_ptr().add(3), v.len() - 6) };
        assert_eq!(&v[..3], &[5, 5, 5]);
        assert!(v[3..v.len() - 3].iter().all(|&b| b == 0));
        assert_eq!(&v[v.len() - 3..], &[5, 5, 5]);
    }
}
