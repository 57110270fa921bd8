//! The `extern "C"` `egl*` entry points: thin shims that catch panics, turn handles into
//! integer ids (looked up in the display's tables, never dereferenced), read attribute lists
//! and client memory through checked pointers, call a safe operation of [`super::display`]
//! and record the thread's error (ARCHITECTURE decision 8).

use std::ffi::{c_char, c_void, CStr};

use super::display::{self as d, EglResult};
use super::native::{EGLMemoryPixmap, EGLMemoryWindow};
use super::surface::{Kind, MemoryLayout, NativeMemory};
use super::thread;
use super::tokens::*;
use super::types::*;

/// Runs `f`, records its error (EGL_SUCCESS when it succeeds) and returns its value, or
/// `fail` on error. A panic is caught here, never crossing into C, and reported as
/// EGL_BAD_ALLOC.
fn call<R>(fail: R, f: impl FnOnce() -> EglResult<R>) -> R {
    match crate::boundary::catch(f) {
        Some(Ok(r)) => {
            thread::set_error(EGL_SUCCESS);
            r
        }
        Some(Err(e)) => {
            thread::set_error(e);
            fail
        }
        None => {
            thread::set_error(EGL_BAD_ALLOC);
            fail
        }
    }
}

/// [`call`] for functions returning EGLBoolean.
fn call_bool(f: impl FnOnce() -> EglResult<()>) -> EGLBoolean {
    call(EGL_FALSE, || f().map(|()| EGL_TRUE))
}

/// A handle's id. Handles are integers cast to pointers; nothing is ever read through them.
fn id(handle: *mut c_void) -> usize {
    handle as usize
}

/// The handle of an id (0 is the null handle).
fn handle(id: usize) -> *mut c_void {
    id as *mut c_void
}

/// Reads an EGL_NONE-terminated attribute list into pairs (null is the empty list).
///
/// # Safety
/// A non-null `list` must point to attribute/value pairs ending with EGL_NONE.
unsafe fn attrib_pairs(list: *const EGLint) -> Vec<(EGLint, EGLint)> {
    // SAFETY: forwarded to the caller's contract.
    unsafe { pairs_until(list, EGL_NONE) }
}

/// [`attrib_pairs`] for EGL 1.5's pointer-wide `EGLAttrib` lists.
///
/// # Safety
/// As [`attrib_pairs`].
unsafe fn attrib_pairs_wide(list: *const EGLAttrib) -> Vec<(EGLAttrib, EGLAttrib)> {
    // SAFETY: forwarded to the caller's contract.
    unsafe { pairs_until(list, EGL_NONE as EGLAttrib) }
}

/// # Safety
/// A non-null `list` must point to attribute/value pairs ending with `none`.
unsafe fn pairs_until<T: Copy + PartialEq>(list: *const T, none: T) -> Vec<(T, T)> {
    let mut pairs = Vec::new();
    if list.is_null() {
        return pairs;
    }
    let mut i = 0;
    loop {
        // SAFETY: by the caller's contract the list is readable up to its terminator, and we
        // stop there.
        let attr = unsafe { list.add(i).read_unaligned() };
        if attr == none {
            return pairs;
        }
        // SAFETY: an attribute that is not the terminator is followed by its value.
        let value = unsafe { list.add(i + 1).read_unaligned() };
        pairs.push((attr, value));
        i += 2;
    }
}

/// EGLAttrib pairs as EGLint ones, for the surface attributes (all of which are EGLint
/// values); a value out of that range is EGL_BAD_ATTRIBUTE.
fn narrow(pairs: &[(EGLAttrib, EGLAttrib)]) -> EglResult<Vec<(EGLint, EGLint)>> {
    pairs
        .iter()
        .map(|&(a, v)| {
            Ok((
                EGLint::try_from(a).map_err(|_| EGL_BAD_ATTRIBUTE)?,
                EGLint::try_from(v).map_err(|_| EGL_BAD_ATTRIBUTE)?,
            ))
        })
        .collect()
}

