//! Build script: generates the C headers and sets the shared library's link options.
//!
//! Headers (`include/GLES`, `include/EGL`, `include/KHR`):
//! - Prototypes come from the `#[no_mangle] extern "C"` functions of `src/gles/ffi/*.rs` and
//!   `src/egl/ffi*.rs`, read by cbindgen one file at a time, then decorated with
//!   `GL_API`/`GL_APIENTRY` (`EGLAPI`/`EGLAPIENTRY`) and sorted into the blocks of the standard
//!   headers; every extension and EGL function also gets its `PFN...PROC` typedef.
//! - Token `#define`s come from `src/gles/tokens.rs`, `src/gles/tokens_ext.rs`,
//!   `src/egl/tokens.rs` (and `src/egl/tokens_ext.rs` if present): each `pub const` becomes a
//!   `#define` with the literal written there, in source order. `// Extension: NAME` and
//!   `// Version: NAME` comment lines start the `#ifndef NAME` blocks.
//! - The memory pixmap and window structs of `src/egl/native.rs` go into `eglplatform.h`
//!   (through cbindgen, with their documentation).
//! - Type typedefs follow the Khronos definitions and are written here as text.
//!
//! Everything is written to `$OUT_DIR/include`. With `GLES_CM_BLESS_HEADERS=1` the headers are
//! also copied to `include/`; `tests/headers.rs` fails while the two differ. A header change
//! never fails the build.
//!
//! Extension blocks of `glext.h` and `eglext.h` follow the Khronos registry as recorded in
//! `headers/glext.txt` and `headers/eglext.txt` (tokens, types, functions of every
//! extension); a registry function the library does not export is declared there but is no
//! entry point, and is listed in `$OUT_DIR/declared_only.txt`.
//!
//! Also written to `$OUT_DIR`: `entry_points.txt` (`header name` per line),
//! `entry_points.inc` (an `EP(name)` X-macro list for `c_tests/entry_points.c`),
//! `gl_proc_table.rs` / `egl_proc_table.rs` (a `proc_table![glA, glB, ...];` invocation
//! naming every exported function, for `include!` where such a macro is in scope, e.g. to
//! build eglGetProcAddress's table). The link options set the
//! SONAME `libGLES_CM.so.1` (see `link_options`).

use std::collections::{BTreeMap, BTreeSet};
use std::env;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

const BLESS_VAR: &str = "GLES_CM_BLESS_HEADERS";

/// Extension functions of the OpenGL ES 1.x registry, by extension. A function listed here is
/// declared in the block of its extension: in `gl.h` when `tokens.rs` has that extension's
/// section (the four extensions of the core header), in `glext.h` otherwise.
const GL_EXTENSION_FUNCTIONS: &[(&str, &[&str])] = &[
    (
        "GL_OES_EGL_image",
        &[
            "glEGLImageTargetTexture2DOES",
            "glEGLImageTargetRenderbufferStorageOES",
        ],
    ),
    ("GL_OES_point_size_array", &["glPointSizePointerOES"]),
    (
        "GL_OES_blend_equation_separate",
        &["glBlendEquationSeparateOES"],
    ),
    ("GL_OES_blend_func_separate", &["glBlendFuncSeparateOES"]),
    ("GL_OES_blend_subtract", &["glBlendEquationOES"]),
    (
        "GL_OES_draw_texture",
        &[
            "glDrawTexsOES",
            "glDrawTexiOES",
            "glDrawTexxOES",
            "glDrawTexsvOES",
            "glDrawTexivOES",
            "glDrawTexxvOES",
            "glDrawTexfOES",
            "glDrawTexfvOES",
        ],
    ),
    (
        "GL_OES_fixed_point",
        &[
            "glAlphaFuncxOES",
            "glClearColorxOES",
            "glClearDepthxOES",
            "glClipPlanexOES",
            "glColor4xOES",
            "glDepthRangexOES",
            "glFogxOES",
            "glFogxvOES",
            "glFrustumxOES",
            "glGetClipPlanexOES",
            "glGetFixedvOES",
            "glGetTexEnvxvOES",
            "glGetTexParameterxvOES",
            "glLightModelxOES",
            "glLightModelxvOES",
            "glLightxOES",
            "glLightxvOES",
            "glLineWidthxOES",
            "glLoadMatrixxOES",
            "glMaterialxOES",
            "glMaterialxvOES",
            "glMultMatrixxOES",
            "glMultiTexCoord4xOES",
            "glNormal3xOES",
            "glOrthoxOES",
            "glPointParameterxvOES",
            "glPointSizexOES",
            "glPolygonOffsetxOES",
            "glRotatexOES",
            "glScalexOES",
            "glTexEnvxOES",
            "glTexEnvxvOES",
            "glTexParameterxOES",
            "glTexParameterxvOES",
            "glTranslatexOES",
            "glGetLightxvOES",
            "glGetMaterialxvOES",
            "glPointParameterxOES",
            "glSampleCoveragexOES",
            "glGetTexGenxvOES",
            "glTexGenxOES",
            "glTexGenxvOES",
        ],
    ),
    (
        "GL_OES_framebuffer_object",
        &[
            "glIsRenderbufferOES",
            "glBindRenderbufferOES",
            "glDeleteRenderbuffersOES",
            "glGenRenderbuffersOES",
            "glRenderbufferStorageOES",
            "glGetRenderbufferParameterivOES",
            "glIsFramebufferOES",
            "glBindFramebufferOES",
            "glDeleteFramebuffersOES",
            "glGenFramebuffersOES",
            "glCheckFramebufferStatusOES",
            "glFramebufferRenderbufferOES",
            "glFramebufferTexture2DOES",
            "glGetFramebufferAttachmentParameterivOES",
            "glGenerateMipmapOES",
        ],
    ),
    (
        "GL_OES_mapbuffer",
        &[
            "glMapBufferOES",
            "glUnmapBufferOES",
            "glGetBufferPointervOES",
        ],
    ),
    (
        "GL_OES_matrix_palette",
        &[
            "glCurrentPaletteMatrixOES",
            "glLoadPaletteFromModelViewMatrixOES",
            "glMatrixIndexPointerOES",
            "glWeightPointerOES",
        ],
    ),
    ("GL_OES_query_matrix", &["glQueryMatrixxOES"]),
    (
        "GL_OES_single_precision",
        &[
            "glClearDepthfOES",
            "glClipPlanefOES",
            "glDepthRangefOES",
            "glFrustumfOES",
            "glGetClipPlanefOES",
            "glOrthofOES",
        ],
    ),
    (
        "GL_OES_texture_cube_map",
        &[
            "glTexGenfOES",
            "glTexGenfvOES",
            "glTexGeniOES",
            "glTexGenivOES",
            "glGetTexGenfvOES",
            "glGetTexGenivOES",
        ],
    ),
    ("GL_EXT_discard_framebuffer", &["glDiscardFramebufferEXT"]),
    (
        "GL_EXT_multi_draw_arrays",
        &["glMultiDrawArraysEXT", "glMultiDrawElementsEXT"],
    ),
    ("GL_EXT_polygon_offset_clamp", &["glPolygonOffsetClampEXT"]),
    (
        "GL_EXT_map_buffer_range",
        &["glMapBufferRangeEXT", "glFlushMappedBufferRangeEXT"],
    ),
    (
        "GL_OES_vertex_array_object",
        &[
            "glBindVertexArrayOES",
            "glDeleteVertexArraysOES",
            "glGenVertexArraysOES",
            "glIsVertexArrayOES",
        ],
    ),
    (
        "GL_KHR_debug",
        &[
            "glDebugMessageControlKHR",
            "glDebugMessageInsertKHR",
            "glDebugMessageCallbackKHR",
            "glGetDebugMessageLogKHR",
            "glPushDebugGroupKHR",
            "glPopDebugGroupKHR",
            "glObjectLabelKHR",
            "glGetObjectLabelKHR",
            "glObjectPtrLabelKHR",
            "glGetObjectPtrLabelKHR",
            "glGetPointervKHR",
        ],
    ),
];

