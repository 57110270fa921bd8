//! EGLImages as the GL sees them (`OES_EGL_image`): EGL creates and destroys them
//! (`egl::display`), and `glEGLImageTarget*OES` read them by handle. The table lives here,
//! below EGL, so that GL looks images up without calling into EGL.
//!
//! An image is the texel contents of its source at creation: a GL object made from it gets
//! a copy, so later changes to one sibling are not seen by the others (CONFORMANCE.md).
#![forbid(unsafe_code)]

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex, MutexGuard};

use gles_cm_core::texture::Image;

static IMAGES: Mutex<BTreeMap<usize, Arc<Image>>> = Mutex::new(BTreeMap::new());

fn images() -> MutexGuard<'static, BTreeMap<usize, Arc<Image>>> {
    IMAGES.lock().unwrap_or_else(|e| e.into_inner())
}

/// Registers `image` under the EGL handle `id`.
pub fn insert(id: usize, image: Image) {
    images().insert(id, Arc::new(image));
}

/// Forgets handle `id`; false if it named no image.
pub fn remove(id: usize) -> bool {
    images().remove(&id).is_some()
}

/// Forgets every image (eglTerminate).
pub fn clear() {
    images().clear();
}

/// A copy of the image `id` names.
pub fn get(id: usize) -> Option<Image> {
    images().get(&id).map(|i| (**i).clone())
}
