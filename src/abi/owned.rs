//! Owning handles of `mjModel` and `mjData`: made by the allocator, freed on drop, and the
//! only way the core outside the C shell reaches their memory (through the safe views).

use super::alloc::{alloc_data, copy_model, delete_data, delete_model, make_model};
use super::view::{Data, DataRef, Model, ModelMut};
use super::*;
use std::ptr::NonNull;

/// An `mjModel` made by `make_model` (or the MJB reader), freed with `delete_model`.
pub struct ModelBox(NonNull<mjModel>);

// SAFETY: the model's memory is owned by the box; shared access only reads it.
unsafe impl Send for ModelBox {}
// SAFETY: as above; writing needs `&mut ModelBox`.
unsafe impl Sync for ModelBox {}

impl ModelBox {
    /// A model with the sizes of `sizes`' header, arrays allocated (contents undefined until
    /// filled), their pages put in as they are first written.
    pub fn new(sizes: &mjModel) -> Result<Self, String> {
        let m = make_model(sizes, false)?;
        // SAFETY: make_model returns a fresh model or an error.
        Ok(unsafe { Self::from_raw(m) })
    }

    /// A model from an MJB image (a file's contents, or a memory buffer when `buffer`);
    /// errors carry 2.2.2's texts.
    pub fn from_mjb(bytes: &[u8], buffer: bool) -> Result<Self, mjb::LoadError> {
        let m = mjb::load(bytes, buffer)?;
        // SAFETY: as in `new`.
        Ok(unsafe { Self::from_raw(m) })
    }

    /// A model from an MJB image of `len` bytes read in order from `src` (a file).
    pub fn from_mjb_reader<R: std::io::Read>(
        src: &mut R,
        len: usize,
        buffer: bool,
    ) -> Result<Self, mjb::LoadError> {
        let m = mjb::load_from(src, len, buffer)?;
        // SAFETY: as in `new`.
        Ok(unsafe { Self::from_raw(m) })
    }

    /// Takes ownership of `m`.
    ///
    /// # Safety
    /// `m` is non-NULL, came from `make_model`, `copy_model` or the MJB reader, and is owned
    /// by nobody else.
    pub unsafe fn from_raw(m: *mut mjModel) -> Self {
        ModelBox(NonNull::new(m).expect("ModelBox::from_raw: NULL model"))
    }

    /// Gives up ownership: the caller frees the model (mj_deleteModel).
    pub fn into_raw(self) -> *mut mjModel {
        let p = self.0.as_ptr();
        std::mem::forget(self);
        p
    }

    /// A copy (mj_copyModel).
    pub fn try_clone(&self) -> Result<Self, String> {
        // SAFETY: a NULL destination makes a new model.
        let m = unsafe { copy_model(std::ptr::null_mut(), self.raw())? };
        // SAFETY: as in `new`.
        Ok(unsafe { Self::from_raw(m) })
    }

    pub fn as_ptr(&self) -> *const mjModel {
        self.0.as_ptr()
    }

    /// The header: sizes, options, statistics, array addresses.
    pub fn raw(&self) -> &mjModel {
        // SAFETY: owned and valid while self lives.
        unsafe { self.0.as_ref() }
    }

    pub fn view(&self) -> Model<'_> {
        // SAFETY: the model came from the allocator (from_raw's contract).
        unsafe { Model::new(self.raw()) }
    }

    pub fn view_mut(&mut self) -> ModelMut<'_> {
        // SAFETY: as in `view`; `&mut self` excludes every other view.
        unsafe { ModelMut::new(self.0.as_mut()) }
    }

    /// The physics options (plain values: writable without touching the layout).
    pub fn opt_mut(&mut self) -> &mut mjOption {
        // SAFETY: `&mut self` gives exclusive access to the header.
        unsafe { &mut self.0.as_mut().opt }
    }

    pub fn stat_mut(&mut self) -> &mut mjStatistic {
        // SAFETY: as in `opt_mut`.
        unsafe { &mut self.0.as_mut().stat }
    }

    pub fn vis_mut(&mut self) -> &mut mjVisual {
        // SAFETY: as in `opt_mut`.
        unsafe { &mut self.0.as_mut().vis }
    }

    /// The MJB image of the model (mj_saveModel).
    pub fn save(&self) -> Vec<u8> {
        mjb::save(self.raw())
    }
}

impl Drop for ModelBox {
    fn drop(&mut self) {
        // SAFETY: owned, from the allocator.
        unsafe { delete_model(self.0.as_ptr()) }
    }
}

/// An `mjData` made by `alloc_data` for one model, freed with `delete_data`.
pub struct DataBox {
    data: NonNull<mjData>,
    /// The model it was made for: views are built only with that model.
    model: *const mjModel,
}

// SAFETY: the data's memory is owned by the box; `model` is only compared, never read.
unsafe impl Send for DataBox {}

impl DataBox {
    /// Data for `m`, its memory zeroed by `alloc_data` (mj_resetData gives the initial state).
    pub fn new(m: &ModelBox) -> Result<Self, String> {
        let d = alloc_data(m.raw())?;
        // SAFETY: alloc_data returns a fresh, non-NULL mjData on success.
        Ok(DataBox {
            data: unsafe { NonNull::new_unchecked(d) },
            model: m.as_ptr(),
        })
    }

    /// Takes ownership of `d`, made for `m`.
    ///
    /// # Safety
    /// `d` is non-NULL, came from `alloc_data(m)` and is owned by nobody else.
    pub unsafe fn from_raw(d: *mut mjData, m: &ModelBox) -> Self {
        DataBox {
            data: NonNull::new(d).expect("DataBox::from_raw: NULL data"),
            model: m.as_ptr(),
        }
    }

    /// Gives up ownership: the caller frees the data (mj_deleteData).
    pub fn into_raw(self) -> *mut mjData {
        let p = self.data.as_ptr();
        std::mem::forget(self);
        p
    }

    /// The header: scalars, diagnostics, array addresses.
    pub fn raw(&self) -> &mjData {
        // SAFETY: owned and valid while self lives.
        unsafe { self.data.as_ref() }
    }

    fn check(&self, m: &ModelBox) {
        assert!(
            std::ptr::eq(self.model, m.as_ptr()),
            "mjData used with a model it was not made for"
        );
    }

    /// The writable view (panics when `m` is not the model the data was made for).
    pub fn view<'a>(&'a mut self, m: &ModelBox) -> Data<'a> {
        self.check(m);
        // SAFETY: the data was made for m (checked), and `&mut self` excludes other views.
        unsafe { Data::new(m.raw(), self.data.as_mut()) }
    }

    /// The read-only view (panics as `view`).
    pub fn view_ref<'a>(&'a self, m: &'a ModelBox) -> DataRef<'a> {
        self.check(m);
        // SAFETY: as in `view`; shared access only reads.
        unsafe { DataRef::new(m.raw(), self.data.as_ref()) }
    }
}

impl Drop for DataBox {
    fn drop(&mut self) {
        // SAFETY: owned, from alloc_data.
        unsafe { delete_data(self.data.as_ptr()) }
    }
}

/// An mjModel header with every size zero and every address NULL (a compiler's blank).
pub fn blank_model_header() -> mjModel {
    // SAFETY: all-zero bits are a valid mjModel: integers, floats and NULL pointers.
    unsafe { std::mem::zeroed() }
}