/// EGL 1.5 functions by the version that introduced them.
const EGL_VERSION_FUNCTIONS: &[(&str, &[&str])] = &[
    (
        "EGL_VERSION_1_0",
        &[
            "eglChooseConfig",
            "eglCopyBuffers",
            "eglCreateContext",
            "eglCreatePbufferSurface",
            "eglCreatePixmapSurface",
            "eglCreateWindowSurface",
            "eglDestroyContext",
            "eglDestroySurface",
            "eglGetConfigAttrib",
            "eglGetConfigs",
            "eglGetCurrentDisplay",
            "eglGetCurrentSurface",
            "eglGetDisplay",
            "eglGetError",
            "eglGetProcAddress",
            "eglInitialize",
            "eglMakeCurrent",
            "eglQueryContext",
            "eglQueryString",
            "eglQuerySurface",
            "eglSwapBuffers",
            "eglTerminate",
            "eglWaitGL",
            "eglWaitNative",
        ],
    ),
    (
        "EGL_VERSION_1_1",
        &[
            "eglBindTexImage",
            "eglReleaseTexImage",
            "eglSurfaceAttrib",
            "eglSwapInterval",
        ],
    ),
    (
        "EGL_VERSION_1_2",
        &[
            "eglBindAPI",
            "eglQueryAPI",
            "eglCreatePbufferFromClientBuffer",
            "eglReleaseThread",
            "eglWaitClient",
        ],
    ),
    ("EGL_VERSION_1_3", &[]),
    ("EGL_VERSION_1_4", &["eglGetCurrentContext"]),
    (
        "EGL_VERSION_1_5",
        &[
            "eglCreateSync",
            "eglDestroySync",
            "eglClientWaitSync",
            "eglGetSyncAttrib",
            "eglCreateImage",
            "eglDestroyImage",
            "eglGetPlatformDisplay",
            "eglCreatePlatformWindowSurface",
            "eglCreatePlatformPixmapSurface",
            "eglWaitSync",
        ],
    ),
];

/// A few EGL extension functions, by extension (for `eglext.h`'s blocks).
const EGL_EXTENSION_FUNCTIONS: &[(&str, &[&str])] = &[
    ("EGL_KHR_wait_sync", &["eglWaitSyncKHR"]),
    (
        "EGL_KHR_image_base",
        &["eglCreateImageKHR", "eglDestroyImageKHR"],
    ),
    (
        "EGL_KHR_lock_surface",
        &["eglLockSurfaceKHR", "eglUnlockSurfaceKHR"],
    ),
    (
        "EGL_KHR_fence_sync",
        &[
            "eglCreateSyncKHR",
            "eglDestroySyncKHR",
            "eglClientWaitSyncKHR",
            "eglGetSyncAttribKHR",
        ],
    ),
    (
        "EGL_KHR_swap_buffers_with_damage",
        &["eglSwapBuffersWithDamageKHR"],
    ),
    (
        "EGL_EXT_swap_buffers_with_damage",
        &["eglSwapBuffersWithDamageEXT"],
    ),
];

/// Typedefs that open a block of `egl.h`, as the Khronos header defines them.
const EGL_VERSION_TYPES: &[(&str, &str)] = &[
    (
        "EGL_VERSION_1_0",
        "typedef unsigned int EGLBoolean;\n\
         typedef void *EGLDisplay;\n\
         typedef void *EGLConfig;\n\
         typedef void *EGLSurface;\n\
         typedef void *EGLContext;\n\
         typedef void (*__eglMustCastToProperFunctionPointerType)(void);\n",
    ),
    (
        "EGL_VERSION_1_2",
        "typedef unsigned int EGLenum;\ntypedef void *EGLClientBuffer;\n",
    ),
    (
        "EGL_VERSION_1_5",
        "typedef void *EGLSync;\n\
         typedef khronos_intptr_t EGLAttrib;\n\
         typedef khronos_utime_nanoseconds_t EGLTime;\n\
         typedef void *EGLImage;\n",
    ),
];

/// The GL scalar types, as the Khronos `gl.h` defines them.
const GL_TYPES: &str = "\
typedef void GLvoid;
typedef char GLchar;
typedef unsigned int GLenum;
typedef unsigned char GLboolean;
typedef unsigned int GLbitfield;
typedef khronos_int8_t GLbyte;
typedef short GLshort;
typedef int GLint;
typedef int GLsizei;
typedef khronos_uint8_t GLubyte;
typedef unsigned short GLushort;
typedef unsigned int GLuint;
typedef khronos_float_t GLfloat;
typedef khronos_float_t GLclampf;
typedef khronos_int32_t GLfixed;
typedef khronos_int32_t GLclampx;
typedef khronos_intptr_t GLintptr;
typedef khronos_ssize_t GLsizeiptr;
";

fn main() {
    let root = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(env::var("OUT_DIR").expect("OUT_DIR"));

    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed={BLESS_VAR}");
    // Directories too, so that a new entry-point file triggers regeneration.
    for dir in [
        "src/gles/ffi",
        "src/egl",
        "src/gles/tokens.rs",
        "src/gles/tokens_ext.rs",
    ] {
        println!("cargo:rerun-if-changed={dir}");
    }

    link_options(&out);

    let mut gen = Generator::default();
    let headers = gen.generate(&root);
    let include_out = out.join("include");
    for (rel, text) in &headers {
        write_if_changed(&include_out.join(rel), text);
    }
    if env::var(BLESS_VAR).map(|v| v == "1").unwrap_or(false) {
        for (rel, text) in &headers {
            let dst = root.join("include").join(rel);
            if !write_if_changed(&dst, text) {
                println!("cargo:warning=could not write {}", dst.display());
            }
        }
    }

    // Lists for the tests and for eglGetProcAddress tables.
    let mut list = String::new();
    let mut inc =
        String::from("/* Generated by build.rs: one EP(name) per exported entry point. */\n");
    let mut gl_table = String::new();
    let mut egl_table = String::new();
    for ep in &gen.entry_points {
        let _ = writeln!(list, "{} {}", ep.header, ep.name);
        match ep.guard {
            Some(g) => {
                let _ = writeln!(inc, "#if defined({g})\nEP({})\n#endif", ep.name);
            }
            None => {
                let _ = writeln!(inc, "EP({})", ep.name);
            }
        }
        let table = if ep.name.starts_with("egl") {
            &mut egl_table
        } else {
            &mut gl_table
        };
        let _ = writeln!(table, "    {},", ep.name);
    }
    write_if_changed(&out.join("entry_points.txt"), &list);
    let mut declared_only = gen.declared_only.clone();
    declared_only.sort();
    declared_only.dedup();
    write_if_changed(
        &out.join("declared_only.txt"),
        &declared_only
            .iter()
            .map(|n| format!("{n}\n"))
            .collect::<String>(),
    );
    write_if_changed(&out.join("entry_points.inc"), &inc);
    write_if_changed(
        &out.join("gl_proc_table.rs"),
        &format!("proc_table![\n{gl_table}];\n"),
    );
    write_if_changed(
        &out.join("egl_proc_table.rs"),
        &format!("proc_table![\n{egl_table}];\n"),
    );

    for w in &gen.warnings {
        println!("cargo:warning={w}");
    }
}

