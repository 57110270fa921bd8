//! The GL and EGL entry points the benchmark calls, resolved at run time with `dlopen` and
//! `dlsym`, so one binary drives our library and Mesa's through the same C API.

use std::ffi::{c_void, CStr, CString};
use std::ptr::null_mut;

use GLES_CM::egl::tokens::*;

use GLES_CM::egl::types::{
    EGLBoolean, EGLConfig, EGLContext, EGLDisplay, EGLNativeDisplayType, EGLSurface, EGLenum,
    EGLint,
};
use GLES_CM::gles::types::{
    GLbitfield, GLclampf, GLenum, GLfloat, GLint, GLsizei, GLsizeiptr, GLubyte, GLuint, GLvoid,
};

/// A library opened with `dlopen`; closed again on drop.
pub struct Library {
    handle: *mut c_void,
    name: String,
}

impl Library {
    /// Opens `path` (a file path or a soname) with `RTLD_NOW | RTLD_LOCAL`.
    pub fn open(path: &str) -> Result<Library, String> {
        let c = CString::new(path).map_err(|_| format!("bad library path {path:?}"))?;
        // SAFETY: `c` is a valid NUL-terminated string; dlopen has no other preconditions.
        // Running the library's initializers is the point of loading it.
        let handle = unsafe { libc::dlopen(c.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL) };
        if handle.is_null() {
            return Err(format!("dlopen {path}: {}", dl_error()));
        }
        Ok(Library {
            handle,
            name: path.to_owned(),
        })
    }

    /// The address of `symbol`, or an error naming it.
    pub fn symbol(&self, symbol: &str) -> Result<*mut c_void, String> {
        let c = CString::new(symbol).map_err(|_| format!("bad symbol {symbol:?}"))?;
        // SAFETY: `self.handle` came from a successful dlopen and stays open while `self`
        // lives; `c` is NUL-terminated.
        let p = unsafe { libc::dlsym(self.handle, c.as_ptr()) };
        if p.is_null() {
            Err(format!("{symbol} not found in {}", self.name))
        } else {
            Ok(p)
        }
    }
}

impl Drop for Library {
    fn drop(&mut self) {
        // SAFETY: the handle is from dlopen and is closed once. Nothing resolved from it is
        // used after the `Api` holding this library is dropped (the `Api` owns both).
        unsafe {
            libc::dlclose(self.handle);
        }
    }
}

fn dl_error() -> String {
    // SAFETY: dlerror returns NULL or a NUL-terminated string valid until the next dl* call
    // on this thread; it is copied at once.
    unsafe {
        let e = libc::dlerror();
        if e.is_null() {
            "unknown error".to_owned()
        } else {
            CStr::from_ptr(e).to_string_lossy().into_owned()
        }
    }
}

macro_rules! api {
    ($( $name:ident : fn($($arg:ty),*) $(-> $ret:ty)?; )*) => {
        /// The entry points, as C function pointers. Calling any of them is `unsafe`: the
        /// caller keeps the GL/EGL contracts (valid pointers, a current context for `gl*`).
        // `bench` and `accuracy` share this file and each calls a subset.
        #[allow(non_snake_case, dead_code)]
        pub struct Api {
            $( pub $name: unsafe extern "C" fn($($arg),*) $(-> $ret)?, )*
            // Declared last so it is dropped after the pointers (which are plain values).
            _libs: Vec<Library>,
        }

        impl Api {
            /// Resolves every entry point from the first of `libs` that has it.
            #[allow(non_snake_case)]
            pub fn load(libs: Vec<Library>) -> Result<Api, String> {
                let find = |name: &str| -> Result<*mut c_void, String> {
                    let mut last = String::new();
                    for lib in &libs {
                        match lib.symbol(name) {
                            Ok(p) => return Ok(p),
                            Err(e) => last = e,
                        }
                    }
                    Err(last)
                };
                $(
                    let p = find(stringify!($name))?;
                    // SAFETY: `p` is the non-null address of the C function of this name,
                    // whose prototype in the Khronos headers is the signature declared
                    // here; fn pointers and data pointers have one size on the platforms
                    // dlsym serves.
                    let $name = unsafe {
                        std::mem::transmute::<*mut c_void, unsafe extern "C" fn($($arg),*) $(-> $ret)?>(p)
                    };
                )*
                Ok(Api { $( $name, )* _libs: libs })
            }
        }
    };
}

