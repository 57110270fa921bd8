/*
 * common.h: what every program in c_tests/ shares. A pbuffer context in one call, checks
 * that count failures instead of stopping at the first, and an image dump the harness
 * (tests/c_programs.rs) turns into a PNG and, in differential mode, compares with Mesa's.
 *
 *     int main(void) {
 *         ct_init(64, 64);                  // RGBA8888, depth 24, stencil 8 pbuffer
 *         glClearColor(1, 0, 0, 1);
 *         glClear(GL_COLOR_BUFFER_BIT);
 *         CHECK_PIXEL(10, 10, 255, 0, 0, 255, 0);
 *         CHECK_GL(GL_NO_ERROR);
 *         ct_save("red");                   // $CT_OUT/red.pam -> target/c_tests/<prog>/red.png
 *         return ct_done();                 // 0 when every check passed
 *     }
 *
 * Marker comments the harness reads from a program's source:
 *     ct:no-diff   skip the program in the Mesa differential run (it tests something
 *                  Mesa's headless EGL lacks, such as pixmap or window surfaces)
 *
 * Written for C99 and later, and for C++.
 */
#ifndef CT_COMMON_H
#define CT_COMMON_H

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES/gl.h>
#include <GLES/glext.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#define CT_UNUSED __attribute__((unused))
#else
#define CT_UNUSED
#endif

static struct {
    EGLDisplay display;
    EGLConfig config;
    EGLSurface surface;
    EGLContext context;
    int width, height;
    int checks, failures;
} ct;

static CT_UNUSED void ct_fail(const char *file, int line, const char *what)
{
    ++ct.failures;
    fprintf(stderr, "%s:%d: check failed: %s\n", file, line, what);
}

