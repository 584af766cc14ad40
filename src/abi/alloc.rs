//! Memory of `mjModel` and `mjData` laid out as 2.2.2 lays it out: one buffer per struct, the
//! X-macro arrays in order, each starting on a 64-byte boundary; the mjData stack apart.

use super::view::ViewSlot;
use super::*;
use crate::runtime::memory::{
    alloc_large, alloc_model_block, copy_pages, free, free_large, free_model_block, malloc, maps,
};
use std::os::raw::c_void;

const ALIGN: usize = 64;

fn pad(offset: usize) -> usize {
    (ALIGN - offset % ALIGN) % ALIGN
}

/// `size` (a buffer's bytes so far) grown by a row of `count` elements of `elem` bytes on the
/// next 64-byte boundary, or None on overflow.
#[inline(never)]
fn grow(size: usize, elem: usize, count: usize) -> Option<usize> {
    size.checked_add(pad(size))?
        .checked_add(elem.checked_mul(count)?)
}

/// Bytes of a buffer of X-macro rows for sizes `m`, or None on overflow or past i32 (summed
/// row by row, with no list of rows: a fresh process's first load faults in every new page
/// it allocates).
macro_rules! buffer_bytes {
    ($m:ident; $(($t:ident, $d1:ident, $($d2:tt)+))*) => {{
        let size = Some(0);
        $(let size = grow(size?, std::mem::size_of::<elem_ty!($t)>(), row_len!($m, $d1, $($d2)+));)*
        size.filter(|&s| s <= i32::MAX as usize)
    }};
}

macro_rules! model_rows {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        /// Bytes of the buffer of a model of these sizes.
        fn model_buffer_bytes(m: &mjModel) -> Option<usize> {
            buffer_bytes!(m; $(($t, $d1, $($d2)+))*)
        }
        /// Number of arrays of mjModel.
        const MODEL_NPTR: usize = [$(stringify!($name)),*].len();
        unsafe fn set_model_pointers(m: &mut mjModel) {
            let base = m.buffer as *mut u8;
            let mut off = 0usize;
            $(
                off += pad(off);
                m.$name = base.add(off) as *mut elem_ty!($t);
                off += std::mem::size_of::<elem_ty!($t)>() * row_len!(m, $d1, $($d2)+);
            )*
            debug_assert_eq!(off, m.nbuffer as usize);
        }
        /// `f(offset, length)` of every array in `m.buffer` in turn in X-macro order,
        /// until an error.
        #[allow(unused_assignments)]
        pub fn walk_model_spans<E>(
            m: &mjModel,
            mut f: impl FnMut(usize, usize) -> Result<(), E>,
        ) -> Result<(), E> {
            let mut end = 0usize;
            $(
                let off = end + pad(end);
                let len = std::mem::size_of::<elem_ty!($t)>() * row_len!(m, $d1, $($d2)+);
                f(off, len)?;
                end = off + len;
            )*
            Ok(())
        }
    };
}
mjmodel_pointers!(model_rows);

macro_rules! data_rows {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        fn data_rows(m: &mjModel) -> Vec<(&'static str, usize, usize)> {
            vec![$((stringify!($name), std::mem::size_of::<elem_ty!($t)>(), row_len!(m, $d1, $($d2)+)),)*]
        }
        /// Bytes of the arrays of a data of model `m`.
        fn data_buffer_bytes(m: &mjModel) -> Option<usize> {
            buffer_bytes!(m; $(($t, $d1, $($d2)+))*)
        }
        unsafe fn set_data_pointers(m: &mjModel, d: &mut mjData) {
            let base = d.buffer as *mut u8;
            let mut off = 0usize;
            $(
                off += pad(off);
                d.$name = base.add(off) as *mut elem_ty!($t);
                off += std::mem::size_of::<elem_ty!($t)>() * row_len!(m, $d1, $($d2)+);
            )*
            debug_assert_eq!(off, d.nbuffer as usize);
        }
        /// Copies every array of `src` into `dest` (not the padding between them, as 2.2.2),
        /// the pages src never wrote left unread (`copy_pages`).
        unsafe fn copy_data_arrays(m: &mjModel, dest: &mjData, src: &mjData) {
            let (mut dst_map, mut src_map) = (ViewSlot::page_map(dest), ViewSlot::page_map(src));
            $(
                copy_pages(
                    &mut dst_map,
                    &mut src_map,
                    dest.$name as *mut u8,
                    src.$name as *const u8,
                    std::mem::size_of::<elem_ty!($t)>() * row_len!(m, $d1, $($d2)+),
                );
            )*
        }
    };
}
mjdata_pointers!(data_rows);

