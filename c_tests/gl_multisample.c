/*
 * gl_multisample.c: 4-sample configs (EGL_SAMPLE_BUFFERS 1, EGL_SAMPLES 4) and ES 1.1 §3.2 /
 * §4.1.3 multisampling. The sample pattern is the documented rotated grid (0.375, 0.125),
 * (0.875, 0.375), (0.125, 0.625), (0.625, 0.875) and the resolve the rounded box mean, so a
 * pixel whose center lies on an edge resolves to exactly two samples of four: 128 of white
 * over black. Checked: the config attributes and the sort (single-sample first), GL_SAMPLES,
 * antialiased vertical and horizontal edges, GL_MULTISAMPLE disabled equal to a
 * single-sample config bit for bit, glSampleCoverage value and invert, alpha to coverage and
 * alpha to one, resolved pixels through glReadPixels, eglCopyBuffers, eglSwapBuffers on a
 * window, a pixmap surface and eglBindTexImage, and the same pixels for GLES_CM_THREADS 1,
 * 2 and 4.
 *
 * ct:no-diff (the exact edge values follow our documented sample pattern and rounding, and
 * the memory pixmaps and windows are this implementation's native types)
 */
#define _POSIX_C_SOURCE 200809L
#include "common.h"
#include "child_hash.h"

#define W 16
#define H 16

static EGLDisplay dpy;

static const EGLint ms_attribs[] = {
    EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
    EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_SAMPLE_BUFFERS, 1, EGL_SAMPLES, 4,
    EGL_NONE,
};

static EGLint attr(EGLConfig c, EGLint a)
{
    EGLint v = -1;
    eglGetConfigAttrib(dpy, c, a, &v);
    return v;
}

