//! The matrix stacks.

use crate::gles::types::*;
use gles_cm_core::fixed::to_f32 as fx;

use super::{read_array, with_context};

#[no_mangle]
pub extern "C" fn glMatrixMode(mode: GLenum) {
    with_context("glMatrixMode", (), |c| c.matrix_mode(mode))
}

#[no_mangle]
pub extern "C" fn glLoadIdentity() {
    with_context("glLoadIdentity", (), |c| c.load_identity())
}

#[no_mangle]
pub extern "C" fn glPushMatrix() {
    with_context("glPushMatrix", (), |c| c.push_matrix())
}

#[no_mangle]
pub extern "C" fn glPopMatrix() {
    with_context("glPopMatrix", (), |c| c.pop_matrix())
}

/// # Safety
/// A non-null `m` must point to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixf(m: *const GLfloat) {
    // SAFETY: the caller passes 16 floats.
    let Some(m) = (unsafe { read_array::<GLfloat, 16>(m) }) else {
        return;
    };
    with_context("glLoadMatrixf", (), |c| c.load_matrix(&m))
}

/// # Safety
/// A non-null `m` must point to 16 fixed-point values.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixx(m: *const GLfixed) {
    // SAFETY: the caller passes 16 values.
    let Some(m) = (unsafe { read_array::<GLfixed, 16>(m) }) else {
        return;
    };
    with_context("glLoadMatrixx", (), |c| c.load_matrix(&m.map(fx)))
}

/// # Safety
/// A non-null `m` must point to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixf(m: *const GLfloat) {
    // SAFETY: the caller passes 16 floats.
    let Some(m) = (unsafe { read_array::<GLfloat, 16>(m) }) else {
        return;
    };
    with_context("glMultMatrixf", (), |c| c.mult_matrix(&m))
}

/// # Safety
/// A non-null `m` must point to 16 fixed-point values.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixx(m: *const GLfixed) {
    // SAFETY: the caller passes 16 values.
    let Some(m) = (unsafe { read_array::<GLfixed, 16>(m) }) else {
        return;
    };
    with_context("glMultMatrixx", (), |c| c.mult_matrix(&m.map(fx)))
}

#[no_mangle]
pub extern "C" fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_context("glTranslatef", (), |c| c.translate(x, y, z))
}

#[no_mangle]
pub extern "C" fn glTranslatex(x: GLfixed, y: GLfixed, z: GLfixed) {
    with_context("glTranslatex", (), |c| c.translate(fx(x), fx(y), fx(z)))
}

#[no_mangle]
pub extern "C" fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_context("glScalef", (), |c| c.scale(x, y, z))
}

#[no_mangle]
pub extern "C" fn glScalex(x: GLfixed, y: GLfixed, z: GLfixed) {
    with_context("glScalex", (), |c| c.scale(fx(x), fx(y), fx(z)))
}

#[no_mangle]
pub extern "C" fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) {
    with_context("glRotatef", (), |c| c.rotate(angle, x, y, z))
}

#[no_mangle]
pub extern "C" fn glRotatex(angle: GLfixed, x: GLfixed, y: GLfixed, z: GLfixed) {
    with_context("glRotatex", (), |c| {
        c.rotate(fx(angle), fx(x), fx(y), fx(z))
    })
}

#[no_mangle]
pub extern "C" fn glFrustumf(
    l: GLfloat,
    r: GLfloat,
    b: GLfloat,
    t: GLfloat,
    n: GLfloat,
    f: GLfloat,
) {
    with_context("glFrustumf", (), |c| c.frustum(l, r, b, t, n, f))
}

#[no_mangle]
pub extern "C" fn glFrustumx(
    l: GLfixed,
    r: GLfixed,
    b: GLfixed,
    t: GLfixed,
    n: GLfixed,
    f: GLfixed,
) {
    with_context("glFrustumx", (), |c| {
        c.frustum(fx(l), fx(r), fx(b), fx(t), fx(n), fx(f))
    })
}

#[no_mangle]
pub extern "C" fn glOrthof(l: GLfloat, r: GLfloat, b: GLfloat, t: GLfloat, n: GLfloat, f: GLfloat) {
    with_context("glOrthof", (), |c| c.ortho(l, r, b, t, n, f))
}

#[no_mangle]
pub extern "C" fn glOrthox(l: GLfixed, r: GLfixed, b: GLfixed, t: GLfixed, n: GLfixed, f: GLfixed) {
    with_context("glOrthox", (), |c| {
        c.ortho(fx(l), fx(r), fx(b), fx(t), fx(n), fx(f))
    })
}