/// Writes `v` to an optional output argument.
///
/// # Safety
/// A non-null `p` must be writable.
unsafe fn put<T>(p: *mut T, v: T) {
    if !p.is_null() {
        // SAFETY: non-null, and writable by the caller's contract.
        unsafe { p.write_unaligned(v) };
    }
}

/// Client memory described by an `EGLMemoryPixmap` or `EGLMemoryWindow`.
struct ClientMemory {
    layout: MemoryLayout,
    pixels: *mut u8,
}

// SAFETY: the application guarantees (native.rs) that the pixels stay valid while a surface
// uses them; EGL only touches them inside `with_bytes`, from whichever thread renders.
unsafe impl Send for ClientMemory {}
// SAFETY: as above; concurrent access is serialized by the surface's target lock.
unsafe impl Sync for ClientMemory {}

impl NativeMemory for ClientMemory {
    fn layout(&self) -> MemoryLayout {
        self.layout
    }

    fn with_bytes(&self, f: &mut dyn FnMut(&mut [u8])) {
        let Some(len) = self.layout.byte_len() else {
            return;
        };
        // SAFETY: `pixels` is non-null and, by the application's contract for native pixmaps
        // and windows, spans `stride * (height - 1) + width * bpp` bytes (validated layout).
        let bytes = unsafe { std::slice::from_raw_parts_mut(self.pixels, len) };
        f(bytes)
    }
}

/// Reads a memory pixmap or window: `None` for a null pointer or null pixels (a layout with
/// bad values is returned and rejected by the caller).
///
/// # Safety
/// A non-null `p` must point to a readable `EGLMemoryPixmap`-shaped struct.
unsafe fn client_memory(p: *const EGLMemoryPixmap) -> Option<Box<dyn NativeMemory>> {
    if p.is_null() {
        return None;
    }
    // SAFETY: non-null and readable by the caller's contract.
    let m = unsafe { p.read_unaligned() };
    if m.pixels.is_null() {
        return None;
    }
    let layout = MemoryLayout {
        width: m.width,
        height: m.height,
        stride: m.stride,
        format: m.format,
    };
    if !layout.is_valid() {
        return None;
    }
    Some(Box::new(ClientMemory {
        layout,
        pixels: m.pixels as *mut u8,
    }))
}

/// The window struct has the pixmap's layout.
fn window_as_pixmap(w: EGLNativeWindowType) -> *const EGLMemoryPixmap {
    const _: () =
        assert!(std::mem::size_of::<EGLMemoryWindow>() == std::mem::size_of::<EGLMemoryPixmap>());
    w as *const EGLMemoryPixmap
}

#[no_mangle]
pub extern "C" fn eglGetError() -> EGLint {
    crate::boundary::catch(thread::take_error).unwrap_or(EGL_BAD_ALLOC)
}

#[no_mangle]
pub extern "C" fn eglGetDisplay(display_id: EGLNativeDisplayType) -> EGLDisplay {
    call(EGL_NO_DISPLAY, || {
        Ok(handle(d::get_display(display_id as usize)))
    })
}

/// EGL_EXT_platform_base, for EGL_MESA_platform_surfaceless only.
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplayEXT(
    platform: EGLenum,
    native_display: *mut c_void,
    attrib_list: *const EGLint,
) -> EGLDisplay {
    call(EGL_NO_DISPLAY, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        d::get_platform_display(platform, native_display as usize, &pairs).map(handle)
    })
}

/// EGL_EXT_platform_base: the native window is a `struct EGLMemoryWindow`, as for
/// eglCreateWindowSurface.
///
/// # Safety
/// As eglCreateWindowSurface's, with `native_window` for `win`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePlatformWindowSurfaceEXT(
    dpy: EGLDisplay,
    config: EGLConfig,
    native_window: *mut c_void,
    attrib_list: *const EGLint,
) -> EGLSurface {
    // SAFETY: forwarded to the caller's contract.
    unsafe { eglCreateWindowSurface(dpy, config, native_window.cast(), attrib_list) }
}