api! {
    eglGetDisplay: fn(EGLNativeDisplayType) -> EGLDisplay;
    eglInitialize: fn(EGLDisplay, *mut EGLint, *mut EGLint) -> EGLBoolean;
    eglBindAPI: fn(EGLenum) -> EGLBoolean;
    eglChooseConfig: fn(EGLDisplay, *const EGLint, *mut EGLConfig, EGLint, *mut EGLint) -> EGLBoolean;
    eglGetConfigAttrib: fn(EGLDisplay, EGLConfig, EGLint, *mut EGLint) -> EGLBoolean;
    eglCreatePbufferSurface: fn(EGLDisplay, EGLConfig, *const EGLint) -> EGLSurface;
    eglCreateContext: fn(EGLDisplay, EGLConfig, EGLContext, *const EGLint) -> EGLContext;
    eglMakeCurrent: fn(EGLDisplay, EGLSurface, EGLSurface, EGLContext) -> EGLBoolean;
    eglDestroySurface: fn(EGLDisplay, EGLSurface) -> EGLBoolean;
    eglDestroyContext: fn(EGLDisplay, EGLContext) -> EGLBoolean;
    eglGetError: fn() -> EGLint;
    eglGetProcAddress: fn(*const std::ffi::c_char) -> *mut c_void;
    glGetString: fn(GLenum) -> *const GLubyte;
    glGetError: fn() -> GLenum;
    glViewport: fn(GLint, GLint, GLsizei, GLsizei);
    glClearColor: fn(GLclampf, GLclampf, GLclampf, GLclampf);
    glClearDepthf: fn(GLclampf);
    glClear: fn(GLbitfield);
    glEnable: fn(GLenum);
    glDisable: fn(GLenum);
    glDepthFunc: fn(GLenum);
    glBlendFunc: fn(GLenum, GLenum);
    glHint: fn(GLenum, GLenum);
    glMatrixMode: fn(GLenum);
    glLoadMatrixf: fn(*const GLfloat);
    glEnableClientState: fn(GLenum);
    glVertexPointer: fn(GLint, GLenum, GLsizei, *const GLvoid);
    glColorPointer: fn(GLint, GLenum, GLsizei, *const GLvoid);
    glDrawArrays: fn(GLenum, GLint, GLsizei);
    glPointSize: fn(GLfloat);
    glLineWidth: fn(GLfloat);
    glPixelStorei: fn(GLenum, GLint);
    glFinish: fn();
    glReadPixels: fn(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, *mut GLvoid);
    glShadeModel: fn(GLenum);
    glColor4f: fn(GLfloat, GLfloat, GLfloat, GLfloat);
    glLoadIdentity: fn();
    glDisableClientState: fn(GLenum);
    glNormalPointer: fn(GLenum, GLsizei, *const GLvoid);
    glTexCoordPointer: fn(GLint, GLenum, GLsizei, *const GLvoid);
    glClientActiveTexture: fn(GLenum);
    glActiveTexture: fn(GLenum);
    glBindTexture: fn(GLenum, GLuint);
    glTexImage2D: fn(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, *const GLvoid);
    glTexParameteri: fn(GLenum, GLenum, GLint);
    glTexEnvi: fn(GLenum, GLenum, GLint);
    glTexEnvf: fn(GLenum, GLenum, GLfloat);
    glTexEnvfv: fn(GLenum, GLenum, *const GLfloat);
    glLightfv: fn(GLenum, GLenum, *const GLfloat);
    glLightModelfv: fn(GLenum, *const GLfloat);
    glMaterialfv: fn(GLenum, GLenum, *const GLfloat);
    glMaterialf: fn(GLenum, GLenum, GLfloat);
    glFogf: fn(GLenum, GLfloat);
    glFogfv: fn(GLenum, *const GLfloat);
    glGenBuffers: fn(GLsizei, *mut GLuint);
    glBindBuffer: fn(GLenum, GLuint);
    glBufferData: fn(GLenum, GLsizeiptr, *const GLvoid, GLenum);
    glDrawElements: fn(GLenum, GLsizei, GLenum, *const GLvoid);
    glFrontFace: fn(GLenum);
    glTexParameteriv: fn(GLenum, GLenum, *const GLint);
}

/// An initialized display with a `width` × `height` pbuffer (RGBA8888 + depth 24, or
/// RGB565 + depth 16) and a current ES 1.x context.
pub struct Egl {
    display: *mut std::ffi::c_void,
    surface: *mut std::ffi::c_void,
    context: *mut std::ffi::c_void,
}

impl Egl {
    // `accuracy` calls this, `bench` the general form.
    #[allow(dead_code)]
    pub fn new(gl: &Api, width: u32, height: u32) -> Result<Egl, String> {
        Egl::with_config(gl, width, height, false, 0)
    }

