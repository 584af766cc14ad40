//! OpenGL loaded at run time, as 2.2.2's loader does it: the GetProcAddress of the platform
//! (EGL, OSMesa or GLX) the caller's program already loaded, found in the process's global
//! symbols or else among its loaded libraries. The library never links libGL. This module is
//! the OpenGL boundary: every call into GL goes through `Gl`.

#![allow(non_snake_case, clippy::too_many_arguments, clippy::missing_safety_doc)]

use std::ffi::{c_void, CStr};
use std::os::raw::c_char;
use std::sync::OnceLock;

pub type DebugProc = unsafe extern "C" fn(u32, u32, u32, u32, i32, *const c_char, *const c_void);
type GetProcAddress = unsafe extern "C" fn(*const c_char) -> *const c_void;

macro_rules! gl_api {
    (
        safe { $(fn $s:ident($($sa:ident: $st:ty),*) $(-> $sr:ty)?;)* }
        raw { $(fn $r:ident($($ra:ident: $rt:ty),*) $(-> $rr:ty)?;)* }
    ) => {
        /// The OpenGL functions the renderer uses (None where the implementation lacks one).
        pub struct Gl {
            $($s: Option<unsafe extern "C" fn($($st),*) $(-> $sr)?>,)*
            $($r: Option<unsafe extern "C" fn($($rt),*) $(-> $rr)?>,)*
            pub version: (i32, i32),
            extensions: String,
        }

        impl Gl {
            /// No function at all: what every call meets before OpenGL is loaded.
            const ABSENT: Gl = Gl {
                $($s: None,)*
                $($r: None,)*
                version: (0, 0),
                extensions: String::new(),
            };

            fn load(get: impl Fn(&CStr) -> *const c_void) -> Gl {
                Gl {
                    // SAFETY: a GL function of this name has this C signature.
                    $($s: unsafe { std::mem::transmute::<*const c_void, Option<unsafe extern "C" fn($($st),*) $(-> $sr)?>>(get(&cname(stringify!($s)))) },)*
                    $($r: unsafe { std::mem::transmute::<*const c_void, Option<unsafe extern "C" fn($($rt),*) $(-> $rr)?>>(get(&cname(stringify!($r)))) },)*
                    version: (0, 0),
                    extensions: String::new(),
                }
            }

            $(
                /// Calls the GL function of this name (no pointers: safe with or without a
                /// current context).
                #[inline]
                pub fn $s(&self, $($sa: $st),*) $(-> $sr)? {
                    let Some(f) = self.$s else { missing(stringify!($s)) };
                    // SAFETY: scalar arguments only.
                    unsafe { f($($sa),*) }
                }
            )*
            $(
                /// Calls the GL function of this name; the caller vouches for its pointers.
                #[inline]
                pub unsafe fn $r(&self, $($ra: $rt),*) $(-> $rr)? {
                    let Some(f) = self.$r else { missing(stringify!($r)) };
                    f($($ra),*)
                }
            )*
        }
    };
}

/// The panic of a call to a GL function that is not loaded (caught at the C boundary, which
/// reports it through mju_error; see `is_missing`).
#[cold]
#[inline(never)]
fn missing(name: &'static str) -> ! {
    std::panic::panic_any(Missing(name))
}

/// Panic payload: the GL function that was called but is not loaded.
pub struct Missing(pub &'static str);

/// The function named by a panic payload of a GL function that is not loaded.
pub fn is_missing(payload: &(dyn std::any::Any + Send)) -> Option<&'static str> {
    payload.downcast_ref::<Missing>().map(|m| m.0)
}

fn cname(s: &str) -> std::ffi::CString {
    std::ffi::CString::new(s).unwrap()
}

