/*
 * egl_platform_surfaceless.c: EGL_EXT_client_extensions, EGL_EXT_platform_base and
 * EGL_MESA_platform_surfaceless as headless programs use them:
 * eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL), with
 * its errors, a pbuffer drawn on that display, and memory windows and pixmaps through
 * eglCreatePlatform{Window,Pixmap}SurfaceEXT.
 * ct:no-diff (the client extension string and the memory surfaces are ours)
 */
#define EGL_EGLEXT_PROTOTYPES 1
#include "common.h"

int main(void)
{
    static const EGLint bad_attribs[] = {0x3333, 1, EGL_NONE};
    static const EGLint pbuffer_attribs[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
    static const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                            EGL_PBUFFER_BIT | EGL_WINDOW_BIT | EGL_PIXMAP_BIT,
                                            EGL_RED_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
    static uint32_t window_pixels[8 * 8], pixmap_pixels[8 * 8];
    struct EGLMemoryWindow win = {8, 8, 8 * 4, EGL_MEMORY_RGBA8888, window_pixels};
    struct EGLMemoryPixmap pix = {8, 8, 8 * 4, EGL_MEMORY_RGBA8888, pixmap_pixels};
    const char *client;
    EGLDisplay dpy;
    EGLConfig config;
    EGLint n = 0, major = 0, minor = 0;
    EGLSurface pbuffer, window, pixmap;
    EGLContext ctx;
    GLubyte px[4];

    /* Before any display: the client extensions, and no other string. */
    client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    CHECK(client != NULL);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(client && ct_has_word(client, "EGL_EXT_client_extensions"));
    CHECK(client && ct_has_word(client, "EGL_EXT_platform_base"));
    CHECK(client && ct_has_word(client, "EGL_MESA_platform_surfaceless"));
    CHECK(eglQueryString(EGL_NO_DISPLAY, EGL_VERSION) == NULL);
    CHECK_EGL(EGL_BAD_DISPLAY);
    CHECK((void (*)(void))eglGetProcAddress("eglGetPlatformDisplayEXT") ==
          (void (*)(void))eglGetPlatformDisplayEXT);

    /* Errors: an unknown platform, a native display, an attribute the platform lacks. */
    CHECK(eglGetPlatformDisplayEXT(0x1234, EGL_DEFAULT_DISPLAY, NULL) == EGL_NO_DISPLAY);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, &win, NULL) ==
          EGL_NO_DISPLAY);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                   bad_attribs) == EGL_NO_DISPLAY);
    CHECK_EGL(EGL_BAD_ATTRIBUTE);

    dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    CHECK(dpy != EGL_NO_DISPLAY);
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglInitialize(dpy, &major, &minor) && major == 1 && minor == 5);
    /* The display's own string lists display extensions only. */
    CHECK(!ct_has_word(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_EXT_platform_base"));
    CHECK(eglChooseConfig(dpy, config_attribs, &config, 1, &n) && n == 1);

    pbuffer = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
    ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    CHECK(pbuffer != EGL_NO_SURFACE && ctx != EGL_NO_CONTEXT);
    CHECK(eglMakeCurrent(dpy, pbuffer, pbuffer, ctx));
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK(px[0] == 0 && px[1] == 255 && px[2] == 0 && px[3] == 255);

    /* Platform surfaces: memory windows and pixmaps, as eglCreate{Window,Pixmap}Surface. */
    window = eglCreatePlatformWindowSurfaceEXT(dpy, config, &win, NULL);
    CHECK(window != EGL_NO_SURFACE);
    CHECK(eglMakeCurrent(dpy, window, window, ctx));
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(eglSwapBuffers(dpy, window));
    {
        /* EGL_MEMORY_RGBA8888: bytes R, G, B, A; the swap wrote the red frame there. */
        const GLubyte *b = (const GLubyte *)window_pixels;
        CHECK(b[0] == 255 && b[1] == 0 && b[2] == 0 && b[3] == 255);
    }
    pixmap = eglCreatePlatformPixmapSurfaceEXT(dpy, config, &pix, NULL);
    CHECK(pixmap != EGL_NO_SURFACE);
    CHECK(eglCreatePlatformWindowSurfaceEXT(dpy, config, NULL, NULL) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_NATIVE_WINDOW);
    CHECK(eglCreatePlatformPixmapSurfaceEXT(EGL_NO_DISPLAY, config, &pix, NULL) ==
          EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_DISPLAY);

    /* EGL 1.5's core forms take EGLAttrib lists. */
    {
        static const EGLAttrib bad[] = {0x3333, 1, EGL_NONE};
        static uint32_t more_pixels[8 * 8];
        struct EGLMemoryPixmap more = {8, 8, 8 * 4, EGL_MEMORY_RGBA8888, more_pixels};
        static const EGLAttrib wide_big[] = {EGL_RENDER_BUFFER, (EGLAttrib)1 << 40, EGL_NONE};
        EGLSurface s;
        CHECK(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL) ==
              dpy);
        CHECK(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, bad) ==
              EGL_NO_DISPLAY);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
        CHECK(eglGetPlatformDisplay(0x1234, EGL_DEFAULT_DISPLAY, NULL) == EGL_NO_DISPLAY);
        CHECK_EGL(EGL_BAD_PARAMETER);
        s = eglCreatePlatformPixmapSurface(dpy, config, &more, NULL);
        CHECK(s != EGL_NO_SURFACE);
        CHECK(eglDestroySurface(dpy, s));
        CHECK(eglCreatePlatformWindowSurface(dpy, config, NULL, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_NATIVE_WINDOW);
        /* A value past EGLint's range is no attribute value. */
        CHECK(eglCreatePlatformWindowSurface(dpy, config, &more, wide_big) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_ATTRIBUTE);
    }

    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(eglDestroySurface(dpy, pixmap));
    CHECK(eglDestroySurface(dpy, window));
    CHECK(eglDestroySurface(dpy, pbuffer));
    CHECK(eglDestroyContext(dpy, ctx));
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    return ct_done();
}