/// The SONAME of the shared library: versioned, so that `ldconfig` manages the installed
/// names and a future incompatible ABI can be `.so.2` beside it.
const SONAME: &str = "libGLES_CM.so.1";

/// The SONAME, and a `libGLES_CM.so.1 -> libGLES_CM.so` link where cargo puts the library.
///
/// A program linked with `-lGLES_CM` against the build directory asks the dynamic loader for
/// the SONAME, so the build directories need that name too (cargo only writes
/// `libGLES_CM.so`): `target/<profile>` and `target/<profile>/deps` (where tests find the
/// library), three levels above `OUT_DIR`. The links may dangle until the library is linked.
///
/// No version script of our own: rustc already links a cdylib with one that exports exactly
/// the `#[no_mangle] pub extern` functions and makes everything else local, and a second
/// script could not hide a symbol rustc lists. So a stray `#[no_mangle]` function is caught
/// by `tests/symbols.rs`, not hidden here.
///
/// `-Bsymbolic-functions` binds the library's references to its own functions at link time.
/// Loaded as a glvnd vendor, the library shares the process with glvnd's `libEGL.so.1` and
/// `libGLESv1_CM.so.1`, which export the same `egl*`/`gl*` names and come first in the
/// lookup scope: without it, an address eglGetProcAddress (or glvnd's `getProcAddress`)
/// hands out could be glvnd's dispatching function of that name, which would call back into
/// us forever.
fn link_options(out: &Path) {
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{SONAME}");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-Bsymbolic-functions");
    let Some(profile) = out.ancestors().nth(3) else {
        return;
    };
    for dir in [profile.to_path_buf(), profile.join("deps")] {
        let link = dir.join(SONAME);
        if fs::read_link(&link).is_ok_and(|t| t == Path::new("libGLES_CM.so")) {
            continue;
        }
        let _ = fs::create_dir_all(&dir);
        let _ = fs::remove_file(&link);
        #[cfg(unix)]
        if let Err(e) = std::os::unix::fs::symlink("libGLES_CM.so", &link) {
            println!("cargo:warning=cannot link {}: {e}", link.display());
        }
    }
}

/// Writes `text` to `path` unless it already holds exactly that. Returns whether the file
/// holds `text` afterwards.
fn write_if_changed(path: &Path, text: &str) -> bool {
    if fs::read_to_string(path).map(|t| t == text).unwrap_or(false) {
        return true;
    }
    if let Some(dir) = path.parent() {
        let _ = fs::create_dir_all(dir);
    }
    fs::write(path, text).is_ok()
}

/// One C function as cbindgen printed it.
#[derive(Clone, Debug)]
struct Function {
    name: String,
    /// Return type, e.g. `void` or `const GLubyte *`.
    ret: String,
    /// Parameter list without parentheses, `void` when empty.
    args: String,
}

impl Function {
    /// `ret` followed by what comes next: a space unless it ends with `*`.
    fn ret_prefix(&self) -> String {
        if self.ret.ends_with('*') {
            self.ret.clone()
        } else {
            format!("{} ", self.ret)
        }
    }

    fn prototype(&self, api: &str, entry: &str) -> String {
        format!(
            "{api} {}{entry} {} ({});\n",
            self.ret_prefix(),
            self.name,
            self.args
        )
    }

    fn pfn(&self, entryp: &str) -> String {
        format!(
            "typedef {}({entryp} PFN{}PROC) ({});\n",
            self.ret_prefix(),
            self.name.to_ascii_uppercase(),
            self.args
        )
    }
}

/// A `pub const` of a token file.
#[derive(Clone, Debug)]
struct Token {
    name: String,
    ty: String,
    value: String,
}

/// A run of tokens under one `// Extension:` / `// Version:` marker (or the unnamed start).
#[derive(Clone, Debug, Default)]
struct Section {
    name: Option<String>,
    comment: Vec<String>,
    tokens: Vec<Token>,
}

/// One line of a `headers/*.txt` registry file.
#[derive(Clone, Debug)]
enum Item {
    Tok(Token),
    Type(String),
    Fn(Function),
    If(String),
    Endif,
}

/// An extension block of a registry file.
#[derive(Clone, Debug, Default)]
struct RegistryExt {
    name: String,
    items: Vec<Item>,
}

/// A registry file: the header's own tokens, then the extensions in registry order.
#[derive(Clone, Debug, Default)]
struct Registry {
    head: Vec<Token>,
    exts: Vec<RegistryExt>,
}

/// The declarations of one `if` group of an extension block (the unconditional part first).
#[derive(Default)]
struct Group {
    cond: Option<String>,
    types: Vec<String>,
    tokens: Vec<Token>,
    funcs: Vec<Function>,
}

struct EntryPoint {
    header: &'static str,
    name: String,
    /// Macro that must be defined for the prototype to be visible.
    guard: Option<&'static str>,
}

#[derive(Default)]
struct Generator {
    warnings: Vec<String>,
    entry_points: Vec<EntryPoint>,
    /// Functions the headers declare (from the registry) that the library does not export.
    declared_only: Vec<String>,
}

