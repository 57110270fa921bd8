/*
 * egl_thread_exit.c: a thread that exits with a context current no longer holds it, so
 * another thread can make it current (this implementation releases it at thread exit).
 * ct:no-diff (EGL 1.4 leaves thread exit without eglReleaseThread undefined)
 */
#define _POSIX_C_SOURCE 200809L
#include "common.h"

#include <pthread.h>

static EGLDisplay dpy;
static EGLSurface s;
static EGLContext c;

static void *bind_and_exit(void *arg)
{
    (void)arg;
    CHECK(eglMakeCurrent(dpy, s, s, c));
    return NULL;
}

int main(void)
{
    static const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    pthread_t t;

    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(eglInitialize(dpy, NULL, NULL));
    CHECK(eglGetConfigs(dpy, &cfg, 1, &n) && n == 1);
    s = eglCreatePbufferSurface(dpy, cfg, size);
    c = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, NULL);
    CHECK(pthread_create(&t, NULL, bind_and_exit, NULL) == 0);
    CHECK(pthread_join(t, NULL) == 0);
    CHECK(eglMakeCurrent(dpy, s, s, c));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(eglDestroySurface(dpy, s) && eglDestroyContext(dpy, c));
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    return ct_done();
}
