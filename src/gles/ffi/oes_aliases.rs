//! The `OES_fixed_point` and `OES_single_precision` names of core ES 1.1 functions
//! (`glFrustumfOES`, `glOrthoxOES`, ...): programs written for ES 1.0 with those extensions
//! call them. Each is the core function under its extension name.

use crate::gles::types::*;

use super::*;

#[no_mangle]
pub extern "C" fn glAlphaFuncxOES(func: GLenum, reference: GLclampx) {
    glAlphaFuncx(func, reference)
}

#[no_mangle]
pub extern "C" fn glClearColorxOES(r: GLclampx, g: GLclampx, bl: GLclampx, a: GLclampx) {
    glClearColorx(r, g, bl, a)
}

#[no_mangle]
pub extern "C" fn glClearDepthxOES(depth: GLclampx) {
    glClearDepthx(depth)
}

/// # Safety
/// As for `glClipPlanex`.
#[no_mangle]
pub unsafe extern "C" fn glClipPlanexOES(plane: GLenum, equation: *const GLfixed) {
    // SAFETY: the caller's contract for `glClipPlanexOES` is that of `glClipPlanex`.
    unsafe { glClipPlanex(plane, equation) }
}

#[no_mangle]
pub extern "C" fn glColor4xOES(r: GLfixed, g: GLfixed, b: GLfixed, a: GLfixed) {
    glColor4x(r, g, b, a)
}

#[no_mangle]
pub extern "C" fn glDepthRangexOES(near: GLclampx, far: GLclampx) {
    glDepthRangex(near, far)
}

#[no_mangle]
pub extern "C" fn glFogxOES(pname: GLenum, param: GLfixed) {
    glFogx(pname, param)
}

/// # Safety
/// As for `glFogxv`.
#[no_mangle]
pub unsafe extern "C" fn glFogxvOES(pname: GLenum, params: *const GLfixed) {
    // SAFETY: the caller's contract for `glFogxvOES` is that of `glFogxv`.
    unsafe { glFogxv(pname, params) }
}

#[no_mangle]
pub extern "C" fn glFrustumxOES(
    l: GLfixed,
    r: GLfixed,
    b: GLfixed,
    t: GLfixed,
    n: GLfixed,
    f: GLfixed,
) {
    glFrustumx(l, r, b, t, n, f)
}

/// # Safety
/// As for `glGetClipPlanex`.
#[no_mangle]
pub unsafe extern "C" fn glGetClipPlanexOES(plane: GLenum, equation: *mut GLfixed) {
    // SAFETY: the caller's contract for `glGetClipPlanexOES` is that of `glGetClipPlanex`.
    unsafe { glGetClipPlanex(plane, equation) }
}

/// # Safety
/// As for `glGetFixedv`.
#[no_mangle]
pub unsafe extern "C" fn glGetFixedvOES(pname: GLenum, params: *mut GLfixed) {
    // SAFETY: the caller's contract for `glGetFixedvOES` is that of `glGetFixedv`.
    unsafe { glGetFixedv(pname, params) }
}

/// # Safety
/// As for `glGetTexEnvxv`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnvxvOES(target: GLenum, pname: GLenum, params: *mut GLfixed) {
    // SAFETY: the caller's contract for `glGetTexEnvxvOES` is that of `glGetTexEnvxv`.
    unsafe { glGetTexEnvxv(target, pname, params) }
}

/// # Safety
/// As for `glGetTexParameterxv`.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameterxvOES(
    target: GLenum,
    pname: GLenum,
    params: *mut GLfixed,
) {
    // SAFETY: the caller's contract for `glGetTexParameterxvOES` is that of `glGetTexParameterxv`.
    unsafe { glGetTexParameterxv(target, pname, params) }
}

#[no_mangle]
pub extern "C" fn glLightModelxOES(pname: GLenum, param: GLfixed) {
    glLightModelx(pname, param)
}

