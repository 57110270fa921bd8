/*
 * egl_context.c: eglCreateContext (client version, sharing, errors), eglQueryContext,
 * eglMakeCurrent's rules and errors, eglGetCurrent*, eglDestroyContext while current,
 * eglTerminate with a current context, eglReleaseThread.
 * ct:no-diff (config ids; ES 2 contexts are refused here)
 */
#include "common.h"

static EGLDisplay dpy;

static EGLConfig config_id(EGLint id)
{
    EGLint attribs[] = {EGL_CONFIG_ID, 0, EGL_NONE};
    EGLConfig c = NULL;
    EGLint n = 0;
    attribs[1] = id;
    CHECK(eglChooseConfig(dpy, attribs, &c, 1, &n) && n == 1);
    return c;
}

static EGLint qctx(EGLContext c, EGLint a)
{
    EGLint v = -12345;
    CHECK(eglQueryContext(dpy, c, a, &v));
    return v;
}

int main(void)
{
    static const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
    EGLConfig c1, c18;
    EGLSurface s1, s18, s18b;
    EGLContext a, b, shared;
    EGLint v;

    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(eglCreateContext(dpy, NULL, EGL_NO_CONTEXT, NULL) == EGL_NO_CONTEXT);
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(eglInitialize(dpy, NULL, NULL));
    c1 = config_id(1);
    c18 = config_id(18);
    s1 = eglCreatePbufferSurface(dpy, c1, size);
    s18 = eglCreatePbufferSurface(dpy, c18, size);
    s18b = eglCreatePbufferSurface(dpy, c18, size);
    CHECK(s1 && s18 && s18b);

    {
        static const EGLint v1[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
        static const EGLint v2[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
        static const EGLint v0[] = {EGL_CONTEXT_CLIENT_VERSION, 0, EGL_NONE};
        static const EGLint unknown[] = {0x1234, 1, EGL_NONE};
        a = eglCreateContext(dpy, c18, EGL_NO_CONTEXT, v1);
        CHECK(a != EGL_NO_CONTEXT);
        CHECK_EGL(EGL_SUCCESS);
        CHECK(eglCreateContext(dpy, c18, EGL_NO_CONTEXT, v2) == EGL_NO_CONTEXT);
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(eglCreateContext(dpy, c18, EGL_NO_CONTEXT, v0) == EGL_NO_CONTEXT);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
        CHECK(eglCreateContext(dpy, c18, EGL_NO_CONTEXT, unknown) == EGL_NO_CONTEXT);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
        CHECK(eglCreateContext(dpy, (EGLConfig)(size_t)77, EGL_NO_CONTEXT, NULL) ==
              EGL_NO_CONTEXT);
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(eglCreateContext(dpy, c18, (EGLContext)(size_t)77, NULL) == EGL_NO_CONTEXT);
        CHECK_EGL(EGL_BAD_CONTEXT);
        CHECK(eglCreateContext((EGLDisplay)(size_t)77, c18, EGL_NO_CONTEXT, NULL) ==
              EGL_NO_CONTEXT);
        CHECK_EGL(EGL_BAD_DISPLAY);
    }
    b = eglCreateContext(dpy, c1, EGL_NO_CONTEXT, NULL);
    shared = eglCreateContext(dpy, c18, a, NULL);
    CHECK(b && shared);

    CHECK(qctx(a, EGL_CONFIG_ID) == 18);
    CHECK(qctx(b, EGL_CONFIG_ID) == 1);
    CHECK(qctx(a, EGL_CONTEXT_CLIENT_TYPE) == EGL_OPENGL_ES_API);
    CHECK(qctx(a, EGL_CONTEXT_CLIENT_VERSION) == 1);
    CHECK(qctx(a, EGL_RENDER_BUFFER) == EGL_NONE);
    CHECK(!eglQueryContext(dpy, a, 0x1234, &v));
    CHECK_EGL(EGL_BAD_ATTRIBUTE);
    CHECK(!eglQueryContext(dpy, (EGLContext)(size_t)77, EGL_CONFIG_ID, &v));
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(!eglQueryContext((EGLDisplay)(size_t)77, a, EGL_CONFIG_ID, &v));
    CHECK_EGL(EGL_BAD_DISPLAY);

    /* eglMakeCurrent errors leave nothing current. */
    CHECK(!eglMakeCurrent((EGLDisplay)(size_t)77, s18, s18, a));
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(!eglMakeCurrent(dpy, s18, s18, (EGLContext)(size_t)77));
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(!eglMakeCurrent(dpy, (EGLSurface)(size_t)77, s18, a));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglMakeCurrent(dpy, s18, (EGLSurface)(size_t)77, a));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglMakeCurrent(dpy, s18, s18, EGL_NO_CONTEXT));
    CHECK_EGL(EGL_BAD_MATCH);
    /* No surfaces at all is EGL_KHR_surfaceless_context (egl_surfaceless_context.c); one
     * without the other is still a mismatch. */
    CHECK(!eglMakeCurrent(dpy, EGL_NO_SURFACE, s18, a));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglMakeCurrent(dpy, s18, EGL_NO_SURFACE, a));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglMakeCurrent(dpy, s1, s1, a)); /* config mismatch */
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglMakeCurrent(dpy, s18, s1, a));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT);
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK_EGL(EGL_SUCCESS);

    /* Separate draw and read surfaces. */
    CHECK(eglMakeCurrent(dpy, s18, s18b, a));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglGetCurrentContext() == a);
    CHECK(eglGetCurrentDisplay() == dpy);
    CHECK(eglGetCurrentSurface(EGL_DRAW) == s18);
    CHECK(eglGetCurrentSurface(EGL_READ) == s18b);
    CHECK(qctx(a, EGL_RENDER_BUFFER) == EGL_BACK_BUFFER);
    ct.width = ct.height = 8;
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(1, 1, 0, 0, 0, 0, 0); /* the read surface is untouched */
    CHECK(eglMakeCurrent(dpy, s18, s18, a));
    CHECK_PIXEL(1, 1, 255, 0, 0, 255, 0);
    CHECK(eglMakeCurrent(dpy, s18b, s18, a));
    CHECK_PIXEL(1, 1, 255, 0, 0, 255, 0);

    /* Switch contexts on the same thread. */
    CHECK(eglMakeCurrent(dpy, s1, s1, b));
    CHECK(eglGetCurrentContext() == b);
    CHECK(qctx(a, EGL_RENDER_BUFFER) == EGL_NONE);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(0, 0, 0, 0, 255, 255, 0);
    CHECK(eglMakeCurrent(dpy, s18, s18, shared));
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);

    /* Destroying a current context is deferred. */
    CHECK(eglDestroyContext(dpy, shared));
    CHECK(eglGetCurrentContext() == shared);
    CHECK(!eglQueryContext(dpy, shared, EGL_CONFIG_ID, &v));
    CHECK_EGL(EGL_BAD_CONTEXT);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_GL(GL_NO_ERROR);
    CHECK(!eglMakeCurrent(dpy, s18, s18, shared));
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(eglGetCurrentContext() == shared);
    CHECK(eglMakeCurrent(dpy, s18, s18, a));
    CHECK(eglGetCurrentContext() == a);
    CHECK(!eglDestroyContext(dpy, shared));
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(!eglDestroyContext((EGLDisplay)(size_t)77, b));
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(eglDestroyContext(dpy, b));

    /* Terminate with a current context: it stays current until released. */
    CHECK(eglTerminate(dpy));
    CHECK(eglGetCurrentContext() == a);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(2, 2, 0, 255, 0, 255, 0);
    CHECK(!eglMakeCurrent(dpy, s18, s18, a));
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(eglReleaseThread());
    CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglInitialize(dpy, NULL, NULL));
    CHECK(!eglDestroyContext(dpy, a));
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(!eglDestroySurface(dpy, s18));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(eglTerminate(dpy));
    return ct_done();
}
