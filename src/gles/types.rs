//! The GL scalar types, as the Khronos headers define them for this platform. cbindgen turns
//! these aliases into the typedefs that prototypes in `include/GLES` use.
#![forbid(unsafe_code)]

use libc::{c_char, c_float, c_int, c_short, c_uchar, c_uint, c_ushort, c_void};

pub type GLvoid = c_void;
/// `OES_EGL_image`: an EGLImage handle as the GL takes it.
pub type GLeglImageOES = *mut c_void;
pub type GLchar = c_char;
pub type GLenum = c_uint;
pub type GLboolean = c_uchar;
pub type GLbitfield = c_uint;
pub type GLbyte = i8;
pub type GLshort = c_short;
pub type GLint = c_int;
pub type GLsizei = c_int;
pub type GLubyte = c_uchar;
pub type GLushort = c_ushort;
pub type GLuint = c_uint;
pub type GLfloat = c_float;
pub type GLclampf = c_float;
pub type GLfixed = i32;
pub type GLclampx = i32;
pub type GLintptr = isize;
pub type GLsizeiptr = isize;
