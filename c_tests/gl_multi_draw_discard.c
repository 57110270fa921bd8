/*
 * gl_multi_draw_discard.c: GL_EXT_multi_draw_arrays (several draws in one call, each as
 * glDrawArrays / glDrawElements would make it, and their errors) and
 * GL_EXT_discard_framebuffer (argument checks; contents may be kept or lost, so only that
 * rendering goes on afterwards is checked).
 */
#include "common.h"
#include "fbo_functions.h"

/* Extension functions through eglGetProcAddress (Mesa exports them only that way). */
static PFNGLMULTIDRAWARRAYSEXTPROC glMultiDrawArraysEXT;
static PFNGLMULTIDRAWELEMENTSEXTPROC glMultiDrawElementsEXT;
static PFNGLDISCARDFRAMEBUFFEREXTPROC glDiscardFramebufferEXT;

int main(void)
{
    /* Two quads: the left half (x < 0) and the right half (x > 0) of the surface. */
    static const GLfloat verts[] = {-1, -1, 0, -1, -1, 1, 0, 1, 0, -1, 1, -1, 0, 1, 1, 1};
    static const GLint first[] = {0, 4};
    static const GLsizei count[] = {4, 4};
    static const GLubyte left[] = {0, 1, 2, 3};
    static const GLushort right[] = {4, 5, 6, 7};
    static const GLenum fb_color[] = {GL_COLOR_ATTACHMENT0_OES};
    static const GLenum default_all[] = {GL_COLOR_EXT, GL_DEPTH_EXT, GL_STENCIL_EXT};
    const GLvoid *index_lists[2];
    GLuint fb, rb;

    ct_init(8, 8);
    glMultiDrawArraysEXT = (PFNGLMULTIDRAWARRAYSEXTPROC)eglGetProcAddress("glMultiDrawArraysEXT");
    glMultiDrawElementsEXT = (PFNGLMULTIDRAWELEMENTSEXTPROC)eglGetProcAddress("glMultiDrawElementsEXT");
    glDiscardFramebufferEXT = (PFNGLDISCARDFRAMEBUFFEREXTPROC)eglGetProcAddress("glDiscardFramebufferEXT");
    CHECK(glMultiDrawArraysEXT && glMultiDrawElementsEXT && glDiscardFramebufferEXT);
    ct_load_fbo();
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, verts);
    glClearColor(0, 0, 0, 0);

    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 0, 0, 1);
    glMultiDrawArraysEXT(GL_TRIANGLE_STRIP, first, count, 2);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(1, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(6, 4, 255, 0, 0, 255, 0);
    /* One draw of the two. */
    glClear(GL_COLOR_BUFFER_BIT);
    glMultiDrawArraysEXT(GL_TRIANGLE_STRIP, first + 1, count, 1);
    CHECK_PIXEL(1, 4, 0, 0, 0, 0, 0);
    CHECK_PIXEL(6, 4, 255, 0, 0, 255, 0);
    /* Errors: as glDrawArrays for each draw, and a negative primcount. */
    glMultiDrawArraysEXT(GL_TRIANGLE_STRIP, first, count, -1);
    CHECK_GL(GL_INVALID_VALUE);
    glMultiDrawArraysEXT(GL_LIGHT0, first, count, 2);
    CHECK_GL(GL_INVALID_ENUM);
    glMultiDrawArraysEXT(GL_TRIANGLE_STRIP, first, count, 0);
    CHECK_GL(GL_NO_ERROR);

    /* Elements: one list of bytes drawn twice as ... GLubyte, then shorts. */
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(0, 1, 0, 1);
    index_lists[0] = left;
    index_lists[1] = left;
    glMultiDrawElementsEXT(GL_TRIANGLE_STRIP, count, GL_UNSIGNED_BYTE, index_lists, 2);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(1, 4, 0, 255, 0, 255, 0);
    CHECK_PIXEL(6, 4, 0, 0, 0, 0, 0);
    index_lists[0] = right;
    glMultiDrawElementsEXT(GL_TRIANGLE_STRIP, count, GL_UNSIGNED_SHORT, index_lists, 1);
    CHECK_PIXEL(6, 4, 0, 255, 0, 255, 0);
    glMultiDrawElementsEXT(GL_TRIANGLE_STRIP, count, GL_FLOAT, index_lists, 1);
    CHECK_GL(GL_INVALID_ENUM);
    glMultiDrawElementsEXT(GL_TRIANGLE_STRIP, count, GL_UNSIGNED_SHORT, index_lists, -3);
    CHECK_GL(GL_INVALID_VALUE);

    /* Discard on the EGL surface's framebuffer. */
    glDiscardFramebufferEXT(GL_FRAMEBUFFER_OES, 3, default_all);
    CHECK_GL(GL_NO_ERROR);
    glDiscardFramebufferEXT(GL_FRAMEBUFFER_OES, 1, fb_color); /* FBO names: not here */
    CHECK_GL(GL_INVALID_ENUM);
    glDiscardFramebufferEXT(GL_TEXTURE_2D, 1, default_all);
    CHECK_GL(GL_INVALID_ENUM);
    glDiscardFramebufferEXT(GL_FRAMEBUFFER_OES, -1, default_all);
    CHECK_GL(GL_INVALID_VALUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glMultiDrawArraysEXT(GL_TRIANGLE_STRIP, first, count, 2);
    CHECK_PIXEL(3, 3, 0, 255, 0, 255, 0);

    /* And on a framebuffer object. */
    glGenFramebuffersOES(1, &fb);
    glGenRenderbuffersOES(1, &rb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA4_OES, 8, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb);
    glDiscardFramebufferEXT(GL_FRAMEBUFFER_OES, 1, fb_color);
    CHECK_GL(GL_NO_ERROR);
    glDiscardFramebufferEXT(GL_FRAMEBUFFER_OES, 1, default_all);
    CHECK_GL(GL_INVALID_ENUM);
    glClear(GL_COLOR_BUFFER_BIT);
    glMultiDrawArraysEXT(GL_TRIANGLE_STRIP, first, count, 2);
    CHECK_PIXEL(5, 5, 0, 255, 0, 255, 0);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteRenderbuffersOES(1, &rb);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
