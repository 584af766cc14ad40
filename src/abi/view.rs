//! Safe views of `mjModel` and `mjData`: every array as a slice of its X-macro length.
//!
//! The engine and compiler work only on these views. Building one is the single unsafe step:
//! it trusts that the struct's pointers address disjoint arrays of the sizes the X-macro
//! lists give, which `mj_makeModel`/`mj_makeData` guarantee.

use super::*;
use crate::runtime::memory::PageMap;

/// A NULL pointer (only ever paired with length 0) gives the empty slice.
#[inline(always)]
unsafe fn view_mut<'a, T>(ptr: *mut T, len: usize) -> &'a mut [T] {
    if ptr.is_null() {
        &mut []
    } else {
        std::slice::from_raw_parts_mut(ptr, len)
    }
}

/// An mjModel or mjData array: `make_model` and `alloc_data` give every one a non-null,
/// aligned address in the struct's buffer, so no NULL check is needed.
#[inline(always)]
unsafe fn array_view<'a, T>(ptr: *mut T, len: usize) -> &'a mut [T] {
    debug_assert!(!ptr.is_null());
    std::slice::from_raw_parts_mut(ptr, len)
}

/// Shared counterpart of `array_view`.
#[inline(always)]
unsafe fn array_ref<'a, T>(ptr: *const T, len: usize) -> &'a [T] {
    debug_assert!(!ptr.is_null());
    std::slice::from_raw_parts(ptr, len)
}

macro_rules! model_views {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        /// Read-only view of a compiled model: sizes, options and statistics through `raw`, every
        /// array through the method of its name (free to build: slices are made on access).
        #[derive(Clone, Copy)]
        pub struct Model<'a> {
            pub raw: &'a mjModel,
        }

        /// Writable view of a model under construction (compiler, `mj_setConst`).
        pub struct ModelMut<'a> {
            $(pub $name: &'a mut [elem_ty!($t)],)*
        }

        impl<'a> Model<'a> {
            /// # Safety
            /// `m` must come from `mj_makeModel` (or have the same array layout).
            pub unsafe fn new(m: &'a mjModel) -> Self {
                Model { raw: m }
            }

            $(
                #[inline(always)]
                pub fn $name(&self) -> &'a [elem_ty!($t)] {
                    // SAFETY: `new`'s contract: the array has this X-macro length.
                    unsafe { array_view(self.raw.$name, row_len!(self.raw, $d1, $($d2)+)) }
                }
            )*
        }

        impl<'a> Model<'a> {
            /// The geoms of body `b` (body_geomadr on, body_geomnum of them; none where the
            /// body has none).
            #[inline(always)]
            pub fn body_geoms(&self, b: usize) -> std::ops::Range<usize> {
                let adr = self.body_geomadr()[b].max(0) as usize;
                adr..adr + self.body_geomnum()[b].max(0) as usize
            }

            /// `mesh_vert` as points (x, y, z).
            #[inline(always)]
            pub fn mesh_vert_xyz(&self) -> &'a [[f32; 3]] {
                // SAFETY: `new`'s contract: mesh_vert holds 3 * nmeshvert floats; [f32; 3] has
                // their alignment and no padding.
                unsafe {
                    array_ref(
                        self.raw.mesh_vert.cast::<[f32; 3]>(),
                        self.raw.nmeshvert.max(0) as usize,
                    )
                }
            }
        }

        impl<'a> ModelMut<'a> {
            /// # Safety
            /// `m` must come from `mj_makeModel`; the arrays must not be aliased elsewhere.
            pub unsafe fn new(m: &'a mut mjModel) -> Self {
                ModelMut { $($name: view_mut(m.$name, row_len!(m, $d1, $($d2)+)),)* }
            }
        }
    };
}
mjmodel_pointers!(model_views);