/// # Safety
/// As for `glLightModelxv`.
#[no_mangle]
pub unsafe extern "C" fn glLightModelxvOES(pname: GLenum, params: *const GLfixed) {
    // SAFETY: the caller's contract for `glLightModelxvOES` is that of `glLightModelxv`.
    unsafe { glLightModelxv(pname, params) }
}

#[no_mangle]
pub extern "C" fn glLightxOES(light: GLenum, pname: GLenum, param: GLfixed) {
    glLightx(light, pname, param)
}

/// # Safety
/// As for `glLightxv`.
#[no_mangle]
pub unsafe extern "C" fn glLightxvOES(light: GLenum, pname: GLenum, params: *const GLfixed) {
    // SAFETY: the caller's contract for `glLightxvOES` is that of `glLightxv`.
    unsafe { glLightxv(light, pname, params) }
}

#[no_mangle]
pub extern "C" fn glLineWidthxOES(width: GLfixed) {
    glLineWidthx(width)
}

/// # Safety
/// As for `glLoadMatrixx`.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixxOES(m: *const GLfixed) {
    // SAFETY: the caller's contract for `glLoadMatrixxOES` is that of `glLoadMatrixx`.
    unsafe { glLoadMatrixx(m) }
}

#[no_mangle]
pub extern "C" fn glMaterialxOES(face: GLenum, pname: GLenum, param: GLfixed) {
    glMaterialx(face, pname, param)
}

/// # Safety
/// As for `glMaterialxv`.
#[no_mangle]
pub unsafe extern "C" fn glMaterialxvOES(face: GLenum, pname: GLenum, params: *const GLfixed) {
    // SAFETY: the caller's contract for `glMaterialxvOES` is that of `glMaterialxv`.
    unsafe { glMaterialxv(face, pname, params) }
}

/// # Safety
/// As for `glMultMatrixx`.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixxOES(m: *const GLfixed) {
    // SAFETY: the caller's contract for `glMultMatrixxOES` is that of `glMultMatrixx`.
    unsafe { glMultMatrixx(m) }
}

#[no_mangle]
pub extern "C" fn glMultiTexCoord4xOES(
    target: GLenum,
    s: GLfixed,
    t: GLfixed,
    r: GLfixed,
    q: GLfixed,
) {
    glMultiTexCoord4x(target, s, t, r, q)
}

#[no_mangle]
pub extern "C" fn glNormal3xOES(nx: GLfixed, ny: GLfixed, nz: GLfixed) {
    glNormal3x(nx, ny, nz)
}

#[no_mangle]
pub extern "C" fn glOrthoxOES(
    l: GLfixed,
    r: GLfixed,
    b: GLfixed,
    t: GLfixed,
    n: GLfixed,
    f: GLfixed,
) {
    glOrthox(l, r, b, t, n, f)
}

/// # Safety
/// As for `glPointParameterxv`.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterxvOES(pname: GLenum, params: *const GLfixed) {
    // SAFETY: the caller's contract for `glPointParameterxvOES` is that of `glPointParameterxv`.
    unsafe { glPointParameterxv(pname, params) }
}

#[no_mangle]
pub extern "C" fn glPointSizexOES(size: GLfixed) {
    glPointSizex(size)
}

#[no_mangle]
pub extern "C" fn glPolygonOffsetxOES(factor: GLfixed, units: GLfixed) {
    glPolygonOffsetx(factor, units)
}

#[no_mangle]
pub extern "C" fn glRotatexOES(angle: GLfixed, x: GLfixed, y: GLfixed, z: GLfixed) {
    glRotatex(angle, x, y, z)
}

#[no_mangle]
pub extern "C" fn glScalexOES(x: GLfixed, y: GLfixed, z: GLfixed) {
    glScalex(x, y, z)
}

#[no_mangle]
pub extern "C" fn glTexEnvxOES(target: GLenum, pname: GLenum, param: GLfixed) {
    glTexEnvx(target, pname, param)
}

