/*
 * An ordinary program with no knowledge of frame capture: tests/capture.rs runs it with
 * GLES_CM_CAPTURE (and GLES_CM_CAPTURE_FINISH) set and reads the PNG files it leaves.
 *
 * On a 32x24 RGBA pbuffer it shows three pictures:
 *   1. red with a green 8x8 square in the top-left corner, then eglSwapBuffers;
 *   2. blue, then glFinish;
 *   3. yellow at alpha 0.2 (51 of 255), then eglSwapBuffers.
 * Exit status 0 when every EGL and GL call succeeded.
 */
#include <EGL/egl.h>
#include <GLES/gl.h>
#include <stdio.h>

int main(void)
{
    static const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
                                            EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE,
                                            8, EGL_NONE};
    static const EGLint size[] = {EGL_WIDTH, 32, EGL_HEIGHT, 24, EGL_NONE};
    EGLConfig config;
    EGLint n = 0;
    int failures = 0;

    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (!eglInitialize(dpy, NULL, NULL) ||
        !eglChooseConfig(dpy, config_attribs, &config, 1, &n) || n != 1) {
        printf("EGL setup failed: 0x%04X\n", (unsigned)eglGetError());
        return 2;
    }
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
    EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (!eglMakeCurrent(dpy, surface, surface, context)) {
        printf("eglMakeCurrent failed: 0x%04X\n", (unsigned)eglGetError());
        return 2;
    }

    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    /* Window coordinates run up from the bottom: the top-left square starts at y = 16. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 16, 8, 8);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    if (!eglSwapBuffers(dpy, surface)) {
        printf("first eglSwapBuffers failed: 0x%04X\n", (unsigned)eglGetError());
        ++failures;
    }

    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();

    glClearColor(1, 1, 0, 0.2f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!eglSwapBuffers(dpy, surface)) {
        printf("second eglSwapBuffers failed: 0x%04X\n", (unsigned)eglGetError());
        ++failures;
    }
    if (glGetError() != GL_NO_ERROR) {
        printf("unexpected GL error\n");
        ++failures;
    }

    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
    printf("%s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
