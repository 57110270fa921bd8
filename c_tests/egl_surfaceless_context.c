/*
 * EGL_KHR_surfaceless_context with GL_OES_surfaceless_context: a context made current
 * with no draw and no read surface. Its default framebuffer does not exist
 * (GL_FRAMEBUFFER_UNDEFINED_OES; clears, draws and reads on it are
 * GL_INVALID_FRAMEBUFFER_OPERATION_OES), its viewport stays (0, 0, 0, 0) until a surface
 * is bound, and it renders into framebuffer objects. One surface without the other, or
 * surfaces without a context, is EGL_BAD_MATCH; calls that need a current surface fail
 * as the specification says.
 */
#include "common.h"
#include "fbo_functions.h"

static void the_default_framebuffer_is_missing(void)
{
    static const GLfloat tri[6] = {-1, -1, 1, -1, 0, 1};
    GLint vp[4] = {-1, -1, -1, -1};
    GLubyte px[4] = {1, 2, 3, 4};
    glGetIntegerv(GL_VIEWPORT, vp);
    CHECK(vp[0] == 0 && vp[1] == 0 && vp[2] == 0 && vp[3] == 0);
    glGetIntegerv(GL_SCISSOR_BOX, vp);
    CHECK(vp[2] == 0 && vp[3] == 0);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_UNDEFINED_OES);
    CHECK_GL(GL_NO_ERROR);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
    CHECK(px[0] == 1 && px[3] == 4);
    glDisableClientState(GL_VERTEX_ARRAY);
}

static void framebuffer_objects_render(void)
{
    static const GLfloat tri[6] = {-1, -1, 3, -1, -1, 3};
    GLuint fb, rb;
    glGenFramebuffersOES(1, &fb);
    glGenRenderbuffersOES(1, &rb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB565_OES, 4, 4);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    glViewport(0, 0, 4, 4);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(3, 3, 255, 0, 0, 255, 0);
    glColor4f(0, 0, 1, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CHECK_PIXEL(1, 1, 0, 0, 255, 255, 0);
    CHECK_GL(GL_NO_ERROR);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
}

int main(void)
{
    EGLContext other;
    EGLint v = -1;
    const char *ext;

    ct_init(8, 8);
    ct_load_fbo();
    CHECK(ct_has_word((const char *)glGetString(GL_EXTENSIONS), "GL_OES_surfaceless_context"));
    ext = eglQueryString(ct.display, EGL_EXTENSIONS);
    CHECK(ct_has_word(ext, "EGL_KHR_surfaceless_context"));

    /* A second context, never current with a surface. */
    other = eglCreateContext(ct.display, ct.config, EGL_NO_CONTEXT, NULL);
    CHECK(other != EGL_NO_CONTEXT);
    /* One surface without the other, and surfaces without a context. */
    CHECK(!eglMakeCurrent(ct.display, ct.surface, EGL_NO_SURFACE, other));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglMakeCurrent(ct.display, EGL_NO_SURFACE, ct.surface, other));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(!eglMakeCurrent(ct.display, ct.surface, ct.surface, EGL_NO_CONTEXT));
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(eglGetCurrentContext() == ct.context);

    CHECK(eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, other));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(eglGetCurrentContext() == other);
    CHECK(eglGetCurrentSurface(EGL_DRAW) == EGL_NO_SURFACE);
    CHECK(eglGetCurrentSurface(EGL_READ) == EGL_NO_SURFACE);
    CHECK(eglQueryContext(ct.display, other, EGL_RENDER_BUFFER, &v) && v == EGL_NONE);
    /* No draw surface: nothing to swap or to set an interval on. */
    CHECK(!eglSwapBuffers(ct.display, ct.surface));
    CHECK_EGL(EGL_BAD_SURFACE);
    CHECK(!eglSwapInterval(ct.display, 1));
    CHECK_EGL(EGL_BAD_SURFACE);
    the_default_framebuffer_is_missing();
    framebuffer_objects_render();

    /* Bound to the pbuffer, the context gets its viewport and a default framebuffer;
     * surfaceless again, it keeps the viewport and loses the framebuffer. */
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, other));
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(7, 7, 0, 255, 0, 255, 0);
    CHECK(eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, other));
    {
        GLint vp[4] = {0, 0, 0, 0};
        glGetIntegerv(GL_VIEWPORT, vp);
        CHECK(vp[2] == 8 && vp[3] == 8);
    }
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_UNDEFINED_OES);
    /* The first context, surfaceless, after it rendered to the pbuffer. */
    CHECK(eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ct.context));
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    CHECK_PIXEL(7, 7, 0, 255, 0, 255, 0);
    CHECK(eglDestroyContext(ct.display, other));
    return ct_done();
}