/// EGL_EXT_platform_base: the native pixmap is a `struct EGLMemoryPixmap`, as for
/// eglCreatePixmapSurface.
///
/// # Safety
/// As eglCreatePixmapSurface's, with `native_pixmap` for `pixmap`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePlatformPixmapSurfaceEXT(
    dpy: EGLDisplay,
    config: EGLConfig,
    native_pixmap: *mut c_void,
    attrib_list: *const EGLint,
) -> EGLSurface {
    // SAFETY: forwarded to the caller's contract.
    unsafe { eglCreatePixmapSurface(dpy, config, native_pixmap.cast(), attrib_list) }
}

/// # Safety
/// `major` and `minor` are null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglInitialize(
    dpy: EGLDisplay,
    major: *mut EGLint,
    minor: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        let (ma, mi) = d::initialize(id(dpy))?;
        // SAFETY: forwarded to the caller's contract.
        unsafe {
            put(major, ma);
            put(minor, mi);
        }
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn eglTerminate(dpy: EGLDisplay) -> EGLBoolean {
    call_bool(|| d::terminate(id(dpy)))
}

#[no_mangle]
pub extern "C" fn eglQueryString(dpy: EGLDisplay, name: EGLint) -> *const c_char {
    call(std::ptr::null(), || {
        d::query_string(id(dpy), name).map(CStr::as_ptr)
    })
}

/// Writes config handles to `configs` (at most `config_size`) and their count to
/// `num_config`; with null `configs`, only the count of all of them.
///
/// # Safety
/// `configs` is null or has room for `config_size` handles; `num_config` is null or writable.
unsafe fn return_configs(
    list: Vec<usize>,
    configs: *mut EGLConfig,
    config_size: EGLint,
    num_config: *mut EGLint,
) -> EglResult<()> {
    if num_config.is_null() {
        return Err(EGL_BAD_PARAMETER);
    }
    let n = if configs.is_null() {
        list.len()
    } else {
        let n = list.len().min(config_size.max(0) as usize);
        for (i, &c) in list.iter().take(n).enumerate() {
            // SAFETY: i < config_size, for which the caller guarantees room.
            unsafe { configs.add(i).write_unaligned(handle(c)) };
        }
        n
    };
    // SAFETY: non-null, writable by the caller's contract.
    unsafe { num_config.write_unaligned(n as EGLint) };
    Ok(())
}

/// # Safety
/// `configs` is null or has room for `config_size` handles; `num_config` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigs(
    dpy: EGLDisplay,
    configs: *mut EGLConfig,
    config_size: EGLint,
    num_config: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        let list = d::get_configs(id(dpy))?;
        // SAFETY: forwarded to the caller's contract.
        unsafe { return_configs(list, configs, config_size, num_config) }
    })
}

/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated; `configs` is null or has room for
/// `config_size` handles; `num_config` is null or writable. An EGL_MATCH_NATIVE_PIXMAP value
/// must be the address of a readable `EGLMemoryPixmap` (which limits it to the low 2 GiB of
/// the address space, EGLint being 32 bits).
#[no_mangle]
pub unsafe extern "C" fn eglChooseConfig(
    dpy: EGLDisplay,
    attrib_list: *const EGLint,
    configs: *mut EGLConfig,
    config_size: EGLint,
    num_config: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        let pixmap = |v: EGLint| {
            // SAFETY: the value is a pixmap address by the caller's contract.
            unsafe { client_memory(v as u32 as usize as *const EGLMemoryPixmap) }
                .map(|m| m.layout())
        };
        if num_config.is_null() {
            d::get_configs(id(dpy))?;
            return Err(EGL_BAD_PARAMETER);
        }
        let list = d::choose_config(id(dpy), &pairs, pixmap)?;
        // SAFETY: forwarded to the caller's contract.
        unsafe { return_configs(list, configs, config_size, num_config) }
    })
}

