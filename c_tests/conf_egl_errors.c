/*
 * conf_egl_errors: the EGL error table. Every row is one (entry point, EGL_BAD_* or
 * EGL_NOT_INITIALIZED) pair EGL 1.4 names: the call with the bad argument made through
 * CALL(expression that is true when the call reports failure), and the error it must set.
 * The runner checks that the call failed, that eglGetError returns the expected error, and
 * that the error then reads EGL_SUCCESS (eglGetError resets it). Statements after CALL undo
 * any setup.
 *
 * Flags: 0 = checked everywhere; STRICT = checked on this library, a known deviation
 * elsewhere (the comment beside the row says what Mesa does); OURS = run only on this
 * library (native window and pixmap types are this implementation's own); NI = run after
 * eglTerminate (the display is not initialized). Rows may SKIP when the configs on offer
 * cannot set up the case. Prints the number of pairs tested.
 */
#include "common.h"

#include <pthread.h>
#include <stdint.h>

#define STRICT 1
#define OURS 2
#define NI 4

/* Handles every row may use. */
static EGLDisplay D;
static EGLConfig C, C_NO_PBUFFER, C_BIND, C_OTHER, C_WINDOW, C_PIXMAP;
static EGLSurface S, S2;
static EGLContext XC, XC2;
#define BADD ((EGLDisplay)(intptr_t)0x7777)
#define BADC ((EGLConfig)(intptr_t)0x7777)
#define BADS ((EGLSurface)(intptr_t)0x7777)
#define BADX ((EGLContext)(intptr_t)0x7777)
#define BADA 0x7777 /* no EGL attribute or enum has this value */

static EGLConfig cfgs[4];
static EGLint n, v;
static const EGLint none[] = {EGL_NONE};
static const EGLint bad_attr[] = {BADA, 1, EGL_NONE};
static const EGLint pb_attr[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};

/* What a row reports. */
static int failed, skip;
static EGLint got;
#define CALL(failure)                                                                    \
    do {                                                                                 \
        failed = (failure);                                                              \
        got = eglGetError();                                                             \
    } while (0)
#define SKIP_IF(cond)                                                                    \
    do {                                                                                 \
        if (cond) {                                                                      \
            skip = 1;                                                                    \
            return;                                                                      \
        }                                                                                \
    } while (0)

static uint8_t pixels[16 * 16 * 4];

/* A memory window / pixmap of this implementation's native types. */
static EGLMemoryWindow win = {8, 8, 32, EGL_MEMORY_RGBA8888, pixels};
static EGLMemoryWindow no_win = {8, 8, 32, EGL_MEMORY_RGBA8888, NULL};
static EGLMemoryPixmap pm = {8, 8, 32, EGL_MEMORY_RGBA8888, pixels};
static EGLMemoryPixmap no_pm = {8, 8, 32, EGL_MEMORY_RGBA8888, NULL};
static EGLMemoryPixmap pm565 = {8, 8, 16, EGL_MEMORY_RGB565, pixels};

/* Makes XC2 current on another thread, holds it until told, then releases it. */
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t cond = PTHREAD_COND_INITIALIZER;
static int holder_state; /* 0 start, 1 holding, 2 asked to release, 3 done */
static EGLSurface holder_surface;