gl_api! {
    safe {
        fn glActiveTexture(texture: u32);
        fn glAlphaFunc(func: u32, r#ref: f32);
        fn glBegin(mode: u32);
        fn glBindBuffer(target: u32, buffer: u32);
        fn glBindFramebuffer(target: u32, framebuffer: u32);
        fn glBindRenderbuffer(target: u32, renderbuffer: u32);
        fn glBindTexture(target: u32, texture: u32);
        fn glBlendFunc(sfactor: u32, dfactor: u32);
        fn glBlitFramebuffer(srcX0: i32, srcY0: i32, srcX1: i32, srcY1: i32, dstX0: i32, dstY0: i32, dstX1: i32, dstY1: i32, mask: u32, filter: u32);
        fn glCallList(list: u32);
        fn glCheckFramebufferStatus(target: u32) -> u32;
        fn glClear(mask: u32);
        fn glClearColor(red: f32, green: f32, blue: f32, alpha: f32);
        fn glClearDepth(depth: f64);
        fn glClearStencil(s: i32);
        fn glColor3f(red: f32, green: f32, blue: f32);
        fn glColor4d(red: f64, green: f64, blue: f64, alpha: f64);
        fn glColor4f(red: f32, green: f32, blue: f32, alpha: f32);
        fn glColorMask(red: u8, green: u8, blue: u8, alpha: u8);
        fn glColorMaterial(face: u32, mode: u32);
        fn glCullFace(mode: u32);
        fn glDeleteLists(list: u32, range: i32);
        fn glDepthFunc(func: u32);
        fn glDepthMask(flag: u8);
        fn glDepthRange(n: f64, f: f64);
        fn glDisable(cap: u32);
        fn glDisableClientState(array: u32);
        fn glDrawArrays(mode: u32, first: i32, count: i32);
        fn glDrawBuffer(buf: u32);
        fn glEnable(cap: u32);
        fn glEnableClientState(array: u32);
        fn glEnd();
        fn glEndList();
        fn glFinish();
        fn glFogf(pname: u32, param: f32);
        fn glFogi(pname: u32, param: i32);
        fn glFramebufferRenderbuffer(target: u32, attachment: u32, renderbuffertarget: u32, renderbuffer: u32);
        fn glFramebufferTexture2D(target: u32, attachment: u32, textarget: u32, texture: u32, level: i32);
        fn glFrontFace(mode: u32);
        fn glFrustum(left: f64, right: f64, bottom: f64, top: f64, zNear: f64, zFar: f64);
        fn glGenLists(range: i32) -> u32;
        fn glGenerateMipmap(target: u32);
        fn glGetError() -> u32;
        fn glGetString(name: u32) -> *const u8;
        fn glHint(target: u32, mode: u32);
        fn glIsEnabled(cap: u32) -> u8;
        fn glLightModeli(pname: u32, param: i32);
        fn glLightf(light: u32, pname: u32, param: f32);
        fn glLineWidth(width: f32);
        fn glListBase(base: u32);
        fn glLoadIdentity();
        fn glMaterialf(face: u32, pname: u32, param: f32);
        fn glMatrixMode(mode: u32);
        fn glNewList(list: u32, mode: u32);
        fn glNormal3d(nx: f64, ny: f64, nz: f64);
        fn glNormal3f(nx: f32, ny: f32, nz: f32);
        fn glOrtho(left: f64, right: f64, bottom: f64, top: f64, zNear: f64, zFar: f64);
        fn glPixelStorei(pname: u32, param: i32);
        fn glPolygonMode(face: u32, mode: u32);
        fn glPopMatrix();
        fn glPushMatrix();
        fn glRasterPos2i(x: i32, y: i32);
        fn glRasterPos3f(x: f32, y: f32, z: f32);
        fn glRasterPos3i(x: i32, y: i32, z: i32);
        fn glReadBuffer(src: u32);
        fn glRenderbufferStorage(target: u32, internalformat: u32, width: i32, height: i32);
        fn glRenderbufferStorageMultisample(target: u32, samples: i32, internalformat: u32, width: i32, height: i32);
        fn glRotatef(angle: f32, x: f32, y: f32, z: f32);
        fn glScalef(x: f32, y: f32, z: f32);
        fn glScissor(x: i32, y: i32, width: i32, height: i32);
        fn glShadeModel(mode: u32);
        fn glStencilFunc(func: u32, r#ref: i32, mask: u32);
        fn glStencilOp(fail: u32, zfail: u32, zpass: u32);
        fn glTexEnvi(target: u32, pname: u32, param: i32);
        fn glTexGeni(coord: u32, pname: u32, param: i32);
        fn glTexParameteri(target: u32, pname: u32, param: i32);
        fn glTranslatef(x: f32, y: f32, z: f32);
        fn glVertex2d(x: f64, y: f64);
        fn glVertex2f(x: f32, y: f32);
        fn glVertex2i(x: i32, y: i32);
        fn glVertex3d(x: f64, y: f64, z: f64);
        fn glVertex3f(x: f32, y: f32, z: f32);
        fn glViewport(x: i32, y: i32, width: i32, height: i32);
        fn glWindowPos2i(x: i32, y: i32);
    }
    raw {
        fn glBitmap(width: i32, height: i32, xorig: f32, yorig: f32, xmove: f32, ymove: f32, bitmap: *const u8);
        fn glBufferData(target: u32, size: isize, data: *const std::ffi::c_void, usage: u32);
        fn glCallLists(n: i32, r#type: u32, lists: *const std::ffi::c_void);
        fn glClipPlane(plane: u32, equation: *const f64);
        fn glColor3fv(v: *const f32);
        fn glColor4fv(v: *const f32);
        fn glColor4ubv(v: *const u8);
        fn glDebugMessageCallback(callback: Option<DebugProc>, userParam: *const std::ffi::c_void);
        fn glDeleteBuffers(n: i32, buffers: *const u32);
        fn glDeleteFramebuffers(n: i32, framebuffers: *const u32);
        fn glDeleteRenderbuffers(n: i32, renderbuffers: *const u32);
        fn glDeleteTextures(n: i32, textures: *const u32);
        fn glDrawElements(mode: u32, count: i32, r#type: u32, indices: *const std::ffi::c_void);
        fn glDrawPixels(width: i32, height: i32, format: u32, r#type: u32, pixels: *const std::ffi::c_void);
        fn glFogfv(pname: u32, params: *const f32);
        fn glGenBuffers(n: i32, buffers: *mut u32);
        fn glGenFramebuffers(n: i32, framebuffers: *mut u32);
        fn glGenRenderbuffers(n: i32, renderbuffers: *mut u32);
        fn glGenTextures(n: i32, textures: *mut u32);
        fn glGetBooleanv(pname: u32, data: *mut u8);
        fn glGetFloatv(pname: u32, data: *mut f32);
        fn glGetIntegerv(pname: u32, data: *mut i32);
        fn glGetRenderbufferParameteriv(target: u32, pname: u32, params: *mut i32);
        fn glLightModelfv(pname: u32, params: *const f32);
        fn glLightfv(light: u32, pname: u32, params: *const f32);
        fn glLoadMatrixf(m: *const f32);
        fn glMaterialfv(face: u32, pname: u32, params: *const f32);
        fn glMultMatrixf(m: *const f32);
        fn glNormal3fv(v: *const f32);
        fn glNormalPointer(r#type: u32, stride: i32, pointer: *const std::ffi::c_void);
        fn glReadPixels(x: i32, y: i32, width: i32, height: i32, format: u32, r#type: u32, pixels: *mut std::ffi::c_void);
        fn glTexCoord2fv(v: *const f32);
        fn glTexCoordPointer(size: i32, r#type: u32, stride: i32, pointer: *const std::ffi::c_void);
        fn glTexGenfv(coord: u32, pname: u32, params: *const f32);
        fn glTexImage2D(target: u32, level: i32, internalformat: i32, width: i32, height: i32, border: i32, format: u32, r#type: u32, pixels: *const std::ffi::c_void);
        fn glVertexPointer(size: i32, r#type: u32, stride: i32, pointer: *const std::ffi::c_void);
    fn glVertex3fv(v: *const f32);
    }
}

const GL_VERSION: u32 = 0x1F02;
const GL_EXTENSIONS: u32 = 0x1F03;

/// Library names that identify the platform, and its GetProcAddress.
const PLATFORMS: [(&str, &CStr); 4] = [
    ("libGLX.so", c"glXGetProcAddressARB"),
    ("libGL.so", c"glXGetProcAddressARB"),
    ("libEGL.so", c"eglGetProcAddress"),
    ("libOSMesa.so", c"OSMesaGetProcAddress"),
];

/// The platform library among those loaded: (path, GetProcAddress name).
struct Found(Option<(std::ffi::CString, &'static CStr)>);

unsafe extern "C" fn find_platform(
    info: *mut libc::dl_phdr_info,
    _size: libc::size_t,
    data: *mut c_void,
) -> libc::c_int {
    let found = &mut *(data as *mut Found);
    let name = (*info).dlpi_name;
    if name.is_null() {
        return 0;
    }
    let path = CStr::from_ptr(name);
    let bytes = path.to_bytes();
    let base = bytes.rsplit(|&c| c == b'/').next().unwrap_or(bytes);
    for (prefix, proc_name) in PLATFORMS {
        if base.starts_with(prefix.as_bytes()) {
            found.0 = Some((path.to_owned(), proc_name));
            return 1;
        }
    }
    0
}

/// The platform's GetProcAddress: EGL, OSMesa or GLX among the global symbols, else from the
/// platform library the process has loaded (privately).
fn proc_address() -> Result<GetProcAddress, String> {
    // SAFETY: dlopen/dlsym/dl_iterate_phdr with valid C strings; a symbol of these names has
    // the GetProcAddress signature.
    unsafe {
        let global = libc::dlopen(std::ptr::null(), libc::RTLD_NOW | libc::RTLD_GLOBAL);
        if !global.is_null() {
            for name in [
                c"eglGetProcAddress",
                c"OSMesaGetProcAddress",
                c"glXGetProcAddressARB",
            ] {
                let p = libc::dlsym(global, name.as_ptr());
                if !p.is_null() {
                    return Ok(std::mem::transmute::<*mut c_void, GetProcAddress>(p));
                }
            }
        }
        let mut found = Found(None);
        libc::dl_iterate_phdr(Some(find_platform), &mut found as *mut Found as *mut c_void);
        let Some((path, proc_name)) = found.0 else {
            return Err(
                "an OpenGL platform library has not been loaded into this process, this \
                        most likely means that a valid OpenGL context has not been created \
                        before mjr_makeContext was called"
                    .into(),
            );
        };
        let handle = libc::dlopen(path.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL);
        if handle.is_null() {
            return Err(format!("failed to dlopen {}", path.to_string_lossy()));
        }
        let p = libc::dlsym(handle, proc_name.as_ptr());
        if p.is_null() {
            return Err("gladLoadGL error".into());
        }
        Ok(std::mem::transmute::<*mut c_void, GetProcAddress>(p))
    }
}

/// A C string returned by GL, as text.
fn gl_string(p: *const u8) -> Option<String> {
    // SAFETY: GL returns NULL or a NUL-terminated static string.
    (!p.is_null()).then(|| {
        unsafe { CStr::from_ptr(p as *const c_char) }
            .to_string_lossy()
            .into_owned()
    })
}

/// "major.minor" at the start of the version string (after an OpenGL ES prefix).
fn parse_version(v: &str) -> (i32, i32) {
    let v = ["OpenGL ES-CM ", "OpenGL ES-CL ", "OpenGL ES "]
        .iter()
        .find_map(|p| v.strip_prefix(p))
        .unwrap_or(v);
    let mut parts = v.split('.');
    let num = |s: Option<&str>| {
        let s = s.unwrap_or("");
        let digits: String = s.chars().take_while(|c| c.is_ascii_digit()).collect();
        digits.parse().unwrap_or(0)
    };
    (num(parts.next()), num(parts.next()))
}

impl Gl {
    /// At least OpenGL 1.5?
    pub fn version_1_5(&self) -> bool {
        self.version.0 > 1 || (self.version.0 == 1 && self.version.1 >= 5)
    }

    /// Does the implementation list extension `name`?
    pub fn has_extension(&self, name: &str) -> bool {
        self.extensions.split(' ').any(|e| e == name)
    }
}

static GL: OnceLock<Option<Gl>> = OnceLock::new();
static ABSENT: Gl = Gl::ABSENT;

/// The loaded functions, or none at all before OpenGL was loaded: every GL call then panics
/// with `Missing` (where 2.2.2 calls through a NULL function pointer).
pub fn loaded_or_absent() -> &'static Gl {
    loaded().unwrap_or(&ABSENT)
}

/// The functions loaded by an earlier `load`, if it found a current context.
pub fn loaded() -> Option<&'static Gl> {
    GL.get().and_then(|g| g.as_ref())
}

/// The loaded functions, once per process as in 2.2.2: None when no context was current at
/// the first try (then every later context fails too).
pub fn load() -> Result<Option<&'static Gl>, String> {
    if let Some(gl) = GL.get() {
        return Ok(gl.as_ref());
    }
    let get = proc_address()?;
    // SAFETY: GetProcAddress takes a NUL-terminated name.
    let gl = Gl::load(|name| unsafe { get(name.as_ptr()) });
    let loaded = match gl.glGetString.map(|_| ()) {
        None => None,
        Some(()) => {
            let version = gl_string(gl.glGetString(GL_VERSION));
            version.map(|v| {
                let mut gl = gl;
                gl.version = parse_version(&v);
                gl.extensions = gl_string(gl.glGetString(GL_EXTENSIONS)).unwrap_or_default();
                gl
            })
        }
    };
    let loaded = loaded.filter(|gl| gl.version != (0, 0));
    Ok(GL.get_or_init(|| loaded).as_ref())
}

/// Safe forms of the pointer-taking calls: arrays of the size GL reads or writes.
impl Gl {
    pub fn vertex3fv(&self, v: &[f32; 3]) {
        // SAFETY: GL reads 3 floats.
        unsafe { self.glVertex3fv(v.as_ptr()) }
    }

    pub fn normal3fv(&self, v: &[f32; 3]) {
        // SAFETY: GL reads 3 floats.
        unsafe { self.glNormal3fv(v.as_ptr()) }
    }

    pub fn tex_coord2fv(&self, v: &[f32; 2]) {
        // SAFETY: GL reads 2 floats.
        unsafe { self.glTexCoord2fv(v.as_ptr()) }
    }

    pub fn color3fv(&self, v: &[f32; 3]) {
        // SAFETY: GL reads 3 floats.
        unsafe { self.glColor3fv(v.as_ptr()) }
    }

    pub fn color4fv(&self, v: &[f32; 4]) {
        // SAFETY: GL reads 4 floats.
        unsafe { self.glColor4fv(v.as_ptr()) }
    }

    pub fn fogfv(&self, pname: u32, v: &[f32; 4]) {
        // SAFETY: GL reads at most 4 floats.
        unsafe { self.glFogfv(pname, v.as_ptr()) }
    }

    pub fn tex_genfv(&self, coord: u32, pname: u32, v: &[f32; 4]) {
        // SAFETY: GL reads 4 floats.
        unsafe { self.glTexGenfv(coord, pname, v.as_ptr()) }
    }

    pub fn lightfv(&self, light: u32, pname: u32, v: &[f32; 4]) {
        // SAFETY: GL reads at most 4 floats.
        unsafe { self.glLightfv(light, pname, v.as_ptr()) }
    }

    pub fn materialfv(&self, face: u32, pname: u32, v: &[f32; 4]) {
        // SAFETY: GL reads at most 4 floats.
        unsafe { self.glMaterialfv(face, pname, v.as_ptr()) }
    }

    pub fn light_modelfv(&self, pname: u32, v: &[f32; 4]) {
        // SAFETY: GL reads at most 4 floats.
        unsafe { self.glLightModelfv(pname, v.as_ptr()) }
    }

    pub fn mult_matrixf(&self, m: &[f32; 16]) {
        // SAFETY: GL reads 16 floats.
        unsafe { self.glMultMatrixf(m.as_ptr()) }
    }

    pub fn load_matrixf(&self, m: &[f32; 16]) {
        // SAFETY: GL reads 16 floats.
        unsafe { self.glLoadMatrixf(m.as_ptr()) }
    }

    pub fn clip_plane(&self, plane: u32, eq: &[f64; 4]) {
        // SAFETY: GL reads 4 doubles.
        unsafe { self.glClipPlane(plane, eq.as_ptr()) }
    }

    pub fn get_integer(&self, pname: u32) -> i32 {
        // query values are 1 to 4 integers here; room for 16
        let mut v = [0i32; 16];
        // SAFETY: v holds more than any queried value.
        unsafe { self.glGetIntegerv(pname, v.as_mut_ptr()) };
        v[0]
    }

    pub fn get_integers<const N: usize>(&self, pname: u32) -> [i32; N] {
        let mut v = [0i32; 16];
        // SAFETY: as above.
        unsafe { self.glGetIntegerv(pname, v.as_mut_ptr()) };
        std::array::from_fn(|i| v[i])
    }

    pub fn get_floats<const N: usize>(&self, pname: u32) -> [f32; N] {
        let mut v = [0f32; 16];
        // SAFETY: room for any queried value.
        unsafe { self.glGetFloatv(pname, v.as_mut_ptr()) };
        std::array::from_fn(|i| v[i])
    }

    pub fn get_boolean(&self, pname: u32) -> u8 {
        let mut v = [0u8; 16];
        // SAFETY: as above.
        unsafe { self.glGetBooleanv(pname, v.as_mut_ptr()) };
        v[0]
    }

    pub fn get_renderbuffer_parameter(&self, target: u32, pname: u32) -> i32 {
        let mut v = 0;
        // SAFETY: one integer.
        unsafe { self.glGetRenderbufferParameteriv(target, pname, &mut v) };
        v
    }

    /// One new name from a glGen* function.
    pub fn gen_framebuffer(&self) -> u32 {
        let mut id = 0;
        // SAFETY: one name.
        unsafe { self.glGenFramebuffers(1, &mut id) };
        id
    }

    pub fn gen_renderbuffer(&self) -> u32 {
        let mut id = 0;
        // SAFETY: one name.
        unsafe { self.glGenRenderbuffers(1, &mut id) };
        id
    }

    pub fn gen_textures(&self, ids: &mut [u32]) {
        // SAFETY: GL writes ids.len() names.
        unsafe { self.glGenTextures(ids.len() as i32, ids.as_mut_ptr()) }
    }

    pub fn gen_buffers(&self, ids: &mut [u32]) {
        // SAFETY: GL writes ids.len() names.
        unsafe { self.glGenBuffers(ids.len() as i32, ids.as_mut_ptr()) }
    }

    pub fn delete_textures(&self, ids: &[u32]) {
        // SAFETY: GL reads ids.len() names.
        unsafe { self.glDeleteTextures(ids.len() as i32, ids.as_ptr()) }
    }

    pub fn delete_buffers(&self, ids: &[u32]) {
        // SAFETY: GL reads ids.len() names.
        unsafe { self.glDeleteBuffers(ids.len() as i32, ids.as_ptr()) }
    }

    pub fn delete_renderbuffer(&self, id: u32) {
        // SAFETY: one name.
        unsafe { self.glDeleteRenderbuffers(1, &id) }
    }

    pub fn delete_framebuffer(&self, id: u32) {
        // SAFETY: one name.
        unsafe { self.glDeleteFramebuffers(1, &id) }
    }

    /// glTexImage2D of RGB bytes (`data` holds width*height*3) or no data.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_2d(
        &self,
        target: u32,
        internal: i32,
        width: i32,
        height: i32,
        format: u32,
        kind: u32,
        data: Option<&[u8]>,
    ) {
        if let Some(d) = data {
            assert!(d.len() >= (width.max(0) as usize) * (height.max(0) as usize) * 3);
        }
        let p = data.map_or(std::ptr::null(), |d| d.as_ptr() as *const c_void);
        // SAFETY: NULL or enough bytes for the image (checked above).
        unsafe { self.glTexImage2D(target, 0, internal, width, height, 0, format, kind, p) }
    }

    /// glBitmap of rows of `(width+7)/8` bytes.
    pub fn bitmap(&self, width: i32, height: i32, xmove: f32, bits: &[u8]) {
        let row = (width.max(0) as usize).div_ceil(8);
        assert!(bits.len() >= row * height.max(0) as usize);
        // SAFETY: the bitmap's rows are in `bits` (unpack alignment 1).
        unsafe { self.glBitmap(width, height, 0.0, 0.0, xmove, 0.0, bits.as_ptr()) }
    }

    pub fn buffer_data<T: Copy>(&self, target: u32, data: &[T], usage: u32) {
        let size = std::mem::size_of_val(data) as isize;
        // SAFETY: GL copies `size` bytes from data.
        unsafe { self.glBufferData(target, size, data.as_ptr() as *const c_void, usage) }
    }
}

/// The GL enums the renderer uses.
pub mod consts {
    pub const GL_ALPHA_TEST: u32 = 0x0BC0;
    pub const GL_ALWAYS: u32 = 0x0207;
    pub const GL_AMBIENT: u32 = 0x1200;
    pub const GL_AMBIENT_AND_DIFFUSE: u32 = 0x1602;
    pub const GL_ARRAY_BUFFER: u32 = 0x8892;
    pub const GL_BACK: u32 = 0x0405;
    pub const GL_BACK_LEFT: u32 = 0x0402;
    pub const GL_BACK_RIGHT: u32 = 0x0403;
    pub const GL_BLEND: u32 = 0x0BE2;
    pub const GL_CCW: u32 = 0x0901;
    pub const GL_CLAMP_TO_EDGE: u32 = 0x812F;
    pub const GL_CLIP_PLANE0: u32 = 0x3000;
    pub const GL_COLOR_ATTACHMENT0: u32 = 0x8CE0;
    pub const GL_COLOR_BUFFER_BIT: u32 = 0x00004000;
    pub const GL_COLOR_MATERIAL: u32 = 0x0B57;
    pub const GL_COMPARE_R_TO_TEXTURE: u32 = 0x884E;
    pub const GL_COMPILE: u32 = 0x1300;
    pub const GL_CONSTANT_ATTENUATION: u32 = 0x1207;
    pub const GL_CULL_FACE: u32 = 0x0B44;
    pub const GL_CULL_FACE_MODE: u32 = 0x0B45;
    pub const GL_CW: u32 = 0x0900;
    pub const GL_DEBUG_OUTPUT: u32 = 0x92E0;
    pub const GL_DEPTH24_STENCIL8: u32 = 0x88F0;
    pub const GL_DEPTH_ATTACHMENT: u32 = 0x8D00;
    pub const GL_DEPTH_BUFFER_BIT: u32 = 0x00000100;
    pub const GL_DEPTH_COMPONENT: u32 = 0x1902;
    pub const GL_DEPTH_STENCIL_ATTACHMENT: u32 = 0x821A;
    pub const GL_DEPTH_TEST: u32 = 0x0B71;
    pub const GL_DEPTH_TEXTURE_MODE: u32 = 0x884B;
    pub const GL_DIFFUSE: u32 = 0x1201;
    pub const GL_DOUBLEBUFFER: u32 = 0x0C32;
    pub const GL_DRAW_FRAMEBUFFER: u32 = 0x8CA9;
    pub const GL_ELEMENT_ARRAY_BUFFER: u32 = 0x8893;
    pub const GL_EMISSION: u32 = 0x1600;
    pub const GL_EQUAL: u32 = 0x0202;
    pub const GL_EYE_LINEAR: u32 = 0x2400;
    pub const GL_EYE_PLANE: u32 = 0x2502;
    pub const GL_FALSE: u32 = 0;
    pub const GL_FILL: u32 = 0x1B02;
    pub const GL_FLAT: u32 = 0x1D00;
    pub const GL_FLOAT: u32 = 0x1406;
    pub const GL_FOG: u32 = 0x0B60;
    pub const GL_FOG_COLOR: u32 = 0x0B66;
    pub const GL_FOG_COORD_SRC: u32 = 0x8450;
    pub const GL_FOG_END: u32 = 0x0B64;
    pub const GL_FOG_HINT: u32 = 0x0C54;
    pub const GL_FOG_MODE: u32 = 0x0B65;
    pub const GL_FOG_START: u32 = 0x0B63;
    pub const GL_FRAGMENT_DEPTH: u32 = 0x8452;
    pub const GL_FRAMEBUFFER: u32 = 0x8D40;
    pub const GL_FRAMEBUFFER_COMPLETE: u32 = 0x8CD5;
    pub const GL_FRAMEBUFFER_UNDEFINED: u32 = 0x8219;
    pub const GL_FRONT: u32 = 0x0404;
    pub const GL_FRONT_AND_BACK: u32 = 0x0408;
    pub const GL_FRONT_LEFT: u32 = 0x0400;
    pub const GL_FRONT_RIGHT: u32 = 0x0401;
    pub const GL_GEQUAL: u32 = 0x0206;
    pub const GL_INTENSITY: u32 = 0x8049;
    pub const GL_KEEP: u32 = 0x1E00;
    pub const GL_LEQUAL: u32 = 0x0203;
    pub const GL_LIGHT0: u32 = 0x4000;
    pub const GL_LIGHTING: u32 = 0x0B50;
    pub const GL_LIGHT_MODEL_AMBIENT: u32 = 0x0B53;
    pub const GL_LIGHT_MODEL_LOCAL_VIEWER: u32 = 0x0B51;
    pub const GL_LIGHT_MODEL_TWO_SIDE: u32 = 0x0B52;
    pub const GL_LINE: u32 = 0x1B01;
    pub const GL_LINEAR: u32 = 0x2601;
    pub const GL_LINEAR_ATTENUATION: u32 = 0x1208;
    pub const GL_LINEAR_MIPMAP_LINEAR: u32 = 0x2703;
    pub const GL_LINES: u32 = 0x0001;
    pub const GL_LINE_STRIP: u32 = 0x0003;
    pub const GL_MAX_CUBE_MAP_TEXTURE_SIZE: u32 = 0x851C;
    pub const GL_MAX_RENDERBUFFER_SIZE: u32 = 0x84E8;
    pub const GL_MAX_SAMPLES: u32 = 0x8D57;
    pub const GL_MAX_TEXTURE_SIZE: u32 = 0x0D33;
    pub const GL_MODELVIEW: u32 = 0x1700;
    pub const GL_MODELVIEW_MATRIX: u32 = 0x0BA6;
    pub const GL_MODULATE: u32 = 0x2100;
    pub const GL_MULTISAMPLE: u32 = 0x809D;
    pub const GL_NEAREST: u32 = 0x2600;
    pub const GL_NICEST: u32 = 0x1102;
    pub const GL_NONE: u32 = 0;
    pub const GL_NORMALIZE: u32 = 0x0BA1;
    pub const GL_NORMAL_ARRAY: u32 = 0x8075;
    pub const GL_OBJECT_LINEAR: u32 = 0x2401;
    pub const GL_OBJECT_PLANE: u32 = 0x2501;
    pub const GL_ONE: u32 = 1;
    pub const GL_ONE_MINUS_SRC_ALPHA: u32 = 0x0303;
    pub const GL_PACK_ALIGNMENT: u32 = 0x0D05;
    pub const GL_POLYGON: u32 = 0x0009;
    pub const GL_POSITION: u32 = 0x1203;
    pub const GL_PROJECTION: u32 = 0x1701;
    pub const GL_PROJECTION_MATRIX: u32 = 0x0BA7;
    pub const GL_Q: u32 = 0x2003;
    pub const GL_QUADRATIC_ATTENUATION: u32 = 0x1209;
    pub const GL_QUADS: u32 = 0x0007;
    pub const GL_R: u32 = 0x2002;
    pub const GL_READ_FRAMEBUFFER: u32 = 0x8CA8;
    pub const GL_RENDERBUFFER: u32 = 0x8D41;
    pub const GL_RENDERBUFFER_SAMPLES: u32 = 0x8CAB;
    pub const GL_REPEAT: u32 = 0x2901;
    pub const GL_REPLACE: u32 = 0x1E01;
    pub const GL_RGB: u32 = 0x1907;
    pub const GL_RGBA8: u32 = 0x8058;
    pub const GL_S: u32 = 0x2000;
    pub const GL_SAMPLES: u32 = 0x80A9;
    pub const GL_SAMPLE_BUFFERS: u32 = 0x80A8;
    pub const GL_SCISSOR_BOX: u32 = 0x0C10;
    pub const GL_SCISSOR_TEST: u32 = 0x0C11;
    pub const GL_SHININESS: u32 = 0x1601;
    pub const GL_SMOOTH: u32 = 0x1D01;
    pub const GL_SPECULAR: u32 = 0x1202;
    pub const GL_SPOT_CUTOFF: u32 = 0x1206;
    pub const GL_SPOT_DIRECTION: u32 = 0x1204;
    pub const GL_SPOT_EXPONENT: u32 = 0x1205;
    pub const GL_SRC_ALPHA: u32 = 0x0302;
    pub const GL_STATIC_DRAW: u32 = 0x88E4;
    pub const GL_STENCIL_BUFFER_BIT: u32 = 0x00000400;
    pub const GL_STENCIL_TEST: u32 = 0x0B90;
    pub const GL_STEREO: u32 = 0x0C33;
    pub const GL_STREAM_DRAW: u32 = 0x88E0;
    pub const GL_T: u32 = 0x2001;
    pub const GL_TEXTURE0: u32 = 0x84C0;
    pub const GL_TEXTURE1: u32 = 0x84C1;
    pub const GL_TEXTURE_2D: u32 = 0x0DE1;
    pub const GL_TEXTURE_COMPARE_FUNC: u32 = 0x884D;
    pub const GL_TEXTURE_COMPARE_MODE: u32 = 0x884C;
    pub const GL_TEXTURE_COORD_ARRAY: u32 = 0x8078;
    pub const GL_TEXTURE_CUBE_MAP: u32 = 0x8513;
    pub const GL_TEXTURE_CUBE_MAP_POSITIVE_X: u32 = 0x8515;
    pub const GL_TEXTURE_CUBE_MAP_SEAMLESS: u32 = 0x884F;
    pub const GL_TEXTURE_ENV: u32 = 0x2300;
    pub const GL_TEXTURE_ENV_MODE: u32 = 0x2200;
    pub const GL_TEXTURE_GEN_MODE: u32 = 0x2500;
    pub const GL_TEXTURE_GEN_Q: u32 = 0x0C63;
    pub const GL_TEXTURE_GEN_R: u32 = 0x0C62;
    pub const GL_TEXTURE_GEN_S: u32 = 0x0C60;
    pub const GL_TEXTURE_GEN_T: u32 = 0x0C61;
    pub const GL_TEXTURE_MAG_FILTER: u32 = 0x2800;
    pub const GL_TEXTURE_MIN_FILTER: u32 = 0x2801;
    pub const GL_TEXTURE_WRAP_R: u32 = 0x8072;
    pub const GL_TEXTURE_WRAP_S: u32 = 0x2802;
    pub const GL_TEXTURE_WRAP_T: u32 = 0x2803;
    pub const GL_TRIANGLES: u32 = 0x0004;
    pub const GL_TRUE: u32 = 1;
    pub const GL_UNPACK_ALIGNMENT: u32 = 0x0CF5;
    pub const GL_UNSIGNED_BYTE: u32 = 0x1401;
    pub const GL_UNSIGNED_INT: u32 = 0x1405;
    pub const GL_VERTEX_ARRAY: u32 = 0x8074;
}

impl Gl {
    /// glCallLists of one byte per list offset (text through font lists).
    pub fn call_lists_bytes(&self, text: &[u8]) {
        // SAFETY: GL reads text.len() bytes.
        unsafe {
            self.glCallLists(
                text.len() as i32,
                consts::GL_UNSIGNED_BYTE,
                text.as_ptr().cast(),
            )
        }
    }
}