macro_rules! data_views {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        /// Writable view of simulation data: every array, the header scalars and the stack.
        /// (`repr(C)`: a built view is kept as bytes with its data, see `ViewSlot`.)
        #[repr(C)]
        pub struct Data<'a> {
            /// Header: scalars, diagnostics, warnings (pointers in it must not be changed).
            pub raw: &'a mut mjData,
            /// Scratch space from the `mjData` stack.
            pub arena: Arena<'a>,
            $(pub $name: &'a mut [elem_ty!($t)],)*
        }

        impl<'a> Data<'a> {
            /// # Safety
            /// `d` must come from `mj_makeData(m)` for this model.
            #[inline(always)]
            pub unsafe fn new(m: &mjModel, d: &'a mut mjData) -> Self {
                let slot = ViewSlot::of(d);
                if (*slot).busy {
                    // in use by a call below this one: its arrays may be lent out
                    return Self::build(m, d);
                }
                if (*slot).holds(m, d) {
                    // the kept view's arrays, a new arena over the stack as it is now
                    let mut view: Self = std::ptr::read((*slot).image.as_ptr().cast());
                    std::ptr::write(&mut view.arena, Self::arena(d));
                    return view;
                }
                let view = Self::build(m, d);
                (*slot).keep(m, &view);
                view
            }

            /// Runs `f` on the view kept with `d`, in place (no copy); on a new one when the
            /// kept view is in use by an outer call (a callback's call) or not of `m`.
            ///
            /// # Safety
            /// As `new`.
            #[inline(always)]
            pub unsafe fn with<R>(m: &mjModel, d: &'a mut mjData, f: impl FnOnce(&mut Data<'a>) -> R) -> R {
                let slot = ViewSlot::of(d);
                if (*slot).busy || !(*slot).owns(d) {
                    return f(&mut Self::build(m, d));
                }
                if !(*slot).holds(m, d) {
                    let d2: *mut mjData = d;
                    (*slot).keep(m, &Self::build(m, &mut *d2));
                }
                let view = (*slot).image.as_mut_ptr() as *mut Data<'a>;
                std::ptr::write(&mut (*view).arena, Self::arena(d));
                let _in_use = InUse::take(slot);
                let r = f(&mut *view);
                (*view).note_peak();
                r
            }

            /// A view from every array's length.
            #[inline(never)]
            unsafe fn build(m: &mjModel, d: &'a mut mjData) -> Self {
                let arena = Self::arena(d);
                $(let $name = array_view(d.$name, row_len!(m, $d1, $($d2)+));)*
                Data { raw: d, arena, $($name,)* }
            }

            /// The arena over the free part of `d`'s stack.
            #[inline(always)]
            unsafe fn arena(d: &mjData) -> Arena<'a> {
                let pstack = d.pstack.clamp(0, d.nstack) as usize;
                let stack = view_mut(d.stack, d.nstack.max(0) as usize);
                Arena { free: &mut stack[pstack..], used: pstack, peak: pstack }
            }

            /// Zeroes the buffer, as mj_resetData: every array, and the padding between
            /// them through the buffer's own pointer. In a buffer mapped for this data, the
            /// pages never written are skipped (zeros already, and kept out of resident memory).
            pub fn clear_arrays(&mut self) {
                // SAFETY: the slot of data from `alloc_data` (`Data::new`'s contract), whose
                // arrays lie in its buffer in this order; each array is written through its
                // own slice, the gaps between them (no slice's) through the buffer pointer;
                // all-zero bytes are a valid value of every element type (numbers, mjContact).
                unsafe {
                    ViewSlot::forget_moments(self.raw);
                    let mut pages = ViewSlot::page_map(self.raw);
                    let buffer = self.raw.buffer as *mut u8;
                    let mut done = 0usize;
                    let gap = |pages: &mut PageMap, from: usize, to: usize| {
                        if to > from {
                            pages.clear(buffer.add(from), to - from);
                        }
                    };
                    $(
                        let array = self.$name.as_mut_ptr() as *mut u8;
                        let offset = array.offset_from(buffer) as usize;
                        gap(&mut pages, done, offset);
                        pages.clear(array, std::mem::size_of_val(self.$name));
                        done = offset + std::mem::size_of_val(self.$name);
                    )*
                    gap(&mut pages, done, self.raw.nbuffer as usize);
                }
            }

            /// Runs `f` on a reborrowed view whose stack allocations are released afterwards
            /// (2.2.2's mjMARKSTACK / mjFREESTACK around a call); their high-water mark stays.
            pub fn scoped<R>(&mut self, f: impl FnOnce(&mut Data<'_>) -> R) -> R {
                let used = self.arena.used;
                let mut inner = Data {
                    raw: &mut *self.raw,
                    arena: Arena { free: &mut *self.arena.free, used, peak: used },
                    $($name: &mut *self.$name,)*
                };
                let r = f(&mut inner);
                let peak = inner.arena.peak;
                drop(inner);
                self.arena.peak = self.arena.peak.max(peak);
                r
            }
        }
    };
}
mjdata_pointers!(data_views);

