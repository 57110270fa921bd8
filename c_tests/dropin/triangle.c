/*
 * A program written only against the standard Khronos headers and libraries: it includes
 * <EGL/egl.h> and <GLES/gl.h> from the system and links -lEGL -lGLESv1_CM. The harness
 * (tests/c_programs.rs) runs the one binary on Mesa and on libGLES_CM through the
 * compatibility names (LD_LIBRARY_PATH=target/<profile>/compat).
 *
 * It makes a 32x32 pbuffer context, clears to blue, draws a red triangle covering the
 * lower-left half with depth testing on, reads back pixels on both sides of the diagonal and
 * prints the renderer it ran on. Exit status 0 when every pixel is right.
 */
#include <EGL/egl.h>
#include <GLES/gl.h>
#include <stdio.h>

static int expect(int x, int y, const GLubyte want[4])
{
    GLubyte p[4] = {0, 0, 0, 0};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    if (p[0] != want[0] || p[1] != want[1] || p[2] != want[2] || p[3] != want[3]) {
        printf("pixel (%d, %d) = (%d, %d, %d, %d), expected (%d, %d, %d, %d)\n", x, y, p[0], p[1],
               p[2], p[3], want[0], want[1], want[2], want[3]);
        return 1;
    }
    return 0;
}

int main(void)
{
    static const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                            EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT,
                                            EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                            EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 16, EGL_NONE};
    static const EGLint pbuffer_attribs[] = {EGL_WIDTH, 32, EGL_HEIGHT, 32, EGL_NONE};
    static const GLfloat vertices[] = {-1, -1, 0, 1, -1, 0, -1, 1, 0};
    static const GLubyte red[4] = {255, 0, 0, 255}, blue[4] = {0, 0, 255, 255};
    EGLDisplay dpy;
    EGLConfig config;
    EGLint count = 0;
    EGLSurface surface;
    EGLContext context;
    int failures = 0;

    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) {
        printf("eglInitialize failed: 0x%04X\n", (unsigned)eglGetError());
        return 2;
    }
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count != 1) {
        printf("eglChooseConfig failed: 0x%04X\n", (unsigned)eglGetError());
        return 2;
    }
    surface = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
    context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (surface == EGL_NO_SURFACE || context == EGL_NO_CONTEXT ||
        !eglMakeCurrent(dpy, surface, surface, context)) {
        printf("context setup failed: 0x%04X\n", (unsigned)eglGetError());
        return 2;
    }
    printf("renderer: %s | %s\n", (const char *)glGetString(GL_RENDERER),
           (const char *)glGetString(GL_VERSION));

    glViewport(0, 0, 32, 32);
    glClearColor(0, 0, 1, 1);
    glClearDepthf(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, vertices);
    glColor4f(1, 0, 0, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    /* The hypotenuse runs from (32, 0) to (0, 32); pixel centers clear of it. */
    failures += expect(2, 2, red);
    failures += expect(15, 15, red);
    failures += expect(17, 17, blue);
    failures += expect(30, 30, blue);
    if (glGetError() != GL_NO_ERROR) {
        printf("unexpected GL error\n");
        ++failures;
    }

    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, context);
    eglDestroySurface(dpy, surface);
    eglTerminate(dpy);
    printf("%s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
