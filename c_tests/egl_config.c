/*
 * egl_config.c: the 36 configs (RGB565/RGB888/RGBA8888 x depth 0/16/24 x stencil 0/8 x
 * samples 0/4; ids 19-36 repeat 1-18 with EGL_SAMPLE_BUFFERS 1), every table 3.1 attribute, eglGetConfigs and eglChooseConfig's matching and sorting, and
 * their errors.
 * ct:no-diff (the config list is this implementation's)
 */
#include "common.h"

static EGLDisplay dpy;

static EGLint attr(EGLConfig c, EGLint a)
{
    EGLint v = -12345;
    CHECK(eglGetConfigAttrib(dpy, c, a, &v));
    return v;
}

static EGLint choose(const EGLint *attribs, EGLConfig *out, EGLint size)
{
    EGLint n = -1;
    CHECK(eglChooseConfig(dpy, attribs, out, size, &n));
    CHECK_EGL(EGL_SUCCESS);
    return n;
}

int main(void)
{
    EGLConfig configs[64];
    EGLint n = -1, i;

    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(!eglGetConfigs(dpy, configs, 64, &n));
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(eglInitialize(dpy, NULL, NULL));

    CHECK(eglGetConfigs(dpy, NULL, 0, &n) && n == 36);
    CHECK(eglGetConfigs(dpy, configs, 5, &n) && n == 5);
    CHECK(eglGetConfigs(dpy, configs, 64, &n) && n == 36);
    CHECK(!eglGetConfigs(dpy, configs, 64, NULL));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!eglGetConfigs((EGLDisplay)(size_t)99, configs, 64, &n));
    CHECK_EGL(EGL_BAD_DISPLAY);

    for (i = 0; i < 36; ++i) {
        EGLConfig c = configs[i];
        EGLint color = i % 18 / 6, depth = (i / 2) % 3, stencil = i % 2, ms = i / 18;
        EGLint r = attr(c, EGL_RED_SIZE), g = attr(c, EGL_GREEN_SIZE);
        EGLint b = attr(c, EGL_BLUE_SIZE), a = attr(c, EGL_ALPHA_SIZE);
        CHECK(attr(c, EGL_CONFIG_ID) == i + 1);
        CHECK(r == (color == 0 ? 5 : 8) && g == (color == 0 ? 6 : 8) && b == r);
        CHECK(a == (color == 2 ? 8 : 0));
        CHECK(attr(c, EGL_BUFFER_SIZE) == r + g + b + a);
        CHECK(attr(c, EGL_DEPTH_SIZE) == (depth == 0 ? 0 : depth == 1 ? 16 : 24));
        CHECK(attr(c, EGL_STENCIL_SIZE) == stencil * 8);
        CHECK(attr(c, EGL_LUMINANCE_SIZE) == 0);
        CHECK(attr(c, EGL_ALPHA_MASK_SIZE) == 0);
        CHECK(attr(c, EGL_BIND_TO_TEXTURE_RGB) == EGL_TRUE);
        CHECK(attr(c, EGL_BIND_TO_TEXTURE_RGBA) == (a ? EGL_TRUE : EGL_FALSE));
        CHECK(attr(c, EGL_COLOR_BUFFER_TYPE) == EGL_RGB_BUFFER);
        CHECK(attr(c, EGL_CONFIG_CAVEAT) == EGL_NONE);
        CHECK(attr(c, EGL_CONFORMANT) == EGL_OPENGL_ES_BIT);
        CHECK(attr(c, EGL_RENDERABLE_TYPE) == EGL_OPENGL_ES_BIT);
        CHECK(attr(c, EGL_LEVEL) == 0);
        CHECK(attr(c, EGL_MAX_PBUFFER_WIDTH) == 8192);
        CHECK(attr(c, EGL_MAX_PBUFFER_HEIGHT) == 8192);
        CHECK(attr(c, EGL_MAX_PBUFFER_PIXELS) == 8192 * 8192);
        CHECK(attr(c, EGL_MIN_SWAP_INTERVAL) == 0);
        CHECK(attr(c, EGL_MAX_SWAP_INTERVAL) == 1);
        CHECK(attr(c, EGL_NATIVE_RENDERABLE) == EGL_TRUE);
        CHECK(attr(c, EGL_NATIVE_VISUAL_ID) == color + 1); /* EGL_MEMORY_* */
        CHECK(attr(c, EGL_NATIVE_VISUAL_TYPE) == EGL_NONE);
        CHECK(attr(c, EGL_SAMPLE_BUFFERS) == ms);
        CHECK(attr(c, EGL_SAMPLES) == ms * 4);
        CHECK(attr(c, EGL_SURFACE_TYPE) == (EGL_PBUFFER_BIT | EGL_PIXMAP_BIT | EGL_WINDOW_BIT |
                                           EGL_SWAP_BEHAVIOR_PRESERVED_BIT));
        CHECK(attr(c, EGL_TRANSPARENT_TYPE) == EGL_NONE);
        attr(c, EGL_TRANSPARENT_RED_VALUE);
        attr(c, EGL_TRANSPARENT_GREEN_VALUE);
        attr(c, EGL_TRANSPARENT_BLUE_VALUE);
        CHECK_EGL(EGL_SUCCESS);
    }
    {
        EGLint v = 77;
        CHECK(!eglGetConfigAttrib(dpy, configs[0], 0x1234, &v) && v == 77);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
        CHECK(!eglGetConfigAttrib(dpy, (EGLConfig)(size_t)37, EGL_RED_SIZE, &v));
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(!eglGetConfigAttrib(dpy, NULL, EGL_RED_SIZE, &v));
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(!eglGetConfigAttrib((EGLDisplay)(size_t)99, configs[0], EGL_RED_SIZE, &v));
        CHECK_EGL(EGL_BAD_DISPLAY);
    }

    /* Defaults: window-capable ES configs, smallest buffers first, then fewer samples. */
    {
        EGLConfig out[64];
        n = choose(NULL, out, 64);
        CHECK(n == 36);
        CHECK(n == 36 && out[0] == configs[0] && out[1] == configs[1] && out[6] == configs[18] &&
              out[12] == configs[6]);
        n = choose(NULL, NULL, 0);
        CHECK(n == 36);
    }
    /* Larger total of requested color bits first. */
    {
        static const EGLint red[] = {EGL_RED_SIZE, 1, EGL_NONE};
        static const EGLint rgba[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                      EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 16, EGL_NONE};
        static const EGLint any_depth[] = {EGL_DEPTH_SIZE, EGL_DONT_CARE, EGL_NONE};
        static const EGLint deep[] = {EGL_DEPTH_SIZE, 17, EGL_STENCIL_SIZE, 1, EGL_NONE};
        EGLConfig out[64];
        n = choose(red, out, 64);
        CHECK(n == 36 && attr(out[0], EGL_CONFIG_ID) == 7 && attr(out[6], EGL_CONFIG_ID) == 25 &&
              attr(out[12], EGL_CONFIG_ID) == 13 && attr(out[24], EGL_CONFIG_ID) == 1);
        n = choose(rgba, out, 64);
        CHECK(n == 8 && attr(out[0], EGL_CONFIG_ID) == 15 && attr(out[3], EGL_CONFIG_ID) == 18 &&
              attr(out[4], EGL_CONFIG_ID) == 33);
        n = choose(any_depth, out, 64);
        CHECK(n == 36);
        n = choose(deep, out, 64);
        CHECK(n == 6 && attr(out[0], EGL_CONFIG_ID) == 6 && attr(out[1], EGL_CONFIG_ID) == 24 &&
              attr(out[5], EGL_CONFIG_ID) == 36);
        n = choose(deep, out, 1);
        CHECK(n == 1 && attr(out[0], EGL_CONFIG_ID) == 6);
    }
    /* Exact, mask and EGL_CONFIG_ID rules. */
    {
        static const EGLint level[] = {EGL_LEVEL, 1, EGL_NONE};
        static const EGLint vg[] = {EGL_RENDERABLE_TYPE, EGL_OPENVG_BIT, EGL_NONE};
        static const EGLint es2[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_NONE};
        static const EGLint surf[] = {EGL_SURFACE_TYPE, EGL_PIXMAP_BIT | EGL_PBUFFER_BIT,
                                      EGL_NONE};
        static const EGLint lum[] = {EGL_COLOR_BUFFER_TYPE, EGL_LUMINANCE_BUFFER, EGL_NONE};
        static const EGLint slow[] = {EGL_CONFIG_CAVEAT, EGL_SLOW_CONFIG, EGL_NONE};
        static const EGLint tex[] = {EGL_BIND_TO_TEXTURE_RGBA, EGL_TRUE, EGL_NONE};
        static const EGLint ms[] = {EGL_SAMPLE_BUFFERS, 1, EGL_NONE};
        static const EGLint byid[] = {EGL_LEVEL, 5, EGL_CONFIG_ID, 5, EGL_RED_SIZE, 8, EGL_NONE};
        static const EGLint noid[] = {EGL_CONFIG_ID, 99, EGL_NONE};
        static const EGLint ignored[] = {EGL_MAX_PBUFFER_WIDTH, 100000, EGL_NATIVE_VISUAL_ID,
                                         77, EGL_MATCH_NATIVE_PIXMAP, EGL_NONE, EGL_NONE};
        static const EGLint conformant[] = {EGL_CONFORMANT, EGL_OPENGL_ES_BIT,
                                            EGL_NATIVE_RENDERABLE, EGL_TRUE, EGL_NONE};
        static const EGLint swap[] = {EGL_MAX_SWAP_INTERVAL, 1, EGL_MIN_SWAP_INTERVAL, 0,
                                      EGL_TRANSPARENT_TYPE, EGL_NONE, EGL_NONE};
        static const EGLint swap2[] = {EGL_MAX_SWAP_INTERVAL, 2, EGL_NONE};
        EGLConfig out[64];
        CHECK(choose(level, out, 64) == 0);
        CHECK(choose(vg, out, 64) == 0);
        CHECK(choose(es2, out, 64) == 0);
        CHECK(choose(surf, out, 64) == 36);
        CHECK(choose(lum, out, 64) == 0);
        CHECK(choose(slow, out, 64) == 0);
        CHECK(choose(tex, out, 64) == 12);
        n = choose(ms, out, 64);
        CHECK(n == 18 && attr(out[0], EGL_CONFIG_ID) == 19 && attr(out[0], EGL_SAMPLES) == 4);
        n = choose(byid, out, 64);
        CHECK(n == 1 && attr(out[0], EGL_CONFIG_ID) == 5);
        CHECK(choose(noid, out, 64) == 0);
        CHECK(choose(ignored, out, 64) == 36);
        CHECK(choose(conformant, out, 64) == 36);
        CHECK(choose(swap, out, 64) == 36);
        CHECK(choose(swap2, out, 64) == 0);
    }
    /* Errors. */
    {
        static const EGLint unknown[] = {0x1234, 1, EGL_NONE};
        static const EGLint negative[] = {EGL_RED_SIZE, -2, EGL_NONE};
        static const EGLint bad_type[] = {EGL_COLOR_BUFFER_TYPE, 0x1234, EGL_NONE};
        static const EGLint bad_caveat[] = {EGL_CONFIG_CAVEAT, 0x1234, EGL_NONE};
        static const EGLint bad_surface[] = {EGL_SURFACE_TYPE, 0x10000, EGL_NONE};
        static const EGLint bad_bool[] = {EGL_BIND_TO_TEXTURE_RGB, 5, EGL_NONE};
        static const EGLint bad_transparent[] = {EGL_TRANSPARENT_TYPE, 0x1234, EGL_NONE};
        static const EGLint level_dc[] = {EGL_LEVEL, EGL_DONT_CARE, EGL_NONE};
        static const EGLint red[] = {EGL_RED_SIZE, 1, EGL_NONE};
        const EGLint *bad[] = {unknown, negative, bad_type, bad_caveat, bad_surface, bad_bool,
                               bad_transparent, level_dc};
        EGLConfig out[4];
        size_t k;
        for (k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
            n = -1;
            CHECK(!eglChooseConfig(dpy, bad[k], out, 4, &n));
            CHECK_EGL(EGL_BAD_ATTRIBUTE);
        }
        CHECK(!eglChooseConfig(dpy, red, out, 4, NULL));
        CHECK_EGL(EGL_BAD_PARAMETER);
        CHECK(!eglChooseConfig((EGLDisplay)(size_t)99, red, out, 4, &n));
        CHECK_EGL(EGL_BAD_DISPLAY);
    }
    CHECK(eglTerminate(dpy));
    CHECK(!eglChooseConfig(dpy, NULL, configs, 4, &n));
    CHECK_EGL(EGL_NOT_INITIALIZED);
    CHECK(!eglGetConfigAttrib(dpy, configs[0], EGL_RED_SIZE, &n));
    CHECK_EGL(EGL_NOT_INITIALIZED);
    return ct_done();
}