macro_rules! data_ref_views {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        /// Read-only view of simulation data: the header and every array by its method.
        #[derive(Clone, Copy)]
        pub struct DataRef<'a> {
            pub raw: &'a mjData,
            m: &'a mjModel,
        }

        impl<'a> DataRef<'a> {
            /// # Safety
            /// `d` must come from `mj_makeData(m)` for this model.
            pub unsafe fn new(m: &'a mjModel, d: &'a mjData) -> Self {
                DataRef { raw: d, m }
            }

            $(
                #[inline(always)]
                pub fn $name(&self) -> &'a [elem_ty!($t)] {
                    // SAFETY: `new`'s contract: the array has this X-macro length.
                    unsafe { array_ref(self.raw.$name, row_len!(self.m, $d1, $($d2)+)) }
                }
            )*
        }
    };
}
mjdata_pointers!(data_ref_views);

/// Room after an `mjData`'s array buffer (`alloc_data` makes it) for the view last built of it:
/// building one computes every array's length (a fifth of an empty model's step); the C entry
/// points use the kept one in place (`Data::with`), other callers copy it (`Data::new`). The
/// view is kept for one model; `owner` and `buffer` say the room is this data's own (a struct
/// copied by value has another address).
#[repr(C)]
pub struct ViewSlot {
    owner: *const mjData,
    buffer: *const std::os::raw::c_void,
    model: *const mjModel,
    /// Lent out by `Data::with` (its arrays may be swapped out for a while).
    busy: bool,
    /// The buffer is a mapping of its own (`memory::alloc_large`): pages never written read
    /// as zeros.
    mapped: bool,
    /// Room right after the slot for `moment_rows` spans `[lo, hi)`: of each actuator's row of
    /// actuator_moment, the columns outside which the last mj_transmission left it zero; valid
    /// while `moments_known`, which anything else that writes the buffer clears.
    moment_rows: usize,
    moments_known: bool,
    image: std::mem::MaybeUninit<Data<'static>>,
}

/// The record of moment spans after a `ViewSlot`, borrowed with actuator_moment (`Data::moments`).
pub struct MomentSpans<'a> {
    /// The spans hold: every row is zero outside its span.
    pub known: &'a mut bool,
    /// One `[lo, hi)` per actuator (empty where the data has no room for the model's).
    pub spans: &'a mut [[u32; 2]],
}

/// Marks a slot in use while alive; a panic through it forgets the view (it may have been
/// left with an array swapped out).
struct InUse(*mut ViewSlot);

impl InUse {
    unsafe fn take(slot: *mut ViewSlot) -> Self {
        (*slot).busy = true;
        InUse(slot)
    }
}

impl Drop for InUse {
    fn drop(&mut self) {
        // SAFETY: the slot outlives the call that made this guard.
        unsafe {
            (*self.0).busy = false;
            if std::thread::panicking() {
                (*self.0).model = std::ptr::null();
            }
        }
    }
}

impl ViewSlot {
    /// Offset of the slot from the start of a buffer of `nbuffer` bytes.
    pub fn offset(nbuffer: usize) -> usize {
        nbuffer.max(1).div_ceil(64) * 64
    }

    /// The slot of `d`.
    ///
    /// # Safety
    /// `d` came from `alloc_data`.
    unsafe fn of(d: &mjData) -> *mut ViewSlot {
        (d.buffer as *mut u8).add(Self::offset(d.nbuffer.max(0) as usize)) as *mut ViewSlot
    }

    /// Marks the slot of `d` as its own and empty (fresh data, or a header overwritten).
    ///
    /// # Safety
    /// `d` came from `alloc_data`, which made room for the slot.
    pub unsafe fn init(d: &mjData) {
        let slot = Self::of(d);
        (*slot).owner = d;
        (*slot).buffer = d.buffer;
        (*slot).model = std::ptr::null();
        (*slot).busy = false;
    }

    /// Gives `d` room for `rows` moment spans, after the slot (`alloc_data` made it), not known
    /// yet.
    ///
    /// # Safety
    /// As `init`; the buffer has that room.
    pub unsafe fn set_moment_spans(d: &mjData, rows: usize) {
        let slot = Self::of(d);
        (*slot).moment_rows = rows;
        (*slot).moments_known = false;
    }

    /// The number of moment spans `d` has room for (`set_moment_spans`).
    ///
    /// # Safety
    /// As `init`.
    pub unsafe fn moment_rows(d: &mjData) -> usize {
        (*Self::of(d)).moment_rows
    }

