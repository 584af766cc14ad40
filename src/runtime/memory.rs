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

/// `size` zero bytes: through the user allocator (then cleared), else mapped when large
/// (64-byte aligned; `populate`: its pages in at once), else from the C heap.
pub fn alloc_large(size: usize, populate: bool) -> *mut c_void {
    let populate = if populate { libc::MAP_POPULATE } else { 0 };
    // SAFETY: reads the handler global, as the C library does.
    let user = unsafe { mju_user_malloc };
    if user.is_some() || size < LARGE_BLOCK {
        return malloc_zeroed(size);
    }
    let ptr = size
        .checked_add(MAP_OFFSET)
        .map_or(std::ptr::null_mut(), |len| {
            // SAFETY: an anonymous private mapping of `len` bytes.
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
                    (base as *mut u8).add(MAP_OFFSET) as *mut c_void
                }
            }
        });
    if ptr.is_null() {
        error("Could not allocate memory");
    }
    ptr
}

/// Frees a block from `alloc_large` of the same `size`.
///
/// # Safety
/// `ptr` is NULL or came from `alloc_large(size, _)` and was not freed.
pub unsafe fn free_large(ptr: *mut c_void, size: usize) {
    let user = mju_user_free;
    if ptr.is_null() || user.is_some() || size < LARGE_BLOCK {
        return free(ptr);
    }
    let base = (ptr as *mut u8).sub(MAP_OFFSET);
    libc::munmap(base as *mut c_void, size + MAP_OFFSET);
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