static void *holder(void *arg)
{
    (void)arg;
    eglMakeCurrent(D, holder_surface, holder_surface, XC2);
    pthread_mutex_lock(&lock);
    holder_state = 1;
    pthread_cond_broadcast(&cond);
    while (holder_state != 2)
        pthread_cond_wait(&cond, &lock);
    pthread_mutex_unlock(&lock);
    eglMakeCurrent(D, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglReleaseThread();
    return NULL;
}

static pthread_t holder_thread;
static void hold_on_other_thread(EGLSurface s)
{
    holder_state = 0;
    holder_surface = s;
    pthread_create(&holder_thread, NULL, holder, NULL);
    pthread_mutex_lock(&lock);
    while (holder_state != 1)
        pthread_cond_wait(&cond, &lock);
    pthread_mutex_unlock(&lock);
}
static void release_other_thread(void)
{
    pthread_mutex_lock(&lock);
    holder_state = 2;
    pthread_cond_broadcast(&cond);
    pthread_mutex_unlock(&lock);
    pthread_join(holder_thread, NULL);
}

static int has_egl_ext(const char *name)
{
    const char *e = eglQueryString(D, EGL_EXTENSIONS);
    return e != NULL && strstr(e, name) != NULL;
}

static EGLint cfg_attr(EGLConfig c, EGLint a)
{
    EGLint x = 0;
    eglGetConfigAttrib(D, c, a, &x);
    return x;
}

/* The table: X(id, expected error, flags, statements with one CALL). */
#define ERRORS(X)                                                                        \
    /* --- displays and configs --- */                                                  \
    X(d1, EGL_BAD_DISPLAY, 0, CALL(!eglInitialize(BADD, NULL, NULL)))                    \
    X(d2, EGL_BAD_DISPLAY, 0, CALL(!eglTerminate(BADD)))                                 \
    X(d3, EGL_BAD_DISPLAY, 0, CALL(eglQueryString(BADD, EGL_VENDOR) == NULL))            \
    X(d4, EGL_BAD_PARAMETER, 0, CALL(eglQueryString(D, BADA) == NULL))                   \
    X(d5, EGL_BAD_DISPLAY, 0, CALL(!eglGetConfigs(BADD, cfgs, 4, &n)))                   \
    X(d6, EGL_BAD_PARAMETER, 0, CALL(!eglGetConfigs(D, cfgs, 4, NULL)))                  \
    X(d7, EGL_BAD_DISPLAY, 0, CALL(!eglChooseConfig(BADD, none, cfgs, 4, &n)))           \
    X(d8, EGL_BAD_ATTRIBUTE, 0, CALL(!eglChooseConfig(D, bad_attr, cfgs, 4, &n)))        \
    X(d9, EGL_BAD_PARAMETER, 0, CALL(!eglChooseConfig(D, none, cfgs, 4, NULL)))          \
    X(d10, EGL_BAD_ATTRIBUTE, 0, const EGLint a_[] = {EGL_COLOR_BUFFER_TYPE, BADA, EGL_NONE}; \
      CALL(!eglChooseConfig(D, a_, cfgs, 4, &n)))                                        \
    X(d11, EGL_BAD_DISPLAY, 0, CALL(!eglGetConfigAttrib(BADD, C, EGL_RED_SIZE, &v)))     \
    X(d12, EGL_BAD_CONFIG, 0, CALL(!eglGetConfigAttrib(D, BADC, EGL_RED_SIZE, &v)))      \
    X(d13, EGL_BAD_ATTRIBUTE, 0, CALL(!eglGetConfigAttrib(D, C, BADA, &v)))              \
    /* --- pbuffer surfaces --- */                                                      \
    X(s1, EGL_BAD_DISPLAY, 0, CALL(eglCreatePbufferSurface(BADD, C, pb_attr) == EGL_NO_SURFACE)) \
    X(s2, EGL_BAD_CONFIG, 0, CALL(eglCreatePbufferSurface(D, BADC, pb_attr) == EGL_NO_SURFACE)) \
    X(s3, EGL_BAD_ATTRIBUTE, 0, CALL(eglCreatePbufferSurface(D, C, bad_attr) == EGL_NO_SURFACE)) \
    X(s4, EGL_BAD_PARAMETER, 0, const EGLint a_[] = {EGL_WIDTH, -1, EGL_NONE};           \
      CALL(eglCreatePbufferSurface(D, C, a_) == EGL_NO_SURFACE))                         \
    X(s5, EGL_BAD_MATCH, 0, SKIP_IF(C_NO_PBUFFER == NULL);                               \
      CALL(eglCreatePbufferSurface(D, C_NO_PBUFFER, pb_attr) == EGL_NO_SURFACE))         \
    X(s6, EGL_BAD_MATCH, 0, SKIP_IF(C_BIND == NULL);                                     \
      const EGLint a_[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, \
                           EGL_NONE};                                                    \
      CALL(eglCreatePbufferSurface(D, C_BIND, a_) == EGL_NO_SURFACE))                    \
    X(s7, EGL_BAD_MATCH, 0, SKIP_IF(C_BIND == NULL);                                     \
      const EGLint a_[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D, \
                           EGL_NONE};                                                    \
      CALL(eglCreatePbufferSurface(D, C_BIND, a_) == EGL_NO_SURFACE))                    \
    X(s8, EGL_BAD_ATTRIBUTE, 0, SKIP_IF(cfg_attr(C, EGL_BIND_TO_TEXTURE_RGBA));          \
      const EGLint a_[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, \
                           EGL_TEXTURE_TARGET, EGL_TEXTURE_2D, EGL_NONE};                \
      CALL(eglCreatePbufferSurface(D, C, a_) == EGL_NO_SURFACE))                         \
    X(s9, EGL_BAD_DISPLAY, 0, CALL(!eglDestroySurface(BADD, S2)))                        \
    X(s10, EGL_BAD_SURFACE, 0, CALL(!eglDestroySurface(D, BADS)))                        \
    X(s11, EGL_BAD_DISPLAY, 0, CALL(!eglQuerySurface(BADD, S, EGL_WIDTH, &v)))           \
    X(s12, EGL_BAD_SURFACE, 0, CALL(!eglQuerySurface(D, BADS, EGL_WIDTH, &v)))           \
    X(s13, EGL_BAD_ATTRIBUTE, 0, CALL(!eglQuerySurface(D, S, BADA, &v)))                 \
    X(s14, EGL_BAD_DISPLAY, 0, CALL(!eglSurfaceAttrib(BADD, S, EGL_MIPMAP_LEVEL, 0)))    \
    X(s15, EGL_BAD_SURFACE, 0, CALL(!eglSurfaceAttrib(D, BADS, EGL_MIPMAP_LEVEL, 0)))    \
    X(s16, EGL_BAD_ATTRIBUTE, 0, CALL(!eglSurfaceAttrib(D, S, BADA, 0)))                 \
    X(s17, EGL_BAD_MATCH, 0,                                                             \
      SKIP_IF(cfg_attr(C, EGL_SURFACE_TYPE) & EGL_MULTISAMPLE_RESOLVE_BOX_BIT);          \
      CALL(!eglSurfaceAttrib(D, S, EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_BOX))) \
    X(s18, EGL_BAD_MATCH, 0,                                                             \
      SKIP_IF(cfg_attr(C, EGL_SURFACE_TYPE) & EGL_SWAP_BEHAVIOR_PRESERVED_BIT);          \
      CALL(!eglSurfaceAttrib(D, S, EGL_SWAP_BEHAVIOR, EGL_BUFFER_PRESERVED)))            \
    X(s19, EGL_BAD_DISPLAY, 0, CALL(!eglBindTexImage(BADD, S, EGL_BACK_BUFFER)))         \
    X(s20, EGL_BAD_SURFACE, 0, CALL(!eglBindTexImage(D, BADS, EGL_BACK_BUFFER)))         \
    /* A buffer other than EGL_BACK_BUFFER is EGL_BAD_MATCH (EGL 1.4 3.6.1). */          \
    X(s21, EGL_BAD_MATCH, 0, CALL(!eglBindTexImage(D, S, BADA)))                         \
    X(s22, EGL_BAD_MATCH, 0, CALL(!eglBindTexImage(D, S, EGL_BACK_BUFFER)))              \
    X(s23, EGL_BAD_DISPLAY, 0, CALL(!eglReleaseTexImage(BADD, S, EGL_BACK_BUFFER)))      \
    X(s24, EGL_BAD_SURFACE, 0, CALL(!eglReleaseTexImage(D, BADS, EGL_BACK_BUFFER)))      \
    /* Mesa's eglReleaseTexImage accepts any pbuffer and buffer. */                      \
    X(s25, EGL_BAD_MATCH, STRICT, CALL(!eglReleaseTexImage(D, S, BADA)))                      \
    X(s26, EGL_BAD_MATCH, STRICT, CALL(!eglReleaseTexImage(D, S, EGL_BACK_BUFFER)))      \
    /* Mesa's surfaceless platform has no OpenVG: it answers EGL_BAD_ALLOC... */        \
    X(s27, EGL_BAD_PARAMETER, STRICT,                                                    \
      CALL(eglCreatePbufferFromClientBuffer(D, BADA, NULL, C, pb_attr) == EGL_NO_SURFACE)) \
    /* --- window and pixmap surfaces (this library's memory windows and pixmaps) --- */ \
    X(w1, EGL_BAD_DISPLAY, OURS,                                                         \
      CALL(eglCreateWindowSurface(BADD, C_WINDOW, &win, NULL) == EGL_NO_SURFACE))        \
    X(w2, EGL_BAD_CONFIG, OURS,                                                          \
      CALL(eglCreateWindowSurface(D, BADC, &win, NULL) == EGL_NO_SURFACE))               \
    X(w3, EGL_BAD_NATIVE_WINDOW, OURS,                                                   \
      CALL(eglCreateWindowSurface(D, C_WINDOW, &no_win, NULL) == EGL_NO_SURFACE))        \
    X(w4, EGL_BAD_ATTRIBUTE, OURS,                                                       \
      CALL(eglCreateWindowSurface(D, C_WINDOW, &win, pb_attr) == EGL_NO_SURFACE))        \
    X(w5, EGL_BAD_MATCH, OURS, SKIP_IF(C_NO_WINDOW() == NULL);                           \
      CALL(eglCreateWindowSurface(D, C_NO_WINDOW(), &win, NULL) == EGL_NO_SURFACE))      \
    X(w6, EGL_BAD_ALLOC, OURS, EGLSurface w_ = eglCreateWindowSurface(D, C_WINDOW, &win, NULL); \
      CALL(eglCreateWindowSurface(D, C_WINDOW, &win, NULL) == EGL_NO_SURFACE);           \
      eglDestroySurface(D, w_))                                                          \
    X(w7, EGL_BAD_DISPLAY, OURS,                                                         \
      CALL(eglCreatePixmapSurface(BADD, C_PIXMAP, &pm, NULL) == EGL_NO_SURFACE))         \
    X(w8, EGL_BAD_CONFIG, OURS,                                                          \
      CALL(eglCreatePixmapSurface(D, BADC, &pm, NULL) == EGL_NO_SURFACE))                \
    X(w9, EGL_BAD_NATIVE_PIXMAP, OURS,                                                   \
      CALL(eglCreatePixmapSurface(D, C_PIXMAP, &no_pm, NULL) == EGL_NO_SURFACE))         \
    X(w10, EGL_BAD_MATCH, OURS,                                                          \
      CALL(eglCreatePixmapSurface(D, C_PIXMAP, &pm565, NULL) == EGL_NO_SURFACE))         \
    X(w11, EGL_BAD_ATTRIBUTE, OURS,                                                      \
      CALL(eglCreatePixmapSurface(D, C_PIXMAP, &pm, bad_attr) == EGL_NO_SURFACE))        \
    X(w12, EGL_BAD_SURFACE, OURS, EGLSurface w_ = eglCreateWindowSurface(D, C_WINDOW, &win, NULL); \
      CALL(!eglBindTexImage(D, w_, EGL_BACK_BUFFER)); eglDestroySurface(D, w_))          \
    X(w13, EGL_BAD_DISPLAY, OURS, CALL(!eglCopyBuffers(BADD, S, &pm)))                   \
    X(w14, EGL_BAD_SURFACE, OURS, CALL(!eglCopyBuffers(D, BADS, &pm)))                   \
    X(w15, EGL_BAD_NATIVE_PIXMAP, OURS, CALL(!eglCopyBuffers(D, S, &no_pm)))             \
    X(w16, EGL_BAD_MATCH, OURS, CALL(!eglCopyBuffers(D, S, &pm565)))                     \
    /* --- contexts --- */                                                              \
    X(c1, EGL_BAD_DISPLAY, 0, CALL(eglCreateContext(BADD, C, EGL_NO_CONTEXT, NULL) == EGL_NO_CONTEXT)) \
    X(c2, EGL_BAD_CONFIG, 0, CALL(eglCreateContext(D, BADC, EGL_NO_CONTEXT, NULL) == EGL_NO_CONTEXT)) \
    X(c3, EGL_BAD_CONTEXT, 0, CALL(eglCreateContext(D, C, BADX, NULL) == EGL_NO_CONTEXT)) \
    X(c4, EGL_BAD_ATTRIBUTE, 0,                                                          \
      CALL(eglCreateContext(D, C, EGL_NO_CONTEXT, bad_attr) == EGL_NO_CONTEXT))          \
    X(c5, EGL_BAD_DISPLAY, 0, CALL(!eglDestroyContext(BADD, XC2)))                        \
    X(c6, EGL_BAD_CONTEXT, 0, CALL(!eglDestroyContext(D, BADX)))                         \
    X(c7, EGL_BAD_DISPLAY, 0, CALL(!eglQueryContext(BADD, XC, EGL_CONFIG_ID, &v)))        \
    X(c8, EGL_BAD_CONTEXT, 0, CALL(!eglQueryContext(D, BADX, EGL_CONFIG_ID, &v)))        \
    X(c9, EGL_BAD_ATTRIBUTE, 0, CALL(!eglQueryContext(D, XC, BADA, &v)))                  \
    X(c10, EGL_BAD_PARAMETER, 0, CALL(!eglBindAPI(BADA)))                                \
    X(c11, EGL_BAD_PARAMETER, 0,                                                         \
      SKIP_IF(strstr(eglQueryString(D, EGL_CLIENT_APIS), "OpenVG") != NULL);             \
      CALL(!eglBindAPI(EGL_OPENVG_API)))                                                 \
    /* --- make current --- */                                                          \
    X(m1, EGL_BAD_DISPLAY, 0, CALL(!eglMakeCurrent(BADD, S, S, XC)))                      \
    X(m2, EGL_BAD_CONTEXT, 0, CALL(!eglMakeCurrent(D, S, S, BADX)))                      \
    X(m3, EGL_BAD_SURFACE, 0, CALL(!eglMakeCurrent(D, BADS, S, XC)))                      \
    X(m4, EGL_BAD_SURFACE, 0, CALL(!eglMakeCurrent(D, S, BADS, XC)))                      \
    X(m5, EGL_BAD_MATCH, 0, CALL(!eglMakeCurrent(D, S, S, EGL_NO_CONTEXT)))              \
    X(m6, EGL_BAD_MATCH, 0, SKIP_IF(has_egl_ext("EGL_KHR_surfaceless_context"));         \
      CALL(!eglMakeCurrent(D, EGL_NO_SURFACE, EGL_NO_SURFACE, XC)))                       \
    X(m7, EGL_BAD_MATCH, 0, SKIP_IF(C_OTHER == NULL);                                    \
      EGLSurface o_ = eglCreatePbufferSurface(D, C_OTHER, pb_attr);                      \
      CALL(!eglMakeCurrent(D, o_, o_, XC)); eglDestroySurface(D, o_))                     \
    X(m8, EGL_BAD_ACCESS, 0, hold_on_other_thread(S2);                                   \
      CALL(!eglMakeCurrent(D, S, S, XC2)); release_other_thread())                        \
    X(m9, EGL_BAD_ACCESS, 0, hold_on_other_thread(S2);                                   \
      CALL(!eglMakeCurrent(D, S2, S2, XC)); release_other_thread())                       \
    X(m10, EGL_BAD_PARAMETER, 0, CALL(eglGetCurrentSurface(BADA) == EGL_NO_SURFACE))     \
    /* --- swaps, waits, copies --- */                                                  \
    X(p1, EGL_BAD_DISPLAY, 0, CALL(!eglSwapBuffers(BADD, S)))                            \
    X(p2, EGL_BAD_SURFACE, 0, CALL(!eglSwapBuffers(D, BADS)))                            \
    X(p3, EGL_BAD_SURFACE, 0, CALL(!eglSwapBuffers(D, S2)))                              \
    X(p4, EGL_BAD_DISPLAY, 0, CALL(!eglSwapInterval(BADD, 1)))                           \
    X(p5, EGL_BAD_CONTEXT, 0, eglMakeCurrent(D, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); \
      CALL(!eglSwapInterval(D, 1)); eglMakeCurrent(D, S, S, XC))                          \
    X(p6, EGL_BAD_PARAMETER, 0, CALL(!eglWaitNative(BADA)))                              \
    /* --- after eglTerminate --- */                                                    \
    X(n1, EGL_NOT_INITIALIZED, NI, CALL(!eglGetConfigs(D, cfgs, 4, &n)))                 \
    X(n2, EGL_NOT_INITIALIZED, NI, CALL(!eglChooseConfig(D, none, cfgs, 4, &n)))         \
    X(n3, EGL_NOT_INITIALIZED, NI, CALL(!eglGetConfigAttrib(D, C, EGL_RED_SIZE, &v)))    \
    X(n4, EGL_NOT_INITIALIZED, NI, CALL(eglQueryString(D, EGL_VENDOR) == NULL))          \
    X(n5, EGL_NOT_INITIALIZED, NI,                                                       \
      CALL(eglCreatePbufferSurface(D, C, pb_attr) == EGL_NO_SURFACE))                    \
    X(n6, EGL_NOT_INITIALIZED, NI,                                                       \
      CALL(eglCreateContext(D, C, EGL_NO_CONTEXT, NULL) == EGL_NO_CONTEXT))              \
    X(n7, EGL_NOT_INITIALIZED, NI, CALL(!eglQuerySurface(D, S, EGL_WIDTH, &v)))          \
    /* Mesa answers EGL_BAD_DISPLAY (its handles died with the display). */              \
    X(n8, EGL_NOT_INITIALIZED, NI | STRICT, CALL(!eglMakeCurrent(D, S, S, XC)))                    \
    X(n9, EGL_NOT_INITIALIZED, NI, CALL(!eglDestroySurface(D, S)))                       \
    X(n10, EGL_NOT_INITIALIZED, NI, CALL(!eglDestroyContext(D, XC)))                      \
    X(n11, EGL_NOT_INITIALIZED, NI, CALL(!eglQueryContext(D, XC, EGL_CONFIG_ID, &v)))

/* A config without EGL_WINDOW_BIT, or NULL. */
static EGLConfig no_window_config;
#define C_NO_WINDOW() no_window_config

#define DEF(id, err, flags, ...)                                                         \
    static void row_##id(void)                                                           \
    {                                                                                    \
        __VA_ARGS__;                                                                     \
    }
ERRORS(DEF)

struct row {
    const char *call;
    void (*run)(void);
    EGLint expected;
    int flags;
};
#define ROW(id, err, flags, ...) {#__VA_ARGS__, row_##id, err, flags},
static const struct row rows[] = {ERRORS(ROW)};

/* Finds the configs the rows need among all of them. */
static void find_configs(void)
{
    EGLConfig all[256];
    EGLint count = 0, i;
    EGLint c_id = cfg_attr(C, EGL_CONFIG_ID);
    eglGetConfigs(D, all, 256, &count);
    for (i = 0; i < count; ++i) {
        EGLint type = cfg_attr(all[i], EGL_SURFACE_TYPE);
        EGLint renderable = cfg_attr(all[i], EGL_RENDERABLE_TYPE);
        if (!(renderable & EGL_OPENGL_ES_BIT))
            continue;
        if (!(type & EGL_PBUFFER_BIT) && C_NO_PBUFFER == NULL)
            C_NO_PBUFFER = all[i];
        if (!(type & EGL_WINDOW_BIT) && no_window_config == NULL)
            no_window_config = all[i];
        if ((type & EGL_PBUFFER_BIT) && cfg_attr(all[i], EGL_BIND_TO_TEXTURE_RGBA) &&
            C_BIND == NULL)
            C_BIND = all[i];
        if ((type & EGL_WINDOW_BIT) && cfg_attr(all[i], EGL_BUFFER_SIZE) == 32 &&
            C_WINDOW == NULL)
            C_WINDOW = all[i];
        if ((type & EGL_PIXMAP_BIT) && cfg_attr(all[i], EGL_BUFFER_SIZE) == 32 &&
            cfg_attr(all[i], EGL_ALPHA_SIZE) == 8 && C_PIXMAP == NULL)
            C_PIXMAP = all[i];
        /* A config whose color buffer differs from C's: its surfaces cannot take X. */
        if ((type & EGL_PBUFFER_BIT) && cfg_attr(all[i], EGL_CONFIG_ID) != c_id &&
            cfg_attr(all[i], EGL_RED_SIZE) != cfg_attr(C, EGL_RED_SIZE) && C_OTHER == NULL)
            C_OTHER = all[i];
    }
}

static void report_row(const struct row *w, int strict, const char *why)
{
    char m[700];
    snprintf(m, sizeof m, "%s: %s", w->call, why);
    if ((w->flags & STRICT) && !strict)
        fprintf(stderr, "known deviation: %s\n", m);
    else
        ct_fail(__FILE__, __LINE__, m);
}

int main(void)
{
    size_t r;
    int tested = 0, skipped = 0, strict, terminated = 0;

    ct_init(16, 16);
    strict = ct_strict();
    D = ct.display;
    C = ct.config;
    S = ct.surface;
    XC = ct.context;
    S2 = eglCreatePbufferSurface(D, C, pb_attr);
    XC2 = eglCreateContext(D, C, EGL_NO_CONTEXT, NULL);
    CHECK(S2 != EGL_NO_SURFACE && XC2 != EGL_NO_CONTEXT);
    find_configs();
    CHECK_EGL(EGL_SUCCESS);

    for (r = 0; r < sizeof rows / sizeof *rows; ++r) {
        const struct row *w = &rows[r];
        EGLint after;
        if ((w->flags & OURS) && !strict) {
            ++skipped;
            continue;
        }
        if ((w->flags & NI) && !terminated) {
            eglMakeCurrent(D, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            CHECK(eglTerminate(D));
            terminated = 1;
        }
        skip = 0;
        failed = 0;
        got = EGL_SUCCESS;
        eglGetError();
        w->run();
        if (skip) {
            printf("skipped (no config sets it up): %.60s\n", w->call);
            ++skipped;
            continue;
        }
        after = eglGetError();
        ++ct.checks;
        if (!failed || got != w->expected || after != EGL_SUCCESS) {
            char why[160];
            snprintf(why, sizeof why, "%s, error 0x%04X then 0x%04X, expected 0x%04X",
                     failed ? "failed" : "succeeded", (unsigned)got, (unsigned)after,
                     (unsigned)w->expected);
            report_row(w, strict, why);
        }
        ++tested;
    }
    /* Everything was released by eglTerminate; ct_done needs nothing more. */
    ct.context = EGL_NO_CONTEXT;
    ct.surface = EGL_NO_SURFACE;
    {
        int rc = ct_done(); /* its summary line, then ours last for the harness log */
        printf("%d (entry point, error) pairs tested, %d skipped\n", tested, skipped);
        return rc;
    }
}
