//! EGL rendering contexts: an OpenGL ES 1.x [`gles::Context`](crate::gles::Context) with the
//! config it was created for.

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
    pub gl: SharedContext,
}

/// Parses eglCreateContext's attribute list: only EGL_CONTEXT_CLIENT_VERSION, and only
/// version 1. Version 2 names a client API no config supports (EGL_OPENGL_ES2_BIT is never
/// set), which section 3.7.1 makes EGL_BAD_CONFIG; any other version or attribute is
/// EGL_BAD_ATTRIBUTE.
pub fn parse_attribs(pairs: &[(EGLint, EGLint)]) -> Result<EGLint, EGLint> {
    let mut version = 1;
    for &(attr, value) in pairs {
        match attr {
            EGL_CONTEXT_CLIENT_VERSION => version = value,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
    }
    match version {
        1 => Ok(1),
        2 => Err(EGL_BAD_CONFIG),
        _ => Err(EGL_BAD_ATTRIBUTE),
    }
}

impl Context {
    pub fn new(
        id: usize,
        config: &'static Config,
        client_version: EGLint,
        share: Option<&Context>,
    ) -> Context {
        let gl = match share {
            Some(s) => crate::gles::Context::new(Some(&current::lock(&s.gl))),
            None => crate::gles::Context::new(None),
        };
        Context {
            id,
            config,
            client_version,
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
        assert_eq!(parse_attribs(&[]), Ok(1));
        assert_eq!(parse_attribs(&[(EGL_CONTEXT_CLIENT_VERSION, 1)]), Ok(1));
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_CLIENT_VERSION, 2)]),
            Err(EGL_BAD_CONFIG)
        );
        assert_eq!(
            parse_attribs(&[(EGL_CONTEXT_CLIENT_VERSION, 0)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(parse_attribs(&[(EGL_WIDTH, 1)]), Err(EGL_BAD_ATTRIBUTE));
    }

    #[test]
    fn shared_contexts_share_objects() {
        let c = crate::egl::config::by_id(1).unwrap();
        let a = Context::new(1, c, 1, None);
        let b = Context::new(2, c, 1, Some(&a));
        let d = Context::new(3, c, 1, None);
        assert!(current::lock(&a.gl).shares_with(&current::lock(&b.gl)));
        assert!(!current::lock(&a.gl).shares_with(&current::lock(&d.gl)));
    }
}
