/*
 * egl_pixmap_window.c: memory windows (eglSwapBuffers converts the back buffer into the
 * window's format, row 0 at the top) and memory pixmaps (initialized from the pixmap,
 * results written back on glFinish / eglWaitGL / release), eglCopyBuffers, and their errors.
 * ct:no-diff (EGLMemoryPixmap / EGLMemoryWindow are this implementation's native types)
 */
#include "common.h"

#include <stdint.h>

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

/* Red bottom half, blue top half (GL y up). */
static void draw_halves(int w, int h)
{
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, w, h / 2);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(0, h / 2, w, h - h / 2);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

int main(void)
{
    EGLConfig c565 = NULL, c888, c8888;
    EGLContext ctx;
    uint8_t win_px[4 * 8 * 10];
    uint16_t px565[4 * 4];
    uint8_t pm_px[4 * 4 * 4];
    EGLMemoryWindow win = {4, 8, 40, EGL_MEMORY_BGRA8888, NULL};
    EGLMemoryPixmap pm = {4, 4, 16, EGL_MEMORY_RGBA8888, NULL};
    EGLMemoryPixmap p565 = {4, 4, 8, EGL_MEMORY_RGB565, NULL};
    EGLSurface ws, ps;
    EGLint v;
    int i;

    win.pixels = win_px;
    pm.pixels = pm_px;
    p565.pixels = px565;
    memset(win_px, 0x55, sizeof win_px);
    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(eglInitialize(dpy, NULL, NULL));
    c565 = config_id(1);
    c888 = config_id(7);
    c8888 = config_id(18);

    /* Window surface. */
    ws = eglCreateWindowSurface(dpy, c8888, &win, NULL);
    CHECK(ws != EGL_NO_SURFACE);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglQuerySurface(dpy, ws, EGL_WIDTH, &v) && v == 4);
    CHECK(eglQuerySurface(dpy, ws, EGL_HEIGHT, &v) && v == 8);
    CHECK(eglQuerySurface(dpy, ws, EGL_RENDER_BUFFER, &v) && v == EGL_BACK_BUFFER);
    v = 77;
    CHECK(eglQuerySurface(dpy, ws, EGL_TEXTURE_FORMAT, &v) && v == 77); /* not a pbuffer */
    CHECK(eglCreateWindowSurface(dpy, c8888, &win, NULL) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_ALLOC); /* already has a surface */
    {
        EGLMemoryWindow bad = win;
        static const EGLint single[] = {EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER, EGL_NONE};
        static const EGLint bad_rb[] = {EGL_RENDER_BUFFER, 0x1234, EGL_NONE};
        static const EGLint pb_attr[] = {EGL_WIDTH, 4, EGL_NONE};
        EGLMemoryWindow w2 = win;
        EGLSurface s2;
        CHECK(eglCreateWindowSurface(dpy, c8888, NULL, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_NATIVE_WINDOW);
        bad.format = 99;
        CHECK(eglCreateWindowSurface(dpy, c8888, &bad, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_NATIVE_WINDOW);
        bad = win;
        bad.stride = 3;
        CHECK(eglCreateWindowSurface(dpy, c8888, &bad, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_NATIVE_WINDOW);
        bad = win;
        bad.pixels = NULL;
        CHECK(eglCreateWindowSurface(dpy, c8888, &bad, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_NATIVE_WINDOW);
        CHECK(eglCreateWindowSurface(dpy, c8888, &w2, bad_rb) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
        CHECK(eglCreateWindowSurface(dpy, c8888, &w2, pb_attr) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
        CHECK(eglCreateWindowSurface(dpy, (EGLConfig)(size_t)50, &w2, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(eglCreateWindowSurface((EGLDisplay)(size_t)50, c8888, &w2, NULL) ==
              EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_DISPLAY);
        s2 = eglCreateWindowSurface(dpy, c8888, &w2, single);
        CHECK(s2 != EGL_NO_SURFACE);
        CHECK(eglQuerySurface(dpy, s2, EGL_RENDER_BUFFER, &v) && v == EGL_SINGLE_BUFFER);
        CHECK(eglDestroySurface(dpy, s2));
        /* Once destroyed, the window may get a surface again. */
        s2 = eglCreateWindowSurface(dpy, c565, &w2, NULL);
        CHECK(s2 != EGL_NO_SURFACE);
        CHECK(eglDestroySurface(dpy, s2));
    }

    ctx = eglCreateContext(dpy, c8888, EGL_NO_CONTEXT, NULL);
    CHECK(eglMakeCurrent(dpy, ws, ws, ctx));
    draw_halves(4, 8);
    /* Nothing reaches the window before eglSwapBuffers. */
    CHECK(win_px[0] == 0x55);
    CHECK(eglSwapBuffers(dpy, ws));
    CHECK_EGL(EGL_SUCCESS);
    /* Row 0 of the window is the top: blue, in BGRA order. */
    CHECK(win_px[0] == 255 && win_px[1] == 0 && win_px[2] == 0 && win_px[3] == 255);
    CHECK(win_px[7 * 40 + 0] == 0 && win_px[7 * 40 + 2] == 255 && win_px[7 * 40 + 3] == 255);
    CHECK(win_px[16] == 0x55); /* the bytes past each row are left alone */
    /* The back buffer is preserved. */
    ct.width = 4;
    ct.height = 8;
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);
    CHECK(eglQuerySurface(dpy, ws, EGL_SWAP_BEHAVIOR, &v) && v == EGL_BUFFER_PRESERVED);
    CHECK(eglSwapInterval(dpy, 1));
    CHECK(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &v) && v == EGL_BACK_BUFFER);

    /* eglCopyBuffers from the window into an RGBA8888 pixmap (4x4: the bottom rows). */
    {
        EGLMemoryPixmap bad = pm;
        memset(pm_px, 0, sizeof pm_px);
        CHECK(eglCopyBuffers(dpy, ws, &pm));
        CHECK_EGL(EGL_SUCCESS);
        /* Only the overlap (the top 4 rows, as row 0 is the top of both) is written. */
        CHECK(pm_px[0] == 0 && pm_px[2] == 255 && pm_px[3] == 255);
        CHECK(!eglCopyBuffers(dpy, ws, NULL));
        CHECK_EGL(EGL_BAD_NATIVE_PIXMAP);
        bad.width = -1;
        CHECK(!eglCopyBuffers(dpy, ws, &bad));
        CHECK_EGL(EGL_BAD_NATIVE_PIXMAP);
        CHECK(!eglCopyBuffers(dpy, ws, &p565));
        CHECK_EGL(EGL_BAD_MATCH);
        CHECK(!eglCopyBuffers(dpy, (EGLSurface)(size_t)50, &pm));
        CHECK_EGL(EGL_BAD_SURFACE);
        CHECK(!eglCopyBuffers((EGLDisplay)(size_t)50, ws, &pm));
        CHECK_EGL(EGL_BAD_DISPLAY);
    }
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(!eglSwapBuffers(dpy, ws));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(eglDestroyContext(dpy, ctx));

    /* Other window formats, through an RGB565 config. */
    {
        uint8_t rgb[4 * 2 * 3];
        uint16_t w565[4 * 2];
        EGLMemoryWindow wr = {4, 2, 12, EGL_MEMORY_RGB888, NULL};
        EGLMemoryWindow w6 = {4, 2, 8, EGL_MEMORY_RGB565, NULL};
        EGLSurface a, b;
        wr.pixels = rgb;
        w6.pixels = w565;
        ctx = eglCreateContext(dpy, c565, EGL_NO_CONTEXT, NULL);
        a = eglCreateWindowSurface(dpy, c565, &wr, NULL);
        b = eglCreateWindowSurface(dpy, c565, &w6, NULL);
        CHECK(a && b && ctx);
        CHECK(eglMakeCurrent(dpy, a, a, ctx));
        glClearColor(1, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK(eglSwapBuffers(dpy, a));
        CHECK(rgb[0] == 255 && rgb[1] == 255 && rgb[2] == 0 && rgb[21] == 255);
        CHECK(eglMakeCurrent(dpy, b, b, ctx));
        glClearColor(0, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK(eglSwapBuffers(dpy, b));
        CHECK(w565[0] == 0x07E0 && w565[7] == 0x07E0);
        CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
        CHECK(eglDestroySurface(dpy, a) && eglDestroySurface(dpy, b));
        CHECK(eglDestroyContext(dpy, ctx));
    }

    /* Pixmap surfaces. */
    for (i = 0; i < 16; ++i) {
        pm_px[4 * i + 0] = 10;
        pm_px[4 * i + 1] = 20;
        pm_px[4 * i + 2] = 30;
        pm_px[4 * i + 3] = 40;
    }
    CHECK(eglCreatePixmapSurface(dpy, c888, &pm, NULL) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_MATCH); /* RGBA pixmap, RGB888 config */
    CHECK(eglCreatePixmapSurface(dpy, c8888, NULL, NULL) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_NATIVE_PIXMAP);
    {
        static const EGLint rb[] = {EGL_RENDER_BUFFER, EGL_BACK_BUFFER, EGL_NONE};
        CHECK(eglCreatePixmapSurface(dpy, c8888, &pm, rb) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
    }
    ps = eglCreatePixmapSurface(dpy, c8888, &pm, NULL);
    CHECK(ps != EGL_NO_SURFACE);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglCreatePixmapSurface(dpy, c8888, &pm, NULL) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_ALLOC);
    CHECK(eglQuerySurface(dpy, ps, EGL_RENDER_BUFFER, &v) && v == EGL_SINGLE_BUFFER);
    ctx = eglCreateContext(dpy, c8888, EGL_NO_CONTEXT, NULL);
    CHECK(eglMakeCurrent(dpy, ps, ps, ctx));
    CHECK(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &v) && v == EGL_SINGLE_BUFFER);
    ct.width = ct.height = 4;
    CHECK_PIXEL(1, 1, 10, 20, 30, 40, 0); /* initialized from the pixmap */
    draw_halves(4, 4);
    glFinish();
    /* Row 0 of the pixmap is the top: blue. */
    CHECK(pm_px[0] == 0 && pm_px[1] == 0 && pm_px[2] == 255 && pm_px[3] == 255);
    CHECK(pm_px[3 * 16] == 255 && pm_px[3 * 16 + 2] == 0);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(eglWaitGL());
    CHECK(pm_px[1] == 255 && pm_px[0] == 0);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(eglWaitClient());
    CHECK(pm_px[0] == 255 && pm_px[2] == 255);
    /* Native rendering, then eglWaitNative: GL sees it. */
    pm_px[0] = 7;
    pm_px[1] = 8;
    pm_px[2] = 9;
    CHECK(eglWaitNative(EGL_CORE_NATIVE_ENGINE));
    CHECK_PIXEL(0, 3, 7, 8, 9, 255, 0);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(eglSwapBuffers(dpy, ps)); /* no effect on a pixmap */
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(pm_px[0] == 0 && pm_px[3] == 0); /* written back on release */
    CHECK(eglDestroySurface(dpy, ps));
    CHECK(eglDestroyContext(dpy, ctx));

    /* RGB565 pixmap. */
    for (i = 0; i < 16; ++i)
        px565[i] = 0xF800;
    ctx = eglCreateContext(dpy, c565, EGL_NO_CONTEXT, NULL);
    ps = eglCreatePixmapSurface(dpy, c565, &p565, NULL);
    CHECK(ps && ctx);
    CHECK(eglMakeCurrent(dpy, ps, ps, ctx));
    CHECK_PIXEL(2, 2, 255, 0, 0, 255, 0);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    CHECK(px565[0] == 0x001F && px565[15] == 0x001F);
    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(eglDestroySurface(dpy, ps));
    CHECK(eglDestroyContext(dpy, ctx));

    CHECK(eglDestroySurface(dpy, ws));
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    return ct_done();
}