impl Generator {
    fn generate(&mut self, root: &Path) -> Vec<(&'static str, String)> {
        // Functions, by the file that defines them.
        let gl_files = rs_files(&root.join("src/gles/ffi"));
        let mut gl_core = BTreeMap::new();
        let mut gl_ext = BTreeMap::new();
        let mut ext_names = BTreeSet::new();
        for f in &gl_files {
            let is_ext = f.file_name().map(|n| n == "ext.rs").unwrap_or(false);
            for func in self.functions(f) {
                if !func.name.starts_with("gl") {
                    self.warnings.push(format!(
                        "{}: exported function {} does not start with gl; left out of the \
                         headers (tests/symbols.rs fails while it is exported)",
                        f.display(),
                        func.name
                    ));
                    continue;
                }
                if is_ext {
                    ext_names.insert(func.name.clone());
                    gl_ext.insert(func.name.clone(), func);
                } else {
                    gl_core.insert(func.name.clone(), func);
                }
            }
        }
        // cbindgen follows `mod x;` items, so ext.rs functions also show up under mod.rs.
        gl_core.retain(|n, _| !ext_names.contains(n));

        let mut egl_core = BTreeMap::new();
        let mut egl_ext = BTreeMap::new();
        // src/egl/ffi.rs and src/egl/ffi_ext.rs, or the files of a src/egl/ffi/ directory
        // (where ext.rs holds the extensions).
        let mut egl_files: Vec<(PathBuf, bool)> = [("ffi.rs", false), ("ffi_ext.rs", true)]
            .iter()
            .map(|(f, e)| (root.join("src/egl").join(f), *e))
            .filter(|(p, _)| p.exists())
            .collect();
        for p in rs_files(&root.join("src/egl/ffi")) {
            let is_ext = p.file_name().map(|n| n == "ext.rs").unwrap_or(false);
            egl_files.push((p, is_ext));
        }
        for (path, is_ext) in egl_files {
            for func in self.functions(&path) {
                if !func.name.starts_with("egl") {
                    self.warnings.push(format!(
                        "{}: exported function {} does not start with egl; left out of the \
                         headers (tests/symbols.rs fails while it is exported)",
                        path.display(),
                        func.name
                    ));
                    continue;
                }
                let map = if is_ext { &mut egl_ext } else { &mut egl_core };
                map.insert(func.name.clone(), func);
            }
        }
        egl_core.retain(|n, _| !egl_ext.contains_key(n));

        let gl_tokens = self.tokens(&root.join("src/gles/tokens.rs"));
        let gl_ext_tokens = self.tokens(&root.join("src/gles/tokens_ext.rs"));
        let egl_tokens = self.tokens(&root.join("src/egl/tokens.rs"));
        let egl_ext_path = root.join("src/egl/tokens_ext.rs");
        let egl_ext_tokens = if egl_ext_path.exists() {
            self.tokens(&egl_ext_path)
        } else {
            Vec::new()
        };

        let gl_registry = self.registry(&root.join("headers/glext.txt"));
        let egl_registry = self.registry(&root.join("headers/eglext.txt"));
        // Extensions of the core header (gl.h) keep their block there.
        let in_gl_h: BTreeSet<String> = gl_tokens.iter().filter_map(|s| s.name.clone()).collect();

        let gl_h = self.gl_h(&gl_tokens, gl_core, &mut gl_ext);
        let glext_h = self.glext_h(&gl_ext_tokens, gl_ext, &gl_registry, &in_gl_h);
        let egl_h = self.egl_h(&egl_tokens, egl_core, &mut egl_ext);
        let eglext_h = self.eglext_h(&egl_ext_tokens, egl_ext, &egl_registry);
        let eglplatform_h = self.eglplatform_h(root);

        vec![
            ("KHR/khrplatform.h", KHRPLATFORM_H.to_string()),
            ("GLES/glplatform.h", GLPLATFORM_H.to_string()),
            ("GLES/gl.h", gl_h),
            ("GLES/glext.h", glext_h),
            ("GLES/egl.h", LEGACY_EGL_H.to_string()),
            ("EGL/eglplatform.h", eglplatform_h),
            ("EGL/egl.h", egl_h),
            ("EGL/eglext.h", eglext_h),
        ]
    }

    /// The exported functions of one Rust file, through cbindgen.
    fn functions(&mut self, path: &Path) -> Vec<Function> {
        println!("cargo:rerun-if-changed={}", path.display());
        let Some(text) = self.cbindgen(path, false, &[]) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for line in text.lines() {
            let line = line.trim();
            if line.starts_with('#') || line.starts_with("//") || !line.ends_with(");") {
                continue;
            }
            match parse_function(line).or_else(|| parse_function_returning_pointer(line)) {
                Some(mut f) => {
                    // The standard header's spelling of eglGetProcAddress's return type.
                    if f.name == "eglGetProcAddress" {
                        f.ret = "__eglMustCastToProperFunctionPointerType".into();
                    }
                    out.push(f)
                }
                None => self.warnings.push(format!(
                    "{}: cannot turn `{line}` into a prototype; use plain C types \
                     (and __eglMustCastToProperFunctionPointerType for function pointers)",
                    path.display()
                )),
            }
        }
        out
    }

    /// cbindgen's C output for one file, or `None` (with a warning) when it fails.
    fn cbindgen(&mut self, path: &Path, docs: bool, types: &[&str]) -> Option<String> {
        let mut config = cbindgen::Config {
            language: cbindgen::Language::C,
            no_includes: true,
            documentation: docs,
            line_length: 10_000,
            style: cbindgen::Style::Both,
            ..Default::default()
        };
        config.function.args = cbindgen::Layout::Horizontal;
        config.function.sort_by = Some(cbindgen::SortKey::Name);
        config.constant.sort_by = Some(cbindgen::SortKey::None);
        // Types no function of the file mentions are only emitted on request.
        config.export.include = types.iter().map(|t| t.to_string()).collect();
        match cbindgen::Builder::new()
            .with_config(config)
            .with_src(path)
            .generate()
        {
            Ok(bindings) => {
                let mut buf = Vec::new();
                bindings.write(&mut buf);
                Some(String::from_utf8_lossy(&buf).into_owned())
            }
            Err(e) => {
                self.warnings
                    .push(format!("cbindgen failed on {}: {e}", path.display()));
                None
            }
        }
    }

    /// A `headers/*.txt` registry file (its format is described at its top).
    fn registry(&mut self, path: &Path) -> Registry {
        println!("cargo:rerun-if-changed={}", path.display());
        let Ok(text) = fs::read_to_string(path) else {
            self.warnings
                .push(format!("cannot read {}", path.display()));
            return Registry::default();
        };
        let mut r = Registry::default();
        for (n, line) in text.lines().enumerate() {
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let (kind, rest) = line.split_once(' ').unwrap_or((line, ""));
            let item = match kind {
                "ext" => {
                    r.exts.push(RegistryExt {
                        name: rest.to_string(),
                        items: Vec::new(),
                    });
                    continue;
                }
                "tok" => rest.split_once(' ').map(|(name, value)| {
                    Item::Tok(Token {
                        name: name.to_string(),
                        ty: C_VALUE.to_string(),
                        value: value.to_string(),
                    })
                }),
                "type" => Some(Item::Type(rest.to_string())),
                "fn" => {
                    let parts: Vec<&str> = rest.split('|').collect();
                    match parts.as_slice() {
                        [ret, name, args] => Some(Item::Fn(Function {
                            name: name.to_string(),
                            ret: ret.to_string(),
                            args: if args.is_empty() { "void" } else { args }.to_string(),
                        })),
                        _ => None,
                    }
                }
                "if" => Some(Item::If(rest.to_string())),
                "endif" => Some(Item::Endif),
                _ => None,
            };
            match (item, r.exts.last_mut()) {
                (Some(Item::Tok(t)), None) => r.head.push(t),
                (Some(i), Some(e)) => e.items.push(i),
                _ => self.warnings.push(format!(
                    "{}:{}: cannot read `{line}`",
                    path.display(),
                    n + 1
                )),
            }
        }
        r
    }

    /// The sections of a token file.
    fn tokens(&mut self, path: &Path) -> Vec<Section> {
        println!("cargo:rerun-if-changed={}", path.display());
        let Ok(text) = fs::read_to_string(path) else {
            self.warnings
                .push(format!("cannot read {}", path.display()));
            return Vec::new();
        };
        let mut sections = vec![Section::default()];
        let mut in_header_comment = false;
        for raw in text.lines() {
            let line = raw.trim();
            let marker = line
                .strip_prefix("// Extension:")
                .or_else(|| line.strip_prefix("// Version:"));
            if let Some(name) = marker {
                sections.push(Section {
                    name: Some(name.trim().to_string()),
                    ..Default::default()
                });
                in_header_comment = true;
                continue;
            }
            if in_header_comment {
                if let Some(c) = line.strip_prefix("//") {
                    if !line.starts_with("//!") {
                        sections
                            .last_mut()
                            .unwrap()
                            .comment
                            .push(c.trim().to_string());
                        continue;
                    }
                }
                in_header_comment = false;
            }
            let Some(rest) = line.strip_prefix("pub const ") else {
                continue;
            };
            match parse_const(rest) {
                Some(t) => sections.last_mut().unwrap().tokens.push(t),
                None => self.warnings.push(format!(
                    "{}: cannot read token line `{line}`",
                    path.display()
                )),
            }
        }
        sections.retain(|s| s.name.is_some() || !s.tokens.is_empty());
        sections
    }

