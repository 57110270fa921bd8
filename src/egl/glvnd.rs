//! The library as a glvnd EGL vendor: `__egl_Main`, the one entry point glvnd's `libEGL.so.1`
//! looks up in a vendor library, and the callbacks it fills into glvnd's import table. The
//! layout and the meaning of every field come from glvnd's `glvnd/libeglabi.h` (EGL vendor
//! ABI 0.2, libglvnd 1.6).
//!
//! glvnd reaches everything else through `getProcAddress`: the core `egl*` functions once,
//! when it loads the vendor, and the `gl*` functions whenever a context of ours becomes
//! current (libGLdispatch fills its table from them), so the program's calls go through
//! glvnd's `libEGL.so.1` and `libGLESv1_CM.so.1` and arrive at this library's functions. The
//! addresses handed out are this library's own even where the process also has glvnd's
//! functions of the same names: the library is linked with `-Bsymbolic-functions`
//! (`build.rs`).
//!
//! Like `ffi`, this is a boundary module: `unsafe` only where glvnd's pointers are read or
//! written, every callback runs through `crate::boundary::catch`.

use std::ffi::{c_char, c_int, c_void, CStr};
use std::ptr::{self, addr_of_mut};

use super::display as d;
use super::ffi;
use super::thread;
use super::tokens::*;
use super::types::*;

/// `EGLAttrib` (EGL 1.5): attribute values of `getPlatformDisplay` are pointer-sized.
type EGLAttrib = isize;

/// `EGL_VENDOR_ABI_MAJOR_VERSION`: glvnd's ABI version is `major << 16 | minor`; a vendor
/// must refuse another major version.
const ABI_MAJOR: u32 = 0;
/// The minor version whose import table ends with `findNativeDisplayPlatform`; an older
/// glvnd passes a shorter table, so that field is written only from this version on.
const ABI_MINOR_FIND_PLATFORM: u32 = 2;

/// `__EGL_VENDOR_STRING_PLATFORM_EXTENSIONS`, the one name `getVendorString` is asked for.
const VENDOR_STRING_PLATFORM_EXTENSIONS: c_int = 0;
/// The platform extensions this vendor adds to glvnd's client extension string (glvnd
/// itself provides EGL_EXT_platform_base and EGL_EXT_client_extensions).
const PLATFORM_EXTENSIONS: &CStr = c"EGL_MESA_platform_surfaceless";

/// `__EGLapiImports` of ABI 0.2: what the vendor gives glvnd. Only the first six are
/// required; the patching ones (for glvnd rewriting its own stubs) stay null.
#[repr(C)]
struct Imports {
    get_platform_display:
        Option<unsafe extern "C" fn(EGLenum, *mut c_void, *const EGLAttrib) -> EGLDisplay>,
    get_supports_api: Option<extern "C" fn(EGLenum) -> EGLBoolean>,
    get_vendor_string: Option<extern "C" fn(c_int) -> *const c_char>,
    get_proc_address: Option<unsafe extern "C" fn(*const c_char) -> *mut c_void>,
    get_dispatch_address: Option<unsafe extern "C" fn(*const c_char) -> *mut c_void>,
    set_dispatch_index: Option<unsafe extern "C" fn(*const c_char, c_int)>,
    is_patch_supported: *const c_void,
    initiate_patch: *const c_void,
    release_patch: *const c_void,
    patch_thread_attach: *const c_void,
    find_native_display_platform: *const c_void,
}

/// glvnd's entry into the vendor: checks the ABI version and fills `imports`. `exports`
/// (glvnd's own services, for vendors that dispatch EGL extension functions themselves) and
/// `vendor` are not needed: every function this library has is one glvnd already knows.
///
/// # Safety
/// `imports` is null or points to a writable `__EGLapiImports` of the version `version`
/// names, as glvnd passes it.
#[no_mangle]
pub unsafe extern "C" fn __egl_Main(
    version: u32,
    _exports: *const c_void,
    _vendor: *mut c_void,
    imports: *mut c_void,
) -> EGLBoolean {
    let imports = imports.cast::<Imports>();
    if version >> 16 != ABI_MAJOR || imports.is_null() {
        return EGL_FALSE;
    }
    // SAFETY: glvnd's table is writable and at least as long as ABI 0.0's, which ends with
    // patch_thread_attach; the last field is written only for a version that has it.
    unsafe {
        addr_of_mut!((*imports).get_platform_display).write(Some(get_platform_display));
        addr_of_mut!((*imports).get_supports_api).write(Some(get_supports_api));
        addr_of_mut!((*imports).get_vendor_string).write(Some(get_vendor_string));
        addr_of_mut!((*imports).get_proc_address).write(Some(get_proc_address));
        addr_of_mut!((*imports).get_dispatch_address).write(Some(get_dispatch_address));
        addr_of_mut!((*imports).set_dispatch_index).write(Some(set_dispatch_index));
        addr_of_mut!((*imports).is_patch_supported).write(ptr::null());
        addr_of_mut!((*imports).initiate_patch).write(ptr::null());
        addr_of_mut!((*imports).release_patch).write(ptr::null());
        addr_of_mut!((*imports).patch_thread_attach).write(ptr::null());
        if version & 0xFFFF >= ABI_MINOR_FIND_PLATFORM {
            addr_of_mut!((*imports).find_native_display_platform).write(ptr::null());
        }
    }
    EGL_TRUE
}