static void pixel_space(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, (GLfloat)w, 0, (GLfloat)h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void rect(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1)
{
    GLfloat v[] = {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

/* Black, then a white rectangle whose right edge (x = 2.5) halves pixel column 2. */
static void edge_scene(void)
{
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor4f(1, 1, 1, 1);
    rect(0, 0, 2.5f, H);
}

/* Red of columns 0..3 of row y must be a, b, c, d. */
static void check_row(int y, int a, int b, int c, int d)
{
    CHECK_PIXEL(0, y, a, a, a, a, 0);
    CHECK_PIXEL(1, y, b, b, b, b, 0);
    CHECK_PIXEL(2, y, c, c, c, c, 0);
    CHECK_PIXEL(3, y, d, d, d, d, 0);
}

/* A scene of many overlapping, depth-tested triangles with edges at arbitrary positions. */
static void busy_scene(int w, int h)
{
    uint32_t s = 12345;
    int i, k;
    pixel_space(w, h);
    glClearColor(0.1f, 0.2f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnableClientState(GL_VERTEX_ARRAY);
    for (i = 0; i < 300; ++i) {
        GLfloat v[9];
        for (k = 0; k < 9; ++k) {
            s = s * 1664525u + 1013904223u;
            v[k] = (GLfloat)((s >> 8) % 100000) / 100000.0f;
        }
        for (k = 0; k < 3; ++k) {
            v[3 * k] *= (GLfloat)w;
            v[3 * k + 1] *= (GLfloat)h;
            v[3 * k + 2] = v[3 * k + 2] * 2 - 1;
        }
        glColor4f(v[2] * 0.5f + 0.5f, v[5] * 0.5f + 0.5f, v[8] * 0.5f + 0.5f, 1);
        glVertexPointer(3, GL_FLOAT, 0, v);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_DEPTH_TEST);
}

/* FNV-1a of the busy scene on a 4-sample pbuffer (run through ct_child_hash); 0 when
 * anything fails. */
static uint64_t busy_hash(void)
{
    static GLubyte px[64 * 64 * 4];
    GLint samples = 0;
    ct_init_config(64, 64, ms_attribs);
    glGetIntegerv(GL_SAMPLES, &samples);
    busy_scene(64, 64);
    glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, px);
    if (samples != 4 || glGetError() != GL_NO_ERROR)
        return 0;
    return ct_fnv1a(1469598103934665603ull, px, sizeof px);
}

static void configs(void)
{
    EGLConfig c[64];
    EGLint n = 0, i, any[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    CHECK(eglChooseConfig(dpy, ms_attribs, c, 64, &n) && n >= 1);
    for (i = 0; i < n; ++i)
        CHECK(attr(c[i], EGL_SAMPLE_BUFFERS) == 1 && attr(c[i], EGL_SAMPLES) == 4);
    CHECK((attr(c[0], EGL_SURFACE_TYPE) & (EGL_PBUFFER_BIT | EGL_PIXMAP_BIT | EGL_WINDOW_BIT)) ==
          (EGL_PBUFFER_BIT | EGL_PIXMAP_BIT | EGL_WINDOW_BIT));
    CHECK(attr(c[0], EGL_RED_SIZE) == 8 && attr(c[0], EGL_ALPHA_SIZE) == 8);
    /* Without samples requested, fewer samples sort first (EGL 1.4 §3.4.1). */
    CHECK(eglChooseConfig(dpy, any, c, 64, &n) && n >= 2);
    CHECK(attr(c[0], EGL_SAMPLES) == 0 && attr(c[0], EGL_SAMPLE_BUFFERS) == 0);
    for (i = 1; i < n; ++i)
        if (attr(c[i], EGL_BUFFER_SIZE) == attr(c[i - 1], EGL_BUFFER_SIZE))
            CHECK(attr(c[i], EGL_SAMPLES) >= attr(c[i - 1], EGL_SAMPLES));
    if (ct_strict()) {
        EGLint want[] = {EGL_SAMPLES, 5, EGL_NONE};
        CHECK(eglChooseConfig(dpy, want, c, 64, &n) && n == 0);
    }
}

static void masks(void)
{
    /* glSampleCoverage 0.5: samples 0 and 1 (of which 0 is left of x = 2.5). */
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.5f, GL_FALSE);
    edge_scene();
    check_row(5, 128, 128, 64, 0);
    /* Inverted: samples 2 and 3 (2 left of the edge). */
    glSampleCoverage(0.5f, GL_TRUE);
    edge_scene();
    check_row(5, 128, 128, 64, 0);
    /* 0.25: sample 0; inverted: 1, 2 and 3. */
    glSampleCoverage(0.25f, GL_FALSE);
    edge_scene();
    check_row(5, 64, 64, 64, 0);
    glSampleCoverage(0.25f, GL_TRUE);
    edge_scene();
    check_row(5, 191, 191, 64, 0);
    glSampleCoverage(0.0f, GL_FALSE);
    edge_scene();
    check_row(5, 0, 0, 0, 0);
    glSampleCoverage(1.0f, GL_FALSE);
    glDisable(GL_SAMPLE_COVERAGE);

    /* Alpha to coverage: alpha 0.5 (128) covers samples 0 and 1. */
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 1, 1, 0.5f);
    rect(0, 0, 2.5f, H);
    CHECK_PIXEL(0, 5, 128, 128, 128, 64, 0);
    CHECK_PIXEL(2, 5, 64, 64, 64, 32, 0);
    /* Alpha 0.2 (51): one sample; alpha 0.1 (26): none. */
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 1, 1, 0.2f);
    rect(0, 0, 2.5f, H);
    CHECK_PIXEL(0, 5, 64, 64, 64, 13, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 1, 1, 0.1f);
    rect(0, 0, 2.5f, H);
    CHECK_PIXEL(0, 5, 0, 0, 0, 0, 0);
    /* Alpha to one: the covered samples store alpha 1. */
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 1, 1, 0.5f);
    rect(0, 0, 2.5f, H);
    CHECK_PIXEL(0, 5, 128, 128, 128, 128, 0);
    /* ... before the alpha test (§4.1.3 precedes §4.1.4): alpha 1 passes GL_GREATER 0.9. */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.9f);
    glClear(GL_COLOR_BUFFER_BIT);
    rect(0, 0, 2.5f, H);
    CHECK_PIXEL(0, 5, 128, 128, 128, 128, 0);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    /* Both masks are multisample operations: off with GL_MULTISAMPLE. */
    glDisable(GL_MULTISAMPLE);
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.0f, GL_FALSE);
    edge_scene();
    check_row(5, 255, 255, 0, 0);
    glDisable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(1.0f, GL_FALSE);
    glEnable(GL_MULTISAMPLE);
    CHECK_GL(GL_NO_ERROR);
}

