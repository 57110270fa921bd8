/* The README's triangle, built against the system's glvnd libEGL.so.1 and libGLESv1_CM.so.1
 * (tests/glvnd.rs): glvnd loads the vendor named by __EGL_VENDOR_LIBRARY_FILENAMES and
 * dispatches every egl* and gl* call to it. Prints the strings and pixels the test checks;
 * exits non-zero at the first call that fails. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES/gl.h>
#include <stdio.h>
#include <string.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

#define CHECK(cond)                                                                    \
    do {                                                                               \
        if (!(cond)) {                                                                 \
            fprintf(stderr, "failed: %s (eglGetError 0x%x)\n", #cond, eglGetError());  \
            return 1;                                                                  \
        }                                                                              \
    } while (0)

int main(void)
{
    static const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                            EGL_RED_SIZE, 8, EGL_DEPTH_SIZE, 16, EGL_NONE};
    static const EGLint size[] = {EGL_WIDTH, 64, EGL_HEIGHT, 64, EGL_NONE};
    static const GLfloat triangle[] = {-1, -1, 1, -1, 0, 1};
    EGLConfig config;
    EGLint n = 0;
    GLubyte inside[4], outside[4];

    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    CHECK(client != NULL);
    printf("client extensions: %s\n", client);

    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    CHECK(dpy != EGL_NO_DISPLAY);
    CHECK(eglInitialize(dpy, NULL, NULL));
    printf("EGL_VENDOR: %s\n", eglQueryString(dpy, EGL_VENDOR));

    /* The platform our vendor names in glvnd's client extensions reaches the same display. */
    if (strstr(client, "EGL_MESA_platform_surfaceless") != NULL) {
        PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
            (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
        CHECK(get_platform_display != NULL);
        EGLDisplay surfaceless =
            get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        printf("surfaceless display is the default one: %s\n",
               surfaceless == dpy ? "yes" : "no");
    }

    CHECK(eglChooseConfig(dpy, config_attribs, &config, 1, &n) && n == 1);
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
    CHECK(surface != EGL_NO_SURFACE);
    EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    CHECK(context != EGL_NO_CONTEXT);
    CHECK(eglMakeCurrent(dpy, surface, surface, context));
    CHECK(eglGetCurrentContext() == context);

    printf("GL_VENDOR: %s\n", (const char *)glGetString(GL_VENDOR));
    printf("GL_RENDERER: %s\n", (const char *)glGetString(GL_RENDERER));
    glClearColor(0, 0, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 0.5f, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, triangle);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glReadPixels(32, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, inside);
    glReadPixels(2, 60, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, outside);
    CHECK(glGetError() == GL_NO_ERROR);
    printf("pixel (32, 16) = %d %d %d %d\n", inside[0], inside[1], inside[2], inside[3]);
    printf("pixel (2, 60) = %d %d %d %d\n", outside[0], outside[1], outside[2], outside[3]);

    /* The error state is the vendor's, reached through glvnd. */
    CHECK(!eglMakeCurrent(dpy, surface, surface, (EGLContext)0x7777));
    printf("eglGetError after a bad context: 0x%x\n", eglGetError());

    CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    CHECK(eglDestroyContext(dpy, context));
    CHECK(eglDestroySurface(dpy, surface));
    CHECK(eglTerminate(dpy));
    CHECK(eglReleaseThread());
    return 0;
}
