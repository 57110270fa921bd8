/*
 * EGL 1.5 context attributes and EGL_KHR_create_context for OpenGL ES 1: major version 1
 * with minor version 0 or 1, debug contexts (EGL_CONTEXT_OPENGL_DEBUG, or the KHR debug
 * flag), and the errors: a later minor version (EGL_BAD_MATCH), an ES 2 or later version
 * (EGL_BAD_CONFIG: no config offers it), desktop-only attributes and flags
 * (EGL_BAD_ATTRIBUTE), a boolean that is neither EGL_TRUE nor EGL_FALSE.
 */
#include "common.h"
#include <EGL/eglext.h>
#include <GLES/glext.h>

/* eglCreateContext with `attribs`: the error, and the context made current and destroyed
 * when there is one (it must render, with GL_KHR_debug's output on exactly in a debug
 * context). */
static EGLint create_as(const EGLint *attribs, int debug)
{
    EGLContext c = eglCreateContext(ct.display, ct.config, EGL_NO_CONTEXT, attribs);
    EGLint e = eglGetError();
    if (c != EGL_NO_CONTEXT) {
        CHECK(e == EGL_SUCCESS);
        CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, c));
        CHECK(glIsEnabled(GL_DEBUG_OUTPUT_KHR) == (debug ? GL_TRUE : GL_FALSE));
        glClearColor(0, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK_PIXEL(2, 2, 0, 255, 0, 255, 0);
        CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
        CHECK(eglDestroyContext(ct.display, c));
    }
    return e;
}

static EGLint create(const EGLint *attribs)
{
    return create_as(attribs, 0);
}

int main(void)
{
    static const EGLint v10[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 0,
                                 EGL_NONE};
    static const EGLint v11[] = {EGL_CONTEXT_MAJOR_VERSION_KHR, 1,
                                 EGL_CONTEXT_MINOR_VERSION_KHR, 1, EGL_NONE};
    static const EGLint v12[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 2,
                                 EGL_NONE};
    static const EGLint v30[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    static const EGLint debug[] = {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
    static const EGLint debug_flag[] = {EGL_CONTEXT_FLAGS_KHR,
                                        EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR, EGL_NONE};
    static const EGLint bad_bool[] = {EGL_CONTEXT_OPENGL_DEBUG, 2, EGL_NONE};
    static const EGLint forward[] = {EGL_CONTEXT_FLAGS_KHR,
                                     EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR, EGL_NONE};
    static const EGLint profile[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    static const EGLint unknown[] = {EGL_WIDTH, 1, EGL_NONE};

    ct_init(4, 4);
    CHECK(ct_has_word(eglQueryString(ct.display, EGL_EXTENSIONS), "EGL_KHR_create_context"));
    glDisable(GL_DITHER);
    CHECK(create(NULL) == EGL_SUCCESS);
    CHECK(create(v10) == EGL_SUCCESS);
    CHECK(create(v11) == EGL_SUCCESS);
    /* Debug contexts: ours has them (and so has llvmpipe); Mesa's softpipe has none. */
    if (ct_strict()) {
        CHECK(create_as(debug, 1) == EGL_SUCCESS);
        CHECK(create_as(debug_flag, 1) == EGL_SUCCESS);
    }
    CHECK(create(v12) == EGL_BAD_MATCH);
    /* No config of ours offers ES 2 or 3 (EGL 1.5 §3.7.1: EGL_BAD_CONFIG); Mesa's do. */
    if (ct_strict())
        CHECK(create(v30) == EGL_BAD_CONFIG);
    CHECK_MESA_DEVIATES(create(bad_bool) == EGL_BAD_ATTRIBUTE,
                        "Mesa takes any non-zero value as EGL_TRUE");
    CHECK(create(forward) == EGL_BAD_ATTRIBUTE);
    CHECK(create(profile) == EGL_BAD_ATTRIBUTE);
    CHECK(create(unknown) == EGL_BAD_ATTRIBUTE);
    return ct_done();
}
