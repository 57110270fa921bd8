/*
 * egl_display_impl.c: what this implementation answers where EGL 1.4 leaves a choice:
 * the strings, eglBindAPI for APIs it lacks, eglWaitNative's engine check, the exact
 * eglGetProcAddress table, unknown names.
 * ct:no-diff (Mesa supports more APIs and extensions)
 */
#include "common.h"

int main(void)
{
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    const char *s;

    /* Every native display value maps to the one display. */
    CHECK(eglGetDisplay((EGLNativeDisplayType)(size_t)1234) == dpy);
    CHECK(eglInitialize(dpy, NULL, NULL));
    s = eglQueryString(dpy, EGL_VERSION);
    CHECK(s != NULL && strncmp(s, "1.5 gles-cm", 11) == 0);
    s = eglQueryString(dpy, EGL_CLIENT_APIS);
    CHECK(s != NULL && strcmp(s, "OpenGL_ES") == 0);
    s = eglQueryString(dpy, EGL_EXTENSIONS);
    CHECK(s != NULL && strcmp(s, "EGL_KHR_get_all_proc_addresses EGL_KHR_surfaceless_context "
                                 "EGL_KHR_create_context EGL_KHR_fence_sync EGL_KHR_wait_sync "
                                 "EGL_KHR_image_base EGL_KHR_gl_texture_2D_image") == 0);
    s = eglQueryString(dpy, EGL_VENDOR);
    CHECK(s != NULL && strcmp(s, "gles-cm") == 0);
    /* EGL_EXT_client_extensions: EGL_NO_DISPLAY answers only EGL_EXTENSIONS (the client
     * extensions, see egl_platform_surfaceless.c). */
    CHECK(eglQueryString(EGL_NO_DISPLAY, EGL_VENDOR) == NULL);
    CHECK_EGL(EGL_BAD_DISPLAY);

    CHECK(!eglBindAPI(EGL_OPENVG_API));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(!eglBindAPI(EGL_OPENGL_API));
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(eglQueryAPI() == EGL_OPENGL_ES_API);

    CHECK(!eglWaitNative(0x1234));
    CHECK_EGL(EGL_BAD_PARAMETER);

    CHECK(eglGetProcAddress("eglNoSuchFunction") == NULL);
    CHECK(eglGetProcAddress("glNoSuchFunction") == NULL);
    CHECK(eglGetProcAddress("") == NULL);
    CHECK(eglGetProcAddress(NULL) == NULL);
    CHECK((void (*)(void))eglGetProcAddress("eglSwapBuffers") == (void (*)(void))eglSwapBuffers);
    CHECK((void (*)(void))eglGetProcAddress("glClear") == (void (*)(void))glClear);
    CHECK(eglGetProcAddress("eglGetProcAddress") != NULL);
    CHECK_EGL(EGL_SUCCESS);

    CHECK(eglGetCurrentSurface(0x1234) == EGL_NO_SURFACE);
    CHECK_EGL(EGL_BAD_PARAMETER);

    /* eglCreatePbufferFromClientBuffer: no client buffer types. */
    {
        EGLConfig cfg;
        EGLint n = 0;
        CHECK(eglGetConfigs(dpy, &cfg, 1, &n) && n == 1);
        CHECK(eglCreatePbufferFromClientBuffer(dpy, EGL_OPENVG_IMAGE, (EGLClientBuffer)1, cfg,
                                               NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_PARAMETER);
        CHECK(eglCreatePbufferFromClientBuffer(dpy, EGL_OPENVG_IMAGE, (EGLClientBuffer)1,
                                               (EGLConfig)(size_t)999, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_CONFIG);
        CHECK(eglCreatePbufferFromClientBuffer((EGLDisplay)(size_t)77, EGL_OPENVG_IMAGE,
                                               (EGLClientBuffer)1, cfg, NULL) == EGL_NO_SURFACE);
        CHECK_EGL(EGL_BAD_DISPLAY);
    }
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    return ct_done();
}