/// Reads an EGL_NONE-terminated `EGLAttrib` list into pairs (null is the empty list).
///
/// # Safety
/// A non-null `list` must point to attribute/value pairs ending with EGL_NONE.
unsafe fn attrib_pairs(list: *const EGLAttrib) -> Vec<(EGLAttrib, EGLAttrib)> {
    let mut pairs = Vec::new();
    if list.is_null() {
        return pairs;
    }
    let mut i = 0;
    loop {
        // SAFETY: readable up to its EGL_NONE by the caller's contract, and we stop there.
        let attr = unsafe { list.add(i).read_unaligned() };
        if attr == EGL_NONE as EGLAttrib {
            return pairs;
        }
        // SAFETY: an attribute that is not EGL_NONE is followed by its value.
        let value = unsafe { list.add(i + 1).read_unaligned() };
        pairs.push((attr, value));
        i += 2;
    }
}

/// The display of `platform`, or EGL_NO_DISPLAY when this vendor has none (glvnd then asks
/// the next vendor). glvnd passes EGL_NONE for plain eglGetDisplay, whatever the native
/// display, and EGL_PLATFORM_SURFACELESS_MESA for eglGetPlatformDisplay(EXT) on the one
/// platform we name in [`PLATFORM_EXTENSIONS`].
///
/// # Safety
/// `attrib_list` is null or EGL_NONE-terminated.
unsafe extern "C" fn get_platform_display(
    platform: EGLenum,
    native_display: *mut c_void,
    attrib_list: *const EGLAttrib,
) -> EGLDisplay {
    let result = crate::boundary::catch(|| {
        // SAFETY: forwarded to the caller's contract.
        let pairs = unsafe { attrib_pairs(attrib_list) };
        if platform == EGL_NONE as EGLenum {
            return Ok(d::get_display(native_display as usize));
        }
        // An attribute that does not fit an EGLint cannot be one the platform knows; it is
        // kept unequal to EGL_NONE so the platform rejects it.
        let narrow = |v: EGLAttrib| EGLint::try_from(v).unwrap_or(EGLint::MAX);
        let pairs: Vec<(EGLint, EGLint)> =
            pairs.iter().map(|&(a, v)| (narrow(a), narrow(v))).collect();
        d::get_platform_display(platform, native_display as usize, &pairs)
    });
    match result {
        Some(Ok(dpy)) => {
            thread::set_error(EGL_SUCCESS);
            dpy as EGLDisplay
        }
        Some(Err(e)) => {
            thread::set_error(e);
            ptr::null_mut()
        }
        None => {
            thread::set_error(EGL_BAD_ALLOC);
            ptr::null_mut()
        }
    }
}

/// Whether contexts of `api` can be made: only OpenGL ES (1.x).
extern "C" fn get_supports_api(api: EGLenum) -> EGLBoolean {
    if api == EGL_OPENGL_ES_API {
        EGL_TRUE
    } else {
        EGL_FALSE
    }
}

/// Strings glvnd asks the vendor for; null for a name it does not know.
extern "C" fn get_vendor_string(name: c_int) -> *const c_char {
    if name == VENDOR_STRING_PLATFORM_EXTENSIONS {
        PLATFORM_EXTENSIONS.as_ptr()
    } else {
        ptr::null()
    }
}

/// Any `egl*` or `gl*` function of this library (what eglGetProcAddress answers).
///
/// # Safety
/// `name` is null or NUL-terminated.
unsafe extern "C" fn get_proc_address(name: *const c_char) -> *mut c_void {
    // SAFETY: forwarded to the caller's contract.
    crate::boundary::catch(|| unsafe { ffi::proc_address_c(name) })
        .flatten()
        .map_or(ptr::null_mut(), |p| p.cast_mut())
}

