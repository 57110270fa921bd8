/*
 * egl_threads.c: per-thread current contexts and errors. A context (or surface) current on
 * one thread cannot be made current on another (EGL_BAD_ACCESS); after release, or after
 * the owning thread exits, it can. eglGetError is per thread.
 */
#define _POSIX_C_SOURCE 200809L
#include "common.h"

#include <pthread.h>

static EGLDisplay dpy;
static EGLConfig cfg;
static EGLSurface s1, s2;
static EGLContext c1, c2;

static void *other_thread(void *arg)
{
    int phase = *(int *)arg;
    if (phase == 0) {
        /* c1 and s1 are current on the main thread. */
        CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT);
        CHECK_EGL(EGL_SUCCESS); /* the main thread's error is not ours */
        CHECK(!eglMakeCurrent(dpy, s2, s2, c1));
        CHECK_EGL(EGL_BAD_ACCESS);
        CHECK(!eglMakeCurrent(dpy, s1, s1, c2));
        CHECK_EGL(EGL_BAD_ACCESS);
        CHECK(eglMakeCurrent(dpy, s2, s2, c2));
        CHECK_EGL(EGL_SUCCESS);
        glClearColor(0, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    } else if (phase == 1) {
        /* The main thread released c1: take it, and exit with it current. */
        CHECK(eglMakeCurrent(dpy, s1, s1, c1));
        CHECK_EGL(EGL_SUCCESS);
        CHECK(eglGetCurrentContext() == c1);
        CHECK(eglReleaseThread());
    } else {
        CHECK(eglMakeCurrent(dpy, s2, s2, c2));
    }
    return NULL;
}

static void run(int phase)
{
    pthread_t t;
    CHECK(pthread_create(&t, NULL, other_thread, &phase) == 0);
    CHECK(pthread_join(t, NULL) == 0);
}

int main(void)
{
    static const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
                                     EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, EGL_NONE};
    static const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
    EGLint n = 0;

    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(eglInitialize(dpy, NULL, NULL));
    CHECK(eglChooseConfig(dpy, attribs, &cfg, 1, &n) && n == 1);
    s1 = eglCreatePbufferSurface(dpy, cfg, size);
    s2 = eglCreatePbufferSurface(dpy, cfg, size);
    c1 = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, NULL);
    c2 = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, NULL);
    CHECK(s1 && s2 && c1 && c2);

    CHECK(eglMakeCurrent(dpy, s1, s1, c1));
    eglQueryString(dpy, 0x1234); /* leaves EGL_BAD_PARAMETER on this thread */
    run(0);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglGetCurrentContext() == c1);

    /* The other thread rendered into s2 with c2 and released it. */
    CHECK(eglMakeCurrent(dpy, s2, s2, c2));
    ct.width = ct.height = 8;
    CHECK_PIXEL(4, 4, 0, 255, 0, 255, 0);

    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    run(1);
    /* The other thread released c1 (eglReleaseThread) before exiting. */
    CHECK(eglMakeCurrent(dpy, s1, s1, c1));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));

    CHECK(eglDestroySurface(dpy, s1));
    CHECK(eglDestroySurface(dpy, s2));
    CHECK(eglDestroyContext(dpy, c1));
    CHECK(eglDestroyContext(dpy, c2));
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    return ct_done();
}