    fn gl_h(
        &mut self,
        sections: &[Section],
        core: BTreeMap<String, Function>,
        ext: &mut BTreeMap<String, Function>,
    ) -> String {
        let mut core = core;
        let mut h = String::new();
        h += &preamble("GLES/gl.h", "OpenGL ES 1.1 Common profile");
        h += "#ifndef __gles1_gl_h_\n#define __gles1_gl_h_ 1\n\n";
        h += "#include <GLES/glplatform.h>\n\n";
        h += CPP_OPEN;
        h += "#ifndef GL_APIENTRYP\n#define GL_APIENTRYP GL_APIENTRY*\n#endif\n\n";

        let core_section = Section {
            name: Some("GL_VERSION_ES_CM_1_0".into()),
            ..Default::default()
        };
        let mut sections = sections.to_vec();
        if sections.first().map(|s| s.name.is_none()).unwrap_or(false) {
            sections[0].name = core_section.name.clone();
        } else {
            sections.insert(0, core_section);
        }
        for (i, s) in sections.iter().enumerate() {
            let name = s.name.as_deref().unwrap();
            h += &block_open(name, &s.comment);
            if i == 0 {
                h += "#include <KHR/khrplatform.h>\n";
                h += GL_TYPES;
            }
            h += &defines(&s.tokens, name);
            // Functions of this block: the core ones, or the listed extension functions.
            let funcs: Vec<Function> = if i == 0 {
                // Functions the table assigns to an extension are declared in its block.
                let rest: Vec<String> = core
                    .keys()
                    .filter(|n| extension_of(GL_EXTENSION_FUNCTIONS, n).is_none())
                    .cloned()
                    .collect();
                rest.iter().filter_map(|n| core.remove(n)).collect()
            } else {
                take_listed(GL_EXTENSION_FUNCTIONS, name, &mut [&mut core, ext])
            };
            for f in &funcs {
                h += &f.prototype("GL_API", "GL_APIENTRY");
                self.entry("GLES/gl.h", &f.name, None);
            }
            h += &format!("#endif /* {name} */\n\n");
        }
        // Core-file functions that belong to an extension of glext.h are declared there.
        ext.append(&mut core);
        h += CPP_CLOSE;
        h += "#endif /* __gles1_gl_h_ */\n";
        h
    }

    fn glext_h(
        &mut self,
        sections: &[Section],
        ext: BTreeMap<String, Function>,
        registry: &Registry,
        in_gl_h: &BTreeSet<String>,
    ) -> String {
        let mut h = String::new();
        h += &preamble("GLES/glext.h", "OpenGL ES 1.x extensions");
        h += "#ifndef __gles1_glext_h_\n#define __gles1_glext_h_ 1\n\n";
        h += "#include <GLES/gl.h>\n\n";
        h += CPP_OPEN;
        h += "#ifndef GL_APIENTRYP\n#define GL_APIENTRYP GL_APIENTRY*\n#endif\n\n";
        h += "/* Extension prototypes are declared when GL_GLEXT_PROTOTYPES is defined;\n";
        h += " * the PFN...PROC pointer types always are. */\n\n";
        h += &self.extension_blocks(
            "GLES/glext.h",
            sections,
            registry,
            in_gl_h,
            GL_EXTENSION_FUNCTIONS,
            ext,
            ("GL_API", "GL_APIENTRY", "GL_APIENTRYP"),
            "GL_GLEXT_PROTOTYPES",
            "is not listed under any extension in build.rs",
        );
        h += CPP_CLOSE;
        h += "#endif /* __gles1_glext_h_ */\n";
        h
    }

    fn egl_h(
        &mut self,
        sections: &[Section],
        mut core: BTreeMap<String, Function>,
        ext: &mut BTreeMap<String, Function>,
    ) -> String {
        let mut h = String::new();
        h += &preamble("EGL/egl.h", "EGL 1.5");
        h += "#ifndef __egl_h_\n#define __egl_h_ 1\n\n";
        h += "#include <EGL/eglplatform.h>\n\n";
        h += CPP_OPEN;
        h += "#ifndef EGL_EGL_PROTOTYPES\n#define EGL_EGL_PROTOTYPES 1\n#endif\n\n";
        let mut sections: Vec<Section> = sections
            .iter()
            .filter(|s| s.name.is_some())
            .cloned()
            .collect();
        for (v, _) in EGL_VERSION_FUNCTIONS {
            if !sections.iter().any(|s| s.name.as_deref() == Some(v)) {
                sections.push(Section {
                    name: Some(v.to_string()),
                    ..Default::default()
                });
            }
        }
        for s in &sections {
            let name = s.name.as_deref().unwrap();
            h += &block_open(name, &s.comment);
            if let Some((_, types)) = EGL_VERSION_TYPES.iter().find(|(v, _)| *v == name) {
                h += types;
            }
            h += &defines(&s.tokens, name);
            let funcs = take_listed(EGL_VERSION_FUNCTIONS, name, &mut [&mut core]);
            h += &self.pfn_and_prototypes(
                "EGL/egl.h",
                &funcs,
                ("EGLAPI", "EGLAPIENTRY", "EGLAPIENTRYP"),
                "EGL_EGL_PROTOTYPES",
            );
            h += &format!("#endif /* {name} */\n\n");
        }
        // Anything else in ffi.rs is not core EGL: it goes to eglext.h.
        ext.append(&mut core);
        h += CPP_CLOSE;
        h += "#endif /* __egl_h_ */\n";
        h
    }

    fn eglext_h(
        &mut self,
        sections: &[Section],
        ext: BTreeMap<String, Function>,
        registry: &Registry,
    ) -> String {
        let mut h = String::new();
        h += &preamble("EGL/eglext.h", "EGL extensions");
        h += "#ifndef __eglext_h_\n#define __eglext_h_ 1\n\n";
        h += "#include <EGL/egl.h>\n\n";
        h += CPP_OPEN;
        h += "/* Extension prototypes are declared when EGL_EGLEXT_PROTOTYPES is defined;\n";
        h += " * the PFN...PROC pointer types always are. */\n\n";
        h += &defines(&registry.head, "");
        h += EGL_ATTRIB_TYPE;
        h += &self.extension_blocks(
            "EGL/eglext.h",
            sections,
            registry,
            &BTreeSet::new(),
            EGL_EXTENSION_FUNCTIONS,
            ext,
            ("EGLAPI", "EGLAPIENTRY", "EGLAPIENTRYP"),
            "EGL_EGLEXT_PROTOTYPES",
            "is neither core EGL nor listed under an EGL extension in build.rs",
        );
        h += CPP_CLOSE;
        h += "#endif /* __eglext_h_ */\n";
        h
    }