    /// [`Egl::new`] with an RGB565 + depth 16 pbuffer when `rgb565`, and exactly `samples`
    /// samples per pixel (0: single-sample).
    pub fn with_config(
        gl: &Api,
        width: u32,
        height: u32,
        rgb565: bool,
        samples: EGLint,
    ) -> Result<Egl, String> {
        let (rgba, depth): ([EGLint; 4], EGLint) = if rgb565 {
            ([5, 6, 5, 0], 16)
        } else {
            ([8, 8, 8, 8], 24)
        };
        // SAFETY: every pointer passed is valid for the call: attribute lists end in
        // EGL_NONE, `configs` has room for the `configs.len()` entries announced, the out
        // parameters point at live locals. Handles come from the same display.
        unsafe {
            let dpy = (gl.eglGetDisplay)(EGL_DEFAULT_DISPLAY);
            if dpy.is_null() {
                return Err(format!("eglGetDisplay: 0x{:04X}", (gl.eglGetError)()));
            }
            let (mut major, mut minor) = (0, 0);
            if (gl.eglInitialize)(dpy, &mut major, &mut minor) == 0 {
                return Err(format!("eglInitialize: 0x{:04X}", (gl.eglGetError)()));
            }
            (gl.eglBindAPI)(EGL_OPENGL_ES_API);
            let attribs = [
                EGL_SURFACE_TYPE,
                EGL_PBUFFER_BIT,
                EGL_RENDERABLE_TYPE,
                EGL_OPENGL_ES_BIT,
                EGL_RED_SIZE,
                rgba[0],
                EGL_GREEN_SIZE,
                rgba[1],
                EGL_BLUE_SIZE,
                rgba[2],
                EGL_ALPHA_SIZE,
                rgba[3],
                EGL_DEPTH_SIZE,
                depth,
                EGL_SAMPLE_BUFFERS,
                (samples > 0) as EGLint,
                EGL_SAMPLES,
                samples,
                EGL_NONE,
            ];
            let mut configs: Vec<EGLConfig> = vec![null_mut(); 256];
            let mut n: EGLint = 0;
            if (gl.eglChooseConfig)(
                dpy,
                attribs.as_ptr(),
                configs.as_mut_ptr(),
                configs.len() as EGLint,
                &mut n,
            ) == 0
            {
                return Err(format!("eglChooseConfig: 0x{:04X}", (gl.eglGetError)()));
            }
            // EGL sorts deeper color first (10-bit configs on Mesa): keep exact sizes, and
            // of those the one with the least stencil.
            let attr = |c: EGLConfig, a: EGLint| {
                let mut v = -1;
                (gl.eglGetConfigAttrib)(dpy, c, a, &mut v);
                v
            };
            let config = configs[..n.max(0) as usize]
                .iter()
                .copied()
                .filter(|&c| {
                    [EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE]
                        .iter()
                        .zip(rgba)
                        .all(|(&a, bits)| attr(c, a) == bits)
                        && attr(c, EGL_DEPTH_SIZE) == depth
                        && attr(c, EGL_SAMPLES) == samples
                })
                .min_by_key(|&c| attr(c, EGL_STENCIL_SIZE))
                .ok_or_else(|| format!("no pbuffer config of color {rgba:?} and depth {depth}"))?;
            let size = [
                EGL_WIDTH,
                width as EGLint,
                EGL_HEIGHT,
                height as EGLint,
                EGL_NONE,
            ];
            let surface = (gl.eglCreatePbufferSurface)(dpy, config, size.as_ptr());
            if surface.is_null() {
                return Err(format!(
                    "eglCreatePbufferSurface: 0x{:04X}",
                    (gl.eglGetError)()
                ));
            }
            let ctx_attribs = [EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE];
            let context = (gl.eglCreateContext)(dpy, config, EGL_NO_CONTEXT, ctx_attribs.as_ptr());
            if context.is_null() {
                return Err(format!("eglCreateContext: 0x{:04X}", (gl.eglGetError)()));
            }
            if (gl.eglMakeCurrent)(dpy, surface, surface, context) == 0 {
                return Err(format!("eglMakeCurrent: 0x{:04X}", (gl.eglGetError)()));
            }
            Ok(Egl {
                display: dpy,
                surface,
                context,
            })
        }
    }

    /// Releases the context and surface. The display is left initialized: terminating it
    /// as the process exits gains nothing.
    pub fn destroy(self, gl: &Api) {
        // SAFETY: the handles were created on this display and are released once.
        unsafe {
            (gl.eglMakeCurrent)(self.display, null_mut(), null_mut(), EGL_NO_CONTEXT);
            (gl.eglDestroyContext)(self.display, self.context);
            (gl.eglDestroySurface)(self.display, self.surface);
        }
    }
}
