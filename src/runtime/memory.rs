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