/* Counts a check; prints where and what when it fails. Never stops the program. */
#define CHECK(cond)                                                                      \
    do {                                                                                 \
        ++ct.checks;                                                                     \
        if (!(cond))                                                                     \
            ct_fail(__FILE__, __LINE__, #cond);                                          \
    } while (0)

/*
 * True on this library (its GL_VENDOR names it): checks of behaviour the specification
 * fixes but other implementations (Mesa, in the harness's differential run) depart from are
 * made only then. Needs a current context.
 */
static CT_UNUSED int ct_strict(void)
{
    const char *vendor = (const char *)glGetString(GL_VENDOR);
    return vendor != NULL && strstr(vendor, "gles-cm") != NULL;
}

/*
 * A check the specification fixes but Mesa is known to fail. On this library it is an
 * ordinary CHECK; elsewhere a failure is printed as a known deviation and not counted.
 * `why` says what Mesa does instead.
 */
#define CHECK_MESA_DEVIATES(cond, why)                                                   \
    do {                                                                                 \
        if (ct_strict()) {                                                               \
            CHECK(cond);                                                                 \
        } else if (!(cond)) {                                                            \
            fprintf(stderr, "%s:%d: known deviation: %s (%s)\n", __FILE__, __LINE__,     \
                    #cond, why);                                                         \
        }                                                                                \
    } while (0)

/* Checks (and thereby clears) the GL error flag. */
#define CHECK_GL(expected)                                                               \
    do {                                                                                 \
        GLenum ct_e_ = glGetError();                                                     \
        ++ct.checks;                                                                     \
        if (ct_e_ != (GLenum)(expected)) {                                               \
            char ct_m_[160];                                                             \
            snprintf(ct_m_, sizeof ct_m_, "glGetError() == 0x%04X, expected %s (0x%04X)",  \
                     (unsigned)ct_e_, #expected, (unsigned)(expected));                  \
            ct_fail(__FILE__, __LINE__, ct_m_);                                          \
        }                                                                                \
    } while (0)

/* Checks (and thereby clears) the calling thread's EGL error. */
#define CHECK_EGL(expected)                                                              \
    do {                                                                                 \
        EGLint ct_e_ = eglGetError();                                                    \
        ++ct.checks;                                                                     \
        if (ct_e_ != (EGLint)(expected)) {                                               \
            char ct_m_[160];                                                             \
            snprintf(ct_m_, sizeof ct_m_, "eglGetError() == 0x%04X, expected %s (0x%04X)", \
                     (unsigned)ct_e_, #expected, (unsigned)(expected));                  \
            ct_fail(__FILE__, __LINE__, ct_m_);                                          \
        }                                                                                \
    } while (0)

/* Reads one RGBA pixel of the read surface (window coordinates, y up). */
static CT_UNUSED void ct_read(int x, int y, GLubyte rgba[4])
{
    memset(rgba, 0, 4);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

static CT_UNUSED int ct_near(int a, int b, int tol)
{
    return a - b <= tol && b - a <= tol;
}

/* Checks pixel (x, y) against r, g, b, a, each within tol steps. */
#define CHECK_PIXEL(x, y, r, g, b, a, tol)                                               \
    do {                                                                                 \
        GLubyte ct_p_[4];                                                                \
        ct_read((x), (y), ct_p_);                                                        \
        ++ct.checks;                                                                     \
        if (!ct_near(ct_p_[0], (r), (tol)) || !ct_near(ct_p_[1], (g), (tol)) ||          \
            !ct_near(ct_p_[2], (b), (tol)) || !ct_near(ct_p_[3], (a), (tol))) {          \
            char ct_m_[200];                                                             \
            snprintf(ct_m_, sizeof ct_m_,                                                \
                     "pixel (%d, %d) is (%d, %d, %d, %d), expected (%d, %d, %d, %d) +-%d",   \
                     (int)(x), (int)(y), ct_p_[0], ct_p_[1], ct_p_[2], ct_p_[3], (int)(r), \
                     (int)(g), (int)(b), (int)(a), (int)(tol));                          \
            ct_fail(__FILE__, __LINE__, ct_m_);                                          \
        }                                                                                \
    } while (0)

/* Whether `word` is one of the space-separated names in `list` (an extension string; a
 * name that only begins another does not count). */
static CT_UNUSED int ct_has_word(const char *list, const char *word)
{
    size_t n = strlen(word);
    const char *p = list;
    while (p && (p = strstr(p, word)) != NULL) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
        p += n;
    }
    return 0;
}

static CT_UNUSED int ct_is_size_attrib(EGLint a)
{
    return a == EGL_RED_SIZE || a == EGL_GREEN_SIZE || a == EGL_BLUE_SIZE ||
           a == EGL_ALPHA_SIZE || a == EGL_DEPTH_SIZE || a == EGL_STENCIL_SIZE;
}

/*
 * Sets up EGL on the default display with the first config matching `config_attribs`
 * (EGL_NONE-terminated; EGL_SURFACE_TYPE EGL_PBUFFER_BIT is implied when absent) whose
 * red, green, blue, alpha, depth and stencil sizes equal those requested, a
 * width x height pbuffer and an ES 1.x context, current on this thread. Exits with status 2
 * when any step fails: nothing after it could mean anything.
 */
static CT_UNUSED void ct_init_config(int width, int height, const EGLint *config_attribs)
{
    EGLint attribs[64];
    EGLConfig configs[64];
    EGLint n = 0, count = 0, i = 0, c;
    int has_surface_type = 0;
    EGLint pbuffer_attribs[5];

    for (; config_attribs && config_attribs[i] != EGL_NONE && n < 60; i += 2) {
        if (config_attribs[i] == EGL_SURFACE_TYPE)
            has_surface_type = 1;
        attribs[n++] = config_attribs[i];
        attribs[n++] = config_attribs[i + 1];
    }
    if (!has_surface_type) {
        attribs[n++] = EGL_SURFACE_TYPE;
        attribs[n++] = EGL_PBUFFER_BIT;
    }
    attribs[n++] = EGL_RENDERABLE_TYPE;
    attribs[n++] = EGL_OPENGL_ES_BIT;
    attribs[n] = EGL_NONE;

    ct.width = width;
    ct.height = height;
    ct.display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (ct.display == EGL_NO_DISPLAY || !eglInitialize(ct.display, NULL, NULL)) {
        fprintf(stderr, "ct_init: no EGL display (error 0x%04X)\n", (unsigned)eglGetError());
        exit(2);
    }
    if (!eglChooseConfig(ct.display, attribs, configs, 64, &count) || count < 1) {
        fprintf(stderr, "ct_init: no matching config (error 0x%04X)\n", (unsigned)eglGetError());
        exit(2);
    }
    /* EGL sorts deeper color first (sizes are minimums): take the first config whose sizes
     * equal the requested ones, so a 5/6/5 request gets an RGB565 surface. */
    ct.config = NULL;
    for (c = 0; c < count && ct.config == NULL; ++c) {
        int exact = 1;
        for (i = 0; attribs[i] != EGL_NONE; i += 2) {
            EGLint value = 0;
            if (!ct_is_size_attrib(attribs[i]))
                continue;
            eglGetConfigAttrib(ct.display, configs[c], attribs[i], &value);
            exact = exact && value == attribs[i + 1];
        }
        if (exact)
            ct.config = configs[c];
    }
    if (ct.config == NULL) {
        fprintf(stderr, "ct_init: no config with exactly the requested sizes\n");
        exit(2);
    }
    pbuffer_attribs[0] = EGL_WIDTH;
    pbuffer_attribs[1] = width;
    pbuffer_attribs[2] = EGL_HEIGHT;
    pbuffer_attribs[3] = height;
    pbuffer_attribs[4] = EGL_NONE;
    ct.surface = eglCreatePbufferSurface(ct.display, ct.config, pbuffer_attribs);
    ct.context = eglCreateContext(ct.display, ct.config, EGL_NO_CONTEXT, NULL);
    if (ct.surface == EGL_NO_SURFACE || ct.context == EGL_NO_CONTEXT ||
        !eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context)) {
        fprintf(stderr, "ct_init: no pbuffer context (error 0x%04X)\n", (unsigned)eglGetError());
        exit(2);
    }
}

/* ct_init_config with an RGBA8888 / depth 24 / stencil 8 config. */
static CT_UNUSED void ct_init(int width, int height)
{
    static const EGLint rgba8888_d24_s8[] = {
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
        EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE,
    };
    ct_init_config(width, height, rgba8888_d24_s8);
}

/*
 * Writes the current read surface (ct.width x ct.height, read as RGBA / UNSIGNED_BYTE) as
 * $CT_OUT/<name>.pam, top row first. Does nothing when CT_OUT is unset. Leaves the GL error
 * flag as it found it only if reading raises none; call it where no error is pending.
 */
static CT_UNUSED void ct_save(const char *name)
{
    const char *dir = getenv("CT_OUT");
    char path[1024];
    GLubyte *pixels;
    FILE *f;
    int y;

    if (!dir || ct.width <= 0 || ct.height <= 0)
        return;
    pixels = (GLubyte *)malloc((size_t)ct.width * (size_t)ct.height * 4);
    if (!pixels)
        return;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, ct.width, ct.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    snprintf(path, sizeof path, "%s/%s.pam", dir, name);
    f = fopen(path, "wb");
    if (f) {
        fprintf(f, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n",
                ct.width, ct.height);
        for (y = ct.height - 1; y >= 0; --y)
            fwrite(pixels + (size_t)y * (size_t)ct.width * 4, 4, (size_t)ct.width, f);
        fclose(f);
    }
    free(pixels);
}

/*
 * Releases what ct_init made (if anything) and reports. Returns the exit status: 0 when
 * every check passed, 1 otherwise.
 */
static CT_UNUSED int ct_done(void)
{
    if (ct.display != EGL_NO_DISPLAY && ct.display != NULL) {
        eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (ct.context != EGL_NO_CONTEXT)
            eglDestroyContext(ct.display, ct.context);
        if (ct.surface != EGL_NO_SURFACE)
            eglDestroySurface(ct.display, ct.surface);
        eglTerminate(ct.display);
        eglReleaseThread();
    }
    printf("%d checks, %d failed\n", ct.checks, ct.failures);
    return ct.failures == 0 ? 0 : 1;
}

#endif /* CT_COMMON_H */
