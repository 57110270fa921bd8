//! A GL ES 1.1 context: the state machine behind the `gl*` entry points.

use std::sync::{Arc, Mutex};

use crate::core::{RenderState, Target, TargetFormat};

use super::tokens::*;
use super::types::*;

/// What a context draws into. EGL surfaces implement it; the context only needs the target
/// and a way to say "the rendering issued so far is complete" (pixmap surfaces copy their
/// pixels out to the caller's memory then).
pub trait Surface: Send + Sync {
    fn target(&self) -> &Mutex<Target>;
    /// Called after `glFinish` (and other points where the specification says rendering to
    /// the surface is complete) with the target unlocked.
    fn rendering_complete(&self) {}
}

/// Objects shared between the contexts of one share group (textures and buffer objects).
#[derive(Default)]
pub struct SharedObjects {}

pub struct Context {
    pub(super) shared: Arc<Mutex<SharedObjects>>,
    pub(super) draw: Option<Arc<dyn Surface>>,
    pub(super) read: Option<Arc<dyn Surface>>,
    /// Set on the first `make_current`: the viewport and scissor start at the surface size.
    pub(super) initialized: bool,
    pub(super) error: GLenum,
    pub(super) render: RenderState,
}

impl Context {
    /// A new context, sharing objects with `share` when given.
    pub fn new(share: Option<&Context>) -> Context {
        Context {
            shared: share.map_or_else(Default::default, |s| s.shared.clone()),
            draw: None,
            read: None,
            initialized: false,
            error: GL_NO_ERROR,
            render: RenderState::new(0, 0),
        }
    }

    /// True when `self` and `other` share texture and buffer objects.
    pub fn shares_with(&self, other: &Context) -> bool {
        Arc::ptr_eq(&self.shared, &other.shared)
    }

    /// Binds the draw and read surfaces (on `eglMakeCurrent`). The first time a context is
    /// bound, the viewport and scissor box are set to the draw surface's size.
    pub fn make_current(&mut self, draw: Option<Arc<dyn Surface>>, read: Option<Arc<dyn Surface>>) {
        if !self.initialized {
            if let Some(d) = &draw {
                let t = d.target().lock().unwrap_or_else(|e| e.into_inner());
                self.render = RenderState::new(t.width() as i32, t.height() as i32);
                self.initialized = true;
            }
        }
        self.draw = draw;
        self.read = read;
    }

    /// Completes all rendering issued so far (the `glFinish` semantics), then tells the draw
    /// surface. EGL calls this before a context stops being current and on `eglWaitClient`.
    pub fn finish(&mut self) {
        if let Some(d) = &self.draw {
            d.rendering_complete();
        }
    }

    /// The format of the draw surface, if one is bound.
    pub fn draw_format(&self) -> Option<TargetFormat> {
        let d = self.draw.as_ref()?;
        let t = d.target().lock().unwrap_or_else(|e| e.into_inner());
        Some(t.format())
    }

    /// Records `e` unless an earlier error is still unread (the first error sticks).
    pub fn set_error(&mut self, e: GLenum) {
        if self.error == GL_NO_ERROR {
            self.error = e;
        }
    }

    /// Returns and clears the recorded error.
    pub fn take_error(&mut self) -> GLenum {
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }
}
