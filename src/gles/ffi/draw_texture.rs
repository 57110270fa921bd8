//! `OES_draw_texture`: screen-aligned textured rectangles.

use crate::gles::types::*;
use gles_cm_core::fixed;

use super::{read_array, with_context};

fn draw(call: &'static str, v: [f32; 5]) {
    with_context(call, (), |c| c.draw_texture(v[0], v[1], v[2], v[3], v[4]))
}

#[no_mangle]
pub extern "C" fn glDrawTexsOES(x: GLshort, y: GLshort, z: GLshort, w: GLshort, h: GLshort) {
    draw("glDrawTexsOES", [x, y, z, w, h].map(f32::from))
}

#[no_mangle]
pub extern "C" fn glDrawTexiOES(x: GLint, y: GLint, z: GLint, w: GLint, h: GLint) {
    draw("glDrawTexiOES", [x, y, z, w, h].map(|v| v as f32))
}

#[no_mangle]
pub extern "C" fn glDrawTexxOES(x: GLfixed, y: GLfixed, z: GLfixed, w: GLfixed, h: GLfixed) {
    draw("glDrawTexxOES", [x, y, z, w, h].map(fixed::to_f32))
}

#[no_mangle]
pub extern "C" fn glDrawTexfOES(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat, h: GLfloat) {
    draw("glDrawTexfOES", [x, y, z, w, h])
}

/// # Safety
/// A non-null `coords` must point to 5 values: x, y, z, width, height.
#[no_mangle]
pub unsafe extern "C" fn glDrawTexsvOES(coords: *const GLshort) {
    // SAFETY: the application passes 5 values.
    if let Some(v) = unsafe { read_array::<_, 5>(coords) } {
        draw("glDrawTexsvOES", v.map(f32::from))
    }
}

/// # Safety
/// A non-null `coords` must point to 5 values: x, y, z, width, height.
#[no_mangle]
pub unsafe extern "C" fn glDrawTexivOES(coords: *const GLint) {
    // SAFETY: the application passes 5 values.
    if let Some(v) = unsafe { read_array::<_, 5>(coords) } {
        draw("glDrawTexivOES", v.map(|c| c as f32))
    }
}

/// # Safety
/// A non-null `coords` must point to 5 values: x, y, z, width, height.
#[no_mangle]
pub unsafe extern "C" fn glDrawTexxvOES(coords: *const GLfixed) {
    // SAFETY: the application passes 5 values.
    if let Some(v) = unsafe { read_array::<_, 5>(coords) } {
        draw("glDrawTexxvOES", v.map(fixed::to_f32))
    }
}

/// # Safety
/// A non-null `coords` must point to 5 values: x, y, z, width, height.
#[no_mangle]
pub unsafe extern "C" fn glDrawTexfvOES(coords: *const GLfloat) {
    // SAFETY: the application passes 5 values.
    if let Some(v) = unsafe { read_array::<_, 5>(coords) } {
        draw("glDrawTexfvOES", v)
    }
}