    /// Forgets what the moment spans say: `d`'s buffer was written by other means.
    ///
    /// # Safety
    /// As `init`.
    pub unsafe fn forget_moments(d: &mjData) {
        (*Self::of(d)).moments_known = false;
    }

    /// Records whether `d`'s buffer is a mapping of its own.
    ///
    /// # Safety
    /// As `init`.
    pub unsafe fn set_mapped(d: &mjData, mapped: bool) {
        (*Self::of(d)).mapped = mapped;
    }

    /// A page map for `d`'s buffer: the kernel's where the buffer is a mapping of `d`'s own.
    ///
    /// # Safety
    /// As `init`.
    pub(crate) unsafe fn page_map(d: &mjData) -> PageMap {
        let slot = &*Self::of(d);
        PageMap::new(slot.owns(d) && slot.mapped)
    }

    fn owns(&self, d: &mjData) -> bool {
        std::ptr::eq(self.owner, d) && std::ptr::eq(self.buffer, d.buffer)
    }

    fn holds(&self, m: &mjModel, d: &mjData) -> bool {
        self.owns(d) && std::ptr::eq(self.model, m)
    }

    /// Keeps a bitwise copy of `view` (never dropped; read back by `Data::new`).
    unsafe fn keep(&mut self, m: &mjModel, view: &Data) {
        if self.owns(view.raw) {
            std::ptr::copy_nonoverlapping(
                view as *const Data as *const u8,
                self.image.as_mut_ptr() as *mut u8,
                std::mem::size_of::<Data>(),
            );
            self.model = m;
        }
    }
}

impl<'a> Data<'a> {
    /// The view kept with `d` for `m`, borrowed in place for reading: no copy and nothing
    /// written, so calls that only read may share it; None where none is kept for `m` or it is
    /// lent out (`with`). Its arena is that of the call that kept it: not for use.
    ///
    /// # Safety
    /// As `new`; nothing writes `d` while the borrow lasts.
    #[inline(always)]
    pub unsafe fn kept(m: &mjModel, d: &'a mjData) -> Option<&'a Data<'a>> {
        let slot = ViewSlot::of(d);
        if (*slot).busy || !(*slot).holds(m, d) {
            return None;
        }
        Some(&*(*slot).image.as_ptr())
    }
}

impl Data<'_> {
    /// actuator_moment with the record of where its rows may be nonzero.
    pub fn moments(&mut self) -> (&mut [f64], MomentSpans<'_>) {
        // SAFETY: `new`'s contract: the data came from `alloc_data`, which made the slot and
        // its record of `moment_rows` spans, memory apart from every array.
        unsafe {
            let slot = &mut *ViewSlot::of(self.raw);
            let first = (slot as *mut ViewSlot).add(1) as *mut [u32; 2];
            let spans = std::slice::from_raw_parts_mut(first, slot.moment_rows);
            let known = &mut slot.moments_known;
            (&mut *self.actuator_moment, MomentSpans { known, spans })
        }
    }

    /// Runs `f` with this data and a scratch arena scope taken from its stack; everything `f`
    /// allocates is released afterwards (mjMARKSTACK / mjFREESTACK).
    pub fn with_scratch<R>(&mut self, f: impl FnOnce(&mut Self, &mut Arena) -> R) -> R {
        let mut arena = std::mem::replace(&mut self.arena, Arena::over(&mut []));
        let r = arena.scope(|a| f(self, a));
        self.arena = arena;
        r
    }
}

impl Data<'_> {
    /// The stack's high-water mark into `maxuse_stack`.
    fn note_peak(&mut self) {
        let peak = self.arena.peak as i32;
        if peak > self.raw.maxuse_stack {
            self.raw.maxuse_stack = peak;
        }
    }
}

impl Drop for Data<'_> {
    fn drop(&mut self) {
        self.note_peak();
    }
}

/// Error raised by the core; the C API reports it through `mju_error`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EngineError(pub String);

impl std::fmt::Display for EngineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// 2.2.2's error when the stack runs out (out of line: allocations inline their fast path).
#[cold]
#[inline(never)]
fn stack_overflow() -> EngineError {
    EngineError("Stack overflow".into())
}

/// Stack-discipline scratch allocator over the free part of the `mjData` stack.
///
/// Allocations live until the arena (or the `scope` that made them) ends.
pub struct Arena<'a> {
    free: &'a mut [f64],
    used: usize,
    peak: usize,
}

