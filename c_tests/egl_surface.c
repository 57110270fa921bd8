/*
 * egl_surface.c: pbuffers (sizes, EGL_LARGEST_PBUFFER, texture attributes and their errors),
 * eglQuerySurface for every attribute, eglSurfaceAttrib, eglBindTexImage/eglReleaseTexImage,
 * eglSwapBuffers/eglSwapInterval on a pbuffer, eglDestroySurface.
 * ct:no-diff (limits, config ids and texture support are this implementation's)
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

static EGLint query(EGLSurface s, EGLint a)
{
    EGLint v = -12345;
    CHECK(eglQuerySurface(dpy, s, a, &v));
    return v;
}

static EGLSurface pbuffer(EGLConfig c, const EGLint *attribs, EGLint expected_error)
{
    EGLSurface s = eglCreatePbufferSurface(dpy, c, attribs);
    CHECK((s == EGL_NO_SURFACE) == (expected_error != EGL_SUCCESS));
    CHECK_EGL(expected_error);
    return s;
}

int main(void)
{
    EGLConfig c565, c8888;
    EGLSurface s, tex;
    EGLContext ctx;
    EGLint v;

    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(eglInitialize(dpy, NULL, NULL));
    c565 = config_id(1);
    c8888 = config_id(18);

    {
        static const EGLint a[] = {EGL_WIDTH, 16, EGL_HEIGHT, 8, EGL_NONE};
        s = pbuffer(c8888, a, EGL_SUCCESS);
    }
    CHECK(query(s, EGL_CONFIG_ID) == 18);
    CHECK(query(s, EGL_WIDTH) == 16);
    CHECK(query(s, EGL_HEIGHT) == 8);
    CHECK(query(s, EGL_LARGEST_PBUFFER) == EGL_FALSE);
    CHECK(query(s, EGL_TEXTURE_FORMAT) == EGL_NO_TEXTURE);
    CHECK(query(s, EGL_TEXTURE_TARGET) == EGL_NO_TEXTURE);
    CHECK(query(s, EGL_MIPMAP_TEXTURE) == EGL_FALSE);
    CHECK(query(s, EGL_MIPMAP_LEVEL) == 0);
    CHECK(query(s, EGL_RENDER_BUFFER) == EGL_BACK_BUFFER);
    CHECK(query(s, EGL_SWAP_BEHAVIOR) == EGL_BUFFER_PRESERVED);
    CHECK(query(s, EGL_MULTISAMPLE_RESOLVE) == EGL_MULTISAMPLE_RESOLVE_DEFAULT);
    CHECK(query(s, EGL_HORIZONTAL_RESOLUTION) == EGL_UNKNOWN);
    CHECK(query(s, EGL_VERTICAL_RESOLUTION) == EGL_UNKNOWN);
    CHECK(query(s, EGL_PIXEL_ASPECT_RATIO) == EGL_UNKNOWN);
    CHECK(query(s, EGL_VG_COLORSPACE) == EGL_VG_COLORSPACE_sRGB);
    CHECK(query(s, EGL_VG_ALPHA_FORMAT) == EGL_VG_ALPHA_FORMAT_NONPRE);
    CHECK_EGL(EGL_SUCCESS);
    v = 77;
    CHECK(!eglQuerySurface(dpy, s, 0x1234, &v) && v == 77);
    CHECK_EGL(EGL_BAD_ATTRIBUTE);
    CHECK(!eglQuerySurface(dpy, (EGLSurface)(size_t)5, EGL_WIDTH, &v));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglQuerySurface((EGLDisplay)(size_t)5, s, EGL_WIDTH, &v));
    CHECK_EGL(EGL_BAD_DISPLAY);

    /* eglSurfaceAttrib. */
    CHECK(eglSurfaceAttrib(dpy, s, EGL_MIPMAP_LEVEL, 2));
    CHECK(query(s, EGL_MIPMAP_LEVEL) == 2);
    CHECK(eglSurfaceAttrib(dpy, s, EGL_SWAP_BEHAVIOR, EGL_BUFFER_DESTROYED));
    CHECK(query(s, EGL_SWAP_BEHAVIOR) == EGL_BUFFER_DESTROYED);
    CHECK(eglSurfaceAttrib(dpy, s, EGL_SWAP_BEHAVIOR, EGL_BUFFER_PRESERVED));
    CHECK(eglSurfaceAttrib(dpy, s, EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_DEFAULT));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(!eglSurfaceAttrib(dpy, s, EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_BOX));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglSurfaceAttrib(dpy, s, EGL_MULTISAMPLE_RESOLVE, 0x1234));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!eglSurfaceAttrib(dpy, s, EGL_SWAP_BEHAVIOR, 0x1234));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!eglSurfaceAttrib(dpy, s, EGL_WIDTH, 4));
    CHECK_EGL(EGL_BAD_ATTRIBUTE);
    CHECK(!eglSurfaceAttrib(dpy, (EGLSurface)(size_t)5, EGL_MIPMAP_LEVEL, 0));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(query(s, EGL_SWAP_BEHAVIOR) == EGL_BUFFER_PRESERVED);

    /* Sizes. */
    {
        static const EGLint none[] = {EGL_NONE};
        static const EGLint neg[] = {EGL_WIDTH, -1, EGL_HEIGHT, 4, EGL_NONE};
        static const EGLint huge[] = {EGL_WIDTH, 100000, EGL_HEIGHT, 2, EGL_NONE};
        static const EGLint huge_h[] = {EGL_WIDTH, 2, EGL_HEIGHT, 8193, EGL_NONE};
        static const EGLint largest[] = {EGL_WIDTH, 100000, EGL_HEIGHT, 2, EGL_LARGEST_PBUFFER,
                                         EGL_TRUE, EGL_NONE};
        static const EGLint bad_bool[] = {EGL_LARGEST_PBUFFER, 3, EGL_NONE};
        static const EGLint unknown[] = {0x1234, 1, EGL_NONE};
        static const EGLint window_only[] = {EGL_RENDER_BUFFER, EGL_BACK_BUFFER, EGL_NONE};
        EGLSurface z = pbuffer(c565, none, EGL_SUCCESS);
        CHECK(query(z, EGL_WIDTH) == 0 && query(z, EGL_HEIGHT) == 0);
        CHECK(eglDestroySurface(dpy, z));
        z = pbuffer(c565, NULL, EGL_SUCCESS);
        CHECK(eglDestroySurface(dpy, z));
        pbuffer(c565, neg, EGL_BAD_PARAMETER);
        pbuffer(c565, huge, EGL_BAD_ALLOC);
        pbuffer(c565, huge_h, EGL_BAD_ALLOC);
        z = pbuffer(c565, largest, EGL_SUCCESS);
        CHECK(query(z, EGL_WIDTH) == 8192 && query(z, EGL_HEIGHT) == 2);
        CHECK(query(z, EGL_LARGEST_PBUFFER) == EGL_TRUE);
        CHECK(eglDestroySurface(dpy, z));
        pbuffer(c565, bad_bool, EGL_BAD_ATTRIBUTE);
        pbuffer(c565, unknown, EGL_BAD_ATTRIBUTE);
        pbuffer(c565, window_only, EGL_BAD_ATTRIBUTE);
        CHECK(eglCreatePbufferSurface(dpy, (EGLConfig)(size_t)40, none) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(eglCreatePbufferSurface((EGLDisplay)(size_t)40, c565, none) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_DISPLAY);
    }

    /* Texture pbuffers. */
    {
        static const EGLint only_format[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGB, EGL_NONE};
        static const EGLint only_target[] = {EGL_TEXTURE_TARGET, EGL_TEXTURE_2D, EGL_NONE};
        static const EGLint rgba[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_TEXTURE_FORMAT,
                                      EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D,
                                      EGL_MIPMAP_TEXTURE, EGL_TRUE, EGL_NONE};
        static const EGLint bad_format[] = {EGL_TEXTURE_FORMAT, 0x1234, EGL_NONE};
        static const EGLint bad_target[] = {EGL_TEXTURE_TARGET, 0x1234, EGL_NONE};
        static const EGLint pre[] = {EGL_VG_ALPHA_FORMAT, EGL_VG_ALPHA_FORMAT_PRE, EGL_NONE};
        pbuffer(c565, only_format, EGL_BAD_MATCH);
        pbuffer(c565, only_target, EGL_BAD_MATCH);
        pbuffer(c565, rgba, EGL_BAD_ATTRIBUTE); /* RGB565 cannot bind as RGBA */
        pbuffer(c565, bad_format, EGL_BAD_ATTRIBUTE);
        pbuffer(c565, bad_target, EGL_BAD_ATTRIBUTE);
        pbuffer(c565, pre, EGL_BAD_MATCH);
        tex = pbuffer(c8888, rgba, EGL_SUCCESS);
        CHECK(query(tex, EGL_TEXTURE_FORMAT) == EGL_TEXTURE_RGBA);
        CHECK(query(tex, EGL_TEXTURE_TARGET) == EGL_TEXTURE_2D);
        CHECK(query(tex, EGL_MIPMAP_TEXTURE) == EGL_TRUE);
    }

    ctx = eglCreateContext(dpy, c8888, EGL_NO_CONTEXT, NULL);
    CHECK(ctx != EGL_NO_CONTEXT);

    /* eglBindTexImage / eglReleaseTexImage. */
    CHECK(!eglBindTexImage(dpy, s, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglBindTexImage(dpy, tex, 0x1234));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!eglBindTexImage(dpy, (EGLSurface)(size_t)5, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglReleaseTexImage(dpy, s, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglReleaseTexImage(dpy, tex, 0x1234));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglMakeCurrent(dpy, s, s, ctx));
    CHECK(eglBindTexImage(dpy, tex, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(!eglBindTexImage(dpy, tex, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_BAD_ACCESS);
    CHECK(eglReleaseTexImage(dpy, tex, EGL_BACK_BUFFER));
    CHECK(eglReleaseTexImage(dpy, tex, EGL_BACK_BUFFER)); /* not bound: no effect */
    CHECK(eglBindTexImage(dpy, tex, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_SUCCESS);

    /* Swap and interval on a pbuffer. */
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(eglSwapBuffers(dpy, s));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(!eglSwapBuffers(dpy, tex)); /* not current */
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglSwapBuffers(dpy, (EGLSurface)(size_t)5));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglSwapBuffers((EGLDisplay)(size_t)5, s));
    CHECK_EGL(EGL_BAD_DISPLAY);
    ct.width = 16;
    ct.height = 8;
    CHECK_PIXEL(3, 3, 0, 255, 0, 255, 0);
    CHECK(eglSwapInterval(dpy, 0));
    CHECK(eglSwapInterval(dpy, 50)); /* clamped */
    CHECK(eglSwapInterval(dpy, -3));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(!eglSwapInterval((EGLDisplay)(size_t)5, 1));
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(eglWaitGL() && eglWaitClient() && eglWaitNative(EGL_CORE_NATIVE_ENGINE));
    CHECK_EGL(EGL_SUCCESS);

    /* Destroying the current surface defers deletion; the handle is invalid at once. */
    CHECK(eglDestroySurface(dpy, s));
    CHECK(eglGetCurrentSurface(EGL_DRAW) == s);
    CHECK(!eglQuerySurface(dpy, s, EGL_WIDTH, &v));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglWaitClient());
    CHECK_EGL(EGL_BAD_CURRENT_SURFACE);
    CHECK(!eglSwapInterval(dpy, 1));
    CHECK_EGL(EGL_BAD_SURFACE);
    glClear(GL_COLOR_BUFFER_BIT); /* still renders into the live surface */
    CHECK_GL(GL_NO_ERROR);
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(!eglDestroySurface(dpy, s));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglSwapInterval(dpy, 1));
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(!eglDestroySurface((EGLDisplay)(size_t)5, tex));
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(eglDestroySurface(dpy, tex));
    CHECK(eglDestroyContext(dpy, ctx));
    CHECK(eglTerminate(dpy));
    CHECK(!eglCreatePbufferSurface(dpy, c565, NULL));
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(eglReleaseThread());
    return ct_done();
}