/* GL_MULTISAMPLE disabled on the 4-sample surface gives the single-sample config's pixels. */
static void disabled_equals_single_sample(void)
{
    static const EGLint single_attribs[] = {
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
        EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_SAMPLES, 0, EGL_SURFACE_TYPE,
        EGL_PBUFFER_BIT, EGL_NONE,
    };
    static const EGLint size[] = {EGL_WIDTH, 64, EGL_HEIGHT, 64, EGL_NONE};
    static GLubyte a[64 * 64 * 4], b[64 * 64 * 4], c[64 * 64 * 4];
    EGLConfig single = NULL;
    EGLint n = 0;
    EGLSurface s1, s4;
    EGLContext x1, x4;
    CHECK(eglChooseConfig(dpy, single_attribs, &single, 1, &n) && n == 1);
    CHECK(attr(single, EGL_SAMPLES) == 0);
    s1 = eglCreatePbufferSurface(dpy, single, size);
    s4 = eglCreatePbufferSurface(dpy, ct.config, size);
    x1 = eglCreateContext(dpy, single, EGL_NO_CONTEXT, NULL);
    x4 = eglCreateContext(dpy, ct.config, EGL_NO_CONTEXT, NULL);
    CHECK(s1 && s4 && x1 && x4);

    CHECK(eglMakeCurrent(dpy, s1, s1, x1));
    {
        GLint sb = -1, sm = -1;
        glGetIntegerv(GL_SAMPLE_BUFFERS, &sb);
        glGetIntegerv(GL_SAMPLES, &sm);
        CHECK(sb == 0 && sm == 0);
    }
    busy_scene(64, 64);
    glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, a);
    CHECK(eglMakeCurrent(dpy, s4, s4, x4));
    glDisable(GL_MULTISAMPLE);
    busy_scene(64, 64);
    glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, b);
    CHECK(memcmp(a, b, sizeof a) == 0);
    glEnable(GL_MULTISAMPLE);
    busy_scene(64, 64);
    glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, c);
    CHECK(memcmp(a, c, sizeof a) != 0);
    CHECK_GL(GL_NO_ERROR);
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, ct.context));
    eglDestroyContext(dpy, x1);
    eglDestroyContext(dpy, x4);
    eglDestroySurface(dpy, s1);
    eglDestroySurface(dpy, s4);
}

/* eglCopyBuffers, a window's eglSwapBuffers and a pixmap surface see resolved pixels. */
static void native_surfaces(void)
{
    uint8_t pm_px[W * H * 4], win_px[W * H * 4], sp_px[W * H * 4];
    EGLMemoryPixmap pm = {W, H, W * 4, EGL_MEMORY_RGBA8888, NULL};
    EGLMemoryPixmap spm = {W, H, W * 4, EGL_MEMORY_RGBA8888, NULL};
    EGLMemoryWindow win = {W, H, W * 4, EGL_MEMORY_RGBA8888, NULL};
    EGLSurface ws, ps;
    pm.pixels = pm_px;
    spm.pixels = sp_px;
    win.pixels = win_px;

    edge_scene();
    memset(pm_px, 0x55, sizeof pm_px);
    CHECK(eglCopyBuffers(dpy, ct.surface, &pm));
    /* Row 0 of the pixmap is the top; every row is alike. */
    CHECK(pm_px[4 * 1] == 255 && pm_px[4 * 2] == 128 && pm_px[4 * 2 + 3] == 128 &&
          pm_px[4 * 3] == 0);

    ws = eglCreateWindowSurface(dpy, ct.config, &win, NULL);
    CHECK(ws != EGL_NO_SURFACE);
    CHECK(eglMakeCurrent(dpy, ws, ws, ct.context));
    pixel_space(W, H);
    edge_scene();
    memset(win_px, 0x55, sizeof win_px);
    CHECK(eglSwapBuffers(dpy, ws));
    CHECK(win_px[4 * W * 7 + 4 * 2] == 128 && win_px[4 * W * 7 + 4 * 2 + 3] == 128);

    memset(sp_px, 0, sizeof sp_px);
    ps = eglCreatePixmapSurface(dpy, ct.config, &spm, NULL);
    CHECK(ps != EGL_NO_SURFACE);
    CHECK(eglMakeCurrent(dpy, ps, ps, ct.context));
    {
        GLint sm = 0;
        glGetIntegerv(GL_SAMPLES, &sm);
        CHECK(sm == 4);
    }
    pixel_space(W, H);
    glColor4f(1, 1, 1, 1);
    rect(0, 0, W, 2.5f); /* a horizontal edge: row 2 is half covered */
    glFinish();
    /* Pixmap row 0 is the top: GL row 2 is pixmap row H - 3. */
    CHECK(sp_px[4 * W * (H - 1)] == 255 && sp_px[4 * W * (H - 3)] == 128 &&
          sp_px[4 * W * (H - 4)] == 0);
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, ct.context));
    eglDestroySurface(dpy, ws);
    eglDestroySurface(dpy, ps);
    CHECK_EGL(EGL_SUCCESS);
}