/// # Safety
/// `value` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigAttrib(
    dpy: EGLDisplay,
    config: EGLConfig,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        let v = d::get_config_attrib(id(dpy), id(config), attribute)?;
        // SAFETY: forwarded to the caller's contract.
        unsafe { put(value, v) };
        Ok(())
    })
}

/// # Safety
/// `win` is null or points to a valid `EGLMemoryWindow` whose pixels stay valid while the
/// surface exists; `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreateWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    win: EGLNativeWindowType,
    attrib_list: *const EGLint,
) -> EGLSurface {
    call(EGL_NO_SURFACE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        // SAFETY: forwarded to the caller's contract.
        unsafe { create_native(dpy, config, Kind::Window, window_as_pixmap(win), &pairs) }
    })
}

/// A window or pixmap surface on a memory pixmap-shaped struct.
///
/// # Safety
/// `memory` is null or points to a valid `EGLMemoryPixmap`-shaped struct whose pixels stay
/// valid while the surface exists.
unsafe fn create_native(
    dpy: EGLDisplay,
    config: EGLConfig,
    kind: Kind,
    memory: *const EGLMemoryPixmap,
    pairs: &[(EGLint, EGLint)],
) -> EglResult<EGLSurface> {
    // SAFETY: forwarded to the caller's contract.
    let client = unsafe { client_memory(memory) };
    d::create_native(id(dpy), id(config), kind, memory as usize, client, pairs).map(handle)
}

/// # Safety
/// `pixmap` is null or points to a valid `EGLMemoryPixmap` whose pixels stay valid while the
/// surface exists; `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePixmapSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    pixmap: EGLNativePixmapType,
    attrib_list: *const EGLint,
) -> EGLSurface {
    call(EGL_NO_SURFACE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        // SAFETY: forwarded to the caller's contract.
        unsafe { create_native(dpy, config, Kind::Pixmap, pixmap, &pairs) }
    })
}

/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePbufferSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    attrib_list: *const EGLint,
) -> EGLSurface {
    call(EGL_NO_SURFACE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        d::create_pbuffer(id(dpy), id(config), &pairs).map(handle)
    })
}

/// No client buffer types are supported: after the display and config checks, always
/// EGL_BAD_PARAMETER.
#[no_mangle]
pub extern "C" fn eglCreatePbufferFromClientBuffer(
    dpy: EGLDisplay,
    buftype: EGLenum,
    buffer: EGLClientBuffer,
    config: EGLConfig,
    attrib_list: *const EGLint,
) -> EGLSurface {
    let _ = (buftype, buffer, attrib_list);
    call(EGL_NO_SURFACE, || {
        d::get_config_attrib(id(dpy), id(config), EGL_CONFIG_ID)?;
        Err(EGL_BAD_PARAMETER)
    })
}

#[no_mangle]
pub extern "C" fn eglDestroySurface(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    call_bool(|| d::destroy_surface(id(dpy), id(surface)))
}

/// # Safety
/// `value` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglQuerySurface(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        if let Some(v) = d::query_surface(id(dpy), id(surface), attribute)? {
            // SAFETY: forwarded to the caller's contract.
            unsafe { put(value, v) };
        }
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn eglSurfaceAttrib(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: EGLint,
) -> EGLBoolean {
    call_bool(|| d::surface_attrib(id(dpy), id(surface), attribute, value))
}

/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreateContext(
    dpy: EGLDisplay,
    config: EGLConfig,
    share_context: EGLContext,
    attrib_list: *const EGLint,
) -> EGLContext {
    call(EGL_NO_CONTEXT, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        d::create_context(id(dpy), id(config), id(share_context), &pairs).map(handle)
    })
}

#[no_mangle]
pub extern "C" fn eglDestroyContext(dpy: EGLDisplay, ctx: EGLContext) -> EGLBoolean {
    call_bool(|| d::destroy_context(id(dpy), id(ctx)))
}