    /// One `#ifndef NAME` block per extension (its tokens, then its functions' pointer types
    /// and prototypes under `guard`), including extensions that have functions but no token
    /// section, then a block for the functions `table` lists under no extension.
    ///
    /// The registry's extensions come first, in its order, each with the tokens and exported
    /// functions of ours that belong to it; then our extensions the registry does not have.
    #[allow(clippy::too_many_arguments)]
    fn extension_blocks(
        &mut self,
        header: &'static str,
        sections: &[Section],
        registry: &Registry,
        skip: &BTreeSet<String>,
        table: &[(&str, &[&str])],
        mut ext: BTreeMap<String, Function>,
        decor: (&str, &str, &str),
        guard: &'static str,
        unlisted: &str,
    ) -> String {
        let mut h = String::new();
        let mut sections: Vec<Section> = sections
            .iter()
            .filter(|s| s.name.is_some())
            .cloned()
            .collect();
        for r in registry.exts.iter().filter(|r| !skip.contains(&r.name)) {
            let ours = sections
                .iter()
                .position(|s| s.name.as_deref() == Some(&r.name))
                .map(|i| sections.remove(i))
                .unwrap_or_default();
            let mut exported: BTreeMap<String, Function> =
                take_listed(table, &r.name, &mut [&mut ext])
                    .into_iter()
                    .map(|f| (f.name.clone(), f))
                    .collect();
            // Exported functions the table does not assign: found by the registry's name.
            for item in &r.items {
                if let Item::Fn(f) = item {
                    if let Some(mine) = ext.remove(&f.name) {
                        exported.insert(f.name.clone(), mine);
                    }
                }
            }
            let mut groups = vec![Group::default()];
            for item in &r.items {
                match item {
                    Item::If(m) => groups.push(Group {
                        cond: Some(m.clone()),
                        ..Default::default()
                    }),
                    Item::Endif => groups.push(Group::default()),
                    Item::Tok(t) => groups.last_mut().unwrap().tokens.push(t.clone()),
                    Item::Type(t) => groups.last_mut().unwrap().types.push(t.clone()),
                    Item::Fn(f) => groups.last_mut().unwrap().funcs.push(f.clone()),
                }
            }
            // Our tokens the registry does not list (aliases of ours), and exported functions
            // it does not name, go with its unconditional part.
            let named: BTreeSet<&str> = r
                .items
                .iter()
                .filter_map(|i| match i {
                    Item::Tok(t) => Some(t.name.as_str()),
                    _ => None,
                })
                .collect();
            let extra: Vec<Token> = ours
                .tokens
                .iter()
                .filter(|t| !named.contains(t.name.as_str()))
                .cloned()
                .collect();
            groups[0].tokens.extend(extra);
            h += &block_open(&r.name, &ours.comment);
            let registry_fns: BTreeSet<String> = groups
                .iter()
                .flat_map(|g| g.funcs.iter().map(|f| f.name.clone()))
                .collect();
            let unnamed: Vec<String> = exported
                .keys()
                .filter(|n| !registry_fns.contains(*n))
                .cloned()
                .collect();
            for n in unnamed {
                groups[0].funcs.push(exported[&n].clone());
            }
            for g in groups {
                if g.types.is_empty() && g.tokens.is_empty() && g.funcs.is_empty() {
                    if let Some(c) = &g.cond {
                        // Kept, empty, as the registry has it.
                        h += &format!("#ifdef {c}\n#endif /* {c} */\n");
                    }
                    continue;
                }
                if let Some(c) = &g.cond {
                    h += &format!("#ifdef {c}\n");
                }
                for t in &g.types {
                    h += t;
                    h += "\n";
                }
                h += &defines(&g.tokens, &r.name);
                // (function, exported by us): ours where we export it, else the registry's.
                let funcs: Vec<(Function, bool)> = g
                    .funcs
                    .into_iter()
                    .map(|f| match exported.remove(&f.name) {
                        Some(mine) => (mine, true),
                        None => (f, false),
                    })
                    .collect();
                h += &self.mixed_prototypes(header, &funcs, decor, guard);
                if let Some(c) = &g.cond {
                    h += &format!("#endif /* {c} */\n");
                }
            }
            h += &format!("#endif /* {} */\n\n", r.name);
        }
        for (e, _) in table {
            if !sections.iter().any(|s| s.name.as_deref() == Some(e))
                && ext.keys().any(|n| extension_of(table, n) == Some(e))
            {
                sections.push(Section {
                    name: Some(e.to_string()),
                    ..Default::default()
                });
            }
        }
        for s in &sections {
            let name = s.name.as_deref().unwrap();
            let funcs = take_listed(table, name, &mut [&mut ext]);
            h += &block_open(name, &s.comment);
            h += &defines(&s.tokens, name);
            h += &self.pfn_and_prototypes(header, &funcs, decor, guard);
            h += &format!("#endif /* {name} */\n\n");
        }
        if !ext.is_empty() {
            let funcs: Vec<Function> = ext.into_values().collect();
            for f in &funcs {
                self.warnings.push(format!(
                    "{} {unlisted}; declared in {header}'s block of further entry points",
                    f.name
                ));
            }
            h += "/* Further entry points of this library. */\n";
            h += &self.pfn_and_prototypes(header, &funcs, decor, guard);
            h += "\n";
        }
        h
    }

    fn pfn_and_prototypes(
        &mut self,
        header: &'static str,
        funcs: &[Function],
        (api, entry, entryp): (&str, &str, &str),
        guard: &'static str,
    ) -> String {
        if funcs.is_empty() {
            return String::new();
        }
        let mut h = String::new();
        for f in funcs {
            h += &f.pfn(entryp);
        }
        if guard == "EGL_EGL_PROTOTYPES" {
            h += "#if EGL_EGL_PROTOTYPES\n";
        } else {
            h += &format!("#ifdef {guard}\n");
        }
        for f in funcs {
            h += &f.prototype(api, entry);
            let g = if guard == "EGL_EGL_PROTOTYPES" {
                None
            } else {
                Some(guard)
            };
            self.entry(header, &f.name, g);
        }
        h += "#endif\n";
        h
    }

    /// Pointer types and prototypes of a registry group: the ones the library exports are
    /// entry points, the others are declared (and said to be missing) only.
    fn mixed_prototypes(
        &mut self,
        header: &'static str,
        funcs: &[(Function, bool)],
        (api, entry, entryp): (&str, &str, &str),
        guard: &'static str,
    ) -> String {
        if funcs.is_empty() {
            return String::new();
        }
        let mut h = String::new();
        let missing: Vec<&str> = funcs
            .iter()
            .filter(|(_, ours)| !ours)
            .map(|(f, _)| f.name.as_str())
            .collect();
        if !missing.is_empty() {
            h += &format!(
                "/* Not provided by libGLES_CM: {}. */\n",
                missing.join(", ")
            );
        }
        for (f, _) in funcs {
            h += &f.pfn(entryp);
        }
        h += &format!("#ifdef {guard}\n");
        for (f, ours) in funcs {
            h += &f.prototype(api, entry);
            if *ours {
                self.entry(header, &f.name, Some(guard));
            } else {
                self.declared_only.push(f.name.clone());
            }
        }
        h += "#endif\n";
        h
    }