macro_rules! model_int_names {
    ($(($name:ident)),* $(,)?) => {
        /// The int fields of mjModel in X-macro order, with their values.
        pub fn model_ints(m: &mjModel) -> [(&'static str, i32); MODEL_NINT] {
            [$((stringify!($name), m.$name),)*]
        }
        /// Number of int fields of mjModel.
        const MODEL_NINT: usize = [$(stringify!($name)),*].len();
    };
}
mjmodel_ints!(model_int_names);

/// Allocates a model whose int fields are copied from `sizes`; default options. `overwrite`:
/// the caller writes every byte of the buffer (a copy, an MJB image): it may hold old bytes
/// (`memory::alloc_model_block`), fresh pages come in at once; else it is zeroed, fresh pages
/// coming in as they are first written (a compiler filling it while freeing its own arrays:
/// a lower peak).
pub fn make_model(sizes: &mjModel, overwrite: bool) -> Result<*mut mjModel, String> {
    for (name, v) in model_ints(sizes) {
        if v < 0 {
            return Err(format!("Invalid model: negative {name}"));
        }
    }
    if sizes.nbody == 0 {
        return Err("Invalid model: nbody == 0".into());
    }
    if sizes.nmocap >= i32::MAX / 4 {
        return Err("Invalid model: nmocap too large".into());
    }
    let nbuffer = model_buffer_bytes(sizes).ok_or("Invalid model: buffer too large")?;
    // SAFETY: all-zero bits are a valid mjModel (null pointers, zero numbers).
    let mut header: mjModel = unsafe { std::mem::zeroed() };
    copy_ints(&mut header, sizes);
    header.nbuffer = nbuffer as i32;
    header.opt = default_option();
    header.vis = default_visual();
    header.stat = default_statistic();
    let m = malloc(std::mem::size_of::<mjModel>()) as *mut mjModel;
    let buffer = alloc_model_block(nbuffer.max(1), overwrite);
    if m.is_null() || buffer.is_null() {
        // SAFETY: each is NULL or a fresh allocation.
        unsafe {
            free(m as *mut c_void);
            free_model_block(buffer, nbuffer.max(1));
        }
        return Err("Could not allocate mjModel".into());
    }
    // SAFETY: fresh allocations of the right sizes (the buffer zeroed).
    unsafe {
        header.buffer = buffer;
        m.write(header);
        set_model_pointers(&mut *m);
    }
    Ok(m)
}

macro_rules! copy_int_fields {
    ($(($name:ident)),* $(,)?) => {
        fn copy_ints(dst: &mut mjModel, src: &mjModel) {
            $(dst.$name = src.$name;)*
        }
    };
}
mjmodel_ints!(copy_int_fields);

/// # Safety
/// `m` is NULL or came from `make_model`.
pub unsafe fn delete_model(m: *mut mjModel) {
    if !m.is_null() {
        free_model_block((*m).buffer, (*m).nbuffer.max(1) as usize);
        free(m as *mut c_void);
    }
}

/// Copies `src` into `dest` (same sizes) or into a new model when `dest` is NULL.
///
/// # Safety
/// `dest` is NULL or came from `make_model`; `src` came from `make_model`.
pub unsafe fn copy_model(dest: *mut mjModel, src: &mjModel) -> Result<*mut mjModel, String> {
    let dest = if dest.is_null() {
        make_model(src, true)?
    } else {
        dest
    };
    if (*dest).nbuffer != src.nbuffer {
        return Err("dest and src models have different buffer size".into());
    }
    let buffer = (*dest).buffer;
    std::ptr::copy_nonoverlapping(src as *const mjModel, dest, 1);
    (*dest).buffer = buffer;
    set_model_pointers(&mut *dest);
    std::ptr::copy_nonoverlapping(
        src.buffer as *const u8,
        buffer as *mut u8,
        src.nbuffer as usize,
    );
    Ok(dest)
}

/// Size of the MJB image of a model, as `mj_sizeModel` reports it.
pub fn size_model(m: &mjModel) -> i32 {
    let nint = MODEL_NINT;
    (std::mem::size_of::<i32>() * (4 + nint)
        + std::mem::size_of::<mjOption>()
        + std::mem::size_of::<mjVisual>()
        + std::mem::size_of::<mjStatistic>()) as i32
        + m.nbuffer
}

/// Allocates data for `m`; its contents are undefined until reset.
pub fn alloc_data(m: &mjModel) -> Result<*mut mjData, String> {
    let nbuffer = data_buffer_bytes(m).ok_or("Invalid data: buffer too large")?;
    let nstack = m.nstack.max(0) as usize;
    let d = malloc(std::mem::size_of::<mjData>()) as *mut mjData;
    // both zeroed, so that no view ever reads uninitialized memory (scratch taken unzeroed by
    // Arena::alloc_stale, arrays before mj_resetData); large ones are fresh pages, untouched
    // until the simulation reaches them
    let rows = m.nu.max(0) as usize;
    let buffer_size = data_buffer_size(nbuffer, rows);
    let mapped = maps(buffer_size);
    let buffer = alloc_large(buffer_size, false);
    let stack = alloc_large((nstack * 8).max(1), false);
    if d.is_null() || buffer.is_null() || stack.is_null() {
        // SAFETY: each is NULL or a fresh allocation.
        unsafe {
            free(d as *mut c_void);
            free_large(buffer, buffer_size);
            free_large(stack, (nstack * 8).max(1));
        }
        return Err("Could not allocate mjData".into());
    }
    // SAFETY: fresh allocations; all-zero bits are a valid mjData header.
    unsafe {
        std::ptr::write_bytes(d as *mut u8, 0, std::mem::size_of::<mjData>());
        (*d).nbuffer = nbuffer as i32;
        (*d).nstack = nstack as i32;
        (*d).buffer = buffer;
        (*d).stack = stack as *mut f64;
        set_data_pointers(m, &mut *d);
        ViewSlot::init(&*d);
        ViewSlot::set_mapped(&*d, mapped);
        ViewSlot::set_moment_spans(&*d, rows);
    }
    Ok(d)
}

/// Bytes of an mjData buffer of `nbuffer` for `rows` actuators: the arrays, then the view
/// slot and its moment spans.
fn data_buffer_size(nbuffer: usize, rows: usize) -> usize {
    ViewSlot::offset(nbuffer)
        + std::mem::size_of::<ViewSlot>()
        + rows * std::mem::size_of::<[u32; 2]>()
}

/// # Safety
/// `d` is NULL or came from `alloc_data`.
pub unsafe fn delete_data(d: *mut mjData) {
    if !d.is_null() {
        let rows = ViewSlot::moment_rows(&*d);
        free_large(
            (*d).buffer,
            data_buffer_size((*d).nbuffer.max(0) as usize, rows),
        );
        free_large(
            (*d).stack as *mut c_void,
            ((*d).nstack.max(0) as usize * 8).max(1),
        );
        free(d as *mut c_void);
    }
}

/// `mj_copyData`.
///
/// # Safety
/// `dest` is NULL or was made for `m`; `src` was made for `m`.
pub unsafe fn copy_data(
    dest: *mut mjData,
    m: &mjModel,
    src: &mjData,
) -> Result<*mut mjData, String> {
    let dest = if dest.is_null() { alloc_data(m)? } else { dest };
    if (*dest).nbuffer != src.nbuffer {
        return Err("dest and src data buffers have different size".into());
    }
    if (*dest).nstack != src.nstack {
        return Err("dest and src stacks have different size".into());
    }
    if src.pstack != 0 {
        return Err("Attempting to copy mjData while stack is in use".into());
    }
    if std::ptr::eq(dest, src) {
        // a copy onto itself leaves it as it is
        return Ok(dest);
    }
    let (buffer, stack) = ((*dest).buffer, (*dest).stack);
    std::ptr::copy_nonoverlapping(src as *const mjData, dest, 1);
    (*dest).buffer = buffer;
    (*dest).stack = stack;
    set_data_pointers(m, &mut *dest);
    ViewSlot::init(&*dest);
    ViewSlot::forget_moments(&*dest);
    copy_data_arrays(m, &*dest, src);
    Ok(dest)
}

/// Fills the whole array buffer with one byte (`mj_resetDataDebug`'s pattern).
///
/// # Safety
/// `d` came from `alloc_data`.
pub unsafe fn fill_buffer(d: &mut mjData, byte: u8) {
    ViewSlot::forget_moments(d);
    std::ptr::write_bytes(d.buffer as *mut u8, byte, d.nbuffer as usize);
}

pub fn default_solref() -> [f64; 2] {
    [0.02, 1.0]
}

pub fn default_solimp() -> [f64; 5] {
    [0.9, 0.95, 0.001, 0.5, 2.0]
}

pub fn default_option() -> mjOption {
    mjOption {
        timestep: 0.002,
        apirate: 100.0,
        impratio: 1.0,
        tolerance: 1e-8,
        noslip_tolerance: 1e-6,
        mpr_tolerance: 1e-6,
        gravity: [0.0, 0.0, -9.81],
        wind: [0.0; 3],
        magnetic: [0.0, -0.5, 0.0],
        density: 0.0,
        viscosity: 0.0,
        o_margin: 0.0,
        o_solref: default_solref(),
        o_solimp: default_solimp(),
        integrator: mjtIntegrator::mjINT_EULER as i32,
        collision: mjtCollision::mjCOL_ALL as i32,
        cone: mjtCone::mjCONE_PYRAMIDAL as i32,
        jacobian: mjtJacobian::mjJAC_AUTO as i32,
        solver: mjtSolver::mjSOL_NEWTON as i32,
        iterations: 100,
        noslip_iterations: 0,
        mpr_iterations: 50,
        disableflags: 0,
        enableflags: 0,
    }
}

pub fn default_lropt() -> mjLROpt {
    mjLROpt {
        mode: mjtLRMode::mjLRMODE_MUSCLE as i32,
        useexisting: 1,
        uselimit: 0,
        accel: 20.0,
        maxforce: 0.0,
        timeconst: 1.0,
        timestep: 0.01,
        inttotal: 10.0,
        inteval: 2.0,
        tolrange: 0.05,
    }
}

pub fn default_statistic() -> mjStatistic {
    mjStatistic {
        meaninertia: 1.0,
        meanmass: 1.0,
        meansize: 0.2,
        extent: 2.0,
        center: [0.0; 3],
    }
}

pub fn default_visual() -> mjVisual {
    let rgba = |r: f32, g: f32, b: f32, a: f32| [r, g, b, a];
    mjVisual {
        global: mjVisualGlobal {
            fovy: 45.0,
            ipd: 0.068,
            azimuth: 90.0,
            elevation: -45.0,
            linewidth: 1.0,
            glow: 0.3,
            offwidth: 640,
            offheight: 480,
        },
        quality: mjVisualQuality {
            shadowsize: 4096,
            offsamples: 4,
            numslices: 28,
            numstacks: 16,
            numquads: 4,
        },
        headlight: mjVisualHeadlight {
            ambient: [0.1; 3],
            diffuse: [0.4; 3],
            specular: [0.5; 3],
            active: 1,
        },
        map: mjVisualMap {
            stiffness: 100.0,
            stiffnessrot: 500.0,
            force: 0.005,
            torque: 0.1,
            alpha: 0.3,
            fogstart: 3.0,
            fogend: 10.0,
            znear: 0.01,
            zfar: 50.0,
            haze: 0.3,
            shadowclip: 1.0,
            shadowscale: 0.6,
            actuatortendon: 2.0,
        },
        scale: mjVisualScale {
            forcewidth: 0.1,
            contactwidth: 0.3,
            contactheight: 0.1,
            connect: 0.2,
            com: 0.4,
            camera: 0.3,
            light: 0.3,
            selectpoint: 0.2,
            jointlength: 1.0,
            jointwidth: 0.1,
            actuatorlength: 0.7,
            actuatorwidth: 0.2,
            framelength: 1.0,
            framewidth: 0.1,
            constraint: 0.1,
            slidercrank: 0.2,
        },
        rgba: mjVisualRgba {
            fog: rgba(0., 0., 0., 1.),
            haze: rgba(1., 1., 1., 1.),
            force: rgba(1., 0.5, 0.5, 1.),
            inertia: rgba(0.8, 0.2, 0.2, 0.6),
            joint: rgba(0.2, 0.6, 0.8, 1.),
            actuator: rgba(0.2, 0.25, 0.2, 1.),
            actuatornegative: rgba(0.2, 0.6, 0.9, 1.),
            actuatorpositive: rgba(0.9, 0.4, 0.2, 1.),
            com: rgba(0.9, 0.9, 0.9, 1.),
            camera: rgba(0.6, 0.9, 0.6, 1.),
            light: rgba(0.6, 0.6, 0.9, 1.),
            selectpoint: rgba(0.9, 0.9, 0.1, 1.),
            connect: rgba(0.2, 0.2, 0.8, 1.),
            contactpoint: rgba(0.9, 0.6, 0.2, 1.),
            contactforce: rgba(0.7, 0.9, 0.9, 1.),
            contactfriction: rgba(0.9, 0.8, 0.4, 1.),
            contacttorque: rgba(0.9, 0.7, 0.9, 1.),
            contactgap: rgba(0.5, 0.8, 0.9, 1.),
            rangefinder: rgba(1., 1., 0.1, 1.),
            constraint: rgba(0.9, 0., 0., 1.),
            slidercrank: rgba(0.5, 0.3, 0.8, 1.),
            crankbroken: rgba(0.9, 0., 0., 1.),
        },
    }
}

/// Byte offset and length of each array within a buffer laid out from `rows`.
fn spans(rows: &[(&'static str, usize, usize)]) -> Vec<(&'static str, usize, usize)> {
    let mut off = 0;
    rows.iter()
        .map(|&(name, elem, count)| {
            off += pad(off);
            let span = (name, off, elem * count);
            off += elem * count;
            span
        })
        .collect()
}

/// Every mjData array as (name, byte offset in `d.buffer`, byte length), in X-macro order.
pub fn data_spans(m: &mjModel) -> Vec<(&'static str, usize, usize)> {
    spans(&data_rows(m))
}

/// Number of int fields and of arrays of mjModel: the MJB header's counts.
pub fn model_counts() -> (usize, usize) {
    (MODEL_NINT, MODEL_NPTR)
}