impl<'a> Arena<'a> {
    /// An arena over caller-owned memory (tests, compiler scratch).
    pub fn over(buf: &'a mut [f64]) -> Self {
        Arena {
            free: buf,
            used: 0,
            peak: 0,
        }
    }

    /// `n` zeroed mjtNums, or an error like 2.2.2's "Stack overflow".
    #[inline]
    pub fn alloc(&mut self, n: usize) -> Result<&'a mut [f64], EngineError> {
        let head = self.alloc_stale(n)?;
        head.fill(0.0);
        Ok(head)
    }

    /// `n` mjtNums holding whatever an earlier allocation left there (not zeroed, like
    /// mj_stackAlloc): for scratch the caller writes before it reads.
    #[inline(always)]
    pub fn alloc_stale(&mut self, n: usize) -> Result<&'a mut [f64], EngineError> {
        if n > self.free.len() {
            return Err(stack_overflow());
        }
        let free = std::mem::take(&mut self.free);
        let (head, tail) = free.split_at_mut(n);
        self.free = tail;
        self.used += n;
        self.peak = self.peak.max(self.used);
        Ok(head)
    }

    /// `n` ints, not zeroed (see `alloc_stale`).
    #[inline]
    pub fn alloc_int_stale(&mut self, n: usize) -> Result<&'a mut [i32], EngineError> {
        let words = self.alloc_stale(n)?;
        // SAFETY: f64 storage is 8-aligned, initialized and large enough for n i32s.
        Ok(unsafe { std::slice::from_raw_parts_mut(words.as_mut_ptr() as *mut i32, n) })
    }

    /// `n` ints, not zeroed, taken as `n` mjtNums (2.2.2's `(int*)mj_stackAlloc(d, n)`):
    /// packed two to a slot, and the slots they leave free given back as scratch.
    #[inline]
    pub fn alloc_int_stale_spare(
        &mut self,
        n: usize,
    ) -> Result<(&'a mut [i32], &'a mut [f64]), EngineError> {
        let words = self.alloc_stale(n)?;
        let (ints, spare) = words.split_at_mut(n.div_ceil(2));
        // SAFETY: f64 storage is 8-aligned, initialized and holds 2 * ceil(n / 2) >= n i32s.
        let ints = unsafe { std::slice::from_raw_parts_mut(ints.as_mut_ptr() as *mut i32, n) };
        Ok((ints, spare))
    }

    /// `n` zeroed ints, taken from the same stack: one mjtNum each, as 2.2.2's
    /// `(int*)mj_stackAlloc(d, n)` takes them (so that `maxuse_stack` counts as 2.2.2's).
    #[inline]
    pub fn alloc_int(&mut self, n: usize) -> Result<&'a mut [i32], EngineError> {
        let words = self.alloc(n)?;
        // SAFETY: f64 storage is 8-aligned and large enough for n i32s; zero bits are 0i32.
        Ok(unsafe { std::slice::from_raw_parts_mut(words.as_mut_ptr() as *mut i32, n) })
    }

    /// `n` mjtNum-sized slots as u64, not zeroed: for records of two 32-bit fields packed in
    /// one slot (2.2.2's `mjtBroadphase`, an int and a float).
    #[inline]
    pub fn alloc_u64_stale(&mut self, n: usize) -> Result<&'a mut [u64], EngineError> {
        let words = self.alloc_stale(n)?;
        // SAFETY: u64 has f64's size and alignment, and every bit pattern is a valid u64.
        Ok(unsafe { std::slice::from_raw_parts_mut(words.as_mut_ptr() as *mut u64, n) })
    }

    /// Counts `n` mjtNums as taken and given back at once: the high-water mark and the
    /// overflow error of 2.2.2's allocation where a shortcut needs no scratch.
    #[inline]
    pub fn account(&mut self, n: usize) -> Result<(), EngineError> {
        if n > self.free.len() {
            return Err(stack_overflow());
        }
        self.peak = self.peak.max(self.used + n);
        Ok(())
    }

    /// Runs `f` with a nested arena; everything it allocates is released afterwards.
    #[inline]
    pub fn scope<R>(&mut self, f: impl FnOnce(&mut Arena<'_>) -> R) -> R {
        let mut inner = Arena {
            free: &mut *self.free,
            used: self.used,
            peak: self.used,
        };
        let r = f(&mut inner);
        self.peak = self.peak.max(inner.peak);
        r
    }

    /// Restarts the high-water mark (mj_resetData clears `maxuse_stack`; later use counts anew).
    #[inline]
    pub fn reset_peak(&mut self) {
        self.peak = 0;
    }

    /// Number of mjtNums in use, counted from the bottom of the `mjData` stack.
    #[inline]
    pub fn used(&self) -> usize {
        self.used
    }
}