/// # Safety
/// `value` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglQueryContext(
    dpy: EGLDisplay,
    ctx: EGLContext,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        let v = d::query_context(id(dpy), id(ctx), attribute)?;
        // SAFETY: forwarded to the caller's contract.
        unsafe { put(value, v) };
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn eglMakeCurrent(
    dpy: EGLDisplay,
    draw: EGLSurface,
    read: EGLSurface,
    ctx: EGLContext,
) -> EGLBoolean {
    call_bool(|| d::make_current(id(dpy), id(draw), id(read), id(ctx)))
}

#[no_mangle]
pub extern "C" fn eglGetCurrentContext() -> EGLContext {
    call(EGL_NO_CONTEXT, || Ok(handle(d::current_context())))
}

#[no_mangle]
pub extern "C" fn eglGetCurrentDisplay() -> EGLDisplay {
    call(EGL_NO_DISPLAY, || Ok(handle(d::current_display())))
}

#[no_mangle]
pub extern "C" fn eglGetCurrentSurface(readdraw: EGLint) -> EGLSurface {
    call(EGL_NO_SURFACE, || d::current_surface(readdraw).map(handle))
}

#[no_mangle]
pub extern "C" fn eglSwapBuffers(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    call_bool(|| d::swap_buffers(id(dpy), id(surface)))
}

/// # Safety
/// `target` is null or points to a valid `EGLMemoryPixmap`.
#[no_mangle]
pub unsafe extern "C" fn eglCopyBuffers(
    dpy: EGLDisplay,
    surface: EGLSurface,
    target: EGLNativePixmapType,
) -> EGLBoolean {
    call_bool(|| {
        // SAFETY: forwarded to the caller's contract.
        let memory = unsafe { client_memory(target) };
        d::copy_buffers(id(dpy), id(surface), memory)
    })
}

#[no_mangle]
pub extern "C" fn eglSwapInterval(dpy: EGLDisplay, interval: EGLint) -> EGLBoolean {
    call_bool(|| d::swap_interval(id(dpy), interval))
}

#[no_mangle]
pub extern "C" fn eglBindTexImage(
    dpy: EGLDisplay,
    surface: EGLSurface,
    buffer: EGLint,
) -> EGLBoolean {
    call_bool(|| d::bind_tex_image_egl(id(dpy), id(surface), buffer))
}

#[no_mangle]
pub extern "C" fn eglReleaseTexImage(
    dpy: EGLDisplay,
    surface: EGLSurface,
    buffer: EGLint,
) -> EGLBoolean {
    call_bool(|| d::release_tex_image(id(dpy), id(surface), buffer))
}

#[no_mangle]
pub extern "C" fn eglWaitGL() -> EGLBoolean {
    call_bool(d::wait_client)
}

#[no_mangle]
pub extern "C" fn eglWaitClient() -> EGLBoolean {
    call_bool(d::wait_client)
}

#[no_mangle]
pub extern "C" fn eglWaitNative(engine: EGLint) -> EGLBoolean {
    call_bool(|| d::wait_native(engine))
}

#[no_mangle]
pub extern "C" fn eglBindAPI(api: EGLenum) -> EGLBoolean {
    call_bool(|| d::bind_api(api))
}

#[no_mangle]
pub extern "C" fn eglQueryAPI() -> EGLenum {
    call(EGL_NONE as EGLenum, || Ok(d::query_api()))
}

#[no_mangle]
pub extern "C" fn eglReleaseThread() -> EGLBoolean {
    call_bool(|| {
        d::release_thread();
        Ok(())
    })
}

macro_rules! proc_table {
    ($($name:ident),* $(,)?) => {
        /// The address of the `egl*` function called `name`.
        fn egl_proc_address(name: &str) -> Option<*const c_void> {
            match name {
                $(stringify!($name) => Some($name as *const c_void),)*
                _ => None,
            }
        }

        /// Every `egl*` function this library exports.
        pub const PROC_NAMES: &[&str] = &[$(stringify!($name)),*];
    };
}

// build.rs lists every exported `egl*` function, so the table cannot miss one.
include!(concat!(env!("OUT_DIR"), "/egl_proc_table.rs"));

