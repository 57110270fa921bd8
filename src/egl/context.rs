//! EGL rendering contexts: an OpenGL ES 1.x [`gles::Context`](crate::gles::Context) with the
//! config it was created for.
#![forbid(unsafe_code)]

use std::sync::{Arc, Mutex};

use crate::gles::current::{self, SharedContext};

use super::config::Config;
use super::tokens::*;
use super::types::EGLint;

pub struct Context {
    /// Handle value (never reused).
    pub id: usize,
    pub config: &'static Config,
    pub client_version: EGLint,
    /// Created as a debug context.
    pub debug: bool,
    pub gl: SharedContext,
}

/// What eglCreateContext's attributes ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Request {
    pub client_version: EGLint,
    /// A debug context (EGL 1.5's `EGL_CONTEXT_OPENGL_DEBUG`, EGL_KHR_create_context's
    /// debug flag): `GL_KHR_debug` output starts enabled.
    pub debug: bool,
}

/// Parses eglCreateContext's attribute list (EGL 1.5 §3.7.1 with EGL_KHR_create_context's
/// names). Major version 1 (minor 0 or 1) is what there is; major version 2 or more names a
/// client API no config supports, which §3.7.1 makes EGL_BAD_CONFIG, as is robust access
/// (buffer robustness is not offered); a minor version past 1 is EGL_BAD_MATCH. Attributes
/// that exist only for desktop OpenGL (profiles, forward compatibility, the reset
/// strategy, the KHR flags but debug) and unknown ones are EGL_BAD_ATTRIBUTE.
pub fn parse_attribs(pairs: &[(EGLint, EGLint)]) -> Result<Request, EGLint> {
    let (mut major, mut minor, mut debug) = (1, 0, false);
    let boolean = |v: EGLint| match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(EGL_BAD_ATTRIBUTE),
    };
    for &(attr, value) in pairs {
        match attr {
            // EGL_CONTEXT_CLIENT_VERSION and EGL_CONTEXT_MAJOR_VERSION are one token.
            EGL_CONTEXT_MAJOR_VERSION => major = value,
            EGL_CONTEXT_MINOR_VERSION => minor = value,
            EGL_CONTEXT_OPENGL_DEBUG => debug = boolean(value)?,
            EGL_CONTEXT_OPENGL_ROBUST_ACCESS => {
                if boolean(value)? {
                    return Err(EGL_BAD_CONFIG);
                }
            }
            EGL_CONTEXT_FLAGS_KHR => {
                if value & !EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR != 0 {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                debug = value & EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR != 0;
            }
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
    }
    match (major, minor) {
        (1, 0 | 1) => Ok(Request {
            client_version: 1,
            debug,
        }),
        (1, _) => Err(EGL_BAD_MATCH),
        (m, _) if m >= 2 => Err(EGL_BAD_CONFIG),
        _ => Err(EGL_BAD_ATTRIBUTE),
    }
}

/// EGL_KHR_create_context's flags attribute and its debug bit (the other bits are desktop
/// OpenGL's).
pub const EGL_CONTEXT_FLAGS_KHR: EGLint = 0x30FC;
pub const EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR: EGLint = 0x0001;

impl Context {
    pub fn new(
        id: usize,
        config: &'static Config,
        request: Request,
        share: Option<&Context>,
    ) -> Context {
        let mut gl = match share {
            Some(s) => crate::gles::Context::new(Some(&current::lock(&s.gl))),
            None => crate::gles::Context::new(None),
        };
        gl.set_debug_context(request.debug);
        Context {
            id,
            config,
            client_version: request.client_version,
            debug: request.debug,
            gl: Arc::new(Mutex::new(gl)),
        }
    }

    /// eglQueryContext. `render_buffer` is the answer for EGL_RENDER_BUFFER (which depends
    /// on the surface the context is bound to).
    pub fn query(&self, attribute: EGLint, render_buffer: EGLint) -> Result<EGLint, EGLint> {
        Ok(match attribute {
            EGL_CONFIG_ID => self.config.id,
            EGL_CONTEXT_CLIENT_TYPE => EGL_OPENGL_ES_API as EGLint,
            EGL_CONTEXT_CLIENT_VERSION => self.client_version,
            EGL_RENDER_BUFFER => render_buffer,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        })
    }

    /// Completes the context's rendering (glFinish semantics).
    pub fn finish(&self) {
        current::lock(&self.gl).finish();
    }

    /// Rasterizes the context's pending work.
    pub fn flush(&self) {
        current::lock(&self.gl).flush();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn client_version_rules() {
        let es1 = |debug| {
            Ok(Request {
                client_version: 1,
                debug,
            })
        };
        assert_eq!(parse_attribs(&[]), es1(false));
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_CLIENT_VERSION, 1)]),
            es1(false)
        );
        assert_eq!(parse_attribs(&[(EGL_CONTEXT_MINOR_VERSION, 1)]), es1(false));
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_MINOR_VERSION, 2)]),
            Err(EGL_BAD_MATCH)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_CLIENT_VERSION, 2)]),
            Err(EGL_BAD_CONFIG)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_CLIENT_VERSION, 0)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(parse_attribs(&[(EGL_WIDTH, 1)]), Err(EGL_BAD_ATTRIBUTE));
        assert_eq!(parse_attribs(&[(EGL_CONTEXT_OPENGL_DEBUG, 1)]), es1(true));
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_OPENGL_DEBUG, 2)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR)]),
            es1(true)
        );
        // Forward compatibility is desktop OpenGL's.
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_FLAGS_KHR, 2)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE, 0)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_OPENGL_PROFILE_MASK, 1)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_OPENGL_ROBUST_ACCESS, 0)]),
            es1(false)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_OPENGL_ROBUST_ACCESS, 1)]),
            Err(EGL_BAD_CONFIG)
        );
    }

    #[test]
    fn shared_contexts_share_objects() {
        let c = crate::egl::config::by_id(1).unwrap();
        let r = Request {
            client_version: 1,
            debug: false,
        };
        let a = Context::new(1, c, r, None);
        let b = Context::new(2, c, r, Some(&a));
        let d = Context::new(3, c, r, None);
        assert!(current::lock(&a.gl).shares_with(&current::lock(&b.gl)));
        assert!(!current::lock(&a.gl).shares_with(&current::lock(&d.gl)));
    }
}