/// # Safety
/// As for `glTexEnvxv`.
#[no_mangle]
pub unsafe extern "C" fn glTexEnvxvOES(target: GLenum, pname: GLenum, params: *const GLfixed) {
    // SAFETY: the caller's contract for `glTexEnvxvOES` is that of `glTexEnvxv`.
    unsafe { glTexEnvxv(target, pname, params) }
}

#[no_mangle]
pub extern "C" fn glTexParameterxOES(target: GLenum, pname: GLenum, param: GLfixed) {
    glTexParameterx(target, pname, param)
}

/// # Safety
/// As for `glTexParameterxv`.
#[no_mangle]
pub unsafe extern "C" fn glTexParameterxvOES(
    target: GLenum,
    pname: GLenum,
    params: *const GLfixed,
) {
    // SAFETY: the caller's contract for `glTexParameterxvOES` is that of `glTexParameterxv`.
    unsafe { glTexParameterxv(target, pname, params) }
}

#[no_mangle]
pub extern "C" fn glTranslatexOES(x: GLfixed, y: GLfixed, z: GLfixed) {
    glTranslatex(x, y, z)
}

/// # Safety
/// As for `glGetLightxv`.
#[no_mangle]
pub unsafe extern "C" fn glGetLightxvOES(light: GLenum, pname: GLenum, params: *mut GLfixed) {
    // SAFETY: the caller's contract for `glGetLightxvOES` is that of `glGetLightxv`.
    unsafe { glGetLightxv(light, pname, params) }
}

/// # Safety
/// As for `glGetMaterialxv`.
#[no_mangle]
pub unsafe extern "C" fn glGetMaterialxvOES(face: GLenum, pname: GLenum, params: *mut GLfixed) {
    // SAFETY: the caller's contract for `glGetMaterialxvOES` is that of `glGetMaterialxv`.
    unsafe { glGetMaterialxv(face, pname, params) }
}

#[no_mangle]
pub extern "C" fn glPointParameterxOES(pname: GLenum, param: GLfixed) {
    glPointParameterx(pname, param)
}

#[no_mangle]
pub extern "C" fn glSampleCoveragexOES(value: GLclampx, invert: GLboolean) {
    glSampleCoveragex(value, invert)
}

#[no_mangle]
pub extern "C" fn glClearDepthfOES(depth: GLclampf) {
    glClearDepthf(depth)
}

/// # Safety
/// As for `glClipPlanef`.
#[no_mangle]
pub unsafe extern "C" fn glClipPlanefOES(plane: GLenum, equation: *const GLfloat) {
    // SAFETY: the caller's contract for `glClipPlanefOES` is that of `glClipPlanef`.
    unsafe { glClipPlanef(plane, equation) }
}

#[no_mangle]
pub extern "C" fn glDepthRangefOES(near: GLclampf, far: GLclampf) {
    glDepthRangef(near, far)
}

#[no_mangle]
pub extern "C" fn glFrustumfOES(
    l: GLfloat,
    r: GLfloat,
    b: GLfloat,
    t: GLfloat,
    n: GLfloat,
    f: GLfloat,
) {
    glFrustumf(l, r, b, t, n, f)
}

/// # Safety
/// As for `glGetClipPlanef`.
#[no_mangle]
pub unsafe extern "C" fn glGetClipPlanefOES(plane: GLenum, equation: *mut GLfloat) {
    // SAFETY: the caller's contract for `glGetClipPlanefOES` is that of `glGetClipPlanef`.
    unsafe { glGetClipPlanef(plane, equation) }
}

#[no_mangle]
pub extern "C" fn glOrthofOES(
    l: GLfloat,
    r: GLfloat,
    b: GLfloat,
    t: GLfloat,
    n: GLfloat,
    f: GLfloat,
) {
    glOrthof(l, r, b, t, n, f)
}