/// The address of any `gl*` or `egl*` function of this library called `procname`, extensions
/// included; `None` for other names and for null. Shared by eglGetProcAddress and glvnd's
/// `getProcAddress` (`super::glvnd`).
///
/// # Safety
/// `procname` is null or a NUL-terminated string.
pub(crate) unsafe fn proc_address_c(procname: *const c_char) -> Option<*const c_void> {
    if procname.is_null() {
        return None;
    }
    // SAFETY: non-null and NUL-terminated by the caller's contract.
    let name = unsafe { CStr::from_ptr(procname) }.to_str().ok()?;
    egl_proc_address(name).or_else(|| crate::gles::ffi::proc_address(name))
}

/// Any `gl*` or `egl*` function of this library, extensions included; NULL for other names.
///
/// # Safety
/// `procname` is null or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn eglGetProcAddress(
    procname: *const c_char,
) -> __eglMustCastToProperFunctionPointerType {
    call(None, || {
        // SAFETY: forwarded to the caller's contract.
        let addr = unsafe { proc_address_c(procname) };
        // SAFETY: the address is that of an `extern "C"` function of this library; C casts
        // the generic pointer back to the function's real type before calling it.
        Ok(
            addr.map(|p| unsafe {
                std::mem::transmute::<*const c_void, unsafe extern "C" fn()>(p)
            }),
        )
    })
}

/// EGL 1.5: eglGetPlatformDisplayEXT with an `EGLAttrib` list.
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplay(
    platform: EGLenum,
    native_display: *mut c_void,
    attrib_list: *const EGLAttrib,
) -> EGLDisplay {
    call(EGL_NO_DISPLAY, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs_wide(attrib_list) };
        d::get_platform_display(platform, native_display as usize, &pairs).map(handle)
    })
}

/// EGL 1.5: the native window is a `struct EGLMemoryWindow`.
///
/// # Safety
/// As eglCreateWindowSurface's, with `native_window` for `win`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePlatformWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    native_window: *mut c_void,
    attrib_list: *const EGLAttrib,
) -> EGLSurface {
    call(EGL_NO_SURFACE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = narrow(&unsafe { attrib_pairs_wide(attrib_list) })?;
        let memory = window_as_pixmap(native_window.cast());
        // SAFETY: forwarded to the caller's contract.
        unsafe { create_native(dpy, config, Kind::Window, memory, &pairs) }
    })
}

/// EGL 1.5: the native pixmap is a `struct EGLMemoryPixmap`.
///
/// # Safety
/// As eglCreatePixmapSurface's, with `native_pixmap` for `pixmap`.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePlatformPixmapSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    native_pixmap: *mut c_void,
    attrib_list: *const EGLAttrib,
) -> EGLSurface {
    call(EGL_NO_SURFACE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = narrow(&unsafe { attrib_pairs_wide(attrib_list) })?;
        // SAFETY: forwarded to the caller's contract.
        unsafe { create_native(dpy, config, Kind::Pixmap, native_pixmap.cast(), &pairs) }
    })
}

/// EGL 1.5 fence syncs.
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreateSync(
    dpy: EGLDisplay,
    type_: EGLenum,
    attrib_list: *const EGLAttrib,
) -> EGLSync {
    call(EGL_NO_SYNC, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs_wide(attrib_list) };
        d::create_sync(id(dpy), type_, &pairs, d::SyncApi::Core).map(handle)
    })
}

/// EGL_KHR_fence_sync's eglCreateSync, with an `EGLint` list.
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreateSyncKHR(
    dpy: EGLDisplay,
    type_: EGLenum,
    attrib_list: *const EGLint,
) -> EGLSyncKHR {
    call(EGL_NO_SYNC, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        d::create_sync(id(dpy), type_, &pairs, d::SyncApi::Khr).map(handle)
    })
}

#[no_mangle]
pub extern "C" fn eglDestroySync(dpy: EGLDisplay, sync: EGLSync) -> EGLBoolean {
    call_bool(|| d::destroy_sync(id(dpy), id(sync)))
}