/// The first `words.len()` ints of a span of mjtNums (2.2.2's `(int*)` reuse of an mjtNum
/// buffer as int scratch, one int per slot's first half).
pub fn ints_of(words: &mut [f64]) -> &mut [i32] {
    // SAFETY: f64 storage is 8-aligned and twice the size of the ints taken; every bit
    // pattern is a valid i32.
    unsafe { std::slice::from_raw_parts_mut(words.as_mut_ptr() as *mut i32, words.len()) }
}

/// Writable view of an abstract scene (mjvScene): its header, and its geom and skin vertex
/// buffers as slices.
pub struct Scene<'a> {
    /// Header: counts, lights, GL cameras, flags (its pointers must not be changed).
    pub raw: &'a mut mjvScene,
    pub geoms: &'a mut [mjvGeom],
    /// Order of transparent geoms (maxgeom).
    pub geomorder: &'a mut [i32],
    pub skinvert: &'a mut [f32],
    pub skinnormal: &'a mut [f32],
    /// Per skin (nskin): faces, first vertex and vertex count.
    pub skinfacenum: &'a [i32],
    pub skinvertadr: &'a [i32],
    pub skinvertnum: &'a [i32],
}

/// Number of skin vertices the scene's buffers hold.
///
/// # Safety
/// `skinvertnum` is NULL or holds `nskin` counts.
unsafe fn scene_skin_vertices(scn: &mjvScene) -> usize {
    if scn.skinvertnum.is_null() {
        return 0;
    }
    let vertnum = std::slice::from_raw_parts(scn.skinvertnum, scn.nskin.max(0) as usize);
    vertnum.iter().map(|&n| n.max(0) as usize).sum()
}

/// The scene's skin vertices, read only.
///
/// # Safety
/// As for `Scene::new`.
pub unsafe fn scene_skinvert(scn: &mjvScene) -> &[f32] {
    let n = 3 * scene_skin_vertices(scn);
    if scn.skinvert.is_null() {
        &[]
    } else {
        std::slice::from_raw_parts(scn.skinvert, n)
    }
}

impl<'a> Scene<'a> {
    /// # Safety
    /// `scn` comes from mjv_makeScene (or is cleared): `geoms` holds `maxgeom` geoms, the skin
    /// buffers 3 floats for each vertex its `skinvertnum` counts.
    pub unsafe fn new(scn: &'a mut mjvScene) -> Self {
        let totvert = scene_skin_vertices(scn);
        let maxgeom = scn.maxgeom.max(0) as usize;
        let geoms = view_mut(scn.geoms, maxgeom);
        let geomorder = view_mut(scn.geomorder, maxgeom);
        let nskin = scn.nskin.max(0) as usize;
        let skinfacenum = view_mut(scn.skinfacenum, nskin);
        let skinvertadr = view_mut(scn.skinvertadr, nskin);
        let skinvertnum = view_mut(scn.skinvertnum, nskin);
        let skinvert = view_mut(scn.skinvert, 3 * totvert);
        let skinnormal = view_mut(scn.skinnormal, 3 * totvert);
        Scene {
            raw: scn,
            geoms,
            geomorder,
            skinvert,
            skinnormal,
            skinfacenum,
            skinvertadr,
            skinvertnum,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Arena;

    #[test]
    fn account_counts_like_an_allocation_given_back() {
        let mut buf = [0.0; 10];
        let mut a = Arena::over(&mut buf);
        a.alloc_stale(2).unwrap();
        a.account(5).unwrap();
        assert_eq!(
            (a.used(), a.peak),
            (2, 7),
            "used unchanged, peak as if allocated"
        );
        a.account(8).unwrap();
        assert_eq!(a.peak, 10);
        assert_eq!(a.account(9).unwrap_err().0, "Stack overflow");
        assert_eq!(a.peak, 10, "a failed account leaves the mark");
        let mut b = [0.0; 4];
        let mut c = Arena::over(&mut b);
        assert_eq!(
            c.account(5),
            c.alloc_stale(5).map(|_| ()),
            "same error as the allocation"
        );
    }
}
