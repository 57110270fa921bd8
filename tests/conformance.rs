//! Conformance sweep checks that are not C programs of their own (issue 9; the C side is
//! `c_tests/conf_*.c`).
//!
//! `every_listed_extension_has_a_test`: every name `glGetString(GL_EXTENSIONS)` and
//! `eglQueryString(EGL_EXTENSIONS)` return is exercised by a program in `c_tests/` that is
//! not one of the generic sweeps (the state and error tables, the fuzzer): a program names
//! the extension, or uses one of the tokens or functions only that extension defines
//! (`EVIDENCE`). A newly listed extension fails this test until a program tests it.
//!
//! `eglGetProcAddress` for every exported function is `c_tests/conf_proc_address.c`.

use std::ffi::CStr;
use std::path::Path;

use GLES_CM::egl::ffi::*;
use GLES_CM::egl::tokens::*;
use GLES_CM::egl::types::*;
use GLES_CM::gles::tokens::GL_EXTENSIONS;

// The GL entry points' modules are private; the symbol is linked in from the rlib.
extern "C" {
    fn glGetString(name: u32) -> *const u8;
}

/// The generic sweeps: they touch every extension, so they do not count as its test.
const GENERIC: &[&str] = &[
    "conf_state_table.c",
    "conf_errors.c",
    "conf_fuzz.c",
    "conf_proc_address.c",
    "entry_points.c",
];

/// Identifiers only one extension defines, for extensions whose programs do not name them.
/// Any one found (as a whole identifier) in a non-generic program counts.
const EVIDENCE: &[(&str, &[&str])] = &[
    // Byte vertex and texture coordinates.
    ("GL_OES_byte_coordinates", &["GL_BYTE"]),
    (
        "GL_OES_point_sprite",
        &["GL_POINT_SPRITE_OES", "GL_COORD_REPLACE_OES"],
    ),
    (
        "GL_OES_texture_mirrored_repeat",
        &["GL_MIRRORED_REPEAT_OES"],
    ),
    (
        "GL_OES_read_format",
        &["GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES"],
    ),
    ("GL_OES_point_size_array", &["glPointSizePointerOES"]),
    (
        "GL_OES_matrix_palette",
        &["glMatrixIndexPointerOES", "glCurrentPaletteMatrixOES"],
    ),
    (
        "GL_OES_matrix_get",
        &["GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES"],
    ),
    ("GL_OES_query_matrix", &["glQueryMatrixxOES"]),
    ("GL_OES_mapbuffer", &["glMapBufferOES"]),
    (
        "GL_OES_stencil_wrap",
        &["GL_INCR_WRAP_OES", "GL_DECR_WRAP_OES"],
    ),
    ("GL_OES_blend_subtract", &["glBlendEquationOES"]),
    ("GL_OES_blend_func_separate", &["glBlendFuncSeparateOES"]),
    (
        "GL_OES_blend_equation_separate",
        &["glBlendEquationSeparateOES"],
    ),
    ("GL_OES_element_index_uint", &["GL_UNSIGNED_INT"]),
    (
        "GL_OES_compressed_paletted_texture",
        &["GL_PALETTE4_RGB8_OES", "GL_PALETTE8_RGBA8_OES"],
    ),
    (
        "GL_OES_draw_texture",
        &["glDrawTexiOES", "glDrawTexfOES", "GL_TEXTURE_CROP_RECT_OES"],
    ),
    (
        "GL_OES_framebuffer_object",
        &["glGenFramebuffersOES", "glFramebufferTexture2DOES"],
    ),
    ("GL_OES_texture_cube_map", &["GL_TEXTURE_CUBE_MAP_OES"]),
    ("EGL_KHR_get_all_proc_addresses", &["eglGetProcAddress"]),
];

/// The extension strings of a fresh pbuffer context, made through the library's own entry
/// points (linked into this test as the rlib).
fn extension_strings() -> (String, String) {
    // SAFETY: the library's own entry points, called as a C program would, with live
    // attribute lists and out-parameters.
    unsafe {
        let dpy = eglGetDisplay(std::ptr::null_mut());
        assert!(!dpy.is_null());
        assert_eq!(
            eglInitialize(dpy, std::ptr::null_mut(), std::ptr::null_mut()),
            1
        );
        let attribs = [
            EGL_SURFACE_TYPE,
            EGL_PBUFFER_BIT,
            EGL_RENDERABLE_TYPE,
            EGL_OPENGL_ES_BIT,
            EGL_NONE,
        ];
        let mut config: EGLConfig = std::ptr::null_mut();
        let mut n = 0;
        assert_eq!(
            eglChooseConfig(dpy, attribs.as_ptr(), &mut config, 1, &mut n),
            1
        );
        assert_eq!(n, 1);
        let pb = [EGL_WIDTH, 4, EGL_HEIGHT, 4, EGL_NONE];
        let surface = eglCreatePbufferSurface(dpy, config, pb.as_ptr());
        let context = eglCreateContext(dpy, config, std::ptr::null_mut(), std::ptr::null());
        assert!(!surface.is_null() && !context.is_null());
        assert_eq!(eglMakeCurrent(dpy, surface, surface, context), 1);
        let gl = glGetString(GL_EXTENSIONS);
        assert!(!gl.is_null());
        let gl = CStr::from_ptr(gl.cast()).to_string_lossy().into_owned();
        let egl = eglQueryString(dpy, EGL_EXTENSIONS);
        assert!(!egl.is_null());
        let egl = CStr::from_ptr(egl).to_string_lossy().into_owned();
        eglMakeCurrent(
            dpy,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
        );
        eglDestroyContext(dpy, context);
        eglDestroySurface(dpy, surface);
        (gl, egl)
    }
}

/// True when `word` occurs in `text` as a whole identifier.
fn mentions(text: &str, word: &str) -> bool {
    let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
    text.match_indices(word).any(|(i, _)| {
        !ident(text[..i].chars().next_back()) && !ident(text[i + word.len()..].chars().next())
    })
}

#[test]
fn every_listed_extension_has_a_test() {
    let (gl, egl) = extension_strings();
    let names: Vec<&str> = gl
        .split_whitespace()
        .chain(egl.split_whitespace())
        .collect();
    assert!(
        names.iter().any(|n| n.starts_with("GL_")),
        "GL_EXTENSIONS is empty"
    );
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("c_tests");
    let programs: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("c_tests/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "c"))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            let text = std::fs::read_to_string(&p).expect("read C source");
            (name, text)
        })
        .filter(|(name, _)| !GENERIC.contains(&name.as_str()))
        .collect();

    let mut untested = Vec::new();
    for name in &names {
        // "GL_OES_point_sprite" is named as such or as "OES_point_sprite".
        let short = name.split_once('_').map_or(*name, |(_, rest)| rest);
        let evidence = EVIDENCE
            .iter()
            .find(|(e, _)| e == name)
            .map_or(&[][..], |(_, w)| *w);
        let tested_by: Vec<&str> = programs
            .iter()
            .filter(|(_, text)| {
                mentions(text, name)
                    || mentions(text, short)
                    || evidence.iter().any(|w| mentions(text, w))
            })
            .map(|(n, _)| n.as_str())
            .collect();
        println!("{name}: {}", tested_by.join(" "));
        if tested_by.is_empty() {
            untested.push(*name);
        }
    }
    assert!(
        untested.is_empty(),
        "listed but tested by no program in c_tests/ (name it in the program that tests it, \
         or add evidence to tests/conformance.rs): {untested:?}"
    );
}