#[no_mangle]
pub extern "C" fn eglDestroySyncKHR(dpy: EGLDisplay, sync: EGLSyncKHR) -> EGLBoolean {
    eglDestroySync(dpy, sync)
}

#[no_mangle]
pub extern "C" fn eglClientWaitSync(
    dpy: EGLDisplay,
    sync: EGLSync,
    flags: EGLint,
    timeout: EGLTime,
) -> EGLint {
    // Every wait completes the fence, so neither the flush flag nor the timeout matters.
    let _ = (flags, timeout);
    call(EGL_FALSE as EGLint, || {
        d::client_wait_sync(id(dpy), id(sync))
    })
}

#[no_mangle]
pub extern "C" fn eglClientWaitSyncKHR(
    dpy: EGLDisplay,
    sync: EGLSyncKHR,
    flags: EGLint,
    timeout: EGLTimeKHR,
) -> EGLint {
    eglClientWaitSync(dpy, sync, flags, timeout)
}

#[no_mangle]
pub extern "C" fn eglWaitSync(dpy: EGLDisplay, sync: EGLSync, flags: EGLint) -> EGLBoolean {
    call_bool(|| d::wait_sync(id(dpy), id(sync), flags))
}

/// EGL_KHR_wait_sync: eglWaitSync returning EGLint.
#[no_mangle]
pub extern "C" fn eglWaitSyncKHR(dpy: EGLDisplay, sync: EGLSyncKHR, flags: EGLint) -> EGLint {
    eglWaitSync(dpy, sync, flags) as EGLint
}

/// # Safety
/// `value` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetSyncAttrib(
    dpy: EGLDisplay,
    sync: EGLSync,
    attribute: EGLint,
    value: *mut EGLAttrib,
) -> EGLBoolean {
    call_bool(|| {
        let v = d::get_sync_attrib(id(dpy), id(sync), attribute)?;
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: non-null, and writable by the caller's contract.
        unsafe { put(value, v as EGLAttrib) };
        Ok(())
    })
}

/// EGL_KHR_fence_sync's eglGetSyncAttrib, answering in an `EGLint`.
///
/// # Safety
/// `value` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetSyncAttribKHR(
    dpy: EGLDisplay,
    sync: EGLSyncKHR,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call_bool(|| {
        let v = d::get_sync_attrib(id(dpy), id(sync), attribute)?;
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: non-null, and writable by the caller's contract.
        unsafe { put(value, v) };
        Ok(())
    })
}

/// EGL 1.5 images from GL textures (`EGL_GL_TEXTURE_2D`; `buffer` is the texture name).
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreateImage(
    dpy: EGLDisplay,
    ctx: EGLContext,
    target: EGLenum,
    buffer: EGLClientBuffer,
    attrib_list: *const EGLAttrib,
) -> EGLImage {
    call(EGL_NO_IMAGE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs_wide(attrib_list) };
        let pairs: Vec<(i64, i64)> = pairs.iter().map(|&(a, v)| (a as i64, v as i64)).collect();
        d::create_image(id(dpy), id(ctx), target, buffer as usize, &pairs).map(handle)
    })
}

/// EGL_KHR_image_base's eglCreateImage, with an `EGLint` list.
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
#[no_mangle]
pub unsafe extern "C" fn eglCreateImageKHR(
    dpy: EGLDisplay,
    ctx: EGLContext,
    target: EGLenum,
    buffer: EGLClientBuffer,
    attrib_list: *const EGLint,
) -> EGLImageKHR {
    call(EGL_NO_IMAGE, || {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        d::create_image(id(dpy), id(ctx), target, buffer as usize, &pairs).map(handle)
    })
}

#[no_mangle]
pub extern "C" fn eglDestroyImage(dpy: EGLDisplay, image: EGLImage) -> EGLBoolean {
    call_bool(|| d::destroy_image(id(dpy), id(image)))
}

#[no_mangle]
pub extern "C" fn eglDestroyImageKHR(dpy: EGLDisplay, image: EGLImageKHR) -> EGLBoolean {
    eglDestroyImage(dpy, image)
}