    fn entry(&mut self, header: &'static str, name: &str, guard: Option<&'static str>) {
        self.entry_points.push(EntryPoint {
            header,
            name: name.to_string(),
            guard,
        });
    }

    fn eglplatform_h(&mut self, root: &Path) -> String {
        let mut h = String::new();
        h += &preamble("EGL/eglplatform.h", "EGL platform types");
        h += EGLPLATFORM_H_HEAD;
        let native = root.join("src/egl/native.rs");
        println!("cargo:rerun-if-changed=src/egl/native.rs");
        let body = if native.exists() {
            self.cbindgen(&native, true, &["EGLMemoryPixmap", "EGLMemoryWindow"])
        } else {
            None
        };
        match body {
            Some(body) => {
                h +=
                    "/* The native pixmap and window of this implementation: client memory. */\n\n";
                let body = body.trim();
                h += body;
                h += "\n\n";
            }
            None => {
                h += "struct EGLMemoryPixmap;\nstruct EGLMemoryWindow;\n\n";
            }
        }
        h += EGLPLATFORM_H_TAIL;
        h
    }
}

/// The files `*.rs` of a directory, sorted.
fn rs_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().map(|x| x == "rs").unwrap_or(false))
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

fn extension_of<'a>(table: &'a [(&'a str, &'a [&'a str])], func: &str) -> Option<&'a str> {
    table
        .iter()
        .find(|(_, fs)| fs.contains(&func))
        .map(|(e, _)| *e)
}

/// Removes from `maps` the functions `table` lists under `block`, in table order.
fn take_listed(
    table: &[(&str, &[&str])],
    block: &str,
    maps: &mut [&mut BTreeMap<String, Function>],
) -> Vec<Function> {
    let mut out = Vec::new();
    let Some((_, names)) = table.iter().find(|(e, _)| *e == block) else {
        return out;
    };
    let mut names: Vec<&str> = names.to_vec();
    names.sort_unstable();
    for n in names {
        for m in maps.iter_mut() {
            if let Some(f) = m.remove(n) {
                out.push(f);
                break;
            }
        }
    }
    out
}

/// Splits `ret name(args);` as cbindgen prints a function.
fn parse_function(line: &str) -> Option<Function> {
    let line = line.strip_suffix(';')?;
    let open = line.find('(')?;
    let head = &line[..open];
    let name_start = head.rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))? + 1;
    let name = &head[name_start..];
    let ret = head[..name_start].trim();
    let args = line[open + 1..].strip_suffix(')')?.trim();
    if name.is_empty() || ret.is_empty() || args.contains('(') {
        return None;
    }
    let args = if args.is_empty() { "void" } else { args };
    Some(Function {
        name: name.into(),
        ret: ret.into(),
        args: args.into(),
    })
}

/// Reads `ret (*name(args))(fn_args);`, cbindgen's form of a function returning a function
/// pointer; only eglGetProcAddress may do that (its return type is then replaced).
fn parse_function_returning_pointer(line: &str) -> Option<Function> {
    let rest = line.strip_suffix(';')?;
    let (_, rest) = rest.split_once("(*")?;
    let open = rest.find('(')?;
    let name = &rest[..open];
    let args_end = rest.find("))")?;
    let args = rest[open + 1..args_end].trim();
    if name != "eglGetProcAddress" || args.contains('(') {
        return None;
    }
    let args = if args.is_empty() { "void" } else { args };
    Some(Function {
        name: name.into(),
        ret: String::new(),
        args: args.into(),
    })
}

/// Reads `NAME: TYPE = VALUE;`.
fn parse_const(rest: &str) -> Option<Token> {
    let (name, rest) = rest.split_once(':')?;
    let (ty, value) = rest.split_once('=')?;
    let value = value.trim().strip_suffix(';')?.trim();
    Some(Token {
        name: name.trim().into(),
        ty: ty.trim().into(),
        value: value.into(),
    })
}

/// The C spelling of a token's value.
fn c_value(t: &Token) -> Option<String> {
    if t.value.ends_with("null_mut()") || t.value.ends_with("null()") {
        return Some(format!("EGL_CAST({},0)", t.ty));
    }
    let v = t.value.replace('_', "");
    let is_egl = t.name.starts_with("EGL_");
    // Strip a type suffix such as `u32`.
    let v = v.as_str();
    let digits = [
        "u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64", "usize", "isize",
    ]
    .iter()
    .find_map(|s| {
        v.strip_suffix(s)
            .filter(|d| !d.ends_with("0x") && !d.is_empty())
    })
    .unwrap_or(v);
    let (neg, mag) = match digits.strip_prefix('-') {
        Some(m) => (true, m.trim()),
        None => (false, digits),
    };
    let ok = if let Some(hex) = mag.strip_prefix("0x").or_else(|| mag.strip_prefix("0X")) {
        !hex.is_empty() && hex.chars().all(|c| c.is_ascii_hexdigit())
    } else {
        !mag.is_empty() && mag.chars().all(|c| c.is_ascii_digit())
    };
    if !ok {
        return None;
    }
    Some(match (neg, is_egl) {
        // EGLTime values are 64-bit (EGL_FOREVER), spelt as the standard header does.
        (false, _) if t.ty == "EGLTime" => format!("{mag}ull"),
        (false, _) => mag.to_string(),
        (true, true) => format!("EGL_CAST({},-{mag})", t.ty),
        (true, false) => format!("(-{mag})"),
    })
}

/// `#define`s of a section's tokens (the section's own name is its block guard).
fn defines(tokens: &[Token], block: &str) -> String {
    let mut s = String::new();
    for t in tokens {
        if t.name == block {
            continue;
        }
        let value = if t.ty == C_VALUE {
            t.value.clone()
        } else {
            c_value(t).unwrap_or_else(|| format!("({})", t.value))
        };
        let _ = writeln!(s, "#define {:<33} {}", t.name, value);
    }
    s
}

fn block_open(name: &str, comment: &[String]) -> String {
    let mut s = format!("#ifndef {name}\n#define {name} 1\n");
    if !comment.is_empty() {
        let _ = writeln!(s, "/* {} */", comment.join(" ").replace("*/", "* /"));
    }
    s
}

fn preamble(file: &str, what: &str) -> String {
    format!(
        "/*\n * {file}: {what} for libGLES_CM.\n *\n\
         \x20* Generated by build.rs from the Rust sources (entry points in src/gles/ffi and\n\
         \x20* src/egl, tokens in the tokens*.rs files); do not edit. To regenerate:\n\
         \x20*     GLES_CM_BLESS_HEADERS=1 cargo build\n\
         \x20* Token values are those of the Khronos API registry.\n */\n\n"
    )
}

/// The `ty` of a registry token: its value is written as C already.
const C_VALUE: &str = "C";

/// EGL 1.5's types, which EGL extensions (EGL_KHR_debug, EGL_EXT_device_query,
/// EGL_NV_stream_consumer_eglimage, ...) use; `egl.h` declares them in its EGL 1.5 block once
/// the library has EGL 1.5.
const EGL_ATTRIB_TYPE: &str = "\
#ifndef EGL_VERSION_1_5
typedef void *EGLSync;
typedef khronos_intptr_t EGLAttrib;
typedef khronos_utime_nanoseconds_t EGLTime;
typedef void *EGLImage;
#endif

";

/// `GLES/egl.h`: early OpenGL ES 1.0 programs include only this header for both APIs.
const LEGACY_EGL_H: &str = "\
/*
 * GLES/egl.h: for OpenGL ES 1.0 programs that include only this header, EGL and GL together.
 *
 * Generated by build.rs; do not edit.
 */

#ifndef __legacy_egl_h_
#define __legacy_egl_h_

#include <EGL/egl.h>
#include <GLES/gl.h>

#endif /* __legacy_egl_h_ */
";

const CPP_OPEN: &str = "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n";
const CPP_CLOSE: &str = "#ifdef __cplusplus\n}\n#endif\n\n";

const KHRPLATFORM_H: &str = r#"/*
 * KHR/khrplatform.h: platform types and calling conventions shared by the Khronos APIs,
 * for libGLES_CM.
 *
 * Generated by build.rs; do not edit. To regenerate:
 *     GLES_CM_BLESS_HEADERS=1 cargo build
 */

#ifndef __khrplatform_h_
#define __khrplatform_h_

/*
 * KHRONOS_APICALL comes before the return type of every API function and
 * KHRONOS_APIENTRY between the return type and the name; KHRONOS_APIATTRIBUTES
 * follows the parameter list. The library exports its functions with default
 * visibility, and uses the platform's C calling convention.
 */
#ifndef KHRONOS_APICALL
#  if defined(_WIN32)
#    define KHRONOS_APICALL __declspec(dllimport)
#  elif defined(__GNUC__) && __GNUC__ >= 4
#    define KHRONOS_APICALL __attribute__((visibility("default")))
#  else
#    define KHRONOS_APICALL
#  endif
#endif

#ifndef KHRONOS_APIENTRY
#  if defined(_WIN32)
#    define KHRONOS_APIENTRY __stdcall
#  else
#    define KHRONOS_APIENTRY
#  endif
#endif

#ifndef KHRONOS_APIATTRIBUTES
#  define KHRONOS_APIATTRIBUTES
#endif

/* Fixed-size integer types: from <stdint.h> where the compiler has it. */
#if (defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L) || defined(__GNUC__) \
    || defined(__cplusplus)
#include <stdint.h>
typedef int32_t                 khronos_int32_t;
typedef uint32_t                khronos_uint32_t;
typedef int64_t                 khronos_int64_t;
typedef uint64_t                khronos_uint64_t;
#define KHRONOS_SUPPORT_INT64   1
#define KHRONOS_SUPPORT_FLOAT   1
#elif defined(_WIN32)
typedef __int32                 khronos_int32_t;
typedef unsigned __int32        khronos_uint32_t;
typedef __int64                 khronos_int64_t;
typedef unsigned __int64        khronos_uint64_t;
#define KHRONOS_SUPPORT_INT64   1
#define KHRONOS_SUPPORT_FLOAT   1
#else
typedef int                     khronos_int32_t;
typedef unsigned int            khronos_uint32_t;
typedef long long int           khronos_int64_t;
typedef unsigned long long int  khronos_uint64_t;
#define KHRONOS_SUPPORT_INT64   1
#define KHRONOS_SUPPORT_FLOAT   1
#endif

typedef signed char             khronos_int8_t;
typedef unsigned char           khronos_uint8_t;
typedef signed short int        khronos_int16_t;
typedef unsigned short int      khronos_uint16_t;

/* Pointer-sized integers: long long on 64-bit Windows, long everywhere else. */
#ifdef KHRONOS_USE_INTPTR_T
typedef intptr_t                khronos_intptr_t;
typedef uintptr_t               khronos_uintptr_t;
#elif defined(_WIN64)
typedef signed   long long int  khronos_intptr_t;
typedef unsigned long long int  khronos_uintptr_t;
#else
typedef signed   long  int      khronos_intptr_t;
typedef unsigned long  int      khronos_uintptr_t;
#endif

#if defined(_WIN64)
typedef signed   long long int  khronos_ssize_t;
typedef unsigned long long int  khronos_usize_t;
#else
typedef signed   long  int      khronos_ssize_t;
typedef unsigned long  int      khronos_usize_t;
#endif

#if KHRONOS_SUPPORT_FLOAT
typedef          float          khronos_float_t;
#endif

#if KHRONOS_SUPPORT_INT64
/* Times in nanoseconds, unsigned (absolute) and signed (differences). */
typedef khronos_uint64_t        khronos_utime_nanoseconds_t;
typedef khronos_int64_t         khronos_stime_nanoseconds_t;
#endif

/* Forces enums to 32 bits. */
#ifndef KHRONOS_MAX_ENUM
#define KHRONOS_MAX_ENUM 0x7FFFFFFF
#endif

typedef enum {
    KHRONOS_FALSE = 0,
    KHRONOS_TRUE  = 1,
    KHRONOS_BOOLEAN_ENUM_FORCE_SIZE = KHRONOS_MAX_ENUM
} khronos_boolean_enum_t;

#endif /* __khrplatform_h_ */
"#;

const GLPLATFORM_H: &str = r#"/*
 * GLES/glplatform.h: calling conventions of the OpenGL ES 1.x API, for libGLES_CM.
 *
 * Generated by build.rs; do not edit. To regenerate:
 *     GLES_CM_BLESS_HEADERS=1 cargo build
 */

#ifndef __glplatform_h_
#define __glplatform_h_

#include <KHR/khrplatform.h>

/* GL_API comes before the return type of every function, GL_APIENTRY before its name. */
#ifndef GL_API
#define GL_API      KHRONOS_APICALL
#endif

#ifndef GL_APIENTRY
#define GL_APIENTRY KHRONOS_APIENTRY
#endif

#endif /* __glplatform_h_ */
"#;

const EGLPLATFORM_H_HEAD: &str = r#"#ifndef __eglplatform_h_
#define __eglplatform_h_

#include <KHR/khrplatform.h>

/* EGLAPI comes before the return type of every function, EGLAPIENTRY before its name. */
#ifndef EGLAPI
#define EGLAPI KHRONOS_APICALL
#endif

#ifndef EGLAPIENTRY
#define EGLAPIENTRY  KHRONOS_APIENTRY
#endif
#define EGLAPIENTRYP EGLAPIENTRY*

#ifdef __cplusplus
extern "C" {
#endif

"#;

const EGLPLATFORM_H_TAIL: &str = r#"/*
 * The native types of this EGL: there is no window system. A display is any value
 * (use EGL_DEFAULT_DISPLAY); pixmaps and windows are blocks of client memory
 * described by the structs above.
 */
typedef void *EGLNativeDisplayType;
typedef struct EGLMemoryPixmap *EGLNativePixmapType;
typedef struct EGLMemoryWindow *EGLNativeWindowType;

/* The EGL 1.0 names of the native types. */
typedef EGLNativeDisplayType NativeDisplayType;
typedef EGLNativePixmapType  NativePixmapType;
typedef EGLNativeWindowType  NativeWindowType;

/* EGLint is 32 bits on every platform. */
typedef khronos_int32_t EGLint;

#ifdef __cplusplus
}
#endif

/* Casts in token values (EGL_NO_CONTEXT, EGL_DONT_CARE, ...) that compile cleanly as C++. */
#if defined(__cplusplus)
#define EGL_CAST(type, value) (static_cast<type>(value))
#else
#define EGL_CAST(type, value) ((type) (value))
#endif

#endif /* __eglplatform_h_ */
"#;
