/*
 * egl_display.c: eglGetDisplay, eglInitialize/eglTerminate (repeatable), eglQueryString,
 * eglGetError's per-call reset, eglBindAPI/eglQueryAPI, eglWaitNative/eglWaitGL/eglWaitClient
 * without a context, eglGetProcAddress and eglReleaseThread.
 */
#include "common.h"

typedef EGLint (*get_error_fn)(void);

int main(void)
{
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLDisplay bogus = (EGLDisplay)(size_t)0x7777;
    EGLint major = -1, minor = -1;
    const char *s;

    CHECK(dpy != EGL_NO_DISPLAY);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglGetDisplay(EGL_DEFAULT_DISPLAY) == dpy);

    /* Before eglInitialize. */
    CHECK(eglQueryString(dpy, EGL_VENDOR) == NULL);
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(!eglInitialize(EGL_NO_DISPLAY, NULL, NULL));
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(!eglInitialize(bogus, NULL, NULL));
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK(!eglTerminate(bogus));
    CHECK_EGL(EGL_BAD_DISPLAY);
    /* Terminating an uninitialized display is allowed. */
    CHECK(eglTerminate(dpy));
    CHECK_EGL(EGL_SUCCESS);

    CHECK(eglInitialize(dpy, &major, &minor));
    CHECK(major == 1 && minor >= 4);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglInitialize(dpy, NULL, NULL));
    CHECK_EGL(EGL_SUCCESS);

    s = eglQueryString(dpy, EGL_VERSION);
    CHECK(s != NULL && s[0] == '1' && s[1] == '.');
    CHECK(eglQueryString(dpy, EGL_VENDOR) != NULL);
    CHECK(eglQueryString(dpy, EGL_EXTENSIONS) != NULL);
    s = eglQueryString(dpy, EGL_CLIENT_APIS);
    CHECK(s != NULL && strstr(s, "OpenGL_ES") != NULL);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglQueryString(dpy, 0x1234) == NULL);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglQueryString(bogus, EGL_VENDOR) == NULL);
    CHECK_EGL(EGL_BAD_DISPLAY);

    /* eglGetError resets to EGL_SUCCESS once read. */
    eglQueryString(dpy, 0x1234);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK_EGL(EGL_SUCCESS);
    /* A successful call resets the error too. */
    eglQueryString(dpy, 0x1234);
    CHECK(eglQueryString(dpy, EGL_VENDOR) != NULL);
    CHECK_EGL(EGL_SUCCESS);

    /* Client API. */
    CHECK(eglQueryAPI() == EGL_OPENGL_ES_API);
    CHECK(eglBindAPI(EGL_OPENGL_ES_API));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(!eglBindAPI(0x1234));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglQueryAPI() == EGL_OPENGL_ES_API);

    /* Waits without a current context succeed. */
    CHECK(eglWaitClient());
    CHECK(eglWaitGL());
    CHECK(eglWaitNative(EGL_CORE_NATIVE_ENGINE));
    CHECK_EGL(EGL_SUCCESS);

    /* eglGetProcAddress: core and GL functions too. */
    {
        get_error_fn f = (get_error_fn)eglGetProcAddress("eglGetError");
        CHECK(f != NULL);
        if (f) {
            eglQueryString(dpy, 0x1234);
            CHECK(f() == EGL_BAD_PARAMETER);
        }
        CHECK(eglGetProcAddress("glClear") != NULL);
        CHECK(eglGetProcAddress("eglMakeCurrent") != NULL);
    }

    CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT);
    CHECK(eglGetCurrentDisplay() == EGL_NO_DISPLAY);
    CHECK(eglGetCurrentSurface(EGL_DRAW) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_SUCCESS);

    /* Repeated terminate and initialize. */
    CHECK(eglTerminate(dpy));
    CHECK(eglTerminate(dpy));
    CHECK(eglQueryString(dpy, EGL_VENDOR) == NULL);
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(eglInitialize(dpy, &major, &minor));
    CHECK(eglQueryString(dpy, EGL_VENDOR) != NULL);
    CHECK(eglTerminate(dpy));

    CHECK(eglReleaseThread());
    CHECK_EGL(EGL_SUCCESS);
    return ct_done();
}