/// glvnd asks for a dispatch stub for an `egl*` function it does not know. Every EGL function
/// this library has is core EGL 1.4 or one glvnd implements itself
/// (EGL_EXT_platform_base), so there is none to give.
unsafe extern "C" fn get_dispatch_address(_name: *const c_char) -> *mut c_void {
    ptr::null_mut()
}

/// The index glvnd gives a stub from [`get_dispatch_address`]; never called, as there are
/// none.
unsafe extern "C" fn set_dispatch_index(_name: *const c_char, _index: c_int) {}

#[cfg(test)]
mod tests {
    use super::*;

    /// A glvnd table filled the way glvnd 1.6 would see it.
    fn main_with(version: u32) -> (EGLBoolean, Imports) {
        let mut imports = Imports {
            get_platform_display: None,
            get_supports_api: None,
            get_vendor_string: None,
            get_proc_address: None,
            get_dispatch_address: None,
            set_dispatch_index: None,
            is_patch_supported: ptr::null(),
            initiate_patch: ptr::null(),
            release_patch: ptr::null(),
            patch_thread_attach: ptr::null(),
            find_native_display_platform: ptr::null(),
        };
        // SAFETY: `imports` is a live table of the layout glvnd passes.
        let ok = unsafe {
            __egl_Main(
                version,
                ptr::null(),
                ptr::null_mut(),
                (&mut imports as *mut Imports).cast(),
            )
        };
        (ok, imports)
    }

    #[test]
    fn refuses_another_major_version() {
        let (ok, imports) = main_with(1 << 16);
        assert_eq!(ok, EGL_FALSE);
        assert!(imports.get_proc_address.is_none());
    }

    #[test]
    fn fills_the_required_imports() {
        let (ok, imports) = main_with(2);
        assert_eq!(ok, EGL_TRUE);
        let gpa = imports.get_proc_address.unwrap();
        // SAFETY: the names are NUL-terminated, or null, which the function accepts.
        assert!(!unsafe { gpa(c"eglInitialize".as_ptr()) }.is_null());
        // SAFETY: as above.
        assert!(!unsafe { gpa(c"glClear".as_ptr()) }.is_null());
        // SAFETY: as above.
        assert!(unsafe { gpa(c"glNotAFunction".as_ptr()) }.is_null());
        // SAFETY: as above.
        assert!(unsafe { gpa(ptr::null()) }.is_null());
        assert_eq!(
            (imports.get_supports_api.unwrap())(EGL_OPENGL_ES_API),
            EGL_TRUE
        );
        assert_eq!((imports.get_supports_api.unwrap())(0x30A2), EGL_FALSE);
        let ext = (imports.get_vendor_string.unwrap())(VENDOR_STRING_PLATFORM_EXTENSIONS);
        // SAFETY: the vendor string is a static NUL-terminated string.
        assert_eq!(unsafe { CStr::from_ptr(ext) }, PLATFORM_EXTENSIONS);
        assert!((imports.get_vendor_string.unwrap())(7).is_null());
    }

    #[test]
    fn platform_displays() {
        let gpd = get_platform_display;
        // SAFETY: the attribute lists here and below are null or EGL_NONE-terminated.
        let dpy = unsafe { gpd(EGL_NONE as EGLenum, ptr::null_mut(), ptr::null()) };
        assert_eq!(dpy as usize, d::DISPLAY_HANDLE);
        // SAFETY: as above.
        let dpy = unsafe { gpd(d::PLATFORM_SURFACELESS_MESA, ptr::null_mut(), ptr::null()) };
        assert_eq!(dpy as usize, d::DISPLAY_HANDLE);
        let none = [EGL_NONE as EGLAttrib];
        // SAFETY: as above.
        let dpy = unsafe { gpd(d::PLATFORM_SURFACELESS_MESA, ptr::null_mut(), none.as_ptr()) };
        assert_eq!(dpy as usize, d::DISPLAY_HANDLE);
        // X11 (EGL_PLATFORM_X11_KHR) is another vendor's.
        // SAFETY: as above.
        let dpy = unsafe { gpd(0x31D5, ptr::null_mut(), ptr::null()) };
        assert!(dpy.is_null());
        let attrs = [0x3001, 1 << 40, EGL_NONE as EGLAttrib];
        // SAFETY: as above.
        let dpy = unsafe {
            gpd(
                d::PLATFORM_SURFACELESS_MESA,
                ptr::null_mut(),
                attrs.as_ptr(),
            )
        };
        assert!(dpy.is_null());
    }
}