/* A 4-sample pbuffer bound with eglBindTexImage gives its resolved pixels as texels. */
static void bind_tex_image(void)
{
    static const EGLint tex_attribs[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_TEXTURE_FORMAT,
                                         EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D,
                                         EGL_NONE};
    static const GLfloat uv[] = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1};
    EGLSurface src = eglCreatePbufferSurface(dpy, ct.config, tex_attribs);
    GLuint tex = 0;
    CHECK(src != EGL_NO_SURFACE);
    CHECK(eglMakeCurrent(dpy, src, src, ct.context));
    pixel_space(W, H);
    edge_scene();
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, ct.context));
    pixel_space(W, H);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    CHECK(eglBindTexImage(dpy, src, EGL_BACK_BUFFER));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, uv);
    rect(0, 0, W, H);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisable(GL_TEXTURE_2D);
    check_row(9, 255, 255, 128, 0);
    CHECK(eglReleaseTexImage(dpy, src, EGL_BACK_BUFFER));
    glDeleteTextures(1, &tex);
    eglDestroySurface(dpy, src);
    CHECK_GL(GL_NO_ERROR);
    CHECK_EGL(EGL_SUCCESS);
}

int main(void)
{
    /* Before anything starts the library in this process: children with their own
     * thread counts. */
    uint64_t h1 = ct_child_hash("1", busy_hash), h2 = ct_child_hash("2", busy_hash),
             h4 = ct_child_hash("4", busy_hash);
    GLint sb = -1, sm = -1;
    CHECK(h1 != 0 && h1 == h2 && h1 == h4);

    ct_init_config(W, H, ms_attribs);
    dpy = ct.display;
    CHECK(attr(ct.config, EGL_SAMPLES) == 4 && attr(ct.config, EGL_SAMPLE_BUFFERS) == 1);
    configs();
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sb);
    glGetIntegerv(GL_SAMPLES, &sm);
    CHECK(sb == 1 && sm == 4);
    CHECK(glIsEnabled(GL_MULTISAMPLE));
    pixel_space(W, H);

    /* A vertical edge at x = 2.5: samples at x + 0.125 and x + 0.375 are inside. */
    edge_scene();
    check_row(0, 255, 255, 128, 0);
    check_row(15, 255, 255, 128, 0);
    ct_save("edge");
    /* A horizontal edge at y = 2.5. */
    glClear(GL_COLOR_BUFFER_BIT);
    rect(0, 0, W, 2.5f);
    CHECK_PIXEL(7, 1, 255, 255, 255, 255, 0);
    CHECK_PIXEL(7, 2, 128, 128, 128, 128, 0);
    CHECK_PIXEL(7, 3, 0, 0, 0, 0, 0);
    /* GL_MULTISAMPLE disabled: pixel-center coverage for every sample (the center of
     * column 2 is on the right edge, outside under the top-left rule). */
    glDisable(GL_MULTISAMPLE);
    edge_scene();
    check_row(0, 255, 255, 0, 0);
    glEnable(GL_MULTISAMPLE);

    masks();
    disabled_equals_single_sample();
    native_surfaces();
    bind_tex_image();
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
